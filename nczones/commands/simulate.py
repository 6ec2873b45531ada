"""``nczones simulate`` (DESIGN §8): exit 0 success, 1 an alarm, 2 bad input.

The program is interpreted by :mod:`nczones.gcode` and run through the
reference controller.  ``--break-at LINE[:FRACTION]`` injects a tool break and
runs the automatic recovery (:mod:`nczones.controller.recovery`).
:data:`EXTRA_OPTIONS` and :data:`RUNNERS` let later stages add options and
take over the run.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable
from fractions import Fraction
from typing import Any

from ..errors import Diagnostic, InputError, InvalidArgument, shorten
from ..exact import format_decimal, parse_decimal
from .conventions import (
    EXIT_FAIL,
    EXIT_INPUT,
    EXIT_OK,
    add_dialect_arguments,
    arc_tolerance,
    budget_seconds,
    library_folder,
    program_source,
    standard_output,
    with_dialect,
)

__all__ = ["configure", "render_text", "EXTRA_OPTIONS", "RUNNERS"]

#: Functions ``f(parser)`` that add options to ``simulate`` (e.g. ``--break-at``).
EXTRA_OPTIONS: list[Callable[[argparse.ArgumentParser], None]] = []
#: Functions ``f(args, machine, settings) -> SimulationResult | None``; the first
#: that returns a result replaces the plain run (e.g. a tool-break recovery run).
RUNNERS: list[Callable[[argparse.Namespace, Any, Any], Any]] = []


def _decimal_option(name: str, text: str) -> Fraction:
    try:
        q = parse_decimal(text)
    except InvalidArgument:
        q = None
    if q is None or q < 0:
        raise InputError(Diagnostic("SM101", f"{name} {text!r}: expected a non-negative decimal number of ms",
                                    file="<command line>"))
    return q


def _max_iterations(n: int) -> int:
    if n < 1:
        raise InputError(Diagnostic("SM102", f"--max-iterations {n}: must be at least 1", file="<command line>"))
    return n


def _break_at(text: str | None) -> tuple[int, Fraction] | None:
    """``LINE[:FRACTION]`` -> (line, fraction); the fraction defaults to 0 (the start of the motion)."""
    if text is None:
        return None
    line_s, _, frac_s = text.partition(":")
    try:
        line = int(line_s)
        frac = parse_decimal(frac_s) if frac_s else Fraction(0)
    except ValueError:  # int() or parse_decimal (InvalidArgument is a ValueError)
        line, frac = 0, Fraction(-1)
    if line < 1 or not 0 <= frac <= 1:
        raise InputError(Diagnostic("SM111", f"--break-at {text!r}: expected LINE[:FRACTION], a source line "
                                    "number and the fraction of its cutting motion done when the tool breaks "
                                    "(0 to 1), such as 12:0.5", file="<command line>"))
    return line, frac


def render_text(result: Any, program: str) -> str:
    """The human-readable report of one simulation."""
    axes = result.axes

    def pt(coords: Any) -> str:
        return " ".join(f"{a}{format_decimal(c)}" for a, c in zip(axes, coords))

    lines = [f"{program}: simulated in {result.mode.value} mode, monitor {result.monitor.value}"]
    if result.alarms:
        for a in result.alarms:
            where = f"line {a.line}, block {a.block}" if a.line is not None else "before the first block"
            during = f" during {a.derived}" if a.kind == "recovery" else ""
            if a.kind == "solid":
                lines.append(f"  ALARM tool solid: {a.part} enters fixture \"{a.zone}\" at {where}: "
                             f"{pt(a.position)}")
            else:
                lines.append(f"  ALARM stroke limit{during}, zone \"{a.zone}\" at {where}: {pt(a.position)}")
            if a.source:
                lines.append(f"    {shorten(a.source)}")
            if a.blocked:
                lines.append("    direction cleared: " + ", ".join(f"{ax}{'+' if s > 0 else '-'}" for ax, s in a.blocked)
                             + " (a jog in the opposite direction is still accepted)")
            if a.first_outside is not None:
                lines.append(f"    first pulse outside: {pt(a.first_outside)}; caught {a.overshoot_pulses} "
                             f"interpolation steps later (periodic sampling)")
    else:
        lines.append("  no alarm" + ("" if result.completed else " (program did not complete)"))
    for e in result.events:
        d = dict(e.data)
        if e.kind == "tool-break":
            lines.append(f"  TOOL BREAK at line {e.line} after step {d['step']} of {d['of_steps']}: "
                         f"{pt(d['position'].values())}; {d['variant']} restart")
        elif e.kind == "recovery":
            lines.append(f"    recovery {d['leg']} to {pt(d['end'].values())}")
        elif e.kind == "resume":
            lines.append(f"    resumed at {pt(d['position'].values())}")
    lines.append(f"  machine position: {pt(result.machine_position)}")
    if result.temporary_position is not None:
        lines.append(f"  temporary machine coordinates (program check): {pt(result.temporary_position)}")
    lines.append("  pulses: " + ", ".join(f"{a} {p}" for a, p in zip(axes, result.pulses)))
    lines.append(f"  simulated time: {result.simulated_time_s:.6f} s ({result.motions} motions, {result.steps} steps)")
    if result.monitor.value == "periodic":
        lines.append(f"  periodic sampling may overshoot by up to {result.overshoot_bound_mm:.6f} mm (feed x period)")
    if result.max_regions:
        lines.append(f"  limit-value table lookups: at most {result.max_lookup_comparisons} comparisons "
                     f"(table of {result.max_regions} regions)")
    if result.servo is not None:
        lines.append(f"  servo (post-interpolation {result.servo.filter} filter): max deviation from the "
                     f"commanded path {result.servo.max_deviation_mm:.6f} mm at {result.servo.max_deviation_time_s:.4f} s")
    if result.blind_spot:
        lines.append(f"  BLIND SPOT: {result.blind_spot}")
    for n in result.notes:
        lines.append(f"  note: {n}")
    return "\n".join(lines) + "\n"


def _run(args: argparse.Namespace) -> int:
    from ..controller import Settings
    from ..machine import load_machine

    machine = with_dialect(load_machine(args.machine), args.dialect)
    library = library_folder(args.library)
    source = program_source(args.program)
    settings = Settings(
        pre_time_constant_ms=_decimal_option("--accdec-before-ms", args.accdec_before_ms),
        post_time_constant_ms=_decimal_option("--accdec-after-ms", args.accdec_after_ms),
        post_filter=args.filter,
        log_motions=args.format == "json" and args.events,
        blending=args.blending,
    )
    result = None
    for runner in RUNNERS:
        result = runner(args, machine, settings)
        if result is not None:
            break
    notes: list[str] = []
    budget_stop = False
    if result is None:
        from ..pipeline.simulation import simulate_source
        from ..prover.options import VerifyOptions
        from ..report.progress import progress_for

        # the interpretation's settings, checked in the order the command always checked them
        budget = budget_seconds(args.budget)
        options = VerifyOptions(arc_tolerance=arc_tolerance(args.arc_tolerance),
                                max_iterations=_max_iterations(args.max_iterations), library=library,
                                budget_s=budget)
        bar = progress_for(sys.stderr, "simulate")
        try:
            result, notes, budget_stop = simulate_source(source, machine, options, progress=bar, mode=args.mode,
                                                         monitor=args.monitor, settings=settings,
                                                         break_at=_break_at(args.break_at))
        finally:
            if bar is not None:
                bar.close()
    if args.format == "json":
        data = result.to_json()
        data["program"] = source.name
        data["program_sha256"] = source.sha256
        data["dialect"] = machine.dialect
        data["notes"] = list(data["notes"]) + notes
        if not args.events:
            data.pop("events")
        standard_output().write(json.dumps(data, indent=2) + "\n")
    else:
        text = render_text(result, source.name)
        standard_output().write(text + f"  dialect: {machine.dialect}\n" + "".join(f"  note: {n}\n" for n in notes))
    if result.alarms:
        return EXIT_FAIL
    if budget_stop or any("not supported" in n for n in notes):
        return EXIT_INPUT
    return EXIT_OK


def configure(p: argparse.ArgumentParser) -> None:
    from ..gcode.runner_common import DEFAULT_MAX_LOOP_ITERATIONS

    p.description = ("Run PROGRAM through the reference controller pulse by pulse. Exit status: 0 "
                     "no alarm, 1 an alarm, 2 bad input or a code the controller cannot run.")
    p.add_argument("program", metavar="PROGRAM", help="the G-code program file; '-' reads standard input")
    p.add_argument("--machine", required=True, metavar="M.toml",
                   help="the machine file: axes, zones, pulse units, rates (specs/machine-file.md)")
    p.add_argument("--mode", choices=("normal", "lock", "check"), default="normal",
                   help="normal; lock (machine lock: axes frozen, the stroke check sees nothing); "
                        "check (program check: temporary coordinates, stroke check, maximum feed)")
    p.add_argument("--monitor", choices=("pulse", "periodic"), default="pulse",
                   help="check limits after every pulse, or every monitor_period_ms of the machine")
    p.add_argument("--accdec-before-ms", default="0", metavar="MS",
                   help="linear acc/dec of the feed before interpolation (time constant)")
    p.add_argument("--accdec-after-ms", default="0", metavar="MS",
                   help="filter time constant on every axis after interpolation (servo log)")
    p.add_argument("--filter", choices=("exponential", "linear"), default="exponential",
                   help="shape of the filter after interpolation (--accdec-after-ms): exponential (default) or "
                        "linear (moving average)")
    p.add_argument("--blending", choices=("auto", "exact", "linuxcnc"), default="auto",
                   help="corners: LinuxCNC's blend arcs (linuxcnc; needs [machine.acceleration]), the programmed "
                        "path (exact), or auto: blend where the machine starts in G64 and gives accelerations "
                        "(specs/path-modes.md)")
    p.add_argument("--arc-tolerance", default=None, metavar="MM|linuxcnc|grbl", help='largest mismatch (mm) of an arc end point with its circle (default: the machine file\'s arc_tolerance, else 0.002), or "linuxcnc"/"grbl" for that control\'s own acceptance rule')
    p.add_argument("--events", action="store_true", help="include the event log in the JSON output")
    p.add_argument("--break-at", metavar="LINE[:FRACTION]", default=None,
                   help="break the tool in the first cutting motion of LINE after FRACTION of it (default 0) "
                        "and run the automatic recovery of the machine's [tool_change]")
    add_dialect_arguments(p)
    p.add_argument("--max-iterations", type=int, default=DEFAULT_MAX_LOOP_ITERATIONS, metavar="N",
                   help="iterations a loop (while, do, repeat) may run per entry before the simulation stops "
                        f"there (GC302; default {DEFAULT_MAX_LOOP_ITERATIONS})")
    p.add_argument("--budget", default=None, metavar="SECONDS",
                   help="time for the interpretation (default: verify's, 60; 'none' for no limit): a loop, "
                        "repeat or cycle pass past it stops the simulation there (VF203, exit 2)")
    p.add_argument("--format", choices=("text", "json"), default="text",
                   help="text (readable) or json (specs/simulate.schema.json)")
    for extra in EXTRA_OPTIONS:
        extra(p)
    p.set_defaults(handler=_run)

