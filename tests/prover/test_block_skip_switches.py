"""Optional block skip /1 .. /9 (issue 33, class 5): nine switches, not one.

FANUC 0i-MF operator's manual (B-64604EN), "Optional block skip" / "Additional optional block skip"
(BDT2-BDT9): a block starting with ``/n`` (n = 1..9) is skipped while switch n is on; ``/`` alone is
``/1``.  Every switch a program uses is verified off and on, in every combination with the other free
switches (``nczones.prover.switch_combinations``); a violation names the switches its witness depends on.

LinuxCNC (the installed ``rs274``, 2.9): one switch.  With it on (``rs274 -b``) a line whose first
character other than blanks is ``/`` is skipped without reading the rest (``/1 G0 X4``, ``//G0 X4``); with
it off those two are errors ("Bad character '1' used", "Bad character '/' used").
"""

from __future__ import annotations

import itertools
import json
import shutil
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import jsonschema
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.blockskip import format_block_delete, parse_block_delete, used_switches
from nczones.errors import GcodeError, InvalidArgument, MachineFileError
from nczones.gcode import interpret_text
from nczones.machine import load_machine, parse_machine
from nczones.prover import MAX_SWITCH_COMBINATIONS, Verdict, verify_text
from nczones.replay import replay_report
from nczones.report import render_report
from tests.machines import machine_text

FANUC_MILL = "specs/machines/fanuc_mill.toml"
# fanuc_mill.toml: G54 = (-400, -250, -300), H1 = 110; the clamp (a tip zone) is machine X -315..-285,
# Y -270..-190, Z -510..-285, i.e. in G54 program coordinates X 85..115, Y -20..60, tip Z below 15.
HEAD = "%\nO1000\nG00 G17 G40 G49 G80 G90 G21\nG54 G00 X0 Y0\n"
# Z5 (tip inside the clamp's height); /2 lifts to Z50 before X100 crosses the clamp (X 85..115 at Y0):
# with switch 2 on the lift is skipped and line 7 enters the clamp.
LIFT = HEAD + "G43 H1 Z5.\n/2 Z50.\nX100.\nG00 Z50.\nM30\n%\n"


def _fanuc():
    return load_machine(FANUC_MILL)


def test_a_skipped_bdt2_lift_is_unsafe_and_names_switch_2():
    # before the fix /2 lines ran in both passes: safe
    r = verify_text(LIFT, _fanuc())
    assert r.verdict is Verdict.UNSAFE
    assert r.violations[0].line == 7 and r.violations[0].zone == "clamp"
    assert r.violations[0].switches == (("block_delete/2", "on"),)
    assert any("/2" in n and "off (those lines run) and on" in n for n in r.notes)


def test_fixed_switches_and_the_report_says_so():
    m = _fanuc()
    assert verify_text(LIFT, m, block_delete="2=off").verdict is Verdict.SAFE
    assert verify_text(LIFT, m, block_delete="off").verdict is Verdict.SAFE
    # switch 1 fixed says nothing about switch 2
    assert verify_text(LIFT, m, block_delete="1=off").verdict is Verdict.UNSAFE
    on = verify_text(LIFT, m, block_delete="off,2=on")
    assert on.verdict is Verdict.UNSAFE and on.violations[0].switches == ()
    assert any("/2 ON only" in n for n in on.notes)
    assert dict(on.settings)["block_delete"] == "off,2=on"
    with pytest.raises(InvalidArgument, match="switch position"):
        verify_text(LIFT, m, block_delete="2=maybe")


def test_the_machine_file_names_switches():
    text = Path(FANUC_MILL).read_text().replace('dialect = "fanuc"', 'dialect = "fanuc"\nblock_delete = "2=off"')
    m = parse_machine(text, "fanuc_2off.toml")
    assert m.block_delete == "2=off"
    r = verify_text(LIFT, m)
    assert r.verdict is Verdict.SAFE and any("/2 OFF only" in n for n in r.notes)
    table = Path(FANUC_MILL).read_text().replace('dialect = "fanuc"',
                                                 'dialect = "fanuc"\nblock_delete = { 2 = "off", 3 = "on" }')
    assert parse_machine(table).block_delete == "2=off,3=on"
    for bad in ('"2=maybe"', '"0=on"', '"1=on,1=off"', '"2=on,off"', '{ 10 = "on" }'):
        with pytest.raises(MachineFileError, match="ZN114"):
            parse_machine(text.replace('block_delete = "2=off"', f"block_delete = {bad}"))


