"""Shared helpers of the report tests: run the bundled examples, compare goldens."""

from __future__ import annotations

import os
from pathlib import Path

from nczones.machine import load_machine
from nczones.prover import verify

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"
GOLDEN = ROOT / "tests" / "golden" / "report"
MACHINES = ROOT / "specs" / "machines"


def run_example(program: str, machine: str, *, base: Path = EX, **kwargs):
    """Verify ``base/program`` on ``MACHINES/machine``; the report names the program as written."""
    m = load_machine(MACHINES / machine)
    return verify(str(base / program), m, file=program, **kwargs), m


def check_golden(name: str, actual: str) -> None:
    """Compare with tests/golden/report/<name>; NCZONES_UPDATE_GOLDENS=1 rewrites it."""
    path = GOLDEN / name
    if os.environ.get("NCZONES_UPDATE_GOLDENS") == "1":
        path.write_text(actual, encoding="utf-8")
    expected = path.read_text(encoding="utf-8")
    assert actual == expected, f"{name} differs from the golden file (NCZONES_UPDATE_GOLDENS=1 rewrites it)"


def verify_with_hot_path(source, machine_path: Path):
    """(machine, result, path) of ``source`` on the machine file: the path collected around the violating
    blocks and their passes, as the figure and the interactive view draw it (report tests of both)."""
    from nczones.report.figure import collect_path, hot_passes

    m = load_machine(machine_path)
    result = verify(source, m)
    path = collect_path(source, m, {v.block for v in result.violations}, passes=hot_passes(result.violations))
    return m, result, path
