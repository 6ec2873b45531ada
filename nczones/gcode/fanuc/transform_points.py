"""Points under one Fanuc G68 rotation or G51 scaling, one at a time, without numpy (issue 36).

The numpy-free box route reads runs of plain lines from the text (:mod:`nczones.gcode.fanuc.boxrun`); under a
transform it keeps the *program* point as scaled integers (``10**S``) and maps each point it moves to as
``FanucInterpreter._transform_target`` does, with the arithmetic of
:mod:`nczones.gcode.fanuc.transform_columns` done in Python integers and floats instead of ``int64`` and
``float64`` columns (IEEE doubles both: the same values):

* **scaling**: ``N = c fd + fn (p - c)`` (the point times the factor's denominator ``fd``) rounded to the
  increment ``st`` halves away from zero, ``sign(N) floor((2|N| + fd st) / (2 fd st))``, exactly as
  :func:`~nczones.gcode.fanuc.transforms.scale` (a point on the grid stays, a coordinate at its centre or of
  factor 1 is not moved).  Python integers: no range to check.
* **rotation**: the double screen of ``transform_columns`` (its docstring holds the soundness argument: the
  error bound covers the enclosures of ``cos``/``sin`` and the double evaluation, so a coordinate the screen
  takes rounds to the increment ``transforms.certified_round`` gives), on coordinates below ``2**50`` scaled
  units; any other coordinate, and every one the screen leaves, is computed by
  :func:`~nczones.gcode.fanuc.transforms.rotate` itself (exact rationals), and a point it finds uncertain is
  None: the reader then leaves the line to the general path, which says ``unknown``.

``tests/gcode/fanuc/test_box_transforms.py`` holds :class:`PointMap` to ``transforms.scale`` and
``transforms.rotate`` and the reader to the general path.
"""

from __future__ import annotations

import math
from fractions import Fraction

from .transforms import TIE_GUARD, PointNotCertain, cos_sin_enclosure, rotate

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, Callable

    from .transforms import Rotation

__all__ = ["PointMap", "rotation_doubles", "FLOAT_EXACT", "GUARD", "ROUNDING", "QUOTIENT"]

#: Magnitudes (scaled integers) the rotation's doubles stay below (integers exact in doubles, ``frac`` exact).
FLOAT_EXACT = 2**50
#: The float screen's margins: the tie guard in increments (rounded up), and slack for its own evaluation.
GUARD = float(TIE_GUARD) * (1 + 2**-20) + 2**-40
#: the rounding of the two products and the sum (relative to ``|x| + |y|``), and of the quotient (to ``|u|``)
ROUNDING = 2.0**-51
QUOTIENT = 2.0**-50

_DOUBLES: dict[Fraction, tuple[float, float, float]] = {}


