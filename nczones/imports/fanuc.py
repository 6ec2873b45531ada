"""Fanuc: a parameter listing in the text form the control punches and reads.

The format (FANUC Series 30i/31i/32i-MODEL A Parameter Manual B-63950EN,
section 3.3 "Inputting and outputting parameters through the reader/puncher
interface"; Series 15i B-63330EN section 3; the 16i/18i/21i form is the same
without ``Q1``): a record between ``%`` lines, one block per parameter,
``N<number> [Q1] P<value>`` or, per axis, ``N<number> [Q1] A1 P<value> A2
P<value> ...``.  A bit parameter's value is 8 binary digits, bit 7 first (as
the parameter screen shows ``#7 .. #0``; "N00010P00000001: bit 0 is 1").  A
real value has a decimal point and may carry the keyword ``M`` (metric) or
``I`` (inch) instead of ``P``; an integer length is a count of the axis'
least command increment.  Comments in parentheses and ``;`` block ends are
allowed.

The parameters read, their meaning and what they become are listed in
``specs/machine-import.md``.  The stored stroke checks become box zones:
stroke check 1 (1320/1321, and 1326/1327 switched by the EXLM signal) allows
the inside, stroke check 2 (1322/1323) forbids the inside or, with 1300#0
OUT, the outside, stroke check 3 (1324/1325) forbids the inside.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

from ..errors import SourceSpan
from ..exact import format_decimal
from ..machine import AXIS_NAMES, ROTARY_AXES
from .model import (
    INCH,
    Collector,
    HomingDraft,
    ImportedMachine,
    Sourced,
    ZoneDraft,
    frozen,
    in_range,
    line_span,
)

__all__ = ["read_fanuc", "Parameter", "parse_listing", "BIT_PARAMETERS"]

#: Bit parameters the import reads (their values must be 8 binary digits).
BIT_PARAMETERS = frozenset({0, 1001, 1004, 1006, 1013, 1300, 1310, 1401, 3401, 3402, 5002, 5006, 5101, 5400, 6001, 6004})

#: Least command increment per increment system (1004 / 1013 bits), metric (mm, deg) and inch.
_INCREMENTS = {
    "IS-A": (Fraction(1, 100), Fraction(1, 1000)),
    "IS-B": (Fraction(1, 1000), Fraction(1, 10000)),
    "IS-C": (Fraction(1, 10000), Fraction(1, 100000)),
    "IS-D": (Fraction(1, 100000), Fraction(1, 1000000)),
    "IS-E": (Fraction(1, 1000000), Fraction(1, 10000000)),
}

_WORD = re.compile(r"([A-Za-z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")


@dataclass
class Parameter:
    """One parameter block: its values (per axis when axis-type) with their source."""

    number: int
    span: SourceSpan
    value: tuple[str, str, SourceSpan] | None = None  # (keyword P/M/I, text, span)
    axes: dict[int, tuple[str, str, SourceSpan]] = field(default_factory=dict)


def parse_listing(path: str, text: str, c: Collector) -> dict[int, Parameter]:
    """The parameter blocks of a listing by number; malformed blocks are ``IM102``.

    >>> c = Collector()
    >>> ps = parse_listing("p.prm", "%\\nN01320Q1A1P500.000A2P400.000;\\nN3401P00000001\\n%\\n", c)
    >>> ps[1320].axes[2][1], ps[3401].value[1], c.errors
    ('400.000', '00000001', [])
    """
    out: dict[int, Parameter] = {}
    for i, line in enumerate(text.lstrip("\ufeff").split("\n"), 1):
        body = line.rstrip("\r")
        pos = 0
        for block in re.split(r";", re.sub(r"\([^)]*\)", lambda m: " " * len(m.group(0)), body)):
            start = pos
            pos += len(block) + 1
            stripped = block.strip()
            if not stripped or stripped == "%":
                continue
            col = start + len(block) - len(block.lstrip())
            span = line_span(path, i, body, col, start + len(block.rstrip()))
            p = _block(path, i, body, start, block, span, c)
            if p is None:
                continue
            if p.number in out:
                c.error("IM108", f"parameter {p.number} is set twice (first at line {out[p.number].span.line})", span)
                continue
            out[p.number] = p
    return out


def _block(path: str, i: int, body: str, start: int, block: str, span: SourceSpan,
           c: Collector) -> Parameter | None:
    words: list[tuple[str, str, SourceSpan]] = []
    at = 0
    text = block
    while at < len(text):
        if text[at].isspace():
            at += 1
            continue
        m = _WORD.match(text, at)
        if not m:
            c.error("IM102", f"malformed parameter block {block.strip()!r}: expected N<number>, then P<value> or "
                    "A<axis> P<value> pairs (the punch format of Fanuc parameters)",
                    line_span(path, i, body, start + at))
            return None
        words.append((m.group(1).upper(), m.group(2), line_span(path, i, body, start + m.start(2), start + m.end(2))))
        at = m.end()
    if not words or words[0][0] != "N" or "." in words[0][1] or words[0][1].startswith(("-", "+")):
        c.error("IM102", f"malformed parameter block {block.strip()!r}: a block starts with N and the parameter "
                "number", span)
        return None
    p = Parameter(int(words[0][1]), span)
    axis: int | None = None
    for letter, value, wspan in words[1:]:
        if letter == "Q" and value == "1":
            continue
        if letter in "AS" and re.fullmatch(r"\d+", value) and int(value) >= 1:
            if axis is not None:
                c.error("IM102", f"parameter {p.number}: {letter}{value} follows an axis with no value", wspan)
                return None
            axis = int(value) if letter == "A" else -int(value)
            continue
        if letter in "PMI":
            if axis is None:
                if p.value is not None or p.axes:
                    c.error("IM102", f"parameter {p.number}: a second value without an axis", wspan)
                    return None
                p.value = (letter, value, wspan)
            else:
                if axis in p.axes:
                    c.error("IM108", f"parameter {p.number}: axis {axis} is given twice", wspan)
                    return None
                if p.value is not None:
                    c.error("IM102", f"parameter {p.number}: a value for the path and per axis at once", wspan)
                    return None
                p.axes[axis] = (letter, value, wspan)
                axis = None
            continue
        if letter == "L":
            c.note("IM201", f"parameter {p.number}: L{value} (a path of a multi-path control) is not read; only the "
                   "listing's first path is taken", wspan)
            return None
        c.error("IM102", f"parameter {p.number}: unexpected {letter}{value}; a parameter block holds N, Q1, A or S "
                "(axis or spindle) and P, M or I (the value)", wspan)
        return None
    if axis is not None:
        c.error("IM102", f"parameter {p.number}: the last axis has no value", span)
        return None
    if p.value is None and not p.axes:
        c.error("IM102", f"parameter {p.number}: no value", span)
        return None
    return p


class _Listing:
    def __init__(self, path: str, params: dict[int, Parameter], c: Collector):
        self.path = path
        self.params = params
        self.c = c

    def bits(self, number: int, axis: int | None = None) -> tuple[str, SourceSpan] | None:
        p = self.params.get(number)
        if p is None:
            return None
        entry = p.value if axis is None else p.axes.get(axis)
        if entry is None:
            return None
        _, text, span = entry
        if not re.fullmatch(r"[01]{8}", text):
            self.c.error("IM102", f"parameter {number}{'' if axis is None else f' axis {axis}'}: {text!r} is not a bit "
                         "parameter's 8 binary digits (#7 first)", span)
            return None
        return text, span

    def bit(self, number: int, bit: int, axis: int | None = None) -> tuple[bool, SourceSpan] | None:
        b = self.bits(number, axis)
        if b is None:
            return None
        return b[0][7 - bit] == "1", b[1]

    def describe(self, number: int, axis: int | None, keyword: str, text: str) -> str:
        return f"{number}{'' if axis is None else f' A{axis}'} {keyword}{text}"


def read_fanuc(path: str, text: str, c: Collector) -> ImportedMachine:
    """Read a Fanuc parameter listing (see the module docstring)."""
    params = parse_listing(path, text, c)
    c.raise_if_failed()
    if not params:
        c.error("IM107", "no parameter blocks (N<number> P<value>) in the listing", file=path)
        c.raise_if_failed()
    ls = _Listing(path, params, c)
    n_axes = max((a for p in params.values() for a in p.axes if a > 0), default=0)
    if n_axes == 0:
        c.error("IM107", "no axis-type parameter (A1 P... ) in the listing: the axes cannot be told", file=path)
        c.raise_if_failed()

    # axis names (1020: the program axis name as an ASCII code)
    names: dict[int, str] = {}
    codes = params.get(1020)
    for k in range(1, n_axes + 1):
        if codes is not None and k in codes.axes:
            _, t, span = codes.axes[k]
            letter = chr(int(t)) if re.fullmatch(r"\d{2,3}", t) and 65 <= int(t) <= 90 else ""
            if letter not in AXIS_NAMES:
                c.error("IM105", f"parameter 1020 A{k} P{t}: not the code of an axis name nczones knows "
                        f"({', '.join(f'{a}={ord(a)}' for a in AXIS_NAMES)})", span)
                continue
            if letter in names.values():
                c.error("IM108", f"parameter 1020 A{k} P{t}: axis {letter} is named twice", span)
                continue
            names[k] = letter
        else:
            names[k] = "XYZABCUVW"[k - 1] if k <= 9 else "?"
    if codes is None:
        c.note("IM203", f"no parameter 1020 (the axes' names): axes 1 to {n_axes} are taken as "
               f"{' '.join(names.values())}", file=path)
    c.raise_if_failed()
    axes = tuple(names[k] for k in sorted(names))

    # units: inch machine (1001#0 INM), increment system (1013 per axis, else 1004), CMR (1820)
    inm = ls.bit(1001, 0)
    inch = bool(inm and inm[0])
    inc_how: dict[int, str] = {}
    increment: dict[int, Fraction] = {}
    inc_system: dict[int, str] = {}
    sys_1004 = None
    b1004 = ls.bits(1004)
    if b1004 is not None:
        isa, isc = b1004[0][7] == "1", b1004[0][6] == "1"
        sys_1004 = "IS-A" if isa and not isc else "IS-C" if isc and not isa else "IS-B" if not (isa or isc) else None
        if sys_1004 is None:
            c.error("IM105", "parameter 1004: #0 ISA and #1 ISC are both 1, which is no increment system", b1004[1])
    for k in range(1, n_axes + 1):
        system = None
        b = ls.bits(1013, k)
        if b is not None:
            set_bits = [s for s, bit in (("IS-A", 0), ("IS-C", 1), ("IS-D", 2), ("IS-E", 3)) if b[0][7 - bit] == "1"]
            if len(set_bits) > 1:
                c.error("IM105", f"parameter 1013 A{k}: more than one of #0 ISA, #1 ISC, #2 ISD, #3 ISE is 1", b[1])
                continue
            system = set_bits[0] if set_bits else "IS-B"
            inc_how[k] = f"1013 A{k} P{b[0]}: {system}"
        elif sys_1004 is not None and b1004 is not None:
            system = sys_1004
            inc_how[k] = f"1004 P{b1004[0]}: {system}"
        else:
            system = "IS-B"
            inc_how[k] = "no 1004 or 1013: IS-B assumed"
        inc_system[k] = system
        metric_inc, inch_inc = _INCREMENTS[system]
        rotary = names[k] in ROTARY_AXES
        increment[k] = inch_inc * INCH if inch and not rotary else metric_inc
    if b1004 is None and 1013 not in params:
        c.note("IM203", "no parameter 1004 or 1013 (the increment system): IS-B assumed, so an integer length "
               "is a count of 0.001 mm (0.0001 in on an inch machine, 0.001 deg)", file=path)
    c.raise_if_failed()

    # rotary axes (1006#0 ROT) must agree with the machine file's A B C
    for k in range(1, n_axes + 1):
        rot = ls.bit(1006, 0, k)
        if rot is not None and rot[0] != (names[k] in ROTARY_AXES):
            c.error("IM106", f"parameter 1006 A{k} #0 ROT = {int(rot[0])} makes axis {names[k]} "
                    f"{'rotary' if rot[0] else 'linear'}; the machine file treats A, B, C as rotary and the others "
                    "as linear", rot[1])
    # diameter axes (1006#3 DIA = 1): program words are diameters, and so are the axis' positions ("Display
    # of axis position: displayed as diameter value", B-62754EN 9.4).  The stored stroke checks 1320-1327
    # are read as diameters on such an axis (no manual text found: the sound side, specs/machine-import.md); the
    # reference positions 1240-1243, machine coordinates of the same axis, are read the same way (an
    # inference the IM203 note states).  The machine file counts machine coordinates as radii
    # (diameter_axes): those values are halved.
    diameter: dict[int, SourceSpan] = {}
    for k in range(1, n_axes + 1):
        dia = ls.bit(1006, 3, k)
        if dia is not None and dia[0]:
            if names[k] in ROTARY_AXES:
                c.note("IM201", f"parameter 1006 A{k} #3 DIA = 1 on the rotary axis {names[k]}: ignored (only linear "
                       "axes take diameters)", dia[1])
                continue
            diameter[k] = dia[1]
            c.note("IM203", f"parameter 1006 A{k} #3 DIA = 1: axis {names[k]} is programmed in diameter "
                   f"(diameter_axes); its stored stroke limits (1320-1327) are diameters, and its reference "
                   "positions (1240-1243) are taken as diameters too; both halved to the machine file's radius",
                   dia[1])
    c.raise_if_failed()

    def length(number: int, k: int, *, speed: bool = False) -> Sourced | None:
        p = params.get(number)
        if p is None or k not in p.axes:
            return None
        keyword, t, span = p.axes[k]
        q = c.real(t, f"parameter {number} A{k}", span)
        if q is None:
            return None
        rotary = names[k] in ROTARY_AXES
        what = ls.describe(number, k, keyword, t)
        per = "/min" if speed else ""
        if keyword == "I" or (keyword == "P" and "." in t and inch and not rotary):
            scale, how = INCH, f"{what} in{per}, x 25.4"
        elif keyword == "M" or "." in t:
            scale, how = Fraction(1), f"{what} {'deg' if rotary else 'mm'}{per}"
        elif speed:
            if inch and not rotary:
                scale, how = INCH / 10, f"{what} x 0.1 in/min, x 25.4"
            else:
                scale, how = Fraction(1), f"{what} {'deg' if rotary else 'mm'}/min"
        else:
            scale, how = increment[k], f"{what} x {format_decimal(increment[k])} {'deg' if rotary else 'mm'} ({inc_how[k]})"
        return Sourced(q * scale, how, span)

    def coordinate(number: int, k: int) -> Sourced | None:
        """A machine coordinate parameter (1240-1243, 1320-1327): on a diameter axis a diameter, halved."""
        v = length(number, k)
        if v is None or k not in diameter:
            return v
        return Sourced(v.value / 2, f"{v.how}, a diameter (1006 A{k} #3 DIA = 1): / 2", v.span)

    # rapid rates (1420)
    rapid: dict[str, Sourced] = {}
    for k in range(1, n_axes + 1):
        v = length(1420, k, speed=True)
        if v is None:
            c.error("IM107", f"axis {names[k]}: no rapid traverse rate (parameter 1420 A{k})",
                    params[1420].span if 1420 in params else None, file=path)
        elif v.value <= 0:
            c.error("IM108", f"{v.how}: the rapid traverse rate must be greater than 0", v.span)
        elif in_range(c, v.value, v.how, v.span):
            rapid[names[k]] = v

    # reference positions (1240: where reference return ends; 1241-1243 the 2nd to 4th)
    reference: dict[str, Sourced] = {}
    for k in range(1, n_axes + 1):
        v = coordinate(1240, k)
        if v is None:
            v = Sourced(Fraction(0), f"no parameter 1240 A{k}: the control's default 0")
        if in_range(c, v.value, v.how, v.span):
            reference[names[k]] = v
    if 1240 not in params:
        c.note("IM203", "no parameter 1240 (the reference position): taken as machine zero on every axis",
               file=path)
    zones = _stroke_checks(ls, names, n_axes, coordinate, c)

    # modal state at power-on and decimal-point input
    modal: list[tuple[str, str]] = []
    g91 = ls.bit(3402, 3)
    if g91 is not None and g91[0]:
        modal.append(("G91", f"3402 #3 G91 = 1 ({g91[1].file}:{g91[1].line})"))
    ini = ls.bit(0, 2)
    if ini is not None and ini[0]:
        modal.append(("G20", f"0000 #2 INI = 1: input in inches ({ini[1].file}:{ini[1].line})"))
    ipr = ls.bit(1004, 7)
    if ipr is not None and ipr[0]:
        c.note("IM201", "parameter 1004 #7 IPR = 1: values without a decimal point are ten times the least input "
               "increment; the machine file has no place for it", ipr[1])
    settings = _fanuc_settings(ls, names, n_axes, inc_system, bool(ini and ini[0]), c, lathe=bool(diameter))
    macros = _macros(ls, c)
    references: list[tuple[str, dict[str, Sourced]]] = []
    for number, n in ((1241, 2), (1242, 3), (1243, 4)):
        if number in params:
            vs = {names[k]: v for k in range(1, n_axes + 1) if (v := coordinate(number, k)) is not None}
            for a in axes:
                vs.setdefault(a, Sourced(Fraction(0), f"no {number} for axis {a}: the control's default 0"))
            references.append((f"machine.reference_{n}", vs))

    lrp = ls.bit(1401, 1)
    if lrp is None:
        rapid_mode = ("dogleg", "no 1401: #1 LRP = 0 assumed, each axis moves at its own rapid rate")
        c.note("IM203", "no parameter 1401: #1 LRP = 0 (the control's default) assumed, so G0 moves each axis at "
               "its own rapid rate (rapid_mode = \"dogleg\")", file=path)
    elif lrp[0]:
        rapid_mode = ("linear", f"1401 #1 LRP = 1: G0 moves on a straight line ({lrp[1].file}:{lrp[1].line})")
    else:
        rapid_mode = ("dogleg", f"1401 #1 LRP = 0: G0 moves each axis at its own rapid rate "
                      f"({lrp[1].file}:{lrp[1].line})")

    homing = _homing(ls, names, n_axes, length, increment, reference, c)
    c.raise_if_failed()
    return ImportedMachine(
        kind="fanuc", source=path, name=Path(path).stem, name_how="the file name",
        axes=axes, axes_how=("1020: the program axis names" if codes is not None
                             else "no 1020: axes 1, 2, 3... taken as X, Y, Z..."),
        rapid=frozen(rapid), reference=frozen(reference),
        rapid_mode=rapid_mode,
        modal=tuple(modal), zones=zones, homing=homing, notes=tuple(c.notes),
        extra=(("dialect", '"fanuc"', "a Fanuc control: programs are read in the Fanuc dialect"),) + ((
            ("type", '"lathe"', "a diameter axis (1006 #3 DIA = 1): a lathe control"),
            ("diameter_axes", "[" + ", ".join(f'"{names[k]}"' for k in sorted(diameter)) + "]",
             "1006 #3 DIA = 1: " + ", ".join(f"A{k} ({sp.file}:{sp.line})" for k, sp in sorted(diameter.items()))),
        ) if diameter else ()),
        axis_tables=tuple((name, frozen(vs)) for name, vs in references),
        tables=tuple((name, rows) for name, rows in (("fanuc", settings), ("macros", macros)) if rows),
    )


Row = tuple[str, str, str]


def _fanuc_settings(ls: _Listing, names: dict[int, str], n_axes: int, systems: dict[int, str], inch_input: bool,
                    c: Collector, lathe: bool = False) -> tuple[Row, ...]:
    """The ``[fanuc]`` table: the parameters nczones' Fanuc dialect models (``specs/fanuc.md``)."""
    rows: list[Row] = []

    def where(span: SourceSpan) -> str:
        return f"({span.file}:{span.line})"

    dpi = ls.bit(3401, 0)
    if dpi is not None:
        rows.append(("decimal_point_input", '"calculator"' if dpi[0] else '"increment"',
                     f"3401 #0 DPI = {int(dpi[0])}: " + ("X100 means 100 mm" if dpi[0] else
                                                        "X100 counts least input increments") + f" {where(dpi[1])}"))
    used = sorted(set(systems.values()))
    if len(used) == 1 and used[0] in ("IS-A", "IS-B", "IS-C"):
        if ls.params.get(1004) is not None or ls.params.get(1013) is not None:
            rows.append(("increment_system", f'"{used[0]}"', "1004 / 1013: the least input increment"))
    elif used:
        c.note("IM201", f"increment systems {', '.join(f'{names[k]} {systems[k]}' for k in sorted(systems))}: the "
               "machine file's increment_system is one of IS-A, IS-B, IS-C for every axis, so it is not set",
               _first_span(ls.params, 1013, 1004))
    path_system = systems.get(1, "IS-B")
    step = _INCREMENTS[path_system][1 if inch_input else 0] * (INCH if inch_input else 1)
    for number, key in ((5114, "g73_retract"), (5115, "g83_clearance")):
        p = ls.params.get(number)
        if p is None or p.value is None:
            continue
        keyword, text, span = p.value
        q = c.real(text, f"parameter {number}", span)
        if q is None:
            continue
        if keyword == "I" or ("." in text and inch_input and keyword == "P"):
            value, how = q * INCH, f"{number} {keyword}{text} in, x 25.4"
        elif "." in text or keyword == "M":
            value, how = q, f"{number} {keyword}{text} mm"
        else:
            value, how = q * step, f"{number} P{text} x {format_decimal(step)} mm (least input increment)"
        if value < 0:
            c.error("IM108", f"parameter {number} P{text}: a {key.replace('_', ' ')} is not negative", span)
            continue
        rows.append((key, f'"{format_decimal(value)}"', f"{how} {where(span)}"))
    rd1, rd2 = ls.bit(5101, 4), ls.bit(5101, 5)
    if rd1 is not None and rd2 is not None:
        shift = {(False, False): "+X", (True, False): "-X", (False, True): "+Y", (True, True): "-Y"}[(rd1[0], rd2[0])]
        rows.append(("boring_shift", f'"{shift}"', f"5101 #4 RD1 = {int(rd1[0])}, #5 RD2 = {int(rd2[0])} "
                     f"{where(rd1[1])}"))
    rin, scr = ls.bit(5400, 0), ls.bit(5400, 7)
    if scr is not None:
        rows.append(("scaling_unit", '"0.001"' if scr[0] else '"0.00001"', f"5400 #7 SCR = {int(scr[0])} "
                     f"{where(scr[1])}"))
    if rin is not None:
        rows.append(("rotation_incremental", "true" if rin[0] else "false", f"5400 #0 RIN = {int(rin[0])} "
                     f"{where(rin[1])}"))
    nat = ls.bit(6004, 0)
    if nat is not None:
        rows.append(("atan_signed", "true" if nat[0] else "false", f"6004 #0 NAT = {int(nat[0])} {where(nat[1])}"))
    tos = ls.bit(5006, 6)
    if tos is not None:
        rows.append(("tool_length_motion", '"shift"' if tos[0] else '"move"', f"5006 #6 TOS = {int(tos[0])} "
                     f"{where(tos[1])}"))
    if lathe:
        # a lathe's tool offsets: 5002#4 LGT (geometry by coordinate shift or by tool movement) and #5 LGC
        # (offset number 0 cancels the geometry offset too)
        lgt, lgc = ls.bit(5002, 4), ls.bit(5002, 5)
        if lgt is not None:
            rows.append(("tool_offset_motion", '"move"' if lgt[0] else '"shift"',
                         f"5002 #4 LGT = {int(lgt[0])} {where(lgt[1])}"))
        if lgc is not None:
            # written commented out: no manual text for 5002#5 was found (specs/machine-import.md), so which of
            # its values keeps the geometry offset is not certain; unset, T..00 under a geometry offset is unknown
            rows.append(("# tool_offset_cancel", '"all"' if lgc[0] else '"wear"',
                         f"5002 #5 LGC = {int(lgc[0])} {where(lgc[1])}: LGC = 1 is read as 'T0100 cancels the "
                         "geometry offset too', not confirmed by a manual text here: check it, then remove the '#'"))
    return tuple(rows)


