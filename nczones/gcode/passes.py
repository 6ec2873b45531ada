"""Bounds on the passes a lathe cycle generates (no run is unbounded).

A multiple repetitive cycle (Fanuc G71-G76, LinuxCNC G70-G72) expands one block into passes whose number
follows from its words: ``G71 U0.001`` from X800 would make about 385,000 roughing passes.  The generators take a
:class:`PassGuard`: they count the passes against ``max_loop_iterations`` (``--max-iterations``) before
making them where the count is known up front (and as they go where it is not), and ask the watched run's
budget (``--budget``) at every pass.  Past either, :class:`PassBound` ends the cycle; the interpreter turns
it into ``unknown`` with its code (the cycle's name for the count, ``VF203`` for the budget).
"""

from __future__ import annotations

from collections.abc import Callable

from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

__all__ = ["PassBound", "PassGuard"]


class PassBound(Exception):
    """A cycle stopped by a bound: ``code`` (the cycle's name, or VF203 for the budget) and the reason."""

    def __init__(self, code: str, reason: str):
        super().__init__(reason)
        self.code = code
        self.reason = reason


@dataclass(frozen=True)
class PassGuard:
    """The bounds of one cycle block ``name``: at most ``max_passes`` passes (per counted kind), and
    ``spent()`` (the reason the run's budget is spent, or None) asked at every pass."""

    name: str
    max_passes: int
    spent: Callable[[], str | None] = lambda: None

    def count(self, what: str, n: int, *, at_least: bool = False) -> None:
        """Raise :class:`PassBound` when the cycle would make ``n`` ``what`` (more than ``max_passes``;
        ``at_least``: ``n`` is a lower bound of the count)."""
        if n > self.max_passes:
            raise PassBound(self.name, f"the cycle would make {'at least ' if at_least else ''}{n} {what}, more than "
                                       f"{self.max_passes} "
                                       "(max_loop_iterations, --max-iterations); not interpreted further")

    def tick(self, what: str) -> None:
        """At every pass: raise :class:`PassBound` (VF203) once the run's budget is spent."""
        why = self.spent()
        if why is not None:
            raise PassBound("VF203", f"{why}: {self.name} had made {what}; not interpreted further")
