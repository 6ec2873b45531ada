"""Benchmark the reference controller: axis-pulses per second (script, not a test).

Runs long lines (vectorized numpy path vs the naive per-pulse Python loop,
both with per-pulse limit monitoring) and arcs, on one core, and prints
axis-pulses/s and the speed-up; the same for arcs (vectorized walk,
controller/arcs.py, vs the per-step reference walk).  Targets (issue 26): >= 50
million axis-pulses/s on lines, >= 25 million on arcs.  An axis-pulse is one
pulse on one axis.

Arc rates are the fastest of ``--repeat`` runs (CPU time; default 3), printed with
the first run (cold: fresh memory pages cost system time).

    python bench/bench_controller.py [--quick] [--repeat N]
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


REPEAT = 1  # runs per measurement; the fastest CPU time is reported (set by --repeat)
FIRST: dict[str, float] = {}  # the first run's CPU time per label, when REPEAT > 1


def _run(segs, engine, monitor="pulse", label=None):
    best = r = None
    for k in range(REPEAT):
        t = time.process_time()  # CPU time: the machine may be shared
        r = simulate(segs, MACHINE, settings=Settings(engine=engine, log_motions=False), monitor=monitor)
        dt = time.process_time() - t
        if k == 0 and label:
            FIRST[label] = dt
        best = dt if best is None else min(best, dt)
    return sum(r.pulses), best, r


def _first(label, ap):
    if REPEAT > 1 and label in FIRST:
        return f" [best of {REPEAT}; first run {FIRST[label]:.3f} s = {ap / FIRST[label] / 1e6:.2f} M]"
    return ""


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs per arc measurement; the fastest CPU time is printed, with the first run's")
    args = ap.parse_args()
    global REPEAT
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
    arcs = [_arc((radius, 0, 0), (radius, 0, 10), False), _arc((radius, 0, 10), (radius, 0, 0), True)]
    REPEAT = max(args.repeat, 1)
    ap_a, dt_a, r = _run(arcs, "vector", label="helix")
    assert r.program_position == (F(radius), F(0), F(0))
    rate_a = ap_a / dt_a
    print(f"full-circle helices (R{radius}), vectorized:    {ap_a:,} axis-pulses in {dt_a:.3f} s "
          f"= {rate_a / 1e6:.2f} M axis-pulses/s{_first('helix', ap_a)}")
    flat = [_arc((radius, 0, 0), (radius, 0, 0), False), _arc((radius, 0, 0), (radius, 0, 0), True)]
    ap_f, dt_f, _ = _run(flat, "vector", label="flat")
    rate_f = ap_f / dt_f
    print(f"full circles (R{radius}, no helix), vectorized: {ap_f:,} axis-pulses in {dt_f:.3f} s "
          f"= {rate_f / 1e6:.2f} M axis-pulses/s{_first('flat', ap_f)}")
    REPEAT = 1
    small = [_arc((10, 0, 0), (10, 0, 1), False)]  # the reference walk, one step per Python iteration
    ap_s, dt_s, r_ref = _run(small, "reference")
    _, dt_sv, r_vec = _run(small, "vector")
    assert r_ref.pulses == r_vec.pulses and r_ref.steps == r_vec.steps  # identical walks
    rate_s = ap_s / dt_s
    print(f"helix R10, naive per-step reference walk: {ap_s:,} axis-pulses in {dt_s:.3f} s "
          f"= {rate_s / 1e6:.3f} M axis-pulses/s (vectorized on the same arc: {ap_s / dt_sv / 1e6:.2f} M)")
    print(f"speed-up vectorized / per-step reference on arcs: {rate_a / rate_s:.0f}x")
    print(f"targets: long lines >= 50 M axis-pulses/s {'met' if rate_v >= 50e6 else 'NOT met'}, "
          f"arcs >= 25 M {'met' if min(rate_a, rate_f) >= 25e6 else 'NOT met'} (best of {args.repeat}; "
          f"first runs: {'met' if min(ap_a / FIRST['helix'], ap_f / FIRST['flat']) >= 25e6 else 'NOT met'})")
    print("(times are CPU seconds of this process: time.process_time)")


def _arc(a, b, cw):
    return Segment(SegmentKind.ARC, tuple(F(v) for v in a), tuple(F(v) for v in b), AXES, feed_mm_min=F(5000),
                   plane=Plane.XY, clockwise=cw, centre=(F(0), F(0)))


if __name__ == "__main__":
    main()
