"""The prover's ``box_fits`` on stepped tables in integers against the rational region scan it replaced
(issue 36, table45): the same answer on every box, allow and forbid tables, with margins and tip shifts."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import given
from hypothesis import strategies as st

from nczones.prover.exact import box_fits, reachable
from nczones.zones import AllowedSet, Region, SteppedZone, ZonePoint
from tests.zones.strategies import FAST
from tests.zones.test_step_table import old_reachable, tables_and_boxes

F = Fraction


def old_stepped_box_fits(z: SteppedZone, r0, r1, l0, l1) -> bool:
    """``prover.exact._stepped_box_fits`` as it was: region by region, in Fractions."""
    if z.forbid:
        for i in old_reachable(z, r0, r1):
            reg = z.regions[i]
            if reg.min is not None and reg.min == reg.max:
                continue
            if not ((reg.max is not None and l0 >= reg.max) or (reg.min is not None and l1 <= reg.min)):
                return False
    else:
        if r0 < z.start or r1 > z.regions[-1].upto:
            return False
        for i in old_reachable(z, r0, r1):
            reg = z.regions[i]
            if i > 0 and r1 <= z.regions[i - 1].upto:
                continue
            if (reg.min is not None and l0 < reg.min) or (reg.max is not None and l1 > reg.max):
                return False
    return True


@FAST
@given(tables_and_boxes(), st.sampled_from([F(0), F(0), F(1, 10), F(1, 3)]))
def test_box_fits_agrees_with_the_region_scan(zb, margin):
    zone, r0, r1, l0, l1 = zb
    allowed = AllowedSet((zone,), tool_axis=None)
    want = old_stepped_box_fits(zone, r0 - margin, r1 + margin, l0 - margin, l1 + margin)
    assert box_fits(allowed, {"X": r0, "Y": l0}, {"X": r1, "Y": l1}, margin, F(0)) == want
    assert reachable(zone, r0, r1) == old_reachable(zone, r0, r1)


@FAST
@given(tables_and_boxes(), st.sampled_from([F(0), F(5, 2)]))
def test_a_tip_table_sees_the_box_less_the_tool_length(zb, tool_length):
    zone, r0, r1, l0, l1 = zb
    tip = SteppedZone(zone.name, "X", "Z", zone.start, zone.regions, zone.forbid, ZonePoint.TIP)
    allowed = AllowedSet((tip,), tool_axis="Z")
    want = old_stepped_box_fits(tip, r0, r1, l0 - tool_length, l1 - tool_length)
    assert box_fits(allowed, {"X": r0, "Z": l0}, {"X": r1, "Z": l1}, F(0), tool_length) == want


def test_a_table_of_4096_regions_in_one_box():
    """The benchmark's shape: one box across every region, fitting and one hair too wide or too deep."""
    regions = tuple(Region(F(k + 1) * F(976562, 10**6), F(-1 - k % 7), F(300 + k % 5)) for k in range(4096))
    zone = SteppedZone("table", "X", "Y", F(0), regions)
    allowed = AllowedSet((zone,))
    hair = F(1, 10**9)
    answers = []
    for lo, hi in (((F(0), F(-1)), (regions[-1].upto, F(300))),  # the largest min and the smallest max
                   ((F(0), F(-1) - hair), (regions[-1].upto, F(300))),
                   ((F(0), F(-1)), (regions[-1].upto, F(300) + hair)),
                   ((F(0), F(-1)), (regions[-1].upto + hair, F(300))),
                   ((F(10), F(-4)), (F(21, 2), F(300))),  # within region 10
                   ((F(10), F(-4) - hair), (F(21, 2), F(300)))):
        box_lo, box_hi = {"X": lo[0], "Y": lo[1]}, {"X": hi[0], "Y": hi[1]}
        got = box_fits(allowed, box_lo, box_hi, F(0), F(0))
        assert got == old_stepped_box_fits(zone, lo[0], hi[0], lo[1], hi[1])
        answers.append(got)
    assert answers == [True, False, False, False, True, False]
