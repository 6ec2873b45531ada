"""Issue 39: the tool-solids contract on lathes (turret tools, T0101 changes), fixture prisms and fixtures in a
work offset (G55, G10 L2 P2), prover and controller held to one verdict (tests/contract/solids_more.py;
specs/contract.md, "Tool solids: lathes, prisms and work offsets")."""

import os

import pytest
from hypothesis import given, settings

from .solids_more import check_lathe, check_mill, lathe_cases, mill_cases

LONG = os.environ.get("HYPOTHESIS_PROFILE") == "long"
#: CI size: 6 + 6 programs (derandomized, a few seconds); the long profile: NCZONES_SOLIDS_MORE_EXAMPLES each
EXAMPLES = int(os.environ.get("NCZONES_SOLIDS_MORE_EXAMPLES", 10_000 if LONG else 6))


@settings(max_examples=EXAMPLES)
@given(mill_cases())
def test_prisms_and_work_offsets_keep_the_contract(case):
    check_mill(*case)


@settings(max_examples=EXAMPLES)
@given(lathe_cases())
def test_lathe_turret_solids_keep_the_contract(case):
    check_lathe(*case)


@pytest.mark.long
@settings(max_examples=EXAMPLES)
@given(mill_cases())
def test_prisms_and_work_offsets_keep_the_contract_long(case):
    check_mill(*case)


@pytest.mark.long
@settings(max_examples=EXAMPLES)
@given(lathe_cases())
def test_lathe_turret_solids_keep_the_contract_long(case):
    check_lathe(*case)


def _blind(segs, machine, options):
    """A prover that drops the solid violations (it keeps only the controlled point's verdict)."""
    from dataclasses import replace

    from nczones.prover import Verdict
    from nczones.prover import prove as real_prove

    r = real_prove(segs, machine, options)
    kept = tuple(v for v in r.violations if v.kind != "solid")
    return replace(r, violations=kept, verdict=Verdict.SAFE if not kept else r.verdict)


def test_the_lathe_contract_has_teeth():
    """Tool 1's holder (x 0..40, z 10..40 from the tip) against a solid chuck of radius 50 up to Z 60: tool
    offset 1 is X50 Z100 (LATHE_OFFSETS), so the tip is (machine X - 50, machine Z - 100). At program X60
    (machine X 80, tip X 30) the holder covers X 30..70, in the chuck's -50..50; its bottom is at machine
    Z - 100 + 10, below 60 once machine Z < 150. The line down to program Z 45 (machine Z 145) enters it by
    5 mm: the prover says unsafe, the controller alarms, and a prover blind to the solids fails S1."""
    from fractions import Fraction as F

    from .contract import ContractViolation

    tools = {1: [("insert", F(-2), F(0), F(0), F(10), F(0)), ("holder", F(0), F(40), F(10), F(40), F(0))],
             2: [("insert", F(0), F(2), F(0), F(5), F(0))]}
    fixtures = [{"name": "chuck0", "kind": "chuck", "r": F(50), "r_in": F(0), "z0": F(0), "z1": F(60)}]
    text = "%\nO1\nG21 G18 G98 G40\nT0101\nG00 X60. Z100.\nG01 Z45. F2000\nM30\n%\n"
    assert check_lathe("0.01", tools, fixtures, text) == "unsafe"
    with pytest.raises(ContractViolation, match="grown by 4 pulses"):
        check_lathe("0.01", tools, fixtures, text, prove=_blind)


def test_the_prism_and_frame_contract_has_teeth():
    """A G55 box (X 0..20, Y 0..20, Z 0..35 in G55, whose origin is machine X 100) and a wedge prism (right
    angle at (-30, -30), legs 4k = 20 along +X and 3k = 15 along +Y, up to Z 20): tool 1's cutter (Ø10, H1 =
    25) at G55 X-3 Y10 is 2 mm into the box's side (its axis 5 from X0 would touch); lowered from Z50 to Z10
    it enters the box. The prover says unsafe, the controller alarms, a blind prover fails S1; a program run
    in G54 leaves the G55 box out (the prover unknown, VF219) and the controller with it."""
    from fractions import Fraction as F

    from .contract import ContractViolation

    tools = {1: ([("cutter", "10", "25")], "25"), 2: ([("cutter", "6", "20")], "20")}
    fixtures = [{"kind": "box", "name": "box0", "x0": "0", "x1": "20", "y0": "0", "y1": "20", "z0": "0", "z1": "35",
                 "frame": True},
                {"kind": "prism", "name": "wedge1", "x0": "-30", "y0": "-30", "k": "5", "sx": 1, "sy": 1, "z0": "0",
                 "z1": "20"}]
    g55 = (F(100), F(0), F(0))
    text = "G21 G90 G17 G55\nT1 M6\nG43 H1\nG0 X-3 Y10 Z50\nG1 Z10 F2000\nM30\n"
    assert check_mill("0.01", tools, fixtures, g55, text) == "unsafe"
    with pytest.raises(ContractViolation, match="grown by 4 pulses"):
        check_mill("0.01", tools, fixtures, g55, text, prove=_blind)
    # the wedge's hypotenuse from (-10, -30) to (-30, -15): at its midpoint (-20, -22.5) moved out along
    # (3, 4) / 5 by the cutter's radius 5 less 1 mm, the cutter is 1 mm into it (G54: machine coordinates)
    wedge = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X-17.6 Y-19.3 Z50\nG1 Z10 F2000\nM30\n"
    assert check_mill("0.01", tools, fixtures, g55, wedge) == "unknown"  # the G55 box is not placed in G54
    with pytest.raises(ContractViolation, match="grown by 4 pulses"):
        check_mill("0.01", tools, fixtures[1:], None, wedge, prove=_blind)
