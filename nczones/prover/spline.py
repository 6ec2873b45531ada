"""Prover for SPLINE segments (exact NURBS curves, :mod:`nczones.geometry.nurbs`).

Enclosure: with positive weights the whole curve lies in the convex hull of
its control points, and the curve over one knot span in the convex hull of
that span's ``degree + 1`` control points.  The box of all control points
is screened first (one exact test proves most curves); otherwise each knot
span is a piece (:meth:`nczones.geometry.nurbs.Nurbs.span_curve`, no knot
insertion), and each piece is

1. screened exactly: the bounding box of its control points fits every zone
   (with the margin) -> proved;
2. otherwise asked of Z3 as a linear query (QF_LRA): some convex combination
   ``sum l_j P_j`` (``l_j >= 0``, ``sum l_j = 1``) of its control points,
   plus the margin perturbation ``-d <= e <= d`` per axis, violates a zone.
   ``unsat`` -> proved (the hull holds the piece);
3. on ``sat``, exact curve points of the piece are tested with
   ``AllowedSet.violated_zones`` (the ends, and the points at the parameters
   nearest the model's barycentric weights); a violating point is reported
   as the witness (an exact point *on the curve*);
4. otherwise the piece is split at its middle parameter (exact Boehm
   insertion: the halves' hulls are tighter) and both halves go back to 1,
   up to a budget of pieces; when the budget is spent the segment is
   ``unknown`` with the reason.

Never ``safe`` otherwise; parameter ranges on a spline are ``unknown``.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..geometry.nurbs import Nurbs, spline_curve
from ..motion import Segment
from ..zones import ZonePoint
from . import exact as ex
from .result import Outcome, Reason, Violation
from .smt import add, mul, q

__all__ = ["check_spline", "SPLINE_PIECE_BUDGET"]

#: Pieces examined per spline segment before the verdict is unknown.
SPLINE_PIECE_BUDGET = 400
_MAX_DEPTH = 24


def _hull_query(prover: Any, seg: Segment, pts: Any) -> tuple[str, list[str]]:
    names = [f"l{j}" for j in range(len(pts))]
    body = ["".join(f"(declare-const {n} Real)(assert (>= {n} 0.0))" for n in names),
            f"(assert (= {add(*names)} 1.0))"]
    mdecl, evars = prover.margin_decls(names)
    body.append(mdecl)
    pt, enclosure = {}, {}
    for k, a in enumerate(prover.axes):
        coords = [p[k] for p in pts]
        lo, hi = min(coords), max(coords)
        enclosure[a] = (lo, hi)
        if lo == hi:
            term = q(lo)
        else:
            term = add(*(mul(n, q(c)) for n, c in zip(names, coords)))
        pt[a] = add(term, evars[a])
    zones = prover.relevant_zones(tuple(enclosure[a][0] for a in prover.axes),
                                  tuple(enclosure[a][1] for a in prover.axes), seg.tool_length)
    body.append(f"(assert {prover.violation_formula(pt, q(seg.tool_length), enclosure, zones)})")
    return "".join(body), names


def _violating_point(prover: Any, seg: Segment, c: Nurbs, hint: list[Fraction] | None) -> Any:
    lo, hi = c.domain
    params = [lo, hi, (lo + hi) / 2]
    if hint:
        # the barycentric weights suggest where along the piece the hull point lies (Greville-like abscissae)
        n = len(hint) - 1
        t = sum((Fraction(j, n) * h for j, h in enumerate(hint)), Fraction(0)) if n else Fraction(1, 2)
        t = min(max(t, Fraction(0)), Fraction(1))
        params.append(lo + (hi - lo) * _round(t))
    for s in params:
        pt = c.point(s)
        pmap = dict(zip(prover.axes, pt))
        bad = prover.allowed.violated_zones(pmap, seg.tool_length, prover.margin)
        if bad:
            return s, pt, bad
    return None


def _round(t: Fraction) -> Fraction:
    return Fraction(round(t * 1024), 1024)


def check_spline(prover: Any, seg: Segment) -> Any:
    """Decide one SPLINE segment: ``Outcome`` with a violation, a reason, or neither (proved).

    Screens first, without the solver: the box of all control points (the
    whole curve lies in their convex hull), then the box of each knot span's
    ``degree + 1`` control points (its local hull; no knot insertion).  Only
    the spans whose box does not fit go on to the hull query, the exact
    curve points and the refinement; only those count against
    :data:`SPLINE_PIECE_BUDGET`.
    """
    if prover.param_relevant(seg):
        return Outcome(reason=Reason("parameter ranges are not supported on spline (NURBS) motion",
                                      seg.span, seg.block), engine="unknown")
    curve = spline_curve(seg)
    auto = prover.engine == "auto"
    if auto and _hull_fits(prover, seg, curve.points):
        prover.stats["screened"] += 1
        return Outcome(engine="exact")
    p = curve.degree
    work = []
    for i in range(p, len(curve.points)):
        if curve.knots[i] < curve.knots[i + 1]:
            if auto and _hull_fits(prover, seg, curve.points[i - p: i + 1]):
                continue
            work.append((curve.span_curve(i), 0))
    if not work:
        prover.stats["screened"] += 1
        return Outcome(engine="exact")
    work.reverse()
    examined = 0
    engine = "exact"
    while work:
        c, depth = work.pop()
        prover.checkpoint()
        pts = c.points
        if depth and auto and _hull_fits(prover, seg, pts):
            continue
        examined += 1
        if examined > SPLINE_PIECE_BUDGET:
            return Outcome(reason=Reason(f"spline: the control hulls of {SPLINE_PIECE_BUDGET} curve pieces near a "
                                          "zone boundary were examined without proving the curve or finding an "
                                          "exact point outside", seg.span, seg.block), engine="unknown")
        engine = "z3"
        prover.stats["z3_segments"] += 1
        body, names = _hull_query(prover, seg, pts)
        ans = prover.solver.check(body, names)
        if ans.status == "unsat":
            continue
        if ans.status == "unknown":
            return prover.unknown_outcome(seg, ans, "a spline piece")
        hint = [ans.values.get(n, Fraction(0)) for n in names[: len(pts)]]
        found = _violating_point(prover, seg, c, hint)
        if found is not None:
            return Outcome(_violation(prover, seg, curve, found), engine=engine)
        if depth >= _MAX_DEPTH:
            return Outcome(reason=Reason("spline: the curve comes within a refinement limit of a zone boundary "
                                          "without an exact point outside", seg.span, seg.block), engine="unknown")
        lo, hi = c.domain
        a, b = c.split((lo + hi) / 2)
        work.append((b, depth + 1))
        work.append((a, depth + 1))
    return Outcome(engine=engine)


def _hull_fits(prover: Any, seg: Segment, pts: Any) -> bool:
    """Does the box of these control points fit every zone (with the margin)?"""
    n = len(prover.axes)
    lo_pt = tuple(min(q[k] for q in pts) for k in range(n))
    hi_pt = tuple(max(q[k] for q in pts) for k in range(n))
    return bool(prover.bbox_fits(lo_pt, hi_pt, seg.tool_length))


def _violation(prover: Any, seg: Segment, curve: Nurbs, found: Any) -> Violation:
    s, path, bad = found
    pmap = dict(zip(prover.axes, path))
    zone = bad[0]
    outside = ex.outside_point(prover.allowed, zone, pmap, prover.margin, seg.tool_length)
    if outside is None or zone not in prover.allowed.violated_zones(outside, seg.tool_length):
        from ..errors import InternalError

        raise InternalError(f"block {seg.block}: no point strictly outside inside the margin box")
    seen = dict(pmap)
    if zone.point is ZonePoint.TIP and prover.tool_axis in seen:
        seen[prover.tool_axis] -= seg.tool_length
    depth = ex.point_depth(zone, seen, prover.margin)
    lo, hi = curve.domain
    tau = (s - lo) / (hi - lo)
    return Violation(
        block=seg.block, span=seg.span, zone=zone.name,
        point=tuple((a, outside[a]) for a in prover.axes),
        path_point=tuple(zip(prover.axes, path)),
        parameter=tau, parameter_exact=True,
        first_exit=tuple(zip(prover.axes, path)), first_exit_parameter=tau, first_exit_exact=False,
        depth=depth, depth_exact=False, engine="z3", segment_kind="spline",
        derived=seg.derived, zones=tuple(z.name for z in bad),
        note="spline: a curve point outside (not necessarily the first exit; depth is at that point, a lower bound)",
        exit_located=False,
    )
