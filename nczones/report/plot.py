"""Plots of the allowed set and toolpaths (matplotlib; floats for drawing only).

:func:`plot_zones` draws the zones of a machine in the plane of two axes:
allow zones shaded, the area outside them grey, forbid zones hatched red.
:func:`plot_path` draws motion segments over it (rapids dashed, arcs
sampled finely), and :func:`mark_points` marks counterexample points.
Nothing here feeds back into a proof.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from fractions import Fraction
from typing import Any

import matplotlib.pyplot as plt
from matplotlib.patches import Polygon as PolygonPatch
from matplotlib.patches import Rectangle

from ..exact import to_float
from ..machine import Machine
from ..motion import Segment, SegmentKind, arc_path_float
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone
from ..zones.kinds import KindTable

__all__ = ["plot_zones", "plot_path", "mark_points", "plot_machine", "path_points_float", "view_limits"]

_ALLOW = "#cfe8cf"
_FORBID = "#e06666"
_OUTSIDE = "#e6e6e6"


def view_limits(machine: Machine, plane: tuple[str, str], pad_fraction: float = 0.08) -> tuple[tuple[float, float], tuple[float, float]]:
    """Float view limits covering every finite zone bound in the plane."""
    out = []
    for axis in plane:
        values = [machine.start[machine.axis_names.index(axis)], machine.reference[machine.axis_names.index(axis)]]
        for z in machine.zones:
            lo, hi = z.bounds().get(axis, (None, None))
            values += [v for v in (lo, hi) if v is not None]
        lo_f, hi_f = to_float(min(values)), to_float(max(values))
        pad = (hi_f - lo_f) * pad_fraction or 10.0
        out.append((lo_f - pad, hi_f + pad))
    return out[0], out[1]


def _finite(v: Fraction | None, default: float) -> float:
    return default if v is None else to_float(v)


def zone_patches(zone: Zone, plane: tuple[str, str], xlim: Any, ylim: Any) -> tuple[str, list[Any]] | None:
    """Rectangles/polygons (float) that draw ``zone`` in ``plane``; None if not drawable."""
    return ZONE_PATCHES(zone, plane)


def _bounds_patches(zone: Zone, plane: tuple[str, str]) -> tuple[str, list[Any]] | None:
    h, v = plane
    bounds = zone.bounds()
    if h not in bounds and v not in bounds:
        return None
    hx = bounds.get(h, (None, None))
    vy = bounds.get(v, (None, None))
    x0, x1 = _finite(hx[0], -1e9), _finite(hx[1], 1e9)
    y0, y1 = _finite(vy[0], -1e9), _finite(vy[1], 1e9)
    return ("rects", [((x0, y0), x1 - x0, y1 - y0)])


#: :func:`zone_patches` per zone kind.  Fallback: the rectangle of its bounds.
ZONE_PATCHES: KindTable[Callable[[Any, tuple[str, str]], tuple[str, list[Any]] | None]] = KindTable(
    "report.plot.zone_patches", fallback=_bounds_patches)
ZONE_PATCHES.set(BoxZone, _bounds_patches)


@ZONE_PATCHES.register(SteppedZone)
def _stepped_patches(zone: SteppedZone, plane: tuple[str, str]) -> tuple[str, list[Any]] | None:
    h, v = plane
    rects = []
    if {zone.reference_axis, zone.limited_axis} != {h, v}:
        return None
    for i, reg in enumerate(zone.regions):
        a, b = to_float(zone.region_lower(i)), to_float(reg.upto)
        lo, hi = _finite(reg.min, -1e9), _finite(reg.max, 1e9)
        if zone.reference_axis == h:
            rects.append(((a, lo), b - a, hi - lo))
        else:
            rects.append(((lo, a), hi - lo, b - a))
    return ("rects", rects)


@ZONE_PATCHES.register(PolygonZone)
def _polygon_patches(zone: PolygonZone, plane: tuple[str, str]) -> tuple[str, list[Any]] | None:
    h, v = plane
    if tuple(zone.plane) in ((h, v), (v, h)):
        pts = [(to_float(p[0]), to_float(p[1])) for p in zone.vertices]
        if tuple(zone.plane) == (v, h):
            pts = [(y, x) for x, y in pts]
        return ("poly", pts)
    return _bounds_patches(zone, plane)


def plot_zones(machine: Machine, plane: tuple[str, str] | None = None, ax: Any = None, *,
               legend: bool = True) -> Any:
    """Draw the machine's zones in the plane of two axes.

    Parameters
    ----------
    machine : Machine
    plane : (str, str), optional
        Horizontal and vertical axis; default the machine's first two axes.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib Axes

    Examples
    --------
    >>> from nczones import load_machine
    >>> ax = plot_zones(load_machine("specs/machines/grinder.toml"))
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('X (mm)', 'Y (mm)')
    """
    if plane is None:
        plane = (machine.axis_names[0], machine.axis_names[1])
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4.5))
    xlim, ylim = view_limits(machine, plane)
    allow = [z for z in machine.zones if not z.forbid]
    if allow:
        ax.add_patch(Rectangle((xlim[0], ylim[0]), xlim[1] - xlim[0], ylim[1] - ylim[0], color=_OUTSIDE, zorder=0))
    for z in allow:
        drawn = zone_patches(z, plane, xlim, ylim)
        if drawn is None:
            continue
        kind, shapes = drawn
        label = f"{z.name} (allowed{', tool tip' if z.point.value == 'tip' else ''})"
        if kind == "rects":
            for k, (xy, w, hgt) in enumerate(shapes):
                ax.add_patch(Rectangle(xy, w, hgt, facecolor=_ALLOW, edgecolor="#4c8c4c", lw=1.0, zorder=1, label=label if k == 0 else None))
        else:
            ax.add_patch(PolygonPatch(shapes, closed=True, facecolor=_ALLOW, edgecolor="#4c8c4c", zorder=1, label=label))
    for z in machine.zones:
        if not z.forbid:
            continue
        drawn = zone_patches(z, plane, xlim, ylim)
        if drawn is None:
            continue
        kind, shapes = drawn
        label = f"{z.name} (forbidden{', tool tip' if z.point.value == 'tip' else ''})"
        if kind == "rects":
            for k, (xy, w, hgt) in enumerate(shapes):
                ax.add_patch(Rectangle(xy, w, hgt, facecolor=_FORBID, alpha=0.35, hatch="//", edgecolor=_FORBID, zorder=2, label=label if k == 0 else None))
        else:
            ax.add_patch(PolygonPatch(shapes, closed=True, facecolor=_FORBID, alpha=0.35, hatch="//", edgecolor=_FORBID, zorder=2, label=label))
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    unit = {a.name: ("deg" if a.rotary else "mm") for a in machine.axes}
    ax.set_xlabel(f"{plane[0]} ({unit[plane[0]]})")
    ax.set_ylabel(f"{plane[1]} ({unit[plane[1]]})")
    ax.set_title(machine.name)
    if legend:
        ax.legend(loc="best", fontsize=8, framealpha=0.9)
    return ax


def _arc_float_points(seg: Segment, steps_per_turn: int = 360) -> list[tuple[float, ...]]:
    """Float samples along an arc (for drawing); the exact geometry lives in the prover."""
    at, sweep = arc_path_float(seg)
    n = max(8, int(abs(sweep) / (2 * math.pi) * steps_per_turn))
    return [tuple(at(k / n)) for k in range(n + 1)]


def _developed_arc_float_points(seg: Segment, samples: int = 48) -> list[tuple[float, ...]]:
    """Float samples of a G07.1 arc in machine coordinates (linear axis mm, rotary degrees)."""
    from ..geometry.cylinder import cylinder_of, developed_arc_of

    info = cylinder_of(seg)
    if info is None:
        raise ValueError("not a motion made in cylindrical interpolation")
    linear, rotary, _ = info
    iz, ic = seg.axes.index(linear), seg.axes.index(rotary)
    arc = developed_arc_of(seg)
    out = []
    for k in range(samples + 1):
        f = Fraction(k, samples)
        z, _, c = arc.point(f)
        p = [to_float(a + (b - a) * f) for a, b in zip(seg.start, seg.end)]
        p[iz], p[ic] = to_float(z.mid()), to_float(c.mid())
        out.append(tuple(p))
    return out


def _spline_float_points(seg: Segment, per_span: int = 12) -> list[tuple[float, ...]]:
    """Float samples of a SPLINE's exact NURBS curve (exact points at rational parameters, then floats)."""
    from ..geometry.nurbs import spline_curve

    curve = spline_curve(seg)
    out = [tuple(to_float(c) for c in curve.points[0])]
    for (a, b), _ in curve.span_hulls():
        for i in range(1, per_span + 1):
            out.append(tuple(to_float(c) for c in curve.point(a + (b - a) * Fraction(i, per_span))))
    return out


