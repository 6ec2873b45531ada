"""Arcs of the double pass (:mod:`nczones.gcode.linuxcnc.doubles`): from the pass's doubles, a box that holds
the full path's exact arc, or the reason the pass declines the arc.

The full path (``Interpreter.arc``) models an arc exactly in its plane's first and second axes (G17: X, Y;
G18: Z, X; G19: Y, Z, ``motion.PLANE_AXES``; here ``x`` and ``y`` stand for them, I and J for the plane's
centre words, and G2 is clockwise in that order): an I/J arc from the exact start ``S`` about
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
end).  The sweep's ends are ``u = S - C`` and ``w = E - C``, each component within ``err`` of its double: the
directions taken are those of every sweep between a quadrant the exact ``u`` may lie in and one the exact ``w``
may lie in (:func:`_box`; a sweep of about 0 or a whole turn takes all four: LinuxCNC makes an end on the
start's ray a whole turn).  Taking a direction the exact sweep does not contain only grows the box, which
stays sound.

Quick boxes: :func:`r_screen` (the discs of radius ``2|R|`` about the ends, or for ``R > 0`` the disc on the
chord, no square root) and :func:`ij_screen` (the centre +- the larger radius) hold the arc by the same error
terms (their docstrings) and decline exactly what :func:`r_arc` / :func:`ij_arc` decline or more; the pass
keeps them and :func:`refined` gives the sweep's box when a proof needs a tighter one.

What declines (the full path errors or decides otherwise there): a radius about 0 (GC304 exactly at 0), an
I/J radius near or below LinuxCNC's zero-radius limit of 0.00005 inch (GC304 on the full path), an
I/J arc whose radii differ near or past the arc tolerance's rule (GC301), an R arc whose chord is about 0
(GC303) or about ``2|R|`` or longer (a half circle or GC302).
"""

from __future__ import annotations

import math
from fractions import Fraction

from ...exact import to_float

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["R_INCH_REL", "R_WHY", "chain_offb", "inch_offb", "inch_rule", "ij_arc", "ij_screen", "r_arc", "r_screen",
           "r_screen_code", "radius_rule", "refined", "sector_box"]

_U = 2.0**-52
#: An R arc is declined unless ``X' > _HALF * R'**2`` (its chord is clearly shorter than 2|R|).
_HALF = 1e-9
#: :func:`r_screen`'s quick form of its last decline test (``ed (l1 + ed) < _QUICK_X R**2``): see its docstring.
_QUICK_X = 2e-10
_DOWN, _UP = -math.inf, math.inf
#: LinuxCNC's CENTER_ARC_RADIUS_TOLERANCE in mm (2 * 0.01 * sqrt 2), and its inch one (2 * 0.001 * sqrt 2 inch) in
#: mm: an I/J arc in G20 is compared in inches (``interpreter.linuxcnc_rejects_arc``).
_A = 2 * 0.01 * math.sqrt(2)
_A_INCH = 25.4 * 2 * 0.001 * math.sqrt(2)
#: LinuxCNC refuses an I/J radius below 0.00005 inch ("Zero-radius arc", ``interpreter.LINUXCNC_ZERO_RADIUS_SQ``):
#: the pass takes radii clearly above it (the radii's doubles are within ``err / 2`` of the exact ones).
_ZERO_RADIUS = 0.00127 * (1 + 1e-6)


def radius_rule(tolerance: Fraction | str) -> float:
    """The I/J rule of the full path for ``tolerance`` (the interpreter's ``arc_tolerance``), as :func:`ij_arc`
    takes it: -1 for LinuxCNC's rule, else the tolerance in mm as a double rounded down (Grbl's rule is the
    fixed 0.005 mm)."""
    if tolerance == "linuxcnc":
        return -1.0
    if tolerance == "grbl":
        tolerance = Fraction(5, 1000)
    t = to_float(Fraction(tolerance))
    if Fraction(t) > Fraction(tolerance):
        t = math.nextafter(t, _DOWN)
    return t


#: :func:`r_arc`'s ``rel`` for an R arc in G20: its R is ``fl(d * fl(25.4))``, within ``2.52 u |R'|`` (plus ``28 eta``,
#: far below what the declines of a chord about 0 leave) of the full path's exact ``25.4 w`` (:mod:`.double_units`),
#: so ``|R**2 - R'**2| <= (5.04 u + 7 u**2) R'**2``, below ``8 u R'**2 = 2**-50 R'**2``.  :func:`r_screen`'s box
#: takes ``|R| <= |R'| (1 + 2.52 u)``: its ``2 |R'|`` then moves by ``5.04 u |R'|``, far below its ``err``.
R_INCH_REL = 2.0**-50

