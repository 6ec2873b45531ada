"""Streamed arc plans (controller/arcs.py ArcStream): any chunking gives the reference plan and the same stop.

The oracle is the reference engine: the per-step walk (``pulses.arc_walk``), the helix columns on the whole
array and the per-step helix interleave (``pulses.helix_steps``), monitored pulse by pulse in Python.
"""

from __future__ import annotations

from contextlib import contextmanager
from dataclasses import replace

import numpy as np
from hypothesis import event, given, settings
from hypothesis import strategies as st

from nczones.controller import Controller, Settings, simulate
from nczones.controller import arcs as arcs_mod
from nczones.controller.pulses import arc_centre
from nczones.exact import format_decimal
from nczones.motion import PLANE_AXES, Plane
from tests.sizes import examples

from .helpers import FAST, F, arc, decimals, machine, rationals

AXES = ("X", "Y", "Z")


@contextmanager
def _chunk(size: int):
    old = arcs_mod.STREAM_CHUNK
    arcs_mod.STREAM_CHUNK = size
    try:
        yield
    finally:
        arcs_mod.STREAM_CHUNK = old


def _pyth(c, r, t):
    return (c[0] + r * (1 - t * t) / (1 + t * t), c[1] + r * 2 * t / (1 + t * t))


arc_cases = st.tuples(
    st.sampled_from([Plane.XY, Plane.XZ, Plane.YZ]), st.booleans(), st.integers(0, 1),
    st.integers(60, 1000).map(lambda n: F(n, 1000)), rationals(-3, 3), rationals(-3, 3), st.booleans(),
    st.one_of(st.just(F(0)), decimals(-1, 1), decimals(-6, 6)),  # no helix, a gentle one, a steep one
    decimals(-2, 2), decimals(-2, 2), st.sampled_from(["centre", "R", "spiral"]),
)


def _segment(case):
    plane, cw, turns, r, ts, te, full, dz, cx, cy, form = case
    a, b, n = PLANE_AXES[plane]
    ia, ib, iz = AXES.index(a), AXES.index(b), AXES.index(n)
    s2 = _pyth((cx, cy), r, ts)
    e2 = s2 if full or form == "R" and ts == te else _pyth((cx, cy), r, te)
    if form == "spiral":  # the end radius differs from the start radius (I/J spirals): the walk corrects inwards
        e2 = _pyth((cx, cy), r * F(3, 4), te)
    start, end = [F(0)] * 3, [F(0)] * 3
    start[ia], start[ib], end[ia], end[ib] = s2[0], s2[1], e2[0], e2[1]
    end[iz] = dz
    if form == "R" and s2 != e2:  # an irrational centre (64-bit enclosure): the walk needs Python integers
        return arc(start, end, None, plane=plane, clockwise=cw, radius=r if turns else -r), ia, ib
    return arc(start, end, (cx, cy), plane=plane, clockwise=cw, turns=turns), ia, ib


