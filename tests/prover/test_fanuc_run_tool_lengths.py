"""A Fanuc cutting-mode run whose middle motions carry another tool length (a G43/G49 inside the run).

A Fanuc control in cutting mode (G64) keeps the path inside the convex hull of the motions since the last exact
stop (specs/path-modes.md §3), and the proof tests that hull (its box) as a whole.  A tip zone sees the machine
point less the tool length; where the two motions of a LinuxCNC corner have different lengths, the corner is
tested at both.  The run's hull was tested at the lengths of its FIRST and LAST motions only: a run
``G49 ... G43 H1 ... G49`` had its hull never tested at H1, and a tip probe the hull reaches only at H1 was
proved ``safe`` (found by hunt36; both the one-motion lane and the column runs of issue 36 did it).

The geometry (test mill: G54 = (100, 50, -200), H1 = 100; Fanuc G43 adds H to the programmed Z): after
``G00 X0. Y0. Z0.`` and a dwell (an exact stop), the run is

- ``G01 X100.``: machine (100, -200) -> (200, -200) in X, Z, tool length 0;
- ``G43 H1 Z200.``: machine Z = 200 - 200 + 100 = 100, X 200: (200, -200) -> (200, 100), length 100;
- ``G49 X0.``: machine Z = 200 - 200 = 0, X 100: (200, 100) -> (100, 0), length 0,

closed by a dwell.  Its hull's box is X 100..200, Z -200..100 (machine).  The probe forbids the tip in X 140..160,
Z -260..-240.  At length 0 the hull's tip Z is -200..100: it misses the probe; at length 100 it is -300..0, which
holds the probe's Z, and X 140..160 lies in 100..200: the hull at H1 meets the probe.  Each motion on its own
misses it (the first at tip Z -200, the second at X 200, the third's tip from (200, 100) to (100, 0) above -200),
so the verdict is decided by the run's hull alone: not ``safe``.  Written with ``G61`` before the run (exact stops
between the motions: no hull) it is ``safe``, the control case.
"""

from __future__ import annotations

import pytest

from nczones.prover import verify_text
from nczones.prover.blend import CornerCheck
from tests.gcode.fanuc.helpers import mill

_ZONES = """
[[zones]]
name = "travel"
kind = "box"
min = { X = "-1000", Y = "-1000", Z = "-1000" }
max = { X = "1000", Y = "1000", Z = "1000" }
[[zones]]
name = "probe"
kind = "box"
forbid = true
point = "tip"
min = { X = "140", Y = "-1000", Z = "-260" }
max = { X = "160", Y = "1000", Z = "-240" }
"""

_RUN = "G01 X100.\nG43 H1 Z200.\nG49 X0.\n"


def _program(pad: str, mode: str = "") -> str:
    """The run after ``pad`` (motions far from the probe, each group ended by a dwell)."""
    return ("O1\nG90 G17 G21 G54 G49 F500.\n" + pad + "G00 X0. Y0. Z0.\nG04 X0\n" + mode + _RUN + "G04 X0\nG64\n"
            + "M30\n")


def _loop(n: int) -> str:
    """A WHILE loop of ``n`` motions and dwells in the machine's box far from the probe (tip Z >= -200)."""
    return f"#1 = 0\nWHILE [#1 LT {n}] DO1\nG01 X[#1 MOD 7] Y5.\nG04 X0\n#1 = #1 + 1\nEND1\n"


def _plain(n: int) -> str:
    return "".join(f"G01 X{k % 7}. Y5.\n" for k in range(n)) + "G04 X0\n"


def _long_run(n: int) -> str:
    """The run inside a long run of straight moves: ``n`` moves on the line Z0 before it (a column chunk's rows
    past the first 512 motions, in one group with the run's G43/G49)."""
    return f"#1 = 0\nWHILE [#1 LT {n}] DO1\nG01 X[#1 MOD 2 * 100]\n#1 = #1 + 1\nEND1\n"


_CASES = {
    "short": "",
    "plain 600": _plain(600),  # past the proof's 512-motion tier, no macro (the fast path may take it)
    "loop 600": _loop(300),  # 600 motions and dwells of a WHILE loop first (the full interpreter's chunks)
}


@pytest.mark.parametrize("pad", list(_CASES))
def test_a_tool_length_inside_a_run_is_tested(pad):
    m = mill(tables=_ZONES)
    got = verify_text(_program(_CASES[pad]), m)
    assert got.verdict.label == "unknown", got.verdict
    assert any("VF208" in r.message and "inside `probe`" in r.message for r in got.reasons)
    assert verify_text(_program(_CASES[pad], "G61\n"), m).verdict.label == "safe"


def test_a_tool_length_inside_a_column_run(monkeypatch):
    """The run as rows of a column chunk (the interpreter's run of straight moves past 512 motions, taken by
    the corner check's hull lane): the rows before it on the line Z0 (machine Z -200, X 100..200) are inside the
    run's box already."""
    m = mill(tables=_ZONES)
    text = ("O1\nG90 G17 G21 G54 G49 F500.\n" + _loop(300) + "G00 X0. Y0. Z0.\nG04 X0\n" + _long_run(200) + _RUN
            + "G04 X0\nM30\n")
    taken: list[int] = []
    real = CornerCheck._hull_columns

    def spy(self, chunk, at):
        taken.append(len(chunk))
        return real(self, chunk, at)

    monkeypatch.setattr(CornerCheck, "_hull_columns", spy)
    got = verify_text(text, m)
    assert taken and max(taken) >= 200, taken
    assert got.verdict.label == "unknown", got.verdict
    assert any("VF208" in r.message and "inside `probe`" in r.message for r in got.reasons)
