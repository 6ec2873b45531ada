"""nczones.plain_toml: the machine file's TOML without tomllib, for the plain subset (issue 36, start-up).

The oracle is ``tomllib.loads(text, parse_float=decimal.Decimal)``, what machine.py read before: where the
subset reader answers, tomllib must accept the text and give the same value, compared strictly (types, so
``True`` is not ``1``; a Decimal's digits as written, so ``1.50`` is not ``1.5``).  Texts are generated from
lines in the subset and just outside it (escapes, leading zeros, underscores, exponents, dates, redefined
tables, tables under arrays of tables or inline tables, arrays over two lines, carriage returns...).
"""

from __future__ import annotations

import decimal
import glob
import tomllib
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.plain_toml import loads

ROOT = Path(__file__).resolve().parents[1]


def strict(value):
    """``value`` with the type of every item and each Decimal's text, so that == compares them too."""
    if isinstance(value, dict):
        return ("dict", tuple((k, strict(v)) for k, v in value.items()))
    if isinstance(value, list):
        return ("list", tuple(strict(v) for v in value))
    if isinstance(value, decimal.Decimal):
        return ("Decimal", str(value))
    return (type(value).__name__, value)


def agrees(text: str) -> bool:
    """The subset reader's answer for ``text`` is tomllib's; True when it answered (not None)."""
    got = loads(text)
    if got is None:
        return False
    want = tomllib.loads(text, parse_float=decimal.Decimal)  # raises if the reader accepted an invalid text
    assert strict(got) == strict(want), text
    return True


def test_the_shipped_machine_files():
    files = sorted({*glob.glob(str(ROOT / "specs/**/*.toml"), recursive=True),
                    *glob.glob(str(ROOT / "tests/machines/**/*.toml"), recursive=True),
                    *glob.glob(str(ROOT / "examples/**/*.toml"), recursive=True)})
    read = 0
    for f in files:
        text = Path(f).read_text(encoding="utf-8")
        try:
            tomllib.loads(text, parse_float=decimal.Decimal)
        except tomllib.TOMLDecodeError:
            assert loads(text) is None, f
            continue
        read += agrees(text)
    assert read >= 0.8 * len(files) and read >= 50  # the machine files keep to the subset, mostly


KEYS = st.sampled_from(["a", "b", "X", "min", "max", "name", "tool_lengths", "H1", "z-1", "a_b"])
PLAIN = st.sampled_from(['"text"', '"15000"', '"-0.5"', '""', '"a # b"', '"tab\there"', '"é ü"', "0", "7", "-3",
                         "+12", "1.5", "-0.250", "+0.0", "1.50", "-0", "true", "false"])
SCALARS = st.one_of(PLAIN, PLAIN, PLAIN, st.sampled_from([
    '"esc\\"q"', "'literal'", '"bad\x01"', "007", "-01", "00", "1_000", "1.", ".5", "1e3", "1.5E-2", "inf", "nan",
    "True", "1979-05-27", "07:32:00", "0x1F", "1979-05-27T07:32:00Z", "01.5", "1.5.2", "--1", "truex"]))


def values(depth: int = 2):
    if depth == 0:
        return SCALARS
    inner = values(depth - 1)
    arrays = st.lists(inner, max_size=4).flatmap(lambda items: st.sampled_from([
        "[" + ", ".join(items) + "]", "[" + ",".join(items) + ",]" if items else "[,]", "[ " + " , ".join(items) + " ]",
        "[" + ", ".join(items) + "\n]"]))
    tables = st.lists(st.tuples(KEYS, inner), max_size=3).flatmap(lambda kv: st.sampled_from([
        "{ " + ", ".join(f"{k} = {v}" for k, v in kv) + " }", "{" + ",".join(f"{k}={v}" for k, v in kv) + ",}",
        "{" + ", ".join(f"{k} = {v}" for k, v in kv) + "}"]))
    return st.one_of(inner, arrays, tables)


HEADERS = st.sampled_from(["[a]", "[b]", "[a.b]", "[a.b.c]", "[b.a]", "[[a]]", "[[zones]]", "[zones]",
                           "[zones.x]", "[[a.b]]", "[ a ]", "[a] # c", "[\"a\"]", "[a]]", "[[a]", "[min]"])
LINES = st.one_of(
    HEADERS,
    st.tuples(KEYS, values(), st.sampled_from(["", "  # note", "#", "\t", " # \x7f"])).map(
        lambda t: f"{t[0]} = {t[1]}{t[2]}"),
    st.tuples(KEYS, values()).map(lambda t: f"  {t[0]}={t[1]}"),
    st.sampled_from(["", "# comment", "   ", "a.b = 1", '"a" = 1', "a =", "= 1", "a = 1 2", "a = 1\r", "\ufeffa = 1"]),
)


@settings(max_examples=400, deadline=None)
@given(st.lists(LINES, max_size=12))
def test_generated_texts(lines):
    agrees("\n".join(lines))


def test_the_rules_a_line_by_line_reader_could_miss():
    # tomllib's errors (the subset reader must not answer) and near misses it accepts (the same value or None)
    for text in ("a = {x = 1}\n[a.b]", "[a]\nb = {c = 1}\n[a.b]", "a = {x = 1}\n[a]", "a = 007", "a = -01",
                 "a = [1,\n2]", "[a]\n[a]", "a = 1\n[a]", "[a.b]\n[a]\nb = 1", "a = 1\na = 2", "[[a]]\n[a]",
                 "a = [1]\n[[a]]", "[a]\n[[a]]", "x = { a = 1, a = 2 }", "x = { a = 1, }", "a = [,]", "a = 1.",
                 "a = .5", 'a = "x\x01"', "a = 1 # \x7f", "[a]]", "a = truex", "a = 1.5.2"):
        try:
            tomllib.loads(text, parse_float=decimal.Decimal)
        except tomllib.TOMLDecodeError:
            assert loads(text) is None, text
        else:
            agrees(text)


def test_subset_texts_are_read():
    # what the machine files write is read without tomllib (else the start-up gains nothing)
    text = ('# a mill\n[machine]\nname = "m"\naxes = ["X", "Y", "Z"]\npulse = "0.001"\n\n[machine.rapid]\n'
            'X = "15000"\n[offsets]\nG54 = { X = "150", Y = "100" }\n[[zones]]\nname = "travel"\nkind = "box"\n'
            'min = { X = "0", Y = -1.50 }\nforbid = true\nvertices = [["0", "0"], ["1", "0"], ]\n[[zones]]\n'
            'name = "two"\n[tool_lengths]\nH1 = 120\n')
    assert agrees(text)
