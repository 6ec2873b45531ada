"""The libm spread's fast paths (spread41) against an exact oracle kept here, not in the package.

libm40 carries a SIN/COS/... result's spread as its least and greatest double (specs/fanuc.md, "Results of the
library functions").  spread41 made that cheap without changing it:

* :func:`neighbours` finds a SIN/COS result's two neighbours in three operations: equal to ``math.nextafter``'s;
* ``r * SIN[t]`` / ``r * COS[t]`` is one closure: its double and its spread equal those of the oracle below
  (the result's neighbours, the products' corners rounded once from their exact values with Fractions), in an
  assignment and in a condition, with plain, spread and zero operands;
* round_to screens a spread inline and the relations screen its ends: wherever they decide, every double of the
  spread (its two ends, the readings monotone in between) decides the same with the plain path, and they
  decline where the ends agree only rarely (at most 1% of the draws).

Mutations caught (run by hand, spread41): ``_NEIGHBOUR = 2**-53`` (the tie at a power of two rounds to even:
``test_neighbours_are_nextafters``), a polar corner dropped (``p = a * c``: ``test_polar_product_is_the_oracles``),
the round screen's width bound raised to 1.0 (``test_round_screen_decides_only_what_every_double_gives``).
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.fanuc.expr import (
    FanucVariables,
    RoundingNotCertain,
    SpreadDouble,
    compile_tree,
    neighbours,
    round_to,
)
from nczones.gcode.fanuc.parser import parse_line

# -- the oracle: the spread in exact rationals ------------------------------------------------------------------


def _next(c: float) -> tuple[float, float]:
    return math.nextafter(c, -math.inf), math.nextafter(c, math.inf)


def _oracle_trig(name: str, t: float) -> tuple[float, float, float]:
    """SIN/COS of ``t`` degrees as libm40 defines it: CPython's double, its neighbours (none at 0)."""
    c = (math.sin if name == "SIN" else math.cos)(t * math.pi / 180.0)
    lo, hi = (c, c) if t == 0.0 else _next(c)
    return c, lo, hi


def _oracle_mul(x: tuple[float, float, float], y: tuple[float, float, float]) -> tuple[float, float, float]:
    """``x * y`` of (double, lo, hi) triples: the least and greatest exact corner, each rounded once."""
    corners = [Fraction(a) * Fraction(b) for a in x[1:] for b in y[1:]]
    return x[0] * y[0], float(min(corners)), float(max(corners))


def _triple(value: tuple) -> tuple[float, float, float]:
    d = value[0]
    if d.__class__ is SpreadDouble:
        return float(d), d.lo, d.hi
    return d, d, d


# -- neighbours ---------------------------------------------------------------------------------------------------

_EDGES = [1.0, -1.0, 0.5, -0.5, 0.25, 2.0**-969, -(2.0**-969), 2.0**-968, 1.0 - 2.0**-53, 0.49999999999999994,
          0.5000000000000001, 2.0**-970, 5e-324, 1e-300, 0.9999999999999999, 0.7071067811865476]


@pytest.mark.parametrize("c", _EDGES)
def test_neighbours_at_the_edges(c):
    assert neighbours(c) == _next(c)


@settings(max_examples=300, deadline=None)
@given(st.floats(-1.0, 1.0, allow_nan=False) | st.floats(allow_nan=False, allow_infinity=False))
def test_neighbours_are_nextafters(c):
    assert neighbours(c) == _next(c)


def test_neighbours_of_many_sines_and_cosines():
    rng = random.Random(41)
    for _ in range(20000):
        c = math.sin(rng.uniform(-7.0, 7.0)) if rng.random() < 0.5 else math.ldexp(rng.random(), -rng.randint(0, 990))
        assert neighbours(c) == _next(c), c


# -- r * SIN[t], r * COS[t] -----------------------------------------------------------------------------------------

_ANGLES = st.sampled_from([0.0, 30.0, 45.0, 60.0, 90.0, 180.0, 270.0, 360.0, 3.6, 7.2, 123.4, -45.0, 1e-300]) | st.floats(
    -720.0, 720.0, allow_nan=False)
_RADII = st.sampled_from([0.0, 1.0, -1.0, 0.01, 3.0, 1000.0, 0.37, 1e-310]) | st.floats(-1e6, 1e6, allow_nan=False)


def _variables(r: float, t: float, spread_r: str | None) -> FanucVariables:
    v = FanucVariables()
    v.local[1] = (t, None)
    if spread_r is None:
        v.local[2] = (r, None)
    return v


@settings(max_examples=200, deadline=None)
@given(_RADII, _ANGLES, st.sampled_from(["SIN", "COS"]), st.sampled_from([None, "SIN", "COS"]),
       st.sampled_from(["assign", "condition"]))
