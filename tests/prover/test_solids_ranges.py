"""Tool solids with parameter ranges and fixtures in work offsets (issue 39): ranges move the solids (a work
offset range the path, a tool-length range the spindle against the tip), fixtures placed with ``frame`` move
with their work offset as the program sets it; range verdicts against concrete values (metamorphic), and the
prover against the independent oracle of tests/oracles/solids.py at concrete values."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import MachineFileError
from nczones.gcode import segments_text
from nczones.machine import load_machine, parse_machine
from nczones.prover import verify_text
from nczones.solids import FixtureBox, machine_solids
from tests.oracles.concrete import machine_at
from tests.oracles.solids import inside_part_and_fixture, sampled_hit

F = Fraction
ROOT = Path(__file__).resolve().parents[2]
MACHINE = ROOT / "specs/machines/mill_solids.toml"
MILL_TEXT = MACHINE.read_text(encoding="utf-8")
CLEARS = (ROOT / "specs/examples/programs/holder_clears_vise.ngc").read_text(encoding="utf-8")
HOLDER = "holder (Ø63 × 60 at 40..100 above the tip)"


def _mill():
    return load_machine(MACHINE)


def _clearance(r, part=HOLDER, fixture="vise"):
    return {(p, f): c for p, f, c, _ in r.extra["clearance"]}.get((part, fixture))


# holder_clears_vise.ngc (specs/examples/programs): G54 = 0, H1 = 100; the tip plunges to Z10 at X60 Y40 and
# feeds to Y20. The holder (radius 31.5, 40..100 above the tip) then reaches X 60 + 31.5 = 91.5 below the
# jaw's top Z60; the jaw's face is X100: 8.5 mm clear. A G54.X deviation d moves the path by d in X.

@pytest.mark.parametrize("param, verdict, clearance", [
    ("G54.X=-5..5", "safe", F(7, 2)),     # 8.5 - 5: the holder reaches 96.5 at most
    ("G54.X=-8.5..8.5", "safe", F(0)),    # touching the jaw at d = 8.5 is allowed (its interior is forbidden)
    ("G54.X=0..10", "unknown", None),     # nominal 0 clears; d > 8.5 enters: not safe, no witness value
    ("G54.X=15..25", "unsafe", None),     # the case is built at d = 20 (the range's middle): the holder enters
])
def test_work_offset_range_moves_the_tool_solids(param, verdict, clearance):
    r = verify_text(CLEARS, _mill(), params=[param])
    assert r.verdict.label == verdict, (r.reasons, r.violations)
    if verdict == "safe":
        assert _clearance(r) == clearance
        assert not [x for x in r.reasons if x.code == "VF212"]
    if verdict == "unknown":
        assert {x.code for x in r.reasons} == {"VF218"}
    if verdict == "unsafe":
        v = r.violations[0]
        assert v.kind == "solid" and v.zones == ("holder",) and v.line == 6 and dict(v.params) == {"G54.X": 20}
        # the witness at its own value: X60 + 20 = 80, holder reaching 111.5 into the jaw (X100..250)
        at = verify_text(CLEARS, machine_at(_mill(), {"G54.X": F(20)}))
        assert at.verdict.label == "unsafe" and at.violations[0].line == 6


def test_tool_length_range_moves_the_spindle_not_the_tool_parts():
    """Machine Z is the tip plus the length: a tool-length range moves the gauge line (and the spindle nose)
    against the tip, while the tool's parts stay where the tip is. H1 = 90..110 keeps the holder 8.5 clear
    (not 8.5 minus the range); H1 = 40..100 lets the spindle nose (radius 60 from the gauge line up) down to
    the tip + 40 = Z50, below the jaw's top 60, reaching X 60 + 60 = 120 > 100: unknown over the range (the
    nominal 100 clears), and unsafe at the concrete H1 = 40 (metamorphic: a concrete unsafe value => the range
    is not safe)."""
    r = verify_text(CLEARS, _mill(), params=["H1=90..110"])
    assert r.verdict.label == "safe", r.reasons
    assert _clearance(r) == F(17, 2)
    r = verify_text(CLEARS, _mill(), params=["H1=40..100"])
    assert r.verdict.label == "unknown" and {x.code for x in r.reasons} == {"VF218"}
    assert any("spindle nose" in x.message for x in r.reasons)
    at = verify_text(CLEARS, machine_at(_mill(), {"H1": F(40)}))
    assert at.verdict.label == "unsafe" and at.violations[0].zones == ("spindle nose",)


def _long(x: str) -> str:
    """More than 512 motions (zig-zags far from the jaw), then one plunge at X``x``."""
    body = "".join(f"G1 X{-50 + (i % 2) * 10} Y{i % 50}\n" for i in range(600))
    return ("G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X-50 Y0 Z100\nG1 Z10 F500\n" + body
            + f"G0 Z100\nG0 X{x} Y40\nG1 Z10\nG0 Z100\nM30\n")


@pytest.mark.parametrize("param, verdict", [("G54.X=-5..5", "safe"), ("G54.X=5..15", "unsafe")])
def test_ranges_on_a_long_program(param, verdict):
    # X60 with d in -5..5: 3.5 clear; with 5..15 the case is built at d = 10: X70, the holder reaches 101.5
    r = verify_text(_long("60"), _mill(), params=[param])
    assert r.verdict.label == verdict, (r.reasons, r.violations)
    if verdict == "unsafe":
        assert r.violations[0].line == 5 + 600 + 3 and dict(r.violations[0].params) == {"G54.X": 10}


def test_ranges_on_a_parametric_program():
    # with ranges the double pass is not taken: '#' programs go through the full interpreter
    text = "#1 = 60\nG21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X#1 Y40 Z100\nG1 Z10 F300\nG0 Z100\nM30\n"
    assert verify_text(text, _mill(), params=["G54.X=-5..5"]).verdict.label == "safe"
    assert verify_text(text, _mill(), params=["G54.X=0..10"]).verdict.label == "unknown"


# --------------------------------------------------------------------------- fixtures in work offsets

FRAMED = MILL_TEXT.replace('G54 = { X = "0", Y = "0", Z = "0" }',
                           'G54 = { X = "300", Y = "200", Z = "0" }\nG55 = { X = "0", Y = "0", Z = "0" }') + """
