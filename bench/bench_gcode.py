"""Benchmark of the G-code front end (a script, not a test).

    python bench/bench_gcode.py [--lines 1000000]

Prints interpreted lines/s on stellabee1.ngc (corpus), on a generated
CAM-style program (fast path) and on a generated program that needs the full
interpreter (incremental moves with M/S/T words on every line), the
fast/full ratio, and peak memory (resource.ru_maxrss).
"""

from __future__ import annotations

import argparse
import random
import resource
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from nczones.gcode import interpret  # noqa: E402
from nczones.machine import parse_machine  # noqa: E402

STELLA = Path("/work/shared/corpus/linuxcnc/tests/trajectory-planner/circular-arcs/nc_files/performance/stellabee1.ngc")
MACHINE = parse_machine(
    '[machine]\naxes = ["X", "Y", "Z"]\npulse = "0.0001"\n[machine.rapid]\nX = "1000"\nY = "1000"\nZ = "1000"\n'
    '[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n[tool_lengths]\nH1 = "100"\n'
)


def cam_program(n: int, seed: int = 1) -> str:
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54", "G43 H1 G0 Z5", "G1 F800"]
    x = y = 0.0
    for i in range(n - 4):
        if i % 50 == 49:
            x = round(x + 2, 3)
            out.append(f"G2 X{x:.3f} Y{y:.3f} I1.000 J0")
            out.append("G1")
        else:
            x = round(x + rnd.uniform(-1, 1), 3)
            y = round(y + rnd.uniform(-1, 1), 3)
            out.append(f"X{x:.3f} Y{y:.3f}")
    out.append("M30")
    return "\n".join(out) + "\n"


def full_program(n: int, seed: int = 2) -> str:
    rnd = random.Random(seed)
    out = ["G21 G91 G17 G54 F500"]
    for i in range(n - 2):
        out.append(f"G1 X{rnd.uniform(-1, 1):.3f} Y{rnd.uniform(-1, 1):.3f} S{1000 + i % 7} M3")
    out.append("M30")
    return "\n".join(out) + "\n"


def timed(path: Path, fast: bool = True) -> tuple[int, float, int, int]:
    lines = path.read_bytes().count(b"\n")
    t = time.perf_counter()
    run = interpret(path, MACHINE, fast=fast, arc_tolerance="0.1")
    segs = sum(len(c) for c in run)
    dt = time.perf_counter() - t
    return lines, dt, segs, run.fast_lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=1_000_000)
    ap.add_argument("--full-lines", type=int, default=200_000)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        rows = []
        if STELLA.is_file():
            rows.append(("stellabee1.ngc (fast path)", *timed(STELLA)))
            rows.append(("stellabee1.ngc (full interpreter)", *timed(STELLA, fast=False)))
        cam = Path(d) / "cam.ngc"
        cam.write_text(cam_program(a.lines))
        rows.append((f"generated CAM {a.lines} lines (fast path)", *timed(cam)))
        full = Path(d) / "full.ngc"
        full.write_text(full_program(a.full_lines))
        rows.append((f"generated full-interpreter {a.full_lines} lines", *timed(full)))
        for name, lines, dt, segs, fl in rows:
            print(f"{name:45s} {lines:9d} lines {dt:7.2f} s {lines / dt:10.0f} lines/s  segments {segs}  fast lines {fl}")
        fast_rate = rows[-2][1] / rows[-2][2]
        full_rate = rows[-1][1] / rows[-1][2]
        print(f"fast/full ratio: {fast_rate / full_rate:.1f}")
    print(f"peak memory (ru_maxrss): {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MiB")


if __name__ == "__main__":
    main()
