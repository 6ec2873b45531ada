"""Fanuc positions and offsets: incremental moves across a tool length change, a bare H, G92 in G91,
lathe G50 during a tool offset, canned cycle R/Z across G90/G91 — each derived from the manual beside it.

Sources (specs/fanuc.md, specs/turning.md "Sources"):

* [0i] FANUC Series 0i-MODEL D Operator's Manual B-64304EN, "Tool length compensation": the example
  "Tool length compensation (in boring holes #1, #2, and #3)" with H01 = -4.0 (below, block for block), and
  parameter 5006#6 TOS = 0 (compensation by moving the axis);
  "Setting a workpiece coordinate system" (G92): "If IP_ is an incremental command value, the workpiece
  coordinate system is defined so that the current tool position coincides with the result of adding the
  specified incremental value to the coordinates of the previous tool position";
* [0i-T] the same manual for lathes, "Coordinate system setting" (G50): "If a coordinate system is set using
  G50 during offset, a coordinate system in which the position before offset matches the position specified
  in G50 is set".
"""

from __future__ import annotations

from fractions import Fraction as Q

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.gcode.turning.helpers import lathe, moves
from tests.machines import machine_text

from .helpers import ends, mill

# ----------------------------------------------------------------------------------------------- the mill

#: A mill with no work offset (machine = program + tool length on Z), H1 = -4.0 as in the manual's example,
#: H2 = 100 and H3 = 150.5 (positive lengths), and a vise jaw under the manual's second hole (X150 Y30): its
#: top at machine Z -75.
JAW_MILL = machine_text("fanuc_0imd_jaw_mill")

#: [0i] "Tool length compensation", Example (boring holes #1, #2, #3), H01 = -4.0, transcribed from the
#: manual (no copy of it is stored with the project: the issue quotes N2 as ``G91 G00 G43 Z-32.0 H01``, here
#: G91 G00 are modal from N1, and N12 as ``G00 Z57.0 H00``; the Z moves below sum to 0 as the issue says).
MANUAL_EXAMPLE = """\
O0001
N1 G91 G00 X120.0 Y80.0
N2 G43 Z-32.0 H01
N3 G01 Z-21.0 F1000
N4 G04 P2000
N5 G00 Z21.0
N6 X30.0 Y-50.0
N7 G01 Z-41.0
N8 G00 Z41.0
N9 X50.0 Y30.0
N10 G01 Z-25.0
N11 G04 P2000
N12 G00 Z57.0 H00
N13 X-200.0 Y-60.0
N14 M2
"""

#: The Z move of each block of the example, from the manual's figure: N2 is the increment plus the new
#: offset minus the old, -32 + (-4 - 0) = -36; N12 cancels with H00 in G43 mode (a bare H, no G43 in the
#: block), 57 + (0 - (-4)) = +61; the others are their increments.  They sum to 0: the tool is back where it
#: started.
MANUAL_Z_MOVES = [-36, -21, 21, -41, 41, -25, 61]


def jaw_mill():
    return parse_machine(JAW_MILL, "jaw.toml")


def _segments(text, machine, **options):
    run = interpret_text(text, machine, file="t.nc", **options)
    segs = list(run.segments())
    assert not run.unsupported, run.unsupported
    return segs


def test_manual_tool_length_example_block_for_block():
    segs = [s for s in _segments(MANUAL_EXAMPLE, jaw_mill()) if s.kind.name != "DWELL"]
    z = [s.end[2] for s in segs]
    start = [Q(0)] + z[:-1]
    dz = [b - a for a, b in zip(start, z) if b != a]
    assert dz == MANUAL_Z_MOVES
    assert sum(dz) == 0 and z[-1] == 0
    # the hole bottoms in machine Z: #1 0 - 36 - 21 = -57, #2 -36 - 41 = -77, #3 -36 - 25 = -61
    bottoms = {(s.end[0], s.end[1]): s.end[2] for s in segs if s.kind.name == "LINE"}
    assert bottoms == {(120, 80): -57, (150, 30): -77, (200, 60): -61}