def rotation_doubles(angle: Fraction) -> tuple[float, float, float]:
    """``(c, s, delta)``: the doubles nearest the midpoints of the enclosures of ``cos`` and ``sin`` of ``angle``
    degrees, and a bound (rounded up) on their distance from every point of those enclosures.

    >>> c, s, delta = rotation_doubles(Fraction(90))
    >>> (c, s, delta < 1e-300)
    (0.0, 1.0, True)
    """
    got = _DOUBLES.get(angle)
    if got is None:
        (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(angle)
        c, s = float((c_lo + c_hi) / 2), float((s_lo + s_hi) / 2)
        far = max(abs(Fraction(c) - c_lo), abs(Fraction(c) - c_hi), abs(Fraction(s) - s_lo),
                  abs(Fraction(s) - s_hi))
        delta = math.nextafter(float(far), math.inf) * (1 + 2**-40)
        got = _DOUBLES[angle] = (c, s, delta)
        if len(_DOUBLES) > 256:
            _DOUBLES.clear()
    return got


def _at(q: Fraction, unit: int) -> int | None:
    """``q`` in units of ``1 / unit``, None when it is not a whole number of them."""
    v = q * unit
    return v.numerator if v.denominator == 1 else None


class PointMap:
    """One G68 rotation or G51 scaling (``FanucInterpreter.box_transform``'s) on scaled integers (``10**scale``);
    :meth:`of` builds it, None when a number is not on the scale.

    >>> from nczones.gcode.fanuc.transforms import Scaling
    >>> xf = (None, Scaling((Fraction(0),) * 3, (Fraction(5, 4),) * 3), Fraction(1, 1000))
    >>> pm = PointMap.of(xf, 3)
    >>> pm.scaled(0, 1001), pm.scaled(0, -1001), pm.scaled(0, 2)  # 1.25125 -> 1.251, -1.251; 0.0025 -> 0.003
    (1251, -1251, 3)
    """

    __slots__ = ("axes", "rot", "step", "st", "unit", "ia", "ib", "ca", "cb", "c", "s", "per", "rotated")

    axes: tuple[tuple[int, int, int, int] | None, ...]  # scaling: (centre, fn, fd, fd st) by axis, None: unmoved
    rot: Any
    step: Fraction
    st: int
    unit: int
    ia: int
    ib: int
    ca: int
    cb: int
    c: float
    s: float
    per: float
    #: ``rotated(a, b)``: the rotated plane coordinates of the program's ``(a, b)`` (the rotation's axes), rounded
    #: to the increment; None when ``transforms.rotate`` finds the point uncertain (module docstring).  A closure
    #: over the map's numbers (:func:`_rotator`), not a method: the box reader calls it for every line it moves.
    rotated: Callable[[int, int], tuple[int, int] | None]

    @classmethod
    def of(cls, xf: tuple, scale: int) -> PointMap | None:
        """The map of ``xf = (rotation, scaling, increment)`` at ``10**scale``, None when the increment or a centre
        is not on that scale."""
        rot, scaling, step = xf
        pm = cls()
        pm.unit = unit = 10**scale
        pm.step = step
        st = _at(step, unit)
        if not st or st >= FLOAT_EXACT:  # (the screen's argument takes st below 2**50: transform_columns)
            return None
        pm.st = st
        pm.rot = rot
        pm.axes = ()
        if rot is None:
            axes = []
            for c, f in zip(scaling.centre, scaling.factors):
                ci = _at(c, unit)
                if ci is None:
                    return None
                axes.append(None if f == 1 else (ci, f.numerator, f.denominator, f.denominator * st))
            pm.axes = tuple(axes)
            return pm
        ca, cb = _at(rot.ca, unit), _at(rot.cb, unit)
        if ca is None or cb is None:
            return None
        pm.ia, pm.ib, pm.ca, pm.cb = rot.ia, rot.ib, ca, cb
        pm.c, pm.s, delta = rotation_doubles(rot.angle)
        pm.per = (delta + ROUNDING) / st
        pm.rotated = _rotator(pm)
        return pm

    def factor(self, i: int) -> Fraction:
        """Axis ``i``'s scale factor (1 under a rotation or for an axis not scaled)."""
        ax = self.axes[i] if self.axes else None
        return Fraction(1) if ax is None else Fraction(ax[1], ax[2])

    def scaled(self, i: int, v: int) -> int:
        """Axis ``i``'s coordinate ``v`` scaled about its centre and rounded to the increment (module docstring)."""
        ax = self.axes[i] if self.axes else None
        if ax is None:
            return v
        c, fn, fd, den = ax
        if v == c:
            return v
        n = c * fd + fn * (v - c)
        k = (2 * (n if n >= 0 else -n) + den) // (2 * den)
        return (k if n >= 0 else -k) * self.st


def _exact(rot: Rotation, step: Fraction, unit: int, a: int, b: int) -> tuple[int, int] | None:
    """``(a, b)`` (units of ``1 / unit``) rotated by ``transforms.rotate`` (exact rationals), None when it finds
    the point uncertain: ``PointMap.rotated`` where the double screen leaves the point."""
    point = [Fraction(0)] * (max(rot.ia, rot.ib) + 1)
    point[rot.ia], point[rot.ib] = Fraction(a, unit), Fraction(b, unit)
    try:
        got = rotate(rot, point, step)
    except PointNotCertain:
        return None
    ra, rb = _at(got[rot.ia], unit), _at(got[rot.ib], unit)
    assert ra is not None and rb is not None  # the centre and the increment are on the scale
    return ra, rb


def _rotator(pm: PointMap) -> Callable[[int, int], tuple[int, int] | None]:
    """``PointMap.rotated`` of the rotation map ``pm``: the double screen of ``transform_columns`` on one point (its
    docstring holds the soundness argument), :func:`_exact` for a coordinate of ``2**50`` units or more and for a
    point the screen leaves.  The map's numbers are the closure's (no attribute is read per point)."""
    ca, cb, c, s, step, per = pm.ca, pm.cb, pm.c, pm.s, pm.st, pm.per
    rot, exact_step, unit = pm.rot, pm.step, pm.unit
    low, big, quot, guard, floor = -FLOAT_EXACT, FLOAT_EXACT, QUOTIENT, GUARD, math.floor

    def rotated(a: int, b: int) -> tuple[int, int] | None:
        x = a - ca
        y = b - cb
        if low < x < big and low < y < big:
            xd = float(x)
            yd = float(y)
            err = (abs(xd) + abs(yd)) * per
            u = (xd * c - yd * s) / step
            m = floor(u)
            frac = u - m  # exact: |u| < 2**50
            if abs(frac - 0.5) > err + abs(u) * quot + guard:  # (transform_columns._nearest's sum)
                v = (xd * s + yd * c) / step
                n = floor(v)
                fv = v - n
                if abs(fv - 0.5) > err + abs(v) * quot + guard:
                    return ca + (m + (frac > 0.5)) * step, cb + (n + (fv > 0.5)) * step
        return _exact(rot, exact_step, unit, a, b)

    return rotated
