"""rs274 differential findings fixed on branch rs274-fix (LinuxCNC 2.9.0~pre1's rs274 is the reference).

* A G20/G21 while a tool length is applied, then G49 (or G43, or M72's restore of G49): LinuxCNC 2.9's
  ``convert_length_units`` converts the position but not the tool offset, so ``G49`` adds the old-unit
  number to the new-unit position.  Recorded with ``rs274 -g`` (tool table ``T1 P1 Z0.519``):
  ``G21 G90 F100 / G43 H1 / G20 / G49 / G0 X1`` gives ``STRAIGHT_TRAVERSE(25.4000, 0.0000, 321.6554 ...)``
  (mm): Z = (-0.519 + 13.1826) inch = 12.6636 inch = 321.655 mm, a Z move the program does not write.
  nczones does not model it: the verdict is ``unknown`` naming G49, never the ``safe`` of a Z that stays.
* ``#5021``-``#5029`` and ``#5081``-``#5089``: rs274 2.9.0~pre1 reads 0 (param-5021.ngc), newer LinuxCNC the
  position / applied length: ``unknown`` (GC395), version-dependent.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from nczones.gcode import GcodeError
from nczones.machine import load_machine, parse_machine
from nczones.prover import verify_text as verify

MILL = load_machine("specs/machines/mill.toml")
COMP = parse_machine(Path("specs/machines/mill.toml").read_text().replace(
    "[machine]\n", '[machine]\ncutter_compensation = "linuxcnc"\n', 1) + '\n[tool_diameters]\nT1 = "6"\nT2 = "10"\n')
MOVES = "".join(f"G1 X{i % 7} Y{i % 5}\n" for i in range(600))  # > 512 motions: the vectorized tier


@pytest.mark.parametrize("body", [
    "G21 G90 G0 X0 Y0\nF100\nG43 H1\nG20\nG49\nG0 X1\n",
    "G21 G90 G0 X0 Y0\nF100\n" + MOVES + "G43 H1\nG20\nG49\nG0 X1\n" + MOVES.replace("G1", "G1 G21", 1),
    "G21 G90 G0 X0 Y0\nF100\n#1 = 1\nG43 H1\nG20\nG49\nG0 X[#1]\n",                  # the double pass ('#')
    "G21 G90 G0 X0 Y0\nF100\n#1 = 1\n" + MOVES + "G43 H1\nG20\nG49\nG0 X[#1]\n",
    # M73 in a subroutine: its return restores G21 first, then G49 (LinuxCNC restore_settings)
    "o100 sub\nM73\nG20\nG43 H1\no100 endsub\nG21 G90 G0 X0 Y0\nF100\no100 call\nG0 X1\n",
])
def test_g49_after_a_units_change_under_g43_is_unknown(body):
    result = verify(body + "M30\n", MILL)
    assert result.verdict.label == "unknown", result.verdict
    assert "G20/G21 while a tool length is applied" in " ".join(r.message for r in result.reasons), result.reasons


def test_g49_in_the_units_of_its_g43_is_still_proved():
    result = verify("G21 G90 G0 X0 Y0\nF100\nG43 H1\nG20\nG21\nG49\nG0 X1\nM30\n", MILL)
    assert "G20/G21" not in " ".join(r.message for r in result.reasons), result.reasons


@pytest.mark.parametrize("param", ["#5021", "#5083"])
def test_version_dependent_parameters_are_unknown_end_to_end(param):
    result = verify(f"G21 G90\nG43 H1\nG0 X[{param} * 0 + 1]\nM30\n", MILL)
    assert result.verdict.label == "unknown"
    assert "version-dependent" in " ".join(r.message for r in result.reasons), result.reasons


def test_restoring_g94_over_g93_is_unknown():
    """rs274_findings/restore-g93-feed.ngc, recorded: ``G21 G90 F100 / M70 / G93 F30 / M72 / G1 X1`` -> rs274
    ``SET_FEED_MODE(0, 0)`` then ``SET_FEED_RATE(0.0000)`` and "Cannot do g1 with zero feed rate"; generator seed
    7024 the same through an M73 return; seed 19 (``G94 F300`` then ``G93 F30`` in the M73 sub) restores F500 and
    runs.  nczones restored F in all three: now unknown."""
    for text in ("G21 G90 F100\nM70\nG93 F30\nM72\nG1 X1\nM30\n",
                 "G21 G90 F100\n#1 = 1\nM70\nG93 F30\nM72\n" + MOVES.replace("G1", "G0", 600) + "G1 X[#1]\nM30\n",
                 "o100 sub\nM73\nG93 F30\no100 endsub\nG21 G90 G0 X0 Y0\nF100\no100 call\nG1 X1\nM2\n",
                 "o100 sub\nM73\nG94 F300\nG93 F30\no100 endsub\nG21 G90 G0 X0 Y0\nF500\no100 call\nG1 X1\nM2\n"):
        result = verify(text, MILL)
        assert result.verdict.label == "unknown", result.verdict
        assert any("over G93" in r.message for r in result.reasons), result.reasons


@pytest.mark.parametrize("body", ["T1 M6\nM61 Q2\nG0 X[#5400]\n", "T1 M6\nM61 Q2\nG0 X[#5410]\n",
                                  "T1 M6\nM61 Q2\nG0 Z[#5403]\n", "M61 Q2\nG41\nG1 X10 F100\nG40\nG0 X0\n"])
def test_spindle_slot_reads_after_m61_are_unknown(body):
    """rs274_findings/m61-current-tool.ngc: after ``M61 Q2`` rs274 reads ``#5400`` as 0 (nczones read 2), and
    ``M61 Q4 / G41 / G1 X22.8 Y-16.8`` ends at X22.8 (rs274) where nczones offset it by T4's diameter: the
    standalone interpreter keeps the spindle slot's table entry (as for G43 after M61, already unknown)."""
    result = verify("G21 G90 G0 X0 Y0\n" + body + "M30\n", COMP)
    assert result.verdict.label == "unknown", result.verdict
    assert "M61" in " ".join(r.message for r in result.reasons), result.reasons


