"""Polygon zones without the solver: exact decisions and a vectorized grid screen.

Two structures per polygon, each built once and kept (keyed by the zone):

* :class:`EdgeBoxes` — the edges in integers (the vertices times their
  common denominator), filed in horizontal bands: the edges whose boxes meet
  a query box are found exactly without numpy, and a point is located in
  integer arithmetic over the edges of its band (no ``Fraction`` an edge).
  The exact tests then run on the few edges found.
* :class:`PolygonGrid` — a grid of square cells over the polygon's box, in
  integers (coordinates times ``L``, the common denominator of the vertices
  and of the motion's scale).  A cell is *boundary* when the closed cell
  meets an edge (decided exactly, column by column); any other cell lies
  wholly in the interior or wholly outside, which the crossing number of
  its centre decides (exactly, half-open rule).  Summed-area tables of the
  non-inside and non-outside cells answer, for a whole column chunk at once,
  whether a box lies in inside cells only (it is in the polygon) or in
  outside cells only (it misses the polygon).

The exact decisions (:func:`line_violation`, :func:`box_fits`) rest on two
facts about a simple polygon ``P``: near any boundary point there are
points of the interior and of the exterior; and a connected set that meets
no edge lies wholly in the interior or wholly outside.  So with margin
``d > 0`` the box of half-width ``d`` around ``p`` violates an allow zone
iff ``p`` is outside ``P`` or some edge meets the open box, i.e. ``p`` lies
in the open hexagon ``edge + open square``; it violates a forbid zone iff
``p`` is in the interior or in such a hexagon.  With ``d = 0`` a piece is
cut at its exact meeting parameters with the edges and each open piece
between them is in or out as its midpoint is.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..zones import PolygonZone
from ..zones.model import segment_meets_open_box

# not typing's (start-up, issue 36: no other module of a small verify imports typing): a type checker takes any
# TYPE_CHECKING for true; numpy loads with the grid (the fast path's)
TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any, TypeVar

    import numpy as np

    T = TypeVar("T")

__all__ = ["EdgeBoxes", "PolygonGrid", "box_fits", "cached", "edge_boxes", "grid", "locate", "open_box_point",
           "plane_violation", "screen_rows"]

F0 = Fraction(0)
F1 = Fraction(1)
Pt = tuple[Fraction, Fraction]

_CACHE: dict[tuple[int, int], tuple[PolygonZone, Any]] = {}
_CACHE_SIZE = 32


def cached(zone: PolygonZone, key: int, build: Callable[[], T]) -> T:
    """One structure per (zone, key); the zone is held with it, so its id is not reused meanwhile."""
    k = (id(zone), key)
    hit = _CACHE.get(k)
    if hit is not None and hit[0] is zone:
        got: T = hit[1]
        return got
    if len(_CACHE) >= _CACHE_SIZE:
        _CACHE.pop(next(iter(_CACHE)))
    value = build()
    _CACHE[k] = (zone, value)
    return value


class EdgeBoxes:
    """The polygon's edges, exact, in integers and filed in horizontal bands (no numpy, no ``Fraction`` an edge).

    The vertices times ``unit`` (the least common denominator of their coordinates) are integers; edge ``i``
    (vertex ``i`` to ``i + 1``) is ``ints[i] = (ax, ay, bx, by)`` in those units.  The band of an integer ``y``
    is ``(y - y0) // width`` clamped to ``0 .. len(bands) - 1``, nondecreasing in ``y``, and ``bands[k]`` lists
    (ascending) every edge whose range of ``y`` holds an integer of band ``k``: an edge from its low ``y``'s band
    to its high ``y``'s.  Invariant: an edge whose ``y`` range holds a real ``y*`` holds the integer
    ``floor(y*)`` (its ends are integers), so it is listed in that integer's band.  The width is chosen so
    that the lists hold a few entries an edge in all (at most about ``6 n``), whatever the polygon.
    """

    def __init__(self, zone: PolygonZone):
        v = zone.vertices
        self.edges = list(zip(v, v[1:] + v[:1]))  # zone.edges(), built in C
        ratios = [(x.as_integer_ratio(), y.as_integer_ratio()) for x, y in v]
        unit = math.lcm(*{d for (_, dx), (_, dy) in ratios for d in (dx, dy)})
        self.unit = unit
        xs = [nx * (unit // dx) for (nx, dx), _ in ratios]
        ys = [ny * (unit // dy) for _, (ny, dy) in ratios]
        xb, yb = xs[1:] + xs[:1], ys[1:] + ys[:1]
        n = len(xs)
        self.ints = list(zip(xs, ys, xb, yb))
        self.x_lo, self.x_hi = list(map(min, xs, xb)), list(map(max, xs, xb))
        self.y_lo, self.y_hi = y_lo, y_hi = list(map(min, ys, yb)), list(map(max, ys, yb))
        self.y0 = y0 = min(y_lo)
        span = max(y_hi) - y0 + 1
        # n bands at most; wider when the edges are tall, so the lists hold at most 4 n + 2 n entries
        self.width = w = max(1, -(-span // n), -(-(sum(y_hi) - sum(y_lo)) // (4 * n)))
        self.bands: list[list[int]] = [[] for _ in range(-(-span // w))]
        for i, lo, hi in zip(range(n), y_lo, y_hi):  # every y is in the bands' range: no clamping
            b0, b1 = (lo - y0) // w, (hi - y0) // w
            if b0 == b1:
                self.bands[b0].append(i)
            else:
                for k in range(b0, b1 + 1):
                    self.bands[k].append(i)

    def band(self, y: int) -> int:
        """The band of the integer ``y`` (in units of ``1 / unit``), clamped to the bands there are."""
        return min(max((y - self.y0) // self.width, 0), len(self.bands) - 1)

    def near(self, x0: Fraction, x1: Fraction, y0: Fraction, y1: Fraction) -> list[tuple[Pt, Pt]]:
        """Every edge whose closed box meets the closed box ``[x0, x1] x [y0, y1]`` (exactly those), in order.

        An edge's ends are integers in units of ``1 / unit``: its range ``[lo, hi]`` meets ``[x0, x1]`` iff
        ``lo <= floor(x1 unit)`` and ``hi >= ceil(x0 unit)``.  The bands searched are those of
        ``floor(y0 unit)`` .. ``ceil(y1 unit)``: an edge that meets the box at some ``y*`` is listed in the
        band of ``floor(y*)``, which lies between them (:class:`EdgeBoxes`)."""
        u = self.unit
        (nx0, dx0), (nx1, dx1) = x0.as_integer_ratio(), x1.as_integer_ratio()
        (ny0, dy0), (ny1, dy1) = y0.as_integer_ratio(), y1.as_integer_ratio()
        ix0, ix1 = -((-nx0 * u) // dx0), (nx1 * u) // dx1
        fy0, cy1 = (ny0 * u) // dy0, -((-ny1 * u) // dy1)
        iy0, iy1 = -((-ny0 * u) // dy0), (ny1 * u) // dy1
        b0, b1 = self.band(fy0), self.band(cy1)
        if b0 == b1:
            cand: Any = self.bands[b0]
        elif 2 * (b1 - b0) >= len(self.bands):
            cand = range(len(self.ints))
        else:
            cand = sorted({i for k in range(b0, b1 + 1) for i in self.bands[k]})
        x_lo, x_hi, y_lo, y_hi = self.x_lo, self.x_hi, self.y_lo, self.y_hi
        return [self.edges[i] for i in cand if x_lo[i] <= ix1 and x_hi[i] >= ix0 and y_lo[i] <= iy1 and y_hi[i] >= iy0]

    def locate(self, xn: int, xd: int, yn: int, yd: int) -> int:
        """:func:`locate` of the point ``(xn / xd, yn / yd)`` (``xd``, ``yd`` positive; any such fractions, not
        only lowest terms), in integers: the point over its coordinates' common denominator ``d``, the edges
        times ``d``; the crossing test ``q_x < x_cross`` is the sign of the cross product ``(b - a) x (q - a)``
        (times ``d``), which decides it for an edge going up and the other way for one going down."""
        d = xd // math.gcd(xd, yd) * yd
        u = xn * (d // xd) * self.unit
        v = yn * (d // yd) * self.unit
        inside = False
        for i in self.bands[self.band(v // d)]:
            ax, ay, bx, by = self.ints[i]
            ayd, byd = ay * d, by * d
            if (ayd < v and byd < v) or (ayd > v and byd > v):
                continue  # the edge misses the line y = q_y
            s = (bx - ax) * (v - ayd) - (by - ay) * (u - ax * d)
            if s == 0 and min(ax, bx) * d <= u <= max(ax, bx) * d:
                return 0
            if (ayd > v) != (byd > v) and (s > 0) == (by > ay):
                inside = not inside
        return 1 if inside else -1


def edge_boxes(zone: PolygonZone) -> EdgeBoxes:
    return cached(zone, 0, lambda: EdgeBoxes(zone))


def locate(zone: PolygonZone, q: Pt) -> int:
    """+1 strictly inside, 0 on the boundary, -1 outside (exact; the crossing number of a ray to +x, half-open
    rule: an edge counts when one end is above ``q`` and the other not; :meth:`EdgeBoxes.locate`)."""
    return edge_boxes(zone).locate(*q[0].as_integer_ratio(), *q[1].as_integer_ratio())


def _meets(p0: Pt, r: Pt, a: Pt, b: Pt) -> list[Fraction]:
    """Parameters ``t`` in ``[0, 1]`` where ``p0 + t r`` meets the edge ``[a, b]`` (both ends of an overlap)."""
    s = (b[0] - a[0], b[1] - a[1])
    w = (a[0] - p0[0], a[1] - p0[1])
    den = r[0] * s[1] - r[1] * s[0]
    if den != 0:
        t = (w[0] * s[1] - w[1] * s[0]) / den
        u = (w[0] * r[1] - w[1] * r[0]) / den
        return [t] if 0 <= t <= 1 and 0 <= u <= 1 else []
    if w[0] * r[1] - w[1] * r[0] != 0:
        return []  # parallel, not on one line
    rr = r[0] * r[0] + r[1] * r[1]
    ta = (w[0] * r[0] + w[1] * r[1]) / rr
    tb = ((b[0] - p0[0]) * r[0] + (b[1] - p0[1]) * r[1]) / rr
    lo, hi = max(F0, min(ta, tb)), min(F1, max(ta, tb))
    return [lo, hi] if lo <= hi else []


def _sides(zone: PolygonZone, p0: Pt, p1: Pt) -> list[tuple[Fraction, Fraction, bool, int]]:
    """The piece ``p0 -> p1`` cut where it meets the boundary: ``(t0, t1, closed, where)`` for each open
    piece between consecutive cuts (``where`` as :func:`locate` gives it for all of that piece), and
    for the two ends (closed, ``t0 == t1``).  A piece that stands still in the plane is one closed
    piece ``[0, 1]``."""
    if p0 == p1:
        return [(F0, F1, True, locate(zone, p0))]
    r = (p1[0] - p0[0], p1[1] - p0[1])
    cuts = {F0, F1}
    for a, b in edge_boxes(zone).near(min(p0[0], p1[0]), max(p0[0], p1[0]), min(p0[1], p1[1]), max(p0[1], p1[1])):
        cuts.update(_meets(p0, r, a, b))
    ts = sorted(cuts)
    out = [(F0, F0, True, locate(zone, p0)), (F1, F1, True, locate(zone, p1))]
    for t0, t1 in zip(ts, ts[1:]):
        m = (t0 + t1) / 2
        out.append((t0, t1, False, locate(zone, (p0[0] + m * r[0], p0[1] + m * r[1]))))
    return out


def plane_violation(zone: PolygonZone, p0: Pt, p1: Pt, d: Fraction) -> list[tuple[Fraction, Fraction, bool, bool]]:
    """The ``t`` in ``[0, 1]`` at which the margin box around ``p0 + t (p1 - p0)`` violates the
    polygon (its plane part), as intervals ``(lo, hi, lo_closed, hi_closed)``, possibly overlapping."""
    out: list[tuple[Fraction, Fraction, bool, bool]] = []
    bad = 1 if zone.forbid else -1  # where the point itself violates: in the interior / outside
    for t0, t1, closed, where in _sides(zone, p0, p1):
        if where == bad:
            out.append((t0, t1, closed, closed))
    if d > 0:
        lo_x, hi_x = min(p0[0], p1[0]) - d, max(p0[0], p1[0]) + d
        lo_y, hi_y = min(p0[1], p1[1]) - d, max(p0[1], p1[1]) + d
        for a, b in edge_boxes(zone).near(lo_x, hi_x, lo_y, hi_y):
            got = _hexagon_interval(p0, p1, a, b, d)
            if got is not None:
                out.append(got)
    return out


def _hexagon_interval(p0: Pt, p1: Pt, a: Pt, b: Pt, d: Fraction) -> tuple[Fraction, Fraction, bool, bool] | None:
    """``{t in [0, 1] : p(t) in the open hexagon [a, b] + (-d, d)^2}`` as an interval, or None."""
    r = (p1[0] - p0[0], p1[1] - p0[1])
    n = (a[1] - b[1], b[0] - a[0])
    k = d * (abs(n[0]) + abs(n[1]))
    c0 = n[0] * (p0[0] - a[0]) + n[1] * (p0[1] - a[1])
    c1 = n[0] * r[0] + n[1] * r[1]
    forms = (
        (min(a[0], b[0]) - d - p0[0], -r[0]), (p0[0] - max(a[0], b[0]) - d, r[0]),
        (min(a[1], b[1]) - d - p0[1], -r[1]), (p0[1] - max(a[1], b[1]) - d, r[1]),
        (c0 - k, c1), (-c0 - k, -c1),
    )
    lo, hi, lo_closed, hi_closed = F0, F1, True, True
    for alpha, beta in forms:  # alpha + beta t < 0
        if beta == 0:
            if alpha >= 0:
                return None
            continue
        x = -alpha / beta
        if beta > 0:  # t < x
            if x < hi or (x == hi and hi_closed):
                hi, hi_closed = x, False
        elif x > lo or (x == lo and lo_closed):  # t > x
            lo, lo_closed = x, False
    if lo < hi or (lo == hi and lo_closed and hi_closed):
        return lo, hi, lo_closed, hi_closed
    return None


def box_fits(zone: PolygonZone, lo: Pt, hi: Pt) -> bool:
    """Does the closed box ``[lo, hi]`` (in the plane, margin and tool shift already applied) satisfy the
    polygon's plane part: inside ``P`` (allow), or meeting no interior point (forbid)?  Exact."""
    if lo[0] < hi[0] and lo[1] < hi[1]:
        eb = edge_boxes(zone)
        for a, b in eb.near(lo[0], hi[0], lo[1], hi[1]):
            if segment_meets_open_box(a, b, lo, hi):
                return False
        # the centre, (lo + hi) / 2 on each axis as integers over 2 b d (no Fraction to normalize)
        (a0, b0), (c0, d0) = lo[0].as_integer_ratio(), hi[0].as_integer_ratio()
        (a1, b1), (c1, d1) = lo[1].as_integer_ratio(), hi[1].as_integer_ratio()
        where = eb.locate(a0 * d0 + c0 * b0, 2 * b0 * d0, a1 * d1 + c1 * b1, 2 * b1 * d1)
        return where < 0 if zone.forbid else where > 0
    # a flat box is the segment between its corners
    return not plane_violation(zone, lo, hi, F0)


