"""The interpreter: exact machine coordinates, arcs, offsets, cycles, never silent."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret, interpret_text, segments_text
from nczones.machine import parse_machine
from nczones.motion import Plane, SegmentKind, SplineCurve
from tests.corpus import CORPUS
from tests.machines import machine_text

F = Fraction
BAD = CORPUS / "linuxcnc" / "tests" / "interp" / "bad"

MILL = parse_machine(machine_text("mill_g54_g55_h1_h2"))
XY = parse_machine(machine_text("xy_fast"))


def ends(text, machine=MILL, **kw):
    return [s.end for s in segments_text(text, machine, **kw)]


def test_ten_incremental_tenths_end_exactly():
    segs = segments_text("G91 G1 F100\n" + "Y0.1\n" * 10, MILL)
    assert segs[-1].end[1] == 300
    assert [s.kind for s in segs] == [SegmentKind.LINE] * 10


def test_work_offset_tool_length_and_inches():
    segs = segments_text("G20 G90 G54 G43 H1 G0 X1 Y2 Z0.5\nG55 G1 X0 F10\nG49 G0 Z0\n", MILL)
    assert segs[0].end == (F(100) + F("25.4"), F("50.8"), F(50) + F("12.7") + 120)
    assert segs[0].tool_length == 120 and segs[0].tool_register == 1
    assert segs[1].end[0] == 200
    assert segs[1].feed_mm_min == F("254")
    assert segs[2].end[2] == 60 and segs[2].tool_length == 0


def test_g53_and_g28_via_intermediate_point():
    segs = segments_text("G0 X10 Y10 Z10\nG53 G0 Z300\nG91 G28 Z0\n", MILL)
    assert segs[1].end == (110, 10, 300)
    assert segs[2].end == (110, 10, 300) and segs[2].derived == "G28 intermediate"
    assert segs[3].end == (110, 10, 400) and segs[3].derived == "G28 home"


def test_g92_and_g92_1():
    segs = segments_text("G0 X10\nG92 X0\nG0 X5\nG92.1\nG0 X5\n", MILL)
    assert [s.end[0] for s in segs] == [110, 115, 105]


def test_g10_l2_and_l20():
    segs = segments_text("G10 L2 P1 X5\nG0 X1\nG10 L20 P1 X0\nG0 X2\n", MILL)
    assert [s.end[0] for s in segs] == [6, 8]


def test_arc_directions_per_plane():
    s = segments_text("G0 X0 Y0 Z0\nG17 G2 X10 Y0 I5 F100\n", MILL)[1]
    assert s.plane is Plane.XY and s.clockwise and s.centre == (105, 0)
    with pytest.raises(GcodeError) as e:
        segments_text("G0 X0 Y0 Z0\nG18 G3 X10 Z0 I5\n", MILL)
    assert e.value.diagnostics[0].code == "GC305"  # no feed rate yet


def test_arc_plane_centre_order_g18():
    s = segments_text("G0 X0 Y0 Z0\nF10 G18 G3 X10 Z0 I5 K0\n", MILL)[1]
    # G18 centre is (Z, X) like LinuxCNC's ARC_FEED
    assert s.plane is Plane.XZ and not s.clockwise and s.centre == (F(50), F(105))


def test_r_format_arcs_and_full_circle_and_helix():
    s = segments_text("G0 X0 Y0 Z0\nF10 G2 X10 Y0 R-5\n", MILL)[1]
    assert s.centre == (105, 0)  # half circle: the chord midpoint, as LinuxCNC
    s = segments_text("G0 X0 Y0 Z0\nF10 G2 X10 Y0 R-7\n", MILL)[1]
    assert s.centre is None and s.radius == -7 and s.clockwise
    s = segments_text("G0 X0 Y0 Z0\nF10 G3 I5 Z-3 P2\n", MILL)[1]
    assert s.start[:2] == s.end[:2] and s.turns == 1 and s.is_helix()


def test_arc_off_circle_is_an_error_with_span():
    with pytest.raises(GcodeError) as e:
        segments_text("G0 X0 Y0\nF10 G2 X10 Y0 I5.01\n", XY)
    d = e.value.diagnostics[0]
    assert d.code == "GC301" and d.span.line == 2
    # within the tolerance: accepted, end point kept (LinuxCNC's spiral)
    s = segments_text("G0 X0 Y0\nF10 G2 X10 Y0 I5.001\n", XY)[1]
    assert s.end == (10, 0) and s.centre == (F("5.001"), 0)
    with pytest.raises(GcodeError):
        segments_text("G0 X0 Y0\nF10 G2 X10 Y0 I5.001\n", XY, arc_tolerance="0.0001")


def test_linuxcnc_arc_rule_accepts_what_linuxcnc_accepts():
    # radius 5 at the start, 5.01 at the end: 0.01 mm off, inside LinuxCNC's 0.028 mm
    program = "G0 X0 Y0\nF10 G2 X10 Y0 I5.01\n"
    s = segments_text(program, XY, arc_tolerance="linuxcnc")[1]
    assert s.kind is SegmentKind.ARC and s.end == (10, 0) and s.centre == (F("5.01"), 0)
    # 0.1 mm off a radius of 5 mm: above 0.028 mm and above 0.1 %: LinuxCNC refuses it too
    with pytest.raises(GcodeError) as e:
        segments_text("G0 X0 Y0\nF10 G2 X10 Y0 I5.1\n", XY, arc_tolerance="linuxcnc")
    assert e.value.diagnostics[0].code == "GC301"
    # 1 mm off a radius of 2000 mm: above 0.028 mm but within 0.1 %: accepted, as LinuxCNC does
    big = "G0 X0 Y0\nF10 G2 X4000 Y0 I2000.5\n"
    assert segments_text(big, XY, arc_tolerance="linuxcnc")[1].centre == (F("2000.5"), 0)
    with pytest.raises(GcodeError):
        segments_text(big, XY)


def test_axis_the_machine_lacks_is_an_error():
    with pytest.raises(GcodeError) as e:
        segments_text("G0 X1 Z5\n", XY)
    assert e.value.diagnostics[0].code == "GC203" and e.value.diagnostics[0].span.column == 7


def test_two_codes_of_one_modal_group():
    with pytest.raises(GcodeError) as e:
        segments_text("G0 G1 X1\n", XY)
    assert e.value.diagnostics[0].code == "GC201"


def test_unsupported_stops_emission_and_keeps_earlier_motion():
    run = interpret_text("G1 X1 F10\nG41 D1\nG1 X5\n", MILL)
    got = [s.end[0] for s in run.segments()]
    assert got == [101]
    assert run.status == "unknown" and run.unsupported[0].span.line == 2
    assert "compensation" in run.unsupported[0].reason


def test_assumed_modal_reported():
    run = interpret_text("G1 X1 F10\nG21\n", MILL)
    list(run)
    assert run.assumed_modal == {"units": "G21", "distance": "G90", "offset": "G54"}
    run = interpret_text("G21 G90 G54 G1 X1 F10\n", MILL)
    list(run)
    assert run.assumed_modal == {}


def test_canned_cycle_g81_g98_g99_and_repeats():
    segs = segments_text("G0 X0 Y0 Z10\nF100 G99 G91 G81 X5 Z-3 R-2 L3\n", MILL)
    feeds = [s for s in segs if s.kind is SegmentKind.LINE]
    assert [s.end[0] for s in feeds] == [105, 110, 115]
    assert all(s.end[2] == 50 + 5 for s in feeds)
    assert segs[-1].end[2] == 50 + 8


def test_g83_pecks():
    segs = segments_text("G0 X0 Y0 Z5\nF100 G98 G83 X1 Z-3 R1 Q1.5\n", MILL)
    feeds = [s.end[2] - 50 for s in segs if s.kind is SegmentKind.LINE]
    assert feeds == [F("-0.5"), F(-2), F(-3)]
    assert segs[-1].end[2] == 55


def test_dependencies_tracked():
    segs = segments_text("G0 X1\nG43 H1 Z5\nG91 G1 X1 F10\nG90 G53 G0 Z300\n", MILL, track_dependencies=True)
    assert segs[0].deps_end == (("G54",), ("start",), ("start",))
    assert segs[1].deps_end[2] == ("G54", "H1")
    assert segs[2].deps_end[0] == ("G54",)
    assert segs[3].deps_end[2] == ()


def test_missing_tool_register_is_an_error():
    with pytest.raises(GcodeError) as e:
        segments_text("G43 H7 G0 Z1\n", MILL)
    assert "H7" in e.value.diagnostics[0].message


def test_streaming_chunks_are_bounded():
    run = interpret_text("G91 G1 F10\n" + "X0.001\n" * 3000, MILL, chunk_size=500, fast=False)
    sizes = [len(c) for c in run]
    assert max(sizes) <= 500 and sum(sizes) == 3000


# --------------------------------------------------------------------------- property test

_dec = st.decimals(min_value=-500, max_value=500, places=3, allow_nan=False, allow_infinity=False)


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.lists(st.tuples(st.sampled_from(["G90", "G91"]), st.sampled_from(["G20", "G21"]),
                          st.sampled_from("XYZ"), _dec), min_size=1, max_size=25))
def test_decimal_moves_match_fraction_arithmetic(moves):
    lines = []
    pos = [F(0), F(299), F(400)]  # machine start = reference
    off = [F(100), F(0), F(50)]
    expected = []
    for dist, units, axis, value in moves:
        text = format(value, "f")
        lines.append(f"{dist} {units} G1 {axis}{text} F100")
        v = F(text) * (F("25.4") if units == "G20" else 1)
        i = "XYZ".index(axis)
        pos[i] = v + off[i] if dist == "G90" else pos[i] + v
        expected.append(tuple(pos))
    got = ends("\n".join(lines) + "\n")
    assert got == expected


# --------------------------------------------------------------------------- LinuxCNC bad programs

#: bad/ programs that end ``unknown`` instead of being rejected, with the reason.
BAD_UNKNOWN: dict[str, str] = {}  # ccomp-gouging.ngc is rejected since cutter comp is modelled (GC324)


@pytest.mark.skipif(not BAD.is_dir(), reason="corpus not available")
@pytest.mark.parametrize("path", sorted(BAD.glob("*.ngc")) if BAD.is_dir() else [], ids=lambda p: p.name)
def test_linuxcnc_bad_programs_are_rejected(path):
    from tests.gcode.test_canon_linuxcnc import _machine

    run = interpret(path, _machine(None))
    if path.name in BAD_UNKNOWN:
        list(run)
        assert run.status == "unknown"
        return
    with pytest.raises(GcodeError) as e:
        list(run)
    d = e.value.diagnostics[0]
    assert d.span is not None and d.span.line >= 1


# ---------------------------------------------------------------- tool table writes, coverage fixes


def _z_ends(text: str) -> list[Fraction]:
    run = interpret_text(text, MILL)
    out = [s.end[2] for s in run.segments()]
    assert run.status == "complete", run.unsupported
    return out


def test_g10_l1_sets_the_tool_length_used_by_the_next_g43():
    # machine Z = program + G54 (50) + tool length; the table write takes effect at G43, not before
    assert _z_ends("G21 G90 G54\nG43 H1 G0 Z0\nG10 L1 P1 Z7.5\nG0 Z1\nG43 H1\nG0 Z0\n") == [F(170), F(171), F(115, 2)]


def test_g10_l10_l11_make_the_current_position_read_the_value():
    # L10: length = machine - G5x - G92 - value; L11 uses G59.3 (zero here) and no G92:
    # at machine Z60 it gives 60, so G54 Z0 is then 0 + 50 + 60
    z = _z_ends("G21 G90 G54\nG0 Z10\nG10 L10 P2 Z1.5\nG43 H2\nG0 Z1.5\nG10 L11 P3 Z0\nG43 H3\nG0 Z0\n")
    assert z == [F(60), F(60), F(110)]


def test_g10_l1_offset_on_a_non_tool_axis_is_unknown():
    run = interpret_text("G21\nG10 L1 P1 X0.5\nG0 X1\n", MILL)
    assert list(run.segments()) == [] and run.unsupported[0].code == "G10 L1"
    assert interpret_text("G21\nG10 L1 P1 X0 Z2 R3\nG0 X1\n", MILL).status == "complete"  # zero X offset, radius R


def test_m19_takes_an_r_word_and_g4_with_an_explicit_motion_code_moves():
    assert interpret_text("M19 R45 Q2\nG0 X1\n", MILL).status == "complete"
    segs = segments_text("G21 G90\nG4 P0.5 G0 X1 Y2\n", MILL)
    assert [s.kind for s in segs] == [SegmentKind.DWELL, SegmentKind.RAPID] and segs[1].end[:2] == (F(101), F(2))


@pytest.mark.parametrize("code", ["G71.2 Q1 P2 D0.5", "G72.1 Q1 P2 D0.5"])
def test_linuxcnc_lathe_cycle_without_its_profile_is_an_error(code):
    """LinuxCNC's G71/G72 read their profile from o<Q>: a subroutine the file does not define is an error, as
    LinuxCNC's call of it is (the cycles themselves: tests/gcode/turning/test_linuxcnc_g7x.py)."""
    with pytest.raises(GcodeError) as e:
        list(interpret_text(f"G21\nG0 X1\n{code}\nX2 Y3 R1 K0\n", MILL).segments())
    assert e.value.diagnostics[0].code == "GC313" and e.value.diagnostics[0].span.line == 3


