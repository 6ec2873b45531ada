"""Tool-break recovery (issue 9): machine section, controller, prover, and their agreement."""

from dataclasses import replace
from fractions import Fraction as F
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller import Controller, simulate
from nczones.controller.recovery import record_pulses
from nczones.errors import MachineFileError
from nczones.gcode import interpret, interpret_text
from nczones.machine import load_machine, parse_machine
from nczones.motion import SegmentKind, segments_of
from nczones.plans.recovery import (
    RecoveryVariant,
    motion_sequences,
    recovery_legs,
    tool_change_config,
)
from nczones.prover import verify, verify_text
from nczones.prover.recovery import verify_recovery

ROOT = Path(__file__).resolve().parents[3]
EX = ROOT / "specs" / "examples"
LOW = EX / "machines" / "mill_toolchange.toml"
HIGH = EX / "machines" / "mill_toolchange_high.toml"
PROG = EX / "programs" / "recovery_clamp.ngc"
CUT_LINES = (5, 8, 9)


def _machine(path=HIGH, **subs) -> object:
    text = Path(path).read_text()
    for key, value in subs.items():
        old = next(l for l in text.splitlines() if l.startswith(f"{key} ="))
        text = text.replace(old, f'{key} = "{value}"')
    return parse_machine(text, str(path))


# --------------------------------------------------------------------------- machine file


def _codes(text_tc: str) -> list[str]:
    base = LOW.read_text().split("[tool_change]")[0]
    zones = "[[zones]]" + LOW.read_text().split("[[zones]]", 1)[1]
    with pytest.raises(MachineFileError) as e:
        parse_machine(base + "[tool_change]\n" + text_tc + "\n" + zones, "m.toml")
    return [(d.code, d.message) for d in e.value.diagnostics]


GOOD = ('position = { X = "560", Y = "200", Z = "380" }\nclearance = "300"\napproach_distance = "5"\n'
        'approach_feed = "200"\n')


@pytest.mark.parametrize("text, code, words", [
    (GOOD + 'clearence = "3"\n', "ZN150", 'did you mean "clearance"'),
    (GOOD.replace('Z = "380"', 'W = "380"'), "ZN152", "unknown axis"),
    (GOOD + 'retract_axis = "Q"\n', "ZN152", "not an axis"),
    (GOOD.replace('approach_distance = "5"', 'approach_distance = "-5"'), "ZN154", "must not be negative"),
    (GOOD.replace('approach_feed = "200"', 'approach_feed = "0"'), "ZN154", "greater than 0"),
    (GOOD + 'variant = "startt"\n', "ZN155", 'did you mean "start"'),
    (GOOD + 'retract_distance = "10"\n', "ZN156", "both"),
    (GOOD.replace('clearance = "300"\n', ''), "ZN156", "neither"),
    (GOOD.replace('approach_feed = "200"\n', ''), "ZN151", "missing approach_feed"),
    (GOOD.replace('clearance = "300"', 'clearance = "abc"'), "ZN153", "not a decimal"),
    (GOOD + 'length_register = "T2"\n', "ZN157", "length register"),
])
def test_bad_tool_change_sections_are_explained(text, code, words):
    got = _codes(text)
    assert any(c == code and words in msg for c, msg in got), got


def test_length_register_must_exist():
    m = _machine(LOW, length_register="H7")
    with pytest.raises(MachineFileError) as e:
        tool_change_config(m)
    assert e.value.diagnostics[0].code == "ZN157" and "H7" in e.value.diagnostics[0].message


def test_motion_sequences_of_the_example():
    m = load_machine(LOW)
    segs = list(interpret(str(PROG), m).segments())
    seqs = [(segs[a].line, segs[b].line) for a, b in motion_sequences(segs)]
    assert seqs == [(5, 5), (8, 9)]  # the plunge and the second pass are one sequence


# --------------------------------------------------------------------------- controller: pulse for pulse


