"""Enclosures of π, arctangent, arcsine, sine and cosine: the one implementation of each.

Every function returns an :class:`~nczones.exact.Interval` of rationals that
contains the exact real value; nothing here uses a float.  The soundness
argument of each is in its docstring; the test suite checks them once
against mpmath at high precision (``tests/exact/test_exact_core.py``).

Invariants
----------
* :func:`atan_interval` at ``bits``: the true value lies at least
  ``4 * 2**-(bits + 16)`` inside each end (the bound of the series' error
  is ``4`` units of ``2**-(bits + 16)`` less than the widening).  So an
  enclosure whose width is below that, at a higher precision, lies inside
  one at a lower precision.
* :func:`pi_interval` is computed once (Machin's formula) and cached.
* :func:`sin_cos_degrees` is exact (a point) at the angles where sine or
  cosine is rational (multiples of 30 and 90 degrees: by Niven's theorem
  the only rational degree angles with a rational sine or cosine).
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache

from .interval import GRID_BITS, Interval, round_down, round_down_scaled, round_up, round_up_scaled

__all__ = [
    "pi_interval",
    "atan_interval",
    "atan_range",
    "atan2_interval",
    "asin_interval",
    "sin_cos_interval",
    "sin_cos_degrees",
    "degrees",
    "radians",
]

_F0 = Fraction(0)
_F1 = Fraction(1)
_M1 = Fraction(-1)
_HALF = Fraction(1, 2)
#: Guard bits of the fixed-point arctangent series beyond the requested grid.
_GUARD = 16


def _round_out(total: int, err: int, bits: int) -> Interval:
    """``[total - err, total + err] / 2**(bits + _GUARD)`` with its ends rounded outwards to ``2**-bits``."""
    shift = bits + _GUARD
    return Interval(round_down(Fraction(total - err, 1 << shift), bits),
                    round_up(Fraction(total + err, 1 << shift), bits))


def _atan_small(x: Fraction, bits: int) -> Interval:
    """Enclosure of ``atan(x)`` for ``0 <= x <= 1/2`` by its alternating series in fixed point.

    Integers scaled by ``S = 2**(bits + 16)``: ``X = floor(x S)``, ``X2 = floor(X**2 / S)`` (so
    ``x**2 S - 2 <= X2 <= x**2 S``), the powers ``p_k = floor(p_(k-1) X2 / S)`` from ``p_0 = X``.  Each
    ``p_k`` is below ``x**(2k+1) S`` by less than 3 units (the error shrinks by 4 a step and grows by at
    most 2), each term ``p_k // (2k+1)`` by less than 4; the series stops when ``p_k`` is 0, so the rest
    of it (alternating, decreasing: below its first term) is below 4 units too.  The sum is thus within
    ``4 k + 4`` units of ``atan(x) S``; the enclosure is the sum widened by ``4 k + 8`` units (4 to
    spare: the invariant of the module), its ends rounded outwards to ``2**-bits``.
    """
    shift = bits + _GUARD
    xs = (x.numerator << shift) // x.denominator
    x2 = (xs * xs) >> shift
    p, total, k = xs, 0, 0
    while p:
        term = p // (2 * k + 1)
        total = total + term if k % 2 == 0 else total - term
        p = (p * x2) >> shift
        k += 1
    return _round_out(total, 4 * k + 8, bits)


@lru_cache(maxsize=1)
def pi_interval() -> Interval:
    """Enclosure of π: Machin's formula ``π = 16 atan(1/5) - 4 atan(1/239)``.

    Both arctangents come from :func:`_atan_small` at :data:`GRID_BITS` (each
    an enclosure), combined in interval arithmetic (outward rounding): the
    result contains π.  Width below ``2**-190``.  Computed once.

    >>> p = pi_interval()
    >>> Fraction(333, 106) < p.lo <= p.hi < Fraction(355, 113), p.width() < Fraction(1, 10**55)
    (True, True)
    """
    return 16 * _atan_small(Fraction(1, 5), GRID_BITS) - 4 * _atan_small(Fraction(1, 239), GRID_BITS)


def atan_interval(x: Fraction, bits: int = GRID_BITS) -> Interval:
    """Enclosure of ``atan(x)`` (radians) for a rational ``x``.

    ``atan(0) = 0`` exactly.  Reduction to the series argument ``|y| <= 1/2`` by exact identities:
    ``atan(-x) = -atan(x)``; ``atan(x) = π/2 - atan(1/x)`` for ``x > 1``;
    ``atan(x) = π/4 + atan((x - 1)/(x + 1))`` for ``1/2 < x <= 1`` (then
    ``0 < (1 - x)/(x + 1) < 1/3``).  Each identity is evaluated in interval
    arithmetic with :func:`pi_interval`, so the enclosure survives it.  The
    width is about ``(4 k + 8) 2**-(bits + 15)`` (``k`` series terms, at most
    ``bits / 2 + 9``) plus the outward rounding to ``2**-bits``.

    Parameters
    ----------
    x : Fraction
    bits : int
        The grid of the series' result (default :data:`GRID_BITS`).

    Examples
    --------
    >>> a = atan_interval(Fraction(1))
    >>> (4 * a).lo <= pi_interval().hi and pi_interval().lo <= (4 * a).hi
    True
    >>> atan_interval(Fraction(1, 3), 96).width() < Fraction(1, 2**90)
    True
    """
    if x == 0:
        return Interval(_F0, _F0)
    if x < 0:
        return -atan_interval(-x, bits)
    if x > 1:
        return pi_interval() / 2 - atan_interval(1 / x, bits)
    if x > _HALF:
        return pi_interval() / 4 + atan_interval((x - 1) / (x + 1), bits)
    return _atan_small(x, bits)


def atan_range(iv: Interval, bits: int = GRID_BITS) -> Interval:
    """Enclosure of ``atan`` over ``iv`` (increasing: the enclosures of the two ends).

    >>> atan_range(Interval(Fraction(0), Fraction(1))).lo
    Fraction(0, 1)
    """
    return Interval(atan_interval(iv.lo, bits).lo, atan_interval(iv.hi, bits).hi)


def atan2_interval(y: Fraction, x: Fraction) -> Interval:
    """Enclosure of ``atan2(y, x)`` in ``(-π, π]`` radians for a rational point other than the origin.

    ``atan(y/x)`` for ``x > 0``; ``±π/2`` on the Y axis; ``atan(y/x) ± π`` for ``x < 0`` (``+`` when
    ``y >= 0``): the usual branches, each exact identities evaluated in interval arithmetic.

    Raises
    ------
    ValueError
        At the origin, where the angle is undefined.

    >>> a = atan2_interval(Fraction(0), Fraction(-1))
    >>> a == pi_interval()
    True
    >>> atan2_interval(Fraction(-1), Fraction(0)) == -(pi_interval() / 2)
    True
    """
    if x == 0 and y == 0:
        raise ValueError("atan2(0, 0): the angle of the origin is undefined")
    if x > 0:
        return atan_interval(y / x)
    if x == 0:
        return pi_interval() / 2 if y > 0 else -(pi_interval() / 2)
    a = atan_interval(y / x)
    return a + pi_interval() if y >= 0 else a - pi_interval()


def asin_interval(iv: Interval) -> Interval:
    """Enclosure of ``asin`` over ``iv`` within ``[0, 1]`` (radians; values above 1 are clipped to 1, below
    0 to 0).

    ``asin(x) = atan(x / sqrt(1 - x**2))`` for ``0 < x < 1``: the square root and the quotient enclosed,
    atan increasing; ``asin(1) = π/2``; when the enclosure of ``sqrt(1 - x**2)`` reaches 0 the upper end is
    ``π/2`` (the largest value of asin).

    >>> a = asin_interval(Interval.of(Fraction(1, 2)))
    >>> (6 * a).lo <= pi_interval().hi and pi_interval().lo <= (6 * a).hi
    True
    """
    half_pi = pi_interval() / 2

    def at(x: Fraction, upper: bool) -> Fraction:
        if x <= 0:
            return _F0
        if x >= 1:
            return half_pi.hi if upper else half_pi.lo
        c = Interval.of(1 - x * x).sqrt()
        if c.lo <= 0:
            return half_pi.hi if upper else _F0
        a = atan_range(Interval(round_down_scaled(x / c.hi), round_up_scaled(x / c.lo)))
        return a.hi if upper else a.lo

    return Interval(at(iv.lo, False), at(iv.hi, True))


def _sin_cos_point(x: Fraction) -> tuple[Interval, Interval]:
    """Enclosures of sin(x) and cos(x) for a rational ``|x| <= 8`` (Taylor series, Lagrange remainder).

    The terms ``x**n / n!`` are rounded towards 0 by :func:`round_down_scaled` (each by less than
    ``2**-GRID_BITS``); the rounding of a term carries into the later ones by a factor below
    ``e**|x| < e**8 < 4096``, so the sums are off by less than ``(n + 2) 4096`` units of
    ``2**-GRID_BITS``.  The series stop once ``n > |x|`` and the next term is below
    ``2**-(GRID_BITS + 8)``: from there the terms decrease, so the remainder of each series (alternating,
    decreasing: below its first omitted term) is below the next term.  The enclosure is the sum widened
    by both.  (Exact ``Fraction`` terms rather than fixed-point integers: the numbers of the cylindrical
    and polar enclosures, and so their reported points, stay those they were before the core.)
    """
    s, c = _F0, _F1
    term = _F1  # x^n / n!
    n = 0
    ax = abs(x)
    bound = Fraction(1, 1 << (GRID_BITS + 8))
    while True:
        n += 1
        term = term * x / n
        term = round_down_scaled(term) if term > 0 else -round_down_scaled(-term)
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
    slack = abs(term) * ax / (n + 1) + Fraction((n + 2) * 4096, 1 << GRID_BITS)
    return (Interval(round_down_scaled(s - slack), round_up_scaled(s + slack)),
            Interval(round_down_scaled(c - slack), round_up_scaled(c + slack)))


def sin_cos_interval(iv: Interval) -> tuple[Interval, Interval]:
    """Enclosures of sin and cos over ``iv`` (radians, ``|x| <= 8``).

    The values at the middle ``m`` (:func:`_sin_cos_point`) widened by the half width ``h``: sine and
    cosine are 1-Lipschitz, so over ``[m - h, m + h]`` they stay within ``h`` of their value at ``m``;
    then clipped to ``[-1, 1]``.

    >>> s, c = sin_cos_interval(pi_interval() / 6)
    >>> s.contains(Fraction(1, 2)), c.lo**2 < Fraction(3, 4) < c.hi**2, s.width() < Fraction(1, 10**50)
    (True, True, True)
    """
    m = round_down_scaled(iv.mid())
    s, c = _sin_cos_point(m)
    h = max(iv.hi - m, m - iv.lo)
    if h:
        s, c = s.widen(h), c.widen(h)
    return (Interval(max(s.lo, _M1), min(s.hi, _F1)), Interval(max(c.lo, _M1), min(c.hi, _F1)))


def degrees(rad: Interval) -> Interval:
    """An angle in radians to degrees: ``rad * 180 / π``, enclosed.

    >>> degrees(pi_interval()).contains(180)
    True
    """
    return rad * 180 / pi_interval()


def radians(deg: Fraction | Interval) -> Interval:
    """An angle in degrees to radians: ``deg * π / 180``, enclosed.

    >>> radians(Fraction(180)) == pi_interval()
    True
    """
    p = pi_interval()
    if isinstance(deg, Interval):
        return p * deg / 180
    lo, hi = p.lo * deg / 180, p.hi * deg / 180  # one product per end (exact), then rounded outwards
    if deg < 0:
        lo, hi = hi, lo
    return Interval(round_down_scaled(lo), round_up_scaled(hi))


#: cos and sin of the angles (degrees, in [0, 360)) where they are rational
_EXACT_COS = {Fraction(a): Fraction(c) for a, c in ((0, 1), (60, "1/2"), (90, 0), (120, "-1/2"), (180, -1),
                                                     (240, "-1/2"), (270, 0), (300, "1/2"))}
_EXACT_SIN = {Fraction(a): Fraction(s) for a, s in ((0, 0), (30, "1/2"), (90, 1), (150, "1/2"), (180, 0),
                                                     (210, "-1/2"), (270, -1), (330, "-1/2"))}


@lru_cache(maxsize=256)
def sin_cos_degrees(angle: Fraction) -> tuple[Interval, Interval]:
    """Enclosures of ``sin`` and ``cos`` of ``angle`` degrees; exact points where they are rational.

    The angle is reduced exactly (``angle mod 360``, then its quadrant ``q`` and the rest ``r`` in
    ``[0, 90)``); ``r`` in radians is enclosed by :func:`radians` and its sine and cosine by
    :func:`sin_cos_interval`; the quadrant maps them by the exact identities
    ``(sin, cos)(r + 90 q) = (cos r, -sin r), (-sin r, -cos r), (-cos r, sin r)`` for ``q = 1, 2, 3``.
    Where sine or cosine is rational (the table of multiples of 30 and 90 degrees) that value is used.
    Cached: programs repeat their angles.

    >>> sin_cos_degrees(Fraction(90))
    (Interval(lo=Fraction(1, 1), hi=Fraction(1, 1)), Interval(lo=Fraction(0, 1), hi=Fraction(0, 1)))
    >>> s, c = sin_cos_degrees(Fraction(45))
    >>> c.lo**2 < Fraction(1, 2) < c.hi**2 and s.lo**2 < Fraction(1, 2) < s.hi**2 and c.width() < 1e-50
    True
    """
    a = Fraction(angle) % 360
    c_exact = _EXACT_COS.get(a)
    s_exact = _EXACT_SIN.get(a)
    if c_exact is not None and s_exact is not None:
        return Interval(s_exact, s_exact), Interval(c_exact, c_exact)
    quadrant, r = divmod(a, 90)
    sr, cr = sin_cos_interval(radians(r))
    sin_iv, cos_iv = {0: (sr, cr), 1: (cr, -sr), 2: (-sr, -cr), 3: (-cr, sr)}[int(quadrant)]
    if s_exact is not None:
        sin_iv = Interval(s_exact, s_exact)
    if c_exact is not None:
        cos_iv = Interval(c_exact, c_exact)
    return sin_iv, cos_iv
