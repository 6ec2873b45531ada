"""Offsets written by macro (``#5221 =``, ``#7001 =``, ``#11001 =``, ...) are stored in whole least input
increments, as ``G10`` stores them (its words are rounded as every address word is).

A Fanuc control keeps offsets as whole numbers of the least input increment (IS-B: 0.001 mm, 0.0001 inch,
0.001 deg; B-64304EN "Increment system"), so ``#5221 = 1.23456`` puts G54 X at 1.235, not at 1.23456: a zone
face between the two decides whether the tool enters a zone (finding of n5amb37; specs/fanuc.md, "System
variables").  A value the readings of its double round to different multiples is ``unknown`` (GC399), as a
position word is.
"""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import box_zone, machine_text

from .helpers import mill

XYZC = parse_machine(machine_text("fanuc_xyzc"), "xyzc.toml")


def _run(text: str, machine) -> tuple:
    """``(end points, unsupported codes)`` of a program."""
    run = interpret_text(text, machine, file="t.nc")
    ends = [tuple(s.end) for s in run.segments()]
    return ends, [u.code for u in run.unsupported]


#: (machine, unit line, variable, G10 form, the move that shows the offset): a work offset on X (metric and
#: inch), one on a rotary axis (degrees in both units), a G54.1 offset and the tool length tables.
CASES = {
    "G54 X mm": (mill, "G21", "#5221", "G10 L2 P1 X{v}", "G90 G54 G0 X0 Y0"),
    "G54 X inch": (mill, "G20", "#5221", "G10 L2 P1 X{v}", "G90 G54 G0 X0 Y0"),
    "G55 Y inch": (mill, "G20", "#5242", "G10 L2 P2 Y{v}", "G90 G55 G0 X0 Y0"),
    "G54.1 P3 Z": (mill, "G21", "#7043", "G10 L20 P3 Z{v}", "G90 G54.1 P3 G0 Z0"),
    "C deg": (lambda: XYZC, "G21", "#5224", "G10 L2 P1 C{v}", "G90 G54 G0 C0"),
    "C deg inch": (lambda: XYZC, "G20", "#5224", "G10 L2 P1 C{v}", "G90 G54 G0 C0"),
    "H1 geometry": (mill, "G21", "#11001", "G10 L10 P1 R{v}", "G90 G54 G0 G43 H1 Z0"),
    "H2 wear inch": (mill, "G20", "#10002", "G10 L11 P2 R{v}", "G90 G54 G0 G43 H2 Z0"),
}


def _twins(case: str, v: str) -> tuple[str, str]:
    _m, units, var, g10, move = CASES[case]
    return f"{units}\n{var} = {v}\n{move}\n", f"{units}\n{g10.format(v=v)}\n{move}\n"


def _step(case: str) -> Fraction:
    """The increment an offset of ``case`` is kept in, in program units (IS-B)."""
    rotary = case.startswith("C ")
    return Fraction(1, 10000) if CASES[case][1] == "G20" and not rotary else Fraction(1, 1000)


@settings(max_examples=60, deadline=None)
@given(case=st.sampled_from(sorted(CASES)), digits=st.integers(4, 6), n=st.integers(0, 3_000_000),
       sign=st.sampled_from([1, -1]), through_variable=st.booleans())
def test_a_macro_offset_write_and_its_g10_twin_move_alike(case, digits, n, sign, through_variable):
    v = format(Decimal(sign * n).scaleb(-digits), "f")
    machine = CASES[case][0]()
    if through_variable:  # the same double in both: both rounded by round_to, both unknown at a split half
        by_macro, by_g10 = (f"#1 = {v}\n" + t.replace(f"= {v}", "= #1").replace(f"{v}\n", "#1\n")
                            for t in _twins(case, v))
        assert "#1\n" in by_g10 and "= #1\n" in by_macro
        assert _run(by_macro, machine) == _run(by_g10, machine)
        return
    by_macro, by_g10 = _twins(case, v)
    macro, g10 = _run(by_macro, machine), _run(by_g10, machine)
    assert not g10[1], g10
    if macro[1]:
        # the literal in G10 is a decimal (no double to read); the macro value is a double: only at a half
        # increment may its readings split
        assert macro[1] == ["GC399"], macro
        assert (Fraction(v) / _step(case)).denominator == 2, (v, macro)
        return
    assert macro == g10


def test_the_offset_is_stored_rounded_not_as_written():
    # fails on storing the exact value: G54 X = 100 + ... here the offset alone, 1.23456 -> 1.235 (IS-B mm)
    ends, unsupported = _run("#5221 = 1.23456\nG90 G54 G0 X0\n", mill())
    assert not unsupported and ends[-1][0] == Fraction("1.235")
    ends, unsupported = _run("G20\n#5221 = 0.04861\nG90 G54 G0 X0\n", mill())  # 0.0486 in, not 0.04861
    assert not unsupported and ends[-1][0] == Fraction("0.0486") * Fraction("25.4")
    ends, unsupported = _run("#11001 = 20.0004\nG90 G54 G0 G43 H1 Z0\n", mill())  # length 20.000
    assert not unsupported and ends[-1][2] == -200 + 1 + Fraction(20)  # G54 Z, EXT Z, H1


def test_an_offset_at_a_split_half_is_unknown():
    # 1.5 * 1.017: its 15-digit decimal 1.5255 rounds to 1.526, the double times 1000 to 1.525 (N5)
    _ends, unsupported = _run("#5221 = 1.5 * 1.017\nG90 G54 G0 X0\n", mill())
    assert unsupported == ["GC399"]


#: fanuc_finding_mill (travel X 0..100, G54 zero, start at X50 Y50): the offset written by macro, then a feed
#: across a clamp whose face (min X) lies between the value written and the increment the control keeps.
_PROGRAM = "{units}\n#5221 = {v}\nG21 G61 G90 G54 G0 X0 Y50.\nG1 Y70. F100\n"


@pytest.mark.parametrize(("units", "v", "face", "label"), [
    ("G21", "1.23456", "1.2348", "unsafe"),  # exact 1.23456 before the face; the control's 1.235 past it
    ("G21", "1.23436", "1.2342", "safe"),  # exact 1.23436 past the face; the control's 1.234 before it
    ("G20", "0.04861", "1.2346", "safe"),  # 0.04861 in = 1.234694 mm past; 0.0486 in = 1.23444 mm before
    ("G20", "0.04866", "1.2357", "unsafe"),  # 1.235964 mm past either way: the control's 0.0487 in = 1.23698
])
def test_a_zone_face_between_the_value_and_its_increment(units, v, face, label):
    clamp = box_zone("clamp", {"X": face, "Y": "60", "Z": "0"}, {"X": "40", "Y": "80", "Z": "200"}, forbid=True)
    machine = parse_machine(machine_text("fanuc_finding_mill", extra=clamp), "clamp.toml")
    r = verify_text(_PROGRAM.format(units=units, v=v), machine)
    assert r.verdict.label == label, r.verdict
    if label == "unsafe":
        assert r.violations[0].zone == "clamp"
