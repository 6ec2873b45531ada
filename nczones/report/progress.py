"""A progress bar on standard error for long verifications and simulations.

The prover's :func:`~nczones.prover.verify` and the controller's
:func:`~nczones.controller.simulate` accept an optional ``progress``
callable, called as ``progress(line, total)`` after each chunk or segment
with the source line reached so far and the number of lines of the program
(``total`` may be None when unknown); ``verify`` also passes ``motions=``
and ``blocks=`` (executed so far, loops and subroutines counted as they
run) to a callable whose ``counts`` attribute is true, as the bar's is.  :func:`progress_for` returns such a
callable that draws a bar when the stream is a terminal, and None otherwise,
so that redirected output, CI logs and pipes stay quiet.

Invariant: the bar only ever writes to its own stream, and only when that
stream is a terminal (or ``force`` is given); it never changes a result.
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, TextIO

__all__ = ["ProgressBar", "progress_for", "is_terminal", "item_last_line", "count_lines"]

Progress = Callable[[int, "int | None"], None]


def is_terminal(stream: Any) -> bool:
    """True when ``stream`` is an interactive terminal that is not ``TERM=dumb``.

    >>> import io
    >>> is_terminal(io.StringIO())
    False
    """
    try:
        tty = bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False
    return tty and os.environ.get("TERM", "") != "dumb"


def count_lines(text: str) -> int:
    """Number of lines of a program text (a last line without newline counts).

    >>> count_lines("G0 X1\\nG1 X2"), count_lines("G0 X1\\n"), count_lines("")
    (2, 1, 0)
    """
    if not text:
        return 0
    return text.count("\n") + (0 if text.endswith("\n") else 1)


def item_last_line(item: object) -> int | None:
    """The last source line of a :class:`~nczones.motion.Segment` or a MotionChunk (None if unknown).

    >>> from fractions import Fraction as F
    >>> from nczones.errors import SourceSpan
    >>> from nczones.motion import Segment, SegmentKind
    >>> seg = Segment(SegmentKind.LINE, (F(0),), (F(1),), ("X",), block=0, span=SourceSpan("p", 7))
    >>> item_last_line(seg)
    7
    """
    span = getattr(item, "span", None)
    if span is not None:
        return int(span.line)
    line = getattr(item, "line", None)
    if line is not None and getattr(item, "scale", None) is not None:
        return int(line[-1]) if len(line) else None
    objects = getattr(item, "objects", None)
    if objects:
        last = objects[-1].span
        return None if last is None else last.line
    return None


class ProgressBar:
    """A one-line progress bar drawn with carriage returns.

    Parameters
    ----------
    stream : text stream
        Where to draw (standard error in the CLI).
    label : str
        Shown before the bar (``verify``, ``simulate``).
    total : int, optional
        Default total when the callback gets None.
    min_interval : float
        Seconds between redraws (the callback may be called per segment).
    force : bool
        Draw even if ``stream`` is not a terminal (tests, ``--progress``).

    Examples
    --------
    >>> import io
    >>> s = io.StringIO()
    >>> bar = ProgressBar(s, "verify", total=4, min_interval=0, force=True, width=8)
    >>> bar(2, 4); bar.close()
    >>> s.getvalue().split("\\r")[1]
    'verify [####    ]  50% line 2/4'

    With the motions and blocks executed so far (what ``verify`` passes),
    it shows those, the elapsed time and the rate instead of a share of the
    source lines (a loop runs its lines many times):

    >>> t = iter([10.0, 12.0])
    >>> s = io.StringIO()
    >>> bar = ProgressBar(s, "verify", min_interval=0, force=True, clock=lambda: next(t))
    >>> bar(3, 4, motions=90000, blocks=45000)
    >>> s.getvalue().split("\\r")[-1]
    'verify 90,000 motions, 45,000 blocks (line 3/4) 2.0 s, 45,000 motions/s'
    """

    def __init__(self, stream: TextIO, label: str = "", *, total: int | None = None,
                 min_interval: float = 0.1, force: bool = False, width: int = 30,
                 clock: Callable[[], float] = time.monotonic):
        self.stream = stream
        self.label = label
        self.total = total
        self.min_interval = min_interval
        self.enabled = force or is_terminal(stream)
        self.width = width
        self.clock = clock
        self._last_draw = -float("inf")
        self._drawn = False
        self._last_text = ""
        self._started = clock()
        self.calls = 0

    #: :func:`nczones.prover.verify` passes ``motions=`` and ``blocks=`` to callables that say so
    counts = True

    def __call__(self, line: int | None, total: int | None = None, *, motions: int | None = None,
                 blocks: int | None = None) -> None:
        self.calls += 1
        if not self.enabled or line is None:
            return
        now = self.clock()
        total = total if total is not None else self.total
        if now - self._last_draw < self.min_interval and not (total and line >= total and motions is None):
            return
        self._last_draw = now
        if motions is not None:
            self._draw_counts(line, total, motions, blocks, now - self._started)
        else:
            self._draw(line, total)

    def _draw_counts(self, line: int, total: int | None, motions: int, blocks: int | None, elapsed: float) -> None:
        """Progress by execution: motions and blocks executed so far (loops and subroutines count as
        they run), the elapsed time and the rate; the source line only says where the run is."""
        rate = f", {motions / elapsed:,.0f} motions/s" if elapsed > 0 else ""
        where = f"line {line}/{total}" if total else f"line {line}"
        text = (f"{self.label} {motions:,} motions" + (f", {blocks:,} blocks" if blocks is not None else "")
                + f" ({where}) {elapsed:.1f} s{rate}")
        self._write(text)

    def _draw(self, line: int, total: int | None) -> None:
        if total:
            frac = min(max(line / total, 0.0), 1.0)
            filled = int(round(frac * self.width))
            text = (f"{self.label} [{'#' * filled}{' ' * (self.width - filled)}] "
                    f"{int(frac * 100):3d}% line {line}/{total}")
        else:
            text = f"{self.label} line {line}"
        self._write(text)

    def _write(self, text: str) -> None:
        pad = max(0, len(self._last_text) - len(text))
        self.stream.write("\r" + text + " " * pad)
        self.stream.flush()
        self._last_text = text
        self._drawn = True

    def close(self) -> None:
        """Erase the bar (leaves the terminal as it was)."""
        if self._drawn:
            self.stream.write("\r" + " " * len(self._last_text) + "\r")
            self.stream.flush()
            self._drawn = False


def progress_for(stream: TextIO | None = None, label: str = "", total: int | None = None,
                 *, force: bool = False) -> ProgressBar | None:
    """A :class:`ProgressBar` when ``stream`` (default ``sys.stderr``) is a terminal, else None.

    >>> import io
    >>> progress_for(io.StringIO(), "verify") is None
    True
    """
    stream = sys.stderr if stream is None else stream
    if not (force or is_terminal(stream)):
        return None
    return ProgressBar(stream, label, total=total, force=force)
