"""A violation's point in the program's coordinates (issue 37: ``point_program``).

The prover reports the witness ``point`` in machine coordinates.  The program's coordinates of that point
are the inverse of what the control adds at the violating block: the work offset (G54..), the G92/G52
shift, an XY rotation (LinuxCNC ``G10 L2 R``, Fanuc ``G68``), lathe diameter mode and the tool offsets
(the program point is where the tool tip is).  Every expectation here is derived in the test from the
offsets the test writes (the machine text below and the program's G10/G92/G52 words), never read back
from the code under test; a second, offset-free check: the witness of a line lies on the programmed line,
so in program coordinates it is ``P0 + t (P1 - P0)`` with ``P0``, ``P1`` the words of the program and ``t``
the violation's exact segment parameter.
"""

from __future__ import annotations

import json
import math
import re
from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.exact import format_decimal
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.report import render_report
from tests.machines import machine_text

# A LinuxCNC mill whose offsets the test states: G54 X150 Y100 Z100, tool length H1 = 120 (G43 moves
# machine Z up by it: machine Z = program Z + G54 Z + G92 Z + 120).  Travel X 0..600.
MILL = machine_text("report_mill")

G54 = (F(150), F(100), F(100))
H1 = F(120)


def _line_point(p0, p1, t):
    """The point at parameter t of the line p0 -> p1 (program coordinates, as the program writes them)."""
    return tuple(a + t * (b - a) for a, b in zip(p0, p1))


def _only(result, text: str | None = None):
    """The violation of the block written ``text`` (the only one when None)."""
    assert result.verdict.label == "unsafe", result.reasons
    if text is None:
        assert len(result.violations) == 1
        v = result.violations[0]
    else:
        v = next(v for v in result.violations if v.source == text)
    assert v.parameter_exact and v.point == v.path_point
    return v


def _pp(v):
    assert v.point_program is not None, v
    return tuple(x for _a, x in v.point_program)


# --------------------------------------------------------------------------- LinuxCNC mill: G54 + G92 + G43


def _mill_g92_program(lines_before: int = 0, hash_param: bool = False) -> tuple[str, tuple, tuple]:
    """G54 + G43 H1, G92 X10 Y20 at program X30 Y40 (so the G92 shift is X30-10 = 20, Y40-20 = 20, Z 0),
    then a line from program X0 Y0 Z10 to X500 Y0 Z10 that leaves travel at machine X600.  ``lines_before``
    safe plain lines first (the vectorized tier takes them); ``hash_param`` writes the end through a
    parameter (the double pass)."""
    pre = [f"G1 X{i % 10} Y{i % 7} Z10" for i in range(lines_before)]
    end = "G1 X[#1] Y0 Z10" if hash_param else "G1 X500 Y0 Z10"
    text = "\n".join(["G21 G90 G54 G43 H1 F1000", "G0 X30 Y40 Z10", "G92 X10 Y20", *pre, "G1 X0 Y0 Z10",
                      *(["#1 = 500"] if hash_param else []), end, *pre, "M30"]) + "\n"
    return text, (F(0), F(0), F(10)), (F(500), F(0), F(10))


def _check_mill_g92(r, p0, p1):
    v = _only(r, next(x.source for x in r.violations if "X500" in x.source or "#1" in x.source))
    shift = (F(20), F(20), F(0))  # G92: the program point (30, 40) becomes (10, 20)
    machine = tuple(x for _a, x in v.point)
    expected = (machine[0] - G54[0] - shift[0], machine[1] - G54[1] - shift[1], machine[2] - G54[2] - shift[2] - H1)
    assert _pp(v) == expected
    assert _pp(v) == _line_point(p0, p1, v.parameter)
    assert machine[0] > 600  # outside travel: X 500 + 150 + 20 = 670 at the end


