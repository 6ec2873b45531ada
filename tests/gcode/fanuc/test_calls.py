"""Fanuc calls: G65 (argument specification I and II), G66/G67, M98 P L and P30002, M99 P, M97,
subprograms in the file and in a library folder, custom G/M/T codes from the machine file."""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.errors import GcodeError
from nczones.gcode.fanuc.expr import VACANT
from nczones.gcode.program import UnsupportedGcode
from nczones.machine import FanucSettings

from .helpers import blocks, ends, mill, var


def xs(got) -> list:
    return [dict(b).get("X") for b in got if "X" in dict(b)]


def test_g65_argument_specification_one():
    got, _, _ = blocks("G65 P9000 A1. B2. C3. D7. E8. F9. H11. I4. J5. K6. M13. Q17. R18. S19. T20. U21. V22. "
                       "W23. X24. Y25. Z26.\nM30\nO9000\n"
                       + "".join(f"G0 X#{n}\n" for n in (1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13, 17, 18, 19, 20, 21, 22,
                                                         23, 24, 25, 26))
                       + "M99\n")
    assert xs(got) == [1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26]


def test_g65_argument_specification_two_and_mixed():
    # II: A B C and sets of I J K; I3 lands in #10, K10 in #33; where I and II meet, the later word wins
    got, _, _ = blocks("G65 P9000 A1. I2. J3. K4. I5. J6. K7. I8.\nG65 P9001 I1. I2. D9.\nM30\n"
                       "O9000\nG0 X#1\nG0 X#4\nG0 X#5\nG0 X#6\nG0 X#7\nG0 X#8\nG0 X#9\nG0 X#10\nM99\n"
                       "O9001\nG0 X#4\nG0 X#7\nM99\n")
    assert xs(got) == [1, 2, 3, 4, 5, 6, 7, 8, 1, 9]


def test_macro_call_levels_have_their_own_locals():
    # #1 of the caller survives the call; the macro's #2 is vacant; M98 shares the caller's level
    got, v, _ = blocks("#1 = 5\n#2 = 7\nG65 P9000 A1.\nG0 X#1\nM98 P9001\nM30\n"
                       "O9000\n#100 = #1\n#101 = #2\n#1 = 99\nM99\nO9001\n#102 = #2\nM99\n")
    assert xs(got) == [5]
    assert var(v, 100) == 1 and v.read(101) is VACANT and var(v, 102) == 7


def test_g65_repeats_and_nested_macros():
    got, _, _ = blocks("#100 = 0\nG65 P9000 L3 A2.\nG0 X#100\nM30\nO9000\n#100 = #100 + #1\nG65 P9001\nM99\n"
                       "O9001\n#100 = #100 + 10\nM99\n")
    assert xs(got) == [36]


def test_macro_nesting_limit():
    with pytest.raises(GcodeError) as e:
        blocks("G65 P9000\nM30\nO9000\nG65 P9000\nM99\n")
    assert e.value.code == "GC316" and "PS0077" in e.value.diagnostics[0].message


def test_g66_calls_after_each_move_until_g67():
    got, _, _ = blocks("G66 P9010 Z-5. R2.\nG0 X10.\nG0 X20.\nG67\nG0 X30.\nM30\n"
                       "O9010\nG1 Z#26\nG0 Z#18\nM99\n")
    assert got == [[("G", 0), ("X", 10)], [("G", 1), ("Z", -5)], [("G", 0), ("Z", 2)],
                   [("G", 0), ("X", 20)], [("G", 1), ("Z", -5)], [("G", 0), ("Z", 2)], [("G", 0), ("X", 30)],
                   [("M", 30)]]


def test_m98_repeats_p_l_and_four_digit_count():
    got, _, _ = blocks("G91\nM98 P100 L2\nM98 P30100\nM98 P100 L0\nM30\nO100\nG0 X1.\nM99\n")
    assert xs(got) == [1] * 5


def test_m99_p_returns_to_a_sequence_number():
    got, _, _ = blocks("M98 P100\nG0 X1.\nN20 G0 X2.\nM30\nO100\nG0 X9.\nM99 P20\n")
    assert xs(got) == [9, 2]


