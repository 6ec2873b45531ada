"""The proof that the tool assembly's swept solids stay out of the fixtures (issue 39, the mill core).

Each part of the active tool (:mod:`nczones.solids`) is a vertical cylinder of radius ``r`` over ``lo..hi``
relative to the machine Z position (``lo = z0 - tool length`` for a tool part: the tip is at machine Z minus
the active tool length; ``z0`` for a spindle part).  At the controlled position ``p`` it meets the open
interior of a fixture exactly when

* the heights overlap: ``p_z + lo < f_z1`` and ``p_z + hi > f_z0`` (open: touching is allowed), and
* in XY the closed disk of radius ``r`` about ``p_xy`` meets the open fixture section, i.e.
  ``g(p) < thr`` with ``g`` the squared distance from ``p_xy`` to the closed rectangle (a box; ``thr = r²``)
  or to the centre (a cylinder of radius ``R``; ``thr = (R + r)²``) — the rounded box / grown disk.

Along a straight piece ``p(t)`` the height condition is an interval of ``t`` (linear inequalities) and ``g``
is a convex piecewise quadratic with rational breakpoints (where ``x(t)`` or ``y(t)`` crosses a side), so its
minimum over that interval is rational and found exactly: the piece violates iff the minimum is below
``thr``.  The witness is the rational ``t`` of the minimum (moved into the open interval when needed) and a
rational contact point inside both the part and the fixture.  Arcs and helices are enclosed
piece by piece (:meth:`SolidsChecker._arc`): the box of the controlled point over a piece of the sweep
(exact extremes) grown by the part is tested against the fixture; an undecided piece is tried at its ends
(exact points of the circle) and split, at most :data:`ARC_PIECES` times; what is left is ``unknown``
with reason ``VF210``.  A motion without a known tool (G49 while tools are described) is ``unknown`` (``VF211``).

Straight motions are screened first in batches (:mod:`nczones.prover.solids_screen`, numpy; on the fast
path's column chunks straight from the columns): only the motions the screen cannot decide reach the exact
proof above, so that a CAM program of a million lines costs little more than its point-only verdict.

The least clearance per part and fixture is the least horizontal distance between them at the moments their
heights overlap (the distance between two vertical solids at overlapping heights), a certified lower bound
(square roots rounded down); lines give it exactly up to that rounding, arcs a lower bound from their box.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import numpy as np

from ..machine import Machine
from ..motion import MotionChunk, Segment, SegmentKind
from ..solids import FixtureBox, FixtureCylinder, FixturePrism, Part, Solids
from .geometry import (
    arc_bases,
    arc_geom,
    in_sweep,
    line_pieces,
    split_arc_piece,
    sqrt_bounds,
)
from .result import Reason, Result, Violation
from .solids_ranges import UNTRACKED, axis_displacement, untracked
from .solids_screen import Screened, group_by_tool, needs_exact, needs_exact_columns

if TYPE_CHECKING:
    from .options import VerifyOptions

__all__ = ["SolidsChecker", "SpindleToolCheck"]

F0 = Fraction(0)
F1 = Fraction(1)
_HALF = Fraction(1, 2)

Fixture = FixtureBox | FixtureCylinder | FixturePrism
#: Arc pieces the solids proof may split an arc into before it says ``unknown`` (VF210).
ARC_PIECES = 64
#: Straight motions screened together (:mod:`nczones.prover.solids_screen`).
SCREEN_BATCH = 16384
#: Whether the checker screens (tests turn it off to compare with the exact proof of every motion).
SCREEN = True
_STRAIGHT = (SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.DWELL)


@dataclass(frozen=True, slots=True)
class _Fx:
    """A box or cylinder fixture as one motion sees it: the XY rectangle ``x0..x1 × y0..y1`` (None:
    unbounded) grown by ``rr`` (0 for a box; a cylinder is its centre as a point rectangle grown by its
    radius; a parameter range widens the rectangle), over the heights ``z0..z1``."""

    name: str
    x0: Fraction | None
    x1: Fraction | None
    y0: Fraction | None
    y1: Fraction | None
    z0: Fraction | None
    z1: Fraction | None
    rr: Fraction


@dataclass(frozen=True, slots=True)
class _Prism:
    """A polygon prism as one motion sees it; ``grow`` widens it (a parameter range's reach, 0 nominal)."""

    name: str
    vertices: tuple[tuple[Fraction, Fraction], ...]
    z0: Fraction | None
    z1: Fraction | None
    grow: Fraction = F0


_Placed = _Fx | _Prism


def _add(v: Fraction | None, d: Fraction) -> Fraction | None:
    return None if v is None else v + d


def _in_machine(fx: Fixture, o: tuple[Fraction, Fraction, Fraction]) -> Fixture:
    """The fixture where a motion sees it, in machine coordinates (moved by its work offset's origin ``o``), for
    the report's drawing of the contact."""
    if not fx.frame:
        return fx
    ox, oy, oz = o
    if isinstance(fx, FixturePrism):
        return replace(fx, vertices=tuple((x + ox, y + oy) for x, y in fx.vertices), z0=_add(fx.z0, oz),
                       z1=_add(fx.z1, oz), frame="")
    if isinstance(fx, FixtureCylinder):
        return replace(fx, cx=fx.cx + ox, cy=fx.cy + oy, z0=_add(fx.z0, oz), z1=_add(fx.z1, oz), frame="")
    return replace(fx, x0=_add(fx.x0, ox), x1=_add(fx.x1, ox), y0=_add(fx.y0, oy), y1=_add(fx.y1, oy),
                   z0=_add(fx.z0, oz), z1=_add(fx.z1, oz), frame="")


def _place(fx: Fixture, o: tuple[Fraction, Fraction, Fraction]) -> _Placed:
    """The fixture moved by ``o`` (its work offset's origin; zero in machine coordinates)."""
    ox, oy, oz = o
    if isinstance(fx, FixturePrism):
        return _Prism(fx.name, tuple((x + ox, y + oy) for x, y in fx.vertices), _add(fx.z0, oz), _add(fx.z1, oz))
    if isinstance(fx, FixtureCylinder):
        cx, cy = fx.cx + ox, fx.cy + oy
        return _Fx(fx.name, cx, cx, cy, cy, _add(fx.z0, oz), _add(fx.z1, oz), fx.radius)
    return _Fx(fx.name, _add(fx.x0, ox), _add(fx.x1, ox), _add(fx.y0, oy), _add(fx.y1, oy), _add(fx.z0, oz),
               _add(fx.z1, oz), F0)


def _grown(f: _Placed, d: tuple[tuple[Fraction, Fraction], ...]) -> _Placed:
    """Every place of ``f`` relative to a part displaced by some ``d`` in the box ``d`` (per axis lo..hi):
    the part at ``p + d`` meets ``f`` iff ``p`` meets ``f - d``, and the union over ``d`` is ``f`` grown by the
    box, exactly for a rectangle; a polygon is moved by the box's centre and grown by its half-extents' sum
    (an enclosure: the Euclidean reach of the box is at most that)."""
    (xl, xh), (yl, yh), (zl, zh) = d
    z0, z1 = _add(f.z0, -zh), _add(f.z1, -zl)
    if isinstance(f, _Prism):
        cx, cy = (xl + xh) / 2, (yl + yh) / 2
        return _Prism(f.name, tuple((x - cx, y - cy) for x, y in f.vertices), z0, z1,
                      f.grow + (xh - xl) / 2 + (yh - yl) / 2)
    return _Fx(f.name, _add(f.x0, -xh), _add(f.x1, -xl), _add(f.y0, -yh), _add(f.y1, -yl), z0, z1, f.rr)


def _reach(f: _Placed) -> Fraction:
    return f.grow if isinstance(f, _Prism) else f.rr


class _Span:
    """``t`` in ``lo..hi`` with open or closed ends (None: empty)."""

    __slots__ = ("lo", "hi", "lo_open", "hi_open")

    def __init__(self, lo: Fraction, hi: Fraction, lo_open: bool = False, hi_open: bool = False) -> None:
        self.lo, self.hi, self.lo_open, self.hi_open = lo, hi, lo_open, hi_open

    def above(self, a: Fraction, b: Fraction) -> _Span | None:
        """Intersect with ``a + b t > 0``."""
        if b == 0:
            return self if a > 0 else None
        c = -a / b
        if b > 0:
            if c > self.lo or (c == self.lo and not self.lo_open):
                self.lo, self.lo_open = c, True
        elif c < self.hi or (c == self.hi and not self.hi_open):
            self.hi, self.hi_open = c, True
        return self if self.ok() else None

    def ok(self) -> bool:
        return self.lo < self.hi or (self.lo == self.hi and not self.lo_open and not self.hi_open)


def _quad_min(coef: tuple[Fraction, Fraction, Fraction], a: Fraction, b: Fraction) -> tuple[Fraction, Fraction]:
    """Minimum ``(value, t)`` of ``q2 t² + q1 t + q0`` over ``[a, b]`` (convex: q2 >= 0)."""
    q2, q1, q0 = coef
    cands = [a, b]
    if q2 > 0:
        v = -q1 / (2 * q2)
        if a < v < b:
            cands.append(v)
    return min(((q2 * t + q1) * t + q0, t) for t in cands)


def _gap_coef(p0: Fraction, d: Fraction, lo: Fraction | None, hi: Fraction | None,
              mid: Fraction) -> tuple[Fraction, Fraction]:
    """The signed gap outside ``[lo, hi]`` of ``p0 + d t`` on a piece around ``mid``, as ``(c0, c1)``."""
    x = p0 + d * mid
    if lo is not None and x < lo:
        return lo - p0, -d
    if hi is not None and x > hi:
        return p0 - hi, d
    return F0, F0


def _g_coef(fx: _Fx, px: Fraction, dx: Fraction, py: Fraction, dy: Fraction,
            mid: Fraction) -> tuple[Fraction, Fraction, Fraction]:
    ax, dx = _gap_coef(px, dx, fx.x0, fx.x1, mid)
    ay, dy = _gap_coef(py, dy, fx.y0, fx.y1, mid)
    return dx * dx + dy * dy, 2 * (ax * dx + ay * dy), ax * ax + ay * ay


def _breaks(fx: _Fx, px: Fraction, dx: Fraction, py: Fraction, dy: Fraction) -> list[Fraction]:
    out = []
    for p, d, sides in ((px, dx, (fx.x0, fx.x1)), (py, dy, (fx.y0, fx.y1))):
        if d != 0:
            out += [(s - p) / d for s in set(sides) if s is not None]
    return out


def _thr(fx: _Placed, r: Fraction) -> Fraction:
    return (_reach(fx) + r) ** 2


def _g(fx: _Placed, x: Fraction, y: Fraction) -> Fraction:
    """The squared XY distance from ``(x, y)`` to the fixture's core (rectangle or polygon; 0 inside)."""
    if isinstance(fx, _Prism):
        return _poly_dist2(fx.vertices, (x, y))
    gx = max(F0, (fx.x0 - x) if fx.x0 is not None else F0, (x - fx.x1) if fx.x1 is not None else F0)
    gy = max(F0, (fx.y0 - y) if fx.y0 is not None else F0, (y - fx.y1) if fx.y1 is not None else F0)
    return gx * gx + gy * gy


def _contact(fx: _Placed, part: Part, x: Fraction, y: Fraction, z: Fraction, lo: Fraction,
             hi: Fraction) -> tuple[Fraction, Fraction, Fraction] | None:
    """A rational point inside the part at ``(x, y, z)`` and inside the fixture's open interior (the caller
    checked that they meet; a nominal fixture), or None when none was found."""
    zl = z + lo if fx.z0 is None else max(z + lo, fx.z0)
    zh = z + hi if fx.z1 is None else min(z + hi, fx.z1)
    zc = (zl + zh) / 2
    if isinstance(fx, _Prism):
        c = _prism_contact(fx, part.radius, (x, y))
        return None if c is None else (c[0], c[1], zc)
    if fx.rr > 0:  # toward the nearest core point q: |c - p| < r and |c - q| < rr (module docstring)
        qx, qy = _clamp(x, fx.x0, fx.x1), _clamp(y, fx.y0, fx.y1)
        lam = part.radius / (fx.rr + part.radius)
        return x + (qx - x) * lam, y + (qy - y) * lam, zc
    d_hi = sqrt_bounds(_g(fx, x, y))[1]
    delta = (part.radius - d_hi) / 4  # > 0: clamp into the box shrunk by delta, within d + delta·√2 < r
    out = []
    for v, a, b in ((x, fx.x0, fx.x1), (y, fx.y0, fx.y1)):
        a2 = None if a is None else a + delta
        b2 = None if b is None else b - delta
        if a2 is not None and b2 is not None and a2 > b2:
            a2 = b2 = (a + b) / 2  # type: ignore[operator]
        out.append(_clamp(v, a2, b2))
    return out[0], out[1], zc


def _clamp(v: Fraction, a: Fraction | None, b: Fraction | None) -> Fraction:
    v = v if a is None else max(v, a)
    return v if b is None else min(v, b)


# --------------------------------------------------------------------------- polygons (exact, 2-D)

Pt = tuple[Fraction, Fraction]


def _cross(o: Pt, a: Pt, b: Pt) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _locate(poly: tuple[Pt, ...], q: Pt) -> int:
    """+1 strictly inside, 0 on the boundary, -1 outside (crossing number, exact)."""
    inside = False
    n = len(poly)
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        if _cross(a, b, q) == 0 and min(a[0], b[0]) <= q[0] <= max(a[0], b[0]) \
                and min(a[1], b[1]) <= q[1] <= max(a[1], b[1]):
            return 0
        if (a[1] > q[1]) != (b[1] > q[1]):
            if q[0] < a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]):
                inside = not inside
    return 1 if inside else -1