def _record(machine, break_at=None):
    run = interpret(str(PROG), machine)
    segs = list(run.segments())
    ctl = Controller(machine, start=segs[0].start, break_at=break_at)
    log = record_pulses(ctl)
    result = ctl.run(segs)
    return result, log, segs


def _program_rows(log):
    rows = [p for _, d, p in log if not d.startswith("tool-break recovery")]
    return np.vstack(rows)


@pytest.mark.parametrize("variant", ["start", "breakpoint"])
@pytest.mark.parametrize("register", ["H1", "H2"])
@pytest.mark.parametrize("line, frac", [(5, F(1, 3)), (8, F(1, 2)), (9, F(3, 4)), (9, F(0)), (5, F(1))])
def test_resumed_cut_equals_the_uninterrupted_cut_pulse_for_pulse(variant, register, line, frac):
    m = _machine(variant=variant, length_register=register)
    plain, ulog, segs = _record(m)
    assert plain.completed and not plain.alarms
    broken, blog, _ = _record(m, (line, frac))
    assert broken.completed and not broken.alarms
    U = _program_rows(ulog)
    # K: steps before the break; K0: steps before the interrupted sequence started
    first_rec = next(i for i, (_, d, _) in enumerate(blog) if d.startswith("tool-break recovery"))
    K = sum(len(p) for _, d, p in blog[:first_rec])
    seg_i = next(i for i, s in enumerate(segs) if s.line == line and s.kind.name in ("LINE", "ARC"))
    seq_first = next(a for a, b in motion_sequences(segs) if a <= seg_i <= b)
    K0 = sum(len(p) for b, _, p in ulog if b < segs[seq_first].block)
    dz = round((m.tool_length(int(register[1:])) - m.tool_length(1)) / m.axis("Z").pulse)
    tail = U[K0:] if variant == "start" else U[K:]
    tail = tail.copy()
    tail[:, 2] += dz
    expected = np.vstack([U[:K], tail])
    B = _program_rows(blog)
    assert B.shape == expected.shape
    assert np.array_equal(B, expected)
    # the recovery ends at the restart point, the tip in the same place
    resume = dict(next(e for e in broken.events if e.kind == "resume").data)["position"]
    restart = tuple(int(v) for v in (U[K0 - 1] if variant == "start" and K0 else U[K - 1] if K else U[0]))
    if variant == "start" and K0 == 0:
        restart = tuple(round(v / F("0.01")) for v in segs[seq_first].start)
    assert tuple(round(v / F("0.01")) for v in resume.values()) == (restart[0], restart[1], restart[2] + dz)


def test_recovery_events_and_alarm_kind():
    m = load_machine(LOW)
    r = simulate(interpret(str(PROG), m), m, break_at=(5, F(1, 2)))
    kinds = [e.kind for e in r.events]
    assert kinds.index("sequence-start") < kinds.index("tool-break") < kinds.index("recovery")
    assert r.alarms and r.alarms[0].kind == "recovery" and r.alarms[0].zone == "clamp"
    assert r.alarms[0].derived == "tool-break recovery: to tool change"
    assert not r.completed
    assert simulate(interpret(str(PROG), m), m, break_at=(9, F(1, 2))).completed


# --------------------------------------------------------------------------- prover and controller agree


def _agree(machine, variant):
    out = verify_recovery(interpret(str(PROG), machine), machine, variant=variant)
    assert not out.reasons
    unsafe_lines = {v.break_line for v in out.violations}
    for line in CUT_LINES:
        for frac in (F(0), F(1, 4), F(1, 2), F(3, 4), F(1)):
            r = simulate(interpret(str(PROG), machine), machine, break_at=(line, frac))
            rec = [a for a in r.alarms if a.kind == "recovery"]
            if rec:  # the controller found an unsafe recovery: the prover must have found it too
                assert line in unsafe_lines, (line, frac, rec[0])
    for v in out.violations:  # every counterexample replays as an alarm
        pt = dict(v.point)
        assert machine.allowed.violated_zones(pt, machine.tool_length(1))
        r = simulate(interpret(str(PROG), machine), machine, break_at=(v.break_line, v.break_parameter))
        assert any(a.kind == "recovery" for a in r.alarms), v
    return out


