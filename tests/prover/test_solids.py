"""Tool assemblies and fixtures as solids (issue 39, the mill core): the bundled example, every lane end to
end (short programs, more than 512 motions, parameters '#'), G49, machine-file errors, and the prover
against the independent oracle of tests/oracles/solids.py on generated programs."""

from __future__ import annotations

import json
import os
import time
from collections import Counter
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import MachineFileError
from nczones.gcode import segments_text
from nczones.machine import load_machine, parse_machine
from nczones.prover import verify, verify_text
from nczones.solids import FixtureBox, FixturePrism, machine_solids
from tests.machines import machine_text
from tests.oracles.solids import inside_part_and_fixture, sampled_hit

F = Fraction

ROOT = Path(__file__).resolve().parents[2]
MACHINE = ROOT / "specs/machines/mill_solids.toml"
PROGRAMS = ROOT / "specs/examples/programs"


def _mill():
    return load_machine(MACHINE)


# The example machine (specs/machines/mill_solids.toml): the vise's jaw is X 100..250, Y 0..80, Z 0..60;
# tool 1 = cutter Ø10 × 25, shank Ø10 × 15, holder Ø63 × 60 (40..100 above the tip), H1 = 100.


def test_example_holder_hits_vise():
    r = verify(str(PROGRAMS / "holder_hits_vise.ngc"), _mill())
    assert r.verdict.label == "unsafe"
    v = r.violations[0]
    # G1 Z10 at X80: the holder's axis is 20 from the jaw face (X100) and its radius is 31.5, so it enters the
    # jaw once its bottom (tip + 40) is below the jaw top 60: the tip goes down to Z10 on line 6
    assert v.kind == "solid" and v.zone == "vise" and v.zones == ("holder",) and v.line == 6
    assert "holder (Ø63 × 60 at 40..100 above the tip) enters `vise` at line 6" in v.note
    point = tuple(x for _, x in v.point)
    path = tuple(x for _, x in v.path_point)
    holder = machine_solids(_mill()).tools[1][2]
    vise = next(f for f in machine_solids(_mill()).fixtures if f.name == "vise")
    assert inside_part_and_fixture(point, path, holder, vise, Fraction(100))
    # the tip alone clears the jaw: no violation names a zone through the controlled point
    assert all(x.kind == "solid" for x in r.violations)


def test_example_holder_clears_vise_with_clearance():
    r = verify(str(PROGRAMS / "holder_clears_vise.ngc"), _mill())
    assert r.verdict.label == "safe", r.reasons
    # at X60 the holder reaches X 60 + 31.5 = 91.5, 8.5 from the jaw face X100, while it is below the jaw top
    assert any(n.startswith("least clearance: holder (Ø63 × 60 at 40..100 above the tip) is at least 8.5 mm "
                            "from `vise`") for n in r.notes)
    clear = {(p, f): c for p, f, c, _ in r.extra["clearance"]}
    assert clear[("holder (Ø63 × 60 at 40..100 above the tip)", "vise")] == Fraction(17, 2)


def _with_polygon(vertices: str, plane: str = '["X", "Y"]', limits: str = 'min = { Z = "40" }\nmax = { Z = "70" }\n'):
    return parse_machine(MACHINE.read_text(encoding="utf-8") + (
        f'\n[[zones]]\nname = "clamp plate"\nkind = "polygon"\nforbid = true\nplane = {plane}\n'
        f'vertices = {vertices}\n{limits}'))


