"""Where the proof puts each zone for one tool placement: what figures draw (one model for plot, the HTML
report and the notebooks).

A tool-tip zone is seen by the tool tip, so in machine coordinates it moves by the active tool's length on
the tool axis and by its offsets on the other axes (a lathe's X), exactly as the prover moves it
(:func:`nczones.zones.tip_shifted`); on a lathe whose tools have a nose radius the prover proves the tip zones
enlarged by the nose's reach (:func:`nczones.prover.nose.nose_zones`), so they are drawn enlarged too.
"""

from __future__ import annotations

import types
from fractions import Fraction
from typing import Any

from ..machine import Machine
from ..motion import Segment, tip_offset
from ..prover.nose import nose_zones
from ..zones import Zone, tip_shifted

__all__ = ["Placement", "drawing_machine", "placed_zones", "placement_label", "placement_of"]


Placement = tuple[Fraction, tuple[tuple[str, Fraction], ...]]
"""Where a segment's tool tip is: (tool length on the tool axis, offsets on other axes as ``Segment.extra``'s
``tip_offset``)."""


def placement_of(seg: Segment) -> Placement:
    """The tool placement a segment carries (what its tool-tip zones see)."""
    return (seg.tool_length or Fraction(0), tuple(sorted(tip_offset(seg.extra).items())) if seg.extra else ())


def placed_zones(machine: Machine, placement: Placement | None) -> tuple[Zone, ...]:
    """The machine's zones in machine coordinates for one tool placement: the tool-tip zones moved by the
    tool length on the tool axis and by the tool offsets on the other axes, exactly as the prover places
    them (:func:`nczones.zones.tip_shifted` of the segment's :func:`nczones.zones.tip_offset`, and
    :meth:`nczones.zones.AllowedSet.seen_by` for the tool length); machine zones unchanged.

    >>> from nczones import load_machine
    >>> m = load_machine("specs/machines/fanuc_lathe.toml")
    >>> jaws = next(z for z in placed_zones(m, (Fraction(50), (("X", Fraction(80)),))) if z.name == "jaws")
    >>> [(a, str(lo), str(hi)) for a, lo, hi in jaws.limits]  # X105-112 Z150-190, grown by a nose reach of 0.8
    [('X', '521/5', '564/5'), ('Z', '746/5', '954/5')]
    """
    if placement is None:
        return tuple(machine.zones)
    machine = nose_zones(machine)[0]  # the tip zones as the proof checks them: enlarged by a nose radius
    length, tip = placement
    shift = dict(tip)
    axis = machine.allowed.tool_axis
    if length and axis is not None:
        shift[axis] = shift.get(axis, Fraction(0)) + length
    return tip_shifted(machine.allowed, shift).zones if any(shift.values()) else tuple(machine.zones)


def placement_label(machine: Machine, placement: Placement | None) -> str:
    """How a placement reads in a legend: ``"tool tip, tool offset Z50 X80"`` (a lathe), ``"tool tip, tool length
    120"`` (a mill)."""
    from ..exact import format_decimal

    if placement is None:
        return "tool tip"
    length, tip = placement
    others = [f"{a}{format_decimal(v)}" for a, v in tip if v]
    if not others:  # a mill: the tool length alone
        return f"tool tip, tool length {format_decimal(length)}" if length else "tool tip"
    parts = ([f"{machine.allowed.tool_axis}{format_decimal(length)}"] if length and machine.allowed.tool_axis else [])
    return "tool tip, tool offset " + " ".join(parts + others)



def drawing_machine(machine: Machine, placement: Placement | None) -> Any:
    """A drawing proxy of ``machine`` whose zones are :func:`placed_zones`."""
    if placement is None:
        return machine
    return types.SimpleNamespace(name=machine.name, axes=machine.axes, axis_names=machine.axis_names,
                                 start=machine.start, reference=machine.reference,
                                 zones=placed_zones(machine, placement))
