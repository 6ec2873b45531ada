"""The machine file (TOML): axes, rates, offsets, tool lengths and zones.

:func:`load_machine` reads one file exactly (TOML floats become
``decimal.Decimal``, then ``Fraction``), checks everything, and either returns
a complete :class:`Machine` or raises :class:`~nczones.errors.MachineFileError`
with every problem found, each naming the file (with line and column where the
text can be located), the zone and field, the value as written and what is
allowed.  Nothing is verified against a half-read machine.

The format and every error code are described in ``specs/machine-file.md``;
the JSON Schema is ``specs/machine.schema.json``.
"""

from __future__ import annotations

import decimal
import enum
import functools
import itertools
import math
import operator
import os
import re
from collections.abc import Callable, Mapping
from fractions import Fraction
from types import MappingProxyType

from .blockskip import format_block_delete, parse_block_delete
from .digest import sha256
from .errors import Diagnostic, MachineFileError, Severity, SourceSpan, close_matches
from .exact import DECIMAL_RE, MAX_ABS_LENGTH, format_decimal
from .machine_cache import cached_table
from .precompiled import dataclass, field, field_names, replace  # start-up: no dataclasses
from .zones import AllowedSet, BoxZone, PolygonZone, Region, SteppedZone, Zone, ZonePoint

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = [
    "Axis",
    "RapidMode",
    "Machine",
    "load_machine",
    "parse_machine",
    "AXIS_NAMES",
    "ROTARY_AXES",
    "WORK_OFFSETS",
    "DEFAULT_MODAL",
    "DEFAULT_RETRACT",
    "DIALECTS",
    "FanucSettings",
    "FANUC_OFFSETS",
    "ToolOffset",
    "MACHINE_TYPES",
    "GCODE_SYSTEMS",
]

AXIS_NAMES = ("X", "Y", "Z", "A", "B", "C", "U", "V", "W")
ROTARY_AXES = frozenset("ABC")
WORK_OFFSETS = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")
#: Work offsets only Fanuc controls have: the external workpiece zero offset (added to every system,
#: ``#5201``..) and the additional systems ``G54.1 P1``..``P48`` (written ``"G54.1P1"``).
FANUC_OFFSETS = ("EXT",) + tuple(f"G54.1P{n}" for n in range(1, 49))
#: Values of ``[machine] dialect``: how the program text is read (``specs/fanuc.md``).
DIALECTS = ("linuxcnc", "fanuc")
DEFAULT_MODAL = ("G90", "G21", "G17", "G54", "G94", "G40", "G49", "G80")
#: Values of ``[machine] type``: a mill (the default) or a lathe (``specs/turning.md``).
MACHINE_TYPES = ("mill", "lathe")
#: Fanuc lathe G code systems (``[fanuc] gcode_system``): A (U/W incremental, G50 coordinate setting, G90/G92/G94
#: cycles) or B (G90/G91 distance modes, G92 coordinate setting, G77/G78/G79 cycles).
GCODE_SYSTEMS = ("A", "B")
MODAL_CHOICES = {
    "distance": ("G90", "G91"),
    "units": ("G20", "G21"),
    "plane": ("G17", "G18", "G19"),
    "offset": WORK_OFFSETS,
    "feed": ("G93", "G94", "G95"),
    "cutter": ("G40",),
    "tool": ("G49",),
    "cycle": ("G80",),
    "retract": ("G98", "G99"),
}
#: The canned-cycle retract mode a dialect's control starts in when ``modal`` names neither G98 nor G99:
#: LinuxCNC's interpreter starts in G99 (``interp_setup.cc``: ``retract_mode(R_PLANE)``; its sample INI files'
#: ``RS274NGC_STARTUP_CODE`` do not set it), a Fanuc control in G98 at power-on.
DEFAULT_RETRACT = {"linuxcnc": "G99", "fanuc": "G98"}


class RapidMode(enum.Enum):
    """How a rapid (G0) moves: one straight line, or each axis at its own rate."""

    LINEAR = "linear"
    DOGLEG = "dogleg"


@dataclass(frozen=True, slots=True)
class Axis:
    """One machine axis; lengths in mm (degrees for rotary axes)."""

    name: str
    pulse: Fraction
    rapid_mm_min: Fraction
    max_feed_mm_min: Fraction
    rotary: bool = False
    #: ``[machine.acceleration]``: the axis' maximum acceleration, mm/s^2 (deg/s^2); None when the file does not
    #: give it (LinuxCNC's ``[AXIS_x] MAX_ACCELERATION``; the reference controller blends corners with it)
    accel_mm_s2: Fraction | None = None


@dataclass(frozen=True, slots=True)
class FanucSettings:
    """The Fanuc parameters nczones models (``[fanuc]`` of the machine file, ``specs/fanuc.md``).

    Lengths in mm.  ``None`` means the machine file does not give the value: a program that needs
    it is ``unknown`` with a reason naming the setting.
    """

    #: Parameter 3401#0 DPI: an address word without a decimal point is a count of least input
    #: increments (``"increment"``, DPI = 0) or units (``"calculator"``, DPI = 1).
    decimal_point_input: str = "calculator"
    #: Increment system: least input increment 0.01 (IS-A), 0.001 (IS-B), 0.0001 mm (IS-C).
    increment_system: str = "IS-B"
    #: Parameter 5114: G73 retract amount d.
    g73_retract: Fraction | None = None
    #: Parameter 5115: G83 clearance d.
    g83_clearance: Fraction | None = None
    #: Parameter 5101 bits RD1/RD2: direction of the G76/G87 shift (``"+X"``, ``"-X"``, ``"+Y"``, ``"-Y"``).
    boring_shift: str | None = None
    #: Parameter 5400#7 SCR: the unit of a G51 P scale factor without a decimal point.
    scaling_unit: Fraction = Fraction(1, 1000)
    #: Parameter 5400#0 RIN: a G68 R angle follows G90/G91 (True) or is always absolute (False).
    rotation_incremental: bool = False
    #: Parameter 6004#0 NAT: ATAN/ASIN results in 0..360 (False) or -180..180 (True).
    atan_signed: bool = False
    #: Parameter 5006#6 (TOS): a tool length offset change moves the tool axis (``"move"``) or shifts
    #: the coordinate system, taking effect at the next move of that axis (``"shift"``).
    tool_length_motion: str = "move"
    #: M codes of this machine with no effect on motion (beyond the standard ones).
    harmless_m: frozenset[int] = frozenset()
    #: 2nd to 4th reference positions (G30 P2..P4), machine coordinates, by number.
    references: Mapping[int, tuple[Fraction, ...]] = field(default_factory=lambda: MappingProxyType({}))
    #: Initial values of common variables (``[variables]``): number -> exact value.
    variables: Mapping[int, Fraction] = field(default_factory=lambda: MappingProxyType({}))
    #: Custom macro calls (``[macros]``): ``"G100"``/``"M50"``/``"T"`` -> (program number, "macro" or
    #: "subprogram"): the role of parameters 6050-6059, 6080-6089, 6071-6079 and 6001#5.
    macros: Mapping[str, tuple[int, str]] = field(default_factory=lambda: MappingProxyType({}))
    # ---- lathes (``[machine] type = "lathe"``, ``specs/turning.md``)
    #: Lathe G code system (3401#6 GSB, #7 GSC): ``"A"`` or ``"B"``.
    gcode_system: str = "A"
    #: Parameter 5132: G71/G72 depth of cut (radius, mm) when the program gives none.
    g71_depth: Fraction | None = None
    #: Parameter 5133: G71/G72 escape amount e (mm) when the program gives none.
    g71_retract: Fraction | None = None
    #: Parameter 5102#2 RF1: G71/G72 end with a cut along the shape offset by the allowance (True: RF1 = 0).
    roughing_final_pass: bool = True
    #: Parameters 5135, 5136: G73 relief in X (radius) and Z when the program gives none.
    g73_relief_x: Fraction | None = None
    g73_relief_z: Fraction | None = None
    #: Parameter 5137: G73 number of divisions when the program gives none.
    g73_divisions: int | None = None
    #: Parameter 5139: G74/G75 return amount e when the program gives none.
    g74_retract: Fraction | None = None
    #: Parameter 5130: thread chamfer (pull-out) amount of G92/G76, in leads; None: not given.
    thread_chamfer: Fraction | None = None
    #: Parameter 5131: thread chamfer angle in degrees (45 or 0 and 90 are exact; other angles unknown).
    thread_chamfer_angle: Fraction = Fraction(45)
    #: Parameters 5142, 5143, 5140, 5141: G76 finishing repeats m, tool angle a, minimum depth, finishing
    #: allowance d, when the program gives none.
    g76_finish_passes: int | None = None
    g76_tool_angle: Fraction | None = None
    g76_min_depth: Fraction | None = None
    g76_finish_allowance: Fraction | None = None
    #: Parameter 5002#4 LGT: a lathe tool offset shifts the coordinate system (``"shift"``: LGT = 0, the next
    #: move carries it) or moves the tool in the T block (``"move"``).
    tool_offset_motion: str = "shift"
    #: Parameter 5002#5 LGC (with LGT = 0): offset number 0 (``T0100``) cancels the wear offset only, the
    #: geometry offset stays (``"wear"``) or cancels both (``"all"``); None: not given (no manual text for the
    #: parameter was found: ``T..00`` under a geometry offset is then unknown, specs/turning.md).
    tool_offset_cancel: str | None = None
    #: The path (channel) of a multi-path control whose slides this machine file describes: a program with
    #: ``$n`` path headers is read as the program of path ``$path`` (``specs/turning.md``); None: not given.
    path: int | None = None

    @property
    def increment_mm(self) -> Fraction:
        """The least input increment in mm (and degrees)."""
        return {"IS-A": Fraction(1, 100), "IS-B": Fraction(1, 1000), "IS-C": Fraction(1, 10000)}[
            self.increment_system]


@dataclass(frozen=True, slots=True)
class ToolOffset:
    """A lathe tool offset (Fanuc ``T0101``: tool 1 with offset 1; ``[tool_offsets]`` of the machine file).

    ``geometry`` and ``wear`` map axes to lengths in **machine units** (radius on a diameter axis);
    the offset moves the machine so that the tool tip reaches the programmed point:
    machine = program + work offset + geometry + wear.  ``nose_radius`` (geometry + wear) and
    ``tip`` (the imaginary tool nose direction 0-9) serve tool nose radius compensation.

    >>> F = Fraction
    >>> t = ToolOffset(1, (("X", F(-100)), ("Z", F(-300))), (("X", F(1, 100)),), F(4, 10), F(0), 3)
    >>> t.total("X"), t.total("Z"), t.total("Y")
    (Fraction(-9999, 100), Fraction(-300, 1), Fraction(0, 1))
    """

    number: int
    geometry: tuple[tuple[str, Fraction], ...] = ()
    wear: tuple[tuple[str, Fraction], ...] = ()
    nose_radius: Fraction = Fraction(0)
    wear_radius: Fraction = Fraction(0)
    tip: int = 0

    def total(self, axis: str) -> Fraction:
        """Geometry plus wear on ``axis`` (0 where neither is given)."""
        return dict(self.geometry).get(axis, Fraction(0)) + dict(self.wear).get(axis, Fraction(0))


