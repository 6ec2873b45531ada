"""The Fanuc line parser: ISO words, Custom Macro B statements, with spans.

:func:`parse_line` turns one source line into a :class:`FanucLine` without
evaluating anything.  The syntax is the Fanuc 0i/30i operator's manuals'
(``specs/fanuc.md``, "Custom Macro B"):

* blanks outside comments are insignificant and letters are case-insensitive;
  ``( )`` comments; ``;`` is the end of block (EOB): after it only blanks and
  comments may follow on the line; ``%`` lines; ``/`` (and ``/1``..``/9``)
  block delete; ``N`` sequence numbers; ``O1234`` or ``:1234`` program numbers;
* words: an address letter and a number, ``#i``, ``-#i``, ``[expression]`` or
  ``-[expression]``.  A literal keeps whether it has a decimal point (the
  decimal-point input rule, parameter 3401#0);
* macro statements: ``#i = expression`` (no brackets needed), ``#[e] = ...``,
  ``IF [condition] GOTO n``, ``IF [condition] THEN #i = ...``, ``GOTO n``
  (``n`` a number, ``#i`` or ``[e]``), ``WHILE [condition] DO m``, ``DO m``,
  ``END m``; ``DPRNT``/``BPRNT``/``POPEN``/``PCLOS`` output statements.

Expressions use Fanuc's precedence (functions; ``* / AND MOD``; ``+ - OR
XOR``; relational operators only in conditions), brackets at most five levels
deep (alarm PS0118).  In a condition, ``AND OR XOR`` between relational
expressions join them (``[#1 GT 0 AND #2 LT 5]``); inside an inner bracket
they are the arithmetic operators.

Trees are tuples: ``(NUM, double, Fraction)``, ``(VAR, index_tree)``,
``(NEG, tree)``, ``(BIN, op, left, right)``, ``(FN, name, tree)``,
``(FN2, name, a, b)`` (``ATAN[a]/[b]``, ``ATAN[a,b]``, ``POW[a,b]``).

>>> fl = parse_line("N10 G1 X-#1 Y[#2*2] F100.", 3, "p.nc")
>>> fl.number, [(w[0], w[1]) for w in fl.words]
(Fraction(10, 1), [('G', 0), ('X', 1), ('Y', 1), ('F', 0)])
>>> parse_line("IF [#1 EQ #0] GOTO 20", 1, "p").stmt[0]
'if'
"""

from __future__ import annotations

import re
from fractions import Fraction

from ...errors import Diagnostic, GcodeError, SourceSpan
from ...precompiled import dataclass  # start-up: no dataclasses import
from ..lexer import decimal_value

__all__ = ["NUM", "VAR", "NEG", "BIN", "FN", "FN2", "FanucLine", "parse_line", "FUNCTIONS", "LITERAL", "EXPR"]

NUM, VAR, NEG, BIN, FN, FN2 = range(6)
#: An expression tree (see the module docstring).
Tree = tuple
#: Word kinds: a literal number, or an expression tree evaluated when the block runs.
LITERAL, EXPR = 0, 1

#: One-argument functions of Custom Macro B (0i/30i), degrees for the trigonometric ones.
FUNCTIONS = frozenset(("sin", "cos", "tan", "asin", "acos", "atan", "sqrt", "abs", "bin", "bcd", "round", "fix",
                       "fup", "ln", "exp", "adp"))
_TWO_ARGS = frozenset(("atan", "pow"))
_MULTIPLICATIVE = ("*", "/", "and", "mod")
_ADDITIVE = ("+", "-", "or", "xor")
_RELATIONAL = ("eq", "ne", "gt", "ge", "lt", "le")
_CONNECTIVES = ("and", "or", "xor")
#: Statements that print or open a device: no effect on motion.
_OUTPUT = ("dprnt", "bprnt", "popen", "pclos")
#: Macro statements of newer controls nczones does not model (the line is ``unknown`` when it runs).
_UNMODELLED = ("else", "endif", "setvn", "quit", "break", "continue")
_NAME = re.compile(r"[a-z]+")
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)")
_INT = re.compile(r"\d+")
MAX_BRACKET_DEPTH = 5


