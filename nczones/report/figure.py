"""Figures of a program on a machine: the allowed set, the toolpath, the violations.

:func:`plot_program` is the notebook entry point (and what ``nczones plot``
and the HTML report draw): the machine's zones in one axis plane (see
:func:`relevant_planes`), the toolpath over them (feeds solid, rapids dashed,
dogleg rapids drawn axis by axis as the machine moves), the violating blocks
in red and, when a verification :class:`~nczones.prover.Result` is given,
its counterexample points (red crosses, SVG id ``counterexample``) and first
exits (hollow circles, ``first-exit``).

Tool-tip zones are drawn where the *spindle* would have to be for the tip to
enter them when one tool length is in use (the counterexample points are
machine coordinates), labelled with that tool length.

Floats here are for drawing only; nothing feeds back into a proof.
"""

from __future__ import annotations

import os
import types
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import Any

import numpy as np

from ..machine import Machine, RapidMode
from ..motion import MotionChunk, Segment, SegmentKind
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint

__all__ = ["plot_program", "relevant_planes", "collect_path", "PathFloat"]


def relevant_planes(machine: Machine, result: Any = None, limit: int = 3) -> list[tuple[str, str]]:
    """The axis planes worth drawing: those the zones are defined in.

    Stepped tables and polygons name their plane; a box bounding several
    axes contributes the planes of its first bounded axis with each other
    (XY and XZ for a 3-D box).  Axes are ordered as in the machine.  A
    violation outside the listed planes adds a plane containing its axes.

    >>> from nczones import load_machine
    >>> relevant_planes(load_machine("specs/machines/mill.toml"))
    [('X', 'Y'), ('X', 'Z')]
    >>> relevant_planes(load_machine("specs/machines/grinder.toml"))
    [('X', 'Y')]
    """
    names = machine.axis_names
    order = {a: i for i, a in enumerate(names)}
    if len(names) < 2:
        return []
    if len(names) == 2:
        return [(names[0], names[1])]

    def pair(a: str, b: str) -> tuple[str, str]:
        return (a, b) if order[a] < order[b] else (b, a)

    planes: list[tuple[str, str]] = []

    def add(p: tuple[str, str]) -> None:
        if p[0] != p[1] and p not in planes and all(a in order for a in p):
            planes.append(p)

    for z in machine.zones:
        if isinstance(z, SteppedZone):
            add(pair(z.reference_axis, z.limited_axis))
        elif isinstance(z, PolygonZone):
            add(pair(*z.plane))
    for z in machine.zones:
        if isinstance(z, BoxZone):
            bounded = sorted((a for a, (lo, hi) in z.bounds().items() if lo is not None or hi is not None),
                             key=lambda a: order.get(a, len(order)))
            for other in bounded[1:]:
                add(pair(bounded[0], other))
    if result is not None:
        for v in result.violations:
            outside = [a for a, _ in v.point if a in order]
            if outside and not any(a in p for p in planes for a in outside[:1]):
                add(pair(outside[0], next(a for a in names if a != outside[0])))
    if not planes:
        planes.append((names[0], names[1]))
    return planes[:limit]


@dataclass
class PathFloat:
    """A toolpath as float polylines (machine coordinates, axis order of the machine)."""

    axes: tuple[str, ...]
    feed_lines: list[np.ndarray] = field(default_factory=list)   # arrays (n, 2, naxes)
    rapid_lines: list[np.ndarray] = field(default_factory=list)
    feed_curves: list[np.ndarray] = field(default_factory=list)  # arrays (k, naxes)
    rapid_curves: list[np.ndarray] = field(default_factory=list)
    hot_curves: list[tuple[np.ndarray, bool]] = field(default_factory=list)  # (points, rapid)
    tool_lengths: set = field(default_factory=set)
    hot_tool_length: Fraction | None = None
    segments: int = 0
    drawn: int = 0


def _seg_points(seg: Segment, machine: Machine) -> np.ndarray:
    from .plot import path_points_float

    return np.asarray(path_points_float(seg, machine), dtype=float)


