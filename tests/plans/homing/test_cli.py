"""``nczones home``: simulation output, proofs, the counterexample round trip, bad input (golden)."""

from __future__ import annotations

import json
import os
import shlex
from pathlib import Path

import pytest

from nczones.cli import main
from nczones.machine import load_machine

ROOT = Path(__file__).resolve().parents[3]
MILL = "specs/machines/homing_mill.toml"
GOLDEN = ROOT / "tests" / "golden" / "homing"
REGEN = os.environ.get("NCZONES_REGEN_GOLDEN") == "1"
BAD = sorted(GOLDEN.glob("*.toml"))


@pytest.fixture(autouse=True)
def _at_root(monkeypatch):
    monkeypatch.chdir(ROOT)


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_example_machine_loads_with_three_homing_axes():
    m = load_machine(ROOT / MILL)
    assert sorted(m.sections["homing"]) == ["X", "Y", "Z"]


def test_simulate_all_axes_text(capsys):
    code, out, err = run(capsys, "home", "--machine", MILL)
    assert code == 0 and err == ""
    assert out.count("result: homing ended exactly at machine zero") == 3
    assert "X3.217        grid point latched" in out
    assert "grid shift -3.217 mm (stored)" in out


def test_simulate_json(capsys):
    code, out, _ = run(capsys, "home", "--machine", MILL, "--axis", "Z", "--format", "json")
    doc = json.loads(out)
    assert code == 0 and doc["ok"] is True and doc["prove"] is False
    (z,) = doc["axes"]
    assert z["axis"] == "Z" and z["origin_error_pulses"] == 0 and z["latched_grid"] == "395.5"
    assert [e["kind"] for e in z["events"]] == ["search_start", "dog_trip", "signal_seen", "grid_latched",
                                               "shift_move", "origin_set"]
    assert z["events"][1]["position"] == "392"


def test_prove_round_trip(capsys):
    """``home --prove`` prints a counterexample; ``home --phase .. --trip-offset ..`` reproduces it exactly."""
    code, out, _ = run(capsys, "home", "--machine", MILL, "--axis", "X", "--prove", "--format", "json")
    doc = json.loads(out)
    assert code == 0 and doc["ok"]  # the configured phase is proved exact
    proofs = {p["name"]: p for p in doc["axes"][0]["proofs"]}
    assert proofs["exact-after-installation"]["status"] == "proved"
    assert proofs["margin-condition"]["status"] == "proved"
    assert proofs["configured-phase"]["status"] == "proved"
    cex = proofs["one-pitch-error"]["counterexample"]
    assert proofs["one-pitch-error"]["status"] == "refuted" and cex["reproduced"]
    argv = shlex.split(cex["reproduce"])
    assert argv[:2] == ["nczones", "home"] and "--phase" in argv and "--trip-offset" in argv
    code, out, _ = run(capsys, *argv[1:], "--format", "json")
    again = json.loads(out)["axes"][0]
    assert code == 1
    assert again["origin_error_pulses"] == cex["origin_error_pulses"]
    assert abs(again["origin_error_pulses"]) == 10000
    assert again["phase"] == cex["phase"] and again["trip_offset"] == cex["trip_offset"]


def test_prove_text_for_a_bad_phase_exits_1_and_reproduces(capsys, tmp_path):
    text = (ROOT / MILL).read_text().replace('detector_phase = "3.217"', 'detector_phase = "6.51"')
    text = text.replace('grid_shift = "-3.217"', 'grid_shift = "3.49"')
    bad = tmp_path / "bad_phase.toml"
    bad.write_text(text)
    code, out, _ = run(capsys, "home", "--machine", str(bad), "--axis", "X", "--prove")
    assert code == 1
    assert "[COUNTEREXAMPLE] configured-phase" in out
    assert "NOT proved exact" in out
    line = next(l for l in out.splitlines() if "reproduce:" in l and "--phase" not in l)
    argv = shlex.split(line.split("reproduce:", 1)[1])
    code, out, _ = run(capsys, *argv[1:])
    assert code == 1
    assert "origin error -10000 pulses" in out or "origin error 10000 pulses" in out


def test_start_on_the_dog_alarm_exits_1(capsys, tmp_path):
    text = (ROOT / MILL).read_text().replace('start = "300"', 'start = "5"')
    f = tmp_path / "on_dog.toml"
    f.write_text(text)
    code, out, _ = run(capsys, "home", "--machine", str(f), "--axis", "X")
    assert code == 1
    assert "ALARM (start too close to the dog)" in out


@pytest.mark.parametrize("argv, message", [
    (["--axis", "A"], "--axis A: the machine has no [homing.A] section"),
    (["--phase", "10"], "--phase 10: axis X needs a phase in [0, 10)"),
    (["--phase", "abc"], "--phase 'abc' is not a length"),
    (["--trip-offset", "0.03"], "--trip-offset 0.03: must lie within axis X's switch jitter window [-0.02, 0.02]"),
    (["--prove", "--trip-offset", "0"], "--trip-offset is for simulation"),
])
def test_bad_options_exit_2(capsys, argv, message):
    code, out, err = run(capsys, "home", "--machine", MILL, *argv)
    assert code == 2 and out == ""
    assert err.startswith(f"nczones: error: {message}") and "Traceback" not in err


def test_machine_without_homing_exits_2(capsys):
    code, _, err = run(capsys, "home", "--machine", "specs/machines/mill.toml")
    assert code == 2 and "no [homing.<axis>] section" in err


@pytest.mark.parametrize("path", BAD, ids=[p.stem for p in BAD])
def test_bad_homing_section_golden(path, capsys):
    rel = path.relative_to(ROOT).as_posix()
    code, out, err = run(capsys, "home", "--machine", rel)
    assert code == 2 and out == ""
    assert "Traceback" not in err
    for line in err.splitlines():
        if not line.startswith(" "):
            assert line.startswith(rel) and "error[ZN1" in line, line
    expected = path.with_suffix(".expected")
    if REGEN:
        expected.write_text(err, encoding="utf-8")
    assert err == expected.read_text(encoding="utf-8")


def test_prove_with_phase_override_round_trip(capsys):
    """``--prove --phase P`` (a re-mounted detector): every counterexample command reproduces its error."""
    code, out, _ = run(capsys, "home", "--machine", MILL, "--axis", "Z", "--phase", "3", "--prove", "--format", "json")
    doc = json.loads(out)
    assert code == 1 and not doc["ok"]  # grid point 1 mm past the edge, lag 1 mm: inside the window
    cexs = [p["counterexample"] for p in doc["axes"][0]["proofs"] if p["counterexample"]]
    assert {p["name"] for p in doc["axes"][0]["proofs"] if p["status"] == "refuted"} == {"one-pitch-error",
                                                                                       "configured-phase"}
    for cex in cexs:
        argv = shlex.split(cex["reproduce"])
        assert "--phase" in argv
        code, out, _ = run(capsys, *argv[1:], "--format", "json")
        assert code == 1
        assert json.loads(out)["axes"][0]["origin_error_pulses"] == cex["origin_error_pulses"] != 0
