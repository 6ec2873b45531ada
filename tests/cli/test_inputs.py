"""The command line as a gate in front of a machine (issue 20): strict inputs, many files, one line per OS error.

Every bad case runs the real command in a subprocess on real files and checks the exact message and
exit status.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import jsonschema
import pytest

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"
MILL = str(ROOT / "specs" / "machines" / "mill.toml")
GRINDER = str(ROOT / "specs" / "machines" / "grinder.toml")
SCHEMA = json.loads((ROOT / "specs" / "report.schema.json").read_text())


def nczones(*args: str, cwd: Path | str = ROOT, stdin: bytes | None = None) -> subprocess.CompletedProcess:
    r = subprocess.run([sys.executable, "-m", "nczones", *args], capture_output=True, cwd=cwd, input=stdin)
    r.stdout, r.stderr = r.stdout.decode(), r.stderr.decode()  # type: ignore[assignment]
    assert "Traceback" not in r.stderr, r.stderr
    return r


def test_a_mistyped_path_is_an_error_not_program_text(tmp_path):
    r = nczones("verify", "O1000", "--machine", MILL, cwd=tmp_path)
    assert (r.returncode, r.stdout) == (2, "")
    assert r.stderr == "O1000: error[GC100]: cannot read the program: No such file or directory\n"
    r = nczones("verify", "part.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr == "part.nc: error[GC100]: cannot read the program: No such file or directory\n"


def test_a_directory_is_not_a_program(tmp_path):
    r = nczones("verify", str(tmp_path), "--machine", MILL)
    assert r.returncode == 2
    assert r.stderr == f"{tmp_path}: error[GC100]: cannot read the program: Is a directory\n"


@pytest.mark.parametrize("content,what", [
    (b"", "the file is empty (0 bytes)"),
    (b"  \n\t\n\r\n", "the file holds only whitespace"),
])
def test_an_empty_program_is_exit_2(tmp_path, content, what):
    (tmp_path / "empty.nc").write_bytes(content)
    r = nczones("verify", "empty.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr == f"empty.nc: error[GC109]: empty program: {what}; there is nothing to verify\n"


def test_empty_standard_input_is_exit_2():
    r = nczones("verify", "-", "--machine", MILL, stdin=b"")
    assert r.returncode == 2
    assert r.stderr == "<stdin>: error[GC109]: empty program: the input is empty (0 bytes); there is nothing to verify\n"


def test_a_program_without_motion_says_so(tmp_path):
    (tmp_path / "still.nc").write_text("G21 G90 (nothing moves)\nM30\n")
    r = nczones("verify", "still.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 0
    assert r.stdout.startswith("still.nc: safe: the program has no motion (nothing can leave the allowed set); "
                               "0 segments checked")


def test_a_binary_file_gets_one_message(tmp_path):
    (tmp_path / "tool.nc").write_bytes(b"\x7fELF\x02\x01\x01\x00\x00\xb8\xc3\x00" * 200)
    r = nczones("verify", "tool.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr == "tool.nc: error[GC108]: a binary file, not G-code text: a NUL byte at offset 7 (line 1)\n"


def test_non_utf8_text_outside_a_comment_gets_one_message(tmp_path):
    (tmp_path / "latin1.nc").write_bytes(b"G21\nG0 X1 \xd8 (Bohrung 5 mm)\n")
    r = nczones("verify", "latin1.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr == ("latin1.nc: error[GC108]: not UTF-8 text: byte 0xd8 at offset 10 (line 2) is not valid "
                        "UTF-8 and is not inside a comment; save the program as UTF-8 (or ASCII)\n")


def test_latin1_and_cp1252_bytes_in_comments_are_read_with_a_note(tmp_path):
    # issue 38: a shop's comment with Ø (Latin-1 0xd8), ° (0xb0) or € (CP1252 0x80) no longer rejects the program
    (tmp_path / "latin1.nc").write_bytes(b"G21 G90 G54\nG0 X1 (Bohrung \xd8 5 mm, \x80)\nG0 X2 ; Tiefe 3\xb0\n")
    r = nczones("verify", "latin1.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert ("latin1.nc: note: the program is not UTF-8: bytes inside comments on line(s) 2, 3 were read as "
            "CP1252/Latin-1") in r.stdout
    from nczones.gcode.source import load_program

    assert load_program(tmp_path / "latin1.nc").text.splitlines()[1:] == ["G0 X1 (Bohrung Ø 5 mm, €)",
                                                                          "G0 X2 ; Tiefe 3°"]


@pytest.mark.parametrize("codec, bom, label", [("utf-16-le", b"\xff\xfe", "UTF-16 LE"),
                                               ("utf-16-be", b"\xfe\xff", "UTF-16 BE"),
                                               ("utf-8", b"\xef\xbb\xbf", None)])
def test_a_byte_order_mark_decides_the_encoding(tmp_path, codec, bom, label):
    text = "G21 G90 G54\nG0 X1 (Ø 5)\nG0 X500\n"  # G54 X150 + X500 leaves mill.toml's table: the program is read, not skipped
    (tmp_path / "p.nc").write_bytes(bom + text.encode(codec))
    r = nczones("verify", "p.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 1, r.stderr
    assert "p.nc:3:" in r.stdout and "unsafe" in r.stdout
    assert (f"p.nc: note: the program is {label} text (read by its byte order mark)" in r.stdout) == (label is not None)


def test_a_huge_single_line_is_refused_at_once_with_a_short_excerpt(tmp_path):
    line = "G1 X1 Y2 " * 2_500_000  # 22.5 MB, no line end
    (tmp_path / "one_line.nc").write_text(line)
    t0 = time.perf_counter()
    r = nczones("verify", "one_line.nc", "--machine", MILL, cwd=tmp_path)
    elapsed = time.perf_counter() - t0
    assert r.returncode == 2
    head, source, caret = r.stderr.splitlines()
    assert head == ("one_line.nc:1:1: error[GC110]: line 1 is 22,500,000 characters long; nczones reads lines of "
                    "at most 65,536 characters")
    assert source.startswith("    G1 X1 Y2 G1") and source.endswith("…") and len(source) <= 4 + 200
    assert caret == "    ^"
    assert elapsed < 30  # was 82 s and 3.4 GB; a generous bound for a loaded 2-core machine


def test_carriage_returns_only_get_a_hint(tmp_path):
    (tmp_path / "mac.nc").write_bytes(b"G0 X1\r" * 20_000)
    r = nczones("verify", "mac.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr.splitlines()[0] == (
        "mac.nc:1:1: error[GC110]: line 1 is 120,000 characters long; nczones reads lines of at most 65,536 "
        "characters; its lines seem to end with a carriage return only (\\r): convert them to \\n")


def test_excerpts_are_cut_around_the_caret(tmp_path):
    (tmp_path / "long.nc").write_text("G1 X1 (" + "x" * 5000 + ") $ Y2\n")
    r = nczones("verify", "long.nc", "--machine", MILL, cwd=tmp_path)
    assert r.returncode == 2
    head, source, caret = r.stderr.splitlines()[:3]
    assert head.startswith("long.nc:1:5010: error[GC101]: unexpected character '$'")
    assert len(source) <= 4 + 200 and len(caret) <= 4 + 200
    assert source.startswith("    …") and source.endswith(") $ Y2")
    assert source[caret.index("^")] == "$"


@pytest.mark.parametrize("target,message", [
    ("missing/dir/r.json", "the directory missing/dir does not exist"),
    (".", "it is a directory"),
    ("plain.txt/r.json", "plain.txt is a file, not a directory"),
])
def test_output_that_cannot_be_written_is_one_line(tmp_path, target, message):
    (tmp_path / "plain.txt").write_text("a file where a directory is expected\n")
    r = nczones("verify", str(EX / "programs/notch_over.ngc"), "--machine", GRINDER, "--output", target,
                cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr == f"<command line>: error[VF107]: --output {target}: cannot write the report: {message}\n"


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write anywhere")
def test_output_without_permission_is_one_line(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        r = nczones("verify", str(EX / "programs/notch_over.ngc"), "--machine", GRINDER, "--output",
                    str(locked / "r.json"))
    finally:
        locked.chmod(0o700)
    assert r.returncode == 2
    assert r.stderr.endswith("cannot write the report: permission denied\n")


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full (Linux)")
def test_an_output_error_while_writing_is_one_line():
    """An error that only writing shows (a full disk: /dev/full, which root cannot write either)."""
    r = nczones("verify", str(EX / "programs/notch_over.ngc"), "--machine", GRINDER, "--output", "/dev/full")
    assert r.returncode == 2
    assert r.stderr == ("<command line>: error[VF107]: --output /dev/full: cannot write the report: "
                        "No space left on device\n")


def test_a_missing_machine_file_is_one_line(tmp_path):
    r = nczones("verify", str(EX / "programs/notch_over.ngc"), "--machine", "nope.toml", cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr == "nope.toml: error[ZN099]: cannot read the machine file: No such file or directory\n"


def test_a_closed_stdout_is_one_line():
    """``nczones verify ... | head -0``: the reader is gone before the report is written."""
    p = subprocess.Popen([sys.executable, "-m", "nczones", "verify", str(EX / "programs/notch_dip.ngc"),
                          "--machine", GRINDER], stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=ROOT)
    p.stdout.close()
    err = p.stderr.read().decode()
    assert p.wait() == 2
    assert err == "nczones: error: cannot read or write standard output: Broken pipe\n"


def test_several_programs_one_report_each_and_the_worst_exit():
    programs = sorted(str(p.relative_to(ROOT)) for p in (EX / "programs").glob("*.ngc"))
    r = nczones("verify", *programs, "--machine", "specs/machines/mill.toml")
    # unsafe programs (vise_enter, drill_vise, ...) make it 1, though others do not parse on a 3-axis mill
    assert r.returncode == 1
    summaries = {m.group(1): m.group(2) for m in re.finditer(r"^([^:\n]+): (safe|unsafe|unknown): ", r.stdout, re.M)}
    failed = {m.group(1) for m in re.finditer(r"^([^:\n]+):\d+:\d+: error\[", r.stderr, re.M)}
    assert sorted(summaries.keys() | failed) == programs and not summaries.keys() & failed
    assert summaries["specs/examples/programs/drill_vise.ngc"] == "unsafe"
    assert summaries["specs/examples/programs/vise_slide.ngc"] == "safe"


def test_worst_exit_order():
    over, dip = str(EX / "programs/notch_over.ngc"), str(EX / "programs/notch_dip.ngc")
    comp, slide = str(EX / "programs/cutter_comp.ngc"), str(EX / "programs/vise_slide.ngc")
    assert nczones("verify", over, over, "--machine", GRINDER).returncode == 0
    assert nczones("verify", slide, comp, "--machine", MILL).returncode == 3  # safe + unknown
    assert nczones("verify", comp, "missing.nc", "--machine", MILL).returncode == 2  # unknown + bad input
    assert nczones("verify", "missing.nc", dip, over, "--machine", GRINDER).returncode == 1  # + unsafe


def test_standard_input_is_a_program():
    text = (EX / "programs/notch_dip.ngc").read_bytes()
    r = nczones("verify", "-", "--machine", GRINDER, stdin=text)
    assert r.returncode == 1
    assert r.stdout.startswith("<stdin>:5:1: violation[wheel area]: line leaves the allowed set, 90 mm deep\n")
    r = nczones("verify", "-", "--machine", GRINDER, "--format", "json", stdin=text)
    doc = json.loads(r.stdout)
    jsonschema.validate(doc, SCHEMA)
    assert doc["program"] == "<stdin>"
    assert doc["program_sha256"] == "421c2299bb064b2470586537b2862142070eefc43d4e6aa29db213fba7855ad7"
    assert nczones("verify", "-", "-", "--machine", GRINDER, stdin=text).stderr == \
        "<command line>: error[VF106]: standard input (-) can be read only once\n"


def test_json_for_several_programs_is_a_list_with_error_entries(tmp_path):
    (tmp_path / "bad.nc").write_text("G1 X1 $\n")
    r = nczones("verify", str(EX / "programs/notch_dip.ngc"), "bad.nc", str(EX / "programs/notch_over.ngc"),
                "--machine", GRINDER, "--format", "json", cwd=tmp_path)
    assert r.returncode == 1
    doc = json.loads(r.stdout)
    jsonschema.validate(doc, SCHEMA)
    assert [d["verdict"] for d in doc] == ["unsafe", "error", "safe"]
    assert doc[1] == {"program": "bad.nc", "verdict": "error", "errors": [
        {"code": "GC101", "message": doc[1]["errors"][0]["message"], "location": "bad.nc:1:7"}]}
    assert doc[1]["errors"][0]["message"].startswith("unexpected character '$'")
    assert r.stderr.startswith("bad.nc:1:7: error[GC101]: unexpected character '$'")


def test_html_takes_one_program():
    over = str(EX / "programs/notch_over.ngc")
    r = nczones("verify", over, over, "--machine", GRINDER, "--format", "html")
    assert r.returncode == 2
    assert r.stderr == ("<command line>: error[VF106]: --format html writes the report of one program; 2 were "
                        "given (use json, sarif or text for several)\n")


def test_max_iterations_bounds_loops(tmp_path):
    (tmp_path / "loop.ngc").write_text("#1 = 0\no100 while [#1 LT 50]\nG1 X[#1] F100\n#1 = [#1 + 1]\n"
                                       "o100 endwhile\nM2\n")
    assert nczones("verify", "loop.ngc", "--machine", MILL, cwd=tmp_path).returncode == 0
    r = nczones("verify", "loop.ngc", "--machine", MILL, "--max-iterations", "10", cwd=tmp_path)
    assert r.returncode == 3
    assert "loop.ngc:2:1: unknown[GC392]: o100 while loop ran more than 10 iterations (max_loop_iterations)" in r.stdout
    bad = nczones("verify", "loop.ngc", "--machine", MILL, "--max-iterations", "0", cwd=tmp_path)
    assert bad.returncode == 2
    assert bad.stderr == "<command line>: error[VF105]: --max-iterations 0: must be at least 1\n"
    sim = nczones("simulate", "loop.ngc", "--machine", MILL, "--max-iterations", "10", cwd=tmp_path)
    assert sim.returncode == 2 and "GC392" in sim.stdout


def test_simulate_and_plot_take_the_same_inputs(tmp_path):
    assert nczones("simulate", "O1000", "--machine", MILL, cwd=tmp_path).stderr == \
        "O1000: error[GC100]: cannot read the program: No such file or directory\n"
    text = (EX / "programs/notch_dip.ngc").read_bytes()
    sim = nczones("simulate", "-", "--machine", GRINDER, "--mode", "check", "--format", "json", stdin=text)
    assert sim.returncode == 1
    doc = json.loads(sim.stdout)
    assert doc["program"] == "<stdin>" and isinstance(doc["simulated_time_s"], float)
    r = nczones("plot", "-", "--machine", GRINDER, "-o", str(tmp_path / "p.png"), "--no-verify", stdin=text)
    assert r.returncode == 0 and (tmp_path / "p.png").stat().st_size > 1000


def test_every_option_has_help_text():
    """Every option and argument of every command and subcommand, walked through argparse (nested ones too)."""
    import argparse

    from nczones.cli import build_parser

    missing: list[str] = []
    seen: list[str] = []

    def walk(parser: argparse.ArgumentParser, path: str) -> None:
        for a in parser._actions:
            if isinstance(a, argparse._HelpAction):
                continue
            if isinstance(a, argparse._SubParsersAction):
                for name, sub in a.choices.items():
                    walk(sub, f"{path} {name}".strip())
                continue
            seen.append(f"{path} {'/'.join(a.option_strings) or a.dest}")
            if not a.help or a.help == argparse.SUPPRESS:
                missing.append(seen[-1])

    walk(build_parser(), "")
    assert missing == []
    # the walk reached nested subcommands and the options the issue named
    assert {"verify --machine", "verify --engine", "verify --max-violations", "verify --output",
            "verify --max-iterations", "fleet check --scheduler"} <= set(seen)


def _durations(doc: object, path: str = "") -> list[tuple[str, object]]:
    """Every value of a JSON document under a key that names seconds (``..._s``), with its path."""
    out: list[tuple[str, object]] = []
    if isinstance(doc, dict):
        for k, v in doc.items():
            if k.endswith("_s") and not isinstance(v, (dict, list)):
                out.append((f"{path}/{k}", v))
            out += _durations(v, f"{path}/{k}")
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            out += _durations(v, f"{path}/{i}")
    return out


def test_one_number_format_for_times_in_verify_simulate_and_home():
    """Seconds are JSON numbers rounded to the microsecond in every command's report (issue 20: ``simulate``
    wrote numbers, ``home`` strings)."""
    dip = str(EX / "programs/notch_dip.ngc")
    docs = {
        "verify": nczones("verify", dip, "--machine", GRINDER, "--format", "json"),
        "simulate": nczones("simulate", dip, "--machine", GRINDER, "--format", "json"),
        "home": nczones("home", "--machine", "specs/machines/homing_mill.toml", "--axis", "Z", "--format", "json"),
    }
    for command, r in docs.items():
        times = _durations(json.loads(r.stdout))
        assert times, f"{command} reports no times"
        for where, value in times:
            if value is None:  # an unset budget
                continue
            assert type(value) is float, f"{command} {where} = {value!r}"
            assert value == round(value, 6), f"{command} {where} = {value!r} is not rounded to the microsecond"


def test_the_python_api_reads_a_str_as_a_path_never_as_text(tmp_path, monkeypatch):
    """``verify("O1001", m)`` read the name as G-code and proved it safe; a str is a path, text goes to *_text."""
    from nczones.errors import GcodeError
    from nczones.gcode import interpret, segments, segments_text
    from nczones.machine import load_machine
    from nczones.prover import verify, verify_text

    monkeypatch.chdir(tmp_path)
    machine = load_machine(GRINDER)
    for call in (verify, segments, interpret):
        with pytest.raises(GcodeError) as e:
            call("O1001", machine)
        assert str(e.value) == "O1001: error[GC100]: cannot read the program: No such file or directory"
    with pytest.raises(GcodeError) as e:
        verify("G0 X1", machine)  # text given where a path is expected is not read as text either
    assert e.value.diagnostics[0].code == "GC100"
    (tmp_path / "O1001").write_text("G0 X10 Y300\n")
    assert verify("O1001", machine).verdict.value == verify(tmp_path / "O1001", machine).verdict.value
    assert verify_text("G0 X10 Y300\n", machine).verdict.value == verify("O1001", machine).verdict.value
    assert [s.end for s in segments_text("G0 X10 Y300\n", machine)] == [s.end for s in segments("O1001", machine)]


@pytest.mark.parametrize("name, text, label", [
    ("lathe.ini", "[EMC]\nMACHINE = LinuxCNC-HAL-SIM-LATHE\n[TRAJ]\nCOORDINATES = X Z\n", "a LinuxCNC INI file"),
    ("grbl $$.txt", "$0=10\n$1=25\n$130=200.000\n", "a Grbl $$ settings dump"),
    ("params.txt", "%\nN01320A1P500000A2P400000\n%\n", "a Fanuc parameter listing"),
])
def test_a_controller_configuration_given_as_machine_names_the_import_command(tmp_path, name, text, label):
    # issue 38: an INI passed as --machine gave "ZN100 not valid TOML" with no hint; the decision (specs/machine-file.md):
    # an error naming the exact import-machine command, never an import on the fly that the gate would not show
    (tmp_path / "p.nc").write_text("G0 X1\n")
    (tmp_path / name).write_text(text)
    r = nczones("verify", "p.nc", "--machine", name, cwd=tmp_path)
    assert (r.returncode, r.stdout) == (2, "")
    stem = name.rsplit(".", 1)[0]
    src, out = (f"'{name}'", f"'{stem}.toml'") if " " in name else (name, f"{stem}.toml")
    assert r.stderr == (f"{name}: error[ZN100]: not valid TOML: this looks like {label}, not a machine file: convert "
                        f"it once with `nczones import-machine {src} -o {out}` and pass {out} to --machine\n")
