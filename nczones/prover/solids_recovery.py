"""Tool-break recovery legs proved for the tool solids (issue 39): every break point of every cutting motion.

The break points of a piece of a cutting motion (a line cut into pieces of its parameter ``s``; an arc as a
whole) lie in a box ``B`` (the piece's exact box), with one of them, ``P0``, exact on the path.  The recovery
plan (:func:`nczones.plans.recovery.plan_legs`) computed in **interval terms** over ``B`` gives, per leg and axis,
the intervals its start and end take over the piece (the plan's ``max`` and ``+`` map intervals exactly);
the same plan from ``P0`` (:func:`nczones.plans.recovery.recovery_legs`) gives one exact leg ``A0 → B0``.  Every leg
of the family is that leg displaced within a box ``D``: a straight leg's point ``(1-t) A + t B`` differs
from ``(1-t) A0 + t B0`` by a convex combination of ``A - A0`` and ``B - B0``, per axis within the hull of
``0`` and their intervals; a dogleg rapid moves each axis 1-Lipschitz in its ends, so within
``±(|A - A0| + |B - B0|)``.  The exact proof of the solids (:class:`nczones.prover.solids.SolidsChecker`, its
fixtures grown by ``D``, exact for boxes and cylinders; on a lathe
:class:`nczones.prover.lathe_solids.LatheSolidsChecker`, its Minkowski rectangles grown by ``D`` on X and Z,
exact) decides the family: clear; a part in a fixture at
``P0`` itself (a witness: ``unsafe``, kind ``recovery``); or undecided, then the line's piece is halved (at
most :data:`RECOVERY_PIECES` pieces per motion) and what remains is ``unknown`` (``VF220``).  The tool on
each leg is the plan's (the broken tool's length up to the tool change, the replacement's after it: the
same ``[[tools]]`` entry; a lathe's legs carry the cut's turret tool and tip offset), in the cut's work
offset.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from typing import Any

from ..lathe_solids import LatheSolids
from ..machine import Machine, RapidMode
from ..motion import Segment, SegmentKind
from ..plans.recovery import RecoveryLeg, RecoveryVariant, plan_legs, recovery_legs
from ..solids import Solids
from .geometry import arc_geom
from .lathe_solids import LatheSolidsChecker
from .result import Reason, Violation
from .solids import SolidsChecker

__all__ = ["recovery_solids", "resume_solids", "RECOVERY_PIECES"]

F0, F1 = Fraction(0), Fraction(1)
#: Pieces a cutting line's break points may be cut into before the recovery of the solids is ``unknown``.
RECOVERY_PIECES = 32

Box = tuple[tuple[Fraction, Fraction], ...]


class _IntervalTerms:
    """The plan's arithmetic over closed intervals ``(lo, hi)``: exact images of boxes."""

    def number(self, v: Fraction) -> tuple[Fraction, Fraction]:
        return v, v

    def plus(self, a: tuple[Fraction, Fraction], d: Fraction) -> tuple[Fraction, Fraction]:
        return a[0] + d, a[1] + d

    def maximum(self, a: tuple[Fraction, Fraction], b: tuple[Fraction, Fraction]) -> tuple[Fraction, Fraction]:
        return max(a[0], b[0]), max(a[1], b[1])


def recovery_solids(segs: list[Segment], machine: Machine, solids: Solids | LatheSolids, cfg: Any, replacement: Any,
                    starts: dict[int, tuple[Fraction, ...]], max_violations: int
                    ) -> tuple[list[Violation], list[Reason]]:
    """The recovery legs from every break point of every cutting motion ``segs[i]`` in ``starts`` (its motion
    sequence's start, the restart point of the ``start`` variant), proved for the tool solids;
    ``replacement(L)`` is the replacement tool's length.  (violations, reasons)"""
    violations: list[Violation] = []
    reasons: list[Reason] = []
    for i, start in starts.items():
        if len(violations) >= max_violations:
            break
        seg = segs[i]
        v, why = _one_motion(seg, machine, solids, cfg, replacement(seg.tool_length), start)
        if v is not None:
            violations.append(v)
        reasons += [r for r in why if r.message not in {x.message for x in reasons}]
    return violations, reasons


