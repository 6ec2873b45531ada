"""Zone-size benchmark (a script, not a test): how load and verify scale with the zones.

    python bench/bench_zones.py [--segments 100000] [--tables 16,256,4096,65536]
                                [--polygons 10,1000,100000] [--timeout 120] [--z3-sample 20]

For every machine it prints, each measured in a fresh process (CPU seconds,
which count less of the other load on a shared machine than wall seconds):

* **load**: ``load_machine`` of the TOML file (parse, validate, build zones);
* **verify**: ``nczones.prover.verify`` of a generated program of
  ``--segments`` straight moves (end to end: read, interpret, screen, decide),
  its verdict and how many segments the screen proved and Z3 decided;
* **Z3 per segment**: ``Prover(engine="z3").check`` on ``--z3-sample``
  segments of the same program, in the same process, extrapolated to every
  segment: the naive way the screen replaces, and the ratio to it.

Machines: a stepped table of ``--tables`` regions (an X-Y grinder table, the
program runs across the whole table) and an allow polygon of ``--polygons``
vertices (a digitised outline: a circle of radius 100 with a ripple of
amplitude 3; the program is a random walk of short moves between radius 60
and 0.3 inside the outline, so many segments pass close to its edges).  A case that takes longer than ``--timeout`` seconds is stopped and
printed as such.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from _bench import ROOT, Clock, emit, machine_description  # noqa: E402

HEAD = """
[machine]
name = "bench {name}"
axes = ["X", "Y"]
rapid_mode = "linear"
[machine.rapid]
X = "10000"
Y = "10000"
[machine.reference]
X = "{rx}"
Y = "{ry}"
"""


def table_machine(regions: int) -> str:
    """A stepped table over X in [0, 4000] (regions of equal width), Y limited to about [-1, 300]."""
    width = 4000 / regions
    rows = ",\n  ".join(f'{{upto = "{(i + 1) * width:.6f}", min = "{-(i % 7) - 1}", max = "{300 + i % 5}"}}'
                        for i in range(regions))
    return HEAD.format(name="table", rx="10", ry="100") + f"""
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "0"
regions = [
  {rows}
]
"""


def outline(n: int) -> list[tuple[float, float]]:
    """``n`` vertices of a rippled circle (radius 100 +- 3), counter-clockwise, 4 decimals."""
    out = []
    for i in range(n):
        th = 2 * math.pi * i / n
        r = 100 + 3 * math.sin(37 * th)
        out.append((round(r * math.cos(th), 4), round(r * math.sin(th), 4)))
    return out


def polygon_machine(n: int) -> str:
    verts = ",\n  ".join(f'["{x:.4f}", "{y:.4f}"]' for x, y in outline(n))
    return HEAD.format(name="polygon", rx="0", ry="0") + f"""
