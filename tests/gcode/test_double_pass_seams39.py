"""Where the double pass's new parts meet (lathes, G20, cycles, G64 P, the machine file's modal groups).

Each part came from its own branch with its own tests; these hold the combinations the merge had to decide:
the inch code scales a word, not a lathe's halved X, so G20 where X may be a diameter declines; G64 P in G20 is
inches; a cycle in G20 or on a lathe declines (its words are a mill's millimetres); a program that leaves the
plane to a lathe's machine file runs in its G18 and says so.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.pipeline import verification
from nczones.prover import verify_text
from tests.machines import machine_text as named_machine

from .test_double_pass import MACHINE, check_against_full, machine_text

LATHE = parse_machine(named_machine("report_lathe"))


@pytest.mark.parametrize("text, machine, why", [
    ("G20 G90 G18 G54 F100\n#1 = 1\nG1 X[#1*2] Z-1\nM30\n", LATHE, "diameter"),
    ("G21 G90 G17 G54 F100\n#1 = 1\nG20\nG1 Y[#1*2]\nG7\nG1 X1\nM30\n", MACHINE, "G7 after a G20"),
    ("G21 G90 G17 G54 F100\n#1 = 1\nG7\nG1 X[#1*2]\nG20\nG1 X1\nM30\n", MACHINE, "diameter"),
    ("G21 G90 G18 G54 G98 F100\n#1 = 1\nG0 X10 Z10\nG81 X#1 Z-1 R2\nG80\nM30\n", LATHE, "lathe"),
])
def test_combinations_the_pass_does_not_follow_decline(text, machine, why):
    with pytest.raises(Declined, match=why):
        double_pass(text, machine, max_iterations=100)
    check_against_full(text, machine)  # (declines: the full path decides)


def test_g64_p_in_inches_bounds_25_4_times_the_word():
    text = "G20 G90 G17 G54 F100\n#1 = 1\nG64 P0.01\nG1 X[#1*2] Y1\nG1 X0\nM30\n"
    path = check_against_full(text, MACHINE)
    assert path is not None and path.tolerance >= 2 * Fraction("0.254")
    assert path.tolerance - 0.508 < 1e-12


@pytest.mark.parametrize("gap", ["0.3", "0.5", "0.6", "2"])
def test_g64_p_in_inches_near_a_wall_agrees_with_the_full_path(monkeypatch, gap):
    """G64 P0.01 in G20 blends within 0.508 mm: at a gap below it the pass must not prove (0.02 mm, read as
    millimetres, would)."""
    machine = parse_machine(machine_text(extra='[[zones]]\nname = "pocket"\nkind = "box"\n'
                                               'min = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
                                               'max = { X = "100", Y = "1000", Z = "1000" }\n'))
    text = (f"G20 G90 G17 G54 F20\nG64 P0.01\n#1 = 0\no1 while [#1 LT 4]\nG1 X[[100 - {gap}] / 25.4] Y[#1 * 0.1]\n"
            "G1 X0 Y[#1 * 0.1 + 0.05]\n#1 = [#1 + 1]\no1 endwhile\nM2\n")
    routed = verify_text(text, machine)
    with monkeypatch.context() as m:
        m.setattr(verification, "_double_pass_reads", lambda t, machine=None: False)
        full = verify_text(text, machine)
    assert routed.verdict == full.verdict, (gap, routed.reasons, full.reasons)
    if dict(routed.stats).get("double_pass_boxes", 0):
        assert float(gap) > 0.508


def test_a_lathe_program_without_a_plane_runs_in_the_machine_files_g18():
    path = check_against_full("F100\n#1 = 1\nG1 X[#1*20] Z-1\nG3 X24 Z-3 K-2 I0\nM30\n", LATHE)
    assert path is not None and path.assumed[-1] == ("plane", "G18")
