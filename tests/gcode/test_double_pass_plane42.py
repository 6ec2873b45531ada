"""plane42 (issue 36): the double pass's quicker text screens and arc code agree with what they replace."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.double_cycles import may_cycle

_ONE_SET = re.compile(r"[Gg][ \t]*0*(?:73|8[1-9])(?![0-9])")  # may_cycle's pattern before plane42


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(["G", "g", "X", " ", "\t", "0", "7", "3", "8", "1", "9", "5", "\n", ".", "#"]),
                max_size=30).map("".join))
def test_may_cycle_is_the_one_set_search(text: str) -> None:
    """Searching for ``G`` and ``g`` apart finds what the one ``[Gg]`` pattern finds."""
    assert may_cycle(text) == (_ONE_SET.search(text) is not None)


def test_may_cycle_either_case() -> None:
    assert may_cycle("X1\ng 0081 R2") and may_cycle("G73 Q1") and not may_cycle("G1 X81 g8 G810 G 7 3")
