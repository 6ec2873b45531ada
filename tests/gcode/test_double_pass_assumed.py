"""A program that leaves its units, distance mode, work offset or plane to the machine file takes the double pass.

Before, the pass declined the first motion while one of them was still the machine file's (the full path notes
each such group), and such a program, say a parametric one without ``G54`` in its header, ran the full path, some
8x slower (100,000 lines with an expression each: 2.2 s against 0.28 s).  Now the pass runs it in the machine
file's codes and carries the notes (``DoublePath.assumed``): the routed result must be the full path's, notes
included.
"""

from __future__ import annotations

import pytest

from nczones.machine import parse_machine
from nczones.pipeline import verification
from nczones.prover import verify_text

from .test_double_pass import machine_text

POST = '[[zones]]\nname = "post"\nkind = "box"\nforbid = true\nmin = { X = "40", Y = "40", Z = "-1000" }\n' \
       'max = { X = "50", Y = "50", Z = "1000" }\n'


def _result(text: str, machine, monkeypatch, *, routed: bool):
    with monkeypatch.context() as m:
        if not routed:
            m.setattr(verification, "_double_pass_reads", lambda t, machine=None: False)
        return verify_text(text, machine)


PROGRAMS = {
    "no header": "F100\n#1 = 1\nG1 X[#1 * 30] Y2\nG2 X[#1 * 34] Y2 R3\nM30\n",
    "no work offset": "G21 G90 G17 F100\n#1 = 1\nG1 X[#1 * 30] Y2\nG1 X20 Y[#1 * 20]\nM30\n",
    "no plane": "G21 G90 G54 F100\n#1 = 1\nG1 X[#1 * 30] Y2\nG3 X30 Y6 R3\nM30\n",
    "into the post": "F100\n#1 = 1\nG1 X[#1 * 30] Y2\nG1 X45 Y[#1 * 45]\nM30\n",
}


@pytest.mark.parametrize("modal", [None, '["G55"]'])
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_routed_as_the_full_path_notes_included(monkeypatch, name, modal):
    machine = parse_machine(machine_text({"G55": ("1", "2", "0")}, modal=modal, extra=POST))
    text = PROGRAMS[name]
    routed = _result(text, machine, monkeypatch, routed=True)
    full = _result(text, machine, monkeypatch, routed=False)
    assert routed.verdict == full.verdict
    assert routed.notes == full.notes and any("from the machine file" in n for n in routed.notes)
    assert [(v.block, v.zone) for v in routed.violations] == [(v.block, v.zone) for v in full.violations]
    assert dict(routed.stats)["segments"] == dict(full.stats)["segments"]
    if routed.verdict.label == "safe":  # proved by the pass (not declined): its boxes counted
        assert dict(routed.stats).get("double_pass_boxes", 0) >= 1, routed.stats
        assert "double_pass_boxes" not in dict(full.stats)
