"""Parse a line by its shape: lines that differ only in their numbers are parsed once.

Macro-style programs repeat a few line shapes with different numbers
(``G1 X[#1 + 12.5] Y[#2 + 3.25]``, ``N120Y[#<yscale>*-56.12]``).  A line's
*shape* is its text with every run of digits (with at most one decimal point
after its first digit) replaced by a placeholder; a point before the digits
(``.5``) stays in the shape.  Every decision of the parser
(:mod:`nczones.gcode.parser`) reads letters, signs, points, brackets and
blanks, and whether a digit comes next, never which digits, and a literal only
ever becomes a ``NUM`` leaf; so the parse of a line
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
from collections.abc import Callable
from operator import itemgetter
from types import FunctionType

from ..code_cache import compiled
from ..frozen import builder
from .expr import (
    UNSET,
    EvalError,
    atan_degrees,
    binary_op,
    pair,
    q_add,
    q_div,
    q_mul,
    q_sub,
    read_only,
    unary_op,
)
from .lexer import G_MACRO_CALLS, M_CONTROL, plain_decimal_value, to_double
from .parser import ATAN, BIN, FN, NEG, NPAR, NUM, PAR, ParsedLine, Parser, parse_line

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["parse_line_shaped", "line_shaped", "CompiledLine", "MAX_SHAPES", "RUNS", "LAYOUT", "compiled_line", "shaped",
           "shape_source"]

#: Shapes (and layouts) kept (a table is emptied when full: memory does not grow with the program).
MAX_SHAPES = 4096
_LITERAL = re.compile(r"([0-9]+\.?[0-9]*)")  # the parser's number without what comes before its first digit
_SHAPES: dict[str, object] = {}
_LAYOUTS: dict[bytes, tuple] = {}  # the line with its digits made 0 -> (its shape, its literal cutter)
_ZERO_DIGITS = bytes.maketrans(b"123456789", b"000000000")
#: ``line.encode().translate(LAYOUT)``: the *layout* of an ASCII line (its digits made ``0``).
LAYOUT = _ZERO_DIGITS
#: The layouts whose shape has compiled code: layout -> ``(run, cut, shape)``; for a line of the
#: layout (no comment), ``run(cut(line), params)`` is what :class:`CompiledLine` documents, and
#: ``compiled_line(shape, cut(line))`` the line :func:`line_shaped` returns.  For the runner's loop.
RUNS: dict[bytes, tuple] = {}
_NO_SHAPE = object()  # parse lines of this shape afresh
_PREFIXES = frozenset(("+", "-", ".", "+.", "-."))  # what a number may have before its first digit


def parse_line_shaped(line: str, lineno: int, file: str) -> ParsedLine:
    """:func:`~nczones.gcode.parser.parse_line`, rebuilt from an earlier line of the same shape when possible.

    >>> a = parse_line_shaped("G1 X[#1 + 1.5] Y-2", 1, "p")
    >>> b = parse_line_shaped("G1 X[#1 + 12.25] Y-.5", 2, "p")  # same shape (the point of '.5' is in it)
    >>> b == parse_line("G1 X[#1 + 12.25] Y-.5", 2, "p")
    True
    """
    shape, literals = _shaped(line, lineno, file)
    parsed: ParsedLine = shape if literals is None else shape.rebuild(literals, line)
    return parsed


def line_shaped(line: str, lineno: int, file: str) -> ParsedLine | CompiledLine:
    """The line as the runner executes it: a :class:`CompiledLine` when its shape has compiled code,
    else :func:`parse_line_shaped`.

    >>> clear()
    >>> first = line_shaped("G1 X[#1 + 1.5]", 1, "p")  # a new shape: parsed
    >>> type(first).__name__, type(line_shaped("G1 X[#1 + 22.75]", 2, "p")).__name__
    ('ParsedLine', 'CompiledLine')
    """
    if "(" not in line and ";" not in line and line.isascii():  # _shaped's first lookup, for the usual case
        hit = RUNS.get(line.encode().translate(_ZERO_DIGITS))
        if hit is not None:
            return compiled_line(hit[2], hit[1](line))
    shape, literals = _shaped(line, lineno, file)
    if literals is None:
        parsed: ParsedLine = shape
        return parsed
    if shape.run is None:
        rebuilt: ParsedLine = shape.rebuild(literals, line)
        return rebuilt
    return compiled_line(shape, literals)


def compiled_line(shape: _Shape, parts: tuple) -> CompiledLine:
    """The :class:`CompiledLine` of a line of ``shape`` whose literals are ``parts``."""
    c = _new(CompiledLine)
    c.shape = shape
    c.parts = parts
    return c


def clear() -> None:
    """Forget every shape and layout (the next line of each shape is parsed afresh)."""
    _SHAPES.clear()
    _LAYOUTS.clear()
    RUNS.clear()


def _shaped(line: str, lineno: int, file: str) -> tuple[Any, tuple[str, ...] | None]:
    """``(shape, its literals in this line)``, or ``(parse_line(...), None)`` when the line is parsed
    afresh (a new shape, a shape that cannot be used, a comment or non-ASCII text).

    Two lookups: the *layout* (the line with every digit made ``0``: lines of one layout have their
    literals at the same columns, so they are cut out by fixed slices), else the shape (the literals
    found by a regular expression), whose new layout is then noted.
    """
    if "(" in line or ";" in line or not line.isascii():
        return parse_line(line, lineno, file), None
    layout = line.encode().translate(_ZERO_DIGITS)
    hit = _LAYOUTS.get(layout)
    if hit is not None:
        shape, cut = hit
        if shape is _NO_SHAPE:
            return parse_line(line, lineno, file), None
        return shape, cut(line)
    parts = _LITERAL.split(line)
    key = "\x00".join(parts[0::2])
    shape = _SHAPES.get(key)
    pl = None
    if shape is None:
        pl = parse_line(line, lineno, file)  # raises the parser's own errors
        if len(_SHAPES) >= MAX_SHAPES:
            _SHAPES.clear()
        shape = _SHAPES[key] = _compile(line, parts, pl)
    if len(_LAYOUTS) >= MAX_SHAPES:
        _LAYOUTS.clear()
        RUNS.clear()
    cut = _cutter(parts)
    _LAYOUTS[layout] = (shape, cut)
    if shape is not _NO_SHAPE and shape.run is not None:
        RUNS[layout] = (shape.run, cut, shape)
    if pl is not None:
        return pl, None
    if shape is _NO_SHAPE:
        return parse_line(line, lineno, file), None
    return shape, tuple(parts[1::2])


def shaped(line: str, lineno: int, file: str) -> tuple[Any, tuple[str, ...] | None]:
    """``(shape, the literals of this line)`` when the line's shape is known, else ``(its parse, None)``; the
    layout of the line is registered either way (:data:`RUNS` when its shape has compiled code)."""
    return _shaped(line, lineno, file)


def _cutter(parts: list[str]) -> Callable[[str], tuple[str, ...]]:
    """A function cutting the literals out of a line of the layout of the line split into ``parts``."""
    cuts = []
    pos = 0
    for k, text in enumerate(parts):
        if k % 2:
            cuts.append(slice(pos, pos + len(text)))
        pos += len(text)
    if len(cuts) > 1:
        return itemgetter(*cuts)
    if cuts:
        cut = cuts[0]
        return lambda line: (line[cut],)
    return _no_literals


def _no_literals(line: str) -> tuple:
    return ()


class CompiledLine:
    """A line whose shape has compiled code.

    ``shape.run(parts, params)`` evaluates its words and assignments the way
    :meth:`~nczones.gcode.program._Runner.execute` does and returns ``(N number, letters, values)``
    after making the assignments, or None, having changed nothing, when the line needs the general
    path (an error, a code the language layer acts on: M2 M30 M97 M98 M99, G65-G67).
    ``columns(parts, line)`` gives each word's ``(column, end column, text)``.
    """

    __slots__ = ("shape", "parts")
    shape: _Shape
    parts: tuple[str, ...]

    @property
    def columns(self) -> Any:
        return self.shape.columns


class _Shape:
    __slots__ = ("rebuild", "run", "columns", "source")
    run: Any  # the compiled code, or None (a CompiledLine's shape always has it)

    def __init__(self, rebuild: Callable[..., ParsedLine], run: Callable[..., Any] | None, columns: Any,
                 source: tuple[ParsedLine, dict[int, str]]) -> None:
        self.rebuild = rebuild
        self.run = run
        self.columns = columns
        self.source = source


def shape_source(shape: Any) -> tuple[ParsedLine, dict[int, str]]:
    """The parse of a shape's first line and, by ``id`` of each of its ``NUM`` nodes, the Python source of
    that literal's text in a line of the shape (``P[k]``, or a sign or point before it: ``'-' + P[k]``), the
    literals ``P`` being what the layout's cutter (:data:`RUNS`) cuts out of the line."""
    source: tuple[ParsedLine, dict[int, str]] = shape.source
    return source


