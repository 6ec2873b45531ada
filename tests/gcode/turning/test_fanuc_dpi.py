"""Lathe cycles under ``decimal_point_input = "increment"`` (parameter 3401#0 DPI = 0, the factory setting).

Only length words are counts of least input increments when written without a decimal point.  The words of
the lathe cycles that are not lengths ([0i-T] FANUC Series 0i-TD Operator's Manual B-64304EN, "Multiple
repetitive cycle"):

* G70-G73 ``P(ns) Q(nf)``: sequence numbers of the finishing shape's first and last blocks;
* G73 first block ``G73 U(Δi) W(Δk) R(d)``: d "the number of divisions" (a count);
* G74/G75 ``P(Δi) Q(Δk)`` and G76 ``Q(Δdmin)``, ``P(k) Q(Δd)``: "specified without a decimal point", in
  least input increments whatever the DPI setting (the cycle scales them itself);
* the one-block G71 (Haas) ``R1``: type II (a flag).

Each of these reads the same under DPI = 0 and DPI = 1; the note "length word without a decimal point"
names none of them.  Before the fix ``G71 P10 Q20`` read Q20 as 0.02 mm and stopped with GC209 (exit 2).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from nczones.machine import load_machine
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.turning.helpers import lathe, moves, unknown_reason

ROOT = Path(__file__).resolve().parents[3]
G71_JAWS = (ROOT / "specs/examples/programs/g71_jaws.nc").read_text()


def _dpi(machine, mode: str):
    return replace(machine, fanuc=replace(machine.fanuc, decimal_point_input=mode))


def _first_line(result) -> int:
    return min(v.span.line for v in result.violations)


@pytest.mark.parametrize("long", [False, True], ids=["short", "vectorized"])
def test_bundled_g71_jaws_is_unsafe_under_dpi_zero(long):
    # specs/examples/examples.toml: g71_jaws.nc on fanuc_lathe.toml is unsafe, first at line 7 (the G71 block),
    # zone "jaws".  Its only words without a decimal point are P10 Q20 (sequence numbers), so DPI = 0 must give
    # the same verdict.  The long variant adds 600 moves after the cycle (the vectorized tier, > 512 motions).
    text = G71_JAWS
    if long:
        tail = "".join(f"G01 X{200 + (i % 2)}. Z{100 + (i % 7)}.\n" for i in range(600))
        text = text.replace("M30\n", tail + "M30\n")
    # (the calculator setting is the example's own machine file: tests/prover/test_examples.py)
    base = load_machine(ROOT / "specs/machines/fanuc_lathe.toml")
    r = verify_text(text, _dpi(base, "increment"), file="g71_jaws.nc")
    assert r.verdict is Verdict.UNSAFE, (r.verdict, r.reasons)
    assert _first_line(r) == 7 and {v.zone for v in r.violations} == {"jaws"}
    assert not any("without a decimal point" in n for n in r.notes), r.notes


G71_SHAPE = "N10 G00 X30.\nG01 Z-20.\nX40. Z-30.\nN20 Z-40.\n"
G73_SHAPE = "N10 G00 X20. Z0\nG01 X40. Z-10.\nN20 Z-20.\n"

CASES = {
    # the two-block G71 (P Q sequence numbers)
    "G71": "G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20 U2. W0.5 F0.2\n" + G71_SHAPE + "G00 X100.\n",
    # G73 R3: three divisions, not 0.003 mm
    "G73": "G00 X60. Z5.\nG73 U4. W0 R3\nG73 P10 Q20 U0 W0 F0.2\n" + G73_SHAPE,
    # G70 P Q
    "G70": "G00 X60. Z5.\nG70 P10 Q20 F0.1\nG00 X100.\nM30\n" + G73_SHAPE,
    # G74 Q2000 and G75 P2000 Q1000 are least increments under either setting (2 mm, 1 mm)
    "G74": "G00 X0 Z1.\nG74 R0.5\nG74 Z-4. Q2000 F0.1\n",
    "G75": "G00 X50. Z-10.\nG75 R0.5\nG75 X40. Z-12. P2000 Q1000 F0.1\n",
    # G76 P010060 Q100 R0. then P1300 Q500
    "G76": "G00 X32. Z5.\nG76 P010060 Q100 R0.\nG76 X27.4 Z-20. P1300 Q500 F1.5\n",
    # the one-block (Haas) G71 with R1: type II; D with a decimal point
    "G71 R1": "G00 X50. Z2.\nG71 P10 Q20 D5. R1 F0.2\n" + G71_SHAPE,
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_cycle_counts_and_sequence_numbers_do_not_depend_on_dpi(name):
    prog = CASES[name]
    fanuc = 'g71_retract = "1"\ng74_retract = "0.5"\nthread_chamfer = "0"'
    calc = moves(prog, lathe(fanuc=fanuc + '\ndecimal_point_input = "calculator"'))
    inc = moves(prog, lathe(fanuc=fanuc + '\ndecimal_point_input = "increment"'))
    assert len(calc) > 3
    assert inc == calc


def test_note_counts_only_length_words():
    # X100 (a length without a point) is counted; P10 Q20 (sequence numbers) and R3 (divisions) are not
    m = lathe(fanuc='decimal_point_input = "increment"', zones="")
    r = verify_text("G00 X60. Z5.\nG73 U4. W0 R3\nG73 P10 Q20 U0 W0 F0.2\n" + G73_SHAPE + "G00 X100\nM30\n", m)
    notes = [n for n in r.notes if "without a decimal point" in n]
    assert len(notes) == 1 and notes[0].startswith("1 length word ") and "X100" in notes[0], notes


def test_thread_start_angle_q_is_not_a_length():
    # [0i-T] "Thread cutting (G32)": Q is the threading start angle shift in 0.001 deg, without a decimal point;
    # G92's Q the same.  Not a length: the note does not count it.
    m = lathe(fanuc='decimal_point_input = "increment"\nthread_chamfer = "0"')
    prog = "G00 X40. Z5.\nG32 Z-20. F1.5 Q180000\nG00 X60.\nZ5.\nG92 X38. Z-20. F1.5 Q90000\nM30\n"
    r = verify_text(prog, m)
    assert not any("without a decimal point" in n for n in r.notes), r.notes


def test_one_block_g71_depth_without_a_decimal_point_is_unknown():
    # Haas reads D in mm (D0.15), the FS10/11 / FS15 tape formats in least input increments: not known which
    fanuc = 'g71_retract = "1"'
    why = unknown_reason("G00 X50. Z2.\nG71 P10 Q20 D5 F0.2\n" + G71_SHAPE, lathe(fanuc=fanuc))
    assert "D5" in why and "decimal point" in why


def test_one_block_g73_with_divisions_d_is_unknown():
    why = unknown_reason("G00 X60. Z5.\nG73 P10 Q20 I4. K0 U0 W0 D3 F0.2\n" + G73_SHAPE, lathe(
        fanuc='g73_relief_x = "5"\ng73_relief_z = "0"\ng73_divisions = 2'))
    assert "one-block" in why


def test_cli_exit_status_of_the_bundled_program_under_dpi_zero(tmp_path, capsys):
    # the reported symptom: exit 2 (GC209 "Q20 ... sequence number") with DPI = 0; now exit 1 (unsafe) as
    # with DPI = 1
    from nczones.cli import main

    text = (ROOT / "specs/machines/fanuc_lathe.toml").read_text()
    machine = tmp_path / "lathe_dpi0.toml"
    machine.write_text(text.replace("[fanuc]\n", '[fanuc]\ndecimal_point_input = "increment"\n'))
    prog = str(ROOT / "specs/examples/programs/g71_jaws.nc")
    assert main(["verify", prog, "--machine", str(machine)]) == 1
    out = capsys.readouterr().out
    assert "violation[jaws]" in out and "GC209" not in out
