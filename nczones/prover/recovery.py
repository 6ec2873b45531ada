"""Proving tool-break recovery: every break point, every recovery leg (DESIGN §6, issue 9).

The recovery path (:func:`nczones.plans.recovery.recovery_legs`) depends
on where the tool breaks.  The prover does not sample break points: the
break parameter is a variable.

* On a line from ``S0`` to ``S1`` the break point is ``P(s) = S0 + s (S1 - S0)``,
  ``0 <= s <= 1``.  On a circular arc (rational centre ``c``, radius ``r``)
  it is a point ``(x, y)`` with ``(x-cx)^2 + (y-cy)^2 = r^2`` inside the swept
  sector (half-plane tests, exact); on a helix the other axes are enclosed
  between their start and end values (an over-approximation).
* The legs — which, from where to where, with which tool, rapid or feed —
  are the shared plan (:func:`nczones.plans.recovery.plan_legs`) computed in SMT
  terms of the break variables: the restart point is the constant sequence
  start (``start``) or ``P(s)`` itself (``breakpoint``), the plan's maxima
  (the retract height ``max(P_z, clearance)``) become ``ite`` terms.  Only
  how a leg is encoded is decided here.
* A straight leg from ``A`` to ``B`` is ``A + t (B - A)``, ``0 <= t <= 1``: with
  ``A`` or ``B`` depending on ``s`` this has products ``s t`` (QF_NRA, decided
  exactly by Z3's nlsat).  A leg whose ends differ in one coordinate only (the
  plan's retract, rapid down and approach) is that coordinate between its two
  ends (linear).  A dogleg rapid (the machine's ``rapid_mode``) is, at time
  ``tau >= 0``, ``A_i + sign(d_i) min(rate_i tau, |d_i|)`` with ``d = B - A``
  (linear with ``ite``).

One query per (cutting motion, leg) asks for a break point and a point of
the leg outside the allowed set (exactly as :mod:`.smt` encodes zones, tip
zones seeing the leg's tool length).  ``unsat`` proves the leg for every
break point.  A model gives a break parameter ``s*`` (rational; rounded to
``1e-12`` when Z3 gives an algebraic number, arcs through the rational
parametrisation of the circle); the concrete recovery path from ``s*`` is
then re-checked exactly by :class:`~nczones.prover.core.Prover`, and only
that exact point is reported.  When the re-check does not confirm it (a
rounding moved ``s*`` off a thin violating set, a helix), the verdict is
``unknown`` with the reason.

The resumed cut (``resume`` leg) only differs from the program when the
replacement tool has another length; then every motion run with the broken
tool's length is proved shifted by the difference (an over-approximation of
every possible remainder).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any

from ..machine import Machine, RapidMode
from ..motion import Segment, SegmentKind, segments_of, tip_offset
from ..plans.recovery import (
    RecoveryLeg,
    RecoveryVariant,
    ToolChangeConfig,
    is_cutting,
    motion_sequences,
    plan_legs,
    recovery_legs,
    replacement_length,
    shift_segment,
    tool_axis_index,
    tool_change_config,
)
from ..zones import ZonePoint
from .core import Prover
from .geometry import arc_geom, rational_point_on_arc
from .limits import BudgetSpent
from .result import Reason, Violation
from .smt import add, mul, or_all, q, sub, zone_violation

__all__ = ["RecoveryOutcome", "verify_recovery"]

#: Feed motions a tool can break in whose break points the recovery proof does not place: the recovery
#: from them is ``unknown`` (RC201), never assumed (they are not LINE or ARC, see ``nczones.plans.recovery.is_cutting``).
_UNMODELLED_FEEDS = {
    SegmentKind.DEVELOPED_ARC: "a developed arc in cylindrical interpolation (G07.1)",
    SegmentKind.SPLINE: "a spline (G5, G5.1, G5.2, G6.2)",
    SegmentKind.POLAR: "a move in polar coordinate interpolation (G12.1)",
}

F0, F1 = Fraction(0), Fraction(1)


@dataclass(frozen=True, slots=True)
class RecoveryOutcome:
    """Recovery violations (``kind == "recovery"``), reasons for ``unknown``, counters."""

    violations: tuple[Violation, ...]
    reasons: tuple[Reason, ...]
    stats: tuple[tuple[str, int], ...]
    variant: RecoveryVariant


def _ite_max(a: str, b: str) -> str:
    return f"(ite (>= {a} {b}) {a} {b})"


def _ite_min(a: str, b: str) -> str:
    return f"(ite (<= {a} {b}) {a} {b})"


class _SmtTerms:
    """The shared recovery plan's arithmetic in SMT-LIB terms of the break variables."""

    def number(self, v: Fraction) -> str:
        return q(v)

    def plus(self, a: str, d: Fraction) -> str:
        return a if d == 0 else add(a, q(d))

    def maximum(self, a: str, b: str) -> str:
        return a if a == b else _ite_max(a, b)


