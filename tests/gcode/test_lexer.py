"""Lexical forms, spans, exact decimals and golden diagnostics of the G-code language layer."""

from __future__ import annotations

import os
import re
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError, SourceSpan
from nczones.exact import parse_decimal
from nczones.gcode.lexer import decimal_value, scan_simple
from nczones.gcode.parser import parse_line
from nczones.gcode.program import iter_blocks

GOLDEN = Path(__file__).resolve().parent.parent / "golden" / "gcode"


def words(text: str, **kw):
    return [[(w.letter, w.value) for w in b.words] for b in iter_blocks(text, "t.ngc", **kw)]


@pytest.mark.parametrize(
    "text, value",
    [("X5", Fraction(5)), ("X+5", Fraction(5)), ("X.5", Fraction(1, 2)), ("X5.", Fraction(5)),
     ("X-.5", Fraction(-1, 2)), ("x-0.100", Fraction(-1, 10)), ("X1 2.5", Fraction(25, 2)),
     ("X 1 2 . 5 0", Fraction(25, 2)), ("X[-2.5]", Fraction(-5, 2)), ("X[1.5 + 0.25 * 2]", Fraction(2))],
)
def test_number_forms(text, value):
    assert words(text) == [[("X", value)]]


def test_lower_case_no_spaces_and_spans():
    (b,) = iter_blocks("n20g1x-1.5y2f100", "p.ngc")
    assert b.number == 20
    assert [(w.letter, w.text, w.span.column, w.span.end_column) for w in b.words] == [
        ("G", "g1", 4, 6), ("X", "x-1.5", 6, 11), ("Y", "y2", 11, 13), ("F", "f100", 13, 17)]
    assert b.words[1].span == SourceSpan("p.ngc", 1, 6, 11, "n20g1x-1.5y2f100")
    assert b.span.line == 1 and b.span.text == "n20g1x-1.5y2f100"


def test_fast_path_and_parser_agree_on_spans():
    line = "/N5 G01 X 1 2.5 (c) Y-.5 ; tail"
    fast = scan_simple(line, 3, "f")
    assert fast is not None
    slow = parse_line(line, 3, "f")
    assert slow.delete and slow.number == 5
    assert [(w.letter, w.span.column, w.span.end_column, w.text) for w in fast[2]] == [
        (letter, col, end, text) for letter, _tree, col, end, text in slow.words]


def test_comments_semicolon_percent_and_empty_lines():
    prog = "%\n(header)\n\n; only a comment\nG0 X1 (move) ; rest X9\n%\nG0 X99\n"
    assert words(prog) == [[("G", 0), ("X", 1)]]


def test_block_delete_switch():
    prog = "G0 X1\n/G0 X2\n  / G0 X3\nM2\n"
    assert words(prog) == [[("G", 0), ("X", 1)], [("G", 0), ("X", 2)], [("G", 0), ("X", 3)], [("M", 2)]]
    assert words(prog, block_delete=True) == [[("G", 0), ("X", 1)], [("M", 2)]]


def test_program_stops_after_m2_or_m30_and_garbage_after_is_not_read():
    assert words("G0 X1\nM30\nthis is $$$ garbage\n") == [[("G", 0), ("X", 1)], [("M", 30)]]
    assert words("G1 X1 M02\nG0 X5\n") == [[("G", 1), ("X", 1), ("M", 2)]]


def test_g_code_decimal_value_and_block_index_and_crlf():
    blocks = list(iter_blocks("G59.1\r\nG0 X1\r\n"))
    assert blocks[0].words[0].value == Fraction(591, 10)
    assert [b.index for b in blocks] == [0, 1]
    assert blocks[1].words[1].text == "X1"


def test_bom_is_ignored():
    assert words("\ufeffG0 X1\n") == [[("G", 0), ("X", 1)]]


def test_magic_comments_recorded():
    (b,) = iter_blocks("#1=2.5\nG0 X1 (MSG, hello) (debug, v=#1) (print, p=#<_nope>) (just a note)\n")
    assert b.messages == ("MSG, hello", "DEBUG, v=2.500000", "PRINT, p=######")


def test_several_errors_are_collected():
    with pytest.raises(GcodeError) as e:
        list(iter_blocks("G0 X1\nG1 X$\nG1 Y\nG1 Z(\nM2\nG1 $\n", "m.ngc"))
    codes = [(d.code, d.span.line) for d in e.value.diagnostics]
    assert codes == [("GC104", 2), ("GC104", 3), ("GC104", 4)]  # stops at the program end


# --------------------------------------------------------------------------- Hypothesis

