"""Corner blending (issue 35, specs/path-modes.md): the path the machine really moves, proved.

Every case is a program whose programmed path stays in the allowed set while a rounded corner may not.  The
expected verdicts come from the planner's rules as specs/path-modes.md derives them from LinuxCNC's sources
(``tp.c``/``blendmath.c``: a blend uses at most half of each motion; ``G64 P p`` keeps within p of the path,
its Q, which defaults to P, merges within q) and from the Fanuc manuals (cutting mode G64 vs exact stop
G61/G09), never from the code under test.
"""

from __future__ import annotations

from decimal import Decimal

import pytest

from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.prover.blend import BLEND_CODE, CornerCheck

HEAD = """
[machine]
name = "blend test"
axes = ["X", "Y", "Z"]
pulse = "0.001"
monitor_period_ms = "5"
tool_axis = "Z"
{extra}
[machine.rapid]
X = "10000"
Y = "10000"
Z = "10000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
"""

TABLE = """
[[zones]]
name = "table"
kind = "box"
min = {{ X = "-10", Y = "-10", Z = "-50" }}
max = {{ X = "200", Y = "200", Z = "50" }}
[[zones]]
name = "clamp"
kind = "box"
forbid = true
min = {{ X = "{x0}", Y = "{y0}" }}
max = {{ X = "{x1}", Y = "{y1}" }}
"""


def machine(extra: str = "", x0="95", y0="1", x1="99", y1="5", zones: str | None = None):
    return parse_machine(HEAD.format(extra=extra) + (zones if zones is not None else
                                                    TABLE.format(x0=x0, y0=y0, x1=x1, y1=y1)))


def run(program: str, m, **kw):
    return verify_text(program, m, **kw)


def blend_reasons(result):
    return [r for r in result.reasons if r.code == BLEND_CODE]


# The L corner of the issue: X0 Y0 -> X100 Y0 -> X100 Y100 passes the forbidden box X95..99 Y1..5 by 1 mm.
# G64 without P: a blend may use half of each motion, so it may pass every point C + a (M1 - C) + b (M2 - C)
# (C = X100 Y0, M1 = X50 Y0, M2 = X100 Y50, a and b in [0, 1]), X50..100 Y0..50: the box is in it.
L_CORNER = "G1 F100 X100 Y0\nG1 X100 Y100\n"


def test_the_l_corner_is_not_safe_in_g64_linuxcnc():
    r = run(L_CORNER, machine())
    assert r.verdict.label == "unknown" and not r.violations
    (why,) = blend_reasons(r)
    assert "lines 1 and 2" in why.message and "`clamp`" in why.message and why.span.line == 2


@pytest.mark.parametrize("mode", ["G61", "G61.1"])
def test_the_l_corner_is_safe_in_exact_path_and_exact_stop(mode):
    assert run(f"{mode}\n" + L_CORNER, machine()).verdict.label == "safe"
    # the machine file's start-up mode (the INI's RS274NGC_STARTUP_CODE) does the same
    assert run(L_CORNER, machine(f'path_mode = "{mode}"')).verdict.label == "safe"


def test_the_mode_of_the_first_motion_decides_its_corner():
    # LinuxCNC: the blend with the next motion is the previous segment's termination condition
    # (tp.c tpHandleBlendArc/tpChooseBestBlend read prev_tc->term_cond), set when that segment was queued.
    assert run("G1 F100 X100 Y0\nG61\nG1 X100 Y100\n", machine()).verdict.label == "unknown"
    assert run("G61\nG1 F100 X100 Y0\nG64\nG1 X100 Y100\n", machine()).verdict.label == "safe"
    # a dwell waits for the motion to end: no corner
    assert run("G1 F100 X100 Y0\nG4 P0.5\nG1 X100 Y100\n", machine()).verdict.label == "safe"


def test_fanuc_cutting_mode_vs_exact_stop():
    fanuc = 'dialect = "fanuc"'
    prog = "G01 F100. X100. Y0\nG01 X100. Y100.\n"
    r = run(prog, machine(fanuc))
    assert r.verdict.label == "unknown" and "path_tolerance" in blend_reasons(r)[0].message
    assert run("G61\n" + prog, machine(fanuc)).verdict.label == "safe"
    # G09 stops exactly at the end of its own block only
    assert run("G09 G01 F100. X100. Y0\nG01 X100. Y100.\n", machine(fanuc)).verdict.label == "safe"
    assert run("G01 F100. X100. Y0\nG09 G01 X100. Y100.\n", machine(fanuc)).verdict.label == "unknown"
    # G63 (tapping mode) and G62 (corner override) are cutting modes too
    assert run("G61\nG63\n" + prog, machine(fanuc)).verdict.label == "unknown"
    # with the machine's bound: within 0.01 of the path, the clamp 1 mm away
    assert run(prog, machine(fanuc + '\npath_tolerance = "0.01"')).verdict.label == "safe"


# A clamp whose corner is d from the path's corner on both axes: X90..(100-d) Y d..10.  G64 P0.01 keeps the
# path within P + Q = 0.02 (Q defaults to P: interp_convert.cc convert_control_mode), a box distance of
# 0.02 on each axis (the box of half-width 0.02 touches the clamp: allowed).
@pytest.mark.parametrize("d, expected", [("0.02", "safe"), ("0.005", "unknown")])
def test_g64_p_tolerance_enlarges_the_margin(d, expected):
    x1 = str(Decimal(100) - Decimal(d))
    m = machine(x0="90", y0=d, x1=x1, y1="10")
    assert run("G64 P0.01\n" + L_CORNER, m).verdict.label == expected
    assert run(L_CORNER, machine('path_tolerance = "0.01"', x0="90", y0=d, x1=x1, y1="10")).verdict.label == expected
    assert run("G61\n" + L_CORNER, m).verdict.label == "safe"