_SMT_TERMS = _SmtTerms()


class _Encoder:
    """SMT terms of the recovery path of one cutting motion, as functions of the break variables."""

    def __init__(self, machine: Machine, cfg: ToolChangeConfig, margin: Fraction):
        self.m = machine
        self.cfg = cfg
        self.axes = machine.axis_names
        self.margin = margin
        self.tool_axis = machine.allowed.tool_axis
        self.zones = machine.allowed.zones

    def break_point(self, seg: Segment) -> tuple[list[str], list[str], list[str]] | None:
        """(declarations/assertions, coordinate terms, variable names); None when unsupported."""
        if seg.kind is SegmentKind.LINE:
            body = ["(declare-const s Real)", "(assert (<= 0.0 s 1.0))"]
            pt = [add(q(a), mul("s", q(b - a))) for a, b in zip(seg.start, seg.end)]
            return body, pt, ["s"]
        g = arc_geom(seg)
        if g.centre is None or g.r2_lo != g.r2_hi:
            return None
        cx, cy = g.centre
        body = ["(declare-const px Real)", "(declare-const py Real)",
                f"(assert (= (+ (* (- px {q(cx)}) (- px {q(cx)})) (* (- py {q(cy)}) (- py {q(cy)}))) {q(g.r2_lo)}))"]
        if not g.full:
            a = (g.s[0] - cx, g.s[1] - cy)
            b = (g.e[0] - cx, g.e[1] - cy)
            if not g.ccw:
                a, b = b, a

            def cross_ge(u: tuple[Fraction, Fraction], w_is_v_first: bool) -> str:
                # cross(u, v) >= 0 or cross(v, u) >= 0 with v = (px - cx, py - cy)
                vx, vy = f"(- px {q(cx)})", f"(- py {q(cy)})"
                if not w_is_v_first:
                    return f"(>= (- (* {q(u[0])} {vy}) (* {q(u[1])} {vx})) 0.0)"
                return f"(>= (- (* {vx} {q(u[1])}) (* {vy} {q(u[0])})) 0.0)"

            c = a[0] * b[1] - a[1] * b[0]
            after_a, before_b = cross_ge(a, False), cross_ge(b, True)
            if c > 0:
                body.append(f"(assert (and {after_a} {before_b}))")
            elif c < 0:
                body.append(f"(assert (or {after_a} {before_b}))")
            else:  # half a turn
                body.append(f"(assert {after_a})")
        pt = []
        names = ["px", "py"]
        for k, (a0, a1) in enumerate(zip(seg.start, seg.end)):
            if k == g.ia:
                pt.append("px")
            elif k == g.ib:
                pt.append("py")
            elif a0 == a1:
                pt.append(q(a0))
            else:  # helix axis: enclosed between its ends
                v = f"h{k}"
                body.append(f"(declare-const {v} Real)(assert (<= {q(min(a0, a1))} {v} {q(max(a0, a1))}))")
                pt.append(v)
                names.append(v)
        return body, pt, names

    def legs(self, P: list[str], R: list[str], L: Fraction, L2: Fraction) -> tuple[RecoveryLeg[str], ...]:
        """The shared plan's five legs from break point ``P`` to restart point ``R``, in SMT terms."""
        return plan_legs(self.cfg, self.m, P, R, L, L2, _SMT_TERMS)

    def leg_points(self, leg: RecoveryLeg[str], body: list[str]) -> list[str]:
        """The terms of a point of ``leg`` (its variables declared in ``body``)."""
        A, B = list(leg.start), list(leg.end)
        moving = [k for k, (a, b) in enumerate(zip(A, B)) if a != b]
        if len(moving) <= 1:  # along one axis (or standing): that coordinate between the two ends
            if not moving:
                return A
            k = moving[0]
            body.append("(declare-const w Real)")
            lo, hi = _ite_min(A[k], B[k]), _ite_max(A[k], B[k])
            body.append(f"(assert (and (<= {lo} w) (<= w {hi})))")
            return [("w" if i == k else a) for i, a in enumerate(A)]
        if leg.kind is SegmentKind.RAPID and self.m.rapid_mode is RapidMode.DOGLEG:
            body.append("(declare-const tau Real)(assert (>= tau 0.0))")
            out = []
            for i, (a, b) in enumerate(zip(A, B)):
                if a == b:
                    out.append(a)
                    continue
                rate = q(self.m.axes[i].rapid_mm_min / 1000)
                d = sub(b, a)
                m = _ite_min(f"(* {rate} tau)", f"(ite (>= {d} 0.0) {d} (- {d}))")
                out.append(f"(+ {a} (ite (>= {d} 0.0) {m} (- {m})))")
            return out
        body.append("(declare-const t Real)(assert (<= 0.0 t 1.0))")
        return [a if a == b else add(a, mul("t", f"(- {b} {a})")) for a, b in zip(A, B)]

    def outside(self, pt: list[str], L: Fraction, body: list[str], tip: dict[str, Fraction]) -> str:
        """A point outside the allowed set (with the margin box); tool-tip zones see the point minus the tool
        length on the tool axis and minus ``tip`` (a lathe tool offset) on the other axes."""
        seen_base = {}
        for k, a in enumerate(self.axes):
            term = pt[k]
            if self.margin:
                body.append(f"(declare-const e{k} Real)(assert (<= {q(-self.margin)} e{k} {q(self.margin)}))")
                term = add(term, f"e{k}")
            seen_base[a] = term
        parts = []
        for zone in self.zones:
            seen = dict(seen_base)
            if zone.point is ZonePoint.TIP and self.tool_axis in seen:
                seen[self.tool_axis] = sub(seen[self.tool_axis], q(L))
            if zone.point is ZonePoint.TIP:
                for a, d in tip.items():
                    if a in seen and d:
                        seen[a] = sub(seen[a], q(d))
            parts.append(zone_violation(zone, seen, None))
        return or_all(parts)


