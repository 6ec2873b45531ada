"""A stepped table's point depth (``exact._stepped_depth``) from the regions near the point, the allowed table's
eroded rectangles built once and searched outwards (issue 36: a 12-line program violating a 4,096-region table
ran past 100 s, each of thousands of depth points walking every region).

Held to the former code, kept here as the reference: every region walked, the rectangles rebuilt over every
region for every span, the least distance over all of them.
"""

from __future__ import annotations

from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.prover import exact as ex
from nczones.zones import Region, SteppedZone
from tests.sizes import examples

small = st.fractions(min_value=-30, max_value=30, max_denominator=4)


def former_eroded_rects(zone, d):
    regs = zone.regions
    cuts = sorted({zone.start + d, regs[-1].upto - d} | {r.upto + s for r in regs for s in (-d, d)})
    cuts = [c for c in cuts if zone.start + d <= c <= regs[-1].upto - d]
    rects = []
    for a, b in [(c, c) for c in cuts] + list(zip(cuts, cuts[1:])):
        mid = (a + b) / 2
        lo_r, hi_r = mid - d, mid + d
        los, his = [], []
        for i, reg in enumerate(regs):
            ra, rb = zone.region_lower(i), reg.upto
            if lo_r <= rb and (hi_r >= ra if i == 0 else hi_r > ra):
                if reg.min is not None:
                    los.append(reg.min + d)
                if reg.max is not None:
                    his.append(reg.max - d)
        lo = max(los) if los else None
        hi = min(his) if his else None
        if lo is None or hi is None or lo <= hi:
            rects.append(((a, b), (lo, hi)))
    return rects


def former_depth(zone, q, d):
    if zone.forbid:
        best = F(0)
        for i, reg in enumerate(zone.regions):
            if reg.min is not None and reg.max is not None and not reg.min < reg.max:
                continue
            rect = ((zone.region_lower(i) - d, reg.upto + d),
                    (None if reg.min is None else reg.min - d, None if reg.max is None else reg.max + d))
            slacks = [q[0] - rect[0][0], rect[0][1] - q[0]]
            if rect[1][0] is not None:
                slacks.append(q[1] - rect[1][0])
            if rect[1][1] is not None:
                slacks.append(rect[1][1] - q[1])
            best = max(best, min(slacks))
        return best
    rects = former_eroded_rects(zone, d)
    if not rects:
        return F(0)
    return min(ex._rect_dist(q, r) for r in rects)


@st.composite
def tables(draw):
    start = draw(small)
    widths = draw(st.lists(st.fractions(min_value=F(1, 4), max_value=12, max_denominator=4), min_size=1, max_size=9))
    regions, upto = [], start
    for w in widths:
        upto += w
        lo, hi = sorted((draw(small), draw(small)))
        if draw(st.integers(0, 5)) == 0:
            hi = lo  # a flat row
        regions.append(Region(upto, lo if draw(st.integers(0, 4)) else None, hi if draw(st.integers(0, 4)) else None))
    return SteppedZone("t", "X", "Y", start, tuple(regions), forbid=draw(st.booleans()))


@settings(max_examples=examples(200, 2000), deadline=None)
@given(zone=tables(), x=st.fractions(min_value=-60, max_value=120, max_denominator=8), y=small,
       d=st.sampled_from((F(0), F(1, 4), F(1), F(5, 2), F(40))))
def test_the_depth_is_the_former_one(zone, x, y, d):
    assert ex.point_depth(zone, {"X": x, "Y": y}, d) == former_depth(zone, (x, y), d)


@settings(max_examples=examples(60, 600), deadline=None)
@given(zone=tables(), d=st.sampled_from((F(0), F(1, 4), F(5, 2), F(40))))
def test_the_rectangles_are_the_former_ones_in_order(zone, d):
    got, ends = ex._eroded(zone, d)
    assert sorted(got) == sorted(former_eroded_rects(zone, d)) and got == sorted(got)
    assert ends == [r[0][1] for r in got]


def test_large_tables_give_the_former_depths():
    """A 4,096-region forbidden table and a 300-region allowed one (the former allowed code is quadratic in the
    regions: the reference is kept small), points in, across and beyond them."""
    for n, forbid in ((4096, True), (300, False)):
        regions = tuple(Region(F(k + 1), F(-(k % 7) - 1), F(300 + k % 5)) for k in range(n))
        zone = SteppedZone("t", "X", "Y", F(0), regions, forbid=forbid)
        for x, y in ((F(n - 1, 2), F(10)), (F(100), F(301)), (F(n - 96), F(-9)), (F(-3), F(0)), (F(n + 2), F(7))):
            assert ex.point_depth(zone, {"X": x, "Y": y}, F(1, 2)) == former_depth(zone, (x, y), F(1, 2))
