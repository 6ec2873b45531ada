"""Bounds on a verification run: per-query solver limits, the program's budget, Ctrl-C.

No run is unbounded (README, "Standards"):

* **Per query**: every Z3 call carries a deterministic resource limit
  (``rlimit``: :data:`LINEAR_RLIMIT` for linear queries,
  :data:`NONLINEAR_RLIMIT` for nonlinear ones).  Z3's nonlinear arithmetic
  counts its work unevenly (measured on R-format arc queries: 10 s for
  1,100,000 units, 30 s for 515,000; its ``qfnra-nlsat`` tactic 50 s for
  2,000,000 units), so a query also has a **time backstop**
  (``query_time_s``): a watchdog thread calls Z3's own interrupt when a
  query runs past it.  Linear queries and most nonlinear ones end long
  before either limit, so verdicts repeat run to run; a query stopped by the
  backstop says so in its reason (``VF202``).  The exact tiers
  (:mod:`nczones.prover.arcs`) keep nonlinear queries rare.
* **Per program**: a budget in seconds (``budget_s``, default
  :data:`DEFAULT_BUDGET_S`).  Once it is spent no solver query and no
  refinement is started any more (a running query is interrupted); the
  motions that would need one are ``unknown`` ("budget spent"), while the
  exact tiers (screens, exact line decisions) still check the rest of the
  program, so the report is complete for everything they decide.
* **Interpretation**: while a run is watched, the language layers and the
  interpreters ask :func:`nczones.gcode.program.interpretation_spent` at every repetition they
  make (a loop iteration, a jump back, a repeat of a subprogram call or of a
  canned cycle); once the budget is spent the interpretation ends there as
  ``unknown`` (``VF203``, naming the block and what it counted), so a
  program whose loops would run for hours (nested ``WHILE`` loops, each
  within ``--max-iterations``) ends within the budget too.  A straight-line
  program is never stopped by it: its length bounds its interpretation.
  The commands that interpret without proving (``simulate``, ``plot
  --no-verify``) bound their interpretation the same way through
  :func:`interpretation_budget` (their ``--budget``, default
  :data:`DEFAULT_BUDGET_S`).
* **Ctrl-C**: while a run is watched (:meth:`RunLimits.watch`, in the main
  thread), SIGINT reaches the watchdog through :func:`signal.set_wakeup_fd`;
  it interrupts the running Z3 query at once (Z3's interrupt: a Python
  signal handler cannot run while Z3 holds the main thread), and Python's
  own ``KeyboardInterrupt`` then stops the run; the prover turns it into a
  partial result marked ``interrupted``.  The watchdog thread (and the
  wake-up fd) start with the first solver query of the watched block: until
  then no query runs for it to stop, and Python's own handler stops the
  run (a small verify needs no query: no thread, no ``threading``, no
  ``signal`` module at its start, issue 36).

Invariant: a limit, a spent budget or an interrupt never yields ``safe`` for
the motion it stopped; it yields ``unknown`` with the reason (or, for an
interrupt, a partial result that says so).
"""

from __future__ import annotations

import _thread
import functools
import os
import time
from collections.abc import Callable, Iterator

from ..gcode.runner_common import WATCHED_LIMITS

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["RunLimits", "BudgetSpent", "interpretation_budget", "DEFAULT_BUDGET_S", "DEFAULT_QUERY_TIME_S", "LINEAR_RLIMIT",
           "NONLINEAR_RLIMIT"]

#: Seconds a program may spend on solver work and refinement (``--budget``).
DEFAULT_BUDGET_S = 60.0
#: Seconds after which one solver query is interrupted even if its rlimit was not reached.
DEFAULT_QUERY_TIME_S = 5.0
#: Resource limit of a linear query (Z3 ``rlimit`` units).
LINEAR_RLIMIT = 5_000_000
#: Resource limit of a nonlinear query (arcs, helices, R-format centres, products of parameters).
NONLINEAR_RLIMIT = 5_000_000


if TYPE_CHECKING:
    _Active = tuple[int, Any, "float | None", str]

def _contextmanager(steps: Callable[..., Iterator[Any]]) -> Callable[..., Any]:
    """:func:`contextlib.contextmanager` of ``steps``, made at the first call: a verify that asks no solver
    query never imports :mod:`contextlib` (18 classes, some 3 million instructions of its start-up, issue 36)."""
    made: list[Callable[..., Any]] = []

    @functools.wraps(steps)
    def manager(*args: Any, **kwargs: Any) -> Any:
        if not made:
            from contextlib import contextmanager

            made.append(contextmanager(steps))
        return made[0](*args, **kwargs)

    return manager


class BudgetSpent(Exception):
    """Raised inside the prover when the program's budget is spent (control flow, never shown)."""


