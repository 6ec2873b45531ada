"""Benchmark the reference controller: axis-pulses per second (script, not a test).

Runs long lines (vectorized numpy path vs the naive per-pulse Python loop,
both with per-pulse limit monitoring) and arcs, on one core, and prints
axis-pulses/s and the speed-up.  Target: >= 20 million axis-pulses/s for long
lines.  An axis-pulse is one pulse on one axis.

    python bench/bench_controller.py [--quick]
"""

from __future__ import annotations

import argparse
import sys
import time
from fractions import Fraction as F
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from nczones.controller import Settings, simulate  # noqa: E402
from nczones.machine import parse_machine  # noqa: E402
from nczones.motion import Plane, Segment, SegmentKind  # noqa: E402

MACHINE = parse_machine("""
[machine]
name = "bench"
axes = ["X", "Y", "Z"]
pulse = "0.001"
monitor_period_ms = "2"
[machine.rapid]
X = "60000"
Y = "60000"
Z = "60000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[[zones]]
name = "travel"
kind = "box"
min = { X = "-5000", Y = "-5000", Z = "-5000" }
max = { X = "5000", Y = "5000", Z = "5000" }
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "-5000"
regions = [{ upto = "-1000", max = "5000" }, { upto = "0", max = "4000" }, { upto = "5000", min = "-4000", max = "5000" }]
""", "bench.toml")
AXES = MACHINE.axis_names


def _line(a, b):
    return Segment(SegmentKind.LINE, tuple(F(v) for v in a), tuple(F(v) for v in b), AXES, feed_mm_min=F(5000))


def _run(segs, engine, monitor="pulse"):
    t = time.perf_counter()
    r = simulate(segs, MACHINE, settings=Settings(engine=engine, log_motions=False), monitor=monitor)
    dt = time.perf_counter() - t
    return sum(r.pulses), dt, r


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    length = 400 if args.quick else 2000  # mm per line
    lines = [_line((0, 0, 0), (length, length * 0.75, length * 0.5)),
             _line((length, length * 0.75, length * 0.5), (0, 0, 0))]
    ap_v, dt_v, _ = _run(lines, "vector")
    print(f"long lines, vectorized, per-pulse monitor: {ap_v:,} axis-pulses in {dt_v:.3f} s "
          f"= {ap_v / dt_v / 1e6:.1f} M axis-pulses/s")
    ap_p, dt_p, _ = _run(lines, "vector", "periodic")
    print(f"long lines, vectorized, periodic monitor:  {ap_p:,} axis-pulses in {dt_p:.3f} s "
          f"= {ap_p / dt_p / 1e6:.1f} M axis-pulses/s")
    short = [_line((0, 0, 0), (40, 30, 20))]
    ap_r, dt_r, _ = _run(short, "reference")
    ap_v2, dt_v2, _ = _run(short, "vector")
    rate_r, rate_v = ap_r / dt_r, ap_v / dt_v
    print(f"same kind of line, naive per-pulse loop:   {ap_r:,} axis-pulses in {dt_r:.3f} s "
          f"= {rate_r / 1e6:.3f} M axis-pulses/s")
    print(f"speed-up vectorized / per-pulse loop: {rate_v / rate_r:.0f}x")
    radius = 50 if args.quick else 200
    arcs = [Segment(SegmentKind.ARC, (F(radius), F(0), F(0)), (F(radius), F(0), F(10)), AXES,
                    feed_mm_min=F(5000), plane=Plane.XY, clockwise=cw, centre=(F(0), F(0)))
            for cw in (False, True)]
    arcs[1] = Segment(SegmentKind.ARC, (F(radius), F(0), F(10)), (F(radius), F(0), F(0)), AXES,
                      feed_mm_min=F(5000), plane=Plane.XY, clockwise=True, centre=(F(0), F(0)))
    ap_a, dt_a, r = _run(arcs, "vector")
    assert r.program_position == (F(radius), F(0), F(0))
    print(f"full-circle helices (R{radius}), lattice walk:   {ap_a:,} axis-pulses in {dt_a:.3f} s "
          f"= {ap_a / dt_a / 1e6:.2f} M axis-pulses/s")
    target = 20e6
    print(f"target >= 20 M axis-pulses/s on long lines: {'met' if rate_v >= target else 'NOT met'}")


if __name__ == "__main__":
    main()
