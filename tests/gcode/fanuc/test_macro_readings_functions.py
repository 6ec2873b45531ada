"""POW's exponent, ASIN/ACOS's -1..1, the angle functions' shadows and a literal ``#[...]`` under the readings rule
(GC398; nczones/gcode/fanuc/expr.py: ``_pow_domain``, ``_arc_domain``, ``_angle``, ``literal_number``).

The readings of a macro value are the double as it is, its 15-significant-digit decimal and the exact decimal it
stands for (the shadow, when kept); test_macro_readings.py holds FIX/FUP/ROUND/MOD/``#[...]``/relations to them.
Here the same rule for the decisions readings38 left on the double:

* ``POW[a,b]`` with a negative base alarms for a non-integer exponent and computes for an integer one (its parity
  the sign): ``POW[-2, 0.3 / 0.1]`` is the alarm for the double 2.9999999999999996 and -8 for its 15 digits;
* ``ASIN``/``ACOS`` alarm outside -1..1: ``ACOS[#1 / 3]`` with ``#1 = 0.1 * 3 * 10`` is the double
  1.0000000000000002 (the alarm) and its 15 digits 1;
* ``#[literal]``: ``#[125.49999999999999999]`` is #126 for the double 125.5 and #125 for the decimal written.

The expected readings are computed here independently (``Decimal`` to 15 digits, ``Fraction``), never through
nczones's own; where the reference reader (tests/oracles/fanuc_ref.py) models the functions (``#[...]``, SIN) the
motion is compared with it.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode.expr import EvalError
from nczones.gcode.fanuc.expr import (
    FanucVariables,
    ReadingsSplit,
    compile_tree,
    evaluate_tree,
    literal_number,
)
from nczones.gcode.fanuc.parser import BIN, FN, FN2, NUM, VAR
from tests.oracles.fanuc_ref import reference_motion

from .ref_differential import nczones_motion, normalise, ref_machine
from .test_macro_readings import _HEAD, _outcome, _readings, _run, _ulps, _values

# -- the interpreter: unknown at the line where they split, the value where they agree ---------------------------

#: name -> (body at the split, the GC398 line, a body where the readings agree, the X it moves to there)
SPLITS = {
    "POW": ("#1 = POW[-2, 0.3 / 0.1]\nG01 X#1\n", 4, "#1 = POW[-2, 1 + 2]\nG01 X[#1 + 10]\n", "2"),
    "POW exact": ("#1 = POW[-1, 3.0000000000000000001]\nG01 X#1\n", 4, "#1 = POW[-1, 3.0]\nG01 X#1\n", "-1"),
    "POW parity": ("#1 = POW[-1, 1000000000000001]\nG01 X#1\n", 4, "#1 = POW[-1, 100000000000001]\nG01 X#1\n",
                   "-1"),
    "ACOS": ("#1 = 0.1 * 3 * 10\n#2 = ACOS[#1 / 3]\nG01 X#2\n", 5,
             "#1 = 0.1 * 3 * 10\n#2 = ACOS[#1 / 6]\nG01 X[#2 / 2]\n", "30"),
    "ASIN": ("#1 = ASIN[1.0000000000000000001]\nG01 X[#1 / 10]\n", 4,
             "#1 = ASIN[1.0]\nG01 X[#1 / 10]\n", "9"),
    "#[literal]": ("#125 = 1.\n#126 = 2.\n#1 = #[125.49999999999999999]\nG01 X#1\n", 6,
                   "#125 = 1.\n#126 = 2.\n#1 = #[125.4999999999]\nG01 X#1\n", "1"),
    "#[literal] =": ("#[2.49999999999999999] = 5.\nG01 X#2\n", 4, "#[2.4999999999] = 5.\nG01 X#2\n", "5"),
    "#[literal] + 1": ("#2 = 1.\n#3 = 4.\n#1 = #[2.49999999999999999] + 1\nG01 X#1\n", 6,
                       "#2 = 1.\n#3 = 4.\n#1 = #[2.50000000000000001] + 1\nG01 X#1\n", "5"),
}


@pytest.mark.parametrize("name", sorted(SPLITS))
def test_a_split_is_unknown_at_its_line_and_where_they_agree_the_value_stands(name):
    split, line, agree, x = SPLITS[name]
    r, reasons = _run(split)
    assert r.verdict.label == "unknown" and reasons == [("GC398", line)], reasons
    assert "give different results" in r.reasons[0].message
    r, reasons = _run(agree + "G01 X0\n")
    assert r.verdict.label == "safe" and not reasons, reasons
    _, segs = nczones_motion(_HEAD + agree + "M30\n", "calculator", False)
    assert normalise(segs)[-1][1][0] - normalise(segs)[0][1][0] == Fraction(x), normalise(segs)


@pytest.mark.parametrize("text", ["#1 = POW[-2, 2.9999999999999]\n", "#1 = POW[0, -0.5 * 3]\n",
                                  "#1 = ACOS[1.0000000000001]\n", "#1 = ASIN[-1.0000000000001]\n"])
def test_where_every_reading_alarms_the_alarm_stands(text):
    with pytest.raises(GcodeError, match="GC312"):
        _run(text)


def test_the_reason_names_each_reading_and_what_it_does():
    with pytest.raises(ReadingsSplit) as e:
        evaluate_tree((FN2, "pow", (NUM, -2.0, Fraction(-2)), (BIN, "/", (NUM, 0.3, Fraction(3, 10)),
                                                                  (NUM, 0.1, Fraction(1, 10)))), FanucVariables())
    assert e.value.code == "GC398"
    assert "the double as it is, 2.999999999999999555910790150..., with a negative base gives an alarm" in e.value.reason
    assert "its 15-digit decimal, 3, with a negative base gives a negative power" in e.value.reason


@pytest.mark.parametrize("name", ["#[literal]", "#[literal] + 1"])
def test_where_a_literal_index_agrees_the_reference_reader_moves_alike(name):
    _split, _line, agree, _x = SPLITS[name]
    text = _HEAD + agree + "M30\n"
    _, segs = nczones_motion(text, "calculator", False)
    assert normalise(segs) == normalise(reference_motion(text, ref_machine("calculator")))


# -- every given result is every reading's ----------------------------------------------------------------------


def _pow_case(base: Fraction, r: Fraction) -> str:
    """What POW does, by the definition: an alarm, or the sign of the power."""
    if base < 0:
        return "alarm" if r.denominator != 1 else ("-" if r.numerator % 2 else "+")
    return "alarm" if base == 0 and r < 0 else "+"


@settings(max_examples=300, deadline=None)
@given(_values(), st.sampled_from([-2.0, -1.0, -0.5, 0.0, 3.0]), st.booleans())
def test_pow_gives_a_result_only_every_reading_gives(y, base, computed):
    """The exponent a number node, or computed (``y + 0``: its shadow found again near a split)."""
    exponent = (BIN, "+", (NUM, *y), (NUM, 0.0, Fraction(0))) if computed else (NUM, *y)
    kind, got = _outcome(lambda: _alarm_or(lambda: evaluate_tree(
        (FN2, "pow", (NUM, base, Fraction(base)), exponent), FanucVariables())))
    cases = {_pow_case(Fraction(base), r) for r in _readings(*y)}
    if kind == "split":
        assert len(cases) > 1, (y, base, got.reason)
        return
    assert len(cases) == 1, (y, base, got)
    case = cases.pop()
    if case == "alarm":
        assert got == "alarm", (y, base, got)
        return
    try:
        power = math.pow(base, y[0])
    except OverflowError:  # beyond the doubles in every reading: the alarm for the overflow
        assert got == "alarm", (y, base, got)
        return
    sign = math.copysign(1.0, got[0])  # an underflow keeps the sign: -0.0
    assert got[0] == power and sign == math.copysign(1.0, power) and (sign < 0) == (case == "-"), (y, base, got)


def test_a_zero_base_reads_its_shadow():
    """-10**-400 underflows to the double -0.0: its exact reading is negative (the alarm for POW[., 0.5])."""
    tiny = (NUM, -0.0, Fraction(-1, 10**400))
    with pytest.raises(ReadingsSplit, match="with a negative base gives an alarm"):
        evaluate_tree((FN2, "pow", (BIN, "*", tiny, (NUM, 1.0, Fraction(1))), (NUM, 0.5, Fraction(1, 2))),
                      FanucVariables())
    assert evaluate_tree((FN2, "pow", tiny, (NUM, 2.0, Fraction(2))), FanucVariables())[0] == 0.0


def _alarm_or(fn):
    try:
        return fn()
    except EvalError as e:
        assert e.code == "GC312", e
        return "alarm"


#: arguments at -1 and 1 and a few ulps around them, with a shadow or without
_near_one = st.builds(lambda sign, k, q: (_ulps(sign, k), (Fraction(int(sign)) + Fraction(q, 10**20))
                                          if q is not None and float(Fraction(int(sign)) + Fraction(q, 10**20))
                                          == _ulps(sign, k) else None),
                      st.sampled_from([-1.0, 1.0]), st.integers(-3, 3), st.one_of(st.none(), st.integers(-9, 9)))


@settings(max_examples=300, deadline=None)
@given(st.one_of(_near_one, _values()), st.sampled_from(["asin", "acos"]), st.booleans())
def test_asin_acos_alarm_only_where_every_reading_is_outside(x, name, computed):
    arg = (BIN, "*", (NUM, *x), (NUM, 1.0, Fraction(1))) if computed else (NUM, *x)
    kind, got = _outcome(lambda: _alarm_or(lambda: evaluate_tree((FN, name, arg), FanucVariables())))
    inside = {-1 <= r <= 1 for r in _readings(*x)}
    if kind == "split":
        assert len(inside) > 1, (x, got.reason)
    elif got == "alarm":
        assert inside == {False}, x
    else:
        assert inside == {True}, x
        fn = math.asin if name == "asin" else math.acos
        degrees = fn(x[0]) * 180.0 / math.pi
        assert got[0] == (degrees + 360.0 if degrees < 0.0 else degrees), (x, got)


@settings(max_examples=200, deadline=None)
@given(st.integers(100, 190), st.sampled_from(["49999999999999999", "5", "50000000000000001", "4999999999",
                                               "49999999999999", "500000000000001"]))
def test_a_literal_variable_number_is_every_reading_s(whole, digits):
    q = Fraction(f"{whole}.{digits}")
    d = float(q)
    numbers = {math.floor(r + Fraction(1, 2)) for r in _readings(d, q)}
    got = literal_number((NUM, d, q))
    v = FanucVariables({n: Fraction(n) for n in range(100, 200)})
    kind, value = _outcome(lambda: evaluate_tree((VAR, (NUM, d, q)), v))
    if len(numbers) == 1:
        assert got == numbers.pop() == value[0], (q, got, value)
    else:
        assert got is None and kind == "split", (q, got, value)


# -- the angle functions: what they read, and why their shadows are sound -------------------------------------

_INTEGER_OF = {"fix": math.trunc, "round": lambda r: int(math.copysign(math.floor(abs(r) + Fraction(1, 2)), r))}


@settings(max_examples=300, deadline=None)
@given(st.one_of(_near_one, _values()), st.sampled_from(["atan", "asin", "acos"]), st.sampled_from(["fix", "round"]),
       st.integers(-3, 3))
def test_an_angle_s_shadow_is_its_double_and_can_only_part_readings(x, name, kind, k):
    """ATAN/ASIN/ACOS keep a shadow only where the double is an integer, and it is that double: FIX/ROUND of the
    result give what its double's readings give; a comparison with a value that keeps a shadow adds the pair of
    exact values, which can part a result (GC398) but never give another one than the doubles' readings."""
    arg = (NUM, *x)
    kind_value, angle = _outcome(lambda: _alarm_or(lambda: evaluate_tree((FN, name, arg), FanucVariables())))
    if kind_value != "value" or angle == "alarm":
        return
    d, q = angle
    assert q is None or (q.denominator == 1 and q == Fraction(d)), angle
    # FIX/ROUND of the angle: every reading of every double the control's library can give (libm40: the radians
    # CPython gives or a neighbour, none at ASIN/ATAN of 0 and ACOS of 1) gives the result, the shadow or not
    ints = {_INTEGER_OF[kind](r) for c in _angle_doubles(name, x[0]) for r in _readings(c, None)}
    for value in (angle, (d, None)):
        got = _outcome(lambda v=value: evaluate_tree((FN, kind, (NUM, *v)), FanucVariables()))
        if len(ints) > 1:
            assert got[0] in ("split", "unknown"), (angle, got)
        else:
            assert got[0] == "value" and got[1][0] == next(iter(ints)), (angle, got)
    # a comparison with an integer whose shadow differs from it by a ulp's fraction
    other = (float(round(d)) if math.isfinite(d) else 0.0, Fraction(round(d)) + Fraction(k, 10**20))
    if float(other[1]) != other[0]:
        return
    with_shadow = _outcome(lambda: compile_tree((BIN, "le", (NUM, *angle), (NUM, *other)), FanucVariables(),
                                                exact=False)())
    without = _outcome(lambda: compile_tree((BIN, "le", (NUM, d, None), (NUM, *other)), FanucVariables(),
                                            exact=False)())
    if with_shadow[0] == "value":
        assert without == with_shadow, (angle, other)
    if without[0] == "split":
        assert with_shadow[0] == "split", (angle, other)


