"""The double pass's canned cycles beyond G81-G83 in G90 (cyc40, issue 36; nczones/gcode/linuxcnc/double_cycles.py):
L repeats, cycles in G91 (R above the initial level, the bottom below R, the hole's increments added on every
repeat) and G20, G73, G84, G85, G86 and G89, the spindle G84 and G86 check.

The pass's invariant (``check_against_full``: the full path runs the program with no note, as many motions,
rapids and dwells, every motion in the pass's box, corners blended where the full path blends them) on generated
programs of these forms, their windows, and fixed programs the pass must take or decline.
"""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from tests.gcode.rs274_arc_programs import in_plane
from tests.gcode.test_double_pass import MACHINE, check_against_full, machines
from tests.prover.test_double_pass_proof import machine_of
from tests.prover.test_double_pass_windows import windows_of

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "100"))

#: G91 levels: R above the initial level (then an "up to R" rapid) or below it, the bottom below R (now and
#: then above it: declined), expressions; G90 ones as cycles39's.
RS = {"G90": ["2", "5", "[#1 + 1]", "0.3", "[#2 / 3]", "20"], "G91": ["-3", "-0.5", "1", "[#2 / 3]", "-[#1]", "-3"]}
BOTTOMS = {"G90": ["-3", "-0.5", "[#2 / 3]", "-[#1]"], "G91": ["-5", "-0.7", "-[#1 * 2]", "[#2 / 3]", "-5"]}
PECKS = ["1", "0.7", "[#1 / 3]", "2.5"]
PLACES = {"G90": ["1", "-2.5", "[#1 + 4.911]", "[#2 * 7]", "0"],
          "G91": ["10", "-2.5", "[#1 / 7]", "0.1", "[#2 * 3]", "0"]}
REPEATS = ["", "", "", " L2", " L5", " L1", " L[#1 + 1.5]", " L2.00001", " L3"]
CODES = ["G81", "G82", "G83", "G73", "G85", "G89", "G84", "G86", "G85", "G84"]
#: a dwell the first time (G84's is the sticky P of any cycle before, 0 before any)
DWELL = {"G82": " P0.5", "G89": " P[#1]", "G86": " P1", "G84": ""}


@st.composite
def hole_line(draw, dist: str) -> str:
    """A line of a modal cycle: X and/or Y, sometimes L, R, the bottom, a code, the distance or retract mode."""
    words = [f"{a}{draw(st.sampled_from(PLACES[dist]))}"
             for a in draw(st.lists(st.sampled_from("XY"), min_size=1, max_size=2, unique=True))]
    extra = draw(st.sampled_from(["", "", "", " R{r}", " Z{z}", " G98", " G99", " P0.2", " M8", " Z{z} R{r}"]))
    return (" ".join(words) + extra.format(r=draw(st.sampled_from(RS[dist])), z=draw(st.sampled_from(BOTTOMS[dist])))
            + draw(st.sampled_from(REPEATS)))


@st.composite
def cycle_block(draw, label: int) -> list[str]:
    """A spindle code, a first cycle block in G90 or G91 and its holes, sometimes in a loop, then G80 and G90,
    a G90 motion or nothing."""
    code = draw(st.sampled_from(CODES))
    dist = draw(st.sampled_from(["G91", "G91", "G90"]))
    spindle = draw(st.sampled_from(["M3 S500", "M3 S500", "M4 S500", "M5", "", "T1 M6"]))
    retract = draw(st.sampled_from(["G98", "G99"]))
    more = DWELL.get(code, "")
    if code in ("G73", "G83"):
        more = f" Q{draw(st.sampled_from(PECKS))}"
    xy = f"X{draw(st.sampled_from(PLACES[dist]))} Y{draw(st.sampled_from(PLACES[dist]))}"
    if draw(st.integers(0, 5)) == 0:
        xy = ""
    first = (f"{dist} {retract} {code} {xy} Z{draw(st.sampled_from(BOTTOMS[dist]))} R{draw(st.sampled_from(RS[dist]))}"
             f"{more}{draw(st.sampled_from(REPEATS))}")
    holes = [draw(st.one_of(hole_line(dist), hole_line(dist), st.sampled_from(["G4 P0.5", "M3", "G90", "G91"])))
             for _ in range(draw(st.integers(0, 3)))]
    if draw(st.integers(0, 3)) == 0:
        holes = ["#3 = 0", f"o{label} while [#3 LT 3]", f"X{draw(st.sampled_from(PLACES[dist]))} L2",
                 "#3 = [#3 + 1]", f"o{label} endwhile"]
    tail = draw(st.sampled_from([["G90 G80"], ["G80", "G90 G0 X0 Y0 Z30"], [], ["G90 G1 X0 Y0 Z20"]]))
    return [spindle, first, *holes, *tail]