def test_block_delete_forms():
    assert format_block_delete(parse_block_delete("both")) == "both"
    assert format_block_delete(parse_block_delete(" off , /2 = both")) == "off,2=both"
    assert parse_block_delete({"3": "on"})[3] == "on" and parse_block_delete({"3": "on"})[1] == "both"
    assert used_switches("G0\n/G0 X1\n/1 G0\n/9G0\n", "fanuc") == {1: [2, 3], 9: [4]}


def test_interacting_switches_every_combination():
    # /3 skips G91: X100 is absolute (enters the clamp from X0 or X200) or incremental (from X0 only).
    # /2 on skips the drop to Z5: every crossing is at Z50, above the clamp.
    program = HEAD + "G43 H1 Z50.\n/2 Z5.\n/3 G91\n/4 X200.\nX100.\nG90 G00 Z50.\nM30\n%\n"
    r = verify_text(program, _fanuc())
    got = {(v.line, v.switches) for v in r.violations}
    # line 8 (/4 X200 from X0 crosses X 85..115 at Z5, absolute or incremental): needs /2 off, /4 off
    assert (8, (("block_delete/2", "off"), ("block_delete/4", "off"))) in got
    # line 9: X100 after X200 absolute (back across), or from X0: a witness with /3 on and /4 off
    assert any(line == 9 and ("block_delete/2", "off") in sw for line, sw in got)
    notes = " ".join(r.notes)
    assert "in every combination with /3, /4" in notes


def test_too_many_free_switches_is_unknown_unless_fixed():
    # five free switches, each lifting further: nothing ever reaches the clamp (safe in every combination)
    lines = "".join(f"/{n} Z{50 + n}.\n" for n in range(2, 7))
    program = HEAD + "G43 H1 Z50.\n" + lines + "X100.\nM30\n%\n"
    assert 2 ** 5 > MAX_SWITCH_COMBINATIONS
    r = verify_text(program, _fanuc())
    assert r.verdict is Verdict.UNKNOWN
    assert [x.code for x in r.reasons] == ["VF206"] and "/2, /3, /4, /5, /6" in r.reasons[0].message
    assert verify_text(program, _fanuc(), block_delete="5=off,6=off").verdict is Verdict.SAFE
    # a witness found among the verified combinations still makes it unsafe
    drop = HEAD + "G43 H1 Z50.\n" + lines + "/7 Z5.\nX100.\nM30\n%\n"
    r = verify_text(drop, _fanuc())
    assert r.verdict is Verdict.UNSAFE and r.violations[0].line == 12
    assert dict(r.violations[0].switches)["block_delete/7"] == "off"


def test_combinations_whose_runs_cannot_differ_are_not_run():
    # /5 /6 /7 are in O2000, which only /4 calls (switch 4 off); /2 is after M30 (never run).  Of the 32
    # combinations of /2 and /4 .. /7 only 8 + 1 runs can differ: with switch 4 on no run reaches a /5, /6
    # or /7 line, and no run reaches the /2 line.  Without that the 32 would exceed the 16 runs (VF206).
    sub = "O2000\n/5 G00 Z5.\n/6 X100.\n/7 G00 Z60.\nM99\n"
    program = HEAD + "G43 H1 Z50.\n/4 M98 P2000\nX0\nM30\n/2 G00 X500.\n" + sub + "%\n"
    r = verify_text(program, _fanuc())
    assert not any(x.code == "VF206" for x in r.reasons)
    assert any("9 of the 32 combinations" in n for n in r.notes), r.notes
    # switches 4, 5, 6 off: the tip at Z5 crosses the clamp (X 85..115) at line 12 (/6 X100.) whatever /7
    # and /2 are; rising from Z5 at X100 (line 13) needs /7 off too
    got = {v.line: dict(v.switches) for v in r.violations}
    assert got[12] == {"block_delete/4": "off", "block_delete/5": "off", "block_delete/6": "off"}
    assert got[13] == {"block_delete/4": "off", "block_delete/5": "off", "block_delete/6": "off",
                       "block_delete/7": "off"}
    # /2 before the call instead: 2 x 8 + 2 x 1 = 18 runs can differ, more than 16: VF206
    r = verify_text(program.replace("/4 M98", "/2 Z55.\n/4 M98").replace("M30\n/2 G00 X500.\n", "M30\n"),
                    _fanuc())
    assert r.verdict is Verdict.UNSAFE and any(x.code == "VF206" for x in r.reasons)