def open_box_point(zone: PolygonZone, lo: Pt, hi: Pt, inside: bool) -> Pt | None:
    """A point of the open box ``(lo, hi)`` strictly inside the polygon (``inside``) or strictly outside it;
    None when there is none.  Exact, for any simple polygon however thin.

    The box is cut into horizontal slabs at the vertices' ``y`` values; no vertex lies inside a slab, so
    the edges crossing it keep their order there and the polygon's cross-section at ``y`` is a row of
    intervals between consecutive edges (inside and outside alternating, from outside).  For each
    interval ``(L(y), R(y))`` (``L``, ``R`` linear in ``y``, or infinite) the ``y`` of the slab where it
    meets ``(lo_x, hi_x)`` form an open interval found from two linear inequalities; its midpoint and the
    middle of the overlap there is the point.  Invariant: the point is in no edge (it lies strictly
    between two edges of its slab) and the crossing number puts it on the side asked for.

    >>> F = Fraction
    >>> blade = PolygonZone("b", ("X", "Y"), ((F(40), F(40)), (F(60), F(60)), (F(4999, 100), F(5001, 100))), forbid=True)
    >>> q = open_box_point(blade, (F(49), F(46)), (F(53), F(50)), True)
    >>> locate(blade, q), F(49) < q[0] < F(53) and F(46) < q[1] < F(50)
    (1, True)
    >>> open_box_point(blade, (F(0), F(0)), (F(1), F(1)), True) is None
    True
    """
    (x0, y0), (x1, y1) = lo, hi
    if not (x0 < x1 and y0 < y1):
        return None
    cuts = sorted({y0, y1} | {v[1] for v in zone.vertices if y0 < v[1] < y1})
    edges = [(a, b) for a, b in zone.edges() if a[1] != b[1]]
    for s0, s1 in zip(cuts, cuts[1:]):
        mid = (s0 + s1) / 2
        # x = alpha + beta y for each edge spanning the slab (an edge meeting the open slab spans it)
        lines = sorted(
            (a[0] + (mid - a[1]) * (b[0] - a[0]) / (b[1] - a[1]), a[0] - a[1] * (b[0] - a[0]) / (b[1] - a[1]),
             (b[0] - a[0]) / (b[1] - a[1]))
            for a, b in edges if min(a[1], b[1]) <= s0 and max(a[1], b[1]) >= s1)
        bounds: list[tuple[Fraction, Fraction] | None] = [None, *((al, be) for _, al, be in lines), None]
        pairs = list(zip(bounds, bounds[1:]))
        for left, right in pairs[1::2] if inside else pairs[0::2]:
            ya, yb = s0, s1
            # left(y) < x1 and right(y) > x0, each an open half-line in y (or all or nothing)
            for line, bound, below in ((left, x1, True), (right, x0, False)):
                if line is None:
                    continue
                al, be = line
                if be == 0:
                    if (al >= bound) if below else (al <= bound):
                        ya, yb = s1, s0
                    continue
                y = (bound - al) / be
                if (be > 0) == below:
                    yb = min(yb, y)
                else:
                    ya = max(ya, y)
            if ya < yb:
                y = (ya + yb) / 2
                xl = x0 if left is None else max(x0, left[0] + left[1] * y)
                xr = x1 if right is None else min(x1, right[0] + right[1] * y)
                return ((xl + xr) / 2, y)
    return None


