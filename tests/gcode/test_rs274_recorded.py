"""nczones against LinuxCNC's own interpreter on recorded generated programs, without LinuxCNC.

``tests/gcode/data/rs274/`` holds programs from the generator of ``tests/tools/rs274_diff.py`` (modal state
mixed in many orders: units, distance and arc-centre modes, planes, work offsets and G10 L2/L20 with rotation,
tool lengths through G10 L1/L10/L11, G43/G43.1/G49 and tool changes, G92/G52, G28/G30, G53, canned cycles with
repeats, dwells, feed modes, parameters, o-word control flow and subroutines) and, in ``expected.json``, the
motion ``rs274 -g`` (LinuxCNC 2.9) printed for each, parsed to machine millimetres with its rounding bound
(:mod:`tests.oracles.rs274`), or the error it stopped with.  ``python -m tests.tools.rs274_diff record``
rewrites them where ``rs274`` is installed.
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import pytest

from nczones.machine import parse_machine
from tests.oracles.rs274 import CanonMove, compare, machine_text

DATA = Path(__file__).parent / "data" / "rs274"
EXPECTED = json.loads((DATA / "expected.json").read_text())


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_nczones_moves_as_linuxcnc_did(name):
    case = EXPECTED[name]
    tools = {int(k): Fraction(v) for k, v in case["tools_inch"].items()}
    offsets = {k: {a: Fraction(v) for a, v in o.items()} for k, o in case.get("offsets_inch", {}).items()}
    machine = parse_machine(machine_text(tuple(case["axes"]), tools, offsets))
    moves = [CanonMove.from_json(row) for row in case["motion"]]
    error = tuple(case["error"]) if case["error"] else None
    outcome = compare((DATA / f"{name}.ngc").read_text(), machine, moves, error)
    assert outcome.status == "match", outcome.detail


def test_the_recording_covers_the_features():
    """The recorded set is not a handful of trivial programs: it moves, refuses and mixes the modal codes."""
    texts = [(DATA / f"{n}.ngc").read_text() for n in EXPECTED]
    joined = "\n".join(texts)
    assert len(EXPECTED) >= 80
    assert sum(len(c["motion"]) for c in EXPECTED.values()) >= 2000
    assert any(c["error"] for c in EXPECTED.values()) and any(c["offsets_inch"] for c in EXPECTED.values())
    for code in ("G20", "G91", "G18", "G19", "G90.1", "G10 L2", "G10 L20", "G43", "G43.1", "G92", "G52", "G28",
                 "G53", "G83", "G85", "G93", "G95", "o1", "sub", "while", "repeat", " R-", " P2", "A"):
        assert code in joined, code
