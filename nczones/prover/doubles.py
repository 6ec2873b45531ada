"""``safe`` from the double pass (:mod:`nczones.gcode.linuxcnc.doubles`, run by :mod:`nczones.pipeline`): boxes that hold
the motion, proved exactly.

The double pass gives every motion's end point as doubles with a bound on its distance from the full
path's exact point, and :meth:`~nczones.gcode.linuxcnc.doubles.DoublePath.enclosure` turns a run of motions into an
exact box holding every position of those motions.  When such boxes, proved with the exact box test of the
per-motion path (:func:`nczones.prover.exact.box_fits`, every zone kind, the margin), cover every motion,
every motion of the full path fits: the program is ``safe``.  This is a sound over-approximation of the
per-motion proof, never a replacement for it: a box that does not fit splits, and a single motion whose
box does not fit (or too many boxes) sends the program to the full path, which then decides it as if this
had not been tried (``tests/prover/test_double_pass_proof.py`` holds the two to the same verdicts).
"""

from __future__ import annotations

import time
from fractions import Fraction

from ..machine import Machine, declares_solids
from ..motion import DROPPED_BELOW
from .exact import box_fits
from .result import Result, Verdict

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["prove_enclosures", "prove_double_path", "WindowProof", "may_be_zero"]

#: A box that does not fit is split into this many.
SPLIT = 16
#: Motions per box at first (after the whole program's box).
FIRST_BOX = 4096