# --------------------------------------------------------------------------- the grid

_GRID_CELLS = 1024


class PolygonGrid:
    """Cells of the polygon's box in integer units ``1/L``: boundary, inside, outside; summed-area tables.

    ``not_in`` / ``not_out`` are ``(nx + 1, ny + 1)`` prefix sums of the cells that are not inside /
    not outside; a box whose cells sum to 0 in ``not_in`` lies in ``P``, in ``not_out`` misses ``P``.
    """

    def __init__(self, zone: PolygonZone, unit: int):
        import numpy as np

        self.unit = unit
        ints = [(int(x * unit), int(y * unit)) for x, y in zone.vertices]
        xs = [p[0] for p in ints]
        ys = [p[1] for p in ints]
        extent = max(max(xs) - min(xs), max(ys) - min(ys))
        w = max(1, -(-extent // _GRID_CELLS))
        self.w = w
        self.x0 = min(xs) - 2 * w
        self.y0 = min(ys) - 2 * w
        self.nx = (max(xs) - self.x0) // w + 3
        self.ny = (max(ys) - self.y0) // w + 3
        span = max(self.nx, self.ny) * w
        dtype: Any = np.int64 if span < 2**29 else object  # products below stay under 2**62
        v = np.array([(x - self.x0, y - self.y0) for x, y in ints], dtype=dtype)
        a, b = v, np.roll(v, -1, axis=0)
        nx, ny = self.nx, self.ny
        marks = np.zeros((nx, ny + 1), dtype=np.int32)  # (int32, as the tables: fewer bytes to sum)
        # columns an edge meets (closed cells), then the rows it meets in each column
        xl, xh = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
        c_lo = (-((-xl) // w) - 1).astype(np.int64)
        c_hi = (xh // w).astype(np.int64)
        c_lo = np.maximum(c_lo, 0)
        counts = c_hi - c_lo + 1
        e = np.repeat(np.arange(len(v)), counts)
        col = np.repeat(c_lo, counts) + (np.arange(e.size) - np.repeat(np.cumsum(counts) - counts, counts))
        ax, ay, bx, by = a[e, 0], a[e, 1], b[e, 0], b[e, 1]
        u0 = np.maximum(np.minimum(ax, bx), col.astype(dtype) * w)
        u1 = np.minimum(np.maximum(ax, bx), (col.astype(dtype) + 1) * w)
        dx = bx - ax
        vertical = dx == 0
        sgn = np.where(dx < 0, -1, 1)
        den = np.where(vertical, 1, dx * sgn)
        n0 = np.where(vertical, np.minimum(ay, by), (ay * dx + (u0 - ax) * (by - ay)) * sgn)
        n1 = np.where(vertical, np.maximum(ay, by), (ay * dx + (u1 - ax) * (by - ay)) * sgn)
        y_lo, y_hi = np.minimum(n0, n1), np.maximum(n0, n1)
        r_lo = np.maximum((-((-y_lo) // (den * w)) - 1).astype(np.int64), 0)
        r_hi = np.minimum((y_hi // (den * w)).astype(np.int64), ny - 1)
        np.add.at(marks, (col, r_lo), 1)
        np.add.at(marks, (col, r_hi + 1), -1)
        boundary = np.cumsum(marks, axis=1)[:, :ny] > 0
        # crossings of the rows' centre lines y = (2r + 1) w / 2 (half-open rule), by column
        ay2, by2 = 2 * a[:, 1], 2 * b[:, 1]
        lo2, hi2 = np.minimum(ay2, by2), np.maximum(ay2, by2)
        # rows r with lo2 <= (2r + 1) w < hi2; only the crossings' parity counts: bytes, summed by exclusive or
        r0 = (-((-(lo2 - w)) // (2 * w))).astype(np.int64)
        r1 = (-((-(hi2 - w)) // (2 * w))).astype(np.int64) - 1
        cnt = np.maximum(r1 - r0 + 1, 0)
        e2 = np.repeat(np.arange(len(v)), cnt)
        row = np.repeat(r0, cnt) + (np.arange(e2.size) - np.repeat(np.cumsum(cnt) - cnt, cnt))
        ax, ay, bx, by = a[e2, 0], a[e2, 1], b[e2, 0], b[e2, 1]
        dy = by - ay
        sg = np.where(dy < 0, -1, 1)
        num = (2 * ax * dy + ((2 * row.astype(dtype) + 1) * w - 2 * ay) * (bx - ax)) * sg
        t_col = (num // (2 * w * dy * sg)).astype(np.int64)
        tog = np.zeros((ny, nx + 1), dtype=np.uint8)
        np.bitwise_xor.at(tog, (row, np.clip(t_col + 1, 0, nx)), 1)
        before = np.bitwise_xor.accumulate(tog, axis=1)  # before[r, k]: parity of the crossings in row r left of k
        right = before[:, -1:] ^ before[:, 1:]  # parity of the crossings right of column c (column > c)
        inside = right.T.astype(bool) & ~boundary
        outside = ~inside & ~boundary
        self.not_in = _sat(~inside)
        self.not_out = _sat(~outside)

    def count(self, table: np.ndarray, c0: np.ndarray, c1: np.ndarray, r0: np.ndarray, r1: np.ndarray) -> Any:
        return table[c1 + 1, r1 + 1] - table[c0, r1 + 1] - table[c1 + 1, r0] + table[c0, r0]


def _sat(cells: np.ndarray) -> np.ndarray:
    """The summed-area table of ``cells`` (bool), with a zero first row and column: ``out[i, j]`` counts the
    true cells of ``cells[:i, :j]`` (``int32``: a grid's ``(nx + 1) * (ny + 1)`` cells stay far below ``2**31``).
    Rows summed first (contiguous), then the rows accumulated in place: some twice as fast on the 1,026 x 1,026
    grid as two ``cumsum`` into new ``int64`` arrays.

    >>> import numpy as np
    >>> _sat(np.array([[True, False], [True, True]])).tolist()
    [[0, 0, 0], [0, 1, 1], [0, 2, 3]]
    """
    import numpy as np

    out = np.zeros((cells.shape[0] + 1, cells.shape[1] + 1), dtype=np.int32)  # a grid has < 2**31 cells
    np.cumsum(cells, axis=1, dtype=np.int32, out=out[1:, 1:])
    np.add.accumulate(out, axis=0, out=out)
    return out


def grid(zone: PolygonZone, scale: int) -> PolygonGrid:
    """The grid for coordinates scaled by ``10**scale`` (its unit: that and the vertices' denominators)."""
    unit = math.lcm(10**scale, *{c.denominator for p in zone.vertices for c in p})
    return cached(zone, 1 + scale, lambda: PolygonGrid(zone, unit))


def screen_rows(zone: PolygonZone, scale: int, lo_a: np.ndarray, hi_a: np.ndarray, lo_b: np.ndarray,
                hi_b: np.ndarray) -> Any:
    """Rows whose closed boxes (plane part, ``int64`` at ``10**scale``) the grid proves: inside the polygon
    (allow) or missing it (forbid).  False means "not proved here", never "violates"."""
    import numpy as np

    g = grid(zone, scale)
    k = g.unit // 10**scale
    ok = np.zeros(lo_a.shape, dtype=bool)
    limit = 2**61 // max(k, 1)
    if max(int(np.abs(lo_a).max(initial=0)), int(np.abs(hi_a).max(initial=0)), int(np.abs(lo_b).max(initial=0)),
           int(np.abs(hi_b).max(initial=0))) >= limit:
        return ok
    c0 = (lo_a * k - g.x0) // g.w
    c1 = (hi_a * k - g.x0) // g.w
    r0 = (lo_b * k - g.y0) // g.w
    r1 = (hi_b * k - g.y0) // g.w
    if zone.forbid:  # beyond the grid nothing is in the polygon: clip to the outer (outside) cells
        c0, c1 = np.clip(c0, 0, g.nx - 1), np.clip(c1, 0, g.nx - 1)
        r0, r1 = np.clip(r0, 0, g.ny - 1), np.clip(r1, 0, g.ny - 1)
        return g.count(g.not_out, c0, c1, r0, r1) == 0
    within = (c0 >= 0) & (c1 < g.nx) & (r0 >= 0) & (r1 < g.ny)
    c0, c1 = np.clip(c0, 0, g.nx - 1), np.clip(c1, 0, g.nx - 1)
    r0, r1 = np.clip(r0, 0, g.ny - 1), np.clip(r1, 0, g.ny - 1)
    return within & (g.count(g.not_in, c0, c1, r0, r1) == 0)