def verify_recovery(segments: Any, machine: Machine, *, variant: RecoveryVariant | str | None = None,
                    margin: Fraction = F0, max_violations: int = 20, prover: Prover | None = None,
                    rlimit: int = 20_000_000, limits: Any = None) -> RecoveryOutcome:
    """Prove the recovery path from every break point of every cutting motion.

    ``segments`` is the program's motion (an interpretation or segments);
    ``variant`` overrides the machine's ``[tool_change] variant``.  At most
    one violation per cutting motion (the first leg that fails), at most
    ``max_violations`` in all.

    >>> from nczones.machine import load_machine
    >>> from nczones.gcode import interpret
    >>> m = load_machine("specs/examples/machines/mill_toolchange.toml")
    >>> out = verify_recovery(interpret("specs/examples/programs/recovery_clamp.ngc", m), m)
    >>> v = out.violations[0]
    >>> v.kind, v.break_line, v.leg, v.zone
    ('recovery', 5, 'to tool change', 'clamp')
    >>> high = load_machine("specs/examples/machines/mill_toolchange_high.toml")
    >>> verify_recovery(interpret("specs/examples/programs/recovery_clamp.ngc", high), high).violations
    ()
    """
    cfg = tool_change_config(machine, variant)
    segs = _segments(segments)
    enc = _Encoder(machine, cfg, Fraction(margin))
    pr = prover or Prover(machine, margin=Fraction(margin), rlimit=rlimit, limits=limits)
    solver = pr.solver
    violations: list[Violation] = []
    reasons: list[Reason] = []
    stats = {"recovery_motions": 0, "recovery_queries": 0, "recovery_proved_legs": 0}
    seq_of: dict[int, int] = {}
    for first, last in motion_sequences(segs):
        for i in range(first, last + 1):
            seq_of[i] = first
    budget_spent = False
    for i, seg in enumerate(segs):
        if budget_spent:
            break
        if seg.kind in _UNMODELLED_FEEDS and len(violations) < max_violations:
            reasons.append(Reason(f"tool-break recovery: a break during {_UNMODELLED_FEEDS[seg.kind]} is not "
                                  "modelled (unsupported); the recovery from this motion is not proved",
                                  seg.span, seg.block, "RC201"))
            continue
        if not is_cutting(seg) or len(violations) >= max_violations:
            continue
        stats["recovery_motions"] += 1
        L = seg.tool_length
        L2 = replacement_length(cfg, machine, L)
        bp = enc.break_point(seg)
        if bp is None:
            reasons.append(Reason("tool-break recovery: R-format or spiral arc; the break point on it is not "
                                  "encoded (unsupported)", seg.span, seg.block, "RC201"))
            continue
        decl, P, names = bp
        tip = tip_offset(seg.extra)
        S = segs[seq_of[i]].start
        R = P if cfg.variant is RecoveryVariant.BREAKPOINT else [q(v) for v in S]
        for leg in enc.legs(P, R, L, L2):
            name = leg.name
            body = list(decl)
            pt = enc.leg_points(leg, body)
            body.append(f"(assert {enc.outside(pt, leg.tool_length, body, tip)})")
            stats["recovery_queries"] += 1
            try:
                ans = solver.check("".join(body), names)
            except BudgetSpent:
                reasons.append(Reason("tool-break recovery: budget spent before the recovery from this motion "
                                      "was proved", seg.span, seg.block, "VF203"))
                budget_spent = True
                break
            if ans.status == "unsat":
                stats["recovery_proved_legs"] += 1
                continue
            if ans.status == "unknown":
                reasons.append(Reason(f"tool-break recovery, leg {name!r}: {ans.reason()}",
                                      seg.span, seg.block, "RC202"))
                break
            v = _confirm(pr, enc, cfg, machine, seg, S, L, L2, name, ans, segs)
            if v is None:
                reasons.append(Reason(f"tool-break recovery, leg {name!r}: a violating break point was found "
                                      "but could not be confirmed on the exact path (it lies on a helix or a "
                                      "thin set)", seg.span, seg.block, "RC203"))
            else:
                violations.append(v)
            break
    if any(replacement_length(cfg, machine, s.tool_length) != s.tool_length for s in segs if is_cutting(s)):
        _check_resume(pr, cfg, machine, segs, violations, reasons, max_violations)
    if not budget_spent:
        _recovery_solids(segs, machine, cfg, seq_of, violations, reasons, max_violations)
    return RecoveryOutcome(tuple(violations), tuple(reasons), tuple(stats.items()), cfg.variant)


