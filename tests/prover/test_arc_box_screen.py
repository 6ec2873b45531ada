"""The per-motion proof screens an arc about a rational centre by its box computed in integers (arcs38).

``Prover._check_arc`` asks :func:`nczones.prover.geometry.rational_arc_plane_box` first (circles, spirals, whole
turns: the box ``arc_geom(seg).plane_bbox()`` gives, in integer arithmetic) and builds ``arc_geom`` only when
that box does not fit.  Checked here, on arcs drawn by tests/prover/test_blend_screens.py's ``arcs`` (a forbidden
clamp whose face touches the box, or lies just inside or outside it, on a drawn side):

- the integer box is ``plane_bbox``'s, bound for bound, and a box the former Fraction formulas compute
  (``_fraction_centre_box``, tests/prover/test_rformat_box.py);
- an R-format arc's parts (``ArcGeom.r_format_parts``, now from integers) are the Fraction formulas';
- ``verify_segments`` answers the same verdict, reasons and counts with the integer screen as without it (the
  screen turned off: every arc through ``arc_geom`` as before).
"""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction
from fractions import Fraction as F
from math import ceil, floor, isqrt

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from nczones.errors import InvalidArgument
from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover import core
from nczones.prover.geometry import arc_geom, rational_arc_plane_box
from tests.machines import box_zone, machine_text
from tests.prover.test_blend_screens import arcs
from tests.prover.test_rformat_box import _fraction_centre_box


@settings(max_examples=200, deadline=None)
@given(seg=arcs())
def test_the_integer_box_is_the_fraction_one(seg):
    try:
        g = arc_geom(seg)
    except InvalidArgument:  # a zero radius: arc_geom refuses it, and the integer box is None
        assert rational_arc_plane_box(seg) is None
        return
    got = rational_arc_plane_box(seg)
    assert got == (*_fraction_centre_box(g), g.ia, g.ib)
    assert got == (*g.plane_bbox(), g.ia, g.ib)


def _decimal(x: Fraction) -> str:
    return str(Decimal(x.numerator) / Decimal(x.denominator)) if 10**12 % x.denominator == 0 else str(x)


def _clamp(seg, side: int, where: str) -> str:
    """A forbidden clamp 1 thick beyond one face of the arc's box (``side``: 0-3, low/high of the plane's two axes),
    its face at the box's bound (``touch``) or at the bound rounded to 0.001 inward (``cut``) or outward."""
    (bx, by, ia, ib) = rational_arc_plane_box(seg)
    axis, high = (seg.axes[ia], bx) if side < 2 else (seg.axes[ib], by), side % 2
    bound = bx[high] if side < 2 else by[high]
    inward = (high == 1) == (where == "cut")
    face = bound if where == "touch" else Fraction((floor if inward else ceil)(bound * 1000), 1000)
    if where == "touch" and 10**12 % face.denominator:
        face = Fraction(floor(bound * 1000) if high else ceil(bound * 1000), 1000)  # not a decimal: just inside
    lo, hi = (face, face + 1) if high else (face - 1, face)
    assume(not lo <= 0 <= hi)  # the machine's reference point (the start) outside the clamp
    assume(-10**6 < lo and hi < 10**6)  # a machine file's magnitudes
    return box_zone("clamp", {axis[0]: _decimal(lo)}, {axis[0]: _decimal(hi)}, forbid=True)


@settings(max_examples=40, deadline=None)
@given(seg=arcs(), side=st.integers(0, 3), where=st.sampled_from(["touch", "cut", "clear"]))
def test_the_screen_answers_as_arc_geom(seg, side, where):
    try:
        arc_geom(seg)
    except InvalidArgument:
        return
    machine = parse_machine(machine_text("box_5000", extra=_clamp(seg, side, where)))
    with_screen = core.verify_segments([seg], machine)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(core, "rational_arc_plane_box", lambda s, bits=64: None)
        without = core.verify_segments([seg], machine)
    assert with_screen.verdict == without.verdict
    assert with_screen.reasons == without.reasons
    assert with_screen.violations == without.violations
    assert with_screen.stats == without.stats


def _fraction_r_parts(g):
    """``ArcGeom.r_format_parts`` as computed before arcs38: Fraction arithmetic on the points."""
    (sx, sy), (ex, ey) = g.s, g.e
    cx, cy = ex - sx, ey - sy
    q = g.r_signed * g.r_signed / (cx * cx + cy * cy) - F(1, 4)
    sign = -1 if (not g.ccw) != (g.r_signed < 0) else 1
    return (sx + ex) / 2, (sy + ey) / 2, -cy, cx, q, sign


_COORD = st.integers(-10**6, 10**6)


@settings(max_examples=200, deadline=None)
@given(_COORD, _COORD, _COORD, _COORD, st.sampled_from([1, 3, 1000, 2**52]), st.integers(0, 10**6),
       st.booleans(), st.booleans())
def test_the_r_format_parts_are_the_fraction_ones(sx, sy, ex, ey, den, extra, clockwise, major):
    """The R-format parts from integers equal the Fraction formulas' (R from just half the chord up)."""
    sx, sy, ex, ey = (F(v, den) for v in (sx, sy, ex, ey))
    if (sx, sy) == (ex, ey):
        return
    half = F(isqrt(int(((ex - sx) ** 2 + (ey - sy) ** 2) * 10**12)) + 1, 2 * 10**6)
    r = half + F(extra, 10**4)
    seg = Segment(SegmentKind.ARC, (sx, sy, F(0)), (ex, ey, F(0)), ("X", "Y", "Z"), plane=Plane.XY,
                  clockwise=clockwise, radius=-r if major else r)
    g = arc_geom(seg)
    if g.centre is not None:  # q a square: a rational centre, no R-format parts after arc_geom
        return
    assert g.r_format_parts() == _fraction_r_parts(g)


_SMALL = st.integers(-6, 6)
_POINT = st.tuples(_SMALL, _SMALL)


@settings(max_examples=400, deadline=None)
@given(s=_POINT, e=_POINT, ends=st.one_of(st.tuples(_POINT, _POINT), _POINT.map(lambda p: (p, p))),
       ccw=st.booleans())
def test_the_four_sweep_tests_are_sweep_may_hold(s, e, ends, ccw):
    """``_axis_sweeps_may_hold`` (each end's vectors once for the four directions) answers as
    ``_sweep_may_hold`` direction by direction; small integers put many signs at 0 (collinear points)."""
    from nczones.prover import geometry

    want = [geometry._sweep_may_hold(s, e, list(ends), v, ccw) for v, _a, _s in geometry._INT_DIRECTIONS]
    assert geometry._axis_sweeps_may_hold(s, e, list(ends), ccw) == want
