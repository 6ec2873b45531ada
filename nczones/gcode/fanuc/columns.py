"""Runs of a Fanuc interpretation's straight moves handed to the proof as column chunks.

The Fanuc full interpreter (Macro B loops, G65/M98 calls) gives its motion as segments, in chunks of
``chunk_size``.  Proved one by one, every motion of a Fanuc cutting-mode run went through the corner check's
per-motion path (``CornerCheck._segment``: exact boxes compared as Fractions) and the proof's per-segment
batches were turned into columns again (``segment_columns``).  :func:`column_runs` turns each run of plain
straight moves into one column chunk that *keeps its segments*: the columns are the exact image of the
segments (every coordinate and tool length a decimal of at most :data:`SCALE` places, checked), and
``MotionChunk.segments()`` gives the segments themselves, spans, feeds and frames included.  So the corner
check takes the run by its column lanes (``_hull_columns`` / ``_columns``, the lanes the fast path's Fanuc
runs take), the proof screens it as one chunk, and whatever needs a segment (a flagged row, a violation, a
reason) gets the interpreter's own.

A segment stays in an object chunk (the path it took before) when it is not a line or rapid, carries a
payload or a dependency (parameter ranges, tool tips, polar, developed arcs), comes from another file than
the run's, or has a number that is not such a decimal; so do the first :data:`START` motions, and on a
two-axis machine (a lathe) every motion (the corner check's convex-hull refinement keeps the points of
object rows only).  Runs shorter than :data:`MIN_RUN` rows stay objects (the proof batches those anyway).
``tests/gcode/fanuc/test_column_runs.py`` holds the lanes to the exact path.

**Rows written by the lane** (issue 36, fourth step).  :func:`column_runs` gives the interpretation's Fanuc
interpreter a :class:`RowSink`; from motion :data:`START` on, its plain lane (``FanucInterpreter.lane``: a block
of axis words with at most G0/G1 and F, absolute metric G94 input, nothing pending) then writes each straight
move as a row of a :class:`Rows` run (one item of the interpreter's ``emitted`` list) instead of a segment: the
end coordinates scaled at :data:`SCALE` places (checked as above; a move that fails the check gets its segment
and ends the run) and the arguments its segment is made from.  A run of at least :data:`MIN_RUN` rows becomes a
column chunk as it is, whose ``objects`` build a segment only when one is read (a row the proof flags, a corner
at a chunk's edge, a violation) and give the same object on every read; a shorter run, or one before
:data:`START` motions have passed, becomes its segments and takes the path above.  The segments are those the
lane would have made (``Interpreter._lean_move``'s arguments); ``DIRECT`` off turns the rows off.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction
from math import isqrt

from ...motion import MotionChunk, Segment, SegmentKind
from ..segments import make_segment

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

#: Decimal places of the columns (the proof's line columns use the same, ``prover.screen.LINE_SCALE``).
SCALE = 9
_UNIT = 10**SCALE
#: Rows of one column chunk at most, and the least run worth columns.
MAX_ROWS = 8192
MIN_RUN = 64
#: Motions before the first column chunk: the proof screens its batches by columns only from
#: ``prover.core.SCREEN_MIN_SEGMENTS`` (512) motions on, and a column chunk ends the batch before it (a
#: short program's motion stays in objects, proved one by one as before)
START = 512
#: Coordinates at the scale stay below this (the corner check's column lanes take less than ``2**58``).
_LIMIT = 2**57
_LOW = -_LIMIT

_MULT: dict[int, int | None] = {}
_LINE, _RAPID = SegmentKind.LINE, SegmentKind.RAPID
_LINE_V, _RAPID_V = int(_LINE), int(_RAPID)  # the kind column's numbers


def _mult(den: int) -> int | None:
    """``10**SCALE // den`` when ``den`` divides it, else None (cached)."""
    got = _MULT.get(den, 0)
    if got == 0:
        q, r = divmod(_UNIT, den)
        got = q if r == 0 else None
        if len(_MULT) < 4096:
            _MULT[den] = got
    return got


def _scaled(p: tuple[Fraction, ...]) -> list[int] | None:
    out = []
    for x in p:
        m = _MULT.get(x._denominator, 0)  # type: ignore[attr-defined]  # read through the slots
        if m == 0:
            m = _mult(x._denominator)  # type: ignore[attr-defined]
        if m is None:
            return None
        v = x._numerator * m  # type: ignore[attr-defined]
        if not _LOW < v < _LIMIT:
            return None
        out.append(v)
    return out


