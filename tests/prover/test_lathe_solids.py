"""A lathe's turret tools and chucks as solids (issue 39, the lathe case): the bundled boring-bar example, tool
changes by T (the tool, not the offset), arcs in ZX, every lane end to end (short, more than 512 motions,
LinuxCNC with '#'), machine-file errors, and the prover against the independent oracle of
tests/oracles/lathe_solids.py on generated programs."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import MachineFileError
from nczones.gcode import segments_text
from nczones.machine import load_machine, parse_machine
from nczones.prover import verify, verify_text
from nczones.solids import machine_solids
from tests.machines import machine_text
from tests.oracles.lathe_solids import contact_inside, part_meets, sampled_hit, tip_of, tool_of

ROOT = Path(__file__).resolve().parents[2]
MACHINE = ROOT / "specs/machines/lathe_solids.toml"
PROGRAMS = ROOT / "specs/examples/programs"
TEXT = MACHINE.read_text()

# The example machine (specs/machines/lathe_solids.toml), in the tip's frame (machine minus tool offset 1:
# X 100, Z 150; G54 Z130): the jaws are the ring of radii 30..70 over Z 60..90, the chuck body radii 25..100
# over Z 0..60.  Tool 1: the bar holder is X -30..45, Z 35..95 from the tip, 40 thick (the proof grows it by
# 20 on both X sides: X -50..65).


def _lathe():
    return load_machine(MACHINE)


def test_example_boring_bar_hits_chuck():
    r = verify(str(PROGRAMS / "boring_bar_hits_chuck.nc"), _lathe())
    assert r.verdict.label == "unsafe"
    v = r.violations[0]
    # G01 Z-80. at X30. (tip radius 15): the holder's radial section at the tip's X 15 is -35..80, which meets
    # the jaws' radii 30..70, and its bottom (tip Z + 35) is below the jaws' face Z 90 once the tip is below
    # Z 55, that is machine Z 55 + 150 = 205 (the program's Z -75); the line runs down to machine Z 130 - 80 +
    # 150 = 200, so it violates on (200, 205): the witness is the middle, Z 202.5, 2.5 deep, at machine X 115
    assert v.kind == "solid" and v.zone == "jaws" and v.zones == ("bar holder",) and v.line == 7
    assert dict(v.path_point) == {"X": Fraction(115), "Z": Fraction(405, 2)}
    assert v.depth == Fraction(5, 2)
    assert "bar holder (X -30..45, Z 35..95 from the tip, 40 thick) enters `jaws` at line 7" in v.note
    # the contact point is in the jaws (radius 50 in 30..70, Z 88.75 in 60..90) and in the holder, even
    # without the thickness's growth (tip X 15: X -15..60; tip Z 52.5: Z 87.5..147.5)
    holder = machine_solids(_lathe()).tools[1][2]
    jaws = next(f for f in machine_solids(_lathe()).fixtures if f.name == "jaws")
    plain = type(holder)(holder.name, holder.x0, holder.x1, holder.z0, holder.z1)
    assert contact_inside(tuple(x for _, x in v.point), (Fraction(15), Fraction(105, 2)), plain, jaws)
    # the tip alone clears everything: every violation is a solid's
    assert all(x.kind == "solid" for x in r.violations)


def test_example_boring_bar_clears_chuck_with_clearance():
    r = verify(str(PROGRAMS / "boring_bar_clears_chuck.nc"), _lathe())
    assert r.verdict.label == "safe", (r.reasons, r.violations)
    # the deepest tip is Z 130 - 35 = 95: the holder's bottom is at 130, 40 above the jaws' face Z 90, and its
    # radial section (-35..80 at the tip's X 15) overlaps the jaws' radii, so the distance is that gap
    clear = {(p, f): c for p, f, c, _ in r.extra["clearance"]}
    assert clear[("bar holder (X -30..45, Z 35..95 from the tip, 40 thick)", "jaws")] == 40
    assert any(n.startswith("least clearance: bar holder (X -30..45, Z 35..95 from the tip, 40 thick) is at "
                            "least 40 mm from `jaws`") for n in r.notes)


HEAD = "%\nO1\nG21 G18 G99 G40\n"
TOOL2 = TEXT.replace('1 = { X = "100", Z = "150", R = "0.4", tip = 2 }',
                     '1 = { X = "100", Z = "150", R = "0.4", tip = 2 }\n2 = { X = "100", Z = "150", tip = 2 }') + """
