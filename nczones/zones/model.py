"""Zones and the allowed set, exactly as DESIGN §3 defines them.

A zone sees a point as a mapping ``axis name -> Fraction``.  Axes a zone does
not name are free.  Boxes and polygons are closed sets; a stepped table is the
union of its half-open rows (a reference value equal to ``upto[i]`` reads row
``i``'s limits, so where the next row is wider the table is not closed).  A
forbid zone forbids only its interior (touching its boundary is allowed; a flat
range such as ``min = max`` has no interior and forbids nothing).  The allowed set is the
intersection of all allow zones minus the union of the forbid zones'
interiors (no allow zone: everywhere allowed).

Margins: ``contains_box(point, d)`` asks whether the closed box of half-width
``d`` around the point fits in the allowed set (inside every allow zone,
meeting no forbid zone's interior).  ``d = 0`` is plain membership.
"""

from __future__ import annotations

import enum
import itertools
import math
from collections.abc import Mapping, Sequence
from fractions import Fraction

from ..exact import max_bound, min_bound
from ..precompiled import dataclass, field  # dataclasses' without importing it (start-up)

__all__ = [
    "ZonePoint",
    "Region",
    "SteppedZone",
    "StepTable",
    "BoxZone",
    "PolygonZone",
    "Zone",
    "ZONE_KINDS",
    "AllowedSet",
    "Point",
    "translated",
    "tip_shifted",
]

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

Point = Mapping[str, Fraction]
_ZERO = Fraction(0)


def _bisect_left(a: Sequence[Any], x: Any) -> int:
    """:func:`bisect.bisect_left`, imported at the first search (a machine without stepped zones makes none, and
    ``_bisect`` is a C extension to load at start-up, boot44); the name is then the function itself."""
    global _bisect_left, _bisect_right
    from bisect import bisect_left, bisect_right

    _bisect_left, _bisect_right = bisect_left, bisect_right
    return bisect_left(a, x)


def _bisect_right(a: Sequence[Any], x: Any) -> int:
    """:func:`bisect.bisect_right`, imported at the first search (as :func:`_bisect_left`)."""
    _bisect_left((), 0)
    return _bisect_right(a, x)


def _floor_times(q: Fraction, den: int) -> int:
    """``floor(q * den)`` exactly, in integers."""
    return q.numerator * den // q.denominator


