"""LinuxCNC cutter radius compensation (G41/G42, G41.1/G42.1, G40), as its interpreter computes it.

Opt-in per machine (``[machine] cutter_compensation = "linuxcnc"``): other
controls (Fanuc type A/B/C start-up, intersection vectors at convex corners)
move differently, so with the default ``"none"`` G41/G42 make the result
``unknown``.

What LinuxCNC does (``interp_convert.cc`` ``convert_straight_comp1/2``,
``convert_arc_comp1/2``; ``interp_queue.cc``), reimplemented here:

* The first move after G41/G42 (a line or an arc) is an entry move: it ends
  one tool radius from its programmed end point, perpendicular to the entry
  direction (lines) or along the arc's radius (arcs).
* Every later move ends one radius to the side of its programmed end point.
  At a **convex** corner (the turn exceeds 0.05 rad) a feed inserts an arc of
  the tool radius around the programmed corner point (a rapid inserts a
  straight traverse instead); at a **concave** corner the previous move is
  held back in a queue and its end point is moved back to where the tool
  touches both elements.  If that reverses the previous move (the tool does
  not fit), the program is rejected: "... in concave corner cannot be reached
  by the tool without gouging".
* G40 and program end (M2/M30, and M0/M1/M60) flush the queue; after G40 the
  interpreter believes the tool is at the programmed point while it stands at
  the compensated one, so the next move starts where the machine is.

Numbers: LinuxCNC computes this geometry in IEEE doubles (angles, sines,
square roots).  So does this module, with the same formulas in the same
order, in the program's frame and units (program coordinates without the
work offsets, inch under G20); every resulting double is then taken
**exactly** as a rational (``Fraction(float)``) and shifted by the exact
offsets, the stance of :mod:`nczones.gcode.expr` for expressions.  Floats
appear only in the ``_f*`` helpers and local variables of this module; every
emitted segment holds exact Fractions.  The arc inserted at a convex corner
has the exact programmed corner point as its centre.

Invariants
----------
* Emitted segments are continuous: each starts where the previous one ended
  (a queued move's end may still move before it is emitted).
* Each segment keeps the block index and span of the block that programmed
  it; a corner arc carries the span of the block it precedes and
  ``derived="cutter comp corner"``.
* The programmed position (``Interpreter.pos``) stays the programmed point;
  the compensated position lives here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Protocol

from ...errors import Diagnostic, GcodeError
from ...exact import to_float
from ...motion import PLANE_AXES, Plane, SegmentKind
from ..segments import make_segment, with_tool_deps
from .comp_floats import (
    CONCAVE_TOLERANCE_RAD,
    ENTRY_COS,
    ENTRY_SHORT,
    GOUGE,
    LEFT,
    RADIUS,
    SAME_CENTRE,
    SPIRAL,
    arc_arc_back,
    arc_centre_r,
    arc_corner,
    arc_entry,
    arc_line_back,
    arc_moved,
    entry_line,
    find_turn,
    line_arc_back,
    line_corner,
    retreat,
    reverses,
)
from .comp_floats import RIGHT as _RIGHT

if TYPE_CHECKING:
    from collections.abc import Sequence

    from ...errors import SourceSpan
    from ...machine import Machine
    from ...motion import ProgramFrame, Segment
    from ..blocks import Block, Word


class CompensatedInterpreter(Protocol):
    """What cutter compensation reads and drives of the interpreter it compensates for
    (:class:`nczones.gcode.interpreter.Interpreter`): its state, its emission of segments and its arc rule.

    Declared here, below the interpreter, so that this module does not import the interpreter back.
    """

    pos: Sequence[Fraction]
    dep_pos: list[dict[str, int]]
    machine_at: tuple[Fraction, ...] | None
    comp_on: bool
    comp_just_off: bool
    segment_count: int

    @property
    def machine(self) -> Machine: ...
    @property
    def axes(self) -> tuple[str, ...]: ...
    @property
    def index(self) -> dict[str, int]: ...
    @property
    def plane(self) -> Plane: ...
    @property
    def inch(self) -> bool: ...
    @property
    def track(self) -> bool: ...
    @property
    def ranged(self) -> frozenset[Any]: ...
    @property
    def off(self) -> list[Fraction]: ...
    @property
    def dep_off(self) -> list[dict[Any, Any]]: ...
    @property
    def tlo(self) -> Fraction: ...
    @property
    def tool_register(self) -> int | None: ...
    @property
    def tool_in_spindle(self) -> int: ...
    @property
    def feed(self) -> Fraction: ...
    @property
    def feed_mode(self) -> int: ...
    @property
    def prerotation_xy(self) -> list[Fraction] | None: ...
    @property
    def unsupported(self) -> Sequence[object]: ...
    @property
    def span(self) -> SourceSpan | None: ...
    @property
    def block_index(self) -> int: ...
    @property
    def kind_counts(self) -> dict[SegmentKind, int]: ...
    @property
    def emitted(self) -> list[Segment]: ...

    def unknown(self, code: str, reason: str, word: Word | None = None) -> None: ...
    def length_mm(self, v: Fraction) -> Fraction: ...
    def deps_tuple(self, deps: list[dict[Any, Any]]) -> tuple[tuple[str, ...], ...]: ...
    def tool_dep_names(self) -> tuple[str, ...]: ...
    def program_frame(self) -> ProgramFrame: ...
    def emit(self, kind: SegmentKind, end: list[Fraction], *, feed: bool = False, derived: str = "",
             plane: Plane | None = None, clockwise: bool = False, centre: Any = None, radius: Any = None,
             turns: int = 0, dwell: Fraction | None = None, end_deps: list[dict[Any, Any]] | None = None) -> None: ...
    def arc(self, block: Block, axis_words: list[tuple[int, Word]], words: dict[str, Word], cw: bool,
            g53: bool) -> None: ...

__all__ = ["CutterComp", "CONCAVE_TOLERANCE_RAD"]

_INCH = Fraction(254, 10)

#: segment kinds by plain names (Python 3.11 reads an Enum member through ``EnumType.__getattr__``, slowly)
_ARC, _LINE, _RAPID, _DWELL = SegmentKind.ARC, SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.DWELL

#: GC codes of cutter compensation errors.
GC_STATE = "GC320"      # comp turned on in a wrong state (plane, already on, D word)
GC_TOOL = "GC321"       # tool diameter missing
GC_ENTRY = "GC322"      # entry move / arc too short
GC_RADIUS = "GC323"     # tool radius not less than arc radius
GC_GOUGE = "GC324"      # concave corner the tool cannot reach
GC_FORBIDDEN = "GC325"  # an operation LinuxCNC refuses while comp is on
GC_BUG = "GC329"        # LinuxCNC's own consistency checks ("BUG: ...")


@dataclass(slots=True)
class _Move:
    """A move waiting in LinuxCNC's queue (in-plane end as doubles in program frame/units)."""

    kind: SegmentKind
    a: float
    b: float
    end: list  # machine end, exact, all axes (plane axes replaced from a, b when emitted)
    da: float = 0.0  # programmed direction (lines), for the gouging check
    db: float = 0.0
    ca: float = 0.0  # centre (arcs), doubles
    cb: float = 0.0
    centre: tuple | None = None  # exact machine centre to emit (arcs)
    turn: int = 0  # arcs: +-(turns + 1), positive counterclockwise
    sweep: float = 0.0  # LinuxCNC original_turns (radians)
    block: int = 0
    span: object = None
    feed: Fraction | None = None
    derived: str = ""
    deps: list | None = None
    dwell: Fraction | None = None


