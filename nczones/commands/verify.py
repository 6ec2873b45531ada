"""``nczones verify`` (DESIGN §8): exit 0 safe, 1 unsafe, 2 bad input, 3 unknown, 130 interrupted.

``nczones verify PROGRAM... --machine M.toml`` verifies each program (a
path; ``-`` reads standard input) and writes one report per program; the
exit status is the worst outcome: 1 if any program is unsafe, else 2 if any
could not be read or parsed, else 3 if any is unknown, else 0.  With
``--format json`` several programs give a JSON list (one program: the
report object); with ``--format sarif`` one SARIF log with one run.
Ctrl-C stops the run: the reports of the programs verified so far (the
current one partial, marked interrupted) are written and the exit status is
130 (143 when SIGTERM stopped it the same way, see :func:`nczones.cli.sigterm_as_interrupt`).

The parts are one function each so that later options slot in: the options
are read by :func:`verify_options`, one program is verified by
:func:`verify_one`, the reports are written by :func:`write_output`.
"""

from __future__ import annotations

import argparse
import gc
import os
import re
import sys
from collections.abc import Sequence

from ..errors import InputError
from ..prover.limits import DEFAULT_BUDGET_S
from ..report import FORMATS
from .conventions import (
    EXIT_FAIL,
    EXIT_INPUT,
    EXIT_INTERRUPTED,
    EXIT_OK,
    EXIT_UNKNOWN,
    add_dialect_arguments,
    program_source,
    standard_output,
    tell_beside_file,
    usage_error,
    with_dialect,
)

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, TextIO

    from ..gcode.source import ProgramSource
    from ..machine import Machine
    from ..prover.options import VerifyOptions
    from ..prover.result import Result

__all__ = ["configure", "verify_options", "verify_one", "write_output", "worst_exit", "EXIT_INTERRUPTED"]

#: Exit statuses from worst to best: several programs exit with the first one that occurs.
EXIT_ORDER = (EXIT_FAIL, EXIT_INPUT, EXIT_UNKNOWN, EXIT_OK)

#: The youngest generation's collection threshold while the command runs: interpreting a program allocates
#: millions of small objects that reference counting frees, and collecting every 700 allocations (Python's
#: default) cost 8 % of the CPU of a 100,000-line verify through the full interpreter.
GC_THRESHOLD = 10_000


def fewer_collections() -> None:
    """Raise the garbage collector's first threshold to :data:`GC_THRESHOLD` (never lower it, never turn
    a disabled collector on): cyclic garbage is still collected, a few thousand allocations later."""
    first, second, third = gc.get_threshold()
    if 0 < first < GC_THRESHOLD:
        gc.set_threshold(GC_THRESHOLD, second, third)


def worst_exit(codes: Sequence[int]) -> int:
    """The exit status of several programs: unsafe (1) before bad input (2) before unknown (3) before safe (0).

    >>> worst_exit([0, 3, 2]), worst_exit([3, 1, 2]), worst_exit([])
    (2, 1, 0)
    """
    for code in EXIT_ORDER:
        if code in codes:
            return code
    return EXIT_OK


def verify_options(args: argparse.Namespace, machine: Machine) -> VerifyOptions:
    """The options of :func:`nczones.prover.verify` from the command line, read and checked
    (:meth:`~nczones.prover.options.VerifyOptions.from_args`: ``VF1xx`` errors), ``--param`` ranges read
    against ``machine``."""
    from ..prover.options import VerifyOptions

    return VerifyOptions.from_args(args, machine)


def verify_one(program: str, machine: Machine, options: VerifyOptions,
               stream: bool = False) -> tuple[ProgramSource, Result]:
    """Read and verify one program (a path or ``-``) with a progress bar on a terminal: (source, result).

    ``stream``: a large plain program file is read as it is verified, not held in memory (issue 36)."""
    from ..pipeline.verification import verify_source

    source = program_source(program, stream=stream)
    bar = _progress_bar(sys.stderr)
    try:
        return source, verify_source(source, machine, options, progress=bar)
    finally:
        if bar is not None:
            bar.close()


def _progress_bar(stream: Any) -> Any:
    """:func:`nczones.report.progress.progress_for(stream, "verify") <nczones.report.progress.progress_for>`, whose
    module is imported for a terminal only: a stream that is none (``isatty`` false, or not to be asked) gets no
    bar there either (start-up, boot44)."""
    try:
        if not stream.isatty():
            return None
    except (AttributeError, ValueError, OSError):
        return None
    from ..report.progress import progress_for

    return progress_for(stream, "verify")


