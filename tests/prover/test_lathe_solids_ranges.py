"""A lathe's tool solids with parameter ranges and with tool-break recovery (issue 39, the lathe case): ranges
move the turret tool against the chuck (a work offset or homing range the path, a tool-length range nothing:
the tip is the controlled point minus the length), range verdicts against concrete values (metamorphic,
with the independent oracle of tests/oracles/lathe_solids.py), and recovery legs proved with the turret
tool's solids.  Before this, both were ``unknown`` (VF212)."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode import segments_text
from nczones.machine import load_machine, parse_machine
from nczones.prover import verify, verify_text
from nczones.solids import machine_solids
from tests.oracles.concrete import machine_at
from tests.oracles.lathe_solids import part_meets, sampled_hit, tip_of, tool_of
from tests.prover.test_lathe_solids import LINUXCNC, ORACLE, _long, programs
from tests.prover.test_solids_ranges import range_against_values

F = Fraction
ROOT = Path(__file__).resolve().parents[2]
MACHINE = ROOT / "specs/machines/lathe_solids.toml"
CLEARS = str(ROOT / "specs/examples/programs/boring_bar_clears_chuck.nc")
HOLDER = "bar holder (X -30..45, Z 35..95 from the tip, 40 thick)"


def _clearance(r, part=HOLDER, fixture="jaws"):
    return {(p, f): c for p, f, c, _ in r.extra["clearance"]}.get((part, fixture))


def _codes(r):
    return {x.code for x in r.reasons}


# boring_bar_clears_chuck.nc on specs/machines/lathe_solids.toml (G54 Z130, tool offset 1 Z150): the deepest
# tip is at Z 130 - 35 = 95 in the tip's frame, the holder's bottom (35 above the tip) at 130, 40 above the
# jaws' face Z 90, the holder's radial section overlapping the jaws' radii (the bundled example's
# derivation, tests/prover/test_lathe_solids.py).  A G54.Z deviation d (or a homing error d on Z) moves the
# path, and the holder, by d on Z: the gap is 40 + d.

@pytest.mark.parametrize("param, verdict, clearance", [
    ("G54.Z=-30..10", "safe", F(10)),     # 40 - 30
    ("home.Z=-30..0", "safe", F(10)),     # a homing error moves the machine, not the chuck
    ("G54.Z=-40..0", "safe", F(0)),       # touching the jaws' face at d = -40 is allowed
    ("G54.X=-10..10", "safe", F(40)),     # X moves the holder along the face: the Z gap stays
    ("H1=100..200", "safe", F(40)),       # no H register on a Fanuc lathe's T offsets: nothing moves
    ("G54.Z=-45..0", "unknown", None),    # d < -40 enters; the nominal 0 clears: no witness value
    ("home.Z=-50..0", "unknown", None),
    ("G54.Z=-50..-40", "unsafe", None),   # the case is built at d = -45 (the middle): the holder 5 deep
])
def test_ranges_move_a_lathes_tool_solids(param, verdict, clearance):
    lathe = load_machine(MACHINE)
    if param.startswith("H1"):  # give the register a nominal value the range holds
        lathe = parse_machine(MACHINE.read_text() + '\n[tool_lengths]\nH1 = "150"\n', "lathe.toml")
    r = verify(CLEARS, lathe, params=[param])
    assert r.verdict.label == verdict, (r.reasons, r.violations)
    assert "VF212" not in _codes(r)
    if verdict == "safe":
        assert _clearance(r) == clearance
    if verdict == "unknown":
        assert _codes(r) == {"VF218"} and any("bar holder" in x.message for x in r.reasons)
    if verdict == "unsafe":
        v = r.violations[0]
        assert (v.kind, v.zone, v.zones, v.line) == ("solid", "jaws", ("bar holder",), 7)
        assert dict(v.params) == {"G54.Z": -45}
        # the witness replays at its own value: the tip down to Z 85 + 0 ... the holder's bottom at 85 < 90
        at = verify(CLEARS, machine_at(lathe, {"G54.Z": F(-45)}))
        assert at.verdict.label == "unsafe" and at.violations[0].line == 7
        assert at.violations[0].zones == ("bar holder",)


def test_a_witness_at_the_nominal_values_wins_over_a_pair_the_ranges_may_bring_together():
    """boring_bar_hits_chuck.nc with G54.X = 0..10 (the nominal 0 in it): at line 7 (G01 Z-80. at X30., tip
    radius 15, down to tip Z 50) the insert, radii 8.5..17.5 with its thickness' growth, reaches the chuck
    (radii 25..100, Z 0..60) only when X moves by more than 7.5: a pair the ranges may bring together, not at
    the nominal value.  The bar holder enters the jaws at the nominal value (the example's derivation): the
    block is unsafe with that witness, not unknown because the insert's pair came first."""
    r = verify(str(ROOT / "specs/examples/programs/boring_bar_hits_chuck.nc"), load_machine(MACHINE),
               params=["G54.X=0..10"])
    assert r.verdict.label == "unsafe", (r.reasons, r.violations)
    v = next(v for v in r.violations if v.line == 7)
    assert (v.zone, v.zones, dict(v.params)) == ("jaws", ("bar holder",), {"G54.X": 0})
    assert not r.reasons


def test_a_tool_length_range_does_not_move_the_tip_on_linuxcnc():
    """LinuxCNC: G43 H1 puts the controlled point at the tip plus H1, so an H1 range moves the controlled path
    and the tip's offset alike: the parts stay where the program puts the tip.  The holder stops 35 above the
    tip at Z 130 - 35 = 95 (G54 Z130): 130 against the jaws' face 90, 40 clear whatever H1 is.  Only the first
    rapid starts from the machine's start position, which H1 does not move: there the tip moves by -d, and the
    proof encloses the displacement along the motion by its hull, at the rapid's end (tip Z 5 + 130 = 135,
    the holder's bottom 170) 170 - |d| - 90: 70 for H1 = 140..160 (the bore's 40 is the least), 30 for
    H1 = 100..200 (a lower bound).  A G54.Z range moves the tip (-30..10: 10 clear), also in a program with
    '#' (the full interpreter: with ranges the double pass is not taken)."""
    m = parse_machine(LINUXCNC, "m.toml")
    text = "#1 = -35\nG18 G21 G90 G54\nT1 M6\nG43 H1\nG0 X30 Z5\nG1 Z#1 F100\nG0 Z5\nM30\n"
    for param, clearance in (("H1=140..160", 40), ("H1=100..200", 30)):
        r = verify_text(text, m, params=[param])
        assert r.verdict.label == "safe", (r.reasons, r.violations)
        assert _clearance(r, "bar holder (X -30..45, Z 35..95 from the tip)") == clearance
    r = verify_text(text, m, params=["G54.Z=-30..10"])
    assert r.verdict.label == "safe", (r.reasons, r.violations)
    assert _clearance(r, "bar holder (X -30..45, Z 35..95 from the tip)") == 10
    r = verify_text(text, m, params=["G54.Z=-50..0"])
    assert r.verdict.label == "unknown" and _codes(r) == {"VF218"}


@pytest.mark.parametrize("param, verdict", [("G54.Z=-30..10", "safe"), ("G54.Z=-50..-40", "unsafe")])
def test_ranges_on_a_long_lathe_program(param, verdict):
    # more than 512 facing strokes far from the chuck, then the bore to Z-35 (40 clear nominal, as above)
    r = verify_text(_long("-35."), load_machine(MACHINE), params=[param])
    assert r.verdict.label == verdict, (r.reasons, r.violations[:1])
    if verdict == "unsafe":
        v = r.violations[0]
        assert v.zones == ("bar holder",) and v.line == 3 + 2 + 600 + 2 and dict(v.params) == {"G54.Z": -45}


# --------------------------------------------------------------------------- ranges against concrete values

half = st.integers(-16, 16).map(lambda v: Fraction(v, 2))


@st.composite
def ranges(draw):
    name = draw(st.sampled_from(["G54.X", "G54.Z"]))
    a, b = sorted((draw(half), draw(half)))
    return name, a, b


def _oracle_hit(text, machine, result=None):
    """The oracle's first part-in-fixture sample of ``text`` on ``machine`` (None: none)."""
    solids = machine_solids(machine)
    for seg in segments_text(text, machine, fast=False):
        tool = tool_of(seg)
        parts = solids.tools.get(tool, ()) if tool is not None else ()
        hit = sampled_hit(seg, parts, solids.fixtures, 32) if parts else None
        if hit is not None:
            return hit
    return None


def _range_against_values(text, rng):
    """The range verdict against its ends and middle (tests/prover/test_solids_ranges.py, with the lathe's
    oracle): a range ``safe`` holds at every value, a concrete ``unsafe`` or oracle hit makes it not ``safe``,
    a range witness replays at its own value."""
    r = range_against_values(text, parse_machine(ORACLE, "oracle.toml"), rng, _oracle_hit)
    assert "VF212" not in _codes(r)


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs(), ranges())
def test_range_verdict_against_concrete_values(text, rng):
    _range_against_values(text, rng)


