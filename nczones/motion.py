"""Motion segments in machine coordinates: what the front end hands on.

The G-code interpreter emits motion; the prover and the controller consume it
and never see text.  :class:`Segment` is the exchange value (exact rationals,
one per motion); :mod:`nczones.gcode` may also emit column chunks for speed
(DESIGN §9), but every chunk can be viewed as segments.

Coordinates are **machine coordinates** (what the controller counts), one
entry per machine axis in the order of ``Machine.axes``.  Linear axes are in
millimetres (inch programs are converted exactly, 1 in = 25.4 mm), rotary
axes in degrees.

Arc geometry
------------
An arc lies in a plane given by two machine axes ``(first, second)``:
G17 = (X, Y), G18 = (Z, X), G19 = (Y, Z), following LinuxCNC's ARC_FEED
convention, so that ``clockwise`` is always judged looking from the positive
normal axis down onto the (first, second) plane, with first to the right and
second up.  All other axes (the helix axis included) move linearly with the
swept angle.  ``turns`` counts extra full turns (LinuxCNC ``P`` minus one).
A full circle has ``start == end`` in the plane and sweeps 360°.

``centre`` is exact when it is rational (I J K format).  For R-format arcs it
is in general irrational; then ``centre`` is ``None`` and ``radius`` holds the
programmed signed R (negative R = the arc of more than 180°); the exact centre
is the one of the two points at distance |R| from start and end that lies to
the right of the chord (start → end) for G2 with R > 0, as Fanuc and LinuxCNC
define it.  The prover encodes that centre exactly with polynomial constraints;
the controller uses a rational enclosure far inside one pulse.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable, Iterator
from fractions import Fraction

from .errors import InvalidArgument, SourceSpan
from .precompiled import dataclass, field, field_names, replace  # start-up: no dataclasses

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, TypeVar

    import numpy as np  # the column arrays are numpy's; importing numpy is left to the code that builds them

__all__ = ["SegmentKind", "Plane", "PLANE_AXES", "Segment", "MotionChunk", "PathMode", "arc_plane_axes",
           "DROPPED_BELOW", "arc_path_float", "segments_of", "ProgramFrame", "FrameRotation", "Payload", "Developed",
           "TipOffset", "SplineCurve", "PolarData", "TurretTool", "tip_offset"]


class SegmentKind(enum.IntEnum):
    LINE = 0  # G1 and every feed move the interpreter derives (canned-cycle feeds)
    ARC = 1  # G2/G3, helices included
    RAPID = 2  # G0 and derived rapids; expanded by the machine's rapid_mode downstream
    DWELL = 3  # G4: no motion, start == end
    DEVELOPED_ARC = 4  # G2/G3 in cylindrical interpolation (G07.1): a circle on the developed surface, see nczones.geometry.cylinder
    SPLINE = 5  # G5/G5.1/G5.2/G6.2: an exact clamped NURBS curve (a SplineCurve in Segment.extra), see nczones.geometry.nurbs
    POLAR = 6  # G01/G02/G03 in polar coordinate interpolation (G12.1): a plane path in machine X/C, see nczones.geometry.polar


#: A straight motion shorter than this (mm, or degrees) on every axis may be dropped by LinuxCNC: its canonical
#: layer sends no move whose every axis change is below ``CART_FUZZ`` (``emccanon.cc`` ``applyMinDisplacement``
#: zeroes each change under 1e-8 of the machine's units, then ``flush_segments`` appends the move only ``if
#: ((vel && acc) || synched)``), 2.54e-7 mm on an inch machine, and the planner drops a line shorter than
#: ``TP_POS_EPSILON`` (``tpAddLine``, 1e-12): a blended corner is then between the motions around it
#: (specs/path-modes.md §1).  3e-7 covers both units with room for the doubles' rounding.
DROPPED_BELOW = Fraction(3, 10**7)


@dataclass(frozen=True, slots=True)
class PathMode:
    """The path control mode a motion runs in (``specs/path-modes.md``): program meaning, from the interpreter.

    ``blend``: the control may round the corner at the END of the motion (LinuxCNC G64, a Fanuc control's
    cutting mode G64/G62); False for G61, G61.1 (LinuxCNC), G61, G63 and a block with G09 (Fanuc).
    ``tolerance``: LinuxCNC ``G64 P`` in mm (None: no tolerance, P absent or 0), or the machine file's
    ``path_tolerance`` on a Fanuc control; ``naive``: LinuxCNC's naive-CAM merging tolerance (``G64 Q``,
    which defaults to P) in mm; ``dialect``: whose planner rounds (``"linuxcnc"`` or ``"fanuc"``);
    ``code``: the code as written, for reports.

    >>> PathMode(True, None, Fraction(0), "linuxcnc", "G64").bound() is None
    True
    >>> PathMode(True, Fraction(1, 100), Fraction(1, 100), "linuxcnc", "G64 P0.01").bound()
    Fraction(1, 50)
    """

    blend: bool
    tolerance: Fraction | None = None
    naive: Fraction = Fraction(0)
    dialect: str = "linuxcnc"
    code: str = "G64"

    def bound(self) -> Fraction | None:
        """How far the moved path may leave the programmed one near a corner (None: not bounded by a tolerance)."""
        if not self.blend:
            return Fraction(0)
        if self.tolerance is None or self.tolerance <= 0:
            return None
        return self.tolerance + self.naive


class Plane(enum.IntEnum):
    XY = 17
    XZ = 18
    YZ = 19


#: (first, second, normal) axis names per plane, LinuxCNC ARC_FEED order.
PLANE_AXES: dict[Plane, tuple[str, str, str]] = {
    Plane.XY: ("X", "Y", "Z"),
    Plane.XZ: ("Z", "X", "Y"),
    Plane.YZ: ("Y", "Z", "X"),
}


def arc_plane_axes(plane: Plane) -> tuple[str, str, str]:
    """Axis names (first, second, normal) of an arc plane.

    >>> arc_plane_axes(Plane.XZ)
    ('Z', 'X', 'Y')
    """
    return PLANE_AXES[plane]


_INCH = Fraction(254, 10)


@dataclass(frozen=True, slots=True)
class FrameRotation:
    """A coordinate rotation in the plane of two axes, as the control applies it.

    ``machine (a, b) = R(program (a, b) + before) + after``, ``R`` the rotation by ``degrees`` counter-clockwise
    with the cosine and sine the interpreter used (``cos``, ``sin``: LinuxCNC's doubles taken exactly, or the
    midpoint of Fanuc's certified enclosure): LinuxCNC ``G10 L2 R`` has ``before`` = the G92/G52 shift and
    ``after`` = the work offset (and tool offset); Fanuc ``G68`` has ``before`` = −centre, ``after`` = centre +
    every offset.
    """

    axes: tuple[str, str]
    degrees: Fraction
    cos: Fraction
    sin: Fraction
    before: tuple[Fraction, Fraction]
    after: tuple[Fraction, Fraction]


@dataclass(frozen=True, slots=True)
class ProgramFrame:
    """How the program's coordinates map onto machine coordinates at a block (issue 37's ``point_program``).

    ``machine = program' + offset`` per axis, where ``program'`` is the program value in mm (inch converted,
    a diameter axis halved) and ``offset`` is everything the control adds: the work offset (``work``:
    G54..G59.3, Fanuc also EXT, G54.1 Pn), the G92/G50 shift, G52 local shift and the tool offsets (the
    length on the tool axis, a lathe tool's X offset), so the program point is where the tool tip is.
    ``rotation``: an XY (or G68 plane) rotation; its axes use it instead of ``offset``.
    ``diameter``: axes the program writes as diameters.  ``inch``: the program's units are inches (G20).
    ``opaque``: why the program point cannot be given (a transform not inverted, such as Fanuc G51
    scaling); empty otherwise.

    The interpreter makes one per change of these (segments share it); reports invert it only for a
    violation's point (:meth:`program_point`).

    >>> F = Fraction
    >>> f = ProgramFrame("G54", (F(100), F(-50)), diameter=("X",))
    >>> f.program_point(("X", "Z"), (F(131), F(-60)))
    (('X', Fraction(62, 1)), ('Z', Fraction(-10, 1)))
    """

    work: str
    offset: tuple[Fraction, ...]
    rotation: FrameRotation | None = None
    diameter: tuple[str, ...] = ()
    inch: bool = False
    opaque: str = ""
    #: the machine position of the active work offset's origin (LinuxCNC: G54..G59.3 as G10 L2 set it;
    #: Fanuc: EXT plus G54..G59 / G54.1 Pn), before G92/G52 and tool offsets: where fixtures placed in that
    #: work offset are (issue 39); None when the producer did not record it
    work_offset: tuple[Fraction, ...] | None = None

    @property
    def exact(self) -> bool:
        """False when a rotation is involved: its inverse uses the control's rounded cosine and sine, and the
        control rounded the rotated point, so the program point is close but not exact."""
        return self.rotation is None

    def program_point(self, axes: tuple[str, ...], point: tuple[Fraction, ...]) -> tuple[tuple[str, Fraction], ...]:
        """The program coordinates (program units: mm or inch, degrees; diameters on diameter axes) of a
        machine point.  Raises ValueError when the frame is :attr:`opaque`."""
        if self.opaque:
            raise ValueError(self.opaque)
        mm = [p - o for p, o in zip(point, self.offset)]
        rot = self.rotation
        if rot is not None and rot.axes[0] in axes and rot.axes[1] in axes:
            ia, ib = axes.index(rot.axes[0]), axes.index(rot.axes[1])
            x = point[ia] - rot.after[0]
            y = point[ib] - rot.after[1]
            c, s = rot.cos, rot.sin
            norm = c * c + s * s  # the inverse of [[c, -s], [s, c]] is [[c, s], [-s, c]] / (c² + s²)
            mm[ia] = (c * x + s * y) / norm - rot.before[0]
            mm[ib] = (c * y - s * x) / norm - rot.before[1]
        out = []
        for name, v in zip(axes, mm):
            if name in self.diameter:
                v = 2 * v
            if self.inch and name not in ("A", "B", "C"):
                v = v / _INCH
            out.append((name, v))
        return tuple(out)

    def describe(self) -> str:
        """How the frame reads in a report: ``G54, G20 (inch), X as diameter, rotated 30° in XY``."""
        parts = [self.work]
        if self.inch:
            parts.append("inch")
        if self.diameter:
            parts.append(", ".join(self.diameter) + " as diameter")
        if self.rotation is not None:
            from .exact import format_decimal

            parts.append(f"rotated {format_decimal(self.rotation.degrees)}° in {''.join(self.rotation.axes)}")
        return ", ".join(parts)


@dataclass(frozen=True, slots=True)
class Developed:
    """A motion made in cylindrical interpolation (G07.1): the axes and radius of the developed surface."""

    linear_axis: str
    rotary_axis: str
    cylinder_radius: Fraction


@dataclass(frozen=True, slots=True)
class TipOffset:
    """Tool offsets off the tool axis (a lathe's X offset): ``point = "tip"`` zones see machine − offset."""

    offsets: tuple[tuple[str, Fraction], ...]


@dataclass(frozen=True, slots=True)
class SplineCurve:
    """The exact clamped NURBS of a ``SegmentKind.SPLINE`` (control points in machine coordinates)."""

    degree: int
    knots: tuple[Fraction, ...]
    control: tuple[tuple[Fraction, ...], ...]
    weights: tuple[Fraction, ...]
    source: str = ""


@dataclass(frozen=True, slots=True)
class PolarData:
    """A motion made in polar coordinate interpolation (G12.1): its plane path and how it maps to X/C.

    ``start``/``end`` are the programmed plane points, ``turns`` the whole turns of C at the start,
    ``x_off``/``c_entry`` the linear axis's offset and C at entry, ``grid`` the (linear, rotary) output
    grid, ``arc`` whether it is a G02/G03 with ``centre`` (I/J) or ``radius`` (R).
    """

    start: tuple[Fraction, Fraction]
    end: tuple[Fraction, Fraction]
    turns: int
    x_off: Fraction
    c_entry: Fraction
    linear_axis: str
    rotary_axis: str
    grid: tuple[Fraction, Fraction]
    arc: bool
    centre: tuple[Fraction, Fraction] | None = None
    radius: Fraction | None = None


def tip_offset(extra: tuple[Payload, ...]) -> dict[str, Fraction]:
    """The tool offsets off the tool axis a segment's ``extra`` carries (a lathe's X offset; :class:`TipOffset`):
    ``point = "tip"`` zones see ``machine - offset`` there.

    >>> tip_offset((TipOffset((("X", Fraction(3)),)),)), tip_offset(())
    ({'X': Fraction(3, 1)}, {})
    """
    for p in extra:
        if type(p) is TipOffset:
            return dict(p.offsets)
    return {}


@dataclass(frozen=True, slots=True)
class TurretTool:
    """The turret tool a Fanuc lathe motion runs with (the T word's tool number, not its offset), carried when
    the machine describes turret tool solids (:mod:`nczones.lathe_solids`)."""

    number: int


#: What a segment may carry besides its geometry (``Segment.extra``), one value of each type at most.
Payload = Developed | TipOffset | SplineCurve | PolarData | TurretTool
if TYPE_CHECKING:
    _P = TypeVar("_P", Developed, TipOffset, SplineCurve, PolarData, TurretTool)


@dataclass(frozen=True, slots=True)
class Segment:
    """One motion in machine coordinates.

    Attributes
    ----------
    kind : SegmentKind
    start, end : tuple of Fraction
        Machine coordinates, in the order of the machine's axes.
    axes : tuple of str
        The axis names the coordinates refer to (the machine's axes).
    block : int
        Index of the block in execution order (0-based, counts repeats and
        subprogram calls separately).
    span : SourceSpan or None
        The source line of the block (with the motion word's column).
    tool_length : Fraction
        Active tool length offset (added to machine Z by G43); ``point = "tip"``
        zones subtract it.
    feed_mm_min : Fraction or None
        Programmed feed for LINE and ARC (None for rapids and dwells).
    plane, clockwise, centre, radius, turns
        Arc geometry, see the module docstring; ``None``/defaults otherwise.
    dwell_s : Fraction or None
        Dwell time for DWELL.
    derived : str
        Empty for a motion written in the program; otherwise what produced it
        (``"G28 intermediate"``, ``"G81 retract"``, ...), for reports.
    tool_register : int or None
        The H register of the active tool length (None under G49).
    deps_start, deps_end : tuple of tuple of str
        Per axis, the parameter sources the coordinate depends on, for
        parameter ranges (DESIGN §5): ``"G54"`` (that work offset's component
        on this axis), ``"H1"`` (tool length register, tool axis only),
        ``"start"`` (the start position's component).  Empty tuples when the
        interpreter was not asked to track dependencies.  A coordinate with
        sources S equals its nominal value plus the sum of the deviations of
        S's parameters on that axis.
    deps_tool : tuple of str
        The parameter sources of ``tool_length`` (on the tool axis): ``("H1",)``
        after ``G43 H1`` with the machine file's length, ``()`` after a length
        the program wrote itself (``G10 L1``), whatever ``tool_register``
        says.  Empty when dependencies are not tracked.
    extra : tuple of Payload
        Typed data a motion kind or mode needs besides the fields above, read with :meth:`payload`:
        :class:`SplineCurve` (G5 family), :class:`Developed` (G07.1), :class:`PolarData` (G12.1),
        :class:`TipOffset` (a lathe tool's offsets off the tool axis), :class:`TurretTool` (a lathe's T tool).
    frame : ProgramFrame or None
        The program's coordinate frame at the block (work offset, G92/G52, rotation, diameter, units, tool
        offsets), for reports of a violation's point in program coordinates; None when the producer did
        not record it.  Not part of equality (two equal motions may be written in different frames).
    """

    kind: SegmentKind
    start: tuple[Fraction, ...]
    end: tuple[Fraction, ...]
    axes: tuple[str, ...]
    block: int = 0
    span: SourceSpan | None = None
    tool_length: Fraction = Fraction(0)
    feed_mm_min: Fraction | None = None
    plane: Plane | None = None
    clockwise: bool = False
    centre: tuple[Fraction, Fraction] | None = None
    radius: Fraction | None = None
    turns: int = 0
    dwell_s: Fraction | None = None
    derived: str = ""
    tool_register: int | None = None
    deps_start: tuple[tuple[str, ...], ...] = ()
    deps_end: tuple[tuple[str, ...], ...] = ()
    deps_tool: tuple[str, ...] = ()
    extra: tuple[Payload, ...] = field(default=())
    frame: ProgramFrame | None = field(default=None, compare=False)

    @property
    def line(self) -> int | None:
        return None if self.span is None else self.span.line

    def payload(self, kind: type[_P]) -> _P | None:
        """The payload of type ``kind`` the segment carries in ``extra`` (None if it carries none).

        >>> seg = Segment(SegmentKind.LINE, (Fraction(0),), (Fraction(1),), ("X",),
        ...               extra=(TipOffset((("X", Fraction(2)),)),))
        >>> seg.payload(TipOffset).offsets, seg.payload(Developed) is None
        ((('X', Fraction(2, 1)),), True)
        """
        for p in self.extra:
            if type(p) is kind:
                return p
        return None

    def axis_index(self, name: str) -> int:
        return self.axes.index(name)

    def point_at(self, name: str, which: str = "start") -> Fraction:
        """A coordinate of the start or end point by axis name."""
        coords = self.start if which == "start" else self.end
        return coords[self.axes.index(name)]

    def plane_indices(self) -> tuple[int, int, int | None]:
        """Indices (first, second, normal) of an arc's plane axes in ``axes``.

        The normal index is None when the machine has no such axis.
        """
        if self.plane is None:
            raise ValueError("not an arc")
        a, b, n = PLANE_AXES[self.plane]
        return self.axes.index(a), self.axes.index(b), (self.axes.index(n) if n in self.axes else None)

    def is_helix(self) -> bool:
        """True for an arc along which some axis outside its plane moves."""
        if self.kind is not SegmentKind.ARC:
            return False
        i, j, _ = self.plane_indices()
        return any(s != e for k, (s, e) in enumerate(zip(self.start, self.end)) if k not in (i, j))


def arc_path_float(seg: Segment) -> tuple[Callable[[float], list[float]], float]:
    """An arc (helix, spiral, R-format arc) as floats: ``(point at fraction f of the sweep, sweep in radians)``.

    For drawing and approximate checks only (the exact geometry lives in the
    prover): the radius changes linearly with the angle from the start radius
    to the end radius (a spiral when they differ), every other axis linearly;
    an R-format arc takes its centre on the side the sign of R and the
    direction choose.

    >>> F = Fraction
    >>> seg = Segment(SegmentKind.ARC, (F(1), F(0)), (F(0), F(1)), ("X", "Y"), plane=Plane.XY, centre=(F(0), F(0)))
    >>> at, sweep = arc_path_float(seg)
    >>> [round(v, 9) for v in at(0.5)], round(sweep, 9)
    ([0.707106781, 0.707106781], 1.570796327)
    """
    from .exact import to_float

    i, j, _ = seg.plane_indices()
    s = [to_float(x) for x in seg.start]
    e = [to_float(x) for x in seg.end]
    if seg.centre is not None:
        ca, cb = to_float(seg.centre[0]), to_float(seg.centre[1])
    else:
        r = to_float(seg.radius) if seg.radius is not None else 0.0
        dx, dy = e[i] - s[i], e[j] - s[j]
        d = math.hypot(dx, dy) or 1.0
        h = math.sqrt(max(r * r - d * d / 4, 0.0))
        sign = (1 if seg.clockwise else -1) * (1 if r > 0 else -1)
        ca = (s[i] + e[i]) / 2 + sign * h * dy / d
        cb = (s[j] + e[j]) / 2 - sign * h * dx / d
    a0 = math.atan2(s[j] - cb, s[i] - ca)
    a1 = math.atan2(e[j] - cb, e[i] - ca)
    sweep = a1 - a0
    if seg.clockwise:
        while sweep >= 0:
            sweep -= 2 * math.pi
    else:
        while sweep <= 0:
            sweep += 2 * math.pi
    if seg.start == seg.end:
        sweep = -2 * math.pi if seg.clockwise else 2 * math.pi
    sweep += (-1 if seg.clockwise else 1) * 2 * math.pi * seg.turns
    r0 = math.hypot(s[i] - ca, s[j] - cb)
    r1 = math.hypot(e[i] - ca, e[j] - cb)

    def at(f: float) -> list[float]:
        ang = a0 + sweep * f
        rad = r0 + (r1 - r0) * f
        q = [sv + (ev - sv) * f for sv, ev in zip(s, e)]
        q[i], q[j] = ca + rad * math.cos(ang), cb + rad * math.sin(ang)
        return q

    return at, sweep


@dataclass(frozen=True)
class MotionChunk:
    """A run of consecutive segments as columns (DESIGN §9).

    Two forms:

    * **columns** (``scale`` is an int): every coordinate is the integer
      ``value * 10**scale`` in an ``int64`` array; ``kind``, ``start``,
      ``end``, ``line``, ``block``, ``tool_length`` are always filled; arc
      columns (``centre`` shape (n, 2), ``plane`` int8 17/18/19,
      ``clockwise`` bool, ``turns`` int32) are filled when any row is an arc
      (rows of other kinds hold zeros there).  Only segments whose numbers
      are all exact decimals at that scale, whose arc centres are rational
      (or R-format arcs given by ``radius``, below), and that need no dependency tracking go into column chunks.
      Optional columns: ``dwell`` (``int64``, the dwell time in seconds
      times ``10**scale`` on DWELL rows, 0 elsewhere; when None, dwells have
      no time) and ``derived`` (object array of str, what produced each row,
      such as ``"G81 retract"``; when None, every row is written motion) and ``radius`` (``int64``,
      the signed R times ``10**scale`` on the rows of R-format arcs whose centre is not rational or
      not computed, 0 elsewhere: such a row has ``centre`` 0 and stands for the segment with
      ``centre=None`` and that ``radius``; when None, every arc row has its centre).  ``tool_register``
      (one for the whole chunk, None under G49) is meaningful when ``tools_known``: the vectorized fast path
      records it (its runs have no H or T word), other producers leave ``tools_known`` False.
    * **objects** (``scale`` is None): ``objects`` holds the segments.
    * **both** (``scale`` is an int and ``objects`` is not None): columns that are the exact image of the
      segments in ``objects``, row for row (``nczones.gcode.fanuc.columns``: runs of the Fanuc full
      interpreter's straight moves); consumers may read the columns, and ``segments()`` and ``rows()`` give
      the segments themselves (their spans, feeds and frames), not views of the columns.

    ``segments()`` gives per-segment views in both forms, so consumers may
    always fall back to it.
    """

    axes: tuple[str, ...]
    scale: int | None
    kind: np.ndarray | None = None
    start: np.ndarray | None = None
    end: np.ndarray | None = None
    line: np.ndarray | None = None
    block: np.ndarray | None = None
    tool_length: np.ndarray | None = None
    centre: np.ndarray | None = None
    plane: np.ndarray | None = None
    clockwise: np.ndarray | None = None
    turns: np.ndarray | None = None
    feed: np.ndarray | None = None
    file: str = ""
    objects: tuple[Segment, ...] | None = None
    dwell: np.ndarray | None = None
    derived: np.ndarray | None = None
    #: the program frame every row was written in (a column run never changes offsets), see Segment.frame
    frame: ProgramFrame | None = None
    radius: np.ndarray | None = None
    #: the tool length register of every row (``G43 H<n>``; None under G49), valid when ``tools_known``: the
    #: producer (the vectorized fast path) recorded it; the tool solids pick the assembly by it
    tool_register: int | None = None
    tools_known: bool = False

    def __len__(self) -> int:
        if self.scale is None:
            return len(self.objects or ())
        return 0 if self.kind is None else int(self.kind.shape[0])

    def rows(self, a: int, b: int) -> MotionChunk:
        """Rows ``a`` to ``b`` (exclusive) as a chunk of their own: every column sliced, whatever columns the
        class has (a new column cannot be forgotten by a caller), the frame and file kept."""
        if self.scale is None:
            return replace(self, objects=(self.objects or ())[a:b])
        return replace(self, **{
            name: getattr(self, name)[a:b] for name in field_names(type(self))
            if name not in ("axes", "scale", "file", "frame", "tool_register", "tools_known")
            and getattr(self, name) is not None})

    def segments(self, lines: dict[int, str] | None = None) -> Iterator[Segment]:
        """Per-segment views (exact Fractions); ``lines`` maps line numbers to source text."""
        if self.scale is None or self.objects is not None:
            yield from self.objects or ()
            return
        den = 10**self.scale
        kinds, line_col, starts, ends = self.kind, self.line, self.start, self.end
        blocks, lengths = self.block, self.tool_length
        # the columns form always fills these (class docstring)
        assert kinds is not None and line_col is not None and starts is not None and ends is not None
        assert blocks is not None and lengths is not None
        for i in range(len(self)):
            kind = SegmentKind(int(kinds[i]))
            line_no = int(line_col[i])
            span = SourceSpan(self.file, line_no, 1, None, (lines or {}).get(line_no, ""))
            start = tuple(Fraction(int(v), den) for v in starts[i])
            end = tuple(Fraction(int(v), den) for v in ends[i])
            arc: dict[str, Any] = {}
            if kind is SegmentKind.ARC:
                assert self.plane is not None and self.clockwise is not None
                assert self.centre is not None and self.turns is not None
                arc = dict(
                    plane=Plane(int(self.plane[i])),
                    clockwise=bool(self.clockwise[i]),
                    centre=(Fraction(int(self.centre[i, 0]), den), Fraction(int(self.centre[i, 1]), den)),
                    turns=int(self.turns[i]),
                )
                if self.radius is not None and self.radius[i]:
                    arc["centre"], arc["radius"] = None, Fraction(int(self.radius[i]), den)
            feed = None
            if self.feed is not None and kind in (SegmentKind.LINE, SegmentKind.ARC):
                feed = Fraction(int(self.feed[i]), den)
            if self.dwell is not None and kind is SegmentKind.DWELL:
                arc["dwell_s"] = Fraction(int(self.dwell[i]), den)
            if self.derived is not None:
                arc["derived"] = str(self.derived[i])
            yield Segment(
                kind, start, end, self.axes, int(blocks[i]), span,
                Fraction(int(lengths[i]), den), feed, **arc, frame=self.frame, tool_register=self.tool_register,
            )


def segments_of(motion: Any) -> Iterator[Segment]:
    """The segments of a Segment, a MotionChunk, or an iterable of either (such as an interpretation).

    >>> F = Fraction
    >>> seg = Segment(SegmentKind.LINE, (F(0),), (F(1),), ("X",))
    >>> [s.end for s in segments_of([seg, MotionChunk(("X",), None, objects=(seg, seg))])]
    [(Fraction(1, 1),), (Fraction(1, 1),), (Fraction(1, 1),)]
    """
    if isinstance(motion, Segment):
        yield motion
        return
    if isinstance(motion, MotionChunk):
        yield from motion.segments()
        return
    for item in motion:
        if isinstance(item, Segment):
            yield item
        elif isinstance(item, MotionChunk):
            yield from item.segments()
        elif hasattr(item, "segments"):
            yield from item.segments()
        else:
            raise InvalidArgument(f"cannot run {type(item).__name__}: expected Segment or MotionChunk")
