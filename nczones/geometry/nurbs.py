"""Exact rational NURBS curves: evaluation, knot insertion, local convex hulls.

A NURBS curve of degree ``p`` has control points ``P_0..P_n`` (tuples of
Fractions, any dimension), positive weights ``w_i`` and a non-decreasing
knot vector ``u_0..u_{n+p+1}``; nczones only builds *clamped* curves (the
first and last ``p+1`` knots equal), so the curve starts at ``P_0`` and ends
at ``P_n`` and its domain is ``[u_p, u_{n+1}]``.

Facts the prover and the controller rely on (all exact, no floats):

* **Local convex hull.**  With positive weights, the piece of the curve over
  the knot span ``[u_i, u_{i+1})`` is a convex combination of
  ``P_{i-p}..P_i`` (the rational basis functions there are non-negative and
  sum to one), so it lies in their convex hull.
* **de Boor.**  The point at a rational parameter is an exact rational point
  (:meth:`Nurbs.point`), computed in homogeneous coordinates.
* **Boehm knot insertion** (:meth:`Nurbs.insert`) leaves the curve unchanged
  (the same point at every parameter) and refines the control polygon:
  repeated insertion makes the local hulls converge to the curve.

>>> F = Fraction
>>> c = Nurbs(2, (F(0), F(0), F(0), F(1), F(1), F(1)), ((F(0), F(0)), (F(1), F(2)), (F(2), F(0))), (F(1),) * 3)
>>> c.point(F(1, 2))
(Fraction(1, 1), Fraction(1, 1))
>>> c.insert(F(1, 2)).point(F(1, 4)) == c.point(F(1, 4))
True
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..motion import Segment

__all__ = ["Nurbs", "clamped_uniform_knots", "NurbsError", "spline_curve"]


class NurbsError(ValueError):
    """A control polygon/knot vector that does not define a clamped NURBS curve."""


def clamped_uniform_knots(npoints: int, order: int) -> tuple[Fraction, ...]:
    """LinuxCNC's G5.2 knot vector (``knot_vector_creator``): ``order`` zeros,
    ``1 .. npoints-order``, ``order`` times ``npoints-order+1``.

    >>> [int(k) for k in clamped_uniform_knots(5, 3)]
    [0, 0, 0, 1, 2, 3, 3, 3]
    """
    n = npoints - 1
    out = []
    for i in range(n + order + 1):
        if i < order:
            out.append(Fraction(0))
        elif i <= n:
            out.append(Fraction(i - order + 1))
        else:
            out.append(Fraction(n - order + 2))
    return tuple(out)


@dataclass(frozen=True, slots=True)
class Nurbs:
    """A clamped rational B-spline curve with exact data.

    Invariants (checked): ``len(knots) == len(points) + degree + 1``, knots
    non-decreasing, first and last ``degree + 1`` knots equal, weights > 0,
    all points of one dimension.
    """

    degree: int
    knots: tuple[Fraction, ...]
    points: tuple[tuple[Fraction, ...], ...]
    weights: tuple[Fraction, ...]

    def __post_init__(self):
        p, k, P, w = self.degree, self.knots, self.points, self.weights
        if p < 1:
            raise NurbsError(f"degree {p} must be at least 1")
        if len(P) < p + 1:
            raise NurbsError(f"{len(P)} control points are fewer than order {p + 1}")
        if len(w) != len(P):
            raise NurbsError("one weight per control point is needed")
        if len(k) != len(P) + p + 1:
            raise NurbsError(f"{len(k)} knots given; {len(P)} control points of order {p + 1} need {len(P) + p + 1}")
        if any(b < a for a, b in zip(k, k[1:])):
            raise NurbsError("knots must be non-decreasing")
        if len(set(k[: p + 1])) != 1 or len(set(k[-p - 1:])) != 1 or k[0] == k[-1]:
            raise NurbsError(f"the knot vector must be clamped: the first and last {p + 1} knots equal, and "
                             "the two ends different")
        inner = k[p + 1: len(P)]
        if any(inner.count(u) > p for u in set(inner)):
            raise NurbsError(f"an interior knot repeated more than the degree {p} times (the curve would jump)")
        if any(x <= 0 for x in w):
            raise NurbsError("weights must be positive")
        if len({len(pt) for pt in P}) != 1:
            raise NurbsError("control points of different dimensions")

    @property
    def domain(self) -> tuple[Fraction, Fraction]:
        return self.knots[self.degree], self.knots[len(self.points)]

    def span(self, t: Fraction) -> int:
        """Index ``i`` with ``u_i <= t < u_{i+1}`` (the last non-empty span for t at the end)."""
        lo, hi = self.domain
        if not lo <= t <= hi:
            raise NurbsError(f"parameter {t} outside the domain [{lo}, {hi}]")
        n = len(self.points) - 1
        if t == hi:
            i = n
            while self.knots[i] == self.knots[i + 1]:
                i -= 1
            return i
        i = self.degree
        while not (self.knots[i] <= t < self.knots[i + 1]):
            i += 1
        return i

    def point(self, t: Fraction) -> tuple[Fraction, ...]:
        """The exact curve point at parameter ``t`` (de Boor in homogeneous coordinates)."""
        p, U = self.degree, self.knots
        i = self.span(Fraction(t))
        d = [tuple(c * w for c in pt) + (w,) for pt, w in zip(self.points[i - p: i + 1], self.weights[i - p: i + 1])]
        for r in range(1, p + 1):
            for j in range(p, r - 1, -1):
                a, b = U[j + i - p], U[j + 1 + i - r]
                alpha = (t - a) / (b - a)
                d[j] = tuple((1 - alpha) * x + alpha * y for x, y in zip(d[j - 1], d[j]))
        h = d[p]
        return tuple(x / h[-1] for x in h[:-1])

    def insert(self, t: Fraction) -> "Nurbs":
        """Boehm insertion of knot ``t`` (strictly inside the domain): the same curve, one more control point."""
        t = Fraction(t)
        lo, hi = self.domain
        if not lo < t < hi:
            raise NurbsError(f"knot {t} is not strictly inside the domain")
        p, U = self.degree, self.knots
        k = self.span(t)
        H = [tuple(c * w for c in pt) + (w,) for pt, w in zip(self.points, self.weights)]
        new = []
        for i in range(len(H) + 1):
            if i <= k - p:
                new.append(H[i])
            elif i > k:
                new.append(H[i - 1])
            else:
                a = (t - U[i]) / (U[i + p] - U[i])
                new.append(tuple((1 - a) * x + a * y for x, y in zip(H[i - 1], H[i])))
        knots = U[: k + 1] + (t,) + U[k + 1:]
        pts = tuple(tuple(x / h[-1] for x in h[:-1]) for h in new)
        make = Nurbs if self.clamped else Nurbs._unchecked
        return make(p, knots, pts, tuple(h[-1] for h in new))

    def split(self, t: Fraction) -> tuple["Nurbs", "Nurbs"]:
        """The two clamped curves over ``[lo, t]`` and ``[t, hi]`` (``t`` strictly inside the domain).

        ``t`` is inserted up to multiplicity ``p``; then the control point
        ``P_{j-1}`` (``j`` = first index of ``t``) is the curve point at ``t``
        and is shared by both halves.

        >>> F = Fraction
        >>> c = Nurbs(2, (F(0),) * 3 + (F(1),) * 3, ((F(0), F(0)), (F(1), F(2)), (F(2), F(0))), (F(1), F(2), F(1)))
        >>> a, b = c.split(F(1, 3))
        >>> a.points[-1] == b.points[0] == c.point(F(1, 3)), b.point(F(1, 2)) == c.point(F(1, 2))
        (True, True)
        """
        t = Fraction(t)
        c = self
        p = c.degree
        while sum(1 for u in c.knots if u == t) < p:
            c = c.insert(t)
        if sum(1 for u in c.knots if u == t) > p:
            raise NurbsError(f"knot {t} has multiplicity above the degree")
        j = c.knots.index(t)
        make = Nurbs if self.clamped else Nurbs._unchecked
        left = make(p, c.knots[:j] + (t,) * (p + 1), c.points[:j], c.weights[:j])
        right = make(p, (t,) * (p + 1) + c.knots[j + p:], c.points[j - 1:], c.weights[j - 1:])
        return left, right

    @property
    def clamped(self) -> bool:
        """False only for a single-span curve made by :meth:`span_curve`."""
        p = self.degree
        return len(set(self.knots[: p + 1])) == 1 and len(set(self.knots[-p - 1:])) == 1

    @classmethod
    def _unchecked(cls, degree: int, knots: tuple[Fraction, ...], points: tuple[tuple[Fraction, ...], ...],
                   weights: tuple[Fraction, ...]) -> "Nurbs":
        obj = object.__new__(cls)
        for name, value in (("degree", degree), ("knots", tuple(knots)), ("points", tuple(points)),
                            ("weights", tuple(weights))):
            object.__setattr__(obj, name, value)
        return obj

    def span_curve(self, i: int) -> "Nurbs":
        """The piece over the knot span ``[u_i, u_{i+1}]`` as a curve of its own, without knot insertion.

        Its control points are ``P_{i-p}..P_i`` (the local convex hull) and
        its knots ``u_{i-p}..u_{i+p+1}``; it is not clamped (its domain is the
        span), but evaluation, insertion and :meth:`split` work on it and
        give the same points as the whole curve.

        >>> F = Fraction
        >>> c = Nurbs(2, (F(0),) * 3 + (F(1), F(2)) + (F(3),) * 3,
        ...           tuple((F(x), F(x * x % 5)) for x in range(5)), (F(1), F(2), F(1), F(3), F(1)))
        >>> piece = c.span_curve(3)
        >>> piece.domain, piece.point(F(3, 2)) == c.point(F(3, 2))
        ((Fraction(1, 1), Fraction(2, 1)), True)
        >>> a, b = piece.split(F(7, 4))
        >>> a.point(F(13, 8)) == c.point(F(13, 8)), b.domain
        (True, (Fraction(7, 4), Fraction(2, 1)))
        """
        p = self.degree
        if not (p <= i < len(self.points) and self.knots[i] < self.knots[i + 1]):
            raise NurbsError(f"{i} is not the index of a non-empty knot span")
        return Nurbs._unchecked(p, self.knots[i - p: i + p + 2], self.points[i - p: i + 1],
                                self.weights[i - p: i + 1])

    def span_hulls(self) -> list[tuple[tuple[Fraction, Fraction], tuple[tuple[Fraction, ...], ...]]]:
        """Per non-empty knot span: ((u_i, u_{i+1}), control points P_{i-p}..P_i whose hull holds that piece)."""
        p, U = self.degree, self.knots
        out = []
        for i in range(p, len(self.points)):
            if U[i] < U[i + 1]:
                out.append(((U[i], U[i + 1]), self.points[i - p: i + 1]))
        return out

    def pieces(self) -> list["Nurbs"]:
        """The curve cut at its interior knots: one clamped single-span curve per non-empty span."""
        out = []
        rest = self
        for u in sorted({k for k in self.knots if self.domain[0] < k < self.domain[1]}):
            left, rest = rest.split(u)
            out.append(left)
        out.append(rest)
        return out

    def refine(self, times: int = 1) -> "Nurbs":
        """Insert the midpoint of every non-empty span, ``times`` times (hulls tighten around the curve)."""
        c = self
        for _ in range(times):
            mids = [(a + b) / 2 for (a, b), _ in c.span_hulls()]
            for m in mids:
                c = c.insert(m)
        return c


def spline_curve(seg: "Segment") -> Nurbs:
    """The exact NURBS of a SPLINE segment (control points in machine coordinates).

    The interpreter stores the curve in the segment's ``extra``: ``degree``,
    ``knots``, ``control`` points and ``weights``.
    """
    from ..motion import SplineCurve

    e = seg.payload(SplineCurve)
    if e is None:
        raise ValueError("not a spline: the segment carries no SplineCurve")
    return Nurbs(e.degree, e.knots, e.control, e.weights)