def _pt_seg(q: Pt, a: Pt, b: Pt) -> tuple[Fraction, Fraction]:
    """``(squared distance, s)`` from ``q`` to the segment ``a + s (b - a)``, ``s`` in [0, 1]."""
    ux, uy = b[0] - a[0], b[1] - a[1]
    n2 = ux * ux + uy * uy
    s = F0 if n2 == 0 else min(F1, max(F0, ((q[0] - a[0]) * ux + (q[1] - a[1]) * uy) / n2))
    dx, dy = a[0] + s * ux - q[0], a[1] + s * uy - q[1]
    return dx * dx + dy * dy, s


def _seg_seg(a0: Pt, a1: Pt, b0: Pt, b1: Pt) -> tuple[Fraction, Fraction]:
    """``(squared distance, s)`` between the segments ``a0 a1`` and ``b0 b1``, ``s`` the parameter on ``a`` of
    a closest point: 0 where they cross, else the least of the four endpoint distances (in the plane the
    distance of two disjoint segments is attained at an endpoint of one of them)."""
    d1, d2 = _cross(b0, b1, a0), _cross(b0, b1, a1)
    d3, d4 = _cross(a0, a1, b0), _cross(a0, a1, b1)
    if ((d1 > 0 > d2) or (d1 < 0 < d2)) and ((d3 > 0 > d4) or (d3 < 0 < d4)):
        return F0, d1 / (d1 - d2)
    cands = [(_pt_seg(a0, b0, b1)[0], F0), (_pt_seg(a1, b0, b1)[0], F1)]
    for q in (b0, b1):
        cands.append(_pt_seg(q, a0, a1))
    return min(cands)


