"""Corner blending: the enclosure of the path the machine really moves, proved (``specs/path-modes.md``).

The per-motion proof (:mod:`nczones.prover.core`) is about the programmed path.  In a blending path mode
(LinuxCNC G64, a Fanuc control's cutting mode) the control rounds the corner between two motions; this
module proves, beside that proof, that every rounded corner stays in the allowed set, or names the corner
whose enclosure may leave it (an ``unknown`` reason, VF208, never ``safe``).  The enclosures, derived from
LinuxCNC's trajectory planner in ``specs/path-modes.md``:

* LinuxCNC, ``G64`` without tolerance: a blend uses at most half of each of two lines, so every point
  of it is ``C + a (M1 - C) + b (M2 - C)`` with ``a, b`` in ``[0, 1]``, ``C`` the corner and ``M1``, ``M2``
  the midpoints of the two lines (a parallelogram); with an arc, the box of the part a blend may use (half a
  line, the first half of an arc after the corner, the last three quarters of one before it: the planner
  trims up to two thirds there) stands for it, and the region is the Minkowski sum of the two boxes less ``C``.
* LinuxCNC, ``G64 P p Q q`` (Q defaults to P): every point within ``p + q`` of the programmed path (naive-CAM
  merging within ``q``, then blends within ``p``): the two motions' boxes with the margin enlarged by
  ``p + q``; with ``q = 0`` the region above proves a corner too.
* Fanuc cutting mode with ``[machine] path_tolerance t``: within ``t`` of the programmed path; without it,
  acc/dec after interpolation keeps the path in the convex hull of the run of motions between exact stops:
  that run's box must fit.

The fast path is kept fast: column chunks are screened with numpy (the box of many corner regions at once;
for lines every corner region lies in the box of its two motions), and only regions near a zone are
refined one by one in exact arithmetic.
"""

from __future__ import annotations

import time
from bisect import bisect_right
from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction
from operator import itemgetter

from ..errors import InvalidArgument
from ..exact import format_decimal
from ..machine import Machine, RapidMode
from ..motion import (
    DROPPED_BELOW,
    MotionChunk,
    PathMode,
    Segment,
    SegmentKind,
    SplineCurve,
    tip_offset,
)
from ..precompiled import replace  # dataclasses.replace without importing dataclasses (start-up)
from ..zones import ZonePoint, tip_shifted
from .exact import box_fits
from .hull2d import convex_hull, hull_fits
from .result import ParamRange, Reason

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["BLEND_CODE", "CornerCheck"]

# SegmentKind's members as plain names: reading a member off an Enum class costs about 0.25 us in Python 3.11 (the
# metaclass's ``__getattr__`` turns off the interpreter's quick attribute path), and this module reads several a motion
_LINE, _ARC, _RAPID, _DWELL = SegmentKind.LINE, SegmentKind.ARC, SegmentKind.RAPID, SegmentKind.DWELL

#: The code of every reason this module gives.
BLEND_CODE = "VF208"
#: Corner regions refined at most this many times (4 sub-regions each).
DEPTH = 5
#: Screened corner boxes split in this many parts when their union does not fit.
SPLIT = 16
#: The integer scale of the screen of object segments (coordinates that are multiples of 1/SCALE: decimals of
#: up to 15 places, and the doubles of parametric programs, binary fractions of up to 64 places).
SCALE = 10**15 * 2**64
#: The share of the run's time budget the corner proofs may spend refining (the per-motion proof keeps the rest).
REFINE_SHARE = 0.25
#: Box tests the exact refinement of a run may spend; past them a corner that does not fit at once is unknown.
MAX_TESTS = 200_000
#: At most this many corner reasons per run (the rest are counted).
MAX_REASONS = 20
#: Exact boxes of arcs kept for arcs that repeat (:meth:`CornerCheck._arc_box`); past it the cache starts over
#: (memory flat whatever the program's length).
ARC_CACHE = 4096
#: Corners screened together (:meth:`CornerCheck._flush`): the corner check's window of motion.
CORNER_BATCH = 4096
#: Fanuc cutting mode without ``path_tolerance`` on column chunks: the runs' boxes from the columns (False: one
#: motion at a time, :meth:`CornerCheck._segment`; the agreement test compares the two).
HULL_COLUMNS = True
#: How much of each straight motion a LinuxCNC blend may use (``BLEND_DIST_FRACTION``, specs/path-modes.md).
#: The column screen's boxes lie in the box of the two motions whatever this is; the exact regions use it.
BLEND_FRACTION = Fraction(1, 2)
#: LinuxCNC's naive-CAM chain (``G64 Q``) holds at most this many points (``emccanon.cc`` ``linkable``: a chain of
#: more than 100 points takes no more): one merged line spans at most this many programmed motions.
NAIVE_CHAIN = 101
#: G64 Q without P: prove the corners a block of NAIVE_CHAIN motions at a time first (False: each corner alone,
#: the reference the agreement tests compare with).
NAIVE_BLOCKS = True

F0 = Fraction(0)
Box = tuple[tuple[Fraction, ...], tuple[Fraction, ...]]


#: the most points of a Fanuc run on a two-axis machine kept for its convex hull (beyond: its box decides)
HULL_POINTS = 100_000
#: the motion kinds the column screen takes (others: the exact path, one motion at a time)
_SIMPLE = frozenset((_LINE, _RAPID, _ARC, _DWELL))
#: the tip offsets of motions without any (CornerCheck._shifts)
_NO_SHIFT: frozenset[tuple[tuple[str, Fraction], ...]] = frozenset({()})


# The per-motion proof compares coordinates a dozen times a motion; Fraction's own comparison first checks its
# operand against ``numbers.Rational`` (an ABC check), most of the time it takes.  These compare the normalised
# numerators and denominators directly (denominators are positive), as nczones.gcode.lexer builds them; an
# operand that is not a Fraction (an int) takes the generic comparison.
def _lt(a: Any, b: Any) -> bool:
    """``a < b`` for exact coordinates."""
    try:
        return bool(a._numerator * b._denominator < b._numerator * a._denominator)
    except AttributeError:
        return bool(a < b)


def _lo(a: Any, b: Any) -> Any:
    """``min(a, b)`` for exact coordinates."""
    return b if _lt(b, a) else a


def _hi(a: Any, b: Any) -> Any:
    """``max(a, b)`` for exact coordinates."""
    return b if _lt(a, b) else a


def _mid(a: Any, b: Any) -> Any:
    """``(a + b) / 2`` for exact coordinates: one Fraction from the parts (the same value, without the two
    operations' normalisations)."""
    try:
        an, ad, bn, bd = a._numerator, a._denominator, b._numerator, b._denominator
    except AttributeError:
        return (a + b) / 2
    return Fraction(an * bd + bn * ad, 2 * ad * bd)


def _plus_less(x: Any, y: Any, z: Any) -> Any:
    """``x + y - z`` for exact coordinates: one Fraction from the parts (the same value)."""
    try:
        xn, xd, yn, yd, zn, zd = x._numerator, x._denominator, y._numerator, y._denominator, z._numerator, z._denominator
    except AttributeError:
        return x + y - z
    return Fraction((xn * yd + yn * xd) * zd - zn * xd * yd, xd * yd * zd)


def _plus_half(y: Any, f: Any, c: Any) -> Any:
    """``y + (f - c) / 2`` for exact coordinates: one Fraction from the parts (the same value)."""
    try:
        yn, yd, fn, fd, cn, cd = y._numerator, y._denominator, f._numerator, f._denominator, c._numerator, c._denominator
    except AttributeError:
        return y + (f - c) / 2
    return Fraction(2 * yn * fd * cd + yd * (fn * cd - cn * fd), 2 * yd * fd * cd)


def _lo_half(y: Any, f: Any, c: Any) -> Any:
    """``y + min(0, (f - c) / 2)``: ``y`` itself when ``f >= c``."""
    return _plus_half(y, f, c) if _lt(f, c) else y


def _hi_half(y: Any, f: Any, c: Any) -> Any:
    """``y + max(0, (f - c) / 2)``: ``y`` itself when ``f <= c``."""
    return _plus_half(y, f, c) if _lt(c, f) else y


def _same(p: Sequence[Any], q: Sequence[Any]) -> bool:
    """``p == q`` for points of exact coordinates (normalised Fractions are equal when their parts are)."""
    if p is q:
        return True
    try:
        for x, y in zip(p, q, strict=True):
            if x is not y and (x._numerator != y._numerator or x._denominator != y._denominator):
                return False
        return True
    except AttributeError:
        return tuple(p) == tuple(q)


_SHORT_NUM, _SHORT_DEN = DROPPED_BELOW.numerator, DROPPED_BELOW.denominator


def _short(p: Sequence[Any], q: Sequence[Any]) -> bool:
    """Is ``|q_i - p_i| < DROPPED_BELOW`` on every axis?  Exactly that test, in integers: with ``x = a/b`` and
    ``y = c/d`` (``b, d > 0``), ``|y - x| < n/m`` is ``|c b - a d| m < n b d``; an operand that is not a
    Fraction (an int) takes Fraction arithmetic."""
    for x, y in zip(p, q):
        if x is y:
            continue
        try:
            a, b, c, d = x._numerator, x._denominator, y._numerator, y._denominator
        except AttributeError:
            if not abs(y - x) < DROPPED_BELOW:
                return False
            continue
        if b == d:
            if abs(c - a) * _SHORT_DEN >= _SHORT_NUM * b:
                return False
        elif abs(c * b - a * d) * _SHORT_DEN >= _SHORT_NUM * b * d:
            return False
    return True


def _range_widening(ranges: Sequence[ParamRange], axes: Sequence[str], tool_axis: str | None) -> dict[str, Fraction]:
    """How far the parameter ranges move a position, per axis (a sound bound: the sum of the ranges' sizes
    that act on the axis).

    >>> from nczones.prover.result import ParamRange
    >>> r = [ParamRange("G54.Y", Fraction(-1), Fraction(1), (Fraction(-1), Fraction(1))),
    ...      ParamRange("H1", Fraction(-2), Fraction(1), (Fraction(198), Fraction(201)))]
    >>> _range_widening(r, ("X", "Y", "Z"), "Z")
    {'X': Fraction(0, 1), 'Y': Fraction(1, 1), 'Z': Fraction(2, 1)}
    """
    out = {a: F0 for a in axes}
    for r in ranges:
        size = max(abs(r.lo), abs(r.hi))
        prefix, _, axis = r.name.partition(".")
        if axis in out and prefix.upper() != "H":
            on: Sequence[str] = (axis,)
        elif r.name.upper().startswith("H") and not axis and tool_axis in out:
            on = (tool_axis,)
        else:
            on = tuple(axes)
        for a in on:
            out[a] += size
    return out


class _ZoneView:
    """What the motions' screen (:data:`~nczones.prover.screen.ZONE_ROWS`) reads of a prover: the zones, the
    margin, the tool axis, and its cache of per-zone constants (:class:`~nczones.prover.screen.ScreenedProver`)."""

    __slots__ = ("zones", "margin", "tool_axis", "screen_constants")

    def __init__(self, zones: Sequence[Any], margin: Fraction, tool_axis: str | None):
        self.zones = tuple(zones)
        self.margin = margin
        self.tool_axis = tool_axis
        self.screen_constants: dict | None = None


