"""Pulse distribution along SPLINE segments (exact NURBS curves).

The curve (:func:`nczones.geometry.nurbs.spline_curve`) is cut at its knots
and each piece is halved by exact knot insertion until it is *flat*: every
control point ``P_j`` of a piece with ``n + 1`` points lies within
:data:`FLATNESS` pulses, on every axis, of the chord point
``A + (j / n) (B - A)`` (``A``, ``B`` the piece's end points, which are
exact curve points).  The piece lies in the convex hull of its control
points and the set of points within ``FLATNESS`` pulses (per axis) of the
chord is convex, so the whole piece is within ``FLATNESS`` pulses of its
chord.  Pulses are then distributed along the chords between the rounded
curve points exactly as for straight lines (within one pulse of the
chord).

Deviation bound: the commanded pulse position stays within
``1 + FLATNESS`` = 1.25 pulses of the exact curve on every axis (one pulse
for a straight line, DESIGN §7, plus the flatness), so spline motion that
passes within 1.25 pulses of a zone boundary is in the contract's gray band
(specs/contract.md, specs/gcode-support.md).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidArgument
from ..geometry.nurbs import spline_curve
from ..motion import Segment
from .pulses import line_steps, round_pulse

__all__ = ["FLATNESS", "spline_chord_points", "spline_positions", "spline_walk"]

#: Allowed distance (in pulses, per axis) of a piece's control polygon from its chord.
FLATNESS = Fraction(1, 4)
_MAX_DEPTH = 40


def _flat(c: Any, pulse: Sequence[Fraction]) -> bool:
    pts = c.points
    a, b = pts[0], pts[-1]
    n = len(pts) - 1
    for j, p in enumerate(pts[1:-1], start=1):
        t = Fraction(j, n)
        for k, u in enumerate(pulse):
            if abs(p[k] - (a[k] + t * (b[k] - a[k]))) > FLATNESS * u:
                return False
    return True


def spline_chord_points(seg: Segment, pulse: Sequence[Fraction]) -> list[tuple[Fraction, ...]]:
    """Exact curve points (start to end) whose chords are within FLATNESS pulses of the curve."""
    curve = spline_curve(seg)
    out = [curve.points[0]]
    for piece in curve.pieces():
        stack = [(piece, 0)]
        while stack:
            c, depth = stack.pop()
            if _flat(c, pulse):
                out.append(c.points[-1])
                continue
            if depth >= _MAX_DEPTH:
                raise InvalidArgument(f"block {seg.block}: spline could not be flattened to {FLATNESS} pulse")
            lo, hi = c.domain
            left, right = c.split((lo + hi) / 2)
            stack.append((right, depth + 1))
            stack.append((left, depth + 1))
    return out


def spline_positions(seg: Segment, pulse: Sequence[Fraction], p0: Sequence[int]) -> np.ndarray:
    """Pulse positions after each step (shape (n, axes)), starting from ``p0``."""
    steps: list[tuple[int, ...]] = []
    cur = tuple(p0)
    for pt in spline_chord_points(seg, pulse)[1:]:
        nxt = tuple(round_pulse(v, u) for v, u in zip(pt, pulse))
        if nxt != cur:
            steps.extend(line_steps(cur, nxt))
            cur = nxt
    return np.array(steps, dtype=np.int64).reshape(len(steps), len(p0))


def spline_walk(seg: Segment, pulse: Sequence[Fraction], p0: tuple[int, ...]) -> tuple[np.ndarray, float]:
    """The pulse positions of a spline and the length of its chords (``Controller.plan``)."""
    pos = spline_positions(seg, pulse, p0)
    pts = spline_chord_points(seg, pulse)
    return pos, sum(math.dist([float(v) for v in a], [float(v) for v in b]) for a, b in zip(pts, pts[1:]))
