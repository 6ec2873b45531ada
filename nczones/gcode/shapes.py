"""Parse a line by its shape: lines that differ only in their numbers are parsed once.

Macro-style programs repeat a few line shapes with different numbers
(``G1 X[#1 + 12.5] Y[#2 + 3.25]``, ``N120Y[#<yscale>*-56.12]``).  A line's
*shape* is its text with every unsigned number literal replaced by a
placeholder that records only whether the literal starts with a digit or a
point.  Every decision of the parser (:mod:`nczones.gcode.parser`) reads
letters, signs, brackets, blanks and that first character, never the other
digits, and a literal only ever becomes a ``NUM`` leaf; so the parse of a line
is the parse of any earlier line of the same shape with the leaves made from
its own literals and the columns moved by the difference in literal lengths.

:func:`parse_line_shaped` keeps one compiled rebuild function per shape (at
most :data:`MAX_SHAPES`).  A shape is only used when its first line's parse
satisfies the reasoning above, checked: the parser read exactly one number per
literal, at the literal (or at a sign right before it), and the rebuild of that
first line equals its parse.  Lines with comments, non-ASCII text, O words,
Fanuc macro statements or a parse error are always parsed afresh, and every
error comes from the parser itself.

Invariant
---------
``parse_line_shaped(line, n, f) == parse_line(line, n, f)`` for every line,
whatever lines came before (``tests/gcode/test_shapes.py``: generated lines and
every line of the corpus with its numbers changed).
"""

from __future__ import annotations

import re

from .lexer import plain_decimal_value
from .parser import NUM, ParsedLine, _Parser, parse_line

__all__ = ["parse_line_shaped", "MAX_SHAPES"]

#: Shapes kept (the table is emptied when full: memory does not grow with the program).
MAX_SHAPES = 4096
_LITERAL = re.compile(r"(\d+\.?\d*|\.\d+)")  # the unsigned part of the parser's number
_FIRST_CHAR = str.maketrans("0123456789", "dddddddddd")
_SHAPES: dict[str, object] = {}
_NO_SHAPE = object()  # parse lines of this shape afresh


def parse_line_shaped(line: str, lineno: int, file: str) -> ParsedLine:
    """:func:`~nczones.gcode.parser.parse_line`, rebuilt from an earlier line of the same shape when possible.

    >>> a = parse_line_shaped("G1 X[#1 + 1.5] Y-2", 1, "p")
    >>> b = parse_line_shaped("G1 X[#1 + 12.25] Y-.5", 2, "p")  # same shape (the '.5' starts with a point)
    >>> b == parse_line("G1 X[#1 + 12.25] Y-.5", 2, "p")
    True
    """
    if "(" in line or ";" in line or not line.isascii():
        return parse_line(line, lineno, file)
    parts = _LITERAL.split(line)
    literals = parts[1::2]
    key = "\x00".join(parts[0::2]) + "\x01" + "".join([t[0] for t in literals]).translate(_FIRST_CHAR)
    shape = _SHAPES.get(key)
    if shape is None:
        pl = parse_line(line, lineno, file)  # raises the parser's own errors
        if len(_SHAPES) >= MAX_SHAPES:
            _SHAPES.clear()
        _SHAPES[key] = _compile(line, parts, pl)
        return pl
    if shape is _NO_SHAPE:
        return parse_line(line, lineno, file)
    return shape(parts, line)


