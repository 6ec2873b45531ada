"""nczones beside a peer interpreter (a script, not a test): CPU seconds on the same files, in one run.

    python bench/bench_peers.py [--lines 1000000] [--small 100000] [--corpus 10] [--macro 100000]
                                [--timeout 300] [--skip-large] [--repeat 3] [--only TEXT]
    python bench/bench_peers.py --scaling [--sizes 10000,1000000,5000000] [--ten-million] [--repeat 1] [--only TEXT]

``--scaling`` prints, instead, ``nczones verify`` of each class (CAM G1, an expression on every line, R-format
arcs in both dialects, the LinuxCNC o-word loop and the Fanuc WHILE, G65 and M98 loops; ``--only TEXT`` picks
some) at each size: CPU, the child's peak RSS and the marginal µs/line between consecutive sizes, then the
marginal µs/line of every size step per class (issue 36: no size cliff).

Columns, every one the CPU seconds of its own process (user + system of the
child, so start-up counts the same way for every tool), the least of ``--repeat`` rounds (default 3: other
load on a shared machine only ever adds time).  Each round runs a row's commands once each, in turn (regex
pass, rs274, interpret, verify), so that a change of load between minutes falls on every column of the row
alike; a row's ratios compare runs made within the same seconds:

* **regex pass** — Python reads the file and splits every line into words
  with one regular expression: the floor of "reading G-code";
* **rs274** — LinuxCNC's C++ interpreter alone (``rs274 -g FILE /dev/null``: batch mode, its canonical
  calls written to ``/dev/null``; Debian package ``linuxcnc-uspace``, no INI file or tool table needed),
  skipped with a note when it is not installed; its exit status is printed beside it (``rs274 exit``),
  since a program it refuses stops early;
* **nczones interpret** — ``nczones.gcode.interpret`` over the whole program
  (text to motion, no proof);
* **nczones verify** — the command line ``nczones verify`` end to end
  (start-up, machine, interpretation, proof), against a large box; **verify MiB** is that process's
  peak resident memory (``wait4``'s ``ru_maxrss`` of that child alone).

The package's bytecode is compiled once before any timing (an installed package has it; without it,
every process compiles the modules again where ``PYTHONDONTWRITEBYTECODE`` is set).

The verify column is what a user sees from the second run on: the parsed machine file comes from its cache
(``nczones/machine_cache.py``), kept in a folder of this run (``NCZONES_CACHE_DIR``, never the user's), warmed
before any timing.  The first run's figure (cache cold: ``tomllib`` imported and the file parsed) is printed
once, beside the warm one, for a 3-line program on each dialect's box.

``--as-installed`` runs the nczones children as from an installed wheel (``bench_startup.installed_like``: a
throw-away virtual environment whose ``.pth`` names this checkout and the project's libraries as plain
paths), without the editable install's import hook and ``.pth`` files that a development environment's
``site`` loads at every start (about 14 ms of CPU per process on the machine of specs/performance.md); the
verify column then runs the ``nczones`` console script pip writes (``bench_startup.CONSOLE_SCRIPT``, what a
user types), not ``python -m nczones`` (whose :mod:`runpy` a user does not run).

Ratios are taken within the same run: ``verify / rs274`` where rs274 ran,
and ``verify / regex`` always.  Programs: generated G1 lines (``--lines`` and
``--small``), an expression on every line (``--small``), R-format arcs (``--small`` lines of
``G2``/``G3 X.. Y.. R..``, ``bench_gcode.rarc_program``; LinuxCNC, and Fanuc without an rs274 column), I/J arcs
(``--small`` lines, ``bench_gcode.ijarc_program``), stellabee1.ngc with
``--arc-tolerance linuxcnc``, the corpus's ``--corpus`` largest LinuxCNC
programs, and generated Fanuc Custom Macro B loops (a WHILE loop, a G65 call per iteration, an M98 call
per iteration; rs274's column, marked ``*``, is rs274 on the LinuxCNC equivalent: the o-word loop, a sub called
with three arguments, a sub called without) and LinuxCNC o-word loops of about ``--macro`` executed lines, and
issue 36's two zone rows of ``--small`` lines (``bench_zones.py``'s machines and programs): short moves 2.5 mm
inside a 200-vertex outline (an allowed polygon zone), and moves across a 4,096-region stepped table, each
verified against its own machine file instead of the box.
Interpretation and verify
run with a loop bound above any row's iterations (``--max-iterations``), so a row of a million lines is
interpreted to its end rather than stopped as ``unknown`` at the default bound of 100,000 iterations.
"""

