"""LinuxCNC language and modal meaning where nczones proved a path LinuxCNC does not take (issue 33, classes
11, 12, 13, 14, 18, 19 and the errors of its "also compared" list).

Every expected motion is the canonical output of LinuxCNC 2.9's ``rs274 -g`` (the installed
``linuxcnc-uspace`` 2.9.0~pre1) of the same program, quoted in the test (program coordinates; G54 = 0, so
with no G92 and no tool length they are the machine coordinates; the standalone interpreter's tool table is
in inches: tool 1 is 0.5 in = 12.7 mm, tool 2 1.25 in = 31.75 mm).  Each verdict test runs the program
through :func:`nczones.prover.verify_text` as written (the general path), after 600 plain moves (the
vectorized tier takes the run) and with ``#`` parameters in those moves (the double pass is tried first):
in each, LinuxCNC's path enters the clamp and the verdict must be ``unsafe`` where nczones said ``safe``.
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from fractions import Fraction
from pathlib import Path

import pytest

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.oracles.rs274 import canon_error, canon_motion, compare, machine_text, tool_table

TOOLS_INCH = {1: Fraction("0.5"), 2: Fraction("1.25")}


def machine(clamp_min: str, clamp_max: str):
    """X Y Z from machine zero, travel +-100 mm, one clamp; tools 1 and 2 as rs274's table."""
    return parse_machine(machine_text(("X", "Y", "Z"), TOOLS_INCH) + f"""
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "-100", Y = "-100", Z = "-100" }}
max = {{ X = "100", Y = "100", Z = "100" }}
[[zones]]
name = "clamp"
kind = "box"
forbid = true
min = {{ {clamp_min} }}
max = {{ {clamp_max} }}
""")


#: 600 plain feeds well away from every clamp of this file, then back to machine zero.
LONG = "F1000\n" + "".join(f"G1 X{i % 7} Y{60 + i % 3} Z0\n" for i in range(600)) + "G0 X0 Y0 Z0\n"


def lanes(program: str) -> dict[str, str]:
    return {"short": program, "long": LONG + program,
            "hash": "#1 = 0\n" + LONG.replace(" Z0\n", " Z[#1]\n") + program}


def assert_unsafe_in_every_lane(program: str, m) -> None:
    for lane, text in lanes(program).items():
        result = verify_text(text, m)
        assert result.verdict.label == "unsafe", (lane, result.verdict)
        assert {v.zone for v in result.violations} == {"clamp"}, lane


def moves(program: str, m) -> list[tuple[str, Fraction, Fraction, Fraction]]:
    run = interpret_text(program, m)
    out = [(s.kind.name, *s.end) for c in run for s in c.segments()]
    assert not run.unsupported, run.unsupported
    return out


def rows(*rs) -> list[tuple]:
    return [(r[0], *(Fraction(str(v)) for v in r[1:])) for r in rs]


CLAMP_X10 = machine('X = "9", Y = "-5", Z = "-100"', 'X = "11", Y = "5", Z = "-1"')


# ---------------------------------------------------------------- class 11: M70/M72/M73 restore every group
G92_RESTORE = "F100\nG0 X0 Y0 Z0\nM70\nG92 X-20\nG0 X0\nM72\nG0 X10 Y0 Z-5\nM2\n"
TOOL_RESTORE = "F100\nG0 X0 Y0 Z0\nM70\nT1 M6\nG43 H1\nG0 X5\nM72\nG0 X10 Y0 Z-5\nM2\n"
DIAMETER_RESTORE = "F100\nG18 G8\nG0 X0 Z0\nM70\nG7\nG0 X40\nM72\nG0 X20 Z-5\nM2\n"


def test_m72_restores_g92_not_applied():
    """save_settings keeps #5210 (G92 applied: no) as ``G92.2``; M72 runs it.  rs274:
    ``SET_G92_OFFSET(20, 0, 0 ...)`` at G92, ``SET_G92_OFFSET(0, 0, 0 ...)`` at M72, then
    ``STRAIGHT_TRAVERSE(10, 0, -5)``: into the clamp at X 9..11.  nczones kept the G92 offset and went to X 30."""
    assert moves(G92_RESTORE, CLAMP_X10)[-1] == ("RAPID", 10, 0, -5)
    assert_unsafe_in_every_lane(G92_RESTORE, CLAMP_X10)