def check_output_path(path: str | None) -> None:
    """Fail before verifying when ``--output`` cannot be written (``VF107``)."""
    if path is None:
        return
    parent = os.path.dirname(os.path.abspath(path))
    problem = None
    if os.path.isdir(path):
        problem = "it is a directory"
    elif not os.path.isdir(parent):
        shown = os.path.dirname(path) or parent
        problem = (f"{shown} is a file, not a directory" if os.path.exists(parent)
                   else f"the directory {shown} does not exist")
    elif not os.access(parent, os.W_OK) or (os.path.exists(path) and not os.access(path, os.W_OK)):
        problem = "permission denied"
    if problem:
        raise usage_error("VF107", f"--output {path}: cannot write the report: {problem}")


def write_output(path: str | None, text: str) -> None:
    """Write ``text`` to ``path`` (standard output when None); an OS error is ``VF107``, one line."""
    if path is None:
        standard_output().write(text)
        return
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)
    except OSError as exc:
        raise usage_error("VF107", f"--output {path}: cannot write the report: "
                                   f"{exc.strerror or exc}") from None


def _error_entry(program: str, exc: InputError) -> dict[str, Any]:
    """The JSON list entry of a program that could not be verified."""
    return {"program": "<stdin>" if program == "-" else program, "verdict": "error",
            "errors": [{"code": d.code, "message": d.message, "location": str(d.span) if d.span else d.location()}
                       for d in exc.diagnostics]}


def render_many(results: list, errors: list[tuple[int, str, InputError]], args: argparse.Namespace,
                machine: Machine, several: bool) -> str:
    """The reports of every program in the chosen format (see the module docstring)."""
    from ..report import render_report

    if args.format == "json" and several:
        import json

        from ..prover.render import to_json_dict

        entries: list[tuple[int, dict[str, Any]]] = [(k, to_json_dict(r)) for k, _, r in results]
        entries += [(k, _error_entry(p, e)) for k, p, e in errors]
        return json.dumps([e for _, e in sorted(entries, key=lambda x: x[0])], indent=2, ensure_ascii=False) + "\n"
    if args.format == "sarif":
        from ..report.sarif import render_sarif

        return render_sarif([r for _, _, r in results], machine=machine, base=args.sarif_root,
                            files_from=os.getcwd())
    color = args.output is None and args.format == "text" and _color(sys.stdout)
    stats = args.format == "text" and getattr(args, "stats", False)
    if stats:
        from ..report.text import render_stats

    return "".join(render_report(r, args.format, machine=machine, program=source, color=color)
                   + (render_stats(r) if stats else "") for _, source, r in results)


def with_tool_table(machine: Machine, path: str, units: str | None,
                    x_offsets: str | None = None) -> tuple[Machine, str]:
    """``machine`` with the tools of a tool table (``--tool-table``), and the note the reports carry.

    The format is told by the content: a Fanuc tool offset listing (``G10`` blocks, as the control punches
    its offset memory out; :mod:`nczones.imports.fanuc_offsets`) or a LinuxCNC tool table (``.tbl``).  The
    table replaces the machine file's ``[tool_lengths]``/``[tool_diameters]`` (a lathe listing:
    ``[tool_offsets]``) whole, as the control uses only its memory (a tool not in it has none).  ``units``
    is required (``VF111``) unless a listing states G20/G21: a table is in the control's unit."""
    import hashlib
    from dataclasses import replace
    from types import MappingProxyType

    from ..imports.fanuc_offsets import is_fanuc_listing, read_fanuc_listing
    from ..imports.linuxcnc import read_tool_table

    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError as exc:
        raise usage_error("VF111", f"--tool-table {path}: cannot read it: {exc.strerror or exc}") from None
    digest = hashlib.sha256(data).hexdigest()
    text = data.decode("utf-8", errors="replace")
    if is_fanuc_listing(text):
        if machine.dialect != "fanuc":
            raise usage_error("VF111", f"--tool-table {path}: a Fanuc tool offset listing (G10 blocks); "
                                       f"this machine's dialect is {machine.dialect}")
        listing = read_fanuc_listing(path, units, machine.is_lathe, machine.axis_names, machine.diameter_axes,
                                     x_offsets)
        if machine.is_lathe:
            note = (f"lathe tool offsets from the Fanuc offset listing {path} ({listing.units}, sha256 "
                    f"{digest[:12]}; {len(listing.offsets)} offset(s), geometry and wear), replacing the machine "
                    "file's [tool_offsets]")
            return replace(machine, tool_offsets=MappingProxyType(listing.offsets)), note
        note = (f"tool lengths and diameters from the Fanuc offset listing {path} (memory {listing.memory}, "
                f"{listing.units}, sha256 {digest[:12]}; {len(listing.lengths)} length(s), geometry and wear), "
                "replacing the machine file's")
        return replace(machine, tool_lengths=MappingProxyType(listing.lengths),
                       tool_diameters=MappingProxyType(listing.diameters),
                       tool_length_wear=MappingProxyType(listing.length_wear),
                       tool_radius_wear=MappingProxyType(listing.radius_wear)), note
    # a .tbl line starts with T<n> (a pre-2.4 table with its number: the .tbl reader says what LinuxCNC does)
    looks_tbl = any(re.match(r"\s*(?:[Tt][+-]?)?\d", ln) for ln in text.split("\n"))
    if not looks_tbl and any(ln.split(";")[0].strip() for ln in text.split("\n")):
        raise usage_error("VF111", f"--tool-table {path}: neither a LinuxCNC tool table (.tbl: lines "
                                   "T<n> P<pocket> Z<length> D<diameter>) nor a Fanuc tool offset listing "
                                   "(G10 L10/L11/L12/L13 P<n> R<value>, or G10 P<n> X Z R Q for a lathe)")
    if units is None:
        raise usage_error("VF111", f"--tool-table {path}: give --tool-table-units mm or inch (a LinuxCNC "
                                   "tool table is in the configuration's [TRAJ] LINEAR_UNITS, which the "
                                   "table itself does not say)")
    if machine.dialect != "linuxcnc":
        raise usage_error("VF111", f"--tool-table {path}: reads a LinuxCNC tool table (.tbl) or a Fanuc "
                                   f"offset listing; this is a .tbl and the machine's dialect is "
                                   f"{machine.dialect}")
    lengths, diameters, table_notes = read_tool_table(path, units, machine.axis_names)
    for skipped in table_notes:
        print(skipped.render(), file=sys.stderr)
    note = (f"tool lengths and diameters from the tool table {path} ({units}, sha256 {digest[:12]}; "
            f"{len(lengths)} length(s)), replacing the machine file's")
    return replace(machine, tool_lengths=MappingProxyType(lengths),
                   tool_diameters=MappingProxyType(diameters)), note


