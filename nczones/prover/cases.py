"""Cases of one verification: parameter boxes split where the path branches, merged results.

The interpreter builds the path at nominal parameter values and carries, per
coordinate, the parameters it depends on; the prover then proves that path
for every value of the ranges.  That is sound only while every branch the
interpreter took (a canned cycle's "R above the initial level?", ...) is
the same for every value of the ranges.  When a branch switches inside a
range (``Interpreter.branch_split``), the range is cut at the switching
value into cases — the two open sides and the switching value itself —
and each case is interpreted with its nominal values moved inside it
(:func:`centred`), so its path is the real one for all its values.

:func:`merge` combines the results of several cases (parameter cases, and
the block-delete switch positions) into one :class:`Result`.
"""

from __future__ import annotations

from fractions import Fraction
from types import MappingProxyType

from ..errors import SourceSpan
from ..machine import Machine
from ..precompiled import replace  # dataclasses.replace without importing dataclasses (start-up)
from .result import ParamRange, Reason, Result, Verdict, Violation

__all__ = ["centred", "split_box", "merge", "MAX_CASES"]

F0 = Fraction(0)
#: At most this many interpretations for one program (each split adds at most 2).
MAX_CASES = 25


def _contains(r: ParamRange, x: Fraction) -> bool:
    above = r.lo < x or (r.lo == x and not r.lo_open)
    below = x < r.hi or (x == r.hi and not r.hi_open)
    return above and below


def centred(machine: Machine, ranges: tuple[ParamRange, ...]) -> tuple[Machine, tuple[ParamRange, ...]]:
    """The machine with every ranged value moved inside its range, and the ranges relative to it.

    A range that holds the machine file's value keeps it (``centre`` 0);
    another gets the middle of the range.  Homing errors (``home.X``) are
    not interpreted, they stay as they are.

    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('[machine]\\naxes=["X","Z"]\\n[machine.rapid]\\nX="1"\\nZ="1"\\n'
    ...                   '[machine.reference]\\nX="0"\\nZ="0"\\n[tool_lengths]\\nH1="200"\\n')
    >>> F = Fraction
    >>> m2, (r,) = centred(m, (ParamRange("H1", F(10), F(30), (F(210), F(230)), absolute=True),))
    >>> m2.tool_length(1), r.lo, r.hi, r.centre
    (Fraction(220, 1), Fraction(-10, 1), Fraction(10, 1), Fraction(20, 1))
    """
    offsets = {k: list(v) for k, v in machine.offsets.items()}
    tools = dict(machine.tool_lengths)
    start = list(machine.start)
    axes = machine.axis_names
    out = []
    for r in ranges:
        base = replace(r, lo=r.lo + r.centre, hi=r.hi + r.centre, centre=F0)
        if r.name.startswith("home.") or _contains(base, F0):
            c = F0
        else:
            c = (base.lo + base.hi) / 2
        if c:
            if r.absolute:
                reg = int(r.name[1:])
                tools[reg] = machine.tool_length(reg) + c
            else:
                head, axis = r.name.rsplit(".", 1)
                k = axes.index(axis)
                if head == "start":
                    start[k] += c
                else:
                    offsets.setdefault(head, list(machine.offset(head)))[k] += c
        out.append(replace(base, lo=base.lo - c, hi=base.hi - c, centre=c))
    m2 = replace(machine, offsets=MappingProxyType({k: tuple(v) for k, v in offsets.items()}),
                 tool_lengths=MappingProxyType(tools), start=tuple(start))
    return m2, tuple(out)


def split_box(ranges: tuple[ParamRange, ...], name: str, at: Fraction) -> list[tuple[ParamRange, ...]]:
    """The cases of ``ranges`` cut at deviation ``at`` of parameter ``name``: below, at, above.

    Deviations are from the machine file's value (``centre`` 0 in the result).

    >>> F = Fraction
    >>> r = ParamRange("G54.X", F(-1), F(1), (F(-1), F(1)))
    >>> [(c[0].lo, c[0].hi, c[0].lo_open, c[0].hi_open) for c in split_box((r,), "G54.X", F(1, 2))]
    [(Fraction(-1, 1), Fraction(1, 2), False, True), (Fraction(1, 2), Fraction(1, 2), False, False), (Fraction(1, 2), Fraction(1, 1), True, False)]
    """
    out = []
    for side in ("below", "at", "above"):
        case: list[ParamRange] | None = []
        for r in ranges:
            base = replace(r, lo=r.lo + r.centre, hi=r.hi + r.centre, centre=F0)
            if r.name == name:
                if side == "below":
                    base = replace(base, hi=at, hi_open=True)
                elif side == "at":
                    base = replace(base, lo=at, hi=at, lo_open=False, hi_open=False)
                else:
                    base = replace(base, lo=at, lo_open=True)
                if base.lo > base.hi or (base.lo == base.hi and (base.lo_open or base.hi_open)) \
                        or (side == "at" and not _contains(replace(r, lo=r.lo + r.centre, hi=r.hi + r.centre), at)):
                    case = None
                    break
            assert case is not None
            case.append(base)
        if case is not None:
            out.append(tuple(case))
    return out


def merge(results: list[Result], *, max_violations: int, params: tuple[ParamRange, ...]) -> Result:
    """One result from the results of several cases (each already complete with notes and spans).

    Violations: every case's, without repeating a block that an earlier case
    already reported (or, across block-delete positions, a source line and
    zone), in execution order within a case; reasons and notes: the union.
    """
    if len(results) == 1:
        return replace(results[0], params=params)
    violations: list[Violation] = []
    seen: set[tuple] = set()
    seen_lines: set[tuple] = set()
    reasons: list[Reason] = []
    seen_r: set[tuple] = set()
    notes: list[str] = []
    stats: dict[str, int] = {}
    timings: dict[str, float] = {}
    engines: dict[int, str] = {}
    for res in results:
        for v in res.violations:
            key = (v.switches, v.block, v.kind, v.break_line)
            line_key = (v.line, v.zone, v.kind, v.break_line)
            if key in seen or (v.switches and line_key in seen_lines):
                continue
            seen.add(key)
            seen_lines.add(line_key)
            violations.append(v)
        for r in res.reasons:
            rkey = (r.message, r.code, None if r.span is None else r.span.line)
            if rkey not in seen_r:
                seen_r.add(rkey)
                reasons.append(r)
        for note in res.notes:
            if note not in notes:
                notes.append(note)
        for k, n in res.stats:
            stats[k] = stats.get(k, 0) + n
        for k, t in res.timings:
            timings[k] = timings.get(k, 0.0) + t
        for b, e in res.engines:
            engines.setdefault(b, e)
    violations.sort(key=lambda v: (v.switches, v.block, v.kind != "motion"))
    truncated = any(r.truncated for r in results) or len(violations) > max_violations
    violations = violations[:max_violations]
    verdict = Verdict.UNSAFE if violations else (Verdict.UNKNOWN if reasons else Verdict.SAFE)
    first = results[0]
    return replace(first, verdict=verdict, violations=tuple(violations), reasons=tuple(reasons), notes=tuple(notes),
                   stats=tuple(stats.items()), timings=tuple(timings.items()), engines=tuple(sorted(engines.items())),
                   truncated=truncated, params=params, interrupted=any(r.interrupted for r in results))


def budget_reason(span: SourceSpan | None) -> Reason:
    """Why a verification whose path branched too often inside the ranges is unknown."""
    return Reason(f"the path branches inside a parameter range more often than {MAX_CASES} cases allow; "
                  "verify narrower ranges", span, None, "VF201")
