"""bench/bench_peers.py: its timing rounds (a row's commands interleaved, the least run of the common exit status); its
machine, the package's peer box."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))

import bench_peers  # noqa: E402


def _logger(log: Path, name: str, code: int = 0) -> list[str]:
    return [sys.executable, "-c", f"open({str(log)!r}, 'a').write({name!r}); raise SystemExit({code})"]


def test_each_round_runs_every_command_once_in_turn(tmp_path, monkeypatch):
    monkeypatch.setattr(bench_peers, "REPEAT", [3])
    log = tmp_path / "order"
    got = bench_peers.cpu_rounds({"a": (_logger(log, "a"), None), "b": (_logger(log, "b"), None)}, 60)
    assert log.read_text() == "ababab"
    assert got["a"][1] == 0 and got["b"][1] == 0 and got["a"][0] > 0 and got["b"][2] > 0


def test_only_runs_with_the_most_common_exit_status_count(tmp_path, monkeypatch):
    monkeypatch.setattr(bench_peers, "REPEAT", [3])
    log = tmp_path / "n"
    # exits 7 on its first run, 0 on the two after: the 0 runs are the measurement
    script = (f"import os; p = {str(log)!r}; n = os.path.getsize(p) if os.path.exists(p) else 0; "
              "open(p, 'a').write('x'); raise SystemExit(7 if n == 0 else 0)")
    got = bench_peers.cpu_rounds({"c": ([sys.executable, "-c", script], None)}, 60)
    assert log.read_text() == "xxx" and got["c"][1] == 0


def test_a_command_past_its_timeout_is_not_run_again(tmp_path, monkeypatch):
    monkeypatch.setattr(bench_peers, "REPEAT", [3])
    log = tmp_path / "slow"
    slow = [sys.executable, "-c", f"import time; open({str(log)!r}, 'a').write('s'); time.sleep(30)"]
    got = bench_peers.cpu_rounds({"slow": (slow, None)}, 0.5)
    assert got["slow"] == (None, None, None) and log.read_text() == "s"


@pytest.mark.parametrize("repeat", [1, 2])
def test_cpu_of_is_one_command_in_rounds(tmp_path, monkeypatch, repeat):
    monkeypatch.setattr(bench_peers, "REPEAT", [repeat])
    log = tmp_path / "one"
    cpu, code = bench_peers.cpu_of(_logger(log, "o", 3), 60)
    assert code == 3 and cpu is not None and log.read_text() == "o" * repeat
    assert bench_peers.LAST_RSS[0] is not None and bench_peers.LAST_RSS[0] > 0


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_the_peer_box_is_the_package_s_box_machine(dialect):
    """bench_peers writes ``nczones.precompiled.machines.peer_box`` (dup44: one description, also the Fanuc
    machine of the start-up recordings): the dialect's mill with H1 and one zone, a box, so the Fanuc box reader
    runs on it; ``--scaling`` widens the box."""
    from nczones.machine import parse_machine
    from nczones.precompiled import machines
    from nczones.zones import BoxZone

    assert bench_peers.peer_box is machines.peer_box
    machine = parse_machine(machines.peer_box(dialect))
    assert machine.dialect == dialect and machine.axis_names == ("X", "Y", "Z") and dict(machine.tool_lengths) == {1: 100}
    assert [type(z) for z in machine.zones] == [BoxZone]
    wide = parse_machine(machines.peer_box(dialect, "900000")).zones[0]
    assert wide.contains({"X": 899999, "Y": 0, "Z": 0}) and not machine.zones[0].contains({"X": 899999, "Y": 0, "Z": 0})


def test_the_zone_rows_run_on_their_own_machines(tmp_path):
    """Issue 36's polygon and stepped-table rows: in the table with their machine files, every program proved
    safe against its machine (the walk stays inside the outline, the moves on the table) and, where rs274 is
    installed, run by it to the program end without an error."""
    import shutil
    import subprocess
    from argparse import Namespace

    from nczones.machine import load_machine
    from nczones.prover import verify

    a = Namespace(skip_large=True, small=600, macro=600, corpus=0, lines=0)
    rows = [r for r in bench_peers.programs(a, tmp_path) if r[1] in bench_peers.MACHINE_OF]
    assert [r[0] for r in rows] == ["200-vertex polygon zone, 600 lines", "4,096-region stepped table, 600 lines"]
    for _name, path, _dialect, _tol in rows:
        machine = load_machine(bench_peers.MACHINE_OF[path])
        assert len(path.read_text().splitlines()) == 600 + 3
        assert verify(str(path), machine).verdict.label == "safe"
        if shutil.which("rs274"):
            run = subprocess.run(["rs274", "-g", str(path), "/dev/null"], capture_output=True, text=True,
                                 env={"HOME": str(tmp_path), "PATH": "/usr/bin:/bin"})
            assert run.returncode == 0, run.stderr


def test_every_scaling_machine_names_a_class_and_loads():
    from nczones.machine import parse_machine

    names = {c[0] for c in bench_peers.SCALING_CLASSES}
    assert set(bench_peers.SCALING_MACHINES) <= names and len(bench_peers.SCALING_MACHINES) == 2
    for make in bench_peers.SCALING_MACHINES.values():
        assert parse_machine(make()).allowed.zones


def test_the_table_has_every_class_of_issue_36(tmp_path):
    """The rows issue 36's table names (beside rs274): G1, an expression on every line, R-format and I/J arcs,
    the loops and calls, the zone rows."""
    from argparse import Namespace

    a = Namespace(skip_large=True, small=300, macro=300, corpus=0, lines=0)
    names = [r[0] for r in bench_peers.programs(a, tmp_path)]
    for start in ("G1,", "an expression on every line", "R-format arcs,", "I/J arcs,", "R-format arcs, Fanuc",
                  "Fanuc Macro B loop", "Fanuc G65 call", "LinuxCNC o-word loop", "200-vertex polygon zone",
                  "4,096-region stepped table"):
        assert any(n.startswith(start) for n in names), start