#: :func:`radius_rule`'s LinuxCNC rule for an arc in G20 (``inch_rule``).
INCH_RULE = -2.0


def inch_rule(rule: float) -> float:
    """The rule :func:`ij_check` takes for an I/J arc in G20: LinuxCNC's in inches (:data:`INCH_RULE`), or the
    same fixed tolerance in mm (the full path's ``sqrt_diff_exceeds`` is in mm whatever the units)."""
    return INCH_RULE if rule < 0 else rule


def inch_offb(offb: float, i: float, j: float) -> float:
    """The offsets' bound an I/J arc in G20 is computed with: ``offb + 2 (|i| + |j|)`` rounded up.

    The words ``i``, ``j`` of an arc in G20 are ``fl(d * fl(25.4))``: within ``2.52 u |i| + 28 eta`` of the full
    path's exact ``25.4 w`` (:mod:`.double_units`), where :func:`ij_check`'s sums take half an ulp, ``u |i|``.  Each
    of those sums counts a word's error at most once per ``m 2**-52`` it allows (``|C - C'| <= rho + m 2**-52``,
    the radii within ``3 rho + 6 m 2**-52``), and every quantity moves by at most the words' error (``C = S + (I,
    J)``, the radii are 1-Lipschitz in the centre): with ``m`` grown by ``2 (|i| + |j|)`` each allowance grows by
    ``4 u (|i| + |j|)``, above the extra ``1.52 u (|i| + |j|)``; the ``28 eta`` are far below ``err``'s
    ``2**-56``.  ``err`` grows with ``m``: the box is wider and the declines (zero radius, the start's ray, the
    tolerance) take more, which stays sound."""
    return math.nextafter(offb + 2.0 * (abs(i) + abs(j)), _UP)


def chain_offb(offb: float, ein: float) -> float:
    """The offsets' bound an arc is computed with when its start or end row carries a G91 chain's error: ``offb +
    ein 2**50`` rounded up, ``ein`` a bound of ``|S' - S|`` and ``|E' - E|`` per component (the chains' bounds of
    the plane's two axes at the arc's start and end, ``_Pass._arc_plane_body``: each bounds the whole distance of its
    row's double from the full path's exact coordinate, the G90 row's part included).

    Every function here takes the rows' error as ``rho <= (4 m + 2**-8) 2**-52`` with ``m`` at or above the offsets'
    bound (the module's docstring, :func:`ij_check`, :func:`r_arc`, :func:`r_screen`: ``rho`` enters each error
    sum only through that bound, and every other term grows with ``m``).  With the offsets' bound grown by ``ein
    2**50`` (exact: a power of two) that bound grows by ``4 ein 2**50 2**-52 = ein``, above a chained row's whole
    error: the arguments hold as written for arcs whose ends carry a chain's error (G91 arcs, and G90 arcs whose
    start or unnamed plane axis is still on a chain).  ``err`` grows with ``m`` (by ``16 ein``): the boxes are
    wider and the declines (zero radius, the start's ray, the tolerance, a chord about 0 or ``2|R|``) take more,
    which stays sound; a chain so long that its error matters declines its arcs.

    >>> chain_offb(0.0, 0.0), chain_offb(10.0, 2.0**-40) > 10.0 + 2.0**10
    (0.0, True)
    """
    if ein == 0.0:
        return offb
    return math.nextafter(offb + ein * 2.0**50, _UP)


def ij_arc(sx: float, sy: float, ex: float, ey: float, i: float, j: float, cw: bool, offb: float,
           tol: float, turn: bool = False) -> Any:
    """The box of :func:`ij_check`'s arc (:func:`_box`), or its ``str``."""
    got = ij_check(sx, sy, ex, ey, i, j, cw, offb, tol, turn)
    if got.__class__ is str:
        return got
    return _box(*got)


