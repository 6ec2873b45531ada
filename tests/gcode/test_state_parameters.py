"""State parameters a program reads (#5221, #5420, #<_abs_x> ...): filled from the machine file and the
interpreter's state, following parameter ranges, or unknown (issue 18, item 4)."""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.gcode import interpret_text as interpret
from nczones.gcode.linuxcnc.state import linuxcnc_state_parameters
from nczones.machine import load_machine, parse_machine
from nczones.prover import parse_param
from nczones.prover import verify_text as verify
from tests.machines import machine_text

F = Fraction
MILL_FILE = "specs/machines/mill.toml"

MILL = parse_machine(machine_text("mill_start_all_offsets"))


def reads(program: str, machine=MILL, **options) -> list[Fraction]:
    """The X end point of every segment: a program writes what it read as ``G53 G0 X[...]``."""
    run = interpret(program, machine, **options)
    out = [s.end[0] for s in run.segments()]
    assert not run.unsupported, run.unsupported
    return out


def read_value(expr: str, before: str = "", machine=MILL) -> Fraction:
    x = reads(f"{before}\nG90 G53 G0 X[{expr}]\nM30\n", machine)[-1]
    return x / F("25.4") if "G20" in before else x


@pytest.mark.parametrize(("expr", "value"), [
    ("#5221", 100), ("#5222", 0), ("#5223", 50),          # G54 from the machine file
    ("#5241", 200), ("#5242", 10), ("#5243", 60),         # G55
    ("#5381", -7), ("#5383", -9),                         # G59.3
    ("#5261", 0),                                         # G56: not in the file, zero
    ("#5224", 0),                                         # G54 A: the machine has no A axis
    ("#5230", 0),                                         # G54 rotation
    ("#5161", 1), ("#5162", 2), ("#5163", 400),           # G28 position = reference
    ("#5181", 1), ("#5183", 400),                         # G30 position = reference
    ("#5210", 0), ("#5211", 0),                           # no G92 at the start
    ("#5220", 1),                                         # G54 active
    ("#5400", 0), ("#5403", 0),                           # no tool in the spindle
    ("#5420", -95), ("#5421", 6), ("#5422", 250),         # start position in G54
    ("#<_x>", -95), ("#<_abs_x>", 5), ("#<_abs_z>", 300),
    ("#<_coord_system>", 540), ("#<_metric>", 1), ("#<_absolute>", 1), ("#<_plane>", 170),
    ("#<_motion_mode>", 800), ("#<_tool_offset>", 0), ("#<_current_tool>", 0),
    # LinuxCNC starts in G99 (interp_setup.cc: retract_mode(R_PLANE)); the machine file names neither
    ("#<_retract_old_z>", 0), ("#<_retract_r_plane>", 1),
])
def test_state_parameters_read_the_machine_file(expr, value):
    assert read_value(expr) == value


@pytest.mark.parametrize(("before", "expr", "value"), [
    ("G55", "#5220", 2),
    ("G59.3", "#<_coord_system>", 593),
    ("G10 L2 P1 X12.5", "#5221", F("12.5")),
    ("G10 L2 P2 R30", "#5250", 30),
    ("G0 X10 Y20 Z30", "#5420", 10),
    ("G0 X10 Y20 Z30\nG92 X0", "#5211", 10),         # machine 110 - G54 100 - 0
    ("G0 X10 Y20 Z30\nG92 X0", "#5210", 1),
    ("G0 X10 Y20 Z30\nG92 X0\nG92.2", "#5210", 0),
    ("G0 X10 Y20 Z30\nG92 X0\nG92.2", "#5211", 10),    # kept for G92.3
    ("G0 X10 Y20 Z30\nG92 X0\nG92.1", "#5211", 0),
    ("G0 X10 Y20 Z30\nG28.1", "#5161", 110),
    ("G0 X10 Y20 Z30\nG30.1", "#5182", 20),
    ("T2 M6", "#5400", 2),
    ("T2 M6", "#5403", F("95.5")),                     # tool table = machine file tool lengths
    ("T2 M6", "#5410", 6),
    ("T1 M6\nG10 L1 P1 Z50", "#5403", 50),             # G10 L1 rewrites the loaded tool's entry
    ("T1 M6\nG43", "#<_tool_offset>", 1),
    ("T1 M6\nG43\nG0 Z0", "#<_abs_z>", 170),
    ("G20\nG0 X1", "#5420", 1),                        # program units
    ("G20\nG0 X1", "#<_abs_x>", F("125.4") / F("25.4")),  # machine position, program units
    ("G20", "#5221", 100),                             # stored offsets: machine units (mm)
    ("G91", "#<_incremental>", 1),
    ("G99", "#<_retract_r_plane>", 1),
    ("G98", "#<_retract_r_plane>", 0),  # LinuxCNC starts in G99
    ("G1 F250", "#<_feed>", 250),
    ("G18", "#<_plane>", 180),
])
def test_state_parameters_follow_the_interpreter(before, expr, value):
    assert read_value(expr, before) == value