@dataclass(frozen=True, slots=True)
class FanucLine:
    """One parsed, not yet executed line.

    ``words``: ``(letter, kind, payload, column, end_column, text)``: kind
    :data:`LITERAL` with payload ``(value, has_point)``, or :data:`EXPR` with
    an expression tree.  ``assigns``: ``(target_tree, value_tree, column,
    end_column)``, the target a ``VAR`` tree.  ``stmt``: None or
    ``("goto", tree)``, ``("if", condition, then)`` with ``then`` a
    ``("goto", tree)`` or ``("assign", assigns)``, ``("while", condition, m)``,
    ``("do", m)``, ``("end", m)``, ``("output",)``.  ``stmt_at``: the
    statement's columns.  ``unmodelled``: ``(reason, column, end)`` for a
    statement nczones does not model.
    """

    delete: int = 0  # 0: no '/', 1..9: the block delete switch of '/n' ('/' is 1)
    number: Fraction | None = None
    program: int | None = None
    words: tuple = ()
    assigns: tuple = ()
    comments: tuple = ()
    stmt: tuple | None = None
    stmt_at: tuple[int, int] = (1, 1)
    percent: bool = False
    unmodelled: tuple | None = None


class _Fail(Exception):
    def __init__(self, code: str, message: str, start: int, end: int | None = None, cols: list | None = None):
        super().__init__(message)
        self.code, self.message, self.start, self.end, self.cols = code, message, start, end, cols


def _compress(line: str) -> tuple[str, list[int], list]:
    """The code of a line without blanks, lower case; the source column (0-based) of each character and,
    last, the length; and the comments ``(body, 1-based column)``.  ``;`` ends the code: only blanks and
    comments may follow it.
    """
    chars: list[str] = []
    cols: list[int] = []
    comments: list = []
    i, n = 0, len(line)
    while i < n:
        c = line[i]
        if c == "(":
            j = line.find(")", i + 1)
            if j < 0:
                cols.append(i)
                cols.append(len(line.rstrip("\r\n")))
                raise _Fail("GC102", "comment not closed: missing ')'", len(chars), len(chars) + 1, cols)
            comments.append((line[i + 1:j], i + 1))
            i = j + 1
            continue
        if c == ";":
            rest = line[i + 1:]
            k = 0
            while k < len(rest):
                if rest[k] in " \t\r":
                    k += 1
                elif rest[k] == "(":
                    j = rest.find(")", k + 1)
                    if j < 0:
                        break
                    comments.append((rest[k + 1:j], i + 2 + k))
                    k = j + 1
                else:
                    break
            if k < len(rest):
                cols.append(i)
                cols.append(len(line.rstrip("\r\n")))
                raise _Fail("GC101", "';' ends the block (EOB) in the fanuc dialect; only comments in parentheses "
                            "may follow it on the line", len(cols) - 2, len(cols) - 1, cols)
            break
        if c not in " \t\r\n":
            chars.append(c.lower() if "A" <= c <= "Z" else c)
            cols.append(i)
        i += 1
    cols.append(len(line.rstrip("\r\n")))
    return "".join(chars), cols, comments


