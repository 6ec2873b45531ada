"""Where last session's Fanuc transform changes meet (hunt43): transformed runs near quarter turns, with huge
offsets, G20/G91/M98/G65/macro lines inside (:mod:`tests.contract.fanuc_seams43`) against the general path
alone, the verdict with every route off, zones moved with the work offsets (margin 0.5 safe => safe), a face at
one motion's end, and the independent reference reader.

CI: 2 derandomized examples; ``-m long`` with ``NCZONES_SEAMS43`` examples (default 300).
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
from tests.contract.fanuc_seams42 import offsets_agree, verdicts_agree_at
from tests.contract.fanuc_seams43 import fanuc_programs43
from tests.contract.test_fanuc_seams41 import _SETTINGS
from tests.gcode.fanuc.helpers import mill

CI_EXAMPLES = 2
LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS43", "300"))
SHIFTS = st.tuples(*(st.integers(-50, 50) for _ in range(3)))


def check(data) -> None:
    face, dpi = data.draw(FACES), data.draw(st.sampled_from(("calculator", "increment")))
    shift, pick = data.draw(SHIFTS), data.draw(st.integers(0, 10**6))
    parts = data.draw(fanuc_programs43())
    event("lanes: " + lanes_agree(program(parts), mill(f'decimal_point_input = "{dpi}"')).split(" (")[0])
    event("verdict: " + verdicts_agree(program(parts), face, dpi))
    text = program(parts, reads=False)
    # a G10 L2 offset is written by the program: moving the machine file's offsets does not move it
    event("offsets: " + ("skip (G10)" if "G10" in text else offsets_agree(text, shift, face, dpi)))
    event("at a motion: " + verdicts_agree_at(program(parts), face, pick, dpi))
    event("reference: " + reference_agrees(program(parts, reads=False), dpi).split(":")[0])


@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data())
def test_fanuc_seams43_agree_with_the_general_path(data):
    check(data)


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data())
def test_fanuc_seams43_long(data):
    check(data)
