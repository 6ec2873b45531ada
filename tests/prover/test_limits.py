"""No run is unbounded: per-query limits, the program's budget, Ctrl-C (issue 19).

The hard query is an R-format arc whose centre is irrational (a point of a
spiral of R-format arcs written in inches, as LinuxCNC's ``arcspiral.ngc``
is): Z3's nonlinear arithmetic spends more than ten seconds on it while its
resource count stays far below the rlimit of 5,000,000, so it stands for "a
query that cannot finish".
"""

from __future__ import annotations

import signal
import subprocess
import sys
import time
from fractions import Fraction as F
from pathlib import Path

import pytest

from nczones.machine import load_machine
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover import Verdict, verify_text
from nczones.prover.core import Prover
from nczones.prover.geometry import arc_geom
from nczones.prover.limits import RunLimits
from tests.processes import cpu_seconds, interrupt

ROOT = Path(__file__).resolve().parents[2]
MILL = load_machine(ROOT / "specs" / "machines" / "mill.toml")
INCH = F(254, 10)

#: The hard arc in the mill's G54 (X150 Y100 Z100), inch words as written.
HARD_ARC = ("X-0.315142 Y-1.950708", "X-0.507799 Y-1.907568", "R1.974")


def hard_segment() -> Segment:
    def mm(word, off):
        return off + INCH * F(word)

    return Segment(SegmentKind.ARC, (mm("-0.315142", 150), mm("-1.950708", 100), mm("-0.1", 100)),
                   (mm("-0.507799", 150), mm("-1.907568", 100), mm("-0.1", 100)), ("X", "Y", "Z"),
                   plane=Plane.XY, clockwise=True, radius=INCH * F("1.974"))


def hard_program(repeats: int = 1, then: str = "") -> str:
    start, end, r = HARD_ARC
    lines = ["G20 G90 G54 G17", f"G0 {start} Z1", "G1 Z-0.1 F24"]
    for _ in range(repeats):
        lines += [f"G2 {end} {r}", f"G1 {start}"]
    return "\n".join(lines + ([then] if then else []) + ["M2", ""])


def hard_query(prover: Prover):
    seg = hard_segment()
    return prover.arc_query(seg, arc_geom(seg), False)


def test_a_query_that_cannot_finish_ends_unknown_within_its_time_limit():
    limits = RunLimits(budget_s=None, query_time_s=0.5)
    prover = Prover(MILL, limits=limits)
    prover.solver.nonlinear_rlimit = 4_000_000_000  # only the backstop can stop it
    body, names = hard_query(prover)
    t0 = time.perf_counter()
    with limits.watch():
        ans = prover.solver.check(body, names, nonlinear=True)
    took = time.perf_counter() - t0
    assert ans.status == "unknown" and ans.stopped == "time" and ans.code == "VF202"
    assert took < 0.5 + 1.5, took
    # the context is usable afterwards
    assert prover.solver.check("(declare-const a Real)(assert (> a 1.0))", ["a"]).status == "sat"


def test_the_rlimit_stops_the_nonlinear_solver_deterministically():
    outcomes = []
    for _ in range(2):
        prover = Prover(MILL)
        prover.solver.nonlinear_rlimit = 50_000
        body, names = hard_query(prover)
        t0 = time.perf_counter()
        ans = prover.solver.check(body, names, nonlinear=True)
        outcomes.append((ans.status, ans.stopped, ans.code))
        assert time.perf_counter() - t0 < 5
    assert outcomes == [("unknown", "rlimit", "VF201")] * 2


def test_a_spent_budget_is_unknown_and_the_exact_tier_still_reports_the_rest():
    # the hard arc goes to Z3 (engine z3), the budget stops it; the line after it leaves the
    # travel box (X600) at line 6 and is still decided exactly
    text = hard_program(then="G1 X30")
    t0 = time.perf_counter()
    r = verify_text(text, MILL, engine="z3", budget_s=1.0)
    assert time.perf_counter() - t0 < 1.0 + 3.0
    assert r.verdict is Verdict.UNSAFE
    assert [v.line for v in r.violations] == [6] and r.violations[0].zone == "travel"
    budget = [x for x in r.reasons if x.code == "VF203"]
    assert len(budget) == 1 and budget[0].span.line == 4 and "budget of 1 s spent" in budget[0].message
    assert dict(r.stats)["budget_undecided"] >= 1
    assert r.budget_s == 1.0 and not r.interrupted


def test_budget_is_never_safe():
    r = verify_text(hard_program(), MILL, engine="z3", budget_s=0.5)
    assert r.verdict is Verdict.UNKNOWN
    assert any(x.code == "VF203" for x in r.reasons)


def test_budget_clock():
    t = [0.0]
    lim = RunLimits(budget_s=2, clock=lambda: t[0])
    lim.checkpoint()
    t[0] = 2.0
    from nczones.prover.limits import BudgetSpent

    with pytest.raises(BudgetSpent):
        lim.checkpoint()
    assert lim.spent_at == 2.0


def test_ctrl_c_stops_a_running_verify_within_two_seconds_with_a_partial_report(tmp_path):
    prog = tmp_path / "hard.ngc"
    prog.write_text(hard_program(repeats=6))
    # a terminal user's Ctrl-C: SIGINT with its default disposition (a background test runner may
    # have it ignored, which the child would inherit)
    proc = subprocess.Popen([sys.executable, "-m", "nczones", "verify", str(prog), "--machine",
                             str(ROOT / "specs" / "machines" / "mill.toml"), "--engine", "z3"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    # Start-up, then into the hard queries (each runs to its 5 s backstop).  Waiting for the child's
    # own CPU time rather than a fixed wall time: under load the imports alone can take seconds.
    deadline = time.monotonic() + (120 if Path("/proc").is_dir() else 4)
    while cpu_seconds(proc.pid) < 1.5 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    assert proc.poll() is None, proc.communicate()
    stopped = interrupt(proc)
    out, err = stopped.out, stopped.err
    assert proc.returncode == 130, (out, err)
    # "within a second" as CPU the run spends after the signal (wall time on a loaded machine
    # measures the scheduler); the wall bound catches a run that waits instead of working
    assert stopped.cpu_after_signal_s < 1.0 and stopped.wall_after_signal_s < 20, stopped
    assert "unknown[VF204]: interrupted (Ctrl-C)" in out, out
    assert "(interrupted: a partial report)" in out.splitlines()[-1]
    assert "Traceback" not in err
