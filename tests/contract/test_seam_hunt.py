"""Soundness hunt where features meet: G64 corners at the seams of the lanes (task t7 "hunt").

The corner proof (``specs/path-modes.md``) and the lanes that feed it (the full interpreter, the vectorized
column chunks, the double pass and its windows) each cut the motion somewhere; a corner whose two motions
fall on the two sides of such a cut is where a wrong ``safe`` hides.  Findings first (each a reproducer
through :func:`nczones.prover.verify_text` that failed before its fix), then the generated hunts.

The probe of every finding is a small forbidden box around a point the control really moves through,
derived from LinuxCNC's planner (``src/emc/tp/blendmath.c``, as quoted in specs/path-modes.md §2 and §7), off
the programmed path: the same program in ``G61`` (no blending) must be ``safe`` (so the probe is off the
path), and in ``G64`` the verdict must not be ``safe``.
"""

from __future__ import annotations

import pytest

import nczones.gcode.linuxcnc.doubles as pass_module
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text


def probe_machine(x0: str, y0: str, x1: str, y1: str, *, path_mode: str = "G64"):
    """``xy_fast`` on a 1000 mm table with a forbidden probe box X x0..x1 Y y0..y1."""
    extra = ('[[zones]]\nname = "table"\nkind = "box"\nmin = { X = "-500", Y = "-500" }\n'
             'max = { X = "500", Y = "500" }\n'
             f'[[zones]]\nname = "probe"\nkind = "box"\nforbid = true\nmin = {{ X = "{x0}", Y = "{y0}" }}\n'
             f'max = {{ X = "{x1}", Y = "{y1}" }}\n')
    return parse_machine(machine_text("xy_fast", set={"machine.path_mode": path_mode}, extra=extra))


# ---------------------------------------------------------------------------------------------------------
# Finding 1: the double pass proved a corner next to a motion of length 0 with the wrong neighbours.
#
# LinuxCNC's canonical layer drops a move of length 0 (and tpAddLine refuses a segment shorter than
# TP_POS_EPSILON), so the corner is between the motions around it.  The double pass proves a corner that
# falls between two of its boxes from rows k-1, k, k+1 only: with motion k+1 of length 0 that region is
# the segment from C to the midpoint of motion k, and the real blend toward motion k+2 was never tested.
# Same at the end of a window (the windows overlap by one motion): a window ending on a motion of length 0
# left the corner of the motions around it in neither window.
#
# The corner: a line along +X of 20 mm into C = (0, 0), then along +Y for 20 mm (a 90 degree turn).
# blendInit3FromLineLine: L1 = min(target, 0.5 * 20) = 10, L2 = 0.5 * 20 = 10; tcFindBlendTolerance with no
# P: T = min(20/4, 20/4) = 5; theta = 45 degrees, h_tol = T / (1 - sin theta) = 17.07, d_tol = cos theta *
# h_tol = 12.07; d_geom = min(L1, L2, d_tol) = 10, R_geom = tan theta * d_geom = 10.  At a feed high enough
# that v_goal^2 / a_n >= R_geom (F10000 is 166 mm/s: above sqrt(a_n * 10) for any a_max below 3,200 mm/s^2),
# v_plan = sqrt(a_n R_geom) and R_plan = R_geom = 10: the blend arc is tangent at (-10, 0) and (0, 10),
# centre (-10, 10), and its middle is (-10 + 10/sqrt 2, 10 - 10/sqrt 2) = (-2.929, 2.929).  The probe
# X -3.2..-2.7 Y 2.7..3.2 holds it and is 2.7 mm off both lines.
PROBE = ("-3.2", "2.7", "-2.7", "3.2")