from __future__ import annotations

import argparse
import csv
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from _bench import ROOT, STELLABEE, machine_description  # noqa: E402

from nczones.precompiled.machines import peer_box  # noqa: E402

CORPUS = Path("/work/shared/corpus")

REGEX_PASS = r"""
import re, sys
word = re.compile(rb"([A-Za-z#])\s*([-+]?[0-9.]+|\[[^\]]*\])")
n = 0
with open(sys.argv[1], "rb") as fh:
    for line in fh:
        n += len(word.findall(line))
print(n)
"""


#: The LinuxCNC equivalent rs274 runs for a Fanuc row (its file -> the equivalent's file), set by :func:`programs`.
PEER_OF: dict[Path, Path] = {}

#: The machine file of a row that is not checked against its dialect's box (the zone rows), set by :func:`programs`.
MACHINE_OF: dict[Path, Path] = {}

#: Runs of each command per row; the least CPU time is printed (``--repeat``).
REPEAT = [1]


#: Peak resident memory (MiB) of the last command :func:`cpu_of` measured (its least-CPU run), None if stopped.
LAST_RSS: list[float | None] = [None]


def _run_once(cmd: list[str], timeout: float, env: dict | None) -> tuple[float, int, float] | None:
    """(CPU seconds, exit status, peak RSS MiB) of one child process running ``cmd``, measured for that child alone
    (:func:`os.wait4`); None when it ran past ``timeout`` seconds and was killed."""
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    timer = threading.Timer(timeout, proc.kill)
    timer.start()
    try:
        _pid, status, usage = os.wait4(proc.pid, 0)
    finally:
        timer.cancel()
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode == -signal.SIGKILL:
        return None
    return usage.ru_utime + usage.ru_stime, proc.returncode, usage.ru_maxrss / 1024


def _least(runs: list[tuple[float, int, float]]) -> tuple[float, int, float]:
    """The least-CPU run among the runs with the most common exit status.  A run that exits with another status
    than most runs is not a measurement of the same work (an rs274 that stopped early once took 0.017 s for a
    100,000-line file)."""
    statuses = [c for _cpu, c, _rss in runs]
    common = max(statuses, key=statuses.count)
    return min(r for r in runs if r[1] == common)


def cpu_rounds(cmds: dict[str, tuple[list[str], dict | None]], timeout: float
               ) -> dict[str, tuple[float | None, int | None, float | None]]:
    """(CPU seconds, exit status, peak RSS MiB) of each named command, the least of :data:`REPEAT` rounds; every
    round runs each command once, in turn, so that a change of the machine's load between minutes falls on all
    of them alike and the ratios taken within a row compare runs made in the same seconds.  A command that ran
    past ``timeout`` is not run again and gives ``(None, None, None)``."""
    runs: dict[str, list[tuple[float, int, float]]] = {name: [] for name in cmds}
    stopped: set[str] = set()
    for _ in range(REPEAT[0]):
        for name, (cmd, env) in cmds.items():
            if name in stopped:
                continue
            run = _run_once(cmd, timeout, env)
            if run is None:
                stopped.add(name)
            else:
                runs[name].append(run)
    return {name: (None, None, None) if name in stopped else _least(runs[name]) for name in cmds}


def cpu_of(cmd: list[str], timeout: float, env: dict | None = None) -> tuple[float | None, int | None]:
    """CPU seconds (user + system) of a child process and its exit status, the least of :data:`REPEAT` runs
    (a run that times out is not repeated); None on timeout.  Only the runs with the most common exit status
    count (:func:`_least`).  The peak resident memory of that child alone (``wait4``'s ``ru_maxrss``, not the
    largest of all children) is left in :data:`LAST_RSS`."""
    cpu, code, LAST_RSS[0] = cpu_rounds({"cmd": (cmd, env)}, timeout)["cmd"]
    return cpu, code


INTERPRET = r"""
import sys, time
from nczones.gcode import interpret
from nczones.machine import load_machine
m = load_machine(sys.argv[2])
options = {"arc_tolerance": sys.argv[3]} if sys.argv[3] else {}
options["max_loop_iterations"] = 10**9  # the loop rows run past the default bound (as verify's below)
n = 0
for chunk in interpret(sys.argv[1], m, **options):
    n += len(chunk)
print(n)
"""


