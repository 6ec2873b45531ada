"""Vectorized circular interpolation: the lattice walk of :func:`.pulses.arc_walk`, in numpy.

:func:`arc_path` returns **exactly** the positions of the reference walk
(same points, same order); it is the reference walk computed by
*speculate and verify*:

1. From the current (exact) walk state, the walk is in one of four quarter
   regions (x major at the top and bottom, y major left and right; see
   :func:`.pulses._arc_step`).  There the major axis steps one pulse every
   step and the minor axis is a function of it: the lattice point nearest the
   circle.  A whole stretch of *candidate* positions up to the estimated end
   of the region is computed at once from ``sqrt`` in floats.  Candidates
   are guesses; nothing about them is trusted.
2. Every candidate step is checked against the exact step rule, applied to
   the candidate's predecessor: the same major-axis test, the same three
   residuals ``|nu² + nv² - q|`` in the same order with the same strict
   comparison, the same quadrant counting and end-ray test.  This runs in
   int64 when an explicit bound shows that no product can overflow, else on
   Python integers (numpy object arrays).  Both are exact.
3. The candidates up to the first disagreement are the reference walk's
   positions (the walk is deterministic, and each of those steps is the one
   the rule takes from the previous, already-verified position).  At a
   disagreement one exact reference step is taken in Python, and the loop
   resumes from there.

Invariant: the positions returned equal ``arc_walk(...).points`` for every
input; only the time taken depends on how good the guesses are (a handful of
disagreements per quarter: region boundaries and rounding ties).  Tests
compare both on random arcs in all planes, directions and turn counts,
including R-format centres whose rational enclosures need Python integers.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidArgument
from .pulses import (
    ArcFrame,
    arc_frame,
    arc_step,
    arc_walk,
    helix_chunk,
    plane_line,
    quadrant_of,
    step_deltas,
)

__all__ = ["ArcPath", "ArcStream", "HelixColumns", "arc_path", "arc_positions", "path_fractions", "path_fractions_moved",
           "unwrap", "SHORT_ARC_STEPS", "CANDIDATES", "STREAM_CHUNK"]

#: Below this many estimated steps the reference loop is faster than numpy set-up.
SHORT_ARC_STEPS = 48
#: Most candidate steps proposed at once.
CANDIDATES = 1 << 16
#: Verify on Python integers (object arrays) when int64 cannot hold the products.  That is
#: exact but no faster than the reference loop, so it is off: such arcs run arc_walk itself.
OBJECT_VERIFY = False
_INT64_SAFE = 1 << 62
#: Steps per chunk in :func:`path_fractions_moved`.
FRACTION_CHUNK = 1 << 16
#: Planar steps per chunk of an :class:`ArcStream`: a chunk's positions (768 KB on three axes) and the
#: walk's and the monitor's temporaries stay in the core's cache, and nothing of the arc's size is allocated.
STREAM_CHUNK = 1 << 15


@dataclass(frozen=True, slots=True)
class ArcPath:
    """The planar pulse positions of an arc as an ``(n, 2)`` int64 array, plus sweep data.

    The same content as :class:`.pulses.ArcWalk` (``points`` there is a tuple).
    """

    points: np.ndarray
    sweep_rad: float
    radius_mm: float
    walk_steps: int


def arc_path(
    start_pulse: tuple[int, int],
    end_pulse: tuple[int, int],
    start: tuple[Fraction, Fraction],
    end: tuple[Fraction, Fraction],
    centre: tuple[Fraction, Fraction],
    clockwise: bool,
    turns: int,
    pulse: tuple[Fraction, Fraction],
) -> ArcPath:
    """The positions of :func:`.pulses.arc_walk`, computed vectorized (identical output).

    >>> F = Fraction
    >>> args = ((10_000, 0), (0, 10_000), (F(10), F(0)), (F(0), F(10)), (F(0), F(0)), False, 0,
    ...         (F(1, 1000), F(1, 1000)))
    >>> fast = arc_path(*args)
    >>> from nczones.controller.pulses import arc_walk
    >>> fast.points.tolist() == [list(p) for p in arc_walk(*args).points], fast.points[-1].tolist()
    (True, [0, 10000])
    """
    pos, sweep, radius, walk = arc_positions(2, 0, 1, start_pulse, end_pulse, start, end, centre, clockwise, turns,
                                             pulse)
    return ArcPath(pos, sweep, radius, walk)


def arc_positions(
    naxes: int, i: int, j: int,
    start_pulse: tuple[int, int],
    end_pulse: tuple[int, int],
    start: tuple[Fraction, Fraction],
    end: tuple[Fraction, Fraction],
    centre: tuple[Fraction, Fraction],
    clockwise: bool,
    turns: int,
    pulse: tuple[Fraction, Fraction],
) -> tuple[np.ndarray, float, float, int]:
    """:func:`arc_path` written straight into columns ``i``, ``j`` of an ``(n, naxes)`` int64 array.

    Returns ``(positions, sweep_rad, radius_mm, walk_steps)``; the other
    columns are left unset for the caller.

    >>> F = Fraction
    >>> pos, *_ = arc_positions(3, 2, 0, (10, 0), (0, 10), (F(10), F(0)), (F(0), F(10)), (F(0), F(0)), False, 0,
    ...                         (F(1), F(1)))
    >>> pos[:, [2, 0]].tolist() == arc_path((10, 0), (0, 10), (F(10), F(0)), (F(0), F(10)), (F(0), F(0)),
    ...                                     False, 0, (F(1), F(1))).points.tolist()
    True
    """
    fr = arc_frame(start_pulse, end_pulse, start, end, centre, clockwise, turns, pulse)
    walk_args = (start_pulse, end_pulse, start, end, centre, clockwise, turns, pulse)
    est, vectorized = _walk_plan(fr)
    if not vectorized:
        w = arc_walk(*walk_args)
        pos = np.empty((len(w.points), naxes), dtype=np.int64)
        pos[:, [i, j]] = np.array(w.points, dtype=np.int64).reshape(-1, 2)
        return pos, w.sweep_rad, w.radius_mm, w.walk_steps
    out = _Columns(naxes, i, j, fr.sj, int(est * 1.02) + 64)
    walk = 0
    for xs, ys in _walk(fr, turns, est):
        out.put(xs, ys)
        walk += len(xs)
    last = out.last() if walk else (start_pulse[0], start_pulse[1])
    tail = plane_line(last, (end_pulse[0], end_pulse[1]))
    if tail:
        out.put_rows(np.array(tail, dtype=np.int64))
    pos = out.result()
    return pos, fr.sweep, fr.radius_mm, walk


def _walk_plan(fr: ArcFrame) -> tuple[float, bool]:
    """The estimated number of walk steps, and whether the vectorized walk applies (else :func:`arc_walk`)."""
    est = fr.sweep * math.sqrt(fr.q) / min(fr.ai, fr.aj) if fr.q else 0.0
    reach = 2 * math.isqrt(fr.q) + abs(fr.cx) + abs(fr.cy) + 4 * max(fr.ai, fr.aj)
    big = 4 * reach * reach + fr.q >= _INT64_SAFE  # int64 verification impossible (e.g. R-format centres)
    return est, not (fr.tiny or est < SHORT_ARC_STEPS or (big and not OBJECT_VERIFY))


class _Columns:
    """An ``(n, naxes)`` int64 array filled in pieces (columns ``i``, ``j``), grown when needed.

    The capacity is reserved with ``np.empty``: pages never written cost nothing.
    """

    def __init__(self, naxes: int, i: int, j: int, sj: int, cap: int) -> None:
        self.buf = np.empty((max(cap, 16), naxes), dtype=np.int64)
        self.i, self.j, self.sj, self.n = i, j, sj, 0

    def _room(self, k: int) -> None:
        if self.n + k > len(self.buf):
            grown = np.empty((max(2 * len(self.buf), self.n + k), self.buf.shape[1]), dtype=np.int64)
            grown[:self.n] = self.buf[:self.n]
            self.buf = grown

    def put(self, xs: np.ndarray, ys: np.ndarray) -> None:
        """Walk positions: x and the mirrored y (unmirrored here)."""
        k = len(xs)
        self._room(k)
        lo, hi = self.n, self.n + k
        self.buf[lo:hi, self.i] = xs
        if self.sj < 0:
            np.negative(ys, out=self.buf[lo:hi, self.j])
        else:
            self.buf[lo:hi, self.j] = ys
        self.n = hi

    def put_rows(self, rows: np.ndarray) -> None:
        """Plane positions ``(k, 2)``, already unmirrored."""
        self._room(len(rows))
        self.buf[self.n:self.n + len(rows), [self.i, self.j]] = rows
        self.n += len(rows)

    def last(self) -> tuple[int, int]:
        return int(self.buf[self.n - 1, self.i]), int(self.buf[self.n - 1, self.j])

    def result(self) -> np.ndarray:
        return self.buf[:self.n]


def _walk(fr: ArcFrame, turns: int, est: float, cap: int | None = None) -> Iterator[tuple[np.ndarray, np.ndarray]]:
    """The walk's positions in pieces ``(xs, ys)`` (``ys`` mirrored, as in the frame) of at most ``cap`` steps.

    Pieces may be views of temporaries: a consumer copies them before asking
    for the next.  Every piece is non-empty.
    """
    x, y, u, v, qc = fr.x, fr.y, fr.u, fr.v, fr.qcount
    walk = 0
    if fr.past_end(u, v, qc):
        return
    limit = fr.limit(turns)
    budget = int(est) + 16  # steps proposed in total; the walk makes about est steps
    most = CANDIDATES if cap is None else min(CANDIDATES, cap)
    while walk < limit:
        k = min(_region_steps(fr, u, v), max(budget - walk, 16), most)
        xs, ys = _candidates(fr, x, y, u, v, k)
        ok, stop, qc_at = _verify(fr, x, y, u, v, qc, xs, ys)
        take = min(ok, stop)
        if take:
            yield xs[:take], ys[:take]
            walk += take
            x, y = int(xs[take - 1]), int(ys[take - 1])
            u, v, qc = x * fr.ai - fr.cx, y * fr.aj - fr.cy, qc_at(take - 1)
        if stop < ok:  # candidate `stop` is a verified step past the end ray: the walk ends
            return
        if ok < len(xs):  # the rule disagrees with candidate `ok`: one exact reference step
            dx, dy, nu, nv = arc_step(u, v, fr.q, fr.ai, fr.aj)
            nq = quadrant_of(nu, nv)
            nqc = qc + ((nq - qc) % 4)
            if fr.past_end(nu, nv, nqc):
                return
            x, y, u, v, qc = x + dx, y + dy, nu, nv, nqc
            yield np.array([x], dtype=np.int64), np.array([y], dtype=np.int64)
            walk += 1
    raise InvalidArgument("arc walk did not reach its end")  # pragma: no cover - as in arc_walk


def _region_steps(fr: ArcFrame, u: int, v: int) -> int:
    """Steps (estimated, +2) until the major axis changes, from offset ``(u, v)``."""
    ai, aj = fr.ai, fr.aj
    b_u = math.sqrt(fr.q) * aj / math.hypot(ai, aj)  # |u| where |v| aj = |u| ai on the circle
    b_v = math.sqrt(fr.q) * ai / math.hypot(ai, aj)
    if abs(v) * aj >= abs(u) * ai:
        w = -float(u) if v > 0 else float(u)  # grows by ai per step
        return max(int((b_u - w) / ai) + 2, 1)
    w = float(v) if u > 0 else -float(v)
    return max(int((b_v - w) / aj) + 2, 1)


def _candidates(fr: ArcFrame, x: int, y: int, u: int, v: int, k: int) -> tuple[np.ndarray, np.ndarray]:
    """``k`` guessed positions after ``(x, y)``: the major axis steps, the minor is nearest the circle."""
    ai, aj = float(fr.ai), float(fr.aj)
    qf = float(fr.q)
    steps = np.arange(1, k + 1, dtype=np.int64)
    if abs(v) * fr.aj >= abs(u) * fr.ai:
        dx = -1 if v > 0 else 1
        xs = x + dx * steps
        uk = float(u) + (dx * ai) * steps.astype(float)
        vk = np.sqrt(np.clip(qf - uk * uk, 0.0, None)) * (1.0 if v > 0 else -1.0)
        ys = y + np.floor((vk - float(v)) / aj + 0.5).astype(np.int64)
    else:
        dy = 1 if u > 0 else -1
        ys = y + dy * steps
        vk = float(v) + (dy * aj) * steps.astype(float)
        uk = np.sqrt(np.clip(qf - vk * vk, 0.0, None)) * (1.0 if u > 0 else -1.0)
        xs = x + np.floor((uk - float(u)) / ai + 0.5).astype(np.int64)
    return xs, ys


_Verified = tuple[int, int, Callable[[int], int]]


def _verify(fr: ArcFrame, x: int, y: int, u: int, v: int, qc: int, xs: np.ndarray, ys: np.ndarray) -> _Verified:
    """Check candidates against the exact step rule.

    Returns ``(ok, stop, qc_at)``: candidates ``[:ok]`` are the steps the
    rule takes; ``stop`` is the index of the first of those that lies past the
    end ray (``len(xs)`` if none); ``qc_at(i)`` the quadrant count after
    candidate ``i < ok``.  The int64 fast path (:func:`_verify_fast`) answers
    the common case; whatever it cannot decide cheaply goes to the general check.
    """
    got = _verify_fast(fr, x, y, u, v, qc, xs, ys)
    if got is not None:
        return got
    ok, stop, qcs = _verify_general(fr, x, y, u, v, qc, xs, ys)
    return ok, stop, lambda i: int(qcs[i])


def _verify_fast(fr: ArcFrame, x: int, y: int, u: int, v: int, qc: int, xs: np.ndarray,
                 ys: np.ndarray) -> _Verified | None:
    """The step rule checked in int64 on a stretch where the major axis and its sign are fixed.

    Applies when int64 cannot overflow (the same bound as the general check),
    the first step's tangent sign holds for every verified position (so the
    major axis moves monotonically, the quadrant changes at most once, and
    the candidates' major-axis steps are right by construction), the minor
    offset stays above half a minor pulse (so the three residuals are ordered,
    see the comment in the code), and every minor step is -1, 0 or +1.
    Returns ``None`` otherwise.
    """
    ai, aj, q, cx, cy = fr.ai, fr.aj, fr.q, fr.cx, fr.cy
    n = len(xs)
    xmajor = abs(v) * aj >= abs(u) * ai
    mj, mn = (xs, ys) if xmajor else (ys, xs)  # candidates are monotone in the major axis
    bmaj = max(abs(int(mj[0])), abs(int(mj[-1])))
    bmin = max(int(mn.max()), -int(mn.min()))
    bx = max(abs(x), bmaj if xmajor else bmin) * ai + abs(cx)
    by = max(abs(y), bmin if xmajor else bmaj) * aj + abs(cy)
    bound = max(bx, by) + max(ai, aj)
    if not (4 * bound * bound + q < _INT64_SAFE and (abs(fr.eu) + abs(fr.ev)) * bound < _INT64_SAFE):
        return None
    # the major/minor roles: (a, b) = (x, y) when x is major, else (y, x), with offsets A, B
    if xmajor:
        A = xs * ai - cx
        B = ys * aj - cy
        a0, b0, sa, sb = u, v, ai, aj
        mins = ys
        m0 = y
    else:
        A = ys * aj - cy
        B = xs * ai - cx
        a0, b0, sa, sb = v, u, aj, ai
        mins = xs
        m0 = x
    # A (major offset) after each step, B (minor) after each step; predecessors Ap, Bp
    Bp = np.empty(n, dtype=np.int64)
    Bp[0] = b0
    Bp[1:] = B[:-1]
    # the major axis of each step, from the predecessor: |B| sb >= |A| sa (x major: |v| aj >= |u| ai)
    Ap = np.empty(n, dtype=np.int64)
    Ap[0] = a0
    Ap[1:] = A[:-1]
    absB = np.abs(Bp)
    same = absB * sb >= np.abs(Ap) * sa if xmajor else absB * sb > np.abs(Ap) * sa
    m = int(np.argmin(same)) if not same.all() else n
    if m == 0:
        return None
    pos = b0 > 0
    # every |Bp| (and the last B) above half a minor pulse, all of one sign: see below
    if pos:
        if 2 * b0 <= sb or 2 * int(B[:m].min()) <= sb:
            return None
    elif -2 * b0 <= sb or -2 * int(B[:m].max()) <= sb:
        return None
    dmin = step_deltas(mins[:m], m0)
    if int(dmin.max()) > 1 or int(dmin.min()) < -1:
        return None
    # The three residuals e(w) = A^2 + w^2 - q for w = Bp - sb, Bp, Bp + sb: with T = 2 sb |Bp| > sb^2
    # the inward one (towards B = 0) is below g = e(Bp) and the outward one above, so the rule
    # (smallest |e|, the no-move option first on ties) moves inward iff 2g > T - sb^2, outward iff
    # 2g < -(T + sb^2), else not at all; no tie between the two moves can decide anything.
    Bpm = Bp[:m]
    Am = A[:m]
    h = Am * Am
    h += Bpm * Bpm
    h -= q
    h *= 2
    T = (2 * sb if pos else -2 * sb) * Bpm
    ss = sb * sb
    inward = (h - T) > -ss
    outward = (h + T) < -ss
    expect = outward.view(np.int8) - inward.view(np.int8)  # in units of sign(B): -1 inward, +1 outward
    if not pos:
        np.negative(expect, out=expect)
    bad = dmin != expect
    ok = int(np.argmax(bad)) if bad.any() else m
    # quadrants: B keeps its sign, A is monotone and crosses zero at most once
    if xmajor:  # (u, v) = (A, B): v > 0 -> 0 while u > 0, then 1; v < 0 -> 2 while u < 0, then 3
        qa, qb = (0, 1) if pos else (2, 3)
        c = int(np.count_nonzero(A[:m] > 0)) if pos else int(np.count_nonzero(A[:m] < 0))
    else:  # (u, v) = (B, A): u > 0 -> 3 while v < 0, then 0; u < 0 -> 1 while v > 0, then 2
        qa, qb = (3, 0) if pos else (1, 2)
        c = int(np.count_nonzero(A[:m] < 0)) if pos else int(np.count_nonzero(A[:m] > 0))
    qstart = qc % 4
    if c:
        ca = qc + (qa - qstart) % 4
        cb = ca + (qb - qa) % 4
    else:
        ca = cb = qc + (qb - qstart) % 4
    if ok == 0 or max(ca, cb) < fr.qe:
        stop = n
    else:
        Un, Vn = (A[:ok], B[:ok]) if xmajor else (B[:ok], A[:ok])
        cross = fr.eu * Vn - fr.ev * Un
        qcs = np.where(np.arange(ok) < c, ca, cb)
        past = (qcs > fr.qe) | ((qcs == fr.qe) & (cross >= 0))
        stop = int(np.argmax(past)) if past.any() else n
    return ok, stop, lambda i: ca if i < c else cb


def _verify_general(fr: ArcFrame, x: int, y: int, u: int, v: int, qc: int, xs: np.ndarray,
                    ys: np.ndarray) -> tuple[int, int, np.ndarray]:
    """Check candidates against the exact step rule.

    Returns ``(ok, stop, qcounts)``: candidates ``[:ok]`` are the steps the
    rule takes; ``stop`` is the index of the first of those that lies past the
    end ray (``len(xs)`` if none); ``qcounts`` the quadrant counts.
    """
    ai, aj, q, cx, cy = fr.ai, fr.aj, fr.q, fr.cx, fr.cy
    n = len(xs)
    bx = max(abs(x), int(np.abs(xs).max())) * ai + abs(cx)
    by = max(abs(y), int(np.abs(ys).max())) * aj + abs(cy)
    bound = max(bx, by) + max(ai, aj)  # |u|, |v| and every offset tried, before and after a step
    exact64 = 4 * bound * bound + q < _INT64_SAFE and (abs(fr.eu) + abs(fr.ev)) * bound < _INT64_SAFE
    dt = np.int64 if exact64 else object
    X = np.concatenate([np.array([x], dtype=np.int64), xs])
    Y = np.concatenate([np.array([y], dtype=np.int64), ys])
    if exact64:
        U = X * ai - cx
        V = Y * aj - cy
    else:
        U = X.astype(object) * ai - cx
        V = Y.astype(object) * aj - cy
    Up, Vp = U[:-1], V[:-1]
    # the major axis of every step; only the stretch with the first step's major axis is checked
    # (a step with the other major axis counts as a disagreement: the caller takes it exactly)
    xmaj = np.abs(Vp) * aj >= np.abs(Up) * ai
    turn = xmaj != xmaj[0]
    m = int(np.argmax(turn)) if turn.any() else n
    Up, Vp = Up[:m], Vp[:m]
    if xmaj[0]:  # x major: dx = -sign(v), dy in (0, s, -s), s = +1 if u > 0 else -1, first strict minimum
        major_ok = np.diff(X[: m + 1]) == np.where(Vp > 0, -1, 1)
        s = np.where(Up > 0, 1, -1).astype(dt)
        nu = Up + np.where(Vp > 0, -1, 1).astype(dt) * ai
        g = nu * nu + Vp * Vp - q  # the residual with dy = 0
        h = 2 * s * Vp * aj
        minor, other, scale = np.diff(Y[: m + 1]), s, aj * aj
    else:  # y major: dy = sign(u) (+1 if u > 0 else -1), dx in (0, t, -t), t = -1 if v > 0 else 1
        major_ok = np.diff(Y[: m + 1]) == np.where(Up > 0, 1, -1)
        s = np.where(Vp > 0, -1, 1).astype(dt)
        nv = Vp + np.where(Up > 0, 1, -1).astype(dt) * aj
        g = nv * nv + Up * Up - q
        h = 2 * s * Up * ai
        minor, other, scale = np.diff(X[: m + 1]), s, ai * ai
    f0 = np.abs(g)
    f1 = np.abs(g + h + scale)  # minor axis forwards (+s)
    f2 = np.abs(g - h + scale)  # backwards (-s)
    pick1 = f1 < f0
    best = np.where(pick1, f1, f0)
    d = np.where(f2 < best, -other, np.where(pick1, other, 0)).astype(np.int64)
    bad = ~major_ok | (d != minor)
    ok = int(np.argmax(bad)) if bad.any() else m
    # quadrant counts and the end-ray test of the (verified) positions
    Un, Vn = U[1:], V[1:]
    quad = np.where((Un > 0) & (Vn >= 0), 0, np.where((Un <= 0) & (Vn > 0), 1,
                                                       np.where((Un < 0) & (Vn <= 0), 2, 3))).astype(np.int64)
    prev = np.concatenate([np.array([qc % 4], dtype=np.int64), quad[:-1]])
    qcs = qc + np.cumsum((quad - prev) % 4)
    cross = fr.eu * Vn - fr.ev * Un
    past = (qcs > fr.qe) | ((qcs == fr.qe) & (cross >= 0))
    past = np.asarray(past, dtype=bool)
    stop = int(np.argmax(past)) if past.any() else n
    return ok, stop, qcs


class HelixColumns:
    """The helix columns of an arc's positions, filled chunk by chunk in order (the state is carried).

    Each helix axis follows the swept angle, rounded to the nearest pulse: the
    angle of every planar position, unwrapped (:func:`unwrap`), relative to the
    start angle ``a0``, as a fraction of the sweep clipped to [0, 1] and made
    non-decreasing; the axis ``k`` stands at ``a + floor(phi * (b - a) + 1/2)``
    for each ``(k, a, b)`` of ``axes``, and the arc's last step at ``b``.

    Invariant: every float operation is elementwise or carried exactly from
    one chunk to the next (the unwrap correction, the first angle's whole
    turns, the running maximum), so any chunking of the positions gives the
    whole-array result bit for bit.

    >>> pos = np.array([[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [1, 0, 0]])
    >>> h = HelixColumns((0, 1), (1.0, 1.0), (0.0, 0.0), 1.0, 0.0, 2 * math.pi, [(2, 0, 8)])
    >>> h.fill(pos[:2], False); h.fill(pos[2:], True)
    >>> pos[:, 2].tolist()
    [0, 2, 4, 6, 8]
    """

    __slots__ = ("plane", "pulse2", "centre", "sgn", "a0", "sweep", "axes", "prev_raw", "total", "shift", "run_max")

    def __init__(self, plane: tuple[int, int], pulse2: tuple[float, float], centre: tuple[float, float], sgn: float,
                 a0: float, sweep: float, axes: Sequence[tuple[int, int, int]]) -> None:
        self.plane, self.pulse2, self.centre, self.sgn, self.a0, self.sweep = plane, pulse2, centre, sgn, a0, sweep
        self.axes = tuple(axes)
        self.prev_raw: float | None = None  # last raw angle of the previous chunk (unwrap across chunks)
        self.total = 0.0  # the unwrap correction carried
        self.shift: Any = None  # whole turns removed so that the first angle is near 0
        self.run_max = -np.inf

    def fill(self, pos: np.ndarray, last: bool) -> None:
        """Write the helix columns of the next ``len(pos)`` positions (``last``: they end the arc)."""
        m = len(pos)
        if not m:
            return
        pi, pj = self.plane
        fi, fj = self.pulse2
        cx, cy = self.centre
        yy = pos[:, pj] * fj
        yy -= cy
        if self.sgn < 0:
            np.negative(yy, out=yy)  # == -1.0 * yy exactly
        xx = pos[:, pi] * fi
        xx -= cx
        raw = np.arctan2(yy, xx, out=yy)
        ext = raw if self.prev_raw is None else np.concatenate(([self.prev_raw], raw))
        up, self.total = unwrap_from(ext, self.total)  # a fresh array: the steps below work in place
        if self.prev_raw is not None:
            up = up[1:]
        self.prev_raw = float(raw[-1])
        ang = up
        ang -= self.a0
        if self.shift is None:
            self.shift = 2 * math.pi * np.round(ang[0] / (2 * math.pi))
        ang -= self.shift
        if self.sweep > 0:
            phi = ang
            phi /= self.sweep
            np.clip(phi, 0.0, 1.0, out=phi)
        else:
            phi = np.ones(m)
        if m > 1 and not (phi[1:] >= phi[:-1]).all():  # the running maximum; a no-op where phi never falls
            np.maximum.accumulate(phi, out=phi)
        if phi[0] < self.run_max:
            np.maximum(phi, self.run_max, out=phi)
        self.run_max = float(phi[-1])
        for k, a, b in self.axes:
            t = phi * (b - a)
            t += 0.5
            np.floor(t, out=t)
            pos[:, k] = t
            pos[:, k] += a
            if last:
                pos[m - 1, k] = b


def unwrap_from(p: np.ndarray, total: float) -> tuple[np.ndarray, float]:
    """:func:`unwrap` of ``p`` with a correction ``total`` already carried from before ``p[0]``.

    ``p[0]`` itself gets ``total`` only as numpy would give it: callers pass the
    previous chunk's last raw value there and drop it.
    """
    dd = np.diff(p)
    idx = np.flatnonzero(np.abs(dd) >= math.pi)
    up = p + total if total else p.copy()
    if not len(idx):
        return up, total
    sub = dd[idx]
    ddmod = np.mod(sub + math.pi, 2 * math.pi) - math.pi
    ddmod[(ddmod == -math.pi) & (sub > 0)] = math.pi
    corr = ddmod - sub
    bounds = [*idx.tolist(), len(dd)]
    for c, k, k_next in zip(corr.tolist(), bounds[:-1], bounds[1:]):
        total += c  # numpy's cumsum adds the corrections in this order
        up[k + 1:k_next + 1] = p[k + 1:k_next + 1] + total
    return up, total


def unwrap(p: np.ndarray) -> np.ndarray:
    """``np.unwrap(p)`` bit for bit, touching only the jumps (an arc's angle jumps once per turn).

    >>> a = np.array([3.0, 3.1, -3.1, -3.0, 3.1])
    >>> bool(np.array_equal(unwrap(a), np.unwrap(a)))
    True
    """
    if len(p) < 2:
        return np.unwrap(p)
    return unwrap_from(p, 0.0)[0]


_ALLOCATOR_SETTLED = False


def _settle_allocator() -> None:
    """Free one large, never touched block once per process, so that a chunk's temporaries stay mapped.

    glibc's malloc serves blocks above its mmap threshold (128 KB at start) by mmap and returns heap memory
    above its trim threshold to the system; a stream's temporaries of 256 KB would be mapped, faulted in
    page by page and unmapped again in every chunk (measured: 30,000 minor faults per R200 helix circle,
    a third of its time).  Freeing an mmapped block raises both thresholds to its size (the allocator's
    own adaptation), after which the temporaries are reused from the heap.  The block is never written,
    so it costs no page faults; other allocators are unaffected.
    """
    global _ALLOCATOR_SETTLED
    if not _ALLOCATOR_SETTLED:
        block = np.empty(1 << 23, dtype=np.uint8)
        del block
        _ALLOCATOR_SETTLED = True


class ArcStream:
    """The vector engine's plan of one arc on every axis, computed chunk by chunk.

    :meth:`chunks` yields ``(m, naxes)`` int64 arrays: the positions after
    each step.  Concatenated, they are the whole plan: the planar walk of
    :func:`arc_positions` in columns ``i``, ``j``; the helix columns of
    :class:`HelixColumns` (``helix`` lists ``(k, a, b)``, ``helix_frame`` is
    ``(pulse2, centre, sgn, a0)`` in floats); every other axis standing at
    ``p0``; a steep helix's pulses interleaved (:func:`.pulses.helix_chunk`).
    Each stage works on one chunk of at most ``chunk`` planar steps, with its
    state carried (the walk's position, the helix angle, the previous row), so
    the concatenation does not depend on the chunk size: the invariant the
    tests check against the whole-array forms and the reference walk.  Nothing
    of the size of the whole arc is allocated.

    ``vectorized`` says whether the walk is the numpy one (else the arc is
    small, or needs Python integers, and :func:`.pulses.arc_walk` runs whole).

    >>> F = Fraction
    >>> walk = ((10, 0), (10, 0), (F(10), F(0)), (F(10), F(0)), (F(0), F(0)), False, 0, (F(1), F(1)))
    >>> s = ArcStream(3, 0, 1, walk, (10, 0, 0), [(2, 0, 6)], ((1.0, 1.0), (0.0, 0.0), 1.0, 0.0), chunk=5)
    >>> parts = [c.copy() for c in s.chunks()]
    >>> whole = ArcStream(3, 0, 1, walk, (10, 0, 0), [(2, 0, 6)], ((1.0, 1.0), (0.0, 0.0), 1.0, 0.0)).positions()
    >>> s.vectorized, len(parts), bool(np.array_equal(np.vstack(parts), whole)), whole[-1].tolist()
    (True, 12, True, [10, 0, 6])
    """

    def __init__(self, naxes: int, i: int, j: int, walk_args: tuple, p0: Sequence[int],
                 helix: Sequence[tuple[int, int, int]], helix_frame: tuple, chunk: int | None = None) -> None:
        self.naxes, self.i, self.j, self.walk_args = naxes, i, j, walk_args
        self.p0 = tuple(int(v) for v in p0)
        self.helix, self.helix_frame = tuple(helix), helix_frame
        self.chunk = max(1, STREAM_CHUNK if chunk is None else chunk)
        self.frame = arc_frame(*walk_args)
        self.sweep_rad, self.radius_mm = self.frame.sweep, self.frame.radius_mm
        self.est, self.vectorized = _walk_plan(self.frame)

    def _pieces(self) -> Iterator[tuple[np.ndarray, np.ndarray, bool]]:
        """The planar positions in non-empty pieces ``(xs, ys, mirrored)``."""
        start_pulse, end_pulse = self.walk_args[0], self.walk_args[1]
        if not self.vectorized:
            w = arc_walk(*self.walk_args)
            if w.points:
                pts = np.array(w.points, dtype=np.int64).reshape(-1, 2)
                yield pts[:, 0], pts[:, 1], False
            return
        fr = self.frame
        last = (start_pulse[0], start_pulse[1])
        for xs, ys in _walk(fr, self.walk_args[6], self.est, self.chunk):
            yield xs, ys, fr.sj < 0
            last = (int(xs[-1]), fr.sj * int(ys[-1]))
        tail = plane_line(last, (end_pulse[0], end_pulse[1]))
        if tail:
            t = np.array(tail, dtype=np.int64)
            yield t[:, 0], t[:, 1], False

    def chunks(self) -> Iterator[np.ndarray]:
        """The positions after each step, chunk by chunk (a chunk is valid until the next is asked for)."""
        _settle_allocator()
        size, i, j = self.chunk, self.i, self.j
        buf = np.empty((size, self.naxes), dtype=np.int64, order="F")  # columns contiguous
        moving = {i, j, *(k for k, _, _ in self.helix)}
        for k in range(self.naxes):
            if k not in moving:
                buf[:, k] = self.p0[k]
        hax = [k for k, _, _ in self.helix]
        pulse2, centre, sgn, a0 = self.helix_frame
        hc = HelixColumns((i, j), pulse2, centre, sgn, a0, self.sweep_rad, self.helix) if self.helix else None
        prev: tuple[int, ...] = self.p0
        pieces = self._pieces()
        cur = next(pieces, None)
        off = m = 0
        while cur is not None:
            xs, ys, mirrored = cur
            take = min(size - m, len(xs) - off)
            buf[m:m + take, i] = xs[off:off + take]
            if mirrored:
                np.negative(ys[off:off + take], out=buf[m:m + take, j])
            else:
                buf[m:m + take, j] = ys[off:off + take]
            m += take
            off += take
            if off == len(xs):
                cur, off = next(pieces, None), 0
            if m == size or cur is None:
                rows = buf[:m]
                if hc is not None:
                    hc.fill(rows, cur is None)
                    rows = helix_chunk(rows, prev, hax)
                    prev = tuple(int(v) for v in rows[-1])
                m = 0
                yield rows

    def positions(self) -> np.ndarray:
        """The whole plan as one ``(n, naxes)`` int64 array (the chunks concatenated)."""
        out = np.empty((int(self.est * 1.02) + 64, self.naxes), dtype=np.int64)  # pages never written cost nothing
        n = 0
        for c in self.chunks():
            if n + len(c) > len(out):
                grown = np.empty((max(2 * len(out), n + len(c)), self.naxes), dtype=np.int64)
                grown[:n] = out[:n]
                out = grown
            out[n:n + len(c)] = c
            n += len(c)
        return out[:n]


def path_fractions(pos: np.ndarray, p0: Sequence[int], pulse_mm: Sequence[float | Fraction]) -> np.ndarray:
    """Cumulative chord length after each step as a fraction of the whole (floats, timing only).

    Steps that move every axis by at most one pulse (arcs and interleaved
    helices) take their length from a table indexed by which axes moved.

    >>> path_fractions(np.array([[1, 0], [2, 1], [2, 2]]), (0, 0), (1.0, 1.0)).round(3).tolist()
    [0.293, 0.707, 1.0]
    """
    n = len(pos)
    if not n:
        return np.ones(0)
    moved = np.abs(np.diff(pos, axis=0, prepend=np.asarray(p0, dtype=np.int64).reshape(1, -1)))
    k = pos.shape[1]
    u2 = np.array([float(u) ** 2 for u in pulse_mm])
    if k <= 12 and moved.max() <= 1:
        code = moved @ (1 << np.arange(k, dtype=np.int64))
        table = np.sqrt(((np.arange(1 << k)[:, None] >> np.arange(k)) & 1) @ u2)
        step_len = table[code]
    else:
        step_len = np.sqrt((moved.astype(float) ** 2) @ u2)
    cum = np.cumsum(step_len)
    return cum / cum[-1] if cum[-1] > 0 else np.ones(n)


def path_fractions_moved(pos: np.ndarray, p0: Sequence[int], pulse_mm: Sequence[float | Fraction],
                         moving: Any) -> tuple[np.ndarray, tuple[int, ...]]:
    """:func:`path_fractions` (bit for bit) and the pulses each axis makes over all steps.

    Columns of axes not in ``moving`` must stay at ``p0`` (the caller builds
    them so); only the moving columns are read.  Falls back to the general
    form when a step moves an axis by more than one pulse.

    >>> pos = np.array([[1, 0, 5], [2, 1, 5], [2, 2, 5]])
    >>> sig, moved = path_fractions_moved(pos, (0, 0, 5), (1.0, 1.0, 1.0), [0, 1])
    >>> bool(np.array_equal(sig, path_fractions(pos, (0, 0, 5), (1.0, 1.0, 1.0)))), moved
    (True, (2, 2, 0))
    """
    n, k = pos.shape
    if not n:
        return np.ones(0), (0,) * k
    if k > 8:
        return _fractions_general(pos, p0, pulse_mm)
    u2 = np.array([float(u) ** 2 for u in pulse_mm])
    table = np.sqrt(((np.arange(1 << k)[:, None] >> np.arange(k)) & 1) @ u2)
    cum = np.empty(n)
    totals = [0] * k
    prev = [np.int64(p0[a]) for a in moving]
    carry = 0.0
    for lo in range(0, n, FRACTION_CHUNK):  # chunks: temporaries stay in cache
        hi = min(n, lo + FRACTION_CHUNK)
        code = np.zeros(hi - lo, dtype=np.uint8)
        for c, a in enumerate(moving):
            d = step_deltas(pos[lo:hi, a], prev[c])
            if int(d.max()) > 1 or int(d.min()) < -1:
                return _fractions_general(pos, p0, pulse_mm)
            m = d != 0
            totals[a] += int(np.count_nonzero(m))
            code |= m.view(np.uint8) << np.uint8(a)
            prev[c] = pos[hi - 1, a]
        step = table[code]
        step[0] += carry  # cumsum adds left to right: carrying the sum keeps every partial sum bit for bit
        np.cumsum(step, out=cum[lo:hi])
        carry = float(cum[hi - 1])
    if cum[-1] > 0:
        cum /= cum[-1]
        return cum, tuple(totals)
    return np.ones(n), tuple(totals)


def _fractions_general(pos: np.ndarray, p0: Sequence[int], pulse_mm: Sequence[float | Fraction]) -> tuple[np.ndarray, tuple[int, ...]]:
    moved = np.abs(np.diff(pos, axis=0, prepend=np.asarray(p0, dtype=np.int64).reshape(1, -1)))
    return path_fractions(pos, p0, pulse_mm), tuple(int(t) for t in moved.sum(axis=0))
