"""The dialect setting: machine file, --dialect, reports naming it, cross-dialect hints, decimal point input,
and the property that both dialects move the same on programs valid in both."""

from __future__ import annotations

import json
from dataclasses import replace
from decimal import Decimal
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.cli import main
from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

from .helpers import mill

SAFETY_LINE = "G00 G17 G40 G49 G80 G90\n"


def test_the_standard_safety_line_and_g69(tmp_path):
    m = mill()
    run = interpret_text(SAFETY_LINE + "G69\nG15 G50 G50.1\nX10. Y5.\nM30\n", m)
    assert [tuple(s.end) for s in run.segments()] == [(110, 55, 0)] and run.status == "complete"  # G54 X100 Y50
    linuxcnc = replace(m, dialect="linuxcnc")
    # LinuxCNC reads the safety line too: its read_g drops a G80 beside another motion code
    run = interpret_text(SAFETY_LINE + "X10. Y5.\nM30\n", linuxcnc)
    assert [tuple(s.end) for s in run.segments()] == [(110, 55, 0)] and run.status == "complete"
    with pytest.raises(GcodeError) as e:  # two other motion codes: LinuxCNC refuses, Fanuc takes the last
        list(interpret_text("G00 G17 G01 X10. F100.\n", linuxcnc))
    d = e.value.diagnostics[0]
    assert d.code == "GC201" and d.message.endswith(
        'valid in the fanuc dialect: set dialect = "fanuc" in [machine] (or pass --dialect fanuc)')


def test_hint_for_the_other_way_round():
    with pytest.raises(GcodeError) as e:
        list(interpret_text("G0 X1.\nG91.1\n", mill()))
    d = e.value.diagnostics[0]
    assert d.code == "GC202" and "valid in the linuxcnc dialect" in d.message
    with pytest.raises(GcodeError) as e:  # a line neither dialect reads gets no hint
        list(interpret_text("G0 X1.\nG1 X$\n", mill()))
    assert "valid in the" not in e.value.diagnostics[0].message


def test_linuxcnc_unknown_gets_a_hint_for_fanuc_macro_statements():
    m = replace(mill(), dialect="linuxcnc")
    r = verify_text("G0 X1\n#1 = 2\nIF [#1 EQ 2] GOTO 5\nN5 G0 X2\n", m)
    assert r.verdict.label == "unknown" and "valid in the fanuc dialect" in r.reasons[0].message
    assert verify_text("G0 X1\n#1 = 2\nIF [#1 EQ 2] GOTO 5\nN5 G0 X2\n", m, dialect="fanuc").verdict.label == "safe"


def test_default_dialect_is_linuxcnc_and_the_machine_file_sets_it():
    base = mill()
    assert replace(base, dialect="linuxcnc").dialect == "linuxcnc"
    text = machine_text("x_unit")
    assert parse_machine(text).dialect == "linuxcnc"
    assert parse_machine(text.replace("[machine]\n", "[machine]\ndialect = \"fanuc\"\n")).dialect == "fanuc"


def _write_machine(tmp_path, dialect="fanuc", extra=""):
    text = (f'[machine]\nname = "m"\ndialect = "{dialect}"\naxes = ["X", "Y", "Z"]\n'
            '[machine.rapid]\nX = "1000"\nY = "1000"\nZ = "1000"\n'
            '[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n' + extra +
            '[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-10", Y = "-10", Z = "-10" }\n'
            'max = { X = "200", Y = "200", Z = "10" }\n'
            '[[zones]]\nname = "fixture"\nkind = "box"\nforbid = true\nmin = { X = "50", Y = "-10" }\n'
            'max = { X = "150", Y = "200" }\n')
    path = tmp_path / f"{dialect}.toml"
    path.write_text(text)
    return path