def _macros(ls: _Listing, c: Collector) -> tuple[Row, ...]:
    """``[macros]``: the G and M codes that call programs (6050-6059, 6071-6079, 6080-6089) and 6001#5 TCS."""
    rows: list[Row] = []
    for first, count, program, call, letter in ((6050, 10, 9010, "macro", "G"), (6071, 9, 9001, "subprogram", "M"),
                                                (6080, 10, 9020, "macro", "M")):
        for i in range(count):
            p = ls.params.get(first + i)
            if p is None or p.value is None:
                continue
            _, text, span = p.value
            if not re.fullmatch(r"[-+]?\d+", text):
                c.error("IM103", f"parameter {first + i}: {text!r} is not a {letter} code number", span)
                continue
            code = int(text)
            if code == 0:
                continue
            if code < 0 or code > 9999 or (letter == "G" and code in (65, 66, 67)):
                c.note("IM201", f"parameter {first + i} P{text}: a {'modal (G66-type) ' if code < 0 else ''}call by "
                       f"{letter}{abs(code)} is not taken", span)
                continue
            value = str(program + i) if call == "macro" else f'{{ program = {program + i}, call = "subprogram" }}'
            rows.append((f"{letter}{code}", value, f"{first + i} P{text}: {letter}{code} calls O{program + i} "
                         f"({span.file}:{span.line})"))
    tcs = ls.bit(6001, 5)
    if tcs is not None and tcs[0]:
        rows.append(("T", "9000", f"6001 #5 TCS = 1: a T code calls O9000 ({tcs[1].file}:{tcs[1].line})"))
    return tuple(rows)


