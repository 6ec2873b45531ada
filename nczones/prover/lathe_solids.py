"""The proof that a lathe's turret tool stays out of its fixtures (issue 39, the lathe case).

The model is :mod:`nczones.lathe_solids`: in the section through the spindle axis a tool part is a rectangle
``[a, b] × [c, d]`` relative to the tool tip and a fixture (a solid of revolution) one or two open
rectangles ``(f0, f1) × (g0, g1)``.  The tip is the controlled point minus the tool offsets (``tip_offset``
in X, the tool length on the tool axis Z), so at the controlled position ``(X, Z)`` the part meets a fixture
rectangle exactly when

    ``f0 - b + sx < X < f1 - a + sx``  and  ``g0 - d + sz < Z < g1 - c + sz``

(the Minkowski sum of the fixture with the reflected part: an open rectangle ``Q`` of controlled
positions; ``sx``, ``sz`` the tip's offsets).  Along a straight piece ``p(t)``, ``t ∈ [0, 1]``, the set of
``t`` in ``Q`` is an open interval (each side a linear inequality), so the piece violates iff that interval
meets ``[0, 1]``, and the middle of the overlap is a rational witness strictly inside: exact.  The least
clearance is the least distance from the path to ``Q``'s closure (a convex piecewise quadratic in ``t``,
minimised exactly, square root rounded down): the distance between the part's and the fixture's sections,
a lower bound of their distance in space (radial distances do not exceed distances).

Arcs (G2/G3 in the ZX plane) are enclosed piece by piece as in :mod:`nczones.prover.solids`: the sweep is cut
at quarter turns, a piece whose exact box misses every ``Q`` is proved, an undecided piece is tried at its
ends (exact points of the circle) and halved, at most :data:`ARC_PIECES` times; what remains is
``unknown`` (VF210).  A motion with no known turret tool is ``unknown`` (VF211); a motion of an axis other
than X, Z and C (the spindle angle: the fixtures are solids of revolution, C turns them into themselves)
is ``unknown`` (VF210).

Parameter ranges (``--param``) and the tool-break recovery's families of legs move the tool against the
fixtures by a displacement box ``D`` (X, Z; :meth:`LatheSolidsChecker._displacement`, as a mill's tool part in
:mod:`nczones.prover.solids`): the part at ``p + d`` is in a fixture iff ``p`` is in ``Q - d``, so over ``D``
the open rectangle ``Q`` is grown by ``D`` into another open rectangle, and the proof above decides it as
exactly.  A motion only the grown rectangle meets is ``unknown`` (VF218); one the nominal rectangle meets has
its witness at the nominal values.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from ..exact import format_decimal
from ..lathe_solids import LatheFixture, LathePart, LatheSolids, turret_tool
from ..machine import Machine
from ..motion import MotionChunk, Segment, SegmentKind, tip_offset
from .geometry import (
    arc_bases,
    arc_geom,
    in_sweep,
    line_pieces,
    split_arc_piece,
    sqrt_bounds,
)
from .result import Reason, Violation
from .solids_ranges import UNTRACKED, axis_displacement, untracked

__all__ = ["LatheSolidsChecker", "ARC_PIECES", "CLEARANCE_MEANING", "segment_tool", "tip_shift"]

F0 = Fraction(0)
F1 = Fraction(1)
ARC_PIECES = 64
#: How the least clearance of a lathe reads in the result's notes.
CLEARANCE_MEANING = ("distance in the section through the spindle axis, a certified lower bound of the distance "
                     "in space")

Bound = Fraction | None
#: An open rectangle of controlled positions (X low, X high, Z low, Z high; None: unbounded).
Rect = tuple[Bound, Bound, Bound, Bound]
#: A displacement box of the tool against the fixtures ((X lo, X hi), (Z lo, Z hi)); None: none.
Move = tuple[tuple[Fraction, Fraction], tuple[Fraction, Fraction]] | None


def _add(v: Bound, d: Fraction) -> Bound:
    return None if v is None else v + d


def _grow(rect: Rect, move: tuple[tuple[Fraction, Fraction], tuple[Fraction, Fraction]]) -> Rect:
    """The controlled positions from which some displacement ``d`` of the box ``move`` brings the part into
    the fixture: ``p + d`` in the open rectangle ``Q`` for some ``d`` iff ``p`` is in ``Q`` less the box, an open
    rectangle again (exact)."""
    (xl, xh), (zl, zh) = move
    return _add(rect[0], -xh), _add(rect[1], -xl), _add(rect[2], -zh), _add(rect[3], -zl)


def _open_span(rect: Rect, p: tuple[Fraction, Fraction], d: tuple[Fraction, Fraction]) -> Fraction | None:
    """``t`` in ``[0, 1]`` strictly inside ``rect`` along ``p + d t``: a rational ``t`` in the middle of the
    overlap, or None when the piece stays out of the open rectangle."""
    lo: Fraction | None = None
    hi: Fraction | None = None
    for (q0, q1), pk, dk in (((rect[0], rect[1]), p[0], d[0]), ((rect[2], rect[3]), p[1], d[1])):
        for q, sign in ((q0, 1), (q1, -1)):
            if q is None:
                continue
            # sign * (pk + dk t - q) > 0
            a, b = sign * (pk - q), sign * dk
            if b == 0:
                if a <= 0:
                    return None
                continue
            c = -a / b
            if b > 0:
                lo = c if lo is None else max(lo, c)
            else:
                hi = c if hi is None else min(hi, c)
    t0 = F0 if lo is None else max(lo, F0)
    t1 = F1 if hi is None else min(hi, F1)
    if (lo is not None and lo >= 1) or (hi is not None and hi <= 0) or (lo is not None and hi is not None
                                                                        and lo >= hi):
        return None
    return (t0 + t1) / 2  # strictly inside the open interval (lo, hi) and in [0, 1]


def _gap(v: Fraction, q0: Bound, q1: Bound) -> Fraction:
    if q0 is not None and v < q0:
        return q0 - v
    if q1 is not None and v > q1:
        return v - q1
    return F0


def _dist2_min(rect: Rect, p: tuple[Fraction, Fraction], d: tuple[Fraction, Fraction]) -> Fraction:
    """The least squared distance from ``p + d t`` (``t ∈ [0, 1]``) to the closed rectangle: convex and
    quadratic between the ``t`` where a coordinate crosses a side, minimised exactly on each piece."""
    cuts = {F0, F1}
    for (q0, q1), pk, dk in (((rect[0], rect[1]), p[0], d[0]), ((rect[2], rect[3]), p[1], d[1])):
        if dk != 0:
            cuts.update(t for t in ((q - pk) / dk for q in (q0, q1) if q is not None) if 0 < t < 1)
    ts = sorted(cuts)
    best: Fraction | None = None
    for a, b in zip(ts, ts[1:]):
        m = (a + b) / 2
        q2 = q1_ = q0_ = F0
        for (r0, r1), pk, dk in (((rect[0], rect[1]), p[0], d[0]), ((rect[2], rect[3]), p[1], d[1])):
            v = pk + dk * m
            if r0 is not None and v < r0:
                c0, c1 = r0 - pk, -dk
            elif r1 is not None and v > r1:
                c0, c1 = pk - r1, dk
            else:
                continue
            q2, q1_, q0_ = q2 + c1 * c1, q1_ + 2 * c0 * c1, q0_ + c0 * c0
        cands = [a, b]
        if q2 > 0 and a < -q1_ / (2 * q2) < b:
            cands.append(-q1_ / (2 * q2))
        val = min((q2 * t + q1_) * t + q0_ for t in cands)
        best = val if best is None else min(best, val)
    if best is None:  # a single point
        gx, gz = _gap(p[0], rect[0], rect[1]), _gap(p[1], rect[2], rect[3])
        best = gx * gx + gz * gz
    return best


def _box_dist2(rect: Rect, bx: tuple[Fraction, Fraction], bz: tuple[Fraction, Fraction]) -> Fraction:
    """The least squared distance between the closed box ``bx × bz`` and the closed rectangle."""
    gx = max(F0, (rect[0] - bx[1]) if rect[0] is not None else F0, (bx[0] - rect[1]) if rect[1] is not None else F0)
    gz = max(F0, (rect[2] - bz[1]) if rect[2] is not None else F0, (bz[0] - rect[3]) if rect[3] is not None else F0)
    return gx * gx + gz * gz


def segment_tool(seg: Segment) -> int | None:
    """The turret tool a motion runs with: its :class:`~nczones.motion.TurretTool`, else its tool register."""
    tool = turret_tool(seg.extra) if seg.extra else None
    return seg.tool_register if tool is None else tool


def tip_shift(seg: Segment, tool_axis: str | None) -> tuple[Fraction, Fraction]:
    """The controlled point minus the tool tip, on X and Z (the tool length on the tool axis, the motion's
    tip offset on the other)."""
    off = tip_offset(seg.extra) if seg.extra else {}
    sx = seg.tool_length if tool_axis == "X" else off.get("X", F0)
    sz = seg.tool_length if tool_axis == "Z" else off.get("Z", F0)
    return sx, sz


@dataclass
class LatheSolidsChecker:
    """Fed every motion in execution order; collects violations, reasons and least clearances (the
    interface of :class:`nczones.prover.solids.SolidsChecker`)."""

    machine: Machine
    solids: LatheSolids
    #: the parameter ranges of the case (:class:`~nczones.prover.result.ParamRange`, deviations from the values
    #: the motion was built at): every rectangle is grown by the displacement they allow (:meth:`_displacement`)
    ranges: tuple[Any, ...] = ()
    #: a displacement box (X lo..hi, Z lo..hi, containing 0) added to every motion's: the tool-break recovery
    #: proves a family of legs as one leg displaced within it (:mod:`.solids_recovery`)
    shift: tuple[tuple[Fraction, Fraction], ...] | None = None
    violations: list[Violation] = field(default_factory=list)
    reasons: list[Reason] = field(default_factory=list)
    #: (part label, fixture name) -> (least clearance lower bound, line)
    clearance: dict[tuple[str, str], tuple[Fraction, int | None]] = field(default_factory=dict)
    #: block -> (the turret tool's parts, the tip shift (X, Z), the part that enters, the fixture) at a
    #: contact, for the report's drawing of the tool (:mod:`nczones.report.solids_view`)
    contacts: dict[int, tuple[tuple[LathePart, ...], tuple[Fraction, Fraction], LathePart, LatheFixture]] = field(
        default_factory=dict)
    _blocks: set[int] = field(default_factory=set)
    _pairs: dict[tuple, list] = field(default_factory=dict)
    #: id of a rectangle of :attr:`_pairs` -> (the clearance it was grown by, the grown bounds)
    _grown: dict[int, tuple] = field(default_factory=dict)

    def __post_init__(self) -> None:
        axes = self.machine.axis_names
        self.ix, self.iz = axes.index("X"), axes.index("Z")
        self.tool_axis = self.machine.tool_axis
        self._dev = {r.name: (r.lo, r.hi) for r in self.ranges}
        self._moves: dict[tuple, Any] = {}

    # ------------------------------------------------------------------ which rectangles
    def _tip_shift(self, seg: Segment) -> tuple[Fraction, Fraction]:
        """The controlled point minus the tool tip, on X and Z."""
        return tip_shift(seg, self.tool_axis)

    def _rects(self, parts: tuple[LathePart, ...], shift: tuple[Fraction, Fraction], move: Move = None) -> list:
        """``(part, fixture, rect, key, nominal)`` for every part, fixture and section rectangle: ``nominal`` the
        open rectangle of controlled positions where the part enters the fixture (module docstring), ``rect``
        that rectangle grown by the displacement box ``move`` (the same object without one); ``key`` names the
        pair in :attr:`clearance`.  Kept (bounded) while the checker lives: :meth:`_apart` keys on them."""
        key = (parts, shift, move)
        out = self._pairs.get(key)
        if out is None:
            if len(self._pairs) > 4096:  # memory stays bounded whatever the program
                self._pairs.clear()
                self._grown.clear()
            out = []
            sx, sz = shift
            for part in parts:
                a, b, c, d = part.rect()
                label = part.label()
                for fx in self.solids.fixtures:
                    for f0, f1 in fx.sections():
                        rect = (_add(f0, sx - b), _add(f1, sx - a), _add(fx.z0, sz - d), _add(fx.z1, sz - c))
                        out.append((part, fx, rect if move is None else _grow(rect, move), (label, fx.name), rect))
            self._pairs[key] = out
        return out

    def _displacement(self, seg: Segment) -> Move | str:
        """The box (X lo..hi, Z lo..hi) the ranges (and :attr:`shift`) move the tool's parts by against the
        fixtures at ``seg``, None when it is the point 0, or the reason it is not known.  The coordinate's
        sources (``Segment.deps_start``/``deps_end``, their hull along the motion) less the tool length's on
        the tool axis (the tip is the controlled point minus the length), plus a homing error (the fixtures are
        on the machine: they do not move with it), as :meth:`nczones.prover.solids.SolidsChecker._displacement`
        for a mill's tool part."""
        if not self._dev and self.shift is None:
            return None
        key = (seg.deps_start, seg.deps_end, seg.deps_tool)
        got = self._moves.get(key)
        if got is None:
            if len(self._moves) > 4096:
                self._moves.clear()
            got = self._moves[key] = self._move(seg)
        return got

    def _move(self, seg: Segment) -> Move | str:
        if self._dev and untracked(self.ranges, seg):
            return UNTRACKED
        out = []
        for n, (a, i) in enumerate((("X", self.ix), ("Z", self.iz))):
            lo, hi = axis_displacement(seg, self._dev, a, i, less_tool=a == self.tool_axis)
            if self.shift is not None:
                lo, hi = lo + self.shift[n][0], hi + self.shift[n][1]
            out.append((lo, hi))
        return None if all(lo == hi == 0 for lo, hi in out) else (out[0], out[1])

    # ------------------------------------------------------------------ feeding
    def feed_chunk(self, chunk: MotionChunk) -> None:
        """A column chunk of the vectorized fast path, row by row (its segments carry the chunk's tool
        register when it recorded one; otherwise the register is unknown and the motion is ``VF211``)."""
        for seg in chunk.segments():
            self.feed(seg)

    def flush(self) -> None:
        """Nothing is batched on a lathe: every motion is proved as it is fed."""

    def feed(self, seg: Segment) -> None:
        if seg.block in self._blocks or not self.solids.fixtures:
            return
        tool = segment_tool(seg)
        if tool is None:
            self._unknown(seg, "VF211", "no turret tool is known (no T word yet, or G49): which tool's solids move "
                          "with the turret is not known, so they were not checked against the fixtures")
            return
        parts = self.solids.tools.get(tool, ())
        if not parts:
            return  # a tool without [[tools]] parts: nothing described to check (specs/turning.md)
        moved = [a for k, a in enumerate(seg.axes) if a not in "XZC" and seg.start[k] != seg.end[k]]
        if moved:
            self._unknown(seg, "VF210", f"the motion moves {', '.join(moved)}: a lathe's tool solids are modelled "
                          "on a machine moving X and Z (and C) only")
            return
        move = self._displacement(seg)
        if isinstance(move, str):
            self._unknown(seg, "VF218", move)
            return
        rects = self._rects(parts, self._tip_shift(seg), move)
        if seg.kind is SegmentKind.ARC:
            self._arc(seg, rects)
        elif seg.kind in (SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.DWELL):
            for piece in line_pieces(seg, self.machine):
                if self._line(seg, rects, piece.p0, piece.p1, piece.tau0, piece.tau1):
                    return
        else:
            self._unknown(seg, "VF210", f"the tool solids along a {seg.kind.name.lower()} motion are not modelled")

    def _unknown(self, seg: Segment, code: str, message: str) -> None:
        self._blocks.add(seg.block)
        self.reasons.append(Reason(message, seg.span, seg.block, code))

    def _clear(self, key: tuple[str, str], d2: Fraction, seg: Segment) -> None:
        best = self.clearance.get(key)
        if best is not None and d2 >= best[0] * best[0]:
            return
        c = sqrt_bounds(d2, 64)[0]
        if best is None or c < best[0]:
            self.clearance[key] = (c, seg.line)

    def _apart(self, rect: Rect, c: Fraction, bx: tuple[Fraction, Fraction], bz: tuple[Fraction, Fraction]) -> bool:
        """Is the box ``bx × bz`` at least ``c`` (>= 0) from ``rect`` on X or on Z?  Then no point of it is in
        the open rectangle (it touches at most) and none is nearer than ``c``: comparisons with the rectangle
        grown by ``c``, kept until ``c`` changes."""
        grown = self._grown.get(id(rect))
        if grown is None or grown[0] is not c:
            grown = (c, _add(rect[0], -c), _add(rect[1], c), _add(rect[2], -c), _add(rect[3], c))
            self._grown[id(rect)] = grown
        _, e0, e1, e2, e3 = grown
        return ((e0 is not None and bx[1] <= e0) or (e1 is not None and bx[0] >= e1)
                or (e2 is not None and bz[1] <= e2) or (e3 is not None and bz[0] >= e3))

    def _line(self, seg: Segment, rects: list, p0: tuple, p1: tuple, tau0: Fraction, tau1: Fraction) -> bool:
        p = (p0[self.ix], p0[self.iz])
        d = (p1[self.ix] - p[0], p1[self.iz] - p[1])
        bx, bz = (min(p[0], p[0] + d[0]), max(p[0], p[0] + d[0])), (min(p[1], p[1] + d[1]), max(p[1], p[1] + d[1]))
        maybe = None  # a pair only the ranges may bring together: unknown, unless another one is a witness
        for part, fx, rect, key, nominal in rects:
            best = self.clearance.get(key)
            if best is not None and self._apart(rect, best[0], bx, bz):
                continue  # cannot enter the fixture nor come closer than the least clearance so far
            t = _open_span(rect, p, d)
            if t is None:  # over the ranges: a lower bound of the clearance at every value
                self._clear(key, _dist2_min(rect, p, d), seg)
                continue
            self.clearance[key] = (F0, seg.line)
            if rect is not nominal:
                t = _open_span(nominal, p, d)
                if t is None:
                    maybe = maybe or (part, fx)
                    continue
            path = tuple(a + t * (b - a) for a, b in zip(p0, p1))
            self._report(seg, part, fx, nominal, path, tau0 + t * (tau1 - tau0), exact=True)
            return True
        if maybe is not None:
            self._unknown(seg, "VF218", f"the {maybe[0].label()} may enter `{maybe[1].name}` for some values of the "
                          "parameter ranges (not at their nominal values): the ranges move it that far")
            return True
        return False

    def _report(self, seg: Segment, part: LathePart, fx: LatheFixture, rect: Rect, path: tuple, tau: Fraction,
                *, exact: bool) -> None:
        x, z = path[self.ix], path[self.iz]
        sx, sz = self._tip_shift(seg)
        a, b, c, d = part.rect()
        # the Minkowski rectangle was built from one section rectangle of the fixture: recover it
        f0, f1 = _add(rect[0], b - sx), _add(rect[1], a - sx)
        g0, g1 = _add(rect[2], d - sz), _add(rect[3], c - sz)
        px0, px1, pz0, pz1 = x - sx + a, x - sx + b, z - sz + c, z - sz + d
        lo_x, hi_x = px0 if f0 is None else max(px0, f0), px1 if f1 is None else min(px1, f1)
        lo_z, hi_z = pz0 if g0 is None else max(pz0, g0), pz1 if g1 is None else min(pz1, g1)
        cx, cz = (lo_x + hi_x) / 2, (lo_z + hi_z) / 2  # inside the part and strictly inside the fixture
        depth = min(v for v in (x - rect[0] if rect[0] is not None else None,
                                rect[1] - x if rect[1] is not None else None,
                                z - rect[2] if rect[2] is not None else None,
                                rect[3] - z if rect[3] is not None else None) if v is not None)
        where = f"line {seg.line}" if seg.line is not None else f"block {seg.block}"
        note = (f"{part.label()} enters `{fx.name}` at {where}, X{format_decimal(x, 4)} Z{format_decimal(z, 4)}, "
                f"{format_decimal(depth, 3)} mm deep (contact point X{format_decimal(cx, 4)} Y0 "
                f"Z{format_decimal(cz, 4)}, in the section through the spindle axis)")
        axes = self.machine.axis_names
        self._blocks.add(seg.block)
        tool = segment_tool(seg)
        self.contacts[seg.block] = (self.solids.tools.get(tool, (part,)) if tool is not None else (part,),
                                    (sx, sz), part, fx)
        pp = tuple(zip(axes, path))
        self.violations.append(Violation(
            block=seg.block, span=seg.span, zone=fx.name, point=(("X", cx), ("Z", cz)), path_point=pp,
            parameter=tau, parameter_exact=exact, first_exit=pp, first_exit_parameter=tau, first_exit_exact=False,
            depth=depth, depth_exact=False, engine="exact", segment_kind=seg.kind.name.lower(),
            derived=seg.derived, kind="solid", zones=(part.name,), note=note, exit_located=False, frame=seg.frame))

    # ------------------------------------------------------------------ arcs
    def _arc(self, seg: Segment, rects: list) -> None:
        try:
            g = arc_geom(seg)
        except Exception:  # noqa: BLE001 - an arc outside the ZX plane: not modelled, never silently safe
            self._unknown(seg, "VF210", "an arc outside the ZX plane: a lathe's tool solids are not modelled on it")
            return
        if {g.ia, g.ib} != {self.ix, self.iz} or g.helix or not g.exact:
            self._arc_pieces(seg, rects, [None], g)  # the whole arc's box; undecided: unknown
            return
        c = g.centre
        assert c is not None
        u = (g.s[0] - c[0], g.s[1] - c[1])
        w = (g.e[0] - c[0], g.e[1] - c[1])
        bases = arc_bases(u, g.ccw)
        if g.full:
            cuts = bases + [u]
        else:
            cuts = [u] + [v for v in bases[1:] if v != w and in_sweep(u, w, v, g.ccw, False)] + [w]
        self._arc_pieces(seg, rects, list(zip(cuts, cuts[1:])), g)

    def _piece_box(self, seg: Segment, g: Any, piece: tuple | None) -> tuple:
        """The box of the controlled point over an arc piece (None: the whole arc) on X and Z."""
        lo, hi = [min(s, e) for s, e in zip(seg.start, seg.end)], [max(s, e) for s, e in zip(seg.start, seg.end)]
        if piece is None:
            (lo[g.ia], hi[g.ia]), (lo[g.ib], hi[g.ib]) = g.plane_bbox()
        else:
            a, b = piece
            start, end = list(seg.start), list(seg.end)
            start[g.ia], start[g.ib] = g.centre[0] + a[0], g.centre[1] + a[1]
            end[g.ia], end[g.ib] = g.centre[0] + b[0], g.centre[1] + b[1]
            sub = Segment(SegmentKind.ARC, tuple(start), tuple(end), seg.axes, plane=seg.plane,
                          clockwise=seg.clockwise, centre=g.centre)
            (lo[g.ia], hi[g.ia]), (lo[g.ib], hi[g.ib]) = arc_geom(sub).plane_bbox()
        return (lo[self.ix], hi[self.ix]), (lo[self.iz], hi[self.iz])

    def _arc_pieces(self, seg: Segment, rects: list, queue: list, g: Any) -> None:
        budget = ARC_PIECES
        while queue:
            piece = queue.pop()
            bx, bz = self._piece_box(seg, g, piece)
            hit = None
            clear = []
            for entry in rects:
                if _meets_open(entry[2], bx, bz):
                    hit = entry
                    break
                clear.append((entry[3], _box_dist2(entry[2], bx, bz)))
            if hit is None:  # a clearance counts from a piece that proves every pair
                for key, d2 in clear:
                    self._clear(key, d2, seg)
                continue
            part, fx = hit[0], hit[1]
            if piece is not None:
                for v in piece:  # an exact witness at a piece's end (a rational point of the circle)
                    pt = list(seg.start)
                    pt[g.ia], pt[g.ib] = g.centre[0] + v[0], g.centre[1] + v[1]
                    found = len(self.violations)
                    if self._line(seg, [hit], tuple(pt), tuple(pt), F0, F0):
                        if len(self.violations) > found:
                            self.violations[-1] = _inexact(self.violations[-1])
                        return
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
            queue += list(halves)


def _meets_open(rect: Rect, bx: tuple[Fraction, Fraction], bz: tuple[Fraction, Fraction]) -> bool:
    """Does the closed box ``bx × bz`` meet the open rectangle?"""
    return ((rect[0] is None or bx[1] > rect[0]) and (rect[1] is None or bx[0] < rect[1])
            and (rect[2] is None or bz[1] > rect[2]) and (rect[3] is None or bz[0] < rect[3]))


def _inexact(v: Violation) -> Violation:
    """An arc's witness: its parameter is an angle, not reported exactly."""
    from dataclasses import replace

    return replace(v, parameter_exact=False)