def test_mill_g54_g92_tool_length_short_program():
    m = parse_machine(MILL)
    text, p0, p1 = _mill_g92_program()
    r = verify_text(text, m, file="p.ngc")
    _check_mill_g92(r, p0, p1)
    # JSON and SARIF carry the same exact program point
    doc = json.loads(render_report(r, "json", machine=m, deterministic=True))["violations"][0]
    sarif = json.loads(render_report(r, "sarif", machine=m, deterministic=True))["runs"][0]["results"][0]
    pp = dict(r.violations[0].point_program)
    assert doc["point_program_exact"] == sarif["properties"]["pointProgramExact"] == {a: str(x) for a, x in pp.items()}
    assert doc["program_frame"]["work"] == "G54" and doc["point_program_missing"] == ""


def test_mill_g54_g92_in_the_vectorized_tier():
    """More than 512 motions: the plain lines before and after run in column chunks, which carry the frame."""
    m = parse_machine(MILL)
    text, p0, p1 = _mill_g92_program(lines_before=300)
    columns = [c for c in interpret_text(text, m) if getattr(c, "scale", None) is not None]
    assert columns and all(c.frame is not None and c.frame.offset == (F(170), F(120), F(220)) for c in columns)
    r = verify_text(text, m, file="p.ngc")
    assert dict(r.stats)["segments"] > 512
    _check_mill_g92(r, p0, p1)


def test_mill_g54_g92_with_parameters():
    """'#' in the text: the double pass is tried first; the violation (and its frame) comes from the full path."""
    m = parse_machine(MILL)
    text, p0, p1 = _mill_g92_program(lines_before=300, hash_param=True)
    _check_mill_g92(verify_text(text, m, file="p.ngc"), p0, p1)


def test_mill_rotation_g10_l2_r():
    """G10 L2 P1 R30: LinuxCNC rotates (program + G92) about the G54 origin, then adds G54 and the tool length
    (emccanon ``rotate_and_offset_pos``).  G92 Z-5 at program Z10 shifts Z by 15, X and Y by 0 (G92 X0 Y0 at
    X0 Y0).  The inverse, in the test: rotate (machine - G54) by -30° and take off the shifts."""
    m = parse_machine(MILL)
    text = "G21 G90 G10 L2 P1 R30\nG54 G43 H1 F1000\nG0 X0 Y0 Z10\nG92 X0 Y0 Z-5\nG1 X560 Y0 Z-5\nM30\n"
    v = _only(verify_text(text, m, file="p.ngc"))
    mx, my, mz = (float(x) for _a, x in v.point)
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    dx, dy = mx - 150, my - 100
    px, py = c * dx + s * dy, -s * dx + c * dy
    got = [float(x) for x in _pp(v)]
    assert abs(got[0] - px) < 1e-9 and abs(got[1] - py) < 1e-9
    assert _pp(v)[2] == F(mz) - G54[2] - F(15) - H1
    # on the programmed line X0 Y0 -> X560 Y0 (Z -5): Y is 0 and X = 560 t, to the rotation's rounding
    assert abs(got[1]) < 1e-9 and abs(got[0] - 560 * float(v.parameter)) < 1e-9
    assert v.frame is not None and not v.frame.exact
    doc = json.loads(render_report(verify_text(text, m, file="p.ngc"), "json", machine=m, deterministic=True))
    frame = doc["violations"][0]["program_frame"]
    assert frame["rotation"] == {"axes": ["X", "Y"], "degrees": "30"} and frame["exact"] is False
    text_report = render_report(verify_text(text, m, file="p.ngc"), "text", machine=m, deterministic=True)
    assert "rotated 30° in XY; approximate" in text_report


def test_inch_program_point_is_in_inches():
    """G20: the program writes inches; machine = 25.4 * program + offsets."""
    m = parse_machine(MILL)
    text = "G20 G90 G54 F40\nG0 X0 Y0 Z0\nG1 X20 Y0 Z0\nM30\n"
    v = _only(verify_text(text, m, file="p.ngc"))
    mx, my, mz = (x for _a, x in v.point)
    assert _pp(v) == ((mx - 150) / F("25.4"), (my - 100) / F("25.4"), (mz - 100) / F("25.4"))
    assert _pp(v) == _line_point((F(0), F(0), F(0)), (F(20), F(0), F(0)), v.parameter)