@pytest.mark.long
@settings(max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs(), ranges())
def test_range_verdict_against_concrete_values_long(text, rng):
    _range_against_values(text, rng)


# --------------------------------------------------------------------------- tool-break recovery

RECOVERY = LINUXCNC.replace('{ name = "bar holder", x = ["-30", "45"], z = ["35", "95"] }',
                            '{ name = "bar", x = ["-8", "8"], z = ["0", "120"] }')
BORE = "G18 G21 G90 G54\nT1 M6\nG43 H1\nG0 X40 Z5\nG1 Z-60 F100\nG0 Z5\nM30\n"


def _tool_change(clearance: str, x: str = "200") -> str:
    return (f'\n[tool_change]\nposition = {{ X = "{x}", Z = "400" }}\nclearance = "{clearance}"\n'
            'approach_distance = "5"\napproach_feed = "200"\nvariant = "breakpoint"\n')


def _oracle_recovery_hit(text, machine, n: int = 16):
    """The oracle over break points ``s = k / n`` of every cutting line: the recovery legs from there (the shared
    plan, nczones.plans.recovery.recovery_legs, as the controller moves them, each leg with the cut's tool and
    tip offset) sampled against the fixtures in space.  None: no hit."""
    from nczones.plans.recovery import recovery_legs, replacement_length, tool_change_config

    cfg = tool_change_config(machine, "breakpoint")
    solids = machine_solids(machine)
    for seg in segments_text(text, machine, fast=False):
        parts = solids.tools.get(tool_of(seg), ())
        if seg.kind.name != "LINE" or not parts:
            continue
        for k in range(n + 1):
            P = tuple(a + F(k, n) * (b - a) for a, b in zip(seg.start, seg.end))
            L2 = replacement_length(cfg, machine, seg.tool_length)
            for leg in recovery_legs(cfg, machine, P, P, seg.tool_length, L2):
                moved = leg.segment(machine.axis_names, seg)
                hit = sampled_hit(moved, parts, solids.fixtures, 64)
                if hit is not None:
                    return seg.line, F(k, n), leg.name, hit
    return None