def test_a_forbidden_xy_polygon_is_a_prism_fixture():
    """A forbidden polygon in the XY plane over a Z range is a prism the holder may not enter (issue 39).

    holder_clears_vise.ngc plunges the tip to Z10 at X60 Y40, then feeds to Y20. The holder (radius 31.5,
    40..100 above the tip) is then at Z 50..110, over the plate's Z 40..70 once the tip is below 70 - 40 = 30.
    A plate whose apex is at (60, 70) is 30 from the holder's axis at Y40: 1.5 mm inside on line 6 (the plunge;
    the shank, radius 5 at 25..40 above the tip, stays 25 clear). With the apex at (60, 72) the holder passes
    32 - 31.5 = 0.5 clear; a plate far away (X500) is proved too."""
    text = (PROGRAMS / "holder_clears_vise.ngc").read_text(encoding="utf-8")
    hit = verify_text(text, _with_polygon('[["60", "70"], ["40", "120"], ["80", "120"]]'))
    assert hit.verdict.label == "unsafe", (hit.reasons, hit.violations)
    v = hit.violations[0]
    assert (v.zone, v.zones, v.line) == ("clamp plate", ("holder",), 6)
    point = tuple(x for _, x in v.point)
    path = tuple(x for _, x in v.path_point)
    holder = machine_solids(_mill()).tools[1][2]
    plate = FixturePrism("clamp plate", ((F(60), F(70)), (F(40), F(120)), (F(80), F(120))), F(40), F(70))
    assert inside_part_and_fixture(point, path, holder, plate, F(100))
    clear = verify_text(text, _with_polygon('[["60", "72"], ["40", "120"], ["80", "120"]]'))
    assert clear.verdict.label == "safe", (clear.reasons, clear.violations)
    c = {(p, f): c for p, f, c, _ in clear.extra["clearance"]}
    assert c[("holder (Ø63 × 60 at 40..100 above the tip)", "clamp plate")] == F(1, 2)
    far = verify_text(text, _with_polygon('[["500", "500"], ["520", "500"], ["520", "520"]]'))
    assert far.verdict.label == "safe", far.reasons


def test_a_sharp_prism_vertex_gets_a_witness_inside():
    """A thin plate (apex (100, 300), base X200 Y290..310, Z 0..30; the apex angle about 11.4°). The holder's
    axis at X90 Y317 is nearest the apex (it is in the apex's normal cone: (-10, 17) is at 120° from +X, more
    than 90° from both edges), √389 ≈ 19.7 < 31.5 from it; with the tip at Z-15 the holder (from Z25 up) is
    below the plate's top: unsafe, and the contact point must be strictly inside the plate, found between the
    apex's two edges (neither the way from the axis to the apex nor an edge's normal leads inside)."""
    m = _with_polygon('[["100", "300"], ["200", "290"], ["200", "310"]]', limits='min = { Z = "0" }\nmax = { Z = "30" }\n')
    r = verify_text(HEADER + "G0 X90 Y317 Z100\nG1 Z-15 F300\nG0 Z100\nM30\n", m)
    assert r.verdict.label == "unsafe", (r.reasons, r.violations)
    v = r.violations[0]
    assert (v.zone, v.zones, v.line) == ("clamp plate", ("holder",), 5)
    plate = FixturePrism("clamp plate", ((F(100), F(300)), (F(200), F(290)), (F(200), F(310))), F(0), F(30))
    holder = machine_solids(_mill()).tools[1][2]
    assert inside_part_and_fixture(tuple(x for _, x in v.point), tuple(x for _, x in v.path_point), holder, plate,
                                   F(100))


def test_a_forbidden_polygon_in_another_plane_is_not_a_solid_fixture_and_the_verdict_says_so():
    """A polygon in the ZX plane (a lathe-style profile) is no prism along the tool axis: the holder is not
    checked against it, so it is named and the verdict is unknown (VF210), never safe."""
    text = (PROGRAMS / "holder_clears_vise.ngc").read_text(encoding="utf-8")
    r = verify_text(text, _with_polygon('[["500", "500"], ["520", "500"], ["520", "520"]]', '["Z", "X"]', ""))
    assert r.verdict.label == "unknown"
    assert any(x.code == "VF210" and "`clamp plate`" in x.message for x in r.reasons), r.reasons


STEPS = """
[[zones]]
name = "steps"
kind = "stepped"
forbid = true
point = "tip"
reference_axis = "X"
limited_axis = "Z"
from = "450"
regions = [{ upto = "480", min = "0", max = "40" }, { upto = "520", min = "0", max = "10" }]
"""


