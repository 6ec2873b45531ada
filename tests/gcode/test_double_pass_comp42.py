"""comp42: the compensated moves' quicker code in the double pass (nczones/gcode/linuxcnc/double_comp.py).

``corner_box`` is ``double_arcs.sector_box`` (the box of every arc of the pass, dup44: one function) with
``ij_check``'s ``err``: the box of an I/J arc about the same centre is the corner arc's bit for bit.  Its
directions are the union over the quadrants the exact vectors may lie in (no angles for an end on the centre's
axis): near an axis, with the exact vectors anywhere within ``err / 2`` of the doubles, it holds the exact arc's
extremes (an exact reference: pseudo-angles in Fractions), a sweep of about a whole turn included.
``Comp.line`` (a move naming only the plane's axes) gives the rows ``Comp.straight`` gives.
"""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import double_comp
from nczones.gcode.linuxcnc.double_arcs import ij_arc
from nczones.gcode.linuxcnc.double_comp import corner_box
from nczones.gcode.linuxcnc.doubles import double_pass
from tests.machines import load_machine

MILL = load_machine("mill_cutter_comp_g54")
_U = 2.0**-52


def _err(sx, sy, ex, ey, cx, cy, offb):
    """``corner_box``'s ``err`` (the bound of the exact ``u``, ``w`` per component: the module's docstring)."""
    r0, r1 = math.hypot(sx - cx, sy - cy), math.hypot(ex - cx, ey - cy)
    return (64.0 * (abs(sx) + abs(sy) + r0 + r1 + offb) + 0.0625) * _U


def _pseudo(x: Fraction, y: Fraction) -> Fraction:
    """A pseudo-angle in [0, 4) of a nonzero vector, increasing with its angle (exact)."""
    if y >= 0:
        return y / (x + y) if x > 0 else 1 - x / (y - x)
    return 2 - y / (-x - y) if x < 0 else 3 + x / (x - y)


def _crossed(u, w):
    """The directions (+X, +Y, -X, -Y) in the exact counter-clockwise sweep from ``u`` to ``w`` (ends included)."""
    a, b = _pseudo(*u), _pseudo(*w)
    sweep = (b - a) % 4
    return [(Fraction(d) - a) % 4 <= sweep for d in range(4)]


centres = st.floats(-300, 300, allow_nan=False).map(lambda v: round(v, 3))
radii = st.floats(0.3, 8.0).map(lambda v: round(v, 3))
#: angles on or near an axis (as quarter arcs' ends), and anywhere
angles = st.one_of(st.sampled_from([0.0, math.pi / 2, math.pi, -math.pi / 2]),
                   st.integers(0, 3).flatmap(lambda q: st.floats(-1e-14, 1e-14).map(lambda e: q * math.pi / 2 + e)),
                   st.floats(-math.pi, math.pi))


#: directions with rational components ``(a / c, b / c)``: the axes', 3-4-5's and 5-12-13's
units = st.sampled_from([(1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1), (3, 4, 5), (-4, 3, 5), (-3, -4, 5), (4, -3, 5),
                         (5, 12, 13), (-12, -5, 13)])


@settings(max_examples=400, deadline=None)
@given(st.integers(-2400, 2400), st.integers(-2400, 2400), st.integers(1, 64), units, units, st.booleans(),
       st.sampled_from([0.0, 1e-4, -1e-4, 2.0**-40]), st.none() | angles, st.integers(-64, 64))
