"""Fanuc programmable coordinate transforms: polar coordinates (G16), scaling (G51), programmable mirror
image (G51.1) and coordinate rotation (G68).

Each acts on the *program point* (workpiece coordinates, mm, before offsets) about its centre in the
workpiece system; the machine point is the transformed point plus the offsets (EXT, G54.., G52, G92, tool
length).  The control holds positions as whole least increments, so a point the transform moves off the
decimal grid (a rotation, a polar point, a scale factor) is rounded to the increment, halves away from zero,
as :func:`~nczones.gcode.fanuc.expr.round_to` rounds; scaling and mirroring of decimals stay exact where
they land on the grid.  One transform at a time: their order when combined differs between the manuals'
models, and a combination is ``unknown``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from .expr import round_to

__all__ = ["Rotation", "Scaling", "Mirror", "Polar", "rotate", "scale", "mirror", "polar_point"]


@dataclass(frozen=True, slots=True)
class Rotation:
    """G68: the plane's axes ``(ia, ib)``, the centre ``(ca, cb)`` (program mm) and the angle (degrees)."""

    ia: int
    ib: int
    ca: Fraction
    cb: Fraction
    angle: Fraction

    @property
    def cos_sin(self) -> tuple[float, float]:
        t = float(self.angle) * math.pi / 180.0
        return math.cos(t), math.sin(t)


@dataclass(frozen=True, slots=True)
class Scaling:
    """G51: the centre and the factor per axis (1 for an axis not scaled)."""

    centre: tuple[Fraction, ...]
    factors: tuple[Fraction, ...]


@dataclass(frozen=True, slots=True)
class Mirror:
    """G51.1: the mirror position per mirrored axis (axis index -> position, program mm)."""

    axes: tuple[tuple[int, Fraction], ...]


@dataclass(frozen=True, slots=True)
class Polar:
    """G16 in a plane: the radius axis ``ia`` and the angle axis ``ib``; the last radius and angle."""

    ia: int
    ib: int
    radius: Fraction | None = None
    angle: Fraction | None = None


def rotate(rot: Rotation, p: list[Fraction], step: Fraction) -> list[Fraction]:
    """The rotated point (doubles, rounded to ``step``); the other axes unchanged.

    >>> r = Rotation(0, 1, Fraction(0), Fraction(0), Fraction(90))
    >>> rotate(r, [Fraction(10), Fraction(0), Fraction(5)], Fraction(1, 1000))
    [Fraction(0, 1), Fraction(10, 1), Fraction(5, 1)]
    """
    c, s = rot.cos_sin
    x = float(p[rot.ia] - rot.ca)
    y = float(p[rot.ib] - rot.cb)
    out = list(p)
    out[rot.ia] = rot.ca + round_to((x * c - y * s, None), step)
    out[rot.ib] = rot.cb + round_to((x * s + y * c, None), step)
    return out


def scale(sc: Scaling, p: list[Fraction], step: Fraction) -> list[Fraction]:
    """``centre + factor * (p - centre)`` per axis, rounded to ``step`` where it leaves the grid.

    >>> scale(Scaling((Fraction(0), Fraction(0)), (Fraction(1, 2), Fraction(1))), [Fraction(3), Fraction(3)],
    ...       Fraction(1, 1000))
    [Fraction(3, 2), Fraction(3, 1)]
    """
    out = []
    for v, c, f in zip(p, sc.centre, sc.factors):
        q = c + f * (v - c) if f != 1 else v
        out.append(q if (q / step).denominator == 1 else round_to((float(q), q), step))
    return out


def mirror(mi: Mirror, p: list[Fraction]) -> list[Fraction]:
    """``2 * position - p`` on the mirrored axes (exact).

    >>> mirror(Mirror(((0, Fraction(5)),)), [Fraction(7), Fraction(1)])
    [Fraction(3, 1), Fraction(1, 1)]
    """
    out = list(p)
    for i, c in mi.axes:
        out[i] = 2 * c - p[i]
    return out


def polar_point(radius: Fraction, angle: Fraction, step: Fraction) -> tuple[Fraction, Fraction]:
    """``(r cos a, r sin a)`` (degrees), rounded to ``step``.

    >>> polar_point(Fraction(10), Fraction(30), Fraction(1, 1000))
    (Fraction(433, 50), Fraction(5, 1))
    """
    t = float(angle) * math.pi / 180.0
    r = float(radius)
    return round_to((r * math.cos(t), None), step), round_to((r * math.sin(t), None), step)
