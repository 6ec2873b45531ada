"""Generate notebooks/04_cylindrical_interpolation.ipynb (run: python docs/make_notebook_04.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

ROOT = Path(__file__).resolve().parents[1]

cells = [
    new_markdown_cell("""# 4. Cylindrical interpolation: a cam groove on the developed surface

A groove on the side of a cylinder moves two axes at once: Z along the cylinder and the
rotary axis C. The old practice (JP patent 001) cut the groove into short straight Z-C
moves computed by hand. **Cylindrical interpolation** (Fanuc `G07.1 C<radius>`) lets the
programmer draw the groove on the *developed* (unrolled) surface with ordinary lines and
arcs; the controller interpolates there and converts the developed coordinate into the
rotary displacement:

$$\\text{angle (rad)} = \\frac{\\text{developed length}}{R}, \\qquad C\\,[\\deg] = \\frac{180\\, s}{\\pi R}.$$

Because of $\\pi$, nczones never computes these numbers in floats: every quantity is an
interval of rationals that contains the exact value. This notebook shows the groove both
ways, plots them, verifies them against a clamp, and runs the reference controller."""),
    new_code_cell("""from fractions import Fraction
from pathlib import Path
import math
import matplotlib.pyplot as plt

from nczones.machine import load_machine
from nczones.gcode import segments_text
from nczones.prover import verify_text
from nczones.controller import simulate
from nczones.geometry.cylinder import pi_interval, degree_length, developed_arc_of

EX = Path("..") / "specs" / "examples"
machine = load_machine(EX / "machines" / "cylinder.toml")
near = load_machine(EX / "machines" / "cylinder_clamp_near.toml")
seg_prog = (EX / "programs" / "cam_groove_segments.ngc").read_text()
arc_prog = (EX / "programs" / "cam_groove_g071.ngc").read_text()
print(seg_prog)
print(arc_prog)"""),
    new_markdown_cell("""## Pi, enclosed

`pi_interval()` encloses $\\pi$ by Machin's formula; `degree_length(R)` is
$k = \\pi R/180$, the developed millimetres per degree."""),
    new_code_cell("""p = pi_interval()
print("pi in [", float(p.lo), ",", float(p.hi), "], width", float(p.hi - p.lo))
print("333/106 < lo:", Fraction(333, 106) < p.lo, "  hi < 355/113:", p.hi < Fraction(355, 113))
k = degree_length(Fraction("37.266"))
print("k =", float(k.mid()), "mm per degree;  123 deg =", float((k * 123).mid()), "mm developed")"""),
    new_markdown_cell("""## The groove both ways

The seven G01 points lie close to a quarter circle of radius 80 mm on the developed
surface with its centre at (Z110, C30). With R = 37.266 mm, 123° of C are 80 mm, so
the G07.1 program is a single `G02 Z110 C153 R80`."""),
    new_code_cell("""segs_a = segments_text(seg_prog, machine)
segs_b = segments_text(arc_prog, machine)
print([s.kind.name for s in segs_a])
print([s.kind.name for s in segs_b])
arc_seg = next(s for s in segs_b if s.kind.name == "DEVELOPED_ARC")
arc = developed_arc_of(arc_seg)
print("centre (Z, s from C30):", [round(float(c.mid()), 6) for c in arc.centre])
print("radius", float(arc.rho.mid()), "mm, sweep", float(arc.sweep.mid()) * 180 / math.pi, "deg (float for display)")
print("developed length", float(arc.length().mid()), "mm")"""),
    new_code_cell("""def developed_polyline(segs, k):
    pts = []
    for s in segs:
        if s.kind.name in ("LINE", "RAPID"):
            if not pts:
                pts.append((float(s.start[0]), float(s.start[1]) * k))
            pts.append((float(s.end[0]), float(s.end[1]) * k))
    return pts

kf = float(degree_length(Fraction("37.266")).mid())
lines = [s for s in segs_a if s.kind.name == "LINE"]
poly = developed_polyline(lines, kf)
arc_pts = []
for i in range(201):
    z, s, c = arc.point(Fraction(i, 200))
    arc_pts.append((float(z.mid()), float(s.mid()) + 30 * kf))

