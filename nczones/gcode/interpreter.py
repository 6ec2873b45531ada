"""The G-code interpreter: evaluated blocks -> motion in machine coordinates.

The language layer (:mod:`nczones.gcode.program`) runs the program's control
(parameters, expressions, O-words, subprograms) and yields one
:class:`~nczones.gcode.blocks.Block` per executed block.  This module gives
the blocks their machine meaning with the Fanuc/LinuxCNC semantics and emits
:class:`~nczones.motion.Segment` values in **machine coordinates** (exact
rationals; millimetres, degrees for rotary axes), grouped into
:class:`~nczones.motion.MotionChunk` objects.

Invariants
----------
* Every number stays an exact ``Fraction``; inch values are converted with
  exactly 1 in = 25.4 mm.  No float ever enters a coordinate.
* ``machine = program + work offset (G54..G59.3) + G92/G52 offset + tool
  length`` (the tool length on the machine's tool axis only), so an
  incremental move moves the machine by exactly the programmed distance
  (LinuxCNC: changing an offset never moves the machine by itself).
* Blocks are executed in LinuxCNC's order of execution within a block
  (feed, tool, plane, units, tool length, coordinate system, distance mode,
  retract mode, G28/G30/G10/G92/G52, motion, stop).
* Never silent: a code that cannot be modelled exactly ends motion emission
  and is recorded in :attr:`Interpreter.unsupported` with its span and reason;
  motion before it is still emitted.  Block-level errors after that point are
  still reported (the blocks are still checked), but nothing is emitted.
* A user error raises :class:`~nczones.errors.GcodeError` with a ``GC2xx``
  (block/modal) or ``GC3xx`` (interpretation) code and the block's span.

The support table and every decision (G30 position, G64, G4 units, arcs off
their circle, ...) is in ``specs/gcode-support.md``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction

from ..errors import Diagnostic, GcodeError, InternalError, SourceSpan
from ..exact import to_float
from ..machine import DEFAULT_RETRACT, Machine
from ..motion import (
    PLANE_AXES,
    FrameRotation,
    MotionChunk,
    PathMode,
    Plane,
    ProgramFrame,
    Segment,
    SegmentKind,
)
from ..precompiled import dataclass, replace  # dataclasses' without importing it (start-up)
from . import (  # defined in the package, which loads this module lazily
    DEFAULT_ARC_TOLERANCE,
    DEFAULT_CHUNK_SIZE,
)
from .blocks import LANE_FULL, Block, Word
from .codes import (
    LANE_INTERPRETER,
    LANE_PLAIN,
    LINUXCNC_G,
    LINUXCNC_M,
    SPLINE_CODES,
    LaneCodes,
    claimed,
    modal_groups,
)
from .expr import EvalError, lcnc_integer
from .lexer import PlainBlock, fraction_raw, to_fraction
from .linuxcnc.state import (
    DEBUG_FLAG,
    DEBUG_FLAG_DEFAULT,
    StateParameter,
    StateTable,
    StateValue,
    linuxcnc_state_parameters,
)
from .passes import PassGuard
from .runner_common import DEFAULT_MAX_LOOP_ITERATIONS, MODAL_GROUP_NAMES, interpretation_spent
from .segments import dadd, make_segment, with_tool_deps

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from .linuxcnc.cutter_comp import CutterComp

_NAME_PENDING = "NURBS"

# The members of SegmentKind and Plane as plain names: reading a member off an Enum class costs about 0.25 us in
# Python 3.11 (the metaclass's ``__getattr__`` turns off the interpreter's quick attribute path), and a canned
# cycle's block reads a dozen of them
_LINE, _ARC, _RAPID, _DWELL = SegmentKind.LINE, SegmentKind.ARC, SegmentKind.RAPID, SegmentKind.DWELL
_XY, _XZ, _YZ = Plane.XY, Plane.XZ, Plane.YZ

__all__ = [
    "Interpreter",
    "Unsupported",
    "DEFAULT_ARC_TOLERANCE",
    "LINUXCNC_RADIUS_TOLERANCE",
    "MODAL_GROUP_NAMES",
    "PLAIN_CODES",
    "FULL_CODES",
]

#: Grbl's arc rule as nczones takes it (``arc_tolerance = "grbl"``).  Grbl's gcode.c accepts an I/J/K arc when
#: its end radius differs from its start radius by at most 0.005 mm, or by at most 0.5 mm and 0.1 % of the
#: radius; it then moves on the start radius and ends with a straight segment to the end point, where
#: nczones proves LinuxCNC's spiral.  nczones accepts the first part only (0.005 mm, which bounds that
#: difference); a larger mismatch is GC301.  R arcs: Grbl errors when the chord exceeds 2R, no tolerance.
GRBL_ARC_TOLERANCE = Fraction(5, 1000)

#: LinuxCNC's RADIUS_TOLERANCE_MM (0.00005 in): how far an R arc may fall short (arc_tolerance="linuxcnc").
LINUXCNC_RADIUS_TOLERANCE = Fraction(5, 100000) * Fraction(254, 10)
#: The squared I/J/K radius (mm**2) below which LinuxCNC refuses an arc ("Zero-radius arc": ``arc_data_ijk``
#: compares either radius with RADIUS_TOLERANCE, 0.00005 inch, in its doubles; rs274 runs 0.00127 mm and
#: refuses 0.00126), with 1e-9 of the radius more: a radius that close to the limit is refused here, never run
#: where LinuxCNC refuses it.
LINUXCNC_ZERO_RADIUS_SQ = (LINUXCNC_RADIUS_TOLERANCE * (1 + Fraction(1, 10**9))) ** 2

INCH = Fraction(254, 10)
_ZERO = Fraction(0)
_ONE = Fraction(1)
#: LinuxCNC G73/G83 rapid back-off (0.010 in; 0.254 mm in mm programs).
G83_RAPID_DELTA_MM = Fraction(254, 1000)
_TINY = Fraction(1, 10**12)

AXIS_LETTERS = "XYZABCUVW"
ROTARY = frozenset("ABC")
WORK_OFFSETS = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")
_WCS_BY_KEY = {540: "G54", 550: "G55", 560: "G56", 570: "G57", 580: "G58", 590: "G59",
               591: "G59.1", 592: "G59.2", 593: "G59.3"}

# G codes keyed by 10 * number (G59.1 -> 591); their modal groups from the dialect's code table.
GROUP_OF: dict[int, int] = modal_groups(LINUXCNC_G)


# Codes that cannot be modelled exactly: key -> reason.
UNSUPPORTED_G = {
    410: "cutter radius compensation (G41) offsets the path by the tool radius, and controls differ in how; "
         "if this machine is LinuxCNC, set cutter_compensation = \"linuxcnc\" in [machine] to model it",
    420: "cutter radius compensation (G42) offsets the path by the tool radius, and controls differ in how; "
         "if this machine is LinuxCNC, set cutter_compensation = \"linuxcnc\" in [machine] to model it",
    411: "dynamic cutter radius compensation (G41.1) offsets the path by the tool radius; if this machine is "
         "LinuxCNC, set cutter_compensation = \"linuxcnc\" in [machine] to model it",
    421: "dynamic cutter radius compensation (G42.1) offsets the path by the tool radius; if this machine is "
         "LinuxCNC, set cutter_compensation = \"linuxcnc\" in [machine] to model it",
    760: "threading cycle (G76) is not modelled",
    382: "probing (G38.2) stops at a position that depends on the part",
    383: "probing (G38.3) stops at a position that depends on the part",
    384: "probing (G38.4) stops at a position that depends on the part",
    385: "probing (G38.5) stops at a position that depends on the part",
    870: "back boring cycle (G87) is not modelled",
    880: "boring cycle with manual retract (G88) lets the operator move the spindle",
    432: "additional tool length offset (G43.2) is not modelled",
    70: "lathe diameter mode (G7) is not modelled",
    171: "plane G17.1 (UV) is not modelled",
    181: "plane G18.1 (WU) is not modelled",
    191: "plane G19.1 (VW) is not modelled",
    680: "coordinate rotation (G68) is not modelled",
    510: "scaling (G51) is not modelled",
    511: "mirroring (G51.1) is not modelled",
    500: "G50 means scaling cancel on some controls and coordinate setting on others",
    150: "polar coordinates (G15/G16) are not modelled",
    160: "polar coordinates (G15/G16) are not modelled",
    541: "extended work offsets (G54.1 P) are not in the machine file",
    650: "macro call (G65) was not expanded by the language layer",
    660: "modal macro call (G66) is not modelled",
    700: "lathe finishing cycle (G70) is not modelled",
    710: "lathe roughing cycle (G71) is not modelled",
    720: "lathe facing cycle (G72) is not modelled",
    711: "lathe roughing cycle (G71.1) is not modelled",
    721: "lathe facing cycle (G72.1) is not modelled",
    712: "lathe roughing cycle (G71.2) is not modelled",
    722: "lathe facing cycle (G72.2) is not modelled",
    740: "left-hand tapping cycle (G74) is not modelled",
    71: "cylindrical interpolation (G7.1) is not modelled",
    1070: "cylindrical interpolation (G107) is not modelled",
    120: "circular pocket cycle (G12) is not modelled",
    130: "circular pocket cycle (G13) is not modelled",
    220: "stored stroke check (G22) is not modelled",
    1121: "polar coordinate interpolation (G112) is not modelled",
}
# Harmless codes: no effect on the path.
#: Words LinuxCNC reads as integers within 0.0001 of one (``read_integer_value``: read_h, read_l, read_t).
_INTEGER_LETTERS = ("H", "L", "T")

_HARMLESS_M = {0, 1, 3, 4, 5, 7, 8, 9, 19, 48, 49, 50, 51, 52, 53, 60, 62, 63, 64, 65, 66, 67, 68,
               70, 71, 72}
_M_GROUP = modal_groups(LINUXCNC_M)
_NO_PLAN = object()
#: Spindle and coolant M codes: no effect on motion, and a plain move may carry one (Interpreter._lean), which
#: then keeps the spindle direction LinuxCNC's G84/G86/G33 checks read.
LEAN_M = claimed(LINUXCNC_M, LANE_PLAIN)
#: The codes the plain lane and the full interpreter claim and decline (the code table).
PLAIN_CODES = LaneCodes(LANE_PLAIN, LINUXCNC_G, LINUXCNC_M)
FULL_CODES = LaneCodes(LANE_INTERPRETER, LINUXCNC_G, LINUXCNC_M)
_CYCLES = {730, 810, 820, 830, 840, 850, 860, 890}
_AXIS_USERS = {100: "G10", 280: "G28", 300: "G30", 920: "G92", 520: "G52"}
#: Letters whose use LinuxCNC checks per block (Interpreter._check_word_users).
_USED_BY = frozenset("ABCDEHLPQ")


class StopProgram(Exception):
    """Internal: the program ended (M2/M30)."""


@dataclass(frozen=True, slots=True)
class Unsupported:
    """Why the interpretation is incomplete: a code nczones cannot model."""

    code: str
    reason: str
    span: SourceSpan | None

    def render(self) -> str:
        return f"{self.span if self.span else '<input>'}: unknown: {self.code}: {self.reason}"


def gkey(value: Fraction) -> int | None:
    d = value.denominator
    if d == 1:
        return value.numerator * 10
    n = value.numerator * 10
    if n % d:
        return None
    return n // d


_new = object.__new__
def qadd(a: Any, b: Any) -> Fraction:  # Fractions, read through their slots
    """``a + b`` for Fractions, with a shortcut for equal denominators (decimal inputs)."""
    if not b._numerator:
        same: Fraction = a
        return same
    da = a._denominator
    db = b._denominator
    if da == db:
        return to_fraction(a._numerator + b._numerator, da)
    return to_fraction(a._numerator * db + b._numerator * da, da * db)


def _qinch(a: Any) -> Fraction:  # a Fraction, read through its slots
    """``a * 25.4`` (inches to mm) by integer arithmetic."""
    return to_fraction(a._numerator * 127, a._denominator * 5)


def _qlt(a: Any, b: Any) -> bool:  # Fractions, read through their slots
    """``a < b`` for Fractions by integer cross-multiplication (denominators are positive)."""
    less: bool = a._numerator * b._denominator < b._numerator * a._denominator
    return less


if to_fraction is not fraction_raw:  # pragma: no cover - a Python whose Fraction has other slots
    def qadd(a: Any, b: Any) -> Fraction:  # noqa: F811
        total: Fraction = a + b
        return total

    def _qlt(a: Any, b: Any) -> bool:  # noqa: F811
        less: bool = a < b
        return less

    def _qinch(a: Any) -> Fraction:  # noqa: F811
        mm: Fraction = a * INCH
        return mm


def gname(key: int) -> str:
    return f"G{key // 10}" if key % 10 == 0 else f"G{key // 10}.{key % 10}"


def fmt_number(q: Fraction) -> str:
    from ..exact import format_decimal

    return format_decimal(q, places=6)


class Interpreter:
    """Modal state machine from blocks to machine-coordinate motion.

    Parameters
    ----------
    machine : Machine
        Axes, start position, reference position (G28/G30), work offsets,
        tool lengths and the initial modal state.
    file : str
        Name used in spans of derived diagnostics.
    arc_tolerance : Fraction
        Largest allowed difference (mm) between the radius at the start and
        the radius at the end of an I/J/K arc (and by which an R arc may be
        too short; in the LinuxCNC dialect at most LinuxCNC's own 0.00005 inch); beyond it the arc is an error
        GC301/GC302.
    track_dependencies : bool
        Fill ``deps_start``/``deps_end`` of every segment.
    param_ranges : iterable
        The parameters given as ranges: objects with ``name`` (``"G54.X"``,
        ``"H1"``, ``"start.Z"``), ``lo`` and ``hi`` (deviations from the
        machine file's values, Fractions) and optional ``lo_open``/``hi_open``
        (such as :class:`nczones.prover.ParamRange`).  Implies tracking.  A
        state parameter read whose value depends on one of them makes the
        interpretation unknown (:mod:`nczones.gcode.linuxcnc.state`).
    chunk_size : int
        Segments per emitted :class:`~nczones.motion.MotionChunk`.

    Examples
    --------
    >>> from nczones.machine import parse_machine
    >>> from nczones.gcode.interpreter import Interpreter, blocks_from_words
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X", "Y"]
    ... pulse = "0.001"
    ... [machine.rapid]
    ... X = "1000"
    ... Y = "1000"
    ... [machine.reference]
    ... X = "0"
    ... Y = "0"
    ... [offsets]
    ... G54 = { X = "100" }
    ... ''')
    >>> it = Interpreter(m)
    >>> segs = [s for c in it.run(blocks_from_words([("G0", "X1", "Y2"), ("G91", "G1", "X0.5", "F100")])) for s in c.segments()]
    >>> [(s.kind.name, [str(v) for v in s.end]) for s in segs]
    [('RAPID', ['101', '2']), ('LINE', ['203/2', '2'])]
    """

    def __init__(
        self,
        machine: Machine,
        *,
        file: str = "<program>",
        arc_tolerance: Fraction | str = DEFAULT_ARC_TOLERANCE,
        track_dependencies: bool = False,
        chunk_size: int = DEFAULT_CHUNK_SIZE,
        param_ranges: Iterable[Any] = (),
    ):
        #: "linuxcnc": accept I/J/K arcs exactly when LinuxCNC does (see linuxcnc_rejects_arc); "grbl": I/J/K
        #: arcs off by at most GRBL_ARC_TOLERANCE, R arcs not short at all (Grbl's gcode.c, see there)
        self.arc_rule = arc_tolerance if arc_tolerance in ("linuxcnc", "grbl") else "fixed"
        if self.arc_rule == "linuxcnc":
            arc_tolerance = LINUXCNC_RADIUS_TOLERANCE
        elif self.arc_rule == "grbl":
            arc_tolerance = GRBL_ARC_TOLERANCE
        elif not isinstance(arc_tolerance, Fraction) or arc_tolerance < 0:
            from ..exact import exact

            arc_tolerance = exact(arc_tolerance)
        self.machine = machine
        self.file = file
        self.arc_tolerance = Fraction(arc_tolerance)
        #: name -> (lo, hi, lo_open, hi_open): the deviation box of the parameters given as ranges
        self.param_box = {r.name: (Fraction(r.lo), Fraction(r.hi), bool(getattr(r, "lo_open", False)),
                                   bool(getattr(r, "hi_open", False))) for r in param_ranges}
        self.ranged = frozenset(self.param_box)
        #: name -> the deviation from the machine file at which this interpretation's nominal values lie
        self.param_centre = {r.name: Fraction(getattr(r, "centre", 0)) for r in param_ranges}
        #: (name, deviation) where a branch of the path switches inside the range (see _level_lt)
        self.branch_split: tuple[str, Fraction] | None = None
        self.track = bool(track_dependencies) or bool(self.param_box)
        self.chunk_size = max(1, int(chunk_size))
        self.axes: tuple[str, ...] = machine.axis_names
        self.naxes = len(self.axes)
        self.index = {a: i for i, a in enumerate(self.axes)}
        self.rotary = tuple(a in ROTARY for a in self.axes)
        self.tool_axis = self.index.get(machine.tool_axis) if machine.tool_axis else None
        n = self.naxes
        z = [_ZERO] * n
        # ---- modal state
        modal = set(machine.modal)
        self.inch = "G20" in modal
        self.absolute = "G91" not in modal
        self.arc_absolute = False  # G91.1 (LinuxCNC default)
        self.plane = _XZ if "G18" in modal else _YZ if "G19" in modal else _XY
        self.wcs = next((c for c in machine.modal if c in WORK_OFFSETS), "G54")
        self.feed_mode = 93 if "G93" in modal else 95 if "G95" in modal else 94
        self.motion: int | None = None
        self.feed = _ZERO  # program units per minute
        self.retract_r = self.initial_retract_r(modal)  # LinuxCNC: G99 unless the machine file says
        self.cycle_r: Fraction | None = None
        self.cycle_cc: Fraction | None = None
        self.cycle_p = _ZERO
        self.cycle_q: Fraction | None = None
        self.comp_on = False
        self.comp_just_off = False
        #: LinuxCNC cutter radius compensation, when the machine file asks for it (nczones.gcode.linuxcnc.cutter_comp)
        self._comp: CutterComp | None = None
        if getattr(machine, "cutter_compensation", "none") == "linuxcnc":
            from .linuxcnc.cutter_comp import CutterComp

            self._comp = CutterComp(self)
        self.tool_selected = 0
        self.tool_in_spindle = 0
        #: LinuxCNC's spindle state for the checks it makes: direction 1 (M3), -1 (M4), 0 (stopped), and the
        #: S value; None where nczones does not follow it (M72 restores them as LinuxCNC does).
        self.spindle_dir: int | None = 0
        self.spindle_speed: Fraction | None = _ZERO
        self.tlo = _ZERO
        #: the units (inch?) in force when the applied tool length was set: LinuxCNC 2.9's convert_length_units
        #: does not convert its tool offset, so a G43/G49 after a G20/G21 moves the position by the stale number
        self.tlo_inch: bool | None = None
        self.tool_register: int | None = None
        # ---- offsets (mm, machine axes)
        self.g5x = {name: list(machine.offset(name)) for name in WORK_OFFSETS}
        self.rot = {name: _ZERO for name in WORK_OFFSETS}  # G10 L2 R: XY rotation in degrees
        self._ix, self._iy = self.index.get("X", -1), self.index.get("Y", -1)  # -1: no such axis
        self.g92 = list(z)
        self.g92_params = list(z)
        self.g92_applied = False
        self.home = {280: tuple(machine.reference), 300: tuple(machine.reference)}
        self.tool_table: dict[int, tuple[Fraction, dict]] = {}  # G10 L1/L10/L11 writes
        self.tool_diameters_set: dict[int, Fraction] = {}  # G10 L1/L10/L11 R writes (mm)
        self.pos: Sequence[Fraction] = list(machine.start)  # a tuple once the first move is emitted
        # dependency tracking (per axis: {source: coefficient})
        self.dep_pos = [{"start": 1} for _ in range(n)]
        self.dep_g5x = {name: [{name: 1} for _ in range(n)] for name in WORK_OFFSETS}
        self.dep_g92: list[dict] = [{} for _ in range(n)]
        self.dep_g92_params: list[dict] = [{} for _ in range(n)]
        self.dep_home: dict[int, list[dict]] = {280: [{} for _ in range(n)], 300: [{} for _ in range(n)]}
        self.dep_tlo: dict = {}
        self.recompute_offsets()
        # ---- bookkeeping
        self.unset = {"units", "distance", "offset", "plane", "feed", "tool", "retract"}
        self.assumed: dict[str, str] = {}
        self.unsupported: list[Unsupported] = []
        #: program stops executed (M0, M1, M60) as (code, line), the first 100: the operator acts there
        self.stops: list[tuple[int, int]] = []
        self.blocks = 0
        self.segment_count = 0
        self.kind_counts = {k: 0 for k in SegmentKind}
        self.ended = False
        self.emitted: list[Segment] = []
        self._plans: dict = {}  # letters of a PlainBlock -> how the plain lane reads it (_plain_plan)
        self.block_index = 0  # the index of the block being executed
        self._init_block_tables(machine)
        self._declined = -1  # the index of the last block lane() declined
        self.span: SourceSpan | None = None
        # the state every block reads, as instance attributes (reading a class default is slower)
        self.machine_at = self.prerotation_xy = self.prerotation_xy_next = None
        self.spline_state = self.cycle_il = self.last_cycle = None
        self._noted_straight = False
        self.m73_saved = []

    @property
    def cutter_comp(self) -> CutterComp | None:
        """LinuxCNC cutter radius compensation's state, when the machine file asks for it."""
        return self._comp

    # ------------------------------------------------------------------ helpers
    def recompute_offsets(self) -> None:
        g5 = self.g5x[self.wcs]
        off = [g5[i] + self.g92[i] for i in range(self.naxes)]
        if self.tool_axis is not None:
            off[self.tool_axis] += self.tlo
        old = getattr(self, "off", None)
        self.off = off
        if self.cycle_il is not None and old is not None and off[self._cycle_il_axis] != old[self._cycle_il_axis]:
            # LinuxCNC keeps a modal cycle's initial level in program coordinates (cycle_il): a tool length,
            # G92 or work offset change between hole blocks moves it with the offsets
            self.cycle_il += off[self._cycle_il_axis] - old[self._cycle_il_axis]
            self._cycle_il_deps = {}
            if self.track:
                self.unknown("canned cycle", "an offset change while a canned cycle is modal moves its initial "
                              "level; not followed with parameter ranges")
        if self.rot[self.wcs] or self.prerotation_xy is not None:
            self._update_rotation()
        if self.track:
            deps = []
            for i in range(self.naxes):
                d = dadd(self.dep_g5x[self.wcs][i], self.dep_g92[i])
                if i == self.tool_axis:
                    d = dadd(d, self.dep_tlo)
                deps.append(d)
            self.dep_off = deps

    # ------------------------------------------------------------------ the program frame (reports)
    #: the frame segments carry (Segment.frame), made on the first motion after a change: a new ``self.off``
    #: list (every offset, tool length and work offset change makes one) or ``invalidate_frame`` (units,
    #: diameter mode, transforms)
    _frame: ProgramFrame | None = None
    _frame_off: Any = None

    def invalidate_frame(self) -> None:
        """State the program frame reads changed without a new ``self.off`` (G20/G21, G7/G8, a transform)."""
        self._frame = None

    def program_frame(self) -> ProgramFrame:
        """The program's coordinate frame now (:class:`~nczones.motion.ProgramFrame`), cached until it changes."""
        f = self._frame
        if f is None or self._frame_off is not self.off:
            f = self._frame = self.make_frame()
            self._frame_off = self.off
        return f

    def make_frame(self) -> ProgramFrame:
        """A new :class:`~nczones.motion.ProgramFrame` of the current state: ``machine = program + self.off``,
        XY rotated about the work offset after the G92 shift (LinuxCNC ``rotate_and_offset_pos``), X a
        diameter in G7."""
        rot = None
        r = self.rot[self.wcs]
        ix, iy = self._ix, self._iy
        if r and ix >= 0 and iy >= 0:
            t = to_float(r) * math.pi / 180.0  # as _update_rotation computes them
            g5 = self.g5x[self.wcs]
            rot = FrameRotation((self.axes[ix], self.axes[iy]), r, Fraction(math.cos(t)), Fraction(math.sin(t)),
                                (self.g92[ix], self.g92[iy]), (g5[ix], g5[iy]))
        diameter = ("X",) if getattr(self, "diameter_mode", False) and "X" in self.index else ()
        opaque = "cylindrical interpolation (G07.1): the program writes developed lengths" \
            if getattr(self, "cylinder", None) is not None else ""
        return ProgramFrame(self.wcs, tuple(self.off), rot, diameter, self.inch, opaque, tuple(self.g5x[self.wcs]))

    # ------------------------------------------------------------------ XY rotation (G10 L2 R)
    machine_at: tuple[Fraction, ...] | None = None  # where the machine really is, if not at self.pos
    prerotation_xy: list[Fraction] | None = None  # pre-rotation XY (program mm + G92) while a rotation is active
    prerotation_xy_next: list[Fraction] | None = None  # the pre-rotation XY of the target being emitted
    _rot_key: tuple | None = None
    _cs: tuple[float, float] = (1.0, 0.0)

    def _update_rotation(self) -> None:
        """Follow a change of offsets or rotation: the machine stays, the pre-rotation position is recomputed.

        LinuxCNC keeps the machine where it is and re-derives the program
        position by the inverse rotation (in doubles) when the active
        coordinate system, its offset or its rotation changes.
        """
        r = self.rot[self.wcs]
        if r == 0:
            self.prerotation_xy = None
            self._rot_key = None
            return
        ix, iy = self._ix, self._iy
        if ix < 0 or iy < 0:
            self.unknown("G10 R", f"coordinate system rotation R{fmt_number(r)} needs X and Y axes; this machine has "
                          f"{', '.join(self.axes)}")
            return
        if self.track:
            self.unknown("G10 R", "parameter ranges are not supported with a rotated coordinate system "
                          "(the position is not a sum of offsets)")
        if self.tool_axis in (ix, iy) and self.tlo:
            self.unknown("G10 R", "a tool length offset on X or Y with a rotated coordinate system is not modelled")
        g5 = self.g5x[self.wcs]
        key = (self.wcs, r, g5[ix], g5[iy])
        if key != self._rot_key:
            self._rot_key = key
            t = to_float(r) * math.pi / 180.0  # LinuxCNC D2R, in doubles as LinuxCNC computes
            self._cs = (math.cos(t), math.sin(t))
            self.prerotation_xy = list(self._rot_inv(self.pos[ix], self.pos[iy]))

    def _rot_fwd(self, ux: Fraction, uy: Fraction) -> tuple[Fraction, Fraction]:
        """Machine XY of a pre-rotation point (LinuxCNC ``rotate_and_offset_pos``, in doubles, taken exactly)."""
        c, s = self._cs
        x, y = to_float(ux), to_float(uy)
        g5 = self.g5x[self.wcs]
        return (Fraction((x * c - y * s) + to_float(g5[self._ix])),
                Fraction((x * s + y * c) + to_float(g5[self._iy])))

    def _rot_inv(self, mx: Fraction, my: Fraction) -> tuple[Fraction, Fraction]:
        """Pre-rotation XY (program + G92, mm) of a machine XY: rotation by -R in doubles, taken exactly."""
        c, s = self._cs
        g5 = self.g5x[self.wcs]
        x, y = to_float(mx - g5[self._ix]), to_float(my - g5[self._iy])
        return Fraction(x * c + y * s), Fraction(y * c - x * s)

    def _machine_xy(self, end: list[Fraction]) -> None:
        """Under rotation, a target given in machine coordinates (G53, G28 home) as LinuxCNC moves there.

        The interpreter turns it into program coordinates (inverse rotation)
        and the canon layer rotates them back, both in doubles.
        """
        if self.prerotation_xy is None:
            return
        ix, iy = self._ix, self._iy
        u = list(self._rot_inv(end[ix], end[iy]))
        end[ix], end[iy] = self._rot_fwd(u[0], u[1])
        self.prerotation_xy_next = u

    def error(self, code: str, message: str, word: Word | None = None) -> GcodeError:
        span = word.span if word is not None else self.span
        return GcodeError(Diagnostic(code, message, span))

    def _mm(self, v: Fraction, i: int) -> Fraction:
        if self.inch and not self.rotary[i]:
            return v * INCH
        return v

    def length_mm(self, v: Fraction) -> Fraction:
        return v * INCH if self.inch else v

    def unknown(self, code: str, reason: str, word: Word | None = None) -> None:
        span = word.span if word is not None else self.span
        if not self.unsupported:
            self.unsupported.append(Unsupported(code, reason, span))

    #: The most repetitions one block may make (a canned cycle's L/K, its pecks): ``max_loop_iterations``,
    #: set by :class:`~nczones.gcode.Interpretation`.
    max_repeats: int = DEFAULT_MAX_LOOP_ITERATIONS

    def too_many(self, name: str, what: str, count: int, word: Word | None = None) -> bool:
        """True (and unknown at ``word``) when a block would repeat ``count`` times, more than
        ``max_repeats``: checked before any repetition is made, so none is held in memory."""
        if count <= self.max_repeats:
            return False
        self.unknown(name, f"{what} repeats {count} times, more than {self.max_repeats} (max_loop_iterations, "
                     "--max-iterations); not interpreted further", word)
        return True

    def pass_guard(self, name: str) -> PassGuard:
        """The bounds of one lathe cycle's passes (:mod:`nczones.gcode.passes`): ``max_repeats`` passes and
        the watched run's budget."""
        return PassGuard(name, self.max_repeats, interpretation_spent)

    def budget_gone(self, name: str, what: str, word: Word | None = None) -> bool:
        """At each repetition of a block: True (and unknown, VF203, saying what was counted) once the watched
        run's budget is spent."""
        why = interpretation_spent()
        if why is None:
            return False
        self.unknown("VF203", f"{why}: {name} {what}; not interpreted further", word)
        return True

    def finish(self) -> None:
        """End of the program text: a spline curve still waiting for data makes the result unknown."""
        if self.spline_state is not None:
            self.unknown(_NAME_PENDING, _spline_pending(self))
            self.spline_state = None
        if self._comp is not None:
            self._comp.program_end()

    @property
    def stopped(self) -> bool:
        """True once an unsupported code ended motion emission."""
        return bool(self.unsupported)

    #: The dialect whose control's start-up state applies where the machine file's ``modal`` is silent.
    dialect = "linuxcnc"

    def initial_retract_r(self, modal: set[str]) -> bool:
        """True (G99, back to R) or False (G98, back to the initial level) at the start of a program: the
        machine file's ``modal`` if it names one, else the control's own start-up mode
        (:data:`~nczones.machine.DEFAULT_RETRACT`)."""
        if "G98" in modal or "G99" in modal:
            return "G99" in modal
        return DEFAULT_RETRACT[self.dialect] == "G99"

    def note_assumed(self, groups: tuple[str, ...]) -> None:
        for g in groups:
            if g in self.unset and g not in self.assumed:
                self.assumed[g] = self._current_code(g)

    def _current_code(self, group: str) -> str:
        return {
            "units": "G20" if self.inch else "G21",
            "distance": "G90" if self.absolute else "G91",
            "offset": self.wcs,
            "plane": f"G{int(self.plane)}",
            "feed": f"G{self.feed_mode}",
            "tool": "G49" if self.tool_register is None and self.tlo == 0 else "G43",
            "retract": "G99" if self.retract_r else "G98",
        }[group]

    def deps_tuple(self, deps: list[dict]) -> tuple[tuple[str, ...], ...]:
        out = []
        for i, d in enumerate(deps):
            names = self._dep_names(d, i)
            if names is None:
                return tuple(() for _ in deps)
            out.append(names)
        return tuple(out)

    def _dep_names(self, d: dict, i: int | None) -> tuple[str, ...] | None:
        """The sources of one coordinate (axis ``i``) as segments carry them; None (and unknown) when a
        source a range is given for has a coefficient other than 1."""
        names = []
        for k, v in d.items():
            if v != 1:
                if self.ranged and i is not None:
                    axis = self.axes[i]
                    if (k if k.startswith("H") else f"{k}.{axis}") not in self.ranged:
                        continue  # a fixed value: its coefficient does not matter
                self.unknown(
                    "dependencies",
                    f"the position depends on {k} with coefficient {v} (through G92/G10/G52 "
                    "arithmetic); parameter ranges cannot be expressed per segment",
                )
                return None
            names.append(k)
        return tuple(sorted(names))

    def initial_path_mode(self, machine: Machine) -> PathMode:
        """The path control mode at start: ``[machine] path_mode`` and ``path_tolerance`` (LinuxCNC: the INI's
        start-up ``G64 P<tolerance>``, whose Q defaults to P; interp_convert.cc ``convert_control_mode``)."""
        if machine.path_mode != "G64":
            return PathMode(False, None, _ZERO, "linuxcnc", machine.path_mode)
        tol = machine.path_tolerance
        if tol:
            return PathMode(True, tol, tol, "linuxcnc", f"G64 P{fmt_number(tol)}")
        return PathMode(True, None, _ZERO, "linuxcnc", "G64")

    def _init_block_tables(self, machine: Machine) -> None:
        """The per-block tables the proofs read besides the motion, and the path mode's numbers."""
        #: the path control mode (specs/path-modes.md) from each block index on: (first block, mode), in order
        self.path_mode = self.initial_path_mode(machine)
        self.path_modes: list[tuple[int, PathMode]] = [(-1, self.path_mode)]
        #: the tool the program put in the spindle (M6, M61) from each block index on: (first block, tool), in
        #: order; the tool solids hold it to the active tool length register (nczones.prover.solids)
        self.spindle_tools: list[tuple[int, int]] = []
        #: LinuxCNC's G61/G61.1/G64 and its P and Q numbers as written (program units), what M70/M73 save
        #: and M72 (or an M73 subroutine's return) restores when they differ (``restore_settings``)
        self.path_words: tuple[int, Fraction | None, Fraction | None] = self._initial_path_words(machine)

    def _initial_path_words(self, machine: Machine) -> tuple[int, Fraction | None, Fraction | None]:
        """The start-up mode as G-code numbers (the INI's start-up ``G64 P<tolerance>``, in the start-up units)."""
        if machine.path_mode != "G64":
            return (611 if machine.path_mode == "G61.1" else 610, None, None)
        tol = machine.path_tolerance
        number = tol / INCH if tol and self.inch else tol or None
        return (640, number, number)

    def _restore_path_mode(self, words: tuple[int, Fraction | None, Fraction | None]) -> None:
        """M72 / an M73 subroutine's return: LinuxCNC's restore_settings writes G61, G61.1 or ``G64 P Q`` when
        the saved numbers differ from the current ones, after restoring the units: the numbers are read in the
        restored units (rs274 2.9.0~pre1: ``G21 G64 P1``, ``G20``, ``M70``, ``G61``, ``M72`` sets the tolerance
        to 1 in inches)."""
        if words == self.path_words:
            return
        code, p, q = words
        if code != 640:
            self._control_mode(code, {})
            return
        written = " ".join(["G64"] + [f"{k}{fmt_number(v)}" for k, v in (("P", p), ("Q", q)) if v is not None])
        self._g64(p, q, f"{written} (restored)")

    def put_in_spindle(self, tool: int) -> None:
        """M6 / M61: ``tool`` is in the spindle from the current block on (``tool_in_spindle``, ``spindle_tools``)."""
        self.tool_in_spindle = tool
        table = self.spindle_tools
        if table and table[-1][0] == self.block_index:
            table[-1] = (self.block_index, self.tool_in_spindle)
        elif not table or table[-1][1] != self.tool_in_spindle:
            table.append((self.block_index, self.tool_in_spindle))

    def set_path_mode(self, mode: PathMode) -> None:
        """The path control mode from the current block on (its motion included)."""
        if mode != self.path_mode:
            self.path_mode = mode
            if self.path_modes[-1][0] == self.block_index:
                self.path_modes[-1] = (self.block_index, mode)
            else:
                self.path_modes.append((self.block_index, mode))

    def _control_mode(self, code: int, words: dict) -> None:
        """G61, G61.1, G64 [P] [Q] (LinuxCNC ``convert_control_mode``: P < 0 or absent is no tolerance, Q
        absent is P, in program units)."""
        if code != 640:
            self.set_path_mode(PathMode(False, None, _ZERO, "linuxcnc", "G61" if code == 610 else "G61.1"))
            self.path_words = (code, None, None)
            return
        written = " ".join(["G64"] + [w.text for k, w in sorted(words.items()) if k in "PQ" and w.text])
        self._g64(words["P"].value if "P" in words else None, words["Q"].value if "Q" in words else None, written)

    def _g64(self, p_number: Fraction | None, q_number: Fraction | None, written: str) -> None:
        """G64 with LinuxCNC's P and Q numbers as written (program units; None: absent)."""
        unit = INCH if self.inch else Fraction(1)
        p = p_number * unit if p_number is not None and p_number >= 0 else None
        q = q_number * unit if q_number is not None and q_number >= 0 else p
        self.set_path_mode(PathMode(True, p if p else None, q or _ZERO, "linuxcnc", written))
        self.path_words = (640, p_number, q_number)

    def emit(self, kind: SegmentKind, end: list[Fraction], *, feed: bool = False, derived: str = "",
              plane: Plane | None = None, clockwise: bool = False, centre: Any = None, radius: Any = None,
              turns: int = 0, dwell: Fraction | None = None,
              end_deps: list[dict] | None = None) -> None:
        start = self.pos
        if type(start) is not tuple:
            start = tuple(start)
        if self.machine_at is not None:  # after LinuxCNC's G84 outside G17 the machine is not where the interpreter thinks
            start = self.machine_at
            self.machine_at = None
        endt = tuple(end)
        fmm = None
        if feed and self.feed_mode == 94:
            fmm = self.feed * INCH if self.inch else self.feed
        ds: tuple = ()
        de: tuple = ()
        dt: tuple = ()
        if self.track:
            ds = self.deps_tuple(self.dep_pos)
            de = self.deps_tuple(end_deps if end_deps is not None else self.dep_pos)
            dt = self.tool_dep_names()
        if not self.unsupported:
            fr = self._frame
            if fr is None or self._frame_off is not self.off:
                fr = self.program_frame()
            seg = make_segment(kind, start, endt, self.axes, self.block_index, self.span, self.tlo, fmm,
                           plane, clockwise, centre, radius, turns, dwell, derived, self.tool_register,
                           ds, de, (), fr)
            if dt:
                seg = with_tool_deps(seg, dt)
            self.emitted.append(seg)
            self.segment_count += 1
            self.kind_counts[kind] += 1
        self.pos = endt
        if self.prerotation_xy is not None:
            if self.prerotation_xy_next is not None:
                self.prerotation_xy = self.prerotation_xy_next
            elif endt[self._ix] != start[self._ix] or endt[self._iy] != start[self._iy]:
                self.prerotation_xy = list(self._rot_inv(endt[self._ix], endt[self._iy]))
        self.prerotation_xy_next = None
        if end_deps is not None:
            self.dep_pos = end_deps

    def tool_dep_names(self) -> tuple[str, ...]:
        """The sources of the active tool length (``Segment.deps_tool``; unknown on a bad coefficient)."""
        if not self.dep_tlo:
            return ()
        return self._dep_names(self.dep_tlo, self.tool_axis) or ()

    # ------------------------------------------------------------------ parameters
    def bind_parameters(self, params: Any) -> None:
        """Provide the state parameters of :meth:`state_parameters` to the language layer.

        Every entry is computed on each read (the current position, offsets,
        tool, modes, ...); a read that depends on a parameter range, or of
        state nczones does not model, raises the language layer's "unknown"
        (GC395) at that word; an assignment to an entry is unknown too.
        """
        self._scopes = getattr(params, "scopes", None)
        params.set(DEBUG_FLAG, DEBUG_FLAG_DEFAULT)  # #5599, an ordinary parameter that starts at 1
        for key, entry in self.state_parameters().items():
            params.provide(key, self._state_reader(entry))
            params.guard(key, f"{_show_key(key)} ({entry.meaning}) is controller state; a program that assigns "
                              "it changes the controller in ways nczones does not follow")

    def state_parameters(self) -> StateTable:
        """The dialect's table of state parameters (:mod:`nczones.gcode.linuxcnc.state`); LinuxCNC's here."""
        return _LINUXCNC_STATE

    def _state_reader(self, entry: StateParameter) -> Any:
        def read():
            if self.m73_saved:
                self.m73_returns()
            got = entry.read(self)
            if got is None:
                raise EvalError("GC395", f"{_show_key(entry.key)} reads the {entry.meaning}, controller state "
                                         "nczones does not model")
            if type(got) is StateValue:
                if self.ranged:
                    hit = sorted(n for n, c in got.deps.items() if c and n in self.ranged)
                    if hit:
                        raise EvalError(
                            "GC395",
                            f"{_show_key(entry.key)} ({entry.meaning}) depends on the parameter "
                            f"range{'s' if len(hit) > 1 else ''} {', '.join(hit)}; nczones does not follow a range "
                            "through expressions, so the program is verified only up to this read")
                return got.value
            return got
        return read

    # the state the readers of nczones.gcode.linuxcnc.state see: (value, dependencies as parameter names)
    def _named_deps(self, deps: dict, i: int | None, sign: int = 1) -> dict[str, int]:
        if not self.track or not deps:
            return {}
        assert i is not None  # only a coordinate of an axis (the tool axis, for tool lengths) has sources
        axis = self.axes[i]
        return {(src if src.startswith("H") else f"{src}.{axis}"): sign * c for src, c in deps.items() if c}

    def state_work_offset(self, name: str, i: int) -> StateValue:
        """Work offset ``name`` (G54 ...) on axis ``i``, mm."""
        return StateValue(self.g5x[name][i], self._named_deps(self.dep_g5x[name][i], i))

    def state_g92(self, i: int) -> StateValue:
        """The stored G92 offset (what G92.3 restores), mm."""
        return StateValue(self.g92_params[i], self._named_deps(self.dep_g92_params[i], i))

    def state_home(self, k: int, i: int) -> StateValue:
        """The G28 (``k = 280``) or G30 (300) position, machine coordinates, mm."""
        return StateValue(self.home[k][i], self._named_deps(self.dep_home[k][i], i))

    def tool_diameter(self, tool: int) -> Fraction | None:
        """Tool ``tool``'s diameter, mm: what G10 L1/L10/L11 R set, else the machine file's ``[tool_diameters]``."""
        d = self.tool_diameters_set.get(tool)
        return d if d is not None else self.machine.tool_diameters.get(tool)

    def _compensated(self, i: int) -> tuple[bool, Fraction | None]:
        """While cutter compensation has moved, LinuxCNC's current point of a plane axis is the compensated one
        (``settings->current_x``: the last move's end offset by the radius, before the next corner adjusts it),
        not the programmed one: (True, that point in machine mm), (True, None) where nczones does not follow it
        exactly (rotation, parameter ranges, compensation not modelled: the read is then unknown), (False, None)
        off the plane or without compensation (the programmed point)."""
        comp = self._comp
        if not self.comp_on:
            return False, None
        if comp is None:
            return True, None  # G41/G42 not modelled: the run is unknown anyway; never the programmed point
        if not comp.active or comp.first:
            return False, None  # no compensated move yet (or radius 0): the programmed point
        in_plane, point = comp.current_point(i)
        if not in_plane:
            return False, None
        if self.prerotation_xy is not None or self.track:
            return True, None
        return True, point

    def state_machine_position(self, i: int) -> StateValue | None:
        """Where axis ``i`` is, machine coordinates, mm (degrees for rotary axes)."""
        comped, c = self._compensated(i)
        if comped:
            return None if c is None else StateValue(c, {})
        return StateValue(self.pos[i], self._named_deps(self.dep_pos[i], i))

    def state_program_position(self, i: int) -> StateValue | None:
        """Where axis ``i`` is in the current coordinate system (all offsets off), mm."""
        comped, c = self._compensated(i)
        if comped:
            return None if c is None else StateValue(c - self.off[i], {})
        if self.prerotation_xy is not None and i in (self._ix, self._iy):
            return StateValue(self.prerotation_xy[0 if i == self._ix else 1] - self.g92[i], {})
        return StateValue(self.pos[i] - self.off[i], self._named_deps(dadd(self.dep_pos[i], self.dep_off[i], -1), i)
                          if self.track else {})

    def state_applied_tool_length(self) -> StateValue:
        """The active tool length offset (G43), mm, on the tool axis."""
        return StateValue(self.tlo, self._named_deps(self.dep_tlo, self.tool_axis))

    def state_spindle_tool_length(self) -> StateValue:
        """The tool table's length of the tool in the spindle, mm (0 with no tool)."""
        tool = self.tool_in_spindle
        if tool in self.tool_table:
            length, deps = self.tool_table[tool]
            return StateValue(length, self._named_deps(deps, self.tool_axis))
        if tool == 0:
            return StateValue(_ZERO)
        return StateValue(self.machine.tool_length(tool), {f"H{tool}": 1})

    def state_ccomp(self) -> int | None:
        """400 (G40), 410 (G41) or 420 (G42); None (not known) when compensation is not modelled."""
        if not self.comp_on:
            return 400
        if self._comp is None or self._comp.side is None:
            return None
        from .linuxcnc.cutter_comp import LEFT

        return 410 if self._comp.side == LEFT else 420

    # ------------------------------------------------------------------ driver
    #: Whether the program may read the N of the last block (a Fanuc macro's #4114, kept in ``last["N"]``):
    #: the plain-move lane then keeps it too
    keeps_number = False
    last: dict[str, Any]  # (the Fanuc interpreter's: the last D F H M N words read, "N*": FanucRunner.number_alone)

    def run(self, blocks: Iterable[Block]) -> Iterator[MotionChunk]:
        """Interpret blocks in execution order, yielding motion chunks.

        Memory does not grow with the program: at most ``chunk_size``
        segments are held before they are handed on.
        """
        size = self.chunk_size
        inline = type(self).execute is Interpreter.execute
        for block in blocks:
            if self.ended:
                break
            if block is LANE_FULL:  # the lane says a chunk is full (a Fanuc lane's run of rows may be one item)
                if self.emitted:
                    yield MotionChunk(self.axes, None, objects=tuple(self.emitted), file=self.file)
                    self.emitted = []
                continue
            self.blocks += 1
            self.block_index = block.index
            self.span = block.span
            try:
                if inline and type(block) is PlainBlock and not self.m73_saved:
                    # execute() inlined (subclasses that wrap execute() go through it)
                    if block.index == self._declined or not self._plain(block.letters, block.values):
                        self._execute_general(block)
                    elif self.keeps_number and block.number is not None:
                        self.keep_number(block.number)  # (_execute_general's _record_block keeps it)
                else:
                    self.execute(block)
            except StopProgram:
                self.ended = True
            if len(self.emitted) >= size:
                yield MotionChunk(self.axes, None, objects=tuple(self.emitted), file=self.file)
                self.emitted = []
        if self.emitted:
            yield MotionChunk(self.axes, None, objects=tuple(self.emitted), file=self.file)
            self.emitted = []

    # ------------------------------------------------------------------ one block
    def execute(self, block: Block) -> None:
        """Execute one block (LinuxCNC order of execution)."""
        if self.m73_saved:
            self.m73_returns()
        if type(block) is PlainBlock and self._plain(block.letters, block.values):
            if self.keeps_number and block.number is not None:
                self.keep_number(block.number)  # (_execute_general's _record_block keeps it)
            return
        self._execute_general(block)

    def keep_number(self, number: Fraction) -> None:
        """The N of a block with an NC word, for a macro's read of the last sequence number (a Fanuc ``#4114``):
        it settles what an earlier line of its N alone left (``last["N*"]``, ``FanucRunner.number_alone``)."""
        last = self.last
        last["N"] = number
        if "N*" in last:
            del last["N*"]

    def _split_words(
        self, block: Block
    ) -> tuple[list[tuple[int, Word]], list[tuple[int, Word]], dict[str, Word], list[tuple[int, Word]]]:
        """A block's words as (G codes as (key, word), M codes as (number, word), the other words by letter,
        axis words as (axis index, word)); GC202/GC203/GC204 for a G or M code no control has, an axis the
        machine lacks, a letter twice."""
        gcodes: list[tuple[int, Word]] = []
        mcodes: list[tuple[int, Word]] = []
        words: dict[str, Word] = {}
        axis_words: list[tuple[int, Word]] = []
        for w in block.words:
            letter = w.letter
            if letter == "G":
                k = gkey(w.value)
                if k is None:
                    raise self.error("GC202", f"unknown G code {w.text or 'G' + str(w.value)}: G codes have at most one decimal", w)
                gcodes.append((k, w))
            elif letter == "M":
                mcodes.append((self._m_number(w), w))
            else:
                if letter in words:
                    raise self.error("GC204", f"two {letter} words in one block ({words[letter].text or letter} and {w.text or letter}); a letter may appear once", w)
                words[letter] = w
                if letter in AXIS_LETTERS:
                    i = self.index.get(letter)
                    if i is None:
                        raise self.error(
                            "GC203",
                            f"axis word {w.text or letter} names axis {letter}, which this machine does not have "
                            f"(axes: {', '.join(self.axes)})",
                            w,
                        )
                    axis_words.append((i, w))
        return gcodes, mcodes, words, axis_words

    def _m_number(self, w: Word) -> int:
        """An M word's number.  LinuxCNC reads it as an integer within 0.0001 (``read_m`` ->
        ``read_integer_value``: ``M[3.00001]`` is M3, ``M[3.0001]`` "Non integer value for integer") and refuses a
        negative one ("Negative m code used").  One above 199 is refused only when the INI remaps no such M code
        (``m_remapped`` is looked up first: ``M428`` of LinuxCNC's own configurations): it stays unknown here."""
        if self.dialect != "linuxcnc":
            if w.value.denominator != 1:
                raise self.error("GC202", f"unknown M code {w.text or w.value}: M codes are integers", w)
            return w.value.numerator
        n = lcnc_integer(w.value)
        if n is None:
            raise self.error("GC202", f"M code {w.text or w.value} is not an integer: LinuxCNC reads an M number "
                             f"within 0.0001 of an integer (its error: Non integer value for integer)", w)
        if n < 0:
            raise self.error("GC202", f"negative M code {w.text or w.value} (LinuxCNC's error: Negative m code used)",
                             w)
        return n

    def _execute_general(self, block: Block) -> None:
        """:meth:`execute` for a block the plain-move lane did not take."""
        messages = getattr(block, "messages", ())
        if messages:
            for msg in messages:
                if msg.startswith("ABORT,"):
                    # LinuxCNC's (abort, ...): the program stops with this text before the block runs
                    raise self.error("GC305", f"the program aborts here (LinuxCNC (ABORT, ...)): {msg[6:].strip()}")
        gcodes, mcodes, words, axis_words = self._split_words(block)
        for letter in _INTEGER_LETTERS:
            w = words.get(letter)
            if w is not None and w.value.denominator != 1:
                n = lcnc_integer(w.value)  # LinuxCNC read_integer_value: T[2.00001] is T2
                if n is not None:
                    words[letter] = replace(w, value=Fraction(n))
        polar = "@" in words or "^" in words
        if axis_words and not polar and len(gcodes) <= 1 and len(mcodes) <= 1 and not self.track \
                and self.machine_at is None \
                and self._lean(gcodes[0][0] if gcodes else None, mcodes[0][0] if mcodes else None, words.get("F"),
                               len(words) - len(axis_words) - ("F" in words) - ("S" in words), words.get("S")):
            self._lean_move(tuple((k, i) for k, (i, _w) in enumerate(axis_words)), [w.value for _i, w in axis_words])
            return
        # ---- modal group checks
        groups: dict[int, tuple[int, Word]] = {}
        for k, w in gcodes:
            g = GROUP_OF.get(k)
            if g is None:
                if k in UNSUPPORTED_G:
                    g = 100 + k
                else:
                    raise self.error("GC202", f"unknown G code {gname(k)} (written {w.text or gname(k)}); see specs/gcode-support.md for the supported codes", w)
            if g in groups:
                if g == 1 and 800 in (k, groups[g][0]):
                    # LinuxCNC's read_g: G80 beside another motion code is dropped (either order, or G80 twice)
                    if k == 800:
                        continue
                else:
                    raise self.error("GC201", f"{gname(groups[g][0])} and {gname(k)} are in the same modal group; a block may contain only one of them", w)
            groups[g] = (k, w)
        mgroups: dict[int, tuple[int, Word]] = {}
        for k, w in mcodes:
            g = _M_GROUP.get(k, 1000 + k)
            if g in mgroups and not (g == 8 and {k, mgroups[g][0]} == {7, 8}):
                raise self.error("GC201", f"M{mgroups[g][0]} and M{k} are in the same modal group; a block may contain only one of them", w)
            mgroups[g] = (k, w)
        if len(mcodes) > 4:
            raise self.error("GC206", f"{len(mcodes)} M words in one block; at most 4 are allowed", mcodes[4][1])
        g0 = groups.get(0)
        g1 = groups.get(1)
        if polar and g0 and g0[0] in _AXIS_USERS:
            raise self.error("GC205", f"polar coordinates (@, ^) can only be used for motion, not with {gname(g0[0])}",
                             words.get("@") or words["^"])
        if g0 and g1 and g0[0] in _AXIS_USERS and g1[0] not in (800,) and axis_words:
            raise self.error("GC205", f"{gname(g0[0])} and {gname(g1[0])} both use the axis words of the block; write them in separate blocks", g1[1])
        if g1 and g1[0] == 800 and axis_words and not (g0 and g0[0] in _AXIS_USERS):
            raise self.error("GC205", "G80 cancels the canned cycle and cannot take axis words; write the motion in a separate block", axis_words[0][1])
        # R word without a user
        if "R" in words:
            motion_to_be = g1[0] if g1 else self.motion
            uses_r = (motion_to_be in (20, 30, 62) or motion_to_be in _CYCLES) and (g1 is not None or axis_words or g0 is None) \
                or (g0 and g0[0] == 100) or (groups.get(13, (0,))[0] == 640) or any(k == 19 for k, _ in mcodes)
            unknown_code = any(k in UNSUPPORTED_G for k, _ in gcodes) or any(
                k not in _HARMLESS_M and k not in (2, 30, 6, 61, 98, 99) for k, _ in mcodes)
            if not uses_r and not unknown_code and not self.unsupported:  # after unknown the mode is unknown
                raise self.error("GC204", f"R word {words['R'].text or 'R'} with no G code that uses it (R is used by G2/G3, canned cycles and G10)", words["R"])
        if "R" in words and 19 in {k for k, _ in mcodes} and groups.get(13, (0,))[0] == 640:
            raise self.error("GC204", "R word is ambiguous in a block with both G64 and M19; write them in separate blocks", words["R"])
        if not self.unsupported and not words.keys().isdisjoint(_USED_BY):
            self._check_word_users(gcodes, mcodes, groups, words, axis_words)
        self._check_needed_words(g1, groups, words, axis_words)
        # unsupported codes: stop emitting, keep checking blocks
        for k, w in gcodes:
            if k in UNSUPPORTED_G:
                if k in (410, 420, 411, 421) and self._comp is not None:
                    continue
                self.unknown(gname(k), UNSUPPORTED_G[k], w)
                if k in (410, 420, 411, 421):
                    self.comp_on = True
        for k, w in mcodes:
            if k not in _HARMLESS_M and k not in (2, 30, 6, 61, 73, 98, 99):
                self.unknown(f"M{k}", f"M{k} is not a code nczones models (user M codes may run anything)", w)
            if k in (0, 1, 60) and len(self.stops) < 100:
                self.stops.append((k, w.span.line if w.span is not None else 0))
        if self._comp is not None and self._comp.side is not None:
            self._comp.check_block(groups, mcodes, words, axis_words, self.motion)
        # ---- order of execution
        # 2-3: feed mode, F
        if 5 in groups:
            self.feed_mode = groups[5][0] // 10
            self.unset.discard("feed")
            if self.feed_mode in (94, 95):
                self.feed = _ZERO  # LinuxCNC convert_feed_mode: G94 and G95 set the feed rate to 0
                self.feed_inverse_rate = False
        if "F" in words:
            f = words["F"].value
            if f < 0:
                raise self.error("GC209", f"negative feed rate {words['F'].text}; F must be 0 or more", words["F"])
            if self.feed_mode != 93:
                # LinuxCNC execute_block calls convert_feed_rate only outside G93: an inverse-time F is the block's
                # own and leaves the feed rate (#<_feed>, what M70 saves) at its G94/G95 value
                self.feed = f
                self.feed_inverse_rate = False
        if "S" in words:
            sv = words["S"].value
            if sv < 0:
                raise self.error("GC209", f"negative spindle speed {words['S'].text}; S must be 0 or more", words["S"])
            self.spindle_speed = sv
        # 5-6: tool select and change
        if "T" in words:
            t = words["T"].value
            if t.denominator != 1 or t < 0:
                raise self.error("GC209", f"tool number {words['T'].text} must be a non-negative integer", words["T"])
            self.tool_selected = int(t)
        mset = {k for k, _ in mcodes}
        if 6 in mset:
            self._tool_change_moves()
            if self.tool_selected == 0 and self.tool_in_spindle != 0:
                self.spindle_slot_stale = True
            elif self.tool_selected != 0:
                self.spindle_slot_stale = False
            self.put_in_spindle(self.tool_selected)
            self.spindle_dir = 0  # LinuxCNC convert_tool_change stops the spindle (TOOL_CHANGE_WITH_SPINDLE_ON off)
        for k, d in ((3, 1), (4, -1), (5, 0), (19, 0)):
            if k in mset:
                self.spindle_dir = d
        if 61 in mset:
            q = words.get("Q")
            if q is None or q.value.denominator != 1 or q.value < 0:
                raise self.error("GC208", "M61 needs a Q word with a non-negative integer tool number", mgroups[6][1])
            self.put_in_spindle(int(q.value))
            self.spindle_slot_stale = True  # M61 sets the number only: the interpreter's spindle entry stays what it was
        if mgroups.get(10) is not None:
            # LinuxCNC convert_m: M70-M73 after F, S, T and M6 of the block, before its G codes and motion
            self._modal_context(mgroups[10][0], mgroups[10][1], bool(gcodes or axis_words or len(mcodes) > 1))
        # 10: dwell
        if g0 and g0[0] == 40:
            p = words.get("P")
            if p is None:
                raise self.error("GC208", "G4 needs a P word with the dwell time in seconds", g0[1])
            if p.value < 0:
                raise self.error("GC209", f"dwell time {p.text} is negative", p)
            if "X" in words and g1 is None:
                self.unknown("G4 X", "G4 with an X word dwells on Fanuc controls but moves X on LinuxCNC", words["X"])
            if self._comp is not None:
                self._comp.dwell(p.value)
            else:
                self.emit(_DWELL, list(self.pos), dwell=p.value)
        # 11: plane
        if 2 in groups:
            k = groups[2][0]
            if k in (170, 180, 190):
                self.plane = {170: _XY, 180: _XZ, 190: _YZ}[k]
            self.unset.discard("plane")
        # 12: units
        if 6 in groups:
            self._set_units(groups[6][0] == 200)
            self.unset.discard("units")
        # 13: cutter comp
        if 7 in groups and self._comp is not None:
            self._comp.select(groups[7][0], groups[7][1], words)
        elif 7 in groups:
            if groups[7][0] == 400:
                if self.comp_on:
                    self.comp_just_off = True
                self.comp_on = False
        # 14: tool length
        if 8 in groups:
            self._tool_length(groups[8], words)
        # 15-16: coordinate system; path mode after the units and M70 (``G20 G64 P0.01``: 0.01 inch, as convert_g)
        if 12 in groups:
            self.wcs = _WCS_BY_KEY[groups[12][0]]
            self.unset.discard("offset")
            self.recompute_offsets()
        if 13 in groups:
            self._control_mode(groups[13][0], words)
        # 17: distance modes
        if 3 in groups:
            self.absolute = groups[3][0] == 900
            self.unset.discard("distance")
        if 4 in groups:
            self.arc_absolute = groups[4][0] == 901
        # 18: retract mode
        if 10 in groups:
            self.retract_r = groups[10][0] == 990
            self.unset.discard("retract")
        # 19: G28/G30, G10, G92, G52
        nonmodal_uses_axes = False
        if g0 and g0[0] != 40:
            k = g0[0]
            nonmodal_uses_axes = k in _AXIS_USERS
            if k in (280, 300):
                self._home(k, axis_words, g0[1])
            elif k in (281, 301):
                self.home[k - 1] = tuple(self.pos)
                self.dep_home[k - 1] = [dict(d) for d in self.dep_pos]
            elif k == 100:
                self._g10(words, axis_words, g0[1])
            elif k == 920:
                self._g92(axis_words, g0[1])
            elif k in (921, 922):
                self.g92 = [_ZERO] * self.naxes
                self.dep_g92 = [{} for _ in range(self.naxes)]
                self.g92_applied = False
                if k == 921:
                    self.g92_params = [_ZERO] * self.naxes
                    self.dep_g92_params = [{} for _ in range(self.naxes)]
                self.recompute_offsets()
            elif k == 923:
                self.g92 = list(self.g92_params)
                self.dep_g92 = [dict(d) for d in self.dep_g92_params]
                self.g92_applied = True
                self.recompute_offsets()
            elif k == 520:
                self._g52(axis_words, g0[1])
        if 8 in groups and groups[8][0] == 431 and g1 is None:
            nonmodal_uses_axes = True  # the axis words are G43.1's offsets, not a move (LinuxCNC motion_to_be)
        # 20: motion
        g53 = bool(g0 and g0[0] == 530)
        if polar:
            axis_words = self._polar(words, axis_words, g1, g53, nonmodal_uses_axes)
        if g1:
            k = g1[0]
            if k not in _CYCLES:
                self.cycle_il = None
                self.last_cycle = None
            if self.spline_state is not None and k not in (52, 53, 62):
                self.unknown(gname(k), _spline_pending(self) + f" (motion changed to {gname(k)})", g1[1])
                self.spline_state = None
            if k == 800:
                self.motion = None
            elif k in UNSUPPORTED_G:
                self.motion = None
            else:
                self.motion = k
        if ("I" in words or "J" in words or "K" in words) and self.motion not in (20, 30, 330, 331) and not self.unsupported \
                and not (g0 and g0[0] == 100) and not (self.motion in (50, 51) and "K" not in words) \
                and not (self.motion == 62 and "I" not in words and "J" not in words):
            w = words.get("I") or words.get("J") or words["K"]
            raise self.error("GC204", f"{w.text or w.letter} word with no G2 or G3 to use it", w)
        moving = bool(axis_words or (g1 and g1[0] in (20, 30)))
        if moving and not nonmodal_uses_axes and self.motion is not None:
            if self.motion in (20, 30) and self.comp_just_off:
                raise self.error("GC326", "the move just after turning off cutter compensation (G40) must be straight, not an arc", (g1[1] if g1 else axis_words[0][1]))
            self.comp_just_off = False
        if not nonmodal_uses_axes:
            if g53 and not (g1 and g1[0] in (0, 10)) and not (self.motion in (0, 10) and not g1):
                raise self.error("GC207", "G53 needs G0 or G1 in the same block (or active)", g0[1] if g0 else None)
            if axis_words or (g1 and g1[0] not in (800,) and g1[0] not in UNSUPPORTED_G):
                if self.unsupported and not g1 and not axis_words:
                    pass
                else:
                    self._motion_block(block, axis_words, words, g1, g53)
        if self.machine_at is not None and (6 in mset or 61 in mset):
            # after a tool change LinuxCNC re-reads where the machine is (read_inputs: refresh_actual_position),
            # e.g. the compensated point G40 left the tool at, or where G84 outside G17 left it
            self.pos = list(self.machine_at)
            self.machine_at = None
        # 21: stop
        if self._comp is not None:
            if 2 in mset or 30 in mset:
                self._comp.program_end()
            elif 0 in mset or 1 in mset or 60 in mset:
                self._comp.stop()
        if 2 in mset or 30 in mset:
            raise StopProgram

    def lane_for_blocks(self):
        """:meth:`lane` for the language layer's ``iter_blocks(..., lane=...)``, or None for an
        interpreter whose :meth:`execute` is not this class's (its blocks must reach it)."""
        return self.lane if type(self).execute is Interpreter.execute else None

    def lane(self, letters: str, values: tuple, span: SourceSpan, index: int) -> int:
        """Execute a plain block handed over by the language layer without a Block object (see
        :func:`~nczones.gcode.program.iter_blocks`, ``lane``): 0 declined (nothing changed: the block
        is then yielded to :meth:`run`), 1 executed, 2 executed and a chunk is full (the layer then
        yields :data:`~nczones.gcode.blocks.LANE_FULL`, for :meth:`run` to hand the chunk on)."""
        if self.ended or self.m73_saved:
            return 0
        self.block_index = index
        self.span = span
        self.blocks += 1
        if not self._plain(letters, values):
            self.blocks -= 1
            self._declined = index  # run() then takes the block to the general path at once
            return 0
        return 2 if len(self.emitted) >= self.chunk_size else 1

    def _plain(self, letters: str, values: tuple) -> bool:
        """Execute a :class:`~nczones.gcode.lexer.PlainBlock` by the plain-move lane if it is one.

        Returns False, having changed nothing, when the block needs the
        general path (which then reads its words).
        """
        if self.track or self.machine_at is not None:
            return False
        plan = self._plans.get(letters, _NO_PLAN)
        if plan is _NO_PLAN:
            plan = self._plain_plan(letters)
        if plan is None:
            return False
        axis_at, gk, mk, fk, sk = plan
        g = m = None
        if gk >= 0:
            v = values[gk]
            if v._denominator != 1:
                return False
            g = v._numerator * 10
        if mk >= 0:
            v = values[mk]
            if v._denominator != 1:
                return False
            m = v._numerator
        if not self._lean(g, m, values[fk] if fk >= 0 else None, 0, values[sk] if sk >= 0 else None):
            return False
        self._lean_move(axis_at, values)
        return True

    def _plain_plan(self, letters: str) -> tuple | None:
        """How the plain lane reads a block with these letters: ``((value index, axis index), ...)``
        and the value indices of G, M and F (-1: absent); None if the letters rule the lane out
        (no axis, a repeated letter, a letter other than axes, G, M, F, S)."""
        plan = None
        if len(set(letters)) == len(letters) and all(c in self.index or c in "GMFS" for c in letters):
            axis_at = tuple((k, self.index[c]) for k, c in enumerate(letters) if c in self.index)
            if axis_at:
                plan = (axis_at, letters.find("G"), letters.find("M"), letters.find("F"), letters.find("S"))
        if len(self._plans) < 4096:
            self._plans[letters] = plan
        return plan

    def _check_needed_words(self, g1: tuple[int, Word] | None, groups: dict[int, tuple[int, Word]],
                            words: dict[str, Word], axis_words: list[tuple[int, Word]]) -> None:
        """GC208 for a probing move without axis words, and for G96 without S (LinuxCNC: ``interp_check.cc``
        ``check_other_codes``, NCE_S_WORD_MISSING_WITH_G96; rs274 2.9 stops there)."""
        if g1 and g1[0] in (382, 383, 384, 385) and not axis_words:
            raise self.error("GC208", f"{gname(g1[0])} without axis words: a probing move needs a target", g1[1])
        if 14 in groups and groups[14][0] == 960 and "S" not in words and self.dialect == "linuxcnc":
            raise self.error("GC208", "G96 without an S word (the surface speed): LinuxCNC refuses the block "
                                      "(\"S word missing with G96\"); write G96 S<speed>", groups[14][1])

    def _check_word_users(self, gcodes: list[tuple[int, Word]], mcodes: list[tuple[int, Word]],
                          groups: dict[int, tuple[int, Word]], words: dict[str, Word],
                          axis_words: list[tuple[int, Word]]) -> None:
        """GC204 for a D, E, H, L, P or Q word that no code of the block uses, and for an A, B or C word in a
        canned cycle: LinuxCNC's ``check_other_codes`` (``interp_check.cc``), which rejects such a block.

        The motion a word may belong to is LinuxCNC's ``motion_to_be``: the block's own G0-G89, else the
        active motion mode when the block has axis words (and no G10/G28/G30/G52/G92, which take them, and
        no G43.1), else none.  Where LinuxCNC versions differ (2.9 refuses D with G70, G73 and G83; later
        versions take it), the block is accepted.  After an unknown code the block is left alone, as for R.
        """
        if any(k in UNSUPPORTED_G for k, _ in gcodes) or any(
                k not in _HARMLESS_M and k not in (2, 30, 6, 61, 98, 99) for k, _ in mcodes):
            return
        k0 = groups[0][0] if 0 in groups else None
        comp = groups[7][0] if 7 in groups else None
        length = groups[8][0] if 8 in groups else None
        control = groups[13][0] if 13 in groups else None
        spindle_mode = groups[14][0] if 14 in groups else None
        if 1 in groups:
            motion = groups[1][0]
        elif k0 in _AXIS_USERS or length == 431:
            motion = None
        elif axis_words:
            motion = self.motion
        else:
            motion = None
        ms = {k for k, _ in mcodes}

        def refuse(letter: str, users: str) -> None:
            w = words[letter]
            raise self.error("GC204", f"{w.text or letter} word with no {users} to use it; LinuxCNC refuses the "
                                      "block", w)

        for letter in "ABC":
            if letter in words and motion is not None and (810 <= motion <= 890 or motion in (730, 740)):
                raise self.error("GC204", f"{words[letter].text or letter} word in a canned cycle "
                                          f"({gname(motion)}); LinuxCNC refuses the block", words[letter])
        if "D" in words and comp not in (410, 411, 420, 421) and spindle_mode != 960 \
                and motion not in (700, 710, 711, 712, 720, 721, 722, 730, 830):
            refuse("D", "G41, G41.1, G42, G42.1, G70-G72, G73, G83 or G96")
        if "E" in words and motion not in (760, 330, 331, 700) and ms.isdisjoint((66, 67, 68)):
            refuse("E", "G70, G76, G33, G33.1, M66, M67 or M68")
        if "H" in words and length not in (430, 432) and motion != 760:
            refuse("H", "G43, G43.2 or G76")
        if "L" in words and not (motion is not None and (810 <= motion <= 890 or motion in (730, 760, 52, 62))) \
                and k0 != 100 and comp not in (410, 411, 420, 421) and 66 not in ms:
            refuse("L", "G10, cutter compensation, canned cycle, M66 or NURBS code")
        if "P" in words and k0 not in (100, 40) and control != 640 \
                and motion not in (760, 820, 860, 880, 890, 50, 52, 62, 700, 20, 30, 740, 840) \
                and ms.isdisjoint((50, 51, 52, 53, 62, 63, 64, 65, 66, 19)):
            refuse("P", "G2, G3, G4, G5, G5.2, G6.2, G10, G64, G70, G74, G76, G82, G84, G86, G88, G89, "
                        "M19, M50-M53 or M62-M66")
        if "Q" in words and k0 != 100 and control != 640 \
                and motion not in (830, 730, 50, 62, 760, 700, 710, 711, 712, 720, 721, 722) \
                and ms.isdisjoint((66, 67, 68, 61, 19)):
            refuse("Q", "G5, G6.2, G10, G64, G70-G72, G73, G76, G83, M19, M61 or M66-M68")

    def _lean(self, g: int | None, m: int | None, f: Any, extra: int, s: Any = None) -> bool:
        """Apply the modal part of a plain straight move and return True, or return False untouched.

        A plain move is at most one of G0/G1 (``g``: the G key), axis
        words, F (``f``: a Word or a value), S and at most one spindle or
        coolant M code (``m``: M3 M4 M5 M7 M8 M9), nothing else (``extra``
        other words: 0), in a state with nothing pending (no unknown code,
        rotation, spline, cutter compensation or M73 frame).  For such a
        block the general path does nothing but set F and the motion mode
        before the move; every check it makes (modal groups, R/I/J/K users,
        G53) cannot fire.
        """
        if extra or self.unsupported or self.prerotation_xy is not None or self.spline_state is not None or self.comp_on \
                or self.comp_just_off or self.m73_saved:
            return False
        speed = self.spindle_speed
        if s is not None:
            speed = s.value if isinstance(s, Word) else s
            if speed < 0:
                return False
        if self.feed_mode != 94 and (g == 10 or (g is None and self.motion == 10)):
            # G93 needs F in the block, G95 a feed and a spindle speed: the general path's checks
            fnew = self.feed if f is None else (f.value if isinstance(f, Word) else f)
            if self.feed_mode == 93 or not fnew or (speed is not None and not speed):
                return False
        if m is not None and m not in LEAN_M:
            return False
        if g is not None:
            if g != 0 and g != 10:
                return False
        elif self.motion != 0 and self.motion != 10:
            return False
        if f is not None:
            fv: Any = f.value if isinstance(f, Word) else f  # a Fraction, read through its slots
            if fv._numerator < 0:
                return False
            if self.feed_mode != 93:  # an inverse-time F is the block's own (see _execute_general)
                self.feed = fv
        if g is not None:
            self.cycle_il = None
            self.last_cycle = None
            self.motion = g
        if m is not None and m <= 5:
            self.spindle_dir = 1 if m == 3 else -1 if m == 4 else 0
        self.spindle_speed = speed
        return True

    def _lean_move(self, axis_at: tuple[tuple[int, int], ...], values: Sequence[Fraction]) -> None:
        """The G0/G1 move of a plain block: ``_motion_block``, ``_program_target`` and ``_emit``
        for the one case they reduce to (no G53, rotation, tracking or pending machine position).
        ``axis_at``: ``(value index, axis index)`` of each axis word, its value in ``values``.
        ``tests/gcode/test_plain_lane.py`` holds the two paths to identical segments."""
        if self.unset and not self._noted_straight:
            self.note_assumed(("units", "distance", "offset"))
            self._noted_straight = True  # unset only shrinks and assumed only grows: once is enough
        pos = self.pos
        end: Any = list(pos)  # the target's coordinates, then the tuple the segment holds
        inch = self.inch
        if inch:
            rotary = self.rotary
            values = [v if rotary[i] else _qinch(v) for v, (_k, i) in zip([values[k] for k, _i in axis_at], axis_at)]
            axis_at = tuple((n, i) for n, (_k, i) in enumerate(axis_at))
        if self.absolute:
            off = self.off
            for k, i in axis_at:
                o: Any = off[i]  # a Fraction, read through its slots
                end[i] = qadd(values[k], o) if o._numerator else values[k]
        else:
            for k, i in axis_at:
                end[i] = qadd(end[i], values[k])
        fmm = None
        if self.motion == 10:
            kind = _LINE
            if self.feed_mode == 94:
                feed: Any = self.feed  # a Fraction, read through its slots
                if feed._numerator == 0:
                    self.check_feed()
                fmm = _qinch(self.feed) if inch else self.feed
        else:
            kind = _RAPID
        end = tuple(end)
        fr = self._frame
        if fr is None or self._frame_off is not self.off:
            fr = self.program_frame()
        self.emitted.append(make_segment(kind, pos if type(pos) is tuple else tuple(pos), end, self.axes, self.block_index,
                                  self.span, self.tlo, fmm, None, False, None, None, 0, None, "", self.tool_register,
                                  (), (), (), fr))
        self.segment_count += 1
        self.kind_counts[kind] += 1
        self.pos = end
        self.prerotation_xy_next = None

    # ------------------------------------------------------------------ pieces
    _noted_straight = False
    _contexts: list | None = None  # [scope, depth, snapshot | None, auto-restore] per call frame (M70-M73)
    cycle_il: Fraction | None = None
    _spline = None  # an unfinished G5.2/G6.2 curve (nczones.gcode.linuxcnc.splines)

    m73_saved: list = []  # the contexts of M73s (auto-restore) whose call frame has not returned
    _scopes: list | None = None  # the language layer's local scopes (one per o-word call)

    def _frame_alive(self, ctx: list) -> bool:
        scopes = self._scopes
        if ctx[0] is None or scopes is None:
            return True
        depth = ctx[1]
        return len(scopes) >= depth and scopes[depth - 1] is ctx[0]

    def _frame_context(self, create: bool) -> list | None:
        """The M70-M73 context of the current call frame (LinuxCNC's ``sub_context[call_level]``, cleared when
        a call enters it): a call frame is a local-scope object of the language layer (o-word and M98 calls);
        the main program (or blocks without the language layer) is frame None."""
        scopes = self._scopes
        scope, depth = (scopes[-1], len(scopes)) if scopes is not None and len(scopes) > 1 else (None, 1)
        ctxs = self._contexts
        if ctxs is None:
            ctxs = self._contexts = []
        found = None
        keep = []
        for ctx in ctxs:
            if ctx[0] is scope and ctx[1] == depth:
                found = ctx
            if ctx[3] or self._frame_alive(ctx):  # a returned frame's context is gone (auto ones: m73_returns)
                keep.append(ctx)
        ctxs[:] = keep
        if found is None and create:
            found = [scope, depth, None, False]
            ctxs.append(found)
        return found

    def _modal_context(self, k: int, w: Word, others: bool = False) -> None:
        """M70 (save), M71 (invalidate), M72 (restore), M73 (save, restore when this call returns): LinuxCNC's
        ``convert_m``, ``save_settings`` and ``restore_settings`` on the current call frame.  ``others``: the block
        has G codes, axis words or other M codes.  M72 beside them is unknown: LinuxCNC 2.9's restore runs the
        restored codes through ``Interp::execute``, which reads them into the current block, so when it runs
        anything the rest of the block is lost (rs274 2.9.0~pre1 drops ``M72 G1 X100 Y0``'s motion)."""
        if k == 72 and others:
            self.unknown("M72", "M72 with G codes, axis words or other M codes in its block: LinuxCNC 2.9's restore "
                         "runs the restored codes as blocks of their own, which take the place of the rest of this "
                         "block (rs274 2.9.0~pre1 drops its motion and its G64); write M72 alone", w)
        if k in (70, 73):
            ctx = self._frame_context(True)
            assert ctx is not None
            ctx[2] = self._modal_snapshot()
            if k == 73 and ctx[0] is not None and not ctx[3]:
                ctx[3] = True  # at the main level M73 only saves (LinuxCNC: nothing to return to)
                self.m73_saved = [*self.m73_saved, ctx]
        elif k == 71:
            ctx = self._frame_context(False)
            if ctx is not None:
                ctx[2] = None  # LinuxCNC clears CONTEXT_VALID only: a later M70 re-arms an M73's restore
        elif k == 72:
            ctx = self._frame_context(False)
            if ctx is None or ctx[2] is None:
                raise self.error("GC204", "M72 restores the modal state M70 or M73 saved in this call frame, but none "
                                 "is saved here (LinuxCNC: cannot restore context from invalid stack frame)", w)
            self._restore_modal(ctx[2], w)

    def m73_returns(self) -> None:
        """Restore the state M73 saved in every subroutine that has returned since (innermost first).

        A subroutine call is alive while its local-scope object is still on
        the language layer's scope stack; checked before every block and every
        state parameter read, so nothing observes the state in between.
        """
        while self.m73_saved:
            ctx = self.m73_saved[-1]
            if self._frame_alive(ctx):
                break
            self.m73_saved = self.m73_saved[:-1]
            if self._contexts is not None and ctx in self._contexts:
                self._contexts.remove(ctx)
            if ctx[2] is not None:  # LinuxCNC leave_context: restores if the frame is still valid (no M71)
                self._restore_modal(ctx[2], None)

    def _modal_snapshot(self) -> tuple:
        """What LinuxCNC's save_settings keeps (``write_g_codes``, ``write_settings``) that nczones follows:
        units, distance and arc-centre modes, plane, work offset, feed mode and F, retract mode, cutter
        compensation, whether a tool length is applied (G43 when it is not zero, else G49), whether G92 is
        applied (#5210), the lathe diameter mode and the spindle (direction and S)."""
        return (self.inch, self.absolute, self.arc_absolute, self.plane, self.wcs, self.feed_mode,
                self.feed, self.retract_r, self._comp_key(), self.tlo != 0, self.g92_applied,
                bool(getattr(self, "diameter_mode", False)), self.spindle_dir, self.spindle_speed, self.path_words)

    def _comp_key(self) -> tuple:
        return (self.comp_on, None if self._comp is None else self._comp.side)

    def _set_units(self, inch: bool) -> None:
        """G20/G21 (and M72's restore): LinuxCNC's convert_length_units converts the positions and offsets it
        holds, but not a modal cycle's initial level (``cycle_il``, a program number): the next hole block
        retracts to that number read in the new units."""
        if inch != self.inch and self.cycle_il is not None:
            if self.track:
                self.unknown("canned cycle", "a units change (G20/G21) while a canned cycle is modal moves its "
                             "initial level; not followed with parameter ranges")
            ax = self._cycle_il_axis
            number = (self.cycle_il - self.off[ax]) / (INCH if self.inch else _ONE)
            self.cycle_il = number * (INCH if inch else _ONE) + self.off[ax]
            self._cycle_il_deps = {}
        self.inch = inch
        self._frame = None

    def _restore_modal(self, snap: tuple, w: Word | None) -> None:
        """LinuxCNC's restore_settings: G20/G21 first if it differs, then one block of the codes of every group
        that differs from the saved state (``gen_settings``), run in the order of execution: feed mode (G94
        and G95 set the feed to 0), ``F%.1f`` of the saved feed if it differs (not in G93), the lathe diameter
        mode, the plane, cutter compensation, ``G43`` (the tool in the spindle: the saved length is not kept,
        only whether one was applied) or ``G49``, the work offset, the distance modes, the retract mode and
        ``G92.3``/``G92.2``.  The motion mode is not restored."""
        (inch, absolute, arc_absolute, plane, wcs, feed_mode, feed, retract_r, comp, tlo_on, g92_on,
         diameter, spindle_dir, spindle_speed, path_words) = snap
        old_feed, old_speed, old_mode = self.feed, self.spindle_speed, self.feed_mode
        if inch != self.inch:
            self._set_units(inch)
        if feed_mode != self.feed_mode:
            self.feed_mode = feed_mode
            if feed_mode in (94, 95):
                self.feed = _ZERO
                self.feed_inverse_rate = False
        if old_mode == 93 and feed_mode != 93:
            # rs274 restoring G94 over G93 F30 leaves the feed at 0 in rs274_findings/restore-g93-feed.ngc (M72)
            # and in generator seed 7024 (M73), but restores F500 in seed 19 (a G94 F300 before the G93).  The rule
            # (branch diff33): a G93 F is not the feed rate, so the rate is still the saved one in the first two,
            # and 2.9.0~pre1's gen_settings writes F only when it differs, after the G94 that zeroed it; newer
            # LinuxCNC writes F always (interp_convert.cc, LinuxCNC issue 1987): version-dependent
            self.unknown("M72" if w is not None else "M73", "the feed after restoring G94/G95 over G93 (M72, or "
                         "the return of an M73 subroutine): LinuxCNC 2.9.0~pre1 leaves it at 0 when the saved feed "
                         "rate equals the current one, newer versions restore F; version-dependent, not modelled", w)
        if feed != old_feed and feed_mode != 93:
            # gen_settings writes " F%.1f": the double rounded to one decimal (an F below 0.05 restores F0)
            self.feed = round(Fraction(float(feed)), 1)
            self.feed_inverse_rate = False
        # " S%.0f" if the speed differs; M3/M4/M5 (gen_m_codes) if the direction does; None: not followed
        if spindle_speed is None or old_speed is None:
            self.spindle_speed = None
        elif spindle_speed != old_speed:
            self.spindle_speed = Fraction(round(Fraction(float(spindle_speed))))
        self.spindle_dir = spindle_dir
        if hasattr(self, "diameter_mode"):
            self.diameter_mode = diameter
            self._frame = None
        self.plane = plane
        if comp != self._comp_key():
            self.unknown("M72", "restoring cutter compensation (M72, or the return of an M73 subroutine, with "
                         "compensation switched since the save) is not modelled", w)
        if tlo_on != (self.tlo != 0):
            self._tool_length((430 if tlo_on else 490, w), {})  # type: ignore[arg-type]
        self.wcs = wcs
        self.absolute, self.arc_absolute, self.retract_r = absolute, arc_absolute, retract_r
        if g92_on != self.g92_applied:
            if g92_on:  # G92.3: the stored offsets
                self.g92 = list(self.g92_params)
                self.dep_g92 = [dict(d) for d in self.dep_g92_params]
            else:  # G92.2
                self.g92 = [_ZERO] * self.naxes
                self.dep_g92 = [{} for _ in range(self.naxes)]
            self.g92_applied = g92_on
        self.recompute_offsets()
        self._restore_path_mode(path_words)

    def _tool_length(self, g: tuple[int, Word], words: dict[str, Word]) -> None:
        k, w = g
        self.unset.discard("tool")
        if self.tlo != 0 and self.tlo_inch is not None and self.tlo_inch != self.inch:
            # rs274 (2.9.0~pre1): G21 G43 H1, G20, G49, G0 X1 moves Z by 12.66 inch for a 0.519 inch tool
            # (current_z += the offset still in mm): the machine moves an axis the program does not name
            self.unknown("G43", f"G{k // 10}{'.1' if k == 431 else ''} after a G20/G21 while a tool length is "
                         "applied: LinuxCNC 2.9 keeps that length in the old units and moves the tool axis by the "
                         "unconverted number; not modelled", w)
        self.tlo_inch = self.inch
        if k == 490:
            self.tlo = _ZERO
            self.tool_register = None
            self.dep_tlo = {}
        elif k == 430:
            h = words.get("H")
            if h is not None:
                if h.value.denominator != 1 or h.value < 0:
                    raise self.error("GC209", f"H word {h.text} must be a non-negative integer register number", h)
                # H0 is the tool in the spindle (LinuxCNC find_tool_index: tool 0 is the spindle's table entry)
                reg = int(h.value) or self.tool_in_spindle
            else:
                reg = self.tool_in_spindle
            if (h is None or h.value == 0) and self.spindle_slot_stale:
                # rs274 keeps the unloaded tool's entry in the spindle slot after T0 M6, and M61 changes only the
                # number: G43 then applies the length of that entry
                self.unknown("G43", "G43 of the tool in the spindle after T0 M6 or M61: LinuxCNC's interpreter "
                              "reads the spindle slot's table entry, which those leave as it was; not modelled", h or w)
                return
            if reg in self.tool_table:
                self.tlo, self.dep_tlo = self.tool_table[reg]
                self.tool_register = reg
                self.recompute_offsets()
                return
            if reg != 0 and reg not in self.machine.tool_lengths:
                where = h if h is not None else w
                known = ", ".join(f"H{r}" for r in sorted(self.machine.tool_lengths)) or "none"
                raise self.error("GC310", f"tool length register H{reg} is not in the machine file's [tool_lengths] (known: {known})", where)
            self.tlo = self.machine.tool_length(reg)
            self.tool_register = reg
            self.dep_tlo = {f"H{reg}": 1} if reg != 0 else {}
        elif k == 431:
            if self.tool_axis is None:
                raise self.error("GC204", "G43.1 needs a tool axis in the machine file", w)
            axis = self.axes[self.tool_axis]
            for other in self.axes:
                ow = words.get(other)
                if other != axis and ow is not None and ow.value != 0:
                    self.unknown("G43.1", f"G43.1 {ow.text or other} offsets the tool on {other}; only the length on the "
                                 f"tool axis {axis} is modelled", ow)
                    return
            zw = words.get(axis)
            # LinuxCNC: every axis G43.1 does not name gets offset 0
            self.tlo = _ZERO if zw is None else self.length_mm(zw.value)
            self.tool_register = None
            self.dep_tlo = {}
        self.recompute_offsets()

    def _polar(self, words: dict[str, Word], axis_words: list[tuple[int, Word]], g1: Any, g53: bool,
               nonmodal: bool) -> list[tuple[int, Word]]:
        """LinuxCNC's polar coordinates (``@`` radius, ``^`` angle in degrees) of a G0-G3 block as X and Y words
        (``find_ends``, ``interp_find.cc``; a canned cycle's hole, ``convert_cycle_xy``), in LinuxCNC's doubles:
        about the program origin, in G91 from where the tool is (the radius added to its distance from the
        origin, then the angle to its direction).  G91 cycles repeated with L (the angle turns on every
        repeat), cutter compensation, a rotated system and parameter ranges: unknown."""
        w = words.get("@") or words["^"]
        motion = g1[0] if g1 else self.motion
        ix, iy = self._ix, self._iy
        if "X" in words or "Y" in words:
            raise self.error("GC205", "polar coordinates (@, ^) cannot be given with an X or Y word", w)
        if self.plane is not _XY:
            raise self.error("GC205", "polar coordinates (@, ^) are allowed in the G17 plane only", w)
        if g53:
            raise self.error("GC207", "polar coordinates (@, ^) cannot be used with G53", w)
        if motion is None and not nonmodal:
            raise self.error("GC208", "polar coordinates (@, ^) without an active motion mode (G80 is active); "
                             "write G0, G1, G2 or G3", w)
        lw = words.get("L")
        cycle = motion in _CYCLES
        if nonmodal or not (motion in (0, 10, 20, 30) or (cycle and (self.absolute or lw is None or lw.value == 1))) \
                or ix < 0 or iy < 0 or self.comp_on or self.prerotation_xy is not None or self.track or self.ranged \
                or self.unsupported:
            self.unknown("@ ^", "LinuxCNC polar coordinates (@ radius, ^ angle) are modelled for G0-G3 and single "
                         "canned cycles, without cutter compensation, rotation or parameter ranges (G91 cycles with "
                         "L turn the angle on every repeat: not modelled)", w)
            return axis_words
        unit = INCH if self.inch else _ONE
        cx = (self.pos[ix] - self.off[ix]) / unit
        cy = (self.pos[iy] - self.off[iy]) / unit
        px, py = to_float(cx), to_float(cy)
        rw, tw = words.get("@"), words.get("^")
        d2r = math.pi / 180.0
        if self.absolute:
            if rw is not None and tw is not None:
                r, t = to_float(rw.value), to_float(tw.value) * d2r
            elif rw is not None:
                if px == 0.0 and py == 0.0 and not cycle:  # convert_cycle_xy takes atan2(0, 0) = 0
                    raise self.error("GC305", "polar coordinates at the origin need an angle (^)", rw)
                r, t = to_float(rw.value), math.atan2(py, px)
            else:
                assert tw is not None
                r, t = math.hypot(py, px), to_float(tw.value) * d2r
            px, py = r * math.cos(t), r * math.sin(t)
        else:
            if px == 0.0 and py == 0.0:
                raise self.error("GC305", "G91 motion with polar coordinates is indeterminate at the origin", w)
            if rw is not None:
                t, r = math.atan2(py, px), math.hypot(py, px) + to_float(rw.value)
                px, py = r * math.cos(t), r * math.sin(t)
            if tw is not None:
                t, r = math.atan2(py, px) + to_float(tw.value) * d2r, math.hypot(py, px)
                px, py = r * math.cos(t), r * math.sin(t)
        x, y = Fraction(px), Fraction(py)
        if not self.absolute:
            x, y = x - cx, y - cy
        out = [(i, v) for i, v in axis_words if i not in (ix, iy)]
        out += [(ix, Word("X", x, w.span, w.text)), (iy, Word("Y", y, w.span, w.text))]
        return sorted(out, key=lambda iw: iw[0])

    def program_target(self, axis_words: list[tuple[int, Word]], g53: bool, absolute: bool | None = None) -> tuple[list[Fraction], list[dict] | None]:
        absolute = self.absolute if absolute is None else absolute
        end = list(self.pos)
        deps = [dict(d) for d in self.dep_pos] if self.track else None
        for i, w in axis_words:
            v = w.value
            if self.inch and not self.rotary[i]:
                v = v * INCH
            if g53:
                end[i] = v
                if deps is not None:
                    deps[i] = {}
            elif absolute:
                end[i] = qadd(v, self.off[i])
                if deps is not None:
                    deps[i] = dict(self.dep_off[i])
            else:
                end[i] = qadd(end[i], v)
        if self.prerotation_xy is not None:
            if g53:
                self._machine_xy(end)
            else:
                ix, iy = self._ix, self._iy
                p = [self.prerotation_xy[0] - self.g92[ix], self.prerotation_xy[1] - self.g92[iy]]
                for i, w in axis_words:
                    if i == ix or i == iy:
                        k = 0 if i == ix else 1
                        v = w.value * INCH if self.inch else w.value
                        p[k] = v if absolute else p[k] + v
                u = [p[0] + self.g92[ix], p[1] + self.g92[iy]]
                end[ix], end[iy] = self._rot_fwd(u[0], u[1])
                self.prerotation_xy_next = u
        return end, deps

    def _motion_block(self, block: Block, axis_words: list[tuple[int, Word]], words: dict[str, Word], g1: Any,
                      g53: bool) -> None:
        motion = self.motion
        if motion is None:
            if axis_words and not self.unsupported:
                raise self.error("GC208", "axis words without an active motion mode (G80 is active); write G0, G1, G2 or G3", axis_words[0][1])
            return
        if self.unsupported:
            return
        if self.feed_mode == 93 and motion != 0:
            # LinuxCNC's inverse_time_rate_straight/_arc set the feed rate to the move's length x F (a double of a
            # square root): #<_feed> reads it until the next F in G94/G95 or a G94/G95
            self.feed_inverse_rate = True
        if motion in (10, 20, 30):
            self._feed_rule(words, "g1" if motion == 10 else "arc")
        if motion in (0, 10):
            if g53 and not self.absolute:
                raise self.error("GC207", "G53 cannot be used in incremental mode (G91)", axis_words[0][1] if axis_words else None)
            if not axis_words:
                return
            if g53 and any(i == self.tool_axis for i, _ in axis_words) and self.tool_length_units_stale(
                    "G53 (a move of the tool axis in machine coordinates)", axis_words[0][1]):
                return
            self.note_assumed(("units", "distance") if g53 else ("units", "distance", "offset"))
            end, deps = self.program_target(axis_words, g53)
            if motion == 0:
                if self._comp is not None and self._comp.active:
                    self._comp.straight(_RAPID, end, deps)
                else:
                    self.emit(_RAPID, end, end_deps=deps)
            else:
                self.check_feed()
                if self._comp is not None and self._comp.active:
                    self._comp.straight(_LINE, end, deps)
                else:
                    self.emit(_LINE, end, feed=True, end_deps=deps)
        elif motion in (20, 30) and self._comp is not None and self._comp.active:
            self._comp.arc(block, axis_words, words, motion == 20)
        elif motion in (20, 30):
            self.arc(block, axis_words, words, motion == 20, g53)
        elif motion in (330, 331):
            self._spindle_synced(motion, axis_words, words, g53)
        elif self.prerotation_xy is not None and not self.unsupported:
            self.unknown(gname(motion), f"{gname(motion)} in a rotated coordinate system (G10 L2 R) is not modelled")
        elif motion in _CYCLES:
            self._cycle(motion, axis_words, words)
        elif motion in SPLINE_CODES:
            _spline_block(self, motion, axis_words, words, g1)
        else:
            raise InternalError(f"motion mode {motion}")

    def _feed_rule(self, words: dict[str, Word], what: str) -> None:
        """LinuxCNC's feed checks of a G1 or arc block (``convert_straight``, ``convert_arc``): in G94 and G95 a
        feed rate that is not 0 (G94/G95 set it to 0), in G95 a spindle speed, in G93 an F word in the block."""
        if self.feed_mode == 93:
            if "F" not in words:
                raise self.error("GC305", f"inverse time feed (G93): every {'G1' if what == 'g1' else 'arc'} block needs "
                                 "its own F word")
        elif self.feed == 0:
            self.check_feed(any_mode=True)
        elif self.feed_mode == 95 and self.spindle_speed is not None and self.spindle_speed == 0:
            raise self.error("GC305", "feed per revolution (G95) with spindle speed 0: write S before the move")

    def _spindle_turning(self, name: str, direction: int | None = None) -> None:
        """LinuxCNC refuses G33, G33.1, G86 with the spindle stopped, and G84 unless it turns clockwise."""
        if self.spindle_dir is None:
            return
        if self.spindle_dir == 0:
            raise self.error("GC305", f"spindle not turning in {name}: start it with M3 (or M4) first")
        if direction is not None and self.spindle_dir != direction:
            raise self.error("GC305", f"spindle turning counterclockwise (M4) in {name}: {name} taps with M3")

    def _spindle_synced(self, motion: int, axis_words: list[tuple[int, Word]], words: dict[str, Word], g53: bool) -> None:
        """G33 (threading) and G33.1 (rigid tapping): the geometry of LinuxCNC's spindle-synchronized moves.

        G33 is a straight line to the end point (K = pitch, the speed follows
        the spindle).  G33.1 feeds along the straight line to the end point,
        then back to the start (LinuxCNC ``RIGID_TAP``; the interpreter's
        position stays at the start).  The feed is spindle speed x pitch, not
        F: ``feed_mm_min`` is None.
        """
        name = gname(motion)
        if g53:
            raise self.error("GC207", f"G53 cannot be used with {name}")
        kw = words.get("K")
        if kw is None:
            raise self.error("GC208", f"{name} needs a K word (the pitch, distance per spindle revolution)")
        # any K, 0 and negative too: LinuxCNC checks only that the block has one; the path is the line either way
        if self.comp_on:
            raise self.error("GC204", f"{name} cannot be used with cutter compensation on")
        self._spindle_turning(name)
        if not axis_words:
            return
        self.note_assumed(("units", "distance", "offset"))
        start = list(self.pos)
        # after G84 outside G17 the machine is not where the interpreter believes (_g84_swapped): RIGID_TAP
        # feeds from where the machine is and reverses back to there (rs274: the tap's second STRAIGHT_FEED ends
        # at the G84 retract's end), while the interpreter's position stays at its own start
        actual = self.machine_at
        u0 = list(self.prerotation_xy) if self.prerotation_xy is not None else None
        end, deps = self.program_target(axis_words, False)
        if motion == 330:
            self.emit(_LINE, end, derived="G33 thread", end_deps=deps)
            return
        sdeps = [dict(d) for d in self.dep_pos] if self.track else None
        self.emit(_LINE, end, derived="G33.1 tap", end_deps=deps)
        self.prerotation_xy_next = u0
        self.emit(_LINE, list(actual) if actual is not None else start, derived="G33.1 retract",
                  end_deps=sdeps)
        if actual is not None:
            self.pos = start
            self.machine_at = actual

    def check_feed(self, any_mode: bool = False) -> None:
        """GC305 for a feed motion at feed rate 0: in G94, or in every mode (``any_mode``, LinuxCNC's G95)."""
        if (self.feed_mode == 94 or any_mode) and self.feed == 0:
            raise self.error("GC305", "feed motion with zero feed rate: no F word since the start or the last G94/G95 "
                             "(which set the feed rate to 0); write F before or in this block")

    # ------------------------------------------------------------------ arcs
    def arc(self, block: Block, axis_words: list[tuple[int, Word]], words: dict[str, Word], cw: bool, g53: bool) -> None:
        if g53:
            raise self.error("GC207", "G53 cannot be used with G2/G3")
        plane = self.plane
        a_name, b_name, n_name = PLANE_AXES[plane]
        ia, ib = self.index.get(a_name), self.index.get(b_name)
        if ia is None or ib is None:
            raise self.error("GC308", f"an arc in plane G{int(plane)} needs axes {a_name} and {b_name}; this machine has {', '.join(self.axes)}")
        offs = {"X": "I", "Y": "J", "Z": "K"}
        la, lb, ln = offs[a_name], offs[b_name], offs[n_name]
        if ln in words:
            raise self.error("GC204", f"{ln} word {words[ln].text} given for an arc in plane G{int(plane)} (use {la} and {lb})", words[ln])
        rw = words.get("R")
        if rw is not None and (la in words or lb in words):
            raise self.error("GC204", "mixed radius (R) and centre (I/J/K) format in one arc", rw)
        if rw is None and la not in words and lb not in words:
            raise self.error("GC208", f"arc without {la}, {lb} or R word: the centre or radius is missing", axis_words[0][1] if axis_words else None)
        self.check_feed()
        turns = 0
        pw = words.get("P")
        if pw is not None:
            # LinuxCNC check_other_codes: round_to_int(P) within 0.001 of P, at least 1
            pd = pw.value.numerator / pw.value.denominator
            pr = round(pd)
            if abs(pr - pd) > 0.001 or pr < 1:
                raise self.error("GC209", f"arc turn count {pw.text} must be a positive integer", pw)
            turns = pr - 1
        self.note_assumed(("units", "distance", "offset", "plane"))
        end, deps = self.program_target(axis_words, False)
        rotated = self.prerotation_xy is not None
        if rotated:
            if plane is not _XY:
                self.unknown(f"G{int(plane)} arc", f"an arc in plane G{int(plane)} of a rotated coordinate system "
                              "(G10 L2 R) lies in a plane that is no machine plane; not modelled")
                return
            # the arc in the pre-rotation frame (program + G92); end and centre rotated as LinuxCNC does
            assert self.prerotation_xy is not None and self.prerotation_xy_next is not None  # set by _program_target under rotation
            (sa, sb), (ea, eb) = self.prerotation_xy, self.prerotation_xy_next
            off_a, off_b = self.g92[ia], self.g92[ib]
        else:
            sa, sb = self.pos[ia], self.pos[ib]
            ea, eb = end[ia], end[ib]
            off_a, off_b = self.off[ia], self.off[ib]
        tol = self.arc_tolerance
        if rw is not None:
            tol = self._r_arc_tolerance()
            r = self.length_mm(rw.value)
            if sa == ea and sb == eb:
                raise self.error("GC303", "R-format arc whose end point equals its start point: the centre is undefined (use I/J/K for a full circle)", rw)
            if r == 0:
                raise self.error("GC304", "zero-radius arc (R0)", rw)
            h2 = ((ea - sa) ** 2 + (eb - sb) ** 2) / 4
            r2 = r * r
            if h2 > r2:
                # |h| - |r| > tol  <=>  h > r + tol
                if h2 > (abs(r) + tol) ** 2:
                    raise self.error(
                        "GC302",
                        f"arc radius R{fmt_number(abs(r))} mm is too small to reach the end point (half the chord is "
                        f"{fmt_number(Fraction(h2))}**0.5 mm; tolerance {fmt_number(tol)} mm)",
                        rw,
                    )
            if rotated and (h2 * (1 - _TINY) ** -2 < r2 and h2 < r2):
                # the rotated ends (doubles) may be a rounding error farther apart than 2|R|
                mh2 = ((end[ia] - self.pos[ia]) ** 2 + (end[ib] - self.pos[ib]) ** 2) / 4
                if mh2 >= r2:
                    h2 = r2
            if h2 * (1 - _TINY) ** -2 >= r2 or h2 >= r2:
                # LinuxCNC takes the chord midpoint as the centre (a half circle)
                centre = ((sa + ea) / 2, (sb + eb) / 2)
                if rotated:
                    centre = self._rot_fwd(*centre)
                self.emit(_ARC, end, feed=True, plane=plane, clockwise=cw, centre=centre,
                           turns=turns, end_deps=deps)
            else:
                self.emit(_ARC, end, feed=True, plane=plane, clockwise=cw, radius=r,
                           turns=turns, end_deps=deps)
            return
        iw, jw = words.get(la), words.get(lb)
        iv = self.length_mm(iw.value) if iw is not None else _ZERO
        jv = self.length_mm(jw.value) if jw is not None else _ZERO
        if self.arc_absolute:
            ca = (iv + off_a) if iw is not None else off_a
            cb = (jv + off_b) if jw is not None else off_b
        else:
            ca, cb = sa + iv, sb + jv
        r0 = (sa - ca) ** 2 + (sb - cb) ** 2
        r1 = (ea - ca) ** 2 + (eb - cb) ** 2
        self._refuse_zero_radius(r0, r1, iw or jw)
        rejected = (linuxcnc_rejects_arc(r0, r1, self.inch) if self.arc_rule == "linuxcnc"
                    else r0 != r1 and sqrt_diff_exceeds(r0, r1, tol))
        if rejected:
            if self.arc_rule == "linuxcnc":
                tol = Fraction(28284, 1000000)  # for the message: 2 * 0.01 * sqrt(2) mm
            raise self.error(
                "GC301",
                f"arc end point is off its circle: radius at start {_fmt_sqrt(r0)} mm, at end {_fmt_sqrt(r1)} mm "
                f"(start=({a_name}{fmt_number(sa)},{b_name}{fmt_number(sb)}) centre=({a_name}{fmt_number(ca)},{b_name}{fmt_number(cb)}) "
                f"end=({a_name}{fmt_number(ea)},{b_name}{fmt_number(eb)}) in machine mm); allowed difference is {fmt_number(tol)} mm",
                iw or jw,
            )
        centre = self._rot_fwd(ca, cb) if rotated else (ca, cb)
        self.emit(_ARC, end, feed=True, plane=plane, clockwise=cw, centre=centre,
                   turns=turns, end_deps=deps)

    def _r_arc_tolerance(self) -> Fraction:
        """How far (mm) an R arc's radius may fall short of half its chord before the arc is refused (GC302)."""
        if self.arc_rule == "grbl":
            return _ZERO  # Grbl refuses an R arc whose chord is longer than 2R at all (h_x2_div_d < 0)
        if self.dialect == "linuxcnc" and self.arc_tolerance > LINUXCNC_RADIUS_TOLERANCE:
            # LinuxCNC refuses an R short by more than its own 0.00005 inch whatever the tolerance set here
            # ("Arc radius too small to reach end point": R4.99873 from X0 to X10 runs, R4.99872 does not)
            return LINUXCNC_RADIUS_TOLERANCE
        return self.arc_tolerance

    def _refuse_zero_radius(self, r0: Fraction, r1: Fraction, word: Word | None) -> None:
        """GC304 for an I/J/K arc whose squared start or end radius ``r0``/``r1`` is zero, or (LinuxCNC) below its
        0.00005 inch."""
        if r0 == 0 or r1 == 0:
            raise self.error("GC304", "zero-radius arc: the centre coincides with the start or end point", word)
        if self.dialect == "linuxcnc" and min(r0, r1) < LINUXCNC_ZERO_RADIUS_SQ:
            raise self.error("GC304", f"zero-radius arc: radius at start {_fmt_sqrt(r0)} mm, at end {_fmt_sqrt(r1)} mm; "
                             "LinuxCNC refuses a radius below 0.00005 inch (0.00127 mm)", word)

    # ------------------------------------------------------------------ G28/G30, G10, G92, G52
    def _tool_change_moves(self) -> None:
        """The moves LinuxCNC makes at M6 on a machine configured for them (``[machine] tool_change_*``).

        ``convert_tool_change`` (interp_convert.cc) traverses Z to machine 0 (``TOOL_CHANGE_QUILL_UP``), then
        every axis to the G30 position (``TOOL_CHANGE_AT_G30``), and the task's ``CHANGE_TOOL`` (emccanon.cc)
        then moves on a straight line to ``TOOL_CHANGE_POSITION`` in machine coordinates; the interpreter
        re-reads the position after the change.  All are rapids in machine coordinates."""
        m = self.machine
        if self.dialect != "linuxcnc":
            return  # LinuxCNC INI settings (a Fanuc tool change: specs/fanuc.md)
        if (getattr(m, "tool_change_quill_up", False) or getattr(m, "tool_change_at_g30", False)) \
                and self.tool_length_units_stale("M6 (its move to the tool change position)", None):
            return
        if getattr(m, "tool_change_quill_up", False) and "Z" in self.index:
            iz = self.index["Z"]
            end = list(self.pos)
            end[iz] = _ZERO
            deps = [dict(d) for d in self.dep_pos] if self.track else None
            if deps is not None:
                deps[iz] = {}
            self.emit(_RAPID, end, derived="M6 quill up (TOOL_CHANGE_QUILL_UP)", end_deps=deps)
        if getattr(m, "tool_change_at_g30", False):
            home = self.home[300]
            end = list(home)
            deps = [dict(d) for d in self.dep_home[300]] if self.track else None
            self._machine_xy(end)
            self.emit(_RAPID, end, derived="M6 to the G30 position (TOOL_CHANGE_AT_G30)", end_deps=deps)
        position = getattr(m, "tool_change_position", None)
        if position:
            end = list(self.pos)
            deps = [dict(d) for d in self.dep_pos] if self.track else None
            for a, v in position.items():
                i = self.index[a]
                end[i] = v
                if deps is not None:
                    deps[i] = {}
            self.emit(_RAPID, end, derived="M6 to the tool change position (TOOL_CHANGE_POSITION)",
                      end_deps=deps)

    def tool_length_units_stale(self, what: str, w: Word | None) -> bool:
        """Unknown (True) for ``what`` after a G20/G21 made while a tool length is applied, on LinuxCNC.

        LinuxCNC 2.9's rs274 re-reads the applied tool length at a units change without converting it (see
        ``_tool_length``); the interpreter's computations that use it then put the tool axis elsewhere than
        the program says: G43/G49, ``find_relative`` (G28/G30's home, M6's quill up and G30 position) and
        ``find_ends`` of a G53 move of the tool axis (interp_find.cc)."""
        if self.dialect != "linuxcnc" or self.tlo == 0 or self.tlo_inch is None or self.tlo_inch == self.inch:
            return False
        self.unknown(what.split()[0], f"{what} after a G20/G21 while a tool length is applied: LinuxCNC 2.9 keeps "
                     "that length in the old units and moves the tool axis by the unconverted number; not modelled",
                     w)
        return True

    def _home(self, k: int, axis_words: list[tuple[int, Word]], w: Word) -> None:
        self.note_assumed(("units", "distance", "offset"))
        inter, deps = self.program_target(axis_words, False)
        self.emit(_RAPID, inter, derived=f"{gname(k)} intermediate", end_deps=deps)
        if (not axis_words or any(i == self.tool_axis for i, _ in axis_words)) \
                and self.tool_length_units_stale(f"{gname(k)} (its home move of the tool axis)", w):
            return
        if axis_words and self.rot[self.wcs] and self.dialect == "linuxcnc" and not self.unsupported:
            # rs274 (rs274_findings/rotated-g28-axis.ngc): G28 X-8 after G10 L2 P0 Y6 R-39.9 homes X in the
            # rotated program frame, so machine Y moves too (nczones homed machine X only); not modelled
            self.unknown(gname(k), f"{gname(k)} with axis words in a coordinate system rotated by G10 L2 R: "
                         "LinuxCNC homes the named axes in the program frame (other machine axes move too); "
                         "not modelled", w)
            return
        home = self.home[k]
        end = list(self.pos)
        hdeps = [dict(d) for d in self.dep_pos] if self.track else None
        moving = [i for i, _ in axis_words] if axis_words else range(self.naxes)
        for i in moving:
            end[i] = home[i]
            if hdeps is not None:
                hdeps[i] = dict(self.dep_home[k][i])
        self._machine_xy(end)
        self.emit(_RAPID, end, derived=f"{gname(k)} home", end_deps=hdeps)

    def _g10(self, words: dict[str, Word], axis_words: list[tuple[int, Word]], w: Word) -> None:
        lw, pw = words.get("L"), words.get("P")
        if lw is None:
            raise self.error("GC208", "G10 needs an L word (L1, L2, L10, L20)", w)
        L = lw.value
        if L not in (1, 2, 10, 11, 20):
            raise self.error("GC209", f"G10 {lw.text}: L must be 1, 2, 10, 11 or 20", lw)
        if pw is None:
            raise self.error("GC208", f"G10 L{L} needs a P word", w)
        P = pw.value
        # LinuxCNC check_g10: P rounded half away from zero (p_int) must be within 0.0002 below P + 0.0001, i.e.
        # P is in [p_int - 0.5, p_int + 0.0001]: G10 L2 P1.6 passes the check
        pd = P.numerator / P.denominator
        p_int = int(pd + 0.5) if pd >= 0 else int(pd - 0.5)
        if (pd + 0.0001) - p_int > 0.0002:
            raise self.error("GC209", f"G10 L{L} {pw.text}: P must be an integer (LinuxCNC: P value not an integer "
                              "with G10)", pw)
        if L in (2, 20):
            if not 0 <= p_int <= 9:
                raise self.error("GC209", f"G10 L{L} {pw.text}: P must be an integer 0 (active) to 9 (G59.3)", pw)
            # convert_setup then truncates P + 0.0001: G10 L2 P1.6 and P1.5 write G54 (P1)
            k = int(pd + 0.0001)
            name = self.wcs if k == 0 else WORK_OFFSETS[k - 1]
            rw = words.get("R")
            reg = self.g5x[name]
            dreg = self.dep_g5x[name]
            if rw is not None and L == 20:
                raise self.error("GC204", "R word in G10 L20: LinuxCNC sets a rotation only with G10 L2 R", rw)
            ix, iy = self._ix, self._iy
            if rw is not None and name == self.wcs and rw.value != self.rot[name] and ix >= 0 and iy >= 0 \
                    and (self.g92[ix] or self.g92[iy]):
                # LinuxCNC's convert_setup re-derives the position as rotate(program) + G5x, leaving G92 out of the
                # rotation the canon layer applies to it: from here on its interpreter aims every relative move
                # from a point where the machine is not
                self.unknown("G10 L2 R", "changing the rotation of the active coordinate system while a G92/G52 "
                              "offset is applied on X or Y is not modelled (LinuxCNC's interpreter loses the "
                              "position); clear it with G92.1 first", rw)
                return
            if rw is not None:
                self.rot[name] = rw.value
            rot20 = L == 20 and self.rot[name] != 0 and any(i in (ix, iy) for i, _ in axis_words)
            if rot20:
                self._g10_l20_rotated(name, axis_words)
            for i, aw in axis_words:
                v = self._mm(aw.value, i)
                if rot20 and i in (ix, iy):
                    continue
                if L == 2:
                    reg[i] = v
                    dreg[i] = {}
                else:
                    tl = self.tlo if i == self.tool_axis else _ZERO
                    reg[i] = self.pos[i] - self.g92[i] - tl - v
                    if self.track:
                        d = dadd(self.dep_pos[i], self.dep_g92[i], -1)
                        if i == self.tool_axis:
                            d = dadd(d, self.dep_tlo, -1)
                        dreg[i] = d
            self.recompute_offsets()
        else:
            if p_int < 1:  # LinuxCNC check_g10: P >= 1 with L1, L10 and L11
                raise self.error("GC209", f"G10 L{L} {pw.text}: P must be a positive integer tool number", pw)
            # convert_setup_tool: is_near_int, the tool number (int)(P + 0.5)
            self._g10_tool(int(L), Fraction(int(pd + 0.5)), pw, axis_words, words.get("R"))

    def _g10_l20_rotated(self, name: str, axis_words: list[tuple[int, Word]]) -> None:
        """G10 L20 on X/Y of a rotated system: the offset that makes the current position read the values.

        Axes without a word keep their current program value in that system;
        ``offset = machine - rotate(program + G92)`` in doubles (LinuxCNC),
        taken exactly; both X and Y offsets change.
        """
        ix, iy = self._ix, self._iy
        reg = self.g5x[name]
        t = to_float(self.rot[name]) * math.pi / 180.0
        c, s = math.cos(t), math.sin(t)
        x, y = to_float(self.pos[ix] - reg[ix]), to_float(self.pos[iy] - reg[iy])
        u = [Fraction(x * c + y * s), Fraction(y * c - x * s)]
        for i, aw in axis_words:
            if i in (ix, iy):
                u[0 if i == ix else 1] = self._mm(aw.value, i) + self.g92[i]
        ux, uy = to_float(u[0]), to_float(u[1])
        reg[ix] = Fraction(to_float(self.pos[ix]) - (ux * c - uy * s))
        reg[iy] = Fraction(to_float(self.pos[iy]) - (ux * s + uy * c))
        self.dep_g5x[name][ix] = {}
        self.dep_g5x[name][iy] = {}

    def _g10_tool(self, L: int, P: Fraction, pw: Word, axis_words: list[tuple[int, Word]],
                  rw: Word | None = None) -> None:
        """G10 L1/L10/L11: write the tool table entry of tool P (LinuxCNC ``convert_setup_tool``).

        Only the tool-axis length is modelled; an offset on another axis (a
        lathe X offset) that is not zero is unknown.  L1 takes the value as
        written; L10 makes the current position read the value in the current
        coordinate system (``length = machine - G5x - G92 - value``); L11 the
        same in G59.3 without G92.  The active length changes only at the next
        G43 (the table entry is not the active offset).
        """
        if P.denominator != 1 or P < 1:  # LinuxCNC check_g_codes: P >= 1 with L1, L10 and L11
            raise self.error("GC209", f"G10 L{L} {pw.text}: P must be a positive integer tool number", pw)
        tool = int(P)
        if L != 1 and any(i == self.tool_axis for i, _ in axis_words) and self.tool_length_units_stale(
                f"G10 L{L} (find_current_in_system_without_tlo adds the applied length)", pw):
            return
        if rw is not None:
            # convert_setup_tool: the R word is the tool's radius (diameter = 2 R, in the control's units): what
            # G41/G42 D and #5410 read from then on
            self.tool_diameters_set[tool] = self.length_mm(rw.value) * 2
        for i, aw in axis_words:
            if i == self.tool_axis:
                v = self._mm(aw.value, i)
                if L == 1:
                    length, deps = v, dict[str, Fraction]()
                else:
                    g5 = self.g5x["G59.3" if L == 11 else self.wcs][i]
                    g92 = _ZERO if L == 11 else self.g92[i]
                    length = self.pos[i] - g5 - g92 - v
                    deps = {}
                    if self.track:
                        deps = dadd(self.dep_pos[i], self.dep_g5x["G59.3" if L == 11 else self.wcs][i], -1)
                        if L != 11:
                            deps = dadd(deps, self.dep_g92[i], -1)
                self.tool_table[tool] = (length, deps)
            elif L != 1 or aw.value != 0:
                self.unknown(f"G10 L{L}", f"G10 L{L} sets a tool offset on axis {self.axes[i]} ({aw.text}); nczones "
                              "models tool length on the tool axis only", aw)
                return

    def _g92(self, axis_words: list[tuple[int, Word]], w: Word) -> None:
        if not axis_words:
            raise self.error("GC208", "G92 needs at least one axis word", w)
        for i, aw in axis_words:
            v = self._mm(aw.value, i)
            if self.prerotation_xy is not None and i in (self._ix, self._iy):
                self.g92[i] = self.prerotation_xy[0 if i == self._ix else 1] - v
                continue
            tl = self.tlo if i == self.tool_axis else _ZERO
            self.g92[i] = self.pos[i] - self.g5x[self.wcs][i] - tl - v
            if self.track:
                d = dadd(self.dep_pos[i], self.dep_g5x[self.wcs][i], -1)
                if i == self.tool_axis:
                    d = dadd(d, self.dep_tlo, -1)
                self.dep_g92[i] = d
        self.g92_params = list(self.g92)
        self.dep_g92_params = [dict(d) for d in self.dep_g92]
        self.g92_applied = True
        self.recompute_offsets()

    def _g52(self, axis_words: list[tuple[int, Word]], w: Word) -> None:
        if not axis_words:
            raise self.error("GC208", "G52 needs at least one axis word", w)
        for i, aw in axis_words:
            self.g92[i] = self._mm(aw.value, i)
            self.dep_g92[i] = {}
        self.g92_params = list(self.g92)
        self.dep_g92_params = [dict(d) for d in self.dep_g92]
        self.g92_applied = True
        self.recompute_offsets()

    # ------------------------------------------------------------------ canned cycles
    def _linuxcnc_pecks(self, rprog: Fraction, cprog: Fraction, old_prog_mm: Fraction) -> int:
        """How many pecks LinuxCNC's G73/G83 loop makes: ``for (d = r - q; d > bottom; d -= q)`` in doubles of
        the program values (current units). Exact arithmetic differs where the bottom is a whole number of
        pecks below R, give or take an ulp: LinuxCNC then pecks once more, or once less."""
        q = to_float(self.cycle_q or _ZERO)
        if self.absolute:
            r, bottom = to_float(rprog), to_float(cprog)
        else:
            old = to_float(old_prog_mm / INCH if self.inch else old_prog_mm)
            r = to_float(rprog) + old
            bottom = r + to_float(cprog)
        n, d = 0, r - q
        while d > bottom and n < 1_000_000:
            n += 1
            d -= q
        return n

    def _cycle(self, motion: int, axis_words: list[tuple[int, Word]], words: dict[str, Word]) -> None:
        plane = self.plane
        a_name, b_name, c_name = PLANE_AXES[plane]
        ia, ib, ic = self.index.get(a_name), self.index.get(b_name), self.index.get(c_name)
        if ia is None or ib is None or ic is None:
            raise self.error("GC308", f"a canned cycle in plane G{int(plane)} needs axes {a_name}, {b_name} and {c_name}; this machine has {', '.join(self.axes)}")
        for i, aw in axis_words:
            if self.axes[i] not in (a_name, b_name, c_name):
                raise self.error("GC210", f"cannot put an {self.axes[i].lower()} word ({aw.text}) in a canned cycle", aw)
        if self.comp_on:
            raise self.error("GC204", "canned cycles cannot be used with cutter compensation on")
        self.check_feed(any_mode=True)  # LinuxCNC convert_cycle: in G94 and G95 alike
        if self.feed_mode == 93:
            raise self.error("GC204", "canned cycles cannot be used with inverse time feed (G93)")
        if motion in (840, 860):
            self._spindle_turning(gname(motion), 1 if motion == 840 else None)
        self.note_assumed(("retract",))
        swapped = motion == 840 and plane is not _XY
        if swapped and self.track:
            self.unknown("G84", "parameter ranges are not supported with G84 outside G17")
        first = self.last_cycle != motion
        rw = words.get("R")
        if rw is None:
            if first or self.cycle_r is None:
                raise self.error("GC208", f"{gname(motion)} needs an R word (the retract plane) the first time")
            rprog = self.cycle_r
        else:
            rprog = rw.value
        cw_ = words.get(c_name)
        if cw_ is None:
            if first or self.cycle_cc is None:
                raise self.error("GC208", f"{gname(motion)} needs a {c_name} word (the bottom) the first time")
            cprog = self.cycle_cc
        else:
            cprog = cw_.value
        lw = words.get("L")
        reps = 1
        if lw is not None:
            if lw.value.denominator != 1 or lw.value < 1:
                raise self.error("GC209", f"canned cycle repeat count {lw.text} must be a positive integer", lw)
            reps = int(lw.value)
            if self.too_many(gname(motion), f"{gname(motion)} {lw.text}", reps, lw):
                return
        dwell = None
        delta = None
        if motion in (820, 840, 860, 890):
            pw = words.get("P")
            if pw is not None:
                if pw.value < 0:
                    raise self.error("GC209", f"dwell time {pw.text} is negative", pw)
                self.cycle_p = pw.value
            elif first and motion != 840:
                raise self.error("GC208", f"{gname(motion)} needs a P word (dwell time) the first time")
            # G84 dwells the sticky P of any earlier cycle (LinuxCNC convert_cycle_xy: p_number or cycle_p)
            dwell = self.cycle_p if (pw is not None or not first or motion == 840) else _ZERO
        if motion in (730, 830):
            qw = words.get("Q")
            if qw is not None:
                self.cycle_q = qw.value
            elif first or self.cycle_q is None:
                raise self.error("GC208", f"{gname(motion)} needs a Q word (peck depth) the first time")
            if self.cycle_q <= 0:
                raise self.error("GC209", f"peck depth Q{fmt_number(self.cycle_q)} must be greater than 0", qw)
            delta = self.length_mm(self.cycle_q)
        self.note_assumed(("units", "distance", "offset", "plane"))
        # Levels are (value, dependencies on axis ic); every comparison of two levels goes through
        # _level_lt, which says whether the branch is the same for every parameter value of the ranges.
        track = self.track
        nodeps: dict = {}
        current_cc = self.pos[ic]
        current_d = self.dep_pos[ic] if track else nodeps
        if self.cycle_il is None:
            self.cycle_il = current_cc
            self._cycle_il_axis = ic
            self._cycle_il_deps = dict(current_d)
        elif self._cycle_il_axis != ic:
            # a plane change between cycle blocks: LinuxCNC reads the same program number on the new normal axis
            if track:
                self.unknown(gname(motion), "a plane change while a canned cycle is modal is not followed with "
                              "parameter ranges")
                return
            self.cycle_il = self.cycle_il - self.off[self._cycle_il_axis] + self.off[ic]
            self._cycle_il_axis = ic
        old_cc, old_d = self.cycle_il, self._cycle_il_deps if track else nodeps
        il_cc = old_cc  # LinuxCNC's old_cc (minus the offset: program coordinates) for G91's R, read by pecks
        wd = {self.axes[i]: aw for i, aw in axis_words}
        if self.absolute:
            inc_a = inc_b = _ZERO
            r = qadd(self.length_mm(rprog), self.off[ic])
            cc = qadd(self.length_mm(cprog), self.off[ic])
            r_d = cc_d = self.dep_off[ic] if track else nodeps
            aa = qadd(self.length_mm(wd[a_name].value), self.off[ia]) if a_name in wd else self.pos[ia]
            bb = qadd(self.length_mm(wd[b_name].value), self.off[ib]) if b_name in wd else self.pos[ib]
            a_d = (self.dep_off[ia] if a_name in wd else self.dep_pos[ia]) if track else nodeps
            b_d = (self.dep_off[ib] if b_name in wd else self.dep_pos[ib]) if track else nodeps
        else:
            inc_a = self.length_mm(wd[a_name].value) if a_name in wd else _ZERO
            inc_b = self.length_mm(wd[b_name].value) if b_name in wd else _ZERO
            r = qadd(self.length_mm(rprog), old_cc)
            cc = qadd(r, self.length_mm(cprog))
            r_d = cc_d = old_d
            aa, bb = self.pos[ia], self.pos[ib]
            a_d = self.dep_pos[ia] if track else nodeps
            b_d = self.dep_pos[ib] if track else nodeps
        lt = self._level_lt
        if lt((r, r_d), (cc, cc_d), ic, "the retract plane R is below the bottom"):
            raise self.error("GC306", f"canned cycle retract plane R ({fmt_number(r)} mm machine) is below the bottom {c_name} ({fmt_number(cc)} mm machine)", rw or cw_)

        def go(kind, a, b, c, derived, here=False):
            """A move to (a, b) in the plane — the hole, or where the tool stands (``here``) — and level c."""
            end = list(self.pos)
            end[ia], end[ib], end[ic] = a, b, c[0]
            deps = None
            if track:
                deps = [dict(d) for d in self.dep_pos]
                if not here:
                    deps[ia], deps[ib] = dict(a_d), dict(b_d)
                deps[ic] = dict(c[1])
            self.emit(kind, end, feed=kind is _LINE, derived=derived, end_deps=deps)

        name = gname(motion)
        if lt((old_cc, old_d), (r, r_d), ic, "the initial level is below R"):
            go(_RAPID, self.pos[ia], self.pos[ib], (r, r_d), f"{name} up to R", here=True)
            old_cc, old_d = r, r_d
            current_cc, current_d = r, r_d
        clear = (r, r_d) if self.retract_r else (old_cc, old_d)
        for rep in range(reps):
            if rep and self.budget_gone(name, f"{lw.text if lw is not None else ''} had made {rep} repeats", lw):
                return
            if rep or not self.absolute:  # absolute: the increments are zero
                aa = qadd(aa, inc_a)
                bb = qadd(bb, inc_b)
            if rep == 0 and lt((r, r_d), (current_cc, current_d), ic, "R is below the current level"):
                go(_RAPID, aa, bb, (current_cc, current_d), f"{name} position")
                go(_RAPID, aa, bb, (r, r_d), f"{name} to R")
            else:
                go(_RAPID, aa, bb, clear, f"{name} position")
                if lt((r, r_d), clear, ic, "R is below the clear level"):
                    go(_RAPID, aa, bb, (r, r_d), f"{name} to R")
            if motion in (730, 830):
                assert delta is not None  # Q read above for G73/G83
                depth = r - delta
                pecks = None if track else self._linuxcnc_pecks(rprog, cprog, il_cc - self.off[ic])
                if pecks is not None and self.too_many(name, f"{name} Q{fmt_number(self.cycle_q or _ZERO)} (one "
                                                       "peck per Q)", pecks):
                    return
                made = 0
                while (lt((cc, cc_d), (depth, r_d), ic, "a peck ends above the bottom") if pecks is None
                       else pecks > 0):
                    made += 1
                    if made > self.max_repeats:  # with parameter ranges the count is not known before
                        self.too_many(name, f"{name} (one peck per Q)", made)
                        return
                    if pecks is not None:
                        pecks -= 1
                    go(_LINE, aa, bb, (depth, r_d), f"{name} peck")
                    if motion == 830:  # back out to R, not to the clear level (LinuxCNC convert_cycle_g83)
                        go(_RAPID, aa, bb, (r, r_d), f"{name} clear")
                    go(_RAPID, aa, bb, (depth + G83_RAPID_DELTA_MM, r_d), f"{name} back off")
                    depth -= delta
            if swapped:
                self._g84_swapped(plane, ia, ib, ic, aa, bb, cc, clear[0], dwell)
                continue
            go(_LINE, aa, bb, (cc, cc_d), f"{name} feed")
            if dwell is not None:
                self.emit(_DWELL, list(self.pos), dwell=dwell, derived=f"{name} dwell")
            if motion == 850:  # feed out to R only, then rapid to the clear level (LinuxCNC convert_cycle_g85)
                go(_LINE, aa, bb, (r, r_d), f"{name} retract")
                if clear[0] != r:
                    go(_RAPID, aa, bb, clear, f"{name} clear")
            elif motion in (840, 890):
                go(_LINE, aa, bb, clear, f"{name} retract")
            else:
                go(_RAPID, aa, bb, clear, f"{name} retract")
        self.cycle_cc = cprog
        self.cycle_r = rprog
        self.last_cycle = motion

    last_cycle: int | None = None
    feed_inverse_rate = False  # a G93 feed move set LinuxCNC's feed rate to its length x F (#<_feed> unknown)
    _cycle_il_deps: dict = {}
    spindle_slot_stale = False  # T0 M6 or M61 left the spindle slot's table entry behind the tool number
    _cycle_il_axis = 0

    def _level_lt(self, a: tuple[Fraction, dict], b: tuple[Fraction, dict], i: int, what: str) -> bool:
        """``a < b`` for two levels ``(value, dependencies)`` on axis ``i``: the branch of the path.

        Without parameter ranges, the plain comparison.  With ranges, the
        difference ``b - a`` is affine in the deviations of the ranged
        parameters; over their box it either has one sign (the branch taken
        at the nominal values holds for every value: returned) or it changes
        sign: then the interpretation stops as unknown, and when exactly one
        ranged parameter drives the difference, ``branch_split`` records it
        and the value where the branch switches, for the caller to verify
        the two sides and the switching value as separate cases
        (:func:`nczones.prover.verify` does).  The nominal branch with range
        dependencies is never taken.
        """
        nominal = _qlt(a[0], b[0])
        if not self.ranged:
            return nominal
        axis = self.axes[i]
        coeffs: dict[str, Fraction] = {}
        for src, c in dadd(b[1], a[1], -1).items():
            name = src if src.startswith("H") else f"{src}.{axis}"
            if name in self.ranged and c:
                coeffs[name] = coeffs.get(name, 0) + c
        coeffs = {n: c for n, c in coeffs.items() if c}
        if not coeffs:
            return nominal
        d0 = b[0] - a[0]
        lo = hi = d0
        lo_open = hi_open = False
        for n, c in coeffs.items():
            plo, phi, po_lo, po_hi = self.param_box[n]
            # c * [plo, phi]: the low end of the product comes from plo when c > 0
            (x, xo), (y, yo) = ((c * plo, po_lo), (c * phi, po_hi)) if c > 0 else ((c * phi, po_hi), (c * plo, po_lo))
            lo, hi = lo + x, hi + y
            lo_open, hi_open = lo_open or xo, hi_open or yo
        always = lo > 0 or (lo == 0 and lo_open)
        never = hi <= 0
        if always or never:
            if always == nominal:
                return nominal
        if len(coeffs) == 1 and not (always or never):
            ((n, c),) = coeffs.items()
            if self.branch_split is None:
                self.branch_split = (n, -d0 / c)
            self.unknown("parameter range", f"the canned cycle's branch ({what}) depends on {n}: it switches at "
                          f"{n} = {fmt_number(self.written_deviation(n, -d0 / c))} inside the range; each side is a "
                          "different path")
        elif always or never:
            self.unknown("parameter range", f"the canned cycle's branch ({what}) at the nominal values differs from "
                          f"the branch for every value of {', '.join(sorted(coeffs))} in the range")
        else:
            self.unknown("parameter range", f"the canned cycle's branch ({what}) depends on "
                          f"{' and '.join(sorted(coeffs))} together; each side is a different path (not split)")
        return nominal

    def written_deviation(self, name: str, dev: Fraction) -> Fraction:
        """A deviation of the interpreted nominal value, as ``--param`` writes the parameter."""
        centre = self.param_centre.get(name, _ZERO)
        if name.startswith("H"):
            return self.machine.tool_length(int(name[1:])) + dev
        return centre + dev

    def _g84_swapped(self, plane: Plane, ia: int, ib: int, ic: int, aa: Fraction, bb: Fraction, cc: Fraction,
                     clear: Fraction, dwell: Fraction | None) -> None:
        """G84's two feeds in G18/G19 as LinuxCNC really sends them (its canon logs ``tests/interp/g84``).

        LinuxCNC's G84 outside G17 feeds with the axis order of the *other*
        vertical plane: in G18 (a=Z, b=X, c=Y) to ``X=c, Y=a, Z=b``; in G19
        (a=Y, b=Z, c=X) to ``X=b, Y=c, Z=a`` (program values; each axis then
        gets its own offset).  Its interpreter believes the tool is at
        ``(a, b, clear)``: the next move is computed from there but starts
        where the machine is.
        """
        prog = {ia: aa - self.off[ia], ib: bb - self.off[ib]}
        ix, iy, iz = self.index["X"], self.index["Y"], self.index["Z"]

        def point(c_mm):
            a, b, c = prog[ia], prog[ib], c_mm - self.off[ic]
            x, y, z = (c, a, b) if plane is _XZ else (b, c, a)
            end = list(self.pos)
            end[ix], end[iy], end[iz] = x + self.off[ix], y + self.off[iy], z + self.off[iz]
            return end

        self.emit(_LINE, point(cc), feed=True, derived="G84 feed (LinuxCNC axis order outside G17)")
        if dwell is not None:
            self.emit(_DWELL, list(self.pos), dwell=dwell, derived="G84 dwell")
        self.emit(_LINE, point(clear), feed=True, derived="G84 retract (LinuxCNC axis order outside G17)")
        actual = tuple(self.pos)
        believed = list(self.pos)
        believed[ia], believed[ib], believed[ic] = aa, bb, clear
        self.pos = believed
        if tuple(believed) != actual:
            self.machine_at = actual


_LINUXCNC_STATE = linuxcnc_state_parameters()


def _show_key(key: int | str) -> str:
    return f"#{key}" if isinstance(key, int) else f"#<{key}>"


def linuxcnc_rejects_arc(r0_sq: Fraction, r1_sq: Fraction, inch: bool) -> bool:
    """LinuxCNC's acceptance rule for an I/J/K arc (interp_arc.cc ``arc_data_ijk``), in its doubles.

    With ``A`` = CENTER_ARC_RADIUS_TOLERANCE (2 * 0.01 * sqrt 2 mm, or
    2 * 0.001 * sqrt 2 in under G20) and the relative tolerance 0.001, the arc
    is refused when ``|r1 - r0| > 100 A``, or when ``|r1 - r0| > A`` and
    ``|r1 - r0| / max(r0, r1) > 0.001``.  This only decides acceptance, the
    way the controller decides it; an accepted arc is modelled exactly as the
    spiral from radius r0 to r1 that the machine moves.

    >>> from fractions import Fraction as F
    >>> linuxcnc_rejects_arc(F(100), F("100.5"), False), linuxcnc_rejects_arc(F(1), F(4), False)
    (False, True)
    """
    from math import sqrt

    from ..exact import to_float

    r0, r1 = sqrt(to_float(r0_sq)), sqrt(to_float(r1_sq))
    if inch:  # LinuxCNC compares in program units
        r0, r1 = r0 / 25.4, r1 / 25.4
    tol = 2 * (0.001 if inch else 0.01) * sqrt(2)
    abs_err = abs(r1 - r0)
    rel_err = abs_err / max(r0, r1)
    return abs_err > 100 * tol or (abs_err > tol and rel_err > 0.001)


def sqrt_diff_exceeds(a: Fraction, b: Fraction, t: Fraction) -> bool:
    """Exactly: |sqrt(a) - sqrt(b)| > t for a, b >= 0, t >= 0."""
    # (sqrt a - sqrt b)^2 = a + b - 2 sqrt(ab) > t^2  <=>  a + b - t^2 > 2 sqrt(ab)
    lhs = a + b - t * t
    if lhs <= 0:
        return False
    return lhs * lhs > 4 * a * b


def _fmt_sqrt(q: Fraction) -> str:
    # an exact enclosure would be overkill for a message; 6 decimals by integer sqrt
    import math

    from ..exact import format_decimal

    scaled = q * 10**12
    root = math.isqrt(int(scaled))
    return format_decimal(Fraction(root, 10**6), places=6)


def blocks_from_words(lines: Iterable[Iterable[str]], file: str = "<words>") -> list[Block]:
    """Blocks from tuples of word texts (``("G1", "X1.5")``); for examples and tests.

    Not a lexer: each item must be one word, letter then decimal.

    >>> [w.value for w in blocks_from_words([("G59.1", "X-.5")])[0].words]
    [Fraction(591, 10), Fraction(-1, 2)]
    """
    from ..exact import parse_decimal

    out = []
    for n, words in enumerate(lines):
        text = " ".join(words)
        span = SourceSpan(file, n + 1, 1, None, text)
        ws = []
        col = 1
        for t in words:
            ws.append(Word(t[0].upper(), parse_decimal(t[1:]), SourceSpan(file, n + 1, col, col + len(t), text), t))
            col += len(t) + 1
        out.append(Block(tuple(ws), span, n))
    return out


def _spline_block(it: Any, motion: int, axis_words: Any, words: Any, g1: Any) -> None:
    """:func:`.linuxcnc.splines.spline_block`, its module imported at the first spline motion (start-up, boot44)."""
    from .linuxcnc.splines import spline_block

    spline_block(it, motion, axis_words, words, g1)


def _spline_pending(it: Any) -> Any:
    """:func:`.linuxcnc.splines.spline_pending` (asked once a spline motion has loaded the module)."""
    from .linuxcnc.splines import spline_pending

    return spline_pending(it)
