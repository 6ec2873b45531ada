"""An I/J arc whose end lies on the ray from the centre through its start (codes36, item 1).

LinuxCNC (posemath ``pmCircleInit``) moves a whole spiral turn there (the radii differ within the arc
tolerance).  The one-by-one path proves such an arc by its whole turn's box (``geometry.whole_turn_box``: the
centre +- the larger radius, the other axes from start to end) when that box fits, with parameter ranges by
the enclosure over the ranges (``Prover._check_arc_varying``), and otherwise, or with ``engine="z3"``, answers
``unknown`` (never a witness: the spiral's points are not modelled exactly).  Checked here:

- the box holds the path LinuxCNC moves: 200-bit points of the whole turn at both radii
  (``tests.gcode.test_double_pass.arc_points``, which computes them from the segment alone);
- ``safe`` when the box fits; ``unknown`` when a zone cuts the box but not the start..end sweep, or with
  ``engine="z3"``; with a parameter range, decided by the enclosure over the range (never by one value's box,
  also where the arc is on the ray at one end of the range only); and one by one, through the column screen, past 512 motions (the fast path) and
  on the Fanuc box route alike;
- a drawn on-ray arc is ``safe`` only if every point of its turn fits the drawn travel box (an independent check
  of the verdict: mpmath points at both radii against the box's faces).
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover import verify_text
from nczones.prover.core import verify_segments
from nczones.prover.geometry import arc_geom, on_start_ray, whole_turn_box
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import arc_points, check_arc_in_box
from tests.machines import box_zone, machine_text

F = Fraction
AXES = ("X", "Y", "Z")
EXAMPLES = int(os.environ.get("NCZONES_SPIRAL_TURN_EXAMPLES", "60"))
#: the wall at X >= 66 (tests/machines/xyz_spiral_wall.toml)
WALL = parse_machine(machine_text("xyz_spiral_wall"))
#: the wall and a clamp in the corner of the box of the turn about (62, 20) of radius 2, outside its circle
CORNER = parse_machine(machine_text("xyz_spiral_wall", extra=box_zone(
    "clamp", {"X": "63.8", "Y": "21.8"}, {"X": "64.5", "Y": "22.5"}, forbid=True)))
#: the end 0.001 further out on the start's ray, by start X
OUT = {"60": "60.001", "63": "63.001"}


def _program(start: str, arc: str, repeat: int = 1) -> str:
    return "G21 G90 G17 G61 F600\n" + f"G1 X{start} Y20 Z10\n{arc}\n" * repeat + "M30\n"


def _spiral(g: str = "G2", start: str = "60", end: str = "60.001", z: str = "") -> str:
    return f"{g} X{end} Y20{z} I2 J0"


def test_on_start_ray_is_the_end_on_the_start_s_ray():
    seg = Segment(SegmentKind.ARC, (F(1), F(0), F(0)), (F(2), F(0), F(0)), AXES, plane=Plane.XY, centre=(F(0), F(0)))
    assert on_start_ray(seg)
    for end in ((F(1), F(0)), (F(-2), F(0)), (F(0), F(2)), (F(2), F(1, 10**9))):  # equal, opposite, off the ray
        other = Segment(SegmentKind.ARC, seg.start, (*end, F(0)), AXES, plane=Plane.XY, centre=(F(0), F(0)))
        assert not on_start_ray(other), end
    assert not on_start_ray(Segment(SegmentKind.ARC, seg.start, seg.end, AXES, plane=Plane.XY,
                                    centre=(F(0), F(0)), turns=1))


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200)
@given(st.integers(-5000, 5000), st.integers(-5000, 5000), st.integers(-3000, 3000), st.integers(-3000, 3000),
       st.integers(-50, 50).filter(bool), st.booleans(), st.sampled_from([Plane.XY, Plane.XZ, Plane.YZ]),
       st.integers(-900, 900))
def test_the_whole_turn_box_holds_the_spiral(ca, cb, ua, ub, delta, clockwise, plane, other):
    """The box holds the whole turn at both radii (the spiral LinuxCNC moves lies between them) and the other
    axis's range; the turn is drawn on the ray of ``(ua, ub)`` out or in by ``delta`` thousandths of its
    length's step (an exact rational end)."""
    if (ua, ub) == (0, 0):
        ua = 1
    scale = F(1, 1000)
    k = 1 + F(delta, 10**5)
    ia, ib, ic = {Plane.XY: (0, 1, 2), Plane.XZ: (2, 0, 1), Plane.YZ: (1, 2, 0)}[plane]
    start, end = [F(0)] * 3, [F(0)] * 3
    c = (ca * scale, cb * scale)
    start[ia], start[ib] = c[0] + ua * scale, c[1] + ub * scale
    end[ia], end[ib] = c[0] + k * ua * scale, c[1] + k * ub * scale
    end[ic] = other * scale
    seg = Segment(SegmentKind.ARC, tuple(start), tuple(end), AXES, plane=plane, clockwise=clockwise, centre=c)
    assert on_start_ray(seg)
    lo, hi = whole_turn_box(seg)
    assert (lo[ic], hi[ic]) == (min(F(0), end[ic]), max(F(0), end[ic]))
    g = arc_geom(seg)
    assert g.full  # every box made of its geometry (blends, hulls, tool solids) holds the whole turn
    (bx, by) = g.plane_bbox(sweep=True)
    flat = Segment(SegmentKind.ARC, (start[ia], start[ib], F(0)), (end[ia], end[ib], F(0)), AXES,
                   plane=Plane.XY, clockwise=clockwise, centre=c)  # arc_points reads the X/Y plane
    check_arc_in_box(flat, {"X": lo[ia], "Y": lo[ib]}, {"X": hi[ia], "Y": hi[ib]})
    check_arc_in_box(flat, {"X": bx[0], "Y": by[0]}, {"X": bx[1], "Y": by[1]})


