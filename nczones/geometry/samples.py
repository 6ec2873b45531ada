"""Float samples of exactly defined paths, for plots and for replaying a report's points.

Floats are for pictures and approximate distances only: the prover and the controller never read
these.  The exact geometry lives in :mod:`nczones.geometry.polar` and the other curve modules.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..motion import Segment
from .polar import polar_move_of, polar_of

__all__ = ["polar_float_points"]

F0 = Fraction(0)
F1 = Fraction(1)


def polar_float_points(seg: Segment, samples: int = 48, lo: Fraction = F0, hi: Fraction = F1,
                       theta_lo: float | None = None) -> list[tuple[float, ...]]:
    """Float samples of a polar move in machine coordinates at ``samples + 1`` fractions from ``lo`` to ``hi``.

    For plots and approximate checks.  The plane points are the exact enclosures' middles; X and C are
    converted in floats, C unwound from the start angle (or from ``theta_lo``, the unwound angle at ``lo``).
    """
    move = polar_move_of(seg)
    e = polar_of(seg)
    assert e is not None
    ix, ic = seg.axes.index(e.linear_axis), seg.axes.index(e.rotary_axis)
    theta = float(move.start_angle().mid()) if theta_lo is None else theta_lo
    out = []
    for k in range(samples + 1):
        f = lo + (hi - lo) * Fraction(k, samples)
        x, y = (float(v.mid()) for v in move.point(f))
        a = math.degrees(math.atan2(y, x))
        theta = a + 360.0 * round((theta - a) / 360.0)
        p = [float(a0 + (b0 - a0) * f) for a0, b0 in zip(seg.start, seg.end)]
        p[ix] = float(move.x_off) + math.hypot(x, y)
        p[ic] = float(move.c_entry) + theta
        out.append(tuple(p))
    return out