def test_every_report_names_the_dialect(tmp_path, capsys):
    machine = _write_machine(tmp_path, "linuxcnc")
    prog = tmp_path / "p.nc"
    prog.write_text("G0 X1 Y1\n")
    assert main(["verify", str(prog), "--machine", str(machine)]) == 0
    assert "; dialect linuxcnc;" in capsys.readouterr().out
    assert main(["verify", str(prog), "--machine", str(machine), "--dialect", "fanuc", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["dialect"] == "fanuc"
    assert main(["verify", str(prog), "--machine", str(machine), "--dialect", "fanuc", "--format", "sarif"]) == 0
    assert '"dialect": "fanuc"' in capsys.readouterr().out
    assert main(["simulate", str(prog), "--machine", str(machine), "--dialect", "fanuc", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["dialect"] == "fanuc"
    assert main(["verify", str(prog), "--machine", str(machine), "--library", str(tmp_path / "none")]) == 2
    assert "--library" in capsys.readouterr().err


def test_flipping_decimal_point_input_changes_the_verdict(tmp_path, capsys):
    # X100 without a decimal point: 100 mm with calculator-type input, inside the fixture (X 50..150): unsafe;
    # 0.1 mm with increment-type input (IS-B): safe.  The report notes the word either way.
    prog = tmp_path / "p.nc"
    prog.write_text("O1000\nG90 G0 X100 Y20.\nM30\n")
    calc = _write_machine(tmp_path, extra='[fanuc]\ndecimal_point_input = "calculator"\n')
    assert main(["verify", str(prog), "--machine", str(calc)]) == 1
    out = capsys.readouterr().out
    assert "violation[fixture]" in out and "line 2: X100" in out
    inc = tmp_path / "inc.toml"
    inc.write_text(calc.read_text().replace('"calculator"', '"increment"'))
    assert main(["verify", str(prog), "--machine", str(inc)]) == 0
    out = capsys.readouterr().out
    assert "safe" in out and 'this machine uses "increment"' in out


def test_no_decimal_point_note_when_both_settings_agree():
    r = verify_text("G0 X0 Y100.\n", mill())
    assert not any("decimal point" in n for n in r.notes)


# ---------------------------------------------------------------- both dialects, same motion

_coords = st.decimals(min_value=-50, max_value=50, places=3, allow_nan=False, allow_infinity=False)


@st.composite
def common_programs(draw):
    """Programs valid in both dialects with the same meaning: G0/G1 moves and semicircle/full-circle
    arcs with decimal points, G90/G91, G17, G54/G55, F, G43 H with a Z move, G49 with a Z move (those two in
    G90: see below)."""
    lines = ["G0 G90 G17 G54 X0. Y0. Z0."]
    absolute = True
    for _ in range(draw(st.integers(1, 12))):
        kind = draw(st.sampled_from(["move", "move", "arc", "mode", "wcs", "tool"]))
        if kind == "move":
            g = draw(st.sampled_from(["G0", "G1"]))
            words = " ".join(f"{a}{draw(_coords)}" for a in draw(st.sets(st.sampled_from("XYZ"), min_size=1)))
            lines.append(f"{g} {words} F{draw(st.integers(10, 900))}.")
        elif kind == "arc":
            i, j = draw(_coords), draw(_coords)
            if i * i + j * j < Decimal("0.00127") ** 2:
                continue  # (LinuxCNC refuses a radius below 0.00005 inch: "Zero-radius arc", GC304)
            g = draw(st.sampled_from(["G2", "G3"]))
            if draw(st.booleans()):
                lines.append(f"G91 {g} X{2 * i} Y{2 * j} I{i} J{j} F100.")
                lines.append("G90" if absolute else "G91")
            else:
                lines.append(f"G91 {g} X0. Y0. I{i} J{j} F100.")
                lines.append("G90" if absolute else "G91")
        elif kind == "mode":
            absolute = draw(st.booleans())
            lines.append("G90" if absolute else "G91")
        elif kind == "wcs":
            lines.append(draw(st.sampled_from(["G54", "G55"])))
        else:
            # in G90 only: with an incremental Z word the dialects differ.  Fanuc (TOS = 0) moves by the
            # increment plus the length change ([0i] "Tool length compensation" example: G91 G43 Z-32. H01
            # with H01 = -4 moves -36; tests/gcode/fanuc/test_offsets.py); LinuxCNC re-expresses the current point
            # in the new offset and moves by the increment alone (rs274: G91 G1 G43 H1 Z0 does not move)
            z = draw(_coords)
            line = draw(st.sampled_from([f"G1 G43 H1 Z{z} F100.", f"G0 G43 H2 Z{z}", f"G0 G49 Z{z}"]))
            lines.append(line if absolute else f"G90 {line}\nG91")
    return "\n".join(lines) + "\nM30\n"


def _common_mill():
    """The test mill without what only Fanuc has (the external offset EXT, G54.1 systems)."""
    from types import MappingProxyType

    m = mill()
    return replace(m, offsets=MappingProxyType({k: v for k, v in m.offsets.items() if k in ("G54", "G55")}))


def _motion(text, machine):
    run = interpret_text(text, machine)
    segs = [(s.kind.name, tuple(s.start), tuple(s.end), s.centre, s.clockwise, s.turns) for s in run.segments()]
    return segs, run.status


@settings(max_examples=80, deadline=None)
@given(common_programs())
def test_both_dialects_give_the_same_motion(text):
    fanuc = _common_mill()
    linuxcnc = replace(fanuc, dialect="linuxcnc")
    a, sa = _motion(text, fanuc)
    b, sb = _motion(text, linuxcnc)
    assert sa == sb == "complete"
    assert a == b


def test_both_dialects_on_a_fixed_program_with_an_arc():
    text = "G0 G90 G17 G54 X0. Y0. Z0.\nG1 X10. F100.\nG3 X0. Y10. I-10. J0.\nG0 G43 H1 Z5.\nX1.\nM30\n"
    fanuc = _common_mill()
    a, _ = _motion(text, fanuc)
    b, _ = _motion(text, replace(fanuc, dialect="linuxcnc"))
    # derivation: X1 in G54 (X100) -> 101; Y10 + 50 = 60; Z5 - 200 + H1 100 = -95
    assert a == b and a[-1][2] == (Fraction(101), Fraction(60), Fraction(-95))
