"""Automatic tool-break recovery, run by the reference controller (DESIGN §6).

The plan — which legs, to where, with which tool — is :mod:`nczones.plans.recovery`
(``specs/recovery.md``); this module runs it pulse by pulse: the break after
a given fraction of a cutting motion's interpolation steps, the recovery legs
through the controller's own interpolation and limit monitor, the resumed cut
pulse for pulse.  :mod:`nczones.prover.recovery` proves the same plan for every
break point.
"""

from __future__ import annotations

import math
from dataclasses import replace
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import Diagnostic, InputError, InvalidArgument
from ..motion import Segment, segments_of
from ..plans.recovery import (
    RecoveryVariant,
    is_cutting,
    recovery_legs,
    replacement_length,
    same_tool,
    shift_segment,
    tool_axis_index,
    tool_change_config,
)

__all__ = ["run_with_break", "record_pulses"]


# --------------------------------------------------------------------------- the controller side


def _split(plan: Any, k: int) -> tuple[Any, Any]:
    """The plan's first ``k`` steps and the rest, as two explicit plans."""
    n = plan.n
    pos = np.asarray(plan.chunk(0, n), dtype=np.int64).reshape(n, len(plan.p0))
    sig = plan.sigma if plan.sigma is not None else np.arange(1, n + 1, dtype=float) / n
    sk = float(sig[k - 1]) if k > 0 else 0.0
    T = plan.base_time_s
    first = rest = None
    if k > 0:
        first = type(plan)(plan.seg, plan.p0, tuple(int(v) for v in pos[k - 1]), k, positions=pos[:k],
                      sigma=sig[:k] / sk if sk > 0 else np.ones(k), base_time_s=T * sk, accdec=plan.accdec,
                      speed_mm_s=plan.speed_mm_s)
    if k < n:
        p0 = tuple(int(v) for v in pos[k - 1]) if k > 0 else plan.p0
        rem = 1.0 - sk
        rest = type(plan)(plan.seg, p0, plan.p1, n - k, positions=pos[k:],
                     sigma=(sig[k:] - sk) / rem if rem > 0 else np.ones(n - k), base_time_s=T * rem,
                     accdec=plan.accdec, speed_mm_s=plan.speed_mm_s)
    return first, rest


def _shift_plan(plan: Any, axis: int | None, dp: int) -> Any:
    if plan is None or axis is None or dp == 0:
        return plan
    pos = plan.positions.copy()
    pos[:, axis] += dp
    sh = lambda p: tuple(v + dp if k == axis else v for k, v in enumerate(p))  # noqa: E731
    return type(plan)(plan.seg, sh(plan.p0), sh(plan.p1), plan.n, positions=pos, sigma=plan.sigma,
                      base_time_s=plan.base_time_s, accdec=plan.accdec, speed_mm_s=plan.speed_mm_s)


def _mark_recovery(ctl: Any, before: int, leg: str) -> None:
    for i in range(before, len(ctl.alarms)):
        a = ctl.alarms[i]
        ctl.alarms[i] = replace(a, kind="recovery", derived=f"tool-break recovery: {leg}")


