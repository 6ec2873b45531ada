"""FIX, FUP, ROUND, MOD, AND/OR/XOR, ``#[...]`` and the relational operators when the readings of a macro double
split (GC398, nczones/gcode/fanuc/expr.py: ``integer_of``, ``_related``, ``_agreed_binary``).

A Fanuc macro value is a double; a control could read it as the double it is, as its 15-significant-digit
decimal ([15i] "Custom macro variables are decimal numbers with a precision of 15 digits") or as the exact
decimal it stands for (nczones's shadow).  ``FIX[0.3 / 0.1]`` is 2 for the double (2.9999999999999996) and 3 for
its 15 digits: a loop count, a branch or a variable number that differs from the control's changes the whole
motion, so where the readings give different results the line is ``unknown`` (GC398), and where they agree the
result stands.  The readings here are computed independently (``Decimal`` rounded to 15 digits, ``Fraction``),
never through nczones's own.
"""

from __future__ import annotations

import math
import operator
from decimal import ROUND_HALF_EVEN, Context, Decimal
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.fanuc.expr import FanucVariables, ReadingsSplit, compile_tree, evaluate_tree
from nczones.gcode.fanuc.parser import BIN, FN, NUM, VAR
from nczones.machine import parse_machine
from tests.gcode.fanuc.helpers import blocks
from tests.machines import machine_text

_FIFTEEN = Context(prec=15, rounding=ROUND_HALF_EVEN)


def _readings(d: float, q: Fraction | None) -> list[Fraction]:
    """The double's exact value, its 15-digit decimal, the shadow when kept (independently of nczones)."""
    out = [Fraction(d), Fraction(_FIFTEEN.create_decimal(Decimal(d)))]
    return out + ([q] if q is not None else [])


def _trunc(r: Fraction) -> int:
    return math.trunc(r)


def _up(r: Fraction) -> int:
    return math.ceil(r) if r >= 0 else math.floor(r)


def _nearest(r: Fraction) -> int:
    n = math.floor(abs(r) + Fraction(1, 2))
    return n if r >= 0 else -n


_OF = {"fix": _trunc, "fup": _up, "round": _nearest}


# -- the interpreter: unknown at the line where they split, the result where they agree -------------------------

_MACHINE = machine_text("fanuc_finding_mill", set={"offsets.G54": {"X": "50", "Y": "0", "Z": "0"}})
_HEAD = "O1000\nG21 G90 G54 G17 G40 G80 G94 F100.\nG00 X0 Y50. Z100.\n"


def _run(body: str):
    from nczones.prover import verify_text

    r = verify_text(_HEAD + body + "M30\n", parse_machine(_MACHINE, "m.toml"), file="t.nc")
    return r, [(x.code, x.span.line if x.span else None) for x in r.reasons]


#: name -> (body at the split, the GC398 line, the body just off it, the X it moves to there)
SPLITS = {
    "FIX": ("#1 = FIX[0.3 / 0.1]\nG01 X#1\n", 4, "#1 = FIX[2.9999999999999]\nG01 X#1\n", "2"),
    "FUP": ("#1 = FUP[0.1 * 3 * 10]\nG01 X#1\n", 4, "#1 = FUP[3.0000000000001]\nG01 X#1\n", "4"),
    "ROUND": ("#1 = ROUND[1.5 * 1.017 * 1000] / 1000\nG01 X#1\n", 4,
              "#1 = ROUND[1525.4999999999] / 1000\nG01 X#1\n", "1.525"),
    "MOD": ("#1 = [1.5 * 1.017 * 1000] MOD 7\nG01 X#1\n", 4, "#1 = [1525.4999999999] MOD 7\nG01 X#1\n", "6"),
    "AND": ("#1 = [0.3 / 0.1] AND 1\nG01 X#1\n", 4, "#1 = [2.9999999999999] AND 1\nG01 X#1\n", "0"),
    "#[...]": ("#125 = 1.\n#126 = 2.\n#1 = #[1.5 * 1.017 * 1000 - 1400]\nG01 X#1\n", 6,
               "#125 = 1.\n#126 = 2.\n#1 = #[125.4999999999 * 1]\nG01 X#1\n", "1"),
    "EQ": ("IF [[0.1 * 3] EQ 0.3] GOTO 5\nG01 X1.\nN5 G01 X2.\n", 4,
           "IF [[0.1 * 3] EQ 0.3000000000001] GOTO 5\nG01 X1.\nN5 G01 X2.\n", "2"),
    "WHILE": ("#1 = 0\nWHILE [#1 LT 1] DO1\n#1 = #1 + 0.1\nEND1\nG01 X#1\n", 5,
              "#1 = 0\nWHILE [#1 LT 1.05] DO1\n#1 = #1 + 0.1\nEND1\nG01 X[ROUND[#1 * 10]]\n", "11"),
}


