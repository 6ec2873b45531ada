"""A ranged witness must replay: the program re-interpreted at each witness's parameter values.

Over parameter ranges the prover finds a violating motion and a parameter
value at which it violates; it does not ask whether the control runs the
program up to that motion at that value.  Elsewhere in the range an earlier
block may be refused (LinuxCNC's "arc end point is off its circle", a Fanuc R
arc too short), a branch may end the program: the witness then names a
motion the machine never makes, and an ``unsafe`` verdict must carry an
exact, replayable witness (docs/design.md).

:func:`replayed_witnesses` re-interprets the program at every reported
witness's values, as nominal values with no ranges (the way ``nczones
replay`` builds the machine of a counterexample), up to the witness's line,
and drops the witnesses it does not reach.

Soundness: this step only removes violations, and a result left with none
is ``unknown`` (VF232), never ``safe``: the range proof failed at those
values, and nothing here proves the rest of the range.  A witness that the
re-interpretation reaches is kept unchanged.  The cost is one interpretation
(up to the furthest witness line) per distinct set of witness values, and
only for ranged results with violations.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import InputError
from ..precompiled import replace
from ..prover.result import Reason, Result, Verdict, Violation

if TYPE_CHECKING:
    from fractions import Fraction

    from ..gcode.source import ProgramSource
    from ..machine import Machine
    from ..prover.options import VerifyOptions

__all__ = ["replayed_witnesses"]

#: the error code of a ranged result whose every witness lies where the control stops before its line
REFUSED_CODE = "VF232"


def replayed_witnesses(result: Result, source: ProgramSource, machine: Machine, options: VerifyOptions,
                       skip: frozenset[int]) -> Result:
    """``result`` without the violations whose parameter values do not run the program to their line.

    Parameters
    ----------
    result : Result
        A result over parameter ranges (``options.params``); its violations name their values (``params``).
    source, machine, options, skip
        What the result was proved from: the program, the machine (before any case's centring), the
        options and the block-skip switches on.

    Returns
    -------
    Result
        ``result`` itself when every witness replays (or there is none with values); else the kept
        violations, a note per dropped witness, and — none kept — the verdict ``unknown`` with a VF232
        reason per refusal.
    """
    groups: dict[tuple[tuple[str, Fraction], ...], list[Violation]] = {}
    for v in () if result.interrupted else result.violations:
        if v.params and v.kind == "motion" and v.span is not None:
            groups.setdefault(tuple(v.params), []).append(v)
    dropped: dict[int, str] = {}
    for params, group in groups.items():
        why = _unreached(source, machine, options, skip, params, {(v.span.file, v.span.line) for v in group})
        dropped.update({id(v): why[(v.span.file, v.span.line)] for v in group if (v.span.file, v.span.line) in why})
    if not dropped:
        return result
    kept = tuple(v for v in result.violations if id(v) not in dropped)
    notes = tuple(f"a witness of line {v.line} was dropped: {dropped[id(v)]}" for v in result.violations
                  if id(v) in dropped)
    if kept:
        return replace(result, violations=kept, notes=tuple(result.notes) + notes)
    reasons = tuple(Reason(f"{REFUSED_CODE}: {why}", v.span, v.block, REFUSED_CODE)
                    for v in result.violations for why in (dropped[id(v)],))
    return replace(result, verdict=Verdict.UNKNOWN, violations=(), reasons=tuple(result.reasons) + reasons,
                   truncated=False)


def _unreached(source: ProgramSource, machine: Machine, options: VerifyOptions, skip: frozenset[int],
               params: tuple[tuple[str, Fraction], ...], lines: set[tuple[str, int]]) -> dict[tuple[str, int], str]:
    """The ``(file, line)`` of ``lines`` that the program at ``params`` (nominal values) does not move on
    before it stops, each with why: a refused block, or the program's end (or an unsupported code)."""
    from ..replay import machine_at_values
    from .verification import interpretation

    at = ", ".join(f"{n} = {_written(x)}" for n, x in params)
    run = interpretation(source, machine_at_values(machine, dict(params)), replace(options, params=()), skip=skip)
    todo = set(lines)
    try:
        for seg in run.segments():
            if seg.span is not None:
                todo.discard((seg.span.file, seg.span.line))
                if not todo:
                    return {}
    except InputError as exc:
        d = exc.diagnostics[0]
        where = f"line {d.span.line}" if d.span is not None else d.location()
        why = (f"a witness at values where the control refuses an earlier block, {where}: {d.message} "
               f"[{d.code}] ({at})")
        return {k: why for k in todo}
    stop = f"; {run.unsupported[0].reason}" if run.unsupported else ""
    why = f"a witness at values where the program stops before its line ({at}{stop})"
    return {k: why for k in todo}


def _written(x: Fraction) -> str:
    from ..exact import format_rational

    return format_rational(x)
