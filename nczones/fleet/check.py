"""``fleet check``: plan the jobs, verify what the store does not have, record the run.

The incremental rule: a cell whose job key is in the store is reused; only
jobs with a new key run.  Change one machine file and only its cells get
new keys; change one program and only its cells do.

Results are stored as they arrive.  Ctrl-C (KeyboardInterrupt) stops the
run: tasks still queued are cancelled, the run is recorded as interrupted
with its unfinished cells pending, and the interrupt goes on to the caller.
Ctrl-C is also noted when it arrives and checked after every result: a
KeyboardInterrupt that Python raises inside a finalizer (``__del__``) is
lost, the note is not.
"""

from __future__ import annotations

import hashlib
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, TextIO

from .jobs import Job, JobPlan, code_version, plan_jobs
from .project import Cell, Project
from .split import Chunk, combine, split_program
from .store import Store
from .work import machine_for, record

__all__ = ["CheckOptions", "CheckSummary", "run_check", "EXIT_BY_VERDICT"]

#: Exit status of a verdict, as ``nczones verify`` (errors are bad input).
EXIT_BY_VERDICT = {"unsafe": 1, "error": 2, "unknown": 3, "safe": 0}


@dataclass(frozen=True, slots=True)
class CheckOptions:
    """How a fleet run executes (none of this changes a verdict, so none of it is in a job key).

    ``executor``: ``"auto"`` (in this process when fewer than ``cluster_threshold`` jobs need to run or
    Dask, the ``[fleet]`` extra, is not installed; otherwise the first :data:`PROBE_JOBS` jobs run in
    this process and are timed, and a local Dask cluster takes the rest only when it is projected to win
    by :func:`projected_seconds`),
    ``"serial"``, ``"local"`` (always the local cluster) or a scheduler
    address.  ``split_lines``: split programs of more than twice that many
    lines where that is sound (None, the default: never; see
    :mod:`nczones.fleet.split` for when it pays).  ``transfer``: ``"paths"`` (workers read programs from the
    project folder; a shared file system), ``"bytes"`` (programs travel
    with the tasks) or ``"auto"`` (paths for local runs, bytes for a
    scheduler).
    """

    executor: str = "auto"
    workers: int | None = None
    split_lines: int | None = None  # None: verify every program whole
    transfer: str = "auto"
    cluster_threshold: int = 50
    attempts: int = 3
    progress: bool | None = None  # None: when standard error is a terminal


@dataclass(slots=True)
class CheckSummary:
    """What a run did: counts by verdict over the cells, jobs run and reused, time, interrupted or not."""

    run_id: int
    cells: int
    jobs: int
    ran: int = 0
    reused: int = 0
    split: int = 0
    fallbacks: int = 0
    retried: int = 0
    failed: int = 0
    wall_s: float = 0.0
    executor: str = ""
    interrupted: bool = False
    #: (jobs measured in this process, their wall seconds, jobs left) when ``"auto"`` measured first.
    probe: tuple[int, float, int] = (0, 0.0, 0)
    #: Why the executor was chosen, when it was chosen by measurement ("" otherwise).
    choice: str = ""
    verdicts: dict[str, int] = field(default_factory=dict)
    problems: list[str] = field(default_factory=list)

    @property
    def exit_code(self) -> int:
        for verdict in ("unsafe", "error", "unknown"):
            if self.verdicts.get(verdict):
                return EXIT_BY_VERDICT[verdict]
        return 0


