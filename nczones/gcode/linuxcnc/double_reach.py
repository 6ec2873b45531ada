"""How far a blended corner can leave the box of the double pass's motions around it: the bound that proves the
corners inside a box with arcs (:meth:`~nczones.gcode.linuxcnc.doubles.DoublePath.reach`, used by
:mod:`nczones.prover.doubles`).

Why the bound holds
-------------------
Without a tolerance (G64) a rounded corner at the point ``C`` where motion ``i`` ends and motion ``j`` begins
lies in ``{x + y - C}``, ``x`` in the box of (a part of) motion ``i`` and ``y`` in that of motion ``j``
(``specs/path-modes.md``, "The enclosure without tolerance"; an arc's part is within its whole box).  When both
motions lie in the box ``[lo, hi]`` (of motions ``first``..``last``), on each axis ``x + y - C <= hi + (y - C)
<= hi + w_j`` and ``<= hi + (x - C) <= hi + w_i``, ``w`` a motion's width there (``C`` is a point of both
motions), and likewise below ``lo``: the corner lies in the box grown by ``min(w_i, w_j)``.  Normally ``j = i +
1``, and the largest ``min(w_k, w_(k+1))`` over the box's neighbouring motions grows it enough for every corner
inside it, however long the box (the growth by the box's own size, ``[2 lo - hi, 2 hi - lo]``, is the case of
widths ``hi - lo``: a CAM program of 4,000 mm of small side arcs split in some 1,500 boxes under it).

LinuxCNC drops a motion shorter than :data:`~nczones.motion.DROPPED_BELOW` (its canon, its planner): the corner
is then between the motion ``i`` before a run of dropped ones and the motion ``j`` after it, which runs from
``C``, the end of ``i`` (``prover/blend.py``, ``CornerCheck._dropped_corner``): its width is at most ``w_j``
plus the run's (each dropped motion moves less than ``DROPPED_BELOW`` on every axis).  A motion whose rows'
doubles differ on every axis by less than ``DROPPED_BELOW`` plus twice their error (:func:`_limit`) may be
one (each row is within its error of the full path's exact one); with ``t`` of them in the box, every width
grows by ``t DROPPED_BELOW``, and when one of them lies between two others (``j`` need not follow ``i``) the
bound takes the widest motion of the box instead of the neighbours' least.  A run at either end of the box
joins none of its motions to another of them (the corner between boxes is proved on its own; the motion after
a run at the box's start runs from a point before the box, and its corner with the next is taken with it as
programmed, as the full path takes it).

The widths: a straight motion (G0, G1, a cycle's, a dwell's) moves each axis monotonically between its exact
ends, each within ``e`` of its row's double, so its width is at most ``|d_k - d_(k-1)| + 2 e``; a float
difference is within half an ulp of the exact one (``|d| (1 + 2**-52)`` is above it).  ``e`` here
(:func:`row_error`) is the module's bound of :class:`~nczones.gcode.linuxcnc.doubles.DoublePath` computed with
``4 (top + offset) + 1`` ulps for its ``4 (top + offset) + 2**-8`` (``top`` the largest magnitude of the box's
doubles, the start's double included: a row before an axis first moves is the exact start, within half an ulp
of its double) plus the G91 chains' bound ``inc_bound``: above it.  An arc's box (:mod:`.double_arcs`, the
quick screen's or the sweep's) holds the full path's exact arc on its plane's two axes: its width there, a
float difference times the same factor, bounds the arc's (a helix's third axis moves monotonically, as a
straight motion's).  Each plane axis takes the widest arc of the box, whatever its plane (a superset: no
plane slot is read), as the width of every arc: ``min(w_i, w_j)`` is at most it when either is an arc.
"""

from __future__ import annotations

import math
from fractions import Fraction
from heapq import nlargest
from operator import sub

from ...motion import DROPPED_BELOW

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["reach", "row_error"]

_ULP = Fraction(1, 2**52)
#: ``1 + 2**-52``: a float difference times this is above the exact difference of the doubles.
_UP = 1 + _ULP
#: :func:`_neighbours` looks at the pairs among this many largest steps.
_FEW = 32


def row_error(top: float, offset: Fraction, inc: float) -> Fraction:
    """A bound (exact, at or above :class:`~nczones.gcode.linuxcnc.doubles.DoublePath`'s widening) of the
    distance of a row's double from the full path's exact coordinate, for rows whose doubles are at most ``top``
    in magnitude, computed with work offsets up to ``offset``, on G91 chains within ``inc`` (0.0: none)."""
    return (4 * (Fraction(top) + offset) + 1) * _ULP + Fraction(inc)