def programs(a, d: Path) -> list[tuple[str, Path, str, str]]:
    """(name, file, dialect, arc tolerance) of every row; :data:`PEER_OF` gets the LinuxCNC equivalent rs274
    runs for a Fanuc row that has one."""
    import bench_fanuc
    import bench_gcode
    import bench_zones

    out = []

    def gen(name: str, text: str, dialect: str = "linuxcnc", tol: str = "", peer: str = "") -> None:
        p = d / f"program{len(out)}.ngc"  # one file per row (names alone would collide)
        p.write_text(text)
        out.append((name, p, dialect, tol))
        if peer:
            q = d / f"peer{len(out)}.ngc"
            q.write_text(peer)
            PEER_OF[p] = q

    if not a.skip_large:
        gen(f"G1, {a.lines:,} lines", bench_gcode.cam_program(a.lines))
    gen(f"G1, {a.small:,} lines", bench_gcode.cam_program(a.small))
    gen(f"an expression on every line, {a.small:,}", bench_gcode.expr_program(a.small))
    gen(f"R-format arcs, {a.small:,} lines", bench_gcode.rarc_program(a.small))
    gen(f"I/J arcs, {a.small:,} lines", bench_gcode.ijarc_program(a.small))
    gen(f"R-format arcs, Fanuc, {a.small:,} lines", bench_gcode.rarc_program(a.small, dialect="fanuc"), "fanuc",
        peer=bench_gcode.rarc_program(a.small))  # the same arcs in LinuxCNC's words
    if STELLABEE.is_file():
        out.append(("stellabee1.ngc --arc-tolerance linuxcnc", STELLABEE, "linuxcnc", "linuxcnc"))
    manifest = CORPUS / "MANIFEST.tsv"
    if manifest.is_file() and a.corpus:
        with manifest.open() as fh:
            rows = [r for r in csv.DictReader(fh, delimiter="\t")
                    if r["role"] == "program" and "LinuxCNC" in r["dialect"] and (CORPUS / r["path"]).is_file()]
        rows.sort(key=lambda r: -int(r["size"]))
        for r in rows[: a.corpus]:
            if STELLABEE.is_file() and (CORPUS / r["path"]).resolve() == STELLABEE.resolve():
                continue
            out.append((f"corpus {Path(r['path']).name}", CORPUS / r["path"], "linuxcnc", ""))
    # rs274 runs the LinuxCNC equivalent of each Fanuc loop row (the o-word loop, a sub called with or without
    # arguments) and of the Fanuc hole list (the same holes in LinuxCNC's words): its column is marked with '*'
    gen(f"Fanuc Macro B loop, {a.macro:,} executed lines", bench_fanuc.macro_program(a.macro), "fanuc",
        peer=bench_fanuc.linuxcnc_macro_program(a.macro))
    gen(f"Fanuc G65 call per iteration, {a.macro:,} lines", bench_fanuc.call_program(a.macro), "fanuc",
        peer=bench_fanuc.linuxcnc_call_program(a.macro))
    gen(f"Fanuc M98 call per iteration, {a.macro:,} lines", bench_fanuc.subprogram_program(a.macro), "fanuc",
        peer=bench_fanuc.linuxcnc_subprogram_program(a.macro))
    gen(f"LinuxCNC o-word loop, {a.macro:,} executed lines", bench_fanuc.linuxcnc_macro_program(a.macro))
    gen(f"Fanuc G81 hole list, {a.small:,} holes", bench_fanuc.holes_program(a.small), "fanuc",
        peer=bench_fanuc.holes_program(a.small, dialect="linuxcnc"))
    # issue 36's zone rows (bench/bench_zones.py's machines and programs): short moves 2.5 mm inside a digitised
    # outline, and moves across a grinder's stepped table
    zone_rows = (
        ("200-vertex polygon zone", bench_zones.polygon_machine(200),
         lambda p: bench_zones.polygon_program(a.small, p, bench_zones.inner_radius(200) - 2.5)),
        ("4,096-region stepped table", bench_zones.table_machine(4096), lambda p: bench_zones.table_program(a.small, p)),
    )
    for name, machine, write in zone_rows:
        p = d / f"program{len(out)}.ngc"
        write(p)
        MACHINE_OF[p] = m = d / f"machine{len(out)}.toml"
        m.write_text(machine)
        out.append((f"{name}, {a.small:,} lines", p, "linuxcnc", ""))
    return out


