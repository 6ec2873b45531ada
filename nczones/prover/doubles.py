"""``safe`` from the double pass (:mod:`nczones.gcode.doubles`, run by :mod:`nczones.pipeline`): boxes that hold
the motion, proved exactly.

The double pass gives every motion's end point as doubles with a bound on its distance from the full
path's exact point, and :meth:`~nczones.gcode.doubles.DoublePath.enclosure` turns a run of motions into an
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
from typing import Any

from ..machine import Machine
from .exact import box_fits
from .result import Result, Verdict

__all__ = ["prove_enclosures", "prove_double_path"]

#: A box that does not fit is split into this many.
SPLIT = 16
#: Motions per box at first (after the whole program's box).
FIRST_BOX = 4096


def prove_enclosures(path: Any, machine: Machine, margin: Fraction, max_boxes: int) -> int | None:
    """The number of boxes that proved every motion of ``path`` fits ``machine`` with ``margin``, or None when
    a single motion's box does not fit or more than ``max_boxes`` boxes would be needed.

    The whole program's box first; a box that does not fit is split in :data:`SPLIT` (the first time, in
    boxes of :data:`FIRST_BOX` motions).
    """
    allowed = machine.allowed
    zero = Fraction(0)
    todo = [(1, path.motions)] if path.motions else []
    boxes = 0
    while todo:
        first, last = todo.pop()
        boxes += 1
        if boxes > max_boxes:
            return None
        lo, hi = path.enclosure(first, last)
        if box_fits(allowed, lo, hi, margin, zero):
            continue
        if first == last:
            return None
        n = last - first + 1
        size = FIRST_BOX if n > FIRST_BOX * SPLIT and first == 1 and last == path.motions else -(-n // SPLIT)
        todo.extend((a, min(a + size - 1, last)) for a in range(first, last + 1, size))
    return boxes


def prove_double_path(path: Any, machine: Machine, margin: Fraction, started: float | None = None) -> Result | None:
    """A ``safe`` result for the double pass's path (:func:`nczones.gcode.doubles.double_pass`), or None when
    its boxes do not prove the program (the caller then runs the full path).  ``started`` is when the pass
    began (:func:`time.perf_counter`), for the timings."""
    from ..solids import machine_solids
    from .smt import z3_version

    if machine_solids(machine) is not None:
        return None  # the boxes are about the controlled point; tool solids need the full path
    if started is None:
        started = time.perf_counter()
    boxes = prove_enclosures(path, machine, margin, max_boxes=max(64, path.motions // 16))
    if boxes is None:
        return None
    n = path.motions
    stats = (("segments", n), ("pieces", 0), ("screened", n), ("exact_decided", 0), ("z3_segments", 0),
             ("z3_queries", 0), ("double_pass_boxes", boxes))
    seconds = time.perf_counter() - started
    profile = {"total_s": round(seconds, 6), "motions": n, "blocks": path.blocks,
               "motions_screened_vectorized": 0, "double_pass": {"motions": n, "boxes": boxes},
               "tiers": {"screen_vectorized_s": 0.0, "exact_per_motion_s": 0.0, "solver_s": 0.0,
                         "interpretation_and_rest_s": round(seconds, 6)},
               "kinds": {}, "solver": {"calls": 0, "seconds": 0.0, "stopped": {}}, "slowest": []}
    counts = {"blocks": path.blocks, "segments": n, "fast_lines": 0, "line": path.lines, "rapid": path.rapids}
    return Result(verdict=Verdict.SAFE, solver="z3", solver_version=z3_version(),
                  timings=(("prove_s", seconds),), stats=stats, margin=margin, engine="auto",
                  extra={"counts": counts, "splits": ()}, profile=profile)