@pytest.mark.parametrize("z, verdict", [("10", "safe"), ("-5", "unsafe")])
def test_a_forbidden_stepped_table_is_a_fixture_box_per_region(z, verdict):
    """A forbidden stepped table of X and Z (here X 450..480 up to Z40, X 480..520 up to Z10, every Y) is one
    fixture box per region. The tip plunges at X440 Y300: the cutter (radius 5) reaches X445, clear of the
    steps; the holder (radius 31.5, from 40 above the tip) reaches X471.5, over the first step: its bottom at
    tip Z10 is Z50, 10 above the step's top 40 (safe); at tip Z-5 it is at Z35, inside (unsafe)."""
    m = parse_machine(MACHINE.read_text(encoding="utf-8") + STEPS)
    r = verify_text(HEADER + f"G0 X440 Y300 Z100\nG1 Z{z} F300\nG0 Z100\nM30\n", m)
    assert r.verdict.label == verdict, (r.reasons, r.violations)
    if verdict == "unsafe":
        v = r.violations[0]
        assert (v.zone, v.zones, v.line) == ("steps", ("holder",), 5)
        holder = machine_solids(m).tools[1][2]
        step = FixtureBox("steps", F(450), F(480), None, None, F(0), F(40))
        assert inside_part_and_fixture(tuple(x for _, x in v.point), tuple(x for _, x in v.path_point), holder,
                                       step, F(100))
    else:
        clear = {(p, f): c for p, f, c, _ in r.extra["clearance"]}
        # the holder is over the first step (horizontally inside), its heights never overlap: no figure; the
        # cutter (0..25 above the tip, Z10..35 overlapping the step's 0..40) is 5 from the step's face X450
        assert clear[("cutter (Ø10 × 25 at 0..25 above the tip)", "steps")] == 5


HEADER = "G21 G90 G17 G54\nT1 M6\nG43 H1\n"


def test_solids_under_g64_are_proved_on_the_rounded_corners():
    """The holder sweeps the path the control moves (nczones/prover/solids_blend.py).  The clear example's
    holder passes 8.5 mm from the jaw on the programmed path, its corners all at X60 (a plunge, a move in Y, a
    retract), so the corner regions of G64 keep the holder 8.5 mm away too: safe, from the machine's start-up
    mode or a G64 in the program.  With G64 P p (Q defaults to P) the path may leave the programmed one by 2p:
    P4 (8 mm) is safe, P5 (10 mm) unknown (VF233).  Before, every G64 program with solids was unknown VF210."""
    text = (PROGRAMS / "holder_clears_vise.ngc").read_text(encoding="utf-8")
    assert verify_text(text, _mill()).verdict.label == "safe"
    blending = parse_machine(MACHINE.read_text(encoding="utf-8").replace('path_mode = "G61"', 'path_mode = "G64"'))
    for machine, program in ((blending, text), (_mill(), "G64\n" + text), (_mill(), "G64 P4\n" + text)):
        r = verify_text(program, machine)
        assert r.verdict.label == "safe", r.reasons
    # the least clearance on the rounded path: the holder grown by 8 mm is 8.5 - 8 = 0.5 mm from the jaw
    assert any(n.startswith("least clearance on the path the control may move (G64 P4: within 8 mm")
               and "holder is at least 0.5 mm from `vise`" in n for n in r.notes), r.notes
    r = verify_text("G64 P5\n" + text, _mill())
    assert r.verdict.label == "unknown" and {x.code for x in r.reasons} == {"VF233"}, r.reasons
    assert any("holder" in x.message and "10 mm" in x.message for x in r.reasons)


def _long(x_hit: str, n: int = 300) -> str:
    """More than 512 motions, safe zig-zags away from the vise, then one plunge at ``X{x_hit}``."""
    body = "".join(f"G1 X{-50 + (i % 2) * 10} Y{i % 50}\n" for i in range(2 * n))
    return HEADER + "G0 X-50 Y0 Z100\nG1 Z10 F500\n" + body + f"G0 Z100\nG0 X{x_hit} Y40\nG1 Z10\nG0 Z100\nM30\n"


