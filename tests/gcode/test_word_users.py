"""Words no code of the block uses: LinuxCNC refuses such a block, and so does the LinuxCNC dialect.

The table follows ``Interp::check_other_codes`` (``src/emc/rs274ngc/interp_check.cc``); each refused
row was also refused, and each accepted row accepted, by LinuxCNC 2.9's ``rs274 -g`` on the same text
after the same preamble (set-up of this file, not of the test run: CI has no LinuxCNC).
"""

from __future__ import annotations

import pytest

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from tests.machines import machine_text

MACHINE = parse_machine(machine_text("mill_xyz", set={"machine.pulse": "0.0001"}, extra='[tool_lengths]\nH1 = "10"\n'))
PREAMBLE = "G21 G90 G17 G54 F100 T1 M6 G43 H1\n"

REFUSED = [
    # (block, letter refused, column of the word)
    ("G1 X1 E3", "E", 7),
    ("G1 G90 X1 F100 E0", "E", 16),
    ("S100 E1", "E", 6),
    ("T1 E1", "E", 4),
    ("G1 X1 H1", "H", 7),
    ("H1", "H", 1),
    ("G49 H1", "H", 5),
    ("G10 L1 P1 Z1 H1", "H", 14),
    ("G1 X1 D1", "D", 7),
    ("G40 D1", "D", 5),
    ("G43 H1 D1", "D", 8),
    ("D1", "D", 1),
    ("G1 X1 L2", "L", 7),
    ("G43 H1 L1", "L", 8),
    ("M8 L1", "L", 4),
    ("L2", "L", 1),
    ("G1 X1 P2", "P", 7),
    ("G0 X1 P2", "P", 7),
    ("M3 S100 P1", "P", 9),
    ("M5 P1", "P", 4),
    ("G81 X1 Y1 Z-1 R2 P1", "P", 18),
    ("G92 X1 P1", "P", 8),
    ("G28 P1", "P", 5),
    ("G53 G0 X1 P1", "P", 11),
    ("P2", "P", 1),
    ("G1 X1 Q2", "Q", 7),
    ("G0 X1 Q2", "Q", 7),
    ("G81 X1 Y1 Z-1 R2 Q0.5", "Q", 18),
    ("F100 Q1", "Q", 6),
    ("Q2", "Q", 1),
]

ACCEPTED = [
    "G43 H1",
    "G41 D1|G1 X5",  # D with G41: cutter compensation off in this machine makes the rest unknown, not an error
    "G10 L2 P1 X0",
    "G4 P1",
    "G64 P0.01",
    "G64 P0.01 Q0.001",
    "G82 X1 Y1 Z-1 R2 P1",
    "G83 X1 Y1 Z-1 R2 Q0.5",
    "G73 X1 Y1 Z-1 R2 Q0.5",
    "G81 X1 Y1 Z-1 R2 L2",
    "G91 G81 X1 Y1 Z-1 R2 L2",
    "G2 X1 Y1 I0.5 J0.5 P2",
    "G10 L1 P1 Z1 Q1",
    "G1 X1|X2 Y2",
    "G82 X1 Y1 Z-1 R2 P1|X2 Y2 P0.5",  # P on a later hole line: the cycle is the block's motion
    "M66 P0 L3 Q5",
    "M62 P1",
    "M19 R90 Q1 P0",
]


def _run(body: str) -> None:
    for _ in interpret_text(PREAMBLE + body.replace("|", "\n") + "\nM2\n", MACHINE):
        pass


@pytest.mark.parametrize("block,letter,column", REFUSED, ids=[r[0] for r in REFUSED])
def test_a_word_no_code_uses_is_refused_at_the_word(block, letter, column):
    with pytest.raises(GcodeError) as exc:
        _run(block)
    d = exc.value.diagnostics[0]
    assert d.code == "GC204", d
    assert (d.span.line, d.span.column) == (2, column), d.span
    assert d.message.startswith(block.split()[[w[0] for w in block.split()].index(letter)] + " word with no "), d
    assert "LinuxCNC refuses the block" in d.message


@pytest.mark.parametrize("block", ACCEPTED)
def test_a_word_its_code_uses_is_accepted(block):
    _run(block)


def test_refused_inside_a_run_the_fast_path_would_take():
    """A long run of CAM lines goes through the vectorized fast path; the line with the stray word still
    reaches the check, with its own line and column."""
    lines = [f"G1 X{i % 50}.5 Y{i % 7}.25" for i in range(300)]
    lines[200] = "G1 X3 Y4 E0.5"
    with pytest.raises(GcodeError) as exc:
        _run("\n".join(lines))
    d = exc.value.diagnostics[0]
    assert (d.code, d.span.line, d.span.column) == ("GC204", 202, 10)


def test_after_an_unknown_code_the_block_is_left_alone():
    """A user M code may take P and Q (LinuxCNC passes them on): the block is unknown, not an error."""
    run = interpret_text(PREAMBLE + "M100 P1 Q2\nG1 X1\nM2\n", MACHINE)
    for _ in run:
        pass
    assert [(u.code, u.span.line) for u in run.unsupported] == [("M100", 2)]


def test_the_fanuc_dialect_is_not_held_to_linuxcncs_rule():
    fanuc = parse_machine(
        machine_text("mill_xyz", set={"machine.pulse": "0.0001", "machine.dialect": "fanuc"}))
    segments = [s for c in interpret_text("G21 G90 G94 F100\nG01 X1 E3\nM30\n", fanuc) for s in c.segments()]
    assert [s.end[0] for s in segments] == [1]
