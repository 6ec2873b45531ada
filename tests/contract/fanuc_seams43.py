"""Generated Fanuc mill programs where last session's transform changes meet (hunt43): hunt42's generator
(:mod:`tests.contract.fanuc_seams42`) with transformed runs aimed at the box route's transform reader
(``boxrun._read_transformed``, ``transform_points.PointMap``) and the column lane's range declines
(``transform_columns``).

New in the mix, each a transform block, the absolute first move, a run of plain lines, the cancel:

* rotation angles near multiples of 90 degrees (``89.999``, ``90.0001``, ``-0.001``, ``359.9999``, ``450.``) and
  any angle with four decimals, and scalings by factors near 1 (``0.99999``, ``1.00001``) and mirrors;
* huge work offsets first (``G10 L2 P2`` up to 4,900 mm, then ``G55``; ``G52`` up to 3,000 mm);
* inside the run: ``G20``/``G21`` (inch input after the route's text test, lengths then in inches), ``G91`` ...
  ``G90``, ``M98 P1000`` (a sub with G91 moves and a cycle), ``G65 P2000`` and macro lines (``#1 = ...``, a move
  by ``[#1 + ...]``) in a program with ``#``, an R arc (the reader's stop), lines with 4-7 integer digits;
* now and then the run repeated past ``FAST_PATH_MIN_LINES`` (the vectorized path and its int64 declines) or
  kept short (the box route).
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

from tests.contract import fanuc_seams41 as s41
from tests.contract import fanuc_seams42 as s42
from tests.contract.fanuc_seams41 import _Draw, _num, _text

#: angles near quarter turns (either side by 1e-3 or 1e-4 degrees), a full turn and more
NEAR = ("89.999", "90.001", "90.0001", "179.9999", "180.001", "-0.001", "0.0001", "269.9999", "-90.0001",
        "359.9999", "360.", "450.", "-270.", "0.")
#: factors near 1 and mirrors
NEAR_ONE = ("0.99999", "1.00001", "-1.", "0.999", "-0.99999", "1.")


def _huge_offset(d: _Draw) -> list[str]:
    """A huge work offset written into G55 (then selected), or a huge G52 shift; or nothing."""
    draw = d.draw
    kind = draw(st.integers(0, 3))
    if kind == 0:
        return [f"G10 L2 P2 X{_num(draw, -4900, 4900)} Y{_num(draw, -4900, 4900)} Z-200.", "G55"]
    if kind == 1:
        return [f"G52 X{_num(draw, -3000, 3000)} Y{_num(draw, -3000, 3000)}"]
    return []


def _block(d: _Draw) -> tuple[str, str]:
    draw = d.draw
    centre = f"X{_num(draw, -40, 40)} Y{_num(draw, -40, 40)}"
    kind = draw(st.integers(0, 5))
    if kind <= 2:
        angle = draw(st.sampled_from(NEAR)) if kind else _num(draw, -720, 720, 4)
        return f"G68 {centre} R{angle}", "G69"
    if kind == 3:
        return f"G51 {centre} Z0. P{draw(st.sampled_from(NEAR_ONE))}", "G50"
    i = draw(st.sampled_from(NEAR_ONE))
    j = draw(st.sampled_from((i, draw(st.sampled_from(NEAR_ONE)))))
    return f"G51 {centre} Z0. I{i} J{j} K1.", "G50"


def _inserted(d: _Draw) -> list[str]:
    """A line or two that meets the transform's run: units, distance mode, a call, a macro line, an R arc."""
    draw = d.draw
    kind = draw(st.integers(0, 7))
    if kind == 0:
        inch = not d.inch
        d.inch = inch
        return ["G20" if inch else "G21"]
    if kind == 1:
        d.incremental = not d.incremental
        return ["G91" if d.incremental else "G90"]
    if kind == 2:
        return [draw(st.sampled_from(("M98 P1000", "M98 P21000")))]
    if kind == 3 and not d.plain:
        return [draw(st.sampled_from(("G65 P2000 A1.5 B-2.", "#1 = #1 + 0.5", "#1 = SIN[30.] * 10."))),
                f"G01 X[#1 + {_num(draw, -30, 30)}] Y{_num(draw, -30, 30)}"]
    if kind == 4:
        r = Fraction(draw(st.integers(20, 300)), 10)
        return [f"G02 X{_text(r, 1)} Y{_text(r, 1)} R{_text(r, 1)}" if d.incremental else
                f"G91 G03 X{_text(r, 1)} Y{_text(-r, 1)} R{_text(r, 1)}", "G01" if d.incremental else "G90 G01"]
    if kind == 5:  # many integer digits
        return [f"G01 X{draw(st.integers(-9999, 9999))}.{draw(st.integers(0, 999)):03d} Y{_num(draw, -40, 40)}"]
    return s41._run_line(d)


def rotated43(d: _Draw) -> list[str]:
    """A huge offset maybe, a transform block near a quarter turn or a unit factor, the absolute first move, a
    run with :func:`_inserted` lines in it, the cancel and the absolute move after it; the units and distance
    mode put back."""
    draw = d.draw
    lines = _huge_offset(d)
    if d.incremental:
        lines.append("G90")
        d.incremental = False
    block, cancel = _block(d)
    inch0 = d.inch
    lines += [f"{d.number()}{block}", *s42.absolute(d)]
    d.in_run = True
    run: list[str] = []
    for _ in range(draw(st.integers(8, 90))):
        run += _inserted(d) if draw(st.integers(0, 7)) == 0 else s41._run_line(d)
    d.in_run = False
    if draw(st.integers(0, 7)) == 0:
        run *= 7 if len(run) > 75 else 600 // len(run) + 1
    back = ["G20" if inch0 else "G21"] if d.inch != inch0 else []
    d.inch = inch0
    lines += run + back + [cancel, *s42.absolute(d)]
    if d.incremental:
        lines.append("G90")
        d.incremental = False
    if draw(st.booleans()):
        lines.append("G54 G52 X0 Y0" if draw(st.booleans()) else "G54")
    return lines


def _statement(d: _Draw) -> list[str]:
    kind = d.draw(st.integers(0, 4))
    if kind <= 2:
        return rotated43(d)
    return s42._statement(d)


@st.composite
def fanuc_programs43(draw) -> tuple[str, str]:
    """hunt42's program parts with :func:`rotated43` statements among them."""
    inch = draw(st.integers(0, 5)) == 0
    # half of them plain (no ``#``: the box route's run reader reads only such a text)
    return s41.parts(_Draw(draw, inch, plain=draw(st.booleans())), _statement, 3, ["G69 G50 G50.1 G90"])
