"""A ranged witness must replay: the program re-interpreted at each witness's parameter values.

Over parameter ranges the prover finds a violating motion and a parameter
value at which it violates; it does not ask whether the control runs the
program at that value.  Elsewhere in the range a block may be refused
(LinuxCNC's "arc end point is off its circle", a Fanuc R arc too short), a
branch may end the program: the witness then names a motion the machine never
makes, and an ``unsafe`` verdict must carry an exact, replayable witness
(docs/design.md).

:func:`replayed_witnesses` re-interprets the whole program at every reported
witness's values, as nominal values with no ranges (the way ``nczones replay``
builds the machine of a counterexample), and keeps a witness only when
``nczones replay`` would confirm it there: the motion of its **block** — its
occurrence in execution order (``Violation.block``, ``Segment.block``: a
loop's passes and a subprogram's calls are blocks of their own), not its
``(file, line)`` — is made at those values, the witness's path point lies on
that motion (exactly; an irrational path point, marked ``on_path = False``,
within :data:`nczones.witness_geometry.IRRATIONAL_TOLERANCE_MM`), and its point lies
within the margin of the path point, outside the allowed set, in the zone it
names (exact: :func:`nczones.witness_geometry.motion_witness_replays`).  A loop's later
pass through a line is therefore not confirmed by its first pass, nor a
witness by a motion of its line that does not carry its point.

Why matching by block is exact: the prover's path is built at the case's
nominal values, and a block's index counts the blocks executed before it.
Within a case no branch and no loop count depends on a ranged parameter (a
read of a ranged value is ``unknown``, a canned cycle's branch that switches
splits the case), so the replay at values inside the case executes the same
blocks in the same order up to the first block it refuses; the index of the
witness's block is its index there.  The replay does not lean on this: a
witness whose block the replay does not make, or makes without its point, is
dropped, never kept on trust.

Soundness: this step only removes violations, and a result left with none
is ``unknown``, never ``safe``: the range proof failed at those values, and
nothing here proves the rest of the range.  A witness that replays is kept
unchanged.  A witness is dropped when

* the control refuses a block at its values: an earlier block, so it never
  gets there; or a later one, since the control stops the program at the
  error and need not make the motions it has read ahead (LinuxCNC discards
  what its interpreter queued past the machine; Fanuc stops on the alarm),
  and ``nczones verify`` and ``nczones replay`` give that error there, not
  the witness; the program's end (or an unsupported code) before its block:
  a note, or with none kept a ``VF232`` reason;
* its block runs at its values but its motion does not carry its point, or
  the point is not in its zone there: a note, or with none kept a ``VF231``
  reason (it does not replay);
* the run's budget (``--budget``, the same :class:`~nczones.prover.limits.RunLimits`
  as the proof's) is spent before its replay ends: it was not shown to
  replay, so it is not reported as a witness, and a ``VF203`` reason names
  it (raise ``--budget``);
* Ctrl-C or SIGTERM stops the run (during the proof or the replays): the
  same, with a ``VF204`` reason, and the result is marked ``interrupted``
  (a partial report);
* another witness of its line and zone replayed already and its values have
  no other line or zone to check: a note (one replay fewer; the line keeps
  its witness of that zone).

The cost is one interpretation of the whole program per distinct set of
witness values that still has a line to show (a refusal after the witness
must be seen too), holding only the motions of the witnesses' blocks, and
only for ranged results with violations; every one draws on the run's budget
(its loops ask :func:`nczones.gcode.program.interpretation_spent` while it is
watched) and stops at once on Ctrl-C (no solver query runs in it: Python's
own handler raises ``KeyboardInterrupt``).
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
    from typing import Any

    from ..gcode import Interpretation
    from ..machine import Machine
    from ..motion import Segment
    from ..prover.limits import RunLimits

    _Values = tuple[tuple[str, Fraction], ...]
    _Where = tuple[str, int]

__all__ = ["concrete_machine", "replayed_witnesses"]

#: the error code of a ranged result whose every witness lies where the control refuses a block or stops before it
REFUSED_CODE = "VF232"
#: the error code of a ranged result whose every witness's block runs at its values without its point in its zone
MISSED_CODE = "VF231"
#: the codes of a witness left unchecked: the budget spent, the run interrupted
BUDGET_CODE, INTERRUPT_CODE = "VF203", "VF204"
#: how a dropped witness is reported: as a note (another witness is kept) or a reason of this code
_REFUSED, _MISSED, _BUDGET, _INTERRUPT, _SAME_LINE = "refused", "missed", "budget", "interrupt", "same line"


def replayed_witnesses(result: Result, machine: Machine, interpret: Callable[[Machine], Interpretation],
                       limits: RunLimits | None = None) -> Result:
    """``result`` with only the violations that replay at their parameter values: their block's motion there.

    Parameters
    ----------
    result : Result
        A result over parameter ranges (``options.params``); its violations name their values (``params``).
    machine : Machine
        The machine the ranges are deviations from (before any case's centring).
    interpret : callable
        The program's interpretation on a given machine with the result's options and block-skip switches
        and no parameter ranges (``interpretation(source, m, replace(options, params=()), skip=skip)``).
    limits : RunLimits, optional
        The run's budget (the proof's): the replays draw on it and stop once it is spent.

    Returns
    -------
    Result
        ``result`` itself when every witness replays (or there is none with values); else the kept
        violations, a note per witness dropped where the control refuses a block or stops before its block
        (a ``VF232`` reason each when none is kept) or whose block runs without its point in its zone
        (``VF231``), a ``VF203``/``VF204`` reason per witness the budget or an interrupt left unchecked, and
        the verdict ``unknown`` when none is kept.
    """
    groups = _groups(result)
    if not groups:
        return result
    if result.interrupted:  # Ctrl-C during the proof: stop now, nothing replayed
        dropped, interrupted = _unchecked(groups, _INTERRUPT, _interrupt_why(limits)), True
    else:
        dropped, interrupted = _replay_groups(groups, machine, interpret, limits, result.margin)
    if not dropped:
        return result
    return _without(result, dropped, interrupted)


def _groups(result: Result) -> dict[_Values, dict[_Where, list[Violation]]]:
    """The ranged motion witnesses of ``result`` by their values, then by ``(file, line)``, in report order."""
    groups: dict[_Values, dict[_Where, list[Violation]]] = {}
    for v in result.violations:
        if v.params and v.kind == "motion" and v.span is not None:
            groups.setdefault(tuple(v.params), {}).setdefault((v.span.file, v.span.line), []).append(v)
    return groups


def _replay_groups(groups: dict[_Values, dict[_Where, list[Violation]]], machine: Machine,
                   interpret: Callable[[Machine], Interpretation], limits: RunLimits | None, margin: Fraction
                   ) -> tuple[dict[int, tuple[str, str]], bool]:
    """Replay each set of values in turn: ``({id(violation): (how, why)}`` of the dropped ones, interrupted)."""
    dropped: dict[int, tuple[str, str]] = {}
    shown: dict[tuple[str, int, str], _Values] = {}  # a (file, line, zone) that replayed, and at which values
    todo = list(groups.items())
    try:
        while todo:
            params, at_line = todo[0]
            if all((*k, v.zone) in shown for k, vs in at_line.items() for v in vs):
                # every line already replayed at other values, with a witness of the same zone: no run
                dropped.update({id(v): (_SAME_LINE, _same_line_why(shown[(*k, v.zone)]))
                                for k, vs in at_line.items() for v in vs})
            elif limits is not None and limits.budget_spent():
                break
            else:
                at_values, shift = concrete_machine(machine, dict(params))
                with limits.watch() if limits is not None else _no_limits():  # its loops ask the budget
                    unreached = _unreached(interpret, at_values, params, at_line, shift, margin)
                dropped.update(unreached)
                for k, vs in at_line.items():
                    shown.update({(*k, v.zone): params for v in vs
                                  if id(v) not in unreached and (*k, v.zone) not in shown})
            todo.pop(0)
    except KeyboardInterrupt:
        dropped.update(_unchecked(dict(todo), _INTERRUPT, _interrupt_why(limits)))
        return dropped, True
    dropped.update(_unchecked(dict(todo), _BUDGET, _budget_why(limits)))
    return dropped, False


def _unchecked(groups: dict[_Values, dict[_Where, list[Violation]]], how: str, why: str
               ) -> dict[int, tuple[str, str]]:
    """Every witness of ``groups`` as not replayed, ``how`` and ``why``."""
    return {id(v): (how, f"{why} ({_at(params)})") for params, at_line in groups.items()
            for vs in at_line.values() for v in vs}


def _budget_why(limits: RunLimits | None) -> str:
    if limits is None or limits.budget_s is None:
        return ""
    return (f"budget of {limits.budget_s:g} s spent after {limits.spent_at or limits.elapsed():.1f} s before "
            "this witness was replayed at its values, so it is not reported (raise --budget)")


def _interrupt_why(limits: RunLimits | None) -> str:
    after = f" after {limits.elapsed():.1f} s" if limits is not None else ""
    return f"interrupted (Ctrl-C){after} before this witness was replayed at its values, so it is not reported"


def _same_line_why(params: _Values) -> str:
    return f"not replayed: a witness of the same line and zone replays ({_at(params)})"


def _without(result: Result, dropped: dict[int, tuple[str, str]], interrupted: bool) -> Result:
    """``result`` without the ``dropped`` violations: notes and reasons for them, the verdict from what is kept."""
    kept = tuple(v for v in result.violations if id(v) not in dropped)
    gone = [(v, *dropped[id(v)]) for v in result.violations if id(v) in dropped]
    codes = {_BUDGET: BUDGET_CODE, _INTERRUPT: INTERRUPT_CODE} | (
        {} if kept else {_REFUSED: REFUSED_CODE, _MISSED: MISSED_CODE})
    notes = tuple(f"a witness of line {v.line} was dropped: {why}" for v, how, why in gone if how not in codes)
    reasons = tuple(Reason(f"{codes[how]}: {why}", v.span, v.block, codes[how]) for v, how, why in gone
                    if how in codes)
    out = replace(result, violations=kept, notes=tuple(result.notes) + notes,
                  reasons=tuple(result.reasons) + reasons, interrupted=result.interrupted or interrupted)
    if kept:
        return out
    return replace(out, verdict=Verdict.UNKNOWN, truncated=False)


def _unreached(interpret: Callable[[Machine], Interpretation], at_values: Machine, params: _Values,
               at_line: dict[_Where, list[Violation]], shift: tuple[Fraction, ...], margin: Fraction
               ) -> dict[int, tuple[str, str]]:
    """The witnesses of ``at_line`` (all at ``params``) that do not replay on ``at_values`` (the machine at
    ``params``, nominal values; ``shift`` the homing errors apart), ``{id(witness): (how, why)}``: the program
    refused (before or after the witness), stopped before its block (its end, an unsupported code), the run's
    budget spent on the way (unchecked), or its block's motion there without its point in its zone."""
    wanted = [v for vs in at_line.values() for v in vs]
    run = interpret(at_values)
    made, refused = _motions(run, {v.block for v in wanted})
    at = _at(params)
    if refused is not None:
        return {id(v): (_REFUSED, _refused_why(refused, v.block in made, at)) for v in wanted}
    spent = next((u for u in run.unsupported if u.code == BUDGET_CODE), None)
    if spent is not None:  # the budget ended the replay: no witness is shown either way
        why = f"{spent.reason}, before this witness was replayed at its values, so it is not reported ({at})"
        return {id(v): (_BUDGET, why) for v in wanted}
    out: dict[int, tuple[str, str]] = {}
    for v in wanted:
        if v.block not in made:
            stop = f"; {run.unsupported[0].reason}" if run.unsupported else ""
            out[id(v)] = (_REFUSED, f"a witness at values where the program stops before its line (this pass of "
                                    f"it; {at}{stop})")
            continue
        ok, found = _replays(v, made[v.block], at_values, shift, margin)
        if not ok:
            out[id(v)] = (_MISSED, f"at its values ({at}) the program runs its block, but {found}: the witness does "
                                   "not replay, so it is not reported")
    return out