def test_m72_restores_g49():
    """save_settings keeps G49 (no tool length applied); M72 runs ``G49``.  rs274:
    ``USE_TOOL_LENGTH_OFFSET(0 0 12.7)`` at G43 H1, ``USE_TOOL_LENGTH_OFFSET(0 0 0)`` at M72, then
    ``STRAIGHT_TRAVERSE(10, 0, -5)``.  nczones kept tool 1's 12.7 mm and stayed at machine Z 7.7."""
    assert moves(TOOL_RESTORE, CLAMP_X10)[-1] == ("RAPID", 10, 0, -5)
    assert_unsafe_in_every_lane(TOOL_RESTORE, CLAMP_X10)


def test_m72_restores_g8():
    """save_settings keeps the lathe diameter mode; M72 runs ``G8``.  rs274: ``STRAIGHT_TRAVERSE(20, 0, 0)``
    for ``G7 X40``, then ``STRAIGHT_TRAVERSE(20, 0, -5)`` for ``X20`` read as a radius again.  nczones kept G7
    and went to X 10."""
    m = machine('X = "19", Y = "-5", Z = "-100"', 'X = "21", Y = "5", Z = "-1"')
    assert moves(DIAMETER_RESTORE, m)[-1] == ("RAPID", 20, 0, -5)
    assert_unsafe_in_every_lane(DIAMETER_RESTORE, m)


def test_m73_restores_on_return_from_an_m98_subprogram():
    """M73 in an M98 subprogram restores at M99 (leave_context restores every call frame marked by M73);
    nczones made it unknown.  rs274: the G92 of the subprogram is undone, ``STRAIGHT_TRAVERSE(10, 0, -5)``."""
    text = "F100\nG0 X0 Y0 Z0\nM98 P100\nG0 X10 Y0 Z-5\nM2\nO100\nM73\nG92 X-20\nM99\n"
    assert moves(text, CLAMP_X10)[-1] == ("RAPID", 10, 0, -5)
    assert_unsafe_in_every_lane(text, CLAMP_X10)


def test_m72_restores_in_its_own_call_frame_only():
    """M70 saves in the current call frame (``sub_context[call_level]``), cleared when a call enters it: M72 in
    a subroutine without its own M70 is LinuxCNC's error "Cannot restore context from invalid stack frame"."""
    text = "o1 sub\nM72\no1 endsub\nM70\nG91\no1 call\nM2\n"
    with pytest.raises(GcodeError) as e:
        moves(text, CLAMP_X10)
    d = e.value.diagnostics[0]
    assert (d.code, d.span.line, d.span.column) == ("GC204", 2, 1)


def test_an_m72_restored_feed_below_0_05_is_zero():
    """gen_settings writes the feed as ``F%.1f``: F0.04 comes back as F0.0 and the next G1 is refused (rs274:
    "Cannot do g1 with zero feed rate" at ``G1 X2``); F12.34 comes back as F12.3."""
    with pytest.raises(GcodeError) as e:
        moves("G1 X1 F0.04\nM70\nF100\nM72\nG1 X2\nM2\n", CLAMP_X10)
    d = e.value.diagnostics[0]
    assert (d.code, d.span.line) == ("GC305", 5)
    run = interpret_text("G1 X1 F12.34\nM70\nF100\nM72\nG1 X2\nM2\n", CLAMP_X10)
    assert [s.feed_mm_min for c in run for s in c.segments()] == [Fraction("12.34"), Fraction("12.3")]


# ---------------------------------------------------------------- class 12: counts and integer words round
def test_repeat_rounds_its_count():
    """``o1 repeat [2.6]``: LinuxCNC's round_to_int (nearbyint) makes 3.  rs274: feeds to X 10, 20 and 30
    (``STRAIGHT_FEED(30, 0, -5)``), through the clamp at X 25..27; nczones truncated to 2 and stopped at X 20."""
    m = machine('X = "25", Y = "-5", Z = "-100"', 'X = "27", Y = "5", Z = "-1"')
    text = "F100\nG0 X0 Y0 Z-5\no1 repeat [2.6]\nG91 G1 X10\no1 endrepeat\nG90\nM2\n"
    assert moves(text, m)[-1] == ("LINE", 30, 0, -5)
    assert_unsafe_in_every_lane(text, m)
    # halves go to even (nearbyint): [2.5] twice, [3.5] four times
    assert len(moves("F100\no1 repeat [2.5]\nG91 G1 X1\no1 endrepeat\nM2\n", m)) == 2
    assert len(moves("F100\no1 repeat [3.5]\nG91 G1 X1\no1 endrepeat\nM2\n", m)) == 4


