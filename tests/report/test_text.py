"""Golden tests of the compiler-style text report, colour rules and the CLI text output."""

import io
import subprocess
import sys

import pytest

from nczones.report.text import render_text, use_color

from .helpers import EX, GOLDEN, ROOT, check_golden, run_example

CASES = [
    # (golden name, program, base folder, machine, verify options)
    ("safe_notch_over.txt", "programs/notch_over.ngc", EX, "grinder.toml", {}),
    ("unsafe_notch_dip.txt", "programs/notch_dip.ngc", EX, "grinder.toml", {}),
    ("unsafe_several.txt", "programs/several.ngc", GOLDEN, "grinder.toml", {}),
    ("unsafe_drill_vise_tip_zone.txt", "programs/drill_vise.ngc", EX, "mill.toml", {}),
    ("unknown_cutter_comp.txt", "programs/cutter_comp.ngc", EX, "mill.toml", {}),
    ("unsafe_param_g54x.txt", "programs/x_near_limit.ngc", EX, "mill.toml", {"params": ["G54.X=-2..2"]}),
    ("unsafe_param_tool_length.txt", "programs/z_tool_range.ngc", EX, "mill.toml", {"params": ["H1=115..126"]}),
    ("safe_param_tool_length.txt", "programs/z_tool_range.ngc", EX, "mill.toml", {"params": ["H1=115..125"]}),
]


@pytest.mark.parametrize("name,program,base,machine,opts", CASES, ids=[c[0] for c in CASES])
def test_text_golden(name, program, base, machine, opts):
    from nczones.report.numbers import resolution_of

    result, m = run_example(program, machine, base=base, **opts)
    # as the CLI renders it (render_report passes the machine's resolution)
    check_golden(name, render_text(result, deterministic=True, resolution=resolution_of(m)))


def test_several_violations_in_execution_order_with_carets():
    result, _ = run_example("programs/several.ngc", "grinder.toml", base=GOLDEN)
    text = render_text(result, deterministic=True)
    heads = [ln for ln in text.splitlines() if ": violation[" in ln]
    assert [h.split(":")[1] for h in heads] == ["5", "6", "8", "9"]
    lines = text.splitlines()
    i = lines.index("    G1 X-250")
    assert lines[i + 1] == "    ^~~~~~~~"  # the caret underlines the whole block
    assert lines[-1].startswith("programs/several.ngc: unsafe: 4 violating blocks, the first at line 5;")


def test_deterministic_mode_has_no_timing_or_solver_version():
    result, _ = run_example("programs/notch_dip.ngc", "grinder.toml")
    full = render_text(result).splitlines()[-1]
    det = render_text(result, deterministic=True).splitlines()[-1]
    assert result.solver_version and result.solver_version in full and full.endswith(" s")
    assert result.solver_version not in det and not det.endswith(" s")


def test_colour_only_when_asked_and_honours_no_color(monkeypatch):
    result, _ = run_example("programs/notch_dip.ngc", "grinder.toml")
    plain = render_text(result)
    coloured = render_text(result, color=True)
    assert "\x1b[" not in plain and "\x1b[1;31mviolation[wheel area]:\x1b[0m" in coloured

    class FakeTTY(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.delenv("NO_COLOR", raising=False)
    monkeypatch.setenv("TERM", "xterm-256color")
    assert use_color(FakeTTY()) is True
    assert use_color(io.StringIO()) is False
    monkeypatch.setenv("NO_COLOR", "1")
    assert use_color(FakeTTY()) is False
    monkeypatch.delenv("NO_COLOR")
    monkeypatch.setenv("TERM", "dumb")
    assert use_color(FakeTTY()) is False


def test_cli_text_is_plain_when_piped():
    r = subprocess.run([sys.executable, "-m", "nczones", "verify", "programs/notch_dip.ngc", "--machine",
                        "../machines/grinder.toml"], capture_output=True, text=True, cwd=EX)
    assert r.returncode == 1
    assert r.stdout.startswith("programs/notch_dip.ngc:5:1: violation[wheel area]: line leaves the allowed set")
    assert "\x1b[" not in r.stdout and "\r" not in r.stderr  # no colour, no progress bar on a pipe
    assert (ROOT / "tests" / "golden" / "report" / "unsafe_notch_dip.txt").exists()


def test_a_witness_on_an_enclosed_path_is_not_called_the_first_exit():
    """A polar move's counterexample is a certified point, not a located first exit: the text, JSON and
    SARIF reports say so, while an exactly located exit keeps its "first exit at" line."""
    import json

    import jsonschema

    from nczones.machine import load_machine
    from nczones.prover import verify
    from nczones.prover.render import to_json_dict
    from nczones.report.sarif import render_sarif

    polar = verify(str(EX / "programs/polar_face.nc"),
                   load_machine(EX / "machines/turning_centre_clamp_near.toml"), file="polar_face.nc")
    exact, _ = run_example("programs/notch_dip.ngc", "grinder.toml")
    assert polar.verdict.label == "unsafe" and exact.verdict.label == "unsafe"
    v, w = polar.violations[0], exact.violations[0]
    assert not v.exit_located and w.exit_located and w.first_exit_exact
    text = render_text(polar, deterministic=True)
    assert "first exit not located" in text and "first exit at" not in text
    assert "first exit at X200 Y130" in render_text(exact, deterministic=True)
    schema = json.loads((ROOT / "specs" / "report.schema.json").read_text())
    for result, located in ((polar, False), (exact, True)):
        doc = to_json_dict(result)
        jsonschema.validate(doc, schema)
        assert {x["first_exit_located"] for x in doc["violations"]} == {located}
    sarif = render_sarif([polar], base=ROOT)
    assert "first exit not located" in sarif and "first exit at" not in sarif
