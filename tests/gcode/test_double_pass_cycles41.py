"""The double pass's canned cycles of cyc41 (issue 36; nczones/gcode/linuxcnc/double_cycles.py): G20 hole lines
from the cycle's template, levels equal to R by value (``G0 Z2`` then ``G98 G81 ... R2``).

The pass's invariant (``check_against_full``: the full path runs the program with no note, as many motions,
rapids and dwells, every motion in the pass's box) on fixed programs, and that the rows came the way they
were meant to (a hole line from the template, not the general path).
"""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import double_cycles
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from tests.gcode.rs274_arc_programs import in_plane
from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion
from tests.gcode.test_double_pass import MACHINE, check_against_full, machines
from tests.gcode.test_rs274_double_cycles import SETUP
from tests.machines import load_machine

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "100"))
#: G54 and G55 of different Z, tool lengths H1 and H2
TOOLS = load_machine("mill_g54_g55_h1_h2")

#: G20 programs whose hole lines (X and Y words, L; no R, bottom, P or Q) take the template; per program, how
#: many cycle blocks run the general path (the first of each cycle, and a line that writes R or Z).
G20_HOLES = {
    "G90 G81 and G82": ("G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z1\nG98 G81 X1 Y1 Z-0.1 R0.1\nX[#1 * 3] Y0.5\n"
                        "X2\nY[#1 + 0.25] L2\nG99 G82 X1 Z-0.2 R0.05 P0.5\nX[#1 * 7]\nY-1.3\nG80\nM30\n", 2),
    "G91 with L": ("G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z1\nG91 G99 G81 X0.5 Y0.1 Z-0.3 R-0.5\nX[#1] L3\n"
                   "Y-0.2\nX-0.05 Y[#1 / 3] L4\nG90 G80\nM30\n", 1),
    "pecks": ("G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z1\nG99 G83 X1 Y1 Z-0.5 R0.1 Q0.07\nX2\nX[#1 + 3] L2\n"
              "G98 G73 Y2 R0.1 Z-0.5 Q[#1]\nX4\nY[#1 * 9]\nG80\nM30\n", 2),
    "G55, G85 and G89": ("G20 G90 G17 G55 F10\n#1 = 0.25\nG0 X0 Y0 Z2\nG98 G85 X1 Y1 Z-0.3 R0.2\n"
                                   "X[#1]\nX0.3 Y0.4\nG99 G89 X1 Z-0.1 R0.3 P0.2\nY[#1]\nG80\nM30\n", 2),
}


@pytest.mark.parametrize("name", sorted(G20_HOLES))
def test_g20_hole_lines_from_the_template(name, monkeypatch):
    text, general = G20_HOLES[name]
    calls = []
    run = double_cycles.Cycles._general

    def counted(self, *args):
        calls.append(args)
        return run(self, *args)

    monkeypatch.setattr(double_cycles.Cycles, "_general", counted)
    path = check_against_full(text, MACHINE)
    assert path is not None, "declined"
    assert len(calls) == general  # (every other hole line: the template's rows)


# -- R equal to the level before it by value (G0 Z2, then G98 G81 ... R2) -------------------------------------

#: Literals of one value written apart (and two of equal doubles but different exact values: 0.3 and
#: 0.30000000000000001), an expression of the same value.
LEVELS = ["2", "2.0", "[2]", "02.000", "+2", "0.3", "0.30000000000000001", "[#1]", "[1 + 1]", "0.3", "2"]
#: What comes between the move to the level and the cycle: moves that keep the normal axis where it is, and
#: moves, offsets, units and cycles that change what its level is.
BETWEEN = ["", "", "G0 X3 Y4", "G1 X1 F50", "G91 G0 Z0", "G91 G0 Z0.1\nG0 Z-0.1\nG90", "G55", "G20", "G21",
           "G2 X1 Y0 I0.5 J0", "G0 Z2 (comment)", "G99 G81 X1 Y1 Z-1 R5\nG80", "G98 G81 X1 Y1 Z-1 R2\nG80",
           "G0 Z0.3 X1", "G43 H1", "G1 Z[#1] F50", "G99 G81 X1 Y1 Z-1 R2\nG80\nG0 X3 Y4",
           "G98 G81 X1 Y1 Z-1 R5\nG80\nG1 X2 F50", "G99 G81 X1 Y1 Z-1 R2\nG80\nG0 Z5 X1",
           "G99 G81 X1 Y1 Z-1 R2\nG80\nG91 G0 X1 Z0\nG90"]


