"""Text and JSON renderings of a verification :class:`~nczones.prover.Result` (DESIGN §8).

Text is compiler-style: ``file:line:col: violation[zone]: ...`` followed by
the source line, one entry per violating block in execution order, then the
reasons for ``unknown`` and a summary line.  JSON follows
``specs/report.schema.json``; numbers are exact decimal strings (a repeating
expansion is rounded to 12 places and marked with ``…``).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from fractions import Fraction

from .. import __version__
from ..errors import shorten
from ..exact import format_decimal, format_rational, seconds
from .result import Result, Verdict, Violation, point_program_missing

__all__ = ["render_text", "render_json", "to_json_dict", "program_point_json"]


def _d(x: Fraction) -> str:
    return format_decimal(x)


def _pt(pairs: Iterable[tuple[str, Fraction]]) -> str:
    return " ".join(f"{a}{_d(v)}" for a, v in pairs)


def render_text(result: Result, program: str = "") -> str:
    """A compiler-style report."""
    out = []
    name = result.file or program or "<program>"
    for v in result.violations:
        loc = f"{v.span.file}:{v.span.line}:{v.span.column}" if v.span else name
        what = v.segment_kind + (f" ({v.derived})" if v.derived else "")
        depth = ("" if v.depth_exact else ">=") + _d(v.depth)
        par = ("" if v.parameter_exact else "~") + format_decimal(v.parameter, 6)
        out.append(
            f"{loc}: violation[{v.zone}]: {what} leaves the allowed set at {_pt(v.point)} "
            f"(segment parameter {par}), depth {depth} mm"
        )
        if v.source:
            out.append(f"    {shorten(v.source)}")
        fe = ("" if v.first_exit_exact else "~") + format_decimal(v.first_exit_parameter, 6)
        if v.exit_located:
            out.append(f"    first exit at {_pt(v.first_exit)} (parameter {fe}); engine {v.engine}")
        else:
            out.append(f"    first exit not located (the point is outside; the path may leave earlier); engine {v.engine}")
        if result.margin:
            out.append(f"    path point {_pt(v.path_point)} has less than the margin {_d(result.margin)}")
        if v.params:
            out.append("    with " + ", ".join(f"{n}={_d(x)}" for n, x in v.params))
        for switch, position in v.switches:
            out.append(f"    with the {switch.replace('_', '-')} switch {position}")
        if v.note:
            out.append(f"    note: {v.note}")
    for r in result.reasons:
        loc = f"{r.span.file}:{r.span.line}:{r.span.column}" if r.span else name
        out.append(f"{loc}: unknown: {r.message}")
        if r.span is not None and r.span.text:
            out.append(f"    {shorten(r.span.text.rstrip())}")
    for n in result.notes:
        out.append(f"{name}: note: {n}")
    stats = dict(result.stats)
    summary = (
        f"{name}: {result.verdict.label}: {len(result.violations)} violating block(s)"
        + (" (list truncated)" if result.truncated else "")
        + f"; {stats.get('segments', 0)} segments, {stats.get('screened', 0)} proved by screening, "
        f"{stats.get('z3_queries', 0)} solver queries; {result.solver} {result.solver_version}"
    )
    if result.margin:
        summary += f"; margin {_d(result.margin)}"
    if result.params:
        summary += "; parameters " + ", ".join(f"{p.name}={_d(p.written[0])}..{_d(p.written[1])}" for p in result.params)
    out.append(summary)
    return "\n".join(out) + "\n"


def _exact_point(pairs: Iterable[tuple[str, Fraction]]) -> dict[str, str]:
    return {a: format_rational(x) for a, x in pairs}


def to_json_dict(result: Result, *, deterministic: bool = False) -> dict:
    """The JSON report as a dict (see ``specs/report.schema.json``).

    Points appear twice: as decimals (``point``, rounded to 12 places and
    marked ``…`` when the expansion repeats) and as exact rationals
    (``point_exact``: ``"1900/3"``), which ``nczones replay`` reads back.
    ``deterministic=True`` leaves out what changes between runs or machines
    (timings, the solver's version and counters), for golden files.
    """
    def span(s):
        return None if s is None else {"file": s.file, "line": s.line, "column": s.column}

    violations = []
    for v in result.violations:
        violations.append({
            "kind": v.kind,
            "block": v.block,
            "line": v.line,
            "column": v.span.column if v.span else None,
            "source": v.source,
            "zone": v.zone,
            "zones": list(v.zones),
            "point": {a: _d(x) for a, x in v.point},
            "point_exact": _exact_point(v.point),
            "path_point": {a: _d(x) for a, x in v.path_point},
            "path_point_exact": _exact_point(v.path_point),
            "path_point_on_path": v.on_path,
            "parameter": format_decimal(v.parameter, 12),
            "parameter_exact": v.parameter_exact,
            "parameter_rational": format_rational(v.parameter) if v.parameter_exact else None,
            "first_exit": {a: _d(x) for a, x in v.first_exit},
            "first_exit_point_exact": _exact_point(v.first_exit),
            "first_exit_parameter": format_decimal(v.first_exit_parameter, 12),
            "first_exit_exact": v.first_exit_exact,
            "first_exit_located": v.exit_located,
            "depth": _d(v.depth),
            "depth_exact": v.depth_exact,
            "segment_kind": v.segment_kind,
            "derived": v.derived,
            "engine": v.engine,
            "params": {n: _d(x) for n, x in v.params},
            "params_exact": {n: format_rational(x) for n, x in v.params},
            "switches": dict(v.switches),
            "note": v.note,
            **program_point_json(v),
        })
        if v.kind == "recovery":
            violations[-1].update({
                "break_line": v.break_line,
                "break_parameter": None if v.break_parameter is None else format_decimal(v.break_parameter, 12),
                "break_point": {a: _d(x) for a, x in v.break_point},
                "break_point_exact": _exact_point(v.break_point),
                "leg": v.leg,
            })
    settings = dict(result.settings)
    doc = {
        "verdict": result.verdict.label,
        "program": result.file,
        "program_sha256": result.program_sha256,
        "machine": {"name": result.machine_name, "file": result.machine_file, "sha256": result.machine_sha256},
        "nczones_version": __version__,
        "dialect": settings.get("dialect"),
        "settings": {k: list(x) if isinstance(x, tuple) else x for k, x in settings.items()},
        "violations": violations,
        "truncated": result.truncated,
        "interrupted": result.interrupted,
        "budget_s": result.budget_s,
        "reason": "; ".join(
            (f"{r.span.file}:{r.span.line}: " if r.span else "") + r.message for r in result.reasons
        ) if result.verdict is Verdict.UNKNOWN else None,
        "reasons": [{"message": r.message, "code": r.code, "location": span(r.span),
                     "source": r.span.text.rstrip() if r.span else ""} for r in result.reasons],
        "solver": {"name": result.solver, "version": "" if deterministic else result.solver_version},
        "engine": result.engine,
        "engines": [{"block": b, "engine": e} for b, e in result.engines],
        "margin": _d(result.margin),
        "params": [{"name": p.name, "lo": _d(p.written[0]), "hi": _d(p.written[1])} for p in result.params],
        "notes": list(result.notes),
        **({"clearance": [{"part": p, "fixture": f, "at_least": format_decimal(Fraction(math.floor(c * 1000), 1000)),
                           "at_least_exact": format_rational(c), "line": line}
                          for p, f, c, line in result.extra["clearance"]]} if result.extra.get("clearance") else {}),
        "stats": ({"segments": dict(result.stats).get("segments", 0)} if deterministic
                  else {**dict(result.stats), **({"profile": result.profile} if result.profile else {})}),
        "timings": {} if deterministic else {k: seconds(v) for k, v in result.timings},
    }
    return doc


def program_point_json(v: Violation) -> dict:
    """The ``point_program`` fields of a violation's JSON: the point in the program's coordinates (decimals
    and exact rationals), the frame it was computed in, and why it is missing when it is (issue 37).

    ``point_program_exact`` is the exact image of ``point_exact`` under the inverse frame; with a rotation
    (``program_frame.exact`` false) that inverse uses the cosine and sine the control computed, so it is
    the program point to within the control's rounding, not a proof-grade value.
    """
    pp = v.point_program
    frame = v.frame
    return {
        "point_program": None if pp is None else {a: _d(x) for a, x in pp},
        "point_program_exact": None if pp is None else _exact_point(pp),
        "point_program_missing": point_program_missing(v),
        "program_frame": None if frame is None or pp is None else {
            "work": frame.work,
            "units": "inch" if frame.inch else "mm",
            "diameter_axes": list(frame.diameter),
            "rotation": None if frame.rotation is None else {
                "axes": list(frame.rotation.axes), "degrees": _d(frame.rotation.degrees)},
            "exact": frame.exact,
            "offset": {a: _d(o) for a, o in zip((a for a, _ in v.point), frame.offset)},
            "description": frame.describe(),
        },
    }


def render_json(result: Result, *, deterministic: bool = False) -> str:
    """:func:`to_json_dict` as indented JSON text."""
    import json  # here: a text report needs no json (issue 36)

    return json.dumps(to_json_dict(result, deterministic=deterministic), indent=2, ensure_ascii=False) + "\n"
