"""An M word's number in the LinuxCNC dialect, as rs274 2.9.0~pre1 reads it (issue 33's leftover ``M[3.00001]``).

LinuxCNC's ``read_m`` reads the number with ``read_integer_value`` (interp_read.cc): ``floor`` of the double,
then ``ceil`` when the rest is above 0.9999, and "Non integer value for integer" when the rest is above 0.0001;
then "Negative m code used" below 0 and "M-code greater than 199" above 199.  The installed rs274 on
``M[...] S100 / G0 X1 / M2`` (``rs274 -g``):

    M[3.00001], M[2.99999], M[3.000001], #1=3.00001 M#1, M[3]  -> SET_SPINDLE_SPEED(0, 100) START_SPINDLE_CLOCKWISE
    M[3.0001] (3.0001 - 3 = 1.00000000000021e-4 in doubles), M[3.4], M[3.5] -> "Non integer value for integer"
    M[-3]                                                      -> "Negative m code used"
    M200, M[199.99995]                                         -> "M-code greater than 199: M200"

each error on the M word's line.  The last is the standalone rs274's: ``read_m`` looks up the INI's remapped M codes
first (LinuxCNC's own configurations remap ``M428``), so an M above 199 stays unknown in nczones, as M100-M199.  nczones refused every non-integer M (GC202), also those LinuxCNC runs.  Through
``verify_text`` on a short program, one with > 512 motions (the vectorized tier) and one with '#' (the double pass).
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest

from nczones.errors import GcodeError
from nczones.machine import parse_machine
from nczones.prover import Verdict, verify_text
from tests.tools.rs274_diff import FINDING_SETUP, RS274, outcome

MACHINE = parse_machine(
    '[machine]\ndialect = "linuxcnc"\naxes = ["X", "Y", "Z"]\n[machine.rapid]\nX = "5000"\nY = "5000"\nZ = "5000"\n'
    '[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n'
    '[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1", Y = "-1", Z = "-1" }\n'
    'max = { X = "100", Y = "100", Z = "1" }\n'
    '[[zones]]\nname = "post"\nkind = "box"\nforbid = true\nmin = { X = "49", Y = "-1", Z = "-1" }\n'
    'max = { X = "51", Y = "1", Z = "1" }\n', "m.toml")

LONG = "".join(f"G1 X{1 + k % 5} Y{10 + k % 3} F500\n" for k in range(600)) + "G0 Y0\n"
SHAPES = {"short": "", "long": LONG, "params": "#1 = 2\nG0 X#1\n"}


def _program(m: str, pre: str) -> str:
    return f"G21 G90 F100\n{pre}{m} S100\nG1 X60\nM2\n"


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("m", ["M[3.00001]", "M[2.99999]", "M[3.000001]", "#2 = 3.00001\nM#2"])
def test_an_m_number_within_0_0001_of_an_integer_is_that_code(m, shape):
    """rs274 runs these as M3: the program then crosses the post at X50 (unsafe, as with a plain M3)."""
    got = verify_text(_program(m, SHAPES[shape]), MACHINE, file="p.ngc")
    plain = verify_text(_program("M3", SHAPES[shape]), MACHINE, file="p.ngc")
    assert got.verdict is plain.verdict is Verdict.UNSAFE
    assert [v.zone for v in got.violations] == [v.zone for v in plain.violations] == ["post"]


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("m,says", [("M[3.0001]", "not an integer"), ("M[3.4]", "not an integer"),
                                    ("M[-3]", "negative M code")])
def test_an_m_number_linuxcnc_refuses_is_refused_on_its_line(m, says, shape):
    text = _program(m, SHAPES[shape])
    with pytest.raises(GcodeError) as e:
        verify_text(text, MACHINE, file="p.ngc")
    d = e.value.diagnostics[0]
    line = text.splitlines().index(f"{m} S100") + 1
    assert d.code == "GC202" and d.span is not None and d.span.line == line and says in d.message, d


@pytest.mark.skipif(not Path(RS274).exists(), reason="rs274 (LinuxCNC's standalone interpreter) not installed")
@pytest.mark.parametrize("m", ["M[3.00001]", "M[2.99999]", "M[3]", "#1 = 3.00001\nM#1", "M[3.0001]", "M[3.4]",
                               "M[-3]"])
def test_rs274_agrees(m):
    """The same programs through rs274 and nczones: the same motion, or both refuse on the same line."""
    with tempfile.TemporaryDirectory() as tmp:
        o = outcome(f"G21 F100\n{m} S100\nG1 X6\nM2\n", FINDING_SETUP, Path(tmp))
    assert o.status == "match", o
