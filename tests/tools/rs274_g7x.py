"""Differential run of LinuxCNC's lathe cycles G70, G71, G72 (and .1/.2) against LinuxCNC's own ``rs274 -g``.

A focused generator beside ``tests/tools/rs274_diff.py`` (whose grammar leaves the lathe cycles out): each
seed writes one short lathe program — G18, G7 or G8, G20 or G21, a start point, a profile subroutine of
straight lines and arcs (X/Z or U/W, I/K or R, the A/C corners, G90/G91 inside it, sometimes a non-monotonic
piece) and one cycle with a random choice of its words (X Z D E P for G70; X Z U W D I R for G71/G72) —
and compares nczones's motion with rs274's, motion by motion (``tests/oracles/rs274.py``), on the same
three-axis machine as ``rs274_diff`` (rs274 runs the cycles in G18 on any machine).

    python -m tests.tools.rs274_g7x run --count 500 --seed 1      # compare, minimise mismatches

``tests/gcode/test_rs274_g7x.py`` runs the CI size and the long profile (``@pytest.mark.long``).
"""

from __future__ import annotations

import argparse
import random
import sys
import tempfile
from collections import Counter
from fractions import Fraction
from pathlib import Path

from tests.tools.rs274_diff import RS274, Setup, minimise, outcome, signature

#: X Y Z A B C (the axes of the standalone rs274: its GET_EXTERNAL_AXIS_MASK is 0x3f, so A and C words are read
#: and U, V, W are "Bad character"), four tools of 0.1 inch, no offsets
SETUP: Setup = (("X", "Y", "Z", "A", "B", "C"), {n: Fraction(1, 10) for n in range(1, 5)}, {})


def _n(r: random.Random, lo: float, hi: float, step: float = 0.5) -> str:
    """A number on a grid of ``step`` (sometimes a finer one), written as LinuxCNC reads it."""
    if r.random() < 0.2:
        step = 0.001
    k = r.randint(round(lo / step), round(hi / step))
    v = round(k * step, 4)
    text = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


