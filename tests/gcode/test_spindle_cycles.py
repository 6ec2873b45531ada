"""G33 threading, G33.1 rigid tapping: geometry of LinuxCNC's spindle-synchronized moves."""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.errors import GcodeError
from nczones.gcode import segments_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from tests.machines import machine_text

F = Fraction
MILL = parse_machine(machine_text("mill_xyz", extra='[offsets]\nG54 = { X = "100", Y = "0", Z = "50" }\n'))


def test_g33_is_a_straight_line_to_the_end_point_with_k_as_pitch():
    segs = segments_text("G20 G0 X1 Z0.1\nS100 M3\nG33 Z-2 K0.025\nG33 X1.1 Z-2.5 K0.05\nG0 X1.25\n", MILL)
    assert [(s.kind, s.end) for s in segs[1:3]] == [
        (SegmentKind.LINE, (F(100) + F("25.4"), F(0), F(50) - F("50.8"))),
        (SegmentKind.LINE, (F(100) + F("27.94"), F(0), F(50) - F("63.5"))),
    ]
    assert segs[1].feed_mm_min is None and segs[1].derived == "G33 thread"


def test_g33_1_taps_to_the_end_and_returns_to_the_start():
    segs = segments_text("G0 X0 Y0 Z1\nS1000 M3\nG33.1 Z-1.2 K0.1\nG0 X5\n", MILL)
    start = (F(100), F(0), F(51))
    assert [(s.kind, s.start, s.end) for s in segs[1:3]] == [
        (SegmentKind.LINE, start, (F(100), F(0), F(50) - F("1.2"))),
        (SegmentKind.LINE, (F(100), F(0), F(50) - F("1.2")), start),
    ]
    assert segs[3].start == start and segs[3].end == (F(105), F(0), F(51))


def test_g91_g33_1_is_relative_to_the_start():
    segs = segments_text("G0 X0 Y0 Z1 M3 S100\nG91 G33.1 Z-2 K1\nG33.1 Z-3 K1\n", MILL)
    assert [s.end[2] for s in segs[1:]] == [F(49), F(51), F(48), F(51)]


def test_g33_without_k_is_an_error_any_k_value_is_not():
    with pytest.raises(GcodeError) as e:
        segments_text("G0 Z1\nG33 Z-1\n", MILL)
    assert e.value.diagnostics[0].code == "GC208"
    # LinuxCNC takes any K (rs274 runs G33 K0, G33 K-1, G33.1 K0); only a missing K is refused
    for k in ("K0", "K-1"):
        segs = segments_text(f"G0 Z1 M3 S100\nG33.1 Z-1 {k}\n", MILL)
        assert [s.end[2] for s in segs[1:]] == [F(49), F(51)]


def test_g84_in_g18_and_g19_moves_as_linuxcnc_really_does():
    # LinuxCNC's G84 outside G17 feeds with the other vertical plane's axis order (its canon logs
    # tests/interp/g84/g18, g19); the next move starts where the machine is, aimed from where
    # the interpreter believes it is.
    text = "G18 G98 G0 X0 Y2 Z0 M3 S100\nG84 X1 Z1 Y-1 R1 F10\nG0 X5\n"
    segs = [s for s in segments_text(text, MILL) if s.kind is not SegmentKind.DWELL]
    ends = [(s.kind, s.end) for s in segs]
    assert ends == [
        (SegmentKind.RAPID, (F(100), F(2), F(50))),
        (SegmentKind.RAPID, (F(101), F(2), F(51))),  # position: X=1 Z=1 at the initial level Y=2
        (SegmentKind.RAPID, (F(101), F(1), F(51))),  # to R
        (SegmentKind.LINE, (F(100) - 1, F(1), F(51))),  # X <- bottom Y-1, Y <- Z1, Z <- X1
        (SegmentKind.LINE, (F(102), F(1), F(51))),  # X <- clear Y2
        (SegmentKind.RAPID, (F(105), F(2), F(51))),  # from the believed (1, 2, 1) in program terms
    ]
    assert segs[-1].start == (F(102), F(1), F(51))
    assert all(a.end == b.start for a, b in zip(segs, segs[1:]))  # the path stays continuous

    segs = [s for s in segments_text("G19 G99 G0 X2 Y0 Z0 M3 S100\nG84 Y1 Z2 X0.5 R3 F10\n", MILL)
            if s.kind is SegmentKind.LINE]
    # G19: X <- Z value, Y <- the X-direction depth, Z <- Y value
    assert [s.end for s in segs] == [(F(102), F("0.5"), F(51)), (F(102), F(3), F(51))]


M73_SUB = """o100 sub
  M73
  G90 G20
  G0 X1
o100 endsub
o200 sub
  M73
  G90
  o201 if [#1 EQ 1]
    M71
  o201 endif
o200 endsub
"""


def test_m73_restores_the_modal_state_when_the_subroutine_returns():
    text = M73_SUB + "G53 G0 X0 Y0 Z0\nG21 G91\no100 call\nG0 X1\no100 call\no100 call\nG0 X[#<_incremental> * 7]\n"
    xs = [s.end[0] for s in segments_text(text, MILL)]
    # in the sub: G90 G20 X1 = machine 100 + 25.4; after the return: G21 G91 again (+1 mm, then +7 mm);
    # two calls in a row (no block in between) restore each time
    assert xs == [F(0), F(100) + F("25.4"), F(100) + F("26.4"), F(100) + F("25.4"), F(100) + F("25.4"),
                  F(100) + F("32.4")]


def test_m71_cancels_the_m73_restore_of_its_frame():
    text = M73_SUB + "G53 G0 X0 Y0 Z0\nG91\no200 call [0]\nG0 X1\no200 call [1]\nG0 X1\n"
    xs = [s.end[0] for s in segments_text(text, MILL)]
    assert xs == [F(0), F(1), F(101)]  # restored to G91 after the first call, still G90 after the second


def test_m73_in_the_main_program_saves_like_m70():
    """LinuxCNC at call level 0: "M73 at top level: nothing to return to; storing context anyway" (convert_m);
    rs274 then restores it at M72: G0 X5, G91 X1 (6), M72 (G90), X1 (1)."""
    xs = [s.end[0] for s in segments_text("G53 G0 X0 Y0 Z0\nG0 X5\nM73\nG91\nG0 X1\nM72\nG0 X1\nM2\n", MILL)]
    assert [x - 100 for x in xs[1:]] == [F(5), F(6), F(1)]  # G54 X is 100