def _compile(line: str, parts: list[str], pl: ParsedLine) -> Any:
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
    leaf_of: dict[int, str] = {}  # id(node) -> the source of its literal's text (sign included)
    for k, ((a, b, node), (la, lb)) in enumerate(zip(numbers, spans)):
        if b != lb:
            return _NO_SHAPE
        if a == la:
            leaf_of[id(node)] = f"P[{k}]"
        elif a < la and line[a:la].replace(" ", "").replace("\t", "") in _PREFIXES:
            leaf_of[id(node)] = f"{line[a:la].replace(' ', '').replace(chr(9), '')!r} + P[{k}]"
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
        number_src = f"_num({leaf_of[id(numbers[0][2])]})[2]"
    else:
        return _NO_SHAPE
    # D[k]: how much longer the first k literals are than in the first line of the shape
    lines = ["def rebuild(P, line):", "    D = [0]"]
    lines += [f"    D.append(D[-1] + len(P[{k}]) - {b - a})" for k, (a, b) in enumerate(spans)]
    lines.append(f"    return _parsed_line({pl.delete!r}, {number_src}, ({''.join(w + ', ' for w in words)}), "
                 f"({''.join(a + ', ' for a in assigns)}))")
    src = "\n".join(lines) + "\n"
    scope: dict[str, Any] = {"_parsed_line": _parsed_line, "_num": _num}
    exec(compiled(src, "<line shape>"), scope)  # noqa: S102  # built only from reprs of str/int/bool
    rebuild = scope["rebuild"]
    if rebuild(tuple(parts[1::2]), line) != pl:
        return _NO_SHAPE
    run = columns = None
    if _COMPILE_RUNS and not pl.delete:
        try:
            run, columns = _executor(spans, pl, leaf_of, at,
                                     None if pl.number is None else leaf_of[id(numbers[0][2])])
        except (_Unshaped, RecursionError):
            run = columns = None
    return _Shape(rebuild, run, columns, (pl, leaf_of))


