"""Where the CPU of ``nczones verify`` goes on the full-interpreter rows of bench_peers (a script, not a test).

    python bench/bench_breakdown.py [--lines 100000] [--runs 3]

For the two rows of ``bench/bench_peers.py`` that go through the language layer (an expression on
every line; the LinuxCNC o-word loop), against bench_peers' box machine, the package's bytecode
compiled first, least CPU seconds (user + system) of ``--runs`` fresh processes:

* **the double pass** (:mod:`nczones.gcode.linuxcnc.doubles`, what ``nczones verify`` runs first on these programs):
  **pass** (the program in doubles) and **boxes** (the exact proof of its enclosures), in the same process
  before the full path;
* **start** — a process that imports what a verify of such a program loads (the command line, the
  G-code layer, the prover and its column screen with numpy) and reads the machine file: CPU from the
  process's start;
* the full path (what verify runs when the double pass declines), in the same process (with the verify
  command's garbage-collector threshold), ``verify_segments`` over ``interpret(...)`` as it streams, split by timing
  wrappers into **interpret** (the time spent producing the interpreter's chunks), **columns**
  (``segment_columns``: the batches turned into integer rows), **screen** (``screen_chunk``) and
  **rest** (batching, the per-segment path, the result);
* **verify** — ``nczones verify`` end to end in its own process (the command line and the report
  included), the sum's check;
* **rs274** — LinuxCNC's interpreter on the same file, and **rs274 start** on a two-line program.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from _bench import ROOT, machine_description  # noqa: E402
from bench_peers import cpu_of  # noqa: E402

from nczones.precompiled.machines import peer_box  # noqa: E402

SPLIT = r"""
import json, sys, time
import nczones.cli, nczones.gcode, nczones.prover, nczones.prover.screen as screen
from nczones.machine import load_machine
from nczones.gcode import interpret
from nczones.prover.core import verify_segments
from nczones.commands.verify import fewer_collections
fewer_collections()  # as the verify command does
machine = load_machine(sys.argv[2])
start = time.process_time()
spent = {"interpret": 0.0, "columns": 0.0, "screen": 0.0}

def timed(name, fn):
    def run(*args):
        t = time.process_time()
        try:
            return fn(*args)
        finally:
            spent[name] += time.process_time() - t
    return run

screen.segment_columns = timed("columns", screen.segment_columns)
screen.screen_chunk = timed("screen", screen.screen_chunk)

def chunks(it):
    it = iter(it)
    step = timed("interpret", lambda: next(it, None))
    while (chunk := step()) is not None:
        yield chunk

from fractions import Fraction
from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.prover.doubles import prove_enclosures
text = open(sys.argv[1]).read()
t = time.process_time()
path = double_pass(text, machine, max_iterations=100_000)
spent["pass"] = time.process_time() - t
t = time.process_time()
assert prove_enclosures(path, machine, Fraction(0), 10**6) is not None
spent["boxes"] = time.process_time() - t
t = time.process_time()
assert verify_segments(chunks(interpret(sys.argv[1], machine)), machine).verdict.label == "safe"
spent["rest"] = time.process_time() - t - sum(spent[p] for p in ("interpret", "columns", "screen"))
spent["start"] = start
print(json.dumps(spent))
"""

PASS = ("start", "pass", "boxes")
PARTS = ("start", "interpret", "columns", "screen", "rest")


def main() -> None:
    import bench_fanuc
    import bench_gcode

    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=100_000)
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    print(f"machine: {machine_description()}")
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "nczones")], check=True,
                   stdout=subprocess.DEVNULL)
    rs274 = shutil.which("rs274")
    print(f"CPU seconds, least of {a.runs} fresh processes")
    print(f"{'':40} {'the double pass':>29}   {'the full path':>49}")
    print(f"{'program':40} " + " ".join(f"{p:>9}" for p in PASS) + f" {'sum':>6} "
          + " ".join(f"{p:>9}" for p in PARTS[1:]) + f" {'sum':>6} {'verify':>6} {'rs274':>6} {'rs274 start':>11}  load")
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        machine = d / "box.toml"
        machine.write_text(peer_box("linuxcnc"))
        tiny = d / "tiny.ngc"
        tiny.write_text("G1 X1 F100\nM2\n")
        rows = [(f"an expression on every line, {a.lines:,}", bench_gcode.expr_program(a.lines)),
                (f"LinuxCNC o-word loop, {a.lines:,} executed", bench_fanuc.linuxcnc_macro_program(a.lines))]
        for name, text in rows:
            path = d / "program.ngc"
            path.write_text(text)
            splits = []
            for _ in range(a.runs):
                out = subprocess.run([sys.executable, "-c", SPLIT, str(path), str(machine)], env=env, check=True,
                                     capture_output=True, text=True).stdout
                splits.append(json.loads(out))
            best = {p: min(s[p] for s in splits) for p in set(PARTS) | set(PASS)}
            verify = min(cpu_of([sys.executable, "-m", "nczones", "verify", str(path), "--machine", str(machine),
                                 "--format", "json"], 600, env)[0] or 0.0 for _ in range(a.runs))
            peer = [min(cpu_of([rs274, "-g", str(p), os.devnull], 600)[0] or 0.0 for _ in range(a.runs))
                    for p in (path, tiny)] if rs274 else None
            print(f"{name:40} " + " ".join(f"{best[p]:9.3f}" for p in PASS) + f" {sum(best[p] for p in PASS):6.2f} "
                  + " ".join(f"{best[p]:9.3f}" for p in PARTS[1:])
                  + f" {sum(best[p] for p in PARTS):6.2f} {verify:6.2f}"
                  + (f" {peer[0]:6.2f} {peer[1]:11.2f}" if peer else f" {'n/a':>6} {'n/a':>11}")
                  + f"  {os.getloadavg()[0]:4.1f}", flush=True)


if __name__ == "__main__":
    main()
