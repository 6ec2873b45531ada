"""The double pass takes T, M6, M61, G4, G61, G61.1 and G64 (issue 36): the invariant on programs full of them.

``tests/gcode/test_double_pass.py`` mixes these codes among every other statement, where most programs leave
the subset somewhere; here programs are built to stay in it (positive feeds, set units, a few short motions
LinuxCNC may drop, loops), so the pass takes most of them and the invariant (``check_against_full``: as many
motions, dwells and rapids as the full path, its every motion in the pass's box, a corner blended exactly where
the full path's corner check blends one) is checked on the new codes, on machines starting in G64, G61, G61.1
and G64 with a tolerance.  Machines whose tool change moves (``[machine] tool_change_*``) make M6 decline, and
T alone does not.
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from tests.gcode.test_double_pass import arcs, check_against_full, expressions, machine_text
from tests.machines import load_machine
from tests.machines import machine_text as fixture_text

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "80"))

#: The lines of issue 36's codes; each in the subset (on a machine without tool change moves).
CODES = ["T1 M6", "T2", "M6", "T03 M06", "M61 Q3", "M6 M3 T1", "M61 Q0 M8", "T1 M6 G1 X[#1] F100", "G4 P0.5",
         "G4 P[ABS[#1] + 0.1]", "G04 P1 M9", "G4 P0.25 F200", "G61", "G61.1", "G64", "G64 G1 X[#1 / 3]",
         "G61 G0 Z[#2]", "G61.1 X[#1 + 0.0000001]", "G64 M5", "T5 G61", "G91", "G90", "G91 G1 X[#1] Y-0.1",
         "G91 G0 Z[-#2 / 3]", "G90 G1 X[#1] Y[#2] Z1"]


@st.composite
def moves(draw) -> list[str]:
    """A straight move of expressions, sometimes one so short that LinuxCNC may drop it in a blended corner."""
    code = draw(st.sampled_from(["G1 ", "G0 ", "", "G01 "]))
    if draw(st.integers(0, 4)) == 0:
        return [f"{code}X[#1 + 0.0000001] Y[#2]"]
    axes = draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True))
    return [code + " ".join(f"{a}{draw(expressions(1))}" for a in axes)]


@st.composite
def statement(draw, depth: int, labels: list[int]) -> list[str]:
    kind = draw(st.integers(0, 7))
    if kind <= 1:
        return draw(moves())
    if kind <= 3:
        return [draw(st.sampled_from(CODES))]
    if kind == 4:
        return [f"{draw(st.sampled_from(['#1', '#2', '#3']))} = {draw(expressions(1))}"]
    if kind == 5 and draw(st.booleans()):
        return [*draw(arcs()), "G1"]
    if kind == 6 and depth > 0:
        label = 100 + len(labels)
        labels.append(label)
        body = [line for _ in range(draw(st.integers(1, 3))) for line in draw(statement(depth - 1, labels))]
        return ["#9 = 0", f"o{label} while [#9 LT {draw(st.integers(1, 3))}]", *body, "#9 = [#9 + 1]",
                f"o{label} endwhile"]
    return draw(moves())


@st.composite
def programs(draw) -> str:
    head = draw(st.sampled_from(["G21 G90 G17 G54 F300 G1", "G21 G90 G17 G54 F800 G0", "T1 M6\nG21 G90 G17 G54 F100 G1",
                                 "G21 G90 G17 G54 G61 F300 G1", "G21 G90 G17 G54 G64 F300 G1"]))
    labels: list[int] = []
    body = [line for _ in range(draw(st.integers(2, 10))) for line in draw(statement(2, labels))]
    return "\n".join([head, "#1 = 0.5", "#2 = 1", "#<a> = 2", "#<b> = -0.25", *body, "M30"]) + "\n"


@st.composite
def machines(draw):
    keys = draw(st.sampled_from(["", "", 'path_mode = "G61"', 'path_mode = "G61.1"', 'path_tolerance = "0.01"']))
    offsets = draw(st.sampled_from([None, {"G54": ("10", "-2.5", "0.1")}]))
    return parse_machine(machine_text(offsets, ("0", "0", "0"), keys=keys))


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(programs(), machines())
def test_tools_dwells_and_path_modes_are_enclosed_by_the_full_interpreter(text, machine):
    check_against_full(text, machine)


def test_most_of_these_programs_are_taken():
    """The programs above exercise the new codes: the pass takes most of them (not a test that declines)."""
    taken, total = 0, 0

    @settings(max_examples=40, deadline=None, derandomize=True,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(programs(), machines())
    def run(text, machine):
        nonlocal taken, total
        total += 1
        path = check_against_full(text, machine)
        taken += path is not None and (path.dwells > 0 or len(path.modes) > 1 or "M6" in text)

    run()
    assert taken >= total // 3, (taken, total)


#: A parametric program with a tool change, a dwell and every path mode.
PROGRAM = ("G21 G90 G17 G54 F800\nT1 M6\n#1 = 0\nG1 X[#1 + 1] Y2\nG4 P0.5\nG61\nG1 X[#1 + 3]\nG61.1 Y[#1]\n"
           "T2\nM6 M3 S1000\nG64\nG1 X0 Y0\nM61 Q3\nG04 P[#1 + 1]\nM30\n")


def test_a_program_with_the_new_codes_is_taken():
    path = check_against_full(PROGRAM, load_machine("box_5000"))
    assert path is not None
    assert (path.motions, path.dwells, path.lines) == (6, 2, 4)
    assert path.modes == ((1, True), (3, False), (5, True))
    assert [path.blended(k) for k in range(1, 6)] == [False, False, False, False, False]


@pytest.mark.parametrize("key", [{"machine.tool_change_quill_up": True}, {"machine.tool_change_at_g30": True},
                                 {"machine.tool_change_position": {"Z": "0"}}])
def test_m6_on_a_machine_whose_tool_change_moves_is_declined(key):
    machine = parse_machine(fixture_text("box_5000", set=key))
    with pytest.raises(Declined, match="tool change moves"):
        double_pass(PROGRAM, machine, max_iterations=10)
    # a T word alone selects: no motion, taken
    path = check_against_full(PROGRAM.replace("T1 M6", "T1").replace("M6 M3", "M3").replace("M61 Q3\n", ""), machine)
    assert path is not None and path.motions == 6


@settings(max_examples=max(10, EXAMPLES // 4), deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(programs(), machines(), st.integers(1, 4))
def test_the_windows_blend_the_corners_the_whole_path_blends(text, machine, window):
    """In windows (``on_window``: the rows dropped each ``window`` motions, the path modes and dwells before the
    window with them), each window's corners blend as the whole path's, and its dwells are the whole's."""
    try:
        whole = double_pass(text, machine, max_iterations=1000)
    except Declined:
        return
    seen: dict[int, bool] = {}

    def keep(path):
        for k in range(path.row0 + 1, path.motions):
            assert seen.setdefault(k, path.blended(k)) == path.blended(k)
        return True

    last = double_pass(text, machine, max_iterations=1000, on_window=keep, window=window)
    keep(last)
    assert seen == {k: whole.blended(k) for k in range(1, whole.motions)}
    assert (last.dwells, last.lines, last.modes[-1]) == (whole.dwells, whole.lines, whole.modes[-1])