def fmt(v: float | None) -> str:
    return "stopped" if v is None else f"{v:.2f}"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=1_000_000)
    ap.add_argument("--small", type=int, default=100_000)
    ap.add_argument("--corpus", type=int, default=10)
    ap.add_argument("--macro", type=int, default=100_000)
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--skip-large", action="store_true", help="leave out the --lines program")
    ap.add_argument("--only", help="only the rows whose name holds this text (e.g. 'R-format')")
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs of every command per row; the least CPU time is printed (the machine is shared)")
    ap.add_argument("--as-installed", action="store_true",
                    help="run nczones as from an installed wheel (no editable install's import hook)")
    a = ap.parse_args()
    REPEAT[0] = max(1, a.repeat)
    print(f"machine: {machine_description()}")
    rs274 = shutil.which("rs274")
    if rs274 is None:
        print("rs274: not installed (Debian package linuxcnc-uspace); its column is skipped")
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    # an installed package has its bytecode (pip compiles it); where PYTHONDONTWRITEBYTECODE is set, every
    # process would compile the modules again, which no user pays: compile them once, before any timing
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "nczones")], check=True,
                   stdout=subprocess.DEVNULL)
    print("bytecode of nczones compiled before timing (as an installed package has it)")
    python = sys.executable
    scratch = tempfile.TemporaryDirectory()
    if a.as_installed:
        from bench_startup import console_script, installed_like

        python = installed_like(Path(scratch.name))
        nczones = [console_script(python)]
        env.pop("PYTHONPATH", None)
        print("nczones runs as from an installed wheel (a virtual environment without the editable install's hook, "
              "its console script)")
    else:
        nczones = [python, "-m", "nczones"]
    env[CACHE_ENV] = str(Path(scratch.name) / "cache")
    print(f"machine-file cache: {env[CACHE_ENV]} (warmed before timing; verify is a second run)")
    machines = start_up(nczones, env, Path(scratch.name))
    print(f"CPU seconds per process, the least of {REPEAT[0]} round(s), a row's commands interleaved in each round; "
          "ratio = nczones verify / peer, measured in this run")
    print(f"{'program':58} {'regex':>7} {'rs274':>7} {'interp':>7} {'verify':>7}  exit  rs274 exit  verify/rs274"
          "  verify/regex  verify MiB  load")
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        for name, path, dialect, tol in programs(a, d):
            if a.only and a.only not in name:
                continue
            machine = MACHINE_OF.get(path, machines[dialect])
            if path in MACHINE_OF:  # its parsed machine file cached too: verify is a user's second run
                _run_once([*nczones, "verify", str(machines["three-linuxcnc"]), "--machine", str(machine)], 60, env)
            peer_path = path if dialect == "linuxcnc" else PEER_OF.get(path)
            # --max-iterations: a loop row of more than 100,000 iterations is interpreted to its end (the default
            # bound would stop it early as unknown)
            cmd = [*nczones, "verify", str(path), "--machine", str(machine), "--format", "json",
                   "--max-iterations", "1000000000"]
            if tol:
                cmd += ["--arc-tolerance", tol]
            cmds = {"regex": ([sys.executable, "-c", REGEX_PASS, str(path)], None)}
            if rs274 is not None and peer_path is not None:
                cmds["rs274"] = ([rs274, "-g", str(peer_path), os.devnull], None)
            cmds["interp"] = ([python, "-c", INTERPRET, str(path), str(machine), tol], env)
            cmds["verify"] = (cmd, env)
            got = cpu_rounds(cmds, a.timeout)
            regex = got["regex"][0]
            peer, peer_code, _ = got.get("rs274", (None, None, None))
            interp = got["interp"][0]
            verify, code, rss = got["verify"]
            r_peer = "" if peer is None or verify is None else f"{verify / peer:.2f}"
            r_regex = "" if regex is None or verify is None else f"{verify / regex:.2f}"
            shown = 'n/a' if not rs274 or peer_path is None else fmt(peer) + ('*' if peer_path != path else '')
            print(f"{name[:58]:58} {fmt(regex):>7} {shown:>7} {fmt(interp):>7} "
                  f"{fmt(verify):>7}  {code if code is not None else '-':>4}  "
                  f"{peer_code if peer_code is not None else '-':>10}  {r_peer:>12}  {r_regex:>12}  "
                  f"{'' if rss is None else f'{rss:.0f}':>10}  {os.getloadavg()[0]:4.1f}", flush=True)