class _Bar:
    """A one-line progress bar of finished jobs on a terminal."""

    def __init__(self, stream: TextIO, total: int, enabled: bool):
        self.stream, self.total, self.enabled = stream, total, enabled and total > 0
        self.done = 0
        self.counts: dict[str, int] = {}
        self.t0 = time.monotonic()
        self._last = 0.0
        self._width = 0

    def update(self, verdict: str) -> None:
        self.done += 1
        self.counts[verdict] = self.counts.get(verdict, 0) + 1
        now = time.monotonic()
        if not self.enabled or (now - self._last < 0.1 and self.done < self.total):
            return
        self._last = now
        frac = self.done / self.total
        elapsed = now - self.t0
        rate = self.done / elapsed if elapsed > 0 else 0.0
        eta = (self.total - self.done) / rate if rate > 0 else 0.0
        bad = ", ".join(f"{n} {v}" for v, n in sorted(self.counts.items()) if v != "safe")
        text = (f"fleet [{'#' * int(frac * 30):<30}] {self.done}/{self.total} jobs"
                f"{'; ' + bad if bad else ''}; {rate:.1f} jobs/s, {elapsed:.0f} s, about {eta:.0f} s left")
        self.stream.write("\r" + text.ljust(self._width))
        self.stream.flush()
        self._width = len(text)

    def close(self) -> None:
        if self.enabled and self._width:
            self.stream.write("\r" + " " * self._width + "\r")
            self.stream.flush()


def _task(project: Project, plan: JobPlan, job: Job, transfer: str) -> dict[str, Any]:
    task: dict[str, Any] = {
        "kind": "whole", "key": job.key, "program": job.program, "program_sha256": job.program_sha256,
        "machine_file": _machine_display(project, job.machine), "machine_text": plan.machine_text[job.machine],
        "machine_sha256": job.machine_sha256, "settings": list(job.settings), "root": str(project.root),
    }
    if transfer == "paths":
        task["program_path"] = str(project.root / job.program)
    else:
        try:
            task["program_data"] = (project.root / job.program).read_bytes()
        except OSError:
            task["program_path"] = str(project.root / job.program)  # the worker reports it
    return task


def _machine_display(project: Project, name: str) -> str:
    path = project.machine(name).file
    try:
        return path.relative_to(project.root).as_posix()
    except ValueError:
        return str(path)


def _split_tasks(project: Project, plan: JobPlan, job: Job, split_lines: int,
                 transfer: str = "bytes") -> list[dict[str, Any]] | None:
    """Chunk tasks for a long program that may be split (see :mod:`nczones.fleet.split`), else None."""
    try:
        data = (project.root / job.program).read_bytes()
    except OSError:
        return None
    if data.count(b"\n") < 2 * split_lines or hashlib.sha256(data).hexdigest() != job.program_sha256:
        return None
    import io

    from ..errors import InputError
    from ..gcode.source import read_stdin

    try:
        text = read_stdin(io.BytesIO(data)).text  # the bytes the key was computed from, decoded as a file is
        machine = machine_for(_machine_display(project, job.machine), plan.machine_text[job.machine],
                              job.machine_sha256)
        chunks = split_program(text, machine, dict(job.settings), split_lines)
    except InputError:
        return None  # verified whole, which reports the error
    if chunks is None:
        return None
    base = _task(project, plan, job, "paths")
    del base["program_path"]
    tasks = []
    for i, chunk in enumerate(chunks):
        task = dict(base, kind="chunk", index=i, count=len(chunks), chunk=chunk)
        if transfer == "paths":  # each worker reads the file and cuts its chunk: no program through the network
            task["program_path"] = str(project.root / job.program)
        else:
            task["text"] = chunk.text(text)
        tasks.append(task)
    return tasks


