"""Figures of a program on a machine: the allowed set, the toolpath, the violations.

:func:`plot_program` is the notebook entry point (and what ``nczones plot``
and the HTML report draw): the machine's zones in one axis plane (see
:func:`relevant_planes`), the toolpath over them (feeds solid, rapids dashed,
dogleg rapids drawn axis by axis as the machine moves), the violating blocks
in red and, when a verification :class:`~nczones.prover.Result` is given,
its counterexample points (red crosses, SVG id ``counterexample``) and first
exits (hollow circles, ``first-exit``).

Every zone is drawn where the proof puts it, in machine coordinates (the
counterexample points are machine coordinates): tool-tip zones are moved by
the placement of the tool active at the violating block — its length on the
tool axis and its offsets on the other axes (a lathe's X offset, wear
included) — with the prover's own :func:`nczones.zones.tip_shifted`
(:func:`placed_zones`), labelled with that offset; a program whose
violations saw several tools gets each placement's tip zones.

Floats here are for drawing only; nothing feeds back into a proof.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import Any

import numpy as np

from ..machine import Machine, RapidMode
from ..motion import MotionChunk, Segment, SegmentKind
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint
from ..zones.kinds import KindTable
from .placement import Placement, drawing_machine, placement_label, placement_of

__all__ = ["plot_program", "relevant_planes", "collect_path", "PathFloat", "thin_path"]


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
    >>> relevant_planes(load_machine("specs/machines/fanuc_lathe.toml"))  # a lathe: Z horizontal, X up
    [('Z', 'X')]
    """
    names = machine.axis_names
    order = {a: i for i, a in enumerate(names)}
    if len(names) < 2:
        return []
    if len(names) == 2:
        return [("Z", "X")] if _lathe_like(machine) else [(names[0], names[1])]

    def pair(a: str, b: str) -> tuple[str, str]:
        return (a, b) if order[a] < order[b] else (b, a)

    planes: list[tuple[str, str]] = []

    def add(p: tuple[str, str]) -> None:
        if p[0] != p[1] and p not in planes and all(a in order for a in p):
            planes.append(p)

    planes_of = [ZONE_PLANES(z, order) for z in machine.zones]
    for p in [p for own, _ in planes_of for p in own] + [p for _, spanned in planes_of for p in spanned]:
        add(pair(*p))
    if result is not None:
        for v in result.violations:
            outside = [a for a, _ in v.point if a in order]
            if outside and not any(a in p for p in planes for a in outside[:1]):
                add(pair(outside[0], next(a for a in names if a != outside[0])))
    if not planes:
        planes.append((names[0], names[1]))
    if _lathe_like(machine):  # lathe programmers read Z horizontal, X up
        planes = [("Z", "X") if set(p) == {"X", "Z"} else p for p in planes]
        planes = list(dict.fromkeys(planes))
    return planes[:limit]


def _bounded_planes(z: Zone, order: Mapping[str, int]) -> tuple[list[tuple[str, str]], list[tuple[str, str]]]:
    bounded = sorted((a for a, (lo, hi) in z.bounds().items() if lo is not None or hi is not None),
                     key=lambda a: order.get(a, len(order)))
    return [], [(bounded[0], other) for other in bounded[1:]]


#: The planes that show a zone (:func:`relevant_planes`), per zone kind: ``(its own planes, the planes its
#: bounded axes span)``; every zone's own planes come before any spanned one.  Fallback: by its bounds.
ZONE_PLANES: KindTable[Callable[[Any, Mapping[str, int]], tuple[list[tuple[str, str]], list[tuple[str, str]]]]] = (
    KindTable("report.figure.zone_planes", fallback=_bounded_planes))
ZONE_PLANES.set(BoxZone, _bounded_planes)
ZONE_PLANES.set(SteppedZone, lambda z, order: ([(z.reference_axis, z.limited_axis)], []))
ZONE_PLANES.set(PolygonZone, lambda z, order: ([z.plane], []))


