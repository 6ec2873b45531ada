"""LinuxCNC's ``rs274`` against the double pass on lathe programs (lathe39): G7/G8, G91 X in G7, G18 arcs.

Drawn programs (a seeded generator, :func:`lathe_text`) switch between diameter (G7) and radius (G8) mode, move
X and Z by literals and expressions, absolutely and incrementally (G91 X in G7: LinuxCNC halves the increment,
``Interp::read_x``), and cut G18 arcs by K/I (radii) and R from ends written in the mode in force, after G96 (D S), G97 or M3.  Each runs
through ``rs274 -g`` (no INI: the programs write G7 themselves; LinuxCNC starts in G8, as a lathe whose machine
file has no ``diameter_axes``); when the pass takes it, it has rs274's motion count and every row of the pass
is rs274's end point within the log's rounding (4 decimals), and the full interpreter's run agrees with the
pass (``check_against_full``).  Skipped without rs274 (CI has it).
"""

from __future__ import annotations

import os
import random
import shutil
import tempfile
from fractions import Fraction
from pathlib import Path

import pytest

from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from tests.gcode.test_double_pass import check_against_full
from tests.machines import machine_text
from tests.tools.rs274_diff import RS274, run_rs274

pytestmark = pytest.mark.skipif(shutil.which("rs274") is None and not os.path.exists(RS274) and not os.environ.get("CI"),
                                reason="LinuxCNC's rs274 is not installed")

#: report_lathe without diameter axes (G8 at the start, as rs274), with no work offset (rs274's parameter file), in
#: exact stop (G61: an arc after a short motion is taken, no corner blends)
MACHINE = parse_machine(machine_text("report_lathe", set={
    "machine.diameter_axes": [], "offsets.G54": {"X": "0", "Z": "0"}, "machine.path_mode": "G61"}))
SETUP = (("X", "Y", "Z"), {}, {})
SEEDS = range(int(os.environ.get("NCZONES_RS274_DOUBLE_LATHE", "6")))


def lathe_text(seed: int) -> str:
    """A lathe program of some 40 blocks (module docstring)."""
    rnd = random.Random(seed)
    spindle = rnd.choice(["G96 D2500 S200 M3", "G97 S800 M4", "M3 S500"])  # G96/G97 move nothing
    out = ["G18 G21 G90 G54 G7 F200", spindle, "#1 = 0.5", "G0 X40 Z5"]
    dia, x, z = True, 20.0, 5.0  # the mode, where the tool is (radius), in program units
    for _ in range(40):
        kind = rnd.randrange(6)
        if kind == 0:
            dia = not dia
            out.append("G7" if dia else "G8")
        elif kind == 1:  # G91 in the mode in force, back to G90 for X and Z
            dx, dz = rnd.choice([1, -1, 2.5, -0.125]), rnd.choice([1, -0.5])
            out += [f"G91 G1 X[#1 * {dx * (4 if dia else 2)}] Z{dz}", "G90"]
            x, z = x + dx, z + dz
            out.append(f"G1 X{x * (2 if dia else 1):.4f} Z{z:.4f}")
        elif kind == 2:
            x, z = rnd.randint(50, 400) / 10, rnd.randint(-400, 50) / 10
            out.append(f"{rnd.choice(['G0', 'G1'])} X[{x * (2 if dia else 1):.4f} + #1 - 0.5] Z{z:.4f}")
        else:  # a quarter (K/I) or an R arc from (z, x): counter-clockwise in (Z, X) up, or clockwise down
            r = rnd.randint(5, 40) / 10
            up = x < 20
            code, ex = ("G3", x + r) if up else ("G2", x - r)
            # K/I: a quarter about (z - r, x); R: the same end, a radius 1.5 r (the short way)
            words = f"R{1.5 * r:.4f}" if kind == 5 else f"K{-r:.4f} I0"
            out.append(f"{code} X{ex * (2 if dia else 1):.4f} Z{z - r:.4f} {words}")
            x, z = ex, z - r
    out.append("M2")
    return "\n".join(out) + "\n"


@pytest.mark.parametrize("seed", SEEDS)
def test_the_pass_has_rs274s_rows_on_lathe_programs(seed):
    text = lathe_text(seed)
    with tempfile.TemporaryDirectory() as d:
        moves, error, log = run_rs274(text, SETUP, Path(d))
    assert error is None, (error, text)
    try:
        path = double_pass(text, MACHINE, max_iterations=1000)
    except Declined as exc:
        pytest.fail(f"the pass declined a drawn lathe program: {exc.reason}\n{text}")
    assert path.motions == len(moves), (path.motions, len(moves))
    assert path.arcs == sum(mv.kind == "ARC" for mv in moves)
    for k, mv in enumerate(moves, start=1):
        for a, name in ((0, "X"), (1, "Z")):
            got = Fraction(path.columns[a][k])
            want = mv.end["XYZ".index(name)]
            assert abs(got - want) <= mv.tol + Fraction(1, 10**9), (k, name, float(got), float(want), text)
    assert check_against_full(text, MACHINE) is not None
