"""Exact path geometry for the prover: pieces, rapids, arcs, enclosures.

A :class:`~nczones.motion.Segment` becomes one or more *pieces*:

* :class:`LinePiece` — a straight piece ``p(t) = p0 + t (p1 - p0)``, ``t`` in
  ``[0, 1]``, covering the segment parameter ``tau0 .. tau1`` (lines and
  linear rapids are one piece with ``tau`` = ``t``; a dogleg rapid is a
  polyline whose breakpoints are the exact rational times at which the
  axes reach their targets, every axis starting together at its own rapid
  rate, ``tau`` being the fraction of the rapid's duration).
* :class:`ArcGeom` — a G2/G3 motion, described exactly: the plane axes, the
  start and end points in the plane, the direction, the centre (rational, or
  ``None`` for an R-format arc whose centre is irrational, then ``r_signed``),
  whether the sweep is a full circle, and the other axes' start/end values
  (a helix when they differ).

Invariants: every coordinate is a ``Fraction``; nothing here rounds.
Irrational quantities are only ever *enclosed* (``sqrt_bounds``,
``atan_bounds``, ``pi_bounds``: the exact core's :mod:`nczones.exact`
enclosures as ``(lo, hi)`` pairs) in rational intervals that contain them.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from math import isqrt, lcm

from ..errors import InvalidArgument
from ..exact import atan_interval, is_square, pi_interval, sqrt_interval
from ..exact import round_down as exact_round_down
from ..exact import round_up as exact_round_up
from ..machine import Machine, RapidMode
from ..motion import PLANE_AXES, Segment, SegmentKind
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

# not typing's (start-up): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    #: a vector of the sweep tests: Fractions, or integers (the points times a common denominator, _common_scale)
    _SweepVec = tuple[Fraction | int, Fraction | int]

__all__ = [
    "LinePiece",
    "ArcGeom",
    "line_pieces",
    "dogleg_breakpoints",
    "arc_geom",
    "sqrt_bounds",
    "is_square",
    "atan_bounds",
    "pi_bounds",
    "rational_point_on_arc",
    "in_sweep",
    "round_down",
    "round_up",
    "simple_in",
    "arc_bases",
    "half_tan",
    "angle_bounds",
    "on_start_ray",
    "whole_turn_box",
]

F0 = Fraction(0)
F1 = Fraction(1)


@dataclass(frozen=True, slots=True)
class LinePiece:
    """A straight piece of a segment's path.

    ``p(t) = p0 + t (p1 - p0)`` for ``t`` in ``[0, 1]``; the piece covers the
    segment parameter ``tau0 + t (tau1 - tau0)``.
    """

    p0: tuple[Fraction, ...]
    p1: tuple[Fraction, ...]
    tau0: Fraction = F0
    tau1: Fraction = F1

    def at(self, t: Fraction) -> tuple[Fraction, ...]:
        return tuple(a + t * (b - a) for a, b in zip(self.p0, self.p1))

    def tau(self, t: Fraction) -> Fraction:
        return self.tau0 + t * (self.tau1 - self.tau0)


def dogleg_breakpoints(start: Sequence[Fraction], end: Sequence[Fraction],
                       rates: Sequence[Fraction]) -> tuple[Fraction, ...]:
    """Segment parameters (fractions of the rapid's duration) where an axis stops.

    Every axis starts together and moves at its own rapid rate; axis ``i``
    needs ``|end_i - start_i| / rate_i``.  Returns the sorted distinct
    interior breakpoints in ``(0, 1)``.

    >>> F = Fraction
    >>> dogleg_breakpoints((F(0), F(0)), (F(100), F(10)), (F(1000), F(1000)))
    (Fraction(1, 10),)
    """
    times = [abs(e - s) / r for s, e, r in zip(start, end, rates)]
    total = max(times, default=F0)
    if total == 0:
        return ()
    return tuple(sorted({t / total for t in times if 0 < t < total}))


def line_pieces(seg: Segment, machine: Machine | None) -> tuple[LinePiece, ...]:
    """The straight pieces of a LINE or RAPID segment (DWELL: one point).

    >>> from nczones.motion import Segment, SegmentKind
    >>> F = Fraction
    >>> s = Segment(SegmentKind.LINE, (F(0), F(0)), (F(1), F(2)), ("X", "Y"))
    >>> line_pieces(s, None)[0].at(F(1, 2))
    (Fraction(1, 2), Fraction(1, 1))
    """
    if seg.kind in (SegmentKind.LINE, SegmentKind.DWELL):
        return (LinePiece(seg.start, seg.end),)
    if seg.kind is not SegmentKind.RAPID:
        raise InvalidArgument(f"not a straight motion: {seg.kind.name}")
    if machine is None or machine.rapid_mode is RapidMode.LINEAR:
        return (LinePiece(seg.start, seg.end),)
    rates = tuple(machine.axis(a).rapid_mm_min for a in seg.axes)
    times = [abs(e - s) / r for s, e, r in zip(seg.start, seg.end, rates)]
    total = max(times, default=F0)
    if total == 0:
        return (LinePiece(seg.start, seg.end),)
    cuts = (F0,) + dogleg_breakpoints(seg.start, seg.end, rates) + (F1,)

    def at(tau: Fraction) -> tuple[Fraction, ...]:
        out = []
        for s, e, t_axis in zip(seg.start, seg.end, times):
            if t_axis == 0:
                out.append(s)
            else:
                frac = min(F1, tau * total / t_axis)
                out.append(s + frac * (e - s))
        return tuple(out)

    return tuple(LinePiece(at(a), at(b), a, b) for a, b in zip(cuts, cuts[1:]))


# --------------------------------------------------------------------------- enclosures


#: Resolution (bits after the binary point) of outward-rounded enclosures: far below any pulse, and it keeps
#: the numbers refinement multiplies together from growing without bound.
ENCLOSURE_BITS = 128


def round_down(x: Fraction, bits: int = ENCLOSURE_BITS) -> Fraction:
    """:func:`nczones.exact.round_down` at :data:`ENCLOSURE_BITS` unless told.

    >>> round_down(Fraction(1, 3), 4), round_down(Fraction(-1, 3), 4), round_down(Fraction(3, 8), 4)
    (Fraction(5, 16), Fraction(-3, 8), Fraction(3, 8))
    """
    return exact_round_down(x, bits)


def round_up(x: Fraction, bits: int = ENCLOSURE_BITS) -> Fraction:
    """:func:`nczones.exact.round_up` at :data:`ENCLOSURE_BITS` unless told.

    >>> round_up(Fraction(1, 3), 4), round_up(Fraction(-1, 3), 4)
    (Fraction(3, 8), Fraction(-5, 16))
    """
    return exact_round_up(x, bits)


def sqrt_bounds(q: Fraction, bits: int = 96) -> tuple[Fraction, Fraction]:
    """Rational ``lo <= sqrt(q) <= hi`` with ``hi - lo <= 2**-bits`` (exact if square):
    :func:`nczones.exact.sqrt_interval` as a pair.

    >>> lo, hi = sqrt_bounds(Fraction(2), 20)
    >>> lo * lo <= 2 <= hi * hi, float(hi - lo) <= 2**-20
    (True, True)
    """
    return sqrt_interval(q, bits).bounds()


def pi_bounds() -> tuple[Fraction, Fraction]:
    """π enclosed: :func:`nczones.exact.pi_interval` as a pair.

    >>> lo, hi = pi_bounds()
    >>> Fraction(3141592653589793238, 10**18) < lo < hi < Fraction(3141592653589793239, 10**18)
    True
    """
    return pi_interval().bounds()


def atan_bounds(x: Fraction, bits: int = ENCLOSURE_BITS) -> tuple[Fraction, Fraction]:
    """Rational enclosure of ``atan(x)``: :func:`nczones.exact.atan_interval` as a pair.

    >>> lo, hi = atan_bounds(Fraction(1))
    >>> lo <= pi_bounds()[1] / 4 and pi_bounds()[0] / 4 <= hi
    True
    """
    return atan_interval(x, bits).bounds()


# --------------------------------------------------------------------------- arcs


def _cross(u: _SweepVec, v: _SweepVec) -> Fraction | int:
    return u[0] * v[1] - u[1] * v[0]


def _dot(u: _SweepVec, v: _SweepVec) -> Fraction | int:
    return u[0] * v[0] + u[1] * v[1]


def in_sweep(u: _SweepVec, w: _SweepVec, v: _SweepVec, ccw: bool, full: bool) -> bool:
    """Does direction ``v`` lie in the sweep from ``u`` to ``w`` (closed)?

    Directions are vectors from the centre; ``u`` and ``w`` need not have the
    same length.

    >>> F = Fraction
    >>> in_sweep((F(1), F(0)), (F(0), F(1)), (F(1), F(1)), True, False)
    True
    >>> in_sweep((F(1), F(0)), (F(0), F(1)), (F(1), F(1)), False, False)
    False
    """
    if full:
        return True
    if not ccw:  # clockwise from u to w = counter-clockwise from w to u
        u, w = w, u
    return _angle_le(u, v, w)


#: The four axis directions of a plane: (direction, axis, sign).
_DIRECTIONS = (((F1, F0), 0, 1), ((-F1, F0), 0, -1), ((F0, F1), 1, 1), ((F0, -F1), 1, -1))


def _sweep_may_hold(s: _SweepVec, e: _SweepVec, ends: Sequence[_SweepVec], v: _SweepVec, ccw: bool) -> bool:
    """May direction ``v`` lie in the sweep of the arc from ``s`` to ``e`` (not a whole turn) about a centre
    somewhere on the segment between the two points ``ends``?  False only when it cannot.

    :func:`in_sweep` reads only the signs of ``cross(u, v)``, ``cross(u, w)`` and ``cross(v, w)`` (``u = s - c``,
    ``w = e - c``; a dot product only where a cross product is 0), and each is affine in the centre ``c``
    (``cross(s - c, e - c) = cross(s, e) - cross(s, c) - cross(c, e)``).  When all three have the same strict
    signs at both ends of the segment, they have them at every point of it, so ``in_sweep`` answers the same for
    every centre there, the exact one included; otherwise the answer is "may" (the sound side).

    >>> F = Fraction
    >>> s, e = (F(2), F(1)), (F(-1), F(2))  # from 26.6 to 116.6 degrees about a centre near the origin
    >>> near = [(F(-1, 1000), F(-1, 1000)), (F(1, 1000), F(1, 1000))]
    >>> [_sweep_may_hold(s, e, near, v, True) for v, _a, _s in _DIRECTIONS]  # +X, -X, +Y, -Y
    [False, False, True, False]
    >>> [_sweep_may_hold(s, e, near, v, False) for v, _a, _s in _DIRECTIONS]  # clockwise: the other way round
    [True, True, False, True]
    """
    if ends[0] == ends[-1]:  # a rational centre after all: the exact test
        c = ends[0]
        return in_sweep((s[0] - c[0], s[1] - c[1]), (e[0] - c[0], e[1] - c[1]), v, ccw, False)
    seen = set()
    for c in ends:
        u = (s[0] - c[0], s[1] - c[1])
        w = (e[0] - c[0], e[1] - c[1])
        signs = (_cross(u, v), _cross(u, w), _cross(v, w))
        if F0 in signs:
            return True
        seen.add((tuple(x > 0 for x in signs), in_sweep(u, w, v, ccw, False)))
    return len(seen) != 1 or next(iter(seen))[1]


def _axis_sweeps_may_hold(s: _SweepVec, e: _SweepVec, ends: Sequence[_SweepVec], ccw: bool) -> list[bool]:
    """``_sweep_may_hold(s, e, ends, v, ccw)`` for each direction ``v`` of :data:`_INT_DIRECTIONS`, in order.

    The same tests, with each end's ``u = s - c``, ``w = e - c`` and ``cross(u, w)`` computed once for the four
    directions (they do not depend on the direction): a zero sign at either end answers "may", otherwise the
    answer is "may" unless both ends give the same signs and :func:`in_sweep` says no there."""
    if ends[0] == ends[-1]:
        return [_sweep_may_hold(s, e, ends, v, ccw) for v, _a, _s in _INT_DIRECTIONS]
    vecs = []
    for c in ends:
        u, w = (s[0] - c[0], s[1] - c[1]), (e[0] - c[0], e[1] - c[1])
        vecs.append((u, w, _cross(u, w)))
    out = []
    for v, _a, _s in _INT_DIRECTIONS:
        seen: set = set()
        zero = False
        for u, w, uw in vecs:
            uv, vw = _cross(u, v), _cross(v, w)
            if uv == 0 or uw == 0 or vw == 0:
                zero = True
                break
            seen.add((uv > 0, uw > 0, vw > 0, in_sweep(u, w, v, ccw, False)))
        out.append(zero or len(seen) != 1 or next(iter(seen))[3])
    return out


#: :data:`_DIRECTIONS` in integers (for :func:`_common_scale`'s points).
_INT_DIRECTIONS = (((1, 0), 0, 1), ((-1, 0), 0, -1), ((0, 1), 1, 1), ((0, -1), 1, -1))


def _common_scale(points: Sequence[tuple[Fraction, Fraction]]) -> list[tuple[int, int]]:
    """``points`` times the least common denominator of their coordinates: integers.

    For the sweep tests of :func:`_sweep_may_hold` (and :func:`in_sweep`, :func:`_angle_le`, :func:`_half`), which
    read only the signs of cross and dot products of differences of these points and of axis directions: scaling
    every point by the same ``D > 0`` scales each difference by ``D``, a product of one difference and a direction
    by ``D`` and a product of two differences by ``D**2``, so every sign, and every answer, is the same, without
    Fraction arithmetic (an R-format arc's centre bounds have denominators of 64-bit square-root bounds).

    >>> _common_scale([(Fraction(1, 2), Fraction(1, 3)), (Fraction(-1), Fraction(0))])
    [(3, 2), (-6, 0)]
    """
    d = lcm(*(x.denominator for p in points for x in p))
    return [(x.numerator * (d // x.denominator), y.numerator * (d // y.denominator)) for x, y in points]


def _half(u: _SweepVec, v: _SweepVec) -> int:
    """0 when the ccw angle from u to v is in [0, pi), else 1."""
    c = _cross(u, v)
    return 0 if c > 0 or (c == 0 and _dot(u, v) > 0) else 1


def _angle_le(u: _SweepVec, v: _SweepVec, w: _SweepVec) -> bool:
    """ccw angle(u -> v) <= ccw angle(u -> w), angles in [0, 2 pi)."""
    hv, hw = _half(u, v), _half(u, w)
    if hv != hw:
        return hv < hw
    return _cross(v, w) >= 0


@dataclass(frozen=True, slots=True)
class ArcGeom:
    """An arc's exact geometry in its plane (first, second axis indices ``ia``, ``ib``).

    ``centre`` is rational or None (R-format with an irrational centre; then
    ``r_signed`` is the programmed R and the centre is on the side fixed by
    DESIGN/motion.py).  ``full`` is a whole turn (``start == end`` in the plane
    or ``turns > 0``, or an I/J arc whose end lies on the ray from the centre
    through its start: LinuxCNC's whole spiral turn, :func:`on_start_ray`; every
    box made of it then holds the whole turn).  ``r2_lo``/``r2_hi`` are the squared radii at start and
    end (ordered); they differ for a slightly inconsistent I/J arc, whose path
    is then enclosed in the annulus sector (a spiral, as LinuxCNC moves it).
    """

    ia: int
    ib: int
    s: tuple[Fraction, Fraction]
    e: tuple[Fraction, Fraction]
    ccw: bool
    full: bool
    centre: tuple[Fraction, Fraction] | None
    r_signed: Fraction | None
    r2_lo: Fraction
    r2_hi: Fraction
    start: tuple[Fraction, ...]
    end: tuple[Fraction, ...]

    @property
    def helix(self) -> bool:
        return any(
            a != b for k, (a, b) in enumerate(zip(self.start, self.end)) if k not in (self.ia, self.ib)
        )

    @property
    def exact(self) -> bool:
        """Is the plane path a circle arc with rational centre (polynomial, exact)?"""
        return self.centre is not None and self.r2_lo == self.r2_hi

    def centre_bounds(self, bits: int = 96) -> tuple[tuple[Fraction, Fraction], tuple[Fraction, Fraction]]:
        """Per plane axis ``(lo, hi)`` enclosing the centre."""
        if self.centre is not None:
            return ((self.centre[0], self.centre[0]), (self.centre[1], self.centre[1]))
        parts = self.r_format_parts()
        return _r_centre_bounds(parts, sqrt_bounds(parts[4], bits))

    def r_format_parts(self):
        """R-format centre = M + k n with k = sign * sqrt(q): returns (Mx, My, nx, ny, q, sign).

        ``M = (s + e) / 2``, ``n = (-(ey - sy), ex - sx)`` and ``q = R**2 / |n|**2 - 1/4``, each built from
        :meth:`_r_scaled`'s integers (the same values as the Fraction formulas)."""
        d, (s0, s1, e0, e1), (nx, ny), q, sign = self._r_scaled()
        return Fraction(s0 + e0, 2 * d), Fraction(s1 + e1, 2 * d), Fraction(nx, d), Fraction(ny, d), q, sign

    def _r_scaled(self) -> tuple[int, tuple[int, int, int, int], tuple[int, int], Fraction, int]:
        """An R-format arc's parts on integers: the common denominator ``d`` of the start and end, the start and
        end times ``d`` (``s0, s1, e0, e1``), ``n`` times ``d`` (``(s1 - e1, e0 - s0)``), ``q`` (a Fraction:
        ``R**2 / (|N|**2 / d**2) - 1/4 = (4 R**2 d**2 - |N|**2) / (4 |N|**2)``) and the side's sign."""
        (sx, sy), (ex, ey), r = self.s, self.e, self.r_signed
        assert r is not None  # an R-format arc (no rational centre) has its signed R
        d = lcm(sx.denominator, sy.denominator, ex.denominator, ey.denominator)
        s0, s1, e0, e1 = (v.numerator * (d // v.denominator) for v in (sx, sy, ex, ey))
        nx, ny = s1 - e1, e0 - s0
        nn = nx * nx + ny * ny
        rn, rd = r.numerator, r.denominator
        q = Fraction(4 * rn * rn * d * d - rd * rd * nn, 4 * rd * rd * nn)
        sign = -1 if (not self.ccw) != (r < 0) else 1
        return d, (s0, s1, e0, e1), (nx, ny), q, sign

    def plane_bbox(self, bits: int = 64, sweep: bool = False) -> tuple[tuple[Fraction, Fraction], tuple[Fraction, Fraction]]:
        """A rational box containing the arc's plane path (exact extremes when rational).

        An R-format arc whose centre is irrational: its whole circle's box, or with ``sweep`` only the circle's
        extremes its sweep may reach (:func:`_sweep_may_hold`; the Fanuc hull and box route use it).  The
        per-motion solver query keeps the whole circle (a tighter enclosure changes which queries are hard:
        tests/prover/test_limits.py's stand-in for "a query that cannot finish" needs it)."""
        if self.centre is None and sweep:
            return self._r_sweep_box(bits)
        if self.centre is None:  # centre_bounds: the centre's two bounding points
            mx, my, nx, ny, q, sign = self.r_format_parts()
            ends = [(mx + sign * k * nx, my + sign * k * ny) for k in sqrt_bounds(q, bits)]
            (cxl, cxh), (cyl, cyh) = (tuple(sorted(p[axis] for p in ends)) for axis in (0, 1))
        else:
            (cxl, cxh), (cyl, cyh) = self.centre_bounds(bits)
        if self.centre is None:
            assert self.r_signed is not None
            r_hi = sqrt_bounds(self.r_signed * self.r_signed, bits)[1]
        else:
            r_hi = sqrt_bounds(self.r2_hi, bits)[1]
        xs = [self.s[0], self.e[0]]
        ys = [self.s[1], self.e[1]]
        if self.centre is None:
            # direction tests need the centre: use the whole circle's box (sound)
            xs += [cxl - r_hi, cxh + r_hi]
            ys += [cyl - r_hi, cyh + r_hi]
        else:
            c = self.centre
            si, ei, ci = _common_scale((self.s, self.e, c))  # the same signs in integers (_common_scale)
            u = (si[0] - ci[0], si[1] - ci[1])
            w = (ei[0] - ci[0], ei[1] - ci[1])
            for v, axis, sgn in _INT_DIRECTIONS:
                if in_sweep(u, w, v, self.ccw, self.full):
                    (xs if axis == 0 else ys).append(c[axis] + sgn * r_hi)
            if self.r2_lo != self.r2_hi:
                # a spiral: every path point is within (r_hi - r_lo) of the circular arc of the
                # start radius, whose box is within (r_hi - r_lo) of this one
                g = 2 * (r_hi - sqrt_bounds(self.r2_lo, bits)[0])
                return ((min(xs) - g, max(xs) + g), (min(ys) - g, max(ys) + g))
        return ((min(xs), max(xs)), (min(ys), max(ys)))


    def _r_sweep_box(self, bits: int) -> tuple[tuple[Fraction, Fraction], tuple[Fraction, Fraction]]:
        """:meth:`plane_bbox` with ``sweep`` of an R-format arc whose centre is irrational.

        The exact centre lies on the segment between two rational points, ``M + sign k n`` for ``k`` the two
        :func:`sqrt_bounds` of ``q`` (:meth:`r_format_parts`): a direction's extreme (that end of the segment
        plus ``r_hi``, the bound of ``|R|``) is left out only where :func:`_sweep_may_hold` settles the sweep.
        Computed on integers: the start and end times their common denominator ``d`` (``S``, ``E``), ``n`` times
        ``d`` (``N``), ``q = (4 R**2 d**2 - |N|**2) / (4 |N|**2)`` (the same value as :meth:`r_format_parts`'s,
        so the same bounds), and every point times ``2 d K`` (``K`` the bounds' common denominator): the centre
        points ``(S + E) K + 2 sign k_j K N``.  One positive scale for every point keeps every sign of the sweep
        tests (:func:`_common_scale`), and each bound is the same value as the Fraction formula's."""
        d, (s0, s1, e0, e1), (nx, ny), q, sign = self._r_scaled()
        r = self.r_signed
        assert r is not None  # an R-format arc (no rational centre) has its signed R
        k_lo, k_hi = sqrt_bounds(q, bits)
        big_k = lcm(k_lo.denominator, k_hi.denominator)
        ks = (sign * k_lo.numerator * (big_k // k_lo.denominator), sign * k_hi.numerator * (big_k // k_hi.denominator))
        mx, my = (s0 + e0) * big_k, (s1 + e1) * big_k
        ends = [(mx + 2 * k * nx, my + 2 * k * ny) for k in ks]
        scale = 2 * d * big_k
        s, e = (2 * big_k * s0, 2 * big_k * s1), (2 * big_k * e0, 2 * big_k * e1)
        r_hi = sqrt_bounds(r * r, bits)[1]
        xs, ys = [self.s[0], self.e[0]], [self.s[1], self.e[1]]
        for (_v, axis, sgn), may in zip(_INT_DIRECTIONS, _axis_sweeps_may_hold(s, e, ends, self.ccw)):
            if may:
                pick = max if sgn > 0 else min
                (xs if axis == 0 else ys).append(Fraction(pick(p[axis] for p in ends), scale) + sgn * r_hi)
        return (min(xs), max(xs)), (min(ys), max(ys))


def _r_centre_bounds(parts: tuple, k_bounds: tuple[Fraction, Fraction]
                     ) -> tuple[tuple[Fraction, Fraction], tuple[Fraction, Fraction]]:
    """:meth:`ArcGeom.centre_bounds` of an R-format arc from its :meth:`~ArcGeom.r_format_parts` and the bounds
    of ``sqrt(q)``: the centre ``M + sign k n`` for ``k`` between them."""
    mx, my, nx, ny, _q, sign = parts
    ks = (sign * k_bounds[0], sign * k_bounds[1])
    xs = sorted((mx + k * nx for k in ks))
    ys = sorted((my + k * ny for k in ks))
    return ((xs[0], xs[1]), (ys[0], ys[1]))


def arc_geom(seg: Segment) -> ArcGeom:
    """The exact geometry of an ARC segment.

    >>> from nczones.motion import Plane
    >>> F = Fraction
    >>> s = Segment(SegmentKind.ARC, (F(1), F(0)), (F(0), F(1)), ("X", "Y"), plane=Plane.XY,
    ...             centre=(F(0), F(0)))
    >>> g = arc_geom(s); g.exact, g.full, g.plane_bbox()
    (True, False, ((Fraction(0, 1), Fraction(1, 1)), (Fraction(0, 1), Fraction(1, 1))))
    """
    ia, ib, _ = seg.plane_indices()
    s = (seg.start[ia], seg.start[ib])
    e = (seg.end[ia], seg.end[ib])
    full = s == e or seg.turns > 0 or on_start_ray(seg)
    centre = seg.centre
    r_signed = None
    if centre is None:
        if seg.radius is None:
            raise InvalidArgument("arc without centre or radius")
        r_signed = seg.radius
        if s == e:
            raise InvalidArgument("R-format arc with equal start and end")
        g = ArcGeom(ia, ib, s, e, not seg.clockwise, False, None, r_signed, r_signed**2, r_signed**2,
                    seg.start, seg.end)
        mx, my, nx, ny, q, sign = g.r_format_parts()
        if q < 0:
            raise InvalidArgument(f"R-format arc: radius {abs(r_signed)} is shorter than half the chord")
        k = is_square(q)
        if k is not None:
            centre = (mx + sign * k * nx, my + sign * k * ny)
            r_signed = None
    if centre is not None:
        u2 = (s[0] - centre[0]) ** 2 + (s[1] - centre[1]) ** 2
        w2 = (e[0] - centre[0]) ** 2 + (e[1] - centre[1]) ** 2
    else:
        assert seg.radius is not None  # without a centre the arc is given by R
        u2 = w2 = seg.radius**2
    if u2 == 0:
        raise InvalidArgument("arc with zero radius")
    return ArcGeom(ia, ib, s, e, not seg.clockwise, full, centre, r_signed, min(u2, w2), max(u2, w2),
                   seg.start, seg.end)


def on_start_ray(seg: Segment) -> bool:
    """Does an arc with a rational centre end on the ray from the centre through its start (another point of it)?

    LinuxCNC (posemath ``pmCircleInit``) then moves a whole turn, a spiral when the radii differ (within the arc
    tolerance), where the exact sweep from start to end holds nothing: :func:`whole_turn_box` encloses that path.
    An arc with laps (``turns``) or without a centre (R format) is not such an arc.

    >>> from nczones.motion import Plane
    >>> F = Fraction
    >>> arc = Segment(SegmentKind.ARC, (F(1), F(0)), (F(2), F(0)), ("X", "Y"), plane=Plane.XY, centre=(F(0), F(0)))
    >>> on_start_ray(arc), on_start_ray(Segment(SegmentKind.ARC, (F(1), F(0)), (F(-2), F(0)), ("X", "Y"),
    ...                                         plane=Plane.XY, centre=(F(0), F(0))))
    (True, False)
    """
    last = _RAY_LAST
    if last[0] is seg:
        kept: bool = last[1]
        return kept
    answer = _on_start_ray(seg)
    _RAY_LAST[:] = [seg, answer]
    return answer


#: :func:`on_start_ray`'s last segment and answer (the prover asks twice an arc: ``decide_point_path``, then
#: ``check_concrete``); a Segment is frozen, and the entry keeps it alive, so ``is`` names the same arc
_RAY_LAST: list = [None, False]


def _on_start_ray(seg: Segment) -> bool:
    """:func:`on_start_ray`, computed: the vectors from the centre times the common denominator ``d`` of the
    start, end and centre (integers, :func:`_scaled_arc`): ``d u`` and ``d w`` are equal, collinear or of a
    positive dot product exactly when ``u`` and ``w`` are (``d > 0``)."""
    if seg.centre is None or seg.turns:
        return False
    scaled = _scaled_arc(seg)
    if scaled is None:  # not Fractions: the formula
        c = seg.centre
        ia, ib, _ = seg.plane_indices()
        u = (seg.start[ia] - c[0], seg.start[ib] - c[1])
        w = (seg.end[ia] - c[0], seg.end[ib] - c[1])
    else:
        u, w = scaled[1], scaled[2]
    return u != w and _cross(u, w) == 0 and _dot(u, w) > 0


def _scaled_arc(seg: Segment) -> tuple | None:
    """``(d, u, w, (s0, s1, e0, e1, c0, c1), ia, ib)`` of an arc with a rational centre: ``d`` the least common
    denominator of its start, end and centre in its plane, those six coordinates times ``d`` (integers) and
    the vectors ``u``, ``w`` from the centre to start and end, times ``d``; None when a coordinate is not a
    Fraction (an int)."""
    key = id(seg)
    hit = _SCALED.get(key)
    if hit is not None and hit[0] is seg:
        kept: tuple | None = hit[1]
        return kept
    scaled = _scale_arc(seg)
    _keep(_SCALED, key, (seg, scaled))
    return scaled


def _keep(cache: dict[int, tuple], key: int, entry: tuple) -> None:
    """``cache[key] = entry``, the oldest entry out first when :data:`_KEPT` are kept (another thread's change
    between the look-up and the removal only skips the removal)."""
    if len(cache) >= _KEPT:
        try:
            cache.pop(next(iter(cache)), None)
        except (RuntimeError, StopIteration):
            pass
    cache[key] = entry


#: how many answers :func:`_scaled_arc` and :func:`rational_arc_plane_box` keep
_KEPT = 4096


#: :func:`_scaled_arc`'s answers by ``id(seg)`` with the segment (the whole-turn test and the box of the same arc,
#: in the per-motion proof and the corner check), kept as :data:`_PLANE_BOXES` keeps boxes (each entry holds its segment)
_SCALED: dict[int, tuple] = {}


def _scale_arc(seg: Segment) -> tuple | None:
    """:func:`_scaled_arc`, computed."""
    centre = seg.centre
    assert centre is not None  # the callers ask arcs with a centre
    ia, ib, _ = seg.plane_indices()
    vals: tuple = (seg.start[ia], seg.start[ib], seg.end[ia], seg.end[ib], centre[0], centre[1])
    try:
        dens = [v._denominator for v in vals]
        nums = [v._numerator for v in vals]
    except AttributeError:  # not Fractions
        return None
    d = lcm(*dens)
    pts = s0, s1, e0, e1, c0, c1 = tuple(n * (d // q) for n, q in zip(nums, dens))
    return d, (s0 - c0, s1 - c1), (e0 - c0, e1 - c1), pts, ia, ib




def whole_turn_box(seg: Segment, bits: int = 64) -> tuple[tuple[Fraction, ...], tuple[Fraction, ...]]:
    """Corners ``(lo, hi)`` (by axis index) of a box holding the whole spiral turn of an arc :func:`on_start_ray`.

    In the plane: the centre +- an upper bound of the larger radius; on every other axis: its range from start to
    end.  Sound for every way a control may move such an arc: LinuxCNC's spiral turn keeps its radius between the
    start's and the end's (it moves linearly with the angle), a Grbl control moves on the start circle and then
    straight to the end (a chord of the disc of the larger radius, which the box holds), a sweep of nothing would
    be the straight move between two points of that disc; the other axes move linearly in every case.

    >>> from nczones.motion import Plane
    >>> F = Fraction
    >>> arc = Segment(SegmentKind.ARC, (F(1), F(0), F(0)), (F(2), F(0), F(5)), ("X", "Y", "Z"), plane=Plane.XY,
    ...               centre=(F(0), F(0)))
    >>> whole_turn_box(arc)
    ((Fraction(-2, 1), Fraction(-2, 1), Fraction(0, 1)), (Fraction(2, 1), Fraction(2, 1), Fraction(5, 1)))
    """
    c = seg.centre
    assert c is not None  # an arc on its start's ray has a rational centre
    ia, ib, _ = seg.plane_indices()
    r2 = max((seg.start[ia] - c[0]) ** 2 + (seg.start[ib] - c[1]) ** 2,
             (seg.end[ia] - c[0]) ** 2 + (seg.end[ib] - c[1]) ** 2)
    r = sqrt_bounds(r2, bits)[1]
    lo, hi = list(map(min, seg.start, seg.end)), list(map(max, seg.start, seg.end))
    lo[ia], hi[ia], lo[ib], hi[ib] = c[0] - r, c[0] + r, c[1] - r, c[1] + r
    return tuple(lo), tuple(hi)


def rational_point_on_arc(g: ArcGeom, m: Fraction, base: tuple[Fraction, Fraction] | None = None) -> tuple[Fraction, Fraction]:
    """The exact rational point of a circle reached by rotating ``base`` (default the
    start vector) by ``2 atan(m)`` in the arc's direction (rational parametrisation).

    >>> F = Fraction
    >>> from nczones.motion import Plane
    >>> s = Segment(SegmentKind.ARC, (F(1), F(0)), (F(0), F(1)), ("X", "Y"), plane=Plane.XY,
    ...             centre=(F(0), F(0)))
    >>> rational_point_on_arc(arc_geom(s), F(1))
    (Fraction(0, 1), Fraction(1, 1))
    """
    c = g.centre
    assert c is not None  # rational points exist on circles with a rational centre
    u = base if base is not None else (g.s[0] - c[0], g.s[1] - c[1])
    perp = (-u[1], u[0]) if g.ccw else (u[1], -u[0])
    den = 1 + m * m
    a = (1 - m * m) / den
    b = 2 * m / den
    return (c[0] + a * u[0] + b * perp[0], c[1] + a * u[1] + b * perp[1])


def arc_axis_names(seg: Segment) -> tuple[str, str, str]:
    assert seg.plane is not None  # an arc has its plane
    return PLANE_AXES[seg.plane]


def simple_in(lo: Fraction, hi: Fraction) -> Fraction:
    """A short decimal in [lo, hi] (the midpoint if none has at most 60 places)."""
    mid = (lo + hi) / 2
    for k in range(61):
        x = Fraction(round(mid * 10**k), 10**k)
        if lo <= x <= hi:
            return x
    return mid


def arc_bases(u: tuple[Fraction, Fraction], ccw: bool) -> list[tuple[Fraction, Fraction]]:
    """u rotated by 0, 90, 180, 270 degrees in the arc's direction (exact)."""
    out = [u]
    for _ in range(3):
        a = out[-1]
        out.append((-a[1], a[0]) if ccw else (a[1], -a[0]))
    return out


def half_tan(base: tuple[Fraction, Fraction], target: tuple[Fraction, Fraction], ccw: bool) -> Fraction | None:
    """Rational approximation of tan(angle(base -> target)/2) in the arc's direction."""
    cr = base[0] * target[1] - base[1] * target[0]
    if not ccw:
        cr = -cr
    dt = base[0] * target[0] + base[1] * target[1]
    n = sqrt_bounds((base[0] ** 2 + base[1] ** 2) * (target[0] ** 2 + target[1] ** 2), 120)[0]
    den = n + dt
    if den <= 0:
        return None
    half: Fraction = (cr / den).limit_denominator(10**40)
    return half


_Vec = tuple[Fraction, Fraction]


def split_arc_piece(g: ArcGeom, a: _Vec, b: _Vec) -> tuple[tuple[_Vec, _Vec], tuple[_Vec, _Vec]] | None:
    """The piece of ``g`` from vector ``a`` to ``b`` (from the centre) halved at a rational point of the circle
    near its middle: ``((a, mid), (mid, b))``; None when the piece cannot be split (no usable half angle)."""
    m = half_tan(a, b, g.ccw)
    if m is None or m <= 0 or g.centre is None:
        return None
    mid = rational_point_on_arc(g, m / 2, base=a)
    mid_v: tuple[Fraction, Fraction] = (mid[0] - g.centre[0], mid[1] - g.centre[1])
    return (a, mid_v), (mid_v, b)


def angle_bounds(u: tuple[Fraction, Fraction], v: tuple[Fraction, Fraction], ccw: bool) -> tuple[Fraction, Fraction]:
    """Rational enclosure of the angle from u to v in the given direction, in [0, 2 pi)."""
    pi_lo, pi_hi = pi_bounds()
    for k, base in enumerate(arc_bases(u, ccw)):
        cr = base[0] * v[1] - base[1] * v[0]
        if not ccw:
            cr = -cr
        dt = base[0] * v[0] + base[1] * v[1]
        if cr >= 0 and dt > 0 or (cr > 0 and dt == 0):
            n_lo, n_hi = sqrt_bounds((base[0] ** 2 + base[1] ** 2) * (v[0] ** 2 + v[1] ** 2), 120)
            m_lo, m_hi = cr / (n_hi + dt), cr / (n_lo + dt)
            a_lo, a_hi = atan_bounds(m_lo)[0], atan_bounds(m_hi)[1]
            return k * pi_lo / 2 + 2 * a_lo, k * pi_hi / 2 + 2 * a_hi
    return F0, 2 * pi_hi


def rational_arc_plane_box(seg: Segment, bits: int = 64) -> tuple | None:
    """``arc_geom(seg).plane_bbox(bits)`` of an arc with a rational centre, with its plane's axis indices:
    ``((lo, hi), (lo, hi), ia, ib)``; None for other arcs (R format, no plane, a zero radius: ``arc_geom``
    decides them, raising where it refuses the arc).

    The same box (an equal value, bound for bound) without Fraction arithmetic: the start, end and centre times
    their common denominator ``d`` are integers (:func:`_common_scale`'s argument: the vectors ``u``, ``w`` from
    the centre are ``d`` times the rational ones, so every sign of a cross or dot product, hence every answer of
    :func:`in_sweep` and of the whole-turn test of :func:`on_start_ray`, is the same), and the squared radii are
    ``|u|**2 / d**2``: the same values, so :func:`sqrt_bounds` gives the same bounds.  A spiral (start and end at
    different distances) is grown by ``2 (r_hi - r_lo)`` as in :meth:`ArcGeom.plane_bbox`.  Every bound is
    computed as an integer over one denominator (of the points and the two root bounds): a positive scale keeps
    the order, so the least and greatest are the scaled ones, and each bound is one Fraction of the same value."""
    if seg.centre is None or seg.plane is None:
        return None
    key = id(seg)
    hit = _PLANE_BOXES.get(key)
    if hit is not None and hit[0] is seg and hit[1] == bits:
        kept: tuple | None = hit[2]
        return kept
    box = _rational_arc_plane_box(seg, bits)
    _keep(_PLANE_BOXES, key, (seg, bits, box))
    return box


#: :func:`rational_arc_plane_box`'s answers by ``id(seg)``, with the segment and ``bits`` (the corner check and
#: the per-motion proof box the same arc, a batch of motions apart).  A Segment is frozen and each entry keeps
#: its own alive, so no other object has its id while the entry is kept; the oldest entry goes first.
_PLANE_BOXES: dict[int, tuple] = {}


def _scaled_root(n2: int, d: int, bits: int, upper: bool) -> tuple[int, int]:
    """``sqrt_bounds(Fraction(n2, d * d), bits)[upper]`` as ``(numerator, denominator)``, not reduced: the same
    value without the Fractions.

    :func:`~nczones.exact.sqrt_interval` gives the root itself when ``n2 / d**2`` is the square of a rational,
    which it is exactly when the integer ``n2`` is a square (a rational whose square is the integer ``n2`` is an
    integer): then ``isqrt(n2) / d``.  Else its bounds are ``n / 2**bits`` and ``(n + 1) / 2**bits`` with ``n``
    the integer root of ``floor(q 4**bits)``, which depends on the value ``q`` only.

    >>> _scaled_root(9, 2, 64, True), _scaled_root(2, 1, 4, False), _scaled_root(2, 1, 4, True)
    ((3, 2), (22, 16), (23, 16))
    """
    k = isqrt(n2)
    if k * k == n2:
        return k, d
    scale = 1 << bits
    n = isqrt(n2 * scale * scale // (d * d))
    return (n + 1 if upper else n), scale


def _rational_arc_plane_box(seg: Segment, bits: int) -> tuple | None:
    """:func:`rational_arc_plane_box`, computed (an arc with a centre and a plane)."""
    scaled = _scaled_arc(seg)
    if scaled is None:
        return None
    d, u, w, (s0, s1, e0, e1, c0, c1), ia, ib = scaled
    u2, w2 = u[0] * u[0] + u[1] * u[1], w[0] * w[0] + w[1] * w[1]
    if u2 == 0:
        return None  # arc_geom refuses it
    # arc_geom's whole turn: start == end, laps, or the end on the ray through the start (on_start_ray)
    full = seg.turns > 0 or (_cross(u, w) == 0 and _dot(u, w) > 0)
    hi_n, hi_d = _scaled_root(max(u2, w2), d, bits, True)
    lo_n, lo_d = _scaled_root(min(u2, w2), d, bits, False) if u2 != w2 else (hi_n, hi_d)
    # every bound on one denominator: the points', r_hi's and r_lo's (integers; one Fraction a bound at the end)
    big = lcm(d, hi_d, lo_d)
    m = big // d
    hi = hi_n * (big // hi_d)
    xs, ys = [s0 * m, e0 * m], [s1 * m, e1 * m]
    ccw = not seg.clockwise
    for v, axis, sgn in _INT_DIRECTIONS:
        if in_sweep(u, w, v, ccw, full):
            (xs if axis == 0 else ys).append((c1 if axis else c0) * m + sgn * hi)
    # a spiral: every path point is within (r_hi - r_lo) of the circular arc of the start radius, whose box is
    # within (r_hi - r_lo) of this one (ArcGeom.plane_bbox); 0 for a circle
    g = 2 * (hi - lo_n * (big // lo_d)) if u2 != w2 else 0
    return ((Fraction(min(xs) - g, big), Fraction(max(xs) + g, big)),
            (Fraction(min(ys) - g, big), Fraction(max(ys) + g, big)), ia, ib)
