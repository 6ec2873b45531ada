"""Where a verification's time goes (``nczones verify --stats``, the JSON report's ``stats.profile``).

:class:`RunProfile` counts, while the prover runs, the motions and blocks
executed so far (the progress bar shows them: loops and subroutines count as
they run), the seconds of each tier and of each motion kind, the solver's
calls, and keeps the slowest blocks with their lines.  It only observes: a
run's verdict never depends on it.
"""

from __future__ import annotations

import time
from collections.abc import Callable

from ..motion import MotionChunk, Segment, SegmentKind

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["RunProfile", "kind_label"]


def kind_label(seg: Segment) -> str:
    """``line``, ``rapid``, ``arc``, ``helix``, ``dwell``, ``developed_arc`` or ``spline``.

    >>> from fractions import Fraction as F
    >>> kind_label(Segment(SegmentKind.RAPID, (F(0),), (F(1),), ("X",)))
    'rapid'
    """
    if seg.kind is SegmentKind.ARC:
        return "helix" if seg.is_helix() else "arc"
    return seg.kind.name.lower()


class RunProfile:
    """Counters and clocks of one verification run (see the module docstring).

    Examples
    --------
    >>> from fractions import Fraction as F
    >>> p = RunProfile(slowest=2)
    >>> seg = Segment(SegmentKind.LINE, (F(0),), (F(1),), ("X",), block=4)
    >>> p.decided(seg, 0.5); p.decided(seg, 0.25)
    >>> p.motions, p.blocks, p.kinds["line"]
    (2, 5, [2, 0.75])
    """

    def __init__(self, slowest: int = 10, clock: Callable[[], float] = time.perf_counter):
        self.clock = clock
        self.started = clock()
        self.motions = 0
        self.blocks = 0
        self.kinds: dict[str, list] = {}  # label -> [motions, seconds deciding them one by one]
        self.screen_s = 0.0
        self.screened_rows = 0
        self.decide_s = 0.0
        self._solvers: list[tuple[int, float, dict[str, int]]] = []  # (calls, seconds, stopped) of finished runs
        self._slowest_n = slowest
        self._slowest: list[tuple[float, int, int, int | None, str]] = []  # a min-heap once full
        self._heapreplace: Any = None  # heapq.heapreplace, once the heap is full
        self._n = 0

    def screened(self, chunk: MotionChunk, flagged: int, seconds: float) -> None:
        """A column chunk went through the vectorized screen (``flagged`` rows were not proved)."""
        n = len(chunk)
        self.screen_s += seconds
        self.screened_rows += n - flagged
        if n and chunk.block is not None and chunk.kind is not None:
            import numpy as np  # a column chunk exists only once numpy is loaded

            self.blocks = max(self.blocks, int(chunk.block[-1]) + 1)
            counts = np.bincount(chunk.kind.astype(np.int64), minlength=len(SegmentKind))
            for k, c in enumerate(counts.tolist()):
                if c:
                    label = SegmentKind(k).name.lower()
                    entry = self.kinds.setdefault(label, [0, 0.0])
                    entry[0] += c
            self.motions += n  # the flagged rows are decided one by one, counted here

    def decided(self, seg: Segment, seconds: float, counted: bool = True) -> None:
        """One motion was decided on its own (exact tiers, solver, refinement) in ``seconds``."""
        label = kind_label(seg)
        entry = self.kinds.setdefault(label, [0, 0.0])
        if counted:
            entry[0] += 1
            self.motions += 1
        entry[1] += seconds
        self.decide_s += seconds
        self.blocks = max(self.blocks, seg.block + 1)
        self._n += 1
        item = (seconds, self._n, seg.block, seg.line, label)
        if len(self._slowest) < self._slowest_n:  # a list until it is full, then a heap (heapq: issue 36)
            self._slowest.append(item)
            if len(self._slowest) == self._slowest_n:
                import heapq

                self._heapreplace = heapq.heapreplace
                heapq.heapify(self._slowest)
        elif seconds > self._slowest[0][0]:
            self._heapreplace(self._slowest, item)

    def slowest(self) -> list[dict]:
        """The slowest motions decided one by one, slowest first."""
        return [{"block": b, "line": line, "kind": k, "seconds": round(s, 6)}
                for s, _, b, line, k in sorted(self._slowest, reverse=True)]

    @staticmethod
    def _solver_work(solver: Any) -> tuple[int, float, dict[str, int]]:
        return (getattr(solver, "queries", 0), getattr(solver, "seconds", 0.0),
                dict(getattr(solver, "stopped", {})))

    def solver_done(self, solver: Any) -> None:
        """A prover's run ended: its solver's calls, seconds and stops count in every later summary
        (a program proved as several cases or block-delete positions has one profile)."""
        self._solvers.append(self._solver_work(solver))

    def as_dict(self, solver: Any = None, total_s: float | None = None) -> dict[str, Any]:
        """The profile for reports: tiers, kinds, solver, slowest (seconds rounded to microseconds).

        ``solver``: the running prover's solver; its work is added to that of the
        finished runs (:meth:`solver_done`).
        """
        total = self.clock() - self.started if total_s is None else total_s
        runs = self._solvers + ([] if solver is None else [self._solver_work(solver)])
        calls = sum(c for c, _, _ in runs)
        solver_s = sum(s for _, s, _ in runs)
        stopped: dict[str, int] = {}
        for _, _, st in runs:
            for k, v in st.items():
                stopped[k] = stopped.get(k, 0) + v
        tiers = {
            "screen_vectorized_s": round(self.screen_s, 6),
            "exact_per_motion_s": round(max(0.0, self.decide_s - solver_s), 6),
            "solver_s": round(solver_s, 6),
            "interpretation_and_rest_s": round(max(0.0, total - self.screen_s - self.decide_s), 6),
        }
        return {
            "total_s": round(total, 6),
            "motions": self.motions,
            "blocks": self.blocks,
            "motions_screened_vectorized": self.screened_rows,
            "tiers": tiers,
            "kinds": {k: {"motions": v[0], "seconds_one_by_one": round(v[1], 6)} for k, v in sorted(self.kinds.items())},
            "solver": {"calls": calls, "seconds": round(solver_s, 6), "stopped": dict(sorted(stopped.items()))},
            "slowest": self.slowest(),
        }
