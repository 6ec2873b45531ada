"""``safe`` for a Fanuc program without numpy: the box of every motion, proved exactly (issue 36).

A Fanuc program that needs the language layer (Macro B loops, G65/M98 calls) and is short as text is read by
the full interpreter alone (``pipeline.verification.FAST_PATH_MIN_LINES``), and so, on this route, is a plain one
(no ``#``, no call) of up to ``pipeline.verification.FANUC_BOX_LINES`` lines; for today's path its plain lane writes
runs of straight moves as rows (:class:`nczones.gcode.fanuc.columns.Rows`: Python lists of exact integers,
coordinates times ``10**SCALE``), which become numpy column chunks; loading numpy alone costs more than rs274
takes for a 10,000-line run.  :func:`prove_boxes` instead follows the interpretation's motion with no numpy: the
lane writes each run's exact box only (``nczones.gcode.fanuc.columns.BoxRows``, the same scaled integers; the
pipeline gives the interpreter that sink, and this module reads a run through its ``bounds()``, importing no
program reader: the import contract of the prover), the other motions come as segments, and the exact box of every position the program commands is tested with the
exact box test of the per-motion proof (:func:`nczones.prover.exact.box_fits`, every zone kind, the margin) at
every tool length the program used.

Why a fitting box proves the program ``safe`` (the same model as the full path, never more):

* every motion lies in the box of its positions: a straight move (G1, a straight or dogleg G0: each axis moves
  monotonically from start to end) in the box of its two ends, a circular arc or a helix in
  ``ArcGeom.plane_bbox`` (the exact extremes of an arc with a rational centre; for an R-format arc, whose centre
  may be irrational, its ends and the extremes of the circle (outward rational bounds of the centre and radius)
  in every axis direction its sweep may reach for a centre in the enclosure) and the box of its ends on the
  other axes; an I/J arc whose end lies on the ray from the centre through its start (a whole spiral turn on
  LinuxCNC) in ``geometry.whole_turn_box`` (the centre +- the larger radius), the box the per-motion proof
  proves it by (``Prover._decide_whole_turn``);
* an arc the lane writes into a run's box (``FanucInterpreter._arc_lane``, ``BoxRows.add_arc``: a G2/G3 block
  with R, or I/J/K whose ends are at one distance from the centre, in the state the straight lane takes; issue
  36, for plain programs of 512 lines and more) is boxed the same way in scaled integers:
  ``columns.r_arc_box`` decides exactly, with no square root, which of the circle's four axis extremes lie on
  the arc (the chord's line cuts the circle into the minor and the major arc, the centre being on the major
  one's side: an extreme is on the arc when it lies on the arc's side of that line, a sign of
  ``A - sqrt(Q)`` or ``A + sqrt(Q)`` with integers ``A``, ``Q``) and encloses the irrational centre outward by
  integer square roots; ``columns.centre_arc_box`` takes the exact centre and the radius's root rounded up.
  Every bound is outward (at most 2 units of ``10**-9`` mm beyond ``ArcGeom.plane_bbox``'s), and every arc
  left out (equal ends, a chord of ``2|R|`` within the interpreter's tolerance, a spiral, an error, a mode noted
  as assumed) takes the general path and comes here as a segment;
* the control may leave the programmed path in cutting mode (acc/dec after interpolation rounds corners): the
  path then stays in the convex hull of the run of motions between exact stops (``specs/path-modes.md`` §3).
  A box is convex: when it holds every motion it holds the hull of every run, whatever the exact stops
  (G09, G61) are; so no run is ever split here.  ``[machine] path_tolerance`` (a different bound) declines;
* a tip zone sees the position less the tool length on the tool axis: the box is tested at every tool length
  a motion carried (a G43 H inside a run included, as the full path's hull test takes every length of a run);
* the allowed set is tested with the margin by ``box_fits``, exactly, as the full path tests a box.

Anything else declines (None: the caller runs today's path, which decides as if this had not been tried): a box
that does not fit (no split: a run's hull needs one box that holds the whole run), a motion kind other than a
line, rapid, arc or dwell, a segment with a payload (lathe tip offsets, turret tools, polar, splines) or
dependencies, a two-axis machine (a lathe), tool solids, an error while reading, a block-skip switch the run
met.  A code the interpreter could not model (``run.unsupported``: a loop past its bound, say) ends the motion
there as it ends it for the full path: the box proves every motion read, and the pipeline makes the verdict
``unknown`` with the full path's reasons for those codes (``pipeline.verification._fanuc_boxes``, one case of
``_verify_cases``), so a long loop that ends ``unknown`` is not read twice.  The pipeline reports the facts the
full path reports (the run's notes, the assumed modes, counts, its own notes).  ``tests/prover/
test_fanuc_boxes.py`` holds its verdicts, reasons and notes to the full path's.
"""