[[tools]]
number = 2                # a short grooving blade: nothing behind the tip beyond Z 20
parts = [{ name = "blade", x = ["-3", "0"], z = ["0", "20"] }]
"""


@pytest.mark.parametrize("t, expected", [("T0101", "unsafe"), ("T0201", "safe"), ("T0202", "safe"),
                                         ("T0102", "unsafe")])
def test_the_tool_number_picks_the_parts_not_the_offset(t, expected):
    # offsets 1 and 2 are equal; the deep bore (tip Z 50) puts tool 1's holder into the jaws, while tool 2's
    # blade (Z 0..20 from the tip, radius 12..15 at tip X 15) clears the jaws (radii 30..70) and the chuck
    # (radii from 25): T0201 is tool 2 with offset 1
    m = parse_machine(TOOL2, "m.toml")
    r = verify_text(HEAD + f"{t}\nG00 X30. Z5.\nG01 Z-80. F0.1\nG00 Z5.\nM30\n%\n", m)
    assert r.verdict.label == expected, (r.reasons, r.violations)


def test_a_tool_change_switches_the_parts():
    m = parse_machine(TOOL2, "m.toml")
    r = verify_text(HEAD + "T0202\nG00 X30. Z5.\nG01 Z-80. F0.1\nG00 Z5.\nT0101\nG00 X30. Z5.\nG01 Z-80.\n"
                    "G00 Z5.\nM30\n%\n", m)
    assert r.verdict.label == "unsafe" and [v.line for v in r.violations] == [10, 11]
    # the second G01 Z-80. and the retract G00 Z5. that starts from there (the holder is still in the jaws)


def test_motion_before_a_tool_is_unknown():
    r = verify_text(HEAD + "G00 X200. Z100.\nM30\n%\n", _lathe())
    assert r.verdict.label == "unknown" and {x.code for x in r.reasons} == {"VF211"}


@pytest.mark.parametrize("g, expected", [("G02", "unsafe"), ("G03", "safe")])
def test_arc_in_zx_is_decided_by_pieces(g, expected):
    # tool 1's holder enters the jaws once the tip is below Z 55 (the example's derivation).  The arc runs
    # from tip (X 9, Z 60) to (X 21, Z 60) about (X 15, Z 60), radius 6.  In G18 seen from +Y (Z to the right,
    # X up) clockwise from the lower point goes through smaller Z: G02 dips to Z 54 (inside), G03 rises to
    # Z 66 (clear; the bar and the insert stay within radius 23.5 < 25 and 30)
    text = HEAD + f"T0101\nG00 X18. Z5.\nG01 Z-70. F0.1\n{g} X42. Z-70. I6. K0.\nG00 Z5.\nM30\n%\n"
    r = verify_text(text, _lathe())
    assert r.verdict.label == expected, (r.reasons, r.violations)
    if expected == "unsafe":
        v = r.violations[0]
        assert v.line == 7 and v.zones == ("bar holder",) and v.zone == "jaws"
        # the witness is the quarter-turn point (tip X 15, Z 54), an exact point of the circle: machine X 115,
        # Z 54 + 150
        assert dict(v.path_point) == {"X": Fraction(115), "Z": Fraction(204)} and not v.parameter_exact


def _long(z_deep: str, n: int = 300) -> str:
    """More than 512 motions of safe facing strokes far from the chuck, then one bore to ``Z{z_deep}``."""
    body = "".join(f"G01 X{60 + (i % 2) * 20}. Z{5 + i % 7}.\n" for i in range(2 * n))
    return HEAD + "T0101\nG00 X60. Z10.\n" + body + f"G00 X30. Z5.\nG01 Z{z_deep}\nG00 Z5.\nM30\n%\n"


@pytest.mark.parametrize("z, expected", [("-80.", "unsafe"), ("-35.", "safe")])
def test_long_program(z, expected):
    r = verify_text(_long(z), _lathe())
    assert r.verdict.label == expected, (r.reasons, r.violations[:1])
    if expected == "unsafe":
        assert r.violations[0].zones == ("bar holder",) and r.violations[0].line == 3 + 2 + 600 + 2  # head, T and G00, strokes, G00, G01


LINUXCNC = machine_text("linuxcnc_lathe_boring_bar")


@pytest.mark.parametrize("z, expected", [("-80", "unsafe"), ("-35", "safe")])
def test_linuxcnc_lathe_with_parameters(z, expected):
    # LinuxCNC: the tool by its length register (G43 H1), no X offset: the tip is machine X, machine Z - 150.
    # G7 (diameter mode, from diameter_axes): X30 is radius 15.  The holder (X -30..45, no thickness) enters
    # the jaws below tip Z 55, as in the Fanuc example; '#' takes the double pass, which declines solids
    m = parse_machine(LINUXCNC, "m.toml")
    text = f"#1 = {z}\nG18 G21 G90 G54\nT1 M6\nG43 H1\nG0 X30 Z5\nG1 Z#1 F100\nG0 Z5\nM30\n"
    r = verify_text(text, m)
    assert r.verdict.label == expected, (r.reasons, r.violations)
    if expected == "unsafe":
        assert r.violations[0].zones == ("bar holder",) and r.violations[0].line == 6


LATHE_HEAD = machine_text("xz_rapid_1000")  # 8 lines: the tails below start at line 9


@pytest.mark.parametrize("tail, code, line, column", [
    ('[[tools]]\nnumber = 1\nparts = [{ name = "bar", x = ["5", "-5"], z = ["0", "9"] }]\n', "ZN165", 11, 26),
    ('[[tools]]\nnumber = 1\nparts = [{ name = "bar", x = "5", z = ["0", "9"] }]\n', "ZN165", 11, 26),
    ('[[tools]]\nnumber = 1\nparts = [{ name = "bar", diameter = "5", length = "9" }]\n', "ZN160", 11, 26),
    ('[[fixtures]]\nname = "jaws"\nkind = "box"\n', "ZN166", 11, 1),
    ('[[fixtures]]\nname = "jaws"\nkind = "chuck"\nradius = "30"\ninner_radius = "30"\n', "ZN166", 13, 1),
    ('[[fixtures]]\nname = "jaws"\nkind = "chuck"\nradius = "30"\nmin_z = "9"\nmax_z = "1"\n', "ZN166", 14, 1),
    ('[[fixtures]]\nname = "jaws"\nkind = "chuck"\ncentre = { X = "0", Y = "0" }\nradius = "3"\n', "ZN160", 12, 1),
])
def test_machine_file_errors(tail, code, line, column):
    # line:column of the key at fault (column 26: the part's x or diameter key after `parts = [{ name = "bar", `)
    with pytest.raises(MachineFileError) as e:
        parse_machine(LATHE_HEAD + tail, "m.toml")
    d = e.value.diagnostics[0]
    assert d.code == code, d
    assert d.span is not None and (d.span.line, d.span.column) == (line, column), d


ORACLE = TEXT.replace('1 = { X = "100", Z = "150", R = "0.4", tip = 2 }',
                      '1 = { X = "100", Z = "150" }\n2 = { X = "110", Z = "140" }') + """
