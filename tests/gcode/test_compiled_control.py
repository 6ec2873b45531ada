"""Loops and subroutines reuse their control: compiled conditions, jumps found once.

The runner compiles the expressions of O-word lines that run again (a loop's,
a subroutine's) into closures (:func:`nczones.gcode.expr.compile_expression`)
and keeps every jump an O-word searched for (``Runner.skip_to``).  These tests
hold both to the plain way (``program._REUSE_CONTROL`` off: every condition
evaluated from its tree, every jump searched in the text again):

* a compiled expression gives :func:`~nczones.gcode.expr.evaluate`'s value,
  the same double and exact shadow, or the same error, for generated
  expressions over set, unset, computed and out-of-range parameters (and a
  tree too deep to compile);
* generated programs of nested ``while``/``do``/``repeat`` loops,
  ``if``/``elseif``/``else``, ``break``/``continue``, subroutine calls and
  returns (with messages on O-word lines, and mistakes: unmatched labels,
  a loop beyond the iteration bound) give the same blocks, errors and
  parameters, and through the interpreter the same segments.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import NczonesError
from nczones.gcode import interpret_text, program
from nczones.gcode.expr import (
    MAX_COMPILED_DEPTH,
    EvalError,
    Parameters,
    compile_expression,
    evaluate,
)
from nczones.gcode.parser import parse_line
from nczones.gcode.program import iter_blocks
from tests.gcode.test_compiled_lines import expressions, literals
from tests.gcode.test_fastpath_blocks import MACHINE


def _params() -> Parameters:
    params = Parameters()
    for key, value in ((1, 0.1), (2, 2), (3, 0.123), ("a", 1.5), ("_g", 0)):
        params.set(key, value)
    params.provide(5420, lambda: 12.5)
    return params


def _outcome(fn, params: Parameters) -> tuple:
    try:
        return ("value", repr(fn(params)))  # repr: a NaN double equals itself
    except EvalError as e:
        return ("error", e.code, e.message)
    except (ArithmeticError, ValueError, KeyError, RecursionError) as e:  # whatever evaluate lets through
        return ("raised", type(e).__name__, str(e))


@st.composite
def expression_trees(draw):
    text = draw(expressions(3))
    parts = text.split("§")
    text = "".join(p + (draw(literals) if k < len(parts) - 1 else "") for k, p in enumerate(parts))
    return parse_line(f"X[{text}]", 1, "t.ngc").words[0][1]


@settings(max_examples=500, deadline=None, derandomize=True, database=None)
@given(expression_trees())
def test_compiled_expressions_give_evaluates_value_or_error(tree):
    compiled = compile_expression(tree)
    for _ in range(2):  # a compiled expression runs again on the same store
        assert _outcome(compiled, _params()) == _outcome(lambda p: evaluate(tree, p), _params())


@pytest.mark.parametrize("depth", [MAX_COMPILED_DEPTH - 1, MAX_COMPILED_DEPTH + 5, 400])
def test_deep_expressions_compile_or_are_left_to_evaluate(depth):
    tree = parse_line("X" + "[1 + " * depth + "#1" + "]" * depth, 1, "t.ngc").words[0][1]
    compiled = compile_expression(tree)
    assert _outcome(compiled, _params()) == _outcome(lambda p: evaluate(tree, p), _params())


def _run_blocks(text: str, reuse: bool, monkeypatch) -> tuple:
    monkeypatch.setattr(program, "_REUSE_CONTROL", reuse)
    params = Parameters()
    out = []
    try:
        for b in iter_blocks(text, "t.ngc", params=params, max_loop_iterations=40):
            out.append((b.index, b.number, b.messages, str(b.span),
                        tuple((w.letter, w.value, w.text, str(w.span)) for w in b.words)))
    except NczonesError as exc:
        out.append(("error", type(exc).__name__, str(exc)))
    return out, dict(params._num), dict(params._globals), [dict(s) for s in params._scopes]


def _run_segments(text: str, reuse: bool, monkeypatch) -> tuple:
    monkeypatch.setattr(program, "_REUSE_CONTROL", reuse)
    run = interpret_text(text, MACHINE, fast=False, max_loop_iterations=40)
    try:
        return [(s.kind, s.start, s.end, s.block, str(s.span)) for s in run.segments()], \
            [str(u) for u in run.unsupported]
    except NczonesError as exc:
        return ("error", str(exc)), [str(u) for u in run.unsupported]


conditions = st.sampled_from(["[#1 LT 5]", "[#1 GT 2]", "[#2 EQ 1]", "[[#1 MOD 3] EQ 0]", "[#1 LE #3]",
                              "[#<c> GT 1]", "[#1 NE 4 AND #2 LT 3]", "[COS[#1 * 60] GT 0]", "[1/#4 GT 0]",
                              "[#<unset> GT 0]", "[#1 GE 2.5]"])
moves = st.sampled_from(["G1 X[#1 * 2] Y[#2]", "G0 X#1", "G1 Y[SIN[#1 * 30] * 5]", "#2 = [#2 + 1]",
                         "#3 = [#3 + #1]", "#<c> = [#<c> + 0.5]", "G1 X[#1] Y[#3 / 4]", "#4 = [#4 - 1]"])


@st.composite
def bodies(draw, depth: int, loop: int | None) -> list[str]:
    """Lines of a block; ``loop``: the label of the innermost loop (break and continue refer to it)."""
    out: list[str] = []
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.integers(0, 9 if depth else 2))
        label = 200 + depth * 10 + len(out)
        msg = draw(st.sampled_from(["", "", "", " (DEBUG, #1)"]))
        if kind <= 2:
            out.append(draw(moves))
        elif kind <= 4:
            out.append(f"o{label} if {draw(conditions)}{msg}")
            out += draw(bodies(depth - 1, loop))
            for _ in range(draw(st.integers(0, 2))):
                out.append(f"o{label} elseif {draw(conditions)}")
                out += draw(bodies(depth - 1, loop))
            if draw(st.booleans()):
                out.append(f"o{label} else{msg}")
                out += draw(bodies(depth - 1, loop))
            out.append(f"o{label} endif")
        elif kind == 5:
            out.append(f"o{label} repeat [{draw(st.integers(0, 3))}]")
            out += draw(bodies(depth - 1, label))
            out.append(f"o{label} endrepeat")
        elif kind == 6:
            out.append(f"o{label} do")
            out += ["#1 = [#1 + 1]", *draw(bodies(depth - 1, label))]
            out.append(f"o{label} while {draw(conditions)}{msg}")
        elif kind == 7 and loop is not None:
            out.append(f"o{loop} {draw(st.sampled_from(['break', 'continue']))}{msg}")
        elif kind == 8:
            out.append(f"o<sub> call [#1] [{draw(literals)}]")
        else:
            out.append(f"o{label} while {draw(conditions)}")
            out += ["#1 = [#1 + 1]", *draw(bodies(depth - 1, label))]
            out.append(f"o{label} endwhile")
    return out


@st.composite
def loop_programs(draw) -> str:
    sub = ["o<sub> sub", "#<local> = [#1 + #2]", "o300 if [#<local> GT 3]", "G1 Z[#<local>]", "o<sub> return [#1]",
           "o300 endif", "G0 Z1", "o<sub> endsub"]
    head = ["G21 G90 G17 G54 F100", "#1 = 0", "#2 = 0", "#3 = 1", "#4 = 3", "#<c> = 0"]
    body = ["o100 while [#1 LT 6]", "#1 = [#1 + 1]", *draw(bodies(2, 100)), "o100 endwhile"]
    lines = [*sub, *head, *body] if draw(st.booleans()) else [*head, *body, *sub]
    if draw(st.integers(0, 6)) == 0:  # a mistake: a label that does not match
        k = draw(st.integers(0, len(lines) - 1))
        lines[k] = lines[k].replace("o2", "o9", 1)
    return "\n".join([*lines, "M2"]) + "\n"


@settings(max_examples=200, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(loop_programs())
def test_reused_control_gives_the_plain_blocks_errors_and_parameters(monkeypatch, text):
    assert _run_blocks(text, True, monkeypatch) == _run_blocks(text, False, monkeypatch), text


@settings(max_examples=60, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(loop_programs())
def test_reused_control_gives_the_plain_segments(monkeypatch, text):
    assert _run_segments(text, True, monkeypatch) == _run_segments(text, False, monkeypatch), text
