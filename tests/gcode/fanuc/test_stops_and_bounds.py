"""No internal error on program stops, and repeat counts bounded (issue 33, classes 6 and 7).

Class 6: every Fanuc program with ``M00``/``M01`` ended in an internal error (exit 4) in ``verify`` and
``plot``: the Fanuc interpreter recorded its stops as bare line numbers where the report (``_switch_notes``)
reads the LinuxCNC interpreter's ``(code, line)`` pairs.
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from nczones.cli import main
from nczones.machine import load_machine
from nczones.prover import verify_text

ROOT = Path(__file__).resolve().parents[3]
FANUC_MILL = ROOT / "specs" / "machines" / "fanuc_mill.toml"
FANUC_LATHE = ROOT / "specs" / "machines" / "fanuc_lathe.toml"
LINUXCNC_MILL = ROOT / "specs" / "machines" / "mill.toml"


def _fanuc_stops(n_moves: int, far: bool = False) -> str:
    """M00 then M01 around ``n_moves`` feed moves (> 512: the vectorized tier); ``far`` ends 900 mm out in X."""
    moves = "".join(f"G1 X{10 + i % 20}. Y{10 + i % 7}. F100.\n" for i in range(n_moves))
    return ("O1\nG90 G54 G0 X10. Y10. Z10.\nM00\n" + moves + "M01\n#100 = 5.\nG1 X#100\n"
            + ("G1 X900.\n" if far else "") + "M30\n")


@pytest.mark.parametrize("n_moves", [1, 600])
def test_fanuc_m00_m01_verify_names_the_stops(n_moves):
    r = verify_text(_fanuc_stops(n_moves), load_machine(FANUC_MILL))
    assert r.verdict.label == "safe", r.reasons
    note = next(n for n in r.notes if "M0 (program stop)" in n)
    # the stops are at line 3 (M00) and at the line after the moves (M01)
    assert "M1 (optional stop)" in note and f"line(s) 3, {4 + n_moves}" in note, note


def test_fanuc_m00_does_not_hide_a_violation():
    r = verify_text(_fanuc_stops(600, far=True), load_machine(FANUC_MILL))
    assert r.verdict.label == "unsafe" and r.violations[0].line == 4 + 600 + 3


@pytest.mark.parametrize(("dialect", "code"), [
    *((d, "M00") for d in ("fanuc", "fanuc-lathe", "linuxcnc")), ("fanuc", "M01"),
    # the rest of the matrix behind -m long (a second each)
    *(pytest.param(d, c, marks=pytest.mark.long) for d in ("fanuc", "fanuc-lathe", "linuxcnc")
      for c in ("M01", "M30", "M02", "M60") if (d, c) != ("fanuc", "M01"))])
def test_every_command_takes_program_stops(tmp_path, capsys, code, dialect):
    """verify (every report format), plot, simulate and replay end with their documented exit status on a
    program with each stop/end code, never 4.  M60 is a machine function nczones does not model on a Fanuc
    control (unknown: 3; simulate refuses it: 2); on LinuxCNC it is a pallet-change stop (no motion)."""
    if dialect == "fanuc":
        machine, text = FANUC_MILL, f"O1\nG90 G54 G0 X10. Y10. Z10.\n{code}\nG1 X900. F100.\nM30\n"
    elif dialect == "fanuc-lathe":
        # short incremental moves from the reference: the pulse-by-pulse simulation stays quick
        machine, text = FANUC_LATHE, f"O1\nG0 U-2. W-1.\n{code}\nG1 W-1. F0.2\nM30\n"
    else:
        machine, text = LINUXCNC_MILL, f"G21 G90 G54 G0 X10 Y10 Z10\n{code}\nG1 X900 F100\nM2\n"
    prog = tmp_path / ("p.ngc" if dialect == "linuxcnc" else "p.nc")
    prog.write_text(text)
    ends = code in ("M30", "M02")
    unmodelled = code == "M60" and dialect != "linuxcnc"
    # the X900 move leaves the travel of the mills; the lathe program stays inside
    expect = 3 if unmodelled else (0 if ends or dialect == "fanuc-lathe" else 1)
    for fmt in ("text", "json", "html", "sarif"):
        out = tmp_path / f"r.{fmt}"
        assert main(["verify", str(prog), "--machine", str(machine), "--format", fmt, "--output", str(out)]) == expect
    assert main(["plot", str(prog), "--machine", str(machine), "-o", str(tmp_path / "p.svg")]) in (0, 1)
    assert main(["simulate", str(prog), "--machine", str(machine), "--format", "json"]) == (
        2 if unmodelled else (1 if expect == 1 else 0))
    if expect in (0, 1):
        assert main(["replay", str(tmp_path / "r.json")]) == 0
    capsys.readouterr()


# ---------------------------------------------------------------------------------------------------- class 7
# Every repetition counts against --max-iterations (per entry, as loops do): a call's or a cycle's repeat count
# above it ends the interpretation at its block, as unknown, before any repetition is made (nothing of it is
# held in memory); every repetition also asks the run's --budget, so repetitions nested inside each other
# (each within the bound) end within the budget.

SUB = "O2\nG91 G1 X0.001 F100.\nG1 X-0.001\nG90\nM99\n"  # two feed moves that come back: one repeat = 2 motions


def _fanuc(text: str, **kw):
    return verify_text("O1\nG90 G54 G0 X10. Y10. Z10.\n" + text, load_machine(FANUC_MILL), **kw)


def _unknown_at(r, line: int, *words: str):
    assert r.verdict.label == "unknown", r.violations
    reason = r.reasons[0]
    assert reason.span is not None and reason.span.line == line, reason
    for w in words:
        assert w in reason.message, reason.message


@pytest.mark.parametrize("call", ["M98 P2 L99999999", "G65 P2 L99999999", "M98 P99990002", "M97 P100 L99999999"])
def test_a_huge_call_repeat_is_unknown_at_its_block_at_once(call):
    # M98 P99990002: the 0i format P####nnnn, the repeat count 9999 in the digits before the last four
    body = "M30\nN100 G91 G1 X0.001 F100.\nG1 X-0.001\nG90\nM99\n" if call.startswith("M97") else "M30\n" + SUB
    t0 = time.process_time()
    r = _fanuc(f"{call}\n{body}", max_iterations=5000)
    assert time.process_time() - t0 < 10
    _unknown_at(r, 3, "9999", "max_loop_iterations")


@pytest.mark.parametrize("n_motions", [20, 600])  # 600: the vectorized tier
@pytest.mark.parametrize("form", ["M98 P2 L{n}", "M98 P{n:04d}0002", "G65 P2 L{n}"])
def test_the_repeat_count_is_compared_with_max_iterations(form, n_motions):
    """O2 makes 2 motions a repeat; n = n_motions / 2 repeats are allowed by max_iterations = n and refused by
    n - 1 (then nothing of the call runs: the G0 is the only motion checked)."""
    n = n_motions // 2
    call = form.format(n=n)
    ok = _fanuc(f"{call}\nM30\n{SUB}", max_iterations=n)
    assert ok.verdict.label == "safe" and dict(ok.stats)["segments"] == 1 + n_motions, (ok.reasons, ok.stats)
    _unknown_at(_fanuc(f"{call}\nM30\n{SUB}", max_iterations=n - 1), 3, str(n))


@pytest.mark.parametrize("n_holes", [10, 200])  # G81: 3 motions a hole (position, to R, feed) + retract
def test_canned_cycle_k_is_compared_with_max_iterations(n_holes):
    cycle = f"G91 G99 G81 X0.01 Z-1. R-1. K{n_holes} F100.\nG80\nM30\n"
    ok = _fanuc(cycle, max_iterations=n_holes)
    assert ok.verdict.label == "safe", ok.reasons
    _unknown_at(_fanuc(cycle, max_iterations=n_holes - 1), 3, f"K{n_holes}", str(n_holes))


def test_canned_cycle_k99999999_ends_at_once():
    t0 = time.process_time()
    _unknown_at(_fanuc("G91 G81 X0.001 Z-1. R-1. K99999999 F100.\nG80\nM30\n"), 3, "K99999999")
    assert time.process_time() - t0 < 10


def test_peck_count_is_compared_with_max_iterations():
    # G83 from R (Z1 above the part) to Z-9 by Q0.001: 9999 pecks before the last feed, more than 5000
    _unknown_at(_fanuc("G90 G83 X10. Z-9. R1. Q0.001 F100.\nG80\nM30\n", max_iterations=5000), 3, "G83", "9999")


def test_nested_while_loops_end_within_the_budget():
    """Two nested DO loops of 90,000 iterations each are within --max-iterations per entry; 8.1e9 iterations
    would run for days.  The budget (1 s) ends them: unknown (VF203) at a loop line, saying what was counted."""
    text = ("#1 = 0\nWHILE [#1 LT 90000] DO1\n#2 = 0\nWHILE [#2 LT 90000] DO2\n#2 = #2 + 1\nEND2\n#1 = #1 + 1\n"
            "END1\nM30\n")
    t0 = time.process_time()
    r = _fanuc(text, budget_s=1)
    assert time.process_time() - t0 < 15
    assert r.verdict.label == "unknown" and r.reasons[0].code == "VF203", r.reasons
    assert "budget of 1 s" in r.reasons[0].message and "DO2 loop had run" in r.reasons[0].message


def test_a_violating_canned_cycle_block_with_many_holes_ends_within_the_budget():
    """One G81 block of 1,500 holes, 0.001 mm apart, from X84.4 into the clamp (program X 85 to 115 at Y10, the
    clamp's Y -270..-190 in machine coordinates is program Y -20..60): from hole 600 on every hole violates.
    Each violating motion of a block already reported only deepened its depth, exactly, at tens of ms a
    motion (1,200 holes took 47 s, 90,000 holes hours); past the budget the depth stays a lower bound."""
    t0 = time.process_time()
    r = verify_text("O1\nG90 G54 G0 X84.4 Y10. Z10.\nG91 G81 X0.001 Z-1. R-1. K1500 F100.\nG80\nM30\n",
                    load_machine(FANUC_MILL), budget_s=1)
    assert time.process_time() - t0 < 20
    assert r.verdict.label == "unsafe" and any(v.line == 3 and v.zone == "clamp" for v in r.violations)
