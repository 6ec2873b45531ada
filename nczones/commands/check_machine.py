"""``nczones check-machine M.toml``: validate a machine file and summarise it (exit 0 valid, 2 not).

:func:`describe_machine` writes the summary; how it describes a zone is a table per zone kind,
:data:`ZONE_LINES` (docs/design.md §10, "How to add a zone kind").
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from fractions import Fraction
from typing import Any

from ..exact import format_decimal
from ..machine import Machine, load_machine
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone
from ..zones.kinds import KindTable
from .conventions import EXIT_OK

__all__ = ["configure", "describe_machine", "ZONE_LINES"]


def _bound(value: Fraction | None) -> str:
    return "unbounded" if value is None else format_decimal(value)


def _zone_lines(z: Zone, role: str, tip: str, extra: str = "") -> list[str]:
    ranges = ", ".join(f"{a} [{_bound(lo)}, {_bound(hi)}]" for a, (lo, hi) in z.bounds().items())
    return [f"    {z.name}: {role} {z.kind}{tip}{extra} {ranges}"]


#: The lines of ``check-machine`` that describe one zone (``role`` "allow"/"forbid", ``tip`` " (tool tip)" or
#: ""), per zone kind.  Fallback: its kind and bounds.
ZONE_LINES: KindTable[Callable[[Any, str, str], list[str]]] = KindTable("commands.check_machine.zone_lines",
                                                                     fallback=_zone_lines)
ZONE_LINES.set(BoxZone, _zone_lines)


@ZONE_LINES.register(PolygonZone)
def _polygon_lines(z: PolygonZone, role: str, tip: str) -> list[str]:
    return _zone_lines(z, role, tip, f" in {z.plane[0]}{z.plane[1]} with {len(z.vertices)} vertices")


@ZONE_LINES.register(SteppedZone)
def _stepped_lines(z: SteppedZone, role: str, tip: str) -> list[str]:
    lines = [
        f"    {z.name}: {role} stepped table{tip}, {z.limited_axis} limited by "
        f"{z.reference_axis}, {len(z.regions)} regions from {format_decimal(z.start)}"
    ]
    lower = z.start
    for i, r in enumerate(z.regions):
        bracket = "[" if i == 0 else "("
        lines.append(
            f"      region {i + 1}: {z.reference_axis} {bracket}{format_decimal(lower)}, "
            f"{format_decimal(r.upto)}] -> {z.limited_axis} [{_bound(r.min)}, {_bound(r.max)}]"
        )
        lower = r.upto
    return lines


def describe_machine(machine: Machine) -> str:
    """A readable summary of a machine (what ``check-machine`` prints).

    Examples
    --------
    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('''
    ... [machine]
    ... name = "demo"
    ... axes = ["X"]
    ... [machine.rapid]
    ... X = "1000"
    ... [machine.reference]
    ... X = "5"
    ... [[zones]]
    ... name = "travel"
    ... kind = "box"
    ... min = { X = "0" }
    ... max = { X = "10" }
    ... ''', "demo.toml")
    >>> print(describe_machine(m))
    demo.toml: machine "demo" is valid
      axes: X (linear, pulse 0.001 mm, rapid 1000 mm/min)
      rapid mode: linear; limit monitor every 5 ms
      reference: X5; start: X5
      zones (1):
        travel: allow box X [0, 10]
      allowed set lies within: X [0, 10]
    """
    lines = [f"{machine.source}: machine \"{machine.name}\" is valid"]
    axes = []
    for a in machine.axes:
        unit = "deg" if a.rotary else "mm"
        axes.append(
            f"{a.name} ({'rotary' if a.rotary else 'linear'}, pulse {format_decimal(a.pulse)} {unit}, "
            f"rapid {format_decimal(a.rapid_mm_min)} {unit}/min)"
        )
    lines.append("  axes: " + ", ".join(axes))
    lines.append(
        f"  rapid mode: {machine.rapid_mode.value}; limit monitor every "
        f"{format_decimal(machine.monitor_period_ms)} ms"
    )

    def pt(coords: tuple[Fraction, ...]) -> str:
        return " ".join(f"{n}{format_decimal(c)}" for n, c in zip(machine.axis_names, coords))

    lines.append(f"  reference: {pt(machine.reference)}; start: {pt(machine.start)}")
    if machine.offsets:
        lines.append("  work offsets: " + "; ".join(f"{k} {pt(v)}" for k, v in machine.offsets.items()))
    if machine.tool_lengths:
        lines.append(
            "  tool lengths: "
            + ", ".join(f"H{k} {format_decimal(v)}" for k, v in sorted(machine.tool_lengths.items()))
        )
    if machine.is_lathe or machine.diameter_axes:
        dia = ", ".join(machine.diameter_axes)
        lines.append(f"  type: {machine.machine_type}" + (
            f"; program words on {dia} are diameters (machine coordinates and zones are radii)" if dia else ""))
    for n, t in sorted(machine.tool_offsets.items()):
        def val(a: str, v: Fraction) -> str:
            return f"{a}{format_decimal(v)}" + (f" (diameter {format_decimal(2 * v)})"
                                                if a in machine.diameter_axes else "")
        parts = [val(a, v) for a, v in t.geometry]
        if t.wear:
            parts.append("wear " + " ".join(val(a, v) for a, v in t.wear))
        if t.nose_radius or t.wear_radius:
            parts.append(f"nose radius {format_decimal(t.nose_radius + t.wear_radius)}")
        parts.append(f"tip {t.tip}")
        lines.append(f"  tool offset {n}: " + ", ".join(parts))
    lines.append(f"  zones ({len(machine.zones)}):")
    for z in machine.zones:
        role = "forbid" if z.forbid else "allow"
        tip = " (tool tip)" if z.point.value == "tip" else ""
        lines += ZONE_LINES(z, role, tip)
    bbox = machine.allowed.bounding_box()
    if bbox:
        lines.append(
            "  allowed set lies within: "
            + ", ".join(f"{a} [{_bound(lo)}, {_bound(hi)}]" for a, (lo, hi) in bbox.items())
        )
    else:
        lines.append("  allowed set: unbounded (no machine-point allow zone)")
    for w in machine.warnings:
        lines.append(w.render())
    return "\n".join(lines)


def _run_check_machine(args: argparse.Namespace) -> int:
    machine = load_machine(args.machine_file)
    print(describe_machine(machine))
    return EXIT_OK


def configure(p: argparse.ArgumentParser) -> None:
    p.add_argument("machine_file", metavar="M.toml", help="the machine file to check (specs/machine-file.md)")
    p.set_defaults(handler=_run_check_machine)
