"""Custom Macro B: variables, vacant, operators, functions, IF/GOTO, WHILE/DO/END (fanuc dialect)."""

from __future__ import annotations

import math
import re
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode.fanuc.expr import VACANT
from nczones.gcode.program import IterationBoundExceeded, UnsupportedGcode
from tests.machines import machine_text

from .helpers import blocks, var

# ---------------------------------------------------------------- values and vacant


@pytest.mark.parametrize("expr, expected", [
    ("1 + 2 * 3", 7), ("[1 + 2] * 3", 9), ("10 - 4 - 3", 3), ("7 / 2", Fraction(7, 2)),
    ("2 + 3 AND 1", 3),        # AND binds like *: 2 + (3 AND 1) = 2 + 1
    ("6 OR 1 * 0", 6),         # OR binds like +: 6 OR (1 * 0)
    ("5 XOR 3", 6), ("12 AND 10", 8), ("12 OR 3", 15),
    ("27 MOD 20", 7), ("-27 MOD 20", -7), ("27.6 MOD 5", 3),  # operands rounded; the dividend's sign
    ("FIX[1.2]", 1), ("FIX[-1.2]", -1), ("FUP[1.2]", 2), ("FUP[-1.2]", -2),  # towards / away from 0
    ("ROUND[2.5]", 3), ("ROUND[-2.5]", -3), ("ROUND[1.2345]", 1),
    ("ABS[-2.5]", Fraction(5, 2)), ("SQRT[16]", 4), ("POW[2,10]", 1024),
    ("BCD[12]", 18), ("BIN[18]", 12), ("ATAN[-1]/[-1]", 225), ("ATAN[1,1]", 45), ("ATAN[0]/[-1]", 180),
    ("ASIN[-1]", 270), ("ACOS[-1]", 180), ("-[2 * 3]", -6),
])
def test_operators_functions_precedence(expr, expected):
    _, v, _ = blocks(f"#100 = {expr}\n")
    assert var(v, 100) == expected


def test_trigonometry_is_in_degrees_with_the_controllers_double():
    _, v, _ = blocks("#1 = SIN[30]\n#2 = COS[60]\n#3 = TAN[45]\n#4 = LN[EXP[1]]\n")
    assert v.read(1)[0] == math.sin(30 * math.pi / 180)
    assert v.read(2)[0] == math.cos(60 * math.pi / 180)
    assert abs(v.read(3)[0] - 1) < 1e-15
    assert v.read(4)[0] == 1.0


def test_atan_and_asin_signed_with_nat():
    from nczones.gcode.fanuc.expr import Context, FanucVariables, evaluate_tree
    from nczones.gcode.fanuc.parser import parse_line

    tree = parse_line("#1 = ATAN[-1]/[-1]", 1, "p").assigns[0][1]
    assert evaluate_tree(tree, FanucVariables(), Context(signed_angles=True))[0] == -135
    assert evaluate_tree(tree, FanucVariables(), Context(signed_angles=False))[0] == 225


def test_vacant_rules():
    # Fanuc's table: vacant stays vacant when copied, is 0 in arithmetic, differs from 0 only in EQ/NE
    _, v, _ = blocks(
        "#2 = #1\n#3 = #1 + 1\n#4 = #1 * 5\n#5 = #1 + #1\n#6 = [#1]\n"
        "IF [#1 EQ #0] THEN #10 = 1\nIF [#1 EQ 0] THEN #11 = 1\nIF [#1 NE 0] THEN #12 = 1\n"
        "IF [#1 GE 0] THEN #13 = 1\nIF [#1 GT 0] THEN #14 = 1\n#20 = 0\nIF [#20 EQ #0] THEN #15 = 1\n"
        "IF [#20 NE #0] THEN #16 = 1\n")
    assert v.read(2) is VACANT and v.read(6) is VACANT
    assert (var(v, 3), var(v, 4), var(v, 5)) == (1, 0, 0)
    assert (var(v, 10), var(v, 11), var(v, 12), var(v, 13), var(v, 14)) == (1, None, 1, 1, None)
    assert (var(v, 15), var(v, 16)) == (None, 1)


def test_vacant_variable_drops_its_word():
    got, _, _ = blocks("#1 = 10\nG90 X#1 Y#2 Z-#3\nG0 X[#4]\n")
    assert got == [[("G", 90), ("X", 10)], [("G", 0)]]


