# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell
nb.cells = [
md("""# 5 · Homing: grid points, the near-zero dog and the grid shift

At power-on the controller does not know where the machine is. Homing moves each axis towards its
zero until a dog closes the *near-zero* switch, then stops at the next **grid point** of the position
detector (one per detector revolution) and takes that as its reference. Aligning a grid point with
the machine's true zero mechanically is fiddly. The better method (the origin-correction patent):
measure once, at installation, the distance from that first grid point to machine zero, store it as
the **grid shift**, and move on by it at every homing.

This notebook simulates homing pulse by pulse, lets Z3 prove when it always ends at machine zero,
and shows the configuration where it ends one grid pitch off."""),
code("""from fractions import Fraction as F
import matplotlib.pyplot as plt
from nczones import load_machine, format_decimal
from nczones.plans.homing import homing_config, edge_to_grid_distance, exactness_margin, window_is_clear
from nczones.controller.homing import simulate_homing, measure_grid_shift
from nczones.prover.homing import prove_homing, find_one_pitch_error

machine = load_machine("../specs/machines/homing_mill.toml")
cfg = homing_config(machine)["X"]
pulse = machine.axis("X").pulse
print(f"dog edge at X{format_decimal(cfg.dog_position)}, grid pitch {format_decimal(cfg.grid_pitch)} mm, "
      f"detector phase {format_decimal(cfg.detector_phase)}, stored grid shift {format_decimal(cfg.grid_shift)}")
print(f"switch jitter ±{format_decimal(cfg.switch_jitter)} mm, servo lag {format_decimal(cfg.lag)} mm at search speed")"""),
md("""## One homing, event by event"""),
code("""run = simulate_homing(cfg, pulse)
for e in run.events:
    print(f"{float(e.time_s):8.3f} s  X{format_decimal(e.position):>9}  {e.kind.value:<22} {e.text}")
print("origin error:", run.origin_error_pulses, "pulses")"""),
code("""fig, ax = plt.subplots(figsize=(8, 2.2))
grid = [cfg.detector_phase + k * cfg.grid_pitch for k in range(-3, 3)]
ax.vlines([float(g) for g in grid], 0, 1, colors="#888", linestyles=":", label="grid points")
lo = cfg.dog_position - cfg.dog_length
ax.axvspan(float(lo), float(cfg.dog_position), color="#f4c542", alpha=0.4, label="dog")
for e in run.events:
    ax.plot(float(e.position), 0.5, "o")
    ax.annotate(e.kind.value, (float(e.position), 0.5), rotation=60, fontsize=7, xytext=(0, 6), textcoords="offset points")
ax.set_xlim(-15, 20); ax.set_yticks([]); ax.set_xlabel("machine X (mm)"); ax.legend(loc="lower right", fontsize=7)
plt.show()"""),
md("""## The grid shift makes every detector phase exact

Re-mounting the detector changes its phase, so the grid points move. After a new installation
measurement homing ends at machine zero again — for every phase we try here, and Z3 proves it for
all phases at once below."""),
code("""phases = [F(k, 8) for k in range(0, 80)]  # 0 .. 9.875 mm
errors = []
for phase in phases:
    shift = measure_grid_shift(cfg, pulse, start=F(40), phase=phase).grid_shift
    errors.append(simulate_homing(cfg, pulse, start=F(40), phase=phase, grid_shift=shift).origin_error_pulses)
print(f"{len(phases)} phases: origin errors seen = {sorted(set(errors))} pulses")
fig, ax = plt.subplots(figsize=(7, 2.2))
ax.plot([float(p) for p in phases], errors, ".")
ax.set_xlabel("detector phase (mm)"); ax.set_ylabel("origin error (pulses)")
plt.show()"""),
md("""## When the dog edge sits next to a grid point

The switch trips somewhere within ± jitter of the dog edge, and the controller sees the signal only
after the servo lag. If a grid point lies inside that window, one homing latches it and the next
latches the following one: the origin is one grid pitch off. Z3 searches for such a configuration;
the simulation replays it."""),
code("""proof = find_one_pitch_error(cfg, pulse)
cex = proof.counterexample
print(proof.statement)
print("Z3:", proof.status.value, "| phase", format_decimal(cex.phase), "| trip offset", format_decimal(cex.trip_offset))
replayed = simulate_homing(cfg, pulse, start=F(40), phase=cex.phase, trip_offset=cex.trip_offset)
print("origin error per Z3:", cex.origin_error_pulses, "pulses; per simulation:", replayed.origin_error_pulses,
      "pulses; grid pitch =", int(cfg.grid_pitch / pulse), "pulses")"""),
code("""trips = [F(k, 1000) for k in range(-int(cfg.switch_jitter * 1000), int(cfg.switch_jitter * 1000) + 1, 2)]
shift = measure_grid_shift(cfg, pulse, start=F(40), phase=cex.phase).grid_shift
errs = [simulate_homing(cfg, pulse, start=F(40), phase=cex.phase, trip_offset=t, grid_shift=shift).origin_error_pulses for t in trips]
fig, ax = plt.subplots(figsize=(7, 2.2))
ax.step([float(t) for t in trips], errs, where="mid")
ax.set_xlabel("where the switch trips, from the dog edge (mm)"); ax.set_ylabel("origin error (pulses)")
ax.set_title(f"phase {format_decimal(cex.phase)}: the same machine homes to two different origins")
plt.show()"""),
md("""## The condition, proved

Homing is always exact when the distance from the dog edge (plus lag) to the nearest grid point
exceeds the jitter. `prove_homing` checks every claim for the configured axis."""),
code("""report = prove_homing(cfg, pulse)
for p in report.proofs:
    print(f"{p.status.value:>8}  {p.name:<26} {p.statement}")
print(f"edge-to-grid distance {format_decimal(report.edge_to_grid)} mm, needed more than "
      f"{format_decimal(report.margin)} mm -> window clear: {report.window_clear}; {report.solver}")"""),
md("""## Exercises

1. Move the dog edge (`dog_position`) in a copy of `homing_mill.toml` until `nczones home --prove`
   reports a counterexample. Reproduce it with the printed `nczones home --phase ... --trip-offset ...`.
2. Double the search speed. What happens to the lag, and to the exactness margin?
3. A one-pitch homing error shifts every zone. Use `nczones verify --param home.X=-10..10` on a
   program to see whether it stays safe anyway."""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/05_homing.ipynb")
