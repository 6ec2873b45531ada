"""A stepped table's questions in integers (:class:`nczones.zones.StepTable`) against the rational scans they
replaced (issue 36, table45).

``SteppedZone.box_inside``, ``region_bisect``, ``reached`` (the prover's ``reachable``) and the prover's
``box_fits`` read the table's numbers as integers over a common denominator; the functions below are the code
they replaced, region by region in ``Fraction``\\ s, kept here as the reference.  The zones mix denominators
(tenths, thirds, sevenths) so that the common denominator is not a power of ten, and the boxes sit on the
table's numbers exactly and a hair either side.
"""

from __future__ import annotations

import bisect
from dataclasses import replace
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from nczones.zones import Region, SteppedZone, StepTable, translated

from .strategies import FAST

F = Fraction


# --------------------------------------------------------------------------- the replaced code, as it was


def _ge(value, bound):
    return bound is None or value >= bound


def _le(value, bound):
    return bound is None or value <= bound


def old_box_inside(zone: SteppedZone, p, d) -> bool:
    r, lim = p[zone.reference_axis], p[zone.limited_axis]
    lo, hi = r - d, r + d
    if lo < zone.start or hi > zone.regions[-1].upto:
        return False
    for i, reg in enumerate(zone.regions):
        a, b = zone.region_lower(i), reg.upto
        touches = lo <= b and (hi >= a if i == 0 else hi > a)
        if touches and not (_ge(lim - d, reg.min) and _le(lim + d, reg.max)):
            return False
    return True


def old_reachable(zone: SteppedZone, lo, hi) -> range:
    ups = zone.uptos
    first = bisect.bisect_left(ups, lo)
    last = bisect.bisect_right(ups, hi)
    return range(first, min(last + 1, len(ups)))


def old_region_bisect(zone: SteppedZone, r):
    if r < zone.start or r > zone.regions[-1].upto:
        return None
    return bisect.bisect_left(zone.uptos, r)


# --------------------------------------------------------------------------- strategies

_DENOMINATORS = (1, 10, 1000, 3, 7, 20)


@st.composite
def rationals(draw, lo: int, hi: int) -> Fraction:
    den = draw(st.sampled_from(_DENOMINATORS))
    return F(draw(st.integers(lo * den, hi * den)), den)


@st.composite
def tables(draw, forbid: bool | None = None) -> SteppedZone:
    """A table of 1-12 regions, any denominators, some bounds missing, some rows flat."""
    start = draw(rationals(-50, 50))
    regions = []
    upto = start
    for _ in range(draw(st.integers(1, 12))):
        upto += draw(rationals(1, 30).filter(lambda q: q > 0))
        lo = draw(st.none() | rationals(-40, 40))
        hi = draw(st.none() | rationals(-40, 40) | st.just(lo))
        if lo is not None and hi is not None and lo > hi:
            lo, hi = hi, lo
        regions.append(Region(upto, lo, hi))
    is_forbid = draw(st.booleans()) if forbid is None else forbid
    return SteppedZone("t", "X", "Y", start, tuple(regions), is_forbid)


def _near(zone: SteppedZone, axis: str) -> list[Fraction]:
    if axis == zone.reference_axis:
        base = [zone.start, *zone.uptos]
    else:
        base = [v for r in zone.regions for v in (r.min, r.max) if v is not None] or [F(0)]
    return [b + k * F(1, 10**7) for b in base for k in (-1, 0, 1)]


@st.composite
def tables_and_boxes(draw, forbid: bool | None = None):
    """A table and a box ``[r0, r1] x [l0, l1]`` (``r0 <= r1``, ``l0 <= l1``) with ends on its numbers."""
    zone = draw(tables(forbid))

    def coord(axis):
        return st.sampled_from(_near(zone, axis)) | rationals(-120, 400)

    r0, r1 = sorted(draw(st.lists(coord("X"), min_size=2, max_size=2)))
    l0, l1 = sorted(draw(st.lists(coord("Y"), min_size=2, max_size=2)))
    return zone, r0, r1, l0, l1


# --------------------------------------------------------------------------- agreement


@FAST
@given(tables_and_boxes(forbid=False), st.sampled_from([F(0), F(0), F(1, 10), F(1, 3), F(2)]))
def test_box_inside_agrees_with_the_region_scan(zb, d):
    zone, r0, _, l0, _ = zb
    p = {"X": r0, "Y": l0}
    assert zone.box_inside(p, d) == old_box_inside(zone, p, d)


@FAST
@given(tables_and_boxes())
def test_reached_and_region_bisect_agree_with_rational_bisection(zb):
    zone, r0, r1, _, _ = zb
    assert zone.reached(r0, r1) == old_reachable(zone, r0, r1)
    assert zone.region_bisect(r0) == old_region_bisect(zone, r0)
    assert zone.region_bisect(r0) == zone.region_sequential(r0)[0]


@FAST
@given(tables_and_boxes(forbid=False))
def test_fits_is_the_box_inside_the_closed_set(zb):
    """``fits`` of a box is ``box_inside`` of its centre and half-width when the box is a square."""
    zone, r0, r1, l0, _ = zb
    d = (r1 - r0) / 2
    centre = {"X": r0 + d, "Y": l0 + d}
    assert zone.fits(r0, r1, l0, l0 + 2 * d) == old_box_inside(zone, centre, d)


