"""G92.1 (workpiece coordinate system preset) where no manual text settles it: unknown, never a guess.

nczones read ``G92.1`` as "cancel the G92 shift of every axis", whatever the block named, and left a G52 local
system in place.  The sentence that would say which axes the preset acts on and whether it also cancels G52
was written from memory (issue 33's leftovers) and could not be found in a manual here (specs/fanuc.md, the
G92.1 row).  The one reading every candidate agrees on is kept: ``G92.1 X0 Y0 Z0`` with only G92 shifts on the
named axes returns them to the unshifted workpiece system (``tests/gcode/fanuc/test_reference_findings.py`` N1).
The rest is unknown.  Through ``verify_text`` on a short program, one with > 512 motions and one with a
macro variable.
"""

from __future__ import annotations

import pytest

from nczones.machine import parse_machine
from nczones.prover import Verdict, verify_text
from tests.gcode.fanuc.helpers import MILL

ZONES = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "0", Y = "0", Z = "-250" }\n'
         'max = { X = "300", Y = "200", Z = "0" }\n')
MACHINE = parse_machine(MILL.replace("{fanuc_extra}", "").replace("{tables}", "") + ZONES, "mill.toml")
LONG = "".join(f"G01 X{5 + k % 3}. Y{5 + k % 2}. F500.\n" for k in range(600))
SHAPES = {"short": "", "long": LONG, "macro": "#1 = 5.\nG00 X#1\n"}


def _run(body: str, shape: str):
    # G54 = (100, 50, -200): X5. Y5. Z5. is machine (105, 55, -195)
    text = f"G21 G90 G54 G00 X5. Y5. Z-5.\n{SHAPES[shape]}G00 X5. Y5. Z-5.\n{body}M30\n"
    return verify_text(text, MACHINE, file="p.nc")


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("body,why", [
    # Y's G92 shift is not named: the old reading cancelled it too (G00 Y60. then went to machine Y 110, inside);
    # if the control presets only the named axes, Y60. is machine Y 60 + 50 + 5 = 115 (also inside here, but the
    # proof must not rest on either reading)
    ("G92 X0 Y0\nG92.1 X0\nG00 Y60.\n", "does not name an axis with a G92 shift"),
    ("G52 X10.\nG92.1 X0 Y0 Z0\nG00 X0\n", "local coordinate system (G52)"),
    ("G92 X0\nG92.1\nG00 X0\n", "without axis words"),
    ("G92 X0\nG92.1 X3.\nG00 X0\n", "other than 0"),
])
def test_a_preset_the_manual_text_does_not_settle_is_unknown(body, why, shape):
    r = _run(body, shape)
    assert r.verdict is Verdict.UNKNOWN, r.verdict
    assert any(why in x.message for x in r.reasons), r.reasons


@pytest.mark.parametrize("shape", SHAPES)
def test_a_preset_of_the_shifted_axes_returns_to_the_workpiece_system(shape):
    # G92 X0 Y0 at G54 X5. Y5.: the point (machine X 105) reads X0.  G92.1 X0 Y0 returns X and Y to G54 (program
    # X = machine X - 100), so G00 X-105. goes to machine X -5: outside the travel box (X from 0), unsafe.  With
    # the G92 shift kept it would end at machine X 0, on the box: the verdict tells the readings apart.
    r = _run("G92 X0 Y0\nG92.1 X0 Y0\nG00 X-105.\n", shape)
    assert r.verdict is Verdict.UNSAFE and r.violations[0].zone == "travel"