from __future__ import annotations

import time
from fractions import Fraction

from ..errors import InvalidArgument
from ..machine import Machine, declares_solids
from ..motion import MotionChunk, Segment, SegmentKind
from .exact import box_fits
from .result import Result, Verdict

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["prove_boxes", "BoxWalk", "boxes_apply"]

#: Whether the pipeline tries this route (tests of today's lanes turn it off: tests/gcode/fanuc/conftest.py).
ROUTE = True
#: The lane's runs as ``nczones.gcode.fanuc.columns.Rows`` (lists of every row) instead of their boxes
#: (``columns.BoxRows``), as the pipeline sets the interpreter's sink; tests compare the two.
ROWS_AS_LISTS = False
_LINE, _RAPID, _ARC, _DWELL = SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.ARC, SegmentKind.DWELL


def boxes_apply(machine: Machine) -> bool:
    """Whether :func:`prove_boxes` can take a program on ``machine``: not a two-axis machine (a lathe: nose
    radius, turret and tip offsets are the full path's), no tool solids, no ``path_tolerance``."""
    return (ROUTE and len(machine.axis_names) > 2 and not declares_solids(machine) and not machine.path_tolerance
            and machine.dialect == "fanuc")


class _Declined(Exception):
    """The walk met what it does not model."""


#: the positions the walk keeps as integers are multiples of ``1 / _SCALE`` (Fanuc increments, exact decimals)
_SCALE = 10**12
#: ``_SCALE // d`` by denominator ``d`` (0: ``d`` does not divide ``_SCALE``)
_PER: dict[int, int] = {}