[[fixtures]]
name = "stop"             # a stop block on the part, in G54: X 0..20, Y 0..20, Z 0..30 of the work
kind = "box"
frame = "G54"
min = { X = "0", Y = "0", Z = "0" }
max = { X = "20", Y = "20", Z = "30" }
"""
CUTTER = "cutter (Ø10 × 25 at 0..25 above the tip)"


def test_a_fixture_in_a_work_offset_moves_with_it():
    """The stop is at machine X 300..320 with G54 = X300. The cutter (radius 5, the tip at Z10 below the stop's
    top 30) at program X-6 Y10 is 1 mm clear of the stop's face X0, at X-4 1 mm inside. After G10 L2 P1 X280
    the stop is at machine X 280..300: a G53 move to machine X 306 (G54 X26) is 1 mm clear of its face X300
    (G54 X20), at machine X 304 1 mm inside."""
    m = parse_machine(FRAMED, "framed.toml")
    head = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X-30 Y10 Z100\nG1 Z10 F300\n"
    r = verify_text(head + "G1 X-6\nG0 Z100\nM30\n", m)
    assert r.verdict.label == "safe", (r.reasons, r.violations)
    assert _clearance(r, CUTTER, "stop") == 1
    r = verify_text(head + "G1 X-4\nG0 Z100\nM30\n", m)
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "stop" and r.violations[0].line == 6
    stop = FixtureBox("stop", F(300), F(320), F(200), F(220), F(0), F(30))
    cutter = machine_solids(m).tools[1][0]
    v = r.violations[0]
    assert inside_part_and_fixture(tuple(x for _, x in v.point), tuple(x for _, x in v.path_point), cutter, stop,
                                   F(100))
    moved = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG10 L2 P1 X280\nG53 G0 X{x} Y210 Z200\nG53 G1 Z110 F300\nM30\n"
    r = verify_text(moved.format(x=306), m)
    assert r.verdict.label == "safe", (r.reasons, r.violations)
    assert _clearance(r, CUTTER, "stop") == 1
    r = verify_text(moved.format(x=304), m)
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "stop" and r.violations[0].line == 6


def test_a_fixture_in_another_work_offset_is_unknown_and_ranges_of_its_offset_cancel():
    """In G55 the solids proof does not know where G54 is now (a G10 L2 P1 may have moved it): unknown
    (VF219). A G54 range moves the path and the stop alike: the 1 mm clearance stays exact."""
    m = parse_machine(FRAMED, "framed.toml")
    r = verify_text("G21 G90 G17 G55\nT1 M6\nG43 H1\nG0 X0 Y0 Z300\nM30\n", m)
    assert r.verdict.label == "unknown" and {x.code for x in r.reasons} == {"VF219"}
    text = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X-30 Y10 Z100\nG1 Z10 F300\nG1 X-6\nG0 Z100\nM30\n"
    r = verify_text(text, m, params=["G54.X=-3..3", "G54.Y=-2..2"])
    assert r.verdict.label == "safe", (r.reasons, r.violations)
    assert _clearance(r, CUTTER, "stop") == 1


FANUC_FRAMED = MILL_TEXT.replace('path_mode = "G61"', 'path_mode = "G61"\ndialect = "fanuc"').replace(
    'G54 = { X = "0", Y = "0", Z = "0" }',
    'EXT = { X = "7", Y = "0", Z = "0" }\nG54 = { X = "0", Y = "0", Z = "0" }\n'
    '"G54.1P1" = { X = "300", Y = "200", Z = "0" }') + "[[fixtures]]" + FRAMED.split("[[fixtures]]")[-1].replace(
    'frame = "G54"', 'frame = "G54.1 P1"')


@pytest.mark.parametrize("program, verdict", [
    # in G54.1 P1 (machine X = EXT 7 + 300 + program X): the stop's face is program X0 as in G54 above
    ("G0 X-30 Y10 Z100\nG1 Z10 F300\nG1 X-6\nG0 Z100", "safe"),
    ("G0 X-30 Y10 Z100\nG1 Z10 F300\nG1 X-4\nG0 Z100", "unsafe"),
    # G10 L20 P1 X280 (Fanuc 0i "Programmable data input"): the stop at machine X 7 + 280 = 287 .. 307; the
    # cutter at machine X313 is 1 clear of its face, at X311 1 inside
    ("G10 L20 P1 X280\nG53 G0 X313 Y210 Z200\nG53 G0 Z110", "safe"),
    ("G10 L20 P1 X280\nG53 G0 X311 Y210 Z200\nG53 G0 Z110", "unsafe"),
])
def test_fanuc_fixture_in_an_additional_work_offset(program, verdict):
    m = parse_machine(FANUC_FRAMED, "fanuc_framed.toml")
    r = verify_text("G21 G90 G17 G54.1 P1\nT1 M6\nG43 H1 Z200\n" + program + "\nM30\n", m)
    assert r.verdict.label == verdict, (r.reasons, r.violations)
    if verdict == "unsafe":
        v = r.violations[0]
        assert (v.zone, v.zones, v.line) == ("stop", ("cutter",), 6)


@pytest.mark.parametrize("frame, ok", [('"G54"', True), ('"g54.1 p3"', True), ('"G53"', False), ("54", False)])
def test_fixture_frame_errors(frame, ok):
    text = FRAMED.replace('frame = "G54"', f"frame = {frame}")
    if ok:
        parse_machine(text, "m.toml")
        return
    with pytest.raises(MachineFileError) as e:
        parse_machine(text, "m.toml")
    d = e.value.diagnostics[0]
    assert d.code == "ZN170" and d.span is not None
    assert d.span.line == next(i for i, ln in enumerate(text.splitlines(), 1) if ln.startswith("frame ="))


# --------------------------------------------------------------------------- ranges against concrete values

# The oracle machine of tests/prover/test_solids.py (G54 = 0, H1 = 50, H2 = 80, the jaw box, the post
# cylinder) with a prism (a forbidden triangle plate in XY over Z 0..20) and a stop box in G54 (moved to
# X5 Y-3 Z0 here so the frame matters).
from tests.prover.test_solids import ORACLE_MACHINE, programs  # noqa: E402

RANGE_MACHINE = ORACLE_MACHINE.replace('G54 = { X = "0", Y = "0", Z = "0" }',
                                       'G54 = { X = "5", Y = "-3", Z = "0" }') + """
