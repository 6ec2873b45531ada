"""Benchmark of the Fanuc dialect (a script, not a test).

    python bench/bench_fanuc.py [--lines 200000] [--macro-lines 100000] [--naive-lines 50000] [--runs 3]

Two targets of issue 22:

* Custom Macro B programs through the full interpreter: at least 100,000 executed lines per second
  (every line the language layer executes counts, once per loop iteration: WHILE, END, assignments,
  IF, GOTO, the G65 call and the macro's lines included);
* Fanuc CAM output (a program number, the safety line, runs of ``X.. Y..``/``G1 X.. Y.. F..`` lines
  with decimal points, M30) on the vectorized fast path: at least 1,000,000 lines per second.

Each case runs in a fresh process (``bench/_bench.py``), the least CPU of ``--runs``; the clock starts
after the G-code modules are imported and a 100-line program of the same kind has run (importing and
compiling regular expressions is a per-process cost; ``bench_gcode.py`` prints it on its own).  The CAM
program is also run through the full interpreter alone (``fast=False``, the naive way) for the ratio and in
the LinuxCNC dialect (without its program number and ``%`` lines) for comparison, and the macro program in
the LinuxCNC dialect's equivalent (``o100 while``).
"""

from __future__ import annotations

import argparse
import random
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _bench import Clock, emit, machine_description, run_case  # noqa: E402

MACHINE = """
[machine]
dialect = "{dialect}"
axes = ["X", "Y", "Z"]
pulse = "0.001"
[machine.rapid]
X = "30000"
Y = "30000"
Z = "30000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[tool_lengths]
H1 = "100"
"""


def cam_program(n: int, seed: int = 7) -> str:
    """Fanuc-style CAM output: every length with a decimal point, modal G01 moves."""
    rnd = random.Random(seed)
    out = ["%", "O1000 (CAM)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0.", "G43 H1 Z25.", "G01 Z-1. F800."]
    for i in range(n - 8):
        if i % 50 == 0:
            out.append(f"G01 X{rnd.uniform(0, 300):.3f} Y{rnd.uniform(0, 200):.3f} F{rnd.randint(500, 2000)}.")
        else:
            out.append(f"X{rnd.uniform(0, 300):.3f} Y{rnd.uniform(0, 200):.3f}")
    out += ["M30", "%"]
    return "\n".join(out) + "\n"


def holes_program(n: int, seed: int = 11, dialect: str = "fanuc") -> str:
    """A CAM drilling list: a ``G98 G81`` block, then ``n`` lines of X and Y (four motions a hole), Fanuc words
    (decimal points) or, with ``dialect="linuxcnc"``, the same holes in LinuxCNC's (rs274's peer program)."""
    rnd = random.Random(seed)
    fanuc = dialect == "fanuc"
    head = (["%", "O1000 (HOLES)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0.", "G43 H1 Z25."] if fanuc else
            ["G17 G40 G49 G80 G90 G21", "G54 G0 X0 Y0", "G43 H1 Z25"])
    out = head + ["G98 G81 X0. Y0. Z-2. R2. F300." if fanuc else "G98 G81 X0 Y0 Z-2 R2 F300"]
    out += [f"X{rnd.uniform(0, 500):.3f} Y{rnd.uniform(0, 300):.3f}" for _ in range(n)]
    out += ["G80", "M30", "%"] if fanuc else ["G80", "M30"]
    return "\n".join(out) + "\n"


#: A macro loop: per iteration WHILE, four assignments, an IF, a move, END (8 executed lines).
MACRO_BODY = 8