def ij_screen(sx: float, sy: float, ex: float, ey: float, i: float, j: float, cw: bool, offb: float,
              tol: float, turn: bool = False) -> Any:
    """A box holding the full path's I/J arc, quicker than :func:`ij_arc`'s (no sweep), or :func:`ij_check`'s
    ``str``: the disc about the centre ``C'`` of radius the larger radius ``big`` (the arc lies in the annulus
    about the exact centre ``C`` of radii ``r_min``..``r_max``; ``|C - C'|`` is below ``err / 4`` and
    ``|r_max - big|`` below ``err / 2``, :func:`ij_check`), widened by ``2 err``, far above those and the rounding of the four
    sums (each below ``m 2**-52``).  :func:`refined` narrows it to :func:`ij_arc`'s box when a proof needs it.

    >>> [round(v, 9) + 0.0 for v in ij_screen(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, False, 0.0, 0.002)]
    [-1.0, 1.0, -1.0, 1.0]
    """
    return ij_check(sx, sy, ex, ey, i, j, cw, offb, tol, turn, True)


def ij_check(sx: float, sy: float, ex: float, ey: float, i: float, j: float, cw: bool, offb: float,
             tol: float, turn: bool = False, screen: bool = False) -> Any:
    """:func:`_box`'s arguments for the box ``(xlo, xhi, ylo, yhi)`` (doubles, outer bounds) holding the full
    path's I/J arc from ``(sx, sy)``
    to ``(ex, ey)`` (machine doubles) with centre offsets ``i``, ``j``, or a ``str``: why the pass declines.
    ``offb`` bounds the work offsets' magnitude (rounded up), ``tol`` is :func:`radius_rule`'s; ``turn``: the
    block names no axis of the plane, so the end is the start exactly (a whole turn); ``screen``: return
    :func:`ij_screen`'s box instead (the pass calls this directly: a call of ten arguments and a tuple of
    fourteen less an arc, a quarter of the check's cost).

    An end that may lie on the ray from the centre through the start (their cross product within its error
    of 0; the dot product is then about ``r0 r1``, clearly positive or negative) is declined unless ``turn``:
    LinuxCNC moves a whole turn there, which the full path proves by the circle for an end equal to the start
    and otherwise (a spiral lap) by the box of the centre +- the larger radius (``Prover._decide_whole_turn``);
    the doubles cannot tell the two apart, so the pass leaves both to the full path.

    The radii's doubles are within ``err / 2`` of the exact radii; an arc is taken when it is inside the full
    path's rule (exact for a fixed tolerance, LinuxCNC's in doubles) by ``2 err`` and ``1e-9`` of the radius
    and ``1e-9`` mm more, far above those errors and the rule's own rounding.

    >>> box = ij_arc(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, False, 0.0, 0.002)  # a ccw quarter
    >>> [round(v, 9) + 0.0 for v in box]
    [0.0, 1.0, 0.0, 1.0]
    >>> [round(v, 9) + 0.0 for v in ij_arc(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, True, 0.0, 0.002)]
    [-1.0, 1.0, -1.0, 1.0]
    """
    cx, cy = sx + i, sy + j  # |C - C'| <= rho + m 2**-52
    wx, wy = ex - cx, ey - cy  # within 2 rho + 2 m 2**-52 of E - C (and -i, -j within m 2**-53 of S - C)
    r0, r1 = math.hypot(i, j), math.hypot(wx, wy)  # within 3 rho + 6 m 2**-52 of the exact radii
    # m: above every magnitude here (|C| <= |S| + r0, |E| <= |C| + r1), so rho <= (4 m + 2**-8) 2**-52
    # (conditionals for abs(): this runs per arc)
    m = (sx if sx >= 0.0 else -sx) + (sy if sy >= 0.0 else -sy) + r0 + r1 + offb  # (>= max(|sx|, |sy|) + ...)
    # every error above is below err / 2: the radii's is the largest, 3 rho + 6 m 2**-52 <= (18 m + 2**-6) 2**-52
    # (the centre's, rho + m 2**-52, below err / 4); the uses below need no less (units39 found the comment's
    # former err / 4 too small for the radii)
    err = (64.0 * m + 0.0625) * _U
    if not (r0 > _ZERO_RADIUS + err and r1 > _ZERO_RADIUS + err):  # (4 err < _ZERO_RADIUS + err)
        return "an arc of a radius about 0 or near LinuxCNC's zero-radius limit"
    if not turn and i * wx + j * wy < 0:  # -(u . w), u = (-i, -j): the end ahead of the start's normal
        a = j * wx - i * wy  # the cross product of u and w
        if abs(a) <= err * (abs(i) + abs(j) + abs(wx) + abs(wy)) * 1.01 + 2 * err * err + \
                (abs(j * wx) + abs(i * wy)) * 2.0**-51:
            return "an arc whose end may lie on the ray from the centre through its start"
    diff, big = (r1 - r0, r1) if r1 > r0 else (r0 - r1, r0)
    margin = diff + big * 1e-9 + 1e-9 + 2 * err
    # tol >= 0: the fixed rule; else LinuxCNC's (``interpreter.linuxcnc_rejects_arc`` is False, by a margin:
    # ``diff`` already holds one), in mm: refused when ``|r1 - r0| > 100 A``, or ``> A`` and ``> 0.001`` of the
    # larger radius, ``A = 2 * 0.01 * sqrt 2`` mm in G21, ``a = 2 * 0.001 * sqrt 2`` inch (_A_INCH mm) in G20, where
    # LinuxCNC compares the radii divided by 25.4 in doubles (the margin's 1e-9 of the radius and 1e-9 mm are far
    # above those roundings); written out here, not a call (plane42: a call less an I/J arc)
    a = _A if tol == -1.0 else _A_INCH
    if not (margin < tol if tol >= 0 else margin < a or (margin < 100 * a and margin < 0.001 * (big - margin))):
        return "an arc whose end is near or past the arc tolerance"
    if screen:  # ij_screen's box
        w = big + 2 * err
        return (cx - w, cx + w, cy - w, cy + w)
    return (sx, sy, ex, ey, cx, cy, -i, -j, wx, wy, big, diff + err, err, cw)