def _one_motion(seg: Segment, machine: Machine, solids: Solids | LatheSolids, cfg: Any, L2: Fraction,
                start: tuple[Fraction, ...]) -> tuple[Violation | None, list[Reason]]:
    """The recovery from every break point of ``seg``: a witness, or the reasons it is not proved."""
    if seg.kind is SegmentKind.ARC:
        g = arc_geom(seg)
        arc_box = [(min(a, b), max(a, b)) for a, b in zip(seg.start, seg.end)]
        arc_box[g.ia], arc_box[g.ib] = g.plane_bbox()
        queue: list[tuple[Fraction, Fraction, Box]] = [(F0, F1, tuple(arc_box))]
    else:
        queue = [(F0, F1, _line_box(seg, F0, F1))]
    budget = RECOVERY_PIECES
    while queue:  # breadth first: the pieces are refined evenly, their ends and middles tried as witnesses
        s0, s1, box = queue.pop(0)
        v, why = _piece(seg, machine, solids, cfg, L2, start, box, _at(seg, s0), s0)
        if v is not None:
            return v, []
        if why is None:  # proved for the piece
            continue
        if why:
            return None, why
        m = (s0 + s1) / 2
        for s in (F1,) if seg.kind is SegmentKind.ARC else (m, s1):  # exact points of the path
            v, _ = _piece(seg, machine, solids, cfg, L2, start, _line_box(seg, s, s), seg.end if s == F1 else
                          _at(seg, s), s)
            if v is not None:
                return v, []
        if seg.kind is SegmentKind.ARC or budget <= 0:
            what = "the arc's" if seg.kind is SegmentKind.ARC else "the motion's"
            return None, [Reason(f"tool-break recovery with tool solids: from {what} break points the legs pass "
                                 "close to a fixture and the proof could not decide (no witness was found at the "
                                 "pieces' ends)", seg.span, seg.block, "VF220")]
        budget -= 1
        queue += [(s0, m, _line_box(seg, s0, m)), (m, s1, _line_box(seg, m, s1))]
    return None, []


def _at(seg: Segment, s: Fraction) -> tuple[Fraction, ...]:
    return tuple(p + s * (q - p) for p, q in zip(seg.start, seg.end))


def _line_box(seg: Segment, s0: Fraction, s1: Fraction) -> Box:
    return tuple((min(x, y), max(x, y)) for x, y in zip(_at(seg, s0), _at(seg, s1)))


def _piece(seg: Segment, machine: Machine, solids: Solids | LatheSolids, cfg: Any, L2: Fraction,
           start: tuple[Fraction, ...], box: Box, P0: tuple[Fraction, ...], s0: Fraction
           ) -> tuple[Violation | None, list[Reason] | None]:
    """The legs from every break point in ``box`` (``P0`` one of them, on the path): (a witness at ``P0``,
    None) / (None, None) proved / (None, []) undecided / (None, reasons) not known."""
    axes = machine.axis_names
    restart_box = box if cfg.variant is RecoveryVariant.BREAKPOINT else tuple((v, v) for v in start)
    family = plan_legs(cfg, machine, box, restart_box, seg.tool_length, L2, _IntervalTerms())
    R0 = P0 if cfg.variant is RecoveryVariant.BREAKPOINT else start
    nominal = recovery_legs(cfg, machine, P0, R0, seg.tool_length, L2)
    ix = [axes.index(a) for a in ("XZ" if isinstance(solids, LatheSolids) else "XYZ")]
    undecided = False
    for fam, leg in zip(family, nominal):
        dogleg = leg.kind is SegmentKind.RAPID and machine.rapid_mode is not RapidMode.LINEAR
        shift = tuple(_reach(fam.start[i], fam.end[i], leg.start[i], leg.end[i], dogleg) for i in ix)
        checker = _checker(machine, solids, shift)
        checker.feed(_leg_segment(leg, axes, seg))
        if checker.violations and all(lo == hi == 0 for lo, hi in shift):
            return _recovery_violation(checker.violations[0], seg, cfg, leg.name, P0, s0, axes), None
        if checker.violations or any(r.code == "VF218" for r in checker.reasons):
            if not checker.violations:
                undecided = True
                continue
            exact = _checker(machine, solids, None)  # the displaced family met: is P0's leg in it?
            exact.feed(_leg_segment(leg, axes, seg))
            if exact.violations:
                return _recovery_violation(exact.violations[0], seg, cfg, leg.name, P0, s0, axes), None
            undecided = True
        elif checker.reasons:
            return None, [replace(r, message="tool-break recovery, leg " + repr(leg.name) + ": " + r.message)
                          for r in checker.reasons]
    return None, ([] if undecided else None)


