"""Corpus benchmark of the prover (a script, not a test).

    python bench/bench_corpus.py [--corpus DIR] [--timeout 60] [--only TEXT] [--save FILE] [--compare FILE]

Runs :func:`nczones.prover.verify` on every program of the external corpus
(``MANIFEST.tsv`` rows with role ``program``, and every program of the
corpus's ``fanuc/`` folder) against two machines:

* **permissive**: one allow box of +-100 m on X, Y and Z (every other axis
  free), so nearly every program is ``safe``;
* **tight**: a machine built for each program that cuts through the
  program's own bounding box: the travel box ends at the middle of the
  program's X range, and a forbid box stands in the middle of its XY
  extent, so most programs are ``unsafe`` and their witnesses are needed.

and prints, per program and machine: the verdict, wall-clock seconds, CPU
seconds and the number of solver calls; then the totals and the slowest
programs.  The machine is shared with other work, so both clocks are
printed: CPU seconds are what the run itself cost.  Each program runs in a worker process with a time limit
(``--timeout``, default 60 s: a run that takes longer is killed and shown as
``>60``), so one hang cannot stop the benchmark.  ``--save`` writes the
results as JSON and ``--compare`` prints the slowest programs of an earlier
saved run beside this one (the before/after table of
``specs/performance.md``).

The corpus is read from ``../shared/corpus`` beside the repository (or
``--corpus``); nothing of it is copied.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import os
import sys
import time
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from _bench import machine_description  # noqa: E402

DEFAULT_CORPUS = ROOT.parent.parent / "shared" / "corpus"
if not DEFAULT_CORPUS.is_dir():
    DEFAULT_CORPUS = Path("/work/shared/corpus")

_AXES = ["X", "Y", "Z", "A", "B", "C", "U", "V", "W"]


def programs(corpus: Path) -> list[tuple[str, str]]:
    """(path relative to the corpus, dialect) of every program, the ``fanuc/`` folder included."""
    out = []
    manifest = corpus / "MANIFEST.tsv"
    for row in manifest.read_text().splitlines()[1:]:
        cols = row.split("\t")
        if len(cols) > 6 and cols[4] == "program":
            out.append((cols[0], cols[6]))
    fanuc = corpus / "fanuc" / "MANIFEST.tsv"
    if fanuc.is_file():
        for row in fanuc.read_text().splitlines()[1:]:
            cols = row.split("\t")
            if cols and cols[0]:
                out.append(("fanuc/" + cols[0], "Fanuc/Haas"))
    return out


def _dec(x: Fraction) -> str:
    return f"{float(x):.3f}"


def machine_text(dialect: str, zones: str, reference: dict | None = None) -> str:
    linuxcnc = dialect.startswith("LinuxCNC")
    reference = reference or {}
    return ("[machine]\naxes = " + json.dumps(_AXES) + '\npulse = "0.0001"\n'
            + ('cutter_compensation = "linuxcnc"\n' if linuxcnc else "")
            + "[machine.rapid]\n" + "\n".join(f'{a} = "1000"' for a in _AXES) + "\n"
            + "[machine.reference]\n" + "\n".join(f'{a} = "{reference.get(a, "0")}"' for a in _AXES) + "\n"
            + "[tool_lengths]\n" + "\n".join(f'H{i} = "0"' for i in range(1, 100)) + "\n"
            + ("[tool_diameters]\n" + "\n".join(f'T{i} = "1"' for i in range(0, 100)) + "\n" if linuxcnc else "")
            + zones)


PERMISSIVE_ZONES = """
[[zones]]
name = "travel"
kind = "box"
min = { X = "-100000", Y = "-100000", Z = "-100000" }
max = { X = "100000", Y = "100000", Z = "100000" }
"""


def tight_zones(lo: dict, hi: dict) -> str:
    """An allow box that ends at the middle of the X range and a forbid box in the middle of XY."""
    w = {a: hi[a] - lo[a] for a in "XYZ"}
    x_mid = lo["X"] + w["X"] / 2
    return f"""
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "{_dec(lo['X'] - 1)}", Y = "{_dec(lo['Y'] - 1)}", Z = "{_dec(lo['Z'] - 1)}" }}
max = {{ X = "{_dec(x_mid)}", Y = "{_dec(hi['Y'] + 1)}", Z = "{_dec(hi['Z'] + 1)}" }}

