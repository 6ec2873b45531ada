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
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from fractions import Fraction
from typing import Any

from ...motion import MotionChunk, Segment, SegmentKind

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
        if not -_LIMIT < v < _LIMIT:
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
                    if not -_LIMIT < v < _LIMIT:
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


def column_runs(chunks: Iterable[Any], axes: tuple[str, ...], file: str) -> Iterator[Any]:
    """The chunks of an interpretation with its runs of plain straight moves as column chunks that keep their
    segments (module docstring); the motion and its order unchanged."""
    if len(axes) == 2:
        yield from chunks
        return
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
            yield chunk
            met += len(chunk) if isinstance(chunk, MotionChunk) else 1
            continue
        for seg in chunk.objects or ():
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
