"""Exact rational decisions for straight pieces against box, stepped and polygon zones.

For a straight piece ``p(t) = p0 + t (p1 - p0)``, ``t`` in ``[0, 1]``, and one
zone, :func:`line_violation` computes the *exact* set of parameters whose
margin box violates the zone, as a finite union of intervals with rational
end points (open or closed).  With margin ``d`` a point violates an allow
zone when some point of its closed box of half-width ``d`` is outside the
zone, and a forbid zone when the box meets the zone's open interior
(``AllowedSet.violated_zones`` semantics); per axis the box is independent,
so each condition is linear in ``t``.  This is a decision procedure: the
piece is safe for the zone iff the returned union is empty.

Invariant: every returned interval lies in ``[0, 1]`` and is non-empty;
``t`` in an interval <=> ``violated_zones(p(t), L, d)`` contains the zone.

Also here: the first exit (infimum of the union), depth along a piece
(:func:`point_depth`, maximised exactly over a piece by
:func:`line_depth`), a point strictly outside the allowed set inside a
violating margin box (:func:`outside_point`) and the certification of a
small rational box (:func:`box_certainly_violates`), used for witnesses on
irrational paths.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from fractions import Fraction

from ..exact import max_bound, min_bound
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)
from ..zones import AllowedSet, BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint
from ..zones.kinds import KindTable

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = [
    "ParamRange",
    "line_violation",
    "first_point",
    "point_depth",
    "line_depth",
    "line_depth_bound",
    "zone_constants",
    "outside_point",
    "box_certainly_violates",
    "decidable",
    "reachable",
    "box_fits",
]

F0 = Fraction(0)
F1 = Fraction(1)


@dataclass(frozen=True, slots=True)
class ParamRange:
    """A non-empty interval of the motion parameter ``t`` with rational ends; ``lo_closed``/``hi_closed`` say
    which ends belong.  A set of parameters, exact: not an enclosure (that is :class:`nczones.exact.Interval`)."""

    lo: Fraction
    hi: Fraction
    lo_closed: bool
    hi_closed: bool

    def sample(self) -> Fraction:
        """A parameter inside the interval (the low end if it belongs, else the midpoint)."""
        if self.lo_closed:
            return self.lo
        if self.hi_closed and self.hi == self.lo:
            return self.hi
        return (self.lo + self.hi) / 2

    def contains(self, t: Fraction) -> bool:
        return (self.lo < t or (self.lo_closed and t == self.lo)) and (
            t < self.hi or (self.hi_closed and t == self.hi)
        )


UNIT = ParamRange(F0, F1, True, True)


def _make(lo: Fraction, hi: Fraction, lc: bool, hc: bool) -> ParamRange | None:
    if lo > hi or (lo == hi and not (lc and hc)):
        return None
    return ParamRange(lo, hi, lc, hc)


def _intersect(a: ParamRange | None, b: ParamRange | None) -> ParamRange | None:
    if a is None or b is None:
        return None
    if a.lo > b.lo:
        lo, lc = a.lo, a.lo_closed
    elif b.lo > a.lo:
        lo, lc = b.lo, b.lo_closed
    else:
        lo, lc = a.lo, a.lo_closed and b.lo_closed
    if a.hi < b.hi:
        hi, hc = a.hi, a.hi_closed
    elif b.hi < a.hi:
        hi, hc = b.hi, b.hi_closed
    else:
        hi, hc = a.hi, a.hi_closed and b.hi_closed
    return _make(lo, hi, lc, hc)


def _atom(alpha: Fraction, beta: Fraction, strict: bool) -> ParamRange | None:
    """``{t in [0,1] : alpha + beta t < 0}`` (``<=`` when not strict)."""
    if beta == 0:
        ok = alpha < 0 if strict else alpha <= 0
        return UNIT if ok else None
    x = -alpha / beta
    if beta > 0:  # t < x
        return _intersect(UNIT, ParamRange(min(x, F0) - 1, x, True, not strict) if x >= F0 - 1 else None)
    return _intersect(UNIT, ParamRange(x, max(x, F1) + 1, not strict, True))


class _Line:
    """Coordinates of a piece as affine functions of t, as a zone sees them."""

    __slots__ = ("p0", "p1", "index", "shift_axis", "shift")

    def __init__(self, p0: Sequence[Fraction], p1: Sequence[Fraction], axes: Sequence[str], zone: Zone,
                 tool_length: Fraction, tool_axis: str | None):
        self.p0, self.p1 = p0, p1
        self.index = {a: i for i, a in enumerate(axes)}
        self.shift_axis = tool_axis if (zone.point is ZonePoint.TIP and tool_length) else None
        self.shift = tool_length

    def ends(self, axis: str) -> tuple[Fraction, Fraction]:
        i = self.index[axis]
        a, b = self.p0[i], self.p1[i]
        if axis == self.shift_axis:
            return a - self.shift, b - self.shift
        return a, b

    def lt(self, axis: str, c: Fraction, strict: bool = True) -> ParamRange | None:
        """t where coord(t) < c (<= when not strict)."""
        a, b = self.ends(axis)
        return _atom(a - c, b - a, strict)

    def gt(self, axis: str, c: Fraction, strict: bool = True) -> ParamRange | None:
        a, b = self.ends(axis)
        return _atom(c - a, a - b, strict)


def decidable(zone: Zone) -> bool:
    """Zones :func:`line_violation` decides: the kinds of :data:`LINE_VIOLATION` (boxes, stepped tables,
    polygons)."""
    return type(zone) in LINE_VIOLATION.kinds


def _all(parts: Iterable[ParamRange | None]) -> ParamRange | None:
    out: ParamRange | None = UNIT
    for p in parts:
        out = _intersect(out, p)
        if out is None:
            return None
    return out


def _union(parts: Iterable[ParamRange | None]) -> list[ParamRange]:
    """Sorted union (merged where they overlap or touch with a closed end)."""
    items = sorted((p for p in parts if p is not None), key=lambda i: (i.lo, not i.lo_closed))
    out: list[ParamRange] = []
    for it in items:
        if out:
            last = out[-1]
            if it.lo < last.hi or (it.lo == last.hi and (it.lo_closed or last.hi_closed)):
                if it.hi > last.hi or (it.hi == last.hi and it.hi_closed and not last.hi_closed):
                    out[-1] = ParamRange(last.lo, it.hi, last.lo_closed, it.hi_closed)
                continue
        out.append(it)
    return out


def line_violation(
    zone: Zone,
    p0: tuple[Fraction, ...],
    p1: tuple[Fraction, ...],
    axes: tuple[str, ...],
    margin: Fraction = F0,
    tool_length: Fraction = F0,
    tool_axis: str | None = "Z",
) -> list[ParamRange]:
    """Exact set of ``t`` in ``[0,1]`` whose margin box violates ``zone``.

    Examples
    --------
    >>> from nczones.zones import Region
    >>> F = Fraction
    >>> notch = SteppedZone("t", "X", "Y", F(0), (Region(F(10), F(5)), Region(F(20), F(0)),
    ...                                           Region(F(30), F(5))))
    >>> line_violation(notch, (F(5), F(6)), (F(25), F(6)), ("X", "Y"))
    []
    >>> line_violation(notch, (F(5), F(6)), (F(25), F(2)), ("X", "Y"))
    [ParamRange(lo=Fraction(3, 4), hi=Fraction(1, 1), lo_closed=False, hi_closed=True)]
    """
    return LINE_VIOLATION(zone, _Line(p0, p1, axes, zone, tool_length, tool_axis), margin)


#: The exact set of ``t`` whose margin box violates the zone along a straight piece, per zone kind: the kinds
#: with an entry are :func:`decidable` (the others go to the SMT tier).
LINE_VIOLATION: KindTable[Callable[[Any, _Line, Fraction], list[ParamRange]]] = KindTable("prover.exact.line_violation")


@LINE_VIOLATION.register(BoxZone)
def _box_violation(zone: BoxZone, ln: _Line, d: Fraction) -> list[ParamRange]:
        if zone.forbid:
            if _flat(zone.limits):
                return []  # no interior, nothing forbidden, whatever the margin
            conds = []
            for axis, lo, hi in zone.limits:
                if lo is not None:
                    conds.append(ln.gt(axis, lo - d))
                if hi is not None:
                    conds.append(ln.lt(axis, hi + d))
            return _union([_all(conds)])
        parts = []
        for axis, lo, hi in zone.limits:
            if lo is not None:
                parts.append(ln.lt(axis, lo + d))
            if hi is not None:
                parts.append(ln.gt(axis, hi - d))
        return _union(parts)


@LINE_VIOLATION.register(SteppedZone)
def _stepped_violation(zone: SteppedZone, ln: _Line, d: Fraction) -> list[ParamRange]:
        r, lim = zone.reference_axis, zone.limited_axis
        parts = []
        ra, rb = ln.ends(r)
        r_lo, r_hi = min(ra, rb) - d, max(ra, rb) + d
        idx = reachable(zone, r_lo, r_hi)
        if zone.forbid:
            for i in idx:
                reg = zone.regions[i]
                if reg.min is not None and reg.max is not None and not reg.min < reg.max:
                    continue  # a flat row has no interior
                a, b = zone.region_lower(i), reg.upto
                conds = [ln.lt(r, b + d), ln.gt(r, a - d)]
                if reg.max is not None:
                    conds.append(ln.lt(lim, reg.max + d))
                if reg.min is not None:
                    conds.append(ln.gt(lim, reg.min - d))
                parts.append(_all(conds))
            for i in idx:
                if i + 1 >= len(zone.regions):
                    continue
                reg, nxt = zone.regions[i], zone.regions[i + 1]
                b = reg.upto
                lo = max_bound(reg.min, nxt.min)
                hi = min_bound(reg.max, nxt.max)
                if lo is not None and hi is not None and not lo < hi:
                    continue
                conds = [ln.lt(r, b + d, False), ln.gt(r, b - d, False)]
                if hi is not None:
                    conds.append(ln.lt(lim, hi + d))
                if lo is not None:
                    conds.append(ln.gt(lim, lo - d))
                parts.append(_all(conds))
            return _union(parts)
        parts.append(ln.lt(r, zone.start + d))
        parts.append(ln.gt(r, zone.regions[-1].upto - d))
        for i in idx:
            reg = zone.regions[i]
            a, b = zone.region_lower(i), reg.upto
            touch = _all([ln.lt(r, b + d, False), ln.gt(r, a - d, i != 0)])
            if touch is None:
                continue
            if reg.min is not None:
                parts.append(_intersect(touch, ln.lt(lim, reg.min + d)))
            if reg.max is not None:
                parts.append(_intersect(touch, ln.gt(lim, reg.max - d)))
        return _union(parts)


@LINE_VIOLATION.register(PolygonZone)
def _polygon_violation(zone: PolygonZone, ln: _Line, d: Fraction) -> list[ParamRange]:
    """A polygon is a prism: its plane part (:func:`nczones.prover.polygon.plane_violation`) times the
    box of its limits.  An allow prism is violated where either part is; a forbid prism where both
    are (the margin box is a product too, so it meets the prism's interior iff each part does)."""
    from .polygon import plane_violation

    xa, xb = ln.ends(zone.plane[0])
    ya, yb = ln.ends(zone.plane[1])
    plane = [_make(lo, hi, lc, hc) for lo, hi, lc, hc in plane_violation(zone, (xa, ya), (xb, yb), d)]
    if zone.forbid:
        if _flat(zone.limits):
            return []
        conds = []
        for axis, lo, hi in zone.limits:
            if lo is not None:
                conds.append(ln.gt(axis, lo - d))
            if hi is not None:
                conds.append(ln.lt(axis, hi + d))
        within = _all(conds)
        return _union(_intersect(p, within) for p in plane)
    parts = plane
    for axis, lo, hi in zone.limits:
        if lo is not None:
            parts.append(ln.lt(axis, lo + d))
        if hi is not None:
            parts.append(ln.gt(axis, hi - d))
    return _union(parts)


def _flat(limits: tuple[tuple[str, Fraction | None, Fraction | None], ...]) -> bool:
    """Does some axis range have no interior (``min == max``)?  Then a forbid zone forbids nothing."""
    return any(lo is not None and hi is not None and not lo < hi for _, lo, hi in limits)


def reachable(zone: SteppedZone, lo: Fraction, hi: Fraction) -> range:
    """Indices of regions whose closed reference range meets ``[lo, hi]`` (:meth:`SteppedZone.reached`)."""
    return zone.reached(lo, hi)


def first_point(intervals: list[ParamRange]) -> tuple[Fraction, bool]:
    """Infimum of a non-empty union and whether it is attained."""
    first = intervals[0]
    return first.lo, first.lo_closed


# --------------------------------------------------------------------------- depth


def zone_constants(zone: Zone, axis: str) -> list[Fraction]:
    """The zone's boundary values on one axis (where its predicate can change)."""
    return sorted(set(ZONE_CONSTANTS(zone, axis)))


#: The zone's boundary values on one axis, per zone kind (unsorted, repeats allowed).
ZONE_CONSTANTS: KindTable[Callable[[Any, str], list[Fraction]]] = KindTable("prover.exact.zone_constants")


@ZONE_CONSTANTS.register(BoxZone)
def _box_constants(zone: BoxZone, axis: str) -> list[Fraction]:
    out: list[Fraction] = []
    for a, lo, hi in zone.limits:
        if a == axis:
            out += [v for v in (lo, hi) if v is not None]
    return out


@ZONE_CONSTANTS.register(SteppedZone)
def _stepped_constants(zone: SteppedZone, axis: str) -> list[Fraction]:
    out: list[Fraction] = []
    if axis == zone.reference_axis:
        out.append(zone.start)
        out += list(zone.uptos)
    elif axis == zone.limited_axis:
        for reg in zone.regions:
            out += [v for v in (reg.min, reg.max) if v is not None]
    return out


@ZONE_CONSTANTS.register(PolygonZone)
def _polygon_constants(zone: PolygonZone, axis: str) -> list[Fraction]:
    out: list[Fraction] = []
    if axis in zone.plane:
        k = zone.plane.index(axis)
        out += [v[k] for v in zone.vertices]
    for a, lo, hi in zone.limits:
        if a == axis:
            out += [v for v in (lo, hi) if v is not None]
    return out


def _rect_dist(p: tuple[Fraction, Fraction], rect: Any) -> Fraction:
    (x0, x1), (y0, y1) = rect
    gaps = [F0]
    if x0 is not None:
        gaps.append(x0 - p[0])
    if x1 is not None:
        gaps.append(p[0] - x1)
    if y0 is not None:
        gaps.append(y0 - p[1])
    if y1 is not None:
        gaps.append(p[1] - y1)
    return max(gaps)


def _stepped_eroded_rects(zone: SteppedZone, d: Fraction) -> list[Any]:
    """Closed rectangles whose union is the closure of {q : box(q, d) fits the zone}, in order along the
    reference axis (the spans between consecutive cuts and the cuts themselves, each after the one before).

    At each span's middle the regions a box of half-width ``d`` reaches are one run (:meth:`SteppedZone.reached`
    less a region it only touches at its open lower end, as :meth:`SteppedZone.box_inside` counts them): their
    largest ``min`` and smallest ``max`` bound the rectangle.  Made once per zone and margin
    (:func:`_eroded`): a depth is asked at thousands of points of a violating piece (issue 36: a 12-line
    program against a 4,096-region table ran for minutes, every point rebuilding them over every region)."""
    regs = zone.regions
    cuts = sorted({zone.start + d, regs[-1].upto - d} | {r.upto + s for r in regs for s in (-d, d)})
    cuts = [c for c in cuts if zone.start + d <= c <= regs[-1].upto - d]
    rects = []
    spans = sorted([(c, c) for c in cuts] + list(zip(cuts, cuts[1:])))
    for a, b in spans:
        mid = (a + b) / 2
        lo_r, hi_r = mid - d, mid + d
        los, his = [], []
        for i in zone.reached(lo_r, hi_r):
            reg = regs[i]
            if i > 0 and not hi_r > regs[i - 1].upto:
                continue  # touches the region's open lower end only
            if reg.min is not None:
                los.append(reg.min + d)
            if reg.max is not None:
                his.append(reg.max - d)
        lo = max(los) if los else None
        hi = min(his) if his else None
        if lo is None or hi is None or lo <= hi:
            rects.append(((a, b), (lo, hi)))
    return rects


_ERODED: dict[tuple[int, Fraction], tuple[SteppedZone, list[Any], list[Fraction]]] = {}


def _eroded(zone: SteppedZone, d: Fraction) -> tuple[list[Any], list[Fraction]]:
    """:func:`_stepped_eroded_rects` of ``zone`` and ``d``, and their reference ends (``b`` of each), kept for the
    last few zones and margins (the zone held with them, so its id is not reused meanwhile)."""
    key = (id(zone), d)
    hit = _ERODED.get(key)
    if hit is None or hit[0] is not zone:
        if len(_ERODED) >= 16:
            _ERODED.pop(next(iter(_ERODED)))
        rects = _stepped_eroded_rects(zone, d)
        hit = _ERODED[key] = (zone, rects, [r[0][1] for r in rects])
    return hit[1], hit[2]


def _nearest_rect_dist(q: tuple[Fraction, Fraction], rects: list[Any], ends: list[Fraction]) -> Fraction:
    """``min(_rect_dist(q, r) for r in rects)`` for rectangles in order along the reference axis (their ranges
    ``[a, b]`` with ``a`` and ``b`` nondecreasing, ``ends`` the ``b``): searched outwards from the first one that
    ends at or after ``q``'s reference value, each way only while the reference gap alone is below the best
    distance (a rectangle farther along is farther by at least its gap, which only grows)."""
    from bisect import bisect_left

    x = q[0]
    k = bisect_left(ends, x)
    best: Fraction | None = None
    for j in range(k, len(rects)):  # ends >= x: the gap is a - x where positive
        gap = rects[j][0][0] - x
        if best is not None and gap >= best:
            break
        v = _rect_dist(q, rects[j])
        best = v if best is None or v < best else best
    for j in range(k - 1, -1, -1):  # ends < x: the gap x - b
        if best is not None and x - ends[j] >= best:
            break
        v = _rect_dist(q, rects[j])
        best = v if best is None or v < best else best
    assert best is not None
    return best


def point_depth(zone: Zone, p: Mapping[str, Fraction], margin: Fraction = F0) -> Fraction:
    """How far past the zone's boundary (beyond the margin) the point ``p`` is.

    Definitions (``p`` as the zone sees it, i.e. the tool tip for tip zones):

    * allow box / allow stepped table: the L-infinity distance from ``p`` to
      the closed set of points whose margin box fits the zone (0 inside);
    * forbid box: the L-infinity distance from ``p`` to the complement of the
      open interior grown by the margin (how deep inside it is);
    * forbid stepped table: the same for the deepest single row (a lower
      bound where rows join);
    * polygon: the L-infinity distance to the polygon's boundary plus the
      margin, for a violating point (a lower bound with margins).

    >>> F = Fraction
    >>> box = BoxZone("b", (("X", F(0), F(10)),))
    >>> point_depth(box, {"X": F(12)}), point_depth(box, {"X": F(9)}, F(2))
    (Fraction(2, 1), Fraction(1, 1))
    """
    return POINT_DEPTH(zone, p, margin)


#: :func:`point_depth` per zone kind (``d`` the margin).
POINT_DEPTH: KindTable[Callable[[Any, Mapping[str, Fraction], Fraction], Fraction]] = KindTable("prover.exact.point_depth")


@POINT_DEPTH.register(BoxZone)
def _box_depth(zone: BoxZone, p: Mapping[str, Fraction], d: Fraction) -> Fraction:
    if zone.forbid:
        if _flat(zone.limits):
            return F0
        slacks = []
        for a, lo, hi in zone.limits:
            if lo is not None:
                slacks.append(p[a] - (lo - d))
            if hi is not None:
                slacks.append((hi + d) - p[a])
        return max(F0, min(slacks)) if slacks else F0
    gaps = [F0]
    for a, lo, hi in zone.limits:
        if lo is not None:
            gaps.append(lo + d - p[a])
        if hi is not None:
            gaps.append(p[a] - (hi - d))
    return max(gaps)


@POINT_DEPTH.register(SteppedZone)
def _stepped_depth(zone: SteppedZone, p: Mapping[str, Fraction], d: Fraction) -> Fraction:
    q = (p[zone.reference_axis], p[zone.limited_axis])
    if zone.forbid:
        # a region's slack on the reference axis is positive only where q lies within d of its range, so only
        # the regions [q - d, q + d] reaches can raise the depth above 0
        best = F0
        regs = zone.regions
        for i in zone.reached(q[0] - d, q[0] + d):
            reg = regs[i]
            if reg.min is not None and reg.max is not None and not reg.min < reg.max:
                continue
            rect = ((zone.region_lower(i) - d, reg.upto + d),
                    (None if reg.min is None else reg.min - d, None if reg.max is None else reg.max + d))
            slacks = [q[0] - rect[0][0], rect[0][1] - q[0]]
            if rect[1][0] is not None:
                slacks.append(q[1] - rect[1][0])
            if rect[1][1] is not None:
                slacks.append(rect[1][1] - q[1])
            best = max(best, min(slacks))
        return best
    rects, ends = _eroded(zone, d)
    if not rects:
        return F0
    return _nearest_rect_dist(q, rects, ends)


@POINT_DEPTH.register(PolygonZone)
def _polygon_depth(zone: PolygonZone, p: Mapping[str, Fraction], d: Fraction) -> Fraction:
    q = (p[zone.plane[0]], p[zone.plane[1]])
    dist = min(_seg_dist_inf(q, a, b) for a, b in zone.edges())
    lim_gap = F0
    for a, lo, hi in zone.limits:
        if lo is not None:
            lim_gap = max(lim_gap, lo - p[a])
        if hi is not None:
            lim_gap = max(lim_gap, p[a] - hi)
    return max(dist, lim_gap) + d


def _seg_dist_inf(q: Sequence[Fraction], a: Sequence[Fraction], b: Sequence[Fraction]) -> Fraction:
    """Exact L-infinity distance from q to the segment [a, b]."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    cands = {F0, F1}
    if dx:
        cands.add((q[0] - a[0]) / dx)
    if dy:
        cands.add((q[1] - a[1]) / dy)
    for s in (1, -1):  # q_x - a_x - t dx = s (q_y - a_y - t dy)
        den = dx - s * dy
        if den:
            cands.add(((q[0] - a[0]) - s * (q[1] - a[1])) / den)
    best: Fraction | None = None
    for t in cands:
        if 0 <= t <= 1:
            v = max(abs(q[0] - a[0] - t * dx), abs(q[1] - a[1] - t * dy))
            best = v if best is None else min(best, v)
    assert best is not None  # t = 0 and t = 1 are candidates
    return best


def line_depth(
    zone: Zone, p0: Sequence[Fraction], p1: Sequence[Fraction], axes: Sequence[str], margin: Fraction,
    tool_length: Fraction, tool_axis: str | None,
    max_candidates: int = 20000,
) -> tuple[Fraction, Fraction, bool]:
    """Maximum of :func:`point_depth` over a straight piece: ``(depth, t, exact)``.

    The depth along a line is piecewise linear in ``t`` with breakpoints only
    where two of the affine functions it is built from (coordinate minus a
    zone constant, shifted by the margin) are equal or one is zero; the
    maximum is attained at such a breakpoint or at an end.  ``exact`` is
    False when the candidate set was capped (then the value is a lower bound).
    """
    ln = _Line(p0, p1, axes, zone, tool_length, tool_axis)
    zaxes = [a for a in zone.axes if a in ln.index]
    lines = []  # (axis, a, b) with coord(t) = a + t (b - a)
    for ax in zaxes:
        a, b = ln.ends(ax)
        lo, hi = min(a, b) - margin, max(a, b) + margin
        consts = [c for c in zone_constants(zone, ax)]
        near = [c for c in consts if lo - (hi - lo) - 1 <= c <= hi + (hi - lo) + 1] or consts[:2]
        for c in near:
            for s in (-margin, margin, F0):
                lines.append((a - (c + s), b - (c + s)))
                lines.append((-(a - (c + s)), -(b - (c + s))))
    cands, exact = _breakpoints(lines, max_candidates)
    best: Fraction | None = None
    best_t = F0
    for t in sorted(cands):
        pt = {ax: ln.ends(ax)[0] + t * (ln.ends(ax)[1] - ln.ends(ax)[0]) for ax in zaxes}
        v = point_depth(zone, pt, margin)
        if best is None or v > best:
            best, best_t = v, t
    assert best is not None  # t = 0 and t = 1 are candidates
    return best, best_t, exact and LINE_DEPTH_EXACT.of(zone)


def line_depth_bound(zone: Zone, p0: Sequence[Fraction], p1: Sequence[Fraction], axes: Sequence[str],
                     margin: Fraction, tool_length: Fraction, tool_axis: str | None) -> Fraction:
    """An upper bound of :func:`line_depth`'s depth over the piece ``p0 -> p1``, from the depths at its two ends
    (:data:`LINE_DEPTH_BOUND`, per zone kind).

    Soundness (``tests/prover/test_line_depth_bound.py`` holds every kind to it): :func:`point_depth` is
    1-Lipschitz in the L-infinity norm of the zone's coordinates for every zone kind (an L-infinity distance to a
    closed set -- an eroded box, a union of eroded rectangles, a polygon's boundary -- or a minimum or maximum of
    coordinate differences, each of which changes by at most as much as the point moves, and the maximum of such
    with a constant); the tool-tip shift moves every point alike.  A 1-Lipschitz ``f`` on a piece of L-infinity
    length ``L`` has ``f(t) <= f(0) + t L`` and ``f(t) <= f(1) + (1 - t) L``, so ``f(t) <= (f(0) + f(1) + L) / 2``
    everywhere on it.  An allowed box's depth is also convex (the maximum of 0 and affine functions of the
    point), so along a piece it is at most its larger end.  :func:`line_depth` returns ``f`` at some ``t``.

    >>> F = Fraction
    >>> box, hole = BoxZone("b", (("X", F(0), F(10)),)), BoxZone("h", (("X", F(0), F(10)),), forbid=True)
    >>> line_depth_bound(box, (F(8),), (F(14),), ("X",), F(0), F(0), None)
    Fraction(4, 1)
    >>> line_depth_bound(hole, (F(-2),), (F(4),), ("X",), F(0), F(0), None), line_depth(hole, (F(-2),), (F(4),), ("X",), F(0), F(0), None)[0]
    (Fraction(5, 1), Fraction(4, 1))
    """
    ln = _Line(p0, p1, axes, zone, tool_length, tool_axis)
    zaxes = [a for a in zone.axes if a in ln.index]
    ends = [ln.ends(a) for a in zaxes]
    f0 = point_depth(zone, {a: e[0] for a, e in zip(zaxes, ends)}, margin)
    f1 = point_depth(zone, {a: e[1] for a, e in zip(zaxes, ends)}, margin)
    if LINE_DEPTH_BOUND.of(zone)(zone):
        return max(f0, f1)
    length = max((abs(b - a) for a, b in ends), default=F0)
    return (f0 + f1 + length) / 2


#: Is the zone's :func:`point_depth` convex in the point (then along a piece it is at most its larger end)?  An
#: allowed box's is; fallback: no (the 1-Lipschitz bound of :func:`line_depth_bound`).
LINE_DEPTH_BOUND: KindTable[Callable[[Any], bool]] = KindTable("prover.exact.line_depth_convex",
                                                               fallback=lambda z: False)
LINE_DEPTH_BOUND.set(BoxZone, lambda z: not z.forbid)
LINE_DEPTH_BOUND.set(SteppedZone, lambda z: False)  # a distance to a union of rectangles: not convex
LINE_DEPTH_BOUND.set(PolygonZone, lambda z: False)


def _breakpoints(lines: Sequence[tuple[Fraction, Fraction]], max_candidates: int) -> tuple[set[Fraction], bool]:
    """The ``t`` in [0, 1] where one of ``lines`` (``f(t) = f0 + t (f1 - f0)``, each with its negation) is zero or
    two of them are equal, with 0 and 1; and whether the pairs were taken (at most ``max_candidates`` pairs: else
    only the zeros, and ``False``).

    ``t`` is the same when every line is scaled by one factor, so each is taken as integers over the common
    denominator and a candidate becomes a ``Fraction`` once, when it lies in (0, 1): the pairwise crossings in
    ``Fraction`` arithmetic cost a violating piece some 4 ms (issue 36: a 229-line unsafe program took 29 s,
    nearly all of it here).  Each line is taken once up to its sign (a line and its negation cross only at its
    zero), and a pair gives both of its crossings, ``f = g`` and ``f = -g``: the same set as every pair of the
    signed list (``tests/prover/test_line_depth_breakpoints.py`` holds it to that).

    >>> sorted(_breakpoints([(Fraction(-1), Fraction(1)), (Fraction(1, 2), Fraction(1, 2))], 100)[0])
    [Fraction(0, 1), Fraction(1, 4), Fraction(1, 2), Fraction(3, 4), Fraction(1, 1)]
    """
    exact = len(lines) ** 2 <= max_candidates
    scale = 1
    for f0, f1 in lines:
        scale = math.lcm(scale, f0.denominator, f1.denominator)
    rows = set()  # (a, s): f(t) * scale = a + s t, its sign chosen so that s > 0, or a >= 0 where s = 0
    for f0, f1 in lines:
        a = f0.numerator * (scale // f0.denominator)
        s = f1.numerator * (scale // f1.denominator) - a
        rows.add((-a, -s) if s < 0 or (s == 0 and a < 0) else (a, s))
    found = {(-a, s) for a, s in rows if s and 0 < -a < s}  # zeros: a + s t = 0
    if exact:
        ordered = list(rows)
        for i, (a, s) in enumerate(ordered):
            for b, u in ordered[i + 1:]:
                for num, den in ((b - a, s - u), (-b - a, s + u)):  # a + s t = b + u t, and = -(b + u t)
                    if den < 0:
                        num, den = -num, -den
                    if 0 < num < den:
                        found.add((num, den))
    cands = {F0, F1}
    cands.update(Fraction(num, den) for num, den in found)
    return cands, exact


#: Is the depth along a line piecewise linear with breakpoints at the zone constants (then
#: :func:`line_depth` is exact)?  Not for a polygon's slanted edges.  Fallback: no (a lower bound).
LINE_DEPTH_EXACT: KindTable[bool] = KindTable("prover.exact.line_depth_exact", fallback=False)
LINE_DEPTH_EXACT.set(BoxZone, True)
LINE_DEPTH_EXACT.set(SteppedZone, True)
LINE_DEPTH_EXACT.set(PolygonZone, False)


# --------------------------------------------------------------------------- witnesses


def _seen(allowed: AllowedSet, zone: Zone, p: dict[str, Fraction], tool_length: Fraction) -> Mapping[str, Fraction]:
    return allowed.seen_by(zone, p, tool_length)


def outside_point(
    allowed: AllowedSet, zone: Zone, p: dict[str, Fraction], margin: Fraction, tool_length: Fraction
) -> dict[str, Fraction] | None:
    """A point of the closed margin box around ``p`` that violates ``zone`` with margin 0.

    Candidates per zone axis are the box ends, the zone constants inside the
    box and the midpoints between consecutive ones: for boxes and stepped
    tables that hits every cell on which the zone's predicate is constant.
    A polygon's slanted edges can pass between those candidates (a thin
    blade, a slit); then the plane point is one of the open box strictly
    inside or outside the polygon (:func:`nczones.prover.polygon.open_box_point`).
    """
    if margin == 0:
        return dict(p) if zone in allowed.violated_zones(p, tool_length) else None
    shift = {}
    if zone.point is ZonePoint.TIP and tool_length and allowed.tool_axis in p:
        shift[allowed.tool_axis] = tool_length
    axes = [a for a in zone.axes if a in p]
    choices = []
    for a in axes:
        seen = p[a] - shift.get(a, F0)
        lo, hi = seen - margin, seen + margin
        vals = sorted({lo, hi, seen} | {c for c in zone_constants(zone, a) if lo < c < hi})
        mids = [(x + y) / 2 for x, y in zip(vals, vals[1:])]
        choices.append([v + shift.get(a, F0) for v in sorted(set(vals) | set(mids))])
    for combo in itertools.product(*choices):
        q = dict(p)
        q.update(zip(axes, combo))
        if zone in allowed.violated_zones(q, tool_length):
            return q
    return OUTSIDE_POINT_MORE(zone, allowed, p, margin, tool_length, shift, axes, choices)


#: Where the grid of zone constants can miss a violating point of the margin box: a kind's own search
#: (``None``: none found).  Fallback: no further search (no witness point; the caller says so).
OUTSIDE_POINT_MORE: KindTable[Callable[..., dict[str, Fraction] | None]] = KindTable(
    "prover.exact.outside_point_more", fallback=lambda zone, *args: None)
OUTSIDE_POINT_MORE.set(BoxZone, lambda zone, *args: None)  # the grid hits every cell of a box
OUTSIDE_POINT_MORE.set(SteppedZone, lambda zone, *args: None)  # and of a stepped table


@OUTSIDE_POINT_MORE.register(PolygonZone)
def _polygon_outside_point(zone: PolygonZone, allowed: AllowedSet, p: dict[str, Fraction], margin: Fraction,
                           tool_length: Fraction, shift: dict[str, Fraction], axes: list[str],
                           choices: list[list[Fraction]]) -> dict[str, Fraction] | None:
    if all(a in p for a in zone.plane):
        # the grid of vertex coordinates can miss a thin polygon (or a thin gap): a point of the open
        # margin box strictly inside it (forbid) or outside it (allow), found exactly, with the limit
        # axes' candidates
        from .polygon import open_box_point

        (x, y), s = zone.plane, shift
        plane = open_box_point(zone, (p[x] - s.get(x, F0) - margin, p[y] - s.get(y, F0) - margin),
                               (p[x] - s.get(x, F0) + margin, p[y] - s.get(y, F0) + margin), zone.forbid)
        if plane is not None:
            rest = [(a, c) for a, c in zip(axes, choices) if a not in zone.plane]
            for combo in itertools.product(*(c for _, c in rest)):
                q = dict(p)
                q.update({x: plane[0] + s.get(x, F0), y: plane[1] + s.get(y, F0)})
                q.update(zip((a for a, _ in rest), combo))
                if zone in allowed.violated_zones(q, tool_length):
                    return q
    return None


def box_certainly_violates(
    allowed: AllowedSet, zone: Zone, lo: dict[str, Fraction], hi: dict[str, Fraction],
    margin: Fraction, tool_length: Fraction,
) -> bool:
    """Does every point of the rational box ``[lo, hi]`` violate ``zone`` (with margin)?

    Sound for box and stepped zones: their predicate (with margin) is
    constant on the open cells cut by the zone constants shifted by
    ``+-margin``; if no such value lies in ``[lo_a, hi_a]`` on any zone axis
    where the box has width (an axis of one value, even a shifted constant,
    is the centre's own), one test at the box centre decides the whole box.  Polygon zones: True
    only when the box grown by the margin meets no edge, or the box is one point in the polygon's plane,
    and its centre violates (the predicate is then constant over the box).
    """
    shift = tool_length if (zone.point is ZonePoint.TIP and tool_length) else F0
    centre = {a: (lo[a] + hi[a]) / 2 for a in lo}
    cells = CERTAIN_CELLS(zone, allowed, lo, hi, margin, shift)
    if isinstance(cells, bool):
        return cells
    for a in cells:
        if a not in lo or lo[a] == hi[a]:  # one value on this axis: the centre's test covers it
            continue
        s = shift if a == allowed.tool_axis else F0
        for c in zone_constants(zone, a):
            for m in (-margin, margin):
                if lo[a] - s <= c + m <= hi[a] - s:
                    return False
    return zone in allowed.violated_zones(centre, tool_length, margin)


#: :func:`box_certainly_violates` per zone kind, first step: True/False when the kind decides the box at once,
#: else the axes on which the zone constants (shifted by the margin) must stay out of the box for the centre's
#: test to decide it.  Fallback: False (not certified: the caller goes on without the certificate).
CERTAIN_CELLS: KindTable[Callable[..., bool | list[str]]] = KindTable(
    "prover.exact.certain_cells", fallback=lambda zone, *args: False)


@CERTAIN_CELLS.register(BoxZone)
def _box_cells(zone: BoxZone, allowed: AllowedSet, lo: dict[str, Fraction], hi: dict[str, Fraction],
               margin: Fraction, shift: Fraction) -> bool | list[str]:
    if not zone.forbid:
        for a, z_lo, z_hi in zone.limits:  # one axis on which every point's margin box leaves the zone
            if a in lo:
                s = shift if a == allowed.tool_axis else F0
                if (z_lo is not None and hi[a] - s - margin < z_lo) or (z_hi is not None and lo[a] - s + margin > z_hi):
                    return True
    return list(zone.axes)


@CERTAIN_CELLS.register(SteppedZone)
def _stepped_cells(zone: SteppedZone, allowed: AllowedSet, lo: dict[str, Fraction], hi: dict[str, Fraction],
                   margin: Fraction, shift: Fraction) -> bool | list[str]:
    return list(zone.axes)


@CERTAIN_CELLS.register(PolygonZone)
def _polygon_cells(zone: PolygonZone, allowed: AllowedSet, lo: dict[str, Fraction], hi: dict[str, Fraction],
                   margin: Fraction, shift: Fraction) -> bool | list[str]:
    from ..zones.model import segment_meets_open_box  # exact clipping helper

    x, y = zone.plane
    # the box as the zone sees it: a tip zone whose plane holds the tool axis sees it less the tool length
    sx, sy = (shift if a == allowed.tool_axis else F0 for a in (x, y))
    gx = (lo[x] - sx - margin - 1 / Fraction(10**30), hi[x] - sx + margin + 1 / Fraction(10**30))
    gy = (lo[y] - sy - margin - 1 / Fraction(10**30), hi[y] - sy + margin + 1 / Fraction(10**30))
    # a box of one point in the polygon's plane (a helix of a rational circle: only the axis along it is
    # enclosed) sees the polygon part of the predicate at that one point, whatever edges its margin box
    # crosses: the zone is a prism and the margin box a product, so that part is the same for every point
    # of the box, and the centre's test below decides it
    flat = lo[x] == hi[x] and lo[y] == hi[y]
    if not flat and any(segment_meets_open_box(a, b, (gx[0], gy[0]), (gx[1], gy[1])) for a, b in zone.edges()):
        return False
    return [a for a, _, _ in zone.limits]


def box_fits(allowed: AllowedSet, lo: dict, hi: dict, margin: Fraction, tool_length: Fraction,
             zones: Iterable[Zone] | None = None) -> bool:
    """Exact test: every point of the box ``[lo, hi]`` has a fitting margin box (boxes, stepped tables).

    Polygon zones: exact too (:func:`nczones.prover.polygon.box_fits`: no
    edge meets the open box and its centre is inside, or outside).  ``zones``
    restricts the test to those zones (default: all of ``allowed``).
    """
    d = margin
    for z in allowed.zones if zones is None else zones:
        shift = tool_length if (z.point is ZonePoint.TIP and tool_length) else F0

        def rng(a):
            s = shift if a == allowed.tool_axis else F0  # noqa: B023 - called within this iteration
            if s or d:
                return lo[a] - s - d, hi[a] - s + d
            return lo[a], hi[a]  # no shift, no margin: the same values without four Fraction operations

        if not BOX_FITS(z, rng, lo):
            return False
    return True


#: Does the box ``lo`` (its lower corner, by axis) to ``rng(axis) -> (lo, hi)`` (its range as the zone sees
#: it, margin included) fit the zone?  Fallback: not shown (the box is not proved inside, a later tier decides).
Rng = Callable[[str], tuple[Fraction, Fraction]]
BOX_FITS: KindTable[Callable[[Any, Rng, Mapping[str, Fraction]], bool]] = KindTable(
    "prover.exact.box_fits", fallback=lambda z, rng, lo: False)


@BOX_FITS.register(BoxZone)
def _box_box_fits(z: BoxZone, rng: Rng, lo: Mapping[str, Fraction]) -> bool:
    if z.forbid:
        if any(lo_ is not None and lo_ == hi_ for _a, lo_, hi_ in z.limits):
            return True  # no interior: forbids nothing (as line_violation)
        return any(
            (hi_ is not None and rng(a)[0] >= hi_) or (lo_ is not None and rng(a)[1] <= lo_)
            for a, lo_, hi_ in z.limits
        )
    for a, lo_, hi_ in z.limits:
        r0, r1 = rng(a)
        if (lo_ is not None and r0 < lo_) or (hi_ is not None and r1 > hi_):
            return False
    return True


@BOX_FITS.register(SteppedZone)
def _stepped_box_fits(z: SteppedZone, rng: Rng, lo: Mapping[str, Fraction]) -> bool:
    """An allow table: the box lies in it (:meth:`SteppedZone.fits`, exact).  A forbid table: every region the
    box's reference range reaches is flat or has the box's limited range outside its open range
    (:meth:`SteppedZone.rows_clear`: then the box misses the interior).  Both in the table's integers over a
    common denominator, one bisection and a run of a list per query (``tests/prover/test_stepped_box_fits.py``
    holds them to the region-by-region comparisons in rationals they replaced)."""
    r0, r1 = rng(z.reference_axis)
    l0, l1 = rng(z.limited_axis)
    if z.forbid:
        return z.rows_clear(r0, r1, l0, l1)
    return z.fits(r0, r1, l0, l1)


@BOX_FITS.register(PolygonZone)
def _polygon_box_fits(z: PolygonZone, rng: Rng, lo: Mapping[str, Fraction]) -> bool:
    if z.forbid:
        b = z.bounds()
        if any((bh is not None and rng(a)[0] >= bh) or (bl is not None and rng(a)[1] <= bl)
               for a, (bl, bh) in b.items() if a in lo):
            return True
    else:
        for a, lo_, hi_ in z.limits:
            r0, r1 = rng(a)
            if (lo_ is not None and r0 < lo_) or (hi_ is not None and r1 > hi_):
                return False
    from .polygon import box_fits as polygon_box_fits

    (x0, x1), (y0, y1) = rng(z.plane[0]), rng(z.plane[1])
    return polygon_box_fits(z, (x0, y0), (x1, y1))
