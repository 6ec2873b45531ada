"""Differential run of nczones's LinuxCNC interpreter against LinuxCNC's own ``rs274 -g``.

Generates programs that mix modal state in many orders (seeded, reproducible), runs each through
``rs274`` (LinuxCNC's standalone interpreter, package ``linuxcnc-uspace``) and nczones, and compares
the motion in machine coordinates and where each refuses the program (``tests/oracles/rs274.py``).

    python -m tests.tools.rs274_diff run --count 2000 --seed 1        # compare, minimise mismatches
    python -m tests.tools.rs274_diff record --count 150 --seed 1000   # rewrite tests/gcode/data/rs274

``record`` keeps only programs nczones matches and writes them with rs274's parsed motion to
``tests/gcode/data/rs274/`` (``tests/gcode/test_rs274_recorded.py`` holds nczones to them without
rs274).  One program at a time, one process: it is meant to run beside other work.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
from collections import Counter
from fractions import Fraction
from pathlib import Path

from nczones.machine import parse_machine
from tests.oracles.rs274 import (
    WORK_OFFSETS,
    CanonMove,
    Outcome,
    canon_error,
    canon_motion,
    compare,
    machine_text,
    tool_table,
    var_file,
)

DATA = Path(__file__).resolve().parents[1] / "gcode" / "data" / "rs274"
RS274 = os.environ.get("RS274", "/usr/bin/rs274")

#: Pythagorean directions: points of the circle of radius 5 with integer coordinates.
CIRCLE5 = [(5, 0), (4, 3), (3, 4), (0, 5), (-3, 4), (-4, 3), (-5, 0), (-4, -3), (-3, -4), (0, -5), (3, -4), (4, -3)]
PLANES = {"G17": ("X", "Y", "Z", "I", "J", "K"), "G18": ("Z", "X", "Y", "K", "I", "J"),
          "G19": ("Y", "Z", "X", "J", "K", "I")}


class Generator:
    """One random LinuxCNC program and the machine it runs on."""

    def __init__(self, seed: int):
        self.r = random.Random(seed)
        r = self.r
        self.axes = ("X", "Y", "Z", "A") if r.random() < 0.25 else ("X", "Y", "Z")
        self.tools = {n: Fraction(r.randint(-200, 4000), 1000) for n in range(1, 5)}
        #: work offsets from the parameter file (inches; A in degrees), in two programs of five
        self.work_offsets: dict[str, dict[str, Fraction]] = {}
        if r.random() < 0.4:
            for name in r.sample(WORK_OFFSETS, r.randint(1, 4)):
                self.work_offsets[name] = {a: Fraction(r.randint(-3000, 3000), 1000) for a in self.axes
                                      if r.random() < 0.8}
        self.lines: list[str] = []
        self.subs: list[str] = []
        self.units = "G21"
        self.dist = "G90"
        self.plane = "G17"
        self.ijk = "G91.1"
        self.feed_mode = "G94"
        self.cycle = False
        self.onum = 100
        self.depth = 0

    # ---- numbers
    def num(self, lo: float = -40, hi: float = 40, places: int | None = None) -> str:
        r = self.r
        if self.units == "G20":
            lo, hi = lo / 25, hi / 25
        places = r.choice([0, 0, 1, 2, 3, 4]) if places is None else places
        v = round(r.uniform(lo, hi), places)
        s = f"{v:.{places}f}"
        return "0" if s in ("-0", "0") else s

    def coord(self, axis: str) -> str:
        r = self.r
        if axis == "A":
            return f"A{self.num(-90, 90, r.choice([0, 1, 3]))}"
        if self.dist == "G91":
            return f"{axis}{self.num(-15, 15)}"
        roll = r.random()
        if roll < 0.2:
            return f"{axis}[#<_{axis.lower()}>+{self.num(-10, 10)}]"
        if roll < 0.3:
            return f"{axis}[#1+{self.num(-5, 5)}]"
        return f"{axis}{self.num()}"

    def axis_words(self, k: int | None = None) -> str:
        axes = list(self.axes)
        k = k if k is not None else self.r.randint(1, len(axes))
        return " ".join(self.coord(a) for a in sorted(self.r.sample(axes, k), key=axes.index))

    def feed(self, force: bool = False) -> str:
        r = self.r
        if self.feed_mode == "G93":
            return f" F{r.choice(['10', '50', '200.5'])}" if force or r.random() < 0.97 else ""
        if self.feed_mode == "G95":
            return f" F{r.choice(['0.1', '0.25', '1'])}" if force or r.random() < 0.1 else ""
        return f" F{r.choice(['100', '250', '1000', '37.5'])}" if force or r.random() < 0.05 else ""

    # ---- blocks
    def modal(self) -> list[str]:
        r = self.r
        roll = r.randrange(11)
        if roll == 0:
            # rs274's canon layer hands the tool length back unconverted after G20/G21
            # (saicanon GET_EXTERNAL_TOOL_LENGTH_ZOFFSET), real LinuxCNC converts it: switch without one
            self.units = r.choice(["G20", "G21"])
            return ["G49", self.units]
        if roll == 1:
            self.dist = r.choice(["G90", "G91"])
            return [self.dist]
        if roll == 2:
            self.plane = r.choice(["G17", "G17", "G18", "G19"])
            return [self.plane]
        if roll == 3:
            self.ijk = r.choice(["G90.1", "G91.1"])
            return [self.ijk]
        if roll == 4:
            return [r.choice(["G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"])]
        if roll == 5:
            self.feed_mode = r.choice(["G94", "G94", "G93", "G95"])
            f = self.feed(force=r.random() < 0.9)
            return [self.feed_mode + f]
        if roll == 6:
            return [r.choice(["M3 S1000", "M4 S500", "M5", "S2000", "M8", "M9", "M7", "G64 P0.01", "G61", "G61.1",
                              "M70", "M72", "M19 R90"])]
        if roll == 7:
            return [f"F{r.choice(['100', '80', '2000'])}"]
        if roll == 8:
            return [f"#1 = {self.num(-5, 5)}", f"#<d> = [#1 * {r.choice(['2', '0.5', '-1'])}]"][: r.randint(1, 2)]
        if roll == 9:
            return [r.choice(["G98", "G99"])]
        return [r.choice(["G80", "G40", "G49", "G97", "G96 S100 D2000"])]

    def straight(self) -> list[str]:
        r = self.r
        code = r.choice(["G0", "G1", "G1", "G1", "G0", ""])
        f = self.feed() if code != "G0" else ""
        words = self.axis_words()
        return [f"{code} {words}{f}".strip()]

    def arc(self) -> list[str]:
        r = self.r
        fa, sa, na, fi, si, ni = PLANES[self.plane]
        s = r.choice([1, 1, 2, 0.5, 0.2]) * (0.04 if self.units == "G20" else 1)
        cx, cy = r.choice(CIRCLE5)  # centre relative to the start
        ex, ey = r.choice(CIRCLE5)  # end relative to the centre
        full = r.random() < 0.15
        if full:
            ex, ey = -cx, -cy
        code = r.choice(["G2", "G3"])

        def fmt(v: float) -> str:
            t = f"{v:.4f}".rstrip("0").rstrip(".")
            return "0" if t in ("-0", "") else t

        dx, dy = (cx + ex) * s, (cy + ey) * s
        if self.dist == "G91":
            end = f"{fa}{fmt(dx)} {sa}{fmt(dy)}"
        else:
            end = f"{fa}[#<_{fa.lower()}>+{fmt(dx)}] {sa}[#<_{sa.lower()}>+{fmt(dy)}]"
        if full and r.random() < 0.5:
            end = ""
        if r.random() < 0.3 and not full:
            radius = 5 * s * r.choice([1, 1, 1.5, 3])
            if r.random() < 0.3:
                radius = -radius
            centre = f"R{fmt(radius)}"
        elif self.ijk == "G90.1":
            centre = f"{fi}[#<_{fa.lower()}>+{fmt(cx * s)}] {si}[#<_{sa.lower()}>+{fmt(cy * s)}]"
        else:
            centre = f"{fi}{fmt(cx * s)} {si}{fmt(cy * s)}"
        extra = ""
        if r.random() < 0.25:
            extra += " " + (f"{na}{self.num(-5, 5)}" if self.dist == "G91" else f"{na}[#<_{na.lower()}>+{self.num(-5, 5)}]")
        if r.random() < 0.15 and "R" not in centre:
            extra += f" P{r.choice([1, 2, 3])}"
        if "A" in self.axes and r.random() < 0.1:
            extra += " " + self.coord("A")
        return [f"{code} {end} {centre}{extra}{self.feed()}".replace("  ", " ")]

    def offsets(self) -> list[str]:
        r = self.r
        roll = r.randrange(12)
        p = r.choice([0, 1, 1, 2, 3, 9])
        if roll == 0:
            rot = f" R{self.num(-45, 45, r.choice([0, 1, 3]))}" if r.random() < 0.3 else ""
            return [f"G10 L2 P{p} {self.axis_words()}{rot}"]
        if roll == 1:
            return [f"G10 L20 P{p} {self.axis_words()}"]
        if roll == 2:
            t = r.randint(1, 4)
            lcode = r.choice(["L1", "L10", "L11"])
            return [f"G10 {lcode} P{t} Z{self.num(-20, 60)}", r.choice([f"G43 H{t}", "G43", "G49", "G0 X0"])]
        if roll == 3:
            return [r.choice(["G43 H1", "G43 H2", "G43 H3", "G43", "G49", "G43 H0"])]
        if roll == 4:
            return [f"G43.1 Z{self.num(-30, 30)}" if r.random() < 0.8 else f"G1 G43.1 Z{self.num(-30, 30)}{self.feed()}"]
        if roll == 5:
            t = r.randint(0, 4)
            # rs274's own canon layer keeps no tool offset in the position it hands back after a tool change
            # (saicanon GET_EXTERNAL_POSITION): a move right before M6 or M61 keeps the two in step, and G43
            # goes on a line of its own
            sync = "G0 X0" if self.dist == "G91" else "G0 X[#<_x>]"
            return r.choice([[sync, f"T{t} M6"], [sync, f"T{t} M6", "G43"], [f"T{t}"], [sync, "M6"],
                             [sync, f"M61 Q{t}"]])
        if roll == 6:
            return [f"G92 {self.axis_words()}"]
        if roll == 7:
            return [r.choice(["G92.1", "G92.2", "G92.3"])]
        if roll == 8:
            return [f"G52 {self.axis_words()}"]
        if roll == 9:
            return [r.choice(["G28", "G30", "G28.1", "G30.1", f"G28 {self.axis_words(r.randint(1, 2))}",
                              f"G30 {self.axis_words(1)}"])]
        if roll == 10:
            return [f"G53 G{r.choice([0, 1])} {self.axis_words()}{self.feed()}"]
        if r.random() < 0.5:
            return [f"G4 P{r.choice(['0.5', '1', '0', '2.25', '[#1 * #1]'])}"]
        if self.dist == "G91":
            return [f"G33 {self.axis_words(r.randint(1, 2))} K{self.num(0.5, 2, 1)}",
                    f"G33.1 Z{self.num(-5, -0.5)} K{self.num(0.5, 2, 1)}"][: r.randint(1, 2)]
        return [r.choice([f"G33 Z[#<_z>+{self.num(-5, -0.5)}] K1", f"G33.1 X[#<_x>] Z[#<_z>+{self.num(-5, -0.5)}] K1.5"])]

    def canned(self) -> list[str]:
        r = self.r
        code = r.choice(["G81", "G82", "G83", "G73", "G85", "G89", "G84", "G86"])
        extra = ""
        if code in ("G83", "G73"):
            extra += f" Q{r.choice(['0.5', '1', '2.5'])}" if self.units == "G21" else " Q0.04"
        if code in ("G82", "G89", "G86"):
            extra += f" P{r.choice(['0.5', '1'])}"
        fa, sa, na, *_ = PLANES[self.plane]
        if self.dist == "G91":
            pos = f"{fa}{self.num(-10, 10)} {sa}{self.num(-10, 10)} {na}{self.num(-8, -0.5)} R{self.num(-2, 5)}"
            if r.random() < 0.4:
                extra += f" L{r.randint(2, 4)}"
        else:
            pos = (f"{fa}[#<_{fa.lower()}>+{self.num(-10, 10)}] {sa}{self.num()} "
                   f"{na}[#<_{na.lower()}>+{self.num(-8, -0.5)}] R[#<_{na.lower()}>+{self.num(-2, 5)}]")
        lines = [f"{r.choice(['G98', 'G99', ''])} {code} {pos}{extra}{self.feed()}".strip()]
        for _ in range(r.randint(0, 3)):
            lines.append(f"{fa}{self.num(-10, 10)} {sa}{self.num(-10, 10)}" if self.dist == "G91"
                         else f"{fa}{self.num()} {sa}[#<_{sa.lower()}>+{self.num(-5, 5)}]")
        if r.random() < 0.8:
            lines.append("G80")
        return lines

    def control(self) -> list[str]:
        r = self.r
        if self.depth > 1:
            return self.block()
        self.depth += 1
        n = self.onum
        self.onum += 1
        roll = r.randrange(4)
        body = [ln for _ in range(r.randint(1, 3)) for ln in self.block()]
        if roll == 0:
            other = [ln for _ in range(r.randint(0, 2)) for ln in self.block()]
            out = [f"o{n} if [#<_{r.choice(['x', 'y', 'z'])}> GT {self.num(-5, 5)}]", *body]
            if other:
                out += [f"o{n} else", *other]
            out.append(f"o{n} endif")
        elif roll == 1:
            out = [f"#{n} = 0", f"o{n} while [#{n} LT {r.randint(1, 3)}]", *body, f"#{n} = [#{n} + 1]",
                   f"o{n} endwhile"]
        elif roll == 2:
            out = [f"o{n} repeat [{r.randint(1, 3)}]", *body, f"o{n} endrepeat"]
        else:
            self.subs += [f"o{n} sub", *[ln.replace("#1", "#2") for ln in body], f"o{n} endsub"]
            out = [f"o{n} call [{self.num(-5, 5)}] [{self.num(-5, 5)}]"]
            if r.random() < 0.3:
                out.append(out[0])
        self.depth -= 1
        return out

    def block(self) -> list[str]:
        r = self.r
        roll = r.random()
        if roll < 0.18:
            return self.modal()
        if roll < 0.48:
            return self.straight()
        if roll < 0.66:
            return self.arc()
        if roll < 0.84:
            return self.offsets()
        if roll < 0.93:
            return self.canned()
        return self.control()

    def program(self) -> str:
        r = self.r
        head = []
        if r.random() < 0.7:
            head.append(" ".join(r.sample(["G21", "G90", "G17", "G54", "G94", "G40", "G49", "G80"], r.randint(1, 5))))
        head.append(f"F{r.choice(['100', '500'])}")
        if r.random() < 0.85:
            head.append(r.choice(["M3 S1000", "M4 S300", "S500 M3"]))
        head.append("#1 = 0")
        body = [ln for _ in range(r.randint(10, 45)) for ln in self.block()]
        return "\n".join([*self.subs, *head, *body, "M2"]) + "\n"


Setup = tuple  # (machine axes, tool table in inches, work offsets in inches)


def generate(seed: int) -> tuple[str, Setup]:
    """(program, setup) of one seed."""
    g = Generator(seed)
    text = g.program()
    return text, (g.axes, g.tools, g.work_offsets)


def machine_of(setup: Setup):
    axes, tools, offsets = setup
    return parse_machine(machine_text(axes, tools, offsets))


def run_rs274(program: str, setup: Setup, workdir: Path,
              timeout: float = 20) -> tuple[list[CanonMove], tuple[str, str] | None, str]:
    """rs274's motions, error and raw log of one program (a fresh tool table and parameter file)."""
    _axes, tools, offsets = setup
    (workdir / "prog.ngc").write_text(program)
    (workdir / "tool.tbl").write_text(tool_table(tools))
    for stale in workdir.glob("*.var*"):
        stale.unlink()
    (workdir / "prog.var").write_text(var_file(offsets))
    try:
        p = subprocess.run([RS274, "-t", "tool.tbl", "-v", "prog.var", "-g", "prog.ngc"], cwd=workdir,
                           capture_output=True, text=True, errors="replace", timeout=timeout, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return [], ("rs274 timed out", ""), ""
    return canon_motion(p.stdout), canon_error(p.returncode, p.stderr), p.stdout


def outcome(program: str, setup: Setup, workdir: Path) -> Outcome:
    moves, error, _ = run_rs274(program, setup, workdir)
    machine = machine_of(setup)
    try:
        return compare(program, machine, moves, error)
    except Exception as exc:  # noqa: BLE001 - an internal error of nczones is a finding too
        return Outcome("crash", f"{type(exc).__name__}: {exc}")


def signature(o: Outcome) -> tuple[str, str]:
    """What a minimised program must keep: the status and the kind of difference."""
    import re

    d = re.sub(r"prog\.ngc:\d+:\d+: ", "", o.detail)
    d = re.sub(r"[-\d.]+", "#", d)
    return o.status, d.split("/")[-1][:40] if o.status == "error-line" else d[:30]


def minimise(program: str, setup: Setup, workdir: Path, status) -> tuple[str, Outcome]:
    """Drop lines (then chunks of lines) while the outcome keeps its signature."""
    lines = program.splitlines()
    best = outcome(program, setup, workdir)
    chunk = max(1, len(lines) // 4)
    while chunk >= 1:
        i = 0
        while i < len(lines) - 1:  # keep the final M2
            cand = lines[:i] + lines[i + chunk:]
            if not cand or cand[-1] != "M2":
                i += chunk
                continue
            o = outcome("\n".join(cand) + "\n", setup, workdir)
            if signature(o) == status:
                lines, best = cand, o
            else:
                i += chunk
        chunk //= 2
    return "\n".join(lines) + "\n", best


def cmd_run(args) -> int:
    counts: Counter = Counter()
    found: list[tuple[int, str, Outcome]] = []
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for seed in range(args.seed, args.seed + args.count):
            text, setup = generate(seed)
            o = outcome(text, setup, work)
            counts[o.status] += 1
            if o.status not in ("match", "unknown"):
                small, mo = minimise(text, setup, work, signature(o)) if args.minimise else (text, o)
                found.append((seed, small, mo))
                print(f"--- seed {seed} {mo.status}: {mo.detail}\n    axes {setup[0]} tools "
                      f"{ {k: str(v) for k, v in setup[1].items()} } offsets {setup[2]}\n"
                      + "".join(f"    | {ln}\n" for ln in small.splitlines()), flush=True)
            elif o.status == "unknown" and args.verbose:
                print(f"--- seed {seed} unknown: {o.detail}", flush=True)
    print("outcomes:", dict(counts))
    return 0


def cmd_record(args) -> int:
    DATA.mkdir(parents=True, exist_ok=True)
    for old in DATA.glob("*.ngc"):
        old.unlink()
    index = {}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        seed = args.seed
        while len(index) < args.count and seed < args.seed + 20 * args.count:
            text, setup = generate(seed)
            axes, tools, offsets = setup
            moves, error, _ = run_rs274(text, setup, work)
            machine = machine_of(setup)
            o = compare(text, machine, moves, error)
            refused = sum(1 for c in index.values() if c["error"])
            wanted = len(moves) >= 5 if error is None else refused < args.count // 4  # mostly programs that run
            if o.status == "match" and wanted and all(m.kind != "UNPARSED" for m in moves):
                name = f"g{seed:05d}"
                (DATA / f"{name}.ngc").write_text(text)
                index[name] = {"axes": list(axes), "tools_inch": {str(k): str(v) for k, v in tools.items()},
                               "offsets_inch": {k: {a: str(v) for a, v in o.items()} for k, o in offsets.items()},
                               "error": list(error) if error else None, "motion": [m.to_json() for m in moves]}
            seed += 1
    (DATA / "expected.json").write_text(json.dumps(index, separators=(",", ":"), sort_keys=True) + "\n")
    print(f"recorded {len(index)} programs in {DATA}")
    return 0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    run = sub.add_parser("run")
    run.add_argument("--count", type=int, default=200)
    run.add_argument("--seed", type=int, default=1)
    run.add_argument("--no-minimise", dest="minimise", action="store_false")
    run.add_argument("--verbose", action="store_true")
    rec = sub.add_parser("record")
    rec.add_argument("--count", type=int, default=150)
    rec.add_argument("--seed", type=int, default=100000)
    args = ap.parse_args(argv)
    if not Path(RS274).exists():
        print(f"{RS274} not found (LinuxCNC's standalone interpreter, package linuxcnc-uspace)", file=sys.stderr)
        return 2
    return cmd_run(args) if args.cmd == "run" else cmd_record(args)


if __name__ == "__main__":
    sys.exit(main())
