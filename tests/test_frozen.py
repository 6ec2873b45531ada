"""``nczones.frozen.builder`` makes instances equal to the constructor's, frozen from then on."""

from __future__ import annotations

import dataclasses
import pickle

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import SourceSpan
from nczones.frozen import builder
from nczones.gcode.blocks import Word
from nczones.gcode.parser import ParsedLine
from nczones.motion import Segment

values = st.one_of(st.none(), st.integers(), st.text(max_size=5), st.tuples(st.integers(), st.integers()))


@pytest.mark.parametrize("cls", [Segment, SourceSpan, Word, ParsedLine])
@settings(max_examples=50, deadline=None, derandomize=True, database=None)
@given(data=st.data())
def test_built_instances_equal_the_constructors(cls, data):
    names = [f.name for f in dataclasses.fields(cls)]
    args = data.draw(st.tuples(*[values] * len(names)))
    built = builder(cls)(*args)
    made = cls(*args)
    assert type(built) is cls
    assert built == made and repr(built) == repr(made)
    if all(isinstance(a, (int, str, tuple, type(None))) for a in args):
        assert hash(built) == hash(made)
    assert pickle.loads(pickle.dumps(built)) == made
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(built, names[0], 1)


def test_parameters_in_any_order_and_constants():
    make = builder(SourceSpan, ("text", "line"), file="p.ngc", column=1, end_column=None)
    assert make("G1", 3) == SourceSpan("p.ngc", 3, 1, None, "G1")


@dataclasses.dataclass(frozen=True, slots=True)
class _Base:
    a: int


@dataclasses.dataclass(frozen=True, slots=True)
class _Derived(_Base):
    b: int


def test_a_class_with_another_base_is_built_through_its_slots():
    built = builder(_Derived)(1, 2)
    assert type(built) is _Derived and built == _Derived(1, 2)
    with pytest.raises(dataclasses.FrozenInstanceError):
        built.a = 3


def test_every_field_must_be_given_once():
    with pytest.raises(ValueError, match="must name each field"):
        builder(SourceSpan, ("file", "line"))
    with pytest.raises(ValueError, match="must name each field"):
        builder(SourceSpan, ("file", "line", "column", "end_column", "text"), text="")