def _lathe_like(machine: Any) -> bool:
    """A lathe (``[machine] type = "lathe"``) or a two-axis X/Z machine."""
    return bool(getattr(machine, "is_lathe", False)) or set(machine.axis_names) == {"X", "Z"}


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
    placements: set = field(default_factory=set)  # every Placement a segment carries
    hot_placements: dict = field(default_factory=dict)  # violating block -> Placement of its first hot segment
    segments: int = 0
    drawn: int = 0
    # where each drawn point comes from, for hover and click (:func:`where_code`): one int64 array per entry
    # of feed_lines/rapid_lines (one code per row) and of feed_curves/rapid_curves (one per point); one int per
    # hot curve; files: the file names the codes index (the program's and its called files')
    feed_where: list[np.ndarray] = field(default_factory=list)
    rapid_where: list[np.ndarray] = field(default_factory=list)
    feed_curve_where: list[np.ndarray] = field(default_factory=list)
    rapid_curve_where: list[np.ndarray] = field(default_factory=list)
    hot_where: list[int] = field(default_factory=list)
    files: list[str] = field(default_factory=list)
    thinned: int = 0  # points left out of the drawing by thin_path (never of a violating block)
    thin_cell: float = 0.0  # thin_path's grid cell: every left-out point lies within cell * sqrt(axes) of a drawn one


#: a where code is ``file index * WHERE_FILE + line`` (line 0: no line)
WHERE_FILE = 1 << 32


def where_code(path: PathFloat, file: str | None, line: int | None) -> int:
    """The code of (file, line) in ``path.files`` (the file added when new)."""
    name = file or ""
    if name not in path.files:
        path.files.append(name)
    return path.files.index(name) * WHERE_FILE + (line or 0)


def where_of(path: PathFloat, code: int) -> tuple[str, int | None]:
    """(file, line) of a where code (line None for 0)."""
    k, line = divmod(int(code), WHERE_FILE)
    return path.files[k], (line or None)


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
        out.placements.add(placement_of(seg))
        is_hot = seg.block in hot
        only = passes.get(seg.block) if passes else None
        if is_hot and only is not None and pass_name(seg.derived) not in only:
            is_hot = False
        if not is_hot and out.drawn >= max_segments:
            return
        out.drawn += 1
        rapid = seg.kind is SegmentKind.RAPID
        where = where_code(out, seg.span.file if seg.span is not None else None, seg.line)
        if is_hot:
            if out.hot_tool_length is None:
                out.hot_tool_length = seg.tool_length
            out.hot_placements.setdefault(seg.block, placement_of(seg))
            out.hot_curves.append((_seg_points(seg, machine), rapid))
            out.hot_where.append(where)
        elif not (seg.kind is SegmentKind.LINE or (rapid and not dogleg)):  # curves and doglegs
            pts = _seg_points(seg, machine)
            (out.rapid_curves if rapid else out.feed_curves).append(pts)
            (out.rapid_curve_where if rapid else out.feed_curve_where).append(np.full(len(pts), where, np.int64))
        else:
            pair = np.asarray([[float(c) for c in seg.start], [float(c) for c in seg.end]], dtype=float)
            (out.rapid_lines if rapid else out.feed_lines).append(pair[None, :, :])
            (out.rapid_where if rapid else out.feed_where).append(np.asarray([where], np.int64))

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
            for v in np.unique(tl[idx]):  # column rows carry no tip offset (the prover reads none either)
                out.placements.add((Fraction(int(v), 10**chunk.scale), ()))
        idx = idx[:room]
        out.drawn += len(idx)
        if len(idx):
            pairs = np.stack([np.asarray(chunk.start)[idx] / den, np.asarray(chunk.end)[idx] / den], axis=1)
            rapid = kinds[idx] == SegmentKind.RAPID.value
            where = where_code(out, chunk.file, 0) + np.asarray(chunk.line)[idx].astype(np.int64)
            if rapid.any():
                out.rapid_lines.append(pairs[rapid])
                out.rapid_where.append(where[rapid])
            if (~rapid).any():
                out.feed_lines.append(pairs[~rapid])
                out.feed_where.append(where[~rapid])
        if special.any():
            for i, seg in enumerate(chunk.segments()):
                if special[i]:
                    add_segment(seg)
    return out