def _angle_doubles(name: str, x: float) -> list[float]:
    """The degrees (270..90 or 0..180) of every radian result a control's library can give for ATAN/ASIN/ACOS
    of ``x``: CPython's and its two neighbours, only CPython's where the true value is 0 (computed here, not
    through nczones)."""
    r = {"atan": math.atan, "asin": math.asin, "acos": math.acos}[name](x)
    exact = x == (1.0 if name == "acos" else 0.0)
    radians = [r] if exact else [r, math.nextafter(r, -math.inf), math.nextafter(r, math.inf)]
    return [deg + 360.0 if deg < 0.0 else deg for deg in (t * 180.0 / math.pi for t in radians)]


def test_an_angle_of_an_argument_whose_readings_differ_is_the_double_s():
    """SIN/COS/ATAN read their argument's double (the control computes them in doubles, as + - * /): 30.000000000
    000004 (0.1 * 3 * 100; its 15 digits 30) gives the sine of the double, as the reference reader does; its
    readings are taken where the result becomes an address (GC399 here: 2.001 * SIN[30.] is at half an increment
    of the double and its 15 digits)."""
    text = _HEAD + "#1 = 0.1 * 3 * 100\nG01 X[1000 * SIN[#1]] Y[1000 * COS[#1]]\nM30\n"
    _, segs = nczones_motion(text, "calculator", False)
    assert normalise(segs) == normalise(reference_motion(text, ref_machine("calculator")))
    v = FanucVariables()
    v.write(1, (0.1 * 3 * 100, None))
    sine = evaluate_tree((FN, "sin", (VAR, (NUM, 1.0, Fraction(1)))), v)
    assert sine == (math.sin(0.1 * 3 * 100 * math.pi / 180.0), None) and sine != (math.sin(math.pi / 6), None)
    r, reasons = _run("#1 = 0.1 * 3 * 100\nG01 X[2.001 * SIN[#1]]\n")
    assert r.verdict.label == "unknown" and reasons == [("GC399", 5)], reasons
