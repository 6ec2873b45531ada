"""The per-motion proof screens an arc about a rational centre by its box computed in integers (arcs38).

``Prover._check_arc`` asks :func:`nczones.prover.geometry.rational_arc_plane_box` first (circles, spirals, whole
turns: the box ``arc_geom(seg).plane_bbox()`` gives, in integer arithmetic) and builds ``arc_geom`` only when
that box does not fit.  Checked here, on arcs drawn by tests/prover/test_blend_screens.py's ``arcs`` (a forbidden
clamp whose face touches the box, or lies just inside or outside it, on a drawn side):

- the integer box is ``plane_bbox``'s, bound for bound, and a box the former Fraction formulas compute
  (``_fraction_centre_box``, tests/prover/test_rformat_box.py);
- ``verify_segments`` answers the same verdict, reasons and counts with the integer screen as without it (the
  screen turned off: every arc through ``arc_geom`` as before).
"""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction
from math import ceil, floor

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from nczones.errors import InvalidArgument
from nczones.machine import parse_machine
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