def test_address_values_round_as_the_control():
    # 0i manual, ROUND: X-#1 with #1 = 1.2345 moves 1.235; X[#1 + #2] = 3.5801 -> 3.580;
    # X[ROUND[#1] + ROUND[#2]] = 1.235 + 2.346 = 3.581; integer addresses round to the nearest integer
    got, _, _ = blocks("#1 = 1.2345\n#2 = 2.3456\nG0 X-#1 Y[#1 + #2] Z[ROUND[#1] + ROUND[#2]]\n"
                       "#3 = 1000.5\nS#3 M[3.4999]\n")
    assert got[0] == [("G", 0), ("X", Fraction("-1.235")), ("Y", Fraction("3.580")), ("Z", Fraction("3.581"))]
    assert got[1] == [("S", 1001), ("M", 3)]


def test_common_variables_start_from_the_machine_file_and_locals_vacant():
    _, v, _ = blocks("#101 = #500 + 1\n", initial={500: Fraction(5, 2)})
    assert var(v, 101) == Fraction(7, 2)
    assert v.read(1) is VACANT and v.read(199) is VACANT


@pytest.mark.parametrize("text, code", [
    ("#0 = 1\n", "GC205"), ("#40 = 1\n", "GC205"), ("#1 = 1 / 0\n", "GC311"), ("#1 = SQRT[-1]\n", "GC312"),
    ("#1 = ASIN[2]\n", "GC312"), ("#1 = 5 MOD 0\n", "GC311"), ("#1 = LN[0]\n", "GC312"),
    # 1e308 degrees: finite, but 1e308 * pi overflows a double (was Python's ValueError, an internal error)
    *((f"#1 = {fn}[1{'0' * 308}]\n", "GC312") for fn in ("SIN", "COS", "TAN")),
    *((f"#2 = 1{'0' * 308}\n#1 = {fn}[#2]\n", "GC312") for fn in ("SIN", "COS", "TAN")),
])
def test_run_time_errors(text, code):
    with pytest.raises(GcodeError) as e:
        blocks(text)
    assert e.value.code == code and e.value.diagnostics[0].span.line == text.count("\n")  # the last line


@pytest.mark.parametrize("line, code, column", [
    ("#1 = [[[[[[1]]]]]]", "GC105", 11), ("G1 X1 ; Y2", "GC101", 7), ("#1 = FOO[1]", "GC106", 6),
    ("IF [#1 EQ 1] G1 X1", "GC202", 14), ("WHILE [#1 LT 2] X1", "GC202", 17), ("##1 = 2", "GC107", 1),
    ("G1 X1 (unclosed", "GC102", 7),
])
def test_syntax_errors_point_at_the_text(line, code, column):
    with pytest.raises(GcodeError) as e:
        blocks(line + "\n")
    d = e.value.diagnostics[0]
    assert (d.code, d.span.line, d.span.column) == (code, 1, column)


# ---------------------------------------------------------------- control flow


def test_if_goto_forward_and_backward():
    got, v, _ = blocks("#1 = 0\nN10 #1 = #1 + 1\nIF [#1 LT 5] GOTO 10\nIF [#1 EQ 5] GOTO 30\nG0 X99\n"
                       "N30 G0 X#1\n")
    assert got == [[("G", 0), ("X", 5)]]


def test_goto_computed_and_missing_target():
    got, _, _ = blocks("#7 = 20\nGOTO #7\nG0 X1\nN20 G0 X2\n")
    assert got == [[("G", 0), ("X", 2)]]
    with pytest.raises(GcodeError) as e:
        blocks("GOTO 77\nN20 G0 X2\n")
    assert e.value.code == "GC314" and "N77" in e.value.diagnostics[0].message


def test_while_do_end_and_nesting():
    got, v, _ = blocks("#1 = 0\n#3 = 0\nWHILE [#1 LT 3] DO1\n#2 = 0\nWHILE [#2 LT 2] DO2\n#3 = #3 + 1\n"
                       "#2 = #2 + 1\nEND2\n#1 = #1 + 1\nEND1\nG0 X#3\n")
    assert got == [[("G", 0), ("X", 6)]]


def test_while_false_at_entry_skips_to_its_end():
    got, _, _ = blocks("WHILE [1 EQ 2] DO1\nG0 X9\nWHILE [1 EQ 1] DO2\nEND2\nEND1\nG0 X1\n")
    assert got == [[("G", 0), ("X", 1)]]


