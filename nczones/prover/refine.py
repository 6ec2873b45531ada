"""Refinement by splitting for helices and spiral I/J arcs (issue 4, DESIGN §5).

A helix (a circular arc in its plane with other axes moving linearly in the
swept angle) and a spiral arc (radius moving linearly in the swept angle) are
not polynomial, so :meth:`Prover.arc_query` proves a *containing* set: the
planar arc (or annular sector) times the whole range of every moving axis.
When that enclosure admits a violation the exact path may not reach, this
module splits the sweep into sub-arcs, proves each sub-arc's (much tighter)
enclosure with the same encoding, and splits again where needed, up to a
budget (:data:`MAX_PIECES` queries, :data:`MAX_DEPTH` halvings); then the
answer is ``unknown`` with the reason.  Never ``safe`` by default.

Soundness argument (why a proved piece proves that part of the exact path)
--------------------------------------------------------------------------
Let ``u`` be the start direction from the (rational) centre, ``Θ`` the total
swept angle and ``θ(v)`` the swept angle at which the exact path points in
direction ``v``.  Every piece is a pair of rational directions ``(da, db)``
with a sweep of less than a quarter turn, and rational bounds
``θa_lo <= θ(da)``, ``θ(db) <= θb_hi`` (quarter-turn boundaries are
``j·π/2`` enclosed with :func:`pi_bounds`; other directions use the
rational angle enclosure :func:`angle_bounds`, plus ``2π·lap``).  On the
exact path between ``da`` and ``db``:

* the planar point is at a direction in the closed sector ``[da, db]`` — the
  sector is encoded exactly with half-plane tests;
* each moving non-plane axis is ``start + (end - start)·θ/Θ``, monotone in
  ``θ``, and ``θ/Θ ∈ [max(0, θa_lo/Θ_hi), min(1, θb_hi/Θ_lo)]``; the axis is
  encoded as anywhere in the image of that interval;
* for a spiral the radius ``r_s + (r_e - r_s)·θ/Θ`` is multilinear in
  ``(r_s, r_e, θ/Θ)``, so its range over the enclosures of ``r_s``, ``r_e``
  (:func:`sqrt_bounds`) and ``θ/Θ`` is spanned by the corners; the squared
  radius is encoded in the square of that range (widened to contain the
  piece's own rational end points, which only enlarges it).

Hence the piece's encoded set contains the exact sub-path, and ``unsat``
proves it.  The pieces' sectors cover the whole sweep (each split inserts a
direction strictly inside its parent's sector), so all pieces proved means
the segment is proved.  A violation is only reported after
:meth:`Prover.arc_witness_enclosed` certified it on the exact path (a
rational box around an exact path point that certainly violates).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..motion import Segment
from .geometry import (
    ArcGeom,
    angle_bounds,
    arc_bases,
    half_tan,
    in_sweep,
    pi_bounds,
    round_down,
    round_up,
    sqrt_bounds,
)
from .result import Outcome, Reason

F0 = Fraction(0)
F1 = Fraction(1)

#: At most this many sub-arc queries per segment.
MAX_PIECES = 64
#: At most this many halvings of one initial (quarter-turn) piece.
MAX_DEPTH = 8


def _rot(d: tuple[Fraction, Fraction], m: Fraction, ccw: bool) -> tuple[Fraction, Fraction]:
    """``d`` rotated by ``2·atan(m)`` in the arc's direction (exact, keeps the length)."""
    perp = (-d[1], d[0]) if ccw else (d[1], -d[0])
    den = 1 + m * m
    return (((1 - m * m) * d[0] + 2 * m * perp[0]) / den, ((1 - m * m) * d[1] + 2 * m * perp[1]) / den)


def quarter_of(u: tuple[Fraction, Fraction], w: tuple[Fraction, Fraction], ccw: bool) -> tuple[int, bool]:
    """Quarter index k with angle(u -> w) in [k π/2, (k+1) π/2), and whether it is exactly k π/2."""
    for k, base in enumerate(arc_bases(u, ccw)):
        cr = base[0] * w[1] - base[1] * w[0]
        if not ccw:
            cr = -cr
        dt = base[0] * w[0] + base[1] * w[1]
        if cr >= 0 and dt > 0 or (cr > 0 and dt == 0):
            return k, cr == 0
    raise AssertionError("direction in no quarter")


