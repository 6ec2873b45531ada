"""A Fanuc tool offset listing as the control punches it out (``verify --tool-table``).

The Fanuc 0i/30i write their tool offset memory as a program of ``G10`` blocks between ``%`` marks
("Inputting and outputting offset data"; the block format is "Programmable data input (G10)"):

* milling, tool compensation memory C: ``G10 L10 P<n> R<v>`` tool length geometry of H<n>, ``L11`` its
  wear, ``L12`` cutter radius geometry of D<n>, ``L13`` its wear;
* milling, memory A: ``G10 L11 P<n> R<v>``, one value per number used by H and D alike (radius for D);
* turning: ``G10 P<n> X<x> Z<z> R<r> Q<q>``: P 1..9999 the wear of offset n, P 10000+n its geometry
  (R the tool nose radius, Q the imaginary tool nose direction 0-9).

Anything else is refused (``VF111``, file:line:column): ``G91`` or ``U``/``W``/``C`` (increments on a value
the listing does not give), ``P0`` (a work shift), a number without a decimal point other than 0 (its value
depends on parameter 3401#0 DPI and the increment system), other words.
"""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

from ..errors import Diagnostic, InputError, SourceSpan
from ..machine import ToolOffset
from .model import line_span, read_source

_WORD = re.compile(r"([A-Za-z])\s*([+-]?[0-9.]*)")
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)")
_INCH = Fraction(254, 10)


def is_fanuc_listing(text: str) -> bool:
    """True when the first block that is not ``%``, an O number, a comment or a block of ``G20``/``G21``/``G90``
    alone (which a listing may state before its ``G10`` blocks) is a ``G10`` block."""
    for raw in text.split("\n"):
        line = re.sub(r"\([^)]*\)?", "", raw).strip().upper()
        if not line or line == "%" or re.fullmatch(r"O\d+", line):
            continue
        if re.fullmatch(r"(N\d+\s*)?(G\s*(20|21|90)\s*)+", line):
            continue
        return re.match(r"(N\d+\s*)?G\s*10(?!\d)", line) is not None
    return False


class FanucListing:
    """The tools of a listing, in mm: ``lengths``/``diameters`` (geometry) and the memory C wear
    (``length_wear``, ``radius_wear``: a radius) by register (mill), ``offsets`` (lathe)."""

    def __init__(self) -> None:
        self.lengths: dict[int, Fraction] = {}
        self.diameters: dict[int, Fraction] = {}
        self.length_wear: dict[int, Fraction] = {}
        self.radius_wear: dict[int, Fraction] = {}
        self.offsets: dict[int, ToolOffset] = {}
        self.memory = ""
        self.units: str | None = None
        #: the line of each offset: ``(L, n)`` on a mill, ``(geometry?, n)`` on a lathe
        self.lines: dict[tuple, int] = {}

    @property
    def levels(self) -> frozenset[int]:
        """The L numbers of a mill listing's blocks (10..13): which memory it holds (import-machine says)."""
        return frozenset() if self.memory == "lathe" else frozenset(key[0] for key in self.lines)