def pass_name(derived: str) -> str:
    """The generated pass a segment label belongs to: ``"G71 roughing pass 3: cut"`` -> ``"G71 roughing pass 3"``
    (labels of lathe cycles, ``specs/turning.md``); "" for a label that names no pass.

    >>> pass_name("G71 roughing pass 3: escape"), pass_name("G70 finishing pass 1"), pass_name("cutter comp corner")
    ('G71 roughing pass 3', 'G70 finishing pass 1', '')
    """
    head = derived.split(":", 1)[0].strip()
    return head if (" pass" in head or "position " in head) else ""


def hot_passes(violations: Iterable[Any]) -> dict[int, frozenset[str] | None]:
    """Block -> the generated passes to highlight (the failing pass alone, not the whole cycle block), or None
    for the whole block (a violation in a segment that is no generated pass)."""
    out: dict[int, frozenset[str] | None] = {}
    for v in violations:
        name = pass_name(getattr(v, "derived", "") or "")
        if not name:
            out[v.block] = None
        elif v.block not in out or out[v.block] is not None:
            out[v.block] = (out.get(v.block) or frozenset()) | {name}
    return out


def collect_path(program: Any, machine: Machine, hot_blocks: Iterable[int] = (), *,
                 max_segments: int = 200_000, passes: Mapping[int, frozenset[str] | None] | None = None,
                 library: Any = None) -> PathFloat:
    """Interpret ``program`` (a path or a :class:`~nczones.gcode.source.ProgramSource`) and keep
    float polylines for drawing.

    Violating blocks (``hot_blocks``) are always kept; other segments past
    ``max_segments`` are left out of the drawing (``drawn`` < ``segments``).
    ``passes`` (:func:`hot_passes`) narrows a hot block to its failing generated passes: the block's other
    passes are drawn as the rest of the path.  ``library``: the subprogram folders of the run
    (:func:`nczones.prover.verify`'s ``library``, in ``Result.settings``).

    >>> from nczones import load_machine
    >>> p = collect_path("specs/examples/programs/notch_dip.ngc", load_machine("specs/machines/grinder.toml"), {3})
    >>> p.segments, len(p.hot_curves)
    (3, 1)
    """
    from ..gcode import interpret

    hot = set(hot_blocks)
    out = PathFloat(tuple(machine.axis_names))
    dogleg = machine.rapid_mode is RapidMode.DOGLEG

    def add_segment(seg: Segment) -> None:
        out.segments += 1
        if seg.kind is SegmentKind.DWELL:
            return
        if seg.tool_length:
            out.tool_lengths.add(seg.tool_length)
        is_hot = seg.block in hot
        only = passes.get(seg.block) if passes else None
        if is_hot and only is not None and pass_name(seg.derived) not in only:
            is_hot = False
        if not is_hot and out.drawn >= max_segments:
            return
        out.drawn += 1
        rapid = seg.kind is SegmentKind.RAPID
        if is_hot:
            if out.hot_tool_length is None:
                out.hot_tool_length = seg.tool_length
            out.hot_curves.append((_seg_points(seg, machine), rapid))
        elif not (seg.kind is SegmentKind.LINE or (rapid and not dogleg)):  # curves and doglegs
            (out.rapid_curves if rapid else out.feed_curves).append(_seg_points(seg, machine))
        else:
            pair = np.asarray([[float(c) for c in seg.start], [float(c) for c in seg.end]], dtype=float)
            (out.rapid_lines if rapid else out.feed_lines).append(pair[None, :, :])

    run = interpret(program, machine) if library is None else interpret(program, machine, library=library)
    for chunk in run:
        if not isinstance(chunk, MotionChunk) or chunk.scale is None or len(chunk) == 0:
            for seg in (chunk.segments() if isinstance(chunk, MotionChunk) else [chunk]):
                add_segment(seg)
            continue
        kinds = np.asarray(chunk.kind)
        special = (kinds == SegmentKind.ARC.value) | np.isin(np.asarray(chunk.block), list(hot))
        if dogleg:
            special |= kinds == SegmentKind.RAPID.value
        simple = ~special & (kinds != SegmentKind.DWELL.value)
        den = float(10**chunk.scale)
        room = max(0, max_segments - out.drawn)
        idx = np.nonzero(simple)[0]
        out.segments += int((kinds == SegmentKind.DWELL.value).sum()) + len(idx)
        tl = np.asarray(chunk.tool_length)
        if len(tl):
            for v in np.unique(tl[tl != 0]):
                out.tool_lengths.add(Fraction(int(v), 10**chunk.scale))
        idx = idx[:room]
        out.drawn += len(idx)
        if len(idx):
            pairs = np.stack([np.asarray(chunk.start)[idx] / den, np.asarray(chunk.end)[idx] / den], axis=1)
            rapid = kinds[idx] == SegmentKind.RAPID.value
            if rapid.any():
                out.rapid_lines.append(pairs[rapid])
            if (~rapid).any():
                out.feed_lines.append(pairs[~rapid])
        if special.any():
            for i, seg in enumerate(chunk.segments()):
                if special[i]:
                    add_segment(seg)
    return out


