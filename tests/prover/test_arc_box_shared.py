"""An arc's box and whole-turn test computed once, in integers (comp39), against the former code kept here.

The corner check and the per-motion proof box the same arc (a cutter compensation corner: a spiral about the
programmed corner); :func:`nczones.prover.geometry.rational_arc_plane_box` keeps its answers by segment, its
square-root bounds come from integers (``_scaled_root``), and :func:`~nczones.prover.geometry.on_start_ray`
works on the points times their common denominator and keeps its last answer.  Checked here:

- ``_scaled_root`` is ``sqrt_bounds``'s bound, value for value (squares, non-squares, every ``bits``);
- ``on_start_ray`` answers as the Fraction formula, on Hypothesis arcs (whole turns, rays, spirals);
- the kept box is the computed one, for another ``bits`` too, and after other arcs pushed it out;
- whole G41/G42 programs verified against a forbidden clamp whose face touches (or cuts, or clears) a corner
  arc's box answer exactly as with the former functions patched in (verdict, reasons, violations, counts).
"""

from __future__ import annotations

from fractions import Fraction
from fractions import Fraction as F
from math import ceil, floor, lcm

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError, InvalidArgument
from nczones.gcode import interpret_text, program_text
from nczones.machine import parse_machine
from nczones.motion import PathMode, Segment, SegmentKind
from nczones.pipeline.verification import VerifyOptions, verify_source
from nczones.prover import blend, core, geometry
from nczones.prover.geometry import _cross, _dot, arc_geom, sqrt_bounds
from tests.gcode.test_cutter_comp_fast import _MACHINES, comp_programs
from tests.machines import machine_text
from tests.prover.test_arc_box_screen import _clamp, _decimal
from tests.prover.test_blend_screens import arcs
from tests.sizes import examples


# ---------------------------------------------------------------------------------------------- references
def ref_on_start_ray(seg) -> bool:
    """The former ``on_start_ray``: Fraction arithmetic."""
    c = seg.centre
    if c is None or seg.turns:
        return False
    ia, ib, _ = seg.plane_indices()
    u = (seg.start[ia] - c[0], seg.start[ib] - c[1])
    w = (seg.end[ia] - c[0], seg.end[ib] - c[1])
    return u != w and _cross(u, w) == 0 and _dot(u, w) > 0