def test_a_switch_only_a_library_program_uses(tmp_path):
    # O9001 (a --library file) steps X by 10 to X90 and, switch 3 off, drops the tip to Z-10 inside the
    # clamp (X 85..115, tip Z below 15); the main text has no '/' line at all
    (tmp_path / "O9001.nc").write_text("O9001\nG91 G00 X10.\n/3 G00 Z-60.\nM99\n")
    program = HEAD + "G00 X80.\nG43 H1 Z50.\nM98 P9001\nG90 G00 Z50.\nM30\n%\n"
    m = _fanuc()
    r = verify_text(program, m, library=str(tmp_path))
    assert r.verdict is Verdict.UNSAFE
    assert r.violations[0].switches == (("block_delete/3", "off"),)
    assert any("library program start with /3" in n for n in r.notes)
    # fixed on, the library line is skipped (it ran before: a fixed switch reached only the main text)
    on = verify_text(program, m, library=str(tmp_path), block_delete="3=on")
    assert on.verdict is Verdict.SAFE and any("/3 ON only" in n for n in on.notes)
    assert verify_text(program, m, library=str(tmp_path), block_delete="3=off").verdict is Verdict.UNSAFE


def test_the_vectorized_tier_long_program():
    # > 512 lines: the same reproducer after 600 plain moves far from the clamp
    pad = "".join(f"G01 X{-50 - (k % 7)}. Y{-50 - (k % 5)}. F1000.\n" for k in range(600))
    program = HEAD + "G43 H1 Z5.\n" + pad + "G00 X0 Y0\n/2 Z50.\nX100.\nG00 Z50.\nM30\n%\n"
    r = verify_text(program, _fanuc())
    assert r.verdict is Verdict.UNSAFE
    v = r.violations[0]
    assert v.zone == "clamp" and v.line == 5 + 600 + 3 and v.switches == (("block_delete/2", "on"),)
    assert verify_text(program, _fanuc(), block_delete="2=off").verdict is Verdict.SAFE


def test_cli_exit_codes_and_reports(tmp_path):
    program = tmp_path / "o1000.nc"
    program.write_text(LIFT)

    def run(*args):
        return subprocess.run([sys.executable, "-m", "nczones", "verify", str(program), "--machine", FANUC_MILL,
                               *args], capture_output=True, text=True)

    both = run()
    assert both.returncode == 1, both.stdout + both.stderr
    assert "with the block-delete/2 switch on" in both.stdout
    js = run("--format", "json")
    doc = json.loads(js.stdout)
    assert doc["violations"][0]["switches"] == {"block_delete/2": "on"}
    assert doc["settings"]["block_delete"] == "both"
    schema = json.loads(Path("specs/report.schema.json").read_text())
    jsonschema.validate(doc, schema)
    fixed_on = json.loads(render_report(verify_text(LIFT, _fanuc(), block_delete="off,2=on"), "json"))
    assert fixed_on["settings"]["block_delete"] == "off,2=on"
    jsonschema.validate(fixed_on, schema)
    fixed = run("--block-delete", "2=off")
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert "/2 OFF only" in fixed.stdout
    bad = run("--block-delete", "2=sometimes")
    assert bad.returncode == 2 and "VF110" in bad.stderr and "Traceback" not in bad.stderr
    # the JSON report replays: the witness is re-found with switch 2 on
    checks = replay_report(doc, program_file=str(program), machine_file=FANUC_MILL)
    assert checks and all(c.confirmed for c in checks), [c.render() for c in checks]


