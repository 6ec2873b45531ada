"""Machines at concrete parameter values and machines with shifted zones, built without prover code.

The metamorphic soundness suite compares a verdict over parameter ranges with verdicts at concrete
values; these helpers make the concrete machines by plain dataclass replacement, independently of
:mod:`nczones.prover.cases`.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from types import MappingProxyType

from nczones.machine import Machine
from nczones.zones import AllowedSet, BoxZone, PolygonZone, Region, SteppedZone


def machine_at(machine: Machine, values: dict[str, Fraction]) -> Machine:
    """``machine`` with parameters fixed: ``G54.X`` and ``start.Z`` deviate from the file, ``H1`` is absolute."""
    offsets = {k: list(v) for k, v in machine.offsets.items()}
    tools = dict(machine.tool_lengths)
    start = list(machine.start)
    for name, value in values.items():
        value = Fraction(value)
        if name.startswith("H"):
            tools[int(name[1:])] = value
            continue
        head, axis = name.rsplit(".", 1)
        k = machine.axis_names.index(axis)
        if head == "start":
            start[k] += value
        elif head == "home":
            raise ValueError("homing errors are not interpreted; shift the zones instead")
        else:
            offsets.setdefault(head, list(machine.offset(head)))[k] += value
    return replace(machine, offsets=MappingProxyType({k: tuple(v) for k, v in offsets.items()}),
                   tool_lengths=MappingProxyType(tools), start=tuple(start))


def _shift(value, d):
    return None if value is None else value + d


def shift_zones(machine: Machine, by: dict[str, Fraction]) -> Machine:
    """``machine`` with every zone moved by the vector ``by`` (axis -> distance); the program stays.

    Moving the zones by ``-v`` is moving the whole path by ``v`` (G53 and G28 targets included).
    """
    out = []
    for z in machine.allowed.zones:
        if isinstance(z, BoxZone):
            out.append(replace(z, limits=tuple((a, _shift(lo, by.get(a, 0)), _shift(hi, by.get(a, 0)))
                                               for a, lo, hi in z.limits)))
        elif isinstance(z, SteppedZone):
            dr, dl = by.get(z.reference_axis, 0), by.get(z.limited_axis, 0)
            out.append(replace(z, start=z.start + dr, regions=tuple(
                Region(r.upto + dr, _shift(r.min, dl), _shift(r.max, dl)) for r in z.regions)))
        elif isinstance(z, PolygonZone):
            da, db = by.get(z.plane[0], 0), by.get(z.plane[1], 0)
            out.append(replace(z, vertices=tuple((x + da, y + db) for x, y in z.vertices),
                               limits=tuple((a, _shift(lo, by.get(a, 0)), _shift(hi, by.get(a, 0)))
                                            for a, lo, hi in z.limits)))
        else:  # pragma: no cover - a new zone kind
            raise TypeError(z)
    return replace(machine, allowed=AllowedSet(tuple(out), machine.allowed.tool_axis))