[[zones]]
name = "plate"
kind = "polygon"
forbid = true
point = "tip"
plane = ["X", "Y"]
vertices = [["-40", "-10"], ["-10", "-30"], ["-20", "0"]]
min = { Z = "0" }
max = { Z = "20" }
[[fixtures]]
name = "stop"
kind = "box"
frame = "G54"
min = { X = "20", Y = "-40", Z = "0" }
max = { X = "30", Y = "-25", Z = "15" }
"""

half = st.integers(-12, 12).map(lambda v: Fraction(v, 2))


@st.composite
def ranges(draw):
    name = draw(st.sampled_from(["G54.X", "G54.Y", "G54.Z", "H1", "H2"]))
    a, b = sorted((draw(half), draw(half)))
    if name.startswith("H"):  # absolute tool lengths about the file's 50 / 80
        base = 50 if name == "H1" else 80
        a, b = a + base, b + base
    return name, a, b


def _fmt(v: Fraction) -> str:
    return str(v.numerator) if v.denominator == 1 else f"{float(v)}"


def _placed(machine):
    """The machine's fixtures where they are (the oracle's placement: a fixture in G54 moved by the machine
    file's G54; these programs never change it)."""
    g54 = dict(zip(machine.axis_names, machine.offset("G54")))
    out = []
    for fx in machine_solids(machine).fixtures:
        if getattr(fx, "frame", ""):
            fx = FixtureBox(fx.name, fx.x0 + g54["X"], fx.x1 + g54["X"], fx.y0 + g54["Y"], fx.y1 + g54["Y"],
                            fx.z0 + g54["Z"], fx.z1 + g54["Z"])
        out.append(fx)
    return out


