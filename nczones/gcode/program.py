"""Run a G-code program's *control*: text in, executed and evaluated blocks out.

Entry points
------------
``iter_blocks(text, file="<program>", *, params=None, block_delete=False,
max_loop_iterations=100000, max_call_depth=100) -> Iterator[Block]``
    Lazily executes the program in ``text`` and yields one
    :class:`~nczones.gcode.blocks.Block` per executed block, in execution
    order (``Block.index`` counts 0, 1, 2 ... in that order; loop bodies and
    subroutine calls yield their blocks anew each time).

``read_program(path, **same_options) -> Iterator[Block]``
    The same, streaming from a file on disk (the file is read line by line
    and seeked for jumps; it is never held in memory as a whole).

What the blocks contain
-----------------------
* Every word's value is an exact :class:`~fractions.Fraction`.  Plain
  decimal literals are exact (``X0.1`` is 1/10).  Words with parameters or
  ``[...]`` expressions are evaluated as IEEE doubles like LinuxCNC, and the
  word receives the exact rational of the controller's double, or the exact
  decimal when it rounds to that very double (see :mod:`nczones.gcode.expr`).
* Consumed by the language layer, never in ``Block.words``: ``N`` (it is
  ``Block.number``), O-words, parameter assignments, comments, and the
  Fanuc subprogram words ``M98``/``M99`` with their ``P``/``L`` words.  A
  line that holds nothing else yields no block.  ``(MSG,..)``, ``(DEBUG,..)``,
  ``(PRINT,..)``, ``(LOG..)`` comments go to ``Block.messages`` as
  ``"KIND,text"`` with ``#`` parameters substituted (a line with only such
  a comment yields a block without words).
* Program end: after yielding a block that has ``M2`` or ``M30`` the
  generator stops; a ``%`` line after the first executed line ends the
  program too (a leading ``%`` is the tape start).  Lines after the end are
  never read.
* Block delete: ``block_delete=False`` (the switch off, the default)
  executes ``/`` lines; ``True`` skips them.

The Parameters hook (how the interpreter shares state)
------------------------------------------------------
The interpreter creates one :class:`~nczones.gcode.expr.Parameters` and
passes it as ``params``.  The language layer reads it for every ``#``
reference and writes it for every assignment.  Because blocks are yielded
lazily, a block k+1 is not even read before the interpreter has processed
block k, so:

* ``params.set(5221, Fraction("10"))`` after a ``G10 L2`` block makes later
  ``#5221`` reads see 10;
* ``params.provide(5420, lambda: current_x)`` (or ``provide("_x", ...)``)
  makes a parameter computed on every read (current position #5420-#5428,
  tool #5400, predefined ``#<_metric>`` ...);
* ``params.on_write = fn`` is called ``fn(key, double)`` for every
  assignment the program makes (e.g. ``#5221 = 10``), so the interpreter can
  refresh its offsets if it mirrors them.

Values set by the interpreter may be Fraction/int (exact) or float.

The same order holds for blocks handed to a ``lane`` (``iter_blocks(...,
lane=interpreter.lane)``): the interpreter executes a plain block there and
then, before the next line is read; only the Block object is never built.

Errors and the unsupported mechanism
------------------------------------
* Bad text raises :class:`~nczones.errors.GcodeError` (an ``InputError``)
  with ``file:line:column`` diagnostics: ``GC1xx`` lexical, ``GC2xx`` block
  syntax, ``GC3xx`` run-time language errors (undefined named parameter
  GC310, division by zero GC311, math domain GC312, unknown subroutine
  GC313, unmatched control flow GC314, return outside a subroutine GC315,
  call depth GC316, M98 errors GC317, assignment to a read-only parameter GC318).  A lexical or syntax error in an
  executed line is reported together with those of up to nine following
  lines.
* Language that cannot be modelled raises :class:`UnsupportedGcode`
  (**not** an InputError: the program may be fine, we just cannot tell what
  it does).  The interpreter catches it and turns the verdict into
  ``unknown`` with ``exc.diagnostic`` (code, reason, line).  All blocks
  before it were yielded and are certain to execute.  Codes: GC301 Fanuc
  macro statements (IF/GOTO/WHILE-DO), G65/G66/G67 macro calls, M97 local
  subprograms, ``#3000``/``#3006`` alarms and messages, ``M99 P``; GC302
  (subclass :class:`IterationBoundExceeded`) a loop ran more than
  ``max_loop_iterations`` times; GC303 a named subroutine not defined in the
  file (LinuxCNC would search external files); GC304 ``M99`` in the main
  program (restarts the program forever).

Examples
--------
>>> prog = "#1 = 0.1\\nG91\\nO10 repeat [3]\\nG1 Y#1\\nO10 endrepeat\\nM30\\n"
>>> [[(w.letter, w.value) for w in b.words] for b in iter_blocks(prog)]
[[('G', Fraction(91, 1))], [('G', Fraction(1, 1)), ('Y', Fraction(1, 10))], [('G', Fraction(1, 1)), ('Y', Fraction(1, 10))], [('G', Fraction(1, 1)), ('Y', Fraction(1, 10))], [('M', Fraction(30, 1))]]
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection, Generator, Iterator
from fractions import Fraction

from ..errors import Diagnostic, GcodeError, NczonesError, SourceSpan
from ..precompiled import dataclass, field  # dataclasses' without importing it (start-up)
from .blocks import LANE_FULL, Block, ShapeBlock
from .expr import (
    EvalError,
    Parameters,
    compile_expression,
    evaluate,
    format_parameter,
    lcnc_integer,
    parameter_key,
    read_only,
    word_value,
)
from .lexer import (
    G_MACRO_CALLS,
    M_CONTROL,
    magic_comment,
    make_span,
    make_word,
    plain_block,
    plain_block_of,
    plain_control,
    scan_plain,
    scan_simple,
)
from .parser import OWord, ParsedLine, parse_line
from .runner_common import (  # what the Fanuc runner shares with this one (its own module: start-up)
    DEFAULT_MAX_LOOP_ITERATIONS,
    WATCHED_LIMITS,  # noqa: F401  # (kept here: nczones.gcode.program.WATCHED_LIMITS)
    FastRunRequest,
    IterationBoundExceeded,
    LineSource,
    StringSource,
    UnsupportedGcode,
    interpretation_spent,
)
from .shapes import LAYOUT, RUNS, CompiledLine, compiled_line, line_shaped, parse_line_shaped

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:  # pathlib (and urllib.parse, ipaddress) is imported where a library is searched
    from pathlib import Path
    from typing import Any, BinaryIO

__all__ = [
    "iter_blocks",
    "read_program",
    "UnsupportedGcode",
    "IterationBoundExceeded",
    "Parameters",
    "DEFAULT_MAX_LOOP_ITERATIONS",
]

MAX_REPORTED_ERRORS = 10

# --------------------------------------------------------------------------- sources


class _FileSource(LineSource):
    __slots__ = ("f", "where")

    def __init__(self, f: BinaryIO):
        self.f = f
        self.where = 0

    def line_at(self, pos: int) -> tuple[str | None, int]:
        if pos != self.where:
            self.f.seek(pos)
        raw = self.f.readline()
        if not raw:
            self.where = pos
            return None, pos
        nxt = pos + len(raw)
        self.where = nxt
        line = raw.decode("utf-8", errors="replace").rstrip("\r\n")
        if pos == 0 and line.startswith("\ufeff"):
            line = line[1:]
        return line, nxt


# --------------------------------------------------------------------------- control frames


@dataclass(slots=True)
class _Loop:
    kind: str  # "while", "do", "repeat"
    label: object
    head: tuple[int, int]  # (pos, lineno) of the while line / the line after do / repeat
    remaining: int = 0
    count: int = 0
    ifs: int = 0  # the frame's open ifs when the loop began: a break/continue leaves those opened inside


#: LinuxCNC's lathe cycles that read their profile from a subroutine (Q): G70, G71, G71.1, G71.2, G72, G72.1,
#: G72.2.
_G7X = frozenset(Fraction(k, 10) for k in (700, 710, 711, 712, 720, 721, 722))

@dataclass(slots=True)
class _Frame:
    """A subroutine call (``o.. call`` or ``M98``); the main program is frame 0."""

    kind: str  # "main", "o", "m98"
    label: object = None
    ret: tuple[int, int] = (0, 0)
    saved: dict | None = None
    body: tuple[int, int] = (0, 0)
    repeats: int = 0
    loops: list[_Loop] = field(default_factory=list)
    ifs: list = field(default_factory=list)
    #: the calling file's reading state (see ``Runner._PER_FILE``) when the subroutine is in another file
    caller: dict | None = None


#: LinuxCNC's call levels, the main program's included (``INTERP_SUB_ROUTINE_LEVELS``, interp_internal.hh).
LINUXCNC_CALL_LEVELS = 10

_OLINE = re.compile(r"/?(?:[nN][\d.]+)?[oO](<[^>]*>|\d+)([A-Za-z]*)")
_FANUC_END = re.compile(r"[mM][ \t]*0*99(?![\d.])")
_PROGRAM_END_HINT = re.compile(r"(?:^|[^a-zA-Z])[mM][ \t]*0*(?:2|30)(?![\d.])|^[ \t]*%")


def _olabel(m: re.Match) -> int | str:
    raw: str = m.group(1)
    if raw[0] == "<":
        return raw[1:-1].lower()
    return int(raw)


def scan_oword(line: str) -> tuple[str, int | str] | None:
    """``(keyword, label)`` of an O-word line as the scans for jumps read it (the line without blanks; the
    keyword in lower case, ``""`` for a Fanuc program number), else None.

    >>> scan_oword("N10 o100 WHILE [#1 LT 3]"), scan_oword("G1 X1")
    (('while', 100), None)
    """
    if "o" not in line and "O" not in line:
        return None
    m = _OLINE.match(_BLANK.sub("", line))
    if m is None:
        return None
    return m.group(2).lower(), _olabel(m)


def _show(label: object) -> str:
    return f"o<{label}>" if isinstance(label, str) else f"o{label}"


_BLANK = re.compile(r"[ \t]+")
#: Keep the jumps O-words found and compile the conditions of lines that run again (tests turn it off to
#: compare with searching and evaluating every time).
_REUSE_CONTROL = True
_DEBUG_PARAM = re.compile(r"#(?:<([^>]*)>|(\d+))")


def _skipped_unread(line: str) -> bool:
    """Whether a line starts with '/' and LinuxCNC, its block-delete switch on, skips it unread: only its
    comments are checked (an unclosed or nested comment is an error even there, ``rs274 -b``), so a line
    with a comment is left to the parser."""
    head = line.lstrip(" \t")
    return head[:1] == "/" and "(" not in head


class Runner:
    def __init__(self, source: LineSource, file: str, params: Parameters, block_delete: bool | Collection[int],
                 max_loop_iterations: int, max_call_depth: int, first_line: int = 1, first_index: int = 0,
                 fast_runs: dict | None = None, lane: Any = None, library: Collection[str | Path] = (),
                 files: dict[str, dict] | None = None):
        #: folders searched for ``name.ngc`` when ``o<name> call`` names a subroutine the file does not define
        #: (LinuxCNC's [RS274NGC] SUBROUTINE_PATH, in order)
        if library:
            from pathlib import Path

            self.library = tuple(Path(d) for d in library)
        else:
            self.library = ()
        #: path of a subroutine file -> its reading state (``_PER_FILE``), kept between calls (``files``: the
        #: caller's dict, which then shows the files read)
        self.files: dict[str, dict] = {} if files is None else files
        self.found: dict[str, Path] = {}  # label -> its subroutine file
        self.fast_runs = fast_runs  # offsets of lines where a FastRunRequest is yielded (see run)
        self.lane = lane  # plain blocks are offered to it before they are built (see iter_blocks)
        self.first_line = first_line
        self.src = source
        self.file = file
        self.params = params
        # LinuxCNC has one block-delete switch (number 1 of the nine a setting names)
        self.block_delete = block_delete if isinstance(block_delete, bool) else 1 in block_delete
        self.max_loops = max_loop_iterations
        self.max_depth = max_call_depth
        self.frames: list[_Frame] = [_Frame("main")]
        #: label -> (pos, lineno) of the line after "sub": the subroutines defined so far, as LinuxCNC's offset
        #: map holds them (a definition the flow executed, or found by a call searching forward)
        self.subs: dict[object, tuple[int, int]] = {}
        #: label -> every "o<label> sub" of the file, (pos, lineno) of the line after it (find_definitions)
        self.all_subs: dict[object, list[tuple[int, int]]] = {}
        #: (sub, label) -> (line, keyword) of the first if/while/repeat/do executed with that label in that sub
        #: ("" the main program): LinuxCNC's offset map refuses a label reused on another line
        self.control_lines: dict[tuple, tuple[int, str]] = {}
        #: the first break/continue that ran (keyword, line): a loop beginning after it is unknown
        self.jumped: tuple[str, int] | None = None
        self.do_continued: int | None = None  # the line of a continue that ran in a do loop (LinuxCNC's flag stays)
        self.fanuc: dict[int, tuple[int, int]] = {}  # O number -> (pos, lineno) of the line after it
        self.scanned_all = False
        self.cache: dict[int, tuple] = {}  # offset -> (parsed line, line, next offset)
        self.jumps: dict[tuple, tuple[str, int, int, str, int]] = {}  # skip_to's results by its arguments
        self.compiled: dict[int, tuple] = {}  # id of an expression tree -> (the tree, its compiled form)
        self.index = first_index
        self.started = False
        self.main_label_seen = False

    #: what the runner keeps per file read: the main program's, or a subroutine file's while its sub runs
    _PER_FILE = ("src", "file", "cache", "jumps", "subs", "all_subs", "fanuc", "scanned_all", "control_lines")

    def _state(self) -> dict:
        return {a: getattr(self, a) for a in self._PER_FILE}

    def _load(self, state: dict) -> None:
        for a, v in state.items():
            setattr(self, a, v)

    def external_sub(self, label: str, lineno: int, line: str, col: int, end: int) -> tuple[dict, tuple[int, int]] | None:
        """Switch to the file ``<label>.ngc`` of the first library folder that has one (LinuxCNC's
        find_ngc_file: the name in lower case, ``.ngc``, SUBROUTINE_PATH in order); ``(the caller's state,
        the body of its o<label> sub)``, or None where no folder has the file."""
        path = self.found.get(label)
        if path is None:  # searched once per name: a call in a loop does not stat the folders again
            path = next((d / f"{label}.ngc" for d in self.library if (d / f"{label}.ngc").is_file()), None)
            if path is None:
                return None
            self.found[label] = path
        key = str(path)
        caller = self._state()
        state = self.files.get(key)
        if state is None:
            text = path.read_bytes().decode("utf-8", errors="replace")
            state = {"src": StringSource(text), "file": key, "cache": {}, "jumps": {}, "subs": {}, "all_subs": {},
                     "fanuc": {}, "scanned_all": False, "control_lines": {}}
            self.files[key] = state
        self._load(state)
        self.find_definitions()
        body = self.subs.get(label) or next(iter(self.all_subs.get(label, ())), None)
        if body is None:
            self._load(caller)
            raise self.error("GC313", f"subroutine file {key} has no o<{label}> sub (LinuxCNC reads the "
                             "subroutine from the file named after it)", lineno, line, col, end)
        self.subs[label] = body
        return caller, body

    # -- diagnostics --------------------------------------------------------------
    def span(self, lineno: int, line: str, col: int = 1, end: int | None = None) -> SourceSpan:
        if end is None:
            end = max(col + 1, len(line) + 1)
        return SourceSpan(self.file, lineno, col, end, line)

    def error(self, code: str, message: str, lineno: int, line: str, col: int = 1,
              end: int | None = None) -> GcodeError:
        return GcodeError(Diagnostic(code, message, self.span(lineno, line, col, end)))

    def unsupported(self, code: str, message: str, lineno: int, line: str, col: int = 1, end: int | None = None,
                    cls: type[UnsupportedGcode] = UnsupportedGcode) -> UnsupportedGcode:
        return cls(Diagnostic(code, message, self.span(lineno, line, col, end)))

    def syntax_error(self, exc: GcodeError, pos: int, lineno: int) -> GcodeError:
        """Add the syntax errors of the following lines (up to the program end) to ``exc``."""
        diags = list(exc.diagnostics)
        while len(diags) < MAX_REPORTED_ERRORS:
            line, pos = self.src.line_at(pos)
            if line is None:
                break
            lineno += 1
            if _PROGRAM_END_HINT.search(line):
                break
            if scan_simple(line, lineno, self.file) is not None:
                continue
            try:
                parse_line(line, lineno, self.file)
            except GcodeError as e:
                diags.extend(e.diagnostics)
        return GcodeError(diags[:MAX_REPORTED_ERRORS])

    # -- scanning (no execution) -------------------------------------------------
    def scan(self, pos: int, lineno: int) -> Iterator[tuple[int, int, str, int]]:
        """Yield ``(pos, lineno, line, next_pos)`` from ``pos`` (lineno of the first line)."""
        while True:
            line, nxt = self.src.line_at(pos)
            if line is None:
                return
            yield pos, lineno, line, nxt
            pos = nxt
            lineno += 1

    def skip_to(self, label: object, keywords: tuple[str, ...], pos: int, lineno: int, what: str, line0: str,
                lineno0: int, nested_sub_error: bool = False) -> tuple[str, int, int, str, int]:
        """Find the next line ``<label> <keyword>`` with keyword in ``keywords``.

        Returns ``(keyword, pos, lineno, line, next_pos)``.  LinuxCNC matches
        O-words by label, not by nesting, and so does this.  A jump found is
        kept (the text does not change, and the subroutines the scan
        registered stay registered), so a loop's jumps are searched once.
        """
        if not _REUSE_CONTROL:
            return self._skip_to(label, keywords, pos, lineno, what, line0, lineno0, nested_sub_error)
        key = (label, keywords, pos, lineno, nested_sub_error)
        found = self.jumps.get(key)
        if found is not None:
            return found
        found = self._skip_to(label, keywords, pos, lineno, what, line0, lineno0, nested_sub_error)
        if len(self.jumps) < 100_000:
            self.jumps[key] = found
        return found

    def _skip_to(self, label: object, keywords: tuple[str, ...], pos: int, lineno: int, what: str, line0: str,
                 lineno0: int, nested_sub_error: bool) -> tuple[str, int, int, str, int]:
        for p, ln, line, nxt in self.scan(pos, lineno):
            seen = scan_oword(line)
            if seen is None:
                continue
            kw, lab = seen
            if nested_sub_error and kw == "sub":
                raise self.error("GC314", f"nested subroutine definition: {_show(lab)} sub inside "
                                 f"{_show(label)} sub", ln, line)
            if lab == label and kw in keywords:
                return kw, p, ln, line, nxt
        raise self.error("GC314", f"{_show(label)} {what} has no matching "
                         + " / ".join(f"{_show(label)} {k}" for k in keywords), lineno0, line0)

    def find_definitions(self) -> None:
        """Index every ``o.. sub`` and Fanuc ``O<n>`` line of the program (once)."""
        if self.scanned_all:
            return
        self.scanned_all = True
        for _p, ln, line, nxt in self.scan(0, 1 if self.file in self.files else self.first_line):
            if "o" not in line and "O" not in line:
                continue
            m = _OLINE.match(_BLANK.sub("", line))
            if m is None:
                continue
            lab = _olabel(m)
            kw = m.group(2).lower()
            if kw == "sub":
                self.all_subs.setdefault(lab, []).append((nxt, ln + 1))
            elif kw == "" and isinstance(lab, int):
                self.fanuc.setdefault(lab, (nxt, ln + 1))

    # -- execution ----------------------------------------------------------------
    def run(self) -> Iterator[Any]:
        """Yield the program's blocks; also a :class:`FastRunRequest` at a line of ``fast_runs`` and
        ``LANE_FULL`` when the lane asks for its blocks to be taken."""
        parsed: Any  # a ParsedLine, a CompiledLine or a scanner's tuple
        shape: Any
        pos, lineno = 0, self.first_line
        src = self.src
        file = self.file
        cache = self.cache
        in_text = type(src) is StringSource
        main_src = src
        fast = self.fast_runs
        lane = self.lane
        declined = -1  # the offset whose request the caller just declined
        while True:
            if fast and pos in fast and pos != declined:
                req = FastRunRequest(pos, lineno, self.index)
                yield req
                if req.resume is not None:
                    pos, lineno, self.index = req.resume
                    self.started = True
                    declined = -1
                    continue
                declined = pos
            pending = None  # a line the loop below read and parsed but leaves to the general path
            if in_text and pos and len(self.frames) == 1 and not self.frames[0].loops:
                # a run of plain and compiled lines of the main program (no control, nothing to cache):
                # the paths below, without the general loop's bookkeeping; stops before any other line
                assert isinstance(src, StringSource)
                text, n, delete_on = src.text, src.n, self.block_delete
                while pos < n:
                    if fast and pos in fast and pos != declined:
                        break
                    end = text.find("\n", pos)
                    if end < 0:
                        end = n
                    line = text[pos:end]
                    if line.endswith("\r"):
                        line = line[:-1]
                    if "#" in line or "[" in line:
                        if "(" in line or ";" in line:
                            break
                        hit = RUNS.get(line.encode().translate(LAYOUT)) if line.isascii() else None
                        if hit is not None:  # line_shaped's first lookup, without making its CompiledLine
                            run, cut, shape = hit
                            parts = cut(line)
                        else:
                            try:
                                parsed = line_shaped(line, lineno, file)
                            except GcodeError:
                                break  # the general path reports it
                            if type(parsed) is not CompiledLine:
                                pending = (parsed, line, end + 1)
                                break
                            shape, parts = parsed.shape, parsed.parts
                            run = shape.run
                        done = run(parts, self.params)
                        if done is None:  # declined: the general path says why
                            pending = (parse_line_shaped(line, lineno, file), line, end + 1)
                            break
                        number, letters, values = done
                    else:
                        parsed = scan_plain(line)
                        if parsed is None:
                            break
                        delete, number, letters, values = parsed
                        if delete and delete_on:
                            letters = ""
                        elif letters and plain_control(letters, values):
                            break
                        shape = None
                    pos, lineno0, lineno = end + 1, lineno, lineno + 1
                    if letters:
                        self.started = True
                        span = make_span(file, lineno0, 1, len(line) + 1, line)
                        taken = lane(letters, values, span, self.index) if lane is not None else 0
                        if not taken:  # a compiled line's words are made from the line only if read
                            yield plain_block(letters, values, span, self.index, number,
                                              None if shape is None else compiled_line(shape, parts))
                        self.index += 1
                        if taken == 2:
                            yield LANE_FULL
                if fast and pos in fast and pos != declined:
                    continue
            hit = cache.get(pos) if cache else None
            if pending is not None:
                parsed, line, nxt = pending
            elif hit is not None:
                parsed, line, nxt = hit
            else:
                read, nxt = src.line_at(pos)
                if read is None:
                    self.check_open_frames(lineno)
                    return
                line = read
                parsed = None
                if self.block_delete and _skipped_unread(line):
                    # LinuxCNC reads nothing after the '/' of a line its switch skips ('/1 G0', '//G0')
                    pos, lineno = nxt, lineno + 1
                    continue
            if parsed is None:
                # '#' or '[' outside comments: for the parser only (both scanners would refuse the line)
                parsed = None if (("#" in line or "[" in line) and "(" not in line and ";" not in line) \
                    else (scan_plain(line) or scan_simple(line, lineno, file))
                if parsed is None:
                    try:
                        parsed = line_shaped(line, lineno, file)
                    except GcodeError as e:
                        raise self.syntax_error(e, nxt, lineno) from None
                if len(self.frames) > 1 or self.frames[0].loops:
                    if type(parsed) is ParsedLine and parsed.oword is None and not parsed.comments:
                        # the first line of its shape is parsed; run again, it is one of the shape's lines
                        again = line_shaped(line, lineno, file)
                        if type(again) is CompiledLine:
                            parsed = again
                    if len(cache) < 200_000:
                        cache[pos] = (parsed, line, nxt)  # lines run again in loops and subroutines
            hand_on = False  # a block for the plain lane: (number, letters, values), words made if read
            if type(parsed) is CompiledLine:
                done = parsed.shape.run(parsed.parts, self.params)
                if done is None:
                    parsed = parse_line_shaped(line, lineno, file)  # the general path says why it declined
                else:
                    number, letters, values = done
                    words = parsed
                    hand_on = True
            elif type(parsed) is tuple and len(parsed) == 4 and type(parsed[2]) is str:
                # plainest path: (delete, number, letters, values)
                delete, number, letters, values = parsed
                if delete and self.block_delete:
                    pos, lineno = nxt, lineno + 1
                    continue
                if plain_control(letters, values):
                    parsed = scan_simple(line, lineno, file)  # M98/M99/M2/M30/G65...: the general path below
                else:
                    words = None
                    hand_on = True
            if hand_on:
                pos, lineno0, lineno = nxt, lineno, lineno + 1
                if letters:
                    self.started = True
                    span = make_span(file, lineno0, 1, len(line) + 1, line)
                    taken = lane(letters, values, span, self.index) if lane is not None else 0
                    if not taken:
                        yield plain_block(letters, values, span, self.index, number, words)
                    self.index += 1
                    if taken == 2:
                        yield LANE_FULL
                continue
            if type(parsed) is tuple:
                # fast path: (delete, number, words, comments)
                delete, number, words, comments = parsed
                if delete and self.block_delete:
                    pos, lineno = nxt, lineno + 1
                    continue
                messages = self.messages(comments) if comments else ()
                stop = False
                for w in words:
                    letter = w.letter
                    if letter == "M":
                        v = w.value
                        if v.denominator == 1 and v.numerator in M_CONTROL:
                            stop = True
                            break
                    elif letter == "G":
                        v = w.value
                        if 65 <= v.numerator // v.denominator <= 67 or 70 <= v.numerator // v.denominator <= 72:
                            stop = True
                            break
                if stop:
                    # M98/M99/M2/M30/G65... take the general path below
                    parsed = parse_line(line, lineno, file)
                elif words or messages:
                    self.started = True
                    yield Block(words, make_span(file, lineno, 1, len(line) + 1, line), self.index, number, messages)
                    self.index += 1
                    pos, lineno = nxt, lineno + 1
                    continue
                else:
                    pos, lineno = nxt, lineno + 1
                    continue
            # general path
            ow = parsed.oword
            if ow is not None and not parsed.comments and not parsed.percent and not (
                    parsed.delete and self.block_delete):
                # an O-word line without messages yields no block: executed without the generators
                target = self.oword(ow, self.olabel(ow, lineno, line), line, lineno, pos, nxt)
            else:
                target = yield from self.execute(parsed, line, lineno, pos, nxt)
            if target is None:
                return
            pos, lineno = target
            if self.src is not src:  # a call into a subroutine file, or the return from one
                src, file, cache = self.src, self.file, self.cache
                fast = self.fast_runs if src is main_src else None  # its offsets are the main program's

    def messages(self, comments: tuple) -> tuple[str, ...]:
        out = []
        for body, _col in comments:
            magic = magic_comment(body)
            if magic is None:
                continue
            kind, text = magic
            if kind in ("DEBUG", "PRINT", "LOG", "ABORT"):
                text = _DEBUG_PARAM.sub(self._debug_value, text)
            out.append(f"{kind},{text}")
        return tuple(out)

    def _debug_value(self, m: re.Match) -> str:
        key = m.group(1).replace(" ", "").lower() if m.group(1) is not None else int(m.group(2))
        try:
            return format_parameter(self.params.read(key)[0])
        except (KeyError, NczonesError, EvalError):
            return "######"

    def evaluate(self, tree: Any, lineno: int, line: str, col: int = 1,
                 end: int | None = None, again: bool = False) -> tuple[Any, ...]:
        """The value of ``tree``; ``again``: a tree of a line that runs again (a loop's, a subroutine's),
        evaluated by its compiled form (:func:`~nczones.gcode.expr.compile_expression`, made once)."""
        try:
            if again:
                got = self.compiled.get(id(tree))
                if got is None or got[0] is not tree:
                    if len(self.compiled) >= 10_000:
                        self.compiled.clear()
                    got = self.compiled[id(tree)] = (tree, compile_expression(tree))  # the tree kept: its id stays
                compiled: Callable[[Parameters], tuple[Any, ...]] = got[1]
                return compiled(self.params)
            return evaluate(tree, self.params)
        except EvalError as e:
            if e.code.startswith(("GC39", "GC30")):  # GC39x: a reason for unknown (GC30x: before issue 34)
                raise self.unsupported(e.code, e.message, lineno, line, col, end) from None
            raise self.error(e.code, e.message, lineno, line, col, end) from None
        except RecursionError:
            raise self.error("GC312", "expression nested too deeply", lineno, line, col, end) from None

    def execute(self, pl: ParsedLine, line: str, lineno: int, pos: int,
                nxt: int) -> Generator[Block, None, tuple[int, int] | None]:
        """Execute one general line; yields its block; returns the next (pos, lineno) or None to stop."""
        if pl.delete and self.block_delete:
            return nxt, lineno + 1
        if pl.percent:
            if self.started:
                return None
            self.started = True
            return nxt, lineno + 1
        if pl.oword is not None:
            return (yield from self.execute_oword(pl, line, lineno, pos, nxt))
        if pl.unsupported is not None:
            reason, col, end = pl.unsupported
            raise self.unsupported("GC391", reason, lineno, line, col, end)
        params = self.params
        # every read on the line sees the values from before the line's assignments
        words: list[tuple] = []  # (letter, value, column, end column, text)
        m98 = m99 = None
        stop = False
        for letter, tree, col, end, text in pl.words:
            if tree[0] == 0:  # NUM literal: exact as written
                value = tree[2]
            else:
                value = word_value(self.evaluate(tree, lineno, line, col, end))
            if letter == "M" and value.denominator == 1:
                n = value.numerator
                if n == 98:
                    m98 = (col, end)
                    continue
                if n == 99:
                    m99 = (col, end)
                    continue
                if n == 97:
                    raise self.unsupported("GC391", "M97 local subprogram calls (Haas) are not supported",
                                           lineno, line, col, end)
                if n in (2, 30):
                    stop = True
            if letter == "G" and 65 <= value.numerator // value.denominator <= 67 and value in G_MACRO_CALLS:
                raise self.unsupported("GC391", f"G{value} macro calls are not supported", lineno, line, col, end)
            words.append((letter, value, col, end, text))
        values = []
        for target, tree, col, end in pl.assigns:
            try:
                key = parameter_key(target, params)
            except EvalError as e:
                raise self.error(e.code, e.message, lineno, line, col, end) from None
            if key in (3000, 3006):
                raise self.unsupported("GC391", f"#{key} (Fanuc alarm / message stop) is not supported",
                                       lineno, line, col, end)
            if read_only(key):
                raise self.error("GC318", f"#<{key}> is read-only: LinuxCNC refuses to assign it (only a "
                                 "program's own parameters may be assigned)", lineno, line, col, end)
            guarded = params.guarded(key)
            if guarded is not None:
                raise self.unsupported("GC395", guarded, lineno, line, col, end)
            values.append((key, self.evaluate(tree, lineno, line, col, end)))
        for key, value in values:
            params.write(key, value)
        messages = self.messages(pl.comments) if pl.comments else ()
        if m98 is not None or m99 is not None:
            pword = lword = None
            rest = []
            for w in words:
                if w[0] == "P" and pword is None:
                    pword = w
                elif w[0] == "L" and lword is None and m98 is not None:
                    lword = w
                else:
                    rest.append(w)
            words = rest
            pword, lword = (None if w is None else make_word(w[0], w[1], make_span(self.file, lineno, w[2], w[3], line),
                                                             w[4]) for w in (pword, lword))
        if any(w[0] == "G" and w[1] in _G7X for w in words) and any(w[0] == "Q" for w in words):
            self.started = True
            shape = yield from self.g7x_profile(words, line, lineno)
            span = make_span(self.file, lineno, 1, len(line) + 1, line)
            yield ShapeBlock.of(words, span, self.index, pl.number, shape)
            self.index += 1
            return None if stop else (nxt, lineno + 1)
        if words or messages:
            self.started = True
            span = make_span(self.file, lineno, 1, len(line) + 1, line)
            if messages or m98 is not None or m99 is not None:
                yield Block(tuple(make_word(w[0], w[1], make_span(self.file, lineno, w[2], w[3], line), w[4])
                                  for w in words), span, self.index, pl.number, messages)
            else:
                # evaluated words in the plain lane's form (letters and values); Words are made when read
                yield plain_block_of(words, span, self.index, pl.number)
            self.index += 1
        if stop:
            return None
        if m98 is not None:
            return self.call_m98(pword, lword, m98, line, lineno, nxt)
        if m99 is not None:
            if pword is not None:
                raise self.unsupported("GC391", "M99 P (return to a sequence number) is not supported",
                                       lineno, line, *m99)
            return self.return_m99(m99, line, lineno)
        return nxt, lineno + 1

    def g7x_profile(self, words: list, line: str, lineno: int) -> Generator[Any, Any, tuple]:
        """The profile of a LinuxCNC G70-G72 block: subroutine ``O<Q>`` called and run as LinuxCNC's
        ``convert_g7x`` reads it (its control flow and parameter assignments executed), its blocks collected
        until the call returns — handed to the interpreter with the cycle block, not executed.  Yields nothing
        (a generator for the runner's ``yield from``); returns the blocks."""
        qw = next(w for w in words if w[0] == "Q")
        q = qw[1]
        if q.denominator != 1 or q < 0:
            raise self.error("GC209", f"{qw[4]}: Q of a lathe cycle is the number of the profile's subroutine",
                             lineno, line, qw[2], qw[3])
        label = int(q)
        body = self.subs.get(label)
        if body is None:
            self.find_definitions()
            body = self.all_subs.get(label, [None])[0]
        if body is None:
            raise self.error("GC313", f"{qw[4]}: subroutine o{label} (the cycle's profile) is not defined in this "
                             "file", lineno, line, qw[2], qw[3])
        depth = len(self.frames)
        new = _Frame("o", label, (-1, -1), None, body)
        self.push(new, lineno, line)
        new.saved = self.params.push_scope(())
        shape: list = []
        pos, ln = body
        steps = 0
        while len(self.frames) > depth:
            steps += 1
            if steps > self.max_loops:
                raise self.unsupported("GC392", f"the profile o{label} of a lathe cycle did not return within "
                                       f"{self.max_loops} lines (max_loop_iterations)", lineno, line,
                                       cls=IterationBoundExceeded)
            text, nxt = self.src.line_at(pos)
            if text is None:
                self.check_open_frames(ln)
                raise self.error("GC315", f"the profile o{label} of a lathe cycle has no endsub", lineno, line)
            try:
                pl = parse_line(text, ln, self.file)
            except GcodeError as e:
                raise self.syntax_error(e, nxt, ln) from None
            gen = self.execute(pl, text, ln, pos, nxt)
            try:
                while True:
                    b = next(gen)
                    if isinstance(b, Block) and b.words:
                        shape.append(b)
            except StopIteration as stop:
                target = stop.value
            if target is None:
                raise self.error("GC315", f"the program ends inside the profile o{label} of a lathe cycle",
                                 lineno, line)
            pos, ln = target
        return tuple(shape)
        yield  # pragma: no cover - a generator

    # -- Fanuc subprograms -----------------------------------------------------------
    def call_m98(self, pword: Any, lword: Any, loc: tuple[int, int], line: str, lineno: int,
                 nxt: int) -> tuple[int, int]:
        if pword is None:
            raise self.error("GC317", "M98 needs a P word naming the subprogram (M98 P1000)", lineno, line, *loc)
        # P and L are read as LinuxCNC reads integers: within 0.0001 of one (read_integer_value)
        p = lcnc_integer(pword.value)
        if p is None or p < 0:
            raise self.error("GC317", f"M98 P{pword.text[1:]}: the program number must be a non-negative integer",
                             lineno, line, pword.span.column, pword.span.end_column)
        count = 1
        if lword is not None:
            lv = lcnc_integer(lword.value)
            if lv is None or lv < 0:
                raise self.error("GC317", f"M98 L{lword.text[1:]}: the repeat count must be a non-negative integer",
                                 lineno, line, lword.span.column, lword.span.end_column)
            count = lv
        if count == 0:
            return nxt, lineno + 1
        if count > self.max_loops:
            raise self.unsupported("GC392", f"M98 P{pword.text[1:]} L{lword.text[1:] if lword else ''} repeats "
                                   f"{count} times, more than {self.max_loops} (max_loop_iterations, "
                                   "--max-iterations); not interpreted further", lineno, line, *loc,
                                   cls=IterationBoundExceeded)
        label = int(p)
        self.find_definitions()
        body = self.fanuc.get(label)
        if body is None:
            if label in self.all_subs:
                raise self.error("GC317", f"M98 P{label}: o{label} is an 'o{label} sub' subroutine; call it "
                                 f"with 'o{label} call'", lineno, line, *loc)
            raise self.error("GC317", f"M98 P{label}: no subprogram O{label} in this file", lineno, line, *loc)
        self.push(_Frame("m98", label, (nxt, lineno + 1), None, body, count), lineno, line)
        self.params.push_locals()  # LinuxCNC: every M98 call (each L repeat too) has its own named locals
        return body

    def value_unknown(self, why: str) -> None:
        """``#<_value>`` and ``#<_value_returned>`` read as unknown (GC395) until the next endsub, return or M99."""
        def unknown() -> object:
            raise EvalError("GC395", why)

        for key in ("_value", "_value_returned"):
            self.params.provide(key, unknown)

    def set_value(self, value: Any) -> None:
        """``#<_value>`` and ``#<_value_returned>`` as LinuxCNC's read_o leaves them at an endsub, return or
        M99: the value returned, else 0 and 0 (a subroutine that returns nothing resets them)."""
        self.params.set_returned(value)

    def return_m99(self, loc: tuple[int, int], line: str, lineno: int) -> tuple[int, int]:
        frame = self.frames[-1]
        if frame.kind == "main":
            raise self.unsupported("GC394", "M99 in the main program restarts it forever; endless programs "
                                   "are not supported", lineno, line, *loc)
        if frame.kind != "m98":
            raise self.error("GC315", f"M99 inside {_show(frame.label)} sub; an 'o.. sub' subroutine ends with "
                             f"{_show(frame.label)} endsub", lineno, line, *loc)
        self.set_value(None)  # LinuxCNC read_o: M99 returns no value
        self.params.pop_locals()
        frame.repeats -= 1
        if frame.repeats > 0:
            self.budget_left(f"O{frame.label} (called at line {frame.ret[1] - 1}) had {frame.repeats} repeats left",
                             lineno, line)
            frame.loops.clear()
            frame.ifs.clear()
            self.params.push_locals()  # the next repeat is a new call (a new frame)
            return frame.body
        self.frames.pop()
        return frame.ret

    def push(self, frame: _Frame, lineno: int, line: str) -> None:
        if len(self.frames) > self.max_depth:
            raise self.error("GC316", f"subroutine calls nested deeper than {self.max_depth} levels", lineno, line)
        if len(self.frames) >= LINUXCNC_CALL_LEVELS:
            raise self.error("GC316", f"subroutine calls nested deeper than {LINUXCNC_CALL_LEVELS - 1} levels: "
                             f"LinuxCNC has {LINUXCNC_CALL_LEVELS} call levels with the main program "
                             "(INTERP_SUB_ROUTINE_LEVELS; 'Too many subroutine levels')", lineno, line)
        self.frames.append(frame)

    # -- O-words ----------------------------------------------------------------
    def execute_oword(self, pl: ParsedLine, line: str, lineno: int, pos: int,
                      nxt: int) -> Generator[Block, None, tuple[int, int] | None]:
        ow = pl.oword
        assert ow is not None
        label = self.olabel(ow, lineno, line)
        messages = self.messages(pl.comments) if pl.comments else ()
        if messages:
            self.started = True
            yield Block((), make_span(self.file, lineno, 1, len(line) + 1, line), self.index, pl.number, messages)
            self.index += 1
        return self.oword(ow, label, line, lineno, pos, nxt)

    def olabel(self, ow: OWord, lineno: int, line: str) -> object:
        """The label of an O-word: ``o[expr]`` evaluated (a non-negative integer)."""
        label = ow.label
        if isinstance(label, tuple):  # o[expr]
            d, _q = self.evaluate(label, lineno, line, ow.column, ow.end_column)
            n = lcnc_integer(Fraction(d))  # LinuxCNC read_integer_value: within 0.0001 of an integer
            if n is None or n < 0:
                raise self.error("GC202", f"O-word number {d!r} is not a non-negative integer", lineno, line,
                                 ow.column, ow.end_column)
            label = n
        return label

    def oword(self, ow: OWord, label: object, line: str, lineno: int, pos: int, nxt: int) -> tuple[int, int] | None:
        """Execute an O-word line whose label is ``label`` (its comments' messages already yielded); the next
        (pos, lineno)."""
        kw = ow.keyword
        frame = self.frames[-1]
        here = (nxt, lineno + 1)
        if kw is None:
            # a Fanuc program number/subprogram label reached in the flow: a label only
            return here
        col, end = ow.column, ow.end_column
        # the line may run again: its condition compiled
        again = _REUSE_CONTROL and (len(self.frames) > 1 or bool(frame.loops))

        def cond() -> bool:
            return bool(self.evaluate(ow.args[0], lineno, line, col, end, again)[0] != 0.0)

        if kw == "sub":
            known = self.subs.get(label)
            if known is not None:
                # LinuxCNC control_save_offset: a sub is defined once; reached again (in a loop, or after a call
                # found it searching forward) it is "found in illegal location", elsewhere "redefining sub"
                raise self.error("GC314", f"{_show(label)} sub " + (
                    "reached again: a subroutine defined (or called) before may not be defined here (LinuxCNC: "
                    "found in illegal location)" if known == here else
                    f"redefines {_show(label)} (defined at line {known[1] - 1}); a subroutine is defined once"),
                    lineno, line, col, end)
            self.subs[label] = here
            _k, _p, ln, eline, after = self.skip_to(label, ("endsub",), nxt, lineno + 1, "sub", line, lineno,
                                                    nested_sub_error=True)
            # LinuxCNC's read_o sets #<_value> when it reads an endsub, also the one that ends a definition it
            # skips: to the endsub's value, else 0 (with #<_value_returned>)
            end_ow = parse_line(eline, ln, self.file).oword
            if end_ow is not None and end_ow.args:
                try:
                    value = evaluate(end_ow.args[0], self.params)
                except EvalError:
                    # LinuxCNC reads a name not defined there as nothing while it defines a sub (read_named_
                    # parameter, defining_sub): #<_value> is then what its reader's variable held
                    self.value_unknown(f"#<_value> after the definition of {_show(label)} (line {lineno}): its "
                                       f"endsub value at line {ln} reads a parameter not defined outside a call, "
                                       "which LinuxCNC reads as an undefined value")
                else:
                    self.set_value(value)
            else:
                self.set_value(None)
            return after, ln + 1
        if kw == "call":
            args = tuple(self.evaluate(a, lineno, line, col, end, again) for a in ow.args)
            body = self.subs.get(label)
            if body is None:
                # LinuxCNC control_back_to: a sub not defined yet is searched forward from the call (a definition
                # above, inside a skipped if or loop, is not found); found, it is defined there
                self.find_definitions()
                body = next((b for b in self.all_subs.get(label, ()) if b[1] > lineno), None)
                if body is not None:
                    self.subs[label] = body
            if body is None:
                if label in self.all_subs:
                    raise self.error("GC313", f"subroutine {_show(label)} is not defined here: its definition was not "
                                     "executed (it is in a skipped branch or loop) and there is none after the call",
                                     lineno, line, col, end)
                if isinstance(label, str):
                    found = self.external_sub(label, lineno, line, col, end)
                    if found is not None:
                        caller, body = found
                        new = _Frame("o", label, here, None, body, caller=caller)
                        try:
                            self.push(new, lineno, line)
                        except GcodeError:
                            self._load(caller)
                            raise
                        new.saved = self.params.push_scope(args)
                        return body
                    where = (" nor as " + " or ".join(str(d / f"{label}.ngc") for d in self.library)
                             if self.library else
                             " (pass --library DIR, or name LinuxCNC's SUBROUTINE_PATH in the machine file, to read "
                             "subroutine files)")
                    raise self.unsupported("GC393", f"subroutine o<{label}> is not defined in this file{where}",
                                           lineno, line, col, end)
                if label in self.fanuc:
                    raise self.error("GC313", f"o{label} is a Fanuc subprogram (O{label} ... M99); call it with "
                                     f"M98 P{label}", lineno, line, col, end)
                raise self.error("GC313", f"subroutine o{label} is not defined in this file", lineno, line, col, end)
            new = _Frame("o", label, here, None, body)
            self.push(new, lineno, line)
            new.saved = self.params.push_scope(args)
            return body
        if kw in ("return", "endsub"):
            if frame.kind != "o":
                if frame.kind == "m98":
                    raise self.error("GC315", f"{_show(label)} {kw} inside Fanuc subprogram O{frame.label}; "
                                     "it must end with M99", lineno, line, col, end)
                raise self.error("GC315", f"{_show(label)} {kw} outside a subroutine", lineno, line, col, end)
            if ow.args:
                value = self.evaluate(ow.args[0], lineno, line, col, end, again)
            assert frame.saved is not None  # an "o" frame saved the caller's scope when it was pushed
            self.params.pop_scope(frame.saved)
            self.set_value(value if ow.args else None)
            self.frames.pop()
            if frame.caller is not None:  # back in the calling file
                self._load(frame.caller)
            return frame.ret
        if kw in ("if", "while", "repeat", "do"):
            self.control_label(frame, label, kw, lineno, line, col, end)
        if kw == "if":
            return self.branch(label, cond(), frame, nxt, lineno, line, open_if=True)
        if kw == "elseif":
            if not frame.ifs or frame.ifs[-1] != label:
                raise self.error("GC314", f"{_show(label)} elseif without {_show(label)} if", lineno, line, col, end)
            # reached by executing the previous branch: skip to endif
            _k, _p, ln, _l, after = self.skip_to(label, ("endif",), nxt, lineno + 1, "elseif", line, lineno)
            frame.ifs.pop()
            return after, ln + 1
        if kw == "else":
            if not frame.ifs or frame.ifs[-1] != label:
                raise self.error("GC314", f"{_show(label)} else without {_show(label)} if", lineno, line, col, end)
            _k, _p, ln, _l, after = self.skip_to(label, ("endif",), nxt, lineno + 1, "else", line, lineno)
            frame.ifs.pop()
            return after, ln + 1
        if kw == "endif":
            if not frame.ifs or frame.ifs[-1] != label:
                raise self.error("GC314", f"{_show(label)} endif without {_show(label)} if", lineno, line, col, end)
            frame.ifs.pop()
            return here
        if kw in ("do", "repeat") or (kw == "while" and not (
                frame.loops and frame.loops[-1].label == label and (
                    frame.loops[-1].kind == "do" or frame.loops[-1].head == (pos, lineno)))):
            self.loop_after_jump(kw, label, lineno, line, col, end)
        if kw == "do":
            frame.loops.append(_Loop("do", label, here, ifs=len(frame.ifs)))
            return here
        if kw == "while":
            loops = frame.loops
            if loops and loops[-1].label == label and loops[-1].kind == "do":
                loop = loops[-1]
                if cond():
                    self.count(loop, lineno, line)
                    return loop.head
                loops.pop()
                return here
            if loops and loops[-1].label == label and loops[-1].kind == "while" and loops[-1].head == (pos, lineno):
                loop = loops[-1]
            else:
                loop = _Loop("while", label, (pos, lineno), ifs=len(frame.ifs))
                loops.append(loop)
            if cond():
                self.count(loop, lineno, line)
                return here
            loops.pop()
            _k, _p, ln, _l, after = self.skip_to(label, ("endwhile",), nxt, lineno + 1, "while", line, lineno)
            return after, ln + 1
        if kw == "endwhile":
            loop = self.innermost(frame, label, ("while",), kw, lineno, line, col, end)
            return loop.head
        if kw == "repeat":
            d = self.evaluate(ow.args[0], lineno, line, col, end)[0]
            n = round(d)  # LinuxCNC round_to_int (nearbyint): [2.6] repeats 3 times, [2.5] twice
            if n <= 0:
                _k, _p, ln, _l, after = self.skip_to(label, ("endrepeat",), nxt, lineno + 1, "repeat", line, lineno)
                return after, ln + 1
            loop = _Loop("repeat", label, here, remaining=n, ifs=len(frame.ifs))
            self.count(loop, lineno, line)
            frame.loops.append(loop)
            return here
        if kw == "endrepeat":
            loop = self.innermost(frame, label, ("repeat",), kw, lineno, line, col, end)
            loop.remaining -= 1
            if loop.remaining > 0:
                self.count(loop, lineno, line)
                return loop.head
            if self.do_continued is not None:
                # a continue in a do leaves LinuxCNC 2.9's doing_continue set (the do's closing while does not
                # clear it): the repeat's last endrepeat then loops back and the whole repeat runs again (rs274
                # never ends on generator seed 215995, a repeat [1] around such a do)
                raise self.unsupported("GC390", f"{_show(label)} endrepeat after a continue in a do loop (line "
                                       f"{self.do_continued}): LinuxCNC 2.9 runs the repeat again (its loop state "
                                       "is left behind); not modelled", lineno, line, col, end)
            frame.loops.pop()
            return here
        if kw in ("break", "continue"):
            loop = self.innermost(frame, label, ("while", "do", "repeat"), kw, lineno, line, col, end)
            # the ifs opened inside the loop are left with it (LinuxCNC runs rs274_findings/break-in-if.ngc)
            del frame.ifs[loop.ifs:]
            if self.jumped is None:
                self.jumped = (kw, lineno)
            if kw == "continue" and loop.kind == "do" and self.do_continued is None:
                self.do_continued = lineno
            if kw == "continue":
                if loop.kind == "while":
                    return loop.head
                if loop.kind == "repeat":
                    loop.remaining -= 1
                    if loop.remaining > 0:
                        self.count(loop, lineno, line)
                        return loop.head
                    frame.loops.pop()
                    _k, _p, ln, _l, after = self.skip_to(label, ("endrepeat",), nxt, lineno + 1, kw, line, lineno)
                    return after, ln + 1
                # do: go to the closing "while" and evaluate it
                _k, p, ln, _l, _after = self.skip_to(label, ("while",), nxt, lineno + 1, kw, line, lineno)
                return p, ln
            frame.loops.pop()
            end_kw = {"while": "endwhile", "do": "while", "repeat": "endrepeat"}[loop.kind]
            _k, _p, ln, _l, after = self.skip_to(label, (end_kw,), nxt, lineno + 1, kw, line, lineno)
            return after, ln + 1
        raise AssertionError(kw)  # pragma: no cover

    def loop_after_jump(self, kw: str, label: object, lineno: int, line: str, col: int, end: int) -> None:
        """A loop that begins after a break or continue ran: LinuxCNC 2.9's loop state is then wrong (rs274 runs
        a ``repeat [3]`` after a ``continue`` in a ``do`` 6 times, a ``do`` body after a ``break`` out of a
        ``while`` once: rs274_findings/do-continue-repeat.ngc, while-break-then-do.ngc); not modelled."""
        if self.jumped is not None:
            jkw, jline = self.jumped
            raise self.unsupported("GC390", f"o-word {kw} after a {jkw} (line {jline}): LinuxCNC 2.9 runs a loop "
                                   "that begins after a break or continue a different number of times than "
                                   "written (its loop state is left behind); not modelled", lineno, line, col, end)

    def control_label(self, frame: _Frame, label: object, kw: str, lineno: int, line: str, col: int,
                      end: int) -> None:
        """LinuxCNC's offset map: an if/while/repeat label (named per subroutine) belongs to one line; the same
        label on another line is "duplicate O-word label" (a ``while`` may close a ``do`` of its label)."""
        key = ("" if frame.kind == "main" else frame.label, label)
        seen = self.control_lines.get(key)
        if seen is None:
            self.control_lines[key] = (lineno, kw)
        elif seen[0] != lineno and kw != "do" and not (kw == "while" and seen[1] == "do"):
            raise self.error("GC314", f"{_show(label)} {kw}: the label {_show(label)} is already used by the "
                             f"{seen[1]} at line {seen[0]}; LinuxCNC refuses a duplicate O-word label (use another "
                             "number)", lineno, line, col, end)

    def branch(self, label: object, taken: bool, frame: _Frame, nxt: int, lineno: int, line: str,
               open_if: bool) -> tuple[int, int]:
        frame.ifs.append(label)
        if taken:
            return nxt, lineno + 1
        p, ln = nxt, lineno + 1
        while True:
            kw, _p, kln, kline, after = self.skip_to(label, ("elseif", "else", "endif"), p, ln, "if", line, lineno)
            if kw == "endif":
                frame.ifs.pop()
                return after, kln + 1
            if kw == "else":
                return after, kln + 1
            # elseif: evaluate its condition
            try:
                pl = parse_line(kline, kln, self.file)
            except GcodeError as e:
                raise self.syntax_error(e, after, kln) from None
            ow = pl.oword
            assert ow is not None  # skip_to found this line by its O-word
            if self.evaluate(ow.args[0], kln, kline, ow.column, ow.end_column)[0] != 0.0:
                return after, kln + 1
            p, ln = after, kln + 1

    def innermost(self, frame: _Frame, label: object, kinds: tuple[str, ...], kw: str, lineno: int, line: str,
                  col: int, end: int) -> _Loop:
        loops = frame.loops
        while loops and loops[-1].label != label:
            loops.pop()  # LinuxCNC leaves inner loops silently on break/continue of an outer one
        if not loops or loops[-1].kind not in kinds:
            raise self.error("GC314", f"{_show(label)} {kw} without an open {_show(label)} "
                             + "/".join(kinds), lineno, line, col, end)
        return loops[-1]

    def count(self, loop: _Loop, lineno: int, line: str) -> None:
        loop.count += 1
        if loop.count > self.max_loops:
            raise self.unsupported("GC392", f"{_show(loop.label)} {loop.kind} loop ran more than "
                                   f"{self.max_loops} iterations (max_loop_iterations); not interpreted further",
                                   lineno, line, cls=IterationBoundExceeded)
        self.budget_left(f"{_show(loop.label)} {loop.kind} loop had run {loop.count} iterations", lineno, line)

    def budget_left(self, what: str, lineno: int, line: str) -> None:
        """At every repetition (a loop iteration, a repeat of an M98 call): past the run's budget the
        interpretation ends here as unknown (VF203), saying what was counted."""
        why = interpretation_spent()
        if why is not None:
            raise self.unsupported("VF203", f"{why}: {what}; not interpreted further", lineno, line,
                                   cls=IterationBoundExceeded)

    def check_open_frames(self, lineno: int) -> None:
        frame = self.frames[-1]
        if len(self.frames) > 1:
            raise GcodeError(Diagnostic("GC314", f"end of file inside subroutine {_show(frame.label)}",
                                        SourceSpan(self.file, lineno, 1)))
        if frame.loops:
            loop = frame.loops[-1]
            raise GcodeError(Diagnostic("GC314", f"end of file inside {_show(loop.label)} {loop.kind} loop",
                                        SourceSpan(self.file, loop.head[1], 1)))
        if frame.ifs:
            raise GcodeError(Diagnostic("GC314", f"end of file inside {_show(frame.ifs[-1])} if",
                                        SourceSpan(self.file, lineno, 1)))


def iter_blocks(
    text: str,
    file: str = "<program>",
    *,
    params: Parameters | None = None,
    block_delete: bool | Collection[int] = False,
    max_loop_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS,
    max_call_depth: int = 100,
    first_line: int = 1,
    first_index: int = 0,
    lane: Any = None,
    library: Collection[str | Path] = (),
    files: dict[str, dict] | None = None,
) -> Iterator[Block]:
    """Execute the program's control and yield its blocks in execution order.

    Parameters
    ----------
    text : str
        The program.
    file : str
        Name used in spans and diagnostics.
    params : Parameters, optional
        The shared parameter store (see the module docstring); a fresh one
        by default.
    block_delete : bool
        The block-delete switch: True skips lines starting with ``/``.
    max_loop_iterations : int
        Iterations allowed per loop (per entry into it) before
        :class:`IterationBoundExceeded` is raised.
    max_call_depth : int
        Maximum nesting of subroutine calls.
    first_line, first_index : int
        Line number of the text's first line and index of its first block,
        for a piece cut from a longer program (spans and diagnostics then
        name the program's own lines).
    library : folders, optional
        Where ``o<name> call`` finds ``name.ngc`` when the text does not
        define ``o<name> sub`` (LinuxCNC's ``[RS274NGC] SUBROUTINE_PATH``,
        searched in order); without one such a call is ``unknown`` (GC303).
        ``files`` (a dict, filled as the files are read) shows which.
    lane : callable, optional
        ``lane(letters, values, span, index) -> int``: the consumer's way to
        execute the blocks that would be yielded as a
        :class:`~nczones.gcode.lexer.PlainBlock` from a plain or compiled line
        without the block being built.  Each is offered to it first: 0
        declines it (it is then yielded as usual), 1 takes it, 2 takes it and
        asks for control back (:data:`~nczones.gcode.blocks.LANE_FULL` is then
        yielded).  The interpreter's is
        :meth:`~nczones.gcode.interpreter.Interpreter.lane`.

    Raises
    ------
    GcodeError
        Bad text, with ``file:line:column`` diagnostics.
    UnsupportedGcode
        Language the layer cannot model (verdict ``unknown``).

    Examples
    --------
    >>> blocks = list(iter_blocks("%\\nN10 G0 X1.5 (MSG, hi)\\n/G1 x-.5 f100\\nM2\\nG0 X9\\n", "p.ngc"))
    >>> [(b.index, b.number, [w.text for w in b.words], b.messages) for b in blocks]
    [(0, Fraction(10, 1), ['G0', 'X1.5'], ('MSG, hi',)), (1, None, ['G1', 'x-.5', 'f100'], ()), (2, None, ['M2'], ())]
    >>> str(blocks[1].words[1].span)
    'p.ngc:3:5'
    """
    from .source import FileText

    if not isinstance(text, (str, FileText)):  # a streamed ASCII file is read a line at a time, as a str
        raise TypeError(f"iter_blocks expects the program text as str, got {type(text).__name__}")
    runner = Runner(StringSource(text), file, params if params is not None else Parameters(), block_delete,
                     max_loop_iterations, max_call_depth, first_line, first_index, lane=lane, library=library,
                     files=files)
    return runner.run()


def read_program(
    path: str | Path,
    *,
    params: Parameters | None = None,
    block_delete: bool | Collection[int] = False,
    max_loop_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS,
    max_call_depth: int = 100,
) -> Iterator[Block]:
    """Stream the blocks of the program file at ``path`` (see :func:`iter_blocks`).

    The file is read line by line (UTF-8, undecodable bytes replaced) and
    closed when the iterator is exhausted or garbage-collected.

    >>> import tempfile, os
    >>> with tempfile.NamedTemporaryFile("w", suffix=".ngc", delete=False) as f:
    ...     _ = f.write("G0 X1\\nG1 Y2 F100\\n")
    >>> [b.words[-1].value for b in read_program(f.name)]
    [Fraction(1, 1), Fraction(100, 1)]
    >>> os.unlink(f.name)
    """
    from pathlib import Path

    path = Path(path)

    def gen() -> Iterator[Block]:
        with open(path, "rb") as f:
            runner = Runner(_FileSource(f), str(path), params if params is not None else Parameters(),
                             block_delete, max_loop_iterations, max_call_depth)
            yield from runner.run()

    return gen()