def test_every_format_names_the_switch():
    r = verify_text(LIFT, _fanuc())
    assert "with the block-delete/2 switch on" in render_report(r, "text")
    sarif = json.loads(render_report(r, "sarif", machine=_fanuc()))
    assert "block-delete/2 switch on" in sarif["runs"][0]["results"][0]["message"]["text"]


# ---- the result equals the worst over explicit per-combination runs --------------------------------

_LINES = ("Z5.", "Z50.", "X100.", "X0", "X200.", "G91", "G90", "Y-100.", "Y0", "X-30.")


_BODIES = st.lists(st.tuples(st.sampled_from((None, 1, 2, 3)), st.sampled_from(_LINES)), min_size=2, max_size=6)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_BODIES)
def test_result_is_the_worst_over_explicit_combinations(body):
    _check_worst(body)


@pytest.mark.long
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_BODIES)
def test_result_is_the_worst_over_explicit_combinations_long(body):
    _check_worst(body)


def _check_worst(body):
    text = HEAD + "G43 H1 Z50.\n" + "".join((f"/{n} " if n == 1 and k % 2 else "/ " if n == 1 else
                                             f"/{n} " if n else "") + code + "\n"
                                            for k, (n, code) in enumerate(body)) + "G90 G00 Z50.\nM30\n%\n"
    m = _fanuc()
    used = sorted(used_switches(text, "fanuc"))
    whole = verify_text(text, m, max_violations=100)
    runs = {}
    for bits in itertools.product(("off", "on"), repeat=len(used)):
        spec = ",".join(f"{n}={p}" for n, p in zip(used, bits)) or "off"
        runs[bits] = verify_text(text, m, block_delete=spec, max_violations=100)
    assert whole.verdict == min(r.verdict for r in runs.values())
    assert {(v.line, v.zone) for v in whole.violations} == {(v.line, v.zone) for r in runs.values()
                                                             for v in r.violations}
    for v in whole.violations:
        named = dict(v.switches)
        # the combination the violation names (switches it does not name: off) reproduces it
        bits = tuple(named.get("block_delete" if n == 1 else f"block_delete/{n}", "off") for n in used)
        assert (v.line, v.zone) in {(w.line, w.zone) for w in runs[bits].violations}
        # and a switch it does not name does not matter: flipped, the violation stays
        for k, n in enumerate(used):
            if ("block_delete" if n == 1 else f"block_delete/{n}") not in named:
                flipped = bits[:k] + (("on",) if bits[k] == "off" else ("off",)) + bits[k + 1:]
                assert (v.line, v.zone) in {(w.line, w.zone) for w in runs[flipped].violations}


# ---- LinuxCNC: one switch; /1 and // lines as rs274 reads them ---------------------------------------

LINUXCNC = machine_text("box_x3")


@pytest.mark.parametrize("line", ["/1 G0 X4", "//G0 X4", "/2 G0 X4", "  /1G0 X4"])
@pytest.mark.parametrize("hashes", [False, True])
def test_linuxcnc_slash_digit_lines_follow_rs274(line, hashes):
    # rs274 -b skips the line unread (G0 X1 then G0 Y2); rs274 without -b stops: "Bad character"
    m = parse_machine(LINUXCNC)
    program = f"#1=2\nG0 X1\n{line}\nG0 Y[#1]\nM2\n" if hashes else f"G0 X1\n{line}\nG0 Y2\nM2\n"
    on = verify_text(program, m, block_delete="on")
    assert on.verdict is Verdict.SAFE  # X4 would leave the travel (X <= 3): it is skipped
    ends = [tuple(s.end) for s in interpret_text(program, m, block_delete=True).segments()]
    assert ends == [(1, 0, 0), (1, 2, 0)]
    for mode in ("both", "off"):
        with pytest.raises(GcodeError, match="GC101"):
            verify_text(program, m, block_delete=mode)


