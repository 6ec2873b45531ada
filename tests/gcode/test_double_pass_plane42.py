"""plane42 (issue 36): the double pass's quicker text screens and arc code agree with what they replace."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.double_cycles import may_cycle

_ONE_SET = re.compile(r"[Gg][ \t]*0*(?:73|8[1-9])(?![0-9])")  # may_cycle's pattern before plane42


@settings(max_examples=200, deadline=None)
@given(st.lists(st.sampled_from(["G", "g", "X", " ", "\t", "0", "7", "3", "8", "1", "9", "5", "\n", ".", "#"]),
                max_size=30).map("".join))
def test_may_cycle_is_the_one_set_search(text: str) -> None:
    """Searching for ``G`` and ``g`` apart finds what the one ``[Gg]`` pattern finds."""
    assert may_cycle(text) == (_ONE_SET.search(text) is not None)


def test_may_cycle_either_case() -> None:
    assert may_cycle("X1\ng 0081 R2") and may_cycle("G73 Q1") and not may_cycle("G1 X81 g8 G810 G 7 3")


_DOUBLES = st.one_of(st.floats(min_value=0.0, max_value=1e300, allow_nan=False),
                     st.floats(min_value=0.0, max_value=2.0**-1000), st.sampled_from([0.0, 5e-324, 2.0**-1022]))


@settings(max_examples=200, deadline=None)
@given(_DOUBLES, _DOUBLES, _DOUBLES)
def test_one_nextafter_a_g91_step_bounds_the_step(e: float, d: float, x: float) -> None:
    """``_Pass._straight_ends``'s G91 step with one ``nextafter`` (plane42; its docstring's argument):
    ``e' >= e + (|d| + |x|) 2**-53 + 2**-1075`` exactly, subnormal terms included."""
    import math
    from fractions import Fraction

    EPS2 = 2.0**-52  # (doubles._EPS2)

    step = math.nextafter(e + (abs(d) + abs(x)) * EPS2, math.inf)
    assert Fraction(step) >= Fraction(e) + (Fraction(abs(d)) + Fraction(abs(x))) / 2**53 + Fraction(1, 2**1075)