class _Unshaped(Exception):
    pass


#: ``ParsedLine(delete, number, None, words, assigns)``, built faster (an ordinary, equal ParsedLine; the
#: rebuild of every shape is checked against the parser's own).
_parsed_line = builder(ParsedLine, ("delete", "number", "words", "assigns"), oword=None, comments=(), percent=False,
                       unsupported=None)
_new = object.__new__


class _Recording(Parser):
    """The parser, noting the raw span and node of every number it reads."""

    __slots__ = ("numbers",)
    numbers: list[tuple[int, int, Any]]

    def number(self, i: int) -> tuple[Any, int]:
        node, j = Parser.number(self, i)
        self.numbers.append((self.cols[i], self.cols[j - 1] + 1, node))
        return node, j


def _tree(node: Any, leaf_of: dict[int, str]) -> str:
    """Python source rebuilding an expression tree, its NUM leaves from the literals."""
    if type(node) is not tuple:
        if node is None or type(node) in (str, int, bool):
            return repr(node)
        raise _Unshaped
    if node and node[0] == NUM:
        src = leaf_of.get(id(node))
        if src is None:
            raise _Unshaped
        return f"_num({src})"
    return "(" + "".join(_tree(t, leaf_of) + ", " for t in node) + ")"


def _num(text: str) -> tuple:
    """The NUM leaf of a literal (an optional sign, digits, at most one point, no blanks), as the parser makes it.

    Long literals are mostly distinct (coordinates): they skip the reader's cache, whose misses cost more
    than the reading itself.
    """
    return (NUM, float(text), plain_decimal_value(text) if len(text) < 5 else _decimal_uncached(text))


