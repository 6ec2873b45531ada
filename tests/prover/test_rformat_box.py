"""The box of an R-format arc whose centre is irrational (``ArcGeom.plane_bbox(sweep=True)``) holds the arc and
no more than the arc's own box (lead, session of 2026-12-06).

Before, such an arc was boxed by its whole circle: sound, but after the Fanuc G61/G09 hull (an arc outside a
cutting-mode run is proved by its box) a minor R arc bulging away from a zone face was ``unknown`` because the
far side of its circle crossed the face (tests/prover/test_fanuc_boxes.py, ``G02 R10.001``).  Now an axis
extreme enters the box only when the sweep may reach it for some centre on the segment that encloses the
exact one (:func:`nczones.prover.geometry._sweep_may_hold`).

The oracle is independent of that code: the centre from 200-bit bounds, the arc sampled with floats (cos, sin)
and its extremes found from the angles; the box must hold every sample (to 1e-9) and lie within the sampled
arc's box plus the extremes the float angles put in the sweep (to 1e-6).
"""

from __future__ import annotations

import math
from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import InvalidArgument
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover.geometry import arc_geom
from tests.prover.test_blend_screens import arcs

AXES = ("X", "Y", "Z")
coord = st.integers(-2000, 2000).map(lambda n: F(n, 100))


def _float_arc(g, ccw):
    (cxl, cxh), (cyl, cyh) = g.centre_bounds(200)
    cx, cy = float((cxl + cxh) / 2), float((cyl + cyh) / 2)
    sx, sy, ex, ey = (float(v) for v in (*g.s, *g.e))
    r = math.hypot(sx - cx, sy - cy)
    a0, a1 = math.atan2(sy - cy, sx - cx), math.atan2(ey - cy, ex - cx)
    sweep = (a1 - a0) % (2 * math.pi) if ccw else -((a0 - a1) % (2 * math.pi))
    pts = [(cx + r * math.cos(a0 + sweep * k / 400), cy + r * math.sin(a0 + sweep * k / 400)) for k in range(401)]
    for k in range(8):  # the axis extremes the float angles put in the sweep
        t = k * math.pi / 2
        d = (t - a0) % (2 * math.pi) if ccw else (a0 - t) % (2 * math.pi)
        if d <= abs(sweep):
            pts.append((cx + r * math.cos(t), cy + r * math.sin(t)))
    return pts, r


@settings(max_examples=300, deadline=None)
@given(coord, coord, coord, coord, st.integers(1, 4000), st.booleans(), st.booleans())
def test_the_box_of_an_r_arc_holds_it_and_no_more(sx, sy, ex, ey, extra, clockwise, major):
    chord = math.hypot(float(ex - sx), float(ey - sy))
    if chord == 0:
        return
    r = F(math.ceil(chord * 50), 100) + F(extra, 1000)  # at least half the chord, in 0.001 mm steps
    seg = Segment(SegmentKind.ARC, (sx, sy, F(0)), (ex, ey, F(0)), AXES, plane=Plane.XY, clockwise=clockwise,
                  radius=-r if major else r)
    g = arc_geom(seg)
    (xl, xh), (yl, yh) = g.plane_bbox(sweep=True)
    pts, rf = _float_arc(g, not clockwise)
    tol = 1e-9 * (1 + rf)
    for x, y in pts:
        assert float(xl) - tol <= x <= float(xh) + tol and float(yl) - tol <= y <= float(yh) + tol
    loose = 1e-6 * (1 + rf)
    assert float(xl) >= min(p[0] for p in pts) - loose and float(xh) <= max(p[0] for p in pts) + loose
    assert float(yl) >= min(p[1] for p in pts) - loose and float(yh) <= max(p[1] for p in pts) + loose