#: The same motion written in G90 (program Z = machine Z - (-4) while H01 is active): the reference the G91
#: program must agree with.
MANUAL_EXAMPLE_G90 = """\
N1 G90 G00 X120.0 Y80.0
N2 G43 Z-32.0 H01
N3 G01 Z-53.0 F1000
N5 G00 Z-32.0
N6 X150.0 Y30.0
N7 G01 Z-73.0
N8 G00 Z-32.0
N9 X200.0 Y60.0
N10 G01 Z-57.0
N12 G00 Z0 H00
N13 X0 Y0
N14 M2
"""


def test_the_jaw_under_the_second_hole_is_entered_in_g91_as_in_g90():
    # hole #2 goes to machine Z -77, 2 mm into the jaw whose top is at -75 (nczones read N2 as -32, the
    # bottom as -73, 2 mm above the jaw, and proved the program safe)
    m = jaw_mill()
    for text in (MANUAL_EXAMPLE, MANUAL_EXAMPLE_G90):
        r = verify_text(text, m)
        assert r.verdict.label == "unsafe", text
        assert r.violations[0].zone == "vise jaw"
    g91 = [s.end for s in _segments(MANUAL_EXAMPLE, m) if s.kind.name != "DWELL"]
    g90 = [s.end for s in _segments(MANUAL_EXAMPLE_G90, m)]
    assert g91 == g90


def test_the_jaw_example_past_512_motions_and_with_variables():
    # the vectorized tier (> 512 motions, the fast path taking the plain G91 lines) and the language layer
    # (a variable in the text) reach the same wrong-then-right point
    m = jaw_mill()
    tail = "".join("X1.\nX-1.\n" for _ in range(300))
    long = MANUAL_EXAMPLE.replace("N14 M2\n", tail + "M2\n")
    r = verify_text(long, m)
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "vise jaw"
    assert r.profile["motions_screened_vectorized"] > 512
    run = interpret_text(long, m)
    assert sum(len(c) for c in run) == 613 and run.counts["fast_lines"] >= 600
    macro = MANUAL_EXAMPLE.replace("N2 G43 Z-32.0 H01", "#1 = -32.0\nN2 G43 Z#1 H01")
    r = verify_text(macro, m)
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "vise jaw"
    # and with the jaw 3 mm lower (top at -78) the real bottom -77 clears it: safe, not a blanket unsafe
    lower = parse_machine(JAW_MILL.replace('Z = "-75"', 'Z = "-78"'), "jaw.toml")
    assert verify_text(long, lower).verdict.label == "safe"


def test_the_fast_path_leaves_tool_length_blocks_to_the_interpreter():
    # runs of plain G91 lines between tool length changes (G43 H2, a bare H3, G49 with a Z word): the fast
    # path and the full interpreter give the same segments, and the last point is the rule's:
    # +100 (G43 H2), +50.5 (H3), then G91 G49 Z-1. moves -1 - 150.5: Z ends at -1
    run = "".join("X1.\nX-1.\n" for _ in range(300))
    text = "G91 G00\nG43 H2\n" + run + "H3\n" + run + "G49 Z-1.\n" + run + "M30\n"
    m = jaw_mill()
    fast = interpret_text(text, m, fast=True)
    fsegs = [(s.kind, s.start, s.end) for s in fast.segments()]
    full = [(s.kind, s.start, s.end) for s in interpret_text(text, m, fast=False).segments()]
    assert fsegs == full and fast.counts["fast_lines"] >= 600
    assert fsegs[-1][2] == (0, 0, -1)


