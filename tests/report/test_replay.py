"""Replayable reports (issue 20): the golden JSON reports of every unsafe example, and ``nczones replay``.

``specs/examples/reports/`` holds the deterministic JSON report of every unsafe pair of
``specs/examples/examples.toml`` (``NCZONES_UPDATE_GOLDENS=1`` rewrites them); each must match what
``verify`` reports today, validate against the schema, and replay: every counterexample confirmed in
exact arithmetic against the files it names.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import tomllib
from fractions import Fraction
from pathlib import Path

import jsonschema
import pytest

from nczones.machine import load_machine
from nczones.prover import verify
from nczones.prover.render import to_json_dict
from nczones.replay import on_arc, on_dogleg, on_line, replay_file, replay_report

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"
REPORTS = EX / "reports"
SCHEMA = json.loads((ROOT / "specs" / "report.schema.json").read_text())
CASES = [c for c in tomllib.loads((EX / "examples.toml").read_text())["example"] if c["verdict"] == "unsafe"]


def _slug(case: dict) -> str:
    name = Path(case["program"]).stem
    if case.get("margin"):
        name += f".margin-{case['margin']}"
    for p in case.get("params", []):
        name += ".param-" + re.sub(r"[^A-Za-z0-9.=-]+", "_", p)
    if case.get("recovery"):
        name += f".recovery-{case['recovery']}"
    return name + ".json"


def _report(case: dict) -> dict:
    """The deterministic report, with the paths written relative to the repository root (as verify run there)."""
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        machine = load_machine(os.path.relpath(EX / case["machine"]))
        result = verify(os.path.relpath(EX / case["program"]), machine, margin=case.get("margin", "0"),
                        params=case.get("params", []), recovery=case.get("recovery"))
    finally:
        os.chdir(cwd)
    return to_json_dict(result, deterministic=True)


@pytest.mark.parametrize("case", CASES, ids=[_slug(c) for c in CASES])
def test_golden_unsafe_report(case):
    doc = _report(case)
    jsonschema.validate(doc, SCHEMA)
    text = json.dumps(doc, indent=2, ensure_ascii=False) + "\n"
    path = REPORTS / _slug(case)
    if os.environ.get("NCZONES_UPDATE_GOLDENS") == "1":
        REPORTS.mkdir(exist_ok=True)
        path.write_text(text, encoding="utf-8")
    assert text == path.read_text(encoding="utf-8"), f"{path.name} differs (NCZONES_UPDATE_GOLDENS=1 rewrites it)"
    assert doc["verdict"] == "unsafe" and doc["violations"][0]["line"] == case["first_line"]


def test_every_golden_unsafe_report_replays():
    """The round trip the issue asks for, through the command line: every counterexample confirmed."""
    files = sorted(REPORTS.glob("*.json"))
    assert {p.name for p in files} == {_slug(c) for c in CASES}
    r = subprocess.run([sys.executable, "-m", "nczones", "replay", *map(str, files)], capture_output=True,
                       text=True, cwd=ROOT)
    assert r.returncode == 0, r.stdout + r.stderr
    lines = r.stdout.splitlines()
    n = sum(len(json.loads(p.read_text())["violations"]) for p in files)
    assert sum(": confirmed: " in ln for ln in lines) == n
    assert lines[-1].startswith(f"replay: {n} of {n} counterexamples confirmed")
    exact = [ln for ln in lines if ln.endswith(" exactly") or " exactly with " in ln]
    on_path = sum(v["path_point_on_path"] for p in files for v in json.loads(p.read_text())["violations"])
    assert len(exact) == on_path >= n - 6  # helices, an irrational R-arc centre, a developed arc, two polar moves


def test_replay_refuses_changed_files(tmp_path):
    doc = json.loads((REPORTS / "notch_dip.json").read_text())
    prog = tmp_path / "notch_dip.ngc"
    prog.write_text((EX / "programs/notch_dip.ngc").read_text().replace("G1 X50", "G1 X60"))
    doc["program"] = str(prog)
    report = tmp_path / "r.json"
    report.write_text(json.dumps(doc))
    r = subprocess.run([sys.executable, "-m", "nczones", "replay", str(report)], capture_output=True, text=True,
                       cwd=ROOT)
    assert r.returncode == 2
    assert r.stderr.startswith(f"{report}: error[RP102]: the program {prog} is not the one the report was made "
                               "from: its SHA-256 is ")


def test_replay_finds_a_counterexample_that_does_not_hold(tmp_path):
    """A report whose point was moved inside the allowed set is not reproduced (exit 1)."""
    doc = json.loads((REPORTS / "notch_dip.json").read_text())
    v = doc["violations"][0]
    v["point_exact"] = {"X": "380", "Y": "250"}  # above the notch: allowed
    v["path_point_exact"] = {"X": "380", "Y": "250"}
    report = tmp_path / "moved.json"
    report.write_text(json.dumps(doc))
    r = subprocess.run([sys.executable, "-m", "nczones", "replay", str(report)], capture_output=True, text=True,
                       cwd=ROOT)
    assert r.returncode == 1
    assert r.stdout.splitlines()[0] == ("specs/examples/programs/notch_dip.ngc:5: NOT REPRODUCED: the path point "
                                        "X380 Y250 is not on the line of block 3")
    v["path_point_exact"] = {"X": "380", "Y": "130"}  # on the line, but the point is 120 mm away
    report.write_text(json.dumps(doc))
    checks = replay_file(str(report), base=str(ROOT))
    assert not checks[0].confirmed and "more than the margin 0 mm" in checks[0].message


def test_replay_of_a_list_and_of_standard_input(tmp_path):
    """``verify --format json`` of several programs gives a list; a program read from stdin needs --program."""
    prog = EX / "programs" / "notch_dip.ngc"
    out = subprocess.run([sys.executable, "-m", "nczones", "verify", "-", "--machine", "specs/machines/grinder.toml",
                          "--format", "json"], input=prog.read_text(), capture_output=True, text=True, cwd=ROOT)
    report = tmp_path / "stdin.json"
    report.write_text(out.stdout)
    r = subprocess.run([sys.executable, "-m", "nczones", "replay", str(report)], capture_output=True, text=True,
                       cwd=ROOT)
    assert r.returncode == 2
    assert r.stderr == f"{report}: error[RP103]: the report's program is <stdin> (not a file); pass --program\n"
    assert replay_file(str(report), base=str(ROOT), program_file=str(prog))[0].confirmed
    both = subprocess.run([sys.executable, "-m", "nczones", "verify", str(prog), "specs/examples/programs/notch_over.ngc",
                           "--machine", "specs/machines/grinder.toml", "--format", "json"], capture_output=True,
                          text=True, cwd=ROOT)
    report.write_text(both.stdout)
    assert [c.confirmed for c in replay_file(str(report))] == [True]


def test_reports_carry_what_makes_them_replayable():
    doc = json.loads((REPORTS / "x_near_limit.param-G54.X=-2..2.json").read_text())
    assert doc["machine"]["file"] == "specs/machines/mill.toml"
    assert len(doc["machine"]["sha256"]) == 64 and len(doc["program_sha256"]) == 64
    assert doc["settings"]["params"] == ["G54.X=-2..2"] and doc["settings"]["margin"] == "0"
    assert doc["settings"]["engine"] == "auto" and doc["settings"]["arc_tolerance"] == "0.002"
    assert doc["nczones_version"] and doc["dialect"] == doc["settings"]["dialect"]
    v = doc["violations"][0]
    assert {a: Fraction(x) for a, x in v["point_exact"].items()} == {
        a: Fraction(x) for a, x in v["point_exact"].items()}  # every value reads back as an exact rational
    assert v["params_exact"] == {"G54.X": "2"}


def test_arc_witness_is_a_rational_point_on_the_arc():
    """The exact form of an arc witness is a rational point on the circle (its decimals may repeat)."""
    doc = json.loads((REPORTS / "arc_bulge_cw.json").read_text())
    v = doc["violations"][0]
    assert v["path_point_on_path"]
    x, y = (Fraction(v["path_point_exact"][a]) for a in "XY")
    machine = load_machine(EX / "../machines/grinder.toml")
    from nczones.gcode import segments

    arc = next(s for s in segments(EX / "programs/arc_bulge_cw.ngc", machine) if s.block == v["block"])
    cx, cy = arc.centre
    assert (x - cx) ** 2 + (y - cy) ** 2 == (arc.start[0] - cx) ** 2 + (arc.start[1] - cy) ** 2
    assert on_arc((x, y), arc)


def test_exact_membership_checks():
    F = Fraction
    assert on_line((F(1, 3), F(2, 3)), (F(0), F(0)), (F(1), F(2))) == F(1, 3)
    assert on_line((F(2), F(4)), (F(0), F(0)), (F(1), F(2))) is None  # beyond the end
    # dogleg: X at 100/min, Y at 50/min from (0,0) to (20,10): X arrives at 0.2, Y at 0.2; the path is straight
    assert on_dogleg((F(10), F(5)), (F(0), F(0)), (F(20), F(10)), (F(100), F(50))) == F(1, 10)
    # X at 100/min, Y at 100/min: the path bends at (10, 10)
    assert on_dogleg((F(15), F(10)), (F(0), F(0)), (F(20), F(10)), (F(100), F(100))) == F(3, 20)
    assert on_dogleg((F(10), F(5)), (F(0), F(0)), (F(20), F(10)), (F(100), F(100))) is None


def test_replay_report_needs_a_report():
    from nczones.errors import InputError

    with pytest.raises(InputError) as e:
        replay_report({"x": 1})
    assert e.value.code == "RP101"
