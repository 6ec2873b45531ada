"""Disagreements the contract suite found, kept as minimal tests.

Each was a bug when found; the test keeps it fixed.
"""

from fractions import Fraction as F

from nczones.controller import simulate
from nczones.machine import parse_machine
from nczones.motion import Segment, SegmentKind
from tests.machines import machine_text

MACHINE = machine_text("xy_pulse_001_travel_70")


def test_periodic_alarm_reports_the_excursion_it_caught():
    m = parse_machine(MACHINE)
    axes = m.axis_names
    feed = F(3000)
    # block 0 ends one pulse below Y0 (outside); block 1 goes straight back in, then drifts out past X0
    dip = Segment(SegmentKind.LINE, (F(10), F(10)), (F(0), F(-1, 100)), axes, block=0, feed_mm_min=feed)
    back = Segment(SegmentKind.LINE, (F(0), F(-1, 100)), (F(-6, 1000), F(9365, 1000)), axes, block=1,
                   feed_mm_min=feed)
    pulse = simulate([dip, back], m, monitor="pulse")
    periodic = simulate([dip, back], m, monitor="periodic")
    assert pulse.alarms[0].block == 0  # the one-pulse dip at the end of block 0
    alarm = periodic.alarms[0]
    assert alarm.block == 1  # the dip was shorter than a period; the later excursion is caught
    # The excursion caught starts where X first rounds to -1 pulse (half way along block 1), not at the dip:
    assert alarm.first_outside != (F(0), F(-1, 100))
    assert alarm.overshoot_pulses <= 20  # 2 ms at 50 mm/s = 0.1 mm = 10 pulses (+ rounding)
