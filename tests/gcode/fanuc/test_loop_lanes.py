"""The Macro B loop machinery's shortcuts agree with the general path (issue 36, loops at interpreter speed).

* The arithmetic and comparison closures of :func:`~nczones.gcode.fanuc.expr.compile_tree` inline
  :func:`nczones.gcode.expr.binary_op`: the same IEEE operation on the doubles and the same exact shadow
  (kept only where it rounds to the double), so every value is bit-identical to ``binary_op``'s.  The
  order comparisons are Fanuc's (0i-MF "Arithmetic and logic operation": GT/GE/LT/LE compare the values,
  vacant reads as 0) and give ``(1.0, 1)`` / ``(0.0, 0)``.
* A plain line that runs again (a loop body, a subprogram) is scanned once and replayed
  (``_Source.plain``); a bare M99 returns without building the block.  A loop or an M98 call of a
  subprogram must move the machine exactly as the same lines written out one after the other
  (unrolled), including a body that switches G20/G21 (the literal check is kept per unit system).
"""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.gcode.expr import EvalError, binary_op
from nczones.gcode.fanuc.expr import FanucVariables, compile_tree
from nczones.gcode.fanuc.parser import BIN, NUM
from nczones.prover import verify_text

from .helpers import mill

_doubles = st.floats(allow_nan=False, allow_infinity=False, width=64) | st.sampled_from(
    [0.0, -0.0, 1.0, 0.1, 3.0, 1e308, -1e308, 5e-324])


@st.composite
def _values(draw):
    """A value ``(double, shadow)``: a decimal literal with its exact shadow, or a double without one."""
    if draw(st.booleans()):
        q = Fraction(draw(st.integers(-10**6, 10**6)), 10 ** draw(st.integers(0, 4)))
        return (q.numerator / q.denominator, q)
    d = draw(_doubles)
    return (d, Fraction(d) if draw(st.booleans()) else None)


def _same(a: tuple, b: tuple) -> bool:
    """Bit-identical values: the doubles' bits (so -0.0 differs from 0.0) and the shadows."""
    return a[0].hex() == b[0].hex() and math.copysign(1, a[0]) == math.copysign(1, b[0]) and a[1] == b[1]


@settings(max_examples=300, deadline=None)
@given(_values(), _values(), st.sampled_from(["+", "-", "*", "/", "gt", "ge", "lt", "le"]))
def test_compiled_operators_agree_with_binary_op(left, right, op):
    fn = compile_tree((BIN, op, (NUM, *left), (NUM, *right)), FanucVariables())
    if op in ("+", "-", "*", "/"):
        try:
            expected = binary_op(op, left, right)
        except EvalError as e:
            try:
                fn()
            except EvalError as f:
                assert (f.code, f.message) == (e.code, e.message)
            else:
                raise AssertionError("binary_op raised, the closure did not")
            return
    else:  # Fanuc: the doubles compared; true is 1, false 0
        holds = {"gt": left[0] > right[0], "ge": left[0] >= right[0], "lt": left[0] < right[0],
                 "le": left[0] <= right[0]}[op]
        expected = (1.0, Fraction(1)) if holds else (0.0, Fraction(0))
    assert _same(fn(), expected)


_BODY = [
    "#2 = #1 * 0.37",
    "#3 = #2 * COS[#1 * 7.5] - #1 / 3",
    "#4 = [#2 + 1.25] * SIN[#1 * 7.5]",
    "IF [#4 GT 2] THEN #5 = #5 + 1",
    "G01 X#3 Y#4",
    "G01 Z-1.",
    "X1.2345",  # four decimals: plain in inch input, rounded (not plain) in metric input
    "G20",
    "X1.2345 Y-0.5",
    "G21",
    "Y2.",
    "G00 X[#5] Y#2",
]


def _segments(text: str) -> list:
    m = mill()
    return [(s.kind, s.start, s.end, s.feed_mm_min, s.block) for s in interpret_text(text, m).segments()]


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(_BODY), min_size=1, max_size=7), st.integers(1, 6), st.booleans())
def test_loop_and_subprogram_move_as_the_unrolled_lines(body, reps, as_subprogram):
    head = ["O1000", "G90 G17 G21 G54 F500.", "#1 = 0", "#5 = 0"]
    if as_subprogram:
        looped = head + [f"WHILE [#1 LT {reps}] DO1", "M98 P9020", "#1 = #1 + 1", "END1", "M30", "O9020", *body,
                         "M99"]
    else:
        looped = head + [f"WHILE [#1 LT {reps}] DO1", *body, "#1 = #1 + 1", "END1", "M30"]
    unrolled = list(head)
    for _ in range(reps):
        unrolled += [*body, "#1 = #1 + 1"]
    unrolled.append("M30")
    assert _segments("\n".join(looped) + "\n") == _segments("\n".join(unrolled) + "\n")


def test_long_loop_verifies_as_the_unrolled_program():
    """> 512 motions (the vectorized screening tier) through verify: the loop, the M98 loop and the unrolled
    text give the same verdict and the same first violation (a zone the spiral leaves)."""
    zone = '\n[[zones]]\nname = "table"\nkind = "box"\nmin = { X = "0", Y = "-50", Z = "-300" }\n' \
           'max = { X = "400", Y = "300", Z = "100" }\n'
    m = mill(tables=zone)
    reps = 300
    body = ["#2 = #1 * 0.5", "G01 X[#2 * COS[#1 * 7.5]] Y#2", "G01 Z-1.", "Z1."]
    head = ["O1000", "G90 G17 G21 G54 F500.", "#1 = 0"]
    looped = head + [f"WHILE [#1 LT {reps}] DO1", *body, "#1 = #1 + 1", "END1", "M30"]
    sub = head + [f"WHILE [#1 LT {reps}] DO1", "M98 P9020", "#1 = #1 + 1", "END1", "M30", "O9020", *body, "M99"]
    unrolled = list(head)
    for _ in range(reps):
        unrolled += [*body, "#1 = #1 + 1"]
    unrolled.append("M30")
    results = [verify_text("\n".join(t) + "\n", m) for t in (looped, sub, unrolled)]
    assert dict(results[0].stats)["segments"] > 512
    summaries = [(r.verdict.label, [(v.block, v.zone, v.point, v.first_exit) for v in r.violations])
                 for r in results]
    # machine X = 100 (G54) + #2 COS[#1 * 7.5] with #2 = #1 / 2: below the zone's X 0 once #2 > 100 and the
    # cosine is -1 (#1 = 216: #2 = 108, COS[1620 deg] = -1 -> X = -8); Y = 50 + #2 <= 200 and Z stay inside
    assert summaries[0][0] == "unsafe"
    assert summaries[0] == summaries[1] == summaries[2]


def test_subprogram_line_read_again_after_a_unit_switch():
    """A subprogram line first run in inch input (G20: IS-B takes four decimals, X1.2345 is exact) and
    again in metric input (G21: three decimals, X1.2345 is rounded to 1.235 as the control rounds it): the
    second call must read it as metric, as the same lines written out do."""
    called = ["O1000", "G90 G17 G20 G54 F20.", "M98 P9020", "G21", "M98 P9020", "M30", "O9020", "G01 X1.2345",
              "M99"]
    written = ["O1000", "G90 G17 G20 G54 F20.", "G01 X1.2345", "G21", "G01 X1.2345", "M30"]
    got = _segments("\n".join(called) + "\n")
    assert got == _segments("\n".join(written) + "\n")
    assert got[-1][2][0] == 100 + Fraction("1.235")  # G54 X = 100 mm; 1.2345 rounded half away from zero
