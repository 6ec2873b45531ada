"""Pulse distribution: deviation <= one pulse per axis, exact sums, circles close, dogleg ends."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from nczones.controller import Controller, round_pulse, simulate
from nczones.controller.pulses import arc_centre, line_chunk, line_steps, step_deltas
from nczones.motion import PLANE_AXES, Plane, SegmentKind

from .helpers import FAST, F, arc, decimals, line, machine, rationals

U = F(1, 1000)


def _plan(ctl, seg):
    ctl.prog[:] = [round_pulse(v, u) for v, u in zip(seg.start, ctl.pulse)]
    return ctl.plan(seg)


@FAST
@given(st.lists(st.tuples(rationals(-4, 4), rationals(-4, 4)), min_size=1, max_size=4))
def test_line_deviation_at_most_one_pulse_and_exact_end(coords):
    start = tuple(s for s, _ in coords)
    end = tuple(e for _, e in coords)
    p0 = tuple(round_pulse(v, U) for v in start)
    p1 = tuple(round_pulse(v, U) for v in end)
    steps = list(line_steps(p0, p1))
    n = len(steps)
    assert n == max((abs(b - a) for a, b in zip(p0, p1)), default=0)
    assert (steps[-1] if steps else p0) == p1  # the pulses sum to the rounded displacement exactly
    prev = p0
    for i, p in enumerate(steps, start=1):
        assert all(abs(a - b) <= 1 for a, b in zip(p, prev))  # at most one pulse per axis per step
        t = Fraction(i, n)
        for k in range(len(p)):  # the exact path point at the same parameter is within one pulse
            ideal = start[k] + t * (end[k] - start[k])
            assert abs(p[k] * U - ideal) <= U
        prev = p
    if n:
        assert np.array_equal(line_chunk(p0, tuple(b - a for a, b in zip(p0, p1)), n, 0, n), np.array(steps))


@FAST
@given(st.lists(st.integers(-3000, 3000), min_size=1, max_size=4), st.lists(st.integers(-10**6, 10**6), min_size=4,
                                                                            max_size=4), st.data())
def test_line_chunks_are_the_reference_steps_on_every_slice(delta, p0, data):
    """Any slice lo..hi of a line, vectorized, is those rows of the per-step loop: the major axis (|d| = n,
    either sign), standing axes and the minor axes' floor division alike."""
    p0 = tuple(p0[:len(delta)])
    if data.draw(st.booleans()):  # a second axis as long as the first: two major axes
        delta = [delta[0], -delta[0], *delta[2:]] if len(delta) > 1 else delta
    n = max(abs(d) for d in delta)
    steps = np.array(list(line_steps(p0, tuple(p + d for p, d in zip(p0, delta)))), dtype=np.int64)
    if n == 0:
        return
    lo = data.draw(st.integers(0, n - 1))
    hi = data.draw(st.integers(lo + 1, n))
    assert np.array_equal(line_chunk(p0, tuple(delta), n, lo, hi), steps[lo:hi].reshape(hi - lo, len(delta)))


@FAST
@given(st.lists(st.integers(-2**40, 2**40), max_size=50), st.integers(-2**40, 2**40))
def test_step_deltas_are_numpy_diff_with_the_previous_position(col, prev):
    col_a = np.array(col, dtype=np.int64)
    assert np.array_equal(step_deltas(col_a, prev), np.diff(col_a, prepend=np.int64(prev)))


def test_round_pulse_ties_go_up_and_sums_chain():
    assert round_pulse(F("0.0005"), U) == 1 and round_pulse(F("-0.0005"), U) == 0
    m = machine()
    pts = [(0, 0, 0), ("1.0005", "-2.0005", "0.00049"), ("3.1234567", "0", "-0.0015"), ("-1", "1", "1")]
    segs = [line(a, b, block=i) for i, (a, b) in enumerate(zip(pts, pts[1:]))]
    r = simulate(segs, m)
    assert r.program_position == tuple(round_pulse(F(v), U) * U for v in pts[-1])


