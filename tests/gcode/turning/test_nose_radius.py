"""The lathe tool's nose radius (``[tool_offsets] R``, ``tip``) enlarges the tool's reach for tip zones.

[0i-T] FANUC Series 0i-TD Operator's Manual B-64304EN, "Imaginary tool nose": the offsets measure to the
imaginary tool nose, the nose centre for tip 0/9, a point R away on each axis of the turning plane (a
corner of the square around the nose, tips 1-4) or on one axis (a side, 5-8) otherwise.  The cutting edge
is the nose circle of radius R around the centre; a proof must keep the circle out of the jaws.  nczones
proves the square of half-width R (tip 0/9) or 2R (1-8) around the imaginary tip clear
(``nczones.prover.nose``), which contains the circle whatever the machine's tip numbering.

Before the fix the reproducer below (nose centre 0.5 mm above the jaw face, R 0.8: the edge 0.3 mm
inside the jaw) was proved ``safe``.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.exact import format_decimal
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.turning.helpers import lathe

F = Fraction

# The jaw is a tip zone: radius 25..32, Z 100..140 (machine coordinates = program coordinates: no offsets).
JAWS = """
[[zones]]
name = "travel"
kind = "box"
min = { X = "0", Z = "0" }
max = { X = "250", Z = "700" }

[[zones]]
name = "jaws"
kind = "box"
forbid = true
point = "tip"
min = { X = "25", Z = "100" }
max = { X = "32", Z = "140" }
"""


def _machine(radius: str = "0.8", tip: int = 0, zones: str = JAWS):
    return lathe(zones=zones, offsets=f'1 = {{ X = "0", Z = "0", R = "{radius}", tip = {tip} }}')


def _pass(x_diameter: str, moves: int = 0) -> str:
    """Tool 1 along the jaw's top face at diameter ``x_diameter`` (radius half of it), Z 150 -> 120."""
    tail = "".join(f"G01 X{200 + (i % 2)}. Z{300 + (i % 5)}.\n" for i in range(moves))
    return f"G00 X200. Z200.\nT0101\nG00 X{x_diameter} Z150.\nG01 Z120. F0.2\nG00 X200.\nZ200.\n{tail}M30\n"


def test_nose_centre_half_a_millimetre_from_the_jaw_face_is_unsafe():
    # tip 0: the offsets measure to the nose centre.  X65. is radius 32.5, 0.5 above the jaw's face X32; the
    # nose circle (R 0.8) reaches down to 31.7, 0.3 mm into the jaw.
    r = verify_text(_pass("65."), _machine())
    assert r.verdict is Verdict.UNSAFE and {v.zone for v in r.violations} == {"jaws"}
    assert r.violations[0].span.line == 4
    assert any("nose radius" in n for n in r.notes)
    # without a nose radius the same pass is safe (the centre point alone stays 0.5 mm clear)
    assert verify_text(_pass("65."), _machine(radius="0")).verdict is Verdict.SAFE
    # 0.9 above the face (radius 32.9): the circle stays 0.1 clear
    assert verify_text(_pass("65.8"), _machine()).verdict is Verdict.SAFE


def test_the_vectorized_tier_sees_the_nose_too():
    # the same pass in a program of more than 512 motions
    assert verify_text(_pass("65.", moves=600), _machine()).verdict is Verdict.UNSAFE
    assert verify_text(_pass("65.", moves=600), _machine(radius="0")).verdict is Verdict.SAFE


def test_tip_direction_three():
    # tip 3: the nose centre is R away from the imaginary tip on both X and Z.  With R 0.8 and the tip 1.2
    # above the face (radius 33.2) a centre 0.8 lower (32.4) puts the edge at 31.6, inside the jaw: unsafe.
    # 1.7 above (radius 33.7): the circle lies within 2R = 1.6 of the tip on each axis, it cannot reach 32.
    m = _machine(tip=3)
    assert verify_text(_pass("66.4"), m).verdict is Verdict.UNSAFE
    assert verify_text(_pass("67.4"), m).verdict is Verdict.SAFE
    # the same 1.2 mm with tip 0 (the centre at the tip) is clear of the jaw: 33.2 - 0.8 = 32.4 > 32
    assert verify_text(_pass("66.4"), _machine(tip=0)).verdict is Verdict.SAFE


def test_a_polygon_tip_zone_grows_by_the_nose_too():
    # the tailstock as a polygon in the ZX plane: its top X 15 from Z 320 on; a pass at radius 15.5 (0.5 above)
    zones = JAWS.replace('name = "jaws"', 'name = "jaws"').rstrip() + """

[[zones]]
name = "tailstock"
kind = "polygon"
forbid = true
point = "tip"
plane = ["Z", "X"]
vertices = [["300", "0"], ["320", "15"], ["360", "15"], ["360", "0"]]
"""
    prog = "G00 X200. Z400.\nT0101\nG00 X31. Z350.\nG01 Z330. F0.2\nG00 X200.\nM30\n"
    assert verify_text(prog, _machine(zones=zones)).verdict is Verdict.UNSAFE
    assert verify_text(prog, _machine(radius="0", zones=zones)).verdict is Verdict.SAFE


def test_an_allowed_polygon_tip_zone_with_a_nose_radius_is_unknown():
    zones = JAWS + """
[[zones]]
name = "envelope"
kind = "polygon"
point = "tip"
plane = ["Z", "X"]
vertices = [["0", "0"], ["700", "0"], ["700", "250"], ["0", "250"]]
"""
    r = verify_text(_pass("70."), _machine(zones=zones))
    assert r.verdict is Verdict.UNKNOWN and any(x.code == "VF207" for x in r.reasons)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(top=st.integers(26, 40), z_end=st.integers(90, 150), tip=st.sampled_from([0, 3, 5, 8, 9]),
       radius=st.sampled_from(["0.2", "0.8", "1.5"]), d=st.integers(-20, 40))
def test_the_nose_radius_is_never_more_permissive(top, z_end, tip, radius, d):
    # a pass along Z at a radius near the jaw's face: whenever the proof with the nose radius says safe, the
    # proof without it (the imaginary tip alone) says safe too
    x = format_decimal(2 * top + 2 * F(d, 10))  # a diameter: radius top + d/10
    x += "" if "." in x else "."
    prog = f"G00 X200. Z200.\nT0101\nG00 X{x} Z160.\nG01 Z{z_end}. F0.2\nG00 X200.\nM30\n"
    with_nose = verify_text(prog, _machine(radius=radius, tip=tip)).verdict
    without = verify_text(prog, _machine(radius="0", tip=tip)).verdict
    assert not (with_nose is Verdict.SAFE and without is not Verdict.SAFE)
    assert with_nose in (Verdict.SAFE, Verdict.UNSAFE)


def test_the_double_pass_of_a_linuxcnc_lathe_program_sees_the_nose_too():
    # a LinuxCNC program with '#' takes the double pass (nczones.prover.doubles); G7: X words are diameters
    m = lathe(zones=JAWS, dialect="linuxcnc", offsets='1 = { X = "0", Z = "0", R = "0.8", tip = 0 }')
    prog = "#1=65\nG18 G7\nG00 X200 Z200\nG00 X#1 Z150\nG01 Z120 F100\nG00 X200\n"
    assert verify_text(prog, m).verdict is Verdict.UNSAFE
    m0 = lathe(zones=JAWS, dialect="linuxcnc", offsets='1 = { X = "0", Z = "0", R = "0", tip = 0 }')
    assert verify_text(prog, m0).verdict is Verdict.SAFE
