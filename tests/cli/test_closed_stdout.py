"""Standard output closed (the process started without file descriptor 1, ``cmd >&-``: Python's ``sys.stdout``
is None): ``verify`` and ``simulate`` report a user's error, exit 2, never an internal error (hunt43's F1); a
report written with ``--output`` is complete."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from nczones import cli
from nczones.commands.conventions import EXIT_INPUT, EXIT_OK

ROOT = Path(__file__).resolve().parents[2]
MILL = ROOT / "specs" / "machines" / "mill.toml"
PROGRAM = "G90 G21\nG1 X10 Y10 F100\nM2\n"


@pytest.mark.parametrize("command", (["verify"], ["verify", "--format", "json"], ["simulate"]))
def test_a_closed_standard_output_is_a_users_error(tmp_path, capsys, monkeypatch, command):
    program = tmp_path / "p.ngc"
    program.write_text(PROGRAM)
    monkeypatch.setattr(sys, "stdout", None)
    assert cli.main([*command, str(program), "--machine", str(MILL)]) == EXIT_INPUT
    err = capsys.readouterr().err
    assert "standard output is closed" in err and "internal error" not in err, err


def test_a_report_file_is_complete_with_standard_output_closed(tmp_path):
    """The whole program (``python -m nczones``, its fast exit, ``cli._leave_now``) with fd 1 closed."""
    program, out = tmp_path / "p.ngc", tmp_path / "r.json"
    program.write_text(PROGRAM)
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    got = subprocess.run([sys.executable, "-m", "nczones", "verify", str(program), "--machine", str(MILL),
                          "--format", "json", "--output", str(out)], env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, preexec_fn=lambda: os.close(1), timeout=120)
    assert got.returncode == EXIT_OK, got.stderr
    assert json.loads(out.read_text())["verdict"] == "safe"
