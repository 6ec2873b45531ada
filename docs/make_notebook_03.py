# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell
nb.cells = [
md("""# 3 · Inside the controller: pulses, the limit monitor, machine lock and program check

An NC controller does not move along lines and arcs; it sends **pulses**, one pulse = one step of
one axis (0.001 mm here). The interpolator decides, step by step, which axes get a pulse so that the
commanded position stays within one pulse of the ideal path. A **limit monitor** compares the current
position with the zone table — after every pulse, or every few milliseconds — and, on a violation,
stops pulse distribution in the offending direction while still letting the axis move back.

nczones contains an executable reference controller that does exactly this, in integers."""),
code("""from fractions import Fraction as F
from pathlib import Path
import matplotlib.pyplot as plt
from nczones import load_machine, parse_machine, format_decimal
from nczones.gcode import segments_text
from nczones.controller import Controller, simulate, line_steps, arc_walk"""),
md("""## Pulse distribution on a line

The line from (0, 0) to (13, 5) pulses: after step *i* each axis stands at the ideal position rounded
to the nearest pulse, so it is never more than half a pulse away on any axis."""),
code("""p0, p1 = (0, 0), (13, 5)
steps = [p0] + list(line_steps(p0, p1))
n = max(abs(b - a) for a, b in zip(p0, p1))
worst = max(abs(F(x) - F(i * p1[0], n)) for i, (x, _) in enumerate(steps)) , max(abs(F(y) - F(i * p1[1], n)) for i, (_, y) in enumerate(steps))
print(f"{len(steps) - 1} steps; largest deviation from the ideal line per axis: "
      f"X {format_decimal(worst[0])} pulse, Y {format_decimal(worst[1])} pulse")
fig, ax = plt.subplots(figsize=(6, 3))
ax.plot([0, 13], [0, 5], "k--", lw=1, label="ideal line")
ax.step([p[0] for p in steps], [p[1] for p in steps], where="post", marker="o", ms=3, label="commanded pulse position")
ax.set_aspect("equal"); ax.set_xlabel("X (pulses)"); ax.set_ylabel("Y (pulses)"); ax.legend(fontsize=8)
plt.show()"""),
md("""## Circular interpolation

The arc walk steps on the integer lattice around the exact circle and closes full circles exactly."""),
code("""r = 12
walk = arc_walk((r, 0), (r, 0), (F(r), F(0)), (F(r), F(0)), (F(0), F(0)), False, 0, (F(1), F(1)))
pts = [(r, 0)] + list(walk.points)
print(f"{len(walk.points)} steps for a full circle of radius {r} pulses; closes at {pts[-1]}")
import math
fig, ax = plt.subplots(figsize=(4, 4))
ax.plot([r * math.cos(t / 100) for t in range(629)], [r * math.sin(t / 100) for t in range(629)], "k--", lw=1)
ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=".", ms=4)
ax.set_aspect("equal"); ax.set_title("pulse positions of a full circle")
plt.show()"""),
md("""## The monitor stops the line at the notch

The grinder program below dips into the work-head notch. With monitoring after every pulse the
controller stops at the first pulse outside, clears the offending direction, and raises an alarm."""),
code("""grinder = load_machine("../specs/machines/grinder.toml")
program = Path("../specs/examples/programs/notch_dip.ngc").read_text()
motion = segments_text(program, grinder)
ctl = Controller(grinder, monitor="pulse")
result = ctl.run(motion)
alarm = result.alarms[0]
print(f"alarm in line {alarm.line} ({alarm.source!r}), zone {alarm.zone!r}, at",
      {a: format_decimal(c) for a, c in zip(result.axes, alarm.position)},
      "- cleared:", [f"{a}{'+' if s > 0 else '-'}" for a, s in alarm.blocked])"""),
code("""forward = ctl.jog("X", 5)
back = ctl.jog("X", -5)
print(f"jog X+5 pulses: refused={forward.refused}, moved {forward.moved}")
print(f"jog X-5 pulses: refused={back.refused}, moved {back.moved}, now at",
      {a: format_decimal(c) for a, c in zip(result.axes, back.position)})"""),
md("""## Overshoot: monitoring every few milliseconds at rapid feed

Real monitors run periodically. Between two samples the axis keeps moving, so the alarm comes up to
*feed × period* past the boundary. Below, a rapid runs into the notch; we vary the monitor period."""),
code("""text = Path("../specs/machines/grinder.toml").read_text().replace('rapid_mode = "dogleg"', 'rapid_mode = "linear"')
rapid_into_notch = "G21 G90 G54\\nG0 X-250 Y300\\nG1 Y130 F500\\nG0 X50\\n"
periods, overshoot_mm, bounds = [], [], []
for period in ["1", "2", "5", "10", "20"]:
    m = parse_machine(text.replace('monitor_period_ms = "5"', f'monitor_period_ms = "{period}"'), "grinder.toml")
    r = simulate(segments_text(rapid_into_notch, m), m, monitor="periodic")
    a = r.alarms[0]
    past = a.position[0] - a.first_outside[0]
    periods.append(float(period)); overshoot_mm.append(float(past)); bounds.append(r.overshoot_bound_mm)
    print(f"period {period:>2} ms: alarm {format_decimal(past)} mm after the first outside pulse "
          f"(bound feed x period = {r.overshoot_bound_mm:.3f} mm)")
fig, ax = plt.subplots(figsize=(6, 3))
ax.plot(periods, overshoot_mm, "o-", label="measured overshoot")
ax.plot(periods, bounds, "k--", label="feed x period")
ax.set_xlabel("monitor period (ms)"); ax.set_ylabel("mm past the first outside pulse"); ax.legend(fontsize=8)
plt.show()"""),
md("""## Machine lock versus program check

*Machine lock* runs the program with the axes frozen — and with them the machine coordinates the stroke
check reads, so a program that leaves the allowed set passes unnoticed. *Program check* (the Chinese
patent in `shared/seeds`) keeps the axes still but lets temporary machine coordinates follow the
interpolation, so the stroke check still works; it also runs at maximum feed without acceleration,
so the check is much faster than the real run."""),
code("""runs = {mode: simulate(motion, grinder, mode=mode) for mode in ["normal", "lock", "check"]}
for mode, r in runs.items():
    where = "-" if not r.alarms else {a: format_decimal(c) for a, c in zip(r.axes, r.alarms[0].position)}
    print(f"{mode:>6}: alarms {len(r.alarms)} at {where}; simulated time {r.simulated_time_s:8.3f} s; "
          f"machine position afterwards {[format_decimal(c) for c in r.machine_position]}")
print()
print(runs["lock"].blind_spot)"""),
code("""fig, ax = plt.subplots(figsize=(5, 2.6))
ax.bar(list(runs), [r.simulated_time_s for r in runs.values()], color=["#1f4e9c", "#999", "#4c8c4c"])
ax.set_ylabel("simulated time (s)"); ax.set_title("same program, three modes")
plt.show()"""),
md("""## Exercises

1. Monitor after every pulse and compare the alarm position with the prover's first exit point for
   the same program (`nczones.prover.verify`). How far apart are they, in pulses?
2. Make the rapid dogleg again. Does the alarm move? Why?
3. Find the longest monitor period for which the overshoot at the notch stays below 0.5 mm."""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/03_inside_the_controller.ipynb")