def drawing_placements(path: PathFloat) -> list[Placement]:
    """The placements to draw tip zones for: those of the violating segments (in order), else the one
    placement the program uses besides "no tool" (none when it uses several)."""
    if path.hot_placements:
        return list(dict.fromkeys(path.hot_placements.values()))
    used = [p for p in path.placements if p != (Fraction(0), ())]
    return used if len(used) == 1 else []


def _project(arrs: Sequence[np.ndarray], h: int, v: int) -> list[np.ndarray]:
    return [a[..., [h, v]] for a in arrs]


def _draw_zones(ax: Any, machine: Machine, plane: tuple[str, str], path: Any, result: Any) -> None:
    """Every zone where the proof puts it: tip zones moved by the placement of the tool active at each
    violating block (each further placement adds its own tip zones), machine zones as they are; the fixture
    solids and the tool at each solid violation's contact."""
    from .solids_view import draw_contacts

    placements = drawing_placements(path)
    first = placements[0] if placements else None
    draw_allowed_set(drawing_machine(machine, first), plane, ax, tip_label=placement_label(machine, first))
    for k, extra in enumerate(placements[1:], start=2):
        draw_tip_zones(drawing_machine(machine, extra), plane, ax, placement_label(machine, extra), k)
    draw_contacts(ax, machine, plane, result)


def plot_program(program: Any, machine: Machine | str | os.PathLike[str], plane: Sequence[str] | None = None,
                 result: Any = None, *, ax: Any = None, path: PathFloat | None = None, title: str | None = None,
                 legend: bool = True, diameter: bool = False, zoom: bool = False) -> Any:
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
    diameter : bool
        Read the machine's ``diameter_axes`` (a lathe's X) in diameter: tick labels twice the machine
        coordinate, the axis label says so.  The drawn data stay machine coordinates (radius).
    zoom : bool
        Show only the violations (with ``result``): the violating blocks' paths, counterexample points and
        first exits, padded; everything is still drawn (pan or reset the limits to see the whole machine).

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
    _draw_zones(ax, machine, plane, path, result)
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
    if zoom and result is not None and result.violations:
        _zoom_to_violations(ax, path, result, plane, machine)
    if path.drawn < path.segments or path.thinned:
        note = [f"{path.segments - path.drawn} of {path.segments} segments not drawn"] if path.drawn < path.segments else []
        note += [f"path thinned for drawing ({path.thinned} points left out)"] if path.thinned else []
        ax.text(0.99, 0.01, "; ".join(note), transform=ax.transAxes, ha="right", va="bottom", fontsize=7,
                color="#555555")
    if diameter:
        from matplotlib.ticker import FuncFormatter

        unit = {a.name: ("deg" if a.rotary else "mm") for a in machine.axes}
        for axis_name, mpl_axis in zip(plane, (ax.xaxis, ax.yaxis)):
            if axis_name in getattr(machine, "diameter_axes", ()):
                mpl_axis.set_major_formatter(FuncFormatter(lambda x, _pos: f"{2 * x:g}"))
                mpl_axis.set_label_text(f"{axis_name} (diameter, {unit[axis_name]})")
    ax.set_title(title if title is not None else f"{machine.name}: {plane[0]}{plane[1]} plane", fontsize=10, wrap=True)
    if legend:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, framealpha=0.9, borderaxespad=0)
    fig.tight_layout()
    return fig


