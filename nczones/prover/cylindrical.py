"""Proving motion made in cylindrical interpolation (G07.1).

Lines of the mode are exact LINE segments in machine coordinates and are
proved like any other line; their counterexamples get a note with the
developed coordinate.  Developed arcs (``SegmentKind.DEVELOPED_ARC``) are
circles in the (Z, s) plane with ``s = pi R C / 180``: not polynomial in
rationals because of pi, so they are decided by sound enclosure and
refinement (DESIGN §5):

1. The swept angle is cut into pieces (quarters, then halves of halves).
   Each piece's path is enclosed in a rational box (:meth:`DevelopedArc.box`:
   its end points' enclosures grown by the sagitta bound; C from s through
   the enclosure of pi).  A box that fits every zone with the margin
   (:func:`nczones.prover.exact.box_fits`, exact) proves the piece.
2. For a piece that does not fit, the exact path point at the piece's middle
   is enclosed in a box of width about 1e-50; if every point of that box
   violates a zone (:func:`nczones.prover.exact.box_certainly_violates`), the
   exact path point does: a counterexample, reported at a short decimal
   point inside the box (re-checked with ``AllowedSet.violated_zones``).
3. Otherwise the piece is halved, up to :data:`MAX_DEPTH` levels and
   :data:`BUDGET` enclosures per arc; then ``unknown`` with the reason.

Invariants: ``safe`` for an arc only when every piece's box fits (the boxes
contain the exact path); a violation only at a point whose enclosure lies
wholly outside.  Parameter ranges on a developed arc give ``unknown``.
Polygon allow zones cannot be screened by boxes (``unknown``).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..exact import Interval, format_decimal, round_up_scaled
from ..geometry.cylinder import DevelopedArc, cylinder_of, degree_length, developed_arc_of
from ..motion import Segment, SegmentKind
from . import exact as ex
from .enclosed import box_depth, certify_box, enclosed_violation
from .result import Outcome, Reason, Violation

__all__ = ["check_cylindrical", "developed_note", "MAX_DEPTH", "BUDGET"]

#: Deepest halving of a quarter of the sweep (pieces of 1/4 / 2**MAX_DEPTH).
MAX_DEPTH = 18
#: Most piece enclosures per developed arc before ``unknown``.
BUDGET = 600
F0 = Fraction(0)


def _dec(x: Fraction) -> str:
    return format_decimal(x, places=6)


def developed_note(seg: Segment, point: dict[str, Fraction]) -> str:
    """The counterexample on the developed surface: ``s = pi R C / 180`` from C = 0 (mm)."""
    info = cylinder_of(seg)
    if info is None:
        return ""
    lin, rot, rc = info
    k = degree_length(rc)
    s = k * point[rot]
    return (f"on the developed surface (cylinder radius {_dec(rc)} mm): {lin}={_dec(point[lin])} mm, "
            f"s={_dec(s.mid())} mm (= pi*R*{rot}/180, {rot}={_dec(point[rot])} deg)")


def check_cylindrical(prover: Any, seg: Segment) -> Any:
    """Decide one segment made in G07.1 mode (called by :meth:`Prover.check`)."""
    from dataclasses import replace

    if seg.kind is not SegmentKind.DEVELOPED_ARC:
        out = prover.check_with_params(seg) if prover.param_relevant(seg) else prover.check_concrete(seg, ())
        if out.violation is not None:
            note = developed_note(seg, dict(out.violation.path_point))
            v = out.violation
            out.violation = replace(v, note=(v.note + "; " if v.note else "") + note)
        return out
    if prover.param_relevant(seg):
        return Outcome(reason=Reason("parameter ranges are not supported on arcs in cylindrical interpolation "
                                      "(G07.1)", seg.span, seg.block), engine="unknown")
    try:
        arc = developed_arc_of(seg)
    except ValueError as exc:
        return Outcome(reason=Reason(f"developed arc cannot be modelled: {exc}", seg.span, seg.block),
                        engine="unknown")
    return _ArcCheck(prover, seg, arc).run()


class _ArcCheck:
    def __init__(self, prover: Any, seg: Segment, arc: DevelopedArc):
        self.p = prover
        self.seg = seg
        self.arc = arc
        info = cylinder_of(seg)
        assert info is not None  # developed_arc_of(seg) succeeded
        lin, rot, _ = info
        self.lin, self.rot = lin, rot
        self.points: dict[Fraction, tuple[Interval, Interval, Interval]] = {}
        self.used = 0

    def point(self, f: Fraction) -> tuple[Interval, Interval, Interval]:
        got = self.points.get(f)
        if got is None:
            got = self.points[f] = self.arc.point(f)
        return got

    def _dicts(self, z: Interval, c: Interval) -> tuple[dict[str, Fraction], dict[str, Fraction]]:
        lo = dict(zip(self.seg.axes, self.seg.start))
        hi = dict(lo)
        lo[self.lin], hi[self.lin] = z.lo, z.hi
        lo[self.rot], hi[self.rot] = c.lo, c.hi
        return lo, hi

    def _box(self, fa: Fraction, fb: Fraction) -> Any:
        za, sa, _ = self.point(fa)
        zb, sb, _ = self.point(fb)
        alpha = self.arc.sweep.hi * (fb - fa)
        h = round_up_scaled(self.arc.rho.hi * alpha * alpha / 8)
        z = za.hull(zb).widen(h)
        s = sa.hull(sb).widen(h)
        return z, self.arc.c0 + s / self.arc.k

    def run(self):
        p, seg = self.p, self.seg
        p.stats["pieces"] += 1
        stack = [(Fraction(3 - i, 4), Fraction(4 - i, 4), 0) for i in range(4)]  # the last piece at the bottom
        while stack:
            fa, fb, depth = stack.pop()
            self.used += 1
            if self.used > BUDGET:
                break
            z, c = self._box(fa, fb)
            lo, hi = self._dicts(z, c)
            if ex.box_fits(p.allowed, lo, hi, p.margin, seg.tool_length):
                continue
            v = self._certify((fa + fb) / 2, fa)
            if v is not None:
                p.stats["z3_segments"] += 0
                return Outcome(v, engine="exact")
            if depth >= MAX_DEPTH:
                break
            mid = (fa + fb) / 2
            stack.append((mid, fb, depth + 1))
            stack.append((fa, mid, depth + 1))
        else:
            p.stats["screened"] += 1
            return Outcome(engine="exact")
        return Outcome(reason=Reason(
            "arc in cylindrical interpolation (G07.1): its enclosure meets a zone boundary and no point of the "
            f"exact path was certified outside after {self.used - 1} refinements (pi and the developed geometry "
            "are enclosed; the path may touch the boundary)", seg.span, seg.block), engine="unknown")

    def _certify(self, f: Fraction, proven_up_to: Fraction) -> Violation | None:
        p, seg = self.p, self.seg
        z, _, c = self.point(f)
        lo, hi = self._dicts(z, c)
        got = certify_box(p, seg, lo, hi)
        if got is None:
            return None
        mid, bad = got
        depth = F0  # a lower bound from certified points along the arc
        for i in range(33):
            zz, _, cc = self.point(Fraction(i, 32))
            blo, bhi = self._dicts(zz, cc)
            depth = max(depth, box_depth(p, seg, blo, bhi, max(zz.width(), cc.width())))
        width = max(z.width(), c.width())
        note = (f"irrational path point (pi); reported point within {float(width):.1e} of it, the whole "
                f"enclosure violates; {developed_note(seg, mid)}")
        return enclosed_violation(p, seg, f, mid, bad, width, depth, "developed_arc", note)
