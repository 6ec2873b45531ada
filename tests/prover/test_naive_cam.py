"""G64 Q without P: naive-CAM merging, then blends with no tolerance (issue 35, specs/path-modes.md §2).

LinuxCNC v2.9.0-pre1 ``convert_control_mode``: ``G64 Q q`` without P sets the blend tolerance 0 (none) and the
naive-CAM tolerance q.  ``emccanon.cc`` then merges consecutive straight feeds into one line while every point
of the chain (at most 101) lies within q of it, and the planner blends the merged lines using up to half of
each (``blendInit3FromLineLine``).  nczones proves every corner over the windows of NAIVE_CHAIN motions before
and after it (``nczones.prover.blend._NaiveWindows``); the model is checked against an independent model of
the merging (``tests/oracles/blend.py`` ``naive_cam``) followed by the planner's blend arc.
"""

from __future__ import annotations

from decimal import Decimal

import pytest

from nczones.machine import parse_machine
from nczones.prover import blend as blend_module
from nczones.prover import verify_text
from tests.machines import box_zone, machine_text
from tests.oracles.blend import blend_arc, naive_cam


def _machine(x0, y0, x1, y1):
    clamp = box_zone("clamp", {"X": x0, "Y": y0}, {"X": x1, "Y": y1}, forbid=True)
    return parse_machine(machine_text("xyz_table_200_naive_cam", extra=clamp))


def _zigzag(n: int, wiggle: str = "0.004"):
    """X0 Y0 -> X100 Y0 -> X100 Y100 in n steps per side, every other point off the line by ``wiggle``."""
    pts = [(Decimal(100) * k / n, Decimal(wiggle) if k % 2 and k < n else Decimal(0)) for k in range(1, n + 1)]
    pts += [(Decimal(100) - (Decimal(wiggle) if k % 2 and k < n else 0), Decimal(100) * k / n) for k in range(1, n + 1)]
    return pts


def _program(pts, mode="G64 Q0.01"):
    body = "\n".join(f"G1 X{x.normalize():f} Y{y.normalize():f}" for x, y in pts)
    return f"G61\nG0 X0 Y0\n{mode}\nG1 F600 X0 Y0\n{body}\nG61\nG4 P0\n"


def _deep_blend_point(pts):
    """A point of the planner's blend at X100 Y0 after naive CAM merged the motions around it (far from the
    programmed path: with slow acceleration a blend of merged lines reaches half of each into the corner)."""
    merged = naive_cam((0.0, 0.0), [(float(x), float(y)) for x, y in pts], 0.01)
    k = merged.index((100.0, 0.0))
    assert k >= 1 and merged[k - 1][0] <= 100 - 100 / len(pts), merged  # a merged line ends at the corner
    arc = blend_arc(merged[k - 1], merged[k], merged[k + 1], a_max=50.0, v_goal=1000.0)
    return max(arc, key=lambda p: min(p[1], 100 - p[0]))


@pytest.mark.parametrize("n", [10, 300])  # 20 motions (per-segment tier), 600 (> 512: the column tier)
def test_a_clamp_at_a_merged_blend_point_is_never_safe(n):
    pts = _zigzag(n)
    x, y = _deep_blend_point(pts)
    assert 1 < y and x < 99  # off the programmed path by more than a millimetre
    m = _machine(f"{x - 0.5:.3f}", f"{y - 0.5:.3f}", f"{x + 0.5:.3f}", f"{y + 0.5:.3f}")
    assert verify_text(_program(pts), m).verdict.label == "unknown"
    assert verify_text(_program(pts, "G61"), m).verdict.label == "safe"


@pytest.mark.parametrize("n", [10, 300])
def test_a_clamp_outside_the_merging_windows_is_proved(n):
    # Every merged line runs between programmed points of the L and every blend lies in the triangle of its
    # lines' far ends and the corner: a clamp beyond the L's hypotenuse (X + Y < 100 is inside it) is never
    # reached.  Before issue 35's follow-up, every G64 Q without P corner was unknown.
    pts = _zigzag(n)
    m = _machine("5", "150", "20", "160")
    assert verify_text(_program(pts), m).verdict.label == "safe"
    m = _machine("150", "5", "160", "20")  # beyond X100 on the first side's end: outside every window's box
    assert verify_text(_program(pts), m).verdict.label == "safe"


def test_shrinking_the_merging_window_lets_the_blend_through(monkeypatch):
    pts = _zigzag(10)
    x, y = _deep_blend_point(pts)
    m = _machine(f"{x - 0.5:.3f}", f"{y - 0.5:.3f}", f"{x + 0.5:.3f}", f"{y + 0.5:.3f}")
    assert verify_text(_program(pts), m).verdict.label == "unknown"
    monkeypatch.setattr(blend_module, "NAIVE_CHAIN", 1)  # only the two motions at each corner
    assert verify_text(_program(pts), m).verdict.label == "safe", "one motion each side must not hold a merged blend"


def test_p0_with_q_is_q_without_p():
    # convert_control_mode: P0 is a tolerance of 0, which tcFindBlendTolerance reads as none
    pts = _zigzag(10)
    x, y = _deep_blend_point(pts)
    m = _machine(f"{x - 0.5:.3f}", f"{y - 0.5:.3f}", f"{x + 0.5:.3f}", f"{y + 0.5:.3f}")
    assert verify_text(_program(pts, "G64 P0 Q0.01"), m).verdict.label == "unknown"
    assert verify_text(_program(pts, "G64 P0 Q0.01"), _machine("5", "150", "20", "160")).verdict.label == "safe"


def test_with_parameters_in_the_text():
    # '#' in a LinuxCNC program would take the double pass; G64 in the text makes it decline (prover/doubles.py),
    # so the corners are proved as above
    pts = _zigzag(10)
    x, y = _deep_blend_point(pts)
    m = _machine(f"{x - 0.5:.3f}", f"{y - 0.5:.3f}", f"{x + 0.5:.3f}", f"{y + 0.5:.3f}")
    text = "#1 = 0.01\n" + _program(pts).replace("G64 Q0.01", "G64 Q#1")
    assert verify_text(text, m).verdict.label == "unknown"
    assert verify_text(text, _machine("5", "150", "20", "160")).verdict.label == "safe"