def _shifted_machine(machine: Machine, tool_length: Fraction | None) -> tuple[Any, Fraction | None]:
    """A drawing proxy whose tip boxes sit where the spindle is when the tip touches them."""
    if not tool_length or machine.tool_axis is None:
        return machine, None
    zones: list[Zone] = []
    shifted = False
    for z in machine.zones:
        if z.point is ZonePoint.TIP and isinstance(z, BoxZone) and machine.tool_axis in z.bounds():
            limits = tuple((a, None if lo is None else lo + tool_length if a == machine.tool_axis else lo,
                            None if hi is None else hi + tool_length if a == machine.tool_axis else hi)
                           for a, lo, hi in z.limits)
            from ..exact import format_decimal

            zones.append(replace(z, name=f"{z.name} (at tool length {format_decimal(tool_length)})",
                                 limits=limits, point=ZonePoint.MACHINE))
            shifted = True
        else:
            zones.append(z)
    if not shifted:
        return machine, None
    proxy = types.SimpleNamespace(name=machine.name, axes=machine.axes, axis_names=machine.axis_names,
                                  start=machine.start, reference=machine.reference, zones=tuple(zones))
    return proxy, tool_length


def _project(arrs: Sequence[np.ndarray], h: int, v: int) -> list[np.ndarray]:
    return [a[..., [h, v]] for a in arrs]


