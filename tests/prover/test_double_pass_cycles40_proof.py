"""``safe`` from the double pass on G91 drilling programs with L repeats, G73 and G84-G89 (cyc40:
nczones/gcode/linuxcnc/double_cycles.py) is the full path's verdict, with a zone face at a cycle motion's
extreme: the R plane above the initial level (the "up to R" rapid and every retract reach it), the initial level
G98 retracts to, the bottom, and the last of the L repeats (the farthest hole); the face exactly there, a hair
inside and a hair outside.  Where the verdict is ``safe`` with the face a millimetre away, the pass proved it
(its boxes are in the stats): the test is about the pass.
"""

from __future__ import annotations

from decimal import Decimal

import pytest

from nczones.prover.result import Verdict
from tests.prover.test_double_pass_cycles_proof import NUDGES, both_ways, machine_with_face

#: Offsets of mill_g54_g55_h1_h2: G54 X 100, Z 50, H1 120 (machine Z = program Z + 170); it starts at Z 400.
#: The initial level 250 (machine 420); in G91 R is above it and the bottom below R; four holes 2.5 mm apart
#: from X 0 (the last at X 10: machine 110).
PROGRAM = ("G21 G90 G17 G54 F200\n#1 = 2.5\nG43 H1\nM3 S1000\nG0 X0 Y0 Z250\n"
           "G91 {retract} {code} X[#1] Y0.1 Z-8 R{r}{p} L4\nG90 G80\nM30\n")
#: The face's axis and its level (machine mm) per extreme, and R (G91: above the initial level).
FACES = {"R above the initial level": ("Z", "max", Decimal(430), "10"),
         "the initial level (G98)": ("Z", "max", Decimal(420), "-248"),
         "the bottom": ("Z", "min", Decimal(164), "-248"),
         "the last of the repeats": ("X", "max", Decimal(110), "-248")}
DWELL = {"G81": "", "G85": "", "G89": " P0.5", "G84": "", "G86": " P0.5"}


#: (G99 retracts to R, below the initial level: no motion reaches it after the first)
CASES = [(face, retract) for face in sorted(FACES) for retract in ("G98", "G99") if face[4:11] != "initial" or
         retract == "G98"]


@pytest.mark.parametrize(("face", "retract"), CASES)
@pytest.mark.parametrize("code", ["G81", "G85", *(pytest.param(c, marks=pytest.mark.long) for c in ("G84", "G86", "G89"))])
def test_a_face_at_a_g91_cycle_extreme(face, code, retract, monkeypatch):
    axis, side, level, r = FACES[face]
    text = PROGRAM.format(retract=retract, code=code, r=r, p=DWELL[code])
    for nudge in NUDGES:
        # the face moved outwards by nudge (a negative nudge cuts into the motion: unsafe)
        machine = machine_with_face(axis, side, level + nudge if side == "max" else level - nudge)
        with_pass, without = both_ways(text, machine, monkeypatch)
        assert with_pass.verdict == without.verdict, (face, nudge)
        assert [(v.line, v.zone) for v in with_pass.violations] == [(v.line, v.zone) for v in without.violations]
        assert with_pass.verdict is (Verdict.UNSAFE if nudge < 0 else Verdict.SAFE), (face, nudge)
        if nudge == 1:
            assert "double_pass_boxes" in dict(with_pass.stats), "the pass did not prove it"


@pytest.mark.parametrize("retract", ["G98", "G99"])
@pytest.mark.parametrize("nudge", [NUDGES[0], NUDGES[3]])
def test_a_face_at_g73s_last_peck(retract, nudge, monkeypatch):
    # G73's pecks back off upwards by 0.254 mm: the bottom (machine 167) is the lowest point, the pecks above it
    text = ("G21 G90 G17 G54 F200\n#1 = 2\nG43 H1\nG0 X0 Y0 Z250\n"
            f"{retract} G73 X[#1] Y1 Z-3 R2 Q0.7 L2\nX[#1 * 3]\nG80\nM30\n")
    machine = machine_with_face("Z", "min", Decimal(167) - nudge)
    with_pass, without = both_ways(text, machine, monkeypatch)
    assert with_pass.verdict == without.verdict
    assert with_pass.verdict is (Verdict.UNSAFE if nudge < 0 else Verdict.SAFE)
    if nudge == 1:
        assert "double_pass_boxes" in dict(with_pass.stats), "the pass did not prove it"
