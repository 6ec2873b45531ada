"""The tool solids and the tool the program puts in the spindle (where tool changes meet tool lengths).

The solids proof takes the ``[[tools]]`` entry numbered like the active tool length register, at that
register's length (specs/machine-file.md, "Which tool").  LinuxCNC's ``M6`` changes the tool in the spindle but
not the tool length offset (rs274: ``T2 M6`` prints ``CHANGE_TOOL`` and no ``USE_TOOL_LENGTH_OFFSET``; the
offset changes only with ``G43``/``G49``), so after ``T1 M6 / G43 H1 / T2 M6`` the machine holds tool 2 and
moves it by H1's length.  On the machine below (specs/machines/mill_solids.toml plus a tool 2 whose cutter is
150 long, H2 = 150): at X150 Y40, above the vise jaw X100..250 Y0..80 Z0..60, program Z70 with H1 active is
machine Z 70 + 100 = 170, so tool 2's tip is at 170 - 150 = 20, inside the jaw.  The proof placed tool 1's
solids at Z70 and found them clear: a wrong ``safe``.  Now such a motion is ``unknown`` (VF211); with
``G43 H2`` after the change the same motion is proved (tip at Z70, clear of the jaw top Z60).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nczones.machine import parse_machine
from nczones.prover import verify_text

ROOT = Path(__file__).resolve().parents[2]
TOOL2 = '\n[[tools]]\nnumber = 2\nparts = [{ name = "long cutter", diameter = "10", length = "150" }]\n'


def _machine():
    text = (ROOT / "specs/machines/mill_solids.toml").read_text(encoding="utf-8")
    return parse_machine(text.replace('H1 = "100"', 'H1 = "100"\nH2 = "150"') + TOOL2)


MOVE = "G0 X150 Y40 Z100\nG0 Z70\nG0 Z100\n"
FILLER = "G0 X-50 Y0 Z100\n" + "".join(f"G1 X{-50 + (i % 2) * 10} Y{i % 50} F500\n" for i in range(600))

MISMATCHED = {
    "m6-without-g43": "G21 G90 G17 G54\nT1 M6\nG43 H1\nT2 M6\n",
    "g43-of-another-tool": "G21 G90 G17 G54\nT2 M6\nG43 H1\n",
    "m61": "G21 G90 G17 G54\nT1 M6\nG43 H1\nM61 Q2\n",
}


@pytest.mark.parametrize("name", sorted(MISMATCHED))
@pytest.mark.parametrize("long", [False, True], ids=["short", "600 motions"])
def test_a_motion_with_another_tool_in_the_spindle_is_unknown(name, long):
    program = MISMATCHED[name] + (FILLER if long else "") + MOVE + "M30\n"
    r = verify_text(program, _machine())
    assert r.verdict.label == "unknown" and not r.violations, (r.reasons, r.violations)
    (why,) = [x for x in r.reasons if x.code == "VF211"]
    assert "tool 2 is in the spindle" in why.message and "H1" in why.message


def test_the_same_motion_with_the_tools_own_length_is_proved():
    """``G43 H2`` after the change: tool 2's tip at program Z70, 10 above the jaw: safe, as the contract says."""
    for head in ("G21 G90 G17 G54\nT1 M6\nG43 H1\nT2 M6\nG43 H2\n", "G21 G90 G17 G54\nT2 M6 G43 H2\n",
                 "G21 G90 G17 G54\nT2 M6\nG43\n"):
        r = verify_text(head + MOVE + "M30\n", _machine())
        assert r.verdict.label == "safe", (head, r.reasons, r.violations)


def test_tool_2_really_hits_the_jaw_at_h1s_length():
    """The metamorphic check of the docstring's arithmetic: tool 2 at program Z20 with its own length H2 (tip at
    Z20, the place H1 puts it) is unsafe, so the motion of the mismatched program is not safe."""
    r = verify_text("G21 G90 G17 G54\nT2 M6\nG43 H2\nG0 X150 Y40 Z100\nG0 Z20\nM30\n", _machine())
    assert r.verdict.label == "unsafe"
