"""Geometry of cylindrical interpolation (G07.1): the developed surface, exactly enclosed.

In cylindrical interpolation the program describes a path on the cylinder's
*developed* (unrolled) surface: the linear axis along the cylinder (Z for a
C rotary axis) and the developed rotary coordinate ``s`` in millimetres.  The
controller interpolates in that plane and converts ``s`` into the rotary
displacement ``angle (rad) = s / R`` (JP patent 001, "angle = developed
length / radius"), in degrees ``C = s * 180 / (pi R)``.

Because of pi, the developed coordinate of an angle given in degrees is
irrational: ``s = k C`` with ``k = pi R / 180`` (mm per degree).  Straight
moves stay straight in machine coordinates (``s`` is linear in ``C``), so a
G01 in the mode is an ordinary exact LINE.  A G02/G03 is a circle in
``(Z, s)`` — an ellipse in ``(Z, C)`` whose chord end lies at the irrational
developed distance ``D = k (C1 - C0)`` — so its geometry is *enclosed*: every
quantity here is an :class:`~nczones.exact.Interval` of rationals that
contains the exact value (pi, square roots, sines, cosines and arc sines from
the exact core :mod:`nczones.exact`; all rounding outward on a
``2**-GRID_BITS`` grid).  ``Interval``, ``pi_interval``, ``atan_point``,
``asin_interval``, ``sin_cos_interval`` and ``GRID_BITS`` are the core's,
re-exported here for the callers that name them from this module.

Conventions of a developed arc (``SegmentKind.DEVELOPED_ARC``)
---------------------------------------------------------------
* The plane is (first, second) = (linear axis, developed rotary axis): Z and
  C for a C axis (Fanuc's G18 with C in place of X), X and A for A, Y and B
  for B (:data:`LINEAR_AXIS_OF`).  ``clockwise`` is judged as everywhere in
  nczones: first axis to the right, second axis up.
* ``s`` is measured from the segment's start angle: the start is
  ``(Z0, 0)``, the end ``(Z1, D)``.
* ``radius`` is the programmed signed R in developed millimetres; the centre
  is the point at distance ``|R|`` from both ends to the right of the chord
  for G02 with ``R > 0`` (left for G03; a negative R the other side: the arc
  of more than 180 degrees), as for ordinary R-format arcs.  A chord longer
  than ``2 |R|`` (accepted by the interpreter only within its arc
  tolerance) gives the chord midpoint as centre (a half circle).

Invariants: every :class:`Interval` contains the exact quantity it names;
:meth:`DevelopedArc.point` encloses the exact path point at a fraction of the
swept angle, :meth:`DevelopedArc.box` the exact sub-arc between two
fractions.  No float is used.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

from ..exact import (
    GRID_BITS,
    Interval,
    asin_interval,
    pi_interval,
    round_up_scaled,
    sin_cos_interval,
)
from ..exact import atan_interval as atan_point
from ..motion import Developed

if TYPE_CHECKING:
    from ..motion import Segment

__all__ = [
    "GRID_BITS",
    "LINEAR_AXIS_OF",
    "Interval",
    "pi_interval",
    "atan_point",
    "asin_interval",
    "sin_cos_interval",
    "degree_length",
    "DevelopedArc",
    "developed_arc",
    "developed_arc_of",
    "cylinder_of",
]

#: The linear axis parallel to each rotary axis (the cylinder's axis).
LINEAR_AXIS_OF = {"A": "X", "B": "Y", "C": "Z"}

F0 = Fraction(0)
F1 = Fraction(1)


def degree_length(cylinder_radius: Fraction) -> Interval:
    """``k = pi R / 180``: developed millimetres per degree of the rotary axis.

    >>> k = degree_length(Fraction(180))
    >>> k.lo <= pi_interval().hi and pi_interval().lo <= k.hi
    True
    """
    return pi_interval() * Fraction(cylinder_radius) / 180


# --------------------------------------------------------------------------- developed arcs


@dataclass(frozen=True)
class DevelopedArc:
    """A G02/G03 on the developed surface, with enclosures of its exact geometry.

    Attributes (exact): ``z0, c0, z1, c1`` (linear axis mm, rotary axis
    degrees, machine coordinates), ``cylinder_radius`` (mm), ``radius`` (the
    signed programmed R, developed mm), ``clockwise``.  Enclosures: ``k``
    (mm per degree), ``d`` (developed chord component ``k (c1 - c0)``),
    ``centre`` (Z, s) with ``s`` from the start angle, ``u`` (start minus
    centre), ``rho`` (the radius of the moved circle: ``|R|``, or half the
    chord for an over-long chord), ``sweep`` (radians, in ``(0, 2 pi)``),
    ``half_circle`` (the chord-midpoint case).
    """

    z0: Fraction
    c0: Fraction
    z1: Fraction
    c1: Fraction
    cylinder_radius: Fraction
    radius: Fraction
    clockwise: bool
    k: Interval
    d: Interval
    centre: tuple[Interval, Interval]
    u: tuple[Interval, Interval]
    rho: Interval
    sweep: Interval
    half_chord: Interval
    half_circle: bool

    def point(self, f: Fraction) -> tuple[Interval, Interval, Interval]:
        """Enclosure ``(Z, s, C)`` of the exact path point at fraction ``f`` of the swept angle.

        >>> F = Fraction
        >>> a = developed_arc(F(0), F(0), F(10), F(0), F(100), F(5), True)
        >>> z, s, c = a.point(F(1, 2))
        >>> z.contains(5) and s.contains(5) and c.width() < F(1, 10**40)
        True
        """
        phi = self.sweep * Fraction(f)
        sn, cs = sin_cos_interval(phi)
        if self.clockwise:
            sn = -sn
        ux, uy = self.u
        z = self.centre[0] + ux * cs - uy * sn
        s = self.centre[1] + ux * sn + uy * cs
        return z, s, self.c0 + s / self.k

    def box(self, fa: Fraction, fb: Fraction) -> tuple[Interval, Interval, Interval]:
        """Enclosure ``(Z, s, C)`` of the sub-arc between fractions ``fa <= fb`` (``fb - fa <= 1/4``).

        The sub-arc lies in the box of its end points grown by its sagitta
        ``h = rho (1 - cos(alpha/2)) <= rho alpha**2 / 8`` (alpha its angle,
        at most pi/2 here).
        """
        if not (0 <= fa <= fb <= 1) or fb - fa > Fraction(1, 4):
            raise ValueError("sub-arc fractions must satisfy 0 <= fa <= fb <= 1, fb - fa <= 1/4")
        za, sa, _ = self.point(fa)
        zb, sb, _ = self.point(fb)
        alpha = self.sweep.hi * (fb - fa)
        h = round_up_scaled(self.rho.hi * alpha * alpha / 8)
        z = za.hull(zb).widen(h)
        s = sa.hull(sb).widen(h)
        return z, s, self.c0 + s / self.k

    def length(self) -> Interval:
        """Developed arc length ``rho * sweep`` (mm)."""
        return self.rho * self.sweep


def developed_arc(z0: Fraction, c0: Fraction, z1: Fraction, c1: Fraction, cylinder_radius: Fraction,
                  radius: Fraction, clockwise: bool) -> DevelopedArc:
    """The enclosed geometry of a developed arc (see the module docstring).

    Raises ``ValueError`` for a zero radius, equal end points, or a chord
    certainly longer than ``2 |R|`` (the interpreter decides the tolerance
    first and passes only arcs it accepts; then the chord midpoint is the
    centre).

    >>> F = Fraction
    >>> a = developed_arc(F(30), F(30), F(110), F(153), F("37.266"), F(80), True)
    >>> float(a.d.lo) > 80, float(a.sweep.mid()) > 1.57, a.half_circle
    (True, True, False)
    """
    z0, c0, z1, c1 = (Fraction(v) for v in (z0, c0, z1, c1))
    rc, r = Fraction(cylinder_radius), Fraction(radius)
    if rc <= 0:
        raise ValueError(f"cylinder radius must be positive, got {rc}")
    if r == 0:
        raise ValueError("zero arc radius")
    if z0 == z1 and c0 == c1:
        raise ValueError("developed R-format arc with equal start and end points")
    k = degree_length(rc)
    dz = z1 - z0
    d = k * (c1 - c0)
    l2 = d.sqr() + dz * dz
    q = Interval.of(r * r) / l2 - Fraction(1, 4)
    half_circle = q.hi <= 0
    right = (clockwise and r > 0) or (not clockwise and r < 0)
    nz, ns = (d, Interval.of(-dz)) if right else (-d, Interval.of(dz))
    mz, ms = Interval.of(z0 + dz / 2), d / 2
    if half_circle:
        centre = (mz, ms)
    else:
        t = q.sqrt()  # q.lo < 0 is clipped: the enclosure then includes the midpoint case
        centre = (mz + t * nz, ms + t * ns)
    u = (Interval.of(z0) - centre[0], -centre[1])
    rho = (u[0].sqr() + u[1].sqr()).sqrt()
    half_chord = l2.sqrt() / 2
    if half_circle:
        sweep = pi_interval()
    else:
        x = half_chord / Interval.of(abs(r))
        minor = 2 * asin_interval(Interval(max(x.lo, F0), x.hi))
        sweep = minor if r > 0 else 2 * pi_interval() - minor
    return DevelopedArc(z0, c0, z1, c1, rc, r, clockwise, k, d, centre, u, rho, sweep, half_chord, half_circle)


def cylinder_of(seg: Segment) -> tuple[str, str, Fraction] | None:
    """``(linear axis, rotary axis, cylinder radius)`` of a motion made in G07.1 mode, else None."""
    d = seg.payload(Developed)
    return None if d is None else (d.linear_axis, d.rotary_axis, d.cylinder_radius)


def developed_arc_of(seg: Segment) -> DevelopedArc:
    """The :class:`DevelopedArc` of a ``SegmentKind.DEVELOPED_ARC`` segment."""
    info = cylinder_of(seg)
    if info is None or seg.radius is None:
        raise ValueError("not a developed arc (no cylinder radius or no R)")
    lin, rot, rc = info
    iz, ic = seg.axes.index(lin), seg.axes.index(rot)
    return developed_arc(seg.start[iz], seg.start[ic], seg.end[iz], seg.end[ic], rc, seg.radius, seg.clockwise)
