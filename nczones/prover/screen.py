"""Vectorized tier-1 screen over column chunks (DESIGN §9).

For each row of a :class:`~nczones.motion.MotionChunk` in column form
(coordinates are ``int64`` values scaled by ``10**scale``) the screen proves
the row when the axis-aligned bounding box of the motion, grown by the
margin, fits every zone — an exact integer test (zone constants are rounded
*towards the inside* of the allowed set when they are not multiples of the
scale, which can only flag more rows; a polygon by its exact integer grid,
:func:`nczones.prover.polygon.screen_rows`).  Lines, rapids (both rapid modes: a
dogleg stays in the bounding box of its end points) and dwells are
screened; arcs and every unproved row are returned as *flagged* and go to
the exact per-segment path, which decides them.

Overflow: only sums and differences of coordinates and constants are
formed; inputs whose magnitude exceeds ``2**61`` are not screened (all rows
flagged, i.e. handled by exact Python integers downstream).
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Sequence
from fractions import Fraction
from itertools import chain
from typing import Any, Protocol

import numpy as np

from ..exact import decimal_places
from ..motion import PLANE_AXES, Developed, MotionChunk, Plane, Segment, SegmentKind, tip_offset
from ..zones import BoxZone, PolygonZone, SteppedZone, ZonePoint
from ..zones.kinds import KindTable


class ScreenedProver(Protocol):
    """What the screen reads of the prover (:class:`nczones.prover.core.Prover` provides it): the zones,
    the margin and the tool axis, and a cache of per-zone constants it keeps on the prover; to take
    segments into columns, its axes, parameter ranges, whether it has tip zones and which segments depend
    on a range.

    Declared here so that the screen does not import the prover's core back.
    """

    screen_constants: dict | None

    @property
    def zones(self) -> tuple[SteppedZone | BoxZone | PolygonZone, ...]: ...
    @property
    def margin(self) -> Fraction: ...
    @property
    def tool_axis(self) -> str | None: ...
    @property
    def axes(self) -> tuple[str, ...]: ...
    @property
    def params(self) -> tuple: ...
    @property
    def has_tip_zones(self) -> bool: ...
    def param_relevant(self, seg: Segment) -> bool: ...

__all__ = ["screen_chunk", "segment_columns", "shared_arc_boxes"]

_LIMIT = 2**61
_NEG = np.iinfo(np.int64).min // 4
_POS = np.iinfo(np.int64).max // 4


def _scaled(x: Fraction | None, scale: int, up: bool, default: int) -> int:
    """``x * 10**scale`` rounded up (``up``) or down to an integer, within ``[_NEG, _POS]``; ``default`` for None.

    In integers (a stepped table's limits are 4 a region: some 16,000 of these for 4,096 regions).

    >>> _scaled(Fraction(-7, 3), 1, True, 0), _scaled(Fraction(-7, 3), 1, False, 0), _scaled(None, 3, True, 5)
    (-23, -24, 5)
    >>> _scaled(Fraction(10**30), 0, False, 0) == _POS
    True
    """
    if x is None:
        return default
    num = x.numerator * 10**scale
    n = -(-num // x.denominator) if up else num // x.denominator
    return _POS if n > _POS else _NEG if n < _NEG else n


class _RangeTable:
    """Sparse table for O(1) range max / min queries over region limits.

    ``flat[j * n + i]`` is ``op`` over ``values[i : i + 2**j]`` (rows padded
    with the last valid entry), so a query is two gathers from the flat table.
    """

    def __init__(self, values: np.ndarray, op: Callable[[np.ndarray, np.ndarray], np.ndarray]):
        self.op = op
        n = len(values)
        levels = [np.asarray(values, dtype=np.int64)]
        k = 1
        while 2 * k <= n:
            prev = levels[-1]
            nxt = prev.copy()
            nxt[: n - k] = op(prev[: n - k], prev[k:])
            levels.append(nxt)
            k *= 2
        self.n = n
        self.flat = np.concatenate(levels)

    def query(self, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """op over values[lo..hi] inclusive (lo <= hi)."""
        length = hi - lo + 1
        lvl = np.frexp(np.maximum(length, 1).astype(np.float64))[1].astype(np.int64) - 1  # floor(log2)
        base = lvl * self.n
        out: np.ndarray = self.op(self.flat[base + lo], self.flat[base + hi - (np.int64(1) << lvl) + 1])
        return out


def _isqrt_ceil(n: np.ndarray) -> Any:
    """Exact ``ceil(sqrt(n))`` of non-negative int64 values below ``2**62``."""
    r = np.floor(np.sqrt(n.astype(np.float64))).astype(np.int64)
    for _ in range(3):  # float rounding is off by at most one here; fix it exactly
        r = np.where(r * r > n, r - 1, r)
        r = np.where((r + 1) * (r + 1) <= n, r + 1, r)
    return r + (r * r < n)


def _isqrt_floor(n: np.ndarray) -> Any:
    r = _isqrt_ceil(n)
    return r - (r * r > n)


def _half(cr: np.ndarray, dt: np.ndarray) -> np.ndarray:
    """0 where the ccw angle is in [0, pi) (cross > 0, or cross == 0 and dot > 0), else 1."""
    return np.where((cr > 0) | ((cr == 0) & (dt > 0)), 0, 1)


def arc_boxes(chunk: MotionChunk, rows: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Widen ``lo``/``hi`` of the arc ``rows`` to a sound box of each arc; True where that worked.

    Exact integer version of :meth:`nczones.prover.geometry.ArcGeom.plane_bbox`:
    in the arc's plane the box holds the end points and, for every axis
    direction ``±first``, ``±second`` that the closed sweep contains (decided
    exactly from signs of integer cross and dot products, as
    :func:`~nczones.prover.geometry.in_sweep` does), the centre plus or minus
    ``ceil(sqrt(r2))``, ``r2`` the larger squared radius.  A spiral arc
    (start and end radii differ: an I/J arc within the end-point tolerance)
    is grown by twice the difference of the radii (rounded outwards), which
    encloses its annulus sector.  Other axes (helix) span their start and
    end values, as ``lo``/``hi`` already do.

    Returns False for rows it cannot box: zero radius, a plane axis the
    machine lacks, or coordinates of ``2**31`` units or more (squares could
    overflow ``int64``); those rows go to the exact per-segment path.
    """
    ok = np.ones(rows.size, dtype=bool)
    if rows.size == 0:
        return ok
    axes = list(chunk.axes)
    assert chunk.plane is not None and chunk.centre is not None and chunk.start is not None \
        and chunk.end is not None and chunk.turns is not None and chunk.clockwise is not None  # arcs, columns form
    planes = chunk.plane[rows]
    rformat = None if chunk.radius is None else chunk.radius[rows] != 0
    for pv in sorted(set(planes.tolist())):  # (np.unique would import numpy.ma, ~10 ms)
        sel = planes == pv
        a_name, b_name, _ = PLANE_AXES[Plane(int(pv))]
        if a_name not in axes or b_name not in axes:
            ok[sel] = False
            continue
        ia, ib = axes.index(a_name), axes.index(b_name)
        if rformat is not None and rformat.any():
            rsel = sel & rformat
            if rsel.any():  # R-format rows (no rational centre): the certified centre enclosure
                assert chunk.scale is not None and chunk.radius is not None
                from .rformat import rformat_boxes

                r = rows[rsel]
                sa, sb = chunk.start[r, ia], chunk.start[r, ib]
                ea, eb = chunk.end[r, ia], chunk.end[r, ib]
                got, lo_a, hi_a, lo_b, hi_b = rformat_boxes(sa, sb, ea, eb, chunk.radius[r],
                                                             chunk.clockwise[r], chunk.turns[r], chunk.scale)
                lo[r, ia] = np.minimum(lo_a, np.minimum(sa, ea))
                hi[r, ia] = np.maximum(hi_a, np.maximum(sa, ea))
                lo[r, ib] = np.minimum(lo_b, np.minimum(sb, eb))
                hi[r, ib] = np.maximum(hi_b, np.maximum(sb, eb))
                ok[rsel] = got
            sel = sel & ~rformat
            if not sel.any():
                continue
        r = rows[sel]
        sa, sb = chunk.start[r, ia], chunk.start[r, ib]
        ea, eb = chunk.end[r, ia], chunk.end[r, ib]
        ca, cb = chunk.centre[r, 0], chunk.centre[r, 1]
        u0, u1, w0, w1 = sa - ca, sb - cb, ea - ca, eb - cb
        big = np.maximum.reduce([np.abs(u0), np.abs(u1), np.abs(w0), np.abs(w1)]) >= _SQ_LIMIT
        if big.any():  # keep the products below 2**63; flagged rows are computed on zeros
            u0, u1, w0, w1 = (np.where(big, 1, x) for x in (u0, u1, w0, w1))
        r2s = u0 * u0 + u1 * u1
        r2e = w0 * w0 + w1 * w1
        rhi = _isqrt_ceil(np.maximum(r2s, r2e))
        grow = np.where(r2s == r2e, 0, 2 * (rhi - _isqrt_floor(np.minimum(r2s, r2e))))
        # a whole turn: back to the start, laps, or (LinuxCNC) an end on the start's ray from the centre
        full = ((sa == ea) & (sb == eb)) | (chunk.turns[r] > 0) | ((u0 * w1 - u1 * w0 == 0) & (u0 * w0 + u1 * w1 > 0))
        ccw = ~chunk.clockwise[r].astype(bool)
        # in_sweep: clockwise from u to w is ccw from w to u
        p0, p1 = np.where(ccw, u0, w0), np.where(ccw, u1, w1)
        q0, q1 = np.where(ccw, w0, u0), np.where(ccw, w1, u1)
        hw = _half(p0 * q1 - p1 * q0, p0 * q0 + p1 * q1)

        def contains(cr_pv: np.ndarray, dot_pv: np.ndarray, cr_vq: np.ndarray) -> Any:
            hv = _half(cr_pv, dot_pv)
            return full | np.where(hv != hw, hv < hw, cr_vq >= 0)  # noqa: B023 - called within this iteration

        # v = (1, 0), (-1, 0), (0, 1), (0, -1): cross(p, v), dot(p, v), cross(v, q)
        plus_a = contains(-p1, p0, q1)
        minus_a = contains(p1, -p0, -q1)
        plus_b = contains(p0, p1, -q0)
        minus_b = contains(-p0, -p1, q0)
        lo_a = np.where(minus_a, ca - rhi, np.minimum(sa, ea)) - grow
        hi_a = np.where(plus_a, ca + rhi, np.maximum(sa, ea)) + grow
        lo_b = np.where(minus_b, cb - rhi, np.minimum(sb, eb)) - grow
        hi_b = np.where(plus_b, cb + rhi, np.maximum(sb, eb)) + grow
        lo[r, ia] = np.minimum(lo_a, np.minimum(sa, ea))
        hi[r, ia] = np.maximum(hi_a, np.maximum(sa, ea))
        lo[r, ib] = np.minimum(lo_b, np.minimum(sb, eb))
        hi[r, ib] = np.maximum(hi_b, np.maximum(sb, eb))
        ok[sel] = ~big & (r2s > 0) & (r2e > 0)
    return ok


_SQ_LIMIT = 2**31


class _ZoneConstants:
    """A zone's limits scaled to ``10**scale`` (rounded towards the inside), with range tables.

    Each is :func:`_scaled` of the zone's number (its floor or ceiling at the scale, clamped to
    ``[_NEG, _POS]``, a missing limit the default), computed from the zone's :class:`~nczones.zones.StepTable`:
    a number ``k / den`` is ``floor(k * 10**scale / den)`` or its ceiling in integers, a column at a time
    (``tests/prover/test_screen_constants.py`` holds them to :func:`_scaled` of each Fraction).
    """

    def __init__(self, z: SteppedZone, s: int):
        t = z.steps()
        self.ups_dn = np.array(_scaled_column(t.uptos, t.den, s, False), dtype=np.int64)
        self.ups_up = np.array(_scaled_column(t.uptos, t.den, s, True), dtype=np.int64)
        self.start_dn = _scaled(z.start, s, False, _NEG)
        self.start_up = _scaled(z.start, s, True, _NEG)
        if z.forbid:
            mins = np.array(_scaled_column(t.mins, t.den, s, False, t.low, _NEG), dtype=np.int64)
            maxs = np.array(_scaled_column(t.maxs, t.den, s, True, t.high, _POS), dtype=np.int64)
            self.min_t = _RangeTable(mins, np.minimum)
            self.max_t = _RangeTable(maxs, np.maximum)
        else:
            mins_lo = np.array(_scaled_column(t.mins, t.den, s, True, t.low, _NEG), dtype=np.int64)
            maxs_hi = np.array(_scaled_column(t.maxs, t.den, s, False, t.high, _POS), dtype=np.int64)
            self.min_t = _RangeTable(mins_lo, np.maximum)
            self.max_t = _RangeTable(maxs_hi, np.minimum)


def _scaled_column(ks: list[int], den: int, scale: int, up: bool, missing: int | None = None,
                   default: int = 0) -> list[int]:
    """:func:`_scaled` of each ``k / den`` of ``ks`` (``missing``: the value that stands for no number, read as
    ``default``), exact in integers: ``floor(k * 10**scale / den)`` is ``k * 10**scale // den``, the ceiling
    ``-(-k * 10**scale // den)``, each clamped to ``[_NEG, _POS]``."""
    f = 10**scale
    if f % den == 0:  # den divides the scale's power of ten (a table written to no more places): exact products
        m = f // den
        out = [k * m for k in ks]
    elif up:
        out = [-(-k * f // den) for k in ks]
    else:
        out = [k * f // den for k in ks]
    if missing is not None and missing in ks:
        out = [default if k == missing else n for k, n in zip(ks, out)]
    if out and (max(out) > _POS or min(out) < _NEG):
        out = [max(min(n, _POS), _NEG) for n in out]
    return out


def _constants(prover: ScreenedProver, z: SteppedZone, s: int) -> _ZoneConstants:
    cache = prover.screen_constants
    if cache is None:
        cache = {}
        prover.screen_constants = cache
    key = (id(z), s)
    got = cache.get(key)
    if got is None:
        got = cache[key] = _ZoneConstants(z, s)
    return got


#: A chunk with R-format rows is screened at this scale at least (``10**-6`` mm): their boxes are rounded
#: outwards to the scale, and a program written in whole millimetres (scale 0) would lose up to 1 mm.
R_SCALE = 6


def _refined(chunk: MotionChunk) -> MotionChunk:
    """``chunk`` at :data:`R_SCALE` (its coordinates, centres, radii and tool lengths times a power of ten,
    exact), or as it is when a value would reach ``2**59`` there."""
    from dataclasses import replace

    assert chunk.scale is not None and chunk.start is not None and chunk.end is not None \
        and chunk.tool_length is not None
    f = 10 ** (R_SCALE - chunk.scale)
    cols = [c for c in (chunk.start, chunk.end, chunk.tool_length, chunk.centre, chunk.radius) if c is not None]
    if max(int(np.abs(c).max(initial=0)) for c in cols) >= 2**59 // f:
        return chunk
    return replace(chunk, scale=R_SCALE, start=chunk.start * f, end=chunk.end * f, tool_length=chunk.tool_length * f,
                   centre=None if chunk.centre is None else chunk.centre * f,
                   radius=None if chunk.radius is None else chunk.radius * f)


def screen_chunk(chunk: MotionChunk, prover: ScreenedProver) -> list[int]:
    """Row indices the screen could not prove (to be decided exactly), in order.

    Lines, rapids and dwells are screened by the bounding box of their end
    points (a dogleg rapid stays in it too), arcs by :func:`arc_boxes`.
    """
    n = len(chunk)
    if n == 0:
        return []
    coarse = chunk
    if chunk.radius is not None and chunk.scale is not None and chunk.scale < R_SCALE:
        chunk = _refined(chunk)
    s = chunk.scale
    start, end, tl, kinds = chunk.start, chunk.end, chunk.tool_length, chunk.kind
    assert s is not None and start is not None and end is not None and tl is not None and kinds is not None, \
        "the columns form"
    if (
        max(int(np.abs(start).max(initial=0)), int(np.abs(end).max(initial=0))) > _LIMIT
        or int(np.abs(tl).max(initial=0)) > _LIMIT
        or (chunk.centre is not None and int(np.abs(chunk.centre).max(initial=0)) > _LIMIT)
        or (chunk.radius is not None and int(np.abs(chunk.radius).max(initial=0)) > _LIMIT)
    ):
        return list(range(n))
    lo = np.minimum(start, end)
    hi = np.maximum(start, end)
    d_up = _scaled(prover.margin, s, True, 0)
    if abs(d_up) > _LIMIT:
        return list(range(n))
    ok = np.ones(n, dtype=bool)
    arows = np.flatnonzero(kinds == SegmentKind.ARC)
    if arows.size:
        _box_arcs(coarse, chunk, arows, lo, hi, ok)
    axes = list(chunk.axes)
    for z in prover.zones:
        if not ok.any():
            break
        tip = z.point is ZonePoint.TIP

        def rng(a: str) -> tuple[np.ndarray, np.ndarray]:
            k = axes.index(a)
            a_lo, a_hi = lo[:, k] - d_up, hi[:, k] + d_up
            if tip and a == prover.tool_axis:  # noqa: B023 - called within this iteration
                a_lo, a_hi = a_lo - tl, a_hi - tl
            return a_lo, a_hi

        ZONE_ROWS(z, prover, rng, ok, s, axes)
    return np.flatnonzero(~ok).tolist()


def _box_arcs(coarse: MotionChunk, chunk: MotionChunk, arows: np.ndarray, lo: np.ndarray, hi: np.ndarray,
              ok: np.ndarray) -> None:
    """Widen ``lo``/``hi`` (at ``chunk``'s scale: ``coarse`` as given, or refined for its R-format rows) of the
    arc rows ``arows`` to their boxes (:func:`arc_boxes`), ``ok`` False where that failed; kept for
    :func:`shared_arc_boxes`."""
    if chunk.centre is None or chunk.plane is None:
        ok[arows] = False
    elif chunk is not coarse and chunk.radius is not None:
        # refined for the R-format rows: the I/J rows are boxed at their own scale (their squares stay
        # in int64 there), then scaled up exactly
        assert coarse.start is not None and coarse.end is not None and coarse.scale is not None \
            and chunk.scale is not None
        rf = chunk.radius[arows] != 0
        ij = arows[~rf]
        if ij.size:
            lo0, hi0 = np.minimum(coarse.start, coarse.end), np.maximum(coarse.start, coarse.end)
            ok[ij] = arc_boxes(coarse, ij, lo0, hi0)
            f = 10 ** (chunk.scale - coarse.scale)
            lo[ij], hi[ij] = lo0[ij] * f, hi0[ij] * f
        if rf.any():
            ok[arows[rf]] = arc_boxes(chunk, arows[rf], lo, hi)
    else:
        ok[arows] = arc_boxes(chunk, arows, lo, hi)
    assert chunk.scale is not None
    # lo/hi are not changed after this (the zones read new arrays from them); ok is: a copy
    _LAST_BOXES[0] = (weakref.ref(coarse), chunk.scale, ok.copy(), lo, hi)


#: The boxes :func:`screen_chunk` formed for the last column chunk it was given with arcs (held by a weak
#: reference to that chunk object, so that no other chunk matches): ``(chunk, scale, ok, lo, hi)``.
_LAST_BOXES: list[Any] = [None]


def shared_arc_boxes(chunk: MotionChunk) -> tuple[int, np.ndarray, np.ndarray, np.ndarray] | None:
    """``(scale, ok, lo, hi)``: the rows' boxes of ``chunk`` (this very object) as the screen formed them, when it
    boxed this chunk's arcs last (else None): at ``scale`` (the chunk's, or finer for its R-format rows), each
    arc row's :func:`arc_boxes` box (sound where ``ok``), the other rows' the box of their end points.  The
    Fanuc run hull (``nczones.prover.blend``) sees each chunk just after the screen and rounds these outwards
    to the chunk's scale instead of boxing the arcs again.  Read only."""
    got = _LAST_BOXES[0]
    if got is None or got[0]() is not chunk:
        return None
    return got[1], got[2], got[3], got[4]


RowRange = Callable[[str], tuple[np.ndarray, np.ndarray]]


def _unscreened(z: object, prover: ScreenedProver, rng: RowRange, ok: np.ndarray, s: int, axes: list[str]) -> None:
    ok[:] = False


#: Set to False the rows of ``ok`` (a bool column, changed in place) whose box (``rng(axis)``: its integer
#: range at scale ``s`` as the zone sees it, margin included) the screen cannot show inside the zone (allowed)
#: or clear of its interior (forbidden), per zone kind.  Fallback: no row is shown (the exact tier decides).
ZONE_ROWS: KindTable[Callable[..., None]] = KindTable("prover.screen.zone_rows", fallback=_unscreened)


@ZONE_ROWS.register(BoxZone)
def _box_rows(z: BoxZone, prover: ScreenedProver, rng: RowRange, ok: np.ndarray, s: int, axes: list[str]) -> None:
    if z.forbid:
        clear = np.zeros(len(ok), dtype=bool)
        for a, lo_, hi_ in z.limits:
            r0, r1 = rng(a)
            if hi_ is not None:
                clear |= r0 >= _scaled(hi_, s, True, _POS)
            if lo_ is not None:
                clear |= r1 <= _scaled(lo_, s, False, _NEG)
        ok &= clear
    else:
        for a, lo_, hi_ in z.limits:
            r0, r1 = rng(a)
            if lo_ is not None:
                ok &= r0 >= _scaled(lo_, s, True, _NEG)
            if hi_ is not None:
                ok &= r1 <= _scaled(hi_, s, False, _POS)


@ZONE_ROWS.register(SteppedZone)
def _stepped_rows(z: SteppedZone, prover: ScreenedProver, rng: RowRange, ok: np.ndarray, s: int, axes: list[str]) -> None:
    k = _constants(prover, z, s)
    r0, r1 = rng(z.reference_axis)
    l0, l1 = rng(z.limited_axis)
    last = len(k.ups_dn) - 1
    # region range reached by [r0, r1] (closed), generous at rounding
    i0 = np.searchsorted(k.ups_up, r0, side="left")
    i1 = np.searchsorted(k.ups_dn, r1, side="left")
    i0c = np.minimum(i0, last)
    i1c = np.minimum(i1, last)
    if z.forbid:
        lo_i = np.maximum(np.minimum(i0c, i1c) - 1, 0)
        hi_i = np.minimum(i1c + 1, last)
        below = l1 <= k.min_t.query(lo_i, hi_i)
        above = l0 >= k.max_t.query(lo_i, hi_i)
        outside = (r1 <= k.start_dn) | (r0 >= k.ups_up[-1])
        ok &= below | above | outside
    else:
        inside = (r0 >= k.start_up) & (r1 <= k.ups_dn[-1]) & (i1 <= last)
        hi_i = np.minimum(i1c + 1, last)  # a rounded boundary may reach one more row
        ok &= inside & (l0 >= k.min_t.query(i0c, hi_i)) & (l1 <= k.max_t.query(i0c, hi_i))


@ZONE_ROWS.register(PolygonZone)
def _polygon_rows(z: PolygonZone, prover: ScreenedProver, rng: RowRange, ok: np.ndarray, s: int, axes: list[str]) -> None:
    from .polygon import screen_rows

    if z.plane[0] not in axes or z.plane[1] not in axes:
        ok[:] = False
        return
    x0, x1 = rng(z.plane[0])
    y0, y1 = rng(z.plane[1])
    if z.forbid:  # clear when the box misses the prism's limits or the polygon (its grid)
        clear = np.zeros(len(ok), dtype=bool)
        for a, lo_, hi_ in z.limits:
            r0, r1 = rng(a)
            if hi_ is not None:
                clear |= r0 >= _scaled(hi_, s, True, _POS)
            if lo_ is not None:
                clear |= r1 <= _scaled(lo_, s, False, _NEG)
        todo = ok & ~clear
        if todo.any():
            rows = np.flatnonzero(todo)
            clear[rows] = screen_rows(z, s, x0[rows], x1[rows], y0[rows], y1[rows])
        ok &= clear
    else:
        for a, lo_, hi_ in z.limits:
            r0, r1 = rng(a)
            if lo_ is not None:
                ok &= r0 >= _scaled(lo_, s, True, _NEG)
            if hi_ is not None:
                ok &= r1 <= _scaled(hi_, s, False, _POS)
        rows = np.flatnonzero(ok)
        if rows.size:
            ok[rows] = screen_rows(z, s, x0[rows], x1[rows], y0[rows], y1[rows])


#: The finest decimal scale arc columns are built at (``10**-12`` mm).
MAX_SEGMENT_SCALE = 12
#: The scale of line, rapid and dwell columns (``10**-9`` mm): their boxes are rounded outwards to it.
LINE_SCALE = 9
_LINE_UNIT = 10**LINE_SCALE
_LINE_KINDS = frozenset({SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.DWELL})
_DEC_EXP: dict[int, int] = {1: 0}
_LINE_MULT: dict[int, int | None] = {1: _LINE_UNIT}


def _decimal_exponent(den: int) -> int:
    """The least ``s`` with ``den`` dividing ``10**s``; ``MAX_SEGMENT_SCALE + 1`` when there is none that small."""
    got = _DEC_EXP.get(den)
    if got is None:
        places = decimal_places(Fraction(1, den))
        got = places if places is not None and places <= MAX_SEGMENT_SCALE else MAX_SEGMENT_SCALE + 1
        if len(_DEC_EXP) < 4096:
            _DEC_EXP[den] = got
    return got


def _line_multiplier(den: int) -> int | None:
    """``10**LINE_SCALE // den`` when ``den`` divides it (the value is exact in line columns), else None."""
    q, r = divmod(_LINE_UNIT, den)
    got = q if r == 0 else None
    if len(_LINE_MULT) < 4096:
        _LINE_MULT[den] = got
    return got


def _screenable(seg: Segment, prover: ScreenedProver) -> bool:
    """Whether the prover decides ``seg`` on its concrete path, so that a proved box proves it."""
    if seg.axes != prover.axes:
        return False
    if seg.extra and (seg.payload(Developed) is not None
                      or (prover.has_tip_zones and tip_offset(seg.extra))):
        return False
    return not (prover.params and prover.param_relevant(seg))


def segment_columns(segments: Sequence[Segment], prover: ScreenedProver) -> list[tuple[MotionChunk, list[int]]]:
    """The segments the column screen can take, as column chunks, each with the indices of its rows in ``segments``.

    A segment is taken when the prover would decide it on its concrete path
    (:meth:`~nczones.prover.core.Prover.check`: a line, rapid, dwell or an
    arc with a centre, not depending on a parameter range, no lathe tool-tip
    shift, no developed arc) and its tool length is exact in the columns.

    Invariant (soundness): the box :func:`screen_chunk` forms for a row
    contains the segment's exact box.  Lines, rapids and dwells go into one
    chunk at :data:`LINE_SCALE`, each row spanning its segment's box rounded
    outwards there (from the floor of the low corner to the ceiling of the
    high one; exact for decimals of at most that many places, and the full
    interpreter's doubles are binary fractions that are not); a line, rapid
    or dwell is screened by that box.  The corners are computed per
    distinct point (a segment that starts at the tuple the one before ended
    at shares its row of numbers), in ``int64`` columns for decimals and
    binary fractions (:func:`_scaled_bounds`, exact integer shifts) and by
    Python's integers for every other number; a line with a number of
    magnitude ``2**60`` or more at the scale is not taken.  Arcs go into a second chunk at the
    finest decimal scale any of them needs (at most
    :data:`MAX_SEGMENT_SCALE`), taken only when their end points and centre
    are such decimals, so their rows are exact.  The screen proves a row only
    when its box (grown by the margin) fits every zone, and a box that fits
    holds every smaller one, so a proved row is a proved segment; the rows it
    cannot prove and the segments not taken are left for the per-segment
    path, which decides them exactly.

    >>> from fractions import Fraction as F
    >>> from nczones.machine import parse_machine
    >>> from nczones.prover import Prover
    >>> m = parse_machine('[machine]\\naxes = ["X"]\\n[machine.rapid]\\nX = "1"\\n[machine.reference]\\nX = "0"\\n'
    ...                   '[[zones]]\\nname = "t"\\nkind = "box"\\nmin = { X = "0" }\\nmax = { X = "10" }\\n')
    >>> segs = [Segment(SegmentKind.LINE, (F(1, 4),), (F(1, 3),), ("X",)),
    ...         Segment(SegmentKind.ARC, (F(0),), (F(0),), ("X",), centre=(F(1, 3), F(0)))]
    >>> [(rows, c.scale, c.start[:, 0].tolist(), c.end[:, 0].tolist()) for c, rows in segment_columns(segs, Prover(m))]
    [([0], 9, [250000000], [333333334])]
    """
    arcs: list[int] = []
    line_rows: list[int] = []
    taken: list[Segment] = []
    points: list[tuple[Fraction, ...]] = []  # the distinct start and end tuples of the taken segments
    at_start: list[int] = []  # per taken segment, the index of its start and of its end in points
    at_end: list[int] = []
    tls: list[int] = []
    mults = _LINE_MULT
    arc_kind = SegmentKind.ARC
    line_kinds = _LINE_KINDS
    simple = not prover.params and not prover.has_tip_zones
    axes = prover.axes
    prev_end: tuple | None = None
    prev_at = -1
    prev_tl: Fraction | None = None
    tl_scaled: int | None = None
    for i, seg in enumerate(segments):
        kind = seg.kind
        if kind is arc_kind:
            arcs.append(i)
            continue
        if kind not in line_kinds:
            continue
        if simple:
            if (seg.axes is not axes and seg.axes != axes) or (
                    seg.payload(Developed) is not None):
                continue
        elif not _screenable(seg, prover):
            continue
        tl = seg.tool_length
        if tl is not prev_tl:
            m_tl = mults.get(tl.denominator, 0)
            if m_tl == 0:
                m_tl = _line_multiplier(tl.denominator)
            prev_tl, tl_scaled = tl, (None if m_tl is None else tl.numerator * m_tl)
        if tl_scaled is None:
            continue
        tls.append(tl_scaled)
        line_rows.append(i)
        taken.append(seg)
        start = seg.start
        if start is not prev_end:  # a segment mostly starts where the one before ended: the same tuple
            prev_at = len(points)
            points.append(start)
        at_start.append(prev_at)
        end = seg.end
        if end is not start:
            prev_at = len(points)
            points.append(end)
        at_end.append(prev_at)
        prev_end = end
    out: list[tuple[MotionChunk, list[int]]] = []
    if line_rows:
        got = _line_rows(points, at_start, at_end, tls, len(axes))
        if got is not None:
            keep, lo, hi, tl_col = got
            if keep is not None:
                line_rows = [line_rows[k] for k in keep]
                taken = [taken[k] for k in keep]
            if line_rows:
                n = len(taken)
                out.append((MotionChunk(
                    axes, LINE_SCALE, kind=np.fromiter((int(s.kind) for s in taken), np.int8, n), start=lo, end=hi,
                    line=np.fromiter((0 if s.span is None else s.span.line for s in taken), np.int64, n),
                    block=np.fromiter((s.block for s in taken), np.int64, n), tool_length=tl_col), line_rows))
    if arcs:
        got_arcs = _arc_columns(segments, arcs, prover)
        if got_arcs is not None:
            out.append(got_arcs)
    return out


def _line_rows(points: list[tuple[Fraction, ...]], at_start: list[int], at_end: list[int], tls: list[int],
               k: int) -> tuple[list[int] | None, np.ndarray, np.ndarray, np.ndarray] | None:
    """The rows of lines whose start and end are ``points[at_start[r]]`` and ``points[at_end[r]]``:
    ``(kept, low corners, high corners, tool lengths)`` at :data:`LINE_SCALE`, each corner the floor of
    the box's low corner and the ceiling of its high one.  A row with a number of magnitude ``2**60``
    or more (in units of the scale) is left out: ``kept`` lists the rows kept, None when all are; the
    result is None when none is."""
    values = list(chain.from_iterable(points))
    floors, ceils, done = _scaled_bounds(values)
    bound = _ROW_BOUND
    big: set[int] = set()  # points with a number beyond the bound
    for j in np.flatnonzero(~done).tolist():
        n, d = values[j].as_integer_ratio()
        f = (n * _LINE_UNIT) // d
        c = -((-n * _LINE_UNIT) // d)
        if -bound < f and c < bound:
            floors[j], ceils[j] = f, c
        else:
            big.add(j // k)
    keep: list[int] | None = None
    if big or any(not -bound < t < bound for t in tls):
        keep = [r for r in range(len(at_start))
                if at_start[r] not in big and at_end[r] not in big and -bound < tls[r] < bound]
        if not keep:
            return None
        tls = [tls[r] for r in keep]
        at_start = [at_start[r] for r in keep]
        at_end = [at_end[r] for r in keep]
    fl = floors.reshape(len(points), k)
    cl = ceils.reshape(len(points), k)
    s = np.array(at_start, dtype=np.intp)
    e = np.array(at_end, dtype=np.intp)
    return keep, np.minimum(fl[s], fl[e]), np.maximum(cl[s], cl[e]), np.array(tls, dtype=np.int64)


#: Rows are built only from numbers below this magnitude (in units of :data:`LINE_SCALE`).
_ROW_BOUND = 2**60
_FIVE9 = 5**9  # 10**9 == 5**9 * 2**9


def _scaled_bounds(values: list[Fraction]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(floor, ceiling, done)`` of ``v * 10**LINE_SCALE`` for every value, in ``int64`` arrays: exact where
    ``done`` is True (the value a decimal of at most :data:`LINE_SCALE` places, or a binary fraction, with
    numerator and denominator in ``int64`` and the result below ``2**58``), left for the caller elsewhere.

    A binary fraction ``n / 2**k`` (``k > 9``) times ``10**9`` is ``n * 5**9 / 2**(k - 9)``; with
    ``n = h * 2**26 + l`` (``0 <= l < 2**26``) the floor is
    ``(h * 5**9 + ((l * 5**9) >> 26)) >> (k - 35)`` for ``k >= 35`` and
    ``((h * 5**9) << (35 - k)) + ((l * 5**9) >> (k - 9))`` below, by integer shifts (floors) that stay
    in ``int64``; the ceiling is minus the floor of ``-n``.
    """
    m = len(values)
    floors = np.zeros(m, dtype=np.int64)
    ceils = np.zeros(m, dtype=np.int64)
    done = np.zeros(m, dtype=bool)
    try:
        try:
            n, d = _terms(values)
        except AttributeError:  # a number that is not a Fraction (a caller's int): read by the properties
            n, d = _terms_by_properties(values)
    except OverflowError:  # a numerator or denominator beyond int64: every value by Python's integers
        return floors, ceils, done
    fits = (n > -2**62) & (n < 2**62)
    # decimals of at most LINE_SCALE places: exact
    dec = (_LINE_UNIT % d) == 0
    mult = np.where(dec, _LINE_UNIT // np.minimum(d, _LINE_UNIT), 1)
    exact = dec & fits & (np.abs(np.where(fits, n, 0)) <= (_ROW_BOUND - 1) // mult)
    floors[exact] = ceils[exact] = n[exact] * mult[exact]
    # binary fractions n / 2**k, k > LINE_SCALE
    pow2 = ~dec & ((d & (d - 1)) == 0) & fits
    if pow2.any():
        df = d.astype(np.float64)  # a power of two below 2**63: exact
        k = np.frexp(df)[1] - 1
        small = np.abs(n.astype(np.float64)) * (1e9 / df) < 2.0**58  # relative error far below 1/2
        sel = np.flatnonzero(pow2 & small)
        if sel.size:
            ns, ks = n[sel], k[sel].astype(np.int64)
            floors[sel] = _floor_scaled(ns, ks)
            ceils[sel] = -_floor_scaled(-ns, ks)
            done[sel] = True
    done |= exact
    return floors, ceils, done


def _terms_by_slots(values: list[Fraction]) -> tuple[np.ndarray, np.ndarray]:
    return (np.array([v._numerator for v in values], dtype=np.int64),  # type: ignore[attr-defined]
            np.array([v._denominator for v in values], dtype=np.int64))  # type: ignore[attr-defined]


def _terms_by_properties(values: list[Fraction]) -> tuple[np.ndarray, np.ndarray]:
    return (np.array([v.numerator for v in values], dtype=np.int64),
            np.array([v.denominator for v in values], dtype=np.int64))


def _slots_hold_terms() -> bool:
    f = Fraction(-6, 4)
    return getattr(f, "_numerator", None) == -3 and getattr(f, "_denominator", None) == 2


#: Numerators and denominators of Fractions as ``int64`` arrays (OverflowError beyond): read from CPython's
#: slots (4x faster than the properties) when they hold them, checked once.
_terms = _terms_by_slots if _slots_hold_terms() else _terms_by_properties


def _floor_scaled(n: np.ndarray, k: np.ndarray) -> np.ndarray:
    """``floor(n * 10**9 / 2**k)`` for ``|n| < 2**62``, ``9 < k < 63`` and a result below ``2**58`` (see
    :func:`_scaled_bounds`)."""
    h = (n >> 26) * _FIVE9
    low = (n & (2**26 - 1)) * _FIVE9
    wide = k >= 35
    return np.where(wide, (h + (low >> 26)) >> np.where(wide, k - 35, 0),
                    (h << np.where(wide, 0, 35 - k)) + (low >> np.where(wide, 0, k - 9)))


def _arc_columns(segments: Sequence[Segment], which: list[int],
                 prover: ScreenedProver) -> tuple[MotionChunk, list[int]] | None:
    """The arcs among ``segments[which]`` whose numbers are decimals of at most MAX_SEGMENT_SCALE places, exact
    (R-format arcs without a rational centre by their ``radius`` column, :mod:`nczones.prover.rformat`)."""
    exp = _decimal_exponent
    limit = MAX_SEGMENT_SCALE
    taken: list[int] = []
    scale = 0
    for i in which:
        seg = segments[i]
        c = seg.centre
        if c is None:
            if seg.radius is None:
                continue
            c = (seg.radius, seg.radius)  # an R-format arc: its radius goes into the columns
        if seg.plane is None or not _screenable(seg, prover):
            continue
        s = max(exp(seg.tool_length.denominator), exp(c[0].denominator), exp(c[1].denominator))
        for v in seg.start:
            s = max(s, exp(v.denominator))
        for v in seg.end:
            s = max(s, exp(v.denominator))
        if s > limit:
            continue
        scale = max(scale, s)
        taken.append(i)
    unit: int = 10**scale
    bound = 2**60
    rows: list[int] = []
    starts: list[list[int]] = []
    ends: list[list[int]] = []
    tls: list[int] = []
    centres: list[tuple[int, int]] = []
    planes: list[int] = []
    cws: list[bool] = []
    turns: list[int] = []
    blocks: list[int] = []
    lines: list[int] = []
    radii: list[int] = []

    def scaled(v: Fraction) -> int:
        return v.numerator * (unit // v.denominator)

    for i in taken:
        seg = segments[i]
        assert seg.plane is not None  # taken above
        st = [scaled(v) for v in seg.start]
        en = [scaled(v) for v in seg.end]
        tl = scaled(seg.tool_length)
        if seg.centre is None:
            assert seg.radius is not None  # taken above
            ctr, rad = (0, 0), scaled(seg.radius)
        else:
            ctr, rad = (scaled(seg.centre[0]), scaled(seg.centre[1])), 0
        if max(abs(v) for v in (*st, *en, tl, *ctr, rad)) >= bound:
            continue
        radii.append(rad)
        rows.append(i)
        starts.append(st)
        ends.append(en)
        tls.append(tl)
        centres.append(ctr)
        planes.append(int(seg.plane))
        cws.append(bool(seg.clockwise))
        turns.append(int(seg.turns))
        blocks.append(seg.block)
        lines.append(seg.span.line if seg.span is not None else 0)
    if not rows:
        return None
    m = len(rows)
    chunk = MotionChunk(
        prover.axes, scale, kind=np.full(m, int(SegmentKind.ARC), dtype=np.int8),
        start=np.array(starts, dtype=np.int64).reshape(m, len(prover.axes)),
        end=np.array(ends, dtype=np.int64).reshape(m, len(prover.axes)),
        line=np.array(lines, dtype=np.int64), block=np.array(blocks, dtype=np.int64),
        tool_length=np.array(tls, dtype=np.int64), centre=np.array(centres, dtype=np.int64).reshape(m, 2),
        plane=np.array(planes, dtype=np.int8), clockwise=np.array(cws, dtype=bool),
        turns=np.array(turns, dtype=np.int32),
        radius=np.array(radii, dtype=np.int64) if any(radii) else None,
    )
    return chunk, rows
