"""Arcs decided by exact enclosures of pieces of their sweep, without the solver.

Every arc kind the prover meets — I/J arcs (rational centre), R-format arcs
(irrational centre), spirals (I/J arcs whose end radius differs within the
tolerance), helices and multi-turn helices — is cut into pieces of at most a
quarter turn.  Each piece is enclosed in a rational box; a box that fits
every zone with the margin (:func:`nczones.prover.exact.box_fits`, exact for
boxes and stepped tables) proves the piece.  A piece that does not fit is
halved, and at each new division point the path point's enclosure (a box of
width about ``2**-90``, or the exact rational point of a circle) is tested:
when every point of it violates a zone
(:func:`nczones.prover.exact.box_certainly_violates`), that is a certified
counterexample.  Pieces and depth are bounded (:data:`MAX_PIECES`,
:data:`MAX_DEPTH`); what they leave open goes to the solver.  The work per
arc is bounded (every enclosure is rounded outwards to a fixed grid, so the
numbers stay short), so this tier, like the other exact ones, still runs
once the run's budget is spent.

Positions along the sweep
-------------------------
A division point is a *position* ``g = j + m``: quarter ``j`` (laps
included) and ``m`` in ``[0, 1)``, the direction from the centre being the
``j``-th quarter base (the start direction turned by ``j`` right angles in
the arc's direction) turned further by ``2·atan(m)``: a rational rotation,
so for a circle with rational centre the point ``centre + direction`` lies
exactly on the circle.  Positions are monotone in the swept angle
``θ = j·π/2 + 2·atan(m)``.

Soundness (why a fitting box proves the piece, why a certified point is real)
------------------------------------------------------------------------------
* The centre lies in a rational box ``C`` (one point when rational; for an
  R-format arc the enclosure of ``M + k·n``, ``k = ±√q``); interval
  arithmetic over ``C`` encloses every quantity that depends on it.
* A piece spans less than a half turn, so the path over it is enclosed by
  the corner points at its two end directions (at the smallest and largest
  radius the piece can have) together with ``c ± ρ_max`` along every axis
  direction that may lie strictly inside the piece's sector (decided by
  signs of cross products evaluated in interval arithmetic: "may" when a
  sign is not certain).
* Axes outside the plane move linearly in the swept angle; a piece's angle
  range is enclosed with :func:`~nczones.prover.geometry.pi_bounds` and
  :func:`~nczones.prover.geometry.atan_bounds` (for an R-format arc widened
  by the angle its start direction can have over ``C``), so their range
  over the piece is enclosed too; a spiral's radius (linear in the angle) in
  the same way.
* A division point is only used as a counterexample when its direction is
  certainly strictly inside the sweep for every centre in ``C``.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..exact import Bounds, atan_interval
from ..motion import Segment
from . import exact as ex
from .geometry import ArcGeom, atan_bounds, half_tan, in_sweep, pi_bounds, simple_in, sqrt_bounds  # noqa: F401
from .result import Outcome, Violation

__all__ = ["ArcEnclosure", "decide_arc", "MAX_PIECES", "MAX_DEPTH"]

F0 = Fraction(0)
F1 = Fraction(1)
#: Pieces examined per arc before the solver takes over.
MAX_PIECES = 96
#: Halvings of one quarter-turn piece before the solver takes over.
MAX_DEPTH = 12
#: Precision (bits) of square roots and of the centre of an R-format arc.
BITS = 96
#: Bisection steps of the first exit (a quarter turn / 2**24).
EXIT_STEPS = 24

Vec = tuple[Fraction, Fraction]
IVec = tuple[Bounds, Bounds]
Box = tuple[dict[str, Fraction], dict[str, Fraction]]
Hit = tuple[Any, dict[str, Fraction], list]  # (zone, point, violated zones)
_GRID = 2**72


def _out(iv: Bounds) -> Bounds:
    """``iv`` rounded outwards to multiples of ``2**-72`` (keeps the numbers short; still encloses)."""
    lo, hi = iv
    return (Fraction(lo.numerator * _GRID // lo.denominator, _GRID),
            Fraction(-((-hi.numerator * _GRID) // hi.denominator), _GRID))


_PI = pi_bounds()
_FIX = 96  # bits of the arctangent's grid


def _atan_iv(m: Fraction) -> Bounds:
    """Enclosure of ``atan(m)`` for ``0 <= m <= 1`` on a ``2**-96`` grid (about ``2**-94`` wide):
    :func:`nczones.exact.atan_interval` as a pair."""
    return atan_interval(m, _FIX).bounds()


def _angle_iv(bases: list[Vec], v: Vec, ccw: bool) -> Bounds:
    """Enclosure of the angle from ``bases[0]`` to ``v`` in the arc's direction, in ``[0, 2π)``
    (``bases``: the start direction turned by 0, 1, 2, 3 right angles in that direction)."""
    for k, base in enumerate(bases):
        cr = base[0] * v[1] - base[1] * v[0]
        if not ccw:
            cr = -cr
        dt = base[0] * v[0] + base[1] * v[1]
        if cr >= 0 and dt > 0 or (cr > 0 and dt == 0):
            # tan of half the angle from base to v: cross / (|base| |v| + dot), in [0, 1)
            n_lo, n_hi = sqrt_bounds((base[0] ** 2 + base[1] ** 2) * (v[0] ** 2 + v[1] ** 2), 80)
            m_lo, m_hi = _out((cr / (n_hi + dt), cr / (n_lo + dt)))
            lo, hi = _atan_iv(max(F0, m_lo))[0], _atan_iv(min(F1, m_hi))[1]
            return k * _PI[0] / 2 + 2 * lo, k * _PI[1] / 2 + 2 * hi
    return F0, 2 * _PI[1]


def _imul(a: Bounds, b: Bounds) -> Bounds:
    p = (a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1])
    return min(p), max(p)


def _iadd(a: Bounds, b: Bounds) -> Bounds:
    return a[0] + b[0], a[1] + b[1]


def _isub(a: Bounds, b: Bounds) -> Bounds:
    return a[0] - b[1], a[1] - b[0]


def _pt(x: Fraction) -> Bounds:
    return x, x


def _cross(a: IVec, b: IVec) -> Bounds:
    """cross(a, b) of two interval vectors."""
    return _isub(_imul(a[0], b[1]), _imul(a[1], b[0]))


def _rot(d: Vec, m: Fraction, ccw: bool) -> Vec:
    """``d`` turned by ``2·atan(m)`` in the arc's direction (exact; keeps the length)."""
    perp = (-d[1], d[0]) if ccw else (d[1], -d[0])
    den = 1 + m * m
    return (((1 - m * m) * d[0] + 2 * m * perp[0]) / den, ((1 - m * m) * d[1] + 2 * m * perp[1]) / den)


