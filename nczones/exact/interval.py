"""The one outward-rounded rational :class:`Interval`, and the rounding it rests on.

Every irrational quantity a proof needs (a square root, an angle, π) is
*enclosed*: a closed interval ``[lo, hi]`` of rationals that contains the
exact real value.  Arithmetic on enclosures is interval arithmetic whose
results are rounded *outwards*, so that an enclosure computed from
enclosures still contains the exact result.

Invariants
----------
* ``lo <= hi``, both :class:`~fractions.Fraction`; no float anywhere.
* Soundness: for every operation ``op`` and every ``x`` in ``a``, ``y`` in
  ``b``, ``op(x, y)`` lies in ``op(a, b)``.  The exact interval result is
  computed with rationals, then its lower end is rounded down and its upper
  end up (:func:`round_down_scaled`, :func:`round_up_scaled`), which only
  widens it.
* The numbers stay short: an end whose denominator exceeds
  ``2**GRID_BITS`` is rounded to a multiple of ``2**-GRID_BITS``; an end
  with a smaller denominator (``1/3``, a decimal) is kept exact.

Square roots are here too (:func:`sqrt_interval`, :meth:`Interval.sqrt`):
exact when the root is rational, else the two neighbouring multiples of
``2**-bits`` around it, from the integer square root (``math.isqrt``), so no
approximation error beyond the grid step.

Two further roundings live here because the enclosures of the prover use
them: :func:`round_down`/:func:`round_up` (to a multiple of ``2**-bits``,
always) and the None-aware :func:`max_bound`/:func:`min_bound` of zone
limits (None: unbounded).
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..errors import InvalidArgument
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

__all__ = [
    "GRID_BITS",
    "Interval",
    "round_down_scaled",
    "round_up_scaled",
    "round_down",
    "round_up",
    "max_bound",
    "min_bound",
    "is_square",
    "sqrt_interval",
    "Bounds",
]

#: Outward rounding grid (bits) of every :class:`Interval` operation.
GRID_BITS = 200
_SCALE = 1 << GRID_BITS

_F0 = Fraction(0)

#: An enclosure as a bare ``(lo, hi)`` pair, for code that does its own exact arithmetic on the ends
#: (:meth:`Interval.bounds` gives it); the same invariant: ``lo <= value <= hi``.
Bounds = tuple[Fraction, Fraction]


def round_down_scaled(x: Fraction) -> Fraction:
    """``x`` when its denominator is at most ``2**GRID_BITS``, else the multiple of ``2**-GRID_BITS`` below it.

    Never above ``x``; within ``2**-GRID_BITS`` of it.

    >>> round_down_scaled(Fraction(1, 3))
    Fraction(1, 3)
    >>> y = round_down_scaled(Fraction(1, 3**200))
    >>> 0 <= y <= Fraction(1, 3**200) and y.denominator <= 2**GRID_BITS
    True
    """
    if x.denominator <= _SCALE:
        return x
    return Fraction((x.numerator * _SCALE) // x.denominator, _SCALE)


def round_up_scaled(x: Fraction) -> Fraction:
    """``x`` when its denominator is at most ``2**GRID_BITS``, else the multiple of ``2**-GRID_BITS`` above it.

    Never below ``x``; within ``2**-GRID_BITS`` of it.

    >>> round_up_scaled(Fraction(-1, 3))
    Fraction(-1, 3)
    >>> round_up_scaled(Fraction(1, 3**200)) == Fraction(1, 2**GRID_BITS)
    True
    """
    if x.denominator <= _SCALE:
        return x
    return Fraction(-((-x.numerator * _SCALE) // x.denominator), _SCALE)


def round_down(x: Fraction, bits: int) -> Fraction:
    """The largest multiple of ``2**-bits`` not above ``x`` (``x`` itself when it is one).

    >>> round_down(Fraction(1, 3), 4), round_down(Fraction(-1, 3), 4), round_down(Fraction(3, 8), 4)
    (Fraction(5, 16), Fraction(-3, 8), Fraction(3, 8))
    """
    scale = 1 << bits
    if scale % x.denominator == 0:
        return x
    return Fraction((x.numerator * scale) // x.denominator, scale)


def round_up(x: Fraction, bits: int) -> Fraction:
    """The smallest multiple of ``2**-bits`` not below ``x``.

    >>> round_up(Fraction(1, 3), 4), round_up(Fraction(-1, 3), 4)
    (Fraction(3, 8), Fraction(-5, 16))
    """
    return -round_down(-x, bits)


def max_bound(a: Fraction | None, b: Fraction | None) -> Fraction | None:
    """The larger of two lower limits, None being unbounded (so the other one wins).

    >>> max_bound(None, Fraction(2)), max_bound(Fraction(1), Fraction(2)), max_bound(None, None)
    (Fraction(2, 1), Fraction(2, 1), None)
    """
    if a is None:
        return b
    if b is None:
        return a
    return max(a, b)


def min_bound(a: Fraction | None, b: Fraction | None) -> Fraction | None:
    """The smaller of two upper limits, None being unbounded (so the other one wins).

    >>> min_bound(Fraction(3), None), min_bound(Fraction(1), Fraction(2))
    (Fraction(3, 1), Fraction(1, 1))
    """
    if a is None:
        return b
    if b is None:
        return a
    return min(a, b)


@dataclass(frozen=True, slots=True)
class Interval:
    """A closed rational interval ``[lo, hi]`` with outward-rounded arithmetic.

    ``+ - * /`` take intervals, ``Fraction`` or ``int`` on either side; the
    result contains every value of the operation over the operands
    (division by an interval containing 0 raises ``ZeroDivisionError``).

    Examples
    --------
    >>> a = Interval.of(1) / 3
    >>> a.lo <= Fraction(1, 3) <= a.hi, a.width() < Fraction(1, 10**60)
    (True, True)
    >>> (Interval(Fraction(-1), Fraction(2)) * Interval(Fraction(3), Fraction(4))).lo
    Fraction(-4, 1)
    >>> Interval(Fraction(-1), Fraction(2)).sqr()
    Interval(lo=Fraction(0, 1), hi=Fraction(4, 1))
    """

    lo: Fraction
    hi: Fraction

    @staticmethod
    def of(x: Fraction | int | str) -> "Interval":
        """The point interval ``[x, x]``."""
        q = Fraction(x)
        return Interval(q, q)

    @staticmethod
    def _coerce(x: "Interval | Fraction | int") -> "Interval":
        return x if isinstance(x, Interval) else Interval.of(x)

    def __add__(self, o: "Interval | Fraction | int") -> "Interval":
        o = Interval._coerce(o)
        return Interval(round_down_scaled(self.lo + o.lo), round_up_scaled(self.hi + o.hi))

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
        return Interval(round_down_scaled(min(ps)), round_up_scaled(max(ps)))

    __rmul__ = __mul__

    def __truediv__(self, o: "Interval | Fraction | int") -> "Interval":
        o = Interval._coerce(o)
        if o.lo <= 0 <= o.hi:
            raise ZeroDivisionError("interval division by an interval containing 0")
        return self * Interval(round_down_scaled(1 / o.hi), round_up_scaled(1 / o.lo))

    def __rtruediv__(self, o: "Interval | Fraction | int") -> "Interval":
        return Interval._coerce(o) / self

    def sqr(self) -> "Interval":
        """``{x**2 : x in self}`` (tighter than ``self * self`` when ``self`` contains 0)."""
        if self.lo >= 0:
            return Interval(round_down_scaled(self.lo * self.lo), round_up_scaled(self.hi * self.hi))
        if self.hi <= 0:
            return Interval(round_down_scaled(self.hi * self.hi), round_up_scaled(self.lo * self.lo))
        return Interval(_F0, round_up_scaled(max(self.lo * self.lo, self.hi * self.hi)))

    def sqrt(self) -> "Interval":
        """Square root of the non-negative part (negative lower ends are clipped to 0).

        Each end is enclosed by :func:`sqrt_interval` on the grid (sqrt is
        increasing, so the lower end's lower bound and the upper end's upper
        bound enclose the range).

        >>> r = Interval.of(2).sqrt()
        >>> r.lo * r.lo <= 2 <= r.hi * r.hi, r.width() <= Fraction(1, 2**GRID_BITS)
        (True, True)
        """
        lo = max(self.lo, _F0)
        hi = max(self.hi, _F0)
        return Interval(sqrt_interval(lo, GRID_BITS).lo, sqrt_interval(hi, GRID_BITS).hi)

    def hull(self, o: "Interval | Fraction | int") -> "Interval":
        """The smallest interval containing both."""
        o = Interval._coerce(o)
        return Interval(min(self.lo, o.lo), max(self.hi, o.hi))

    def widen(self, d: Fraction) -> "Interval":
        """``[lo - d, hi + d]``."""
        return Interval(self.lo - d, self.hi + d)

    def width(self) -> Fraction:
        return self.hi - self.lo

    def mid(self) -> Fraction:
        return (self.lo + self.hi) / 2

    def contains(self, x: Fraction | int) -> bool:
        return self.lo <= Fraction(x) <= self.hi

    def bounds(self) -> Bounds:
        """``(lo, hi)``: the pair form some callers keep (exact arithmetic of their own on the ends)."""
        return self.lo, self.hi


def is_square(q: Fraction) -> Fraction | None:
    """The exact rational square root of ``q``, or None when it is irrational (or ``q < 0``).

    ``p/q`` in lowest terms is a rational square iff ``p`` and ``q`` are squares of integers.

    >>> is_square(Fraction(9, 4)), is_square(Fraction(2)), is_square(Fraction(-1))
    (Fraction(3, 2), None, None)
    """
    if q < 0:
        return None
    n, d = q.numerator, q.denominator
    rn, rd = math.isqrt(n), math.isqrt(d)
    if rn * rn == n and rd * rd == d:
        return Fraction(rn, rd)
    return None


def sqrt_interval(q: Fraction, bits: int = GRID_BITS) -> Interval:
    """Enclosure of ``sqrt(q)`` for ``q >= 0``: the point when it is rational, else width ``2**-bits``.

    Soundness: with ``s = 2**bits`` and ``n = isqrt(floor(q s**2))`` (exact
    integer arithmetic), ``n <= sqrt(floor(q s**2)) <= sqrt(q) s`` and
    ``sqrt(q) s < n + 1`` (else ``(n + 1)**2 <= q s**2``, and, ``(n+1)**2``
    being an integer, ``<= floor(q s**2)``, against the definition of ``n``).
    So ``n/s <= sqrt(q) < (n+1)/s``.

    Raises
    ------
    InvalidArgument
        If ``q < 0``.

    Examples
    --------
    >>> r = sqrt_interval(Fraction(2), 20)
    >>> r.lo * r.lo <= 2 <= r.hi * r.hi, r.width() == Fraction(1, 2**20)
    (True, True)
    >>> sqrt_interval(Fraction(1, 9))
    Interval(lo=Fraction(1, 3), hi=Fraction(1, 3))
    """
    if q < 0:
        raise InvalidArgument(f"sqrt of a negative number {q}")
    root = is_square(q)
    if root is not None:
        return Interval(root, root)
    scale = 1 << bits
    n = math.isqrt(q.numerator * scale * scale // q.denominator)
    return Interval(Fraction(n, scale), Fraction(n + 1, scale))
