"""A macro value at half an increment whose readings round apart (GC399, N5) on every Fanuc lane.

The decision is the language layer's (``round_to`` in nczones/gcode/fanuc/expr.py): a lane that takes the line
(the kept closures of a line with expressions, the G65 argument closure, the plain lane, the box route, its run
reader) must not prove what the general path calls ``unknown``.  Each program here has the ambiguous value on a
line a lane could take, and a far zone face: with every lane on or off the verdict is ``unknown`` with GC399 at
that line, never ``safe``; so with a parameter range (the lanes that track ranges).  Each program with 1.016 in place of 1.017 (1.524: no half) is ``safe`` on the same
machine, so the programs are ones the lanes prove.
"""

from __future__ import annotations

import pytest

from nczones.machine import parse_machine
from tests.machines import machine_text

_MACHINE = machine_text("fanuc_finding_mill", set={"offsets.G54": {"X": "50", "Y": "0", "Z": "0"}})
_HEAD = "O1000\nG21 G90 G54 G17 G40 G80 G94 F100.\nG00 X0 Y50. Z100.\n"

#: name -> (program, line of the ambiguous value)
PROGRAMS = {
    "plain line": (_HEAD + "#101 = 1.017\nG01 X[1.5 * #101]\nG01 X0\nM30\n", 5),
    "no variable": (_HEAD + "G01 X[1.5 * 1.017]\nG01 X0\nM30\n", 4),
    # the line runs again (kept as a closure from its second run): 1.016 on two passes, 1.017 on the third
    "loop": (_HEAD + "#1 = 0\n#101 = 1.016\nWHILE [#1 LT 3] DO1\nG01 X[1.5 * #101]\nG01 X0\n"
             "IF [#1 EQ 1] THEN #101 = 1.017\n#1 = #1 + 1\nEND1\nM30\n", 7),
    "G65 argument": (_HEAD + "#101 = 1.017\nG65 P9001 X[1.5 * #101]\nM30\nO9001\nG01 X#24\nG01 X0\nM99\n", 5),
    "G65 argument in a loop": (_HEAD + "#1 = 0\n#101 = 1.016\nWHILE [#1 LT 3] DO1\nG65 P9001 X[1.5 * #101]\n"
                               "IF [#1 EQ 1] THEN #101 = 1.017\n#1 = #1 + 1\nEND1\nM30\nO9001\nG01 X#24\nG01 X0\n"
                               "M99\n", 7),
    "ROUND in the address": (_HEAD + "#101 = 1.017\nG01 X[ROUND[1.5 * #101]]\nG01 X0\nM30\n", 5),
    "incremental": (_HEAD + "#101 = 1.017\nG91 G01 X[1.5 * #101]\nG90 G01 X0\nM30\n", 5),
}


def _report(text: str, **options) -> tuple:
    from nczones.prover import verify_text

    r = verify_text(text, parse_machine(_MACHINE, "m.toml"), file="t.nc", **options)
    return r.verdict.label, tuple((x.code, x.span.line if x.span else None, x.message) for x in r.reasons)


def _lanes_off(monkeypatch) -> None:
    """The plain lane, the box run reader and the kept closures off: the general path alone."""
    from nczones.gcode.fanuc import boxrun
    from nczones.gcode.fanuc.interpreter import FanucInterpreter
    from nczones.gcode.fanuc.program import FanucRunner

    monkeypatch.setattr(boxrun, "BOX_RUNS", False)
    monkeypatch.setattr(FanucInterpreter, "lane", lambda self, *args: 0)

    def none(self, source, pos, lineno, entry):
        source.ops[pos] = None

    monkeypatch.setattr(FanucRunner, "add_op", none)


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_every_lane_says_unknown_where_the_readings_split(name, monkeypatch):
    text, line = PROGRAMS[name]
    on = _report(text)
    assert on[0] == "unknown" and on[1][0][:2] == ("GC399", line), on
    ranged = _report(text, params=("H1=49..51",))  # tracked dependencies: the lanes that carry ranges
    assert ranged[0] == "unknown" and ranged[1][0] == on[1][0], ranged
    assert _report(text.replace("1.017", "1.016"))[0] == "safe"
    _lanes_off(monkeypatch)
    assert _report(text) == on