def run_with_break(ctl: Any, motion: Any) -> Any:
    """Run ``motion`` on ``ctl`` with the tool-break event ``ctl.break_at`` (called by ``Controller.run``).

    The break happens in the first cutting motion of source line ``line``
    after ``floor(fraction * n)`` of its ``n`` interpolation steps.  The
    event log gets ``sequence-start``, ``tool-break``, ``recovery`` (one per
    leg, with its end point), ``tool-change`` and ``resume`` entries; alarms
    during the recovery have ``kind == "recovery"`` and name the leg in
    ``derived``.

    Invariant: the resumed cut is the uninterrupted run's cut, pulse for
    pulse (shifted by the length difference on the tool axis), from the
    break step (``breakpoint``) or from the sequence start (``start``).

    >>> from nczones.machine import load_machine
    >>> from nczones.gcode import interpret
    >>> from nczones.controller import simulate
    >>> m = load_machine("specs/examples/machines/mill_toolchange.toml")
    >>> prog = "specs/examples/programs/recovery_clamp.ngc"
    >>> r = simulate(interpret(prog, m), m, break_at=(5, Fraction(1, 2)))
    >>> r.alarms[0].kind, r.alarms[0].derived, r.alarms[0].zone
    ('recovery', 'tool-break recovery: to tool change', 'clamp')
    """
    line, fraction = ctl.break_at
    fraction = Fraction(fraction)
    if not 0 <= fraction <= 1:
        raise InvalidArgument(f"break fraction {fraction}: must be between 0 and 1")
    cfg = tool_change_config(ctl.machine)
    machine = ctl.machine
    axes = ctl.axes
    ti = tool_axis_index(machine)
    if ctl.mode.value != "lock" and not ctl.alarms:
        bad = ctl.monitor.check(tuple(ctl.counter), ctl.tool_length)
        if bad:
            ctl.record_alarm(None, tuple(ctl.counter), bad, (), note="start position outside the allowed set")
    seq: list[Segment] = []  # the current motion sequence (what a `start` restart re-runs)
    seq_start: tuple[int, ...] | None = None  # the sequence-start register (pulses)
    prev: Segment | None = None
    broken = False
    shift: tuple[Fraction, Fraction, Segment] | None = None  # (delta, new length, broken segment)
    skipped = 0

    def run_seg(seg: Segment) -> None:
        ctl.tool_length = seg.tool_length
        ctl.run_segment(seg)

    for seg in segments_of(motion):
        if ctl.halted:
            skipped += 1
            continue
        if shift is not None and same_tool(seg, shift[2]):
            seg = shift_segment(seg, ti, shift[0], shift[1])
        elif shift is not None:
            shift = None  # the program changed the tool: its own lengths apply again
        if is_cutting(seg):
            if prev is None or not same_tool(prev, seg):
                seq, seq_start = [], tuple(ctl.prog)
                ctl.log("sequence-start", seg.block, seg.line,
                         (("position", dict(zip(axes, ctl.mm(seq_start)))),))
            seq.append(seg)
            prev = seg
        else:
            prev = None
        if broken or not is_cutting(seg) or seg.line != line:
            run_seg(seg)
            continue
        # the break
        broken = True
        ctl.tool_length = seg.tool_length
        plan = ctl.plan(seg)
        k = math.floor(fraction * plan.n)
        first, rest = _split(plan, k) if plan.n else (None, None)
        if first is not None:
            ctl.run_plan(seg, first)
        if ctl.halted:
            continue
        P = ctl.mm(ctl.prog)
        L = seg.tool_length
        L2 = replacement_length(cfg, machine, L)
        restart = ctl.mm(seq_start) if cfg.variant is RecoveryVariant.START else P
        ctl.log("tool-break", seg.block, seg.line, (
            ("step", k), ("of_steps", plan.n), ("position", dict(zip(axes, P))),
            ("sequence_start", dict(zip(axes, ctl.mm(seq_start)))), ("variant", cfg.variant.value),
            ("saved", {"block": seg.block, "line": seg.line, "feed": seg.feed_mm_min, "tool_length": L}),
        ))
        for leg in recovery_legs(cfg, machine, P, restart, L, L2):
            if leg.name == "to restart":
                ctl.log("tool-change", seg.block, seg.line, (("old_length", L), ("new_length", L2),
                                                              ("register", cfg.length_register)))
            before = len(ctl.alarms)
            run_seg(leg.segment(axes, seg))
            ctl.log("recovery", seg.block, seg.line, (("leg", leg.name), ("end", dict(zip(axes, leg.end)))))
            _mark_recovery(ctl, before, leg.name)
            if ctl.halted:
                break
        if ctl.halted:
            continue
        delta = L2 - L
        ctl.log("resume", seg.block, seg.line, (("variant", cfg.variant.value),
                                                 ("position", dict(zip(axes, ctl.mm(ctl.prog))))))
        if delta != 0 or L2 != L:
            shift = (delta, L2, seg)
        if cfg.variant is RecoveryVariant.BREAKPOINT:
            if rest is not None:
                dp = 0 if ti is None else ctl.prog[ti] - (first.p1[ti] if first is not None else plan.p0[ti])
                ctl.tool_length = L2
                ctl.run_plan(replace(seg, tool_length=L2), _shift_plan(rest, ti, dp))
        else:
            for s in seq:  # re-cut the sequence from its start, then go on
                if ctl.halted:
                    break
                run_seg(shift_segment(s, ti, delta, L2))
    if not broken and not ctl.halted:
        raise InputError(Diagnostic("SM110", f"--break-at {line}: line {line} has no cutting motion (G1, G2, G3) "
                                    "that ran; a tool can only break while cutting", file="<command line>"))
    if ctl.halted and skipped:
        ctl.log("halt", data=(("blocks_not_run", skipped),))
    if not ctl.halted:
        ctl.final_sample()
        ctl.completed = not ctl.halted
    ctl.log("end", data=(("completed", ctl.completed),))
    if not broken:
        ctl.notes.append(f"the run stopped before line {line}: no tool break happened")
    return ctl.result()


def record_pulses(ctl: Any) -> list[tuple[int, str, np.ndarray]]:
    """Record every interpolation step the controller runs: ``[(block, derived, positions (n, axes))]``.

    For tests and notebooks: wraps this controller's ``_run_plan``.
    """
    log: list[tuple[int, str, np.ndarray]] = []
    inner = ctl.run_plan

    def wrapped(seg, plan):
        steps0 = ctl.steps
        inner(seg, plan)
        done = ctl.steps - steps0
        if done:
            log.append((seg.block, seg.derived, np.asarray(plan.chunk(0, done), dtype=np.int64).reshape(done, len(plan.p0))))

    ctl.run_plan = wrapped
    return log
