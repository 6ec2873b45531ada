"""Generate notebooks/06_tool_break_recovery.ipynb (run from the repository root)."""

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = []
md = lambda s: cells.append(new_markdown_cell(s.strip()))  # noqa: E731
code = lambda s: cells.append(new_code_cell(s.strip()))  # noqa: E731

md("""
# 6 · Tool-break recovery: the moves nobody programmed

A long unattended cut breaks its tool. A controller with *automatic recovery* stops, saves where it
was, retracts, rapids to the tool changer, changes the tool, comes back above the place to restart,
rapids down to a small distance α above it, approaches slowly, restores its state and goes on.

Those moves are made by the controller, not written in the program, so checking the program alone
says nothing about them. In this notebook a program that is perfectly safe on its own turns out to
drive the spindle through a clamp when the tool breaks in one of its passes — and the prover finds
that for **every** possible break point at once, not by sampling.
""")

code("""
from fractions import Fraction as F
import matplotlib.pyplot as plt
from nczones import load_machine, format_decimal
from nczones.gcode import interpret
from nczones.prover import verify
from nczones.controller import simulate
from nczones.plans.recovery import tool_change_config, recovery_legs, motion_sequences

PROGRAM = "../specs/examples/programs/recovery_clamp.ngc"
low = load_machine("../specs/examples/machines/mill_toolchange.toml")
high = load_machine("../specs/examples/machines/mill_toolchange_high.toml")
print(open(PROGRAM).read())
cfg = tool_change_config(low)
print("tool change at", [format_decimal(v) for v in cfg.position_tuple(low.axis_names)],
      "| clearance Z", format_decimal(cfg.clearance), "| alpha", format_decimal(cfg.approach_distance),
      "| variant", cfg.variant.value)
""")

md("""
## The program alone is safe

The two passes sit either side of a fence clamp (a *tip* zone: the cutter must stay above its top);
the rapid between them goes over it.
""")

code("""
alone = verify(PROGRAM, low)
print("program alone:", alone.verdict.label)
clamp = next(z for z in low.allowed.zones if z.name == "clamp")
print("clamp:", {a: (format_decimal(lo) if lo is not None else None, format_decimal(hi) if hi is not None else None)
                 for a, lo, hi in clamp.limits})
""")

md("""
## Motion sequences and the sequence-start register

A *motion sequence* is a maximal run of consecutive cutting motions (G1/G2/G3) with the same tool
length; rapids, dwells and tool-length changes end it. The controller stores the position where
each sequence starts: the `start` variant restarts there and re-cuts up to the break.
""")

code("""
segs = list(interpret(PROGRAM, low).segments())
for a, b in motion_sequences(segs):
    print(f"sequence: lines {segs[a].line}..{segs[b].line}, starts at",
          [format_decimal(v) for v in segs[a].start])
""")

md("""
## The prover: every break point at once

For a line the break point is `start + s (end - start)` with `s` a *variable* in `[0, 1]`. Every leg
of the recovery path is then a set of points parameterised by `s` and the leg's own parameter; Z3
decides whether any of them leaves the allowed set. A model gives a break parameter, which is made
rational and replayed exactly before it is reported.
""")

code("""
rec = verify(PROGRAM, low, recovery="start")
print("with recovery:", rec.verdict.label)
v = rec.violations[0]
print("tool breaks in line", v.break_line, "at s =", format_decimal(v.break_parameter, 6))
print("leg leaving the allowed set:", v.leg, "| zone:", v.zone, "| depth:", format_decimal(v.depth), "mm")
print("break point:", {a: format_decimal(x) for a, x in v.break_point})
print("point outside:", {a: format_decimal(x, 3) for a, x in v.point})
""")

