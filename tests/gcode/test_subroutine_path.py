"""LinuxCNC subroutine files (issue 38, "LinuxCNC programs as shops keep them"): ``o<name> call`` of a sub
the program does not define reads ``name.ngc`` from LinuxCNC's ``[RS274NGC] SUBROUTINE_PATH`` folders, in
order (src/emc/rs274ngc/interp_o_word.cc ``find_ngc_file``); nczones takes them from ``--library`` (one
folder or an ``os.pathsep`` list).  Diagnostics and violations name the subroutine file and its line.

The motion is held to LinuxCNC's own ``rs274 -i t.ini`` with ``SUBROUTINE_PATH = nothere:subs``: the
first folder has no file, the second does (rs274 2.9 prints ``STRAIGHT_FEED(10, 0, 5)`` then
``STRAIGHT_FEED(10, 10, 5)`` for ``o<square> call [10]``; without the INI it stops with "EOF in file ...
seeking o-word: o<square>").
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import pytest

from nczones.machine import load_machine
from nczones.prover import verify_text as verify
from tests.oracles.rs274 import canon_error, canon_motion, compare, machine_text

MILL = "specs/machines/mill.toml"
# square.ngc line 2 is "G1 X#1 F100", line 3 "G1 Y#1"
SQUARE = "o<square> sub\nG1 X#1 F100\nG1 Y#1\no<square> endsub\nM2\n"
RS274 = os.environ.get("RS274", "/usr/bin/rs274")


@pytest.fixture
def subs(tmp_path: Path) -> Path:
    folder = tmp_path / "subs"
    folder.mkdir()
    (folder / "square.ngc").write_text(SQUARE)
    return folder


def _program(value: str, before: str = "", after: str = "") -> str:
    # the mill: G54 puts program X0 Y0 Z0 at machine X150 Y100 Z100; travel X 0..600, Y 0..400
    return f"G21 G90 G17 G54\nG0 X0 Y0 Z100\n{before}o<square> call [{value}]\n{after}G0 Z110\nM2\n"


@pytest.mark.skipif(not Path(RS274).exists(), reason="LinuxCNC's rs274 is not installed")
def test_motion_from_a_subroutine_file_is_linuxcncs(tmp_path: Path, subs: Path):
    program = "G21 G90 G17\nG0 X0 Y0 Z5\no<square> call [10]\nG0 Z10\nM2\n"
    (tmp_path / "prog.ngc").write_text(program)
    (tmp_path / "t.ini").write_text("[RS274NGC]\nSUBROUTINE_PATH = nothere:subs\n")
    p = subprocess.run([RS274, "-i", "t.ini", "-g", "prog.ngc"], cwd=tmp_path, capture_output=True, text=True,
                       errors="replace", timeout=20, stdin=subprocess.DEVNULL)
    moves = canon_motion(p.stdout)
    assert len(moves) >= 4  # the two feeds of the subroutine are in the log
    machine = load_machine_text(machine_text(("X", "Y", "Z"), {}))
    library = os.pathsep.join((str(tmp_path / "nothere"), str(subs)))
    assert compare(program, machine, moves, canon_error(p.returncode, p.stderr), library=library).status == "match"


def load_machine_text(text: str):
    from nczones.machine import parse_machine

    return parse_machine(text)


def test_without_a_library_the_call_stays_unknown_and_says_how():
    result = verify(_program("10"), load_machine(MILL), file="main.ngc")
    assert result.verdict.label == "unknown"
    (reason,) = [r for r in result.reasons if r.code == "GC393"]
    assert "--library" in reason.message and "SUBROUTINE_PATH" in reason.message


@pytest.mark.parametrize("case", ["short", "parametric", "long"])
def test_a_violation_in_the_subroutine_file_names_that_file(subs: Path, case: str):
    # X500 from G54's X150 is machine X650, past the travel's 600: the feed at square.ngc:2 leaves it,
    # then square.ngc:3 (Y500 -> machine Y600 > 400) and the main program's G0 Z110 (still at X650)
    value, before, after = "500", "", ""
    if case == "parametric":  # '#' in the text: the double pass must hand the call to the full path
        before, value = "#<v> = 500\n", "#<v>"
    if case == "long":  # > 512 motions around the call: runs of plain lines on both sides
        before = "".join(f"G1 X{i % 7} Y{i % 5} F1000\n" for i in range(600))
        after = "".join(f"G1 X{i % 7} Y{i % 5} Z100\n" for i in range(600))
    machine = load_machine(MILL)
    result = verify(_program(value, before, after), machine, file="main.ngc", library=subs)
    assert result.verdict.label == "unsafe"
    where = [(v.span.file, v.span.line) for v in result.violations]
    sub_file = str(subs / "square.ngc")
    assert where[:2] == [(sub_file, 2), (sub_file, 3)]
    assert result.violations[0].span.text == "G1 X#1 F100"
    if case == "long":  # the return lands in the main program's second run of plain lines (line 605 + 1)
        assert where[2] == ("main.ngc", 3 + 600 + 1)
    else:
        assert where[2][0] == "main.ngc"
    # inside the travel the same program is safe
    ok = verify(_program("10" if case != "parametric" else "#<v>",
                         before.replace("500", "10"), after), machine, file="main.ngc", library=subs)
    assert ok.verdict.label == "safe", ok.reasons


def test_the_first_folder_with_the_file_wins_and_a_file_without_the_sub_is_an_error(tmp_path: Path, subs: Path):
    first = tmp_path / "first"
    first.mkdir()
    (first / "square.ngc").write_text("o<square> sub\nG1 X1 F100\no<square> endsub\nM2\n")
    machine = load_machine(MILL)
    result = verify(_program("500"), machine, file="main.ngc", library=os.pathsep.join((str(first), str(subs))))
    assert result.verdict.label == "safe"  # first/square.ngc moves to X1 only
    (first / "square.ngc").write_text("o<other> sub\no<other> endsub\n")
    from nczones.errors import GcodeError

    with pytest.raises(GcodeError) as err:
        verify(_program("500"), machine, file="main.ngc", library=[first, subs])
    assert err.value.diagnostics[0].code == "GC313" and "o<square>" in err.value.diagnostics[0].message


def test_the_library_is_searched_only_for_calls_the_file_does_not_define(tmp_path: Path, subs: Path):
    # the program's own o<square> (to X1) is LinuxCNC's choice over the file's (rs274: the offset map first)
    program = "G21 G90 G54\nG0 X0 Y0 Z100\no<square> sub\nG1 X1 F100\no<square> endsub\no<square> call [500]\nM2\n"
    assert verify(program, load_machine(MILL), library=subs).verdict.label == "safe"



def test_the_machine_files_subroutine_path_is_read_relative_to_it(tmp_path: Path, subs: Path):
    text = Path(MILL).read_text() + '\n[linuxcnc]\nsubroutine_path = ["missing", "subs"]\n'
    (tmp_path / "m.toml").write_text(text)
    machine = load_machine(tmp_path / "m.toml")
    assert machine.subroutine_path == (str(tmp_path / "missing"), str(subs))
    result = verify(_program("500"), machine, file="main.ngc")
    assert result.verdict.label == "unsafe" and result.violations[0].span.file == str(subs / "square.ngc")
    # --library folders come first (as given on the command line), then the machine file's
    other = tmp_path / "other"
    other.mkdir()
    (other / "square.ngc").write_text("o<square> sub\nG1 X1 F100\no<square> endsub\nM2\n")
    assert verify(_program("500"), machine, file="main.ngc", library=other).verdict.label == "safe"


@pytest.mark.parametrize("bad, code", [('subroutine_path = "subs"', "ZN103"), ("subroutine_path = [1]", "ZN103"),
                                       ('subroutine_pth = ["subs"]', "ZN101")])
def test_a_bad_subroutine_path_is_a_machine_file_error(tmp_path: Path, bad: str, code: str):
    from nczones.errors import MachineFileError

    (tmp_path / "m.toml").write_text(Path(MILL).read_text() + f"\n[linuxcnc]\n{bad}\n")
    with pytest.raises(MachineFileError) as err:
        load_machine(tmp_path / "m.toml")
    assert [d.code for d in err.value.errors] == [code]
    assert err.value.errors[0].span is not None and err.value.errors[0].span.line > 1


def test_import_machine_takes_subroutine_path_from_the_ini(tmp_path: Path):
    from nczones.imports import import_machine

    gold = Path("tests/golden/import/linuxcnc")
    cfg = tmp_path / "cfg"
    (cfg / "subs").mkdir(parents=True)
    (cfg / "subs" / "square.ngc").write_text(SQUARE)
    for name in ("mill_mm.tbl", "mill_mm.var"):
        (cfg / name).write_text((gold / name).read_text())
    # find_ngc_file (interp_o_word.cc): [DISPLAY] PROGRAM_PREFIX first, then SUBROUTINE_PATH in order
    ini = (gold / "mill_mm.ini").read_text().replace("[RS274NGC]\n", "[RS274NGC]\nSUBROUTINE_PATH = nothere:subs\n")
    ini = ini.replace("[DISPLAY]\n", "[DISPLAY]\nPROGRAM_PREFIX = progs/\n")
    (cfg / "mill.ini").write_text(ini)
    out = tmp_path / "out" / "mill.toml"
    out.parent.mkdir()
    result = import_machine(str(cfg / "mill.ini"), output=str(out))
    assert 'subroutine_path = ["../cfg/progs", "../cfg/nothere", "../cfg/subs"]' in result.text
    out.write_text(result.text)
    machine = load_machine(out)
    assert machine.subroutine_path == (str(cfg / "progs"), str(cfg / "nothere"), str(cfg / "subs"))
    program = "G21 G90 G54\nG0 X0 Y0 Z10\no<square> call [1000]\nM2\n"
    got = verify(program, machine, file="main.ngc")
    assert got.verdict.label == "unsafe" and got.violations[0].span.file == str(cfg / "subs" / "square.ngc")


def test_the_html_report_lists_the_subroutine_file_with_its_lines_marked(subs: Path):
    pytest.importorskip("matplotlib")
    from nczones.gcode.source import program_text
    from nczones.report.html import render_html

    machine = load_machine(MILL)
    program = _program("500")
    result = verify(program, machine, file="main.ngc", library=subs)
    page = render_html(result, machine, program_text(program, "main.ngc"), deterministic=True)
    sub_file = str(subs / "square.ngc")
    # the violations at square.ngc:2 and :3 link to that file's listing, not to main.ngc's lines 2 and 3
    assert f'<a href="#F1L2">{sub_file}:2:1</a>' in page and f'<a href="#F1L3">{sub_file}:3:1</a>' in page
    assert f"Called file <code>{sub_file}</code>" in page
    assert re.search(r'class="line hot" id="F1L2"[^>]*><a class="ln" href="#F1L2">2</a>G1 X#1 F100', page)
    assert 'id="L3"' in page and not re.search(r'class="line hot" id="L3"', page)  # main.ngc:3 is the call


def test_fleet_reads_the_machine_files_subroutine_path_and_reruns_when_a_sub_file_changes(tmp_path: Path):
    import sys

    sys.path.insert(0, str(Path("tests/fleet").resolve()))
    from fleet_helpers import check

    lib = tmp_path / "lib"
    (lib / "machines" / "subs").mkdir(parents=True)
    (lib / "programs").mkdir()
    (lib / "machines" / "mill.toml").write_text(Path(MILL).read_text() + '\n[linuxcnc]\nsubroutine_path = ["subs"]\n')
    (lib / "machines" / "subs" / "square.ngc").write_text(SQUARE)
    (lib / "programs" / "p.ngc").write_text(_program("10"))
    (lib / "nczones.toml").write_text('[project]\nname = "subs"\n\n[machines.mill]\nfile = "machines/mill.toml"\n'
                                      'programs = ["programs/*.ngc"]\n')
    first, cells = check(lib / "nczones.toml", tmp_path / "s.sqlite")
    assert [v[2] for v in cells.values()] == ["safe"]
    # the sub file now moves 500 mm (past the travel): the machine file and program are unchanged, the cell runs
    (lib / "machines" / "subs" / "square.ngc").write_text(SQUARE.replace("X#1", "X[#1 * 50]"))
    again, cells = check(lib / "nczones.toml", tmp_path / "s.sqlite")
    assert again.ran == 1 and [v[2] for v in cells.values()] == ["unsafe"]


def test_the_command_line_takes_library_repeated_or_as_a_path_list(tmp_path: Path, subs: Path, capsys):
    from nczones.cli import main

    (tmp_path / "main.ngc").write_text(_program("500"))
    empty = tmp_path / "empty"
    empty.mkdir()
    base = ["verify", str(tmp_path / "main.ngc"), "--machine", MILL]
    assert main(base + ["--library", str(empty), "--library", str(subs)]) == 1  # unsafe
    out = capsys.readouterr().out
    assert f"{subs / 'square.ngc'}:2:1: violation[travel]" in out
    assert main(base + ["--library", os.pathsep.join((str(empty), str(subs)))]) == 1
    capsys.readouterr()
    assert main(base + ["--library", str(empty)]) == 3  # unknown: GC393
    assert "GC393" in capsys.readouterr().out
    assert main(base + ["--library", str(tmp_path / "nothere")]) == 2
    # VF112, its own code: VF105 is --max-iterations (issue 34: one code, one meaning)
    assert "error[VF112]: --library" in capsys.readouterr().err


def test_the_result_notes_name_the_subroutine_files_read(subs: Path):
    result = verify(_program("10"), load_machine(MILL), file="main.ngc", library=subs)
    assert result.verdict.label == "safe"
    assert any(str(subs / "square.ngc") in n and "o<square>" in n for n in result.notes), result.notes
