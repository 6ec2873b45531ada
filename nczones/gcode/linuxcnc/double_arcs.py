"""Arcs of the double pass (:mod:`nczones.gcode.linuxcnc.doubles`): from the pass's doubles, a box that holds
the full path's exact arc, or the reason the pass declines the arc.

The full path (``Interpreter.arc``) models a G17 arc exactly: an I/J arc from the exact start ``S`` about
the exact centre ``C = S + (I, J)`` to the exact end ``E`` (a spiral when ``|E - C| != |S - C|``), an R arc
on the circle of radius ``|R|`` through ``S`` and ``E`` whose centre ``C = (S + E) / 2 + s h n``
(``h = sqrt(R**2 - |E - S|**2 / 4)``, ``n`` the unit normal left of the chord, ``s = -1`` for G2 with
``R > 0`` and G3 with ``R < 0``, else ``+1``) is irrational in general.  The pass has doubles ``S'``,
``E'`` within the row bound ``rho`` of :class:`~nczones.gcode.linuxcnc.doubles.DoublePath` and the words'
doubles (each within half an ulp of its exact value, plus the smallest subnormal).

Why the bound holds
-------------------
Every ``+ - * /`` and ``sqrt`` below is correctly rounded (IEEE-754, to nearest), so each result is within
``2**-53`` relative of the exact operation on its (already inexact) operands; ``math.hypot`` is within
one ulp.  With ``m`` the largest magnitude of the doubles involved (ends, centre, words, radii) plus the
work offsets' bound, each error is a small multiple of ``m 2**-52`` (the sums are in the functions'
comments); the box is widened by ``64 m 2**-52 + 2**-56`` (``_err``), above every such sum, then rounded
outwards with :func:`math.nextafter`.  For an R arc the centre's distance ``h`` is a square root, which is
ill-conditioned near a half circle: ``|sqrt a - sqrt b| = |a - b| / (sqrt a + sqrt b) <= |a - b| / sqrt b``
bounds it, and an arc whose ``X' = R'**2 - D'/4`` is not above ``10**-9 R'**2`` and eight times its own
error is declined (the full path takes a chord within ``10**-12`` of ``2|R|`` as a half circle and a
longer one as GC302: those arcs are the full path's to decide).

The arc's box: the annulus sector between radii ``r_min`` and ``r_max`` (the exact start and end radii)
over the exact sweep holds the arc.  Its box is the box of its corners (within ``|r1 - r0|`` of the end
points) and, for every axis direction ``+X, +Y, -X, -Y`` the sweep contains, ``C +- r_max`` on that axis
(over an angle interval without such a direction a coordinate is monotone or has its one extreme at an
end).  The sweep's ends are the angles of ``S - C`` and ``E - C``; a vector ``v`` moved by at most ``d``
(Euclidean) turns by at most ``asin(d / |v'|) <= pi/2 d / |v'|``, so each end angle is known within
``eta = 2.5 err / |v'|`` (``d <= sqrt 2 err``) plus ``10**-12`` for ``atan2`` and the float ``2 pi``.  A
direction is taken when it is within the computed sweep grown by those angles; when the computed sweep
is within them of 0 or of a whole turn (the exact one may be either: LinuxCNC makes an end on the start's
ray a whole turn), all four are taken.  Taking a direction the exact sweep does not contain only grows
the box, which stays sound.

What declines (the full path errors or decides otherwise there): a radius about 0 (GC304 exactly at 0), an
I/J arc whose radii differ near or past the arc tolerance's rule (GC301), an R arc whose chord is about 0
(GC303) or about ``2|R|`` or longer (a half circle or GC302).
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

from ...exact import to_float

__all__ = ["ij_arc", "r_arc", "radius_rule"]

_U = 2.0**-52
_TAU = 2.0 * math.pi
#: Angle slack (radians) for atan2, the float 2 pi and the sums of angles: far above their rounding.
_SLACK = 1e-12
#: An R arc is declined unless ``X' > _HALF * R'**2`` (its chord is clearly shorter than 2|R|).
_HALF = 1e-9
_DOWN, _UP = -math.inf, math.inf
#: The directions +X, +Y, -X, -Y as angles: (angle, plane axis 0 or 1, sign).
_DIRECTIONS = ((0.0, 0, 1.0), (math.pi / 2, 1, 1.0), (math.pi, 0, -1.0), (-math.pi / 2, 1, -1.0))


def radius_rule(tolerance: Fraction | str) -> tuple[str, float]:
    """The I/J rule of the full path for ``tolerance`` (the interpreter's ``arc_tolerance``): ``("linuxcnc",
    0)`` or ``("fixed", tolerance in mm as a double rounded down)`` (Grbl's rule is the fixed 0.005 mm)."""
    if tolerance == "linuxcnc":
        return "linuxcnc", 0.0
    if tolerance == "grbl":
        tolerance = Fraction(5, 1000)
    t = to_float(Fraction(tolerance))
    if Fraction(t) > Fraction(tolerance):
        t = math.nextafter(t, _DOWN)
    return "fixed", t


def _accepted(r0: float, r1: float, rule: tuple[str, float], err: float) -> bool:
    """Is an I/J arc with radii ``r0``, ``r1`` (doubles within ``err / 2`` of the exact radii) clearly inside
    the full path's rule, by a margin far above those errors and the rule's own rounding?"""
    diff = abs(r1 - r0)
    big = max(r0, r1)
    slack = big * 1e-9 + 1e-9 + 2 * err
    kind, tol = rule
    if kind == "fixed":
        return diff + slack < tol
    # interpreter.linuxcnc_rejects_arc, in mm (the pass runs G21 only): refused when |r1 - r0| > 100 A, or
    # > A and > 0.001 of the larger radius, A = 2 * 0.01 * sqrt 2
    a = 2 * 0.01 * math.sqrt(2)
    return diff + slack < a or (diff + slack < 100 * a and diff + slack < 0.001 * (big - slack))


def _err(m: float) -> float:
    return (64.0 * m + 0.0625) * _U


def ij_arc(sx: float, sy: float, ex: float, ey: float, i: float, j: float, cw: bool, offb: float,
           rule: tuple[str, float]) -> Any:
    """The box ``(xlo, xhi, ylo, yhi)`` (doubles, outer bounds) holding the full path's I/J arc from ``(sx, sy)``
    to ``(ex, ey)`` (machine doubles) with centre offsets ``i``, ``j``, or a ``str``: why the pass declines.
    ``offb`` bounds the work offsets' magnitude (rounded up).

    >>> box = ij_arc(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, False, 0.0, ("fixed", 0.002))  # a ccw quarter
    >>> [round(v, 9) + 0.0 for v in box]
    [0.0, 1.0, 0.0, 1.0]
    >>> [round(v, 9) + 0.0 for v in ij_arc(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, True, 0.0, ("fixed", 0.002))]
    [-1.0, 1.0, -1.0, 1.0]
    """
    cx, cy = sx + i, sy + j  # |C - C'| <= rho + m 2**-52
    ux, uy = -i, -j  # exactly the doubles of -I, -J: within m 2**-53 of S - C
    wx, wy = ex - cx, ey - cy  # within 2 rho + 2 m 2**-52 of E - C
    r0, r1 = math.hypot(ux, uy), math.hypot(wx, wy)  # within 3 rho + 6 m 2**-52 of the exact radii
    m = max(abs(sx), abs(sy), abs(ex), abs(ey), abs(cx), abs(cy), r0, r1) + offb  # r0 >= |i|, |j|
    err = _err(m)  # rho <= (4 m + 2**-8) 2**-52: every error above is below err / 4
    if not (r0 > 4 * err and r1 > 4 * err):
        return "an arc of a radius about 0"
    if not _accepted(r0, r1, rule, err):
        return "an arc whose end is near or past the arc tolerance"
    return _box(sx, sy, ex, ey, cx, cy, (ux, uy, wx, wy), max(r0, r1), abs(r1 - r0) + err, err, cw)


def r_arc(sx: float, sy: float, ex: float, ey: float, r: float, cw: bool, offb: float) -> Any:
    """The box ``(xlo, xhi, ylo, yhi)`` holding the full path's R arc, or a ``str``: why the pass declines.

    >>> [round(v, 9) + 0.0 for v in r_arc(1.0, 0.0, 0.0, 1.0, 1.0, False, 0.0)]  # ccw, R > 0: the short way
    [0.0, 1.0, 0.0, 1.0]
    >>> [round(v, 9) + 0.0 for v in r_arc(1.0, 0.0, 0.0, 1.0, -1.0, False, 0.0)]  # R < 0: three quarters about (1, 1)
    [0.0, 2.0, 0.0, 2.0]
    >>> r_arc(0.0, 0.0, 2.0, 0.0, 1.0, True, 0.0)  # a half circle: the full path's
    'an R arc of a chord about 0 or about 2|R| or longer'
    """
    dx, dy = ex - sx, ey - sy
    m0 = max(abs(sx), abs(sy), abs(ex), abs(ey)) + offb
    rho = (4.0 * m0 + 2.0**-8) * _U  # the rows' bound (DoublePath.enclosure's, halved)
    length = math.hypot(dx, dy)
    ed = 2 * rho + length * _U  # |d - d'| per component
    dd = dx * dx + dy * dy
    rr = r * r
    # |D - D'| <= 2 (|dx'| + |dy'|) ed + 2 ed**2 + 3 D' 2**-53 and |R**2 - R'**2| <= R'**2 2**-51
    e_x = rr * 2.0**-51 + (2 * (abs(dx) + abs(dy)) * ed + 2 * ed * ed + 2 * dd * _U) / 4 + (rr + dd) * _U
    x = rr - dd / 4
    if not (length > 4 * ed and x > _HALF * rr and x > 8 * e_x):
        return "an R arc of a chord about 0 or about 2|R| or longer"
    h = math.sqrt(x)
    e_h = e_x / h + h * _U  # |sqrt X - sqrt X'| <= e_x / sqrt X', plus the rounding of sqrt
    e_n = 3 * ed / length + 4 * _U  # the unit normal's error (per component)
    k = (h if (r > 0) != cw else -h) / length  # centre to the left of the chord: G3 with R > 0, G2 with R < 0
    cx, cy = (sx + ex) / 2 - k * dy, (sy + ey) / 2 + k * dx
    ux, uy, wx, wy = sx - cx, sy - cy, ex - cx, ey - cy
    m = max(m0, abs(cx), abs(cy), abs(r), h, length)
    e_c = rho + e_h + h * e_n + 4 * m * _U  # |C - C'|
    err = _err(m) + 2 * e_c  # above |C - C'| + rho + the rounding of the box's sums
    return _box(sx, sy, ex, ey, cx, cy, (ux, uy, wx, wy), abs(r), err, err, cw)


def _box(sx: float, sy: float, ex: float, ey: float, cx: float, cy: float, uw: tuple[float, float, float, float],
         rmax: float, widen: float, err: float, cw: bool) -> tuple[float, float, float, float]:
    """The box of the arc: its ends, ``C +- rmax`` in the directions its sweep may contain, widened by
    ``widen`` and rounded outwards (``err`` bounds the error of ``S - C`` and ``E - C`` per component)."""
    ux, uy, wx, wy = uw
    ru, rw = math.hypot(ux, uy), math.hypot(wx, wy)
    lo = [min(sx, ex), min(sy, ey)]
    hi = [max(sx, ex), max(sy, ey)]
    centre = (cx, cy)
    whole = not (ru > 2 * err and rw > 2 * err)
    start = sweep = eta = 0.0
    if not whole:
        a, b = math.atan2(uy, ux), math.atan2(wy, wx)
        start, end = (b, a) if cw else (a, b)  # clockwise from u to w is counter-clockwise from w to u
        eta = 2.5 * err / ru + 2.5 * err / rw + _SLACK
        sweep = (end - start) % _TAU
        whole = sweep < 4 * eta or sweep > _TAU - 4 * eta
    for angle, axis, sign in _DIRECTIONS:
        if whole or (angle - start + eta) % _TAU <= sweep + 4 * eta:
            v = centre[axis] + sign * rmax
            if sign > 0:
                hi[axis] = max(hi[axis], v)
            else:
                lo[axis] = min(lo[axis], v)
    return (math.nextafter(lo[0] - widen, _DOWN), math.nextafter(hi[0] + widen, _UP),
            math.nextafter(lo[1] - widen, _DOWN), math.nextafter(hi[1] + widen, _UP))
