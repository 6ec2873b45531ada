"""Run a Fanuc program's *control*: text in, executed and evaluated blocks out.

The Fanuc dialect's language layer, the counterpart of
:mod:`nczones.gcode.program` (whose blocks, spans, sources, plain lane and
fast-run hand-over it shares): it reads the text with
:mod:`nczones.gcode.fanuc.parser`, runs Custom Macro B (variables per call
level, ``IF``/``GOTO``/``WHILE``/``DO``/``END``), the calls (``M98 P L``,
``M98 P30002``, ``M99``, ``M99 P``, ``M97 P``, ``G65``, ``G66``/``G67``,
custom G/M/T codes from the machine file's ``[macros]``, subprograms in the
same file or in a library folder) and yields one
:class:`~nczones.gcode.blocks.Block` per executed NC statement with every
word's value exact:

* a literal as written, except that with ``decimal_point_input =
  "increment"`` (parameter 3401#0 DPI = 0) a length word without a decimal
  point is a count of least input increments (``X100`` is 0.1 mm on an IS-B
  control), and a length literal with more decimals than the increment is
  rounded to it;
* a ``#``/``[...]`` value rounded as the control rounds it: lengths to the
  address's least input increment, integer addresses (M S T H D P L N) to an
  integer, G codes to one decimal; a vacant value drops the word.

Words consumed here, never in a block: ``N``, ``O``, macro statements, the
call words (``G65 G66 G67 M98 M99 M97`` with their ``P``/``L``/arguments, a
custom code with its arguments).  ``#3000 = n (MESSAGE)`` stops the program
(the alarm is recorded, :attr:`FanucRunner.alarm`); ``#3006`` is a stop with
a message (recorded, the run goes on).  Errors are ``GcodeError`` with
``file:line:column``; what cannot be modelled raises
:class:`~nczones.gcode.program.UnsupportedGcode` whose code names the Fanuc
code (``"G66"``, ``"#5405"``, ``"ELSE"``), listed in ``specs/fanuc.md``.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Collection, Generator, Iterator
from fractions import Fraction

from ...blockskip import skipped_switches
from ...errors import Diagnostic, GcodeError, SourceSpan
from ...exact import format_decimal
from ...machine import FanucSettings
from ...precompiled import dataclass, field  # start-up: no dataclasses import
from ..blocks import LANE_FULL
from ..codes import FANUC_CANCEL_CYCLE_G, FANUC_CYCLE_G
from ..expr import EvalError
from ..lexer import make_span, plain_block, plain_block_of, scan_plain
from ..runner_common import (
    DEFAULT_MAX_LOOP_ITERATIONS,
    FastRunRequest,
    IterationBoundExceeded,
    StringSource,
    UnsupportedGcode,
    interpretation_spent,
)
from .expr import (
    COMMON_FIRST,
    COMMON_LAST,
    LOCALS,
    SHADOW_ON_GRID_BOUND,
    VACANT,
    Context,
    FanucVariables,
    RoundingNotCertain,
    SystemVariableUnknown,
    compile_tree,
    denominator_of,
    double_of,
    literal_number,
    round_to,
    value_as_is,
    variable_number,
)
from .parser import EXPR, LITERAL, NEG, VAR, FanucLine, parse_line

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from pathlib import Path
    from typing import Any, Protocol, TypeVar

    from .. import Interpretation

__all__ = ["iter_blocks", "FanucRunner", "LENGTH_LETTERS", "needs_language_layer", "MAX_MACRO_LEVELS",
           "MAX_CALL_DEPTH", "fanuc_notes"]

if TYPE_CHECKING:  # names of annotations only
    _T = TypeVar("_T")
    #: What executing a line yields (blocks) and returns: the next ``(pos, lineno)``, or None at the end.
    _Flow = Generator[Any, None, "tuple[int, int] | None"]

    class _LineSource(Protocol):
        def line_at(self, pos: int) -> tuple[str | None, int]: ...


#: Addresses whose values are lengths or angles: the decimal point input rule and the least input
#: increment apply (``K`` only outside canned cycles, where it is the repeat count).
LENGTH_LETTERS = frozenset("XYZUVWABCIJKRQ")
#: Addresses that take integers: a computed value is rounded to the nearest integer (halves away from 0).
INTEGER_LETTERS = frozenset("MSTHDPLN")
#: Argument specification I (G65/G66): address -> local variable.
ARGUMENTS_I = {"A": 1, "B": 2, "C": 3, "I": 4, "J": 5, "K": 6, "D": 7, "E": 8, "F": 9, "H": 11, "M": 13, "Q": 17,
               "R": 18, "S": 19, "T": 20, "U": 21, "V": 22, "W": 23, "X": 24, "Y": 25, "Z": 26}
#: Macro call levels (G65, G66, custom codes) and all nested calls (with M98/M97), 0i/30i limits.
MAX_MACRO_LEVELS = 5
MAX_CALL_DEPTH = 15
MAX_LOOP_NESTING = 3
MAX_REPORTED_ERRORS = 10
#: Lines kept as closures (FanucRunner.make_op) per run, about 1 KB each: the others run the general path.
MAX_KEPT_LINES = 50_000
#: A line the plain lane must not take: variables, expressions, comments, EOB, program numbers, macro
#: statements, G65-G67.
_PLAIN_BREAKERS = re.compile(r"[#\[(;:%]|[Oo]\d|[Gg][ \t]*0*6[5-7](?![\d.])|(?i:goto|while|end\d|do\d|if)")
#: A length literal without a decimal point (its value depends on the decimal point input setting).
_INT_LENGTH = re.compile(r"[XYZUVWABCIJKRQxyzuvwabcijkrq][ \t]*[+-]?\d+(?![\d.])")
_M_LANGUAGE = frozenset((2, 30, 97, 98, 99))
_CALL_G = frozenset((65, 66, 67))
_CALL_M = frozenset((97, 98, 99))
#: G codes under which a block's words are read specially (G04 seconds, G51 factors, G68 angle, cycles).
_SPECIAL_G = frozenset((4, 51, 68, 73, 74, 76, 81, 82, 83, 84, 85, 86, 87, 88, 89, Fraction("84.2"),
                        Fraction("84.3")))
_END_HINT = re.compile(r"[Mm]0*(?:2|30|99)(?![\d.])|^[ \t]*%")
_LOOP_WORD = re.compile(r"(?i:end|do)[ \t]*\d")
_N_LABEL = re.compile(r"[ \t]*(?:/[1-9]?[ \t]*)?[Nn][ \t]*(\d+)")
_O_LINE = re.compile(r"[ \t]*(?:/[1-9]?[ \t]*)?[Oo:][ \t]*(\d+)")


@dataclass(slots=True)
class _Loop:
    m: int
    head: tuple[int, int]  # (pos, lineno) of the WHILE / DO line
    count: int = 0


class _Source:
    """A program text and its index of program numbers and sequence-number labels."""

    __slots__ = ("src", "file", "programs", "extents", "labels", "cache", "plain", "ops")

    def __init__(self, src: _LineSource, file: str):
        self.src = src
        self.file = file
        self.programs: dict[int, tuple[int, int]] | None = None
        self.extents: list = []  # (start pos, end pos) of each program text: O line to the next O line
        self.labels: dict[int, list] = {}
        self.cache: dict[int, tuple] = {}  # offset -> the compiled line (FanucRunner.compiled)
        #: offset -> (line, next offset, scan_plain of it, lengths_ok metric, lengths_ok inch) of a plain line
        #: that runs again (in a loop or a subprogram; FanucRunner.run)
        self.plain: dict[int, tuple] = {}
        #: offset -> the line run again as one closure (FanucRunner.make_op), or None when it has none
        self.ops: dict[int, Callable[[], Any] | None] = {}

    def index(self) -> None:
        """Find every program number line and every block with a sequence number (once)."""
        if self.programs is not None:
            return
        self.programs = {}
        starts = [0]
        pos, lineno = 0, 1
        while True:
            line, nxt = self.src.line_at(pos)
            if line is None:
                break
            m = _O_LINE.match(line)
            if m is not None:
                self.programs.setdefault(int(m.group(1)), (nxt, lineno + 1))
                if pos and starts[-1] != pos:
                    starts.append(pos)
            else:
                n = _N_LABEL.match(line)
                if n is not None:
                    self.labels.setdefault(int(n.group(1)), []).append((pos, lineno))
            pos, lineno = nxt, lineno + 1
        starts.append(pos + 1)
        self.extents = list(zip(starts[:-1], starts[1:]))

    def program(self, number: int) -> tuple[int, int] | None:
        """Where program ``O<number>`` of this text begins (the line after its number), or None."""
        self.index()
        assert self.programs is not None
        return self.programs.get(number)

    def extent(self, pos: int) -> tuple[int, int]:
        """The text of the program that holds offset ``pos``: from its O line to the next one."""
        self.index()
        for a, b in self.extents:
            if a <= pos < b:
                return a, b
        return (0, 1 << 62)


@dataclass(slots=True)
class _Frame:
    """One program being executed: the main program, a subprogram (M98, M97, a subprogram M code) or a
    macro (G65, G66, a custom G/M/T code), with its source, return point and loops."""

    kind: str
    source: _Source
    program: int | None = None
    ret: tuple[int, int] = (0, 0)
    body: tuple[int, int] = (0, 0)
    repeats: int = 1
    saved: list | None = None  # the caller's local level (macro calls)
    args: dict | None = None
    loops: list = field(default_factory=list)
    custom: bool = False  # called by a custom G/M/T code: such codes are ordinary codes inside


#: Literal G codes of a block that change how its words are read.
#: G84.2/G84.3 (rigid tapping) are canned cycles too: their K is the repeat count.
_CYCLE_G = FANUC_CYCLE_G
_CANCEL_CYCLE_G = FANUC_CANCEL_CYCLE_G
_LATHE_PQ = frozenset((70, 71, 72, 73, 74, 75, 76))
#: Lathe threading codes whose Q is the start angle shift (0.001 deg, without a decimal point), not a length:
#: G32 and G92 (system A), G33 and G78 (system B).
_LATHE_Q_ANGLE = frozenset((32, 33, 78, 92))
#: Lathe cycles whose R is a count or a flag in some forms (G73 R(d) divisions; one-block G71/G72 R1 type II).
_LATHE_R_COUNT = frozenset((71, 72, 73))


class FanucRunner:
    """The Fanuc language layer of one program run (see the module docstring and :func:`iter_blocks`)."""

    def __init__(self, source: _LineSource, file: str, variables: FanucVariables, *,
                 settings: FanucSettings | None = None, block_delete: bool | Collection[int] = False,
                 library: str | os.PathLike | Collection[str] | None = None, state: Any = None,
                 max_loop_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS, first_line: int = 1, first_index: int = 0,
                 fast_runs: dict | None = None, lane: Callable[..., int] | None = None):
        self.settings = settings or FanucSettings()
        self.main = _Source(source, file)
        self.vars = variables
        #: the optional block skip switches that are on (BDT1..BDT9): their '/n' lines are skipped
        self.skipped = skipped_switches(block_delete)
        self.block_delete = 1 in self.skipped  # '/' alone (and '/1'): the plain lanes see only these
        #: the switches of every '/n' line met (run or skipped), library programs included: a proof covers
        #: the switches the main text shows, and a switch only a library program uses must be added to them
        self.seen_switches: set[int] = set()
        #: the library folders, in order (one, or several joined by os.pathsep as --library gives them)
        if library:
            from pathlib import Path  # only for a library (start-up: no pathlib, urllib, ipaddress)
        self.libraries: tuple[Path, ...] = tuple(Path(f) for f in os.fspath(library).split(os.pathsep) if f) \
            if isinstance(library, (str, os.PathLike)) else tuple(Path(f) for f in library or ())
        self.library = self.libraries[0] if len(self.libraries) == 1 else None
        self.state = state  # the interpreter: its units and canned cycle decide how words are read
        self.max_loops = max_loop_iterations
        self.first_line = first_line
        self.index = first_index
        self.fast_runs = fast_runs
        self.lane = lane
        self.frames: list[_Frame] = [_Frame("main", self.main)]
        self.cached = 0  # lines kept compiled (in the sources' caches), bounded
        self.kept_ops = 0  # lines kept as closures (about 1 KB each), bounded by MAX_KEPT_LINES
        self.started = False  # a % line or a block was met: the next % line ends the program
        # a block other than % and O lines ran: the next O line ends the main program (in a piece of a
        # program, the program's own number line is before it)
        self.ran = first_line > 1
        self.jumps_back = 0
        self.modal_call: tuple | None = None  # G66: (program, repeats, args, frame depth it was set at)
        self.alarm: tuple | None = None  # (number, message, span) of a #3000 alarm that stopped the program
        self.stops: list = []  # (number, message, span) of #3006 stops
        self.dpi_words: list = []  # (line, text) of length words without a decimal point (value not 0)
        self.dpi_count = 0
        self.rounded: list = []  # (line, text) of literals rounded to the least input increment
        self.rounded_count = 0
        self.library_sources: dict[int, _Source] = {}
        self._located: dict[tuple[int, int], tuple[Any, Any]] = {}  # locate() per (calling file, program)
        self.ctx = Context(self.settings.atan_signed, self._increment_program_units)
        macros = self.settings.macros
        self.custom_g = {int(k[1:]): v for k, v in macros.items() if k[0] == "G"}
        self.custom_m = {int(k[1:]): v for k, v in macros.items() if k[0] == "M"}
        self.custom_t = macros.get("T")
        self._dpi_increment = self.settings.decimal_point_input == "increment"
        self._inc_mm = self.settings.increment_mm
        self._inc_inch = self._inc_mm / 10
        self._ms = Fraction(1, 1000)
        #: G codes whose block reads a finishing shape between its P and Q sequence numbers (a lathe's
        #: G70-G73), from the interpreter; empty on a mill.
        self.shape_codes: frozenset = frozenset(getattr(state, "shape_codes", ()) or ())
        self.current_pos = 0  # the offset of the line being executed
        digits = {"IS-A": 2, "IS-B": 3, "IS-C": 4}[self.settings.increment_system]
        #: the box route's run reader (boxrun.read_box_run): the decimals a length may have, the layouts read
        self.box_digits = digits
        self.box_layouts: dict[str, Any] = {}
        self.box_keys: Any = None  # the main text cut into lines, their digits zeroed (read_box_run: boxrun._Lines)
        self.box_declined = -1  # the offset where read_box_run last took no line
        self.box_misses = self.box_wait = 0  # attempts in a row that took none; lines to pass before the next
        self._long_mm = re.compile(rf"[XYZUVWABCIJKRQxyzuvwabcijkrq][ \t]*[+-]?\d*\.\d{{{digits + 1}}}")
        self._long_inch = re.compile(rf"[XYZUVWIJKRQxyzuvwijkrq][ \t]*[+-]?\d*\.\d{{{digits + 2}}}|"
                                     rf"[ABCabc][ \t]*[+-]?\d*\.\d{{{digits + 1}}}")

    # -- units -------------------------------------------------------------------------
    def _inch(self) -> bool:
        return bool(getattr(self.state, "inch", False))

    def _increment_program_units(self) -> Fraction:
        inc = self.settings.increment_mm
        return inc / 10 if self._inch() else inc

    def increment(self, letter: str) -> Fraction:
        """The least input increment of an address, in program units (rotary axes in degrees)."""
        if letter in "ABC":
            return self._inc_mm
        return self._inc_inch if self._inch() else self._inc_mm

    # -- diagnostics ---------------------------------------------------------------------
    def span(self, lineno: int, line: str, col: int = 1, end: int | None = None) -> SourceSpan:
        if end is None:
            end = max(col + 1, len(line) + 1)
        return SourceSpan(self.frames[-1].source.file, lineno, col, end, line)

    def error(self, code: str, message: str, lineno: int, line: str, col: int = 1,
              end: int | None = None) -> GcodeError:
        return GcodeError(Diagnostic(code, message, self.span(lineno, line, col, end)))

    def unsupported(self, code: str, message: str, lineno: int, line: str, col: int = 1, end: int | None = None,
                    cls: type[UnsupportedGcode] = UnsupportedGcode) -> UnsupportedGcode:
        return cls(Diagnostic(code, message, self.span(lineno, line, col, end)))

    def syntax_error(self, exc: GcodeError, src: _LineSource, pos: int, lineno: int, file: str) -> GcodeError:
        """``exc`` with the syntax errors of the following lines (up to the program's end)."""
        diags = list(exc.diagnostics)
        while len(diags) < MAX_REPORTED_ERRORS:
            line, pos = src.line_at(pos)
            if line is None:
                break
            lineno += 1
            if _O_LINE.match(line) or _END_HINT.search(line):
                break
            try:
                parse_line(line, lineno, file)
            except GcodeError as e:
                diags.extend(e.diagnostics)
        return GcodeError(diags[:MAX_REPORTED_ERRORS])

    def evaluate(self, fn: Callable[[], _T], lineno: int, line: str, col: int = 1, end: int | None = None) -> _T:
        try:
            return fn()
        except EvalError as e:
            raise self.error(e.code, e.message, lineno, line, col, end) from None
        except SystemVariableUnknown as e:
            raise self.unsupported(e.code, e.reason, lineno, line, col, end) from None
        except RecursionError:
            raise self.error("GC312", "expression nested too deeply", lineno, line, col, end) from None

    # -- compiled lines ---------------------------------------------------------------------
    def compiled(self, source: _Source, pos: int, line: str, lineno: int, nxt: int) -> tuple:
        """The line at ``pos`` parsed, its expressions compiled (kept for lines that run again)."""
        hit: tuple | None = source.cache.get(pos)
        if hit is not None:
            return hit
        try:
            fl = parse_line(line, lineno, source.file)
        except GcodeError as e:
            raise self.syntax_error(e, source.src, nxt, lineno, source.file) from None
        v, ctx = self.vars, self.ctx
        words = []
        for w in fl.words:
            if w[1] == EXPR:
                var = _negated_variable(w[2])
                words.append((w[0], EXPR, compile_tree(w[2], v, ctx, True), w[3], w[4], w[5],
                              compile_tree(var, v, ctx) if var is not None else None))
            else:
                words.append(w + (None,))
        assigns = tuple((_target(a[0], v, ctx), compile_tree(a[1], v, ctx), a[2], a[3]) for a in fl.assigns)
        stmt = fl.stmt
        if stmt is not None:
            kind = stmt[0]
            if kind == "goto":
                stmt = ("goto", compile_tree(stmt[1], v, ctx))
            elif kind == "if":
                then = stmt[2]
                if then[0] == "goto":
                    then = ("goto", compile_tree(then[1], v, ctx))
                else:
                    then = ("assign", tuple((_target(a[0], v, ctx), compile_tree(a[1], v, ctx), a[2], a[3])
                                            for a in then[1]))
                stmt = ("if", compile_tree(stmt[1], v, ctx, exact=False), then)  # (its double only is read)
            elif kind == "while":
                stmt = ("while", compile_tree(stmt[1], v, ctx, exact=False), stmt[2])
        gcodes = {w[2][0] for w in fl.words if w[0] == "G" and w[1] == LITERAL}
        # which checks a block of this line needs: the G65-G67/M97-M99/custom code calls (a computed G, M or
        # T word, or a literal one of them), the canned cycle (K), the special readings of G04/G51/G68
        calls = (self.custom_t is not None and any(w[0] == "T" for w in fl.words)) or any(
            w[0] in "GM" and (w[1] == EXPR or w[2][0] in (_CALL_G if w[0] == "G" else _CALL_M)
                              or w[2][0] in (self.custom_g if w[0] == "G" else self.custom_m))
            for w in fl.words)
        # a lathe's G70-G76 read P, Q and some R words as sequence numbers and counts (word_values)
        plain = not (gcodes & _SPECIAL_G) and not any(w[0] == "K" for w in fl.words) and not (
            self.shape_codes and gcodes & (_LATHE_PQ | _LATHE_Q_ANGLE) and any(w[0] in "QR" for w in fl.words))
        # an NC line the run hands to the interpreter's plain-move lane (no macro statement, call, M code or
        # special G code; words evaluated by plain_values): FanucRunner.run
        simple = (bool(words) and plain and not calls and not assigns and stmt is None and not fl.delete
                  and not fl.percent and fl.program is None and fl.unmodelled is None
                  and not any(w[0] == "M" for w in fl.words))
        out = (fl, tuple(words), assigns, stmt, line, nxt, gcodes, calls, plain, simple)
        if self.cached < 200_000:
            source.cache[pos] = out
            self.cached += 1
        return out

    # -- lines run again, as closures ---------------------------------------------------------
    # A line that runs a second time (in a loop, a subprogram, a macro) is kept as one closure of no
    # arguments (``source.ops``) doing what the general path does with it: it returns the next
    # ``(pos, lineno)`` in the same text (the same frame, or a call or a return whose frame reads this text:
    # ``source.ops`` stays the closures of the top frame's text); ``[pos_lineno, None]`` after a call or a return
    # into another text (a library file);
    # ``[here]`` when the plain-move lane took its motion and the chunk is full (run() yields LANE_FULL);
    # ``[here, block]`` when the lane declined it (run() yields the block); or None,
    # having changed nothing, when the general path must run the line this time (the first entry of a
    # loop, an error to report with its span, a vacant word that shifts an argument, a bound reached, a
    # state the closure does not cover: G66, a unit system whose literals need rounding, ...).
    def add_op(self, source: _Source, pos: int, lineno: int, entry: tuple) -> None:
        """Keep the line at ``pos`` (its compiled entry, or its ``source.plain`` entry) as a closure."""
        if self.cached >= 200_000 or self.kept_ops >= MAX_KEPT_LINES:
            source.ops[pos] = None
            return
        self.cached += 1
        self.kept_ops += 1
        source.ops[pos] = self.plain_op(source, lineno, entry) if len(entry) == 5 else self.make_op(
            source, pos, lineno, entry)

    def make_op(self, source: _Source, pos: int, lineno: int, compiled: tuple) -> Callable[[], Any] | None:
        """:meth:`make_op_of`'s closure; for a line with an N and no NC word, one that first records the N as
        :meth:`execute` does (:meth:`number_alone`)."""
        op = self.make_op_of(source, pos, lineno, compiled)
        fl = compiled[0]
        if op is None or compiled[1] or fl.number is None:
            return op
        number, record = fl.number, self.number_alone

        def numbered() -> Any:
            record(number)
            return op()
        return numbered

    def make_op_of(self, source: _Source, pos: int, lineno: int, compiled: tuple) -> Callable[[], Any] | None:
        fl, words, assigns, stmt, line, nxt, _gcodes, calls, plain, simple = compiled
        if fl.delete or fl.percent or fl.program is not None or fl.unmodelled is not None:
            return None
        here = (nxt, lineno + 1)
        if words:
            if assigns or stmt is not None:
                return None
            if simple:
                return None if self.shape_codes else self.nc_op(source, pos, lineno, compiled, here)
            if calls and plain:
                return self.call_op(source, pos, lineno, compiled, here)
            return None
        if stmt is None:
            return self.assign_op(fl.assigns, assigns, here, None)
        if assigns:
            return None
        kind = stmt[0]
        if kind == "while":
            return self.while_op(source, pos, lineno, stmt, here, line)
        if kind == "end":
            return self.end_op(stmt[1])
        if kind == "if" and stmt[2][0] == "assign":
            return self.assign_op(fl.stmt[2][1], stmt[2][1], here, stmt[1])
        return None

    def assign_op(self, raw: tuple, assigns: tuple, here: tuple[int, int],
                  cond: Callable[[], tuple] | None) -> Callable[[], Any] | None:
        """``#n = value`` (n a local or common variable written as a number), or ``IF [cond] THEN #n =
        value``, or a line with nothing to execute (a comment, a sequence number alone)."""
        runner, variables = self, self.vars
        if not assigns:
            def nothing() -> Any:
                runner.started = runner.ran = True
                return here
            return nothing
        if len(assigns) != 1:
            return None
        n = _static_index(raw[0][0])
        if n is None or not (0 < n <= LOCALS or COMMON_FIRST <= n <= COMMON_LAST):
            return None
        value = assigns[0][1]
        common = variables.common
        local = n <= LOCALS

        def assign() -> Any:
            try:
                if cond is not None and cond()[0] == 0.0:
                    runner.started = runner.ran = True
                    return here
                v = value()
            except _EVAL_ERRORS:
                return None
            if variables.on_write is not None:
                return None
            if local:
                variables.local[n] = v
            else:
                common[n] = v
            runner.started = runner.ran = True
            return here
        return assign

    def while_op(self, source: _Source, pos: int, lineno: int, stmt: tuple, here: tuple[int, int],
                 line: str) -> Callable[[], Any] | None:
        """``WHILE [cond] DOm`` met again at the head of its loop (``statement``'s loop bookkeeping, the END
        found once)."""
        m = stmt[2]
        if m not in (1, 2, 3):
            return None
        try:
            end_pos, end_line = self.find_end(source, m, here[0], lineno + 1, lineno, line)
        except GcodeError:
            return None
        after = (source.src.line_at(end_pos)[1], end_line + 1)
        head = (pos, lineno)
        cond = stmt[1]
        runner, frames, bound = self, self.frames, self.max_loops

        def loop_head() -> Any:
            loops = frames[-1].loops
            if not loops:
                return None
            loop = loops[-1]
            if loop.head != head:
                return None
            try:
                c = cond()
            except _EVAL_ERRORS:
                return None
            if c[0] != 0.0:
                if loop.count >= bound or interpretation_spent() is not None:
                    return None  # the general path counts it and stops there
                loop.count += 1
                runner.started = runner.ran = True
                return here
            loops.pop()
            runner.started = runner.ran = True
            return after
        return loop_head

    def end_op(self, m: int) -> Callable[[], Any] | None:
        """``ENDm`` of the innermost open loop: back to its head."""
        if m not in (1, 2, 3):
            return None
        runner, frames = self, self.frames

        def loop_end() -> Any:
            loops = frames[-1].loops
            if not loops or loops[-1].m != m:
                return None
            runner.started = runner.ran = True
            return loops[-1].head
        return loop_end

    def word_specs(self, words: tuple) -> list | None:
        """Per word of a plain NC line: ``(value, None, None)`` for a literal whose value does not depend on
        the unit system and is not noted (else None for the whole line), ``(None, fn, var, step)`` for an
        expression: ``step`` the increment it is rounded to, :data:`_UNITS` for the linear axes' (inch or
        metric), None for an address that takes the value as it is (``plain_values``)."""
        specs: list = []
        for letter, kind, payload, _col, _end, _text, var in words:
            if kind == EXPR:
                if letter in LENGTH_LETTERS:
                    step: Any = self._inc_mm if letter in "ABC" else _UNITS
                elif letter in INTEGER_LETTERS:
                    step = _ONE
                elif letter == "G":
                    step = _TENTH
                else:
                    step = None
                specs.append((None, payload, var, step))
                continue
            q, point = payload
            if letter in LENGTH_LETTERS:
                if not point:
                    if q:
                        return None  # counted (and scaled) per execution by literal()
                else:
                    for inc in ((self._inc_mm,) if letter in "ABC" else (self._inc_mm, self._inc_inch)):
                        if (q.numerator * inc.denominator) % (q.denominator * inc.numerator):
                            return None  # rounded (and counted) per execution by literal()
            specs.append((q, None, None, None))
        return specs

    def nc_op(self, source: _Source, pos: int, lineno: int, compiled: tuple,
              here: tuple[int, int]) -> Callable[[], Any] | None:
        """An NC line with expressions for the plain-move lane (run()'s ``compiled[9]`` branch)."""
        words, line, number = compiled[1], compiled[4], compiled[0].number
        specs = self.word_specs(words)
        if specs is None:
            return None
        base = [s[0] for s in specs]
        exprs = tuple((i, s[1], s[2], s[3], _step_denominator(s[3])) for i, s in enumerate(specs) if s[1] is not None)
        letters_all = "".join([w[0] for w in words])
        meta = [(w[0], w[3], w[4], w[5]) for w in words]
        span = make_span(source.file, lineno, 1, len(line) + 1, line)
        runner, lane, state = self, self.lane, self.state
        inc_mm, inc_inch = self._inc_mm, self._inc_inch
        usd_mm, usd_inch = _step_denominator(inc_mm), _step_denominator(inc_inch)
        bound = SHADOW_ON_GRID_BOUND

        def nc_line() -> Any:
            if runner.modal_call is not None:
                return None
            vals = base[:]
            dropped = False
            inc, usd = (inc_inch, usd_inch) if getattr(state, "inch", False) else (inc_mm, usd_mm)
            try:
                for i, fn, var, step, sd in exprs:
                    v = fn()
                    if v is VACANT or (var is not None and var() is VACANT):
                        vals[i] = _DROPPED  # a vacant variable drops its word
                        dropped = True
                    elif step is None:
                        q = v[1]
                        vals[i] = q if q is not None else value_as_is(v, letters_all[i])
                    else:
                        if step is _UNITS:
                            step, sd = inc, usd
                        q = v[1]
                        # round_to's first case (a multiple of the step, kept as it is) without the call
                        vals[i] = q if q is not None and sd and not sd % denominator_of(q) and \
                            -bound < v[0] < bound else round_to(v, step)
            except _EVAL_ERRORS:
                return None
            if dropped:
                keep = [i for i, q in enumerate(vals) if q is not _DROPPED]
                letters = "".join([letters_all[i] for i in keep])
                values = tuple([vals[i] for i in keep])
            else:
                keep, letters, values = None, letters_all, tuple(vals)
            runner.current_pos = pos
            runner.started = runner.ran = True
            index = runner.index
            taken = lane(letters, values, span, index) if lane is not None and values else 0
            if taken:
                runner.index = index + 1
                if number is not None:
                    runner.lane_number(number)
                return here if taken == 1 else [here]
            rows = [(meta[i][0], vals[i]) + meta[i][1:] for i in (keep if keep is not None else range(len(vals)))]
            return [here, plain_block_of(rows, span, index, number)]
        return nc_line

    def plain_op(self, source: _Source, lineno: int, hit: tuple) -> Callable[[], Any] | None:
        """A plain line (``source.plain``) for the plain-move lane: what run() does with it."""
        line, nxt, parsed, ok_mm, ok_inch = hit
        delete, number, letters, values = parsed
        if delete or not letters or not (ok_mm or ok_inch):
            return None
        # plain_words_ok depends on the run's state only through in_custom() (custom G and T codes)
        moving = bool(self.custom_g) or self.custom_t is not None
        if not moving and not self.plain_words_ok(letters, values):
            return None
        here = (nxt, lineno + 1)
        span = make_span(source.file, lineno, 1, len(line) + 1, line)
        runner, lane, state = self, self.lane, self.state

        def plain_line() -> Any:
            if runner.modal_call is not None or not (ok_inch if getattr(state, "inch", False) else ok_mm):
                return None
            if moving and not runner.plain_words_ok(letters, values):
                return None
            runner.started = runner.ran = True
            index = runner.index
            taken = lane(letters, values, span, index) if lane is not None else 0
            if taken:
                runner.index = index + 1
                if number is not None:
                    runner.lane_number(number)
                return here if taken == 1 else [here]
            return [here, plain_block(letters, values, span, index, number, None)]
        return plain_line

    def call_op(self, source: _Source, pos: int, lineno: int, compiled: tuple,
                here: tuple[int, int]) -> Callable[[], Any] | None:
        """A bare ``M99``, an ``M98 P<n>`` alone, a ``G65 P<n> [L<n>] arguments`` (``execute``'s call lines)."""
        words, line = compiled[1], compiled[4]
        w = words[0]
        if w[1] != LITERAL:
            return None
        if w[0] == "M" and len(words) == 1 and w[2][0] == 99:
            return self.m99_op(pos, source)
        if w[0] == "M" and len(words) == 2 and w[2][0] == 98 and words[1][0] == "P" and words[1][1] == LITERAL:
            return self.m98_op(source, pos, lineno, line, words[1][2][0], here)
        if w[0] == "G" and w[2][0] == 65:
            return self.g65_op(source, pos, lineno, line, words, here)
        return None

    def m99_op(self, pos: int, source: _Source) -> Callable[[], Any] | None:
        """A bare ``M99`` ending the last (or only) repetition of a subprogram or macro call (to a caller in the
        same text: its ``(pos, lineno)``, run() goes on with that frame's closures, which are this text's)."""
        runner, frames, variables = self, self.frames, self.vars

        def m99() -> Any:
            frame = frames[-1]
            if frame.repeats != 1 or frame.kind == "main":
                return None
            runner.current_pos = pos
            runner.started = runner.ran = True
            frame.repeats = 0
            frames.pop()
            if frame.saved is not None:
                variables.pop_level(frame.saved)
            return frame.ret if frames[-1].source is source else [frame.ret, None]
        return m99

    def m98_op(self, source: _Source, pos: int, lineno: int, line: str, p: Fraction,
               here: tuple[int, int]) -> Callable[[], Any] | None:
        """``M98 P<n>`` (``m98`` and ``call_sub``: the program found once; in the same text, the body's
        ``(pos, lineno)``: run() goes on with the same closures)."""
        if p.denominator != 1 or p < 0:
            return None
        count, program = divmod(int(p), 10000) if p > 9999 else (1, int(p))
        if count == 0 or count > self.max_loops:
            return None
        try:
            target, body = self.locate(program, lineno, line, "M98")
        except GcodeError:
            return None
        runner, frames = self, self.frames
        jump = body if target is source else [body, None]  # (a list: run() takes the new frame's lines)

        def m98() -> Any:
            if len(frames) >= MAX_CALL_DEPTH:
                return None
            runner.current_pos = pos
            runner.started = runner.ran = True
            frames.append(_Frame("m98", target, program, here, body, count))
            return jump
        return m98

    def g65_op(self, source: _Source, pos: int, lineno: int, line: str, words: tuple,
               here: tuple[int, int]) -> Callable[[], Any] | None:
        """``G65 P<n> [L<n>]`` and its arguments (``calls``, ``call_words``, ``arguments``, ``call_macro``:
        the argument letters mapped to variables and the program found once)."""
        pword = lword = None
        rest = []
        for w in words[1:]:
            if w[0] == "P" and pword is None:
                pword = w
            elif w[0] == "L" and lword is None:
                lword = w
            elif w[0] == "G":
                return None
            else:
                rest.append(w)
        if pword is None or pword[1] != LITERAL or (lword is not None and lword[1] != LITERAL):
            return None
        p, repeats = pword[2][0], lword[2][0] if lword is not None else _ONE
        if p.denominator != 1 or p < 0 or repeats.denominator != 1 or not 0 < repeats <= self.max_loops:
            return None
        specs = self.word_specs(tuple(rest))
        if specs is None:
            return None
        args = _argument_specs(rest, specs)
        if args is None:
            return None
        program, count = int(p), int(repeats)
        try:
            target, body = self.locate(program, lineno, line, "G65")
        except GcodeError:
            return None
        runner, frames, variables, state = self, self.frames, self.vars, self.state
        inc_mm, inc_inch = self._inc_mm, self._inc_inch
        usd_mm, usd_inch = _step_denominator(inc_mm), _step_denominator(inc_inch)
        jump = body if target is source else [body, None]  # (as m98_op's)
        bound = SHADOW_ON_GRID_BOUND

        def g65() -> Any:
            values = [VACANT] * (LOCALS + 1)  # the macro's local level: its arguments, the others vacant
            inc, usd = (inc_inch, usd_inch) if getattr(state, "inch", False) else (inc_mm, usd_mm)
            try:
                for n, const, fn, var, step, shifts, sd in args:
                    if fn is None:
                        values[n] = const
                        continue
                    v = fn()
                    if v is VACANT or (var is not None and var() is VACANT):
                        if shifts:
                            return None  # the later I, J, K words move up a set: the general path
                        continue  # a vacant variable drops its word
                    if step is None:
                        q = v[1]
                        q = q if q is not None else value_as_is(v, f"G65 argument #{n}")
                    else:
                        if step is _UNITS:
                            step, sd = inc, usd
                        q = v[1]
                        if q is None or not sd or sd % denominator_of(q) or not -bound < v[0] < bound:
                            q = round_to(v, step)  # else kept as round_to keeps it
                    values[n] = (double_of(q), q)
            except _EVAL_ERRORS:
                return None
            if len(frames) > MAX_MACRO_LEVELS and (len(frames) >= MAX_CALL_DEPTH or sum(
                    1 for f in frames if f.saved is not None) >= MAX_MACRO_LEVELS):  # (main is no macro)
                return None
            runner.current_pos = pos
            runner.started = runner.ran = True
            # the arguments (call_macro's dict) are read again only to repeat the macro (L2 and up)
            passed = {k: v for k, v in enumerate(values) if v is not VACANT} if count > 1 else None
            frames.append(_Frame("macro", target, program, here, body, count, variables.local, passed))
            variables.enter_level(values)
            return jump
        return g65

    # -- the run -------------------------------------------------------------------------
    def run(self) -> Iterator:
        pos, lineno = 0, self.first_line
        main_src = self.main.src
        fast = self.fast_runs
        declined = -1
        frames = self.frames
        box_run = self.box_reader()
        while True:
            frame = frames[-1]
            source = frame.source
            ops = source.ops
            op = ops.get(pos)
            r: Any = None
            while op is not None:  # lines run before, as closures (make_op), in this frame
                r = op()
                if r.__class__ is not tuple:
                    break
                pos, lineno = r
                op = ops.get(pos)
            if op is None or r is None:  # the general path for the line at pos
                r = None
                frame = frames[-1]  # (a call or a return within one text stays in the loop above)
                source = frame.source
                ops = source.ops
                compiled = source.cache.get(pos)
                if compiled is not None and pos not in ops and not (fast and pos in fast):
                    self.add_op(source, pos, lineno, compiled)  # run again: kept as one closure from now on
                if compiled is None or (fast and pos in fast):  # a line not run before, or a fast run's start
                    if fast and source.src is main_src and pos in fast and pos != declined:
                        req = FastRunRequest(pos, lineno, self.index)
                        yield req
                        if req.resume is not None:
                            pos, lineno, self.index = req.resume
                            self.started = self.ran = True
                            declined = -1
                            continue
                        declined = pos
                    r = box_run(frame, pos, lineno) if box_run is not None else None
                    if r is None:
                        got = self.read_plain(frame, pos, lineno, not (fast and pos in fast))
                        if got is None:
                            self.end_of_text(lineno)
                            return
                        line, nxt, parsed, ok = got
                        if ok:
                            r = self.plain_first(source, line, nxt, parsed, lineno)
                        else:
                            compiled = self.compiled(source, pos, line, lineno, nxt)
                if r is None:
                    assert compiled is not None
                    if compiled[9] and self.modal_call is None and not self.shape_codes:
                        r = self.nc_first(source, compiled, pos, lineno)
                    else:
                        if compiled[1] or compiled[0].percent or compiled[0].program is not None:
                            target = yield from self.execute(compiled, pos, lineno)
                        else:
                            target = self.macro_line(compiled, pos, lineno)  # no generator for a macro-only line
                        if target is None:
                            return
                        pos, lineno = target
                        continue
                if r.__class__ is tuple:
                    pos, lineno = r
                    continue
            # a list (a closure's or plain_first's / nc_first's): a call or a return, or something to yield
            pos, lineno = r[0]
            if len(r) == 1:  # the lane took the motion and its chunk is full
                yield LANE_FULL
            elif r[1] is not None:  # the lane declined the motion: its block
                yield r[1]
                self.index += 1

    def box_reader(self) -> Callable[..., Any] | None:
        """:meth:`box_run` when the interpreter's plain lane writes boxes (``columns.BoxSink``: the numpy-free box
        route) of a main text held as a string, else None."""
        sink = getattr(self.state, "row_sink", None)
        if sink is None or not getattr(sink, "arcs", False) or self.fast_runs or type(self.main.src) is not StringSource \
                or self.main.file != getattr(self.state, "file", None) or "#" in self.main.src.text:
            return None  # (a macro program's plain lines run in its loops and calls, which the reader leaves)
        from . import boxrun

        return self.box_run if boxrun.BOX_RUNS else None

    def box_run(self, frame: _Frame, pos: int, lineno: int) -> Any:
        """A run of plain lines of the main text from ``pos`` read by :func:`nczones.gcode.fanuc.boxrun.read_box_run`
        (outside loops and calls): as a closure's result (``(pos, lineno)`` after it, ``[(pos, lineno)]`` when the
        chunk is full), or None when it takes no line (it is not asked again at that line; after 8k attempts in a row
        that took none, the next k lines are not tried: a program it declines line by line, G91 say, costs little)."""
        if pos == self.box_declined or len(self.frames) != 1 or frame.loops or frame.source is not self.main:
            return None
        if self.box_wait:  # lines since the last attempt that took none (a run of lines it declines costs little)
            self.box_wait -= 1
            return None
        from .boxrun import read_box_run

        got = read_box_run(self, self.main.src.text, pos, lineno)  # type: ignore[attr-defined]  # a StringSource
        if got is None:
            self.box_declined = pos
            self.box_misses += 1
            self.box_wait = self.box_misses // 8
            return None
        self.box_misses = 0
        return [got[:2]] if got[2] else got[:2]

    def plain_first(self, source: _Source, line: str, nxt: int, parsed: tuple, lineno: int) -> Any:
        """A plain line the plain lane takes (read_plain), not kept as a closure: as a closure's result
        (``here``, ``[here]`` after a full chunk, ``[here, block]`` when the lane declines)."""
        delete, number, letters, values = parsed
        here = (nxt, lineno + 1)
        if (delete and self.skips(1)) or not letters:
            if number is not None and not (delete and self.skips(1)):
                self.number_alone(number)
            return here
        self.started = self.ran = True
        span = make_span(source.file, lineno, 1, len(line) + 1, line)
        index = self.index
        taken = self.lane(letters, values, span, index) if self.lane is not None else 0
        if not taken:
            return [here, plain_block(letters, values, span, index, number, None)]
        self.index = index + 1
        if number is not None:
            self.lane_number(number)
        return here if taken == 1 else [here]

    def nc_first(self, source: _Source, compiled: tuple, pos: int, lineno: int) -> Any:
        """An NC line with expressions (X#3 Y[#1 * 2]) not kept as a closure: what execute() -> nc() -> block()
        do with it, its values handed to the plain-move lane without a block (the block when the lane
        declines); the result as plain_first's."""
        line, nxt = compiled[4], compiled[5]
        try:
            values = self.plain_values(compiled[1], lineno, line)
        except RoundingNotCertain as e:
            raise self.unsupported(e.code, e.reason, lineno, line) from None
        self.current_pos = pos
        self.started = self.ran = True
        span = make_span(source.file, lineno, 1, len(line) + 1, line)
        index = self.index
        lane = self.lane
        taken = lane("".join([v[0] for v in values]), tuple([v[1] for v in values]), span,
                     index) if lane is not None and values else 0
        here = (nxt, lineno + 1)
        if not taken:
            return [here, plain_block_of(values, span, index, compiled[0].number)]
        self.index = index + 1
        if compiled[0].number is not None:
            self.lane_number(compiled[0].number)
        return here if taken == 1 else [here]

    def number_alone(self, number: Fraction) -> None:
        """A line with an N and no NC word (``N25`` alone, or with macro statements only: no block for this
        reader), kept beside the last block's N as ``last["N*"]`` (until a block's N, :meth:`lane_number`,
        ``Interpreter.keep_number``): whether the control's ``#4114`` then holds it is not settled, so a read where
        the two readings differ is unknown (:func:`nczones.gcode.fanuc.system.read`)."""
        last = getattr(self.state, "last", None)
        if last is not None:
            last["N*"] = number

    def lane_number(self, number: Fraction) -> None:
        """The N of a block the plain-move lane took, kept as the general path's ``_record_block`` keeps it: the
        last sequence number a macro reads (``#4114``)."""
        last = getattr(self.state, "last", None)
        if last is not None:
            last["N"] = number
            last.pop("N*", None)  # a block's N settles a line's alone (number_alone)

    def read_plain(self, frame: _Frame, pos: int, lineno: int, may_keep: bool) -> tuple | None:
        """The line at ``pos`` (not run before as a compiled line) for run(): ``(line, next offset, its
        scan_plain or None, whether the plain lane takes it)``, or None at the end of the text.  A plain line
        that runs again is kept scanned (``source.plain``) and, run a second time, as a closure (``may_keep``:
        not the start of a fast run)."""
        source = frame.source
        hit = source.plain.get(pos)
        if hit is not None:  # a plain line run before (in a loop or a subprogram)
            if may_keep and pos not in source.ops:
                self.add_op(source, pos, lineno, hit)
            parsed = hit[2]
            return hit[0], hit[1], parsed, self.modal_call is None and (
                hit[4] if self._inch() else hit[3]) and self.plain_words_ok(parsed[2], parsed[3])
        line, nxt = source.src.line_at(pos)
        if line is None:
            return None
        parsed = None
        if self.modal_call is None and not _PLAIN_BREAKERS.search(line):
            parsed = scan_plain(line)
        ok = parsed is not None and self.plain_ok(parsed[2], parsed[3], line)
        if parsed is not None and (frame.loops or len(self.frames) > 1) and self.cached < 200_000:
            # the line runs again: keep its scan and which unit systems its literals pass in
            source.plain[pos] = (line, nxt, parsed, self.lengths_ok(line, False), self.lengths_ok(line, True))
            self.cached += 1
        return line, nxt, parsed, ok

    def plain_ok(self, letters: str, values: tuple, line: str) -> bool:
        """Whether a plain line's values are its words' values and the line does nothing the general path
        must see: no length literal without a decimal point or with more decimals than the increment, no
        program end, call or custom code, no lathe cycle that reads a shape."""
        return self.lengths_ok(line, self._inch()) and self.plain_words_ok(letters, values)

    def lengths_ok(self, line: str, inch: bool) -> bool:
        """No length literal of the line without a decimal point or with more decimals than the increment
        (in inch or metric input)."""
        return not (_INT_LENGTH.search(line) or (self._long_inch if inch else self._long_mm).search(line))

    def plain_words_ok(self, letters: str, values: tuple) -> bool:
        """:meth:`plain_ok` but for the literals' text: no program end, call or custom code, no G51, no lathe
        cycle that reads a shape (this depends on the state: it is checked on every run of a line)."""
        if "G" in letters:
            # G51's P (and I J K) without a decimal point is in scaling_unit (word_values): the plain lane
            # would read P3 as the factor 3
            i = letters.find("G")
            while i >= 0:
                if values[i] == 51:
                    return False
                i = letters.find("G", i + 1)
        if self.shape_codes and "G" in letters:
            i = letters.find("G")
            while i >= 0:
                if values[i] in self.shape_codes:
                    return False
                i = letters.find("G", i + 1)
        if "M" in letters:
            i = letters.find("M")
            while i >= 0:
                v = values[i]
                if v._denominator != 1 or v._numerator in _M_LANGUAGE or v._numerator in self.custom_m:
                    return False
                i = letters.find("M", i + 1)
        if self.custom_g and "G" in letters:
            i = letters.find("G")
            while i >= 0:
                v = values[i]
                if v._denominator == 1 and v._numerator in self.custom_g and not self.in_custom():
                    return False
                i = letters.find("G", i + 1)
        if self.custom_t is not None and "T" in letters and not self.in_custom():
            return False
        return True

    def in_custom(self) -> bool:
        return any(f.custom for f in self.frames)

    def end_of_text(self, lineno: int) -> None:
        """The end of the current source: the end of the program, or an error in a subprogram or loop."""
        frame = self.frames[-1]
        if frame.loops:
            loop = frame.loops[-1]
            raise GcodeError(Diagnostic("GC314", f"end of the program inside the DO{loop.m} loop; END{loop.m} is "
                                        "missing", SourceSpan(frame.source.file, loop.head[1], 1)))
        if len(self.frames) > 1:
            raise GcodeError(Diagnostic("GC314", f"end of the text inside subprogram O{frame.program}: M99 is "
                                        "missing", SourceSpan(frame.source.file, lineno, 1)))

    def skips(self, switch: int) -> bool:
        """Whether a line starting with ``/switch`` is skipped (its switch on); the switch is recorded."""
        self.seen_switches.add(switch)
        return switch in self.skipped

    # -- one general line -------------------------------------------------------------------
    def execute(self, compiled: tuple, pos: int, lineno: int) -> _Flow:
        fl, words, assigns, stmt, line, nxt, gcodes, maybe_calls, plain = compiled[:9]
        self.current_pos = pos
        frame = self.frames[-1]
        here = (nxt, lineno + 1)
        if fl.delete and self.skips(fl.delete):
            return here
        if fl.percent:
            if self.started:
                return None
            self.started = True
            return here
        if fl.program is not None:
            if not self.ran:
                self.started = True
                return here
            if frame.kind == "main":
                return None  # the main program's text ends where the next program begins
            raise self.error("GC314", f"subprogram O{frame.program} runs into program O{fl.program} without M99",
                             lineno, line)
        if fl.unmodelled is not None:
            reason, col, end = fl.unmodelled
            raise self.unsupported(reason.split()[3], reason, lineno, line, col, end)
        if not words and fl.number is not None:
            self.number_alone(fl.number)
        if words and assigns:
            raise self.unsupported("macro", "an NC statement and a macro assignment in one block: Fanuc controls "
                                   "alarm (PS0114), Haas executes both; their order is not modelled",
                                   lineno, line, assigns[0][2], assigns[0][3])
        self.started = self.ran = True
        for target, value, col, end in assigns:
            if self.assign(target, value, lineno, line, col, end, fl):
                return None  # #3000 alarm
        if stmt is not None:
            return self.statement(stmt, fl, pos, lineno, line, nxt)
        if not words:
            return here
        if maybe_calls and len(words) <= 2:
            w = words[0]
            if len(words) == 1 and w[0] == "M" and w[1] == LITERAL and w[2][0] == 99:
                # a bare M99 (the end of every subprogram): what calls() does with it, without building the
                # block's value list (M99 is a call code before any custom M code; no other word runs)
                return self.return_m99(None, ("M", w[2][0], w[3], w[4], w[5]), lineno, line, nxt)
            if len(words) == 2 and w[0] == "M" and w[1] == LITERAL and w[2][0] == 98 and words[1][0] == "P" \
                    and words[1][1] == LITERAL:
                # M98 P<n>: what calls() does with it (M98 before any custom code; P the only other word)
                p = words[1]
                return self.m98(("P", p[2][0], p[3], p[4], p[5]), None, ("M", w[2][0], w[3], w[4], w[5]), lineno,
                                line, here)
        try:
            values = self.plain_values(words, lineno, line) if plain else self.word_values(words, gcodes, lineno, line)
        except RoundingNotCertain as e:
            raise self.unsupported(e.code, e.reason, lineno, line) from None
        if maybe_calls:
            calls = [v for v in values if v[0] == "G" and v[1] in (65, 66, 67)]
            if calls or self.has_call_code(values):
                return (yield from self.calls(values, calls, fl, lineno, line, nxt))
        return (yield from self.nc(values, fl, lineno, line, nxt))

    def plain_values(self, words: tuple, lineno: int, line: str) -> list:
        """:meth:`word_values` of a block with no G04, G51, G68, canned cycle code or K word."""
        values = []
        inc = None  # the linear axes' increment (read once per block)
        for letter, kind, payload, col, end, text, var in words:
            if kind == EXPR:
                try:
                    value = payload()
                except (EvalError, SystemVariableUnknown, RecursionError):
                    value = self.evaluate(payload, lineno, line, col, end)  # raises the diagnostic
                if value is VACANT or (var is not None and self.evaluate(var, lineno, line, col, end) is VACANT):
                    continue  # a vacant variable drops its word
                if letter in LENGTH_LETTERS:
                    if letter in "ABC":
                        q = round_to(value, self._inc_mm)
                    else:
                        if inc is None:
                            inc = self._inc_inch if self._inch() else self._inc_mm
                        q = round_to(value, inc)
                else:
                    q = self.address_value(letter, value, False)
            else:
                q, point = payload
                if letter in LENGTH_LETTERS:
                    q = self.literal(letter, q, point, lineno, text)
            values.append((letter, q, col, end, text))
        return values

    def macro_line(self, compiled: tuple, pos: int, lineno: int) -> tuple[int, int] | None:
        """A line without NC words (assignments, IF, GOTO, WHILE, DO, END, comments): the next
        ``(pos, lineno)``, or None when a #3000 alarm stops the program."""
        fl, _words, assigns, stmt, line, nxt = compiled[:6]
        if fl.delete and self.skips(fl.delete):
            return nxt, lineno + 1
        if fl.unmodelled is not None:
            reason, col, end = fl.unmodelled
            raise self.unsupported(reason.split()[3], reason, lineno, line, col, end)
        self.started = self.ran = True
        if fl.number is not None:
            self.number_alone(fl.number)
        for target, value, col, end in assigns:
            if self.assign(target, value, lineno, line, col, end, fl):
                return None  # #3000 alarm
        if stmt is not None:
            return self.statement(stmt, fl, pos, lineno, line, nxt)
        return nxt, lineno + 1

    def word_values(self, words: tuple, gcodes: set, lineno: int, line: str) -> list:
        """The block's words ``(letter, exact value, column, end column, text)`` as the control reads them."""
        in_cycle = getattr(self.state, "in_cycle", None)
        lathe = bool(self.shape_codes)
        cycle = not lathe and (bool(gcodes & _CYCLE_G) or (not (gcodes & _CANCEL_CYCLE_G) and in_cycle is not None
                                                            and in_cycle()))
        # a lathe's G70-G76 read P and Q as sequence numbers or counts of the least increment, not lengths
        # ([0i-T] "Multiple repetitive cycle": ns/nf, G74/G75 Δi Δk and G76 Δdmin, k, Δd "without a decimal
        # point"); R is a count in G73's first block (d, the number of divisions) and a flag in the one-block
        # G71/G72/G73 form with P and Q (R1: type II); R of G71/G72/G74-G76 without P/Q is a length (e, Δd, d, i)
        integer_q = lathe and bool(gcodes & (_LATHE_PQ | _LATHE_Q_ANGLE))
        count_r = lathe and bool(gcodes & _LATHE_R_COUNT) and (
            73 in gcodes or any(w[0] == "P" for w in words))
        g51 = 51 in gcodes
        degrees = 68 in gcodes  # G68 R is an angle
        dwell = 4 in gcodes  # G04 X/U are seconds (increment 0.001 s)
        values = []
        for letter, kind, payload, col, end, text, var in words:
            if kind == EXPR:
                value = self.evaluate(payload, lineno, line, col, end)
                if value is VACANT or (var is not None and self.evaluate(var, lineno, line, col, end) is VACANT):
                    continue  # a vacant variable drops its word
                if g51 and letter in "PIJK":
                    q = value_as_is(value, f"G51 {letter}")
                elif dwell and letter in "XU":
                    q = round_to(value, self._ms)
                elif degrees and letter == "R":
                    q = round_to(value, self._inc_mm)
                elif integer_q and letter == "Q":
                    q = round_to(value, Fraction(1))
                elif count_r and letter == "R":
                    q = value_as_is(value, f"{letter} (a count)")
                else:
                    q = self.address_value(letter, value, cycle)
            else:
                q, point = payload
                if g51 and letter in "PIJK":
                    if not point:
                        q = q * self.settings.scaling_unit
                elif dwell and letter in "XU":
                    if not point and self._dpi_increment:
                        q = q / 1000
                elif letter in LENGTH_LETTERS and not (letter == "K" and cycle) and not (
                        integer_q and letter == "Q") and not (count_r and letter == "R"):
                    q = self.literal("A" if degrees and letter == "R" else letter, q, point, lineno, text)
            values.append((letter, q, col, end, text))
        return values

    def literal(self, letter: str, q: Fraction, point: bool, lineno: int, text: str) -> Fraction:
        """A length literal as the control reads it (decimal point input, least input increment)."""
        if not point:
            if q:
                self.dpi_count += 1
                if len(self.dpi_words) < 20:
                    self.dpi_words.append((lineno, text))
                if self._dpi_increment:
                    return q * self.increment(letter)
            return q
        inc = self.increment(letter)
        # q / inc not an integer (Fraction's division by integers: denominators are positive, inc > 0)
        if (q.numerator * inc.denominator) % (q.denominator * inc.numerator):
            self.rounded_count += 1
            if len(self.rounded) < 20:
                self.rounded.append((lineno, text))
            return round_to((None, q), inc)  # the decimal as written: no double to read
        return q

    def address_value(self, letter: str, value: tuple, cycle: bool) -> Fraction:
        """A computed value as the address takes it (rounded as the control rounds it)."""
        if letter in LENGTH_LETTERS and not (letter == "K" and cycle):
            return round_to(value, self.increment(letter))
        if letter in INTEGER_LETTERS or letter == "K":
            return round_to(value, Fraction(1))
        if letter == "G":
            return round_to(value, Fraction(1, 10))
        return value_as_is(value, letter)

    def assign(self, target: Callable[[], int], value: Callable[[], tuple], lineno: int, line: str, col: int,
               end: int, fl: FanucLine) -> bool:
        """``#i = value``; True when it raised a #3000 alarm (the program stops)."""
        try:
            n = target()
            v = value()
        except (EvalError, SystemVariableUnknown, RecursionError):  # again through evaluate: the diagnostic
            n = self.evaluate(target, lineno, line, col, end)
            v = self.evaluate(value, lineno, line, col, end)
        if 0 < n <= LOCALS and self.vars.on_write is None:
            self.vars.local[n] = v  # FanucVariables.write's first case, inline
            return False
        if n in (3000, 3006):
            message = fl.comments[0][0].strip() if fl.comments else ""
            try:
                number = int(round_to(v, Fraction(1))) if v is not VACANT else 0
            except RoundingNotCertain as e:
                raise self.unsupported(e.code, e.reason, lineno, line, col, end) from None
            if n == 3000:
                self.alarm = (number, message, self.span(lineno, line, col, end))
                return True
            self.stops.append((number, message, self.span(lineno, line, col, end)))
            return False
        try:
            self.vars.write(n, v)
        except EvalError as e:
            raise self.error(e.code, e.message, lineno, line, col, end) from None
        except SystemVariableUnknown as e:
            raise self.unsupported(e.code, e.reason, lineno, line, col, end) from None
        return False

    # -- control statements ----------------------------------------------------------------
    def statement(self, stmt: tuple, fl: FanucLine, pos: int, lineno: int, line: str,
                  nxt: int) -> tuple[int, int] | None:
        frame = self.frames[-1]
        col, end = fl.stmt_at
        kind = stmt[0]
        here = (nxt, lineno + 1)
        if kind == "output":
            return here
        if kind == "if":
            try:
                cond = stmt[1]()
            except (EvalError, SystemVariableUnknown, RecursionError):
                cond = self.evaluate(stmt[1], lineno, line, col, end)
            if cond[0] == 0.0:
                return here
            then = stmt[2]
            if then[0] == "goto":
                return self.goto(then[1], pos, lineno, line, col, end)
            for target, value, c, e in then[1]:
                if self.assign(target, value, lineno, line, c, e, fl):
                    return None
            return here
        if kind == "goto":
            return self.goto(stmt[1], pos, lineno, line, col, end)
        if kind in ("while", "do"):
            m = stmt[-1]
            self.check_id(m, lineno, line, col, end)
            loops = frame.loops
            if loops and loops[-1].head == (pos, lineno):
                loop = loops[-1]
            else:
                if len(loops) >= MAX_LOOP_NESTING:
                    raise self.error("GC314", f"DO loops nested more than {MAX_LOOP_NESTING} levels deep (Fanuc "
                                     "alarm PS0126)", lineno, line, col, end)
                if any(lp.m == m for lp in loops):
                    raise self.error("GC314", f"DO{m} inside an open DO{m} loop: nested loops need different "
                                     "identification numbers (1, 2, 3)", lineno, line, col, end)
                loop = _Loop(m, (pos, lineno))
                loops.append(loop)
            if kind == "while":
                try:
                    cond = stmt[1]()
                except (EvalError, SystemVariableUnknown, RecursionError):
                    cond = self.evaluate(stmt[1], lineno, line, col, end)
            if kind == "do" or cond[0] != 0.0:
                self.count(loop, lineno, line)
                return here
            loops.pop()
            end_pos, end_line = self.find_end(frame.source, m, nxt, lineno + 1, lineno, line)
            return frame.source.src.line_at(end_pos)[1], end_line + 1
        # END m
        m = stmt[1]
        self.check_id(m, lineno, line, col, end)
        loops = frame.loops
        if not loops or loops[-1].m != m:
            if any(lp.m == m for lp in loops):
                raise self.error("GC314", f"END{m} closes DO{m} while DO{loops[-1].m} inside it is still open: "
                                 "DO ranges must not cross (Fanuc alarm PS0124)", lineno, line, col, end)
            raise self.error("GC314", f"END{m} without an open DO{m} (a GOTO cannot jump into a loop)",
                             lineno, line, col, end)
        head: tuple[int, int] = loops[-1].head
        return head

    def check_id(self, m: int, lineno: int, line: str, col: int, end: int) -> None:
        if m not in (1, 2, 3):
            raise self.error("GC314", f"loop identification number {m}: DO and END take 1, 2 or 3 (Fanuc alarm "
                             "PS0126)", lineno, line, col, end)

    def count(self, loop: _Loop, lineno: int, line: str) -> None:
        loop.count += 1
        if loop.count > self.max_loops:
            raise self.unsupported("WHILE", f"the DO{loop.m} loop ran more than {self.max_loops} iterations "
                                   "(max_loop_iterations); not interpreted further", lineno, line,
                                   cls=IterationBoundExceeded)
        self.budget_left(f"the DO{loop.m} loop had run {loop.count} iterations", lineno, line)

    def budget_left(self, what: str, lineno: int, line: str, col: int = 1, end: int | None = None) -> None:
        """At every repetition (a loop iteration, a jump back, a repeat of a call): past the run's budget the
        interpretation ends here as unknown (VF203), saying what was counted."""
        why = interpretation_spent()
        if why is not None:
            raise self.unsupported("VF203", f"{why}: {what}; not interpreted further", lineno, line, col, end,
                                   cls=IterationBoundExceeded)

    def repeat_count(self, what: str, count: int, lineno: int, line: str, col: int = 1,
                     end: int | None = None) -> None:
        """A call's or a cycle's repeat count above ``max_loop_iterations`` ends the interpretation as unknown
        at its block, before any repetition runs."""
        if count > self.max_loops:
            raise self.unsupported(what.split()[0], f"{what} repeats {count} times, more than {self.max_loops} "
                                   "(max_loop_iterations, --max-iterations); not interpreted further", lineno,
                                   line, col, end, cls=IterationBoundExceeded)

    def find_end(self, source: _Source, m: int, pos: int, lineno: int, lineno0: int, line0: str) -> tuple[int, int]:
        """``(pos, lineno)`` of the ``END m`` closing the loop opened on line ``lineno0`` (scanning from ``pos``)."""
        src = source.src
        while True:
            line, nxt = src.line_at(pos)
            if line is None or _O_LINE.match(line):
                break
            if _LOOP_WORD.search(line):
                fl = self.compiled(source, pos, line, lineno, nxt)[0]
                if fl.stmt is not None:
                    if fl.stmt[0] == "end" and fl.stmt[1] == m:
                        return pos, lineno
                    if fl.stmt[0] in ("while", "do") and fl.stmt[-1] == m:
                        raise self.error("GC314", f"DO{m} inside the DO{m} loop that begins on line {lineno0}: "
                                         "nested loops need different identification numbers", lineno, line)
            pos, lineno = nxt, lineno + 1
        raise self.error("GC314", f"DO{m} has no matching END{m} (Fanuc alarm PS0124)", lineno0, line0)

    def goto(self, fn: Callable[[], tuple], pos: int, lineno: int, line: str, col: int,
             end: int) -> tuple[int, int]:
        value = self.evaluate(fn, lineno, line, col, end)
        try:
            n = int(round_to(value, Fraction(1))) if value is not VACANT else -1
        except RoundingNotCertain as e:
            raise self.unsupported(e.code, e.reason, lineno, line, col, end) from None
        if not 1 <= n <= 99999999:
            raise self.error("GC314", f"GOTO {n if n >= 0 else '<vacant>'}: a sequence number is 1 to 99999999 "
                             "(Fanuc alarm PS0128)", lineno, line, col, end)
        return self.jump(n, pos, lineno, line, col, end, "GOTO")

    def jump(self, n: int, pos: int, lineno: int, line: str, col: int, end: int, what: str) -> tuple[int, int]:
        """Go to the block with sequence number ``n`` of the current program (GOTO, M99 P in the main
        program, M97 P): loops it leaves are closed; jumping back counts against the loop bound."""
        frame = self.frames[-1]
        source = frame.source
        target = self.find_label(source, n, pos)
        if target is None:
            raise self.error("GC314", f"{what} {n}: no block N{n} in this program (Fanuc alarm PS0128)",
                             lineno, line, col, end)
        tpos, tline = target
        if tpos <= pos:
            self.jumps_back += 1
            if self.jumps_back > self.max_loops:
                raise self.unsupported("GOTO", f"{what} {n} jumped back more than {self.max_loops} times "
                                       "(max_loop_iterations); not interpreted further", lineno, line, col, end,
                                       cls=IterationBoundExceeded)
            self.budget_left(f"{what} {n} had jumped back {self.jumps_back} times", lineno, line, col, end)
        while frame.loops:  # leave the loops whose range does not hold the target
            loop = frame.loops[-1]
            if tpos > loop.head[0]:
                end_pos = self.find_end(source, loop.m, source.src.line_at(loop.head[0])[1], loop.head[1] + 1,
                                        loop.head[1], "")[0]
                if tpos <= end_pos:
                    break
            frame.loops.pop()
        return tpos, tline

    def find_label(self, source: _Source, n: int, pos: int) -> tuple[int, int] | None:
        """Block ``N n`` of the program that holds ``pos``: searched forward from ``pos``, then from the
        program's start, as the control searches."""
        source.index()
        places = source.labels.get(n)
        if not places:
            return None
        a, b = source.extent(pos)
        inside = [p for p in places if a <= p[0] < b]
        if not inside:
            return None
        after = [p for p in inside if p[0] > pos]
        found: tuple[int, int] = after[0] if after else inside[0]
        return found

    # -- NC statements and calls ------------------------------------------------------------
    def has_call_code(self, values: list) -> bool:
        custom = not self.in_custom()
        for letter, q, *_rest in values:
            if letter == "M" and q.denominator == 1 and (q.numerator in (97, 98, 99) or q.numerator in self.custom_m):
                return True
            if custom and letter == "G" and q.denominator == 1 and q.numerator in self.custom_g:
                return True
            if custom and letter == "T" and self.custom_t is not None:
                return True
        return False

    def block(self, values: list, number: Fraction | None, lineno: int, line: str) -> Iterator:
        """Yield one block of evaluated words."""
        self.started = True
        span = make_span(self.frames[-1].source.file, lineno, 1, len(line) + 1, line)
        yield plain_block_of(values, span, self.index, number)
        self.index += 1

    def nc(self, values: list, fl: FanucLine, lineno: int, line: str, nxt: int) -> _Flow:
        """Yield an NC statement's block; the G66 modal call after a move; M2/M30 end the program."""
        if self.shape_codes and any(v[0] == "G" and v[1] in self.shape_codes for v in values) and any(
                v[0] == "P" for v in values) and any(v[0] == "Q" for v in values):
            return (yield from self.shape_cycle(values, fl, lineno, line, nxt))
        yield from self.block(values, fl.number, lineno, line)
        if any(v[0] == "M" and v[1] in (2, 30) for v in values):
            return None
        here = (nxt, lineno + 1)
        if self.modal_call is not None and self.modal_call[3] == len(self.frames) and any(
                v[0] in "XYZUVWABC" for v in values) and not any(
                v[0] == "G" and v[1] in (4, 10, 52, 92) for v in values):
            program, repeats, args, _depth = self.modal_call
            return self.call_macro(program, repeats, dict(args), here, lineno, line, "G66")
        return here

    def shape_cycle(self, values: list, fl: FanucLine, lineno: int, line: str, nxt: int) -> _Flow:
        """A lathe cycle block that reads a finishing shape (G70-G73 with P and Q): the blocks from ``N P`` to
        ``N Q`` of the current program are read and evaluated (not executed) and handed to the interpreter
        with the cycle block (:class:`~nczones.gcode.blocks.ShapeBlock`).  After G71-G73 whose shape follows the
        cycle block, the program goes on after ``N Q`` (the shape's blocks are not executed again, 0i-TD
        "Multiple repetitive cycle"); otherwise, and after G70 always, after the cycle block."""
        pword = next(v for v in values if v[0] == "P")
        qword = next(v for v in values if v[0] == "Q")
        frame = self.frames[-1]
        source = frame.source
        src = source.src
        for w in (pword, qword):
            if w[1].denominator != 1 or w[1] <= 0:
                raise self.error("GC209", f"{w[4]}: {w[0]} of a lathe cycle is the sequence number of the "
                                 f"finishing shape's {'first' if w[0] == 'P' else 'last'} block", lineno, line,
                                 w[2], w[3])
        here = self.current_pos
        first = self.find_label(source, int(pword[1]), here)
        if first is None:
            raise self.error("GC314", f"{pword[4]}: no block N{int(pword[1])} in this program for the finishing "
                             "shape (Fanuc alarm PS0063)", lineno, line, pword[2], pword[3])
        pos, ln = first
        shape: list = []
        index = self.index
        while True:
            text, after = src.line_at(pos)
            if text is None:
                raise self.error("GC314", f"{qword[4]}: the finishing shape from N{int(pword[1])} has no block "
                                 f"N{int(qword[1])} after it (Fanuc alarm PS0063)", lineno, line, qword[2], qword[3])
            compiled = self.compiled(source, pos, text, ln, after)
            sfl, swords, assigns, stmt, _t, _n, gcodes = compiled[:7]
            if sfl.percent or sfl.program is not None:
                raise self.error("GC314", f"the finishing shape from N{int(pword[1])} runs into the end of the "
                                 f"program before N{int(qword[1])}", lineno, line, qword[2], qword[3])
            if not (sfl.delete and self.skips(sfl.delete)):
                if sfl.unmodelled is not None or assigns or stmt is not None:
                    raise self.unsupported(f"G{int(next(v[1] for v in values if v[0] == 'G' and v[1] in self.shape_codes))}",
                                           "a macro statement inside a lathe cycle's finishing shape: the manuals "
                                           "allow only NC blocks between P and Q; not modelled", ln, text)
                if swords:
                    try:
                        svalues = self.word_values(swords, gcodes, ln, text)
                    except RoundingNotCertain as e:
                        raise self.unsupported(e.code, e.reason, ln, text) from None
                    if any(v[0] == "M" and v[1] in (97, 98, 99) for v in svalues) or any(
                            v[0] == "G" and v[1] in (65, 66, 67) for v in svalues) or self.has_call_code(svalues):
                        raise self.error("GC314", "a subprogram or macro call inside a lathe cycle's finishing "
                                         "shape (M98/M99/G65 between P and Q): the control alarms", ln, text)
                    span = make_span(source.file, ln, 1, len(text) + 1, text)
                    shape.append(plain_block_of(svalues, span, index, sfl.number))
            if sfl.number == qword[1]:
                break
            pos, ln = after, ln + 1
        from ..blocks import ShapeBlock

        span = make_span(source.file, lineno, 1, len(line) + 1, line)
        self.started = True
        yield ShapeBlock.of(values, span, self.index, fl.number, tuple(shape))
        self.index += 1
        g70 = any(v[0] == "G" and v[1] == 70 for v in values)
        if first[0] > here and not g70:
            return after, ln + 1
        return nxt, lineno + 1

    def calls(self, values: list, calls: list, fl: FanucLine, lineno: int, line: str, nxt: int) -> _Flow:
        here = (nxt, lineno + 1)
        if calls:
            code = int(calls[0][1])
            if len(calls) > 1:
                raise self.error("GC201", "G65, G66 and G67 cannot share a block", lineno, line, calls[1][2],
                                 calls[1][3])
            if code == 67:
                self.modal_call = None
                rest = [v for v in values if v is not calls[0]]
                if rest:
                    return (yield from self.nc(rest, fl, lineno, line, nxt))
                return here
            first = values.index(calls[0])
            if first:
                raise self.error("GC202", f"G{code} must come first in its block (before its P, L and argument "
                                 "words)", lineno, line, values[0][2], values[0][3])
            program, repeats, args = self.call_words(values[1:], f"G{code}", lineno, line, calls[0])
            if code == 66:
                if self.modal_call is not None:
                    raise self.unsupported("G66", "a G66 while another G66 modal call is active (nested modal "
                                           "calls) is not modelled", lineno, line, calls[0][2], calls[0][3])
                self.modal_call = (program, repeats, args, len(self.frames))
                return here
            return self.call_macro(program, repeats, args, here, lineno, line, "G65")
        # M98 / M99 / M97 / custom codes: the block's other words run first
        custom = not self.in_custom()
        call: tuple | None = None
        rest = []
        for v in values:
            letter, q = v[0], v[1]
            if call is None and letter == "M" and q.denominator == 1 and q.numerator in (97, 98, 99):
                call = ("M", q.numerator, v)
            elif call is None and letter == "M" and q.denominator == 1 and q.numerator in self.custom_m:
                call = ("M", q.numerator, v) + self.custom_m[q.numerator]
            elif call is None and custom and letter == "G" and q.denominator == 1 and q.numerator in self.custom_g:
                call = ("G", q.numerator, v) + self.custom_g[q.numerator]
            elif call is None and custom and letter == "T" and self.custom_t is not None:
                call = ("T", q, v) + self.custom_t
            else:
                rest.append(v)
        assert call is not None  # has_call_code() found one
        letter, number, word = call[:3]
        if len(call) > 3:  # a custom code of the machine file
            program, how = call[3], call[4]
            name = "T" if letter == "T" else f"{letter}{number}"
            if letter == "T":  # the T code's value goes to common variable #149 (0i/30i, parameter 6001#5)
                self.vars.write(149, (float(number), number))
            if how == "macro":
                args = {} if letter == "T" else self.arguments(rest, lineno, line)
                if letter == "T" and rest:
                    yield from self.block(rest, fl.number, lineno, line)
                return self.call_macro(program, 1, args, here, lineno, line, name, custom=True)
            if rest:
                yield from self.block(rest, fl.number, lineno, line)
            return self.call_sub(program, 1, here, lineno, line, name, custom=True)
        pword = next((v for v in rest if v[0] == "P"), None)
        lword = next((v for v in rest if v[0] == "L"), None) if number != 99 else None
        others = [v for v in rest if v is not pword and v is not lword]
        if others:
            yield from self.block(others, fl.number, lineno, line)
            if any(v[0] == "M" and v[1] in (2, 30) for v in others):
                return None
        if number == 98:
            return self.m98(pword, lword, word, lineno, line, here)
        if number == 97:
            if pword is None or pword[1].denominator != 1 or pword[1] <= 0:
                raise self.error("GC317", "M97 needs a P word with the sequence number of the local subprogram "
                                 "(Haas M97 P100)", lineno, line, word[2], word[3])
            count = int(lword[1]) if lword is not None and lword[1].denominator == 1 else 1
            if count <= 0:
                return here
            self.repeat_count(f"M97 P{int(pword[1])} L{count}", count, lineno, line, word[2], word[3])
            frame = self.frames[-1]
            target = self.jump(int(pword[1]), nxt, lineno, line, pword[2], pword[3], "M97 P")
            self.push(_Frame("m97", frame.source, frame.program, here, target, count), lineno, line)
            return target
        return self.return_m99(pword, word, lineno, line, nxt)

    def m98(self, pword: tuple | None, lword: tuple | None, word: tuple, lineno: int, line: str,
            here: tuple[int, int]) -> tuple[int, int]:
        if pword is None:
            raise self.error("GC317", "M98 needs a P word naming the subprogram (M98 P1000)", lineno, line,
                             word[2], word[3])
        p = pword[1]
        if p.denominator != 1 or p < 0:
            raise self.error("GC317", f"M98 {pword[4]}: the program number must be a non-negative integer",
                             lineno, line, pword[2], pword[3])
        count = 1
        program = int(p)
        if lword is not None:
            if lword[1].denominator != 1 or lword[1] < 0:
                raise self.error("GC317", f"M98 {lword[4]}: the repeat count must be a non-negative integer",
                                 lineno, line, lword[2], lword[3])
            count = int(lword[1])
        elif program > 9999:
            count, program = divmod(program, 10000)  # M98 P30002: the digits before the last four repeat
        if count == 0:
            return here
        if count > self.max_loops:  # the message is built only when it is needed
            self.repeat_count(f"M98 {pword[4]}{' ' + lword[4] if lword is not None else ''} (subprogram "
                              f"O{program})", count, lineno, line, word[2], word[3])
        return self.call_sub(program, count, here, lineno, line, "M98")

    def call_words(self, words: list, what: str, lineno: int, line: str,
                   gword: tuple) -> tuple[int, int, dict[int, tuple]]:
        pword = lword = None
        rest = []  # the argument words: all but the first P and the first L
        for v in words:
            letter = v[0]
            if letter == "P" and pword is None:
                pword = v
            elif letter == "L" and lword is None:
                lword = v
            else:
                rest.append(v)
        if pword is None or pword[1].denominator != 1 or pword[1] < 0:
            raise self.error("GC317", f"{what} needs a P word with the macro's program number ({what} P9010 A1 B2)",
                             lineno, line, gword[2], gword[3])
        repeats = 1
        if lword is not None:
            if lword[1].denominator != 1 or lword[1] < 0:
                raise self.error("GC317", f"{what} {lword[4]}: the repeat count must be a non-negative integer",
                                 lineno, line, lword[2], lword[3])
            repeats = int(lword[1])
        args = self.arguments(rest, lineno, line)
        return int(pword[1]), repeats, args

    def arguments(self, words: list, lineno: int, line: str) -> dict[int, tuple]:
        """Argument specification I (A B C D E F H I J K M Q R S T U V W X Y Z) and II (A B C and up to ten
        sets of I J K): the n-th I goes to #(4 + 3(n-1)), J to #(5 + 3(n-1)), K to #(6 + 3(n-1)); where both
        forms name one variable the later word wins (0i/30i, "Argument specification")."""
        args: dict[int, tuple] = {}
        seen = {"I": 0, "J": 0, "K": 0}
        for letter, q, col, end, text in words:
            if letter in seen:
                k = seen[letter]
                seen[letter] += 1
                if k >= 10:
                    raise self.error("GC204", f"more than ten {letter} arguments (argument specification II takes "
                                     "ten sets of I J K)", lineno, line, col, end)
                n = 4 + 3 * k + "IJK".index(letter)
            else:
                spec_one = ARGUMENTS_I.get(letter)
                if spec_one is None:
                    raise self.error("GC204", f"{text}: {letter} cannot be a macro argument (G, L, N, O, P are not "
                                     "arguments)", lineno, line, col, end)
                n = spec_one
            args[n] = (double_of(q), q)
        return args

    def push(self, frame: _Frame, lineno: int, line: str) -> None:
        macros = sum(1 for f in self.frames if f.saved is not None) + (frame.saved is not None)
        if macros > MAX_MACRO_LEVELS:
            raise self.error("GC316", f"macro calls nested more than {MAX_MACRO_LEVELS} levels deep (Fanuc alarm "
                             "PS0077)", lineno, line)
        if len(self.frames) >= MAX_CALL_DEPTH:
            raise self.error("GC316", f"calls nested more than {MAX_CALL_DEPTH} levels deep (Fanuc alarm PS0077)",
                             lineno, line)
        self.frames.append(frame)

    def locate(self, program: int, lineno: int, line: str, what: str) -> tuple[_Source, tuple[int, int]]:
        """Where program ``O<program>`` begins: in the calling file, the main file, else the library folder."""
        caller = self.frames[-1].source
        key = (id(caller), program)
        got = self._located.get(key)
        if got is not None and got[0] is caller:  # found before from this file (files do not change)
            found: tuple[_Source, tuple[int, int]] = got[1]
            return found
        out = self._locate(program, lineno, line, what)
        if len(self._located) < 4096:
            self._located[key] = (caller, out)
        return out

    def _locate(self, program: int, lineno: int, line: str, what: str) -> tuple[_Source, tuple[int, int]]:
        for here in dict.fromkeys((self.frames[-1].source, self.main)):
            body = here.program(program)
            if body is not None:
                return here, body
        source = self.library_sources.get(program)
        if source is None and self.libraries:
            path = next((p for p in (_library_file(f, program) for f in self.libraries) if p is not None), None)
            if path is not None:
                text = path.read_bytes().decode("utf-8", errors="replace")
                source = _Source(StringSource(text), str(path))
                self.library_sources[program] = source
        if source is None:
            where = (f" nor in the library {os.pathsep.join(map(str, self.libraries))}" if self.libraries
                     else " (pass --library DIR to search a folder of subprogram files)")
            raise self.error("GC317", f"{what}: no program O{program} in this file{where}", lineno, line)
        return source, source.program(program) or (0, 1)

    def call_sub(self, program: int, count: int, ret: tuple[int, int], lineno: int, line: str, what: str,
                 custom: bool = False) -> tuple[int, int]:
        source, body = self.locate(program, lineno, line, what)
        self.push(_Frame("m98", source, program, ret, body, count, custom=custom), lineno, line)
        return body

    def call_macro(self, program: int, repeats: int, args: dict, ret: tuple[int, int], lineno: int, line: str,
                   what: str, custom: bool = False) -> tuple[int, int]:
        if repeats == 0:
            return ret
        if repeats > self.max_loops:  # the message is built only when it is needed
            self.repeat_count(f"{what} P{program} L{repeats}", repeats, lineno, line)
        source, body = self.locate(program, lineno, line, what)
        frame = _Frame("macro", source, program, ret, body, repeats, self.vars.local, args, custom=custom)
        self.push(frame, lineno, line)
        self.vars.push_level(args)
        return body

    def return_m99(self, pword: tuple | None, word: tuple, lineno: int, line: str, nxt: int) -> tuple[int, int]:
        frame = self.frames[-1]
        col, end = word[2], word[3]
        if frame.kind == "main":
            if pword is None:
                raise self.unsupported("M99", "M99 in the main program restarts it forever; endless programs are "
                                       "not supported", lineno, line, col, end)
            return self.jump(int(pword[1]), nxt, lineno, line, pword[2], pword[3], "M99 P")
        frame.repeats -= 1
        if frame.repeats > 0 and pword is None:
            self.budget_left(f"O{frame.program} (called at line {frame.ret[1] - 1}) had {frame.repeats} repeats "
                             "left", lineno, line, col, end)
            frame.loops.clear()
            if frame.saved is not None:  # the next repetition of a macro starts with its arguments only
                self.vars.local = [VACANT] * len(self.vars.local)
                for k, v in (frame.args or {}).items():
                    self.vars.local[k] = v
            return frame.body
        self.frames.pop()
        if frame.saved is not None:
            self.vars.pop_level(frame.saved)
        if pword is None:
            return frame.ret
        caller = self.frames[-1]
        target = self.find_label(caller.source, int(pword[1]), frame.ret[0])
        if target is None:
            raise self.error("GC314", f"M99 {pword[4]}: no block N{int(pword[1])} in the calling program (Fanuc "
                             "alarm PS0128)", lineno, line, pword[2], pword[3])
        if target[0] <= frame.ret[0]:
            self.jumps_back += 1
            if self.jumps_back > self.max_loops:
                raise self.unsupported("M99", f"M99 {pword[4]} jumped back more than {self.max_loops} times "
                                       "(max_loop_iterations); not interpreted further", lineno, line, col, end,
                                       cls=IterationBoundExceeded)
            self.budget_left(f"M99 {pword[4]} had jumped back {self.jumps_back} times", lineno, line, col, end)
        caller.loops.clear()
        return target


#: The sentinels and constants of the closures of lines run again (FanucRunner.make_op).
_UNITS = object()  # rounded to the linear axes' increment of the unit system in effect
_DROPPED = object()  # a word dropped for a vacant variable
_ONE = Fraction(1)
_TENTH = Fraction(1, 10)
_EVAL_ERRORS = (EvalError, SystemVariableUnknown, RecursionError)


def _argument_specs(words: list, specs: list) -> list | None:
    """The G65 arguments of a closure (``arguments``, resolved once): ``(variable, value or None, fn, var, step,
    shifts, step denominator)`` per word (:meth:`FanucRunner.word_specs`), ``shifts`` for I, J, K (a vacant one moves the later
    sets up); None where ``arguments`` raises."""
    seen = {"I": 0, "J": 0, "K": 0}
    args = []
    for w, (q, fn, var, step) in zip(words, specs):
        letter = w[0]
        if letter in seen:
            if seen[letter] >= 10:
                return None
            n = 4 + 3 * seen[letter] + "IJK".index(letter)
            seen[letter] += 1
        elif letter in ARGUMENTS_I:
            n = ARGUMENTS_I[letter]
        else:
            return None
        args.append((n, (double_of(q), q) if fn is None else None, fn, var, step, letter in seen,
                     _step_denominator(step)))
    return args


def _step_denominator(step: Any) -> int:
    """The denominator of a step 1/n (round_to keeps a value whose denominator divides it), else 0 (the
    linear axes' step, chosen per execution, and steps m/n: round_to decides)."""
    return step.denominator if isinstance(step, Fraction) and step.numerator == 1 else 0


def _static_index(tree: tuple) -> int | None:
    """The variable number of an assignment's target written as a number (``#12``), else None (also a literal
    whose readings part, :func:`~nczones.gcode.fanuc.expr.literal_number`: the general path raises GC398)."""
    return literal_number(tree[1])


def _negated_variable(tree):
    """For ``X-#1``: the variable (its vacancy drops the word, as ``X#1``'s does); else None."""
    if tree[0] == NEG and tree[1][0] == VAR:
        return tree[1]
    return None


def _target(tree: tuple, variables: FanucVariables, ctx: Context) -> Callable[[], int]:
    """The variable number an assignment writes (a function of no arguments)."""
    index = tree[1]
    n = literal_number(index)
    if n is not None:
        return lambda: n
    fn = compile_tree(index, variables, ctx)
    return lambda: variable_number(fn())


def _library_file(folder: Path, program: int) -> Path | None:
    """The file of program ``O<program>`` in a library folder: ``O1234``, ``O1234.nc``, ``o1234.nc``,
    ``1234.nc``, ... (four digits or as many as the number has, with the usual extensions)."""
    names = []
    for digits in dict.fromkeys((f"{program:04d}", str(program), f"{program:05d}", f"{program:08d}")):
        for stem in (f"O{digits}", f"o{digits}", digits):
            for ext in ("", ".nc", ".NC", ".txt", ".TXT", ".tap", ".TAP", ".min", ".MIN", ".eia", ".EIA", ".ngc"):
                names.append(stem + ext)
    for name in names:
        p = folder / name
        if p.is_file():
            return p
    return None


def needs_language_layer(text: str) -> bool:
    """Whether a Fanuc program needs the whole-program language layer (macro statements, variables,
    calls, block delete, several programs): otherwise runs of plain lines go to the fast path piece by
    piece (:mod:`nczones.gcode.fastpath`)."""
    return bool(_NEEDS.search(text))


_NEEDS = re.compile(r"[#\[/]|[Mm][ \t]*0*9[789](?![\d.])|[Gg][ \t]*0*6[5-7](?![\d.])|(?i:goto|while|end[ \t]*\d|"
                    r"do[ \t]*\d|\bif\b)")


def iter_blocks(
    text: str,
    file: str = "<program>",
    *,
    variables: FanucVariables | None = None,
    settings: FanucSettings | None = None,
    block_delete: bool | Collection[int] = False,
    library: str | Path | None = None,
    state: Any = None,
    max_loop_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS,
    first_line: int = 1,
    first_index: int = 0,
    lane: Callable[..., int] | None = None,
    runner_out: list | None = None,
) -> Iterator:
    """Execute a Fanuc program's control and yield its blocks in execution order.

    ``state`` is the interpreter (its ``inch`` and ``in_cycle()`` decide how words are read);
    ``runner_out``, if given, receives the :class:`FanucRunner` (alarms, notes).

    >>> blocks = list(iter_blocks("O1000\\n#1=2.5\\nG0 X#1 Y[#1*2]\\nM30\\n"))
    >>> [[(w.letter, str(w.value)) for w in b.words] for b in blocks]
    [[('G', '0'), ('X', '5/2'), ('Y', '5')], [('M', '30')]]
    """
    variables = variables if variables is not None else FanucVariables(
        dict(settings.variables) if settings is not None else None)
    runner = FanucRunner(StringSource(text), file, variables, settings=settings, block_delete=block_delete,
                         library=library, state=state, max_loop_iterations=max_loop_iterations,
                         first_line=first_line, first_index=first_index, lane=lane)
    if runner_out is not None:
        runner_out.append(runner)
    return runner.run()


def fanuc_notes(interp: Interpretation) -> list[str]:
    """Report notes of a Fanuc run: decimal point input, rounded literals, alarms and stops (here, not in
    :mod:`nczones.gcode.dialects`: a Fanuc run has this module loaded; start-up, boot44)."""
    notes: list[str] = []
    runners = interp.runners
    settings = interp.machine.fanuc
    dpi = sum(r.dpi_count for r in runners)
    if dpi:
        words = [w for r in runners for w in r.dpi_words][:20]
        inc = settings.increment_mm
        mode = settings.decimal_point_input
        shown = ", ".join(f"line {ln}: {t}" for ln, t in words) + (", ..." if dpi > len(words) else "")
        notes.append(f"{dpi} length word{'s' if dpi != 1 else ''} without a decimal point ({shown}): with "
                     f"decimal_point_input = \"increment\" (parameter 3401#0 DPI = 0) X100 means {format_decimal(inc * 100)} mm, "
                     f"with \"calculator\" 100 mm; this machine uses \"{mode}\"")
    rounded = sum(r.rounded_count for r in runners)
    if rounded:
        words = [w for r in runners for w in r.rounded][:20]
        shown = ", ".join(f"line {ln}: {t}" for ln, t in words) + (", ..." if rounded > len(words) else "")
        notes.append(f"{rounded} literal{'s' if rounded != 1 else ''} with more decimals than the least input "
                     f"increment ({settings.increment_system}) were rounded to it ({shown})")
    for r in runners:
        for number, message, span in r.stops:
            notes.append(f"line {span.line}: #3006 = {number} stops the program with the message "
                         f"\"{message}\"; it resumes at cycle start")
    alarm = interp.alarm
    if alarm is not None:
        number, message, span = alarm
        notes.append(f"line {span.line}: #3000 = {number} raises alarm {3000 + number} \"{message}\": the program "
                     "stops there; nothing after it runs")
    return notes
