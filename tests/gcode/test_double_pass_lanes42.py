"""The o-word lanes' speed-ups of oword42 (issue 36) agree with what they replace.

* The double pass's text screens (may the text write G41/G42, a canned cycle?) search "G" and "g" apart, a
  letter the regex engine scans for, instead of one ``[Gg]`` class tested at every character: they must answer
  as the class does on every text.
"""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.double_cycles import may_cycle
from nczones.gcode.linuxcnc.doubles import _may_compensate

#: the screens as they were, one class for the letter
_COMP = re.compile(r"[Gg][ \t]*0*4[12](?![0-9])")
_CYCLE = re.compile(r"[Gg][ \t]*0*(?:73|8[1-9])(?![0-9])")

_TEXT = st.text(alphabet="Gg 0123478912\t\nX.", max_size=40)


@settings(max_examples=400, deadline=None)
@given(_TEXT)
def test_the_screens_answer_as_the_class_did(text: str) -> None:
    assert _may_compensate(text) is (_COMP.search(text) is not None)
    assert may_cycle(text) is (_CYCLE.search(text) is not None)


def test_the_screens_see_either_case() -> None:
    assert _may_compensate("G1 X1\ng41 D1\n") and _may_compensate("G42.1 D2")
    assert may_cycle("g 083 q1") and may_cycle("X0\nG81 R1")
    assert not _may_compensate("G1 X41 Y42") and not may_cycle("G1 X81 Y73")