class _Run:
    """The rows of the column chunk being built (coordinates in one flat list per column)."""

    __slots__ = ("segs", "kinds", "starts", "ends", "lines", "blocks", "tls", "prev_end", "prev_row",
                 "prev_tl", "tl_row")

    def __init__(self) -> None:
        self.segs: list[Segment] = []
        self.kinds: list[int] = []
        self.starts: list[int] = []
        self.ends: list[int] = []
        self.lines: list[int] = []
        self.blocks: list[int] = []
        self.tls: list[int] = []
        self.prev_end: Any = None
        self.prev_row: list[int] = []
        self.prev_tl: Any = None
        self.tl_row = 0

    def add(self, seg: Segment, file: str) -> bool:
        """Append ``seg`` as a row (True), or leave the run unchanged (False: it needs its object form)."""
        kind = seg.kind
        if (kind is not _LINE and kind is not _RAPID) or seg.extra or seg.deps_start or seg.deps_end \
                or seg.deps_tool:
            return False
        span = seg.span
        if span is None or span.file != file:
            return False
        tl = seg.tool_length
        if tl is not self.prev_tl:
            got = _scaled((tl,))
            if got is None:
                return False
            self.prev_tl, self.tl_row = tl, got[0]
        start, end = seg.start, seg.end
        prev = self.prev_end
        x: Any  # a Fraction, read through its slots
        s_row: list[int] | None
        e_row: list[int] | None
        if start is prev:  # the common case: the motion starts at the tuple the one before ended at
            s_row = self.prev_row
            e_row = s_row[:]
            mult = _MULT
            i = 0
            for x in end:
                if x is not prev[i]:  # an axis the motion moves (one it does not move keeps its number)
                    d = x._denominator
                    m = mult.get(d, 0)
                    if m == 0:
                        m = _mult(d)
                    if m is None:
                        return False
                    v = x._numerator * m
                    if not _LOW < v < _LIMIT:
                        return False
                    e_row[i] = v
                i += 1
        else:
            s_row = _scaled(start)
            if s_row is None:
                return False
            e_row = s_row if end is start else _scaled(end)
            if e_row is None:
                return False
        self.prev_end, self.prev_row = end, e_row
        self.segs.append(seg)
        self.kinds.append(_LINE_V if kind is _LINE else _RAPID_V)
        self.starts.extend(s_row)
        self.ends.extend(e_row)
        self.lines.append(span.line)
        self.blocks.append(seg.block)
        self.tls.append(self.tl_row)
        return True

    def chunk(self, axes: tuple[str, ...], file: str) -> MotionChunk:
        import numpy as np

        n = len(self.segs)
        return MotionChunk(
            axes, SCALE, kind=np.array(self.kinds, dtype=np.int8),
            start=np.array(self.starts, dtype=np.int64).reshape(n, len(axes)),
            end=np.array(self.ends, dtype=np.int64).reshape(n, len(axes)),
            line=np.array(self.lines, dtype=np.int64), block=np.array(self.blocks, dtype=np.int64),
            tool_length=np.array(self.tls, dtype=np.int64), file=file, objects=tuple(self.segs))


class _Built(Sequence):
    """The segments of a :class:`Rows` run, each built when first read (then the same object on every read)."""

    __slots__ = ("rows", "segs")

    def __init__(self, rows: Rows) -> None:
        self.rows = rows
        self.segs: list[Segment | None] = [None] * len(rows.args)

    def __len__(self) -> int:
        return len(self.segs)

    def __getitem__(self, i: Any) -> Any:
        segs = self.segs
        if isinstance(i, slice):
            a, b, step = i.indices(len(segs))
            if step != 1 or any(segs[k] is None for k in range(a, b)):
                for k in range(a, b, step) if step == 1 else range(len(segs)):
                    if segs[k] is None:
                        segs[k] = self.rows.segment(k)
            return tuple(segs[i])
        seg = segs[i]
        if seg is None:
            k = i + len(segs) if i < 0 else i
            seg = segs[k] = self.rows.segment(k)
        return seg

    def __iter__(self) -> Iterator[Segment]:
        segs = self.segs
        if any(s is None for s in segs):
            built = self.rows.segments()
            for k, s in enumerate(segs):
                if s is None:
                    segs[k] = built[k]
        return iter(segs)  # type: ignore[arg-type]  # every item built