class _Parser:
    __slots__ = ("s", "n", "depth")

    def __init__(self, s: str):
        self.s = s
        self.n = len(s)
        self.depth = 0

    def shown(self, i: int) -> str:
        return repr(self.s[i:i + 8]) if i < self.n else "the end of the line"

    # -- expressions -----------------------------------------------------------
    def number(self, i: int) -> tuple[Tree, int]:
        m = _NUMBER.match(self.s, i)
        if m is None:
            raise _Fail("GC104", f"expected a number, found {self.shown(i)}", i, i + 1)
        text = m.group()
        q = decimal_value(text)
        return (NUM, self.double(q, i, m.end()), q), m.end()

    def double(self, q: Fraction, start: int, end: int) -> float:
        """The double of a literal; one beyond the double range is an error, not a crash."""
        try:
            return q.numerator / q.denominator
        except OverflowError:
            raise _Fail("GC104", f"number too large: {self.s[start:start + 12]}... ({end - start} characters) is "
                        "beyond the range of the control's values", start, end) from None

    def open(self, i: int) -> None:
        self.depth += 1
        if self.depth > MAX_BRACKET_DEPTH:
            raise _Fail("GC105", f"brackets nested more than {MAX_BRACKET_DEPTH} levels deep (Fanuc alarm PS0118)",
                        i, i + 1)

    def close(self, i: int) -> int:
        if i >= self.n or self.s[i] != "]":
            raise _Fail("GC105", f"expression not closed: expected ']', found {self.shown(i)}", i, i + 1)
        self.depth -= 1
        return i + 1

    def variable(self, i: int) -> tuple[Tree, int]:
        """``#n`` or ``#[e]`` at ``i`` (the '#')."""
        j = i + 1
        s = self.s
        if j < self.n and s[j] == "[":
            self.open(j)
            index, k = self.arith(j + 1, True)
            return (VAR, index), self.close(k)
        m = _INT.match(s, j)
        if m is None:
            if j < self.n and s[j] == "#":
                raise _Fail("GC107", "'##n' is not Fanuc syntax; write #[#n] for an indirect variable", i, j + 1)
            if j < self.n and s[j] == "_":
                raise _Fail("GC107", "system variable names (#_...) are not supported; write the number", i, j + 1)
            raise _Fail("GC107", f"expected a variable number or '[expression]' after '#', found {self.shown(j)}",
                        i, j + 1)
        q = int(m.group())
        return (VAR, (NUM, self.double(Fraction(q), j, m.end()), Fraction(q))), m.end()

    def primary(self, i: int, connectives: bool) -> tuple[Tree, int]:
        s = self.s
        if i >= self.n:
            raise _Fail("GC104", "expected a value, found the end of the line", i)
        c = s[i]
        if c == "[":
            self.open(i)
            node, j = self.arith(i + 1, True)
            return node, self.close(j)
        if c == "#":
            return self.variable(i)
        if c in "+-" and i + 1 < self.n and not (s[i + 1].isdigit() or s[i + 1] == "."):
            node, j = self.primary(i + 1, connectives)
            return (node if c == "+" else (NEG, node)), j
        if "a" <= c <= "z":
            return self.function(i)
        return self.number(i)

    def function(self, i: int) -> tuple[Tree, int]:
        m = _NAME.match(self.s, i)
        assert m is not None  # primary() calls this at a letter
        name = m.group()
        known = next((f for f in sorted(FUNCTIONS | _TWO_ARGS, key=len, reverse=True) if name.startswith(f)), None)
        if known is None or not name == known:
            raise _Fail("GC106", f"unknown function {name.upper()!r}; known functions are "
                        + ", ".join(sorted(f.upper() for f in FUNCTIONS | _TWO_ARGS)), i, m.end())
        j = m.end()
        if j >= self.n or self.s[j] != "[":
            raise _Fail("GC105", f"expected '[' after {name.upper()}, found {self.shown(j)}", j, j + 1)
        self.open(j)
        arg, k = self.arith(j + 1, True)
        if name in _TWO_ARGS and k < self.n and self.s[k] == ",":  # ATAN[a,b], POW[a,b] (30i)
            arg2, k = self.arith(k + 1, True)
            return (FN2, name, arg, arg2), self.close(k)
        k = self.close(k)
        if name == "atan" and k + 1 < self.n and self.s[k] == "/" and self.s[k + 1] == "[":
            self.open(k + 1)
            arg2, k2 = self.arith(k + 2, True)
            return (FN2, name, arg, arg2), self.close(k2)
        if name == "pow":
            raise _Fail("GC105", "POW needs two arguments: POW[a,b]", j, k)
        return (FN, name, arg), k

    def op(self, i: int, ops: tuple[str, ...]) -> str | None:
        s = self.s
        if i >= self.n:
            return None
        c = s[i]
        if c in "+-*/":
            return c if c in ops else None
        if "a" <= c <= "z":
            for o in ops:
                if len(o) > 1 and s.startswith(o, i):
                    return o
        return None

    def term(self, i: int, connectives: bool) -> tuple[Tree, int]:
        node, i = self.primary(i, connectives)
        ops = _MULTIPLICATIVE if connectives else ("*", "/", "mod")
        while True:
            o = self.op(i, ops)
            if o is None:
                return node, i
            right, i = self.primary(i + len(o), connectives)
            node = (BIN, o, node, right)

    def arith(self, i: int, connectives: bool) -> tuple[Tree, int]:
        """An arithmetic expression (``connectives``: AND/OR/XOR are arithmetic operators here)."""
        node, i = self.term(i, connectives)
        ops = _ADDITIVE if connectives else ("+", "-")
        while True:
            o = self.op(i, ops)
            if o is None:
                return node, i
            right, i = self.term(i + len(o), connectives)
            node = (BIN, o, node, right)

    def condition(self, i: int) -> tuple[Tree, int]:
        """``[ rel ((AND|OR|XOR) rel)* ]`` at ``i`` (the '['), rel = ``arith (EQ|NE|GT|GE|LT|LE arith)?``."""
        if i >= self.n or self.s[i] != "[":
            raise _Fail("GC105", f"expected '[' opening the condition, found {self.shown(i)}", i, i + 1)
        self.open(i)
        node, j = self.relation(i + 1)
        while True:
            o = self.op(j, _CONNECTIVES)
            if o is None:
                break
            right, j = self.relation(j + len(o))
            node = (BIN, o, node, right)
        return node, self.close(j)

    def relation(self, i: int) -> tuple[Tree, int]:
        left, j = self.arith(i, False)
        o = self.op(j, _RELATIONAL)
        if o is None:
            return left, j
        right, j = self.arith(j + len(o), False)
        return (BIN, o, left, right), j

    def label(self, i: int) -> tuple[Tree, int]:
        """The target of GOTO / the id of DO/END: a number, ``#i`` or ``[e]``."""
        s = self.s
        if i < self.n and s[i] in "#[":
            if s[i] == "#":
                return self.variable(i)
            self.open(i)
            node, j = self.arith(i + 1, True)
            return node, self.close(j)
        m = _INT.match(s, i)
        if m is None:
            raise _Fail("GC104", f"expected a sequence number, found {self.shown(i)}", i, i + 1)
        q = int(m.group())
        return (NUM, self.double(Fraction(q), i, m.end()), Fraction(q)), m.end()

    def loop_id(self, i: int, kw: str) -> tuple[int, int]:
        m = _INT.match(self.s, i)
        if m is None:
            raise _Fail("GC202", f"{kw.upper()} needs its identification number 1, 2 or 3 (DO1 ... END1)", i, i + 1)
        return int(m.group()), m.end()


