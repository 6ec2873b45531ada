"""Modes: check = normal on alarms, real coordinates untouched, faster; lock is blind; acc/dec."""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller import Mode, Settings, simulate
from nczones.machine import load_machine
from nczones.motion import SegmentKind

from .helpers import FAST, F, arc, decimals, line

GRINDER = load_machine("specs/machines/grinder.toml")
XY = ("X", "Y")


def _program(points, feed, with_arc):
    segs, here = [], (F(1150), F(300))
    for i, p in enumerate(points):
        kind = SegmentKind.RAPID if i == 0 else SegmentKind.LINE
        segs.append(line(here, p, block=i, feed=feed, kind=kind, axes=XY))
        here = p
    if with_arc:  # a half circle down and back up towards -X
        end = (here[0] - 10, here[1])
        segs.append(arc(here, end, (here[0] - 5, here[1]), clockwise=False, block=len(segs), feed=feed, axes=XY))
    return segs


programs = st.tuples(
    st.lists(st.tuples(decimals(5, 1195, 1), decimals(60, 300, 1)), min_size=1, max_size=4),
    st.sampled_from(["50", "500", "2500"]),
    st.booleans(),
)


@settings(FAST, max_examples=20)
@given(programs)
def test_check_mode_raises_the_same_alarms_leaves_machine_coordinates_and_is_faster(case):
    pts, feed, with_arc = case
    segs = _program(pts, feed, with_arc)
    normal = simulate(segs, GRINDER)
    check = simulate(segs, GRINDER, mode="check")
    assert [(a.block, a.zone, a.position) for a in check.alarms] == [(a.block, a.zone, a.position) for a in normal.alarms]
    assert check.machine_position == (F(1150), F(300))  # the real axes never moved
    assert check.temporary_position == normal.machine_position  # the temporary coordinates did
    assert check.servo_pulses == (0, 0) and check.pulses == normal.pulses
    assert check.simulated_time_s <= normal.simulated_time_s
    fed = sum(dict(e.data)["steps"] for e in normal.events
              if e.kind == "motion" and dict(e.data)["kind"] in ("line", "arc"))
    if fed > 1000:  # feed moves ran: they run at the system maximum in check mode
        assert check.simulated_time_s < normal.simulated_time_s
        if feed == "50":
            assert check.simulated_time_s * 10 < normal.simulated_time_s  # far shorter for slow feeds


def test_lock_raises_no_stroke_alarm_side_by_side():
    # down to Y100 over the work head (region 2 allows Y >= 220): a violation
    segs = [line((1150, 300), (300, 300), kind=SegmentKind.RAPID, axes=XY),
            line((300, 300), (300, 100), block=1, feed="500", axes=XY)]
    normal = simulate(segs, GRINDER)
    lock = simulate(segs, GRINDER, mode="lock")
    check = simulate(segs, GRINDER, mode="check")
    assert normal.alarms and normal.alarms[0].block == 1
    assert not lock.alarms and lock.completed
    assert lock.machine_position == (F(1150), F(300)) and lock.servo_pulses == (0, 0)
    assert "no alarm" in lock.blind_spot and "frozen" in lock.blind_spot
    assert check.alarms[0].position == normal.alarms[0].position
    assert lock.program_position == (F(300), F(100))  # the interpolation itself ran to the end


def test_mode_changes_and_motions_are_in_the_event_log():
    segs = _program([(F(500), F(250)), (F(600), F(200))], "1000", True)
    r = simulate(segs, GRINDER, mode="check")
    kinds = [e.kind for e in r.events]
    assert kinds[0] == "mode" and dict(r.events[0].data)["mode"] == "check"
    assert kinds.count("motion") == len(segs) and kinds[-1] == "end"
    assert r.completed and r.simulated_time_s > 0


def test_pre_interpolation_accdec_lengthens_every_block():
    segs = [line((500, 300), (600, 300), feed="600", axes=XY), line((600, 300), (600, 250), block=1, feed="600", axes=XY)]
    plain = simulate(segs, GRINDER)
    ramped = simulate(segs, GRINDER, settings=Settings(pre_time_constant_ms=F(100)))
    assert ramped.simulated_time_s == pytest.approx(plain.simulated_time_s + 2 * 0.1)
    assert ramped.pulses == plain.pulses and ramped.machine_position == plain.machine_position
    check = simulate(segs, GRINDER, mode="check", settings=Settings(pre_time_constant_ms=F(100)))
    assert check.simulated_time_s < plain.simulated_time_s  # acc/dec skipped, maximum feed


def test_post_interpolation_filter_rounds_the_corner_but_not_the_straight():
    straight = [line((500, 300), (600, 300), feed="3000", axes=XY)]
    corner = straight + [line((600, 300), (600, 200), block=1, feed="3000", axes=XY)]
    for filt in ("exponential", "linear"):
        s = Settings(post_time_constant_ms=F(30), post_filter=filt)
        r_s = simulate(straight, GRINDER, settings=s)
        r_c = simulate(corner, GRINDER, settings=s)
        assert r_s.servo.max_deviation_mm < 0.01
        assert r_c.servo.max_deviation_mm > 0.1  # the filtered output cuts the corner
        assert r_c.machine_position == (F(600), F(200))  # the counter follows the pulses, not the filter
        assert r_c.servo.output_mm[-1] == pytest.approx([600, 200], abs=1e-3)  # it settles at the end


def test_result_is_frozen():
    r = simulate([line((500, 300), (510, 300), axes=XY)], GRINDER)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.mode = Mode.LOCK