[[zones]]
name = "post"
kind = "box"
forbid = true
min = {{ X = "{_dec(lo['X'] + w['X'] * Fraction(3, 10))}", Y = "{_dec(lo['Y'] + w['Y'] * Fraction(2, 5))}" }}
max = {{ X = "{_dec(lo['X'] + w['X'] * Fraction(9, 20))}", Y = "{_dec(hi['Y'] - w['Y'] * Fraction(2, 5))}" }}
"""


def bounding_box(path: Path, machine) -> tuple[dict, dict] | None:
    """The box of the program's motion on X, Y, Z (end points and arc circles), or None."""
    from nczones.gcode import interpret
    from nczones.motion import MotionChunk, SegmentKind

    lo = {a: None for a in "XYZ"}
    hi = {a: None for a in "XYZ"}

    def add(a, v):
        lo[a] = v if lo[a] is None else min(lo[a], v)
        hi[a] = v if hi[a] is None else max(hi[a], v)

    run = interpret(path, machine)
    ix = {a: machine.axis_names.index(a) for a in "XYZ"}
    for chunk in run:
        if isinstance(chunk, MotionChunk) and chunk.scale is not None and len(chunk):
            den = 10**chunk.scale
            for a, k in ix.items():
                add(a, Fraction(int(min(chunk.start[:, k].min(), chunk.end[:, k].min())), den))
                add(a, Fraction(int(max(chunk.start[:, k].max(), chunk.end[:, k].max())), den))
            continue
        for s in chunk.segments():
            for a, k in ix.items():
                add(a, s.start[k])
                add(a, s.end[k])
            if s.kind is SegmentKind.SPLINE:
                for p in dict(s.extra)["control"]:
                    for a, k in ix.items():
                        add(a, p[k])
    if lo["X"] is None:
        return None
    for a in "XYZ":
        if hi[a] - lo[a] < 2:
            lo[a], hi[a] = lo[a] - 1, hi[a] + 1
    return lo, hi


def run_one(corpus: str, rel: str, dialect: str, kind: str, budget: float | None) -> dict:
    """Verify one program on one machine; the outcome as a dict."""
    from nczones.errors import NczonesError
    from nczones.machine import parse_machine
    from nczones.prover import verify

    path = Path(corpus) / rel
    out = {"program": rel, "machine": kind}
    try:
        permissive = parse_machine(machine_text(dialect, PERMISSIVE_ZONES))
        machine = permissive
        if kind == "tight":
            box = bounding_box(path, permissive)
            if box is None:
                out.update(verdict="no motion", wall=0.0, cpu=0.0, solver_calls=0)
                return out
            lo, hi = box
            # the machine starts inside its travel box, away from the forbid box
            machine = parse_machine(machine_text(dialect, tight_zones(lo, hi),
                                                 {"X": _dec(lo["X"]), "Y": _dec(lo["Y"]), "Z": _dec(hi["Z"])}))
        extra = {}
        if budget is not None:
            extra["budget_s"] = budget
        w0, c0 = time.perf_counter(), time.process_time()
        r = verify(path, machine, **extra)
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        stats = dict(r.stats)
        out.update(verdict=r.verdict.label, wall=wall, cpu=cpu,
                   solver_calls=int(stats.get("z3_queries", 0)), segments=int(stats.get("segments", 0)),
                   violations=len(r.violations), reasons=len(r.reasons),
                   first=(r.violations[0].line if r.violations else None),
                   reason=(r.reasons[0].message[:90] if r.reasons and not r.violations else ""))
    except NczonesError as exc:
        diags = getattr(exc, "diagnostics", None)
        why = f"{diags[0].code}: {diags[0].message}" if diags else str(exc).splitlines()[0]
        out.update(verdict="rejected", wall=0.0, cpu=0.0, solver_calls=0, reason=why[:90])
    return out


def _worker(conn) -> None:
    while True:
        job = conn.recv()
        if job is None:
            return
        try:
            conn.send(run_one(*job))
        except Exception as exc:  # noqa: BLE001 - reported in the table, the benchmark goes on
            conn.send({"program": job[1], "machine": job[3], "verdict": "error", "wall": 0.0, "cpu": 0.0,
                       "solver_calls": 0, "reason": f"{type(exc).__name__}: {exc}"[:120]})


class Pool:
    """One worker process; a job that exceeds the time limit kills it (a fresh one starts)."""

    def __init__(self):
        self.ctx = mp.get_context("fork")
        self.proc = None

    def _start(self):
        self.conn, child = self.ctx.Pipe()
        self.proc = self.ctx.Process(target=_worker, args=(child,), daemon=True)
        self.proc.start()

    def run(self, job, timeout: float) -> dict:
        if self.proc is None or not self.proc.is_alive():
            self._start()
        t0 = time.perf_counter()
        self.conn.send(job)
        if self.conn.poll(timeout):
            return self.conn.recv()
        self.proc.kill()
        self.proc.join()
        self.proc = None
        return {"program": job[1], "machine": job[3], "verdict": "timeout", "wall": time.perf_counter() - t0,
                "cpu": None, "solver_calls": None, "reason": f"killed after {timeout:g} s"}

    def close(self):
        if self.proc is not None and self.proc.is_alive():
            self.conn.send(None)
            self.proc.join(5)