def path_points_float(seg: Segment, machine: Machine | None = None) -> list[tuple[float, ...]]:
    """Float points along one segment, in machine axis order (for plots).

    With ``machine``, rapids are drawn the way that machine moves them (a
    dogleg polyline when its ``rapid_mode`` is ``dogleg``).
    """
    return _FLOAT_POINTS[seg.kind](seg, machine)


def _straight_float_points(seg: Segment, machine: Machine | None) -> list[tuple[float, ...]]:
    if seg.kind is SegmentKind.RAPID and machine is not None:
        from ..prover.geometry import line_pieces

        pieces = line_pieces(seg, machine)
        pts = [pieces[0].p0] + [p.p1 for p in pieces]
        return [tuple(to_float(c) for c in p) for p in pts]
    return [tuple(to_float(c) for c in seg.start), tuple(to_float(c) for c in seg.end)]


def _polar_float_points(seg: Segment, machine: Machine | None) -> list[tuple[float, ...]]:
    from ..geometry.samples import polar_float_points

    return polar_float_points(seg)


#: How a plot samples each motion kind (docs/design.md §10 "How to add a motion kind").
_FLOAT_POINTS: dict[SegmentKind, Callable[[Segment, Machine | None], list[tuple[float, ...]]]] = {
    SegmentKind.LINE: _straight_float_points,
    SegmentKind.RAPID: _straight_float_points,
    SegmentKind.DWELL: _straight_float_points,
    SegmentKind.ARC: lambda seg, machine: _arc_float_points(seg),
    SegmentKind.DEVELOPED_ARC: lambda seg, machine: _developed_arc_float_points(seg),
    SegmentKind.SPLINE: lambda seg, machine: _spline_float_points(seg),
    SegmentKind.POLAR: _polar_float_points,
}
SAMPLED_KINDS = frozenset(_FLOAT_POINTS)


