"""Cutter compensation in the double pass (nczones/gcode/linuxcnc/double_comp.py) against the full path.

The pass's invariant (``check_against_full``: the same motions, kinds and corners, every exact end and every
corner arc in its row's box) over generated G41/G42 contours of straight moves: convex and concave corners,
expressions, Z moves and rapids under compensation, G40 mid-program and a new G41/G42 after it.  On machines
whose offsets are binary fractions, with words that are too, the rows are the full path's ends exactly
(``float`` of each exact end): a compensation formula off by one ulp (a radius, a side) shows there.  The
verdict with the pass is the full path's with zones touching a corner arc's extreme and an entry move's end.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.pipeline.verification as verification
from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import check_against_full
from tests.machines import load_machine

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "80"))
MILL = load_machine("mill_cutter_comp_g54")  # G54 X100 Y50, T1 2 mm
XY = load_machine("xy_cutter_comp_g54", extra='[tool_diameters]\nT1 = "0.5"\n')  # G54 X10 Y0
SETTINGS = settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                           HealthCheck.function_scoped_fixture])

#: words that are binary fractions (exact doubles): every row of the pass is then the full path's end exactly
eighths = st.integers(-160, 160).map(lambda n: f"{n / 8:g}")


@st.composite
def comp_moves(draw) -> list[str]:
    """A run of moves under compensation: X/Y lines, an expression, a lone Z, a rapid."""
    out = []
    for _ in range(draw(st.integers(1, 10))):
        kind = draw(st.sampled_from(["xy", "xy", "xy", "x", "y", "expr", "z", "rapid"]))
        x, y = draw(eighths), draw(eighths)
        out.append({"xy": f"G1 X{x} Y{y}", "x": f"X{x}", "y": f"Y{y}", "expr": f"X[#1 + {x}] Y[{y} * 2]",
                    "z": f"Z{draw(st.integers(-5, 5))}", "rapid": f"G0 X{x} Y{y}"}[kind])
    return out


@st.composite
def comp_programs(draw) -> str:
    """A G41/G42 contour (D1, or the tool in the spindle after T1 M6; or G41.1/G42.1 with a diameter), G40
    mid-program and again, an end with or without G40 and M30."""
    lines = ["G21 G90 G17 G54 F800", "#1 = 0.5"]
    spindle = draw(st.booleans())
    if spindle:
        lines.append("T1 M6")
    for _ in range(draw(st.integers(1, 3))):
        lines.append(f"G0 X{draw(eighths)} Y{draw(eighths)}")
        side = draw(st.sampled_from(["G41", "G42", "G41", "G42", "G41.1", "G42.1"]))
        if side.endswith(".1"):  # D is the diameter (a negative one: the other side)
            d = draw(st.sampled_from([" D2", " D1.5", " D[-2]"]))
        else:
            d = "" if spindle and draw(st.booleans()) else " D1"
        lines.append(f"{side}{d} G1 X{draw(eighths)} Y{draw(eighths)}")
        lines += draw(comp_moves())
        lines.append(draw(st.sampled_from(["G40 G0 X0 Y0", "G40", "G40 G1 X1 Y1", ""])))
        lines.append(draw(st.sampled_from(["G1 X2 Y-3", "", "Z1"])))
    lines.append(draw(st.sampled_from(["M30", "", "G40\nM2"])))
    return "\n".join(lines) + "\n"


def check_rows_exact(text: str, machine) -> None:
    """Every row of the pass is ``float`` of the full path's exact end (binary-fraction words and offsets)."""
    try:
        path = double_pass(text, machine, max_iterations=100)
    except Declined:
        return
    segments = list(interpret_text(text, machine, max_loop_iterations=100).segments())
    for k, seg in enumerate(segments, start=1):
        for i, col in enumerate(path.columns):
            assert col[k] == float(seg.end[i]), (k, machine.axis_names[i], col[k], seg.end[i], seg.kind)


@SETTINGS
@given(comp_programs(), st.sampled_from(["mill", "xy"]))
def test_compensated_programs_are_enclosed_by_the_full_path(text, which):
    machine = MILL if which == "mill" else XY
    check_against_full(text, machine, max_iterations=100)
    check_rows_exact(text, machine)


def test_the_pass_takes_a_contour_with_corners_of_both_kinds():
    # convex corners (arcs about the programmed corner), a concave one, a Z move and a rapid under G41, then G42
    text = ("G21 G90 G17 G54 F800\nT1 M6\nG0 X0 Y0\nG41 G1 X5 Y0\nX15 Y2\nX25 Y0\nX25 Y10\nZ-1\nX15 Y12\nG0 X5 Y10\n"
            "G40 G0 X0 Y0\nG42 D1 G1 X5 Y20\nX15 Y22\nX25 Y20\nG40 X30 Y30\nM30\n")
    path = check_against_full(text, MILL, max_iterations=100)
    assert path is not None
    assert path.arcs >= 1 and path.rapids >= 2
    check_rows_exact(text, MILL)


