"""Vectorized fast path for CAM-style G-code (DESIGN §9).

CAM output is mostly runs of lines such as ``G1 X12.5 Y-3.25 F800`` or
``X12.6 Y-3.2`` (modal words) or ``G2 X.. Y.. I.. J..``.  This module reads
such runs with numpy at the byte level, straight into column
:class:`~nczones.motion.MotionChunk` values of scaled ``int64``; every other
line (and any run it cannot prove it handles exactly like the full
interpreter) goes through the language layer and the full
:class:`~nczones.gcode.interpreter.Interpreter`, which keeps the modal state
across both paths.

A line is *simple* when, outside comments and blanks, it holds only words
``G0``-``G3`` (at most one), axis words of the machine, ``I J K`` (with an
arc), ``F``, ``S``, at most one spindle or coolant code ``M3 M4 M5 M7 M8
M9`` (they change nothing the motion depends on) and a leading ``N``, each
with a plain decimal literal, and its comments are not magic comments; a
run is cut before a line with any other M code.  A program with ``O`` words,
``M98``/``M99`` or ``/`` anywhere is run entirely by the full path (its
control flow needs the language layer); so are runs shorter than
:data:`MIN_RUN` lines.  Parameters and expressions alone (``#1 = 5``,
``G1 X[#1 + 2]``) do not need that: their lines are never simple, so they
go to the full path, and every such piece of the program shares one
parameter store, so values set in one piece are read in the next and the
state parameters (``#5420``, ``#<_x>``, ...) read the interpreter's state,
which both paths keep.

Drilling: while a G81 or G82 cycle is active and has already run once
(its first block, with R, Z, P, F, G98/G99 and the initial level, always
goes through the full interpreter), a *hole line* holds only ``X`` and/or
``Y`` words (and a leading ``N``).  Hole lines in G90 G17 G94, with the
tool at the cycle's clear level and nothing pending (no unknown code,
rotation, cutter compensation, dependency tracking), are taken in columns
by ``_fast_cycle_run``: per hole the rapids, feed, dwell (G82, the
``dwell`` column) and retract ``Interpreter._cycle`` emits, with its
``derived`` names (the ``derived`` column).  Any other line (G80, G0,
G91, L, R, Z, P, F words, G73/G83-G89, G18/G19) ends the hole run and goes
to the full path.  A Fanuc control's hole lines the same way (its G81/G82
after the cycle's first block, with R and Z written in G90, at the top
level: ``_fanuc_holes``, ``FanucInterpreter._fanuc_cycle``'s rows).

Fanuc transforms: under one G68 rotation or G51 scaling (``FanucInterpreter.column_transform``) a run's
positions are computed in the program system and mapped to the machine's by
:mod:`nczones.gcode.fanuc.transform_columns` (its docstring states why the mapping is the general path's);
a point the general path finds uncertain cuts the run before its line.

Invariants
----------
* Identical segments: the fast path produces the same segments (kinds,
  exact coordinates, centres, feeds, line and block numbers) as the full
  path; ``tests/gcode/test_fastpath_corpus.py`` checks this on the corpus,
  ``tests/gcode/test_fastpath_cycles.py`` on generated drilling programs.
* Exact: numbers are parsed digit by digit into integers; the common scale
  ``10**s`` is the largest number of decimals in the run (plus one for
  inches, 25.4 = 254/10).  Magnitudes are checked before any product so no
  ``int64`` ever wraps; a run that could overflow goes to the full path.
* Arc radius tolerance: a float64 screen decides only with a margin far
  above its rounding error; undecided arcs are checked with exact Python
  integers, and a run with a bad arc goes to the full path, which raises
  the diagnostic.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterator
from fractions import Fraction
from typing import Any

import numpy as np

from ..motion import PLANE_AXES, MotionChunk, Plane, SegmentKind
from .codes import FANUC_HOLE_CYCLES, LANE_FASTPATH, LINUXCNC_G, LINUXCNC_M, LaneCodes, claimed
from .fanuc.holes import fanuc_holes
from .interpreter import LEAN_M
from .lexer import decimal_value
from .source import FileText, materialized

__all__ = ["CODES", "run_with_fastpath", "MIN_RUN"]

#: M codes a simple line may carry (spindle and coolant; the interpreter's plain lane takes the same).
_LEAN_M_CODES = np.array(sorted(LEAN_M), dtype=np.int64)
#: The motion modes a run of simple lines may start in (the code table's fast-path claims, less the G81/G82
#: hole lines, which _fast_cycle_run takes).
_RUN_MOTIONS = frozenset({None} | (claimed(LINUXCNC_G, LANE_FASTPATH) - {810, 820}))

#: The codes this lane claims and declines (the code table).
CODES = LaneCodes(LANE_FASTPATH, LINUXCNC_G, LINUXCNC_M)
#: Shorter runs of simple lines are left to the full interpreter.
MIN_RUN = 64
_MAX_SCALE = 9
_LIMIT = 2**62
_LIMIT_STATE = 2**59  # |position|, |offset|, feed, tool length (scaled) for the fast path

_NL, _CR, _SP, _TAB = 10, 13, 32, 9
_LP, _RP, _SEMI = ord("("), ord(")"), ord(";")
_HASH, _LBRACKET = ord("#"), ord("[")
_MAGIC = re.compile(r"\(\s*(MSG|DEBUG|PRINT|LOG|PROBE|ABORT)", re.I)


def run_with_fastpath(interp: Any, block_bytes: int | None = None) -> Iterator[MotionChunk]:
    """Yield the chunks of ``interp`` (an Interpretation), fast where possible.

    The program is read in blocks of about ``block_bytes`` bytes (default
    :data:`BLOCK_BYTES`) cut at line ends, so memory and chunk sizes are
    bounded whatever the program length; runs of simple lines are split at
    block ends (each piece is interpreted in columns, with the modal state
    handed on through the interpreter).
    """
    from . import program_blocks
    from .expr import Parameters

    it = interp.interpreter
    fanuc = getattr(interp, "dialect", "linuxcnc") == "fanuc"
    size = BLOCK_BYTES if block_bytes is None else max(1, int(block_bytes))
    text = _percent_cut(interp.text)  # a streamed file (FileText) is cut to a streamed head
    if not text or (_fanuc_needs_language_layer(text) if fanuc else _needs_language_layer(text, it, size)):
        if isinstance(interp.text, FileText) and (fanuc or not interp.text.isascii()):
            # the Fanuc language layer reads the text in memory; LinuxCNC's reads a streamed ASCII file a
            # line at a time (a StringSource over the FileText: its finds and slices are read a window at a time)
            interp.text = materialized(interp.text)
            text = _percent_cut(interp.text)
        if text is None:
            text = interp.text  # the language layer reads the whole program, % lines included
        if text and _utf8_exact(interp.text):
            runs = _run_starts(text, it, size)
            if runs:
                yield from _language_layer_with_runs(interp, runs)
                return
        if fanuc:
            yield from it.run(interp.blocks(interp.text))
            return
        yield from it.run(program_blocks(interp.text, interp.file, interp.block_delete, it,
                                  max_loop_iterations=interp.max_loop_iterations,
                                  library=getattr(interp, "subroutine_path", ()),
                                  files=getattr(interp, "subroutine_files", None)))
        return
    block_counter = [0]
    line0 = 0
    params = None
    if not fanuc:
        params = Parameters()  # one store for every piece the full path runs
        it.bind_parameters(params)
    for blk in _encoded_blocks(text, size):
        if it.ended:
            break
        yield from _run_block(interp, blk, line0, block_counter, params=params)
        line0 += blk.count(b"\n") + (0 if blk.endswith(b"\n") else 1)


def _utf8_exact(text: str) -> bool:
    """Whether the program's UTF-8 bytes map back to its characters one to one (no undecodable bytes
    kept as surrogates), so byte offsets of its lines convert to character offsets."""
    if text.isascii():
        return True
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def _char_offsets(blk: bytes) -> Callable[[Any], int]:
    """A function from byte offsets of (valid UTF-8) ``blk`` to character offsets."""
    b = np.frombuffer(blk, dtype=np.uint8)
    if not (b >= 0x80).any():
        return int
    continuation = np.concatenate(([0], np.cumsum((b & 0xC0) == 0x80)))
    return lambda p: int(p) - int(continuation[p])


def _run_starts(text: str, it: Any, size: int) -> dict[int, list]:
    """The runs of at least :data:`MIN_RUN` simple lines of a program, by the (character) offset of
    their first line: ``[end offset, first line number, lines, retries so far, times declined]``."""
    runs: dict[int, list] = {}
    base = 0
    line0 = 0
    for blk in _encoded_blocks(text, size):
        if not _may_have_long_run(blk):
            line0 += blk.count(b"\n") + (0 if blk.endswith(b"\n") else 1)
            base += _char_offsets(blk)(len(blk))
            continue
        simple, starts, ends_, _code = _classify(blk, it)
        char = _char_offsets(blk)
        for a, b in _simple_runs(simple):
            if b - a >= MIN_RUN:
                end = char(min(int(ends_[b - 1]) + 1, len(blk)))
                runs[base + char(starts[a])] = [base + end, line0 + a + 1, b - a, 0, 0]
        base += char(len(blk))
        line0 += len(starts)
    return runs


def _language_layer_with_runs(interp: Any, runs: dict[int, list]) -> Iterator[MotionChunk]:
    """The whole program through the language layer, which hands each run of simple lines it
    reaches (``runs``, see :func:`_run_starts`) to the fast path; a run the fast path cannot take
    in the state it finds (or only in part) is read by the language layer as usual.

    The language layer's control flow decides which lines run and how often, so this is exact in
    loops and subroutines too: a run is interpreted whenever the flow reaches it, from the state the
    interpreter is in at that moment.
    """
    from . import unknown_at_unsupported
    from .expr import Parameters
    from .program import (
        FastRunRequest,
        Runner,
        StringSource,
    )

    it = interp.interpreter
    if getattr(interp, "dialect", "linuxcnc") == "fanuc":
        flow = interp.blocks(interp.text, fast_runs=runs)
    else:
        params = Parameters()
        it.bind_parameters(params)
        runner = Runner(StringSource(interp.text), interp.file, params, interp.block_delete,
                         interp.max_loop_iterations, 100, fast_runs=runs, lane=it.lane_for_blocks(),
                         library=getattr(interp, "subroutine_path", ()),
                         files=getattr(interp, "subroutine_files", None))
        flow = unknown_at_unsupported(it, runner.run())
    requests: list[FastRunRequest] = []

    def blocks():
        for b in flow:
            if type(b) is FastRunRequest:
                requests.append(b)
                return
            yield b

    while True:
        yield from it.run(blocks())
        if not requests or it.ended:
            return
        req = requests.pop()
        chunk = _take_run(interp, runs, req)
        if chunk is not None and len(chunk):
            yield chunk


def _take_run(interp: Any, runs: dict[int, list], req: Any) -> MotionChunk | None:
    """Interpret the run at ``req.pos`` (or its first part) in columns and set ``req.resume``; or leave
    it unset (the language layer reads the lines) and register a retry 1, 2, 4, ... lines further on.

    A run declined :data:`MAX_DECLINES` times (in a loop, say) is not offered again.
    """
    it = interp.interpreter
    entry = runs[req.pos]
    end, lineno, nlines, retries = entry[:4]
    chunk = None
    taken = 0
    if it.m73_saved:
        it.m73_returns()  # what executing the run's first block would do first (no-op inside the call)
    if lineno == req.lineno and (_holes_active(it) or _state_ok(it)) and _state_decimal(it) is not None:
        blk = interp.text[req.pos:end].encode("utf-8")
        simple, starts, _ends, code = _classify(blk, it)
        if len(starts) == nlines and simple.all():
            counter = [req.index]
            if _holes_active(it):
                done = _fast_cycle_run(interp, code, 0, nlines, counter, lineno - 1)
            else:
                done = _fast_run(interp, code, 0, nlines, counter, lineno - 1)
                if done is not None and type(done) is not tuple:
                    done = (done, nlines)
            if done is not None and done[1] > 0:
                chunk, taken = done
                req.resume = (req.pos + _char_offsets(blk)(starts[taken]) if taken < nlines else end,
                              lineno + taken, counter[0])
                _keep_last(it, code, 0, taken)  # a Fanuc macro reads the last N and M (#4114, #4113)
    if taken == 0:
        step = 1 << retries
        if nlines - step >= MIN_RUN:
            pos = req.pos
            for _ in range(step):
                pos = interp.text.index("\n", pos) + 1
            runs.setdefault(pos, [end, lineno + step, nlines - step, retries + 1, 0])
        entry[4] += 1
        if entry[4] >= MAX_DECLINES:
            del runs[req.pos]
    return chunk


def _keep_last(it: Any, code: tuple[np.ndarray, np.ndarray], lo: int, hi: int) -> None:
    """A Fanuc interpreter's ``last["N"]`` and ``last["M"]`` (what a macro reads as #4114 and #4113): the number
    of the last N and M word of a block's lines ``lo`` .. ``hi - 1``, which a run took, where they have one
    (``_record_block`` keeps them block by block on the full path).  An M word alone on its line is a block (it
    sets #4113: hunt41), an N alone is not."""
    last = getattr(it, "last", None) if getattr(it, "keeps_number", False) else None
    if last is not None:
        m = _last_word(code, lo, hi, ord("M"), alone=True)
        if m is not None:
            last["M"] = m
        alone = _last_word(code, lo, hi, ord("N"), alone=True)  # in any line: None when the lines have no N
        if alone is not None:
            number = _last_word(code, lo, hi, ord("N"))
            if number is not None:
                last["N"] = number
            if alone != number:  # the last N is a line's alone (FanucRunner.number_alone)
                last["N*"] = alone
            else:  # a block's: it settles an alone before it
                last.pop("N*", None)


def _last_word(code: tuple[np.ndarray, np.ndarray], lo: int, hi: int, letter: int,
               alone: bool = False) -> Fraction | None:
    """The number of the last word ``letter`` in a block's lines ``lo`` .. ``hi - 1`` in a line with another word
    (``alone``: in any line), from its code bytes (``_classify``'s: comments and blanks out, upper case; a simple
    line's words are letters and numbers), None when none has one.

    >>> c = np.frombuffer(b"N10G1X1M8G1X2N30X3M09N40", dtype=np.uint8)
    >>> line = np.repeat(np.arange(4, dtype=np.int32), [9, 4, 8, 3])
    >>> n, m = ord("N"), ord("M")
    >>> _last_word((c, line), 0, 2, n), _last_word((c, line), 0, 4, n), _last_word((c, line), 1, 2, n)
    (Fraction(10, 1), Fraction(30, 1), None)
    >>> _last_word((c, line), 0, 2, m), _last_word((c, line), 0, 3, m)
    (Fraction(8, 1), Fraction(9, 1))
    >>> c = np.frombuffer(b"G1X1M4N30", dtype=np.uint8)
    >>> line = np.repeat(np.arange(3, dtype=np.int32), [4, 2, 3])
    >>> _last_word((c, line), 0, 3, m), _last_word((c, line), 0, 3, m, alone=True), _last_word((c, line), 0, 3, n)
    (None, Fraction(4, 1), None)
    """
    c, cl_line = code
    for at in np.flatnonzero((c == letter) & (cl_line >= lo) & (cl_line < hi))[::-1].tolist():
        k = first = at + 1
        line = cl_line[at]
        while k < c.size and cl_line[k] == line and c[k] in _NUMBER_BYTES:
            k += 1
        if k > first and (alone or at > 0 and cl_line[at - 1] == line or k < c.size and cl_line[k] == line):
            return decimal_value(c[first:k].tobytes().decode("ascii"))
    return None  # (a line of its N alone is no block: the language layer skips it, plain_first)


_NUMBER_BYTES = frozenset(b"0123456789.+-")


#: Declines after which the language layer stops offering a run to the fast path.
MAX_DECLINES = 8


def _state_decimal(it: Any) -> int | None:
    """The decimals the interpreter's position, offsets, feed and tool length need (None: more than
    the fast path's scale allows, or not decimal), checked before any line of a run is read."""
    s = 0
    for q in (it.tlo, it.feed, *it.pos, *it.off):
        d = _decimals(q)
        if d is None or d > _MAX_SCALE:
            return None
        s = max(s, d)
    return s


def _simple_runs(simple: np.ndarray) -> list[list[int]]:
    """The maximal runs ``[first, end)`` of True in ``simple`` (lines of a block).

    >>> _simple_runs(np.array([True, True, False, True]))
    [[0, 2], [3, 4]]
    """
    edges = np.flatnonzero(np.diff(np.concatenate(([False], simple, [False])).astype(np.int8)))
    return edges.reshape(-1, 2).tolist()


def _prepare(blk: bytes, it: Any) -> tuple[Any, np.ndarray, np.ndarray, Any, list[tuple[int, int]], dict]:
    """What a block needs before interpretation, independent of the modal state: the
    classification, the runs to take fast and their parsed words (a pure function of the bytes).

    A block in which no :data:`MIN_RUN` lines in a row can be simple (see :func:`_may_have_long_run`)
    is not classified: it has no run to take fast but the short ones at its ends, and those the full
    path takes as well.
    """
    if not _may_have_long_run(blk):
        starts, ends_ = _line_bounds(np.flatnonzero(np.frombuffer(blk, dtype=np.uint8) == _NL), len(blk))
        return None, starts, ends_, None, [], {}
    simple, starts, ends_, code = _classify(blk, it)
    nlines = len(starts)
    fast_runs = [(a, b) for a, b in _simple_runs(simple) if b - a >= MIN_RUN or a == 0 or b == nlines]
    parsed = {(a, b): _parse_words(code[0], code[1], a, b) for a, b in fast_runs}
    return simple, starts, ends_, code, fast_runs, parsed


#: Characters per block of the fast path (cut at a line end): about 50,000 lines of CAM code.
BLOCK_BYTES = 1 << 20


def _encoded_blocks(src: str | bytes, size: int) -> Iterator[bytes]:
    """Blocks of about ``size`` characters of ``src``, each ending after a newline (or at the end), as bytes.

    Only one block is encoded at a time, so no second copy of the program is made.
    """
    if isinstance(src, FileText):  # a streamed file: the same cuts, read from the file
        yield from src.blocks(size)
        return
    n = len(src)
    lo = 0
    while lo < n:
        hi = lo + size
        if hi >= n:
            hi = n
        else:
            cut = src.find("\n", hi - 1) if isinstance(src, str) else src.find(b"\n", hi - 1)
            hi = n if cut < 0 else cut + 1
        blk = src[lo:hi]
        yield blk.encode("utf-8", errors="surrogateescape") if isinstance(blk, str) else blk
        lo = hi


#: M then 9, 8 or 9, or M then ``#`` or ``[`` (a computed M code), with anything up to a blank between
#: them (lines are joined when the code is checked).
_M98_M99_RAW = re.compile(r"[Mm][\x00-\x20]*(?:9[\x00-\x20]*[89]|[#\[])")


def _m98_m99_raw(src: str) -> bool:
    """``_M98_M99_RAW.search(src) is not None``, tried only at the ``M``s when they are few (a search
    for a character class steps through every character).

    >>> _m98_m99_raw("G1 X1 M3\\nM 9 8 P1\\n"), _m98_m99_raw("M3 S100\\nm#1\\n"), _m98_m99_raw("G1 M3 M5\\n")
    (True, True, False)
    """
    budget = len(src) >> 6  # Ms tried before the search is cheaper
    for ch in "Mm":
        p = src.find(ch)
        while p >= 0:
            if _M98_M99_RAW.match(src, p) is not None:
                return True
            budget -= 1
            if budget < 0:
                return _M98_M99_RAW.search(src) is not None
            p = src.find(ch, p + 1)
    return False


_SUSPECT = np.zeros(256, dtype=bool)
_SUSPECT[list(b"/OoMm")] = True


def _distinct_sorted(a: np.ndarray) -> np.ndarray:
    """``np.unique`` of an already sorted array (without it: its first call imports numpy.ma, ~40 ms).

    >>> _distinct_sorted(np.array([1, 1, 3, 7, 7])).tolist()
    [1, 3, 7]
    """
    if a.size == 0:
        return a
    return a[np.concatenate(([True], a[1:] != a[:-1]))]


def _needs_language_layer(src: str | bytes, it: Any, size: int) -> bool:
    """True if the code (outside comments) has ``O / M98 M99``: the whole program needs the language layer.

    So does a computed M code (``M#1``, ``M[90 + 8]``), which could be one of them.  Parameter
    names are not code: ``T#<tool_no> M6`` has no ``O`` word.

    Only the lines holding one of the bytes ``/ O o M m`` can hold such a
    token; they are stripped of comments and blanks and checked exactly.
    """
    if isinstance(src, str):
        if not any(src.find(ch) >= 0 for ch in "/OoMm"):
            return False
    elif not any(src.find(bytes((ch,))) >= 0 for ch in b"/OoMm"):
        return False
    if isinstance(src, str) and not any(src.find(ch) >= 0 for ch in "/Oo(;") and not _m98_m99_raw(src):
        return False  # M words, but none can read M98/M99/M#/M[ once blanks are removed (no comment can hide one)
    for blk in _encoded_blocks(src, size):
        b = np.frombuffer(blk, dtype=np.uint8)
        pos = np.flatnonzero(_SUSPECT[b])
        if pos.size == 0:
            continue
        nl = np.flatnonzero(b == _NL)
        starts = np.concatenate(([0], nl + 1))
        ends_ = np.concatenate((nl + 1, [b.size]))
        lines = _distinct_sorted(np.searchsorted(nl, pos))  # line index of each suspect byte
        sub = b"".join(blk[s:e] if blk[e - 1:e] == b"\n" else blk[s:e] + b"\n"
                       for s, e in zip(starts[lines].tolist(), ends_[lines].tolist()))
        code, code_line = _classify(sub, it)[3]
        cb = code.tobytes()
        if any(t in cb for t in _LANGUAGE_TOKENS):
            if b"<" not in cb:
                return True
            # parameter names (#<tool_no>) are not code: look again, line by line, without them
            cuts = (np.flatnonzero(np.diff(code_line)) + 1).tolist()
            for a, z in zip([0, *cuts], [*cuts, len(cb)]):
                line = _NAMES.sub(b"<>", cb[a:z])
                if any(t in line for t in _LANGUAGE_TOKENS):
                    return True
    return False


_LANGUAGE_TOKENS = (b"O", b"/", b"M98", b"M99", b"M#", b"M[")
_NAMES = re.compile(rb"<[^<>]*>")


def _run_block(interp: Any, blk: bytes, line0: int, block_counter: Any, prep: Any = None,
               params: Any = None) -> Iterator[MotionChunk]:
    """Interpret one block of whole lines (line ``line0`` is its first, 0-based).

    Maximal runs of simple lines are taken fast when long enough or cut by
    the block's ends (see :func:`_prepare`).
    """
    it = interp.interpreter
    simple, starts, ends_, code, fast_runs, parsed = prep if prep is not None else _prepare(blk, it)
    nlines = len(starts)
    if nlines == 0:
        return
    i = 0
    k = 0
    failures = 0
    while i < nlines and not it.ended:
        while k < len(fast_runs) and fast_runs[k][1] <= i:
            k += 1
            failures = 0
        if k < len(fast_runs) and fast_runs[k][0] <= i:
            a, b = fast_runs[k]
            if _holes_active(it):
                done = _fast_cycle_run(interp, code, i, b, block_counter, line0, _words_from(parsed, a, b, i))
                if done is not None:
                    chunk, end = done
                    _keep_last(it, code, i, end)
                    i = end
                    if len(chunk):
                        yield chunk
                    failures = 0
                    continue
            elif _state_ok(it):
                chunk = _fast_run(interp, code, i, b, block_counter, line0, _words_from(parsed, a, b, i))
                if chunk is not None:
                    end = b
                    if type(chunk) is tuple:  # the run was cut before a line it cannot take
                        chunk, end = chunk
                    _keep_last(it, code, i, end)
                    if len(chunk):
                        yield chunk
                    i = end
                    failures = 0
                    continue
            # the full path for 1, 2, 4, ... lines of the run, then try the rest fast again
            # (typically the first line of a run sets modes the fast path does not handle)
            j = min(b, i + (1 << failures))
            failures += 1
        else:
            j = fast_runs[k][0] if k < len(fast_runs) else nlines
        yield from _full_piece(interp, blk, starts, ends_, i, j, block_counter, line0, params)
        i = j


def _words_from(parsed: dict, a: int, b: int, i: int) -> Any:
    """The parsed words of lines ``i..b-1`` of the run ``a..b``, cut from the run's (None: parse them).

    A word ends where the next begins, so cutting the run's words at a line gives exactly the words that
    parsing only the lines from there gives: a run the fast path declines at its first lines (modes set by
    its header) is tried again from a later line without parsing all of it again.
    """
    words = parsed.get((a, b))
    if words is None or i == a:
        return words
    k = int(np.searchsorted(words[0], i))
    return tuple(w[k:] for w in words)


def _percent_cut(text: str) -> str | None:
    r"""``text`` without what follows its last line of code, when its ``%`` lines cannot end the program
    early; None when they might, and the language layer must read the whole program.

    The language layer (as LinuxCNC) takes a line whose first character other than a blank is ``%``
    as a ``%`` line: the first one it meets is skipped, the next ends the program.  So the program
    can be split only when every ``%`` line comes before its first other non-blank line (at most one
    there) or after its last one (where nothing follows but blank and ``%`` lines); a ``%`` later in a
    line (``(50% feed)``) does not make a ``%`` line.

    >>> _percent_cut("%\nG1 X1 (50% feed)\n%\n\n"), _percent_cut("G1 X1\n %\nG1 X2\n"), _percent_cut("%\n%\nG1 X1\n")
    ('%\nG1 X1 (50% feed)\n', None, None)
    """
    if "%" not in text:
        return text
    n = len(text)
    # the first and the last line with something other than blanks that is not a % line
    first = None
    pos = 0
    percent_lines = 0
    while pos < n:
        nl = text.find("\n", pos)
        end = n if nl < 0 else nl + 1
        body = text[pos:end].lstrip(" \t\r\n")
        if body:
            if not body.startswith("%"):
                first = pos
                break
            percent_lines += 1
        pos = end
    if first is None:
        return text  # no code at all
    if percent_lines > 1:
        return None
    last_end = n
    while last_end > first:
        ls = text.rfind("\n", 0, last_end - 1) + 1
        body = text[ls:last_end].lstrip(" \t\r\n")
        if body and not body.startswith("%"):
            break
        last_end = ls
    p = text.find("%", first, last_end)
    while p >= 0:  # a % between the first and the last line of code: harmless unless it starts its line
        ls = text.rfind("\n", 0, p) + 1
        if not text[ls:p].strip(" \t\r"):
            return None
        p = text.find("%", text.find("\n", p) + 1 or last_end, last_end)
    if isinstance(text, FileText):  # a streamed file: its head, still read from the file
        return text.head(last_end)
    return text[:last_end]


def _state_ok(it: Any) -> bool:
    ok = getattr(it, "fast_state_ok", None)  # what a dialect's interpreter adds (Fanuc: no cycle, transform)
    return (not it.unsupported and it.motion in _RUN_MOTIONS and not it.comp_just_off
            and not it.comp_on and not it.track and it.prerotation_xy is None  # no XY rotation (G10 L2 R) active
            and it.machine_at is None  # the machine is where the interpreter believes (G84 outside G17)
            and (ok is None or ok()))


#: What makes a Fanuc program need the whole-program language layer, searched in its lower-cased text
#: (each pattern starts with a literal, which the regex engine finds fast): calls and returns, G65-G67,
#: loops and GOTO; ``#``, ``[`` (variables, expressions, IF, WHILE), ``/`` (block delete) and an EOB ``;``
#: with code after it are tested on the text itself.
_FANUC_CALLS = (re.compile(r"m[ \t]*0*9[789](?![\d.])"), re.compile(r"g[ \t]*0*6[5-7](?![\d.])"),
                re.compile(r"goto"), re.compile(r"end[ \t]*\d"), re.compile(r"do[ \t]*\d"))
_FANUC_EOB = re.compile(r";[ \t]*[^ \t\r\n(]")
_PROGRAM_NUMBER = re.compile(r"\n[ \t]*[o:][ \t]*\d")


def _fanuc_needs_language_layer(text: str | FileText) -> bool:
    """Whether a Fanuc program must be read by the language layer as a whole: macro statements, variables,
    calls, block delete, more than one program number, or an EOB ``;`` with code after it.  Otherwise runs
    of simple lines go to the fast path and the rest to the language layer piece by piece.

    >>> _fanuc_needs_language_layer("O1\\nG1 X1. F100.\\nM30\\n"), _fanuc_needs_language_layer("O1\\nM98 P2\\n")
    (False, True)
    """
    if "#" in text or "[" in text or "/" in text:
        return True
    eob = ";" in text
    numbers = 0  # program numbers found so far
    # a piece at a time, each cut after a newline (every pattern lies within one line), lower-cased
    for piece in (text,) if isinstance(text, str) else text.pieces(BLOCK_BYTES):
        if eob and _FANUC_EOB.search(piece):
            return True
        lower = piece.lower()
        if any(p.search(lower) for p in _FANUC_CALLS):
            return True
        lower = "\n" + lower  # each piece starts a line
        first = _PROGRAM_NUMBER.search(lower)
        if first is not None:
            numbers += 1 if _PROGRAM_NUMBER.search(lower, first.end()) is None else 2
            if numbers > 1:
                return True
    return False


def _full_piece(interp, data, starts, ends_, i, j, block_counter, line0=0, params=None):
    """Run lines i..j-1 (of a block whose first line is ``line0``) through the language layer and the interpreter.

    ``params``: the program's parameter store, bound to the interpreter (a fresh one if None).
    """

    it = interp.interpreter
    piece = data[starts[i]:ends_[j - 1]].decode("utf-8", errors="surrogateescape")
    offset = i + line0  # the piece's first line is line offset + 1 of the program

    from . import unknown_at_unsupported
    from .expr import Parameters
    from .program import iter_blocks

    if getattr(interp, "dialect", "linuxcnc") == "fanuc":
        blocks = interp.blocks(piece, offset + 1, block_counter[0])
    else:
        if params is None:
            params = Parameters()
            it.bind_parameters(params)
        # the piece's lines and blocks are numbered as in the whole program
        blocks = unknown_at_unsupported(it, iter_blocks(piece, file=interp.file, params=params,
                                                         block_delete=interp.block_delete, first_line=offset + 1,
                                                         first_index=block_counter[0], lane=it.lane_for_blocks(),
                                                         max_loop_iterations=interp.max_loop_iterations))
    consumed = it.blocks
    try:
        yield from it.run(blocks)
    finally:
        block_counter[0] += it.blocks - consumed  # every block the language layer yields is consumed


# --------------------------------------------------------------------------- classification


def _may_have_long_run(data: bytes) -> bool:
    """False when every run of :data:`MIN_RUN` lines in a row of ``data`` has a line holding ``#``
    or ``[`` before any ``(`` or ``;``: such a line is never simple, so no run of simple lines is
    that long (a cheap test that spares the classification of macro-style code).

    >>> _may_have_long_run(b"G1 X1\\n" * MIN_RUN), _may_have_long_run(b"#1 = 2\\nG1 X1\\n" * MIN_RUN)
    (True, False)
    >>> _may_have_long_run(b"G1 X1 (#1 in a comment)\\n" * MIN_RUN)
    True
    """
    if data.find(b"#") < 0 and data.find(b"[") < 0:
        return True
    b = np.frombuffer(data, dtype=np.uint8)
    marked = np.flatnonzero((b == _HASH) | (b == _LBRACKET))
    nl = np.flatnonzero(b == _NL)
    nlines = nl.size + (0 if b.size and b[-1] == _NL else 1)
    line_of_mark = np.searchsorted(nl, marked)
    if data.find(b"(") >= 0 or data.find(b";") >= 0:  # only marks before the line's first comment count
        openers = np.flatnonzero((b == _LP) | (b == _SEMI))
        line_of_opener = np.searchsorted(nl, openers)
        first = np.concatenate(([True], line_of_opener[1:] != line_of_opener[:-1]))
        first_opener = np.full(nlines, b.size)
        first_opener[line_of_opener[first]] = openers[first]
        line_of_mark = line_of_mark[marked < first_opener[line_of_mark]]
    lines = _distinct_sorted(line_of_mark)  # the lines holding one
    gaps = np.diff(np.concatenate(([-1], lines, [nlines]))) - 1  # unmarked lines between
    return bool(gaps.max() >= MIN_RUN)


def _line_bounds(nl: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Byte offsets of each line's first byte and of its end (its newline, or ``size``), from the
    offsets ``nl`` of the newlines in ``size`` bytes."""
    starts = np.concatenate(([0], nl + 1))
    ends_ = np.concatenate((nl, [size]))
    if starts[-1] >= size:
        starts, ends_ = starts[:-1], ends_[:-1]
    return starts, ends_


def _classify(data: bytes, it: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """Per line of a block: simple or not; line byte ranges; the code bytes (comments/blanks removed).

    Returns ``(simple, starts, ends, (code, code_line))``: ``code`` holds the
    upper-cased code bytes of all lines in order and ``code_line`` the
    (block-relative) line of each.
    """
    b = np.frombuffer(data, dtype=np.uint8)
    nl = np.flatnonzero(b == _NL)
    starts, ends_ = _line_bounds(nl, b.size)
    nlines = len(starts)
    bad = np.zeros(nlines, dtype=bool)
    if b.size == 0:
        return ~bad, starts, ends_, (np.zeros(0, np.uint8), np.zeros(0, np.int32))
    line_of = np.zeros(b.size, dtype=np.int32)
    line_of[nl[nl + 1 < b.size] + 1] = 1
    np.cumsum(line_of, out=line_of)
    has_paren = data.find(b"(") >= 0 or data.find(b")") >= 0
    if has_paren:
        # parentheses: depth relative to the line start
        op = (b == _LP).view(np.int8)
        cl = (b == _RP).view(np.int8)
        depth = np.cumsum(op.astype(np.int32) - cl, dtype=np.int32)
        base = np.concatenate((np.zeros(1, np.int32), depth))[starts]
        rel = depth - base[line_of]
        in_paren = (rel > 0) | (cl == 1)
        # nesting or unbalanced: not simple
        bad[line_of[(rel > 1) | (rel < 0)]] = True
        bad |= (ends_ > starts) & (rel[np.maximum(ends_ - 1, 0)] > 0)
    else:
        op = None
        in_paren = None
    if data.find(b";") >= 0:
        semi = b == _SEMI
        if in_paren is not None:
            semi &= ~in_paren
        sc = np.cumsum(semi, dtype=np.int32)
        sbase = np.concatenate((np.zeros(1, np.int32), sc))[starts]
        in_semi = (sc - sbase[line_of]) > 0
        comment = in_semi if in_paren is None else (in_paren | in_semi)
    else:
        comment = in_paren
    # (byte tests by comparisons: a histogram or a table lookup would widen every byte to an index)
    if ((b < 33) & (b != _SP) & (b != _TAB) & (b != _CR) & (b != _NL)).any():
        keep = _KEEP[b]  # control bytes other than blanks are kept, and make their line not simple
    else:
        keep = b > 32
    if comment is not None:
        keep &= ~comment
    c = b[keep]
    if ((b - np.uint8(97)) < 26).any():  # lower-case letters
        c = _UPPER[c]
    cl_line = line_of[keep]
    allowed = _allowed_table(it)
    others = set(c.tobytes().translate(None, _allowed_bytes(allowed)))  # the code bytes that are not allowed
    if len(others) > 8:
        bad[cl_line[~allowed[c]]] = True
    else:
        for v in others:  # usually a few letters (H, T, P, ...): one comparison each instead of a table lookup
            bad[cl_line[c == v]] = True
    if others.isdisjoint(b"R") and c.size and (c == _R).any():
        _mark_r_with_other_g(c, cl_line, bad)
    # magic comments: rare; check by regex on lines with '('
    if op is not None:
        paren_lines = _distinct_sorted(line_of[op == 1])
        for ln in paren_lines.tolist():
            if not bad[ln] and _MAGIC.search(data[starts[ln]:ends_[ln]].decode("latin-1")):
                bad[ln] = True
        # a comment inside a word (X1(c)0, X(c)1): removing it would join the word; LinuxCNC refuses the line.
        # A match holds a "(" and no newline: it lies in one of paren_lines, whose text alone is searched when
        # they are few (a header comment: the scan of every byte of a long block cost 0.1 s per 100,000 lines)
        if paren_lines.size * COMMENT_LINES_APART < nlines:
            for ln in paren_lines.tolist():
                if _COMMENT_IN_WORD.search(data, int(starts[ln]), int(ends_[ln])):
                    bad[ln] = True
        else:
            for m in _COMMENT_IN_WORD.finditer(data):
                bad[line_of[m.start()]] = True
    return ~bad, starts, ends_, (c, cl_line)


_R, _G, _DOT = ord("R"), ord("G"), ord(".")


def _mark_r_with_other_g(c: np.ndarray, cl_line: np.ndarray, bad: np.ndarray) -> None:
    """Mark not simple the lines holding an ``R`` word and a G code other than 0-3 (a canned cycle's R
    level, G10, a rotation): the fast path would refuse them anyway, and a run that starts with such a line
    (the first block of a drilling cycle) costs the full path more lines than the line itself.

    >>> c = np.frombuffer(b"G81X1R2G2X1R3G02X1R1G0003R1G2.1R1", dtype=np.uint8)
    >>> bad = np.zeros(5, dtype=bool)
    >>> _mark_r_with_other_g(c, np.repeat(np.arange(5), [7, 6, 7, 7, 6]).astype(np.int32), bad)
    >>> bad.tolist()
    [True, False, False, False, True]
    """
    gp = np.flatnonzero(c == _G)
    if gp.size == 0:
        return
    n = c.size

    def at(k: int) -> np.ndarray:
        i = gp + k
        return np.where(i < n, c[np.minimum(i, n - 1)], 0)

    b1, b2 = at(1), at(2)  # the common G0 G1 G2 G3 first (one digit 0-3, then no digit and no point)
    gp = gp[~((b1 >= 48) & (b1 <= 51) & ((b2 < 48) | (b2 > 57)) & (b2 != _DOT))]
    if gp.size == 0:
        return
    # a G code of value 0..3: zeros, then at most one digit 0..3, then no digit and no point
    small = np.zeros(gp.size, dtype=bool)
    zeros = np.ones(gp.size, dtype=bool)  # the digits so far are all zeros
    for k in range(1, 20):
        b = at(k)
        digit = (b >= 48) & (b <= 57)
        end = ~digit & (b != _DOT)
        small |= zeros & end & (k > 1)  # G0, G00: only zeros
        nxt = at(k + 1)
        small |= zeros & (b >= 49) & (b <= 51) & ~((nxt >= 48) & (nxt <= 57)) & (nxt != _DOT)
        zeros &= b == 48
        if not zeros.any():
            break
    other_g_lines = cl_line[gp[~small]]
    if other_g_lines.size:
        both = set(other_g_lines.tolist()).intersection(cl_line[c == _R].tolist())
        bad[list(both)] = True


#: :func:`_classify` searches the lines with a "(" one by one for a comment inside a word when at most one line in
#: this many has one; else it scans the whole block once.
COMMENT_LINES_APART = 16

#: A comment after a letter or a number and before a number: inside a word (the full path refuses it, GC101).
_COMMENT_IN_WORD = re.compile(rb"[0-9A-Za-z.][ \t]*(?:\([^()\n]*\)[ \t]*)+[0-9.+\-]")


def _allowed_bytes(allowed: np.ndarray) -> bytes:
    """The bytes an :func:`_allowed_table` allows, for ``bytes.translate`` (which deletes them)."""
    return bytes(np.flatnonzero(allowed).tolist())


def _allowed_table(it: Any) -> np.ndarray:
    letters = set(b"GIJKRFNSM") | {ord(a) for a in it.axes if a in "XYZABCUVW"}
    allowed = np.zeros(256, dtype=bool)
    for ch in letters | set(b"0123456789.+-"):
        allowed[ch] = True
    for ch in letters:  # lower case is upper-cased before the code bytes are tested
        allowed[ch + 32] = True
    return allowed


_KEEP = np.ones(256, dtype=bool)
_KEEP[[_SP, _TAB, _CR, _NL]] = False
_UPPER = np.arange(256, dtype=np.uint8)
_UPPER[97:123] -= 32
_POW10 = 10 ** np.arange(19, dtype=np.int64)


# --------------------------------------------------------------------------- one run


def _parse_words(c, cl_line, lo_line, hi_line):
    """Words of lines [lo, hi): (line, letter, int value, decimals) arrays, or None if malformed.

    The value of a word is the integer of its digits (the decimal point
    removed); ``decimals`` counts the digits after the point.  At most 18
    digits, so no value can overflow ``int64``.
    """
    line = cl_line.dtype.type  # a key of the array's own type: a Python int would widen the whole array first
    sel_lo = np.searchsorted(cl_line, line(lo_line))
    sel_hi = np.searchsorted(cl_line, line(hi_line))
    cc = c[sel_lo:sel_hi]
    ln = cl_line[sel_lo:sel_hi]
    if cc.size == 0:
        return (np.zeros(0, np.int32), np.zeros(0, np.uint8), np.zeros(0, np.int64), np.zeros(0, np.int64),
                np.zeros(0, bool))
    is_letter = cc >= 65  # the classification let only letters, digits and . + - through
    # every line's first code byte must be a letter
    if not is_letter[0] or np.any(~is_letter[1:] & (ln[1:] != ln[:-1])):
        return None
    wstart = np.flatnonzero(is_letter)
    nwords = wstart.size
    wend = np.empty(nwords, dtype=np.int64)
    wend[:-1] = wstart[1:]
    wend[-1] = cc.size
    if np.any(wend - wstart <= 1):
        return None
    d = cc - np.uint8(48)  # digits 0..9; '.', '+', '-' wrap to 254, 251, 253
    isdigit = d < 10
    isdot = d == 254
    issign = (d == 251) | (d == 253)
    if not (is_letter | isdigit | isdot | issign).all():
        return None  # another byte (a line the classification did not let through)
    # a sign only right after the letter
    sp = np.flatnonzero(issign)
    if sp.size and not is_letter[sp - 1].all():
        return None
    # a word is its letter, at most one sign, digits and at most one point: its digits are the rest
    ndig = wend - wstart - 1
    if sp.size:
        ndig[np.searchsorted(wstart, sp, side="right") - 1] -= 1  # (one sign per word: it follows the letter)
    decimals = np.zeros(nwords, dtype=np.int64)
    dots = np.flatnonzero(isdot)
    points = np.zeros(nwords, dtype=bool)
    if dots.size:
        dw = np.searchsorted(wstart, dots, side="right") - 1  # the word of each point
        if np.any(dw[1:] == dw[:-1]):
            return None  # two points in one word
        decimals[dw] = wend[dw] - 1 - dots  # only digits follow the point
        ndig[dw] -= 1
        points[dw] = True
    if np.any(ndig == 0) or np.any(ndig > 18):
        return None
    # integer value of the digit string, by Horner's rule over all words at once: the digits of word w
    # are the ndig[w] consecutive entries of the digit list starting at first[w]; step k appends the
    # k-th digit of every word that has one (arrays of one entry per word, not per digit)
    digits = d[isdigit]
    first = np.zeros(nwords, dtype=np.int64)
    np.cumsum(ndig[:-1], out=first[1:])
    value = np.zeros(nwords, dtype=np.int64)
    top = digits.size - 1
    for k in range(int(ndig.max())):
        at = first + k
        np.minimum(at, top, out=at)
        value = np.where(ndig > k, value * 10 + digits[at], value)
    if sp.size:
        neg = np.zeros(nwords, dtype=bool)
        neg[np.searchsorted(wstart, sp[cc[sp] == 45], side="right") - 1] = True
        value = np.where(neg, -value, value)
    return ln[wstart], cc[wstart], value, decimals, points


def _fast_run(interp, code, lo, hi, block_counter, line0=0, parsed=None):
    """Interpret simple lines lo..hi-1 in columns; None to send them to the full path, or
    ``(chunk, end)`` when only lines lo..end-1 could be taken (a line with another M code follows)."""
    it = interp.interpreter
    c, cl_line = code
    if parsed is None:
        parsed = _parse_words(c, cl_line, lo, hi)
    if parsed is None:
        return None
    wl, wletter, wval, wdec, wpoint = parsed
    if getattr(it, "dialect", "linuxcnc") == "fanuc" and not _fanuc_words_ok(it, wletter, wval, wdec, wpoint):
        return None
    n = hi - lo
    axes = it.axes
    na = len(axes)
    # N only as the first word of its line; drop N words
    isN = wletter == ord("N")
    if isN.any():
        firstw = np.ones(wl.size, dtype=bool)
        firstw[1:] = wl[1:] != wl[:-1]
        if np.any(isN & ~firstw):
            return None
        keep = ~isN
        wl, wletter, wval, wdec = wl[keep], wletter[keep], wval[keep], wdec[keep]
    rel = wl - lo
    # duplicates of a letter in a line: a word with the letter of one of the (few) words before it in its
    # line, compared at distances 1, 2, ... while some line has that many words (``rel`` is sorted)
    same = rel[1:] == rel[:-1]
    j = 1
    while same.any():
        if np.any(same & (wletter[j:] == wletter[:-j])):
            return None
        j += 1
        same = same[1:] & (rel[j:] == rel[:-j])
    # S and spindle/coolant M words (M3 M4 M5 M7 M8 M9) change nothing the motion depends on
    # (Interpreter._lean); the last S and M3/M4/M5 of the run become the spindle state LinuxCNC's checks read.
    # A line with another M code ends the run before it
    isM = wletter == ord("M")
    isS = wletter == ord("S")
    only_sm_lines = None
    spindle: tuple = (None, None)  # the run's last S value and last M3/M4/M5
    if isM.any() or isS.any():
        bad = isM & ((wdec != 0) | ~np.isin(wval, _LEAN_M_CODES))
        if bad.any():
            return _cut_before(interp, code, lo, int(rel[np.argmax(bad)]), block_counter, line0, parsed)
        only_sm_lines = rel[isM | isS]  # blocks even when nothing else is left on the line
        if isS.any():
            if it.feed_mode == 95 or np.any(wval[isS] < 0):
                return None  # a speed that G95 feeds read line by line, or a negative one: the full path
            k = int(np.flatnonzero(isS)[-1])
            spindle = (Fraction(int(wval[k]), 10 ** int(wdec[k])), None)
        dirs = isM & np.isin(wval, (3, 4, 5))
        if dirs.any():
            spindle = (spindle[0], int(wval[int(np.flatnonzero(dirs)[-1])]))
        keep = ~(isM | isS)
        rel, wletter, wval, wdec = rel[keep], wletter[keep], wval[keep], wdec[keep]
        wl = wl[keep]
    # G words: values 0..3 without decimals
    isG = wletter == ord("G")
    gval = wval[isG]
    gdec = wdec[isG]
    gbad = (gdec > 0) | (gval < 0) | (gval > 3)
    if gbad.any():  # another G code: a Fanuc run's lines before it (G69 ending a rotation, say)
        return _cut_before(interp, code, lo, int(rel[isG][np.argmax(gbad)]), block_counter, line0, parsed) \
            if it.dialect == "fanuc" else None
    # scale
    inch = it.inch
    numeric = ~isG
    s = int(wdec[numeric].max()) if numeric.any() else 0
    s_units = s + (1 if inch else 0)
    need = [it.tlo, it.feed * (Fraction(254, 10) if inch else 1)] + list(it.pos) + list(it.off)
    xf = _transform_of(it, need)  # a Fanuc G68/G51: positions in the program system, then mapped (its numbers)
    if xf is False:
        return None
    for q in need:
        dd = _decimals(q)
        if dd is None:
            return None
        s_units = max(s_units, dd)
    if s_units > _MAX_SCALE:
        return None
    S = s_units
    if numeric.any():
        # |value| * 10**(S - decimals) * 25.4 must stay below 2**59: a bound from the extremes first
        nv, nd = wval[numeric], wdec[numeric]
        if int(np.abs(nv).max()) * 10 ** (S - int(nd.min())) * 254 // 10 >= 2**59:
            if np.any(np.abs(nv).astype(np.float64) * 10.0 ** (S - nd) * 25.4 > 2.0**59):
                return None
    # per line: has word?  blocks are lines with at least one word (after N)
    has_word = np.zeros(n, dtype=bool)
    has_word[rel] = True
    if only_sm_lines is not None:
        has_word[only_sm_lines] = True
    # motion mode per line (forward filled)
    gline = np.full(n, -1, dtype=np.int64)
    gline[rel[isG]] = gval
    mode0 = -1 if it.motion is None else it.motion // 10
    idx = np.where(gline >= 0, np.arange(n), -1)
    idx = np.maximum.accumulate(idx)
    mode = np.where(idx >= 0, gline[np.maximum(idx, 0)], mode0)
    # values scaled to S (mm) per letter per line
    def scaled(mask):
        v = wval[mask]
        e = S - wdec[mask] - (1 if inch else 0)
        if e.size and int(e.min()) == int(e.max()):  # common: one number of decimals
            out = v * int(_POW10[int(e[0])])
        else:
            out = v * _POW10[e]
        if inch:
            out = out * 254
        return out

    axis_present = []
    axis_val = []
    for k, a in enumerate(axes):
        pres = np.zeros(n, dtype=bool)
        val = np.zeros(n, dtype=np.int64)
        m = wletter == ord(a)
        if m.any():
            rows = rel[m]
            pres[rows] = True
            if it.rotary[k]:
                val[rows] = wval[m] * _POW10[S - wdec[m]]
            else:
                val[rows] = scaled(m)
        axis_present.append(pres)
        axis_val.append(val)
    moving = np.logical_or.reduce(axis_present) if na else np.zeros(n, dtype=bool)
    # I J K
    ijk = {}
    for letter in "IJK":
        m = wletter == ord(letter)
        if m.any():
            col = np.zeros(n, dtype=np.int64)
            pres = np.zeros(n, dtype=bool)
            col[rel[m]] = scaled(m)
            pres[rel[m]] = True
            ijk[letter] = (col, pres)
    any_ijk = np.zeros(n, dtype=bool)
    for _col, pres in ijk.values():
        any_ijk |= pres
    r_col = r_pres = None
    rmask = wletter == ord("R")
    if rmask.any():  # R-format arcs (the R word on a line that is no arc: the full path)
        r_col = np.zeros(n, dtype=np.int64)
        r_pres = np.zeros(n, dtype=bool)
        r_col[rel[rmask]] = scaled(rmask)
        r_pres[rel[rmask]] = True
        if np.any(r_pres & any_ijk):
            return None  # R and I/J/K in one arc: the full path refuses it
        any_ijk = any_ijk | r_pres
    is_arc_line = (mode == 2) | (mode == 3)
    if np.any(any_ijk & ~is_arc_line):
        return None
    if np.any((mode < 0) & moving):
        return None
    arc_rows = is_arc_line & (moving | (gline >= 2))
    if np.any(is_arc_line & (gline >= 2) & ~moving & ~any_ijk):
        return None
    if np.any(any_ijk & ~arc_rows):
        return None
    # feed
    fmask = wletter == ord("F")
    feed = np.zeros(n, dtype=np.int64)
    fpres = np.zeros(n, dtype=bool)
    if fmask.any():
        if np.any(wval[fmask] < 0):
            return None
        feed[rel[fmask]] = scaled(fmask)
        fpres[rel[fmask]] = True
    f0 = _scaled_int(it.feed * (Fraction(254, 10) if inch else 1), S)
    fidx = np.maximum.accumulate(np.where(fpres, np.arange(n), -1))
    feed_line = np.where(fidx >= 0, feed[np.maximum(fidx, 0)], f0)
    feedmove = (arc_rows | (moving & (mode == 1)))
    feedcheck = feedmove | (gline == 1)  # LinuxCNC checks the feed of a G1 block without axis words too
    if it.feed_mode != 93 and np.any(feedcheck & (feed_line == 0)):
        return None  # LinuxCNC refuses a feed move without a feed rate: the full path says so
    if it.feed_mode == 95 and feedcheck.any() and it.spindle_speed is not None and not it.spindle_speed:
        return None  # G95 with spindle speed 0 (or not followed): the full path
    if it.feed_mode == 93 and np.any(feedcheck & ~fpres):
        return None  # G93 wants F in every feed block
    # positions
    pos0 = [_scaled_int(p, S) for p in (it.pos if xf is None else it.prog)]
    off = [_scaled_int(o, S) for o in it.off] if xf is None else [0] * na
    if max(map(abs, pos0 + off + [f0, _scaled_int(it.tlo, S)]), default=0) > _LIMIT_STATE:
        return None  # the state's numbers could overflow int64 in sums: the full path (exact ints)
    end = np.empty((n, na), dtype=np.int64)
    ar = np.arange(n, dtype=np.int64)
    for k in range(na):
        pres, val = axis_present[k], axis_val[k]
        if it.absolute:
            # forward fill of the last programmed value (plus the work offset)
            pidx = np.maximum.accumulate(np.where(pres, ar, -1))
            col = val[np.maximum(pidx, 0)] + off[k]
            end[:, k] = np.where(pidx >= 0, col, pos0[k])
        else:
            if float(np.abs(val).astype(np.float64).sum()) + abs(pos0[k]) > 2.0**60:
                return None
            np.cumsum(val, out=end[:, k])
            end[:, k] += pos0[k]
    start = np.vstack((np.array(pos0, dtype=np.int64)[None, :], end[:-1]))
    emit = moving | arc_rows
    rows = np.flatnonzero(emit)
    m = rows.size
    kind = np.where(mode[rows] == 0, SegmentKind.RAPID, np.where(mode[rows] == 1, SegmentKind.LINE, SegmentKind.ARC)).astype(np.int8)
    st = start[rows]
    en = end[rows]
    centre = plane_col = cw = turns = radius = None
    arcs = kind == SegmentKind.ARC
    if arcs.any():
        got = _arc_columns(it, xf, rows, arcs, mode, start, end, ijk, (r_col, r_pres), off, bool(inch), S)
        if got is None:
            return None
        centre, plane_col, cw, turns, radius = got
    last = end[-1]
    if xf is not None:  # the program points mapped to the machine's (a point in doubt cuts the run before it)
        mapped = _transformed(xf, it, pos0, end, rows, st, centre, cw, arcs, S)
        if isinstance(mapped, int):
            return _cut_before(interp, code, lo, mapped, block_counter, line0, parsed)
        if mapped is None:
            return None
        st, en, centre, cw, last = mapped
    # blocks and lines
    block_of_line = np.cumsum(has_word) - 1 + block_counter[0]
    block_counter[0] += int(has_word.sum())
    tl = _scaled_int(it.tlo, S)
    chunk = MotionChunk(
        axes, S, kind=kind, start=st, end=en, line=(rows + (lo + 1 + line0)).astype(np.int64),
        block=block_of_line[rows].astype(np.int64), tool_length=np.full(m, tl, dtype=np.int64),
        centre=centre, plane=plane_col, clockwise=cw, turns=turns,
        feed=(feed_line[rows] if it.feed_mode == 94 else None), file=interp.file,
        frame=it.program_frame(), tool_register=it.tool_register, tools_known=True,  # a run of simple lines
        radius=radius if radius is not None and radius.any() else None)  # changes no offset, unit, transform, tool
    # hand the state back to the interpreter
    den = 10**S
    it.pos = [Fraction(int(v), den) for v in last]
    if xf is not None:
        it.prog = [Fraction(int(v), den) for v in end[-1]]
    last_mode = int(mode[-1])
    it.motion = None if last_mode < 0 else last_mode * 10
    if it.feed_mode == 93 and feedcheck.any():
        it.feed_inverse_rate = True  # LinuxCNC's feed rate is now a move's length x F (Interpreter._motion_block)
    if fpres.any() and it.feed_mode != 93:  # an F in G93 is the block's own (Interpreter: #<_feed> keeps G94's)
        last_f = Fraction(int(feed_line[-1]), den)
        it.feed = last_f / Fraction(254, 10) if inch else last_f
    if spindle[0] is not None:
        it.spindle_speed = spindle[0]
    if spindle[1] is not None:
        it.spindle_dir = 1 if spindle[1] == 3 else -1 if spindle[1] == 4 else 0
    if m:
        it.note_assumed(("units", "distance", "offset", "plane") if arcs.any() and xf is None
                        else ("units", "distance", "offset"))
    it.blocks += int(has_word.sum())
    it.segment_count += m
    for k in (SegmentKind.RAPID, SegmentKind.LINE, SegmentKind.ARC):
        it.kind_counts[k] += int(np.count_nonzero(kind == k))
    interp.fast_lines += n
    return chunk


def _cut_before(interp: Any, code: Any, lo: int, first_bad: int, block_counter: Any, line0: int,
                parsed: tuple) -> tuple | None:
    """The run's lines before its line ``lo + first_bad`` (one the fast path cannot take) in columns, with that
    line: ``(chunk, lo + first_bad)``; None when it is the first (nothing taken)."""
    if first_bad == 0:
        return None
    # the words of the lines before it, as parsing only those lines gives them (a word ends where the next
    # begins, so cutting at a line changes no word)
    k = int(np.searchsorted(parsed[0], lo + first_bad))
    chunk = _fast_run(interp, code, lo, lo + first_bad, block_counter, line0, tuple(a[:k] for a in parsed))
    if chunk is None or type(chunk) is tuple:  # (cut again, earlier: a G code before an M code, say)
        return chunk
    return chunk, lo + first_bad


def _transform_of(it: Any, need: list) -> Any:
    """None when no programmable transform is active (``it.prog`` None: every interpreter but a Fanuc one under
    G68/G51/...); else the one ``nczones.gcode.fanuc.transform_columns`` maps (its numbers added to ``need``),
    or False when the lane does not mirror it."""
    if getattr(it, "prog", None) is None:
        return None
    xf = it.column_transform()
    if xf is None:
        return False
    need.extend(xf.numbers)
    return xf


def _transformed(xf: Any, it: Any, ppos0: list[int], pend: np.ndarray, rows: np.ndarray, st: np.ndarray,
                 centre: Any, cw: Any, arcs: np.ndarray, S: int) -> tuple | int | None:
    """A run's program columns (start ``st`` of the motions ``rows``, every line's point ``pend``, the arcs'
    centres) mapped by the transform ``xf``: ``(start, end, centre, clockwise, last machine point)``, the line to
    cut the run before, or None (``transform_columns.machine_columns``)."""
    from .fanuc.transform_columns import machine_columns, reverses

    pos0 = [_scaled_int(p, S) for p in it.pos]
    arc_in = None
    if centre is not None:
        at = np.flatnonzero(arcs)
        ia, ib = it.index[PLANE_AXES[it.plane][0]], it.index[PLANE_AXES[it.plane][1]]
        arc_in = (arcs, st[at], centre[at, 0], centre[at, 1], ia, ib)
    got = machine_columns(xf, pos0, pend, rows, S, arc_in)
    if got is None or isinstance(got, int):
        return got
    mst, men, cen_a, cen_b = got
    if centre is not None:
        centre = centre.copy()
        centre[at, 0], centre[at, 1] = cen_a, cen_b
        if reverses(xf, ia, ib):
            cw = arcs & ~cw
    return mst, men, centre, cw, men[-1] if len(men) else np.array(pos0, dtype=np.int64)


def _arc_columns(it: Any, xf: Any, rows: np.ndarray, arcs: np.ndarray, mode: np.ndarray, start: np.ndarray,
                 end: np.ndarray, ijk: dict, r_words: tuple, off: list[int], inch: bool, S: int) -> tuple | None:
    """The arc columns of a run's motions ``rows`` (``arcs`` marks them): ``(centre, plane, clockwise, turns,
    radius)``, or None when an arc needs the full path (it reports errors).  Under a transform ``xf`` (program
    points) R arcs, absolute centres and a plane the transform does not map arcs in decline."""
    from .fanuc.transform_columns import arcs_plane_ok

    n, m = len(end), len(rows)
    r_col, r_pres = r_words
    plane = it.plane
    a_name, b_name, n_name = PLANE_AXES[plane]
    ia, ib = it.index.get(a_name), it.index.get(b_name)
    if ia is None or ib is None:
        return None
    if xf is not None and (it.arc_absolute or (r_pres is not None and r_pres[rows[arcs]].any())
                           or not arcs_plane_ok(xf, ia, ib)):
        return None
    offs = {"X": "I", "Y": "J", "Z": "K"}
    la, lb, ln_ = offs[a_name], offs[b_name], offs[n_name]
    if ln_ in ijk and np.any(ijk[ln_][1][rows[arcs]]):
        return None
    arow = rows[arcs]
    ia_col = ijk.get(la, (np.zeros(n, np.int64), np.zeros(n, bool)))
    ib_col = ijk.get(lb, (np.zeros(n, np.int64), np.zeros(n, bool)))
    r_rows = None
    if r_pres is not None and r_pres[arow].any():
        assert r_col is not None
        r_rows = r_pres[arow]
        got = _r_arcs(start[arow[r_rows], ia], start[arow[r_rows], ib], end[arow[r_rows], ia],
                      end[arow[r_rows], ib], r_col[arow[r_rows]])
        if got is None:
            return None
        r_half, r_ca, r_cb = got
    if np.any(~(ia_col[1][arow] | ib_col[1][arow] | (False if r_rows is None else r_rows))):
        return None  # missing centre: full path
    if it.arc_absolute:
        ca = np.where(ia_col[1][arow], ia_col[0][arow] + off[ia], off[ia])
        cb = np.where(ib_col[1][arow], ib_col[0][arow] + off[ib], off[ib])
    else:
        ca = start[arow, ia] + ia_col[0][arow]
        cb = start[arow, ib] + ib_col[0][arow]
    radius = None
    if r_rows is not None:
        ij = ~r_rows
        ca, cb = ca[ij], cb[ij]
    else:
        ij = slice(None)
    # under LinuxCNC's rule the arcs LinuxCNC accepts (the interpreter's rule, decided the same way);
    # a run with an arc it refuses goes to the full interpreter, which reports it
    if getattr(it, "arc_rule", "fixed") == "linuxcnc":
        if not _arcs_ok_linuxcnc(start[arow[ij], ia], start[arow[ij], ib], end[arow[ij], ia],
                                 end[arow[ij], ib], ca, cb, bool(inch), S):
            return None
    elif not _arcs_ok(start[arow[ij], ia], start[arow[ij], ib], end[arow[ij], ia], end[arow[ij], ib], ca, cb,
                      it.arc_tolerance, S):
        return None
    centre = np.zeros((m, 2), dtype=np.int64)
    if r_rows is None:
        centre[arcs, 0] = ca
        centre[arcs, 1] = cb
    else:
        at = np.flatnonzero(arcs)
        centre[at[ij], 0] = ca
        centre[at[ij], 1] = cb
        centre[at[r_rows], 0] = r_ca
        centre[at[r_rows], 1] = r_cb
        radius = np.zeros(m, dtype=np.int64)
        assert r_col is not None
        radius[at[r_rows]] = np.where(r_half, 0, r_col[arow[r_rows]])
    plane_col = np.where(arcs, int(plane), 0).astype(np.int8)
    cw = arcs & (mode[rows] == 2)
    turns = np.zeros(m, dtype=np.int32)
    return centre, plane_col, cw, turns, radius


_FANUC_LENGTH = np.zeros(256, dtype=bool)
_FANUC_LENGTH[list(b"XYZUVWABCIJKRQ")] = True
_FANUC_ROTARY = np.zeros(256, dtype=bool)
_FANUC_ROTARY[list(b"ABC")] = True


def _fanuc_words_ok(it: Any, wletter: np.ndarray, wval: np.ndarray, wdec: np.ndarray,
                    points: np.ndarray) -> bool:
    """Whether every length word (of the parsed words of a run) is read as written in the Fanuc dialect: with
    a decimal point (or zero) and no more decimals than the least input increment.  Other lines go to the
    language layer, which applies the decimal point input rule and the rounding and notes them."""
    length = _FANUC_LENGTH[wletter]
    if not length.any():
        return True
    digits = {"IS-A": 2, "IS-B": 3, "IS-C": 4}[it.settings.increment_system]
    limit = np.where(_FANUC_ROTARY[wletter], digits, digits + (1 if it.inch else 0))
    bad = length & ((~points & (wval != 0)) | (wdec > limit))
    return not bad.any()


def _decimals(q: Fraction) -> int | None:
    from ..exact import decimal_places

    return decimal_places(q)


def _scaled_int(q: Fraction, S: int) -> int:
    v = q * 10**S
    if v.denominator != 1:
        raise ValueError("not representable")
    return int(v)


#: Chord components and radii (scaled) of R-format arcs the fast path takes: squares stay in ``int64``.
_R_LIMIT = 2**30


def _r_arcs(sa: np.ndarray, sb: np.ndarray, ea: np.ndarray, eb: np.ndarray,
            r: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """R-format arcs as ``Interpreter.arc`` emits them: ``(half, ca, cb)`` where ``half`` marks the half
    circles (chord exactly ``2|R|``: the chord's midpoint is their centre, ``ca``/``cb``), the other rows
    keep their signed R (no centre); None when a row needs the full path: start equal to end (GC303, or
    Fanuc's arc of no motion), R = 0 (GC304), a chord longer than ``2|R|`` (GC302, or a half circle within
    the radius tolerance), a chord within the interpreter's relative ``_TINY`` of ``2|R|`` but not equal
    (taken as a half circle there), a midpoint that is not on the scale, or numbers whose squares could
    leave ``int64``.

    The decision is exact: ``D = chord**2`` and ``4 R**2`` are exact integers; a row is a plain R arc when
    ``D < 4 R**2 (1 - 10**-12)**2``, i.e. ``D * 10**24 < 4 R**2 (10**12 - 1)**2``, decided with a float
    only where the two sides differ by far more than its rounding (``D / 4R**2 < 1 - 10**-9``), and with
    Python integers on the few others.
    """
    da = ea - sa
    db = eb - sb
    if np.any((np.abs(da) >= _R_LIMIT) | (np.abs(db) >= _R_LIMIT) | (np.abs(r) >= _R_LIMIT) | (r == 0)):
        return None
    d2 = da * da + db * db
    if np.any(d2 == 0):
        return None
    r4 = 4 * r * r
    half = d2 == r4
    near = ~half & (d2.astype(np.float64) / r4.astype(np.float64) >= 1 - 1e-9)
    for k in np.flatnonzero(near).tolist():
        if int(d2[k]) * 10**24 >= int(r4[k]) * (10**12 - 1) ** 2:
            return None  # a half circle by the interpreter's tolerance, or too short an R
    ma, mb = sa + ea, sb + eb
    if np.any(half & (((ma | mb) & 1) != 0)):
        return None  # a half circle whose centre is not on the scale
    return half, np.where(half, ma // 2, 0), np.where(half, mb // 2, 0)


def _arcs_ok(sa: np.ndarray, sb: np.ndarray, ea: np.ndarray, eb: np.ndarray, ca: np.ndarray, cb: np.ndarray,
             tol: Fraction, S: int) -> bool:
    """Every arc: both radii non-zero and |r0 - r1| <= tol (exactly)."""
    r0f = (sa - ca).astype(np.float64) ** 2 + (sb - cb).astype(np.float64) ** 2
    r1f = (ea - ca).astype(np.float64) ** 2 + (eb - cb).astype(np.float64) ** 2
    if np.any(((sa == ca) & (sb == cb)) | ((ea == ca) & (eb == cb))):
        return False
    t = float(tol * 10**S)
    diff = np.abs(np.sqrt(r0f) - np.sqrt(r1f))
    rad = np.sqrt(np.maximum(r0f, r1f))
    margin = rad * 1e-9 + 1.0
    clear_ok = diff + margin < t
    unsure = ~clear_ok
    if not unsure.any():
        return True
    from .interpreter import sqrt_diff_exceeds

    tt = tol * 10**S
    for k in np.flatnonzero(unsure).tolist():
        a0 = (int(sa[k]) - int(ca[k])) ** 2 + (int(sb[k]) - int(cb[k])) ** 2
        a1 = (int(ea[k]) - int(ca[k])) ** 2 + (int(eb[k]) - int(cb[k])) ** 2
        if a0 != a1 and sqrt_diff_exceeds(Fraction(a0), Fraction(a1), tt):
            return False
    return True


#: Above LinuxCNC's smallest I/J/K radius (0.00127 mm, ``interpreter.LINUXCNC_ZERO_RADIUS_SQ``) by far more than the
#: rounding of the float radii: a smaller radius is the interpreter's to decide.
_ZERO_RADIUS = 0.00127 * (1 + 1e-6)


def _arcs_ok_linuxcnc(sa: np.ndarray, sb: np.ndarray, ea: np.ndarray, eb: np.ndarray, ca: np.ndarray,
                      cb: np.ndarray, inch: bool, S: int) -> bool:
    """Every arc: both radii above LinuxCNC's zero-radius limit and accepted by its rule
    (``interpreter.linuxcnc_rejects_arc``).

    Arcs clearly inside the rule by a float test with a wide margin are accepted; every other arc is decided
    by the interpreter's own function on its exact squared radii, so the answer is the interpreter's.
    """
    if np.any(((sa == ca) & (sb == cb)) | ((ea == ca) & (eb == cb))):
        return False
    unit = 10.0**S * (25.4 if inch else 1.0)  # scaled integers per program unit
    r0 = np.sqrt((sa - ca).astype(np.float64) ** 2 + (sb - cb).astype(np.float64) ** 2) / unit
    r1 = np.sqrt((ea - ca).astype(np.float64) ** 2 + (eb - cb).astype(np.float64) ** 2) / unit
    if np.any(np.minimum(r0, r1) * (25.4 if inch else 1.0) < _ZERO_RADIUS):
        return False  # LinuxCNC's "Zero-radius arc" (interpreter.LINUXCNC_ZERO_RADIUS_SQ): the interpreter's
    tol = 2 * (0.001 if inch else 0.01) * math.sqrt(2)
    err = np.abs(r1 - r0)
    big = np.maximum(r0, r1)
    slack = big * 1e-9 + 1e-9  # far above the rounding of these few operations
    clear = (err + slack < tol) | ((err + slack < 100 * tol) & (err + slack < 0.001 * (big - slack)))
    unsure = np.flatnonzero(~clear)
    if unsure.size == 0:
        return True
    from .interpreter import linuxcnc_rejects_arc

    den = 10 ** (2 * S)
    for k in unsure.tolist():
        a0 = (int(sa[k]) - int(ca[k])) ** 2 + (int(sb[k]) - int(cb[k])) ** 2
        a1 = (int(ea[k]) - int(ca[k])) ** 2 + (int(eb[k]) - int(cb[k])) ** 2
        if linuxcnc_rejects_arc(Fraction(a0, den), Fraction(a1, den), inch):
            return False
    return True


# --------------------------------------------------------------------------- drilling cycles

_XYN = np.zeros(256, dtype=bool)
_XYN[list(b"XYN")] = True


def _cycle_state_ok(it: Any) -> bool:
    """The state in which a hole line (X/Y words only) under G81/G82 is exactly what :func:`_fast_cycle_run` builds."""
    comp = getattr(it, "cutter_comp", None)
    return (not it.unsupported and it.motion in (810, 820) and it.last_cycle == it.motion
            and it.absolute and it.plane is Plane.XY and it.feed_mode == 94 and it.feed > 0
            and not it.comp_on and not it.comp_just_off and (comp is None or comp.side is None)
            and not it.track and it.prerotation_xy is None and it.machine_at is None and not it.m73_saved
            and it.spline_state is None and it.cycle_r is not None and it.cycle_cc is not None
            and it.cycle_il is not None and all(a in it.index for a in "XYZ"))


def _holes_active(it: Any) -> bool:
    """Is a cycle modal whose hole lines the fast path may take (LinuxCNC's G81/G82 motion mode, a Fanuc
    control's group 09 code of :data:`FANUC_HOLE_CYCLES`)?"""
    return it.motion in (810, 820) or getattr(it, "cycle", None) in FANUC_HOLE_CYCLES


def _linuxcnc_holes(it: Any) -> tuple | None:
    """LinuxCNC's hole (``Interpreter._cycle`` for a block of X/Y words after the cycle's first): ``(name, levels,
    template, feed, dwell, the modal groups noted)``, the template's rows ``(kind, at the previous hole?, level,
    what)``: an "up to R" rapid at the previous hole when the initial level is below R, a "position" rapid at
    the clear level, a "to R" rapid when R is below it, the feed to the bottom, a dwell (G82) and the retract to
    the clear level (R under G99, the initial level under G98), each row's ``derived`` name written out; None when
    the state is not that one (the Z axis must be at the clear level: true after every hole)."""
    if not _cycle_state_ok(it):
        return None
    ic = it.index["Z"]
    ln = (lambda v: v * Fraction(254, 10)) if it.inch else (lambda v: v)
    r = ln(it.cycle_r) + it.off[ic]
    cc = ln(it.cycle_cc) + it.off[ic]
    il = it.cycle_il
    if r < cc:
        return None  # GC306: the full path raises it
    up_r = il < r
    clear = r if (it.retract_r or up_r) else il
    if it.pos[ic] != clear:
        return None
    dwell = it.cycle_p if it.motion == 820 else None
    R, L, D = SegmentKind.RAPID, SegmentKind.LINE, SegmentKind.DWELL
    name = "G81" if it.motion == 810 else "G82"
    tmpl = [(R, True, "r", f"{name} up to R")] if up_r else []
    tmpl.append((R, False, "clear", f"{name} position"))
    if r < clear:
        tmpl.append((R, False, "r", f"{name} to R"))
    tmpl.append((L, False, "cc", f"{name} feed"))
    if dwell is not None:
        tmpl.append((D, False, "cc", f"{name} dwell"))
    tmpl.append((R, False, "clear", f"{name} retract"))
    return name, {"r": r, "cc": cc, "clear": clear}, tmpl, ln(it.feed), dwell, ("units", "distance", "offset", "plane")


#: The hole of each dialect (:func:`_fast_cycle_run`)
_HOLES = {"linuxcnc": _linuxcnc_holes, "fanuc": fanuc_holes}


def _hole_lines(code: Any, lo: int, hi: int, parsed: Any) -> tuple | None:
    """The hole lines lo..j-1 (the longest prefix of lo..hi-1 holding only X, Y and a leading N): ``(j, rel,
    wletter, wval, wdec, wpoint, has_word)``, the X and Y words' lines (relative to ``lo``), letters, values,
    decimals and points, and which lines have a word; None when there is none."""
    c, cl_line = code
    if parsed is None:
        parsed = _parse_words(c, cl_line, lo, hi)
    if parsed is None:
        return None
    wl, wletter, wval, wdec, wpoint = parsed
    # the first line (from lo) with a word other than X, Y, N ends the run; so does a repeated
    # letter or an N that is not the first word
    rel = (wl - lo).astype(np.int64)
    bad = ~_XYN[wletter]
    firstw = np.ones(wl.size, dtype=bool)
    firstw[1:] = rel[1:] != rel[:-1]
    isN = wletter == ord("N")
    bad |= isN & ~firstw
    if rel.size:
        bits = np.left_shift(np.int64(1), (wletter.astype(np.int64) - 65))
        lstart = np.flatnonzero(firstw)
        dup = np.add.reduceat(bits, lstart) != np.bitwise_or.reduceat(bits, lstart)
        bad[lstart[dup]] = True
    j = hi
    if bad.any():
        j = lo + int(rel[int(np.argmax(bad))])
    if j <= lo:
        return None
    keep = (rel < j - lo) & ~isN
    has_word = np.zeros(j - lo, dtype=bool)
    has_word[rel[keep]] = True
    return j, rel[keep], wletter[keep], wval[keep], wdec[keep], wpoint[keep], has_word


def _fast_cycle_run(interp, code, lo, hi, block_counter, line0=0, parsed=None):
    """Hole lines lo..j-1 (the longest prefix of lo..hi-1 holding only X, Y and a leading N) under an
    active G81/G82 cycle, in columns: ``(chunk, j)``, or None to send line ``lo`` to the full path.

    The rows of a hole are the dialect's template (:data:`_HOLES`: LinuxCNC's ``Interpreter._cycle``, a Fanuc
    control's ``FanucInterpreter._fanuc_cycle``, each for a block of X/Y words after the cycle's first), the
    same kinds, levels, feeds, dwells and ``derived`` names; the state is handed back as they leave it."""
    it = interp.interpreter
    plan = _HOLES[getattr(it, "dialect", "linuxcnc")](it)
    if plan is None:
        return None
    lines = _hole_lines(code, lo, hi, parsed)
    if lines is None:
        return None
    j, rel, wletter, wval, wdec, wpoint, has_word = lines
    if getattr(it, "dialect", "linuxcnc") == "fanuc" and not _fanuc_words_ok(it, wletter, wval, wdec, wpoint):
        return None  # a length without a point, or finer than the increment: the language layer's rules
    scaled = _hole_scale(it, plan, wval, wdec)
    if scaled is None:
        return None
    return _hole_chunk(interp, plan, scaled, (lo, j, rel, wletter, wval, wdec, has_word), block_counter, line0), j


def _hole_scale(it: Any, plan: tuple, wval: np.ndarray, wdec: np.ndarray) -> tuple | None:
    """The scale ``S`` of a hole run's columns and the state scaled by it: ``(S, pos0, off, levels, tool length,
    feed, dwell)``; None when a number is not a decimal of at most :data:`_MAX_SCALE` places or too large."""
    _name, levels, _tmpl, fmm, dwell, _notes = plan
    inch = it.inch
    s = int(wdec.max()) if wdec.size else 0
    S = s + (1 if inch else 0)
    for q in [it.tlo, fmm, *levels.values(), *it.pos, *it.off] + ([dwell] if dwell is not None else []):
        dd = _decimals(q)
        if dd is None:
            return None
        S = max(S, dd)
    if S > _MAX_SCALE:
        return None
    if wval.size:
        if int(np.abs(wval).max()) * 10 ** (S - int(wdec.min())) * 254 // 10 >= 2**59:
            if np.any(np.abs(wval).astype(np.float64) * 10.0 ** (S - wdec) * 25.4 > 2.0**59):
                return None
    pos0 = [_scaled_int(p, S) for p in it.pos]
    off = [_scaled_int(o, S) for o in it.off]
    z = {k: _scaled_int(v, S) for k, v in levels.items()}
    tl, f_s = _scaled_int(it.tlo, S), _scaled_int(fmm, S)
    dw = _scaled_int(dwell, S) if dwell is not None else 0
    if max(map(abs, pos0 + off + [*z.values(), tl, f_s, dw]), default=0) > _LIMIT_STATE:
        return None
    return S, pos0, off, z, tl, f_s, dw


def _hole_xy(it: Any, S: int, pos0: list[int], off: list[int], words: tuple) -> list[tuple[np.ndarray, np.ndarray]]:
    """Per line of a hole run, the hole's X and Y (machine, scaled), forward filled from the last word, and the
    lines that write them."""
    _lo, j, rel, wletter, wval, wdec, _has = words
    n = len(_has)
    ar = np.arange(n, dtype=np.int64)
    cols = []
    for letter, k in (("X", it.index["X"]), ("Y", it.index["Y"])):
        m = wletter == ord(letter)
        val = np.zeros(n, dtype=np.int64)
        pres = np.zeros(n, dtype=bool)
        if m.any():
            e = S - wdec[m] - (1 if it.inch else 0)
            v = wval[m] * _POW10[e]
            if it.inch:
                v = v * 254
            val[rel[m]] = v
            pres[rel[m]] = True
        pidx = np.maximum.accumulate(np.where(pres, ar, -1))
        cols.append((np.where(pidx >= 0, val[np.maximum(pidx, 0)] + off[k], pos0[k]), pres))
    return cols


def _hole_chunk(interp: Any, plan: tuple, scaled: tuple, words: tuple, block_counter: Any,
                line0: int) -> MotionChunk:
    """The rows of a hole run (every hole the template's rows) as a column chunk; the interpreter's state after it."""
    it = interp.interpreter
    name, _levels, tmpl, _fmm, dwell, notes = plan
    S, pos0, off, z, tl, f_s, dw = scaled
    lo, _j, _rel, _wletter, _wval, _wdec, has_word = words
    (cx, px_), (cy, py_) = _hole_xy(it, S, pos0, off, words)
    holes = np.flatnonzero(px_ | py_)
    h = holes.size
    n = len(has_word)
    block_of_line = np.cumsum(has_word) - 1 + block_counter[0]
    block_counter[0] += int(has_word.sum())
    it.blocks += int(has_word.sum())
    interp.fast_lines += n
    if h == 0:
        return MotionChunk(it.axes, None, objects=(), file=interp.file)
    ia, ib, ic = it.index["X"], it.index["Y"], it.index["Z"]
    hx, hy = cx[holes], cy[holes]
    px = np.concatenate(([pos0[ia]], hx[:-1]))
    py = np.concatenate(([pos0[ib]], hy[:-1]))
    T = len(tmpl)
    rows = h * T
    end = np.empty((rows, len(it.axes)), dtype=np.int64)
    end[:] = np.asarray(pos0, dtype=np.int64)
    ex, ey, ez = (end[:, k].reshape(h, T) for k in (ia, ib, ic))
    for t, (_kind, prev, level, _what) in enumerate(tmpl):
        ex[:, t] = px if prev else hx
        ey[:, t] = py if prev else hy
        ez[:, t] = z[level]
    end[:, ia], end[:, ib], end[:, ic] = ex.reshape(-1), ey.reshape(-1), ez.reshape(-1)
    start = np.vstack((np.asarray(pos0, dtype=np.int64)[None, :], end[:-1]))
    kind = np.tile(np.array([int(t[0]) for t in tmpl], dtype=np.int8), h)
    names = np.empty(T, dtype=object)
    names[:] = [t[3] for t in tmpl]
    D = SegmentKind.DWELL
    chunk = MotionChunk(
        it.axes, S, kind=kind, start=start, end=end,
        line=np.repeat(holes + (lo + 1 + line0), T).astype(np.int64),
        block=np.repeat(block_of_line[holes], T).astype(np.int64), tool_length=np.full(rows, tl, dtype=np.int64),
        feed=np.full(rows, f_s, dtype=np.int64), file=interp.file,
        dwell=np.where(kind == D, dw, 0).astype(np.int64) if dwell is not None else None, derived=np.tile(names, h),
        frame=it.program_frame(), tool_register=it.tool_register, tools_known=True,
    )
    # hand the state back to the interpreter (as the dialect's cycle and emit() leave it)
    last = end[-1].tolist()
    den = 10**S
    it.pos = tuple(it.pos[k] if k not in (ia, ib, ic) else Fraction(int(last[k]), den) for k in range(len(it.axes)))
    it.prerotation_xy_next = None
    it.note_assumed(notes)
    it.segment_count += rows
    for kk in (SegmentKind.RAPID, SegmentKind.LINE, D):
        it.kind_counts[kk] += h * sum(1 for t in tmpl if t[0] is kk)
    return chunk