def test_safe_when_the_whole_turn_s_box_fits():
    for g in ("G2", "G3"):
        for end in ("60.001", "59.999"):
            text = _program("60", _spiral(g, end=end))
            assert verify_text(text, WALL).verdict is Verdict.SAFE, text
            helix = _program("60", _spiral(g, end=end, z=" Z12"))
            assert verify_text(helix, WALL).verdict is Verdict.SAFE, helix


def test_unknown_when_a_zone_cuts_the_box_only():
    """The clamp is in the box's corner, outside the circle of the larger radius: the path is clear, but the
    box does not prove it, so ``unknown`` (never ``unsafe``: no witness) with the reason; the wall, which the
    whole turn does reach (past X 66), is ``unknown`` too, not ``unsafe``."""
    for machine, start in ((CORNER, "60"), (WALL, "63")):
        r = verify_text(_program(start, _spiral(end=OUT[start])), machine)
        assert r.verdict is Verdict.UNKNOWN, r
        assert not r.violations
        assert any("whole spiral turn" in x.message and "does not fit" in x.message for x in r.reasons), r.reasons


@pytest.mark.parametrize("start, verdict", [("60", Verdict.SAFE), ("63", Verdict.UNKNOWN)])
def test_with_parameter_ranges_the_enclosure_over_the_ranges_decides(start, verdict):
    """With a range the turn is decided as an arc whose shape moves (``Prover._check_arc_varying``): proved by
    the centre's range +- the largest radius, else ``unknown``; a range proved ``safe`` is ``safe`` at each of
    its values, each value proved on its own (the range's ends and the middle)."""
    text = _program(start, _spiral(start=start, end=OUT[start]))
    r = verify_text(text, WALL, params=["G54.X=-0.001..0.001"])
    assert r.verdict is verdict, r.reasons
    if verdict is Verdict.SAFE:
        for value in ("-0.001", "0", "0.001"):
            shifted = verify_text(text, WALL, params=[f"G54.X={value}..{value}"])
            assert shifted.verdict is Verdict.SAFE, (value, shifted.reasons)
    else:
        assert any("enclosure over the whole ranges" in x.message for x in r.reasons), r.reasons


def test_unknown_with_z3_alone():
    text = _program("60", _spiral())
    r = verify_text(text, WALL, engine="z3")
    assert r.verdict is Verdict.UNKNOWN and any("engine z3" in x.message for x in r.reasons), r.reasons


#: an arc about (65, 25) of radius 2 from (63, 25): at the range's zero end its end (63.001, 25) is on the start's
#: ray (LinuxCNC moves a whole turn, out to X67, through the wall at X66); elsewhere in the range it is a tiny
#: sweep or a turn of a spiral that is not on the ray.  The start moves with ``start.Y`` (it is the reference
#: point), the end with ``G54.Y`` (the start is fixed by a G53 move).
_RAY_AT_AN_END = {"start": "G21 G90 G17 G61 F600\nG2 X{x} Y25 I2 J0\nM30\n",
                  "G54": "G21 G90 G17 G61 F600\nG53 G1 X{s} Y25 Z100\nG2 X{x} Y25 I2 J0\nM30\n"}


