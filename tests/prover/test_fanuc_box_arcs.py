"""Arcs on the numpy-free box route (issue 36, fanucarcs36): the lane's integer arc boxes
(``nczones.gcode.fanuc.columns.r_arc_box`` / ``centre_arc_box``, written by ``FanucInterpreter._arc_lane`` into a
``BoxRows``) and plain Fanuc programs of 512 to ``FANUC_BOX_LINES`` lines routed to the box route first.

Two relations:

* the boxes hold every point of the arc, sampled with floats by an oracle independent of the code under test
  (``nczones.motion.arc_path_float``, the drawing code: its own centre and angles), to 1e-9 relative; and they are
  no looser than ``ArcGeom.plane_bbox(sweep=True)`` (today's box) by more than 2 units of the integer scale nor
  tighter (beyond those units) than the sampled arc's own box;
* ``verify`` with the route and without it (today's path: past 512 lines the vectorized fast path) gives the same
  verdict, violations, reasons, notes and motion count, on generated plain programs of R and I/J arcs in G17, G18
  and G19, both directions, over a zone whose faces the arcs touch and cross.  When the route answers the answer
  is ``safe``; it may decline (its box is one box) where today's path proves ``safe``, never the other way round.

The mill (tests/gcode/fanuc/helpers.py): G54 = (100, 50, -200); the zone machine X -10..150, Y -10..90, Z -201..0,
so program X50. (machine 150), Y40. (machine 90) and Z-1. (machine -201) lie on its faces.
"""

from __future__ import annotations

import math
import os
import random
from fractions import Fraction as F

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode.fanuc.columns import centre_arc_box, r_arc_box
from nczones.motion import Plane, Segment, SegmentKind, arc_path_float
from nczones.prover.geometry import arc_geom
from tests.prover.test_fanuc_boxes import _MACHINES, _agree

AXES = ("X", "Y", "Z")
UNIT = 1000  # the tests' integer scale: 0.001 mm
ints = st.integers(-20000, 20000)


def _samples(seg: Segment) -> list[list[float]]:
    at, _sweep = arc_path_float(seg)
    return [at(k / 2000) for k in range(2001)]


def _check(box: tuple[int, int, int, int], seg: Segment, units: int = 2) -> None:
    lo_a, hi_a, lo_b, hi_b = (v / UNIT for v in box)
    pts = _samples(seg)
    size = 1 + max(abs(v) for p in pts for v in p[:2])
    tol = 1e-9 * size
    for x, y in (p[:2] for p in pts):
        assert lo_a - tol <= x <= hi_a + tol and lo_b - tol <= y <= hi_b + tol
    # no looser than today's box (ArcGeom.plane_bbox(sweep=True)) by more than ``units`` units of the scale
    (xl, xh), (yl, yh) = arc_geom(seg).plane_bbox(sweep=True)
    two = F(units, UNIT)
    assert F(box[0], UNIT) >= xl - two and F(box[1], UNIT) <= xh + two
    assert F(box[2], UNIT) >= yl - two and F(box[3], UNIT) <= yh + two
    # and no tighter than the sampled arc's box (the extremes are on the arc: sampled finely, 2000 steps)
    step = 2 * math.pi * size / 2000
    assert lo_a <= min(p[0] for p in pts) + step and hi_a >= max(p[0] for p in pts) - step


@settings(max_examples=150, deadline=None, database=None)
@given(ints, ints, ints, ints, st.integers(1, 40000), st.booleans(), st.booleans())
def test_the_r_arc_box_holds_the_arc(sa, sb, ea, eb, extra, cw, major):
    """An R arc from (sa, sb) to (ea, eb) (0.001 mm units), |R| at least half the chord plus ``extra``."""
    chord2 = (ea - sa) ** 2 + (eb - sb) ** 2
    if chord2 == 0:
        return
    r = math.isqrt(chord2) // 2 + extra
    if (2 * r) ** 2 <= chord2:
        r += 1
    r = -r if major else r
    box = r_arc_box(sa, sb, ea, eb, r, cw)
    assert box is not None
    seg = Segment(SegmentKind.ARC, (F(sa, UNIT), F(sb, UNIT), F(0)), (F(ea, UNIT), F(eb, UNIT), F(0)), AXES,
                  plane=Plane.XY, clockwise=cw, radius=F(r, UNIT))
    _check(box, seg)


@settings(max_examples=150, deadline=None, database=None)
@given(ints, ints, st.integers(-20000, 20000), st.integers(-20000, 20000), st.integers(0, 3), st.booleans(),
       st.sampled_from([(0, 0)] * 3 + [(1, 0), (0, -1), (2, 1), (-3, 2)]))
