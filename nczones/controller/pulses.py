"""Pulse distribution: exact integer interpolation of one motion.

Positions are integer **pulse counts** per axis (one pulse = ``Axis.pulse``
mm, or degrees on a rotary axis).  Every function here is pure integer (or
exact rational) arithmetic; floats appear only in the *timing* helpers, which
decide when a pulse happens, never where.

Rounding of end points
----------------------
A segment's exact end point ``q`` (a rational, in mm) becomes the pulse count
``round_pulse(q, u) = floor(q / u + 1/2)``: the nearest pulse, ties towards
+infinity.  That rule is translation invariant (shifting a program by a whole
number of pulses shifts every pulse position by the same count), and because
consecutive segments share their end/start point exactly, the rounded targets
chain: the pulses of a whole program sum to ``round(end) - round(start)`` on
every axis, whatever happens in between.

Invariants
----------
* **Linear** (:func:`line_position`, :func:`line_steps`, :func:`line_chunk`):
  ``N = max |D_k|`` steps; after step ``i`` axis ``k`` stands at
  ``P0_k + floor(i D_k / N + 1/2)``.  Each step moves every axis by 0 or ±1
  pulse (the major axis always by one), step ``N`` is exactly ``P1``, and
  every position is within 1/2 pulse of the integer line ``P0 → P1``, which is
  itself within 1/2 pulse of the exact line (both end points are).  So the
  commanded position is within one pulse of the exact path on every axis.
* **Circular** (:func:`arc_walk`): a lattice walk around the exact rational
  centre in the counter-clockwise sense (clockwise arcs are mirrored): the
  axis with the larger tangent component steps one pulse, the other steps
  -1, 0 or +1, whichever leaves the smallest ``|distance² - R²|`` (exact
  integers).  The walk tracks quadrant crossings to count the swept angle
  (``turns`` extra turns included) and stops before it would cross the exact
  end ray for the last time; a short linear approach then lands exactly on
  the rounded end point.  Full circles therefore close exactly.  Axes outside
  the plane (helix) follow the swept angle, rounded to the nearest pulse; on
  a steep helix their pulses are interleaved (:func:`helix_steps`) so that no
  step moves any axis by more than one pulse.
  :mod:`nczones.controller.arcs` computes the identical walk vectorized.
* **Dogleg rapid** (:func:`dogleg_steps`): every axis starts at once and
  steps at its own constant pulse period (its rapid rate); pulses are merged
  in exact time order, so each axis reaches its own end exactly.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidArgument

__all__ = [
    "round_pulse",
    "line_position",
    "line_steps",
    "line_chunk",
    "arc_centre",
    "ArcWalk",
    "arc_walk",
    "dogleg_steps",
    "helix_steps",
    "helix_chunk",
    "LINE_CHUNK",
    "step_deltas",
]

#: Steps per numpy chunk when a long line is processed or a plan is monitored vectorized: small enough that a
#: chunk's positions and the monitor's temporaries stay in the core's cache (measured: 2**15 runs long lines
#: 2-3 times as fast as 2**18, whose temporaries stream through memory).
LINE_CHUNK = 1 << 15


def round_pulse(q: Fraction, pulse: Fraction) -> int:
    """The pulse count nearest to ``q`` (mm or deg); ties go towards +infinity.

    >>> F = Fraction
    >>> round_pulse(F("1.0004"), F("0.001")), round_pulse(F("1.0005"), F("0.001"))
    (1000, 1001)
    >>> round_pulse(F("-1.0005"), F("0.001"))
    -1000
    """
    x = Fraction(q) / pulse
    return (2 * x.numerator + x.denominator) // (2 * x.denominator)


# --------------------------------------------------------------------------- lines


def line_position(p0: Sequence[int], delta: Sequence[int], n: int, i: int) -> tuple[int, ...]:
    """Position after step ``i`` of the line ``p0 → p0 + delta`` (``n = max |delta|``).

    >>> line_position((0, 0), (5, 2), 5, 2)
    (2, 1)
    """
    if n == 0:
        return tuple(p0)
    return tuple(p + (2 * i * d + n) // (2 * n) for p, d in zip(p0, delta))


def line_steps(p0: Sequence[int], p1: Sequence[int]) -> Iterator[tuple[int, ...]]:
    """Positions after each step of the linear interpolation ``p0 → p1`` (reference loop).

    This is the readable form: one step per iteration, pure integers.

    >>> list(line_steps((0, 0, 0), (3, -1, 2)))
    [(1, 0, 1), (2, -1, 1), (3, -1, 2)]
    """
    delta = tuple(b - a for a, b in zip(p0, p1))
    n = max((abs(d) for d in delta), default=0)
    two_n = 2 * n
    for i in range(1, n + 1):
        yield tuple(p + (2 * i * d + n) // two_n for p, d in zip(p0, delta))


def line_chunk(p0: Sequence[int], delta: Sequence[int], n: int, lo: int, hi: int) -> np.ndarray:
    """Positions after steps ``lo+1 .. hi`` as an ``(hi - lo, axes)`` int64 array.

    The same formula as :func:`line_steps`, vectorized (the major axis, where
    ``|delta| == n``, is ``p ± i`` exactly; a standing axis stays at ``p``).  Raises
    :class:`~nczones.errors.InvalidArgument` if ``2 n max|delta|`` would not fit
    in int64 (the caller then uses the Python loop).

    >>> line_chunk((0, 0), (5, 2), 5, 0, 5).tolist()
    [[1, 0], [2, 1], [3, 1], [4, 2], [5, 2]]
    """
    big = 2 * n * max((abs(d) for d in delta), default=0) + n
    if big >= 2**62 or any(abs(p) >= 2**62 for p in p0):
        raise InvalidArgument("line too long for int64 vectorization")
    out = np.empty((hi - lo, len(delta)), dtype=np.int64)
    for k, (p, d) in enumerate(zip(p0, delta)):
        if d == 0:
            out[:, k] = p
        elif abs(d) == n:  # (2 d i + n) // 2n == i * sign(d): the major axis moves every step
            out[:, k] = (np.arange(p + lo + 1, p + hi + 1, dtype=np.int64) if d > 0
                           else np.arange(p - lo - 1, p - hi - 1, -1, dtype=np.int64))
        else:  # 2 d i + n for i = lo+1 .. hi, then floored by 2n in place (no temporaries)
            t = np.arange(2 * d * (lo + 1) + n, 2 * d * hi + n + (1 if d > 0 else -1), 2 * d, dtype=np.int64)
            t //= 2 * n
            t += p
            out[:, k] = t
    return out


# --------------------------------------------------------------------------- arcs


def _isqrt_fraction(q: Fraction, bits: int) -> tuple[Fraction, Fraction]:
    """A rational enclosure ``lo <= sqrt(q) <= hi`` with ``hi - lo <= 2**-bits``."""
    scale = 1 << bits
    # sqrt(q) * scale = sqrt(num * scale**2 / den) ; floor via isqrt of num*scale^2*den / den^2
    n = q.numerator * scale * scale * q.denominator
    r = math.isqrt(n)
    lo = Fraction(r, q.denominator * scale)
    hi = Fraction(r + 1, q.denominator * scale)
    return lo, hi


def arc_centre(
    start: tuple[Fraction, Fraction], end: tuple[Fraction, Fraction], radius: Fraction, clockwise: bool,
    *, bits: int = 64,
) -> tuple[tuple[Fraction, Fraction], Fraction]:
    """A rational centre for an R-format arc, and a bound on its error (mm).

    The exact centre lies at distance ``|R|`` from both points, to the right
    of the chord ``start → end`` for G2 with R > 0 (left for G3; a negative R
    takes the other side, the arc of more than 180°).  It is
    ``M + t * perp`` with ``t = sqrt(R²/|w|² - 1/4)``, irrational in general;
    ``t`` is enclosed in an interval of width ``2**-bits`` and the lower end
    used, so the returned centre is within ``error`` of the exact one.

    >>> F = Fraction
    >>> c, err = arc_centre((F(0), F(0)), (F(10), F(0)), F(5), True)
    >>> c, err
    ((Fraction(5, 1), Fraction(0, 1)), Fraction(0, 1))
    >>> c, err = arc_centre((F(0), F(0)), (F(2), F(0)), F(-2), False)
    >>> float(c[1]) < 0 and err < F(1, 10**12)
    True
    """
    wx, wy = end[0] - start[0], end[1] - start[1]
    l2 = wx * wx + wy * wy
    if l2 == 0:
        raise InvalidArgument("R-format arc with start == end has no defined centre")
    r = abs(radius)
    disc = r * r / l2 - Fraction(1, 4)
    if disc < 0:
        # the chord is longer than the diameter; the interpreter accepts this only
        # within a tolerance, then the centre is the chord's midpoint
        disc = Fraction(0)
    lo, hi = _isqrt_fraction(disc, bits)
    if lo * lo == disc:
        hi = lo
    # right of the chord: (wy, -wx)
    right = (clockwise and radius > 0) or (not clockwise and radius < 0)
    px, py = (wy, -wx) if right else (-wy, wx)
    mx, my = (start[0] + end[0]) / 2, (start[1] + end[1]) / 2
    centre = (mx + lo * px, my + lo * py)
    error = (hi - lo) * max(abs(px), abs(py))
    return centre, error


def quadrant_of(u: int, v: int) -> int:
    if u > 0 and v >= 0:
        return 0
    if u <= 0 and v > 0:
        return 1
    if u < 0 and v <= 0:
        return 2
    return 3


def _lcm(*values: int) -> int:
    out = 1
    for v in values:
        out = out * v // math.gcd(out, v)
    return out


@dataclass(frozen=True, slots=True)
class ArcWalk:
    """The planar pulse positions of an arc and its exact sweep data.

    ``points`` are (first, second) pulse positions after each step (the last
    one is the rounded end point); ``sweep_rad`` is the ideal swept angle (a
    float, for timing and helix axes only); ``radius_mm`` is the start radius
    (float, timing only).
    """

    points: tuple[tuple[int, int], ...]
    sweep_rad: float
    radius_mm: float
    walk_steps: int  # steps taken by the circle walk before the final approach


@dataclass(frozen=True, slots=True)
class ArcFrame:
    """An arc in exact integer units of ``1/scale`` mm, mirrored to counter-clockwise.

    ``u = x * ai - cx`` and ``v = y * aj - cy`` are the offsets of the pulse
    position ``(x, y)`` (``y`` mirrored for clockwise arcs) from the centre;
    ``q`` is the squared start radius; ``qcount`` counts quadrant crossings
    of the current position (``qe`` is the count at the end ray).
    """

    sj: int
    ai: int
    aj: int
    cx: int
    cy: int
    eu: int
    ev: int
    q: int
    radius_mm: float
    sweep: float
    x: int
    y: int
    u: int
    v: int
    qcount: int
    qe: int
    tiny: bool  # a circle smaller than two pulses: no walk, only the approach

    def past_end(self, uu: int, vv: int, qq: int) -> bool:
        """Would the position ``(uu, vv)`` with quadrant count ``qq`` lie past the end ray?"""
        return qq > self.qe or (qq == self.qe and self.eu * vv - self.ev * uu >= 0)

    def limit(self, turns: int) -> int:
        """A generous bound on the number of walk steps (reaching it is a bug)."""
        rq = math.isqrt(self.q) + 1
        return 8 * (rq // self.ai + rq // self.aj + 4) * (turns + 2) + 64


def arc_frame(start_pulse: Sequence[int], end_pulse: Sequence[int], start: Sequence[Fraction],
               end: Sequence[Fraction], centre: Sequence[Fraction], clockwise: bool, turns: int,
               pulse: Sequence[Fraction]) -> ArcFrame:
    sj = -1 if clockwise else 1  # mirror the second axis: a clockwise arc becomes counter-clockwise
    ui, uj = pulse
    scale = _lcm(
        ui.denominator, uj.denominator, centre[0].denominator, centre[1].denominator,
        start[0].denominator, start[1].denominator, end[0].denominator, end[1].denominator,
    )
    ai, aj = int(ui * scale), int(uj * scale)  # one pulse in units of 1/scale mm
    cx, cy = int(centre[0] * scale), sj * int(centre[1] * scale)
    su, sv = int(start[0] * scale) - cx, sj * int(start[1] * scale) - cy
    eu, ev = int(end[0] * scale) - cx, sj * int(end[1] * scale) - cy
    q = su * su + sv * sv  # R² of the exact start (scaled)
    radius_mm = math.sqrt(q) / scale
    ang_s, ang_e = math.atan2(sv, su), math.atan2(ev, eu)
    sweep = (ang_e - ang_s) % (2 * math.pi)
    full = eu * sv - ev * su == 0 and eu * su + ev * sv > 0
    if full or sweep == 0:
        sweep = 2 * math.pi
    sweep += 2 * math.pi * turns
    x, y = start_pulse[0], sj * start_pulse[1]
    tiny = q == 0 or radius_mm < 2 * float(max(ui, uj))
    qs = quadrant_of(su, sv)
    qe_rel = (quadrant_of(eu, ev) - qs) % 4
    if qe_rel == 0:
        cr = su * ev - sv * eu
        if cr < 0 or (cr == 0 and su * eu + sv * ev > 0):
            qe_rel = 4
    qe = qs + qe_rel + 4 * turns
    u, v = x * ai - cx, y * aj - cy
    delta = (quadrant_of(u, v) - qs) % 4
    qcount = qs + (delta if delta <= 1 else delta - 4)
    return ArcFrame(sj, ai, aj, cx, cy, eu, ev, q, radius_mm, sweep, x, y, u, v, qcount, qe, tiny)


def arc_step(u: int, v: int, q: int, ai: int, aj: int) -> tuple[int, int, int, int]:
    """One step of the counter-clockwise lattice walk from offset ``(u, v)``: ``(dx, dy, nu, nv)``.

    The axis with the larger tangent component steps one pulse; the other
    steps 0, then forwards, then backwards — the first of those with the
    smallest ``|nu² + nv² - q|`` wins.
    """
    if abs(v) * aj >= abs(u) * ai:  # tangent (-v, u): x is the major axis
        dx = -1 if v > 0 else 1
        nu = u + dx * ai
        best = None
        for dy in (0, 1 if u > 0 else -1, -1 if u > 0 else 1):
            nv = v + dy * aj
            f = abs(nu * nu + nv * nv - q)
            if best is None or f < best[0]:
                best = (f, dx, dy, nu, nv)
    else:
        dy = 1 if u > 0 else -1
        nv = v + dy * aj
        best = None
        for dx in (0, -1 if v > 0 else 1, 1 if v > 0 else -1):
            nu = u + dx * ai
            f = abs(nu * nu + nv * nv - q)
            if best is None or f < best[0]:
                best = (f, dx, dy, nu, nv)
    assert best is not None  # three candidates were tried
    return best[1], best[2], best[3], best[4]


def arc_walk(
    start_pulse: tuple[int, int],
    end_pulse: tuple[int, int],
    start: tuple[Fraction, Fraction],
    end: tuple[Fraction, Fraction],
    centre: tuple[Fraction, Fraction],
    clockwise: bool,
    turns: int,
    pulse: tuple[Fraction, Fraction],
) -> ArcWalk:
    """Circular interpolation in the (first, second) plane of an arc (the per-step reference).

    ``start_pulse``/``end_pulse`` are where the controller stands and the
    rounded end; ``start``, ``end`` and ``centre`` are the exact points in mm.
    Returns the positions after each step; see the module docstring for the
    invariants (within one pulse of the exact arc per axis, exact close).
    :func:`nczones.controller.arcs.arc_path` computes the same positions
    vectorized.

    >>> F = Fraction
    >>> w = arc_walk((10, 0), (10, 0), (F(10), F(0)), (F(10), F(0)), (F(0), F(0)), False, 0, (F(1), F(1)))
    >>> w.points[-1], len(set(w.points)) == len(w.points)
    ((10, 0), True)
    >>> max(abs(x) for x, _ in w.points), max(abs(y) for _, y in w.points)
    (10, 10)
    """
    fr = arc_frame(start_pulse, end_pulse, start, end, centre, clockwise, turns, pulse)
    ex, ey = end_pulse
    points: list[tuple[int, int]] = []
    if fr.tiny:
        # a circle smaller than two pulses: only the end point can be commanded meaningfully
        points.extend(plane_line((start_pulse[0], start_pulse[1]), (ex, ey)))
        return ArcWalk(tuple(points), fr.sweep, fr.radius_mm, 0)
    x, y, u, v, qcount, sj = fr.x, fr.y, fr.u, fr.v, fr.qcount, fr.sj
    walk = 0
    if not fr.past_end(u, v, qcount):
        limit = fr.limit(turns)
        while walk < limit:
            dx, dy, nu, nv = arc_step(u, v, fr.q, fr.ai, fr.aj)
            nq = quadrant_of(nu, nv)
            nqcount = qcount + ((nq - qcount) % 4)
            if fr.past_end(nu, nv, nqcount):
                break
            x, y, u, v, qcount = x + dx, y + dy, nu, nv, nqcount
            points.append((x, sj * y))
            walk += 1
        else:  # pragma: no cover - the limit is generous; reaching it is a bug
            raise InvalidArgument("arc walk did not reach its end")
    last = points[-1] if points else (start_pulse[0], start_pulse[1])
    points.extend(plane_line(last, (ex, ey)))
    return ArcWalk(tuple(points), fr.sweep, fr.radius_mm, walk)


def plane_line(a: tuple[int, int], b: tuple[int, int]) -> list[tuple[int, int]]:
    return [(p[0], p[1]) for p in line_steps(a, b)]


def helix_steps(pos: Sequence[Sequence[int]], p0: Sequence[int], helix_axes: Sequence[int]) -> list[tuple[int, ...]]:
    """Interleave helix-axis pulses so that no step moves any axis by more than one pulse (reference loop).

    ``pos`` are the positions after each planar arc step, with the helix axes
    already at their rounded targets.  On a steep helix a helix axis jumps by
    ``m > 1`` pulses between two planar steps; that step becomes ``L = max |m|``
    sub-steps: the helix axes follow the line ``prev -> next`` rounded
    (:func:`line_position`), the plane moves at sub-step ``(L + 1) // 2`` (the
    middle, so each intermediate helix value stands next to the nearer of the
    two planar positions).  Steps with ``L <= 1`` are unchanged.

    >>> helix_steps([(1, 0, 3), (2, 1, 4)], (0, 0, 0), (2,))
    [(0, 0, 1), (1, 0, 2), (1, 0, 3), (2, 1, 4)]
    """
    out: list[tuple[int, ...]] = []
    prev = tuple(p0)
    for row in pos:
        row = tuple(int(c) for c in row)
        m = [row[h] - prev[h] for h in helix_axes]
        big = max((abs(d) for d in m), default=0)
        if big > 1:
            mid = (big + 1) // 2
            for s in range(1, big):
                sub = list(row if s >= mid else prev)
                for h, d in zip(helix_axes, m):
                    sub[h] = prev[h] + (2 * s * d + big) // (2 * big)
                out.append(tuple(sub))
        out.append(row)
        prev = row
    return out


def step_deltas(col: np.ndarray, prev: Any) -> np.ndarray:
    """The moves of one axis in each step: ``np.diff(col, prepend=prev)`` without copying ``col`` first.

    >>> step_deltas(np.array([3, 4, 4, 2]), 1).tolist()
    [2, 1, 0, -2]
    """
    d = np.empty(len(col), dtype=np.int64)
    if len(col):
        d[0] = col[0] - prev
        np.subtract(col[1:], col[:-1], out=d[1:])
    return d


def _jumps(pos: np.ndarray, p0: Sequence[int], axes: Sequence[int], chunk: int = 1 << 16) -> bool:
    """Does any of ``axes`` move by more than one pulse in a step (checked in cache-sized chunks)?"""
    for h in axes:
        prev = np.int64(p0[h])
        for lo in range(0, len(pos), chunk):
            d = step_deltas(pos[lo:lo + chunk, h], prev)
            if int(d.max()) > 1 or int(d.min()) < -1:
                return True
            prev = pos[min(lo + chunk, len(pos)) - 1, h]
    return False


def helix_chunk(pos: np.ndarray, p0: Sequence[int], helix_axes: Sequence[int]) -> np.ndarray:
    """:func:`helix_steps` vectorized (identical rows, int64 ``(steps, axes)``).

    >>> helix_chunk(np.array([(1, 0, 3), (2, 1, 4)]), (0, 0, 0), (2,)).tolist()
    [[0, 0, 1], [1, 0, 2], [1, 0, 3], [2, 1, 4]]
    """
    pos = np.asarray(pos, dtype=np.int64)
    if not len(pos) or not helix_axes:
        return pos
    if not _jumps(pos, p0, helix_axes):
        return pos  # no helix axis jumps: nothing to interleave
    rows = np.vstack([np.asarray(p0, dtype=np.int64).reshape(1, -1), pos])
    jumps = np.diff(rows[:, list(helix_axes)], axis=0)
    big = np.abs(jumps).max(axis=1)
    if big.max() <= 1:
        return pos
    length = np.maximum(big, 1)
    src = np.repeat(np.arange(len(pos)), length)  # the planar step each sub-step belongs to
    ends = np.cumsum(length)
    s = np.arange(len(src)) - np.repeat(ends - length, length) + 1  # sub-step 1..L within its step
    L = length[src]
    prev = rows[src]
    out = np.where((s >= (L + 1) // 2)[:, None], pos[src], prev)
    for c, h in enumerate(helix_axes):
        d = jumps[src, c]
        out[:, h] = prev[:, h] + (2 * s * d + L) // (2 * L)
    return out


# --------------------------------------------------------------------------- dogleg rapids


def dogleg_steps(
    p0: Sequence[int], p1: Sequence[int], period_s: Sequence[Fraction]
) -> tuple[np.ndarray, np.ndarray, int]:
    """Dogleg rapid: each axis at its own pulse period, all starting together.

    Axis ``k`` issues its ``j``-th pulse at exact time ``j * period_s[k]``;
    pulses due at the same instant form one step.  Returns the positions after
    each step (``(steps, axes)`` int64) and the exact step times as integer
    ticks with their denominator (time = ticks / den seconds).

    >>> pos, ticks, den = dogleg_steps((0, 0), (3, -1), (Fraction(1), Fraction(2)))
    >>> pos.tolist(), [str(Fraction(int(t), den)) for t in ticks]
    ([[1, 0], [2, -1], [3, -1]], ['1', '2', '3'])
    """
    delta = [b - a for a, b in zip(p0, p1)]
    k = len(delta)
    den = _lcm(*(Fraction(p).denominator for p in period_s))
    ticks = [int(Fraction(p) * den) for p in period_s]  # integer period per axis
    times: list[np.ndarray] = []
    axes: list[np.ndarray] = []
    for a, d in enumerate(delta):
        if d:
            j = np.arange(1, abs(d) + 1, dtype=np.int64)
            times.append(j * ticks[a])
            axes.append(np.full(abs(d), a, dtype=np.int64))
    if not times:
        return np.zeros((0, k), dtype=np.int64), np.zeros(0, dtype=np.int64), den
    t_all = np.concatenate(times)
    a_all = np.concatenate(axes)
    order = np.argsort(t_all, kind="stable")
    t_all, a_all = t_all[order], a_all[order]
    uniq, first = np.unique(t_all, return_index=True)
    step_of_pulse = np.searchsorted(uniq, t_all)
    inc = np.zeros((len(uniq), k), dtype=np.int64)
    sign = np.array([1 if d > 0 else -1 for d in delta], dtype=np.int64)
    np.add.at(inc, (step_of_pulse, a_all), sign[a_all])
    pos = np.cumsum(inc, axis=0) + np.asarray(p0, dtype=np.int64)
    return pos, uniq, den
