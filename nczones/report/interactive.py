"""The interactive view of the HTML report: the figure data for Plotly's JavaScript (issue 37).

:func:`view_data` turns a collected path (:func:`nczones.report.figure.collect_path`) and a verification
result into a Plotly figure as plain JSON-ready data: a 3-D view (``scatter3d`` and ``mesh3d``) when the
machine has linear X, Y and Z axes, else a 2-D view of its first relevant plane (``scatter``).  The zones are
solids placed by :mod:`nczones.report.placement` exactly as the 2-D figures and the proof place them (boxes;
stepped tables as stacked boxes; polygons as prisms along the third axis), unbounded sides cut at the
drawing's limits; the toolpath is thinned for a long program (:func:`nczones.report.figure.thin_path`,
never a violating block); each violation has its witness ✕ and first exit ○, and a view around it.

Every drawn point carries an index into ``where`` (the program file and line it comes from), which the page
turns into hover text (line and block text) and the anchor of the listing line a click jumps to.

:func:`plotly_js` is the bundled plotly.js of the ``plotly`` package (the ``html`` extra), embedded once in
the page; None when it is not installed (the report then keeps its 2-D figures and says so).

Floats here are for drawing only; nothing feeds back into a proof.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ..exact import to_float
from ..machine import Machine
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint
from ..zones.kinds import KindTable
from .figure import PathFloat, drawing_placements, relevant_planes, thin_path, where_code
from .placement import drawing_machine, placement_label

__all__ = ["plotly_js", "view_data", "view_axes", "MAX_POINTS"]

#: points of the thinned feeds and rapids drawn in the interactive view (about 30 bytes each in the page)
MAX_POINTS = 20_000

_BLUE, _RED, _GREEN = "#1f4e9c", "#c00000", "#2e7d32"


def plotly_js() -> str | None:
    """The minified plotly.js bundled with the ``plotly`` Python package, or None without it."""
    try:
        from plotly.offline import get_plotlyjs
    except ImportError:
        return None
    js: str = get_plotlyjs()
    return js


def view_axes(machine: Machine, result: Any = None) -> tuple[str, ...]:
    """The axes of the interactive view: X, Y, Z for a machine with those linear axes (3-D), else its first
    relevant plane (:func:`nczones.report.figure.relevant_planes`; a lathe: Z, X).

    >>> from nczones import load_machine
    >>> view_axes(load_machine("specs/machines/mill.toml")), view_axes(load_machine("specs/machines/fanuc_lathe.toml"))
    (('X', 'Y', 'Z'), ('Z', 'X'))
    """
    linear = {a.name for a in machine.axes if not a.rotary}
    if {"X", "Y", "Z"} <= linear:
        return ("X", "Y", "Z")
    planes = relevant_planes(machine, result)
    return tuple(planes[0]) if planes else tuple(machine.axis_names[:2])


def _limits(machine: Machine, axes: Sequence[str]) -> list[tuple[float, float]]:
    from .plot import view_limits

    out = []
    for k, a in enumerate(axes):
        other = axes[1] if k == 0 else axes[0]
        out.append(view_limits(machine, (a, other))[0])
    return out


def _triangles(poly: list[tuple[float, float]]) -> list[tuple[int, int, int]]:
    """Ear-clipping triangulation of a simple polygon (vertex indexes)."""
    n = len(poly)
    area = sum(poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1] for i in range(n))
    idx = list(range(n)) if area > 0 else list(range(n))[::-1]

    def cross(a: int, b: int, c: int) -> float:
        (ax, ay), (bx, by), (cx, cy) = poly[a], poly[b], poly[c]
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)

    def inside(p: int, a: int, b: int, c: int) -> bool:
        return cross(a, b, p) >= 0 and cross(b, c, p) >= 0 and cross(c, a, p) >= 0

    out = []
    guard = 0
    while len(idx) > 3 and guard < n * n:
        guard += 1
        for k in range(len(idx)):
            a, b, c = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            if cross(a, b, c) <= 0:
                continue
            if any(inside(p, a, b, c) for p in idx if p not in (a, b, c)):
                continue
            out.append((a, b, c))
            del idx[k]
            break
        else:  # degenerate (collinear) rest: fan it
            break
    out += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
    return out


def _zone_solids(zone: Zone, axes: Sequence[str], lims: list[tuple[float, float]]) -> list[Any]:
    """The zone as solids in the view's axes: ("box", lo, hi) per box, ("prism", polygon, (i, j), k, lo, hi) for
    a polygon of axes i, j extruded along k; [] when it does not show in these axes."""
    return ZONE_SOLIDS(zone, axes, lims)


def _span(lims: list[tuple[float, float]], k: int, lo: Any, hi: Any) -> tuple[float, float]:
    return (lims[k][0] if lo is None else to_float(lo), lims[k][1] if hi is None else to_float(hi))


def _bounds_solids(zone: Zone, axes: Sequence[str], lims: list[tuple[float, float]]) -> list[Any]:
    bounds = zone.bounds()
    if not any(a in bounds for a in axes):
        return []
    lo = [_span(lims, k, *bounds.get(a, (None, None)))[0] for k, a in enumerate(axes)]
    hi = [_span(lims, k, *bounds.get(a, (None, None)))[1] for k, a in enumerate(axes)]
    return [("box", lo, hi)]


#: :func:`_zone_solids` per zone kind.  Fallback: the box of its bounds.
ZONE_SOLIDS: KindTable[Callable[[Any, Sequence[str], list[tuple[float, float]]], list[Any]]] = KindTable(
    "report.interactive.zone_solids", fallback=_bounds_solids)
ZONE_SOLIDS.set(BoxZone, _bounds_solids)


@ZONE_SOLIDS.register(SteppedZone)
def _stepped_solids(zone: SteppedZone, axes: Sequence[str], lims: list[tuple[float, float]]) -> list[Any]:
    if zone.reference_axis not in axes or zone.limited_axis not in axes:
        return []
    r, m = axes.index(zone.reference_axis), axes.index(zone.limited_axis)
    out = []
    for i, reg in enumerate(zone.regions):
        lo = [_span(lims, k, None, None)[0] for k in range(len(axes))]
        hi = [_span(lims, k, None, None)[1] for k in range(len(axes))]
        lo[r], hi[r] = to_float(zone.region_lower(i)), to_float(reg.upto)
        lo[m], hi[m] = _span(lims, m, reg.min, reg.max)
        out.append(("box", lo, hi))
    return out


@ZONE_SOLIDS.register(PolygonZone)
def _polygon_solids(zone: PolygonZone, axes: Sequence[str], lims: list[tuple[float, float]]) -> list[Any]:
    if not set(zone.plane) <= set(axes):
        return []
    i, j = axes.index(zone.plane[0]), axes.index(zone.plane[1])
    poly = [(to_float(v[0]), to_float(v[1])) for v in zone.vertices]
    rest = [k for k in range(len(axes)) if k not in (i, j)]
    if not rest:
        return [("prism", poly, (i, j), None, 0.0, 0.0)]
    k = rest[0]
    bottom, top = _span(lims, k, *zone.bounds().get(axes[k], (None, None)))
    return [("prism", poly, (i, j), k, bottom, top)]


def _box_prism(lo: Sequence[float], hi: Sequence[float]) -> tuple[list[tuple[float, float]], float, float]:
    return [(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])], lo[2], hi[2]


def _solid_traces3d(solid: Any, name: str, forbid: bool, group: str, first: bool) -> list[dict[str, Any]]:
    """A mesh3d (the faces) and a scatter3d (the edges) of one solid."""
    if solid[0] == "box":
        poly, zlo, zhi = _box_prism(solid[1], solid[2])
        ij, k = (0, 1), 2
    else:
        _, poly, ij, k, zlo, zhi = solid
    n = len(poly)
    pts = [[0.0, 0.0, 0.0] for _ in range(2 * n)]
    for q, (u, v) in enumerate(poly):
        for layer, w in ((0, zlo), (1, zhi)):
            p = pts[q + layer * n]
            p[ij[0]], p[ij[1]], p[k] = u, v, w
    tri = _triangles(poly)
    faces = [t for t in tri] + [(a + n, c + n, b + n) for a, b, c in tri]
    for q in range(n):
        r = (q + 1) % n
        faces += [(q, r, r + n), (q, r + n, q + n)]
    colour = "#e06666" if forbid else "#4caf50"
    mesh = {"type": "mesh3d", "x": [p[0] for p in pts], "y": [p[1] for p in pts], "z": [p[2] for p in pts],
            "i": [f[0] for f in faces], "j": [f[1] for f in faces], "k": [f[2] for f in faces],
            "color": colour, "opacity": 0.35 if forbid else 0.07, "flatshading": True, "name": name,
            "legendgroup": group, "showlegend": first, "hoverinfo": "name"}
    ex: list[float | None] = []
    ey: list[float | None] = []
    ez: list[float | None] = []

    def stroke(corners: list[list[float]]) -> None:  # one polyline of the edges, then a gap
        ex.extend([c[0] for c in corners] + [None])
        ey.extend([c[1] for c in corners] + [None])
        ez.extend([c[2] for c in corners] + [None])

    for loop in (range(n), range(n, 2 * n)):
        stroke([pts[q] for q in [*loop, loop[0]]])
    for q in range(n):
        stroke([pts[q], pts[q + n]])
    edges = {"type": "scatter3d", "mode": "lines", "x": ex, "y": ey, "z": ez, "name": name, "legendgroup": group,
             "showlegend": False, "hoverinfo": "name",
             "line": {"color": "#b22222" if forbid else _GREEN, "width": 3 if forbid else 2}}
    return [mesh, edges]


def _solid_traces2d(solid: Any, name: str, forbid: bool, group: str, first: bool) -> list[dict[str, Any]]:
    if solid[0] == "box":
        (x0, y0), (x1, y1) = solid[1][:2], solid[2][:2]
        poly = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    else:
        poly = solid[1] if solid[2] == (0, 1) else [(v, u) for u, v in solid[1]]
    xs = [p[0] for p in poly] + [poly[0][0]]
    ys = [p[1] for p in poly] + [poly[0][1]]
    return [{"type": "scatter", "mode": "lines", "x": xs, "y": ys, "fill": "toself", "name": name,
             "legendgroup": group, "showlegend": first, "hoverinfo": "name",
             "fillcolor": "rgba(224,102,102,0.4)" if forbid else "rgba(76,175,80,0.12)",
             "line": {"color": "#b22222" if forbid else _GREEN, "width": 1.5}}]


def _contact_traces(result: Any, machine: Machine, axes: Sequence[str], lims: list[tuple[float, float]]
                    ) -> list[dict[str, Any]]:
    """The fixture solids and the tool at each solid violation's contact (:mod:`nczones.report.solids_view`)."""
    from .solids_view import contact_traces

    out: list[dict[str, Any]] = contact_traces(result, machine, axes, lims, _solid_traces3d)
    return out


