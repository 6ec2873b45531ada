"""The full line parser: LinuxCNC RS274/NGC syntax with spans.

:func:`parse_line` turns one source line into a :class:`ParsedLine`
(block delete, N, O-word, words whose values are expression trees,
parameter assignments, comments) without evaluating anything; evaluation
happens when the line is executed (:mod:`nczones.gcode.expr`,
:mod:`nczones.gcode.program`).  Plain lines normally take the regex fast path
in :mod:`nczones.gcode.lexer`; this parser handles everything else and
produces the diagnostics.

Like LinuxCNC, blanks outside comments are insignificant (``G 1 X 1 2`` is
``G1 X12``) and letters are case-insensitive; the parser works on the line
with blanks removed and lower-cased outside comments and keeps a map back to
the original columns for spans.

Expression trees are tuples whose first item is a tag:

``(NUM, float, Fraction)``, ``(PAR, index_tree)``, ``(NPAR, name)``,
``(NEG, tree)``, ``(BIN, op, left, right)``, ``(FN, name, tree)``,
``(ATAN, y, x)``, ``(EXISTS, parameter_tree)``.

Operator precedence (LinuxCNC ``Interp::precedence``), all left-associative:
``**`` 6; ``* / MOD`` 5; ``+ -`` 4; ``EQ NE GT GE LT LE`` 3; ``AND OR XOR`` 2.

>>> pl = parse_line("N5 G1 X[1 + 2 * #3] (cut)", 4, "p.ngc")
>>> pl.number, [w[0] for w in pl.words], pl.comments
(Fraction(5, 1), ['G', 'X'], (('cut', 21),))
>>> pl.words[1][1][0] == BIN
True
"""

from __future__ import annotations

import re
from fractions import Fraction

from ..errors import Diagnostic, GcodeError, SourceSpan
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)
from .lexer import decimal_value

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, NoReturn

__all__ = [
    "NUM", "PAR", "NPAR", "NEG", "BIN", "FN", "ATAN", "EXISTS",
    "OWord", "ParsedLine", "parse_line", "LineSyntaxError", "O_KEYWORDS", "FUNCTIONS",
]

NUM, PAR, NPAR, NEG, BIN, FN, ATAN, EXISTS = range(8)

#: Unary functions LinuxCNC knows (ATAN takes two bracketed arguments, EXISTS a parameter).
FUNCTIONS = frozenset(
    ("abs", "acos", "asin", "atan", "cos", "exp", "exists", "fix", "fup", "ln", "round", "sin", "sqrt", "tan")
)
#: O-word keywords.
O_KEYWORDS = frozenset(
    ("sub", "endsub", "call", "return", "do", "while", "endwhile", "if", "elseif", "else", "endif",
     "break", "continue", "repeat", "endrepeat")
)
_NEEDS_CONDITION = frozenset(("if", "elseif", "while", "repeat"))
_OPTIONAL_VALUE = frozenset(("return", "endsub"))

PRECEDENCE = {
    "**": 6, "*": 5, "/": 5, "mod": 5, "+": 4, "-": 4,
    "eq": 3, "ne": 3, "gt": 3, "ge": 3, "lt": 3, "le": 3,
    "and": 2, "or": 2, "xor": 2,
}

_TOKENS = re.compile(r"\([^)\n]*\)?|;.*|[^ \t\r\n]")
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)")
_NAME = re.compile(r"[a-z]+")
_WORD_OP = re.compile(r"mod|and|xor|or|eq|ne|gt|ge|lt|le")
_FANUC_MACRO = re.compile(r"(?:if\[|if#|goto|then|while\[|end\d|do\d)")
_INT_LABEL = re.compile(r"\d+")


def _word_name(s: str, i: int) -> str:
    """The run of letters at ``i`` (empty when there is none)."""
    m = _NAME.match(s, i)
    return m.group() if m is not None else ""


@dataclass(frozen=True, slots=True)
class OWord:
    """An O-word: ``label`` is an int (``o100``) or a lower-case name (``o<foo>``).

    ``keyword`` is one of :data:`O_KEYWORDS`, or None for a Fanuc program
    number line (``O1000``).  ``args`` are the expression trees after the
    keyword (call arguments, the condition, the return value).
    """

    label: int | str | tuple
    keyword: str | None
    args: tuple
    column: int
    end_column: int

    @property
    def display(self) -> str:
        return f"o<{self.label}>" if isinstance(self.label, str) else f"o{self.label}"


@dataclass(frozen=True, slots=True)
class ParsedLine:
    """One parsed, not yet executed line.

    ``words``: ``(letter, tree, column, end_column, text)``;
    ``assigns``: ``(target_tree, value_tree, column, end_column)``, target a
    ``PAR`` or ``NPAR`` tree; ``comments``: ``(body, column)``;
    ``unsupported``: ``(reason, column, end_column)`` for a Fanuc macro
    statement the language layer does not model (raised when executed).
    """

    delete: bool = False
    number: Fraction | None = None
    oword: OWord | None = None
    words: tuple = ()
    assigns: tuple = ()
    comments: tuple = ()
    percent: bool = False
    unsupported: tuple | None = None


