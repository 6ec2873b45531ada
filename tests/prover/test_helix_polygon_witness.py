"""A helix whose margin box crosses a slanted polygon edge (issue: ~55 s to ``unknown``; the same arc without Z:
``unsafe`` in 0.5 s).

The circle of centre X0 Y0 and radius 10 passes at 45 degrees through X7.0711 Y7.0711; the polygon's edge from
X4 Y12 to X12 Y4 lies on ``x + y = 16``, 16/sqrt(2) - 10 = 1.314 mm from the circle, so the tool's margin box of
half-width 1 (corner at x + y = 14.142 + 2 = 16.142) crosses the edge there while the path itself stays 1.3 mm
clear: ``unsafe`` with the margin, for the arc and for the helix whose Z sinks 0.001 mm over the turn (Z does not
matter: the polygon has no Z bounds).  The exact tier certifies points of the path by rational boxes; a helix
point is exact in X Y (a rational point of the circle) and only enclosed in Z, and the polygon test refused any
box whose margin box meets an edge, so the helix went to the solver's refinement until the budget was spent.
A box of one point in the polygon's plane now decides the polygon part at that point.
"""

from __future__ import annotations

import time

import pytest

from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

MACHINE = parse_machine(machine_text("helix_post_polygon"))


def _programs(arc: str) -> dict[str, str]:
    many = "".join(f"G1 F1000 X{10 - (k % 2)} Y0 Z0\n" for k in range(600))
    return {
        "short": f"G0 X10 Y0 Z0\n{arc}\nM2\n",
        "many": f"G0 X10 Y0 Z0\n{many}G1 X10 Y0 Z0\n{arc}\nM2\n",  # > 512 motions: the vectorized tier
        "hash": f"#1 = 10\nG0 X#1 Y0 Z0\n{arc.replace('I-10', 'I-#1')}\nM2\n",  # the double pass
    }


@pytest.mark.parametrize("lane", ["short", "many", "hash"])
@pytest.mark.parametrize("arc", ["G2 X10 Y0 I-10 J0 F100", "G2 X10 Y0 Z-0.001 I-10 J0 F100",
                                 "G3 X-8 Y6 Z-0.001 R10 F100"])
def test_helix_margin_box_across_a_slanted_edge_is_unsafe_fast(lane, arc):
    text = _programs(arc)[lane]
    t0 = time.monotonic()
    r = verify_text(text, MACHINE, margin="1", budget_s=10)
    took = time.monotonic() - t0
    assert r.verdict.label == "unsafe", r.reasons if hasattr(r, "reasons") else r
    assert {v.zone for v in r.violations} == {"post"}
    assert all(v.line == text.splitlines().index(arc.replace("I-10", "I-#1") if lane == "hash" else arc) + 1
               for v in r.violations)
    assert took < 5


def test_without_margin_the_helix_is_safe():
    """The path itself stays 1.3 mm from the edge: without the margin every lane proves it."""
    r = verify_text("G0 X10 Y0 Z0\nG2 X10 Y0 Z-0.001 I-10 J0 F100\nM2\n", MACHINE, budget_s=10)
    assert r.verdict.label == "safe"
