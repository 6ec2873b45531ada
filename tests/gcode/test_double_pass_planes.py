"""The double pass's arcs in G18 and G19 (plane38): the pass's proof against the full path's on a zone face
at an arc's exact extreme.

The arcs lie on the circle of radius 10 about the plane's origin: from (10, 0) to (-6, 8) in the plane's
(first, second) axes (G18: Z, X; G19: Y, Z, as the full path's ``PLANE_AXES``), by the centre words (G18: K and
I) or by R, counter-clockwise the short way (through (0, 10)) or clockwise the long way (through (0, -10) and
(-10, 0)), and as a helix.  The extremes are exact (10), and the direction decides which of them the arc
reaches: a face 1e-12 mm inside an extreme the arc reaches is ``unsafe`` both ways (a pass that took G2 for G3
in a plane would prove it ``safe``: the mutation check of plane38), on it and beyond it as the full path
decides, and 1e-9 mm beyond it proved by the pass.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.machine import parse_machine
from nczones.motion import PLANE_AXES, Plane
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import check_against_full
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import both_ways, same_outcome

_CENTRE = {"X": "I", "Y": "J", "Z": "K"}
#: (the arc's words in the plane's first/second axes ``a``, ``b`` and centre words ``i``, ``j``; the normal
#: axis ``n``), and the extremes it reaches: (0 first axis / 1 second, sign).
ARCS = {
    "ccw by centre": ("G3 {a}-6 {b}8 {i}-10 {j}0", [(1, 1)]),
    "cw by centre": ("G2 {a}-6 {b}8 {i}-10 {j}0", [(1, -1), (0, -1)]),
    "ccw by R": ("G3 {a}-6 {b}8 R10", [(1, 1)]),
    "cw by R, the long way": ("G2 {a}-6 {b}8 R-10", [(1, -1), (0, -1)]),
    "a helix": ("G3 {a}-6 {b}8 {n}3 {i}-10 {j}0", [(1, 1)]),
}
CASES = [(plane, name, axis, sign) for plane in (18, 19) for name, (_w, ext) in sorted(ARCS.items())
         for axis, sign in ext]


def program(plane: int, name: str) -> str:
    """The arc ``name`` in ``plane`` after a move to its start (a parametric program: the pass's route)."""
    a, b, n = PLANE_AXES[Plane(plane)]
    words = ARCS[name][0].format(a=a, b=b, n=n, i=_CENTRE[a], j=_CENTRE[b])
    return f"G21 G90 G{plane} G54 F300\n#1 = 10\nG0 {a}#1 {b}0\n{words}\nM30\n"


def machine(axis: str, sign: int, face: Fraction):
    """box_5000 in exact stop (G61: no blended corner) with its travel's face on ``axis`` (``sign``) at
    ``sign * face``."""
    text = machine_text("box_5000", set={"machine.path_mode": "G61"})
    line = 'max = { X = "5000", Y = "5000", Z = "5000" }' if sign > 0 else 'min = { X = "-5000", Y = "-5000", Z = "-5000" }'
    value = sign * face
    places = f"{float(value):.15f}".rstrip("0")  # the faces here are decimals of at most 12 places
    assert Fraction(places) == value
    return parse_machine(text.replace(line, line.replace(f'{axis} = "{sign * 5000}"', f'{axis} = "{places}"')))


@pytest.mark.parametrize("plane, name", [(p, n) for p in (18, 19) for n in sorted(ARCS)])
def test_the_pass_takes_the_arc_and_encloses_the_full_paths(plane, name):
    text = program(plane, name)
    path = check_against_full(text, parse_machine(machine_text("box_5000")))
    assert path is not None and path.arcs == 1
    a, b, _n = PLANE_AXES[Plane(plane)]
    assert path.arc_axes == ("XYZ".index(a), "XYZ".index(b)) and list(path.arc_planes) == [0]


@pytest.mark.parametrize("plane, name, axis, sign", CASES)
def test_a_face_at_the_arcs_extreme_is_decided_as_the_full_path_does(plane, name, axis, sign, monkeypatch):
    on = PLANE_AXES[Plane(plane)][axis]
    text = program(plane, name)
    for eps in (Fraction(-1, 10**12), Fraction(0), Fraction(1, 10**12), Fraction(1, 10**9)):
        with_pass, without = both_ways(text, machine(on, sign, 10 + eps), monkeypatch)
        same_outcome(with_pass, without)
        if eps < 0:
            assert with_pass.verdict is Verdict.UNSAFE, (eps, with_pass.reasons)
        else:
            assert with_pass.verdict is Verdict.SAFE, (eps, with_pass.reasons)
        if eps > Fraction(1, 10**10):  # past the pass's rounding: its proof
            assert "double_pass_boxes" in dict(with_pass.stats)


def test_arcs_in_two_planes_each_on_its_planes_axes():
    """Arcs in two planes (arc40): each arc's box on its own plane's (first, second) axes
    (``DoublePath.arc_pair``), and the full path's arcs inside them."""
    text = program(18, "ccw by R").replace("M30\n", "G17 G0 X10 Y0\nG3 X-6 Y8 R10\nG18 G0 Z10 X0\n"
                                                   "G2 Z-6 X8 K-10 I0\nM30\n")
    path = check_against_full(text, parse_machine(machine_text("box_5000")))
    assert path is not None and path.arcs == 3
    assert [path.arc_pair(k) for k in range(3)] == [(2, 0), (0, 1), (2, 0)]
    assert path.arc_axes == (2, 0, 0, 1) and list(path.arc_planes) == [0, 1, 0]