def _run(args: argparse.Namespace) -> int:
    from ..machine import load_machine

    programs: list[str] = args.programs
    if programs.count("-") > 1:
        raise usage_error("VF106", "standard input (-) can be read only once")
    if args.format == "html" and len(programs) > 1:
        raise usage_error("VF106", f"--format html writes the report of one program; {len(programs)} "
                                   "were given (use json, sarif or text for several)")
    if args.sarif_root is not None and not os.path.isdir(args.sarif_root):
        raise usage_error("VF108", f"--sarif-root {args.sarif_root}: not a directory")
    check_output_path(args.output)
    fewer_collections()
    machine = with_dialect(load_machine(args.machine), args.dialect)
    table_note = None
    if args.tool_table is not None:
        machine, table_note = with_tool_table(machine, args.tool_table, args.tool_table_units,
                                                args.tool_table_x_offset)
    options = verify_options(args, machine)
    results: list = []
    errors: list[tuple[int, str, InputError]] = []
    codes: list[int] = []
    for k, program in enumerate(programs):
        try:
            # the HTML report draws the program from its text: not streamed
            source, result = verify_one(program, machine, options, stream=args.format != "html")
        except InputError as exc:
            if len(programs) == 1:
                raise
            print(exc.render(), file=sys.stderr)
            errors.append((k, program, exc))
            codes.append(EXIT_INPUT)
            continue
        if table_note is not None:
            from dataclasses import replace

            result = replace(result, notes=(table_note,) + tuple(result.notes))
        results.append((k, source, result))
        codes.append(result.verdict.exit_code)
        if result.interrupted:  # Ctrl-C: report what was done, verify no further program
            break
    if results or args.format in ("json", "sarif"):
        write_output(args.output, render_many(results, errors, args, machine, len(programs) > 1))
    if args.output is not None:  # the report went to a file: the verdicts still show where the run was started
        print_summaries(results, args.output)
    if results and results[-1][2].interrupted:
        return EXIT_INTERRUPTED
    return worst_exit(codes)


def print_summaries(results: list, output: str) -> None:
    """With ``--output``: each program's one-line summary (the text report's last line) on standard output,
    then where the report is, so a CI log or a terminal still shows the verdicts."""
    from ..report.text import summary_line

    color = _color(sys.stdout)
    for _, _, result in results:
        tell_beside_file(summary_line(result, result.file or "<program>", color=color))
    tell_beside_file(f"report written to {output}")


def _color(stream: TextIO) -> bool:
    from ..report.text import use_color

    return use_color(stream)