def _fmt_time(r: dict) -> str:
    if r["verdict"] == "timeout":
        return f">{r['wall']:.0f}"
    return f"{r['wall']:.2f}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--corpus", default=str(DEFAULT_CORPUS))
    ap.add_argument("--timeout", type=float, default=60.0, help="kill a run after this many seconds (default 60)")
    ap.add_argument("--budget", type=float, default=None,
                    help="pass verify(budget_s=...) (default: the prover's own default)")
    ap.add_argument("--only", action="append", default=[], help="run only programs whose path contains TEXT")
    ap.add_argument("--machines", default="permissive,tight")
    ap.add_argument("--save", metavar="FILE", help="write the results as JSON")
    ap.add_argument("--compare", metavar="FILE", help="a saved earlier run: print its slowest beside this run")
    ap.add_argument("--slowest", type=int, default=20)
    ap.add_argument("--quiet", action="store_true", help="no per-program lines, only totals and the slowest")
    args = ap.parse_args(argv)

    corpus = Path(args.corpus)
    if not (corpus / "MANIFEST.tsv").is_file():
        print(f"corpus not found at {corpus}", file=sys.stderr)
        return 2
    todo = [p for p in programs(corpus) if not args.only or any(t in p[0] for t in args.only)]
    kinds = [k for k in args.machines.split(",") if k]
    print(f"# {machine_description()}")
    print(f"# {len(todo)} programs x {len(kinds)} machines, time limit {args.timeout:g} s per run")
    pool = Pool()
    results = []
    t_start = time.perf_counter()
    try:
        for rel, dialect in todo:
            for kind in kinds:
                r = pool.run((str(corpus), rel, dialect, kind, args.budget), args.timeout)
                results.append(r)
                if not args.quiet:
                    calls = "-" if r.get("solver_calls") is None else r["solver_calls"]
                    cpu = "-" if r.get("cpu") is None else f"{r['cpu']:.2f}"
                    print(f"{r['verdict']:9s} {_fmt_time(r):>8s} s {cpu:>7s} cpu {calls:>6} calls  {kind:10s} {rel}"
                          + (f"  [{r['reason']}]" if r.get("reason") and r["verdict"] != "safe" else ""),
                          flush=True)
    finally:
        pool.close()
    total = time.perf_counter() - t_start
    print()
    for kind in kinds:
        rows = [r for r in results if r["machine"] == kind]
        counts: dict[str, int] = {}
        for r in rows:
            counts[r["verdict"]] = counts.get(r["verdict"], 0) + 1
        wall = sum(r["wall"] for r in rows)
        cpu = sum(r.get("cpu") or 0 for r in rows)
        calls = sum(r.get("solver_calls") or 0 for r in rows)
        over = sum(1 for r in rows if r["wall"] > 10)
        over_cpu = sum(1 for r in rows if r["verdict"] == "timeout" or (r.get("cpu") or 0) > 10)
        print(f"{kind:10s}: {len(rows)} runs, {wall:.1f} s wall, {cpu:.1f} s cpu, {calls} solver calls, "
              f"{over} over 10 s wall ({over_cpu} over 10 s cpu); "
              + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    print(f"benchmark wall time {total:.1f} s")
    slow = sorted(results, key=lambda r: -r["wall"])[: args.slowest]
    before = {}
    if args.compare:
        for r in json.loads(Path(args.compare).read_text())["results"]:
            before[(r["program"], r["machine"])] = r
    print(f"\n{args.slowest} slowest runs" + (" (before: " + args.compare + ")" if before else ""))
    for r in slow:
        b = before.get((r["program"], r["machine"]))
        prev = f"{_fmt_time(b):>8s} s {b['verdict']:8s} -> " if b else ""
        cpu = "-" if r.get("cpu") is None else f"{r['cpu']:.2f}"
        print(f"  {prev}{_fmt_time(r):>8s} s {cpu:>6s} cpu {r['verdict']:8s} {r.get('solver_calls') or 0:>6} calls  "
              f"{r['machine']:10s} {r['program']}")
    if before:
        prev_slow = sorted(before.values(), key=lambda r: -r["wall"])[: args.slowest]
        now = {(r["program"], r["machine"]): r for r in results}
        print(f"\nthe {args.slowest} slowest of the earlier run, now")
        for b in prev_slow:
            r = now.get((b["program"], b["machine"]))
            cur = f"{_fmt_time(r):>8s} s {r['verdict']:8s}" if r else "not run"
            print(f"  {_fmt_time(b):>8s} s {b['verdict']:8s} -> {cur}  {b['machine']:10s} {b['program']}")
    if args.save:
        Path(args.save).write_text(json.dumps({"machine": machine_description(), "timeout": args.timeout,
                                               "results": results}, indent=1))
    return 0


if __name__ == "__main__":
    os.environ.setdefault("PYTHONHASHSEED", "0")
    sys.exit(main())
