"""The metamorphic suite has teeth: dependency propagation broken in one place is caught at CI size.

Each test breaks how the interpreter carries one kind of parameter source into the segments
(monkeypatch) and runs the same property as test_metamorphic.py, with the same number of examples as
its CI run, requiring a :class:`MetamorphicViolation`.  (The issue-18 acceptance: offsets, tool
lengths and the start position.)
"""

import pytest
from hypothesis import Phase, given, settings

from nczones.gcode.interpreter import Interpreter

from .metamorphic import MetamorphicViolation, range_cases
from .test_metamorphic import CI_EXAMPLES, ranges_property


def run_ranges_property():
    """The suite's own range property, its CI examples (same inner function: same derandomized draws)."""
    settings(max_examples=CI_EXAMPLES["ranges"], derandomize=True, database=None, deadline=None,
             phases=[Phase.generate], report_multiple_bugs=False)(given(range_cases())(ranges_property))()


def test_work_offsets_without_their_dependency_are_caught(monkeypatch):
    original = Interpreter.recompute_offsets

    def broken(self):
        original(self)
        if self.track:  # the G54..G59.3 sources never reach a coordinate
            self.dep_off = [{k: c for k, c in d.items() if not k.startswith("G5")} for d in self.dep_off]

    monkeypatch.setattr(Interpreter, "recompute_offsets", broken)
    with pytest.raises(MetamorphicViolation):
        run_ranges_property()


def test_tool_lengths_without_their_dependency_are_caught(monkeypatch):
    original = Interpreter._tool_length

    def broken(self, g, words):
        original(self, g, words)
        self.dep_tlo = {}  # H<n> reaches neither the tool axis nor the tip zones
        self.recompute_offsets()

    monkeypatch.setattr(Interpreter, "_tool_length", broken)
    with pytest.raises(MetamorphicViolation):
        run_ranges_property()


def test_the_start_position_without_its_dependency_is_caught(monkeypatch):
    original = Interpreter.__init__

    def broken(self, *args, **kwargs):
        original(self, *args, **kwargs)
        self.dep_pos = [{} for _ in range(self.naxes)]  # where the machine starts is taken as fixed

    monkeypatch.setattr(Interpreter, "__init__", broken)
    with pytest.raises(MetamorphicViolation):
        run_ranges_property()
