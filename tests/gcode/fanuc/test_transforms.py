"""Fanuc programmable transforms: G68/G69 rotation, G51/G50 scaling, G51.1/G50.1 mirror image, G16/G15 polar
coordinates — golden machine positions with their derivations, and parameter ranges through a transform.

The test mill: G54 = (100, 50, -200), EXT Z 1 (so program Z0 is machine Z -199).
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction as Q

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

from .helpers import BOX_ZONE, ends, mill, probe_route

START = "G90 G17 G54 G0 X0 Y0 Z0\n"


def segs(text, machine=None):
    run = interpret_text(text, machine or mill())
    out = list(run.segments())
    return out, run


def test_rotation_about_the_origin_with_an_arc():
    # G68 R90 about (0, 0): X10 -> (0, 10) -> machine (100, 60); the CCW arc from (10, 0) to (0, 10) about
    # (0, 0) turns into the arc from (0, 10) to (-10, 0) about (0, 0): end (90, 50), centre (100, 50), still CCW.
    out, run = segs(START + "G68 X0 Y0 R90.\nG1 X10. F100.\nG3 X0 Y10. I-10. J0\nG69\nG0 X0 Y0\n")
    assert run.status == "complete"
    assert [tuple(s.end[:2]) for s in out[1:]] == [(100, 60), (90, 50), (100, 50)]
    assert out[2].centre == (100, 50) and not out[2].clockwise


def test_rotation_about_a_centre_rounds_to_the_increment():
    # G68 X10 Y0 R30: X20 Y0 is 10 from the centre: (10 + 10 cos 30, 10 sin 30) = (18.660254.., 5) ->
    # rounded to 0.001 mm: (18.660, 5.000) -> machine (118.660, 55).  Incremental G91 X10 rotates the step too.
    out, _ = segs(START + "G68 X10. Y0 R30.\nG1 X20. F100.\nG91 X10.\n")
    assert tuple(out[1].end[:2]) == (Q("118.660"), 55)
    assert tuple(out[2].end[:2]) == (Q("127.321"), 60)  # (10 + 20 cos 30, 20 sin 30) = (27.3205, 10)


def test_incremental_rotation_angle_with_rin():
    m = mill("rotation_incremental = true")
    # G68 R30 then G91 G68 R60: 90 in total; G90 X10 -> (0, 10) -> machine (100, 60)
    out, _ = segs(START + "G68 X0 Y0 R30.\nG91 G68 R60.\nG90 G1 X10. F100.\n", m)
    assert tuple(out[-1].end[:2]) == (100, 60)


def test_mirror_image_reverses_arcs():
    # G51.1 X5: X10 -> 0 -> machine 100; the CW arc (10, 3) -> (12, 5) about (12, 3) mirrors to the CCW arc
    # (0, 3) -> (-2, 5) about (-2, 3): end (98, 55), centre (98, 53).
    out, _ = segs(START + "G51.1 X5.\nG1 X10. Y3. F100.\nG2 X12. Y5. I2. J0\nG50.1\nG0 X0\n")
    assert tuple(out[1].end[:2]) == (100, 53)
    assert tuple(out[2].end[:2]) == (98, 55) and out[2].centre == (98, 53) and not out[2].clockwise
    assert tuple(out[3].end[:2]) == (100, 55)


def test_scaling_with_p_and_per_axis_factors():
    # G51 X0 Y0 Z0 P2000 (unit 0.001): X10 Y3 -> (20, 6) -> machine (120, 56).
    # G51 X0 Y0 Z0 I-1000 J500 K1000: X10 Y4 -> (-10, 2) -> machine (90, 52); factors with a point: I-1. as well.
    assert ends(START + "G51 X0 Y0 Z0 P2000\nG1 X10. Y3. F100.\n")[-1][:2] == (120, 56)
    assert ends(START + "G51 X0 Y0 Z0 I-1000 J500 K1000\nG1 X10. Y4. F100.\n")[-1][:2] == (90, 52)
    assert ends(START + "G51 X0 Y0 Z0 I-1. J.5 K1.\nG1 X10. Y4. F100.\n")[-1][:2] == (90, 52)
    # a uniform factor scales an arc's radius: R10 -> 20 (the chord from X20 to X40, 20 long, is shorter)
    out, _ = segs(START + "G51 X0 Y0 Z0 P2.\nG1 X10. F100.\nG2 X20. Y0 R10.\n")
    assert out[-1].radius == 20 and tuple(out[-1].end[:2]) == (140, 50)


def test_polar_bolt_circle_with_a_drilling_cycle():
    # G16: X is the radius, Y the angle about the work zero: 50 at 0, 120, 240 degrees ->
    # (50, 0), (-25, 43.30127..) -> (-25, 43.301), (-25, -43.301); machine X 150, 75, 75.
    pts = ends("G90 G17 G54 G0 X0 Y0 Z10.\nG16\nG81 G99 X50. Y0 Z-5. R2. F100.\nY120.\nY240.\nG80 G15\n")
    holes = [p[:2] for p in pts if p[2] == -204]
    assert holes == [(150, 50), (75, Q("93.301")), (75, Q("6.699"))]


def test_transform_combinations_and_unmodelled_uses_are_unknown():
    for text, code in [
        (START + "G68 X0 Y0 R10.\nG51.1 X0\nG1 X1. F100.\n", "G68"),
        (START + "G68 X0 Y0 R10.\nG91 G1 X1. F100.\n", "G1"),
        (START + "G68 X0 Y0 R10.\nG28 X0\n", "G28"),
        (START + "G68 X0 Y0 R10.\nG55\n", "G55"),
        (START + "G68 X0 Y0\n", "G68"),
        (START + "G51 X0 Y0 Z0 I2000 J1000 K1000\nG2 X1. Y1. R1. F100.\n", "G51"),
        (START + "G16\nG91 G1 X10. Y10. F100.\n", "G1"),
    ]:
        _, run = segs(text)
        assert run.status == "unknown" and run.unsupported[0].code == code, (text, run.unsupported)


def test_first_move_after_cancel_must_be_absolute():
    _, run = segs(START + "G68 X0 Y0 R10.\nG1 X5. F100.\nG69\nG91 G1 X1.\n")
    assert run.status == "unknown" and run.unsupported[0].span.line == 5


_TRANSFORM_PAIRS = [("G68 X0 Y0 R90.", "G69"), ("G51 X0 Y0 Z0 I2. J2. K1.", "G50")]


def _hole_after_cancel(on: str, off: str, holes: int = 0) -> str:
    """hunt42's H2: a hole line in G90 right after the cancel, ``holes`` more, then an incremental move."""
    more = "".join(f"X{k % 7}. Y{k % 5}.\n" for k in range(holes))
    return (f"G17 G40 G80 G21 G90 G54 F300.\nG00 Z20.\n{on}\nG90 G00 X1. Y1. Z10.\nG81 X2. Y2. Z-1. R2. F200.\n"
            f"{off}\nX5. Y5.\n{more}G80\nG91 G01 X1. Y1.\nM30\n")