class Rows:
    """A run of straight moves the Fanuc interpreter's plain lane wrote as column rows, without a Segment each
    (``FanucInterpreter.lane`` with a :class:`RowSink`): the columns at :data:`SCALE` places, and per row what
    the segment is built from when a consumer reads it (:meth:`segments`: the interpreter's own arguments,
    so the segment is the one the lane would have made).  Every row starts where the row before ended."""

    __slots__ = ("file", "axes", "first", "first_row", "prev_end", "prev_row", "ends", "args", "tl", "tl_row", "tls",
                 "full", "max_rows")

    def __init__(self, start: tuple, start_row: list[int], axes: tuple[str, ...], file: str, max_rows: int) -> None:
        self.file, self.axes, self.max_rows = file, axes, max_rows
        self.first, self.first_row = start, start_row
        self.prev_end, self.prev_row = start, start_row
        self.ends: list[int] = []
        self.args: list[tuple] = []
        self.tl: Any = None
        self.tl_row = 0
        self.tls: dict[int, int] = {}  # the scaled tool lengths of the rows, by the id of their Fraction
        self.full = False

    def add(self, kind: SegmentKind, end: tuple, axis_at: tuple, index: int, span: Any, tlo: Any, fmm: Any,
            register: Any, frame: Any) -> bool:
        """Append the move from ``prev_end`` to ``end`` (its moved axes: ``axis_at``'s axis indices) as a row
        (True), or leave the run unchanged (False: a number that is not a decimal of at most :data:`SCALE`
        places, too large, or another file: the move then needs its segment)."""
        if span.file != self.file:
            return False
        if tlo is not self.tl:
            got = _scaled((tlo,))
            if got is None:
                return False
            self.tl, self.tl_row = tlo, got[0]
            self.tls[id(tlo)] = got[0]  # the Fraction stays alive in the row's arguments
        e_row = self.prev_row[:]
        mult = _MULT
        for _k, i in axis_at:
            x: Any = end[i]  # a Fraction, read through its slots
            d = x._denominator
            m = mult.get(d, 0)
            if m == 0:
                m = _mult(d)
            if m is None:
                return False
            v = x._numerator * m
            if not _LOW < v < _LIMIT:
                return False
            e_row[i] = v
        self.prev_end, self.prev_row = end, e_row
        self.ends.extend(e_row)
        args = self.args
        args.append((kind, end, index, span, tlo, fmm, register, frame))
        if len(args) >= self.max_rows:
            self.full = True
        return True

    def __len__(self) -> int:
        return len(self.args)

    def segment(self, k: int) -> Segment:
        """The segment of row ``k`` (as :meth:`segments` builds it)."""
        kind, end, index, span, tlo, fmm, register, frame = self.args[k]
        start = self.args[k - 1][1] if k else self.first
        seg: Segment = make_segment(kind, start, end, self.axes, index, span, tlo, fmm, None, False, None, None, 0,
                                    None, "", register, (), (), (), frame)
        return seg

    def segments(self) -> list[Segment]:
        """The segments of the rows, as the lane builds them (``Interpreter._lean_move``)."""
        out = []
        start = self.first
        axes = self.axes
        for kind, end, index, span, tlo, fmm, register, frame in self.args:
            out.append(make_segment(kind, start, end, axes, index, span, tlo, fmm, None, False, None, None, 0, None,
                                    "", register, (), (), (), frame))
            start = end
        return out

    def bounds(self) -> tuple[list[int], list[int], set[int], int, int]:
        """The run's box as :meth:`BoxRows.bounds` gives it (the start and every row's end)."""
        w = len(self.axes)
        ends, first = self.ends, self.first_row
        lo = [min(min(ends[i::w]), first[i]) for i in range(w)]
        hi = [max(max(ends[i::w]), first[i]) for i in range(w)]
        return lo, hi, set(self.tls.values()), len(self.args), SCALE

    def chunk(self) -> MotionChunk:
        """The rows as a column chunk whose ``objects`` are their segments, built when read."""
        import numpy as np

        n, width = len(self.args), len(self.axes)
        end = np.array(self.ends, dtype=np.int64).reshape(n, width)
        start = np.empty_like(end)
        start[0] = self.first_row
        start[1:] = end[:-1]
        objects: Any = _Built(self)
        args, tls = self.args, self.tls
        return MotionChunk(
            self.axes, SCALE, kind=np.array([a[0] for a in args], dtype=np.int8), start=start, end=end,
            line=np.array([a[3].line for a in args], dtype=np.int64),
            block=np.array([a[2] for a in args], dtype=np.int64),
            tool_length=np.array([tls[id(a[4])] for a in args], dtype=np.int64), file=self.file, objects=objects)