_decimal_uncached = plain_decimal_value.__wrapped__


#: Compile run code for shapes (tests turn it off to compare with the general path).
_COMPILE_RUNS = True


def _executor(spans: list[tuple[int, int]], pl: ParsedLine, leaf_of: dict[int, str], at: Callable[[int], str],
              number_src: str | None) -> tuple[Callable[..., Any], Callable[..., Any]]:
    """Compiled ``(run, columns)`` of this shape (see :class:`CompiledLine`), or raise _Unshaped.

    ``run`` mirrors ``_Runner.execute`` and :func:`~nczones.gcode.expr.evaluate`: the same double
    operations in the same order, the same exact shadows kept by the same test, the same words; anything
    that would raise there (and the codes the runner acts on) returns None before any assignment is made,
    so that the general path then reports it.  A literal's exact value is computed only where a shadow
    needs it.  ``columns(P, line)`` gives the words' ``(column, end column, text)``, for when the block's
    words are read.
    """
    em = _Emit(leaf_of)
    body: list[str] = []
    columns = []
    for k, (letter, tree, col, end, _text) in enumerate(pl.words):
        if tree[0] == NUM:
            src = leaf_of.get(id(tree))
            if src is None:
                raise _Unshaped
            body.append(f"v{k} = {_exact(src)}")
        else:
            d, q, lazy = em.value(tree, body)
            if lazy:
                body.append(f"v{k} = {q}")
            else:
                body.append(f"v{k} = {q} if {q} is not None else to_double({d})")
        if letter == "M":
            body.append(f"if v{k}._denominator == 1 and v{k}._numerator in _STOP_M: return None")
        elif letter == "G":
            body.append(f"if 65 <= v{k}._numerator // v{k}._denominator <= 72 and (v{k} in G_MACRO_CALLS or "
                        f"v{k}._numerator // v{k}._denominator >= 70): return None")  # macro calls, G70-G72 profiles
        columns.append(f"({at(col - 1)}+1, {at(end - 1)}+1, line[{at(col - 1)}:{at(end - 1)}])")
    writes = []
    for k, (target, tree, _c, _e) in enumerate(pl.assigns):
        if target[0] == NPAR:
            key = repr(target[1])
            if read_only(target[1]):
                body.append("return None")  # the general path refuses it (GC318)
            body.append(f"if {key} in params._guarded: return None")
        elif target[0] == PAR and target[1][0] == NUM and id(target[1]) in leaf_of:
            key = f"k{k}"
            src = leaf_of[id(target[1])]
            body.append(f"{key} = _IDX.get({src}) or _index({src})")
            body.append(f"if not 1 <= {key} <= params.max_parameter or {key} == 3000 or {key} == 3006 "
                        f"or {key} in params._guarded: return None")
        else:
            raise _Unshaped
        d, q, _lazy = em.value(tree, body)
        writes.append(f"write({key}, ({d}, {q}))")
    letters = "".join(w[0] for w in pl.words)
    values = "".join(f"v{k}, " for k in range(len(pl.words)))
    lines = ["def run(P, params):"]
    if em.uses_store:
        lines += ["    num = params._num", "    providers = params._providers"]
    if body:
        lines += ["    try:"] + [f"        {b}" for b in body] + ["    except EvalError:", "        return None"]
    if writes:
        lines += ["    write = params.write"] + [f"    {w}" for w in writes]
    number = "None" if number_src is None else _exact(number_src)
    lines.append(f"    return {number}, {letters!r}, ({values})")
    lines += ["def columns(P, line):", "    D = [0]"]
    lines += [f"    D.append(D[-1] + len(P[{k}]) - {b - a})" for k, (a, b) in enumerate(spans)]
    lines.append(f"    return [{''.join(c + ', ' for c in columns)}]")
    scope: dict[str, Any] = {"_dec": _decimal, "_pdv": plain_decimal_value, "_dun": _decimal_uncached, "to_double": to_double,
             "_STOP_M": M_CONTROL, "G_MACRO_CALLS": G_MACRO_CALLS, "EvalError": EvalError, "UNSET": UNSET, "pair": pair, "binary_op": binary_op, "unary_op": unary_op,
             "q_add": q_add, "q_sub": q_sub, "q_mul": q_mul, "q_div": q_div, "_atan": atan_degrees,
             "_IDX": _IDX, "_index": _index}
    return _compiled_when_called("\n".join(lines) + "\n", scope)


