"""The path control mode at every feed, held to rs274's log, for blocks that mix G20/G21, G61/G61.1/G64 P Q,
M70/M71/M72, a motion and an M73 subroutine (hunt36).

The motion differentials (``tests/tools/rs274_diff.py``) compare where the machine goes, not the mode it blends
in, so a block's order of execution was never held for the mode: ``G20 G64 P0.04`` had P read in the units
before the block (a wrong ``safe``), and ``M72 G1 X100 Y0`` moved where rs274 drops the motion (a wrong
``safe``); both are fixed (tests/prover/test_blend_modal_restore.py).  This hunt generates such blocks in any
order and requires nczones's mode (blend, tolerance in mm) at each ``STRAIGHT_FEED`` to equal rs274's
(``USE_LENGTH_UNITS`` and ``SET_MOTION_CONTROL_MODE`` read from its log), or nczones to decline the program
(``unknown``: M72 beside other codes), or both to refuse it.  CI: a few examples; ``-m long``:
``MODE_EXAMPLES["long"]`` (counts in specs/contract.md "Where features meet").
"""

from __future__ import annotations

import random
import shutil
from unittest import mock

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from tests.prover.test_blending import machine

MODE_EXAMPLES = {"ci": 6, "long": 2_000}
OUTCOMES: dict[str, int] = {}

pytestmark = pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")

_MODES = ["G61", "G61.1", "G64", "G64 P0.01", "G64 P0.5", "G64 P1", "G64 P0", "G64 P0.01 Q0.002", "G64 P0.5 Q0.1",
          "G64 P0.5 Q0", "G64 Q0.01", "G64 Q0.2"]
_SUBS = ["M73\nG61\n", "M73\nG20 G64 P0.01\n", "G64 P0.3\n", "M73\nG21 G61.1\n", "M73\nG64 P0.02 G20\nG21\n"]


def program(rnd: random.Random) -> str:
    """Two to eight blocks of units, a mode, M70/M71/M72 and a feed in a shuffled order, a feed after each, and
    at times a call of an o-word subroutine that changes the mode (with M73 or without)."""
    lines, x, call = [], 0, False
    for _ in range(rnd.randint(2, 8)):
        parts = []
        if rnd.random() < 0.4:
            parts.append(rnd.choice(["G20", "G21"]))
        if rnd.random() < 0.6:
            parts.append(rnd.choice(_MODES))
        if rnd.random() < 0.3:
            parts.append(rnd.choice(["M70", "M71", "M72"]))
        rnd.shuffle(parts)
        if rnd.random() < 0.5:
            x += 1
            parts.append(f"G1 X{x} F100")
        if parts:
            lines.append(" ".join(parts))
        if rnd.random() < 0.15:
            lines.append("o100 call")
            call = True
        x += 1
        lines.append(f"G1 X{x} F100")
    head = "o100 sub\n" + rnd.choice(_SUBS) + "o100 endsub\n" if call else ""
    return head + "G21\n" + "\n".join(lines) + "\nG21\n"


def _examples() -> int:
    return MODE_EXAMPLES["long" if settings.default.max_examples > 100 else "ci"]


def _count(key: str) -> None:
    OUTCOMES[key] = OUTCOMES.get(key, 0) + 1


def test_modes_of_mixed_blocks_are_rs274s(tmp_path_factory):
    from tests.prover.test_blend_modal_restore import _nczones_modes, _rs274_modes

    @settings(max_examples=_examples(), deadline=None)
    @given(st.randoms(use_true_random=False))
    def run(rnd):
        text = program(rnd)
        try:
            interp = interpret_text(text, machine())
            list(interp.segments())
            declined = bool(interp.unsupported)
            ours = None if declined else _nczones_modes(text)
        except GcodeError:
            ours, declined = "error", False
        try:
            theirs = _rs274_modes(text, tmp_path_factory.mktemp("rs274"))
        except AssertionError:  # rs274 refused the program
            theirs = "error"
        if declined:
            _count("nczones unknown")
            return
        _count("both refused" if ours == theirs == "error" else "equal" if ours == theirs else "different")
        assert ours == theirs, text

    run()


@pytest.mark.long
def test_mode_hunt_long(tmp_path_factory):
    OUTCOMES.clear()
    with mock.patch.dict(MODE_EXAMPLES, {"ci": MODE_EXAMPLES["long"]}):
        test_modes_of_mixed_blocks_are_rs274s(tmp_path_factory)
    print(f"mode hunt: {sorted(OUTCOMES.items())}")