class RowSink:
    """What :func:`column_runs` gives the Fanuc interpreter (``FanucInterpreter.row_sink``) for its plain lane
    to write rows instead of segments: from motion ``start`` on, runs of at most ``max_rows`` rows of ``file``."""

    __slots__ = ("axes", "file", "start", "max_rows")
    #: the class of the runs :meth:`open` makes (the lane continues a run of this class)
    rows: type = Rows
    #: whether the lane writes arcs into the runs too (``FanucInterpreter._arc_lane``: :meth:`BoxRows.add_arc`)
    arcs = False

    def __init__(self, axes: tuple[str, ...], file: str, start: int, max_rows: int) -> None:
        self.axes, self.file, self.start, self.max_rows = axes, file, start, max_rows

    def open(self, start: Any) -> Rows | None:
        """A new run of rows from the point ``start`` (None when it is not a decimal at the scale)."""
        start = start if type(start) is tuple else tuple(start)
        row = _scaled(start)
        return None if row is None else Rows(start, row, self.axes, self.file, self.max_rows)


class BoxRows:
    """A run of straight moves (and arcs: :meth:`add_arc`) the plain lane hands over as its box only (``BoxSink``,
    the numpy-free route of :mod:`nczones.prover.fanucboxes`): per axis the least and greatest coordinate of the
    run's start and every row's end (an arc's row: its sound box), at :data:`SCALE` places (checked as
    :class:`Rows` checks them), the scaled tool lengths the rows carried and their count.  No segment can be built from it: a consumer that needs segments uses :class:`Rows`.
    A move that fails the check (False) may have widened the box by its own end's coordinates, positions the
    program commands (its segment follows, with the same end)."""

    __slots__ = ("file", "prev_end", "lo", "hi", "tl", "tls", "count", "full", "max_rows")

    def __init__(self, start: tuple, start_row: list[int], file: str, max_rows: int) -> None:
        self.file, self.max_rows = file, max_rows
        self.prev_end = start
        self.lo, self.hi = start_row[:], start_row[:]
        self.tl: Any = None
        self.tls: set[int] = set()
        self.count = 0
        self.full = False

    def add(self, kind: SegmentKind, end: tuple, axis_at: tuple, index: int, span: Any, tlo: Any, fmm: Any,
            register: Any, frame: Any) -> bool:
        """The move from ``prev_end`` to ``end`` into the box (True), or False as :meth:`Rows.add` says it."""
        if span.file != self.file:
            return False
        if tlo is not self.tl:
            got = _scaled((tlo,))
            if got is None:
                return False
            self.tl = tlo
            self.tls.add(got[0])
        lo, hi = self.lo, self.hi
        mult = _MULT
        for _k, i in axis_at:
            x: Any = end[i]  # a Fraction, read through its slots
            d = x._denominator
            m = mult.get(d, 0)
            if m == 0:
                m = _mult(d)
            if m is None:
                return False
            v = x._numerator * m
            if not _LOW < v < _LIMIT:
                return False
            if v < lo[i]:
                lo[i] = v
            elif v > hi[i]:
                hi[i] = v
        self.prev_end = end
        self.count += 1
        if self.count >= self.max_rows:
            self.full = True
        return True

    def add_arc(self, cw: bool, end: tuple, axis_at: tuple, ia: int, ib: int, r: Any, ij: Any, span: Any,
                tlo: Any, tol: Any = None) -> bool:
        """The arc from ``prev_end`` to ``end`` in the plane of axes ``ia``, ``ib`` (clockwise ``cw``), given by
        its signed radius ``r`` or (``r`` None) its centre's offsets from the start ``ij`` (``tol``: the radius
        tolerance of :func:`centre_arc_box`, None for none), into the box (True):
        the box of its ends on every axis and, on the plane axes, its sound box (:func:`r_arc_box`,
        :func:`centre_arc_box`).  False, the run unchanged, when a number is not a decimal at the scale or too
        large, or the arc is not one those boxes take (then the block takes the interpreter's general path)."""
        if span.file != self.file:
            return False
        start = self.prev_end
        got = _scaled((start[ia], start[ib], end[ia], end[ib], r) if r is not None else
                      (start[ia], start[ib], end[ia], end[ib], ij[0], ij[1]) + ((tol,) if tol is not None else ()))
        helix = [i for _k, i in axis_at if i != ia and i != ib]  # the other axes the arc moves: their ends
        ends = _scaled(tuple(end[i] for i in helix)) if helix else []
        if got is None or ends is None:
            return False
        sa, sb = got[0], got[1]
        if r is not None:
            box = r_arc_box(sa, sb, got[2], got[3], got[4], cw)
        else:
            box = centre_arc_box(sa, sb, got[2], got[3], sa + got[4], sb + got[5], cw,
                                 got[6] if tol is not None else None)
        if box is None:
            return False
        if tlo is not self.tl:
            t = _scaled((tlo,))
            if t is None:
                return False
            self.tl = tlo
            self.tls.add(t[0])
        lo, hi = self.lo, self.hi
        for i, v in zip(helix, ends):
            if v < lo[i]:
                lo[i] = v
            elif v > hi[i]:
                hi[i] = v
        widen_plane(lo, hi, ia, ib, box)  # the ends' box and the arc's extremes
        self.prev_end = end
        self.count += 1
        if self.count >= self.max_rows:
            self.full = True
        return True

    def __len__(self) -> int:
        return self.count

    def bounds(self) -> tuple[list[int], list[int], set[int], int, int]:
        """(least and greatest coordinate per axis, the tool lengths, all at ``10**-scale``; the rows; the scale)."""
        return self.lo, self.hi, self.tls, self.count, SCALE