class RunLimits:
    """The budget, the per-query backstop and the interrupt of one verification run.

    Parameters
    ----------
    budget_s : float or None
        Seconds for the whole run's solver work and refinement; None = no budget.
    query_time_s : float or None
        Backstop per solver query (seconds); None = rlimit only.
    clock : callable
        Monotonic seconds (tests pass a fake one).

    Examples
    --------
    >>> t = [0.0]
    >>> lim = RunLimits(budget_s=5, clock=lambda: t[0])
    >>> lim.budget_spent()
    False
    >>> t[0] = 5.5
    >>> lim.budget_spent(), round(lim.elapsed(), 1)
    (True, 5.5)
    """

    def __init__(self, budget_s: float | None = DEFAULT_BUDGET_S, query_time_s: float | None = DEFAULT_QUERY_TIME_S,
                 *, clock: Callable[[], float] = time.monotonic):
        if budget_s is not None and not budget_s > 0:
            from ..errors import InvalidArgument

            raise InvalidArgument(f"budget_s must be a positive number of seconds, got {budget_s!r}")
        self.budget_s = budget_s
        self.query_time_s = query_time_s
        self.clock = clock
        self.started = clock()
        self.spent_at: float | None = None
        self.interrupted = False
        self._lock = _thread.allocate_lock()  # threading.Lock, without importing threading (issue 36)
        self._active: _Active | None = None  # (sequence number, z3 context, deadline, why) of the running query
        self._seq = 0
        self._stopped: dict[int, str] = {}
        self._thread: Any = None  # the watchdog (threading.Thread), started by the first query of a watch
        self._watching = False
        self._old_fd: int | None = None
        self._wake: _Wake | None = None
        self._closing = False

    # ------------------------------------------------------------------ budget

    def elapsed(self) -> float:
        return self.clock() - self.started

    def budget_spent(self) -> bool:
        """True once the budget is spent (and from then on)."""
        if self.spent_at is not None:
            return True
        if self.budget_s is not None and self.elapsed() >= self.budget_s:
            self.spent_at = self.elapsed()
            return True
        return False

    def checkpoint(self) -> None:
        """Raise :class:`BudgetSpent` when no more solver or refinement work may start."""
        if self.budget_spent():
            raise BudgetSpent

    # ------------------------------------------------------------------ queries

    @_contextmanager
    def query(self, ctx: Any) -> Iterator[Callable[[], str]]:
        """Around one Z3 call on ``ctx``: the watchdog may interrupt it.

        Yields a function that tells, after the call, why it was stopped:
        ``"time"`` (the backstop), ``"budget"``, ``"interrupt"`` (Ctrl-C) or
        ``""`` (it was not stopped by us).
        """
        self.checkpoint()
        if self._watching and self._thread is None:
            self._start_watchdog()
        now = self.clock()
        deadline, why = None, "time"
        if self.query_time_s is not None:
            deadline = now + self.query_time_s
        if self.budget_s is not None:
            end = self.started + self.budget_s
            if deadline is None or end < deadline:
                deadline, why = end, "budget"
        with self._lock:
            self._seq += 1
            seq = self._seq
            self._active = (seq, ctx, deadline, why)
        try:
            yield lambda: self._stopped.get(seq, "")
        finally:
            with self._lock:
                self._active = None
                self._stopped.pop(seq, None)

    def _fire(self, reason: str, act: _Active | None = None) -> None:
        """Interrupt the running query (called by the watchdog); only ``act`` when given."""
        with self._lock:
            if act is not None and self._active is not act:
                return
            act = self._active
            if act is None:
                return
            seq, ctx, _, _ = act
            self._stopped[seq] = reason
            if reason == "budget":
                self.spent_at = self.elapsed()
            ctx.interrupt()

    # ------------------------------------------------------------------ watchdog

    def watch(self) -> _Watch:
        """Run the watchdog (backstop, budget, Ctrl-C) for the duration of the block (``with lim.watch():``).

        Ctrl-C is watched only when called from the main thread (where
        Python delivers signals); the previous wakeup fd is restored after
        and still receives the signal bytes.  The watchdog starts with the
        block's first solver query (:meth:`query`).
        """
        return _Watch(self)

    def _begin_watch(self) -> object:
        """What entering :meth:`watch`'s block does: the context token to reset, or None (nested: the outer watch
        does the work)."""
        if self._watching:
            return None
        token = WATCHED_LIMITS.set(self)
        self._watching = True
        return token

    def _end_watch(self, token: object) -> None:
        """What leaving :meth:`watch`'s block does (however it is left), given what :meth:`_begin_watch` gave."""
        if token is None:
            return
        self._watching = False
        try:
            if self._thread is not None:
                self._stop_watchdog()
        finally:
            WATCHED_LIMITS.reset(token)  # type: ignore[arg-type]

    def _start_watchdog(self) -> None:
        """Start the watchdog thread, with the wake-up fd where this is the main thread (the first query)."""
        import signal
        import threading

        self._old_fd = None
        try:  # set_wakeup_fd works only in the main thread (ValueError elsewhere)
            self._wake = _Wake()
            self._old_fd = signal.set_wakeup_fd(self._wake.w, warn_on_full_buffer=False)
        except (ValueError, OSError):
            if self._wake is not None:
                self._wake.close()
            self._wake = None
        self._closing = False
        self._thread = threading.Thread(target=self._watchdog, args=(self._old_fd,), name="nczones-limits",
                                        daemon=True)
        self._thread.start()

    def _stop_watchdog(self) -> None:
        """Stop the watchdog, the previous wake-up fd restored."""
        import signal

        self._closing = True
        if self._wake is not None:
            try:
                signal.set_wakeup_fd(self._old_fd if self._old_fd is not None else -1)
            except (ValueError, OSError):
                pass
            try:
                self._wake.write(b"\0")
            except OSError:
                pass
        self._thread.join(1.0)
        self._thread = None
        if self._wake is not None:
            self._wake.close()
            self._wake = None

    def _watchdog(self, old_fd: int | None) -> None:
        import select
        import signal

        wake = self._wake
        while not self._closing:
            with self._lock:
                act = self._active
            timeout = 0.25
            if act is not None and act[2] is not None:
                left = act[2] - self.clock()
                if left <= 0:
                    self._fire(act[3], act)
                else:
                    timeout = min(timeout, left)
            if wake is None:
                time.sleep(timeout)
                continue
            try:
                ready, _, _ = select.select([wake.r], [], [], timeout)
            except (OSError, ValueError):
                return
            if not ready:
                continue
            try:
                data = wake.read()
            except (BlockingIOError, OSError):
                data = b""
            data = data.replace(b"\0", b"")
            if old_fd is not None and old_fd >= 0 and data:
                try:
                    os.write(old_fd, data)
                except OSError:
                    pass
            if int(signal.SIGINT) in data or int(signal.SIGTERM) in data:  # SIGTERM: nczones.cli's handler
                self.interrupted = True
                self._fire("interrupt")