def test_incomplete_g6_2_curve_is_unknown_and_a_complete_one_is_a_spline():
    run = interpret_text("G21 F100\nG0 X1\nG6.2 X1 Y2 R1 K0 P4 Q1\nX2 Y3 R1 K0\n", MILL)
    assert len(list(run.segments())) == 1
    assert run.status == "unknown" and "never completed" in run.unsupported[0].reason
    text = ("G21 G90 F100\nG0 X1 Y2\nG6.2 X1 Y2 R1 K0 P3 Q1\nX2 Y3 R1 K0\nX3 Y2 R2 K0\nX4 Y4 R1 K1\n"
            "G6.2 K2\nG6.2 K2\nG6.2 K2\nG1 X0\n")
    segs = segments_text(text, MILL)
    assert [s.kind for s in segs] == [SegmentKind.RAPID, SegmentKind.SPLINE, SegmentKind.LINE]
    e = segs[1].payload(SplineCurve)
    assert e is not None and e.source == "G6.2"
    assert e.degree == 2 and e.knots == (0, 0, 0, 1, 2, 2, 2) and e.weights == (1, 1, 2, 1)
    assert segs[1].end == segs[2].start and segs[1].end[:2] == (F(104), F(4))


@pytest.mark.parametrize("kind", ["small", "medium", "big"])
@pytest.mark.parametrize("units", ["metric", "imperial"])
def test_linuxcnc_arc_rule_matches_linuxcncs_own_arc_tolerance_tests(kind, units):
    """LinuxCNC's interp tests: good-arc.* must run, bad-arc.* must fail (README.arc-radius-tolerance)."""
    from tests.gcode.test_canon_linuxcnc import _machine

    interp = CORPUS / "linuxcnc" / "tests" / "interp"
    if not interp.is_dir():
        pytest.skip("../shared/corpus is not present")
    good = interp / "good" / f"good-arc.{kind}.{units}.center-format.ngc"
    bad = interp / "bad" / f"bad-arc.{kind}.{units}.center-format.ngc"
    run = interpret(good, _machine(None), arc_tolerance="linuxcnc")
    list(run)
    assert run.status == "complete"
    with pytest.raises(GcodeError) as e:
        list(interpret(bad, _machine(None), arc_tolerance="linuxcnc"))
    assert e.value.diagnostics[0].code == "GC301"
