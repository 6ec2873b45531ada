"""The ranged-witness replays (:mod:`nczones.pipeline.witnesses`) draw on the run's budget and stop on Ctrl-C.

A witness the replays did not check (the budget spent, an interrupt) is not reported as a witness: a
``VF203``/``VF204`` reason names its line instead, and a result left with no witness is ``unknown``, never
``safe``.  The programs: a loop (LinuxCNC ``o100 while``, Fanuc ``WHILE``) and then rapids into a clamp that
each violate at their own values of ``G54.X``/``G54.Y`` (16 witness sets, 16 replays without a budget).

The budget tests use a fake clock: frozen while the proof runs (so the proof itself is never short of
budget), then moved on by the test once the replays start, so the cut falls where the test says, not where a
loaded machine's timing puts it.
"""

from __future__ import annotations

import signal
import subprocess
import sys
import time
from fractions import Fraction
from pathlib import Path
from unittest import mock

import pytest

from nczones.pipeline import witnesses
from nczones.precompiled import replace
from nczones.prover import verify_text
from nczones.prover.limits import RunLimits
from tests.contract.test_range_seams import Setup, _zone_text, machine_for
from tests.machines import machine_text
from tests.processes import cpu_seconds, interrupt

ROOT = Path(__file__).resolve().parents[2]
_Z = (Fraction(-80), Fraction(-80), Fraction(-30)), (Fraction(80), Fraction(80), Fraction(260))
#: a clamp the rapids reach only when G54.Y moves them up by more than their distance to machine Y 0.5
_CLAMP = ("clamp", (Fraction(25), Fraction(1, 2), Fraction(-30)), (Fraction(40), Fraction(5), Fraction(260)), True,
          False)
PARAMS = ["G54.Y=-1..1", "G54.X=-1..1"]
_LOOP = {"linuxcnc": "#1=0\no100 while [#1 LT {n}]\n#1=[#1+1]\no100 endwhile\n",
         "fanuc": "#1=0\nWHILE [#1 LT {n}] DO1\n#1=#1+1\nEND1\n"}


def _setup(dialect: str) -> Setup:
    return Setup(dialect, "G61", "linear", (("travel", *_Z, False, False), _CLAMP))


def program(dialect: str, loop: int = 1000) -> str:
    """``loop`` passes of a counting loop, then eight rapids towards the clamp (each violating at some values)."""
    body = "".join(f"G0 X{26 + i}. Y{(-45 + 10 * i) / 100:.2f}\nG0 X0. Y0.\n" for i in range(8))
    return "G21 G90 G17 G54 F600.\n" + _LOOP[dialect].format(n=loop) + body + "M30\n"


class Clock:
    """A fake monotonic clock: ``t`` seconds, moved by ``step`` at every reading once ``ticking``."""

    def __init__(self) -> None:
        self.t, self.step, self.ticking = 0.0, 0.0, False

    def __call__(self) -> float:
        if self.ticking:
            self.t += self.step
        return self.t


def _counted(calls: list, after=None):
    """``witnesses._unreached`` counting its calls into ``calls``; ``after(n)`` run after the n-th."""
    orig = witnesses._unreached

    def run(*args):
        out = orig(*args)
        calls.append(args[3])
        if after is not None:
            after(len(calls))
        return out

    return run


def _lines(reasons, code):
    return sorted(r.span.line for r in reasons if r.code == code)


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_every_witness_set_replays_without_a_budget(dialect):
    """The reference the budget tests cut: 16 witnesses at 16 sets of values, every one replayed and kept."""
    calls: list = []
    with mock.patch.object(witnesses, "_unreached", _counted(calls)):
        got = verify_text(program(dialect), machine_for(_setup(dialect)), params=PARAMS)
    assert got.verdict.label == "unsafe" and len(got.violations) == len(calls) == 16
    assert len({v.params for v in got.violations}) == 16
    assert not [r for r in got.reasons if r.code in ("VF203", "VF204")]


