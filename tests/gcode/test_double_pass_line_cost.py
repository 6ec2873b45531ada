"""What the double pass does once a line or once a pass, made cheaper (line44, issue 36), against what it replaces.

- ``doubles._cycle_in_mode``: a modal straight move's cycle call folded into its mode's tests.  The folded code
  and the code it replaces (the call, then the tests) have the same outcome for every motion mode and feed: the
  same return, the same decline, or on to the move.
- ``state.linuxcnc_state_numbers``: the state parameters' numbers (the pass declines a read of one) without the
  table's readers: the table's numbered keys.
- ``doubles._first_rows``: a plan records its axes' first rows on its first run only: the rows of main's pass."""

from __future__ import annotations

import pytest

from nczones.gcode.linuxcnc.double_cycles import CYCLE_CODES, cycle_call
from nczones.gcode.linuxcnc.doubles import Declined, _cycle_in_mode, _mode_checks


class _State:
    def __init__(self, motion, feed):
        self.motion, self.feed = motion, feed


def _run(body, motion, feed):
    """``body`` as a plan's, then "moved": its outcome."""
    src = "def plan(v):\n" + "".join(f"    {b}\n" for b in body) + "    return 'moved'\n"
    scope = {"st": _State(motion, feed), "D": Declined, "CYC": CYCLE_CODES, "CY": lambda *args: ("cycle", args)}
    exec(src, scope)  # noqa: S102 - the test's own code
    try:
        return scope["plan"]((1.5, -2.0, 3.0, "3.0"))
    except Declined as exc:
        return ("declined", str(exc))


@pytest.mark.parametrize("motion", [None, 0, 1, 2, 3, 33, *sorted(CYCLE_CODES)])
@pytest.mark.parametrize("feed", [0.0, -1.0, 800.0])
@pytest.mark.parametrize("words", [["X", "Y"], ["X", "Y", "R"], ["X", "Y", "I", "J"]])
def test_the_fold_has_the_outcome_of_the_call_then_the_tests(motion, feed, words):
    """A modal straight move, an R arc and an I/J arc (whose call declines a cycle)."""
    calls = cycle_call(words, [(0, 0), (1, 1)])
    motion_body = _mode_checks(None, len(words) > 2) + ["off = 1"]
    folded = _cycle_in_mode(calls, motion_body)
    assert folded != calls + motion_body  # (folded: a modal line)
    assert _run(folded, motion, feed) == _run(calls + motion_body, motion, feed)


def test_no_fold_where_the_call_is_not_alone_or_the_move_not_modal():
    """A call with a P's decline after it, or a move with its own code: the code as it was."""
    calls = cycle_call(["X", "P"], [(0, 0)])
    motion_body = _mode_checks(None, False)
    assert _cycle_in_mode(calls, motion_body) == calls + motion_body
    calls = cycle_call(["X"], [(0, 0)])
    motion_body = _mode_checks(1, False)
    assert _cycle_in_mode(calls, motion_body) == calls + motion_body


def test_the_state_numbers_are_the_table_s():
    from nczones.gcode.linuxcnc.state import linuxcnc_state_numbers, linuxcnc_state_parameters

    assert linuxcnc_state_numbers() == frozenset(k for k in linuxcnc_state_parameters() if isinstance(k, int))


def test_each_axis_s_first_row_with_plans_run_again():
    """``_first_rows``: a plan records its axes' first rows on its first run only; each axis's first row is the
    first motion that moved it, whichever plan ran it (a flag left false from the start, or never cleared but
    ``moved`` skipped, fails here)."""
    from nczones.gcode.linuxcnc.doubles import double_pass
    from nczones.machine import parse_machine

    m = parse_machine('[machine]\naxes = ["X", "Y", "Z"]\n[machine.rapid]\nX = "1000"\nY = "1000"\nZ = "1000"\n'
                      '[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n')
    text = "G21 G90 G17 G54 F100\nG1 X1\nX2\nG1 Y1\nX3 Y2\nG2 X4 Y2 R1\nG1 X5 Z1\nX6\nM30\n"
    path = double_pass(text, m, max_iterations=100)
    assert path.first_row == (1, 3, 6)
    path = double_pass("G21 G90 G17 G54 F100\nG0 Z5\nG2 X1 Y1 R1\nX2 Y0 R1\nM30\n", m, max_iterations=100)
    assert path.first_row == (2, 2, 1)