def prove_enclosures(path: Any, machine: Machine, margin: Fraction, max_boxes: int) -> int | None:
    """The number of boxes that proved every motion of ``path`` fits ``machine`` with ``margin``, or None when
    a single motion's box does not fit or more than ``max_boxes`` boxes would be needed.

    The whole program's box first; a box that does not fit is split in :data:`SPLIT` (the first time, in
    boxes of :data:`FIRST_BOX` motions).

    Corner blending (``specs/path-modes.md``): the pass's programs start in the machine's start-up path mode
    and may write G61, G61.1 and G64 without P (``path.modes``) or with P alone.  In G64 without tolerance a
    rounded corner between two straight motions uses at most half of each, so it lies in the box of the two:
    a corner inside a box is proved with it, and every corner between two boxes is proved on its own
    (:func:`_corner_fits`) unless the full path has no corner there (:meth:`~nczones.gcode.linuxcnc.doubles.
    DoublePath.blended`: the motion before it in exact stop, a dwell on either side; the exact-stop path is the
    programmed one, which the boxes hold).  With the machine's ``path_tolerance`` (``G64 P p``, whose Q is p)
    the path stays within ``2 p`` of the programmed one: the margin grows by that much for every motion, a
    superset for those the program runs in another mode (a path with arcs is left to the full path there).  The
    program's own ``G64 P p`` likewise (``path.tolerance``, at or above ``2 p``, from the window that holds its
    first motion in that mode on: an earlier window's motions ran in the modes before it).

    Arcs: the pass keeps a quick box of each arc (a screen, :mod:`~nczones.gcode.linuxcnc.double_arcs`); a box
    with arcs that does not fit (and a corner next to one) is tried again with its arcs' sweep boxes
    (:meth:`~nczones.gcode.linuxcnc.doubles.DoublePath.refine`, once per arc) before it splits.

    Arcs (``specs/path-modes.md``, "The enclosure without tolerance"): a rounded corner next to an arc lies in
    the Minkowski sum of the two motions' boxes less the corner ``C``, which a box holding both need not
    hold.  A box of two or more motions with an arc is proved grown by its own size on every side
    (``[2 lo - hi, 2 hi - lo]`` holds ``a + b - C`` for ``a``, ``b``, ``C`` in ``[lo, hi]``), or else by a
    bound of how far such a corner leaves it (:func:`_grown_fits`), either of which holds every corner inside it; the
    corner at a box's end is proved on its own.
    """
    arcs = bool(getattr(path, "arcs", 0))
    corners = _bare(path, machine)
    if machine.path_mode == "G64" and machine.path_tolerance:
        if arcs:
            return None  # blends of arcs with a tolerance: the full path's (prover/blend.py)
        margin += 2 * machine.path_tolerance
    tolerance = getattr(path, "tolerance", 0.0)  # the program's G64 P: every motion within it of its path
    if tolerance:
        if arcs:
            return None  # as above
        margin += Fraction(tolerance)
    blended = getattr(path, "blended", None) if getattr(path, "modes", ()) else None
    allowed = machine.allowed
    zero = Fraction(0)
    start = getattr(path, "row0", 0) + 1  # a window of a long program holds rows row0..motions
    todo = [(start, path.motions)] if path.motions >= start else []
    boxes = 0
    while todo:
        first, last = todo.pop()
        boxes += 1
        if boxes > max_boxes:
            return None
        lo, hi = path.enclosure(first, last)
        if corners and arcs and last > first and path.has_arcs(first, last):
            fits = _grown_fits(path, allowed, margin, first, last, lo, hi)
        else:
            fits = box_fits(allowed, lo, hi, margin, zero)
        if fits:
            if corners and last < path.motions and _corner_wanted(path, blended, last) \
                    and not _corner_fits(path, allowed, margin, last):
                if not (arcs and _refine(path, last, last + 1) and _corner_fits(path, allowed, margin, last)):
                    return None
            continue
        if arcs and _refine(path, first, last):
            todo.append((first, last))  # the same motions again, with their arcs' sweep boxes
            boxes -= 1
            continue
        if first == last:
            return None
        n = last - first + 1
        size = FIRST_BOX if n > FIRST_BOX * SPLIT and first == start and last == path.motions else -(-n // SPLIT)
        todo.extend((a, min(a + size - 1, last)) for a in range(first, last + 1, size))
    return boxes


def _corner_wanted(path: Any, blended: Any, k: int) -> bool:
    """Must the corner after motion ``k`` (between two boxes) be proved: may the full path round a corner
    there?  Yes where motion ``k`` blends (``blended``: its mode, no dwell beside it; None: every corner), and
    where motion ``k`` may be dropped (:func:`may_be_zero`) with no dwell beside it: LinuxCNC then joins the
    motion before the dropped ones to the one after them in the earlier motion's mode, whatever the dropped
    motion's own (``CornerCheck._dropped_corner``; ``tests/contract/test_seam_hunt.py``, G61 on the short
    move after a G64 motion), and :func:`_corner_fits` proves that join."""
    if blended is None or blended(k):
        return True
    return not path.dwell_beside(k) and may_be_zero(path, k)


def _bare(path: Any, machine: Machine) -> bool:
    """May a corner of ``path`` blend without a tolerance: a motion in G64 without P (the program's, ``path.modes``,
    or the machine's start mode without ``path_tolerance``)?"""
    modes = getattr(path, "modes", ())
    if modes:
        return any(bare for _row, bare in modes)
    return machine.path_mode == "G64" and not machine.path_tolerance


def _refine(path: Any, first: int, last: int) -> bool:
    """Narrow the quick boxes of the arcs among motions ``first``..``last`` to their sweep boxes
    (:meth:`~nczones.gcode.linuxcnc.doubles.DoublePath.refine`); whether one was narrowed."""
    refine = getattr(path, "refine", None)
    return bool(refine is not None and refine(first, last))


def _corner_fits(path: Any, allowed: Any, margin: Fraction, k: int) -> bool:
    """Does the blend region of the corner between motions ``k`` and ``k + 1`` fit?  Every point of it is
    ``P1 + a (M1 - P1) + b (M2 - P1)`` (``a, b`` in [0, 1], ``M1``, ``M2`` the midpoints of the motions,
    ``P0``, ``P1``, ``P2`` rows ``k - 1``, ``k``, ``k + 1``): in the box of ``P1``, ``M1``, ``M2`` and
    ``(P0 + P2) / 2``, each bounded with the rows' boxes (``path.enclosure(r + 1, r)`` is row r's alone).
    Those points are convex combinations of ``P0``, ``P1``, ``P2``, so that box lies in the box of the three
    rows' boxes, which ``path.enclosure(k, k + 1)`` (rows ``k - 1``..``k + 1``) holds: when that one fits
    (one enclosure, one test), so does the corner; else the corner's own box is tried.

    A motion of length 0 is dropped by LinuxCNC's canonical layer: the corner is then between the motions
    around it (specs/path-modes.md §1), whose midpoints rows ``k - 1``..``k + 1`` do not hold.  When motion
    ``k`` or ``k + 1`` may be dropped (:func:`may_be_zero`: length 0 or below 3e-7 mm), the corner of the
    motions around it lies in the box of those motions (a line-line blend region lies in the box of its two
    motions), which must then fit; a window that does not hold them gives False (the pass declines).

    An arc on either side: the Minkowski sum of the two motions' whole boxes less the corner's box (a sound
    superset of the region of specs/path-modes.md); next to a motion that may be dropped, False, but for the
    program's first motion (``k == 1``: nothing before it to join the arc to, whether it is dropped or not)."""
    arcs = getattr(path, "arcs", 0) and path.has_arcs(k, k + 1)
    if arcs:
        # the program's first motion has no motion before it: dropped, the arc runs from where it began (no
        # corner); else its corner with the arc is the one bounded below (the full path: CornerCheck)
        if (k > 1 and may_be_zero(path, k)) or may_be_zero(path, k + 1):
            return False
        (l1, h1), (l2, h2), (lc, hc) = path.enclosure(k, k), path.enclosure(k + 1, k + 1), path.enclosure(k + 1, k)
        lo = {a: l1[a] + l2[a] - hc[a] for a in l1}
        hi = {a: h1[a] + h2[a] - lc[a] for a in h1}
        return box_fits(allowed, lo, hi, margin, Fraction(0))
    if may_be_zero(path, k) or may_be_zero(path, k + 1):
        first, last = k, k + 1
        while may_be_zero(path, first):
            first -= 1
            if first <= getattr(path, "row0", 0):
                return False  # the motion before the corner is not in this window
        while may_be_zero(path, last):
            last += 1
            if last > path.motions:
                return False  # the motion after it is not read yet
        if getattr(path, "arcs", 0) and path.has_arcs(first, last):
            return False  # an arc beside a dropped motion: the full path's
        lo, hi = path.enclosure(first, last)
        return box_fits(allowed, lo, hi, margin, Fraction(0))
    # first the box of rows k-1..k+1 (one enclosure): it holds each row's box, so the corner's box below
    lo, hi = path.enclosure(k, k + 1)
    if box_fits(allowed, lo, hi, margin, Fraction(0)):
        return True
    (l0, h0), (l1, h1), (l2, h2) = (path.enclosure(r + 1, r) for r in (k - 1, k, k + 1))
    lo = {a: min(l1[a], (l0[a] + l1[a]) / 2, (l1[a] + l2[a]) / 2, (l0[a] + l2[a]) / 2) for a in l1}
    hi = {a: max(h1[a], (h0[a] + h1[a]) / 2, (h1[a] + h2[a]) / 2, (h0[a] + h2[a]) / 2) for a in h1}
    return box_fits(allowed, lo, hi, margin, Fraction(0))


class WindowProof:
    """``on_window`` for :func:`nczones.gcode.linuxcnc.doubles.double_pass`: proves each window of a long program as
    the pass hands it over (then the pass drops its rows), counting the boxes; False stops the pass, None asks
    for the window again a motion later (it ends on a motion that may have length 0)."""

    def __init__(self, machine: Machine, margin: Fraction):
        self.machine = machine
        self.margin = margin
        self.boxes = 0
        self.windows = 0

    def __call__(self, path: Any) -> bool | None:
        # declares_solids is machine_solids(...) is not None without importing nczones.solids (start-up)
        if declares_solids(self.machine):
            return False  # the boxes are about the controlled point; tool solids need the full path
        if _bare(path, self.machine) and may_be_zero(path, path.motions):
            # the window ends on a motion that may have length 0: its corner joins the motion before it,
            # which the next window does not hold (the windows overlap by one motion): the window ends later
            return None
        boxes = prove_enclosures(path, self.machine, self.margin, max_boxes=_max_boxes(path))
        if boxes is None:
            return False
        self.boxes += boxes
        self.windows += 1
        return True


def _grown_fits(path: Any, allowed: Any, margin: Fraction, first: int, last: int, lo: dict[str, Fraction],
                hi: dict[str, Fraction]) -> bool:
    """Does the box ``[lo, hi]`` of motions ``first``..``last`` (with an arc) fit grown so that it holds every
    blended corner between two of its motions?  Grown on each axis by its own size (``[2 lo - hi, 2 hi - lo]``
    holds ``a + b - C`` for ``a``, ``b``, ``C`` in ``[lo, hi]``) or by the path's bound of how far such a corner
    leaves the box (``path.reach``, :mod:`nczones.gcode.linuxcnc.double_reach`), whichever is less: the bound
    asked for the widest axis first, then for the others (each costs a scan of the rows)."""
    zero = Fraction(0)
    size = {a: hi[a] - lo[a] for a in lo}
    for names in _reach_order(size, hasattr(path, "reach")):
        if names:
            reach = path.reach(first, last, names)
            if reach is None:
                return False
            size.update((a, min(size[a], g)) for a, g in reach.items())
        if box_fits(allowed, {a: lo[a] - g for a, g in size.items()}, {a: hi[a] + g for a, g in size.items()},
                    margin, zero):
            return True
    return False


def _reach_order(size: dict[str, Fraction], reach: bool) -> list[tuple[str, ...]]:
    """The axes to ask ``path.reach`` for before each test of :func:`_grown_fits`: none (the box's own size), the
    widest axis, the others (none at all without ``reach``)."""
    if not reach:
        return [()]
    order = sorted(size, key=size.__getitem__, reverse=True)
    return [(), tuple(order[:1]), tuple(order[1:])][:3 if len(order) > 1 else 2]


def may_be_zero(path: Any, k: int) -> bool:
    """May motion ``k`` (rows ``k - 1`` and ``k``) of the double pass's ``path`` be dropped by LinuxCNC's planner
    (length 0, or below :data:`~nczones.motion.DROPPED_BELOW`): are its two rows' boxes that close on every axis?
    Rows whose doubles are far apart on an axis (:meth:`~nczones.gcode.linuxcnc.doubles.DoublePath.apart`) are
    not, without the boxes; else the boxes are compared exactly."""
    apart = getattr(path, "apart", None)
    if apart is not None and apart(k - 1, k, DROPPED_BELOW):
        return False  # farther apart on an axis than the boxes could make up (DoublePath.apart)
    (l0, h0), (l1, h1) = (path.enclosure(r + 1, r) for r in (k - 1, k))
    return all(l0[a] - h1[a] < DROPPED_BELOW and l1[a] - h0[a] < DROPPED_BELOW for a in l0)


def _kinds(path: Any) -> dict[str, dict[str, Any]]:
    """The profile's motions by kind, as the other lanes report them (none decided one by one)."""
    counts = (("arc", getattr(path, "arcs", 0)), ("line", path.lines), ("rapid", path.rapids),
              ("dwell", getattr(path, "dwells", 0)))
    return {kind: {"motions": n, "seconds_one_by_one": 0.0} for kind, n in counts if n}


def _max_boxes(path: Any) -> int:
    motions: int = path.motions - getattr(path, "row0", 0)
    return max(64, motions // 16)


def prove_double_path(path: Any, machine: Machine, margin: Fraction, started: float | None = None,
                      windows: WindowProof | None = None) -> Result | None:
    """A ``safe`` result for the double pass's path (:func:`nczones.gcode.linuxcnc.doubles.double_pass`), or None when
    its boxes do not prove the program (the caller then runs the full path).  ``started`` is when the pass
    began (:func:`time.perf_counter`), for the timings; ``windows`` the proof of the windows the pass handed
    over before ``path``, its last."""
    from ..gcode.runner_common import assumed_modal_notes
    from .solver_version import z3_version

    if declares_solids(machine):
        return None  # the boxes are about the controlled point; tool solids need the full path
    if started is None:
        started = time.perf_counter()
    boxes = prove_enclosures(path, machine, margin, max_boxes=_max_boxes(path))
    if boxes is None:
        return None
    if windows is not None:
        boxes += windows.boxes
    n = path.motions
    stats = (("segments", n), ("pieces", 0), ("screened", n), ("exact_decided", 0), ("z3_segments", 0),
             ("z3_queries", 0), ("double_pass_boxes", boxes))
    seconds = time.perf_counter() - started
    profile = {"total_s": round(seconds, 6), "motions": n, "blocks": path.blocks,
               "motions_screened_vectorized": 0, "double_pass": {"motions": n, "boxes": boxes},
               "tiers": {"screen_vectorized_s": 0.0, "exact_per_motion_s": 0.0, "solver_s": 0.0,
                         "interpretation_and_rest_s": round(seconds, 6)},
               "kinds": _kinds(path), "solver": {"calls": 0, "seconds": 0.0, "stopped": {}}, "slowest": []}
    counts = {"blocks": path.blocks, "segments": n, "fast_lines": 0, "line": path.lines,
              "arc": getattr(path, "arcs", 0), "rapid": path.rapids, "dwell": getattr(path, "dwells", 0), "developed_arc": 0, "spline": 0,
              "polar": 0}
    # the full path's notes of the program (the pass's invariant: no others): the modal groups it assumed
    notes = tuple(assumed_modal_notes(getattr(path, "assumed", ()), machine.modal, "linuxcnc"))
    return Result(verdict=Verdict.SAFE, solver="z3", solver_version=z3_version(), notes=notes,
                  timings=(("prove_s", seconds),), stats=stats, margin=margin, engine="auto",
                  extra={"counts": counts, "splits": ()}, profile=profile)