def test_g10_p_and_integer_words_as_linuxcnc_reads_them():
    """check_g10 lets P be from p_int - 0.5 to p_int + 0.0001 and convert_setup truncates P + 0.0001:
    ``G10 L2 P1.6`` writes G54, ``G10 L20 P2.5`` G55; T, H (read_integer_value) within 0.0001 of an integer.
    rs274: ``SET_G5X_OFFSET(1, 10, 0, 0 ...)``, ``SET_G5X_OFFSET(2, 5, 0, 0 ...)`` (X0 at machine 0 read as -5),
    ``USE_TOOL_LENGTH_OFFSET(0 0 31.75)``; nczones refused all three (exit 2)."""
    text = ("G10 L2 P1.6 X10\nG10 L20 P2.5 X-5\nG54 G0 X0 Y0 Z-5\nG55 G0 X0 Y0 Z-5\nT[2.00001] M6\n"
            "G43 H[2.00001]\nG0 X0 Z-5\nM2\n")
    assert moves(text, CLAMP_X10) == rows(("RAPID", 10, 0, -5), ("RAPID", 5, 0, -5), ("RAPID", 5, 0, "26.75"))
    assert_unsafe_in_every_lane(text, CLAMP_X10)
    for bad, col in (("G10 L2 P1.4 X1", 8), ("T2.5 M6", 1), ("G43 H1.5", 5)):
        with pytest.raises(GcodeError) as e:
            moves(bad + "\nM2\n", CLAMP_X10)
        assert (e.value.diagnostics[0].code, e.value.diagnostics[0].span.column) == ("GC209", col), bad


def test_m98_l_and_p_within_the_tolerance():
    """rs274: ``M98 P2 L[2.00001]`` calls O2 twice (read_integer_value)."""
    text = "F100\nG0 X0 Y0 Z-5\nM98 P[2.00001] L[2.00001]\nM2\nO2\nG91 G1 X5\nG90\nM99\n"
    assert moves(text, CLAMP_X10)[-1] == ("LINE", 10, 0, -5)
    assert_unsafe_in_every_lane(text, CLAMP_X10)


# ---------------------------------------------------------------- class 14: G70 with a non-integer P
G70_P = "G18 G21 F100\no1 sub\nG1 X5 Z0\nG1 X8 Z-10\nX12\no1 endsub\nG0 X12 Z4\nG70 Q1 X12 Z2 D1 E0 P2.6\nM2\n"


def test_g70_counts_int_p_passes_spaced_by_the_real_p():
    """interp_g7x.cc (LinuxCNC 2.9) ``for(int pass=p; pass>0; pass--)`` with ``distance=(pass-1)*(d-e)/p+e`` in
    the double P: P2.6 makes 2 passes, the first 1/2.6 = 0.3846 mm off the profile.  rs274:
    ``STRAIGHT_TRAVERSE(5.3684, 0, 0.1105)``, ``STRAIGHT_FEED(8.2862, 0, -9.6154)``, ``STRAIGHT_FEED(12, 0,
    -9.6154)``, then the last pass on the profile.  nczones divided by 2 (0.5 mm off: Z -9.5), past the clamp
    at Z -9.65..-9.58; P0.5 makes no pass (nczones refused it)."""
    m = machine('X = "9", Y = "-5", Z = "-9.65"', 'X = "11", Y = "5", Z = "-9.58"')
    got = moves(G70_P, m)
    assert [(k, round(float(x), 4), round(float(z), 4)) for k, x, _y, z in got[3:6]] == [
        ("RAPID", 5.3684, 0.1105), ("LINE", 8.2862, -9.6154), ("LINE", 12.0, -9.6154)]
    assert_unsafe_in_every_lane(G70_P, m)
    # P0.5 makes no pass; 2.9.0~pre1 then takes the profile's end as its position (the start is restored only
    # by later versions, b1f3e7d8): unknown after the rapids to X12 Z4 and to X12 Z2 (specs/turning.md, "Version")
    run = interpret_text(G70_P.replace("P2.6", "P0.5"), m)
    assert len([s for c in run for s in c.segments()]) == 2 and "makes no move" in run.unsupported[0].reason


# ---------------------------------------------------------------- class 13: #<_value> resets
CLAMP_X0 = machine('X = "-1", Y = "-5", Z = "-100"', 'X = "1", Y = "5", Z = "-1"')