def _ceil_times(q: Fraction, den: int) -> int:
    """``ceil(q * den)`` exactly, in integers."""
    return -(-q.numerator * den // q.denominator)


class ZonePoint(enum.Enum):
    """Which point a zone constrains: the machine position or the tool tip."""

    MACHINE = "machine"
    TIP = "tip"


def _ge(value: Fraction, bound: Fraction | None) -> bool:
    return bound is None or value >= bound


def _le(value: Fraction, bound: Fraction | None) -> bool:
    return bound is None or value <= bound


def _gt(value: Fraction, bound: Fraction | None) -> bool:
    return bound is None or value > bound


def _lt(value: Fraction, bound: Fraction | None) -> bool:
    return bound is None or value < bound


@dataclass(frozen=True, slots=True)
class Region:
    """One row of a limit-value table: reference values up to ``upto``.

    ``min``/``max`` bound the limited axis in this region; None is unbounded.
    """

    upto: Fraction
    min: Fraction | None = None
    max: Fraction | None = None


#: The setters of a Region's three slots (what its ``__init__`` does, one call each).
_REGION_SETTERS = tuple(Region.__dict__[name].__set__ for name in ("upto", "min", "max"))


def _regions(uptos: list[Fraction], mins: list[Fraction | None], maxs: list[Fraction | None]) -> tuple[Region, ...]:
    """``tuple(map(Region, uptos, mins, maxs))``, a column at a time: the instances made by ``object.__new__`` and
    each slot set by its descriptor over the column, in C (``Region.__init__`` does nothing else: it sets the
    three fields; a Python call a region costs as much as the rest of reading a table, issue 36).
    ``tests/zones/test_step_table.py`` holds the result to ``Region(...)`` and the fields to these three."""
    made = list(map(object.__new__, itertools.repeat(Region, len(uptos))))
    columns: tuple[list[Any], ...] = (uptos, mins, maxs)
    for setter, column in zip(_REGION_SETTERS, columns):
        any(map(setter, made, column))  # each call returns None: any() runs the map to its end
    return tuple(made)


def _present(column: list[int | None]) -> list[int]:
    """The integers of ``column`` (``column`` itself when it holds no None: found in C, no copy)."""
    if None not in column:
        return column  # type: ignore[return-value]  # (no None in it)
    return [v for v in column if v is not None]


def _filled(column: list[int | None], fill: int) -> list[int]:
    """``column`` with each None replaced by ``fill`` (``column`` itself when it holds none)."""
    if None not in column:
        return column  # type: ignore[return-value]  # (no None in it)
    return [fill if v is None else v for v in column]


class StepTable:
    """A stepped table's numbers as integers over one common denominator (made once per zone).

    ``den`` is a common denominator of ``from``, every ``upto``, ``min`` and ``max`` (their least common
    multiple when made from a zone's Fractions, :meth:`of`; the power of ten of a machine file's decimals
    when read from it, :meth:`SteppedZone.from_integers`); ``start``, ``uptos``, ``mins`` and ``maxs`` are those
    values times ``den``, exact integers, ``mins[i]`` / ``maxs[i]`` being ``low`` / ``high`` where region
    ``i`` has no ``min`` / ``max``.  ``low`` is less and ``high`` greater than every finite value of the table,
    so the largest ``min`` of a run of regions is ``low`` only when none of them has one (and likewise the
    smallest ``max``), and a region with one missing bound never reads as flat (``mins[i] == maxs[i]``).

    A rational ``q`` compares with an entry ``k / den`` as ``q * den`` with ``k``: ``q >= k / den`` exactly
    when ``floor(q * den) >= k`` and ``q <= k / den`` exactly when ``ceil(q * den) <= k`` (``k`` an integer),
    so one floor or ceiling per query bound turns every comparison with the table into one of integers.

    A plain class with slots, not a dataclass: it is made only for a machine with a stepped zone (a dataclass
    costs every start-up its creation, boot44).
    """

    __slots__ = ("den", "start", "uptos", "mins", "maxs", "low", "high")

    def __init__(self, den: int, start: int, uptos: list[int], mins: list[int | None], maxs: list[int | None]):
        self.den, self.start, self.uptos = den, start, uptos
        finite = [start, min(uptos), max(uptos)]
        for column in (mins, maxs):
            given = _present(column)
            if given:
                finite += (min(given), max(given))
        self.low, self.high = min(finite) - 1, max(finite) + 1
        self.mins = _filled(mins, self.low)
        self.maxs = _filled(maxs, self.high)

    @classmethod
    def of(cls, zone: SteppedZone) -> StepTable:
        """The table of ``zone``'s Fractions over the least common multiple of their denominators."""
        regions = zone.regions
        ups = [r.upto for r in regions]
        lows = [r.min for r in regions]
        highs = [r.max for r in regions]
        dens = {v.denominator for v in ups}
        dens.update([v.denominator for v in lows if v is not None])
        dens.update([v.denominator for v in highs if v is not None])
        den = math.lcm(zone.start.denominator, *dens)
        return cls(den, zone.start.numerator * (den // zone.start.denominator),
                   [v.numerator * (den // v.denominator) for v in ups],
                   [None if v is None else v.numerator * (den // v.denominator) for v in lows],
                   [None if v is None else v.numerator * (den // v.denominator) for v in highs])


@dataclass(frozen=True, slots=True)
class SteppedZone:
    """A stepped limit-value table.

    Region ``i`` covers reference values ``r`` with ``upto[i-1] < r <= upto[i]``;
    the first region also includes ``start`` (the file's ``from``).  Reference
    values outside ``[start, upto[last]]`` are outside the zone.

    Examples
    --------
    >>> F = Fraction
    >>> z = SteppedZone("wheel", "X", "Y", F(0), (Region(F(500), None, F(300)),
    ...                                          Region(F(800), F(150), F(300))))
    >>> z.contains({"X": F(500), "Y": F(0)}), z.contains({"X": F(501), "Y": F(0)})
    (True, False)
    >>> z.region_sequential(F(650))
    (1, 3)
    """

    name: str
    reference_axis: str
    limited_axis: str
    start: Fraction
    regions: tuple[Region, ...]
    forbid: bool = False
    point: ZonePoint = ZonePoint.MACHINE
    # the table in integers, made at the first query that needs it (not an argument: replace() and
    # translated() make a new zone, which makes its own; not compared, hashed or shown: a function of the rest)
    _steps: StepTable | None = field(default=None, init=False, repr=False, compare=False)
    kind = "stepped"  # a class attribute, not a field (unannotated: no typing.ClassVar to import at start-up)

    @property
    def axes(self) -> tuple[str, ...]:
        return (self.reference_axis, self.limited_axis)

    def steps(self) -> StepTable:
        """The table in integers over a common denominator (:class:`StepTable`), made once."""
        got = self._steps
        if got is None:
            got = StepTable.of(self)
            object.__setattr__(self, "_steps", got)  # a cache of a frozen instance (the lexer's words do so)
        return got

    @classmethod
    def from_integers(cls, name: str, reference_axis: str, limited_axis: str, den: int, start: int,
                      uptos: list[int], mins: list[int | None], maxs: list[int | None], forbid: bool = False,
                      point: ZonePoint = ZonePoint.MACHINE) -> SteppedZone:
        """The table whose ``from`` is ``start / den``, region ``i`` reaching ``uptos[i] / den`` with limits
        ``mins[i] / den`` and ``maxs[i] / den`` (None: none), its :class:`StepTable` made of the same integers.

        How a machine file's table is read (issue 36): the regions' Fractions are made from these integers
        here, so the table in integers is exact by construction, with no second pass over the Fractions; a
        limit written many times is one Fraction.

        >>> z = SteppedZone.from_integers("t", "X", "Y", 10, 0, [15, 30], [None, -5], [20, 20])
        >>> z == SteppedZone("t", "X", "Y", Fraction(0), (Region(Fraction(3, 2), None, Fraction(2)),
        ...                                             Region(Fraction(3), Fraction(-1, 2), Fraction(2))))
        True
        """
        limits: dict[int | None, Fraction | None] = {k: Fraction(k, den) for k in {*mins, *maxs} if k is not None}
        regions = _regions(list(map(Fraction, uptos, itertools.repeat(den))), list(map(limits.get, mins)),
                           list(map(limits.get, maxs)))
        zone = cls(name, reference_axis, limited_axis, Fraction(start, den), regions, forbid, point)
        object.__setattr__(zone, "_steps", StepTable(den, start, uptos, mins, maxs))
        return zone

    def reached(self, lo: Fraction, hi: Fraction) -> range:
        """Indices of the regions whose closed reference range ``[lower, upto]`` meets ``[lo, hi]``.

        The first region with ``upto >= lo`` up to the first with ``upto > hi`` (or the last region): the
        bisections of the table's integers, ``upto >= lo`` being ``upto * den >= ceil(lo * den)`` and
        ``upto > hi`` being ``upto * den > floor(hi * den)``.
        """
        t = self.steps()
        first = _bisect_left(t.uptos, _ceil_times(lo, t.den))
        last = _bisect_right(t.uptos, _floor_times(hi, t.den))
        return range(first, min(last + 1, len(t.uptos)))

    def fits(self, r0: Fraction, r1: Fraction, l0: Fraction, l1: Fraction) -> bool:
        """Does the closed box ``[r0, r1] x [l0, l1]`` (reference x limited axis, ``r0 <= r1``) lie in the zone?

        Exact.  It does when ``[r0, r1]`` lies in ``[from, upto[last]]`` and every region whose reference range
        the box meets (``(upto[i-1], upto[i]]``, the first one closed) holds ``[l0, l1]``: the regions
        ``first..e``, ``first`` the first with ``upto >= r0`` and ``e`` the first with ``upto >= r1`` (a region
        after ``e`` starts at ``upto[e] >= r1`` or later, open, so the box misses it), whose largest ``min``
        must be at most ``l0`` and smallest ``max`` at least ``l1``.  In the integers of :meth:`steps` (see
        :class:`StepTable`): two bisections and the largest and smallest entry of two runs of a list, so a box
        over thousands of regions costs no rational arithmetic.  An inverted ``r0 > r1`` is not shown to fit.
        """
        t = self.steps()
        den, uptos = t.den, t.uptos
        c1 = _ceil_times(r1, den)
        if r0 > r1 or _floor_times(r0, den) < t.start or c1 > uptos[-1]:
            return False
        first = _bisect_left(uptos, _ceil_times(r0, den))
        end = _bisect_left(uptos, c1) + 1
        highest = max(t.mins[first:end])
        if highest != t.low and _floor_times(l0, den) < highest:
            return False
        lowest = min(t.maxs[first:end])
        return lowest == t.high or _ceil_times(l1, den) <= lowest

    def rows_clear(self, r0: Fraction, r1: Fraction, l0: Fraction, l1: Fraction) -> bool:
        """Is ``[l0, l1]`` outside the open limited range of every region :meth:`reached` by ``[r0, r1]``?

        A flat region (``min == max``) has no interior and counts as clear.  Then the box ``[r0, r1] x [l0,
        l1]`` meets no region's interior, nor the interior at a boundary (which lies in both neighbours' open
        ranges): it misses the zone's interior.  (It may miss it also when this says False, at a boundary the
        box only touches.)  Exact in the integers of :meth:`steps`.
        """
        t = self.steps()
        fl0, cl1 = _floor_times(l0, t.den), _ceil_times(l1, t.den)
        mins, maxs, low, high = t.mins, t.maxs, t.low, t.high
        for i in self.reached(r0, r1):
            lo, hi = mins[i], maxs[i]
            if lo == hi or (hi != high and fl0 >= hi) or (lo != low and cl1 <= lo):
                continue
            return False
        return True

    @property
    def uptos(self) -> tuple[Fraction, ...]:
        return tuple(r.upto for r in self.regions)

    def region_lower(self, i: int) -> Fraction:
        """Lower end of region i on the reference axis (open except for i = 0)."""
        return self.start if i == 0 else self.regions[i - 1].upto

    def region_sequential(self, r: Fraction) -> tuple[int | None, int]:
        """Find the region of reference value ``r`` the way the controller does.

        Compare ``r`` with ``from`` and then with each boundary in turn until it
        is not greater.  Returns ``(index or None, comparisons made)``; at most
        ``len(regions) + 1`` comparisons.
        """
        comparisons = 1
        if r < self.start:
            return None, comparisons
        for i, region in enumerate(self.regions):
            comparisons += 1
            if r <= region.upto:
                return i, comparisons
        return None, comparisons

    def region_bisect(self, r: Fraction) -> int | None:
        """The same lookup by binary search (O(log n)), in the integers of :meth:`steps`."""
        if r < self.start or r > self.regions[-1].upto:
            return None
        t = self.steps()
        return _bisect_left(t.uptos, _ceil_times(r, t.den))

    def contains(self, p: Point) -> bool:
        """Closed-set membership."""
        i, _ = self.region_sequential(p[self.reference_axis])
        if i is None:
            return False
        reg = self.regions[i]
        return _ge(p[self.limited_axis], reg.min) and _le(p[self.limited_axis], reg.max)

    def interior_contains(self, p: Point) -> bool:
        """Membership in the topological interior."""
        return self.box_meets_interior(p, _ZERO)

    def box_inside(self, p: Point, d: Fraction) -> bool:
        """Does the closed box of half-width ``d`` (``d >= 0``) around ``p`` lie in the zone?  (:meth:`fits`.)"""
        r, lim = p[self.reference_axis], p[self.limited_axis]
        if d:
            return self.fits(r - d, r + d, lim - d, lim + d)
        return self.fits(r, r, lim, lim)

    def box_meets_interior(self, p: Point, d: Fraction) -> bool:
        """Does the closed box of half-width ``d`` meet the zone's interior?"""
        r, lim = p[self.reference_axis], p[self.limited_axis]
        for i, reg in enumerate(self.regions):
            a, b = self.region_lower(i), reg.upto
            if (
                r - d < b
                and r + d > a
                and _open_nonempty(reg.min, reg.max)
                and _lt(lim - d, reg.max)
                and _gt(lim + d, reg.min)
            ):
                return True
        for reg, nxt in zip(self.regions, self.regions[1:]):
            b = reg.upto
            if r - d <= b <= r + d:
                lo = max_bound(reg.min, nxt.min)
                hi = min_bound(reg.max, nxt.max)
                if _open_nonempty(lo, hi) and _lt(lim - d, hi) and _gt(lim + d, lo):
                    return True
        return False

    def bounds(self) -> dict[str, tuple[Fraction | None, Fraction | None]]:
        mins = [r.min for r in self.regions]
        maxs = [r.max for r in self.regions]
        lo = None if any(m is None for m in mins) else min(m for m in mins if m is not None)
        hi = None if any(m is None for m in maxs) else max(m for m in maxs if m is not None)
        return {self.reference_axis: (self.start, self.regions[-1].upto), self.limited_axis: (lo, hi)}


Limits = tuple[tuple[str, Fraction | None, Fraction | None], ...]


def _limits_box_inside(limits: Limits, p: Point, d: Fraction) -> bool:
    return all(_ge(p[a] - d, lo) and _le(p[a] + d, hi) for a, lo, hi in limits)


def _open_nonempty(lo: Fraction | None, hi: Fraction | None) -> bool:
    """Is the open interval (lo, hi) non-empty?  (A flat range has no interior.)"""
    return lo is None or hi is None or lo < hi


def _limits_box_meets_interior(limits: Limits, p: Point, d: Fraction) -> bool:
    return all(
        _open_nonempty(lo, hi) and _lt(p[a] - d, hi) and _gt(p[a] + d, lo) for a, lo, hi in limits
    )


@dataclass(frozen=True, slots=True)
class BoxZone:
    """Per-axis ranges ``(axis, min, max)``; None is unbounded.

    >>> F = Fraction
    >>> vise = BoxZone("vise", (("X", F(0), F(100)), ("Z", None, F(50))), forbid=True)
    >>> vise.interior_contains({"X": F(0), "Z": F(10)}), vise.interior_contains({"X": F(1), "Z": F(10)})
    (False, True)
    """

    name: str
    limits: Limits
    forbid: bool = False
    point: ZonePoint = ZonePoint.MACHINE
    kind = "box"  # a class attribute, not a field (unannotated: no typing.ClassVar to import at start-up)

    @property
    def axes(self) -> tuple[str, ...]:
        return tuple(a for a, _, _ in self.limits)

    def contains(self, p: Point) -> bool:
        return _limits_box_inside(self.limits, p, _ZERO)

    def interior_contains(self, p: Point) -> bool:
        return _limits_box_meets_interior(self.limits, p, _ZERO)

    def box_inside(self, p: Point, d: Fraction) -> bool:
        return _limits_box_inside(self.limits, p, d)

    def box_meets_interior(self, p: Point, d: Fraction) -> bool:
        return _limits_box_meets_interior(self.limits, p, d)

    def bounds(self) -> dict[str, tuple[Fraction | None, Fraction | None]]:
        return {a: (lo, hi) for a, lo, hi in self.limits}


Vertex = tuple[Fraction, Fraction]


def _cross(o: Vertex, a: Vertex, b: Vertex) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _on_segment(q: Vertex, a: Vertex, b: Vertex) -> bool:
    return (
        _cross(a, b, q) == 0
        and min(a[0], b[0]) <= q[0] <= max(a[0], b[0])
        and min(a[1], b[1]) <= q[1] <= max(a[1], b[1])
    )


def segment_meets_open_box(a: Vertex, b: Vertex, lo: Vertex, hi: Vertex) -> bool:
    """Does segment [a, b] meet the open box (lo, hi)?  Exact clipping in t."""
    t_lo, t_hi = Fraction(0), Fraction(1)
    lo_open = hi_open = False
    for k in (0, 1):
        delta = b[k] - a[k]
        if delta == 0:
            if not lo[k] < a[k] < hi[k]:
                return False
            continue
        t1 = (lo[k] - a[k]) / delta
        t2 = (hi[k] - a[k]) / delta
        if t1 > t2:
            t1, t2 = t2, t1
        if t1 > t_lo or (t1 == t_lo):
            if t1 > t_lo:
                t_lo, lo_open = t1, True
            else:
                lo_open = True
        if t2 < t_hi or (t2 == t_hi):
            if t2 < t_hi:
                t_hi, hi_open = t2, True
            else:
                hi_open = True
    if lo_open or hi_open:
        return t_lo < t_hi
    return t_lo <= t_hi


@dataclass(frozen=True, slots=True)
class PolygonZone:
    """A simple polygon in the plane of two axes, boundary included.

    ``limits`` optionally bounds other axes (a prism).

    >>> F = Fraction
    >>> tri = PolygonZone("t", ("X", "Z"), ((F(0), F(0)), (F(10), F(0)), (F(0), F(10))))
    >>> tri.contains({"X": F(5), "Z": F(5)}), tri.contains({"X": F(6), "Z": F(5)})
    (True, False)
    """

    name: str
    plane: tuple[str, str]
    vertices: tuple[Vertex, ...]
    limits: Limits = ()
    forbid: bool = False
    point: ZonePoint = ZonePoint.MACHINE
    kind = "polygon"  # a class attribute, not a field (unannotated: no typing.ClassVar to import at start-up)

    @property
    def axes(self) -> tuple[str, ...]:
        return self.plane + tuple(a for a, _, _ in self.limits)

    def edges(self) -> tuple[tuple[Vertex, Vertex], ...]:
        v = self.vertices
        return tuple((v[i], v[(i + 1) % len(v)]) for i in range(len(v)))

    def _locate(self, q: Vertex) -> int:
        """+1 strictly inside, 0 on the boundary, -1 outside."""
        inside = False
        qx, qy = q
        for a, b in self.edges():
            if (a[1] < qy and b[1] < qy) or (a[1] > qy and b[1] > qy):
                continue  # neither on the edge nor crossing the ray: the edge misses the line y = qy
            if _on_segment(q, a, b):
                return 0
            if (a[1] > q[1]) != (b[1] > q[1]):
                x_cross = a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                if q[0] < x_cross:
                    inside = not inside
        return 1 if inside else -1

    def _plane_point(self, p: Point) -> Vertex:
        return (p[self.plane[0]], p[self.plane[1]])

    def contains(self, p: Point) -> bool:
        return self._locate(self._plane_point(p)) >= 0 and _limits_box_inside(self.limits, p, _ZERO)

    def interior_contains(self, p: Point) -> bool:
        return self._locate(self._plane_point(p)) > 0 and _limits_box_meets_interior(
            self.limits, p, _ZERO
        )

    def box_inside(self, p: Point, d: Fraction) -> bool:
        q = self._plane_point(p)
        if not _limits_box_inside(self.limits, p, d):
            return False
        if d == 0:
            return self._locate(q) >= 0
        lo, hi = (q[0] - d, q[1] - d), (q[0] + d, q[1] + d)
        if any(segment_meets_open_box(a, b, lo, hi) for a, b in self.edges()):
            return False
        return self._locate(q) >= 0

    def box_meets_interior(self, p: Point, d: Fraction) -> bool:
        q = self._plane_point(p)
        if not _limits_box_meets_interior(self.limits, p, d):
            return False
        if d == 0:
            return self._locate(q) > 0
        lo, hi = (q[0] - d, q[1] - d), (q[0] + d, q[1] + d)
        if any(segment_meets_open_box(a, b, lo, hi) for a, b in self.edges()):
            return True
        return self._locate(q) > 0

    def bounds(self) -> dict[str, tuple[Fraction | None, Fraction | None]]:
        xs = [v[0] for v in self.vertices]
        ys = [v[1] for v in self.vertices]
        out: dict[str, tuple[Fraction | None, Fraction | None]] = {
            self.plane[0]: (min(xs), max(xs)),
            self.plane[1]: (min(ys), max(ys)),
        }
        out.update({a: (lo, hi) for a, lo, hi in self.limits})
        return out


Zone = SteppedZone | BoxZone | PolygonZone

#: Every zone kind (the per-kind tables of nczones/zones/kinds.py are checked against this list).
ZONE_KINDS: tuple[type, ...] = (SteppedZone, BoxZone, PolygonZone)


@dataclass(frozen=True, slots=True)
class AllowedSet:
    """All zones of a machine, and exact membership of machine positions.

    ``tool_axis`` is the axis the tool length acts on; ``point = "tip"`` zones
    see that axis' machine coordinate minus the active tool length.

    Examples
    --------
    >>> F = Fraction
    >>> s = AllowedSet((BoxZone("travel", (("X", F(0), F(10)),)),
    ...                 BoxZone("clamp", (("X", F(4), F(6)),), forbid=True)))
    >>> [s.contains({"X": F(x)}) for x in (0, 4, 5, 6, 11)]
    [True, True, False, True, False]
    """

    zones: tuple[Zone, ...]
    tool_axis: str | None = "Z"

    def seen_by(self, zone: Zone, p: Point, tool_length: Fraction) -> Point:
        """The point as ``zone`` sees it (tool tip for ``point = "tip"``)."""
        if zone.point is ZonePoint.TIP and tool_length and self.tool_axis is not None and self.tool_axis in p:
            q = dict(p)
            q[self.tool_axis] = q[self.tool_axis] - tool_length
            return q
        return p

    def violated_zones(
        self, p: Point, tool_length: Fraction = _ZERO, margin: Fraction = _ZERO
    ) -> tuple[Zone, ...]:
        """The zones that the box of half-width ``margin`` around ``p`` violates."""
        out = []
        for z in self.zones:
            q = self.seen_by(z, p, tool_length)
            bad = z.box_meets_interior(q, margin) if z.forbid else not z.box_inside(q, margin)
            if bad:
                out.append(z)
        return tuple(out)

    def contains(self, p: Point, tool_length: Fraction = _ZERO) -> bool:
        """Is the point in the allowed set?"""
        return not self.violated_zones(p, tool_length)

    def contains_box(self, p: Point, margin: Fraction, tool_length: Fraction = _ZERO) -> bool:
        """Does the closed box of half-width ``margin`` around ``p`` fit?"""
        return not self.violated_zones(p, tool_length, margin)

    def allow_zones(self) -> tuple[Zone, ...]:
        return tuple(z for z in self.zones if not z.forbid)

    def forbid_zones(self) -> tuple[Zone, ...]:
        return tuple(z for z in self.zones if z.forbid)

    def bounding_box(self) -> dict[str, tuple[Fraction | None, Fraction | None]]:
        """Per-axis bounds of the allowed set implied by the machine-point allow zones."""
        out: dict[str, tuple[Fraction | None, Fraction | None]] = {}
        for z in self.allow_zones():
            if z.point is not ZonePoint.MACHINE:
                continue
            for axis, (lo, hi) in z.bounds().items():
                old_lo, old_hi = out.get(axis, (None, None))
                out[axis] = (max_bound(old_lo, lo), min_bound(old_hi, hi))
        return out


def _shift(v: Fraction | None, d: Fraction) -> Fraction | None:
    return None if v is None else v + d


def translated(zone: Zone, shift: Mapping[str, Fraction]) -> Zone:
    """The zone moved by ``shift`` (axis -> distance): a point ``p`` is in the result exactly when
    ``p - shift`` is in ``zone``.

    >>> F = Fraction
    >>> z = translated(BoxZone("b", (("X", F(0), F(10)), ("Z", None, F(5)))), {"X": F(2)})
    >>> z.limits
    (('X', Fraction(2, 1), Fraction(12, 1)), ('Z', None, Fraction(5, 1)))
    """
    from dataclasses import replace

    if not any(shift.get(a) for a in zone.axes):
        return zone
    if isinstance(zone, BoxZone):
        return replace(zone, limits=tuple((a, _shift(lo, shift.get(a, _ZERO)), _shift(hi, shift.get(a, _ZERO)))
                                          for a, lo, hi in zone.limits))
    if isinstance(zone, PolygonZone):
        da, db = shift.get(zone.plane[0], _ZERO), shift.get(zone.plane[1], _ZERO)
        return replace(zone, vertices=tuple((u + da, v + db) for u, v in zone.vertices),
                       limits=tuple((a, _shift(lo, shift.get(a, _ZERO)), _shift(hi, shift.get(a, _ZERO)))
                                    for a, lo, hi in zone.limits))
    dr, dl = shift.get(zone.reference_axis, _ZERO), shift.get(zone.limited_axis, _ZERO)
    return replace(zone, start=zone.start + dr,
                   regions=tuple(Region(r.upto + dr, _shift(r.min, dl), _shift(r.max, dl)) for r in zone.regions))


def tip_shifted(allowed: AllowedSet, shift: Mapping[str, Fraction]) -> AllowedSet:
    """The allowed set in which the tip zones are moved by ``shift``: the zones a machine position meets when the
    tool tip is ``shift`` away from it on those axes (besides the tool length on the tool axis)."""
    return AllowedSet(tuple(translated(z, shift) if z.point is ZonePoint.TIP else z for z in allowed.zones),
                      allowed.tool_axis)