def _recovery_solids(segs: list[Segment], machine: Machine, cfg: Any, seq_of: dict[int, int],
                     violations: list[Violation], reasons: list[Reason], max_violations: int) -> None:
    """The recovery legs and the resumed cut proved for the tool solids (:mod:`.solids_recovery`), on a
    machine that has them; a motion whose recovery already left the allowed set is not checked again."""
    from ..solids import machine_solids

    solids = machine_solids(machine)
    if solids is None or not solids.fixtures:
        return
    from .solids_recovery import recovery_solids, resume_solids

    def replacement(length: Fraction) -> Fraction:
        return replacement_length(cfg, machine, length)

    done = {v.block for v in violations}
    starts = {i: segs[seq_of[i]].start for i, s in enumerate(segs)
              if is_cutting(s) and s.block not in done}
    found, why = recovery_solids(segs, machine, solids, cfg, replacement, starts, max_violations - len(violations))
    ti = tool_axis_index(machine)
    more, why2 = resume_solids(segs, machine, solids, replacement,
                               lambda seg, L2: shift_segment(seg, ti, L2 - seg.tool_length, L2),
                               max_violations - len(violations) - len(found))
    violations += found + more
    reasons += [r for r in why + why2 if r.message not in {x.message for x in reasons}]


def _segments(motion: Any) -> list[Segment]:
    return list(segments_of(motion))


