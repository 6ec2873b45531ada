"""The reference controller checks the tool solids against the fixtures pulse by pulse (issue 39).

Expected positions are derived from the machine file by hand (the comments), not read from the code: the
monitor checks each part grown by half a pulse step (radius + (u_x + u_y) / 2, heights ± u_z / 2, see
nczones/controller/solids.py), so it alarms at the first pulse position where the grown part meets the open
interior of a fixture."""

from __future__ import annotations

import ast
import json
from fractions import Fraction
from pathlib import Path

import jsonschema
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller import Controller, Settings, simulate
from nczones.controller.solids import MachineSolids
from nczones.exact import format_decimal as fd
from nczones.gcode import interpret_text
from nczones.machine import load_machine, parse_machine
from tests.machines import machine_text

ROOT = Path(__file__).resolve().parents[2]
MACHINE = ROOT / "specs/machines/mill_solids.toml"
PROGRAMS = ROOT / "specs/examples/programs"
HEADER = "G21 G90 G17 G54\nT1 M6\nG43 H1\n"
F = Fraction


def _mill():
    return load_machine(MACHINE)


def _run(text, machine=None, **kw):
    machine = machine or _mill()
    return simulate(interpret_text(text, machine, fast=False), machine, **kw)


# specs/machines/mill_solids.toml: pulse 0.001 on X, Y, Z; the vise's jaw X 100..250, Y 0..80, Z 0..60 (a forbid
# box, hence a fixture); the clamp post: centre X400 Y200, radius 15, up to Z50; tool 1 = cutter Ø10 × 25,
# shank Ø10 × 15, holder Ø63 × 60 (40..100 above the tip), H1 = 100; spindle nose Ø120 × 80 from the gauge line.


def test_holder_hits_vise_alarms_at_the_first_pulse_the_holder_meets_the_jaw():
    # G1 Z10 at X80 Y40: the holder (radius 31.5) reaches X111.5 > 100, inside the jaw's Y range. Its bottom
    # is machine Z - 100 + 40 = Z - 60, grown by half a Z pulse: it meets the jaw (top Z60, open) once
    # Z - 60 - 0.0005 < 60, i.e. Z < 120.0005: the first pulse position going down is Z120 (the holder's
    # bottom touches the jaw top there: the monitor's half-step gray band)
    r = _run((PROGRAMS / "holder_hits_vise.ngc").read_text())
    a = r.alarms[0]
    assert (a.kind, a.zone, a.line) == ("solid", "vise", 6)
    assert a.part == "holder (Ø63 × 60 at 40..100 above the tip)"
    assert a.position == (F(80), F(40), F(120))
    assert a.blocked == (("Z", -1),)
    assert not r.completed
    doc = json.loads(json.dumps(r.to_json()))
    jsonschema.validate(doc, json.loads((ROOT / "specs/simulate.schema.json").read_text(encoding="utf-8")))
    j = doc["alarms"][0]
    assert j["kind"] == "solid" and j["part"] == a.part and j["zone"] == "vise"
    assert any(e.kind == "alarm" and "holder (Ø63 × 60 at 40..100 above the tip) enters `vise`" in dict(e.data)["note"]
               for e in r.events)


@pytest.mark.parametrize("text, start, line, position", [
    # the same plunge, short (started next to it: the reference engine checks every pulse in rationals)
    (HEADER + "G0 X80 Y40 Z21\nG1 Z19 F300\nM30\n", (80, 40, 122), 5, (F(80), F(40), F(120))),
    # a quarter arc at tip Z10 (machine Z110: the holder 50..110 is at the jaw's heights) about (60, -40) from
    # (60, 0) to (100, -40), on the machine with 0.01 pulses: the holder (radius 31.5 + 0.01) first meets the
    # jaw's corner (100, 0) where (X - 100)² + Y² < 31.51² on the circle; both engines walk the same pulses
    # and alarm at the same one
    (HEADER + "G0 X60 Y0 Z10\nG2 X100 Y-40 I0 J-40 F3000\nM30\n", (60, 0, 111), 5, None),
])
def test_both_engines_alarm_at_the_same_pulse(text, start, line, position):
    machine = _mill() if position is not None else parse_machine(
        MACHINE.read_text(encoding="utf-8").replace('pulse = "0.001"', 'pulse = "0.01"'))
    got = [_run(text, machine, settings=Settings(engine=e), start=tuple(map(F, start))).alarms[0]
           for e in ("vector", "reference")]
    assert got[0] == got[1]
    a = got[0]
    assert (a.kind, a.zone, a.line) == ("solid", "vise", line) and a.part.startswith("holder")
    if position is not None:
        assert a.position == position
    else:
        x, y, _ = a.position
        assert (x - 100) ** 2 + y ** 2 < F(3151, 100) ** 2