@pytest.mark.parametrize("dialect,cut", [("linuxcnc", 0), ("linuxcnc", 3), ("fanuc", 1), ("fanuc", 15)])
def test_the_budget_spent_between_replays_leaves_the_rest_unreported(dialect, cut):
    """The budget runs out after ``cut`` replays: their witnesses are kept, every other one is a VF203 reason
    on its line (no further replay starts); none kept (``cut`` 0), the verdict is ``unknown``."""
    machine = machine_for(_setup(dialect))
    full = verify_text(program(dialect), machine, params=PARAMS)
    clock = Clock()

    def spend(n):
        if n >= cut:
            clock.t = 1e6

    calls: list = []
    with mock.patch.object(witnesses, "_unreached", _counted(calls, spend)):
        if cut == 0:
            with mock.patch.object(witnesses, "_replay_groups", _spent_first(clock)):
                got = verify_text(program(dialect), machine, params=PARAMS,
                                  limits=RunLimits(budget_s=100, clock=clock))
        else:
            got = verify_text(program(dialect), machine, params=PARAMS, limits=RunLimits(budget_s=100, clock=clock))
    assert len(calls) == cut
    assert got.violations == full.violations[:cut]
    assert _lines(got.reasons, "VF203") == sorted(v.line for v in full.violations[cut:])
    assert all("before this witness was replayed" in r.message for r in got.reasons if r.code == "VF203")
    assert got.verdict.label == ("unsafe" if cut else "unknown")
    assert not got.interrupted


def test_a_real_budget_bounds_the_proof_and_the_replays_together():
    """On the wall clock: a budget shorter than the proof and its 16 replays (a 20,000-pass loop each) ends the
    run about when it is spent, never ``safe``; every witness reported replays, every other is a VF203 reason
    (wherever the budget fell: in the proof's loop, the replays' or between them)."""
    machine = machine_for(_setup("linuxcnc"))
    text = program("linuxcnc", loop=20000)
    started, wall = time.process_time(), time.monotonic()
    got = verify_text(text, machine, params=PARAMS, budget_s=0.8)
    spent, wall = time.process_time() - started, time.monotonic() - wall
    assert got.verdict.label in ("unsafe", "unknown") and any(r.code == "VF203" for r in got.reasons)
    # the budget is wall time: the CPU after it is at most a loop pass, a solver query's stop and the report
    assert spent < 0.8 + 1.5 and wall < 30, (spent, wall)
    for v in got.violations:
        at = verify_text(text, machine_for(_setup("linuxcnc"), dict(v.params)))
        assert v.line in [w.line for w in at.violations], v


def _spent_first(clock: Clock):
    """``witnesses._replay_groups`` with the budget spent as it starts."""
    orig = witnesses._replay_groups

    def run(*args):
        clock.t = 1e6
        return orig(*args)

    return run


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_a_loop_inside_a_replay_stops_at_the_budget(dialect):
    """The clock ticks once the replays start (a hundredth of a second a reading, one reading a loop pass): the
    first replay's loop ends at the budget (VF203, "while interpreting"), and no witness is reported."""
    machine = machine_for(_setup(dialect))
    clock = Clock()
    orig = witnesses._replay_groups

    def ticking(*args):
        clock.ticking, clock.step = True, 0.01
        return orig(*args)

    with mock.patch.object(witnesses, "_replay_groups", ticking):
        got = verify_text(program(dialect, loop=5000), machine, params=PARAMS,
                          limits=RunLimits(budget_s=1, clock=clock))
    assert got.verdict.label == "unknown" and not got.violations
    budget = [r for r in got.reasons if r.code == "VF203"]
    assert len(budget) == 16
    assert sum("while interpreting the program" in r.message for r in budget) == 1, [r.message for r in budget]
    assert clock.t < 2, "the loop ran on past the budget"


def test_an_interrupt_during_the_replays_is_a_partial_report():
    """KeyboardInterrupt in the third replay: the first two witnesses stay, the others are VF204 reasons, the
    result is marked interrupted."""
    machine = machine_for(_setup("linuxcnc"))
    full = verify_text(program("linuxcnc"), machine, params=PARAMS)
    orig = witnesses._unreached
    calls: list = []

    def run(*args):
        calls.append(1)
        if len(calls) == 3:
            raise KeyboardInterrupt
        return orig(*args)

    with mock.patch.object(witnesses, "_unreached", run):
        got = verify_text(program("linuxcnc"), machine, params=PARAMS)
    assert got.interrupted and got.verdict.label == "unsafe"
    assert got.violations == full.violations[:2]
    assert _lines(got.reasons, "VF204") == sorted(v.line for v in full.violations[2:])


def test_an_interrupted_proof_replays_nothing_and_reports_no_unchecked_witness():
    """A proof stopped by Ctrl-C with witnesses found: none is replayed (the run stops now), so none is
    reported; a VF204 reason names each, and the verdict is ``unknown``."""
    machine = machine_for(_setup("fanuc"))
    full = verify_text(program("fanuc"), machine, params=PARAMS)
    calls: list = []
    with mock.patch.object(witnesses, "_unreached", _counted(calls)):
        got = witnesses.replayed_witnesses(replace(full, interrupted=True), machine, lambda m: None)
    assert not calls and not got.violations and got.interrupted
    assert got.verdict.label == "unknown"
    assert _lines(got.reasons, "VF204") == sorted(v.line for v in full.violations)