FINDINGS = Path(__file__).parent / "data" / "rs274_findings"


@pytest.mark.parametrize(("name", "many"), [("do-continue-repeat", False), ("while-break-then-do", False),
                                            ("do-continue-repeat", True), ("while-break-then-do", True)])
def test_a_loop_after_break_or_continue_is_unknown(name, many):
    """Recorded in rs274_findings/NAME.rs274.txt: after a ``continue`` in a ``do`` rs274 runs the next
    ``repeat [3]`` 6 times (6 ``STRAIGHT_FEED``, nczones wrote 3); after a ``break`` out of a ``while`` the
    next ``do`` body runs once (2 traverses, nczones 8).  LinuxCNC 2.9's loop state: unknown (GC390)."""
    text = (FINDINGS / f"{name}.ngc").read_text()
    if many:
        text = text.replace("G21 G90 F500\n", "G21 G90 F500\n" + MOVES, 1)
    result = verify(text, MILL)
    assert result.verdict.label == "unknown", result.verdict
    assert any(r.code == "GC390" and "after a" in r.message for r in result.reasons), result.reasons


@pytest.mark.parametrize("many", [False, True])
def test_break_of_a_loop_inside_an_if_runs(many):
    """rs274_findings/break-in-if.ngc: LinuxCNC runs it (rs274: X1, then Y1); nczones refused the outer
    ``o1 endif`` (GC314): the ifs opened inside the loop are left with it.  The loop body moves X#3 for #3 = 1
    before the break at #3 = 2, then Y1."""
    text = (FINDINGS / "break-in-if.ngc").read_text()
    if many:
        text = text.replace("G21 G90\n", "G21 G90\nF100\n" + MOVES, 1)
    result = verify(text, MILL)
    assert result.verdict.label != "unknown", result.reasons


def test_g5_in_g93_without_f_is_refused():
    """rs274_findings/g93-spline-without-f.ngc: rs274 "F word missing with inverse time arc move" at
    ``G5 X2 Y3 P1 Q1`` (G93, the F only on the block before); nczones ran it."""
    for text in ("G21 G90 G93 F10\nG5 X1 Y1 I1 J0 P1 Q1 F20\nG5 X2 Y3 P1 Q1\nM2\n",
                 "G21 G90 F100\n#1 = 3\n" + MOVES + "G93 F10\nG5 X1 Y1 I1 J0 P1 Q1 F20\nG5 X2 Y[#1] P1 Q1\nM2\n"):
        with pytest.raises(GcodeError) as e:
            verify(text, MILL)
        assert "G93" in str(e.value) and "G5" in str(e.value)


@pytest.mark.parametrize("many", [False, True])
def test_modal_g5_1_without_ij_feeds_straight(many):
    """rs274 on ``G21 G90 F100 / G1 X1 / G5.1 X8 Y2 I1 J0 / X10 Y4``: the modal block without I J is a
    STRAIGHT_FEED(10, 4) (rs274_findings/g5-without-ij.ngc); ``G5.1 X8 Y2`` with its word is refused ("Must
    specify both I and J with G5.1").  nczones refused the modal block (GC208)."""
    pre = "G21 G90 F100\n#1 = 4\n" + (MOVES if many else "")
    result = verify(pre + "G0 X0 Y0\nG1 X1\nG5.1 X8 Y2 I1 J0\nX10 Y[#1]\nM2\n", MILL)
    assert result.verdict.label != "unknown", result.reasons
    with pytest.raises(GcodeError):
        verify(pre + "G1 X1\nG5.1 X8 Y2\nM2\n", MILL)


def test_g5_without_ij_not_after_a_g5_is_unknown():
    """rs274 runs ``G1 X1 / G5 X5 Y5 P1 Q1`` (a NURBS_FEED whose points ``rs274 -g`` does not print): unknown,
    not the GC208 refusal it was."""
    result = verify("G21 G90 F100\nG0 X0 Y0\nG1 X1\nG5 X5 Y5 P1 Q1\nM2\n", MILL)
    assert result.verdict.label == "unknown"
    assert any("G5 without I and J" in r.message for r in result.reasons), result.reasons


@pytest.mark.parametrize("pre", ["", MOVES, "#1 = -8\n"])
def test_g28_with_axis_words_in_a_rotated_system_is_unknown(pre):
    """rs274_findings/rotated-g28-axis.ngc (recorded): after ``G10 L2 P0 Y6 R-39.9``, ``G28 X-8`` ends with
    machine Y at -0.00001 in rs274 (X homed in the rotated program frame moves Y); nczones kept Y at 7.60034."""
    x = "X[#1]" if pre.startswith("#") else "X-8"
    text = f"G21 G90 F100\nG0 X0 Y0\n{pre}G10 L2 P0 Y6 R-39.9\nG28 {x}\nG0 X-1 Y-7 Z-10\nM2\n"
    result = verify(text, MILL)
    assert result.verdict.label == "unknown", result.verdict
    assert any("rotated by G10 L2 R" in r.message for r in result.reasons), result.reasons