def _column(cols: list[int], i: int) -> int:
    return cols[min(i, len(cols) - 1)] + 1


def _end_column(cols: list[int], j: int) -> int:
    """1-based exclusive end column of compressed text ending before ``j``."""
    return cols[j - 1] + 2 if j > 0 else 1


def parse_line(line: str, lineno: int, file: str) -> FanucLine:
    """Parse one source line (without its newline) in the Fanuc dialect.

    Raises
    ------
    GcodeError
        With one diagnostic (``GC1xx``/``GC2xx``) whose span points at the offending text.

    Examples
    --------
    >>> fl = parse_line("#101 = #1 + 2 * SIN[30] (note)", 1, "p")
    >>> len(fl.assigns), fl.comments
    (1, (('note', 25),))
    >>> parse_line("WHILE [#1 LT 10] DO1", 1, "p").stmt[0::2]
    ('while', 1)
    >>> parse_line("G1 X1 ; more", 2, "p.nc")
    Traceback (most recent call last):
    ...
    nczones.errors.GcodeError: p.nc:2:7: error[GC101]: ';' ends the block (EOB) in the fanuc dialect; only comments in parentheses may follow it on the line
        G1 X1 ; more
              ^
    """
    cols: list[int] = []
    try:
        s, cols, comments = _compress(line)
        return _parse(line, s, cols, comments)
    except _Fail as e:
        if e.cols is not None:
            cols = e.cols
        if not cols:
            cols = [len(line)]
        start = _column(cols, e.start)
        end = _end_column(cols, e.end) if e.end is not None and e.end > e.start else start + 1
        raise GcodeError(Diagnostic(e.code, e.message, SourceSpan(file, lineno, start, max(end, start + 1),
                                                                  line.rstrip("\r\n")))) from None
    except RecursionError:
        raise GcodeError(Diagnostic("GC105", "expression nested too deeply",
                                    SourceSpan(file, lineno, 1, None, line.rstrip("\r\n")))) from None