def test_reproducer_g54_read_then_g53_move_is_unsafe():
    """The issue's reproducer: #5221 read 0, so ``G53 G0 X[#5221 * 4 + 1]`` was proved safe; it moves to X601."""
    machine = load_machine(MILL_FILE)
    result = verify("G21 G90\nG53 G0 X[#5221 * 4 + 1]\nM30\n", machine)
    assert result.verdict.label == "unsafe"
    assert result.violations[0].line == 2 and result.violations[0].zone == "travel"
    assert reads("G53 G0 X[#5221 * 4 + 1]\nM30\n", machine) == [601]


def test_a_read_that_depends_on_a_range_is_unknown_at_the_read():
    machine = load_machine(MILL_FILE)
    program = "G21 G90\nG0 X0 Y0\nG53 G0 X[#5221 + 1]\nG0 X1\nM30\n"
    result = verify(program, machine, params=["G54.X=-1..1"])
    assert result.verdict.label == "unknown"
    (reason,) = result.reasons
    assert reason.code == "GC395" and reason.span.line == 3 and reason.span.column == 8
    assert "G54.X" in reason.message
    # a range the read does not depend on keeps the proof
    assert verify(program, machine, params=["G54.Y=-1..1"]).verdict.label == "safe"
    # nothing after the read is emitted: a violation after it is not reported from a nominal value
    bad = "G21 G90\nG53 G0 X[#5221 + 1]\nG53 G0 X700\nM30\n"
    assert verify(bad, machine, params=["G54.X=-1..1"]).verdict.label == "unknown"


@pytest.mark.parametrize(("program", "param", "unknown"), [
    ("G0 X10\nG53 G0 X[#5420 + 100]\n", "G54.X=-1..1", False),    # program position: the offset cancels
    ("G53 G0 X10\nG0 Y[#5420 + 100]\n", "G54.X=-1..1", True),     # machine X10 in G54: depends on G54.X
    ("G0 X10\nG53 G0 X[#<_abs_x> - 100]\n", "G54.X=-1..1", True),  # machine position follows G54.X
    ("G0 X10\nG53 G0 X[#<_abs_y> + 1]\n", "G54.X=-1..1", False),
    ("G53 G0 X[#<_abs_x> + 1]\n", "start.X=-1..1", True),
    ("G53 G0 X[#<_abs_y> + 1]\n", "start.X=-1..1", False),
    ("T1 M6\nG53 G0 X[#5403]\n", "H1=110..130", True),
    ("T1 M6\nG10 L1 P1 Z50\nG53 G0 X[#5403]\n", "H1=110..130", False),
    ("G0 X10\nG28.1\nG53 G0 X[#5161]\n", "G54.X=-1..1", True),
    ("G0 X10\nG92 X0\nG92.2\nG53 G0 X[#5211 + 1]\n", "G54.X=-1..1", False),  # machine - G54: cancels
    ("G53 G0 X10\nG92 X0\nG92.2\nG53 G0 X[#5211 + 1]\n", "G54.X=-1..1", True),
])
def test_range_dependencies_follow_the_state(program, param, unknown):
    ranges = (parse_param(param, MILL),)
    run = interpret(program + "M30\n", MILL, param_ranges=ranges)
    list(run.segments())
    assert bool(run.unsupported) is unknown, run.unsupported
    if unknown:
        assert run.unsupported[0].code == "GC395" and param.split("=")[0] in run.unsupported[0].reason


