"""``nczones fleet check|status|diff`` as a user runs them: subprocesses on real files."""

from __future__ import annotations

import json
import os
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

from fleet_helpers import LIBRARY, ROOT, small_library

from nczones.fleet.generate import mill_variant
from nczones.fleet.project import load_project
from tests.processes import interrupt


def nczones(*args: str, cwd: Path | str = ROOT) -> subprocess.CompletedProcess:
    r = subprocess.run([sys.executable, "-m", "nczones", *args], capture_output=True, cwd=cwd, text=True)
    assert "Traceback" not in r.stderr, r.stderr
    return r


def test_the_bundled_library_has_mixed_verdicts_and_every_example(tmp_path):
    project = load_project(LIBRARY)
    cells = project.cells()
    programs = {c.program for c in cells}
    assert len(programs) >= 30
    assert {p for p in programs if p.startswith("../programs/")} == {
        f"../programs/{p.name}" for p in (ROOT / "specs" / "examples" / "programs").glob("*.*")}
    store = tmp_path / "lib.sqlite"
    r = nczones("fleet", "check", str(LIBRARY), "--store", str(store), "--serial", "--machine", "grinder",
                "--machine", "mill_start")
    assert r.returncode == 1, r.stderr  # some cell is unsafe
    summary = r.stdout.splitlines()[-1]
    assert summary.startswith("bundled example library: 19 cells: ") and "unsafe" in summary and "safe" in summary
    assert "../programs/notch_dip.ngc on grinder: unsafe: line 5 (wheel area)" in r.stdout
    assert "../programs/home_shift_close.ngc on mill_start: unsafe" in r.stdout  # params home.X=-10..10
    again = nczones("fleet", "check", str(LIBRARY), "--store", str(store), "--machine", "grinder",
                    "--machine", "mill_start")
    assert "0 jobs ran, 19 reused" in again.stdout
    status = nczones("fleet", "status", str(LIBRARY), "--store", str(store), "--format", "json")
    doc = json.loads(status.stdout)
    assert doc["machines"] == ["grinder", "mill_start"] and len(doc["cells"]) == 19
    verdicts = {(c["program"], c["machine"]): c["verdict"] for c in doc["cells"]}
    assert verdicts[("../programs/notch_over.ngc", "grinder")] == "safe"
    assert verdicts[("../programs/x_near_limit.ngc", "mill_start")] == "safe"  # margin 1 from [[settings]]
    page = tmp_path / "site" / "index.html"
    # HTML reports verify each job again (tests/fleet/test_fleet_status_html.py covers them): none here
    r = nczones("fleet", "status", str(LIBRARY), "--store", str(store), "--format", "html", "--output", str(page),
                "--html-reports", "none")
    assert r.returncode == 0
    assert not list((page.parent / "reports").glob("*.html"))
    html = page.read_text()
    key = next(c["job_key"] for c in doc["cells"] if c["program"] == "../programs/notch_dip.ngc")
    assert f'href="reports/{key}.txt"' in html and "http" not in html.split("<body>")[1]
    assert "notch_dip.ngc:5:1: violation[wheel area]" in (page.parent / "reports" / f"{key}.txt").read_text()
    assert json.loads((page.parent / "reports" / f"{key}.json").read_text())["verdict"] == "unsafe"


def test_status_text_and_diff_after_a_machine_changes(tmp_path):
    project = small_library(tmp_path / "lib", programs=3, machines=2, moves=5)
    assert nczones("fleet", "check", str(project), "--serial").returncode == 1
    text = nczones("fleet", "status", str(project)).stdout
    assert "programs/part_000.ngc  X X" in text  # part_000 cuts into the vise
    assert "programs/part_001.ngc  . ." in text
    assert "programs/part_000.ngc on mill_000: unsafe: line 7 (vise)" in text
    # mill_001's vise grows under every pocket walk
    wide = mill_variant(1).replace('X = "143", Y = "180"', 'X = "600", Y = "400"')
    assert wide != mill_variant(1)
    (tmp_path / "lib" / "machines" / "mill_001.toml").write_text(wide, encoding="utf-8")
    nczones("fleet", "check", str(project), "--serial")
    diff = nczones("fleet", "diff", str(project))
    assert diff.returncode == 1
    lines = diff.stdout.splitlines()
    newly = [line for line in lines if line.startswith("newly unsafe: ")]
    assert lines[0].startswith("changes from run 1 to run 2: ") and lines[1:len(newly) + 1] == newly
    assert len(newly) == 2 and all("on mill_001: safe -> unsafe" in line for line in newly)
    assert lines[3].startswith("violations changed: programs/part_000.ngc on mill_001: unsafe -> unsafe: was line 7")
    assert all("mill_001" in line for line in lines[1:])
    as_json = json.loads(nczones("fleet", "diff", str(project), "--format", "json").stdout)
    assert [c["kind"] for c in as_json["changes"]][:len(newly)] == ["newly unsafe"] * len(newly)
    (tmp_path / "lib" / "machines" / "mill_001.toml").write_text(mill_variant(1), encoding="utf-8")
    nczones("fleet", "check", str(project), "--serial")
    fixed = nczones("fleet", "diff", str(project))
    assert fixed.returncode == 0 and fixed.stdout.count("fixed: ") == len(newly)