def plot_program(program: Any, machine: Machine | str | os.PathLike[str], plane: Sequence[str] | None = None,
                 result: Any = None, *, ax: Any = None, path: PathFloat | None = None, title: str | None = None,
                 legend: bool = True) -> Any:
    """Draw a program's toolpath over the allowed set of a machine; returns the figure.

    Parameters
    ----------
    program : str, path or ProgramSource
        The program file (a ``str`` is a path; for text pass
        :func:`~nczones.gcode.source.program_text`).
    machine : Machine or path of a machine file
    plane : (str, str), optional
        Horizontal and vertical axis; default the first of :func:`relevant_planes`.
    result : Result, optional
        A verification result: its violating blocks are drawn red and its
        counterexample points marked.
    ax : matplotlib Axes, optional
        Draw into it (its figure is returned).
    path : PathFloat, optional
        A path already collected by :func:`collect_path` (saves interpreting again).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> from nczones import load_machine
    >>> from nczones.prover import verify
    >>> m = load_machine("specs/machines/grinder.toml")
    >>> prog = "specs/examples/programs/notch_dip.ngc"
    >>> fig = plot_program(prog, m, result=verify(prog, m))
    >>> [c.get_gid() for c in fig.axes[0].collections if c.get_gid()]
    ['toolpath-feed', 'toolpath-rapid', 'counterexample', 'first-exit']
    >>> import matplotlib.pyplot as plt; plt.close(fig)
    """
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    from ..exact import to_float

    if not isinstance(machine, Machine):
        from ..machine import load_machine

        machine = load_machine(machine)
    hot = {v.block for v in result.violations} if result is not None else set()
    if path is None:
        path = collect_path(program, machine, hot, passes=hot_passes(result.violations) if result is not None else None,
                            library=dict(result.settings).get("library") if result is not None else None)
    if plane is None:
        plane = relevant_planes(machine, result)[0]
    plane = (str(plane[0]).upper(), str(plane[1]).upper())
    names = machine.axis_names
    for a in plane:
        if a not in names:
            from ..errors import InvalidArgument

            raise InvalidArgument(f"plane axis {a!r} is not an axis of the machine ({', '.join(names)})")
    h, v = names.index(plane[0]), names.index(plane[1])
    if ax is None:
        fig, ax = plt.subplots(figsize=(7.5, 5))
    fig = ax.figure
    tool_length = path.hot_tool_length if path.hot_tool_length else (
        next(iter(path.tool_lengths)) if len(path.tool_lengths) == 1 else None)
    drawing_machine, _ = _shifted_machine(machine, tool_length)
    draw_allowed_set(drawing_machine, plane, ax)
    blue = "#1f4e9c"
    feeds = [a[:, :, [h, v]] for a in path.feed_lines]
    feed_segs = (list(np.concatenate(feeds)) if feeds else []) + _project(path.feed_curves, h, v)
    rapids = [a[:, :, [h, v]] for a in path.rapid_lines]
    rapid_segs = (list(np.concatenate(rapids)) if rapids else []) + _project(path.rapid_curves, h, v)
    lc = LineCollection(feed_segs, colors=blue, linewidths=1.2, zorder=4, label="feed")
    lc.set_gid("toolpath-feed")
    ax.add_collection(lc)
    lr = LineCollection(rapid_segs, colors=blue, linewidths=1.0, linestyles="--", zorder=4, label="rapid")
    lr.set_gid("toolpath-rapid")
    ax.add_collection(lr)
    for k, (pts, rapid) in enumerate(path.hot_curves):
        (line,) = ax.plot(pts[:, h], pts[:, v], color="#c00000", lw=2.4, ls="--" if rapid else "-", zorder=5,
                          label="violating block" if k == 0 else None)
        line.set_gid(f"violating-block-{k + 1}")
    if result is not None and result.violations:
        points = [dict(x.point) for x in result.violations]
        exits = [dict(x.first_exit) for x in result.violations]
        xs = [to_float(p[plane[0]]) for p in points if plane[0] in p and plane[1] in p]
        ys = [to_float(p[plane[1]]) for p in points if plane[0] in p and plane[1] in p]
        sc = ax.scatter(xs, ys, marker="X", s=110, color="#c00000", edgecolors="white", linewidths=0.8,
                        zorder=7, label="counterexample")
        sc.set_gid("counterexample")
        ex = [(to_float(p[plane[0]]), to_float(p[plane[1]])) for p in exits if plane[0] in p and plane[1] in p]
        fe = ax.scatter([p[0] for p in ex], [p[1] for p in ex], marker="o", s=60, facecolors="none",
                        edgecolors="#c00000", linewidths=1.5, zorder=7, label="first exit")
        fe.set_gid("first-exit")
        for i, (x, y) in enumerate(zip(xs, ys)):
            line = result.violations[i].line
            ax.annotate(f"line {line}" if line is not None else f"block {result.violations[i].block}",
                        (x, y), xytext=(6, 6), textcoords="offset points", fontsize=8, color="#800000", zorder=8)
    # keep every drawn point in view (a toolpath may leave the zones' extent)
    allpts = [s for s in feed_segs + rapid_segs] + [p[:, [h, v]] for p, _ in path.hot_curves]
    if allpts:
        stacked = np.concatenate([np.asarray(p).reshape(-1, 2) for p in allpts])
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        lo, hi = stacked.min(axis=0), stacked.max(axis=0)
        padx, pady = 0.03 * (max(x1, hi[0]) - min(x0, lo[0])), 0.03 * (max(y1, hi[1]) - min(y0, lo[1]))
        ax.set_xlim(min(x0, lo[0] - padx), max(x1, hi[0] + padx))
        ax.set_ylim(min(y0, lo[1] - pady), max(y1, hi[1] + pady))
    if path.drawn < path.segments:
        ax.text(0.99, 0.01, f"{path.segments - path.drawn} of {path.segments} segments not drawn",
                transform=ax.transAxes, ha="right", va="bottom", fontsize=7, color="#555555")
    ax.set_title(title if title is not None else f"{machine.name}: {plane[0]}{plane[1]} plane")
    if legend:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, framealpha=0.9, borderaxespad=0)
    fig.tight_layout()
    return fig


