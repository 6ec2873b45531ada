"""Blended corners on a lathe whose tool offsets move the tip off the controlled point (Fanuc T-word offsets).

A Fanuc lathe's ``T0101`` with ``[tool_offsets] 1 = { X = "50" }`` moves the controlled point by the offset and
the tip zones see ``machine - offset`` (specs/turning.md; ``TipOffset``), so the tip follows the programmed
path.  The corner proof tested its enclosures (in machine coordinates) against the tip zones unmoved: a tip
zone 0.2 mm inside the programmed corner was never met by the enclosure, which ran 50 mm away, and the verdict
was ``safe`` while the control in cutting mode may round that corner through the zone.

The relation every case checks: the tip follows the program whatever the offset, so the verdict with the
offset equals the verdict of the same program without it (offset 0: machine = program = tip).  And by hand:
the programmed tip corner is X100 Z0 (``G01 X100. Z0`` then ``G01 X150. Z0``); the forbidden tip zone `post`
X100.2..101 Z-1..-0.2 lies 0.2 mm inside it.  With ``path_tolerance = "0.5"`` the control may pass within 0.5
of the corner (specs/path-modes.md §3), which reaches the zone: ``unknown`` (VF208); without a tolerance the
hull of the run (from the reference point X200 Z300) holds the zone: ``unknown``; in G61 the path clears it.
"""

from __future__ import annotations

import pytest

from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

CORNER = "G00 X100. Z-50.\nG01 F100 X100. Z0\nG01 X150. Z0\n"
FILLER = "".join(f"G01 X{60 + i % 7}. Z{-100 - i % 5}.\n" for i in range(600))  # > 512 motions, far from `post`


def _text(mode: str, tol: str, offset: str) -> str:
    """tests/machines/fanuc_lathe_tip_post.toml in path mode ``mode``, with ``path_tolerance = tol`` (none when
    empty) and tool 1's X offset."""
    keys: dict[str, object] = {"machine.path_mode": mode, "tool_offsets.1": {"X": offset, "Z": "0"}}
    return machine_text("fanuc_lathe_tip_post", set=keys | ({"machine.path_tolerance": tol} if tol else {}))


def _machine(mode: str, tol: str, offset: str):
    return parse_machine(_text(mode, tol, offset))


@pytest.mark.parametrize("mode, tol, expected", [("G64", "0.5", "unknown"), ("G64", "", "unknown"),
                                                 ("G61", "", "safe")])
@pytest.mark.parametrize("long", [False, True], ids=["short", "600 motions"])
def test_the_corner_sees_the_tip_zone_where_the_tip_is(mode, tol, expected, long):
    program = "T0101\n" + ("G00 X60. Z-100.\nG01 F100\n" + FILLER if long else "") + CORNER + "M30\n"
    verdicts = {}
    for offset in ("50", "0"):
        r = verify_text(program, _machine(mode, tol, offset))
        assert not r.violations, r.violations
        verdicts[offset] = r.verdict.label
        if expected == "unknown":
            assert "`post`" in " ".join(x.message for x in r.reasons if x.code == "VF208"), r.reasons
    assert verdicts == {"50": expected, "0": expected}


# The hull of a cutting-mode run on a two-axis machine (nczones.prover.hull2d): the run X0 Z0 -> X0 Z10 ->
# X10 Z10 (tip = program, no offset) has the triangle (0,0), (0,10), (10,10) as its convex hull and the square
# X0..10 Z0..10 as its box.  A forbidden tip box at X6..9 Z1..3 lies in the box but below the hypotenuse X = Z
# (the point X6 Z3 has X > Z): outside the hull, so the control (inside the hull, specs/path-modes.md §3)
# cannot reach it: safe, where the box alone said unknown.  At X1..3 Z6..9 it lies inside the triangle
# (X < Z): unknown.  The run starts at the reference point X200 Z300, so the hull is that of (200,300), (0,0),
# (0,10), (10,10): its lower edge runs from (0,0) to (200,300) (Z = 1.5 X) and every point of X6..9 Z1..3 lies
# below it (Z <= 3 < 9 <= 1.5 X): still outside.
TRIANGLE = "G00 X0 Z0\nG01 F100 X0 Z10.\nG01 X10. Z10.\nM30\n"


@pytest.mark.parametrize("post, expected", [(("6", "9", "1", "3"), "safe"), (("1", "3", "6", "9"), "unknown")])
def test_the_run_is_proved_by_its_hull_not_its_box(post, expected):
    x0, x1, z0, z1 = post
    text = _text("G64", "", "0").replace(
        'min = { X = "100.2", Z = "-1" }', f'min = {{ X = "{x0}", Z = "{z0}" }}').replace(
        'max = { X = "101", Z = "-0.2" }', f'max = {{ X = "{x1}", Z = "{z1}" }}')
    r = verify_text("T0101\n" + TRIANGLE, parse_machine(text))
    assert r.verdict.label == expected and not r.violations, r.reasons
    # exact stop (G61): the path itself clears both posts
    assert verify_text("T0101\n" + TRIANGLE, parse_machine(text.replace('"G64"', '"G61"'))).verdict.label == "safe"


def test_the_bundled_g71_clear_is_proved_by_the_hull_of_its_run():
    """specs/examples/programs/g71_clear.nc on specs/machines/fanuc_lathe.toml (cutting mode, no path_tolerance):
    the run from the reference point X240 Z650 to the cycle's passes near Z192 has a box that holds the tailstock
    (a tip zone: X 0..45 from Z360 in tip coordinates, the tool's X offset 80 and length 50 off), but its hull's
    left edge, from (X240, Z650) to (X95.2, Z252.1) in machine coordinates, passes machine Z410 (tip Z360) at
    machine X 95.2 + 144.8 x 157.9 / 397.9 = 152.7 (tip X 72.7), clear of it: safe."""
    from pathlib import Path

    from nczones.machine import load_machine
    from nczones.prover import verify

    root = Path(__file__).resolve().parents[2]
    r = verify(str(root / "specs/examples/programs/g71_clear.nc"), load_machine(root / "specs/machines/fanuc_lathe.toml"))
    assert r.verdict.label == "safe", r.reasons
