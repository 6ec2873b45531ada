"""Geometry of polar coordinate interpolation (G12.1 / G112): the programmed plane, exactly enclosed.

In polar coordinate interpolation (Fanuc G12.1, G13.1 cancels; Haas G112,
G113) a turning centre mills a face with its linear axis X and its rotary
axis C: the program describes a path in a Cartesian plane fixed to the
workpiece — the first coordinate ``x`` on X (the distance from the centre of
rotation), the second ``y`` the *hypothetical axis*, written with the rotary
axis' address C — and the control moves the machine so that the tool follows
that path:

* machine X = ``x_off + sqrt(x**2 + y**2)`` (a radius; ``x_off`` is the
  machine X of the centre of rotation: the work and tool offsets on X),
* machine C = ``c_entry + theta`` degrees, ``theta`` the plane angle of
  ``(x, y)`` measured from the point where G12.1 found the tool (angle 0),
  *continuous* along the path (unwound: it may pass 180 or 360 degrees).

``sqrt`` and ``atan2`` of rationals are irrational, so every machine
quantity here is an :class:`~nczones.geometry.cylinder.Interval` of rationals that
contains the exact value (the elementary functions of
:mod:`nczones.geometry.cylinder`: series with remainder bounds, outward rounding on a
``2**-200`` grid).  No float is used.

A polar move (``SegmentKind.POLAR``) is a straight line or a circular arc in
the plane, described by :class:`PolarMove`: plane start and end (exact),
for an arc its centre (exact for I/J, enclosed for R) and direction, the
number of whole turns of the start angle (the unwound start angle is
``atan2(y0, x0) + 360 * turns`` degrees), ``x_off`` and ``c_entry``.  Other
axes (Z) move linearly with the path parameter.

Invariants: :meth:`PolarMove.point` encloses the exact plane point at a
fraction of the path (of its length for a line, of its swept angle for an
arc); :meth:`PolarMove.box` encloses the exact sub-path between two
fractions; :func:`angle_range` and :func:`radius_range` enclose the angles
(unwound near a given angle) and the distances from the centre of rotation of
every point of a box that does not contain the centre.
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache
from typing import TYPE_CHECKING

from ..exact import (
    Interval,
    asin_interval,
    atan2_interval,
    degrees,
    pi_interval,
    round_up_scaled,
    sin_cos_interval,
)
from ..motion import PolarData
from ..precompiled import dataclass  # start-up: no dataclasses import

if TYPE_CHECKING:
    from ..motion import Segment

__all__ = [
    "PolarMove",
    "PlaneArc",
    "CentreCrossing",
    "atan2_deg",
    "angle_range",
    "radius_range",
    "plane_arc",
    "polar_move",
    "polar_move_of",
    "walk_angle",
    "MAX_WALK_DEPTH",
]

F0 = Fraction(0)
F1 = Fraction(1)
Point = tuple[Fraction, Fraction]
IPoint = tuple[Interval, Interval]

#: Deepest halving when following the unwound angle along a move (pieces of ``2**-MAX_WALK_DEPTH``).
MAX_WALK_DEPTH = 64


class CentreCrossing(ValueError):
    """The path passes through (or within the resolution of the enclosures of) the centre of rotation."""


def atan2_rad(x: Fraction, y: Fraction) -> Interval:
    """Enclosure of ``atan2(y, x)`` in ``(-pi, pi]`` radians, for a rational point other than the origin
    (:func:`nczones.exact.atan2_interval`; the origin is a :class:`CentreCrossing`).

    >>> a = atan2_rad(Fraction(-1), Fraction(0))
    >>> a.contains(Fraction(314159, 100000)) or a.lo > 3
    True
    """
    if x == 0 and y == 0:
        raise CentreCrossing("the angle of the centre of rotation is undefined")
    return atan2_interval(y, x)


@lru_cache(maxsize=1 << 16)
def atan2_deg(x: Fraction, y: Fraction) -> Interval:
    """``atan2(y, x)`` in degrees, in ``(-180, 180]``, enclosed.

    Cached: the interpreter (following the angle) and the prover (enclosing it) meet the same rational
    points, box corners and piece ends.

    >>> a = atan2_deg(Fraction(1), Fraction(1))
    >>> a.lo <= 45 <= a.hi, a.width() < Fraction(1, 10**50)
    (True, True)
    """
    return degrees(atan2_rad(x, y))


def _unwrap(a: Interval, near: Fraction) -> Interval:
    """``a + 360 k`` for the whole ``k`` that brings the middle of ``a`` nearest to ``near``."""
    k = round((near - a.mid()) / 360)
    return a + 360 * k if k else a


def angle_range(bx: Interval, by: Interval, near: Fraction) -> Interval | None:
    """The angles (degrees, unwound near ``near``) of every point of the box ``bx x by``.

    ``near`` must be (within far less than a degree) the unwound angle of a
    point of the box.  None when the box contains the centre of rotation or
    subtends 179 degrees or more (then the branch of some corner could be
    wrong; the caller cuts the box smaller).  A convex set without the centre
    sees it under less than 180 degrees, and the extreme directions are those
    of its corners.

    >>> F = Fraction
    >>> r = angle_range(Interval(F(1), F(2)), Interval(F(0), F(1)), F(10))
    >>> r.lo <= 0 and 45 <= r.hi < 46
    True
    >>> angle_range(Interval(F(-1), F(1)), Interval(F(-1), F(1)), F(0)) is None
    True
    """
    if bx.lo <= 0 <= bx.hi and by.lo <= 0 <= by.hi:
        return None
    out: Interval | None = None
    for x, y in {(x, y) for x in (bx.lo, bx.hi) for y in (by.lo, by.hi)}:
        a = _unwrap(atan2_deg(x, y), near)
        out = a if out is None else out.hull(a)
    assert out is not None  # four corners
    if out.width() >= 179:
        return None
    return out


def radius_range(bx: Interval, by: Interval) -> Interval:
    """The distances from the centre of rotation of the points of the box ``bx x by``, enclosed.

    >>> F = Fraction
    >>> r = radius_range(Interval(F(3), F(4)), Interval(F(-1), F(4)))
    >>> r.lo == 3, r.hi >= F(5656, 1000)
    (True, True)
    """
    def near0(iv: Interval) -> Fraction:
        if iv.lo <= 0 <= iv.hi:
            return F0
        return min(abs(iv.lo), abs(iv.hi))

    def far(iv: Interval) -> Fraction:
        return max(abs(iv.lo), abs(iv.hi))

    lo2 = near0(bx) ** 2 + near0(by) ** 2
    hi2 = far(bx) ** 2 + far(by) ** 2
    return Interval(Interval.of(lo2).sqrt().lo, Interval.of(hi2).sqrt().hi)


# --------------------------------------------------------------------------- arcs in the plane


@dataclass(frozen=True)
class PlaneArc:
    """A G02/G03 in the polar plane: centre, start vector, swept angle (enclosures).

    The path is ``centre + s(f) * rot(u, ±f * sweep)`` for ``f`` in [0, 1]:
    ``u`` the start minus the centre, ``rot`` a rotation counter-clockwise for
    G03 (clockwise for G02), ``s(f) = 1 + f (ratio - 1)`` the radius growing
    linearly from the start radius to the end radius (``ratio`` = end radius /
    start radius: 1 for R arcs; an I/J arc whose end is not on the start's
    circle — within the arc tolerance — is a spiral, as controls interpolate
    it).  The first axis (x) is to the right, the second (y) up: G02 is
    clockwise seen so.
    """

    centre: IPoint
    u: IPoint
    rho: Interval  # start radius
    ratio: Interval
    sweep: Interval  # radians, in (0, 2 pi]
    clockwise: bool
    rho_max: Fraction  # upper bound of the radius along the arc

    def point(self, f: Fraction) -> IPoint:
        phi = self.sweep * Fraction(f)
        sn, cs = sin_cos_interval(phi)
        if self.clockwise:
            sn = -sn
        ux, uy = self.u
        s = 1 + (self.ratio - 1) * Fraction(f)
        x = self.centre[0] + s * (ux * cs - uy * sn)
        y = self.centre[1] + s * (ux * sn + uy * cs)
        return x, y

    def length(self) -> Interval:
        """Arc length (the mean radius times the sweep for a spiral, within its small error)."""
        return self.rho * (1 + self.ratio) / 2 * self.sweep


def plane_arc(p0: Point, p1: Point, clockwise: bool, *, centre: Point | None = None,
              radius: Fraction | None = None) -> PlaneArc:
    """The enclosed geometry of an arc in the polar plane (I/J: ``centre`` exact; R: signed ``radius``).

    With I/J the arc runs from ``p0`` around ``centre`` to the direction of
    ``p1`` (equal directions: a full circle); with R the centre is the point at
    distance ``|R|`` from both ends to the right of the chord for G02 with
    R > 0 (left for G03; a negative R the other side: more than 180 degrees),
    the chord midpoint when the chord is at least ``2 |R|`` (the interpreter
    accepts that only within its arc tolerance).

    >>> F = Fraction
    >>> a = plane_arc((F(20), F(10)), (F(10), F(20)), False, radius=F(10))
    >>> [round(float(v.mid()), 6) for v in a.centre], [round(float(v.mid()), 6) for v in a.point(F(1, 2))]
    ([10.0, 10.0], [17.071068, 17.071068])
    """
    x0, y0 = p0
    x1, y1 = p1
    if centre is not None:
        cx, cy = centre
        ux, uy = x0 - cx, y0 - cy
        vx, vy = x1 - cx, y1 - cy
        r0sq, r1sq = ux * ux + uy * uy, vx * vx + vy * vy
        if r0sq == 0:
            raise ValueError("arc whose centre is its start point")
        if r1sq == 0:
            raise ValueError("arc whose centre is its end point")
        cross = ux * vy - uy * vx
        dot = ux * vx + uy * vy
        if clockwise:
            cross = -cross
        two_pi = 2 * pi_interval()
        if cross == 0 and dot > 0:
            sweep = two_pi  # equal directions: a full circle (end on the start's ray)
        else:
            a = atan2_rad(dot, cross)  # the angle from u to v in the arc's direction, (-pi, pi]
            sweep = a if cross > 0 or (cross == 0 and dot < 0) else a + two_pi
        rho = Interval.of(r0sq).sqrt()
        ratio = Interval.of(r1sq).sqrt() / rho
        rho_max = max(rho.hi, (rho * ratio).hi)
        return PlaneArc((Interval.of(cx), Interval.of(cy)), (Interval.of(ux), Interval.of(uy)), rho, ratio,
                        sweep, clockwise, rho_max)
    if radius is None or radius == 0:
        raise ValueError("an R arc needs a radius other than zero")
    if p0 == p1:
        raise ValueError("R-format arc with equal start and end points")
    r = Fraction(radius)
    dx, dy = x1 - x0, y1 - y0
    l2 = dx * dx + dy * dy
    q = Interval.of(r * r / l2 - Fraction(1, 4))
    half_circle = q.hi <= 0
    right = (clockwise and r > 0) or (not clockwise and r < 0)
    nx, ny = (dy, -dx) if right else (-dy, dx)
    mx, my = x0 + dx / 2, y0 + dy / 2
    if half_circle:
        c = (Interval.of(mx), Interval.of(my))
    else:
        t = q.sqrt()
        c = (mx + t * nx, my + t * ny)
    u = (x0 - c[0], y0 - c[1])
    rho_iv = (u[0].sqr() + u[1].sqr()).sqrt()
    half_chord = Interval.of(l2).sqrt() / 2
    if half_circle:
        sweep = pi_interval()
    else:
        s = half_chord / Interval.of(abs(r))
        minor = 2 * asin_interval(Interval(max(s.lo, F0), s.hi))
        sweep = minor if r > 0 else 2 * pi_interval() - minor
    return PlaneArc(c, u, rho_iv, Interval.of(1), sweep, clockwise, rho_iv.hi)


# --------------------------------------------------------------------------- polar moves


@dataclass(frozen=True)
class PolarMove:
    """One motion in polar coordinate interpolation (see the module docstring)."""

    p0: Point
    p1: Point
    turns: int
    x_off: Fraction
    c_entry: Fraction
    arc: PlaneArc | None = None

    def point(self, f: Fraction) -> IPoint:
        """Enclosure of the exact plane point at fraction ``f``."""
        if self.arc is not None:
            return self.arc.point(f)
        x0, y0 = self.p0
        x1, y1 = self.p1
        f = Fraction(f)
        return Interval.of(x0 + (x1 - x0) * f), Interval.of(y0 + (y1 - y0) * f)

    def box(self, fa: Fraction, fb: Fraction) -> IPoint:
        """Enclosure of the sub-path between fractions ``fa <= fb`` (``fb - fa <= 1/4`` for an arc).

        An arc piece lies in the box of its ends grown by its sagitta
        ``rho (1 - cos(alpha/2)) <= rho alpha**2 / 8`` plus twice the change of
        the radius along the piece (a spiral).
        """
        xa, ya = self.point(fa)
        xb, yb = self.point(fb)
        bx, by = xa.hull(xb), ya.hull(yb)
        if self.arc is None:
            return bx, by
        if not (0 <= fa <= fb <= 1) or fb - fa > Fraction(1, 4):
            raise ValueError("arc piece fractions must satisfy 0 <= fa <= fb <= 1, fb - fa <= 1/4")
        arc = self.arc
        alpha = arc.sweep.hi * (fb - fa)
        grow = (arc.ratio - 1) * (fb - fa) * arc.rho
        h = round_up_scaled(arc.rho_max * alpha * alpha / 8 + 2 * max(abs(grow.lo), abs(grow.hi)))
        return bx.widen(h), by.widen(h)

    def start_angle(self) -> Interval:
        """The unwound plane angle of the start (degrees; the machine C is ``c_entry`` plus it)."""
        return atan2_deg(*self.p0) + 360 * self.turns

    def length(self) -> Interval:
        """Path length in the plane (mm): the feed applies to it."""
        if self.arc is not None:
            return self.arc.length()
        dx, dy = self.p1[0] - self.p0[0], self.p1[1] - self.p0[1]
        return Interval.of(dx * dx + dy * dy).sqrt()

    def first_pieces(self) -> list[tuple[Fraction, Fraction]]:
        """The pieces a walk starts from: the whole line, an arc's quarters."""
        if self.arc is None:
            return [(F0, F1)]
        return [(Fraction(i, 4), Fraction(i + 1, 4)) for i in range(4)]