@st.composite
def by_value_programs(draw) -> str:
    """A move to a level (a literal or an expression, G90 or G91), what comes between, then cycles whose R is
    written as that level (or another), their hole lines, G80 and again."""
    head = draw(st.sampled_from(["G21 G90 G17 G54 F100", "G20 G90 G17 G54 F10", "G21 G90 G17 G55 F100"]))
    lines = [head, "#1 = 2", f"G0 X0 Y0 Z{draw(st.sampled_from(LEVELS))}"]
    for _ in range(draw(st.integers(1, 3))):
        lines += draw(st.sampled_from(BETWEEN)).split("\n")
        code = draw(st.sampled_from(["G81", "G82 P0.5", "G83 Q0.4", "G73 Q0.7", "G85", "G89 P0.2"]))
        retract = draw(st.sampled_from(["G98", "G99", "G98"]))
        lines.append(f"G90 {retract} {code} X1 Y1 Z-1 R{draw(st.sampled_from(LEVELS))}")
        lines += [draw(st.sampled_from(["X2", "Y3 L2", "X[#1] Y1", "G98 X4", "G99 X5"]))
                  for _ in range(draw(st.integers(0, 2)))]
        lines += draw(st.sampled_from([["G80"], ["G80", f"G0 Z{draw(st.sampled_from(LEVELS))}"], []]))
    return "\n".join(line for line in [*lines, "M30"] if line) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(by_value_programs(), st.one_of(st.just(TOOLS), machines(tools=True)))
def test_levels_equal_by_value_are_enclosed_by_the_full_interpreter(text, machine):
    check_against_full(text, machine)


#: Programs the pass takes since cyc41 (it declined them: "canned cycle levels too close to compare exactly").
BY_VALUE = {
    "G98, R the initial level": "G21 G90 G17 G54 F100\nG0 Z2\nG98 G81 X1 Y1 Z-1 R2\nX2\nM30\n",
    "an XY move between, written apart": "G21 G90 G17 G54 F100\nG0 Z2.0\nG0 X5 Y3\nG98 G81 X1 Y1 Z-1 R2\nX2\n"
                                         "G99 X3\nM30\n",
    "G99, a comment": "G21 G90 G17 G54 F100\nG0 Z2 (c)\nG99 G81 X1 Y1 Z-1 R2\nX2\nM30\n",
    "G20 pecks": "G20 G90 G17 G54 F100\nG0 Z0.3\nG98 G83 X1 Y1 Z-1 R0.3 Q0.2\nX2\nM30\n",
    "a bracketed literal": "G21 G90 G17 G54 F100\nG0 Z[0.3]\nG98 G81 X1 Y1 Z-1 R0.3\nX2\nM30\n",
    "G18": "G21 G90 G18 G54 F100\nG0 Y2\nG98 G81 X1 Z1 Y-1 R2\nX2\nM30\n",
    "a tool length": "G21 G90 G17 G54 F100\nG43 H1 G0 Z20\nG98 G81 X1 Y1 Z-3 R20\nX2\nM30\n",
    # the same words, other levels: another offset, other units, a G91 move, a cycle since (each level's token
    # must say so, or the pass takes the levels equal and its rows are not the full path's)
    "another offset": "G21 G90 G17 G54 F100\nG0 Z2\nG55\nG98 G81 X1 Y1 Z-1 R2\nX2\nM30\n",
    "other units": "G21 G90 G17 G54 F100\nG0 Z2\nG20\nG98 G81 X1 Y1 Z-1 R2\nX2\nM30\n",
    "a G91 move": "G21 G90 G17 G54 F100\nG0 Z1\nG91 G0 Z2\nG90 G98 G81 X1 Y1 Z-1 R2\nX2\nM30\n",
    # the clear level a cycle left the tool at (XY moves since), R written as it again
    "a cycle's clear level": "G21 G90 G17 G54 F100\nG0 Z20\nG99 G81 X1 Y1 Z-1 R2\nX2\nG80\nG0 X0 Y0\nM3 S100\n"
                             "G99 G84 X3 Z-1 R2\nX4\nM30\n",
    "a G98 cycle's clear level": "G21 G90 G17 G54 F100\nG0 Z20\nG98 G81 X1 Y1 Z-1 R2\nG80\nG1 X0 Y0 F50\n"
                                 "G98 G83 X3 Z-1 R20 Q2\nX4\nM30\n",
    "a cycle since": "G21 G90 G17 G54 F100\nG0 Z2\nG99 G81 X1 Y1 Z-1 R5\nG80\nG0 X0\nG98 G81 X1 Y1 Z-1 R2\nX2\n"
                     "M30\n",
}


