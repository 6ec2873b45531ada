"""G43.1 (dynamic tool length) in the LinuxCNC dialect: its axis words are offsets, not a move.

LinuxCNC's ``enhance_block`` gives a block with G43.1 and no motion code no motion at all
(``motion_to_be`` stays -1): ``G43.1 Z10`` sets the tool length and the tool stays where it is; every
axis G43.1 does not name gets offset 0. With a motion code in the block (``G1 G43.1 Z10``) the words
are both. Expected paths below are ``rs274 -g`` (LinuxCNC 2.9) canonical output of the same programs
(canonical Z = machine Z - tool length), written out by hand.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

MACHINE_TEXT = machine_text("box_100_clamp_fine")
MACHINE = parse_machine(MACHINE_TEXT)
HEAD = "G21 G90 G17 G54 F100\nG1 X1 Y1 Z-5\n"


def canonical(text: str) -> list[tuple[Fraction, ...]]:
    """End points of the program's motions as LinuxCNC's canon prints them (tool length taken off Z)."""
    run = interpret_text(text, MACHINE)
    ends = [s.end[:2] + (s.end[2] - s.tool_length,) for c in run for s in c.segments()]
    assert not run.unsupported, run.unsupported
    return ends


@pytest.mark.parametrize("body,expected", [
    ("G43.1 Z10\nG1 X2", [(1, 1, -5), (2, 1, -15)]),
    ("G1 G43.1 Z10\nG1 X2", [(1, 1, -5), (1, 1, 10), (2, 1, 10)]),
    ("G43.1 Z10 F50\nG43.1 Z0\nG1 X2", [(1, 1, -5), (2, 1, -5)]),
    ("G43.1 Z10 X0\nG1 X2", [(1, 1, -5), (2, 1, -15)]),
])
def test_g43_1_axis_words_are_offsets_not_a_move(body, expected):
    assert canonical(HEAD + body + "\nM2\n") == [tuple(Fraction(v) for v in e) for e in expected]


def test_g43_1_before_any_motion_mode_is_accepted():
    assert canonical("G21 G90 G17 G54 F100\nG43.1 Z10\nG1 X1 Y1 Z-5\nM2\n") == [(1, 1, -5)]


@pytest.mark.parametrize("block", ["G43.1 X3 Z10", "G43.1 X3", "G43.1 Y-2"])
def test_a_g43_1_offset_off_the_tool_axis_is_unknown(block):
    run = interpret_text(HEAD + block + "\nG1 X2\nM2\n", MACHINE)
    assert len([s for c in run for s in c.segments()]) == 1
    assert [(u.code, u.span.line) for u in run.unsupported] == [("G43.1", 3)]


def test_the_tool_stays_down_through_the_clamp_after_g43_1():
    """The wrong `safe`: read as a move, ``G43.1 Z10`` lifted the tool 25 mm over the clamp on paper, while the
    machine stays at Z-5 and drives X through it."""
    result = verify_text(HEAD + "G43.1 Z10\nG1 X2\nM2\n", MACHINE)
    assert result.verdict.label == "unsafe"
    assert [(v.line, v.zone) for v in result.violations] == [(4, "clamp")]
