"""The exact core's enclosures (nczones.exact), checked once against mpmath at high precision.

Every enclosure must contain the true value: mpmath computes it with 1200 bits, far below the
enclosures' widths (about ``2**-200`` at the finest); the comparison allows the reference's own error
(``2**-1100`` relative, well inside any enclosure).  Widths must shrink as the precision grows.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import InvalidArgument
from nczones.exact import (
    GRID_BITS,
    Interval,
    asin_interval,
    atan2_interval,
    atan_interval,
    atan_range,
    degrees,
    is_square,
    max_bound,
    min_bound,
    pi_interval,
    radians,
    round_down,
    round_up,
    sin_cos_degrees,
    sin_cos_interval,
    sqrt_interval,
)

F = Fraction
FEW = settings(max_examples=60, deadline=None)
_PREC = 1200
#: the reference's error allowance (absolute, for values of magnitude up to a few hundred)
_EPS = F(1, 2**1100)

fractions = st.fractions(min_value=-1000, max_value=1000, max_denominator=10**12)
unit = st.fractions(min_value=0, max_value=1, max_denominator=10**12)
small = st.fractions(min_value=-8, max_value=8, max_denominator=10**9)
angles = st.one_of(st.fractions(min_value=-720, max_value=720, max_denominator=10**6),
                   st.integers(-24, 24).map(lambda k: F(15 * k)))


def _mp(q: Fraction) -> mpmath.mpf:
    return mpmath.mpf(q.numerator) / q.denominator


def _exact(v: mpmath.mpf) -> Fraction:
    sign, man, exp, _ = mpmath.mpf(v)._mpf_  # (-1)**sign * man * 2**exp, exactly
    return (-1) ** sign * F(int(man)) * F(2) ** exp


def _inside(iv: Interval, true: mpmath.mpf) -> bool:
    v = _exact(true)
    eps = _EPS * max(1, abs(v))
    return iv.lo <= v + eps and v - eps <= iv.hi


@pytest.fixture(autouse=True)
def _precision():
    with mpmath.workprec(_PREC):
        yield


def test_pi_encloses_pi_narrowly():
    p = pi_interval()
    assert _inside(p, mpmath.pi) and p.width() < F(1, 2**190)
    assert p is pi_interval()  # computed once


@FEW
@given(fractions, st.sampled_from([24, 64, 96, 128, GRID_BITS]))
def test_atan_encloses(x, bits):
    with mpmath.workprec(_PREC):
        iv = atan_interval(x, bits)
        assert _inside(iv, mpmath.atan(_mp(x)))
        assert iv.width() <= F(1, 2**(bits - 8))


@FEW
@given(unit)
def test_atan_widths_shrink_and_nest_with_precision(x):
    """A more precise enclosure is narrower and (the module's invariant: 4 units to spare) inside a coarser one."""
    coarse, fine = atan_interval(x, 64), atan_interval(x, 160)
    assert fine.width() <= coarse.width()
    assert coarse.lo <= fine.lo <= fine.hi <= coarse.hi


@FEW
@given(fractions, fractions)
def test_atan2_encloses(y, x):
    if x == 0 and y == 0:
        with pytest.raises(ValueError):
            atan2_interval(y, x)
        return
    with mpmath.workprec(_PREC):
        iv = atan2_interval(y, x)
        assert _inside(iv, mpmath.atan2(_mp(y), _mp(x)))
        assert -pi_interval().hi <= iv.lo and iv.hi <= pi_interval().hi


@FEW
@given(unit, unit)
def test_atan_range_and_asin_enclose(a, b):
    lo, hi = min(a, b), max(a, b)
    with mpmath.workprec(_PREC):
        r = atan_range(Interval(lo, hi))
        assert _inside(r, mpmath.atan(_mp(lo))) and _inside(r, mpmath.atan(_mp(hi)))
        s = asin_interval(Interval(lo, hi))
        assert _inside(s, mpmath.asin(_mp(lo))) and _inside(s, mpmath.asin(_mp(hi)))


@FEW
@given(st.fractions(min_value=0, max_value=10**6, max_denominator=10**12), st.sampled_from([16, 64, 128, GRID_BITS]))
def test_sqrt_encloses_and_is_exact_on_squares(q, bits):
    with mpmath.workprec(_PREC):
        iv = sqrt_interval(q, bits)
        assert _inside(iv, mpmath.sqrt(_mp(q)))
        assert iv.lo * iv.lo <= q <= iv.hi * iv.hi  # exactly, without the reference
        assert iv.width() <= F(1, 2**bits)
        if is_square(q) is not None:
            assert iv.width() == 0
        assert sqrt_interval(q * q, bits) == Interval.of(q)
        assert sqrt_interval(q, bits + 32).width() <= iv.width()


def test_sqrt_of_a_negative_number_is_refused():
    with pytest.raises(InvalidArgument):
        sqrt_interval(F(-1))
    assert Interval(F(-1), F(4)).sqrt() == Interval(F(0), F(2))  # the interval form clips


@FEW
@given(small, st.fractions(min_value=0, max_value=F(1, 100), max_denominator=10**6))
def test_sin_cos_radians_enclose(x, h):
    with mpmath.workprec(_PREC):
        s, c = sin_cos_interval(Interval(x - h, x + h))
        for v in (x - h, x, x + h):
            assert _inside(s, mpmath.sin(_mp(v))) and _inside(c, mpmath.cos(_mp(v)))
        if h == 0:
            assert s.width() < F(1, 2**180) and c.width() < F(1, 2**180)


@FEW
@given(angles)
def test_sin_cos_degrees_enclose(a):
    with mpmath.workprec(_PREC):
        s, c = sin_cos_degrees(a)
        rad = _mp(a) * mpmath.pi / 180
        assert _inside(s, mpmath.sin(rad)) and _inside(c, mpmath.cos(rad))
        assert s.width() < F(1, 2**180) and c.width() < F(1, 2**180)


def test_sin_cos_degrees_exact_where_rational():
    """Niven: the rational values of sine and cosine at rational degree angles are 0, +-1/2, +-1."""
    for a in range(0, 720, 30):
        s, c = sin_cos_degrees(F(a))
        rational = [v for v in (s, c) if v.width() == 0]
        assert rational, a  # every multiple of 30 degrees has one rational value
        for v in rational:
            assert v.lo in (0, F(1, 2), F(-1, 2), 1, -1)
    assert sin_cos_degrees(F(45))[0].width() > 0


@FEW
@given(angles)
def test_degrees_and_radians_are_inverse_enclosures(a):
    with mpmath.workprec(_PREC):
        r = radians(a)
        assert _inside(r, _mp(a) * mpmath.pi / 180)
        assert degrees(r).contains(a)


@FEW
@given(fractions, fractions, st.fractions(min_value=-10, max_value=10, max_denominator=1000).filter(lambda q: q != 0))
def test_interval_arithmetic_encloses(a, b, c):
    """Each operation on intervals contains the operation on members (here the ends and the middle)."""
    x = Interval(min(a, b), max(a, b))
    d = Interval.of(c)
    for op in (lambda u, v: u + v, lambda u, v: u - v, lambda u, v: u * v, lambda u, v: u / v):
        iv = op(x, d)
        for m in (x.lo, x.hi, x.mid()):
            assert iv.contains(op(m, c))
    sq = x.sqr()
    for m in (x.lo, x.hi, x.mid(), F(0) if x.contains(0) else x.lo):
        assert sq.contains(m * m)
    assert (x / 3).contains(x.mid() / 3)  # rounding to the grid keeps the enclosure


@given(st.fractions(max_denominator=10**40), st.integers(1, 100))
@FEW
def test_grid_rounding(x, bits):
    lo, hi = round_down(x, bits), round_up(x, bits)
    assert lo <= x <= hi and hi - lo <= F(1, 2**bits)
    assert (lo * 2**bits).denominator == 1 and (hi * 2**bits).denominator == 1


def test_bounds_of_limits():
    assert max_bound(None, F(1)) == F(1) and max_bound(F(2), None) == F(2) and max_bound(F(1), F(2)) == F(2)
    assert min_bound(None, F(1)) == F(1) and min_bound(F(1), F(2)) == F(1) and min_bound(None, None) is None


def test_one_core():
    """No second Interval class, π, or limit-bound helper outside nczones/exact (issue 34: one exact core).

    Doubles that reproduce a control's own arithmetic (``math.pi`` in the LinuxCNC interpreter and cutter
    compensation, the x87 sine) are not enclosures and stay where they are."""
    import re
    from pathlib import Path

    package = Path(__file__).resolve().parents[2] / "nczones"
    pattern = re.compile(r"class \w*Interval\b|^\w*Interval = |atan\(1/5\)|3\.14159|def _?(max|min)_bound\b", re.M)
    found = [f"{p.relative_to(package)}: {m.group(0)}" for p in sorted(package.rglob("*.py"))
             if p.parent.name != "exact" for m in pattern.finditer(p.read_text(encoding="utf-8"))]
    assert found == []
