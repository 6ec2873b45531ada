"""Benchmark the reference controller: axis-pulses per second (script, not a test).

Runs long lines (vectorized numpy path vs the naive per-pulse Python loop,
both with per-pulse limit monitoring) and arcs, on one core, and prints
axis-pulses/s and the speed-up; the same for arcs (vectorized walk,
controller/arcs.py, vs the per-step reference walk).  Targets (issue 26): >= 50
million axis-pulses/s on lines, >= 25 million on arcs.  An axis-pulse is one
pulse on one axis.

Arc rates are printed cold and warm separately (CPU time): *cold* is the first
arc of a process, measured both in this process (after the line runs) and in
``--processes`` fresh processes that run nothing else (fresh memory pages and
first calls cost there; one OpenBLAS thread, as the ``nczones`` command sets); *warm* is the fastest of the ``--repeat`` runs after
the first in this process.  The arc target holds only if every cold and warm
figure meets it.

    python bench/bench_controller.py [--quick] [--repeat N] [--processes N]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from fractions import Fraction as F
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from nczones.controller import Settings, simulate  # noqa: E402
from nczones.machine import parse_machine  # noqa: E402
from nczones.motion import Plane, Segment, SegmentKind  # noqa: E402
from nczones.precompiled.machines import box_machine  # noqa: E402

MACHINE = parse_machine(box_machine("bench", "5000", ['pulse = "0.001"', 'monitor_period_ms = "2"'], rapid="60000") + """
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
    t = time.process_time()  # CPU time: the machine may be shared
    r = simulate(segs, MACHINE, settings=Settings(engine=engine, log_motions=False), monitor=monitor)
    return sum(r.pulses), time.process_time() - t, r


def _cold_and_warm(segs, repeat):
    """CPU seconds of the first run and the fastest of the ``repeat`` runs after it (vector engine)."""
    ap, first, r = _run(segs, "vector")
    warm = min(_run(segs, "vector")[1] for _ in range(max(repeat, 1)))
    return ap, first, warm, r


def _helices(radius):
    return [_arc((radius, 0, 0), (radius, 0, 10), False), _arc((radius, 0, 10), (radius, 0, 0), True)]


def _fresh_processes(n, radius):
    """Axis-pulses/s of the helices as the first arcs of ``n`` fresh processes (each prints its own CPU time)."""
    rates = []
    env = dict(os.environ, PYTHONHASHSEED="0")
    if "OPENBLAS_NUM_THREADS" not in env and "OMP_NUM_THREADS" not in env:
        # as the nczones command sets it: OpenBLAS's idle threads otherwise spin for about 0.05 s of CPU
        # after numpy loads, which the child's process CPU time would count as the arc's
        env["OPENBLAS_NUM_THREADS"] = "1"
    for _ in range(n):
        out = subprocess.run([sys.executable, __file__, "--first-arc", str(radius)], check=True, env=env,
                             capture_output=True, text=True).stdout
        got = json.loads(out)
        rates.append(got["axis_pulses"] / got["cpu_s"])
    return rates


def _first_arc(radius):
    """Child of :func:`_fresh_processes`: the helices as the first motion this process runs."""
    ap, dt, r = _run(_helices(radius), "vector")
    assert r.program_position == (F(radius), F(0), F(0))
    print(json.dumps({"axis_pulses": ap, "cpu_s": dt}))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeat", type=int, default=3, help="warm runs per arc measurement (the fastest is printed)")
    ap.add_argument("--processes", type=int, default=3, help="fresh processes measuring a cold first arc")
    ap.add_argument("--first-arc", type=int, default=None, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.first_arc is not None:
        _first_arc(args.first_arc)
        return
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
    ap_a, cold_a, warm_a, r = _cold_and_warm(_helices(radius), args.repeat)
    assert r.program_position == (F(radius), F(0), F(0))
    print(f"full-circle helices (R{radius}), vectorized, {ap_a:,} axis-pulses:")
    print(f"  warm (fastest of {args.repeat} runs after the first): {warm_a:.3f} s = {ap_a / warm_a / 1e6:.2f} M axis-pulses/s")
    print(f"  cold (the first arc of this process):          {cold_a:.3f} s = {ap_a / cold_a / 1e6:.2f} M axis-pulses/s")
    fresh = _fresh_processes(args.processes, radius)
    if fresh:
        print(f"  cold (the first arc of {len(fresh)} fresh processes):    "
              + ", ".join(f"{v / 1e6:.2f}" for v in fresh) + " M axis-pulses/s")
    flat = [_arc((radius, 0, 0), (radius, 0, 0), False), _arc((radius, 0, 0), (radius, 0, 0), True)]
    ap_f, cold_f, warm_f, _ = _cold_and_warm(flat, args.repeat)
    print(f"full circles (R{radius}, no helix), vectorized, {ap_f:,} axis-pulses:")
    print(f"  warm (fastest of {args.repeat} runs after the first): {warm_f:.3f} s = {ap_f / warm_f / 1e6:.2f} M axis-pulses/s")
    print(f"  cold (its first run in this process):          {cold_f:.3f} s = {ap_f / cold_f / 1e6:.2f} M axis-pulses/s")
    small = [_arc((10, 0, 0), (10, 0, 1), False)]  # the reference walk, one step per Python iteration
    ap_s, dt_s, r_ref = _run(small, "reference")
    _, dt_sv, r_vec = _run(small, "vector")
    assert r_ref.pulses == r_vec.pulses and r_ref.steps == r_vec.steps  # identical walks
    rate_s = ap_s / dt_s
    warm_rate = ap_a / warm_a
    print(f"helix R10, naive per-step reference walk: {ap_s:,} axis-pulses in {dt_s:.3f} s "
          f"= {rate_s / 1e6:.3f} M axis-pulses/s (vectorized on the same arc: {ap_s / dt_sv / 1e6:.2f} M)")
    print(f"speed-up vectorized (warm helices) / per-step reference on arcs: {warm_rate / rate_s:.0f}x")
    warm_min = min(ap_a / warm_a, ap_f / warm_f)
    cold_min = min([ap_a / cold_a, ap_f / cold_f, *fresh])
    print(f"targets: long lines >= 50 M axis-pulses/s {'met' if rate_v >= 50e6 else 'NOT met'}; "
          f"arcs >= 25 M warm {'met' if warm_min >= 25e6 else 'NOT met'} (lowest {warm_min / 1e6:.1f} M), "
          f"cold {'met' if cold_min >= 25e6 else 'NOT met'} (lowest {cold_min / 1e6:.1f} M)")
    load = os.getloadavg() if hasattr(os, "getloadavg") else None
    print("(times are CPU seconds of each process: time.process_time"
          + (f"; load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f})" if load else ")"))


def _arc(a, b, cw):
    return Segment(SegmentKind.ARC, tuple(F(v) for v in a), tuple(F(v) for v in b), AXES, feed_mm_min=F(5000),
                   plane=Plane.XY, clockwise=cw, centre=(F(0), F(0)))


if __name__ == "__main__":
    main()
