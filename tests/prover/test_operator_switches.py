"""Operator switches (issue 18, item 5): block delete is verified in both positions unless the machine
file or the command line fixes it, every report says what was verified, and stops are noted."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from nczones.errors import MachineFileError
from nczones.machine import load_machine, parse_machine
from nczones.prover import verify_text as verify
from nczones.report import render_report

GRINDER = "specs/machines/grinder.toml"
# G1 Y130 over the grinding region, then (block delete) back up to Y230 before crossing the work head at
# X250 (machine): with the switch on the wheel crosses the head at Y130
PROGRAM = "G21 G90 G54\nG0 X200 Y300\nG1 Y130 F500\n/G1 Y230\nG1 X-150\nM30\n"


def test_the_reproducer_is_unsafe_with_the_switch_on():
    machine = load_machine(GRINDER)
    result = verify(PROGRAM, machine)
    assert result.verdict.label == "unsafe"
    (v,) = result.violations
    assert v.line == 5 and v.switches == (("block_delete", "on"),)
    assert any("both" not in n and "switch off (those lines run) and on" in n for n in result.notes)
    assert verify(PROGRAM, machine, block_delete="off").verdict.label == "safe"
    on = verify(PROGRAM, machine, block_delete="on")
    assert on.verdict.label == "unsafe" and on.violations[0].switches == ()


def test_a_violation_in_both_positions_names_none_and_one_in_the_off_position_names_it():
    machine = load_machine(GRINDER)
    program = "G21 G90 G54\nG0 X200 Y300\nG1 Y130 F500\n/G1 X-350 Y100\nG1 X-150\nM30\n"
    result = verify(program, machine)
    assert [(v.line, v.switches) for v in result.violations] == [(4, (("block_delete", "off"),)), (5, ())]


def test_the_machine_file_fixes_the_switch_and_the_report_says_so():
    text = open(GRINDER).read().replace('rapid_mode = "dogleg"', 'rapid_mode = "dogleg"\nblock_delete = "off"')
    machine = parse_machine(text, "grinder_off.toml")
    result = verify(PROGRAM, machine)
    assert result.verdict.label == "safe"
    assert any("switch OFF only" in n for n in result.notes)
    assert verify(PROGRAM, machine, block_delete="both").verdict.label == "unsafe"
    with pytest.raises(MachineFileError, match="ZN114"):
        parse_machine(text.replace('block_delete = "off"', 'block_delete = "yes"'))


def test_every_format_reports_the_switch():
    machine = load_machine(GRINDER)
    result = verify(PROGRAM, machine)
    assert "with the block-delete switch on" in render_report(result, "text")
    doc = json.loads(render_report(result, "json"))
    assert doc["violations"][0]["switches"] == {"block_delete": "on"}
    assert any("block-delete switch off" in n for n in doc["notes"])
    sarif = json.loads(render_report(result, "sarif", machine=machine))
    assert "block-delete switch on" in sarif["runs"][0]["results"][0]["message"]["text"]


def test_programs_without_block_delete_lines_are_interpreted_once_and_say_nothing():
    machine = load_machine(GRINDER)
    result = verify("G21 G90 G54\nG0 X200 Y300\nG1 Y130 F500\nM30\n", machine)
    assert result.verdict.label == "safe" and not any("block" in n for n in result.notes)
    assert all(v.switches == () for v in verify(PROGRAM.replace("/", ""), machine, block_delete="on").violations)


def test_stops_are_noted():
    machine = load_machine(GRINDER)
    result = verify("G21 G90 G54\nG0 X200 Y300\nM1\nG1 Y130 F500\nM0\nM30\n", machine)
    (note,) = [n for n in result.notes if "stop" in n]
    assert "M1 (optional stop)" in note and "M0 (program stop)" in note and "line(s) 3, 5" in note


def test_the_command_line_option(tmp_path):
    program = tmp_path / "bd.ngc"
    program.write_text(PROGRAM)
    for option, code, text in (("off", 0, "switch OFF only"), ("both", 1, "block-delete switch on")):
        run = subprocess.run([sys.executable, "-m", "nczones", "verify", str(program), "--machine", GRINDER,
                              "--block-delete", option], capture_output=True, text=True)
        assert run.returncode == code, run.stdout + run.stderr
        assert text in run.stdout