#: ``run`` and ``columns`` of a shape before their first call: they compile the shape's source (``_COMPILE_NOW``,
#: a name in each shape's own scope), then run what it defines.
_STUB_SOURCE = ("def run(P, params):\n    return _COMPILE_NOW()[0](P, params)\n"
                "def columns(P, line):\n    return _COMPILE_NOW()[1](P, line)\n")
_STUB_CODE: list[Any] = []  # the code objects of the two stubs, compiled at the first shape


def _compiled_when_called(source: str, scope: dict[str, Any]) -> tuple[Callable[..., Any], Callable[..., Any]]:
    """``(run, columns)`` as ``source`` defines them in ``scope``, compiled at the first call of either (issue 36:
    the double pass reads a shape's source, never runs it; compiling ``run`` was most of its start).

    Each is a function in ``scope`` whose code, at that first call, becomes the compiled function's own: the same
    code with the same globals, so that every later call, from wherever the function object was stored (RUNS,
    a shape), is the compiled function's, without a wrapper.  The source is straight-line code (each statement
    one operation on names: :class:`_Emit`'s nesting is in the order of its lines), which ``compile`` takes at
    any length; what could not be emitted raised :class:`_Unshaped` before, as when it was compiled at once.
    """
    if not _STUB_CODE:
        stubs: dict[str, Any] = {}
        exec(compiled(_STUB_SOURCE, "<line shape stub>"), stubs)  # noqa: S102  # a constant source
        _STUB_CODE.extend((stubs["run"].__code__, stubs["columns"].__code__))
    run = FunctionType(_STUB_CODE[0], scope, "run")
    columns = FunctionType(_STUB_CODE[1], scope, "columns")

    def compile_now() -> tuple[Callable[..., Any], Callable[..., Any]]:
        exec(compiled(source, "<line shape run>"), scope)  # noqa: S102  # reprs only
        run.__code__, columns.__code__ = scope["run"].__code__, scope["columns"].__code__
        scope["run"], scope["columns"] = run, columns
        return run, columns

    scope["_COMPILE_NOW"] = compile_now
    return run, columns


#: Parameter numbers of literals (``#12``): the text's index, or -1 when it is not within 0.0001 of an
#: integer (then the general path reports it).
_IDX: dict[str, int] = {}


def _index(text: str) -> int:
    """``round(float(text))`` as the parameter number ``#text`` reads, -1 when not an integer (cached)."""
    x = float(text)
    try:
        i = round(x)
    except (OverflowError, ValueError):
        return -1
    if abs(x - i) > 0.0001:
        i = -1
    if len(_IDX) < 10_000:
        _IDX[text] = i
    return i


def _exact(src: str) -> str:
    """Source of :func:`_decimal` of the literal ``src``, its body inlined for a plain ``P[k]`` (one call
    less per literal)."""
    if re.fullmatch(r"P\[\d+\]", src):
        return f"(_pdv({src}) if len({src}) < 5 else _dun({src}))"
    return f"_dec({src})"


