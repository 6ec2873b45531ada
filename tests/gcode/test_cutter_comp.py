"""LinuxCNC cutter radius compensation (nczones.gcode.linuxcnc.cutter_comp): hand-computed paths, refusals, identities."""

from __future__ import annotations

import math
from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret, interpret_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from tests.corpus import CORPUS


def _machine(comp: str = "linuxcnc", diameters: str = 'T1 = "2"\nT2 = "4"') -> object:
    return parse_machine(f'''
[machine]
axes = ["X", "Y", "Z"]
cutter_compensation = "{comp}"
[machine.rapid]
X = "1000"
Y = "1000"
Z = "1000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[offsets]
G54 = {{ X = "100", Y = "50" }}
[tool_diameters]
{diameters}
''')


LCNC = _machine()


def _segs(text: str, machine=LCNC, **kw):
    run = interpret_text(text, machine, **kw)
    segs = list(run.segments())
    return run, segs


def _xy(seg, digits: int = 9):
    """End point in program coordinates (G54 = X100 Y50), rounded: the doubles of LinuxCNC's trigonometry."""
    return (round(float(seg.end[0] - 100), digits), round(float(seg.end[1] - 50), digits))


def test_default_machine_keeps_comp_unknown_and_says_how_to_enable_it():
    run, segs = _segs("G0 X0 Y0\nG41 D1 G1 X10 F100\n", _machine("none"))
    assert run.status == "unknown" and run.unsupported[0].code == "G41"
    assert 'cutter_compensation = "linuxcnc"' in run.unsupported[0].reason
    assert len(segs) == 1  # the move before G41


def test_convex_corner_gets_an_arc_around_the_exact_programmed_corner():
    run, segs = _segs("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nY-10\nG40 X20\n")
    assert run.status == "complete"
    assert [s.kind for s in segs] == [SegmentKind.RAPID, SegmentKind.LINE, SegmentKind.ARC, SegmentKind.LINE,
                                      SegmentKind.LINE]
    assert [_xy(s) for s in segs[1:]] == [(10, 1), (11, 0), (11, -10), (20, -10)]
    arc = segs[2]
    assert arc.centre == (F(110), F(50)) and arc.clockwise and arc.derived == "cutter comp corner"
    assert arc.block == segs[3].block and arc.span.line == 3  # the block the corner precedes
    for a, b in zip(segs, segs[1:]):  # continuous, exact
        assert a.end == b.start
    assert all(isinstance(v, F) for s in segs for v in s.end)


def test_concave_corner_moves_the_previous_end_back():
    run, segs = _segs("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nY10\nG40 X9 Y20\n")
    # left turn with the tool on the left: inside corner, the first line stops at X9
    assert [_xy(s) for s in segs[1:]] == [(9, 1), (9, 10), (9, 20)]
    assert segs[1].span.line == 2 and segs[2].span.line == 3
    assert segs[3].start == segs[2].end  # after G40 the move starts where the machine is


def test_square_outside_with_g42_and_a_tool_table_diameter():
    prog = "T1 M6\nG0 X0 Y0\nG42 D1 G1 X10 F100\nY10\nX0\nY0\nG40 G0 X-5\n"
    run, segs = _segs(prog)
    got = [(s.kind.name, _xy(s)) for s in segs]
    assert got == [("RAPID", (0, 0)), ("LINE", (10, -1)), ("ARC", (11, 0)), ("LINE", (11, 10)), ("ARC", (10, 11)),
                   ("LINE", (0, 11)), ("ARC", (-1, 10)), ("LINE", (-1, 0)), ("RAPID", (-5, 0))]
    assert [s.centre for s in segs if s.kind is SegmentKind.ARC] == [(110, 50), (110, 60), (100, 60)]
    assert not any(s.clockwise for s in segs if s.kind is SegmentKind.ARC)


def test_square_pocket_inside_with_g41_ccw():
    run, segs = _segs("G0 X0 Y0\nG41 D2 G1 X10 F100\nY10\nX0\nY0\nX10\nG40 X20\n")  # D2 = 4 mm
    assert [_xy(s) for s in segs[1:]] == [(8, 2), (8, 8), (2, 8), (2, 2), (10, 2), (20, 0)]


