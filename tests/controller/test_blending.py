"""The reference controller rounds G64 corners with LinuxCNC's blend arcs (nczones/controller/blending.py).

Expected values are derived by hand from LinuxCNC's planner (``src/emc/tp/blendmath.c``, the functions named
in each test), not read from the code under test.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

from nczones.cli import main
from nczones.controller import Settings, simulate
from nczones.controller.blending import BlendArc, blend_motion, blends
from nczones.errors import InvalidArgument, MachineFileError
from nczones.exact import format_decimal
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import box_zone, machine_text

ACCEL = '[machine.acceleration]\nX = "500"\nY = "500"\nZ = "500"'
L_CORNER = "G1 F3000 X100 Y0\nG1 X100 Y100\nG1 X0 Y100\n"


def _text(x0="95", y0="1", x1="99", y1="5", accel=ACCEL, **machine):
    """The test machine (tests/machines/xyz_table_200_blend.toml) with a clamp, an acceleration table (``accel``,
    "" for none) and ``[machine]`` keys (``path_mode="G61"``)."""
    clamp = box_zone("clamp", {"X": x0, "Y": y0, "Z": "-10"}, {"X": x1, "Y": y1, "Z": "10"}, forbid=True)
    return machine_text("xyz_table_200_blend", set={f"machine.{k}": v for k, v in machine.items()},
                        extra=clamp + (accel + "\n" if accel else ""))


def _machine(x0="95", y0="1", x1="99", y1="5", accel=ACCEL, **machine):
    return parse_machine(_text(x0, y0, x1, y1, accel, **machine))


def _alarms(text, m, **settings):
    return simulate(interpret_text(text, m, fast=False), m, settings=Settings(**settings)).alarms


def test_the_issue_l_corner_alarms_when_blended_and_not_on_the_exact_path():
    # issue 35: G1 X100 Y0 / G1 X100 Y100 around the forbidden box X95..99 Y1..5; the blend arc (radius 20/pi,
    # below) passes X = 100 - r + r cos(45deg) = 98.14, Y = r (1 - sin 45deg) = 1.86 on its way: inside the box
    m = _machine()
    blended = _alarms(L_CORNER, m)
    assert blended and blended[0].zone == "clamp" and blended[0].derived == "G64 blend arc"
    assert _alarms(L_CORNER, m, blending="exact") == ()
    assert _alarms("G61\n" + L_CORNER, m) == ()  # the program's own G61 (the interpreter's path-mode table)
    assert _alarms("G61.1\n" + L_CORNER, m) == ()
    assert verify_text(L_CORNER, m).verdict.label == "unknown"  # the prover: the corner may pass the clamp


def test_blend_arc_radius_follows_the_planner():
    # F3000 (50 mm/s), 100 mm motions at 90 degrees, a = 500 mm/s^2 on X and Y, v = 100 mm/s:
    # theta = 45deg; tcFindBlendTolerance (no P): T = min(100/4, 100/4) = 25; L1 = L2 = 50 (BLEND_DIST_FRACTION);
    # blendComputeParameters: h_tol = 25 / (1 - sin 45) = 85.36, d_tol = cos 45 * h_tol = 60.36, d_geom = 50,
    # R_geom = tan 45 * 50 = 50; a_max = 500 (inscribed diameter in the XY plane), a_n = 500 sqrt(0.75) = 433.0;
    # v_goal = 50 (the feed; the planar bound is 100); v_plan = min(sqrt(433.0 * 50), 50) = 50;
    # a_par = 250, v_triangle = sqrt(2 * 250 * 50) = 158.1, t_blend = 50 / 250 = 0.2, s_blend = 10,
    # R_blend = min(10 / (pi/2), 50) = 20/pi = 6.366; R_accel = 50^2 / 433.0 = 5.774; R_plan = 20/pi,
    # d_plan = R_plan / tan 45 = 20/pi.
    m = _machine()
    run = interpret_text(L_CORNER, m, fast=False)
    items = list(blend_motion(list(run.segments()), m, run))
    arcs = [a for a in items if isinstance(a, BlendArc)]
    assert len(arcs) == 2 and len(items) == 5
    r = 20 / math.pi
    assert arcs[0].radius == pytest.approx(r, rel=1e-12)
    assert arcs[0].start[:2] == pytest.approx((100 - r, 0.0)) and arcs[0].end[:2] == pytest.approx((100.0, r))
    assert arcs[0].centre[:2] == pytest.approx((100 - r, r))
    assert float(items[0].end[0]) == pytest.approx(100 - r)  # the first motion trimmed by d_plan
    assert arcs[0].speed_mm_s == pytest.approx(50.0)


@pytest.mark.parametrize("gap, alarmed", [("0.02", False), ("0.005", True)])
def test_g64_p_keeps_the_blend_within_p(gap, alarmed):
    # G64 P0.01: tcFindBlendTolerance T = min(0.01, 100/4, 100/4) = 0.01; blendComputeParameters: d_tol limits,
    # h = T / (1 - sin theta) from the corner to the centre, R = h sin theta, so the arc's middle is h - R = T from
    # the corner, on the bisector: (100 - T/sqrt2, T/sqrt2) = (99.99293, 0.00707).  A clamp X <= 100 - gap,
    # Y >= gap (its corner at (100 - gap, gap) on that bisector) holds that point when gap <= 0.00707.
    # The prover (specs/path-modes.md: within p + q = 0.02 per axis of the motions) proves gap 0.02, not 0.005.
    g = Fraction(gap)
    m = _machine(x0=format_decimal(100 - g - 5), y0=format_decimal(g), x1=format_decimal(100 - g),
                 y1=format_decimal(g + 5))
    text = "G64 P0.01\n" + L_CORNER
    assert bool(_alarms(text, m)) is alarmed
    assert (verify_text(text, m).verdict.label == "safe") is (not alarmed)


def test_auto_blends_only_where_the_machine_starts_in_g64_with_accelerations():
    assert blends(_machine(), "auto")
    assert not blends(_machine(accel=""), "auto")  # no accelerations: the exact path
    assert not blends(_machine(path_mode="G61"), "auto")
    assert not blends(_machine(dialect="fanuc"), "auto")  # Fanuc: exact path, the prover unknown
    assert not blends(_machine(), "exact") and blends(_machine(), "linuxcnc")
    with pytest.raises(InvalidArgument, match="acceleration"):
        blends(_machine(accel=""), "linuxcnc")
    with pytest.raises(InvalidArgument, match="blending"):
        blends(_machine(), "parabolic")


def test_a_machine_path_tolerance_blends_within_it():
    # [machine] path_tolerance 0.01: the control starts in G64 P0.01; the arc's middle (100 - 0.00707, 0.00707)
    # (derivation above) lies in the clamp X 99.99..99.999 Y 0.001..0.01
    m = _machine(x0="99.99", y0="0.001", x1="99.999", y1="0.01", path_tolerance="0.01")
    assert _alarms(L_CORNER, m)
    m = _machine(x0="99.99", y0="0.001", x1="99.999", y1="0.01", path_tolerance="0.0001")
    assert not _alarms(L_CORNER, m)  # within 0.0001 of the path: every pulse position has X = 100 or Y = 0


def test_rapids_blend_too_and_a_dwell_stops_the_corner():
    # G0 (tpAddLine for traverses blends alike) at v = 100 mm/s: v_plan = min(sqrt(433.0 * 50), 100) = 100,
    # t_blend = min(158.1, 100) / 250 = 0.4, s_blend = 40, R_blend = 40 / (pi/2) = 25.46, R_accel = 100^2 / 433.0
    # = 23.09, so R = 80/pi; the arc's middle is (100 - R (1 - 1/sqrt2), R (1 - 1/sqrt2)) = (92.54, 7.46)
    m = _machine(x0="92", y0="7", x1="93", y1="8")
    assert _alarms("G0 X100 Y0\nG0 X100 Y100\n", m)
    assert not _alarms("G61\nG0 X100 Y0\nG0 X100 Y100\n", m)
    m = _machine()
    assert _alarms(L_CORNER, m)
    assert not _alarms("G1 F3000 X100 Y0\nG4 P0.1\nG1 X100 Y100\n", m)  # DWELL waits for the queue


@pytest.mark.parametrize("table, code", [('[machine.acceleration]\nX = "500"\nY = "500"', "ZN102"),
                                         ('[machine.acceleration]\nX = "500"\nY = "0"\nZ = "1"', "ZN106"),
                                         ('[machine.acceleration]\nX = "500"\nY = "5"\nZ = "1"\nQ = "1"', "ZN110")])
def test_acceleration_table_is_validated(table, code):
    with pytest.raises(MachineFileError) as e:
        _machine(accel=table)
    assert code in [d.code for d in e.value.diagnostics]


def test_simulate_command_takes_the_blending_option(tmp_path, capsys):
    machine = tmp_path / "m.toml"
    machine.write_text(_text())
    prog = tmp_path / "l.ngc"
    prog.write_text(L_CORNER)
    assert main(["simulate", str(prog), "--machine", str(machine)]) != 0  # auto: blends, alarms in the clamp
    assert "clamp" in capsys.readouterr().out
    assert main(["simulate", str(prog), "--machine", str(machine), "--blending", "exact"]) == 0
    capsys.readouterr()
    machine.write_text(_text(accel=""))
    assert main(["simulate", str(prog), "--machine", str(machine), "--blending", "linuxcnc"]) == 2
    assert "acceleration" in capsys.readouterr().err


def test_line_arc_blend_follows_the_planner():
    # G1 to (100, 0) heading +X, then G3 X50 Y50 I-50 J0: a quarter circle of radius 50 around (50, 0), leaving
    # (100, 0) heading +Y: a 90 degree corner, theta_tan = 45deg.  blendInit3FromLineArc (tp.c
    # tpCreateLineArcBlend): arcConvexTest((50,0), P, u1 = +X, reverse) = (P - C2).u1 = 50 >= 0: convex, so
    # phi2_max = min(sweep / 3, theta_tan) = pi/6; the secant to the point pi/12 along the arc cuts theta to
    # theta_tan - phi2_max / 4 = 5pi/24; L1 = min(100, 100/2) = 50, L2 = sin(phi2_max / 4) * 50 = 50 sin(pi/24)
    # = 6.526.  tcFindBlendTolerance: T = min(100/4, 78.54/4) = 19.63, d_tol = cos(theta) T / (1 - sin(theta))
    # = 39.8, so d_geom = L2 and R_geom = tan(5pi/24) * L2 = 5.008.  a_max = 500, a_n = 500 sqrt(0.75);
    # v_plan = min(sqrt(a_n R_geom), 50) = 46.57 (F3000 = 50 mm/s), so R_plan = v_plan^2 / a_n = R_geom.
    # blendLineArcPostProcess: the blend circle (radius R) is inside the arc's circle, tangent to it, its
    # centre at distance d2 = 50 - R from (50, 0) and R above the line: centre (100 - dL, R) with
    # (50 - dL)^2 + R^2 = (50 - R)^2, dL = 50 - sqrt(2500 - 100 R) = 5.288 (the smaller root); the arc is
    # trimmed by the angle of the centre seen from (50, 0): atan2(R, 50 - dL) = 0.1116 rad < pi/6.
    m = _machine()
    text = "G1 F3000 X100 Y0\nG3 X50 Y50 I-50 J0\nG61\nG4 P0\n"
    run = interpret_text(text, m, fast=False)
    items = list(blend_motion(list(run.segments()), m, run))
    blend = [a for a in items if isinstance(a, BlendArc) and a.label == "G64 blend arc"]
    assert len(blend) == 1
    theta, l2 = 5 * math.pi / 24, 50 * math.sin(math.pi / 24)
    r = math.tan(theta) * l2
    d_l = 50 - math.sqrt(2500 - 100 * r)
    t2 = math.atan2(r, 50 - d_l)
    arc = blend[0]
    assert arc.radius == pytest.approx(r, rel=1e-9)
    assert arc.centre[:2] == pytest.approx((100 - d_l, r))
    assert arc.start[:2] == pytest.approx((100 - d_l, 0.0))
    assert arc.end[:2] == pytest.approx((50 + 50 * math.cos(t2), 50 * math.sin(t2)))
    assert arc.speed_mm_s == pytest.approx(math.sqrt(500 * math.sqrt(0.75) * r))
    # the arc then runs from the blend's end on its circle (a piece of the programmed arc)
    trimmed = items[items.index(arc) + 1]
    assert isinstance(trimmed, BlendArc) and trimmed.circle is not None
    assert trimmed.circle.angle == pytest.approx(math.pi / 2 - t2)
    assert trimmed.point(1.0)[:2] == pytest.approx((50.0, 50.0))


NAIVE_ZIGZAG = "G64 P0.01 Q{q}\nG1 F3000 X10 Y0.4\nG1 X20 Y0\nG1 X30 Y0.4\nG1 X40 Y0\nG61\nG4 P0\n"


@pytest.mark.parametrize("q, lines", [("0.5", 1), ("0.3", 4)])
def test_naive_cam_merges_lines_within_q(q, lines):
    # emccanon linkable: the points (10,0.4) (20,0) (30,0.4) lie 0.4 from the chord (0,0)-(40,0): within
    # Q0.5 the four lines are sent as that one chord; with Q0.3 not even (10,0.4) (0.4 from (0,0)-(20,0)) links
    m = _machine()
    run = interpret_text(NAIVE_ZIGZAG.format(q=q), m, fast=False)
    moved = [s for s in blend_motion(list(run.segments()), m, run) if not isinstance(s, BlendArc)
             and s.kind.name == "LINE"]
    assert len(moved) == lines
    if lines == 1:
        assert (moved[0].start[:2], moved[0].end[:2]) == ((0, 0), (40, 0))


def test_naive_cam_chains_at_most_101_points():
    # linkable refuses a point when the chain holds more than 100: 150 collinear lines are sent as two,
    # the first to the 101st point (X101), the second to the last
    m = _machine()
    text = "G64 P0.01\nG1 F3000 " + "\n".join(f"X{k}" for k in range(1, 151)) + "\nG61\nG4 P0\n"
    run = interpret_text(text, m, fast=False)
    moved = [s for s in blend_motion(list(run.segments()), m, run) if s.kind.name == "LINE"]
    assert [(float(s.start[0]), float(s.end[0])) for s in moved] == [(0.0, 101.0), (101.0, 150.0)]
