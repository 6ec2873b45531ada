"""nczones against LinuxCNC's ``rs274 -g`` on generated modal save/restore programs (M70, M71, M72, M73).

``tests/gcode/data/rs274_modal/`` holds programs of ``tests/tools/rs274_modal.py`` (every group LinuxCNC's
``save_settings`` keeps changed between a save and a restore: units, distance and arc-centre modes, plane,
work offsets, feed mode and F, spindle, retract mode, G43/G43.1/G49, G92/G52 applied or not, G7/G8; saves and
restores by M70/M72 in the main program, M73 in o-word and M98 subroutines, M71, M72 in a frame that saved
nothing) and, in ``expected.json``, the motion or error ``rs274 -g`` (LinuxCNC 2.9.0~pre1) gave for each.
``python -m tests.tools.rs274_modal record`` rewrites them where rs274 is installed; ``run`` compares fresh
programs (``specs/gcode-support.md``, "M70-M73").
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import pytest

from nczones.machine import parse_machine
from tests.oracles.rs274 import CanonMove, compare, machine_text

DATA = Path(__file__).parent / "data" / "rs274_modal"
EXPECTED = json.loads((DATA / "expected.json").read_text())


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_modal_restore_as_linuxcnc(name):
    case = EXPECTED[name]
    tools = {int(k): Fraction(v) for k, v in case["tools_inch"].items()}
    offsets = {k: {a: Fraction(v) for a, v in o.items()} for k, o in case["offsets_inch"].items()}
    machine = parse_machine(machine_text(tuple(case["axes"]), tools, offsets))
    moves = [CanonMove.from_json(row) for row in case["motion"]]
    error = tuple(case["error"]) if case["error"] else None
    outcome = compare((DATA / f"{name}.ngc").read_text(), machine, moves, error)
    if outcome.status == "unknown" and "G20/G21 while a tool length is applied" in outcome.detail:
        # conservative by design (tests/gcode/test_rs274_findings_fixed.py): G43/G49 after a units change under a
        # tool length is unknown; LinuxCNC's stale-unit position only shows on a later move that omits Z
        return
    assert outcome.status == "match", outcome.detail


def test_the_recording_covers_every_saved_group():
    texts = [(DATA / f"{n}.ngc").read_text() for n in EXPECTED]
    joined = "\n".join(texts)
    assert len(EXPECTED) >= 60
    assert sum(len(c["motion"]) for c in EXPECTED.values()) >= 800
    assert any(c["error"] for c in EXPECTED.values())
    for code in ("M70", "M71", "M72", "M73", "M98", "G20", "G21", "G91", "G90.1", "G91.1", "G18", "G19", "G55",
                 "G56", "G95", "G98", "G99", "G43 H", "G43\n", "G43.1", "G49", "G92 ", "G92.1", "G92.2", "G92.3",
                 "G52", "G10 L2", "G7", "G8", "M3", "M5", "F0.04", "F12.34", "G81"):
        assert code in joined, code
