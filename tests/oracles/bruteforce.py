"""An independent brute-force checker: does a motion leave the allowed set?

It uses only exact rationals and :meth:`AllowedSet.violated_zones` — no
prover code — so it can judge the prover.  Each segment is sampled densely
with exact points of the ideal path, plus every parameter at which a
coordinate crosses a zone constant (shifted by the margin and, on the tool
axis of tool-tip zones, by the tool length) or a polygon edge, and points
just either side of those.  It can miss a violation (sampling), never
invent one: every point it reports is an exact point of the path whose
margin box violates a zone.

Paths, as DESIGN and :mod:`nczones.motion` define them:

* LINE and linear RAPID: the straight line, parameter = fraction of length;
* dogleg RAPID: every axis starts at once and moves at its own rapid rate,
  so the path is a polyline with a corner whenever an axis arrives;
* ARC (I J K format, no helix): exact rational points of the circle (the
  tangent half-angle parametrisation of rotations), axis extremes and
  boundary crossings where they are rational, restricted exactly to the
  swept angle; a spiral (end radius off the start radius) only its ends.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from nczones.machine import Machine, RapidMode
from nczones.motion import Segment, SegmentKind
from nczones.zones import ZonePoint

F0 = Fraction(0)
EPS = Fraction(1, 10**7)


class Unsupported(Exception):
    """The brute force does not model this motion (R-format arc, helix)."""


@dataclass(frozen=True)
class Hit:
    index: int  # index of the segment in the list given
    block: int
    point: tuple[Fraction, ...]
    zones: tuple[str, ...]


def zone_constants(machine: Machine, axis: str, tool_length: Fraction) -> set[Fraction]:
    """Every value of ``axis`` at which some zone's membership can change (machine coordinates)."""
    out: set[Fraction] = set()
    for z in machine.allowed.zones:
        shift = tool_length if (z.point is ZonePoint.TIP and axis == machine.allowed.tool_axis) else F0
        vals: set[Fraction] = set()
        if z.kind == "stepped":
            if axis == z.reference_axis:
                vals.add(z.start)
                vals.update(z.uptos)
            if axis == z.limited_axis:
                vals.update(v for r in z.regions for v in (r.min, r.max) if v is not None)
        else:
            if z.kind == "polygon" and axis in z.plane:
                k = z.plane.index(axis)
                vals.update(v[k] for v in z.vertices)
            for a, (lo, hi) in z.bounds().items():
                if a == axis:
                    vals.update(v for v in (lo, hi) if v is not None)
        out.update(v + shift for v in vals)
    return out


def _linear_params(p0, p1, axes, machine: Machine, tool_length: Fraction, margin: Fraction, n: int) -> set[Fraction]:
    ts = {Fraction(i, n) for i in range(n + 1)}
    crossings: set[Fraction] = set()
    for k, a in enumerate(axes):
        a0, a1 = p0[k], p1[k]
        if a0 == a1:
            continue
        for c in zone_constants(machine, a, tool_length):
            for sh in (-margin, F0, margin):
                crossings.add((c + sh - a0) / (a1 - a0))
    # polygon edges: where the segment crosses the line through an edge (shifted by the margin)
    for z in machine.allowed.zones:
        if z.kind != "polygon":
            continue
        i, j = axes.index(z.plane[0]), axes.index(z.plane[1])
        d = (p1[i] - p0[i], p1[j] - p0[j])
        vs = z.vertices
        for (ax, ay), (bx, by) in zip(vs, vs[1:] + vs[:1]):
            e = (bx - ax, by - ay)
            den = d[0] * e[1] - d[1] * e[0]
            if den == 0:
                continue
            for sx in (-margin, F0, margin):
                for sy in (-margin, F0, margin):
                    crossings.add(((ax + sx - p0[i]) * e[1] - (ay + sy - p0[j]) * e[0]) / den)
            # and the parameters at which the segment passes a vertex on some axis
    for t in crossings:
        for e in (F0, EPS, -EPS):
            if 0 <= t + e <= 1:
                ts.add(t + e)
    return ts


def line_points(seg: Segment, machine: Machine, margin: Fraction = F0, n: int = 64) -> list[tuple[Fraction, ...]]:
    p0, p1 = seg.start, seg.end
    ts = _linear_params(p0, p1, seg.axes, machine, seg.tool_length, margin, n)
    return [tuple(a + t * (b - a) for a, b in zip(p0, p1)) for t in sorted(ts)]