def test_project_file_errors_name_the_line_and_exit_2(tmp_path):
    small_library(tmp_path, programs=1, machines=1)
    (tmp_path / "nczones.toml").write_text(
        '[machines.a]\nfile = "machines/mill_000.toml"\nprograms = ["programs/*.ngc"]\nmargin = 0.1\n'
        '[machines.b]\nfile = "nowhere.toml"\n'
        '[[settings]]\nprograms = ["x.ngc"]\nmachines = ["c"]\nspeed = "fast"\n')
    r = nczones("fleet", "check", str(tmp_path))
    assert r.returncode == 2 and r.stdout == ""
    err = r.stderr
    assert "nczones.toml:4:1: error[FL105]: [machines.a]: margin = 0.1: expected a decimal number" in err
    assert "nczones.toml:6:1: error[FL103]: [machines.b]: machine file 'nowhere.toml' does not exist" in err
    assert "nczones.toml:9:1: error[FL103]: [[settings]] #1: no machine named 'c'" in err
    assert "nczones.toml:10:1: error[FL104]: [[settings]] #1: unknown key 'speed'" in err
    r = nczones("fleet", "status", str(tmp_path / "missing"))
    assert r.returncode == 2 and "error[FL100]: no project file" in r.stderr
    (tmp_path / "nczones.toml").write_text('[machines.a]\nfile = "machines/mill_000.toml"\nprograms = ["*.ngc"]\n')
    r = nczones("fleet", "diff", str(tmp_path))
    assert r.returncode == 2 and "error[FL300]: no result store" in r.stderr


def test_ctrl_c_stops_the_run_and_keeps_what_finished(tmp_path):
    project = small_library(tmp_path / "lib", programs=12, machines=2, moves=40)
    store = tmp_path / "lib" / ".nczones" / "results.sqlite"
    proc = subprocess.Popen([sys.executable, "-m", "nczones", "fleet", "check", str(project), "--serial"],
                            cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    done = 0
    while time.monotonic() < deadline and proc.poll() is None:
        if store.exists():
            try:
                done = sqlite3.connect(store).execute("SELECT count(*) FROM results").fetchone()[0]
            except sqlite3.OperationalError:
                done = 0
            if done >= 2:
                break
        time.sleep(0.05)
    assert proc.poll() is None, "the run ended before it could be interrupted"
    stopped = interrupt(proc)
    err = stopped.err
    # within a second of the run's own CPU (wall time on a loaded machine measures the scheduler)
    assert stopped.cpu_after_signal_s < 1.0 and stopped.wall_after_signal_s < 20, stopped
    assert proc.returncode == 130 and "interrupted" in err and "Traceback" not in err, (proc.returncode, err[-3000:])
    db = sqlite3.connect(store)
    interrupted, ran = db.execute("SELECT interrupted, ran FROM runs").fetchone()
    stored = db.execute("SELECT count(*) FROM results").fetchone()[0]
    pending = db.execute("SELECT count(*) FROM cells WHERE status = 'pending'").fetchone()[0]
    assert interrupted == 1 and 2 <= stored == ran < 24 and pending == 24 - stored
    again = subprocess.run([sys.executable, "-m", "nczones", "fleet", "check", str(project), "--serial"],
                           cwd=ROOT, capture_output=True, text=True, env=dict(os.environ))
    assert f"{24 - stored} jobs ran, {stored} reused" in again.stdout


def test_an_unreachable_scheduler_is_one_line_and_exit_2(tmp_path):
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]  # closed again: nothing listens there
    small_library(tmp_path, programs=1, machines=1)
    r = subprocess.run([sys.executable, "-m", "nczones", "fleet", "check", str(tmp_path), "--scheduler",
                        f"tcp://127.0.0.1:{port}"], capture_output=True, text=True, cwd=ROOT, timeout=120,
                       env=dict(os.environ, DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="2s"))
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert f"error[FL111]: cannot reach the Dask scheduler at tcp://127.0.0.1:{port}" in r.stderr


def test_every_fleet_option_has_help_text():
    import argparse

    from nczones.cli import build_parser

    def subparsers(p):
        return next(a for a in p._actions if isinstance(a, argparse._SubParsersAction))

    fleet = subparsers(build_parser()).choices["fleet"]
    commands = subparsers(fleet).choices
    assert set(commands) == {"check", "status", "diff"}
    missing = [f"{name} {'/'.join(a.option_strings) or a.dest}" for name, p in commands.items()
               for a in p._actions if not isinstance(a, argparse._HelpAction) and not a.help]
    assert missing == []
