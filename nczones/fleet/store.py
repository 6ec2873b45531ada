"""The result store: an embedded SQLite database (``.nczones/results.sqlite``), schema version 1.

Tables (``specs/fleet.md`` has the full schema):

* ``meta`` — ``schema_version`` and who created the store;
* ``results`` — one row per job key: the verdict, violations, reasons,
  notes, timings, the keys it was computed from and its JSON and text
  reports (zlib-compressed);
* ``runs`` — one row per ``fleet check``: when, what ran, what was reused,
  whether it was interrupted;
* ``cells`` — the matrix of each run: (program, machine) -> job key and
  verdict, and whether the job ran, was reused, failed to start or is
  pending (an interrupted run).

A result is written (and committed) as soon as it arrives, so an
interrupted run keeps every finished job.  The store opens a store written
by an older schema version only after migrating it, and refuses a newer
one.
"""

from __future__ import annotations

import json
import sqlite3
import time
import zlib
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import Diagnostic, InputError

__all__ = ["SCHEMA_VERSION", "Store", "Run", "CellRow"]

SCHEMA_VERSION = 1

_SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (
    name TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS results (
    job_key TEXT PRIMARY KEY,
    program_sha256 TEXT NOT NULL,
    machine_sha256 TEXT NOT NULL,
    settings_sha256 TEXT NOT NULL,
    nczones_version TEXT NOT NULL,
    program TEXT NOT NULL,
    machine TEXT NOT NULL,
    settings_json TEXT NOT NULL,
    verdict TEXT NOT NULL CHECK (verdict IN ('safe', 'unsafe', 'unknown', 'error')),
    violation_count INTEGER NOT NULL,
    first_line INTEGER,
    violations_json TEXT NOT NULL,
    reasons_json TEXT NOT NULL,
    notes_json TEXT NOT NULL,
    truncated INTEGER NOT NULL,
    wall_s REAL NOT NULL,
    timings_json TEXT NOT NULL,
    stats_json TEXT NOT NULL,
    chunks INTEGER NOT NULL,
    attempts INTEGER NOT NULL,
    worker TEXT NOT NULL,
    finished_at REAL NOT NULL,
    report_json BLOB NOT NULL,
    report_text BLOB NOT NULL
);
CREATE TABLE IF NOT EXISTS runs (
    run_id INTEGER PRIMARY KEY AUTOINCREMENT,
    started_at REAL NOT NULL,
    finished_at REAL,
    project TEXT NOT NULL,
    project_sha256 TEXT NOT NULL,
    nczones_version TEXT NOT NULL,
    executor TEXT NOT NULL,
    cells INTEGER NOT NULL,
    jobs INTEGER NOT NULL,
    ran INTEGER NOT NULL DEFAULT 0,
    reused INTEGER NOT NULL DEFAULT 0,
    interrupted INTEGER NOT NULL DEFAULT 0,
    partial INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE IF NOT EXISTS cells (
    run_id INTEGER NOT NULL REFERENCES runs(run_id) ON DELETE CASCADE,
    program TEXT NOT NULL,
    machine TEXT NOT NULL,
    job_key TEXT,
    status TEXT NOT NULL CHECK (status IN ('ran', 'reused', 'error', 'pending')),
    verdict TEXT,
    message TEXT,
    PRIMARY KEY (run_id, program, machine)
);
CREATE INDEX IF NOT EXISTS cells_by_key ON cells(job_key);
"""

_RESULT_COLUMNS = ("job_key", "program_sha256", "machine_sha256", "settings_sha256", "nczones_version", "program",
                   "machine", "settings_json", "verdict", "violation_count", "first_line", "violations_json",
                   "reasons_json", "notes_json", "truncated", "wall_s", "timings_json", "stats_json", "chunks",
                   "attempts", "worker", "finished_at", "report_json", "report_text")


@dataclass(frozen=True, slots=True)
class Run:
    """One ``fleet check`` as the store recorded it."""

    run_id: int
    started_at: float
    finished_at: float | None
    project: str
    executor: str
    cells: int
    jobs: int
    ran: int
    reused: int
    interrupted: bool
    partial: bool


@dataclass(frozen=True, slots=True)
class CellRow:
    """A cell of a run's matrix, with its job's result when there is one."""

    program: str
    machine: str
    job_key: str | None
    status: str
    verdict: str | None
    message: str | None
    violations: tuple[dict[str, Any], ...]
    reasons: tuple[dict[str, Any], ...]
    wall_s: float | None


def _pack(text: str) -> bytes:
    return zlib.compress(text.encode("utf-8"), 6)


def _unpack(blob: bytes) -> str:
    return zlib.decompress(blob).decode("utf-8")


class Store:
    """The SQLite result store of a project (see the module docstring).

    >>> import tempfile, os
    >>> s = Store(os.path.join(tempfile.mkdtemp(), "r.sqlite"))
    >>> s.schema_version, s.has("0" * 64)
    (1, False)
    >>> s.close()
    """

    def __init__(self, path: str | Path, *, create: bool = True):
        self.path = Path(path)
        if not create and not self.path.is_file():
            raise InputError(Diagnostic("FL300", f"no result store at {self.path}: run 'nczones fleet check' "
                                                 "first", file=str(self.path)))
        self.path.parent.mkdir(parents=True, exist_ok=True)
        try:
            self.db = sqlite3.connect(str(self.path), timeout=30)
            self.db.execute("PRAGMA journal_mode=WAL")
            self.db.execute("PRAGMA synchronous=NORMAL")
            self.db.execute("PRAGMA foreign_keys=ON")
            self._migrate()
        except sqlite3.DatabaseError as exc:
            raise InputError(Diagnostic("FL301", f"{self.path}: not a result store this nczones can read "
                                                 f"({exc})", file=str(self.path))) from None

    def _migrate(self) -> None:
        with self.db:
            self.db.execute("CREATE TABLE IF NOT EXISTS meta (name TEXT PRIMARY KEY, value TEXT NOT NULL)")
            row = self.db.execute("SELECT value FROM meta WHERE name = 'schema_version'").fetchone()
            version = int(row[0]) if row else 0
            if version > SCHEMA_VERSION:
                raise sqlite3.DatabaseError(f"schema version {version} is newer than this nczones's "
                                            f"{SCHEMA_VERSION}; use a newer nczones")
            if version < 1:
                self.db.executescript(_SCHEMA)
                self.db.execute("INSERT OR REPLACE INTO meta VALUES ('schema_version', ?)", (str(SCHEMA_VERSION),))
                self.db.execute("INSERT OR REPLACE INTO meta VALUES ('created_at', ?)", (str(time.time()),))

    @property
    def schema_version(self) -> int:
        row = self.db.execute("SELECT value FROM meta WHERE name = 'schema_version'").fetchone()
        return int(row[0])

    def close(self) -> None:
        self.db.close()

    def __enter__(self) -> Store:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # results ---------------------------------------------------------------------------------

    def has(self, key: str) -> bool:
        return self.db.execute("SELECT 1 FROM results WHERE job_key = ?", (key,)).fetchone() is not None

    def known(self, keys: Iterable[str]) -> set[str]:
        """The keys among ``keys`` that have a result."""
        keys = list(keys)
        found: set[str] = set()
        for i in range(0, len(keys), 500):
            part = keys[i:i + 500]
            rows = self.db.execute(f"SELECT job_key FROM results WHERE job_key IN ({','.join('?' * len(part))})",
                                   part)
            found.update(r[0] for r in rows)
        return found

    def put(self, job: Any, rec: dict[str, Any], *, attempts: int, worker: str, commit: bool = True) -> None:
        """Store the record of a finished job (replaces a result with the same key)."""
        violations = rec["violations"]
        lines = [v.get("line") for v in violations if v.get("line") is not None]
        first_line = lines[0] if lines else None
        if first_line is None:
            for r in rec["reasons"]:
                loc = r.get("location")
                if isinstance(loc, dict) and loc.get("line") is not None:
                    first_line = loc["line"]
                    break
        row = (job.key, job.program_sha256, job.machine_sha256, job.settings_sha256, job.version, job.program,
               job.machine, json.dumps(dict(job.settings), sort_keys=True), rec["verdict"], len(violations),
               first_line, json.dumps(violations), json.dumps(rec["reasons"]), json.dumps(rec["notes"]),
               int(rec["truncated"]), float(rec["wall_s"]), json.dumps(rec["timings"]), json.dumps(rec["stats"]),
               int(rec["chunks"]), attempts, worker, time.time(), _pack(rec["report_json"]),
               _pack(rec["report_text"]))
        self.db.execute(f"INSERT OR REPLACE INTO results ({', '.join(_RESULT_COLUMNS)}) "
                        f"VALUES ({', '.join('?' * len(_RESULT_COLUMNS))})", row)
        if commit:
            self.db.commit()

    def result(self, key: str) -> dict[str, Any] | None:
        """The stored row of a job (JSON columns decoded, reports as text), or None."""
        cur = self.db.execute(f"SELECT {', '.join(_RESULT_COLUMNS)} FROM results WHERE job_key = ?", (key,))
        row = cur.fetchone()
        if row is None:
            return None
        out = dict(zip(_RESULT_COLUMNS, row))
        for k in ("violations_json", "reasons_json", "notes_json", "timings_json", "stats_json", "settings_json"):
            out[k[:-5]] = json.loads(out.pop(k))
        out["report_json"] = _unpack(out["report_json"])
        out["report_text"] = _unpack(out["report_text"])
        return out

    def results(self) -> Iterator[dict[str, Any]]:
        keys = [r[0] for r in self.db.execute("SELECT job_key FROM results ORDER BY job_key")]
        for key in keys:
            found = self.result(key)
            if found is not None:
                yield found

    def prune(self) -> int:
        """Delete results no cell of the latest run uses; returns how many."""
        latest = self.latest_run()
        if latest is None:
            return 0
        cur = self.db.execute("DELETE FROM results WHERE job_key NOT IN "
                              "(SELECT job_key FROM cells WHERE run_id = ? AND job_key IS NOT NULL)",
                              (latest.run_id,))
        self.db.commit()
        return cur.rowcount

    # runs and cells ------------------------------------------------------------------------

    def begin_run(self, project: Any, executor: str, version: str, cells: int, jobs: int) -> int:
        cur = self.db.execute("INSERT INTO runs (started_at, project, project_sha256, nczones_version, executor, "
                              "cells, jobs) VALUES (?, ?, ?, ?, ?, ?, ?)",
                              (time.time(), str(project.file), project.sha256, version, executor, cells, jobs))
        self.db.commit()
        run_id = cur.lastrowid
        assert run_id is not None
        return run_id

    def set_cells(self, run_id: int, rows: Iterable[tuple[str, str, str | None, str, str | None, str | None]]) -> None:
        """(program, machine, job_key, status, verdict, message) rows of a run."""
        self.db.executemany("INSERT OR REPLACE INTO cells VALUES (?, ?, ?, ?, ?, ?, ?)",
                            [(run_id, *r) for r in rows])
        self.db.commit()

    def finish_cells(self, run_id: int, key: str, verdict: str) -> None:
        """Every pending cell of ``run_id`` whose job is ``key`` ran and has ``verdict``."""
        self.db.execute("UPDATE cells SET status = 'ran', verdict = ? WHERE run_id = ? AND job_key = ? "
                        "AND status = 'pending'", (verdict, run_id, key))

    def fail_cells(self, run_id: int, key: str, message: str) -> None:
        self.db.execute("UPDATE cells SET status = 'error', verdict = 'error', message = ? "
                        "WHERE run_id = ? AND job_key = ?",
                        (message, run_id, key))

    def end_run(self, run_id: int, *, ran: int, reused: int, interrupted: bool, partial: bool) -> None:
        self.db.execute("UPDATE runs SET finished_at = ?, ran = ?, reused = ?, interrupted = ?, partial = ? "
                        "WHERE run_id = ?", (time.time(), ran, reused, int(interrupted), int(partial), run_id))
        self.db.commit()

    def commit(self) -> None:
        self.db.commit()

    def rollback(self) -> None:
        """Drop what was written since the last commit (a result whose cells were not yet marked)."""
        self.db.rollback()

    def ran_jobs(self, run_id: int) -> int:
        """How many jobs of ``run_id`` ran: their cells are marked ``ran`` (committed with their results)."""
        row = self.db.execute("SELECT count(DISTINCT job_key) FROM cells WHERE run_id = ? AND status = 'ran'",
                              (run_id,)).fetchone()
        return int(row[0])

    def runs(self) -> list[Run]:
        rows = self.db.execute("SELECT run_id, started_at, finished_at, project, executor, cells, jobs, ran, "
                               "reused, interrupted, partial FROM runs ORDER BY run_id").fetchall()
        return [Run(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], bool(r[9]), bool(r[10])) for r in rows]

    def latest_run(self, before: int | None = None, complete: bool = False) -> Run | None:
        """The newest run (older than run ``before`` if given; not interrupted if ``complete``)."""
        for run in reversed(self.runs()):
            if before is not None and run.run_id >= before:
                continue
            if complete and (run.interrupted or run.finished_at is None):
                continue
            return run
        return None

    def cells(self, run_id: int) -> list[CellRow]:
        """The matrix of a run, each cell with its job's violations and reasons."""
        rows = self.db.execute(
            "SELECT c.program, c.machine, c.job_key, c.status, COALESCE(r.verdict, c.verdict), c.message, "
            "r.violations_json, r.reasons_json, r.wall_s FROM cells c LEFT JOIN results r ON r.job_key = c.job_key "
            "WHERE c.run_id = ? ORDER BY c.machine, c.program", (run_id,)).fetchall()
        return [CellRow(p, m, k, s, v, msg, tuple(json.loads(vj)) if vj else (), tuple(json.loads(rj)) if rj else (),
                        w) for p, m, k, s, v, msg, vj, rj, w in rows]