@pytest.mark.parametrize("name", sorted(SPLITS))
def test_a_split_is_unknown_at_its_line_and_just_off_it_the_result_stands(name):
    split, line, off, x = SPLITS[name]
    r, reasons = _run(split)
    assert r.verdict.label == "unknown" and reasons == [("GC398", line)], reasons
    assert "give" in r.reasons[0].message or "compare differently" in r.reasons[0].message
    r, reasons = _run(off + "G01 X0\n")
    assert r.verdict.label == "safe" and not reasons, reasons
    got, _v, _runner = blocks(_HEAD + off + "M30\n")
    xs = [value for words in got for letter, value in words if letter == "X"]
    assert xs[-1] == Fraction(x), xs


def test_the_reason_names_each_reading_and_its_result():
    with pytest.raises(ReadingsSplit) as e:
        evaluate_tree((FN, "fix", (BIN, "/", (NUM, 0.3, Fraction(3, 10)), (NUM, 0.1, Fraction(1, 10)))),
                      FanucVariables())
    assert e.value.code == "GC398"
    assert "the double as it is, 2.999999999999999555910790150..., gives 2;" in e.value.reason
    assert "its 15-digit decimal, 3, gives 3" in e.value.reason
    # 3, the exact quotient, is not the double nearest it: no shadow is kept, and no exact reading named
    assert "exact value" not in e.value.reason


def test_the_exact_reading_is_found_again_for_an_operand_computed_as_a_double():
    """``FIX[#1 * 3]`` with ``#1`` an 18-digit decimal: the double is 1.0, the exact product 0.999...9: the
    operand of FIX is computed without its shadow, and computed again with it near the split."""
    v = FanucVariables()
    v.write(1, (float(Fraction("0.333333333333333333")), Fraction("0.333333333333333333")))
    tree = (FN, "fix", (BIN, "*", (VAR, (NUM, 1.0, Fraction(1))), (NUM, 3.0, Fraction(3))))
    with pytest.raises(ReadingsSplit, match="the exact value it stands for, 0.999999999999999999, gives 0"):
        compile_tree(tree, v, exact=False)()
    cond = (BIN, "eq", (BIN, "*", (VAR, (NUM, 1.0, Fraction(1))), (NUM, 3.0, Fraction(3))), (NUM, 1.0, Fraction(1)))
    with pytest.raises(ReadingsSplit, match="the exact values they stand for"):
        compile_tree(cond, v, exact=False)()


# -- every given result is every reading's ----------------------------------------------------------------------

#: doubles near where the readings part: integers and halves and a few ulps around them, decimal products
_near = st.builds(lambda n, half, k: _ulps(n + half, k), st.integers(-3000, 3000), st.sampled_from([0.0, 0.5]),
                  st.integers(-4, 4))
_factors = st.builds(lambda a, b: (Fraction(a, 1000), Fraction(b, 100)), st.integers(-5000, 5000),
                     st.integers(-500, 500))


def _ulps(x: float, k: int) -> float:
    for _ in range(abs(k)):
        x = math.nextafter(x, math.inf if k > 0 else -math.inf)
    return x


