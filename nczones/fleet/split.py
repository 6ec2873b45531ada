"""Splitting a long program into chunks that verify on several workers, and combining their results.

A chunk must start from the exact machine state the previous chunk ends in.
The interpreter's state is not a public value, so a program is split only
where that state can be read off the text exactly; every other program is
verified whole.  :func:`split_program` splits a program only when all of
these hold (checked on the text with its comments blanked):

* the settings have no parameter ranges, no tool-break recovery and no
  subprogram library, and the dialect is ``linuxcnc``;
* the program uses only these words: G0 G1 G2 G3 G17 G18 G19 G20 G21 G40
  G43 (with H on its line) G49 G54-G59 G80 G90 G90.1 G91.1 G94, M2 M3 M4 M5
  M7 M8 M9 M30, the machine's axis letters, I J K R P F S N H; every letter
  directly followed by its number; no ``#``, ``[``, ``O``, ``/``, ``%``,
  ``T``, ``G91``, ``G92``, ``G53``, cycles, cutter compensation, tool changes;
* ``G90`` is written on or before the first line with an axis word (so every
  axis word is an absolute position), and M2/M30, if present, is followed by
  no other word;
* at a boundary, no units, work-offset or tool-length code stands between
  an axis's last word and the boundary.

Under these conditions the state at the start of a line is: for each modal
group the last code written before it (or the machine's initial code), the
last F word, and for each axis the last value written, in the units, work
offset and tool length in force when it was written, which are those in
force at the boundary.  Each chunk after the first is verified as
``preamble`` (those modal codes and F on one line, no motion) followed by
its lines, on the machine with its start position moved to the machine
position at the boundary.  That position is computed by the interpreter
itself: the end of a rapid to the last axis values after the same preamble.

:func:`combine` joins the chunks' results (worst verdict wins, violations in
execution order, the first ``max_violations`` kept, block numbers and lines
those of the whole program).  It declines (returns None) when a chunk has a
reason for ``unknown`` or a finding on its preamble line: the caller then
verifies the program whole, so a split never changes a verdict.  The tests
compare split and whole verification on generated programs.
"""

from __future__ import annotations

import bisect
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any

__all__ = ["Chunk", "split_program", "combine", "count_lines", "DEFAULT_SPLIT_LINES"]

#: A chunk size worth trying (``--split-lines``): splitting is off unless asked for.
DEFAULT_SPLIT_LINES = 1_000_000

_COMMENT = re.compile(r"\([^)\n]*\)|;[^\n]*")
_G_OK = r"0*(?:(?:0|1|2|3|17|18|19|20|21|40|43|49|5[4-9]|80|90|94)(?![0-9.])|(?:90|91)\.1(?![0-9.]))"
_BAD_G = re.compile(rf"G(?!{_G_OK})")
_BAD_M = re.compile(r"M(?!0*(?:2|3|4|5|7|8|9|30)(?![0-9.]))")
_END = re.compile(r"M0*(?:2|30)(?![0-9.])")
_LETTER_WITHOUT_NUMBER = re.compile(r"[A-Za-z](?![0-9.+\-])|[+\-](?![0-9.])")
_G90 = re.compile(r"G0*90(?![0-9.])")
#: A character outside words, comments and the parser's white space (space, tab, CR, LF).
_NOT_WORD_CHAR = re.compile(r"[^A-Za-z0-9.+\- \t\r\n]")
_F = re.compile(r"F[+\-]?[0-9.]+")
_H = re.compile(r"H[+\-]?[0-9.]+")  # every H, once each letter is known to be followed by its number
_G43 = re.compile(r"G0*43(?![0-9.])")
_MOTION = re.compile(r"G0*(0|1|2|3|80)(?![0-9.])")
#: Modal groups other than motion, by code: the preamble writes the last code of each.
_GROUP_OF = {"G17": "plane", "G18": "plane", "G19": "plane", "G20": "units", "G21": "units", "G90": "distance",
             "G90.1": "arc distance", "G91.1": "arc distance", "G94": "feed mode", "G40": "cutter compensation",
             **{f"G5{k}": "work offset" for k in range(4, 10)}, "G43": "tool length", "G49": "tool length"}
_GROUP_ORDER = ("plane", "units", "distance", "arc distance", "feed mode", "cutter compensation", "work offset",
                "tool length")
_MODAL = re.compile(r"G0*(17|18|19|20|21|40|43|49|5[4-9]|90\.1|91\.1|90|94)(?![0-9.])")
#: Codes whose change moves the machine position of an axis word written before it.
_STATE_GROUPS = frozenset(("units", "work offset", "tool length"))
_MAX_STATE_WORDS = 100_000