@pytest.mark.parametrize("name", sorted(BY_VALUE))
def test_levels_equal_by_value(name):
    path = check_against_full(BY_VALUE[name], TOOLS)
    assert path is not None, "declined"


#: Levels the pass cannot tell equal (their doubles are): still declined.
NOT_BY_VALUE = {
    "equal doubles of different values": "G21 G90 G17 G54 F100\nG0 Z0.3\nG98 G81 X1 Y1 Z-1 R0.30000000000000001\n",
    "an expression": "G21 G90 G17 G54 F100\nG0 Z[0.1 * 3]\nG98 G81 X1 Y1 Z-1 R0.30000000000000004\n",
    "a G91 move to it": "G21 G90 G17 G54 F100\nG0 Z2\nG91 G0 Z0\nG90 G98 G81 X1 Y1 Z-1 R2\n",
    "a G91 move after a cycle": "G21 G90 G17 G54 F100\nG0 Z5\nG99 G81 X1 Y1 Z-1 R5.0\nG80\nG91 G0 X1 Z0\n"
                                "G90 G98 G81 X1 Y1 Z-1 R5\n",
}


@pytest.mark.parametrize("name", sorted(NOT_BY_VALUE))
def test_levels_not_known_equal_decline(name):
    with pytest.raises(Declined, match="too close"):
        double_pass(NOT_BY_VALUE[name], TOOLS, max_iterations=100)


# -- G73 and G83 in G91 ------------------------------------------------------------------------------------

#: Where the tool stands before the cycle (its initial level: a literal, an expression, the end of a G91 chain)
STARTS = ["G0 Z5", "G0 Z[#1 * 3]", "G0 Z2.1", "G0 Z5\nG91 G0 Z0.1\nG0 Z-0.3\nG90", "G0 Z0.30000000000000004",
          "G0 Z[#2 / 3]"]
#: R above or below the initial level, and bottoms a whole number of pecks below R (LinuxCNC's count in doubles:
#: one more or one less than the exact count where a double falls a hair off), give or take
PECK_LEVELS = [("-1", "-0.3", "0.1"), ("-1", "-2.1", "0.7"), ("0.5", "-0.9", "0.3"), ("[#2]", "-[#1]", "0.1"),
               ("-0.2", "-0.7", "[#1 / 3]"), ("-1", "-1.2", "0.4"), ("-0.1", "-3", "1")]