def configure(p: argparse.ArgumentParser) -> None:
    from ..gcode.runner_common import DEFAULT_MAX_LOOP_ITERATIONS

    p.description = ("Prove that every motion of each PROGRAM stays inside the machine's allowed set, or report "
                     "exact counterexamples (with --output the report goes to the file and each program's one-line summary "
                     "to standard output). Exit status: 0 safe, 1 unsafe, 2 bad input, 3 unknown; with several "
                     "programs the worst (1 before 2 before 3 before 0); 130 when Ctrl-C stopped the run, 143 when SIGTERM "
                     "did.")
    p.add_argument("programs", nargs="+", metavar="PROGRAM",
                   help="G-code program file(s); '-' reads standard input; several files (e.g. a shell glob) "
                        "give one report each")
    p.add_argument("--machine", required=True, metavar="M.toml",
                   help="the machine file: axes, zones, offsets, tool lengths (specs/machine-file.md)")
    p.add_argument("--tool-table", default=None, metavar="TBL",
                   help="take tool lengths and diameters from this LinuxCNC tool table (.tbl) or Fanuc tool "
                        "offset listing (G10 blocks, as the control outputs its offset memory) instead of the "
                        "machine file's; needs --tool-table-units")
    p.add_argument("--tool-table-units", choices=("mm", "inch"), default=None,
                   help="the tool table's length unit: the configuration's [TRAJ] LINEAR_UNITS, the Fanuc "
                        "control's input unit (a listing that states G20/G21 needs none)")
    p.add_argument("--tool-table-x-offset", choices=("diameter", "radius"), default=None,
                   help="a Fanuc lathe listing's X on a diameter axis is a diameter or a radius (parameter "
                        "5004#1 ORC)")
    p.add_argument("--margin", default="0", metavar="D", help="required clearance in mm on every axis (default 0)")
    p.add_argument("--param", action="append", default=[], metavar="NAME=LO..HI",
                   help="parameter range: G54.X=-2..2 (offset deviation), H1=195..205 (tool length), "
                        "start.Z=-10..0 (start deviation), home.X=-0.5..0.5 (homing error); repeatable")
    p.add_argument("--recovery", choices=("start", "breakpoint"), default=None,
                   help="also prove the automatic tool-break recovery of the machine's [tool_change] "
                        "from every break point, restarting at the sequence start or at the break point")
    p.add_argument("--block-delete", default=None, metavar="both|off|on|N=POS,...",
                   help="block-delete switch positions to verify for lines starting with / (Fanuc: /1 .. /9, "
                        "/ is /1): both (the default, unless the machine file's block_delete says otherwise: "
                        "every combination of the switches the program uses), off (the lines run) or on (they "
                        "are skipped) for every switch, or per switch, e.g. 1=on,2=off or off,2=both "
                        "(switches not named: both); every report says what was verified")
    p.add_argument("--engine", choices=("auto", "z3"), default="auto",
                   help="auto: exact vectorized decisions where they are exact, Z3 for the rest (default); "
                        "z3: every segment through Z3 (the reference path)")
    p.add_argument("--arc-tolerance", default=None, metavar="MM|linuxcnc|grbl",
                   help="largest mismatch (mm) of an arc end point with its circle (default: the machine file's "
                        "arc_tolerance, else 0.002), or \"linuxcnc\"/\"grbl\" for that control's own acceptance rule")
    p.add_argument("--max-iterations", type=int, default=DEFAULT_MAX_LOOP_ITERATIONS, metavar="N",
                   help="iterations a loop (while, do, repeat) may run per entry before the verdict becomes "
                        f"unknown (GC302; default {DEFAULT_MAX_LOOP_ITERATIONS}); a repeat count above it (M98/G65 "
                        "L, a canned cycle's K/L, its pecks) is unknown at its block")
    add_dialect_arguments(p)
    p.add_argument("--max-violations", type=int, default=20, metavar="N",
                   help="stop after N violating blocks per program (default 20); the report says when the "
                        "list was cut")
    p.add_argument("--budget", default=None, metavar="SECONDS",
                   help=f"time per program for solver work, refinement and repetitions (default "
                        f"{DEFAULT_BUDGET_S:g}; 'none' for no limit); motions still undecided then are unknown "
                        "('budget spent'), the exact tiers check the rest; a loop or repeat past it ends the "
                        "interpretation as unknown (VF203)")
    p.add_argument("--stats", action="store_true",
                   help="after each text report, where the time went: per tier and per motion kind, the solver "
                        "calls and the slowest blocks (the JSON report always has them in stats.profile)")
    p.add_argument("--format", choices=FORMATS, default="text",
                   help="text (compiler-style), json (specs/report.schema.json; a list for several programs), "
                        "html (one self-contained file with plots; one program), sarif (SARIF 2.1.0 for code "
                        "scanning)")
    p.add_argument("--output", metavar="FILE",
                   help="write the report to FILE instead of standard output (standard output then shows each "
                        "program's one-line summary)")
    p.add_argument("--sarif-root", metavar="DIR",
                   help="directory that SARIF artifact URIs are relative to (uriBaseId SRCROOT; default the "
                        "working directory, e.g. the repository root in CI)")
    p.set_defaults(handler=_run)

