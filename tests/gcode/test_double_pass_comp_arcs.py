"""Arcs (G2/G3, I/J and R) under cutter compensation in the double pass (nczones/gcode/linuxcnc/double_comp.py,
comp41) against the full path.

The pass's invariant (``check_against_full``: the same motions in the same order, every exact end and every
arc in its row's box) over generated G41/G42 contours mixing lines and arcs: entry arcs, line-arc, arc-line and
arc-arc corners, convex and concave, arcs on both sides of the tool (inside and outside), R (the short and the
long way) and I/J, G2 and G3, G40 mid-program.  The words are binary fractions (on the G54 X100 Y50 machine):
the rows are then ``float`` of the full path's exact ends, so a formula off by one ulp (a centre computed
another way, a radius's sign) shows.  The verdict with the pass is the full path's with a zone face at a
compensated arc's extreme, one pulse either side.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

import nczones.pipeline.verification as verification
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import check_against_full
from tests.gcode.test_double_pass_comp import MILL, SETTINGS, check_rows_exact
from tests.machines import load_machine

#: centre offsets of radius 5 k / 8 (3-4-5 triangles, so R is a binary fraction too) and of axis-parallel radii
_OFFSETS = [(3, 4), (4, -3), (-3, -4), (-4, 3), (5, 0), (0, 5), (-5, 0), (0, -5)]


def _rot(dx: int, dy: int, quarter: int) -> tuple[int, int]:
    for _ in range(quarter):
        dx, dy = -dy, dx
    return dx, dy


def _arc(draw, x: int, y: int) -> tuple[str, int, int]:
    """An arc from (x, y) (in eighths) to the start rotated about a centre by a quarter, half or three
    quarters; I/J, or R when the chord is not a diameter (R < 0: the long way)."""
    k = draw(st.integers(1, 12))  # radius 5 k / 8 mm: from below the tool radius (1 mm) to 7.5 mm
    ox, oy = draw(st.sampled_from(_OFFSETS))
    i, j = ox * k, oy * k
    cw = draw(st.booleans())
    quarter = draw(st.sampled_from([1, 2, 3]))
    ex, ey = _rot(-i, -j, (4 - quarter) % 4 if cw else quarter)
    ex, ey = x + i + ex, y + j + ey
    code = "G2" if cw else "G3"
    if quarter != 2 and draw(st.booleans()):
        r = 5 * k * (1 if quarter == 1 else -1)
        return f"{code} X{ex / 8:g} Y{ey / 8:g} R{r / 8:g}", ex, ey
    return f"{code} X{ex / 8:g} Y{ey / 8:g} I{i / 8:g} J{j / 8:g}", ex, ey


@st.composite
def arc_contours(draw) -> str:
    """A G41/G42 contour (D1: tool radius 1 mm) of lines and arcs, an arc or a line first, G40 and again."""
    lines = ["G21 G90 G17 G54 F800"]
    x, y = 0, 0
    for _ in range(draw(st.integers(1, 2))):
        lines.append(f"G0 X{x / 8:g} Y{y / 8:g}")
        lines.append(draw(st.sampled_from(["G41 D1", "G42 D1"])))
        for _ in range(draw(st.integers(1, 7))):
            if draw(st.integers(0, 2)):
                text, x, y = _arc(draw, x, y)
            else:
                x, y = x + draw(st.integers(-80, 80)), y + draw(st.integers(-80, 80))
                text = f"G1 X{x / 8:g} Y{y / 8:g}"
            lines.append(text)
        lines.append(draw(st.sampled_from(["G40 G0 X0 Y0", "G40", "G40 G1 X1 Y1"])))
        x, y = (0, 0) if lines[-1].startswith("G40 G0") else (8, 8) if lines[-1].startswith("G40 G1") else (x, y)
    lines.append("M30")
    return "\n".join(lines) + "\n"


@SETTINGS
@given(arc_contours())
def test_compensated_arcs_are_enclosed_by_the_full_path(text):
    check_against_full(text, MILL, max_iterations=100)
    check_rows_exact(text, MILL)


def test_the_generated_contours_take_the_pass_often():
    # (the property above must not pass by declining): a fixed sample of the strategy's kinds
    taken = 0
    for text in CONTOURS.values():
        path = check_against_full(text, MILL, max_iterations=100)
        check_rows_exact(text, MILL)
        taken += path is not None
    assert taken == len(CONTOURS)


#: Contours the pass takes, each corner kind at least once (tool radius 1; G54 X100 Y50)
CONTOURS = {
    "line-arc convex, arc-line, I/J": "G21 G90 G17 G54 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG2 X20 Y0 I5 J0\n"
                                      "G1 X20 Y-10\nG40 X0 Y-20\nM30\n",
    "entry arc, arc-arc, R both ways": "G21 G90 G17 G54 F800\nG0 X0 Y-10\nG42 D1 G3 X10 Y0 I0 J10\nG1 X20 Y0\n"
                                       "G3 X30 Y10 I0 J10\nG3 X20 Y20 R10\nG2 X10 Y10 R-10\nG1 X0\nG40 G0 X-5 Y-5\nM30\n",
    "concave line-arc and arc-line": "G21 G90 G17 G54 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG3 X20 Y10 I0 J10\n"
                                     "G1 X10 Y10\nG2 X0 Y20 I0 J10\nG1 X-10 Y20\nG40 X-20\nM30\n",
    "tangent line-arc-line (a pocket's corner)": "G21 G90 G17 G54 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\n"
                                                 "G3 X15 Y5 I0 J5\nG1 X15 Y20\nG3 X10 Y25 I-5 J0\nG1 X0 Y25\n"
                                                 "G40 G0 X0 Y0\nM30\n",
    "helix under comp": "G21 G90 G17 G54 F800\nG0 X0 Y0 Z5\nG41 D1 G1 X10 Y0\nG3 X20 Y10 Z2 I0 J10\n"
                        "G1 X20 Y20 Z0\nG40 X30\nM30\n",
}


@pytest.mark.parametrize("text", [
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG3 X20 Y0 R5\nM30\n",  # a half circle's R: the full path's
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG3 X10 Y0 I5 J0\nM30\n",  # a whole turn
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG3 X10.5 Y0.5 I0 J0.5\nM30\n",  # inside, radius below the tool's
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG40\nG2 X20 Y0 R6\nM30\n",  # an arc just after G40's flush
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG3 X20 Y10 I0 J10 P2\nM30\n",  # P turns
])
def test_what_the_pass_declines_of_arcs(text):
    with pytest.raises(Declined):
        double_pass(text, MILL, max_iterations=100)
    check_against_full(text, MILL, max_iterations=100)


@pytest.mark.parametrize(("face", "safe"), [("60.999", False), ("61", None), ("61.001", True)])
def test_the_verdict_is_the_full_paths_at_a_compensated_arcs_extreme(monkeypatch, face, safe):
    # G41 on a clockwise arc about (20, 0) of radius 10: the tool outside it (radius 11), its top machine Y 61;
    # the corners before and after it concave (the held line's end and the arc's pulled back)
    zones = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             f'max = {{ X = "1000", Y = "{face}", Z = "1000" }}\n')
    machine = load_machine("mill_cutter_comp_g54", extra=zones)
    text = "G21 G90 G17 G54 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG2 X30 Y0 I10 J0\nG1 X40 Y0\nG40 G0 X50 Y-5\nM30\n"
    double_pass(text, machine, max_iterations=100)  # the pass takes it
    with_pass = verify_text(text, machine, max_iterations=100)
    with monkeypatch.context() as m:
        m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
        without = verify_text(text, machine, max_iterations=100)
    assert with_pass.verdict == without.verdict
    if safe is not None:
        assert with_pass.verdict is (Verdict.SAFE if safe else Verdict.UNSAFE)
    assert [r.message for r in with_pass.reasons] == [r.message for r in without.reasons]


@SETTINGS
@given(arc_contours(), st.integers(1, 4))
def test_the_windows_hold_the_compensated_arcs_boxes(text, window):
    # a held arc and its corner arcs cross window edges: each motion's box is the one without windows
    try:
        whole = double_pass(text, MILL, max_iterations=100)
    except Declined:
        return
    seen = []

    def same(p):
        seen.append(p.motions)
        return all(p.enclosure(k, k) == whole.enclosure(k, k) for k in range(p.row0 + 1, p.motions + 1))

    last = double_pass(text, MILL, max_iterations=100, window=window, on_window=same)
    assert same(last) and (last.motions, last.arcs, last.rapids) == (whole.motions, whole.arcs, whole.rapids)
    assert len(seen) > 1 or whole.motions <= window + 1


def test_comp_arc_program_of_the_bench_takes_the_pass():
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
    try:
        from bench_gcode import comp_arc_program
    finally:
        sys.path.pop(0)
    path = check_against_full(comp_arc_program(400), MILL, max_iterations=100)
    assert path is not None and path.arcs > 200