def _motions(run: Interpretation, blocks: set[int]) -> tuple[dict[int, list[Segment]], InputError | None]:
    """The motions of ``run`` in ``blocks`` by block (the whole program read), and the error that refused a
    block, if one did: then also the motions the interpreter made before it and had not handed out yet."""
    made: dict[int, list[Segment]] = {}
    try:
        for seg in run.segments():
            if seg.block in blocks:
                made.setdefault(seg.block, []).append(seg)
    except InputError as exc:
        for seg in getattr(run.interpreter, "emitted", None) or ():  # made, not yet handed out in a chunk
            if getattr(seg, "block", None) in blocks:
                made.setdefault(seg.block, []).append(seg)
        return made, exc
    return made, None


def _refused_why(exc: InputError, before: bool, at: str) -> str:
    """Why a witness at values where the control refuses a block is dropped: ``before`` when its motion was made
    ahead of the refused block (the block is a later one)."""
    d = exc.diagnostics[0]
    where = f"line {d.span.line}" if d.span is not None else d.location()
    if not before:
        return f"a witness at values where the control refuses an earlier block, {where}: {d.message} [{d.code}] ({at})"
    return (f"a witness at values where the control refuses a later block, {where}: {d.message} [{d.code}] ({at}); "
            "the control stops the program at the error and need not make the motions it has read ahead, this "
            "one among them")


