# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell
nb.cells = [
md("""# 8 · Fanuc programs: Custom Macro B, checked before they run

Most machining centres run a Fanuc control or one that reads Fanuc programs (Haas, Mitsubishi in Fanuc
mode). Their programs start with a safety line like `G00 G17 G40 G49 G80 G90`, call subprograms with
`M98`, and compute positions with **Custom Macro B**: variables `#1`..`#999`, `WHILE [..] DO1 .. END1`,
`IF [..] GOTO`, macros called with `G65 P.. A.. B..`.

A macro program's path is not in its text: it is what the loops and the arithmetic produce. nczones
runs the macro language exactly as the control does (IEEE doubles, values rounded to the least input
increment where they become positions) and proves the path it produces. Set
`[machine] dialect = "fanuc"` in the machine file (or pass `--dialect fanuc`)."""),
code("""from pathlib import Path
from dataclasses import replace
import matplotlib.pyplot as plt
from nczones import load_machine, format_decimal
from nczones.gcode import interpret, segments
from nczones.prover import verify, verify_text
from nczones.report.plot import plot_machine, mark_points

vmc = load_machine("../specs/machines/fanuc_mill.toml")
print(vmc.name, "- dialect:", vmc.dialect)
clamp = next(z for z in vmc.zones if z.name == "clamp")
print("the clamp (the tool tip may not enter):",
      {a: (format_decimal(lo), format_decimal(hi)) for a, (lo, hi) in clamp.bounds().items()})
print("G54 zero:", dict(zip(vmc.axis_names, map(format_decimal, vmc.offset("G54")))))
print("common variable #500 from the machine file:", format_decimal(vmc.fanuc.variables[500]))"""),
md("""## The safe program: a WHILE loop that calls a G65 macro

`#500` comes from the machine file (`[variables]`): the number of slots the operator set. The loop
calls the macro `O9001` once per slot; `G65` passes `X Y D E` as the macro's local variables
`#24 #25 #7 #8` (argument specification I), in a new local level."""),
code("""safe = Path("../specs/examples/programs/fanuc_slots_safe.nc")
print(safe.read_text())
r = verify(safe, vmc)
print(r.verdict.label, "-", len(list(segments(safe, vmc))), "segments")"""),
md("""## The same loop, five passes: it walks into the clamp on the fourth

The second program cuts five slots at a 30 mm pitch. The clamp sits at X 85..115 of the part, so the
fourth slot (X90) runs into it. The report names the line inside the loop; the counterexample's X
says which pass it was."""),
code("""clamp_prog = Path("../specs/examples/programs/fanuc_slots_clamp.nc")
r = verify(clamp_prog, vmc)
print(r.verdict.label)
g54x = vmc.offset("G54")[0]
for v in r.violations:
    x_work = dict(v.point)["X"] - g54x
    print(f"line {v.line}: {v.source!r} enters {v.zone!r}, {format_decimal(v.depth)} mm deep; "
          f"X{format_decimal(x_work)} in the part: pass {int(x_work / 30) + 1}")"""),
code("""fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
for ax, prog, title in ((axes[0], safe, "three slots: safe"), (axes[1], clamp_prog, "five slots: the fourth hits")):
    plot_machine(vmc, segments(prog, vmc), plane=("X", "Y"), ax=ax)
    ax.set_xlim(-430, -240); ax.set_ylim(-290, -170); ax.set_title(title)
worst = r.violations[0]
mark_points([tuple(float(c) for _, c in worst.point)[:2]], axes[1])
plt.show()"""),
md("""## Decimal-point input: the classic crash

On a Fanuc control, a length written without a decimal point is read according to parameter
3401#0 (DPI). With *calculator-type* input (`decimal_point_input = "calculator"`) `X100` is 100 mm;
with *increment-type* input it is 100 least input increments: 0.1 mm. A program written for one
setting runs on the other without any error — and moves somewhere else. nczones reads the machine's
setting and notes every such word in the report."""),
code("""program = "O1000\\nG90 G54 G00 X0 Y0\\nG43 H1 Z25.\\nG00 X100 Y20.\\nG01 Z-5. F300.\\nG00 Z25.\\nM30\\n"
for setting in ("calculator", "increment"):
    m = replace(vmc, fanuc=replace(vmc.fanuc, decimal_point_input=setting))
    r = verify_text(program, m)
    print(f"{setting:10}: {r.verdict.label}", "-", [v.zone for v in r.violations])
print(r.notes[-1])"""),
md("""## What the dialect reads differently

The same text can mean different things to a LinuxCNC and a Fanuc control. nczones reads it the way the
machine file says; an error that only one dialect gives names the other."""),
code("""from nczones.errors import GcodeError

linuxcnc_vmc = replace(vmc, dialect="linuxcnc")
try:
    list(interpret(safe, linuxcnc_vmc))
except GcodeError as e:
    print(e.diagnostics[0].render())"""),
md("""## Exercises

1. Change `#500` in a copy of the machine file to 4. Which line does the report name, and why does
   the safe program now fail although its text did not change?
2. Replace the `WHILE` loop of the clamp program by `M98 P2000 L5` and a subprogram `O2000` that
   advances `#1`. Does the verdict change?
3. Add `G68 X0 Y0 R90.` before the loop of the safe program: the slots turn by 90°. Is it still
   safe? Try `--param G54.Y=-5..5` on it from the command line."""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/08_fanuc_macro_b.ipynb")