class BoxWalk:
    """The exact box of every position of an interpretation's motion, and its tool lengths (Fractions).

    A coordinate that is a multiple of ``1 / _SCALE`` (every Fanuc increment and exact decimal the program can
    write: the common case) joins an integer box of the coordinates times ``_SCALE``, others a Fraction box;
    :meth:`box` takes the least and greatest of the two, exactly (``Fraction(n, _SCALE)`` is the coordinate).  A
    straight motion that starts at the previous motion's end (the same object) adds its end only: its start is
    in the box already."""

    def __init__(self, axes: tuple[str, ...]) -> None:
        self.axes = axes
        self.width = len(axes)
        self.lo: list[Any] = [None] * self.width
        self.hi: list[Any] = [None] * self.width
        self.ilo: list[Any] = [None] * self.width  # the integer box (times _SCALE)
        self.ihi: list[Any] = [None] * self.width
        self.tls: set[Fraction] = set()
        self.motions = 0
        self.rows = 0
        self._last: Any = None  # the last motion's end
        self._tl: Any = None  # the last tool length added

    def take(self, chunk: Any) -> None:
        """Follow one chunk of the interpretation (raises :class:`_Declined` on what is not modelled)."""
        if not isinstance(chunk, MotionChunk) or chunk.scale is not None:
            raise _Declined  # column chunks come from the vectorized path, which this walk does not take
        items: Any = chunk.objects or ()  # segments and runs of the plain lane (columns.BoxRows or Rows)
        for item in items:
            if isinstance(item, Segment):
                self._segment(item)
            else:
                self._run(item)

    def _run(self, run: Any) -> None:
        """A run of the plain lane: its ``bounds()`` (scaled box, tool lengths, rows, scale) joins the box."""
        bounds = getattr(run, "bounds", None)
        if bounds is None:
            raise _Declined
        r_lo, r_hi, tls, count, scale = bounds()
        unit = 10**scale
        self._fractions([Fraction(v, unit) for v in r_lo], [Fraction(v, unit) for v in r_hi])
        self.tls.update(Fraction(v, unit) for v in tls)
        self.motions += count
        self.rows += count
        self._last = None

    def _fractions(self, lo: list[Any], hi: list[Any]) -> None:
        """The box ``lo``..``hi`` (Fractions by axis index) joins the Fraction box."""
        blo, bhi = self.lo, self.hi
        for i in range(self.width):
            if blo[i] is None or lo[i] < blo[i]:
                blo[i] = lo[i]
            if bhi[i] is None or hi[i] > bhi[i]:
                bhi[i] = hi[i]

    def _point(self, p: Any) -> None:
        """The position ``p`` (by axis index) joins the box: the integer one where it can."""
        ilo, ihi, per = self.ilo, self.ihi, _PER
        for i in range(self.width):
            x = p[i]
            try:
                num, d = x._numerator, x._denominator
            except AttributeError:  # an int
                num, d = x.numerator, x.denominator
            m = per.get(d)
            if m is None:
                m = per[d] = 0 if _SCALE % d else _SCALE // d
            if not m:
                self._coordinate(i, x)
                continue
            v = num * m
            lo = ilo[i]
            if lo is None:
                ilo[i] = ihi[i] = v
            elif v < lo:
                ilo[i] = v
            elif v > ihi[i]:
                ihi[i] = v

    def _coordinate(self, i: int, x: Any) -> None:
        """One coordinate joins the Fraction box."""
        if self.lo[i] is None or x < self.lo[i]:
            self.lo[i] = x
        if self.hi[i] is None or x > self.hi[i]:
            self.hi[i] = x

    def _segment(self, seg: Segment) -> None:
        kind = seg.kind
        if seg.extra or seg.deps_start or seg.deps_end or seg.deps_tool:
            raise _Declined
        if kind is _LINE or kind is _RAPID or kind is _DWELL:
            if seg.start is not self._last:
                self._point(seg.start)
            self._point(seg.end)
        elif kind is _ARC:
            from .geometry import on_start_ray, whole_turn_box

            if on_start_ray(seg):  # a whole spiral turn: the per-motion proof's box of it (Prover._decide_whole_turn)
                lo, hi = map(list, whole_turn_box(seg))
            else:
                lo, hi = _arc_box(seg)
            self._fractions(lo, hi)
        else:
            raise _Declined
        self._last = seg.end
        tl = seg.tool_length
        if tl is not self._tl:
            self.tls.add(tl)
            self._tl = tl
        self.motions += 1

    def box(self) -> tuple[dict[str, Fraction], dict[str, Fraction]] | None:
        """The box of every position (by axis), None when there was no motion."""
        if not self.motions:
            return None
        lo, hi = [], []
        for i in range(self.width):
            a, b, ia, ib = self.lo[i], self.hi[i], self.ilo[i], self.ihi[i]
            if ia is not None:
                fa, fb = Fraction(ia, _SCALE), Fraction(ib, _SCALE)
                a = fa if a is None or fa < a else a
                b = fb if b is None or fb > b else b
            lo.append(a)
            hi.append(b)
        return dict(zip(self.axes, lo)), dict(zip(self.axes, hi))

    def tool_lengths(self) -> set[Fraction]:
        """Every tool length a motion carried."""
        return self.tls


def _arc_box(seg: Segment) -> tuple[list[Fraction], list[Fraction]]:
    """The corners (by axis index) of the box of an arc's path (its plane's extremes in its sweep), or
    :class:`_Declined` for an arc the per-motion proof refuses or decides otherwise."""
    from .geometry import arc_geom

    try:
        g = arc_geom(seg)
        (xl, xh), (yl, yh) = g.plane_bbox(sweep=True)
    except (InvalidArgument, ValueError, ZeroDivisionError):
        raise _Declined from None
    lo, hi = list(map(min, seg.start, seg.end)), list(map(max, seg.start, seg.end))
    lo[g.ia], hi[g.ia], lo[g.ib], hi[g.ib] = min(xl, lo[g.ia]), max(xh, hi[g.ia]), min(yl, lo[g.ib]), \
        max(yh, hi[g.ib])
    return lo, hi