@dataclass(frozen=True, slots=True)
class Machine:
    """A validated machine.  Coordinates are tuples in the order of ``axes``."""

    name: str
    units: str
    axes: tuple[Axis, ...]
    rapid_mode: RapidMode
    monitor_period_ms: Fraction
    reference: tuple[Fraction, ...]
    start: tuple[Fraction, ...]
    offsets: Mapping[str, tuple[Fraction, ...]]
    tool_lengths: Mapping[int, Fraction]
    allowed: AllowedSet
    modal: tuple[str, ...] = DEFAULT_MODAL
    tool_axis: str | None = "Z"
    source: str = "<machine>"
    warnings: tuple[Diagnostic, ...] = ()
    sections: Mapping[str, Any] = field(default_factory=lambda: MappingProxyType({}))
    #: "none" (G41/G42 make the result unknown) or "linuxcnc" (modelled as LinuxCNC's interpreter does).
    cutter_compensation: str = "none"
    #: Tool diameters by tool number (``[tool_diameters]`` T<n>), for G41/G42 D<n>.
    tool_diameters: Mapping[int, Fraction] = field(default_factory=lambda: MappingProxyType({}))
    #: SHA-256 of the machine file's bytes (set by :func:`load_machine`; empty for text given directly).
    sha256: str = ""
    #: How program text is read: ``"linuxcnc"`` or ``"fanuc"`` (``[machine] dialect``).
    dialect: str = "linuxcnc"
    #: The Fanuc parameters (``[fanuc]``, ``[variables]``, ``[macros]``); defaults when not given.
    fanuc: FanucSettings = field(default_factory=FanucSettings)
    #: Block-delete switch positions a proof covers: "both" (default), "off" (``/`` lines run), "on" (skipped),
    #: or per switch (Fanuc ``/1`` .. ``/9``) as :func:`nczones.blockskip.format_block_delete` writes it.
    block_delete: str = "both"
    #: How far an arc's end may be off its circle (``[machine] arc_tolerance``): mm, ``"linuxcnc"`` or ``"grbl"``
    #: (the control's own rule); None: ``--arc-tolerance`` or its default.
    arc_tolerance: Fraction | str | None = None
    #: The path control mode at start (``[machine] path_mode``): "G64" blends corners, "G61"/"G61.1" do not
    path_mode: str = "G64"
    #: ``[machine] path_tolerance``: LinuxCNC starts in ``G64 P<it>`` (its INI's start-up code); on a Fanuc
    #: control the bound on how far acc/dec corner rounding leaves the programmed path (``specs/path-modes.md``)
    path_tolerance: Fraction | None = None
    #: ``"mill"`` or ``"lathe"`` (``[machine] type``): a lathe reads its dialect's lathe G codes.
    machine_type: str = "mill"
    #: Axes whose program words are diameters (``[machine] diameter_axes``); machine coordinates, zones and
    #: every value of the machine file stay radii (the tool's distance from the spindle axis).
    diameter_axes: tuple[str, ...] = ()
    #: Lathe tool offsets by offset number (``[tool_offsets]``).
    tool_offsets: Mapping[int, ToolOffset] = field(default_factory=lambda: MappingProxyType({}))
    #: Fanuc tool compensation memory C wear by register, mm: tool length wear of H<n> and cutter radius
    #: wear of D<n> (``#10001``.., ``#12001``..).  Not in the machine file: set from a Fanuc offset listing
    #: (``verify --tool-table``); the lengths and diameters above are then the geometry.
    tool_length_wear: Mapping[int, Fraction] = field(default_factory=lambda: MappingProxyType({}))
    tool_radius_wear: Mapping[int, Fraction] = field(default_factory=lambda: MappingProxyType({}))
    #: The control's own length unit (LinuxCNC ``[TRAJ] LINEAR_UNITS``): ``"mm"`` or ``"inch"``.  LinuxCNC
    #: keeps its numbered state parameters (offsets, stored positions, tool table) in it.
    control_units: str = "mm"
    #: LinuxCNC ``[EMCIO] TOOL_CHANGE_QUILL_UP``: M6 first rapids the Z axis to machine Z 0.
    tool_change_quill_up: bool = False
    #: LinuxCNC ``[EMCIO] TOOL_CHANGE_AT_G30``: M6 rapids to the G30 position (every axis at once).
    tool_change_at_g30: bool = False
    #: LinuxCNC ``[EMCIO] TOOL_CHANGE_POSITION``: M6 moves the axes given here (machine coordinates, mm/deg)
    #: on a straight line at the change, after the moves above; axis name -> position.
    tool_change_position: Mapping[str, Fraction] = field(default_factory=lambda: MappingProxyType({}))
    #: Folders a LinuxCNC ``o<name> call`` reads ``name.ngc`` from when the program does not define the sub
    #: (``[linuxcnc] subroutine_path``, LinuxCNC's ``[RS274NGC] SUBROUTINE_PATH``), in order; resolved against
    #: the machine file's folder.
    subroutine_path: tuple[str, ...] = ()

    @property
    def is_lathe(self) -> bool:
        return self.machine_type == "lathe"

    @property
    def axis_names(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.axes)

    @property
    def zones(self) -> tuple[Zone, ...]:
        return self.allowed.zones

    def axis(self, name: str) -> Axis:
        for a in self.axes:
            if a.name == name:
                return a
        raise KeyError(name)

    def point(self, coords: tuple[Fraction, ...]) -> dict[str, Fraction]:
        """A coordinate tuple as a mapping axis name -> value."""
        return dict(zip(self.axis_names, coords))

    def offset(self, name: str) -> tuple[Fraction, ...]:
        """Machine coordinates of a work offset's zero (zeros if not given)."""
        return self.offsets.get(name, tuple(Fraction(0) for _ in self.axes))

    def tool_length(self, register: int) -> Fraction:
        return self.tool_lengths.get(register, Fraction(0))


# --------------------------------------------------------------------------- reading


class _Locator:
    """Best-effort line/column of a key in the TOML text (tomllib gives none)."""

    #: A table header line such as ``[machine.rapid]`` or ``[[zones]]`` (not an
    #: array element like ``["0", "0"],`` on a continuation line).
    _HEADER_RE = re.compile(r'^\s*\[\[?\s*[A-Za-z0-9_.\- "]+\s*\]\]?\s*(?:#.*)?$')

    def __init__(self, path: str, text: str):
        self.path = path
        self.lines = text.splitlines()
        self._sections: dict[str, list[int]] = {}
        self._brackets: list[int] | None = None
        self._elements: dict[tuple[str, int | None], list[tuple[int, int]]] = {}

    def _span(self, index: int, column: int, width: int) -> SourceSpan:
        return SourceSpan(self.path, index + 1, column + 1, column + 1 + width, self.lines[index])

    def _is_header(self, line: str) -> bool:
        """A table header, not an array element such as ``["0", "0"]`` (two quoted items)."""
        return bool(self._HEADER_RE.match(line)) and line.split("]")[0].count('"') <= 2

    def section(self, header: str, occurrence: int = 0) -> int | None:
        """0-based line index of the ``occurrence``-th ``[header]``/``[[header]]``.

        The header lines are found in one pass per header name (a file with
        thousands of ``[[zones]]`` is read once, not once per zone).
        """
        found = self._sections.get(header)
        if found is None:
            pattern = re.compile(r"^\s*\[+\s*" + re.escape(header) + r"\s*\]+")
            lines = self.lines
            found = self._sections[header] = [i for i in self._bracketed() if pattern.match(lines[i])]
        return found[occurrence] if occurrence < len(found) else None

    def _bracketed(self) -> list[int]:
        r"""The lines whose first character after white space is ``[`` (the only ones a header pattern of
        :meth:`section` can match: ``\s`` and ``str.lstrip`` strip the same characters), found once: a file of
        thousands of region lines is read once for all the headers asked, not once per header name."""
        got = self._brackets
        if got is None:
            got = self._brackets = [i for i, line in enumerate(self.lines) if line.lstrip()[:1] == "["]
        return got

    def header(self, index: int | None) -> SourceSpan | None:
        """A span over the header on line ``index`` (as returned by :meth:`section`)."""
        if index is None:
            return None
        line = self.lines[index]
        stripped = line.split("#")[0].rstrip()
        col = len(line) - len(line.lstrip())
        return self._span(index, col, max(1, len(stripped) - col))

    def key(
        self, key: str, start: int | None, occurrence: int = 0
    ) -> SourceSpan | None:
        """Find the ``occurrence``-th ``key =`` after line ``start``, before the next header.

        With ``start`` None, search the top of the file before the first header.
        """
        begin = 0 if start is None else start + 1
        key_re = re.compile(r"(?:^|[\s{,])(" + re.escape(key) + r"|\"" + re.escape(key) + r"\")\s*=")
        seen = 0
        for i in range(begin, len(self.lines)):
            line = self.lines[i]
            if self._is_header(line):
                break
            if line.lstrip().startswith("#"):
                continue
            m = key_re.search(line.split("#")[0] if "#" in line and '"' not in line else line)
            if m:
                if seen == occurrence:
                    return self._span(i, m.start(1), len(m.group(1)))
                seen += 1
        return None

    def key_in(self, outer: str, start: int | None, key: str, occurrence: int = 0) -> SourceSpan | None:
        """``key`` inside the inline table ``outer = { ... }`` (one line), or None."""
        anchor = self.key(outer, start)
        if anchor is None:
            return None
        line = self.lines[anchor.line - 1]
        key_re = re.compile(r"[\s{,](" + re.escape(key) + r"|\"" + re.escape(key) + r"\")\s*=")
        seen = 0
        for m in key_re.finditer(line, anchor.column - 1 + len(outer)):
            if seen == occurrence:
                return self._span(anchor.line - 1, m.start(1), len(m.group(1)))
            seen += 1
        return None

    def element(self, array_key: str, start: int | None, index: int, key: str) -> SourceSpan | None:
        """The ``key`` inside the ``index``-th ``{ ... }`` element of an array."""
        elements = self._elements.get((array_key, start))
        if elements is None:
            elements = self._elements[(array_key, start)] = self._scan_elements(array_key, start)
        if index >= len(elements):
            return None
        i, c = elements[index]
        line = self.lines[i]
        end = line.find("}", c)
        m = re.compile(r"\b" + re.escape(key) + r"\s*=").search(line, c, len(line) if end < 0 else end)
        if m:
            return self._span(i, m.start(), len(key))
        return self._span(i, c, 1)

    def _scan_elements(self, array_key: str, start: int | None) -> list[tuple[int, int]]:
        """Line and column of the opening brace of every ``{ ... }`` element of an array, in one pass."""
        anchor = self.key(array_key, start)
        if anchor is None:
            return []
        out = []
        depth = 0
        in_string = False
        for i in range(anchor.line - 1, len(self.lines)):
            line = self.lines[i]
            if i > anchor.line - 1 and self._is_header(line):
                break
            col0 = anchor.column - 1 if i == anchor.line - 1 else 0
            for c in range(col0, len(line)):
                ch = line[c]
                if ch == '"':
                    in_string = not in_string
                elif in_string:
                    continue
                elif ch == "{":
                    depth += 1
                    if depth == 1:
                        out.append((i, c))
                elif ch == "}":
                    depth -= 1
                elif ch == "#":
                    break
        return out


class _Reader:
    """Collects diagnostics while the machine is read."""

    def __init__(self, path: str, text: str):
        self.path = path
        self.loc = _Locator(path, text)
        self.diagnostics: list[Diagnostic] = []

    def report(
        self,
        code: str,
        message: str,
        span: SourceSpan | Callable[[], SourceSpan | None] | None = None,
        severity: Severity = Severity.ERROR,
    ) -> None:
        """Record a diagnostic; ``span`` may be a function that finds it (called only here)."""
        if callable(span):
            span = span()
        self.diagnostics.append(Diagnostic(code, message, span, severity, file=self.path))

    @property
    def failed(self) -> bool:
        return any(d.severity is Severity.ERROR for d in self.diagnostics)


#: ``json.dumps``'s escapes of a string (``json.encoder.ESCAPE_DCT``) as a ``str.translate`` table.
_JSON_ESCAPES = {**{i: f"\\u{i:04x}" for i in range(0x20)}, ord("\\"): "\\\\", ord('"'): '\\"', ord("\b"): "\\b",
                 ord("\f"): "\\f", ord("\n"): "\\n", ord("\r"): "\\r", ord("\t"): "\\t"}


def _quoted(text: str) -> str:
    """``json.dumps(text, ensure_ascii=False)`` without importing :mod:`json` (a zone's label, at every start;
    a text report needs no json, issue 36)."""
    return '"' + text.translate(_JSON_ESCAPES) + '"'


def as_written(value: Any) -> str:
    """The value as the user wrote it, in TOML syntax (approximately: TOML loses formatting).

    >>> as_written(["0", decimal.Decimal("1.50"), 3, True, {"X": "1"}])
    '["0", 1.50, 3, true, { X = "1" }]'
    """
    if isinstance(value, str):
        return _quoted(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, decimal.Decimal):
        if value.is_nan():
            return "nan"
        if value.is_infinite():
            return "-inf" if value < 0 else "inf"
        return str(value)
    if isinstance(value, list):
        return "[" + ", ".join(as_written(v) for v in value) + "]"
    if isinstance(value, Mapping):
        if not value:
            return "{}"
        return "{ " + ", ".join(f"{k} = {as_written(v)}" for k, v in value.items()) + " }"
    if value is None:
        return "nothing"
    return str(value)


#: Decimal exponents beyond these are refused before converting to a Fraction
#: (``1e999999999`` would otherwise build a gigantic integer).
_MAX_ADJUSTED_EXPONENT = 9
_MAX_PLACES = 30