@pytest.mark.parametrize("text", [
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X0.5 Y0\nX10\nM30\n",  # an entry not longer than the radius
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nX10 Y0.5\nX0 Y0.5\nM30\n",  # a gouge
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG3 X20 Y0 R5\nM30\n",  # a half circle by R under comp
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG40\nG2 X20 Y0 R5\nM30\n",  # an arc just after G40
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG61 X20\nM30\n",  # a path mode under compensation
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG4 P1\nM30\n",  # a dwell under compensation
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 D7 G1 X10 Y0\nM30\n",  # a tool without a diameter
    "G21 G90 G17 F800\nG0 X0 Y0\nG41.1 G1 X10 Y0\nM30\n",  # G41.1 without D
    "G21 G90 G17 F800\nG0 X0 Y0\nG42.1 D0 G1 X10 Y0\nM30\n",  # G42.1 of diameter 0
    "G21 G90 G17 F800\nG0 X0 Y0\nG41 G1 X10 Y0\nM30\n",  # the tool in the spindle: none
    "G21 G90 G18 F800\nG0 X0 Z0\nG41 D1 G1 X10 Z0\nM30\n",  # G18
    "G20 G90 G17 F80\nG0 X0 Y0\nG41 D1 G1 X1 Y0\nM30\n",  # G20
    "G21 G91 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nM30\n",  # G91
    "G21 G90 G17 F800\nG0 X0 Y0\nG55\nG41 D1 G1 X10 Y0\nM30\n",  # an offset change since X and Y were set
])
def test_what_the_pass_declines(text):
    with pytest.raises(Declined):
        double_pass(text, MILL, max_iterations=100)
    check_against_full(text, MILL, max_iterations=100)  # (declined: nothing to hold)


def test_g41_declines_on_a_machine_without_compensation():
    machine = load_machine("mill_cutter_comp_g54", set={"machine.cutter_compensation": "none"})
    with pytest.raises(Declined):
        double_pass("G21 G90 G17 F800\nG41 D1 G1 X10 Y0\nM30\n", machine, max_iterations=100)


def _both_ways(text: str, machine, monkeypatch):
    with_pass = verify_text(text, machine, max_iterations=100)
    with monkeypatch.context() as m:
        m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
        without = verify_text(text, machine, max_iterations=100)
    return with_pass, without


#: A contour under G42 (tool radius 1, G54 X100 Y50): the entry to (5, 0) ends at (5, -1), machine (105, 49); the
#: convex corner at (25, 0) is an arc about it from (25, -1) to (26, 0), whose extreme x is machine 126.
_CONTOUR = "G21 G90 G17 G54 F800\nG0 X0 Y0\nG42 D1 G1 X5 Y0\nX25 Y0\nX25 Y20\nX5 Y20\nG40 G0 X0 Y0\nM30\n"


@pytest.mark.parametrize(("x_max", "y_top", "safe"), [
    ("126", "48.999", True), ("125.999", "48.999", False), ("126", "49.001", False), ("126.001", "48.999", True),
    ("126", "49", None)])
def test_the_verdict_is_the_full_paths_at_a_corner_arc_and_an_entry(monkeypatch, x_max, y_top, safe):
    # the allowed box's face at the corner arc's extreme; a forbidden box under the entry move's end
    zones = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             f'max = {{ X = "{x_max}", Y = "1000", Z = "1000" }}\n'
             '[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\n'
             f'min = {{ X = "104", Y = "40" }}\nmax = {{ X = "106", Y = "{y_top}" }}\n')
    machine = load_machine("mill_cutter_comp_g54", extra=zones)
    with_pass, without = _both_ways(_CONTOUR, machine, monkeypatch)
    assert with_pass.verdict == without.verdict
    if safe is not None:
        assert with_pass.verdict is (Verdict.SAFE if safe else Verdict.UNSAFE)
    assert [r.message for r in with_pass.reasons] == [r.message for r in without.reasons]
    assert with_pass.notes == without.notes


def test_comp_program_of_the_bench_takes_the_pass():
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
    try:
        from bench_gcode import comp_program
    finally:
        sys.path.pop(0)
    text = comp_program(400)
    path = check_against_full(text, MILL, max_iterations=100)
    assert path is not None and path.arcs > 50


@SETTINGS
@given(comp_programs(), st.integers(1, 4))
def test_the_windows_are_the_rows_and_boxes_of_the_pass_without_windows(text, window):
    # corner arcs and flushed moves cross window edges: each motion's box (its corner arc's included) is the same
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