@pytest.mark.parametrize("which", ["start", "G54"])
@pytest.mark.parametrize("span", ["-0.01..0", "0..0.01", "-0.01..0.01"])
def test_a_range_whose_arc_lands_on_the_start_s_ray_at_one_value_is_never_safe(which, span):
    """A segment instantiated at one parameter combination reaches ``_decide_whole_turn`` as a concrete arc;
    one combination's box proof must never stand for the range.  At the value where the end lies on the ray the
    machine crosses the wall (the turn reaches X67), so the verdict is ``unknown`` or ``unsafe`` — and with the
    wall out of reach (the same arcs 35 mm further from it) the range is proved, so the test can tell them."""
    param = f"{which}.Y={span}"
    text = _RAY_AT_AN_END[which].format(x="63.001", s="63")
    assert verify_text(text, WALL, params=[param]).verdict is not Verdict.SAFE
    away = parse_machine(machine_text("xyz_spiral_wall", set={"machine.reference.X": "28"}))
    far = _RAY_AT_AN_END[which].format(x="28.001", s="28")
    r = verify_text(far, away, params=[param])
    assert r.verdict is Verdict.SAFE, r.reasons


@pytest.mark.parametrize("machine, start, verdict", [(WALL, "60", Verdict.SAFE), (CORNER, "60", Verdict.UNKNOWN),
                                                     (WALL, "63", Verdict.UNKNOWN)])
def test_the_fast_path_and_the_column_screen_agree(machine, start, verdict, monkeypatch):
    """Past 512 motions (the vectorized path's column screen boxes the turn by a larger box, then the rows it
    flags come one by one) the verdict is the short program's, and the outcome (reasons too) is the one-by-one
    path's (``fast=False``): the hunt ``test_plain_arc_programs_past_512_lines_hunt`` found the reasons differing
    when the one-by-one path left every such arc ``unknown``."""
    import nczones.pipeline.verification as verification
    from tests.contract.polygon_metamorphic import column_screen_forced
    from tests.prover.test_double_pass_arc_screens import _slow
    from tests.prover.test_double_pass_proof import same_outcome

    end = OUT[start]
    short = _program(start, _spiral(end=end))
    long = _program(start, _spiral(end=end), repeat=300)
    assert verify_text(short, machine).verdict is verdict
    fast = verify_text(long, machine)
    assert fast.verdict is verdict
    with column_screen_forced():
        assert verify_text(short, machine).verdict is verdict
    monkeypatch.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
    monkeypatch.setattr(verification, "interpretation", _slow(verification.interpretation))
    same_outcome(fast, verify_text(long, machine))


@pytest.mark.parametrize("start, verdict", [("60", Verdict.SAFE), ("63", Verdict.UNKNOWN)])
def test_the_fanuc_box_route_agrees(start, verdict):
    """The Fanuc box route boxes the turn as the per-motion proof does (it declined such an arc before)."""
    import nczones.prover.fanucboxes as fanucboxes

    machine = parse_machine(machine_text("xyz_spiral_wall", set={"machine.dialect": "fanuc"}))
    end = OUT[start]
    text = "O1\nG21 G90 G17 G54 G61 F600.\n" + f"G01 X{start}. Y20. Z10.\nG02 X{end} Y20. I2. J0.\n" * 300 + "M30\n"
    routed = verify_text(text, machine)
    assert routed.verdict is verdict
    assert ("fanuc_boxes" in dict(routed.stats)) is (verdict is Verdict.SAFE)
    saved = fanucboxes.ROUTE
    fanucboxes.ROUTE = False
    try:
        assert verify_text(text, machine).verdict is verdict
    finally:
        fanucboxes.ROUTE = saved


#: the wall and a clamp on the inner side of the corner before the turn about (62, 20) (the turn's box is clear)
_NW = box_zone("nw", {"X": "50", "Y": "20.05"}, {"X": "59.95", "Y": "21"}, forbid=True)