#: Where the nczones children keep the parsed machine files (nczones/machine_cache.py).
CACHE_ENV = "NCZONES_CACHE_DIR"


def start_up(nczones: list[str], env: dict, d: Path) -> dict[str, Path]:
    """Write each dialect's box, warm the machine-file cache of ``env`` with it, and print a 3-line verify's CPU
    with the cache cold (a fresh, empty folder at every run: a user's first run) and warm (every later run).
    Returns the boxes, by dialect, and the 3-line programs (``three-`` and the dialect)."""
    machines = {}
    for dialect, text in (("linuxcnc", "G0 X1 Y1\nG1 X2 F100\nM30\n"), ("fanuc", "G0 X1. Y1.\nG1 X2. F100.\nM30\n")):
        machines[dialect] = machine = d / f"box-{dialect}.toml"
        machine.write_text(peer_box(dialect))
        machines[f"three-{dialect}"] = program = d / f"three-{dialect}.nc"
        program.write_text(text)
        cmd = [*nczones, "verify", str(program), "--machine", str(machine), "--format", "json"]
        _run_once(cmd, 60, env)  # warms the cache
        cold = []
        for i in range(REPEAT[0]):
            run = _run_once(cmd, 60, dict(env, **{CACHE_ENV: str(d / f"cold-{dialect}-{i}")}))
            cold.append(run[0] if run else float("nan"))
        warm = cpu_rounds({"warm": (cmd, env)}, 60)["warm"][0]
        print(f"3-line verify, {dialect}: machine-file cache cold {min(cold):.4f} s (first run), "
              f"warm {warm or float('nan'):.4f} s (every later run: the rows below)")
    return machines


def cpu_rss_of(cmd: list[str], env: dict | None = None) -> tuple[float, int, int]:
    """CPU seconds (user + system), peak RSS in MB and exit status of one child process, measured for that
    child alone (:func:`os.wait4`), not for all children together."""
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    _pid, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss // 1024, proc.returncode


#: The classes ``--scaling`` measures: (name, module, generator call with ``{n}``, dialect).  Each generator
#: writes about ``n`` lines, or about ``n`` executed lines for the loops (their iterations are bounded by
#: ``--max-iterations`` above any size).  Each runs against its dialect's box, or the machine of
#: :data:`SCALING_MACHINES` (issue 36's zone rows).
SCALING_CLASSES = (
    ("CAM G1", "bench_gcode", "cam_program({n})", "linuxcnc"),
    ("expression every line", "bench_gcode", "expr_program({n})", "linuxcnc"),
    ("R-format arcs", "bench_gcode", "rarc_program({n})", "linuxcnc"),
    ("R-format arcs, Fanuc", "bench_gcode", "rarc_program({n}, dialect='fanuc')", "fanuc"),
    ("I/J arcs", "bench_gcode", "ijarc_program({n})", "linuxcnc"),
    ("I/J arcs, Fanuc", "bench_gcode", "ijarc_program({n}, dialect='fanuc')", "fanuc"),
    ("Fanuc CAM G1", "bench_fanuc", "cam_program({n})", "fanuc"),
    ("o-word subs, no #", "bench_gcode", "osub_program({n})", "linuxcnc"),
    ("# declined by the pass", "bench_gcode", "declined_program({n})", "linuxcnc"),
    ("o-word loop", "bench_fanuc", "linuxcnc_macro_program({n})", "linuxcnc"),
    ("Macro B WHILE loop", "bench_fanuc", "macro_program({n})", "fanuc"),
    ("Fanuc G65 call loop", "bench_fanuc", "call_program({n})", "fanuc"),
    ("Fanuc M98 call loop", "bench_fanuc", "subprogram_program({n})", "fanuc"),
    ("Fanuc G81 hole list", "bench_fanuc", "holes_program({n})", "fanuc"),
    ("200-vertex polygon zone", "bench_zones", "polygon_walk({n})", "linuxcnc"),
    ("4,096-region table", "bench_zones", "table_walk({n})", "linuxcnc"),
)