def test_g28_1_and_g92_3_keep_the_dependencies_of_what_they_stored():
    """G28 goes to a position G28.1 stored from a position that depends on G54.X; G92.3 restores a G92
    offset computed from it: both carry the dependency on to the segments."""
    ranges = (parse_param("G54.X=-1..1", MILL),)
    run = interpret("G0 X10\nG28.1\nG0 X50\nG28\nM30\n", MILL, param_ranges=ranges)
    home = [s for s in run.segments() if s.derived == "G28 home"][0]
    assert home.deps_end[0] == ("G54",)
    run = interpret("G53 G0 X10\nG92 X0\nG92.2\nG92.3\nG0 X5\nM30\n", MILL, param_ranges=ranges)
    last = list(run.segments())[-1]
    assert last.end[0] == 15 and last.deps_end[0] == ()   # X = 5 + G92 (10 - 0 - G54.X) + G54.X


@pytest.mark.parametrize("expr", ["#5061", "#5070", "#5399", "#5411", "#5600", "#<_spindle_on>", "#<_rpm>",
                                  "#<_feed_override>", "#<_vmajor>", "#5410"])
def test_state_nczones_does_not_model_is_unknown(expr):
    run = interpret(f"G0 X1\nG53 G0 X[{expr}]\nM30\n", MILL)
    segs = list(run.segments())
    assert len(segs) == 1  # the move before the read
    (u,) = run.unsupported
    assert u.code == "GC395" and u.span.line == 2 and "does not model" in u.reason


# (#<_x> = 2 is LinuxCNC's error "Cannot assign to read-only parameter": tests/gcode/test_rs274_language.py)
@pytest.mark.parametrize("assign", ["#5221 = 3", "#5161 = 0", "#5420 = 1", "#5400 = 1"])
def test_assigning_state_is_unknown(assign):
    for program in (f"G0 X1\n{assign}\nG0 X2\nM30\n", f"G0 X1\n{assign} G0 X2\nM30\n"):
        run = interpret(program, MILL)
        segs = list(run.segments())
        assert len(segs) == 1
        assert run.unsupported[0].code == "GC395" and run.unsupported[0].span.line == 2


def test_the_table_covers_the_linuxcnc_state_parameters():
    table = linuxcnc_state_parameters()
    numbered = {k for k in table if isinstance(k, int)}
    expected = (set(range(5021, 5030)) | set(range(5061, 5071)) | set(range(5081, 5090))
                | set(range(5161, 5170)) | set(range(5181, 5190)) | set(range(5210, 5220))
                | {5220} | {5221 + 20 * n + k for n in range(9) for k in range(10)}
                | {5399} | set(range(5400, 5414)) | set(range(5420, 5429)) | {5600, 5601})
    # #5599, the (DEBUG,) flag, is an ordinary parameter that starts at 1: tests/gcode/test_debug_flag.py
    assert numbered == expected
    from nczones.gcode.expr import PREDEFINED

    named = {k for k in table if isinstance(k, str)}
    assert PREDEFINED - named <= {"_value", "_value_returned"}


@pytest.mark.parametrize("program", ["G0 X10 Y20 Z30\nG0 X[#5021]\n", "T1 M6\nG43\nG0 X[#5083]\n",
                                     "G0 X[#5081]\n", "G0 X[#5029]\n"])
def test_5021_and_5081_are_version_dependent(program):
    """rs274 of LinuxCNC 2.9.0~pre1 (the installed reference, tests/gcode/data/rs274_findings/param-5021.ngc):
    ``(debug, #5021)`` after ``G0 X10`` prints 0.000000 and ``#5083`` after ``T1 M6 G43 H1`` (Z 0.519 inch in
    the tool table) prints 0.000000; newer LinuxCNC reads the position and the applied length.  A program
    that moves by them is ``unknown`` (GC395), not proved for one version."""
    run = interpret(program + "M30\n", MILL)
    list(run.segments())
    assert [u.code for u in run.unsupported] == ["GC395"], run.unsupported
    assert "version-dependent" in run.unsupported[0].reason