def _oracle(text, machine, result):
    """The first part-in-fixture sample of ``text`` on ``machine`` (None: none); every solid violation of
    ``result`` has its contact point inside the part and the fixture."""
    solids = machine_solids(machine)
    fixtures = _placed(machine)
    segs = segments_text(text, machine, fast=False)
    for v in result.violations:
        if v.kind == "solid":
            seg = next(s for s in segs if s.block == v.block)
            part = next(p for p in solids.parts_for(seg.tool_register) if p.name in v.zones)
            fx = next(f for f in fixtures if f.name == v.zone)
            assert inside_part_and_fixture(tuple(x for _, x in v.point), tuple(x for _, x in v.path_point), part,
                                           fx, seg.tool_length), v.note
    for seg in segs:
        parts = solids.parts_for(seg.tool_register)
        hit = sampled_hit(seg, parts, fixtures, 32) if parts else None
        if hit is not None:
            return hit
    return None


def _range_against_values(text, rng):
    range_against_values(text, parse_machine(RANGE_MACHINE, "ranges.toml"), rng, _oracle)


def range_against_values(text, machine, rng, oracle):
    """Over the range ``rng`` and at its ends and middle: the range's ``safe`` holds at every value (the
    prover's and the oracle's verdict there), a concrete ``unsafe`` or oracle hit makes the range not
    ``safe``, a concrete ``safe`` has no oracle hit, and a range witness replays at its own values.
    ``oracle(text, machine, result)``: the oracle's first part-in-fixture sample (None: none).  The range's
    result."""
    name, lo, hi = rng
    r = verify_text(text, machine, params=[f"{name}={_fmt(lo)}..{_fmt(hi)}"])
    for value in sorted({lo, hi, (lo + hi) / 2}):
        at = machine_at(machine, {name: value})
        concrete = verify_text(text, at)
        hit = oracle(text, at, concrete)
        if concrete.verdict.label == "safe":
            assert hit is None, f"safe at {name}={value}, the oracle finds {hit[0].name} in {hit[1].name}"
        if r.verdict.label == "safe":
            assert concrete.verdict.label == "safe", f"safe over {name}={lo}..{hi}, {concrete.verdict} at {value}"
        if concrete.verdict.label == "unsafe" or hit is not None:
            assert r.verdict.label != "safe"
    for v in r.violations:  # a witness replays at its own values
        if v.kind == "solid":
            again = verify_text(text, machine_at(machine, dict(v.params)))
            assert again.verdict.label == "unsafe" and any(w.line == v.line for w in again.violations), v.note
    return r


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs(), ranges())
def test_range_verdict_against_concrete_values(text, rng):
    _range_against_values(text, rng)


@pytest.mark.long
@settings(max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs(), ranges())
def test_range_verdict_against_concrete_values_long(text, rng):
    _range_against_values(text, rng)


# --------------------------------------------------------------------------- tool-break recovery