#: the profile's labels of the interpretation's motion counts (``Interpretation.counts``: by ``SegmentKind``)
_KIND_LABELS = frozenset(k.name.lower() for k in SegmentKind)


def _kinds(counts: dict[str, int]) -> dict[str, dict[str, Any]]:
    """The profile's motions by kind (``RunProfile.as_dict``), none decided one by one: the interpretation's counts
    by motion kind, a helix counted among the arcs (as the vectorized screen counts its rows; the per-motion proof
    labels a helix it decides ``helix``).  ``slowest`` stays empty: no motion is decided on its own here."""
    return {k: {"motions": n, "seconds_one_by_one": 0.0} for k, n in sorted(counts.items())
            if k in _KIND_LABELS and n}


def prove_boxes(run: Any, machine: Machine, margin: Fraction, started: float | None = None) -> Result | None:
    """A ``safe`` result for the motion of the interpretation ``run`` (read by the full interpreter, not the
    vectorized path) on ``machine`` with ``margin``, or None when the route declines (module docstring); the notes
    and counts are the run's, as the full path reports them (the caller adds the reasons of ``run.unsupported``).
    The caller gives the interpreter's plain lane a sink whose runs have ``bounds()``
    (``nczones.gcode.fanuc.columns.BoxSink``: no segment per straight move).  The box is tested after every chunk
    (it only grows): the first chunk that makes it leave the allowed set stops the walk, so a program this route
    cannot prove costs little of a second reading."""
    from .solver_version import z3_version

    if started is None:
        started = time.perf_counter()
    if not boxes_apply(machine) or run.dialect != "fanuc" or margin < 0:  # a negative margin: the full path's error
        return None
    walk = BoxWalk(tuple(machine.axis_names))
    allowed = machine.allowed
    proved: tuple[Any, ...] = ()
    try:
        for chunk in run:
            walk.take(chunk)
            box = walk.box()
            if box is None:
                continue
            lo, hi = box
            tls = walk.tool_lengths()
            if (lo, hi, tls) == proved:
                continue
            if not all(box_fits(allowed, lo, hi, margin, tl) for tl in sorted(tls)):
                return None
            # a copy of the tool lengths: the walk's set grows in place, and a chunk that adds a length but not
            # a position must be tested again (the set itself would compare equal to itself: a wrong safe)
            proved = (lo, hi, frozenset(tls))
    except _Declined:
        return None
    if any(getattr(r, "seen_switches", None) for r in run.runners):
        return None
    n = walk.motions
    seconds = time.perf_counter() - started
    stats = (("segments", n), ("pieces", 0), ("screened", n), ("exact_decided", 0), ("z3_segments", 0),
             ("z3_queries", 0), ("fanuc_boxes", 1 if n else 0))
    counts = run.counts
    profile = {"total_s": round(seconds, 6), "motions": n, "blocks": counts["blocks"],
               "motions_screened_vectorized": 0, "fanuc_boxes": {"motions": n, "rows": walk.rows},
               "tiers": {"screen_vectorized_s": 0.0, "exact_per_motion_s": 0.0, "solver_s": 0.0,
                         "interpretation_and_rest_s": round(seconds, 6)},
               "kinds": _kinds(counts), "solver": {"calls": 0, "seconds": 0.0, "stopped": {}}, "slowest": []}
    notes = tuple(run.assumed_modal_text()) + tuple(run.notes())
    return Result(verdict=Verdict.SAFE, solver="z3", solver_version=z3_version(),
                  timings=(("prove_s", seconds),), stats=stats, margin=margin, engine="auto",
                  extra={"counts": counts, "splits": ()}, profile=profile, notes=notes, file=run.file)