def run_check(project: Project, store: Store, options: CheckOptions = CheckOptions(), *,
              cells: Iterable[Cell] | None = None, force: bool = False, err: TextIO | None = None,
              make_executor: Callable[[CheckOptions, int], Any] | None = None) -> CheckSummary:
    """Verify every cell of ``project`` whose job is not in ``store`` (all of them with ``force``).

    ``make_executor(options, jobs_to_run)`` chooses the executor (default:
    :func:`choose_executor`); tests pass their own.
    """
    err = sys.stderr if err is None else err
    t0 = time.perf_counter()
    version = code_version()
    cell_list = list(project.cells() if cells is None else cells)
    plan = plan_jobs(project, cell_list, version)
    known = set() if force else store.known(plan.jobs)
    todo = [job for key, job in plan.jobs.items() if key not in known]
    run_id = store.begin_run(project, options.executor, version, len(cell_list), len(plan.jobs))
    summary = CheckSummary(run_id, len(cell_list), len(plan.jobs))
    rows: list[tuple[str, str, str | None, str, str | None, str | None]] = []
    for cell in cell_list:
        where = (cell.program, cell.machine)
        if where in plan.errors:
            rows.append((cell.program, cell.machine, None, "error", "error", plan.errors[where]))
        else:
            key = plan.cell_keys[where]
            rows.append((cell.program, cell.machine, key, "reused" if key in known else "pending", None, None))
    store.set_cells(run_id, rows)
    summary.problems.extend(plan.errors.values())
    summary.reused = sum(1 for k in plan.jobs if k in known)
    executor = None
    interrupted = False
    try:
        if todo:
            with _ctrl_c_noted() as ctrl_c:
                if make_executor is None and _may_measure(options, len(todo)):
                    todo = _probe(project, plan, todo, store, options, summary, err, ctrl_c)
                    executor = _measured_executor(options, summary)
                else:
                    executor = (make_executor or choose_executor)(options, len(todo))
                    summary.executor = executor.name
                if todo:
                    _execute(project, plan, todo, store, executor, options, summary, err, ctrl_c)
    except KeyboardInterrupt:
        interrupted = True
        _quiet_half_built_solver_contexts()
        raise
    finally:
        if executor is not None:
            try:
                executor.close()
            except Exception:  # noqa: BLE001 - closing a cluster must not hide the run's outcome
                pass
        store.commit()
        if interrupted:  # Ctrl-C may fall between a result's commit and its count: the store says what ran
            summary.ran = store.ran_jobs(run_id)
        summary.interrupted = interrupted
        summary.wall_s = time.perf_counter() - t0
        store.end_run(run_id, ran=summary.ran, reused=summary.reused, interrupted=interrupted,
                      partial=bool(summary.failed) or interrupted)
        for c in store.cells(run_id):
            v = c.verdict if c.status != "pending" else None
            if v is not None:
                summary.verdicts[v] = summary.verdicts.get(v, 0) + 1
    return summary


@contextmanager
def _ctrl_c_noted() -> Iterator[threading.Event]:
    """An event set by Ctrl-C (SIGINT), which still raises KeyboardInterrupt as before.

    Only in the main thread and only over Python's own handler (an ignored
    or otherwise handled SIGINT is left alone).
    """
    noted = threading.Event()
    previous = signal.getsignal(signal.SIGINT)
    if threading.current_thread() is not threading.main_thread() or previous is not signal.default_int_handler:
        yield noted
        return

    def handler(signum: int, frame: Any) -> None:
        noted.set()
        signal.default_int_handler(signum, frame)

    signal.signal(signal.SIGINT, handler)
    try:
        yield noted
    finally:
        signal.signal(signal.SIGINT, previous)


def _quiet_half_built_solver_contexts() -> None:
    """After Ctrl-C, a Z3 context interrupted in its constructor fails in ``__del__``; that is not news."""
    previous = sys.unraisablehook

    def hook(unraisable: Any) -> None:
        where = getattr(unraisable.object, "__qualname__", "")
        if where == "Context.__del__" and isinstance(unraisable.exc_value, AttributeError):
            return
        previous(unraisable)

    sys.unraisablehook = hook


def _have_dask() -> bool:
    """True when Dask's distributed scheduler is installed (the ``[fleet]`` extra)."""
    import importlib.util

    return importlib.util.find_spec("distributed") is not None