#: the program unit in millimetres as (numerator, denominator): G21, G20
_MM_PARTS, _INCH_PARTS = (1, 1), (_INCH.numerator, _INCH.denominator)


def machine_exact(value: float, off: Fraction, unit: tuple[int, int]) -> Fraction:
    """``Fraction(value) * unit + off``: the exact machine coordinate of the program-frame double ``value``
    (``unit``: the program unit in mm as ``(numerator, denominator)``, ``off``: the axis's exact offset).

    The same value as that formula (one Fraction instead of three operations, each normalising): ``value`` is
    ``n / d`` exactly (``float.as_integer_ratio``), so the sum is the integer quotient
    ``(n un q + p d ud) / (d ud q)`` with ``off = p / q``, ``unit = un / ud``; ``Fraction`` normalises it, so
    numerator and denominator are the formula's too.

    >>> machine_exact(0.1, Fraction(100), (1, 1)) == Fraction(0.1) + 100
    True
    >>> machine_exact(-2.5, Fraction(1, 3), (127, 5))
    Fraction(-379, 6)
    """
    n, d = value.as_integer_ratio()
    p, q = off.as_integer_ratio()
    un, ud = unit
    return Fraction(n * un * q + p * d * ud, d * ud * q)


def program_double(value: Fraction, off: Fraction, unit: tuple[int, int]) -> float:
    """``to_float((value - off) / unit)``: the program-frame double of an exact machine coordinate.

    The same double: the quotient is ``(vn q - p vd) ud / (vd q un)`` with ``value = vn / vd``, ``off = p / q``,
    ``unit = un / ud`` (positive denominators), and Python's division of two integers is correctly rounded,
    as :func:`~nczones.exact.to_float`'s division of the normalised parts is: one rational, one rounding.

    >>> program_double(Fraction(1001, 10), Fraction(100), (1, 1)) == to_float(Fraction(1, 10))
    True
    """
    vn, vd = value.as_integer_ratio()
    p, q = off.as_integer_ratio()
    un, ud = unit
    return ((vn * q - p * vd) * ud) / (vd * q * un)


