"""Certified enclosures of R-format arc centres, in columns (DESIGN §2, §9).

An R-format arc (``G2 X.. Y.. R..``) from ``s`` to ``e`` with signed radius ``R`` has its centre at
``c = (s + e) / 2 + sign * t / 2 * (-d_b, d_a)``, ``d = e - s``, ``t = sqrt((4 R**2 - |d|**2) / |d|**2)``
and ``sign = -1`` when the centre is to the right of the chord (G2 with R > 0, G3 with R < 0), else
``+1`` (:meth:`nczones.prover.geometry.ArcGeom.r_format_parts`, the same formula with ``k = t / 2``).
``t`` is irrational in general, so the column screen takes the centre as an integer box
``[lo, hi]`` (per plane axis, in units of ``10**-scale / m``) that certainly holds it:

* ``d_a, d_b`` and ``2R`` are integers below ``2**26`` in magnitude (other rows are not enclosed), so
  ``D = d_a**2 + d_b**2 < 2**53`` and ``X = 4 R**2 - D`` (``|X| < 2**52``) are exact in ``int64`` and
  exact as doubles;
* the double ``t' = sqrt(X / D)`` (one correctly rounded division, one correctly rounded square root)
  is within ``2u`` relative of ``t`` (``u = 2**-53``); the double ``v = t' * float(d_b * m)`` (``d_b * m``
  an exact integer below ``2**56``, rounded once to a double, then one rounded product) is within ``4u``
  relative of ``t * d_b * m``;
* the enclosure widens ``v`` by ``|v| * 2**-40 + 1`` (far more than ``4u |v|`` plus the rounding of that
  subtraction) before the floor and the ceiling, so ``2 m c`` lies in ``[2 m M + floor(v - w),
  2 m M + ceil(v + w)]`` exactly (``2 M = s + e``, an integer), and halving with the floor and the ceiling
  keeps it.

No decision rests on a double compared with a threshold: every double only moves a bound outwards by
less than its certified error.  Rows outside the magnitudes above, or with ``X <= 0`` (a chord of at
least ``2|R|``: the interpreter gives a half circle a rational centre, and anything else is the exact
path's to refuse), or ``D = 0``, are reported as not enclosed; the screen flags them and the exact
per-motion path decides them.

This module is the one place of these enclosures (the column screen, :func:`rformat_boxes`, reads it).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["centre_enclosure", "rformat_boxes", "ENCLOSE_LIMIT"]

#: Chord components and ``2|R|`` (in units of the chunk's scale) must be below this to be enclosed.
ENCLOSE_LIMIT = 2**26
#: Values in units of the fine scale stay below this (``int64`` sums of a few of them never wrap).
_FINE_LIMIT = 2**59
_REL = 2.0**-40


def fine_factor(scale: int, magnitude: int) -> int:
    """The power of ten ``m`` by which enclosures refine the scale ``10**-scale``: up to ``10**-9`` mm
    (``m = 10**(9 - scale)``), less when ``magnitude * m`` (the largest coordinate or radius, in units
    of the scale) would reach ``2**56``.

    >>> fine_factor(3, 200_000), fine_factor(9, 5), fine_factor(0, 2**40)
    (1000000, 1, 10000)
    """
    k = max(0, 9 - scale)
    while k > 0 and max(magnitude, 1) * 10**k >= 2**56:
        k -= 1
    return 10**k


def centre_enclosure(sa: np.ndarray, sb: np.ndarray, ea: np.ndarray, eb: np.ndarray, r: np.ndarray,
                     cw: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(ok, a_lo, a_hi, b_lo, b_hi)``: the centre of each R-format arc (start ``(sa, sb)``, end ``(ea, eb)``,
    signed radius ``r``, clockwise ``cw``; ``int64`` at one scale) lies in ``[a_lo, a_hi] x [b_lo, b_hi]``
    in units ``m`` times finer, where ``ok``; see the module docstring.  The caller keeps ``|sa + ea| * m``
    (and the same for ``b``) below ``2**59``.

    >>> A = lambda *v: np.array(v, dtype=np.int64)
    >>> ok, alo, ahi, blo, bhi = centre_enclosure(A(0), A(0), A(2), A(0), A(2), np.array([True]), 1000)
    >>> bool(ok[0]), int(alo[0]) <= 1000 <= int(ahi[0]), int(blo[0]) < -1732050 < int(bhi[0]), int(bhi[0] - blo[0]) < 4
    (True, True, True, True)
    """
    da = ea - sa
    db = eb - sb
    ok = ((np.abs(da) < ENCLOSE_LIMIT) & (np.abs(db) < ENCLOSE_LIMIT) & (np.abs(r) < ENCLOSE_LIMIT // 2)
          & (r != 0))
    da = np.where(ok, da, 0)
    db = np.where(ok, db, 0)
    rr = np.where(ok, r, 1)
    d2 = da * da + db * db
    x = 4 * rr * rr - d2
    ok &= (d2 > 0) & (x > 0)
    d2 = np.where(ok, d2, 1)
    x = np.where(ok, x, 1)
    t = np.sqrt(x.astype(np.float64) / d2.astype(np.float64))
    right = cw.astype(bool) != (r < 0)
    sign = np.where(right, -1.0, 1.0)
    va = sign * t * (-(db * m)).astype(np.float64)
    vb = sign * t * (da * m).astype(np.float64)
    wa = np.abs(va) * _REL + 1.0
    wb = np.abs(vb) * _REL + 1.0
    ma, mb = (sa + ea) * m, (sb + eb) * m
    a_lo = (ma + np.floor(va - wa).astype(np.int64)) // 2
    a_hi = -((-(ma + np.ceil(va + wa).astype(np.int64))) // 2)
    b_lo = (mb + np.floor(vb - wb).astype(np.int64)) // 2
    b_hi = -((-(mb + np.ceil(vb + wb).astype(np.int64))) // 2)
    return ok, a_lo, a_hi, b_lo, b_hi


def _sign(v: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The sign of ``v - c`` for a ``c`` in ``[lo, hi]`` (``+1``/``-1``) and whether it is certain."""
    return np.where(v > hi, 1, -1), (v > hi) | (v < lo)


def rformat_boxes(sa: np.ndarray, sb: np.ndarray, ea: np.ndarray, eb: np.ndarray, r: np.ndarray, cw: np.ndarray,
                  turns: np.ndarray, scale: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(ok, lo_a, hi_a, lo_b, hi_b)``: a box (at the chunk's scale, rounded outwards) holding each R-format
    arc's plane path, where ``ok``.

    The box holds the end points and, for each direction ``±a``, ``±b`` the closed sweep contains, the
    centre's enclosure plus or minus ``|R|``.  Which directions the sweep contains follows from the signs
    of the components of ``s - c`` and ``e - c`` (as :func:`nczones.prover.screen.arc_boxes` decides them)
    and from the sign of ``R`` (``R > 0``: less than a half turn; ``R < 0``: more); a row where one of
    those signs is not certain for every centre in the enclosure, or that turns more than once, takes all
    four (the whole circle's box), which holds the arc too.
    """
    mag = int(max((np.abs(v).max(initial=0) for v in (sa, sb, ea, eb, r)), default=0))
    m = fine_factor(scale, 2 * mag + 1)
    ok, a_lo, a_hi, b_lo, b_hi = centre_enclosure(sa, sb, ea, eb, r, cw, m)
    if 2 * mag * m >= _FINE_LIMIT:
        ok[:] = False
    fsa, fsb, fea, feb = sa * m, sb * m, ea * m, eb * m
    p0, c0 = _sign(fsa, a_lo, a_hi)
    p1, c1 = _sign(fsb, b_lo, b_hi)
    q0, c2 = _sign(fea, a_lo, a_hi)
    q1, c3 = _sign(feb, b_lo, b_hi)
    full = ~(c0 & c1 & c2 & c3) | (turns > 0)
    ccw = ~cw.astype(bool)
    # ccw from p to q is the sweep (clockwise from u to w is ccw from w to u), as screen.arc_boxes orders them
    u0, u1, w0, w1 = p0, p1, q0, q1
    p0, p1 = np.where(ccw, u0, w0), np.where(ccw, u1, w1)
    q0, q1 = np.where(ccw, w0, u0), np.where(ccw, w1, u1)
    hw = (r < 0).astype(np.int64)  # the sweep is in [0, pi) (R > 0) or beyond (R < 0): a chord strictly shorter than 2|R|

    def half(cr: np.ndarray, dt: np.ndarray) -> Any:
        return np.where((cr > 0) | ((cr == 0) & (dt > 0)), 0, 1)

    def contains(cr_pv: np.ndarray, dot_pv: np.ndarray, cr_vq: np.ndarray) -> Any:
        hv = half(cr_pv, dot_pv)
        return full | np.where(hv != hw, hv < hw, cr_vq >= 0)

    plus_a = contains(-p1, p0, q1)
    minus_a = contains(p1, -p0, -q1)
    plus_b = contains(p0, p1, -q0)
    minus_b = contains(-p0, -p1, q0)
    rm = np.abs(r) * m
    lo_a = np.minimum(fsa, fea)
    hi_a = np.maximum(fsa, fea)
    lo_b = np.minimum(fsb, feb)
    hi_b = np.maximum(fsb, feb)
    lo_a = np.where(minus_a, np.minimum(lo_a, a_lo - rm), lo_a)
    hi_a = np.where(plus_a, np.maximum(hi_a, a_hi + rm), hi_a)
    lo_b = np.where(minus_b, np.minimum(lo_b, b_lo - rm), lo_b)
    hi_b = np.where(plus_b, np.maximum(hi_b, b_hi + rm), hi_b)
    return ok, lo_a // m, -((-hi_a) // m), lo_b // m, -((-hi_b) // m)