def test_a_long_g91_chain_is_enclosed():
    """1000 G91 steps of 0.1 mm: the controller's doubles drift from the exact 100 mm by about 1.4e-12 mm, far
    past a G90 row's bound (about 1e-13 here); the chain's own bound (``DoublePath.inc_bound``) holds it, in
    windows too (a window's first row keeps its error), and a G90 move ends the chain."""
    text = ("G21 G90 G54 F100\n#1 = 0\nG91\no1 while [#1 LT 1000]\nG1 X0.1 Y[0.1 + #1 * 0]\n#1 = [#1 + 1]\n"
            "o1 endwhile\nG90 G1 X50 Y50\nM30\n")  # the G90 move starts where the chain ended: at X = Y = 100
    machine = load_machine("box_5000")
    path = check_against_full(text, machine, max_iterations=2000)
    assert path is not None and path.motions == 1001
    assert path.columns[0][1000] != 100.0  # the drift the bound is for
    assert 1e-12 < path.inc_bound[0] < 1e-9 and not path.inc_bound[2]
    for window in (1, 7, 100):
        seen: set[int] = set()
        check = _holds_the_chain(window, seen)
        check(double_pass(text, machine, max_iterations=2000, window=window, on_window=check))
        assert seen == set(range(1, 1002))


def _holds_the_chain(window: int, seen: set[int]):
    """``on_window`` of :func:`test_a_long_g91_chain_is_enclosed`: each motion's enclosure holds its exact end
    (X = Y = k / 10, the last motion's start X = Y = 100); the motions seen go into ``seen``."""
    def check(p):
        for k in range(p.row0 + 1, p.motions + 1):
            lo, hi = p.enclosure(k, k)
            x = Fraction(min(k, 1000), 10)  # the motion's end, or the last one's start
            assert lo["X"] <= x <= hi["X"] and lo["Y"] <= x <= hi["Y"], (window, k)
            seen.add(k)
        return True

    return check