def read_number(
    rd: _Reader,
    value: Any,
    what: str,
    span: SourceSpan | Callable[[], SourceSpan | None] | None,
    *,
    positive: bool = False,
    nonnegative: bool = False,
    limit: Fraction = MAX_ABS_LENGTH,
) -> Fraction | None:
    """Read an exact number (decimal text, TOML integer or TOML decimal)."""
    if type(value) is str:
        m = _PLAIN_DECIMAL.match(value)
        if m is not None:  # the common case, read without Decimal (within every limit on digits)
            frac = m.group(3) or ""
            num, den = int(m.group(2) + frac), 10 ** len(frac)
            negative = m.group(1) == "-" and num != 0
            q = Fraction(-num if negative else num, den)
            if (limit.denominator == 1 and num <= limit.numerator * den
                    and not (positive and (negative or num == 0)) and not (nonnegative and negative)):
                return q
            return _in_range(rd, q, value, what, span, positive, nonnegative, limit)
    if isinstance(value, bool) or not isinstance(value, (str, int, decimal.Decimal)):
        rd.report("ZN103", f"{what}: {as_written(value)} is not a number; write a decimal such as \"12.5\"", span)
        return None
    if isinstance(value, decimal.Decimal) and not value.is_finite():
        rd.report("ZN104", f"{what}: {as_written(value)} is not finite; write a finite decimal", span)
        return None
    if isinstance(value, str):
        text = value.strip()
        if text.lower().lstrip("+-") in ("inf", "infinity", "nan"):
            rd.report("ZN104", f"{what}: {as_written(value)} is not finite; write a finite decimal", span)
            return None
        if not DECIMAL_RE.match(text):
            rd.report("ZN103", f"{what}: {as_written(value)} is not a decimal; write digits with an optional sign and point, such as \"-12.5\"", span)
            return None
        value_d = decimal.Decimal(text)
    elif isinstance(value, int):
        value_d = None
    else:
        value_d = value
    if value_d is not None:
        sign, digits, exponent = value_d.as_tuple()
        trailing = len(digits) - len("".join(map(str, digits)).rstrip("0"))
        if any(digits) and value_d.adjusted() > _MAX_ADJUSTED_EXPONENT:
            rd.report("ZN105", f"{what}: {as_written(value)} is out of range; allowed magnitude is at most {format_decimal(limit)}", span)
            return None
        if any(digits) and isinstance(exponent, int) and exponent + trailing < -_MAX_PLACES:
            rd.report("ZN105", f"{what}: {as_written(value)} has more than {_MAX_PLACES} digits after the decimal point", span)
            return None
        q = Fraction(value_d)
    else:
        q = Fraction(value)
    return _in_range(rd, q, value, what, span, positive, nonnegative, limit)


#: Decimal text that needs no further checks of its digits: at most 10 before the point (so the
#: adjusted exponent is at most ``_MAX_ADJUSTED_EXPONENT``) and at most ``_MAX_PLACES`` after it.
_PLAIN_DECIMAL = re.compile(r"([+-]?)([0-9]{1,10})(?:\.([0-9]{0,30}))?\Z")


def _in_range(rd: _Reader, q: Fraction, value: Any, what: str,
              span: SourceSpan | Callable[[], SourceSpan | None] | None,
              positive: bool, nonnegative: bool, limit: Fraction) -> Fraction | None:
    if abs(q) > limit:
        rd.report("ZN105", f"{what}: {as_written(value)} is out of range; allowed magnitude is at most {format_decimal(limit)}", span)
        return None
    if positive and q <= 0:
        rd.report("ZN106", f"{what}: {as_written(value)} must be greater than 0", span)
        return None
    if nonnegative and q < 0:
        rd.report("ZN106", f"{what}: {as_written(value)} must not be negative", span)
        return None
    return q


def _check_keys(
    rd: _Reader,
    table: Mapping[str, Any],
    allowed: tuple[str, ...],
    where: str,
    start: int | None,
) -> None:
    for key in table:
        if key not in allowed:
            close = close_matches(key, allowed, n=1)
            hint = f"; did you mean {as_written(close[0])}?" if close else f"; allowed keys: {', '.join(allowed)}"
            span = rd.loc.key(key, start)
            if span is None and start is None:
                span = rd.loc.header(rd.loc.section(key))
            rd.report("ZN101", f"{where}: unknown key {as_written(key)}{hint}", span)


def _register_table(rd: _Reader, data: Mapping[str, Any], section: str, prefix: str, what: str, example: str) -> dict[int, Fraction]:
    """``[tool_lengths]`` / ``[tool_diameters]``: keys ``<prefix><number>`` (0..9999) with exact values."""
    out: dict[int, Fraction] = {}
    raw = data.get(section, {})
    line = rd.loc.section(section)
    if not isinstance(raw, Mapping):
        rd.report("ZN103", f"[{section}]: expected a table such as {example}, got {as_written(raw)}", None)
        return out
    for key, value in raw.items():
        m = re.fullmatch(prefix + r"(\d{1,4})", key)
        span = functools.partial(rd.loc.key, key, line)  # found when a diagnostic needs it (start-up, boot44)
        if not m:
            rd.report("ZN101", f"[{section}]: {as_written(key)} is not a {what}; write {prefix} followed by its "
                      f"number, such as {prefix}1", span)
            continue
        q = read_number(rd, value, f"[{section}] {key}", span)
        if q is not None:
            out[int(m.group(1))] = q
    return out


def _accelerations(rd: _Reader, mt: Mapping[str, Any], axes: tuple[str, ...], mline: int | None) -> dict[str, Fraction]:
    """``[machine.acceleration]``: every axis' maximum acceleration (mm/s^2, deg/s^2), or none at all."""
    if mt.get("acceleration") is None:
        return {}
    return _per_axis(rd, mt["acceleration"], axes, "[machine.acceleration]", rd.loc.section("machine.acceleration"),
                     required=True, inline=("acceleration", mline), positive=True)


def _per_axis(
    rd: _Reader,
    value: Any,
    axes: tuple[str, ...],
    what: str,
    header_line: int | None,
    *,
    required: bool,
    inline: tuple[str, int | None] | None = None,
    **number_opts: Any,
) -> dict[str, Fraction]:
    """A table ``{ X = "...", ... }`` keyed by known axis names.

    ``header_line`` is the line of its own ``[header]``; ``inline`` is
    ``(key, parent header line)`` when it may be written as ``key = { ... }``.
    """
    out: dict[str, Fraction] = {}

    def own_span() -> SourceSpan | None:
        found = rd.loc.header(header_line)
        if found is None and inline is not None:
            found = rd.loc.key(*inline)
        return found

    if not isinstance(value, Mapping):
        rd.report("ZN103", f"{what}: expected a table of axis values such as {{ X = \"0\" }}, got {as_written(value)}", own_span)
        return out
    # each span is found when a diagnostic needs it (a line search per key: start-up, boot44)
    for axis, raw in value.items():
        span: Callable[[], SourceSpan | None]
        if header_line is None and inline is not None:
            span = functools.partial(rd.loc.key_in, inline[0], inline[1], axis)
        else:
            span = functools.partial(rd.loc.key, axis, header_line)
        if axis not in axes:
            rd.report("ZN110", f"{what}: unknown axis {as_written(axis)}; the machine's axes are {', '.join(axes)}", span)
            continue
        q = read_number(rd, raw, f"{what}.{axis}", span, **number_opts)
        if q is not None:
            out[axis] = q
    if required:
        missing = [a for a in axes if a not in value]
        if missing:
            rd.report("ZN102", f"{what}: missing value for axis {', '.join(missing)} (every axis of the machine needs one)", own_span)
    return out


_TOP_KEYS = ("machine", "offsets", "tool_lengths", "tool_diameters", "zones", "fanuc", "variables", "macros",
             "tool_offsets", "linuxcnc")
_LINUXCNC_KEYS = ("subroutine_path",)
_MACHINE_KEYS = (
    "name", "units", "axes", "pulse", "rapid_mode", "monitor_period_ms", "rapid", "max_feed",
    "reference", "start", "tool_axis", "modal", "cutter_compensation", "dialect", "block_delete", "arc_tolerance",
    "reference_2", "reference_3", "reference_4",
    "reference", "start", "tool_axis", "modal", "cutter_compensation", "dialect",
    "reference_2", "reference_3", "reference_4", "type", "diameter_axes",
    "control_units", "tool_change_quill_up", "tool_change_at_g30", "tool_change_position",
    "path_mode", "path_tolerance", "acceleration",
)
#: Values of ``[machine] path_mode``: the path control mode the control starts in (``specs/path-modes.md``).
PATH_MODES = ("G64", "G61", "G61.1")
#: Values of ``[machine] control_units`` (LinuxCNC's ``[TRAJ] LINEAR_UNITS``).
CONTROL_UNITS = ("mm", "inch")
_FANUC_LATHE_KEYS = ("gcode_system", "g71_depth", "g71_retract", "roughing_final_pass", "g73_relief_x",
                     "g73_relief_z", "g73_divisions", "g74_retract", "thread_chamfer", "thread_chamfer_angle",
                     "g76_finish_passes", "g76_tool_angle", "g76_min_depth", "g76_finish_allowance",
                     "tool_offset_motion", "tool_offset_cancel")
_FANUC_KEYS = ("decimal_point_input", "increment_system", "g73_retract", "g83_clearance", "boring_shift",
               "scaling_unit", "rotation_incremental", "atan_signed", "tool_length_motion",
               "harmless_m", "path") + _FANUC_LATHE_KEYS
#: Values of ``[machine] cutter_compensation``.
CUTTER_COMPENSATION_MODES = ("none", "linuxcnc")
#: The named values of ``[machine] arc_tolerance`` (a control's own rule; otherwise a length in mm).
ARC_TOLERANCE_RULES = ("linuxcnc", "grbl")

#: Values of ``[machine] block_delete`` for every switch at once: which positions of the block-delete
#: switches a proof covers (per switch: ``"1=on,2=off"``, :mod:`nczones.blockskip`).
BLOCK_DELETE_MODES = ("both", "off", "on")
_ZONE_COMMON = ("name", "kind", "forbid", "point")
_ZONE_KEYS = {
    "stepped": _ZONE_COMMON + ("reference_axis", "limited_axis", "from", "regions"),
    "box": _ZONE_COMMON + ("min", "max"),
    "polygon": _ZONE_COMMON + ("plane", "vertices", "min", "max"),
}

#: Extra top-level sections other parts of nczones read (homing, tool change, tool solids), as an explicit
#: table: section name -> ``"module:function"`` of its parser(reader, raw table, axes), whose value goes to
#: ``Machine.sections``.  The module is imported only when a machine file has the section (no import of
#: ``nczones`` loads them for their side effects; docs/design.md §3).  The order is the order of their
#: diagnostics.
SECTION_PARSERS: dict[str, str] = {
    "homing": "nczones.plans.homing:parse_homing_section",
    "tool_change": "nczones.plans.recovery:parse_tool_change_section",
    "tools": "nczones.solids:parse_tools_section",
    "spindle": "nczones.solids:parse_spindle_section",
    "fixtures": "nczones.solids:parse_fixtures_section",
}


def declares_solids(machine: Machine) -> bool:
    """Does the machine declare tool or spindle solids (``[[tools]]``, ``[spindle]``)?  Only then is
    :mod:`nczones.solids` imported to build them (:func:`nczones.solids.machine_solids`)."""
    return bool(machine.sections.get("tools") or machine.sections.get("spindle"))


def section_parser(name: str) -> Callable[[Any, Any, tuple[str, ...]], Any]:
    """The parser of the extra section ``name`` (a key of :data:`SECTION_PARSERS`), its module imported now."""
    import importlib

    module, _, function = SECTION_PARSERS[name].partition(":")
    parser: Callable[[Any, Any, tuple[str, ...]], Any] = getattr(importlib.import_module(module), function)
    return parser


#: What a controller configuration looks like when it is given where a machine file belongs.  The same
#: signs ``nczones.imports.detect_kind`` reads (that layer sits above this one, so they are repeated here);
#: compiled at the first file that is not valid TOML (re.search), not at every start-up.
_FOREIGN = (
    (r"^\s*\[(?:EMC|EMCMOT|EMCIO|TRAJ|KINS|RS274NGC|TASK|HAL|DISPLAY|FILTER|AXIS_[A-Z]|JOINT_\d+)\]\s*$", re.M,
     "a LinuxCNC INI file"),
    (r"^\s*\$\d+\s*=", re.M, "a Grbl $$ settings dump"),
    (r"^\s*N\s*\d{1,5}\s*(?:Q\s*1\s*)?(?:[AS]\s*\d+\s*)?[PMI]\s*[-+.\d]", re.M | re.I,
     "a Fanuc parameter listing"),
)


