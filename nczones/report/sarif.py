"""SARIF 2.1.0 output of a verification, for code-scanning annotations.

One rule per kind of finding:

=========  =====================  ==============================================
id         name                   a result when
=========  =====================  ==============================================
NCZ001     MotionLeavesZone       a motion leaves the allowed set (level error)
NCZ002     RecoveryLeavesZone     a recovery motion after a break does (error)
NCZ003     NotProved              a block could not be modelled or decided
                                  (unsupported code, solver timeout: warning)
=========  =====================  ==============================================

Each result's ``physicalLocation`` names the program by a URI relative to the
working directory (``uriBaseId`` ``SRCROOT``, itself given as an absolute
``file:`` URI in ``originalUriBaseIds``) with ``startLine``/``startColumn``;
the message carries the counterexample point, depth and first exit, and
``properties`` the same as exact decimal strings.  The output validates
against the official OASIS SARIF 2.1.0 schema (tests/report/test_sarif.py).
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from fractions import Fraction
from pathlib import Path, PurePosixPath
from typing import Any
from urllib.parse import quote

from .. import __version__
from ..exact import format_decimal, format_rational, seconds
from ..prover.result import Result
from . import numbers

__all__ = ["to_sarif", "render_sarif", "RULES", "artifact_uri"]

SARIF_SCHEMA_URI = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"

RULES = (
    {
        "id": "NCZ001",
        "name": "MotionLeavesZone",
        "shortDescription": {"text": "A motion leaves the allowed set of the machine."},
        "fullDescription": {"text": "Some point of the commanded motion of this block lies outside the "
                                    "allowed set (outside an allow zone or inside a forbid zone); the "
                                    "point is an exactly re-checked counterexample."},
        "defaultConfiguration": {"level": "error"},
        "help": {"text": "Change the block (or the work offset, tool length or machine file) so that the "
                         "whole motion stays inside the allowed set; the message names the zone, a point "
                         "outside it, how deep the motion goes and where it first leaves."},
    },
    {
        "id": "NCZ002",
        "name": "RecoveryLeavesZone",
        "shortDescription": {"text": "A recovery motion after a break leaves the allowed set."},
        "fullDescription": {"text": "Restarting the program after a break (tool break, stop) at a "
                                    "breakpoint moves the machine outside the allowed set."},
        "defaultConfiguration": {"level": "error"},
        "help": {"text": "Add a safe retract before the restart point or restart from another block."},
    },
    {
        "id": "NCZ003",
        "name": "NotProved",
        "shortDescription": {"text": "The motion could not be proved to stay inside the allowed set."},
        "fullDescription": {"text": "A code nczones does not model (e.g. cutter compensation), or a query "
                                    "the solver could not decide in its budget, makes the verdict unknown."},
        "defaultConfiguration": {"level": "warning"},
        "help": {"text": "Rewrite the block with supported codes, or check this part by other means."},
    },
)
_RULE_INDEX = {r["id"]: i for i, r in enumerate(RULES)}


def artifact_uri(path: str, base: str | os.PathLike | None = None,
                 start: str | os.PathLike | None = None) -> tuple[str, bool]:
    """The URI of a program for SARIF: relative to ``base`` (default the working directory).

    A relative ``path`` is taken from ``start`` (default ``base``).  Returns
    ``(uri, relative)``; a path outside ``base`` (or on another drive)
    becomes an absolute ``file:`` URI.

    >>> artifact_uri("/work/x/part 1.ngc", "/work")
    ('x/part%201.ngc', True)
    >>> artifact_uri("/elsewhere/p.ngc", "/work")
    ('file:///elsewhere/p.ngc', False)
    >>> artifact_uri("x/p.ngc", "/work", start="/work/repo")
    ('repo/x/p.ngc', True)
    """
    base = os.getcwd() if base is None else os.fspath(base)
    absolute = os.path.abspath(os.path.join(base if start is None else os.fspath(start), path))
    try:
        rel = os.path.relpath(absolute, base)
    except ValueError:  # another drive (Windows)
        rel = None
    if rel is None or rel == ".." or rel.startswith(".." + os.sep):
        return Path(absolute).as_uri(), False
    return quote(PurePosixPath(*Path(rel).parts).as_posix()), True


def _location(file: str | None, line: int | None, column: int | None, snippet: str,
              base: tuple[str, str]) -> list[dict]:
    if not file or file.startswith("<") or line is None:
        return []
    uri, relative = artifact_uri(file, *base)
    artifact = {"uri": uri}
    if relative:
        artifact["uriBaseId"] = "SRCROOT"
    region: dict[str, Any] = {"startLine": line, "startColumn": max(1, column or 1)}
    if snippet:
        region["snippet"] = {"text": snippet}
    return [{"physicalLocation": {"artifactLocation": artifact, "region": region}}]


def _result_entries(result: Result, base_abs: tuple[str, str], resolution: dict[str, Fraction] | None = None) -> list[dict]:
    results = []
    for v in result.violations:
        rule = "NCZ002" if v.kind == "recovery" else "NCZ001"
        what = v.segment_kind + (f" ({v.derived})" if v.derived else "")
        # the message is read by people (numbers.py); the properties below keep the exact decimals
        depth = ("at least " if not v.depth_exact else "") + numbers.depth(v.depth, v.depth_exact,
                                                                          numbers.depth_step(resolution))
        text = (f"{what} leaves the allowed set (zone \"{v.zone}\"), {depth} mm deep: the point "
                f"{numbers.point(v.point, resolution)} is outside; " + (
                    f"first exit at {numbers.point(v.first_exit, resolution)}" if v.exit_located else
                    "first exit not located (the path may leave the allowed set earlier)"))
        if v.params:
            text += "; with parameters " + ", ".join(f"{n}={format_decimal(x)}" for n, x in v.params)
        for switch, position in v.switches:
            text += f"; with the {switch.replace('_', '-')} switch {position}"
        if result.margin:
            text += f"; margin {format_decimal(result.margin)} mm"
        text += "."
        props = {
            "zone": v.zone,
            "zones": list(v.zones),
            "block": v.block,
            "point": {a: format_decimal(x) for a, x in v.point},
            "pointExact": {a: format_rational(x) for a, x in v.point},
            "pathPoint": {a: format_decimal(x) for a, x in v.path_point},
            "pathPointExact": {a: format_rational(x) for a, x in v.path_point},
            "pathPointOnPath": v.on_path,
            "depth": format_decimal(v.depth),
            "depthExact": v.depth_exact,
            "firstExit": {a: format_decimal(x) for a, x in v.first_exit},
            "segmentKind": v.segment_kind,
            "engine": v.engine,
            "params": {n: format_decimal(x) for n, x in v.params},
            "paramsExact": {n: format_rational(x) for n, x in v.params},
            "switches": dict(v.switches),
        }
        pp = v.point_program
        if pp is not None:  # the point in the program's coordinates (issue 37), as in the JSON report
            props["pointProgram"] = {a: format_decimal(x) for a, x in pp}
            props["pointProgramExact"] = {a: format_rational(x) for a, x in pp}
            text = text[:-1] + f"; in program coordinates {numbers.program_point(v, resolution)}."
        if v.kind == "recovery":
            props.update({"breakLine": v.break_line, "leg": v.leg,
                          "breakPointExact": {a: format_rational(x) for a, x in v.break_point}})
        res = {"ruleId": rule, "ruleIndex": _RULE_INDEX[rule], "level": "error", "kind": "fail",
               "message": {"text": text}, "properties": props}
        loc = _location(v.span.file if v.span else result.file, v.line, v.span.column if v.span else None,
                        v.source, base_abs)
        if loc:
            res["locations"] = loc
        results.append(res)
    for r in result.reasons:
        res = {"ruleId": "NCZ003", "ruleIndex": _RULE_INDEX["NCZ003"], "level": "warning", "kind": "fail",
               "message": {"text": r.message if r.message.endswith(".") else r.message + "."}}
        if r.code:
            res["properties"] = {"code": r.code}
        loc = _location(r.span.file if r.span else result.file, r.span.line if r.span else None,
                        r.span.column if r.span else None,
                        r.span.text.rstrip("\r\n") if r.span else "", base_abs)
        if loc:
            res["locations"] = loc
        results.append(res)
    return results


def _program_properties(result: Result, deterministic: bool) -> dict:
    settings = dict(result.settings)
    props = {
        "program": result.file,
        "programSha256": result.program_sha256,
        "verdict": result.verdict.label,
        "machine": {"name": result.machine_name, "file": result.machine_file, "sha256": result.machine_sha256},
        "dialect": settings.get("dialect"),
        "settings": {k: list(x) if isinstance(x, tuple) else x for k, x in settings.items()},
        "margin": format_decimal(result.margin),
        "params": [{"name": p.name, "lo": format_decimal(p.written[0]), "hi": format_decimal(p.written[1])}
                   for p in result.params],
        "solver": result.solver if deterministic else f"{result.solver} {result.solver_version}".strip(),
        "truncated": result.truncated,
    }
    if not deterministic and result.timings:
        props["timings"] = {k: seconds(t) for k, t in result.timings}
    return props


def to_sarif(result: Result | Sequence[Result], *, base: str | os.PathLike[str] | None = None, machine: Any = None,
             deterministic: bool = False, files_from: str | os.PathLike[str] | None = None) -> dict[str, Any]:
    """The SARIF 2.1.0 log of a verification (or of several programs: one run, their results) as a dict.

    Parameters
    ----------
    result : Result or sequence of Result
        One result per program; every program's findings go into one run.
    base : path, optional
        Directory the artifact URIs are relative to (``--sarif-root``;
        default the working directory).  Programs outside it get absolute
        ``file:`` URIs.
    files_from : path, optional
        Directory the results' relative file names start from (default
        ``base``; the command line passes the working directory).
    machine : Machine, optional
        Named in the run's properties.
    deterministic : bool
        Leave out timings and the solver version (golden files).

    The run's ``artifacts`` list each program with its SHA-256; its
    ``properties`` carry the nczones version, the dialect, the machine file
    with its SHA-256 and every setting that changes the verdict (for one
    program directly, for several under ``programs``).

    Examples
    --------
    >>> from nczones.machine import load_machine
    >>> from nczones.prover import verify
    >>> m = load_machine("specs/machines/grinder.toml")
    >>> r = verify("specs/examples/programs/notch_dip.ngc", m)
    >>> log = to_sarif(r)
    >>> res = log["runs"][0]["results"][0]
    >>> res["ruleId"], res["locations"][0]["physicalLocation"]["region"]["startLine"]
    ('NCZ001', 5)
    >>> res["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
    'specs/examples/programs/notch_dip.ngc'
    >>> res["properties"]["pointExact"]
    {'X': '380', 'Y': '130'}
    """
    results_in = [result] if isinstance(result, Result) else list(result)
    base_abs = os.path.abspath(os.getcwd() if base is None else os.fspath(base))
    where = (base_abs, os.path.abspath(base_abs if files_from is None else os.fspath(files_from)))
    results = []
    for r in results_in:
        results.extend(_result_entries(r, where, numbers.resolution_of(machine)))
    if len(results_in) == 1:
        run_props = _program_properties(results_in[0], deterministic)
    else:
        run_props = {"verdict": min(r.verdict for r in results_in).label if results_in else "safe",
                     "programs": [_program_properties(r, deterministic) for r in results_in]}
    run_props["nczonesVersion"] = __version__
    if machine is not None:
        run_props["machine"] = {"name": machine.name, "file": str(machine.source), "sha256": machine.sha256}
    artifacts = []
    for r in results_in:
        if not r.file or r.file.startswith("<"):
            continue
        uri, relative = artifact_uri(r.file, *where)
        loc: dict = {"uri": uri}
        if relative:
            loc["uriBaseId"] = "SRCROOT"
        art: dict = {"location": loc}
        if r.program_sha256:
            art["hashes"] = {"sha-256": r.program_sha256}
        artifacts.append(art)
    invocation: dict = {"executionSuccessful": True}
    if not deterministic and len(results_in) == 1 and results_in[0].timings:
        invocation["properties"] = {"timings": {k: seconds(t) for k, t in results_in[0].timings}}
    run = {
        "tool": {"driver": {"name": "nczones", "version": __version__, "semanticVersion": __version__,
                            "rules": [dict(r) for r in RULES]}},
        "originalUriBaseIds": {"SRCROOT": {"uri": Path(base_abs).as_uri().rstrip("/") + "/"}},
        "invocations": [invocation],
        "artifacts": artifacts,
        "results": results,
        "columnKind": "unicodeCodePoints",
        "properties": run_props,
    }
    return {"$schema": SARIF_SCHEMA_URI, "version": "2.1.0", "runs": [run]}


def render_sarif(result: Result | Sequence[Result], **kwargs: Any) -> str:
    """:func:`to_sarif` as indented JSON text."""
    return json.dumps(to_sarif(result, **kwargs), indent=2, ensure_ascii=False) + "\n"