class _Wake:
    """The wake-up fd's pair (:func:`signal.set_wakeup_fd` writes the signal numbers to ``w``, the watchdog reads
    ``r``), both non-blocking: a pipe on POSIX (no ``socket`` import, about 4 ms of every verify's start); a socket
    pair where only a socket may be a wake-up fd (Windows)."""

    def __init__(self) -> None:
        self._pair: Any = None
        if os.name == "nt":
            import socket

            self._pair = socket.socketpair()
            for s in self._pair:
                s.setblocking(False)
            self.r, self.w = self._pair[0].fileno(), self._pair[1].fileno()
        else:
            self.r, self.w = os.pipe()
            os.set_blocking(self.r, False)
            os.set_blocking(self.w, False)

    def read(self) -> bytes:
        return bytes(self._pair[0].recv(64)) if self._pair is not None else os.read(self.r, 64)

    def write(self, data: bytes) -> None:
        if self._pair is not None:
            self._pair[1].send(data)
        else:
            os.write(self.w, data)

    def close(self) -> None:
        if self._pair is not None:
            for s in self._pair:
                s.close()
        else:
            os.close(self.r)
            os.close(self.w)


@_contextmanager
def interpretation_budget(budget_s: float | None = DEFAULT_BUDGET_S) -> Iterator[RunLimits]:
    """Bound the interpretation run inside the block by ``budget_s`` seconds (None: no bound), for the commands
    that interpret without proving (``simulate``, ``plot``): the interpreters' repetitions ask it as they ask
    :meth:`RunLimits.watch`'s budget and end as ``unknown`` (VF203) once it is spent.  No watchdog thread and
    no Ctrl-C handling: no solver query runs here.  A ``verify`` inside the block watches its own limits."""
    lim = RunLimits(budget_s=budget_s, query_time_s=None)
    token = WATCHED_LIMITS.set(lim)
    try:
        yield lim
    finally:
        WATCHED_LIMITS.reset(token)


class _Watch:
    """The block of :meth:`RunLimits.watch`: a class, not a :func:`contextlib.contextmanager` (every verify
    watches; :mod:`contextlib` is not imported for it, issue 36)."""

    __slots__ = ("limits", "token")

    def __init__(self, limits: RunLimits) -> None:
        self.limits = limits
        self.token: object = None

    def __enter__(self) -> RunLimits:
        self.token = self.limits._begin_watch()
        return self.limits

    def __exit__(self, *exc: object) -> None:
        self.limits._end_watch(self.token)

