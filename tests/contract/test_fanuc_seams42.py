"""Where last session's Fanuc merges meet (hunt42): G68/G51 around hunt41's statements
(:mod:`tests.contract.fanuc_seams42`) against the general path alone, the verdict with every route off, the
independent reference reader, zones moved with the work offsets (and margin 0.5 safe => safe), and a face at one
motion's end (one pulse either side) rather than at the extreme.

CI: 3 derandomized examples; ``-m long`` with ``NCZONES_SEAMS42`` examples (default 300).
"""

from __future__ import annotations

import os

import pytest
from hypothesis import event, given, settings
from hypothesis import strategies as st

from tests.contract.fanuc_seams41 import (
    FACES,
    lanes_agree,
    program,
    reference_agrees,
    verdicts_agree,
)
from tests.contract.fanuc_seams42 import fanuc_programs42, offsets_agree, verdicts_agree_at
from tests.contract.test_fanuc_seams41 import _SETTINGS
from tests.gcode.fanuc.helpers import mill

CI_EXAMPLES = 3
LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS42", "300"))
SHIFTS = st.tuples(*(st.integers(-50, 50) for _ in range(3)))


def check(data) -> None:
    face, dpi = data.draw(FACES), data.draw(st.sampled_from(("calculator", "increment")))
    shift, pick = data.draw(SHIFTS), data.draw(st.integers(0, 10**6))
    parts = data.draw(fanuc_programs42())
    event("lanes: " + lanes_agree(program(parts), mill(f'decimal_point_input = "{dpi}"')).split(" (")[0])
    event("verdict: " + verdicts_agree(program(parts), face, dpi))
    event("offsets: " + offsets_agree(program(parts, reads=False), shift, face, dpi))
    event("at a motion: " + verdicts_agree_at(program(parts), face, pick, dpi))
    event("reference: " + reference_agrees(program(parts, reads=False), dpi).split(":")[0])


def test_h1_the_reference_declines_a_cycle_under_a_rotation():
    """H1 (hunt42, the harness's): the reference reader read a hole under ``G68 ... R30.`` unrotated (its moves
    refuse all but quarter turns; its cycles did not ask) where nczones rotates it; it now declines."""
    text = ("O0001\nG17 G40 G80 G20 G90 G55 F300.\nG00 Z0.8\nG68 X-0.1216 Y30 R30.\nM03\n"
            "G84 X0.0138 Y0.0383 Z-1.781 R0.0403 P0 F247.\nG80\nG69\nM30\n")
    assert reference_agrees(text).startswith("skip"), text
    assert lanes_agree(text, mill()).startswith("complete")


@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data())
def test_fanuc_seams42_agree_with_the_general_path(data):
    check(data)


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data())
def test_fanuc_seams42_long(data):
    check(data)
