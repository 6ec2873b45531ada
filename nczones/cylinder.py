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
quantity here is an :class:`Interval` of rationals that contains the exact
value (pi from Machin's formula; square roots, sines, cosines and arc sines by
series with remainder bounds; all rounding outward on a ``2**-GRID_BITS``
grid).

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

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .motion import Segment

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

#: Outward rounding grid (bits) of every interval operation.
GRID_BITS = 200
_SCALE = 1 << GRID_BITS

#: The linear axis parallel to each rotary axis (the cylinder's axis).
LINEAR_AXIS_OF = {"A": "X", "B": "Y", "C": "Z"}

F0 = Fraction(0)
F1 = Fraction(1)


def _down(x: Fraction) -> Fraction:
    if x.denominator <= _SCALE:
        return x
    return Fraction((x.numerator * _SCALE) // x.denominator, _SCALE)


def round_up_scaled(x: Fraction) -> Fraction:
    if x.denominator <= _SCALE:
        return x
    return Fraction(-((-x.numerator * _SCALE) // x.denominator), _SCALE)


@dataclass(frozen=True, slots=True)
class Interval:
    """A closed rational interval ``[lo, hi]`` (outward-rounded arithmetic).

    >>> a = Interval.of(1) / 3
    >>> a.lo <= Fraction(1, 3) <= a.hi, a.width() < Fraction(1, 10**60)
    (True, True)
    >>> (Interval(Fraction(-1), Fraction(2)) * Interval(Fraction(3), Fraction(4))).lo
    Fraction(-4, 1)
    """

    lo: Fraction
    hi: Fraction

    @staticmethod
    def of(x: Fraction | int | str) -> "Interval":
        q = Fraction(x)
        return Interval(q, q)

    @staticmethod
    def _coerce(x: "Interval | Fraction | int") -> "Interval":
        return x if isinstance(x, Interval) else Interval.of(x)

    def __add__(self, o: "Interval | Fraction | int") -> "Interval":
        o = Interval._coerce(o)
        return Interval(_down(self.lo + o.lo), round_up_scaled(self.hi + o.hi))

    __radd__ = __add__

    def __neg__(self) -> "Interval":
        return Interval(-self.hi, -self.lo)

    def __sub__(self, o: "Interval | Fraction | int") -> "Interval":
        return self + (-Interval._coerce(o))

    def __rsub__(self, o: "Interval | Fraction | int") -> "Interval":
        return Interval._coerce(o) - self

    def __mul__(self, o: "Interval | Fraction | int") -> "Interval":
        o = Interval._coerce(o)
        ps = (self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi)
        return Interval(_down(min(ps)), round_up_scaled(max(ps)))

    __rmul__ = __mul__

    def __truediv__(self, o: "Interval | Fraction | int") -> "Interval":
        o = Interval._coerce(o)
        if o.lo <= 0 <= o.hi:
            raise ZeroDivisionError("interval division by an interval containing 0")
        return self * Interval(_down(1 / o.hi), round_up_scaled(1 / o.lo))

    def __rtruediv__(self, o: "Interval | Fraction | int") -> "Interval":
        return Interval._coerce(o) / self

    def sqr(self) -> "Interval":
        if self.lo >= 0:
            return Interval(_down(self.lo * self.lo), round_up_scaled(self.hi * self.hi))
        if self.hi <= 0:
            return Interval(_down(self.hi * self.hi), round_up_scaled(self.lo * self.lo))
        return Interval(F0, round_up_scaled(max(self.lo * self.lo, self.hi * self.hi)))

    def sqrt(self) -> "Interval":
        """Square root of the non-negative part (negative lower ends are clipped to 0)."""
        lo = max(self.lo, F0)
        hi = max(self.hi, F0)
        return Interval(_sqrt_floor(lo), _sqrt_ceil(hi))

    def hull(self, o: "Interval | Fraction | int") -> "Interval":
        o = Interval._coerce(o)
        return Interval(min(self.lo, o.lo), max(self.hi, o.hi))

    def widen(self, d: Fraction) -> "Interval":
        return Interval(self.lo - d, self.hi + d)

    def width(self) -> Fraction:
        return self.hi - self.lo

    def mid(self) -> Fraction:
        return (self.lo + self.hi) / 2

    def contains(self, x: Fraction | int) -> bool:
        return self.lo <= Fraction(x) <= self.hi


def _sqrt_floor(x: Fraction) -> Fraction:
    n = math.isqrt((x.numerator * _SCALE * _SCALE) // x.denominator)
    return Fraction(n, _SCALE)


def _sqrt_ceil(x: Fraction) -> Fraction:
    lo = _sqrt_floor(x)
    return lo if lo * lo == x else lo + Fraction(1, _SCALE)


# --------------------------------------------------------------------------- elementary functions


def _atan_small(x: Fraction) -> Interval:
    """atan(x) for 0 <= x <= 1/2 by its alternating series in fixed point (enclosure).

    Integers scaled by ``S = 2**(GRID_BITS + 16)``: ``X = floor(x S)``, ``X2 = floor(X**2 / S)`` (so
    ``x**2 S - 2 <= X2 <= x**2 S``), the powers ``p_k = floor(p_(k-1) X2 / S)`` from ``p_0 = X``.  Each
    ``p_k`` is below ``x**(2k+1) S`` by less than 3 units (the error shrinks by 4 a step and grows by at most
    2), each term ``p_k // (2k+1)`` by less than 4; the series stops when ``p_k`` is 0, so the rest of it is
    below 4 units too.  The enclosure is the sum widened by 4 units a term and 8 more.
    """
    bits = GRID_BITS + 16
    big = 1 << bits
    xs = (x.numerator << bits) // x.denominator
    x2 = (xs * xs) >> bits
    p, total, k = xs, 0, 0
    while p:
        term = p // (2 * k + 1)
        total = total + term if k % 2 == 0 else total - term
        p = (p * x2) >> bits
        k += 1
    err = 4 * k + 8
    return Interval(_down(Fraction(total - err, big)), round_up_scaled(Fraction(total + err, big)))


@lru_cache(maxsize=1)
def pi_interval() -> Interval:
    """Machin's pi = 16 atan(1/5) - 4 atan(1/239), enclosed.

    >>> p = pi_interval()
    >>> Fraction(333, 106) < p.lo <= p.hi < Fraction(355, 113), p.width() < Fraction(1, 10**55)
    (True, True)
    """
    return 16 * _atan_small(Fraction(1, 5)) - 4 * _atan_small(Fraction(1, 239))


def atan_point(x: Fraction) -> Interval:
    """Enclosure of ``atan(x)`` (radians) for a rational ``x`` (series with remainder bounds).

    >>> a = atan_point(Fraction(1))
    >>> (4 * a).lo <= pi_interval().hi and pi_interval().lo <= (4 * a).hi
    True
    """
    if x < 0:
        return -atan_point(-x)
    pi = pi_interval()
    if x > 1:
        return pi / 2 - atan_point(1 / x)
    if x > Fraction(1, 2):
        return pi / 4 + atan_point((x - 1) / (x + 1))
    return _atan_small(x)


def _atan(iv: Interval) -> Interval:
    """atan is increasing: the enclosure of the ends."""
    return Interval(atan_point(iv.lo).lo, atan_point(iv.hi).hi)


def asin_interval(iv: Interval) -> Interval:
    """Enclosure of ``asin`` over ``iv`` within ``[0, 1]`` (values above 1 are clipped to 1; radians).

    >>> a = asin_interval(Interval.of(Fraction(1, 2)))
    >>> (6 * a).lo <= pi_interval().hi and pi_interval().lo <= (6 * a).hi
    True
    """
    half_pi = pi_interval() / 2

    def at(x: Fraction, upper: bool) -> Fraction:
        if x <= 0:
            return F0
        if x >= 1:
            return half_pi.hi if upper else half_pi.lo
        c = Interval.of(1 - x * x).sqrt()
        ratio = Interval(_down(x / c.hi), round_up_scaled(x / c.lo)) if c.lo > 0 else None
        if ratio is None:
            return half_pi.hi if upper else F0
        a = _atan(ratio)
        return a.hi if upper else a.lo

    return Interval(at(iv.lo, False), at(iv.hi, True))


def _sin_cos_point(x: Fraction) -> tuple[Interval, Interval]:
    """Enclosures of sin(x) and cos(x) for a rational |x| <= 8 (Taylor, Lagrange remainder)."""
    s, c = F0, F1
    term = F1  # x^n / n!
    n = 0
    ax = abs(x)
    bound = Fraction(1, 1 << (GRID_BITS + 8))
    while True:
        n += 1
        term = term * x / n
        term = _down(term) if term > 0 else -_down(-term)
        if n % 4 == 1:
            s += term
        elif n % 4 == 2:
            c -= term
        elif n % 4 == 3:
            s -= term
        else:
            c += term
        # the next term bounds the remainder of both series (with the rounding slack)
        if n > ax and abs(term) * ax / (n + 1) < bound:
            break
    slack = abs(term) * ax / (n + 1) + Fraction((n + 2) * 4096, _SCALE)  # e**8 < 4096: rounding carried by later terms
    return Interval(_down(s - slack), round_up_scaled(s + slack)), Interval(_down(c - slack), round_up_scaled(c + slack))


def sin_cos_interval(iv: Interval) -> tuple[Interval, Interval]:
    """Enclosures of sin and cos over ``iv`` (radians, ``|x| <= 8``): the value at the middle widened by the half
    width (Lipschitz 1).

    >>> s, c = sin_cos_interval(pi_interval() / 6)
    >>> s.contains(Fraction(1, 2)), abs(float(c.mid()) - 3 ** 0.5 / 2) < 1e-15, s.width() < Fraction(1, 10**50)
    (True, True, True)
    """
    m = iv.mid()
    m = _down(m)
    s, c = _sin_cos_point(m)
    h = max(iv.hi - m, m - iv.lo)
    one = Interval(-F1, F1)
    s, c = s.widen(h), c.widen(h)
    return (Interval(max(s.lo, one.lo), min(s.hi, one.hi)), Interval(max(c.lo, one.lo), min(c.hi, one.hi)))


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
    extra = dict(seg.extra)
    if "cylinder_radius" not in extra:
        return None
    return str(extra["linear_axis"]), str(extra["rotary_axis"]), Fraction(extra["cylinder_radius"])  # type: ignore[call-overload]


def developed_arc_of(seg: Segment) -> DevelopedArc:
    """The :class:`DevelopedArc` of a ``SegmentKind.DEVELOPED_ARC`` segment."""
    info = cylinder_of(seg)
    if info is None or seg.radius is None:
        raise ValueError("not a developed arc (no cylinder radius or no R)")
    lin, rot, rc = info
    iz, ic = seg.axes.index(lin), seg.axes.index(rot)
    return developed_arc(seg.start[iz], seg.start[ic], seg.end[iz], seg.end[ic], rc, seg.radius, seg.clockwise)