def _octant_and_helix_changes(pos, p0, ia, ib, centre, pulse):
    """Planar step counts after which the octant of the position or the helix column changes."""
    rows = np.vstack([np.array(p0, dtype=np.int64), pos])
    plane_moved = np.any(np.diff(rows[:, [ia, ib]], axis=0) != 0, axis=1)
    planar = np.cumsum(plane_moved)  # planar steps done after each row
    u = rows[1:, ia] * float(pulse[ia]) - float(centre[0])
    v = rows[1:, ib] * float(pulse[ib]) - float(centre[1])
    octant = (np.arctan2(v, u) // (np.pi / 4)).astype(np.int64)
    helix = rows[1:, 3 - ia - ib]
    at = np.flatnonzero((np.diff(octant) != 0) | (np.diff(helix) != 0)) + 1
    return sorted({int(planar[k]) for k in at})


#: unequal pulses per axis: the walk's angle is not monotone everywhere, the helix columns see it
PULSES = [None, 'pulse = { X = "0.001", Y = "0.002", Z = "0.0005" }', 'pulse = { X = "0.0005", Y = "0.001", Z = "0.003" }']


@settings(FAST, max_examples=examples(22, 45))
@given(arc_cases, st.sampled_from(PULSES), st.data())
def test_any_chunking_of_the_stream_gives_the_reference_plan(case, pulses, data):
    seg, ia, ib = _segment(case)
    m = machine(axes_pulse=pulses)
    ref = Controller(m, start=seg.start, settings=Settings(engine="reference")).plan(seg)
    centre = seg.centre
    if centre is None:
        centre, _ = arc_centre((seg.start[ia], seg.start[ib]), (seg.end[ia], seg.end[ib]), seg.radius, seg.clockwise)
    changes = _octant_and_helix_changes(ref.positions, ref.p0, ia, ib, centre, [a.pulse for a in m.axes]) or [1]
    at = data.draw(st.sampled_from(changes))
    size = data.draw(st.one_of(st.sampled_from([1, 2, 3]), st.integers(4, 4096),
                               st.sampled_from([max(at - 1, 1), max(at, 1), at + 1])))
    with _chunk(size):
        ctl = Controller(m, start=seg.start)
        explicit = ctl.plan(seg)  # the stream's chunks, concatenated
        lazy = ctl.plan(seg, lazy=True)
        parts = None if lazy.stream is None else [c.copy() for c in lazy.stream.chunks()]
        streamed = simulate([seg], m)
    assert np.array_equal(explicit.positions, ref.positions)
    assert np.array_equal(explicit.sigma, ref.sigma) and explicit.moved_total == ref.moved_total
    if parts is not None:  # a lazy plan (the vectorized walk): what a run streams
        assert all(len(p) for p in parts)
        assert np.array_equal(np.vstack(parts), ref.positions)
    whole = simulate([seg], m, settings=Settings(engine="reference"))
    assert (streamed.pulses, streamed.steps, streamed.program_position) == (whole.pulses, whole.steps,
                                                                           whole.program_position)
    assert streamed.simulated_time_s == whole.simulated_time_s


ZONE = """
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "-{xmin}", Y = "-50", Z = "-{zlim}" }}
max = {{ X = "50", Y = "{ymax}", Z = "{zlim}" }}
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "-50"
regions = [{{ upto = "{step}", max = "50" }}, {{ upto = "50", max = "{cap}" }}]
"""


@settings(FAST, max_examples=30)
@given(arc_cases, st.lists(decimals(0, 2), min_size=5, max_size=5), st.sampled_from(["normal", "check", "lock"]),
       st.data())
def test_the_monitor_stops_a_streamed_arc_at_the_reference_pulse_for_any_chunking(case, limits, mode, data):
    seg, _, _ = _segment(case)
    seg = replace(seg, start=tuple(v - s for v, s in zip(seg.start, seg.start)),  # start at X0 Y0 Z0 (inside)
                  end=tuple(v - s for v, s in zip(seg.end, seg.start)),
                  centre=None if seg.centre is None else _plane_shift(seg, seg.centre))
    xmin, ymax, zlim, step, cap = (format_decimal(v) for v in limits)
    m = machine(ZONE.format(xmin=xmin, ymax=ymax, zlim=zlim, step=step, cap=cap))
    whole = simulate([seg], m, mode=mode, settings=Settings(engine="reference"))
    done = whole.steps
    event(f"alarm: {bool(whole.alarms)}, steps: {'0' if not done else '<100' if done < 100 else '100+'}")
    size = data.draw(st.one_of(st.sampled_from([1, 2, 3]), st.integers(4, 4096),
                               st.sampled_from([done + 1, done + 5, done // 2 + 1, max(done // 3, 1)])))
    with _chunk(size):
        streamed = simulate([seg], m, mode=mode)
    assert [(a.pulse_position, a.zones, a.blocked, a.block, a.time_s) for a in streamed.alarms] \
        == [(a.pulse_position, a.zones, a.blocked, a.block, a.time_s) for a in whole.alarms]
    assert (streamed.pulses, streamed.steps, streamed.program_position, streamed.machine_position) \
        == (whole.pulses, whole.steps, whole.program_position, whole.machine_position)
    assert streamed.simulated_time_s == whole.simulated_time_s
    assert streamed.temporary_position == whole.temporary_position


def _plane_shift(seg, centre):
    ia, ib, _ = seg.plane_indices()
    return (centre[0] - seg.start[ia], centre[1] - seg.start[ib])


def test_a_long_helix_streams_without_keeping_its_positions():
    """A 1.1 M-step helix runs through the stream: the plan keeps its step count and pulse totals only."""
    m = machine()
    seg = arc((F(180), F(0), F(0)), (F(180), F(0), F(7)), (0, 0))
    ctl = Controller(m, start=seg.start)
    plan = ctl.plan(seg, lazy=True)
    ctl.run_plan(seg, plan)
    assert plan.streamed and plan.positions is None and plan.n > 1_000_000
    assert ctl.prog == [180_000, 0, 7_000] and ctl.pulses[2] == 7_000
    explicit = Controller(m, start=seg.start).plan(seg)
    assert plan.n == explicit.n and plan.moved_total == explicit.moved_total
