"""The double pass runs canned cycles G81, G82 and G83 in G90 (issue 36; the other forms: test_double_pass_cycles40.py; nczones/gcode/linuxcnc/double_cycles.py).

The module's invariant (``check_against_full``: the full path runs the program with no note, as many motions,
rapids and dwells, every motion in the pass's box, corners blended where the full path blends them) on
generated drilling programs: holes of expressions, R, the bottom and G82's P sticky or written again, G98 and
G99 switched between holes, G80 and a new cycle, the initial level below R, the tool above R, R equal to the
initial level, loops of holes, on machines with offsets and tool lengths, in G17, G18 and G19.  Fixed programs
the pass must take (the benchmark's drilling program among them) and programs it must decline.
"""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from tests.gcode.rs274_arc_programs import in_plane
from tests.gcode.test_double_pass import MACHINE, check_against_full, machines
from tests.machines import load_machine

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "100"))

#: Levels of R (and where the tool stands) and of the bottom: equal values written alike and otherwise,
#: expressions; now and then R below the bottom.
RS = ["2", "2.0", "5", "20", "[#1 + 1]", "[1 + 1]", "0.3", "0.30000000000000001", "[#2 / 3]", "2", "5"]
BOTTOMS = ["-3", "0", "-0.5", "[#2 / 3]", "[#1 * 0.1]", "-[#1]", "-3", "0.3"]
#: G83's pecks (the bottoms are whole numbers of some below some Rs: LinuxCNC's peck count in doubles).
PECKS = ["1", "0.5", "0.7", "[#1 / 3]", "0.1", "2.5", "[#2]"]
#: Hole coordinates.
PLACES = ["1", "-2.5", "[#1 + 4.911]", "[#2 * 7]", "33.72", "[#1 / 3]", "0"]


@st.composite
def hole_line(draw) -> str:
    """A line of a modal cycle: X and/or Y, sometimes R, the bottom, P, a code or the retract mode."""
    words = [f"{a}{draw(st.sampled_from(PLACES))}" for a in draw(st.lists(st.sampled_from("XY"), min_size=1,
                                                                          max_size=2, unique=True))]
    extra = draw(st.sampled_from(["", "", "", "", " R{r}", " Z{z}", " P0.5", " G98", " G99", " F200", " G82 P1",
                                  " G81", " M8", " Z{z} R{r}", " Q{q}", " G83 Q{q}"]))
    return " ".join(words) + extra.format(r=draw(st.sampled_from(RS)), z=draw(st.sampled_from(BOTTOMS)),
                                          q=draw(st.sampled_from(PECKS)))


@st.composite
def cycle_block(draw, label: int) -> list[str]:
    """A first cycle block and its holes, sometimes in a loop, then G80, a motion or nothing."""
    code = draw(st.sampled_from(["G81", "G82", "G82", "G81", "G83", "G83"]))
    retract = draw(st.sampled_from(["G98 ", "G99 ", "G99 ", "G98 ", "G98 ", "G99 ", "G99 ", ""]))
    dwell = f" P{draw(st.sampled_from(['0.5', '[#1]', '1', '1', '0']))}" if code == "G82" else ""
    if code == "G83":  # pecks: a whole number of them below R, give or take, and sticky Q written again
        dwell = f" Q{draw(st.sampled_from(PECKS))}"
    xy = f"X{draw(st.sampled_from(PLACES))} Y{draw(st.sampled_from(PLACES))}"
    if draw(st.integers(0, 5)) == 0:
        xy = ""  # the first hole where the tool stands
    first = f"{retract}{code} {xy} Z{draw(st.sampled_from(BOTTOMS))} R{draw(st.sampled_from(RS))}{dwell}"
    # between holes: a dwell or a tool change moves nothing (the tool stays at the clear level)
    holes = [draw(st.one_of(hole_line(), hole_line(), st.sampled_from(["G4 P0.5", "T1 M6", "M3 S100"])))
             for _ in range(draw(st.integers(0, 4)))]
    if draw(st.integers(0, 3)) == 0:
        holes = ["#3 = 0", f"o{label} while [#3 LT 3]", f"X[#3 * 2 + {draw(st.sampled_from(PLACES))}]",
                 "#3 = [#3 + 1]", f"o{label} endwhile"]
    tail = draw(st.sampled_from([["G80"], ["G80"], ["G0 Z30"], [], ["G1 X0 Y0"], ["G80", "G4 P0.5"], ["G61"]]))
    return [first, *holes, *tail]


