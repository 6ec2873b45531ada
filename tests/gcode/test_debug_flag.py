"""``#5599``, LinuxCNC's (DEBUG,) output flag, is an ordinary parameter that starts at 1 (issue 38).

LinuxCNC's manual: "#5599 - Flag for controlling the output of (DEBUG,) statements. 1=output, 0=no output;
default=1" (volatile).  ``rs274 -g`` on ``G0 X[#5599]`` / ``#5599 = 0`` / ``G0 X[#5599 + 3]`` prints
``STRAIGHT_TRAVERSE(1.0000, ...)`` then ``STRAIGHT_TRAVERSE(3.0000, ...)``: it reads 1 before any
assignment and the assigned value after.  nczones made every program that sets it (shops set it at the top of
programs and subroutines) unknown (GC395).  Checked here in every lane: the full interpreter, the double pass
(the programs hold '#'), and the vectorized tier (> 512 motions).
"""

from __future__ import annotations

import shutil
from fractions import Fraction
from pathlib import Path

import pytest

from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.machine import load_machine
from nczones.prover import verify_text
from nczones.prover.core import Verdict

MILL = load_machine(Path(__file__).resolve().parents[2] / "specs" / "machines" / "mill.toml")
# mill.toml: travel X 0..600 in machine coordinates, G54 X = 150: program X > 450 leaves the travel box.
# X[#5599 * 500] is program X500 (machine 650, unsafe) when #5599 = 1, program X0 (machine 150) when it is 0.
HEAD = "G21 G90 G54 G17\n"


def _program(set_flag: str, filler: int = 0) -> str:
    moves = "".join(f"G1 X[{(k % 7) + 10} + #5599] Y20 Z50 F1000\n" for k in range(filler))
    return HEAD + "G0 Z200\n" + set_flag + moves + "G0 X[#5599 * 500]\nM2\n"


def _end_x(text: str) -> Fraction:
    run = interpret_text(text, MILL)  # the full interpreter
    assert not run.unsupported, run.unsupported
    segs = [s for c in run for s in c.segments()]
    return segs[-1].end[0]


@pytest.mark.parametrize("filler", [0, 600])
def test_the_flag_starts_at_1_and_reads_what_was_assigned(filler):
    default = _program("", filler)
    off = _program("#5599 = 0\n", filler)
    on = _program("#5599 = 1 (turn on debug output)\n(DEBUG, flag is #5599)\n", filler)
    assert _end_x(default) == 650 and _end_x(on) == 650  # program X500 + G54 150, as rs274 reads #5599 = 1
    assert _end_x(off) == 150
    for text, verdict in ((default, Verdict.UNSAFE), (on, Verdict.UNSAFE), (off, Verdict.SAFE)):
        r = verify_text(text, MILL)  # '#' in the text: the double pass; 600 more motions: the vectorized tier
        assert r.verdict == verdict, [str(x) for x in r.reasons]
        if verdict == Verdict.UNSAFE:
            assert r.violations[0].line == text.count("\n") - 1  # the G0 X[#5599 * 500] line
        if "DEBUG" not in text:  # a (DEBUG,) comment sends a program to the full path (a magic comment)
            path = double_pass(text, MILL, max_iterations=1000)  # the double pass takes it (does not decline)
            assert path is not None


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
def test_rs274_reads_the_flag_as_nczones_does(tmp_path):
    from tests.tools.rs274_diff import run_rs274

    for set_flag, want in (("", 500), ("#5599 = 0\n", 0), ("#5599 = 1\n", 500)):
        text = _program(set_flag)
        # a fresh tool table and parameter file in tmp_path, no offsets: machine X = program X
        moves, error, log = run_rs274(text, (("X", "Y", "Z"), {}, {}), tmp_path)
        assert error is None and moves, log
        assert moves[-1].end[0] == want
        assert _end_x(text) - 150 == want  # nczones: the same program X, plus mill.toml's G54 X150
