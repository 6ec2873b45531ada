"""The limit monitor: exact first alarm, periodic lag bound, reverse jog, table lookup cost."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller import Controller, LimitMonitor, Settings, round_pulse, simulate
from nczones.controller.pulses import line_steps
from nczones.machine import load_machine
from nczones.zones import AllowedSet, Region, SteppedZone

from .helpers import FAST, F, decimals, line, machine

U = F(1, 1000)
GRINDER = "specs/machines/grinder.toml"
MILL = "specs/machines/mill.toml"

ZONES = """
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "-10"
regions = [
  { upto = "-2.5", min = "-4", max = "6" },
  { upto = "0.0015", min = "-1.2345", max = "3" },
  { upto = "4", max = "8.0005" },
  { upto = "10", min = "-8" },
]
[[zones]]
name = "z travel"
kind = "box"
min = { Z = "-5" }
max = { Z = "5.0004" }
[[zones]]
name = "clamp"
kind = "box"
forbid = true
point = "tip"
min = { X = "1", Y = "1", Z = "-2" }
max = { X = "2.5", Y = "2", Z = "0" }
"""


def _m():
    return machine(ZONES)


points = st.tuples(decimals(-11, 11, 4), decimals(-9, 9, 4), decimals(-6, 6, 4))


@FAST
@given(st.lists(points, min_size=1, max_size=30), st.sampled_from([F(0), F("1.5"), F("-0.0005")]))
def test_compiled_check_equals_reference_membership(pts, tool_length):
    m = _m()
    mon = LimitMonitor(m)
    comp = mon.compile(tool_length)
    pos = np.array([[round_pulse(v, U) for v in p] for p in pts], dtype=np.int64)
    bad = comp.bad(pos)
    for row, b in zip(pos.tolist(), bad.tolist()):
        ref = mon.check(tuple(row), tool_length)
        assert b == bool(ref)
        point = {a: v * U for a, v in zip("XYZ", row)}
        assert b == (not m.allowed.contains(point, tool_length))  # the zones model agrees


@FAST
@given(st.data())
def test_stepped_lookup_makes_at_most_regions_plus_one_comparisons(data):
    n = data.draw(st.integers(1, 12))
    uptos = sorted(set(data.draw(st.lists(st.integers(-500, 500), min_size=n, max_size=n))))
    start = uptos[0] - data.draw(st.integers(1, 50))
    zone = SteppedZone("t", "X", "Y", F(start), tuple(Region(F(u), F(-1), F(1)) for u in uptos))
    for r in data.draw(st.lists(st.integers(-600, 600), min_size=1, max_size=20)):
        region, comparisons = zone.region_sequential(F(r))
        assert comparisons <= len(uptos) + 1
    mon = LimitMonitor(dataclasses.replace(machine(), allowed=AllowedSet((zone,))))
    for r in range(start - 2, uptos[-1] + 3, max(1, (uptos[-1] - start) // 40)):
        mon.check((r * 1000, 0, 0), F(0))
    assert 1 <= mon.stats.max_lookup_comparisons <= len(uptos) + 1


segments = st.tuples(points, points, st.sampled_from([F(0), F("1.5")]))


def _first_outside(m, seg):
    p0 = tuple(round_pulse(v, U) for v in seg.start)
    p1 = tuple(round_pulse(v, U) for v in seg.end)
    for p in line_steps(p0, p1):
        if not m.allowed.contains({a: v * U for a, v in zip("XYZ", p)}, seg.tool_length):
            return p
    return None


@settings(FAST, max_examples=20)
@given(segments)
def test_per_pulse_monitor_alarms_at_the_first_pulse_outside(case):
    a, b, tl = case
    m = _m()
    seg = line(a, b, tool_length=tl)
    start_ok = m.allowed.contains({k: round_pulse(v, U) * U for k, v in zip("XYZ", a)}, tl)
    expected = _first_outside(m, seg)
    for engine in ("vector", "reference"):
        r = simulate([seg], m, settings=Settings(engine=engine))
        if not start_ok:
            assert r.alarms and r.alarms[0].block is None  # the start itself is outside
            continue
        if expected is None:
            assert not r.alarms and r.completed
        else:
            assert r.alarms[0].pulse_position == expected
            assert r.machine_position == tuple(v * U for v in expected)  # distribution stopped there


def test_vectorized_long_line_same_first_alarm_pulse_as_per_pulse_loop():
    m = load_machine(GRINDER)
    seg = line((0, 250), ("1199.9996", "99.0003"), axes=("X", "Y"))
    seg = seg.__class__(**{**{f: getattr(seg, f) for f in seg.__slots__}, "start": (F(0), F(250)), "end": (F("1199.9996"), F("99.0003"))})
    vec = simulate([seg], m, settings=Settings(engine="vector"))
    ref = simulate([seg], m, settings=Settings(engine="reference"))
    assert vec.alarms[0].pulse_position == ref.alarms[0].pulse_position
    assert vec.alarms[0].zone == ref.alarms[0].zone == "wheel area"
    assert vec.pulses == ref.pulses and vec.steps == ref.steps > 0


@settings(FAST, max_examples=20)
@given(segments, st.sampled_from(["60", "600", "3000"]))
def test_periodic_monitor_alarms_within_one_period_of_travel(case, feed):
    a, b, tl = case
    m = _m()
    if not m.allowed.contains({k: round_pulse(v, U) * U for k, v in zip("XYZ", a)}, tl):
        return
    seg = line(a, b, tool_length=tl, feed=feed)
    expected = _first_outside(m, seg)
    r = simulate([seg], m, monitor="periodic")
    if expected is None:
        assert not r.alarms
        return
    assert r.alarms, "periodic sampling must catch a motion that ends outside or stays outside"
    al = r.alarms[0]
    p0 = tuple(round_pulse(v, U) for v in seg.start)
    p1 = tuple(round_pulse(v, U) for v in seg.end)
    steps = list(line_steps(p0, p1))
    i_first = steps.index(expected)
    i_alarm = steps.index(al.pulse_position) if al.pulse_position in steps else len(steps) - 1
    assert i_alarm >= i_first
    # steps per monitor period at this feed, plus one pulse
    n = len(steps)
    length = math.dist([float(v) for v in seg.start], [float(v) for v in seg.end])
    per_period = n * (float(feed) / 60 * float(m.monitor_period_ms) / 1000) / length
    assert i_alarm - i_first <= per_period + 1
    # and the distance travelled past the first outside pulse is at most feed x period (+1 pulse)
    travel = math.dist([float(v * U) for v in expected], [float(v * U) for v in al.pulse_position])
    assert travel <= float(feed) / 60 * float(m.monitor_period_ms) / 1000 + 2 * 0.001
    assert r.overshoot_bound_mm == pytest.approx(float(feed) / 60 * float(m.monitor_period_ms) / 1000)
    assert al.first_outside == tuple(v * U for v in expected)


@FAST
@given(st.data())
def test_compiled_stepped_table_on_chunks_within_one_row_and_across_rows(data):
    """A chunk whose reference-axis positions all lie in one row takes that row's limits at once; the answer
    is the reference monitor's for every position, whether the chunk stays in a row, spans rows, or starts
    before the table."""
    uptos = sorted(set(data.draw(st.lists(st.integers(-400, 400), min_size=1, max_size=8))))
    start = uptos[0] - data.draw(st.integers(0, 30))
    bound = st.one_of(st.none(), st.integers(-60, 60))
    regions = []
    for u in uptos:
        lo, hi = data.draw(bound), data.draw(bound)
        if lo is not None and hi is not None and lo > hi:
            lo, hi = hi, lo
        regions.append(Region(F(u), None if lo is None else F(lo), None if hi is None else F(hi)))
    zone = SteppedZone("t", "X", "Y", F(start), tuple(regions))
    mon = LimitMonitor(dataclasses.replace(machine(), allowed=AllowedSet((zone,))))
    comp = mon.compile(F(0))
    # a band of X (often inside one row) walked in Y, as a chunk of a plan sees it
    x0 = data.draw(st.integers(start - 40, uptos[-1] + 40)) * 1000
    width = data.draw(st.sampled_from([0, 1, 500, 20_000, 900_000]))
    xs = data.draw(st.lists(st.integers(x0, x0 + width), min_size=1, max_size=40))
    ys = data.draw(st.lists(st.integers(-80_000, 80_000), min_size=len(xs), max_size=len(xs)))
    pos = np.array([[x, y, 0] for x, y in zip(xs, ys)], dtype=np.int64)
    expected = [bool(mon.check(tuple(row), F(0))) for row in pos.tolist()]
    assert comp.bad(pos).tolist() == expected


@settings(FAST, max_examples=15)
@given(segments, st.sampled_from([1, 7, 64, 4096]))
def test_first_alarm_pulse_does_not_depend_on_the_monitor_chunk(case, chunk):
    """The vectorized monitor checks a plan in chunks; where the chunks end changes nothing: the alarm is at
    the first pulse outside (the per-pulse reference loop's)."""
    import nczones.controller.simulator as simulator

    a, b, tl = case
    m = _m()
    seg = line(a, b, tool_length=tl)
    ref = simulate([seg], m, settings=Settings(engine="reference"))
    saved = simulator.LINE_CHUNK
    simulator.LINE_CHUNK = chunk
    try:
        vec = simulate([seg], m, settings=Settings(engine="vector"))
    finally:
        simulator.LINE_CHUNK = saved
    assert [(al.pulse_position, al.zone) for al in vec.alarms] == [(al.pulse_position, al.zone) for al in ref.alarms]
    assert vec.pulses == ref.pulses and vec.steps == ref.steps


def test_reverse_jog_moves_and_forward_jog_does_not():
    m = load_machine(GRINDER)
    down = line((300, 300), (300, 100), axes=("X", "Y"))
    ctl = Controller(m, start=(F(300), F(300)))
    r = ctl.run([down])
    assert r.alarms[0].pulse_position == (300_000, 219_999)
    assert r.alarms[0].blocked == (("Y", -1),)
    fwd = ctl.jog("Y", -10)
    assert fwd.refused and fwd.moved == 0 and ctl.real == [300_000, 219_999]
    back = ctl.jog("Y", 3)
    assert not back.refused and back.moved == 3 and ctl.real == [300_000, 220_002]
    assert not ctl.blocked  # inside again: the direction register is restored
    events = [e.kind for e in ctl.result().events]
    assert events.count("alarm") == 1 and "jog-refused" in events and "alarm-cleared" in events
    # once inside, going out by jog raises a new alarm and stops the jog there
    out = ctl.jog("Y", -10)
    assert out.alarm is not None and out.moved == 3 and ctl.real == [300_000, 219_999]


def test_jog_sideways_while_outside_is_accepted_but_forward_is_not():
    m = load_machine(GRINDER)
    ctl = Controller(m, start=(F(300), F(300)))
    ctl.run([line((300, 300), (300, 100), axes=("X", "Y"))])
    assert ctl.jog("X", 1000).moved == 1000  # along the boundary, still outside: accepted
    assert ctl.jog("Y", -1).refused


def test_polygon_zones_use_the_reference_monitor():
    m = machine("""
[[zones]]
name = "tri"
kind = "polygon"
plane = ["X", "Y"]
vertices = [["0", "0"], ["10", "0"], ["0", "10"]]
""")
    r = simulate([line((1, 1, 0), (9, 9, 0))], m)
    assert r.alarms[0].zone == "tri"
    assert r.alarms[0].pulse_position == (5_001, 5_001, 0)


def test_tip_zone_subtracts_tool_length():
    m = load_machine(MILL)
    # spindle nose at Z 200 over the vise with H1 = 120: the tip is at Z80 inside the vise (50..130)
    segs = [line((120, 100, 260), (120, 100, 200), tool_length=F(120))]
    assert simulate(segs, m).alarms[0].zone == "vise"
    assert not simulate([line((120, 100, 260), (120, 100, 200), tool_length=F(0))], m).alarms
