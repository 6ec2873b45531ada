"""An arc whose start and end depend on different parameters is decided (issue 19).

The first motion of a program starts at the machine's start position; with
``--param start.X=LO..HI`` its start moves with the parameter while its
programmed end does not.  Such an arc used to be ``unknown`` whatever it
did, and the summary's "first at line N" then named a later block.
"""

from fractions import Fraction as F

from nczones.exact import format_exact
from nczones.machine import parse_machine
from nczones.prover import Verdict, verify_text


def machine(top: str, start_x: str = "50"):
    return parse_machine(f"""
[machine]
axes = ["X", "Y"]
[machine.rapid]
X = "1000"
Y = "1000"
[machine.reference]
X = "{start_x}"
Y = "50"
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "0", Y = "0" }}
max = {{ X = "100", Y = "{top}" }}
""")


#: a half circle clockwise from the start (50, 50) over (55, 55) to (60, 50), then a line up to Y60
PROGRAM = "G17 G90 G54\nG2 X60 Y50 I5 J0 F100\nG1 Y60\nM2\n"


def test_arc_from_a_start_range_that_violates_at_every_value_is_unsafe_with_its_values():
    m = machine("53")
    r = verify_text(PROGRAM, m, params=["start.X=-2..2"])
    assert r.verdict is Verdict.UNSAFE
    first = r.violations[0]
    assert first.line == 2 and first.segment_kind == "arc"
    dev = dict(first.params)["start.X"]
    assert -2 <= dev <= 2
    assert m.allowed.violated_zones(dict(first.point), F(0))
    assert not any("different parameters" in x.message for x in r.reasons)
    # replayed at its value (the machine starting there), the same block is unsafe
    at_value = verify_text(PROGRAM, machine("53", format_exact(50 + dev)))
    assert at_value.violations[0].line == 2


def test_arc_from_a_start_range_that_stays_inside_is_safe():
    r = verify_text("G17 G90 G54\nG2 X60 Y50 I5 J0 F100\nM2\n", machine("70"), params=["start.X=-2..2"])
    assert r.verdict is Verdict.SAFE, r.reasons