def test_g44_and_g49_with_an_incremental_tool_axis_word():
    m = jaw_mill()
    # G91 G44 Z-32. H2 from Z0: -32 + (-100 - 0) = -132 (nczones moved -32: a whole tool length short)
    assert ends("G91 G00 G44 Z-32. H2\n", m) == [(0, 0, -132)]
    # G43 H2 alone moves +100 (TOS = 0); G91 G49 Z-10.: -10 + (0 - 100) = -110, ending at Z -10
    assert ends("G43 H2\nG91 G00 G49 Z-10.\n", m) == [(0, 0, 100), (0, 0, -10)]
    # G91 G01 G43 Z5. H3 after G43 H2 (at 100): 5 + (150.5 - 100) = 55.5, ending at 155.5
    assert ends("G43 H2\nG91 G01 G43 Z5. H3 F100.\n", m) == [(0, 0, 100), (0, 0, Q("155.5"))]
    # in G90 the tool axis word names the position with the new length: G90 G43 Z-32. H2 -> -32 + 100
    assert ends("G90 G00 G43 Z-32. H2\n", m) == [(0, 0, 68)]


def test_g43_without_a_tool_axis_word_moves_the_tool_axis_by_the_change():
    # TOS = 0 ([0i] "Tool length compensation": compensation by moving the axis): G43 H2 with only an X word
    # moves Z by +100 in the same block, in G90 and in G91 alike; G49 alone moves back by -100
    m = jaw_mill()
    assert ends("G91 G00 G43 H2 X10.\nG49\n", m) == [(10, 0, 100), (10, 0, 0)]
    assert ends("G90 G00 G43 H2 X10.\nG49\n", m) == [(10, 0, 100), (10, 0, 0)]


def test_a_bare_h_switches_the_offset_in_g43_and_g44_mode():
    m = jaw_mill()
    # G43 mode: H3 alone switches 100 -> 150.5 (a move of +50.5); H0 cancels the length (the manual's N12)
    assert ends("G43 H2\nH3\nH0\n", m) == [(0, 0, 100), (0, 0, Q("150.5")), (0, 0, 0)]
    # G44 mode: the lengths are subtracted: -100, then -150.5
    assert ends("G44 H2\nH3\n", m) == [(0, 0, -100), (0, 0, Q("-150.5"))]
    # G49 mode: an H word alone changes nothing (no tool length compensation is active)
    assert ends("G49 H2\nH3\nG0 Z1.\n", m) == [(0, 0, 1)]
    # with an absolute tool axis word in the block: the word names the position with the new length
    assert ends("G90 G43 H2\nG0 Z5. H3\n", m) == [(0, 0, 100), (0, 0, Q("155.5"))]


def test_a_bare_h_reaches_a_zone_nczones_missed():
    # G43 H2 at Z0 (machine 100), then H3: the real spindle goes to 150.5, into a guard above 120
    text = "G90 G00 G43 Z0 H2\nX10.\nH3\nX20.\n"
    guard = JAW_MILL + '[[zones]]\nname = "guard"\nkind = "box"\nforbid = true\nmin = { X = "5", Y = "-5", ' \
        'Z = "120" }\nmax = { X = "15", Y = "5", Z = "200" }\n'
    r = verify_text(text, parse_machine(guard, "guard.toml"))
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "guard"


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["G43", "G44", "G49", ""]), st.sampled_from(["H0", "H1", "H2", "H3", ""]),
                          st.integers(-50, 50)), min_size=1, max_size=6))
def test_incremental_and_absolute_twins_reach_the_same_points(steps):
    # metamorphic: the rule "machine Z = program Z + active length" makes a G91 program and its G90 twin
    # (each tool axis word the running program Z) end every block at the same machine point
    lengths = {0: Q(0), 1: Q("-4"), 2: Q(100), 3: Q("150.5")}
    mode, reg = "G49", None
    prog_z = Q(0)
    g91, g90 = ["G91 G00"], ["G90 G00"]
    for code, h, dz in steps:
        if code:
            mode = code
        if mode == "G49":
            h = ""
        if code in ("G43", "G44") and reg is None and not h:
            h = "H0"
        if h:
            reg = int(h[1:])
        if code == "G49":
            reg = None
        prog_z += dz
        g91.append(f"{code} Z{dz}. {h}")
        g90.append(f"{code} Z{prog_z}. {h}")
    m = jaw_mill()
    a = ends("\n".join(g91) + "\n", m)
    b = ends("\n".join(g90) + "\n", m)
    assert a == b
    sign = {"G43": 1, "G44": -1, "G49": 0}[mode]
    assert a[-1][2] == prog_z + (sign * lengths[reg] if reg is not None else 0)