@pytest.mark.parametrize("x, expected", [("80", "unsafe"), ("60", "safe")])
def test_long_program_vectorized_tier(x, expected):
    r = verify_text(_long(x), _mill())
    assert r.verdict.label == expected, (r.reasons, r.violations)
    if expected == "unsafe":
        assert r.violations[0].zones == ("holder",) and r.violations[0].line == 3 + 2 + 600 + 3


@pytest.mark.parametrize("x, expected", [("80", "unsafe"), ("60", "safe")])
def test_parametric_program_double_pass(x, expected):
    text = f"#1 = {x}\n" + HEADER + "G0 X#1 Y40 Z100\nG1 Z10 F300\nG0 Z100\nM30\n"
    r = verify_text(text, _mill())
    assert r.verdict.label == expected, (r.reasons, r.violations)


def test_motion_under_g49_is_unknown():
    r = verify_text("G21 G90 G54\nG0 X-50 Y0 Z300\nM30\n", _mill())
    assert r.verdict.label == "unknown"
    assert [x.code for x in r.reasons] == ["VF211"]


def test_cylinder_fixture_and_spindle_nose():
    # the clamp post: centre X400 Y200, radius 15, up to Z50. The cutter (radius 5) at Y200 enters it when
    # X < 400 + 15 + 5 = 420 and the tip is below 50
    r = verify_text(HEADER + "G0 X430 Y200 Z100\nG1 Z40 F300\nG1 X419\nG0 Z100\nM30\n", _mill())
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "clamp" and r.violations[0].line == 6
    r = verify_text(HEADER + "G0 X430 Y200 Z100\nG1 Z40 F300\nG1 X420\nG0 Z100\nM30\n", _mill())
    assert r.verdict.label == "safe", (r.reasons, r.violations)


MACHINE_HEAD = machine_text("xyz_rapid_1000")  # 10 lines: the tails below start at line 11


@pytest.mark.parametrize("tail, code, line", [
    ('[[tools]]\nnumber = 1\nparts = [{ name = "cutter", diameter = "10", lenght = "5" }]\n', "ZN160", 13),
    ('[[tools]]\nnumber = 1\n', "ZN161", None),
    ('[[tools]]\nnumber = -1\nparts = [{ diameter = "10", length = "5" }]\n', "ZN162", 12),
    ('[spindle]\nparts = [{ diameter = "10", length = "5" }]\n[[fixtures]]\nname = "a"\nkind = "cone"\n',
     "ZN163", 15),
    ('[[tools]]\nnumber = 1\nparts = [{ diameter = "0", length = "5" }]\n', "ZN106", 13),
])
def test_machine_file_errors(tail, code, line):
    with pytest.raises(MachineFileError) as e:
        parse_machine(MACHINE_HEAD + tail, "m.toml")
    d = e.value.diagnostics[0]
    assert d.code == code
    if line is not None:
        assert d.span is not None and d.span.line == line


def test_solids_need_xyz():
    text = MACHINE_HEAD.replace('["X", "Y", "Z"]', '["X", "Z"]').replace('Y = "1000"\n', "").replace('Y = "0"\n', "")
    with pytest.raises(MachineFileError) as e:
        parse_machine(text + '[spindle]\nparts = [{ diameter = "10", length = "5" }]\n', "m.toml")
    assert e.value.diagnostics[0].code == "ZN164"


# --------------------------------------------------------------------------- against the oracle

