"""Golden positions from the Fanuc manuals' worked examples and sentences (issue 33).

Every code ``specs/fanuc.md`` marks modelled (G codes, canned cycles, calls, M codes) has at least one
golden here (or in ``test_manual_lathe_examples.py``), marked with ``@covers(...)``;
:func:`test_every_modelled_code_has_a_golden` reads the codes from ``specs/fanuc.md`` and fails when one
has none.  Each golden is built from the example program or the sentence of the manual section that
``specs/fanuc.md`` cites, and its expected positions are derived by hand from the manual text in the
comment beside it — never by running nczones.

Sources (specs/fanuc.md, "Sources"): [0i] FANUC Series 0i-MD / 0i-MF operator's manual (B-64304EN,
B-64604EN), section named in each test; [Haas] the Haas mill operator's manual for M97.  The example
programs are the manuals' (block for block, values as printed) where a section has one; where the
manual's figure leaves a start point or a level unstated, the test states the one it assumes.

The machine (``MANUAL``): Fanuc mill, IS-B, DPI = 1 (calculator), the start and the reference position
at machine (0, 0, 0), G54 = 0 (so machine = program where nothing else is active), G55..G59 and
G54.1 P1 at the offsets below, the manual's H01 = -4.0, G73 d = 2, G83 d = 1, G76 shift +X, the 2nd
reference position (-100, -50, -10).  machine = program + work offset + G52 + G92 + tool length (Z).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from fractions import Fraction as Q
from pathlib import Path

import pytest

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from tests.machines import machine_text

SPEC = Path(__file__).resolve().parents[3] / "specs" / "fanuc.md"

MANUAL = machine_text("fanuc_manual_examples_mill")

#: code -> the goldens that cover it (filled by @covers)
COVERED: dict[str, list[str]] = {}


def covers(*codes: str) -> Callable:
    """Mark a golden with the Fanuc codes it derives positions for (read by the coverage test)."""
    def mark(fn):
        for c in codes:
            COVERED.setdefault(c, []).append(fn.__name__)
        return fn
    return mark


def machine():
    return parse_machine(MANUAL, "manual.toml")


def path(text: str, m=None) -> list[tuple[str, tuple]]:
    """(kind, machine end point) of every motion, dwells and moves of length 0 left out:
    R rapid, L feed (line), A arc."""
    run = interpret_text(text, m or machine(), file="manual.nc")
    out: list[tuple[str, tuple]] = []
    for s in run.segments():
        end = tuple(s.end)
        if s.kind == SegmentKind.DWELL or (tuple(s.start) == end and s.kind != SegmentKind.ARC):
            continue
        out.append(({SegmentKind.RAPID: "R", SegmentKind.LINE: "L", SegmentKind.ARC: "A"}.get(s.kind, "?"), end))
    assert run.status == "complete", run.unsupported
    return out


def ends(text: str, m=None) -> list[tuple]:
    return [e for _, e in path(text, m)]


def P(*xyz) -> tuple:
    """A point of exact decimals."""
    return tuple(Q(str(v)) for v in xyz)


def dedup(moves: list[tuple[str, tuple]], start=(0, 0, 0)) -> list[tuple[str, tuple]]:
    """The hand-derived moves with those that do not move left out (as :func:`path` does)."""
    out, at = [], P(*start)
    for kind, end in moves:
        if end != at:
            out.append((kind, end))
        at = end
    return out


# ----------------------------------------------------------------------------- positions, modes, planes


@covers("G90", "G91", "G00")
def test_absolute_and_incremental_programming():
    # [0i] "Absolute and incremental programming (G90, G91)": the example moves the tool from the start
    # point (X100, Y30 by the figure) to the end point (X40, Y70), written "G90 X40.0 Y70.0 ;" in
    # absolute and "G91 Y40.0 ;" in incremental programming: 100 - 60 = 40, 30 + 40 = 70.
    text = "G00 G90 X100.0 Y30.0\nG90 X40.0 Y70.0\nX100.0 Y30.0\nG91 X-60.0 Y40.0\nM30\n"
    assert path(text) == [("R", P(100, 30, 0)), ("R", P(40, 70, 0)), ("R", P(100, 30, 0)), ("R", P(40, 70, 0))]


@covers("G01", "G94")
def test_linear_interpolation():
    # [0i] "Linear interpolation (G01)": "(G91) G01 X200.0 Y100.0 F200.0 ;" a straight cut from the start
    # (0, 0) to (200, 100) at 200 mm/min (G94 feed per minute, the power-on feed mode).
    run = interpret_text("G94 G91 G01 X200.0 Y100.0 F200.0\nM30\n", machine())
    (s,) = list(run.segments())
    assert s.kind == SegmentKind.LINE and tuple(s.end) == P(200, 100, 0) and s.feed_mm_min == 200


@covers("G93", "G95")
def test_feed_modes_leave_the_path_alone():
    # [0i] "Feed functions": G93 inverse time feed, G95 feed per revolution change only the speed along
    # the programmed path; the straight cuts end where their words say.
    text = "G90 G95 S1000 M03 G01 X10.0 F0.2\nG93 G01 Y10.0 F5.0\nG94 G01 X0 F100.0\nM30\n"
    assert path(text) == [("L", P(10, 0, 0)), ("L", P(10, 10, 0)), ("L", P(0, 10, 0))]


@covers("G02", "G03", "G17", "G92")
@pytest.mark.parametrize("variant", ["R absolute", "IJ absolute", "R incremental"])
def test_circular_interpolation_example(variant):
    # [0i] "Circular interpolation (G02, G03)", the example in absolute and incremental programming:
    #   G92 X200.0 Y40.0 Z0 ;
    #   G90 G03 X140.0 Y100.0 R60.0 F300. ;  G02 X120.0 Y60.0 R50.0 ;     (absolute, R)
    #   G90 G03 X140.0 Y100.0 I-60.0 F300. ; G02 X120.0 Y60.0 I-50.0 ;     (absolute, I J)
    #   G91 G03 Y60.0 R60.0 F300. ;   G02 Y-40.0 R50.0 ;     (incremental)
    # The first arc: centre (200 - 60, 40) = (140, 40), radius 60, counter-clockwise to (140, 100); the
    # second: centre (140 - 50, 100) = (90, 100), radius 50, clockwise to (120, 60).  G92 makes the start
    # (machine 0, 0, 0) read (200, 40, 0): machine = program - (200, 40, 0).
    body = {"R absolute": "G90 G03 X140.0 Y100.0 R60.0 F300.\nG02 X120.0 Y60.0 R50.0\n",
            "IJ absolute": "G90 G03 X140.0 Y100.0 I-60.0 F300.\nG02 X120.0 Y60.0 I-50.0\n",
            "R incremental": "G91 G03 X-60.0 Y60.0 R60.0 F300.\nG02 X-20.0 Y-40.0 R50.0\n"}[variant]
    run = interpret_text("G17 G92 X200.0 Y40.0 Z0\n" + body + "M30\n", machine())
    a, b = list(run.segments())
    assert (a.kind, a.clockwise, tuple(a.end)) == (SegmentKind.ARC, False, P(140 - 200, 100 - 40, 0))
    assert (b.kind, b.clockwise, tuple(b.end)) == (SegmentKind.ARC, True, P(120 - 200, 60 - 40, 0))
    if a.centre is not None:  # I J arcs carry their centre; R arcs may leave it to the radius
        assert tuple(a.centre) == P(140 - 200, 40 - 40) and tuple(b.centre) == P(90 - 200, 100 - 40)


@covers("G18", "G19")
def test_plane_selection():
    # [0i] "Plane selection": G17 XpYp, G18 ZpXp, G19 YpZp: the arc is in the selected plane, its centre
    # given by the plane's two words (G18: I and K, G19: J and K).  From (0, 0, 0), "G18 G02 X20. Z0
    # I10. K0" is a half circle of radius 10 about (X10, Z0) ending at X20 with Y unchanged; "G19 G03
    # Y20. Z0 J10. K0" one about (Y10, Z0) ending at Y20 with X unchanged.
    run = interpret_text("G90 G18 G02 X20.0 Z0 I10.0 K0 F100.\nG19 G03 Y20.0 Z0 J10.0 K0\nM30\n", machine())
    a, b = list(run.segments())
    # the centre in the plane's (first, second) axis order: G18 (Z, X) = (0, 10), G19 (Y, Z) = (10, 0)
    assert tuple(a.end) == P(20, 0, 0) and a.centre == P(0, 10) and a.plane.name == "XZ" and a.clockwise
    assert tuple(b.end) == P(20, 20, 0) and b.centre == P(10, 0) and b.plane.name == "YZ" and not b.clockwise


@covers("G20", "G21")
def test_inch_metric_conversion():
    # [0i] "Inch/metric conversion (G20, G21)": G20 inch input, G21 millimetre input; 1 inch = 25.4 mm:
    # X1.0 Y2.0 in G20 is (25.4, 50.8) mm; X10.0 in G21 is 10 mm.
    assert ends("G20 G90 G00 X1.0 Y2.0\nG21 X10.0\nM30\n") == [P(25.4, 50.8, 0), P(10, 50.8, 0)]


@covers("G04")
def test_dwell():
    # [0i] "Dwell (G04)": "G04 X2.5 ;" or "G04 P2500 ;" dwells 2.5 s (P in milliseconds); no motion.
    run = interpret_text("G04 X2.5\nG04 P2500\nM30\n", machine())
    segs = list(run.segments())
    assert [(s.kind, s.dwell_s, tuple(s.end)) for s in segs] == [(SegmentKind.DWELL, Q(5, 2), P(0, 0, 0))] * 2


@covers("G33")
def test_thread_cutting_is_the_straight_line():
    # [0i] "Thread cutting (G33)": "G33 IP_ F_ ;" cuts a straight thread of lead F to IP: the tool path
    # is the straight line to (0, 0, -10).
    assert path("G90 G33 Z-10.0 F1.5\nM30\n") == [("L", P(0, 0, -10))]


@covers("G40")
def test_cutter_compensation_cancel():
    # [0i] "Cutter compensation C": in the cancel mode (G40, the power-on state) the tool centre path is
    # the programmed path: "G40 G01 X10.0 Y5.0" ends at (10, 5).
    assert path("G40 G90 G01 X10.0 Y5.0 F100.\nM30\n") == [("L", P(10, 5, 0))]


# ----------------------------------------------------------------------------- coordinate systems


@covers("G54", "G55", "G56", "G57", "G58", "G59")
def test_selecting_a_workpiece_coordinate_system():
    # [0i] "Selecting a workpiece coordinate system": "G90 G55 G00 X40.0 Y100.0 ;" positions the tool
    # at (40, 100) in workpiece coordinate system 2: machine = (40, 100) + G55's offset.  The six systems
    # with this machine's offsets: G54 (0, 0, 0), G55 (100, 200, 0), G56 (300, 0, 0), G57 (0, 400, 0),
    # G58 (0, 0, -50), G59 (-10, -20, -30).
    text = "".join(f"G90 G{g} G00 X40.0 Y100.0 Z0\n" for g in (54, 55, 56, 57, 58, 59)) + "M30\n"
    assert ends(text) == [P(40, 100, 0), P(140, 300, 0), P(340, 100, 0), P(40, 500, 0), P(40, 100, -50),
                          P(30, 80, -30)]


@covers("G54.1")
def test_additional_workpiece_coordinate_systems():
    # [0i] "Additional workpiece coordinate systems": "G54.1 Pn ;" selects system n (1 to 48), then
    # positions are read in it: (1, 2, 3) in G54.1 P1 with offset (7, 8, 9) is machine (8, 10, 12).
    assert ends("G90 G54.1 P1 G00 X1.0 Y2.0 Z3.0\nM30\n") == [P(8, 10, 12)]


@covers("G52")
def test_local_coordinate_system():
    # [0i] "Local coordinate system": "G52 IP_ ;" sets a local coordinate system in all the workpiece
    # coordinate systems (G54 to G59), its origin at IP in each; "G52 IP0 ;" cancels it.
    # G52 X10 Y20 then (5, 5) in G54: (15, 25); in G55 (100, 200): (115, 225); after G52 X0 Y0: (105, 205).
    text = "G90 G54 G52 X10.0 Y20.0\nG00 X5.0 Y5.0\nG55 X5.0 Y5.0\nG52 X0 Y0\nX5.0 Y5.0\nM30\n"
    assert ends(text) == [P(15, 25, 0), P(115, 225, 0), P(105, 205, 0)]


@covers("G53")
def test_machine_coordinate_system():
    # [0i] "Machine coordinate system": "(G90) G53 IP_ ;" moves the tool to IP in the machine coordinate
    # system at rapid traverse, whatever workpiece system is selected: from (0, 0) in G55 (machine
    # (100, 200)) to machine (-50, -60).
    assert path("G90 G55 G00 X0 Y0\nG53 X-50.0 Y-60.0\nM30\n") == [("R", P(100, 200, 0)), ("R", P(-50, -60, 0))]


@covers("G92", "G92.1")
def test_setting_a_workpiece_coordinate_system_g92():
    # [0i] "Setting a workpiece coordinate system (G92)": "G92 X25.2 Z23.0 ;" with the tool tip at the
    # start point sets a system in which the tool tip is at (25.2, 23.0): the start (machine 0, 0, 0)
    # reads X25.2 Z23.0, so "G00 X0 Z0" goes to machine (-25.2, 0, -23).
    # [0i] "Workpiece coordinate system preset (G92.1)": "G92.1 IP 0 ;" returns the system shifted by
    # G92 to the one before the shift: "G00 X0 Z0" then goes to machine (0, 0, 0).
    text = "G90 G92 X25.2 Z23.0\nG00 X0 Z0\nG92.1 X0 Z0\nG00 X0 Z0\nM30\n"
    assert ends(text) == [P(-25.2, 0, -23), P(0, 0, 0)]


@covers("G10")
def test_programmable_data_input_work_offsets_and_tool_lengths():
    # [0i] "Changing workpiece coordinate system by G10": "G10 L2 Pp IP_ ;" p = 1..6 is G54..G59; IP is
    # the workpiece origin offset in G90 and the value added to it in G91.  "G10 L20 Pn IP_ ;" sets
    # G54.1 Pn.  [0i] "Tool compensation values input (G10)": "G10 L10 P R ;" sets the tool length
    # geometry of offset P (memory C).
    #   G90 G10 L2 P1 X10. Y20.     G54 = (10, 20, 0): G54 X0 Y0 -> (10, 20)
    #   G91 G10 L2 P1 X5.           G54 X = 10 + 5 = 15: X0 Y0 -> (15, 20)
    #   G90 G10 L20 P1 X1.          G54.1 P1 X = 1: G54.1 P1 X0 Y0 Z0 -> (1, 8, 9)
    #   G10 L10 P2 R25.             H2 = 25: G54 G43 X0 Y0 Z0 H2 -> (15, 20, 0 + 25)
    text = ("G90 G10 L2 P1 X10.0 Y20.0\nG54 G00 X0 Y0\nG91 G10 L2 P1 X5.0\nG90 G00 X0 Y0\n"
            "G90 G10 L20 P1 X1.0\nG54.1 P1 G00 X0 Y0 Z0\nG10 L10 P2 R25.0\nG54 G43 G00 X0 Y0 Z0 H2\nM30\n")
    assert ends(text) == [P(10, 20, 0), P(15, 20, 0), P(1, 8, 9), P(15, 20, 25)]


# ----------------------------------------------------------------------------- reference positions


@covers("G28", "G29", "M06")
def test_reference_position_return_example():
    # [0i] "Reference position return", the example:
    #   G28 G90 X1000.0 Y500.0 ;   (programs movement from A to B; moves to reference position R)
    #   T1111 ; M06 ;              (changes the tool at the reference position)
    #   G29 X1300.0 Y200.0 ;       (programs movement from B to C; moves from R to C via B)
    # A is taken as (200, 300) (the figure's start); R is machine (0, 0) on the named axes X and Y, Z is
    # not named and stays.  Every move at rapid; M06 moves nothing ([0i]; specs/fanuc.md M06).
    text = "G90 G00 X200.0 Y300.0\nG28 G90 X1000.0 Y500.0\nT1111\nM06\nG29 X1300.0 Y200.0\nM30\n"
    assert path(text) == [("R", P(200, 300, 0)), ("R", P(1000, 500, 0)), ("R", P(0, 0, 0)),
                          ("R", P(1000, 500, 0)), ("R", P(1300, 200, 0))]


@covers("G30")
def test_second_reference_position_return():
    # [0i] "2nd, 3rd and 4th reference position return": "G30 P2 IP_ ;" goes through the intermediate
    # point IP to the 2nd reference position (parameter 1241; here (-100, -50, -10)) on the named axes.
    # "G91 G30 P2 Z0 ;": the intermediate point is where Z stands; then Z to -10; X and Y stay.
    assert path("G90 G00 X5.0 Y6.0\nG91 G30 P2 Z0\nM30\n") == [("R", P(5, 6, 0)), ("R", P(5, 6, -10))]


@covers("G27")
def test_reference_position_return_check():
    # [0i] "Reference position return check (G27)": "G27 IP_ ;" positions the tool at rapid traverse at
    # IP (then the control checks that it is the reference position): from (10, 10) to (0, 0).
    assert path("G90 G00 X10.0 Y10.0\nG27 X0 Y0\nM30\n") == [("R", P(10, 10, 0)), ("R", P(0, 0, 0))]


# ----------------------------------------------------------------------------- tool length


@covers("G43", "G44", "G49")
def test_tool_length_compensation_sentence():
    # [0i] "Tool length compensation (G43, G44, G49)": with G43 the offset value of H is added to the
    # Z end point, with G44 subtracted; G49 cancels.  H01 = -4.0 (the manual's value):
    #   G90 G43 Z10. H01   machine Z 10 + (-4) = 6
    #   G44 Z10. H01       10 - (-4) = 14
    #   G49 Z10.           10
    assert ends("G90 G00 G43 Z10.0 H01\nG44 Z10.0 H01\nG49 Z10.0\nM30\n") == [P(0, 0, 6), P(0, 0, 14), P(0, 0, 10)]


@covers("G43", "G49")
def test_tool_length_compensation_example():
    # [0i] "Tool length compensation", the example (H01 = -4.0; the block comments are the manual's):
    #   N1 G91 G00 X120.0 Y80.0 ;        (1) positioning                 X 120, Y 80
    #   N2 G43 Z-32.0 H01 ;              (2) Z by -32 + (-4) = -36:      Z -36
    #   N3 G01 Z-21.0 F1000 ;            (3)                              Z -57
    #   N4 G04 P2000 ;                   (4) dwell
    #   N5 G00 Z21.0 ;                   (5)                              Z -36
    #   N6 X30.0 Y-50.0 ;                (6)                              X 150, Y 30
    #   N7 G01 Z-41.0 ;                  (7)                              Z -77
    #   N8 G00 Z41.0 ;                   (8)                              Z -36
    #   N9 X50.0 Y30.0 ;                 (9)                              X 200, Y 60
    #   N10 G01 Z-25.0 ;                 (10)                             Z -61
    #   N11 G04 P2000 ;                  (11) dwell
    #   N12 G00 Z57.0 H00 ;              (12) Z by 57 - (-4) = +61:       Z 0
    #   N13 Y-60.0 ;             (13)                             X 0, Y 0
    #   N14 M2 ;
    # The tool axis moves by the increment plus (new offset - old offset): the Z moves sum to 0.
    text = ("N1 G91 G00 X120.0 Y80.0\nN2 G43 Z-32.0 H01\nN3 G01 Z-21.0 F1000\nN4 G04 P2000\nN5 G00 Z21.0\n"
            "N6 X30.0 Y-50.0\nN7 G01 Z-41.0\nN8 G00 Z41.0\nN9 X50.0 Y30.0\nN10 G01 Z-25.0\nN11 G04 P2000\n"
            "N12 G00 Z57.0 H00\nN13 X-200.0 Y-60.0\nN14 M2\n")
    assert ends(text) == [P(120, 80, 0), P(120, 80, -36), P(120, 80, -57), P(120, 80, -36), P(150, 30, -36),
                          P(150, 30, -77), P(150, 30, -36), P(200, 60, -36), P(200, 60, -61), P(200, 60, 0),
                          P(0, 0, 0)]


# ----------------------------------------------------------------------------- canned cycles


def drill(holes, *, initial, r, z, retract, feed_out=False, shift=None, pecks=None):
    """The moves of a drilling cycle, per [0i] "Canned cycle for drilling": operation 1 positions X and Y
    at rapid at the current level; 2 rapid to the R point; 3 the hole (feed; ``pecks``: the depths of
    the cuts and how the tool comes back between them); 4 at the bottom; 5 back at rapid to the
    initial level (G98) or to R (G99) — the manual's figures draw the G98 return from the bottom straight
    to the initial level (so does a third-party transcription of the operations, zanotowane.pl "G81
    Drilling Spot Boring": "Op 4) Rapid traverse to Initial level (G98) or R point level (G99)") — or
    with ``feed_out`` at feed to R, then (G98) at rapid to the initial level.  ``holes``: (x, y, G98?)."""
    moves, level = [], initial
    for x, y, g98 in holes:
        moves.append(("R", P(x, y, level)))
        moves.append(("R", P(x, y, r)))
        if pecks is None:
            moves.append(("L", P(x, y, z)))
        else:
            moves += [(k, P(x, y, d)) for k, d in pecks]
        out = initial if g98 else r
        if shift is not None:  # G76: shift away from the wall at the bottom, out, shift back
            moves.append(("R", P(x + shift, y, z)))
            moves.append(("R", P(x + shift, y, out)))
            moves.append(("R", P(x, y, out)))
        elif feed_out:
            moves.append(("L", P(x, y, r)))
            moves.append(("R", P(x, y, out)))
        else:
            moves.append(("R", P(x, y, out)))
        level = initial if g98 else r
    return dedup(moves)


# [0i] "Drilling cycle, spot drilling (G81)", the example (and the same six holes in the examples of the
# other cycles, with their own R, P, Q):
#   M3 S2000 ;
#   G90 G99 G81 X300. Y-250. Z-150. R-100. F120. ;   position, drill hole 1, then return to point R
#   Y-550. ;  Y-750. ;  X1000. ;  Y-550. ;           holes 2 .. 5, return to point R
#   G98 Y-750. ;                                     hole 6, return to the initial level
#   G80 G28 G91 X0 Y0 Z0 ;                           return to the reference position
#   M5 ;
# The initial level is where Z stands when the cycle starts: 0 here (the start).
SIX = "Y-550.\nY-750.\nX1000.\nY-550.\nG98 Y-750.\nG80 G28 G91 X0 Y0 Z0\nM5\nM30\n"
HOLES = [(300, -250, False), (300, -550, False), (300, -750, False), (1000, -750, False), (1000, -550, False),
         (1000, -750, True)]
HOME = [("R", P(0, 0, 0))]


@covers("G81", "G80", "G98", "G99")
def test_drilling_cycle_g81_example():
    text = "M3 S2000\nG90 G99 G81 X300. Y-250. Z-150. R-100. F120.\n" + SIX
    # G80 G28 G91 X0 Y0 Z0: the intermediate point is where the tool stands (1000, -750, 0), then (0, 0, 0)
    assert path(text) == drill(HOLES, initial=0, r=-100, z=-150, retract="R") + HOME


@covers("G82")
def test_drilling_cycle_counter_boring_g82():
    # [0i] "Drilling cycle, counter boring (G82)": as G81 with a dwell P at the bottom (no motion), then
    # rapid to R: "G90 G99 G82 X300. Y-250. Z-150. R-100. P1000 F120. ;".
    text = "M3 S2000\nG90 G99 G82 X300. Y-250. Z-150. R-100. P1000 F120.\n" + SIX
    assert path(text) == drill(HOLES, initial=0, r=-100, z=-150, retract="R") + HOME


def _g73_pecks(r, z, q, d):
    """[0i] "High-speed peck drilling cycle (G73)": cut Q, back off d (parameter 5114) at rapid, cut
    q + d (to the previous depth + Q) ... the last cut to Z."""
    out, depth = [], r
    while depth - q > z:
        depth -= q
        out += [("L", P(0, 0, depth)), ("R", P(0, 0, depth + d))]
    out.append(("L", P(0, 0, z)))
    return [(k, p[2]) for k, p in out]


@covers("G73")
def test_high_speed_peck_drilling_g73():
    # "G90 G99 G73 X300. Y-250. Z-150. R-100. Q15. F120. ;" with d = 2: cuts to -115, -130, -145, each
    # followed by a rapid back-off of 2 mm, then the last cut to -150, then rapid to R.
    text = "M3 S2000\nG90 G99 G73 X300. Y-250. Z-150. R-100. Q15. F120.\n" + SIX
    pecks = _g73_pecks(-100, -150, 15, 2)
    assert pecks == [("L", -115), ("R", -113), ("L", -130), ("R", -128), ("L", -145), ("R", -143), ("L", -150)]
    assert path(text) == drill(HOLES, initial=0, r=-100, z=-150, retract="R", pecks=pecks) + HOME


@covers("G83")
def test_peck_drilling_g83():
    # [0i] "Peck drilling cycle (G83)": after each cut of Q the tool returns to R at rapid, then goes down
    # at rapid to d (parameter 5115, here 1) above the previous bottom and cuts q + d:
    # "G90 G99 G83 X300. Y-250. Z-150. R-100. Q15. F120. ;" cuts to -115, -130, -145, -150.
    pecks = [("L", -115), ("R", -100), ("R", -114), ("L", -130), ("R", -100), ("R", -129), ("L", -145),
             ("R", -100), ("R", -144), ("L", -150)]
    text = "M3 S2000\nG90 G99 G83 X300. Y-250. Z-150. R-100. Q15. F120.\n" + SIX
    assert path(text) == drill(HOLES, initial=0, r=-100, z=-150, retract="R", pecks=pecks) + HOME


@covers("G84", "G74", "G84.2", "G84.3")
@pytest.mark.parametrize("code,spindle", [("G84", "M3"), ("G74", "M4"), ("G84.2", "M3"), ("G84.3", "M4")])
def test_tapping_cycles(code, spindle):
    # [0i] "Tapping cycle (G84)" / "Left-handed tapping cycle (G74)" (and the rigid tapping codes G84.2
    # right-handed, G84.3 left-handed): feed to Z, dwell P, the spindle reverses, feed back out to R:
    # "M3 S100 ; G90 G99 G84 X300. Y-250. Z-150. R-120. P300 F120. ;" (M4 and G74 for the left hand).
    text = f"{spindle} S100\nG90 G99 {code} X300. Y-250. Z-150. R-120. P300 F120.\n" + SIX
    assert path(text) == drill(HOLES, initial=0, r=-120, z=-150, retract="R", feed_out=True) + HOME


@covers("G85", "G89")
@pytest.mark.parametrize("code", ["G85", "G89"])
def test_boring_cycles_feeding_out(code):
    # [0i] "Boring cycle (G85)": feed to Z, feed back to R; "Boring cycle (G89)": the same with a dwell at
    # the bottom: "G90 G99 G85 X300. Y-250. Z-150. R-120. F120. ;" (G89 with P1000).
    text = f"M3 S100\nG90 G99 {code} X300. Y-250. Z-150. R-120. P1000 F120.\n" + SIX
    assert path(text) == drill(HOLES, initial=0, r=-120, z=-150, retract="R", feed_out=True) + HOME


@covers("G86")
def test_boring_cycle_g86():
    # [0i] "Boring cycle (G86)": feed to Z, the spindle stops, rapid back out:
    # "G90 G99 G86 X300. Y-250. Z-150. R-100. F120. ;".
    text = "M3 S2000\nG90 G99 G86 X300. Y-250. Z-150. R-100. F120.\n" + SIX
    assert path(text) == drill(HOLES, initial=0, r=-100, z=-150, retract="R") + HOME


@covers("G76")
def test_fine_boring_cycle_g76():
    # [0i] "Fine boring cycle (G76)": at the bottom the spindle stops at the fixed rotation position and
    # the tool moves away from the wall by Q (direction: parameter 5101, here +X) and is retracted, then
    # moves back by Q: "G90 G99 G76 X300. Y-250. Z-150. R-100. Q5. P1000 F120. ;".
    text = "M3 S500\nG90 G99 G76 X300. Y-250. Z-150. R-100. Q5. P1000 F120.\n" + SIX
    want = drill(HOLES, initial=0, r=-100, z=-150, retract="R", shift=5) + HOME
    assert ends(text) == [p for _, p in want]


# ----------------------------------------------------------------------------- transforms


def _round_is_b(v: float) -> Q:
    """To the least input increment of IS-B (0.001 mm), halves away from zero."""
    n = abs(v) * 1000
    k = math.floor(n + 0.5)
    return Q(int(math.copysign(k, v)), 1000)


@covers("G68", "G69")
def test_coordinate_system_rotation_example():
    # [0i] "Coordinate system rotation (G68, G69)", the example:
    #   N1 G92 Y-500.0 G69 G17 ;
    #   N2 G68 X700.0 Y300.0 R15.0 ;
    #   N3 G90 G01 X0 Y0 F200 ;
    #   N4 G91 X1000.0 ;
    #   N5 G02 Y1000.0 R1000.0 ;
    #   N6 G03 X-1000.0 I-500.0 J-500.0 ;
    #   N7 G01 Y-1000.0 ;
    #   N8 G69 G90 Y-500.0 M02 ;
    # Program points (0,0), (1000,0), (1000,1000), (0,1000), (0,0) turned by 15 degrees about (700, 300):
    # x' = 700 + (x-700) cos 15 - (y-300) sin 15, y' = 300 + (x-700) sin 15 + (y-300) cos 15, each
    # rounded to 0.001 (specs/fanuc.md); G92 makes machine (0, 0) read (-500, -500): machine = p + 500.
    c, s = math.cos(math.radians(15)), math.sin(math.radians(15))

    def turned(x, y):
        return (_round_is_b(700 + (x - 700) * c - (y - 300) * s) + 500,
                _round_is_b(300 + (x - 700) * s + (y - 300) * c) + 500, Q(0))

    want = [turned(0, 0), turned(1000, 0), turned(1000, 1000), turned(0, 1000), turned(0, 0), P(0, 0, 0)]
    text = ("N1 G92 X-500.0 Y-500.0 G69 G17\nN2 G68 X700.0 Y300.0 R15.0\nN3 G90 G01 X0 Y0 F200\nN4 G91 X1000.0\n"
            "N5 G02 Y1000.0 R1000.0\nN6 G03 X-1000.0 I-500.0 J-500.0\nN7 G01 Y-1000.0\n"
            "N8 G69 G90 X-500.0 Y-500.0 M02\n")
    assert ends(text) == want


@covers("G51", "G50")
def test_scaling():
    # [0i] "Scaling (G50, G51)": "G51 X_ Y_ Z_ P_ ;" scales the programmed figure by P about (X, Y, Z)
    # (the same magnification on every axis); G50 cancels.  About (50, 50) by 0.5: (100, 100) is
    # 50 + 0.5 (100 - 50) = 75 on both axes, (0, 100) is (25, 75); after G50, (0, 0) is (0, 0).
    text = "G90 G00 X0 Y0\nG51 X50.0 Y50.0 P0.5\nG01 X100.0 Y100.0 F100.\nX0 Y100.0\nG50\nG90 G00 X0 Y0\nM30\n"
    assert path(text) == [("L", P(75, 75, 0)), ("L", P(25, 75, 0)), ("R", P(0, 0, 0))]


@covers("G51.1", "G50.1", "M98", "M99")
def test_programmable_mirror_image_example():
    # [0i] "Programmable mirror image (G50.1, G51.1)", the example:
    #   subprogram O9000: G00 G90 X60.0 Y60.0 ; G01 X100.0 F100 ; G01 Y100.0 ; G01 X60.0 Y60.0 ; M99 ;
    #   main: N10 G00 G90 ; N20 M98 P9000 ; N30 G51.1 X50.0 ; N40 M98 P9000 ; N50 G51.1 Y50.0 ;
    #         N60 M98 P9000 ; N70 G50.1 X0 ; N80 M98 P9000 ; N90 G50.1 Y0 ;
    # The figure (60,60) (100,60) (100,100) (60,60), mirrored about X = 50 (x -> 100 - x), then also
    # about Y = 50 (y -> 100 - y), then with the X mirror cancelled (the Y one only).
    text = ("O0001\nN10 G00 G90\nN20 M98 P9000\nN30 G51.1 X50.0\nN40 M98 P9000\nN50 G51.1 Y50.0\nN60 M98 P9000\n"
            "N70 G50.1 X0\nN80 M98 P9000\nN90 G50.1 Y0\nM30\n"
            "O9000\nG00 G90 X60.0 Y60.0\nG01 X100.0 F100\nG01 Y100.0\nG01 X60.0 Y60.0\nM99\n")
    fig = [(60, 60), (100, 60), (100, 100), (60, 60)]
    want = ([P(x, y, 0) for x, y in fig] + [P(100 - x, y, 0) for x, y in fig]
            + [P(100 - x, 100 - y, 0) for x, y in fig] + [P(x, 100 - y, 0) for x, y in fig])
    assert ends(text) == want


@covers("G16", "G15")
def test_polar_coordinate_bolt_hole_circle():
    # [0i] "Polar coordinate command (G15, G16)", the bolt hole circle example:
    #   N1 G17 G90 G16 ;                          polar command, XY plane, the work zero the centre
    #   N2 G81 X100.0 Y30.0 Z-20.0 F200.0 ;  radius 100, angle 30 degrees
    #   N3 Y150.0 ;   N4 Y270.0 ;                 angles 150 and 270, the radius kept
    #   N5 G15 G80 ;
    # Holes at (100 cos a, 100 sin a), rounded to 0.001: (86.603, 50), (-86.603, 50), (0, -100); G98 (the
    # power-on return mode): each hole from the initial level 0 down to R -5 and Z -20 and back to 0.
    r3 = Q(86603, 1000)
    holes = [(r3, 50, True), (-r3, 50, True), (0, -100, True)]
    want = drill(holes, initial=0, r=-5, z=-20, retract="I")
    assert path("N1 G17 G90 G16\nN2 G81 X100.0 Y30.0 Z-20.0 R-5.0 F200.0\nN3 Y150.0\nN4 Y270.0\nN5 G15 G80\n"
                "M30\n") == want


# ----------------------------------------------------------------------------- calls, program end


@covers("G65")
def test_macro_simple_call_example():
    # [0i] "Simple call (G65)", the example: "G65 P9010 L2 A1.0 B2.0 ;" calls O9010 twice with #1 = 1,
    # #2 = 2; O9010: "#3=#1+#2 ; IF [#3 GT 360] GOTO 9 ; G00 G91 X#3 ; N9 M99 ;" moves X by 3 each time.
    text = ("O0001\nG90 G00 X0\nG65 P9010 L2 A1.0 B2.0\nM30\n"
            "O9010\n#3=#1+#2\nIF [#3 GT 360] GOTO 9\nG00 G91 X#3\nN9 M99\n")
    assert ends(text) == [P(3, 0, 0), P(6, 0, 0)]


@covers("G66", "G67")
def test_macro_modal_call():
    # [0i] "Modal call (G66)": after "G66 P L <arguments> ;" the macro is called after every block with a
    # move command, with the G66 arguments, until G67.  The manual's drilling-macro example, shortened:
    # the macro goes to R (#18) at rapid, feeds to Z (#26), and returns to the Z it was called at (#5003).
    # G92 makes the start read Z50 (machine = program - 50 on Z); the G66 block itself does not call.
    text = ("O0001\nG92 X0 Y0 Z50.0\nG00 G90 X100.0 Y50.0\nG66 P9110 Z-20.0 R5.0 F500.0\nG90 X20.0 Y20.0\n"
            "X50.0 Y50.0\nG67\nX0 Y0\nM30\n"
            "O9110\n#5=#5003\nG00 G90 Z#18\nG01 Z#26 F#9\nG00 Z#5\nM99\n")
    hole = [(5, "R"), (-20, "L"), (50, "R")]
    want = [("R", P(100, 50, 0))]
    for x, y in ((20, 20), (50, 50)):
        want.append(("R", P(x, y, 0)))
        want += [(k, P(x, y, z - 50)) for z, k in hole]
    want.append(("R", P(0, 0, 0)))
    assert path(text) == want


@covers("M98", "M99")
def test_subprogram_call_and_repeats():
    # [0i] "Subprogram": "M98 P L ;" calls O P L times; "M98 P51002 ;" (more than four digits) calls
    # O1002 five times.  "M99 P n" returns to block N n of the calling program.
    #   M98 P1002 L3        X 10, 20, 30 (O1002: G91 G00 X10. ; M99)
    #   M98 P21002          X 40, 50
    #   M98 P1003           O1003 moves Y by 1 and returns with M99 P30: N20 is skipped, N30 runs
    text = ("O0001\nG90 G00 X0\nM98 P1002 L3\nM98 P21002\nN10 M98 P1003\nN20 G90 G00 X100.0\nN30 G90 G00 X0\nM30\n"
            "O1002\nG91 G00 X10.0\nM99\nO1003\nG91 G00 Y1.0\nM99 P30\n")
    assert ends(text) == [P(10, 0, 0), P(20, 0, 0), P(30, 0, 0), P(40, 0, 0), P(50, 0, 0), P(50, 1, 0), P(0, 1, 0)]


@covers("M97")
def test_haas_local_subprogram():
    # [Haas] "M97 Local Sub-Program Call": "M97 P n L" runs the block N n of the same program up to its
    # M99, L times, then returns to the block after the call.
    text = "O0001\nG90 G00 X0\nM97 P100 L2\nG90 G00 Y5.0\nM30\nN100 G91 G00 X7.0\nM99\n"
    assert ends(text) == [P(7, 0, 0), P(14, 0, 0), P(14, 5, 0)]


@covers("M02", "M30")
@pytest.mark.parametrize("end", ["M02", "M30"])
def test_program_end(end):
    # [0i] "Miscellaneous function": M02 / M30 end the main program; no block after them is executed.
    assert ends(f"G90 G00 X10.0\n{end}\nG00 X20.0\n") == [P(10, 0, 0)]


# ----------------------------------------------------------------------------- coverage


def modelled_codes(text: str) -> set[str]:
    """The codes specs/fanuc.md marks modelled: of its G code table, the canned cycle table, the calls
    and the M codes, every code of a row whose treatment is not **unknown**, harmless or **error**."""
    codes: set[str] = set()
    section = None
    for line in text.splitlines():
        if line.startswith("## ") or line.startswith("### "):
            section = line.strip("# ").split(" (")[0]
            continue
        if section not in ("G codes", "Canned cycles", "Calls", "M codes") or not line.startswith("| "):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if section == "G codes":
            if len(cells) < 3 or not cells[1].startswith("G"):
                continue
            names, treatment = cells[1], cells[2]
        else:
            names, treatment = cells[0], cells[-1] if section != "Calls" else cells[1]
        if treatment.startswith(("**unknown**", "harmless", "**error**", "treatment", "---")) or \
                treatment == "":
            continue
        for token in re.split(r",\s*|\s+", names.replace("`", "")):
            m = re.fullmatch(r"([GM])(\d+(?:\.\d)?)(?:[–-]\1?(\d+))?", token)
            if m is None:
                continue
            if m.group(3) is None:
                codes.add(m.group(1) + m.group(2))
            else:
                width = len(m.group(2))
                codes |= {f"{m.group(1)}{k:0{width}d}" for k in range(int(m.group(2)), int(m.group(3)) + 1)}
    return codes


def test_the_spec_reader_finds_the_tables():
    codes = modelled_codes(SPEC.read_text(encoding="utf-8"))
    # a few of each table, and none of the rows marked unknown or harmless
    assert {"G00", "G43", "G81", "G73", "M98", "G65", "M30", "G54", "G59", "G84.2"} <= codes
    assert not {"G41", "G31", "G87", "G61", "M00", "M03", "G22"} & codes


def test_every_modelled_code_has_a_golden():
    from . import test_manual_lathe_examples as lathe

    covered = set(COVERED) | set(lathe.COVERED)
    missing = sorted(modelled_codes(SPEC.read_text(encoding="utf-8")) - covered)
    assert not missing, f"modelled in specs/fanuc.md without a golden from the manual: {missing}"