def test_g64_p_with_q0_uses_the_tolerance_alone():
    # Q0: no naive-CAM merging; the clamp 0.015 away fits P0.01 but not P + Q = 0.02
    m = machine(x0="90", y0="0.015", x1="99.985", y1="10")
    assert run("G64 P0.01 Q0\n" + L_CORNER, m).verdict.label == "safe"
    assert run("G64 P0.01\n" + L_CORNER, m).verdict.label == "unknown"


STEPPED = """
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "0"
regions = [{ upto = "50", min = "0", max = "100" }, { upto = "100", min = "0", max = "20" }]
"""


def test_a_stepped_tables_step():
    # X40 Y90 -> X40 Y10 -> X90 Y10: the corner's region reaches X65 Y50, above the step's Y max 20 past X50
    prog = "G0 X40 Y90\nG1 F100 Y10\nG1 X90\n"
    m = machine(zones=STEPPED)
    r = run(prog, m)
    assert r.verdict.label == "unknown" and "lines 2 and 3" in blend_reasons(r)[0].message
    assert run("G61\n" + prog, m).verdict.label == "safe"


POLYGON = """
[[zones]]
name = "floor"
kind = "polygon"
plane = ["X", "Y"]
vertices = [["0", "0"], ["100", "0"], ["100", "40"], ["40", "40"], ["40", "100"], ["0", "100"]]
"""


def test_a_polygons_reflex_vertex():
    # X20 Y90 -> X20 Y20 -> X90 Y20 turns round the reflex vertex X40 Y40: the region reaches X55 Y55
    prog = "G0 X20 Y90\nG1 F100 Y20\nG1 X90\n"
    m = machine(zones=POLYGON)
    assert run(prog, m).verdict.label == "unknown"
    assert run("G61\n" + prog, m).verdict.label == "safe"


TIP = """
[tool_lengths]
H1 = "100"
[[zones]]
name = "vise"
kind = "box"
forbid = true
point = "tip"
min = { X = "95", Z = "1" }
max = { X = "99", Z = "5" }
"""


def test_a_tip_zone():
    # in XZ: the tip goes X100 Z0 -> X100 Z100 (machine Z = tip Z + 100); the vise's corner is 1 mm inside
    prog = "G43 H1\nG1 F100 X100 Z0\nG1 X100 Z100\n"
    m = machine(zones=TIP)
    assert run(prog, m).verdict.label == "unknown"
    assert run("G61\n" + prog, m).verdict.label == "safe"


def test_a_certain_violation_stays_unsafe():
    r = run("G1 F100 X97 Y3\nG1 X100 Y100\n", machine())
    assert r.verdict.label == "unsafe"


def filler(n: int) -> str:
    # n short moves far from the clamp (X10..60 Y150..160): their corners fit
    return "".join(f"G1 X{10 + k % 50} Y{150 + k % 10}\n" for k in range(n))


def test_the_vectorized_tier(monkeypatch):
    screened = []
    real = CornerCheck._screen

    def spy(self, chunk, *args, **kw):
        screened.append(len(chunk))
        return real(self, chunk, *args, **kw)

    monkeypatch.setattr(CornerCheck, "_screen", spy)
    body = "G1 F100 X10 Y150\n" + filler(700) + "G1 X0 Y0\n" + L_CORNER + filler(700)
    r = run(body, machine())
    assert screened, "the column chunks were screened"
    assert r.verdict.label == "unknown" and len(blend_reasons(r)) == 1
    assert "lines 703 and 704" in blend_reasons(r)[0].message
    assert run("G61\n" + body, machine()).verdict.label == "safe"


def test_with_parameters_the_double_pass_does_not_prove_the_corner():
    # '#': LinuxCNC programs with parameters try the double pass first; its boxes must hold the corners too
    prog = "G21 G90 G54\n#1 = 100\nG1 F100 X#1 Y0\nG1 X#1 Y100\n"
    assert run(prog, machine()).verdict.label == "unknown"
    assert run("G61\n" + prog, machine()).verdict.label == "safe"
    big = "G21 G90 G54\n#1 = 100\nG1 F100 X10 Y150\n" + filler(700) + "G1 X0 Y0\nG1 X#1 Y0\nG1 X#1 Y100\n" + filler(700)
    assert run(big, machine()).verdict.label == "unknown"
    assert run("G61\n" + big, machine()).verdict.label == "safe"


def test_rapids_blend_too():
    assert run("G0 X100 Y0\nG0 X100 Y100\n", machine()).verdict.label == "unknown"


def test_an_arc_corner():
    # X50 Y0 -> X100 Y0, then a quarter circle about X100 Y50 to X150 Y50 (ccw): the corner at X100 Y0 is
    # tangent; the clamp is below the line, the region (half of each motion) stays at Y0 and above
    m = machine(x0="60", y0="-10", x1="99", y1="-1")
    prog = "G0 X50 Y0\nG1 F100 X100\nG3 X150 Y50 I0 J50\n"
    assert run(prog, m).verdict.label == "safe"
    # X100 Y0 -> the lower half circle about X110 Y0 (ccw: it starts downwards, a 90 degree corner); its first
    # half runs to X110 Y-10, so the region holds points of the line's half moved down along the arc's
    # start: the clamp X90..98 Y-5..-1, below the line and left of the arc, is in it
    m2 = machine(x0="90", y0="-5", x1="98", y1="-1")
    prog2 = "G0 X50 Y0\nG1 F100 X100\nG3 X120 Y0 I10 J0\n"
    assert run(prog2, m2).verdict.label == "unknown"
    assert run("G61\n" + prog2, m2).verdict.label == "safe"