@pytest.mark.parametrize(("on", "off"), _TRANSFORM_PAIRS)
def test_a_hole_in_g90_is_the_first_move_after_a_cancel(on, off):
    """The hole line ``X5. Y5.`` (G90) after G69 / G50 is the absolute first move the manuals ask for: the later
    G91 move is read (from the last hole, machine (105, 55) at G54, to (106, 56)); the fast path (600 holes more:
    the vectorized hole template) gives the same segments, and the box route the full path's verdict."""
    out, run = segs(_hole_after_cancel(on, off))
    assert run.status == "complete", run.unsupported
    assert tuple(out[-1].end[:2]) == (106, 56)
    assert [s.end for s in out if s.end[2] == -200][-1][:2] == (105, 55)  # the hole after the cancel, unmoved
    text = _hole_after_cancel(on, off, 600)
    full = interpret_text(text, mill(), fast=False)
    fast = interpret_text(text, mill(), fast=True)
    assert [(s.kind, s.start, s.end) for s in fast.segments()] == [(s.kind, s.start, s.end) for s in full.segments()]
    assert full.status == fast.status == "complete" and fast.fast_lines > 0
    zone = mill(tables=BOX_ZONE)
    for program in (_hole_after_cancel(on, off), text):  # the box route with its reader, without it, no route
        got = [probe_route(program, zone, "t.nc", runs=runs, route=route)[0]
               for runs, route in ((True, True), (False, True), (True, False))]
        assert {(r.verdict.label, tuple(r.reasons)) for r in got} == {("safe", ())}


