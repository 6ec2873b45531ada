"""Vectorized arcs (controller/arcs.py) == the per-step reference walk; steep helices; same first alarm."""

from __future__ import annotations

import math
from contextlib import contextmanager

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller import Controller, Settings, round_pulse, simulate
from nczones.controller import arcs as arcs_mod
from nczones.controller.arcs import arc_path
from nczones.controller.pulses import arc_centre, arc_walk, helix_chunk, helix_steps
from nczones.exact import format_decimal
from nczones.motion import PLANE_AXES, Plane
from tests.sizes import examples

from .helpers import FAST, F, arc, decimals, machine, rationals

U = F(1, 1000)
AXES = ("X", "Y", "Z")


@contextmanager
def _tuned(short: int, candidates: int):
    """Force the vectorized path on short arcs and small candidate batches (more rounds, more seams)."""
    old = arcs_mod.SHORT_ARC_STEPS, arcs_mod.CANDIDATES, arcs_mod.OBJECT_VERIFY
    arcs_mod.SHORT_ARC_STEPS, arcs_mod.CANDIDATES, arcs_mod.OBJECT_VERIFY = short, candidates, True
    try:
        yield
    finally:
        arcs_mod.SHORT_ARC_STEPS, arcs_mod.CANDIDATES, arcs_mod.OBJECT_VERIFY = old


def _pyth(c, r, t):
    return (c[0] + r * (1 - t * t) / (1 + t * t), c[1] + r * 2 * t / (1 + t * t))


walk_cases = st.tuples(
    decimals(-20, 20), decimals(-20, 20), decimals(0, 1).filter(lambda r: r >= F("0.003")),
    rationals(-5, 5), rationals(-5, 5), st.booleans(), st.integers(0, 2), st.booleans(),
    st.sampled_from([(U, U), (U, F(2, 1000)), (F(5, 1000), U), (F(1, 3000), F(1, 7000))]),
    st.sampled_from([0, 7, 1 << 16]), st.integers(-3, 3), st.integers(-3, 3),
)


@settings(FAST, max_examples=examples(15, 30))
@given(walk_cases, st.sampled_from(["centre", "R", "spiral"]))
def test_vectorized_walk_is_identical_to_the_reference(case, form):
    cx, cy, r, ts, te, cw, turns, full, pulse, candidates, ox, oy = case
    s2 = _pyth((cx, cy), r, ts)
    e2 = s2 if full else _pyth((cx, cy), r, te)
    centre = (cx, cy)
    if form == "R":  # an irrational centre: the 64-bit rational enclosure (Python-integer verification)
        if s2 == e2:
            return
        chord = max(abs(e2[0] - s2[0]), abs(e2[1] - s2[1]))
        radius = (chord * (1 + abs(ts))) * (-1 if turns == 1 else 1)
        centre, _ = arc_centre(s2, e2, radius, cw)
        turns = 0
    elif form == "spiral":  # the end radius differs from the start radius (I/J spirals)
        e2 = _pyth((cx, cy), r + F(ox, 997), te)
    sp = (round_pulse(s2[0], pulse[0]) + ox % 2, round_pulse(s2[1], pulse[1]) - oy % 2)  # start a pulse off
    ep = (round_pulse(e2[0], pulse[0]), round_pulse(e2[1], pulse[1]))
    with _tuned(0, candidates or 1):
        fast = arc_path(sp, ep, s2, e2, centre, cw, turns, pulse)
    ref = arc_walk(sp, ep, s2, e2, centre, cw, turns, pulse)
    assert fast.points.tolist() == [list(p) for p in ref.points]
    assert fast.walk_steps == ref.walk_steps
    assert (fast.sweep_rad, fast.radius_mm) == (ref.sweep_rad, ref.radius_mm)


def test_vectorized_walk_big_circle_identical_and_closes():
    args = ((23_457, -2), (23_457, -2), (F("23.4567"), F("-0.0021")), (F("23.4567"), F("-0.0021")),
            (F("0.0003"), F("0.0001")), True, 1, (U, U))
    fast = arc_path(*args)
    ref = arc_walk(*args)
    assert fast.points.tolist() == [list(p) for p in ref.points]
    assert fast.points[-1].tolist() == [23_457, -2] and len(fast.points) > 200_000