def test_the_centre_arc_box_holds_the_arc(sa, sb, i, j, quarters, cw, off):
    """An I/J arc whose end is its start turned about the centre by ``quarters`` quarter turns (exactly on the
    circle; 0: a whole circle), or moved ``off`` units off it (a spiral: the tolerance 5 units accepts it)."""
    if i == 0 and j == 0:
        return
    ca, cb = sa + i, sb + j
    u = (-i, -j)
    for _ in range(quarters):
        u = (-u[1], u[0])
    ea, eb = ca + u[0] + off[0], cb + u[1] + off[1]
    box = centre_arc_box(sa, sb, ea, eb, ca, cb, cw, 5)
    r0, r1 = i * i + j * j, (ea - ca) ** 2 + (eb - cb) ** 2
    cross, dot = i * (cb - eb) - j * (ca - ea), i * (ea - ca) + j * (eb - cb)
    if r1 == 0 or (r0 != r1 and ((cross == 0 and dot < 0) or abs(math.sqrt(r0) - math.sqrt(r1)) > 5.000001)):
        return  # on its start's ray (u = -(i, j), w = e - c) or off by more than the tolerance: left out
    assert box is not None
    seg = Segment(SegmentKind.ARC, (F(sa, UNIT), F(sb, UNIT), F(0)), (F(ea, UNIT), F(eb, UNIT), F(0)), AXES,
                  plane=Plane.XY, clockwise=cw, centre=(F(ca, UNIT), F(cb, UNIT)))
    _check(box, seg, 2 if r0 == r1 else 6)


def test_the_boxes_leave_the_interpreter_s_cases_to_it():
    """Equal ends, R 0, a chord of 2|R| (the interpreter's half circle about the midpoint, also within its 1e-12
    tolerance: ``Interpreter.arc``), and an I/J arc whose ends are at different distances (a spiral or GC301)."""
    assert r_arc_box(5, 5, 5, 5, 10, True) is None
    assert r_arc_box(0, 0, 10, 0, 0, True) is None
    assert r_arc_box(0, 0, 20, 0, 10, True) is None
    big = 10**12
    assert r_arc_box(0, 0, 2 * big, 0, big + 1, True) is None  # h (1 - 1e-12)**-2 >= r
    assert r_arc_box(0, 0, 2 * big, 0, big + 10, True) is not None
    assert centre_arc_box(0, 0, 10, 1, 5, 0, True) is None  # no tolerance given: a spiral is left out
    assert centre_arc_box(0, 0, 10, 1, 5, 0, True, 1) is not None  # |sqrt 25 - sqrt 26| = 0.099 <= 1
    assert centre_arc_box(0, 0, 12, 0, 5, 0, True, 1) is None  # |5 - 7| > 1: GC301 on the general path
    assert centre_arc_box(10, 0, 11, 0, 5, 0, True, 10) is None  # the end on the start's ray: a spiral turn


# --------------------------------------------------------------------------------------------------------------
# verify: the route against today's path on plain programs of more than 512 lines

#: per plane: its code and the (axis, centre letter, least, greatest program coordinate) of its two axes; the
#: greatest X 50 and Y 40 are the zone's faces, Z -1 its floor (program coordinates)
_PLANES = {
    "G17": (("X", "I", -5000, 50000), ("Y", "J", -5000, 40000)),
    "G18": (("Z", "K", -1000, 30000), ("X", "I", -5000, 50000)),
    "G19": (("Y", "J", -5000, 40000), ("Z", "K", -1000, 30000)),
}


def _num(v: int) -> str:
    return f"{v / UNIT:.3f}"


def _program(rnd: random.Random, plane: str, lines: int, reach: int, gap: int) -> str:
    """A plain program (no ``#``, no call) of ``lines`` moves in ``plane``: a random walk of straight moves and R and
    I/J arcs in both directions (steps up to ``reach``, 0.001 mm), near the corner of the plane's two greatest
    faces (positions at most ``gap`` from them: 0 walks on the faces; arcs may bulge past them); some moves modal
    (no G word)."""
    (a, la, _alo, ahi), (b, lb, _blo, bhi) = _PLANES[plane]
    alo, blo = ahi - 8000, bhi - 8000
    ahi, bhi = ahi - gap, bhi - gap
    pa, pb = rnd.randint(alo, ahi), rnd.randint(blo, bhi)
    out = ["O1", f"G90 {plane} G21 G54 G64 F500.", "G00 X0. Y0. Z0.", f"G01 {a}{_num(pa)} {b}{_num(pb)}"]
    motion = "G01"
    for _ in range(lines):
        kind = rnd.choice(("line", "r", "r", "ij"))
        if kind == "ij":
            i, j = rnd.randint(-reach, reach), rnd.randint(-reach, reach)
            if i == 0 and j == 0:
                continue
            u = (-i, -j)
            for _q in range(rnd.randint(0, 3)):  # 0: a whole circle
                u = (-u[1], u[0])
            ea, eb = pa + i + u[0], pb + j + u[1]
            if rnd.random() < 0.4:  # off the circle by a unit (CAM rounding: a spiral within the tolerance)
                ea += rnd.choice((-1, 1))
            words = f"{a}{_num(ea)} {b}{_num(eb)} {la}{_num(i)} {lb}{_num(j)}"
        else:
            ea = min(ahi, max(alo, pa + rnd.randint(-reach, reach)))
            eb = min(bhi, max(blo, pb + rnd.randint(-reach, reach)))
            if kind == "line":
                words = f"{a}{_num(ea)} {b}{_num(eb)}"
            else:
                chord2 = (ea - pa) ** 2 + (eb - pb) ** 2
                if chord2 == 0:
                    continue
                r = math.isqrt(chord2) // 2 + 1 + rnd.randint(0, reach)
                words = f"{a}{_num(ea)} {b}{_num(eb)} R{_num(r if rnd.random() < 0.7 else -r)}"
        code = "G01" if kind == "line" else rnd.choice(("G02", "G03"))
        out.append(words if code == motion and rnd.random() < 0.5 else f"{code} {words}")
        motion = code
        pa, pb = ea, eb
    out.append("M30")
    return "\n".join(out) + "\n"


