"""``nczones fleet check|status|diff`` (specs/fleet.md).

``check`` exits like ``verify`` over every cell of the run: 1 if a cell is
unsafe, else 2 if one is an error (bad program, bad machine file, a task
that failed), else 3 if one is unknown, else 0; Ctrl-C stops it with 130
after storing what finished.  ``status`` exits 0 (2 without a store);
``diff`` exits 1 when a cell got worse (newly unsafe, unknown or error),
else 0.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from ..fleet.project import Project
from .conventions import EXIT_FAIL, EXIT_OK, usage_error

__all__ = ["configure", "run_fleet_check", "run_fleet_status", "run_fleet_diff"]


def _store_path(project: Project, args: argparse.Namespace) -> Path:
    return Path(args.store).resolve() if args.store else project.store


def run_fleet_check(args: argparse.Namespace) -> int:
    """``nczones fleet check``: verify every cell whose job is not in the store."""
    from ..fleet.check import CheckOptions, run_check
    from ..fleet.project import load_project
    from ..fleet.store import Store

    if args.split_lines is not None and args.split_lines < 1:
        raise usage_error("FL110", f"--split-lines {args.split_lines}: must be at least 1")
    if args.workers is not None and args.workers < 1:
        raise usage_error("FL110", f"--workers {args.workers}: must be at least 1")
    project = load_project(args.project)
    executor = "serial" if args.serial else (args.scheduler or ("local" if args.cluster else "auto"))
    options = CheckOptions(executor=executor, workers=args.workers,
                           split_lines=args.split_lines, transfer=args.transfer,
                           cluster_threshold=args.cluster_threshold,
                           progress=True if args.progress else (False if args.no_progress else None))
    cells = project.cells(machines=args.machine or None, programs=args.program or None)
    if not cells:  # a CI job whose glob matches nothing must not pass with "0 jobs ran"
        raise usage_error("FL112", "no program selected: " + _empty_selection(project, args))
    with Store(_store_path(project, args)) as store:
        summary = run_check(project, store, options, cells=cells, force=args.force)
        from ..fleet.status import status_text

        run = store.latest_run()
        assert run is not None
        rows = store.cells(run.run_id)
    for message in summary.problems[:20]:
        print(message, file=sys.stderr)
    if len(summary.problems) > 20:
        print(f"... and {len(summary.problems) - 20} more problems", file=sys.stderr)
    text = status_text(run, rows, details=False).splitlines()
    bad = [c for c in rows if c.verdict not in ("safe",) and c.status != "pending"]
    for c in sorted(bad, key=lambda c: ({"unsafe": 0, "error": 1, "unknown": 2}.get(c.verdict or "", 3),
                                        c.machine, c.program))[:args.list]:
        from ..fleet.status import first_finding

        print(f"{c.program} on {c.machine}: {c.verdict}" + (f": {first_finding(c)}" if first_finding(c) else ""))
    if len(bad) > args.list:
        print(f"... and {len(bad) - args.list} more cells that are not safe (nczones fleet status)")
    rate = f", {summary.ran / summary.wall_s:.1f} jobs/s" if summary.ran and summary.wall_s > 0 else ""
    split = f", {summary.split} split into chunks" if summary.split else ""
    print(f"{project.name}: {text[-2].split(': ', 1)[1]}; {summary.wall_s:.2f} s"
          + (f" on {summary.executor}" if summary.executor else "") + rate + split)
    if summary.choice:
        print(f"executor: {summary.executor}: {summary.choice}")
    return summary.exit_code


def _empty_selection(project: Project, args: argparse.Namespace) -> str:
    """What selected no (program, machine) cell: the globs and machine names, as written."""
    unknown = [m for m in args.machine if m not in {e.name for e in project.machines}]
    if unknown:
        return (f"--machine {', '.join(unknown)}: no such machine in {project.name} (machines: "
                f"{', '.join(e.name for e in project.machines)})")
    machines = [e for e in project.machines if not args.machine or e.name in args.machine]
    globs = "; ".join(f"{e.name}: programs = {list(e.programs)}" for e in machines)
    where = f" under {project.root}"
    if args.program:
        return (f"--program {', '.join(repr(g) for g in args.program)} matches none of the machines' programs"
                f"{where} ({globs})")
    return f"the programs globs match no file{where} ({globs})"


def run_fleet_status(args: argparse.Namespace) -> int:
    """``nczones fleet status``: the matrix of the latest run."""
    from ..fleet.project import load_project
    from ..fleet.status import status_json, status_text, write_status_html
    from ..fleet.store import Store

    project = load_project(args.project)
    if args.format == "html" and not args.output:
        raise usage_error("FL110", "--format html writes a page and the reports beside it: give --output FILE.html")
    with Store(_store_path(project, args), create=False) as store:
        run = store.latest_run()
        if run is None:
            raise usage_error("FL300", "the store has no run yet: run 'nczones fleet check' first")
        rows = store.cells(run.run_id)
        if args.format == "html":
            written = write_status_html(run, rows, store, args.output, f"nczones fleet: {project.name}",
                                        project=project, html_reports=args.html_reports)
            print(f"{args.output}: the matrix of run {run.run_id} ({len(rows)} cells) and {len(written) - 1} "
                  "reports", file=sys.stderr)
            return EXIT_OK
        text = status_json(run, rows) if args.format == "json" else status_text(run, rows)
    _write(args.output, text)
    return EXIT_OK


def run_fleet_diff(args: argparse.Namespace) -> int:
    """``nczones fleet diff``: what changed between the latest run and the one before."""
    from ..fleet.project import load_project
    from ..fleet.status import diff_json, diff_runs, diff_text
    from ..fleet.store import Store

    project = load_project(args.project)
    with Store(_store_path(project, args), create=False) as store:
        new = store.latest_run()
        old = None if new is None else store.latest_run(before=new.run_id)
        if new is None or old is None:
            raise usage_error("FL300", "a diff needs two runs in the store: run 'nczones fleet check' again")
        changes = diff_runs(store.cells(old.run_id), store.cells(new.run_id))
    _write(args.output, diff_json(old, new, changes) if args.format == "json" else diff_text(old, new, changes))
    worse = any(c.kind.startswith("newly") for c in changes)
    return EXIT_FAIL if worse else EXIT_OK


def _write(path: str | None, text: str) -> None:
    if path is None:
        sys.stdout.write(text)
        return
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(text)


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument("project", nargs="?", metavar="PROJECT",
                   help="the project file nczones.toml or its folder (default: the nearest nczones.toml in the "
                        "working directory or its parents)")
    p.add_argument("--store", metavar="FILE",
                   help="the result store (default: [project] store of the project file, else "
                        ".nczones/results.sqlite beside it)")


def configure(fleet: argparse.ArgumentParser) -> None:
    fleet.description = ("Verify every program of a library (nczones.toml) against every machine it runs on; only jobs "
                         "whose program, machine file, settings or nczones changed run again. See specs/fleet.md.")
    fsub = fleet.add_subparsers(dest="fleet_command", required=True, metavar="SUBCOMMAND",
                                help="check (verify what changed), status (the matrix), diff (what changed)")
    register_check(fsub)
    register_status(fsub)
    register_diff(fsub)


def register_check(fsub: argparse._SubParsersAction) -> None:
    p = fsub.add_parser("check", help="verify what changed since the last run and store the results",
                        description="Verify every (program, machine) cell whose job is not in the store. Exit "
                                    "status: 1 a cell is unsafe, 2 an error, 3 unknown, 0 all safe; 130 after "
                                    "Ctrl-C (what finished is stored).")
    _common(p)
    how = p.add_mutually_exclusive_group()
    how.add_argument("--scheduler", metavar="tcp://HOST:8786",
                     default=os.environ.get("DASK_SCHEDULER_ADDRESS") or None,
                     help="submit the jobs to this Dask scheduler (default: $DASK_SCHEDULER_ADDRESS, else chosen by "
                          "measurement: a local cluster only where it is projected to win)")
    how.add_argument("--serial", action="store_true", help="verify in this process, one job after the other")
    how.add_argument("--cluster", action="store_true",
                     help="always start the local cluster, even for a few jobs")
    p.add_argument("--workers", type=int, metavar="N",
                   help="worker processes of the local cluster (default: one per core)")
    p.add_argument("--cluster-threshold", type=int, default=50, metavar="N",
                   help="with fewer than N jobs to run, verify them in this process; from N on, time the first "
                        "8 and start a local cluster only if it is projected to win (default 50)")
    p.add_argument("--split-lines", type=int, metavar="N",
                   help="split programs of more than 2N lines into chunks of about N lines verified on several "
                        "workers, where that is sound (default: never split; it pays only when verifying a line "
                        "costs more than scanning it, see specs/fleet.md)")
    p.add_argument("--transfer", choices=("auto", "paths", "bytes"), default="auto",
                   help="how workers get programs: paths (read from the project folder: a shared file system), "
                        "bytes (sent with each job), auto (paths locally, bytes to a scheduler; default)")
    p.add_argument("--machine", action="append", default=[], metavar="NAME",
                   help="only this machine's cells (repeatable)")
    p.add_argument("--program", action="append", default=[], metavar="GLOB",
                   help="only programs matching this glob, relative to the project root (repeatable)")
    p.add_argument("--force", action="store_true", help="verify every job again, even those in the store")
    p.add_argument("--list", type=int, default=20, metavar="N",
                   help="list at most N cells that are not safe (default 20)")
    bar = p.add_mutually_exclusive_group()
    bar.add_argument("--progress", action="store_true",
                     help="draw the progress bar even when standard error is not a terminal")
    bar.add_argument("--no-progress", action="store_true", help="never draw the progress bar")
    p.set_defaults(handler=run_fleet_check)


def register_status(fsub: argparse._SubParsersAction) -> None:
    p = fsub.add_parser("status", help="the programs x machines matrix of the latest run",
                        description="Print the verdict matrix of the latest run: text, JSON, or an HTML page "
                                    "with a link to every job's report.")
    _common(p)
    p.add_argument("--format", choices=("text", "json", "html"), default="text",
                   help="text (a matrix and the cells that are not safe), json, or html (a page, with the reports "
                        "written to a reports/ folder beside it; needs --output)")
    p.add_argument("--output", metavar="FILE", help="write to FILE instead of standard output")
    p.add_argument("--html-reports", choices=("all", "not-safe", "none"), default="all",
                   help="with --format html: the cells whose HTML report (with its plots) is made, by verifying "
                        "the job again, and linked from the cell (default all; a report already beside the page "
                        "is kept); text and JSON reports are always written")
    p.set_defaults(handler=run_fleet_status)


def register_diff(fsub: argparse._SubParsersAction) -> None:
    p = fsub.add_parser("diff", help="what changed between the last two runs, newly unsafe first",
                        description="Compare the latest run's cells with the run before: newly unsafe, newly "
                                    "error or unknown, changed violations, fixed, added, removed. Exit status 1 "
                                    "when a cell got worse.")
    _common(p)
    p.add_argument("--format", choices=("text", "json"), default="text", help="text or json")
    p.add_argument("--output", metavar="FILE", help="write to FILE instead of standard output")
    p.set_defaults(handler=run_fleet_diff)