class _Mark:
    """A division point of the sweep: the start, the end, or a position ``g = j + m``."""

    __slots__ = ("kind", "g", "d", "box", "theta")

    def __init__(self, kind: str, g: Fraction, d: Vec = (F0, F0)):
        self.kind = kind  # "S", "E" or "d"
        self.g = g  # position (for E: a lower bound of it)
        self.d = d  # rational direction from the centre (d-marks)
        self.box: Box | None = None  # cached point enclosure: (lo, hi) dicts
        self.theta: Bounds | None = None  # cached angle enclosure


class ArcEnclosure:
    """Pieces of one arc's sweep and their exact enclosures (see the module docstring).

    Examples
    --------
    A quarter circle from (10, 0) to (0, 10) around the origin: its box is
    exact, and a box that cuts its bulge is violated at a certified point.

    >>> from nczones.machine import parse_machine
    >>> from nczones.motion import Plane, Segment, SegmentKind
    >>> from nczones.prover.core import Prover
    >>> from nczones.prover.geometry import arc_geom
    >>> F = Fraction
    >>> m = parse_machine('[machine]\\naxes = ["X", "Y"]\\n[machine.rapid]\\nX = "1"\\nY = "1"\\n'
    ...                   '[machine.reference]\\nX = "0"\\nY = "0"\\n[[zones]]\\nname = "t"\\nkind = "box"\\n'
    ...                   'min = { X = "-1", Y = "-1" }\\nmax = { X = "8", Y = "11" }\\n')
    >>> seg = Segment(SegmentKind.ARC, (F(10), F(0)), (F(0), F(10)), ("X", "Y"), plane=Plane.XY,
    ...               centre=(F(0), F(0)))
    >>> out = decide_arc(Prover(m), seg, arc_geom(seg), ())
    >>> out.violation.zone, out.violation.engine
    ('t', 'exact')
    """

    def __init__(self, prover: Any, seg: Segment, g: ArcGeom):
        self.p = prover
        self.seg = seg
        self.g = g
        self.ccw = g.ccw
        self.ia, self.ib = g.ia, g.ib
        self.axes = prover.axes
        s, e = g.s, g.e
        if g.centre is not None:
            c = g.centre
            self.C = (_pt(c[0]), _pt(c[1]))
            cstar = c
        else:
            (cxl, cxh), (cyl, cyh) = g.centre_bounds(BITS)
            self.C = ((cxl, cxh), (cyl, cyh))
            cstar = ((cxl + cxh) / 2, (cyl + cyh) / 2)
        self.rational_centre = g.centre is not None
        self.cstar = cstar
        self.u = (s[0] - cstar[0], s[1] - cstar[1])  # quarter base 0 (the start direction when rational)
        self.bases = [self.u]
        for _ in range(3):
            a = self.bases[-1]
            self.bases.append((-a[1], a[0]) if self.ccw else (a[1], -a[0]))
        self.u2 = self.u[0] ** 2 + self.u[1] ** 2
        self.spiral = g.r2_lo != g.r2_hi
        self.circle_exact = self.rational_centre and not self.spiral
        self.helix = g.helix
        self.moving = [k for k in range(len(g.start)) if k not in (self.ia, self.ib) and g.start[k] != g.end[k]]
        self.nu = sqrt_bounds(self.u2, BITS)  # |d| of every d-mark (rotations keep the length)
        self.rs: Bounds = (F0, F0)
        self.re: Bounds = (F0, F0)
        if g.centre is None:
            r = abs(g.r_signed or F0)
            self.rho_const: Bounds | None = (r, r)
        elif not self.spiral:
            self.rho_const = sqrt_bounds(g.r2_lo, BITS)
        else:
            self.rho_const = None
            self.rs = sqrt_bounds((s[0] - cstar[0]) ** 2 + (s[1] - cstar[1]) ** 2, BITS)
            self.re = sqrt_bounds((e[0] - cstar[0]) ** 2 + (e[1] - cstar[1]) ** 2, BITS)
        # angle uncertainty of the true start/end direction against the rational base (R-format)
        if self.rational_centre:
            self.delta = F0
        else:  # |c - c*| <= eps turns a direction from the centre by less than 2 eps / its length
            eps = (self.C[0][1] - self.C[0][0]) + (self.C[1][1] - self.C[1][0])
            w2 = (e[0] - cstar[0]) ** 2 + (e[1] - cstar[1]) ** 2
            self.delta = 2 * eps / min(self.nu[0], sqrt_bounds(w2, BITS)[0])
        self.full = g.s == g.e  # back to the start point after whole turns (ArcGeom.full also counts laps)
        self.turns = seg.turns
        self.marks = self._initial_marks()
        self._total: Bounds | None = None

    # ------------------------------------------------------------------ marks

    def _dir_interval(self, mk: _Mark) -> IVec:
        """The direction from the centre to the mark, as an interval vector over C."""
        if mk.kind == "d":
            return (_pt(mk.d[0]), _pt(mk.d[1]))
        p = self.g.s if mk.kind == "S" else self.g.e
        return (_isub(_pt(p[0]), self.C[0]), _isub(_pt(p[1]), self.C[1]))

    def _sign(self, iv: Bounds) -> int | None:
        if iv[0] > 0:
            return 1
        if iv[1] < 0:
            return -1
        if iv[0] == iv[1] == 0:
            return 0
        return None

    def _after(self, a: IVec, b: IVec) -> bool | None:
        """Is direction b certainly strictly after a (within a half turn, in the arc's direction)? None: unsure."""
        t = self._turn(a, b)
        return None if t is None else t > 0

    def _initial_marks(self) -> list[_Mark]:
        g = self.g
        S = _Mark("S", F0)
        if self.full:  # a whole turn (plus laps) back to the start point (rational centre)
            quarters = 4 * (self.turns + 1)
            marks = [S] + [self._dmark(Fraction(j)) for j in range(1, quarters)]
            marks.append(_Mark("E", Fraction(quarters)))
            return marks
        w = (g.e[0] - self.cstar[0], g.e[1] - self.cstar[1])
        from .refine import quarter_of

        k, exact_end = quarter_of(self.u, w, self.ccw)
        last = 4 * self.turns + k  # quarter boundaries 1..last lie before (or at) the end
        marks = [S] + [self._dmark(Fraction(j)) for j in range(1, last + 1)]
        if exact_end and self.rational_centre:
            if last > 0:
                marks.pop()  # the end lies exactly on that boundary
            marks.append(_Mark("E", Fraction(last)))
            return marks
        if last > 0 and not self.rational_centre:
            wi = self._dir_interval(_Mark("E", F0))
            if self._after((_pt(marks[-1].d[0]), _pt(marks[-1].d[1])), wi) is not True:
                marks.pop()  # the end may lie on or before that boundary: merge the pieces
        # a position just before the end (its own position is irrational in general): the marks
        # chosen between a mark and the end stay below it
        m = half_tan(self.bases[last % 4], w, self.ccw)
        gE = Fraction(last) + (max(F0, min(F1, m)) * (1 - Fraction(1, 2**30)) if m is not None else F0)
        if gE <= marks[-1].g:
            gE = marks[-1].g
        marks.append(_Mark("E", gE))
        return marks

    def _dmark(self, gpos: Fraction) -> _Mark:
        j = int(gpos)
        m = gpos - j
        base = self.bases[j % 4]
        d = base if m == 0 else _rot(base, m, self.ccw)
        return _Mark("d", gpos, d)

    def _theta(self, mk: _Mark) -> Bounds:
        """Enclosure of the swept angle from the start to the mark."""
        if mk.theta is not None:
            return mk.theta
        theta: Bounds
        if mk.kind == "S":
            theta = (F0, F0)
        elif mk.kind == "E":
            theta = self.total()
        else:
            j = int(mk.g)
            m = mk.g - j
            pi_lo, pi_hi = _PI
            a_lo, a_hi = _atan_iv(m)
            theta = _out((j * pi_lo / 2 + 2 * a_lo - self.delta, j * pi_hi / 2 + 2 * a_hi + self.delta))
        mk.theta = theta
        return theta

    def total(self) -> Bounds:
        """Enclosure of the whole swept angle (laps included)."""
        if self._total is not None:
            return self._total
        pi_lo, pi_hi = _PI
        if self.full:
            total = (2 * pi_lo * (self.turns + 1), 2 * pi_hi * (self.turns + 1))
        else:
            w = (self.g.e[0] - self.cstar[0], self.g.e[1] - self.cstar[1])
            a_lo, a_hi = _angle_iv(self.bases, w, self.ccw)
            total = (a_lo + 2 * pi_lo * self.turns - 2 * self.delta, a_hi + 2 * pi_hi * self.turns + 2 * self.delta)
        self._total = _out(total)
        return self._total

    def _fraction(self, theta: Bounds) -> Bounds:
        """Enclosure of θ/Θ, clipped to [0, 1]."""
        t_lo, t_hi = self.total()
        if t_lo <= 0:
            return F0, F1
        lo = max(F0, theta[0] / t_hi) if theta[0] >= 0 else F0
        hi = min(F1, theta[1] / t_lo) if theta[1] >= 0 else F0
        return _out((lo, max(lo, hi)))

    def _rho(self, f: Bounds) -> Bounds:
        """Radius enclosure at the angle fractions ``f``."""
        if self.rho_const is not None:
            return self.rho_const
        vals = [r0 + (r1 - r0) * x for r0 in self.rs for r1 in self.re for x in f]
        return _out((max(F0, min(vals)), max(vals)))

    def _axis_values(self, f: Bounds) -> dict[int, Bounds]:
        out = {}
        for k in self.moving:
            a, b = self.g.start[k], self.g.end[k]
            v = (a + (b - a) * f[0], a + (b - a) * f[1])
            out[k] = _out((min(v), max(v)))
        return out

    def _unit(self, d: Vec) -> IVec:
        """Enclosure of d/|d| for a rational direction of length |u| (d-marks)."""
        n_lo, n_hi = self.nu
        out = []
        for x in d:
            out.append(_out((x / n_hi, x / n_lo) if x >= 0 else (x / n_lo, x / n_hi)))
        return out[0], out[1]

    def point_box(self, mk: _Mark) -> Box:
        """Enclosure (lo, hi per axis) of the path point at the mark."""
        if mk.box is not None:
            return mk.box
        g = self.g
        if mk.kind in ("S", "E"):
            p = g.start if mk.kind == "S" else g.end
            ends = dict(zip(self.axes, p))
            mk.box = (ends, ends)
            return mk.box
        lo: dict[str, Fraction] = {}
        hi: dict[str, Fraction] = {}
        plane: IVec
        if self.circle_exact and g.centre is not None:
            c = g.centre
            plane = ((c[0] + mk.d[0], c[0] + mk.d[0]), (c[1] + mk.d[1], c[1] + mk.d[1]))
        else:
            f = self._fraction(self._theta(mk)) if self.spiral else (F0, F1)
            rho = self._rho(f)
            ux, uy = self._unit(mk.d)
            plane = (_out(_iadd(self.C[0], _imul(rho, ux))), _out(_iadd(self.C[1], _imul(rho, uy))))
        axis_vals = self._axis_values(self._fraction(self._theta(mk))) if self.moving else {}
        for k, a in enumerate(self.axes):
            if k == self.ia:
                lo[a], hi[a] = plane[0]
            elif k == self.ib:
                lo[a], hi[a] = plane[1]
            elif k in axis_vals:
                lo[a], hi[a] = axis_vals[k]
            else:
                lo[a] = hi[a] = g.start[k]
        mk.box = (lo, hi)
        return mk.box

    def piece_box(self, a: _Mark, b: _Mark) -> Box:
        """A rational box holding the path between two marks (less than a half turn apart)."""
        f: Bounds = (F0, F1)
        if self.spiral or self.moving:
            f = (self._fraction(self._theta(a))[0], self._fraction(self._theta(b))[1])
        rho = self._rho(f)
        xs: list[Bounds] = []
        ys: list[Bounds] = []
        da, db = self._dir_interval(a), self._dir_interval(b)
        if self.circle_exact:
            for mk in (a, b):
                lo, hi = self.point_box(mk)
                xs.append((lo[self.axes[self.ia]], hi[self.axes[self.ia]]))
                ys.append((lo[self.axes[self.ib]], hi[self.axes[self.ib]]))
        else:
            for mk, dv in ((a, da), (b, db)):
                if mk.kind in ("S", "E") and not self.spiral:
                    p = self.g.s if mk.kind == "S" else self.g.e
                    xs.append(_pt(p[0]))
                    ys.append(_pt(p[1]))
                    continue
                ux, uy = self._unit_interval(mk, dv)
                for r in rho:
                    xs.append(_out(_iadd(self.C[0], _imul(_pt(r), ux))))
                    ys.append(_out(_iadd(self.C[1], _imul(_pt(r), uy))))
        # axis extremes that may lie strictly inside the sector
        p0, q0 = (da, db) if self.ccw else (db, da)
        inside_quadrant = True
        for e, axis, sgn in (((F1, F0), 0, 1), ((-F1, F0), 0, -1), ((F0, F1), 1, 1), ((F0, -F1), 1, -1)):
            ev = (_pt(e[0]), _pt(e[1]))
            c1 = self._sign(_cross(p0, ev))
            c2 = self._sign(_cross(ev, q0))
            if (c1 is not None and c1 <= 0) or (c2 is not None and c2 <= 0):
                continue
            inside_quadrant = False
            ext = _iadd(self.C[axis], (sgn * rho[1], sgn * rho[1]))
            (xs if axis == 0 else ys).append(ext)
        if self.spiral and inside_quadrant:
            xs, ys = self._monotone_spiral(a, b, da, db, rho, xs, ys)
        lo = dict(zip(self.axes, self.g.start))
        hi = dict(lo)
        a_x, a_y = self.axes[self.ia], self.axes[self.ib]
        lo[a_x], hi[a_x] = min(x[0] for x in xs), max(x[1] for x in xs)
        lo[a_y], hi[a_y] = min(y[0] for y in ys), max(y[1] for y in ys)
        if self.moving:
            for k, (v0, v1) in self._axis_values(f).items():
                lo[self.axes[k]], hi[self.axes[k]] = v0, v1
        return lo, hi

    def _monotone_spiral(self, a: _Mark, b: _Mark, da: IVec, db: IVec, rho: Bounds,
                         xs: list[Bounds], ys: list[Bounds]) -> tuple[list[Bounds], list[Bounds]]:
        """A spiral piece's plane ranges from its two end points where the coordinate is monotone.

        On a piece whose sector holds no axis direction, the direction angle
        ``φ`` stays in one quadrant, so ``cos φ`` and ``sin φ`` lie between
        their values at the two marks.  With the radius linear in the swept
        angle ``θ`` (``r' = (r_end - r_start) / Θ``) and ``φ`` turning by
        ``s = ±1`` per unit of ``θ``, ``dx/dθ = r' cos φ - s r sin φ`` and
        ``dy/dθ = r' sin φ + s r cos φ``.  When such an interval excludes
        zero, that coordinate is strictly monotone over the piece: its range
        is between the path points at the two marks (:meth:`point_box`),
        which is exact at the start and the end (a spiral that ends on a
        zone face fits there; the annulus box of the piece never does).
        """
        t_lo, t_hi = self.total()
        if t_lo <= 0:
            return xs, ys
        dr = _isub(self.re, self.rs)
        rates = (dr[0] / t_lo, dr[0] / t_hi, dr[1] / t_lo, dr[1] / t_hi)
        r_rate = _out((min(rates), max(rates)))
        ua = self._unit(a.d) if a.kind == "d" else self._unit_interval(a, da)
        ub = self._unit(b.d) if b.kind == "d" else self._unit_interval(b, db)
        cos = (min(ua[0][0], ub[0][0]), max(ua[0][1], ub[0][1]))
        sin = (min(ua[1][0], ub[1][0]), max(ua[1][1], ub[1][1]))
        s: Bounds = (F1, F1) if self.ccw else (-F1, -F1)
        dx = _isub(_imul(r_rate, cos), _imul(s, _imul(rho, sin)))
        dy = _iadd(_imul(r_rate, sin), _imul(s, _imul(rho, cos)))
        ends = (self.point_box(a), self.point_box(b))
        a_x, a_y = self.axes[self.ia], self.axes[self.ib]
        if self._sign(dx) in (1, -1):
            xs = [(box[0][a_x], box[1][a_x]) for box in ends]
        if self._sign(dy) in (1, -1):
            ys = [(box[0][a_y], box[1][a_y]) for box in ends]
        return xs, ys

    def _unit_interval(self, mk: _Mark, dv: IVec) -> IVec:
        if mk.kind == "d":
            return self._unit(mk.d)
        # S or E over the centre box: d / |d| with |d|^2 an interval
        n2 = _iadd(_imul(dv[0], dv[0]), _imul(dv[1], dv[1]))
        n_lo = sqrt_bounds(max(F0, n2[0]), BITS)[0]
        n_hi = sqrt_bounds(n2[1], BITS)[1]
        if n_lo <= 0:
            return (-F1, F1), (-F1, F1)
        out = []
        for x in dv:
            cands = (x[0] / n_lo, x[0] / n_hi, x[1] / n_lo, x[1] / n_hi)
            out.append(_out((min(cands), max(cands))))
        return out[0], out[1]

    def mid(self, a: _Mark, b: _Mark) -> _Mark | None:
        """A d-mark between two marks (None when there is no room); the end's position is a lower bound."""
        if not a.g < b.g:
            return None
        return self._dmark((a.g + b.g) / 2)

    def certainly_inside(self, mk: _Mark) -> bool:
        """Is the mark's direction strictly inside the sweep for every centre in C?"""
        if mk.kind in ("S", "E"):
            return True
        if self.full or self.turns > 0:  # every direction is swept (the mark's lap is its own)
            return True
        if self.g.centre is not None:
            c = self.g.centre
            u = (self.g.s[0] - c[0], self.g.s[1] - c[1])
            w = (self.g.e[0] - c[0], self.g.e[1] - c[1])
            return in_sweep(u, w, mk.d, self.ccw, False)
        ui = self._dir_interval(_Mark("S", F0))
        wi = self._dir_interval(_Mark("E", F0))
        d = (_pt(mk.d[0]), _pt(mk.d[1]))
        if (self.g.r_signed or F0) > 0:  # at most a half turn: strictly after u and strictly before w
            return self._turn(ui, d) == 1 and self._turn(d, wi) == 1
        # more than a half turn: certainly not in the closed complementary sector (w -> u)
        return self._turn(wi, d) == -1 or self._turn(d, ui) == -1

    def _turn(self, a: IVec, b: IVec) -> int | None:
        """Sign of cross(a, b) in the arc's direction (1: b after a), None when not certain."""
        cr = _cross(a, b)
        if not self.ccw:
            cr = (-cr[1], -cr[0])
        return self._sign(cr)

    # ------------------------------------------------------------------ deciding

    def fits(self, lo: dict[str, Fraction], hi: dict[str, Fraction]) -> bool:
        return ex.box_fits(self.p.allowed, lo, hi, self.p.margin, self.seg.tool_length)

    def certify(self, mk: _Mark) -> Hit | None:
        """(zone, point, bad zones) when every point of the mark's enclosure violates a zone, else None."""
        if not self.certainly_inside(mk):
            return None
        lo, hi = self.point_box(mk)
        allowed, margin, tl = self.p.allowed, self.p.margin, self.seg.tool_length
        if lo == hi or all(lo[a] == hi[a] for a in lo):
            bad = allowed.violated_zones(lo, tl, margin)
            return (bad[0], dict(lo), bad) if bad else None
        for z in self.p.zones:
            if ex.box_certainly_violates(allowed, z, lo, hi, margin, tl):
                pt = {a: simple_in(lo[a], hi[a]) for a in self.axes}
                bad = allowed.violated_zones(pt, tl, margin)
                if z not in bad:
                    from ..errors import InternalError

                    raise InternalError("certified arc enclosure: its chosen point does not violate")
                return z, pt, bad
        return None

    def decide(self) -> tuple[str, tuple[_Mark, _Mark | None, Hit] | None]:
        """("safe", None), ("unsafe", (witness mark, proved-up-to mark, hit)) or ("open", None)."""
        marks = self.marks
        hit = self.certify(marks[0])
        if hit is not None:
            return "unsafe", (marks[0], marks[0], hit)
        stack = [(marks[i], marks[i + 1], 0) for i in range(len(marks) - 1)][::-1]
        proved = marks[0]
        contiguous = True
        used = 0
        open_ = False
        while stack:
            a, b, depth = stack.pop()
            used += 1
            self.p.stats["arc_pieces"] = self.p.stats.get("arc_pieces", 0) + 1
            if used > MAX_PIECES:
                return "open", None
            lo, hi = self.piece_box(a, b)
            if self.fits(lo, hi):
                if contiguous and a is proved:
                    proved = b
                continue
            m = self.mid(a, b)
            hit = self.certify(m) if m is not None else None
            if hit is not None and m is not None:
                return "unsafe", (m, proved if contiguous else None, hit)
            if b.kind == "E":
                hit = self.certify(b)
                if hit is not None:
                    return "unsafe", (b, proved if contiguous else None, hit)
            if m is None or depth >= MAX_DEPTH:
                open_ = True
                contiguous = False
                continue
            stack.append((m, b, depth + 1))
            stack.append((a, m, depth + 1))
        return ("open", None) if open_ else ("safe", None)

    def first_exit(self, proved: _Mark | None, witness: _Mark, hit: Hit) -> tuple[_Mark, Hit]:
        """Narrow the first exit between the proved prefix and the witness: (mark, hit)."""
        if proved is None or proved is witness:
            return witness, hit
        a, w = proved, witness
        for _ in range(EXIT_STEPS * 2):
            m = self.mid(a, w)
            if m is None:
                break
            lo, hi = self.piece_box(a, m)
            if self.fits(lo, hi):
                a = m
                continue
            h = self.certify(m)
            if h is None:
                break
            w, hit = m, h
        return w, hit

    def parameter(self, mk: _Mark) -> Fraction:
        """Approximate fraction of the swept angle at a mark (for reports)."""
        th = self._theta(mk)
        t = self.total()
        if t[1] <= 0:
            return F0
        return min(F1, max(F0, ((th[0] + th[1]) / 2) / ((t[0] + t[1]) / 2))).limit_denominator(10**9)

    def depth_samples(self) -> list[tuple[dict[str, Fraction], Fraction]]:
        """Certified violating points along the arc (sixteen per quarter) and how far each may be from
        its path point, for a depth lower bound."""
        out = []
        n = 16
        for i in range(len(self.marks) - 1):
            a, b = self.marks[i], self.marks[i + 1]
            for k in range(1, n):
                mk = self._dmark(a.g + (b.g - a.g) * k / n)
                h = self.certify(mk)
                if h is not None:
                    lo, hi = self.point_box(mk)
                    out.append((h[1], max(hi[x] - lo[x] for x in lo)))
        return out


