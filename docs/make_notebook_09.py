# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell
nb.cells = [
md("""# 9 · Lathes: the roughing pass that hits the jaws

On a lathe the programmer draws the finished shape; a **multiple repetitive cycle** (`G71` on a Fanuc
control, `G71`/`G72` with a profile subroutine on LinuxCNC) turns it into roughing passes. The classic
crash is not the shape — it is a pass the control generates from it. nczones generates every pass the
way the control does and proves each one; a counterexample names the pass.

The machine file says it is a lathe (`type = "lathe"`), that X words are diameters
(`diameter_axes = ["X"]`: machine coordinates and zones stay radii) and gives the tool offsets
(`T0101`) and the cycle parameters the programs rely on. Chuck, jaws and tailstock are zones of the
tool tip."""),
code("""from pathlib import Path
import matplotlib.pyplot as plt
from nczones import load_machine, format_decimal
from nczones.gcode import segments, segments_text
from nczones.prover import verify, verify_text
from nczones.report.plot import plot_machine, mark_points

lathe = load_machine("../specs/machines/fanuc_lathe.toml")
print(lathe.name, "- type:", lathe.machine_type, "- diameter axes:", lathe.diameter_axes)
for z in lathe.zones:
    print(f"  {z.name:10} {'forbid' if z.forbid else 'allow '} point={z.point.value}")
t = lathe.tool_offsets[1]
print("tool offset 1:", {a: format_decimal(v) for a, v in t.geometry})"""),
md("""## The roughing cycle and its passes

`G71 U3. R1.` sets the depth of cut (3 mm, a radius) and the escape; `G71 P10 Q20 U0.4 W0.1` names the
shape (blocks N10 to N20) and the finishing allowances. Every generated move is a segment of the cycle
block with a note naming its pass."""),
code("""jaws_prog = Path("../specs/examples/programs/g71_jaws.nc")
print(jaws_prog.read_text())
segs = segments(jaws_prog, lathe)
for s in segs[:12]:
    print(f"line {s.span.line}: {s.kind.name:5} to X{format_decimal(s.end[0])} Z{format_decimal(s.end[1])}  {s.derived}")"""),
md("""## The shape is clear; the third pass is not

Cut along the shape alone and the tool's imaginary tip stays clear of the jaws: it ends on their face
(X50, Z-62). That is a proof for a sharp tool. This tool has a nose radius (R0.4, tip 3): its edge is a
circle near the imaginary tip, and nczones proves the whole square of half-width 2R around the tip clear
of the tip zones, whichever way the tip points (`specs/turning.md`), so a shape that runs on the jaws'
face is reported as a possible touch of 0.8 mm: cut to the face with a finishing allowance, or leave room.
The roughing levels above the shape's last point cut to that Z, which lies over the jaws: the third
pass is the first whose level is below the jaws' top."""),
code("""shape_only = "G21 G18 G99\\nT0101\\nG00 X80. Z2.\\nG00 X30.\\nG01 Z-20. F0.25\\nX40. Z-30.\\nZ-45.\\nX50. Z-62.\\n"
from dataclasses import replace
from types import MappingProxyType
sharp = replace(lathe, tool_offsets=MappingProxyType(
    {n: replace(t, nose_radius=0, wear_radius=0) for n, t in lathe.tool_offsets.items()}))
print("the shape alone, a sharp tool:", verify_text(shape_only, sharp).verdict.label)
print("the shape alone, this tool:   ", verify_text(shape_only, lathe).verdict.label)
r = verify(jaws_prog, lathe)
print("the G71 cycle:  ", r.verdict.label)
v = r.violations[0]
print(f"line {v.line} ({v.derived}) enters {v.zone!r}, {format_decimal(v.depth)} mm deep")
clear = Path("../specs/examples/programs/g71_clear.nc")
print("the fixed program (the shape ends 4 mm earlier):", verify(clear, lathe).verdict.label)"""),
code("""fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
for ax, prog, title in ((axes[0], clear, "fixed: safe"), (axes[1], jaws_prog, "pass 3 enters the jaws")):
    plot_machine(lathe, segments(prog, lathe), plane=("Z", "X"), ax=ax)
    ax.set_xlim(100, 320); ax.set_ylim(90, 130); ax.set_title(title)
mark_points([(float(dict(v.point)["Z"]), float(dict(v.point)["X"]))], axes[1])
plt.show()"""),
md("""## The same cycle on LinuxCNC

LinuxCNC's `G71` reads the profile from a subroutine (`Q`) and computes the passes in its own way
(`interp_g7x.cc`): the first pass at the start's level, an escape by `R` on both axes. nczones
reproduces LinuxCNC's moves exactly (its own test logs, move for move)."""),
code("""program = '''G18 G21 G8 F100
o1 sub
G1 X4
Z-10
X10
o1 endsub
G71 Q1 X10 Z1 D0 I2 R0.5
M2
'''
lc = load_machine("../specs/machines/lathe.toml")
for s in segments_text(program, lc)[:8]:
    print(f"{s.kind.name:5} X{format_decimal(s.end[0])} Z{format_decimal(s.end[1])}  {s.derived}")"""),
md("""## Exercises

1. Change the depth of cut `U3.` to `U2.5` in a copy of `g71_jaws.nc`. Which pass does the report name now?
2. Set `roughing_final_pass = false` in a copy of the machine file: which segments disappear?
3. Move the jaws with a work offset range: `--param G54.Z=195..205` on the fixed program. Is it still safe?"""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/09_lathe_roughing.ipynb")
