"""What a worker runs: verify one job (or one chunk of a split job) and describe the outcome.

:func:`run_task` is the one function sent to Dask workers (or called in
this process by the serial executor).  A task is a plain dict:

* ``kind``: ``"whole"`` (verify the program) or ``"chunk"`` (one chunk of
  a split program, :mod:`nczones.fleet.split`);
* ``key``, ``program`` (the name reports use), ``program_data`` (its bytes)
  or ``program_path`` (a path the worker reads; its SHA-256 must match
  ``program_sha256``); for a chunk, ``chunk`` and its ``text`` or the
  ``program_path`` to cut it from;
* ``machine_file`` (name), ``machine_text``, ``machine_sha256``;
* ``settings`` (normalized pairs), ``root`` (the project root, for a
  subprogram library).

The answer is a dict: for a whole job a :func:`record` (JSON values only),
for a chunk the :class:`~nczones.prover.Result` itself (combined by the
coordinator), and in both the worker's :func:`~nczones.fleet.jobs.code_version`.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import socket
import tempfile
import time
import traceback
from collections import OrderedDict
from typing import TYPE_CHECKING, Any

from .jobs import code_version

if TYPE_CHECKING:
    from ..prover.options import VerifyOptions

__all__ = ["run_task", "record", "error_record", "machine_for"]

_MACHINES: OrderedDict[tuple[str, str], Any] = OrderedDict()


def machine_for(name: str, text: str, sha256: str) -> Any:
    """The :class:`~nczones.machine.Machine` of a machine file's text (cached per worker by SHA-256)."""
    from ..machine import parse_machine

    key = (sha256, name)
    machine = _MACHINES.get(key)
    if machine is None:
        machine = dataclasses.replace(parse_machine(text, name), sha256=sha256)
        _MACHINES[key] = machine
        while len(_MACHINES) > 64:
            _MACHINES.popitem(last=False)
    else:
        _MACHINES.move_to_end(key)
    return machine


def _worker_name() -> str:
    return f"{socket.gethostname()}:{os.getpid()}"


def record(result: Any, program: str, wall_s: float, chunks: int = 1) -> dict[str, Any]:
    """What the store keeps of a :class:`~nczones.prover.Result` (JSON values), with its JSON and text reports."""
    from ..report import render_report

    report_json = render_report(result, "json")
    doc = json.loads(report_json)
    return {
        "verdict": result.verdict.label,
        "violations": doc["violations"],
        "reasons": doc["reasons"],
        "notes": doc["notes"],
        "truncated": bool(result.truncated),
        "timings": doc["timings"],
        "stats": doc["stats"],
        "wall_s": wall_s,
        "chunks": chunks,
        "report_json": report_json,
        "report_text": render_report(result, "text", program=program),
    }


def error_record(program: str, message: str, wall_s: float, code: str = "") -> dict[str, Any]:
    """A job that could not be verified (bad G-code, unreadable input, an internal error): verdict ``error``."""
    return {
        "verdict": "error", "violations": [], "reasons": [{"message": message, "code": code, "location": None,
                                                         "source": ""}],
        "notes": [], "truncated": False, "timings": {}, "stats": {}, "wall_s": wall_s, "chunks": 1,
        "report_json": json.dumps({"program": program, "verdict": "error", "errors": [
            {"code": code, "message": message}]}, indent=2) + "\n",
        "report_text": f"{program}: error: {message}\n",
    }


def run_task(task: dict[str, Any]) -> dict[str, Any]:
    """Run one task (see the module docstring); never raises for a problem of the job itself."""
    from ..errors import InputError
    from ..prover.options import VerifyOptions

    t0 = time.perf_counter()
    program = task["program"]
    answer: dict[str, Any] = {"key": task["key"], "kind": task["kind"], "version": code_version(),
                              "worker": _worker_name()}
    try:
        machine = machine_for(task["machine_file"], task["machine_text"], task["machine_sha256"])
        if machine.subroutine_path and task.get("root"):  # named relative to the project root, as the file is
            machine = dataclasses.replace(machine, subroutine_path=tuple(
                os.path.join(task["root"], p) for p in machine.subroutine_path))
        options = VerifyOptions.from_settings(task["settings"], root=task["root"])
        if task["kind"] == "chunk":
            answer["result"] = _verify_chunk(task, machine, options)
        else:
            result = _verify_whole(task, machine, options)
            answer["record"] = record(result, program, time.perf_counter() - t0)
    except InputError as exc:
        answer["record"] = error_record(program, exc.render(), time.perf_counter() - t0, exc.code)
    except KeyboardInterrupt:
        raise
    except Exception as exc:  # noqa: BLE001 - an internal bug: recorded as such, the fleet goes on
        detail = "".join(traceback.format_exception_only(type(exc), exc)).strip()
        answer["record"] = error_record(program, f"internal error (a bug in nczones, please report it): "
                                                 f"{detail}", time.perf_counter() - t0, "internal")
        answer["traceback"] = traceback.format_exc()
    answer["wall_s"] = time.perf_counter() - t0
    return answer


class Interrupted(Exception):
    """A verification stopped by Ctrl-C before it finished (its partial result is not stored)."""


def _finished(result: Any) -> Any:
    if getattr(result, "interrupted", False):
        raise KeyboardInterrupt
    return result


def _verify_whole(task: dict[str, Any], machine: Any, options: VerifyOptions) -> Any:
    from ..gcode import load_program
    from ..pipeline.verification import verify_source

    path = task.get("program_path")
    if path is not None:
        source = load_program(path, task["program"])
        if source.sha256 != task["program_sha256"]:
            raise _changed(task["program"])
        return _finished(verify_source(source.require_code(), machine, options))
    data: bytes = task["program_data"]
    if hashlib.sha256(data).hexdigest() != task["program_sha256"]:
        raise _changed(task["program"])
    fd, tmp = tempfile.mkstemp(suffix=".nc", prefix="nczones-fleet-")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        source = load_program(tmp, task["program"])
    finally:
        os.unlink(tmp)
    return _finished(verify_source(source.require_code(), machine, options))


def _changed(program: str) -> Exception:
    from ..errors import Diagnostic, GcodeError

    return GcodeError(Diagnostic("FL201", "the program changed while the fleet ran (its SHA-256 is not the one "
                                          "its job key was computed from); run the fleet again", file=program))


def _verify_chunk(task: dict[str, Any], machine: Any, options: VerifyOptions) -> Any:
    from ..gcode.source import program_text
    from ..pipeline.verification import verify_source
    from .split import shift_result

    chunk = task["chunk"]
    text = task.get("text")
    if text is None:
        from ..gcode import load_program

        source = load_program(task["program_path"], task["program"])
        if source.sha256 != task["program_sha256"]:
            raise _changed(task["program"])
        text = chunk.text(source.text)
    if chunk.position is not None:
        machine = dataclasses.replace(machine, start=chunk.position)
    result = _finished(verify_source(program_text(text, task["program"]).require_code(), machine, options))
    return shift_result(result, chunk)
