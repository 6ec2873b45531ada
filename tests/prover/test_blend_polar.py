"""A Fanuc turning centre in cutting mode (G64, no path_tolerance) around polar moves (G12.1; issue 35).

Acc/dec after interpolation filters each machine axis (X and C too) with a non-negative, unit-mass impulse
response, so the moved path stays in the convex hull of the commanded machine positions since the last exact
stop (specs/path-modes.md §3).  A polar move's machine positions (X = centre + |p|, C = entry angle + the
unwound angle of p) are enclosed by the pieces the per-motion proof walks (``nczones.prover.polar``), so the
hull of a run with polar moves is a box nczones can prove; before, such a run was ``unknown``.
"""

from __future__ import annotations

from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

FACE = """G21 G98 G54
G00 X40. Z2. C0.
G01 Z-1. F200.
G12.1
G01 X40. C10. F100.
G03 X20. C20. R10.
G01 X-40.
C-10.
G03 X-20. C-20. I10. J0
G01 X40.
C0
G13.1
G00 Z10.
"""


def _machine(zone: str, path_mode: str | None = None):
    """The turning centre of tests/machines/fanuc_xzc_turning_centre.toml with the forbidden box ``clamp`` (``zone``:
    its min and max lines) and, if given, a path mode."""
    clamp = '[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\n' + zone + "\n"
    return parse_machine(machine_text("fanuc_xzc_turning_centre", extra=clamp,
                                      set={"machine.path_mode": path_mode} if path_mode else None),
                         "turning_centre.toml")


# machine X is a radius: the square's corners (+-20, +-20) in the plane are at most 20 sqrt2 = 28.3 from the
# centre; the run (G00 X40. Z2. .. G00 Z10.) stays within X 0..28.3 (radius), work Z -1..10 (machine 199..210)
FAR = 'min = { X = "100", Z = "150" }\nmax = { X = "110", Z = "700" }'
# X 25..27, machine Z 205..209 (work Z 5..9): inside the run's box (X up to 28.3, Z up to 210), off the path
# (above Z 199 the tool is only at X 20: the start and the final retract)
IN_HULL = 'min = { X = "25", Z = "205" }\nmax = { X = "27", Z = "209" }'


def test_a_polar_run_in_cutting_mode_is_proved_by_its_hull():
    assert verify_text(FACE, _machine(FAR)).verdict.label == "safe"
    assert verify_text(FACE, _machine(FAR, "G61")).verdict.label == "safe"


def test_a_zone_in_the_hull_of_a_polar_run_is_unknown_in_cutting_mode_only():
    got = verify_text(FACE, _machine(IN_HULL))
    assert got.verdict.label == "unknown"
    assert any(r.code == "VF208" for r in got.reasons)
    assert verify_text(FACE, _machine(IN_HULL, "G61")).verdict.label == "safe"
