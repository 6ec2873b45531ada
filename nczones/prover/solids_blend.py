"""The tool solids on the path the machine really moves: corner blending (issue 39 × issue 35).

:mod:`nczones.prover.solids` proves the tool assembly along the programmed path.  Where the control may round
a corner (LinuxCNC G64, a Fanuc control's cutting mode, ``specs/path-modes.md``) the controlled point leaves
that path; this module proves, beside it, the solids over the enclosure of the moved path that
:mod:`nczones.prover.blend` proves for the point:

* **With a tolerance** (LinuxCNC ``G64 P p [Q q]``, a Fanuc control with ``[machine] path_tolerance t``):
  every real position lies within ``d`` = :meth:`PathMode.bound` (``p + q``, Q defaulting to P; ``t``) of
  the two programmed motions of its corner.  The tool is rigid and does not rotate, so a controlled point
  displaced by a vector ``v`` with ``|v| <= d`` displaces every point of every part by the same ``v``: a
  part at ``p + v`` lies inside the part at ``p`` grown by the ball of radius ``d``, which lies inside the
  vertical cylinder of radius ``r + d`` over ``lo - d .. hi + d`` (the Minkowski sum of a cylinder and a
  ball, enclosed).  So the motions next to a corner with bound ``d`` are proved with every part grown so
  (:func:`grown_solids`) by a second :class:`~nczones.prover.solids.SolidsChecker` — the exact tiers, the
  numpy screen and the column chunks of the fast path all apply.  Growing the parts rather than the
  fixtures keeps every fixture kind exact: a rectangle grown by a disk of radius ``r + d`` is the rectangle
  grown by ``r`` then by ``d``.  A motion's ``d`` is the larger bound of its two corners (the corner at its
  start is rounded in the previous motion's mode, the one at its end in its own).
* **Without a tolerance** (LinuxCNC ``G64``): a blend uses at most half of each motion, so every point of it
  is ``C + a (M1 - C) + b (M2 - C)`` (``a, b`` in ``[0, 1]``, ``M1``, ``M2`` the midpoints of the two lines;
  ``specs/path-modes.md`` §2).  The tool swept over that parallelogram is proved through its boxes
  (:meth:`SolidsChecker.box_meets`: the controlled point anywhere in a box), the parallelogram split in
  quarters up to :data:`DEPTH` times; an arc's half lies in its box, so an arc corner's region lies in the
  Minkowski sum of the two motions' boxes less ``C``.  On column chunks the corners are screened with numpy
  first: a line corner's region lies in the box of its three points (each coordinate of ``C + a u + b w``
  with ``u``, ``w`` half the legs lies between the least and the largest of ``C``, ``C + 2u``, ``C + 2w``).
* ``G64 Q`` without P (naive-CAM windows) and a Fanuc control in cutting mode without ``path_tolerance``
  (the hull of a run) are not modelled for the solids: ``unknown`` (VF235), naming the first corner.

Verdicts keep the point's rules: a part that meets a fixture on the programmed path is a violation of
:mod:`nczones.prover.solids` (``unsafe``); a blended corner that may meet one while the programmed path does
not is ``unknown`` (VF233 with a tolerance, VF234 without), naming the part, the fixture and the lines;
never ``safe``.
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import replace
from fractions import Fraction
from typing import Any

import numpy as np

from ..exact import format_decimal
from ..lathe_solids import LathePart, LatheSolids
from ..machine import Machine, RapidMode
from ..motion import DROPPED_BELOW, MotionChunk, PathMode, Segment, SegmentKind
from ..solids import FixturePrism, Part, Solids
from .geometry import arc_geom
from .result import Reason
from .solids import SolidsChecker
from .solids_screen import needs_exact_columns

__all__ = ["SolidsCornerCheck", "grown_solids", "grown_lathe_solids", "TOLERANCE_CODE", "REGION_CODE", "MODE_CODE"]

#: a part may meet a fixture within a G64 P / path_tolerance bound of the programmed path
TOLERANCE_CODE = "VF233"
#: a part may meet a fixture in the region of a corner rounded without tolerance (G64)
REGION_CODE = "VF234"
#: a path mode whose moved path the solids proof does not model (G64 Q without P, Fanuc without path_tolerance)
MODE_CODE = "VF235"
#: no-tolerance corner regions are split in quarters at most this many times
DEPTH = 4
#: at most this many reasons (the rest are counted)
MAX_REASONS = 20

F0 = Fraction(0)
F1 = Fraction(1)
_HALF = Fraction(1, 2)
_LINEAR = (SegmentKind.LINE, SegmentKind.RAPID)


def grown_solids(solids: Solids, d: Fraction) -> Solids:
    """``solids`` with every tool and spindle part grown by ``d``: radius ``r + d`` over ``lo - d .. hi + d``
    (it holds the part displaced by any vector of length at most ``d``).

    >>> s = Solids({1: (Part("holder", Fraction(30), Fraction(40), Fraction(100)),)}, (), ())
    >>> grown_solids(s, Fraction(1, 100)).tools[1][0]
    Part(name='holder', radius=Fraction(3001, 100), z0=Fraction(3999, 100), z1=Fraction(10001, 100), spindle=False)
    """
    def grow(p: Part) -> Part:
        return replace(p, radius=p.radius + d, z0=p.z0 - d, z1=p.z1 + d)

    return replace(solids, tools={n: tuple(map(grow, ps)) for n, ps in solids.tools.items()},
                   spindle=tuple(map(grow, solids.spindle)))


def grown_lathe_solids(solids: LatheSolids, d: Fraction) -> LatheSolids:
    """A lathe's turret tools with every part's rectangle grown by ``d`` on each side, in X and in Z (it holds
    the part displaced by any vector of length at most ``d`` in the section).

    >>> s = LatheSolids({1: (LathePart("bar", Fraction(-8), Fraction(8), Fraction(6), Fraction(180)),)}, ())
    >>> grown_lathe_solids(s, Fraction(1, 2)).tools[1][0].rect()
    (Fraction(-17, 2), Fraction(17, 2), Fraction(11, 2), Fraction(361, 2))
    """
    def grow(p: LathePart) -> LathePart:
        return replace(p, x0=p.x0 - d, x1=p.x1 + d, z0=p.z0 - d, z1=p.z1 + d)

    return replace(solids, tools={n: tuple(map(grow, ps)) for n, ps in solids.tools.items()})


def _where(seg: Segment) -> str:
    return f"line {seg.line}" if seg.line is not None else f"block {seg.block}"


def _corner_name(a: Segment, b: Segment) -> str:
    return f"the blend between {_where(a)} and {_where(b)}"


class SolidsCornerCheck:
    """Follows a run's motion (wrap the stream with :meth:`watch`) and proves the tool solids over the path
    the control may move at its blended corners; :meth:`finish` gives the reasons.

    ``modes``: the interpreter's table of path modes, ``(first block index, PathMode)`` in order, as
    :class:`nczones.prover.blend.CornerCheck` reads it."""

    def __init__(self, machine: Machine, solids: Solids | LatheSolids, ranges: Sequence[Any],
                 modes: list[tuple[int, PathMode]]) -> None:
        self.machine = machine
        self.solids = solids
        self.lathe = isinstance(solids, LatheSolids)  # a lathe's turret tools (nczones.lathe_solids), not a zone kind
        self.ranges = tuple(ranges)
        self.modes = modes
        self.dogleg = machine.rapid_mode is RapidMode.DOGLEG
        axes = machine.axis_names
        self.xyz = (axes.index("X"), axes.index("Y") if "Y" in axes else 0, axes.index("Z"))
        # box tests of corner regions (a mill's; a lathe's corner regions are not proved: VF235)
        self.nominal = None if isinstance(solids, LatheSolids) else SolidsChecker(machine, solids, self.ranges,
                                                                                  screen=False)
        self.grown: dict[Fraction, Any] = {}  # SolidsChecker, or a lathe's LatheSolidsChecker
        self.codes: dict[Fraction, set[str]] = {}  # the modes each bound came from, for the reasons
        self.prev: Segment | None = None
        self.prev_stop = True
        self.dropped: Segment | None = None  # the motion before moves LinuxCNC may drop (_dropped)
        self.found: list[tuple[Reason, int, int]] = []  # (reason, first block, last block)
        self.more: dict[str, int] = {}  # corners past the reasons kept, per code
        self.corners = 0  # corners without tolerance proved (for tests and measurements)
        # the column screen compares fixtures as the machine file gives them (SolidsChecker's own condition)
        self.static = not self.lathe and not self.ranges and not any(
            getattr(fx, "frame", "") or isinstance(fx, FixturePrism) for fx in solids.fixtures)

    # ------------------------------------------------------------------ the stream
    def watch(self, items: Iterable[Any]) -> Iterator[Any]:
        """The items unchanged; each one's corners proved as it passes."""
        for item in items:
            yield item
            if isinstance(item, MotionChunk) and item.scale is not None:
                self._chunk(item)
            elif isinstance(item, MotionChunk):
                for seg in item.objects or ():
                    self._segment(seg)
            elif isinstance(item, Segment):
                self._segment(item)
            else:
                for seg in item.segments():
                    self._segment(seg)

    def finish(self, violating: Iterable[int] = (), upto: int | None = None) -> list[Reason]:
        """The reasons after the last motion; those at a ``violating`` block (the verdict is ``unsafe`` there and
        the violation names it) or after ``upto`` (the proof stopped at its violation limit) are left out."""
        for d in sorted(self.grown):
            self._grown_reasons(d)
        bad = set(violating)
        out = [r for r, lo, hi in self.found
               if bad.isdisjoint((lo, hi)) and (upto is None or hi <= upto)]
        more = dict(self.more)
        for r in out[MAX_REASONS:]:
            more[r.code or REGION_CODE] = more.get(r.code or REGION_CODE, 0) + 1
        out = out[:MAX_REASONS]
        if upto is None:
            out += [Reason(f"{n} more blended corner(s) where the tool solids could not be proved to clear the "
                           "fixtures", None, None, code) for code, n in sorted(more.items()) if n]
        return out

    def notes(self) -> list[str]:
        """The least clearances over the motions next to corners rounded within a tolerance ``d``: a part grown
        by ``d`` that clears a fixture by ``c`` holds the real part, displaced by at most ``d``, at least ``c``
        from it (call after :meth:`finish`)."""
        out = []
        for d in sorted(self.grown):
            modes = ", ".join(sorted(self.codes.get(d, ())))
            for (label, fx), (c, line) in sorted(self.grown[d].clearance.items()):
                if c >= 0:
                    out.append(f"least clearance on the path the control may move ({modes}: within "
                               f"{format_decimal(d)} mm of the programmed one, next to its rounded corners): "
                               f"{label.split(' (')[0]} is at least {format_decimal(Fraction(int(c * 1000), 1000))} mm "
                               f"from `{fx}` at line {line}")
        return out

    def mode_of(self, block: int) -> PathMode:
        k = bisect_right(self.modes, block, key=lambda e: e[0]) - 1
        return self.modes[max(k, 0)][1]

    def _add(self, reason: Reason, lo: int, hi: int) -> None:
        if len(self.found) >= 4 * MAX_REASONS:
            code = reason.code or REGION_CODE
            self.more[code] = self.more.get(code, 0) + 1
            return
        self.found.append((reason, lo, hi))

    # ------------------------------------------------------------------ one motion at a time
    def _segment(self, seg: Segment) -> None:
        kind = seg.kind
        if kind is SegmentKind.DWELL:
            self.prev, self.prev_stop, self.dropped = None, True, None
            return
        if seg.start == seg.end and kind is not SegmentKind.ARC:
            return  # a move of length 0: LinuxCNC's canon drops it, the corner is between its neighbours
        if kind is SegmentKind.RAPID and self.dogleg:  # positioning with an in-position check at both ends
            self.prev, self.prev_stop, self.dropped = None, True, None
            return
        prev = self.prev
        self._dropped(prev, seg)
        d = F0
        if prev is not None and not self.prev_stop:
            before = self.mode_of(prev.block)  # the corner is rounded in the mode the first motion runs in
            bound = before.bound()
            if bound is None:
                self._corner(prev, seg, before)
            else:
                if bound > 0:
                    self._tool_change_at(prev, seg, before)
                if bound > d:
                    d = bound
                    self.codes.setdefault(bound, set()).add(before.code)
        mode = self.mode_of(seg.block)
        bound = mode.bound() if mode.blend else F0
        if bound is not None and bound > d:
            d = bound
            self.codes.setdefault(bound, set()).add(mode.code)
        if d > 0:
            self._checker(d).feed(seg)
        self.prev, self.prev_stop = seg, not mode.blend

    def _tool_change_at(self, a: Segment, b: Segment, mode: PathMode) -> None:
        """A corner rounded within a tolerance whose two motions carry different tools, tool lengths or frames
        (a Fanuc ``G43 H`` inside a run in cutting mode; LinuxCNC stops there): the grown parts' checker proves
        each motion with its own tool and length, while a position of the blend may be near either motion with
        either's: not modelled, ``unknown`` (VF233)."""
        if (a.tool_register, a.tool_length, a.frame) == (b.tool_register, b.tool_length, b.frame):
            return
        self._add(Reason(f"the tool solids may meet a fixture in {_corner_name(a, b)}: the control may round this "
                         f"corner ({mode.code}) while the tool length or frame changes between its motions, which "
                         "the proof of the tool solids on the rounded path does not model (G61, or G09 on the "
                         "motion before the change, proves it)", a.span, a.block, TOLERANCE_CODE),
                  a.block, b.block)

    def _dropped(self, prev: Segment | None, seg: Segment) -> None:
        """LinuxCNC drops a straight move shorter than 1e-8 of its units on every axis (``CART_FUZZ``; the point's
        corner proof, ``CornerCheck._dropped_corner``, says where): the corner is then between the motions around
        it, and the motion after runs from the end of the one before.  A move shorter than
        :data:`~nczones.motion.DROPPED_BELOW` may be dropped, so that corner and that motion are proved too: in a
        mode with a tolerance the motion as the planner runs it goes to the grown parts' checker (the blend stays
        within the bound of it and of the motion before); without one, its box and the corner's region are
        tested; an arc after it (another curve from another start) is ``unknown``."""
        if _linear_tiny(seg):
            if self.dropped is None and prev is not None and not self.prev_stop:
                self.dropped = prev
            return
        before, self.dropped = self.dropped, None
        if before is None or self.mode_of(before.block).dialect != "linuxcnc":
            return
        mode = self.mode_of(before.block)
        if seg.kind not in _LINEAR or self.nominal is None:
            self._add(Reason(f"the tool solids may meet a fixture in {_corner_name(before, seg)}: a motion shorter "
                             "than 3e-7 mm between them may be dropped by LinuxCNC, which then runs the motion after "
                             "from the corner: not modelled for the tool solids", before.span, before.block,
                             REGION_CODE), before.block, seg.block)
            return
        moved = replace(seg, start=before.end)  # the motion after the dropped ones, as the planner runs it
        bound = mode.bound()
        if bound is not None and bound > 0:
            self.codes.setdefault(bound, set()).add(mode.code)
            self._checker(bound).feed(moved)
            return
        lo = [min(s, e) for s, e in zip(moved.start, moved.end)]
        hi = [max(s, e) for s, e in zip(moved.start, moved.end)]
        met = self._meets(before, seg, lo, hi)
        if met is not None:
            self._add(Reason(f"{met} may be met by the motion after {_corner_name(before, seg)} as LinuxCNC runs it "
                             "when it drops the motion shorter than 3e-7 mm between them", before.span, before.block,
                             REGION_CODE), before.block, seg.block)
            return
        if mode.blend:
            self._corner(before, moved, mode)

    def _checker(self, d: Fraction) -> Any:
        got: Any = self.grown.get(d)
        if got is None:
            if isinstance(self.solids, LatheSolids):
                from .lathe_solids import LatheSolidsChecker

                got = LatheSolidsChecker(self.machine, grown_lathe_solids(self.solids, d))
            else:
                got = SolidsChecker(self.machine, grown_solids(self.solids, d), self.ranges, screen=None)
            self.grown[d] = got
        return got

    # ------------------------------------------------------------------ column chunks
    def _chunk(self, chunk: MotionChunk) -> None:
        n = len(chunk)
        if n == 0:
            return
        assert chunk.block is not None and chunk.start is not None and chunk.end is not None
        first, last = int(chunk.block[0]), int(chunk.block[-1])
        moving = np.flatnonzero(~(np.asarray(chunk.start) == np.asarray(chunk.end)).all(axis=1))
        if len(moving) < 2 or _tiny_rows(chunk) or bisect_right(self.modes, first, key=lambda e: e[0]) != bisect_right(
                self.modes, last, key=lambda e: e[0]):
            for seg in chunk.segments():  # the mode changes inside the chunk: one motion at a time
                self._segment(seg)
            return
        j0 = int(moving[0])
        for k in range(j0 + 1):  # the corner with the motion before the chunk, and the first motion's bound
            self._segment(_row(chunk, k))
        mode = self.mode_of(first)
        if not mode.blend:
            return  # no corner inside the chunk is rounded (_segment left prev_stop set)
        bound = mode.bound()
        if bound is not None and chunk.tool_length is not None and \
                not (np.asarray(chunk.tool_length)[moving] == np.asarray(chunk.tool_length)[moving[0]]).all():
            for k in range(j0 + 1, n):  # the tool length changes inside the chunk: one motion at a time
                self._segment(_row(chunk, k))
            return
        if bound is not None:  # > 0: a blending mode with a tolerance
            self.codes.setdefault(bound, set()).add(mode.code)
            self._checker(bound).feed_chunk(chunk.rows(j0 + 1, n))
        elif mode.dialect == "fanuc" or mode.naive > 0:
            self._corner(_row(chunk, j0), _row(chunk, int(moving[1])), mode)  # named once, the others counted
            self.more[MODE_CODE] = self.more.get(MODE_CODE, 0) + len(moving) - 2
        elif not self._screen_corners(chunk, moving, mode):
            for k in range(j0 + 1, n):
                self._segment(_row(chunk, k))
            return
        self.prev, self.prev_stop = _row(chunk, int(moving[-1])), False

    def _screen_corners(self, chunk: MotionChunk, moving: np.ndarray, mode: PathMode) -> bool:
        """The corners between consecutive ``moving`` rows (those of non-zero length: the canonical layer drops
        the others) of a chunk in LinuxCNC G64 without tolerance, screened with numpy by the box of each
        corner's three points; those the screen leaves are proved exactly.  False when the chunk is not
        screened (the caller proves its corners one by one)."""
        if isinstance(self.solids, LatheSolids) or not self.static or not chunk.tools_known:
            return False
        parts = self.solids.parts_for(chunk.tool_register)
        if parts is None or chunk.tool_length is None:
            return False
        assert chunk.kind is not None and chunk.start is not None and chunk.end is not None
        kinds = np.asarray(chunk.kind)[moving]
        allowed = [SegmentKind.LINE.value] + ([] if self.dogleg else [SegmentKind.RAPID.value])
        start, end = np.asarray(chunk.start)[moving], np.asarray(chunk.end)[moving]
        length = np.asarray(chunk.tool_length)[moving]
        if not np.isin(kinds, allowed).all() or not (start[1:] == end[:-1]).all() or not (length == length[0]).all():
            return False  # arcs, dwells, dogleg rapids, a gap or a tool length change
        lo = np.minimum(np.minimum(start[:-1], end[:-1]), end[1:])
        hi = np.maximum(np.maximum(start[:-1], end[:-1]), end[1:])
        m = len(moving) - 1
        boxes = replace(chunk, start=lo, end=hi, kind=np.full(m, SegmentKind.LINE.value, dtype=kinds.dtype),
                        tool_length=length[1:], line=None if chunk.line is None else np.asarray(chunk.line)[moving[1:]],
                        block=np.asarray(chunk.block)[moving[1:]])
        hit = needs_exact_columns(boxes, 0, m, self.xyz, parts, self.solids.fixtures, lambda _p, _f: None).hit
        for k in np.flatnonzero(hit).tolist():
            self._corner(_row(chunk, int(moving[k])), _row(chunk, int(moving[k + 1])), mode)
        return True

    # ------------------------------------------------------------------ corners without tolerance
    def _corner(self, a: Segment, b: Segment, mode: PathMode) -> None:
        """The corner between ``a`` and ``b``, rounded without tolerance in ``mode`` (``a``'s)."""
        if self.nominal is None:
            self._add(Reason(f"the tool solids may meet a fixture in {_corner_name(a, b)}: {mode.code} may round it "
                             "with no tolerance, and a lathe's tool solids are proved over rounded corners only "
                             "within a tolerance (give G64 P, path_tolerance, or G61)", a.span, a.block, MODE_CODE),
                      a.block, b.block)
            return
        if mode.dialect == "fanuc" or mode.naive > 0:
            why = ("a Fanuc control in cutting mode without [machine] path_tolerance (acc/dec after interpolation "
                   "rounds corners by an amount the machine file does not bound)" if mode.dialect == "fanuc" else
                   "G64 Q without P (naive-CAM merging, blended without tolerance)")
            self._add(Reason(f"the tool solids may meet a fixture in {_corner_name(a, b)}: {why} is not modelled "
                             f"for the tool solids; give a tolerance ({'path_tolerance' if mode.dialect == 'fanuc' else 'G64 P'}) "
                             "or program G61", a.span, a.block, MODE_CODE), a.block, b.block)
            return
        self.corners += 1
        if a.kind in _LINEAR and b.kind in _LINEAR and b.start == a.end:
            c = a.end
            d1 = tuple((s - e) * _HALF for s, e in zip(a.start, a.end))
            d2 = tuple((e - s) * _HALF for s, e in zip(b.start, b.end))
            met = self._refine(a, b, c, d1, d2, (F0, F1), (F0, F1), DEPTH)
        else:
            ba, bb = _box(a), _box(b)
            if ba is None or bb is None:
                met = f"a {(a if ba is None else b).kind.name.lower()} motion next to a blended corner"
            else:
                c = a.end
                lo = [x + y - z for x, y, z in zip(ba[0], bb[0], c)]
                hi = [x + y - z for x, y, z in zip(ba[1], bb[1], c)]
                met = self._meets(a, b, lo, hi)
        if met is None:
            return
        self._add(Reason(f"{met} may be met in {_corner_name(a, b)}: the control may round this corner using up to "
                         f"half of each motion ({mode.code} without P) while the programmed path clears it; G61, or "
                         "G64 P with a tolerance that clears, proves it", a.span, a.block, REGION_CODE),
                  a.block, b.block)

    def _refine(self, a: Segment, b: Segment, c: tuple[Fraction, ...], d1: tuple[Fraction, ...],
                d2: tuple[Fraction, ...], ra: tuple[Fraction, Fraction], rb: tuple[Fraction, Fraction],
                depth: int) -> str | None:
        """None when the tool clears every fixture with the controlled point anywhere in ``c + s d1 + t d2``
        (``s`` in ``ra``, ``t`` in ``rb``), else what it may meet; split in quarters ``depth`` more times."""
        lo = [x + min(ra[0] * u, ra[1] * u) + min(rb[0] * w, rb[1] * w) for x, u, w in zip(c, d1, d2)]
        hi = [x + max(ra[0] * u, ra[1] * u) + max(rb[0] * w, rb[1] * w) for x, u, w in zip(c, d1, d2)]
        met = self._meets(a, b, lo, hi)
        if met is None or depth == 0 or met.startswith("the tool solids"):
            return met
        ma, mb = (ra[0] + ra[1]) / 2, (rb[0] + rb[1]) / 2
        for sa in ((ra[0], ma), (ma, ra[1])):
            for sb in ((rb[0], mb), (mb, rb[1])):
                got = self._refine(a, b, c, d1, d2, sa, sb, depth - 1)
                if got is not None:
                    return got
        return None

    def _meets(self, a: Segment, b: Segment, lo: list, hi: list) -> str | None:
        """None when the tool of ``a`` and of ``b`` clears every fixture anywhere in the box ``lo..hi``; else what
        it may meet (``the holder (…) and `vise```)."""
        same = (a.tool_register, a.tool_length, a.frame) == (b.tool_register, b.tool_length, b.frame)
        assert self.nominal is not None  # a mill (_corner)
        for seg in (a,) if same else (a, b):
            got = self.nominal.box_meets(seg, lo, hi)
            if got is None:
                self.nominal.reasons.clear()
                return "the tool solids (the tool or the fixtures' place is not known there)"
            if isinstance(got, tuple):
                part, fx = got
                return f"`{fx.name}` by the {part.label()}"
        return None

    # ------------------------------------------------------------------ reasons of the grown checkers
    def _grown_reasons(self, d: Fraction) -> None:
        checker = self.grown[d]
        checker.flush()
        modes = ", ".join(sorted(self.codes.get(d, ())))
        bound = format_decimal(d)
        for v in checker.violations:
            part = v.zones[0] if v.zones else "a part"
            self._add(Reason(f"the {part} may meet `{v.zone}` at {_where_v(v)}: the programmed path clears it, but "
                             f"in {modes} the control may leave that path by up to {bound} mm near the corners, "
                             f"and the {part} grown by {bound} mm meets it (a tighter tolerance, or G61, may prove "
                             "it)", v.span, v.block, TOLERANCE_CODE), v.block, v.block)
        for r in checker.reasons:
            if r.code in ("VF211", "VF219"):
                continue  # the same motion's own proof gives this reason (the tool or the frame, not the bound)
            self._add(Reason(f"on the path the control may move within {bound} mm of the programmed one "
                             f"({modes}): {r.message}", r.span, r.block, TOLERANCE_CODE),
                      r.block or 0, r.block or 0)