RECOVERY_PROGRAM = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X430 Y150 Z100\nG1 Z10 F300\nG1 Y250\nG0 Z100\nM30\n"


def _recovery_mill(clearance: str, register: str = "H1"):
    return parse_machine(MILL_TEXT.replace('H1 = "100"', 'H1 = "100"\nH2 = "60"') + (
        f'\n[tool_change]\nposition = {{ X = "300", Y = "200", Z = "150" }}\nclearance = "{clearance}"\n'
        f'approach_distance = "5"\napproach_feed = "200"\nvariant = "breakpoint"\nlength_register = "{register}"\n'),
        "recovery.toml")


def _oracle_recovery_hit(machine, n: int = 8):
    """The oracle over break points ``s = k / n`` of every cutting line: the recovery legs from there (the
    shared plan, nczones.plans.recovery.recovery_legs, as the controller moves them) sampled against the fixtures."""
    from nczones.plans.recovery import recovery_legs, replacement_length, tool_change_config

    cfg = tool_change_config(machine, "breakpoint")
    solids = machine_solids(machine)
    for seg in segments_text(RECOVERY_PROGRAM, machine, fast=False):
        if seg.kind.name != "LINE":
            continue
        for k in range(n + 1):
            P = tuple(a + F(k, n) * (b - a) for a, b in zip(seg.start, seg.end))
            legs = recovery_legs(cfg, machine, P, P, seg.tool_length, replacement_length(cfg, machine, seg.tool_length))
            for leg in legs:
                hit = sampled_hit(leg.segment(machine.axis_names, seg), solids.parts_for(seg.tool_register),
                                  solids.fixtures, 24)
                if hit is not None:
                    return seg.line, F(k, n), leg.name, hit
    return None


def test_recovery_legs_are_proved_for_the_tool_solids():
    """RECOVERY_PROGRAM cuts at X430 from Y150 to Y250 with the tip at Z10 (machine Z110), beside the clamp
    post (X400 Y200, radius 15, up to Z50; a [[fixtures]] entry only, so the tip itself may pass through it).
    After a break the control rapids to the tool change at machine X300 Y200 Z150 (the tip at Z50, rapids
    linear). With clearance 110 there is no retract: from the break at Y200 (s = 1/2) the leg runs straight
    over the post, the tip at machine Z 110 + 40 · 30/130 ≈ 119.2 (tip Z19.2) at X400: the cutter is in the
    post. With clearance 200 the tip first rises to Z100, and on the way to the tool change at X400 + 20 it is
    at Z 100 - 50 · 10/130 > 50 (above the post), back to the restart it climbs from Z50 at X300 to Z100,
    above 50 from X385 - 5 on: proved (the oracle over sampled break points agrees). Before issue 39's
    recovery for solids both were unknown (VF212)."""
    hit = _recovery_mill("110")
    r = verify_text(RECOVERY_PROGRAM, hit, recovery="breakpoint")
    assert r.verdict.label == "unsafe", (r.reasons, r.violations)
    v = r.violations[0]
    assert (v.kind, v.leg, v.break_line, v.zone, v.zones) == ("recovery", "to tool change", 6, "clamp", ("cutter",))
    assert v.break_parameter == F(1, 2) and dict(v.break_point) == {"X": 430, "Y": 200, "Z": 110}
    cutter = machine_solids(hit).tools[1][0]
    clamp = next(f for f in machine_solids(hit).fixtures if f.name == "clamp")
    assert inside_part_and_fixture(tuple(x for _, x in v.point), tuple(x for _, x in v.path_point), cutter, clamp,
                                   F(100))
    assert _oracle_recovery_hit(hit) is not None
    from nczones.report.text import render_text

    text = render_text(r, deterministic=True)
    assert "recovery rapid (tool-break recovery: to tool change): the cutter enters fixture `clamp`" in text
    # also with a shorter replacement (H2 = 60): the resumed cut and the legs after the tool change run with
    # the spindle 40 lower against the tip; its nose (from the tip + 60 up) stays above the post's top 50
    for machine in (_recovery_mill("200"), _recovery_mill("200", "H2")):
        r = verify_text(RECOVERY_PROGRAM, machine, recovery="breakpoint")
        assert r.verdict.label == "safe", (r.reasons, r.violations)
        assert _oracle_recovery_hit(machine) is None