def read_fanuc_listing(path: str | Path, units: str | None, lathe: bool, axes: tuple[str, ...] = ("X", "Z"),
                       diameter_axes: tuple[str, ...] = (), x_offsets: str | None = None) -> FanucListing:
    """Read a listing (module doc).  ``units`` (mm/inch) is required unless the listing states G20/G21; a
    lathe listing's X on a diameter axis needs ``x_offsets`` ("diameter" or "radius": parameter 5004#1 ORC)."""
    text = read_source(path, "tool offset listing", "VF111")
    p = str(path)
    errors: list[Diagnostic] = []
    blocks: list[tuple[int, str, dict[str, tuple[str, SourceSpan]]]] = []
    stated: str | None = None
    for i, raw in enumerate(text.split("\n"), 1):
        line = raw.rstrip("\r")
        body = re.sub(r"\([^)]*\)", lambda m: " " * len(m.group(0)), line)
        if "(" in body:
            errors.append(Diagnostic("VF111", "a comment that is not closed on its line",
                                     line_span(p, i, line, body.index("("))))
            continue
        stripped = body.strip()
        if not stripped or stripped == "%" or re.fullmatch(r"[Oo]\d+", stripped):
            continue
        words: dict[str, tuple[str, SourceSpan]] = {}
        pos = 0
        bad = None
        while pos < len(body):
            if body[pos].isspace():
                pos += 1
                continue
            m = _WORD.match(body, pos)
            if m is None or not m.group(2):
                end = m.end() if m is not None else pos + 1
                bad = (pos, end, f"{body[pos:end].strip()!r} is not an address word (a letter and a number)")
                break
            letter, number = m.group(1).upper(), m.group(2)
            span = line_span(p, i, line, m.start(), m.end())
            if not _NUMBER.fullmatch(number):
                bad = (m.start(), m.end(), f"{m.group(0)!r}: not a number")
                break
            if letter == "G":
                if number in ("20", "21"):
                    u = "inch" if number == "20" else "mm"
                    if stated is not None and stated != u:
                        bad = (m.start(), m.end(), f"G{number}: the listing stated {stated} before")
                        break
                    stated = u
                elif number == "91":
                    bad = (m.start(), m.end(), "G91: an increment on a value the listing does not give")
                    break
                elif number not in ("10", "90"):
                    bad = (m.start(), m.end(), f"G{number}: a listing holds G10 (G90, G20/G21) only")
                    break
                words.setdefault("G" + number, (number, span))
                pos = m.end()
                continue
            allowed = "NLPR" if not lathe else "NPXYZRQ"
            if letter not in allowed:
                hint = " (increments are refused)" if letter in "UVWC" else ""
                bad = (m.start(), m.end(), f"{m.group(0)!r}: a {'lathe' if lathe else 'mill'} listing takes "
                       f"{' '.join(allowed)} after G10{hint}")
                break
            if letter in words:
                bad = (m.start(), m.end(), f"{letter} given twice in the block")
                break
            if letter in "NLPQ" and not re.fullmatch(r"\d+", number.lstrip("+")):
                bad = (m.start(), m.end(), f"{m.group(0)!r}: {letter} takes a whole number")
                break
            if letter in "XYZR" and "." not in number and Fraction(number) != 0:
                bad = (m.start(), m.end(), f"{m.group(0)!r}: a value without a decimal point depends on parameter "
                       "3401#0 DPI and the increment system; write it with a point (such as R12.5)")
                break
            words[letter] = (number, span)
            pos = m.end()
        if bad is not None:
            errors.append(Diagnostic("VF111", bad[2], line_span(p, i, line, bad[0], bad[1])))
            continue
        if "G10" not in words:
            if set(words) - {"N", "G20", "G21", "G90"}:
                errors.append(Diagnostic("VF111", "a block without G10: a tool offset listing holds G10 blocks",
                                         line_span(p, i, line)))
            continue
        if "P" not in words:
            errors.append(Diagnostic("VF111", "G10 without P (the offset number)", line_span(p, i, line)))
            continue
        blocks.append((i, line, words))
    if errors:
        raise InputError(errors)
    if units is None and stated is None:
        raise InputError(Diagnostic("VF111", "give --tool-table-units mm or inch: a Fanuc offset listing is in "
                                    "the control's input unit, which this one does not state (no G20/G21)",
                                    file=p))
    if units is not None and stated is not None and units != stated:
        raise InputError(Diagnostic("VF111", f"--tool-table-units {units}, but the listing states {stated} "
                                    "(G20/G21)", file=p))
    out = FanucListing()
    out.units = units or stated
    factor = _INCH if out.units == "inch" else Fraction(1)

    def value(words: dict[str, tuple[str, SourceSpan]], letter: str) -> Fraction:
        return Fraction(words[letter][0]) * factor

    seen = out.lines

    def once(key: tuple, i: int, line: str, words: dict[str, tuple[str, SourceSpan]]) -> bool:
        if key in seen:
            errors.append(Diagnostic("VF111", f"the same offset is set twice (first at line {seen[key]})",
                                     words["P"][1]))
            return False
        seen[key] = i
        return True

    if not lathe:
        tables: dict[int, dict[int, Fraction]] = {10: {}, 11: {}, 12: {}, 13: {}}
        for i, line, words in blocks:
            if "L" not in words or int(words["L"][0]) not in tables:
                errors.append(Diagnostic("VF111", "a mill listing sets L10/L11/L12/L13 (memory C) or L11 (memory "
                                         "A); this block has " + (f"L{words['L'][0]}" if "L" in words else "no L"),
                                         words["L"][1] if "L" in words else line_span(p, i, line)))
                continue
            if "R" not in words:
                errors.append(Diagnostic("VF111", "G10 L.. P.. without R (the offset value)", line_span(p, i, line)))
                continue
            n, L = int(words["P"][0]), int(words["L"][0])
            if not 0 <= n <= 9999:
                errors.append(Diagnostic("VF111", f"P{n}: offset numbers are 0 to 9999", words["P"][1]))
                continue
            if once((L, n), i, line, words):
                tables[L][n] = value(words, "R")
        if errors:
            raise InputError(errors)
        if tables[10] or tables[12] or tables[13]:
            out.memory = "C"
            # a register the listing gives (geometry or wear) exists, its other half 0: H = geometry + wear
            for n in set(tables[10]) | set(tables[11]):
                out.lengths[n] = tables[10].get(n, Fraction(0))
                out.length_wear[n] = tables[11].get(n, Fraction(0))
            for n in set(tables[12]) | set(tables[13]):
                out.diameters[n] = 2 * tables[12].get(n, Fraction(0))
                out.radius_wear[n] = tables[13].get(n, Fraction(0))
        else:
            out.memory = "A"
            for n, v in tables[11].items():
                out.lengths[n] = v
                out.diameters[n] = 2 * v
        return out
    geometry: dict[int, dict[str, Fraction]] = {}
    wear: dict[int, dict[str, Fraction]] = {}
    tips: dict[int, int] = {}
    for i, line, words in blocks:
        if "L" in words:
            errors.append(Diagnostic("VF111", "a lathe listing is G10 P.. X.. Z.. R.. Q.. (no L)", words["L"][1]))
            continue
        p_no = int(words["P"][0])
        n = p_no - 10000 if p_no > 10000 else p_no
        if not 1 <= n <= 9999 or p_no == 10000:
            errors.append(Diagnostic("VF111", f"P{p_no}: 1-9999 is a wear offset, 10001-19999 a geometry offset "
                                     "(P0 is the work shift, not read)", words["P"][1]))
            continue
        if not once((p_no > 10000, n), i, line, words):
            continue
        got: dict[str, Fraction] = {}
        for a in "XYZR":
            if a in words:
                v = value(words, a)
                if a != "R" and a not in axes:
                    errors.append(Diagnostic("VF111", f"{a}: the machine has no {a} axis", words[a][1]))
                    continue
                if a == "R" and p_no > 10000 and v < 0:
                    errors.append(Diagnostic("VF111", "a negative tool nose radius", words[a][1]))
                    continue
                if a in diameter_axes:
                    if x_offsets is None:
                        errors.append(Diagnostic("VF111", f"{a} is a diameter axis: give --tool-table-x-offset "
                                                 "diameter or radius (parameter 5004#1 ORC: 0 = the offset is a "
                                                 "diameter, 1 = a radius)", words[a][1]))
                        continue
                    if x_offsets == "diameter":
                        v = v / 2
                got[a] = v
        (geometry if p_no > 10000 else wear)[n] = got
        if "Q" in words:
            q = int(words["Q"][0])
            if not 0 <= q <= 9:
                errors.append(Diagnostic("VF111", f"Q{q}: the imaginary tool nose direction is 0 to 9",
                                         words["Q"][1]))
                continue
            if p_no > 10000 or n not in tips:
                tips[n] = q
    if errors:
        raise InputError(errors)
    out.memory = "lathe"
    for n in sorted(set(geometry) | set(wear)):
        g, w = geometry.get(n, {}), wear.get(n, {})
        out.offsets[n] = ToolOffset(n, tuple((a, v) for a, v in g.items() if a != "R"),
                                    tuple((a, v) for a, v in w.items() if a != "R"),
                                    g.get("R", Fraction(0)), w.get("R", Fraction(0)), tips.get(n, 0))
    return out