def test_the_table_in_integers():
    z = SteppedZone("t", "X", "Y", F(-1, 2), (Region(F(1, 3), None, F(5)), Region(F(2), F(-7, 10), None),
                                               Region(F(4), F(1), F(1))))
    t = z.steps()
    assert t is z.steps()  # made once
    assert t.den == 30
    assert (t.start, t.uptos) == (-15, [10, 60, 120])
    # a missing bound reads as low/high: beyond every finite value, never "flat"
    assert t.mins == [t.low, -21, 30] and t.maxs == [150, t.high, 30]
    assert t.low < -21 and t.high > 150
    # a new zone made from it (replace, translated) makes its own table: the cache is not carried over
    moved = translated(z, {"X": F(1)})
    assert moved.steps() is not t and moved.steps().start == 15
    assert replace(z, start=F(0)).steps().start == 0
    assert z == SteppedZone("t", "X", "Y", F(-1, 2), z.regions) and hash(z) == hash(replace(z))
    assert "_steps" not in repr(z)
    assert isinstance(t, StepTable)


def test_a_missing_bound_is_no_constraint_and_flat_rows_are_not_forbidden():
    z = SteppedZone("t", "X", "Y", F(0), (Region(F(10), None, F(5)), Region(F(20), F(-3), None),
                                          Region(F(30), F(2), F(2))))
    assert z.fits(F(0), F(10), F(-10**9), F(5))
    assert not z.fits(F(0), F(10), F(-10**9), F(5) + F(1, 10**9))
    assert z.fits(F(11), F(20), F(-3), F(10**9))
    assert not z.fits(F(10), F(20), F(-3), F(6))  # the box touches region 0 at X10: its max applies
    assert z.fits(F(10) + F(1, 10**9), F(20), F(-3), F(6))
    assert z.fits(F(20) + F(1, 10**9), F(30), F(2), F(2))
    assert not z.fits(F(5), F(4), F(0), F(0))  # an inverted range is not shown to fit
    f = replace(z, forbid=True)
    assert f.rows_clear(F(21), F(29), F(-100), F(100))  # the flat row has no interior
    assert not f.rows_clear(F(19), F(21), F(0), F(1))
    assert f.rows_clear(F(0), F(9), F(5), F(9))
    assert not f.rows_clear(F(0), F(10), F(5), F(9))  # X10 reaches region 1 too (its lower end, open)


@pytest.mark.parametrize("n", [4096])
def test_a_large_table_is_read_from_its_runs(n):
    """4,096 regions: a box across all of them and one inside a single region, against the scan."""
    regions = tuple(Region(F(k + 1, 7), F(-(k % 5)), F(300 + k % 3)) for k in range(n))
    z = SteppedZone("t", "X", "Y", F(0), regions)
    for r0, r1, l0, l1 in ((F(0), F(n, 7), F(0), F(300)), (F(0), F(n, 7), F(-1), F(300)),
                           (F(3, 7), F(3, 7), F(-2), F(301)), (F(3, 7), F(22, 49), F(-2), F(301)),
                           (F(3, 7), F(22, 49), F(-3), F(301)), (F(3, 7), F(22, 49), F(-2), F(302))):
        d = (r1 - r0) / 2
        want = old_box_inside(replace(z), {"X": r0 + d, "Y": l0 + d}, d) if l1 - l0 == r1 - r0 else None
        got = z.fits(r0, r1, l0, l1)
        if want is not None:
            assert got == want
        expected = all(_ge(l0, z.regions[i].min) and _le(l1, z.regions[i].max)
                       for i in range(n) if z.region_lower(i) <= r1 and (i == 0 or z.region_lower(i) < r1)
                       and z.regions[i].upto >= r0)
        assert got == expected


@FAST
@given(tables_and_boxes(), st.integers(1, 3))
def test_a_table_made_of_integers_is_the_table(zb, extra):
    """``from_integers`` over any common denominator (here the lcm times 1, 2 or 3; a machine file's power of
    ten when read) makes the zone of those numbers, and its table answers as the one made from the Fractions."""
    zone, r0, r1, l0, l1 = zb
    den = zone.steps().den * extra

    def k(q):
        return None if q is None else q.numerator * (den // q.denominator)

    made = SteppedZone.from_integers(zone.name, "X", "Y", den, k(zone.start), [k(r.upto) for r in zone.regions],
                                     [k(r.min) for r in zone.regions], [k(r.max) for r in zone.regions],
                                     zone.forbid)
    assert made == zone
    assert all(type(v) is F for r in made.regions for v in (r.upto, r.min, r.max) if v is not None)
    assert made.steps().den == den and made.fits(r0, r1, l0, l1) == zone.fits(r0, r1, l0, l1)
    assert made.rows_clear(r0, r1, l0, l1) == zone.rows_clear(r0, r1, l0, l1)
    assert made.reached(r0, r1) == zone.reached(r0, r1)


def test_regions_made_a_column_at_a_time_are_regions():
    """``from_integers`` sets a Region's slots directly (what ``Region.__init__`` does): the same objects, as long
    as a Region is these three fields and nothing runs after its ``__init__``."""
    from nczones.precompiled import field_names
    from nczones.zones import model

    assert field_names(Region) == ("upto", "min", "max") and not hasattr(Region, "__post_init__")
    ups, lows, highs = [F(1), F(5, 2)], [None, F(-1)], [F(3), None]
    made = model._regions(ups, lows, highs)
    want = tuple(map(Region, ups, lows, highs))
    assert made == want and [hash(r) for r in made] == [hash(r) for r in want] and repr(made) == repr(want)
    assert all(type(r) is Region for r in made) and made[1].min == F(-1) and made[0].min is None
    with pytest.raises(AttributeError):
        made[0].upto = F(0)  # frozen as any Region