# ------------------------------------------------------------------------------------------------ G92 in G91


def test_g92_in_g91_adds_the_increment_to_the_current_reading():
    # G54 X = 100 (tests/gcode/fanuc/helpers.py).  G90 G54 X1.: machine 101, reading 1.  G91 G92 X5.: the reading
    # becomes 1 + 5 = 6 at machine 101, so the G92 shift is -5 and G90 X0 goes to 0 + 100 - 5 = 95.
    # (Read as absolute, the reading would be 5: shift -4, X0 at 96.)
    assert ends("G90 G54 G0 X1.\nG91 G92 X5.\nG90 X0\n") == [(101, 0, 0), (95, 0, 0)]
    # G92 in G90 afterwards sets the reading absolutely again: at 95 (reading 0) G90 G92 X10. -> shift
    # 95 - 100 - 10 = -15, X0 at 85
    assert ends("G90 G54 G0 X1.\nG91 G92 X5.\nG90 X0\nG92 X10.\nX0\n")[-1] == (85, 0, 0)
    # on the tool axis with a tool length active the same rule holds: Z reads its reading plus the increment
    # (G54 Z -200, EXT Z 1, H1 100: G43 Z0 H1 -> machine -99, reading 0; G91 G92 Z2. -> reading 2;
    # G90 Z0 -> -101)
    assert ends("G90 G54 G0 G43 Z0 H1\nG91 G92 Z2.\nG90 Z0\n") == [(0, 0, -99), (0, 0, -101)]


def test_g92_in_g91_reaches_a_zone_nczones_missed():
    m = parse_machine(JAW_MILL.replace('[tool_lengths]', '[offsets]\nG54 = { X = "100" }\n[tool_lengths]')
                      + '[[zones]]\nname = "stop"\nkind = "box"\nforbid = true\nmin = { X = "90", Y = "10", '
                        'Z = "-5" }\nmax = { X = "95.5", Y = "20", Z = "5" }\n', "g92.toml")
    # the approach at Y0 passes below the stop; at Y15 the tool goes to X 95 (reading 0), inside it (read as
    # absolute, X 96: outside)
    r = verify_text("G90 G54 G0 X1.\nG91 G92 X5.\nG90 Y15.\nX0\n", m)
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "stop"


# ------------------------------------------------------------------------------------ lathe G50 with offset


def test_lathe_g50_during_a_tool_offset_sets_the_position_before_offset_on_both_axes():
    # The lathe stands at machine X200 Z200 (radius); tool offset 1 is X+80 (radius) Z+50, "shift" (T0101
    # does not move).  G50 X100. Z50.: the position before offset (the machine position less the work
    # shifts, without the tool offset) reads X100 (radius 50) and Z50, so the work shift is X 200 - 50 = 150,
    # Z 200 - 50 = 150, and with the tool offset X00 Z0 goes to X 20 + 150 + 80 = 250, Z 0 + 150 + 50 = 200.
    # (nczones read Z as the offset tip: shift 100, Z0 at 150; X was already by this rule.)
    m = lathe(offsets='1 = { X = "80", Z = "50" }')
    assert moves("T0101\nG50 X100. Z50.\nG00 X40. Z0\n", m) == [("", Q(200), Q(250))]
    # each axis alone, by the same rule
    assert moves("T0101\nG50 X100.\nG00 X40.\n", m) == [("", Q(200), Q(250))]
    assert moves("T0101\nG50 Z50.\nG00 Z0\n", m) == [("", Q(200), Q(200))]
    # without an offset the rule is the old one: X 20 + 150 = 170, Z 0 + 150 = 150
    assert moves("G50 X100. Z50.\nG00 X40. Z0\n", m) == [("", Q(150), Q(170))]