@pytest.mark.parametrize("variant", ["start", "breakpoint"])
def test_prover_and_controller_agree_on_the_example(variant):
    low = _agree(load_machine(LOW), variant)
    assert [(v.break_line, v.leg, v.zone) for v in low.violations] == [(5, "to tool change", "clamp")]
    assert _agree(load_machine(HIGH), variant).violations == ()


@settings(max_examples=12, deadline=None, derandomize=True)
@given(clearance=st.integers(240, 399), tc_x=st.integers(350, 590), tc_z=st.integers(300, 400),
       clamp_top=st.integers(120, 300), dogleg=st.booleans(), variant=st.sampled_from(["start", "breakpoint"]))
def test_prover_and_controller_agree_on_generated_machines(clearance, tc_x, tc_z, clamp_top, dogleg, variant):
    text = LOW.read_text()
    text = text.replace('clearance = "300"', f'clearance = "{clearance}"')
    text = text.replace('position = { X = "560", Y = "200", Z = "380" }', f'position = {{ X = "{tc_x}", Y = "200", Z = "{tc_z}" }}')
    text = text.replace('max = { X = "340", Z = "250" }', f'max = {{ X = "340", Z = "{clamp_top}" }}')
    if dogleg:
        text = text.replace('rapid_mode = "linear"', 'rapid_mode = "dogleg"')
    m = parse_machine(text, "gen.toml")
    if verify(str(PROG), m).verdict.label != "safe":  # only programs that are safe on their own
        return
    out = verify_recovery(interpret(str(PROG), m), m, variant=variant)
    unsafe = {v.break_line for v in out.violations}
    for line in CUT_LINES:
        for frac in (F(0), F(1, 2), F(1)):
            r = simulate(interpret(str(PROG), m), m, break_at=(line, frac))
            rec = [a for a in r.alarms if a.kind == "recovery"]
            if rec:
                assert line in unsafe or out.reasons, (line, frac)
    for v in out.violations:
        if v.depth > F("0.02"):  # beyond the one-pulse band
            r = simulate(interpret(str(PROG), m), m, break_at=(v.break_line, v.break_parameter))
            assert any(a.kind == "recovery" for a in r.alarms), v


def test_arc_break_points_are_proved_on_the_circle():
    m = load_machine(LOW)
    # an arc left of the clamp (every break crashes) and one right of it (none does)
    prog = "G21 G90 G17 G54\nG43 H1\nG0 X100 Y100 Z110\nG2 X200 Y100 I50 J0 F600\nG0 Z270\nG0 X450 Y100\n" \
           "G1 Z110 F300\nG3 X550 Y100 I50 J0 F600\nG0 Z270\n"
    out = verify_recovery(interpret_text(prog, m), m)
    assert [(v.break_line, v.leg) for v in out.violations] == [(4, "to tool change")]
    v = out.violations[0]
    bp = dict(v.break_point)
    assert (bp["X"] - 150) ** 2 + (bp["Y"] - 100) ** 2 == 50 ** 2  # exactly on the circle
    r = simulate(interpret_text(prog, m), m, break_at=(4, v.break_parameter))
    assert r.alarms and r.alarms[0].kind == "recovery"
    assert simulate(interpret_text(prog, m), m, break_at=(8, F(1, 2))).completed


def test_recovery_legs_follow_the_section():
    m = _machine(LOW, variant="breakpoint")
    cfg = tool_change_config(m)
    assert cfg.variant is RecoveryVariant.BREAKPOINT
    P = (F(200), F(100), F(350))  # above the clearance: the retract does not go down
    legs = recovery_legs(cfg, m, P, P, F(120), F("95.5"))
    assert legs[0].end == P
    assert legs[-1].end == (F(200), F(100), F(350) - F("24.5"))
    assert [l.name for l in legs] == ["retract", "to tool change", "to restart", "rapid down", "approach"]


