"""Vectorized tier-1 screen over column chunks (DESIGN §9).

For each row of a :class:`~nczones.motion.MotionChunk` in column form
(coordinates are ``int64`` values scaled by ``10**scale``) the screen proves
the row when the axis-aligned bounding box of the motion, grown by the
margin, fits every zone — an exact integer test (zone constants are rounded
*towards the inside* of the allowed set when they are not multiples of the
scale, which can only flag more rows).  Lines, rapids (both rapid modes: a
dogleg stays in the bounding box of its end points) and dwells are
screened; arcs and every unproved row are returned as *flagged* and go to
the exact per-segment path, which decides them.

Overflow: only sums and differences of coordinates and constants are
formed; inputs whose magnitude exceeds ``2**61`` are not screened (all rows
flagged, i.e. handled by exact Python integers downstream).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from ..motion import MotionChunk, SegmentKind
from ..zones import BoxZone, PolygonZone, SteppedZone, ZonePoint

__all__ = ["screen_chunk"]

_LIMIT = 2**61
_NEG = np.iinfo(np.int64).min // 4
_POS = np.iinfo(np.int64).max // 4


def _scaled(x: Fraction | None, scale: int, up: bool, default: int) -> int:
    if x is None:
        return default
    v = x * 10**scale
    n = math.ceil(v) if up else math.floor(v)
    return max(min(n, _POS), _NEG)


class _RangeTable:
    """Sparse table for O(1) range max / min queries over region limits."""

    def __init__(self, values: np.ndarray, op):
        self.op = op
        self.levels = [values]
        k = 1
        while 2 * k <= len(values):
            prev = self.levels[-1]
            self.levels.append(op(prev[:-k], prev[k:]))
            k *= 2

    def query(self, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """op over values[lo..hi] inclusive (lo <= hi)."""
        length = hi - lo + 1
        lvl = np.floor(np.log2(np.maximum(length, 1))).astype(np.int64)
        out = np.empty(len(lo), dtype=np.int64)
        for j in np.unique(lvl):
            sel = lvl == j
            table = self.levels[j]
            k = 1 << int(j)
            out[sel] = self.op(table[lo[sel]], table[hi[sel] - k + 1])
        return out


def screen_chunk(chunk: MotionChunk, prover) -> list[int]:
    """Row indices the screen could not prove (to be decided exactly), in order."""
    n = len(chunk)
    if n == 0:
        return []
    s = chunk.scale
    start, end = chunk.start, chunk.end
    if (
        max(int(np.abs(start).max(initial=0)), int(np.abs(end).max(initial=0))) > _LIMIT
        or int(np.abs(chunk.tool_length).max(initial=0)) > _LIMIT
    ):
        return list(range(n))
    lo = np.minimum(start, end)
    hi = np.maximum(start, end)
    d_up = _scaled(prover.margin, s, True, 0)
    if abs(d_up) > _LIMIT:
        return list(range(n))
    ok = chunk.kind != SegmentKind.ARC
    axes = list(chunk.axes)
    tl = chunk.tool_length
    for z in prover.zones:
        if not ok.any():
            break
        tip = z.point is ZonePoint.TIP

        def rng(a):
            k = axes.index(a)
            a_lo, a_hi = lo[:, k] - d_up, hi[:, k] + d_up
            if tip and a == prover.tool_axis:
                a_lo, a_hi = a_lo - tl, a_hi - tl
            return a_lo, a_hi

        if isinstance(z, BoxZone):
            if z.forbid:
                clear = np.zeros(n, dtype=bool)
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
        elif isinstance(z, SteppedZone):
            r0, r1 = rng(z.reference_axis)
            l0, l1 = rng(z.limited_axis)
            ups_dn = np.array([_scaled(r.upto, s, False, 0) for r in z.regions], dtype=np.int64)
            ups_up = np.array([_scaled(r.upto, s, True, 0) for r in z.regions], dtype=np.int64)
            # region range reached by [r0, r1] (closed), generous at rounding
            i0 = np.searchsorted(ups_up, r0, side="left")
            i1 = np.searchsorted(ups_dn, r1, side="left")
            i0c = np.minimum(i0, len(ups_dn) - 1)
            i1c = np.minimum(i1, len(ups_dn) - 1)
            mins_lo = np.array([_scaled(r.min, s, True, _NEG) for r in z.regions], dtype=np.int64)
            maxs_hi = np.array([_scaled(r.max, s, False, _POS) for r in z.regions], dtype=np.int64)
            if z.forbid:
                mins = np.array([_scaled(r.min, s, False, _NEG) for r in z.regions], dtype=np.int64)
                maxs = np.array([_scaled(r.max, s, True, _POS) for r in z.regions], dtype=np.int64)
                lo_i = np.maximum(np.minimum(i0c, i1c) - 1, 0)
                hi_i = np.minimum(i1c + 1, len(ups_dn) - 1)
                below = l1 <= _RangeTable(mins, np.minimum).query(lo_i, hi_i)
                above = l0 >= _RangeTable(maxs, np.maximum).query(lo_i, hi_i)
                outside = (r1 <= _scaled(z.start, s, False, _NEG)) | (r0 >= ups_up[-1])
                ok &= below | above | outside
            else:
                inside = (r0 >= _scaled(z.start, s, True, _NEG)) & (r1 <= ups_dn[-1]) & (i1 < len(ups_dn))
                hi_i = np.minimum(i1c + 1, len(ups_dn) - 1)  # a rounded boundary may reach one more row
                need_lo = _RangeTable(mins_lo, np.maximum).query(i0c, hi_i)
                need_hi = _RangeTable(maxs_hi, np.minimum).query(i0c, hi_i)
                ok &= inside & (l0 >= need_lo) & (l1 <= need_hi)
        elif isinstance(z, PolygonZone):
            if not z.forbid:
                ok[:] = False
                break
            b = z.bounds()
            clear = np.zeros(n, dtype=bool)
            for a, (bl, bh) in b.items():
                if a not in axes:
                    continue
                r0, r1 = rng(a)
                if bh is not None:
                    clear |= r0 >= _scaled(bh, s, True, _POS)
                if bl is not None:
                    clear |= r1 <= _scaled(bl, s, False, _NEG)
            ok &= clear
    return np.flatnonzero(~ok).tolist()