code("""
L = segs[0].tool_length if segs[0].tool_length else low.tool_length(1)
P = tuple(x for _, x in v.break_point)
seq_start = next(segs[a].start for a, b in motion_sequences(segs) if segs[a].line <= v.break_line <= segs[b].line)
legs = recovery_legs(cfg, low, P, seq_start, low.tool_length(1), low.tool_length(1))

fig, ax = plt.subplots(figsize=(8, 4))
(xlo, xhi), (zlo, zhi) = [(float(lo), float(hi)) for a, lo, hi in clamp.limits if a == "X"][0], \\
                         [(float(lo), float(hi)) for a, lo, hi in clamp.limits if a == "Z"][0]
ax.add_patch(plt.Rectangle((xlo, zlo), xhi - xlo, zhi - zlo, color="#d62728", alpha=0.3, label="clamp (tip zone)"))
for s in segs:
    tip = [float(c - s.tool_length) for c in (s.start[2], s.end[2])]
    ax.plot([float(s.start[0]), float(s.end[0])], tip, "-" if s.kind.name != "RAPID" else ":",
            color="#333" if s.kind.name != "RAPID" else "#888")
for k, leg in enumerate(legs):  # later legs thinner and dashed: "to restart" retraces "to tool change" here
    ax.plot([float(leg.start[0]), float(leg.end[0])],
            [float(leg.start[2] - leg.tool_length), float(leg.end[2] - leg.tool_length)],
            "-" if k < 2 else "--", lw=5 - k, label=leg.name)
pt = dict(v.point)
ax.plot(float(pt["X"]), float(pt["Z"] - low.tool_length(1)), "kx", ms=10, label="counterexample")
ax.set_xlabel("X (mm)"); ax.set_ylabel("tool tip Z (mm)"); ax.legend(fontsize=7, loc="lower right")
ax.set_title("recovery path from the prover's break point (tip, XZ view)")
plt.show()
""")

md("""
## The controller replays the counterexample

`simulate(..., break_at=(line, fraction))` breaks the tool after that fraction of the line's
interpolation steps and runs the recovery pulse by pulse; the limit monitor watches the recovery
legs like any motion, and an alarm there says which leg it was in.
""")

code("""
r = simulate(interpret(PROGRAM, low), low, break_at=(v.break_line, v.break_parameter))
a = r.alarms[0]
print(a.kind, "alarm during", a.derived, "| zone", a.zone, "| at", [format_decimal(x) for x in a.position])
for e in r.events:
    if e.kind in ("sequence-start", "tool-break", "recovery", "tool-change", "resume"):
        print(f"{e.time_s:8.3f} s  {e.kind:<15} {dict(e.data).get('leg', '')}")
""")

md("""
## A sweep of break points agrees with the proof

The controller can only try break points one at a time. We sweep a few per cutting line: every
alarm lands on a line where the prover found a counterexample.
""")

code("""
lines = sorted({s.line for s in segs if s.kind.name in ("LINE", "ARC")})
fractions = [F(k, 8) for k in range(9)]
unsafe_lines = {w.break_line for w in rec.violations}
fig, ax = plt.subplots(figsize=(8, 2.4))
for line in lines:
    for f in fractions:
        res = simulate(interpret(PROGRAM, low), low, break_at=(line, f))
        bad = any(x.kind == "recovery" for x in res.alarms)
        assert not bad or line in unsafe_lines
        ax.plot(float(f), line, "o", color="#d62728" if bad else "#2ca02c")
ax.set_yticks(lines); ax.set_xlabel("break fraction"); ax.set_ylabel("line")
ax.set_title("controller sweep: red = recovery alarm, green = recovered and finished")
plt.show()
print("prover: unsafe break lines", sorted(unsafe_lines), "of cutting lines", lines)
""")

md("""
## The fix: retract above the clamp

The fixed machine file only raises the clearance. Both restart variants are now proved safe for
every break point.
""")

code("""
cfg_high = tool_change_config(high)
print("clearance Z", format_decimal(cfg_high.clearance), "-> tip at",
      format_decimal(cfg_high.clearance - high.tool_length(1)))
for variant in ("start", "breakpoint"):
    print(variant, verify(PROGRAM, high, recovery=variant).verdict.label)
""")

md("""
## Exercises

1. Find the lowest clearance that the prover accepts (bisect over machine files built from the text
   of `mill_toolchange.toml`).
2. Switch the machine to `rapid_mode = "dogleg"`: does the rapid to the tool changer still cross the
   clamp? Replay the new counterexample in the controller.
3. Give the replacement tool a different length register (`length_register = "H2"`) and check in
   the controller that the resumed cut keeps the tip on the same path.
4. Move the tool changer to the left of the clamp: which pass becomes unsafe now?
""")

nb = new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                        "language": "python"}})
nbformat.write(nb, "notebooks/06_tool_break_recovery.ipynb")