# exact path (G61): under G64 every verdict with solids is unknown (VF210) and the comparison is vacuous
ORACLE_MACHINE = MACHINE_HEAD.replace('Z = "400"', 'Z = "300"').replace(
    'axes = ["X", "Y", "Z"]\n', 'axes = ["X", "Y", "Z"]\npath_mode = "G61"\n') + """[offsets]
G54 = { X = "0", Y = "0", Z = "0" }
[tool_lengths]
H1 = "50"
H2 = "80"
[[tools]]
number = 1
parts = [{ name = "cutter", diameter = "6", length = "20" }, { name = "holder", diameter = "40", length = "30" }]
[[tools]]
number = 2
parts = [{ name = "drill", diameter = "4", length = "50" }, { name = "holder", diameter = "32", length = "30" }]
[[zones]]
name = "jaw"
kind = "box"
forbid = true
point = "tip"
min = { X = "0", Y = "0", Z = "0" }
max = { X = "40", Y = "30", Z = "25" }
[[fixtures]]
name = "post"
kind = "cylinder"
centre = { X = "-30", Y = "40" }
radius = "8"
max_z = "35"
"""

coord = st.integers(-80, 80).map(lambda v: Fraction(v, 2))
height = st.integers(5, 160).map(lambda v: Fraction(v, 2))


@st.composite
def programs(draw):
    """Lines and helical arcs (G2/G3 a quarter or half turn about a drawn centre, the end exactly on the
    circle) around the jaw and the post, with tool 1 or 2."""
    h = draw(st.sampled_from([1, 2]))
    lines = [f"G21 G90 G17 G54\nT{h} M6\nG43 H{h}", "G0 X-60 Y-60 Z120"]
    px, py = Fraction(-60), Fraction(-60)
    for _ in range(draw(st.integers(1, 4))):
        z = draw(height)
        if draw(st.booleans()):
            px, py = draw(coord), draw(coord)
            lines.append(f"G1 X{float(px)} Y{float(py)} Z{float(z)} F500")
            continue
        i, j = draw(coord) / 2, draw(coord) / 2
        if i == 0 and j == 0:
            i = Fraction(5)
        cw = draw(st.booleans())
        cx, cy = px + i, py + j
        ux, uy = px - cx, py - cy
        ex, ey = draw(st.sampled_from([(uy, -ux) if cw else (-uy, ux), (-ux, -uy)]))
        px, py = cx + ex, cy + ey
        lines.append(f"G{2 if cw else 3} X{float(px)} Y{float(py)} Z{float(z)} I{float(i)} J{float(j)} F500")
    return "\n".join(lines) + "\nM30\n"


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_never_a_wrong_safe(text):
    _against_oracle(text)


def test_the_oracle_machine_gets_decided_verdicts():
    """The property tests compare `safe` with the oracle: the machine must let the prover decide (G61)."""
    text = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X-60 Y-60 Z120\nG1 X-50 Y-50 Z100 F500\nM30\n"
    assert verify_text(text, parse_machine(ORACLE_MACHINE, "oracle.toml")).verdict.label == "safe"


