"""Differential of LinuxCNC's modal save/restore (M70, M71, M72, M73) against ``rs274 -g``.

Generated programs save the modal state (M70 in the main program, M73 or M70 in o-word and M98 subroutines),
change every group LinuxCNC's ``save_settings`` keeps (units, distance and arc-centre modes, plane, work
offset, feed mode and F, retract mode, tool length G43/G49/G43.1 and tool changes, G92/G52 applied or not,
lathe diameter mode G7/G8), restore it (M72, or the return of an M73 subroutine; M71 in between) and then
move in ways that show each group: straight moves in both distance modes, arcs in the plane with I/J/K,
a drilling cycle (its retract), feed moves (a restored F below 0.05 is F0: LinuxCNC refuses the move).

    python -m tests.tools.rs274_modal run --count 300 --seed 1        # compare (rs274 installed)
    python -m tests.tools.rs274_modal record --count 60 --seed 5000   # rewrite tests/gcode/data/rs274_modal

``record`` writes the programs and rs274's parsed motion (or error) to ``tests/gcode/data/rs274_modal/``;
``tests/gcode/test_rs274_modal.py`` holds nczones to them without rs274 (and to rs274 itself where installed).
"""

from __future__ import annotations

import argparse
import json
import os
import random
import re
import sys
import tempfile
from collections import Counter
from fractions import Fraction
from pathlib import Path

from tests.oracles.rs274 import compare
from tests.tools.rs274_diff import RS274, machine_of, run_rs274

DATA = Path(__file__).resolve().parents[1] / "gcode" / "data" / "rs274_modal"


class ModalGenerator:
    """One program: state changes around saves and restores, with moves that show the state."""

    def __init__(self, seed: int):
        self.r = random.Random(seed)
        r = self.r
        self.axes = ("X", "Y", "Z")
        self.tools = {n: Fraction(r.randint(50, 3000), 1000) for n in range(1, 4)}
        self.work_offsets = {"G55": {"X": Fraction(r.randint(-2000, 2000), 1000), "Y": Fraction(r.randint(-2000, 2000), 1000),
                                     "Z": Fraction(r.randint(-500, 500), 1000)},
                             "G56": {"X": Fraction(r.randint(-2000, 2000), 1000), "Z": Fraction(r.randint(-500, 500), 1000)}}
        self.lathe = r.random() < 0.2  # G7/G8 in the mix (the lathe interpreter)
        self.subs: list[str] = []
        self.onum = 100

    def num(self, lo: int = -20, hi: int = 20) -> str:
        v = self.r.randint(lo * 10, hi * 10) / 10
        return f"{v:g}"

    def change(self) -> str:
        r = self.r
        opts = [
            lambda: r.choice(["G20", "G21"]),
            lambda: r.choice(["G90", "G91"]),
            lambda: r.choice(["G90.1", "G91.1"]),
            lambda: r.choice(["G17", "G18", "G19"]),
            lambda: r.choice(["G54", "G55", "G56"]),
            lambda: r.choice(["G94 F" + r.choice(["100", "250.5", "12.34", "0.04", "0.06", "7.25"]),
                              "M3 S1000 G95 F" + r.choice(["0.1", "0.04", "0.25"]), "F" + r.choice(["80", "0.03", "33.35"])]),
            lambda: r.choice(["G98", "G99"]),
            # (no tool change here: rs274's position after M6 is helper lcnc-machine's subject)
            lambda: r.choice(["G43 H1", "G43 H2", "G43 H3", "G49", "G43", "G43.1 Z" + self.num(-5, 5)]),
            lambda: r.choice(["M3 S1000", "M4 S250.6", "M5", "S0", "S12.5"]),
            lambda: r.choice([f"G92 X{self.num()} Y{self.num()}", f"G92 Z{self.num(-5, 5)}", "G92.1", "G92.2",
                              "G92.3", f"G52 X{self.num(-5, 5)}", f"G10 L2 P2 X{self.num()} Z{self.num(-3, 3)}"]),
        ]
        if self.lathe:
            opts.append(lambda: r.choice(["G7", "G8"]))
        return r.choice(opts)()

    def changes(self, k: int) -> list[str]:
        return [self.change() for _ in range(k)]

    def probe(self) -> list[str]:
        """Moves whose machine positions show the modal state."""
        r = self.r
        out = ["G17 G0 X{} Y{} Z{}".format(self.num(), self.num(), self.num(0, 10)) if r.random() < 0.3 else
               "G0 X{} Y{} Z{}".format(self.num(), self.num(), self.num(0, 10))]
        kind = r.random()
        if kind < 0.25:
            out.append(f"G1 X{self.num()} Y{self.num()}")
        elif kind < 0.5:  # valid in every plane and distance mode: shows the plane and the distance mode
            out.append(f"G1 Z{self.num(-5, 5)} F{r.choice(['100', '50'])}")
            out.append(f"{r.choice(['G2', 'G3'])} X{self.num()} Y{self.num()} Z{self.num(-5, 5)} R50")
        elif kind < 0.6:  # a full circle from X2 Y0 with I1: centre X3 in G91.1, X1 in G90.1
            out += ["G90 G17 G0 X2 Y0", r.choice(["G2 X2 Y0 I1 J0", "G3 X2 Y0 I1 J0.5"])]
        elif kind < 0.8:
            out.append(f"G81 X{self.num()} Y{self.num()} Z{self.num(-8, -1)} R{self.num(0, 3)} F100")
            out.append(f"X{self.num()}")
            out.append("G80")
        else:
            out.append(f"G91 G0 X{self.num(-3, 3)} Z{self.num(-3, 3)}")
            out.append(f"G1 X{self.num(-3, 3)}")
        return out

    def save_restore(self) -> list[str]:
        r = self.r
        kind = r.random()
        if kind < 0.35:  # M70 ... M72 in the main program
            lines = ["M70", *self.changes(r.randint(1, 4)), *self.probe()]
            if r.random() < 0.15:  # invalidated, saved again
                lines += ["M71", *self.changes(1), "M70", *self.changes(1)]
            lines.append("M72")
            return lines + self.probe()
        if kind < 0.75:  # M73 in an o-word subroutine, restored on return
            n = self.onum
            self.onum += 1
            body = ["M73", *self.changes(r.randint(1, 4)), *self.probe()]
            if r.random() < 0.15:
                body += r.choice([["M71"], ["M70", *self.changes(1)], ["M72"]])
            ending = f"o{n} return" if r.random() < 0.3 else ""
            self.subs += [f"o{n} sub", *body] + ([ending] if ending else []) + [f"o{n} endsub"]
            return [f"o{n} call", *self.probe()]
        if kind < 0.93:  # M73 in an M98 subprogram (restored at M99)
            n = self.onum
            self.onum += 1
            self.fanuc = getattr(self, "fanuc", []) + [f"O{n}", "M73", *self.changes(r.randint(1, 3)), *self.probe(),
                                                        "M99"]
            return [f"M98 P{n}", *self.probe()]
        # a save in the main program, a restore attempted inside a subroutine (its own frame: an error)
        n = self.onum
        self.onum += 1
        self.subs += [f"o{n} sub", *self.changes(1), "M72", f"o{n} endsub"]
        return ["M70", *self.changes(2), f"o{n} call", *self.probe()]

    def program(self) -> str:
        r = self.r
        head = ["G21 G90 G17 G54 G94 F100", "T1 M6", r.choice(["G43", "G49", "G43 H2"])]
        if self.lathe:
            head.append(r.choice(["G7", "G8"]))
        body: list[str] = []
        for _ in range(r.randint(1, 3)):
            body += self.changes(r.randint(0, 2)) + self.save_restore()
        tail = ["M2"] + getattr(self, "fanuc", [])
        return "\n".join([*self.subs, *head, *body, *tail]) + "\n"


