"""A child process's own CPU time, so that tests of "stops within a second" hold on a loaded machine.

On a 2-core machine shared with other test workers, wall time after a signal
measures the scheduler as much as the program: a child that needs 0.2 s of CPU
to write its partial report can wait seconds for a core.  What the program
controls is the CPU it spends after the signal, and that is what these helpers
measure (Linux ``/proc``; elsewhere the wall clock stands in).
"""

from __future__ import annotations

import os
import signal
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path


def _stat_fields(pid: int) -> list[str] | None:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return None


def cpu_seconds(pid: int) -> float:
    """User + system CPU seconds spent so far by a running (or not yet reaped) process."""
    fields = _stat_fields(pid)
    if fields is None:
        return 0.0
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


@dataclass(frozen=True, slots=True)
class Interrupted:
    out: str
    err: str
    returncode: int
    cpu_after_signal_s: float
    wall_after_signal_s: float


def interrupt(proc: subprocess.Popen, *, wall_limit_s: float = 60.0, sig: int = signal.SIGINT) -> Interrupted:
    """Send SIGINT (or ``sig``) and wait for the child to end; measure what it spent after the signal.

    The child's CPU is read from ``/proc`` until it is a zombie (ended, not yet
    reaped, its times still readable), then its output is collected.  Its output
    must fit the pipe buffers (64 KiB), as a partial report does.
    """
    has_proc = Path("/proc").is_dir()
    cpu0 = cpu_seconds(proc.pid) if has_proc else 0.0
    t0 = time.monotonic()
    proc.send_signal(sig)
    cpu_end = cpu0
    while has_proc and time.monotonic() - t0 < wall_limit_s:
        fields = _stat_fields(proc.pid)
        if fields is None:
            break
        cpu_end = (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
        if fields[0] in ("Z", "X"):
            break
        time.sleep(0.01)
    out, err = proc.communicate(timeout=wall_limit_s)
    wall = time.monotonic() - t0
    cpu = cpu_end - cpu0 if has_proc else wall
    return Interrupted(out, err, proc.returncode, cpu, wall)
