"""Exact numbers: decimal text and TOML numbers become exact rationals, never floats."""

from __future__ import annotations

import decimal
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from nczones.errors import InvalidArgument, MachineFileError
from nczones.exact import decimal_places, exact, format_decimal, parse_decimal
from nczones.machine import parse_machine
from tests.zones.strategies import FAST

BASE = """
[machine]
axes = ["X", "Y"]
pulse = {pulse}
[machine.rapid]
X = "12000"
Y = "8000"
[machine.reference]
X = "100"
Y = "100"
[[zones]]
name = "wheel area"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = 0
regions = [{{ upto = {upto}, max = "300" }}]
"""


def test_point_one_plus_point_two_is_point_three():
    assert parse_decimal("0.1") + parse_decimal("0.2") == parse_decimal("0.3")
    assert exact("0.1") + exact("0.2") == exact("0.3")


@pytest.mark.parametrize("written", ["500.1", '"500.1"', "500.10", '"500.100"', '" 500.1 "'])
def test_toml_number_and_text_load_as_the_same_fraction(written):
    m = parse_machine(BASE.format(upto=written, pulse='"0.001"'))
    assert m.zones[0].regions[0].upto == Fraction(5001, 10)


def test_toml_float_forms_are_exact():
    m = parse_machine(BASE.format(upto="5.001e2", pulse="1e-3"))
    assert m.zones[0].regions[0].upto == Fraction(5001, 10)
    assert m.axes[0].pulse == Fraction(1, 1000)
    m = parse_machine(BASE.format(upto="500", pulse="0.001"))
    assert m.zones[0].regions[0].upto == 500 and m.axes[1].pulse == Fraction(1, 1000)


@pytest.mark.parametrize("upto", ["1e999999999", "1e-999999999", "-1e400"])
def test_huge_exponents_are_refused_quickly(upto):
    with pytest.raises(MachineFileError) as info:
        parse_machine(BASE.format(upto=upto, pulse='"0.001"'))
    assert info.value.code == "ZN105"


@pytest.mark.parametrize("value", [0.1, 1.0, float("nan"), float("inf")])
def test_a_float_is_refused_naming_the_value(value):
    with pytest.raises(InvalidArgument) as info:
        exact(value)
    text = str(info.value)
    assert repr(value) in text and "float" in text
    assert "decimal text" in text  # and it says how to pass it exactly


@pytest.mark.parametrize("value", [True, None, [1], decimal.Decimal("NaN"), decimal.Decimal("-Infinity")])
def test_other_non_numbers_are_refused(value):
    with pytest.raises(InvalidArgument):
        exact(value)


@pytest.mark.parametrize("text", ["1e3", "inf", "nan", "", "1,5", "--1", "0x10", "1_000", "."])
def test_parse_decimal_refuses_non_decimals(text):
    with pytest.raises(InvalidArgument) as info:
        parse_decimal(text)
    assert repr(text) in str(info.value)


@pytest.mark.parametrize("text, value", [("5.", 5), (".5", Fraction(1, 2)), ("-0.0", 0), ("+12", 12)])
def test_parse_decimal_forms(text, value):
    assert parse_decimal(text) == value


@FAST
@given(st.integers(-10**12, 10**12), st.integers(0, 9))
def test_format_then_parse_is_the_identity_on_decimals(n, places):
    q = Fraction(n, 10**places)
    text = format_decimal(q)
    assert parse_decimal(text) == q
    assert decimal_places(q) <= places
    assert exact(decimal.Decimal(text)) == q


@FAST
@given(st.fractions(max_denominator=10**6))
def test_format_decimal_marks_rounding(q):
    text = format_decimal(q, places=6)
    assert text.endswith("…") == (decimal_places(q) is None or decimal_places(q) > 6)
    assert abs(parse_decimal(text.rstrip("…")) - q) <= Fraction(1, 2 * 10**6)
