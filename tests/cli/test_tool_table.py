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


@pytest.mark.parametrize("table, units, verdict", [
    ("T1 P1 Z50 D6\n", "mm", "safe"),        # 200 + 100 + 50 = 350 <= 400
    ("T1 P1 Z4 D0.25\n", "mm", "safe"),      # 304
    ("T1 P1 Z4 D0.25\n", "inch", "unsafe"),  # 4 in = 101.6 mm: 401.6 > 400
])
def test_the_table_replaces_the_machine_files_tools(tmp_path, table, units, verdict):
    from nczones.commands.verify import with_tool_table
    from nczones.machine import load_machine
    from nczones.prover import verify_text

    machine = load_machine(MILL)
    assert verify_text(PROGRAM, machine).verdict.label == "unsafe"  # the machine file's H1 = 120: Z420
    (tmp_path / "shop.tbl").write_text(table)
    with_table, note = with_tool_table(machine, str(tmp_path / "shop.tbl"), units)
    assert verify_text(PROGRAM, with_table).verdict.label == verdict
    assert note.startswith(f"tool lengths and diameters from the tool table {tmp_path / 'shop.tbl'} ({units}")


def test_a_tool_the_table_lacks_has_no_length(tmp_path):
    from nczones.commands.verify import with_tool_table
    from nczones.errors import GcodeError
    from nczones.machine import load_machine
    from nczones.prover import verify_text

    (tmp_path / "shop.tbl").write_text("T2 P1 Z1\n")
    with_table, _ = with_tool_table(load_machine(MILL), str(tmp_path / "shop.tbl"), "mm")
    with pytest.raises(GcodeError) as e:  # never a guessed length
        verify_text(PROGRAM, with_table)
    assert e.value.diagnostics[0].code == "GC310"


def test_the_command_line(tmp_path):
    (tmp_path / "p.ngc").write_text(PROGRAM)
    (tmp_path / "good.tbl").write_text("T1 P1 Z50\nTOOLNO POCKET LENGTH\n")
    r = nczones("verify", "p.ngc", "--machine", MILL, "--tool-table", "good.tbl", "--tool-table-units", "mm",
                cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "p.ngc: note: tool lengths and diameters from the tool table good.tbl (mm, sha256 " in r.stdout
    assert "good.tbl:2:1: note[IM204]" in r.stderr  # the line LinuxCNC skips is said, not fatal
    (tmp_path / "shop.tbl").write_text("T1 P1 Z1,5\n")
    r = nczones("verify", "p.ngc", "--machine", MILL, "--tool-table", "shop.tbl", cwd=tmp_path)
    assert r.returncode == 2 and "error[VF111]" in r.stderr and "--tool-table-units" in r.stderr
    r = nczones("verify", "p.ngc", "--machine", MILL, "--tool-table", "shop.tbl", "--tool-table-units", "mm",
                cwd=tmp_path)
    assert r.returncode == 2 and "shop.tbl:1:7: error[IM102]" in r.stderr
