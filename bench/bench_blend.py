"""Cost of the corner-blending proof (issue 35, specs/path-modes.md) beside the exact-path verdict.

    python bench/bench_blend.py [--lines 1000000] [--zones box|stepped|both]

A generated CAM-like program (``G1`` moves in a 300 mm square, G64 corners everywhere) is verified twice on
the same machine: with ``path_mode = "G61"`` (no corner is rounded: the exact-path proof alone) and with
``path_mode = "G64"`` (LinuxCNC's default: every corner's region proved too), against a convex box and
against a stepped table whose step the moves stay clear of (each corner region near it is refined).  It
prints both times and their ratio (the issue asks for at most 1.5).
"""

from __future__ import annotations

import argparse
import random
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from nczones.machine import parse_machine  # noqa: E402
from nczones.prover import verify  # noqa: E402

BOX = """
[[zones]]
name = "travel"
kind = "box"
min = { X = "-500", Y = "-500", Z = "-500" }
max = { X = "500", Y = "500", Z = "500" }
"""
STEP = """
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "-500"
regions = [{ upto = "320", min = "-500", max = "500" }, { upto = "500", min = "-500", max = "40" }]
"""


def machine(mode: str, zones: str):
    return parse_machine(f"""
[machine]
name = "bench mill"
axes = ["X", "Y", "Z"]
rapid_mode = "linear"
path_mode = "{mode}"
[machine.rapid]
X = "10000"
Y = "10000"
Z = "10000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
{zones}""")


def generate(n: int, path: Path) -> None:
    rnd = random.Random(35)
    with path.open("w") as fh:
        fh.write("G21 G90 G54 G17\nG1 F1000\n")
        for _ in range(n):
            fh.write(f"X{rnd.randint(0, 300000) / 1000:.3f} Y{rnd.randint(0, 300000) / 1000:.3f}\n")
        fh.write("M30\n")


def timed(program: Path, m) -> tuple[float, str]:
    t0 = time.perf_counter()
    r = verify(program, m)
    return time.perf_counter() - t0, r.verdict.label


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=1_000_000)
    ap.add_argument("--zones", choices=("box", "stepped", "both"), default="both")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        program = Path(tmp) / "cam.ngc"
        generate(args.lines, program)
        for name, zones in (("box", BOX), ("stepped table", STEP)):
            if args.zones != "both" and not name.startswith(args.zones):
                continue
            exact_s, exact_v = timed(program, machine("G61", zones))
            blend_s, blend_v = timed(program, machine("G64", zones))
            print(f"{args.lines} lines, {name}: exact path {exact_s:.2f} s ({exact_v}), with G64 corners "
                  f"{blend_s:.2f} s ({blend_v}), ratio {blend_s / exact_s:.2f}", flush=True)


if __name__ == "__main__":
    main()