def _pythagorean_point(c, r, t):
    return (c[0] + r * (1 - t * t) / (1 + t * t), c[1] + r * 2 * t / (1 + t * t))


arc_cases = st.tuples(
    st.sampled_from([Plane.XY, Plane.XZ, Plane.YZ]), st.booleans(),
    decimals(-20, 20), decimals(-20, 20), decimals(0, 2).filter(lambda r: r >= F("0.005")),
    rationals(-5, 5), rationals(-5, 5), st.integers(0, 1), st.booleans(), decimals(-5, 5),
)


@FAST
@given(arc_cases)
def test_arc_deviation_at_most_one_pulse_all_planes_and_directions(case):
    plane, cw, cx, cy, r, ts, te, turns, full, dz = case
    a, b, n = PLANE_AXES[plane]
    axes = ("X", "Y", "Z")
    ia, ib, iz = axes.index(a), axes.index(b), axes.index(n)
    s2 = _pythagorean_point((cx, cy), r, ts)
    e2 = s2 if full else _pythagorean_point((cx, cy), r, te)
    start, end = [F(0)] * 3, [F(0)] * 3
    start[ia], start[ib], end[ia], end[ib] = s2[0], s2[1], e2[0], e2[1]
    end[iz] = dz  # helix along the normal axis
    seg = arc(start, end, (cx, cy), plane=plane, clockwise=cw, turns=turns)
    ctl = Controller(machine(), start=tuple(start))
    plan = _plan(ctl, seg)
    pos = plan.positions
    p0 = np.array(plan.p0)
    target = tuple(round_pulse(v, U) for v in end)
    if plan.n == 0:
        assert tuple(p0) == target
        return
    assert tuple(pos[-1]) == target  # lands exactly on the rounded end
    steps = np.abs(np.diff(np.vstack([p0, pos]), axis=0))
    assert steps[:, [ia, ib]].max() <= 1
    # in the plane: every pulse position within one pulse (radially, exact) of the exact circle
    sample = pos[:: max(1, len(pos) // 300)].tolist() + [pos[-1].tolist()]
    for p in sample:
        d2 = (p[ia] * U - cx) ** 2 + (p[ib] * U - cy) ** 2
        assert (max(r - U, F(0))) ** 2 <= d2 <= (r + U) ** 2
    # all axes at once: some point of the exact helix within one pulse (Chebyshev) of each position;
    # the helix is sampled at <= 1/40 pulse spacing, hence the 0.03 slack
    sgn = -1 if cw else 1
    a0 = math.atan2(sgn * float(s2[1] - cy), float(s2[0] - cx))
    sweep = (math.atan2(sgn * float(e2[1] - cy), float(e2[0] - cx)) - a0) % (2 * math.pi)
    if full or sweep == 0:
        sweep = 2 * math.pi
    sweep += 2 * math.pi * turns
    length = float(r) * sweep + abs(float(dz))
    phi = np.linspace(0.0, 1.0, int(length / 0.001 * 40) + 2)
    th = a0 + phi * sweep
    helix = np.zeros((len(phi), 3))
    helix[:, ia] = (float(cx) + float(r) * np.cos(th)) / 0.001
    helix[:, ib] = sgn * (sgn * float(cy) + float(r) * np.sin(th)) / 0.001
    helix[:, iz] = float(dz) * phi / 0.001
    # compare each position with the helix near its own swept angle (the window is generous)
    pa = np.array(sample, dtype=float)
    ang = np.unwrap(np.arctan2(sgn * (pos[:, ib] * 0.001 - float(cy)), pos[:, ia] * 0.001 - float(cx)))
    ang = ang - a0
    ang -= 2 * math.pi * np.round(ang[0] / (2 * math.pi))
    idx = list(range(0, len(pos), max(1, len(pos) // 300))) + [len(pos) - 1]
    phi_p = ang[idx] / sweep
    window = 1.0 if float(r) < 0.01 else 4 * 0.001 / (float(r) * sweep)
    for p, f in zip(pa, phi_p):
        lo, hi = np.searchsorted(phi, [f - window, f + window])
        near = helix[max(lo - 1, 0): hi + 1] if hi > lo else helix
        assert np.abs(near - p).max(axis=1).min() <= 1.03


@FAST
@given(decimals(-50, 50), decimals(-50, 50), decimals(1, 3), rationals(-3, 3), st.booleans(),
       st.sampled_from([Plane.XY, Plane.XZ, Plane.YZ]), st.integers(0, 1))
def test_full_circles_close_exactly(cx, cy, r, t, cw, plane, turns):
    a, b, _ = PLANE_AXES[plane]
    axes = ("X", "Y", "Z")
    ia, ib = axes.index(a), axes.index(b)
    s2 = _pythagorean_point((cx, cy), r, t)
    start = [F(0)] * 3
    start[ia], start[ib] = s2
    seg = arc(start, start, (cx, cy), plane=plane, clockwise=cw, turns=turns)
    r_ = simulate([seg], machine())
    assert r_.program_position == tuple(round_pulse(v, U) * U for v in start)
    # each plane axis sweeps the diameter four times per turn (within a few pulses)
    per_axis = 4 * r / U * (turns + 1)
    assert abs(r_.pulses[ia] - per_axis) <= 4 * (turns + 1) and abs(r_.pulses[ib] - per_axis) <= 4 * (turns + 1)


def test_r_format_centre_enclosure_and_side():
    c, err = arc_centre((F(0), F(0)), (F(10), F(0)), F(6), clockwise=True)
    assert err < F(1, 10**12) and c[1] < 0  # G2, R > 0: centre right of the chord (+X) = below
    c2, _ = arc_centre((F(0), F(0)), (F(10), F(0)), F(-6), clockwise=True)
    assert c2[1] > 0
    for cc in (c, c2):
        assert abs(math.hypot(float(cc[0]), float(cc[1])) - 6) < 1e-12
    seg = arc((0, 0, 0), (10, 0, 0), None, clockwise=True, radius=6)
    res = simulate([seg], machine())
    assert res.program_position == (10, 0, 0)
    assert res.pulses[1] > 0  # it really went round (below the chord)


@FAST
@given(st.lists(rationals(-3, 3), min_size=3, max_size=3), st.lists(rationals(-3, 3), min_size=3, max_size=3))
def test_dogleg_rapid_reaches_every_axis_end_exactly(a, b):
    m = machine(rapid="dogleg")
    ctl = Controller(m, start=tuple(a))
    seg = line(a, b, kind=SegmentKind.RAPID)
    plan = _plan(ctl, seg)
    p0, p1 = plan.p0, tuple(round_pulse(v, U) for v in b)
    if plan.n:
        assert tuple(plan.positions[-1]) == p1
    periods = [ax.pulse * 60 / ax.rapid_mm_min for ax in m.axes]
    # every axis starts at once and pulses at its own rate: position = min(floor(t / period), |D|)
    for t, p in zip((Fraction(int(x), plan.tick_den) for x in plan.exact_times), plan.positions.tolist()):
        for k in range(3):
            d = p1[k] - p0[k]
            expect = p0[k] + (1 if d > 0 else -1) * min(math.floor(t / periods[k]), abs(d))
            assert p[k] == expect
    r = simulate([seg], m)
    assert r.program_position == tuple(v * U for v in p1)
    assert r.pulses == tuple(abs(q - p) for p, q in zip(p0, p1))


def test_dogleg_time_is_the_slowest_axis():
    m = machine(rapid="dogleg")
    r = simulate([line((0, 0, 0), (60, 40, 3), kind=SegmentKind.RAPID)], m)
    assert r.simulated_time_s == pytest.approx(0.6)  # X 60 mm at 6000 mm/min; Y 40 at 4000: both 0.6 s


def test_feed_sets_the_pulse_period():
    m = machine()
    r = simulate([line((0, 0, 0), (10, 0, 0), feed="600")], m)
    assert r.simulated_time_s == pytest.approx(1.0)  # 10 mm at 600 mm/min
    assert r.pulses == (10_000, 0, 0)
