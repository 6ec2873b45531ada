"""Compiler-style text report of a verification (DESIGN §8, issue 10).

One entry per violating block in execution order::

    part.ngc:5:1: violation[wheel area]: line leaves the allowed set, 90 mm deep
        G1 X50
        ^~~~~~
        point X380 Y130 is outside the allowed set (segment parameter 0.766667…)
        that is X-20 Y130 (program coordinates: G54)
        first exit at X200 Y130 (segment parameter 0.166667…); engine exact

(the second point line is the same point in the program's coordinates: the inverse of the work offset,
G92/G52, rotation, diameter mode and tool offsets at that block, see ``ProgramFrame``), then the reasons for ``unknown`` (``file:line:col: unknown[CODE]: ...``),
the notes, and a one-line summary.  Colour (ANSI) only when asked for;
:func:`use_color` decides for a stream (a terminal, ``NO_COLOR`` unset,
``TERM`` not ``dumb``).  ``deterministic=True`` leaves out everything that
changes between runs or machines (timings, the solver's version and
internal counters), for golden files.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from fractions import Fraction

from ..errors import caret_excerpt
from ..exact import format_decimal
from ..prover.result import Result, Verdict
from . import numbers

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["render_text", "use_color"]

_RESET = "\x1b[0m"
_STYLES = {
    "loc": "\x1b[1m",
    "violation": "\x1b[1;31m",
    "unknown": "\x1b[1;33m",
    "note": "\x1b[1;36m",
    "caret": "\x1b[1;32m",
    "safe": "\x1b[1;32m",
    "unsafe": "\x1b[1;31m",
}


def use_color(stream: Any) -> bool:
    """Colour for ``stream``: only a terminal, and never with ``NO_COLOR`` set or ``TERM=dumb``.

    >>> import io
    >>> use_color(io.StringIO())
    False
    """
    if os.environ.get("NO_COLOR", "") != "":
        return False
    from .progress import is_terminal

    return is_terminal(stream)


def _d(x: Fraction) -> str:
    return format_decimal(x, 12)



def _solid_lines(v: Any, loc: str, what: str, depth: str, resolution: Any, paint: Any) -> list[str]:
    """A tool solid entering a fixture: the part, the fixture, the contact point, the controlled point."""
    part = v.zones[0] if v.zones else "the tool"
    out = [f"{paint('loc', loc + ':')} {paint('violation', f'violation[{v.zone}]:')} "
           f"{what}: the {part} enters fixture `{v.zone}`, {depth} mm deep"]
    if v.span is not None and v.span.text:
        src, caret = _caret(v.span.text, v.span.column, v.span.end_column)
        out += [f"    {src}", f"    {paint('caret', caret)}"]
    out.append(f"    contact point {numbers.point(v.point, resolution)} is inside both, with the controlled point at "
               f"{numbers.point(v.path_point, resolution)} (segment parameter {_par(v.parameter, v.parameter_exact)})")
    if v.note:
        out.append(f"    note: {v.note}")
    return out


def _par(x: Fraction, exact: bool) -> str:
    return ("" if exact else "~") + format_decimal(x, 6)


def _caret(text: str, column: int, end_column: int | None) -> tuple[str, str]:
    """The source line (tabs as one space, as the lexer counts columns, cut around the caret to
    :data:`~nczones.errors.EXCERPT_CHARS`) and a caret line."""
    return caret_excerpt(text, column, end_column)


def render_text(result: Result, program: str = "", *, color: bool = False,
                deterministic: bool = False, resolution: Mapping[str, Fraction] | None = None) -> str:
    """The compiler-style report of a :class:`~nczones.prover.Result`.

    Parameters
    ----------
    result : Result
    program : str
        Name used when the result carries none (``<program>``).
    color : bool
        ANSI colours (the CLI passes :func:`use_color` of standard output).
    deterministic : bool
        Leave out timings, the solver version and solver counters.
    resolution : mapping, optional
        Axis -> pulse of the machine: points that are not short exact decimals are written rounded to
        it and marked ``≈``, depths to the finest pulse (:mod:`nczones.report.numbers`).

    Examples
    --------
    >>> from nczones.machine import load_machine
    >>> from nczones.prover import verify_text
    >>> m = load_machine("specs/machines/grinder.toml")
    >>> r = verify_text("G21 G90 G54\\nG0 X-250 Y300\\nG1 Y130 F500\\nG1 X50\\n", m, file="dip.ngc")
    >>> print(render_text(r, deterministic=True), end="")
    dip.ngc:4:1: violation[wheel area]: line leaves the allowed set, 90 mm deep
        G1 X50
        ^~~~~~
        point X380 Y130 is outside the allowed set (segment parameter 0.766667…)
        that is X-20 Y130 (program coordinates: G54)
        first exit at X200 Y130 (segment parameter 0.166667…); engine exact
    dip.ngc: unsafe: 1 violating block, the first at line 4; 3 segments checked; dialect linuxcnc; solver z3
    """
    def paint(style: str, text: str) -> str:
        return f"{_STYLES[style]}{text}{_RESET}" if color else text

    out: list[str] = []
    name = result.file or program or "<program>"
    for v in result.violations:
        loc = f"{v.span.file}:{v.span.line}:{v.span.column}" if v.span else name
        what = v.segment_kind + (f" ({v.derived})" if v.derived else "")
        if v.kind == "recovery":
            what = "recovery " + what
        depth = ("at least " if not v.depth_exact else "") + numbers.depth(v.depth, v.depth_exact,
                                                                          numbers.depth_step(resolution))
        # a tool solid in a fixture (nczones.prover.solids; on a recovery leg, nczones.prover.solids_recovery: the
        # part in ``zones``, the fixture in ``zone``, while a recovery of the controlled point lists its zone there)
        if v.kind == "solid" or (v.kind == "recovery" and v.zones and v.zone not in v.zones):
            out.extend(_solid_lines(v, loc, what, depth, resolution, paint))
            continue
        out.append(f"{paint('loc', loc + ':')} {paint('violation', f'violation[{v.zone}]:')} "
                   f"{what} leaves the allowed set, {depth} mm deep")
        if v.span is not None and v.span.text:
            src, caret = _caret(v.span.text, v.span.column, v.span.end_column)
            out.append(f"    {src}")
            out.append(f"    {paint('caret', caret)}")
        out.append(f"    point {numbers.point(v.point, resolution)} is outside the allowed set "
                   f"(segment parameter {_par(v.parameter, v.parameter_exact)})")
        in_program = numbers.program_point(v, resolution)
        if in_program is not None:
            out.append(f"    that is {in_program}")
        if v.exit_located:
            out.append(f"    first exit at {numbers.point(v.first_exit, resolution)} "
                       f"(segment parameter {_par(v.first_exit_parameter, v.first_exit_exact)}); engine {v.engine}")
        else:
            out.append(f"    first exit not located: the point above is outside, the path may leave the allowed set "
                       f"earlier; engine {v.engine}")
        others = [z for z in v.zones if z != v.zone]
        if others:
            out.append("    also outside: " + ", ".join(others))
        if result.margin:
            out.append(f"    path point {numbers.point(v.path_point, resolution)} is closer than the margin {_d(result.margin)} mm")
        if v.params:
            out.append("    with parameters " + ", ".join(f"{n}={_d(x)}" for n, x in v.params))
        for switch, position in v.switches:
            out.append(f"    with the {switch.replace('_', '-')} switch {position}")
        if v.note:
            out.append(f"    note: {v.note}")
    for r in result.reasons:
        loc = f"{r.span.file}:{r.span.line}:{r.span.column}" if r.span else name
        tag = f"unknown[{r.code}]:" if r.code else "unknown:"
        message = r.message
        if r.code and message.startswith(r.code + ": "):
            message = message[len(r.code) + 2:]
        out.append(f"{paint('loc', loc + ':')} {paint('unknown', tag)} {message}")
        if r.span is not None and r.span.text:
            src, caret = _caret(r.span.text, r.span.column, r.span.end_column)
            out.append(f"    {src}")
            out.append(f"    {paint('caret', caret)}")
    for n in result.notes:
        out.append(f"{paint('loc', name + ':')} {paint('note', 'note:')} {n}")
    out.append(summary_line(result, name, color=color, deterministic=deterministic))
    return "\n".join(out) + "\n"


def summary_line(result: Result, name: str, *, color: bool = False, deterministic: bool = False) -> str:
    """The one-line summary that ends the text report."""
    stats = dict(result.stats)
    verdict = result.verdict.label
    if color:
        verdict = f"{_STYLES.get(verdict, _STYLES['unknown'])}{verdict}{_RESET}"
    n = len(result.violations)
    if result.verdict is Verdict.UNSAFE:
        first = result.violations[0].line
        what = f"{n} violating block{'s' if n != 1 else ''}" + (" (list truncated)" if result.truncated else "")
        if first is not None:
            what += f", the first at line {first}"
    elif result.verdict is Verdict.UNKNOWN:
        k = len(result.reasons)
        what = f"not proved, {k} reason{'s' if k != 1 else ''}"
        if result.reasons and result.reasons[0].span is not None:
            what += f", the first at line {result.reasons[0].span.line}"
    elif stats.get("segments", 0) == 0:
        what = "the program has no motion (nothing can leave the allowed set)"
    else:
        what = "every motion stays inside the allowed set"
    nseg = stats.get("segments", 0)
    if getattr(result, "interrupted", False):
        what += " (interrupted: a partial report)"
    parts = [f"{name}: {verdict}: {what}", f"{nseg} segment{'s' if nseg != 1 else ''} checked"]
    if not deterministic and "double_pass_boxes" in stats:
        boxes = stats["double_pass_boxes"]
        parts[-1] += f" (by the double pass in {boxes} box{'es' if boxes != 1 else ''}, 0 solver queries)"
    elif not deterministic and stats.get("fanuc_boxes"):
        parts[-1] += " (in the box of the whole motion, no numpy, 0 solver queries)"
    elif not deterministic:
        parts[-1] += (f" ({stats.get('screened', 0)} by screening, "
                      f"{stats.get('z3_queries', 0)} solver quer{'y' if stats.get('z3_queries', 0) == 1 else 'ies'})")
    if result.margin:
        parts.append(f"margin {_d(result.margin)} mm")
    if result.params:
        parts.append("parameters " + ", ".join(f"{p.name}={_d(p.written[0])}..{_d(p.written[1])}"
                                               for p in result.params))
    parts.append(f"dialect {result.dialect}")
    parts.append(f"solver {result.solver}" + ("" if deterministic or not result.solver_version
                                              else f" {result.solver_version}"))
    if not deterministic:
        total = dict(result.timings).get("total_s")
        if total is not None:
            parts.append(f"{total:.3f} s")
    return "; ".join(parts)


def render_stats(result: Result, name: str = "") -> str:
    """Where the time went (``nczones verify --stats``): tiers, motion kinds, solver calls, slowest blocks.

    >>> from nczones.prover import Result, Verdict
    >>> prof = {"total_s": 2.5, "motions": 1200, "blocks": 600, "motions_screened_vectorized": 1100,
    ...         "tiers": {"screen_vectorized_s": 0.01, "exact_per_motion_s": 1.9, "solver_s": 0.3,
    ...                   "interpretation_and_rest_s": 0.29},
    ...         "kinds": {"arc": {"motions": 100, "seconds_one_by_one": 2.2}},
    ...         "solver": {"calls": 7, "seconds": 0.3, "stopped": {}},
    ...         "slowest": [{"block": 9, "line": 12, "kind": "arc", "seconds": 0.5}]}
    >>> print(render_stats(Result(Verdict.SAFE, profile=prof), "p.ngc"), end="")
    p.ngc: stats: 1,200 motions in 600 blocks, 2.500 s (480 motions/s); 1,100 motions proved by the vectorized screen
    p.ngc: stats: time by tier: vectorized screen 0.010 s, exact tiers one by one 1.900 s, solver 0.300 s (7 calls), interpretation and the rest 0.290 s
    p.ngc: stats: time by motion kind (decided one by one): arc 100 motions 2.200 s
    p.ngc: stats: slowest blocks: line 12 (block 9, arc) 0.500 s
    """
    prof = result.profile or {}
    if not prof:
        return ""
    name = name or result.file or "<program>"
    tiers = prof.get("tiers", {})
    solver = prof.get("solver", {})
    total = prof.get("total_s", 0.0)
    rate = f" ({prof['motions'] / total:,.0f} motions/s)" if total else ""
    lines = [f"{prof['motions']:,} motions in {prof['blocks']:,} blocks, {total:.3f} s{rate}; "
             f"{prof.get('motions_screened_vectorized', 0):,} motions proved by the vectorized screen"]
    if "double_pass" in prof:
        boxes = prof["double_pass"]["boxes"]
        lines[0] += (f", {prof['double_pass']['motions']:,} by the double pass in {boxes:,} "
                     f"box{'es' if boxes != 1 else ''} (its time is the interpretation's)")
    stopped = solver.get("stopped") or {}
    stops = (", stopped: " + ", ".join(f"{k} {v}" for k, v in stopped.items())) if stopped else ""
    lines.append(f"time by tier: vectorized screen {tiers.get('screen_vectorized_s', 0):.3f} s, exact tiers one by one "
                 f"{tiers.get('exact_per_motion_s', 0):.3f} s, solver {tiers.get('solver_s', 0):.3f} s "
                 f"({solver.get('calls', 0)} call{'s' if solver.get('calls', 0) != 1 else ''}{stops}), "
                 f"interpretation and the rest {tiers.get('interpretation_and_rest_s', 0):.3f} s")
    kinds = prof.get("kinds", {})
    if kinds:
        lines.append("time by motion kind (decided one by one): " + ", ".join(
            f"{k} {v['motions']:,} motions {v['seconds_one_by_one']:.3f} s" for k, v in kinds.items()))
    slow = prof.get("slowest", [])
    if slow:
        lines.append("slowest blocks: " + ", ".join(
            f"line {x['line']} (block {x['block']}, {x['kind']}) {x['seconds']:.3f} s" for x in slow))
    return "".join(f"{name}: stats: {line}\n" for line in lines)
