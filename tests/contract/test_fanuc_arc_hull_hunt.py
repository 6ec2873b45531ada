"""A Fanuc mill's cutting-mode runs with arcs and transforms: a tip probe inside a run's convex hull is never
proved ``safe`` (hunt36b).

tests/contract/test_fanuc_mill_hull_hunt.py puts a 1 mm tip probe around a convex combination of one run's
end points, at one of its motions' tool lengths (a Fanuc control in cutting mode may reach any point of the
hull of the motions since the last exact stop, specs/path-modes.md §3), on runs of straight moves.  Here the
runs also hold arcs (G02/G03 with R, with I/J, full circles, in a subprogram) and moves under G68 rotation,
G51 scaling and G51.1 mirror image, and the convex combination takes points along each arc (seven per arc,
from ``arc_path_float``, the float geometry reports draw with: a probe of ±0.5 mm holds the exact point
whatever its float error), so the hull is the hull of the motions, not of their ends.  The runs and tool
lengths are the interpreter's (``runs`` of the straight-move hunt), never the prover's.
CI 10 examples; ``-m long``: the count in specs/contract.md "Where features meet: hunt36b".
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.motion import SegmentKind, arc_path_float
from nczones.prover import verify_text
from tests.contract.test_fanuc_mill_hull_hunt import _machine, runs

OUTCOMES: dict[str, int] = {}


def _statement(rnd: random.Random) -> str:
    k = rnd.randrange(14)
    x, y, z = rnd.randint(-40, 40), rnd.randint(-40, 40), rnd.randint(-30, 0)
    if k < 3:
        return f"G01 X{x}. Y{y}."
    if k == 3:
        return f"G01 Z{z}."
    if k == 4:
        return rnd.choice(["G43 H1", "G43 H2", "G49"]) + f" Z{z}."
    if k == 5:
        return rnd.choice(["G04 X0", f"G09 G01 X{x}.", "G61", "G64"])
    if k == 6:  # an R arc (an end too far for R is an error: the example is left out)
        return f"{rnd.choice(['G02', 'G03'])} X{x}. Y{y}. R{rnd.choice(['', '-'])}{rnd.randint(5, 30)}."
    if k == 7:  # a full circle about a centre I/J away
        return f"{rnd.choice(['G02', 'G03'])} I{rnd.randint(-10, 10)}. J{rnd.randint(-10, 10)}."
    if k == 8:
        return f"G68 X0 Y0 R{rnd.choice([15, 30, 45, 90])}.\nG01 X{x}. Y{y}.\nG69"
    if k == 9:
        return f"G51 X0 Y0 P{rnd.choice(['0.5', '1.5', '2.'])}\nG01 X{x // 2}. Y{y // 2}.\nG50"
    if k == 10:
        return f"G51.1 X{rnd.randint(-10, 10)}.\nG01 X{x}. Y{y}.\nG50.1 X0"
    if k == 11:
        return f"G00 X{x}. Y{y}."
    if k == 12:
        return "M98 P100"
    return f"G91 G01 X{rnd.randint(-5, 5)}. G90"


def program(rnd: random.Random) -> str:
    body = [_statement(rnd) for _ in range(rnd.randint(2, 10))]
    pad = rnd.choice([0, 0, 600])
    lines = ["O1", "G90 G17 G21 G54 G49 G64 F500.", "G00 X0. Y0. Z0."]
    if pad:  # 600 looped motions first: the column runs and the proof's vectorized tier
        lines += ["#1 = 0", f"WHILE [#1 LT {pad // 2}] DO1", "G01 X[#1 MOD 3] Y1.", "G01 Y2.", "#1 = #1 + 1",
                  "END1", "G04 X0"]
    if rnd.random() < 0.5:
        lines += ["#2 = 0", "WHILE [#2 LT 2] DO2", *body, "#2 = #2 + 1", "END2"]
    else:
        lines += body
    lines += ["G04 X0", "M30", "O100", f"G02 X{rnd.randint(-40, 40)}. Y{rnd.randint(-40, 40)}. R45.", "M99"]
    return "\n".join(lines) + "\n"


def _points(seg) -> list:
    pts = [seg.start, seg.end]
    if seg.kind is SegmentKind.ARC:
        at, _sweep = arc_path_float(seg)
        pts += [tuple(Fraction(v).limit_denominator(10**6) for v in at(k / 8)) for k in range(1, 8)]
    return pts


def _probe_is_never_safe(rnd: random.Random) -> None:
    text = program(rnd)
    try:
        found = runs(text)
    except (GcodeError, AssertionError):  # an R too short for its chord, or an unknown: no run to probe
        assume(False)
        return
    assume(bool(found))
    chosen = rnd.choice([r for r in found if len(r) >= 2] or found)
    pts = [p for s in chosen for p in _points(s)]
    tl = rnd.choice(sorted({s.tool_length for s in chosen}))
    w = [Fraction(rnd.randint(0, 10)) for _ in pts]
    w[rnd.randrange(len(w))] += 1
    c = [sum(wi * p[i] for wi, p in zip(w, pts)) / sum(w) for i in range(3)]
    c[2] -= tl  # the tip at that length
    assume(not all(abs(v) < 1 for v in c))  # the start (machine 0 0 0) outside the probe
    half = Fraction(1, 2)
    probe = tuple(f"{float(v):.3f}" for v in (c[0] - half, c[1] - half, c[2] - half, c[0] + half, c[1] + half,
                                                 c[2] + half))
    label = verify_text(text, _machine(probe)).verdict.label
    OUTCOMES[label] = OUTCOMES.get(label, 0) + 1
    assert label != "safe", f"a tip probe inside a run's hull (length {tl}) proved safe:\n{text}"


@settings(max_examples=10, deadline=None, database=None)
@given(st.randoms(use_true_random=False))
def test_a_probe_in_a_hull_with_arcs_is_never_safe(rnd):
    _probe_is_never_safe(rnd)


@pytest.mark.long
@settings(max_examples=1500, deadline=None, database=None)
@given(st.randoms(use_true_random=False))
def test_a_probe_in_a_hull_with_arcs_is_never_safe_long(rnd):
    _probe_is_never_safe(rnd)


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    if OUTCOMES:
        print("\nhunt36b Fanuc hull with arcs:", dict(sorted(OUTCOMES.items())))