def _fraction_sweep_box(g, bits=64):
    """The sweep box as ``plane_bbox(sweep=True)`` computed it before full38: every sign test in Fraction
    arithmetic on the points themselves (no common scale), ``centre_bounds`` and the R-format parts read anew."""
    from nczones.prover import geometry
    from nczones.prover.geometry import sqrt_bounds

    (cxl, cxh), (cyl, cyh) = g.centre_bounds(bits)
    r_hi = sqrt_bounds(g.r_signed * g.r_signed, bits)[1]
    xs, ys = [g.s[0], g.e[0]], [g.s[1], g.e[1]]
    mx, my, nx, ny, q, sign = g.r_format_parts()
    ends = [(mx + sign * k * nx, my + sign * k * ny) for k in sqrt_bounds(q, bits)]
    for v, axis, sgn in geometry._DIRECTIONS:
        if geometry._sweep_may_hold(g.s, g.e, ends, v, g.ccw):
            c = (cxl, cxh) if axis == 0 else (cyl, cyh)
            (xs if axis == 0 else ys).append(c[1] + r_hi if sgn > 0 else c[0] - r_hi)
    return (min(xs), max(xs)), (min(ys), max(ys))


@settings(max_examples=150, deadline=None)
@given(coord, coord, coord, coord, st.integers(0, 4000), st.booleans(), st.booleans(),
       st.sampled_from([Plane.XY, Plane.XZ, Plane.YZ]), st.sampled_from([1, 3, 2**20]))
def test_the_integer_sweep_tests_are_the_fraction_ones(sx, sy, ex, ey, extra, clockwise, major, plane, den):
    """The sweep tests on the points times their common denominator (full38) give the box of the same tests in
    Fractions, exactly; R just above half the chord (``extra`` 0: within 0.01 mm) puts the centre bounds' segment
    across the chord's directions, where the signs differ at its two ends."""
    sx, sy, ex, ey = (v / den for v in (sx, sy, ex, ey))
    chord = math.hypot(float(ex - sx), float(ey - sy))
    if chord == 0:
        return
    r = F(math.ceil(chord * 50 * den), 100 * den) + F(extra, 1000)
    ia, ib = {Plane.XY: (0, 1), Plane.XZ: (2, 0), Plane.YZ: (1, 2)}[plane]
    start, end = [F(0)] * 3, [F(0)] * 3
    start[ia], start[ib], end[ia], end[ib] = sx, sy, ex, ey
    seg = Segment(SegmentKind.ARC, tuple(start), tuple(end), AXES, plane=plane, clockwise=clockwise,
                  radius=-r if major else r)
    g = arc_geom(seg)
    if g.centre is not None:  # R exactly half the chord: a rational centre, the exact tests
        return
    assert g.plane_bbox(sweep=True) == _fraction_sweep_box(g)


def _fraction_centre_box(g, bits=64):
    """``plane_bbox()`` of an arc with a rational centre as computed before full38: the sweep tests on the
    Fraction vectors from the centre."""
    from nczones.prover.geometry import in_sweep, sqrt_bounds

    c = g.centre
    r_hi = sqrt_bounds(g.r2_hi, bits)[1]
    xs, ys = [g.s[0], g.e[0]], [g.s[1], g.e[1]]
    u, w = (g.s[0] - c[0], g.s[1] - c[1]), (g.e[0] - c[0], g.e[1] - c[1])
    for v, axis, sgn in (((F(1), F(0)), 0, 1), ((F(-1), F(0)), 0, -1), ((F(0), F(1)), 1, 1), ((F(0), F(-1)), 1, -1)):
        if in_sweep(u, w, v, g.ccw, g.full):
            (xs if axis == 0 else ys).append(c[axis] + sgn * r_hi)
    if g.r2_lo != g.r2_hi:
        gap = 2 * (r_hi - sqrt_bounds(g.r2_lo, bits)[0])
        return (min(xs) - gap, max(xs) + gap), (min(ys) - gap, max(ys) + gap)
    return (min(xs), max(xs)), (min(ys), max(ys))


@settings(max_examples=150, deadline=None)
@given(st.data())
def test_the_integer_sweep_tests_of_a_rational_centre(data):
    """Arcs about a rational centre (circles, spirals, whole turns) from tests/prover/test_blend_screens.py."""
    seg = data.draw(arcs())
    try:
        g = arc_geom(seg)
    except InvalidArgument:  # a zero radius
        return
    assert g.plane_bbox() == _fraction_centre_box(g)
    assert g.plane_bbox(sweep=True) == _fraction_centre_box(g)