def _corner_program(before: int, after: int, *, zero: str | None = "0", hashed: bool = True, mode: str = "") -> str:
    """``before`` motions along Y = 0, the last from (-20, 0) into C = (0, 0) (the ones before it run back and
    forth between X-400 and X-20), a motion to X``zero`` (None: none; "0": of length 0; a short one, which
    LinuxCNC's planner drops below 1e-12 mm), then ``after`` motions along X = ``zero``, the first 20 mm up to
    Y20 (the others back and forth between Y300 and Y20).  ``hashed``: a ``#`` line sends it through the double
    pass (which declines a G61 or G64 in the text: the machine starts in G64).  ``mode`` (G61): no blending,
    the control that the probe is off the path."""
    lines = [f"G21 G90 G54 {mode} F10000".replace("  ", " ")] + (["#1 = 0"] if hashed else [])
    lines += [f"G1 X{-20 if (before - 1 - k) % 2 == 0 else -400} Y0" for k in range(1, before)]
    lines.append("G1 X0 Y0")
    if zero is not None:
        lines.append(f"G1 X{zero} Y0")
    x = zero or "0"
    lines += [f"G1 X{x} Y{20 if (k - 1) % 2 == 0 else 300}" for k in range(1, after + 1)]
    return "\n".join(lines) + "\nM2\n"


@pytest.mark.parametrize("before", [2, 40])
def test_zero_motion_at_a_box_boundary_of_the_double_pass(before):
    """16 * ``before`` motions: the double pass's first split (boxes of ``before`` motions) puts a boundary
    right after the motion into C, and the motion after it has length 0.  The 640-motion variant is past
    the vectorized tier's 512 too (its full-path control goes through the column chunks)."""
    m = probe_machine(*PROBE)
    after = 16 * before - before - 1
    assert verify_text(_corner_program(before, after, mode="G61"), m).verdict.label == "safe"  # off the path
    full = verify_text(_corner_program(before, after, hashed=False), m)  # the full path: not safe
    assert full.verdict.label == "unknown" and {r.code for r in full.reasons} == {"VF208"}
    got = verify_text(_corner_program(before, after), m)
    assert got.verdict.label != "safe", "the double pass proved the blend into the probe safe"
    # and with a real motion in place of the zero one the corner is caught by the pass too
    assert verify_text(_corner_program(before, after - 1, zero=None), m).verdict.label != "safe"


def test_zero_motion_at_the_end_of_a_window(monkeypatch):
    """Windows of 8 motions: the first ends on the motion of length 0 after C (motion 8)."""
    monkeypatch.setattr(pass_module, "WINDOW", 8)
    m = probe_machine(*PROBE)
    assert verify_text(_corner_program(7, 4, mode="G61"), m).verdict.label == "safe"
    assert verify_text(_corner_program(7, 4, hashed=False), m).verdict.label == "unknown"
    assert verify_text(_corner_program(7, 4), m).verdict.label != "safe"


# Finding 2: a motion shorter than LinuxCNC's TP_POS_EPSILON (1e-12) is dropped by the planner (tpAddLine:
# ``if (tc.target < TP_POS_EPSILON) return TP_ERR_ZERO_LENGTH``), so the corner joins the motions around it,
# as for a motion of length 0; the prover took 1e-14 mm as a motion and proved the two corners with it (each
# region a segment along one motion), never the blend of the two lines: `safe` with the probe on the blend.
TINY = "0.00000000000001"


@pytest.mark.parametrize(("before", "hashed"), [(2, False), (600, False), (2, True), (40, True)])
def test_motion_shorter_than_the_planner_epsilon(before, hashed):
    """The full interpreter (a short program, and past the vectorized tier's 512 motions) and the double pass
    (``#``; 16 * ``before`` motions, a box boundary after the motion into C)."""
    m = probe_machine(*PROBE)
    after = 16 * before - before - 1 if hashed else 10
    assert verify_text(_corner_program(before, after, zero=TINY, hashed=hashed, mode="G61"), m).verdict.label == "safe"
    got = verify_text(_corner_program(before, after, zero=TINY, hashed=hashed), m)
    assert got.verdict.label != "safe", "a blend across a dropped motion was proved safe"


def test_motion_above_the_planner_epsilon_keeps_its_corners():
    """1e-7 mm is a motion the planner keeps: its two blends use at most half of it each and stay near C, so
    the probe 2.7 mm off both lines is not reached and the program stays provable."""
    m = probe_machine(*PROBE)
    assert verify_text(_corner_program(2, 10, zero="0.0000001", hashed=False), m).verdict.label == "safe"