def _parse(line: str, s: str, cols: list[int], comments: list) -> FanucLine:
    n = len(s)
    comments_t = tuple(comments)
    if n and s[0] == "%":
        return FanucLine(percent=True, comments=comments_t)
    p = _Parser(s)
    i = 0
    delete = 0
    number = None
    if i < n and s[i] == "/":
        delete = 1
        i += 1
        if i < n and s[i].isdigit():
            delete = int(s[i])
            if delete == 0:
                raise _Fail("GC101", "block delete '/0' does not exist; use / or /1 to /9", i - 1, i + 1)
            i += 1
    if i < n and (s[i] == "o" or s[i] == ":"):
        m = _INT.match(s, i + 1)
        if m is None:
            raise _Fail("GC202", f"expected a program number after {s[i].upper()!r}, found {p.shown(i + 1)}",
                        i, i + 1)
        if m.end() < n:
            raise _Fail("GC202", "a program number line holds only the number and comments", m.end(), n)
        return FanucLine(delete, None, int(m.group()), comments=comments_t)
    if i < n and s[i] == "n":
        m = _INT.match(s, i + 1)
        if m is None:
            raise _Fail("GC104", f"expected a sequence number after 'N', found {p.shown(i + 1)}", i, i + 1)
        number = Fraction(int(m.group()))
        i = m.end()
    words: list = []
    assigns: list = []
    stmt: tuple | None = None
    stmt_at = (1, 1)
    unmodelled = None
    while i < n:
        c = s[i]
        start = i
        if c == "#":
            target, i = p.variable(i)
            if i >= n or s[i] != "=":
                raise _Fail("GC203", f"expected '=' after the variable in an assignment, found {p.shown(i)}",
                            i, i + 1)
            value, i = p.arith(i + 1, True)
            assigns.append((target, value, _column(cols, start), _end_column(cols, i)))
            continue
        if not ("a" <= c <= "z"):
            raise _Fail("GC101", f"unexpected character {c!r}; a block holds words (a letter and a value), "
                        "'#' assignments, macro statements and comments", i, i + 1)
        kw_match = _NAME.match(s, i)
        assert kw_match is not None  # c is a letter
        kw = kw_match.group()
        if stmt is not None and not kw.startswith("n"):
            raise _Fail("GC202", "a macro statement (IF, GOTO, WHILE, DO, END) must end its block", i, n)
        if s.startswith("if[", i):
            cond, j = p.condition(i + 2)
            if s.startswith("goto", j):
                target, k = p.label(j + 4)
                stmt = ("if", cond, ("goto", target))
                stmt_at = (_column(cols, start), _end_column(cols, k))
                i = k
                continue
            if s.startswith("then", j):
                k = j + 4
                then: list = []
                while k < n and s[k] == "#":
                    at = k
                    target, k = p.variable(k)
                    if k >= n or s[k] != "=":
                        raise _Fail("GC203", f"expected '=' after the variable in an assignment, found "
                                    f"{p.shown(k)}", k, k + 1)
                    value, k = p.arith(k + 1, True)
                    then.append((target, value, _column(cols, at), _end_column(cols, k)))
                if not then:
                    raise _Fail("GC202", "IF [...] THEN takes a macro statement (an assignment such as "
                                "#1 = 5); NC words after THEN are not modelled", k, n)
                if k < n:
                    raise _Fail("GC202", f"unexpected {p.shown(k)} after IF [...] THEN #i = ...", k, n)
                stmt = ("if", cond, ("assign", tuple(then)))
                stmt_at = (_column(cols, start), _end_column(cols, k))
                i = k
                continue
            raise _Fail("GC202", f"IF [condition] must be followed by GOTO or THEN, found {p.shown(j)}", j, j + 1)
        if kw.startswith("goto"):
            target, k = p.label(i + 4)
            stmt = ("goto", target)
            stmt_at = (_column(cols, start), _end_column(cols, k))
            i = k
            continue
        if s.startswith("while[", i):
            cond, j = p.condition(i + 5)
            if not s.startswith("do", j):
                raise _Fail("GC202", f"WHILE [condition] must be followed by DO and its number, found {p.shown(j)}",
                            j, j + 1)
            ident, k = p.loop_id(j + 2, "do")
            stmt = ("while", cond, ident)
            stmt_at = (_column(cols, start), _end_column(cols, k))
            i = k
            continue
        bracket = "do" if s.startswith("do", i) else "end" if s.startswith("end", i) else None
        if bracket is not None and i + len(bracket) < n and s[i + len(bracket)].isdigit():  # DOm, ENDm
            ident, k = p.loop_id(i + len(bracket), bracket)
            stmt = (bracket, ident)
            stmt_at = (_column(cols, start), _end_column(cols, k))
            i = k
            continue
        out = next((o for o in _OUTPUT if kw.startswith(o)), None)
        if out is not None:
            stmt = ("output",)
            stmt_at = (_column(cols, start), _end_column(cols, n))
            i = n  # the device output statement's arguments do not matter for motion
            continue
        other = next((o for o in _UNMODELLED if kw.startswith(o)), None)
        if other is not None:
            unmodelled = (f"the macro statement {other.upper()} is not modelled", _column(cols, start),
                          _end_column(cols, n))
            break
        if c == "n":
            raise _Fail("GC201", "an N word must come first in the block", i, i + 1)
        if c == "o":
            raise _Fail("GC202", "an O program number must come first in its own block", i, i + 1)
        # a word: the letter and its value
        j = i + 1
        if j >= n:
            raise _Fail("GC104", f"letter {c.upper()!r} has no value; a word is a letter followed by a number, "
                        "'#' variable or '[expression]'", i, i + 1)
        d = s[j]
        if d == "#" or d == "[" or (d in "+-" and j + 1 < n and s[j + 1] in "#["):
            tree, k = p.primary(j, True)
            words.append((c.upper(), EXPR, tree, _column(cols, i), _end_column(cols, k), line[cols[i]:cols[k - 1] + 1]))
            i = k
            continue
        m = _NUMBER.match(s, j)
        if m is None:
            raise _Fail("GC104", f"letter {c.upper()!r} has no value; a word is a letter followed by a number, "
                        "'#' variable or '[expression]'", i, i + 1)
        text = m.group()
        words.append((c.upper(), LITERAL, (decimal_value(text), "." in text), _column(cols, i),
                      _end_column(cols, m.end()), line[cols[i]:cols[m.end() - 1] + 1]))
        i = m.end()
    return FanucLine(delete, number, None, tuple(words), tuple(assigns), comments_t, stmt, stmt_at, False, unmodelled)