def r_arc(sx: float, sy: float, ex: float, ey: float, r: float, cw: bool, offb: float, rel: float = 2.0**-51) -> Any:
    """The box ``(xlo, xhi, ylo, yhi)`` holding the full path's R arc, or a ``str``: why the pass declines.
    ``rel`` bounds ``|R**2 - R'**2| / R'**2``: ``2**-51`` for a word's double (half an ulp), :data:`R_INCH_REL` for
    a G20 word's millimetres.

    >>> [round(v, 9) + 0.0 for v in r_arc(1.0, 0.0, 0.0, 1.0, 1.0, False, 0.0)]  # ccw, R > 0: the short way
    [0.0, 1.0, 0.0, 1.0]
    >>> [round(v, 9) + 0.0 for v in r_arc(1.0, 0.0, 0.0, 1.0, -1.0, False, 0.0)]  # R < 0: three quarters about (1, 1)
    [0.0, 2.0, 0.0, 2.0]
    >>> r_arc(0.0, 0.0, 2.0, 0.0, 1.0, True, 0.0)  # a half circle: the full path's
    'an R arc of a chord about 0 or about 2|R| or longer'
    """
    dx, dy = ex - sx, ey - sy
    ar = abs(r)
    # m: above every magnitude here (|S|, |E|, the offsets, |R|, and |C| <= |S| + |R|)
    m = (abs(sx) if abs(sx) > abs(sy) else abs(sy)) + (abs(ex) if abs(ex) > abs(ey) else abs(ey)) + 2 * ar + offb
    rho = (4.0 * m + 2.0**-8) * _U  # above the rows' bound
    length = math.hypot(dx, dy)
    ed = 2 * rho + length * _U  # |d - d'| per component
    dd = dx * dx + dy * dy
    rr = r * r
    # X = R**2 - D/4: |D - D'| <= 2 (|dx'| + |dy'|) ed + 2 ed**2 + 3 D' 2**-53, |R**2 - R'**2| <= R'**2 rel,
    # and the rounding of X' itself
    e_x = rr * rel + ((abs(dx) + abs(dy)) * ed + ed * ed + dd * _U) / 2 + (rr + dd) * _U
    x = rr - dd / 4
    if not (length > 4 * ed and x > _HALF * rr and x > 8 * e_x):
        return "an R arc of a chord about 0 or about 2|R| or longer"
    h = math.sqrt(x)
    # |h - h'| <= e_x / sqrt X' (plus sqrt's rounding); the unit normal is within 3 ed / |d'| + 4 2**-53 per
    # component; the centre C' within rho + |h - h'| + h |n - n'| + 4 m 2**-52 of C
    e_c = rho + e_x / h + h * (3 * ed / length + 6 * _U) + 4 * m * _U
    err = (64.0 * m + 0.0625) * _U + 2 * e_c  # above |C - C'| + rho + the rounding of the box's sums
    k = (h if (r > 0) != cw else -h) / length  # centre to the left of the chord: G3 with R > 0, G2 with R < 0
    cx, cy = (sx + ex) / 2 - k * dy, (sy + ey) / 2 + k * dx
    return _box(sx, sy, ex, ey, cx, cy, sx - cx, sy - cy, ex - cx, ey - cy, ar, err, err, cw)