# --------------------------------------------------------------------------- lathes in diameter


LATHE = machine_text("report_lathe")


def test_linuxcnc_lathe_diameter_with_work_shift():
    """G7 (the machine starts in it): X words are diameters, machine X = X/2 + G54 X (+ G92).  G92 Z0 at program
    Z5 shifts Z by 5; G54 X10 Z200.  The line from Ø40 Z5 to Ø300 Z-5 leaves travel at machine X150."""
    m = parse_machine(LATHE)
    text = "G18 G21 G90 G54 F100\nG0 X40 Z5\nG92 Z0\nG1 X300 Z-10\nM30\n"
    v = _only(verify_text(text, m, file="p.ngc"))
    mx, mz = (x for _a, x in v.point)
    assert mx > 150
    assert _pp(v) == (2 * (mx - 10), mz - 200 - 5)
    assert _pp(v) == _line_point((F(40), F(0)), (F(300), F(-10)), v.parameter)
    assert v.frame is not None and v.frame.diameter == ("X",)


FANUC_LATHE = machine_text("report_fanuc_lathe")


def test_fanuc_lathe_diameter_with_work_shift_and_tool_offset():
    """Fanuc lathe, X in diameter (machine X = X/2 + offsets).  Before any tool, at program Ø20 Z5 the machine
    stands at X10 Z205 (G54 X0 Z200); ``G50 X30. Z0`` makes that point read Ø30 Z0: a shift of X 10 - 15 = -5
    (radius), Z 205 - 200 - 0 = 5.  T0101 then adds tool offset 1 (X80 Z50).  So machine X = X/2 - 5 + 80,
    Z = Z + 200 + 5 + 50, and the program point (the tool tip) is Ø = 2 (X - 75), Z - 255."""
    m = parse_machine(FANUC_LATHE)
    text = "G21 G18 G99 G54\nG0 X20. Z5.\nG50 X30. Z0\nT0101\nG0 X20. Z5.\nG1 X200. Z-5. F0.2\nM30\n"
    r = verify_text(text, m, file="p.nc")
    v = _only(r, "G1 X200. Z-5. F0.2")
    mx, mz = (x for _a, x in v.point)
    assert mx > 150
    assert _pp(v) == (2 * (mx - 75), mz - 255)
    assert _pp(v) == _line_point((F(20), F(5)), (F(200), F(-5)), v.parameter)
    text_report = render_report(r, "text", machine=m, deterministic=True)
    assert "(program coordinates: G54, X as diameter)" in text_report
    # the HTML table shows the same point under the machine point, from the page's data
    page = render_report(r, "html", machine=m, deterministic=True)
    shown = re.findall(r'<span class="point-program" data-point-program="1">([^<]*)</span>', page)
    # X exact (a short decimal); Z a repeating decimal: rounded to the 0.001 pulse and marked ≈
    z = mz - 255
    assert z.denominator % 3 == 0
    assert shown == [f"X{format_decimal(2 * (mx - 75))} Z≈{format_decimal(F(round(z * 1000), 1000))} "
                     "(program coordinates: G54, X as diameter)"]


# --------------------------------------------------------------------------- Fanuc mill: G52 + G68


FANUC_MILL = MILL.replace('name = "test mill"', 'name = "test Fanuc mill"\ndialect = "fanuc"')


def test_fanuc_mill_g52_and_g68_rotation():
    """Fanuc: machine = centre + R(program - centre) + G54 + G52 (+ tool length), G68 X10 Y0 R90 rotating about
    program (10, 0), G52 X5 Y5 a local shift.  The test inverts it: program = centre + R(-90)(machine - G54 -
    G52 - centre); a quarter turn is exact (cos 90 = 0, sin 90 = 1), so the values are exact."""
    m = parse_machine(FANUC_MILL)
    text = "G21 G90 G17 G54 G43 H1 F1000\nG52 X5. Y5.\nG0 X0 Y0 Z10.\nG68 X10. Y0 R90.\nG1 X10. Y0 Z10.\n" \
           "G1 X10. Y-500. Z10.\nM30\n"
    v = _only(verify_text(text, m, file="p.nc"), "G1 X10. Y-500. Z10.")
    mx, my, mz = (x for _a, x in v.point)
    dx, dy = mx - 150 - 5 - 10, my - 100 - 5 - 0  # machine - G54 - G52 - centre
    expected = (10 + dy, 0 - dx, mz - 100 - 120)  # rotate by -90: (x, y) -> (y, -x)
    got = _pp(v)
    assert all(abs(g - e) < F(1, 10**9) for g, e in zip(got, expected))
    assert all(abs(g - e) < F(1, 10**9) for g, e in zip(got, _line_point((F(10), F(0), F(10)),
                                                                          (F(10), F(-500), F(10)), v.parameter)))


