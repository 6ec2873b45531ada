"""``safe`` from the double pass on drilling programs (G81-G83: nczones/gcode/linuxcnc/double_cycles.py) is the
full path's verdict, with a zone face at a cycle motion's extreme: the R plane (above the initial level: the
"up to R" rapid and every retract reach it), the hole bottom, the initial level G98 retracts to, and the
farthest hole; the face exactly there, a hair inside and a hair outside.  Where the verdict is ``safe`` with the
face a millimetre away, the pass proved it (its boxes are in the stats): the test is about the pass.
"""

from __future__ import annotations

import os
from decimal import Decimal

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.pipeline.verification as prover_doubles
from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass_cycles import drilling_programs
from tests.machines import box_zone, load_machine
from tests.prover.test_double_pass_proof import machine_of
from tests.prover.test_double_pass_windows import windows_of

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "40"))

#: Offsets of mill_g54_g55_h1_h2: G54 X 100, Z 50, H1 120 (machine Z = program Z + 170); it starts at Z 400.
PROGRAM = ("G21 G90 G17 G54 F200\n#1 = 2\nG43 H1\nG0 X0 Y0 Z250\n{retract} {code} X[#1] Y1 Z-3 R{r}{p}\n"
           "X[#1 * 3] Y[#1 / 3]\nX[#1 + 1] Y-2\nG80\nM30\n")
#: The face's axis and its level (machine mm) per extreme, and the cases it is one in.
FACES = {"R above the initial level": ("Z", "max", Decimal(430), "260"),
         "the initial level (G98)": ("Z", "max", Decimal(420), "2"),
         "the bottom": ("Z", "min", Decimal(167), "2"),
         "the farthest hole": ("X", "max", Decimal(106), "2")}
NUDGES = [Decimal("-0.001"), Decimal(0), Decimal("0.000000000001"), Decimal(1)]


def machine_with_face(axis: str, side: str, level: Decimal):
    low = {"X": "-1000", "Y": "-1000", "Z": "-1000"}
    high = {"X": "1000", "Y": "1000", "Z": "1000"}
    (low if side == "min" else high)[axis] = f"{level:f}"
    return load_machine("mill_g54_g55_h1_h2", extra=box_zone("travel", low, high))


def both_ways(text: str, machine, monkeypatch):
    with_pass = verify_text(text, machine, max_iterations=1000)
    with monkeypatch.context() as m:
        m.setattr(prover_doubles, "double_pass_result", lambda *args, **kwargs: None)
        without = verify_text(text, machine, max_iterations=1000)
    return with_pass, without


@pytest.mark.parametrize("face", sorted(FACES))
@pytest.mark.parametrize("code", ["G81", "G82", "G83"])
@pytest.mark.parametrize("retract", ["G98", "G99"])
def test_a_face_at_a_cycle_extreme(face, code, retract, monkeypatch):
    axis, side, level, r = FACES[face]
    peck = " Q40" if r == "260" else " Q1.5"  # (a few pecks from either R)
    text = PROGRAM.format(retract=retract, code=code, r=r, p={"G81": "", "G82": " P0.5", "G83": peck}[code])
    for nudge in NUDGES:
        # the face moved outwards by nudge (a negative nudge cuts into the motion: unsafe)
        machine = machine_with_face(axis, side, level + nudge if side == "max" else level - nudge)
        with_pass, without = both_ways(text, machine, monkeypatch)
        assert with_pass.verdict == without.verdict, (face, nudge)
        assert [(v.line, v.zone) for v in with_pass.violations] == [(v.line, v.zone) for v in without.violations]
        assert with_pass.verdict is (Verdict.UNSAFE if nudge < 0 else Verdict.SAFE), (face, nudge)
        if nudge == 1:
            assert "double_pass_boxes" in dict(with_pass.stats), "the pass did not prove it"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(drilling_programs(), st.integers(1, 12))
def test_windows_of_drilling_programs_hold_the_full_paths_motion(text, window):
    """A cycle's rows cross window edges (the pass hands a window over after any of them): the windows put back
    together are the rows without windows, and each window's box of each motion holds the full path's motion
    (G83's pecks widen the normal axis from the first peck on: a window before it is narrower than the path
    without windows; without pecks the boxes are the same)."""
    machine = machine_of("box", 1000, 0)
    try:
        whole = double_pass(text, machine, max_iterations=1000)
    except Declined:
        return
    got, last = windows_of(text, machine, window)
    assert (last.motions, last.rapids, last.dwells) == (whole.motions, whole.rapids, whole.dwells)
    for row0, motions, columns, _first in got:
        assert [c[row0:motions + 1] for c in map(list, whole.columns)] == list(columns)
        assert motions - row0 <= max(window, 2)
    segments = list(interpret_text(text, machine, max_loop_iterations=1000).segments())

    def holds(p) -> bool:
        for k in range(p.row0 + 1, p.motions + 1):
            lo, hi = p.enclosure(k, k)
            assert "G83" in text or (lo, hi) == whole.enclosure(k, k)
            for i, a in enumerate(machine.axis_names):
                assert lo[a] <= segments[k - 1].start[i] <= hi[a] and lo[a] <= segments[k - 1].end[i] <= hi[a]
        return True

    windowed = double_pass(text, machine, max_iterations=1000, window=window, on_window=holds)
    assert holds(windowed) and windowed.motions == whole.motions


@pytest.mark.parametrize("window", [1, 2, 3, 5, 64])
def test_peck_rows_keep_their_widening_across_window_edges(window):
    """A peck row kept at a window's edge (the last two rows stay) keeps its widening: every window's box of
    every motion holds the full path's motion, on pecks whose rows drift by many ulps (R 100.1, Q 0.07)."""
    text = "G21 G90 G17 G54 F100\n#1 = 1\nG0 Z150\nG99 G83 X1 Y1 Z-3 R100.1 Q0.07\nG80\nG0 Z150\nM30\n"
    machine = machine_of("box", 1000, 0)
    segments = list(interpret_text(text, machine, max_loop_iterations=100_000).segments())

    def holds(p) -> bool:
        for k in range(p.row0 + 1, p.motions + 1):
            lo, hi = p.enclosure(k, k)
            for i, a in enumerate(machine.axis_names):
                assert lo[a] <= segments[k - 1].start[i] <= hi[a] and lo[a] <= segments[k - 1].end[i] <= hi[a], k
        return True

    last = double_pass(text, machine, max_iterations=100_000, window=window, on_window=holds)
    assert holds(last) and last.motions == len(segments)