@st.composite
def drilling_programs(draw) -> str:
    head = draw(st.sampled_from(["G21 G90 G17 G54 F300", "G21 G90 G17 G55 F100 G0", "G21 G90 G17 G54 G43 H1 F800",
                                 "G21 G90 G17 G54 F300 G64", "G21 G90 G17 G54 G61 F300", "G21 G90 G17 G54 F300",
                                 "G21 G90 G54 F300"]))
    start = draw(st.sampled_from(["G0 Z20", "G0 X0 Y0 Z20", "G0 Z2", "G0 Z-1", "G0 Z[#1 + 1]", "", "G0 Z5 (R)",
                                  "G0 Z30", "G0 X1 Y1 Z25"]))
    body = [line for k in range(draw(st.integers(1, 3))) for line in draw(cycle_block(k + 1))]
    lines = [head, "#1 = 1.5", "#2 = 0.7", start, *body, "M30"]
    plane = draw(st.sampled_from([17, 17, 17, 18, 19]))
    if plane != 17:
        lines = [lines[0].replace("G17", f"G{plane}"), *(in_plane(line, plane) for line in lines[1:])]
    return "\n".join(line for line in lines if line) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(drilling_programs(), machines(tools=True))
def test_cycles_are_enclosed_by_the_full_interpreter(text, machine):
    check_against_full(text, machine)


# -- fixed programs ----------------------------------------------------------------------------------------