def point_angle(p: IPoint, near: Fraction) -> Interval:
    """The unwound angle of a (tiny) point enclosure, near ``near``; CentreCrossing if it holds the centre."""
    got = angle_range(p[0], p[1], near)
    if got is None:
        raise CentreCrossing("a path point is within the enclosure resolution of the centre of rotation")
    return got


def walk_angle(move: PolarMove, max_depth: int = MAX_WALK_DEPTH) -> Interval:
    """The unwound angle (degrees) at the end of ``move``: its start angle plus the continuous turn along it.

    The path is cut into pieces whose boxes do not contain the centre of
    rotation (so the angle changes by less than 179 degrees across each, and
    the branch of each next point is the one nearest the last).  Raises
    :class:`CentreCrossing` when a piece of ``2**-max_depth`` of the path
    still meets the centre.

    >>> F = Fraction
    >>> m = PolarMove((F(10), F(0)), (F(-10), F(0)), 0, F(0), F(0), plane_arc((F(10), F(0)), (F(-10), F(0)), False, centre=(F(0), F(0))))
    >>> a = walk_angle(m)
    >>> a.lo < 180 < a.hi
    True
    """
    theta = move.start_angle()
    stack = [(fa, fb, 0) for fa, fb in reversed(move.first_pieces())]
    while stack:
        fa, fb, depth = stack.pop()
        bx, by = move.box(fa, fb)
        if angle_range(bx, by, theta.mid()) is not None:
            theta = point_angle(move.point(fb), theta.mid())
            continue
        if depth >= max_depth:
            raise CentreCrossing("the path passes through the centre of rotation (or within "
                                 f"2**-{max_depth} of its length of it)")
        mid = (fa + fb) / 2
        stack.append((mid, fb, depth + 1))
        stack.append((fa, mid, depth + 1))
    return theta


def polar_move(p0: Point, p1: Point, turns: int, x_off: Fraction, c_entry: Fraction, *, clockwise: bool = False,
               centre: Point | None = None, radius: Fraction | None = None, arc: bool = False) -> PolarMove:
    """A :class:`PolarMove` (``arc``: G02/G03 with ``centre`` (I/J) or ``radius`` (R))."""
    pa = plane_arc(p0, p1, clockwise, centre=centre, radius=radius) if arc else None
    return PolarMove(p0, p1, turns, x_off, c_entry, pa)


def polar_of(seg: Segment) -> PolarData | None:
    """The polar data a segment made in G12.1 mode carries in ``Segment.extra`` (``None`` otherwise)."""
    return seg.payload(PolarData)


def polar_move_of(seg: Segment) -> PolarMove:
    """The :class:`PolarMove` of a ``SegmentKind.POLAR`` segment."""
    e = polar_of(seg)
    if e is None:
        raise ValueError("not a motion made in polar coordinate interpolation (G12.1)")
    return polar_move(e.start, e.end, e.turns, e.x_off, e.c_entry, clockwise=seg.clockwise, centre=e.centre,
                      radius=e.radius, arc=e.arc)
