"""``G64 P<p> [Q<q>]`` in the double pass: every motion within ``p + q`` of its programmed path (``2p`` without
Q), the proof's margin grown.

LinuxCNC's ``G64 P p Q q`` (Q absent or below 0 is p) blends within ``p`` after naive-CAM merging within ``q``; the full path
proves each corner within ``p + q`` of the programmed path (``prover/blend.py``).  The pass adds a bound of that
to every motion's margin (``DoublePath.tolerance``), a superset: where it proves, the full path proves; near a
wall it declines and the full path decides.  The invariant's generated programs hold G64 P lines too
(``test_double_pass.TOOLS_AND_MODES``).
"""

from __future__ import annotations

import pytest

from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.machine import parse_machine
from nczones.pipeline import verification
from nczones.prover import verify_text

from .test_double_pass import check_against_full, machine_text

WALL = 100  # the allowed box ends at X = 100 (a box zone of the machine below)
MACHINE = parse_machine(machine_text(extra='[[zones]]\nname = "pocket"\nkind = "box"\n'
                                           f'min = {{ X = "-1000", Y = "-1000", Z = "-1000" }}\n'
                                           f'max = {{ X = "{WALL}", Y = "1000", Z = "1000" }}\n'))


def _program(p: str, gap: str, q: str = "") -> str:
    """A zig-zag whose corners reach ``WALL - gap`` in X under ``G64 P p [Q q]`` (parametric: the pass is tried)."""
    return (f"G21 G90 G17 G54 F500\nG64 P{p}{' Q' + q if q else ''}\n#1 = 0\n"
            f"o1 while [#1 LT 6]\nG1 X[{WALL} - {gap}] Y[#1 * 2]\nG1 X0 Y[#1 * 2 + 1]\n#1 = [#1 + 1]\no1 endwhile\nM2\n")


def _routed_and_full(text: str, monkeypatch):
    routed = verify_text(text, MACHINE)
    with monkeypatch.context() as m:
        m.setattr(verification, "_double_pass_reads", lambda t, machine=None: False)
        full = verify_text(text, MACHINE)
    return routed, full


@pytest.mark.parametrize("gap", ["0.05", "0.1", "0.19", "0.2", "0.21", "0.5", "3"])
def test_verdicts_agree_with_the_full_path_near_a_wall(monkeypatch, gap):
    """``G64 P0.1``: a corner within 0.2 of the wall may leave the box on the full path; the pass proves only a gap
    above its bound, and the routed verdict is always the full path's."""
    text = _program("0.1", gap)
    routed, full = _routed_and_full(text, monkeypatch)
    assert routed.verdict == full.verdict, (gap, routed.reasons, full.reasons)
    by_pass = dict(routed.stats).get("double_pass_boxes", 0) > 0
    if by_pass:
        assert float(gap) > 0.2 and routed.verdict.label == "safe"
    if float(gap) >= 0.5:
        assert by_pass, routed.stats  # far from the wall: the pass proves it


@pytest.mark.parametrize("q, bound", [("0.3", 0.4), ("0", 0.1), ("0.05", 0.15), ("-1", 0.2)])
@pytest.mark.parametrize("gap", ["0.09", "0.12", "0.17", "0.25", "0.35", "0.45", "3"])
def test_with_q_the_verdicts_agree_with_the_full_path_near_a_wall(monkeypatch, q, bound, gap):
    """``G64 P0.1 Q q``: a corner within ``0.1 + q`` of the wall (Q below 0 is P) may leave the box on the full
    path; the pass proves only a gap above that, and the routed verdict is always the full path's."""
    text = _program("0.1", gap, q)
    routed, full = _routed_and_full(text, monkeypatch)
    assert routed.verdict == full.verdict, (q, gap, routed.reasons, full.reasons)
    by_pass = dict(routed.stats).get("double_pass_boxes", 0) > 0
    if by_pass:
        assert float(gap) > bound and routed.verdict.label == "safe"
    if float(gap) >= bound + 0.2:
        assert by_pass, routed.stats  # far from the wall: the pass proves it


@pytest.mark.parametrize("q, inch, bound", [("0.3", False, 0.4), ("0", False, 0.1), ("-1", False, 0.2), ("-0", False, 0.2),
                                            ("0.3", True, 0.4 * 25.4), ("0", True, 0.1 * 25.4)])
def test_the_bound_with_q_is_p_plus_q_rounded_up(q, inch, bound):
    text = _program("0.1", "3", q)
    if inch:  # the same program in inches, far from the wall (the bound scales: P and Q are inches)
        text = text.replace("G21", "G20").replace(f"{WALL} - 3", "1")
    path = double_pass(text, MACHINE, max_iterations=100)
    assert path.tolerance >= bound and path.tolerance - bound < 1e-12
    assert check_against_full(text, MACHINE) is not None


def test_the_bound_is_twice_p_rounded_up():
    path = double_pass(_program("0.1", "3"), MACHINE, max_iterations=100)
    assert path.tolerance >= 0.2 and path.tolerance - 0.2 < 1e-15
    assert check_against_full(_program("0.1", "3"), MACHINE) is not None


@pytest.mark.parametrize("text", ["G21 G90 G54 F5\n#1 = 1\nG64 P0\nG1 X#1\n", "G21 G90 G54 F5\n#1 = 1\nG64 P-1\nG1 X#1\n",
                                  "G21 G90 G54 F5\n#1 = 1\nG64 Q0.1\nG1 X#1\n",
                                  "G21 G90 G54 F5\n#1 = 1\nG64 P0.1 Q0.1 G1 X#1\n",
                                  "G21 G90 G54 F5\n#1 = 1\nG1 X#1\nG64 P0.1 Q0.1 X2\n",
                                  "G21 G90 G54 F5\n#1 = 1\nG64 P0 Q0.1\nG1 X#1\n",
                                  "G21 G90 G54 F5\n#1 = 1\nG4 P1 G64 P1\nG1 X#1\n"])
def test_what_declines(text):
    """P not above 0 (no tolerance, or an exact value that may be 0), Q without P (naive-CAM windows, the full
    path's), Q in a block with axis words or a motion code (a cycle may take it), and G4 with G64 in one block."""
    assert check_against_full(text, MACHINE) is None


CYCLE_HEAD = "G21 G90 G17 G54 G98 F100\n#1 = 1\nG0 Z10\n"


@pytest.mark.parametrize("body, taken, tolerance", [
    ("G82 G61 X#1 Y1 Z-2 R2 P0.5\nG80\nG0 X0\n", True, False),   # P is G82's dwell; G61 the mode
    ("G64 P0.1\nG82 X#1 Y1 Z-2 R2 P0.5\nX2\nG80\nG1 X[#1*3]\n", True, True),
    ("G82 G64 X#1 Y1 Z-2 R2 P0.5\nG80\n", False, False),          # one P, two codes that may take it
    ("G64 P0.1 G82 X#1 Y1 Z-2 R2\n", False, False),               # a G82 without its own P
])
def test_a_p_word_is_read_by_the_one_code_that_takes_it(body, taken, tolerance):
    """G82's dwell and G64's tolerance share the letter P: the pass reads it for the code that takes it and
    declines a block where both may (the invariant holds where it is taken)."""
    path = check_against_full(CYCLE_HEAD + body + "M30\n", MACHINE)
    assert (path is not None) == taken
    if path is not None:
        assert (path.tolerance > 0) == tolerance
