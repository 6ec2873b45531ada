"""``nczones plot PROGRAM --machine M -o out.png [--plane X,Y] [--verify]``: draw a program.

The figure (see :func:`nczones.report.figure.plot_program`) shows the
allowed set in the plane, the toolpath (rapids dashed) and, with
``--verify`` (the default), the violating blocks and counterexample points.
The output format follows the file name (``.png``, ``.svg``, ``.pdf``).
Exit status: 0 written (whatever the verdict), 2 bad input.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ..errors import Diagnostic, InputError
from .conventions import EXIT_OK, budget_seconds, program_source, tell_beside_file, with_dialect

__all__ = ["configure"]


class PlotError(InputError):
    """A bad ``nczones plot`` option (code PL1xx)."""


def _plane(text: str | None, machine: Any) -> tuple[str, str] | None:
    if text is None:
        return None
    parts = [p.strip().upper() for p in text.replace(" ", ",").split(",") if p.strip()]
    if len(parts) == 1 and len(parts[0]) == 2:
        parts = list(parts[0])
    names = machine.axis_names
    if len(parts) != 2 or parts[0] == parts[1] or any(p not in names for p in parts):
        raise PlotError(Diagnostic("PL101", f"--plane {text!r}: expected two different axes of the machine "
                                            f"as H,V (axes: {', '.join(names)}), e.g. --plane "
                                            f"{names[0]},{names[-1]}", file="<command line>"))
    return parts[0], parts[1]


def _run(args: argparse.Namespace) -> int:
    from ..machine import load_machine
    from ..report import use_agg_backend

    machine = with_dialect(load_machine(args.machine), args.dialect)
    plane = _plane(args.plane, machine)
    if len(machine.axis_names) < 2:
        raise PlotError(Diagnostic("PL102", f"{args.machine}: a plot needs a machine with two axes or more",
                                   file="<command line>"))
    suffix = args.output.rsplit(".", 1)[-1].lower() if "." in args.output else ""
    if suffix not in ("png", "svg", "pdf"):
        raise PlotError(Diagnostic("PL103", f"-o {args.output!r}: the file name must end in .png, .svg or .pdf",
                                   file="<command line>"))

    source = program_source(args.program)
    use_agg_backend()
    import matplotlib.pyplot as plt

    from ..prover.limits import interpretation_budget
    from ..report.figure import plot_program
    from ..report.progress import progress_for

    budget = budget_seconds(args.budget)
    result = None
    if args.verify:
        from ..pipeline.verification import verify_source
        from ..prover.options import VerifyOptions

        bar = progress_for(sys.stderr, "verify")
        try:
            result = verify_source(source, machine, VerifyOptions(budget_s=budget), progress=bar)
        finally:
            if bar is not None:
                bar.close()
    # drawing interprets the program again: its repetitions ask the same budget (a fresh one: verify spent its
    # own), so a program that loops for hours is drawn up to where the budget ends it
    with interpretation_budget(budget) as lim:
        fig = plot_program(source, machine, plane, result)
    if lim.spent_at is not None:
        print(f"{source.name}: note: the budget of {budget:g} s was spent while interpreting the program for "
              "the drawing; the plot shows it up to the repetition that found it spent (raise --budget)",
              file=sys.stderr)
    try:
        fig.savefig(args.output, dpi=args.dpi)
    except OSError as exc:
        raise PlotError(Diagnostic("PL104", f"-o {args.output!r}: cannot write the file: {exc.strerror or exc}",
                                   file="<command line>")) from None
    finally:
        plt.close(fig)
    verdict = f" ({result.verdict.label}, {len(result.violations)} violating block(s))" if result else ""
    tell_beside_file(f"{args.output}: plot of {source.name} on {machine.name}{verdict}")
    return EXIT_OK


def configure(p: argparse.ArgumentParser) -> None:
    p.add_argument("program", metavar="PROGRAM", help="the G-code program file; '-' reads standard input")
    p.add_argument("--machine", required=True, metavar="M.toml",
                   help="the machine file whose allowed set is drawn (specs/machine-file.md)")
    p.add_argument("-o", "--output", required=True, metavar="OUT.png",
                   help="the image to write; its suffix (.png, .svg, .pdf) sets the format")
    p.add_argument("--plane", metavar="H,V", help="axes of the plot plane, e.g. X,Z (default: a plane the zones use)")
    p.add_argument("--no-verify", dest="verify", action="store_false",
                   help="draw only; do not verify (no violations marked)")
    p.add_argument("--budget", default=None, metavar="SECONDS",
                   help="time for the verification and, again, for the interpretation that draws the program "
                        "(default: verify's, 60; 'none' for no limit): a loop, repeat or cycle pass past "
                        "it ends the drawing there, with a note")
    p.add_argument("--dpi", type=int, default=120, help="resolution of a PNG in dots per inch (default 120)")
    p.add_argument("--dialect", choices=("linuxcnc", "fanuc"), default=None,
                   help="how the program text is read (default: the machine file's [machine] dialect)")
    p.set_defaults(handler=_run)