def test_a_corner_arc_s_box_is_the_ij_arc_s(cx8, cy8, r8, u0, u1, cw, spiral, a1, nudge):
    """Both call sites of the one box function: ``corner_box`` (double_comp) and ``ij_arc`` (double_arcs:
    ``ij_check``, then ``sector_box``) give one box for one arc: ends on the centre's axes (where comp41's
    ``_box`` took its directions by angles, ``corner_box`` by quadrants), in one quadrant, anywhere (``a1``), the
    end ``spiral`` off the circle, the start ``nudge`` 2**-40 off it (within about ``err`` of an axis: where the
    angles and the quadrants took other directions).  The start and the centre are exact (eighths, plus the
    nudge: ``S + (I, J)`` exact, as ``S - C``), so both compute the same ``u``, ``w``, radii and ``err``."""
    cx, cy = cx8 / 8, cy8 / 8
    sx = cx + r8 * (65 // u0[2]) * u0[0] / 8 + nudge * 2.0**-40  # radius 65 r8 / 8
    sy = cy + r8 * (65 // u0[2]) * u0[1] / 8 - nudge * 2.0**-40
    r = r8 * 65 / 8 * (1 + spiral)
    ex, ey = ((cx + r * u1[0] / u1[2], cy + r * u1[1] / u1[2]) if a1 is None else
              (cx + r * math.cos(a1), cy + r * math.sin(a1)))
    i, j = cx - sx, cy - sy
    assert sx + i == cx and sy + j == cy
    arc = ij_arc(sx, sy, ex, ey, i, j, cw, 150.0, -1.0)
    if arc.__class__ is str:  # declined by ij_check (an end on the start's ray, the tolerance): no box to compare
        return
    assert arc == corner_box(sx, sy, ex, ey, cx, cy, cw, 150.0), (sx, sy, ex, ey, cx, cy, cw)


@settings(max_examples=400, deadline=None)
@given(centres, centres, radii, st.integers(0, 3), st.integers(0, 3), st.booleans(),
       st.tuples(*[st.sampled_from([Fraction(-1, 2), Fraction(0), Fraction(1, 2)])] * 4))
def test_the_box_holds_the_exact_arc_near_the_axes(cx, cy, r, q0, q1, cw, shifts):
    """Ends on the centre's axes (a quarter, half, three-quarter arc, or none), the exact vectors ``err / 2``
    off the doubles either way: the box holds the ends and the exact arc's extreme in every direction its sweep
    crosses (a sweep of about a whole turn: all four)."""
    axis = ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))
    sx, sy = cx + r * axis[q0][0], cy + r * axis[q0][1]
    ex, ey = cx + r * axis[q1][0], cy + r * axis[q1][1]
    err = Fraction(_err(sx, sy, ex, ey, cx, cy, 150.0))
    box = corner_box(sx, sy, ex, ey, cx, cy, cw, 150.0)
    u = (Fraction(sx - cx) + shifts[0] * err, Fraction(sy - cy) + shifts[1] * err)
    w = (Fraction(ex - cx) + shifts[2] * err, Fraction(ey - cy) + shifts[3] * err)
    crossed = _crossed(w, u) if cw else _crossed(u, w)
    low = min(math.hypot(*u), math.hypot(*w)) * (1 - 1e-12)
    extremes = [(cx + low, None), (None, cy + low), (cx - low, None), (None, cy - low)]
    for hit, (x, y) in zip(crossed, extremes):
        if hit:
            assert x is None or box[0] <= x <= box[1], (box, x)
            assert y is None or box[2] <= y <= box[3], (box, y)
    assert box[0] <= min(sx, ex) and max(sx, ex) <= box[1] and box[2] <= min(sy, ey) and max(sy, ey) <= box[3]


def test_a_whole_turn_within_err_takes_every_direction():
    """The start ``err / 2`` above the +X axis, the end on it: counter-clockwise, the exact sweep may be a whole
    turn less a sliver (the doubles alone, a quarter of it less: the box would miss three extremes)."""
    box = corner_box(11.0, 0.0, 11.0, 0.0, 10.0, 0.0, False, 150.0)
    assert box[0] < 9.0 + 1e-9 and box[2] < -1.0 + 1e-9 and box[3] > 1.0 - 1e-9


def _rows(text):
    path = double_pass(text, MILL, max_iterations=100)
    return [list(col) for col in path.columns], list(path.arc_rows), list(path.arc_boxes)


def test_line_gives_straights_rows(monkeypatch):
    """The same contours through ``Comp.line`` and through ``Comp.straight`` (the plans' general call):
    the same rows, arcs and boxes."""
    text = ("G21 G90 G17 G54 F800\nT1 M6\n#1 = 0.25\nG0 X0 Y0\nG41 G1 X5 Y0\nX15 Y[#1 + 1.25]\nX25\nY-2\n"
            "X35 Y-1\nG0 X35 Y10\nG1 X20 Y[10 + #1]\nX20 Y[10 + #1]\nX10 Y10\nG3 X5 Y15 I0 J5\nG1 X0\n"
            "X-2 Y0\nG40 G0 X0 Y-5\nM30\n")
    fast = _rows(text)
    monkeypatch.setattr(double_comp.Comp, "line", lambda self, mode, x, y: self.straight(
        mode, (x, y), tuple((k, i) for k, i, w in ((0, self.ia, x), (1, self.ib, y)) if w is not None)))
    assert _rows(text) == fast
    assert fast[1]  # corner arcs