@pytest.mark.parametrize("dialect, repeat", [("linuxcnc", 1), ("fanuc", 1), ("linuxcnc", 150)])
def test_a_rounded_corner_before_the_turn_is_the_circle_s(dialect, repeat):
    """Found while making the arc provable: the corner checks boxed the arc by its (empty) sweep, so with the
    arc proved, a blended corner from a line into the turn (G64; Fanuc cutting mode: the run's hull) was
    ``safe`` where the same corner into the exact circle (end = start) is ``unknown`` (VF208: the blend may
    reach the clamp on the corner's inner side).  Past 512 motions (``repeat`` 150: the column screen proved
    the turn's box before this change) LinuxCNC's was ``safe`` already.  ``arc_geom`` makes such an arc a whole
    turn now: the same verdict as the circle's, and ``safe`` with exact stops (G61)."""
    machine = parse_machine(machine_text("xyz_spiral_wall", set={"machine.dialect": dialect}, extra=_NW))
    dot = "." if dialect == "fanuc" else ""
    for mode, verdict in (("G64", Verdict.UNKNOWN), ("G61", Verdict.SAFE)):
        for end in ("60.001", f"60{dot}"):
            body = (f"G1 X30{dot} Y10{dot}\nG1 X60{dot} Y20{dot}\nG2 X{end} Y20{dot} I2{dot} J0{dot}\n"
                    f"G1 X60{dot} Y10{dot}\n")
            text = f"O1\nG21 G90 G17 G54 {mode} F600{dot}\nG1 Z10{dot}\nG1 Y5{dot}\n" + body * repeat + "M30\n"
            if dialect == "linuxcnc":
                text = text.replace("O1\n", "")
            r = verify_text(text, machine)
            assert r.verdict is verdict, (text, r.reasons)
            assert not r.violations
            if verdict is Verdict.UNKNOWN:
                assert r.reasons and {x.code for x in r.reasons} == {"VF208"}, r.reasons


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200)
@given(st.integers(58000, 70000), st.integers(1000, 99000), st.integers(-3000, 3000), st.integers(-3000, 3000),
       st.integers(-5, 5).filter(bool), st.booleans(), st.sampled_from([0, 0, 1]))
def test_a_safe_turn_keeps_off_the_wall_at_every_point(ca, cb, ua, ub, delta, clockwise, margin):
    """A drawn turn near the wall (X >= 66, tests/machines/xyz_spiral_wall.toml), with and without a margin:
    ``safe`` only when every point of the turn at both radii keeps the margin off the wall and inside the
    travel box (mpmath, 200 bits); ``unsafe`` never (no witness is claimed)."""
    import mpmath

    if (ua, ub) == (0, 0):
        ua = 1000
    scale = F(1, 1000)
    k = 1 + F(delta, 10**4)
    c = (ca * scale, cb * scale)
    start = (c[0] + ua * scale, c[1] + ub * scale, F(10))
    end = (c[0] + k * ua * scale, c[1] + k * ub * scale, F(10))
    seg = Segment(SegmentKind.ARC, start, end, AXES, plane=Plane.XY, clockwise=clockwise, centre=c, block=1)
    r = verify_segments([seg], WALL, margin=F(margin, 10))
    assert r.verdict is not Verdict.UNSAFE
    if r.verdict is Verdict.SAFE:
        d = mpmath.mpf(margin) / 10
        with mpmath.workprec(200):
            for px, py in arc_points(seg):
                assert d <= px <= 66 - d and d <= py <= 100 - d, (px, py)


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
@pytest.mark.parametrize("param, verdict", [("home.X=-0.5..0.5", Verdict.SAFE), ("home.Z=-5..5", Verdict.SAFE),
                                            ("home.X=0..3", Verdict.UNKNOWN)])
def test_a_homing_range_decides_an_arc_on_the_start_s_ray(dialect, param, verdict):
    """hunt37: a homing error moves every coordinate, so with a ``home.*`` range every segment names it, the
    arc instantiated at one value of the range too: ``_decide_whole_turn`` took that concrete arc for a ranged
    one and went back to ``_check_arc_varying`` until a RecursionError (an internal error in both dialects, since
    9ec9f3b).  The turn about (62, 20) of radius 2 reaches X64.001; the wall is at X66: proved over a homing
    error of 0.5 mm (the enclosure takes the start's and the end's deviations apart: the centre's range +- the
    radius and twice the error), not over one of 3 mm (no witness of the spiral itself: ``unknown``)."""
    machine = parse_machine(machine_text("xyz_spiral_wall", set={"machine.dialect": dialect}))
    text = "G21 G90 G17 G61 F600.\nG1 X60. Y20. Z10.\nG2 X60.001 Y20. I2. J0.\nM30\n"
    r = verify_text(text, machine, params=[param])
    assert r.verdict is verdict, r.reasons
