"""Cost of the tool-solids proof (issue 39, specs/machine-file.md "Tools and fixtures as solids") beside the
point-only verdict on the same program.

    python bench/bench_solids.py [--lines 1000000] [--profile] [--path-mode G64 [--path-tolerance 0.01]]

A generated CAM-like program (a 3-D surfacing raster of short ``G1`` moves over a 300 × 300 mm pocket, a
retract ``G0`` between passes, tool 1 with ``G43 H1``) is verified twice on one machine: without solids
(the controlled point against the zones: the point-only verdict) and with a three-solid tool assembly
(cutter, shank, holder) against ten fixtures (eight boxes and two cylinders around the pocket, near enough
that the holder passes within a few millimetres of some).  CPU seconds of each, side by side, and their
ratio (the issue asks for at most 2) are printed.  The default size is 20,000 lines; ``--lines 1000000`` is
the issue's case.  ``--path-mode G64`` (with ``--path-tolerance 0.01``: LinuxCNC's ``G64 P0.01``) runs both on a
machine that may round corners: the point's corner proof and the solids' (specs/path-modes.md §8) are then
part of both verdicts.
"""

from __future__ import annotations

import argparse
import math
import random
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from nczones.machine import parse_machine  # noqa: E402
from nczones.prover import verify  # noqa: E402

MACHINE = """
[machine]
name = "bench mill with fixtures"
axes = ["X", "Y", "Z"]
rapid_mode = "linear"
path_mode = "G61"
[machine.rapid]
X = "15000"
Y = "15000"
Z = "10000"
[machine.reference]
X = "0"
Y = "0"
Z = "400"
[offsets]
G54 = { X = "0", Y = "0", Z = "0" }
[tool_lengths]
H1 = "100"
[[zones]]
name = "travel"
kind = "box"
min = { X = "-200", Y = "-200", Z = "0" }
max = { X = "600", Y = "600", Z = "400" }
"""

SOLIDS = """
[[tools]]
number = 1
parts = [
  { name = "cutter", diameter = "10", length = "25" },
  { name = "shank", diameter = "10", length = "15" },
  { name = "holder", diameter = "40", length = "60" },
]
"""


def fixtures() -> str:
    """Ten fixtures around the pocket X 0..300, Y 0..300 (the holder, radius 20, passes 5 mm from the
    nearest ones when the cutter is at the pocket's edge)."""
    out = []
    boxes = [("jaw west", "-80", "-25", "0", "300"), ("jaw east", "325", "380", "0", "300"),
             ("stop south", "0", "100", "-60", "-25"), ("stop north", "200", "300", "325", "360"),
             ("block sw", "-80", "-30", "-80", "-30"), ("block se", "330", "380", "-80", "-30"),
             ("block nw", "-80", "-30", "330", "380"), ("block ne", "330", "380", "330", "380")]
    for name, x0, x1, y0, y1 in boxes:
        out.append(f'[[fixtures]]\nname = "{name}"\nkind = "box"\nmin = {{ X = "{x0}", Y = "{y0}", Z = "0" }}\n'
                   f'max = {{ X = "{x1}", Y = "{y1}", Z = "80" }}\n')
    for name, cx, cy in (("clamp a", "150", "-60"), ("clamp b", "150", "360")):
        out.append(f'[[fixtures]]\nname = "{name}"\nkind = "cylinder"\ncentre = {{ X = "{cx}", Y = "{cy}" }}\n'
                   f'radius = "15"\nmin_z = "0"\nmax_z = "60"\n')
    return "\n".join(out)


def generate(n: int, path: Path) -> None:
    """A 3-D surfacing raster (what CAM writes by the million): passes along X over the pocket, 1.5 mm steps
    with the height following a surface (the tip at Z 10..40: the holder, 40 mm above the tip, at the
    fixtures' heights), 2 mm stepover in Y, a retract ``G0`` between passes."""
    rnd = random.Random(39)
    with path.open("w") as fh:
        fh.write("G21 G90 G54 G17\nT1 M6\nG43 H1\nG0 X0 Y0 Z150\nG1 F2000\n")
        x, y, direction = 0.0, 0.0, 1
        for _ in range(n):
            x += 1.5 * direction
            if not 0 <= x <= 300:
                x = min(300.0, max(0.0, x))
                y = y + 2 if y < 298 else 0.0
                direction = -direction
                fh.write(f"G0 Z150\nG0 X{x:.3f} Y{y:.3f}\n")
            z = 25 + 10 * math.sin(x / 37) * math.cos(y / 53) + rnd.uniform(-0.5, 0.5)
            fh.write(f"G1 X{x:.3f} Y{y:.3f} Z{z:.3f}\n")
        fh.write("G0 Z150\nM30\n")


def timed(program: Path, m, profile: bool) -> tuple[float, float, str]:
    w0, c0 = time.perf_counter(), time.process_time()
    if profile:
        import cProfile
        import pstats

        with cProfile.Profile() as prof:
            r = verify(program, m)
        pstats.Stats(prof).sort_stats("cumulative").print_stats(25)
    else:
        r = verify(program, m)
    reasons = "; ".join(x.code or "" for x in r.reasons[:3]) or "; ".join(n for n in r.notes if "holder" in n)[:160]
    return time.process_time() - c0, time.perf_counter() - w0, r.verdict.label + (f" ({reasons})" if reasons else "")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=20_000)
    ap.add_argument("--profile", action="store_true", help="print a cProfile of the solids run")
    ap.add_argument("--path-mode", default="G61", choices=("G61", "G64"), help="the machine's path_mode")
    ap.add_argument("--path-tolerance", default=None, help="the machine's path_tolerance (G64 P), mm")
    args = ap.parse_args()
    mode = f'path_mode = "{args.path_mode}"' + (f'\npath_tolerance = "{args.path_tolerance}"'
                                                 if args.path_tolerance else "")
    base = MACHINE.replace('path_mode = "G61"', mode)
    point_only = parse_machine(base)
    with_solids = parse_machine(base + SOLIDS + fixtures())
    with tempfile.TemporaryDirectory() as tmp:
        program = Path(tmp) / "cam.ngc"
        generate(args.lines, program)
        warm = Path(tmp) / "warm.ngc"  # the first verify of a process loads and compiles what later ones reuse
        generate(600, warm)
        verify(warm, point_only)
        verify(warm, with_solids)
        p_cpu, p_wall, p_v = timed(program, point_only, False)
        s_cpu, s_wall, s_v = timed(program, with_solids, args.profile)
        print(f"{args.lines} lines, {mode.replace(chr(10), ', ')}: point only {p_cpu:.2f} s CPU ({p_wall:.2f} s wall, {p_v}); with 3 tool solids "
              f"against 10 fixtures {s_cpu:.2f} s CPU ({s_wall:.2f} s wall, {s_v}); ratio {s_cpu / p_cpu:.2f}",
              flush=True)


if __name__ == "__main__":
    main()