def test_modes_as_for_zones():
    text = (PROGRAMS / "holder_hits_vise.ngc").read_text()
    check = _run(text, mode="check")
    assert check.alarms[0].kind == "solid" and check.alarms[0].position == (F(80), F(40), F(120))
    assert check.machine_position == _mill().start  # program check: the real axes did not move
    lock = _run(text, mode="lock")
    assert lock.alarms == () and lock.blind_spot is not None
    periodic = _run(text, monitor="periodic")
    # periodic sampling: caught at or after the first pulse (Z decreasing), within the same motion
    a = periodic.alarms[0]
    assert a.kind == "solid" and a.line == 6 and a.position[2] <= 120


def test_holder_clears_vise_runs_clean():
    r = _run((PROGRAMS / "holder_clears_vise.ngc").read_text())
    assert r.alarms == () and r.completed


@pytest.mark.parametrize("x_end, alarm_x", [("419", F(420)), ("420.002", None)])
def test_cylinder_fixture(x_end, alarm_x):
    # the cutter (radius 5) at Y200, tip at Z40 (machine Z140, cutter heights 40..65 below the post top 50):
    # it meets the post when (X - 400)² < (15 + 5 + 0.001)², the grown reach: X < 420.001. Moving from X430
    # down to X419 the first such pulse position is X420 (touching: the gray band); a stop at X420.002 is clear
    text = HEADER + f"G0 X430 Y200 Z100\nG1 Z40 F300\nG1 X{x_end}\nG0 Z100\nM30\n"
    r = _run(text)
    if alarm_x is None:
        assert r.alarms == ()
    else:
        a = r.alarms[0]
        assert (a.kind, a.zone, a.line, a.position[0]) == ("solid", "clamp", 6, alarm_x)
        assert a.part.startswith("cutter")


TWO_TOOLS = machine_text("mill_two_tools_block")


def test_a_tool_change_at_rest_is_checked_where_the_new_tool_is_put():
    # G0 Z200 with H1 = 50 puts the gauge line at machine Z250: tool 1's cutter is 200..250, above the block
    # (top 120). The tool change puts tool 2 (H2 = 150: tip at 100, drill 100..250, radius 2) there, down to
    # the block's heights: at X20 its axis is 10 from the block's face X10, beyond 2 + 0.01: clear. At X11 (1
    # from the face) the drill's side is in the block at once, before the dwell's (empty) motion
    for x, hit in (("20", False), ("11", True)):
        text = f"G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X{x} Y0 Z200\nT2 M6\nG43 H2\nG4 P1\nG0 Z250\nM30\n"
        machine = parse_machine(TWO_TOOLS)
        r = _run(text, machine)
        if not hit:
            assert r.alarms == ()
            continue
        a = r.alarms[0]
        assert a.kind == "solid" and a.part.startswith("long drill") and a.position == (F(11), F(0), F(250))
        assert a.line == 7  # the first block run with H2 (the dwell)
        # nothing moved after the change: the alarm is at rest, before the first pulse of the next block
        assert r.program_position == (F(11), F(0), F(250))


def test_under_g49_only_the_spindle_parts_are_checked():
    # tools are described but no length register is active: the tool is not known (the prover says unknown,
    # VF211); the controller still checks what is always on the spindle. The nose (Ø120 from the gauge line
    # up) at X80 reaches X140, inside the jaw once the gauge line is below Z60 (+ half a pulse)
    r = _run("G21 G90 G54\nG0 X80 Y40 Z300\nG1 Z50 F1000\nM30\n")
    a = r.alarms[0]
    assert a.kind == "solid" and a.part.startswith("spindle nose") and a.position == (F(80), F(40), F(60))