def _checker(machine: Machine, solids: Solids | LatheSolids, shift: Any) -> Any:
    """The solids proof of one leg displaced within ``shift`` (per axis X, Y, Z on a mill, X, Z on a lathe; None:
    not displaced), fed by hand (no batching)."""
    if isinstance(solids, LatheSolids):  # a lathe's turret tools (nczones.lathe_solids), not a zone kind
        return LatheSolidsChecker(machine, solids, shift=shift)
    return SolidsChecker(machine, solids, shift=shift, screen=False)


def _leg_segment(leg: RecoveryLeg[Fraction], axes: tuple[str, ...], seg: Segment) -> Segment:
    """A recovery leg from a break in ``seg`` as a motion, in the cut's frame (with its tip offset and turret
    tool: :meth:`nczones.plans.recovery.RecoveryLeg.segment`)."""
    return replace(leg.segment(axes, seg), frame=seg.frame)


def _reach(a: tuple[Fraction, Fraction], b: tuple[Fraction, Fraction], a0: Fraction, b0: Fraction,
           dogleg: bool) -> tuple[Fraction, Fraction]:
    """The displacement interval of a leg's point on one axis (module docstring)."""
    da, db = (a[0] - a0, a[1] - a0), (b[0] - b0, b[1] - b0)
    if dogleg:
        r = max(abs(da[0]), abs(da[1])) + max(abs(db[0]), abs(db[1]))
        return -r, r
    return min(F0, da[0], db[0]), max(F0, da[1], db[1])


def _recovery_violation(v: Violation, seg: Segment, cfg: Any, leg: str, P0: tuple[Fraction, ...], s: Fraction,
                        axes: tuple[str, ...]) -> Violation:
    from ..exact import format_decimal

    note = (f"tool break in line {seg.line} at s = {format_decimal(s, 9)}; {cfg.variant.value} restart; on the "
            f"{leg} leg the {v.note}")
    return replace(v, kind="recovery", block=seg.block, span=seg.span, break_line=seg.line, break_parameter=s,
                   break_point=tuple(zip(axes, P0)), leg=leg, note=note)


def resume_solids(segs: list[Segment], machine: Machine, solids: Solids | LatheSolids, replacement: Any, shift: Any,
                  max_violations: int) -> tuple[list[Violation], list[Reason]]:
    """The resumed cut with a replacement tool of another length, for the tool solids: every motion run with
    a tool that has cut before is checked shifted along the tool axis by the length's change (``shift(seg,
    L2)``, as :func:`nczones.prover.recovery.verify_recovery` checks the controlled point)."""
    checker = _checker(machine, solids, None)  # fed one by one, never flushed: no batching
    seen: dict[tuple, Segment] = {}
    for seg in segs:
        if len(checker.violations) >= max_violations:
            break
        key = (seg.tool_length, seg.tool_register)
        if seg.kind in (SegmentKind.LINE, SegmentKind.ARC):
            seen.setdefault(key, seg)
        brk = seen.get(key)
        L2 = replacement(seg.tool_length)
        if brk is not None and L2 != seg.tool_length:
            checker.feed(shift(seg, L2))
    out = []
    for v in checker.violations:
        brk_line = next((b.line for b in seen.values() if b.block <= v.block), None)
        out.append(replace(v, kind="recovery", break_line=brk_line, break_parameter=F0, leg="resume",
                           note=f"after a tool break, the resumed cut with the replacement tool: {v.note}"))
    return out, list(checker.reasons)