def generate(seed: int) -> tuple[str, tuple]:
    g = ModalGenerator(seed)
    text = g.program()
    return text, (g.axes, g.tools, g.work_offsets)


def private_home(tmp: str) -> None:
    """rs274 (LinuxCNC 2.9's tooldata_mmap.cc) keeps its tool table in ``$HOME/.tool.mmap``: rs274 runs of other
    processes with the same HOME overwrite each other's tools.  Each run here gets its own HOME."""
    os.environ["HOME"] = tmp


_LENGTH_CHANGE = re.compile(r"G43|G49|M72|M73")


def explained(text: str, o) -> bool:
    """A Z difference in a program that switches to inches and changes or restores the tool length: the
    standalone rs274's tool offset is not converted at G20/G21 (saicanon ``GET_EXTERNAL_TOOL_LENGTH_ZOFFSET``),
    real LinuxCNC's is (specs/gcode-support.md, "Modal save/restore differential")."""
    return o.status == "path" and " axis Z:" in o.detail and "G20" in text and _LENGTH_CHANGE.search(text) is not None


def cmd_run(args) -> int:
    counts: Counter = Counter()
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        private_home(tmp)
        for seed in range(args.seed, args.seed + args.count):
            text, setup = generate(seed)
            moves, error, _ = run_rs274(text, setup, work)
            o = compare(text, machine_of(setup), moves, error)
            status = "explained" if explained(text, o) else o.status
            counts[status] += 1
            if status not in ("match", "explained") and (status != "unknown" or args.verbose):
                print(f"--- seed {seed} {o.status}: {o.detail}\n" + "".join(f"    | {ln}\n" for ln in text.splitlines()),
                      flush=True)
    print("outcomes:", dict(counts))
    return 0


def cmd_record(args) -> int:
    DATA.mkdir(parents=True, exist_ok=True)
    for old in DATA.glob("*.ngc"):
        old.unlink()
    index = {}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        private_home(tmp)
        for seed in range(args.seed, args.seed + args.count):
            text, setup = generate(seed)
            axes, tools, offsets = setup
            moves, error, _ = run_rs274(text, setup, work)
            o = compare(text, machine_of(setup), moves, error)
            if o.status != "match":  # an explained mismatch (specs/gcode-support.md): not recorded
                print(f"seed {seed} not recorded: {o.status} {o.detail}")
                continue
            name = f"m{seed:05d}"
            (DATA / f"{name}.ngc").write_text(text)
            index[name] = {"axes": list(axes), "tools_inch": {str(k): str(v) for k, v in tools.items()},
                           "offsets_inch": {k: {a: str(v) for a, v in o.items()} for k, o in offsets.items()},
                           "error": list(error) if error else None, "motion": [m.to_json() for m in moves]}
    (DATA / "expected.json").write_text(json.dumps(index, separators=(",", ":"), sort_keys=True) + "\n")
    print(f"recorded {len(index)} programs in {DATA}")
    return 0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    run = sub.add_parser("run")
    run.add_argument("--count", type=int, default=300)
    run.add_argument("--seed", type=int, default=1)
    run.add_argument("--verbose", action="store_true")
    rec = sub.add_parser("record")
    rec.add_argument("--count", type=int, default=60)
    rec.add_argument("--seed", type=int, default=5000)
    args = ap.parse_args(argv)
    if not Path(RS274).exists():
        print(f"{RS274} not found (LinuxCNC's standalone interpreter, package linuxcnc-uspace)", file=sys.stderr)
        return 2
    return cmd_run(args) if args.cmd == "run" else cmd_record(args)


if __name__ == "__main__":
    sys.exit(main())
