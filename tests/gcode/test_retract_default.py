"""The canned-cycle retract mode a program starts in when it names neither G98 nor G99.

LinuxCNC's interpreter starts in G99 (``interp_setup.cc``: ``retract_mode(R_PLANE)``; ``rs274 -g`` of the
program below traverses between the holes at R, Z2); a Fanuc control in G98. nczones assumed G98 for
LinuxCNC too, so it proved the traverse at the initial level Z10, over a clamp the machine drives into at Z2.
"""

from __future__ import annotations

import pytest

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text

MACHINE = """
[machine]
path_mode = "G61"  # exact path: this test is not about corner blending (tests/prover/test_blending.py is)
axes = ["X", "Y", "Z"]
pulse = "0.0001"
dialect = "{dialect}"
{modal}
[machine.rapid]
X = "10000"
Y = "10000"
Z = "10000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "-100", Y = "-100", Z = "-100" }}
max = {{ X = "100", Y = "100", Z = "100" }}
[[zones]]
name = "clamp"
kind = "box"
forbid = true
min = {{ X = "7", Y = "-1", Z = "-100" }}
max = {{ X = "8", Y = "1", Z = "5" }}
"""
LINUXCNC = "G21 G90 G17 G54 F100\nG0 X0 Y0 Z10\nG81 X5 Y0 Z-1 R2\nX10\nG80\nM2\n"
FANUC = "G21 G90 G17 G54 G94 F100\nG00 X0 Y0 Z10\nG81 X5 Y0 Z-1 R2\nX10\nG80\nM30\n"


def machine(dialect: str, modal: str = ""):
    return parse_machine(MACHINE.format(dialect=dialect, modal=f"modal = [{modal}]" if modal else ""))


def traverse_levels(text: str, m) -> list[str]:
    """The tool-axis level of each rapid between the holes (X changes)."""
    segs = [s for c in interpret_text(text, m) for s in c.segments()]
    return [str(s.end[2]) for s in segs if s.kind.name == "RAPID" and s.start[0] != s.end[0] and s.start[0] != 0]


@pytest.mark.parametrize("dialect,text,modal,level,verdict", [
    ("linuxcnc", LINUXCNC, "", "2", "unsafe"),        # LinuxCNC's start-up mode: G99, back to R
    ("linuxcnc", LINUXCNC, '"G98"', "10", "safe"),    # an INI whose RS274NGC_STARTUP_CODE has G98
    ("linuxcnc", LINUXCNC, '"G99"', "2", "unsafe"),
    ("fanuc", FANUC, "", "10", "safe"),               # a Fanuc control at power-on: G98
    ("fanuc", FANUC, '"G99"', "2", "unsafe"),
])
def test_the_start_up_retract_mode(dialect, text, modal, level, verdict):
    m = machine(dialect, modal)
    assert traverse_levels(text, m) == [level]
    result = verify_text(text, m)
    assert result.verdict.label == verdict
    if verdict == "unsafe":
        assert [(v.line, v.zone) for v in result.violations] == [(4, "clamp")]


def test_an_assumed_retract_mode_is_noted_and_says_where_it_came_from():
    run = interpret_text(LINUXCNC, machine("linuxcnc"))
    for _ in run:
        pass
    assert run.assumed_modal == {"retract": "G99"}
    assert "the linuxcnc control's start-up mode" in run.assumed_modal_text()[0]
    named = interpret_text(LINUXCNC, machine("linuxcnc", '"G98"'))
    for _ in named:
        pass
    assert named.assumed_modal_text() == ["retract mode (G98/G99): assumed G98 from the machine file"]


def test_a_program_that_sets_the_mode_assumes_nothing():
    run = interpret_text(LINUXCNC.replace("G81", "G98 G81"), machine("linuxcnc"))
    assert traverse_levels(LINUXCNC.replace("G81", "G98 G81"), machine("linuxcnc")) == ["10"]
    for _ in run:
        pass
    assert "retract" not in run.assumed_modal