def _decimal(text: str) -> Any:
    """The exact value of a literal (sign included), as the parser's NUM leaf has it."""
    return plain_decimal_value(text) if len(text) < 5 else _decimal_uncached(text)


class _Emit:
    """Straight-line code for an expression tree: each node's double in a local ``dN`` and its shadow
    in ``qN`` (None when dropped), or, for a literal, the source computing its shadow (``lazy``)."""

    _Q = {"+": "q_add", "-": "q_sub", "*": "q_mul", "/": "q_div"}

    def __init__(self, leaf_of: dict[int, str]):
        self.leaf_of = leaf_of
        self.n = 0
        self.uses_store = False

    def value(self, node: Any, out: list[str]) -> tuple[str, str, bool]:
        """Emit code for ``node``; its (double variable, shadow source, shadow is lazy)."""
        tag = node[0]
        self.n += 1
        n = self.n
        d, q = f"d{n}", f"q{n}"
        if tag == NUM:
            src = self.leaf_of.get(id(node))
            if src is None:
                raise _Unshaped
            out.append(f"{d} = float({src})")
            return d, _exact(src), True
        if tag == PAR:
            index = node[1]
            src = self.leaf_of.get(id(index)) if index[0] == NUM else None
            if src is None:
                raise _Unshaped
            self.uses_store = True
            out += [f"i = _IDX.get({src}) or _index({src})",
                    "if not 1 <= i <= params.max_parameter: return None",
                    "g = providers.get(i)",
                    f"{d}, {q} = num.get(i, UNSET) if g is None else pair(g())"]
            return d, q, False
        if tag == NPAR:
            out += ["try:", f"    {d}, {q} = params.read({node[1]!r})", "except KeyError:", "    return None"]
            return d, q, False
        if tag == BIN:
            op = node[1]
            da, qa, lza = self.value(node[2], out)
            db, qb, lzb = self.value(node[3], out)
            qfn = self._Q.get(op)
            if qfn is None:  # mod, **, comparisons, logic: no shadow read
                out.append(f"{d}, {q} = binary_op({op!r}, ({da}, None), ({db}, None))")
                return d, q, False
            if op == "/":
                out.append(f"if {db} == 0.0: return None")
            out += [f"{d} = {da} {op} {db}", f"if {d} - {d}: return None", f"{q} = None"]  # NaN, inf
            cond = " and ".join([f"{x} is not None" for x, lz in ((qa, lza), (qb, lzb)) if not lz]) or "True"
            out += [f"if {cond}:", f"    a = {qa}", f"    b = {qb}"]
            if op == "/":
                out += ["    if b != 0:", "        c = q_div(a, b)",
                        f"        if c._numerator / c._denominator == {d}: {q} = c"]
            else:
                out += [f"    c = {qfn}(a, b)", f"    if c._numerator / c._denominator == {d}: {q} = c"]
            return d, q, False
        if tag == NEG:
            da, qa, lza = self.value(node[1], out)
            out.append(f"{d} = -{da}")
            if lza:
                return d, f"-{qa}", True
            out.append(f"{q} = -{qa} if {qa} is not None else None")
            return d, q, False
        if tag == FN:
            name = node[1]
            da, qa, lza = self.value(node[2], out)
            if name == "abs":
                out += [f"if {da} - {da}: return None", f"{d} = abs({da})"]  # inf: unary_op's error
                if lza:
                    return d, f"abs({qa})", True
                out.append(f"{q} = abs({qa}) if {qa} is not None else None")
                return d, q, False
            out.append(f"{d}, {q} = unary_op({name!r}, ({da}, None))")  # only ABS reads the shadow
            return d, q, False
        if tag == ATAN:
            dy, _qy, _ly = self.value(node[1], out)
            dx, _qx, _lx = self.value(node[2], out)
            out += [f"{d} = _atan({dy}, {dx})", f"{q} = None"]
            return d, q, False
        raise _Unshaped  # EXISTS, computed parameter numbers: the general path
