"""Shared pieces of the fleet tests: small generated libraries and a comparable view of a store."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from nczones.fleet.check import CheckOptions, run_check
from nczones.fleet.generate import write_library
from nczones.fleet.project import load_project
from nczones.fleet.store import Store

ROOT = Path(__file__).resolve().parents[2]
LIBRARY = ROOT / "specs" / "examples" / "library"


def small_library(folder: Path, programs: int = 4, machines: int = 3, moves: int = 6) -> Path:
    """A generated mill library (every fifth program cuts into the vise of variant 0)."""
    return write_library(folder, programs=programs, machines=machines, moves=moves)


def check(project_file: Path, store_path: Path, executor: Any = "serial", **kw: Any):
    """One ``fleet check`` run; ``executor`` is an option string or an executor object."""
    project = load_project(project_file)
    options = CheckOptions(executor=executor if isinstance(executor, str) else "auto", progress=False,
                           **{k: v for k, v in kw.items() if k in ("split_lines", "transfer", "workers")})
    make = None if isinstance(executor, str) else (lambda _options, _jobs: executor)
    with Store(store_path) as store:
        summary = run_check(project, store, options, force=kw.get("force", False), make_executor=make)
        cells = current(store)
    return summary, cells


def current(store: Store) -> dict[tuple[str, str], tuple[Any, ...]]:
    """The latest run's cells as comparable values: key, verdict and each finding without timings."""
    run = store.latest_run()
    assert run is not None
    out = {}
    for c in store.cells(run.run_id):
        violations = tuple((v["line"], v["column"], v["zone"], v["kind"], v["block"], v["depth"],
                            tuple(sorted(v["point_exact"].items())), tuple(sorted(v["first_exit_point_exact"].items())))
                           for v in c.violations)
        reasons = tuple((r.get("code"), r.get("message")) for r in c.reasons)
        out[(c.program, c.machine)] = (c.job_key, c.status != "pending", c.verdict, violations, reasons)
    return out


def without_status(cells: dict) -> dict:
    return {k: (v[0], v[2], v[3], v[4]) for k, v in cells.items()}
