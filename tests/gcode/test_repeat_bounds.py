"""Repeat counts are bounded in the LinuxCNC dialect too (issue 33, class 7).

``--max-iterations`` counts every repetition per entry: o-word loops (``while``, ``do``, ``repeat``), an M98
call's L, a canned cycle's L and its G73/G83 pecks.  A count above it ends the interpretation as unknown at
its block before any repetition is made; every repetition also asks the run's ``--budget``, so nested loops
(each within the bound) end within the budget, through the double pass ('#' in the text) as well.
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from nczones.machine import load_machine
from nczones.prover import verify_text

MILL = Path(__file__).resolve().parents[2] / "specs" / "machines" / "mill.toml"
START = "G21 G90 G54 G61 G0 X10 Y10 Z10\n"  # G61: about repeats, not corner blending (VF208 under load)
SUB = "O2\nG91 G1 X0.001 F100\nG1 X-0.001\nG90\nM99\n"  # two feed moves that come back: one repeat = 2 motions


def _run(text: str, **kw):
    return verify_text(START + text, load_machine(MILL), **kw)


def _unknown_at(r, line: int, *words: str):
    assert r.verdict.label == "unknown", r.violations
    reason = r.reasons[0]
    assert reason.span is not None and reason.span.line == line, reason
    for w in words:
        assert w in reason.message, reason.message


@pytest.mark.parametrize("hash_", ["", "#1 = 1\n"])  # '#': the double pass is tried first
@pytest.mark.parametrize("n_motions", [20, 600])  # 600: the vectorized tier
def test_m98_l_is_compared_with_max_iterations(n_motions, hash_):
    n = n_motions // 2
    text = f"{hash_}M98 P2 L{n}\nM2\n{SUB}"
    ok = _run(text, max_iterations=n)
    assert ok.verdict.label == "safe" and dict(ok.stats)["segments"] == 1 + n_motions, (ok.reasons, ok.stats)
    _unknown_at(_run(text, max_iterations=n - 1), 2 + bool(hash_), f"L{n}", str(n))


@pytest.mark.parametrize("n_holes", [10, 200])  # G81 in G91 with L: position, to R, feed, retract a hole
def test_canned_cycle_l_is_compared_with_max_iterations(n_holes):
    cycle = f"G91 G99 G81 X0.01 Z-1 R-1 L{n_holes} F100\nG80\nM2\n"
    ok = _run(cycle, max_iterations=n_holes)
    assert ok.verdict.label == "safe", ok.reasons
    _unknown_at(_run(cycle, max_iterations=n_holes - 1), 2, f"L{n_holes}")


@pytest.mark.parametrize("text", ["M98 P2 L99999999\nM2\n" + SUB, "G91 G81 X0.001 Z-1 R-1 L99999999 F100\nG80\nM2\n"])
def test_a_huge_repeat_ends_at_once(text):
    t0 = time.process_time()
    _unknown_at(_run(text), 2, "99999999", "max_loop_iterations")
    assert time.process_time() - t0 < 10


def test_peck_count_is_compared_with_max_iterations():
    # G83 from R1 to Z-9 by Q0.001: LinuxCNC's loop `for (d = r - q; d > bottom; d -= q)` pecks 9999 times
    _unknown_at(_run("G90 G98 G83 X10 Z-9 R1 Q0.001 F100\nG80\nM2\n", max_iterations=5000), 2, "G83")


@pytest.mark.parametrize("hash_", ["", "#3 = 1\n"])
def test_nested_loops_end_within_the_budget(hash_):
    """Two nested loops of 9,000 iterations each are within --max-iterations (10,000) per entry; the budget (1 s)
    ends them: unknown (VF203) at a loop line, naming the loop and its count.  With '#' in the text the
    double pass declines (past 10 x max_iterations = 100,000 iterations in all) and the full path meets the
    budget."""
    text = (hash_ + "#1 = 0\no1 while [#1 LT 9000]\n#2 = 0\no2 while [#2 LT 9000]\n#2 = [#2 + 1]\no2 endwhile\n"
            "#1 = [#1 + 1]\no1 endwhile\nM2\n")
    t0 = time.process_time()
    r = _run(text, budget_s=1, max_iterations=10_000)
    assert time.process_time() - t0 < 20
    assert r.verdict.label == "unknown" and r.reasons[0].code == "VF203", r.reasons
    assert "budget of 1 s" in r.reasons[0].message and "while loop had run" in r.reasons[0].message


def test_repeat_loop_ends_within_the_budget():
    # o1 repeat [99999999] counts its iterations (GC392 past 100,000); the budget ends it before
    r = _run("o1 repeat [99999999]\nG91 G1 X0.001 F100\nG1 X-0.001\nG90\no1 endrepeat\nM2\n", budget_s=1)
    assert r.verdict.label == "unknown" and r.reasons[0].code in ("VF203", "GC392"), r.reasons