@dataclass(frozen=True, slots=True)
class Chunk:
    """A piece of a program: the text ``text[start:end]`` from line ``first_line`` on.

    The first chunk has no preamble and the machine's own start position
    (``position`` None); a later one is verified as ``preamble + "\\n" +
    text[start:end]`` with the machine's start position set to ``position``.
    """

    first_line: int
    start: int
    end: int
    preamble: str
    position: tuple[Fraction, ...] | None

    @property
    def line_offset(self) -> int:
        """Add to a line of the chunk's text to get the program's line (the preamble is line 1)."""
        return self.first_line - 2 if self.preamble or self.position is not None else 0

    def text(self, program: str) -> str:
        body = program[self.start:self.end]
        return body if self.position is None and not self.preamble else self.preamble + "\n" + body


def count_lines(text: str) -> int:
    """Lines of a text as spans number them.

    >>> count_lines("G1 X1\\nG1 X2"), count_lines("G1\\n")
    (2, 1)
    """
    return text.count("\n") + (1 if text and not text.endswith("\n") else 0)


def _cleaned(text: str) -> str | None:
    """The text with comments blanked (same length, same line breaks), upper-cased; None if it is not ASCII.

    Upper-casing keeps every position only for ASCII (``"ß".upper()`` is
    ``"SS"``), and the parser knows no other letters.
    """
    if "(" in text or ";" in text:
        text = _COMMENT.sub(lambda m: " " * len(m.group()), text)
    return text.upper() if text.isascii() else None


def _last_before(rx: re.Pattern[str], text: str, end: int, near: int = 1 << 16,
                 far: int = 1 << 20) -> re.Match[str] | None:
    """The last match of ``rx`` that ends at or before ``end`` (windows backwards, then one forward scan)."""
    window = near
    lo = end
    while window <= far:
        lo = max(0, end - window)
        last = None
        for m in rx.finditer(text, lo, end):
            last = m
        if last is not None:
            return last
        if lo == 0:
            return None
        window *= 4
    last = None
    for m in rx.finditer(text, 0, lo):
        last = m
    return last


def _line_start(text: str, pos: int) -> int:
    return text.rfind("\n", 0, pos) + 1


def _line_end(text: str, pos: int) -> int:
    nl = text.find("\n", pos)
    return len(text) if nl < 0 else nl


def splittable(text: str, machine: Any, settings: Mapping[str, Any]) -> str | None:
    """Why ``text`` cannot be split (a short reason), or None when it can.

    >>> from nczones import load_machine
    >>> from dataclasses import replace
    >>> m = load_machine("specs/machines/mill.toml")
    >>> splittable("G90 G1 X1 F100\\nG1 X2\\n", m, {})
    'a machine that starts blending corners (path_mode G64) is verified whole'
    >>> m = replace(m, path_mode="G61")
    >>> splittable("G90 G1 X1 F100\\nG1 X2\\n", m, {})
    >>> splittable("G91 G1 X1 F100\\n", m, {})
    'uses G91 (only the codes listed in nczones.fleet.split split)'
    """
    early = _early_refusal(machine, settings)
    if early is not None:
        return early
    bad = re.search(_NOT_WORD_CHAR, _COMMENT.sub("", text) if "(" in text or ";" in text else text)
    if bad:
        return f"uses {bad.group()!r}"
    cleaned = _cleaned(text)
    assert cleaned is not None  # ASCII outside comments, checked above
    return _why_not(text, cleaned, machine)


def _why_not(text: str, cleaned: str, machine: Any) -> str | None:
    """:func:`splittable`'s checks on the text (``cleaned``: comments blanked, upper case)."""
    axes = "".join(machine.axis_names)
    bad = re.search(rf"[^GMFSNHIJKRP{axes}0-9.+\- \t\r\n]", cleaned)
    if bad:
        return f"uses {text[bad.start()]!r}"
    if _LETTER_WITHOUT_NUMBER.search(cleaned):
        return "a letter or sign not directly followed by its number"
    for rx in (_BAD_G, _BAD_M):
        m = rx.search(cleaned)
        if m:
            word = re.match(r"[GM][0-9.]*", cleaned[m.start():m.start() + 12])
            return f"uses {word.group() if word else m.group()} (only the codes listed in nczones.fleet.split split)"
    end = _END.search(cleaned)
    if end and re.search(r"[A-Za-z]", cleaned[end.end():]):
        return "words after the program end"
    first_axis = re.search(rf"[{axes}]", cleaned)
    if first_axis:
        g90 = _G90.search(cleaned)
        if g90 is None or g90.start() > _line_end(cleaned, first_axis.start()):
            return "G90 is not written on or before the first axis word"
    for h in _H.finditer(cleaned):
        line = cleaned[_line_start(cleaned, h.start()):_line_end(cleaned, h.start())]
        if not _G43.search(line):
            return "an H word without G43"
    return None


