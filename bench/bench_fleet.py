"""Fleet benchmark (a script, not a test).

    python bench/bench_fleet.py [--programs 30] [--machines 34] [--moves 30] [--workers N]
                                [--long-lines 5000000] [--skip-long]

Prints, on a generated library (``nczones.fleet.generate.write_library``:
mill pocket programs on mill variants whose vise moves, mixed verdicts):

1. jobs/s for every job verified serially in this process (the naive way:
   one verification after the other) and on a Dask ``LocalCluster`` with
   one worker process per core (cluster start-up shown on its own), the
   speed-up, and whether both stores hold the same verdicts;
2. the re-run after one machine file changes: how many jobs ran, their own
   verification time, and the overhead on top (planning, hashing, the store;
   target: below 1 s), and a re-run with nothing changed;
3. one long safe CAM program (``--long-lines``, default 5,000,000) verified
   whole in one process versus split over two workers of a local cluster
   (the split's scan and the chunks' transfer included).

The per-job cost measured in (1) is what the estimate in ``specs/fleet.md``
extrapolates from.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from _bench import Clock, machine_description  # noqa: E402

from nczones.fleet.check import CheckOptions, run_check  # noqa: E402
from nczones.fleet.execute import local_cluster  # noqa: E402
from nczones.fleet.generate import long_mill_program, mill_variant, write_library  # noqa: E402
from nczones.fleet.project import load_project  # noqa: E402
from nczones.fleet.store import Store  # noqa: E402


def _cells(store: Store) -> dict:
    run = store.latest_run()
    assert run is not None
    return {(c.program, c.machine): (c.job_key, c.verdict) for c in store.cells(run.run_id)}


def _job_seconds(store: Store, run_id: int) -> float:
    row = store.db.execute("SELECT COALESCE(SUM(r.wall_s), 0) FROM results r WHERE r.job_key IN "
                           "(SELECT job_key FROM cells WHERE run_id = ? AND status = 'ran')", (run_id,)).fetchone()
    return float(row[0])


def bench_library(args: argparse.Namespace, tmp: Path) -> None:
    project_file = write_library(tmp / "lib", programs=args.programs, machines=args.machines, moves=args.moves)
    project = load_project(project_file)
    jobs = len(project.cells())
    print(f"library: {args.programs} programs x {args.machines} machines = {jobs} jobs "
          f"({args.moves} moves per program)")

    with Store(tmp / "serial.sqlite") as store, Clock() as serial:
        s = run_check(project, store, CheckOptions(executor="serial", progress=False))
        serial_cells = _cells(store)
        per_job = _job_seconds(store, s.run_id) / max(s.ran, 1)
    verdicts = {}
    for _, v in serial_cells.values():
        verdicts[v] = verdicts.get(v, 0) + 1
    print(f"serial (one process, the naive way): {s.ran} jobs in {serial.wall:.2f} s wall, {serial.cpu:.2f} s CPU: "
          f"{s.ran / serial.wall:.1f} jobs/s; {per_job * 1000:.1f} ms per job; verdicts {verdicts}")

    started = {}

    def make(options: CheckOptions, n: int):
        t0 = time.perf_counter()
        executor = local_cluster(args.workers)
        executor.client.wait_for_workers(args.workers or os.cpu_count() or 1)
        started["s"] = time.perf_counter() - t0
        started["name"] = executor.name
        return executor

    with Store(tmp / "cluster.sqlite") as store, Clock() as cluster:
        c = run_check(project, store, CheckOptions(executor="local", workers=args.workers, progress=False),
                      make_executor=make)
        cluster_cells = _cells(store)
    net = cluster.wall - started["s"]
    print(f"{started['name']}: {c.ran} jobs in {cluster.wall:.2f} s wall ({started['s']:.2f} s of it starting the "
          f"cluster): {c.ran / cluster.wall:.1f} jobs/s, {c.ran / net:.1f} jobs/s without the start-up")
    print(f"speed-up over serial: {serial.wall / cluster.wall:.2f}x ({serial.wall / net:.2f}x without the start-up); "
          f"same verdicts and keys as serial: {cluster_cells == serial_cells}")

    # one machine file changes: only its jobs run again (in this process: fewer than 50 jobs)
    (tmp / "lib" / "machines" / "mill_005.toml").write_text(mill_variant(40), encoding="utf-8")
    with Store(tmp / "serial.sqlite") as store, Clock() as rerun:
        r = run_check(project, store, CheckOptions(progress=False))
        own = _job_seconds(store, r.run_id)
    print(f"re-run after one machine file changed: {r.ran} jobs ran, {r.reused} reused, {rerun.wall:.2f} s wall; "
          f"the jobs themselves {own:.2f} s; overhead {rerun.wall - own:.2f} s (target < 1 s; executor "
          f"{r.executor})")
    with Store(tmp / "serial.sqlite") as store, Clock() as nothing:
        n = run_check(project, store, CheckOptions(progress=False))
    print(f"re-run with nothing changed: {n.ran} jobs ran, {n.reused} reused, {nothing.wall:.2f} s wall")


def bench_long(args: argparse.Namespace, tmp: Path) -> None:
    from nczones import load_machine
    from nczones.prover import verify

    root = tmp / "long"
    root.mkdir()
    (root / "part.ngc").write_text(long_mill_program(args.long_lines), encoding="utf-8")
    mill = Path(__file__).resolve().parents[1] / "specs" / "machines" / "mill.toml"
    (root / "nczones.toml").write_text(f'[machines.mill]\nfile = "{mill}"\nprograms = ["part.ngc"]\n',
                                       encoding="utf-8")
    machine = load_machine(mill)
    with Clock() as whole:
        result = verify(root / "part.ngc", machine)
    print(f"long program, {args.long_lines:,} lines, one process: {result.verdict.label} in {whole.wall:.2f} s wall, "
          f"{whole.cpu:.2f} s CPU ({args.long_lines / whole.wall:,.0f} lines/s)")
    project = load_project(root)
    started = {}

    def make(options: CheckOptions, n: int):
        t0 = time.perf_counter()
        executor = local_cluster(2)
        executor.client.wait_for_workers(2)
        started["s"] = time.perf_counter() - t0
        return executor

    with Store(root / "split.sqlite") as store, Clock() as split:
        s = run_check(project, store, CheckOptions(executor="local", workers=2, split_lines=args.long_lines // 2,
                                                   progress=False), make_executor=make)
        verdict = _cells(store)[("part.ngc", "mill")][1]
    net = split.wall - started["s"]
    print(f"long program split over two workers: {verdict} ({s.split} job split, {s.fallbacks} fallbacks) in "
          f"{split.wall:.2f} s wall, {net:.2f} s without starting the cluster ({started['s']:.2f} s): "
          f"{whole.wall / net:.2f}x the one-process speed")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--programs", type=int, default=30, help="programs in the generated library")
    ap.add_argument("--machines", type=int, default=34, help="machines in the generated library")
    ap.add_argument("--moves", type=int, default=30, help="moves per generated program")
    ap.add_argument("--workers", type=int, default=None, help="local cluster workers (default: one per core)")
    ap.add_argument("--long-lines", type=int, default=5_000_000, help="lines of the program split over two workers")
    ap.add_argument("--skip-long", action="store_true", help="leave out the long program")
    ap.add_argument("--only-long", action="store_true", help="only the long program")
    args = ap.parse_args()
    print(machine_description())
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        if not args.only_long:
            bench_library(args, tmp)
        if not args.skip_long:
            bench_long(args, tmp)


if __name__ == "__main__":
    main()
