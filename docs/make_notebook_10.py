# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell
nb.cells = [
md("""# 10 · The whole tool: the holder that hits the vise

Most crashes in a shop are not the tool tip leaving the travel box: the **holder** or the spindle nose hits
the vise, a long shank rubs a clamp. nczones can describe the tool as a stack of solids that move with the
spindle — cutter, shank, holder (`[[tools]]`), the spindle nose (`[spindle]`) — and prove that none of them
ever enters a fixture (`[[fixtures]]`, and every forbidden box zone): for every motion, exactly
(`specs/machine-file.md`, "Tools and fixtures as solids").

This notebook walks the bundled example: a pocket beside the vise jaw where the cutter clears the jaw and
the holder does not, the counterexample and its replay, and the fixed program with its least clearance."""),
code("""import math
from dataclasses import replace
from fractions import Fraction
from pathlib import Path
from types import MappingProxyType

import matplotlib.pyplot as plt
from nczones import load_machine, format_decimal
from nczones.prover import verify
from nczones.prover.render import to_json_dict
from nczones.replay import replay_report
from nczones.report import plot_program
from nczones.solids import machine_solids

mill = load_machine("../specs/machines/mill_solids.toml")
solids = machine_solids(mill)
print(mill.name)
for number, parts in solids.tools.items():
    print(f"tool {number}:")
    for p in parts:
        print("   ", p.label())
print("spindle:", ", ".join(p.label() for p in solids.spindle))
for f in solids.fixtures:
    print("fixture:", f.name, "(cylinder)" if hasattr(f, "radius") else "(box)")
print("tool length H1 =", format_decimal(mill.tool_length(1)))"""),
md("""## The tip clears the jaw

The program drops the tool at X80, beside the jaw (X 100..250, Y 0..80, up to Z 60), to a tip height of
Z10. The cutter has a radius of 5: its edge is at X85, 15 mm from the jaw. Proving the tool tip alone (the
same machine without its tool solids) says `safe`."""),
code("""hits = Path("../specs/examples/programs/holder_hits_vise.ngc")
print(hits.read_text())
tip_only = replace(mill, sections=MappingProxyType(
    {k: v for k, v in mill.sections.items() if k not in ("tools", "spindle")}))
print("the tip alone:", verify(str(hits), tip_only).verdict.label)"""),
md("""## The holder does not

The holder is Ø63 (radius 31.5) and starts 40 mm above the tip. At X80 it reaches X111.5, inside the jaw's
X range; once the tip is below Z20 its bottom is below the jaw top Z60. With the solids, the verdict is
`unsafe`, and the counterexample names the part, the fixture, the line and an exact point inside both."""),
code("""result = verify(str(hits), mill)
print(result.verdict.label)
for v in result.violations:
    print(f"line {v.line}: {v.note}")
v = result.violations[0]
print("witness:", {a: str(x) for a, x in v.point}, " path point:", {a: str(x) for a, x in v.path_point})"""),
md("""## The picture matches the proof

The report draws the tool where the witness puts it: the whole assembly at the path point of the first
contact (grey), the holder that enters the jaw (orange) and the jaw where the solids proof puts it (red
outline). The hatched red box is the jaw as a *tip zone*: drawn where the controlled point (the gauge line)
would be when the tip is in the jaw, i.e. 100 mm (the tool length) higher."""),
code("""fig, axes = plt.subplots(1, 2, figsize=(13, 5))
plot_program(str(hits), mill, ("X", "Z"), result, ax=axes[0], legend=False)
plot_program(str(hits), mill, ("X", "Y"), result, ax=axes[1])
axes[0].set_xlim(-20, 280); axes[0].set_ylim(-10, 220)
axes[1].set_xlim(-20, 280); axes[1].set_ylim(-40, 120)
plt.show()"""),
md("""## Replay: a counterexample anyone can check

`nczones replay` reads the JSON report, runs the program again to the violating block, places the holder at
the reported path point and checks, in exact rationals, that the witness is inside the holder and inside
the jaw."""),
code("""for check in replay_report(to_json_dict(result)):
    print(check.render())"""),
md("""## The fixed program and its least clearance

Moving the pocket 20 mm away (X60) keeps the holder's edge at X91.5: 8.5 mm from the jaw face. The verdict is
`safe`, and the result says how close each part came to each fixture (a certified lower bound): the holder
8.5 mm from the vise."""),
code("""clears = Path("../specs/examples/programs/holder_clears_vise.ngc")
fixed = verify(str(clears), mill)
print(fixed.verdict.label)
for part, fixture, c, line in fixed.extra["clearance"]:
    c = Fraction(math.floor(c * 1000), 1000)  # a lower bound: rounded down
    print(f"{part:45} {fixture:6} at least {format_decimal(c):>8} mm (line {line})")
fig = plot_program(str(clears), mill, ("X", "Z"), fixed)
fig.axes[0].set_xlim(-20, 280); fig.axes[0].set_ylim(-10, 220)
plt.show()"""),
md("""## Exercises

1. Move the pocket to X68.5 in a copy of `holder_clears_vise.ngc`. What is the least clearance now? And at X68.6?
2. Give the holder a diameter of 80 in a copy of the machine file: which line is the first violation now?
3. Drop the tool to Z45 only (`G1 Z45`) in `holder_hits_vise.ngc`: the holder is above the jaw top. Is it safe?"""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/10_whole_tool.ipynb")