class LineSyntaxError(Exception):
    """Internal: one syntax error at compressed positions (converted to a Diagnostic)."""

    def __init__(self, code: str, message: str, start: int, end: int | None = None):
        super().__init__(message)
        self.code, self.message, self.start, self.end = code, message, start, end


def _compress(line: str) -> tuple[str, list[int]]:
    """The line's code without blanks, lower case, comments kept as written and ``;...`` dropped, with
    the 0-based source column of every character (and, last, the line's length without its end).

    >>> _compress("G1 x2 (Cut) ; rest")
    ('g1x2(Cut)', [0, 1, 3, 4, 6, 7, 8, 9, 10, 18])
    """
    parts: list[str] = []
    cols: list[int] = []
    for m in _TOKENS.finditer(line):
        tok = m.group()
        if tok[0] == ";":
            break
        if tok[0] == "(" and len(tok) > 1:
            parts.append(tok)
            cols.extend(range(m.start(), m.end()))
        else:
            parts.append(tok.lower())
            cols.append(m.start())
    cols.append(len(line.rstrip("\r\n")))
    return "".join(parts), cols


class Parser:
    __slots__ = ("s", "cols", "n", "line")

    def __init__(self, line: str):
        self.line = line
        if line.isascii() and "(" not in line and ";" not in line:
            # no comment: the code is the line without blanks, lower case (as _compress gives it)
            if " " in line or "\t" in line or "\r" in line or "\n" in line:
                cols = [i for i, ch in enumerate(line) if ch not in " \t\r\n"]
                self.s = "".join([line[i] for i in cols]).lower()
            else:
                cols = list(range(len(line)))
                self.s = line.lower()
            cols.append(len(line.rstrip("\r\n")))
        else:
            self.s, cols = _compress(line)
        self.cols = cols
        self.n = len(self.s)

    # -- helpers --------------------------------------------------------------
    def col(self, i: int) -> int:
        """1-based source column of compressed position ``i``."""
        return self.cols[min(i, self.n)] + 1

    def fail(self, code: str, message: str, start: int, end: int | None = None) -> NoReturn:
        raise LineSyntaxError(code, message, start, end)

    def shown(self, i: int) -> str:
        return repr(self.s[i]) if i < self.n else "the end of the line"

    # -- values -----------------------------------------------------------------
    def number(self, i: int) -> tuple[Any, int]:
        m = _NUMBER.match(self.s, i)
        if m is None:
            found = self.s[i:i + 8] or "nothing"
            self.fail("GC104", f"expected a number, found {found!r}; numbers are digits with an "
                      "optional sign and decimal point, such as '-12.5' or '.5'", i, i + 1)
        text = m.group()
        return (NUM, float(text), decimal_value(text)), m.end()

    def real_value(self, i: int) -> tuple[Any, int]:
        s = self.s
        if i >= self.n:
            self.fail("GC104", "expected a value, found the end of the line", i)
        c = s[i]
        if c == "[":
            return self.expression(i)
        if c == "#":
            return self.parameter(i)
        if c in "+-" and i + 1 < self.n and not (s[i + 1].isdigit() or s[i + 1] == "."):
            node, j = self.real_value(i + 1)
            return (node if c == "+" else (NEG, node)), j
        if "a" <= c <= "z":
            return self.function(i)
        return self.number(i)

    def function(self, i: int) -> tuple[Any, int]:
        m = _NAME.match(self.s, i)
        assert m is not None  # called at a letter
        name = m.group()
        j = m.end()
        if name not in FUNCTIONS:
            self.fail("GC106", f"unknown function {name.upper()!r}; known functions are "
                      + ", ".join(sorted(f.upper() for f in FUNCTIONS)), i, j)
        if j >= self.n or self.s[j] != "[":
            self.fail("GC105", f"expected '[' after {name.upper()}, found {self.shown(j)}", j, j + 1)
        if name == "exists":
            if j + 1 >= self.n or self.s[j + 1] != "#":
                self.fail("GC107", f"expected '#' reading the parameter of EXISTS, found {self.shown(j + 1)}",
                          j + 1, j + 2)
            par, k = self.parameter(j + 1)
            if k >= self.n or self.s[k] != "]":
                self.fail("GC105", f"expected ']' closing EXISTS[...], found {self.shown(k)}", k, k + 1)
            return (EXISTS, par), k + 1
        arg, k = self.expression(j)
        if name == "atan":
            if k >= self.n or self.s[k] != "/" or k + 1 >= self.n or self.s[k + 1] != "[":
                self.fail("GC105", "ATAN needs two bracketed arguments: ATAN[y]/[x]", k, k + 1)
            arg2, k = self.expression(k + 1)
            return (ATAN, arg, arg2), k
        return (FN, name, arg), k

    def parameter(self, i: int) -> tuple[Any, int]:
        """``#n``, ``##n``, ``#[expr]`` or ``#<name>`` starting at the ``#``."""
        j = i + 1
        s = self.s
        if j < self.n and s[j] == "<":
            end = s.find(">", j + 1)
            if end < 0:
                self.fail("GC107", "named parameter not terminated: missing '>'", i, self.n)
            name = s[j + 1:end]
            if not name:
                self.fail("GC107", "empty parameter name '#<>'", i, end + 1)
            return (NPAR, name), end + 1
        if j >= self.n or not (s[j].isdigit() or s[j] in "#[.+-" or "a" <= s[j] <= "z"):
            self.fail("GC107", f"expected a parameter number, '[expression]' or '<name>' after '#', found "
                      f"{self.shown(j)}", i, j + 1)
        index, k = self.real_value(j)
        return (PAR, index), k

    def operator(self, i: int) -> tuple[str | None, int]:
        s = self.s
        if i >= self.n:
            self.fail("GC105", "expression not closed: missing ']'", i)
        c = s[i]
        if c == "*":
            if i + 1 < self.n and s[i + 1] == "*":
                return "**", i + 2
            return "*", i + 1
        if c in "+-/":
            return c, i + 1
        if c == "]":
            return None, i + 1
        m = _WORD_OP.match(s, i)
        if m is None:
            name = _NAME.match(s, i) if "a" <= c <= "z" else None
            shown = name.group() if name is not None else c
            self.fail("GC105", f"unknown operator {shown.upper()!r} in expression; expected one of "
                      "** * / MOD + - EQ NE GT GE LT LE AND OR XOR or ']'", i, i + 1)
        return m.group(), m.end()

    def expression(self, i: int) -> tuple[Any, int]:
        """``[ value (op value)* ]`` starting at ``[``, with LinuxCNC precedence."""
        values: list[Any] = []
        ops: list[str] = []
        node, j = self.real_value(i + 1)
        values.append(node)
        while True:
            op, j = self.operator(j)
            prec = PRECEDENCE[op] if op is not None else 1
            while ops and PRECEDENCE[ops[-1]] >= prec:
                right = values.pop()
                values[-1] = (BIN, ops.pop(), values[-1], right)
            if op is None:
                return values[0], j
            ops.append(op)
            node, j = self.real_value(j)
            values.append(node)

    # -- line -----------------------------------------------------------------
    def comment(self, i: int, comments: list[Any]) -> int:
        s = self.s
        end = s.find(")", i)
        if end < 0:
            self.fail("GC102", "comment not closed: missing ')'", i, self.n)
        inner = s.find("(", i + 1, end)
        if inner >= 0:
            self.fail("GC103", "nested comment: '(' inside a comment", inner, inner + 1)
        comments.append((s[i + 1:end], self.col(i)))
        return end + 1

    def oword(self, i: int, comments: list[Any]) -> tuple[OWord, int]:
        s = self.s
        j = i + 1
        if j < self.n and s[j] == "<":
            end = s.find(">", j + 1)
            if end < 0:
                self.fail("GC202", "O-word name not terminated: missing '>'", i, self.n)
            label: int | str = s[j + 1:end]
            if not label:
                self.fail("GC202", "empty O-word name 'o<>'", i, end + 1)
            j = end + 1
        elif j < self.n and s[j] in "[#":
            label, j = self.real_value(j)  # o[expr] / o#<name> call: evaluated when executed
        else:
            m = _INT_LABEL.match(s, j)
            if m is None:
                self.fail("GC202", f"expected an O-word number or <name> after 'O', found {self.shown(j)}", i, j + 1)
            label = int(m.group())
            j = m.end()
        m = _NAME.match(s, j)
        keyword = None
        if m is not None:
            keyword = m.group()
            if keyword not in O_KEYWORDS:
                self.fail("GC202", f"unknown O-word keyword {keyword!r}; expected one of "
                          + ", ".join(sorted(O_KEYWORDS)), j, m.end())
            j = m.end()
        args = []
        if keyword == "call":
            while j < self.n and s[j] in "[(":
                if s[j] == "(":
                    j = self.comment(j, comments)
                    continue
                node, j = self.expression(j)
                args.append(node)
        elif keyword in _NEEDS_CONDITION or keyword in _OPTIONAL_VALUE:
            if j < self.n and s[j] == "[":
                node, j = self.expression(j)
                args.append(node)
            elif keyword in _NEEDS_CONDITION:
                self.fail("GC202", f"O-word {keyword!r} needs a bracketed expression, found {self.shown(j)}",
                          j, j + 1)
        return OWord(label, keyword, tuple(args), self.col(i), self.col(j)), j

    def parse(self) -> ParsedLine:
        s = self.s
        n = self.n
        i = 0
        delete = False
        number = None
        oword = None
        words: list[Any] = []
        assigns = []
        comments: list = []
        if n and s[0] == "%":
            return ParsedLine(percent=True)
        if i < n and s[i] == "/":
            delete = True
            i += 1
        if i < n and s[i] == "n":
            node, i = self.number(i + 1)
            number = node[2]
        if i < n and s[i] == "o":
            oword, i = self.oword(i, comments)
            while i < n:
                if s[i] == "(":
                    i = self.comment(i, comments)
                else:
                    self.fail("GC202", f"an O-word line cannot hold anything else, found {s[i:i + 8]!r}", i, n)
            return ParsedLine(delete, number, oword, (), (), tuple(comments))
        while i < n:
            c = s[i]
            if c == "(":
                i = self.comment(i, comments)
            elif c == "#":
                start = i
                target, i = self.parameter(i)
                if i >= n or s[i] != "=":
                    self.fail("GC203", f"expected '=' after the parameter in an assignment, found {self.shown(i)}",
                              i, i + 1)
                value, i = self.real_value(i + 1)
                assigns.append((target, value, self.col(start), self.col(i)))
            elif "a" <= c <= "z":
                m = _FANUC_MACRO.match(s, i)
                if m is not None:
                    return ParsedLine(delete, number, None, tuple(words), tuple(assigns), tuple(comments),
                                      unsupported=(f"Fanuc macro statement {m.group().rstrip('[#').upper()!r} "
                                                   "(IF/GOTO/WHILE-DO/END) is not supported",
                                                   self.col(i), self.col(n)))
                if c == "n":
                    self.fail("GC201", "an N word must come first in the block", i, i + 1)
                if c == "o":
                    self.fail("GC202", "an O-word must come first in the block", i, i + 1)
                if i + 1 >= n or s[i + 1] in "(=]" or (
                        "a" <= s[i + 1] <= "z" and _word_name(s, i + 1) not in FUNCTIONS):
                    self.fail("GC104", f"letter {c.upper()!r} has no value; a word is a letter followed by a "
                              "number, '#' parameter or '[expression]'", i, i + 1)
                value, j = self.real_value(i + 1)
                words.append((c.upper(), value, self.col(i), self.cols[j - 1] + 2,
                              self.line[self.cols[i]:self.cols[j - 1] + 1]))
                i = j
            elif c == "@" or c == "^":
                # LinuxCNC polar coordinates: @ radius, ^ angle (passed on as words)
                value, j = self.real_value(i + 1)
                words.append((c, value, self.col(i), self.cols[j - 1] + 2, self.line[self.cols[i]:self.cols[j - 1] + 1]))
                i = j
            else:
                self.fail("GC101", f"unexpected character {c!r}; a block holds words (a letter and a "
                          "number), '#' assignments and comments", i, i + 1)
        return ParsedLine(delete, number, None, tuple(words), tuple(assigns), tuple(comments))


