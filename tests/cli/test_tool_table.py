"""``nczones verify --tool-table FILE --tool-table-units mm|inch`` (issue 38): tool lengths from the shop's
LinuxCNC tool table without re-importing the machine.

mill.toml: travel Z 0..400 (machine Z, the spindle nose), G54 Z = 100, H1 = 120 mm.  With G43 H1 LinuxCNC's
machine Z is program Z + G54.Z + tool length, so ``G0 Z200`` reaches 200 + 100 + 120 = 420 (unsafe) with the
machine file's H1, and 200 + 100 + L with the table's T1 Z<L> (LinuxCNC's H<n> is tool n's Z offset).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
MILL = str(ROOT / "specs" / "machines" / "mill.toml")
PROGRAM = "G21 G90 G54\nT1 M6\nG43 H1\nG0 X0 Y0 Z200\nM30\n"


def nczones(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    r = subprocess.run([sys.executable, "-m", "nczones", *args], capture_output=True, text=True, cwd=cwd)
    assert "Traceback" not in r.stderr, r.stderr
    return r


@pytest.mark.parametrize("table, units, code", [
    ("T1 P1 Z50 D6\n", "mm", 0),        # 200 + 100 + 50 = 350 <= 400: safe
    ("T1 P1 Z4 D0.25\n", "mm", 0),      # 304: safe
    ("T1 P1 Z4 D0.25\n", "inch", 1),    # 4 in = 101.6 mm: 401.6 > 400: unsafe
    ("T2 P1 Z1\n", "mm", 2),            # no T1 in the table: H1 has no length; GC310, never a guess
])
def test_the_table_replaces_the_machine_files_tools(tmp_path, table, units, code):
    (tmp_path / "p.ngc").write_text(PROGRAM)
    (tmp_path / "shop.tbl").write_text(table)
    assert nczones("verify", "p.ngc", "--machine", MILL, cwd=tmp_path).returncode == 1  # H1 = 120: Z420
    r = nczones("verify", "p.ngc", "--machine", MILL, "--tool-table", "shop.tbl", "--tool-table-units", units,
                cwd=tmp_path)
    assert r.returncode == code, r.stdout + r.stderr
    if code == 2:
        assert "error[GC310]: tool length register H1 is not in" in r.stderr
    else:
        assert "note: tool lengths and diameters from the tool table shop.tbl" in r.stdout


def test_units_are_required_and_a_bad_table_is_exit_2(tmp_path):
    (tmp_path / "p.ngc").write_text(PROGRAM)
    (tmp_path / "shop.tbl").write_text("T1 P1 Z1,5\n")
    r = nczones("verify", "p.ngc", "--machine", MILL, "--tool-table", "shop.tbl", cwd=tmp_path)
    assert r.returncode == 2 and "error[VF110]" in r.stderr and "--tool-table-units" in r.stderr
    r = nczones("verify", "p.ngc", "--machine", MILL, "--tool-table", "shop.tbl", "--tool-table-units", "mm",
                cwd=tmp_path)
    assert r.returncode == 2 and "shop.tbl:1:7: error[IM102]" in r.stderr