@dataclass
class CutterComp:
    """Cutter compensation state and LinuxCNC's move queue for one :class:`Interpreter`.

    The interpreter calls :meth:`select` for G40/G41/G42/G41.1/G42.1,
    :meth:`check_block` for every block while compensation is on,
    :meth:`straight` and :meth:`arc` for moves while it is :attr:`active`,
    :meth:`dwell`, :meth:`stop` (M0/M1/M60) and :meth:`program_end`.

    Examples
    --------
    >>> from nczones.machine import parse_machine
    >>> from nczones.gcode.interpreter import Interpreter, blocks_from_words
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X", "Y"]
    ... cutter_compensation = "linuxcnc"
    ... [machine.rapid]
    ... X = "1000"
    ... Y = "1000"
    ... [machine.reference]
    ... X = "0"
    ... Y = "0"
    ... ''')
    >>> it = Interpreter(m)

    A right turn with the tool on the left is a convex corner: an arc of the
    tool radius around the programmed corner (10, 0), exactly:

    >>> prog = [("G41.1", "D2", "G1", "X10", "F100"), ("X10", "Y-10"), ("G40", "X20")]
    >>> segs = [s for c in it.run(blocks_from_words(prog)) for s in c.segments()]
    >>> [(s.kind.name, s.derived, [round(float(v), 9) for v in s.end]) for s in segs]
    [('LINE', '', [10.0, 1.0]), ('ARC', 'cutter comp corner', [11.0, 0.0]), ('LINE', '', [11.0, -10.0]), ('LINE', '', [20.0, -10.0])]
    >>> segs[1].centre, segs[1].clockwise
    ((Fraction(10, 1), Fraction(0, 1)), True)
    """

    it: CompensatedInterpreter
    side: int | None = None
    radius: float = 0.0
    first: bool = True
    queue: list = field(default_factory=list)
    endpoint: tuple[float, float] = (0.0, 0.0)
    endpoint_valid: bool = False
    cur: tuple[float, float] = (0.0, 0.0)  # compensated position, program frame (doubles)
    prog: tuple[float, float] = (0.0, 0.0)  # programmed position, program frame (doubles)
    machine_now: tuple | None = None  # where the last emitted segment ended (machine, exact)
    orientation: int = 0  # lathe tool orientation (G41.1/G42.1 L): the controlled point is not the nose centre
    deps_now: list | None = None
    #: the last plane :meth:`_axes` was asked for, and its answer (the plane cannot change while compensation is on)
    axes_of: tuple[Plane | None, tuple[int, int, int | None]] = (None, (0, 0, None))

    # ------------------------------------------------------------------ frame
    def _axes(self) -> tuple[int, int, int | None]:
        it = self.it
        plane = it.plane
        last = self.axes_of
        if last[0] is plane:
            return last[1]
        a, b, n = PLANE_AXES[plane]
        axes = it.index[a], it.index[b], it.index.get(n)
        self.axes_of = (plane, axes)
        return axes

    def _unit(self) -> Fraction:
        return _INCH if self.it.inch else Fraction(1)

    def _fprog(self, i: int, machine_value: Fraction) -> float:
        """Program-frame double of an exact machine coordinate (what LinuxCNC holds): :func:`program_double`."""
        return program_double(machine_value, self.it.off[i], _INCH_PARTS if self.it.inch else _MM_PARTS)

    def _fmachine(self, i: int, value: float) -> Fraction:
        """Exact machine coordinate of a program-frame double: :func:`machine_exact`."""
        return machine_exact(value, self.it.off[i], _INCH_PARTS if self.it.inch else _MM_PARTS)

    def current_point(self, i: int) -> tuple[bool, Fraction | None]:
        """Axis ``i`` of the compensated current point (LinuxCNC's ``settings->current_x`` ..), machine
        coordinates: ``(False, None)`` for an axis outside the compensation plane."""
        ia, ib, _ = self._axes()
        if i not in (ia, ib):
            return False, None
        return True, self._fmachine(i, self.cur[0 if i == ia else 1])

    def error(self, code: str, message: str, word: Any = None) -> GcodeError:
        span = word.span if word is not None else self.it.span
        return GcodeError(Diagnostic(code, message, span))

    @property
    def active(self) -> bool:
        """Compensation on with a positive radius (LinuxCNC compensates only then)."""
        return self.side is not None and self.radius > 0.0

    # ------------------------------------------------------------------ G40 / G41 / G42
    def select(self, key: int, word: Any, words: dict) -> None:
        """G40 (key 400), G41 (410), G42 (420), G41.1 (411), G42.1 (421) (``convert_cutter_compensation``)."""
        it = self.it
        if key == 400:
            self.off()
            return
        name = f"G{key // 10}" + (f".{key % 10}" if key % 10 else "")
        if it.plane not in (Plane.XY, Plane.XZ):
            raise self.error(GC_STATE, f"{name}: cutter radius compensation is only allowed in the XY (G17) and "
                              f"XZ (G18) planes; G{int(it.plane)} is active", word)
        if self.side is not None:
            raise self.error(GC_STATE, f"{name}: cannot turn cutter radius compensation on when it is already on "
                              "(write G40 first)", word)
        side = LEFT if key in (410, 411) else _RIGHT
        d = words.get("D")
        if key in (411, 421):
            if d is None:
                raise self.error(GC_STATE, f"{name} with no D word: the D word gives the tool diameter", word)
            radius = to_float(d.value) / 2
            orientation = 0
            lw = words.get("L")
            if lw is not None:
                if it.plane is not Plane.XZ:
                    raise self.error(GC_STATE, f"{name} with L word, but plane is not G18", lw)
                if lw.value.denominator != 1 or not 0 <= lw.value <= 9:
                    raise self.error(GC_STATE, f"{name} L{lw.text}: a lathe tool orientation is 0 to 9", lw)
                orientation = int(lw.value)
        else:
            if d is None:
                tool = it.tool_in_spindle
            else:
                tool = int(to_float(d.value) + 0.5)
                if abs(tool - to_float(d.value)) >= 0.0001:
                    raise self.error(GC_STATE, f"{name} requires the D word to be a whole number (tool number); "
                                      f"got {d.text}", d)
                if d.value < 0:
                    raise self.error(GC_STATE, f"negative D word tool number {d.text} used", d)
                if tool == 0:
                    # D0 is the tool in the spindle: LinuxCNC find_tool_index gives tool 0 the spindle's entry
                    tool = it.tool_in_spindle
            if (d is None or d.value == 0) and getattr(it, "spindle_slot_stale", False):
                # as G43 without H: rs274 reads the spindle slot's table entry, which T0 M6 and M61 leave behind
                # (rs274_findings/m61-current-tool.ngc: M61 Q4 G41 G1 X22.8 is offset by another diameter)
                it.unknown(name, f"{name} of the tool in the spindle after T0 M6 or M61: LinuxCNC's interpreter "
                           "reads its spindle slot's table entry, which those leave as it was; not modelled", word)
            diameters = dict(getattr(it.machine, "tool_diameters", {}))
            diameters.update(getattr(it, "tool_diameters_set", {}))  # G10 L1/L10/L11 R
            if tool not in diameters:
                if tool != 0:
                    known = ", ".join(f"T{t}" for t in sorted(diameters)) or "none"
                    raise self.error(GC_TOOL, f"{name} uses tool {tool}, whose diameter is not in the machine "
                                      f"file's [tool_diameters] (known: {known}); add T{tool} = \"<diameter mm>\"",
                                      d if d is not None else word)
                dia = Fraction(0)  # LinuxCNC: an empty spindle has diameter 0
            else:
                dia = diameters[tool]
            radius = to_float(dia / self._unit()) / 2.0
            orientation = 0
            if it.plane is Plane.XZ and radius != 0.0:
                it.unknown(name, f"{name} in G18 uses the tool table's lathe tool orientation, which shifts the "
                            "controlled point (LinuxCNC latheorigin) and is not in the machine file; use G41.1/G42.1 "
                            "D<diameter> L<orientation>", word)
        if radius < 0.0:
            radius = -radius
            side = _RIGHT if side == LEFT else LEFT
        if it.prerotation_xy is not None:
            it.unknown(name, "cutter radius compensation in a rotated coordinate system (G10 L2 R) is not modelled",
                        word)
        if type(it).__name__ not in ("Interpreter", "LatheInterpreter"):
            it.unknown(name, "cutter radius compensation with cylindrical interpolation is not modelled", word)
        if it.ranged:
            from ..segments import dadd

            # the compensation is computed in the program frame; offsets cannot change while it is on, so
            # it follows the ranges exactly when the position it starts from is fixed in that frame
            ia, ib, _ = self._axes()
            moving = sorted({(src if src.startswith("H") else f"{src}.{it.axes[i]}")
                             for i in (ia, ib) for src, c in dadd(it.dep_pos[i], it.dep_off[i], -1).items()
                             if c} & it.ranged)
            if moving:
                it.unknown(name, f"cutter radius compensation starting from a position whose program coordinates "
                            f"depend on the parameter range {', '.join(moving)}: the compensated path is not a "
                            "shifted copy of the nominal one", word)
        self.side = side
        self.radius = radius
        self.orientation = orientation if it.plane is Plane.XZ else 0
        self.first = True
        self.queue = []
        it.comp_on = True

    def off(self) -> None:
        """G40: flush the queue at the compensated position; the next move starts from there."""
        it = self.it
        if self.active and not self.first:
            self._move_endpoint_and_flush(*self.cur)
            self._dequeue()
            it.comp_just_off = True
            if self.machine_now is not None and tuple(self.machine_now) != tuple(it.pos):
                it.machine_at = tuple(self.machine_now)
        self.side = None
        self.first = True
        it.comp_on = False

    # ------------------------------------------------------------------ refusals
    def check_block(self, groups: dict, mcodes: Any, words: dict, axis_words: Any, motion: Any) -> None:
        """LinuxCNC's refusals while compensation is on, and what nczones cannot model then."""
        it = self.it
        g0 = groups.get(0)
        if any(k == 6 for k, _ in mcodes):
            w = next(w for k, w in mcodes if k == 6)
            raise self.error(GC_FORBIDDEN, "cannot change tools (M6) with cutter radius compensation on", w)
        if 8 in groups:
            raise self.error(GC_FORBIDDEN, "cannot change the tool length offset (G43/G49) with cutter radius "
                              "compensation on", groups[8][1])
        if 6 in groups:
            raise self.error(GC_FORBIDDEN, "cannot change units (G20/G21) with cutter radius compensation on",
                              groups[6][1])
        if 2 in groups:
            k, w = groups[2]
            target = {170: Plane.XY, 180: Plane.XZ, 190: Plane.YZ}.get(k)
            if target is not it.plane:
                raise self.error(GC_FORBIDDEN, "cannot change planes with cutter radius compensation on", w)
        if g0 is not None:
            k, w = g0
            if k in (920, 921, 922, 923, 520):
                raise self.error(GC_FORBIDDEN, "cannot change axis offsets (G92/G52) with cutter radius "
                                  "compensation on", w)
            if k in (280, 300):
                raise self.error(GC_FORBIDDEN, "cannot use G28 or G30 with cutter radius compensation on", w)
            if k == 530 and self.active and axis_words:
                raise self.error(GC_FORBIDDEN, "cannot use G53 with cutter radius compensation on", w)
            if k == 100:
                it.unknown("G10", "G10 while cutter radius compensation is on (offsets or the tool table change "
                            "under a held move) is not modelled", w)
        if 12 in groups:
            it.unknown(f"G{groups[12][0] // 10}", "changing the work offset while cutter radius compensation is "
                        "on is not modelled", groups[12][1])
        g1 = groups.get(1)
        m = g1[0] if g1 is not None else motion
        if m in (52, 53, 62) or (g1 is not None and g1[0] in (51, 50)):
            raise self.error(GC_FORBIDDEN, "cannot convert a spline (G5/G5.1/G5.2/G6.2) with cutter radius "
                              "compensation on", g1[1] if g1 is not None else None)

    # ------------------------------------------------------------------ queue
    def _set_endpoint(self, a: float, b: float) -> None:
        self.endpoint = (a, b)
        self.endpoint_valid = True

    def _enqueue(self, move: _Move) -> None:
        it = self.it
        move.block = it.block_index
        move.span = it.span
        if move.kind is not _RAPID and move.dwell is None and it.feed_mode == 94:
            move.feed = it.length_mm(it.feed)
        self.queue.append(move)

    def _lathe_origin(self) -> tuple[Fraction, Fraction]:
        """The shift (Z, X) from the nose centre to the controlled point of a lathe tool (LinuxCNC
        ``latheorigin_z``/``latheorigin_x``): orientations 1, 2, 6 lower X by the radius and 3, 4, 8 raise it;
        2, 3, 7 lower Z and 1, 4, 5 raise it; 0 and 9 (and a mill) none.  Exact: the radius double, times the
        unit (LinuxCNC adds it in doubles, at most a unit in the last place away)."""
        o = self.orientation
        r = Fraction(self.radius) * self._unit()
        dx = -r if o in (1, 2, 6) else r if o in (3, 4, 8) else Fraction(0)
        dz = -r if o in (2, 3, 7) else r if o in (1, 4, 5) else Fraction(0)
        return dz, dx

    def _dequeue(self) -> None:
        """Emit the queued moves (LinuxCNC ``dequeue_canons``; a lathe tool's moves shifted from the nose centre
        to its controlled point)."""
        it = self.it
        self.endpoint_valid = False
        ia, ib, _ = self._axes()
        shift = self._lathe_origin() if self.orientation else None
        unit = _INCH_PARTS if it.inch else _MM_PARTS
        oa, ob = it.off[ia], it.off[ib]
        for q in self.queue:
            start = self.machine_now
            assert start is not None  # set when compensation started (_start)
            if q.dwell is not None:
                end = start
            else:
                e = list(q.end)
                e[ia] = machine_exact(q.a, oa, unit)
                e[ib] = machine_exact(q.b, ob, unit)
                if shift is not None:
                    e[ia] += shift[0]
                    e[ib] += shift[1]
                end = tuple(e)
            if not it.unsupported:
                self._emit(q, start, end, shift)
            self.machine_now = end
            if q.deps is not None:
                self.deps_now = q.deps
        self.queue = []

    def _emit(self, q: _Move, start: tuple, end: tuple, shift: tuple[Fraction, Fraction] | None) -> None:
        """The segment of queued move ``q`` from ``start`` to ``end`` (machine, exact), appended to the
        interpreter's emitted segments."""
        it = self.it
        ds: tuple = ()
        de: tuple = ()
        dt: tuple = ()
        if it.track:
            ds = it.deps_tuple(self.deps_now if self.deps_now is not None else it.dep_pos)
            de = it.deps_tuple(q.deps if q.deps is not None else (self.deps_now or it.dep_pos))
            dt = it.tool_dep_names()
        kind = q.kind
        arc = kind is _ARC
        centre = q.centre if arc else None
        if centre is not None and shift is not None and (shift[0] or shift[1]):
            centre = (centre[0] + shift[0], centre[1] + shift[1])
        seg = make_segment(kind, start, end, it.axes, q.block, q.span, it.tlo, q.feed, it.plane if arc else None,
                           arc and q.turn < 0, centre, None, abs(q.turn) - 1 if arc else 0, q.dwell, q.derived,
                           it.tool_register, ds, de, (), it.program_frame())
        it.emitted.append(with_tool_deps(seg, dt) if dt else seg)
        it.segment_count += 1
        it.kind_counts[kind] += 1

    def _move_endpoint_and_flush(self, x: float, y: float) -> None:
        """Move the end of every queued move to (x, y), refusing reversals; then emit them (``interp_queue.cc``)."""
        if not self.queue:
            return
        ex, ey = self.endpoint
        for q in self.queue:
            if q.dwell is not None:
                continue
            if q.kind is _ARC:
                bad = arc_moved(q.a, q.b, q.ca, q.cb, q.turn, q.sweep, x, y, ex, ey, self.endpoint_valid,
                                self.it.inch)
                if bad == SPIRAL:
                    r1, r2 = math.hypot(q.a - q.ca, q.b - q.cb), math.hypot(x - q.ca, y - q.cb)
                    raise self.error(GC_BUG, f"cutter compensation generated an invalid arc with mismatched radii "
                                      f"{r1:.6f} and {r2:.6f} (LinuxCNC reports this as a BUG and stops)")
                if bad == GOUGE:  # interp_queue.cc: the sweep may grow by .0254 (G21) or .001 (G20)
                    raise self.error(GC_GOUGE, "Arc move in concave corner cannot be reached by the tool without "
                                      "gouging (cutter radius compensation)")
            else:
                if self.endpoint_valid and reverses(q.da, q.db, x, y, ex, ey):
                    what = "Straight traverse" if q.kind is _RAPID else "Straight feed"
                    raise self.error(GC_GOUGE, f"{what} in concave corner cannot be reached by the tool without "
                                      "gouging (cutter radius compensation: the move shrinks past its start)")
            q.a, q.b = x, y
        self._dequeue()
        self._set_endpoint(x, y)

    def _front_is_arc(self, what: str) -> bool:
        if not self.queue:
            self.it.unknown("cutter comp", f"{what} right after the compensation queue was flushed (M0/M1/M60): "
                             "LinuxCNC reads an empty move queue there; not modelled")
            return False
        return self.queue[0].kind is _ARC

    def _start(self) -> None:
        """Before a compensated move: fix where the machine is and the compensated start of a first move."""
        it = self.it
        if self.machine_now is None or (self.first and not self.queue):
            self.machine_now = tuple(it.machine_at) if it.machine_at is not None else tuple(it.pos)
            self.deps_now = [dict(d) for d in it.dep_pos] if it.track else None
            it.machine_at = None
        if self.first:
            ia, ib, _ = self._axes()
            self.prog = (self._fprog(ia, it.pos[ia]), self._fprog(ib, it.pos[ib]))
            self.cur = self.prog

    def _corner_end(self, end: list) -> list:
        """Machine end of an inserted corner move: the normal axis stays, the other axes already reach the end."""
        it = self.it
        ia, ib, inn = self._axes()
        e = list(end)
        if inn is not None:
            e[inn] = it.pos[inn]
        return e

    def _advance(self, end: list, deps: Any) -> None:
        it = self.it
        it.pos = list(end)
        if deps is not None:
            it.dep_pos = deps

    # ------------------------------------------------------------------ straight moves
    def straight(self, kind: SegmentKind, end: list, deps: Any) -> None:
        """A G0/G1 move to the programmed machine point ``end`` with compensation on."""
        self._start()
        ia, ib, _ = self._axes()
        px, py = self._fprog(ia, end[ia]), self._fprog(ib, end[ib])
        if self.first:
            self._straight_first(kind, px, py, end, deps)
        else:
            self._straight_next(kind, px, py, end, deps)
        self._advance(end, deps)

    def _straight_first(self, kind: SegmentKind, px: float, py: float, end: list, deps: Any) -> None:
        radius, side = self.radius, self.side
        cx, cy = self.cur
        got = entry_line(side, radius, cx, cy, px, py)
        if got is None:
            distance = math.hypot(px - cx, py - cy)
            raise self.error(GC_ENTRY, "Length of cutter compensation entry move is not greater than the tool "
                              f"radius ({distance:.6f} <= {radius:.6f} program units)")
        ex, ey, da, db = got
        self._set_endpoint(cx, cy)
        self._enqueue(_Move(kind, ex, ey, list(end), da, db, deps=deps))
        self.first = False
        self.cur = (ex, ey)
        self.prog = (px, py)

    def _straight_next(self, kind: SegmentKind, px: float, py: float, end: list, deps: Any) -> None:
        it = self.it
        cx, cy = self.cur
        opx, opy = self.prog
        if py == opy and px == opx:  # no motion in the plane
            self._enqueue(_Move(kind, cx, cy, list(end), 0.0, 0.0, deps=deps))
            return
        side, radius = self.side, self.radius
        front = self.queue[0].turn if self.queue and self.queue[0].kind is _ARC else 0
        concave, beta, end_x, end_y, mid_x, mid_y, theta, gamma = line_corner(side, radius, cx, cy, opx, opy,
                                                                               px, py, front)
        ia, ib, _ = self._axes()
        if not concave and beta > CONCAVE_TOLERANCE_RAD:  # convex: go around the corner
            self._move_endpoint_and_flush(cx, cy)
            corner = self._corner_end(end)
            corner_deps = [dict(d) for d in it.dep_pos] if it.track else None
            if kind is _LINE:
                centre = (it.pos[ia], it.pos[ib])  # the programmed corner, exact
                self._enqueue(_Move(_ARC, mid_x, mid_y, corner, ca=opx, cb=opy, centre=centre,
                                    turn=-1 if side == LEFT else 1, derived="cutter comp corner", deps=corner_deps))
            else:
                self._enqueue(_Move(_RAPID, mid_x, mid_y, corner, derived="cutter comp corner",
                                    deps=corner_deps))
            self._dequeue()
            self._set_endpoint(mid_x, mid_y)
        elif concave:
            if not self._front_is_arc("a concave corner"):
                if not self.queue:
                    self._enqueue(_Move(kind, end_x, end_y, list(end), px - opx, py - opy, deps=deps))
                    self.cur, self.prog = (end_x, end_y), (px, py)
                    return
                back = retreat(radius, cx, cy, beta, theta, gamma)
                if back is None:
                    raise self.error(GC_GOUGE, "Zero degree inside corner is invalid for cutter compensation")
                self._move_endpoint_and_flush(*back)
            else:
                prev = self.queue[0]
                back = arc_line_back(side, radius, prev.a, prev.b, prev.ca, prev.cb, prev.turn, opx, opy, px, py)
                if back is None:
                    raise self.error(GC_GOUGE, "Arc to straight motion makes a corner the compensated tool can't fit "
                                     "in without gouging")
                self._move_endpoint_and_flush(*back)
        else:  # straight on (or tangent arc -> line)
            self._dequeue()
            self._set_endpoint(cx, cy)
        self._enqueue(_Move(kind, end_x, end_y, list(end), px - opx, py - opy, deps=deps))
        self.cur = (end_x, end_y)
        self.prog = (px, py)

    # ------------------------------------------------------------------ arcs
    def arc(self, block: Any, axis_words: Any, words: dict, cw: bool) -> None:
        """A G2/G3 move with compensation on.

        The interpreter's own arc conversion runs first on the programmed arc
        (its checks and its exact centre); its emission is captured, then the
        compensated arc is computed here.
        """
        it = self.it
        captured: list[tuple[Any, dict[str, Any]]] = []

        def capture(kind: SegmentKind, end: Any, **kw: Any) -> None:
            captured.append((end, kw))

        it.emit = capture  # type: ignore[method-assign]  # the arc's emission, captured
        try:
            it.arc(block, axis_words, words, cw, False)
        finally:
            del it.emit
        if not captured or it.unsupported:
            return
        end, kw = captured[0]
        deps = kw.get("end_deps")
        turns = kw.get("turns", 0)
        self._start()
        ia, ib, _ = self._axes()
        opx, opy = self.prog
        ex, ey = self._fprog(ia, end[ia]), self._fprog(ib, end[ib])
        turn = (-1 if cw else 1) * (turns + 1)
        rw = words.get("R")
        exact_centre = kw.get("centre")
        if rw is not None:
            tol = (0.00005 if it.inch else 0.00005 * 25.4)
            c = arc_centre_r(opx, opy, ex, ey, to_float(rw.value), cw, tol)
            if c is None:
                raise self.error("GC302", "arc radius too small to reach the end point", rw)
            cax, cay = c
            exact_centre = None
        else:
            assert exact_centre is not None  # an I/J/K arc's centre is always emitted
            cax, cay = self._centre_ij(words, opx, opy)
        if self.first:
            self._arc_first(cw, turn, ex, ey, cax, cay, rw, end, deps)
        else:
            self._arc_next(cw, turn, ex, ey, cax, cay, exact_centre, end, deps)
        self._advance(end, deps)

    def _centre_ij(self, words: dict, opx: float, opy: float) -> tuple[float, float]:
        """The program-frame doubles of an I/J arc's centre as LinuxCNC computes them (``arc_data_ijk``,
        ``arc_data_comp_ijk``): the programmed start's double plus the word's (G91.1), or the word's (G90.1);
        the double pass computes the same (:mod:`.double_comp`)."""
        it = self.it
        a_name, b_name, _ = PLANE_AXES[it.plane]
        offs = {"X": "I", "Y": "J", "Z": "K"}
        iw, jw = words.get(offs[a_name]), words.get(offs[b_name])
        i = to_float(iw.value) if iw is not None else 0.0
        j = to_float(jw.value) if jw is not None else 0.0
        if getattr(it, "arc_absolute", False):
            return i, j
        return opx + i, opy + j

    def _arc_first(self, cw: bool, turn: int, end_x: float, end_y: float, center_x: float, center_y: float,
                   rw: Any, end: list, deps: Any) -> None:
        it = self.it
        side, tool_radius = self.side, self.radius
        cx, cy = self.cur
        arc_radius = abs(to_float(rw.value)) if rw is not None else math.hypot(center_x - cx, center_y - cy)
        got = arc_entry(side, tool_radius, cx, cy, end_x, end_y, center_x, center_y, cw, turn, arc_radius, it.inch)
        if got == ENTRY_SHORT:
            raise self.error(GC_ENTRY, "Radius of cutter compensation entry arc is not greater than the tool radius")
        if got == RADIUS:
            raise self.error(GC_RADIUS, f"Tool radius not less than arc radius with comp (tool radius "
                              f"{tool_radius:.6f}, arc radius {arc_radius:.6f} program units)")
        if got == ENTRY_COS:
            raise self.error(GC_RADIUS, "Tool radius not less than arc radius with comp (entry arc)")
        if got == SPIRAL:
            raise self.error(GC_BUG, "bug in tool radius comp (LinuxCNC: the entry arc's radii differ)")
        assert isinstance(got, tuple)
        self.first = False
        self.prog = (end_x, end_y)
        end_x, end_y, center_x, center_y = got
        ia, ib, _ = self._axes()
        centre = (self._fmachine(ia, center_x), self._fmachine(ib, center_y))
        if self.orientation not in (0, 9):
            # LinuxCNC: "need this move for lathes to move the tool origin first.  otherwise, the arc isn't
            # an arc" -- a feed to where the nose centre is, which moves the controlled point by the shift
            self._enqueue(_Move(_LINE, cx, cy, self._corner_end(end)))
        self._enqueue(_Move(_ARC, end_x, end_y, list(end), ca=center_x, cb=center_y, centre=centre,
                            turn=turn, sweep=find_turn(cx, cy, center_x, center_y, turn, end_x, end_y), deps=deps))
        self.cur = (end_x, end_y)

    def _arc_next(self, cw: bool, turn: int, end_x: float, end_y: float, centerx: float, centery: float,
                  exact_centre: Any, end: list, deps: Any) -> None:
        it = self.it
        opx, opy = self.prog
        cx, cy = self.cur
        side, tool_radius = self.side, self.radius
        got = arc_corner(side, tool_radius, cx, cy, opx, opy, end_x, end_y, centerx, centery, cw, turn)
        if got == -RADIUS:
            arc_radius = math.hypot(centerx - end_x, centery - end_y)
            raise self.error(GC_RADIUS, f"Tool radius not less than arc radius with comp (tool radius "
                              f"{tool_radius:.6f}, arc radius {arc_radius:.6f} program units)")
        assert isinstance(got, tuple)
        how, new_end_x, new_end_y, arc_radius, theta, beta, delta = got
        ia, ib, _ = self._axes()
        centre = exact_centre if exact_centre is not None else (self._fmachine(ia, centerx),
                                                                self._fmachine(ib, centery))
        main = _Move(_ARC, new_end_x, new_end_y, list(end), ca=centerx, cb=centery, centre=centre,
                     turn=turn, sweep=find_turn(opx, opy, centerx, centery, turn, end_x, end_y), deps=deps)
        if how == 1:  # concave
            if not self._front_is_arc("a concave corner before an arc"):
                if not self.queue:
                    self._enqueue(main)
                    self.prog, self.cur = (end_x, end_y), (new_end_x, new_end_y)
                    return
                back = line_arc_back(side, tool_radius, arc_radius, theta, beta, turn, centerx, centery)
                if back is None:
                    raise self.error(GC_GOUGE, "Arc move in concave corner cannot be reached by the tool without "
                                     "gouging")
                self._move_endpoint_and_flush(*back)
            else:
                prev = self.queue[0]
                pulled = arc_arc_back(side, tool_radius, arc_radius, prev.a, prev.b, prev.ca, prev.cb, prev.turn,
                                      centerx, centery, turn)
                if pulled == SAME_CENTRE:
                    raise self.error(GC_GOUGE, "Arc to arc motion is invalid because the arcs have the same center")
                if pulled == GOUGE:
                    raise self.error(GC_GOUGE, "Arc to arc motion makes a corner the compensated tool can't fit in "
                                     "without gouging")
                assert isinstance(pulled, tuple)
                self._move_endpoint_and_flush(*pulled)
            self._enqueue(main)
        elif how == 2:  # convex: an arc around the programmed corner first
            midx = opx + tool_radius * math.cos(delta)
            midy = opy + tool_radius * math.sin(delta)
            self._dequeue()
            corner = self._corner_end(end)
            corner_deps = [dict(d) for d in it.dep_pos] if it.track else None
            self._enqueue(_Move(_ARC, midx, midy, corner, ca=opx, cb=opy,
                                centre=(it.pos[ia], it.pos[ib]), turn=-1 if side == LEFT else 1,
                                derived="cutter comp corner", deps=corner_deps))
            self._dequeue()
            self._set_endpoint(midx, midy)
            self._enqueue(main)
        else:
            self._dequeue()
            self._set_endpoint(cx, cy)
            self._enqueue(main)
        self.prog = (end_x, end_y)
        self.cur = (new_end_x, new_end_y)

    # ------------------------------------------------------------------ other blocks
    def dwell(self, seconds: Fraction) -> None:
        """G4: queued behind a held move (LinuxCNC ``enqueue_DWELL``), else a dwell where the machine is."""
        it = self.it
        if self.queue:
            self._enqueue(_Move(_DWELL, 0.0, 0.0, [], dwell=seconds))
            return
        if it.machine_at is not None:  # after G40 the machine stands at the compensated point
            deps = it.deps_tuple(it.dep_pos) if it.track else ()
            dt = it.tool_dep_names() if it.track else ()
            if not it.unsupported:
                at = tuple(it.machine_at)
                seg = make_segment(_DWELL, at, at, it.axes, it.block_index, it.span, it.tlo,
                               None, None, False, None, None, 0, seconds, "", it.tool_register, deps, deps, (),
                               it.program_frame())
                it.emitted.append(with_tool_deps(seg, dt) if dt else seg)
                it.segment_count += 1
                it.kind_counts[_DWELL] += 1
            return
        it.emit(_DWELL, list(it.pos), dwell=seconds)

    def stop(self) -> None:
        """M0/M1/M60: the queue is flushed at the compensated position (comp stays on)."""
        if self.queue:
            self._move_endpoint_and_flush(*self.cur)
            self._dequeue()

    def program_end(self) -> None:
        """M2/M30 or the end of the text: flush, compensation off."""
        self.stop()
        self.side = None
        self.first = True
        self.it.comp_on = False
