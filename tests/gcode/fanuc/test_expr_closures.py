"""The closures of :func:`~nczones.gcode.fanuc.expr.compile_tree` evaluate every tree as Fanuc defines it (issue 36).

``compile_tree`` specializes common shapes for speed: a local variable and a number (``#1 + 1``, ``#1 * 0.01``,
``#1 LT 10``) in one closure, ``SIN``/``COS`` without the function dispatch, and operands whose exact shadow no
operation reads (those of a comparison, of EQ/NE/MOD/AND/OR/XOR, of a function other than ABS/ROUND/ADP, of
ATAN/POW with two arguments, an IF/WHILE condition: ``exact=False``) computed as doubles only.  None of that may
change a value or an error.  The reference here evaluates a tree node by node with the definitions:

* ``+ - * /``: :func:`nczones.gcode.expr.binary_op` (the IEEE double, checked for NaN/infinity, the exact shadow
  kept only where it rounds to the double);
* EQ/NE tell vacant from 0 (0i-MF "Arithmetic and logic operation"; the module docstring of
  :mod:`nczones.gcode.fanuc.expr`); otherwise GT/GE/LT/LE/EQ/NE, like MOD/AND/OR/XOR, on the values given as number
  nodes (the generic path: the truth every reading of the doubles gives, else GC398; test_macro_readings.py holds
  that to readings computed independently); true is ``(1.0, 1)``, false ``(0.0, 0)``;
* SIN/COS in degrees on the double, no shadow (``math.sin(d * pi / 180)``, the controller's double);
* the other functions and MOD/AND/OR/XOR on a value given as a number node (the generic path, which holds no
  specialization), negation ``(-d, -q)``.

Every tree is compared bit for bit with ``exact=True`` (double and shadow) and on the double with ``exact=False``;
an error must be the same code and message.  A tree with a library function (SIN ... POW) may instead be
``unknown`` GC396/GC397, where the result's one-ulp neighbours part a decision (libm40; test_libm_spread.py holds
those to the neighbours substituted); every double given is still the definitions' double.
"""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.expr import EvalError, binary_op
from nczones.gcode.fanuc.expr import (
    VACANT,
    FanucVariables,
    SystemVariableUnknown,
    compile_tree,
    evaluate_tree,
)
from nczones.gcode.fanuc.parser import BIN, FN, FN2, NEG, NUM, VAR

_TRUE, _FALSE = (1.0, Fraction(1)), (0.0, Fraction(0))


def _num(value: tuple) -> tuple:
    return (NUM, value[0], value[1])


def reference(node: tuple, v: FanucVariables) -> tuple:
    """The value of ``node`` by the definitions (module docstring)."""
    tag = node[0]
    if tag == NUM:
        return (node[1], node[2])
    if tag == VAR:
        return v.read(int(reference(node[1], v)[0]))
    if tag == NEG:
        d, q = reference(node[1], v)
        return (-d, -q if q is not None else None)
    if tag == BIN:
        op, a, b = node[1], reference(node[2], v), reference(node[3], v)
        if op in ("+", "-", "*", "/"):
            return binary_op(op, a, b)
        if op in ("eq", "ne") and (a is VACANT or b is VACANT):
            same = a is VACANT and b is VACANT
            return _TRUE if same == (op == "eq") else _FALSE
        return evaluate_tree((BIN, op, _num(a), _num(b)), v)  # relations, MOD AND OR XOR on number nodes
    if tag == FN:
        name, a = node[1], reference(node[2], v)
        if name in ("sin", "cos"):
            r = a[0] * math.pi / 180.0  # degrees to radians in doubles; inf or NaN (radians overflow): GC312
            if r - r:
                raise EvalError("GC312", f"argument to {name.upper()} is {a[0]!r}"
                                + ("" if a[0] - a[0] else ": its radians overflow a double"))
            return ((math.sin if name == "sin" else math.cos)(r), None)
        return evaluate_tree((FN, name, _num(a)), v)
    assert tag == FN2
    return evaluate_tree((FN2, node[1], _num(reference(node[2], v)), _num(reference(node[3], v))), v)


_numbers = st.one_of(
    st.builds(lambda n, k: Fraction(n, 10**k), st.integers(-10**6, 10**6), st.integers(0, 4)).map(
        lambda q: (q.numerator / q.denominator, q)),
    st.sampled_from([(0.0, Fraction(0)), (1.0, Fraction(1)), (-2.5, Fraction(-5, 2)), (1e308, Fraction(10**308)),
                     (0.1, None), (3.6, Fraction(18, 5)), (1000.0, Fraction(1000)),
                     # where readings split (GC398): FIX[0.3 / 0.1], [0.1 * 3] EQ 0.3, ROUND of 1.5 * 1.017 * 1000
                     (2.9999999999999996, None), (0.30000000000000004, None), (0.3, Fraction(3, 10)),
                     (1525.4999999999998, None)]))