def _controller_configuration(text: str) -> str | None:
    """What controller configuration ``text`` (not valid TOML) looks like, or None."""
    for pattern, flags, label in _FOREIGN:
        if re.search(pattern, text, flags):
            return label
    return None


def parse_machine(text: str, path: str = "<machine>") -> Machine:
    """Read a machine from TOML text; see :func:`load_machine`.

    Examples
    --------
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X", "Y"]
    ... pulse = "0.001"
    ... [machine.rapid]
    ... X = "12000"
    ... Y = "8000"
    ... [machine.reference]
    ... X = 100
    ... Y = 0.1
    ... ''')
    >>> m.axis_names, m.reference
    (('X', 'Y'), (Fraction(100, 1), Fraction(1, 10)))
    """
    rd = _Reader(path, text)
    return _machine(rd, _tomllib_loads(rd, text, path))


def _machine(rd: _Reader, data: dict[str, Any]) -> Machine:
    """The machine of the TOML table ``data`` (read by ``rd``), or the :class:`MachineFileError` of its faults."""
    machine = _build(rd, data)
    if rd.failed or machine is None:
        raise MachineFileError(rd.diagnostics)
    return machine


def _tomllib_loads(rd: _Reader, text: str, path: str) -> dict[str, Any]:
    """``tomllib.loads(text, parse_float=decimal.Decimal)``, a ``ZN100`` error (raised) for a text it refuses."""
    import tomllib

    try:
        return tomllib.loads(text, parse_float=decimal.Decimal)
    except tomllib.TOMLDecodeError as exc:
        m = re.search(r"line (\d+), column (\d+)", str(exc))
        span = None
        if m:
            line, col = int(m.group(1)), int(m.group(2))
            lines = text.splitlines()
            span = SourceSpan(path, line, col, col + 1, lines[line - 1] if line <= len(lines) else "")
        reason = re.sub(r"\s*\(at (?:line \d+, column \d+|end of document)\)", "", str(exc))
        foreign = _controller_configuration(text)
        if foreign is not None:  # issue 38: an INI, a $$ dump or a parameter listing given as --machine
            import shlex  # only here (start-up)

            shown = path if not path.startswith("<") else "CONFIG"
            target = (os.path.splitext(os.path.basename(shown))[0] or "machine") + ".toml"
            quoted = shlex.quote(shown)
            span = None  # the TOML parser's complaint is beside the point
            reason = (f"this looks like {foreign}, not a machine file: convert it once with "
                       f"`nczones import-machine {quoted} -o {shlex.quote(target)}` and pass "
                       f"{shlex.quote(target)} to --machine")
        rd.report("ZN100", f"not valid TOML: {reason}", span)
        raise MachineFileError(rd.diagnostics) from None


def load_machine(path: str | os.PathLike[str]) -> Machine:
    """Load and validate a machine file.

    Parameters
    ----------
    path : str or Path
        The TOML file.

    Returns
    -------
    Machine

    Raises
    ------
    MachineFileError
        With every problem found (codes ``ZN1xx``, see ``specs/machine-file.md``).
    """
    try:
        with open(path, "rb") as fh:  # not pathlib: ~3 ms of start-up with urllib.parse and ipaddress
            data = fh.read()
    except OSError as exc:
        raise MachineFileError(
            Diagnostic("ZN099", f"cannot read the machine file: {exc.strerror or exc}", file=str(path))
        ) from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise MachineFileError(
            Diagnostic("ZN099", f"the machine file is not UTF-8 text ({exc.reason} at byte {exc.start})", file=str(path))
        ) from None
    text = text.replace("\r\n", "\n").replace("\r", "\n")  # universal newlines, as text files are read
    name = str(path)
    rd = _Reader(name, text)
    table = cached_table(os.fspath(path), data, lambda: _tomllib_loads(rd, text, name))  # equal to tomllib's
    return replace(_machine(rd, table), sha256=sha256(data).hexdigest())


def _linuxcnc_settings(rd: _Reader, data: Mapping[str, Any], dialect: Any) -> tuple[str, ...]:
    """``[linuxcnc] subroutine_path``: a list of folders (relative ones against the machine file's folder)."""
    if "linuxcnc" not in data:
        return ()
    raw = data["linuxcnc"]
    line = rd.loc.section("linuxcnc")
    if not isinstance(raw, Mapping):
        rd.report("ZN103", f"[linuxcnc]: expected a table, got {as_written(raw)}", rd.loc.header(line))
        return ()
    _check_keys(rd, raw, _LINUXCNC_KEYS, "[linuxcnc]", line)
    if dialect == "fanuc":
        rd.report("ZN115", "[linuxcnc] is read only in the linuxcnc dialect; the fanuc dialect reads subprograms "
                  "from --library", rd.loc.header(line), Severity.WARNING)
    value = raw.get("subroutine_path", [])
    if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
        rd.report("ZN103", f"[linuxcnc] subroutine_path: expected a list of folders such as [\"subs\", "
                  f"\"../common\"], got {as_written(value)}", rd.loc.key("subroutine_path", line))
        return ()
    base = os.path.dirname(rd.path) if not rd.path.startswith("<") else ""
    return tuple(os.path.normpath(os.path.join(base, v)) for v in value)


def _build(rd: _Reader, data: dict[str, Any]) -> Machine | None:
    extra_sections = tuple(SECTION_PARSERS)
    _check_keys(rd, data, _TOP_KEYS + extra_sections, "top level", None)
    mt = data.get("machine")
    mline = rd.loc.section("machine")
    if not isinstance(mt, Mapping):
        rd.report("ZN102", "missing the [machine] table (axes, pulse, rapid rates, reference)", None)
        return None
    _check_keys(rd, mt, _MACHINE_KEYS, "[machine]", mline)

    # axes
    raw_axes = mt.get("axes")
    axes: tuple[str, ...] = ()
    if not isinstance(raw_axes, list) or not raw_axes:
        rd.report("ZN102", f"[machine] axes: expected a non-empty list of axis names such as [\"X\", \"Z\"], got {as_written(raw_axes)}", rd.loc.key("axes", mline))
        return None
    seen: set[str] = set()
    for a in raw_axes:
        if not isinstance(a, str) or a not in AXIS_NAMES:
            rd.report("ZN110", f"[machine] axes: unknown axis {as_written(a)}; allowed: {', '.join(AXIS_NAMES)}", rd.loc.key("axes", mline))
        elif a in seen:
            rd.report("ZN111", f"[machine] axes: axis {as_written(a)} is listed twice", rd.loc.key("axes", mline))
        else:
            seen.add(a)
            axes += (a,)
    if not axes:
        return None

    name = mt.get("name", "machine")
    if not isinstance(name, str):
        rd.report("ZN103", f"[machine] name: expected text, got {as_written(name)}", rd.loc.key("name", mline))
        name = "machine"
    units = mt.get("units", "mm")
    if units not in ("mm",):
        rd.report("ZN107", f"[machine] units: {as_written(units)} is not supported; machine files are in \"mm\" (programs may still use G20 inches)", rd.loc.key("units", mline))

    # pulse: one value or per axis
    raw_pulse = mt.get("pulse", "0.001")
    pulse: dict[str, Fraction] = {}
    if isinstance(raw_pulse, Mapping):
        pulse = _per_axis(rd, raw_pulse, axes, "[machine] pulse", rd.loc.section("machine.pulse"), required=True, inline=("pulse", mline), positive=True, limit=Fraction(1))
    else:
        q = read_number(rd, raw_pulse, "[machine] pulse", functools.partial(rd.loc.key, "pulse", mline), positive=True, limit=Fraction(1))
        if q is not None:
            pulse = {a: q for a in axes}

    rapid = _per_axis(rd, mt.get("rapid", {}), axes, "[machine.rapid]", rd.loc.section("machine.rapid"), required=True, inline=("rapid", mline), positive=True)
    raw_max_feed = mt.get("max_feed")
    max_feed: dict[str, Fraction] = {}
    if raw_max_feed is None:
        max_feed = dict(rapid)
    elif isinstance(raw_max_feed, Mapping):
        max_feed = _per_axis(rd, raw_max_feed, axes, "[machine.max_feed]", rd.loc.section("machine.max_feed"), required=True, inline=("max_feed", mline), positive=True)
    else:
        q = read_number(rd, raw_max_feed, "[machine] max_feed", functools.partial(rd.loc.key, "max_feed", mline), positive=True)
        if q is not None:
            max_feed = {a: q for a in axes}

    rapid_mode_raw = mt.get("rapid_mode", "linear")
    try:
        rapid_mode = RapidMode(rapid_mode_raw)
    except ValueError:
        rd.report("ZN107", f"[machine] rapid_mode: {as_written(rapid_mode_raw)} is not allowed; use \"linear\" or \"dogleg\"", rd.loc.key("rapid_mode", mline))
        rapid_mode = RapidMode.LINEAR
    period = read_number(rd, mt.get("monitor_period_ms", "5"), "[machine] monitor_period_ms", functools.partial(rd.loc.key, "monitor_period_ms", mline), positive=True, limit=Fraction(1000))

    reference = _per_axis(rd, mt.get("reference", {}), axes, "[machine.reference]", rd.loc.section("machine.reference"), required=True, inline=("reference", mline))
    start_raw = mt.get("start")
    start = dict(reference)
    if start_raw is not None:
        start = _per_axis(rd, start_raw, axes, "[machine.start]", rd.loc.section("machine.start"), required=True, inline=("start", mline))

    tool_axis = mt.get("tool_axis", "Z" if "Z" in axes else None)
    if tool_axis is not None and tool_axis not in axes:
        rd.report("ZN110", f"[machine] tool_axis: {as_written(tool_axis)} is not one of the machine's axes ({', '.join(axes)})", rd.loc.key("tool_axis", mline))
        tool_axis = None

    modal = _modal(rd, mt.get("modal"), mline)
    machine_type = mt.get("type", "mill")
    if machine_type not in MACHINE_TYPES:
        rd.report("ZN114", f"[machine] type: {as_written(machine_type)} is not allowed; use \"mill\" or \"lathe\"",
                  rd.loc.key("type", mline))
        machine_type = None  # unknown: the checks that depend on it are left out
    diameter_axes = _diameter_axes(rd, mt.get("diameter_axes", []), axes, mline)
    if machine_type == "lathe" and not any(str(c).strip().upper() in ("G17", "G18", "G19")
                                           for c in (mt.get("modal") or []) if isinstance(mt.get("modal"), list)):
        modal = tuple("G18" if c == "G17" else c for c in modal)  # a lathe starts in the ZX plane
    dialect = mt.get("dialect", "linuxcnc")
    if dialect not in DIALECTS:
        rd.report("ZN114", f"[machine] dialect: {as_written(dialect)} is not allowed; use \"linuxcnc\" or \"fanuc\"",
                  rd.loc.key("dialect", mline))
        dialect = None  # unknown: the checks that depend on it are left out

    # offsets
    offsets: dict[str, tuple[Fraction, ...]] = {}
    raw_offsets = data.get("offsets", {})
    oline = rd.loc.section("offsets")
    if not isinstance(raw_offsets, Mapping):
        rd.report("ZN103", f"[offsets]: expected a table, got {as_written(raw_offsets)}", None)
        raw_offsets = {}
    for key, value in raw_offsets.items():
        oname = key.replace(" ", "").upper() if isinstance(key, str) else key
        if oname not in WORK_OFFSETS and oname not in FANUC_OFFSETS:
            close = close_matches(key, WORK_OFFSETS + FANUC_OFFSETS, n=1)
            hint = f"; did you mean {as_written(close[0])}?" if close else f"; allowed: {', '.join(WORK_OFFSETS)}"
            rd.report("ZN101", f"[offsets]: unknown work offset {as_written(key)}{hint}", rd.loc.key(key, oline))
            continue
        if oname in FANUC_OFFSETS and dialect == "linuxcnc":
            rd.report("ZN101", f"[offsets]: work offset {as_written(key)} exists only on Fanuc controls; valid in the "
                      "fanuc dialect: set dialect = \"fanuc\" in [machine]", rd.loc.key(key, oline))
            continue
        vals = _per_axis(rd, value, axes, f"[offsets] {key}", rd.loc.section(f"offsets.{key}"), required=False, inline=(key, oline))
        offsets[oname] = tuple(vals.get(a, Fraction(0)) for a in axes)

    tool_lengths = _register_table(rd, data, "tool_lengths", "H", "length register", 'H1 = "200"')
    # cutter compensation and tool diameters
    comp_raw = mt.get("cutter_compensation", "none")
    comp = comp_raw if comp_raw in CUTTER_COMPENSATION_MODES else "none"
    if comp_raw not in CUTTER_COMPENSATION_MODES:
        rd.report("ZN114", f"[machine] cutter_compensation: {as_written(comp_raw)} is not allowed; use \"none\" "
                  "(G41/G42 make the result unknown) or \"linuxcnc\" (modelled as LinuxCNC does it)",
                  rd.loc.key("cutter_compensation", mline))
    tool_diameters = _register_table(rd, data, "tool_diameters", "T", "tool number", 'T1 = "6"')
    block_delete_raw = mt.get("block_delete", "both")
    try:
        block_delete = format_block_delete(parse_block_delete(block_delete_raw))
    except ValueError as e:
        rd.report("ZN114", f"[machine] block_delete: {as_written(block_delete_raw)} is not allowed: {e}; or a "
                  "table { 1 = \"on\", 2 = \"off\" }",
                  rd.loc.key("block_delete", mline))
        block_delete = "both"

    arc_tol: Fraction | str | None = None
    if "arc_tolerance" in mt:
        raw = mt["arc_tolerance"]
        if raw in ARC_TOLERANCE_RULES:
            arc_tol = raw
        elif type(raw) is str and not _PLAIN_DECIMAL.match(raw):
            rd.report("ZN114", f"[machine] arc_tolerance: {as_written(raw)} is not allowed; use a length in mm "
                      "(such as \"0.002\"), \"linuxcnc\" or \"grbl\" (the control's own rule)",
                      rd.loc.key("arc_tolerance", mline))
        else:
            arc_tol = read_number(rd, raw, "[machine] arc_tolerance", functools.partial(rd.loc.key, "arc_tolerance", mline),
                                  nonnegative=True, limit=Fraction(10))

    path_mode = "G64"  # LinuxCNC's interpreter and a Fanuc control both start blending (specs/path-modes.md)
    if "path_mode" in mt:
        raw = mt["path_mode"]
        if type(raw) is str and raw.strip().upper() in PATH_MODES:
            path_mode = raw.strip().upper()
        else:
            rd.report("ZN114", f"[machine] path_mode: {as_written(raw)} is not allowed; use \"G64\" (blending, "
                      "the default), \"G61\" (exact path) or \"G61.1\" (exact stop)", rd.loc.key("path_mode", mline))
    path_tol: Fraction | None = None
    if "path_tolerance" in mt:
        path_tol = read_number(rd, mt["path_tolerance"], "[machine] path_tolerance",
                               functools.partial(rd.loc.key, "path_tolerance", mline), nonnegative=True, limit=Fraction(10))

    fanuc = _fanuc_settings(rd, data, mt, mline, axes, dialect, machine_type)
    control_units, tc_quill, tc_g30, tc_position = _linuxcnc_control(rd, mt, mline, axes, dialect)
    subroutine_path = _linuxcnc_settings(rd, data, dialect)
    tool_offsets = _tool_offsets(rd, data.get("tool_offsets", {}), axes)
    zones = _zones(rd, data.get("zones", []), axes, tool_axis)

    sections: dict[str, Any] = {}
    for key in SECTION_PARSERS:
        if key in data:
            sections[key] = section_parser(key)(rd, data[key], axes)

    if rd.failed or period is None:
        return None

    axis_objs = tuple(Axis(a, pulse[a], rapid[a], max_feed[a], a in ROTARY_AXES, accel.get(a))
                      for accel in [_accelerations(rd, mt, axes, mline)] for a in axes)
    allowed = AllowedSet(tuple(zones), tool_axis)
    start_t = tuple(start[a] for a in axes)
    ref_t = tuple(reference[a] for a in axes)
    machine = Machine(
        name=name, units="mm", axes=axis_objs, rapid_mode=rapid_mode,
        monitor_period_ms=period, reference=ref_t, start=start_t,
        offsets=MappingProxyType(offsets), tool_lengths=MappingProxyType(tool_lengths),
        allowed=allowed, modal=modal, tool_axis=tool_axis, source=rd.path,
        sections=MappingProxyType(sections), cutter_compensation=comp,
        tool_diameters=MappingProxyType(tool_diameters), dialect=dialect or "linuxcnc", fanuc=fanuc,
        block_delete=block_delete, arc_tolerance=arc_tol, path_mode=path_mode, path_tolerance=path_tol,
        machine_type=machine_type or "mill", diameter_axes=diameter_axes, tool_offsets=MappingProxyType(tool_offsets),
        control_units=control_units, tool_change_quill_up=tc_quill, tool_change_at_g30=tc_g30,
        tool_change_position=MappingProxyType(tc_position),
        subroutine_path=subroutine_path,
    )
    # The program starts with no tool length active (G49), so tip zones see Z itself.
    bad = allowed.violated_zones(machine.point(start_t))
    if bad:
        if start_raw is not None:
            where = f"[machine.start]: the start position {_fmt_point(axes, start_t)}"
        else:
            where = (
                f"[machine.reference]: the start position {_fmt_point(axes, start_t)} "
                "(the reference position, as there is no [machine.start])"
            )
        rd.report(
            "ZN130",
            f"{where} is outside the allowed set (it violates zone "
            f"{', '.join(as_written(z.name) for z in bad)}); no program can be verified from there",
            rd.loc.header(rd.loc.section("machine.start")) or rd.loc.key("start", mline)
            if start_raw is not None
            else rd.loc.header(rd.loc.section("machine.reference")) or rd.loc.key("reference", mline),
        )
        return None
    if start_raw is not None:
        bad_ref = allowed.violated_zones(machine.point(ref_t))
        if bad_ref:
            rd.report(
                "ZN131",
                f"[machine.reference]: the reference position {_fmt_point(axes, ref_t)} is outside the allowed set "
                f"(it violates zone {', '.join(as_written(z.name) for z in bad_ref)}); every move to it (G28, homing) will be reported unsafe",
                rd.loc.header(rd.loc.section("machine.reference")) or rd.loc.key("reference", mline),
                Severity.WARNING,
            )
    return Machine(
        **{f: getattr(machine, f) for f in field_names(Machine) if f != "warnings"},
        warnings=tuple(d for d in rd.diagnostics if d.severity is Severity.WARNING),
    )