[[tools]]
number = 2                # an outside turning tool: a shank along X
parts = [
  { name = "insert", x = ["0", "4"], z = ["0", "5"] },
  { name = "shank", x = ["4", "30"], z = ["0", "25"], thickness = "25" },
  { name = "turret", x = ["30", "60"], z = ["-10", "40"] },
]

[[fixtures]]
name = "tailstock quill"
kind = "cylinder"
radius = "20"
min_z = "260"
"""

coord_x = st.integers(-20, 120).map(lambda v: Fraction(v, 2))
coord_z = st.integers(120, 400).map(lambda v: Fraction(v, 2))


@st.composite
def programs(draw):
    """Fanuc lathe programs (X a diameter, G54 Z130: the tip's Z is the program's + 130) of lines, rapids and
    arcs (a quarter or half turn about a drawn centre, the end exactly on the circle) around the chuck, the
    jaws and the tailstock quill, with tool 1 or 2 and maybe a change between them."""
    t = draw(st.sampled_from([1, 2]))
    x, z = Fraction(60), Fraction(150)
    lines = [f"G21 G18 G99 G40\nT0{t}0{t}", f"G00 X{float(2 * x)} Z{float(z - 130)}"]
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(["line", "line", "arc", "change"]))
        if kind == "change":
            t = 3 - t  # the offsets differ: the tip moves relative to the program's frame, so go somewhere known
            x, z = draw(coord_x), draw(coord_z)
            lines.append(f"T0{t}0{t}\nG00 X{float(2 * x)} Z{float(z - 130)}")
        elif kind == "line":
            x, z = draw(coord_x), draw(coord_z)
            lines.append(f"G0{draw(st.sampled_from([0, 1]))} X{float(2 * x)} Z{float(z - 130)} F0.2")
        else:
            i, k = draw(coord_x) / 4, draw(coord_x) / 4
            if i == 0 and k == 0:
                i = Fraction(5)
            cw = draw(st.booleans())
            cx, cz = x + i, z + k
            ux, uz = x - cx, z - cz
            ex, ez = draw(st.sampled_from([(uz, -ux), (-uz, ux), (-ux, -uz)]))
            x, z = cx + ex, cz + ez
            lines.append(f"G0{2 if cw else 3} X{float(2 * x)} Z{float(z - 130)} I{float(i)} K{float(k)} F0.2")
    return "%\nO1\n" + "\n".join(lines) + "\nM30\n%\n"


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_never_a_wrong_safe(text):
    _against_oracle(text)


@pytest.mark.long
@settings(max_examples=2000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_never_a_wrong_safe_long(text):
    _against_oracle(text)


def _against_oracle(text):
    machine = parse_machine(ORACLE, "oracle.toml")
    try:
        r = verify_text(text, machine)
    except Exception as e:  # a program the interpreter refuses (an arc end off the circle): not generated on purpose
        raise AssertionError(text) from e
    solids = machine_solids(machine)
    segs = segments_text(text, machine, fast=False)
    hit = None
    for seg in segs:
        tool = tool_of(seg)
        parts = solids.tools.get(tool, ()) if tool is not None else ()
        hit = hit or (sampled_hit(seg, parts, solids.fixtures, 48) if parts else None)
    if hit is not None:
        assert r.verdict.label != "safe", f"safe, but the oracle finds {hit[0].name} in {hit[1].name} at {hit[2]}"
    for v in r.violations:
        if v.kind != "solid":
            continue
        seg = next(s for s in segs if s.block == v.block)
        part = next(p for p in solids.tools[tool_of(seg)] if p.name in v.zones)
        fx = next(f for f in solids.fixtures if f.name == v.zone)
        tip = tip_of(seg, tuple(x for _, x in v.path_point))
        if part.thickness == 0:  # exact both ways: the contact point is in the part and the fixture
            assert contact_inside(tuple(x for _, x in v.point), tip, part, fx), v.note
        if v.parameter_exact:  # a line's witness: the oracle's own test in space agrees (up to the growth)
            grown = type(part)(part.name, part.x0 - part.thickness / 2, part.x1 + part.thickness / 2,
                               part.z0, part.z1)
            assert part_meets(grown, fx, *tip), v.note


def test_every_violating_block_is_reported():
    # two bores too deep: the holder enters the jaws on both G01 lines (the example's derivation) and starts
    # inside them on both retracts; the later ones must not be screened away by the least clearance (0) the
    # first left
    text = HEAD + "T0101\nG00 X30. Z5.\nG01 Z-80. F0.1\nG00 Z5.\nG01 Z-80.\nG00 Z5.\nM30\n%\n"
    r = verify_text(text, _lathe())
    assert [v.line for v in r.violations] == [6, 7, 8, 9]


@pytest.mark.parametrize("thickness, expected", [("16", "unsafe"), ("0", "safe")])
def test_a_parts_thickness_reaches_further_from_the_axis(thickness, expected):
    # a blade X -1..0 from the tip at radius 29 (X58 in G7), Z 0..10, beside the jaws (radii 30..70, Z 60..90):
    # in the plane it reaches radius 29 only, but 16 thick (8 either side of the plane) its corner is
    # √(29² + 8²) = √905 > 30 from the axis: inside the jaws.  The proof grows it to X -9..8 (radius 37)
    m = parse_machine(LINUXCNC.replace('{ name = "bar holder", x = ["-30", "45"], z = ["35", "95"] }',
                                       f'{{ name = "blade", x = ["-1", "0"], z = ["0", "10"], thickness = "{thickness}" }}'),
                      "m.toml")
    blade = machine_solids(m).tools[1][0]
    jaws = machine_solids(m).fixtures[0]
    assert part_meets(blade, jaws, Fraction(29), Fraction(70)) == (expected == "unsafe")  # the oracle in space
    r = verify_text("G18 G21 G90 G54\nT1 M6\nG43 H1\nG0 X58 Z5\nG1 Z-60 F100\nG0 Z5\nM30\n", m)
    assert r.verdict.label == expected, (r.reasons, r.violations)
