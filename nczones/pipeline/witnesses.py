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

from fractions import Fraction
from types import MappingProxyType

from ..errors import InputError
from ..precompiled import replace
from ..prover.result import Reason, Result, Verdict, Violation

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable

    from ..gcode import Interpretation
    from ..machine import Machine

__all__ = ["concrete_machine", "replayed_witnesses"]

#: the error code of a ranged result whose every witness lies where the control stops before its line
REFUSED_CODE = "VF232"


def replayed_witnesses(result: Result, machine: Machine, interpret: Callable[[Machine], Interpretation]) -> Result:
    """``result`` without the violations whose parameter values do not run the program to their line.

    Parameters
    ----------
    result : Result
        A result over parameter ranges (``options.params``); its violations name their values (``params``).
    machine : Machine
        The machine the ranges are deviations from (before any case's centring).
    interpret : callable
        The program's interpretation on a given machine with the result's options and block-skip switches
        and no parameter ranges (``interpretation(source, m, replace(options, params=()), skip=skip)``).

    Returns
    -------
    Result
        ``result`` itself when every witness replays (or there is none with values); else the kept
        violations, a note per dropped witness, and — none kept — the verdict ``unknown`` with a VF232
        reason per refusal.
    """
    groups: dict[tuple[tuple[str, Fraction], ...], dict[tuple[str, int], list[Violation]]] = {}
    for v in () if result.interrupted else result.violations:
        if v.params and v.kind == "motion" and v.span is not None:
            groups.setdefault(tuple(v.params), {}).setdefault((v.span.file, v.span.line), []).append(v)
    dropped: dict[int, str] = {}
    for params, at_line in groups.items():
        for where, why in _unreached(interpret, concrete_machine(machine, dict(params))[0], params, set(at_line)).items():
            dropped.update({id(v): why for v in at_line[where]})
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


def _unreached(interpret: Callable[[Machine], Interpretation], at_values: Machine,
               params: tuple[tuple[str, Fraction], ...], lines: set[tuple[str, int]]) -> dict[tuple[str, int], str]:
    """The ``(file, line)`` of ``lines`` that the program on ``at_values`` (the machine at ``params``, nominal
    values) does not move on before it stops, each with why: a refused block, or the program's end (or an
    unsupported code)."""
    at = ", ".join(f"{n} = {_written(x)}" for n, x in params)
    run = interpret(at_values)
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


def concrete_machine(machine: Machine, params: dict[str, Fraction]) -> tuple[Machine, tuple[Fraction, ...]]:
    """The machine at a counterexample's parameter values, and the homing shift per axis.

    The values (``--param`` names: an offset or start deviation added, a tool length set) become nominal
    values, with no ranges; a homing error is returned apart, as a shift: it moves the machine, not the
    coordinates the control interprets in (``nczones replay`` adds it to the motion)."""
    axes = machine.axis_names
    offsets = dict(machine.offsets)
    tools = dict(machine.tool_lengths)
    start = list(machine.start)
    shift = [Fraction(0)] * len(axes)
    for name, value in params.items():
        if name.startswith("H") and name[1:].isdigit():
            tools[int(name[1:])] = value
            continue
        head, _, axis = name.rpartition(".")
        k = axes.index(axis)
        if head == "start":
            start[k] += value
        elif head == "home":
            shift[k] += value
        else:
            base = list(offsets.get(head, tuple(Fraction(0) for _ in axes)))
            base[k] += value
            offsets[head] = tuple(base)
    return (replace(machine, offsets=MappingProxyType(offsets), tool_lengths=MappingProxyType(tools),
                    start=tuple(start)), tuple(shift))


def _written(x: Fraction) -> str:
    from ..exact import format_rational

    return format_rational(x)