def _first_span(params: dict[int, Parameter], *numbers: int) -> SourceSpan | None:
    """The span of the first of ``numbers`` the listing has."""
    return next((params[n].span for n in numbers if n in params), None)


Length = Callable[..., Sourced | None]


def _stroke_checks(ls: _Listing, names: dict[int, str], n_axes: int, length: Length,
                   c: Collector) -> tuple[ZoneDraft, ...]:
    zones: list[ZoneDraft] = []
    params = ls.params

    def box(plus: int, minus: int, axes_on: set[int]) -> tuple[dict, dict, list[int]]:
        lo, hi, infinite = {}, {}, []
        for k in sorted(axes_on):
            p, m = length(plus, k), length(minus, k)
            if p is None or m is None:
                continue
            if plus in (1320, 1326) and p.value < m.value:
                infinite.append(k)
                continue
            lo[names[k]], hi[names[k]] = m, p
        return lo, hi, infinite

    every = set(range(1, n_axes + 1))
    # stroke check 1: the inside is allowed
    if 1320 in params or 1321 in params:
        lo, hi, infinite = box(1320, 1321, every)
        for k in infinite:
            c.note("IM203", f"parameters 1320 < 1321 on axis {names[k]}: the control takes the stroke as infinite "
                   "(no stored stroke check 1 on this axis)", params[1320].axes[k][2])
        if lo:
            zones.append(ZoneDraft("stroke check 1", False, frozen(lo), frozen(hi),
                                   ("stored stroke check 1: 1321 (minus) to 1320 (plus), the inside is allowed",)))
    else:
        c.note("IM201", "no parameters 1320/1321 (stored stroke check 1): no soft limits taken", file=ls.path)
    # stroke check 1 with the EXLM signal (1326/1327, when 1300#2 LMS = 1)
    if 1326 in params or 1327 in params:
        lms = ls.bit(1300, 2)
        if lms is not None and not lms[0]:
            c.note("IM201", "parameters 1326/1327 are not used: 1300 #2 LMS = 0 (the EXLM signal cannot switch "
                   "stroke check 1)", _first_span(params, 1326, 1327))
        else:
            lo, hi, _ = box(1326, 1327, every)
            if lo:
                why = "1300 #2 LMS = 1" if lms is not None else "1300 not in the listing"
                zones.append(ZoneDraft("stroke check 1 (EXLM)", False, frozen(lo), frozen(hi), (
                    f"stored stroke check 1 switched by the EXLM signal ({why}): 1327 (minus) to 1326 (plus). "
                    "The control uses either box; the machine file keeps both, so a program is proved inside each",)))
    # stroke check 2 (inside or outside forbidden, 1300#0 OUT) and 3 (inside forbidden)
    out = ls.bit(1300, 0)
    for number, plus, minus, bit, label in ((2, 1322, 1323, 0, "stroke check 2"), (3, 1324, 1325, 1, "stroke check 3")):
        if plus not in params and minus not in params:
            continue
        on = {k for k in every if (b := ls.bit(1310, bit, k)) is None or b[0]}
        off = sorted(every - on)
        if not on:
            c.note("IM201", f"parameters {plus}/{minus} ({label}): 1310 #{bit} OT{number} is 0 on every axis, so the "
                   "control checks it nowhere; no zone taken", _first_span(params, plus, minus))
            continue
        lo, hi, _ = box(plus, minus, on)
        if not lo or all(v.value == 0 for v in [*lo.values(), *hi.values()]):
            c.note("IM201", f"parameters {plus}/{minus} ({label}) are 0 on every checked axis: the area is not set, "
                   "no zone taken", _first_span(params, plus, minus))
            continue
        outside = number == 2 and out is not None and out[0]
        comment = [f"stored {label}: {minus} (minus) to {plus} (plus), the "
                   f"{'outside' if outside else 'inside'} is forbidden"
                   + (" (1300 #0 OUT = 1)" if outside else " (1300 #0 OUT = 0)" if number == 2 and out else "")]
        if off:
            comment.append(f"not checked on {' '.join(names[k] for k in off)} (1310 #{bit} OT{number} = 0)")
        g23 = ls.bit(3402, 7)
        if number == 2 and g23 is not None and g23[0]:
            c.note("IM201", "3402 #7 G23 = 1: stroke check 2 is off at power-on until a program commands G22; its "
                   "area is written as a zone all the same (the machine file has no G22/G23)", g23[1])
        zones.append(ZoneDraft(label, not outside, frozen(lo), frozen(hi), tuple(comment)))
    return tuple(zones)