def _edges(poly: tuple[Pt, ...]) -> Iterator[tuple[Pt, Pt]]:
    for i in range(len(poly)):
        yield poly[i], poly[(i + 1) % len(poly)]


def _poly_dist2(poly: tuple[Pt, ...], q: Pt) -> Fraction:
    if _locate(poly, q) >= 0:
        return F0
    return min(_pt_seg(q, a, b)[0] for a, b in _edges(poly))


def _path_poly(poly: tuple[Pt, ...], a0: Pt, a1: Pt) -> tuple[Fraction, Fraction]:
    """``(least squared distance, s)`` from the segment ``a0 a1`` to the closed polygon region."""
    if _locate(poly, a0) >= 0:
        return F0, F0
    return min(_seg_seg(a0, a1, p, q) for p, q in _edges(poly))


def _rect_poly_gap2(poly: tuple[Pt, ...], bx: tuple[Fraction, Fraction], by: tuple[Fraction, Fraction]) -> Fraction:
    """Least squared distance between the closed rectangle ``bx × by`` and the closed polygon region."""
    corners = ((bx[0], by[0]), (bx[1], by[0]), (bx[1], by[1]), (bx[0], by[1]))
    if _locate(poly, corners[0]) >= 0 or any(bx[0] <= x <= bx[1] and by[0] <= y <= by[1] for x, y in poly):
        return F0
    return min(_seg_seg(a, b, p, q)[0] for a, b in _edges(corners) for p, q in _edges(poly))