@pytest.mark.parametrize(("on", "off"), _TRANSFORM_PAIRS)
def test_an_incremental_hole_right_after_a_cancel_is_unknown(on, off):
    """A G91 hole as the first move after G69 / G50 is an incremental first move, which the manuals give no
    meaning (as a G91 G01 there): unknown at that line on the full path and the fast path, not drilled."""
    text = (f"G17 G40 G80 G21 G90 G54 F300.\nG00 Z20.\n{on}\nG90 G00 X1. Y1. Z10.\n{off}\n"
            "G91 G81 X5. Y5. Z-5. R-8. F200.\nX1.\nG80\nG90 G00 X0. Y0.\nM30\n")
    for fast in (False, True):
        run = interpret_text(text, mill(), fast=fast)
        list(run.segments())
        assert run.status == "unknown" and [(u.code, u.span.line) for u in run.unsupported] == [("G81", 6)], fast


# ---------------------------------------------------------------- parameter ranges through a transform

FENCE = machine_text("fanuc_rotated_fence")

ROTATED = "G90 G17 G54 G0 X0 Y0 Z0\nG68 X0 Y0 R90.\nG1 Y-5. F100.\nG1 X10. F100.\nG69\n"
# derivation: after R90, Y-5 is (5, 0) and X10 (with Y-5) is (5, 10) -> machine X 105 at G54.X 100:
# 3 mm short of the fence at 108.


def test_a_range_on_g54_x_is_proved_through_the_rotation():
    m = parse_machine(FENCE)
    assert verify_text(ROTATED, m).verdict.label == "safe"
    assert verify_text(ROTATED, m, params=["G54.X=-2..2"]).verdict.label == "safe"
    r = verify_text(ROTATED, m, params=["G54.X=-4..4"])
    assert r.verdict.label == "unsafe"
    used = dict(r.violations[0].params)["G54.X"]
    assert used > 3
    # the counterexample's value, applied to the machine, is unsafe too
    from types import MappingProxyType

    shifted = replace(m, offsets=MappingProxyType({"G54": (Q(100) + used, Q(50), Q(0))}))
    assert verify_text(ROTATED, shifted).verdict.label == "unsafe"


@settings(max_examples=12, deadline=None)
@given(st.integers(0, 6), st.sampled_from(["G68 X0 Y0 R90.", "G51.1 Y0", "G16"]))
def test_range_verdicts_agree_with_their_end_values(width, transform):
    # metamorphic: a range verdict is safe exactly when both ends of the range (the worst cases of a
    # translation) are safe
    from types import MappingProxyType

    m = parse_machine(FENCE)
    prog = ("G90 G17 G54 G0 X0 Y0 Z0\n" + transform + "\n"
            + ("G1 X5. Y0 F100.\n" if transform == "G16" else "G1 Y-5. F100.\nG1 X5. F100.\n"))
    ranged = verify_text(prog, m, params=[f"G54.X=-{width}..{width}"]).verdict.label
    ends_safe = all(
        verify_text(prog, replace(m, offsets=MappingProxyType({"G54": (Q(100 + d), Q(50), Q(0))}))).verdict.label
        == "safe" for d in (-width, width))
    assert (ranged == "safe") == ends_safe


# --------------------------------------------------------------------------- certified rotation and polar points

def _reference_round(value, step):
    """``value`` (an mpmath number) rounded to a multiple of ``step``, halves away from zero, and how far
    (in steps) it is from the nearest halfway point."""
    import mpmath

    k = value / (mpmath.mpf(step.numerator) / step.denominator)
    n = mpmath.floor(abs(k) + mpmath.mpf(1) / 2)
    tie_distance = abs(abs(k) - mpmath.floor(abs(k)) - mpmath.mpf(1) / 2)
    return Q(int(-n if k < 0 else n)) * step, tie_distance


