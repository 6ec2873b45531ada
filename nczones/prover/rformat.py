"""Certified enclosures of R-format arc centres, in columns (DESIGN §2, §9).

An R-format arc (``G2 X.. Y.. R..``) from ``s`` to ``e`` with signed radius ``R`` has its centre at
``c = (s + e) / 2 + sign * t / 2 * (-d_b, d_a)``, ``d = e - s``, ``t = sqrt(X / D)`` with
``D = d_a**2 + d_b**2``, ``X = 4 R**2 - D``, and ``sign = -1`` when the centre is to the right of the
chord (G2 with R > 0, G3 with R < 0), else ``+1`` (:meth:`nczones.prover.geometry.ArcGeom.r_format_parts`,
the same formula with ``k = t / 2``).  ``t`` is irrational in general, so the column screen takes the
centre as an integer box ``[lo, hi]`` per plane axis, in units ``m`` times finer than the chunk's scale
(:func:`fine_factor`), that certainly holds it.  The inputs are exact integers; the doubles only move
bounds outwards, each by more than its certified error (``u = 2**-53``, IEEE-754 round to nearest,
correctly rounded ``+ - * / sqrt``):

* ``D' = d_a'**2 + d_b'**2`` and ``S' = 4 R'**2`` (``'``: the double of an integer, within ``u``
  relative) are within ``4u`` relative of ``D`` and ``4 R**2``, so ``X`` is within
  ``e_X = 2**-49 (S' + D')`` (at least ``8u (S + D)``) of ``X' = S' - D'``; a row with
  ``X' <= 2 e_X`` is not enclosed (a chord of about ``2|R|`` or more: the interpreter gives a half
  circle a rational centre, anything else is the exact path's to decide);
* ``t`` lies in ``[sqrt((X' - e_X) / D' (1 - 2**-45)) (1 - 2**-45), sqrt((X' + e_X) / D' (1 + 2**-45))
  (1 + 2**-45)]``: the factors ``1 ± 2**-45`` cover ``D'``'s error and the rounding of the sum, the
  division and the square root (each at most ``u``, together far below ``2**-45``);
* ``v = t * sign * (-d_b m)`` (and ``t * sign * d_a m`` for the other axis) lies between the products of
  the ``t`` bounds with the double of ``sign * (-d_b m)``, widened by ``2**-44`` relative (the rounding of
  that double and of the products) and by 1 unit; its floor and ceiling are exact integers, and
  ``2 m c = m (s + e) + v`` is halved with the floor and the ceiling.

Rows whose numbers, refined by ``m``, could reach ``2**59`` are not enclosed; :func:`rformat_boxes`
reports them with ``ok`` False, the screen flags them and the exact per-motion path decides them.

This module is the one place of these enclosures (the column screen, :func:`rformat_boxes`, reads it).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["centre_enclosure", "rformat_boxes", "fine_factor"]

#: Values in units of the fine scale stay below this (``int64`` sums of a few of them never wrap).
_FINE_LIMIT = 2**59
_WIDE = 2.0**-45
_REL = 2.0**-44


def fine_factor(scale: int, magnitude: int) -> int:
    """The power of ten ``m`` by which enclosures refine the scale ``10**-scale``: up to ``10**-9`` mm
    (``m = 10**(9 - scale)``), less when ``magnitude * m`` (the largest coordinate or radius, in units
    of the scale) would reach ``2**56``.

    >>> fine_factor(3, 200_000), fine_factor(9, 5), fine_factor(0, 2**40)
    (1000000, 1, 10000)
    """
    k = max(0, 9 - int(scale))
    while k > 0 and max(int(magnitude), 1) * 10**k >= 2**56:
        k -= 1
    return int(10**k)


def centre_enclosure(sa: np.ndarray, sb: np.ndarray, ea: np.ndarray, eb: np.ndarray, r: np.ndarray,
                     cw: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(ok, a_lo, a_hi, b_lo, b_hi)``: the centre of each R-format arc (start ``(sa, sb)``, end ``(ea, eb)``,
    signed radius ``r``, clockwise ``cw``; ``int64`` at one scale) lies in ``[a_lo, a_hi] x [b_lo, b_hi]``
    in units ``m`` times finer, where ``ok``; see the module docstring.  The caller keeps every input
    times ``2 m`` below ``2**59``.

    >>> A = lambda *v: np.array(v, dtype=np.int64)
    >>> ok, alo, ahi, blo, bhi = centre_enclosure(A(0), A(0), A(2), A(0), A(2), np.array([True]), 10**8)
    >>> bool(ok[0]), [int(v[0]) for v in (alo, ahi, blo, bhi)]  # G2 X2 Y0 R2 from 0: the centre is (1, -sqrt 3)
    (True, [99999999, 100000001, -173205082, -173205080])
    """
    da = ea - sa
    db = eb - sb
    daf, dbf, rf = da.astype(np.float64), db.astype(np.float64), r.astype(np.float64)
    d2 = daf * daf + dbf * dbf
    s4 = 4.0 * rf * rf
    x = s4 - d2
    ex = (s4 + d2) * 2.0**-49
    ok = (d2 > 0) & (x > 2 * ex)
    d2 = np.where(ok, d2, 1.0)
    x = np.where(ok, x, 1.0)
    ex = np.where(ok, ex, 0.0)
    t_lo = np.sqrt((x - ex) / d2 * (1 - _WIDE)) * (1 - _WIDE)
    t_hi = np.sqrt((x + ex) / d2 * (1 + _WIDE)) * (1 + _WIDE)
    right = cw.astype(bool) != (r < 0)
    sign = np.where(right, -1, 1)
    ma, mb = (sa + ea) * m, (sb + eb) * m

    def bounds(mid: np.ndarray, k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        kf = (k * m).astype(np.float64)
        v1, v2 = t_lo * kf, t_hi * kf
        lo, hi = np.minimum(v1, v2), np.maximum(v1, v2)
        lo = np.floor(lo - np.abs(lo) * _REL - 1.0).astype(np.int64)
        hi = np.ceil(hi + np.abs(hi) * _REL + 1.0).astype(np.int64)
        return (mid + lo) // 2, -((-(mid + hi)) // 2)

    a_lo, a_hi = bounds(ma, -sign * db)
    b_lo, b_hi = bounds(mb, sign * da)
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
