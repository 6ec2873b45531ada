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
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from ..errors import InvalidArgument
from .pulses import _arc_frame, _arc_step, _ArcFrame, _plane_line, _quadrant, arc_walk

__all__ = ["ArcPath", "arc_path", "SHORT_ARC_STEPS", "CANDIDATES"]

#: Below this many estimated steps the reference loop is faster than numpy set-up.
SHORT_ARC_STEPS = 48
#: Most candidate steps proposed at once.
CANDIDATES = 1 << 16
#: Verify on Python integers (object arrays) when int64 cannot hold the products.  That is
#: exact but no faster than the reference loop, so it is off: such arcs run arc_walk itself.
OBJECT_VERIFY = False
_INT64_SAFE = 1 << 62


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
    fr = _arc_frame(start_pulse, end_pulse, start, end, centre, clockwise, turns, pulse)
    est = fr.sweep * math.sqrt(fr.q) / min(fr.ai, fr.aj) if fr.q else 0.0
    reach = 2 * math.isqrt(fr.q) + abs(fr.cx) + abs(fr.cy) + 4 * max(fr.ai, fr.aj)
    big = 4 * reach * reach + fr.q >= _INT64_SAFE  # int64 verification impossible (e.g. R-format centres)
    if fr.tiny or est < SHORT_ARC_STEPS or (big and not OBJECT_VERIFY):
        w = arc_walk(start_pulse, end_pulse, start, end, centre, clockwise, turns, pulse)
        return ArcPath(np.array(w.points, dtype=np.int64).reshape(-1, 2), w.sweep_rad, w.radius_mm, w.walk_steps)
    pieces, walk = _walk(fr, turns, est)
    pts = np.concatenate(pieces) if pieces else np.zeros((0, 2), dtype=np.int64)
    pts[:, 1] *= fr.sj
    last = tuple(int(c) for c in pts[-1]) if len(pts) else (start_pulse[0], start_pulse[1])
    tail = _plane_line(last, (end_pulse[0], end_pulse[1]))
    if tail:
        pts = np.vstack([pts, np.array(tail, dtype=np.int64)])
    return ArcPath(pts, fr.sweep, fr.radius_mm, walk)


def _walk(fr: _ArcFrame, turns: int, est: float) -> tuple[list[np.ndarray], int]:
    """The walk's (x, mirrored y) positions in pieces, and the number of steps."""
    x, y, u, v, qc = fr.x, fr.y, fr.u, fr.v, fr.qcount
    pieces: list[np.ndarray] = []
    walk = 0
    if fr.past_end(u, v, qc):
        return pieces, 0
    limit = fr.limit(turns)
    budget = int(est) + 16  # steps proposed in total; the walk makes about est steps
    while walk < limit:
        k = min(_region_steps(fr, u, v), max(budget - walk, 16), CANDIDATES)
        xs, ys = _candidates(fr, x, y, u, v, k)
        ok, stop, qcs = _verify(fr, x, y, u, v, qc, xs, ys)
        take = min(ok, stop)
        if take:
            pieces.append(np.column_stack([xs[:take], ys[:take]]))
            walk += take
            x, y = int(xs[take - 1]), int(ys[take - 1])
            u, v, qc = x * fr.ai - fr.cx, y * fr.aj - fr.cy, int(qcs[take - 1])
        if stop < ok:  # candidate `stop` is a verified step past the end ray: the walk ends
            return pieces, walk
        if ok < len(xs):  # the rule disagrees with candidate `ok`: one exact reference step
            dx, dy, nu, nv = _arc_step(u, v, fr.q, fr.ai, fr.aj)
            nq = _quadrant(nu, nv)
            nqc = qc + ((nq - qc) % 4)
            if fr.past_end(nu, nv, nqc):
                return pieces, walk
            x, y, u, v, qc = x + dx, y + dy, nu, nv, nqc
            pieces.append(np.array([[x, y]], dtype=np.int64))
            walk += 1
    raise InvalidArgument("arc walk did not reach its end")  # pragma: no cover - as in arc_walk


def _region_steps(fr: _ArcFrame, u: int, v: int) -> int:
    """Steps (estimated, +2) until the major axis changes, from offset ``(u, v)``."""
    ai, aj = fr.ai, fr.aj
    b_u = math.sqrt(fr.q) * aj / math.hypot(ai, aj)  # |u| where |v| aj = |u| ai on the circle
    b_v = math.sqrt(fr.q) * ai / math.hypot(ai, aj)
    if abs(v) * aj >= abs(u) * ai:
        w = -float(u) if v > 0 else float(u)  # grows by ai per step
        return max(int((b_u - w) / ai) + 2, 1)
    w = float(v) if u > 0 else -float(v)
    return max(int((b_v - w) / aj) + 2, 1)


def _candidates(fr: _ArcFrame, x: int, y: int, u: int, v: int, k: int) -> tuple[np.ndarray, np.ndarray]:
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


def _verify(fr: _ArcFrame, x: int, y: int, u: int, v: int, qc: int, xs: np.ndarray, ys: np.ndarray):
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


def path_fractions(pos: np.ndarray, p0, pulse_mm) -> np.ndarray:
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
