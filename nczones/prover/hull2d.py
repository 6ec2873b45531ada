"""The convex hull of a Fanuc cutting-mode run on a two-axis machine (a lathe's X and Z), proved against zones.

A Fanuc control in cutting mode keeps the moved path inside the convex hull of the commanded path since the last
exact stop (specs/path-modes.md §3).  nczones proves the box of that hull first; where the box does not fit,
:func:`hull_fits` proves the hull itself, exactly (rationals), against box and polygon zones; any other zone
kind, or a hull without interior, is not proved here (the caller's ``unknown`` stands).

>>> from fractions import Fraction as Q
>>> from nczones.zones import AllowedSet, BoxZone
>>> pts = [(Q(0), Q(0)), (Q(10), Q(0)), (Q(10), Q(10))]          # the triangle below the diagonal
>>> clamp = BoxZone("clamp", (("X", Q(1), Q(4)), ("Z", Q(6), Q(9))), forbid=True)  # above it
>>> hull_fits(convex_hull(pts), ("X", "Z"), AllowedSet((clamp,), None), Q(0), {})
True
>>> hull_fits(convex_hull(pts), ("X", "Z"), AllowedSet((clamp,), None), Q(3), {})   # grown by 3: it meets
False
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from fractions import Fraction

from ..zones import AllowedSet, BoxZone, PolygonZone, SteppedZone, ZonePoint
from ..zones.kinds import KindTable

__all__ = ["convex_hull", "hull_fits"]

Pt = tuple[Fraction, Fraction]


def _cross(o: Pt, a: Pt, b: Pt) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def convex_hull(points: Iterable[Pt]) -> list[Pt]:
    """The vertices of the convex hull, counterclockwise, collinear points dropped (monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts
    lower: list[Pt] = []
    for p in pts:
        while len(lower) >= 2 and _cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper: list[Pt] = []
    for p in reversed(pts):
        while len(upper) >= 2 and _cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _grown(hull: Sequence[Pt], d: Fraction) -> list[Pt]:
    """The hull of the hull grown by the square of half-width ``d`` (a margin box around every point)."""
    if not d:
        return list(hull)
    return convex_hull((x + sx * d, y + sy * d) for x, y in hull for sx in (-1, 1) for sy in (-1, 1))


def _segment_meets_open_hull(hull: Sequence[Pt], s: Pt, e: Pt) -> bool:
    """Does the segment ``s``-``e`` meet the interior of the convex polygon ``hull`` (counterclockwise)?"""
    lo: Fraction | None = None
    hi: Fraction | None = None
    n = len(hull)
    for i in range(n):
        v, w = hull[i], hull[(i + 1) % n]
        a = _cross(v, w, s)  # inside: cross(v, w, p(t)) > 0, p(t) = s + t (e - s): a + b t
        b = _cross(v, w, e) - a
        if b == 0:
            if a <= 0:
                return False
        elif b > 0:
            t = -a / b
            lo = t if lo is None else max(lo, t)
        else:
            t = -a / b
            hi = t if hi is None else min(hi, t)
    lo_ = Fraction(-1) if lo is None else lo
    hi_ = Fraction(2) if hi is None else hi
    return lo_ < 1 and hi_ > 0 and lo_ < hi_


def _not_shown(z: object, hull: Sequence[Pt], axes: tuple[str, str]) -> bool | None:
    return None


#: Does the convex polygon (counterclockwise, on the two axes) fit the zone?  Fallback: not shown (None); a
#: stepped table is not tried (its box test stands).
HULL_FITS: KindTable = KindTable("prover.hull2d.hull_fits", fallback=_not_shown)
HULL_FITS.set(SteppedZone, _not_shown)


@HULL_FITS.register(BoxZone)
def _box_fits(z: BoxZone, hull: Sequence[Pt], axes: tuple[str, str]) -> bool | None:
    lim = {a: (lo, hi) for a, lo, hi in z.limits}
    if any(a not in axes for a in lim):
        return None  # a limit on another axis: not this module's
    if z.forbid:
        if any(lo is not None and lo == hi for lo, hi in lim.values()):
            return True  # no interior
        # the closed hull misses the open box iff an axis separates them: the box's two or a hull edge's normal
        for k, a in enumerate(axes):
            lo, hi = lim.get(a, (None, None))
            if (hi is not None and min(p[k] for p in hull) >= hi) or (lo is not None and max(p[k] for p in hull) <= lo):
                return True
        if any(v is None for a in axes for v in lim.get(a, (None, None))):
            return None  # an unbounded box: only the axes above are tried
        corners = [(x, y) for x in lim[axes[0]] if x is not None for y in lim[axes[1]] if y is not None]
        n = len(hull)
        return any(all(_cross(hull[i], hull[(i + 1) % n], c) <= 0 for c in corners) for i in range(n))
    return all((lo is None or p[k] >= lo) and (hi is None or p[k] <= hi)
               for p in hull for k, a in enumerate(axes) for lo, hi in [lim.get(a, (None, None))])


@HULL_FITS.register(PolygonZone)
def _polygon_fits(z: PolygonZone, hull: Sequence[Pt], axes: tuple[str, str]) -> bool | None:
    from .polygon import locate

    if z.limits or set(z.plane) != set(axes):
        return None
    swap = z.plane != axes
    h = [(p[1], p[0]) for p in hull] if swap else list(hull)
    if swap:
        h = convex_hull(h)  # counterclockwise again in the zone's plane
    v = z.vertices
    for i in range(len(v)):
        if _segment_meets_open_hull(h, tuple(v[i]), tuple(v[(i + 1) % len(v)])):  # type: ignore[arg-type]
            return False
    # no edge meets the open hull: it lies wholly inside the polygon's interior or wholly outside
    n = len(h)
    centre = (sum((p[0] for p in h), Fraction(0)) / n, sum((p[1] for p in h), Fraction(0)) / n)
    where = locate(z, centre)
    return where < 0 if z.forbid else where > 0


def hull_fits(hull: Sequence[Pt], axes: tuple[str, str], allowed: AllowedSet, margin: Fraction,
              tool_shift: Mapping[str, Fraction]) -> bool:
    """Does every point of the convex polygon ``hull`` (machine positions on ``axes``), grown by ``margin``, fit
    every zone of ``allowed``?  Tip zones see the points less ``tool_shift`` (the tool length on the tool
    axis).  False when not shown (a zone kind other than boxes and polygons, a hull without interior)."""
    if len(hull) < 3:
        return False
    grown = _grown(hull, margin)
    shifted = None
    for z in allowed.zones:
        pts = grown
        if z.point is ZonePoint.TIP and any(tool_shift.values()):
            if shifted is None:
                shifted = [tuple(p[k] - tool_shift.get(a, Fraction(0)) for k, a in enumerate(axes)) for p in grown]
            pts = shifted  # type: ignore[assignment]
        if not HULL_FITS(z, pts, axes):
            return False
    return True
