"""Hole lines on the box route (``boxrun._read_holes``, issue 36) against the interpreter's own cycle.

A Fanuc program of fewer than ``FANUC_BOX_LINES`` lines with a drilling cycle takes the numpy-free box route; its
hole lines (X and Y words after the cycle's first block) are read from the text into the run's box, each hole the
rows of ``fanuc.holes.fanuc_holes``.  Relations (every side nczones; the reader is an optimisation):

* ``verify`` with the reader (``boxrun.BOX_RUNS``) and without it (every hole through
  ``FanucInterpreter._fanuc_cycle``, its segments boxed) give the same verdict, violations, reasons, notes,
  counts (blocks, motions by kind) and stats;
* without the route (``fanucboxes.ROUTE`` off: the full path, or the vectorized fast path past 512 lines) the
  verdict, violations, reasons, notes and motion count are the same;
* after the reader the interpreter's state (position, counts, block index and span, the runner's index) is the
  one ``_fanuc_cycle`` leaves;
* the reader does take hole lines (counted), and a hole whose bottom or position leaves the zone by one
  increment is not ``safe``.

The test mill (tests/gcode/fanuc/helpers.py): G54 = (100, 50, -200); the zone machine X -10..150, Y -10..90,
Z -201..0 and EXT Z = 1, i.e. program X -110..50, Y -60..40, Z -2..199.
"""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from tests.gcode.fanuc.helpers import BOX_ZONE, final_state, mill, probe_route

_MACHINE = mill(tables=BOX_ZONE)
EXAMPLES = int(os.environ.get("NCZONES_BOX_HOLES_EXAMPLES", "12"))
#: the drilling cycles and the words each needs beyond X Y Z R F (G74/G84 tap: the spindle turns)
_CYCLES = {81: "", 82: " P500", 73: " Q0.7", 83: " Q0.4", 85: "", 86: "", 89: " P200", 84: " P100", 74: ""}
#: lines the reader hands back in a run of holes (the interpreter reads them; the reader takes the next again)
_LEAVE = ["(A COMMENT)", "", "X12", "X1.0005", "M08", "G80", "N7", "Y5. M9", "x3.", "G91 X1.", "G90", "Z-0.5",
          "R2.", "G99", "G98"]
#: coordinates near the zone's faces (program X -110..50, Y -60..40) and inside
_XS = ["0.", "10.", "-110.", "50.", "50.001", "-110.001", "12.345", "-3.5"]
_YS = ["0.", "5.", "-60.", "40.", "40.001", "-60.001", "7.25", "-2."]


@st.composite
def _programs(draw, size: int = 25) -> str:
    """A Fanuc program: a drilling cycle, then hole lines and lines the reader leaves, then plain moves."""
    cycle = draw(st.sampled_from(sorted(_CYCLES)))
    spin = "M04 S600" if cycle == 74 else "M03 S1000"
    depth = draw(st.sampled_from(["-0.5", "-2.", "-2.001", "0.2"]))
    r = draw(st.sampled_from(["2.", "5.", "0.5"]))
    top = draw(st.sampled_from(["50.", "2.", "10."]))
    ret = draw(st.sampled_from(["G98", "G99"]))
    lines = ["O2000", f"G90 G17 G21 G54 G00 X0. Y0. Z{top}", spin,
             f"{ret} G{cycle} X{draw(st.sampled_from(_XS))} Y{draw(st.sampled_from(_YS))} Z{depth} R{r}"
             f"{_CYCLES[cycle]} F{draw(st.sampled_from(['200.', '50.5']))}"]
    for _ in range(draw(st.integers(1, size))):
        kind = draw(st.sampled_from(["xy", "xy", "x", "y", "n", "leave"]))
        if kind == "leave":
            lines.append(draw(st.sampled_from(_LEAVE)))
            continue
        n = f"N{draw(st.integers(1, 9999))} " if kind == "n" else ""
        x, y = draw(st.sampled_from(_XS)), draw(st.sampled_from(_YS))
        lines.append(n + (f"X{x}" if kind != "y" else f"Y{y}") + (f" Y{y}" if kind in ("xy", "n") else ""))
    lines += ["G80", "G00 Z50.", "X0. Y0.", "M30"]
    return "\n".join(lines) + "\n"


