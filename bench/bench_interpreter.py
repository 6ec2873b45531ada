"""Benchmark of the full G-code interpreter (a script, not a test).

    python bench/bench_interpreter.py [--lines 200000]

Executed lines per second (every line the language layer executes counts,
once per loop iteration: parameter assignments and O-word lines included)
and blocks per second (blocks handed to the interpreter) of the language
layer alone (``iter_blocks``) and of the full interpreter
(``interpret(..., fast=False)``) on programs that need the full
interpreter (a LinuxCNC program with parameters, expressions and an
O-word loop; moves with an expression on every line) and, for reference,
programs whose lines the fast path takes when it is on (CAM moves in a
program that sets a parameter, moves with S/M words on every line, G81
hole lines), here through the full interpreter.  CPU
time of this process (``time.process_time``), so other load on the
machine counts less; the best of three runs.  The issue's target:
100,000 lines/s.
"""

from __future__ import annotations

import argparse
import random
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_gcode import expr_program, param_program  # noqa: E402  (one generator for both benchmarks)

from nczones.gcode import interpret_text  # noqa: E402
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


def drill_program(n: int, seed: int = 4) -> str:
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54 G98 F300", "G0 Z10", "G81 X1 Y1 Z-3 R2"]
    for _ in range(n - 5):
        out.append(f"X{rnd.uniform(0, 200):.2f} Y{rnd.uniform(0, 100):.2f}")
    out += ["G80", "M30"]
    return "\n".join(out) + "\n"


class _NoCache(dict):
    """A line cache that keeps nothing, so the runner reads every line it executes from its source."""

    def __setitem__(self, key, value) -> None:
        pass


def executed_lines(text: str) -> int:
    """Lines the language layer executes (loop bodies once per iteration), counted by its line reader
    (a subclass of the string source, which also keeps the runner on its general loop; the runner's
    cache of lines that run again is turned off, so every executed line is read)."""
    from nczones.gcode import program
    from nczones.gcode.expr import Parameters

    class Counting(program.StringSource):
        __slots__ = ("count",)

        def line_at(self, pos):
            line, nxt = super().line_at(pos)
            self.count += line is not None
            return line, nxt

    src = Counting(text)
    src.count = 0
    runner = program.Runner(src, "<bench>", Parameters(), False, program.DEFAULT_MAX_LOOP_ITERATIONS, 100)
    runner.cache = _NoCache()
    sum(1 for _ in runner.run())
    return src.count


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
    programs = (
        ("G1 X Y S M3 on every line (G91)*", words_program(n)),
        ("CAM lines + one parameter*", param_program(n)),
        ("G81 holes (4 moves a line)*", drill_program(n)),
        ("params, COS/SIN, o-word repeat", macro_program(n)),
        ("an expression on every line", expr_program(n)),
    )
    print(f"{'program':34s} {'lines':>8s} {'blocks':>8s}   language layer lines/s   full interpreter lines/s (blocks/s)")
    for name, text in programs:
        lines = executed_lines(text)
        blocks = sum(1 for _ in iter_blocks(text))
        lang = best(lambda text=text: sum(1 for _ in iter_blocks(text)))
        full = best(lambda text=text: sum(len(c) for c in interpret_text(text, MACHINE, fast=False)))
        print(f"{name:34s} {lines:8d} {blocks:8d}   {lines / lang:22.0f}   {lines / full:24.0f} ({blocks / full:.0f})")
    print("* with interpret(fast=True) these take the vectorized fast path (bench/bench_gcode.py): "
          "shown here through the full interpreter (fast=False) for reference")


if __name__ == "__main__":
    main()
