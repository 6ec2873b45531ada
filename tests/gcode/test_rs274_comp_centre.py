"""The compensated I/J arc's centre double (comp41, review42): LinuxCNC's ``arc_data_ijk`` (``convert_arc_comp2``:
``program_x + i_number``) and ``arc_data_comp_ijk`` (``convert_arc_comp1``: ``current_x + i_number``) add the
start's double and the word's, in program units (inch under G20), not the correctly rounded exact sum.

* ``test_ulp_centres_are_rs274s`` — contours whose start and I/J words make the two differ by an ulp
  (``10.1 + 10.2``, ``0.7 + 0.1``, ...: asserted): ``rs274 -g`` runs each, the full path matches its log motion
  by motion, and where the pass takes the program (G90, G21) its rows are rs274's motion ends; G20 and G91
  contours (the pass declines them) hold the full path to rs274.
* ``test_a_face_at_an_ulp_centres_extreme`` — a travel face at a compensated arc's top and right extremes (its
  centre an ulp off the exact sum), one pulse either side, on it and 1e-13 mm off it: the verdict with the pass is
  the full path's (the pass's box, ``double_comp.corner_box`` with ``more``, encloses the exact centre's arc).
"""

from __future__ import annotations

from fractions import Fraction

import pytest

import nczones.pipeline.verification as verification
from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion
from tests.gcode.test_rs274_double_comp import SETUP
from tests.machines import load_machine
from tests.oracles.rs274 import compare
from tests.tools.rs274_diff import machine_of, run_rs274

#: (program, the pass takes it, (start, word) pairs whose double sum is not the rounded exact sum)
PROGRAMS = {
    "comp2 arcs, G90": ("G21 G90 G17 G54 F800\nT1 M6\nG0 X0 Y0\nG41 G1 X10.1 Y0\nG2 X20.3 Y-10.2 I10.2 J0\n"
                        "G1 X10.7 Y-10.2\nG3 X0.6 Y-20.3 I0 J-10.1\nG1 X0.6 Y-30\nG40 G0 X-5 Y-35\nM30\n",
                        True, [("10.1", "10.2"), ("-10.2", "-10.1")]),
    "an entry arc, G90": ("G21 G90 G17 G54 F800\nT1 M6\nG0 X10.1 Y0.7\nG41 G2 X20.3 Y11.0005 I10.2 J0.1\n"
                          "G1 X30.3 Y11.0005\nG40 G0 X40 Y0\nM30\n", True, [("10.1", "10.2"), ("0.7", "0.1")]),
    "G42 arcs both ways": ("G21 G90 G17 G54 F700\nT1 M6\nG0 X0 Y-5\nG42 G1 X1.1 Y0.7\nG2 X3.3 Y2.9 I2.2 J0\n"
                           "G1 X10 Y2.9\nG3 X12.8 Y5.7 I0 J2.8\nG1 X12.8 Y20\nG40 G0 X0 Y25\nM30\n", True,
                           [("1.1", "2.2"), ("2.9", "2.8")]),
    "comp2 arcs, G20": ("G20 G90 G17 G54 F30\nT1 M6\nG0 X0 Y0\nG41 G1 X0.1 Y0\nG2 X0.3 Y-0.2 I0.2 J0\n"
                        "G1 X0.1 Y-0.2\nG40 G0 X-0.5 Y-0.5\nM30\n", False, [("0.1", "0.2")]),
    "comp2 arcs, G91": ("G21 G90 G17 G54 F800\nT1 M6\nG0 X0 Y0\nG91\nG41 G1 X10.1 Y0\nG2 X10.2 Y-10.2 I10.2 J0\n"
                        "G1 X-9.6 Y0\nG40 G0 X-5 Y-5\nG90\nM30\n", False, [("10.1", "10.2")]),
    # LinuxCNC's program_x is the G91 chain's double fl(5.7 + 4.4) = 10.100000000000001, its centre then
    # 20.200000000000003; the full path's start double is the rounded exact 10.1, its centre 20.2 (specs/contract.md)
    "a G91 chain before the arc": ("G21 G90 G17 G54 F800\nT1 M6\nG0 X0 Y0\nG91\nG41 G1 X5.7 Y0\nG1 X4.4 Y0\n"
                                   "G2 X10.1 Y-10.1 I10.1 J0\nG1 X-9.6 Y0\nG40 G0 X-5 Y-5\nG90\nM30\n", False,
                                   [("5.7", "4.4")]),
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_sums_differ(name):
    # not vacuous: each program has a centre whose double sum is an ulp off the rounded exact one
    for start, word in PROGRAMS[name][2]:
        assert float(start) + float(word) != float(Fraction(start) + Fraction(word)), (start, word)


@NEEDS_RS274
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_ulp_centres_are_rs274s(name, tmp_path):
    text, taken, _pairs = PROGRAMS[name]
    if taken:
        path = assert_the_pass_is_rs274s_motion(text, SETUP, tmp_path)
        assert path.arcs > 0
        return
    moves, error, log = run_rs274(text, SETUP, tmp_path)
    assert error is None, log[-2000:]
    outcome = compare(text, machine_of(SETUP), moves, error)
    assert outcome.status == "match", outcome


#: G41 on a clockwise arc about (20.3, 0) (its centre double 20.299999999999997) of radius 10.2, the tool outside
#: it (radius 11.2) on the G54 X100 Y50 mill: the compensated arc's top is machine Y 61.2, its right X 131.5
_FACE_PROGRAM = ("G21 G90 G17 G54 F800\nG0 X0 Y0\nG41 D1 G1 X10.1 Y0\nG2 X20.3 Y-10.2 I10.2 J0\nG1 X10 Y-10.2\n"
                 "G40 G0 X0 Y-20\nM30\n")


def _verdicts(text: str, axis: str, face: str, monkeypatch) -> tuple:
    top = {"X": "1000", "Y": "1000", "Z": "1000", axis: face}
    zones = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             f'max = {{ X = "{top["X"]}", Y = "{top["Y"]}", Z = "{top["Z"]}" }}\n')
    machine = load_machine("mill_cutter_comp_g54", extra=zones)
    double_pass(text, machine, max_iterations=100)  # the pass takes it
    with_pass = verify_text(text, machine, max_iterations=100)
    with monkeypatch.context() as m:
        m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
        without = verify_text(text, machine, max_iterations=100)
    return with_pass, without


@pytest.mark.parametrize(("axis", "face", "safe"), [("Y", "61.199", False), ("Y", "61.2", None), ("Y", "61.201", True),
                                                    ("X", "131.499", False), ("X", "131.5", None),
                                                    ("X", "131.501", True), ("Y", "61.2000000000001", None),
                                                    ("X", "131.4999999999999", None)])
def test_a_face_at_an_ulp_centres_extreme(monkeypatch, axis, face, safe):
    assert float("10.1") + float("10.2") != 20.3  # the centre's double is an ulp off the exact sum
    with_pass, without = _verdicts(_FACE_PROGRAM, axis, face, monkeypatch)
    assert with_pass.verdict == without.verdict
    if safe is not None:
        assert with_pass.verdict is (Verdict.SAFE if safe else Verdict.UNSAFE)
    assert [r.message for r in with_pass.reasons] == [r.message for r in without.reasons]
