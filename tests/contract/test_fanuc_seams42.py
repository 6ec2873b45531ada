"""Where last session's Fanuc merges meet (hunt42): G68/G51 around hunt41's statements
(:mod:`tests.contract.fanuc_seams42`) against the general path alone, the verdict with every route off, the
independent reference reader, and zones moved with the work offsets.

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
from tests.contract.fanuc_seams42 import fanuc_programs42, offsets_agree
from tests.contract.test_fanuc_seams41 import _SETTINGS
from tests.gcode.fanuc.helpers import mill

CI_EXAMPLES = 3
LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS42", "300"))
SHIFTS = st.tuples(*(st.integers(-50, 50) for _ in range(3)))


def check(data) -> None:
    face, dpi = data.draw(FACES), data.draw(st.sampled_from(("calculator", "increment")))
    shift = data.draw(SHIFTS)
    parts = data.draw(fanuc_programs42())
    event("lanes: " + lanes_agree(program(parts), mill(f'decimal_point_input = "{dpi}"')).split(" (")[0])
    event("verdict: " + verdicts_agree(program(parts), face, dpi))
    event("offsets: " + offsets_agree(program(parts, reads=False), shift, face, dpi))
    event("reference: " + reference_agrees(program(parts, reads=False), dpi).split(":")[0])


@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data())
def test_fanuc_seams42_agree_with_the_general_path(data):
    check(data)


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data())
def test_fanuc_seams42_long(data):
    check(data)
