"""Motion and errors where nczones differed from LinuxCNC's interpreter, found by ``tests/tools/rs274_diff.py``.

Each expectation is LinuxCNC 2.9's ``rs274 -g`` canonical output of the same program, written out by hand
(program coordinates; with G54 = 0, no G92 and no tool length they are the machine coordinates). The
differential run that found them, and what it compares, is in ``specs/gcode-support.md``
("Differential run against LinuxCNC").
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

MACHINE_TEXT = machine_text("box_100_clamp_parity")
MACHINE = parse_machine(MACHINE_TEXT)


def motion(text: str) -> list[tuple]:
    """(kind, X, Y, Z) of every segment; dwells as ("DWELL", seconds)."""
    run = interpret_text(text, MACHINE)
    out: list[tuple] = []
    for c in run:
        for s in c.segments():
            if s.kind.name == "DWELL":
                out.append(("DWELL", s.dwell_s))
            else:
                out.append((s.kind.name, *s.end))
    assert not run.unsupported, run.unsupported
    return out


def _rows(rows):
    return [(r[0], *(Fraction(v) for v in r[1:])) for r in rows]


def test_canned_cycles_retract_to_r_until_g98():
    """LinuxCNC starts in G99 (``interp_setup.cc``: ``retract_mode(R_PLANE)``); nczones retracted to the
    initial level as if G98 were active, and so proved the move to the next hole 1 mm above where it runs."""
    assert motion("F100\nG81 X5 Y0 Z-3 R-1\nG81 X10 Z-3 R-1\nM2\n") == _rows([
        ("RAPID", 5, 0, 0), ("RAPID", 5, 0, -1), ("LINE", 5, 0, -3), ("RAPID", 5, 0, -1),
        ("RAPID", 10, 0, -1), ("LINE", 10, 0, -3), ("RAPID", 10, 0, -1)])


def test_the_move_between_holes_through_a_clamp_is_unsafe():
    """The wrong `safe`: after the first hole the tool travels at R = -1 (G99), through the clamp at X 7..8
    whose top is Z -0.5; nczones had it travel at the initial level Z 0, above the clamp."""
    result = verify_text("F100\nG81 X5 Y0 Z-3 R-1\nX10\nM2\n", MACHINE)
    assert result.verdict.label == "unsafe"
    assert {v.zone for v in result.violations} == {"clamp"}


def test_g98_still_retracts_to_the_initial_level():
    assert motion("F100\nG98 G81 X5 Y0 Z-3 R-1\nX10\nM2\n")[-4:] == _rows([
        ("RAPID", 10, 0, 0), ("RAPID", 10, 0, -1), ("LINE", 10, 0, -3), ("RAPID", 10, 0, 0)])


def test_g83_backs_out_to_r_between_pecks():
    """``convert_cycle_g83``: each peck rapids out to R, not to the clear level (G98 initial level here)."""
    assert motion("F100\nG98 G83 X7 Y0 Z-2.5 R-0.5 Q1\nM2\n") == _rows([
        ("RAPID", 7, 0, 0), ("RAPID", 7, 0, "-0.5"), ("LINE", 7, 0, "-1.5"), ("RAPID", 7, 0, "-0.5"),
        ("RAPID", 7, 0, "-1.246"), ("LINE", 7, 0, "-2.5"), ("RAPID", 7, 0, 0)])


def test_g85_feeds_out_to_r_then_rapids_to_the_clear_level():
    """``convert_cycle_g85``: feed to the bottom, feed back to R, rapid to the clear level."""
    assert motion("F100\nG98 G85 X6 Y0 Z-6 R-2\nM2\n") == _rows([
        ("RAPID", 6, 0, 0), ("RAPID", 6, 0, -2), ("LINE", 6, 0, -6), ("LINE", 6, 0, -2), ("RAPID", 6, 0, 0)])


def test_g84_dwells_the_p_of_an_earlier_cycle():
    """``convert_cycle_xy``: G84's dwell is its P word or the sticky P of any earlier cycle (here G82's)."""
    rows = motion("F100\nM3 S1000\nG82 X1 Z-3 R1 P0.5\nG84 X2 Z-3 R1\nM2\n")
    assert [r for r in rows if r[0] == "DWELL"] == [("DWELL", Fraction(1, 2)), ("DWELL", Fraction(1, 2))]


def test_changing_the_active_rotation_with_g92_applied_is_unknown():
    """``convert_setup`` re-derives the position as rotate(program) + G5x while the canon layer rotates
    program + G92: rs274 aims ``G3 X[#<_x>-0.32]`` from X -0.1717 where the machine is at X -0.15 + ..., so
    any relative move afterwards goes elsewhere than nczones would compute."""
    run = interpret_text("G0 X2 Y3\nG92 X0 Y0\nG10 L2 P1 X1 R10\nG91 G0 X1\nM2\n", MACHINE)
    segs = [s for c in run for s in c.segments()]
    assert len(segs) == 1
    assert [(u.code, u.span.line) for u in run.unsupported] == [("G10 L2 R", 3)]
    # without G92, or keeping the rotation, LinuxCNC's interpreter stays where the machine is
    for text in ("G0 X2 Y3\nG10 L2 P1 X1 R10\nG91 G0 X1\nM2\n", "G0 X2 Y3\nG92 X0 Y0\nG10 L2 P1 X1\nG91 G0 X1\nM2\n"):
        run = interpret_text(text, MACHINE)
        assert len([s for c in run for s in c.segments()]) == 2 and not run.unsupported


def _error(text: str, fast: bool = True) -> GcodeError:
    with pytest.raises(GcodeError) as info:
        for _ in interpret_text(text, MACHINE, fast=fast):
            pass
    return info.value


#: Programs LinuxCNC refuses, the line it names and its message (rs274's stderr).
REFUSED = [
    ("F100\nG94\nG1 X1\nM2\n", 3, "Cannot do g1 with zero feed rate"),
    ("F100\nG95 S100 M3\nG1 X1\nM2\n", 3, "Cannot do g1 with zero feed rate"),
    ("F100\nG94\nG2 X2 I1\nM2\n", 3, "Cannot make arc with zero feed rate"),
    ("F100\nG94\nG0 X1\nG81 X1 Z-1 R0\nM2\n", 4, "Cannot feed with zero feed rate"),
    ("G1\nM2\n", 1, "Cannot do g1 with zero feed rate"),
    ("G95 F1\nG1 X1\nM2\n", 2, "Cannot feed with zero spindle speed in feed per rev mode"),
    ("F10 M3 S10\nG95\nG1 X1 F1\nS0\nG1 X2\nM2\n", 5, "Cannot feed with zero spindle speed in feed per rev mode"),
    ("G93 G1 X1 F10\nG1 X2\nM2\n", 2, "F word missing with inverse time g1 move"),
    ("G93 F10\nG2 X2 I1\nM2\n", 2, "F word missing with inverse time arc move"),
    ("G10 L1 P0 Z1\nM2\n", 1, "P value out of range with G10 L1"),
    ("G10 L10 P0 Z1\nM2\n", 1, "P value out of range with G10 L10"),
    ("G10 L11 P0 Z1\nM2\n", 1, "P value out of range with G10 L11"),
    ("G10 L20 P1 X0 R1\nM2\n", 1, "R not allowed in G10 L20"),
    ("G52\nM2\n", 1, "All axes missing with g52 or g92"),
    ("S-1\nM2\n", 1, "Negative spindle speed used"),
    ("G33 X1 K1\nM2\n", 1, "Spindle not turning in G33"),
    ("M4 S100\nT1 M6\nG33 X1 K1\nM2\n", 3, "Spindle not turning in G33"),
    ("M3 S100\nM19\nG33 X1 K1\nM2\n", 3, "Spindle not turning in G33"),
    ("M3 S100\nM5\nG33.1 Z-1 K1\nM2\n", 3, "Spindle not turning in G33.1"),
    ("F10\nG86 X1 Z-1 R1 P1\nM2\n", 2, "Spindle not turning in g86"),
    ("F10 M4 S100\nG84 X1 Z-1 R1\nM2\n", 2, "Spindle turning counterclockwise in G84"),
    # (abort, ...) stops the program with its text, before the block's motion (rs274 prints STRAIGHT_TRAVERSE(1)
    # only); nczones read it as a message and proved the motion after it
    ("G21 G0 X1\n(abort, stop here)\nG0 X2\nM2\n", 2, "stop here"),
    ("G21 G0 X1\nG0 X2 (ABORT,now)\nM2\n", 2, "now"),
]

#: Programs LinuxCNC runs through (the same features, in the state it accepts).
ACCEPTED = [
    "F100\nG94 F20\nG1 X1\nM2\n",
    "F100\nG95 F1 S100\nG1 X1\nG1 X2 S200 M3\nM2\n",
    "G93 G1 X1 F10\nG1 X2 F20\nG2 X4 I1 F5\nM2\n",
    "G10 L1 P1 Z1\nG10 L10 P2 Z1\nG10 L11 P3 Z1\nM2\n",
    "F10 M3 S100\nG84 X1 Z-1 R1\nM5\nM3\nG84 X2\nM2\n",
    "F10 M3 S100\nG86 X1 Z-1 R1 P1\nM2\n",
    "F10\nM3 S100\nM70\nM5\nM72\nG84 X1 Z-1 R1\nM2\n",  # M72 restores the spindle (not followed)
    "M3 S100\nG33 X1 K1\nM2\n",
]


@pytest.mark.parametrize("fast", [True, False], ids=["lanes", "general"])
@pytest.mark.parametrize("text,line,linuxcnc", REFUSED, ids=[r[2] + f" {k}" for k, r in enumerate(REFUSED)])
def test_what_linuxcnc_refuses_nczones_refuses_on_the_same_line(text, line, linuxcnc, fast):
    """Until these checks nczones verified the motion of such programs as if the controller ran it."""
    err = _error(text, fast)
    assert err.diagnostics[0].span is not None and err.diagnostics[0].span.line == line, (err.render(), linuxcnc)


@pytest.mark.parametrize("fast", [True, False], ids=["lanes", "general"])
@pytest.mark.parametrize("text", ACCEPTED)
def test_what_linuxcnc_runs_nczones_runs(text, fast):
    run = interpret_text(text, MACHINE, fast=fast)
    for _ in run:  # raises GcodeError where nczones refuses
        pass
    assert not run.unsupported


def test_the_lanes_see_spindle_and_feed_words_of_long_runs():
    """The vectorized run and the plain lane follow S, M3/M4/M5 and G94's zeroed feed like the general path."""
    moves = "".join(f"X{i} Y1\n" for i in range(40))
    for head, tail, line in [
        ("M3 S100 F10\n", "G95\nG1 X1\n", 43),           # G95 zeroes the feed
        ("F10 G95\nS100\n", "S0\nG1 X3\n", 44),           # S0 in G95
        ("F10\nM3 S100\n", "M5\nG86 X1 Z-1 R1 P1\n", 44),  # stopped by M5 in a run
        ("F10\nM3 S100\nG1\n", "M4\nG84 X1 Z-1 R1\n", 45),  # M4 in a run of plain moves
    ]:
        text = head + "G1 " + moves + tail + "M2\n"
        for fast in (True, False):
            err = _error(text, fast)
            assert err.diagnostics[0].span.line == line, (head, tail, fast, err.render())


def test_a_tool_length_change_between_holes_moves_the_initial_level_with_it():
    """LinuxCNC keeps a modal cycle's initial level in program coordinates (``cycle_il``): after ``G43.1 Z-8``
    the next hole's first move goes up to R = 2 at the old hole, in program terms, which is machine Z -6, and
    the tool travels to the next hole there. nczones kept the level in machine coordinates and had it travel
    at machine Z 2 (8 mm above where it runs)."""
    rows = motion("F100\nG81 X5 Y0 Z-3 R2\nG43.1 Z-8\nX10\nM2\n")
    assert rows[4:] == _rows([("RAPID", 5, 0, -6), ("RAPID", 10, 0, -6), ("LINE", 10, 0, -11), ("RAPID", 10, 0, -6)])


def test_a_g92_change_between_holes_moves_the_g98_level_with_it():
    rows = motion("F100\nG98 G81 X5 Y0 Z-3 R-1\nG92 Z4\nX10\nM2\n")
    # rs274: to (10, 0, 4), (10, 0, -1), (10, 0, -3), back to the initial level 0, all with G92 Z -4
    assert rows[4:] == _rows([("RAPID", 10, 0, 0), ("RAPID", 10, 0, -5), ("LINE", 10, 0, -7), ("RAPID", 10, 0, -4)])


def test_g43_h0_is_the_tool_in_the_spindle():
    """LinuxCNC's ``find_tool_index`` reads tool 0 as the spindle's table entry: after ``T3 M6``, ``G43 H0`` applies
    tool 3's length (rs274: ``USE_TOOL_LENGTH_OFFSET(0 0 50.8)`` for a 2 inch tool 3). nczones applied 0."""
    machine = parse_machine(MACHINE_TEXT + '[tool_lengths]\nH1 = "25.4"\nH3 = "50.8"\n')
    run = interpret_text("F10\nT3 M6\nG43 H0\nG1 X1 Z0\nM2\n", machine)
    segs = [s for c in run for s in c.segments()]
    assert [(s.end[2], s.tool_length) for s in segs] == [(Fraction("50.8"), Fraction("50.8"))]


@pytest.mark.parametrize("text,feeds", [
    ("F100\nG0 Z1.1015\nG99 G73 X0 Y0 Z[#<_z>-0.28] R[#<_z>] Q0.04\nM2\n", 7),  # nczones pecked once more
    ("F100\nG0 Z14.5315\nG99 G73 X1 Y0 Z[#<_z>-6] R[#<_z>+5] Q1\nM2\n", 12),  # nczones pecked once less
])
def test_pecks_are_counted_as_linuxcnc_counts_them(text, feeds):
    """LinuxCNC's G73/G83 loop (``for (d = r - q; d > bottom; d -= q)``) runs in doubles: where the bottom is a
    whole number of pecks below R, it pecks once more or once less than exact arithmetic would. rs274 prints
    ``feeds`` STRAIGHT_FEEDs for these programs (the pecks and the last feed to the bottom)."""
    assert sum(1 for r in motion(text) if r[0] == "LINE") == feeds


def test_g43_after_t0_m6_unloaded_a_tool_is_unknown():
    """rs274 applies the unloaded tool 4's length to ``G43`` after ``T4 M6`` ``T0 M6`` (its spindle slot keeps the
    entry); nczones applied 0. Unknown until the controller's behaviour there is pinned down."""
    machine = parse_machine(MACHINE_TEXT + '[tool_lengths]\nH4 = "98.9076"\n')
    run = interpret_text("F500\nT4 M6\nT0 M6\nG1 X-0.652 Z-1\nG43\nG1 X1 Y0 Z-1.472\nM2\n", machine)
    assert len([s for c in run for s in c.segments()]) == 1
    assert [(u.code, u.span.line) for u in run.unsupported] == [("G43", 5)]
    run = interpret_text("F500\nM61 Q4\nG43\nG1 X1 Z-1\nM2\n", machine)  # rs274: length 0, the slot's entry
    assert [s for c in run for s in c.segments()] == []
    assert [(u.code, u.span.line) for u in run.unsupported] == [("G43", 3)]
    run = interpret_text("F500\nG43\nG1 X1 Z-1\nM2\n", machine)  # never loaded: length 0, as rs274
    assert [s.end[2] for c in run for s in c.segments()] == [-1] and not run.unsupported


def test_a_plane_change_between_cycle_blocks_reads_the_initial_level_on_the_new_axis():
    """LinuxCNC's initial level is one program number: after G17 cycles at Z 5 (tool length 25.4 mm), a G19 cycle
    retracts X to 5 (rs274: ``STRAIGHT_TRAVERSE(5, 3, 0)``). nczones carried the machine Z level (30.4) over to X."""
    machine = parse_machine(MACHINE_TEXT + '[tool_lengths]\nH1 = "25.4"\n')
    run = interpret_text("F10\nG43 H1\nG0 Z5\nG98 G81 X0 Y0 Z-1 R1\nG19\nG81 X-1 Y3 Z0 R1\nM2\n", machine)
    ends = [s.end for c in run for s in c.segments()][-4:]
    assert ends == [tuple(Fraction(v) for v in e) for e in
                    [(5, 3, "25.4"), (1, 3, "25.4"), (-1, 3, "25.4"), (5, 3, "25.4")]]


@pytest.mark.parametrize(("text", "rows"), [
    # rs274 -g: STRAIGHT_TRAVERSE(1, 0, 0) for both orders
    ("G21 G90 G0 G80 X1\nM2\n", [("RAPID", 1, 0, 0)]),
    ("G21 G90 G80 G0 X1\nM2\n", [("RAPID", 1, 0, 0)]),
    ("G21 G90 G1 G80 X1 F100\nM2\n", [("LINE", 1, 0, 0)]),
    ("G21 G90 G80 G80\nM2\n", []),
    # the cycle runs: STRAIGHT_TRAVERSE to R, over the hole, STRAIGHT_FEED down, back to R (G99)
    ("G21 G90 G80 G81 X1 Z-1 R1 F100\nM2\n", [("RAPID", 0, 0, 1), ("RAPID", 1, 0, 1), ("LINE", 1, 0, -1),
                                              ("RAPID", 1, 0, 1)]),
    # G80 G1 after a cycle: the G1 block feeds to X2 at Z1 (rs274: STRAIGHT_FEED(2, 0, 1))
    ("G21 G90 G81 X1 Z-1 R1 F100\nG80 G1 X2\nM2\n", [("RAPID", 0, 0, 1), ("RAPID", 1, 0, 1), ("LINE", 1, 0, -1),
                                                    ("RAPID", 1, 0, 1), ("LINE", 2, 0, 1)]),
])
def test_g80_beside_another_motion_code_is_dropped(text, rows):
    """LinuxCNC's ``read_g`` (``interp_read.cc``) drops a G80 written beside another motion-group code, in either
    order, and takes ``G80 G80`` as G80; nczones refused every such block (GC201), among them the corpus's
    ``G00 G17 G21 G40 G49 G80 G90`` start-up lines. Expected rows: rs274's canonical output."""
    assert motion(text) == _rows(rows)


@pytest.mark.parametrize(("text", "code", "column"), [
    ("G21 G90 G0 G1 X1\nM2\n", "GC201", 12),  # rs274: "Two g codes used from same modal group"
    ("G21 G90 G0 X2\nG80 G80 X1\nM2\n", "GC205", 9),  # rs274: "Cannot use axis values with g80"
])
def test_motion_codes_linuxcnc_refuses_together(text, code, column):
    with pytest.raises(GcodeError) as info:
        motion(text)
    d = info.value.diagnostics[0]
    assert (d.code, d.span.column) == (code, column)


def test_a_g80_beside_g0_is_checked_as_the_rapid():
    """The block's rapid is proved like any other: into the clamp it is unsafe."""
    assert verify_text("G21 G90 G0 G80 X7.5 Z-1\nM2\n", MACHINE).verdict.label == "unsafe"
    assert verify_text("G21 G90 G80 G0 X6.5 Z-1\nM2\n", MACHINE).verdict.label == "safe"


def _near(rows, want):
    """Rows within rs274's printed 4 decimals (polar ends are LinuxCNC's doubles)."""
    return len(rows) == len(want) and all(g[0] == w[0] and all(abs(a - b) <= Fraction(1, 20000)
                                                               for a, b in zip(g[1:], w[1:]))
                                          for g, w in zip(rows, want))


@pytest.mark.parametrize("fast", [True, False], ids=["lanes", "general"])
@pytest.mark.parametrize(("text", "rows"), [
    # rs274 -g: STRAIGHT_TRAVERSE(1, 0, 0), STRAIGHT_FEED(7.5, 0, -1): into the clamp at X 7..8
    ("G21 G90 G0 X1\nG1 @7.5 ^0 Z-1 F10\nM2\n", [("RAPID", 1, 0, 0), ("LINE", "7.5", 0, -1)]),
    # STRAIGHT_TRAVERSE(5, 0, -1), STRAIGHT_FEED(0, 5, -1): G91 turns the angle about the origin
    ("G21 G90 G0 X5 Z-1\nG91 G1 ^90 F10\nM2\n", [("RAPID", 5, 0, -1), ("LINE", 0, 5, -1)]),
    # STRAIGHT_FEED(0, 4, 0): G91 adds the radius first, then the angle
    ("G21 G90 G0 X5\nG91 G1 ^90 @-1 F10\nM2\n", [("RAPID", 5, 0, 0), ("LINE", 0, 4, 0)]),
    # STRAIGHT_FEED(200, 0, 0): out of travel
    ("G21 G90 G0 X1\nG1 @200 F10\nM2\n", [("RAPID", 1, 0, 0), ("LINE", 200, 0, 0)]),
    # ARC_FEED(0, 5, 0, 0, 1, 0): the arc's end in polar form
    ("G21 G90 G0 X3 Y4\nG3 @5 ^90 I-3 J-4 F10\nM2\n", [("RAPID", 3, 4, 0), ("ARC", 0, 5, 0)]),
])
def test_polar_coordinates_move_x_and_y(text, rows, fast):
    """LinuxCNC's ``@`` (radius) and ``^`` (angle) words give the end of X and Y (``find_ends``,
    ``interp_find.cc``, in doubles; in G91 about the program origin from where the tool is). nczones read
    them as words and ignored them: such a block moved nothing, and ``G1 @200 F10`` was proved `safe` on a
    100 mm machine (the corpus's ``spiral.ngc`` lost its 800 moves)."""
    run = interpret_text(text, MACHINE, fast=fast)
    got = [(s.kind.name, *s.end) for c in run for s in c.segments()]
    assert not run.unsupported
    assert _near(got, _rows(rows)), got


def test_a_polar_move_into_the_clamp_is_unsafe():
    assert verify_text("G21 G90 G0 X1\nG1 @7.5 ^0 Z-1 F10\nM2\n", MACHINE).verdict.label == "unsafe"
    assert verify_text("G21 G90 G0 X1\nG1 @200 F10\nM2\n", MACHINE).verdict.label == "unsafe"


def test_a_canned_cycle_drills_at_the_polar_point():
    """``convert_cycle_xy``: rs274 -g STRAIGHT_TRAVERSE(5, 0, 2), (0, 5, 2), (0, 5, 1), STRAIGHT_FEED(0, 5, -1),
    STRAIGHT_TRAVERSE(0, 5, 1)."""
    assert _near(motion("G21 G90 G0 X5 Z2\nG81 @5 ^90 Z-1 R1 F10\nM2\n"), _rows([
        ("RAPID", 5, 0, 2), ("RAPID", 0, 5, 2), ("RAPID", 0, 5, 1), ("LINE", 0, 5, -1), ("RAPID", 0, 5, 1)]))


def test_a_g91_cycle_repeated_with_polar_steps_is_unknown():
    """With L, LinuxCNC turns the angle again on every repeat (``CYCLE_MACRO``): not modelled."""
    run = interpret_text("G21 G90 G0 X5 Z2\nG91 G81 R-1 Z-3 ^60 L6 F10\nM2\n", MACHINE)
    segs = [s for c in run for s in c.segments()]
    assert [(u.code, u.span.line) for u in run.unsupported] == [("@ ^", 2)] and len(segs) == 1


@pytest.mark.parametrize(("text", "line"), [
    ("G21 G90 G0 X0 Y0\nG1 @5 F10\nM2\n", 2),  # rs274: Must specify angle in polar coordinate if at the origin
    ("G21 G91 G1 ^5 F10\nM2\n", 1),  # G91 motion with polar coordinates is indeterminate when at the origin
    ("G21 G90 G1 X1 @5 F10\nM2\n", 1),  # Cannot specify both polar coordinate and X word
    ("G21 G18\nG1 @5 ^1 F10\nM2\n", 2),  # Cannot use polar coordinate except in G17 plane
    ("G21 G90 G0 X5 Z2\nG28 @1\nM2\n", 2),  # Polar coordinates can only be used for motion
    ("G21 G90 G0 X5 Z2\nG80\n@5 F10\nM2\n", 3),  # Cannot use axis values without a g code that uses them
])
def test_polar_coordinates_linuxcnc_refuses(text, line):
    assert _error(text).diagnostics[0].span.line == line


COMP_MACHINE = parse_machine(MACHINE_TEXT.replace('pulse = "0.0001"\n', 'pulse = "0.0001"\ncutter_compensation = "linuxcnc"\n')
                             + '[tool_diameters]\nT1 = "2.54"\nT2 = "5.08"\n')


@pytest.mark.parametrize("fast", [True, False], ids=["lanes", "general"])
@pytest.mark.parametrize(("head", "y"), [("", "0"), ("T2 M6\n", "2.54"), ("T1 M6\n", "1.27")])
def test_g41_d0_is_the_tool_in_the_spindle(head, y, fast):
    """``convert_cutter_compensation_on`` reads D0 through ``find_tool_index``, where tool 0 is the spindle's
    table entry (index 0, as for H0); nczones took D0 as tool number 0 and compensated by radius 0 with a
    5.08 mm tool in the spindle, so the path it proved lay 2.54 mm off the path LinuxCNC cuts.  Rows: rs274 -g
    with the tool table T1 D0.1, T2 D0.2 (inches): STRAIGHT_FEED(10, Y), (20, Y), (30, 0)."""
    text = f"G21 F100\n{head}G0 X0 Y0 Z0\nG41 D0 G1 X10 Y0\nG1 X20\nG40 G1 X30\nM2\n"
    run = interpret_text(text, COMP_MACHINE, fast=fast)
    rows = [(s.kind.name, *s.end) for c in run for s in c.segments()]
    assert not run.unsupported
    want = _rows([("LINE", 10, y, 0), ("LINE", 20, y, 0), ("LINE", 30, 0, 0)])
    got = [r for r in rows if r[0] == "LINE"]  # compensated in LinuxCNC's doubles; rs274 prints 4 decimals
    assert len(got) == len(want) and all(abs(a - b) <= Fraction(1, 20000) for g, w in zip(got, want)
                                         for a, b in zip(g[1:], w[1:])), (got, want)


@pytest.mark.parametrize("fast", [True, False], ids=["lanes", "general"])
@pytest.mark.parametrize(("mid", "y"), [("T2 M6", "1.27"), ("M61 Q2", "1.27"), ("M5", "0")])
def test_a_tool_change_after_g40_rereads_where_the_tool_is(mid, y, fast):
    """After G40 LinuxCNC's interpreter holds the programmed point while the tool stands at the compensated one
    (``convert_cutter_compensation_off``); a tool change (M6, M61) makes it re-read the real position
    (``read_inputs``: ``refresh_actual_position``), so a following Z move stays at the compensated XY. nczones
    moved back to the programmed point, a rapid 1.27 mm off the one the machine makes (the corpus's
    ``useful-subroutines.ngc``). Rows: rs274 -g, tool table T1 D0.1, T2 D0.2 (inches); without the tool change
    the rapid does go to Y 0."""
    text = f"G21 F100\nT1 M6\nG0 X0 Y0 Z0\nG41 G1 X10 Y0\nG1 X20\nG40\n{mid}\nG0 Z5\nM2\n"
    run = interpret_text(text, COMP_MACHINE, fast=fast)
    rows = [(s.kind.name, *s.end) for c in run for s in c.segments()]
    assert not run.unsupported
    want = _rows([("RAPID", 0, 0, 0), ("LINE", 10, "1.27", 0), ("LINE", 20, "1.27", 0), ("RAPID", 20, y, 5)])
    assert len(rows) == len(want) and all(g[0] == w[0] and all(abs(a - b) <= Fraction(1, 20000)
                                                               for a, b in zip(g[1:], w[1:]))
                                          for g, w in zip(rows, want)), (rows, want)


@pytest.mark.parametrize("switch", ["G21\n", "M72\n"])
def test_a_units_change_under_a_modal_cycle_keeps_the_initial_level_as_a_number(switch):
    """LinuxCNC's convert_length_units converts the positions and offsets, not a modal cycle's initial level
    (``cycle_il``): after G20 cycles from Z 3.2044 in, the next hole in mm retracts to Z 3.2044 mm. rs274:
    ``STRAIGHT_TRAVERSE(5, 25.4, 81.3918)``, ``(5, 25.4, 2)``, ``STRAIGHT_FEED(5, 25.4, -2)``,
    ``STRAIGHT_TRAVERSE(5, 25.4, 3.2044)``. nczones retracted to 81.39176 mm, where the level had been."""
    head = "G21 G17 G90 G98 F100\nM70\n" if switch == "M72\n" else "G17 G90 G98 F100\n"
    rows = motion(head + "G20\nG0 X1 Y1 Z3.2044\nG81 X2 Z-2.0 R2\n" + switch + "X5\nM2\n")
    assert rows[-4:] == _rows([("RAPID", 5, "25.4", "81.39176"), ("RAPID", 5, "25.4", 2),
                               ("LINE", 5, "25.4", -2), ("RAPID", 5, "25.4", "3.2044")])


def test_the_low_retract_after_a_units_change_runs_into_the_clamp():
    """The wrong ``safe``: the hole at X5 Y0 retracts to Z 3.2044 mm (not 81 mm), and the G0 X7.5 after it
    travels at that level; with a clamp whose top is Z 5 there, the program is unsafe."""
    machine = parse_machine(MACHINE_TEXT.replace('max = { X = "100", Y = "100", Z = "100" }',
                                                 'max = { X = "100", Y = "100", Z = "200" }')
                            .replace('max = { X = "8", Y = "5", Z = "-0.5" }', 'max = { X = "8", Y = "5", Z = "5" }'))
    text = "G17 G90 G98 F100\nG20\nG0 X0 Y0 Z3.2044\nG81 X0.1 Z-0.05 R0.1\nG21\nX5 Y0\nG80\nG0 X7.5\nM2\n"
    result = verify_text(text, machine)
    assert result.verdict.label == "unsafe"
    assert {v.zone for v in result.violations} == {"clamp"}


def test_polar_words_meet_ranges_and_the_double_pass():
    """Where polar words meet other features: under a ``--param`` range the polar end is unknown, never proved
    at the nominal values; in a parametric program the double pass declines (``@`` is outside its subset) and
    the full path finds the move out of travel."""
    text = "G21 G90 G0 X1\nG1 @5 ^0 F10\nM2\n"
    assert verify_text(text, MACHINE).verdict.label == "safe"
    ranged = verify_text(text, MACHINE, params=["G54.X=-1..1"])
    assert ranged.verdict.label == "unknown" and any("polar" in r.message for r in ranged.reasons)
    parametric = verify_text("#1 = 40\nG21 G90 G54 F10\nG1 X1\nG1 @[#1 * 5] ^0\nM2\n", MACHINE)
    assert parametric.verdict.label == "unsafe" and parametric.violations[0].line == 4
