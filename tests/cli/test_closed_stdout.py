"""Standard output closed (the process started without file descriptor 1, ``cmd >&-``: Python's ``sys.stdout``
is None): every command that writes there reports a user's error, exit 2, never an internal error (hunt43's F1)
nor exit 0 with its output lost (mend44); a report written with ``--output`` is complete."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from nczones import cli
from nczones.commands.conventions import EXIT_FAIL, EXIT_INPUT, EXIT_OK

ROOT = Path(__file__).resolve().parents[2]
MILL = ROOT / "specs" / "machines" / "mill.toml"
PROGRAM = "G90 G21\nG1 X10 Y10 F100\nM2\n"


@pytest.mark.parametrize("command", (["verify"], ["verify", "--format", "json"], ["simulate"]))
def test_a_closed_standard_output_is_a_users_error(tmp_path, capsys, monkeypatch, command):
    program = tmp_path / "p.ngc"
    program.write_text(PROGRAM)
    monkeypatch.setattr(sys, "stdout", None)
    assert cli.main([*command, str(program), "--machine", str(MILL)]) == EXIT_INPUT
    err = capsys.readouterr().err
    assert "standard output is closed" in err and "internal error" not in err, err


def test_a_report_file_is_complete_with_standard_output_closed(tmp_path):
    """The whole program (``python -m nczones``, its fast exit, ``cli._leave_now``) with fd 1 closed."""
    program, out = tmp_path / "p.ngc", tmp_path / "r.json"
    program.write_text(PROGRAM)
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    got = subprocess.run([sys.executable, "-m", "nczones", "verify", str(program), "--machine", str(MILL),
                          "--format", "json", "--output", str(out)], env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, preexec_fn=lambda: os.close(1), timeout=120)
    assert got.returncode == EXIT_OK, got.stderr
    assert json.loads(out.read_text())["verdict"] == "safe"


# Every command that writes to standard output: with fd 1 closed it stops as verify does (mend44), never
# exit 0 with its output lost (print() writes nothing when sys.stdout is None), never an internal error.
GOLDEN_INI = ROOT / "tests" / "golden" / "import" / "linuxcnc" / "mill_mm.ini"


def _nczones(args: list[str], *, closed: bool, cwd: Path) -> subprocess.CompletedProcess[str]:
    """``python -m nczones ARGS``, the whole program, with file descriptor 1 closed (``>&-``) or piped."""
    env = {**os.environ, "PYTHONPATH": str(ROOT), "NO_COLOR": "1"}
    return subprocess.run([sys.executable, "-m", "nczones", *args], env=env, cwd=cwd, text=True,
                          stdout=subprocess.DEVNULL if closed else subprocess.PIPE, stderr=subprocess.PIPE,
                          preexec_fn=(lambda: os.close(1)) if closed else None, timeout=300)


@pytest.fixture(scope="module")
def inputs(tmp_path_factory) -> Path:
    """A program, its JSON report (for replay) and a fleet project with one finished run, in one folder."""
    from nczones.fleet.generate import write_library

    folder = tmp_path_factory.mktemp("closed")
    (folder / "p.ngc").write_text(PROGRAM)
    write_library(folder / "fleet", programs=1, machines=1, moves=2)
    for args in (["verify", "p.ngc", "--machine", str(MILL), "--format", "json", "--output", "r.json"],
                 ["fleet", "check", "fleet", "--serial", "--no-progress"]):
        done = _nczones(args, closed=False, cwd=folder)
        assert done.returncode in (EXIT_OK, EXIT_FAIL), done.stderr  # (the fleet's program cuts into a vise)
    return folder


WRITES_TO_STDOUT = {
    "check-machine": ["check-machine", str(MILL)],
    "verify": ["verify", "p.ngc", "--machine", str(MILL)],
    "simulate": ["simulate", "p.ngc", "--machine", str(MILL)],
    "home": ["home", "--machine", str(ROOT / "specs" / "machines" / "homing_mill.toml")],
    "import-machine": ["import-machine", str(GOLDEN_INI)],
    "export-zones": ["export-zones", str(MILL), "--kind", "linuxcnc"],
    "replay": ["replay", "r.json"],
    "fleet check": ["fleet", "check", "fleet", "--serial", "--no-progress", "--force"],
    "fleet status": ["fleet", "status", "fleet"],
    "fleet diff": ["fleet", "diff", "fleet"],
    "linuxcnc-filter": ["linuxcnc-filter", "p.ngc", "--machine", str(MILL)],
}


@pytest.mark.parametrize("command", WRITES_TO_STDOUT)
def test_every_command_stops_when_its_standard_output_is_closed(inputs, command):
    args = WRITES_TO_STDOUT[command]
    if command == "fleet diff":  # a diff needs two runs
        assert _nczones(["fleet", "check", "fleet", "--serial", "--no-progress", "--force"], closed=False,
                        cwd=inputs).returncode == EXIT_FAIL
    opened = _nczones(args, closed=False, cwd=inputs)
    assert opened.stdout.strip(), f"{command} writes its output to standard output"
    got = _nczones(args, closed=True, cwd=inputs)
    assert got.returncode == EXIT_INPUT, (got.returncode, got.stderr)
    assert "nczones: error: cannot read or write: standard output is closed" in got.stderr, got.stderr
    assert "internal error" not in got.stderr and "Traceback" not in got.stderr, got.stderr


WRITES_TO_A_FILE = {
    "verify": ["verify", "p.ngc", "--machine", str(MILL), "--output", "OUT"],
    "import-machine": ["import-machine", str(GOLDEN_INI), "-o", "OUT", "--linuxcnc-filter", "OUT.ini"],
    "export-zones": ["export-zones", str(ROOT / "specs" / "machines" / "mill_solids.toml"), "--kind", "fanuc",
                     "-o", "OUT"],
    "fleet status": ["fleet", "status", "fleet", "--format", "json", "--output", "OUT"],
    "plot": ["plot", "p.ngc", "--machine", str(MILL), "-o", "OUT.svg"],
}


def _named(text: str, out: Path) -> str:
    """``text`` with the output's path, as written or relative to a folder a command names it from (the filter
    snippet's ``MACHINE``: from the imported INI's folder), as ``OUT``."""
    return text.replace(str(out), "OUT").replace(os.path.relpath(out, GOLDEN_INI.parent), "OUT")


@pytest.mark.parametrize("command", WRITES_TO_A_FILE)
def test_a_command_that_writes_a_file_needs_no_standard_output(inputs, tmp_path, command):
    """What a command writes to ``--output`` is its output: with standard output closed it still succeeds (with
    the exit status it has with standard output open) and writes the same file; the lines on standard output
    that tell about the file are left out."""
    if command == "plot":
        pytest.importorskip("matplotlib")
    written = {}
    for closed in (False, True):
        out = tmp_path / ("closed" if closed else "open")
        got = _nczones([a.replace("OUT", str(out)) for a in WRITES_TO_A_FILE[command]], closed=closed, cwd=inputs)
        assert "standard output is closed" not in got.stderr and "internal error" not in got.stderr, got.stderr
        files = sorted(tmp_path.glob(out.name + "*"))
        assert files, got.stderr
        written[closed] = got.returncode, [f.name.replace(out.name, "OUT") for f in files]
        if command != "plot":  # (an SVG holds its own ids); the times differ
            written[closed] += tuple(re.sub(r"\d+\.\d+", "#", _named(f.read_text(), out)) for f in files)
    assert written[True] == written[False]
    assert written[False][0] in (EXIT_OK, EXIT_FAIL)