def _run(text: str, runs: bool, route: bool = True) -> tuple[tuple, int]:
    """(the report, the lines the reader took) of ``verify`` on ``text``."""
    r, _tested, taken = probe_route(text, _MACHINE, "t.nc", runs=runs, route=route)
    if isinstance(r, GcodeError):
        return ("error", tuple((d.code, d.message, str(d.span)) for d in r.diagnostics)), taken
    stats = dict(r.stats)
    return ((r.verdict.label, tuple(r.violations), tuple(r.reasons), r.truncated, tuple(r.notes), stats["segments"],
             r.file, stats.get("fanuc_boxes"), (r.extra or {}).get("counts"), (r.profile or {}).get("blocks")),
            taken)


def _agree(text: str) -> tuple[str, int]:
    """The reader, the interpreter's cycle and the path without the route agree; (verdict, lines the reader took)."""
    read, taken = _run(text, True)
    cycle, none = _run(text, False)
    assert none == 0
    assert read == cycle
    today, _ = _run(text, True, route=False)
    assert today[:7] == read[:7]
    return str(read[0]), taken


@settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_reads_holes_as_the_cycle(text):
    _agree(text)


@settings(max_examples=max(2, EXAMPLES // 4), deadline=None, database=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_reads_holes_as_the_fast_path(text):
    """The same program with 600 holes more (past 512 lines: without the route the fast path's hole template)."""
    head, _, rest = text.partition("\nG80\n")
    extra = "".join(f"\nX{k % 9}. Y{k % 4}." for k in range(600))
    _agree(head + extra + "\nG80\n" + rest)


def test_the_reader_takes_hole_lines_and_sees_a_hole_out():
    """60 holes inside the zone: ``safe``, the reader takes the hole lines; one hole's bottom an increment below
    the zone's floor, or its position an increment past X's face: not ``safe``, as the interpreter says."""
    holes = "".join(f"X{k % 30}. Y{k % 7}.\n" for k in range(60))
    base = "O1\nG90 G17 G21 G54 G00 X0. Y0. Z50.\nG98 G81 X1. Y1. Z-2. R2. F200.\n" + holes + "G80\nM30\n"
    verdict, taken = _agree(base)
    assert verdict == "safe" and taken == 60
    deeper = base.replace("Z-2. R2.", "Z-2.001 R2.")
    assert "Z-2.001" in deeper and _agree(deeper)[0] != "safe"
    for old, new in (("X29. Y1.", "X50.001 Y1."), ("X8. Y1.", "X8. Y-60.001"), ("X27. Y6.", "Y40.001")):
        past = base.replace(old, new, 1)  # a hole line the reader takes, an increment out of the zone
        assert new in past and _agree(past)[0] != "safe"


def _final_state(text: str, runs: bool) -> tuple:
    """``helpers.final_state`` on the test mill.  (The test below keeps its body: a derandomized test draws its
    examples from its source, and others drawn include an unsafe program whose walk the route stops at another
    chunk with the reader than without it, so the states compared are not at the same line.)"""
    return final_state(text, _MACHINE, runs=runs)


@settings(max_examples=max(3, EXAMPLES // 3), deadline=None, database=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_hands_the_state_back_as_the_cycle_leaves_it(text):
    """A program that ends on hole lines (the text ends there): the state is the interpreter's after them."""
    text = text[:text.rindex("\nG80\n") + 1]
    try:
        cycle = _final_state(text, False)
    except GcodeError as exc:
        with pytest.raises(GcodeError) as read:
            _final_state(text, True)
        assert (read.value.code, str(read.value)) == (exc.code, str(exc))
        return
    assert _final_state(text, True) == cycle