def draw_allowed_set(machine: Any, plane: tuple[str, str], ax: Any) -> Any:
    """Draw the allowed set in ``plane``: the intersection of the allow zones green, forbid zones hatched.

    Each zone is projected to the plane (the drawing of :mod:`nczones.report.plot`);
    the allow zones are intersected (the allowed set is their intersection),
    their outlines drawn thin.  Returns the axes.
    """
    from matplotlib.patches import PathPatch, Rectangle
    from matplotlib.path import Path as MplPath
    from shapely.geometry import Polygon as ShapelyPolygon
    from shapely.geometry import box as shapely_box
    from shapely.ops import unary_union

    from .plot import view_limits, zone_patches

    xlim, ylim = view_limits(machine, plane)
    view = shapely_box(xlim[0], ylim[0], xlim[1], ylim[1])

    def geom(z):
        drawn = zone_patches(z, plane, xlim, ylim)
        if drawn is None:
            return None
        kind, shapes = drawn
        if kind == "rects":
            parts = [shapely_box(x, y, x + w, y + hh) for (x, y), w, hh in shapes]
            g = unary_union(parts)
        else:
            g = ShapelyPolygon(shapes).buffer(0)
        return g.intersection(view)

    def patch(g, **kw):
        polys = [g] if g.geom_type == "Polygon" else [p for p in getattr(g, "geoms", []) if p.geom_type == "Polygon"]
        verts, codes = [], []
        for poly in polys:
            for ring in [poly.exterior, *poly.interiors]:
                xy = list(ring.coords)
                verts += xy
                codes += [MplPath.MOVETO] + [MplPath.LINETO] * (len(xy) - 2) + [MplPath.CLOSEPOLY]
        if not verts:
            return None
        return ax.add_patch(PathPatch(MplPath(verts, codes), **kw))

    allow = [(z, geom(z)) for z in machine.zones if not z.forbid]
    allow = [(z, g) for z, g in allow if g is not None]
    if allow:
        ax.add_patch(Rectangle(
            (xlim[0], ylim[0]), xlim[1] - xlim[0], ylim[1] - ylim[0], color="#e6e6e6", zorder=0,
            label="outside the allowed set"))
        region = allow[0][1]
        for _, g in allow[1:]:
            region = region.intersection(g)
        names = " ∩ ".join(z.name for z, _ in allow)
        p = patch(region, facecolor="#cfe8cf", edgecolor="#2e7d32", lw=1.2, zorder=1,
                  label=f"allowed set ({names})")
        if p is not None:
            p.set_gid("allowed-set")
        if len(allow) > 1:
            for _z, g in allow:
                patch(g, facecolor="none", edgecolor="#4c8c4c", lw=0.6, ls=":", zorder=1)
    for z in machine.zones:
        if not z.forbid:
            continue
        g = geom(z)
        if g is None:
            continue
        tip = ", tool tip" if z.point is ZonePoint.TIP else ""
        p = patch(g, facecolor="#e06666", alpha=0.4, hatch="//", edgecolor="#b22222", zorder=2,
                  label=f"{z.name} (forbidden{tip})")
        if p is not None:
            p.set_gid(f"forbid-{z.name}")
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    unit = {a.name: ("deg" if a.rotary else "mm") for a in machine.axes}
    ax.set_xlabel(f"{plane[0]} ({unit[plane[0]]})")
    ax.set_ylabel(f"{plane[1]} ({unit[plane[1]]})")
    return ax
