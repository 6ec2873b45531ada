"""Golden machine positions of the Fanuc dialect, each derived by hand beside it.

The test mill (tests/gcode/fanuc/helpers.py): G54 = (100, 50, -200), G55 = (300, 50, -200), EXT = (0, 0, 1),
G54.1 P3 = (500, 20, -210), H1 = 100, H2 = 150.5, the 2nd reference position (-100, -50, -10), the start
at (0, 0, 0).  machine = program + EXT + G5x + G52 + G92 + tool length (Z).
"""

from __future__ import annotations

from fractions import Fraction as Q

import pytest

from nczones.gcode import interpret_text
from nczones.motion import SegmentKind

from .helpers import ends, mill


def test_tool_length_change_moves_the_tool_axis():
    # G43 H1 alone: Z moves by +100 at once (parameter 5006#6 TOS = 0): 0 -> 100.
    # G43 H2 with an X move: one move, X 10 + 100 (G54) = 110, Z 0 + 150.5 = 150.5.
    # G49 alone: Z back by -150.5 to 0.
    assert ends("G43 H1\nG90 G54 G43 H2 X10.\nG49\n") == [(0, 0, 100), (110, 0, Q("150.5")), (110, 0, 0)]


def test_tool_length_shift_setting_moves_with_the_next_z_move():
    m = mill('tool_length_motion = "shift"')
    # no move at G43 H1; the next Z move goes to 5 - 200 + 1 + 100 = -94
    assert ends("G90 G54 G43 H1\nG0 Z5.\n", m) == [(0, 0, -94)]


def test_work_systems_ext_g54_1_g52_g92():
    # G54 X1: 1 + 100 = 101; Z2: 2 - 200 + 1 (EXT) = -197.
    # G54.1 P3 X1: 1 + 500 = 501.  G52 X10 in G54: X1 -> 1 + 10 + 100 = 111.  G52 X0 cancels: 101.
    # G92 X0 at machine X 101 (program 1) makes that point X0: the shift is +1, G0 X5 -> 5 + 100 + 1 = 106.
    assert ends("G90 G54 G0 X1. Z2.\nG54.1 P3 X1.\nG54 G52 X10.\nX1.\nG52 X0\nX1.\nG92 X0\nX5.\n") == [
        (101, 0, -197), (501, 0, -197), (111, 0, -197), (101, 0, -197), (106, 0, -197)]


def test_g10_data_setting():
    # G10 L2 P1 X20: G54 X becomes 20 -> X1 is 21.  G91 G10 L2 P1 X5: G54 X 25 -> G90 X1 is 26.
    # G10 L2 P0 Z3: EXT Z 3 -> Z0 is 0 - 200 + 3 = -197.  G10 L20 P3 X7: G54.1 P3 X 7 -> X1 is 8.
    # G10 L10 P1 R50 (H1 geometry) and L11 P1 R0.5 (H1 wear): G43 H1 Z0 -> -197 + 50.5 = -146.5.
    assert ends("G90 G10 L2 P1 X20.\nG54 G0 X1.\nG91 G10 L2 P1 X5.\nG90 X1.\nG10 L2 P0 Z3.\nZ0\n"
                "G10 L20 P3 X7.\nG54.1 P3 X1.\nG54 G10 L10 P1 R50.\nG10 L11 P1 R0.5\nG43 H1 Z0\n") == [
        (21, 0, 0), (26, 0, 0), (26, 0, -197), (8, 0, -197), (8, 0, Q("-146.5"))]


def test_offset_variables_are_read_and_written():
    # #5221 (G54 X) reads 100; #5241 (G55 X) = 300; X[#5221 / 10] in G54 -> 10 + 100 = 110.
    # #5221 = 0 moves the G54 zero: X0 -> 0.  #5003 (block end Z, work system, no offsets) after Z5 reads 5.
    # #7041 (G54.1 P3 X) = 500; #2201 (H1 geometry, memory C) = 100.
    assert ends("G90 G54 G0 X[#5221 / 10]\n#5221 = 0\nX0\nZ5.\nX#5003\n#1 = #7041 + #2201\nG0 X[#1 / 100]\n") == [
        (110, 0, 0), (0, 0, 0), (0, 0, -194), (5, 0, -194), (6, 0, -194)]


def test_reference_returns_move_only_the_named_axes():
    # G91 G28 Z0: intermediate = here, then Z to 0 (reference).  G90 G30 P2 X1.: to X 1 + 100 = 101, then
    # X to the 2nd reference X -100; Y and Z stay.  G53 Z-5.: a rapid to machine Z -5.
    run = interpret_text("G90 G54 G0 X5. Y5. Z5.\nG91 G28 Z0\nG90 G30 P2 X1.\nG53 Z-5.\n", mill())
    segs = list(run.segments())
    assert [tuple(s.end) for s in segs] == [(105, 55, -194), (105, 55, -194), (105, 55, 0), (101, 55, 0),
                                            (-100, 55, 0), (-100, 55, -5)]
    assert all(s.kind is SegmentKind.RAPID for s in segs)