@st.composite
def g91_peck_programs(draw) -> str:
    head = draw(st.sampled_from(["G21 G90 G17 G54 F100", "G20 G90 G17 G54 F10", "G21 G90 G17 G55 G43 H1 F100"]))
    lines = [head, "#1 = 0.7", "#2 = 0.1"]
    for _ in range(draw(st.integers(1, 2))):
        lines += draw(st.sampled_from(STARTS)).split("\n")
        r, z, q = draw(st.sampled_from(PECK_LEVELS))
        code, retract = draw(st.sampled_from(["G83", "G73"])), draw(st.sampled_from(["G98", "G99"]))
        lines.append(f"G91 {retract} {code} X0.5 Y0.25 Z{z} R{r} Q{q}{draw(st.sampled_from(['', ' L2', ' L3']))}")
        lines += [draw(st.sampled_from(["X1", "Y-0.5 L2", "X[#2] Y1", "G98 X0.1", f"Z{z} X0.1"]))
                  for _ in range(draw(st.integers(0, 2)))]
        lines.append("G90 G80")
    plane = draw(st.sampled_from([17, 17, 18, 19]))
    if plane != 17:
        lines = [lines[0].replace("G17", f"G{plane}"), *(in_plane(line, plane) for line in lines[1:])]
    return "\n".join([*lines, "M30"]) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(g91_peck_programs(), st.one_of(st.just(TOOLS), machines(tools=True)))
def test_g91_pecks_are_enclosed_by_the_full_interpreter(text, machine):
    check_against_full(text, machine)


G91_PECKS = {
    "G83": "G21 G90 G17 G54 F100\nG0 Z5\nG91 G99 G83 X1 Y1 Z-1 R-1 Q0.5\nX1\nY2 L3\nG90 G80\nM30\n",
    "G73 from an expression's level": "G21 G90 G17 G54 F100\n#1 = 0.7\nG0 Z[#1 * 3]\n"
                                      "G91 G98 G73 X1 Y1 Z-2.1 R-1 Q0.7 L2\nX1\nG90 G80\nM30\n",
    "G20": "G20 G90 G17 G54 F10\nG0 Z0.5\nG91 G99 G83 X0.1 Y0.1 Z-0.3 R-0.2 Q0.1\nX0.1 L2\nG90 G80\nM30\n",
    "moved in G21, drilled in G20": "G21 G90 G17 G54 F100\nG0 Z5\nG20\nG91 G99 G83 X0.1 Y0.1 Z-0.3 R-0.2 Q0.1\n"
                                    "X0.1 L2\nG90 G80\nM30\n",
    "from a G91 chain": "G21 G90 G17 G55 F100\nG0 Z5\nG91 G0 Z0.1\nG99 G83 X1 Y1 Z-1 R-1 Q0.5\nX1\n"
                        "G90 G80\nM30\n",
}


@pytest.mark.parametrize("name", sorted(G91_PECKS))
def test_g91_pecks(name):
    for machine in (MACHINE, TOOLS):
        path = check_against_full(G91_PECKS[name], machine)
        assert path is not None, "declined"


# -- LinuxCNC's rs274 on the new cases ------------------------------------------------------------------------

#: (rs274 runs with no work offsets: G54 here is the machine frame)
RS274 = {
    "G20 hole lines": G20_HOLES["G90 G81 and G82"][0],
    "G20 G91 with L": G20_HOLES["G91 with L"][0],
    "R equal to the level by value": "G21 G90 G17 G54 F100\n#1 = 2\nG0 Z2.0\nG0 X5 Y3\nG98 G81 X1 Y1 Z-1 R2\n"
                                     "X[#1]\nG99 X3\nG80\nG0 Z0.3\nG98 G83 X1 Z-1 R0.3 Q0.4\nX2\nG80\nM30\n",
    "G91 pecks": "G21 G90 G17 G54 F100\n#1 = 0.7\nG0 X0 Y0 Z[#1 * 3]\nG91 G98 G73 X1 Y1 Z-2.1 R-1 Q0.7 L2\nX1\n"
                 "G99 G83 Y1 Z-1.2 R-1 Q0.4 L2\nG90 G80\nM30\n",
    "G91 pecks in G20": G91_PECKS["G20"],
}


@NEEDS_RS274
@pytest.mark.parametrize("name", sorted(RS274))
def test_the_pass_is_rs274s_motion(name, tmp_path):
    assert_the_pass_is_rs274s_motion(RS274[name], SETUP, tmp_path)