@settings(max_examples=3, deadline=None, database=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 2**32), st.sampled_from(sorted(_PLANES)), st.sampled_from([100, 1000]),
       st.sampled_from([300, 1000, 3000]), st.sampled_from(sorted(_MACHINES)))
def test_plain_arc_programs_decide_as_today(seed, plane, reach, gap, machine):
    """520 moves (past FAST_PATH_MIN_LINES: today's path is the fast path)."""
    _agree(_program(random.Random(seed), plane, 520, reach, gap), _MACHINES[machine])


#: examples of the long agreement test (``-m long``); NCZONES_FANUC_BOX_ARC_EXAMPLES changes it
LONG_EXAMPLES = int(os.environ.get("NCZONES_FANUC_BOX_ARC_EXAMPLES", "50"))


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 2**32), st.sampled_from(sorted(_PLANES)), st.sampled_from([100, 1000, 5000]),
       st.sampled_from([0, 300, 1000, 3000]), st.sampled_from(sorted(_MACHINES)), st.sampled_from([520, 3000]))
def test_plain_arc_programs_decide_as_today_long(seed, plane, reach, gap, machine, lines):
    verdict, taken = _agree(_program(random.Random(seed), plane, lines, reach, gap), _MACHINES[machine])
    SEEN[(verdict, taken)] = SEEN.get((verdict, taken), 0) + 1


#: what the long test met: (verdict, the route answered) -> programs
SEEN: dict[tuple[str, bool], int] = {}


@pytest.mark.long
def test_plain_arc_programs_counts():
    """Prints what test_plain_arc_programs_decide_as_today_long met (run after it: ``-m long -s``)."""
    print(SEEN)


def _inside(n: int) -> list[str]:
    """``n`` moves well inside the zone: about program (20, 20), a G01, a G02 R half-way round and a G03 I/J back."""
    cycle = ["G01 X20. Y20.", "G02 X21. Y20. R0.6", "G03 X20. Y20. I-0.5 J0."]
    return [cycle[k % 3] for k in range(n)]


@pytest.mark.parametrize("arc, expected, taken", [
    # from (40, 0) to (40, 20): G03 R10.001 is the minor arc about (39.5528.., 10), bulging to X 49.554 (inside,
    # 0.446 from the face X50.): safe, the route answers
    ("G03 X40. Y20. R10.001", "safe", True),
    # G03: the major arc about (40.4472.., 10), reaching X 40.4472 + 10.001 = 50.448 past the face: unsafe,
    # the route's box leaves the zone, it declines and today's path gives the witness
    ("G03 X40. Y20. R-10.001", "unsafe", False),
    # G02: the major arc about (39.5528.., 10), reaching X 29.55 and Y 10 +- 10.001 = -0.001 .. 20.001:
    # inside (the faces are X50. and Y40.; Y -10 is machine 40, far): safe
    ("G02 X40. Y20. R-10.001", "safe", True),
    # I/J: the half circle about (40, 10) clockwise from (40, 0) over -X: X 30 .. 40: safe; counter-clockwise it
    # bulges to X 50., the face itself: still safe (the boundary is allowed), the box touches the face
    ("G02 X40. Y20. I0. J10.", "safe", True),
    ("G03 X40. Y20. I0. J10.", "safe", True),
    # an I/J whole circle (equal ends) of radius 10.001 about (40, 10), from (29.999, 10): X 50.001, past the face
    ("G01 X29.999 Y10.|G03 X29.999 Y10. I10.001 J0.", "unsafe", False),
    # ... of radius 10: X 50., on the face: safe
    ("G01 X30. Y10.|G03 X30. Y10. I10. J0.", "safe", True),
])
def test_a_long_program_with_one_arc_at_the_face(arc, expected, taken):
    """600 moves well inside the zone, then a G01 to (40, 0) (or the first move given) and one arc near the face
    X50. (machine 150)."""
    moves = arc.split("|") if "|" in arc else ["G01 X40. Y0.", arc]
    text = "\n".join(["O1", "G90 G17 G21 G54 G64 F500.", "G00 X0. Y0. Z0.", *_inside(600), *moves,
                      "G01 X20. Y20.", "M30"]) + "\n"
    assert _agree(text, _MACHINES["box"]) == (expected, taken)