_CHOICES = {
    "gcode_system": GCODE_SYSTEMS,
    "tool_offset_motion": ("shift", "move"),
    "tool_offset_cancel": ("wear", "all"),
    "decimal_point_input": ("calculator", "increment"),
    "increment_system": ("IS-A", "IS-B", "IS-C"),
    "boring_shift": ("+X", "-X", "+Y", "-Y"),
    "tool_length_motion": ("move", "shift"),
}


def _linuxcnc_control(rd: _Reader, mt: Mapping, mline: int | None, axes: tuple[str, ...],
                      dialect: str) -> tuple[str, bool, bool, dict[str, Fraction]]:
    """``control_units`` and the tool-change keys of ``[machine]`` (LinuxCNC's ``[TRAJ] LINEAR_UNITS`` and
    ``[EMCIO] TOOL_CHANGE_QUILL_UP`` / ``TOOL_CHANGE_AT_G30`` / ``TOOL_CHANGE_POSITION``)."""
    units = mt.get("control_units", "mm")
    if units not in CONTROL_UNITS:
        rd.report("ZN114", f"[machine] control_units: {as_written(units)} is not allowed; use \"mm\" or \"inch\" "
                  "(LinuxCNC's [TRAJ] LINEAR_UNITS: the unit of its numbered parameters)",
                  rd.loc.key("control_units", mline))
        units = "mm"
    flags = []
    for key in ("tool_change_quill_up", "tool_change_at_g30"):
        v = mt.get(key, False)
        if not isinstance(v, bool):
            rd.report("ZN103", f"[machine] {key}: expected true or false, got {as_written(v)}", rd.loc.key(key, mline))
            v = False
        flags.append(v)
    position: dict[str, Fraction] = {}
    raw = mt.get("tool_change_position")
    if raw is not None:
        if not isinstance(raw, Mapping):
            rd.report("ZN103", f"[machine] tool_change_position: expected a table of axis positions such as "
                      f"{{ Z = \"0\" }}, got {as_written(raw)}", rd.loc.key("tool_change_position", mline))
        else:
            position = _per_axis(rd, raw, axes, "[machine.tool_change_position]",
                                 rd.loc.section("machine.tool_change_position"), required=False,
                                 inline=("tool_change_position", mline))
    given = [k for k in ("tool_change_quill_up", "tool_change_at_g30", "tool_change_position", "control_units")
             if k in mt]
    if given and dialect != "linuxcnc":
        rd.report("ZN115", f"[machine] {given[0]} is read only in the linuxcnc dialect (a LinuxCNC INI setting)",
                  rd.loc.key(given[0], mline), Severity.WARNING)
    return units, flags[0], flags[1], position


def _fanuc_settings(rd: _Reader, data: Mapping, mt: Mapping, mline: int | None, axes: tuple[str, ...],
                    dialect: str, machine_type: str | None = "mill") -> FanucSettings:
    """``[fanuc]``, ``[variables]``, ``[macros]`` and ``[machine.reference_2..4]`` (``specs/fanuc.md``)."""
    kw: dict[str, Any] = {}
    raw = data.get("fanuc", {})
    fline = rd.loc.section("fanuc")
    given = [k for k in ("fanuc", "variables", "macros") if k in data] + [
        f"machine.{k}" for k in ("reference_2", "reference_3", "reference_4") if k in mt]
    if given and dialect == "linuxcnc":
        rd.report("ZN115", f"[{given[0]}] is read only in the fanuc dialect; set dialect = \"fanuc\" in [machine] "
                  "(or pass --dialect fanuc)", rd.loc.header(rd.loc.section(given[0])), Severity.WARNING)
    if not isinstance(raw, Mapping):
        rd.report("ZN103", f"[fanuc]: expected a table, got {as_written(raw)}", rd.loc.header(fline))
        raw = {}
    _check_keys(rd, raw, _FANUC_KEYS, "[fanuc]", fline)
    for key, choices in _CHOICES.items():
        if key in raw:
            value = raw[key]
            if value not in choices:
                rd.report("ZN114", f"[fanuc] {key}: {as_written(value)} is not allowed; use "
                          + " or ".join(as_written(c) for c in choices), rd.loc.key(key, fline))
            else:
                kw[key] = value
    lathe_given = [k for k in _FANUC_LATHE_KEYS if k in raw]
    if lathe_given and machine_type == "mill" and not (given and dialect == "linuxcnc"):
        rd.report("ZN115", f"[fanuc] {lathe_given[0]} is read only on a lathe; set type = \"lathe\" in [machine]",
                  rd.loc.key(lathe_given[0], fline), Severity.WARNING)
    for key in ("g73_retract", "g83_clearance", "g71_retract", "g73_relief_x", "g73_relief_z", "g74_retract",
                "g76_finish_allowance"):
        if key in raw:
            q = read_number(rd, raw[key], f"[fanuc] {key}", functools.partial(rd.loc.key, key, fline), nonnegative=key not in (
                "g73_relief_x", "g73_relief_z"))
            if q is not None:
                kw[key] = q
    for key in ("g71_depth", "g76_min_depth", "thread_chamfer"):
        if key in raw:
            q = read_number(rd, raw[key], f"[fanuc] {key}", functools.partial(rd.loc.key, key, fline), nonnegative=True)
            if q is not None:
                if key == "g71_depth" and q == 0:
                    rd.report("ZN106", f"[fanuc] {key}: \"0\" must be greater than 0", rd.loc.key(key, fline))
                else:
                    kw[key] = q
    for key, top in (("thread_chamfer_angle", 90), ("g76_tool_angle", 120)):
        if key in raw:
            q = read_number(rd, raw[key], f"[fanuc] {key}", functools.partial(rd.loc.key, key, fline), nonnegative=True)
            if q is not None:
                if q > top:
                    rd.report("ZN105", f"[fanuc] {key}: {as_written(raw[key])} is out of range; allowed 0 to {top} "
                              "degrees", rd.loc.key(key, fline))
                else:
                    kw[key] = q
    for key, top in (("g73_divisions", 99999), ("g76_finish_passes", 99), ("path", 15)):
        if key in raw:
            value = raw[key]
            if not isinstance(value, int) or isinstance(value, bool) or not 1 <= value <= top:
                rd.report("ZN103", f"[fanuc] {key}: expected an integer 1 to {top}, got {as_written(value)}",
                          rd.loc.key(key, fline))
            else:
                kw[key] = value
    if "roughing_final_pass" in raw:
        if not isinstance(raw["roughing_final_pass"], bool):
            rd.report("ZN103", f"[fanuc] roughing_final_pass: expected true or false, got "
                      f"{as_written(raw['roughing_final_pass'])}", rd.loc.key("roughing_final_pass", fline))
        else:
            kw["roughing_final_pass"] = raw["roughing_final_pass"]
    if "scaling_unit" in raw:
        q = read_number(rd, raw["scaling_unit"], "[fanuc] scaling_unit", functools.partial(rd.loc.key, "scaling_unit", fline), positive=True,
                    limit=Fraction(1))
        if q is not None:
            kw["scaling_unit"] = q
    for key in ("rotation_incremental", "atan_signed"):
        if key in raw:
            if not isinstance(raw[key], bool):
                rd.report("ZN103", f"[fanuc] {key}: expected true or false, got {as_written(raw[key])}",
                          rd.loc.key(key, fline))
            else:
                kw[key] = raw[key]
    if "harmless_m" in raw:
        value = raw["harmless_m"]
        if not isinstance(value, list) or not all(isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= 9999
                                                  for v in value):
            rd.report("ZN103", f"[fanuc] harmless_m: expected a list of M code numbers such as [88, 89], got "
                      f"{as_written(value)}", rd.loc.key("harmless_m", fline))
        else:
            kw["harmless_m"] = frozenset(value)
    refs = {}
    for n in (2, 3, 4):
        key = f"reference_{n}"
        if key in mt:
            vals = _per_axis(rd, mt[key], axes, f"[machine.{key}]", rd.loc.section(f"machine.{key}"), required=True,
                             inline=(key, mline))
            if len(vals) == len(axes):
                refs[n] = tuple(vals[a] for a in axes)
    kw["references"] = MappingProxyType(refs)
    kw["variables"] = MappingProxyType(_variables(rd, data.get("variables", {})))
    kw["macros"] = MappingProxyType(_macros(rd, data.get("macros", {})))
    return FanucSettings(**kw)