ACCEPTED = {
    # bench/bench_gcode.py's drill_expr_program: G99, R on the first hole, G80 and the same R again
    "the benchmark's holes": "G21 G90 G17 G54\nG0 Z20\nG0 X0 Y0\nF300\n#1 = 10\nG99 G81 X1.000 Y1.000 Z-3 R2\n"
                             "X[#1 + 4.911] Y33.720\nX[#1 + 157.135] Y205.159\nG80\nG99 G81 X1.000 Y1.000 Z-3 R2\n"
                             "X[#1 + 55.476] Y33.733\nG80\nM30\n",
    "G98 to the initial level": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z25\nG98 G82 X1 Y1 Z-2 R[#1] P0.5\nX[#1 * 3]\n"
                                "Y[#1 / 3] R3\nG99 X0\nG80\nM30\n",
    "the initial level below R": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z0\nG99 G81 X1 Y1 Z-2 R[#1 + 3]\nX2\nX3 R2\n"
                                 "G80\nG0 Z10\nM30\n",
    "a loop of holes": "G21 G90 G17 G54 F200\n#1 = 0\nG0 Z10\nG98 G81 X0 Y0 Z-1 R1\no1 while [#1 LT 10]\n"
                       "X[#1 * 2.5] Y[#1 * #1 / 7]\n#1 = [#1 + 1]\no1 endwhile\nG80\nM30\n",
    "G18": "G21 G90 G18 G54 F200\n#1 = 2\nG0 Y25\nG99 G81 Z1 X1 Y-2 R[#1]\nZ[#1 * 3]\nG80\nM30\n",
    # R written again with the same exact value (LinuxCNC's and the full path's levels compare equal)
    "R written again": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z25\nG99 G81 X1 Y1 Z-2 R2\nX2 R2.0\nG80\n"
                       "G81 X3 Z-2 R+2.000\nX4 R0.30000000000000001\nX5 R0.30000000000000001\nG80\nM30\n",
    # a motion between two cycles: the tool is no longer at the clear level (a level of the same R's value)
    "a motion between cycles": "G21 G90 G17 G54 F200\nG0 Z25\n#1 = 2\nG99 G81 X1 Y1 Z-2 R2\nG0 Z30\n"
                               "G81 X2 Y2 Z-2 R2\nG1 Z3\nG98 G81 X[#1] Z-2 R2\nM30\n",
    # dwells and a tool change between holes move nothing: the tool stays at the clear level
    "dwells between holes": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z25\nG99 G81 X1 Y1 Z-2 R2\nG4 P1\nX2\nT1 M6\n"
                            "G4 P[#1]\nY[#1]\nG80\nG4 P1\nG81 X3 Y1 Z-2 R2\nM30\n",
    "pecks": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z25\nG99 G83 X1 Y1 Z-3 R2 Q0.7\nX[#1 * 3]\nY2 Q[#1 / 3]\n"
             "G98 X0 Z-1\nG81 X1 Z-2 R2\nG83 X2 Z-2.9 R2 Q1\nG80\nM61 Q3\nM30\n",
    "a G82 after a G81": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z25\nG99 G81 X1 Y1 Z-2 R2\nG82 X2 Z-3 R2 P[#1]\nX3\n"
                         "G80\nM30\n",
}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_drilling_programs_the_pass_follows(name):
    path = check_against_full(ACCEPTED[name], MACHINE)
    assert path is not None, "declined"
    assert path.motions >= 4


DECLINED = {
    "no retract mode": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG81 X1 Y1 Z-1 R1\n", "retract mode"),
    "no plane": ("G21 G90 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z-1 R1\n", "plane"),
    "no feed": ("G21 G90 G17 G54\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z-1 R1\n", "feed"),
    "no R": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z-1\n", "without R"),
    "no bottom": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 R1\n", "bottom"),
    "R below the bottom": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z1 R-1\n", "below its bottom"),
    "P with G81": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z-1 R1 P1\n", "word P"),
    "G82 without P": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G82 X1 Y1 Z-1 R1\n", "without P"),
    "G82 P0": ("G21 G90 G17 G54 F100\n#1 = 0\nG0 Z5\nG99 G82 X1 Y1 Z-1 R1 P#1\n", "not positive"),
    "G83 without Q": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G83 X1 Y1 Z-1 R1\n", "without Q"),
    "a peck of 0": ("G21 G90 G17 G54 F100\n#1 = 0\nG0 Z5\nG99 G83 X1 Y1 Z-1 R1 Q#1\n", "not positive"),
    "Q with G81": ("G21 G90 G17 G54 F100\n#1 = 0\nG0 Z5\nG99 G81 X1 Y1 Z-1 R1 Q1\n", "word Q"),
    "Q with G1": ("G21 G90 G17 G54 F100\n#1 = 0\nG1 X1 Y1 Z-1\nX2 Q1\n", "word Q"),
    "Q alone": ("G21 G90 G17 G54 F100\n#1 = 0\nG1 X1 Y1 Z-1\nQ1\n", "word Q"),
    "G64 Q in a peck cycle": ("G21 G90 G17 G54 F100\n#1 = 0\nG0 Z5\nG99 G83 X1 Y1 Z-1 R1 Q1\nG64 X2 Q0.1\n",
                              "word Q"),
    "pecks past the bound": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G83 X1 Y1 Z-100 R1 Q0.1\n", "bound"),
    "an offset change": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z-1 R1\nG55 X2\n", "offset or units change"),
    # (a literal level equal to R is seen equal since cyc41: test_double_pass_cycles41.py; an expression's is not)
    "R equal to the initial level, an expression": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z[#1 + 1]\n"
                                                    "G98 G81 X1 Y1 Z-1 R2\n", "too close"),
    # the same double, an exact value a hair below the last R: the full path's tool is above R, two rapids
    "R a hair below the last": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z-1 R0.30000000000000001\n"
                                "X2 R0.3\n", "too close"),
    "P in G1": ("G21 G90 G17 G54 F100\n#1 = 1\nG1 X1 Y1 Z-1\nX2 P1\n", "word P"),
    "I in a cycle": ("G21 G90 G17 G54 F100\n#1 = 1\nG0 Z5\nG99 G81 X1 Y1 Z-1 R1\nX2 I1\n", "I, J or K"),
}


@pytest.mark.parametrize("name", sorted(DECLINED))
def test_drilling_programs_outside_the_subset_are_declined(name):
    text, why = DECLINED[name]
    with pytest.raises(Declined, match=why):
        double_pass(text, MACHINE, max_iterations=5)


@pytest.mark.parametrize("r", ["1", "7", "100.1"])
@pytest.mark.parametrize("q", ["0.1", "0.3", "[1/3]", "0.07"])
def test_peck_rows_are_enclosed(r, q):
    # a peck's row R' - k Q' drifts from the exact R - k Q by up to k ulps of Q: without the widening of
    # double_cycles' peck_err, some of these rows' boxes miss the full path's point (the invariant fails)
    text = f"G21 G90 G17 G54 F100\n#1 = 1\nG0 Z150\nG99 G83 X1 Y1 Z-3 R{r} Q{q}\nM30\n"
    path = check_against_full(text, MACHINE, max_iterations=100_000)
    assert path is not None and path.motions > 30


def test_a_lathes_cycles_are_declined():
    # an X word of a lathe may be a diameter (G7): its cycles decline, whatever the pass takes of lathes
    lathe = load_machine("box_5000", set={"machine.type": "lathe"})
    with pytest.raises(Declined, match="lathe"):
        double_pass(ACCEPTED["G98 to the initial level"], lathe, max_iterations=5)
