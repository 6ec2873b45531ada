"""Start-up benchmark (a script, not a test): the CPU seconds of ``nczones --help`` and of a 3-line verify.

    python bench/bench_startup.py [--runs 5]

Every case is a fresh ``python -m nczones ...`` process; its CPU time (user + system) comes from
``resource.getrusage(RUSAGE_CHILDREN)`` around the run, so other load on the shared machine counts less
than in wall seconds.  The figures are the least and the median of ``--runs`` runs.

Each command runs two ways in the same run:

* **lazy** (``nczones`` as it is): the command line imports only the module of the command that runs; a
  program of fewer than ``FAST_PATH_MIN_LINES`` lines is read by the full interpreter alone and its
  motions decided one by one on the exact path (no numpy), Z3 is loaded at the first query, and numpy's
  OpenBLAS is asked for one thread;
* **eager** (the naive way, as before issue 26): every subcommand's module is imported to build the parser,
  and with them the prover, the controller (numpy) and the report stages; the 3-line program goes through
  the vectorized path (fast path and column screen, numpy), and OpenBLAS starts its threads.

and under two kinds of start:

* **bytecode cached**: the modules' compiled bytecode is in a cache from an earlier run (as for an installed
  package, or a checkout after its first run);
* **no bytecode cache**: every module of nczones is compiled from source at every start (a fresh checkout,
  or an environment with ``PYTHONDONTWRITEBYTECODE``, as on the machine these figures were taken on): a
  copy of the filled cache without nczones' part, never written to; the libraries' bytecode stays cached.

The children run as from an installed wheel: a throw-away virtual environment whose ``site`` adds this
checkout and the project environment's ``site-packages`` as plain paths (a ``.pth`` file), so the editable
install's import hook (about 10 ms, which an installed wheel does not have) is not loaded; one more row
gives the lazy 3-line verify with that hook (the checkout's own ``.venv``).

It also prints what the libraries alone cost to import (numpy, Z3, Shapely, matplotlib), since they bound
what a command that needs them can reach.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MILL = ROOT / "specs" / "machines" / "mill.toml"
PROGRAM = "G90 G21\nG1 X10 Y10 F100\nM2\n"

#: ``nczones`` the eager way: the parser built from every command's module, OpenBLAS with its own threads,
#: and any program, however small, through the vectorized path.
EAGER = ("import sys\nfrom nczones import cli\nimport nczones.pipeline.verification as api, nczones.prover.core as core\n"
         "cli.chosen_command = lambda argv: None\ncli._one_blas_thread = lambda: None\n"
         "api.FAST_PATH_MIN_LINES = core.SCREEN_MIN_SEGMENTS = 0\nsys.exit(cli.main(sys.argv[1:]))")
LAZY = "from nczones import cli\ncli.run()"


def child_cpu(argv: list[str], env: dict[str, str]) -> float:
    """CPU seconds (user + system) of one child process running ``argv``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env, cwd=ROOT, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def measure(argv: list[str], env: dict[str, str], runs: int) -> tuple[float, float]:
    """The least and the median CPU seconds of ``runs`` runs."""
    times = [child_cpu(argv, env) for _ in range(runs)]
    return min(times), statistics.median(times)


#: The console script pip writes for ``[project.scripts] nczones = "nczones.cli:run"`` (what a user runs as
#: ``nczones``): no :mod:`runpy`, unlike ``python -m nczones``.
CONSOLE_SCRIPT = """#!{python}
import sys
from nczones.cli import run
if __name__ == '__main__':
    sys.argv[0] = sys.argv[0].removesuffix('.exe')
    sys.exit(run())
"""