def parse_line(line: str, lineno: int, file: str) -> ParsedLine:
    """Parse one source line (without its newline).

    Raises
    ------
    GcodeError
        With one diagnostic (``GC1xx``/``GC2xx``) whose span points at the
        offending text.

    Examples
    --------
    >>> pl = parse_line("#1 = [#1 + 1] #<d> = 2", 1, "p")
    >>> [a[0] for a in pl.assigns]
    [(1, (0, 1.0, Fraction(1, 1))), (2, 'd')]
    >>> parse_line("G1 X1 (oops", 3, "p.ngc")
    Traceback (most recent call last):
    ...
    nczones.errors.GcodeError: p.ngc:3:7: error[GC102]: comment not closed: missing ')'
        G1 X1 (oops
              ^~~~~
    """
    p = Parser(line)
    try:
        return p.parse()
    except LineSyntaxError as e:
        raise GcodeError(diagnostic_at(p, e, lineno, file)) from None
    except RecursionError:
        raise GcodeError(Diagnostic("GC105", "expression nested too deeply",
                                    SourceSpan(file, lineno, 1, None, line))) from None


def diagnostic_at(p: Parser, e: LineSyntaxError, lineno: int, file: str) -> Diagnostic:
    start = p.col(e.start)
    end = p.col(e.end) if e.end is not None and e.end > e.start else start + 1
    if e.end is not None and e.end > e.start:
        end = p.cols[min(e.end - 1, p.n)] + 2
    return Diagnostic(e.code, e.message, SourceSpan(file, lineno, start, max(end, start + 1), line_text(p.line)))


def line_text(line: str) -> str:
    return line.rstrip("\r\n")