def _homing(ls: _Listing, names: dict[int, str], n_axes: int, length: Length, increment: dict[int, Fraction],
            reference: dict[str, Sourced], c: Collector) -> tuple[HomingDraft, ...]:
    params = ls.params
    if 1850 not in params and 1821 not in params:
        return ()
    drafts = []
    for k in range(1, n_axes + 1):
        a = names[k]
        fields: list[tuple[str, Sourced | str, str]] = []
        zmi = ls.bit(1006, 5, k)
        if zmi is not None:
            fields.append(("direction", '"negative"' if zmi[0] else '"positive"',
                           f"1006 A{k} #5 ZMI = {int(zmi[0])} ({zmi[1].file}:{zmi[1].line})"))
        detection, det_how = increment[k], "the least command increment"
        cmr = params.get(1820)
        if cmr is not None and k in cmr.axes:
            _, t, span = cmr.axes[k]
            v = int(t) if t.isdigit() else 0
            ratio = Fraction(v, 2) if 2 <= v <= 96 else Fraction(1, v - 100) if 102 <= v <= 127 else None
            if ratio is None:
                c.error("IM104", f"parameter 1820 A{k} P{t}: not a command multiplier code (2..96 for CMR 1..48, "
                        "102..127 for 1/2..1/27)", span)
                continue
            detection, det_how = increment[k] / ratio, f"the least command increment / CMR {format_decimal(ratio)}"
        for number, key in ((1821, "grid_pitch"), (1850, "grid_shift")):
            p = params.get(number)
            if p is not None and k in p.axes:
                _, t, span = p.axes[k]
                q = c.real(t, f"parameter {number} A{k}", span)
                if q is not None:
                    fields.append((key, Sourced(q * detection, f"{number} A{k} P{t} detection units x "
                                                f"{format_decimal(detection)} mm ({det_how})", span), ""))
        fl = length(1425, k, speed=True)
        if fl is not None:
            fields.append(("latch_speed", fl, ""))
        fields.append(("machine_zero", reference[a], ""))
        missing = ["dog_position", "dog_length", "detector_phase"] + (["grid_pitch"] if 1821 not in params else [])
        drafts.append(HomingDraft(a, tuple(fields), tuple(missing)))
    if drafts:
        c.note("IM201", f"reference return ({' '.join(d.axis for d in drafts)}): the grid shift and grid are written "
               f"commented out in [homing.<axis>]; the section also needs {', '.join(drafts[0].missing)}, which "
               "are not parameters (the dog is mounted on the machine)", _first_span(params, 1850, 1821))
    return tuple(drafts)
