"""Lexing G-code lines: exact decimal literals, comments, spans, fast path.

Every source line goes through :func:`scan_simple` first: one compiled regular
expression recognises the lines that make up nearly all of a CAM program
(optional ``/``, optional ``N``, words whose values are plain decimal
literals, ``( )`` comments and a trailing ``;`` comment) and returns their
words directly.  Anything else (parameters, ``[...]`` expressions, O-words,
assignments, errors) returns ``None`` and goes to the full line parser in
:mod:`nczones.gcode.parser`.

Numbers follow LinuxCNC: an optional sign, digits with an optional decimal
point (``5``, ``+5``, ``-.5``, ``5.``), no exponent; blanks between the
letter and the number and between digits are ignored (``X1 2.5`` is
``X12.5``).  Decimal literals become exact :class:`~fractions.Fraction`
values by integer arithmetic and never pass through a float:

>>> decimal_value("-1 2.50")
Fraction(-25, 2)
>>> decimal_value(".5")
Fraction(1, 2)
"""

from __future__ import annotations

import re
from fractions import Fraction
from functools import lru_cache
from math import gcd as _gcd

from ..errors import SourceSpan
from ..frozen import builder
from .blocks import Block, Word

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = [
    "NUMBER",
    "decimal_value",
    "make_span",
    "make_word",
    "scan_simple",
    "scan_plain",
    "plain_control",
    "PlainBlock",
    "MAGIC_COMMENTS",
    "magic_comment",
]

_DIGITS = r"\d(?:[ \t]*\d)*"
#: A LinuxCNC number: sign, digits, optional point and digits; blanks between digits allowed.
NUMBER = rf"[+-]?[ \t]*(?:{_DIGITS}(?:[ \t]*\.(?:[ \t]*\d)*)?|\.[ \t]*{_DIGITS})"

# O and N are positional and go through the full parser (N is accepted here only first).
_PLAIN_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)"
# The common case: no blanks inside numbers (one quick regex), then the general simple line.
_FAST_LINE = re.compile(
    rf"[ \t]*(/[ \t]*)?(?:[Nn][ \t]*({_PLAIN_NUMBER})[ \t]*)?"
    rf"(?:(?:[A-MP-Za-mp-z][ \t]*{_PLAIN_NUMBER}|\([^()]*\))[ \t]*)*(?:;.*)?"
)
_FAST_ITEMS = re.compile(rf"([ \t]*)(?:\(([^()]*)\)|(;.*)|([A-MP-Za-mp-z])([ \t]*)({_PLAIN_NUMBER}))")
_SIMPLE_LINE = re.compile(
    rf"[ \t]*(/[ \t]*)?(?:[Nn][ \t]*({NUMBER})[ \t]*)?"
    rf"(?:(?:[A-MP-Za-mp-z][ \t]*{NUMBER}|\([^()]*\))[ \t]*)*(?:;.*)?"
)
_SIMPLE_ITEM = re.compile(rf"\(([^()]*)\)|;(.*)|([A-MP-Za-mp-z])[ \t]*({NUMBER})")
_BLANKS = re.compile(r"[ \t]+")
# A plain line: words with plain decimal literals and blanks between them, no comment (scan_plain).
_PLAIN_SPLIT = re.compile(rf"([A-NP-Za-np-z])[ \t]*({_PLAIN_NUMBER})")


def fraction_raw(n: int, d: int) -> Fraction:
    """Fraction(n, d) for d > 0 without the generic constructor (5x faster)."""
    g = _gcd(n, d)
    q = _new(Fraction)
    q._numerator = n // g  # type: ignore[attr-defined]
    q._denominator = d // g  # type: ignore[attr-defined]
    return q


def _fraction_safe(n: int, d: int) -> Fraction:
    return Fraction(n, d)


def _double_raw(x: float) -> Fraction:
    """``Fraction(x)`` for a finite double (its ratio is already in lowest terms)."""
    n, d = x.as_integer_ratio()
    q = _new(Fraction)
    q._numerator = n  # type: ignore[attr-defined]
    q._denominator = d  # type: ignore[attr-defined]
    return q


_new = object.__new__
try:  # relies on CPython's Fraction slots; verified here, else the public constructor
    _f = fraction_raw(-25, 10)
    to_fraction = fraction_raw if (_f == Fraction(-5, 2) and hash(_f) == hash(Fraction(-5, 2))
                                  and _f.denominator == 2) else _fraction_safe
except Exception:  # noqa: BLE001  # pragma: no cover
    to_fraction = _fraction_safe
to_double = _double_raw if to_fraction is fraction_raw else Fraction