def test_lathe_g50_u_w_shift_the_reading_by_the_increment():
    # after G50 X100. Z50. (as above, work shift X150 Z150 + offset), G50 U10. W-5.: the readings become
    # X110 (radius +5) and Z45, so the shifts fall by 5 (X) and -5 (Z): X40. Z0 -> X 20 + 145 + 80 = 245,
    # Z 0 + 155 + 50 = 205
    m = lathe(offsets='1 = { X = "80", Z = "50" }')
    assert moves("T0101\nG50 X100. Z50.\nG50 U10. W-5.\nG00 X40. Z0\n", m) == [("", Q(205), Q(245))]
    # system B: G92 in G91 (U and W do not exist), the same rule
    mb = lathe(offsets='1 = { X = "80", Z = "50" }', fanuc='gcode_system = "B"')
    assert moves("T0101\nG90 G92 X100. Z50.\nG91 G92 X10. Z-5.\nG90 G00 X40. Z0\n", mb) == [
        ("", Q(205), Q(245))]


def test_lathe_g50_during_offset_reaches_a_zone_nczones_missed():
    zones = ('[[zones]]\nname = "steady"\nkind = "box"\nforbid = true\nmin = { X = "240", Z = "195" }\n'
             'max = { X = "260", Z = "205" }\n')
    m = lathe(offsets='1 = { X = "80", Z = "50" }', zones=zones)
    r = verify_text("T0101\nG50 X100. Z50.\nG00 X40. Z0\n", m)
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "steady"


# ------------------------------------------------------------------------- canned cycle R/Z across G90/G91


def test_canned_cycle_r_z_kept_across_a_distance_mode_change_is_unknown():
    # R and Z given in G90, the next hole in G91 without them: the manual does not say whether the stored
    # numbers are read again as increments or keep the levels they named
    run = interpret_text("G90 G54 G0 X0 Y0 Z10.\nG99 G81 X1. R2. Z-5. F100.\nG91 X1.\nG80\n", mill(), file="t.nc")
    list(run.segments())
    assert run.unsupported and run.unsupported[0].code == "G81"
    assert "G90" in run.unsupported[0].reason and "G91" in run.unsupported[0].reason
    # given again after the change: modelled (R from the initial level, Z from R)
    run = interpret_text("G90 G54 G0 X0 Y0 Z10.\nG99 G81 X1. R2. Z-5. F100.\nG91 X1. R-8. Z-7.\nG80\n", mill(),
                         file="t.nc")
    list(run.segments())
    assert not run.unsupported


# ------------------------------------------------------------------- what the manuals leave open: unknown


def _unknown(text, machine):
    run = interpret_text(text, machine, file="t.nc")
    list(run.segments())
    return run.unsupported[0] if run.unsupported else None


def test_shift_type_length_change_then_an_incremental_tool_axis_move_is_unknown():
    # tool_length_motion = "shift" (TOS = 1): the next tool axis move takes the change; whether an
    # incremental one carries it (as the TOS = 0 example does) is not stated: unknown, in every lane
    m = parse_machine(JAW_MILL + '[fanuc]\ntool_length_motion = "shift"\n', "shift.toml")
    u = _unknown("G90 G43 H2\nG91 G00 Z-10.\n", m)
    assert u is not None and u.code == "G43" and "shift" in u.reason
    assert _unknown("G91 G00 G44 Z-10. H2\n", m).code == "G44"
    # past 512 lines (the fast path and the plain-move lane must not take the G91 Z lines either)
    run = "".join("Z1.\nZ-1.\n" for _ in range(300))
    assert _unknown("G90 G43 H2\nG91 G00\n" + run, m) is not None
    # an absolute tool axis move takes it (5 + 100 = 105); incremental moves after that are increments
    assert ends("G90 G43 H2\nG00 Z5.\nG91 Z-10.\n", m) == [(0, 0, 105), (0, 0, 95)]
    # a G90 block without a tool axis word does not take it
    assert _unknown("G90 G43 H2\nX5.\nG91 Z-1.\n", m) is not None
    # X/Y moves in G91 do not touch it
    assert ends("G90 G43 H2\nG91 X5.\nG90 Z0\n", m) == [(5, 0, 0), (5, 0, 100)]


