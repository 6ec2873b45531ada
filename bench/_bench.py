"""Shared helpers of the benchmark scripts: fresh-process runs, timing, peak memory.

Every measured case runs in its own Python process (``python SCRIPT --case
NAME ...``), so its peak resident set size (``VmHWM``) belongs to that
case alone and the 100k / 1M cases show whether memory grows with the
program.  Wall-clock and CPU seconds are both reported: on a shared machine
the wall clock includes time the process waited for a core.
"""

from __future__ import annotations

import json
import os
import platform
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STELLABEE = Path("/work/shared/corpus/linuxcnc/tests/trajectory-planner/circular-arcs/nc_files/performance/stellabee1.ngc")


def machine_description() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import numpy

    return (f"{os.cpu_count()} cores, {cpu}, Python {platform.python_version()}, numpy {numpy.__version__}, "
            f"load average {os.getloadavg()[0]:.1f}")


class Clock:
    """Wall and CPU seconds of a block."""

    def __enter__(self):
        self.w0, self.c0 = time.perf_counter(), time.process_time()
        return self

    def __exit__(self, *exc):
        self.wall = time.perf_counter() - self.w0
        self.cpu = time.process_time() - self.c0


def peak_rss_mib() -> float:
    """Peak resident memory of this process (``VmHWM``: unlike ``ru_maxrss`` it is not
    inherited from the parent that started it)."""
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def run_case(script: str, *args: str, runs: int = 1) -> dict:
    """Run ``script --case ...`` in a fresh process ``runs`` times; the result (the last stdout
    line, a JSON dict) of the run with the least CPU time, so other load on the machine counts less."""
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    results = []
    for _ in range(max(1, runs)):
        out = subprocess.run([sys.executable, script, *args], capture_output=True, text=True, env=env)
        if out.returncode != 0:
            raise SystemExit(f"case {args} failed:\n{out.stderr}")
        results.append(json.loads(out.stdout.strip().splitlines()[-1]))
    return min(results, key=lambda r: r.get("cpu", 0.0))


def emit(result: dict) -> None:
    result.setdefault("peak_rss_mib", peak_rss_mib())
    print(json.dumps(result))
