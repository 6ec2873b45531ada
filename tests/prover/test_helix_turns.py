"""A multi-turn helix (``P2`` and up) that leaves the allowed set is unsafe with a witness (issue 19).

The helix is written as G-code; its witness is checked against the helix in floating point
(an independent evaluation: the angle of the reported point, every pass over it, the height there).
"""

import math
from fractions import Fraction as F

import pytest

from nczones.machine import parse_machine
from nczones.prover import Verdict, verify_text
from tests.machines import machine_text

#: allowed: Z >= -40 for X <= 5, only Z >= -25 for 5 < X <= 50 (a stepped table), X/Y within +-50
MACHINE = parse_machine(machine_text("helix_stepped_table"))


def program(turns: int, z_end: int) -> str:
    # counter-clockwise around (0, 0) from (10, 0) to (-10, 0): P1 half a turn, each P one more
    return f"G17 G90 G54\nG1 X10 Y0 Z0 F100\nG3 X-10 Y0 Z{z_end} I-10 J0 P{turns}\nG1 Z0\nM2\n"


def helix_heights(x: float, y: float, turns: int, z_end: float) -> list[float]:
    """Heights of the helix at every pass over the direction of (x, y) (sweep (turns - 1/2) * 2 pi)."""
    sweep = (2 * turns - 1) * math.pi
    a = math.atan2(y, x) % (2 * math.pi)
    out = []
    while a <= sweep + 1e-12:
        out.append(z_end * a / sweep)
        a += 2 * math.pi
    return out


@pytest.mark.parametrize("turns", [2, 3])
def test_multi_turn_helix_leaving_the_table_is_unsafe_with_a_witness_on_the_helix(turns):
    r = verify_text(program(turns, -40), MACHINE)
    assert r.verdict is Verdict.UNSAFE, r.reasons
    assert not r.reasons
    (v,) = r.violations
    assert v.line == 3 and v.segment_kind == "helix" and v.zone == "table"
    point = dict(v.point)
    assert MACHINE.allowed.violated_zones(point, F(0))
    x, y, z = (float(point[a]) for a in "XYZ")
    assert math.hypot(x, y) == pytest.approx(10, abs=1e-9) and x > 5 and z < -25
    assert any(abs(h - z) < 1e-6 for h in helix_heights(x, y, turns, -40)), "not a point of the helix"


def test_the_same_helix_that_stays_above_the_table_is_safe_and_half_a_turn_is_too():
    assert verify_text(program(2, -30), MACHINE).verdict is Verdict.SAFE  # beyond X5 it stays above Z-20
    assert verify_text(program(1, -40), MACHINE).verdict is Verdict.SAFE  # over X > 5 only at Z > -14
