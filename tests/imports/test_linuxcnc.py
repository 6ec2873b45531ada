"""LinuxCNC import: the INI reader's rules, exact unit conversion, the parameter file and tool table."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.cli import main
from nczones.errors import MachineImportError, Severity
from nczones.exact import format_decimal
from nczones.imports import detect_kind, import_machine
from nczones.imports.ini import parse_ini
from nczones.imports.model import Collector
from nczones.testing import decimals

F = Fraction


def _ini(tmp_path: Path, text: str, name: str = "m.ini") -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


BASE = "[TRAJ]\nCOORDINATES = X Y Z\nLINEAR_UNITS = mm\n"


def _codes(exc: MachineImportError) -> list[str]:
    return [d.code for d in exc.diagnostics]


# ---------------------------------------------------------------- the INI reader


def test_ini_rules_first_key_wins_and_values_keep_hashes():
    c = Collector()
    ini = parse_ini("m.ini", "; comment\n[A]\nK = 1 # not a comment\nK = 2\n  # indented comment\n[B]\nK = 3\n[A]\nL = 4\n", c)
    assert c.errors == []
    assert ini.get("A", "K").value == "1 # not a comment"
    assert ini.get("A", "L").value == "4"  # a section named twice is merged
    assert ini.get("B", "K").span.line == 7


def test_ini_continuation_and_include(tmp_path):
    (tmp_path / "inc").mkdir()
    (tmp_path / "inc" / "axes.inc").write_text("[AXIS_X]\nMIN_LIMIT = -1\n#INCLUDE more.inc\n")
    (tmp_path / "inc" / "more.inc").write_text("MAX_LIMIT = 2\n")
    c = Collector()
    text = "[TRAJ]\nCOORDINATES = X \\\n  Z\n#INCLUDE inc/axes.inc\n"
    ini = parse_ini(str(tmp_path / "m.ini"), text, c)
    assert c.errors == []
    assert ini.get("TRAJ", "COORDINATES").value == "X   Z"
    assert ini.get("AXIS_X", "MAX_LIMIT").span.file.endswith("more.inc")  # relative to the including file


def test_ini_include_loop_is_an_error(tmp_path):
    (tmp_path / "a.inc").write_text("#INCLUDE m.ini\n")
    p = _ini(tmp_path, BASE + "#INCLUDE a.inc\n")
    with pytest.raises(MachineImportError) as e:
        import_machine(p)
    assert _codes(e.value) == ["IM108"]


# ---------------------------------------------------------------- exact conversion


def test_inch_machine_converts_exactly_and_starts_in_g20(tmp_path):
    p = _ini(tmp_path, "[TRAJ]\nCOORDINATES = X Z\nLINEAR_UNITS = inch\n[AXIS_X]\nMIN_LIMIT = -0.0001\n"
             "MAX_LIMIT = 12.3456\nMAX_VELOCITY = 0.3\n[AXIS_Z]\nMAX_VELOCITY = 1\n")
    r = import_machine(p)
    assert r.machine.allowed.bounding_box()["X"] == (F("-0.00254"), F("313.57824"))
    assert r.machine.axis("X").rapid_mm_min == F("457.2")
    assert "G20" in r.machine.modal
    assert "Z" not in r.machine.allowed.bounding_box()  # no limits: unlimited, as in LinuxCNC


def test_grad_rotary_axis_converts_to_degrees(tmp_path):
    p = _ini(tmp_path, "[TRAJ]\nCOORDINATES = X A\nLINEAR_UNITS = mm\nANGULAR_UNITS = grad\n"
             "[AXIS_A]\nMIN_LIMIT = -100\nMAX_LIMIT = 400\nMAX_VELOCITY = 10\n")
    r = import_machine(p)
    assert r.machine.allowed.bounding_box()["A"] == (F(-90), F(360))
    assert r.machine.axis("A").rapid_mm_min == F(540)


def test_radians_without_rotary_axes_are_harmless(tmp_path):
    p = _ini(tmp_path, BASE.replace("mm\n", "mm\nANGULAR_UNITS = rad\n"))
    assert import_machine(p).machine.axis_names == ("X", "Y", "Z")


def test_huge_limit_means_no_limit_with_a_note(tmp_path):
    p = _ini(tmp_path, BASE + "[AXIS_X]\nMIN_LIMIT = -1e99\nMAX_LIMIT = 500\n")
    r = import_machine(p)
    assert r.machine.allowed.bounding_box()["X"] == (None, F(500))
    assert any(n.code == "IM203" and "no limit" in n.message for n in r.notes)
    assert all(n.severity is Severity.NOTE for n in r.notes)


def test_joint_limit_tighter_than_axis_is_taken(tmp_path):
    p = _ini(tmp_path, BASE + "[AXIS_X]\nMIN_LIMIT = -10\nMAX_LIMIT = 10\n[JOINT_0]\nMIN_LIMIT = -10\nMAX_LIMIT = 8\n")
    r = import_machine(p)
    assert r.machine.allowed.bounding_box()["X"] == (F(-10), F(8))


def test_gantry_joints_both_limit_their_axis(tmp_path):
    p = _ini(tmp_path, "[KINS]\nKINEMATICS = trivkins coordinates=xyyz\n[TRAJ]\nCOORDINATES = X Y Y Z\n"
             "LINEAR_UNITS = mm\n[AXIS_Y]\nMIN_LIMIT = 0\nMAX_LIMIT = 100\n[JOINT_1]\nMAX_LIMIT = 100\n"
             "[JOINT_2]\nMAX_LIMIT = 99.5\n")
    r = import_machine(p)
    assert r.machine.axis_names == ("X", "Y", "Z")
    assert r.machine.allowed.bounding_box()["Y"] == (F(0), F("99.5"))


def test_rapid_is_the_slowest_of_axis_joint_and_trajectory_limits(tmp_path):
    p = _ini(tmp_path, BASE.replace("mm\n", "mm\nMAX_LINEAR_VELOCITY = 50\n")
             + "[AXIS_X]\nMAX_VELOCITY = 80\n[JOINT_0]\nMAX_VELOCITY = 60\n"
             "[AXIS_Y]\nMAX_VELOCITY = 30\n[JOINT_1]\nMAX_VELOCITY = 40\n")
    m = import_machine(p).machine
    assert (m.axis("X").rapid_mm_min, m.axis("Y").rapid_mm_min) == (F(3000), F(1800))
    assert m.axis("Z").rapid_mm_min == F(60)  # no MAX_VELOCITY: LinuxCNC's 1 unit/s


# ---------------------------------------------------------------- parameter file and tool table


def test_var_offsets_g28_and_active_offset(tmp_path):
    (tmp_path / "m.var").write_text("5161 1.5\n5162 2\n5163 -3\n5220 3.000000\n5221 10\n5281 7.25\n5283 -1\n")
    p = _ini(tmp_path, BASE + "[RS274NGC]\nPARAMETER_FILE = m.var\n[JOINT_0]\nHOME = 4\n")
    m = import_machine(p).machine
    assert m.reference == (F("1.5"), F(2), F(-3))
    assert m.start == (F(4), F(0), F(0))  # where homing leaves the machine
    assert m.offsets["G54"] == (F(10), F(0), F(0))
    assert m.offsets["G57"] == (F("7.25"), F(0), F(-1))
    assert "G56" in m.modal


def test_startup_code_overrides_the_stored_offset(tmp_path):
    (tmp_path / "m.var").write_text("5220 2\n")
    p = _ini(tmp_path, BASE + "[RS274NGC]\nPARAMETER_FILE = m.var\nRS274NGC_STARTUP_CODE = G0054 G91 G64\n")
    r = import_machine(p)
    assert "G54" in r.machine.modal and "G91" in r.machine.modal
    # G64 (no P) is taken as the start-up path mode since issue 35 (specs/path-modes.md)
    assert r.machine.path_mode == "G64" and r.machine.path_tolerance is None
    assert not any("G64 not taken" in n.message for n in r.notes)


def test_parameter_file_option_overrides_the_ini(tmp_path):
    (tmp_path / "other.var").write_text("5221 42\n")
    p = _ini(tmp_path, BASE + "[RS274NGC]\nPARAMETER_FILE = missing.var\n")
    r = import_machine(p, parameter_file=str(tmp_path / "other.var"))
    assert r.machine.offsets["G54"][0] == 42
    assert not any("missing.var" in n.message for n in r.notes)


def test_tool_table_lengths_and_diameters_exact(tmp_path):
    (tmp_path / "t.tbl").write_text("T1 P1 Z0.511 D0.125 ;1/8\n\n; comment\nT2 P2 Z-1e-3\n")
    p = _ini(tmp_path, BASE.replace("= mm", "= inch") + "[EMCIO]\nTOOL_TABLE = t.tbl\n")
    m = import_machine(p).machine
    assert m.tool_lengths == {1: F("12.9794"), 2: F("-0.0254")}
    assert m.tool_diameters == {1: F("3.175"), 2: F(0)}


def test_inch_var_offsets_convert(tmp_path):
    (tmp_path / "m.var").write_text("5221 1.000000\n")
    p = _ini(tmp_path, BASE.replace("= mm", "= inch") + "[RS274NGC]\nPARAMETER_FILE = m.var\n")
    assert import_machine(p).machine.offsets["G54"][0] == F("25.4")


# ---------------------------------------------------------------- property: limits in, exact box out


@settings(max_examples=40, deadline=None)
@given(
    inch=st.booleans(),
    bounds=st.lists(st.tuples(decimals(min_value=-3000, max_value=0, places=4),
                              decimals(min_value=0, max_value=3000, places=4)), min_size=3, max_size=3),
)
def test_soft_limits_become_the_exact_box(tmp_path_factory, inch, bounds):
    tmp = tmp_path_factory.mktemp("ini")
    unit = F(254, 10) if inch else F(1)
    text = f"[TRAJ]\nCOORDINATES = X Y Z\nLINEAR_UNITS = {'inch' if inch else 'mm'}\n"
    for a, (lo, hi) in zip("XYZ", bounds):
        text += f"[AXIS_{a}]\nMIN_LIMIT = {format_decimal(lo)}\nMAX_LIMIT = {format_decimal(hi)}\n"
    (tmp / "m.ini").write_text(text)
    m = import_machine(tmp / "m.ini").machine
    box = m.allowed.bounding_box()
    for a, (lo, hi) in zip("XYZ", bounds):
        assert box[a] == (lo * unit, hi * unit)
        # membership on both sides of each bound, exactly
        inside = {b: (box[b][0] + box[b][1]) / 2 for b in "XYZ"}
        assert m.allowed.contains({**inside, a: lo * unit}) and m.allowed.contains({**inside, a: hi * unit})
        assert not m.allowed.contains({**inside, a: hi * unit + F(1, 10**6)})


# ---------------------------------------------------------------- detection and unreadable input


def test_detection():
    assert detect_kind("# c\n[EMC]\nMACHINE = m\n") == "linuxcnc"
    with pytest.raises(MachineImportError) as e:
        detect_kind("G0 X1\nG1 Y2\n", "p.ngc")
    assert _codes(e.value) == ["IM101"] and "--kind" in e.value.diagnostics[0].message


@pytest.mark.parametrize("setup,code,text", [
    (lambda d: d / "missing.ini", "IM100", "No such file"),
    (lambda d: d, "IM100", "directory"),
    (lambda d: (d / "b.ini").write_bytes(b"[TRAJ]\x00\x01") and d / "b.ini", "IM100", "NUL"),
    (lambda d: (d / "l.ini").write_bytes(b"[TRAJ]\nMACHINE = \xe9\n") and d / "l.ini", "IM100", "UTF-8"),
    (lambda d: (d / "p.ngc").write_text("G0 X1\n") and d / "p.ngc", "IM101", "cannot tell"),
])
def test_cli_unreadable_sources(tmp_path, capsys, setup, code, text):
    target = setup(tmp_path)
    assert main(["import-machine", str(target)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and f"error[{code}]" in err and text in err and "Traceback" not in err


def test_cli_output_file_and_unwritable_output(tmp_path, capsys):
    p = _ini(tmp_path, BASE + "[AXIS_X]\nMIN_LIMIT = 0\nMAX_LIMIT = 10\n")
    assert main(["import-machine", str(p), "-o", str(tmp_path / "m.toml")]) == 0
    out, err = capsys.readouterr()
    assert err == "" and out.startswith(f"{p}: LinuxCNC INI configuration imported") and "-> " in out
    assert (tmp_path / "m.toml").read_text().startswith("# Machine file imported from")
    assert main(["import-machine", str(p), "-o", str(tmp_path / "no" / "such" / "dir.toml")]) == 2
    out, err = capsys.readouterr()
    assert "cannot write" in err and "Traceback" not in err


def test_kind_given_wrong_is_a_clear_error(tmp_path, capsys):
    p = _ini(tmp_path, "$100=250.000\n$130=200.000\n", "dump.txt")
    assert main(["import-machine", str(p), "--kind", "linuxcnc"]) == 2
    err = capsys.readouterr().err
    assert "error[IM1" in err and "Traceback" not in err


@pytest.mark.parametrize("name", ["Mill\x7f", "Mill\x01\x1f X", 'Shop "A" \\ back\tslash', "Fräse Ø"])
def test_machine_names_with_control_characters_round_trip(tmp_path, name):
    # issue 38: the writer quoted with json.dumps, which leaves DEL (0x7f) raw; TOML forbids it in a string and in a
    # comment, so the import failed with IM110 blamed on the configuration. The name read back must be the
    # name written in [EMC] MACHINE (LinuxCNC's INI reader keeps the value after "= " as it is, trailing blanks cut).
    p = tmp_path / "m.ini"
    p.write_bytes(("[EMC]\nMACHINE = " + name + "\n" + BASE).encode("utf-8"))
    r = import_machine(p)
    assert r.machine.name == name
    from nczones.machine import parse_machine

    assert parse_machine(r.text).name == name


def test_tool_table_lines_linuxcnc_skips_are_notes_and_the_rest_is_read(tmp_path):
    # LinuxCNC's tooldata_read_entry (src/emc/tooldata/tooldata_common.cc): a word with an unknown letter, or
    # whose number sscanf cannot read, makes the line invalid; tooldata_load prints "Unrecognized line
    # skipped" and reads on.  A line without T is stored as tool -1 (no tool).  So the table below gives
    # LinuxCNC exactly T2 (Z80 mm) and T5 (Z7 mm), and the import the same, with notes.
    (tmp_path / "t.tbl").write_text("TOOLNO POCKET LENGTH\n  1  1  +0.5\nT2 P2 Z80 D10\nP3 Z5\n"
                                    "T4 P4 Zabc\nt5 p5 z7 ; lower case is read (toupper)\n")
    p = _ini(tmp_path, BASE + "[EMCIO]\nTOOL_TABLE = t.tbl\n")
    r = import_machine(p)
    assert r.machine.tool_lengths == {2: F(80), 5: F(7)}
    skipped = [n for n in r.notes if n.code == "IM204"]
    assert [n.span.line for n in skipped] == [1, 2, 4, 5]
    assert all(n.severity is Severity.NOTE for n in skipped)


def test_a_number_sscanf_reads_only_in_part_is_still_an_error(tmp_path):
    # "Z1,5": sscanf("%lf") reads 1 and LinuxCNC takes Z1; the import refuses to guess between 1 and 1.5
    (tmp_path / "t.tbl").write_text("T1 P1 Z1,5\n")
    p = _ini(tmp_path, BASE + "[EMCIO]\nTOOL_TABLE = t.tbl\n")
    with pytest.raises(MachineImportError) as e:
        import_machine(p)
    assert _codes(e.value) == ["IM102"]
    assert "reads only the number at its start" in e.value.diagnostics[0].message


def test_a_symlinked_tool_table_is_followed_and_a_stored_link_is_named(tmp_path):
    (tmp_path / "real").mkdir()
    (tmp_path / "real" / "shop.tbl").write_text("T3 P3 Z42\n")
    (tmp_path / "linked.tbl").symlink_to(tmp_path / "real" / "shop.tbl")
    p = _ini(tmp_path, BASE + "[EMCIO]\nTOOL_TABLE = linked.tbl\n")
    assert import_machine(p).machine.tool_lengths == {3: F(42)}
    # the same link written as a plain file holding its target (a checkout without symlinks): LinuxCNC skips
    # that one line, so no tools; the note says what the file is and how to get the table read
    (tmp_path / "linked.tbl").unlink()
    (tmp_path / "linked.tbl").write_text("real/shop.tbl")
    r = import_machine(p)
    assert r.machine.tool_lengths == {}
    (note,) = [n for n in r.notes if n.code == "IM204"]
    assert "symbolic link stored as a file" in note.message and "--tool-table" in note.message