def test_drilling_cycles():
    # G81 G98 at X10 Y10 in G54: R2 -> machine 2 - 199 = -197; Z-5 -> -204; the initial level is Z5 -> -194.
    # Position at -194, rapid to R, feed to -204, rapid back to the initial level (G98).
    # Second hole with G99 in G91: X+5, R is measured from the initial level... the tool returns to R.
    pts = ends("G90 G54 G0 X0 Y0 Z5.\nG81 G98 X10. Y10. Z-5. R2. F100.\nG99 X15.\nG80\n")
    assert pts[1:] == [(110, 60, -194), (110, 60, -197), (110, 60, -204), (110, 60, -194),
                       (115, 60, -194), (115, 60, -197), (115, 60, -204), (115, 60, -197)]


def test_incremental_cycle_with_repeats():
    # G91 G81 X10 R-3 Z-4 K3 from X0 Z5 (machine -194): R = -194 - 3 = -197, bottom -197 - 4 = -201;
    # three holes at X 110, 120, 130, back to R (G99) after each.
    pts = ends("G90 G54 G0 X0 Y0 Z5.\nG91 G99 G81 X10. R-3. Z-4. K3 F100.\n")
    holes = [pts[i] for i in range(1, len(pts)) if pts[i][2] == -201]
    assert [h[0] for h in holes] == [110, 120, 130]
    assert pts[-1] == (130, 50, -197)


def test_peck_cycles_with_the_machines_parameters():
    # G73 Q2 from R -197 to -202 with d = 0.5: feeds to -199, -201, -202, backing off 0.5 between.
    # G83 Q2 with d = 1: feed -199, out to R -197, down to -198, feed -201, out, down to -200, feed -202.
    pts = ends("G90 G54 G0 X0 Y0 Z2.\nG99 G73 X1. Z-3. R2. Q2. F100.\nG80\n")
    assert [p[2] for p in pts[1:]] == [-197, -199, Q("-198.5"), -201, Q("-200.5"), -202, -197]
    pts = ends("G90 G54 G0 X0 Y0 Z2.\nG99 G83 X1. Z-3. R2. Q2. F100.\nG80\n")
    assert [p[2] for p in pts[1:]] == [-197, -199, -197, -198, -201, -197, -200, -202, -197]


def test_fine_boring_shift():
    # G76 Q1 with the shift +X: feed to the bottom, dwell, shift X +1, rapid out, shift back.
    pts = ends("G90 G54 G0 X0 Y0 Z2.\nG99 G76 X1. Z-3. R2. Q1. P500 F100.\nG80\n")
    assert pts[1:] == [(101, 50, -197), (101, 50, -202), (101, 50, -202), (102, 50, -202), (102, 50, -197),
                       (101, 50, -197)]


def test_dwell_times():
    run = interpret_text("G04 P1500\nG04 X2.5\nG04 P0.5\n", mill())
    assert [s.dwell_s for s in run.segments()] == [Q("1.5"), Q("2.5"), Q("0.5")]


def test_canned_cycle_needs_its_parameters_or_is_unknown():
    run = interpret_text("G90 G54 G0 X0 Y0 Z2.\nG82 X1. Z-3. F100.\n", mill())
    list(run)
    assert run.status == "unknown" and run.unsupported[0].code == "G82"
    m = mill().__class__  # the machine without g73_retract: G73 is unknown with the parameter named
    from dataclasses import replace

    bare = replace(mill(), fanuc=replace(mill().fanuc, g73_retract=None))
    run = interpret_text("G90 G54 G0 X0 Y0 Z2.\nG73 X1. Z-3. R2. Q1. F100.\n", bare)
    list(run)
    assert run.unsupported[0].code == "G73" and "5114" in run.unsupported[0].reason
    del m


@pytest.mark.parametrize("code", ["G41 D1", "G42 D2", "G31 X1.", "G12.1", "G60 X1."])
def test_unmodelled_codes_are_unknown_with_a_reason(code):
    run = interpret_text(f"G0 X1.\n{code}\nG0 X2.\n", mill())
    segs = list(run.segments())
    assert run.status == "unknown" and run.unsupported[0].span.line == 2
    assert len(segs) == 1 and run.unsupported[0].reason


def test_two_one_shot_codes_in_a_block_is_an_error_of_one_group_the_last_wins():
    from nczones.errors import GcodeError

    with pytest.raises(GcodeError):
        list(interpret_text("G04 G28 X1.\n", mill()))
    assert ends("G90 G54 G0 G1 X1. F100.\n") == [(101, 0, 0)]