def ref_rational_arc_plane_box(seg, bits: int = 64):
    """The former ``rational_arc_plane_box`` (arcs38): computed at every call, roots by ``sqrt_bounds``."""
    centre = seg.centre
    if centre is None or seg.plane is None:
        return None
    ia, ib, _ = seg.plane_indices()
    vals = (seg.start[ia], seg.start[ib], seg.end[ia], seg.end[ib], centre[0], centre[1])
    try:
        dens = [v._denominator for v in vals]
        nums = [v._numerator for v in vals]
    except AttributeError:
        return None
    d = lcm(*dens)
    s0, s1, e0, e1, c0, c1 = (n * (d // q) for n, q in zip(nums, dens))
    u, w = (s0 - c0, s1 - c1), (e0 - c0, e1 - c1)
    u2, w2 = u[0] * u[0] + u[1] * u[1], w[0] * w[0] + w[1] * w[1]
    if u2 == 0:
        return None
    full = seg.turns > 0 or (_cross(u, w) == 0 and _dot(u, w) > 0)
    dd = d * d
    r_hi = sqrt_bounds(Fraction(max(u2, w2), dd), bits)[1]
    r_lo = sqrt_bounds(Fraction(min(u2, w2), dd), bits)[0] if u2 != w2 else r_hi
    big = lcm(d, r_hi.denominator, r_lo.denominator)
    m = big // d
    hi = r_hi.numerator * (big // r_hi.denominator)
    xs, ys = [s0 * m, e0 * m], [s1 * m, e1 * m]
    ccw = not seg.clockwise
    for v, axis, sgn in geometry._INT_DIRECTIONS:
        if geometry.in_sweep(u, w, v, ccw, full):
            (xs if axis == 0 else ys).append((c1 if axis else c0) * m + sgn * hi)
    g = 2 * (hi - r_lo.numerator * (big // r_lo.denominator)) if u2 != w2 else 0
    return ((Fraction(min(xs) - g, big), Fraction(max(xs) + g, big)),
            (Fraction(min(ys) - g, big), Fraction(max(ys) + g, big)), ia, ib)


def ref_half_box(seg, dogleg, end):
    """The former ``blend._half_box`` (builtin min/max)."""
    m = tuple(map(blend._mid, seg.start, seg.end))
    p = seg.end if end else seg.start
    if blend._linear(seg, dogleg):
        return tuple(map(min, m, p)), tuple(map(max, m, p))
    if seg.kind is blend._ARC:
        half = blend._half_arc_box(seg, end)
        if half is not None:
            lo, hi = list(map(min, m, p)), list(map(max, m, p))
            (xl, xh), (yl, yh), ia, ib = half
            lo[ia], hi[ia], lo[ib], hi[ib] = xl, xh, yl, yh
            return tuple(lo), tuple(hi)
    return blend._piece_box(seg)


def ref_screen_box(self, a, b, mode):
    """The former ``CornerCheck._screen_box`` (the straight motion's half box summed with the arc's box)."""
    if mode.dialect == "fanuc" and mode.tolerance is None:
        return None
    bound = mode.bound()
    if bound is None and mode.naive:
        return None
    if blend._linear(a, self.dogleg) and blend._linear(b, self.dogleg) and blend._same(b.start, a.end):
        lo, hi = [blend.F0] * len(self.axes), [blend.F0] * len(self.axes)
        for i in self.rel:
            x, y, z = a.start[i], a.end[i], b.end[i]
            lo[i], hi[i] = blend._lo(blend._lo(x, y), z), blend._hi(blend._hi(x, y), z)
            if bound:
                lo[i] -= bound
                hi[i] += bound
        return tuple(lo), tuple(hi)
    if bound is None:
        ba = ref_half_box(a, self.dogleg, end=True) if blend._linear(a, self.dogleg) else self._piece_box(a)
        bb = ref_half_box(b, self.dogleg, end=False) if blend._linear(b, self.dogleg) else self._piece_box(b)
        if ba is None or bb is None:
            return None
        c = a.end
        return tuple(map(blend._plus_less, ba[0], bb[0], c)), tuple(map(blend._plus_less, ba[1], bb[1], c))
    pa, pb = self._piece_box(a), self._piece_box(b)
    if pa is None or pb is None:
        return None
    g = bound or blend.F0
    return tuple(min(x, y) - g for x, y in zip(pa[0], pb[0])), tuple(max(x, y) + g for x, y in zip(pa[1], pb[1]))


# ---------------------------------------------------------------------------------------------- pieces
@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.integers(0, 10**30) | st.integers(0, 10**6).map(lambda k: k * k), st.integers(1, 10**12),
       st.sampled_from([4, 53, 64, 96]), st.booleans())
def test_scaled_root_is_the_sqrt_bound(n2, d, bits, upper):
    num, den = geometry._scaled_root(n2, d, bits, upper)
    assert Fraction(num, den) == sqrt_bounds(Fraction(n2, d * d), bits)[1 if upper else 0]


@settings(max_examples=300, deadline=None, derandomize=True)
@given(seg=arcs())
def test_on_start_ray_is_the_fraction_formula(seg):
    assert geometry._on_start_ray(seg) == ref_on_start_ray(seg)
    assert geometry.on_start_ray(seg) == ref_on_start_ray(seg)
    assert geometry.on_start_ray(seg) == ref_on_start_ray(seg)  # the kept answer


@settings(max_examples=200, deadline=None, derandomize=True)
@given(seg=arcs(), bits=st.sampled_from([8, 30, 64]))
def test_the_kept_box_is_the_computed_one(seg, bits):
    want = ref_rational_arc_plane_box(seg, bits)
    assert geometry.rational_arc_plane_box(seg, bits) == want
    assert geometry.rational_arc_plane_box(seg, bits) == want  # kept
    assert geometry.rational_arc_plane_box(seg) == ref_rational_arc_plane_box(seg)  # another bits: not the kept
    if want is not None:
        try:
            g = arc_geom(seg)
        except InvalidArgument:
            return
        assert want == (*g.plane_bbox(bits), g.ia, g.ib)


def test_a_box_pushed_out_is_computed_again():
    from nczones.motion import Plane

    def arc(k: int) -> Segment:
        return Segment(SegmentKind.ARC, (F(k + 1), F(0)), (F(k), F(1)), ("X", "Y"), plane=Plane.XY,
                       centre=(F(k), F(0)))

    first = arc(0)
    want = ref_rational_arc_plane_box(first)
    assert geometry.rational_arc_plane_box(first) == want
    for k in range(1, geometry._KEPT + 10):
        geometry.rational_arc_plane_box(arc(k))
    assert len(geometry._PLANE_BOXES) <= geometry._KEPT
    assert geometry.rational_arc_plane_box(first) == want


_G64 = PathMode(True, None, F(0), "linuxcnc", "G64")
_PT = st.tuples(*[st.integers(-10**4, 10**4).map(lambda k: F(k, 8))] * 3)


@settings(max_examples=examples(150, 2000), deadline=None, derandomize=True)
@given(seg=arcs(), far=_PT, other=_PT, line_first=st.booleans(), joined=st.booleans())
def test_a_line_arc_corner_screen_box_is_the_former(seg, far, other, line_first, joined):
    """The straight motion before the arc (from ``far``), or after it (to ``far``, from the arc's end or, not
    joined, from ``other``: the former sum then)."""
    check = blend.CornerCheck(parse_machine(machine_text("box_5000")), F(0), (), [(-1, _G64)])
    if line_first:
        a, b = Segment(SegmentKind.LINE, far, seg.start, seg.axes), seg
    else:
        a, b = seg, Segment(SegmentKind.LINE, seg.end if joined else other, far, seg.axes)
    assert check._screen_box(a, b, _G64) == ref_screen_box(check, a, b, _G64)


# ---------------------------------------------------------------------------------------------- whole programs
def _former(mp: pytest.MonkeyPatch) -> None:
    mp.setattr(geometry, "on_start_ray", ref_on_start_ray)
    mp.setattr(core, "on_start_ray", ref_on_start_ray)
    mp.setattr(geometry, "rational_arc_plane_box", ref_rational_arc_plane_box)
    mp.setattr(core, "rational_arc_plane_box", ref_rational_arc_plane_box)
    mp.setattr(blend, "_half_box", ref_half_box)
    mp.setattr(blend.CornerCheck, "_screen_box", ref_screen_box)


def _local_clamp(seg, side: int, where: str) -> str:
    """A forbidden clamp 1 deep beyond one face of the arc's box, as ``_clamp`` places it (``touch``, ``cut``,
    ``clear``), but only as wide as the box on the plane's other axis (rounded to 0.001 inward): the lines on
    either side of the corner arc pass it, the arc's extreme decides."""
    text = _clamp(seg, side, where)
    (bx, by, ia, ib) = geometry.rational_arc_plane_box(seg)
    other, (olo, ohi) = (seg.axes[ib], by) if side < 2 else (seg.axes[ia], bx)
    lo, hi = Fraction(ceil(olo * 1000), 1000), Fraction(floor(ohi * 1000), 1000)
    assume(lo < hi)
    text = text.replace("min = { ", f"min = {{ {other} = \"{_decimal(lo)}\", ", 1)
    return text.replace("max = { ", f"max = {{ {other} = \"{_decimal(hi)}\", ", 1)


def _verdict(text: str, machine) -> tuple:
    result = verify_source(program_text(text, "<comp>"), machine, VerifyOptions())
    return result.verdict, result.reasons, result.violations, result.stats


@settings(max_examples=examples(20, 300), deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.filter_too_much])
@given(case=comp_programs(), pick=st.integers(0, 100), side=st.integers(0, 3),
       where=st.sampled_from(["touch", "cut", "clear"]))
def test_a_clamp_at_a_corner_arc_answers_as_the_former_code(case, pick, side, where):
    """The whole verification (corner check included) of a G41/G42 program with a forbidden clamp whose face
    touches, cuts or clears a corner arc's box, with the code as it is and with the former functions."""
    text, off = case
    try:
        segs = list(interpret_text(text, _MACHINES[off]).segments())
    except GcodeError:
        assume(False)
    corners = [s for s in segs if s.derived == "cutter comp corner" and ref_rational_arc_plane_box(s) is not None]
    assume(corners)
    seg = corners[pick % len(corners)]
    machine = parse_machine(machine_text("mill_cutter_comp_g54", set={"offsets.G54": {"X": off[0], "Y": off[1]}},
                                         extra=_local_clamp(seg, side, where)))
    now = _verdict(text, machine)
    with pytest.MonkeyPatch.context() as mp:
        _former(mp)
        before = _verdict(text, machine)
    assert now == before
