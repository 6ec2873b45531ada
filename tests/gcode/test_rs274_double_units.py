"""LinuxCNC's ``rs274`` against the double pass on programs in inches (G20, issue 36).

A few parametric programs in G20, with G20/G21 switches, G91 chains, a work offset and a tool length of rs274's
parameter file and tool table (inches), each run by ``rs274 -g`` (:func:`tests.tools.rs274_diff.run_rs274`): the
full path matches rs274's log motion by motion (``tests.oracles.rs274.compare``), the pass takes the program, and
its rows are rs274's motion ends (at the log's rounding) in order, as many.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.gcode.linuxcnc.doubles import double_pass
from tests.gcode.rs274_arc_programs import SETUP
from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion
from tests.oracles.rs274 import compare
from tests.tools.rs274_diff import run_rs274

pytestmark = NEEDS_RS274

PROGRAMS = {
    "inches in G55": "G20 G90 G17 G55 F30\n#1 = 0\no1 while [#1 LT 20]\nG1 X[#1 * 0.1 + 2.5443] Y[#1 / 3]\n"
                     "G0 Z[0.0001 * #1]\n#1 = [#1 + 1]\no1 endwhile\nG54 X3937.0078 Y-1234.56789\nM30\n",
    "switches and a chain": "G21 G90 G17 G54 F300\n#1 = 0\nG1 X10 Y10\nG20 X0.1\nG91\no1 while [#1 LT 25]\n"
                            "G1 X2.5443 Y[1 / 7]\nX-2.544427\n#1 = [#1 + 1]\no1 endwhile\nG21 Y0.1\nG90 G20 X1 Y1\n"
                            "G21 G1 X0 Y0\nM30\n",
    "a tool length in inches": "G20 G90 G17 G55 F30\n#1 = 0.5\nG43 H1\nG1 Z[#1]\nX1 Y[#1 / 3]\nG49\nG0 Z2\n"
                               "G43 H3\nG1 Z-0.1\nM30\n",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_pass_is_rs274s_motion_in_inches(name, tmp_path):
    assert_the_pass_is_rs274s_motion(PROGRAMS[name], SETUP, tmp_path)


#: Seeds of arc programs in G20 (``ArcWriter``'s I/J and R kinds, every position and radius in inches).
ARC_SEEDS = (0, 1, 2)


@pytest.mark.parametrize("seed", ARC_SEEDS)
def test_the_pass_holds_rs274s_inch_arcs(seed, tmp_path):
    """An arc program (I/J and R) in G20 (rs274's work offsets and tool lengths, LinuxCNC's arc rule, in inches): the full
    path matches rs274, the pass takes it, and rs274's arcs lie in the pass's quick and refined boxes
    (``test_rs274_double_arcs.check_pass_arcs``), in windows too."""
    import random

    from tests.gcode.rs274_arc_programs import ArcWriter
    from tests.gcode.test_rs274_double_arcs import _machine, check_pass_arcs, check_windows

    writer = ArcWriter(random.Random(seed), menu=("ij_circle", "ij_turn", "r_pyth", "r_big", "r_near_half"))
    writer.unit = Fraction(254, 10)
    text = writer.program(lines=120).replace("G21 ", "G20 ", 1)
    assert text.startswith("G20 ")
    moves, error, log = run_rs274(text, SETUP, tmp_path)
    assert error is None, log[-2000:]
    machine = _machine(base="xyz_box_900000")
    outcome = compare(text, machine, moves, error)
    assert outcome.status == "match", outcome
    path = double_pass(text, machine, max_iterations=1000, arc_tolerance="linuxcnc")
    check_windows(text, machine, path)  # in windows of 97 motions: the same rows and quick boxes
    assert check_pass_arcs(path, moves) > 10