def dogleg_corners(seg: Segment, machine: Machine) -> list[tuple[Fraction, ...]]:
    """The corners of a dogleg rapid: where each axis arrives (each moves at its own rate)."""
    rates = [machine.axis(a).rapid_mm_min for a in seg.axes]
    arrive = [abs(e - s) / r for s, e, r in zip(seg.start, seg.end, rates)]
    corners = [seg.start]
    for tau in sorted(set(arrive)):
        if tau == 0:
            continue
        corners.append(tuple(
            s + (1 if e > s else -1) * min(tau, T) * r if e != s else s
            for s, e, r, T in zip(seg.start, seg.end, rates, arrive)
        ))
    if corners[-1] != seg.end:  # exact arithmetic: the last corner is the end
        raise AssertionError("dogleg corners do not end at the end point")
    return corners


def _diamond(v) -> Fraction:
    """A pseudo-angle in [0, 4): exact, strictly increasing with the true angle."""
    x, y = v
    if y >= 0:
        return y / (x + y) if x >= 0 and (x + y) else (Fraction(1) - x / (-x + y) if (-x + y) else F0)
    if x < 0:
        return 2 - y / (-x - y) if x <= 0 else F0
    return 3 + x / (x - y)


def _rel(u, v, ccw: bool) -> Fraction:
    d = (_diamond(v) - _diamond(u)) if ccw else (_diamond(u) - _diamond(v))
    return d % 4


def _isqrt_exact(q: Fraction) -> Fraction | None:
    if q < 0:
        return None
    from math import isqrt

    a, b = isqrt(q.numerator), isqrt(q.denominator)
    return Fraction(a, b) if a * a == q.numerator and b * b == q.denominator else None


def arc_points(seg: Segment, machine: Machine, n: int = 64) -> list[tuple[Fraction, ...]]:
    if seg.centre is None:
        raise Unsupported("R-format arc (irrational centre)")
    if seg.is_helix():
        raise Unsupported("helix")
    i, j, _ = seg.plane_indices()
    c = seg.centre
    u = (seg.start[i] - c[0], seg.start[j] - c[1])
    w = (seg.end[i] - c[0], seg.end[j] - c[1])
    ccw = not seg.clockwise
    full = u == w
    r2 = u[0] ** 2 + u[1] ** 2
    if r2 != w[0] ** 2 + w[1] ** 2:
        # a spiral (end off the circle within the arc tolerance): its inner points are not on the start
        # circle and not rational in general; its two ends are the exact points it has
        return [seg.start, seg.end]
    cands = []
    base = u
    for _ in range(4):
        for k in range(n + 1):
            m = Fraction(k, n)
            cs, sn = (1 - m * m) / (1 + m * m), 2 * m / (1 + m * m)
            if not ccw:
                sn = -sn
            cands.append((base[0] * cs - base[1] * sn, base[0] * sn + base[1] * cs))
        base = (-base[1], base[0]) if ccw else (base[1], -base[0])
    r = _isqrt_exact(r2)
    if r is not None:
        cands += [(r, F0), (-r, F0), (F0, r), (F0, -r)]
    for pk, axis_k in enumerate((i, j)):
        for b in zone_constants(machine, seg.axes[axis_k], seg.tool_length):
            d = b - c[pk]
            s = _isqrt_exact(r2 - d * d)
            if s is not None:
                for sgn in (1, -1):
                    v = [F0, F0]
                    v[pk], v[1 - pk] = d, sgn * s
                    cands.append(tuple(v))
    end_rel = _rel(u, w, ccw)
    out = []
    for v in cands:
        if full or _rel(u, v, ccw) <= end_rel:
            p = list(seg.start)
            p[i], p[j] = c[0] + v[0], c[1] + v[1]
            out.append(tuple(p))
    out.append(seg.end)
    return out


def segment_points(seg: Segment, machine: Machine, margin: Fraction = F0, n: int = 64) -> list[tuple[Fraction, ...]]:
    """Exact points of the segment's ideal path (see the module docstring)."""
    if seg.kind is SegmentKind.ARC:
        return arc_points(seg, machine, n)
    if seg.kind is SegmentKind.DWELL:
        return [seg.start]
    if seg.kind is SegmentKind.RAPID and machine.rapid_mode is RapidMode.DOGLEG:
        corners = dogleg_corners(seg, machine)
        pts = []
        for a, b in zip(corners, corners[1:]):
            piece = Segment(SegmentKind.LINE, a, b, seg.axes, tool_length=seg.tool_length)
            pts += line_points(piece, machine, margin, n)
        return pts or [seg.start]
    return line_points(seg, machine, margin, n)


def first_violation(segments, machine: Machine, margin: Fraction = F0, n: int = 64) -> Hit | None:
    """The first segment (in order) with a sampled exact path point whose margin box violates a zone."""
    allowed = machine.allowed
    for idx, seg in enumerate(segments):
        for p in segment_points(seg, machine, margin, n):
            bad = allowed.violated_zones(dict(zip(seg.axes, p)), seg.tool_length, margin)
            if bad:
                return Hit(idx, seg.block, p, tuple(z.name for z in bad))
    return None