def _variables(rd: _Reader, raw: Any) -> dict[int, Fraction]:
    """``[variables]``: initial values of common variables ``"#100"``..``"#999"``."""
    out: dict[int, Fraction] = {}
    line = rd.loc.section("variables")
    if not isinstance(raw, Mapping):
        rd.report("ZN103", f"[variables]: expected a table such as \"#500\" = \"12.5\", got {as_written(raw)}",
                  rd.loc.header(line))
        return out
    for key, value in raw.items():
        m = re.fullmatch(r"#?(\d{1,4})", key.strip())
        span = rd.loc.key(key if not key.startswith("#") else f'"{key}"', line) or rd.loc.key(key, line)
        if not m or not 100 <= int(m.group(1)) <= 999:
            rd.report("ZN101", f"[variables]: {as_written(key)} is not a common variable; write \"#100\" to \"#999\" "
                      "(local #1-#33 start vacant, system variables come from the rest of the machine file)", span)
            continue
        q = read_number(rd, value, f"[variables] {key}", span)
        if q is not None:
            out[int(m.group(1))] = q
    return out


def _macros(rd: _Reader, raw: Any) -> dict[str, tuple[int, str]]:
    """``[macros]``: ``G100 = 9010`` (a G code calls O9010 like G65), ``M50 = 9020`` (an M code calls a
    macro), ``M60 = { program = 9001, call = "subprogram" }`` (like M98), ``T = 9000``."""
    out: dict[str, tuple[int, str]] = {}
    line = rd.loc.section("macros")
    if not isinstance(raw, Mapping):
        rd.report("ZN103", f"[macros]: expected a table such as G100 = 9010, got {as_written(raw)}", rd.loc.header(line))
        return out
    for key, value in raw.items():
        span = rd.loc.key(key, line)
        m = re.fullmatch(r"([GM])(\d{1,4})|T", key.strip().upper())
        if not m:
            rd.report("ZN101", f"[macros]: {as_written(key)} is not a code; write G<number> (1-9999), M<number> or T",
                      span)
            continue
        call = "macro"
        program = value
        if isinstance(value, Mapping):
            extra = [k for k in value if k not in ("program", "call")]
            if extra:
                rd.report("ZN101", f"[macros] {key}: unknown key {as_written(extra[0])}; allowed keys: program, call", span)
                continue
            program = value.get("program")
            call = value.get("call", "macro")
            if call not in ("macro", "subprogram"):
                rd.report("ZN114", f"[macros] {key}: call {as_written(call)} is not allowed; use \"macro\" (like G65, "
                          "with arguments) or \"subprogram\" (like M98)", span)
                continue
        if isinstance(program, str) and program.strip().isdigit():
            program = int(program)
        if not isinstance(program, int) or isinstance(program, bool) or not 1 <= program <= 99999999:
            rd.report("ZN103", f"[macros] {key}: the program number must be an integer such as 9010, got "
                      f"{as_written(program)}", span)
            continue
        code = key.strip().upper()
        if code.startswith("G") and code in ("G65", "G66", "G67"):
            rd.report("ZN114", f"[macros] {key}: {code} is the macro call itself and cannot call a macro", span)
            continue
        out[code if code == "T" else f"{code[0]}{int(code[1:])}"] = (program, call)
    return out


def _diameter_axes(rd: _Reader, raw: Any, axes: tuple[str, ...], mline: int | None) -> tuple[str, ...]:
    """``[machine] diameter_axes``: linear axes of the machine whose program words are diameters."""
    span = rd.loc.key("diameter_axes", mline)
    if not isinstance(raw, list) or not all(isinstance(a, str) for a in raw):
        rd.report("ZN103", f"[machine] diameter_axes: expected a list of axis names such as [\"X\"], got "
                  f"{as_written(raw)}", span)
        return ()
    out: list[str] = []
    for a in raw:
        if a not in axes:
            rd.report("ZN110", f"[machine] diameter_axes: {as_written(a)} is not one of the machine's axes "
                      f"({', '.join(axes)})", span)
        elif a in ROTARY_AXES:
            rd.report("ZN107", f"[machine] diameter_axes: {as_written(a)} is a rotary axis; only linear axes take "
                      "diameters", span)
        elif a in out:
            rd.report("ZN111", f"[machine] diameter_axes: axis {as_written(a)} is listed twice", span)
        else:
            out.append(a)
    return tuple(out)


_OFFSET_KEYS = ("R", "tip", "wear")


def _tool_offsets(rd: _Reader, raw: Any, axes: tuple[str, ...]) -> dict[int, ToolOffset]:
    """``[tool_offsets]``: lathe tool offsets by number, ``1 = { X = "-120", Z = "-310", R = "0.8", tip = 3,
    wear = { X = "0.02" } }`` (lengths in machine units: radius on a diameter axis)."""
    out: dict[int, ToolOffset] = {}
    line = rd.loc.section("tool_offsets")
    if not isinstance(raw, Mapping):
        rd.report("ZN103", f"[tool_offsets]: expected a table such as 1 = {{ X = \"-120\", Z = \"-310\" }}, got "
                  f"{as_written(raw)}", rd.loc.header(line))
        return out
    for key, value in raw.items():
        span = rd.loc.key(key, line) or rd.loc.header(rd.loc.section(f"tool_offsets.{key}"))
        if not (isinstance(key, str) and key.isdigit() and len(key) <= 4):
            rd.report("ZN101", f"[tool_offsets]: {as_written(key)} is not an offset number; write the number (0 to "
                      "9999) as the key, such as 1 = { X = \"-120\", Z = \"-310\" }", span)
            continue
        what = f"[tool_offsets] {key}"
        if not isinstance(value, Mapping):
            rd.report("ZN103", f"{what}: expected a table of axis values, R, tip and wear, got {as_written(value)}",
                      span)
            continue
        for k in value:
            if k not in axes and k not in _OFFSET_KEYS:
                rd.report("ZN101", f"{what}: unknown key {as_written(k)}; allowed: the machine's axes "
                          f"({', '.join(axes)}), {', '.join(_OFFSET_KEYS)}", span)
        geometry = []
        for a in axes:
            if a in value:
                q = read_number(rd, value[a], f"{what}.{a}", span)
                if q is not None:
                    geometry.append((a, q))
        radius = read_number(rd, value.get("R", "0"), f"{what}.R", span, nonnegative=True)
        tip = value.get("tip", 0)
        if not isinstance(tip, int) or isinstance(tip, bool) or not 0 <= tip <= 9:
            rd.report("ZN103", f"{what}.tip: the imaginary tool nose direction is an integer 0 to 9, got "
                      f"{as_written(tip)}", span)
            tip = 0
        wear_raw = value.get("wear", {})
        wear = []
        wear_radius: Fraction | None = Fraction(0)
        if not isinstance(wear_raw, Mapping):
            rd.report("ZN103", f"{what}.wear: expected a table such as {{ X = \"0.02\" }}, got {as_written(wear_raw)}",
                      span)
        else:
            for k in wear_raw:
                if k not in axes and k != "R":
                    rd.report("ZN101", f"{what}.wear: unknown key {as_written(k)}; allowed: the machine's axes, R",
                              span)
            for a in axes:
                if a in wear_raw:
                    q = read_number(rd, wear_raw[a], f"{what}.wear.{a}", span)
                    if q is not None:
                        wear.append((a, q))
            wear_radius = read_number(rd, wear_raw.get("R", "0"), f"{what}.wear.R", span)
        out[int(key)] = ToolOffset(int(key), tuple(geometry), tuple(wear), radius or Fraction(0),
                                   wear_radius or Fraction(0), tip)
    return out


def _fmt_point(axes: tuple[str, ...], coords: tuple[Fraction, ...]) -> str:
    return " ".join(f"{a}{format_decimal(c)}" for a, c in zip(axes, coords))


def _modal(rd: _Reader, raw: Any, mline: int | None) -> tuple[str, ...]:
    if raw is None:
        return DEFAULT_MODAL
    span = rd.loc.key("modal", mline)
    if not isinstance(raw, list) or not all(isinstance(c, str) for c in raw):
        rd.report("ZN103", f"[machine] modal: expected a list of G codes such as [\"G90\", \"G21\"], got {as_written(raw)}", span)
        return DEFAULT_MODAL
    chosen = dict(zip(MODAL_CHOICES, DEFAULT_MODAL))
    given: dict[str, str] = {}
    for code in raw:
        norm = code.strip().upper()
        group = next((g for g, choices in MODAL_CHOICES.items() if norm in choices), None)
        if group is None:
            allowed = ", ".join(c for cs in MODAL_CHOICES.values() for c in cs)
            rd.report("ZN107", f"[machine] modal: {as_written(code)} is not an initial modal code nczones models; allowed: {allowed}", span)
            continue
        if group in given:
            rd.report("ZN108", f"[machine] modal: {as_written(code)} conflicts with {as_written(given[group])}; both set the {group} mode, give one", span)
            continue
        given[group] = code
        chosen[group] = norm
    return tuple(chosen.values())


def _zones(rd: _Reader, raw: Any, axes: tuple[str, ...], tool_axis: str | None) -> list[Zone]:
    if not isinstance(raw, list):
        rd.report("ZN103", f"zones: expected [[zones]] tables, got {as_written(raw)}", None)
        return []
    out: list[Zone] = []
    names: set[str] = set()
    for index, zt in enumerate(raw):
        header = rd.loc.section("zones", index)
        if not isinstance(zt, Mapping):
            rd.report("ZN103", f"zone {index + 1}: expected a table, got {as_written(zt)}", None)
            continue
        name = zt.get("name")
        label = f"zone {_quoted(name)}" if isinstance(name, str) else f"zone {index + 1}"
        if not isinstance(name, str) or not name.strip():
            rd.report("ZN102", f"{label}: missing name (every zone needs a name the reports can use)", rd.loc.header(header))
            name = f"zone {index + 1}"
        elif name in names:
            rd.report("ZN112", f"{label}: the name is used by another zone; names must be unique", rd.loc.key("name", header))
        names.add(name)
        kind = zt.get("kind")
        if not isinstance(kind, str) or kind not in _ZONE_KEYS:
            rd.report("ZN107", f"{label}: kind {as_written(kind)} is not allowed; use \"stepped\", \"box\" or \"polygon\"", rd.loc.key("kind", header))
            continue
        _check_keys(rd, zt, _ZONE_KEYS[kind], label, header)
        forbid = zt.get("forbid", False)
        if not isinstance(forbid, bool):
            rd.report("ZN103", f"{label}: forbid must be true or false, got {as_written(forbid)}", rd.loc.key("forbid", header))
            forbid = False
        point_raw = zt.get("point", "machine")
        try:
            point = ZonePoint(point_raw)
        except ValueError:
            rd.report("ZN107", f"{label}: point {as_written(point_raw)} is not allowed; use \"machine\" or \"tip\"", rd.loc.key("point", header))
            point = ZonePoint.MACHINE
        if point is ZonePoint.TIP and tool_axis is None:
            rd.report("ZN113", f"{label}: point = \"tip\" needs a tool axis, but this machine has none (set [machine] tool_axis)", rd.loc.key("point", header))
        builder = {"stepped": _stepped, "box": _box, "polygon": _polygon}[kind]
        zone = builder(rd, zt, label, name, header, axes, forbid, point)
        if zone is not None:
            out.append(zone)
    return out