def _mp(q):
    import mpmath

    return mpmath.mpf(q.numerator) / q.denominator


_STEP = Q(1, 1000)
_decimals = st.integers(-2_000_000, 2_000_000).map(lambda n: Q(n, 1000))  # -2000..2000 mm on the 0.001 grid
# angles with up to 3 decimals, often on the rational angles (multiples of 30 and 45 degrees)
_angles = st.one_of(st.integers(-720_000, 720_000).map(lambda n: Q(n, 1000)),
                    st.integers(-24, 24).map(lambda n: Q(30 * n)), st.integers(-16, 16).map(lambda n: Q(45 * n)))


@settings(max_examples=300, deadline=None, derandomize=True)
@given(_angles, _decimals, _decimals, _decimals, _decimals)
def test_certified_rotation_is_the_exact_rotation_rounded(angle, x, y, cx, cy):
    """Whenever the block is not unknown, the rotated point is the 50-digit mpmath rotation rounded to the
    increment; it is unknown only within the guard of a rounding tie."""
    import mpmath

    from nczones.gcode.fanuc.transforms import TIE_GUARD, PointNotCertain, Rotation, rotate

    mpmath.mp.dps = 50
    t = _mp(angle) * mpmath.pi / 180
    dx, dy = _mp(x - cx), _mp(y - cy)
    ref = [_reference_round(dx * mpmath.cos(t) - dy * mpmath.sin(t), _STEP),
           _reference_round(dx * mpmath.sin(t) + dy * mpmath.cos(t), _STEP)]
    try:
        got = rotate(Rotation(0, 1, cx, cy, angle), [x, y, Q(7)], _STEP)
    except PointNotCertain:
        assert min(d for _, d in ref) <= _mp(TIE_GUARD) + mpmath.mpf(10) ** -30
        return
    assert got == [cx + ref[0][0], cy + ref[1][0], Q(7)]


@settings(max_examples=300, deadline=None, derandomize=True)
@given(_angles, st.integers(0, 2_000_000).map(lambda n: Q(n, 1000)))
def test_certified_polar_point_is_the_exact_point_rounded(angle, radius):
    import mpmath

    from nczones.gcode.fanuc.transforms import TIE_GUARD, PointNotCertain, polar_point

    mpmath.mp.dps = 50
    t = _mp(angle) * mpmath.pi / 180
    ref = [_reference_round(_mp(radius) * mpmath.cos(t), _STEP), _reference_round(_mp(radius) * mpmath.sin(t), _STEP)]
    try:
        got = polar_point(radius, angle, _STEP)
    except PointNotCertain:
        assert min(d for _, d in ref) <= _mp(TIE_GUARD) + mpmath.mpf(10) ** -30
        return
    assert got == (ref[0][0], ref[1][0])


def test_a_point_on_a_rounding_tie_is_unknown_not_rounded_by_a_guess():
    # G68 R30 about (0, 0): X0 Y0.001 -> X' = -0.001 sin 30 = -0.0005, exactly halfway between two increments:
    # a control computing sin 30 in doubles (0.49999999999999994) stands on 0, one rounding halves away on
    # -0.001.  The block is unknown; the moves before it are kept.
    out, run = segs(START + "G68 X0 Y0 R30.\nG1 X0 Y0.001 F100.\nG1 X5.\n")
    assert run.status == "unknown" and run.unsupported[0].code == "G68"
    assert "halfway between two increments" in run.unsupported[0].reason
    assert len(out) == 1
    # G16: radius 0.001 at 30 degrees: Y = 0.0005, a tie as well
    out, run = segs(START + "G16 G1 X0.001 Y30. F100.\n")
    assert run.status == "unknown" and run.unsupported[0].code == "G16"
    # one increment further from the tie it is certain: 0.003 sin 30 = 0.0015 is a tie too, 0.002 sin 30 is not
    out, run = segs(START + "G16 G1 X0.002 Y30. F100.\nG15\n")
    assert run.status == "complete" and tuple(out[-1].end[:2]) == (Q("100.002"), Q("50.001"))