def test_value_resets_after_a_subroutine_without_a_value():
    """read_o sets ``return_value = 0`` at an endsub or return without a value.  rs274:
    ``STRAIGHT_TRAVERSE(0, 0, -5)`` into the clamp at X -1..1; nczones kept 5 and went to X 10."""
    text = ("o1 sub\no1 return [5]\no1 endsub\no2 sub\no2 endsub\no1 call\no2 call\nG0 X[#<_value>*2] Y0 Z-5\n"
            "M2\n")
    assert moves(text, CLAMP_X0)[-1] == ("RAPID", 0, 0, -5)
    assert_unsafe_in_every_lane(text, CLAMP_X0)


def test_value_is_set_by_the_endsub_of_a_skipped_definition_and_by_m99():
    """read_o reads the endsub that ends a definition it skips, and an M99: rs274 gives #<_value> 7 after
    ``o1 endsub [7]`` is only defined, and 0 after an M98 subprogram."""
    text = "o2 sub\no2 return [5]\no2 endsub\no2 call\no1 sub\no1 endsub [7]\nG0 X#<_value> Y#<_value_returned>\nM2\n"
    assert moves(text, CLAMP_X0) == rows(("RAPID", 7, 1, 0))
    text = "o2 sub\no2 return [5]\no2 endsub\no2 call\nM98 P3\nG0 X#<_value> Y#<_value_returned> Z-5\nM2\nO3\nM99\n"
    assert moves(text, CLAMP_X0) == rows(("RAPID", 0, 0, -5))


def test_value_after_a_definition_whose_endsub_reads_a_local_is_unknown():
    """LinuxCNC reads an undefined name as nothing while it defines a sub (``read_named_parameter``:
    ``defining_sub``), so ``#<_value>`` is whatever its reader's variable held: unknown, not 0 (and not an error:
    the corpus's probe macros end with such an endsub)."""
    run = interpret_text("o1 sub\n#<y> = 1\no1 endsub [#<y>]\nG0 X1\nG0 X#<_value>\nM2\n", CLAMP_X0)
    assert len([s for c in run for s in c.segments()]) == 1
    assert [(u.code, u.span.line) for u in run.unsupported] == [("GC395", 5)]
    assert moves("o1 sub\n#<y> = 1\no1 endsub [#<y>]\no2 sub\no2 endsub\nG0 X#<_value>\nM2\n", CLAMP_X0) == rows(
        ("RAPID", 0, 0, 0))  # the next endsub sets it again


def test_value_is_read_only():
    """rs274: "Cannot assign to read-only parameter #<_value>" at ``#<_value> = 3``."""
    for text in ("#<_value> = 3\nG0 X1\nM2\n", "G0 X1\n#<_x> = 2 G0 X2\nM2\n"):
        with pytest.raises(GcodeError) as e:
            moves(text, CLAMP_X0)
        d = e.value.diagnostics[0]
        assert d.code == "GC318" and d.span.line == text.count("\n", 0, text.index("#<_")) + 1


# ---------------------------------------------------------------- class 18: M98 frames
def test_m98_subprogram_locals_are_its_own():
    """enter_context gives every M98 call a new frame; its named locals are freed at M99.  rs274:
    ``STRAIGHT_TRAVERSE(0, 0, -5)``: the caller's #<y> is still 0; nczones read the subprogram's 10."""
    text = "#<y> = 0\nM98 P100\nG0 X[#<y>] Y0 Z-5\nM2\nO100\n#<y> = 10\nM99\n"
    assert moves(text, CLAMP_X0)[-1] == ("RAPID", 0, 0, -5)
    assert_unsafe_in_every_lane(text, CLAMP_X0)


# ---------------------------------------------------------------- class 19: lathe mode parameters
def test_lathe_mode_parameters_follow_g7_g8():
    """rs274 in G7 takes the ``#<_lathe_diameter_mode> EQ 1`` branch: ``STRAIGHT_TRAVERSE(20, 0, -5)`` (X40 as
    a diameter); nczones read the constant 0 and went to X 30."""
    m = machine('X = "19", Y = "-5", Z = "-100"', 'X = "21", Y = "5", Z = "-1"')
    text = ("G18 G7\nG0 X0 Z0\no1 if [#<_lathe_diameter_mode> EQ 1 AND #<_lathe_radius_mode> EQ 0]\nG0 X40 Z-5\n"
            "o1 else\nG0 X60 Z-5\no1 endif\nM2\n")
    assert moves(text, m)[-1] == ("RAPID", 20, 0, -5)
    assert_unsafe_in_every_lane(text, m)