def test_fanuc_scaling_gives_no_program_point():
    """G51 scaling is not inverted: the report says so instead of a wrong point."""
    m = parse_machine(FANUC_MILL)
    text = "G21 G90 G17 G54 F1000\nG0 X0 Y0 Z10.\nG51 X0 Y0 P2000\nG1 X400. Y0\nM30\n"
    r = verify_text(text, m, file="p.nc")
    v = _only(r)  # X400 scaled by 2 from X0: machine X 950
    assert v.point_program is None
    doc = json.loads(render_report(r, "json", machine=m, deterministic=True))
    assert doc["violations"][0]["point_program"] is None
    assert "scaling" in doc["violations"][0]["point_program_missing"]


# --------------------------------------------------------------------------- metamorphic


@settings(max_examples=15, deadline=None)
@given(dx=st.integers(-40, 40), dy=st.integers(-40, 40), dz=st.integers(-20, 20))
def test_shifting_the_work_offset_and_the_program_keeps_the_machine_points(dx, dy, dz):
    """G10 L2 P1 moves G54 by d and the program's words move by -d: every machine point (the witness included)
    stays; point_program moves by -d."""
    m = parse_machine(MILL)

    def run(d):
        text = (f"G21 G90 G10 L2 P1 X{150 + d[0]} Y{100 + d[1]} Z{100 + d[2]}\nG54 G43 H1 F1000\n"
                f"G0 X{-d[0]} Y{-d[1]} Z{10 - d[2]}\nG1 X{500 - d[0]} Y{20 - d[1]} Z{10 - d[2]}\nM30\n")
        return _only(verify_text(text, m, file="p.ngc"))

    a, b = run((0, 0, 0)), run((dx, dy, dz))
    assert a.point == b.point and a.first_exit == b.first_exit
    assert _pp(b) == tuple(x - d for x, d in zip(_pp(a), (dx, dy, dz)))


def test_fanuc_mill_g52_in_the_vectorized_tier():
    """Fanuc, more than 512 motions in column chunks: G54 X150 Y100 Z100, G52 X5 Y-5 (a local shift), G43 H1
    (120): the program point of the witness is machine - (155, 95, 220), on the programmed line."""
    m = parse_machine(FANUC_MILL.replace('max = { X = "600", Y = "400", Z = "400" }',
                                         'max = { X = "600", Y = "400", Z = "600" }'))
    pre = [f"G01 X{i % 10}. Y{i % 7}." for i in range(300)]
    text = "\n".join(["G21 G90 G17 G54 G43 H1 F1000", "G52 X5. Y-5.", "G00 X0 Y0 Z10.", *pre, "G01 X0 Y0",
                      "G01 X500. Y0", *pre, "M30"]) + "\n"
    columns = [c for c in interpret_text(text, m) if getattr(c, "scale", None) is not None]
    assert columns and all(c.frame is not None and c.frame.offset == (F(155), F(95), F(220)) for c in columns)
    r = verify_text(text, m, file="p.nc")
    assert dict(r.stats)["segments"] > 512
    v = _only(r, "G01 X500. Y0")
    mx, my, mz = (x for _a, x in v.point)
    assert _pp(v) == (mx - 155, my - 95, mz - 220)
    assert _pp(v) == _line_point((F(0), F(0), F(10)), (F(500), F(0), F(10)), v.parameter)