def plot_path(
    segments: Iterable[Segment],
    plane: Sequence[str],
    ax: Any,
    *,
    highlight_blocks: Iterable[int] = (),
    color: str = "#1f4e9c",
    label: str | None = "toolpath",
    machine: Machine | None = None,
) -> Any:
    """Draw segments in ``plane``: feeds solid, rapids dashed, highlighted blocks red.

    Pass ``machine`` to draw rapids as that machine moves them (dogleg).
    """
    hot = set(highlight_blocks)
    first_feed = first_rapid = True
    for seg in segments:
        if seg.kind is SegmentKind.DWELL:
            continue
        pts = path_points_float(seg, machine)
        h, v = seg.axes.index(plane[0]), seg.axes.index(plane[1])
        xs = [p[h] for p in pts]
        ys = [p[v] for p in pts]
        rapid = seg.kind is SegmentKind.RAPID
        c = "#c00000" if seg.block in hot else color
        lab = None
        if label and rapid and first_rapid:
            lab, first_rapid = "rapid", False
        elif label and not rapid and first_feed:
            lab, first_feed = label, False
        ax.plot(xs, ys, linestyle="--" if rapid else "-", color=c, lw=1.8 if seg.block in hot else 1.2, zorder=4, label=lab)
    return ax


def mark_points(points: Iterable[tuple[float, float]], ax: Any, *, label: str = "counterexample") -> Any:
    """Mark points (already projected to the plot plane) with red crosses."""
    pts = list(points)
    if pts:
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], marker="X", s=80, color="#c00000", zorder=6, label=label)
    return ax


def plot_machine(machine: Machine, segments: Iterable[Segment] = (), plane: tuple[str, str] | None = None,
                 ax: Any = None, *, placement: Any = "auto") -> Any:
    """Zones plus an optional toolpath in one call (the notebooks' entry point).

    Tool-tip zones are drawn where the proof puts them for the machine position
    (:func:`nczones.report.placement.placed_zones`): ``placement`` is a
    ``(tool length, tip offsets)`` pair, None for the zones as written, or
    ``"auto"``: the one tool placement the segments use (besides "no tool").
    """
    from .placement import drawing_machine, placement_of

    segments = list(segments)
    if placement == "auto":
        used = {placement_of(s) for s in segments} - {(Fraction(0), ())}
        placement = next(iter(used)) if len(used) == 1 else None
    ax = plot_zones(drawing_machine(machine, placement), plane, ax, legend=False)
    plane = plane or (machine.axis_names[0], machine.axis_names[1])
    plot_path(segments, plane, ax, machine=machine)
    ax.legend(loc="best", fontsize=8, framealpha=0.9)
    return ax
