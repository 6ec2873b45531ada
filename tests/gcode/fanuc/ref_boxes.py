"""The exact box of the reference reader's motion (tests/oracles/fanuc_ref.py), for the box route's differential
(tests/gcode/fanuc/test_reference_boxes.py).

Independent of nczones: no import from ``nczones``.  A straight move (line, rapid, and a dwell, which does not
move) lies in the box of its two ends.  An arc lies in the box of its ends and of those of its circle's four axis
extremes (the centre plus or minus the radius along each plane axis) that lie on it, and of the ends of a helix's
third axis.  Numbers are exact: an R arc's centre is ``M + s sqrt(Q) (-d_b, d_a)`` (``M`` the chord's midpoint,
``d`` the chord, ``Q = r**2 / |d|**2 - 1/4``, ``s`` +1 when the centre is left of the chord: counter-clockwise
with ``r > 0`` or clockwise with ``r < 0``), an I/J arc's radius is ``sqrt(|S - C|**2)``; so every coordinate is
a :class:`Surd` ``a + b sqrt(q)`` with rational ``a``, ``b``, ``q``, and every comparison is decided exactly (no
root is taken).

Which extremes lie on the arc is decided by angles, not by the chord's side (the way ``columns.r_arc_box``
decides it): the arc runs counter-clockwise from ``A`` to ``B`` (``A, B = S, E``; swapped for G02) about ``C``;
when it turns at most half a turn (``r > 0``, or an I/J arc with ``cross(A - C, B - C) >= 0``) the direction
``u`` is on it exactly when ``cross(A - C, u) >= 0`` and ``cross(u, B - C) >= 0``; when it turns more, exactly
when ``u`` is not strictly inside the complementary arc from ``B`` to ``A`` (``cross(B - C, u) > 0`` and
``cross(u, A - C) > 0``); an I/J arc whose end is its start is the whole circle (Fanuc).
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

F = Fraction
_ZERO = F(0)


def _sign(x: Fraction) -> int:
    return (x > 0) - (x < 0)


@dataclass(frozen=True, slots=True)
class Surd:
    """``a + b * sqrt(q)`` (``q >= 0``), exact."""

    a: Fraction
    b: Fraction = _ZERO
    q: Fraction = _ZERO

    def sign(self) -> int:
        """-1, 0 or 1, exactly."""
        if self.b == 0 or self.q == 0:
            return _sign(self.a)
        sa, sb = _sign(self.a), _sign(self.b)
        if sa == sb or sa == 0:
            return sb
        d = self.a * self.a - self.b * self.b * self.q
        return sa if d > 0 else (sb if d < 0 else 0)

    def __sub__(self, other: Surd | Fraction) -> Surd:
        if isinstance(other, Surd):
            assert other.b == 0 or self.b == 0 or other.q == self.q
            return Surd(self.a - other.a, self.b - other.b, self.q if self.b else other.q)
        return Surd(self.a - other, self.b, self.q)

    def __add__(self, other: Fraction) -> Surd:
        return Surd(self.a + other, self.b, self.q)

    def times(self, k: Fraction) -> Surd:
        return Surd(self.a * k, self.b * k, self.q)

    def __float__(self) -> float:
        return float(self.a) + float(self.b) * float(self.q) ** 0.5


def _cross(v: tuple, u: tuple[int, int]) -> Surd:
    """``cross(v, u)`` for a surd vector ``v`` and an axis direction ``u``."""
    return v[0].times(F(u[1])) - v[1].times(F(u[0]))


def _cross_left(u: tuple[int, int], v: tuple) -> Surd:
    """``cross(u, v)``."""
    return v[1].times(F(u[0])) - v[0].times(F(u[1]))


_DIRECTIONS = ((1, 0), (-1, 0), (0, 1), (0, -1))


def _on_arc(u: tuple[int, int], a: tuple, b: tuple, small: bool, whole: bool) -> bool:
    if whole:
        return True
    if small:
        return _cross(a, u).sign() >= 0 and _cross_left(u, b).sign() >= 0
    return not (_cross(b, u).sign() > 0 and _cross_left(u, a).sign() > 0)


def _r_centre(s: tuple, e: tuple, r: Fraction, cw: bool) -> tuple[tuple[Surd, Surd], Surd] | None:
    """The centre of an R arc and its radius (None: equal ends or too short an R, which no generated arc has)."""
    da, db = e[0] - s[0], e[1] - s[1]
    l2 = da * da + db * db
    if l2 == 0:
        return None
    q = r * r / l2 - F(1, 4)
    if q < 0:
        return None
    side = 1 if (not cw) == (r > 0) else -1  # left of the chord
    ma, mb = (s[0] + e[0]) / 2, (s[1] + e[1]) / 2
    return (Surd(ma, -side * db, q), Surd(mb, side * da, q)), Surd(abs(r))


def arc_points(s: tuple, e: tuple, circle: tuple) -> list[tuple[Surd, Surd]] | None:
    """The extremes of the arc from ``s`` to ``e`` (plane coordinates) on its circle ``circle`` (``Reader.circle``:
    ``(ia, ib, cw, centre, r)``) that lie on it, as surd points; None for an arc not boxed here (no circle,
    an I/J end off the start's circle)."""
    _ia, _ib, cw, centre, r = circle
    if centre is None:
        got = _r_centre(s, e, r, cw)
        if got is None:
            return None
        c, rho = got
        small, whole = r > 0, False
    else:
        ca, cb = centre
        r0 = (s[0] - ca) ** 2 + (s[1] - cb) ** 2
        if r0 == 0 or r0 != (e[0] - ca) ** 2 + (e[1] - cb) ** 2:
            return None
        c, rho = (Surd(ca), Surd(cb)), Surd(_ZERO, F(1), r0)
        whole = s == e
        a0, b0 = (s, e) if not cw else (e, s)
        turn = (a0[0] - ca) * (b0[1] - cb) - (a0[1] - cb) * (b0[0] - ca)
        small = turn >= 0
    first, second = (s, e) if not cw else (e, s)
    va = (Surd(first[0]) - c[0], Surd(first[1]) - c[1])
    vb = (Surd(second[0]) - c[0], Surd(second[1]) - c[1])
    out = []
    for u in _DIRECTIONS:
        if _on_arc(u, va, vb, small, whole):
            pa = c[0] + _ZERO if u[0] == 0 else _plus(c[0], rho, u[0])
            pb = c[1] + _ZERO if u[1] == 0 else _plus(c[1], rho, u[1])
            out.append((pa, pb))
    return out


def _plus(c: Surd, rho: Surd, k: int) -> Surd:
    """``c + k * rho`` (one of them rational, or both in one root)."""
    if rho.b == 0:
        return c + k * rho.a
    assert c.b == 0
    return Surd(c.a, k * rho.b, rho.q)


class RefBox:
    """The exact box of a motion: per axis the rational bounds and the surd candidates beyond them."""

    def __init__(self, start: tuple) -> None:
        self.lo = list(start)
        self.hi = list(start)
        self.surds: list[list[Surd]] = [[] for _ in start]

    def point(self, p: tuple) -> None:
        for i, v in enumerate(p):
            if v < self.lo[i]:
                self.lo[i] = v
            elif v > self.hi[i]:
                self.hi[i] = v

    def value(self, i: int, v: Surd) -> None:
        if v.b == 0 or v.q == 0:
            self.point_axis(i, v.a)
        else:
            self.surds[i].append(v)

    def point_axis(self, i: int, v: Fraction) -> None:
        if v < self.lo[i]:
            self.lo[i] = v
        if v > self.hi[i]:
            self.hi[i] = v

    def contained_in(self, lo: list, hi: list) -> list[str]:
        """What of this box lies outside ``lo``..``hi`` (rationals), as messages; empty when it is inside."""
        bad = []
        for i in range(len(lo)):
            if self.lo[i] < lo[i] or self.hi[i] > hi[i]:
                bad.append(f"axis {i}: exact {self.lo[i]}..{self.hi[i]} outside {lo[i]}..{hi[i]}")
            for v in self.surds[i]:
                if (v - lo[i]).sign() < 0 or (v - hi[i]).sign() > 0:
                    bad.append(f"axis {i}: arc extreme {float(v)!r} ({v}) outside {lo[i]}..{hi[i]}")
        return bad

    def float_bounds(self) -> tuple[list[float], list[float]]:
        """The bounds as floats (for messages and the closeness check)."""
        lo = [min([float(self.lo[i])] + [float(v) for v in self.surds[i]]) for i in range(len(self.lo))]
        hi = [max([float(self.hi[i])] + [float(v) for v in self.surds[i]]) for i in range(len(self.hi))]
        return lo, hi


def reference_box(motions: list, circles: dict, start: tuple) -> RefBox | None:
    """The exact box of the reference's ``motions`` (``[(kind, end), ...]`` from ``start``, machine coordinates)
    with the circles of its arcs by index; None when an arc has no circle this module boxes."""
    box = RefBox(tuple(start))
    here = tuple(start)
    for k, (kind, end) in enumerate(motions):
        end = tuple(end)
        box.point(end)
        if kind == "arc":
            circle = circles.get(k)
            if circle is None:
                return None
            ia, ib = circle[0], circle[1]
            pts = arc_points((here[ia], here[ib]), (end[ia], end[ib]), circle)
            if pts is None:
                return None
            for pa, pb in pts:
                box.value(ia, pa)
                box.value(ib, pb)
        here = end
    return box