def test_cli_verify_recovery_and_simulate_break_at():
    import json
    import subprocess
    import sys

    import jsonschema

    def cli(*args):
        return subprocess.run([sys.executable, "-m", "nczones", *args], capture_output=True, text=True, cwd=ROOT)

    r = cli("verify", str(PROG), "--machine", str(LOW), "--recovery", "start", "--format", "json")
    assert r.returncode == 1
    doc = json.loads(r.stdout)
    jsonschema.validate(doc, json.loads((ROOT / "specs" / "report.schema.json").read_text()))
    v = doc["violations"][0]
    assert v["kind"] == "recovery" and v["break_line"] == 5 and v["leg"] == "to tool change"
    assert cli("verify", str(PROG), "--machine", str(HIGH), "--recovery", "breakpoint").returncode == 0
    assert cli("verify", str(PROG), "--machine", str(LOW)).returncode == 0
    s = cli("simulate", str(PROG), "--machine", str(LOW), "--break-at", "5:0.5")
    assert s.returncode == 1 and "during tool-break recovery: to tool change" in s.stdout
    assert cli("simulate", str(PROG), "--machine", str(HIGH), "--break-at", "9:0.5").returncode == 0
    bad = cli("simulate", str(PROG), "--machine", str(HIGH), "--break-at", "9:1.5")
    assert bad.returncode == 2 and "SM111" in bad.stderr and "Traceback" not in bad.stderr
    sarif = cli("verify", str(PROG), "--machine", str(LOW), "--recovery", "start", "--format", "sarif")
    assert json.loads(sarif.stdout)["runs"][0]["results"][0]["ruleId"] == "NCZ002"


def test_recovery_under_parameter_ranges_is_never_called_safe():
    """The recovery proof is nominal-only, so with ranges the verdict must not be 'safe'."""
    machine = load_machine(EX / "machines" / "mill_toolchange_high.toml")
    program = (EX / "programs" / "recovery_clamp.ngc").read_text()
    assert verify_text(program, machine, recovery="start").verdict.label == "safe"
    ranged = verify_text(program, machine, recovery="start", params=["G54.X=-0.001..0.001"])
    assert ranged.verdict.label != "safe"
    assert any(r.code == "RC204" for r in ranged.reasons)


def test_a_recovery_witness_under_parameter_ranges_lies_inside_them():
    """The recovery is proved at one point of the ranges: with the tool length ranged away from the file's
    value, a crash found at the file's value (outside the ranges) must not make the verdict unsafe."""
    machine = load_machine(LOW)  # unsafe recovery at the file's H1 = 120: the tip at Z180 hits the clamp
    program = PROG.read_text()
    assert verify_text(program, machine, recovery="start").verdict.label == "unsafe"
    short = verify_text(program, machine, recovery="start", params=["H1=0..1"])  # the tip above the clamp
    assert short.verdict.label == "unknown" and not short.violations
    assert [r.code for r in short.reasons] == ["RC204"] and "H1 = 0.5" in short.reasons[0].message
    held = verify_text(program, machine, recovery="start", params=["H1=119..121", "G54.X=0.5..1"])
    v = held.violations[0]
    assert v.kind == "recovery" and dict(v.params) == {"H1": 120, "G54.X": F(3, 4)}
    replay = verify_text(program, replace(machine, offsets={"G54": (F(3, 4), F(0), F(0))}), recovery="start")
    assert [(w.break_line, w.leg) for w in replay.violations] == [(v.break_line, v.leg)]


LATHE_TOOL_CHANGE = """[tool_change]
position = { X = "240", Z = "650" }
retract_axis = "Z"
clearance = "600"
approach_distance = "5"
approach_feed = "200"

"""