def test_without_solids_the_monitor_is_unchanged():
    assert MachineSolids.of(load_machine(ROOT / "specs/machines/grinder.toml")) is None


# ----------------------------------------------------------------- the gap between pulse positions

small = st.integers(-400, 400).map(lambda v: Fraction(v, 100))


@settings(max_examples=15, deadline=None)
@given(st.lists(st.tuples(small, small, small, st.sampled_from(["G1", "G2", "G3"])), min_size=1, max_size=3))
def test_steps_are_at_most_one_pulse_per_axis(moves):
    """The half-step growth covers the gap between two pulse positions only if the axes move at most one
    pulse per step: lines, arcs and helices (the lanes the solids are proved on)."""
    machine = parse_machine(TWO_TOOLS)
    lines, px, py = ["G21 G90 G17 G54", "G0 X0 Y0 Z200"], F(0), F(0)
    for x, y, z, g in moves:
        if g == "G1" or (x == px and y == py):
            lines.append(f"G1 X{fd(x)} Y{fd(y)} Z{fd(200 + z)} F3000")
        else:  # centre at the midpoint's side: an R-free I J arc ending exactly on its circle (half turn)
            lines.append(f"{g} X{fd(2 * x - px)} Y{fd(2 * y - py)} Z{fd(200 + z)} I{fd(x - px)} J{fd(y - py)} F3000")
            x, y = 2 * x - px, 2 * y - py
        px, py = x, y
    segs = list(interpret_text("\n".join(lines) + "\nM30\n", machine, fast=False).segments())
    for engine in ("vector", "reference"):
        ctl = Controller(machine, settings=Settings(engine=engine), start=segs[0].start)
        for seg in segs:
            plan = ctl.plan(seg)
            plan.materialize()
            rows = np.vstack([np.array(plan.p0, dtype=np.int64)] + [np.array(p, dtype=np.int64).reshape(1, -1)
                                                                     for p in plan.iter_steps()])
            assert np.abs(np.diff(rows, axis=0)).max(initial=0) <= 1
            ctl.prog[:] = plan.p1


def test_the_controller_has_its_own_distance_computation():
    """It may share the machine-file model (nczones.solids), never the prover's code."""
    for path in (ROOT / "nczones/controller").glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                mod = ("." * node.level) + (node.module or "")
                assert "prover" not in mod, (path.name, mod)
            elif isinstance(node, ast.Import):
                assert all("prover" not in a.name for a in node.names), path.name


# ----------------------------------------------------------------- a lathe's turret tool, prisms, frames

LATHE = ROOT / "specs" / "machines" / "lathe_solids.toml"


def test_lathe_boring_bar_alarms_where_the_holder_meets_the_jaws():
    # specs/machines/lathe_solids.toml: tool offset 1 = X100 Z100.. (X100, Z150), G54 Z130, X words diameters;
    # machine X = X word / 2 + 100, machine Z = Z word + 130 + 150. The tip is (machine X - 100, machine Z - 150).
    # The bar holder: x -30..45, z 35..95 from the tip, 40 thick -> x -50..65 (grown by half its thickness);
    # the jaws: radii 30..70 (a ring), Z 60..90. On "G01 Z-77." at X30. (machine X115, tip X15) the holder
    # covers tip X -35..80, which meets the ring's (30, 70); its bottom is machine Z - 150 + 35 - 0.0005 (half
    # a Z pulse), below the jaws' top 90 once machine Z < 205.0005: going down from 207 by 0.001 the first
    # pulse position is Z205 (touching: the half-pulse gray band). Both engines alarm there.
    lathe = load_machine(LATHE)
    text = "%\nO1\nG21 G18 G99 G40\nT0101\nG00 X30. Z-73.\nG01 Z-77. F0.1\nM30\n%\n"
    got = [simulate(interpret_text(text, lathe, fast=False), lathe, mode="check", start=(F(115), F(210)),
                    settings=Settings(engine=e)).alarms[0] for e in ("vector", "reference")]
    assert got[0] == got[1]
    a = got[0]
    assert (a.kind, a.zone, a.line, a.position) == ("solid", "jaws", 6, (F(115), F(205)))
    assert a.part == "bar holder (X -30..45, Z 35..95 from the tip, 40 thick)"
    # the bundled example: the same contact on its too-deep bore (line 7), the fixed bore runs clean
    hits = (ROOT / "specs/examples/programs/boring_bar_hits_chuck.nc").read_text()
    r = simulate(interpret_text(hits, lathe), lathe, mode="check")
    assert (r.alarms[0].zone, r.alarms[0].line, r.alarms[0].position) == ("jaws", 7, (F(115), F(205)))
    assert r.notes == ()
    clears = (ROOT / "specs/examples/programs/boring_bar_clears_chuck.nc").read_text()
    assert simulate(interpret_text(clears, lathe), lathe, mode="check").alarms == ()


