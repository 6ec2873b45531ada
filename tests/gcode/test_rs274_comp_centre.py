"""The compensated I/J arc's centre double (comp41, review42): LinuxCNC's ``arc_data_ijk`` (``convert_arc_comp2``:
``program_x + i_number``) and ``arc_data_comp_ijk`` (``convert_arc_comp1``: ``current_x + i_number``) add the
start's double and the word's, in program units (inch under G20), not the correctly rounded exact sum.

* ``test_ulp_centres_are_rs274s`` — contours whose start and I/J words make the two differ by an ulp
  (``10.1 + 10.2``, ``0.7 + 0.1``, ...: asserted): ``rs274 -g`` runs each, the full path matches its log motion
  by motion, and where the pass takes the program (G90, G21) its rows are rs274's motion ends; G20 and G91
  contours (the pass declines them) hold the full path to rs274.
* ``test_decimal_contours_are_enclosed_by_the_full_path`` and ``test_decimal_contours_are_rs274s`` — G41/G42
  contours of lines and arcs in tenths (comp41's own generator draws eighths, binary fractions, whose sums are
  exact): the pass's invariant against the full path (``check_against_full``), and rs274 against both;
  ``test_the_tenths_make_ulp_centres`` checks that the draws do make ulp-off centre sums.
* ``test_a_face_at_an_ulp_centres_extreme`` — a travel face at a compensated arc's top and right extremes (its
  centre an ulp off the exact sum), one pulse either side, on it and 1e-13 mm off it: the verdict with the pass is
  the full path's (the pass's box, ``double_comp.corner_box`` with ``more``, encloses the exact centre's arc).
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import nczones.pipeline.verification as verification
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion
from tests.gcode.test_double_pass import check_against_full
from tests.gcode.test_double_pass_comp import MILL
from tests.gcode.test_rs274_double_comp import SETUP
from tests.machines import load_machine
from tests.oracles.rs274 import compare
from tests.sizes import examples
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
    # G90.1: the centre is the words' doubles, no sum (the pass declines G90.1)
    "absolute centres, G90.1": ("G21 G90 G90.1 G17 G54 F800\nT1 M6\nG0 X0 Y0\nG41 G1 X10.1 Y0\n"
                                "G2 X30.5 Y0 I20.3 J0\nG1 X30.5 Y-10\nG40 G0 X40 Y-20\nG91.1\nM30\n", False, []),
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


# ------------------------------------------------------------------------------------------- drawn decimal contours

#: centre offsets of radius 5 k / 10 (3-4-5 triangles) and axis-parallel ones, in tenths
_OFFSETS = [(3, 4), (4, -3), (-3, -4), (-4, 3), (5, 0), (0, 5), (-5, 0), (0, -5)]


def _tenths(v: int) -> str:
    return f"{v / 10:.1f}"


def _decimal_contour(rng: random.Random) -> tuple[str, int]:
    """A G41/G42 contour (in tenths of mm) of lines and I/J arcs (a quarter, half or three quarters of a circle
    about a 3-4-5 centre, radius 1.5 to 9 mm), an arc or a line first; and how many of its I/J centres' double
    sums differ from the rounded exact ones."""
    lines, x, y, ulps = ["G21 G90 G17 G54 F800", "G0 X0 Y0", rng.choice(["G41 D1", "G42 D1"])], 0, 0, 0
    for _ in range(rng.randint(2, 7)):
        if rng.randint(0, 2):
            k = rng.randint(3, 18)
            i, j = (v * k for v in rng.choice(_OFFSETS))
            cw = rng.random() < 0.5
            ex, ey = -i, -j
            for _ in range(rng.choice([1, 2, 3])):  # the start's vector about the centre, turned a quarter
                ex, ey = (ey, -ex) if cw else (-ey, ex)
            ulps += any(float(_tenths(a)) + float(_tenths(b)) != float(Fraction(a + b, 10)) for a, b in ((x, i), (y, j)))
            x, y = x + i + ex, y + j + ey
            lines.append(f"{'G2' if cw else 'G3'} X{_tenths(x)} Y{_tenths(y)} I{_tenths(i)} J{_tenths(j)}")
        else:
            x, y = x + rng.randint(-300, 300), y + rng.randint(-300, 300)
            lines.append(f"G1 X{_tenths(x)} Y{_tenths(y)}")
    lines += [rng.choice(["G40 G0 X0 Y0", "G40", "G40 G1 X1 Y1"]), "M30"]
    return "\n".join(lines) + "\n", ulps


def test_the_tenths_make_ulp_centres():
    rng = random.Random(7)
    assert sum(_decimal_contour(rng)[1] > 0 for _ in range(40)) >= 20  # most drawn contours have one


@settings(max_examples=examples(25, 400), deadline=None)
@given(st.randoms(use_true_random=False))
def test_decimal_contours_are_enclosed_by_the_full_path(rng):
    check_against_full(_decimal_contour(rng)[0], MILL, max_iterations=100)


@NEEDS_RS274
@settings(max_examples=examples(6, 100), deadline=None)
@given(rng=st.randoms(use_true_random=False))
def test_decimal_contours_are_rs274s(rng, tmp_path_factory):
    text = _decimal_contour(rng)[0].replace("G54 F800\n", "G54 F800\nT1 M6\n").replace(" D1", "")
    tmp = tmp_path_factory.mktemp("comp")
    moves, error, log = run_rs274(text, SETUP, tmp)
    outcome = compare(text, machine_of(SETUP), moves, error)
    assert outcome.status == "match", (outcome, text)
    if error is None:
        try:
            double_pass(text, machine_of(SETUP), max_iterations=100)
        except Declined:  # (a corner LinuxCNC may drop, ...): the full path's match is the check
            return
        assert_the_pass_is_rs274s_motion(text, SETUP, tmp)