[[zones]]
name = "fixture outline"
kind = "polygon"
plane = ["X", "Y"]
vertices = [
  {verts}
]
"""


def table_lines(n: int) -> Iterator[str]:
    """The lines of :func:`table_program`: ``n`` moves across the whole table, then a program end."""
    rnd = random.Random(0)
    yield "G21 G90 G17\nG1 F1000\n"
    for _ in range(n):
        yield f"X{rnd.randint(1000, 3999000) / 1000:.3f} Y{rnd.randint(0, 299000) / 1000:.3f}\n"
    yield "M2\n"  # a program end: rs274 (bench_peers) ends without an error


def table_program(n: int, path: Path) -> None:
    with path.open("w") as fh:
        fh.writelines(table_lines(n))


def table_walk(n: int) -> str:
    """:func:`table_program`'s text (bench_peers' stepped-table class)."""
    return "".join(table_lines(n))


def inner_radius(n: int) -> float:
    """Distance from the centre to the nearest edge of the outline of ``n`` vertices."""
    pts = outline(n)
    best = math.inf
    for (ax, ay), (bx, by) in zip(pts, pts[1:] + pts[:1]):
        dx, dy = bx - ax, by - ay
        t = max(0.0, min(1.0, -(ax * dx + ay * dy) / (dx * dx + dy * dy)))
        best = min(best, math.hypot(ax + t * dx, ay + t * dy))
    return best


def polygon_lines(n: int, limit: float) -> Iterator[str]:
    """Short moves (at most 2 long) between radius 60 and ``limit``: a random walk along the outline."""
    rnd = random.Random(0)
    yield "G21 G90 G17\nG1 F1000\nX80 Y0\n"
    x, y = 80.0, 0.0
    for _ in range(n - 1):
        for _ in range(100):
            nx, ny = x + rnd.uniform(-2, 2), y + rnd.uniform(-2, 2)
            if 60 < math.hypot(nx, ny) < limit:
                break
        else:
            nx, ny = 80.0, 0.0
        x, y = nx, ny
        yield f"X{x:.3f} Y{y:.3f}\n"
    yield "M2\n"  # a program end: rs274 (bench_peers) ends without an error


def polygon_program(n: int, path: Path, limit: float) -> None:
    with path.open("w") as fh:
        fh.writelines(polygon_lines(n, limit))


def polygon_walk(n: int) -> str:
    """:func:`polygon_program`'s text 2.5 mm inside the 200-vertex outline (bench_peers' polygon class)."""
    return "".join(polygon_lines(n, inner_radius(200) - 2.5))


def case(kind: str, machine_path: str, program: str, z3_sample: int) -> None:
    with Clock() as cl:
        from nczones.machine import load_machine

        machine = load_machine(machine_path)
    result = {"load_cpu": cl.cpu, "load_wall": cl.wall}
    if kind == "load":
        emit(result)
        return
    from nczones.prover import Prover, verify

    with Clock() as c:
        r = verify(program, machine)
    stats = dict(r.stats)
    result.update(verify_cpu=c.cpu, verify_wall=c.wall, verdict=r.verdict.label,
                  segments=stats.get("segments", 0), screened=stats.get("screened", 0),
                  z3=stats.get("z3_queries", 0))
    if z3_sample:
        from nczones.gcode import interpret
        from nczones.prover.core import _chunk_rows

        segs = []
        for chunk in interpret(program, machine):
            rows = range(0, len(chunk), max(1, len(chunk) // z3_sample))
            segs += list(_chunk_rows(chunk, rows)) if chunk.scale is not None else [chunk.objects[i] for i in rows]
            if len(segs) >= z3_sample:
                break
        segs = segs[:z3_sample]
        z3 = Prover(machine, engine="z3")
        with Clock() as cz:
            for s in segs:
                z3.check(s)
        result.update(z3_sample=len(segs), z3_per_segment_cpu=cz.cpu / max(len(segs), 1))
    emit(result)


def run(me: str, args: list[str], timeout: float) -> dict | None:
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    try:
        out = subprocess.run([sys.executable, me, *args], capture_output=True, text=True, env=env, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    if out.returncode != 0:
        raise SystemExit(f"case {args} failed:\n{out.stderr}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--segments", type=int, default=100_000)
    ap.add_argument("--tables", default="16,256,4096,65536")
    ap.add_argument("--polygons", default="10,1000,100000")
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--z3-sample", type=int, default=20, help="segments sent to Z3 for the naive ratio (0: none)")
    ap.add_argument("--case", nargs=4, metavar=("KIND", "MACHINE", "PROGRAM", "SAMPLE"), help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.case:
        case(a.case[0], a.case[1], a.case[2], int(a.case[3]))
        return
    me = str(Path(__file__).resolve())
    print(f"machine: {machine_description()}")
    print(f"{a.segments:,} segments per program; CPU seconds of a fresh process per case; timeout {a.timeout:.0f} s")
    with tempfile.TemporaryDirectory() as d:
        tprog = Path(d) / "table.ngc"
        table_program(a.segments, tprog)
        cases = [(f"table, {n:,} regions", table_machine(n), tprog, n) for n in map(int, filter(None, a.tables.split(",")))]
        for n in map(int, filter(None, a.polygons.split(","))):
            # the walk comes to within 0.3 of the outline (a safe program: every segment is decided)
            pprog = Path(d) / f"polygon{n}.ngc"
            polygon_program(a.segments, pprog, inner_radius(n) - 0.3)
            cases.append((f"polygon, {n:,} vertices", polygon_machine(n), pprog, n))
        for i, (name, text, prog, size) in enumerate(cases):
            mpath = Path(d) / f"m{i}.toml"
            mpath.write_text(text)
            load = run(me, ["--case", "load", str(mpath), str(prog), "0"], a.timeout)
            if load is None:
                print(f"{name}: load stopped after {a.timeout:.0f} s; verify not run")
                continue
            sample = a.z3_sample if size <= 1000 else 0
            sample = min(sample, 2) if size > 100 else sample
            ver = run(me, ["--case", "verify", str(mpath), str(prog), str(sample)], a.timeout)
            line = f"{name}: load {load['load_cpu']:.2f} s"
            if ver is None:
                print(f"{line}; verify stopped after {a.timeout:.0f} s")
                continue
            segs = max(ver["segments"], 1)
            line += (f"; verify {ver['verify_cpu']:.2f} s ({ver['verdict']}, {ver['segments']:,} segments, "
                     f"screened {ver['screened'] / segs:.1%}, Z3 queries {ver['z3']:,})")
            if ver.get("z3_sample"):
                z3_total = ver["z3_per_segment_cpu"] * segs
                line += (f"; Z3 per segment {ver['z3_per_segment_cpu'] * 1e3:.1f} ms (sample {ver['z3_sample']}) "
                         f"-> {z3_total:,.0f} s for all: ratio {z3_total / max(ver['verify_cpu'], 1e-9):,.0f}x")
            print(line, flush=True)


if __name__ == "__main__":
    main()