fig, ax = plt.subplots(figsize=(7, 5))
ax.plot(*zip(*poly), "o-", label="7 x G01 (conventional)")
ax.plot(*zip(*arc_pts), "-", label="G07.1: G02 R80 on the developed surface")
clamp_s = (160 * kf, 200 * kf)
ax.add_patch(plt.Rectangle((90, clamp_s[0]), 30, clamp_s[1] - clamp_s[0], color="red", alpha=0.3, label="clamp"))
ax.set_xlabel("Z (mm)"); ax.set_ylabel("developed s = pi R C / 180 (mm)"); ax.set_aspect("equal")
ax.legend(); ax.set_title("The cam groove on the developed surface")
plt.show()"""),
    new_markdown_cell("""## How far apart are the two paths?

On the developed surface, the largest distance from a point of the arc to the polyline and
from a polyline vertex to the circle (floats: this is a report number; the program
numbers in `specs/cylindrical.md` come from `docs/cam_groove.py`)."""),
    new_code_cell("""def dist_to_polyline(p, poly):
    best = math.inf
    for a, b in zip(poly, poly[1:]):
        dx, dy = b[0] - a[0], b[1] - a[1]
        L = dx * dx + dy * dy
        t = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L))
        best = min(best, math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy))
    return best

cz, cs, rho = float(arc.centre[0].mid()), float(arc.centre[1].mid()) + 30 * kf, float(arc.rho.mid())
d_arc = max(dist_to_polyline(p, poly) for p in arc_pts)
d_vert = max(abs(math.hypot(p[0] - cz, p[1] - cs) - rho) for p in poly)
print(f"max distance arc -> polyline {d_arc:.4f} mm, polyline vertex -> circle {d_vert:.4f} mm")
code_a = [l.split("(")[0].strip() for l in seg_prog.splitlines() if l.split("(")[0].strip()]
code_b = [l.split("(")[0].strip() for l in arc_prog.splitlines() if l.split("(")[0].strip()]
print("blocks:", len(code_a), "vs", len(code_b))"""),
    new_markdown_cell("""## Verify both against the clamp

`verify` proves the arc with enclosures of $\\pi$: each piece of the arc is enclosed in a
rational box; boxes that fit prove the piece; a violation is reported only at a point whose
whole enclosure lies in the clamp. Counterexamples are given in degrees and in developed
millimetres."""),
    new_code_cell("""for m, name in ((machine, "clamp C160..200"), (near, "clamp C150..200")):
    for prog, label in ((seg_prog, "7 x G01"), (arc_prog, "G07.1 arc")):
        r = verify_text(prog, m)
        line = r.violations[0].line if r.violations else "-"
        print(f"{name:16s} {label:10s} {r.verdict.label:7s} first violating line {line}")
r = verify_text(arc_prog, near)
print(r.violations[0].note)"""),
    new_markdown_cell("""## The controller: developed plane first, rotary pulses second

The reference controller walks the circle on a quarter-pulse developed grid and converts
each point to Z pulses and C pulses (0.001 deg). Here a short arc of the same kind, so
that it runs in a second; the plot shows the commanded C pulses against the exact angle."""),
    new_code_cell("""short = "G0 Z30 C30\\nG7.1 C37.266\\nG2 Z32 C36 R5 F100\\nG7.1 C0\\n"
res = simulate(segments_text(short, machine), machine)
print("alarms:", res.alarms, " end:", [str(v) for v in res.machine_position], " pulses:", res.pulses)
a = developed_arc_of(segments_text(short, machine)[-1])
exact = [a.point(Fraction(i, 100)) for i in range(101)]
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot([float(z.mid()) for z, s, c in exact], [float(c.mid()) for z, s, c in exact], label="exact path")
ax.set_xlabel("Z (mm)"); ax.set_ylabel("C (deg)"); ax.legend(); ax.set_title("G02 R5 on the developed surface, seen in (Z, C)")
plt.show()"""),
    new_markdown_cell("""## Exercises

1. Change the cylinder radius in `cam_groove_g071.ngc` to 30 mm. Which R still reaches
   from A0 to B? (Hint: half the developed chord must not exceed |R|; the interpreter
   reports GC330 otherwise.)
2. Move the clamp of `cylinder.toml` to C 150..200 and find the first line of each program
   that hits it. Why do both programs fail near B?
3. Program the same groove as `G03` with a negative R. What happens on the developed
   surface, and what does `verify` say?
4. Why is a G01 in G07.1 mode an ordinary straight line in (Z, C) while a G02 is not?"""),
]

nb = new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}})
out = ROOT / "notebooks" / "04_cylindrical_interpolation.ipynb"
nbformat.write(nb, out)
print("wrote", out)