def test_a_recovery_leg_drives_the_bar_into_the_jaws():
    """A Ø16 bar (X -8..8, Z 0..120 from the tip) bores at radius 20 (X40 in G7) down to program Z-60: the tip
    at Z 130 - 60 = 70, the bar at radii 12..28, inside the jaws' bore (radius 30): the cut itself is clear.
    After a break at the bottom (machine X20 Z220: H1 = 150) the control retracts to clearance 220 (no move:
    already there) and rapids straight to the tool change at X200 Z400, a slope of 1: at machine X31 the tip is
    at X31 Z 231 - 150 = 81, the bar at radii 23..39 over Z 81..201, inside the jaws (radii 30..70, Z 60..90).
    With clearance 250 the retract lifts the tip to Z 100, above the jaws' face 90, before any X move: every
    leg keeps the bar above the jaws or inside their bore: proved."""
    m = parse_machine(RECOVERY + _tool_change("220"), "recovery.toml")
    assert verify_text(BORE, m).verdict.label == "safe"  # the program itself clears
    r = verify_text(BORE, m, recovery="breakpoint")
    assert r.verdict.label == "unsafe", (r.reasons, r.violations)
    v = r.violations[0]
    assert (v.kind, v.leg, v.break_line, v.zone, v.zones) == ("recovery", "to tool change", 5, "jaws", ("bar",))
    assert "bar (X -8..8, Z 0..120 from the tip) enters `jaws`" in v.note
    # the witness with the oracle's own test in space: the bar at the tip (path point less H1) meets the jaws
    x, z = (dict(v.path_point)[a] for a in "XZ")
    bx, bz = dict(v.break_point)["X"], dict(v.break_point)["Z"]
    assert z - bz == x - bx and bx == 20 and 220 <= bz <= 225  # on the leg (slope 1) from the bore's bottom
    bar = machine_solids(m).tools[1][0]
    jaws = machine_solids(m).fixtures[0]
    assert part_meets(bar, jaws, x, z - 150)
    hit = _oracle_recovery_hit(BORE, m)
    assert hit is not None and (hit[0], hit[2], hit[3][0]) == (5, "to tool change", bar)  # from the bore's deep end
    fixed = parse_machine(RECOVERY + _tool_change("250"), "recovery.toml")
    r = verify_text(BORE, fixed, recovery="breakpoint")
    assert r.verdict.label == "safe", (r.reasons, r.violations)
    assert not _codes(r)
    assert _oracle_recovery_hit(BORE, fixed) is None


