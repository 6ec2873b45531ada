"""Pulse distribution of motion in polar coordinate interpolation (G12.1).

As the control does it: interpolate the programmed path in the polar plane
(the linear axis X and the hypothetical axis), convert each interpolated
point into machine X (its distance from the centre of rotation) and machine
C (its angle, continuous along the path), and round both to pulses.

Method (double precision, as a control's interpolator; the error of a
converted point is below 1e-9 pulse for paths of metres):

1. The plane path ``P(t)``, ``t`` in [0, 1]: a line ``p0 + t (p1 - p0)``, or
   an arc ``c + rho(t) (cos, sin)(a0 +- t sweep)`` (centre from I/J, or
   computed from R here; ``rho`` from the start radius to the end radius).
   Other axes move linearly in ``t``.
2. ``P`` is sampled at uniform ``t``; machine X = ``x_off + |P|``, machine C
   = ``c_entry +`` the angle of ``P`` unwrapped along the samples from the
   start angle the segment names (``atan2(p0) + 360 turns``); wherever two
   consecutive samples differ by more than one pulse on an axis (near the
   centre of rotation C turns fast), the gap is halved, until every step is
   at most one pulse per axis.
3. The rows are joined to where the controller stands and to the rounded end
   point of the segment by linear pulse steps.

Invariant: every commanded position is within half a pulse (plus the double
rounding) of the converted exact path on each axis, and consecutive positions
differ by at most one pulse per axis.  Tests check both against the exact
enclosures of :mod:`nczones.geometry.polar`.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from ..errors import InvalidArgument
from ..motion import PolarData, Segment
from .cylindrical import join_steps
from .pulses import round_pulse

__all__ = ["polar_positions", "polar_walk"]

#: Halvings of a gap before the walk gives up (a path this close to the centre was refused by the interpreter).
MAX_REFINE = 80


class _Path:
    """The plane path of one segment in doubles."""

    def __init__(self, seg: Segment):
        e = seg.payload(PolarData)
        if e is None:
            raise InvalidArgument("not a motion made in polar coordinate interpolation (G12.1)")
        (x0, y0), (x1, y1) = e.start, e.end
        self.p0 = (float(x0), float(y0))
        self.p1 = (float(x1), float(y1))
        self.x_off = float(e.x_off)
        self.c_entry = float(e.c_entry)
        turns = e.turns
        self.theta0 = math.degrees(math.atan2(self.p0[1], self.p0[0])) + 360.0 * turns
        self.ix = seg.axes.index(e.linear_axis)
        self.ic = seg.axes.index(e.rotary_axis)
        self.arc = e.arc
        if not self.arc:
            return
        cw = seg.clockwise
        if e.centre is not None:
            cx, cy = (float(v) for v in e.centre)
            a0 = math.atan2(self.p0[1] - cy, self.p0[0] - cx)
            a1 = math.atan2(self.p1[1] - cy, self.p1[0] - cx)
            d = (a0 - a1) if cw else (a1 - a0)
            d %= 2 * math.pi
            sweep = d if d > 1e-15 else 2 * math.pi
        else:
            assert e.radius is not None  # an arc has I/J or R
            r = float(e.radius)
            dx, dy = self.p1[0] - self.p0[0], self.p1[1] - self.p0[1]
            chord = math.hypot(dx, dy)
            right = (cw and r > 0) or (not cw and r < 0)
            nx, ny = (dy / chord, -dx / chord) if right else (-dy / chord, dx / chord)
            h = math.sqrt(max(r * r - chord * chord / 4, 0.0))
            cx, cy = self.p0[0] + dx / 2 + h * nx, self.p0[1] + dy / 2 + h * ny
            minor = 2 * math.asin(min(chord / 2 / abs(r), 1.0))
            sweep = minor if r > 0 else 2 * math.pi - minor
            a0 = math.atan2(self.p0[1] - cy, self.p0[0] - cx)
        self.centre = (cx, cy)
        self.a0 = a0
        self.sweep = -sweep if cw else sweep
        self.r0 = math.hypot(self.p0[0] - cx, self.p0[1] - cy)
        self.r1 = math.hypot(self.p1[0] - cx, self.p1[1] - cy)

    def points(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if not self.arc:
            return (self.p0[0] + (self.p1[0] - self.p0[0]) * t, self.p0[1] + (self.p1[1] - self.p0[1]) * t)
        a = self.a0 + self.sweep * t
        rho = self.r0 + (self.r1 - self.r0) * t
        return self.centre[0] + rho * np.cos(a), self.centre[1] + rho * np.sin(a)

    def length(self) -> float:
        if not self.arc:
            return math.hypot(self.p1[0] - self.p0[0], self.p1[1] - self.p0[1])
        return abs(self.sweep) * (self.r0 + self.r1) / 2


def _rows(path: _Path, seg: Segment, pulses: tuple[Fraction, ...], p0: tuple[int, ...], t: np.ndarray) -> np.ndarray:
    x, y = path.points(t)
    theta = np.degrees(np.unwrap(np.arctan2(y, x)))
    theta += path.theta0 - theta[0]
    rows = np.empty((t.size, len(p0)), dtype=np.float64)
    for k, (a, b) in enumerate(zip(seg.start, seg.end)):
        rows[:, k] = float(a) + (float(b) - float(a)) * t
    rows[:, path.ix] = path.x_off + np.hypot(x, y)
    rows[:, path.ic] = path.c_entry + theta
    u = np.array([float(p) for p in pulses])
    out: np.ndarray = np.floor(rows / u + 0.5).astype(np.int64)
    return out


def polar_positions(seg: Segment, pulses: tuple[Fraction, ...], p0: tuple[int, ...]) -> np.ndarray:
    """The commanded pulse positions after each step of a polar move (``(steps, axes)`` int64).

    >>> from nczones.motion import PolarData, Segment, SegmentKind
    >>> F = Fraction
    >>> ex = (PolarData((F(10), F(0)), (F(10), F(10)), 0, F(0), F(0), "X", "C", (F(1, 1000), F(1, 1000)), False),)
    >>> seg = Segment(SegmentKind.POLAR, (F(10), F(0)), (F("14.142"), F(45)), ("X", "C"), extra=ex)
    >>> pos = polar_positions(seg, (F(1, 1000), F(1, 1000)), (10000, 0))
    >>> pos[-1].tolist(), int(abs(pos[1:] - pos[:-1]).max())
    ([14142, 45000], 1)
    """
    path = _Path(seg)
    u = [float(p) for p in pulses]
    est = path.length() / min(u[path.ix], 1.0) + abs(float(seg.end[path.ic] - seg.start[path.ic])) / u[path.ic]
    n = int(min(max(est, 8.0), 4e6)) + 1
    t = np.linspace(0.0, 1.0, n)
    rows = _rows(path, seg, pulses, p0, t)
    for _ in range(MAX_REFINE):
        jump = np.abs(np.diff(rows, axis=0)).max(axis=1) > 1
        if not jump.any():
            break
        idx = np.nonzero(jump)[0]
        t = np.sort(np.concatenate((t, (t[idx] + t[idx + 1]) / 2)))
        rows = _rows(path, seg, pulses, p0, t)
    else:  # pragma: no cover - the interpreter refuses paths through the centre
        raise InvalidArgument(f"block {seg.block}: polar move too close to the centre of rotation to interpolate")
    p1 = tuple(round_pulse(v, q) for v, q in zip(seg.end, pulses))
    keep = np.ones(rows.shape[0], dtype=bool)
    keep[1:] = np.abs(np.diff(rows, axis=0)).max(axis=1) > 0
    return join_steps((tuple(r) for r in rows[keep].tolist()), tuple(p0), p1)


def polar_walk(seg: Segment, pulses: tuple[Fraction, ...], p0: tuple[int, ...]) -> tuple[np.ndarray, float]:
    """The pulse positions of a polar move and the length its feed applies to (``Controller.plan``).

    The length is the path length in the polar plane: F is the tangential feed there (Fanuc).
    """
    path = _Path(seg)
    return polar_positions(seg, pulses, p0), path.length()
