"""One code, one meaning (issue 34): the codes that meant two things are split.

Until issue 34 the interpreter's reasons for ``unknown`` shared GC301-GC305 with errors of the same numbers
(GC301 an arc off its circle *and* a Fanuc construct in a LinuxCNC program, GC302 an R arc too short *and*
a loop past ``max_iterations`` ...), GC311 was both division by zero and an arc right after G40, and VF105
both ``--max-iterations`` and a ``--library`` that is no folder.  The reasons now have GC391-GC395, the G40
rule GC326, ``--library`` VF112 (``nczones/error_codes.py``, ``specs/errors.md``).  The verdicts are
unchanged; each case runs through ``verify`` short, after 600 plain moves (the vectorized tier) and with
'#' in the text (the double pass), and every lane must give the new code.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nczones import error_codes
from nczones.errors import GcodeError
from nczones.machine import Machine, load_machine, parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text

ROOT = Path(__file__).resolve().parents[2]
MILL = load_machine(ROOT / "specs" / "machines" / "mill.toml")
HEAD = "G21 G90 G54 G17\nG0 Z200\n"
FILL = "".join(f"G1 X{(k % 7) + 10} Y20 Z50 F1000\n" for k in range(600))
HASH = "#1 = 20\nG1 X#1 F500\n"
LANES = {"short": "", "vectorized": FILL, "double pass": HASH}

# What each program is, from the raise sites in nczones/gcode/program.py and expr.py (their messages quoted):
UNKNOWN = [
    # "M97 local subprogram calls (Haas) are not supported" (a Haas construct in the LinuxCNC dialect)
    ("GC391", "GC301", "M97 P100\nM2\n", {}),
    # "o1 while loop ran more than 50 iterations (max_loop_iterations)"
    ("GC392", "GC302", "o1 while [1]\nG0 X1\no1 endwhile\nM2\n", {"max_iterations": 50}),
    # "subroutine o<probe_it> is not defined in this file (pass --library DIR ...)"
    ("GC393", "GC303", "o<probe_it> call\nM2\n", {}),
    # "M99 in the main program restarts it forever; endless programs are not supported"
    ("GC394", "GC304", "G0 X1\nM99\n", {}),
    # "#<_hal[x.pos]> reads controller state (HAL pins, INI values, predefined parameters) that nobody provided"
    ("GC395", "GC305", "G0 X#<_hal[x.pos]>\nM2\n", {}),
]


@pytest.mark.parametrize("lane", LANES)
@pytest.mark.parametrize("code, old, body, options", UNKNOWN, ids=[u[0] for u in UNKNOWN])
def test_each_interpreter_reason_for_unknown_has_its_own_code(code, old, body, options, lane):
    text = HEAD + LANES[lane] + body
    result = verify_text(text, MILL, **options)
    assert result.verdict.label == "unknown"
    assert [r.code for r in result.reasons] == [code], [str(r) for r in result.reasons]
    entry = error_codes.by_code()[code]
    assert entry.kind == "unknown" and old in entry.meaning  # the catalogue says what it was before
    assert error_codes.by_code()[old].kind == "error"  # the old number keeps its error only


def _comp_machine() -> Machine:
    """A mill with LinuxCNC cutter compensation and tool 1 of diameter 2 (as tests/gcode/test_cutter_comp.py)."""
    return parse_machine(machine_text("mill_cutter_comp_g54"))


@pytest.mark.parametrize("lane", LANES)
def test_an_arc_right_after_g40_is_gc326_and_division_by_zero_stays_gc311(lane):
    # LinuxCNC refuses an arc as the first move after G40 (the interpreter's message: "must be straight")
    head = "G21 G90 G54 G17\nT1 M6\nG0 X0 Y0 Z5\n"
    fill = LANES[lane].replace("Z50", "Z5")
    text = head + fill + "G41 G1 X10 Y0 F100\nG1 X20\nG40\nG2 X30 Y0 I5 J0\nM2\n"
    with pytest.raises(GcodeError) as e:
        verify_text(text, _comp_machine())
    assert e.value.code == "GC326" and "G40" in e.value.diagnostics[0].message
    span = e.value.diagnostics[0].span
    assert span is not None and span.line == text.count("\n") - 1  # the G2 line
    with pytest.raises(GcodeError) as e:
        verify_text(HEAD + LANES[lane] + "#2 = [1 / 0]\nG0 X#2\nM2\n", MILL)
    assert e.value.code == "GC311" and "divide by zero" in e.value.diagnostics[0].message