def _where_v(v: Any) -> str:
    return f"line {v.span.line}" if v.span is not None else f"block {v.block}"


def _linear_tiny(seg: Segment) -> bool:
    """A straight motion of non-zero length shorter than :data:`~nczones.motion.DROPPED_BELOW` on every axis."""
    return seg.kind in _LINEAR and seg.start != seg.end and all(
        abs(e - s) < DROPPED_BELOW for s, e in zip(seg.start, seg.end))


def _tiny_rows(chunk: MotionChunk) -> bool:
    """Does the column chunk hold a moving row shorter than ``DROPPED_BELOW`` on every axis?  Every non-zero change
    is at least one unit of the chunk's scale, so none below 1e-6 mm scale's rows can be."""
    if chunk.scale is None or Fraction(1, 10**chunk.scale) >= DROPPED_BELOW:
        return False
    lim = -(-DROPPED_BELOW.numerator * 10**chunk.scale // DROPPED_BELOW.denominator)
    step = np.abs(np.asarray(chunk.end) - np.asarray(chunk.start))
    return bool(((step < lim).all(axis=1) & (step > 0).any(axis=1)).any())


def _row(chunk: MotionChunk, k: int) -> Segment:
    """Row ``k`` of a column chunk as a segment."""
    return next(iter(chunk.rows(k, k + 1).segments()))


def _box(seg: Segment) -> tuple[list[Fraction], list[Fraction]] | None:
    """A box of every position of ``seg`` (lines and rapids: their ends — a dogleg rapid's axes move
    monotonically too; arcs and helices: the plane sweep's box and the ends elsewhere); None for other kinds."""
    lo, hi = list(map(min, seg.start, seg.end)), list(map(max, seg.start, seg.end))
    if seg.kind in _LINEAR:
        return lo, hi
    if seg.kind is SegmentKind.ARC:
        g = arc_geom(seg)
        (lo[g.ia], hi[g.ia]), (lo[g.ib], hi[g.ib]) = g.plane_bbox()
        return lo, hi
    return None