def _prism_contact(f: _Prism, r: Fraction, p: Pt) -> Pt | None:
    """A point strictly inside the polygon and strictly within ``r`` of ``p`` (the caller found the polygon
    closer than ``r``): ``p`` itself, or a point past the nearest boundary point, halved toward it."""
    if _locate(f.vertices, p) > 0:
        return p
    r2 = r * r
    for a, b in _edges(f.vertices):
        d2, s = _pt_seg(p, a, b)
        if d2 >= r2:
            continue
        q = (a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]))
        nx, ny = b[1] - a[1], a[0] - b[0]  # the edge's normals ±(nx, ny), and the way from p to q
        c = _toward(f.vertices, p, r2, q, ((q[0] - p[0], q[1] - p[1]), (nx, ny), (-nx, -ny)))
        if c is not None:
            return c
    v = f.vertices
    for i, q in enumerate(v):  # a sharp vertex: between its two edges (a positive sum of their directions)
        if (q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2 < r2:
            a, b = v[i - 1], v[(i + 1) % len(v)]
            la, lb = abs(a[0] - q[0]) + abs(a[1] - q[1]), abs(b[0] - q[0]) + abs(b[1] - q[1])
            d = ((a[0] - q[0]) / la + (b[0] - q[0]) / lb, (a[1] - q[1]) / la + (b[1] - q[1]) / lb)
            c = _toward(v, p, r2, q, (d,))
            if c is not None:
                return c
    return None


def _toward(poly: tuple[Pt, ...], p: Pt, r2: Fraction, q: Pt, ways: tuple[Pt, ...]) -> Pt | None:
    """A point ``q + k w`` (``w`` one of ``ways``, ``k`` halved from the part's reach) strictly inside the
    polygon and strictly within ``sqrt(r2)`` of ``p``, or None."""
    for dx, dy in ways:
        if dx == 0 and dy == 0:
            continue
        k = 1 / (abs(dx) + abs(dy))
        for _ in range(64):
            c = (q[0] + dx * k, q[1] + dy * k)
            if (c[0] - p[0]) ** 2 + (c[1] - p[1]) ** 2 < r2 and _locate(poly, c) > 0:
                return c
            k /= 2
    return None


@dataclass
class SolidsChecker:
    """Fed every motion in execution order; collects violations, reasons and least clearances.

    ``ranges``: the parameter ranges of the case (:class:`~nczones.prover.result.ParamRange`, deviations from
    the values the motion was built at); a part is proved against each fixture grown by every displacement
    the ranges allow (:meth:`_displacement`), and a hit of the grown fixture is a violation only where the
    nominal motion hits too (else ``unknown``, ``VF218``)."""

    machine: Machine
    solids: Solids
    ranges: tuple[Any, ...] = ()
    #: a displacement box (per axis X, Y, Z: lo..hi, containing 0) added to every motion's: the tool-break
    #: recovery proves a family of legs as one leg displaced within it (:mod:`.solids_recovery`)
    shift: tuple[tuple[Fraction, Fraction], ...] | None = None
    violations: list[Violation] = field(default_factory=list)
    reasons: list[Reason] = field(default_factory=list)
    #: (part label, fixture name) -> (least clearance lower bound, line)
    clearance: dict[tuple[str, str], tuple[Fraction, int | None]] = field(default_factory=dict)
    #: block -> (the active parts, the tool length, the part, the fixture) of each solid violation, for the
    #: report's drawing of the tool at the contact (:mod:`nczones.report.solids_view`)
    contacts: dict[int, tuple[tuple[Part, ...], Fraction, Part, Fixture]] = field(default_factory=dict)
    #: screen straight motions in batches before the exact proof (then :meth:`flush` must end the feeding);
    #: False (the default: a checker fed by hand checks each motion as it comes); None: SCREEN
    screen: bool | None = False
    screened_out: int = 0
    screened_exact: int = 0
    screened_pairs: int = 0
    column_rows: int = 0  # rows screened straight from the fast path's columns
    _batch: list[Segment] = field(default_factory=list)
    _batch_size: int = 4
    _blocks: set[int] = field(default_factory=set)
    _arc_witness: bool = False
    _labels: dict[Part, str] = field(default_factory=dict)
    _cache: dict[tuple, Any] = field(default_factory=dict)
    _where: dict[tuple[Part, Fixture], tuple[_Placed, _Placed]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        axes = self.machine.axis_names
        self.ix, self.iy, self.iz = axes.index("X"), axes.index("Y"), axes.index("Z")
        self._dev = {r.name: (r.lo, r.hi) for r in self.ranges}
        # the screen compares the fixtures as the machine file gives them: only where no range, work offset
        # or prism moves or shapes them per motion (else every motion goes to the exact proof)
        static = not self._dev and self.shift is None and not any(
            fx.frame or isinstance(fx, FixturePrism) for fx in self.solids.fixtures)
        self.screen = (SCREEN if self.screen is None else self.screen) and static

    def feed(self, seg: Segment) -> None:
        """Check one motion (straight motions are screened in batches first: call :meth:`flush` at the end)."""
        if seg.block in self._blocks or not self.solids.fixtures:
            return
        if self.screen and seg.kind in _STRAIGHT and self.solids.parts_for(seg.tool_register) is not None \
                and all(a in "XYZ" or seg.start[k] == seg.end[k] for k, a in enumerate(seg.axes)):
            self._batch.append(seg)
            if len(self._batch) >= self._batch_size:
                self.flush()
            return
        self.flush()
        self._exact(seg)

    def feed_chunk(self, chunk: MotionChunk) -> None:
        """Check a column chunk (:class:`~nczones.motion.MotionChunk`) of the vectorized fast path: its rows
        screened straight from the columns (slices growing like the batches of :meth:`flush`), only the
        undecided rows made into segments and proved exactly.  A chunk that did not record its tool register
        (``tools_known`` False) is checked segment by segment."""
        if not self.solids.fixtures:
            return
        parts = self.solids.parts_for(chunk.tool_register)
        if chunk.scale is None or not chunk.tools_known or not self.screen or parts is None:
            for seg in chunk.segments():
                self.feed(seg)
            return
        self.flush()
        a, n = 0, len(chunk)
        self.column_rows += n
        while a < n:
            b = min(n, a + self._batch_size)
            self._batch_size = min(SCREEN_BATCH, 2 * self._batch_size)
            screened = needs_exact_columns(chunk, a, b, (self.ix, self.iy, self.iz), parts, self.solids.fixtures,
                                           self._best)
            self._settle(screened, functools.partial(_row_segment, chunk, a))
            a = b

    def _best(self, part: Part, fx: Fixture) -> Fraction | None:
        got = self.clearance.get(self._key(part, fx))
        return None if got is None else got[0]

    def flush(self) -> None:
        """Screen the batched straight motions (:mod:`nczones.prover.solids_screen`) and prove the undecided
        ones exactly, in program order."""
        batch, self._batch = self._batch, []
        if not batch:
            return
        self._batch_size = min(SCREEN_BATCH, 2 * self._batch_size)  # small at first: the exact proof of the
        # first motions sets the least clearances the screen compares with
        for register, idx in group_by_tool(batch).items():
            parts = self.solids.parts_for(register) or ()
            screened = needs_exact([batch[k] for k in idx], (self.ix, self.iy, self.iz), parts, self.solids.fixtures,
                                   self._best)
            self._settle(screened, lambda k, idx=idx: batch[idx[k]])  # type: ignore[misc]

    def _settle(self, screened: Screened, seg_at: Callable[[int], Segment]) -> None:
        """Prove exactly what the screen left: the ``hit`` motions in program order (every pair, as the exact
        proof of every motion would), then per pair its candidates nearest first, the pair alone, until the
        rest cannot come closer than the pair's least clearance (none of them can meet the fixture:
        :class:`~nczones.prover.solids_screen.Screened`).  A block's motions from its first violation on are
        not checked further (as in program order); those before it are.  The verdict, the violations, the
        reasons and the least clearances are those of the exact proof of every motion; where several
        motions reach a least clearance, the line given may be another of them."""
        cache: dict[int, Segment] = {}

        def at(k: int) -> Segment:
            if k not in cache:
                cache[k] = seg_at(k)
            return cache[k]

        before = set(self._blocks)
        stopped: dict[int, int] = {}  # block -> the row of its first violation (or unknown) in this batch
        hits = np.flatnonzero(screened.hit).tolist()
        self.screened_exact += len(hits)
        self.screened_out += len(screened.hit) - len(hits)
        for k in hits:
            seg = at(k)
            self._exact(seg)
            if seg.block in self._blocks and seg.block not in before:
                stopped.setdefault(seg.block, k)
        for pair in screened.pairs:
            rows = np.flatnonzero(pair.cand)
            for k in rows[np.argsort(pair.key[rows], kind="stable")].tolist():
                if pair.far(k, self._best(pair.part, pair.fixture)):
                    break  # sorted: the rest are at least as far
                seg = at(k)
                if seg.block in before or stopped.get(seg.block, k + 1) <= k:
                    continue  # the exact proof of the violating motion itself stopped at the violation
                self.screened_pairs += 1
                if self._placed(seg, (pair.part,)) is None:  # the fixtures where this motion sees them
                    continue
                for piece in line_pieces(seg, self.machine):
                    self._line(seg, (pair.part,), piece.p0, piece.p1, piece.tau0, piece.tau1, (pair.fixture,))

    def _exact(self, seg: Segment) -> None:
        if seg.block in self._blocks:
            return
        parts = self.solids.parts_for(seg.tool_register)
        if parts is None:
            self._unknown(seg, "VF211", "no tool length is active (G49): which tool assembly is in the spindle "
                          "is not known, so its solids were not checked against the fixtures (select the tool's "
                          "length with G43 H<n>; the assembly of [[tools]] number n is used)")
            return
        moved = [a for k, a in enumerate(seg.axes) if a not in "XYZ" and seg.start[k] != seg.end[k]]
        if moved:  # a rotary or extra linear axis may carry the fixtures or the tool: not modelled
            self._unknown(seg, "VF210", f"the motion moves {', '.join(moved)}: the tool solids are modelled on a "
                          "machine moving X, Y and Z only")
        elif self._placed(seg, parts) is None:
            return
        elif seg.kind is SegmentKind.ARC:
            self._arc(seg, parts)
        elif seg.kind in (SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.DWELL):
            for piece in line_pieces(seg, self.machine):
                if self._line(seg, parts, piece.p0, piece.p1, piece.tau0, piece.tau1):
                    return
        else:
            self._unknown(seg, "VF210", f"the tool solids along a {seg.kind.name.lower()} motion are not modelled")

    def box_clear(self, seg: Segment, lo_c: list, hi_c: list) -> bool | None:
        """With the controlled point anywhere in the box ``lo_c..hi_c`` (machine coordinates) and the tool,
        tool length and frame of ``seg``: do the parts stay out of every fixture (True), may one meet one
        (False), or is that not known (None: a reason is given, VF211/VF219)?"""
        if not self.solids.fixtures:
            return True
        parts = self.solids.parts_for(seg.tool_register)
        if parts is None:
            self._unknown(seg, "VF211", "no tool length is active (G49): the tool assembly on the recovery legs is "
                          "not known")
            return None
        if self._placed(seg, parts) is None:
            return None
        return self._box_hits(seg, parts, lo_c, hi_c) is None

    def box_meets(self, seg: Segment, lo_c: list, hi_c: list) -> tuple[Part, Fixture] | bool | None:
        """:meth:`box_clear` naming what may meet: the first part and fixture (in the machine file's terms), False
        when every part stays out of every fixture, None when that is not known (a reason is given)."""
        clear = self.box_clear(seg, lo_c, hi_c)
        if clear is not False:
            return None if clear is None else False
        parts = self.solids.parts_for(seg.tool_register) or ()
        return self._box_hits(seg, parts, lo_c, hi_c) or False

    def _unknown(self, seg: Segment, code: str, message: str) -> None:
        self._blocks.add(seg.block)
        self.reasons.append(Reason(message, seg.span, seg.block, code))

    # ------------------------------------------------------------------ where the fixtures are at a motion

    def _placed(self, seg: Segment, parts: tuple[Part, ...]) -> dict | None:
        """Per (part, fixture): the fixture where the motion sees it, nominal and grown by the ranges'
        displacements (the same object when they allow none); None (a reason given) when a fixture's work
        offset is not known at this motion or the ranges' dependencies were not tracked.  Cached by what the
        placement reads (the parts, the frame if a fixture has one, the dependencies if there are ranges)."""
        framed = any(fx.frame for fx in self.solids.fixtures)
        frame = seg.frame
        key = (parts, (frame.work, frame.work_offset, frame.rotation) if framed and frame is not None else framed,
               (seg.deps_start, seg.deps_end, seg.deps_tool) if self._dev else None)
        got = self._cache.get(key)
        if got is None:
            if len(self._cache) > 4096:  # memory stays bounded whatever the program
                self._cache.clear()
            got = self._cache[key] = self._place_all(seg, parts)
        if isinstance(got, tuple):
            self._unknown(seg, *got)
            return None
        self._where = got
        return got

    def _place_all(self, seg: Segment, parts: tuple[Part, ...]) -> dict | tuple[str, str]:
        if self._dev and untracked(self.ranges, seg):
            return "VF218", UNTRACKED
        where: dict[tuple[Part, Fixture], tuple[_Placed, _Placed]] = {}
        for fx in self.solids.fixtures:
            origin = self._origin(seg, fx)
            if origin is None:
                frame = seg.frame
                now = "no work offset" if frame is None else (
                    f"{frame.work} rotated" if frame.rotation is not None and frame.work == fx.frame else frame.work)
                return "VF219", (f"the fixture `{fx.name}` moves with {fx.frame}, but this motion runs in {now}: where "
                                 f"{fx.frame} is now is not known to the solids proof (run the motions near it in "
                                 f"{fx.frame}, unrotated)")
            nominal = _place(fx, origin)
            for part in parts:
                d = self._displacement(seg, part, fx)
                grown = nominal if all(lo == hi == 0 for lo, hi in d) else _grown(nominal, d)
                where[part, fx] = (nominal, grown)
        return where

    def _origin(self, seg: Segment, fx: Fixture) -> tuple[Fraction, Fraction, Fraction] | None:
        if not fx.frame:
            return F0, F0, F0
        frame = seg.frame
        if frame is None or frame.work != fx.frame or frame.rotation is not None or frame.work_offset is None:
            return None
        w = frame.work_offset
        return w[self.ix], w[self.iy], w[self.iz]

    def _displacement(self, seg: Segment, part: Part, fx: Fixture) -> tuple[tuple[Fraction, Fraction], ...]:
        """Per axis X, Y, Z the interval (containing 0) of the part's displacement against the fixture over the
        ranges: the coordinate's sources (``Segment.deps_start``/``deps_end``, their hull along the motion),
        less a tool part's length sources on Z (the tip is machine Z minus the length), less the fixture's
        work offset; a homing error moves the machine, and a fixture in a work offset maybe with it."""
        out: list[tuple[Fraction, Fraction]] = []
        for a, i in (("X", self.ix), ("Y", self.iy), ("Z", self.iz)):
            lo, hi = axis_displacement(seg, self._dev, a, i, less_tool=a == "Z" and not part.spindle, frame=fx.frame)
            if self.shift is not None:
                lo, hi = lo + self.shift[len(out)][0], hi + self.shift[len(out)][1]
            out.append((lo, hi))
        return tuple(out)

    # ------------------------------------------------------------------ clearances

    def _offsets(self, seg: Segment, part: Part) -> tuple[Fraction, Fraction]:
        shift = F0 if part.spindle else -seg.tool_length
        return part.z0 + shift, part.z1 + shift

    def _key(self, part: Part, fx: Fixture) -> tuple[str, str]:
        label = self._labels.get(part)
        if label is None:
            label = self._labels[part] = part.label()
        return label, fx.name

    def _clear(self, part: Part, fx: Fixture, f: _Placed, gmin: Fraction, seg: Segment) -> None:
        thr_r = _reach(f) + part.radius
        key = self._key(part, fx)
        best = self.clearance.get(key)
        if best is not None and best[0] + thr_r >= 0 and gmin >= (best[0] + thr_r) ** 2:
            return  # cannot lower the least clearance (no square root needed)
        c = sqrt_bounds(gmin, 64)[0] - thr_r
        if best is None or c < best[0]:
            self.clearance[key] = (c, seg.line)

    def _far(self, part: Part, fx: Fixture, f: _Placed, bx: tuple, by: tuple) -> bool:
        """Is the box ``bx × by`` of the part's axis so far from the fixture that the part cannot meet it nor
        come closer than its least clearance so far?  (A cheap screen before the exact minimum.)"""
        best = self.clearance.get(self._key(part, fx))
        if best is None or best[0] < 0:
            return False
        return _rect_gap2(f, bx, by) >= (best[0] + _reach(f) + part.radius) ** 2

    # ------------------------------------------------------------------ straight motions

    def _line(self, seg: Segment, parts: tuple[Part, ...], p0: tuple, p1: tuple, tau0: Fraction,
              tau1: Fraction, fixtures: tuple[Fixture, ...] | None = None) -> bool:
        px, py, pz = p0[self.ix], p0[self.iy], p0[self.iz]
        dx, dy, dz = p1[self.ix] - px, p1[self.iy] - py, p1[self.iz] - pz
        bx, by = (min(px, px + dx), max(px, px + dx)), (min(py, py + dy), max(py, py + dy))
        for part in parts:
            lo, hi = self._offsets(seg, part)
            for fx in self.solids.fixtures if fixtures is None else fixtures:
                nominal, grown = self._where[part, fx]
                if self._far(part, fx, grown, bx, by):
                    continue
                found = _line_min(grown, part.radius, lo, hi, (px, py, pz), (dx, dy, dz))
                if found is None:
                    continue
                gmin, t, span = found
                self._clear(part, fx, grown, gmin, seg)
                if gmin >= _thr(grown, part.radius):
                    continue
                if grown is not nominal:
                    found = _line_min(nominal, part.radius, lo, hi, (px, py, pz), (dx, dy, dz))
                    if found is None or found[0] >= _thr(nominal, part.radius):
                        self._unknown(seg, "VF218", f"the {part.label()} may enter `{fx.name}` for some values of "
                                      "the parameter ranges (not at their nominal values): the ranges move it "
                                      "that far")
                        return True
                    gmin, t, span = found
                if self._hit(seg, part, fx, nominal, span, t, (p0, p1, tau0, tau1), lo, hi):
                    return True
        return False

    def _hit(self, seg: Segment, part: Part, fx: Fixture, f: _Placed, span: _Span, t: Fraction, path: tuple,
             lo: Fraction, hi: Fraction) -> bool:
        """Report the part in the nominal fixture at ``t`` (or the reason no witness was found)."""
        p0, p1, tau0, tau1 = path
        px, py, pz = p0[self.ix], p0[self.iy], p0[self.iz]
        dx, dy, dz = p1[self.ix] - px, p1[self.iy] - py, p1[self.iz] - pz
        inside = _inside(f, part, span, t, px, dx, py, dy)
        at = None if inside is None else (px + dx * inside, py + dy * inside, pz + dz * inside)
        contact = None if at is None else _contact(f, part, *at, lo, hi)
        if inside is None or at is None or contact is None:  # never a silent safe: no witness point was found
            self._unknown(seg, "VF210", f"the {part.label()} meets `{fx.name}` but no witness point was found")
            return True
        self._report(seg, part, f, at, contact, tau0 + inside * (tau1 - tau0), p0, p1, inside, lo, hi, fx)
        return True

    def _report(self, seg: Segment, part: Part, fx: _Placed, p: tuple, contact: tuple, tau: Fraction, p0: tuple,
                p1: tuple, t: Fraction, lo: Fraction, hi: Fraction, orig: Fixture) -> None:
        x, y, z = p
        cx, cy, cz = contact
        path = tuple(a + t * (b - a) for a, b in zip(p0, p1))
        axes = self.machine.axis_names
        depth_xy = _reach(fx) + part.radius - sqrt_bounds(_g(fx, x, y), 64)[1]
        depth_z = min(v for v in ((fx.z1 - (z + lo)) if fx.z1 is not None else None,
                                  ((z + hi) - fx.z0) if fx.z0 is not None else None, depth_xy) if v is not None)
        depth = max(F0, min(depth_xy, depth_z))
        from ..exact import format_decimal

        where = f"line {seg.line}" if seg.line is not None else f"block {seg.block}"
        pt = " ".join(f"{a}{format_decimal(v, 4)}" for a, v in zip("XYZ", (x, y, z)))
        note = (f"{part.label()} enters `{fx.name}` at {where}, {pt}, {format_decimal(depth, 3)} mm deep "
                f"(contact point X{format_decimal(cx, 4)} Y{format_decimal(cy, 4)} Z{format_decimal(cz, 4)})")
        self._blocks.add(seg.block)
        self.contacts[seg.block] = (self.solids.parts_for(seg.tool_register) or (part,), seg.tool_length, part,
                                    _in_machine(orig, self._origin(seg, orig) or (F0, F0, F0)))
        self.violations.append(Violation(
            block=seg.block, span=seg.span, zone=fx.name, point=(("X", cx), ("Y", cy), ("Z", cz)),
            path_point=tuple(zip(axes, path)), parameter=tau, parameter_exact=not self._arc_witness,
            first_exit=tuple(zip(axes, path)), first_exit_parameter=tau, first_exit_exact=False,
            depth=depth, depth_exact=False, engine="exact", segment_kind=seg.kind.name.lower(),
            derived=seg.derived, kind="solid", zones=(part.name,), note=note, exit_located=False,
            frame=seg.frame))

    def _arc(self, seg: Segment, parts: tuple[Part, ...]) -> None:
        """Arcs: pieces of the sweep (cut at quarter turns, then halved, at most :data:`ARC_PIECES`), each
        enclosed by its box; an undecided piece is tried at its ends (exact points of the circle, on a
        plane arc) before it is split; what the budget leaves is ``unknown``."""
        g = arc_geom(seg)
        lo_c = [min(s, e) for s, e in zip(seg.start, seg.end)]
        hi_c = [max(s, e) for s, e in zip(seg.start, seg.end)]
        if not g.exact:  # an R-format arc with an irrational centre, a spiral: the whole arc's box
            (lo_c[g.ia], hi_c[g.ia]), (lo_c[g.ib], hi_c[g.ib]) = g.plane_bbox()
            self._arc_pieces(seg, parts, [(lo_c, hi_c, None)])
            return
        c = g.centre
        assert c is not None
        u = (g.s[0] - c[0], g.s[1] - c[1])
        w = (g.e[0] - c[0], g.e[1] - c[1])
        bases = arc_bases(u, g.ccw)
        if g.full:
            cuts = bases + [u]
        else:
            cuts = [u] + [b for b in bases[1:] if b != w and in_sweep(u, w, b, g.ccw, False)] + [w]
        pieces = list(zip(cuts, cuts[1:]))
        self._arc_pieces(seg, parts, [(lo_c, hi_c, pc) for pc in pieces], g)

    def _arc_pieces(self, seg: Segment, parts: tuple[Part, ...], queue: list, g: Any = None) -> None:
        budget = ARC_PIECES
        while queue:
            lo_c, hi_c, piece = queue.pop()
            box_lo, box_hi = list(lo_c), list(hi_c)
            if piece is not None:  # the piece's own plane box (exact extremes)
                (box_lo[g.ia], box_hi[g.ia]), (box_lo[g.ib], box_hi[g.ib]) = self._piece_box(seg, g, piece)
            hit = self._box_hits(seg, parts, box_lo, box_hi)
            if hit is None:
                continue
            part, fx = hit
            ends = [seg.start, seg.end] if piece is None else [self._arc_point(seg, g, v) for v in piece]
            for pt in ends:  # an exact witness at a piece's end (a helix's interior points have irrational Z)
                self._arc_witness = True  # the parameter of an arc's point is its angle: not reported exactly
                try:
                    if pt is not None and self._line(seg, (part,), pt, pt, F0, F0):
                        return
                finally:
                    self._arc_witness = False
            if piece is None or budget <= 0:
                self._unknown(seg, "VF210", f"the arc passes close to `{fx.name}` with the {part.label()}: "
                              f"{'its pieces' if piece is not None else 'its enclosing box'} meet the fixture and "
                              "no point of it was found inside (a tangency, or the refinement budget is spent)")
                return
            budget -= 1
            halves = split_arc_piece(g, *piece)
            if halves is None:
                self._unknown(seg, "VF210", f"the arc passes close to `{fx.name}`: its piece could not be split")
                return
            queue += [(lo_c, hi_c, halves[0]), (lo_c, hi_c, halves[1])]

    def _piece_box(self, seg: Segment, g: Any, piece: tuple) -> tuple:
        c = g.centre
        a, b = piece
        start, end = list(seg.start), list(seg.end)
        start[g.ia], start[g.ib] = c[0] + a[0], c[1] + a[1]
        end[g.ia], end[g.ib] = c[0] + b[0], c[1] + b[1]
        sub = Segment(SegmentKind.ARC, tuple(start), tuple(end), seg.axes, plane=seg.plane, clockwise=seg.clockwise,
                      centre=c)
        return arc_geom(sub).plane_bbox()

    def _arc_point(self, seg: Segment, g: Any, v: tuple) -> tuple | None:
        """The exact path point at direction ``v`` from the centre: on a plane arc always, on a helix only at
        its start and end (elsewhere the height is irrational)."""
        c = g.centre
        p = list(seg.start)
        p[g.ia], p[g.ib] = c[0] + v[0], c[1] + v[1]
        if not g.helix:
            return tuple(p)
        for q in (seg.start, seg.end):
            if (q[g.ia], q[g.ib]) == (p[g.ia], p[g.ib]):
                return q
        return None

    def _box_hits(self, seg: Segment, parts: tuple[Part, ...], lo_c: list, hi_c: list) -> tuple | None:
        """The first part and fixture the box of controlled positions may bring together (None: none)."""
        bx, by, bz = (lo_c[self.ix], hi_c[self.ix]), (lo_c[self.iy], hi_c[self.iy]), (lo_c[self.iz], hi_c[self.iz])
        clear = []  # a clearance counts from a box that proves every pair (a refined box gives a tighter one)
        for part in parts:
            lo, hi = self._offsets(seg, part)
            for fx in self.solids.fixtures:
                f = self._where[part, fx][1]
                if (f.z1 is not None and bz[0] + lo >= f.z1) or (f.z0 is not None and bz[1] + hi <= f.z0):
                    continue
                gmin = _rect_gap2(f, bx, by)
                if gmin < _thr(f, part.radius):
                    return part, fx
                clear.append((part, fx, f, gmin))
        for part, fx, f, gmin in clear:
            self._clear(part, fx, f, gmin, seg)
        return None


def _row_segment(chunk: MotionChunk, base: int, k: int) -> Segment:
    """Row ``base + k`` of a column chunk as a segment."""
    return next(iter(chunk.rows(base + k, base + k + 1).segments()))


def _line_min(f: _Placed, r: Fraction, lo: Fraction, hi: Fraction, p: tuple, d: tuple
              ) -> tuple[Fraction, Fraction, _Span] | None:
    """Along ``p + d t`` (t in 0..1, the part's heights ``lo..hi`` above the controlled point): the span of
    ``t`` where the heights overlap the fixture's (None: never), and the least squared XY distance from the
    part's axis to the fixture's core over it with its ``t`` (exact: a convex piecewise quadratic for a
    rectangle, the distance of two segments for a polygon)."""
    px, py, pz = p
    dx, dy, dz = d
    span: _Span | None = _Span(F0, F1)
    if f.z1 is not None:  # pz + dz t + lo < z1
        span = span.above(f.z1 - pz - lo, -dz) if span else None
    if f.z0 is not None and span is not None:  # pz + dz t + hi > z0
        span = span.above(pz + hi - f.z0, dz)
    if span is None:
        return None
    if isinstance(f, _Prism):
        a0 = (px + dx * span.lo, py + dy * span.lo)
        a1 = (px + dx * span.hi, py + dy * span.hi)
        g, s = _path_poly(f.vertices, a0, a1)
        return g, span.lo + s * (span.hi - span.lo), span
    cuts = sorted({span.lo, span.hi, *(b for b in _breaks(f, px, dx, py, dy) if span.lo < b < span.hi)})
    best = min((_quad_min(_g_coef(f, px, dx, py, dy, (a + b) / 2), a, b) for a, b in zip(cuts, cuts[1:])),
               default=None)
    if best is None:  # a closed single point
        best = (_g(f, px + dx * span.lo, py + dy * span.lo), span.lo)
    return best[0], best[1], span


def _inside(f: _Placed, part: Part, span: _Span, t: Fraction, px: Fraction, dx: Fraction, py: Fraction,
            dy: Fraction) -> Fraction | None:
    """``t`` moved into the open span, keeping ``g < thr`` (g is continuous; bounded halving)."""
    if not ((t == span.lo and span.lo_open) or (t == span.hi and span.hi_open)):
        return t
    other = span.hi if t == span.lo else span.lo
    thr = _thr(f, part.radius)
    step = (other - t) / 2
    for _ in range(400):
        u = t + step
        if _g(f, px + dx * u, py + dy * u) < thr:
            return u
        step /= 2
    return None  # pragma: no cover - g is continuous at t and below thr there


def _outward(b: tuple[Fraction, Fraction], den: int = 1 << 16) -> tuple[Fraction, Fraction]:
    return Fraction(math.floor(b[0] * den), den), Fraction(math.ceil(b[1] * den), den)


def _rect_gap2(f: _Placed, bx: tuple[Fraction, Fraction], by: tuple[Fraction, Fraction]) -> Fraction:
    """Least squared XY distance between the rectangle ``bx × by`` and the fixture's core."""
    if isinstance(f, _Prism):  # the rectangle rounded outward to 2^-16 mm (an arc piece's box has large
        # denominators the segment distances would carry): a lower bound, all its callers need
        return _rect_poly_gap2(f.vertices, _outward(bx), _outward(by))
    gx = max(F0, (bx[0] - f.x1) if f.x1 is not None else F0, (f.x0 - bx[1]) if f.x0 is not None else F0)
    gy = max(F0, (by[0] - f.y1) if f.y1 is not None else F0, (f.y0 - by[1]) if f.y0 is not None else F0)
    return gx * gx + gy * gy


def prove_with_solids(motion: Iterable[Any], machine: Machine, solids: Solids, options: VerifyOptions,
                      verify_segments: Any, *, file: str = "", profile: Any = None) -> Result:
    """``verify_segments`` (:func:`nczones.prover.core.verify_segments`, passed in: this module sits below
    the driver) of ``motion`` (the controlled point against the zones) joined with the proof of the tool
    solids against the fixtures, fed the same motions as they pass."""
    from dataclasses import replace

    from ..exact import format_decimal
    from ..lathe_solids import LatheSolids
    from ..motion import segments_of
    from .lathe_solids import CLEARANCE_MEANING, LatheSolidsChecker
    from .result import Verdict

    lathe = isinstance(solids, LatheSolids)  # a lathe's turret tools (nczones.lathe_solids), not a zone kind
    ranges = options.ranges(machine)
    checker: Any = (LatheSolidsChecker(machine, solids, ranges) if isinstance(solids, LatheSolids)
                    else SolidsChecker(machine, solids, ranges, screen=None))
    meaning = CLEARANCE_MEANING if lathe else "horizontal distance while their heights overlap, a certified lower bound"

    def tee() -> Iterator[Any]:
        for item in motion:
            if isinstance(item, MotionChunk):
                checker.feed_chunk(item)
            else:
                for seg in segments_of(item):
                    checker.feed(seg)
            yield item

    result: Result = verify_segments(tee(), machine, margin=options.margin, params=options.ranges(machine),
                             engine=options.engine, max_violations=options.max_violations, file=file,
                             limits=options.run_limits(), profile=profile)
    checker.flush()
    violations = result.violations + tuple(checker.violations[:max(0, options.max_violations
                                                                  - len(result.violations))])
    reasons = result.reasons + tuple(checker.reasons)
    if solids.unmodelled:
        reasons += (Reason(f"forbidden zone{'s' if len(solids.unmodelled) > 1 else ''} "
                           f"{', '.join(f'`{n}`' for n in solids.unmodelled)} of a kind the tool solids are not "
                           "checked against (only boxes, stepped tables, XY polygons and [[fixtures]] are solids): the tip is proved, the holder "
                           "is not", None, None, "VF210"),)
    verdict = result.verdict
    if result.interrupted:
        pass
    elif violations:
        verdict = Verdict.UNSAFE
    elif reasons:
        verdict = Verdict.UNKNOWN
    notes = tuple(
        f"least clearance: {part} is at least {format_decimal(Fraction(math.floor(c * 1000), 1000))} mm from "
        f"`{fx}` at line {line} ({meaning})"
        for (part, fx), (c, line) in sorted(checker.clearance.items()) if c >= 0)
    extra = dict(result.extra)
    extra["solid_contacts"] = dict(checker.contacts)
    extra["clearance"] = tuple((part, fx, c, line) for (part, fx), (c, line) in sorted(checker.clearance.items()))
    return replace(result, verdict=verdict, violations=violations, reasons=reasons, notes=result.notes + notes,
                   extra=extra)


class SpindleToolCheck:
    """The tool solids take the ``[[tools]]`` entry numbered like the active tool length register (``G43 H<n>``,
    specs/machine-file.md "Which tool"), at that register's length.  Where the program's own ``M6`` (or ``M61``)
    has put another tool in the spindle while that register stays active (``T2 M6`` with no ``G43 H2`` after
    it, or ``T1 M6`` / ``G43 H2``), the machine moves tool T's solids at another tip height than the proof: the
    motion is ``unknown`` (``VF211``), never proved with the wrong tool.

    ``spindle_tools`` is the interpreter's live table of (first block, tool in the spindle); ``watch`` passes the
    motion through unchanged and looks at the segments only once the program has changed a tool."""

    def __init__(self, spindle_tools: list[tuple[int, int]]) -> None:
        self.table = spindle_tools
        self.reason: Reason | None = None

    @staticmethod
    def wanted(machine: Machine) -> bool:
        """Does ``machine`` have tool assemblies whose choice the check guards?"""
        from ..solids import machine_solids

        solids = machine_solids(machine)
        return solids is not None and bool(solids.tools) and bool(solids.fixtures)

    def watch(self, items: Iterable[Any]) -> Iterator[Any]:
        from ..motion import segments_of

        for item in items:
            if self.reason is None and self.table and not self._chunk_clear(item):
                for seg in segments_of(item):
                    if self._check(seg):
                        break
            yield item

    def _chunk_clear(self, item: Any) -> bool:
        """A column chunk whose recorded register is the tool in the spindle (or no tool) over all its blocks:
        :meth:`_check` is False for each of its rows, so they need not be made into segments."""
        from bisect import bisect_right

        if not isinstance(item, MotionChunk) or item.scale is None or not item.tools_known or not len(item):
            return False
        reg, blocks = item.tool_register, item.block
        if reg is None or blocks is None:
            return False
        lo = bisect_right(self.table, int(blocks[0]), key=lambda e: e[0]) - 1
        hi = bisect_right(self.table, int(blocks[-1]), key=lambda e: e[0])
        return all(tool in (0, reg) for _first, tool in self.table[max(lo, 0):hi])  # before the table: no tool

    def _check(self, seg: Segment) -> bool:
        from bisect import bisect_right

        from ..lathe_solids import turret_tool

        reg = seg.tool_register
        if reg is None or seg.derived.startswith("M6") or turret_tool(seg.extra) is not None:
            return False  # G49 is VF211 already; a tool change's own moves carry the old tool; a Fanuc turret's T
        k = bisect_right(self.table, seg.block, key=lambda e: e[0]) - 1
        tool = self.table[k][1] if k >= 0 else 0
        if tool in (0, reg):
            return False
        self.reason = Reason(f"tool {tool} is in the spindle (M6) while the active tool length is H{reg}: the tool "
                             f"solids are those of [[tools]] number {reg} at H{reg}'s length, not tool {tool}'s, so "
                             f"they were not proved for the tool the machine holds (give G43 H{tool} after the tool "
                             "change)", seg.span, seg.block, "VF211")
        return True

    def reasons(self) -> tuple[Reason, ...]:
        return () if self.reason is None else (self.reason,)