def test_mill_g92_on_the_tool_axis_with_a_tool_length_is_unknown():
    # the lathe's G50 sets the position before offset; the mill's reading (nczones: the tool tip) is not
    # confirmed by a manual sentence, and the two differ by the tool length
    m = jaw_mill()
    u = _unknown("G90 G43 H2 Z0\nG92 Z10.\nG0 Z0\n", m)
    assert u is not None and u.code == "G92" and "tool length" in u.reason
    # without a length, on the other axes, or incremental (both readings add the increment): modelled
    assert _unknown("G90 G49 Z0\nG92 Z10.\nG43 H2 X1. Y1.\nG92 X0 Y0\nG91 G92 Z1.\n", m) is None


# --------------------------------------------------------------------------------------- a real program

STROKE = "serial-number-macro/work/cambam stick 2/numbers_0.nc"


def test_a_cam_stroke_written_in_g91_engraves_at_the_tool_length_plane():
    # A CamBam post's engraving stroke (corpus, GPL-3.0), run entirely in G91 and inch:
    #   G91 G0 X0.1392 Y-0.4606 / G43 Z0.25 H1 / G1 Z-0.254 F5. / arcs / G0 Z0.254 / G28 G91 Z0.0
    # With H1 = -12 in (-304.8 mm: the tool tip 12 in below the spindle's home reading) the G43 block moves
    # 0.25 in + (-12 in - 0) = -11.75 in (-298.45 mm), the plunge ends 0.254 in lower at -304.9016 mm: 0.004 in
    # (0.1016 mm) below the H1 plane, the engraving depth the program means.  (Read without the change, the
    # stroke was engraved 0.25 in above the spindle's start, in the air.)
    import pytest

    from tests.corpus import CORPUS

    path = CORPUS / STROKE
    if not path.is_file():
        pytest.skip("corpus not available")
    m = parse_machine(JAW_MILL.replace('H1 = "-4.0"', 'H1 = "-304.8"').split("[[zones]]")[0], "inch.toml")
    # (some arc end points are off their circles by more than the default 0.002 mm: the post rounds to 0.0001 in)
    segs = _segments(path.read_text(encoding="utf-8"), m, arc_tolerance="0.005")
    z = [s.end[2] for s in segs]
    assert min(z) == Q("-304.9016")
    assert Q("-298.45") in z and z[-1] == 0  # the approach level, and home at the end (G28 Z)
    cut = [s for s in segs if s.kind.name == "ARC"]
    assert cut and all(s.end[2] == Q("-304.9016") for s in cut)


def test_a_reference_return_in_the_block_of_a_tool_length_change_in_g91_is_unknown():
    # G91 G28 Z0 G49 with G43 H2 active: the G00 rule would put the intermediate point 100 mm lower; whether
    # a reference return's intermediate point carries the change is not stated: unknown
    m = jaw_mill()
    u = _unknown("G90 G43 H2 Z0\nG91 G28 Z0 G49\n", m)
    assert u is not None and u.code == "G28"
    # in separate blocks the return is modelled as before: G28 Z0 in G91, the intermediate point where the
    # tool stands (100), then the reference (0)
    assert ends("G90 G43 H2 Z0\nG91 G28 Z0\nG49\n", m)[:3] == [(0, 0, 100), (0, 0, 100), (0, 0, 0)]