class CornerCheck:
    """Follows a run's motion (wrap the chunks with :meth:`watch`) and proves its blended corners.

    ``modes`` is the interpreter's table of path modes, ``(first block index, PathMode)`` in order; it may
    grow while the run is read (the interpreter is never behind the chunks it gave).
    """

    def __init__(self, machine: Machine, margin: Fraction, ranges: Sequence[ParamRange],
                 modes: list[tuple[int, PathMode]], limits: Any = None):
        self.machine = machine
        self.allowed = machine.allowed
        self.margin = margin
        self.axes = machine.axis_names
        self.dogleg = machine.rapid_mode is RapidMode.DOGLEG
        # parameter ranges move positions by at most their size, each on its own axis (G54.X, home.X, start.X:
        # X; H: the tool axis; any other name: every axis): the boxes grow by that much there
        self.widen_axis = _range_widening(ranges, machine.axis_names, machine.allowed.tool_axis)
        self.widens = any(self.widen_axis.values())
        self.modes = modes
        self.zones = self.allowed.zones
        # the axes some zone constrains: screening boxes are computed on them only (others stay 0)
        named: set[str] = set()
        for z in self.zones:
            named.update(a for a, _lo, _hi in getattr(z, "limits", ()))
            named.update(getattr(z, "plane", ()))
            named.update(a for a in (getattr(z, "reference_axis", None), getattr(z, "limited_axis", None)) if a)
        if machine.allowed.tool_axis:
            named.add(machine.allowed.tool_axis)
        self.rel = [i for i, a in enumerate(self.axes) if a in named]
        self.reasons: list[Reason] = []
        self.more = 0
        self.corners = 0
        self.tests = 0  # box tests so far (MAX_TESTS)
        self.limits = limits  # the run's budget (RunLimits): spent, no corner is refined any more
        budget = getattr(limits, "budget_s", None)
        self.refine_cap = REFINE_SHARE * budget if budget else 60.0  # seconds of corner proofs at most
        self.refine_s = 0.0
        self.pending: list[Any] = []  # corners screened together: (a, b, mode, box, its 3 points' _ints, None, bound)
        # the last corner's last two points and their _ints (a chain of motions shares them with the next corner)
        self._chain: tuple[tuple[Any, Any], tuple[Any, Any]] = ((None, None), (None, None))
        self._facts_mode: PathMode | None = None  # _facts: the last mode asked and its answer
        self._box_of: Segment | None = None  # _piece_box: the last motion asked and its box
        self._box_last: Box | None = None
        self._facts_last: tuple[bool, bool, Fraction | None | bool] = (False, False, False)
        self._per_den: dict[int, int] = {}  # _ints: SCALE // d by denominator d
        self._arc_cache: dict[Any, Box | None] = {}  # exact boxes of repeated arcs (_arc_box)
        self.prev: Segment | None = None
        self.prev_stop = True  # no corner before the first motion
        self._dropped: Segment | None = None  # the motion before a run of ones LinuxCNC may drop (_dropped_corner)
        self.stretch: list[Any] | None = None  # Fanuc cutting mode without a tolerance: [lo, hi, first, last]
        self._seen: set[str] = set()
        self._blocks: list[tuple[int, int] | range] = []  # the blocks of each reason's two motions (a Fanuc run: all)
        self.naive = _NaiveWindows()  # G64 Q without P: corners proved over the merging windows
        # a lathe's tool offsets off the tool axis (TipOffset): tip zones see machine - offset, as the per-motion
        # proof does (Prover._tip_prover); the offsets of the motions a test is about, and the moved zone sets
        self.has_tip_zones = any(z.point is ZonePoint.TIP for z in self.zones)
        self._shifts: frozenset[tuple[tuple[str, Fraction], ...]] = _NO_SHIFT
        self._unshifted = [self.allowed]
        self._shifted: dict[tuple[tuple[str, Fraction], ...], Any] = {(): self.allowed}
        self._stretch_shifts: set[tuple[tuple[str, Fraction], ...]] = set()
        # the tool lengths of the run's motions besides its first and last one's (a G43/G49 inside the run): the
        # hull is tested at each, as a corner is at both motions' lengths
        self._stretch_tls: set[Fraction] = set()
        # a two-axis machine (a lathe): the corners of the run's motion boxes, whose convex hull is proved
        # where the run's box does not fit (nczones.prover.hull2d)
        self._stretch_pts: list[tuple[Fraction, ...]] | None = [] if len(self.axes) == 2 else None
        self._last_extra: tuple[Any, tuple[tuple[str, Fraction], ...]] = ((), ())
        self._naive_modes = 0  # the length of the mode table when it was last searched for G64 Q without P
        self._mode_hit: tuple[int, int, PathMode, int, Any] | None = None  # mode_of's last answer
        self._zone_view: _ZoneView | None = None  # _rows_proved: the zones as the motions' screen reads them

    # ------------------------------------------------------------------ the stream
    def watch(self, chunks: Iterable[Any]) -> Iterator[Any]:
        """The chunks unchanged; each one's corners proved as it passes."""
        for chunk in chunks:
            yield chunk
            self.take(chunk)

    def take(self, chunk: Any) -> None:
        """Follow one chunk (a column chunk, a chunk of segments, a segment): its corners proved or queued."""
        if isinstance(chunk, MotionChunk) and chunk.scale is not None:
            self._flush()
            self._columns(chunk)
            self._flush()
        elif isinstance(chunk, MotionChunk):
            for seg in chunk.objects or ():
                self._segment(seg)
        elif isinstance(chunk, Segment):
            self._segment(chunk)
        else:
            for seg in chunk.segments():
                self._segment(seg)
        if len(self.pending) >= CORNER_BATCH:
            self._flush()

    def finish(self, violating: Iterable[int] = (), upto: int | None = None) -> list[Reason]:
        """The reasons (VF208) after the last chunk; a corner next to a ``violating`` block (index) is left
        out: the verdict is ``unsafe`` there anyway and the violation names the block.  ``upto``: the last
        block the proof examined when it stopped at its violation limit; corners after it are left out too
        (how far the motion was read past it depends on how it was batched, and the verdict is ``unsafe``)."""
        self._flush()
        self._close_stretch()
        self._naive_close()
        bad = set(violating)
        if bad or upto is not None:
            kept = [(r, blocks) for r, blocks in zip(self.reasons, self._blocks)
                    if bad.isdisjoint(blocks) and (upto is None or max(blocks) <= upto)]
            self.reasons = [r for r, _b in kept]
            self._blocks = [b for _r, b in kept]
        if self.more and upto is None:
            self.reasons.append(Reason(f"{BLEND_CODE}: {self.more} more blended corner(s) could not be proved inside "
                                       "the allowed set", None, None, BLEND_CODE))
        return self.reasons

    def mode_of(self, block: int) -> PathMode:
        """The mode block ``block`` runs in; the last answer's range of blocks is kept while the table is as it
        was (same length, same last entry: the interpreter appends entries or replaces the last one)."""
        table = self.modes
        hit = self._mode_hit
        if hit is not None and hit[0] <= block < hit[1] and hit[3] == len(table) and hit[4] is table[-1]:
            mode: PathMode = hit[2]
            return mode
        k = max(bisect_right(table, block, key=lambda e: e[0]) - 1, 0)
        lo = table[k][0] if k else -1 << 62
        hi = table[k + 1][0] if k + 1 < len(table) else 1 << 62
        self._mode_hit = (lo, hi, table[k][1], len(table), table[-1])
        return table[k][1]

    # ------------------------------------------------------------------ one motion at a time (exact)
    def _segment(self, seg: Segment) -> None:
        kind = seg.kind
        if kind is _DWELL:
            self._stop()
            return
        if kind is not _ARC and _same(seg.start, seg.end):
            return  # a move of length 0: LinuxCNC's canon drops it, no corner
        if kind is _RAPID and self.dogleg:
            # a dogleg rapid is positioning with an in-position check at both ends (specs/path-modes.md)
            self._stop()
            self.prev = seg
            return
        prev = self.prev
        joined = prev is not None and not self.prev_stop
        if self._naive_tracked():
            self._naive_track(seg, joined)
        if prev is not None and joined:
            self._queue(prev, seg, self.mode_of(prev.block))
        mode = self.mode_of(seg.block)
        self._dropped_corner(prev, seg, joined, mode)
        self.prev, self.prev_stop = seg, not mode.blend
        if mode.blend and mode.dialect == "fanuc" and mode.tolerance is None:
            self._run_motion(seg, mode)
        elif self.stretch is not None:
            self._stretch_tl(self.stretch[3], seg)
            self.stretch[3] = seg  # the motion that ends the run with an exact stop still belongs to it
            self._stretch_shifts.add(self._shift(seg))
            box = _hull_box(seg)
            if box is not None:
                _grow(self.stretch, box)
                self._hull_add(seg, box, False)
            else:
                self._stretch_pts = None  # a motion without a box: the run's box decides
            self._close_stretch()
        elif mode.dialect == "fanuc" and seg.kind in _FILTERED_CURVES:
            self._lone_curve(seg, mode)

    def _lone_curve(self, seg: Segment, mode: PathMode) -> None:
        """A Fanuc arc (or polar move) outside a cutting-mode run (G61, G09, or with ``path_tolerance``): acc/dec
        after interpolation averages commanded positions along it in every path mode, so it is proved as a run of
        one motion, by its box (its convex hull on a two-axis machine)."""
        box = _hull_box(seg)
        if box is None:
            self._reason(seg, seg, mode, None, "a motion of this kind on a Fanuc control is not modelled")
            return
        self.stretch = [list(box[0]), list(box[1]), seg, seg]
        self._stretch_shifts = {self._shift(seg)}
        self._stretch_tls = set()
        self._hull_add(seg, box, True)
        self._close_stretch()

    def _run_motion(self, seg: Segment, mode: PathMode) -> None:
        """A motion in a Fanuc run (cutting mode without a tolerance): the run's box grows to hold it."""
        st = self.stretch
        if st is not None and seg.start is st[3].end and seg.kind in (_LINE, _RAPID):
            # a straight motion from where the run's last motion ended (in the box already): its end alone
            _grow_point(st, seg.end)
            self._stretch_tl(st[3], seg)
            st[3] = seg
            self._stretch_shifts.add(self._shift(seg))
            self._hull_add(seg, None, False)
            return
        box = _hull_box(seg)
        if box is None:
            self._reason(seg, seg, mode, None, "a motion of this kind next to a blended corner is not modelled")
        elif st is None:
            self.stretch = [list(box[0]), list(box[1]), seg, seg]
            self._stretch_shifts = {self._shift(seg)}
            self._stretch_tls = set()
            self._hull_add(seg, box, True)
        else:
            _grow(st, box)
            self._stretch_tl(st[3], seg)
            st[3] = seg
            self._stretch_shifts.add(self._shift(seg))
            self._hull_add(seg, box, False)

    def _stretch_tl(self, last: Segment, seg: Segment) -> None:
        """``seg`` joins the run after ``last``: keep ``last``'s tool length when ``seg`` has another one (the run's
        first and last motions' lengths are tested anyway)."""
        tl = last.tool_length
        if seg.tool_length is not tl and seg.tool_length != tl:
            self._stretch_tls.add(tl)

    def _queue(self, a: Segment, b: Segment, mode: PathMode) -> None:
        """A corner to prove: screened with others first (:meth:`_flush`).

        The common corner (two straight motions, LinuxCNC) is kept as integers (``SCALE``) on the zones'
        axes: the box of its three points, grown by the mode's bound when it has one."""
        naive, fanuc_run, int_bound = self._facts(mode)
        if naive:
            self.naive.pending.append((a, b, mode, self.naive.count - 2))
            return
        if fanuc_run:  # the run's hull proves it (_close_stretch)
            self.corners += 1
            return
        if int_bound is not False and _linear(a, self.dogleg) and _linear(b, self.dogleg) and _same(b.start, a.end):
            # the points of the corner before (a chain of motions: its two ends are this one's first two points)
            (q0, i0), (q1, i1) = self._chain
            p0 = i0 if q0 is a.start else self._ints(a.start)
            p1 = i1 if q1 is a.end else self._ints(a.end)
            p2 = self._ints(b.end)
            self._chain = ((a.end, p1), (b.end, p2))
            if p0 is not None and p1 is not None and p2 is not None:
                self.pending.append((a, b, mode, None, (p0, p1, p2), None, int_bound))
                return
        box = self._screen_box(a, b, mode)
        if box is None:
            self._corner(a, b, mode)
        else:
            self.pending.append((a, b, mode, box, None, None, None))

    def _facts(self, mode: PathMode) -> tuple[bool, bool, Fraction | None | bool]:
        """What :meth:`_queue` asks of ``mode`` (kept for the last mode asked: a frozen value): G64 Q without P (the
        merging windows prove the corner), a Fanuc run's corner (its hull does), and the bound the integer screen
        grows a LinuxCNC corner of two straight motions by (None: none; False: that screen is not for this mode)."""
        if mode is self._facts_mode:
            return self._facts_last
        bound = mode.bound()
        facts = (_naive_only(mode), mode.dialect == "fanuc" and mode.tolerance is None,
                 (bound or None) if mode.dialect == "linuxcnc" and (bound is not None or not mode.naive) else False)
        self._facts_mode, self._facts_last = mode, facts
        return facts

    def _ints(self, p: tuple[Fraction, ...]) -> list[int] | None:
        """``p`` on the zones' axes times ``SCALE`` (None when a coordinate is not a multiple of 1/SCALE)."""
        out = []
        per = self._per_den  # SCALE // d by denominator d (0: d does not divide SCALE)
        for i in self.rel:
            x: Any = p[i]
            try:
                num, d = x._numerator, x._denominator
            except AttributeError:  # an int
                num, d = x.numerator, x.denominator
            m = per.get(d)
            if m is None:
                m = per[d] = 0 if SCALE % d else SCALE // d
            if not m:
                return None
            out.append(num * m)
        return out

    def _screen_box(self, a: Segment, b: Segment, mode: PathMode) -> Box | None:
        """A box holding every enclosure :meth:`_corner` may try for this corner (None: prove it alone).

        No tolerance: two straight motions' region lies in the box of the two (it uses at most half of each:
        each coordinate of ``C + (M1 - C) + (M2 - C)`` is between the two motions' far ends); other motions'
        region is the Minkowski sum of their half boxes less ``C``, which the sum with an arc's whole box holds
        (an arc's half box takes square roots to 96 bits: :meth:`_region` computes it when the screen fails).
        With a bound: both motions' boxes grown by it."""
        if mode.dialect == "fanuc" and mode.tolerance is None:
            return None
        bound = mode.bound()
        if bound is None and mode.naive:
            return None
        if _linear(a, self.dogleg) and _linear(b, self.dogleg) and _same(b.start, a.end):
            # the common case, on the zones' axes only
            lo, hi = [F0] * len(self.axes), [F0] * len(self.axes)
            for i in self.rel:
                x, y, z = a.start[i], a.end[i], b.end[i]
                lo[i], hi[i] = _lo(_lo(x, y), z), _hi(_hi(x, y), z)
                if bound:
                    lo[i] -= bound
                    hi[i] += bound
            return tuple(lo), tuple(hi)
        if bound is None:
            la, lb = _linear(a, self.dogleg), _linear(b, self.dogleg)
            if la != lb and (la or _same(b.start, a.end)):
                return self._line_and_piece(a, b, la)
            ba = _half_box(a, self.dogleg, end=True) if _linear(a, self.dogleg) else self._piece_box(a)
            bb = _half_box(b, self.dogleg, end=False) if _linear(b, self.dogleg) else self._piece_box(b)
            if ba is None or bb is None:
                return None
            c = a.end
            return tuple(map(_plus_less, ba[0], bb[0], c)), tuple(map(_plus_less, ba[1], bb[1], c))
        pa, pb = self._piece_box(a), self._piece_box(b)
        if pa is None or pb is None:
            return None
        g = bound or F0
        return tuple(min(x, y) - g for x, y in zip(pa[0], pb[0])), tuple(max(x, y) + g for x, y in zip(pa[1], pb[1]))

    def _line_and_piece(self, a: Segment, b: Segment, line_first: bool) -> Box | None:
        """:meth:`_screen_box` of a corner between a straight motion and another (an arc) without a bound: the
        same box, without the straight motion's half box.

        With ``C = a.end`` the straight motion's half box less ``C`` is the box of 0 and half its vector from
        ``C`` to its far end ``F`` (``a.start``, or ``b.end`` when ``b`` is the straight one and starts at ``C``):
        its half at its end is the box of ``(F + C) / 2`` and ``C``, at its start that of ``C`` and ``(C + F) / 2``.
        So each bound of ``half box + other box - C`` is the other box's bound plus ``min(0, (F - C) / 2)``
        (low) or ``max(0, (F - C) / 2)`` (high): the same value as :func:`_plus_less` gives, the other box's own
        bound where the added term is 0."""
        c = a.end
        other, far = (self._piece_box(b), a.start) if line_first else (self._piece_box(a), b.end)
        if other is None:
            return None
        return (tuple(map(_lo_half, other[0], far, c)), tuple(map(_hi_half, other[1], far, c)))

    def _piece_box(self, seg: Segment) -> Box | None:
        """:func:`_piece_box`, kept for the last motion asked (a corner's second motion is the next one's first; an
        arc's box takes square-root bounds and sweep tests; a Segment is frozen)."""
        if seg is self._box_of:
            return self._box_last
        box = _piece_box(seg)
        self._box_of, self._box_last = seg, box
        return box

    def _flush(self) -> None:
        """Prove the queued corners: the box of many at once, halves of what does not fit, one by one at last."""
        items, self.pending = self.pending, []
        todo = [(0, len(items))] if items else []
        n = len(self.axes)
        while todo:
            lo_i, hi_i = todo.pop()
            group = items[lo_i:hi_i]
            t0 = group[0][0].tool_length
            if all((a.tool_length is t0 or a.tool_length == t0) and (b.tool_length is t0 or b.tool_length == t0)
                   for a, b, *_r in group):
                lo, hi = [F0] * n, [F0] * n
                ints = [e for e in group if e[4] is not None]
                points = [p for e in ints for p in e[4]]  # every point of the integer corners
                boxes = [e[3] for e in group if e[4] is None]
                g = max((e[6] for e in ints if e[6] is not None), default=F0)
                for k, i in enumerate(self.rel):
                    cand_lo, cand_hi = [], []
                    if ints:
                        at = itemgetter(k)
                        cand_lo.append(Fraction(min(map(at, points)), SCALE) - g)
                        cand_hi.append(Fraction(max(map(at, points)), SCALE) + g)
                    if boxes:
                        cand_lo.append(min(box[0][i] for box in boxes))
                        cand_hi.append(max(box[1][i] for box in boxes))
                    lo[i], hi[i] = min(cand_lo), max(cand_hi)
                self._shifts = (frozenset(self._shift(x) for a, b, *_r in group for x in (a, b))
                                if self.has_tip_zones else _NO_SHIFT)
                if self._fits((tuple(lo), tuple(hi)), (t0,), F0):
                    self.corners += len(group)
                    continue
            if len(group) == 1:
                a, b, mode, *_r = group[0]
                self._corner(a, b, mode)
                continue
            size = -(-len(group) // SPLIT)
            todo.extend((x, min(x + size, hi_i)) for x in range(lo_i, hi_i, size))

    def _dropped_corner(self, prev: Segment | None, seg: Segment, joined: bool, mode: PathMode) -> None:
        """LinuxCNC drops a move whose every axis change is below 1e-8 of the machine's units (the canonical
        layer's ``CART_FUZZ``; the planner's ``TP_POS_EPSILON`` is smaller): the corner is then between the
        motions around it, from the end of the one before (the planner's goal stays there) to the end of the one
        after.  A straight motion shorter than :data:`~nczones.motion.DROPPED_BELOW` on every axis may be
        dropped: that corner is proved too, with the motion after it as the planner runs it (from the corner),
        whose box must fit as well (the per-motion proof proved it from the short motion's end)."""
        if mode.dialect != "linuxcnc":
            return
        if _linear(seg, self.dogleg) and _short(seg.start, seg.end):
            if self._dropped is None and joined and prev is not None:
                self._dropped = prev
            return
        before, self._dropped = self._dropped, None
        if before is None:  # (a stop between clears it; the dropped motions' own modes do not matter)
            return
        if not _linear(seg, self.dogleg):  # an arc (or a curve) run from another start is another curve
            self._reason(before, seg, self.mode_of(before.block), None,
                         "a motion shorter than 3e-7 mm before it may be dropped by LinuxCNC, which then runs this "
                         "curve from the corner: not modelled")
            return
        moved = replace(seg, start=before.end)  # the motion after the dropped ones, as the planner runs it
        if _naive_only(self.mode_of(before.block)):  # the merging windows count the dropped motion as a point
            self._reason(before, seg, self.mode_of(before.block), None,
                         "a motion shorter than 3e-7 mm before it may be dropped by LinuxCNC in G64 Q without P "
                         "(naive CAM): not modelled; give P")
            return
        tls = (moved.tool_length,)
        self._shifts = frozenset((self._shift(moved),))
        if not self._fits(_piece_box(moved) or (moved.start, moved.end), tls, F0):
            self._reason(before, seg, self.mode_of(before.block), _piece_box(moved),
                         "a motion shorter than 3e-7 mm before it may be dropped by LinuxCNC, which then runs "
                         "this one from the corner")
            return
        self._queue(before, moved, self.mode_of(before.block))

    def _stop(self) -> None:
        self.prev_stop = True
        self._dropped = None
        self._close_stretch()
        self._naive_close()

    # ------------------------------------------------------------------ G64 Q without P (naive CAM, no tolerance)
    def _naive_tracked(self) -> bool:
        """Are motion boxes kept for G64 Q without P (the mode table has had such a mode)?"""
        if len(self.modes) != self._naive_modes:
            self._naive_modes = len(self.modes)
            self.naive.active = self.naive.active or any(_naive_only(m) for _b, m in self.modes)
        return self.naive.active

    def _naive_track(self, seg: Segment, joined: bool) -> None:
        """Keep ``seg`` in the run's window; prove the block of corners whose forward windows are complete."""
        nv = self.naive
        if not joined:
            self._naive_close()
        nv.add(seg)
        pending = nv.pending
        # the first waiting block's last forward window complete (its block and the next one read)
        while pending and (pending[0][3] // NAIVE_CHAIN + 2) * NAIVE_CHAIN <= nv.count:
            self._naive_block(nv.take())

    def _naive_close(self) -> None:
        """The run ended (an exact stop, a dwell, the end): prove its waiting corners, start a new window."""
        nv = self.naive
        while nv.pending:
            self._naive_block(nv.take())
        nv.restart()

    def _naive_block(self, group: list[tuple[Segment, Segment, PathMode, int]]) -> None:
        """The corners of one block of NAIVE_CHAIN motions (G64 Q without P): one box for all of them first
        (:meth:`_NaiveWindows.block_region`, a superset of each one's region), each one alone
        (:meth:`_naive_corner`) only when that box does not fit.  The box is tested at every tool length and
        tip offset of the block's motions: each corner's own test is one of those."""
        region = self.naive.block_region(group[0][3] // NAIVE_CHAIN) if NAIVE_BLOCKS else None
        if region is not None and all(b.start is a.end or b.start == a.end for a, b, _m, _i in group):
            t0 = group[0][0].tool_length
            tls: Iterable[Any] = (t0,)
            if not all((a.tool_length is t0 or a.tool_length == t0) and (b.tool_length is t0 or b.tool_length == t0)
                       for a, b, _m, _i in group):
                tls = {x.tool_length for a, b, _m, _i in group for x in (a, b)}
            self._shifts = (frozenset(self._shift(x) for a, b, _m, _i in group for x in (a, b))
                            if self.has_tip_zones else _NO_SHIFT)
            if self._fits(region, tls, F0):
                self.corners += len(group)
                return
        for corner in group:
            self._naive_corner(*corner)

    def _naive_corner(self, a: Segment, b: Segment, mode: PathMode, ia: int) -> None:
        """The corner after motion ``ia`` of the run in G64 Q without P (specs/path-modes.md §2): the planner
        blends, with no tolerance, lines that naive CAM merged from up to NAIVE_CHAIN motions.  The line before
        the corner ``C`` runs from a programmed point at most NAIVE_CHAIN motions back, the one after to one at
        most NAIVE_CHAIN ahead, and a blend uses at most half of each, so every point is ``C + (x - C) + (y - C)``
        with ``x``, ``y`` in the boxes of those windows (for two lines: the triangle of their far ends and C)."""
        self.corners += 1
        c = a.end
        region: Box | None = None
        tls = (a.tool_length, b.tool_length)
        self._shifts = frozenset((self._shift(a), self._shift(b)))
        if b.start == c:
            for exact in (False, True):
                region = self.naive.region(ia, c, exact)
                if region is not None and self._fits(region, tls, F0):
                    return
        self._reason(a, b, mode, region or (c, c),
                     f"G64 Q without P: LinuxCNC merges up to {NAIVE_CHAIN} motions within Q into one line (naive "
                     "CAM) and blends the merged lines with no tolerance, using up to half of each, so the corner "
                     "may be rounded over the motions around it; give P")

    def _close_stretch(self) -> None:
        st, self.stretch = self.stretch, None
        if st is None or (st[2] is st[3] and _linear(st[2], self.dogleg)):
            return  # a lone straight motion is its own hull; a lone arc's filtered path may cut inside it
        if st[2] is not st[3]:
            self.corners += 1
        lo, hi = tuple(st[0]), tuple(st[1])
        self._shifts = frozenset(self._stretch_shifts or {()})
        tls = (st[2].tool_length, st[3].tool_length, *self._stretch_tls)
        self._stretch_tls = set()
        if not self._fits((lo, hi), tls, F0) and not self._hull_fits(tls):
            n = len(self.reasons)
            self._reason(st[2], st[3], self.mode_of(st[2].block), (lo, hi),
                         _LONE_CURVE if st[2] is st[3] else _RUN, tls)
            if len(self.reasons) > n:  # the run's every block: a violation inside it makes the reason redundant
                self._blocks[-1] = range(st[2].block, st[3].block + 1)

    def _hull_add(self, seg: Segment, box: Box | None, first: bool) -> None:
        """Keep the ends of a straight motion (the segment's own tuples: nothing is computed unless the run's box
        does not fit), or the corners of another's box, for the run's convex hull (two-axis machines); a run of
        more than HULL_POINTS points keeps its box only."""
        if first:
            self._stretch_pts = [] if len(self.axes) == 2 else None
        pts = self._stretch_pts
        if pts is None:
            return
        if _linear(seg, self.dogleg):
            pts.append(seg.start)
            pts.append(seg.end)
        else:
            assert box is not None  # a straight motion's box is not needed
            (x0, y0), (x1, y1) = box
            pts.extend(((x0, y0), (x0, y1), (x1, y0), (x1, y1)))
        if len(pts) > HULL_POINTS:
            self._stretch_pts = None

    def _hull_fits(self, tls: tuple[Fraction, ...]) -> bool:
        """The run's convex hull (not its box) fits, on a two-axis machine (specs/path-modes.md §3)."""
        kept = self._stretch_pts
        self._stretch_pts = [] if len(self.axes) == 2 else None
        if not kept:
            return False
        pts = [(p[0], p[1]) for p in kept]
        w = self.widen_axis
        wx, wy = w[self.axes[0]], w[self.axes[1]]
        hull = convex_hull((x + sx * wx, y + sy * wy) for x, y in convex_hull(pts) for sx in (-1, 1)
                           for sy in (-1, 1)) if wx or wy else convex_hull(pts)
        tool_axis = self.allowed.tool_axis
        axes = (self.axes[0], self.axes[1])
        return all(hull_fits(hull, axes, allowed, self.margin, {tool_axis: tl} if tool_axis and tl else {})
                   for allowed in self._allowed_sets() for tl in set(tls))

    def _corner(self, a: Segment, b: Segment, mode: PathMode) -> None:
        """Prove the blend between motions ``a`` and ``b`` (``mode``: the one ``a`` runs in)."""
        t0 = time.perf_counter()
        self._shifts = frozenset((self._shift(a), self._shift(b)))
        try:
            self._prove_corner(a, b, mode)
        finally:
            self.refine_s += time.perf_counter() - t0

    def _prove_corner(self, a: Segment, b: Segment, mode: PathMode) -> None:
        self.corners += 1
        if mode.dialect == "fanuc" and mode.tolerance is None:
            return  # the run's hull (_close_stretch)
        tls = (a.tool_length, b.tool_length)
        bound = mode.bound()
        naive = mode.naive > 0
        if bound is None and naive:
            self._reason(a, b, mode, None, "G64 Q without P merges collinear motions (naive CAM) and blends them "
                                           "with no tolerance: not modelled; give P")
            return
        failed: Box | None = None
        if not naive:
            failed = self._region(a, b, tls)
            if failed is None:
                return
        if bound is not None:
            bad = self._near(a, tls, mode, True) or self._near(b, tls, mode, False)
            if bad is None:
                return
            failed = failed or bad
        if mode.dialect == "fanuc":
            why = (f"a Fanuc control in cutting mode may leave the programmed path by up to path_tolerance "
                   f"{format_decimal(mode.tolerance or F0)} mm at this corner")
        elif bound is not None:
            why = (f"LinuxCNC's planner may leave the programmed path by up to {format_decimal(bound)} mm here "
                   "(G64 P plus the naive-CAM Q, which defaults to P)")
        else:
            why = ("LinuxCNC's planner may round this corner using up to half of each motion (G64 without P); "
                   "G61, or G64 P with a tolerance that fits, proves it")
        if self._spent():
            why += " (the refinement budget was spent: the enclosure was not split further)"
        self._reason(a, b, mode, failed, why)

    # ------------------------------------------------------------------ enclosures
    def _region(self, a: Segment, b: Segment, tls: tuple[Fraction, Fraction]) -> Box | None:
        """None when the no-tolerance corner region fits, else a part of it that does not."""
        c = a.end
        if _linear(a, self.dogleg) and _linear(b, self.dogleg) and b.start == c:
            f = BLEND_FRACTION
            m1 = tuple(e + f * (s - e) for s, e in zip(a.start, a.end))
            m2 = tuple(s + f * (e - s) for s, e in zip(b.start, b.end))
            d1 = tuple(m - x for m, x in zip(m1, c))
            d2 = tuple(m - x for m, x in zip(m2, c))
            return self._refine(c, d1, d2, F0, Fraction(1), F0, Fraction(1), tls, DEPTH)
        ba, bb = _half_box(a, self.dogleg, end=True), _half_box(b, self.dogleg, end=False)
        if ba is None or bb is None:
            return (c, c)
        lo = tuple(x + y - z for x, y, z in zip(ba[0], bb[0], c))
        hi = tuple(x + y - z for x, y, z in zip(ba[1], bb[1], c))
        return None if self._fits((lo, hi), tls, F0) else (lo, hi)

    def _refine(self, c: tuple[Fraction, ...], d1: tuple[Fraction, ...], d2: tuple[Fraction, ...],
                a0: Fraction, a1: Fraction, b0: Fraction, b1: Fraction, tls: tuple[Fraction, Fraction],
                depth: int) -> Box | None:
        lo, hi = [], []
        for x, u, v in zip(c, d1, d2):
            vals = (x + a0 * u + b0 * v, x + a1 * u + b0 * v, x + a0 * u + b1 * v, x + a1 * u + b1 * v)
            lo.append(min(vals))
            hi.append(max(vals))
        box = (tuple(lo), tuple(hi))
        if self._fits(box, tls, F0):
            return None
        if depth == 0 or self._spent():
            return box
        am, bm = (a0 + a1) / 2, (b0 + b1) / 2
        for aa, ab in ((a0, am), (am, a1)):
            for ba, bb in ((b0, bm), (bm, b1)):
                bad = self._refine(c, d1, d2, aa, ab, ba, bb, tls, depth - 1)
                if bad is not None:
                    return bad
        return None

    def _near(self, seg: Segment, tls: tuple[Fraction, Fraction], mode: PathMode, end: bool) -> Box | None:
        """None when every point the control may move through near this corner on ``seg``'s side fits, else a
        part that may not.  A blend keeps within the tolerance p of the half of ``seg`` at the corner
        (``end``: the corner is its end); naive-CAM merging (q > 0, feeds only: ``STRAIGHT_TRAVERSE`` flushes
        the chain) may replace the whole motion by a chord within q of it, blended within p."""
        tol = mode.tolerance or F0
        whole = mode.naive > 0 and seg.kind is not _RAPID
        bound = tol + mode.naive if whole else tol
        if _linear(seg, self.dogleg):
            d = tuple(e - s for s, e in zip(seg.start, seg.end))
            t0, t1 = (F0, Fraction(1)) if whole else ((Fraction(1, 2), Fraction(1)) if end else (F0, Fraction(1, 2)))
            return self._near_line(seg.start, d, t0, t1, tls, bound, DEPTH + 1)
        box = _piece_box(seg) if whole else _half_box(seg, self.dogleg, end)
        if box is None:
            return (seg.start, seg.end)
        return None if self._fits(box, tls, bound) else box

    def _near_line(self, s: tuple[Fraction, ...], d: tuple[Fraction, ...], t0: Fraction, t1: Fraction,
                   tls: tuple[Fraction, Fraction], bound: Fraction, depth: int) -> Box | None:
        p = tuple(x + t0 * y for x, y in zip(s, d))
        q = tuple(x + t1 * y for x, y in zip(s, d))
        box = (tuple(map(min, p, q)), tuple(map(max, p, q)))
        if self._fits(box, tls, bound):
            return None
        if depth == 0 or self._spent():
            return box
        tm = (t0 + t1) / 2
        return (self._near_line(s, d, t0, tm, tls, bound, depth - 1)
                or self._near_line(s, d, tm, t1, tls, bound, depth - 1))

    def _spent(self) -> bool:
        """The refinement budget is spent: MAX_TESTS box tests, or a quarter of the run's time budget spent in
        corner proofs (the per-motion proof keeps the rest), or the run's budget itself."""
        if self.tests > MAX_TESTS or self.refine_s > self.refine_cap:
            return True
        return self.limits is not None and self.limits.budget_spent()

    def _fits(self, box: Box, tls: Iterable[Fraction], extra: Fraction, zone: int | None = None) -> bool:
        self.tests += 1
        w = self.widen_axis
        if self.widens:
            lo = {a: x - w[a] for a, x in zip(self.axes, box[0])}
            hi = {a: x + w[a] for a, x in zip(self.axes, box[1])}
        else:  # no parameter range: the same values without the Fraction operations
            lo, hi = dict(zip(self.axes, box[0])), dict(zip(self.axes, box[1]))
        return all(box_fits(allowed, lo, hi, self.margin + extra, tl,
                            allowed.zones if zone is None else (allowed.zones[zone],))
                   for allowed in self._allowed_sets() for tl in set(tls))

    def _shift(self, seg: Segment) -> tuple[tuple[str, Fraction], ...]:
        """``seg``'s tool offsets off the tool axis, as a key (empty: none, or no tip zone to move)."""
        extra = seg.extra
        if not extra or not self.has_tip_zones:
            return ()
        if extra is self._last_extra[0]:  # the interpreter shares one payload tuple while the offsets hold
            return self._last_extra[1]
        key = tuple(sorted(tip_offset(extra).items()))
        self._last_extra = (extra, key)
        return key

    def _allowed_sets(self) -> list[Any]:
        """The allowed sets a box is tested against: the tip zones moved by each offset of the motions in play."""
        if self._shifts == _NO_SHIFT:
            return self._unshifted
        out = []
        for key in self._shifts:
            got = self._shifted.get(key)
            if got is None:
                got = self._shifted[key] = tip_shifted(self.allowed, dict(key))
            out.append(got)
        return out

    # ------------------------------------------------------------------ reasons
    def _reason(self, a: Segment, b: Segment, mode: PathMode, box: Box | None, why: str,
                tls: tuple[Fraction, ...] = ()) -> None:
        la, lb = a.line, b.line
        where = f"lines {la} and {lb}" if la != lb else f"line {la}"
        key = f"{la}:{lb}"
        if key in self._seen:
            return
        self._seen.add(key)
        if len(self.reasons) >= MAX_REASONS:
            self.more += 1
            return
        zone = ""
        text = ""
        if box is not None:
            text = " may pass " + " ".join(
                f"{n}{format_decimal(lo, 4)}" if lo == hi else f"{n}{format_decimal(lo, 4)}..{format_decimal(hi, 4)}"
                for n, lo, hi in zip(self.axes, box[0], box[1]))
            tls = tls or (a.tool_length, b.tool_length)
            hit = [z for k, z in enumerate(self.zones) if not self._fits(box, tls, F0, zone=k)][:3]
            if hit:
                zone = ", " + ", ".join(f"{'inside' if z.forbid else 'outside'} `{z.name}`" for z in hit)
        what = f"the motion of {where}" if a is b else f"the blend between {where}"
        msg = f"{BLEND_CODE}: {what} ({mode.code}){text}{zone}: {why}"
        self.reasons.append(Reason(msg, b.span, b.block, BLEND_CODE))
        self._blocks.append((a.block, b.block))

    # ------------------------------------------------------------------ column chunks (numpy screen)
    def _columns(self, chunk: MotionChunk) -> None:
        """A column chunk: corner boxes in integers (scale ``2 * 10**scale``), screened many at a time."""
        import numpy as np

        n = len(chunk)
        kinds, starts, ends = chunk.kind, chunk.start, chunk.end
        if n == 0 or kinds is None or starts is None or ends is None or chunk.block is None \
                or chunk.tool_length is None:
            return
        table = self.modes
        at, used = _mode_rows(table, chunk.block)
        count = np.bincount(kinds, minlength=len(SegmentKind))  # rows of each kind (kinds are small and >= 0)
        plain = (not count[[k for k in range(len(count)) if k not in _SIMPLE]].any()
                 and not (self.dogleg and count[_RAPID])
                 and max(int(starts.max()), -int(starts.min()), int(ends.max()), -int(ends.min())) < 2**58)
        hull = [m.blend and m.dialect == "fanuc" and m.tolerance is None for m in used]
        naive = self._naive_tracked()  # G64 Q without P: every motion joins the merging windows, one at a time
        if not naive and plain and any(hull) and HULL_COLUMNS and all(h or not m.blend for h, m in zip(hull, used)):
            self._hull_columns(chunk, at)  # Fanuc cutting mode without path_tolerance: the runs' boxes
            return
        if (naive or not plain or any(hull) or _droppable_rows(chunk)
                or any(m.blend and m.bound() is None and m.naive for m in used)
                or (count[_ARC] and any(m.dialect == "fanuc" for m in used))):
            for seg in chunk.segments():  # the exact path, one motion at a time (a Fanuc arc: its hull)
                self._segment(seg)
            return
        dwell = kinds == _DWELL
        arc = kinds == _ARC
        moving = _rows_differ(starts, ends) | arc
        rows = np.flatnonzero(moving & ~dwell) if count[_DWELL] else np.flatnonzero(moving)
        if rows.size == 0:
            if count[_DWELL]:
                self._stop()
            return
        first, last = int(rows[0]), int(rows[-1])
        if dwell[:first].any():
            self._stop()
        self._segment(_row(chunk, first))  # the corner with the chunk before
        i, j = rows[:-1], rows[1:]
        if len(used) > 1:
            blend = np.array([table[k][1].blend for k in range(len(table))], dtype=bool)[at]
            keep = blend[i]
        else:
            keep = np.full(i.size, used[0].blend, dtype=bool)
        if count[_DWELL]:
            dwells = np.cumsum(dwell)
            keep &= dwells[j] == dwells[i]
        if not keep.all():
            i, j = i[keep], j[keep]
        if i.size:
            self._corner_columns(chunk, i, j, at, used, bool(count[_ARC]))
        seg = _row(chunk, last)
        if last != first:
            self.prev = seg
            self.prev_stop = not self.mode_of(seg.block).blend
        if dwell[last:].any():
            self._stop()

    def _corner_columns(self, chunk: MotionChunk, i: Any, j: Any, at: Any, used: Sequence[PathMode], arcs: bool) -> None:
        """Prove the corners ``i[k]``/``j[k]`` of a column chunk: all at once in one box when it fits, else each one's
        box in integers (over ``2 * 10**scale``), screened many at a time (:meth:`_screen`).

        The one box: the union of every row's box (its end points; an arc's outward-rounded box) grown by the
        largest bound of the chunk's modes, and of the boxes of the corners next to an arc.  It holds every
        corner's box the screen computes (two straight motions' corner region lies in the box of the two, with a
        bound in both boxes grown by it; a corner next to an arc is the Minkowski sum of the half boxes, computed
        as the screen does), so it is the union test :meth:`_screen` starts with on a larger box: when it fits,
        that one fits too.  It is taken when every corner's two rows have the tool length of the first and the
        rows are joined (each starts where the one before ends), as the screen's union test needs."""
        import numpy as np

        kinds, starts, ends, tls = chunk.kind, chunk.start, chunk.end, chunk.tool_length
        assert kinds is not None and starts is not None and ends is not None and tls is not None  # columns
        assert chunk.scale is not None
        lo, hi = np.minimum(starts, ends), np.maximum(starts, ends)
        boxed = np.ones(len(chunk), dtype=bool)
        arc_rows = np.flatnonzero(kinds == _ARC) if arcs else None
        if arc_rows is not None:
            boxed[arc_rows] = _arc_columns(chunk, arc_rows, lo, hi)
        scale2 = 2 * 10**chunk.scale
        whole = (len(chunk.axes) == len(self.axes) and int(tls.min()) == int(tls.max()) and bool(boxed.all())
                 and not _rows_differ(starts[1:], ends[:-1]).any())
        if whole:
            g = max((b for b in (m.bound() for m in used if m.blend) if b is not None), default=F0)
            box_lo = [Fraction(2 * int(lo[:, k].min()), scale2) - g for k in range(len(self.axes))]
            box_hi = [Fraction(2 * int(hi[:, k].max()), scale2) + g for k in range(len(self.axes))]
            if arc_rows is not None:
                near = (kinds[i] == _ARC) | (kinds[j] == _ARC)
                if near.any():
                    c_lo, c_hi = self._corner_ints(chunk, lo, hi, i[near], j[near], at, scale2)
                    for k in range(len(self.axes)):
                        box_lo[k] = min(box_lo[k], Fraction(int(c_lo[:, k].min()), scale2))
                        box_hi[k] = max(box_hi[k], Fraction(int(c_hi[:, k].max()), scale2))
            self._shifts = _NO_SHIFT  # column rows carry no tool offsets
            if self._fits((tuple(box_lo), tuple(box_hi)), (Fraction(int(tls[0]), 10**chunk.scale),), F0):
                self.corners += int(i.size)
                return
        c_lo, c_hi = self._corner_ints(chunk, lo, hi, i, j, at, scale2)
        joined = ~_rows_differ(starts[j], ends[i])  # else the exact path (the corner is not one point)
        self._screen(chunk, c_lo, c_hi, i, j, boxed[i] & boxed[j] & joined, tls[i], tls[j], scale2, at)

    def _corner_ints(self, chunk: MotionChunk, lo: Any, hi: Any, i: Any, j: Any, at: Any, scale2: int) -> Any:
        """The boxes of the corners ``i[k]``/``j[k]`` in integers over ``scale2`` (``lo``/``hi``: the rows' boxes):
        a line's half at the corner and an arc's whole box, summed less the corner; with a bound, both motions'
        boxes grown by it."""
        import numpy as np

        kinds, starts, ends = chunk.kind, chunk.start, chunk.end
        assert kinds is not None and starts is not None and ends is not None  # columns
        table = self.modes
        ei, si, sj, ej = ends[i], starts[i], starts[j], ends[j]
        lo_i, hi_i, lo_j, hi_j = lo[i], hi[i], lo[j], hi[j]
        lin_i = (kinds[i] != _ARC)[:, None]
        lin_j = (kinds[j] != _ARC)[:, None]
        mid_i, mid_j = si + ei, sj + ej
        t_lo = np.where(lin_i, np.minimum(mid_i, 2 * ei), 2 * lo_i)
        t_hi = np.where(lin_i, np.maximum(mid_i, 2 * ei), 2 * hi_i)
        h_lo = np.where(lin_j, np.minimum(mid_j, 2 * sj), 2 * lo_j)
        h_hi = np.where(lin_j, np.maximum(mid_j, 2 * sj), 2 * hi_j)
        c_lo = t_lo + h_lo - 2 * ei
        c_hi = t_hi + h_hi - 2 * ei
        bounds = [m.bound() for m in (table[k][1] for k in range(len(table)))]
        widen = np.array([0 if b is None else -((-b * scale2).numerator // (b * scale2).denominator)
                          for b in bounds], dtype=np.int64)[at[i]]
        tol = widen > 0
        if tol.any():  # within the bound of both motions' boxes
            n_lo = 2 * np.minimum(lo_i, lo_j) - widen[:, None]
            n_hi = 2 * np.maximum(hi_i, hi_j) + widen[:, None]
            c_lo = np.where(tol[:, None], n_lo, c_lo)
            c_hi = np.where(tol[:, None], n_hi, c_hi)
        return c_lo, c_hi

    def _screen(self, chunk: MotionChunk, c_lo: Any, c_hi: Any, i: Any, j: Any, boxed: Any, tl_a: Any, tl_b: Any,
                scale2: int, at: Any) -> None:
        """Prove the corners ``i[k]``/``j[k]`` whose boxes are ``c_lo``/``c_hi`` (integers over ``scale2``): the
        union of many at once, halves of what does not fit, one by one exactly at the end."""
        assert chunk.scale is not None  # a column chunk
        den = 10**chunk.scale
        proved = self._rows_proved(chunk, c_lo, c_hi, boxed, tl_a, tl_b)
        if proved is not None and proved.any():
            self.corners += int(proved.sum())
            rest = (~proved).nonzero()[0]
            c_lo, c_hi, i, j, boxed, tl_a, tl_b = (x[rest] for x in (c_lo, c_hi, i, j, boxed, tl_a, tl_b))
        todo = [(0, int(i.size))] if i.size else []
        axes = range(c_lo.shape[1])
        while todo:
            a, b = todo.pop()
            same = bool((tl_a[a:b] == tl_a[a]).all() and (tl_b[a:b] == tl_a[a]).all())
            if same and boxed[a:b].all():
                box = (tuple(Fraction(int(c_lo[a:b, k].min()), scale2) for k in axes),
                       tuple(Fraction(int(c_hi[a:b, k].max()), scale2) for k in axes))
                self._shifts = _NO_SHIFT  # column rows carry no tool offsets
                if self._fits(box, (Fraction(int(tl_a[a]), den),), F0):
                    self.corners += b - a
                    continue
            if b - a == 1:
                p, q = int(i[a]), int(j[a])
                self._corner(_row(chunk, p), _row(chunk, q), self.modes[int(at[p])][1])
                continue
            size = -(-(b - a) // SPLIT)
            todo.extend((x, min(x + size, b)) for x in range(a, b, size))

    def _rows_proved(self, chunk: MotionChunk, c_lo: Any, c_hi: Any, boxed: Any, tl_a: Any, tl_b: Any) -> Any:
        """Which corners' own boxes (``c_lo``/``c_hi``, integers over ``2 * 10**scale``) the motions' screen proves
        (:data:`~nczones.prover.screen.ZONE_ROWS`, every zone kind, all rows at once), or None when it cannot be
        asked (parameter ranges widen the boxes; the chunk's axes are not the machine's; a number too large).

        Soundness: each row's box is rounded outwards to ``10**-scale`` and grown by the margin rounded up, and the
        screen passes a row only when that box fits every zone (tip zones seen at the row's tool length), as
        :func:`~nczones.prover.exact.box_fits` would show of the corner's exact box, which it holds.  A row is
        asked only where the union test of :meth:`_screen` could take it alone (its box computed, both motions
        at one tool length); every other row goes on to the union tests and the exact path as before.  The
        screen takes the place of the union tests for rows it passes, never of a test that fails (a row it does
        not pass is tested as before), so the corners proved are a subset of those :meth:`_fits` would prove of
        the same boxes (``tests/prover/test_corner_row_screen.py`` holds the two to the same verdicts)."""
        if self.widens or tuple(chunk.axes) != tuple(self.axes) or chunk.scale is None:
            return None
        import numpy as np

        from .screen import ZONE_ROWS

        margin = self.margin
        d_up = -((-margin.numerator * 10**chunk.scale) // margin.denominator)
        limit = 2**60
        if d_up >= limit or int(np.abs(tl_a).max(initial=0)) >= limit or \
                max(int(np.abs(c_lo).max(initial=0)), int(np.abs(c_hi).max(initial=0))) >= limit:
            return None
        lo, hi = c_lo // 2 - d_up, -((-c_hi) // 2) + d_up  # outwards to the chunk's scale, the margin rounded up
        ok = boxed & (tl_a == tl_b)
        names = list(self.axes)
        view = self._zone_view
        if view is None:
            view = self._zone_view = _ZoneView(self.allowed.zones, margin, self.allowed.tool_axis)
        for z in view.zones:
            if not ok.any():
                break
            tip = z.point is ZonePoint.TIP

            def rng(a: str) -> tuple[Any, Any]:
                k = names.index(a)
                if tip and a == view.tool_axis:  # noqa: B023 - called within this iteration
                    return lo[:, k] - tl_a, hi[:, k] - tl_a
                return lo[:, k], hi[:, k]

            ZONE_ROWS(z, view, rng, ok, chunk.scale, names)
        return ok

    # ------------------------------------------------------------------ Fanuc runs on column chunks
    def _hull_columns(self, chunk: MotionChunk, at: Any) -> None:
        """Fanuc cutting mode without a tolerance on a column chunk: what :meth:`_segment` does row by row (the
        same stretches, corners, checks and reasons), each group's box found from the columns.

        A group is the rows after a stop up to the next stop: blended motions, then the non-blended motion that
        ends the run with an exact stop (it belongs to the run) or a dwell (it does not).  A group with a row
        the columns cannot box goes through :meth:`_segment` row by row."""
        import numpy as np

        kinds, starts, ends = chunk.kind, chunk.start, chunk.end
        assert kinds is not None and starts is not None and ends is not None  # a column chunk
        dwell = kinds == _DWELL
        arc = kinds == _ARC
        moving = ((starts != ends).any(axis=1) | arc) & ~dwell
        table = self.modes
        blend = np.array([table[k][1].blend for k in range(len(table))], dtype=bool)[at] & moving
        lo, hi = np.minimum(starts, ends), np.maximum(starts, ends)
        ends_lo, ends_hi = lo.copy(), hi.copy()  # the end points: every box has lo <= ends_lo, hi >= ends_hi
        arcs = np.flatnonzero(arc)
        boxed = np.ones(len(chunk), dtype=bool)
        if arcs.size:
            boxed[arcs] = _arc_columns(chunk, arcs, lo, hi)  # outward-rounded boxes holding each arc
            _one_unit_out(chunk, arcs, lo, hi)  # and :func:`_piece_box`'s box of each (see there)
        ev = np.flatnonzero(moving | dwell)
        if ev.size == 0:
            return
        cut = (np.flatnonzero(dwell[ev] | ~blend[ev]) + 1).tolist()  # a group ends after each stop
        cols = (lo, hi, ends_lo, ends_hi, arc)
        for g, (a, b) in enumerate(zip([0, *cut], [*cut, int(ev.size)])):
            if a == b:
                continue
            rows = ev[a:b]
            before = not g and self.prev is not None and not self.prev_stop  # a blended corner with the rows before
            if self._hull_group(chunk, rows, dwell, blend, boxed, cols, before):
                continue
            if g:  # the exact path from here: the group follows a stop
                self.prev_stop = True
            for r in rows.tolist():
                self._segment(_row(chunk, r))
        last = int(ev[moving[ev]][-1]) if moving[ev].any() else None
        if last is not None:
            self.prev = _row(chunk, last)
            self.prev_stop = not blend[last] or bool(dwell[last:].any())

    def _hull_group(self, chunk: MotionChunk, rows: Any, dwell: Any, blend: Any, boxed: Any, cols: Any,
                    corner_before: bool) -> bool:
        """One group of :meth:`_hull_columns` (False: not done, prove it one motion at a time)."""
        end = int(rows[-1])
        body = rows[:-1] if dwell[end] else rows
        if body.size and not boxed[body].all():
            return False
        if body.size == 0:
            self._stop()
            return True
        self.corners += int(body.size) - 1 + corner_before  # what _queue counts: Fanuc corners wait for the hull
        first, last = int(body[0]), int(body[-1])
        if self.stretch is None and body.size == 1 and not blend[first] and not cols[4][first]:
            return True  # a lone exact-stop straight motion: no run (an arc is held to its hull)
        box = self._rows_box(chunk, body, cols)
        if box is None:
            self.corners -= int(body.size) - 1 + corner_before
            return False
        seg_a = _row(chunk, first)
        seg_b = seg_a if last == first else _row(chunk, last)
        # the convex-hull refinement keeps no points of column rows: the run is proved by its box alone
        self._stretch_pts = None
        tls = chunk.tool_length
        assert tls is not None and chunk.scale is not None  # a column chunk
        if self.stretch is None:
            self.stretch = [list(box[0]), list(box[1]), seg_a, seg_b]
            self._stretch_shifts = {self._shift(seg_a), self._shift(seg_b)}
            self._stretch_tls = set()
        else:
            self._stretch_shifts |= {self._shift(seg_a), self._shift(seg_b)}
            self._stretch_tl(self.stretch[3], seg_a)
            s_lo, s_hi = self.stretch[0], self.stretch[1]
            for k in range(len(s_lo)):
                s_lo[k] = min(s_lo[k], box[0][k])
                s_hi[k] = max(s_hi[k], box[1][k])
            self.stretch[3] = seg_b
        if int(tls[body].min()) != int(tls[body].max()):  # a G43/G49 inside the group: its every length
            den = 10**chunk.scale
            self._stretch_tls |= {Fraction(int(v), den) for v in set(tls[body].tolist())}
        if dwell[end]:
            self._stop()
        elif not blend[last]:
            self._close_stretch()
        return True

    def _arc_box(self, chunk: MotionChunk, r: int) -> Box | None:
        """:func:`_piece_box` of arc row ``r``, shared by rows that repeat the same arc (the same columns: end
        points, centre, radius, sense, turns, plane), as repeated passes do."""
        cols = [chunk.start, chunk.end, chunk.centre, chunk.radius, chunk.clockwise, chunk.turns, chunk.plane]
        key = (chunk.scale, tuple(chunk.axes), *(None if c is None else c[r].tobytes() for c in cols))
        cache = self._arc_cache
        if key not in cache:
            if len(cache) >= ARC_CACHE:
                cache.clear()
            cache[key] = _piece_box(_row(chunk, r))
        return cache[key]

    def _rows_box(self, chunk: MotionChunk, rows: Any, cols: Any) -> Box | None:
        """The box :func:`_piece_box` gives the union of ``rows`` (None: an arc it cannot box), or its union with
        the run's box so far when a run is open (``self.stretch``: the caller takes that union anyway).

        Lines' boxes are their columns'; an arc's exact box lies between its end points and its outward-rounded
        column box, so per axis and side only the arcs whose column box passes the best bound found so far (the
        end points', or the run's when it passes them) are boxed exactly (in order, stopping at the first that
        cannot improve it)."""
        import numpy as np

        lo, hi, ends_lo, ends_hi, arc = cols
        assert chunk.scale is not None  # a column chunk
        den = 10**chunk.scale
        exact: dict[int, Box | None] = {}
        run = self.stretch
        arcs = rows[arc[rows]]
        out_lo: list[Fraction] = []
        out_hi: list[Fraction] = []
        for k in range(len(self.axes)):
            for side in (0, 1):
                if side == 0:
                    end = int(ends_lo[rows, k].min())
                    col = lo[arcs, k]
                else:
                    end = -int(ends_hi[rows, k].max())
                    col = -hi[arcs, k]
                best = Fraction(end if side == 0 else -end, den)
                if run is not None:
                    best = min(best, run[0][k]) if side == 0 else max(best, run[1][k])
                # only arcs whose column box passes the end points can widen the box (columns in the same unit)
                near = np.flatnonzero(col < end)
                near = near[np.argsort(col[near], kind="stable")]
                for o in near.tolist():
                    bound = Fraction(int(col[o]), den)
                    if (bound >= best) if side == 0 else (-bound <= best):
                        break
                    r = int(arcs[o])
                    if r not in exact:
                        exact[r] = self._arc_box(chunk, r)
                    box = exact[r]
                    if box is None:
                        return None
                    best = min(best, box[0][k]) if side == 0 else max(best, box[1][k])
                (out_lo if side == 0 else out_hi).append(best)
        return tuple(out_lo), tuple(out_hi)


def _arc_columns(chunk: MotionChunk, rows: Any, lo: Any, hi: Any) -> Any:
    """:func:`nczones.prover.screen.arc_boxes` of the arc ``rows`` (widen ``lo``/``hi`` at the chunk's scale; True
    where boxed): the screen's boxes of this chunk rounded outwards to its scale when the screen formed them just
    before (:func:`nczones.prover.screen.shared_arc_boxes`: each chunk is screened, then its corners proved),
    else formed here."""
    from .screen import arc_boxes, shared_arc_boxes

    assert chunk.scale is not None  # a column chunk
    shared = shared_arc_boxes(chunk)
    if shared is None or shared[0] < chunk.scale:
        return arc_boxes(chunk, rows, lo, hi)
    f = 10 ** (shared[0] - chunk.scale)
    lo[rows] = shared[2][rows] // f
    hi[rows] = -((-shared[3][rows]) // f)
    return shared[1][rows]


def _one_unit_out(chunk: MotionChunk, rows: Any, lo: Any, hi: Any) -> None:
    """Widen the arc ``rows``' column boxes (:func:`nczones.prover.screen.arc_boxes`, at the chunk's scale or at
    the screen's finer one rounded outwards to it) by one unit in their plane, so that each holds the box
    :func:`_piece_box` gives the arc, as ``_rows_box`` needs.  (Below, "unit" is the unit the box was formed
    in; rounding outwards to a coarser one keeps every bound, and one coarse unit is at least one fine unit.)

    * An I/J arc: ``plane_bbox`` adds the radius's 64-bit upper bound, which may pass the column's
      ``ceil(sqrt(r2))`` by far less than a unit; the sweep tests are the same exact ones.
    * An R arc (:func:`nczones.prover.rformat.rformat_boxes`, where it boxed the row): a centre enclosure
      ``[lo, hi]`` in units ``1/m`` of the column unit (``2 mag m < 2**59``, ``mag`` the largest coordinate or
      radius in column units) holds the exact centre ``c``.  Where the four signs of the components of
      ``s - c`` and ``e - c`` are certain (the end point is outside the enclosure), it is at least ``1/m`` from
      ``c``; ``plane_bbox`` moves the centre by at most ``2**-64 |e - s| <= 2**-64 * 2 sqrt 2 mag < 1/m`` (the
      two ends of its 64-bit centre segment), and ``k_lo > 0`` there (``rformat`` encloses no chord of about
      ``2|R|``), so every sign ``_sweep_may_hold`` reads is the exact centre's at both ends: it keeps exactly
      the directions the sweep holds, which ``rformat_boxes`` keeps too (it is sound).  Where a sign is not
      certain, or the arc turns, ``rformat_boxes`` keeps all four directions.  Each kept extreme there is the
      enclosure's bound plus ``|R|`` rounded up; ``plane_bbox``'s (``|R|`` exact, the centre's end at most
      ``2**-64 |e - s| < 1/m`` beyond the exact one) may pass it by less than a unit.  An R arc whose centre
      is rational (``q`` a square, or a half circle): its exact directions, a subset of the kept ones, and its
      exact extremes.  The end points and the other axes are the same in both."""
    from ..motion import PLANE_AXES, Plane

    if rows.size == 0:
        return
    assert chunk.plane is not None  # arcs, columns form
    axes = list(chunk.axes)
    planes = chunk.plane[rows]
    for pv in sorted(set(planes.tolist())):
        a_name, b_name, _ = PLANE_AXES[Plane(int(pv))]
        sel = rows[planes == pv]
        for name in (a_name, b_name):
            if name in axes:
                lo[sel, axes.index(name)] -= 1
                hi[sel, axes.index(name)] += 1


def _mode_rows(table: Sequence[tuple[int, PathMode]], blocks: Any) -> tuple[Any, list[PathMode]]:
    """The index in the mode table of each row's mode (a chunk's ``block`` column), and the modes used."""
    import numpy as np

    mode_blocks = np.array([b for b, _m in table], dtype=np.int64)
    at = np.maximum(np.searchsorted(mode_blocks, blocks, side="right") - 1, 0)
    k0, k1 = int(at.min()), int(at.max())
    return at, [table[k][1] for k in ((k0,) if k0 == k1 else np.unique(at).tolist())]


def _rows_differ(a: Any, b: Any) -> Any:
    """Per row, do the integer rows of ``a`` and ``b`` differ (a boolean column; column by column, which numpy
    does many times faster than a reduction along the rows of an (n, 3) array)?"""
    ne = a != b
    out = ne[:, 0].copy()
    for k in range(1, ne.shape[1]):
        out |= ne[:, k]
    return out


def _row(chunk: MotionChunk, k: int) -> Segment:
    """Row ``k`` of a column chunk as a segment (``MotionChunk.segments`` for one row)."""
    return next(chunk.rows(k, k + 1).segments())


def _droppable_rows(chunk: MotionChunk) -> bool:
    """Does the column chunk hold a straight motion LinuxCNC may drop (shorter than ``DROPPED_BELOW`` on every
    axis, not 0): then its corners take the one-motion path (:meth:`CornerCheck._dropped_corner`)."""
    import numpy as np

    assert chunk.scale is not None and chunk.start is not None and chunk.end is not None and chunk.kind is not None
    lim = -(-DROPPED_BELOW.numerator * 10**chunk.scale // DROPPED_BELOW.denominator)  # ceil: d < lim iff d < D
    if lim <= 1:
        return False  # every non-zero change is at least one unit of the scale, not below DROPPED_BELOW
    d = np.abs(chunk.end - chunk.start)
    straight = (chunk.kind == _LINE) | (chunk.kind == _RAPID)
    return bool((straight & (d != 0).any(axis=1) & (d < lim).all(axis=1)).any())


#: Motions a Fanuc control's acc/dec after interpolation may pull inside in any path mode (their hull is proved).
_FILTERED_CURVES = frozenset({_ARC, SegmentKind.POLAR})
_RUN = ("a Fanuc control in cutting mode rounds corners by acc/dec after interpolation, which keeps the path inside "
        "the convex hull of the motions between exact stops; give [machine] path_tolerance (the control's bound) or "
        "program G61/G09")
_LONE_CURVE = ("a Fanuc control's acc/dec after interpolation averages the commanded axis positions along an arc or a "
               "polar move in every path mode (G61 and G09 stop only at its end), so the moved path may cut inside "
               "it, anywhere in its convex hull (an arc: between the arc and its chord); nothing in the machine file "
               "bounds that")


def _linear(seg: Segment, dogleg: bool) -> bool:
    return seg.kind is _LINE or (seg.kind is _RAPID and not dogleg)


def _piece_box(seg: Segment) -> Box | None:
    """A box holding every point of ``seg`` (lines, rapids straight or dogleg, arcs); None for other kinds."""
    if seg.kind in (_LINE, _RAPID):
        return tuple(map(_lo, seg.start, seg.end)), tuple(map(_hi, seg.start, seg.end))
    if seg.kind is _ARC:
        plane = _arc_plane_box(seg)
        if plane is None:
            from .geometry import arc_geom

            try:
                g = arc_geom(seg)
            except InvalidArgument:  # an arc the per-motion proof refuses: no box
                return None
            plane = (*g.plane_bbox(sweep=True), g.ia, g.ib)
        (xl, xh), (yl, yh), ia, ib = plane
        lo, hi = list(map(_lo, seg.start, seg.end)), list(map(_hi, seg.start, seg.end))
        lo[ia], hi[ia], lo[ib], hi[ib] = xl, xh, yl, yh
        return tuple(lo), tuple(hi)
    if seg.kind is SegmentKind.SPLINE:
        # a NURBS curve with positive weights lies in the convex hull of its control points
        curve = seg.payload(SplineCurve)
        if curve is None or not curve.control or any(w <= 0 for w in curve.weights):
            return None
        control = curve.control
        pts = [seg.start, seg.end, *control]
        return tuple(map(min, *pts)), tuple(map(max, *pts))
    if seg.kind is SegmentKind.DEVELOPED_ARC:
        from ..geometry.cylinder import cylinder_of, developed_arc_of

        info = cylinder_of(seg)
        try:
            arc = developed_arc_of(seg)
        except ValueError:
            return None
        assert info is not None  # developed_arc_of needs it
        iz, ic = seg.axes.index(info[0]), seg.axes.index(info[1])
        lo, hi = list(map(min, seg.start, seg.end)), list(map(max, seg.start, seg.end))
        for k in range(4):
            z, _s, c = arc.box(Fraction(k, 4), Fraction(k + 1, 4))
            lo[iz], hi[iz] = min(lo[iz], z.lo), max(hi[iz], z.hi)
            lo[ic], hi[ic] = min(lo[ic], c.lo), max(hi[ic], c.hi)
        return tuple(lo), tuple(hi)
    return None


def _arc_plane_box(seg: Segment) -> Any:
    """``ArcGeom.plane_bbox()`` of an arc with a rational centre (a circle, a spiral, a whole turn), with its
    plane's axis indices: :func:`nczones.prover.geometry.rational_arc_plane_box` (integer sweep tests, the same
    box); None for other arcs (``arc_geom`` decides them)."""
    from .geometry import rational_arc_plane_box

    return rational_arc_plane_box(seg)


def _half_box(seg: Segment, dogleg: bool, end: bool) -> Box | None:
    """A box holding the part of ``seg`` a blend may use at its end (``end``) or start: a line's half; a circular
    arc's (of less than a whole turn) half at its start and, at its end, the part from before a quarter of its
    sweep (the planner trims up to two thirds of an arc before a corner, ``blendInit3FromArcLine`` /
    ``ArcArc``: ``phi1_max = angle * 2/3``); the whole box of other motions."""
    m = tuple(map(_mid, seg.start, seg.end))
    p = seg.end if end else seg.start
    if _linear(seg, dogleg):
        return tuple(map(_lo, m, p)), tuple(map(_hi, m, p))
    if seg.kind is _ARC:
        half = _half_arc_box(seg, end)
        if half is not None:
            # the other axes (a helix's) move with the angle: the half of their travel at that end
            lo, hi = list(map(_lo, m, p)), list(map(_hi, m, p))
            (xl, xh), (yl, yh), ia, ib = half
            lo[ia], hi[ia], lo[ib], hi[ib] = xl, xh, yl, yh
            return tuple(lo), tuple(hi)
    return _piece_box(seg)


def _half_arc_box(seg: Segment, end: bool) -> Any:
    """``((lo, hi) first axis, (lo, hi) second axis, ia, ib)`` holding the half of the sweep of a circular arc with
    a rational centre at its start, or its last three quarters (``end``, see :func:`_half_box`); None for a whole
    turn, a spiral or an R-format arc.

    The angular middle of the sweep points along ``u + w`` (``u``, ``w``: start and end from the centre, of
    equal length; the opposite when the sweep is more than half a turn, ``u`` turned a quarter for half a
    turn); the middle point is ``c + r d / |d|``, enclosed with rational square-root bounds.
    """
    from .geometry import arc_geom, in_sweep, sqrt_bounds

    try:
        g = arc_geom(seg)
    except InvalidArgument:
        return None
    if g.full or g.centre is None or g.r2_lo != g.r2_hi:
        return None
    c = g.centre
    u = (g.s[0] - c[0], g.s[1] - c[1])
    w = (g.e[0] - c[0], g.e[1] - c[1])
    cross = u[0] * w[1] - u[1] * w[0]
    if cross == 0:  # half a turn: u turned a quarter in the sweep's sense
        d = (-u[1], u[0]) if g.ccw else (u[1], -u[0])
    else:
        d = (u[0] + w[0], u[1] + w[1])
        if (cross < 0) == g.ccw:  # more than half a turn
            d = (-d[0], -d[1])
    if end:
        # from direction u k + d, k >= |d| / r: on the sweep between u and the quarter point (the bisector of
        # u and d), so the part up to the end holds the last three quarters, more than the two thirds a blend
        # may trim (tp.c tpCreateArcLineBlend / ArcArcBlend: trim1 <= phi1_max <= angle * 2/3)
        r_lo = sqrt_bounds(g.r2_lo)[0]
        k = sqrt_bounds(d[0] * d[0] + d[1] * d[1])[1] / r_lo
        d = (u[0] * k + d[0], u[1] * k + d[1])
    k_lo, k_hi = sqrt_bounds(g.r2_hi / (d[0] * d[0] + d[1] * d[1]))
    mid = [sorted((c[i] + d[i] * k_lo, c[i] + d[i] * k_hi)) for i in (0, 1)]
    a, b = (d, w) if end else (u, d)
    p = g.e if end else g.s
    r_lo, r_hi = sqrt_bounds(g.r2_hi)
    out = []
    for i in (0, 1):
        lo, hi = min(mid[i][0], p[i]), max(mid[i][1], p[i])
        for sgn in (1, -1):
            v = (Fraction(sgn), F0) if i == 0 else (F0, Fraction(sgn))
            if in_sweep(a, b, v, g.ccw, False):
                if sgn > 0:
                    hi = max(hi, c[i] + r_hi)
                else:
                    lo = min(lo, c[i] - r_hi)
        out.append((lo, hi))
    return out[0], out[1], g.ia, g.ib



def _naive_only(mode: PathMode) -> bool:
    """LinuxCNC ``G64 Q q`` without P: naive-CAM merging and blends with no tolerance."""
    return mode.blend and mode.dialect == "linuxcnc" and bool(mode.naive) and not mode.tolerance


class _NaiveWindows:
    """The motions of a run's last windows, for G64 Q without P (specs/path-modes.md §2).

    Kept per motion (the motions themselves; their boxes, :func:`_piece_box`, computed when a corner is proved
    alone), and per block of NAIVE_CHAIN motions the box of the block's motions, grown as they come: a window
    of NAIVE_CHAIN motions touches at most two blocks.  A corner alone is proved first with the blocks its two
    windows touch, then exactly, with the boxes of whole groups of SMALL motions (united when first asked: a
    group is complete by then) and of the single motions at the windows' ends.

    The corners are proved a block at a time (:meth:`block_region`): the corners after motions
    ``k N .. (k + 1) N - 1`` (``N`` = NAIVE_CHAIN) wait until motion ``(k + 2) N - 1`` is read (the last one's
    forward window is then complete) or the run ends.
    """

    SMALL = 10
    #: motions kept (a ring): a corner's windows reach at most 2 NAIVE_CHAIN - 1 motions back from the newest
    KEEP = 3 * NAIVE_CHAIN

    def __init__(self) -> None:
        self.active = False
        self.pending: list[tuple[Segment, Segment, PathMode, int]] = []  # (a, b, mode, index of a)
        self.count = 0  # motions seen (absolute index of the next one)
        self.first = 0  # the run's first motion
        self.segs: list[Segment | None] = [None] * self.KEEP  # motion k at k % KEEP
        self.boxes: dict[int, Box | None] = {}  # the boxes of motions asked (emptied when large)
        self.small: dict[int, Box | None] = {}  # the boxes of complete groups asked (emptied when large)
        self.blocks: dict[int, list[list[Any]] | None] = {}  # [lo, hi] of the block's motions, grown in place
        self._block: list[list[Any]] | None = None  # the newest block's entry
        self._end: Any = None  # the end point of the last straight motion added (the next one may start there)

    def restart(self) -> None:
        self.first = self.count
        self.boxes.clear()
        self.small.clear()
        self.blocks.clear()
        self._end = None

    def add(self, seg: Segment) -> None:
        """Motion ``count`` of the run: kept, and its block's box grown to hold it (a straight motion from where
        the last one ended: by its end point alone, its start is in the box already)."""
        k = self.count
        self.segs[k % self.KEEP] = seg
        self.count = k + 1
        if k % NAIVE_CHAIN == 0 or k == self.first:  # a new block (the run's first one may start inside one)
            self.blocks.pop(k // NAIVE_CHAIN - 4, None)
            box = self.box(k)
            self._block = self.blocks[k // NAIVE_CHAIN] = None if box is None else [list(box[0]), list(box[1])]
        elif (blk := self._block) is not None:
            if seg.kind is _LINE or seg.kind is _RAPID:
                lo, hi = blk
                if seg.start is not self._end:
                    _grow_point(blk, seg.start)
                for i, x in enumerate(seg.end):
                    if _lt(x, lo[i]):
                        lo[i] = x
                    elif _lt(hi[i], x):
                        hi[i] = x
            else:
                box = self.box(k)
                if box is None:
                    self._block = self.blocks[k // NAIVE_CHAIN] = None
                else:
                    _grow(blk, box)
        self._end = seg.end if seg.kind is _LINE or seg.kind is _RAPID else None

    def box(self, k: int) -> Box | None:
        """The box of motion ``k`` of the run (:func:`_piece_box`; None: it has none, or it is not kept)."""
        try:
            return self.boxes[k]
        except KeyError:
            if not (self.first <= k < self.count and k > self.count - self.KEEP):
                return None
            if len(self.boxes) > 4 * self.KEEP:
                self.boxes.clear()
            box = self.boxes[k] = _piece_box(self.segs[k % self.KEEP])  # type: ignore[arg-type]
            return box

    def take(self) -> list[tuple[Segment, Segment, PathMode, int]]:
        """The waiting corners of the first waiting block, removed from the queue."""
        pending = self.pending
        k = pending[0][3] // NAIVE_CHAIN
        m = 1
        while m < len(pending) and pending[m][3] // NAIVE_CHAIN == k:
            m += 1
        group = pending[:m]
        del pending[:m]
        return group

    def block_region(self, k: int) -> Box | None:
        """A box holding the region of every corner after a motion of block ``k`` (None: a motion without a box).

        Soundness.  The corner after motion ``i`` of the run (``k N <= i < (k + 1) N``, ``N`` = NAIVE_CHAIN) is
        ``C``, the end of motion ``i``; its region (:meth:`region`, specs/path-modes.md §2) is the box of
        ``x + y - C``, ``x`` in the box ``X`` of motions ``max(first, i - N + 1) .. i``, ``y`` in the box ``Y`` of
        motions ``i + 1 .. min(count - 1, i + N)``.  Since ``i - N + 1 > (k - 1) N - 1`` and ``i + N < (k + 2) N``,
        those motions lie in blocks ``k - 1 .. k`` (box ``U``) and ``k .. k + 1`` (box ``V``) of the run, as far as
        it is read; ``C`` lies in block ``k`` (box ``B``).  So, axis by axis, ``X.lo + Y.lo - C >= U.lo + V.lo -
        B.hi`` and ``X.hi + Y.hi - C <= U.hi + V.hi - B.lo``: that box holds every corner's region.  A block's box
        holds the boxes of its motions (:func:`_piece_box`), as the corner's own test uses, so each corner's test
        is on a box inside this one (at one of its tool lengths and offsets: :meth:`CornerCheck._naive_block`)."""
        first, last = self.first // NAIVE_CHAIN, (self.count - 1) // NAIVE_CHAIN
        blocks = self.blocks
        own = blocks.get(k)
        u = _union(blocks.get(k - 1), own) if k - 1 >= first else own  # type: ignore[arg-type]
        v = _union(own, blocks.get(k + 1)) if k + 1 <= last else own  # type: ignore[arg-type]
        if u is None or v is None or own is None:
            return None
        return (tuple(x + y - z for x, y, z in zip(u[0], v[0], own[1])),
                tuple(x + y - z for x, y, z in zip(u[1], v[1], own[0])))

    def _group(self, g: int) -> Box | None:
        """The box of motions ``g SMALL .. (g + 1) SMALL - 1`` (a complete group of the run)."""
        try:
            return self.small[g]
        except KeyError:
            n = self.SMALL
            out = self.box(g * n)
            for k in range(g * n + 1, (g + 1) * n):
                out = _union(out, self.box(k))
            if len(self.small) > self.KEEP:
                self.small.clear()
            self.small[g] = out
            return out

    def _span(self, lo: int, hi: int, exact: bool) -> Box | None:
        """A box holding motions ``lo .. hi - 1`` (all of the run): their union, or the union of their blocks."""
        if exact:
            n = self.SMALL
            g0, g1 = -(-lo // n), hi // n  # the whole groups inside
            if g0 >= g1:
                parts = [self.box(k) for k in range(lo, hi)]
            else:
                parts = ([self.box(k) for k in range(lo, g0 * n)] + [self._group(g) for g in range(g0, g1)]
                         + [self.box(k) for k in range(g1 * n, hi)])
        else:
            parts = [self.blocks.get(k) for k in range(lo // NAIVE_CHAIN, (hi - 1) // NAIVE_CHAIN + 1)]  # type: ignore[misc]
        out: Box | None = parts[0] if parts else None
        for p in parts[1:]:
            out = _union(out, p)
        return out

    def region(self, ia: int, c: tuple[Fraction, ...], exact: bool) -> Box | None:
        """The box of ``C + (x - C) + (y - C)``, x in the window before the corner after motion ``ia``, y in the one
        after (None when a motion has no box)."""
        before = self._span(max(self.first, ia - NAIVE_CHAIN + 1), ia + 1, exact)
        after = self._span(ia + 1, min(self.count, ia + NAIVE_CHAIN + 1), exact)
        if before is None or after is None:
            return None
        return (tuple(x + y - z for x, y, z in zip(before[0], after[0], c)),
                tuple(x + y - z for x, y, z in zip(before[1], after[1], c)))


def _union(a: Box | None, b: Box | None) -> Box | None:
    if a is None or b is None:
        return None
    return tuple(map(_lo, a[0], b[0])), tuple(map(_hi, a[1], b[1]))


def _grow_point(stretch: list[Any], p: Sequence[Any]) -> None:
    """Grow a Fanuc run's box (``stretch[0]``, ``stretch[1]``: lists) to hold the point ``p``."""
    lo, hi = stretch[0], stretch[1]
    for i, x in enumerate(p):
        if _lt(x, lo[i]):
            lo[i] = x
        elif _lt(hi[i], x):
            hi[i] = x


def _grow(stretch: list[Any], box: Box) -> None:
    """Grow a Fanuc run's box (``stretch[0]``, ``stretch[1]``: lists) to hold ``box``."""
    lo, hi = stretch[0], stretch[1]
    for i, (x, y) in enumerate(zip(box[0], box[1])):
        if _lt(x, lo[i]):
            lo[i] = x
        if _lt(hi[i], y):
            hi[i] = y


def _hull_box(seg: Segment) -> Box | None:
    """A box holding every machine position of ``seg`` for the hull of a Fanuc run (:func:`_piece_box`, and a
    polar move's (G12.1) machine X and C: the box of its pieces' enclosures, as ``nczones.prover.polar`` walks
    them; None when the path comes too near the centre of rotation)."""
    if seg.kind is not SegmentKind.POLAR:
        return _piece_box(seg)
    from ..geometry.polar import (
        CentreCrossing,
        angle_range,
        point_angle,
        polar_move_of,
        polar_of,
        radius_range,
    )

    try:
        move = polar_move_of(seg)
    except ValueError:
        return None
    e = polar_of(seg)
    assert e is not None  # polar_move_of(seg) succeeded
    ix, ic = seg.axes.index(e.linear_axis), seg.axes.index(e.rotary_axis)
    gx, gc = e.grid
    lo, hi = list(map(min, seg.start, seg.end)), list(map(max, seg.start, seg.end))
    xs, cs = [], []
    theta = move.start_angle()
    stack = [(fa, fb, 0) for fa, fb in reversed(move.first_pieces())]
    try:
        while stack:
            fa, fb, depth = stack.pop()
            bx, by = move.box(fa, fb)
            ang = angle_range(bx, by, theta.mid())
            if ang is not None:
                xs.append(move.x_off + radius_range(bx, by))
                cs.append(move.c_entry + ang)
                theta = point_angle(move.point(fb), theta.mid())
                continue
            if depth >= 20 or len(stack) > 1000:
                return None
            mid = (fa + fb) / 2
            stack.extend(((mid, fb, depth + 1), (fa, mid, depth + 1)))
    except CentreCrossing:
        return None
    lo[ix], hi[ix] = min(lo[ix], *(x.lo for x in xs)) - gx, max(hi[ix], *(x.hi for x in xs)) + gx
    lo[ic], hi[ic] = min(lo[ic], *(c.lo for c in cs)) - gc, max(hi[ic], *(c.hi for c in cs)) + gc
    return tuple(lo), tuple(hi)