LINUXCNC_LATHE = machine_text("lathe_xz_insert_centre")  # tests/machines/lathe_xz_insert_centre.toml


@pytest.mark.parametrize("x, hit_x", [
    # the insert (x 0..4 from the tip, grown by half a pulse: -0.005..4.005) beside the centre (radius 10,
    # solid: the section -10 < x < 10), its tip at machine Z - 20 (H1) + 0..6 within 0..50 at Z50. Going
    # from X20 to X`x` the insert meets (-10, 10) once X - 0.005 < 10: the first pulse position is X10
    ("5", F(10)),
    # beyond the centre line: coming from X-30 the insert's right side X + 4.005 > -10 once X > -14.005: X-14
    ("0", None),
])
def test_linuxcnc_lathe_insert_against_a_solid_centre(x, hit_x):
    machine = parse_machine(LINUXCNC_LATHE)
    start = "G0 X20 Z50" if hit_x is not None else "G0 X-30 Z50"
    text = f"G21 G18 G90 G54\nG43 H1\n{start}\nG1 X{x} F1000\nM30\n"
    r = simulate(interpret_text(text, machine, fast=False), machine, mode="check")
    a = r.alarms[0]
    assert a.kind == "solid" and a.zone == "centre" and a.part.startswith("insert") and a.line == 4
    assert a.position[0] == (hit_x if hit_x is not None else F(-14))


PRISM = TWO_TOOLS.replace("""[[fixtures]]
name = "block"
kind = "box"
min = { X = "-10", Y = "-10", Z = "0" }
max = { X = "10", Y = "10", Z = "120" }
""", """[[zones]]
name = "wedge"
kind = "polygon"
forbid = true
plane = ["X", "Y"]
vertices = [["0", "0"], ["40", "0"], ["0", "30"]]
min = { Z = "0" }
max = { Z = "20" }
""")


@pytest.mark.parametrize("path, alarm", [
    # tool 1's cutter: radius 3, 0..50 above the tip (H1 = 50), grown by (0.01 + 0.01) / 2 = 0.01 to 3.01;
    # the tip at Z10 (within the wedge's heights 0..20). The wedge: the triangle (0,0) (40,0) (0,30); its
    # hypotenuse 3x + 4y = 120 (length 50). A point (x, y) beyond it is at distance (3x + 4y - 120) / 5: along
    # the diagonal y = x moving down, (7x - 120) / 5 < 3.01 once x < 19.29: the first pulse position from
    # X30 Y30 is X19.28 Y19.28 (distance 2.99.. at 19.28, 3.004 at 19.29 is still < 3.01: X19.29)
    ("G0 X30 Y30 Z10\nG1 X10 Y10 F1000", (F("19.29"), F("19.29"))),
    # past the vertex (40, 0) from the right along Y = -2: the distance to the vertex is √((x-40)² + 4) <
    # 3.01 once (x - 40)² < 3.01² - 4 = 5.0601: x - 40 < 2.2494..: the first pulse position X42.24
    ("G0 X60 Y-2 Z10\nG1 X30 F1000", (F("42.24"), F(-2))),
    # above the wedge's top (Z20): the cutter's bottom is Z - 50 - 0.005: at Z70.01 it is 20.005 > 20: clear
    ("G0 X10 Y10 Z80\nG1 Z70.01 F1000", None),
])
def test_prism_fixture(path, alarm):
    machine = parse_machine(PRISM)
    text = f"G21 G90 G17 G54\nT1 M6\nG43 H1\n{path}\nM30\n"
    results = [simulate(interpret_text(text, machine, fast=False), machine, settings=Settings(engine=e))
               for e in ("vector", "reference")]
    assert results[0].alarms == results[1].alarms
    if alarm is None:
        assert results[0].alarms == () and results[0].completed
        return
    a = results[0].alarms[0]
    assert (a.kind, a.zone, a.line) == ("solid", "wedge", 5) and a.part.startswith("cutter")
    assert a.position[:2] == alarm


