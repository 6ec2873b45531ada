"""Wrong `safe` verdicts found by the issue-18 review, each as the reproducer that showed it.

Every range verdict is also replayed at concrete values with an independently built machine
(``concrete``): a range's `unsafe` witness must be unsafe there, and the fixed machines the review
used must give the verdicts it expected.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.gcode import interpret_text as interpret
from nczones.machine import load_machine, parse_machine
from nczones.prover import parse_param
from nczones.prover import verify_text as verify
from tests.machines import box_zone, machine_text
from tests.oracles.concrete import machine_at

F = Fraction


def concrete(machine, **values):
    """The machine with parameters fixed (``G54_X=1``: deviation; ``H1=115``: absolute; ``start_X=-1``)."""
    return machine_at(machine, {k.replace("_", "."): F(v) for k, v in values.items()})


def witness_values(result) -> dict[str, Fraction]:
    return {name.replace(".", "_"): value for name, value in result.violations[0].params}


# ----------------------------------------------------------------------------- 1. dogleg rapids

DOGLEG_TEXT = machine_text("dogleg_post")
DOGLEG = parse_machine(DOGLEG_TEXT, "dogleg.toml")
DOG_MOVE = "G21 G90 G54\nG0 X100 Y0\nM30\n"
DOG_HOME = "G21 G90 G54\nG0 X105\nG0 Y-5\nG28\nM30\n"   # the G28 home leg runs diagonally through the post


@pytest.mark.parametrize(("program", "param", "line"), [
    (DOG_MOVE, None, 2), (DOG_MOVE, "G54.X=-1..1", 2), (DOG_MOVE, "start.X=-1..1", 2),
    (DOG_HOME, None, 4), (DOG_HOME, "G54.Y=-1..1", 4),
])
def test_dogleg_rapid_with_ends_on_different_parameters_is_unsafe(program, param, line):
    """A dogleg rapid whose ends depend on different parameters was checked along one diagonal of the
    per-axis box: `safe`.  Its breakpoints move with the parameters; the encoding is now exact."""
    result = verify(program, DOGLEG, params=[param] if param else [])
    assert result.verdict.label == "unsafe"
    v = result.violations[0]
    assert v.line == line and v.zone == "post"
    if param:
        assert verify(program, concrete(DOGLEG, **witness_values(result))).verdict.label == "unsafe"


def test_dogleg_with_ranges_is_not_over_reported():
    """The exact encoding proves what the box hull of the ends could not: the path passes the post's
    corner diagonally for every offset in the range."""
    m = parse_machine(DOGLEG_TEXT.replace('X = "75", Y = "15"', 'X = "20", Y = "20"')
                      .replace('X = "85", Y = "25"', 'X = "30", Y = "30"'))
    result = verify(DOG_MOVE, m, params=["G54.X=-1..1"])   # diagonal x + y = 100 +- 1 misses the post
    assert result.verdict.label == "safe", result.reasons
    for dx in (-1, 0, 1):
        assert verify(DOG_MOVE, concrete(m, G54_X=dx)).verdict.label == "safe"


# ----------------------------------------------------------------------------- 2. tool lengths the program writes

TOOL_PROGRAM = "G21 G90 G54\nG10 L1 P1 Z50\nG43 H1\nG0 Z100\nG0 X-30 Y0\nG1 Z20 F100\nG0 Z100\nM30\n"


@pytest.mark.parametrize("param", ["H1=100..110", "H1=130..150", None])
def test_a_tool_length_the_program_wrote_ignores_the_machine_files_range(param):
    """``G10 L1 P1 Z50`` then ``G43 H1``: the length is 50 whatever the machine file's H1 is.  The range's
    deviation was added to 50 (the tip of a 50 mm tool in the vise was proved safe for H1=100..110)."""
    mill = load_machine("specs/machines/mill.toml")
    result = verify(TOOL_PROGRAM, mill, params=[param] if param else [])
    assert result.verdict.label == "unsafe"
    assert [v.line for v in result.violations] == [6, 7] and result.violations[0].zone == "vise"
    run = interpret(TOOL_PROGRAM, mill, track_dependencies=True)
    assert {s.deps_tool for s in run.segments()} == {()}
    run = interpret("G43 H1\nG0 Z100\nM30\n", mill, track_dependencies=True)
    assert [s.deps_tool for s in run.segments()] == [("H1",)]


# ----------------------------------------------------------------------------- 3. canned cycles branch on R

CYCLE_TEXT = machine_text("cycle_clamp_g61")
CYCLE = parse_machine(CYCLE_TEXT, "cycle.toml")
# R (machine) = 81 + 100 + H1: above the initial level 300 for H1 > 119 (the cycle climbs to R and moves over
# the clamp at tip level 181), below it for H1 < 119 (it moves at the initial level: tip 300 - H1, in the
# clamp for 110 < H1 < 117)
CYCLE_PROGRAM = "G21 G90 G54 G17\nG43 H1\nG98 G81 X100 Y0 Z-10 R81 F100\nG80\nM30\n"


@pytest.mark.parametrize(("h1", "label"), [(115, "unsafe"), (111, "unsafe"), (110, "safe"), (117, "safe"),
                                          (119, "safe"), (120, "safe"), (150, "safe")])
def test_the_cycle_at_fixed_tool_lengths(h1, label):
    assert verify(CYCLE_PROGRAM, concrete(CYCLE, H1=h1)).verdict.label == label


@pytest.mark.parametrize(("nominal", "param", "label"), [
    (120, "H1=100..150", "unsafe"),   # the review's case: R above the initial level at the nominal value
    (121, "H1=100..150", "unsafe"),   # another nominal value gave a witness the machine never reached
    (105, "H1=100..150", "unsafe"),
    (120, "H1=100..112", "unsafe"),   # nominal outside the range; the initial level had the tool's dependency
    (120, "H1=100..110", "safe"),
    (120, "H1=119..150", "safe"),     # the switching value itself, and above it
    (120, "H1=130..150", "safe"),
    (120, "H1=117..119", "safe"),
])
def test_a_cycle_whose_branch_switches_inside_the_range(nominal, param, label):
    """The cycle was built once at the nominal H1 and every level got the offset's and tool's
    dependencies (the initial level too, a machine position): `safe` over H1=100..150 while H1=115 is
    unsafe.  Now the range is split at the switching value and each side built with its own branch."""
    machine = concrete(CYCLE, H1=nominal)
    result = verify(CYCLE_PROGRAM, machine, params=[param])
    assert result.verdict.label == label, (result.violations, result.reasons)
    if label == "unsafe":
        (h1,) = [v for k, v in result.violations[0].params if k == "H1"]
        lo, hi = (F(x) for x in param.split("=")[1].split(".."))
        assert lo <= h1 <= hi and 110 < h1 < 117
        assert verify(CYCLE_PROGRAM, concrete(CYCLE, H1=h1)).verdict.label == "unsafe"


def test_a_branch_on_two_ranged_parameters_together_is_unknown():
    """R depends on G54.Z and H1, the initial level on neither: the switching set is not a box."""
    result = verify(CYCLE_PROGRAM, CYCLE, params=["H1=100..150", "G54.Z=-30..30"])
    assert result.verdict.label in ("unknown", "unsafe")
    if result.verdict.label == "unknown":
        assert any("together" in r.message for r in result.reasons)


def test_cutter_compensation_from_a_position_that_moves_with_a_range_is_unknown():
    m = parse_machine(machine_text("xy_cutter_comp_g54"))
    prog = "G90 G54\nG41.1 D2 G1 X20 Y10 F100\nX30\nG40 X40\nM30\n"
    assert verify(prog, m).verdict.label == "safe"
    result = verify(prog, m, params=["G54.X=-1..1"])
    assert result.verdict.label == "unknown" and "compensation" in result.reasons[0].message
    # starting from a point of the same frame, the compensated path is a shifted copy: proved
    assert verify("G90 G54\nG0 X0 Y0\n" + prog.split("\n", 1)[1], m, params=["G54.X=-1..1"]).verdict.label == "safe"


# ----------------------------------------------------------------------------- 6. internal errors on valid input

FLAT = parse_machine(machine_text("xy_flat_zone"))


@pytest.mark.parametrize("margin", ["0", "1", "0.001"])
@pytest.mark.parametrize("engine", ["auto", "z3"])
def test_a_flat_forbid_zone_forbids_nothing_with_any_margin(margin, engine):
    """A forbid zone with min = max on an axis has no interior.  The exact tier forgot that once a margin
    was added, disagreed with Z3 and exited 4 ("tier 1 and Z3 disagree")."""
    program = "G90 G0 X0 Y30\nG1 X110 Y60 F100\nG1 X100 Y30\nG1 X115 Y30\nM30\n"
    assert verify(program, FLAT, margin=margin, engine=engine).verdict.label == "safe"
    # the row that is not flat still forbids its interior
    assert verify("G90 G0 X130 Y60\nM30\n", FLAT, margin=margin, engine=engine).verdict.label == "unsafe"




def test_a_spiral_that_grazes_a_face_is_decided_without_an_internal_error():
    """A spiral from radius 10 to 10.002 (inside the arc tolerance) crosses x = 10.001 by about 2e-8 mm just
    past its quarter turn.  Refinement multiplied rationals until one had more than 4,300 digits (exit 4);
    enclosures are now rounded outward to a fixed resolution, and a piece the budget cannot split is
    scanned for a certified witness."""
    def machine(x_max: str):
        # exact path (G61): the rapid's corner with the spiral is proved on boxes that reach the spiral's larger
        # radius (specs/path-modes.md); this test is about the spiral itself
        travel = box_zone("travel", {"X": "-100", "Y": "-100"}, {"X": x_max, "Y": "100"})
        return parse_machine(machine_text("xy_g61_rapid_10000", extra=travel))

    m = machine("10.001")
    program = "G0 X0 Y-10\nG3 X0 Y10.002 I0 J10 F100\nM30\n"
    result = verify(program, m)
    assert result.verdict.label == "unsafe"
    v = result.violations[0]
    assert v.line == 2 and 0 < v.depth < F(1, 10**7) and dict(v.point)["X"] > F("10.001")
    wider = machine("10.0015")
    assert verify(program, wider).verdict.label == "safe"


def test_a_fanuc_cycle_returns_to_the_initial_level_with_its_own_dependencies():
    """The same class in the Fanuc dialect: G98's return to the initial level (here a G53 machine Z) got
    the dependencies of the offsets and tool length, as if it moved with them."""
    machine = parse_machine(CYCLE_TEXT.replace('axes = ["X", "Y", "Z"]', 'axes = ["X", "Y", "Z"]\ndialect = "fanuc"'))
    program = "G21 G90 G54 G17\nG43 H1\nG53 G0 Z300\nG98 G81 X100 Y0 Z-10 R81 F100\nG80\nM30\n"
    run = interpret(program, machine, param_ranges=[parse_param("H1=100..150", machine)])
    legs = {s.derived: s for s in run.segments() if s.derived.startswith("G81")}
    assert legs["G81 retract"].end[2] == 300 and legs["G81 retract"].deps_end[2] == ()
    assert "H1" in legs["G81 to R"].deps_end[2]
    assert not run.unsupported


def test_a_cycle_climbs_to_r_where_the_tool_stands():
    """Found by the metamorphic suite: the climb to R (initial level below R) moves Z only, but its end
    got the hole's X/Y dependencies (G54), so a range of G54.Y moved a point the machine never leaves:
    an `unsafe` whose witness did not replay."""
    program = "G21 G90 G54 G17\nG53 G0 X41 Y0 Z60\nG99 G81 X-9.5 Y1 Z-27 R5.5 F100\nG80\nM30\n"
    run = interpret(program, CYCLE, param_ranges=[parse_param("G54.Y=0.01..0.03", CYCLE)])
    (climb,) = [s for s in run.segments() if s.derived == "G81 up to R"]
    assert climb.start[:2] == climb.end[:2] and climb.deps_end[:2] == climb.deps_start[:2] == ((), ())
    assert climb.deps_end[2] == ("G54",)