@lru_cache(maxsize=8192)  # bounded: memory must not grow with the program
def decimal_value(text: str) -> Fraction:
    """The exact value of a LinuxCNC number literal (blanks allowed between digits).

    Integer arithmetic only, so the result is the decimal exactly as written.

    >>> decimal_value("5.")
    Fraction(5, 1)
    >>> decimal_value("+0.100")
    Fraction(1, 10)
    """
    t = _BLANKS.sub("", text) if (" " in text or "\t" in text) else text
    negative = t[0] == "-"
    if t[0] in "+-":
        t = t[1:]
    whole, _point, frac = t.partition(".")
    n = int(whole + frac) if (whole or frac) else 0
    return to_fraction(-n if negative else n, 10 ** len(frac))


@lru_cache(maxsize=8192)  # bounded, as above
def plain_decimal_value(text: str) -> Fraction:
    """:func:`decimal_value` for a literal without blanks (``[+-]digits[.digits]``, the plain lane's numbers).

    >>> plain_decimal_value("-.25"), plain_decimal_value("+7.")
    (Fraction(-1, 4), Fraction(7, 1))
    """
    whole, _point, frac = text.partition(".")
    return to_fraction(int(whole + frac), _POW10[len(frac)] if len(frac) < 24 else 10 ** len(frac))


_POW10 = tuple(10**k for k in range(24))


#: ``SourceSpan(file, line, column, end_column, text)``, built 2x faster (see :mod:`nczones.frozen`): the
#: lexer and the runner make one span per block and per word read.
make_span = builder(SourceSpan, name="make_span")
#: ``Word(letter, value, span, text)``, built faster (see :mod:`nczones.frozen`).
make_word = builder(Word, name="make_word")
_word_letter = Word.letter.__set__  # type: ignore[attr-defined, misc]  # for _LazyWord
_word_value = Word.value.__set__  # type: ignore[attr-defined, misc]
_word_text = Word.text.__set__  # type: ignore[attr-defined, misc]


class _LazyWord(Word):
    """A :class:`Word` whose span is built only when read (diagnostics, reports).

    The lexer makes one word per literal; building its SourceSpan eagerly cost
    a third of the lexing time, and almost no span is ever read.  It is a
    Word for ``isinstance``, ``repr`` and equality (equal to the eager Word).
    """

    __slots__ = ("_at",)
    __qualname__ = "Word"
    _at: Any

    @property
    def span(self) -> SourceSpan:
        at = self._at
        if type(at) is tuple:
            (file, lineno, line), col, end = at
            if end < 0:  # (start, -1 - k): the k-th item of the line after start, columns not yet known
                col, end = _item_columns(line, col, -1 - end)
            at = make_span(file, lineno, col, end, line)
            object.__setattr__(self, "_at", at)
        built: SourceSpan = at
        return built

    @span.setter
    def span(self, value: SourceSpan) -> None:
        object.__setattr__(self, "_at", value)


_lazy_at = _LazyWord._at.__set__  # type: ignore[misc]


def _item_columns(line: str, start: int, k: int) -> tuple[int, int]:
    """1-based (column, end column) of the k-th ``_FAST_ITEMS`` item of ``line`` after ``start``."""
    pos = start
    for j, (blanks, comment, _semi, letter, gap, num) in enumerate(_FAST_ITEMS.findall(line, start)):
        pos += len(blanks)
        end = pos + len(comment) + 2 if comment or not letter else pos + 1 + len(gap) + len(num)
        if j == k:
            return pos + 1, end + 1
        pos = end
    raise AssertionError("item index beyond the line")  # pragma: no cover


#: Comment keywords LinuxCNC gives a meaning to (``(MSG, ...)`` and friends).
MAGIC_COMMENTS = ("MSG", "DEBUG", "PRINT", "LOGOPEN", "LOGAPPEND", "LOGCLOSE", "LOG", "PROBEOPEN", "PROBECLOSE", "ABORT")
_MAGIC = re.compile(r"[ \t]*(" + "|".join(MAGIC_COMMENTS) + r")[ \t]*(,|\Z)", re.IGNORECASE)


def magic_comment(body: str) -> tuple[str, str] | None:
    """``(KEYWORD, text)`` if a comment body is a magic comment, else None.

    >>> magic_comment("msg, Insert tool 3")
    ('MSG', ' Insert tool 3')
    >>> magic_comment("just a note") is None
    True
    """
    m = _MAGIC.match(body)
    if m is None:
        return None
    return m.group(1).upper(), body[m.end():]


