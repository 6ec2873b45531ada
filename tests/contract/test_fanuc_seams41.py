"""Where the Fanuc lanes' newest features meet (hunt41): generated programs (:mod:`tests.contract.fanuc_seams41`)
against the general path alone, the verdict with every route off, and the independent reference reader.

Findings (``/work/brief/hunt41-findings.md``), each a test below that failed before its fix:

* F1: a vectorized run (64 plain lines and more) with an ``M`` word alone on a line lost it: ``#4113`` read the M
  before the run, so a move by it was proved where the control does not go (a wrong ``safe``).

CI: 3 derandomized examples per test; ``-m long`` with ``NCZONES_SEAMS41`` examples (default 300).
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, Phase, event, given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.prover import verify_text
from tests.contract.fanuc_seams41 import (
    FACES,
    fanuc_programs,
    lanes_agree,
    program,
    reference_agrees,
    verdicts_agree,
)
from tests.gcode.fanuc.helpers import mill

CI_EXAMPLES = 3
LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS41", "300"))
_SETTINGS = dict(deadline=None, suppress_health_check=list(HealthCheck),
                 phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink])
_WALL = '\n[[zones]]\nname = "box"\nkind = "box"\nmin = {{ X = "-10", Y = "-10", Z = "-300" }}\n' \
        'max = {{ X = "{x}", Y = "90", Z = "0" }}\n'


# ---------------------------------------------------------------------------------------------- findings
@pytest.mark.parametrize("lines", [70, 600])
@pytest.mark.parametrize("fast", [True, False])
def test_f1_an_m_alone_in_a_vectorized_run_is_the_last_m(lines, fast):
    """F1: ``M04`` alone on a line of a run the vectorized fast path takes (``fast``), then ``#4113`` into X: 4
    (machine X 104.5 with G54's 100), as on the general path; ``verify`` (600 lines: the fast path's size) finds it
    past a wall at 103 and proves it inside one at 105."""
    body = "".join(f"G01 X{k % 3}. Y{k % 5}.\n" for k in range(lines))
    text = f"O0001\nG17 G40 G80 G21 G90 G54 F300.\n{body}M04\nG01 X1.\n#7 = #4113\nG01 X[#7 + 0.5] Y1. F100.\nM30\n"
    run = interpret_text(text, mill(), file="t.nc", fast=fast)
    assert list(run.segments())[-1].end[0] == Fraction(209, 2)
    if lines >= 512 and fast:
        assert verify_text(text, mill(tables=_WALL.format(x=103)), file="t.nc").verdict.label == "unsafe"
        assert verify_text(text, mill(tables=_WALL.format(x=105)), file="t.nc").verdict.label == "safe"


# ---------------------------------------------------------------------------------------------- the hunt
def _check(data) -> None:
    face, dpi = data.draw(FACES), data.draw(st.sampled_from(("calculator", "increment")))
    parts = data.draw(fanuc_programs())
    event("lanes: " + lanes_agree(program(parts), mill(f'decimal_point_input = "{dpi}"')).split(" (")[0])
    event("verdict: " + verdicts_agree(program(parts), face, dpi))
    event("reference: " + reference_agrees(program(parts, reads=False), dpi).split(":")[0])


@settings(max_examples=CI_EXAMPLES, derandomize=True, **_SETTINGS)
@given(st.data())
def test_fanuc_seams_agree_with_the_general_path(data):
    _check(data)


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data())
def test_fanuc_seams_long(data):
    _check(data)