def refine_arc(prover: Any, seg: Segment, g: ArcGeom, params: Any) -> Any:
    r"""Prove a helix or spiral arc piece by piece (see the module docstring).

    Returns a ``Outcome``: proved (engine ``"z3"``), a certified violation,
    or ``unknown`` whose reason names the budget or the solver limit.
    Requires a rational centre (``g.centre is not None``).  Returns None when
    the sweep has no positive angle (nothing to refine).

    Examples
    --------
    A half-turn helix whose high half is over a raised step: the whole
    enclosure reaches the step, the pieces do not.

    >>> from dataclasses import replace
    >>> from nczones.machine import parse_machine
    >>> from nczones.motion import Plane, SegmentKind
    >>> from nczones.zones import AllowedSet, Region, SteppedZone
    >>> from nczones.prover.core import Prover
    >>> from nczones.prover.geometry import arc_geom
    >>> F = Fraction
    >>> m = parse_machine('[machine]\naxes = ["X", "Y", "Z"]\n[machine.rapid]\nX = "1"\nY = "1"\nZ = "1"\n'
    ...                   '[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n')
    >>> step = SteppedZone("table", "X", "Z", F(-50), (Region(F(0), F(4), None), Region(F(50), F(-20), None)))
    >>> m = replace(m, allowed=AllowedSet((step,), m.allowed.tool_axis))
    >>> seg = Segment(SegmentKind.ARC, (F(-10), F(0), F(10)), (F(10), F(0), F(0)), ("X", "Y", "Z"),
    ...               plane=Plane.XY, clockwise=True, centre=(F(0), F(0)))
    >>> out = refine_arc(Prover(m), seg, arc_geom(seg), ())
    >>> out.violation is None and out.reason is None
    True
    """
    for ends in (g.start, g.end):  # exact path points: a violation there needs no enclosure
        pmap = dict(zip(prover.axes, ends))
        bad = prover.allowed.violated_zones(pmap, seg.tool_length, prover.margin)
        if bad:
            return Outcome(prover.arc_violation(seg, g, pmap, bad, params, True), engine="exact")
    c = g.centre
    assert c is not None  # refinement splits arcs with a rational centre (helix, spiral)
    u = (g.s[0] - c[0], g.s[1] - c[1])
    w = (g.e[0] - c[0], g.e[1] - c[1])
    pi_lo, pi_hi = pi_bounds()
    turns = seg.turns
    bases = arc_bases(u, g.ccw)
    # boundaries: (direction, lap, theta_lo, theta_hi) in sweep order
    if g.s == g.e:
        quarters, exact_end = 4 * (turns + 1), True
    else:
        k, exact_end = quarter_of(u, w, g.ccw)
        quarters = 4 * turns + k
    bounds = [(bases[j % 4], j // 4, j * pi_lo / 2, j * pi_hi / 2) for j in range(quarters + 1)]
    if not exact_end:
        a_lo, a_hi = angle_bounds(u, w, g.ccw)
        bounds.append((w, turns, a_lo + 2 * pi_lo * turns, a_hi + 2 * pi_hi * turns))
    tot_lo, tot_hi = bounds[-1][2], bounds[-1][3]
    if tot_lo <= 0:
        return None
    if len(bounds) - 1 > MAX_PIECES:
        return Outcome(reason=Reason(f"helix/spiral refinement budget exhausted: {len(bounds) - 1} quarter "
                                      f"turns exceed {MAX_PIECES} pieces", seg.span, seg.block), engine="unknown")
    spiral = g.r2_lo != g.r2_hi
    if spiral:
        rs = sqrt_bounds(u[0] ** 2 + u[1] ** 2, 120)
        re_ = sqrt_bounds(w[0] ** 2 + w[1] ** 2, 120)

    def piece_geom(a: Any, b: Any) -> ArcGeom:
        da, _, ta_lo, _ = a
        db, _, _, tb_hi = b
        # every enclosure is rounded outward to a fixed resolution: exact but bounded numbers
        f_lo = max(F0, round_down(ta_lo / tot_hi))
        f_hi = min(F1, round_up(tb_hi / tot_lo))
        start, end = list(g.start), list(g.end)
        for k in range(len(g.start)):
            if k in (g.ia, g.ib) or g.start[k] == g.end[k]:
                continue
            vals = (g.start[k] + (g.end[k] - g.start[k]) * f_lo, g.start[k] + (g.end[k] - g.start[k]) * f_hi)
            start[k], end[k] = round_down(min(vals)), round_up(max(vals))
        r2_lo = r2_hi = g.r2_lo
        if spiral:
            rho = [r0 + (r1 - r0) * f for r0 in rs for r1 in re_ for f in (f_lo, f_hi)]
            r2s = [max(F0, min(rho)) ** 2, max(rho) ** 2, da[0] ** 2 + da[1] ** 2, db[0] ** 2 + db[1] ** 2]
            r2_lo, r2_hi = round_down(min(r2s)), round_up(max(r2s))
        return ArcGeom(g.ia, g.ib, (c[0] + da[0], c[1] + da[1]), (c[0] + db[0], c[1] + db[1]), g.ccw, False,
                       c, None, r2_lo, r2_hi, tuple(start), tuple(end))

    def split(a, b):
        da, lap, _, _ = a
        db = b[0]
        m = half_tan(da, db, g.ccw)
        if m is None or m <= 0:
            return None
        m = (m / 2).limit_denominator(2**24) or Fraction(1, 2**25)
        dm = _rot(da, m, g.ccw)
        if spiral:  # bring the direction near the path radius (keeps the piece's end points tight)
            n2 = dm[0] ** 2 + dm[1] ** 2
            t = sqrt_bounds(((rs[0] + re_[0]) / 2) ** 2 / n2, 40)[0] or F1
            dm = (dm[0] * t, dm[1] * t)
        dm = (round_down(dm[0]), round_down(dm[1]))  # any direction strictly inside the sector will do
        if dm == da or not in_sweep(da, db, dm, g.ccw, False) or in_sweep(da, dm, db, g.ccw, False):
            return None
        lo, hi = angle_bounds(u, dm, g.ccw)
        return (dm, lap, lo + 2 * pi_lo * lap, hi + 2 * pi_hi * lap)

    stack = [(bounds[i], bounds[i + 1], 0) for i in range(len(bounds) - 1)][::-1]
    used = 0
    undecided = False
    while stack:
        a, b, depth = stack.pop()
        used += 1
        if used > MAX_PIECES:
            return Outcome(reason=Reason(f"helix/spiral refinement budget exhausted ({MAX_PIECES} pieces, depth "
                                          f"{MAX_DEPTH}): the enclosure near a boundary could be neither proved "
                                          "nor confirmed violated", seg.span, seg.block), engine="unknown")
        pg = piece_geom(a, b)
        prover.stats["refined_pieces"] = prover.stats.get("refined_pieces", 0) + 1
        body, names = prover.arc_query(seg, pg, False)
        ans = prover.solver.check(body, names, precision=60, nonlinear=True)
        if ans.status == "unsat":
            continue
        if ans.status == "unknown":
            return prover.unknown_outcome(seg, ans, "a helix/spiral piece")
        v = prover.arc_witness_enclosed(seg, g, ans.values, params, retry=False)
        mid = split(a, b)
        if v is None and mid is not None:
            v = prover.arc_witness_enclosed(seg, g, {"x": c[0] + mid[0][0], "y": c[1] + mid[0][1]}, params,
                                             retry=False)
        if v is not None:
            return Outcome(v, engine="z3")
        if mid is None or depth >= MAX_DEPTH:
            # undecided: look for a certified violation here and in the other pieces before answering
            v = _scan_piece(prover, seg, g, a[0], b[0], params)
            if v is not None:
                return Outcome(v, engine="z3")
            undecided = True
            continue
        stack.append((mid, b, depth + 1))
        stack.append((a, mid, depth + 1))
    if undecided:
        return Outcome(reason=Reason(f"helix/spiral refinement budget exhausted (depth {MAX_DEPTH}, "
                                      f"{MAX_PIECES} pieces): a piece's enclosure may violate a zone but no "
                                      "exact violation was confirmed", seg.span, seg.block), engine="unknown")
    return Outcome(engine="z3")


#: Exact directions tried across a piece the budget cannot split further, before answering unknown.
SCAN_DIRECTIONS = 64


def _scan_piece(prover: Any, seg: Segment, g: ArcGeom, da: tuple[Fraction, Fraction],
                db: tuple[Fraction, Fraction], params: Any) -> Any:
    """A certified violation at one of :data:`SCAN_DIRECTIONS` rational directions spread over the
    sector from ``da`` to ``db`` (tangent half-angle steps), or None.

    Only a certification on the exact path (:meth:`Prover.arc_witness_enclosed`) is reported, so
    this can find a witness the pieces' enclosures were too coarse to confirm (a spiral that leaves
    a face by far less than the enclosure's width), never invent one.
    """
    m_end = half_tan(da, db, g.ccw)
    c = g.centre
    if m_end is None or m_end <= 0 or c is None:
        return None
    for i in range(1, SCAN_DIRECTIONS):
        d = _rot(da, round_down(m_end * i / SCAN_DIRECTIONS), g.ccw)
        v = prover.arc_witness_enclosed(seg, g, {"x": c[0] + d[0], "y": c[1] + d[1]}, params, retry=False)
        if v is not None:
            return v
    return None
