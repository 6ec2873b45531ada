"""Proving motion made in polar coordinate interpolation (G12.1 / G112).

A polar move (``SegmentKind.POLAR``) is a line or an arc in the programmed
plane; the machine follows it with X = ``x_off + |p|`` and C = ``c_entry +``
the unwound angle of ``p`` (:mod:`nczones.geometry.polar`).  Square roots and arc
tangents of rationals are irrational, so the move is decided by sound
enclosure and refinement (DESIGN §5), as developed arcs are:

1. The path is cut into pieces (a line whole, an arc in quarters; then
   halves of halves).  Each piece's plane path is enclosed in a rational box
   (:meth:`PolarMove.box`); if the box does not contain the centre of
   rotation, the piece's machine X lies in ``x_off +`` the box's distance
   range and its machine C in ``c_entry +`` the box's angle range (corner
   angles, unwound near the angle already followed to the piece's start),
   both widened by one least increment of the axis (the control ends each
   move on its increment grid).  Other axes move linearly with the path
   parameter.  A machine box that fits every zone with the margin
   (:func:`nczones.prover.exact.box_fits`, exact) proves the piece.
2. For a piece that does not fit, the exact path point at the piece's middle
   is enclosed in a machine box of width about 1e-50; if every point of it
   violates a zone (:func:`nczones.prover.exact.box_certainly_violates`),
   the exact point does: the counterexample, reported at a short decimal
   point inside the box and re-checked with ``AllowedSet.violated_zones``.
3. Otherwise (or when the box contains the centre) the piece is halved, up
   to :data:`MAX_DEPTH` levels and :data:`BUDGET` enclosures per move; then
   ``unknown`` with the reason.

Invariants: ``safe`` for a move only when every piece's machine box fits
(the boxes contain the exact path and its rounded ends); a violation only at
a point whose enclosure lies wholly outside.  Parameter ranges on a polar
move give ``unknown``.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..exact import Interval, format_decimal
from ..geometry.polar import (
    CentreCrossing,
    PolarMove,
    angle_range,
    point_angle,
    polar_move_of,
    polar_of,
    radius_range,
)
from ..motion import Segment
from . import exact as ex
from .enclosed import box_depth, certify_box, enclosed_violation
from .result import Outcome, Reason, Violation

__all__ = ["check_polar", "polar_note", "MAX_DEPTH", "BUDGET"]

#: Deepest halving of a first piece (pieces of 1/4 / 2**MAX_DEPTH of an arc's sweep).
MAX_DEPTH = 40
#: Most piece enclosures per polar move before ``unknown``.
BUDGET = 2000
F0 = Fraction(0)


def _dec(x: Fraction) -> str:
    return format_decimal(x, places=6)


def polar_note(seg: Segment, f: Fraction) -> str:
    """The counterexample in the programmed plane: the plane point at fraction ``f``."""
    try:
        move = polar_move_of(seg)
    except ValueError:
        return ""
    x, y = move.point(f)
    return (f"in the polar interpolation plane (G12.1): X={_dec(x.mid())} mm (radius), C={_dec(y.mid())} mm "
            "(hypothetical axis); machine X = centre + sqrt(X^2 + C^2), machine C = entry angle + atan2(C, X)")


def check_polar(prover: Any, seg: Segment) -> Any:
    """Decide one ``SegmentKind.POLAR`` segment (called by :meth:`Prover.check`)."""
    if prover.param_relevant(seg):
        return Outcome(reason=Reason("parameter ranges are not supported on motion in polar coordinate "
                                      "interpolation (G12.1)", seg.span, seg.block), engine="unknown")
    try:
        move = polar_move_of(seg)
    except ValueError as exc:
        return Outcome(reason=Reason(f"polar move cannot be modelled: {exc}", seg.span, seg.block), engine="unknown")
    return _PolarCheck(prover, seg, move).run()


class _PolarCheck:
    def __init__(self, prover: Any, seg: Segment, move: PolarMove):
        self.p = prover
        self.seg = seg
        self.move = move
        e = polar_of(seg)
        assert e is not None  # polar_move_of(seg) succeeded
        self.ix = seg.axes.index(e.linear_axis)
        self.ic = seg.axes.index(e.rotary_axis)
        gx, gc = e.grid
        self.gx, self.gc = Fraction(gx), Fraction(gc)
        self.theta: dict[Fraction, Interval] = {F0: move.start_angle()}
        self.used = 0

    def _other(self, f: Fraction) -> list[Fraction]:
        s, e = self.seg.start, self.seg.end
        return [a + (b - a) * f for a, b in zip(s, e)]

    def _dicts(self, x: Interval, c: Interval, fa: Fraction, fb: Fraction) -> tuple[dict, dict]:
        a, b = self._other(fa), self._other(fb)
        lo = {n: min(u, v) for n, u, v in zip(self.seg.axes, a, b)}
        hi = {n: max(u, v) for n, u, v in zip(self.seg.axes, a, b)}
        xa, ca = self.seg.axes[self.ix], self.seg.axes[self.ic]
        lo[xa], hi[xa] = x.lo, x.hi
        lo[ca], hi[ca] = c.lo, c.hi
        return lo, hi

    def _machine(self, bx: Interval, by: Interval, near: Fraction) -> tuple[Interval, Interval] | None:
        ang = angle_range(bx, by, near)
        if ang is None:
            return None
        r = radius_range(bx, by)
        return self.move.x_off + r, self.move.c_entry + ang

    def run(self) -> Outcome:
        p, seg, move = self.p, self.seg, self.move
        p.stats["pieces"] += 1
        stack = [(fa, fb, 0) for fa, fb in reversed(move.first_pieces())]
        why = "its enclosure meets a zone boundary and no point of the exact path was certified outside"
        while stack:
            fa, fb, depth = stack.pop()
            self.used += 1
            if self.used > BUDGET:
                break
            p.checkpoint()
            bx, by = move.box(fa, fb)
            near = self.theta[fa].mid()
            got = self._machine(bx, by, near)
            if got is not None:
                x, c = got
                lo, hi = self._dicts(x.widen(self.gx), c.widen(self.gc), fa, fb)
                if ex.box_fits(p.allowed, lo, hi, p.margin, seg.tool_length):
                    try:
                        self.theta[fb] = point_angle(move.point(fb), near)
                    except CentreCrossing:
                        why = "a path point lies within the enclosure resolution of the centre of rotation"
                        break
                    continue
                v = self._certify((fa + fb) / 2, near)
                if v is not None:
                    return Outcome(v, engine="exact")
            if depth >= MAX_DEPTH:
                if got is None:
                    why = "the path passes within a tiny distance of the centre of rotation, where C turns fast"
                break
            mid = (fa + fb) / 2
            stack.append((mid, fb, depth + 1))
            stack.append((fa, mid, depth + 1))
        else:
            p.stats["screened"] += 1
            return Outcome(engine="exact")
        return Outcome(reason=Reason(
            f"motion in polar coordinate interpolation (G12.1): {why} after {self.used - 1} refinements (square "
            "roots and arc tangents are enclosed; the path may touch the boundary)", seg.span, seg.block),
            engine="unknown")

    def _point_box(self, f: Fraction, near: Fraction) -> tuple[dict, dict, Fraction] | None:
        pt = self.move.point(f)
        got = self._machine(pt[0], pt[1], near)
        if got is None:
            return None
        x, c = got
        lo, hi = self._dicts(x, c, f, f)
        return lo, hi, max(x.width(), c.width())

    def _certify(self, f: Fraction, near: Fraction) -> Violation | None:
        p, seg = self.p, self.seg
        got = self._point_box(f, near)
        if got is None:
            return None
        lo, hi, width = got
        hit = certify_box(p, seg, lo, hi)
        if hit is None:
            return None
        mid, bad = hit
        depth = F0  # a lower bound: the points already followed along the path
        for g, th in sorted(self.theta.items()):
            pb = self._point_box(g, th.mid())
            if pb is not None:
                depth = max(depth, box_depth(p, seg, pb[0], pb[1], pb[2]))
        note = (f"irrational path point (square root, arc tangent); reported point within {float(width):.1e} of "
                f"it, the whole enclosure violates; {polar_note(seg, f)}")
        return enclosed_violation(p, seg, f, mid, bad, width, depth, "polar", note)
