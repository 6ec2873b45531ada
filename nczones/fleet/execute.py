"""Executors: where the tasks of a fleet run are verified.

* :class:`SerialExecutor` runs them one after the other in this process
  (``--serial``, small re-runs, and the reference the tests compare with);
* :class:`DaskExecutor` submits them to a Dask distributed cluster — a
  ``LocalCluster`` with one single-threaded worker process per core started
  for the run, or an existing scheduler (``--scheduler tcp://host:8786`` or
  ``DASK_SCHEDULER_ADDRESS``) — and hands results back as they finish.

Both have the same interface: :meth:`submit` a task (a dict for
:func:`~nczones.fleet.work.run_task`), then iterate :meth:`results` for
``(task, answer)`` pairs; more tasks may be submitted while iterating.
A task whose worker died (``KilledWorker``, a lost connection) is
submitted again, up to ``attempts`` times in all; after that its answer
is the exception.
"""

from __future__ import annotations

import logging
import os
import warnings
from collections import deque
from collections.abc import Iterator
from typing import Any

from .work import run_task

__all__ = ["SerialExecutor", "DaskExecutor", "local_cluster", "connect", "DEFAULT_ATTEMPTS"]

#: How often a task is tried when its worker dies under it.
DEFAULT_ATTEMPTS = 3


class SerialExecutor:
    """Runs every task in this process, in submission order."""

    name = "serial"

    def __init__(self) -> None:
        self._queue: deque[dict[str, Any]] = deque()

    def submit(self, task: dict[str, Any]) -> None:
        self._queue.append(task)

    def results(self) -> Iterator[tuple[dict[str, Any], dict[str, Any] | BaseException, int]]:
        while self._queue:
            task = self._queue.popleft()
            yield task, run_task(task), 1

    def cancel(self) -> None:
        self._queue.clear()

    def close(self) -> None:
        self.cancel()


def _lost_worker_errors() -> tuple[type[BaseException], ...]:
    from distributed import KilledWorker
    from distributed.comm.core import CommClosedError

    return (KilledWorker, CommClosedError, ConnectionError, OSError)


class DaskExecutor:
    """Submits tasks to a Dask ``Client`` and yields their answers as they complete.

    Large payloads (a chunk's text, a long program's bytes) are scattered to
    the cluster first so the task graph stays small.
    """

    def __init__(self, client: Any, *, attempts: int = DEFAULT_ATTEMPTS, name: str = "dask",
                 cluster: Any = None):
        from distributed import as_completed

        self.client = client
        self.cluster = cluster
        self.attempts = attempts
        self.name = name
        self._done = as_completed([], with_results=False)
        self._tasks: dict[str, tuple[dict[str, Any], int]] = {}
        self._lost = _lost_worker_errors()
        self._count = 0

    @property
    def workers(self) -> int:
        return len(self.client.scheduler_info(n_workers=-1).get("workers", {}))

    def submit(self, task: dict[str, Any], attempt: int = 1) -> None:
        payload = dict(task)
        for field in ("text", "program_data"):
            value = payload.get(field)
            if value is not None and len(value) > 1 << 20:
                payload[field] = self.client.scatter(value, hash=False)
        self._count += 1
        key = f"nczones-{task['kind']}-{task['key'][:16]}-{task.get('index', 0)}-{attempt}-{self._count}"
        future = self.client.submit(run_task, payload, key=key, pure=False)
        self._tasks[future.key] = (task, attempt)
        self._done.add(future)

    def results(self) -> Iterator[tuple[dict[str, Any], dict[str, Any] | BaseException, int]]:
        for future in self._done:
            task, attempt = self._tasks.pop(future.key)
            try:
                answer = future.result()
            except self._lost as exc:
                if attempt < self.attempts:
                    self.submit(task, attempt + 1)
                    continue
                yield task, exc, attempt
                continue
            except Exception as exc:  # noqa: BLE001 - reported per task by the caller
                yield task, exc, attempt
                continue
            finally:
                future.release()
            yield task, answer, attempt

    def cancel(self) -> None:
        futures = list(self._done.futures)
        self._done.clear()
        self._tasks.clear()
        if futures:
            try:
                self.client.cancel(futures, force=True)
            except Exception:  # noqa: BLE001 - best effort while stopping
                pass

    def close(self) -> None:
        self.cancel()
        try:
            self.client.close(timeout=5)
        finally:
            if self.cluster is not None:
                self.cluster.close(timeout=5)


def local_cluster(workers: int | None = None, *, attempts: int = DEFAULT_ATTEMPTS) -> DaskExecutor:
    """A ``LocalCluster`` with ``workers`` single-threaded worker processes (default: one per core)."""
    from distributed import Client, LocalCluster

    n = workers if workers is not None else (os.cpu_count() or 1)
    with warnings.catch_warnings():
        # the scheduler's HTTP endpoint moves to a free port when another cluster holds 8787: not news
        warnings.filterwarnings("ignore", message=r"Port \d+ is already in use", category=UserWarning)
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None,
                               silence_logs=logging.ERROR)
    client = Client(cluster)
    return DaskExecutor(client, attempts=attempts, name=f"local cluster ({n} workers)", cluster=cluster)


def connect(address: str, *, attempts: int = DEFAULT_ATTEMPTS, timeout: float = 5) -> DaskExecutor:
    """A :class:`DaskExecutor` on an existing scheduler (``tcp://host:8786``)."""
    from distributed import Client

    try:
        client = Client(address, timeout=timeout)
    except (OSError, TimeoutError, ValueError) as exc:
        from ..errors import Diagnostic, InputError

        raise InputError(Diagnostic("FL111", f"cannot reach the Dask scheduler at {address}: {exc}",
                                    file="<command line>")) from None
    return DaskExecutor(client, attempts=attempts, name=f"dask scheduler {address}")
