"""The core install is what ``verify`` needs; plots, HTML and Dask are extras (issue 38).

``pip install nczones`` pulls Z3 and numpy only.  A command that needs a missing extra stops with one
line, ``PK101``, exit 2, naming the extra.  The runs below stand for a core install: a subprocess in which
importing matplotlib, Shapely, Dask or distributed fails as it does when they are not installed
(.ci/wheel-test.sh checks a real fresh install of the wheel).
"""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("matplotlib", "shapely", "dask", "distributed")

#: Runs ``nczones`` (its main) with the heavy packages unimportable, as in a core install.
CORE = f"""
import sys
for name in {HEAVY!r}:
    sys.modules[name] = None  # import raises ModuleNotFoundError(name=...), find_spec gives None: not installed
from nczones.cli import main
sys.exit(main(sys.argv[1:]))
"""


def core(*argv: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", CORE, *argv], capture_output=True, text=True, cwd=cwd,
                          env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}, timeout=120)


def test_the_core_dependencies_are_what_verify_needs():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    names = {d.split("[")[0].split(">")[0].split("=")[0].strip().lower() for d in project["dependencies"]}
    # verify needs Z3 and numpy; import-machine (a core command) writes TOML with tomli-w (pure Python, 20 kB)
    assert names == {"z3-solver", "numpy", "tomli-w"}
    extras = project["optional-dependencies"]

    def packages(extra: str) -> set[str]:
        return {d.split(">")[0].strip().lower() for d in extras[extra]}

    assert packages("plot") == {"matplotlib", "shapely"}
    # the HTML report: the plot packages, and plotly for its interactive view (plotly.js embedded in the page)
    assert packages("html") == packages("plot") | {"plotly"}
    assert packages("fleet") == {"dask[distributed]"}
    assert packages("all") == packages("html") | packages("fleet")
    assert packages("all") <= packages("test")  # make test covers every command


def test_verify_runs_without_the_extras_and_the_plot_names_its_extra(tmp_path):
    program = "specs/examples/programs/notch_dip.ngc"
    machine = "specs/machines/grinder.toml"
    run = core("verify", program, "--machine", machine)
    # The program's line 5 leaves the grinder's stepped zone (tests/cli/test_linuxcnc_filter.py derives it).
    assert run.returncode == 1 and "notch_dip.ngc: unsafe: 1 violating block" in run.stdout, run.stderr
    run = core("plot", program, "--machine", machine, "--output", str(tmp_path / "p.png"))
    assert run.returncode == 2 and run.stderr == (
        "<environment>: error[PK101]: nczones plot needs matplotlib, which is not installed: "
        "pip install 'nczones[plot]' (or 'nczones[all]')\n")
    run = core("verify", program, "--machine", machine, "--format", "html", "--output", str(tmp_path / "r.html"))
    assert run.returncode == 2 and run.stderr.count("\n") == 1 and "error[PK101]" in run.stderr
    assert "pip install 'nczones[html]'" in run.stderr and not (tmp_path / "r.html").exists()


def test_the_linuxcnc_filter_writes_the_text_report_without_the_html_extra(tmp_path):
    program = tmp_path / "notch_dip.ngc"
    program.write_bytes((ROOT / "specs/examples/programs/notch_dip.ngc").read_bytes())
    run = core("linuxcnc-filter", str(program), "--machine", str(ROOT / "specs/machines/grinder.toml"))
    assert run.returncode == 1 and run.stdout == ""
    report = tmp_path / "notch_dip.ngc.nczones.txt"
    assert f"full report: {report}" in run.stderr and "pip install 'nczones[html]'" in run.stderr
    assert "notch_dip.ngc: unsafe: 1 violating block" in report.read_text(encoding="utf-8")


def test_fleet_auto_runs_serially_without_dask():
    """1000 jobs would start a local Dask cluster ("auto"); without the [fleet] extra they run in-process."""
    script = CORE.split("from nczones.cli")[0] + (
        "from nczones.fleet.check import CheckOptions, choose_executor\n"
        "print(type(choose_executor(CheckOptions(), 1000)).__name__)\n")
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60,
                         env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    assert run.stdout.strip() == "SerialExecutor", run.stderr