def r_screen(sx: float, sy: float, ex: float, ey: float, r: float, offb: float, rel: float = 2.0**-51) -> Any:
    """A box holding the full path's R arc, with no square root (quicker than :func:`r_arc`'s), or a ``str``:
    why the pass declines; it accepts only arcs :func:`r_arc` accepts.  :func:`refined` narrows it to
    :func:`r_arc`'s box when a proof needs it.

    The exact arc lies on a circle of radius ``|R|`` through ``S`` and ``E``: within ``2|R|`` of each.  An arc
    with ``R > 0`` is at most a half circle (the short way), so from each of its points the chord is seen under
    an angle of at least 90 degrees (the inscribed angle over the long arc, ``pi - theta / 2`` for a sweep
    ``theta <= pi``): it lies in the disc on the chord, of centre ``M = (S + E) / 2`` and radius
    ``|E - S| / 2 <= (|dx| + |dy|) / 2``.  With the doubles: ``|S - S'|``, ``|E - E'| <= rho`` per component
    (``rho`` of :func:`r_arc`, below ``5 m 2**-52``), ``|R| <= |R'| (1 + 2**-53)``, so the box of ``S' +- 2|R'|``
    and ``E' +- 2|R'|`` (``R < 0``) or ``M' +- (|dx'| + |dy'|) / 2`` (``R > 0``: ``M'`` and the half-sum within
    ``3 rho + 3 m 2**-52`` of the exact ones) widened by ``err = (64 m + 2**-4) 2**-52`` holds it; ``err`` is
    above those terms plus the rounding of the sums (each below ``m 2**-52``).  ``m`` here,
    ``2 (|sx| + |sy| + |R|) + |dx| + |dy|`` plus the offsets' bound, is at least :func:`r_arc`'s
    (``|ex| <= |sx| + |dx|``).

    The decline: ``ed`` here is above :func:`r_arc`'s (``9 m`` for its ``8 m``, far above the rounding of
    either ``m``; ``|E' - S'| <= |dx'| + |dy'|``) and ``e_x`` grows with it; ``dd > 17 ed**2`` gives
    ``|E' - S'| > 4 ed`` (``dd`` and the hypot within a few ulps), so every arc taken here passes
    :func:`r_arc`'s test (whose argument says the full path takes it, neither GC302 nor GC303).  The last test,
    ``x > 8 e_x``, is not computed where ``ed (l1 + ed) < 2e-10 R**2`` (doubles, :data:`_QUICK_X`) and ``x > 1e-9
    R**2`` (the test before) hold, for they imply it: ``x > 0`` gives ``dd <= 4 R**2``, so ``e_x <= (1 + 5u)
    R**2 (2**-50 + 1e-10 + 11 * 2**-52)`` (``rel <= 2**-50``, each operation's rounding counted), ``8 e_x`` below
    ``8.001e-10 R**2 < x``; a product ``ed (l1 + ed)`` below ``2e-10 R**2`` is at least ``2**-118`` (``ed >=
    2**-59``), so ``2e-10 R**2`` is a normal double and those relative bounds hold; an inf or a nan fails the
    quick test and the full one decides.  So the answer is the full test's, always
    (``tests/gcode/test_double_pass_r_screen.py``).

    >>> [round(v, 9) + 0.0 for v in r_screen(1.0, 0.0, 0.0, 1.0, 1.0, 0.0)]  # in the disc on the chord
    [-0.5, 1.5, -0.5, 1.5]
    >>> [round(v, 9) + 0.0 for v in r_screen(1.0, 0.0, 0.0, 1.0, -1.0, 0.0)]  # within 2|R| of both ends
    [-1.0, 2.0, -1.0, 2.0]
    >>> r_screen(0.0, 0.0, 2.0, 0.0, 1.0, 0.0)  # a half circle: the full path's
    'an R arc of a chord about 0 or about 2|R| or longer'
    """
    dx = ex - sx
    dy = ey - sy
    ax = dx if dx >= 0.0 else -dx  # (conditionals: quicker than abs() calls, on a path run per arc)
    ay = dy if dy >= 0.0 else -dy
    ar = r if r >= 0.0 else -r
    l1 = ax + ay
    m = 2.0 * ((sx if sx >= 0.0 else -sx) + (sy if sy >= 0.0 else -sy) + ar) + l1 + offb
    ed = (9.0 * m + 2.0**-7 + l1) * _U  # above r_arc's 2 rho + |E' - S'| 2**-52
    dd = dx * dx + dy * dy
    rr = r * r
    x = rr - dd / 4
    # r_arc's e_x, with this ed; _QUICK_X first: it implies the last test (the docstring), 12 float operations fewer
    if not (dd > 17 * ed * ed and x > _HALF * rr
            and (ed * (l1 + ed) < _QUICK_X * rr
                 or x > 8 * (rr * rel + (l1 * ed + ed * ed + dd * _U) / 2 + (rr + dd) * _U))):
        return R_WHY
    err = (64.0 * m + 0.0625) * _U
    if r > 0.0:
        w = l1 / 2 + err
        mx = (sx + ex) / 2
        my = (sy + ey) / 2
        return (mx - w, mx + w, my - w, my + w)
    w = 2 * ar + err
    if sx > ex:
        xlo, xhi = sx - w, ex + w
    else:
        xlo, xhi = ex - w, sx + w
    if sy > ey:
        return (xlo, xhi, sy - w, ey + w)
    return (xlo, xhi, ey - w, sy + w)