def test_goto_out_of_a_loop_closes_it_and_ids_can_be_reused():
    got, _, _ = blocks("#1 = 0\nWHILE [1 EQ 1] DO1\n#1 = #1 + 1\nIF [#1 GE 3] GOTO 50\nEND1\n"
                       "N50 WHILE [#1 LT 5] DO1\n#1 = #1 + 1\nEND1\nG0 X#1\n")
    assert got == [[("G", 0), ("X", 5)]]


@pytest.mark.parametrize("text, message", [
    ("WHILE [1 EQ 1] DO1\nWHILE [1 EQ 1] DO1\nEND1\nEND1\n", "nested loops need different"),
    ("WHILE [1 EQ 1] DO1\nWHILE [1 EQ 1] DO2\nEND1\nEND2\n", "must not cross"),
    ("END1\n", "without an open DO1"),
    ("WHILE [1 EQ 1] DO4\nEND4\n", "1, 2 or 3"),
    ("WHILE [1 EQ 2] DO1\nG0 X1\n", "no matching END1"),
    ("DO1\nDO2\nDO3\nWHILE [1 EQ 1] DO1\n", "nested more than 3"),
    ("GOTO 5\nWHILE [1 EQ 1] DO1\nN5 G0 X1\nEND1\n", "cannot jump into a loop"),
])
def test_loop_errors(text, message):
    with pytest.raises(GcodeError) as e:
        blocks(text)
    assert e.value.code == "GC314" and message in e.value.diagnostics[0].message


def test_iteration_bound_is_unknown_with_a_clear_message():
    with pytest.raises(IterationBoundExceeded) as e:
        blocks("WHILE [1 EQ 1] DO1\nG0 X1\nEND1\n", max_loop_iterations=50)
    assert e.value.code == "WHILE" and "more than 50 iterations" in e.value.reason
    with pytest.raises(IterationBoundExceeded) as e:
        blocks("N1 G0 X1\nGOTO 1\n", max_loop_iterations=50)
    assert "jumped back more than 50 times" in e.value.reason


def test_alarm_stops_the_program_and_3006_records_a_stop():
    got, _, runner = blocks("G0 X1\n#3006 = 1 (CHECK PART)\nG0 X2\nIF [#1 EQ #0] THEN #3000 = 7 (NO ARGUMENT)\n"
                            "G0 X3\n")
    assert got == [[("G", 0), ("X", 1)], [("G", 0), ("X", 2)]]
    assert runner.alarm[0:2] == (7, "NO ARGUMENT") and runner.alarm[2].line == 4
    assert runner.stops[0][0:2] == (1, "CHECK PART")


def test_nc_words_with_an_assignment_are_unknown_and_unmodelled_statements_too():
    with pytest.raises(UnsupportedGcode) as e:
        blocks("G0 X1 #1 = 2\n")
    assert "NC statement and a macro assignment" in e.value.reason
    with pytest.raises(UnsupportedGcode) as e:
        blocks("IF [#1 EQ 1] THEN #2 = 1\nELSE\n")
    assert e.value.code == "ELSE"


# ---------------------------------------------------------------- decimal point input


def test_decimal_point_input_increment_and_calculator():
    from nczones.machine import FanucSettings

    inc = FanucSettings(decimal_point_input="increment")
    got, _, runner = blocks("G0 X100 Y100. Z-5 F100\n", settings=inc)
    assert got[0][1:] == [("X", Fraction(1, 10)), ("Y", 100), ("Z", Fraction(-1, 200)), ("F", 100)]
    assert runner.dpi_count == 2
    got, _, runner = blocks("G04 X2500\n", settings=inc)
    assert got[0] == [("G", 4), ("X", Fraction(5, 2))]  # dwell X: increments of 0.001 s
    got, _, runner = blocks("G0 X100 Y100. Z-5\n")
    assert got[0][1:] == [("X", 100), ("Y", 100), ("Z", -5)] and runner.dpi_count == 2


def test_repeat_count_k_is_a_count_in_a_cycle_and_a_length_elsewhere():
    from nczones.machine import FanucSettings

    inc = FanucSettings(decimal_point_input="increment")
    got, _, _ = blocks("G81 X1. Z-1. R1. K3\nG17 G02 X1. Y0 I1. K5\n", settings=inc)
    assert ("K", 3) in got[0] and ("K", Fraction(5, 1000)) in got[1]