def _break_candidates(seg: Segment, ans: Any) -> list[Fraction]:
    """Rational break parameters near the model's (line: ``s``; arc: ``tan(theta/2)``)."""
    if seg.kind is SegmentKind.LINE:
        s = min(F1, max(F0, ans.values["s"]))
        out = [s]
        if "s" in ans.approximate:
            out = [s.limit_denominator(10**12), s.limit_denominator(10**6)]
        return out
    g = arc_geom(seg)
    assert g.centre is not None  # break points are encoded on arcs with a rational centre only
    cx, cy = g.centre
    x, y = float(ans.values["px"] - cx), float(ans.values["py"] - cy)
    ux, uy = float(g.s[0] - cx), float(g.s[1] - cy)
    th = math.atan2(ux * y - uy * x, ux * x + uy * y)
    if not g.ccw:
        th = -th
    if th < 0:
        th += 2 * math.pi
    if abs(th - math.pi) < 1e-12:
        th = math.pi - 1e-9
    m = math.tan(th / 2)
    return [Fraction(m).limit_denominator(10**12), Fraction(m).limit_denominator(10**6)]


def _confirm(pr: Prover, enc: _Encoder, cfg: Any, machine: Machine, seg: Segment, S: Any, L: Fraction,
             L2: Fraction, leg_name: str, ans: Any, segs: list[Segment]) -> Violation | None:
    """Re-check the recovery path from a concrete break point exactly; the violation or None."""
    g = arc_geom(seg) if seg.kind is SegmentKind.ARC else None
    if g is not None and g.helix:
        return None
    for cand in _break_candidates(seg, ans):
        if g is None:
            P = tuple(a + cand * (b - a) for a, b in zip(seg.start, seg.end))
            s_param = cand
        else:
            xy = rational_point_on_arc(g, cand)
            P = tuple(xy[0] if k == g.ia else xy[1] if k == g.ib else v for k, v in enumerate(seg.start))
            th = 2 * math.atan(float(cand))
            sweep = _sweep(g)
            s_param = Fraction(th / sweep).limit_denominator(10**9) if sweep > 0 else F0
        R = P if cfg.variant is RecoveryVariant.BREAKPOINT else S
        legs = recovery_legs(cfg, machine, P, R, L, L2)
        order = [lg.name for lg in legs]
        # the failing leg first, then the others (a rounded s* may move the exit to a neighbour leg)
        for lg in sorted(legs, key=lambda lg: (lg.name != leg_name, order.index(lg.name))):
            out = pr.check(lg.segment(machine.axis_names, seg))
            if out.violation is not None:
                v = out.violation
                note = (f"tool break in line {seg.line} at s = {_fmt(s_param)}"
                        f"{' (fraction of the swept angle, approximate)' if g is not None else ''}; "
                        f"{cfg.variant.value} restart; the {lg.name} leg leaves the allowed set")
                return replace(v, kind="recovery", block=seg.block, span=seg.span, break_line=seg.line,
                               break_parameter=s_param, break_point=tuple(zip(machine.axis_names, P)),
                               leg=lg.name, note=note)
    return None


def _sweep(g: Any) -> float:
    if g.full:
        return 2 * math.pi
    cx, cy = g.centre
    a = (float(g.s[0] - cx), float(g.s[1] - cy))
    b = (float(g.e[0] - cx), float(g.e[1] - cy))
    th = math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1])
    if not g.ccw:
        th = -th
    return th if th > 0 else th + 2 * math.pi


def _fmt(x: Fraction) -> str:
    from ..exact import format_decimal

    return format_decimal(x, 9)


def _check_resume(pr: Prover, cfg: Any, machine: Machine, segs: list[Segment], violations: list[Violation],
                  reasons: list[Reason], max_violations: int) -> None:
    """The resumed cut with the replacement's length: every motion run with a broken-able tool, shifted."""
    ti = tool_axis_index(machine)
    firsts: dict[tuple, Segment] = {}
    for seg in segs:
        if len(violations) >= max_violations:
            return
        key = (seg.tool_length, seg.tool_register)
        if is_cutting(seg):
            firsts.setdefault(key, seg)
        brk = firsts.get(key)
        if brk is None:
            continue
        L2 = replacement_length(cfg, machine, seg.tool_length)
        if L2 == seg.tool_length:
            continue
        out = pr.check(shift_segment(seg, ti, L2 - seg.tool_length, L2))
        if out.violation is not None:
            v = out.violation
            violations.append(replace(v, kind="recovery", break_line=brk.line, break_parameter=F0, leg="resume",
                                      note=f"after a tool break at or after line {brk.line}, the resumed cut with "
                                           f"the replacement tool (H{cfg.length_register}) leaves the allowed set"))
        elif out.reason is not None:
            reasons.append(replace(out.reason, message="resumed cut with the replacement tool: " + out.reason.message))
