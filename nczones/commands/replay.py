"""``nczones replay REPORT.json...``: the command of :mod:`nczones.replay` (exit 0 every counterexample
confirmed, 1 one was not, 2 bad input)."""

from __future__ import annotations

import argparse
import os

from ..errors import Diagnostic
from ..replay import IRRATIONAL_TOLERANCE_MM, Check, ReplayError, replay_file
from .conventions import EXIT_FAIL, EXIT_OK

__all__ = ["configure"]


def _run(args: argparse.Namespace) -> int:
    if args.base is not None and not os.path.isdir(args.base):
        raise ReplayError(Diagnostic("RP103", f"--base {args.base}: not a directory", file="<command line>"))
    checks: list[Check] = []
    for report in args.reports:
        checks.extend(replay_file(report, base=args.base, machine_file=args.machine, program_file=args.program))
    for c in checks:
        print(c.render())
    bad = sum(not c.confirmed for c in checks)
    approx = sum(c.confirmed and not c.exact for c in checks)
    if not checks:
        print("replay: no counterexample to replay (every report is safe or unknown)")
    else:
        print(f"replay: {len(checks) - bad} of {len(checks)} counterexample{'s' if len(checks) != 1 else ''} "
              f"confirmed" + (f" ({approx} within {IRRATIONAL_TOLERANCE_MM} mm of an irrational path point)"
                              if approx else "") + (f"; {bad} NOT reproduced" if bad else ""))
    return EXIT_FAIL if bad else EXIT_OK


def configure(p: argparse.ArgumentParser) -> None:
    p.description = ("Re-check every counterexample of REPORT.json (nczones verify --format json) in exact "
                     "arithmetic against the machine file and program it names (their SHA-256 must match). "
                     "Exit status: 0 all confirmed, 1 one was not reproduced, 2 bad input.")
    p.add_argument("reports", nargs="+", metavar="REPORT.json", help="JSON report(s) of nczones verify")
    p.add_argument("--base", metavar="DIR",
                   help="directory the report's relative paths start from (default: the working directory)")
    p.add_argument("--machine", metavar="M.toml", help="the machine file, when it moved since the report")
    p.add_argument("--program", metavar="PROGRAM", help="the program file, when it moved (or was read from "
                                                        "standard input)")
    p.set_defaults(handler=_run)

