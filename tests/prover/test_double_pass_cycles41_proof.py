"""``safe`` from the double pass on G73/G83 in G91 (cyc41: nczones/gcode/linuxcnc/double_cycles.py) is the full
path's verdict with a zone face at the deepest point of the pecks (the bottom, where the last feed ends) and at
the farthest hole of the G91 increments, exactly there, a hair inside and a hair outside (``NUDGES``: one pulse and more).  Where the verdict is
``safe`` with the face a millimetre away, the pass proved it (its boxes are in the stats).
"""

from __future__ import annotations

from decimal import Decimal

import pytest

from nczones.prover.result import Verdict
from tests.prover.test_double_pass_cycles_proof import NUDGES, both_ways, machine_with_face

#: mill_g54_g55_h1_h2: machine Z = program Z + 170 under G54 G43 H1.  The initial level 250 (machine 420), R 248
#: below it (machine 172), the bottom 5 below R (machine 167): pecks of 0.7, the last one short.
PROGRAM = ("G21 G90 G17 G54 F200\n#1 = 2\nG43 H1\nG0 X0 Y0 Z250\n"
           "G91 {retract} {code} X[#1] Y1 Z-5 R-248 Q0.7 L2\nX1\nG90 G80\nM30\n")
#: The holes at X 2, 4 (the L repeats) and 5: machine X 102, 104, 105.
FACES = {"the bottom": ("Z", "min", Decimal(167)), "the last hole": ("X", "max", Decimal(105))}


@pytest.mark.parametrize("retract", ["G98", "G99"])
@pytest.mark.parametrize("code", ["G83", "G73"])
@pytest.mark.parametrize("face", sorted(FACES))
def test_a_face_at_a_g91_peck_extreme(face, code, retract, monkeypatch):
    axis, side, level = FACES[face]
    text = PROGRAM.format(retract=retract, code=code)
    for nudge in NUDGES:
        machine = machine_with_face(axis, side, level + nudge if side == "max" else level - nudge)
        with_pass, without = both_ways(text, machine, monkeypatch)
        assert with_pass.verdict == without.verdict, (face, nudge)
        assert [(v.line, v.zone) for v in with_pass.violations] == [(v.line, v.zone) for v in without.violations]
        assert with_pass.verdict is (Verdict.UNSAFE if nudge < 0 else Verdict.SAFE), (face, nudge)
        if nudge == 1:
            assert "double_pass_boxes" in dict(with_pass.stats), "the pass did not prove it"