def test_linuxcnc_slash_digit_lines_in_a_long_program():
    # > 512 lines (the vectorized tier takes the plain runs): the /1 line is still skipped unread
    m = parse_machine(LINUXCNC)
    pad = "".join(f"G1 X{k % 3} Y{k % 5} F100\n" for k in range(600))
    program = pad + "G0 X1 Y0\n/1 G0 X4\n//G0 X4\nG0 Y2\nM2\n"
    assert verify_text(program, m, block_delete="on").verdict is Verdict.SAFE
    with pytest.raises(GcodeError, match="GC101"):
        verify_text(program, m)


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
@pytest.mark.parametrize("line", ["/1 G0 X4", "//G0 X4", "/ G0 X4", "/G0 X[1+3]"])
def test_linuxcnc_block_delete_agrees_with_rs274(tmp_path, line):
    from tests.oracles.rs274 import canon_motion

    program = f"G0 X1\n{line}\nG0 Y2\nM2\n"
    path = tmp_path / "t.ngc"
    path.write_text(program)
    m = parse_machine(LINUXCNC)
    for flag, skip in (([], False), (["-b"], True)):
        run = subprocess.run(["rs274", "-g", *flag, str(path)], capture_output=True, text=True, timeout=60,
                             cwd=tmp_path)
        failed = "Bad character" in run.stdout + run.stderr
        try:
            ours = [s.end[:3] for s in interpret_text(program, m, block_delete=skip).segments()]
        except GcodeError:
            ours = None
        assert (ours is None) == failed, (line, skip, run.stdout, run.stderr)
        if ours is not None:
            theirs = [mv.end[:3] for mv in canon_motion(run.stdout) if mv.kind in ("RAPID", "LINE")]
            assert [tuple(x) for x in ours] == [tuple(x) for x in theirs], (line, skip)
            assert all(isinstance(x, Fraction) for e in ours for x in e)


@pytest.mark.long
@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
def test_linuxcnc_corpus_block_delete_lines_agree_with_rs274_in_both_positions(tmp_path):
    # every LinuxCNC corpus program with a line starting with '/' (14 on 2026-12-06), through rs274 -g with
    # and without -b and through nczones with the switch on and off: the same motion (or the same refusal)
    from tests.corpus import CORPUS
    from tests.oracles.rs274 import canon_error, canon_motion, compare
    from tests.tools.rs274_corpus import BAD_PERCENT, NO_END, TOOLS, machine_for
    from tests.tools.rs274_diff import RS274, tool_table, var_file

    root = CORPUS / "linuxcnc"
    if not root.is_dir():
        pytest.skip("the corpus is not here")
    files = sorted(p for p in root.rglob("*.ngc") if used_switches(p.read_text(errors="replace"), "linuxcnc"))
    assert files
    tools = {n: Fraction(0) for n in TOOLS}
    m = machine_for(tools)
    (tmp_path / "tool.tbl").write_text(tool_table(tools))
    (tmp_path / "prog.var").write_text(var_file({}))
    bad = []
    for path in files:
        program = path.read_text(errors="replace")
        (tmp_path / "prog.ngc").write_text(program)
        for flag, skip in ((["-b"], True), ([], False)):
            run = subprocess.run([RS274, "-t", "tool.tbl", "-v", "prog.var", "-g", *flag, "prog.ngc"], cwd=tmp_path,
                                 capture_output=True, text=True, errors="replace", timeout=120,
                                 stdin=subprocess.DEVNULL)
            error = canon_error(run.returncode, run.stderr)
            if error is not None and (error[0] == NO_END or (error[0] == BAD_PERCENT and error[1].strip() == "%")):
                error = None
            outcome = compare(program, m, canon_motion(run.stdout), error, arc_tolerance="linuxcnc",
                              block_delete=skip)
            if outcome.status != "match":
                bad.append((str(path.relative_to(root)), skip, outcome.status, outcome.detail[:200]))
    assert not bad, bad