#: Why :func:`r_screen` (and its inline form, :func:`r_screen_code`) declines an arc.
R_WHY = "an R arc of a chord about 0 or about 2|R| or longer"


def r_screen_code(ends: tuple[str, str, str, str], r: str, offb: str, rel: str, emit: Any,
                  fail: str = f"raise D({R_WHY!r})") -> list[str]:
    """:func:`r_screen` as lines of source, which the double pass's plans run inline (arc43: no call of seven
    arguments and no tuple an R arc): ``ends`` (``sx, sy, ex, ey``), ``r``, ``offb`` and ``rel`` are the sources
    of its arguments (names: each is read more than once), ``fail`` the statement that declines, and
    ``emit(xlo, xhi, ylo, yhi)`` the lines that keep the box from the sources of its four bounds.  The
    temporaries' names start with ``r_``.

    Every operation is :func:`r_screen`'s, on the same operands in the same order, so the box and the decline
    are its own, bit for bit (its docstring holds for both), but for these, which give the same doubles: the
    code branches on ``R > 0`` first (there ``|R|`` is ``R``), an ``int`` operand is the ``float`` of the same
    value (``17 * e`` and ``17.0 * e`` round the same real number) and a division by 2 or 4 a product by 0.5
    or 0.25 (both the correctly rounded value of the same real number, a power of two's scaling): the
    interpreter's float fast paths take them (``tests/gcode/test_double_pass_arc43.py`` holds the two bit for
    bit on random arcs, near half circles and tiny chords included, and shows a dropped term caught)."""
    sx, sy, ex, ey = ends
    u = repr(_U)

    def screen(ar: str) -> list[str]:  # the decline test and err, with |R| written ar
        return [
            "r_l1 = r_ax + r_ay",
            f"r_m = 2.0 * (({sx} if {sx} >= 0.0 else -{sx}) + ({sy} if {sy} >= 0.0 else -{sy}) + {ar}) + r_l1 + {offb}",
            f"r_ed = (9.0 * r_m + {2.0**-7!r} + r_l1) * {u}",
            "r_dd = r_dx * r_dx + r_dy * r_dy",
            f"r_rr = {r} * {r}",
            "r_x = r_rr - r_dd * 0.25",
            f"if not (r_dd > 17.0 * r_ed * r_ed and r_x > {_HALF!r} * r_rr and (r_ed * (r_l1 + r_ed) < {_QUICK_X!r} "
            f"* r_rr or r_x > 8.0 * (r_rr * {rel} + (r_l1 * r_ed + r_ed * r_ed + r_dd * {u}) * 0.5 + (r_rr + r_dd) "
            f"* {u}))): {fail}",
            f"r_err = (64.0 * r_m + 0.0625) * {u}"]

    chord = [f"r_dx = {ex} - {sx}; r_dy = {ey} - {sy}",
             "r_ax = r_dx if r_dx >= 0.0 else -r_dx; r_ay = r_dy if r_dy >= 0.0 else -r_dy"]
    within = [*screen(r), f"r_w = r_l1 * 0.5 + r_err; r_mx = ({sx} + {ex}) * 0.5; r_my = ({sy} + {ey}) * 0.5",
              *emit("r_mx - r_w", "r_mx + r_w", "r_my - r_w", "r_my + r_w")]
    wide = [f"r_ar = {r} if {r} >= 0.0 else -{r}", *screen("r_ar"), "r_w = 2.0 * r_ar + r_err",
            f"if {sx} > {ex}: r_xl = {sx} - r_w; r_xh = {ex} + r_w",
            f"else: r_xl = {ex} - r_w; r_xh = {sx} + r_w",
            f"if {sy} > {ey}: r_yl = {sy} - r_w; r_yh = {ey} + r_w",
            f"else: r_yl = {ey} - r_w; r_yh = {sy} + r_w",
            *emit("r_xl", "r_xh", "r_yl", "r_yh")]
    return [*chord, f"if {r} > 0.0:", *(f"    {b}" for b in within), "else:", *(f"    {b}" for b in wide)]