@st.composite
def _values(draw) -> tuple:
    """``(double, shadow)``: a double near an integer or a half without a shadow, or the product of two
    decimals computed in doubles, with the exact product as its shadow when it rounds to it (as nczones keeps
    one), or the double nearest the product a few ulps away."""
    if draw(st.booleans()):
        return (draw(_near), None)
    a, b = draw(_factors)
    q = a * b
    d = _ulps(float(a) * float(b), draw(st.sampled_from([0, 0, 0, -1, 1, -2, 2])))
    return (d, q if float(q) == d else None)


def _outcome(fn):
    try:
        return "value", fn()
    except ReadingsSplit as e:
        return "split", e


@settings(max_examples=300, deadline=None)
@given(_values(), st.sampled_from(["fix", "fup", "round"]))
def test_fix_fup_round_give_a_result_only_every_reading_gives(value, name):
    d, q = value
    kind, got = _outcome(lambda: evaluate_tree((FN, name, (NUM, d, q)), FanucVariables()))
    results = {_OF[name](r) for r in _readings(d, q)}
    if kind == "value":
        assert results == {got[0]}, (value, got)
    else:
        assert len(results) > 1, (value, got.reason)


@settings(max_examples=300, deadline=None)
@given(_values(), st.data(), st.sampled_from(["eq", "ne", "gt", "ge", "lt", "le"]))
def test_comparisons_give_a_truth_only_every_reading_gives(x, data, op):
    """Against another value, or one a few ulps from it (the same double, with or without a shadow)."""
    y = data.draw(st.one_of(_values(), st.builds(lambda k, keep: (_ulps(x[0], k), x[1] if keep and not k else None),
                                                 st.integers(-3, 3), st.booleans())))
    test = getattr(operator, op)
    for cond in ((BIN, op, (NUM, *x), (NUM, *y)),  # a number on the right (the constant bounds)
                 (BIN, op, (NUM, *x), (BIN, "+", (NUM, *y), (NUM, 0.0, Fraction(0))))):  # both computed
        kind, got = _outcome(lambda c=cond: compile_tree(c, FanucVariables(), exact=False)())
        ra, rb = _readings(*x), _readings(*y)
        truths = {test(ra[0], rb[0]), test(ra[1], rb[1])}
        if x[1] is not None and y[1] is not None:
            truths.add(test(x[1], y[1]))
        if kind == "value":
            assert truths == {bool(got[0])}, (x, y, op)
        else:
            assert len(truths) > 1, (x, y, op, got.reason)


@settings(max_examples=200, deadline=None)
@given(_values(), st.integers(1, 9), st.sampled_from(["mod", "and", "xor"]))
def test_mod_and_xor_give_a_result_only_every_reading_gives(x, j, op):
    fn = {"mod": lambda a, b: int(math.copysign(abs(a) % b, a)) if a else 0, "and": operator.and_,
          "xor": operator.xor}[op]
    of = _nearest if op == "mod" else _trunc
    kind, got = _outcome(lambda: evaluate_tree((BIN, op, (NUM, *x), (NUM, float(j), Fraction(j))), FanucVariables()))
    results = {fn(of(r), j) for r in _readings(*x)}
    if kind == "value":
        assert results == {got[0]}, (x, j, op, got)
    else:
        assert len(results) > 1, (x, j, op, got.reason)


@settings(max_examples=200, deadline=None)
@given(st.builds(lambda n, half, k: _ulps(n + half, k), st.integers(100, 190), st.sampled_from([0.0, 0.5]),
                 st.integers(-3, 3)))
def test_a_variable_number_is_every_reading_s(d):
    v = FanucVariables({n: Fraction(n) for n in range(100, 200)})
    index = (BIN, "+", (NUM, d, None), (NUM, 0.0, Fraction(0)))  # computed: #[...]
    kind, got = _outcome(lambda: evaluate_tree((VAR, index), v))
    numbers = {_nearest(r) for r in _readings(d, None)}
    if kind == "value":
        assert numbers == {int(got[0])}, (d, got)
    else:
        assert len(numbers) > 1, (d, got.reason)
