"""Lines run by their shape's compiled code do exactly what the general path does.

The runner executes a line whose shape has compiled code (``shapes.CompiledLine``)
without building its parse: the code evaluates the words and assignments and
returns the block's letters and values, or declines (an error, M2/M30/M98/M99,
G65...) having changed nothing, and the general path then runs the line.  These
tests hold programs run with compiled code to the same programs run without it
(``shapes._COMPILE_RUNS`` off): the blocks with their words, values, columns and
numbers, the errors and unknown reasons, the parameters afterwards, and through
the interpreter the segments.  The lines share shapes, so that most of them
take the compiled code, and cover what it must decline or report: division by
zero, NaN, unset names, out-of-range parameter numbers, exact shadows kept and
dropped, parameters computed from the machine state (``#5420``), loops (the
runner's cache of lines), block delete, N numbers and blanks.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import NczonesError
from nczones.gcode import interpret_text, shapes
from nczones.gcode.expr import Parameters
from nczones.gcode.program import iter_blocks
from tests.corpus import CORPUS, corpus_programs
from tests.gcode.test_fastpath_blocks import MACHINE
from tests.sizes import examples


def _run_blocks(text: str, compiled: bool, monkeypatch) -> tuple:
    """Blocks (every field a report or the interpreter reads), the error if any, the parameters after."""
    monkeypatch.setattr(shapes, "_COMPILE_RUNS", compiled)
    shapes.clear()
    params = Parameters()
    out = []
    try:
        for b in iter_blocks(text, "t.ngc", params=params, max_loop_iterations=50):
            out.append((b.index, b.number, b.messages, str(b.span), b.span.end_column,
                        tuple((w.letter, w.value, w.text, str(w.span), w.span.end_column) for w in b.words)))
    except NczonesError as exc:
        out.append(("error", type(exc).__name__, str(exc)))
    finally:
        shapes.clear()
    return out, dict(params._num), dict(params._globals), [dict(s) for s in params._scopes]


def _run_segments(text: str, compiled: bool, monkeypatch) -> tuple:
    monkeypatch.setattr(shapes, "_COMPILE_RUNS", compiled)
    shapes.clear()
    run = interpret_text(text, MACHINE, fast=False)
    try:
        return [(s.kind, s.start, s.end, s.block, str(s.span), s.feed_mm_min) for s in run.segments()], \
            [str(u) for u in run.unsupported]
    except NczonesError as exc:
        return ("error", str(exc)), [str(u) for u in run.unsupported]
    finally:
        shapes.clear()


#: Literals; as parameter numbers (``#§``) some are out of range (5602), not integers (2.001), or stop the
#: program (#3000); the last one is too large for a double (inf).
literals = st.sampled_from(["0", "1", "2", "0.1", "0.2", ".5", "5.", "12.345", "3", "0.3", "100", "7.25", "0.0",
                            "3000", "5602", "2.001", "3.00001", "1" + "0" * 400])
functions = st.sampled_from(["ABS", "ABS", "COS", "SIN", "SQRT", "FIX", "FUP", "ROUND", "LN", "EXP", "ACOS", "TAN"])
operators = st.sampled_from(["+", "-", "*", "/", "MOD", "**", "GT", "EQ", "AND", "OR"])


def expressions(depth: int = 2):
    """Expression text with "§" where a literal goes."""
    leaf = st.sampled_from(["§", "§", "§", "-§", "-§", "#§", "#1", "#2", "#3", "#<a>", "#<_g>", "#5420", "#5421",
                            "#<never_set>"])
    if depth == 0:
        return leaf
    sub = expressions(depth - 1)
    return st.one_of(
        leaf,
        st.builds(lambda a, op, b: f"[{a} {op} {b}]", sub, operators, sub),
        st.builds(lambda a, op, b: f"{a}{op}{b}", sub, st.sampled_from(["+", "-", "*", "/"]), sub),
        st.builds(lambda f, a: f"{f}[{a}]", functions, sub),
        st.builds(lambda a, b: f"ATAN[{a}]/[{b}]", sub, sub),
        st.builds(lambda a: f"-{a}", sub),
    )


@st.composite
def line_templates(draw):
    """One line shape: words and assignments with "§" for literals."""
    kind = draw(st.integers(0, 9))
    e = draw(expressions())
    if kind <= 3:
        words = draw(st.lists(st.sampled_from(["X", "Y", "Z", "F"]), min_size=1, max_size=3, unique=True))
        text = draw(st.sampled_from(["G1 ", "G0 ", "", "N§ G1 ", "g1"])) + " ".join(f"{w}[{e}]" for w in words)
    elif kind <= 6:
        target = draw(st.sampled_from(["#1", "#2", "#3", "#<a>", "#<_g>", "#§", "#3000", "#5602"]))
        text = f"{target} = [{e}]"
    elif kind == 7:
        text = draw(st.sampled_from(["M§", "M[§]", "G[§] X§", "S[§] M3", "/G1 X[§]", "G1 X#<never_set>",
                                     "G1 X[§/§]", "#1=§ #2=[#1+§]", "G1 X [ § + #1 ] Y#2"]))
    else:
        text = f"G1 X[{e}] #1 = [#1 + §]"
    return text


@st.composite
def programs(draw):
    templates = draw(st.lists(line_templates(), min_size=1, max_size=5))
    out = ["G21 G90 G17 G54 F100", "#1 = 0.1", "#2 = 2", "#3 = 0.123", "#<a> = 1.5", "#<_g> = 0"]
    loop = draw(st.booleans())
    if loop:
        out.append("o100 repeat [3]")
    for _ in range(draw(st.integers(2, 14))):
        t = draw(st.sampled_from(templates))
        parts = t.split("§")
        out.append("".join(p + (draw(literals) if k < len(parts) - 1 else "") for k, p in enumerate(parts)))
    if loop:
        out.append("o100 endrepeat")
    if draw(st.integers(0, 4)) == 3:  # a '%' line: the first one before any block is skipped, the next ends
        out.insert(draw(st.integers(0, len(out))), "%")
    out.append("M2")
    return "\n".join(out) + "\n"


@settings(max_examples=examples(150, 300), deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(programs())
def test_compiled_lines_give_the_general_paths_blocks_errors_and_parameters(monkeypatch, text):
    assert _run_blocks(text, True, monkeypatch) == _run_blocks(text, False, monkeypatch), text


@settings(max_examples=examples(50, 100), deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(programs())
def test_compiled_lines_give_the_general_paths_segments(monkeypatch, text):
    assert _run_segments(text, True, monkeypatch) == _run_segments(text, False, monkeypatch), text


_HUGE = "1" + "0" * 400


#: Programs whose second line has the shape of the first and must be declined by its compiled code (or
#: evaluated to an error, or stop the program), each followed by a line that must not run.
DECLINED = (
    "G1 X[#1] M3\nG1 X[#1] M2\nG1 X9\n",
    "G1 X[#1] M3\nG1 X[#1] M30\nG1 X9\n",
    "G1 X[#1] M3\nG1 X[#1] M98\nG1 X9\n",
    "G1 X[#1] M3\nG1 X[#1] M99\nG1 X9\n",
    "G1 X[#1] M3\nG1 X[#1] M97\nG1 X9\n",
    "G[1] X[1]\nG[65] X[1]\nG1 X9\n",
    "G[1] X[1]\nG[66.1] X[1]\nG1 X9\n",
    "#1 = [1]\n#3000 = [1]\nG1 X9\n",
    "#1 = [1]\n#3006 = [1]\nG1 X9\n",
    "#1 = [1]\n#5602 = [1]\nG1 X9\n",
    "#1 = [1]\n#2.5 = [1]\nG1 X9\n",
    "G1 X[#1]\nG1 X[#5602]\nG1 X9\n",
    "G1 X[#1]\nG1 X[#0]\nG1 X9\n",
    "G1 X[#1]\nG1 X[#1.00001]\nG1 X9\n",  # within 0.0001 of 1: #1
    "G1 X[#1]\nG1 X[#1.001]\nG1 X9\n",
    f"G1 X[#1]\nG1 X[#{_HUGE}]\nG1 X9\n",
    f"G1 X[ABS[-1]]\nG1 X[ABS[-{_HUGE}]]\nG1 X9\n",
    f"G1 X[1 + 1]\nG1 X[1 + {_HUGE}]\nG1 X9\n",
    "G1 X[1 / 1]\nG1 X[1 / 0]\nG1 X9\n",
    "G1 X[#<a>]\nG1 X[#<b>]\nG1 X9\n",
    "G1 X[SQRT[1]]\nG1 X[SQRT[-1]]\nG1 X9\n",
    "G1 X[1 MOD 1]\nG1 X[1 MOD 0]\nG1 X9\n",
)


@pytest.mark.parametrize("text", DECLINED)
def test_what_the_compiled_code_must_decline_runs_as_the_general_path_runs_it(monkeypatch, text):
    text = "#<a> = 1\n" + text
    assert _run_blocks(text, True, monkeypatch) == _run_blocks(text, False, monkeypatch)


@pytest.mark.parametrize("before", ["", "#1 = 0\n"])  # the runner's first line, and a line of a run
def test_a_compiled_line_starts_the_program_for_percent(monkeypatch, before):
    """The first '%' line is skipped only before the program's first block: a block from compiled code
    counts (its shape known from an earlier program, so that the general path never sees the line)."""
    out = []
    for compiled in (True, False):
        monkeypatch.setattr(shapes, "_COMPILE_RUNS", compiled)
        shapes.clear()
        list(iter_blocks("G1 X[#1 + 1]\n", "warm.ngc"))
        out.append([b.values for b in iter_blocks(before + "G1 X[#1 + 2]\n%\nG1 X5\n", "t.ngc")])
    shapes.clear()
    assert out[0] == out[1] == [(Fraction(1), Fraction(2))]


def _counting_runs(monkeypatch) -> list:
    """Make compiled code note each run (True: done, False: declined) in the list returned."""
    calls = []
    real = shapes._executor

    def counting(*args):
        run, columns = real(*args)

        def counted(literals, params):
            done = run(literals, params)
            calls.append(done is not None)
            return done
        return counted, columns

    monkeypatch.setattr(shapes, "_executor", counting)
    shapes.clear()
    return calls


def test_most_lines_of_a_repeated_shape_take_the_compiled_code(monkeypatch):
    """The differential tests above compare something: the compiled code runs, and declines what it must."""
    calls = _counting_runs(monkeypatch)
    text = "#1 = 0.5\n" + "".join(f"G1 X[#1 + {k}.5] Y[1 / [#1 - 0.{k}]]\n" for k in range(1, 10))
    with pytest.raises(NczonesError, match="divide by zero") as exc:
        list(iter_blocks(text, "t.ngc"))
    shapes.clear()
    assert "t.ngc:6:" in str(exc.value)  # line 6: 0.5 - 0.5; the general path reports it
    assert calls == [True] * 3 + [False]  # the first line of a shape is parsed


def test_lines_run_again_in_loops_and_subroutines_take_the_compiled_code_every_time(monkeypatch):
    """A line the runner keeps for loops and subroutines is kept as its shape's compiled line, even
    the first line of the shape (parsed on its first reading): every run of it takes the compiled code."""
    calls = _counting_runs(monkeypatch)
    text = ("o1 sub\nG1 X[#1 * 2] Y[#2 + 0.5]\no1 endsub\n#2 = 1\n"
            "o2 repeat [4]\n#1 = [#1 + 1.5]\nG1 X[#1 + 0.25] F100\no1 call [#1]\no2 endrepeat\nM2\n")
    values = [b.values for b in iter_blocks(text, "t.ngc")]
    shapes.clear()
    assert calls == [True] * 12  # 4 iterations of two loop lines and the subroutine's line
    # in the subroutine #2 is its own, unset argument: 0
    assert values[:4] == [(1, Fraction(7, 4), 100), (1, 3, Fraction(1, 2)), (1, Fraction(13, 4), 100), (1, 6, Fraction(1, 2))]


def test_a_shadow_is_kept_where_the_double_agrees_and_dropped_where_it_does_not(monkeypatch):
    text = "#1 = 0.1\n" + "G1 X[#1 + 0.2]\n" * 2 + "G1 X[#1 + 0.25]\n"
    blocks, *_ = _run_blocks(text, True, monkeypatch)
    values = [b[5][1][1] for b in blocks]
    assert values[:2] == [Fraction(0.1 + 0.2)] * 2  # the controller's sum is not the double nearest 3/10
    assert values[2] == Fraction(35, 100)


def _corpus_programs_with_expressions():
    out = []
    for rel, _dialect in corpus_programs():
        text = (CORPUS / rel).read_bytes().decode("utf-8", errors="surrogateescape")
        if "#" in text or "[" in text:
            out.append((rel, text))
    return out


@pytest.mark.skipif(not CORPUS.is_dir(), reason="corpus not present")
def test_corpus_programs_run_the_same_with_compiled_lines(monkeypatch):
    programs = _corpus_programs_with_expressions()
    assert len(programs) > 100
    differ = [rel for rel, text in programs
              if _run_blocks(text, True, monkeypatch) != _run_blocks(text, False, monkeypatch)]
    assert differ == []


def _stage(run) -> str:
    """Where a shape's run stands: its code's file name (the stub before the first call, then the run's own)."""
    return run.__code__.co_filename


def test_a_shape_run_is_compiled_at_its_first_call():
    """Issue 36: a shape's run is compiled when first called (the double pass never calls it), and is then
    the compiled function itself (the same object, as RUNS holds it)."""
    from nczones.gcode.linuxcnc.doubles import double_pass

    shapes.clear()
    text = "G21 G90 G54 F100\n#1 = 0\no1 while [#1 LT 3]\nG1 X[#1 * 0.5] Y[#1 + 1]\n#1 = [#1 + 1]\no1 endwhile\nM30\n"
    double_pass(text, MACHINE, max_iterations=100)
    runs = [hit[0] for hit in shapes.RUNS.values()]
    assert runs and {_stage(run) for run in runs} == {"<line shape stub>"}
    blocks = list(iter_blocks(text, "t.ngc"))
    assert [b.values for b in blocks if b.letters == "GXY"] == [
        (Fraction(1), Fraction(0), Fraction(1)), (Fraction(1), Fraction(1, 2), Fraction(2)),
        (Fraction(1), Fraction(1), Fraction(3))]
    ran = [run for run in runs if _stage(run) == "<line shape run>"]
    assert ran and all(shapes.RUNS[k][0] in ran or _stage(shapes.RUNS[k][0]) == "<line shape stub>"
                       for k in shapes.RUNS)
    shapes.clear()