#: Arc kinds :func:`refined` reads (``DoublePath.arc_more``'s flags): the box is already :func:`r_arc`'s or
#: :func:`ij_arc`'s, an R arc's screen, an I/J arc's; plus these bits: clockwise, a whole turn, in G20
#: (:func:`inch_offb`, :func:`inch_rule`).
EXACT, R_SCREEN, IJ_SCREEN, CW, TURN, INCH = 0, 1, 2, 4, 8, 16


def refined(flag: int, sx: float, sy: float, ex: float, ey: float, p: float, q: float, offb: float,
            tol: float) -> Any:
    """The box of :func:`r_arc` (``flag & 3 == R_SCREEN``, radius ``p``) or :func:`ij_arc` (``I = p``,
    ``J = q``) for an arc whose screen was kept, or its ``str`` (``flag & INCH``: an I/J arc in G20, whose words
    ``p``, ``q`` are millimetres, :func:`inch_offb`)."""
    cw = bool(flag & CW)
    if flag & 3 == R_SCREEN:
        return r_arc(sx, sy, ex, ey, p, cw, offb, R_INCH_REL if flag & INCH else 2.0**-51)
    if flag & INCH:
        offb, tol = inch_offb(offb, p, q), inch_rule(tol)
    return ij_arc(sx, sy, ex, ey, p, q, cw, offb, tol, bool(flag & TURN))


#: Quadrants by the signs of a vector's components (``2 (x < 0) + (y < 0)``): 0 is x > 0, y > 0, then
#: counter-clockwise; direction d (0 +X, 1 +Y, 2 -X, 3 -Y) is where quadrant d - 1 meets quadrant d.
_QUADRANT = (0, 3, 1, 2)
#: ``_CROSSED[q][n]``: the directions (+X, +Y, -X, -Y) a counter-clockwise sweep from quadrant q crosses on
#: its way through n quadrant boundaries (n = 4: all of them).
_CROSSED = tuple(tuple(tuple(any((q + t) % 4 == d for t in range(1, n + 1)) for d in range(4)) for n in range(5))
                 for q in range(4))
_SWEEPS: tuple[tuple[bool, bool, bool, bool, bool], ...] | None = None
_next_after = math.nextafter  # (a global: one lookup less a call than math.nextafter)


