# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell
nb.cells = [
md("""# 2 · Proving a program: constraints, a proof, a counterexample

A controller checks its stroke limits while the machine moves, and many check only where a block
*ends*. Yet a straight line can dip into a notch of a stepped table with both end points allowed,
and an arc can bulge over a limit between two allowed end points. nczones asks the question about
**every** point of the motion: *is there a point of this block outside the allowed set?* If the
SMT solver Z3 answers *no*, the block is proved safe; if *yes*, it returns the point.

We first write such a query by hand for one line, then let `nczones.prover.verify` do it for whole
programs."""),
code("""from fractions import Fraction as F
from pathlib import Path
import matplotlib.pyplot as plt
import z3
from nczones import load_machine, format_decimal
from nczones.gcode import segments_text
from nczones.prover import verify_text
from nczones.report.plot import plot_machine, mark_points

grinder = load_machine("../specs/machines/grinder.toml")
examples = Path("../specs/examples/programs")
program = (examples / "notch_dip.ngc").read_text()
print(program)
motion = segments_text(program, grinder)
for s in motion:
    print(s.kind.name, "from", [format_decimal(c) for c in s.start], "to", [format_decimal(c) for c in s.end])"""),
md("""## The notch-crossing line, by hand

The last block moves along Y at constant height across the work head. A point of the line is
`P(t) = start + t·(end − start)` with `0 ≤ t ≤ 1`. It is outside the wheel area when its X lies in no
region, or when Y breaks the limits of the region X lies in. Regions are half-open:
`upto[i-1] < X ≤ upto[i]`."""),
code("""line = motion[-1]
table = grinder.zones[0]
t, x, y = z3.Reals("t x y")
(x0, y0), (x1, y1) = line.start, line.end
s = z3.Solver()
s.add(0 <= t, t <= 1, x == x0 + t * (x1 - x0), y == y0 + t * (y1 - y0))
outside = [x < table.start, x > table.regions[-1].upto]
for i, r in enumerate(table.regions):
    lower = table.region_lower(i)
    in_region = z3.And(x >= lower if i == 0 else x > lower, x <= r.upto)
    bad_y = z3.Or(*([y < r.min] if r.min is not None else []), *([y > r.max] if r.max is not None else []))
    outside.append(z3.And(in_region, bad_y))
s.add(z3.Or(*outside))
answer = s.check()
print("Z3:", answer)
if answer == z3.sat:
    m = s.model()
    print("a point outside the wheel area: X =", m[x], " Y =", m[y], " at t =", m[t])"""),
md("""`sat` means a counterexample exists. Had Z3 answered `unsat`, no point of the line would be outside:
a proof. The prover builds the same kind of query for every segment (as SMT-LIB text, with exact
rationals), but first tries exact integer arithmetic, which decides lines against stepped tables
and boxes without the solver at all.

## The same program through the prover"""),
code("""result = verify_text(program, grinder, file="notch_dip.ngc")
print("verdict:", result.verdict.label)
for v in result.violations:
    pt = {a: format_decimal(c) for a, c in v.point}
    exit_pt = {a: format_decimal(c) for a, c in v.first_exit}
    print(f"line {v.line}: zone {v.zone!r}, point {pt}, first exit {exit_pt}, depth {format_decimal(v.depth)} mm ({v.engine})")"""),
code("""ax = plot_machine(grinder, motion)
mark_points([tuple(float(c) for _, c in v.point) for v in result.violations], ax)
ax.set_title("The line dips into the work-head notch")
plt.show()"""),
md("""## The bulging arc

Both arcs below start and end at the same allowed points with the same centre. Clockwise, the arc
swings up over the Y limit; counter-clockwise it swings down, and stays inside. End-point checks
cannot tell them apart; the exact arc encoding (point on the circle, inside the swept sector) can."""),
code("""fig, axes = plt.subplots(1, 2, figsize=(12, 4))
for ax, name in zip(axes, ["arc_bulge_cw.ngc", "arc_bulge_ccw.ngc"]):
    text = (examples / name).read_text()
    r = verify_text(text, grinder, file=name)
    plot_machine(grinder, segments_text(text, grinder), ax=ax)
    mark_points([tuple(float(c) for _, c in v.point) for v in r.violations], ax)
    ax.set_title(f"{name}: {r.verdict.label}")
    ax.set_xlim(500, 900); ax.set_ylim(150, 420)
    for v in r.violations:
        print(name, "depth", format_decimal(v.depth, 4), "mm at", {a: format_decimal(c, 4) for a, c in v.point})
plt.show()"""),
md("""## Exact numbers

Ten incremental steps of `Y-0.1` from `Y41` land on the floor of the grinding region. In floating
point, `0.1` is not one tenth and the sum drifts; nczones reads every decimal exactly, so the first
program is proved safe and the second — one micron further — is not."""),
code("""for name in ["accumulate_exact.ngc", "accumulate_past.ngc"]:
    r = verify_text((examples / name).read_text(), grinder, file=name)
    lowest = min(s.end[1] for s in segments_text((examples / name).read_text(), grinder))
    print(f"{name}: lowest Y = {format_decimal(lowest)}, verdict {r.verdict.label}")
y = 41.0
for _ in range(10):
    y -= 0.1
print(f"the same ten steps in floating point end at Y = {y!r}: a float checker would call the safe program unsafe ({y >= 40 = })")"""),
md("""## Exercises

1. Raise the notch line (`G1 Y130`) until the program is proved safe. Which height is the lowest
   safe one, and why is it exactly the floor of the work-head region?
2. Write an R-format version of the bulging arc (`G2 X... Y... R...`). Does its verdict change with
   the sign of R?
3. Ask for a margin: `verify_text(text, grinder, margin="0.5")`. Which of the programs above stop being
   safe?"""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/02_proving_a_program.ipynb")
