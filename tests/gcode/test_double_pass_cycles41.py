"""The double pass's canned cycles of cyc41 (issue 36; nczones/gcode/linuxcnc/double_cycles.py): G20 hole lines
from the cycle's template.

The pass's invariant (``check_against_full``: the full path runs the program with no note, as many motions,
rapids and dwells, every motion in the pass's box) on fixed programs, and that the rows came the way they
were meant to (a hole line from the template, not the general path).
"""

from __future__ import annotations

import pytest

from nczones.gcode.linuxcnc import double_cycles
from tests.gcode.test_double_pass import MACHINE, check_against_full

#: G20 programs whose hole lines (X and Y words, L; no R, bottom, P or Q) take the template; per program, how
#: many cycle blocks run the general path (the first of each cycle, and a line that writes R or Z).
G20_HOLES = {
    "G90 G81 and G82": ("G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z1\nG98 G81 X1 Y1 Z-0.1 R0.1\nX[#1 * 3] Y0.5\n"
                        "X2\nY[#1 + 0.25] L2\nG99 G82 X1 Z-0.2 R0.05 P0.5\nX[#1 * 7]\nY-1.3\nG80\nM30\n", 2),
    "G91 with L": ("G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z1\nG91 G99 G81 X0.5 Y0.1 Z-0.3 R-0.5\nX[#1] L3\n"
                   "Y-0.2\nX-0.05 Y[#1 / 3] L4\nG90 G80\nM30\n", 1),
    "pecks": ("G20 G90 G17 G54 F10\n#1 = 0.1\nG0 X0 Y0 Z1\nG99 G83 X1 Y1 Z-0.5 R0.1 Q0.07\nX2\nX[#1 + 3] L2\n"
              "G98 G73 Y2 R0.1 Z-0.5 Q[#1]\nX4\nY[#1 * 9]\nG80\nM30\n", 2),
    "G55, G85 and G89": ("G20 G90 G17 G55 F10\n#1 = 0.25\nG0 X0 Y0 Z2\nG98 G85 X1 Y1 Z-0.3 R0.2\n"
                                   "X[#1]\nX0.3 Y0.4\nG99 G89 X1 Z-0.1 R0.3 P0.2\nY[#1]\nG80\nM30\n", 2),
}


@pytest.mark.parametrize("name", sorted(G20_HOLES))
def test_g20_hole_lines_from_the_template(name, monkeypatch):
    text, general = G20_HOLES[name]
    calls = []
    run = double_cycles.Cycles._general

    def counted(self, *args):
        calls.append(args)
        return run(self, *args)

    monkeypatch.setattr(double_cycles.Cycles, "_general", counted)
    path = check_against_full(text, MACHINE)
    assert path is not None, "declined"
    assert len(calls) == general  # (every other hole line: the template's rows)
