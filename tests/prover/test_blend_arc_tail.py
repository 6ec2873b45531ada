"""A blend may trim up to two thirds of an arc before a corner: the prover's enclosure holds it (issue 35).

Found by the blend contract (tests/contract/test_blend_contract.py, the reference controller's arc-line blends,
written from LinuxCNC's tp.c ``tpCreateArcLineBlend``): the corner enclosure took the half of an arc's sweep at
the corner, but ``blendInit3FromArcLine`` lets the blend trim ``phi1_max = min(angle * 2/3, pi/2)`` of the arc
before it (concave corner: the line leaves the arc's circle outward), and the trim is only checked against
that.  The program below (a clockwise arc of radius 100 around the origin from (96, 28) to (100, 0), sweep
atan2(28, 96) = 0.2838 rad, then a line to (300, -20), 82 degrees to the left) in G64 on slow axes
(1 mm/s^2, F3000: the planner takes the largest blend the lengths allow) blends from 55 % of the arc's sweep
before the corner.  The half of the sweep at the corner ends at angle 0.1419 rad, Y = 100 sin 0.1419 = 14.14,
and every point of the enclosure (the half arc's box plus the line's half box less the corner) has
Y <= 14.14; the blend runs through (99.035, 14.191), 0.047 mm outside the circle and off the line, where the
clamp of the test sits.  ``safe`` was the verdict (a wrong one); with the arc's last three quarters in the
enclosure it is ``unknown``, and still ``safe`` in G61 (the programmed path misses the clamp).
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

from nczones.controller import simulate
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

MACHINE = machine_text("xyz_slow_arc_corner")  # tests/machines/xyz_slow_arc_corner.toml
CORNER = "G2 F3000 X100 Y0 I-96 J-28\nG1 X300 Y{y}\nG61\nG4 P0\n"


def _program(kind: str, mode: str = "G64") -> str:
    if kind == "short":
        return f"G61\nG0 X96 Y28\n{mode}\n" + CORNER.format(y="-20")
    if kind == "columns":  # > 512 motions before the corner: the vectorized tier
        zigzag = "".join(f"G1 X{90 + k % 2} Y30\n" for k in range(600))
        # (the line to the arc's start in G61: no blend trims the arc's start)
        return f"G61\nG0 X90 Y30\n{mode}\nG1 F3000\n{zigzag}G61\nG1 X96 Y28\n{mode}\n" + CORNER.format(y="-20")
    return f"#1=20\nG61\nG0 X96 Y28\n{mode}\n" + CORNER.format(y="-#1")  # '#': the double pass


def test_the_clamp_is_off_the_programmed_path():
    # the clamp's nearest point to the origin (its lower left corner) is more than 0.04 mm outside the circle of
    # radius 100 the arc runs on, and its Y (>= 14.186) is above the line from (100, 0) down to (300, -20)
    assert Fraction("99.030") ** 2 + Fraction("14.186") ** 2 > Fraction("100.04") ** 2


@pytest.mark.parametrize("kind", ["short", "columns", "hash"])
def test_an_arc_trimmed_beyond_its_half_is_not_proved_safe(kind):
    m = parse_machine(MACHINE)
    text = _program(kind)
    alarms = simulate(interpret_text(text, m, fast=False), m).alarms
    assert alarms and alarms[0].zone == "clamp" and alarms[0].derived == "G64 blend arc"
    assert verify_text(text, m).verdict.label == "unknown"
    assert verify_text(_program(kind, "G61"), m).verdict.label == "safe"


def test_the_planner_may_trim_two_thirds_of_the_arc():
    # the spec's bound (specs/path-modes.md §2): the controller's trim here is more than half, at most 2/3
    from nczones.controller.blending import BlendArc, blend_motion

    m = parse_machine(MACHINE)
    run = interpret_text(_program("short"), m, fast=False)
    items = list(blend_motion(list(run.segments()), m, run))
    piece = next(i for i in items if isinstance(i, BlendArc) and i.circle is not None)
    sweep = math.atan2(28, 96)
    assert 0.5 < 1 - piece.circle.angle / sweep <= 2 / 3
