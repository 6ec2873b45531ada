"""Jobs: one (program, machine, settings) each, keyed by what decides its verdict.

A job's key is the SHA-256 of the program's bytes, of the machine file's
bytes, of the settings (canonical JSON, :func:`~nczones.fleet.project.settings_json`,
with the contents of a subprogram library folder when the settings name one)
and of the nczones version (:func:`code_version`).  Two cells with the same
key are one job; a key already in the store is not verified again.

Invariant: everything the verdict depends on is in the key.  The machine
files are read once per run and their text is what the workers get; a
program is read to hash it and read again when its job is sent, and the
worker refuses bytes whose SHA-256 is not the key's (``FL201``, not stored).
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Iterable
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

from .project import Cell, Project, settings_json

__all__ = ["Job", "JobPlan", "code_version", "plan_jobs", "job_key"]


@lru_cache(maxsize=1)
def code_version() -> str:
    """``nczones VERSION (code SHA) z3 VERSION``: the version part of every job key.

    The code hash covers the package's Python sources, so an edited checkout
    (an editable install keeps its version number) re-verifies everything;
    the Z3 version is there because the solver decides the hard queries.

    >>> code_version().startswith("nczones ")
    True
    """
    from .. import __version__

    package = Path(__file__).resolve().parent.parent
    h = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        h.update(path.relative_to(package).as_posix().encode())
        h.update(b"\0")
        h.update(path.read_bytes())
        h.update(b"\0")
    try:
        import z3

        z3_version = z3.get_version_string()
    except ImportError:  # pragma: no cover - z3 is a dependency
        z3_version = "none"
    return f"nczones {__version__} (code {h.hexdigest()[:16]}) z3 {z3_version}"


def job_key(program_sha256: str, machine_sha256: str, settings_sha256: str, version: str) -> str:
    """The SHA-256 that names a job.

    >>> job_key("a" * 64, "b" * 64, "c" * 64, "nczones 0")[:12]
    'bd7a59ccedf1'
    """
    doc = json.dumps({"program": program_sha256, "machine": machine_sha256, "settings": settings_sha256,
                      "nczones": version}, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(doc.encode()).hexdigest()


@dataclass(frozen=True, slots=True)
class Job:
    """A unit of work: verify one program on one machine with one set of settings."""

    key: str
    program: str  # relative path of the first cell with this key
    machine: str
    program_sha256: str
    machine_sha256: str
    settings_sha256: str
    settings: tuple[tuple[str, Any], ...]
    version: str


@dataclass(frozen=True, slots=True)
class JobPlan:
    """The cells of a run and the jobs behind them (``cell_keys`` maps (program, machine) -> key)."""

    cells: tuple[Cell, ...]
    cell_keys: dict[tuple[str, str], str]
    jobs: dict[str, Job]
    errors: dict[tuple[str, str], str]  # cells that cannot be a job (bad machine file, bad parameter)
    program_sha256: dict[str, str]  # program -> SHA-256 of its bytes (the bytes are read again when sent)
    machine_text: dict[str, str]  # machine name -> text (UTF-8) of its file


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _library_digest(folder: Path) -> str:
    """A digest of every file under a subprogram library folder (names and bytes)."""
    h = hashlib.sha256()
    if folder.is_dir():
        for path in sorted(p for p in folder.rglob("*") if p.is_file()):
            h.update(path.relative_to(folder).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    else:
        h.update(b"missing")
    return h.hexdigest()


def plan_jobs(project: Project, cells: Iterable[Cell], version: str | None = None) -> JobPlan:
    """Read every program and machine file of ``cells`` once and compute the job keys.

    A machine file that does not load, or a parameter range that does not
    fit the machine, makes its cells errors (``errors``) rather than jobs: the
    other cells still run.
    """
    from ..errors import InputError
    from ..machine import parse_machine
    from ..prover import parse_param

    version = code_version() if version is None else version
    cells = tuple(cells)
    program_sha: dict[str, str] = {}
    machine_text: dict[str, str] = {}
    machine_sha: dict[str, str] = {}
    machines: dict[str, Any] = {}
    errors: dict[tuple[str, str], str] = {}
    machine_errors: dict[str, str] = {}
    for entry in project.machines:
        if not any(c.machine == entry.name for c in cells):
            continue
        try:
            data = entry.file.read_bytes()
            text = data.decode("utf-8")
            machine = parse_machine(text, _display(project, entry.file))
        except (OSError, UnicodeDecodeError) as exc:
            machine_errors[entry.name] = f"{_display(project, entry.file)}: cannot read the machine file: {exc}"
            continue
        except InputError as exc:
            machine_errors[entry.name] = exc.render()
            continue
        machine_text[entry.name] = text
        machine_sha[entry.name] = _sha(data)
        machines[entry.name] = machine
    libraries: dict[str, str] = {}
    jobs: dict[str, Job] = {}
    cell_keys: dict[tuple[str, str], str] = {}
    for cell in cells:
        where = (cell.program, cell.machine)
        if cell.machine in machine_errors:
            errors[where] = machine_errors[cell.machine]
            continue
        if cell.program not in program_sha:
            try:
                program_sha[cell.program] = _sha((project.root / cell.program).read_bytes())
            except OSError as exc:
                errors[where] = f"{cell.program}: cannot read the program: {exc.strerror or exc}"
                continue
        settings = dict(cell.settings)
        try:
            for p in settings.get("params", ()):
                parse_param(p, machines[cell.machine])
        except InputError as exc:
            errors[where] = f"{cell.program} on {cell.machine}: " + "; ".join(d.message for d in exc.diagnostics)
            continue
        hashed = settings_json(cell.settings)
        if "library" in settings:
            lib = settings["library"]
            if lib not in libraries:
                libraries[lib] = _library_digest(project.root / lib)
            hashed += "\0library:" + libraries[lib]
        for folder in machines[cell.machine].subroutine_path:  # [linuxcnc] subroutine_path: its files count too
            if folder not in libraries:
                libraries[folder] = _library_digest(project.root / folder)
            hashed += "\0subroutines:" + libraries[folder]
        settings_sha = _sha(hashed.encode())
        key = job_key(program_sha[cell.program], machine_sha[cell.machine], settings_sha, version)
        cell_keys[where] = key
        if key not in jobs:
            jobs[key] = Job(key, cell.program, cell.machine, program_sha[cell.program],
                            machine_sha[cell.machine], settings_sha, cell.settings, version)
    return JobPlan(cells, cell_keys, jobs, errors, program_sha, machine_text)


def _display(project: Project, path: Path) -> str:
    """A path as reports show it: relative to the project root when inside it."""
    try:
        return path.relative_to(project.root).as_posix()
    except ValueError:
        return os.fspath(path)