decimals = st.builds(
    lambda sign, whole, frac, point: f"{sign}{whole}{'.' if point or not whole else ''}{frac}",
    st.sampled_from(["", "+", "-"]),
    st.text("0123456789", max_size=6),
    st.text("0123456789", max_size=6),
    st.booleans(),
).filter(lambda t: any(c.isdigit() for c in t))


@settings(max_examples=200, derandomize=True, deadline=None)
@given(decimals)
def test_decimal_words_are_exact(text):
    expected = parse_decimal(text)
    assert decimal_value(text) == expected
    (b,) = iter_blocks(f"X{text}")
    assert b.words[0].value == expected
    assert type(b.words[0].value) is Fraction


word_letters = st.sampled_from("GXYZIJKFSRP")


@settings(max_examples=100, derandomize=True, deadline=None)
@given(st.lists(st.tuples(word_letters, decimals), min_size=1, max_size=6), st.randoms(use_true_random=False))
def test_random_whitespace_and_case_do_not_change_blocks(items, rnd):
    plain = " ".join(f"{letter}{num}" for letter, num in items)

    def mangle(letter, num):
        out = letter.lower() if rnd.random() < 0.5 else letter
        out += " " * rnd.randint(0, 2)
        for ch in num:
            out += ch + (" " if ch.isdigit() and rnd.random() < 0.3 else "")
        return out.rstrip() + " " * rnd.randint(0, 2)

    mangled = "".join(mangle(letter, num) for letter, num in items)
    assert words(plain) == words(mangled)


# --------------------------------------------------------------------------- golden diagnostics

BAD_INPUTS = {
    "unclosed_comment": "G0 X1\nG1 X2 (no end\n",
    "nested_comment": "G1 X1 (a (b) c)\n",
    "bad_character": "G1 X1 $5\n",
    "letter_without_value": "G1 X Y2\n",
    "bad_number": "G1 X1.2.3\n",
    "n_not_first": "G1 N10 X1\n",
    "unknown_function": "G1 X[FOO[2]]\n",
    "unclosed_expression": "G1 X[1 + 2\n",
    "unknown_operator": "G1 X[1 ? 2]\n",
    "assignment_without_equals": "#1 5\n",
    "named_param_unterminated": "G0 X#<depth\n",
    "unknown_oword_keyword": "o100 callsub\n",
    "undefined_named_param": "G0 X#<depth>\n",
    "divide_by_zero": "#1 = 0\nG0 X[10 / #1]\n",
    "sqrt_negative": "G0 X[SQRT[-4]]\n",
    "unmatched_endwhile": "o1 endwhile\n",
    "missing_endif": "o1 if [1]\nG0 X1\n",
    "m98_without_p": "M98\nM30\n",
}


@pytest.mark.parametrize("name", sorted(BAD_INPUTS))
def test_golden_diagnostics(name):
    with pytest.raises(GcodeError) as e:
        list(iter_blocks(BAD_INPUTS[name], f"{name}.ngc"))
    text = e.value.render() + "\n"
    golden = GOLDEN / f"{name}.txt"
    if os.environ.get("NCZONES_REGEN_GOLDEN"):
        golden.parent.mkdir(parents=True, exist_ok=True)
        golden.write_text(text)
    assert text == golden.read_text()
    assert all(d.code.startswith("GC") and d.span is not None for d in e.value.diagnostics)


plain_numbers = st.builds(
    lambda sign, whole, point, frac: sign + whole + point + frac if (whole or frac) else sign + "0",
    st.sampled_from(["", "+", "-"]), st.from_regex(r"[0-9]{0,12}", fullmatch=True), st.sampled_from(["", "."]),
    st.from_regex(r"[0-9]{0,12}", fullmatch=True),
).filter(lambda t: re.fullmatch(r"[+-]?(?:\d+\.?\d*|\.\d+)", t, re.ASCII) is not None)


@settings(max_examples=400, deadline=None, derandomize=True, database=None)
@given(plain_numbers)
def test_plain_literals_read_exactly_as_the_general_reader_and_parse_decimal(text):
    from nczones.gcode.lexer import plain_decimal_value

    assert plain_decimal_value(text) == decimal_value(text) == parse_decimal(text.lstrip("+") if text.lstrip("+-") else "0")


@settings(max_examples=400, deadline=None, derandomize=True, database=None)
@given(st.text(alphabet=st.sampled_from(list("GgXx#<>[]*+-.=019 \t\r;(ÄΣ") + ["\x0b", "\n"]), max_size=24))
def test_parser_reads_comment_free_lines_as_the_token_reader_does(line):
    """The parser's shortcut for ASCII lines without comments gives the code and columns of the
    token-by-token reader (``_compress``), which it uses for every other line."""
    from nczones.gcode.parser import Parser, _compress

    p = Parser(line)
    assert (p.s, p.cols) == _compress(line)
