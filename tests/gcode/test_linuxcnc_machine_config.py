"""LinuxCNC meaning that depends on the machine's configuration (issue: `safe` must mean what the control does).

* Class 15 — M6 moves the machine on a LinuxCNC configured with ``[EMCIO] TOOL_CHANGE_QUILL_UP``,
  ``TOOL_CHANGE_AT_G30`` or ``TOOL_CHANGE_POSITION`` (``[machine] tool_change_quill_up`` / ``tool_change_at_g30``
  / ``[machine.tool_change_position]``).
* Class 16 — on an inch LinuxCNC (``[machine] control_units = "inch"``) the numbered state parameters are in
  inches whatever G20/G21 is active.

Expected motion is LinuxCNC's: ``rs274 -i <ini> -g`` (LinuxCNC 2.9.0~pre1, installed) printed the traverses
recorded below; where ``rs274`` is installed the live test re-runs it on the same INI, tool table and parameter
file and checks the recording.  The move to ``TOOL_CHANGE_POSITION`` is made by the task, not the interpreter
(``src/emc/task/emccanon.cc`` ``CHANGE_TOOL``), so ``rs274`` never prints it: its expected end is derived from
that source in the test.

The standalone interpreter's parameter file and tool table are in inches (its external length unit): the
G28/G30 positions ``#5161 = #5181 = 1``, ``#5162 = #5182 = 2``, ``#5163 = #5183 = -0.5`` are X25.4 Y50.8
Z-12.7 mm, the machine file's reference position.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest

from nczones.errors import MachineFileError, MachineImportError
from nczones.gcode import interpret_text
from nczones.imports import import_machine
from nczones.machine import parse_machine
from nczones.prover import verify_text

F = Fraction
RS274 = shutil.which("rs274")

AXES_TEXT = '''
[machine]
axes = ["X", "Y", "Z"]
{extra}
[machine.rapid]
X = "10000"
Y = "10000"
Z = "10000"
[machine.reference]
X = "25.4"
Y = "50.8"
Z = "-12.7"
[machine.start]
X = "0"
Y = "0"
Z = "0"
[tool_lengths]
H1 = "12.7"
[tool_diameters]
T1 = "10"
{zones}
'''

VAR = "5161 1\n5162 2\n5163 -0.5\n5181 1\n5182 2\n5183 -0.5\n"
TBL = "T1 P1 Z0.5 D0.393700787 ;\n"
INI = """[EMC]
VERSION = 1.1
[RS274NGC]
PARAMETER_FILE = m.var
[TRAJ]
LINEAR_UNITS = inch
ANGULAR_UNITS = degree
COORDINATES = X Y Z
[EMCIO]
TOOL_TABLE = m.tbl
{emcio}
"""


def machine(extra: str = "", zones: str = ""):
    return parse_machine(AXES_TEXT.format(extra=extra, zones=zones))


def _own_home(tmp: Path) -> dict[str, str]:
    """rs274's environment with ``tmp`` as HOME: it keeps its tool table in ``$HOME/.tool.mmap``, shared by every
    rs274 of the user, so a parallel test's table could replace this run's (tests/tools/rs274_diff.py)."""
    return {**os.environ, "HOME": str(tmp)}


def rs274_traverses(program: str, emcio: str, tmp: Path) -> list[str]:
    """The STRAIGHT_TRAVERSE lines ``rs274 -i`` prints (X Y Z of program coordinates, mm) and the G5x offset."""
    (tmp / "m.ini").write_text(INI.format(emcio=emcio))
    (tmp / "m.var").write_text(VAR)  # rs274 writes the file back at the end: a fresh copy per run
    (tmp / "m.tbl").write_text(TBL)
    (tmp / "p.ngc").write_text(program)
    p = subprocess.run([RS274, "-i", "m.ini", "-t", "m.tbl", "-v", "m.var", "-g", "p.ngc"], cwd=tmp,
                       capture_output=True, text=True, timeout=30, stdin=subprocess.DEVNULL, env=_own_home(tmp))
    out = []
    for line in p.stdout.splitlines():
        for call in ("STRAIGHT_TRAVERSE(", "SET_G5X_OFFSET(1, "):
            if call in line:
                args = line.split(call, 1)[1].rstrip(")").split(", ")
                out.append(call[:-1].split("(")[0] + " " + " ".join(args[:3]))
        if "CHANGE_TOOL(" in line:  # its argument is a pocket of the standalone's shared tool data: left out
            out.append("CHANGE_TOOL")
    return out


def ends(text: str, m) -> list[tuple[str, tuple[Fraction, ...]]]:
    return [(s.kind.name, tuple(s.end)) for s in interpret_text(text, m).segments()]


# ------------------------------------------------------------------------------------------ class 15: M6 moves

M6_PROGRAM = "G21 G10 L2 P1 X10 Y5 Z-20\nG0 X1 Y2 Z-3\nT1 M6\nG0 X0\nM2\n"
M6_EMCIO = "TOOL_CHANGE_QUILL_UP = 1\nTOOL_CHANGE_AT_G30 = 1\n"
#: rs274 -i (TOOL_CHANGE_QUILL_UP, TOOL_CHANGE_AT_G30) on M6_PROGRAM, program coordinates in mm, G54 = X10 Y5 Z-20:
#: the quill goes up to program Z20 (machine 0: 20 - 20), then every axis to the G30 position (X25.4 Y50.8
#: Z-12.7 machine = program 15.4 45.8 7.3), before CHANGE_TOOL.
M6_RS274 = [
    "SET_G5X_OFFSET 0.0000 0.0000 0.0000",
    "SET_G5X_OFFSET 10.0000 5.0000 -20.0000",
    "STRAIGHT_TRAVERSE 1.0000 2.0000 -3.0000",
    "STRAIGHT_TRAVERSE 1.0000 2.0000 20.0000",
    "STRAIGHT_TRAVERSE 15.4000 45.8000 7.3000",
    "CHANGE_TOOL",
    "STRAIGHT_TRAVERSE 0.0000 45.8000 7.3000",
    "SET_G5X_OFFSET 10.0000 5.0000 -20.0000",
]
#: The same in machine coordinates (program + G54).
M6_MACHINE = [(F(11), F(7), F(-23)), (F(11), F(7), F(0)), (F("25.4"), F("50.8"), F("-12.7")),
              (F(10), F("50.8"), F("-12.7"))]


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
def test_recorded_m6_moves_are_what_rs274_prints(tmp_path):
    assert rs274_traverses(M6_PROGRAM, M6_EMCIO, tmp_path) == M6_RS274
    # without the keys M6 prints no move
    assert [t for t in rs274_traverses(M6_PROGRAM, "", tmp_path) if t.startswith("STRAIGHT")] == [
        "STRAIGHT_TRAVERSE 1.0000 2.0000 -3.0000", "STRAIGHT_TRAVERSE 0.0000 2.0000 -3.0000"]


def test_quill_up_and_g30_moves_are_rapids_in_machine_coordinates():
    m = machine("tool_change_quill_up = true\ntool_change_at_g30 = true")
    got = ends(M6_PROGRAM, m)
    assert got == [("RAPID", e) for e in M6_MACHINE]
    # each alone
    q = ends(M6_PROGRAM, machine("tool_change_quill_up = true"))
    assert [e for _, e in q] == [M6_MACHINE[0], M6_MACHINE[1], (F(10), F(7), F(0))]
    g = ends(M6_PROGRAM, machine("tool_change_at_g30 = true"))
    assert [e for _, e in g] == [M6_MACHINE[0], M6_MACHINE[2], M6_MACHINE[3]]
    # a machine without the keys: M6 does not move (LinuxCNC's default)
    assert [e for _, e in ends(M6_PROGRAM, machine())] == [M6_MACHINE[0], (F(10), F(7), F(-23))]


def test_g30_1_moves_the_tool_change_too():
    """TOOL_CHANGE_AT_G30 goes to the G30 position as it stands (#5181..), which G30.1 stores."""
    m = machine("tool_change_at_g30 = true")
    got = ends("G0 X5 Y6 Z-7\nG30.1\nG0 X0 Y0 Z0\nT1 M6\nM2\n", m)
    assert got[-1] == ("RAPID", (F(5), F(6), F(-7)))


def test_tool_change_position_is_a_straight_move_in_machine_coordinates():
    """emccanon.cc CHANGE_TOOL: with TOOL_CHANGE_POSITION = x y z the task moves X Y Z (3 numbers: A B C U V W
    stay) to that machine position on a straight line, after the interpreter's moves; the interpreter re-reads
    the position after the change (toolchange_flag), so G0 X0 then starts there: machine X = 0 + G54 10."""
    m = machine('tool_change_quill_up = true\ntool_change_position = { X = "100", Y = "-20", Z = "-5" }')
    got = ends(M6_PROGRAM, m)
    assert got == [("RAPID", M6_MACHINE[0]), ("RAPID", M6_MACHINE[1]), ("RAPID", (F(100), F(-20), F(-5))),
                   ("RAPID", (F(10), F(-20), F(-5)))]
    # only the axes given move
    got = ends(M6_PROGRAM, machine('tool_change_position = { Z = "-1" }'))
    assert got[1] == ("RAPID", (F(11), F(7), F(-1)))


# a column the quill-up rapid at X11 Y7 crosses (Z -10..-5); the G0 moves of the program pass beside it
COLUMN = '''
[[zones]]
name = "column"
kind = "box"
forbid = true
min = { X = "10.5", Y = "6.5", Z = "-10" }
max = { X = "11.5", Y = "7.5", Z = "-5" }
'''
# a fixture only the move to TOOL_CHANGE_POSITION X100 Y-20 Z-5 crosses
FIXTURE = '''
[[zones]]
name = "fixture"
kind = "box"
forbid = true
min = { X = "50", Y = "-15", Z = "-20" }
max = { X = "60", Y = "-5", Z = "0" }
'''


def _programs() -> dict[str, str]:
    many = "".join(f"G1 F1000 X{2 - (k % 2)} Y2 Z-3\n" for k in range(600))  # > 512 motions: the vectorized tier
    return {
        "short": M6_PROGRAM,
        "many": "G21 G10 L2 P1 X10 Y5 Z-20\nG0 X1 Y2 Z-3\n" + many + "T1 M6\nG0 X0\nM2\n",
        "hash": "G21 G10 L2 P1 X10 Y5 Z-20\n#1 = 2\n#<t> = 1\nG0 X1 Y#1 Z-3\nT#<t> M6\nG0 X0\nM2\n",
    }


@pytest.mark.parametrize("name", sorted(_programs()))
def test_verify_finds_the_tool_change_moves(name):
    text = _programs()[name]
    plain = verify_text(text, machine(zones=COLUMN + FIXTURE))
    assert plain.verdict.label == "safe"  # M6 motionless: nothing enters the column
    quill = verify_text(text, machine("tool_change_quill_up = true", COLUMN + FIXTURE))
    assert quill.verdict.label == "unsafe"
    assert {v.zone for v in quill.violations} == {"column"}
    assert all(v.line == text.splitlines().index(next(ln for ln in text.splitlines() if "M6" in ln)) + 1
               for v in quill.violations)
    pos = verify_text(text, machine('tool_change_position = { X = "100", Y = "-20", Z = "-5" }', COLUMN + FIXTURE))
    assert pos.verdict.label == "unsafe" and {v.zone for v in pos.violations} == {"fixture"}


def test_machine_file_keys_are_checked():
    with pytest.raises(MachineFileError) as e:
        machine('tool_change_quill_up = "yes"')
    assert e.value.diagnostics[0].code == "ZN103"
    with pytest.raises(MachineFileError) as e:
        machine('tool_change_position = { Q = "1" }')
    assert e.value.diagnostics[0].code == "ZN110"
    with pytest.raises(MachineFileError) as e:
        machine('control_units = "furlong"')
    assert e.value.diagnostics[0].code == "ZN114"
    m = parse_machine(AXES_TEXT.format(extra='dialect = "fanuc"\ntool_change_quill_up = true', zones=""))
    assert [w.code for w in m.warnings] == ["ZN115"]


# ------------------------------------------------------------------------------------------ import


def _ini(tmp_path: Path, emcio: str, var: str = VAR, units: str = "inch") -> Path:
    (tmp_path / "m.var").write_text(var)
    (tmp_path / "m.tbl").write_text(TBL)
    p = tmp_path / "m.ini"
    p.write_text(INI.format(emcio=emcio).replace("= inch", f"= {units}"))
    return p


def test_import_takes_the_tool_change_keys(tmp_path):
    p = _ini(tmp_path, "TOOL_CHANGE_QUILL_UP = 1\nTOOL_CHANGE_AT_G30 = YES\nTOOL_CHANGE_POSITION = 1 2.5 -0.25\n")
    r = import_machine(p)
    m = r.machine
    assert m.tool_change_quill_up and m.tool_change_at_g30
    # inches, x 25.4: X25.4 Y63.5 Z-6.35
    assert dict(m.tool_change_position) == {"X": F("25.4"), "Y": F("63.5"), "Z": F("-6.35")}
    assert m.control_units == "inch"
    assert "tool_change_quill_up = true" in r.text and "[machine.tool_change_position]" in r.text
    # the written file reads back to the same machine
    again = parse_machine(r.text)
    assert again.tool_change_position == m.tool_change_position and again.tool_change_at_g30


def test_import_tool_change_position_counts_as_linuxcnc_does(tmp_path):
    """taskclass.cc readToolChange: 9 numbers, else 6, else 3 (X Y Z); A B C of 6 are degrees."""
    p = _ini(tmp_path, "TOOL_CHANGE_POSITION = 1 2 3 4 5\n", units="mm")
    assert dict(import_machine(p).machine.tool_change_position) == {"X": 1, "Y": 2, "Z": 3}
    with pytest.raises(MachineImportError) as e:
        import_machine(_ini(tmp_path, "TOOL_CHANGE_POSITION = 1 2\n", units="mm"))
    assert [d.code for d in e.value.diagnostics] == ["IM105"]
    assert import_machine(_ini(tmp_path, "", units="mm")).machine.control_units == "mm"


def test_import_refuses_at_g30_when_g30_is_not_the_reference(tmp_path):
    """The machine file has one reference position (G28 and G30); a tool change at a G30 position that
    differs from it would be proved in the wrong place."""
    p = _ini(tmp_path, "TOOL_CHANGE_AT_G30 = 1\n", var=VAR.replace("5183 -0.5", "5183 0"))
    with pytest.raises(MachineImportError) as e:
        import_machine(p)
    assert [d.code for d in e.value.diagnostics] == ["IM111"]


# ------------------------------------------------------------------------------------------ class 16: inch units

UNITS_PROGRAM = ("G21\nG10 L2 P1 X25.4\nG53 G0 X[#5221]\nG10 L1 P1 Z12.7 R5\nT1 M6\nG43\nG53 G0 Z[#5403] X[#5410]\n"
                 "G20 G0 X[#5221]\nG92 X0\nG21 G53 G0 Y[#5211 * 10]\nM2\n")
#: rs274 -i (LINEAR_UNITS = inch) on UNITS_PROGRAM, program coordinates in the current units: #5221 = 1 (25.4 mm
#: in inches), so G53 X[#5221] is machine X1 mm (program -24.4 with G54 X25.4); #5403 = 0.5 (tool 1's 12.7 mm)
#: and #5410 = 0.3937 (its 10 mm diameter) put the spindle at machine Z0.5 (program -12.2 with the 12.7 mm tool)
#: X0.3937 (program -25.0063); in G20, X[#5221] is X1 inch (machine 2 inches = 50.8 mm with G54); G92 X0 there
#: stores #5211 = 1 (inch), and G21 G53 Y[#5211 * 10] is machine Y10 mm.
UNITS_RS274 = [
    "SET_G5X_OFFSET 0.0000 0.0000 0.0000",
    "SET_G5X_OFFSET 25.4000 0.0000 0.0000",
    "STRAIGHT_TRAVERSE -24.4000 0.0000 0.0000",
    "CHANGE_TOOL",
    "STRAIGHT_TRAVERSE -25.0063 0.0000 -12.2000",
    "STRAIGHT_TRAVERSE 1.0000 0.0000 -0.4803",
    "STRAIGHT_TRAVERSE 0.0000 10.0000 -12.2000",
    "SET_G5X_OFFSET 25.4000 0.0000 0.0000",
]


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
def test_recorded_inch_parameters_are_what_rs274_prints(tmp_path):
    for _ in range(3):  # a parallel rs274 can replace the standalone's shared tool data (see _rs274_outcome)
        got = rs274_traverses(UNITS_PROGRAM, "", tmp_path)
        if got == UNITS_RS274:
            break
    assert got == UNITS_RS274


def test_inch_control_reads_numbered_parameters_in_inches():
    m = machine('control_units = "inch"')
    got = [e for _, e in ends(UNITS_PROGRAM, m)]
    # program + G54 (+ tool 12.7 on Z): the rs274 lines above in machine mm
    assert got[0] == (F(1), F(0), F(0))
    assert got[1][2] == F("0.5") and abs(got[1][0] - F("0.3937")) < F(1, 10000)
    assert got[2][0] == F("50.8")
    assert got[3][1] == F(10)  # G53 Y[#5211 * 10]: #5211 = 1 (inch)
    # an mm control reads the same parameters in mm (LinuxCNC with LINEAR_UNITS = mm)
    mm = [e for _, e in ends(UNITS_PROGRAM, machine())]
    assert mm[0] == (F("25.4"), F(0), F(0)) and mm[1][2] == F("12.7") and mm[2][0] == F("25.4") * F("26.4")


CLAMP = '''
[[zones]]
name = "clamp"
kind = "box"
forbid = true
min = { X = "5", Y = "4", Z = "-1" }
max = { X = "15", Y = "6", Z = "1" }
'''


@pytest.mark.parametrize("lane", ["short", "many"])
def test_verify_on_an_inch_control_is_not_25_4_times_larger(lane):
    """G53 G0 X[#5221 * 10] from X300 ends at machine X10 on an inch LinuxCNC (#5221 = 1): inside the clamp;
    read in mm (X254) it would stay clear of it."""
    many = "".join(f"G53 G1 F1000 X{300 + (k % 2)}\n" for k in range(600)) if lane == "many" else ""
    text = f"G21\nG10 L2 P1 X25.4\nG53 G0 X300\n{many}G53 G0 Y5\nG53 G0 X[#5221 * 10]\nM2\n"
    assert verify_text(text, machine('control_units = "inch"', CLAMP)).verdict.label == "unsafe"
    assert verify_text(text, machine("", CLAMP)).verdict.label == "safe"


# ------------------------------------------------------------------------------------------ class 17: reads under comp

COMP_MACHINE = 'cutter_compensation = "linuxcnc"'
COMP_PROGRAM = """G21 G17 G90
G10 L2 P1 X100 Y50
G10 L1 P1 R1.27
T1 M6
G0 X0 Y-5
G41 D1
G1 F100 X10 Y0
G0 Z[#<_x>]
G0 Z[#<_y>]
G1 X10 Y10
G0 Z[#<_abs_x>]
G0 Z[#<_abs_y>]
G3 X0 Y10 I-5 J0
G0 Z[#<_x>]
G0 Z[#<_y>]
G2 X-10 Y10 I-5 J0
G0 Z[#<_x>]
G0 Z[#<_y>]
G40
G1 X-15 Y10
G0 Z[#<_x>]
M2
"""
#: rs274 -i on COMP_PROGRAM (G54 X100 Y50; the tool radius is G10 L1 P1 R1.27, which LinuxCNC's comp reads in
#: place of the machine file's 10 mm diameter): each read moves Z to the value read.  While compensation is on,
#: LinuxCNC's current point (#<_x>, #<_abs_x>: interp_namedparams.cc reads settings->current_x) is the
#: compensated end of the last move *before* the next corner adjusts it: after the entry move to X10 Y0 (from
#: X0 Y-5, tool on the left) the end offset 1.27 perpendicular to the entry direction, X9.4320 Y1.1359; after
#: X10 Y10, X8.73 Y10 (abs X108.73 Y60; the concave corner with the arc then pulls the printed move back to
#: Y8.73, the reading stays); after the G3 arc (centre X5 Y10, tool inside) X1.27; after the G2 arc X-11.27;
#: after G40 the programmed point X-15.
COMP_RS274_Z = ["9.4320", "1.1359", "108.7300", "60.0000", "1.2700", "10.0000", "-11.2700", "10.0000", "-15.0000"]


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
def test_recorded_reads_under_comp_are_what_rs274_prints(tmp_path):
    for _ in range(3):  # a parallel rs274 can replace the standalone's shared tool data (see _rs274_outcome)
        got = rs274_traverses(COMP_PROGRAM, "", tmp_path)
        z_reads = [t.split()[3] for t in got if t.startswith("STRAIGHT_TRAVERSE")][1:]  # after the G0 X0 Y-5
        if z_reads == COMP_RS274_Z:
            break
    assert z_reads == COMP_RS274_Z


def test_reads_under_comp_are_the_compensated_point():
    m = machine(COMP_MACHINE)
    zs = [e[2] for k, e in ends(COMP_PROGRAM, m) if k == "RAPID"][1:]
    assert [f"{float(z):.4f}" for z in zs] == COMP_RS274_Z


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
def test_rs274_refuses_5420_under_comp(tmp_path):
    (tmp_path / "m.ini").write_text(INI.format(emcio=""))
    (tmp_path / "m.var").write_text(VAR)
    (tmp_path / "m.tbl").write_text(TBL)
    text = COMP_PROGRAM.replace("G0 Z[#<_x>]\nG0 Z[#<_y>]\nG1 X10 Y10", "G0 Z[#5420]\nG1 X10 Y10")
    (tmp_path / "p.ngc").write_text(text)
    p = subprocess.run([RS274, "-i", "m.ini", "-t", "m.tbl", "-v", "m.var", "-g", "p.ngc"], cwd=tmp_path,
                       capture_output=True, text=True, timeout=30, stdin=subprocess.DEVNULL, env=_own_home(tmp_path))
    assert "Cannot read current position with cutter radius compensation on" in p.stdout + p.stderr


def test_5420_under_comp_is_linuxcnc_s_error():
    """interp_read.cc read_parameter: #5420-#5428 with cutter_comp_side on is an error (recorded above)."""
    from nczones.errors import GcodeError

    text = COMP_PROGRAM.replace("G0 Z[#<_x>]\nG0 Z[#<_y>]\nG1 X10 Y10", "G0 Z[#5420]\nG1 X10 Y10")
    with pytest.raises(GcodeError) as e:
        ends(text, machine(COMP_MACHINE))
    assert e.value.diagnostics[0].code == "GC325" and e.value.diagnostics[0].span.line == 8
    # a read of #<_x> with G41 modal but cutter_compensation = "none" is never the programmed point
    r = verify_text("G0 X0 Y-5\nG41 D1\nG1 F100 X10 Y0\nG0 Z[#<_x>]\nM2\n", machine())
    assert r.verdict.label == "unknown"


SLAB = '''
[[zones]]
name = "slab"
kind = "box"
forbid = true
min = { X = "109.2", Y = "79", Z = "-1" }
max = { X = "109.6", Y = "81", Z = "1" }
'''


@pytest.mark.parametrize("lane", ["short", "many"])
def test_verify_uses_the_compensated_reading(lane):
    """#1 = #<_x> after the entry move reads X9.432 (program), not the programmed X10: the rapid to X[#1] at Y30
    ends at machine X109.432, inside the slab (X109.2-109.6); read as X10 it would stop at 110, clear of it."""
    many = "".join(f"G1 F1000 X{-(k % 2)} Y-5\n" for k in range(600)) if lane == "many" else ""
    text = ("G21 G17 G90\nG10 L2 P1 X100 Y50\nG10 L1 P1 R1.27\nT1 M6\nG0 X0 Y-5\n" + many
            + "G41 D1\nG1 F100 X10 Y0\n#1 = #<_x>\nG1 X10 Y10\nG40\nG0 X20 Y10\nG0 Y30\nG0 X[#1]\nM2\n")
    r = verify_text(text, machine(COMP_MACHINE, SLAB))
    assert r.verdict.label == "unsafe" and {v.zone for v in r.violations} == {"slab"}


# a concave corner after an arc whose sweep grows a little when its end is pulled back: LinuxCNC allows
# .0254 (G21) or .001 (G20) of growth before "Arc move in concave corner cannot be reached by the tool without
# gouging" (interp_queue.cc move_endpoint_and_flush); nczones allowed .001 in both and refused this program
GROW_PROGRAM = """G21 G17 G90 F100
G10 L1 P1 R1.27
T1 M6
G0 X0 Y-10 Z0
G42 D1
G1 X-10 Y-10
G3 X-20 Y-20 R10.1
G1 X-10 Y-20
G1 X-10 Y-10
G3 X0 Y-10 R5.5
G40
G1 X20 Y10
M2
"""
#: rs274 -g on GROW_PROGRAM (its motion lines).
GROW_RS274 = """    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
   14 N..... STRAIGHT_TRAVERSE(0.0000, -10.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   16 N..... STRAIGHT_FEED(-10.0000, -8.7300, 0.0000, 0.0000, 0.0000, 0.0000)
   17 N..... ARC_FEED(-21.2699, -19.9875, -9.9005, -20.0995, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   18 N..... ARC_FEED(-20.0000, -21.2700, -20.0000, -20.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   19 N..... STRAIGHT_FEED(-10.0000, -21.2700, 0.0000, 0.0000, 0.0000, 0.0000)
   20 N..... ARC_FEED(-8.7300, -20.0000, -10.0000, -20.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   21 N..... STRAIGHT_FEED(-8.7300, -13.3585, 0.0000, 0.0000, 0.0000, 0.0000)
   22 N..... ARC_FEED(1.1545, -10.5291, -5.0000, -7.7087, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   24 N..... STRAIGHT_FEED(20.0000, 10.0000, 0.0000, 0.0000, 0.0000, 0.0000)
"""


def _oracle_comp_machine():
    from tests.oracles.rs274 import machine_text

    text = machine_text(("X", "Y", "Z"), {1: F(0)})
    return parse_machine(text.replace("[machine]\n", '[machine]\ncutter_compensation = "linuxcnc"\n', 1)
                         + '[tool_diameters]\nT1 = "2.54"\n')


def _rs274_outcome(text, machine_, setup, tmp_path):
    """nczones held to rs274 on ``text``; rs274 is run again (up to 3 times) while they differ: the standalone
    interpreter keeps its tool data in shared memory, which another rs274 running at the same time (a parallel
    test) can replace under it ("Requested tool 1 not found", a wrong length); a real difference stays."""
    from tests.oracles.rs274 import compare
    from tests.tools.rs274_diff import run_rs274

    for _ in range(3):
        moves, err, _log = run_rs274(text, setup, tmp_path)
        outcome = compare(text, machine_, moves, err)
        if outcome.status == "match":
            break
    return outcome


def test_arc_sweep_growth_in_a_concave_corner_as_linuxcnc_allows():
    from tests.oracles.rs274 import canon_motion, compare

    outcome = compare(GROW_PROGRAM, _oracle_comp_machine(), canon_motion(GROW_RS274), None)
    assert outcome.status == "match", outcome.detail


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
def test_reads_under_comp_match_rs274_on_generated_profiles(tmp_path):
    """Random compensated profiles (lines and R arcs on a 5 mm grid, G41/G42, three radii) with a read of
    #<_x>, #<_y>, #<_abs_x> or #<_abs_y> after every move, each moving Z to it: nczones's motion is rs274's
    (or both refuse).  340 seeds matched when this was written (the growth tolerance above was the one
    difference); 25 run here."""
    import random

    machine_ = _oracle_comp_machine()
    setup = (("X", "Y", "Z"), {1: F(0)}, {})
    for seed in range(25):
        rng = random.Random(seed)
        lines = ["G21 G17 G90 F100", f"G10 L1 P1 R{rng.choice(['0.5', '1', '1.27'])}", "T1 M6", "G0 X0 Y-10 Z0",
                 f"{rng.choice(['G41', 'G42'])} D1"]
        x, y = 0, -10
        for k in range(rng.randint(2, 6)):
            nx, ny = x + rng.choice([-10, 0, 10, 15]), y + rng.choice([-10, 0, 10, 15])
            if (nx, ny) == (x, y):
                ny += 10
            if k and rng.random() < 0.4:
                chord = ((nx - x) ** 2 + (ny - y) ** 2) ** 0.5
                lines.append(f"{rng.choice(['G2', 'G3'])} X{nx} Y{ny} R{round(chord / 2 + rng.choice([0.5, 3, 8]), 1)}")
            else:
                lines.append(f"G1 X{nx} Y{ny}")
            x, y = nx, ny
            lines.append(f"G0 Z[#<_{rng.choice(['x', 'y', 'abs_x', 'abs_y'])}>]")
        lines += ["G40", f"G1 X{x + 20} Y{y + 20}", "G0 Z[#<_x>]", "M2"]
        text = "\n".join(lines) + "\n"
        outcome = _rs274_outcome(text, machine_, setup, tmp_path)
        assert outcome.status == "match", (seed, outcome.detail, text)


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
def test_state_parameter_units_match_rs274_on_generated_programs(tmp_path):
    """Programs that set offsets, stored positions, G92 and a tool (G10 L1/L2, G28.1/G30.1, G92, T M6 G43) in G20
    or G21 and move to a multiple of a state parameter read in them: on the inch control the standalone rs274
    is (tests/oracles/rs274.py: control_units = "inch"), nczones's motion is rs274's.  300 seeds matched when
    this was written (7 more hit the shared tool data of a parallel rs274); no G20/G21 switch after G43: the
    standalone rs274 re-reads the tool length unconverted there (documented in specs/gcode-support.md)."""
    import random

    from tests.oracles.rs274 import machine_text

    machine_ = parse_machine(machine_text(("X", "Y", "Z"), {1: F(0)}) + '[tool_diameters]\nT1 = "0"\n')
    setup = (("X", "Y", "Z"), {1: F(0)}, {})
    params = ["5161", "5162", "5163", "5181", "5183", "5211", "5212", "5221", "5222", "5223", "5241", "5403",
              "5410", "5420", "5421", "5422", "<_x>", "<_y>", "<_abs_x>", "<_abs_z>", "5220", "5400"]
    for seed in range(25):
        rng = random.Random(seed)
        lines = [rng.choice(["G20", "G21"]) + " G17 G90",
                 f"G10 L1 P1 Z{rng.choice(['0.5', '3', '12.7'])} R{rng.choice(['0.25', '1'])}", "T1 M6", "G43"]
        for _ in range(rng.randint(3, 8)):
            r = rng.random()
            if r < 0.2:
                lines.append(f"G10 L2 P{rng.choice([1, 2])} X{rng.choice(['1', '2.5', '-3'])} "
                             f"Y{rng.choice(['0', '1.5'])} Z{rng.choice(['0', '-1'])}")
            elif r < 0.3:
                lines.append("G49")
            elif r < 0.4:
                lines.append(rng.choice(["G28.1", "G30.1"]))
            elif r < 0.5:
                lines.append(f"G92 X{rng.choice(['0', '1'])} Y{rng.choice(['0', '2'])}")
            elif r < 0.55:
                lines.append("G92.1")
            elif r < 0.65:
                lines.append(rng.choice(["G54", "G55"]))
            else:
                lines.append(f"G0 {rng.choice('XYZ')}[#{rng.choice(params)} * {rng.choice(['1', '2', '0.5'])}]")
        text = "\n".join(lines + ["M2"]) + "\n"
        outcome = _rs274_outcome(text, machine_, setup, tmp_path)
        assert outcome.status == "match", (seed, outcome.detail, text)