def _flat_runs(lines: list[np.ndarray], line_where: list[np.ndarray], curves: list[np.ndarray],
               curve_where: list[np.ndarray], naxes: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Points, where codes and run numbers of the continuous polylines of ``lines`` (rows joined where one
    ends where the next starts) and ``curves`` (one run each)."""
    pts, wheres, runs = [], [], []
    n_runs = 0
    if lines:
        seg = np.concatenate(lines).reshape(-1, 2, naxes)
        w = np.concatenate(line_where)
        breaks = np.ones(len(seg), bool)
        breaks[1:] = np.any(seg[1:, 0] != seg[:-1, 1], axis=1)
        run_of_row = np.cumsum(breaks) - 1
        end_pos = np.arange(len(seg)) + np.cumsum(breaks)
        out = np.empty((len(seg) + int(breaks.sum()), naxes))
        ow = np.empty(len(out), np.int64)
        orun = np.empty(len(out), np.int64)
        out[end_pos] = seg[:, 1]
        ow[end_pos] = w
        orun[end_pos] = run_of_row
        start_pos = end_pos[breaks] - 1
        out[start_pos] = seg[breaks, 0]
        ow[start_pos] = w[breaks]
        orun[start_pos] = run_of_row[breaks]
        pts.append(out)
        wheres.append(ow)
        runs.append(orun)
        n_runs = int(run_of_row[-1]) + 1
    for c, w in zip(curves, curve_where):
        pts.append(np.asarray(c, float).reshape(-1, naxes))
        wheres.append(np.asarray(w, np.int64))
        runs.append(np.full(len(c), n_runs, np.int64))
        n_runs += 1
    if not pts:
        return np.empty((0, naxes)), np.empty(0, np.int64), np.empty(0, np.int64)
    return np.concatenate(pts), np.concatenate(wheres), np.concatenate(runs)


def _snap_keep(points: np.ndarray, runs: np.ndarray, cell: float) -> np.ndarray:
    """Which points to keep: a run's first and last, and each point entering a grid cell (side ``cell``)
    other than its predecessor's.  A left-out point lies in its predecessor's cell, so in the cell of the
    last kept point before it: the drawn line stays within ``cell * sqrt(axes)`` of every point."""
    keep = np.ones(len(points), bool)
    if len(points) < 2:
        return keep
    grid = np.floor(points / cell).astype(np.int64)
    same_run = runs[1:] == runs[:-1]
    keep[1:] = ~same_run | np.any(grid[1:] != grid[:-1], axis=1)
    keep[:-1] |= ~same_run  # the last point of each run
    return keep


def thin_path(path: PathFloat, max_points: int) -> PathFloat:
    r"""``path`` drawn with at most about ``max_points`` points in its feeds and rapids (a long program's
    report stays small and opens fast); the violating blocks (``hot_curves``) are never thinned.

    Points are left out on a grid: a point in the same grid cell as its predecessor on the path is not drawn
    (:func:`_snap_keep`), the cell doubling from 1/8192 of the path's extent until the budget holds, so the drawn
    line stays within a cell's diagonal of the path.  Only when even the polylines' end points exceed the
    budget are whole polylines left out, evenly.  ``thinned`` counts the points not drawn.  The thinned path
    keeps its feeds and rapids as polylines (``feed_curves``, ``rapid_curves``).

    >>> from nczones import load_machine
    >>> m = load_machine("specs/machines/mill.toml")
    >>> text = "G21 G90 G54 F100\nG0 X0 Y0 Z0\n" + "".join(f"G1 X{k % 200 / 100} Y{k // 200}\n" for k in range(4000))
    >>> from nczones.gcode.source import program_text
    >>> p = collect_path(program_text(text, "t.ngc"), m)
    >>> t = thin_path(p, 1000)
    >>> sum(len(c) for c in t.feed_curves) <= 1000 < 4000, t.thinned > 0
    (True, True)
    """
    naxes = len(path.axes)
    parts = [_flat_runs(path.feed_lines, path.feed_where, path.feed_curves, path.feed_curve_where, naxes),
             _flat_runs(path.rapid_lines, path.rapid_where, path.rapid_curves, path.rapid_curve_where, naxes)]
    total = sum(len(p) for p, _, _ in parts)
    if total <= max_points:
        return path
    finite = [p[np.isfinite(p).all(axis=1)] for p, _, _ in parts if len(p)]
    stacked = np.concatenate(finite) if finite else np.zeros((1, naxes))
    extent = float(np.max(stacked.max(axis=0) - stacked.min(axis=0))) or 1.0
    cell = extent / 8192
    keeps = [np.ones(len(p), bool) for p, _, _ in parts]
    for _ in range(24):  # the cell reaches twice the extent: every run down to its two ends
        keeps = [_snap_keep(p, r, cell) for p, _, r in parts]
        if sum(int(k.sum()) for k in keeps) <= max_points:
            break
        cell *= 2
    out: list[tuple[list[np.ndarray], list[np.ndarray]]] = []
    kept_points = sum(int(k.sum()) for k in keeps)
    for (p, w, r), keep in zip(parts, keeps):
        p, w, r = p[keep], w[keep], r[keep]
        if not len(p):
            out.append(([], []))
            continue
        cuts = np.nonzero(r[1:] != r[:-1])[0] + 1
        curves, wheres = np.split(p, cuts), np.split(w, cuts)
        if kept_points > max_points:  # even the ends are too many: every k-th polyline (no distance bound)
            step = -(-kept_points // max_points)
            curves, wheres = curves[::step], wheres[::step]
            cell = float("inf")
        out.append((curves, wheres))
    drawn = sum(len(c) for curves, _ in out for c in curves)
    return replace(path, feed_lines=[], rapid_lines=[], feed_where=[], rapid_where=[],
                   feed_curves=out[0][0], feed_curve_where=out[0][1], rapid_curves=out[1][0],
                   rapid_curve_where=out[1][1], thinned=path.thinned + total - drawn, thin_cell=cell)


def violation_view(path: PathFloat, result: Any, plane: Sequence[str], machine: Machine) -> Any:
    """The view ``((x0, x1), (y0, y1))`` around the violating paths, witnesses and first exits in ``plane``
    (their extent plus a quarter on each side, at least 5 units either way); None when nothing shows there."""
    from ..exact import to_float

    h, v = machine.axis_names.index(plane[0]), machine.axis_names.index(plane[1])
    pts = [p[:, [h, v]] for p, _ in path.hot_curves]
    for x in result.violations:
        for q in (dict(x.point), dict(x.first_exit)):
            if plane[0] in q and plane[1] in q:
                pts.append(np.asarray([[to_float(q[plane[0]]), to_float(q[plane[1]])]]))
    if not pts:
        return None
    stacked = np.concatenate([np.asarray(p).reshape(-1, 2) for p in pts])
    lo, hi = stacked.min(axis=0), stacked.max(axis=0)
    half = np.maximum((hi - lo) * 0.75, 5.0)
    mid = (lo + hi) / 2
    return (mid[0] - half[0], mid[0] + half[0]), (mid[1] - half[1], mid[1] + half[1])


def path_within(path: PathFloat, plane: Sequence[str], machine: Machine, view: Any) -> PathFloat:
    """``path`` without the feeds and rapids whose box misses ``view`` in ``plane`` (a zoomed figure draws only
    what it shows; the violating blocks are always kept)."""
    h, v = machine.axis_names.index(plane[0]), machine.axis_names.index(plane[1])
    (x0, x1), (y0, y1) = view

    def meets(a: np.ndarray) -> np.ndarray:  # a: (n, k, naxes) -> (n,) bool
        lo, hi = a.min(axis=1), a.max(axis=1)
        inside: np.ndarray = (hi[:, h] >= x0) & (lo[:, h] <= x1) & (hi[:, v] >= y0) & (lo[:, v] <= y1)
        return inside

    def lines(arrs: list[np.ndarray], wheres: list[np.ndarray]) -> tuple[list[np.ndarray], list[np.ndarray]]:
        masks = [meets(a) for a in arrs]
        kept = [(a[m], w[m]) for a, w, m in zip(arrs, wheres, masks) if m.any()]
        return [a for a, _ in kept], [w for _, w in kept]

    def curves(arrs: list[np.ndarray], wheres: list[np.ndarray]) -> tuple[list[np.ndarray], list[np.ndarray]]:
        kept = [(c, w) for c, w in zip(arrs, wheres) if len(c) and bool(meets(c[None, :, :])[0])]
        return [c for c, _ in kept], [w for _, w in kept]

    (fl, fw), (rl, rw) = lines(path.feed_lines, path.feed_where), lines(path.rapid_lines, path.rapid_where)
    (fc, fcw), (rc, rcw) = (curves(path.feed_curves, path.feed_curve_where),
                            curves(path.rapid_curves, path.rapid_curve_where))
    return replace(path, feed_lines=fl, rapid_lines=rl, feed_curves=fc, rapid_curves=rc, feed_where=fw,
                   rapid_where=rw, feed_curve_where=fcw, rapid_curve_where=rcw)


def _zoom_to_violations(ax: Any, path: PathFloat, result: Any, plane: tuple[str, str], machine: Machine) -> None:
    """Set the view to :func:`violation_view`."""
    view = violation_view(path, result, plane, machine)
    if view is not None:
        ax.set_xlim(*view[0])
        ax.set_ylim(*view[1])


def draw_allowed_set(machine: Any, plane: tuple[str, str], ax: Any, *, tip_label: str = "tool tip") -> Any:
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
    # one patch per zone name: a tip zone the proof enlarges by a lathe tool's nose radius is several zones of
    # one name (nczones.prover.nose), drawn as their union
    forbidden: dict[str, tuple[Zone, list[Any]]] = {}
    for z in machine.zones:
        g = geom(z) if z.forbid else None
        if g is not None:
            forbidden.setdefault(z.name, (z, []))[1].append(g)
    for z, gs in forbidden.values():
        g = unary_union(gs)
        tip = f", {tip_label}" if z.point is ZonePoint.TIP else ""
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


def draw_tip_zones(machine: Any, plane: tuple[str, str], ax: Any, label: str, k: int) -> None:
    """Draw the tool-tip zones of one more tool placement (a program whose violations saw several tools):
    forbid zones hatched (SVG id ``forbid-NAME@k``), allow zones outlined (``allow-NAME@k``)."""
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path as MplPath
    from shapely.geometry import Polygon as ShapelyPolygon
    from shapely.geometry import box as shapely_box
    from shapely.ops import unary_union

    from .plot import zone_patches

    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    view = shapely_box(-1e8, -1e8, 1e8, 1e8)
    named: dict[tuple[str, bool], tuple[Zone, list[Any]]] = {}  # zones of one name (a nose-enlarged polygon): one patch
    for z in machine.zones:
        if z.point is not ZonePoint.TIP:
            continue
        drawn = zone_patches(z, plane, xlim, ylim)
        if drawn is None:
            continue
        kind, shapes = drawn
        named.setdefault((z.name, z.forbid), (z, []))[1].append(
            unary_union([shapely_box(x, y, x + w, y + hh) for (x, y), w, hh in shapes]) if kind == "rects"
            else ShapelyPolygon(shapes).buffer(0))
    for z, gs in named.values():
        g = unary_union(gs).intersection(view)
        polys = [g] if g.geom_type == "Polygon" else [p for p in getattr(g, "geoms", []) if p.geom_type == "Polygon"]
        verts, codes = [], []
        for poly in polys:
            xy = list(poly.exterior.coords)
            verts += xy
            codes += [MplPath.MOVETO] + [MplPath.LINETO] * (len(xy) - 2) + [MplPath.CLOSEPOLY]
        if not verts:
            continue
        if z.forbid:
            p = ax.add_patch(PathPatch(MplPath(verts, codes), facecolor="#e06666", alpha=0.3, hatch="\\\\",
                                       edgecolor="#b22222", zorder=2, label=f"{z.name} (forbidden, {label})"))
            p.set_gid(f"forbid-{z.name}@{k}")
        else:
            p = ax.add_patch(PathPatch(MplPath(verts, codes), facecolor="none", edgecolor="#2e7d32", ls="--",
                                       zorder=2, label=f"{z.name} (allowed, {label})"))
            p.set_gid(f"allow-{z.name}@{k}")
