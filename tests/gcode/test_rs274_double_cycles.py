"""LinuxCNC's ``rs274`` against the double pass on drilling programs (G73, G81-G86, G89, G98, G99, L, G91;
issue 36).

A few parametric drilling programs, each run by ``rs274 -g`` (:func:`tests.tools.rs274_diff.run_rs274`): the
full path matches rs274's log motion by motion (``tests.oracles.rs274.compare``), the pass takes the program,
and its rows are rs274's motion ends (G82's dwells included, at the log's rounding) in order, as many.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion

pytestmark = NEEDS_RS274

#: rs274's tool table (lengths in inches: it runs in inches) and no work offsets
SETUP = (("X", "Y", "Z"), {1: Fraction(1, 10), 2: Fraction(3, 10)}, {})

PROGRAMS = {
    "G99 holes, R again after G80": "G21 G90 G17 G54 F300\n#1 = 10\nG0 Z20\nG0 X0 Y0\nG99 G81 X1 Y1 Z-3 R2\n"
                                    "X[#1 + 4.911] Y33.72\nX[#1 / 3] Y[#1 * 0.7]\nG80\nG99 G81 X1 Y1 Z-3 R2\n"
                                    "X[#1 + 1]\nG80\nG0 Z20\nM30\n",
    "G98 and G82, the tool length": "G21 G90 G17 G54 F200\n#1 = 2\nG43 H1\nG0 Z25\nG98 G82 X1 Y1 Z-2 R[#1] P0.5\n"
                                    "X[#1 * 3]\nY[#1 / 3] R3\nG99 X0\nG80\nM30\n",
    "the initial level below R": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z0\nG98 G81 X1 Y1 Z-2 R[#1 + 3]\nX2\nX3 R2\n"
                                 "G99 X4\nG80\nG0 Z10\nM30\n",
    "G83 pecks": "G21 G90 G17 G54 F200\n#1 = 0.7\nG0 Z10\nG99 G83 X1 Y1 Z-3 R2 Q#1\nX[#1 * 3] Q[#1 / 3]\n"
                 "G98 Y2 Z-1.1\nG80\nM30\n",
    "a loop of holes in G18": "G21 G90 G18 G54 F200\n#1 = 0\nG0 Y10\nG99 G81 Z0 X0 Y-1 R1\no1 while [#1 LT 6]\n"
                              "Z[#1 * 2.5] X[#1 * #1 / 7]\n#1 = [#1 + 1]\no1 endwhile\nG80\nM30\n",
    # cyc40: L repeats, G91, G73, G84-G86, G89
    "a G91 row with L": "G21 G90 G17 G54 F300\n#1 = 2.5\nG0 X0 Y0 Z10\nG91 G99 G81 X[#1] Y0.1 R-7 Z-5 L6\n"
                        "G98 X-1 Y[#1 / 3] L3\nG90 G80\nG0 Z10\nM30\n",
    "G91 R above the initial level": "G21 G90 G17 G54 F300\n#1 = 0.7\nG0 X1 Y1 Z2\nG91 G98 G89 X[#1] R3 Z-6 P0.2 L4\n"
                                     "G90 G80\nG0 Z10\nM30\n",
    "G73 with L in G90": "G21 G90 G17 G54 F200\n#1 = 0.7\nG0 Z10\nG99 G73 X1 Y1 Z-3 R2 Q#1 L2\nX[#1 * 3]\n"
                         "G98 Y2 Z-1.1\nG80\nM30\n",
    "G84 and G86 after M3": "G21 G90 G17 G54 F200\n#1 = 2\nM3 S500\nG0 Z25\nG98 G84 X1 Y1 Z-2 R[#1]\nX[#1 * 3]\n"
                            "G99 G86 X0 Z-1 R3 P0.5\nG80\nM30\n",
    "G20: G90, G91 with L, pecks": "G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z2\nG98 G81 X1 Y1 Z-1 R1\nG91 X[#1] L3\n"
                                   "G90 G80\nG0 Z2\nG99 G83 X2 Y1 Z-0.5 R0.1 Q0.07\nX3 L2\nG98 G73 Y2 R0.1 Z-0.5 Q[#1]\nG80\nM30\n",
    # (G85 where the clear level is R: LinuxCNC's rapid there moves nothing, and the full path drops it)
    "G85 and G89": "G21 G90 G17 G54 F200\n#1 = 2\nG0 Z25\nG98 G85 X1 Y1 Z-2 R[#1]\nX[#1 * 3]\nG91 X2 R-20 Z-5 L2\n"
                   "G90 G99 G89 X0 Z-1 R3 P0.5\nG98 Y[#1]\nG80\nM30\n",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_pass_is_rs274s_motion(name, tmp_path):
    assert_the_pass_is_rs274s_motion(PROGRAMS[name], SETUP, tmp_path)