def choose_executor(options: CheckOptions, jobs: int) -> Any:
    """The executor for ``jobs`` tasks under ``options`` (see :class:`CheckOptions`)."""
    import os

    from .execute import SerialExecutor, connect, local_cluster

    how = options.executor
    if how == "auto":
        address = os.environ.get("DASK_SCHEDULER_ADDRESS")
        if address:
            how = address
        elif jobs < options.cluster_threshold or not _have_dask():
            how = "serial"  # without the [fleet] extra (Dask) "auto" runs in this process
        else:
            how = "local"
    if how == "serial":
        return SerialExecutor()
    if how == "local":
        return local_cluster(options.workers, attempts=options.attempts)
    return connect(how, attempts=options.attempts)


#: Jobs verified in this process before ``"auto"`` decides whether a local cluster can win (they count).
PROBE_JOBS = 8
#: Wall seconds a local cluster takes to start and import nczones in its workers, and the coordination
#: cost per task on top of the job itself (scheduler, client and transfer beside the workers).  Measured on a
#: 2-core machine: 4.2-5.6 s to start; 1,020 jobs of 85 ms (wall, serial) took 105 s on two workers, 103 ms a
#: job instead of 42.5, so about 60 ms per task (specs/fleet.md, "Choosing the executor").
CLUSTER_START_S = 5.0
TASK_OVERHEAD_S = 0.06
#: The cluster must be projected to take at most this fraction of the serial time to be chosen.
CLUSTER_MUST_WIN = 0.8


def _may_measure(options: CheckOptions, jobs: int) -> bool:
    """True when ``"auto"`` would start a local cluster: then the first jobs are measured first."""
    import os

    return (options.executor == "auto" and not os.environ.get("DASK_SCHEDULER_ADDRESS")
            and jobs >= options.cluster_threshold and _have_dask() and options.split_lines is None)


def _probe(project: Project, plan: JobPlan, todo: list[Job], store: Store, options: CheckOptions,
           summary: CheckSummary, err: TextIO, ctrl_c: threading.Event) -> list[Job]:
    """Verify the first :data:`PROBE_JOBS` jobs in this process; note their wall time; the jobs left."""
    from .execute import SerialExecutor

    first, rest = todo[:PROBE_JOBS], todo[PROBE_JOBS:]
    t0 = time.perf_counter()
    _execute(project, plan, first, store, SerialExecutor(), options, summary, err, ctrl_c)
    summary.probe = (len(first), time.perf_counter() - t0, len(rest))
    return rest


def projected_seconds(job_s: float, jobs: int, workers: int) -> tuple[float, float]:
    """(serial, local cluster) wall seconds projected for ``jobs`` jobs of ``job_s`` seconds each.

    >>> projected_seconds(0.085, 1000, 2)   # the bundled-library measurement: the cluster loses
    (85.0, 107.5)
    >>> projected_seconds(1.0, 1000, 2)[1] < 0.8 * 1000   # second-long jobs: it wins
    True
    """
    serial = job_s * jobs
    cluster = CLUSTER_START_S + jobs * (job_s / max(1, workers) + TASK_OVERHEAD_S)
    return round(serial, 6), round(cluster, 6)


def _measured_executor(options: CheckOptions, summary: CheckSummary) -> Any:
    """The executor for the jobs left after the probe: a local cluster only where it is projected to win."""
    import os

    from .execute import SerialExecutor, local_cluster

    measured, seconds, rest = summary.probe
    workers = min(options.workers or os.cpu_count() or 1, os.cpu_count() or 1)
    serial, cluster = projected_seconds(seconds / max(1, measured), rest, workers)
    executor: Any
    if rest and cluster < CLUSTER_MUST_WIN * serial:
        executor = local_cluster(options.workers, attempts=options.attempts)
        why = "a local cluster is projected to win"
    else:
        executor = SerialExecutor()
        why = "a local cluster cannot win"
    summary.executor = executor.name
    summary.choice = (f"measured {seconds / max(1, measured) * 1000:.0f} ms a job over the first {measured}: "
                      f"{why} ({rest} jobs left: {serial:.1f} s serial, {cluster:.1f} s projected on "
                      f"{workers} worker{'s' if workers != 1 else ''} with its start)")
    return executor


