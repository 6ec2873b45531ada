"""``nczones simulate``: exit codes, JSON validated against specs/simulate.schema.json."""

from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest

from nczones.cli import main

SCHEMA = json.loads(Path("specs/simulate.schema.json").read_text())
GRINDER = "specs/machines/grinder.toml"

VIOLATING = "G90 G21 G54\nG0 X0 Y300\nG1 X-100 Y250 F2000\nG1 Y100\nG1 X0\n"
SAFE = "G90 G21 G54\nG0 X0 Y300\nG1 X100 Y250 F2000\nG2 X200 Y250 I50 J0\nG1 Y300\n"


def _run(tmp_path, capsys, text, *args):
    prog = tmp_path / "p.ngc"
    prog.write_text(text)
    code = main(["simulate", str(prog), "--machine", GRINDER, *args])
    return code, capsys.readouterr()


@pytest.mark.parametrize("mode", ["normal", "lock", "check"])
@pytest.mark.parametrize("monitor", ["pulse", "periodic"])
def test_json_matches_the_schema_and_exit_codes(tmp_path, capsys, mode, monitor):
    code, out = _run(tmp_path, capsys, VIOLATING, "--mode", mode, "--monitor", monitor, "--format", "json", "--events")
    data = json.loads(out.out)
    jsonschema.validate(data, SCHEMA)
    assert data["mode"] == mode
    if mode == "lock":
        assert code == 0 and data["alarms"] == [] and "frozen" in data["blind_spot"]
        assert data["machine_position"] == {"X": "1150", "Y": "300"}
    else:
        assert code == 1
        alarm = data["alarms"][0]
        assert alarm["line"] == 4 and alarm["zone"] == "wheel area" and alarm["source"] == "G1 Y100"
        if monitor == "pulse":
            assert alarm["position"] == {"X": "300", "Y": "219.999"}
    if mode == "check":
        assert data["machine_position"] == {"X": "1150", "Y": "300"}


def test_safe_program_exits_0_with_text_report(tmp_path, capsys):
    code, out = _run(tmp_path, capsys, SAFE)
    assert code == 0
    assert "no alarm" in out.out and "simulated time" in out.out


def test_alarm_text_names_line_zone_and_position(tmp_path, capsys):
    code, out = _run(tmp_path, capsys, VIOLATING)
    assert code == 1
    assert 'zone "wheel area" at line 4' in out.out and "X300 Y219.999" in out.out


def test_bad_input_exits_2(tmp_path, capsys):
    code, out = _run(tmp_path, capsys, "G1 X1 F100\nG1 X$\n")
    assert code == 2 and "Traceback" not in out.err
    prog = tmp_path / "q.ngc"
    prog.write_text(SAFE)
    assert main(["simulate", str(prog), "--machine", str(tmp_path / "missing.toml")]) == 2
    assert main(["simulate", str(prog), "--machine", GRINDER, "--accdec-before-ms", "-3"]) == 2
