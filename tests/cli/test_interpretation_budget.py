"""``simulate`` and ``plot`` bound the interpretation by ``--budget`` too (issue 33, class 7: no run is unbounded).

Two nested loops of 90,000 iterations each are within ``--max-iterations`` per entry; 8.1e9 iterations would run
for days.  ``verify`` ended them within its budget; ``simulate`` and ``plot --no-verify`` ran them with no bound.
Both now take ``--budget`` (default 60 s, as ``verify``): the repetition that finds it spent ends the
interpretation (VF203).  The runs are subprocesses with a timeout, so the test itself is bounded without the fix.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
MACHINES = ROOT / "specs" / "machines"

LOOPS = {
    "fanuc": ("fanuc_mill.toml", "O1\nG90 G54 G0 X10. Y10. Z10.\n#1 = 0\nWHILE [#1 LT 90000] DO1\n#2 = 0\n"
              "WHILE [#2 LT 90000] DO2\n#2 = #2 + 1\nEND2\n#1 = #1 + 1\nEND1\nM30\n"),
    "linuxcnc": ("mill.toml", "G21 G90 G54 G0 X10 Y10 Z10\n#1 = 0\no1 while [#1 LT 90000]\n#2 = 0\n"
                 "o2 while [#2 LT 90000]\n#2 = [#2 + 1]\no2 endwhile\n#1 = [#1 + 1]\no1 endwhile\nM2\n"),
}


def _run(*argv: str) -> tuple[int, str, float]:
    t0 = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "nczones", *argv], capture_output=True, text=True, timeout=60,
                       cwd=ROOT)
    return p.returncode, p.stdout + p.stderr, time.perf_counter() - t0


@pytest.mark.parametrize("dialect", sorted(LOOPS))
def test_simulate_ends_nested_loops_within_the_budget(tmp_path, dialect):
    machine, text = LOOPS[dialect]
    prog = tmp_path / "loops.nc"
    prog.write_text(text)
    rc, out, secs = _run("simulate", str(prog), "--machine", str(MACHINES / machine), "--budget", "1")
    assert rc == 2 and "VF203" in out and "budget of 1 s" in out and "simulation stopped there" in out, out
    assert "Traceback" not in out and secs < 45


@pytest.mark.parametrize("dialect", ["fanuc", pytest.param("linuxcnc", marks=pytest.mark.long)])
def test_plot_no_verify_ends_nested_loops_within_the_budget(tmp_path, dialect):
    machine, text = LOOPS[dialect]
    prog = tmp_path / "loops.nc"
    prog.write_text(text)
    out_png = tmp_path / "out.png"
    rc, out, secs = _run("plot", str(prog), "--machine", str(MACHINES / machine), "--no-verify", "--budget", "1",
                         "-o", str(out_png))
    assert rc == 0 and out_png.exists() and "budget of 1 s was spent" in out, out
    assert "Traceback" not in out and secs < 45


@pytest.mark.long
def test_simulate_refuses_a_lathe_cycle_past_max_iterations(tmp_path):
    """The G71 reproducer (U0.001 from X800: ~385,000 passes) stops at its block in simulate too."""
    jaws = (ROOT / "specs" / "examples" / "programs" / "g71_jaws.nc").read_text()
    prog = tmp_path / "g71.nc"
    prog.write_text(jaws.replace("X80. Z2.", "X800. Z2.").replace("G71 U3. R1.", "G71 U0.001 R0.0005"))
    rc, out, secs = _run("simulate", str(prog), "--machine", str(MACHINES / "fanuc_lathe.toml"), "--budget", "5")
    assert "roughing passes, more than 100000" in out and "Traceback" not in out and secs < 45, out
