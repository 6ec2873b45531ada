"""Every motion kind × every consumer (docs/design.md §10 "How to add a motion kind").

Each consumer of motion dispatches on ``SegmentKind`` through one table: the prover's deciders
(``prover.core.DECIDERS``), the controller's planners (``controller.simulator.PLANNED_KINDS``), the plot's
sampling (``report.plot.SAMPLED_KINDS``) and replay's on-the-motion test (``replay.REPLAYED_KINDS``).
A new kind fails here until every table has it.  Real programs then produce every kind, and each is run
through every consumer: the prover decides it (no "not handled"), the controller moves it to its end, the
plot's samples start and end where the motion does.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from nczones.controller.simulator import PLANNED_KINDS, simulate
from nczones.gcode import segments_text
from nczones.machine import load_machine
from nczones.motion import PolarData, Segment, SegmentKind, SplineCurve
from nczones.prover import verify_text
from nczones.prover.core import DECIDERS
from nczones.replay import REPLAYED_KINDS
from nczones.report.plot import SAMPLED_KINDS, path_points_float

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"

# (machine file, program): together they produce every kind
MILL_TEXT = ("G21 G90 G61 G54 G94\nG0 X10 Y10 Z10\nG1 X20 F600\nG2 X30 Y10 I5 J0\nG4 P0.5\n"
             "G5.1 X40 Y20 I5 J5\nG0 Z20\nM30\n")
CASES = {
    "mill": (ROOT / "specs" / "machines" / "mill.toml", MILL_TEXT),
    "cylinder": (EX / "machines" / "cylinder.toml", (EX / "programs" / "cam_groove_g071.ngc").read_text()),
    "polar": (EX / "machines" / "turning_centre.toml", (EX / "programs" / "polar_face.nc").read_text()),
}


def _segments() -> dict[SegmentKind, list[tuple[str, Segment]]]:
    out: dict[SegmentKind, list[tuple[str, Segment]]] = {}
    for name, (mfile, text) in CASES.items():
        for seg in segments_text(text, load_machine(mfile)):
            out.setdefault(seg.kind, []).append((name, seg))
    return out


SEGMENTS = _segments()


@pytest.mark.parametrize("table, kinds", [("prover.core.DECIDERS", frozenset(DECIDERS)),
                                          ("controller.simulator.PLANNED_KINDS", PLANNED_KINDS),
                                          ("report.plot.SAMPLED_KINDS", SAMPLED_KINDS),
                                          ("replay.REPLAYED_KINDS", REPLAYED_KINDS)])
def test_every_table_has_every_kind(table, kinds):
    missing = set(SegmentKind) - set(kinds)
    assert not missing, f"{table} has no entry for {sorted(k.name for k in missing)}"


def test_the_programs_produce_every_kind():
    assert set(SEGMENTS) == set(SegmentKind), sorted(k.name for k in set(SegmentKind) - set(SEGMENTS))
    (_, spline), = SEGMENTS[SegmentKind.SPLINE]
    assert spline.payload(SplineCurve) is not None and spline.payload(SplineCurve).source == "G5.1"
    assert all(s.payload(PolarData) is not None for _, s in SEGMENTS[SegmentKind.POLAR])


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_prover_decides_every_kind(case):
    mfile, text = CASES[case]
    result = verify_text(text, load_machine(mfile))
    assert result.verdict.name in ("SAFE", "UNSAFE"), result.reasons
    assert not any("not handled" in r.message for r in result.reasons)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_controller_moves_every_kind_to_its_end(case):
    mfile, text = CASES[case]
    machine = load_machine(mfile)
    segs = segments_text(text, machine)
    sim = simulate(segs, machine)
    pulse = [a.pulse for a in machine.axes]
    # the interpolation ends on the last motion's end, rounded to the pulse grid
    assert all(abs(p - e) <= u / 2 for p, e, u in zip(sim.program_position, segs[-1].end, pulse))


@pytest.mark.parametrize("kind", list(SegmentKind), ids=lambda k: k.name)
def test_plot_samples_start_and_end_with_the_motion(kind):
    for case, seg in SEGMENTS[kind]:
        machine = load_machine(CASES[case][0])
        pts = path_points_float(seg, machine)
        assert len(pts) >= 2
        # within a pulse: a polar move's plane path is exact, its end point rounded to the output grid
        tol = [float(a.pulse) for a in machine.axes]
        for got, want in ((pts[0], seg.start), (pts[-1], seg.end)):
            assert all(abs(g - float(w)) <= t for g, w, t in zip(got, want, tol)), (case, kind, got, want)