def _box(sx: float, sy: float, ex: float, ey: float, cx: float, cy: float, ux: float, uy: float, wx: float,
         wy: float, rmax: float, widen: float, err: float, cw: bool) -> tuple[float, float, float, float]:
    """The box of the arc: its ends, ``C +- rmax`` in the directions its sweep may contain, widened by
    ``widen`` and rounded outwards (``err`` bounds the error of ``u = S - C`` and ``w = E - C`` per
    component).

    The directions are the union over every quadrant the exact ``u`` and ``w`` may lie in (:data:`_SWEEPS`;
    no ``abs`` calls and no angles, comp42).  Sound: a component more than ``err`` from 0 has the exact one's
    sign; one within ``err`` may have either, so the exact vector lies in one of the closed quadrants taken,
    and the union holds the directions of the exact pair's (a counter-clockwise sweep crosses the boundaries
    from the start's quadrant to the end's).  A pair in one quadrant holds none when the end is clearly
    ahead of the start (their cross product, whose error is at most ``err (|ux| + |uy| + |wx| + |wy|) + 2
    err**2`` plus its own rounding, clearly positive: the sweep is then less than a quarter turn inside the
    closed quadrant, a direction on its edge only at an end, a row the box holds widened) and all four
    otherwise (behind it, or too close to tell: a whole turn is then taken, sound).  A vector with both
    components within ``err`` (an arc of radius about 0) takes all four.  Where no component is within
    ``err`` of 0 these are the quadrants of the doubles."""
    if cw:  # clockwise from u to w is counter-clockwise from w to u
        ux, uy, wx, wy = wx, wy, ux, uy
    k = (((0 if ux > err else 1 if ux < -err else 2) * 3 + (0 if uy > err else 1 if uy < -err else 2)) * 3
         + (0 if wx > err else 1 if wx < -err else 2)) * 3 + (0 if wy > err else 1 if wy < -err else 2)
    px, py, nx, ny, same = (_SWEEPS or _sweeps())[k]
    if same:  # a pair in one quadrant: none more when w is clearly ahead of u, else all
        a, b = ux * wy, uy * wx
        tol = err * ((ux if ux >= 0.0 else -ux) + (uy if uy >= 0.0 else -uy) + (wx if wx >= 0.0 else -wx)
                     + (wy if wy >= 0.0 else -wy)) * 1.01 + 2 * err * err \
            + ((a if a >= 0.0 else -a) + (b if b >= 0.0 else -b)) * 2.0**-51
        if not a - b > tol:
            px = py = nx = ny = True
    xlo, xhi = (sx, ex) if sx < ex else (ex, sx)
    ylo, yhi = (sy, ey) if sy < ey else (ey, sy)
    if px and cx + rmax > xhi:
        xhi = cx + rmax
    if nx and cx - rmax < xlo:
        xlo = cx - rmax
    if py and cy + rmax > yhi:
        yhi = cy + rmax
    if ny and cy - rmax < ylo:
        ylo = cy - rmax
    return (_next_after(xlo - widen, _DOWN), _next_after(xhi + widen, _UP), _next_after(ylo - widen, _DOWN),
            _next_after(yhi + widen, _UP))


def _sweeps() -> tuple[tuple[bool, bool, bool, bool, bool], ...]:
    """:data:`_SWEEPS`: per sign code of ``(ux, uy, wx, wy)`` (0 above ``err``, 1 below ``-err``, 2 within it;
    ``((ux * 3 + uy) * 3 + wx) * 3 + wy``) the directions (+X, +Y, -X, -Y) a counter-clockwise sweep from a
    quadrant ``u`` may lie in to one ``w`` may lie in crosses, and whether a pair in one quadrant is among them
    (built at the first arc box: not at start-up)."""
    global _SWEEPS
    signs = ((False,), (True,), (False, True))  # the possible ``< 0`` of a component
    out = []
    for code in range(81):
        c = (code // 27, code // 9 % 3, code // 3 % 3, code % 3)
        if (c[0] == 2 and c[1] == 2) or (c[2] == 2 and c[3] == 2):
            out.append((True, True, True, True, False))
            continue
        us = {_QUADRANT[2 * x + y] for x in signs[c[0]] for y in signs[c[1]]}
        ws = {_QUADRANT[2 * x + y] for x in signs[c[2]] for y in signs[c[3]]}
        dirs, same = [False] * 4, False
        for q in us:
            for r in ws:
                n = (r - q) % 4
                if n == 0:
                    same = True
                dirs = [d or e for d, e in zip(dirs, _CROSSED[q][n])]
        out.append((*dirs, same))  # type: ignore[arg-type]
    _SWEEPS = tuple(out)
    return _SWEEPS


#: :func:`_box` under a public name: the box of an annulus sector about a centre the caller has (the corner arcs
#: and compensated arcs of cutter compensation, :mod:`.double_comp`'s ``corner_box``)
sector_box = _box