def _zone_traces(machine: Machine, path: PathFloat, axes: Sequence[str], lims: list[tuple[float, float]]
                 ) -> list[dict[str, Any]]:
    """Every zone where the proof puts it: tip zones moved by the placement of the tool active at the
    violating blocks (each further placement adds its tip zones), as the 2-D figures draw them."""
    placements = drawing_placements(path)
    first = placements[0] if placements else None
    sets = [(drawing_machine(machine, first).zones, placement_label(machine, first), False)]
    for extra in placements[1:]:
        sets.append((drawing_machine(machine, extra).zones, placement_label(machine, extra), True))
    make = _solid_traces3d if len(axes) == 3 else _solid_traces2d
    traces: list[dict[str, Any]] = []
    seen: set[str] = set()
    for zones, label, tips_only in sets:
        for z in zones:
            if tips_only and z.point is not ZonePoint.TIP:
                continue
            tip = f", {label}" if z.point is ZonePoint.TIP else ""
            name = f"{z.name} ({'forbidden' if z.forbid else 'allowed'}{tip})"
            for solid in _zone_solids(z, axes, lims):
                traces += make(solid, name, z.forbid, f"zone:{name}", name not in seen)
                seen.add(name)
    return traces


def _polyline(curves: list[np.ndarray], wheres: list[np.ndarray], idx: list[int], where_index: Any
              ) -> tuple[list[list[float | None]], list[int | None]]:
    """Coordinates (one list per view axis, None between polylines) and where indexes of ``curves``."""
    if not curves:
        return [[] for _ in idx], []
    gap = np.full((1, curves[0].shape[1]), np.nan)
    pts = np.concatenate([part for c in curves for part in (np.asarray(c)[:, idx], gap[:, idx])])
    codes = np.concatenate([part for w in wheres for part in (np.asarray(w, np.int64), np.asarray([-1]))])
    pts = np.round(pts, 4)
    coords: list[list[float | None]] = [[None if v != v else v for v in col] for col in pts.T.tolist()]
    return coords, [None if c < 0 else where_index(c) for c in codes.tolist()]