@pytest.mark.long
@settings(max_examples=20_000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_never_a_wrong_safe_long(text):
    _against_oracle(text)


#: Verdict counts of the programs checked against the oracle; with $NCZONES_SOLIDS_STATS set they are written
#: there as JSON every 100 programs (a long run may be stopped and still report its numbers).
ORACLE_STATS: Counter = Counter()


def _count(label: str) -> None:
    ORACLE_STATS[label] += 1
    out = os.environ.get("NCZONES_SOLIDS_STATS")
    if out and ORACLE_STATS["programs"] % 100 == 0:
        ORACLE_STATS["cpu seconds"] = int(time.process_time())
        Path(out).write_text(json.dumps(dict(ORACLE_STATS), indent=2, sort_keys=True) + "\n")


def _against_oracle(text):
    machine = parse_machine(ORACLE_MACHINE, "oracle.toml")
    r = verify_text(text, machine)
    assert not any("G64" in x.message for x in r.reasons), r.reasons  # the machine runs the exact path
    ORACLE_STATS["programs"] += 1
    solids = machine_solids(machine)
    segs = segments_text(text, machine, fast=False)
    hit = None
    for seg in segs:
        parts = solids.parts_for(seg.tool_register)
        if parts:
            hit = hit or sampled_hit(seg, parts, solids.fixtures, 48)
    if hit is not None and r.verdict.label == "safe":
        raise AssertionError(f"safe, but the oracle finds {hit[0].name} in {hit[1].name} at {hit[2]}")
    for v in r.violations:
        if v.kind != "solid":
            continue
        seg = next(s for s in segs if s.block == v.block)
        part = next(p for p in solids.parts_for(seg.tool_register) if p.name in v.zones)
        fx = next(f for f in solids.fixtures if f.name == v.zone)
        point = tuple(x for _, x in v.point)
        path = tuple(x for _, x in v.path_point)
        assert inside_part_and_fixture(point, path, part, fx, seg.tool_length), v.note
    _count(f"verdict {r.verdict.label}" + (", the oracle's samples hit" if hit is not None else ""))


def test_parametric_program_without_tool_length_is_not_proved_by_the_double_pass():
    # the double pass declines T and H words, so a parametric program it takes runs under G49: its boxes are
    # about the controlled point only and would prove this program; the tool in the spindle is not known
    text = "#1 = 80\nG21 G90 G17 G54\nG0 X#1 Y40 Z300\nG0 Z200\nM30\n"
    r = verify_text(text, _mill())
    assert r.verdict.label == "unknown" and [x.code for x in r.reasons] == ["VF211", "VF211"][: len(r.reasons)]
    # a spindle-only machine: the nose (Ø120 from the gauge line up) at X80 reaches X140, inside the jaw
    # (X 100..250, up to Z60) once the gauge line is below 60
    spindle_only = MACHINE_MILL_TEXT.split("[[tools]]")[0] + (
        '[spindle]\nparts = [{ name = "spindle nose", diameter = "120", length = "80" }]\n')
    r = verify_text("#1 = 80\nG21 G90 G17 G54\nG0 X#1 Y40 Z300\nG0 Z50\nM30\n", parse_machine(spindle_only))
    assert r.verdict.label == "unsafe" and r.violations[0].zones == ("spindle nose",)


MACHINE_MILL_TEXT = MACHINE.read_text(encoding="utf-8")


@pytest.mark.parametrize("z, expected", [("40", "safe"), ("10", "unsafe")])
def test_arc_past_the_jaw_corner_is_decided_by_pieces(z, expected):
    # a quarter arc about (60, -40) of radius 40 from (60, 0) to (100, -40): its box X 60..100, Y -40..0
    # touches the jaw's corner (100, 0), the arc itself stays 40√2 - 40 ≈ 16.57 from it. At tip Z40 only the
    # cutter (radius 5) is at the jaw's heights: safe, 11.57 clear. At tip Z10 the holder (radius 31.5,
    # 50..110) is too: it enters near the arc's middle (its ends are 40 from the jaw), so the witness needs a
    # point inside the arc
    text = HEADER + f"G0 X60 Y0 Z100\nG1 Z{z} F300\nG2 X100 Y-40 I0 J-40\nG0 Z100\nM30\n"
    r = verify_text(text, _mill())
    assert r.verdict.label == expected, (r.reasons, r.violations)
    if expected == "unsafe":
        v = r.violations[0]
        assert v.line == 6 and v.zones == ("holder",) and not v.parameter_exact
        path = tuple(x for _, x in v.path_point)
        assert (path[0] - 60) ** 2 + (path[1] + 40) ** 2 == 40 ** 2  # exactly on the circle
        holder = machine_solids(_mill()).tools[1][2]
        vise = next(f for f in machine_solids(_mill()).fixtures if f.name == "vise")
        assert inside_part_and_fixture(tuple(x for _, x in v.point), path, holder, vise, Fraction(100))
    else:
        clear = {(p, f): c for p, f, c, _ in r.extra["clearance"]}
        c = clear[("cutter (Ø10 × 25 at 0..25 above the tip)", "vise")]
        assert 0 < c <= Fraction(1157, 100)
