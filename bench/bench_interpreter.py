"""Benchmark of the full G-code interpreter (a script, not a test).

    python bench/bench_interpreter.py [--lines 200000]

Lines per second of the language layer alone (``iter_blocks``) and of the
full interpreter (``interpret(..., fast=False)``) on programs that need the
full interpreter: incremental moves with S/M words on every line (the
``bench_gcode.py`` generator), and a LinuxCNC program with parameters,
expressions and an O-word loop.  CPU time of this process
(``time.process_time``), so other load on the machine does not count; the
best of three runs.
"""

from __future__ import annotations

import argparse
import random
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from nczones.gcode import interpret  # noqa: E402
from nczones.gcode.program import iter_blocks  # noqa: E402
from nczones.machine import parse_machine  # noqa: E402

MACHINE = parse_machine(
    '[machine]\naxes = ["X", "Y", "Z"]\npulse = "0.0001"\n[machine.rapid]\nX = "1000"\nY = "1000"\nZ = "1000"\n'
    '[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n[tool_lengths]\nH1 = "100"\n'
)


def words_program(n: int, seed: int = 2) -> str:
    rnd = random.Random(seed)
    out = ["G21 G91 G17 G54 F500"]
    for i in range(n - 2):
        out.append(f"G1 X{rnd.uniform(-1, 1):.3f} Y{rnd.uniform(-1, 1):.3f} S{1000 + i % 7} M3")
    out.append("M30")
    return "\n".join(out) + "\n"


def macro_program(n: int) -> str:
    body = ["#<r> = [#1 * 0.001]", "G1 X[#<r> * COS[#1]] Y[#<r> * SIN[#1]]", "#1 = [#1 + 1]"]
    reps = max(1, (n - 6) // (len(body) + 2))
    return "\n".join(["G21 G90 F800", "#1 = 0", f"o100 repeat [{reps}]", *body, "o100 endrepeat", "M30"]) + "\n"


def best(fn, runs: int = 3) -> float:
    out = []
    for _ in range(runs):
        t = time.process_time()
        fn()
        out.append(time.process_time() - t)
    return min(out)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=200_000)
    a = ap.parse_args()
    n = a.lines
    for name, text in (("words (G1 X Y S M3 per line)", words_program(n)), ("macro (params, COS/SIN, repeat)", macro_program(n))):
        executed = sum(1 for _ in iter_blocks(text))
        lang = best(lambda: sum(1 for _ in iter_blocks(text)))
        full = best(lambda: sum(len(c) for c in interpret(text, MACHINE, fast=False)))
        print(f"{name:34s} {executed:8d} blocks  language layer {executed / lang:9.0f} blocks/s   "
              f"full interpreter {executed / full:9.0f} blocks/s")


if __name__ == "__main__":
    main()
