"""Prover benchmark (a script, not a test): python bench/bench_prover.py [--lines N]

Prints, for stellabee1.ngc from the corpus and for a generated program of N
lines (default 1,000,000) against a 256-region stepped table: end-to-end
seconds, segments/s, the share proved by the screening tier, the ratio
against sending every segment to Z3 (a sample measured in the same run,
extrapolated), and the peak resident memory.
"""

from __future__ import annotations

import argparse
import itertools
import random
import resource
import sys
import tempfile
import time
from pathlib import Path

from nczones.gcode import interpret
from nczones.machine import parse_machine
from nczones.prover import Prover, verify

STELLABEE = Path("/work/shared/corpus/linuxcnc/tests/trajectory-planner/circular-arcs/nc_files/performance/stellabee1.ngc")

BOX_MACHINE = """
[machine]
name = "bench mill"
axes = ["X", "Y", "Z"]
rapid_mode = "linear"
[machine.rapid]
X = "10000"
Y = "10000"
Z = "10000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[[zones]]
name = "travel"
kind = "box"
min = { X = "-500", Y = "-500", Z = "-500" }
max = { X = "500", Y = "500", Z = "500" }
"""


def table_machine(regions: int = 256) -> str:
    rows = ", ".join(f'{{upto = "{(i + 1) * 4}", min = "{-(i % 7) - 1}", max = "{300 + i % 5}"}}' for i in range(regions))
    return f"""
[machine]
name = "bench grinder"
axes = ["X", "Y"]
rapid_mode = "dogleg"
[machine.rapid]
X = "12000"
Y = "8000"
[machine.reference]
X = "10"
Y = "100"
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "0"
regions = [{rows}]
"""


def generate(n: int, path: Path) -> None:
    rnd = random.Random(0)
    with path.open("w") as fh:
        fh.write("G21 G90 G17\nG1 F1000\n")
        for _ in range(n - 2):
            fh.write(f"X{rnd.randint(1000, 1000000) / 1000:.3f} Y{rnd.randint(0, 299000) / 1000:.3f}\n")


def z3_per_segment(program, machine, sample: int) -> float:
    """Seconds per segment with every segment sent to Z3 (measured on a sample)."""
    prover = Prover(machine, engine="z3")
    segs = list(itertools.islice(interpret(program, machine, arc_tolerance="0.01").segments(), sample))
    t = time.perf_counter()
    for s in segs:
        prover.check(s)
    return (time.perf_counter() - t) / max(1, len(segs))


def run(label: str, program, machine, sample: int) -> None:
    t = time.perf_counter()
    r = verify(program, machine, arc_tolerance="0.01")
    dt = time.perf_counter() - t
    stats = dict(r.stats)
    segs = r.extra.get("counts", {}).get("segments", stats.get("segments", 0))
    screened = stats.get("screened", 0)
    per = z3_per_segment(program, machine, sample)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"{label}: verdict {r.verdict.label}; {segs} segments in {dt:.2f} s end-to-end "
          f"({segs / dt:,.0f} segments/s); screened {screened / max(segs, 1):.1%}; "
          f"z3 queries {stats.get('z3_queries', 0)}; Z3-per-segment {per * 1e6:.0f} us/segment "
          f"-> {per * segs:.1f} s extrapolated, ratio {per * segs / dt:.0f}x; peak RSS {peak:.0f} MiB")
    sys.stdout.flush()


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=1_000_000)
    ap.add_argument("--sample", type=int, default=2000)
    args = ap.parse_args()
    if STELLABEE.exists():
        run("stellabee1.ngc", str(STELLABEE), parse_machine(BOX_MACHINE), args.sample)
    else:
        print("stellabee1.ngc: corpus not found, skipped")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "big.ngc"
        generate(args.lines, path)
        run(f"generated {args.lines:,} lines, 256-region table", str(path), parse_machine(table_machine()), args.sample)


if __name__ == "__main__":
    main()