def split_program(text: str, machine: Any, settings: Mapping[str, Any],
                  chunk_lines: int = DEFAULT_SPLIT_LINES) -> tuple[Chunk, ...] | None:
    """Chunks of about ``chunk_lines`` lines of a program that may be split, else None.

    See the module docstring for the conditions.  Boundaries are placed at
    line starts, spaced by size; one that does not meet the conditions is
    moved forward to the next line that sets the motion mode, or dropped.

    >>> from nczones import load_machine
    >>> from dataclasses import replace
    >>> m = replace(load_machine("specs/machines/mill.toml"), path_mode="G61")  # G64: never split
    >>> prog = "G21 G90 G54\\nG0 X10 Y10 Z50\\nG1 X20 F300\\nX30\\nG1 Y20\\nX40\\n"
    >>> chunks = split_program(prog, m, {}, chunk_lines=2)
    >>> [(c.first_line, c.preamble, c.position) for c in chunks][1:]   # doctest: +NORMALIZE_WHITESPACE
    [(3, 'G21 G90 G54 G0', (Fraction(160, 1), Fraction(110, 1), Fraction(150, 1))),
     (4, 'G21 G90 G54 G1 F300', (Fraction(170, 1), Fraction(110, 1), Fraction(150, 1)))]
    """
    if chunk_lines < 1:
        raise ValueError("chunk_lines must be at least 1")
    lines = count_lines(text)
    pieces = -(-lines // chunk_lines)
    if pieces < 2 or _early_refusal(machine, settings) is not None:
        return None
    cleaned = _cleaned(text)
    if cleaned is None or re.search(_NOT_WORD_CHAR, cleaned) or _why_not(text, cleaned, machine) is not None:
        return None
    # the modal codes other than motion are few (set-up lines): found once, looked up per boundary
    modal = [(m.start(), _code(m.group())) for m in _MODAL.finditer(cleaned)]
    if len(modal) > _MAX_STATE_WORDS:
        return None
    h_words = [m.start() for m in _H.finditer(cleaned)]
    state_positions = sorted([p for p, c in modal if _GROUP_OF[c] in _STATE_GROUPS] + h_words)
    axis_rx = {a: re.compile(rf"{a}[+\-]?[0-9.]+") for a in machine.axis_names}
    starts: list[tuple[int, str, tuple[Fraction, ...]]] = []
    previous = 0
    for k in range(1, pieces):
        b = cleaned.find("\n", len(cleaned) * k // pieces)
        if b < 0:
            break
        b += 1
        while b < len(cleaned) and b > previous:
            found = _boundary_state(cleaned, b, axis_rx, state_positions, modal, machine)
            if isinstance(found, tuple):
                starts.append((b, *found))
                previous = b
                break
            if found is None:
                break
            b = found  # the next line that sets the motion mode
    if not starts:
        return None
    chunks = []
    begin, pre, pos = 0, "", None
    for b, preamble, position in starts:
        first = text.count("\n", 0, begin) + 1
        chunks.append(Chunk(first, begin, b, pre, pos))
        begin, pre, pos = b, preamble, position
    chunks.append(Chunk(text.count("\n", 0, begin) + 1, begin, len(text), pre, pos))
    return tuple(chunks)


def _early_refusal(machine: Any, settings: Mapping[str, Any]) -> str | None:
    if settings.get("params") or settings.get("recovery") or settings.get("library"):
        return "parameter ranges, recovery and subprogram libraries are verified whole"
    dialect = settings.get("dialect") or getattr(machine, "dialect", "linuxcnc")
    if dialect != "linuxcnc":
        return f"the {dialect} dialect is verified whole"
    if getattr(machine, "path_mode", "G64") not in ("G61", "G61.1"):
        # the corner between two chunks may be rounded (specs/path-modes.md); neither chunk sees it
        return "a machine that starts blending corners (path_mode G64) is verified whole"
    return None


def _boundary_state(cleaned: str, b: int, axis_rx: Mapping[str, re.Pattern[str]], state_positions: list[int],
                    modal: list[tuple[int, str]], machine: Any) -> tuple[str, tuple[Fraction, ...]] | int | None:
    """(preamble, machine position) at line start ``b``; or a later line start to try; or None (give up)."""
    motion = _last_before(_MOTION, cleaned, b)
    if motion is not None and motion.group(1) in ("2", "3"):
        # an arc mode cannot be written without its words: the boundary goes to a line that sets the mode
        nxt = _MOTION.search(cleaned, b)
        if nxt is None:
            return None
        if _line_start(cleaned, nxt.start()) > b:
            return _line_start(cleaned, nxt.start())
        motion = None  # the line at the boundary sets the motion mode itself
    end = _END.search(cleaned, 0, b)
    if end is not None:
        return None
    words: list[str] = []
    for rx in axis_rx.values():
        last = _last_before(rx, cleaned, b)
        if last is None:
            continue
        after = _line_end(cleaned, last.start())
        k = bisect.bisect_right(state_positions, after)
        if k < len(state_positions) and state_positions[k] < b:
            return None  # a units, offset or tool-length code between this axis word and the boundary
        words.append(last.group())
    last_of: dict[str, tuple[int, str]] = {}
    for at, code in reversed(modal[:bisect.bisect_left(modal, (b, ""))]):
        last_of.setdefault(_GROUP_OF[code], (at, code))
        if len(last_of) == len(_GROUP_ORDER):
            break
    codes: list[str] = []
    for group in _GROUP_ORDER:
        if group not in last_of:
            continue
        at, code = last_of[group]
        codes.append(code)
        if code == "G43":
            h = _H.search(cleaned, _line_start(cleaned, at), _line_end(cleaned, at))
            if h is None:
                return None
            codes.append(h.group())
    if motion is not None:
        codes.append(_code(motion.group()))
    feed = _last_before(_F, cleaned, b)
    if feed is not None:
        codes.append(feed.group())
    preamble = " ".join(codes)
    return preamble, _machine_position(machine, preamble, words)


def _code(word: str) -> str:
    """A G code as the preamble writes it: ``g017`` -> ``G17``, ``G00`` -> ``G0``, ``G90.1`` kept.

    >>> _code("g017"), _code("G00"), _code("G90.1")
    ('G17', 'G0', 'G90.1')
    """
    whole, _, frac = word[1:].partition(".")
    return "G" + (whole.lstrip("0") or "0") + ("." + frac if frac else "")


def _machine_position(machine: Any, preamble: str, words: Sequence[str]) -> tuple[Fraction, ...]:
    """Where the machine stands after ``preamble`` and a rapid to the axis words (the interpreter's answer)."""
    from ..gcode import segments_text

    if not words:
        return tuple(machine.start)
    segs = segments_text((preamble + "\n" if preamble else "") + "G0 " + " ".join(words) + "\n", machine,
                         file="<split>")
    return tuple(segs[-1].end) if segs else tuple(machine.start)


def combine(parts: Sequence[tuple[Any, Chunk]], max_violations: int, program_sha256: str) -> Any | None:
    """One result from the chunks' results, in chunk order (see the module docstring), or None to verify whole.

    ``parts`` holds each chunk's :class:`~nczones.prover.Result` (lines
    already those of the program, see :func:`shift_result`) and the chunk.
    """
    from ..prover import Verdict

    results = [r for r, _ in parts]
    if any(r.reasons for r in results):
        return None
    violations = []
    engines = []
    notes: dict[str, None] = {}
    stats: dict[str, int] = {}
    timings: dict[str, float] = {}
    blocks_before = 0
    for result, chunk in parts:
        pre = 1 if chunk.preamble else 0
        shift = blocks_before - pre
        for v in result.violations:
            if v.block < pre:
                return None
            violations.append(replace(v, block=v.block + shift))
        for block, engine in result.engines:
            if block < pre:
                return None
            engines.append((block + shift, engine))
        notes.update(dict.fromkeys(result.notes))
        for k, n in result.stats:
            stats[k] = stats.get(k, 0) + n
        for k, t in result.timings:
            timings[k] = timings.get(k, 0.0) + t
        blocks_before += int(result.extra.get("counts", {}).get("blocks", 0)) - pre
    truncated = any(r.truncated for r in results) or len(violations) > max_violations
    violations = violations[:max_violations]
    verdict = min((r.verdict for r in results), default=Verdict.SAFE)
    if violations:
        verdict = Verdict.UNSAFE
    first = results[0]
    counts: dict[str, int] = {}
    for r in results:
        for k, n in r.extra.get("counts", {}).items():
            counts[k] = counts.get(k, 0) + int(n)
    counts["blocks"] = blocks_before
    return replace(first, verdict=verdict, violations=tuple(violations), reasons=(), engines=tuple(engines),
                   notes=tuple(notes), stats=tuple(stats.items()), timings=tuple(timings.items()),
                   truncated=truncated, program_digest=program_sha256,
                   extra={**first.extra, "counts": counts, "chunks": len(parts)})


def shift_result(result: Any, chunk: Chunk) -> Any:
    """A chunk's result with the program's line numbers (the chunk's preamble is its line 1)."""
    offset = chunk.line_offset
    if offset == 0:
        return result

    def fix(span: Any) -> Any:
        return None if span is None else replace(span, line=span.line + offset)

    return replace(result, violations=tuple(replace(v, span=fix(v.span), break_line=None if v.break_line is None
                                                    else v.break_line + offset) for v in result.violations),
                   reasons=tuple(replace(r, span=fix(r.span)) for r in result.reasons))