@st.composite
def drilling_programs(draw) -> str:
    head = draw(st.sampled_from(["G21 G90 G17 G54 F300", "G21 G90 G17 G55 F100 G0", "G21 G90 G17 G54 G43 H1 F800",
                                 "G21 G90 G17 G54 F300 G64", "G21 G90 G17 G54 G61 F300", "G20 G90 G17 G54 F30",
                                 "G20 G90 G17 G55 F10 G64", "G20 G90 G17 G54 G43 H1 F30"]))
    start = draw(st.sampled_from(["G0 Z20", "G0 X0 Y0 Z20", "G0 Z2", "G0 Z[#1 + 1]", "G0 X1 Y1 Z25", "G0 Z0.3"]))
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


@settings(max_examples=EXAMPLES // 2, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(drilling_programs(), st.integers(1, 12))
def test_windows_hold_the_full_paths_motion(text, window):
    """A cycle's rows cross window edges (a G91 chain's and a peck's widening kept across them): the windows
    put back together are the rows without windows, and each window's box of each motion holds the full path's."""
    machine = machine_of("box", 1000, 0)
    try:
        whole = double_pass(text, machine, max_iterations=1000)
    except Declined:
        return
    got, last = windows_of(text, machine, window)
    assert (last.motions, last.rapids, last.dwells) == (whole.motions, whole.rapids, whole.dwells)
    for row0, motions, columns, _first in got:
        assert [c[row0:motions + 1] for c in map(list, whole.columns)] == list(columns)
    segments = list(interpret_text(text, machine, max_loop_iterations=1000).segments())

    def holds(p) -> bool:
        for k in range(p.row0 + 1, p.motions + 1):
            lo, hi = p.enclosure(k, k)
            for i, a in enumerate(machine.axis_names):
                assert lo[a] <= segments[k - 1].start[i] <= hi[a] and lo[a] <= segments[k - 1].end[i] <= hi[a]
        return True

    windowed = double_pass(text, machine, max_iterations=1000, window=window, on_window=holds)
    assert holds(windowed) and windowed.motions == whole.motions


# -- fixed programs ----------------------------------------------------------------------------------------

ACCEPTED = {
    "a G91 row of holes": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG91 G99 G81 X10 Y0.1 R-3 Z-5 L20\nG90 G80\n"
                          "G0 Z50\nM30\n",
    "G91 G98, R above the initial level": "G21 G90 G17 G54 F200\n#1 = 3\nG0 X0 Y0 Z5\n"
                                          "G91 G98 G81 X[#1 / 7] R1 Z-8 L7\nY2\nX1 Y1 L3\nG90 G80\nM30\n",
    "G90 L repeats the hole": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG99 G82 X10 R2 Z-5 P0.5 L3\nX2\nM30\n",
    "G73": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG99 G73 X10 R2 Z-5 Q1.1\nX2 L2\nG98 Y3\nM30\n",
    "G85 G98 and G99": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG98 G85 X10 R2 Z-5\nX2\nG99 X3\nM30\n",
    "G89": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG98 G89 X10 R2 Z-5 P1\nX2\nG99 X3\nM30\n",
    "G84 after M3, P sticky": "G21 G90 G17 G54 F200\nM3 S100\nG0 X0 Y0 Z5\nG98 G84 X10 R2 Z-5\nX2\nG99 X3 P2\n"
                              "M30\n",
    "G84 with M3 in its block": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG98 G84 X10 R2 Z-5 M3\nX2\nM30\n",
    "G86 after M4": "G21 G90 G17 G54 F200\nM4 S100\nG0 X0 Y0 Z5\nG98 G86 X10 R2 Z-5 P1\nX2\nM5\nM30\n",
    "G91 G85 then G90 holes": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG91 G98 G85 X10 R-3 Z-5 L4\nG90 G80\n"
                              "G0 X0 Y0 Z5\nG98 G81 X1 Y1 R2 Z-1\nM30\n",
    "a G90 cycle with a G91 chain open": "G21 G90 G17 G54 F200\nG0 X0 Y0 Z5\nG91 G98 G81 X10 R-3 Z-5 L4\n"
                                         "G90 Y3\nX1 Z-2 R3\nG91 X0.5 L2\nG90 G83 Y5 R2 Z-1 Q0.5\nM30\n",
    "G20, G91 and pecks": "G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z2\nG98 G81 X1 Y1 Z-1 R1\nG91 X[#1] L3\n"
                          "G90 G80\nG0 Z2\nG99 G83 X2 Y1 Z-0.5 R0.1 Q0.07\nX3 L2\nG91 G85 Y0.3 R-0.2 Z-0.4 L2\nM30\n",
    # (seams39's: declined before cyc40)
    "a G20 cycle": "G20 G90 G17 G54 G98 F100\n#1 = 1\nG0 Z1\nG81 X#1 Y1 Z-0.1 R0.5\nG80\nM30\n",
    "G91 in G19": "G21 G90 G19 G54 F200\nG0 X5 Y0 Z0\nG91 G99 G81 Y2.5 X-6 R-1 L4\nG90 G80\nM30\n",
}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_drilling_programs_the_pass_follows(name):
    path = check_against_full(ACCEPTED[name], MACHINE)
    assert path is not None, "declined"
    assert path.motions >= 4


DECLINED = {
    "L not a whole number": ("G21 G90 G17 G54 F100\nG0 Z5\nG91 G99 G81 X1 Z-1 R-1 L2.5\n", "whole number"),
    "L0": ("G21 G90 G17 G54 F100\nG0 Z5\nG91 G99 G81 X1 Z-1 R-1 L0\n", "below 1"),
    "L at the bound": ("G21 G90 G17 G54 F100\nG0 Z5\nG91 G99 G81 X1 Z-1 R-1 L5\n", "bound"),
    "L with G1": ("G21 G90 G17 G54 F100\nG1 X1 Z5 L2\n", "word L"),
    "L alone": ("G21 G90 G17 G54 F100\nG1 X1 Z5\nL2\n", "word L"),
    "G84 without M3": ("G21 G90 G17 G54 F100\nM4\nG0 Z5\nG99 G84 X1 Z-1 R1\n", "G84 without M3"),
    "G86 stopped by M6": ("G21 G90 G17 G54 F100\nM3\nT1 M6\nG0 Z5\nG99 G86 X1 Z-1 R1 P1\n", "spindle stopped"),
    "G84 in G18": ("G21 G90 G18 G54 F100\nM3\nG0 Y5\nG99 G84 Z1 Y-1 R1\n", "G84 outside G17"),
    "G86 without P": ("G21 G90 G17 G54 F100\nM3\nG0 Z5\nG99 G86 X1 Z-1 R1\n", "without P"),
    "Q with G85": ("G21 G90 G17 G54 F100\nG0 Z5\nG99 G85 X1 Z-1 R1 Q1\n", "word Q"),
    "a units change while a cycle is modal": ("G21 G90 G17 G54 F100\nG0 Z5\nG99 G81 X1 Z-1 R1\nG20 X2\n",
                                              "units change"),
    "G91 Z0": ("G21 G90 G17 G54 F100\nG0 Z5\nG91 G99 G81 X1 Z0 R-1\n", "too close"),
}


@pytest.mark.parametrize("name", sorted(DECLINED))
def test_drilling_programs_outside_the_subset_are_declined(name):
    text, why = DECLINED[name]
    with pytest.raises(Declined, match=why):
        double_pass(text, MACHINE, max_iterations=5)


@pytest.mark.parametrize(("start", "step"), [("0", "0.1"), ("100.3", "0.07"), ("-977.7", "[1/3]")])
def test_g91_repeat_rows_are_enclosed(start, step):
    # a G91 repeat's hole fl(x + w) drifts from the exact x + k w by up to k ulps of x: without the chain's
    # error (double_cycles' _increment and _relative), some of these rows' boxes miss the full path's point
    text = (f"G21 G90 G17 G54 F100\nG0 X{start} Y{start} Z{start}\n"
            f"G91 G99 G81 X{step} Y-{step} R[{step} * 3] Z-{step} L300\nG90 G80\nM30\n")
    path = check_against_full(text, MACHINE, max_iterations=100_000)
    assert path is not None and path.motions >= 900


@pytest.mark.parametrize("code", ["G83", "G73"])
def test_peck_hole_lines_across_a_window_edge(code):
    # a hole line of pecks appends its rows from the template (_steady); a dwell between holes handed a window
    # over just before it (full() recomputes xerr from the G91 chains alone): every window's boxes still hold
    # the full path's points (the peck rows' widening is put back; at these sizes the rows' drift is within the
    # module's widening too, so this checks the rows and their windows, not that term)
    moves = "".join(f"G0 Z{150 - k}\n" for k in range(10))  # (the next window holds a hole's rows)
    head = f"G21 G90 G17 G54 F100\n{moves}G99 {code} X1 Y1 Z-3 R10.1 Q0.07\n"
    first = double_pass(head + "M30\n", MACHINE, max_iterations=100_000).motions
    text = head + "G4 P0.5\nX2\nX3 L2\nM30\n"
    segments = list(interpret_text(text, MACHINE, max_loop_iterations=100_000).segments())

    ends = []

    def holds(p) -> bool:
        ends.append(p.motions)
        for k in range(p.row0 + 1, p.motions + 1):
            lo, hi = p.enclosure(k, k)
            for i, a in enumerate(MACHINE.axis_names):
                assert lo[a] <= segments[k - 1].end[i] <= hi[a], (k, a)
        return True

    last = double_pass(text, MACHINE, max_iterations=100_000, window=first + 1, on_window=holds)
    assert holds(last) and last.motions == len(segments) and ends[0] == first + 1  # (handed over at the dwell)


#: LinuxCNC's own canned-cycle tests in the corpus (G20, G98/G99, G91 with L, in G17, G18 and G19): the pass
#: takes them (cyc40) and holds the invariant.
INTERP_TESTS = [pytest.param(f"g81/g{p}/g{r}/g{p}-g{r}-g81.ngc", marks=() if (p, r) in ((17, 98), (19, 99))
                             else pytest.mark.long) for p in (17, 18, 19) for r in (98, 99)] + \
               [pytest.param(f"g84/g17/g{r}/g17-g{r}-g84.ngc", marks=() if r == 98 else pytest.mark.long)
                for r in (98, 99)]


@pytest.mark.parametrize("name", INTERP_TESTS)
def test_linuxcncs_cycle_tests_in_the_corpus(name):
    from tests.corpus import CORPUS

    path = CORPUS / "linuxcnc" / "tests" / "interp" / name
    if not path.is_file():
        pytest.skip("the shared corpus is not here")
    got = check_against_full(path.read_text(), MACHINE, max_iterations=10_000)
    assert got is not None, "declined"
    assert got.motions >= 30