def _axis_field(rd: _Reader, zt: Mapping[str, Any], key: str, label: str, header: int | None, axes: tuple[str, ...]) -> str | None:
    value = zt.get(key)
    span = rd.loc.key(key, header)
    if value is None:
        rd.report("ZN102", f"{label}: missing {key} (one of {', '.join(axes)})", span or rd.loc.header(header))
        return None
    if value not in axes:
        rd.report("ZN110", f"{label}: {key} {as_written(value)} is not one of the machine's axes ({', '.join(axes)})", span)
        return None
    return str(value)


def _stepped(rd: _Reader, zt: Mapping[str, Any], label: str, name: str, header: int | None, axes: tuple[str, ...],
             forbid: bool, point: ZonePoint) -> SteppedZone | None:
    ref = _axis_field(rd, zt, "reference_axis", label, header, axes)
    lim = _axis_field(rd, zt, "limited_axis", label, header, axes)
    if ref is not None and ref == lim:
        rd.report("ZN111", f"{label}: reference_axis and limited_axis are both {as_written(ref)}; a table limits one axis by another", rd.loc.key("limited_axis", header))
    if "from" not in zt:
        rd.report("ZN102", f"{label}: missing from (the lower bound of the first region on {ref or 'the reference axis'})", rd.loc.header(header))
        start = None
    else:
        start = read_number(rd, zt["from"], f"{label}: from", functools.partial(rd.loc.key, "from", header))
    raw_regions = zt.get("regions")
    if not isinstance(raw_regions, list) or not raw_regions:
        rd.report("ZN120", f"{label}: regions must be a non-empty list such as [{{ upto = \"500\", max = \"300\" }}], got {as_written(raw_regions)}", rd.loc.key("regions", header))
        return None
    plain = None if start is None else _plain_table(raw_regions, start)
    if plain is not None:  # every region in the common form: what _regions would read, without a word
        if ref is None or lim is None or ref == lim:
            return None
        return SteppedZone.from_integers(name, ref, lim, *plain, forbid, point)
    regions, ok = _regions(rd, raw_regions, label, header, ref, start)
    if not ok or start is None or ref is None or lim is None or ref == lim:
        return None
    return SteppedZone(name, ref, lim, start, tuple(regions), forbid, point)


#: The keys a region of a stepped table may have.
_REGION_KEYS = frozenset(("upto", "min", "max"))


_TEXT_OR_NONE = frozenset((str, type(None)))

#: Decimal texts of :data:`_PLAIN_DECIMAL`, one a line (a list of them joined by newlines, read at once).
_PLAIN_LINES = re.compile(r"(?:[+-]?[0-9]{1,10}(?:\.[0-9]{0,30})?\n)*[+-]?[0-9]{1,10}(?:\.[0-9]{0,30})?")