def view_data(path: PathFloat, result: Any, machine: Machine, *, max_points: int | None = None) -> dict[str, Any]:
    """The interactive view's figure (JSON-ready): ``traces``, ``layout``, ``views`` (the whole machine, then
    one around each violation: ``ranges`` per view axis), ``start`` (the view shown first: the first
    violation's, else the whole machine), ``where`` ((file, line) of each index the traces' ``customdata``
    hold), ``axes``, ``thinned`` and ``drawn`` (points left out of / drawn in the toolpath).

    >>> from nczones import load_machine
    >>> from nczones.prover import verify
    >>> from nczones.report.figure import collect_path
    >>> m = load_machine("specs/machines/mill.toml")
    >>> prog = "specs/examples/programs/drill_vise.ngc"
    >>> r = verify(prog, m)
    >>> d = view_data(collect_path(prog, m, {v.block for v in r.violations}), r, m)
    >>> d["axes"], [v["label"] for v in d["views"]][:2], d["start"]
    (['X', 'Y', 'Z'], ['Whole machine', 'Violation 1: line 5, vise'], 1)
    >>> [t["name"] for t in d["traces"] if t.get("meta") == "witness"]
    ['counterexample']
    """
    axes = view_axes(machine, result)
    names = machine.axis_names
    idx = [names.index(a) for a in axes]
    lims = _limits(machine, axes)
    thin = thin_path(path, MAX_POINTS if max_points is None else max_points)
    where: list[tuple[str, int | None]] = []
    index_of: dict[int, int] = {}

    def where_index(code: int) -> int:
        if code not in index_of:
            index_of[code] = len(where)
            k, line = divmod(int(code), 1 << 32)
            where.append((path.files[k] if k < len(path.files) else "", line or None))
        return index_of[code]

    three = len(axes) == 3
    kind = "scatter3d" if three else "scatter"
    keys = ("x", "y", "z")[:len(axes)]
    traces = _zone_traces(machine, path, axes, lims) + _contact_traces(result, machine, axes, lims)

    def line_trace(name: str, coords: list[list[float | None]], custom: list[int | None], meta: str,
                   line: dict[str, Any]) -> dict[str, Any]:
        t: dict[str, Any] = {"type": kind, "mode": "lines", "name": name, "customdata": custom, "meta": meta,
                             "line": line, "connectgaps": False}
        t.update(zip(keys, coords))
        return t

    drawn = 0
    for name, curves, wheres, dash in (("feed", thin.feed_curves, thin.feed_curve_where, "solid"),
                                       ("rapid", thin.rapid_curves, thin.rapid_curve_where, "dash")):
        lines = [np.asarray(a) for a in thin.feed_lines] if name == "feed" else [np.asarray(a) for a in thin.rapid_lines]
        lw = thin.feed_where if name == "feed" else thin.rapid_where
        # an unthinned path keeps its straight moves as rows: draw each row as a polyline of two points
        curves = list(curves) + [row for a in lines for row in a]
        wheres = list(wheres) + [np.asarray([c, c], np.int64) for w in lw for c in w.tolist()]
        drawn += sum(len(c) for c in curves)
        coords, custom = _polyline(curves, wheres, idx, where_index)
        traces.append(line_trace(name, coords, custom, name,
                                 {"color": _BLUE, "width": 3 if three else 1.5, "dash": dash}))
    hot_pts = [np.asarray(p) for p, _ in path.hot_curves]
    hot_w = [np.full(len(p), w, np.int64) for (p, _), w in zip(path.hot_curves, path.hot_where)]
    for rapid in (False, True):
        sel = [k for k, (_, r) in enumerate(path.hot_curves) if r is rapid]
        if sel:
            coords, custom = _polyline([hot_pts[k] for k in sel], [hot_w[k] for k in sel], idx, where_index)
            traces.append(line_trace("violating block" + (" (rapid)" if rapid else ""), coords, custom, "hot",
                                     {"color": _RED, "width": 7 if three else 3, "dash": "dash" if rapid else "solid"}))
    views: list[dict[str, Any]] = [{"label": "Whole machine", "ranges": [list(lim) for lim in lims]}]
    violations = list(result.violations) if result is not None else []
    marks: dict[str, list[Any]] = {"witness": [], "exit": []}
    for i, v in enumerate(violations, 1):
        file = v.span.file if v.span is not None else None
        code = where_code(path, file, v.line)
        w = where_index(code)
        p, q = dict(v.point), dict(v.first_exit)
        pts = [np.asarray(hp)[:, idx] for hp, c in zip(hot_pts, path.hot_where) if c == code]
        for kind_, pt in (("witness", p), ("exit", q)):
            if all(a in pt for a in axes):
                xyz = [to_float(pt[a]) for a in axes]
                marks[kind_].append((xyz, w, i))
                pts.append(np.asarray([xyz]))
        if not pts:
            continue
        stacked = np.concatenate([np.asarray(a).reshape(-1, len(axes)) for a in pts])
        lo, hi = stacked.min(axis=0), stacked.max(axis=0)
        # a cube (a square in 2-D) around the violation: true proportions, at least 10 mm wide
        half, mid = np.full(len(axes), max(float(np.max(hi - lo)) * 0.75, 5.0)), (lo + hi) / 2
        views.append({"label": f"Violation {i}: line {v.line}, {v.zone}" if v.line is not None
                               else f"Violation {i}: block {v.block}, {v.zone}",
                      "ranges": [[float(a), float(b)] for a, b in zip(mid - half, mid + half)], "violation": i})
    # plotly draws 3-D markers as font glyphs, and fonts often lack its "x" (✖): the witness is a diamond there
    for kind_, label, symbol in (("witness", "counterexample", "x" if not three else "diamond"),
                                 ("exit", "first exit", "circle-open")):
        if not marks[kind_]:
            continue
        t = {"type": kind, "mode": "markers", "name": label, "meta": kind_,
             "customdata": [w for _, w, _ in marks[kind_]], "ids": [f"{kind_}-{i}" for _, _, i in marks[kind_]],
             "marker": {"color": _RED, "symbol": symbol, "size": (7 if three else 12) if kind_ == "witness" else 6,
                        "line": {"color": _RED, "width": 2}}}
        t.update(zip(keys, [[round(xyz[k], 6) for xyz, _, _ in marks[kind_]] for k in range(len(axes))]))
        traces.append(t)
    unit = {a.name: ("deg" if a.rotary else "mm") for a in machine.axes}
    titles = {a: f"{a} ({unit[a]})" for a in axes}
    if three:
        layout: dict[str, Any] = {"scene": {f"{k}axis": {"title": {"text": titles[a]}} for k, a in zip(keys, axes)}}
        layout["scene"]["aspectmode"] = "manual"
    else:
        layout = {"xaxis": {"title": {"text": titles[axes[0]]}},
                  "yaxis": {"title": {"text": titles[axes[1]]}, "scaleanchor": "x", "scaleratio": 1}}
    layout.update({"margin": {"l": 0 if three else 60, "r": 0, "t": 10, "b": 0 if three else 50},
                   "legend": {"x": 1, "xanchor": "right", "y": 1, "bgcolor": "rgba(255,255,255,0.8)"},
                   "hovermode": "closest", "uirevision": "nczones"})
    return {"axes": list(axes), "traces": traces, "layout": layout, "views": views,
            "start": 1 if len(views) > 1 else 0, "where": where, "thinned": thin.thinned, "drawn": drawn,
            "segments": path.segments}