def _steep_helix(cw, plane, dz, turns=0, r="0.5"):
    a, b, n = PLANE_AXES[plane]
    ia, ib = AXES.index(a), AXES.index(b)
    start, end = [F(0)] * 3, [F(0)] * 3
    start[ia] = end[ia] = F(r)
    end[AXES.index(n)] = F(dz)
    return arc(start, end, (0, 0), plane=plane, clockwise=cw, turns=turns), ia, ib, AXES.index(n)


@settings(FAST, max_examples=examples(10, 20))
@given(st.booleans(), st.sampled_from([Plane.XY, Plane.XZ, Plane.YZ]), decimals(-20, 20).filter(lambda v: abs(v) > 3),
       st.integers(0, 1), st.sampled_from(["0.05", "0.2", "0.4321"]))
def test_steep_helix_one_pulse_per_axis_per_step_and_within_one_pulse(cw, plane, dz, turns, r):
    seg, ia, ib, iz = _steep_helix(cw, plane, dz, turns, r)
    plans = []
    for engine in ("vector", "reference"):
        ctl = Controller(machine(), start=seg.start, settings=Settings(engine=engine))
        plans.append(ctl.plan(seg))
    pos, ref = plans[0].positions, plans[1].positions
    assert np.array_equal(pos, ref)  # both engines interleave the same way
    p0 = np.array(plans[0].p0)
    steps = np.abs(np.diff(np.vstack([p0, pos]), axis=0))
    assert steps.max() <= 1 and steps.max(axis=1).min() == 1  # every axis <= one pulse, no empty step
    assert tuple(pos[-1]) == tuple(round_pulse(v, U) for v in seg.end)
    # within one pulse per axis (Chebyshev) of the exact helix, sampled finely
    sgn = -1 if cw else 1
    sweep = 2 * math.pi * (turns + 1)
    rr = float(r)
    phi = np.linspace(0.0, 1.0, int((rr * sweep + abs(float(dz))) / 0.001 * 20) + 2)
    helix = np.zeros((len(phi), 3))
    helix[:, ia] = rr * np.cos(phi * sweep) / 0.001
    helix[:, ib] = sgn * rr * np.sin(phi * sweep) / 0.001
    helix[:, iz] = float(dz) * phi / 0.001
    z = pos[:, iz].astype(float)
    for p in pos[:: max(1, len(pos) // 400)].tolist() + [pos[-1].tolist()]:
        # the helix points near this position's helix coordinate (the helix axis is monotone)
        lo, hi = np.searchsorted(helix[:, iz] * np.sign(float(dz)), [np.sign(float(dz)) * p[iz] - 2,
                                                                      np.sign(float(dz)) * p[iz] + 2])
        near = helix[max(lo - 1, 0): hi + 1]
        assert np.abs(near - np.array(p, dtype=float)).max(axis=1).min() <= 1.05
    assert len(z) >= abs(int(F(dz) / U))  # the helix axis really moves pulse by pulse


@FAST
@given(st.lists(st.tuples(st.integers(-1, 1), st.integers(-1, 1), st.integers(-6, 6), st.integers(-3, 3)),
                min_size=1, max_size=40))
def test_helix_interleave_vectorized_equals_reference_loop(moves):
    p = [0, 0, 5, -2]
    rows = []
    for m in moves:
        p = [p[0] + m[0], p[1] + m[1], p[2] + m[2], p[3] + m[3]]
        rows.append(tuple(p))
    ref = helix_steps(rows, (0, 0, 5, -2), (2, 3))
    fast = helix_chunk(np.array(rows), (0, 0, 5, -2), (2, 3))
    assert fast.tolist() == [list(r) for r in ref]
    steps = np.abs(np.diff(np.vstack([[0, 0, 5, -2], fast]), axis=0))
    assert steps.max() <= 1 and fast[-1].tolist() == list(rows[-1])


ZONE = """
[[zones]]
name = "table"
kind = "stepped"
reference_axis = "X"
limited_axis = "Y"
from = "-50"
regions = [{ upto = "-1.2345", max = "50" }, { upto = "50", max = "{cap}" }]
"""


@FAST
@given(decimals(1, 8), rationals(-3, 3), st.booleans(), st.sampled_from([Plane.XY, Plane.XZ]),
       decimals(0, 6), st.sampled_from(["centre", "R"]))
def test_first_alarm_pulse_on_an_arc_is_the_same_in_both_engines(r, t, cw, plane, cap, form):
    a, b, _ = PLANE_AXES[plane]
    ia, ib = AXES.index(a), AXES.index(b)
    s2 = _pyth((F(0), F(0)), r, t)
    e2 = (-s2[0], -s2[1])
    start, end = [F(0)] * 3, [F(0)] * 3
    start[ia], start[ib], end[ia], end[ib] = s2[0], s2[1], e2[0], e2[1]
    end[3 - ia - ib] = F(2)  # a helix
    seg = arc(start, end, None if form == "R" else (0, 0), plane=plane, clockwise=cw,
              radius=r if form == "R" else None)
    m = machine(ZONE.replace("{cap}", format_decimal(cap)))
    res = [simulate([seg], m, settings=Settings(engine=e)) for e in ("vector", "reference")]
    assert [(a.pulse_position, a.zone, a.blocked, a.block) for a in res[0].alarms] \
        == [(a.pulse_position, a.zone, a.blocked, a.block) for a in res[1].alarms]
    assert res[0].pulses == res[1].pulses and res[0].steps == res[1].steps
    assert res[0].program_position == res[1].program_position


def _old_helix_column(pts, pulse2, centre, sgn, a0, sweep, a, b):
    """The whole-array helix formula the chunked one replaced (np.unwrap over every point)."""
    ang = np.unwrap(np.arctan2(sgn * (pts[:, 1] * pulse2[1] - centre[1]), pts[:, 0] * pulse2[0] - centre[0]))
    ang = ang - a0
    ang -= 2 * math.pi * np.round(ang[0] / (2 * math.pi))
    phi = np.maximum.accumulate(np.clip(ang / sweep, 0.0, 1.0))
    col = a + np.floor(phi * (b - a) + 0.5).astype(np.int64)
    col[-1] = b
    return col


@settings(FAST, max_examples=examples(12, 25))
@given(st.integers(3, 400), st.integers(0, 3), st.booleans(), st.integers(-900, 900), st.sampled_from([1, 7, 64, 1 << 16]))
def test_chunked_helix_columns_and_path_fractions_equal_the_whole_array_forms(r, turns, cw, dz, chunk):
    from nczones.controller import simulator as sim

    sweep = 2 * math.pi * (turns + 1)
    pts = arc_path((r, 0), (r, 0), (F(r), F(0)), (F(r), F(0)), (F(0), F(0)), cw, turns, (F(1), F(1))).points
    sgn = -1.0 if cw else 1.0
    a0 = math.atan2(0.0, float(r))
    pos = np.zeros((len(pts), 3), dtype=np.int64)
    pos[:, :2] = pts
    old = sim.ARC_CHUNK, arcs_mod.FRACTION_CHUNK
    sim.ARC_CHUNK = arcs_mod.FRACTION_CHUNK = chunk
    try:
        sim._helix_columns(pos, (0, 1), (1.0, 1.0), (0.0, 0.0), sgn, a0, sweep, [(2, 5, 5 + dz)])
        want = _old_helix_column(pts, (1.0, 1.0), (0.0, 0.0), sgn, a0, sweep, 5, 5 + dz)
        assert pos[:, 2].tolist() == want.tolist()
        pos = helix_chunk(pos, (r, 0, 5), (2,))
        sig, moved = arcs_mod.path_fractions_moved(pos, (r, 0, 5), (0.001, 0.001, 0.002), [0, 1, 2])
    finally:
        sim.ARC_CHUNK, arcs_mod.FRACTION_CHUNK = old
    assert np.array_equal(sig, arcs_mod.path_fractions(pos, (r, 0, 5), (0.001, 0.001, 0.002)))  # bit for bit
    steps = np.abs(np.diff(pos, axis=0, prepend=np.array([[r, 0, 5]])))
    assert moved == tuple(int(v) for v in steps.sum(axis=0))


def test_unwrap_equals_numpy_on_angles_with_jumps():
    from nczones.controller.simulator import _unwrap

    a = np.arctan2(np.sin(np.linspace(0, 40, 5001)), np.cos(np.linspace(0, 40, 5001)))
    assert np.array_equal(_unwrap(a), np.unwrap(a))