def test_arc_after_tangent_entry_keeps_the_exact_centre():
    run, segs = _segs("G0 X0 Y-10\nG41.1 D2 G1 X0 Y0 F100\nG2 X10 Y0 I5 J0\nG40 G1 X20\n")
    assert [(s.kind.name, _xy(s)) for s in segs[1:]] == [("LINE", (-1, 0)), ("ARC", (11, 0)), ("LINE", (20, 0))]
    arc = segs[2]
    assert arc.centre == (F(105), F(50)) and arc.clockwise


def test_entry_arc_g41_1():
    # first move an arc: LinuxCNC's convert_arc_comp1 (tool ends one radius outside the programmed end)
    run, segs = _segs("G0 X0 Y0\nG42.1 D1 G3 X10 Y0 I5 J0 F100\nG40 G1 X20\n")
    assert _xy(segs[1]) == (10.5, 0)
    assert segs[1].kind is SegmentKind.ARC and not segs[1].clockwise


def test_ccomp_gouging_is_rejected_with_linuxcnc_meaning_and_span():
    path = CORPUS / "linuxcnc" / "tests" / "interp" / "bad" / "ccomp-gouging.ngc"
    if not path.is_file():
        pytest.skip("corpus not available")
    with pytest.raises(GcodeError) as e:
        list(interpret(path, LCNC))
    d = e.value.diagnostics[0]
    assert d.code == "GC324"
    assert "Straight feed in concave corner cannot be reached by the tool without gouging" in d.message
    assert path.read_text().splitlines()[0].lstrip(";") in d.message
    assert (d.span.line, d.span.column) == (7, 1)  # g1x1: the move that reveals the corner


@pytest.mark.parametrize("prog, code, line", [
    ("G0 X0 Y0\nG41.1 D20 G1 X5 F100\n", "GC322", 2),                     # entry not longer than the radius
    ("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nG3 X10 Y2 I0 J1\n", "GC323", 3),   # tool radius >= arc radius, inside
    ("G0 X0 Y0\nG41 D3 G1 X10 F100\n", "GC321", 2),                       # no diameter for tool 3
    ("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nT1 M6\n", "GC325", 3),             # tool change with comp on
    ("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nG92 X0\n", "GC325", 3),            # axis offsets with comp on
    ("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nG20\n", "GC325", 3),               # units with comp on
    ("G0 X0 Y0\nG41.1 D2\nG41.1 D2\n", "GC320", 3),                       # already on
    ("G19\nG41.1 D2\n", "GC320", 2),                                      # G19
    ("G0 X0 Y0\nG41.1\n", "GC320", 2),                                    # G41.1 without D
])
def test_linuxcnc_refusals(prog, code, line):
    with pytest.raises(GcodeError) as e:
        _segs(prog)
    d = e.value.diagnostics[0]
    assert d.code == code and d.span.line == line, d.render()


def test_missing_diameter_error_names_the_tool_and_the_d_word():
    with pytest.raises(GcodeError) as e:
        _segs("G0 X0 Y0\nG41 D3 G1 X10 F100\n")
    d = e.value.diagnostics[0]
    assert "tool 3" in d.message and "[tool_diameters]" in d.message and d.span.column == 5


def test_dwell_and_m_codes_wait_behind_the_held_move():
    run, segs = _segs("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nG4 P1\nM8\nY-10\nM2\n")
    kinds = [s.kind.name for s in segs]
    assert kinds == ["RAPID", "LINE", "DWELL", "ARC", "LINE"]
    assert segs[2].start == segs[2].end == segs[1].end
    assert _xy(segs[-1]) == (11, -10)  # M2 flushed the last move


def test_program_end_without_m2_flushes():
    run, segs = _segs("G0 X0 Y0\nG41.1 D2 G1 X10 F100\n")
    assert [_xy(s) for s in segs] == [(0, 0), (10, 1)]


def test_inch_program_radius_in_inches():
    # T1 = 2 mm diameter: under G20 LinuxCNC converts the tool table's length into program units
    run, segs = _segs("G20\nG0 X0 Y0\nG41 D1 G1 X1 F10\nG40 X2\n")
    # 1 mm to the left: 1/25.4 in as LinuxCNC's double, taken exactly, times 25.4 (not exactly 1 mm)
    assert segs[1].end[1] != 51 and abs(segs[1].end[1] - 51) < F(1, 10**12)