def test_recovery_on_a_long_program_and_with_parameters():
    # the '#' program (the full interpreter) and more than 512 motions before the bore take the same proof
    m = parse_machine(RECOVERY + _tool_change("220"), "recovery.toml")
    text = "#1 = -60\n" + BORE.replace("Z-60", "Z#1")
    r = verify_text(text, m, recovery="breakpoint")
    assert r.verdict.label == "unsafe" and r.violations[0].zones == ("bar",)
    strokes = "".join(f"G1 X{120 + (i % 2) * 20} Z{5 + i % 7} F500\n" for i in range(600))
    long = BORE.replace("G0 X40 Z5\n", "G0 X120 Z10\n" + strokes + "G0 X40 Z5\n")
    r = verify_text(long, m, recovery="breakpoint")
    assert r.verdict.label == "unsafe", (r.reasons, r.violations[:1])
    assert r.violations[0].zones == ("bar",) and r.violations[0].break_line == 5 + 600 + 1


FANUC = MACHINE.read_text().replace('1 = { X = "100", Z = "150", R = "0.4", tip = 2 }', '1 = { X = "100", Z = "150" }')
FANUC = (FANUC.split("[[tools]]", 1)[0] + '[[tools]]\nnumber = 2\nparts = [{ name = "bar", x = ["-8", "8"], '
         'z = ["0", "120"] }]\n\n' + "[[fixtures]]" + FANUC.split("[[fixtures]]", 1)[1])


@pytest.mark.parametrize("clearance, verdict", [("220", "unsafe"), ("250", "safe")])
def test_recovery_legs_carry_the_turret_tool(clearance, verdict):
    """Fanuc: T0201 is tool 2 (the bar) with offset 1 (X100 Z150); tool 1 has no solids.  The legs after a
    break run with tool 2's parts (the bore of the test above, moved by the X offset 100): unsafe with the low
    clearance, safe with the high one.  Legs that took the offset number for the tool would check nothing."""
    m = parse_machine(FANUC + _tool_change(clearance, "300"), "fanuc.toml")
    text = "%\nO1\nG21 G18 G99 G40\nT0201\nG00 X40. Z5.\nG01 Z-60. F0.1\nG00 Z5.\nM30\n%\n"
    assert verify_text(text, m).verdict.label == "safe"
    r = verify_text(text, m, recovery="breakpoint")
    assert r.verdict.label == verdict, (r.reasons, r.violations)
    if verdict == "unsafe":
        v = r.violations[0]
        assert (v.leg, v.zone, v.zones, v.break_line) == ("to tool change", "jaws", ("bar",), 6)
        x, z = (dict(v.path_point)[a] for a in "XZ")
        assert part_meets(machine_solids(m).tools[2][0], machine_solids(m).fixtures[1], x - 100, z - 150)


def test_tip_of_is_the_oracles():
    # the oracle's tip helper agrees with the machine's offsets used above (X100 Z150 on T0201)
    m = parse_machine(FANUC + _tool_change("250", "300"), "fanuc.toml")
    seg = next(s for s in segments_text("%\nO1\nG21 G18\nT0201\nG00 X40. Z5.\nM30\n%\n", m, fast=False))
    assert tool_of(seg) == 2 and tip_of(seg, seg.end) == (F(20), F(135))


@pytest.mark.parametrize("fanuc", [False, True])
def test_a_recovery_solid_witness_replays(tmp_path, fanuc):
    """``nczones replay`` confirms a recovery leg's solid witness (the part on the leg from the reported break
    point, the contact inside it and inside the fixture, by replay's own test) and refuses it once the
    contact point is moved out of the jaws (radius 25, inside their bore).  Fanuc: the leg runs with T0201's
    tool 2, not offset 1's number."""
    from nczones.prover.render import to_json_dict
    from nczones.replay import replay_report

    if fanuc:
        text = FANUC + _tool_change("220", "300")
        program = "%\nO1\nG21 G18 G99 G40\nT0201\nG00 X40. Z5.\nG01 Z-60. F0.1\nG00 Z5.\nM30\n%\n"
    else:
        text, program = RECOVERY + _tool_change("220"), BORE
    (tmp_path / "m.toml").write_text(text)
    (tmp_path / "p.nc").write_text(program)
    r = verify(str(tmp_path / "p.nc"), load_machine(tmp_path / "m.toml"), recovery="breakpoint")
    doc = to_json_dict(r, deterministic=True)
    v = doc["violations"][0]
    assert (v["kind"], v["zone"], v["zones"]) == ("recovery", "jaws", ["bar"])
    (check,) = replay_report(doc)
    assert check.confirmed, check.message
    assert "inside the bar (X -8..8, Z 0..120 from the tip)" in check.message
    moved = dict(v, point_exact=dict(v["point_exact"], X="25"))
    (check,) = replay_report(dict(doc, violations=[moved]))
    assert not check.confirmed, check.message