def scan_simple(line: str, lineno: int, file: str) -> tuple | None:
    """Lex a line made only of literal words and comments, else return None.

    Returns ``(delete, number, words, comments)``: whether the line starts with
    ``/``, the N value (or None), the words with exact values and spans, and
    the ``( )`` comment bodies with their 1-based columns.

    >>> delete, number, words, comments = scan_simple("/N10 g1x-.5 (cut) Y 2.", 7, "p.ngc")
    >>> delete, number, [(w.letter, w.value, w.text) for w in words], comments
    (True, Fraction(10, 1), [('G', Fraction(1, 1), 'g1'), ('X', Fraction(-1, 2), 'x-.5'), ('Y', Fraction(2, 1), 'Y 2.')], (('cut', 13),))
    >>> str(words[1].span), words[1].span.end_column
    ('p.ngc:7:8', 12)
    >>> scan_simple("G1 X[1+2]", 1, "p") is None
    True
    """
    m = _FAST_LINE.fullmatch(line)
    if m is None:
        return _scan_blanks(line, lineno, file)
    ntext = m.group(2)
    number = decimal_value(ntext) if ntext is not None else None
    words: list[Word] = []
    comments: list[tuple[str, int]] = []
    pos = m.end(2) if ntext is not None else (m.end(1) if m.group(1) is not None else 0)
    where = (file, lineno, line)
    if "(" not in line and ";" not in line:
        # words only: columns are computed when a span is read (_item_columns)
        start = pos
        k = 0
        for _blanks, _comment, _semi, letter, gap, num in _FAST_ITEMS.findall(line, pos):
            w = _new(_LazyWord)
            _word_letter(w, letter.upper())
            _word_value(w, decimal_value(num))
            _lazy_at(w, (where, start, -1 - k))
            _word_text(w, letter + gap + num if gap else letter + num)
            words.append(w)
            k += 1
        return (m.group(1) is not None, number, tuple(words), ())
    for blanks, comment, semi, letter, gap, num in _FAST_ITEMS.findall(line, pos):
        pos += len(blanks)
        if letter:
            end = pos + 1 + len(gap) + len(num)
            w = _new(_LazyWord)
            _word_letter(w, letter.upper())
            _word_value(w, decimal_value(num))
            _lazy_at(w, (where, pos + 1, end + 1))
            _word_text(w, line[pos:end])
            words.append(w)
            pos = end
        elif semi:
            break
        else:
            comments.append((comment, pos + 1))
            pos += len(comment) + 2
    return (m.group(1) is not None, number, tuple(words), tuple(comments))


def scan_plain(line: str) -> tuple | None:
    """Lex a line of plain words (no comment, no blank inside a number), else None.

    Returns ``(delete, number, letters, values)``: whether the line starts
    with ``/``, the N value (or None), the upper-case letters as one string
    and their exact values.  This is the language layer's cheapest lane; the
    words (with text and spans) are made from the line only if somebody
    reads them (:class:`PlainBlock`).

    >>> scan_plain("n20 g1x-.5 Y2.")
    (False, Fraction(20, 1), 'GXY', (Fraction(1, 1), Fraction(-1, 2), Fraction(2, 1)))
    >>> scan_plain("G1 X1 (cut)") is None
    True
    """
    if to_fraction is not fraction_raw:  # pragma: no cover - a Python whose Fraction has other slots
        return None
    parts = _PLAIN_SPLIT.split(line)
    delete = False
    head = parts[0]
    if head and head.strip(" \t"):
        if head.strip(" \t") != "/":
            return None
        delete = True
    if len(parts) > 3 and "".join(parts[3::3]).strip(" \t"):
        return None
    letters = "".join(parts[1::3]).upper()
    values = tuple(map(plain_decimal_value, parts[2::3]))
    number = None
    if "N" in letters:
        if letters[0] != "N" or "N" in letters[1:]:
            return None
        number = values[0]
        letters = letters[1:]
        values = values[1:]
    return (delete, number, letters, values)


def plain_control(letters: str, values: tuple) -> bool:
    """Whether a plain line holds a word the language layer acts on (M2 M30 M97 M98 M99, G65-G67, G70-G72).

    >>> plain_control("GXM", (Fraction(1), Fraction(2), Fraction(98)))
    True
    >>> plain_control("GXM", (Fraction(66, 10), Fraction(2), Fraction(3)))
    False
    """
    i = letters.find("M")
    while i >= 0:
        v = values[i]
        if v._denominator == 1 and v._numerator in M_CONTROL:
            return True
        i = letters.find("M", i + 1)
    i = letters.find("G")
    while i >= 0:
        v = values[i]
        if 65 <= v._numerator // v._denominator <= 67 or 70 <= v._numerator // v._denominator <= 72:
            return True  # G65-G67 macro calls, G70-G72 lathe cycles that read a subroutine
        i = letters.find("G", i + 1)
    return False


M_CONTROL = frozenset((2, 30, 97, 98, 99))  # M codes the language layer acts on
G_MACRO_CALLS = frozenset((Fraction(65), Fraction(66), Fraction(661, 10), Fraction(67)))  # G65 G66 G66.1 G67