def _compile(line: str, parts: list[str], pl: ParsedLine):
    """The rebuild function of the shape of ``line`` (parsed as ``pl``), or _NO_SHAPE."""
    if pl.oword is not None or pl.unsupported is not None or pl.percent or pl.comments:
        return _NO_SHAPE
    # raw spans of the literals
    spans = []
    pos = 0
    for k, text in enumerate(parts):
        if k % 2:
            spans.append((pos, pos + len(text)))
        pos += len(text)
    # which number the parser read where, in raw columns
    p = _Recording(line)
    p.numbers = []
    try:
        mine = p.parse()
    except Exception:  # noqa: BLE001  # the parser disagrees with itself: no shape
        return _NO_SHAPE
    if mine != pl:
        return _NO_SHAPE
    pl = mine  # the trees whose NUM nodes were noted (by identity)
    numbers = p.numbers
    if len(numbers) != len(spans):
        return _NO_SHAPE
    leaf_of: dict[int, str] = {}  # id(node) -> the source of its rebuilt leaf
    for k, ((a, b, node), (la, lb)) in enumerate(zip(numbers, spans)):
        if b != lb:
            return _NO_SHAPE
        if a == la:
            leaf_of[id(node)] = f"_num(P[{2 * k + 1}])"
        elif a < la and line[a] in "+-" and not line[a + 1:la].strip(" \t"):
            leaf_of[id(node)] = f"_num({line[a]!r} + P[{2 * k + 1}])"
        else:
            return _NO_SHAPE
    ends = [b for _a, b in spans]

    def at(col0: int) -> str:
        """Source of a raw 0-based position of this line moved to the rebuilt line."""
        k = sum(1 for e in ends if e <= col0)
        return f"{col0}+D[{k}]" if k else f"{col0}"

    try:
        words = []
        for letter, tree, col, end, text in pl.words:
            s0, e0 = col - 1, end - 1
            if line[s0:e0] != text:
                return _NO_SHAPE
            words.append(f"({letter!r}, {_tree(tree, leaf_of)}, {at(s0)}+1, {at(e0)}+1, line[{at(s0)}:{at(e0)}])")
        assigns = [f"({_tree(t, leaf_of)}, {_tree(v, leaf_of)}, {at(c - 1)}+1, {at(e - 1)}+1)"
                   for t, v, c, e in pl.assigns]
    except _Unshaped:
        return _NO_SHAPE
    if pl.number is None:
        number_src = "None"
    elif numbers and numbers[0][2][2] == pl.number and id(numbers[0][2]) in leaf_of:
        number_src = leaf_of[id(numbers[0][2])] + "[2]"
    else:
        return _NO_SHAPE
    # D[k]: how much longer the first k literals are than in the first line of the shape
    lines = ["def rebuild(P, line):", "    D = [0]"]
    lines += [f"    D.append(D[-1] + len(P[{2 * k + 1}]) - {b - a})" for k, (a, b) in enumerate(spans)]
    lines.append(f"    return _parsed_line({pl.delete!r}, {number_src}, ({''.join(w + ', ' for w in words)}), "
                 f"({''.join(a + ', ' for a in assigns)}))")
    src = "\n".join(lines) + "\n"
    scope = {"_parsed_line": _parsed_line, "_num": _num}
    exec(compile(src, "<line shape>", "exec"), scope)  # noqa: S102  # built only from reprs of str/int/bool
    rebuild = scope["rebuild"]
    if rebuild(parts, line) != pl:
        return _NO_SHAPE
    return rebuild


class _Unshaped(Exception):
    pass


_PL_SETTERS = tuple(getattr(ParsedLine, f).__set__ for f in (
    "delete", "number", "oword", "words", "assigns", "comments", "percent", "unsupported"))


def _parsed_line(delete: bool, number, words: tuple, assigns: tuple) -> ParsedLine:
    """``ParsedLine(delete, number, None, words, assigns)`` without the frozen-dataclass overhead (an
    ordinary, equal ParsedLine; the rebuild of every shape is checked against the parser's own)."""
    pl = _new(ParsedLine)
    sd, sn, so, sw, sa, sc, sp, su = _PL_SETTERS
    sd(pl, delete)
    sn(pl, number)
    so(pl, None)
    sw(pl, words)
    sa(pl, assigns)
    sc(pl, ())
    sp(pl, False)
    su(pl, None)
    return pl


_new = object.__new__


class _Recording(_Parser):
    """The parser, noting the raw span and node of every number it reads."""

    __slots__ = ("numbers",)

    def number(self, i: int):
        node, j = _Parser.number(self, i)
        self.numbers.append((self.cols[i], self.cols[j - 1] + 1, node))
        return node, j


def _tree(node, leaf_of: dict[int, str]) -> str:
    """Python source rebuilding an expression tree, its NUM leaves from the literals."""
    if type(node) is not tuple:
        if node is None or type(node) in (str, int, bool):
            return repr(node)
        raise _Unshaped
    if node and node[0] == NUM:
        src = leaf_of.get(id(node))
        if src is None:
            raise _Unshaped
        return src
    return "(" + "".join(_tree(t, leaf_of) + ", " for t in node) + ")"


def _num(text: str) -> tuple:
    """The NUM leaf of a literal (an optional sign, digits, at most one point, no blanks), as the parser makes it.

    Long literals are mostly distinct (coordinates): they skip the reader's cache, whose misses cost more
    than the reading itself.
    """
    return (NUM, float(text), plain_decimal_value(text) if len(text) < 5 else _decimal_uncached(text))


_decimal_uncached = plain_decimal_value.__wrapped__
