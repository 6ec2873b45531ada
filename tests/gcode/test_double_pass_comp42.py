"""comp42: the compensated moves' quicker code in the double pass (nczones/gcode/linuxcnc/double_comp.py).

``corner_box`` is ``double_arcs._box`` in one function, its directions the union over the quadrants the exact
vectors may lie in (no angles for an end on the centre's axis): where no component is within ``err`` of 0 it is
``_box``'s box bit for bit; near an axis, with the exact vectors anywhere within ``err / 2`` of the doubles, it
holds the exact arc's extremes (an exact reference: pseudo-angles in Fractions), a sweep of about a whole turn
included.  ``Comp.line`` (a move naming only the plane's axes) gives the rows ``Comp.straight`` gives.
"""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import double_comp
from nczones.gcode.linuxcnc.double_arcs import sector_box
from nczones.gcode.linuxcnc.double_comp import corner_box
from nczones.gcode.linuxcnc.doubles import double_pass
from tests.machines import load_machine

MILL = load_machine("mill_cutter_comp_g54")
_U = 2.0**-52


def _err(sx, sy, ex, ey, cx, cy, offb):
    """``corner_box``'s ``err`` (the bound of the exact ``u``, ``w`` per component: the module's docstring)."""
    r0, r1 = math.hypot(sx - cx, sy - cy), math.hypot(ex - cx, ey - cy)
    return (64.0 * (abs(sx) + abs(sy) + r0 + r1 + offb) + 0.0625) * _U


def _former(sx, sy, ex, ey, cx, cy, cw, offb):
    """comp41's ``corner_box``: ``double_arcs._box`` (``sector_box``) with the same ``err``."""
    ux, uy, wx, wy = sx - cx, sy - cy, ex - cx, ey - cy
    r0, r1 = math.hypot(ux, uy), math.hypot(wx, wy)
    err = _err(sx, sy, ex, ey, cx, cy, offb)
    diff, big = (r1 - r0, r1) if r1 > r0 else (r0 - r1, r0)
    return sector_box(sx, sy, ex, ey, cx, cy, ux, uy, wx, wy, big, diff + err, err, cw)


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


@settings(max_examples=400, deadline=None)
@given(centres, centres, radii, angles, angles, st.booleans())
def test_the_box_is_the_former_one_away_from_the_axes(cx, cy, r, a0, a1, cw):
    sx, sy, ex, ey = cx + r * math.cos(a0), cy + r * math.sin(a0), cx + r * math.cos(a1), cy + r * math.sin(a1)
    err = _err(sx, sy, ex, ey, cx, cy, 150.0)
    new = corner_box(sx, sy, ex, ey, cx, cy, cw, 150.0)
    old = _former(sx, sy, ex, ey, cx, cy, cw, 150.0)
    if min(abs(v) for v in (sx - cx, sy - cy, ex - cx, ey - cy)) > err:
        assert new == old
    else:  # near an axis: as tight as the former box's (the same here, or within the widening)
        assert all(abs(n - o) <= 4 * err for n, o in zip(new, old)), (new, old)


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
