"""Every specs/examples pair gives its golden verdict and first violating line (both engines)."""

import json
import subprocess
import sys
import tomllib
from pathlib import Path

import jsonschema
import pytest

from nczones.machine import load_machine
from nczones.prover import Verdict, verify, verify_text
from nczones.prover.render import render_text, to_json_dict
from nczones.zones import tip_shifted

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"
CASES = tomllib.loads((EX / "examples.toml").read_text())["example"]
SCHEMA = json.loads((ROOT / "specs" / "report.schema.json").read_text())


def _run(case, engine="auto"):
    machine = load_machine(EX / case["machine"])
    return verify(str(EX / case["program"]), machine, margin=case.get("margin", "0"),
                  params=case.get("params", []), engine=engine, recovery=case.get("recovery"))


def test_at_least_twenty_examples():
    assert len(CASES) >= 20


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_example_golden(case):
    r = _run(case)
    assert r.verdict.label == case["verdict"], render_text(r)
    if case["verdict"] == "unsafe":
        v = r.violations[0]
        assert v.line == case["first_line"]
        if "recovery" in case:
            assert v.kind == "recovery" and v.break_line == case["first_line"] and v.leg
        if "zone" in case:
            assert v.zone == case["zone"]
        for name in case.get("counterexample_params", []):
            assert name in dict(v.params)
        m = load_machine(EX / case["machine"])
        if v.kind == "solid":  # a tool part in a fixture: its witness is checked by replay (tests/report)
            return
        # the reported point is strictly outside the allowed set
        pt = dict(v.point)
        allowed = m.allowed
        if m.tool_offsets:  # the lathe examples use offset 1: its X moves the tip zones, its Z is the tool length
            off = dict(m.tool_offsets[1].geometry)
            allowed = tip_shifted(allowed, {"X": off["X"]})
        assert allowed.violated_zones(pt, _tool_length(v, m))
    elif case["verdict"] == "unknown":
        assert r.reasons and r.reasons[0].span.line == case["first_line"]
    jsonschema.validate(to_json_dict(r), SCHEMA)


def _tool_length(v, m):
    # examples that violate tip zones use H1 in the mill, tool offset 1 on the lathe
    if m.tool_offsets:
        return dict(m.tool_offsets[1].geometry)["Z"]
    return m.tool_length(1) if v.zone in ("vise", "table", "clamp") else 0


@pytest.mark.parametrize("case", [c for c in CASES if not c.get("params")][:12],
                         ids=[c["name"] for c in CASES if not c.get("params")][:12])
def test_example_z3_engine_agrees(case):
    a, b = _run(case), _run(case, "z3")
    assert a.verdict == b.verdict
    assert [v.block for v in a.violations][:1] == [v.block for v in b.violations][:1]


def _cli(*args):
    return subprocess.run([sys.executable, "-c", "import sys; from nczones.cli import main; sys.exit(main())", *args],
                          capture_output=True, text=True, cwd=ROOT)


def test_cli_exit_codes_and_text(tmp_path):
    g = str(EX / "../machines/grinder.toml")
    r = _cli("verify", str(EX / "programs/notch_dip.ngc"), "--machine", g)
    assert r.returncode == 1
    assert "notch_dip.ngc:5:1: violation[wheel area]:" in r.stdout
    assert "    G1 X50" in r.stdout
    assert _cli("verify", str(EX / "programs/notch_over.ngc"), "--machine", g).returncode == 0
    assert _cli("verify", str(EX / "programs/cutter_comp.ngc"), "--machine",
                str(EX / "../machines/mill.toml")).returncode == 3
    bad = _cli("verify", str(EX / "programs/notch_over.ngc"), "--machine", g, "--param", "Q=1..2")
    assert bad.returncode == 2 and "Q" in bad.stderr and "Traceback" not in bad.stderr
    out = tmp_path / "r.json"
    r = _cli("verify", str(EX / "programs/x_near_limit.ngc"), "--machine", str(EX / "../machines/mill.toml"),
             "--param", "G54.X=-2..2", "--format", "json", "--output", str(out))
    assert r.returncode == 1
    doc = json.loads(out.read_text())
    jsonschema.validate(doc, SCHEMA)
    assert doc["verdict"] == "unsafe" and doc["violations"][0]["params"]["G54.X"]
    assert doc["solver"]["version"]


def test_max_violations_caps_the_list():
    case = next(c for c in CASES if c["program"].endswith("notch_dip.ngc"))
    m = load_machine(EX / case["machine"])
    text = "G21 G90 G54\nG0 X-250 Y300\nG1 Y130 F500\n" + "G1 X50\nG1 X-250\n" * 5
    r = verify_text(text, m, max_violations=3)
    assert r.verdict is Verdict.UNSAFE and len(r.violations) == 3 and r.truncated
    assert [v.line for v in r.violations] == [4, 5, 6]
