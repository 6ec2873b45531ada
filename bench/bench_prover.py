"""Prover benchmark (a script, not a test).

    python bench/bench_prover.py [--lines 1000000] [--small 100000] [--sample 2000]

Each case runs ``nczones.prover.verify`` end to end (read, interpret,
screen, decide) in a fresh process and prints: end-to-end seconds (wall
clock and CPU), lines/s and segments/s, the share of segments the screening
tier proved, the peak resident memory, and the ratio against sending every
segment to Z3 — measured in the same process on ``--sample`` segments taken
evenly over the whole program (so the mix of lines and arcs is the
program's), extrapolated to all segments.  It also times the per-segment
tier 1 (Segment objects, no column chunks) on the same sample: the naive
exact path the vectorized screen replaces.

Cases: ``stellabee1.ngc`` from the corpus against a box, and a generated
program of ``--small`` and ``--lines`` lines against a 256-region stepped
table (the two sizes show whether time and memory grow linearly / stay flat).
"""

from __future__ import annotations

import argparse
import random
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from _bench import STELLABEE, Clock, emit, machine_description, peak_rss_mib, run_case  # noqa: E402

from nczones.precompiled.machines import box_machine  # noqa: E402

BOX_MACHINE = box_machine("bench mill", "500", ['rapid_mode = "linear"'])


def table_machine(regions: int = 256) -> str:
    rows = ", ".join(f'{{upto = "{(i + 1) * 4}", min = "{-(i % 7) - 1}", max = "{300 + i % 5}"}}' for i in range(regions))
    return f"""
[machine]
name = "bench grinder"
axes = ["X", "Y"]
rapid_mode = "dogleg"
[machine.rapid]
X = "12000"
Y = "8000"
[machine.reference]
X = "10"
Y = "100"
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "0"
regions = [{rows}]
"""


def generate(n: int, path: Path) -> None:
    rnd = random.Random(0)
    with path.open("w") as fh:
        fh.write("G21 G90 G17\nG1 F1000\n")
        for _ in range(n - 2):
            fh.write(f"X{rnd.randint(1000, 1000000) / 1000:.3f} Y{rnd.randint(0, 299000) / 1000:.3f}\n")


def sample_segments(program, machine, sample: int, total: int):
    """About ``sample`` segments spread evenly over the program (views of the chosen rows only)."""
    from nczones.gcode import interpret
    from nczones.prover.core import _chunk_rows

    step = max(1, total // sample)
    out = []
    index = 0
    for chunk in interpret(program, machine, arc_tolerance="0.01"):
        n = len(chunk)
        first = (-index) % step
        rows = list(range(first, n, step))
        if chunk.scale is None:
            out += [chunk.objects[i] for i in rows]
        else:
            out += list(_chunk_rows(chunk, rows))
        index += n
    return out


def case(program: str, machine_text: str, sample: int) -> None:
    from nczones.machine import parse_machine
    from nczones.prover import Prover, verify

    machine = parse_machine(machine_text)
    lines = Path(program).read_bytes().count(b"\n")
    with Clock() as c:
        r = verify(program, machine, arc_tolerance="0.01")
    stats = dict(r.stats)
    counts = r.extra.get("counts", {})
    segs = counts.get("segments", stats.get("segments", 0))
    result = {"lines": lines, "segments": segs, "wall": c.wall, "cpu": c.cpu, "verdict": r.verdict.label,
              "screened": stats.get("screened", 0), "z3_queries": stats.get("z3_queries", 0),
              "fast_lines": counts.get("fast_lines", 0)}
    result["peak_rss_mib"] = peak_rss_mib()  # of verify() alone, before the Z3 sample
    segs_sample = sample_segments(program, machine, sample, max(segs, 1))
    z3 = Prover(machine, engine="z3")
    with Clock() as cz:
        for s in segs_sample:
            z3.check(s)
    tier1 = Prover(machine)
    with Clock() as ct:
        for s in segs_sample:
            tier1.check(s)
    n = max(len(segs_sample), 1)
    result.update(sample=len(segs_sample), z3_per_segment=cz.wall / n, z3_per_segment_cpu=cz.cpu / n,
                  tier1_per_segment=ct.wall / n, tier1_per_segment_cpu=ct.cpu / n)
    emit(result)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=1_000_000)
    ap.add_argument("--small", type=int, default=100_000)
    ap.add_argument("--sample", type=int, default=2000)
    ap.add_argument("--case", nargs=3, metavar=("PROGRAM", "MACHINE", "SAMPLE"), help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.case:
        case(a.case[0], Path(a.case[1]).read_text(), int(a.case[2]))
        return
    me = str(Path(__file__).resolve())
    print(f"machine: {machine_description()}")
    rows = []
    with tempfile.TemporaryDirectory() as d:
        box = Path(d) / "box.toml"
        box.write_text(BOX_MACHINE)
        table = Path(d) / "table.toml"
        table.write_text(table_machine())
        if STELLABEE.is_file():
            rows.append(("stellabee1.ngc, box", run_case(me, "--case", str(STELLABEE), str(box), str(a.sample))))
        else:
            print("stellabee1.ngc: corpus not found, skipped")
        for n in (a.small, a.lines):
            path = Path(d) / f"gen{n}.ngc"
            generate(n, path)
            rows.append((f"generated {n:,} lines, 256-region table",
                         run_case(me, "--case", str(path), str(table), str(a.sample))))
    for name, r in rows:
        segs = r["segments"]
        z3_total = r["z3_per_segment"] * segs
        t1_total = r["tier1_per_segment"] * segs
        print(f"{name}: verdict {r['verdict']}; {r['lines']:,} lines, {segs:,} segments; end-to-end "
              f"{r['wall']:.2f} s wall, {r['cpu']:.2f} s CPU; {r['lines'] / r['wall']:,.0f} lines/s, "
              f"{segs / r['wall']:,.0f} segments/s (wall); screened {r['screened'] / max(segs, 1):.1%}; "
              f"Z3 queries {r['z3_queries']}; fast-path lines {r['fast_lines'] / max(r['lines'], 1):.0%}; "
              f"peak RSS {r['peak_rss_mib']:.0f} MiB")
        print(f"    Z3 per segment (sample of {r['sample']}): {r['z3_per_segment'] * 1e6:.0f} us -> {z3_total:,.1f} s "
              f"extrapolated: ratio {z3_total / r['wall']:,.0f}x wall ({r['z3_per_segment_cpu'] * segs / r['cpu']:,.0f}x CPU); "
              f"per-segment tier 1 without chunks: {r['tier1_per_segment'] * 1e6:.0f} us -> {t1_total:,.1f} s, "
              f"ratio {t1_total / r['wall']:,.1f}x")
    gen = [r for name, r in rows if name.startswith("generated")]
    if len(gen) == 2:
        a_, b_ = gen
        print(f"scaling {a_['lines']:,} -> {b_['lines']:,} lines: time x{b_['wall'] / a_['wall']:.1f} wall, "
              f"x{b_['cpu'] / a_['cpu']:.1f} CPU (lines x{b_['lines'] / a_['lines']:.0f}); peak RSS "
              f"{a_['peak_rss_mib']:.0f} -> {b_['peak_rss_mib']:.0f} MiB")


if __name__ == "__main__":
    main()
