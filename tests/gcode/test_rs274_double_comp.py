"""LinuxCNC's ``rs274`` against the double pass on G41/G42 contours (comp40, issue 36).

Contours of straight moves under cutter compensation (convex corners: arcs about the programmed corner; concave
ones: the held move pulled back; rapids and Z moves under compensation; G40 and a new G41/G42 after it; G41.1/G42.1), each
run by ``rs274 -t -g`` with the tool table's diameters (:func:`tests.tools.rs274_diff.machine_of`: 0.1 inch): the
full path matches rs274's log motion by motion, the pass takes the program, and its rows are rs274's motion
ends in order, as many.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion

pytestmark = NEEDS_RS274

#: rs274's tool table (inches) and G54 (inches)
SETUP = (("X", "Y", "Z"), {1: Fraction(1, 10), 2: Fraction(3, 10)},
         {"G54": {"X": Fraction(1, 2), "Y": Fraction(-3, 4), "Z": Fraction(0)}})

PROGRAMS = {
    "G41 contour with expressions": "G21 G90 G17 G54 F800\nT1 M6\n#1 = 0.3\nG0 X0 Y0\nG41 G1 X5 Y0\n"
                                    "X15 Y[#1 + 1.25]\nX25 Y[#1 * 2]\nX35 Y-1\nX35 Y10\nZ-1\nX20 Y[10 + #1]\n"
                                    "G40 G0 X0 Y0\nM30\n",
    "G42 with D, a rapid and G40 mid-program": "G21 G90 G17 G54 F500\nG0 X-5 Y-5\nG42 D2 G1 X0 Y0\nX10 Y0\n"
                                                "G0 X10 Y10\nG1 X0 Y10\nX0 Y0.5\nG40\nG1 X-3 Y-3\nG41 D1 G1 X5 Y-3\n"
                                                "X9 Y4\nX13 Y-3\nG40 X20 Y-3\nM2\n",
    "G41.1 and G42.1 with a diameter": "G21 G90 G17 G54 F700\n#2 = 3\nG0 X0 Y0\nG41.1 D[#2] G1 X4 Y0\nX9 Y2\n"
                                       "X14 Y-1\nG40 G1 X18 Y-4\nG42.1 D1.5 X22 Y0\nX26 Y3\nX30 Y0\nG40 X35\nM2\n",
    "a loop of corners": "G21 G90 G17 G54 F600\n#1 = 0\nT2 M6\nG0 X0 Y0\nG41 G1 X2 Y0\n"
                         "o1 while [#1 LT 12]\nX[#1 * 3 + 4] Y[#1 MOD 2 * 1.5]\n#1 = [#1 + 1]\no1 endwhile\n"
                         "G40 G0 X0 Y0\nM30\n",
    # comp41: arcs under compensation (entry arcs, convex and concave line-arc, arc-line and arc-arc corners)
    "a finishing contour of lines and I/J arcs": "G21 G90 G17 G54 F800\nT1 M6\nG0 X-5 Y-5\nG41 G1 X0 Y0\n"
                                                 "X20 Y0\nG3 X25 Y5 I0 J5\nG1 Y15\nG3 X20 Y20 I-5 J0\nG1 X10\n"
                                                 "G2 X5 Y15 I0 J-5\nG1 X0 Y0.5\nG40 G0 X-5 Y-5\nM30\n",
    "R arcs both ways and arc-arc corners": "G21 G90 G17 G54 F700\nG0 X0 Y-10\nG42 D2 G3 X10 Y0 I0 J10\n"
                                            "G1 X20 Y0\nG3 X30 Y10 R10\nG3 X20 Y20 R10\nG2 X10 Y10 R-10.5\n"
                                            "G1 X0 Y12.25\nG40 G1 X-5 Y-5\nM2\n",
    "concave corners into and out of arcs": "G21 G90 G17 G54 F600\n#1 = 0.75\nG0 X0 Y0\nG41 D1 G1 X10 Y0\n"
                                            "G3 X20 Y10 I0 J10\nG1 X10 Y10\nG2 X0 Y[20 + #1] R12\nG1 X-10 Y20\n"
                                            "G3 X-15 Y15 I0 J-5 Z-1\nG40 G1 X-20\nM30\n",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_pass_is_rs274s_motion(name, tmp_path):
    path = assert_the_pass_is_rs274s_motion(PROGRAMS[name], SETUP, tmp_path)
    assert path.arcs > 0