@settings(max_examples=max(EXAMPLES // 4, 5), deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(comp_programs(), st.integers(70, 130), st.integers(30, 70), st.integers(1, 12), st.sampled_from(["0", "0.5"]))
def test_the_verdict_is_the_full_paths_with_a_forbidden_box(monkeypatch, text, x, y, size, margin):
    zones = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             'max = { X = "1000", Y = "1000", Z = "1000" }\n[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\n'
             f'min = {{ X = "{x}", Y = "{y}" }}\nmax = {{ X = "{x + size}", Y = "{y + size}" }}\n')
    machine = load_machine("mill_cutter_comp_g54", extra=zones)
    try:
        with_pass = verify_text(text, machine, max_iterations=100, margin=margin)
    except Exception as exc:  # noqa: BLE001  # a G-code error (a gouge): the same error without the pass
        with monkeypatch.context() as m:
            m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
            with pytest.raises(type(exc)):
                verify_text(text, machine, max_iterations=100, margin=margin)
        return
    with monkeypatch.context() as m:
        m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
        without = verify_text(text, machine, max_iterations=100, margin=margin)
    assert with_pass.verdict == without.verdict
    assert [(v.line, v.zone) for v in with_pass.violations] == [(v.line, v.zone) for v in without.violations]
    assert [r.message for r in with_pass.reasons] == [r.message for r in without.reasons]
    assert with_pass.notes == without.notes


#: Seams the pass takes: G40 and G41/G42 again, loops and subs, Z and rapids under compensation, G61, no M30,
#: a computed D, arcs before and after, tool changes before G41 (each checked against the full path, rows exact)
SEAMS = {
    'g40 then g41': 'G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nX20 Y5\nG40\nG42 D1 G1 X30 Y0\nX40 Y3\nM30\n',
    'start offset': 'G21 G90 G17 F800\nG55\nG41 D1 G1 X10 Y0\nX20 Y5\nG40 X0\nM30\n',
    'loop': 'G21 G90 G17 F800\n#1=0\nG0 X0 Y0\no1 while [#1 LT 3]\nG41 D1 G1 X[10+#1] Y0\nX20 Y[5+#1]\nX25 Y-2\nG40 G0 X0 Y0\n#1=[#1+1]\no1 endwhile\nM30\n',
    'sub': 'G21 G90 G17 F800\no10 sub\nG1 X[#1] Y[#2]\nX[#1+10] Y[#2+3]\no10 endsub\nG0 X0 Y0\nG41 D1\no10 call [5] [0]\no10 call [20] [1]\nG40 G0 X0 Y0\nM30\n',
    'g41 block no move': 'G21 G90 G17 F800\nG0 X0 Y0\nG41 D1\nG1 X10 Y0\nX10 Y10\nX0 Y10\nG40 X-5\nM30\n',
    'z only and concave': 'G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nZ-1\nX10 Y10\nZ0\nX0 Y10\nG40 X-5\nM30\n',
    'rapid corners': 'G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G0 X10 Y0\nX10 Y-10\nG1 X20 Y-10\nG0 X20 Y-20\nG40 X0\nM30\n',
    'g61 then comp': 'G21 G90 G17 G61 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nX20 Y-5\nX30 Y0\nG40 X40\nG64\nX0\nM30\n',
    'no m30 held': 'G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nX20 Y-5\n',
    'g41 G17 same block': 'G21 G90 F800\nG0 X0 Y0\nG17 G41 D1 G1 X10 Y0\nX20 Y-5\nG40 X30\nM30\n',
    'expr D': 'G21 G90 G17 F800\n#3=1\nG0 X0 Y0\nG41 D[#3] G1 X10 Y0\nX20 Y-5\nG40 X30\nM30\n',
    'arc before comp': 'G21 G90 G17 F800\nG0 X0 Y0\nG2 X10 Y0 R6\nG41 D1 G1 X20 Y0\nX30 Y5\nG40 X40\nM30\n',
    'arc after comp': 'G21 G90 G17 F800\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nX20 Y5\nG40 G1 X30 Y0\nG2 X40 Y0 R6\nM30\n',
    'T M6 same block': 'G21 G90 G17 F800\nG0 X0 Y0\nT1 M6 G41 G1 X10 Y0\nX20 Y-5\nG40 X30\nM30\n',
    'T0 M6 then D1': 'G21 G90 G17 F800\nT1 M6\nT0 M6\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nX20 Y-5\nG40 X30\nM30\n',
}


@pytest.mark.parametrize("name", sorted(SEAMS))
def test_seams_the_pass_takes(name):
    assert check_against_full(SEAMS[name], MILL, max_iterations=100) is not None
    check_rows_exact(SEAMS[name], MILL)
