"""A Fanuc text whose last line has no newline, on the box route (``boxrun.read_box_run``, mend44).

After a last line without a newline the next offset is the text's length + 1 (``StringSource.line_at``, which
the general reader and the box run reader's runs both give); the runner asked the reader there, the reader
indexed the text past its end, and the route declined (an exception: the full path read the program again, the
same verdict, slower).  The reader now finds no line there, as ``line_at`` does.

Relations, on programs whose last line is a plain line of the three runs the reader takes (straight moves and
R arcs, hole lines under G81, straight moves under G68), ending with no newline or with a bare CR:

* the text without its last newline gives what the text with it gives: the report (verdict, violations,
  reasons, notes, counts, stats: the route answers ``safe`` on both or on neither), the lines the reader took
  and the state it hands back;
* the reader on and off (the lanes) give the same report, and without the route (the full path) the verdict,
  violations (the witnesses), reasons and notes are the same.

The test mill (tests/gcode/fanuc/helpers.py): G54 = (100, 50, -200), the zone machine X -10..150, Y -10..90,
Z -201..0: program X -110..50, Y -60..40, Z -2..199.
"""

from __future__ import annotations

import os

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from tests.gcode.fanuc.helpers import BOX_ZONE, final_state, mill, probe_route

_MACHINE = mill(tables=BOX_ZONE)
EXAMPLES = int(os.environ.get("NCZONES_BOX_LAST_LINE_EXAMPLES", "20"))
#: how each kind of run starts (the first straight move notes the assumed modes on the general lane)
_HEADS = {
    "plain": ["O1", "G90 G17 G21 G54 G00 X0. Y0. Z10.", "G01 F500.", "G1 X1. Y1."],
    "holes": ["O1", "G90 G17 G21 G54 G00 X0. Y0. Z10.", "M03 S1000", "G99 G81 X0. Y0. Z-1. R2. F200."],
    "rotation": ["O1", "G90 G17 G21 G54 G00 X0. Y0. Z10.", "G68 X0. Y0. R30.", "G01 F500.", "G1 X1. Y1."],
}

#: coordinates in thousandths: inside the zone (on its faces too), and an increment past them
_XS, _X_OUT = [-110000, 50000, 0, 12345, -3500, 20000], [-110001, 50001]
_YS, _Y_OUT = [-60000, 40000, 0, 7250, -2000, 15000], [-60001, 40001]


def _num(units: int) -> str:
    """``units`` thousandths as a decimal with a point."""
    s = f"{units / 1000:.3f}".rstrip("0")
    return "0." if s in ("0.", "-0.") else s


@st.composite
def _programs(draw) -> str:
    """A program of one kind of run whose last line (one the reader takes) has no newline; inside the zone or
    near its faces (program X -110..50, Y -60..40)."""
    kind = draw(st.sampled_from(sorted(_HEADS)))
    lines = list(_HEADS[kind])
    out = draw(st.integers(0, 3)) == 0  # a program that may leave the zone (its witnesses cost the full path)
    x, y = 1000, 1000
    for _ in range(draw(st.integers(1, 8))):
        if kind == "plain" and draw(st.booleans()):  # an R arc a few mm long (a chord below 2|R|)
            x += draw(st.integers(-4000, 4000))
            y += draw(st.integers(-4000, 4000)) or 1000
            r = draw(st.sampled_from([5000, 7500, -6000, 12000]))
            lines.append(f"{draw(st.sampled_from(['G2', 'G3']))} X{_num(x)} Y{_num(y)} R{_num(r)}")
            continue
        x = draw(st.sampled_from(_XS + (_X_OUT if out else [])))
        y = draw(st.sampled_from(_YS + (_Y_OUT if out else [])))
        g = "" if kind == "holes" else draw(st.sampled_from(["G1 ", "G01 ", "G0 "]))
        lines.append(f"{g}X{_num(x)} Y{_num(y)}")
    line_end = draw(st.sampled_from(["\n", "\r\n"]))
    return line_end.join(lines) + draw(st.sampled_from(["", "\r"]))


def _report(text: str, *, runs: bool = True, route: bool = True) -> tuple[tuple, int]:
    """(the report, the lines the box run reader took) of ``verify`` on ``text``."""
    r, _tested, taken = probe_route(text, _MACHINE, "t.nc", runs=runs, route=route)
    if isinstance(r, GcodeError):
        return ("error", tuple((d.code, d.message, str(d.span)) for d in r.diagnostics)), taken
    stats = dict(r.stats)
    return ((r.verdict.label, tuple(r.violations), tuple(r.reasons), tuple(r.notes), r.truncated, stats["segments"],
             stats.get("fanuc_boxes"), (r.extra or {}).get("counts"), (r.profile or {}).get("blocks")), taken)


@settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_a_last_line_without_newline_is_read_as_with_one(text):
    ended = text.removesuffix("\r") + ("\n" if "\r\n" not in text else "\r\n")
    got, taken = _report(text)
    assert (got, taken) == _report(ended)
    assert got == _report(text, runs=False)[0]
    assert got[:4] == _report(text, route=False)[0][:4]
    if got[0] != "error":
        assert final_state(text, _MACHINE, runs=True) == final_state(ended, _MACHINE, runs=True)


def test_the_route_takes_a_last_line_without_newline():
    """Each kind of run ending on its last line: the route answers ``safe`` (one box, no full path), the reader
    takes the run's lines, the last one included, and the full path agrees."""
    for kind, tail in (("plain", ["G1 X10. Y5.", "G2 X14. Y5. R2.5", "G1 X3. Y4."]),
                       ("holes", ["X10. Y5.", "X14. Y5.", "X3. Y4."]),
                       ("rotation", ["G1 X10. Y5.", "X14. Y5.", "X3. Y4."])):
        text = "\n".join(_HEADS[kind] + tail)
        got, taken = _report(text)
        assert got[0] == "safe" and got[6] == 1, (kind, got)  # the route's answer (stats fanuc_boxes)
        assert taken == len(tail), kind
        assert got[:4] == _report(text, route=False)[0][:4]
