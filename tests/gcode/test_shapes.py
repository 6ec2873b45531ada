"""Parsing by line shape equals parsing afresh, whatever lines came before.

``parse_line_shaped`` rebuilds the parse of a line from an earlier line of
the same shape (the text with its number literals taken out).  The
invariant: it returns exactly what ``parse_line`` returns, or raises the same
diagnostic, for every line.  Checked on generated lines that share shapes
(numbers changed, signs, blanks, N words, block delete, parameters,
functions, assignments, malformed lines) and on every line of the corpus
with its numbers replaced.
"""

from __future__ import annotations

import random
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import shapes
from nczones.gcode.parser import parse_line
from tests.corpus import CORPUS, corpus_programs


def _outcome(fn, line: str):
    try:
        return fn(line, 7, "t.ngc")
    except GcodeError as exc:
        return ("error", str(exc))


def _same(line: str) -> None:
    assert _outcome(shapes.parse_line_shaped, line) == _outcome(parse_line, line), repr(line)


literals = st.one_of(
    st.integers(0, 10**7).map(str),
    st.builds(lambda a, b: f"{a}.{b}", st.integers(0, 999), st.integers(0, 99999)),
    st.integers(0, 999).map(lambda a: f"{a}."),
    st.integers(0, 99999).map(lambda b: f".{b}"),
)
# pieces of a line; "§" is where a literal goes
pieces = st.sampled_from([
    "G§", "g§", "X§", "Y-§", "Z+§", "X- §", "F§", "X[#§ + §]", "Y[#§*-§]", "Z[#<depth> - §]", "X[COS[§] * §]",
    "Y[ATAN[§]/[§]]", "X[§ ** §]", "X[§ MOD §]", "X[-§]", "X[+§]", "X#§", "Y##§", "#§ = §", "#§=[#§ + §]",
    "#<_g§> = §", "#<v> = [§ / §]", "X[EXISTS[#<v>]]", " ", "\t", "", "S§ M§", "@§ ^§", "X[§ GT §]",
    # malformed or special: errors and shapes the cache must refuse
    "X[§ +]", "X§.§", "X", "E§", "END§", "DO§", "IF[§]", "#<x§> = §", "G§.§.§", "X[§ §]", "N§", "O§",
])


@st.composite
def shaped_lines(draw):
    """A line shape and several fillings of it (the first fills the cache)."""
    head = draw(st.sampled_from(["", "N§ ", "/", "/N§", "n§"]))
    shape = head + "".join(draw(st.lists(pieces, min_size=1, max_size=6)))
    n = shape.count("§")
    out = []
    for _ in range(3):
        parts = shape.split("§")
        lits = [draw(literals) for _ in range(n)]
        out.append("".join(p + (lits[k] if k < n else "") for k, p in enumerate(parts)))
    return out


@settings(max_examples=600, deadline=None, derandomize=True, database=None)
@given(shaped_lines())
def test_lines_of_one_shape_parse_as_the_parser_parses_them(lines):
    shapes.clear()
    for line in lines:
        _same(line)


def test_a_shape_that_is_not_a_function_of_its_literals_is_not_used():
    shapes.clear()
    for line in ("#<x1> = 2", "#<x2> = 3", "G1 X1 END.5", "G1 X1 END5", "X1.2.3", "X1.23.4"):
        _same(line)
    # names with digits, and the Fanuc END<n> test, make the shape unusable: parsed afresh
    assert shapes._SHAPES["#<x\x00> = \x00"] is shapes._NO_SHAPE


def test_cache_hits_are_rebuilt_not_reparsed(monkeypatch):
    shapes.clear()
    _same("N10 G1 X[#1 + 1.5] Y-2")
    calls = []
    real = shapes.parse_line

    def counting(*args):
        calls.append(args)
        return real(*args)

    monkeypatch.setattr(shapes, "parse_line", counting)
    for k in range(20):
        _same(f"N{k * 10} G1 X[#1 + {k}.25] Y-{k + 2}")
    assert calls == []


def _corpus_lines():
    out = []
    for rel, _dialect in corpus_programs():
        try:
            text = (CORPUS / rel).read_text(errors="replace")
        except OSError:
            continue
        out += [ln for ln in text.splitlines() if ln.isascii() and "(" not in ln and ";" not in ln
                and ("#" in ln or "[" in ln or len(out) % 50 == 0)]
    return out


_LIT = re.compile(r"\d+\.?\d*|\.\d+")


@pytest.mark.corpus
@pytest.mark.skipif(not (CORPUS / "MANIFEST.tsv").is_file(), reason="corpus not available")
def test_every_corpus_line_with_its_numbers_changed():
    """Each line primes its shape, then two variants with other numbers (same first character of each
    literal, so mostly the same shape; sometimes a point where a digit was) are parsed both ways."""
    rnd = random.Random(3)
    lines = _corpus_lines()
    assert len(lines) > 5000
    shapes.clear()
    for line in lines:
        _same(line)
        for _ in range(2):
            def other(m):
                t = m.group()
                if t[0] == "." or rnd.random() < 0.1:
                    return "." + str(rnd.randint(0, 9999))
                return str(rnd.randint(1, 99999)) + rnd.choice(["", ".", "." + str(rnd.randint(0, 999))])
            _same(_LIT.sub(other, line))


@pytest.mark.long
@settings(max_examples=5000, deadline=None, database=None)
@given(shaped_lines())
def test_lines_of_one_shape_long_fuzz(lines):
    """Opt-in (``-m long``): the generated-lines test above with random (not derandomized) examples."""
    for line in lines:
        _same(line)