def test_recovery_legs_keep_the_lathe_tool_offset_of_the_broken_tool():
    """A lathe tool offset off the tool axis (X 80 on the radius) moves the tip during the recovery as during the
    cut: the retract from a cut at tip radius 20 goes up Z into the tailstock (a tip zone, X 0..45 from Z 360).
    Both witnesses used to check the legs' tip at the machine X (100) and called the recovery safe."""
    text = (ROOT / "specs" / "machines" / "fanuc_lathe.toml").read_text()
    lathe = parse_machine(text.replace("[fanuc]", LATHE_TOOL_CHANGE + "[fanuc]", 1), "fanuc_lathe_tool_change.toml")
    prog = "G21 G18 G40 G54 G98\nT0101\nG0 X40. Z80.\nG1 Z60. F100\nG0 X200.\nM30\n"
    assert verify_text(prog, lathe).verdict.label == "safe"
    r = verify_text(prog, lathe, recovery="start")
    assert r.verdict.label == "unsafe"
    v = r.violations[0]
    assert (v.kind, v.break_line, v.leg, v.zone) == ("recovery", 4, "retract", "tailstock")
    sim = simulate(interpret_text(prog, lathe), lathe, break_at=(4, F(1, 2)))
    assert [(a.kind, a.zone, a.derived) for a in sim.alarms] == [("recovery", "tailstock", "tool-break recovery: retract")]


SPLINE_PROG = "G21 G90 G17 G54\nG43 H1\nG0 X100 Y100 Z110\nG5.1 X200 Y100 I50 J50 F600\nG0 Z270\n"
TURNING_TOOL_CHANGE = """[tool_lengths]
H1 = "0"

[tool_change]
position = { X = "200", Z = "600", C = "0" }
retract_axis = "Z"
clearance = "500"
approach_distance = "5"
approach_feed = "200"
variant = "start"
length_register = "H1"

"""


def test_a_break_in_a_feed_motion_recovery_does_not_place_is_never_called_safe():
    """A tool breaks in any feed motion: splines and polar moves (whose break points are not placed) make the
    recovery verdict unknown (RC201) instead of being skipped as if no tool could break there."""
    m = load_machine(HIGH)
    assert verify_text(SPLINE_PROG, m).verdict.label == "safe"
    r = verify_text(SPLINE_PROG, m, recovery="start")
    assert r.verdict.label == "unknown"
    assert [x.code for x in r.reasons] == ["RC201"] and "spline" in r.reasons[0].message

    text = (EX / "machines" / "turning_centre.toml").read_text().replace("[[zones]]", TURNING_TOOL_CHANGE + "[[zones]]", 1)
    lathe = parse_machine(text, "turning_centre_tool_change.toml")
    prog = (EX / "programs" / "polar_face.nc").read_text()
    assert verify_text(prog, lathe).verdict.label == "safe"
    r = verify_text(prog, lathe, recovery="start")
    assert r.verdict.label == "unknown"
    assert r.reasons and {x.code for x in r.reasons} == {"RC201"}
    assert all("polar coordinate interpolation" in x.message for x in r.reasons)


@pytest.mark.parametrize("kind", [k for k in SegmentKind
                                  if k not in (SegmentKind.LINE, SegmentKind.ARC, SegmentKind.RAPID,
                                               SegmentKind.DWELL)])
def test_every_other_feed_kind_is_unknown_for_recovery(kind):
    """Every segment kind that is a feed motion but not LINE or ARC (a kind added later included) gives RC201."""
    m = load_machine(HIGH)
    segs = list(segments_of(interpret_text(SPLINE_PROG.replace("G5.1 X200 Y100 I50 J50", "G1 X200 Y100"), m)))
    feed = next(i for i, s in enumerate(segs) if s.kind is SegmentKind.LINE)
    segs[feed] = replace(segs[feed], kind=kind)
    out = verify_recovery(segs, m)
    assert [r.code for r in out.reasons] == ["RC201"] and not out.violations