# ---------------------------------------------------------------- errors LinuxCNC reports
def test_a_comment_inside_a_word_is_an_error():
    """rs274: "Bad character '0' used" for ``G0 X1(c)0``; nczones (its vectorized tier) read X10."""
    for lane, text in lanes("G0 X1(c)0\nM2\n").items():
        with pytest.raises(GcodeError) as e:
            for _ in interpret_text(text, CLAMP_X0):
                pass
        d = e.value.diagnostics[0]
        assert d.code == "GC101" and d.span.column == 9, lane


@pytest.mark.parametrize("text,line,col", [
    # rs274: "5: duplicate O-word label - already defined in line 2"
    ("G0 X0\no1 if [1]\nG0 X1\no1 endif\no1 if [1]\nG0 X2\no1 endif\nM2\n", 5, 1),
    # rs274: "4: duplicate O-word label: 'o1 repeat [2]' - defined in line 1"
    ("o1 repeat [2]\nG0 X1\no1 endrepeat\no1 repeat [2]\nG0 X2\no1 endrepeat\nM2\n", 4, 1),
    # rs274: "4: duplicate O-word label - already defined in line 2" (an if inside the while of its label)
    ("#1 = 0\no1 while [#1 LT 5]\n#1 = [#1 + 1]\no1 if [#1 EQ 2]\no1 endif\no1 endwhile\nM2\n", 4, 1),
    # rs274: "redefining sub: o|2| already defined"
    ("o2 sub\nG0 X5\no2 endsub\no2 sub\nG0 X7\no2 endsub\no2 call\nM2\n", 4, 1),
    # rs274: "sub: o|2| found in illegal location" (called, found searching forward, then reached)
    ("o2 call\nG0 X1\no2 sub\nG0 Y5\no2 endsub\nM2\n", 3, 1),
    # rs274: "EOF in file seeking o-word: o<2>": a definition in a skipped if is not made (rs274 names the
    # last line; nczones the call)
    ("o1 if [0]\no2 sub\nG0 X5\no2 endsub\no1 endif\no2 call\nM2\n", 6, 1),
    # rs274: "Too many subroutine levels" at the tenth nested call
    ("".join(f"o{k} sub\no{k + 1} call\no{k} endsub\n" for k in range(1, 11)) + "o11 sub\nG0 Z1\no11 endsub\n"
     "o1 call\nM2\n", 26, 1),  # o10 call
])
def test_o_word_errors_linuxcnc_reports(text, line, col):
    with pytest.raises(GcodeError) as e:
        moves(text, CLAMP_X0)
    d = e.value.diagnostics[0]
    assert (d.span.line, d.span.column) == (line, col), d
    assert d.code in ("GC313", "GC314", "GC316")


def test_subroutines_found_forward_and_labels_per_subroutine():
    """rs274 runs these: a call finds a sub defined after it (main program before the definitions), the same
    if label in two subs and in the main program (``o2#1``, ``o3#1``, ``#1``)."""
    text = ("o2 sub\no1 if [1]\nG0 Y5\no1 endif\no2 endsub\no3 sub\no1 if [1]\nG0 Y6\no1 endif\no3 endsub\n"
            "o2 call\no2 call\no3 call\no1 if [1]\nG0 Y7\no1 endif\no4 call\nM2\no4 sub\nG0 Y8\no4 endsub\n")
    assert [y for _k, _x, y, _z in moves(text, CLAMP_X0)] == [5, 5, 6, 7, 8]


# ---------------------------------------------------------------- against rs274 itself, where installed
RS274 = shutil.which("rs274")


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is not installed")
@pytest.mark.parametrize("text", [G92_RESTORE, TOOL_RESTORE, DIAMETER_RESTORE,
                                  "F100\no1 repeat [2.6]\nG91 G1 X10\no1 endrepeat\nM2\n", G70_P,
                                  "#<y> = 0\nM98 P100\nG0 X[#<y>] Y0 Z-5\nM2\nO100\n#<y> = 10\nM99\n"])
def test_the_quoted_programs_match_rs274(text):
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "prog.ngc").write_text(text)
        (work / "tool.tbl").write_text(tool_table(TOOLS_INCH))
        p = subprocess.run([RS274, "-t", "tool.tbl", "-g", "prog.ngc"], cwd=work, capture_output=True, text=True,
                           timeout=30, stdin=subprocess.DEVNULL, env={"HOME": tmp, "PATH": "/usr/bin:/bin"})
    outcome = compare(text, CLAMP_X10, canon_motion(p.stdout), canon_error(p.returncode, p.stderr))
    assert outcome.status == "match", outcome.detail
