"""A Fanuc arc alone between two exact stops in cutting mode is held to its run's enclosure (hunt36b).

specs/path-modes.md §3: a Fanuc control in cutting mode (G64) smooths the interpolated path by acc/dec after
interpolation, whose filters average commanded positions, "so the moved path stays in the convex hull of the
commanded path since the last exact stop"; FANUC's AI contour control specification (A-63512EN, 2.3) says the
same of any interpolated data: "acceleration / deceleration is applied to the interpolated data.
Consequently, the interpolated data is changed by acceleration / deceleration", the machining profile errors
acc/dec before interpolation removes (on a circle: the radius shrinks).  Without ``path_tolerance`` nczones
proves each run's box (its hull on a two-axis machine).  A run of one motion was skipped: right for a straight
motion (its hull is itself), wrong for an arc, whose hull is the region between the arc and its chord (a full
circle: the disk).  ``G04 / G02 I9. / G04`` with a tip probe inside the circle and off the arc was ``safe``.

The geometry (test mill: G54 = (100, 50, -200), EXT Z 1, no tool length): ``G00 X-9. Y9. Z0.`` puts the tool
at machine (91, 59, -199); ``G02 I9. J0.`` is the full circle about machine (100, 59) of radius 9.  The probe
(a forbidden tip box) X 91.001..92, Y 58.9..59.1, Z -200..-198: its nearest corner to the centre, (92, 58.9),
is at distance sqrt(8^2 + 0.1^2) < 9 and its farthest, (91.001, 59.1), at sqrt(8.999^2 + 0.1^2) =
sqrt(80.992) < 9, so the probe lies inside the disk; the circle's points with Y in 58.9..59.1 have
X <= 100 - sqrt(81 - 0.1^2) = 91.00056 < 91.001, so the arc itself never enters it.
"""

from __future__ import annotations

import pytest

from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.gcode.fanuc.helpers import MILL

PROBE = ('\n[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
         'max = { X = "1000", Y = "1000", Z = "1000" }\n'
         '[[zones]]\nname = "probe"\nkind = "box"\nforbid = true\npoint = "tip"\n'
         'min = { X = "91.001", Y = "58.9", Z = "-200" }\nmax = { X = "92", Y = "59.1", Z = "-198" }\n')
MACHINE = parse_machine(MILL.replace("{fanuc_extra}", "").replace("{tables}", PROBE), "mill.toml")

# 600 looped motions first (the proof's vectorized tier, the column runs), away from the probe
_PAD = ["#1 = 0", "WHILE [#1 LT 300] DO1", "G01 X[#1 MOD 3 - 30.] Y-30.", "G01 Y-31.", "#1 = #1 + 1", "END1",
        "G04 X0"]


def _program(arc: str, pad: bool) -> str:
    head = ["O1", "G90 G17 G21 G54 G49 G64 F500."]
    return "\n".join([*head, *(_PAD if pad else []), "G00 X-9. Y9. Z0.", "G04 X0", arc, "G04 X0", "M30"]) + "\n"


@pytest.mark.parametrize("pad", [False, True])
@pytest.mark.parametrize("arc", ["G02 I9. J0.", "G03 I9. J0.", "G02 X0. Y18. R9.", "G02 X0. Y18. I9. J0."])
def test_a_lone_arc_in_cutting_mode_is_held_to_its_hull(arc, pad):
    r = verify_text(_program(arc, pad), MACHINE)
    if pad:
        assert dict(r.stats)["segments"] > 512
    assert r.verdict.label == "unknown", (r.verdict, r.violations)
    assert any(x.code == "VF208" and "probe" in x.message for x in r.reasons)


@pytest.mark.parametrize("pad", [False, True])
def test_a_lone_straight_motion_and_an_arc_far_away_stay_safe(pad):
    """A straight motion alone is its own hull: G01 X-9. Y-9. from (91, 59) runs down X = 91 < 91.001, the
    probe untouched; the circle about program (-20, 9) (machine 80, 59) of radius 9 reaches X 89 at most."""
    for arc in ("G01 X-9. Y-9.", "G00 X-29. Y9.\nG04 X0\nG02 I9. J0."):
        r = verify_text(_program(arc, pad), MACHINE)
        assert r.verdict.label == "safe", (arc, r.reasons, r.violations)



# ---------------------------------------------------------------------------------------------------------------
# In every path mode (the lead's follow-up of hunt36b's open question): the filters act on the interpolated data
# of every cutting block, so G61 and G09 (which decelerate and check in-position only at the END of a block) do
# not stop them pulling an arc inside; `path_tolerance` bounds corner rounding only (specs/path-modes.md §3).
# Before, `G09 G02 I9.` in cutting mode and `G02 I9.` under G61 were `safe` with the probe inside the circle.
TOLERANT = parse_machine(MILL.replace("[machine]\n", '[machine]\npath_tolerance = "0.01"\n', 1)
                         .replace("{fanuc_extra}", "").replace("{tables}", PROBE), "mill.toml")


@pytest.mark.parametrize("pad", [False, True])
@pytest.mark.parametrize("mode, arc, machine", [
    ("G61", "G02 I9. J0.", MACHINE), ("G61", "G03 I9. J0.", MACHINE), ("G61", "G02 X0. Y18. I9. J0.", MACHINE),
    ("G61", "G02 X0. Y18. R9.", MACHINE), ("G64", "G09 G02 I9. J0.", MACHINE), ("G64", "G02 I9. J0.", TOLERANT),
    ("G61", "G02 I9. J0.", TOLERANT)])
def test_an_arc_is_held_to_its_hull_in_every_path_mode(mode, arc, machine, pad):
    r = verify_text(_program(arc, pad).replace("G64", mode), machine)
    if pad:
        assert dict(r.stats)["segments"] > 512
    assert r.verdict.label == "unknown", (r.verdict, r.violations)
    why = [x.message for x in r.reasons if x.code == "VF208" and "probe" in x.message]
    assert why and "the motion of line" in why[0] and "between the arc and its chord" in why[0]


@pytest.mark.parametrize("pad", [False, True])
@pytest.mark.parametrize("mode, machine", [("G61", MACHINE), ("G64", TOLERANT)])
def test_arcs_away_from_the_probe_stay_safe_in_every_path_mode(mode, machine, pad):
    """The circle about machine (80, 59) of radius 9 (see above) reaches X 89 at most; a straight motion is its own
    hull in every mode."""
    for arc in ("G01 X-9. Y-9.", "G00 X-29. Y9.\nG04 X0\nG02 I9. J0.", "G00 X-29. Y9.\nG09 G02 I9. J0."):
        r = verify_text(_program(arc, pad).replace("G64", mode), machine)
        assert r.verdict.label == "safe", (arc, r.reasons, r.violations)
