"""LinuxCNC's ``rs274`` against the double pass on programs with T, M6, M61, G4, G61, G61.1, G64, G91 (issue 36).

A few parametric programs with a tool change (a tool of rs274's tool table, with G43 applied before it: rs274
keeps the applied length at M6), dwells and path modes, each run by ``rs274 -g``
(:func:`tests.tools.rs274_diff.run_rs274`): the full path matches rs274's log motion by motion
(``tests.oracles.rs274.compare``), the pass takes the program, and its rows are rs274's motion ends (dwells
included, at the log's rounding) in order, as many.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion

pytestmark = NEEDS_RS274

#: rs274's tool table (lengths in inches: it runs in inches) and no work offsets
SETUP = (("X", "Y", "Z"), {1: Fraction(1, 10), 2: Fraction(3, 10), 3: Fraction(1, 20)}, {})

PROGRAMS = {
    "tool change with G43": "G21 G90 G17 G54 F500\n#1 = 2.5\nT1 M6\nG43 H1\nG1 X[#1] Y1 Z-1\nT2\nG4 P0.5\n"
                            "M6 M3 S1000\nG1 X[#1 * 2] Z[-#1]\nG49\nG0 Z5\nM30\n",
    "path modes": "G21 G90 G17 G54 F300\n#1 = 0\no1 while [#1 LT 4]\nG61 G1 X[#1] Y[#1 * 0.5]\nG64 X[#1 + 0.1]\n"
                  "G61.1 Y[#1 / 3]\nG4 P[#1 + 0.25]\n#1 = [#1 + 1]\no1 endwhile\nM30\n",
    "G91 chains": "G21 G90 G17 G54 F400\n#1 = 0\nG1 X1 Y1\nG91\no1 while [#1 LT 25]\nG1 X0.1 Y[0.3 / 7]\n"
                  "G0 Z[-0.01 * #1]\n#1 = [#1 + 1]\no1 endwhile\nG43 H2\nZ0.1\nG90 G1 X0 Y0\nG91 Z-0.2\nM30\n",
    "M61 and a dwell": "G21 G90 G17 G54 F200\n#1 = 1\nM61 Q3\nG43 H3\nG1 Z[-#1] X2\nG04 P1 M8\nT1 M6\n"
                       "G1 X0 Y[#1]\nM9\nM30\n",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_pass_is_rs274s_motion(name, tmp_path):
    assert_the_pass_is_rs274s_motion(PROGRAMS[name], SETUP, tmp_path)
