"""The screen's constants of a stepped table, read from its integer table, against :func:`_scaled` of each of its
Fractions, as the screen read them before (issue 36, table45): every scale, both roundings, missing limits and
numbers beyond the int64 clamp."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from nczones.prover.screen import _NEG, _POS, _scaled, _ZoneConstants
from nczones.zones import Region, SteppedZone
from tests.zones.strategies import FAST
from tests.zones.test_step_table import tables

F = Fraction


def old_constants(z: SteppedZone, s: int) -> dict[str, list[int]]:
    """``_ZoneConstants``' columns as they were computed: ``_scaled`` of each Fraction."""
    out = {"ups_dn": [_scaled(r.upto, s, False, 0) for r in z.regions],
           "ups_up": [_scaled(r.upto, s, True, 0) for r in z.regions]}
    if z.forbid:
        out["mins"] = [_scaled(r.min, s, False, _NEG) for r in z.regions]
        out["maxs"] = [_scaled(r.max, s, True, _POS) for r in z.regions]
    else:
        out["mins"] = [_scaled(r.min, s, True, _NEG) for r in z.regions]
        out["maxs"] = [_scaled(r.max, s, False, _POS) for r in z.regions]
    return out


def check(z: SteppedZone, s: int) -> None:
    got = _ZoneConstants(z, s)
    want = old_constants(z, s)
    assert got.ups_dn.tolist() == want["ups_dn"] and got.ups_up.tolist() == want["ups_up"]
    assert (got.start_dn, got.start_up) == (_scaled(z.start, s, False, _NEG), _scaled(z.start, s, True, _NEG))
    n = len(z.regions)
    assert got.min_t.flat[:n].tolist() == want["mins"] and got.max_t.flat[:n].tolist() == want["maxs"]


@FAST
@given(tables(), st.integers(0, 12))
def test_the_screen_constants_are_the_scaled_fractions(zone, s):
    check(zone, s)


def test_numbers_beyond_int64_are_clamped_as_before():
    big = F(10**25, 3)
    z = SteppedZone("t", "X", "Y", -big, (Region(F(1, 7), -big, None), Region(big, None, big)))
    for s in (0, 6, 12):
        check(z, s)
        check(SteppedZone("t", "X", "Y", z.start, z.regions, forbid=True), s)
    got = _ZoneConstants(z, 12)
    assert got.ups_up.tolist()[-1] == _POS and got.min_t.flat[0] == _NEG
    assert np.array_equal(got.ups_dn, np.array([142857142857, _POS]))
