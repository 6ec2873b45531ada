"""``G91.1`` written out in the double pass: LinuxCNC's start-up arc-centre mode (I/J/K relative to the start),
the one the full path starts in (``Interpreter.arc_absolute`` False) and the pass's arcs assume, so the pass
takes it as a no-op; ``G90.1`` (absolute centres) still declines.  CAM posts write ``G91.1`` in their header:
without this, such a program ran the full path (``bench_gcode.declined_program`` measured it at 4x rs274)."""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import check_against_full
from tests.gcode.test_double_pass_planes import machine
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import both_ways, same_outcome

#: from (10, 0) about the origin to (-6, 8), counter-clockwise the short way: its top is Y 10
ARC = "G3 X-6 Y8 I-10 J0"


def program(where: str) -> str:
    """The arc after a move to its start, ``G91.1`` in the header, on its own line, or in the arc's block."""
    head = "G21 G90 G17 G54 F300" + (" G91.1" if where == "header" else "")
    own = "G91.1\n" if where == "own line" else ""
    arc = f"G91.1 {ARC}" if where == "arc block" else ARC
    return f"{head}\n#1 = 10\nG0 X#1 Y0\n{own}{arc}\nM30\n"


@pytest.mark.parametrize("where", ["header", "own line", "arc block"])
def test_the_pass_takes_g91_1_and_encloses_the_full_paths_arc(where):
    path = check_against_full(program(where), parse_machine(machine_text("box_5000")))
    assert path is not None and path.arcs == 1


@pytest.mark.parametrize("where", ["header", "arc block"])
def test_a_face_at_the_arcs_top_is_decided_as_the_full_path_does(where, monkeypatch):
    for eps in (Fraction(-1, 10**12), Fraction(0), Fraction(1, 10**9)):
        with_pass, without = both_ways(program(where), machine("Y", 1, 10 + eps), monkeypatch)
        same_outcome(with_pass, without)
        assert with_pass.verdict is (Verdict.UNSAFE if eps < 0 else Verdict.SAFE), (eps, with_pass.reasons)
        if eps > 0:
            assert "double_pass_boxes" in dict(with_pass.stats)


@pytest.mark.parametrize("code", ["G90.1", "G90.1 G91.1"])
def test_absolute_arc_centres_decline(code):
    text = program("header").replace("G91.1", code) if code == "G90.1" else program("header").replace(
        "G91.1", "G90.1\nG91.1")
    with pytest.raises(Declined):
        double_pass(text, parse_machine(machine_text("box_5000")), max_iterations=100)