def _execute(project: Project, plan: JobPlan, todo: list[Job], store: Store, executor: Any,
             options: CheckOptions, summary: CheckSummary, err: TextIO,
             ctrl_c: threading.Event | None = None) -> None:
    transfer = options.transfer
    if transfer == "auto":
        transfer = "paths" if executor.name == "serial" or executor.name.startswith("local") else "bytes"
    bar = _Bar(err, len(todo), err.isatty() if options.progress is None else options.progress)
    chunks: dict[str, list[tuple[Any, Chunk] | None]] = {}
    attempts: dict[str, int] = {}
    version = code_version()
    try:
        for job in todo:
            tasks = (None if options.split_lines is None
                     else _split_tasks(project, plan, job, options.split_lines, transfer))
            if tasks is None:
                executor.submit(_task(project, plan, job, transfer))
                continue
            summary.split += 1
            chunks[job.key] = [None] * len(tasks)
            for t in tasks:
                executor.submit(t)
        for task, answer, attempt in executor.results():
            if ctrl_c is not None and ctrl_c.is_set():
                raise KeyboardInterrupt  # Ctrl-C came, but its exception was lost on the way
            key = task["key"]
            job = plan.jobs[key]
            attempts[key] = max(attempts.get(key, 1), attempt)
            if attempt > 1:
                summary.retried += 1
            if isinstance(answer, BaseException):
                message = f"{job.program} on {job.machine}: the task failed: {type(answer).__name__}: {answer}"
                _fail(store, summary, key, message)
                chunks.pop(key, None)
                bar.update("error")
                continue
            if answer.get("version") != version:
                _fail(store, summary, key, f"{job.program} on {job.machine}: the worker {answer.get('worker')} "
                                           f"runs {answer.get('version')}, this run needs {version}; install the "
                                           "same nczones on every worker")
                chunks.pop(key, None)
                bar.update("error")
                continue
            if task["kind"] == "chunk":
                parts = chunks.get(key)
                if parts is None:
                    continue  # the job already fell back to a whole verification
                if "result" not in answer:
                    chunks.pop(key)
                    summary.fallbacks += 1
                    executor.submit(_task(project, plan, job, transfer))
                    continue
                parts[task["index"]] = (answer["result"], task["chunk"])
                if any(p is None for p in parts):
                    continue
                done = [p for p in parts if p is not None]
                max_violations = int(dict(job.settings).get("max_violations", 20))
                combined = combine(done, max_violations, job.program_sha256)
                chunks.pop(key)
                if combined is None:
                    summary.fallbacks += 1
                    executor.submit(_task(project, plan, job, transfer))
                    continue
                wall = sum(float(dict(r.timings).get("total_s", 0.0)) for r, _ in done)
                rec = record(combined, job.program, wall, chunks=len(done))
                worker = ",".join(sorted({a for a in [answer["worker"]]}))
            else:
                rec = answer["record"]
                worker = answer["worker"]
                if rec["verdict"] == "error" and rec["reasons"] and rec["reasons"][0].get("code") == "FL201":
                    _fail(store, summary, key, rec["reasons"][0]["message"])
                    bar.update("error")
                    continue
            store.put(job, rec, attempts=attempts.get(key, 1), worker=worker, commit=False)
            store.finish_cells(summary.run_id, key, rec["verdict"])
            store.commit()
            summary.ran += 1
            bar.update(rec["verdict"])
    except KeyboardInterrupt:
        store.rollback()  # a result put but its cells not yet marked: neither is kept
        executor.cancel()
        raise
    finally:
        bar.close()


def _fail(store: Store, summary: CheckSummary, key: str, message: str) -> None:
    store.fail_cells(summary.run_id, key, message)
    store.commit()
    summary.failed += 1
    summary.problems.append(message)