def installed_like(tmp: Path) -> str:
    """A python that sees this checkout and the project's libraries as an installed wheel would: a fresh
    virtual environment (no pip) whose ``.pth`` file lists them as plain paths, with the ``nczones`` console
    script pip would write beside it (:func:`console_script`)."""
    import site
    import sysconfig

    venv = Path(tmp) / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    py = venv / "bin" / "python"
    purelib = subprocess.run([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                             capture_output=True, text=True, check=True).stdout.strip()
    libs = [p for p in site.getsitepackages() if Path(p).is_dir()] or [sysconfig.get_paths()["purelib"]]
    (Path(purelib) / "nczones_bench.pth").write_text("\n".join([str(ROOT), *libs]) + "\n")
    script = Path(console_script(str(py)))
    script.write_text(CONSOLE_SCRIPT.format(python=py))
    script.chmod(0o755)
    return str(py)


def console_script(python: str) -> str:
    """The ``nczones`` console script of the environment of ``python`` (made by :func:`installed_like`)."""
    return str(Path(python).parent / "nczones")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=5, help="fresh processes per case (least and median printed)")
    args = ap.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        program = Path(tmp) / "three_lines.ngc"
        program.write_text(PROGRAM)
        base = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPYCACHEPREFIX")}
        editable = dict(base, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
        base.pop("PYTHONPATH", None)
        cached = dict(base, PYTHONPYCACHEPREFIX=str(Path(tmp) / "pycache"))
        py = installed_like(Path(tmp))
        commands = {
            "nczones --help": ["--help"],
            "nczones verify (3 lines)": ["verify", str(program), "--machine", str(MILL)],
        }
        # fill the bytecode cache with everything either way imports
        for argv in commands.values():
            for code in (LAZY, EAGER):
                child_cpu([py, "-c", code, *argv], cached)
        # the same cache without nczones' bytecode, never written to: nczones is compiled at every start
        stripped = Path(tmp) / "stripped"
        shutil.copytree(Path(tmp) / "pycache", stripped)
        shutil.rmtree(stripped / (ROOT / "nczones").relative_to(ROOT.anchor))
        compiled = dict(base, PYTHONPYCACHEPREFIX=str(stripped), PYTHONDONTWRITEBYTECODE="1")
        print(f"nczones start-up: CPU seconds of a fresh process, least / median of {args.runs} runs; "
              f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
        print(f"{'command':<28} {'start':<18} {'lazy':>15} {'eager (naive)':>15} {'eager/lazy':>10}")
        for label, argv in commands.items():
            for start, env in (("bytecode cached", cached), ("no bytecode cache", compiled)):
                lazy = measure([py, "-c", LAZY, *argv], env, args.runs)
                eager = measure([py, "-c", EAGER, *argv], env, args.runs)
                print(f"{label:<28} {start:<18} {lazy[0]:>6.3f} / {lazy[1]:.3f} {eager[0]:>6.3f} / {eager[1]:.3f} "
                      f"{eager[1] / lazy[1]:>9.1f}x")
        with_hook = measure([sys.executable, "-c", LAZY, *commands["nczones verify (3 lines)"]],
                            dict(editable, PYTHONPYCACHEPREFIX=str(Path(tmp) / "pycache")), args.runs)
        print(f"{'nczones verify (3 lines)':<28} {'cached, editable':<18} {with_hook[0]:>6.3f} / {with_hook[1]:.3f}"
              "   (lazy, with the editable install's import hook: this checkout's .venv)")
        print("\nfor reference (bytecode cached):")
        for label, code in (("python -c pass", "pass"), ("import numpy", "import numpy"), ("import z3", "import z3"),
                            ("import shapely", "import shapely"),
                            ("import matplotlib.pyplot", "import matplotlib.pyplot")):
            least, median = measure([py, "-c", code], cached, args.runs)
            print(f"  {label:<26} {least:.3f} / {median:.3f}")
            if code == "import numpy":
                least, median = measure([py, "-c", code], dict(cached, OPENBLAS_NUM_THREADS="1"), args.runs)
                print(f"  {'  with one OpenBLAS thread':<26} {least:.3f} / {median:.3f}")
        print(f"load average after the run: {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