def _plain_table(raw_regions: list[Any], start: Fraction) -> tuple[int, int, list[int], list[int | None],
                                                                   list[int | None]] | None:
    """A table's regions written in the common form, as integers over one denominator, or None for
    :func:`_regions` to read (and report): ``(den, start, uptos, mins, maxs)``, each number ``k / den``, None
    for a missing ``min`` / ``max`` (:meth:`SteppedZone.from_integers` makes the zone of them).

    The common form: each region an inline table of ``upto`` and optionally ``min`` and ``max``, each a
    decimal string of :data:`_PLAIN_DECIMAL` within :data:`MAX_ABS_LENGTH` (``read_number``'s fast case), ``min``
    at most ``max`` and every ``upto`` greater than the one before (the first greater than ``start``).  Such a
    list is one on which :func:`_regions` reports nothing, and its numbers are the values ``read_number`` reads;
    anything else returns None and is read by :func:`_regions` from the start, so every diagnostic is as it
    was.  Faster than the loop of :func:`_regions` (issue 36, a table of 4,096 regions): the list is read a
    column at a time, by the built-in functions (one pattern over the column's texts joined, ``int`` of each
    text without its point), the limits' texts once each, and the checks are of integers.
    """
    if MAX_ABS_LENGTH.denominator != 1 or set(map(type, raw_regions)) != {dict}:
        return None
    if not set().union(*raw_regions) <= _REGION_KEYS:
        return None
    ups = list(map(dict.get, raw_regions, itertools.repeat("upto")))
    lows = list(map(dict.get, raw_regions, itertools.repeat("min")))
    highs = list(map(dict.get, raw_regions, itertools.repeat("max")))
    # every region has its upto, and no key a value of None (each key counted: the keys are known ones)
    if None in ups or sum(map(len, raw_regions)) != 3 * len(ups) - lows.count(None) - highs.count(None):
        return None
    kinds = set(map(type, lows))
    kinds.update(map(type, highs))
    if not kinds <= _TEXT_OR_NONE:  # (a list or a table would not even go in a set)
        return None
    texts = list({*lows, *highs} - {None})
    read_ups, read_limits = _plain_column(ups), _plain_column(texts)
    if read_ups is None or read_limits is None:
        return None
    den = math.lcm(read_ups[1], read_limits[1], start.denominator)
    uptos = [k * (den // read_ups[1]) for k in read_ups[0]] if den != read_ups[1] else read_ups[0]
    value = dict(zip(texts, [k * (den // read_limits[1]) for k in read_limits[0]]))
    mins, maxs = list(map(value.get, lows)), list(map(value.get, highs))
    first = start.numerator * (den // start.denominator)
    if first >= uptos[0] or not all(map(operator.lt, uptos, itertools.islice(uptos, 1, None))):
        return None
    if any(lo is not None and hi is not None and value[lo] > value[hi] for lo, hi in set(zip(lows, highs))):
        return None  # (each pair of texts written checked once)
    return den, first, uptos, mins, maxs


def _plain_column(texts: list[Any]) -> tuple[list[int], int] | None:
    """``(ks, den)``: each of ``texts`` as ``k / den``, ``den`` a power of ten, when every one is a string of
    :data:`_PLAIN_DECIMAL` of magnitude at most :data:`MAX_ABS_LENGTH` (what :func:`read_number` reads without a
    word, the same value); else None."""
    if not texts:
        return [], 1
    try:
        joined = "\n".join(texts)
    except TypeError:  # not all strings
        return None
    if joined.count("\n") != len(texts) - 1 or _PLAIN_LINES.fullmatch(joined) is None:
        return None
    # digits without the point (the pattern leaves no other character int() would read), and the places
    ks = list(map(int, map(str.replace, texts, itertools.repeat("."), itertools.repeat(""))))
    points = list(map(str.find, texts, itertools.repeat(".")))
    ends = set(map(operator.sub, map(len, texts), points)) if -1 not in points else ()
    if len(ends) == 1:  # every text has a point and as many places after it (a table's usual column)
        top = ends.pop() - 1
    else:
        places = [len(t) - p - 1 if p >= 0 else 0 for t, p in zip(texts, points)]
        top = max(places)
        ks = [k * 10 ** (top - p) for k, p in zip(ks, places)]
    den = 10**top
    if max(map(abs, ks)) > MAX_ABS_LENGTH.numerator * den:
        return None
    return ks, den


def _regions(rd: _Reader, raw_regions: list[Any], label: str, header: int | None, ref: str | None,
             start: Fraction | None) -> tuple[list[Region], bool]:
    """The regions of a table as written, each problem reported (and whether there was none)."""
    regions: list[Region] = []
    previous = start
    ok = True
    for i, rt in enumerate(raw_regions):
        rlabel = f"{label}, region {i + 1}"
        if not isinstance(rt, Mapping):
            rd.report("ZN103", f"{rlabel}: expected an inline table such as {{ upto = \"500\", max = \"300\" }}, got {as_written(rt)}", rd.loc.element("regions", header, i, "upto"))
            ok = False
            continue
        for key in rt:
            if key not in ("upto", "min", "max"):
                close = close_matches(key, ("upto", "min", "max"), n=1)
                hint = f"; did you mean {as_written(close[0])}?" if close else "; allowed keys: upto, min, max"
                rd.report("ZN101", f"{rlabel}: unknown key {as_written(key)}{hint}", rd.loc.element("regions", header, i, key))
                ok = False
        if "upto" not in rt:
            rd.report("ZN102", f"{rlabel}: missing upto (the region's upper bound on {ref or 'the reference axis'})", rd.loc.element("regions", header, i, "upto"))
            ok = False
            continue
        # spans are found only for a diagnostic: finding one reads the array's text
        upto = read_number(rd, rt["upto"], f"{rlabel}: upto", functools.partial(rd.loc.element, "regions", header, i, "upto"))
        lo = read_number(rd, rt["min"], f"{rlabel}: min",
                     functools.partial(rd.loc.element, "regions", header, i, "min")) if "min" in rt else None
        hi = read_number(rd, rt["max"], f"{rlabel}: max",
                     functools.partial(rd.loc.element, "regions", header, i, "max")) if "max" in rt else None
        if upto is None or ("min" in rt and lo is None) or ("max" in rt and hi is None):
            ok = False
            continue
        if lo is not None and hi is not None and lo > hi:
            rd.report("ZN122", f"{rlabel}: min {format_decimal(lo)} is greater than max {format_decimal(hi)}; the region would allow nothing", rd.loc.element("regions", header, i, "min"))
            ok = False
        if previous is not None and upto <= previous:
            prev_word = "from value" if i == 0 else "previous upto"
            rd.report("ZN121", f"{rlabel}: upto {format_decimal(upto)} is not greater than the {prev_word} {format_decimal(previous)}", rd.loc.element("regions", header, i, "upto"))
            ok = False
        previous = upto
        regions.append(Region(upto, lo, hi))
    return regions, ok


def _limits(rd: _Reader, zt: Mapping[str, Any], label: str, header: int | None, axes: tuple[str, ...],
            exclude: tuple[str, ...] = ()) -> tuple[Any, ...] | None:
    lows = zt.get("min", {})
    highs = zt.get("max", {})
    ok = True
    for key, raw in (("min", lows), ("max", highs)):
        if not isinstance(raw, Mapping):
            rd.report("ZN103", f"{label}: {key} must be a table of axis values such as {{ X = \"0\" }}, got {as_written(raw)}", rd.loc.key(key, header))
            ok = False
    if not ok:
        return None
    limits = []
    for axis in dict.fromkeys(list(lows) + list(highs)):
        if axis not in axes:
            rd.report("ZN110", f"{label}: unknown axis {as_written(axis)} in min/max; the machine's axes are {', '.join(axes)}", rd.loc.key(axis, header))
            ok = False
            continue
        if axis in exclude:
            rd.report("ZN111", f"{label}: axis {as_written(axis)} is in the polygon's plane and may not also have min/max", rd.loc.key(axis, header))
            ok = False
            continue
        # the spans found when a diagnostic needs them (start-up, boot44)
        lo = read_number(rd, lows[axis], f"{label}: min.{axis}", functools.partial(rd.loc.key, axis, header)) \
            if axis in lows else None
        hi = read_number(rd, highs[axis], f"{label}: max.{axis}",
                         functools.partial(rd.loc.key, axis, header, 1 if axis in lows else 0)) if axis in highs else None
        if (axis in lows and lo is None) or (axis in highs and hi is None):
            ok = False
            continue
        if lo is not None and hi is not None and lo > hi:
            rd.report("ZN122", f"{label}: min.{axis} {format_decimal(lo)} is greater than max.{axis} {format_decimal(hi)}", rd.loc.key(axis, header))
            ok = False
        limits.append((axis, lo, hi))
    return tuple(limits) if ok else None


def _box(rd: _Reader, zt: Mapping[str, Any], label: str, name: str, header: int | None, axes: tuple[str, ...],
         forbid: bool, point: ZonePoint) -> BoxZone | None:
    limits = _limits(rd, zt, label, header, axes)
    if limits is None:
        return None
    if not limits:
        rd.report("ZN120", f"{label}: a box needs at least one axis in min or max", rd.loc.key("kind", header))
        return None
    return BoxZone(name, limits, forbid, point)


def _polygon(rd: _Reader, zt: Mapping[str, Any], label: str, name: str, header: int | None,
             axes: tuple[str, ...], forbid: bool, point: ZonePoint) -> PolygonZone | None:
    plane = zt.get("plane")
    span = rd.loc.key("plane", header)
    if not (isinstance(plane, list) and len(plane) == 2 and all(isinstance(a, str) for a in plane)):
        rd.report("ZN102", f"{label}: plane must name two axes such as [\"X\", \"Z\"], got {as_written(plane)}", span)
        return None
    bad_axes = [a for a in plane if a not in axes]
    if bad_axes:
        rd.report("ZN110", f"{label}: plane axis {as_written(bad_axes[0])} is not one of the machine's axes ({', '.join(axes)})", span)
        return None
    if plane[0] == plane[1]:
        rd.report("ZN111", f"{label}: plane names axis {as_written(plane[0])} twice", span)
        return None
    raw_vertices = zt.get("vertices")
    vspan = rd.loc.key("vertices", header)
    if not isinstance(raw_vertices, list) or len(raw_vertices) < 3:
        rd.report("ZN123", f"{label}: vertices must list at least 3 points such as [[\"0\", \"0\"], ...], got {as_written(raw_vertices)}", vspan)
        return None
    vertices = []
    for i, v in enumerate(raw_vertices):
        if not (isinstance(v, list) and len(v) == 2):
            rd.report("ZN123", f"{label}: vertex {i + 1} must be a pair [{plane[0]}, {plane[1]}], got {as_written(v)}", vspan)
            return None
        a = read_number(rd, v[0], f"{label}: vertex {i + 1}", vspan)
        b = read_number(rd, v[1], f"{label}: vertex {i + 1}", vspan)
        if a is None or b is None:
            return None
        vertices.append((a, b))
    problem = polygon_problem(vertices)
    if problem:
        rd.report("ZN124", f"{label}: {problem}", vspan)
        return None
    limits = _limits(rd, zt, label, header, axes, exclude=tuple(plane))
    if limits is None:
        return None
    return PolygonZone(name, (plane[0], plane[1]), tuple(vertices), limits, forbid, point)


#: The simple-polygon check runs in Python (no numpy to import) while the sweep's candidate pairs (edges whose
#: ranges of X overlap) number at most ``PYTHON_PAIRS + PYTHON_PAIRS_PER_EDGE * n`` (``n`` edges); numpy's
#: vectorized sweep above it.  An outline has a few pairs an edge, and there the two cost about the same
#: (measured, poly45: a rippled circle of 10,000 vertices, 32,564 pairs, 52 ms in Python, 85 ms in numpy;
#: 100,000 vertices, 330,152 pairs, 0.50 s and 0.46 s, numpy's import not counted); numpy is kept for
#: outlines whose edges overlap in X by the many (a zigzag: some ``n**2 / 2`` pairs).
PYTHON_PAIRS = 20_000
PYTHON_PAIRS_PER_EDGE = 8


def polygon_problem(vertices: list[tuple[Fraction, Fraction]]) -> str | None:
    """Why a vertex list is not a simple polygon (exact), or None.

    A sweep along X: only pairs of edges whose bounding boxes overlap are
    tested (sorted by their low X, each edge meets the edges that start
    before its high X), and those exactly, in integers (the vertices scaled
    by their common denominator).  Every pair of edges that touch has
    overlapping boxes, so the answer is the all-pairs answer; the pair named
    is the first in vertex order, as an all-pairs scan would name it.
    The work is ``O(n log n)`` plus the pairs whose X ranges overlap, which
    for an outline is a few per edge.  Up to some such pairs an edge
    (:data:`PYTHON_PAIRS`) the sweep runs in Python on the exact X ranges
    (:func:`_touching_pairs`), above that in numpy
    (:func:`_touching_pairs_numpy`): the same pairs touch.
    """
    import math

    n = len(vertices)
    for i in range(n):
        if vertices[i] == vertices[(i + 1) % n]:
            return f"vertices {i + 1} and {(i + 1) % n + 1} are the same point"
    den = math.lcm(*{c.denominator for v in vertices for c in v})
    ints = [(v[0].numerator * (den // v[0].denominator), v[1].numerator * (den // v[1].denominator)) for v in vertices]
    (ax, ay), (bx, by) = ints[0], ints[1]
    if all((bx - ax) * (y - ay) == (by - ay) * (x - ax) for x, y in ints[2:]):
        return "the vertices lie on one line and enclose no area"
    bad = _touching_pairs(ints)
    if bad is None:
        bad = _touching_pairs_numpy(vertices, ints)
    if bad:
        i, j = min(bad)
        return (
            f"edge {i + 1} (vertex {i + 1} to {(i + 1) % n + 1}) and edge {j + 1} "
            f"(vertex {j + 1} to {(j + 1) % n + 1}) cross or overlap; "
            "the polygon must not intersect itself"
        )
    return None


def _touching_pairs(ints: list[tuple[int, int]]) -> list[tuple[int, int]] | None:
    """The pairs ``(i, j)``, ``i < j``, of edges (edge ``i``: vertex ``i`` to ``i + 1``) that meet other than at
    the vertex adjacent edges share (:func:`_segments_intersect`), in the integer vertices ``ints``; None when
    more pairs have overlapping ranges of X than :data:`PYTHON_PAIRS` allows (then numpy's sweep is quicker).

    Sorted by their low X, edge ``k`` overlaps in X exactly the edges after it that start at or before its high
    X (``bisect``); of those, the pairs that overlap in Y too are tested: every touching pair is among them."""
    from bisect import bisect_right

    n = len(ints)
    ends = [(ints[i], ints[(i + 1) % n]) for i in range(n)]
    x_lo = [min(a[0], b[0]) for a, b in ends]
    x_hi = [max(a[0], b[0]) for a, b in ends]
    y_lo = [min(a[1], b[1]) for a, b in ends]
    y_hi = [max(a[1], b[1]) for a, b in ends]
    order = sorted(range(n), key=x_lo.__getitem__)
    lo_sorted = [x_lo[i] for i in order]
    reach = [bisect_right(lo_sorted, x_hi[order[k]]) for k in range(n)]  # sorted edges k+1 .. reach-1 overlap
    if sum(r - k - 1 for k, r in enumerate(reach)) > PYTHON_PAIRS + PYTHON_PAIRS_PER_EDGE * n:
        return None
    bad = []
    for k in range(n):
        e = order[k]
        for f in order[k + 1:reach[k]]:
            if y_lo[e] <= y_hi[f] and y_lo[f] <= y_hi[e]:
                i, j = min(e, f), max(e, f)
                if _segments_intersect(*ends[i], *ends[j], j == i + 1 or (i == 0 and j == n - 1)):
                    bad.append((i, j))
    return bad


def _touching_pairs_numpy(vertices: list[tuple[Fraction, Fraction]], ints: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """:func:`_touching_pairs` vectorized (numpy), with no bound on the pairs: the candidates filtered in floats.

    Floats round monotonically, so a pair whose exact ranges touch still overlaps in floats: the filter never
    drops a touching pair; the pairs it keeps are decided exactly, in ``int64`` (Python integers when a
    coordinate reaches ``2**30``: the cross products must not overflow)."""
    import numpy as np

    n = len(vertices)
    big = max(max(abs(x), abs(y)) for x, y in ints) >= 2**30  # int64 cross products need |coordinate| < 2**30
    xy = np.array(ints, dtype=object if big else np.int64)
    nxt = np.roll(np.arange(n), -1)
    fx = np.array([float(v[0]) for v in vertices])
    fy = np.array([float(v[1]) for v in vertices])
    ex_lo, ex_hi = np.minimum(fx, fx[nxt]), np.maximum(fx, fx[nxt])
    ey_lo, ey_hi = np.minimum(fy, fy[nxt]), np.maximum(fy, fy[nxt])
    order = np.argsort(ex_lo, kind="stable")
    lo_sorted = ex_lo[order]
    reach = np.searchsorted(lo_sorted, ex_hi[order], side="right")  # sorted edges k+1 .. reach-1 start in range
    counts = np.maximum(reach - np.arange(n) - 1, 0)
    bad: list[tuple[int, int]] = []
    chunk = 1 << 20
    k0 = 0
    while k0 < n:
        k1 = k0 + 1
        total = int(counts[k0])
        while k1 < n and total + int(counts[k1]) <= chunk:
            total += int(counts[k1])
            k1 += 1
        ks = np.repeat(np.arange(k0, k1), counts[k0:k1])
        if ks.size:
            starts = np.cumsum(counts[k0:k1]) - counts[k0:k1]
            offs = np.arange(ks.size) - np.repeat(starts, counts[k0:k1])
            a, b = order[ks], order[ks + 1 + offs]
            keep = (ey_lo[a] <= ey_hi[b]) & (ey_lo[b] <= ey_hi[a])
            a, b = np.minimum(a[keep], b[keep]), np.maximum(a[keep], b[keep])
            hit = _edges_touch(xy, nxt, a, b, n)
            bad += zip(a[hit].tolist(), b[hit].tolist())
        k0 = k1
    return bad


def _edges_touch(xy: Any, nxt: Any, i: Any, j: Any, n: int) -> Any:
    """For edge pairs ``i < j`` (index arrays): do they meet other than at the vertex adjacent edges share?

    Exact in the integer (or Python-integer) coordinates ``xy``; the rules of
    :func:`_segments_intersect`, evaluated on arrays.
    """
    import numpy as np

    def orient(a: Any, b: Any, c: Any) -> Any:
        v = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        return (v > 0).astype(np.int64) - (v < 0).astype(np.int64)

    def between(a: Any, b: Any, c: Any) -> Any:
        return ((np.minimum(a[:, 0], b[:, 0]) <= c[:, 0]) & (c[:, 0] <= np.maximum(a[:, 0], b[:, 0]))
                & (np.minimum(a[:, 1], b[:, 1]) <= c[:, 1]) & (c[:, 1] <= np.maximum(a[:, 1], b[:, 1])))

    p1, p2, q1, q2 = xy[i], xy[nxt[i]], xy[j], xy[nxt[j]]
    adjacent = (j == i + 1) | ((i == 0) & (j == n - 1))
    o1, o2, o3, o4 = orient(p1, p2, q1), orient(p1, p2, q2), orient(q1, q2, p1), orient(q1, q2, p2)
    crossing = (o1 != o2) & (o3 != o4) & (o1 != 0) & (o2 != 0) & (o3 != 0) & (o4 != 0)
    touching = ((o1 == 0) & between(p1, p2, q1)) | ((o2 == 0) & between(p1, p2, q2)) \
        | ((o3 == 0) & between(q1, q2, p1)) | ((o4 == 0) & between(q1, q2, p2))
    # adjacent edges share one vertex; they are bad only if they overlap (fold back)
    p2_shared = np.all(p2 == q1, axis=1) | np.all(p2 == q2, axis=1)
    shared = np.where(p2_shared[:, None], p2, p1)
    other_q = np.where(np.all(q1 == shared, axis=1)[:, None], q2, q1)
    other_p = np.where(np.all(p2 == shared, axis=1)[:, None], p1, p2)
    fold = (orient(other_p, shared, other_q) == 0) & (between(shared, other_q, other_p)
                                                      | between(shared, other_p, other_q))
    return np.where(adjacent, fold, crossing | touching)


_Pt2 = tuple[Fraction, Fraction] | tuple[int, int]  # a vertex, or one scaled to integers (the sweep's)


def _orient(a: _Pt2, b: _Pt2, c: _Pt2) -> int:
    v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (v > 0) - (v < 0)


def _between(a: _Pt2, b: _Pt2, c: _Pt2) -> bool:
    return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(a[1], b[1])


def _segments_intersect(p1: _Pt2, p2: _Pt2, q1: _Pt2, q2: _Pt2, adjacent: bool) -> bool:
    o1, o2, o3, o4 = _orient(p1, p2, q1), _orient(p1, p2, q2), _orient(q1, q2, p1), _orient(q1, q2, p2)
    if adjacent:
        # adjacent edges share one vertex; they are bad only if they overlap (fold back)
        shared = p2 if p2 in (q1, q2) else p1
        other_q = q2 if q1 == shared else q1
        other_p = p1 if p2 == shared else p2
        return _orient(other_p, shared, other_q) == 0 and (
            _between(shared, other_q, other_p) or _between(shared, other_p, other_q)
        )
    if o1 != o2 and o3 != o4 and 0 not in (o1, o2, o3, o4):
        return True
    return (
        (o1 == 0 and _between(p1, p2, q1))
        or (o2 == 0 and _between(p1, p2, q2))
        or (o3 == 0 and _between(q1, q2, p1))
        or (o4 == 0 and _between(q1, q2, p2))
    )
