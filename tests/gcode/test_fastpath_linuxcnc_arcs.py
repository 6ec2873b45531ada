"""``--arc-tolerance linuxcnc`` keeps the fast path: I/J arcs are accepted or refused as the full interpreter does.

The fast path decides LinuxCNC's acceptance rule (``interpreter.linuxcnc_rejects_arc``) on whole runs: a
float test with a wide margin accepts what is clearly inside the rule, the interpreter's own function decides
the rest.  Generated arcs whose end points lie off the circle by amounts around both of the rule's limits
(the absolute 2 * 0.01 * sqrt 2 mm, the relative 0.001 up to 100 times that; in inches 2 * 0.001 * sqrt 2)
give the same segments, or the same error at the same line, on both paths, and runs of accepted arcs take
the fast path.
"""

from __future__ import annotations

import math
from decimal import Decimal
from fractions import Fraction as F

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from tests.machines import machine_text

MACHINE = parse_machine(machine_text("box_5000"))


def _run(text, fast):
    run = interpret_text(text, MACHINE, fast=fast, arc_tolerance="linuxcnc")
    try:
        segs = [(s.kind, s.start, s.end, s.block, s.centre, s.clockwise, s.turns, s.line)
                for chunk in run for s in chunk.segments()]
    except GcodeError as exc:
        d = exc.diagnostics[0]
        return ("error", d.code, d.span.line if d.span else None), 0
    return ("ok", segs, run.status), run.fast_lines


def _text(x):
    return format(Decimal(x.numerator) / Decimal(x.denominator), "f")


@st.composite
def arc_runs(draw):
    inch = draw(st.booleans())
    tol = 2 * (0.001 if inch else 0.01) * math.sqrt(2)
    lines = ["G20 G90 G17 F10" if inch else "G21 G90 G17 F100", "G0 X0 Y0"]
    x, y = F(0), F(0)
    for _ in range(draw(st.integers(2, 8))):
        r = F(draw(st.integers(1, 500_000)), 10_000)  # 0.0001 .. 50
        # the end's radius differs by a multiple of the rule's limits, near them or between them
        limit = draw(st.sampled_from([tol, 0.001 * float(r), 100 * tol]))
        accepted = draw(st.integers(0, 5)) > 0  # mostly below a limit, so that whole runs are accepted
        factor = draw(st.sampled_from([0, 0.5, 0.999, 0.99999, 1.0] if accepted else [1.00001, 1.001, 2]))
        dr = F(round(limit * factor * 10_000 * draw(st.sampled_from([1, -1]))), 10_000)
        if r + dr <= 0:
            dr = F(0)
        cx, cy = x - r, y
        turn = draw(st.sampled_from([(0, 1), (-1, 0), (0, -1)]))
        ex, ey = cx + (r + dr) * turn[0], cy + (r + dr) * turn[1]
        lines.append(f"{draw(st.sampled_from(['G2', 'G3']))} X{_text(ex)} Y{_text(ey)} I{_text(-r)} J0")
        x, y = ex, ey
    lines.append("M2")
    return "\n".join(lines) + "\n"


@settings(max_examples=150, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(arc_runs())
def test_linuxcnc_rule_on_the_fast_path_equals_the_full_interpreter(text):
    fast, _ = _run(text, True)
    full, _ = _run(text, False)
    assert fast == full, text


def test_accepted_spirals_stay_on_the_fast_path():
    # ends 0.02 mm off their circles: beyond the default 0.002 mm, within LinuxCNC's 0.028 mm
    arcs = "".join(f"G2 X{20 + 20 * k}.02 Y0 I10 J0\nG1 X{20 + 20 * k} Y0\n" for k in range(200))
    text = f"G21 G90 G17 F100\nG0 X0 Y0\n{arcs}M2\n"
    (status, segs, _), fast_lines = _run(text, True)
    assert status == "ok" and len(segs) == 401
    assert fast_lines >= 400
    assert _run(text, False)[0] == (status, segs, "complete")
