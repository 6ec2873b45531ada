"""No internal error on program stops, and repeat counts bounded (issue 33, classes 6 and 7).

Class 6: every Fanuc program with ``M00``/``M01`` ended in an internal error (exit 4) in ``verify`` and
``plot``: the Fanuc interpreter recorded its stops as bare line numbers where the report (``_switch_notes``)
reads the LinuxCNC interpreter's ``(code, line)`` pairs.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nczones.cli import main
from nczones.machine import load_machine
from nczones.prover import verify_text

ROOT = Path(__file__).resolve().parents[2]
FANUC_MILL = ROOT / "specs" / "machines" / "fanuc_mill.toml"
FANUC_LATHE = ROOT / "specs" / "machines" / "fanuc_lathe.toml"
LINUXCNC_MILL = ROOT / "specs" / "machines" / "mill.toml"


def _fanuc_stops(n_moves: int, far: bool = False) -> str:
    """M00 then M01 around ``n_moves`` feed moves (> 512: the vectorized tier); ``far`` ends 900 mm out in X."""
    moves = "".join(f"G1 X{10 + i % 20}. Y{10 + i % 7}. F100.\n" for i in range(n_moves))
    return ("O1\nG90 G54 G0 X10. Y10. Z10.\nM00\n" + moves + "M01\n#100 = 5.\nG1 X#100\n"
            + ("G1 X900.\n" if far else "") + "M30\n")


@pytest.mark.parametrize("n_moves", [1, 600])
def test_fanuc_m00_m01_verify_names_the_stops(n_moves):
    r = verify_text(_fanuc_stops(n_moves), load_machine(FANUC_MILL))
    assert r.verdict.label == "safe", r.reasons
    note = next(n for n in r.notes if "M0 (program stop)" in n)
    # the stops are at line 3 (M00) and at the line after the moves (M01)
    assert "M1 (optional stop)" in note and f"line(s) 3, {4 + n_moves}" in note, note


def test_fanuc_m00_does_not_hide_a_violation():
    r = verify_text(_fanuc_stops(600, far=True), load_machine(FANUC_MILL))
    assert r.verdict.label == "unsafe" and r.violations[0].line == 4 + 600 + 3


@pytest.mark.parametrize("code", ["M00", "M01", *(pytest.param(c, marks=pytest.mark.long) for c in ("M30", "M02", "M60"))])
@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-lathe", "linuxcnc"])
def test_every_command_takes_program_stops(tmp_path, capsys, code, dialect):
    """verify (every report format), plot, simulate and replay end with their documented exit status on a
    program with each stop/end code, never 4.  M60 is a machine function nczones does not model on a Fanuc
    control (unknown: 3; simulate refuses it: 2); on LinuxCNC it is a pallet-change stop (no motion)."""
    if dialect == "fanuc":
        machine, text = FANUC_MILL, f"O1\nG90 G54 G0 X10. Y10. Z10.\n{code}\nG1 X900. F100.\nM30\n"
    elif dialect == "fanuc-lathe":
        # short incremental moves from the reference: the pulse-by-pulse simulation stays quick
        machine, text = FANUC_LATHE, f"O1\nG0 U-2. W-1.\n{code}\nG1 W-1. F0.2\nM30\n"
    else:
        machine, text = LINUXCNC_MILL, f"G21 G90 G54 G0 X10 Y10 Z10\n{code}\nG1 X900 F100\nM2\n"
    prog = tmp_path / ("p.ngc" if dialect == "linuxcnc" else "p.nc")
    prog.write_text(text)
    ends = code in ("M30", "M02")
    unmodelled = code == "M60" and dialect != "linuxcnc"
    # the X900 move leaves the travel of the mills; the lathe program stays inside
    expect = 3 if unmodelled else (0 if ends or dialect == "fanuc-lathe" else 1)
    for fmt in ("text", "json", "html", "sarif"):
        out = tmp_path / f"r.{fmt}"
        assert main(["verify", str(prog), "--machine", str(machine), "--format", fmt, "--output", str(out)]) == expect
    assert main(["plot", str(prog), "--machine", str(machine), "-o", str(tmp_path / "p.svg")]) in (0, 1)
    assert main(["simulate", str(prog), "--machine", str(machine), "--format", "json"]) == (
        2 if unmodelled else (1 if expect == 1 else 0))
    if expect in (0, 1):
        assert main(["replay", str(tmp_path / "r.json")]) == 0
    capsys.readouterr()