def decide_arc(prover: Any, seg: Segment, g: ArcGeom, params: tuple) -> Any:
    """Decide an arc by enclosures: an ``Outcome`` (proved or a certified violation), or None when the
    pieces and depth allowed did not settle it (then the solver decides)."""
    enc = ArcEnclosure(prover, seg, g)
    verdict, info = enc.decide()
    if verdict == "safe":
        prover.stats["arc_pieces_proved"] = prover.stats.get("arc_pieces_proved", 0) + 1
        return Outcome(engine="exact")
    if verdict == "open" or info is None:
        return None
    witness, proved, hit = info
    return Outcome(violation(prover, enc, witness, proved, hit, params), engine="exact")


def violation(prover: Any, enc: ArcEnclosure, witness: _Mark, proved: _Mark | None, hit: Hit,
              params: tuple) -> Violation:
    """The report of a certified violation on an arc (first exit narrowed, depth a lower bound)."""
    seg, g = enc.seg, enc.g
    zone, pmap, bad = hit
    outside = ex.outside_point(prover.allowed, zone, pmap, prover.margin, seg.tool_length)
    if outside is None or zone not in prover.allowed.violated_zones(outside, seg.tool_length):
        from ..errors import InternalError

        raise InternalError(f"block {seg.block}: no point strictly outside inside the margin box")
    first, first_hit = enc.first_exit(proved, witness, hit)
    samples = enc.depth_samples()

    def width(mk: _Mark) -> Fraction:
        lo, hi = enc.point_box(mk)
        return max(hi[a] - lo[a] for a in lo)

    depth = F0
    ends = [(dict(zip(prover.axes, seg.start)), F0), (dict(zip(prover.axes, seg.end)), F0)]
    for p, w in [(pmap, width(witness)), (first_hit[1], width(first)), *samples, *ends]:
        for z in prover.allowed.violated_zones(p, seg.tool_length, prover.margin):
            depth = max(depth, ex.point_depth(z, prover.allowed.seen_by(z, p, seg.tool_length), prover.margin) - w)
    # the path point is exact when it is an end point, or a point of a circle (rational centre) along
    # which no other axis moves; otherwise it is the chosen point of a tiny box around the exact one
    if depth.denominator > 10**12:  # a lower bound: keep it short (rounded down to 1e-12)
        depth = Fraction(depth.numerator * 10**12 // depth.denominator, 10**12)
    exact_point = witness.kind in ("S", "E") or (enc.circle_exact and not enc.moving)
    note = ""
    if not exact_point:
        note = (f"irrational path point; reported point within {float(width(witness)):.1e} mm of it, the "
                "whole enclosure violates")
    return Violation(
        block=seg.block, span=seg.span, zone=zone.name,
        point=tuple((a, outside[a]) for a in prover.axes),
        path_point=tuple((a, pmap[a]) for a in prover.axes),
        parameter=enc.parameter(witness), parameter_exact=witness.kind in ("S", "E"),
        first_exit=tuple((a, first_hit[1][a]) for a in prover.axes),
        first_exit_parameter=enc.parameter(first), first_exit_exact=False,
        depth=depth, depth_exact=False, engine="exact",
        segment_kind="helix" if g.helix else "arc", derived=seg.derived,
        params=prover.written_params(params), zones=tuple(z.name for z in bad), note=note,
        on_path=exact_point,
    )