def _replays(v: Violation, mine: list[Segment], at_values: Machine, shift: tuple[Fraction, ...], margin: Fraction
             ) -> tuple[bool, str]:
    """Whether witness ``v`` replays on ``mine``, its block's motions at its values (``nczones replay``'s check)."""
    from ..witness_geometry import motion_witness_replays

    parameter = v.parameter if v.segment_kind == "spline" and v.parameter_exact else None
    axes = at_values.axis_names
    if not set(axes) <= set(dict(v.point)) & set(dict(v.path_point)):
        return False, f"its point does not name every axis of the machine ({', '.join(axes)})"
    return motion_witness_replays(mine, at_values, shift, margin, block=v.block, zone=v.zone,
                                  point=_coords(v.point, axes), path=_coords(v.path_point, axes), exact=v.on_path,
                                  parameter=parameter, what=v.segment_kind or "motion")


def _coords(named: tuple[tuple[str, Fraction], ...], axes: tuple[str, ...]) -> tuple[Fraction, ...]:
    """A witness's point (axis, value) pairs as a point in the machine's axis order."""
    values = dict(named)
    return tuple(values[a] for a in axes)


def _at(params: _Values) -> str:
    return ", ".join(f"{n} = {_written(x)}" for n, x in params)


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


def _no_limits() -> Any:
    """:func:`contextlib.nullcontext`, imported when first needed (a verify has limits; issue 36)."""
    from contextlib import nullcontext

    return nullcontext()