FRAMED = TWO_TOOLS.replace('G54 = { X = "0", Y = "0", Z = "0" }', 'G54 = { X = "0", Y = "0", Z = "0" }\n'
                           'G55 = { X = "100", Y = "0", Z = "0" }').replace('name = "block"', 'name = "block"\n'
                                                                               'frame = "G55"')


def test_a_fixture_moves_with_its_work_offset():
    # the block is X -10..10, Y -10..10, Z 0..120 in G55, whose origin is machine X100: machine X 90..110.
    # Tool 1's cutter (radius 3 + 0.01) at Y0, tip Z100 in G55 (inside the heights). Moving in G55 from X-30
    # to X0 it meets the block once X - 100 > -10 - 3.01 (machine), i.e. program X > -13.01: the first pulse
    # position is program X-13, machine X87
    machine = parse_machine(FRAMED)
    run = "G0 X-30 Y0 Z100\nG1 X0 F1000\nM30\n"
    r = _run("G21 G90 G17 G55\nT1 M6\nG43 H1\n" + run, machine)
    a = r.alarms[0]
    assert (a.kind, a.zone, a.line, a.position[0]) == ("solid", "block", 5, F(87))
    # G10 L2 P2 X150 moves G55 (and the block with it) to machine X 140..160: the same moves are in the clear
    # until program X-13 again, machine X137
    r = _run("G21 G90 G17 G55\nG10 L2 P2 X150\nT1 M6\nG43 H1\n" + run, machine)
    assert (r.alarms[0].zone, r.alarms[0].position[0]) == ("block", F(137))
    # run in G54: where G55 is then is not followed (the prover says unknown, VF219): not checked, and noted
    r = _run("G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X70 Y0 Z100\nG1 X100 F1000\nM30\n", machine)
    assert r.alarms == () and any("`block`" in n and "VF219" in n for n in r.notes), r.notes


def test_forbidden_zones_that_are_no_fixture_are_named():
    """A forbidden polygon outside the XY plane is no fixture solid: the prover says unknown (VF210); the
    controller notes that it does not check the tool solids against it either."""
    machine = parse_machine(TWO_TOOLS + """[[zones]]
name = "rib"
kind = "polygon"
forbid = true
plane = ["X", "Z"]
vertices = [["50", "0"], ["60", "0"], ["50", "10"]]
""")
    r = _run("G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X0 Y0 Z200\nM30\n", machine)
    assert any("`rib`" in n for n in r.notes), r.notes


POLYGONS = machine_text("xyz_polygon_room_wedge")  # tests/machines/xyz_polygon_room_wedge.toml


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.integers(-1100, 1100), st.integers(-1100, 1100), st.integers(-150, 250)), min_size=1,
                max_size=40), st.sampled_from([Fraction(0), Fraction(1, 2)]))
def test_compiled_polygon_zones_decide_as_the_reference(rows, tool_length):
    """The monitor's vectorized polygon test (a float screen, exact next to an edge; the tool solids' prisms
    and the contract's tip polygons run on it) gives the reference monitor's answer at every pulse position:
    an L-shaped allowed polygon with a Z floor and a forbidden tip triangle with a Z range, positions on a
    0.01 grid through their edges and vertices."""
    from nczones.controller.monitor import LimitMonitor

    mon = LimitMonitor(parse_machine(POLYGONS))
    edges = [(0, 0, 0), (1000, -1000, 0), (0, 500, -100), (1000, -1, 0), (-400, -400, 50), (0, -400, 50),
             (400, -400, 100), (0, -100, 50), (-400, 200, 20), (-399, 199, 20), (0, -101, 0), (-399, 100, 150)]
    pos = np.array(edges + rows, dtype=np.int64)
    compiled = mon.compile(tool_length)
    assert compiled is not None
    got = compiled.bad(pos).tolist()
    assert got == [bool(mon.check(tuple(int(v) for v in row), tool_length)) for row in pos]
