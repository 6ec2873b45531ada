"""The certified-violation test of a rational box (`box_certainly_violates`): every point of the box violates.

It is what arcs, splines and developed arcs use to certify a witness without the solver, so a wrong
`True` would be an `unsafe` whose point is not one, and a needless `False` a decidable violation left
to the solver and the budget (the long metamorphic run found a spiral 8 mm outside the travel box,
certified at margin 0 and `unknown` after 60 s at margin 0.5, because its plane lay exactly at the
travel limit less the margin on an axis where the box has no width).
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from pathlib import Path

from hypothesis import event, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.prover.exact import box_certainly_violates
from nczones.testing import machines
from tests.machines import machine_text
from tests.sizes import examples

F = Fraction
ROOT = Path(__file__).resolve().parents[2]


@st.composite
def boxes_near_zones(draw):
    """A machine, a margin and a rational box whose sides sit on zone constants shifted by the margin (or
    near them), often flat on one or more axes."""
    machine = draw(machines(axes=("X", "Y", "Z"), allow_kinds=("box", "stepped", "polygon"), size=100))
    margin = draw(st.sampled_from((F(0), F(1, 2), F(1), F(5, 2))))
    tool_length = draw(st.sampled_from((F(0), *machine.tool_lengths.values())))
    consts: dict[str, set[Fraction]] = {a: {F(0)} for a in machine.axis_names}
    for z in machine.zones:
        for a, (lo, hi) in z.bounds().items():
            consts[a] |= {v for v in (lo, hi) if v is not None}
    lo, hi = {}, {}
    for a in machine.axis_names:
        base = draw(st.sampled_from(sorted(consts[a])))
        off = draw(st.sampled_from((F(0), margin, -margin, F(1, 3), F(-7, 2), F(20), F(-20))))
        if a == "Z" and draw(st.booleans()):
            off += tool_length
        width = draw(st.sampled_from((F(0), F(0), F(1, 2), F(3), F(40))))
        lo[a], hi[a] = base + off, base + off + width
    return machine, margin, tool_length, lo, hi


@settings(max_examples=examples(50, 100), deadline=None)
@given(boxes_near_zones(), st.data())
def test_a_certified_box_violates_at_every_point(case, data):
    machine, margin, tool_length, lo, hi = case
    axes = machine.axis_names
    for zone in machine.zones:
        if not box_certainly_violates(machine.allowed, zone, lo, hi, margin, tool_length):
            continue
        event(f"certified: {zone.kind}{' forbid' if zone.forbid else ''}")
        corners = [dict(zip(axes, c)) for c in itertools.product(*((lo[a], hi[a]) for a in axes))]
        inner = [{a: lo[a] + (hi[a] - lo[a]) * data.draw(st.fractions(0, 1, max_denominator=64)) for a in axes}
                 for _ in range(8)]
        for p in corners + inner:
            assert zone in machine.allowed.violated_zones(p, tool_length, margin), (zone.name, p, margin)


TRAVEL = parse_machine(machine_text("xyz_travel_100_200"))


def test_a_flat_box_on_a_shifted_face_is_certified():
    travel = TRAVEL.zones[0]
    # X far outside; Z exactly at the face less the margin (flat), and across it (with width)
    flat = ({"X": F(-8), "Y": F(40), "Z": F(399, 2)}, {"X": F(-7), "Y": F(45), "Z": F(399, 2)})
    wide = ({"X": F(-8), "Y": F(40), "Z": F(199)}, {"X": F(-7), "Y": F(45), "Z": F(200)})
    for lo, hi in (flat, wide):
        assert box_certainly_violates(TRAVEL.allowed, travel, lo, hi, F(1, 2), F(0))
    # inside on every axis: not certified
    assert not box_certainly_violates(TRAVEL.allowed, travel, {"X": F(10), "Y": F(40), "Z": F(100)},
                                      {"X": F(20), "Y": F(45), "Z": F(199)}, F(1, 2), F(0))


def test_a_spiral_outside_the_travel_in_the_margin_plane_is_unsafe_at_every_margin():
    """The long run's case: a G2 spiral (radius 9.5 to 9.501) that swings 8 mm beyond X0 in the plane
    Z = 199.5, which is the travel limit 200 less the margin 0.5."""
    for z, margin in (("199.5", "0"), ("199.5", "0.5"), ("199", "1")):
        program = f"G90 G0 X1.5 Y33 Z{z}\nG2 X1.5 Y52.001 I0 J9.5 F600\nM30\n"
        result = verify_text(program, TRAVEL, margin=margin, budget_s=20)
        assert result.verdict.label == "unsafe" and result.violations[0].line == 2, (margin, result.reasons)
        assert result.violations[0].engine == "exact"
