"""Property tests: stepped tables against an independent reference.

The reference builds the zone as explicit half-open rectangles
``(a, b] x [min, max]`` (the first one closed at ``from``) and asks whether
any rectangle holds the point; it shares no code with the sequential scan.
"""

from __future__ import annotations

import dataclasses
from fractions import Fraction

from hypothesis import given
from hypothesis import strategies as st

from nczones.zones import AllowedSet, BoxZone, Region, SteppedZone

from .strategies import FAST, MICRON, stepped_zones, zones_and_points

F = Fraction


def rectangles(zone: SteppedZone):
    """(x_lo, x_lo_closed, x_hi, y_lo, y_hi) for each row."""
    out = []
    lower = zone.start
    for i, r in enumerate(zone.regions):
        out.append((lower, i == 0, r.upto, r.min, r.max))
        lower = r.upto
    return out


def reference_contains(zone: SteppedZone, p) -> bool:
    x, y = p[zone.reference_axis], p[zone.limited_axis]
    for x_lo, closed, x_hi, y_lo, y_hi in rectangles(zone):
        in_x = (x_lo <= x if closed else x_lo < x) and x <= x_hi
        in_y = (y_lo is None or y_lo <= y) and (y_hi is None or y <= y_hi)
        if in_x and in_y:
            return True
    return False


@FAST
@given(zones_and_points())
def test_membership_equals_half_open_rectangles(zp):
    zone, p = zp
    assert zone.contains(p) == reference_contains(zone, p)
    assert AllowedSet((zone,)).contains(p) == reference_contains(zone, p)


@FAST
@given(zones_and_points(forbid=True))
def test_forbid_table_forbids_exactly_its_interior(zp):
    zone, p = zp
    # interior by definition: a small open square around p lies in the zone
    # (the zone's numbers are multiples of 1/10 and p's of 1/1000, so a
    # neighbourhood of radius 1/10000 decides it exactly at the 9 sample points)
    e = F(1, 10000)
    around = [{"X": p["X"] + dx * e, "Y": p["Y"] + dy * e} for dx in (-1, 0, 1) for dy in (-1, 0, 1)]
    interior = all(reference_contains(zone, q) for q in around)
    assert zone.interior_contains(p) == interior
    assert AllowedSet((zone,)).contains(p) == (not interior)


@FAST
@given(stepped_zones(), st.data())
def test_sequential_comparison_equals_bisect(zone, data):
    candidates = [zone.start, *zone.uptos]
    r = data.draw(
        st.sampled_from([c + k * MICRON for c in candidates for k in (-1, 0, 1)])
        | st.integers(-2_000_000, 4_000_000).map(lambda n: F(n, 1000))
    )
    i, comparisons = zone.region_sequential(r)
    assert i == zone.region_bisect(r)
    assert comparisons <= len(zone.regions) + 1
    if i is not None:
        assert zone.region_lower(i) <= r <= zone.regions[i].upto
        assert i == 0 or r > zone.region_lower(i)


@FAST
@given(stepped_zones())
def test_sequential_comparison_counts_one_per_boundary(zone):
    """Region i is found after exactly i + 2 comparisons (from, then upto 0..i)."""
    for i, reg in enumerate(zone.regions):
        assert zone.region_sequential(reg.upto) == (i, i + 2)
    assert zone.region_sequential(zone.start - MICRON) == (None, 1)
    assert zone.region_sequential(zone.uptos[-1] + MICRON) == (None, len(zone.regions) + 1)


# ----------------------------------------------------------- margins vs brute force


def grid(p, d, axes, step):
    """Every point of the closed box of half-width d around p on an exact grid."""
    n = int(2 * d / step)
    pts = [{}]
    for a in axes:
        pts = [dict(q, **{a: p[a] - d + k * step}) for q in pts for k in range(n + 1)]
    return pts


small_ints = st.integers(-6, 6).map(F)


@st.composite
def small_stepped(draw):
    start = draw(small_ints)
    n = draw(st.integers(1, 3))
    regions, upto = [], start
    for _ in range(n):
        upto += draw(st.integers(1, 4))
        lo = draw(st.none() | small_ints)
        hi = draw(st.none() | small_ints)
        if lo is not None and hi is not None and lo > hi:
            lo, hi = hi, lo
        regions.append(Region(upto, lo, hi))
    return SteppedZone("s", "X", "Y", start, tuple(regions), forbid=draw(st.booleans()))


@st.composite
def small_box(draw):
    limits = []
    for axis in ("X", "Y"):
        lo = draw(st.none() | small_ints)
        hi = draw(st.none() | small_ints)
        if lo is not None and hi is not None and lo > hi:
            lo, hi = hi, lo
        limits.append((axis, lo, hi))
    return BoxZone("b", tuple(limits), forbid=draw(st.booleans()))


@FAST
@given(st.lists(small_stepped() | small_box(), min_size=1, max_size=3),
       small_ints, small_ints, st.integers(0, 3).map(F))
def test_contains_box_agrees_with_grid(zones, x, y, d):
    """With integer zone data, integer centre and margin, a grid of step 1/2 decides.

    A forbid interior the box meets contains a half-integer point of the box,
    and a box that leaves an allow zone has an integer point outside it.
    """
    names = [f"z{i}" for i in range(len(zones))]
    zones = tuple(dataclasses.replace(z, name=n) for n, z in zip(names, zones))
    allowed = AllowedSet(zones, tool_axis=None)
    p = {"X": x, "Y": y}
    brute = True
    for q in grid(p, d, ("X", "Y"), F(1, 2)):
        for z in zones:
            if z.forbid and z.interior_contains(q):
                brute = False
            if not z.forbid and not z.contains(q):
                brute = False
    assert allowed.contains_box(p, d) == brute