#: The machine file text of a class that is not checked against its dialect's box, by class name.
SCALING_MACHINES = {
    "200-vertex polygon zone": lambda: __import__("bench_zones").polygon_machine(200),
    "4,096-region table": lambda: __import__("bench_zones").table_machine(4096),
}


def scaling(sizes: list[int], repeat: int, env: dict, only: str = "") -> None:
    """``nczones verify`` of every class of :data:`SCALING_CLASSES` (``only``: those whose name holds it) at
    each size: CPU, peak RSS and the marginal CPU per line between consecutive sizes (flat cost per line: the
    marginal cost stays the same from 10k to 10M lines), then a summary of the marginal costs per class."""
    print(f"\nscaling: nczones verify, least CPU of {repeat} run(s); peak RSS of that child; marginal = "
          "(CPU - CPU of the size before) / (lines - lines before)")
    print(f"{'class':24} {'lines':>11} {'CPU s':>8} {'RSS MB':>7} {'µs/line':>8} {'marginal µs/line':>17}  exit")
    summary: list[tuple[str, list[str]]] = []
    iterations = str(max(sizes) + 100)
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        for name, module, call, dialect in SCALING_CLASSES:
            if only and only.lower() not in name.lower():
                continue
            machine = d / f"machine_{len(summary)}.toml"
            zones = SCALING_MACHINES.get(name)
            # a box the 10M-line CAM walk stays in (the default box is left after about 4M lines)
            machine.write_text(zones() if zones else peer_box(dialect, "900000"))
            warm = d / "warm.nc"  # the machine file's cache entry: every size is a user's second run
            warm.write_text("G0 X1. Y1.\nM30\n")
            subprocess.run([sys.executable, "-m", "nczones", "verify", str(warm), "--machine", str(machine)], env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
            before = None
            marginals: list[str] = []
            for n in sizes:
                path = d / "program.ngc"
                # written by a child: a parent grown by the text would pass its peak RSS on to the forked child
                subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {str(Path(__file__).parent)!r}); "
                                f"import {module}; open({str(path)!r}, 'w').write({module}.{call.format(n=n)})"],
                               check=True)
                cmd = [sys.executable, "-m", "nczones", "verify", str(path), "--machine", str(machine),
                       "--format", "json", "--max-iterations", iterations, "--budget", "3600"]
                runs = [cpu_rss_of(cmd, env) for _ in range(repeat)]
                cpu = min(r[0] for r in runs)
                rss = max(r[1] for r in runs)
                code = runs[0][2]
                marginal = "" if before is None else f"{(cpu - before[1]) / (n - before[0]) * 1e6:.2f}"
                if marginal:
                    marginals.append(f"{before[0]:,}→{n:,}: {marginal}")
                print(f"{name:24} {n:>11,} {cpu:>8.2f} {rss:>7} {cpu / n * 1e6:>8.2f} {marginal:>17}  {code:>4}",
                      flush=True)
                before = (n, cpu)
                path.unlink()
            summary.append((name, marginals))
    print("\nmarginal µs/line per size step (flat cost per line: the steps agree):")
    for name, marginals in summary:
        print(f"  {name:24} {'; '.join(marginals)}")


if __name__ == "__main__":
    if "--scaling" in sys.argv:
        ap = argparse.ArgumentParser(description="nczones verify at growing sizes (CPU, peak RSS, marginal µs/line)")
        ap.add_argument("--scaling", action="store_true")
        ap.add_argument("--sizes", default="10000,1000000,5000000", help="comma-separated line counts")
        ap.add_argument("--ten-million", action="store_true", help="add a 10,000,000-line row per class")
        ap.add_argument("--repeat", type=int, default=1)
        ap.add_argument("--only", default="", help="only the classes whose name holds this text")
        a = ap.parse_args()
        sizes = [int(v) for v in a.sizes.split(",")] + ([10_000_000] if a.ten_million else [])
        env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
        env[CACHE_ENV] = tempfile.mkdtemp(prefix="nczones-cache-")  # not the user's; left in the temp folder
        print(f"machine: {machine_description()}")
        subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "nczones")], check=True,
                       stdout=subprocess.DEVNULL)
        scaling(sorted(sizes), max(1, a.repeat), env, a.only)
    else:
        main()