class G7xGenerator:
    """One lathe program of a seed (see the module's text)."""

    def __init__(self, seed: int):
        self.r = random.Random(seed)

    def profile(self, z0: float, x0: float, facing: bool) -> list[str]:
        """Blocks from the start (z0, x0) going into the material: for turning (G71) down in X, then along -Z
        with X rising; for facing (G72) along -Z first, then down in X.  Arcs as I/K or R, A/C corners."""
        r = self.r
        lines: list[str] = []
        z, x = z0, x0
        n = r.randint(2, 6)
        incremental = r.random() < 0.15
        if incremental:
            lines.append("G91")
        for k in range(n):
            first = k == 0
            if first:
                if facing:
                    nz, nx = z - r.uniform(0.5, 4), x + (r.choice([0, 0, r.uniform(-1, 1)]))
                else:
                    nz, nx = z + r.choice([0, 0, r.uniform(-1, 0.5)]), x - r.uniform(1, 6)
            elif facing:
                nz, nx = z + r.choice([r.uniform(-2, 0.3), 0]), x - r.uniform(0.3, 3)
            else:
                nz, nx = z - r.uniform(0.3, 5), x + r.choice([r.uniform(-0.3, 2), 0, 0])
            if r.random() < 0.05:  # against the grain: LinuxCNC refuses or reorders some of these
                nz, nx = nz + r.uniform(0, 2), nx + r.uniform(-2, 2)
            nz, nx = round(nz, 1 if r.random() < 0.7 else 3), round(nx, 1 if r.random() < 0.7 else 3)
            words = self._move(z, x, nz, nx, incremental, first)
            if words is None:
                continue
            if not first and r.random() < 0.12 and k < n - 1:
                words += f" {r.choice('AC')}{_n(r, 0.1, 1.0, 0.1)}"
            lines.append(words)
            z, x = nz, nx
        if incremental:
            lines.append("G90")
        return lines

    def _move(self, z: float, x: float, nz: float, nx: float, incremental: bool, first: bool) -> str | None:
        r = self.r
        if (nz, nx) == (z, x):
            return None
        dia = 2 if self.diameter else 1

        def xw(v: float) -> str:
            return f"{v * dia:.4f}".rstrip("0").rstrip(".")

        if incremental:
            target = f"X{xw(nx - x)} Z{round(nz - z, 4):g}"
        elif r.random() < 0.1 and not first:
            target = f"U{xw(nx - x)} W{round(nz - z, 4):g}"
        else:
            target = r.choice([f"X{xw(nx)} Z{nz:g}", f"Z{nz:g} X{xw(nx)}"])
            if nz == z and r.random() < 0.5:
                target = f"X{xw(nx)}"
            elif nx == x and r.random() < 0.5:
                target = f"Z{nz:g}"
        if first or r.random() < 0.6 or nz == z or nx == x:
            return f"G1 {target}" if first or r.random() < 0.5 else target
        code = r.choice(["G2", "G3"])
        chord = abs(complex(nz - z, nx - x))
        if r.random() < 0.5:
            rad = round(chord / 2 + r.uniform(0.0, 3.0), 3)
            return f"{code} {target} R{rad:g}"
        # I K: the centre on the chord's perpendicular bisector
        mz, mx = (z + nz) / 2, (x + nx) / 2
        t = r.uniform(-2, 2)
        cz, cx = mz - (nx - x) * t, mx + (nz - z) * t
        cz, cx = round(cz, 4), round(cx, 4)
        return f"{code} {target} I{round(cx - x, 4):g} K{round(cz - z, 4):g}"

    def program(self) -> str:
        r = self.r
        self.diameter = r.random() < 0.4
        cycle = r.choice(["G70", "G71", "G71.1", "G71.2", "G72", "G72.1", "G72.2"])
        facing = cycle.startswith("G72")
        z0 = round(r.uniform(0.5, 3), 1)
        x0 = round(r.uniform(8, 20), 1)
        dia = 2 if self.diameter else 1
        head = [f"G18 {'G7' if self.diameter else 'G8'} {r.choice(['G21', 'G21', 'G21', 'G20'])} G90 G40 F100",
                "M3 S1000"]
        body = self.profile(z0, x0, facing)
        sub = ["o100 sub", *body, "o100 endsub"]
        words = [cycle, "Q100"]
        if r.random() < 0.8:
            words.append(f"X{round(x0 * dia, 4):g}")
        if r.random() < 0.8:
            words.append(f"Z{z0:g}")
        if cycle == "G70":
            for letter, lo, hi in (("D", 0, 1), ("E", 0, 1)):
                if r.random() < 0.5:
                    words.append(f"{letter}{_n(r, lo, hi, 0.1)}")
            if r.random() < 0.4:
                words.append(f"P{r.choice(['1', '2', '3', '0', '1.5', '2.5', '0.5', '2.0001'])}")
        else:
            for letter, lo, hi, p in (("U", -0.5, 0.5, 0.6), ("W", -0.5, 0.5, 0.5), ("D", 0, 1, 0.5),
                                      ("I", 0.3, 3, 0.8), ("R", 0, 1.5, 0.5)):
                if r.random() < p:
                    words.append(f"{letter}{_n(r, lo, hi, 0.1)}")
        r.shuffle(words[1:])
        pre = [f"G0 X{round((x0 + r.choice([0, 1, 2])) * dia, 4):g} Z{z0 + r.choice([0, 1]):g}"]
        tail = []
        if r.random() < 0.3:
            tail.append(f"G0 X{round((x0 + 2) * dia, 4):g} Z{z0 + 2:g}")
        if r.random() < 0.2:
            tail.append(f"X{round((x0 + 3) * dia, 4):g}")  # the motion mode the cycle leaves
        return "\n".join([*sub, *head, *pre, " ".join(words), *tail, "M2"]) + "\n"


def generate(seed: int) -> str:
    return G7xGenerator(seed).program()


def run(seeds: range, work: Path, minimise_found: bool = True, verbose: bool = False) -> tuple[Counter, list]:
    counts: Counter = Counter()
    found: list = []
    for seed in seeds:
        text = generate(seed)
        o = outcome(text, SETUP, work)
        counts[o.status] += 1
        if o.status not in ("match", "unknown"):
            small, mo = minimise(text, SETUP, work, signature(o)) if minimise_found else (text, o)
            found.append((seed, small, mo))
            if verbose:
                print(f"--- seed {seed} {mo.status}: {mo.detail}\n" + "".join(f"    | {ln}\n" for ln in
                                                                           small.splitlines()), flush=True)
        elif o.status == "unknown" and verbose:
            print(f"--- seed {seed} unknown: {o.detail}", flush=True)
    return counts, found


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    rn = sub.add_parser("run")
    rn.add_argument("--count", type=int, default=200)
    rn.add_argument("--seed", type=int, default=1)
    rn.add_argument("--no-minimise", dest="minimise", action="store_false")
    rn.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)
    if not Path(RS274).exists():
        print(f"{RS274} not found (LinuxCNC's standalone interpreter, package linuxcnc-uspace)", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        counts, _ = run(range(args.seed, args.seed + args.count), Path(tmp), args.minimise, not args.quiet)
    print("outcomes:", dict(counts))
    return 0


if __name__ == "__main__":
    sys.exit(main())
