"""What a verify the double pass proves loads, and the names the lazy loads must not disturb (fresh processes)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def run(code: str) -> str:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT).stdout


def test_loading_the_interpreter_late_keeps_the_segments_function():
    out = run("import nczones.gcode as g, nczones.gcode.interpreter, nczones.gcode.fastpath\n"
              "from nczones.gcode import Interpreter, Unsupported, MODAL_GROUP_NAMES\n"
              "print(callable(g.segments), Interpreter.__name__, Unsupported.__name__, len(MODAL_GROUP_NAMES))")
    assert out.split() == ["True", "Interpreter", "Unsupported", "7"]


def test_a_program_the_double_pass_proves_loads_no_numpy_z3_interpreter_or_prover_core(tmp_path):
    program = tmp_path / "loop.ngc"
    program.write_text("G21 G90 G54 F500\n#1 = 0\no1 while [#1 LT 50]\nG1 X[10 * COS[#1 * 7.2]] Y[10 * SIN[#1 * 7.2]]\n"
                       "#1 = [#1 + 1]\no1 endwhile\nM30\n")
    machine = ROOT / "specs" / "machines" / "mill.toml"
    out = run("import sys\nfrom nczones.cli import main\n"
              f"code = main(['verify', '--machine', {str(machine)!r}, {str(program)!r}])\n"
              "print(code, *sorted(m for m in ('numpy', 'z3', 'nczones.gcode.interpreter', 'nczones.prover.core')"
              " if m in sys.modules))")
    assert "by the double pass" in out
    assert out.splitlines()[-1] == "0"