def reach(path: Any, first: int, last: int, names: Any = None) -> dict[str, Fraction] | None:
    """Per axis (of ``names``, default all), an exact bound of how far a blended corner between two of motions
    ``first``..``last`` (rows ``first - 1``..``last`` of ``path``, a
    :class:`~nczones.gcode.linuxcnc.doubles.DoublePath`, ``first > row0``, ``last > first``) can leave their box,
    or None when a double is not finite (the module's docstring says why the bound holds).

    >>> from array import array
    >>> from nczones.gcode.linuxcnc.doubles import DoublePath
    >>> cols = (array("d", [0.0, 1.0, 3.0, 3.5]), array("d", [0.0, 0.0, 0.0, 2.0]))
    >>> p = DoublePath(("X", "Y"), cols, (Fraction(0),) * 2, 3, 3, 0, 3, (Fraction(0),) * 2, (1, 3))
    >>> g = reach(p, 1, 3)  # the corners: min(1, 2) on X, min(0, 2) on Y
    >>> 1 <= g["X"] < 1 + Fraction(1, 10**12), 0 < g["Y"] < Fraction(1, 10**12)
    (True, True)
    >>> cols[0][2] = 1.0 + 1e-9  # motion 2 moves 1e-9 on X and nothing on Y: LinuxCNC may drop it
    >>> g = reach(p, 1, 3)  # between two others: the widest motions (2.5, 2) and the dropped one's 3e-7
    >>> 2.5 < g["X"] < 2.5 + Fraction(31, 10**8), 2 < g["Y"] < 2 + Fraction(31, 10**8)
    (True, True)
    """
    b, e = first - 1 - path.row0, last + 1 - path.row0
    axes = range(len(path.axes)) if names is None else [path.axes.index(x) for x in names]
    rows: dict[int, tuple[Any, list[float], Fraction]] = {}
    flags = _flags(path, b, e, rows)
    inner, extra = _inner(flags), flags.count(1) * DROPPED_BELOW
    plane = set(path.arc_axes)
    arc = _widest_arc(path, first, last) if plane.intersection(axes) else Fraction(0)
    if arc is None:
        return None
    out = {}
    for a in axes:
        _part, steps, err = _rows(path, a, b, e, rows)
        most = max(steps) if inner else _neighbours(steps)
        if not math.isfinite(most):
            return None
        g = Fraction(most) * _UP + 2 * err
        out[path.axes[a]] = (max(g, arc) if a in plane else g) + extra
    return out


def _rows(path: Any, a: int, b: int, e: int, done: dict) -> tuple[Any, list[float], Fraction]:
    """Axis ``a``'s rows ``b``..``e - 1`` (indices of the columns held), their steps' magnitudes (float
    differences) and :func:`row_error` (kept in ``done``: each axis scanned once a call)."""
    got = done.get(a)
    if got is None:
        part = path.columns[a][b:e]
        top = max(max(part), -min(part))
        got = done[a] = (part, list(map(abs, map(sub, part[1:], part[:-1]))), _error(path, a, top))
    return got


def _error(path: Any, a: int, top: float) -> Fraction:
    """:func:`row_error` of rows of axis ``a`` at most ``top`` in magnitude."""
    return row_error(top, path.offset_bound[a], path.inc_bound[a] if path.inc_bound else 0.0)


def _flags(path: Any, b: int, e: int, done: dict) -> bytes:
    """A byte per motion ending at rows ``b + 1``..``e - 1`` (indices of the columns held): 1 when it may be one
    LinuxCNC drops (on every axis its rows' doubles differ by less than :func:`_limit` of their error), else 0.
    The first axis's test picks the candidates; the others are tested at those alone while they are few (with
    the error of those two rows), else scanned (:func:`_rows`)."""
    _part, steps, err = _rows(path, 0, b, e, done)
    flags = bytearray(map(_limit(err).__gt__, steps))
    if 1 not in flags:
        return bytes(flags)
    if flags.count(1) > _FEW:  # (a byte's 0 or 1 is its bit 8 k of the little-endian number: one AND an axis)
        n, both = len(flags), int.from_bytes(flags, "little")
        for a in range(1, len(path.columns)):
            _part, steps, err = _rows(path, a, b, e, done)
            both &= int.from_bytes(bytes(map(_limit(err).__gt__, steps)), "little")
        return both.to_bytes(n, "little")
    for k in [k for k in range(len(flags)) if flags[k]]:
        for a, col in enumerate(path.columns):
            c0, c1 = col[b + k], col[b + k + 1]
            if not abs(c1 - c0) < _limit(_error(path, a, max(abs(c0), abs(c1)))):
                flags[k] = 0
                break
    return bytes(flags)


def _neighbours(steps: list[float]) -> float:
    """At or above ``max(min(s[k], s[k + 1]))`` over the neighbours of ``steps`` (one or more, not nan): the
    :data:`_FEW` largest taken at once, their least ``t`` is above every pair with a step ``t`` or below, and a
    pair of two above it is looked at (fewer than ``_FEW``)."""
    if len(steps) < 2:
        return steps[0]
    t = nlargest(_FEW, steps)[-1]
    above = bytes(map(t.__lt__, steps))
    most, at = t, above.find(b"\x01\x01")
    while at >= 0:
        most = max(most, min(steps[at], steps[at + 1]))
        at = above.find(b"\x01\x01", at + 1)
    return most


def _limit(err: Fraction) -> float:
    """Above ``|d_k - d_(k-1)|`` (a float difference) of a motion LinuxCNC may drop whose rows are within ``err``."""
    return float(DROPPED_BELOW + 2 * err) * (1 + 1e-9)


def _inner(flags: bytes) -> bool:
    """Is a motion that may be dropped (a byte 1 of ``flags``, one a motion) between two that may not, or may
    every one be dropped?  (A run at either end of the box joins no two of its motions.)"""
    if 1 not in flags:
        return False
    low, high = flags.find(0), flags.rfind(0)
    return low < 0 or 1 in flags[low:high]


def _widest_arc(path: Any, first: int, last: int) -> Fraction | None:
    """The widest box on either plane axis of the arcs among motions ``first``..``last`` (exact, above the doubles'
    difference), 0 without arcs, or None when a box is not finite."""
    rows, boxes = path.arc_rows, path.arc_boxes
    if not rows:
        return Fraction(0)
    from bisect import bisect_left, bisect_right

    begin, end = bisect_left(rows, first), bisect_right(rows, last)
    if begin >= end:
        return Fraction(0)
    widths = [list(map(sub, boxes[4 * begin + 2 * k + 1:4 * end:4], boxes[4 * begin + 2 * k:4 * end:4]))
              for k in (0, 1)]
    if not math.isfinite(sum(widths[0]) + sum(widths[1])):  # (a nan or inf anywhere makes the sum one)
        return None
    return Fraction(max(max(widths[0]), max(widths[1]))) * _UP