def macro_program(lines: int) -> str:
    reps = max(1, lines // MACRO_BODY)
    return "\n".join([
        "O2000 (SPIRAL)", "G90 G17 G21 G54 F800.", "#1 = 0", "#5 = 0",
        f"WHILE [#1 LT {reps}] DO1",
        "#2 = #1 * 0.01",
        "#3 = #2 * COS[#1 * 3.6]",
        "#4 = #2 * SIN[#1 * 3.6]",
        "IF [#4 GT 1000] THEN #5 = #5 + 1",
        "G01 X#3 Y#4",
        "#1 = #1 + 1",
        "END1", "M30"]) + "\n"


def call_program(lines: int) -> str:
    """G65 calls: per iteration WHILE, the call, the macro's three lines (G0, G1, M99), the increment, END."""
    reps = max(1, lines // 7)
    return "\n".join([
        "O3000 (HOLES)", "G90 G17 G21 G54 F300.", "#1 = 0",
        f"WHILE [#1 LT {reps}] DO1",
        "G65 P9010 X[#1 * 0.1] Y[#1 * 0.05] D2.",
        "#1 = #1 + 1",
        "END1", "M30",
        "O9010 (ONE HOLE)", "G00 X#24 Y#25", "G01 Z-#7", "M99"]) + "\n"


def subprogram_program(lines: int) -> str:
    """M98 calls: per iteration WHILE, the call, the subprogram's three lines (G0 with expressions, G1, M99),
    the increment, END."""
    reps = max(1, lines // 6)
    return "\n".join([
        "O4000 (SUBS)", "G90 G17 G21 G54 F300.", "#1 = 0",
        f"WHILE [#1 LT {reps}] DO1", "M98 P9020", "#1 = #1 + 1", "END1", "M30",
        "O9020 (SUB)", "G00 X[#1 * 0.1] Y[#1 * 0.05]", "G01 Z-2.", "M99"]) + "\n"


def linuxcnc_macro_program(lines: int) -> str:
    reps = max(1, lines // MACRO_BODY)
    return "\n".join([
        "G90 G17 G21 G54 F800", "#1 = 0", "#5 = 0", "o100 while [#1 LT " + str(reps) + "]",
        "#2 = [#1 * 0.01]", "#3 = [#2 * COS[#1 * 3.6]]", "#4 = [#2 * SIN[#1 * 3.6]]",
        "o101 if [#4 GT 1000]", "#5 = [#5 + 1]", "o101 endif", "G01 X#3 Y#4", "#1 = [#1 + 1]",
        "o100 endwhile", "M30"]) + "\n"


def linuxcnc_call_program(lines: int) -> str:
    """The LinuxCNC equivalent of :func:`call_program` (rs274's peer of the G65 row): a sub with ``G0 X#1 Y#2``
    / ``G1 Z-#3`` called with three arguments per iteration."""
    reps = max(1, lines // 7)
    return "\n".join([
        "o9010 sub", "G0 X#1 Y#2", "G1 Z-#3", "o9010 endsub",
        "G90 G17 G21 G54 F300", "#1 = 0", f"o100 while [#1 LT {reps}]",
        "o9010 call [#1 * 0.1] [#1 * 0.05] [2]", "#1 = [#1 + 1]", "o100 endwhile", "M30"]) + "\n"


def linuxcnc_subprogram_program(lines: int) -> str:
    """The LinuxCNC equivalent of :func:`subprogram_program` (rs274's peer of the M98 row): a sub with
    ``G0 X[#31 * 0.1] Y[#31 * 0.05]`` / ``G1 Z-2.`` called without arguments, #31 the global counter."""
    reps = max(1, lines // 6)
    return "\n".join([
        "o9020 sub", "G0 X[#31 * 0.1] Y[#31 * 0.05]", "G1 Z-2.", "o9020 endsub",
        "G90 G17 G21 G54 F300", "#31 = 0", f"o100 while [#31 LT {reps}]",
        "o9020 call", "#31 = [#31 + 1]", "o100 endwhile", "M30"]) + "\n"


def _xform_moves(n: int, rnd: random.Random, fanuc: bool) -> list[str]:
    """``n`` lines of CAM moves about the origin (``X.. Y..``, a ``G01`` with F every 50th line, an I/J arc
    every 25th: a quarter circle back to the line's start, so the path stays where it was), Fanuc words (decimal
    points) or LinuxCNC's."""
    out = []
    x = y = 0.0
    pt = "." if fanuc else ""
    after_arc = False
    for i in range(n):
        if i % 25 == 12:  # a quarter circle from (x, y) to (x + 2, y + 2)
            if i % 50 == 12:  # CCW about (x, y + 2)
                out.append(f"G03 X{x + 2:.3f} Y{y + 2:.3f} I0{pt} J2{pt}")
            else:  # CW about (x + 2, y)
                out.append(f"G02 X{x + 2:.3f} Y{y + 2:.3f} I2{pt} J0{pt}")
            x, y = x + 2, y + 2
            after_arc = True
            continue
        x, y = rnd.uniform(-150, 150), rnd.uniform(-100, 100)
        if i % 50 == 0:
            out.append(f"G01 X{x:.3f} Y{y:.3f} F{rnd.randint(500, 2000)}{pt}")
        else:
            out.append(("G01 " if after_arc else "") + f"X{x:.3f} Y{y:.3f}")
        after_arc = False
    return out


def rotated_program(n: int, seed: int = 14, dialect: str = "fanuc") -> str:
    """About ``n`` lines of CAM moves under a coordinate rotation (issue 36): Fanuc ``G68 X0. Y0. R27.5`` (the
    rotated points certified and rounded to the increment), or with ``dialect="linuxcnc"`` the same moves under
    LinuxCNC's rotated work offset ``G10 L2 P1 R27.5`` (rs274's peer: LinuxCNC has no G68)."""
    rnd = random.Random(seed)
    if dialect == "fanuc":
        head = ["%", "O1000 (ROTATED)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0.", "G43 H1 Z25.",
                "G01 Z-1. F800.", "G68 X0. Y0. R27.5"]
        tail = ["G69", "G00 X0. Y0.", "M30", "%"]
    else:
        head = ["G17 G40 G49 G80 G90 G21", "G10 L2 P1 X0 Y0 R27.5", "G54 G0 X0 Y0", "G43 H1 Z25", "G1 Z-1 F800"]
        tail = ["M30"]
    body = _xform_moves(max(1, n - len(head) - len(tail)), rnd, dialect == "fanuc")
    if dialect != "fanuc":
        body = [line.replace("G01", "G1").replace("G02", "G2").replace("G03", "G3") for line in body]
    return "\n".join(head + body + tail) + "\n"


def scaled_program(n: int, seed: int = 17, dialect: str = "fanuc", factors: str = "P1.25") -> str:
    """About ``n`` lines of CAM moves under Fanuc scaling ``G51 X0. Y0. Z-1. P1.25`` (``factors`` may give
    ``I.. J.. K..`` instead; a point off the grid is rounded to the increment), or with ``dialect="linuxcnc"``
    rs274's peer: the same program unscaled, its numbers scaled beforehand (LinuxCNC has no G51)."""
    rnd = random.Random(seed)
    fanuc = dialect == "fanuc"
    if fanuc:
        # the centre's Z at the tool's (Z-1.): a Z the lines do not name then stays (G51 moving an axis a block does
        # not name is unknown, ``FanucInterpreter._unnamed_axis_moves``)
        head = ["%", "O1000 (SCALED)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0.", "G43 H1 Z25.",
                "G01 Z-1. F800.", f"G51 X0. Y0. Z-1. {factors}"]
        tail = ["G50", "G00 X0. Y0.", "M30", "%"]
    else:
        head = ["G17 G40 G49 G80 G90 G21", "G54 G0 X0 Y0", "G43 H1 Z25", "G1 Z-1 F800"]
        tail = ["M30"]
    body = _xform_moves(max(1, n - len(head) - len(tail)), rnd, fanuc)
    if not fanuc:
        f = float(factors[1:]) if factors.startswith("P") else 1.25
        body = [_scaled_words(line, f) for line in body]
    return "\n".join(head + body + tail) + "\n"


def _scaled_words(line: str, f: float) -> str:
    """A LinuxCNC line of :func:`_xform_moves` with its lengths (X Y I J) multiplied by ``f``, G words in
    LinuxCNC's spelling."""
    def one(m: re.Match) -> str:
        return f"{m.group(1)}{float(m.group(2)) * f:.4f}"
    line = line.replace("G01", "G1").replace("G02", "G2").replace("G03", "G3")
    return re.sub(r"([XYIJ])(-?[0-9.]+)", one, line)


def program(name: str, lines: int) -> tuple[str, int]:
    """The program of a case and the lines it executes."""
    if name in ("cam", "cam-naive"):
        return cam_program(lines), lines
    if name == "linuxcnc-cam":
        return "\n".join(line for line in cam_program(lines).splitlines()
                         if not line.startswith(("%", "O"))).replace("G00 G17", "G17") + "\n", lines
    if name == "macro":
        return macro_program(lines), 5 + (lines // MACRO_BODY) * MACRO_BODY + 1
    if name == "calls":
        return call_program(lines), 4 + (lines // 7) * 7 + 1
    return linuxcnc_macro_program(lines), 3 + (lines // MACRO_BODY) * MACRO_BODY + 2


def case(name: str, lines: int) -> None:
    from nczones.gcode import interpret_text
    from nczones.machine import parse_machine

    dialect = "linuxcnc" if name.startswith("linuxcnc") else "fanuc"
    machine = parse_machine(MACHINE.replace("{dialect}", dialect))
    text, executed = program(name, lines)
    for _chunk in interpret_text(program(name, 100)[0], machine, fast=name != "cam-naive"):
        pass
    with Clock() as c:
        run = interpret_text(text, machine, fast=name != "cam-naive")
        segments = sum(len(chunk) for chunk in run)
    assert run.status == "complete", run.unsupported
    emit({"case": name, "lines": executed, "segments": segments, "cpu": c.cpu, "wall": c.wall,
          "fast_lines": run.counts["fast_lines"]})


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=200_000, help="lines of the CAM program")
    ap.add_argument("--macro-lines", type=int, default=100_000, help="executed lines of the macro programs")
    ap.add_argument("--naive-lines", type=int, default=50_000, help="lines of the CAM program through the "
                                                                     "full interpreter alone")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--case")
    args = ap.parse_args()
    if args.case:
        case(args.case, args.lines)
        return
    print(f"nczones Fanuc dialect benchmark: {machine_description()}")
    me = str(Path(__file__).resolve())
    rows = [
        ("cam", args.lines, "Fanuc CAM output, fast path", 1_000_000),
        ("cam-naive", args.naive_lines, "the same through the full interpreter alone (naive)", None),
        ("linuxcnc-cam", args.lines, "the same CAM lines in the LinuxCNC dialect", None),
        ("macro", args.macro_lines, "Macro B: WHILE loop, assignments, COS/SIN, IF, a move", 100_000),
        ("calls", args.macro_lines, "Macro B: a G65 call per iteration", 100_000),
        ("linuxcnc-macro", args.macro_lines, "the same loop in the LinuxCNC dialect (o-words)", None),
    ]
    speeds = {}
    for name, lines, what, target in rows:
        r = run_case(me, "--case", name, "--lines", str(lines), runs=args.runs)
        speed = r["lines"] / r["cpu"]
        speeds[name] = speed
        verdict = "" if target is None else (f"  target {target:,}: " + ("met" if speed >= target else "NOT MET"))
        print(f"  {what:58} {r['lines']:>9,} lines  {speed:>12,.0f} lines/s (CPU)  "
              f"{r['peak_rss_mib']:6.1f} MiB{verdict}")
    print(f"  fast path / full interpreter on CAM output: {speeds['cam'] / speeds['cam-naive']:.1f}x")
    print(f"  Fanuc CAM output / the same lines in the LinuxCNC dialect: {speeds['cam'] / speeds['linuxcnc-cam']:.2f}x")
    print(f"  Fanuc macro loop / LinuxCNC o-word loop: {speeds['macro'] / speeds['linuxcnc-macro']:.2f}x")


if __name__ == "__main__":
    main()