#: An R arc whose half chord ``h`` has ``h * (1 - 1/_TINY_DEN)**-2 >= |R|`` is made a half circle about the chord's
#: midpoint by the interpreter (``Interpreter.arc``, its ``_TINY``); :func:`r_arc_box` leaves those to it.
_TINY_DEN = 10**12
_TINY_SQ = _TINY_DEN * _TINY_DEN
_TINY_BOUND = 4 * (_TINY_DEN - 1) ** 2


def widen_plane(lo: list[int], hi: list[int], ia: int, ib: int, box: tuple[int, int, int, int] | None) -> bool:
    """A box (``lo``, ``hi``: scaled integers by axis) widened in the plane's axes ``ia``, ``ib`` by an arc's
    ``box`` (:func:`r_arc_box`'s, :func:`centre_arc_box`'s), False when there is none (the interpreter decides
    the arc).

    >>> lo, hi = [0, 0, 0], [5, 5, 5]
    >>> widen_plane(lo, hi, 0, 1, (-2, 3, 1, 7)), lo, hi, widen_plane(lo, hi, 0, 1, None)
    (True, [-2, 0, 0], [5, 7, 5], False)
    """
    if box is None:
        return False
    la, ha, lb, hb = box
    if la < lo[ia]:
        lo[ia] = la
    if ha > hi[ia]:
        hi[ia] = ha
    if lb < lo[ib]:
        lo[ib] = lb
    if hb > hi[ib]:
        hi[ib] = hb
    return True


