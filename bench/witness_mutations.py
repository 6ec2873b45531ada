"""Does the independence of the prover and the controller buy something?  (issue 21)

Each mutation injects one plausible bug, either into a module of the shared
meaning below both witnesses (the homing arithmetic, the recovery plan, the
exact spline curve) or into one side's own execution (the controller's pulse
loop, the prover's encoding).  For every mutation the script runs the
differential suite — the tests that hold the prover and the controller to
each other — on a copy of the tree whose source text carries the bug, and
then the shared module's own tests, and prints which caught it:

    python bench/witness_mutations.py            # every mutation (the unmutated suite first)
    python bench/witness_mutations.py S-homing   # one of them

Expected, and what specs/contract.md records: a side-specific bug breaks
the agreement of the two witnesses and the differential suite fails; a bug in
the shared meaning is made by both sides at once, the differential suite
cannot see it, and only the shared module's own tests (doctests, unit tests
against an oracle written from the spec) stand guard there.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: The tests that hold the two witnesses to each other (the contract suite in the wide sense).
DIFFERENTIAL = [
    "tests/plans/homing/test_prover.py::test_z3_model_latches_where_the_simulation_latches",
    "tests/plans/homing/test_prover.py::test_closed_form_origin_error_is_the_simulations",
    "tests/plans/homing/test_prover.py::test_one_pitch_counterexample_is_reproduced_by_the_simulation",
    "tests/plans/homing/test_simulation.py::test_simulation_matches_the_closed_form",
    "tests/plans/homing/test_cli.py",
    "tests/plans/recovery/test_recovery.py::test_prover_and_controller_agree_on_the_example",
    "tests/plans/recovery/test_recovery.py::test_prover_and_controller_agree_on_generated_machines",
    "tests/gcode/linuxcnc/splines/test_splines.py::test_controller_stays_within_one_and_a_quarter_pulses_of_the_curve",
    "tests/contract/test_contract.py::test_contract_on_tables_and_boxes",
]

#: Each shared module's own tests (its doctests and the unit tests written from its spec).
OWN = {
    "homing": ["nczones/plans/homing.py", "tests/plans/homing/test_simulation.py"],
    "recovery": ["nczones/plans/recovery.py", "tests/plans/recovery/test_recovery.py::test_recovery_legs_follow_the_section",
                 "tests/plans/recovery/test_recovery.py::test_motion_sequences_of_the_example"],
    "nurbs": ["nczones/geometry/nurbs.py", "tests/gcode/linuxcnc/splines/test_splines.py"],
}


#: name -> (where, shared module whose own tests to run, file, text, mutated text, what the bug is)
MUTATIONS = {
    "S-homing": ("shared", "homing", "nczones/plans/homing.py",
                 "k = floor((a - residue) / pitch) + 1", "k = -((residue - a) // pitch)",
                 "the latched grid point is the first one at or after the arming position (not strictly after)"),
    "S-recovery": ("shared", "recovery", "nczones/plans/recovery.py",
                   "A = tuple(terms.plus(v, cfg.approach_distance) if k == z",
                   "A = tuple(terms.plus(v, 2 * cfg.approach_distance) if k == z",
                   "the plan's rapid stops twice the approach distance above the restart point"),
    "S-spline": ("shared", "nurbs", "nczones/geometry/nurbs.py",
                 'e["control"], e["weights"])', 'e["control"], (Fraction(1),) * len(e["weights"]))',
                 "the exact curve of a spline ignores its weights (a B-spline, not the programmed NURBS)"),
    "C-homing": ("controller", None, "nczones/controller/homing.py", "            lo = A\n", "            lo = prev\n",
                 "a grid point between the last pulse and the arming position counts as after the signal"),
    "C-recovery": ("controller", None, "nczones/controller/recovery.py",
                   "for leg in recovery_legs(cfg, machine, P, restart, L, L2):",
                   "for leg in recovery_legs(cfg, machine, P, restart, L, L2)[1:]:",
                   "the recovery skips its retract (the tool-change rapid starts from the retract height anyway)"),
    "C-dogleg": ("controller", None, "nczones/controller/simulator.py",
                 "if seg.kind is SegmentKind.RAPID and self.machine.rapid_mode is RapidMode.DOGLEG:",
                 "if False:", "rapids move straight on a dogleg machine"),
    "P-homing": ("prover", None, "nczones/prover/homing.py",
                 "g > a, g - self.pitch <= a", "g >= a, g - self.pitch < a",
                 "the Z3 model latches the first grid point at or after the arming position"),
    "P-recovery": ("prover", None, "nczones/prover/recovery.py",
                   "        for leg in enc.legs(P, R, L, L2):",
                   "        for leg in enc.legs(P, R, L, L2)[::2]:",
                   "the legs to the tool-change position and down to the restart point are not encoded"),
    "P-lines": ("prover", None, "nczones/prover/core.py",
                "all(self.bbox_fits(p.p0, p.p1, seg.tool_length) for p in pieces)",
                "all(self.bbox_fits(p.p0, p.p0, seg.tool_length) for p in pieces)",
                "a straight motion whose start point fits is screened as proved"),
}


def _run(name: str | None, tests: list[str]) -> tuple[str, float]:
    """Run ``tests`` on a copy of the tree with mutation ``name``: "caught" (a test failed), "missed" or "error"."""
    t0 = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="nczones-mutant-") as tmp:
        for part in ("nczones", "tests", "specs", "pyproject.toml"):
            src = ROOT / part
            (shutil.copytree if src.is_dir() else shutil.copy)(src, Path(tmp) / part)
        if name is not None:
            _, _, path, old, new, _ = MUTATIONS[name]
            target = Path(tmp) / path
            text = target.read_text()
            if text.count(old) != 1:
                raise SystemExit(f"{name}: the mutated text no longer occurs once in {path}; update the mutation")
            target.write_text(text.replace(old, new))
        env = dict(os.environ, PYTHONPATH=tmp)
        proc = subprocess.run([sys.executable, "-m", "pytest", "-q", "-x", "-p", "no:xdist", "-p", "no:cacheprovider",
                               "-o", "addopts=--doctest-modules", *tests], cwd=tmp, env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    outcome = {0: "missed", 1: "caught"}.get(proc.returncode, "error")
    if outcome == "error":
        print(proc.stdout[-3000:], file=sys.stderr)
    return outcome, time.monotonic() - t0


def main(argv: list[str]) -> int:
    names = argv or list(MUTATIONS)
    base, secs = _run(None, DIFFERENTIAL)
    print(f"unmutated tree: differential suite {'passes' if base == 'missed' else base} ({secs:.0f} s)")
    if base != "missed":
        return 1
    print(f"{'mutation':<12} {'where':<11} {'differential suite':<20} {'own tests':<10} the bug")
    for name in names:
        where, module, *_, what = MUTATIONS[name]
        caught, secs = _run(name, DIFFERENTIAL)
        own = _run(name, OWN[module])[0] if module is not None else "-"
        print(f"{name:<12} {where:<11} {caught + f' ({secs:.0f} s)':<20} {own:<10} {what}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
