"""Fanuc programmable coordinate transforms: polar coordinates (G16), scaling (G51), programmable mirror
image (G51.1) and coordinate rotation (G68).

Each acts on the *program point* (workpiece coordinates, mm, before offsets) about its centre in the
workpiece system; the machine point is the transformed point plus the offsets (EXT, G54.., G52, G92, tool
length).  The control holds positions as whole least increments, so a point the transform moves off the
decimal grid is rounded to the increment.  A scale factor's point is rational and is rounded exactly,
halves away from zero, as :func:`~nczones.gcode.fanuc.expr.round_to` rounds; scaling and mirroring of
decimals stay exact where they land on the grid.

A rotation (G68) or a polar point (G16) involves cosines and sines: the point is *certified*, not computed
in doubles. The cosine and sine of the decimal angle are enclosed in rational intervals by the exact core
(:func:`nczones.exact.sin_cos_degrees`; exact where they are rational: multiples of 30 or 90 degrees, by
Niven's theorem the only rational values), the coordinate is enclosed in a rational interval around the
exact real value, and it is rounded to the nearest increment only when no rounding tie (a halfway point
between two increments) lies within :data:`TIE_GUARD` increments of that interval: then every control that
computes the point to within that guard and rounds to nearest, whatever it does with halves, stands on the
same increment. Otherwise :class:`PointNotCertain` is raised and the block is ``unknown`` (the point is not
known exactly). One transform at a time: their order when combined differs between the manuals' models, and
a combination is ``unknown``.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ...exact import Bounds, sin_cos_degrees
from ...precompiled import dataclass  # start-up: no dataclasses import
from .expr import round_to

__all__ = ["Rotation", "Scaling", "Mirror", "Polar", "PointNotCertain", "TIE_GUARD", "cos_sin_enclosure",
           "certified_round", "rotate", "scale", "mirror", "polar_point"]

#: How close (in least increments) to a rounding tie a rotated or polar coordinate may be before the point
#: counts as not known: the precision the control is assumed to compute a transform with.
TIE_GUARD = Fraction(1, 10**6)


class PointNotCertain(Exception):
    """A rotated or polar coordinate lies within :data:`TIE_GUARD` increments of a rounding tie.

    ``reason`` says which; ``point`` is the nearest-increment candidate (for a caller that goes on after
    recording the block as unknown)."""

    def __init__(self, reason: str, point: list[Fraction]):
        super().__init__(reason)
        self.reason = reason
        self.point = point


def cos_sin_enclosure(angle_deg: Fraction) -> tuple[Bounds, Bounds]:
    """Rational intervals that contain ``cos`` and ``sin`` of ``angle_deg`` degrees (points where exact):
    :func:`nczones.exact.sin_cos_degrees` as pairs.

    >>> cos_sin_enclosure(Fraction(90))
    ((Fraction(0, 1), Fraction(0, 1)), (Fraction(1, 1), Fraction(1, 1)))
    >>> (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(Fraction(45))
    >>> c_lo**2 < Fraction(1, 2) < c_hi**2 and s_lo**2 < Fraction(1, 2) < s_hi**2 and c_hi - c_lo < 1e-25
    True
    """
    s, c = sin_cos_degrees(Fraction(angle_deg))
    return c.bounds(), s.bounds()


def _times(v: Fraction, iv: Bounds) -> Bounds:
    a, b = v * iv[0], v * iv[1]
    return (a, b) if a <= b else (b, a)


def certified_round(enclosure: Bounds, step: Fraction) -> Fraction | None:
    """The multiple of ``step`` nearest to every value of ``enclosure`` widened by :data:`TIE_GUARD`
    steps, or None when a rounding tie (a halfway point between two multiples) lies within that.

    >>> step = Fraction(1, 1000)
    >>> certified_round((Fraction("0.0004"), Fraction("0.0004")), step)
    Fraction(0, 1)
    >>> certified_round((Fraction("0.0005"), Fraction("0.0005")), step) is None  # a tie: a control's halves
    True
    """
    lo = enclosure[0] / step - TIE_GUARD - Fraction(1, 2)
    hi = enclosure[1] / step + TIE_GUARD - Fraction(1, 2)
    if math.floor(hi) >= math.ceil(lo):  # an integer k with lo <= k <= hi: the tie (k + 1/2) step
        return None
    return (math.floor(hi) + 1) * step


def _coordinate(terms: list[tuple[Fraction, Bounds]], step: Fraction, what: str) -> Fraction:
    lo = sum((_times(v, iv)[0] for v, iv in terms), Fraction(0))
    hi = sum((_times(v, iv)[1] for v, iv in terms), Fraction(0))
    got = certified_round((lo, hi), step)
    if got is None:
        raise PointNotCertain(f"{what} is {float((lo + hi) / 2):.12g} mm, within {TIE_GUARD} increments of "
                              f"halfway between two increments of {step} mm: the increment the control "
                              "stands on depends on its arithmetic", [])
    return got


@dataclass(frozen=True, slots=True)
class Rotation:
    """G68: the plane's axes ``(ia, ib)``, the centre ``(ca, cb)`` (program mm) and the angle (degrees)."""

    ia: int
    ib: int
    ca: Fraction
    cb: Fraction
    angle: Fraction


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
    """The rotated point, certified and rounded to ``step`` (module docstring); the other axes unchanged.

    Raises :class:`PointNotCertain` when a coordinate is within :data:`TIE_GUARD` of a rounding tie.

    >>> r = Rotation(0, 1, Fraction(0), Fraction(0), Fraction(90))
    >>> rotate(r, [Fraction(10), Fraction(0), Fraction(5)], Fraction(1, 1000))
    [Fraction(0, 1), Fraction(10, 1), Fraction(5, 1)]
    >>> rotate(Rotation(0, 1, Fraction(0), Fraction(0), Fraction(30)), [Fraction(0), Fraction(1, 1000)],
    ...        Fraction(1, 1000))  # x' = -0.001 sin 30 = -0.0005 exactly, a tie
    Traceback (most recent call last):
    ...
    nczones.gcode.fanuc.transforms.PointNotCertain: G68 rotation: X is -0.0005 mm, ...
    """
    c, s = cos_sin_enclosure(rot.angle)
    x = p[rot.ia] - rot.ca
    y = p[rot.ib] - rot.cb
    out = list(p)
    names = "XYZABCUVW"
    try:
        out[rot.ia] = rot.ca + _coordinate([(x, c), (-y, s)], step, f"G68 rotation: {_axis(names, rot.ia)}")
        out[rot.ib] = rot.cb + _coordinate([(x, s), (y, c)], step, f"G68 rotation: {_axis(names, rot.ib)}")
    except PointNotCertain as e:
        raise PointNotCertain(e.reason, _nearest(rot, p, step)) from None
    return out


def _axis(names: str, i: int) -> str:
    return names[i] if i < len(names) else f"axis {i + 1}"


def _nearest(rot: Rotation, p: list[Fraction], step: Fraction) -> list[Fraction]:
    """A candidate point (the enclosures' midpoints, rounded) for a caller that goes on after the block
    became unknown."""
    (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(rot.angle)
    c, s = (c_lo + c_hi) / 2, (s_lo + s_hi) / 2
    x, y = p[rot.ia] - rot.ca, p[rot.ib] - rot.cb
    out = list(p)
    out[rot.ia] = rot.ca + round_to((None, x * c - y * s), step)
    out[rot.ib] = rot.cb + round_to((None, x * s + y * c), step)
    return out


def scale(sc: Scaling, p: list[Fraction], step: Fraction) -> list[Fraction]:
    """``centre + factor * (p - centre)`` per axis, rounded to ``step`` where it leaves the grid.

    >>> scale(Scaling((Fraction(0), Fraction(0)), (Fraction(1, 2), Fraction(1))), [Fraction(3), Fraction(3)],
    ...       Fraction(1, 1000))
    [Fraction(3, 2), Fraction(3, 1)]
    """
    out = []
    for v, c, f in zip(p, sc.centre, sc.factors):
        # a coordinate at its centre is not moved, so not rounded either: in G20 a centre taken from the
        # current position may lie off the inch grid (a metric work offset), and the axis stays where it is
        if f == 1 or v == c:
            out.append(v)
            continue
        q = c + f * (v - c)
        out.append(q if (q / step).denominator == 1 else round_to((None, q), step))
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
    """``(r cos a, r sin a)`` (degrees), certified and rounded to ``step`` (module docstring).

    Raises :class:`PointNotCertain` when a coordinate is within :data:`TIE_GUARD` of a rounding tie.

    >>> polar_point(Fraction(10), Fraction(30), Fraction(1, 1000))
    (Fraction(433, 50), Fraction(5, 1))
    >>> polar_point(Fraction(1, 1000), Fraction(30), Fraction(1, 1000))  # 0.001 sin 30 = 0.0005, a tie
    Traceback (most recent call last):
    ...
    nczones.gcode.fanuc.transforms.PointNotCertain: G16 polar point: the angle axis is 0.0005 mm, ...
    """
    c, s = cos_sin_enclosure(angle)
    try:
        return (_coordinate([(radius, c)], step, "G16 polar point: the radius axis"),
                _coordinate([(radius, s)], step, "G16 polar point: the angle axis"))
    except PointNotCertain as e:
        mid_c, mid_s = (c[0] + c[1]) / 2, (s[0] + s[1]) / 2
        raise PointNotCertain(e.reason, [round_to((None, radius * mid_c), step),
                                         round_to((None, radius * mid_s), step)]) from None