def r_arc_box(sa: int, sb: int, ea: int, eb: int, r: int, cw: bool) -> tuple[int, int, int, int] | None:
    """A box ``(lo_a, hi_a, lo_b, hi_b)`` holding the R-format arc from ``(sa, sb)`` to ``(ea, eb)`` with signed
    radius ``r`` (all integers at one scale), clockwise ``cw``, as ``nczones.prover.geometry.arc_geom`` models
    it; None when the interpreter would not give such an arc (equal ends, ``r`` 0, a chord of ``2|r|`` or more
    within its tolerance: the general path decides those).

    The model: the centre is ``c = M + sign * k * n`` (``M`` the chord's midpoint, ``n = (-dy, dx)`` the chord
    turned left, ``k = sqrt(r**2 / l**2 - 1/4)``, ``sign`` -1 when clockwise differs from ``r < 0``), and the arc
    runs about it from the start to the end in its direction: the minor arc (at most half the circle) when
    ``r > 0``, the major one when ``r < 0``.  The chord's line cuts the circle into these two arcs: the minor
    one lies on the side away from the centre, the major one on the centre's side.  So the circle's extreme
    point ``c + |r| v`` in an axis direction ``v`` is on the arc exactly when ``(c + |r| v - M) . b >= 0`` for
    ``b = sigma * n`` the normal towards the arc's side (``sigma = -sign`` minor, ``sign`` major).  With
    ``Q = l**2 (4 r**2 - l**2)`` (an integer; ``k l**2 = sqrt(Q) / 2``) and ``A = 2 sigma |r| (v . n)`` this is
    ``A >= sqrt(Q)`` for the minor arc and ``A >= -sqrt(Q)`` for the major one: decided exactly on integers
    (``A >= 0 and A*A >= Q``, ``A >= 0 or A*A <= Q``), no square root.  The box is the ends' and those extremes,
    the centre enclosed by integer square roots rounded outward (``2 c_a = sa + ea - sign dy sqrt(Q) / l**2``):
    every bound is outward, by at most one unit of the scale.

    >>> r_arc_box(-10, 0, 10, 0, 10, True)  # a half circle would be c=(0,0): left to the interpreter
    >>> r_arc_box(0, 0, 20, 0, 20, True)  # G2 from (0,0) to (20,0), R20: bulges up (+b) to 20 - sqrt(300)
    (0, 20, 0, 3)
    >>> r_arc_box(0, 0, 20, 0, -20, True)  # R-20: the major arc, round the centre (10, sqrt(300)) above
    (-10, 30, 0, 38)
    """
    dx, dy = ea - sa, eb - sb
    l2 = dx * dx + dy * dy
    if r > 0:
        rr, minor = r, True
    elif r < 0:
        rr, minor = -r, False
    else:
        return None
    r2 = rr * rr
    # (a chord of at most sqrt(3) |r| is far from the tolerance: the products of the test are not needed)
    if l2 == 0 or (l2 > 3 * r2 and l2 * _TINY_SQ >= r2 * _TINY_BOUND):
        return None
    f = 4 * r2
    q = l2 * (f - l2)
    lo_a, hi_a = (sa, ea) if sa <= ea else (ea, sa)
    lo_b, hi_b = (sb, eb) if sb <= eb else (eb, sb)
    aa = f * dy * dy  # A * A for v = +a or -a (A = 2 sigma |r| (v . n), v . n = -dy or dy), below for +b, -b
    bb = f * dx * dx
    if minor and aa < q and bb < q:  # no extreme on the minor arc: the ends' box
        return lo_a, hi_a, lo_b, hi_b
    s_lo = s_hi = -1  # isqrt(q) rounded down and up, taken when an extreme is on the arc
    sign = -1 if cw != (r < 0) else 1
    sigma = -sign if minor else sign
    two = 2 * sigma * rr
    # twice the centre, enclosed where an extreme is on the arc: 2 c = (s + e) + sign * n * sqrt(Q) / l2, with
    # n = (-dy, dx); and v . n = -dy, dy, dx, -dx for v = +a, -a, +b, -b
    a = -two * dy
    if minor:  # (a >= 0 and a * a >= q), (a <= 0 and a * a >= q)
        up = down = aa >= q
        if up:
            up, down = a >= 0, a <= 0
    else:  # (a >= 0 or a * a <= q), (a <= 0 or a * a <= q)
        up = down = aa <= q
        if not up:
            up, down = a >= 0, a <= 0
    if up or down:
        s_lo = isqrt(q)
        s_hi = s_lo if s_lo * s_lo == q else s_lo + 1
        k = -sign * dy
        if up:  # c_a + |r|, c_a rounded up: ceil((sa + ea + k sqrt(Q) / l2) / 2)
            hi_a = max(hi_a, -((-(sa + ea) - (-((-k * (s_hi if k >= 0 else s_lo)) // l2))) // 2) + rr)
        if down:  # c_a - |r|, c_a rounded down
            lo_a = min(lo_a, (sa + ea + (k * (s_lo if k >= 0 else s_hi)) // l2) // 2 - rr)
    a = two * dx
    if minor:
        up = down = bb >= q
        if up:
            up, down = a >= 0, a <= 0
    else:
        up = down = bb <= q
        if not up:
            up, down = a >= 0, a <= 0
    if up or down:
        if s_lo < 0:
            s_lo = isqrt(q)
            s_hi = s_lo if s_lo * s_lo == q else s_lo + 1
        k = sign * dx
        if up:
            hi_b = max(hi_b, -((-(sb + eb) - (-((-k * (s_hi if k >= 0 else s_lo)) // l2))) // 2) + rr)
        if down:
            lo_b = min(lo_b, (sb + eb + (k * (s_lo if k >= 0 else s_hi)) // l2) // 2 - rr)
    return lo_a, hi_a, lo_b, hi_b


def _axis_sweeps(u: tuple[int, int], w: tuple[int, int], ccw: bool) -> tuple[bool, bool, bool, bool]:
    """Whether the directions +a, -a, +b, -b lie in the sweep from ``u`` to ``w`` (not a whole turn):
    ``nczones.prover.geometry.in_sweep`` on integer vectors, its cross and dot products with the axis directions
    written out (``_half(u, v)``: 0 when the counter-clockwise angle from u to v is in [0, pi))."""
    if not ccw:
        u, w = w, u
    ux, uy = u
    wx, wy = w
    c = ux * wy - uy * wx
    hw = 0 if c > 0 or (c == 0 and ux * wx + uy * wy > 0) else 1
    h = 0 if uy < 0 or (uy == 0 and ux > 0) else 1  # v = +a: cross(u, v) = -uy, dot = ux; cross(v, w) = wy
    pa = h < hw if h != hw else wy >= 0
    h = 0 if uy > 0 or (uy == 0 and ux < 0) else 1  # v = -a: uy, -ux; -wy
    na = h < hw if h != hw else wy <= 0
    h = 0 if ux > 0 or (ux == 0 and uy > 0) else 1  # v = +b: ux, uy; -wx
    pb = h < hw if h != hw else wx <= 0
    h = 0 if ux < 0 or (ux == 0 and uy < 0) else 1  # v = -b: -ux, -uy; wx
    nb = h < hw if h != hw else wx >= 0
    return pa, na, pb, nb


def centre_arc_box(sa: int, sb: int, ea: int, eb: int, ca: int, cb: int, cw: bool, tol: int | None = None
                   ) -> tuple[int, int, int, int] | None:
    """A box ``(lo_a, hi_a, lo_b, hi_b)`` holding the arc from ``(sa, sb)`` to ``(ea, eb)`` about the centre
    ``(ca, cb)`` (integers at one scale), clockwise ``cw``: a whole turn when the ends are equal.  The box is the
    ends' and the circle's extremes ``c +- sqrt(r**2)`` (the root rounded up) in the axis directions the sweep
    holds, decided exactly (``nczones.prover.geometry.in_sweep``, ``ArcGeom.plane_bbox``).  Ends at different
    distances from the centre (the spiral the control moves) are taken when ``tol`` (the interpreter's radius
    tolerance at the scale) accepts them as ``Interpreter.arc`` does (``sqrt_diff_exceeds``): then the larger
    radius, and every side widened by twice the difference of the roots (rounded outward), as ``plane_bbox``.
    None for a radius 0, a spiral without ``tol`` or past it (GC301), or one whose end lies on its start's ray (a
    whole spiral turn: the per-motion proof's reason): the general path decides those.

    >>> centre_arc_box(10, 0, 0, 10, 0, 0, False)  # G3 a quarter from +a to +b
    (0, 10, 0, 10)
    >>> centre_arc_box(10, 0, 0, 10, 0, 0, True)  # G2: three quarters
    (-10, 10, -10, 10)
    """
    u = (sa - ca, sb - cb)
    w = (ea - ca, eb - cb)
    r0 = u[0] * u[0] + u[1] * u[1]
    r1 = w[0] * w[0] + w[1] * w[1]
    if r0 == 0 or r1 == 0:
        return None
    if r0 != r1:
        if tol is None:
            return None
        lhs = r0 + r1 - tol * tol  # sqrt_diff_exceeds: |sqrt r0 - sqrt r1| > tol
        if (lhs > 0 and lhs * lhs > 4 * r0 * r1) or (u[0] * w[1] - u[1] * w[0] == 0 and u[0] * w[0] + u[1] * w[1] > 0):
            return None
    big = r0 if r0 >= r1 else r1
    s = isqrt(big)
    rr = s if s * s == big else s + 1
    lo_a, hi_a = (sa, ea) if sa <= ea else (ea, sa)
    lo_b, hi_b = (sb, eb) if sb <= eb else (eb, sb)
    pa, na, pb, nb = (True, True, True, True) if u == w else _axis_sweeps(u, w, not cw)  # equal ends: a whole turn
    if pa:
        hi_a = max(hi_a, ca + rr)
    if na:
        lo_a = min(lo_a, ca - rr)
    if pb:
        hi_b = max(hi_b, cb + rr)
    if nb:
        lo_b = min(lo_b, cb - rr)
    if r0 != r1:  # a spiral: within (r_hi - r_lo) of the circular arc of the start radius (ArcGeom.plane_bbox)
        g = 2 * (rr - isqrt(r0 if r0 < r1 else r1))
        return lo_a - g, hi_a + g, lo_b - g, hi_b + g
    return lo_a, hi_a, lo_b, hi_b


class BoxSink(RowSink):
    """A :class:`RowSink` whose runs are :class:`BoxRows`: the lane writes a run's box, not its rows."""

    __slots__ = ()
    rows = BoxRows
    arcs = True

    def open(self, start: Any) -> Any:
        """A new run from the point ``start`` (None when it is not a decimal at the scale)."""
        start = start if type(start) is tuple else tuple(start)
        row = _scaled(start)
        return None if row is None else BoxRows(start, row, self.file, self.max_rows)


def _expanded(chunk: MotionChunk) -> MotionChunk:
    """``chunk`` with the segments of its :class:`Rows` items in their place."""
    objects: Sequence[Any] = chunk.objects or ()  # segments and runs of rows
    if not any(type(x) is Rows for x in objects):
        return chunk
    segs: list[Segment] = []
    for x in objects:
        if type(x) is Rows:
            segs.extend(x.segments())
        else:
            segs.append(x)
    return MotionChunk(chunk.axes, None, objects=tuple(segs), file=chunk.file)


#: Whether :func:`column_runs` asks the interpreter to write its plain runs as rows (tests turn it off to
#: compare with the segments' path).
DIRECT = True


def _ask_rows(chunks: Any, axes: tuple[str, ...], file: str) -> None:
    """Give the interpretation's Fanuc interpreter a :class:`RowSink` when its lane can write rows."""
    interp: Any = getattr(chunks, "interpreter", None)
    if DIRECT and getattr(interp, "fused_lane", False) and interp.axes == axes and interp.file == file:
        interp.row_sink = RowSink(axes, file, START, MAX_ROWS)


def column_runs(chunks: Iterable[Any], axes: tuple[str, ...], file: str) -> Iterator[Any]:
    """The chunks of an interpretation with its runs of plain straight moves as column chunks that keep their
    segments (module docstring); the motion and its order unchanged.  An interpretation's Fanuc interpreter
    writes its plain runs as :class:`Rows` (no segment per motion): each becomes a column chunk as it is."""
    if len(axes) == 2:
        yield from chunks
        return
    _ask_rows(chunks, axes, file)
    run = _Run()
    loose: list[Segment] = []  # the segments since the last run, in order (the run is empty while there are any)

    def flush() -> Iterator[Any]:
        nonlocal run, loose
        if loose:
            yield MotionChunk(axes, None, objects=tuple(loose), file=file)
            loose = []
        if len(run.segs) >= MIN_RUN:
            yield run.chunk(axes, file)
        elif run.segs:
            yield MotionChunk(axes, None, objects=tuple(run.segs), file=file)
        if run.segs:
            run = _Run()

    met = 0  # motions so far
    for chunk in chunks:
        if not isinstance(chunk, MotionChunk) or chunk.scale is not None or chunk.axes != axes or met < START:
            yield from flush()
            if isinstance(chunk, MotionChunk) and chunk.scale is None:
                chunk = _expanded(chunk)
            yield chunk
            met += len(chunk) if isinstance(chunk, MotionChunk) else 1
            continue
        items: Sequence[Any] = chunk.objects or ()  # segments and runs of rows
        for item in items:
            if type(item) is Rows:
                if len(item) >= MIN_RUN:
                    yield from flush()
                    run.prev_end = None
                    yield item.chunk()
                    continue
                segs: Iterable[Segment] = item.segments()
            else:
                segs = (item,)
            for seg in segs:
                if run.add(seg, file):
                    if loose:  # the run starts with this segment: what came before it goes first
                        yield MotionChunk(axes, None, objects=tuple(loose), file=file)
                        loose = []
                    if len(run.segs) >= MAX_ROWS:
                        yield from flush()
                    continue
                if run.segs:
                    yield from flush()
                run.prev_end = None
                loose.append(seg)
    yield from flush()
