"""Hypothesis strategies for zones (shared by the foundation tests).

All numbers are exact decimal Fractions; points are biased towards the places
where off-by-one mistakes live: every ``upto``, ``from``, ``min`` and ``max``
exactly and one micron either side.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

from nczones.zones import Region, SteppedZone

MICRON = Fraction(1, 1000)


def decimals(lo: int = -2000, hi: int = 2000, places: int = 1) -> st.SearchStrategy[Fraction]:
    """Exact decimals in [lo, hi] with ``places`` digits after the point."""
    scale = 10**places
    return st.integers(lo * scale, hi * scale).map(lambda n: Fraction(n, scale))


@st.composite
def stepped_zones(draw, max_regions: int = 6, forbid: bool | None = False) -> SteppedZone:
    """A stepped limit-value table with increasing uptos and optional min/max."""
    start = draw(decimals(-500, 500))
    n = draw(st.integers(1, max_regions))
    steps = draw(st.lists(decimals(1, 300), min_size=n, max_size=n))
    regions = []
    upto = start
    for step in steps:
        upto += step
        lo = draw(st.none() | decimals(-300, 300))
        hi = draw(st.none() | decimals(-300, 300))
        if lo is not None and hi is not None and lo > hi:
            lo, hi = hi, lo
        regions.append(Region(upto, lo, hi))
    is_forbid = draw(st.booleans()) if forbid is None else forbid
    return SteppedZone("t", "X", "Y", start, tuple(regions), forbid=is_forbid)


def boundary_values(zone: SteppedZone, axis: str) -> list[Fraction]:
    """The zone's own numbers on ``axis``, each exactly and +-1 micron."""
    if axis == zone.reference_axis:
        base = [zone.start, *zone.uptos]
    else:
        base = [v for r in zone.regions for v in (r.min, r.max) if v is not None] or [Fraction(0)]
    return [b + k * MICRON for b in base for k in (-1, 0, 1)]


def points_near(zone: SteppedZone) -> st.SearchStrategy[dict[str, Fraction]]:
    """Points biased to the zone's boundaries (and some anywhere)."""
    def coord(axis: str) -> st.SearchStrategy[Fraction]:
        return st.sampled_from(boundary_values(zone, axis)) | decimals(-1500, 3000, places=3)

    return st.fixed_dictionaries({zone.reference_axis: coord(zone.reference_axis),
                                  zone.limited_axis: coord(zone.limited_axis)})


@st.composite
def zones_and_points(draw, forbid: bool | None = False):
    zone = draw(stepped_zones(forbid=forbid))
    point = draw(points_near(zone))
    return zone, point


#: Derandomized and small, so the whole foundation suite stays fast.
FAST = settings(derandomize=True, max_examples=200, deadline=None,
                suppress_health_check=[HealthCheck.too_slow])