def test_m99_in_the_main_program_is_unknown_and_m99_p_jumps():
    with pytest.raises(UnsupportedGcode) as e:
        blocks("G0 X1.\nM99\n")
    assert e.value.code == "M99"
    got, _, _ = blocks("#1 = 0\nN5 #1 = #1 + 1\nIF [#1 GT 2] GOTO 9\nM99 P5\nN9 G0 X#1\n")
    assert xs(got) == [3]


def test_haas_m97_local_subprogram():
    got, _, _ = blocks("M97 P100 L2\nG0 X5.\nM30\nN100 G91 G0 X1.\nM99\n")
    assert xs(got) == [1, 1, 5]


def test_subprogram_from_the_library_folder(tmp_path):
    (tmp_path / "O1234.nc").write_text("%\nO1234 (LIB)\nG0 X7.\nM99\n%\n")
    (tmp_path / "O0042").write_text("G0 X8.\nM99\n")
    got, _, _ = blocks("M98 P1234\nM98 P42\nG65 P1234\nM30\n", library=tmp_path)
    assert xs(got) == [7, 8, 7]
    with pytest.raises(GcodeError) as e:
        blocks("M98 P4321\n", library=tmp_path)
    assert "no program O4321" in e.value.diagnostics[0].message and str(tmp_path) in e.value.diagnostics[0].message


def test_library_spans_name_the_library_file(tmp_path):
    (tmp_path / "O1234.nc").write_text("O1234\nG0 X1 Y[1/0]\nM99\n")
    with pytest.raises(GcodeError) as e:
        blocks("M98 P1234\n", library=tmp_path)
    span = e.value.diagnostics[0].span
    assert span.file.endswith("O1234.nc") and span.line == 2


def test_custom_g_m_and_t_codes_call_programs():
    settings = FanucSettings(macros={"G100": (9010, "macro"), "M50": (9020, "subprogram"), "T": (9000, "macro")})
    got, _, _ = blocks("G100 X3. Y4.\nM50\nT7\nM30\n"
                       "O9010\nG0 X#24 Y#25\nG100 X1.\nM99\n"   # inside, G100 is an ordinary G code
                       "O9020\nG0 X5.\nM99\n"
                       "O9000\nG0 X#149\nM99\n", settings=settings)
    assert got == [[("G", 0), ("X", 3), ("Y", 4)], [("G", 100), ("X", 1)], [("G", 0), ("X", 5)],
                   [("G", 0), ("X", 7)], [("M", 30)]]


def test_subprogram_running_into_the_next_program_is_an_error():
    with pytest.raises(GcodeError) as e:
        blocks("M98 P1\nM30\nO1\nG0 X1.\nO2\nM99\n")
    assert "runs into program O2 without M99" in e.value.diagnostics[0].message


def test_main_program_ends_at_the_next_program_number():
    got, _, _ = blocks("O1\nG0 X1.\nO2\nG0 X2.\n")
    assert xs(got) == [1]


def test_calls_on_the_machine():
    # G65 moves through the interpreter; the macro's moves are in the work system (G54 X100 Y50, EXT Z1)
    pts = ends("G90 G54 G0 X0 Y0 Z10.\nG65 P9000 X5. Y6.\nM30\nO9000\nG0 X#24 Y#25\nM99\n")
    assert pts[-1] == (Fraction(105), Fraction(56), Fraction(-189))


def test_g66_bolt_circle_macro_on_the_machine():
    # derivation: G66 calls O9010 after each hole position; the macro feeds to Z-5 and back to R2 in G54
    # (Z offsets -200 + EXT 1 = -199): machine Z -204 and -197 at each of the two holes
    m = mill()
    pts = ends("G90 G54 G0 X0 Y0 Z10.\nG66 P9010 Z-5. R2.\nX10.\nX20.\nG67\nM30\n"
               "O9010\nG1 Z#26 F100.\nG0 Z#18\nM99\n", m)
    assert pts[1:] == [(110, 50, -189), (110, 50, -204), (110, 50, -197),
                       (120, 50, -197), (120, 50, -204), (120, 50, -197)]


def test_nested_g66_is_unknown():
    with pytest.raises(UnsupportedGcode) as e:
        blocks("G66 P9010 Z-5.\nG66 P9011\nM30\nO9010\nM99\nO9011\nM99\n")
    assert e.value.code == "G66" and e.value.span.line == 2