def test_a_line_replayed_at_other_values_needs_no_run():
    """Two witnesses of one line and zone at two sets of values: one replay shows the line; the other witness is
    dropped with a note (no second run), and the verdict stays ``unsafe`` with the first.  A witness of another
    zone on that line is replayed at its own values (and there, its point inside that zone's allowed box, does
    not replay: dropped with a note)."""
    machine = machine_for(_setup("linuxcnc"))
    text = "G21 G90 G17 G54 F600.\nG0 X30. Y0.\nM30\n"
    ranged = verify_text(text, machine, params=["G54.Y=-1..1"])
    (v,) = ranged.violations
    other = replace(v, params=(("G54.Y", Fraction(3, 4)),))
    from nczones.gcode.source import program_text
    from nczones.pipeline.verification import interpretation
    from nczones.prover.options import VerifyOptions

    source, options = program_text(text, "<program>"), VerifyOptions.from_keywords()
    calls: list = []
    with mock.patch.object(witnesses, "_unreached", _counted(calls)):
        out = witnesses.replayed_witnesses(replace(ranged, violations=(v, other)), machine,
                                           lambda m: interpretation(source, m, options))
    assert len(calls) == 1 and out.violations == (v,) and out.verdict.label == "unsafe"
    assert any("witness of line 2 was dropped: not replayed" in n for n in out.notes), out.notes
    # a witness of the same line in another zone is replayed at its own values: the line runs, but the point is
    # inside the travel box, so it does not replay there (matched by its block and zone, not by its line)
    elsewhere = replace(other, zone="travel")
    calls.clear()
    with mock.patch.object(witnesses, "_unreached", _counted(calls)):
        out = witnesses.replayed_witnesses(replace(ranged, violations=(v, elsewhere)), machine,
                                           lambda m: interpretation(source, m, options))
    assert len(calls) == 2 and out.violations == (v,)
    assert any("witness of line 2 was dropped" in n and "does not replay" in n for n in out.notes), out.notes


def _machine_file(tmp_path: Path, dialect: str) -> Path:
    zones = "".join(_zone_text(*z) for z in _setup(dialect).zones)
    path = tmp_path / "m.toml"
    path.write_text(machine_text("xyz_range_seams", set={"machine.dialect": dialect, "machine.path_mode": "G61",
                                                         "machine.rapid_mode": "linear"}, extra=zones))
    return path


#: runs ``nczones verify`` with a line on standard error as each replay starts (the signal's cue)
_CUED = """
import sys
from nczones.pipeline import witnesses
orig = witnesses._unreached
def cued(*args):
    print("replaying", file=sys.stderr, flush=True)
    return orig(*args)
witnesses._unreached = cued
from nczones.cli import main
sys.exit(main(sys.argv[1:]))
"""


@pytest.mark.parametrize(("sig", "status"), [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_ctrl_c_during_the_replays_stops_within_a_second_with_a_partial_report(tmp_path, sig, status):
    """SIGINT (SIGTERM) as the first replay starts (each replays a 30,000-pass loop): exit 130 (143), a partial
    report whose unchecked witnesses are VF204 reasons, within a second of CPU."""
    prog = tmp_path / "ranged.ngc"
    prog.write_text(program("linuxcnc", loop=30000))
    proc = subprocess.Popen([sys.executable, "-c", _CUED, "verify", str(prog), "--machine",
                             str(_machine_file(tmp_path, "linuxcnc")), *(f"--param={p}" for p in PARAMS)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    assert proc.stderr is not None
    before = []  # anything the child writes to standard error ahead of the cue (a warning)
    while (cue := proc.stderr.readline()) and cue.strip() != "replaying":
        before.append(cue)
    assert cue.strip() == "replaying", (before, proc.communicate())
    time.sleep(0.05)
    cpu0 = cpu_seconds(proc.pid)
    stopped = interrupt(proc, sig=sig)
    assert proc.returncode == status, (stopped.out, stopped.err)
    assert stopped.cpu_after_signal_s < 1.0 and stopped.wall_after_signal_s < 20, (stopped, cpu0)
    assert "VF204" in stopped.out and "before this witness was replayed" in stopped.out, stopped.out
    assert "(interrupted: a partial report)" in stopped.out.splitlines()[-1]
    assert "Traceback" not in stopped.err