def test_fast_and_full_interpreter_give_identical_segments():
    lines = ["G0 X0 Y0", "G1 X1 F100"] + [f"X{i} Y{i % 3}" for i in range(2, 40)]
    lines += ["G41.1 D0.5", "G1 X50 Y0"] + [f"X{50 + i} Y{(i % 2) * 10}" for i in range(1, 30)]
    lines += ["G40 G1 X100 Y50"] + [f"X{100 + i} Y{50 + i % 4}" for i in range(1, 40)] + ["M2"]
    text = "\n".join(lines) + "\n"
    fast = interpret_text(text, LCNC, fast=True)
    slow = interpret_text(text, LCNC, fast=False)
    a, b = list(fast.segments()), list(slow.segments())
    key = [(s.kind, s.start, s.end, s.centre, s.clockwise, s.block, s.span.line, s.derived, s.feed_mm_min)
           for s in a]
    assert key == [(s.kind, s.start, s.end, s.centre, s.clockwise, s.block, s.span.line, s.derived, s.feed_mm_min)
                   for s in b]
    assert len(a) > 100 and fast.counts["fast_lines"] > 0
    assert any(s.derived == "cutter comp corner" for s in a)


def _dist_point_segment(px, py, ax, ay, bx, by) -> float:
    dx, dy = bx - ax, by - ay
    t = max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy))


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.lists(st.integers(0, 359), min_size=3, max_size=9, unique=True),
       st.integers(20, 60), st.sampled_from(["G41", "G42"]))
def test_compensated_vertices_keep_the_tool_radius_from_a_convex_polygon(angles, size, code):
    """Outside a convex polygon (G41 clockwise, G42 counterclockwise) every compensated vertex is >= r away."""
    angles = sorted(angles, reverse=code == "G41")
    asc = sorted(angles)
    if any(b - a < 25 for a, b in zip(asc, asc[1:])) or 360 - asc[-1] + asc[0] < 25:
        return  # short edges: LinuxCNC may rightly refuse them
    pts = [(round(size * math.cos(math.radians(a)), 3), round(size * math.sin(math.radians(a)), 3)) for a in angles]
    r = 1.0
    prog = [f"G0 X{pts[0][0] - 20} Y{pts[0][1]}", f"G0 X{pts[0][0] - 10} Y{pts[0][1]}",
            f"{code}.1 D2 G1 X{pts[0][0]} Y{pts[0][1]} F100"]
    prog += [f"X{x} Y{y}" for x, y in pts[1:]] + [f"X{pts[0][0]} Y{pts[0][1]}", f"X{pts[1][0]} Y{pts[1][1]}", "M2"]
    try:
        run, segs = _segs("\n".join(prog) + "\n")
    except GcodeError as e:
        assert e.diagnostics[0].code in ("GC322", "GC324"), e.render()
        return
    edges = list(zip(pts, pts[1:] + pts[:1]))
    comp = [s for s in segs if s.kind is not SegmentKind.RAPID][1:]  # after the entry move
    assert comp
    for s in comp:
        x, y = float(s.end[0] - 100), float(s.end[1] - 50)
        d = min(_dist_point_segment(x, y, ax, ay, bx, by) for (ax, ay), (bx, by) in edges)
        assert d >= r - 1e-9, (s, d)


CANON_DIRS = ["tests/ccomp/mill-g90g91g92", "tests/ccomp/mill-line-arc-entry", "tests/ccomp/mill-zchanges",
              "tests/interp/cam-nisley", "tests/interp/crazy-paths", "tests/interp/inside-corners",
              "tests/interp/inverse-time-with-comp"]


@pytest.mark.parametrize("d", CANON_DIRS)
def test_linuxcnc_canon_logs_with_cutter_comp_match(d):
    from tests.gcode import test_canon_linuxcnc as canon

    cases = {c[0]: c for c in canon._cases()}
    if d not in cases:
        pytest.skip("corpus not available")
    prog, tbl = canon._parse_cmd(cases[d][1])
    base = CORPUS / "linuxcnc" / d
    status, why = canon._compare(d, base / prog, base / tbl if tbl else None)
    assert status == "match", why


def test_lathe_tool_table_comp_is_unknown():
    run, segs = _segs("G18\nG0 X0 Z0\nG41 D1 G1 Z-10 F100\n")
    assert run.status == "unknown" and "orientation" in run.unsupported[0].reason


