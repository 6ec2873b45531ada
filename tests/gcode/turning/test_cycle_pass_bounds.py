"""No lathe cycle is unbounded (issue 33, class 7): the passes of G71-G76 (Fanuc) and G70-G72 (LinuxCNC).

A multiple repetitive cycle expands one block into passes whose number follows from its words: Fanuc
``G71 U0.001 R0.0005`` from X800 (the bundled ``g71_jaws.nc`` with those edits) ran past 120 s and 446 MB
with ``--budget 5``.  Every pass now counts against ``--max-iterations`` (before any pass is made where the
count is known up front) and asks ``--budget``: past either, ``unknown`` at the cycle's block, naming the count
(or VF203 for the budget).  The counts expected below are derived from the manuals' rules by hand, beside each
test; the runs that would not end without the bound are CLI subprocesses with a timeout.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

from nczones.machine import load_machine
from nczones.prover import verify_text

ROOT = Path(__file__).resolve().parents[3]
FANUC_LATHE = ROOT / "specs" / "machines" / "fanuc_lathe.toml"
LC_LATHE = ROOT / "specs" / "machines" / "lathe.toml"
JAWS = (ROOT / "specs" / "examples" / "programs" / "g71_jaws.nc").read_text()


def _verify(text: str, machine: Path, **kw):
    return verify_text(text, load_machine(machine), **kw)


def _bounded_at(r, line: int, *words: str) -> None:
    assert r.verdict.label == "unknown", r.violations
    reason = r.reasons[0]
    assert reason.span is not None and reason.span.line == line, reason
    for w in words:
        assert w in reason.message, reason.message


def _not_bounded(r) -> None:
    assert not any("max_loop_iterations" in x.message or x.code == "VF203" for x in r.reasons), r.reasons


def _cli(path: Path, machine: Path, *options: str, timeout: float = 90) -> tuple[int, str, float]:
    t0 = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "nczones", "verify", str(path), "--machine", str(machine), *options],
                       capture_output=True, text=True, timeout=timeout, cwd=ROOT)
    return p.returncode, p.stdout + p.stderr, time.perf_counter() - t0


# ------------------------------------------------------------------------------------------------ Fanuc


@pytest.mark.parametrize("depth, passes", [
    # A = X80 (diameter) = radius 40; the shape's lowest point X30 moved by the allowance U0.4 (diameter, 0.2 in
    # radius) is radius 15.2; levels 40 - k * depth above it (0i-TD "Stock removal in turning"):
    # U3.: 40 - 3k > 15.2, k < 8.27, so 8 passes (4 motions each: 32 + the rest, the short tier);
    ("3.", 8),
    # U0.18: 40 - 0.18k > 15.2, k < 137.8, so 137 passes, ~550 motions (the vectorized tier; ~9 s: long)
    pytest.param("0.18", 137, marks=pytest.mark.long),
])
def test_fanuc_g71_passes_are_compared_with_max_iterations(depth, passes):
    text = JAWS.replace("G71 U3. R1.", f"G71 U{depth} R1.")
    _not_bounded(_verify(text, FANUC_LATHE, max_iterations=passes))
    _bounded_at(_verify(text, FANUC_LATHE, max_iterations=passes - 1), 7, "G71", f"{passes} roughing passes",
                "max_loop_iterations")


PRE = "%\nO1\nG21 G18 G99\nT0101\n"


@pytest.mark.parametrize("cycle, count, what", [
    # G73 R3: three divisions, three passes (0i-TD "Pattern repeating")
    ("G00 X60. Z5.\nG73 U4. W0 R3\nG73 P10 Q20 U0 W0 F0.2\nG00 X100. Z20.\nM30\n"
     "N10 G00 X20. Z0\nG01 X40. Z-10.\nN20 Z-20.\n", 3, "pattern passes"),
    # G74 from Z1 to Z-4 by Q2000 (2 mm in least increments of 0.001): ceil(5 / 2) = 3 pecks at one position
    ("G00 X0 Z1.\nG74 R0.5\nG74 Z-4. Q2000 F0.1\nG00 X100. Z20.\nM30\n", 3, "pecks in all"),
    # G75 from X50 (radius 25) to X40 (radius 20) by P2000 (2 mm): 3 pecks; Z-10 to Z-12 by Q1000 (1 mm):
    # 1 + 2 = 3 positions; 9 pecks in all
    ("G00 X50. Z-10.\nG75 R0.5\nG75 X40. Z-12. P2000 Q1000 F0.1\nG00 X100. Z20.\nM30\n", 9, "pecks in all"),
    # G76 P010060 Q100 R0, height P1300 (1.3 mm), first depth Q500 (0.5 mm): depths 0.5 sqrt(n) (at least 0.1
    # more each) below 1.3: 0.5, 0.707, 0.866, 1.0, 1.118, 1.225 (n = 1..6; n = 7 gives 1.323), then m = 01
    # finishing pass: 7 passes (tests/gcode/turning/test_fanuc_cycles.py derives the same passes)
    ("G00 X32. Z5.\nG76 P010060 Q100 R0\nG76 X27.4 Z-20. P1300 Q500 F2.\nG00 X100. Z20.\nM30\n", 7,
     "thread passes"),
])
def test_fanuc_cycle_passes_are_compared_with_max_iterations(cycle, count, what):
    text = PRE + cycle
    line = 7
    _not_bounded(_verify(text, FANUC_LATHE, max_iterations=count))
    _bounded_at(_verify(text, FANUC_LATHE, max_iterations=count - 1), line, f"{count} {what}")


def test_fanuc_g71_with_a_tiny_depth_ends_at_once(tmp_path):
    """The reproducer: G71 U0.001 R0.0005 from X800 is ~385,000 passes (radius 400 down to 15.2 by 0.001): more
    than the default --max-iterations (100,000), refused before any pass is made."""
    prog = tmp_path / "g71_tiny.nc"
    prog.write_text(JAWS.replace("X80. Z2.", "X800. Z2.").replace("G71 U3. R1.", "G71 U0.001 R0.0005"))
    rc, out, secs = _cli(prog, FANUC_LATHE, "--budget", "5")
    assert secs < 60 and "roughing passes, more than 100000" in out and ":7:" in out, out
    assert rc != 4 and "Traceback" not in out


def test_fanuc_g71_within_max_iterations_ends_within_the_budget(tmp_path):
    """The same cycle allowed by --max-iterations 1000000: the budget (1 s) ends it as unknown (VF203) at line 7."""
    prog = tmp_path / "g71_tiny.nc"
    prog.write_text(JAWS.replace("X80. Z2.", "X800. Z2.").replace("G71 U3. R1.", "G71 U0.001 R0.0005"))
    rc, out, secs = _cli(prog, FANUC_LATHE, "--budget", "1", "--max-iterations", "1000000")
    assert secs < 60 and "unknown[VF203]" in out and "G71 had made" in out, out
    assert rc != 4 and "Traceback" not in out


# ------------------------------------------------------------------------------------------------ LinuxCNC

LC = """G18 G21 G8 F100
G0 X20 Z5
o1 sub
G1 X4
Z-10
X10
o1 endsub
{cycle}
G0 X20 Z5
M2
"""


@pytest.mark.parametrize("hash_", ["", "#1 = 1\n"])  # '#': the double pass is tried first
def test_linuxcnc_g71_passes_are_compared_with_max_iterations(hash_):
    """G71 Q1 X10 Z1 I0.5 on the profile (Z1 X4) (Z-10 X4) (Z-10 X10): as with I2 (levels 10, 8, 6, then the
    profile's bottom 4 is followed: tests/gcode/turning/test_linuxcnc_g7x.py derives these passes) the cuts are at the
    levels 10 - 0.5 k above 4 (radius), k = 0..11: 12 cuts.  (The profile's 3 lines count too, GC392.)"""
    text = hash_ + LC.format(cycle="G71 Q1 X10 Z1 D0 I0.5 R0.5")
    line = 8 + bool(hash_)
    _not_bounded(_verify(text, LC_LATHE, max_iterations=12))
    _bounded_at(_verify(text, LC_LATHE, max_iterations=11), line, "G71", "12 roughing passes", "max_loop_iterations")


@pytest.mark.parametrize("hash_", ["", "#1 = 1\n"])
def test_linuxcnc_g71_many_passes(hash_):
    """I0.02 from X10 to the bottom X4: about 300 cuts, ~1,200 motions (the vectorized tier): within the default
    bound; refused by --max-iterations 100."""
    text = hash_ + LC.format(cycle="G71 Q1 X10 Z1 D0 I0.02 R0.5")
    line = 8 + bool(hash_)
    r = _verify(text, LC_LATHE)
    _not_bounded(r)
    assert dict(r.stats)["segments"] > 1000, r.stats
    _bounded_at(_verify(text, LC_LATHE, max_iterations=100), line, "G71", "roughing passes")


def test_linuxcnc_g70_passes_are_counted_before_any_is_made():
    """G70 P5: int(5) = 5 finishing passes (interp_g7x.cc do_g70); P99999999 is refused at once."""
    text = LC.format(cycle="G70 Q1 X10 Z1 D1 E0 P5")
    _not_bounded(_verify(text, LC_LATHE, max_iterations=5))
    _bounded_at(_verify(text, LC_LATHE, max_iterations=4), 8, "G70", "5 finishing passes")
    _bounded_at(_verify("#1 = 1\n" + text, LC_LATHE, max_iterations=4), 9, "G70", "5 finishing passes")
    t0 = time.process_time()
    _bounded_at(_verify(LC.format(cycle="G70 Q1 X10 Z1 D1 E0 P99999999"), LC_LATHE), 8, "99999999 finishing passes")
    assert time.process_time() - t0 < 20


def test_linuxcnc_g71_levels_are_counted_before_any_pass_is_made(tmp_path):
    """I0.0001 from X10 down to the profile's bottom X4: the levels 10 - 0.0001 k above 4, k = 0..59999, are 60,000
    cuts; --max-iterations 1000 refuses the cycle before any pass is made, with a lower bound of the count (the
    levels are doubles: one of slack)."""
    prog = tmp_path / "g71.ngc"
    prog.write_text(LC.format(cycle="G71 Q1 X10 Z1 D0 I0.0001 R0.5"))
    rc, out, secs = _cli(prog, LC_LATHE, "--max-iterations", "1000")
    assert "G71: the cycle would make at least 59999 roughing passes, more than 1000" in out and ":8:" in out, out
    assert rc == 3 and secs < 30


def test_linuxcnc_g71_within_max_iterations_ends_within_the_budget(tmp_path):
    """I0.0001 from X10 to X4: ~60,000 cuts, within --max-iterations 1000000: the budget ends it as unknown
    (VF203).  0.05 s: interpreting 60,000 cuts takes longer on any machine (a 1 s budget was not reached on
    a quiet one, and the exact tiers then proved all 300,007 segments in 50 s)."""
    prog = tmp_path / "g71.ngc"
    prog.write_text(LC.format(cycle="G71 Q1 X10 Z1 D0 I0.0001 R0.5"))
    rc, out, secs = _cli(prog, LC_LATHE, "--budget", "0.05", "--max-iterations", "1000000")
    assert secs < 60 and "unknown[VF203]" in out and "G71 had made" in out, out
    assert rc != 4 and "Traceback" not in out
