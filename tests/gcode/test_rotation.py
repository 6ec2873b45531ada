"""G10 L2 R: XY rotation of a coordinate system, computed in doubles as LinuxCNC does, taken exactly."""

from __future__ import annotations

import math
from fractions import Fraction

from nczones.gcode import interpret_text, segments_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from tests.machines import machine_text

F = Fraction
MILL = parse_machine(machine_text("mill_xyz"))


def _rot(x: float, y: float, deg: float, ox: float = 0.0, oy: float = 0.0) -> tuple[Fraction, Fraction]:
    """emccanon rotate_and_offset_pos, written out independently: rotate by deg, then add the offset."""
    t = deg * math.pi / 180.0
    return F(x * math.cos(t) - y * math.sin(t) + ox), F(x * math.sin(t) + y * math.cos(t) + oy)


def test_rotated_point_is_the_double_linuxcnc_computes():
    segs = segments_text("G10 L2 P1 X10 Y5 R30\nG54 G0 X3 Y4 Z2\n", MILL)
    assert [s.end for s in segs] == [(*_rot(3.0, 4.0, 30.0, 10.0, 5.0), F(2))]
    # an isometry: 5 from the origin of the rotated system, to rounding
    x, y, _ = segs[0].end
    assert abs((x - 10) ** 2 + (y - 5) ** 2 - 25) < F(1, 10**12)


def test_incremental_moves_and_z_moves_in_rotated_system():
    segs = segments_text("G10 L2 P1 R90\nG0 X0 Y0\nG91 G1 F100 X1\nX1\nZ-1\nY2\n", MILL)
    ends = [s.end for s in segs]
    assert ends[1] == (*_rot(1.0, 0.0, 90.0), F(0))
    assert ends[2] == (*_rot(2.0, 0.0, 90.0), F(0))
    assert ends[3] == (*_rot(2.0, 0.0, 90.0), F(-1))  # a Z move keeps XY
    assert ends[4] == (*_rot(2.0, 2.0, 90.0), F(-1))
    assert abs(ends[4][0] + 2) < F(1, 10**15) and abs(ends[4][1] - 2) < F(1, 10**15)


def test_inch_and_g92_are_applied_before_the_rotation():
    segs = segments_text("G20 G10 L2 P1 X1 R45\nG92 X0 Y0\nG0 X1 Y0\n", MILL)
    # at machine 0: pre-rotation position = rotate(-45)(-25.4, 0); G92 makes it program 0
    t = math.pi / 4
    ux, uy = -25.4 * math.cos(t), 25.4 * math.sin(t)
    assert segs[0].end[:2] == _rot(float(F(ux) + F(254, 10)), float(F(uy)), 45.0, 25.4, 0.0)


def test_rotated_arc_centre_is_rotated_and_ends_stay_on_the_circle():
    text = "G10 L2 P1 X100 R37.5\nG0 X10 Y0\nG3 X0 Y10 I-10 J0 F100\nG2 X10 Y0 R10\n"
    segs = segments_text(text, MILL)
    arc = segs[1]
    assert arc.kind is SegmentKind.ARC and not arc.clockwise
    assert arc.centre == _rot(0.0, 0.0, 37.5, 100.0, 0.0)
    assert arc.end[:2] == _rot(0.0, 10.0, 37.5, 100.0, 0.0)
    cx, cy = arc.centre
    for px, py in (arc.start[:2], arc.end[:2]):
        assert abs((px - cx) ** 2 + (py - cy) ** 2 - 100) < F(1, 10**10)
    rarc = segs[2]
    assert rarc.kind is SegmentKind.ARC and rarc.clockwise and rarc.radius == 10 and rarc.centre is None


def test_r0_restores_exact_decimals_and_g53_round_trips():
    segs = segments_text("G10 L2 P1 R45\nG0 X1.1 Y2.2\nG53 G0 X1 Y1\nG10 L2 P1 R0\nG0 X1.1 Y2.2\n", MILL)
    assert segs[-1].end[:2] == (F("1.1"), F("2.2"))
    assert abs(segs[1].end[0] - 1) < F(1, 10**15) and abs(segs[1].end[1] - 1) < F(1, 10**15)


def test_g10_l20_in_rotated_system_sets_both_offsets():
    # LinuxCNC tests/interp/g10/g10-l20-while-active: at machine 0, X reads -1 => G5X = (0.7071, 0.7071)
    segs = segments_text("G10 L2 P1 R45\nG53 G0 X0 Y0\nG10 L20 P1 X-1\nG1 F60 X0\n", MILL)
    x, y, _ = segs[-1].end
    assert abs(x - F(math.sqrt(0.5))) < F(1, 10**12) and abs(y - F(math.sqrt(0.5))) < F(1, 10**12)


def test_rotation_stops_the_fast_path_and_both_paths_agree():
    body = "".join(f"G1 X{k % 7}.25 Y{k % 5}.5 F500\n" for k in range(100))
    text = "G10 L2 P1 X3 Y4 R12.5\n" + body + "G10 L2 P1 R0\n" + body
    fast = interpret_text(text, MILL, fast=True)
    full = interpret_text(text, MILL, fast=False)
    a, b = list(fast.segments()), list(full.segments())
    assert [s.end for s in a] == [s.end for s in b] and len(a) == 200
    assert a[0].end[:2] == _rot(0.25, 0.5, 12.5, 3.0, 4.0)
    assert a[150].end[:2] == (F("1.25") + 3, F("0.5") + 4)  # k = 50 after R0: exact decimals again
    assert 64 <= fast.fast_lines <= 101  # only the unrotated run went fast


def test_what_is_not_modelled_under_rotation_is_unknown():
    for text, code in (("G10 L2 P1 R30\nG18 G2 X1 Z1 I1 F100\n", "G18 arc"),
                       ("G10 L2 P1 R30\nG0 Z5\nG81 X1 Y1 Z-1 R1 F100\n", "G81"),
                       ("G0 X1\nG92 X0\nG10 L2 P1 R30\n", "G10 L2 R")):
        run = interpret_text(text, MILL)
        list(run.segments())
        assert run.status == "unknown" and run.unsupported[0].code == code, (text, run.unsupported)


def test_program_position_parameters_read_unrotated_values():
    # LinuxCNC tests/interp/g10/g10-l2-while-active: after G10 L2 P1 X2 Y1 R90 the position reads 0 0
    text = ("G10 L2 P1 R-45 X1\nG1 F60 X0 Y[SQRT[2]]\nG10 L2 P1 X2 Y1 R90\n"
            "G1 X[#5420 + 1] Y[#5421 + 3]\n")
    segs = segments_text(text, MILL)
    x, y, _ = segs[-1].end
    # program (1, 3) in the system rotated 90 deg at (2, 1): machine (2 - 3, 1 + 1)
    assert abs(x + 1) < F(1, 10**12) and abs(y - 2) < F(1, 10**12)
