"""``nczones verify`` (DESIGN §8): exit 0 safe, 1 unsafe, 2 bad input, 3 unknown."""

from __future__ import annotations

import argparse
import sys

from .. import cli
from ..errors import Diagnostic, InputError
from ..exact import parse_decimal

__all__ = ["register"]


def _run(args: argparse.Namespace) -> int:
    from ..machine import load_machine
    from ..report import render_report
    from ..report.progress import progress_for
    from . import parse_param, verify

    machine = load_machine(args.machine)
    try:
        margin = parse_decimal(args.margin)
    except ValueError:  # InvalidArgument is a ValueError
        raise InputError(Diagnostic("VF102", f"--margin {args.margin!r}: expected a decimal number of mm "
                                             "(e.g. 0.001)", file="<command line>")) from None
    if margin < 0:
        raise InputError(Diagnostic("VF102", f"--margin {args.margin}: must not be negative", file="<command line>"))
    if args.max_violations < 1:
        raise InputError(Diagnostic("VF103", f"--max-violations {args.max_violations}: must be at least 1",
                                    file="<command line>"))
    params = tuple(parse_param(p, machine) for p in args.param)
    bar = progress_for(sys.stderr, "verify")
    try:
        result = verify(args.program, machine, margin=margin, params=params, engine=args.engine,
                        max_violations=args.max_violations, progress=bar, recovery=args.recovery,
                        arc_tolerance=_arc_tolerance(args.arc_tolerance))
    finally:
        if bar is not None:
            bar.close()
    text = render_report(result, args.format, machine=machine, program=args.program,
                         color=args.output is None and args.format == "text" and _color(sys.stdout))
    if args.output:
        with open(args.output, "w", encoding="utf-8") as fh:
            fh.write(text)
    else:
        sys.stdout.write(text)
    return result.verdict.exit_code


def _color(stream) -> bool:
    from ..report.text import use_color

    return use_color(stream)


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("verify", help="prove that a program stays inside the allowed set (or show where not)")
    p.add_argument("program", metavar="PROGRAM")
    p.add_argument("--machine", required=True, metavar="M.toml")
    p.add_argument("--margin", default="0", metavar="D", help="required clearance in mm on every axis")
    p.add_argument("--param", action="append", default=[], metavar="NAME=LO..HI",
                   help="parameter range: G54.X=-2..2 (offset deviation), H1=195..205 (tool length), "
                        "start.Z=-10..0 (start deviation), home.X=-0.5..0.5 (homing error)")
    p.add_argument("--recovery", choices=("start", "breakpoint"), default=None,
                   help="also prove the automatic tool-break recovery of the machine's [tool_change] "
                        "from every break point, restarting at the sequence start or at the break point")
    p.add_argument("--engine", choices=("auto", "z3"), default="auto")
    p.add_argument("--arc-tolerance", default="0.002", metavar="MM|linuxcnc", help='largest mismatch (mm) of an arc end point with its circle (default 0.002), or "linuxcnc" for LinuxCNC\'s own acceptance rule')
    p.add_argument("--max-violations", type=int, default=20, metavar="N")
    p.add_argument("--format", choices=("text", "json", "html", "sarif"), default="text",
                   help="text (compiler-style), json (specs/report.schema.json), html (one self-contained "
                        "file with plots), sarif (SARIF 2.1.0 for code scanning)")
    p.add_argument("--output", metavar="FILE")
    p.set_defaults(handler=_run)


cli.REGISTRARS.append(register)


def _arc_tolerance(text: str):
    """``--arc-tolerance``: "linuxcnc" or a non-negative decimal (mm)."""
    if text == "linuxcnc":
        return text
    try:
        q = parse_decimal(text)
    except ValueError:  # InvalidArgument is a ValueError
        q = None
    if q is None or q < 0:
        raise InputError(Diagnostic("VF104", f"--arc-tolerance {text!r}: expected a non-negative decimal number "
                                             "of mm (e.g. 0.002) or 'linuxcnc'", file="<command line>"))
    return q
