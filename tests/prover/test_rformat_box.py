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

from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover.geometry import arc_geom

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