_variable = st.sampled_from([1, 2, 3, 4, 33, 100, 101]).map(lambda n: (VAR, (NUM, float(n), Fraction(n))))
_leaf = _numbers.map(_num) | _variable
_BINARY = ["+", "-", "*", "/", "gt", "ge", "lt", "le", "eq", "ne", "mod", "and", "or", "xor"]
_FUNCTIONS = ["sin", "cos", "abs", "fix", "fup", "round", "sqrt", "atan", "tan", "ln", "exp", "asin", "acos"]


def _extend(children):
    return st.one_of(
        st.tuples(st.just(BIN), st.sampled_from(_BINARY), children, children),
        st.tuples(st.just(BIN), st.sampled_from(["+", "*", "gt", "lt", "le", "ge"]), _variable, _numbers.map(_num)),
        st.tuples(st.just(NEG), children),
        st.tuples(st.just(FN), st.sampled_from(_FUNCTIONS), children),
        st.tuples(st.just(FN2), st.sampled_from(["atan", "pow"]), children, children))


_trees = st.recursive(_leaf, _extend, max_leaves=6)
_values = st.one_of(st.just(VACANT), _numbers, st.floats(-1e6, 1e6).map(lambda d: (d, None)))


def _outcome(fn, *args):
    try:
        return "value", fn(*args)
    except EvalError as e:
        return "error", (e.code, e.message)
    except SystemVariableUnknown as e:  # GC398: readings that split (the same reason)
        return "unknown", (e.code, e.reason)
    except OverflowError:  # an exact shadow beyond the double range (binary_op's own limit)
        return "overflow", None


#: The library functions whose results carry a spread (libm40).
_LIBM = frozenset(("sin", "cos", "tan", "atan", "asin", "acos", "ln", "exp", "pow"))


def _has_libm(node: tuple) -> bool:
    if node[0] in (FN, FN2) and node[1] in _LIBM:
        return True
    return any(isinstance(child, tuple) and child and _has_libm(child) for child in node[1:])


def _spread_split(tree: tuple, outcome: tuple) -> bool:
    """Whether ``outcome`` is a neighbours' split (GC396/GC397), allowed only for a tree with a library function."""
    if outcome[0] == "unknown" and outcome[1][0] in ("GC396", "GC397"):
        assert _has_libm(tree), (tree, outcome)
        return True
    return False


def _bits(d: float) -> tuple:
    return (d.hex(), math.copysign(1, d))


@settings(max_examples=400, deadline=None)
@given(_trees, st.lists(_values, min_size=7, max_size=7))
def test_compiled_trees_evaluate_as_the_definitions(tree, values):
    v = FanucVariables()
    for n, value in zip([1, 2, 3, 4, 33, 100, 101], values):
        v.write(n, value)
    kind, expected = _outcome(reference, tree, v)
    got_kind, got = _outcome(compile_tree(tree, v))
    if _spread_split(tree, (got_kind, got)) or _spread_split(tree, _outcome(compile_tree(tree, v, exact=False))):
        return
    if kind == "overflow":
        assert got_kind == "overflow"
        return
    assert (got_kind, got if kind != "value" else None) == (kind, expected if kind != "value" else None)
    if kind == "value":
        assert _bits(got[0]) == _bits(expected[0]) and got[1] == expected[1]
        assert (got is VACANT) == (expected is VACANT)
    # the double alone (a condition, an operand whose shadow nothing reads): the same double, the same error
    d_kind, d_got = _outcome(compile_tree(tree, v, exact=False))
    if kind != "value":
        assert (d_kind, d_got) == (kind, expected)
    else:
        assert d_kind == "value" and _bits(d_got[0]) == _bits(expected[0])


def test_the_local_shortcuts_read_the_current_call_level():
    """``#1 + 1`` compiled once reads ``#1`` of the level it runs in (a G65 call enters a new level)."""
    v = FanucVariables()
    v.write(1, (2.0, Fraction(2)))
    one = (NUM, 1.0, Fraction(1))
    add = compile_tree((BIN, "+", (VAR, one), (NUM, 0.5, Fraction(1, 2))), v)
    less = compile_tree((BIN, "lt", (VAR, one), (NUM, 3.0, Fraction(3))), v, exact=False)
    assert add() == (2.5, Fraction(5, 2)) and less() == _TRUE
    saved = v.push_level({1: (7.0, Fraction(7))})
    assert add() == (7.5, Fraction(15, 2)) and less() == _FALSE
    v.pop_level(saved)
    assert add() == (2.5, Fraction(5, 2))
    saved = v.push_level({})  # vacant: 0 in arithmetic and in the order comparisons
    assert add() == (0.5, Fraction(1, 2)) and less() == _TRUE