def test_polar_product_is_the_oracles(r, t, name, spread_r, path):
    v = _variables(r, t, spread_r)
    factor = repr(r) if "e" not in repr(r) and "inf" not in repr(r) else "#6"  # (no exponents in Fanuc's numbers)
    v.local[6] = (r, None)
    radius = "#2" if spread_r is None else f"[{spread_r}[#1 + 10] * {factor}]"
    text = f"{radius} * {name}[#1]"
    if path == "assign":
        fn = compile_tree(parse_line(f"#3 = {text}", 1, "p").assigns[0][1], v)
    else:  # the doubles-only path: the operand of a relation, compiled with exact=False
        fn = compile_tree(parse_line(f"#3 = {text}", 1, "p").assigns[0][1], v, exact=False)
    got = _triple(fn())
    if spread_r is None:
        x = (r, r, r)
    else:
        x = _oracle_mul(_oracle_trig(spread_r, t + 10), (r, r, r))
    want = _oracle_mul(x, _oracle_trig(name, t))
    if want[1] == want[2]:  # one double for every choice: the value carries no spread
        assert got[0] == want[0] and got[1] == got[2] == want[0], (text, got, want)
    else:
        assert got == want, (text, got, want)


# -- round_to's and the relations' screens --------------------------------------------------------------------------

_STEP = Fraction(1, 1000)


def _spread_value(rng: random.Random) -> tuple:
    """A value with a spread near a half increment or a bound: a few to a million ulps wide."""
    base = rng.choice([0.0005, 0.0015, 1.2345, 12.3455, 0.5, 1000.0, 73.7, 9.99]) * rng.choice([1, -1, 3, 7])
    d = base + rng.choice([0.0, 1.0, -1.0]) * rng.choice([1e-19, 1e-16, 1e-13, 1e-11, 1e-9, 1e-7, 1e-5])
    below, above = rng.randint(1, 4), rng.randint(1, 4)
    width = rng.choice([0.0, 0.0, 1e-15, 1e-12, 1e-10, 1e-8, 1e-6, 3e-4])
    lo, hi = d - width * rng.random(), d + width * rng.random()
    for _ in range(below):
        lo = math.nextafter(lo, -math.inf)
    for _ in range(above):
        hi = math.nextafter(hi, math.inf)
    s = SpreadDouble(d)
    s.lo, s.hi = lo, hi
    return (s, None)


def _plain_round(x: float) -> Fraction | None:
    try:
        return round_to((x, None), _STEP)
    except RoundingNotCertain:
        return None


def test_round_screen_decides_only_what_every_double_gives():
    rng = random.Random(4141)
    decided = declined_agreeing = agreeing = 0
    for _ in range(4000):
        value = _spread_value(rng)
        s = value[0]
        ends = _plain_round(s.lo), _plain_round(s.hi)
        agree = ends[0] is not None and ends[0] == ends[1]
        agreeing += agree
        try:
            got = round_to(value, _STEP)
        except RoundingNotCertain:
            declined_agreeing += agree
            continue
        decided += 1
        # the readings are non-decreasing in the double and rounding is too: the two ends bound every double
        assert agree and got == ends[0], (float(s), s.lo, s.hi, got, ends)
    assert decided > 1000 and declined_agreeing <= agreeing // 100, (decided, declined_agreeing, agreeing)


@pytest.mark.parametrize("op", ["GT", "LT", "GE", "LE", "EQ", "NE"])
def test_relation_screen_decides_only_what_every_double_gives(op):
    rng = random.Random(hash(op) % 1000)
    decided = 0
    for _ in range(600):
        value = _spread_value(rng)
        s = value[0]
        k = rng.choice([float(s), s.lo, s.hi, round(float(s), 3), float(s) * (1 + 1e-9)])
        v = FanucVariables()
        v.local[4] = value
        fl = parse_line(f"IF [#4 {op} {k!r}] THEN #5 = 1", 1, "p")
        try:
            got = compile_tree(fl.stmt[1], v)()
        except RoundingNotCertain:
            continue
        decided += 1
        if op in ("EQ", "NE"):  # not monotone: decided only where no double of the spread is the constant
            assert not s.lo <= k <= s.hi, (op, float(s), s.lo, s.hi, k, got)
        ends = []
        for x in (s.lo, s.hi):
            v.local[4] = (x, None)
            try:
                ends.append(compile_tree(fl.stmt[1], v)())
            except RoundingNotCertain:
                ends.append(None)
        assert ends[0] == ends[1] == got, (op, float(s), s.lo, s.hi, k, got, ends)
    assert decided > 100
