# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell
nb.cells = [
md("""# 7 · Robust programs: safe for every fixture position in a range

A part is never clamped exactly where the work offset says; a tool is never exactly as long as its
register. A simulator answers for one position. nczones can answer for **all of them at once**:
give a work-offset component, a tool length or the start position as a range, and `safe` means safe
for every value in it — a counterexample names the values that break it.

Here a contour pass runs close to the vise of the 3-axis mill."""),
code("""from fractions import Fraction as F
from pathlib import Path
import matplotlib.pyplot as plt
from nczones import load_machine, format_decimal
from nczones.gcode import segments_text
from nczones.prover import verify_text
from nczones.report.plot import plot_machine, mark_points

mill = load_machine("../specs/machines/mill.toml")
vise = next(z for z in mill.zones if z.name == "vise")
g54 = mill.offset("G54")
print("vise (tool tip may not enter):", {a: (format_decimal(lo), format_decimal(hi)) for a, (lo, hi) in vise.bounds().items()})
print("G54 zero in machine coordinates:", dict(zip(mill.axis_names, map(format_decimal, g54))))

program = '''G21 G90 G17 G54 G94
G43 H1
G0 X-5 Y-50 Z20
G1 Z-5 F300
G1 Y90
G1 X70
G1 Y-50
G1 X-5
G0 Z20
M30
'''
clearance = (F(-5) + g54[0]) - vise.bounds()["X"][1]
print(f"the pass along the vise runs {format_decimal(clearance)} mm from its face at nominal G54")"""),
code("""nominal = verify_text(program, mill)
print("nominal offset:", nominal.verdict.label)
two = verify_text(program, mill, params=["G54.X=-2..2"])
print("G54.X within ±2 mm:", two.verdict.label)
six = verify_text(program, mill, params=["G54.X=-6..6"])
print("G54.X within ±6 mm:", six.verdict.label)
for v in six.violations[:3]:
    print(f"  line {v.line} zone {v.zone!r}: with", {n: format_decimal(x) for n, x in v.params},
          "the machine position reaches", {a: format_decimal(c, 3) for a, c in v.point})"""),
md("""## How big may the range be?

`safe` is monotone in the range: a range inside a safe one is safe. So the largest safe symmetric
range can be found by bisection over proofs. Each step is a full proof over all offsets in the
range, not a sample."""),
code("""lo, hi = F(0), F(20)          # safe at 0 (nominal), unsafe at 20
assert verify_text(program, mill, params=[f"G54.X=-{format_decimal(hi)}..{format_decimal(hi)}"]).verdict.label == "unsafe"
steps = 0
while hi - lo > F(1, 1000):
    mid = (lo + hi) / 2
    mid = F(round(mid * 10_000), 10_000)   # keep the range a short decimal
    r = verify_text(program, mill, params=[f"G54.X=-{format_decimal(mid)}..{format_decimal(mid)}"])
    lo, hi = (mid, hi) if r.verdict.label == "safe" else (lo, mid)
    steps += 1
print(f"after {steps} proofs: safe for G54.X within ±{format_decimal(lo)} mm, unsafe for ±{format_decimal(hi)} mm")"""),
code("""worst = six.violations[0]
ax = plot_machine(mill, segments_text(program, mill))
mark_points([tuple(float(c) for _, c in worst.point)[:2]], ax)
ax.set_xlim(60, 260); ax.set_ylim(20, 220)
ax.set_title("Contour next to the vise; the cross: a tip position reached with G54.X shifted")
plt.show()"""),
md("""## Tool lengths: what the range moves

With `G43 H1` the spindle moves so that the *tip* reaches the programmed point, so the tip does not
depend on the tool length — but the spindle nose does. A longer tool pushes the spindle up, towards
the top of the Z travel."""),
code("""lift = (Path("../specs/examples/programs/z_tool_range.ngc")).read_text()
print(lift)
for rng in ["H1=115..125", "H1=115..126"]:
    r = verify_text(lift, mill, params=[rng])
    detail = "; ".join(f"zone {v.zone!r} with {dict((n, format_decimal(x)) for n, x in v.params)}" for v in r.violations)
    print(f"{rng}: {r.verdict.label} {detail}")"""),
md("""## Exercises

1. Add `G54.Y=-1..1` next to `G54.X`. Does the largest safe X range change? Why (look at where the
   pass turns)?
2. Use `start.Z=-10..0` on a program that starts with a rapid in X and Y only. What does the
   counterexample say?
3. A homing error of one grid pitch shifts the machine zero: try `home.X=-10..10` on the contour."""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/07_robust_programs.ipynb")