class PlainBlock(Block):
    """A :class:`Block` of a plain line whose words are made only when read.

    ``letters`` (one string) and ``values`` are what the interpreter's
    plain-move lane needs; ``words`` (with spans and text, for diagnostics and the general
    path) are lexed from the line on first read.  Equal to the eager Block.
    """

    __slots__ = ("letters", "values", "_words")
    letters: str
    values: tuple[Any, ...]
    _words: Any

    @property
    def words(self) -> tuple[Word, ...]:
        words = self._words
        if words is None:
            span = self.span
            scanned = scan_simple(span.text, span.line, span.file)
            assert scanned is not None  # a plain block's line is simple
            words = scanned[2]
            _block_words(self, words)
        elif type(words) is list:  # evaluated words: (letter, value, column, end column, text) each
            span = self.span
            file, line, text = span.file, span.line, span.text
            words = tuple([make_word(w[0], w[1], make_span(file, line, w[2], w[3], text), w[4]) for w in words])
            _block_words(self, words)
        elif type(words) is not tuple:  # evaluated by a line's compiled code: ask it for the columns
            span = self.span
            file, line, text = span.file, span.line, span.text
            words = tuple([make_word(letter, value, make_span(file, line, c[0], c[1], text), c[2])
                           for letter, value, c in zip(self.letters, self.values, words.columns(words.parts, text))])
            _block_words(self, words)
        made: tuple[Word, ...] = words
        return made

    @words.setter
    def words(self, words: tuple[Word, ...]) -> None:  # Block.__init__ (dataclasses.replace): an eager block
        _block_words(self, words)
        _block_letters(self, "")
        _block_values(self, ())


_block_words = PlainBlock._words.__set__  # type: ignore[misc]
_block_letters = PlainBlock.letters.__set__  # type: ignore[attr-defined, misc]
_block_values = PlainBlock.values.__set__  # type: ignore[attr-defined, misc]
_block_span = Block.span.__set__  # type: ignore[attr-defined, misc]
_block_index = Block.index.__set__  # type: ignore[attr-defined, misc]
_block_number = Block.number.__set__  # type: ignore[misc, union-attr]
_block_messages = Block.messages.__set__  # type: ignore[attr-defined, misc]


def plain_block(letters: str, values: tuple[Any, ...], span: SourceSpan, index: int, number: Fraction | None,
                words: Any = None) -> PlainBlock:
    """A :class:`PlainBlock` built without the frozen-dataclass overhead (``words``: how its words are
    made when read, see :attr:`PlainBlock.words`; None: lexed from the line)."""
    b = _new(PlainBlock)
    _block_letters(b, letters)
    _block_values(b, values)
    _block_words(b, words)
    _block_span(b, span)
    _block_index(b, index)
    _block_number(b, number)
    _block_messages(b, ())
    return b


def plain_block_of(words: list[tuple[Any, ...]], span: SourceSpan, index: int, number: Fraction | None) -> PlainBlock:
    """A :class:`PlainBlock` of evaluated words ``(letter, value, column, end column, text)``: the plain
    lane reads their letters and values; the :class:`Word` objects are made only when read.

    >>> b = plain_block_of([("G", Fraction(1), 1, 3, "G1"), ("X", Fraction(5, 2), 4, 10, "X[5/2]")],
    ...                    SourceSpan("p", 1, 1, 10, "G1 X[5/2]"), 0, None)
    >>> b.letters, b.values, [(w.text, str(w.span)) for w in b.words]
    ('GX', (Fraction(1, 1), Fraction(5, 2)), [('G1', 'p:1:1'), ('X[5/2]', 'p:1:4')])
    """
    b = plain_block("".join([w[0] for w in words]), tuple([w[1] for w in words]), span, index, number)
    _block_words(b, words)
    return b


def _scan_blanks(line: str, lineno: int, file: str) -> tuple | None:
    """:func:`scan_simple` for lines with blanks inside numbers (``X1 2.5``)."""
    m = _SIMPLE_LINE.fullmatch(line)
    if m is None:
        return None
    delete = m.group(1) is not None
    ntext = m.group(2)
    number = decimal_value(ntext) if ntext is not None else None
    words: list[Word] = []
    comments: list[tuple[str, int]] = []
    start = m.end(2) if ntext is not None else 0
    for item in _SIMPLE_ITEM.finditer(line, start):
        letter = item.group(3)
        if letter is not None:
            b = item.start()
            e = item.end()
            words.append(make_word(letter.upper(), decimal_value(item.group(4)),
                                   make_span(file, lineno, b + 1, e + 1, line), line[b:e]))
        elif item.group(1) is not None:
            comments.append((item.group(1), item.start() + 1))
    return (delete, number, tuple(words), tuple(comments))