def test_literals_beyond_the_increment_are_rounded():
    got, _, runner = blocks("G0 X1.23456 Y-0.0005\n")
    assert got[0][1:] == [("X", Fraction("1.235")), ("Y", Fraction("-0.001"))]
    assert runner.rounded_count == 2


@settings(max_examples=60, deadline=None)
@given(st.integers(-10**7, 10**7), st.integers(0, 4))
def test_literal_and_computed_words_agree(n, places):
    # a literal and the same value computed are the same word; but a value at half an increment (four decimals
    # ending in 5) whose double lies just under it and scaled in doubles rounds down (#1 = 0.0215: 21.499999999999996
    # increments) is unknown, GC399 (its 15-digit reading rounds up, as the literal does)
    text = f"{n / 10**places:.{places}f}"
    if places == 0:
        text += "."
    half = places == 4 and abs(n) % 10 == 5
    d = float(text)
    doubles_down = abs(d) * 1000 % 1 < 0.5 or abs(d) / 0.001 % 1 < 0.5
    if half and doubles_down:
        with pytest.raises(UnsupportedGcode) as e:
            blocks(f"#1 = {text}\nG0 X{text} Y#1 Z[#1]\n")
        assert e.value.diagnostic.code == "GC399"
        return
    got, _, _ = blocks(f"#1 = {text}\nG0 X{text} Y#1 Z[#1]\n")
    x, y, z = (w[1] for w in got[0][1:])
    assert x == y == z


@pytest.mark.parametrize("value, expected", [("1.2345", "1.235"), ("0.0045", "0.005"), ("-0.0185", "-0.019"),
                                             ("0.0215", ("0.021", "0.022")), ("-1.0005", ("-1", "-1.001"))])
def test_a_variable_at_half_an_increment_rounds_as_all_readings_or_is_unknown(value, expected):
    # the 0i manual's ROUND example (#1 = 1.2345: X1.235) and others whose double, scaled to increments in doubles,
    # is the half itself (4.5, 18.5); 0.0215 / 0.001 is 21.499999999999996 in doubles, -1.0005 / 0.001
    # -1000.4999999999999: unknown, the reason names both multiples
    if isinstance(expected, tuple):
        with pytest.raises(UnsupportedGcode) as e:
            blocks(f"#1 = {value}\nG0 X#1\n")
        assert e.value.diagnostic.code == "GC399"
        assert set(re.findall(r"rounds to (-?[\d.]+);", e.value.diagnostic.message)) == set(expected)
        return
    got, _, _ = blocks(f"#1 = {value}\nG0 X#1\n")
    assert got[0][1] == ("X", Fraction(expected))


# ---------------------------------------------------------------- numbers beyond the double range

_HUGE = "9" * 400


@pytest.mark.parametrize("text", [f"#1 = {_HUGE}\n", f"#{_HUGE} = 1\n", f"#1 = [{_HUGE} + 1]\n", f"G0 X[{_HUGE}]\n"])
def test_a_literal_beyond_the_double_range_in_an_expression_is_an_input_error(text):
    # float() of such a literal raised OverflowError (a traceback) before
    with pytest.raises(GcodeError, match="GC104.*number too large"):
        blocks(text)


def test_a_word_or_argument_beyond_the_double_range_keeps_its_exact_value():
    from nczones.gcode import interpret_text

    from .helpers import mill

    m = mill()
    (seg,) = list(interpret_text(f"G90 G54 G0 X{_HUGE}.0001\nM30\n", m, dialect="fanuc").segments())
    assert seg.end[0] == Fraction(int(_HUGE)) + 100  # rounded to the increment, plus G54 X
    with pytest.raises(GcodeError, match="GC312"):  # the argument's double is infinite: arithmetic fails
        list(interpret_text(f"G65 P9000 A{_HUGE}\nM30\nO9000\n#2 = #1 + 1\nM99\n", m, dialect="fanuc").segments())


def test_the_linuxcnc_hint_does_not_crash_on_a_huge_literal():
    # a LinuxCNC syntax error's hint parses the line as Fanuc text, which overflowed
    from nczones.gcode import interpret_text
    from nczones.machine import parse_machine

    m = parse_machine(machine_text("x_unit", set={"machine.rapid.X": "1000"}))
    with pytest.raises(GcodeError, match="GC105"):
        list(interpret_text(f"#1=ATAN[{_HUGE}]/[1e3]\nM30\n", m).segments())