def test_dependencies_of_compensated_points_are_those_of_the_programmed_points():
    run, segs = _segs("G0 X0 Y0\nG41.1 D2 G1 X10 F100\nY-10\nG40 X20\n", track_dependencies=True)
    assert run.status == "complete"
    for s in segs[1:]:
        assert s.deps_start[:2] == s.deps_end[:2] == (("G54",), ("G54",))


def test_lathe_tool_orientation_moves_the_controlled_point():
    """G42.1 D2 L3 in G18 (radius mode): LinuxCNC compensates the nose centre, then emits the controlled point,
    the centre moved by latheorigin: orientation 3 lowers Z and raises X by the radius (interp_queue.cc).

    Derivation (program = machine, frame (Z, X), r = 1, tool right of the path):
    * N3 G1 Z2 from (5, 12): entry, the centre ends r to the right of the direction (-1, 0): (2, 13);
    * N4 X8: direction (0, -1), a left turn with the tool on the right: convex, an arc around the programmed
      corner (2, 12) from (2, 13) to (1, 12), then the line to (1, 8);
    * every point and the arc's centre moved by (-1, +1): (1, 14), arc to (0, 13) about (1, 13), line to (0, 9);
    * the first move starts where the tool stands (5, 12); after G40 the next move starts at (0, 9).
    With L0 the same path without the shift."""
    from tests.gcode.turning.helpers import lathe

    m = lathe('cutter_compensation = "linuxcnc"\n', dialect="linuxcnc", diameter=False)
    prog = "G18 G8 G21\nG0 X12 Z5\nG42.1 D2 L{o}\nG1 Z2 F100\nX8\nG40 G0 X20\nM2\n"

    def path(o):
        run = interpret_text(prog.format(o=o), m)
        segs = list(run.segments())
        assert not run.unsupported
        iz, ix = m.axis_names.index("Z"), m.axis_names.index("X")
        return [(s.kind.name, round(float(s.end[iz]), 9), round(float(s.end[ix]), 9),
                 None if s.centre is None else (round(float(s.centre[0]), 9), round(float(s.centre[1]), 9)))
                for s in segs]

    assert path(3) == [("RAPID", 5, 12, None), ("LINE", 1, 14, None), ("ARC", 0, 13, (1, 13)),
                       ("LINE", 0, 9, None), ("RAPID", 2, 20, None)]
    assert path(0) == [("RAPID", 5, 12, None), ("LINE", 2, 13, None), ("ARC", 1, 12, (2, 12)),
                       ("LINE", 1, 8, None), ("RAPID", 2, 20, None)]
    # orientations 0 and 9 have no shift; the other seven move the point by +-r on X and/or Z
    assert path(9) == path(0)
    assert path(6)[1] == ("LINE", 2, 12, None) and path(5)[1] == ("LINE", 3, 13, None)


def test_lathe_tool_entry_arc_moves_the_controlled_point_first():
    """LinuxCNC's entry arc with a lathe tool is preceded by a feed to where the nose centre is (interp_convert.cc,
    "need this move for lathes"): queued at the start, (5, 12) shifted to (4, 13); the arc is the L0 arc moved by
    the shift (-1, +1).  With L0 there is no such move.  The flush at M1 moves the end of every queued move to
    the compensated position (LinuxCNC's move_endpoint_and_flush: "we need to change all of them"), that feed's
    too, so it ends where the arc ends."""
    from tests.gcode.turning.helpers import lathe

    m = lathe('cutter_compensation = "linuxcnc"\n', dialect="linuxcnc", diameter=False)
    prog = "G18 G8 G21\nG0 X12 Z5\nG42.1 D2 L{o}\nG2 X12 Z-5 R10 F100\nM1\nG40 G0 X20\nM2\n"
    iz, ix = m.axis_names.index("Z"), m.axis_names.index("X")
    runs = {o: list(interpret_text(prog.format(o=o), m).segments()) for o in (0, 3)}
    assert [s.kind.name for s in runs[0]] == ["RAPID", "ARC", "RAPID"]
    assert [s.kind.name for s in runs[3]] == ["RAPID", "LINE", "ARC", "RAPID"]
    line, arc, arc0 = runs[3][1], runs[3][2], runs[0][1]
    assert (arc.end[iz], arc.end[ix]) == (arc0.end[iz] - 1, arc0.end[ix] + 1)
    assert line.end == arc.end
    assert arc.centre == (arc0.centre[0] - 1, arc0.centre[1] + 1)
