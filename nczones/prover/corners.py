"""The corner proof of a run, loaded at its first corner (``nczones.prover.blend`` is imported only then).

A corner needs two motions: a program of one motion (the three lines a start-up measures, a single probe move)
has none that a control could round, and a verify of it need not import the corner check and its convex hull.
:class:`Corners` holds the motions it has seen until a second one comes (or a column chunk, which holds many),
then gives them, in order, to a :class:`nczones.prover.blend.CornerCheck` and follows the run with it: the
check sees exactly the motions it would have seen from the start, so its reasons are the same.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from ..motion import MotionChunk, Segment, SegmentKind

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["Corners"]

#: The kinds one motion alone never gives a reason for (only a Fanuc run's motion without a box does: it is
#: given to the check at the end).
_ALONE_SILENT = frozenset((SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.DWELL))


class Corners:
    """:class:`nczones.prover.blend.CornerCheck` (same arguments, ``watch`` and ``finish``), built at the first
    chunk that may hold a corner."""

    def __init__(self, *args: Any) -> None:
        self._args = args
        self.check: Any = None  # the CornerCheck, once built
        self._held: list[Segment] = []  # the motions (at most one that moves) and dwells seen before it
        self._moves = 0

    def watch(self, chunks: Iterable[Any]) -> Iterator[Any]:
        """The chunks unchanged; each one's corners proved as it passes (``CornerCheck.watch``)."""
        for chunk in chunks:
            yield chunk
            if self.check is None and self._hold(chunk):
                continue
            self.check.take(chunk)

    def _hold(self, chunk: Any) -> bool:
        """Keep ``chunk`` while the run has at most one motion (True); else build the check, give it what was
        kept (False: the caller gives it ``chunk``)."""
        if isinstance(chunk, MotionChunk) and chunk.scale is None:
            segs = list(chunk.objects or ())
        elif isinstance(chunk, Segment):
            segs = [chunk]
        else:  # a column chunk (or another kind of chunk): many motions
            self._build()
            return False
        moves = self._moves + sum(s.kind is not SegmentKind.DWELL for s in segs)
        if moves > 1:
            self._build()
            return False
        self._moves = moves
        self._held.extend(segs)
        return True

    def _build(self) -> None:
        from .blend import CornerCheck

        self.check = CornerCheck(*self._args)
        held, self._held = self._held, []
        for s in held:
            self.check.take(s)

    def finish(self, violating: Iterable[int] = (), upto: int | None = None) -> list[Any]:
        """``CornerCheck.finish``: no reason for a run of one line or rapid (no corner)."""
        if self.check is None:
            if all(s.kind in _ALONE_SILENT for s in self._held):
                return []
            self._build()
        reasons: list[Any] = self.check.finish(violating, upto)
        return reasons
