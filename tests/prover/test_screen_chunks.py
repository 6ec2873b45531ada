"""The vectorized tier-1 screen over column chunks (DESIGN §9).

* ``arc_boxes`` (exact integer arc boxes) contains the exact box of
  :meth:`ArcGeom.plane_bbox` and is at most one scale unit looser, for
  every plane, direction, full circles and spirals; every exact rational
  point of the arc lies in it.
* A chunk verified with the screen gives the same verdict and the same
  violating blocks as the segments sent one by one to Z3.
* Overflow guards: rows whose squares could overflow ``int64`` are not
  screened (they go to the exact path), never wrapped.
"""

from __future__ import annotations

import math
from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.motion import MotionChunk, Plane, Segment, SegmentKind
from nczones.prover import Prover, Verdict, verify_segments
from nczones.prover.geometry import arc_geom, in_sweep, rational_point_on_arc
from nczones.prover.screen import _isqrt_ceil, arc_boxes, screen_chunk
from tests.oracles.machines import machine_text
from tests.sizes import examples

AXES3 = ("X", "Y", "Z")


def chunk_of(segs, scale, axes):
    """Column chunk of segments whose coordinates are multiples of 10**-scale."""
    den = 10**scale

    def ints(vals):
        out = [v * den for v in vals]
        assert all(x.denominator == 1 for x in out)
        return [int(x) for x in out]

    n = len(segs)
    arcs = any(s.kind is SegmentKind.ARC for s in segs)
    return MotionChunk(
        axes, scale,
        kind=np.array([int(s.kind) for s in segs], dtype=np.int8),
        start=np.array([ints(s.start) for s in segs], dtype=np.int64).reshape(n, len(axes)),
        end=np.array([ints(s.end) for s in segs], dtype=np.int64).reshape(n, len(axes)),
        line=np.arange(1, n + 1, dtype=np.int64), block=np.array([s.block for s in segs], dtype=np.int64),
        tool_length=np.zeros(n, dtype=np.int64),
        centre=np.array([ints(s.centre) if s.centre else [0, 0] for s in segs], dtype=np.int64) if arcs else None,
        plane=np.array([int(s.plane) if s.plane else 0 for s in segs], dtype=np.int8) if arcs else None,
        clockwise=np.array([s.clockwise for s in segs], dtype=bool) if arcs else None,
        turns=np.array([s.turns for s in segs], dtype=np.int32) if arcs else None,
    )


@st.composite
def arcs3(draw, spiral=False):
    """An I/J/K arc in a random plane (scale 2), possibly a full circle or a spiral."""
    plane = draw(st.sampled_from(list(Plane)))
    seg_axes = {Plane.XY: (0, 1), Plane.XZ: (2, 0), Plane.YZ: (1, 2)}[plane]
    c = (F(draw(st.integers(-500, 500)), 100), F(draw(st.integers(-500, 500)), 100))
    u = (F(draw(st.integers(-300, 300)), 100), F(draw(st.integers(-300, 300)), 100))
    if u == (0, 0):
        u = (F(1), F(0))
    full = draw(st.integers(0, 5)) == 0
    if full:
        e2 = u
    elif spiral:
        e2 = (F(draw(st.integers(-300, 300)), 100), F(draw(st.integers(-300, 300)), 100))
        if e2 == (0, 0):
            e2 = (F(0), F(1))
    else:  # quarter-turn multiples and mirror images keep the end exactly on the circle at scale 2
        e2 = draw(st.sampled_from([(u[1], -u[0]), (-u[0], -u[1]), (-u[1], u[0]), (u[0], -u[1]), (-u[0], u[1]),
                                   (u[1], u[0]), (-u[1], -u[0])]))
    start = [F(0)] * 3
    end = [F(0)] * 3
    start[seg_axes[0]], start[seg_axes[1]] = c[0] + u[0], c[1] + u[1]
    end[seg_axes[0]], end[seg_axes[1]] = c[0] + e2[0], c[1] + e2[1]
    normal = 3 - seg_axes[0] - seg_axes[1]
    start[normal] = F(draw(st.integers(-100, 100)), 100)
    end[normal] = start[normal] + (F(draw(st.integers(-100, 100)), 100) if draw(st.booleans()) else 0)
    return Segment(SegmentKind.ARC, tuple(start), tuple(end), AXES3, plane=plane,
                   clockwise=draw(st.booleans()), centre=c, turns=int(full and draw(st.booleans())))


@settings(max_examples=examples(150, 300), deadline=None, derandomize=True)
@given(st.lists(st.one_of(arcs3(), arcs3(spiral=True)), min_size=1, max_size=6))
def test_integer_arc_boxes_contain_the_exact_box_and_are_tight(segs):
    scale = 2
    ch = chunk_of(segs, scale, AXES3)
    lo = np.minimum(ch.start, ch.end)
    hi = np.maximum(ch.start, ch.end)
    ok = arc_boxes(ch, np.arange(len(segs)), lo, hi)
    assert ok.all()
    for i, s in enumerate(segs):
        g = arc_geom(s)
        (bx, by) = g.plane_bbox()
        for k, (blo, bhi) in ((g.ia, bx), (g.ib, by)):
            assert F(int(lo[i, k]), 100) <= blo and bhi <= F(int(hi[i, k]), 100)
            # at most one unit looser than the rational box (spirals: the same growth rule)
            slack = F(1, 100) if g.r2_lo == g.r2_hi else F(5, 100)
            assert blo - F(int(lo[i, k]), 100) <= slack and F(int(hi[i, k]), 100) - bhi <= slack
        for k in range(3):
            if k not in (g.ia, g.ib):
                assert (lo[i, k], hi[i, k]) == (min(ch.start[i, k], ch.end[i, k]), max(ch.start[i, k], ch.end[i, k]))
        if g.exact:
            c = g.centre
            u = (g.s[0] - c[0], g.s[1] - c[1])
            w = (g.e[0] - c[0], g.e[1] - c[1])
            base = u
            for _ in range(4):
                for j in range(9):
                    p = rational_point_on_arc(g, F(j, 8), base)
                    if in_sweep(u, w, (p[0] - c[0], p[1] - c[1]), g.ccw, g.full):
                        assert F(int(lo[i, g.ia]), 100) <= p[0] <= F(int(hi[i, g.ia]), 100)
                        assert F(int(lo[i, g.ib]), 100) <= p[1] <= F(int(hi[i, g.ib]), 100)
                base = (-base[1], base[0]) if g.ccw else (base[1], -base[0])


@settings(max_examples=200, deadline=None, derandomize=True)
@given(st.integers(0, 2**62 - 1))
def test_isqrt_ceil_is_exact(n):
    r = int(_isqrt_ceil(np.array([n], dtype=np.int64))[0])
    assert r == math.isqrt(n) + (math.isqrt(n) ** 2 < n)


AXES2 = ("X", "Y")


@st.composite
def chunk_segments(draw):
    """Lines, rapids and arcs at scale 2 near a small stepped table."""
    out = []
    for i in range(draw(st.integers(1, 6))):
        kind = draw(st.sampled_from([SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.ARC, SegmentKind.ARC]))
        s = (F(draw(st.integers(-200, 3000)), 100), F(draw(st.integers(-900, 1100)), 100))
        if kind is SegmentKind.ARC:
            u = (F(draw(st.integers(-400, 400)), 100), F(draw(st.integers(-400, 400)), 100))
            if u == (0, 0):
                u = (F(1), F(0))
            c = (s[0] - u[0], s[1] - u[1])
            e2 = draw(st.sampled_from([(u[1], -u[0]), (-u[0], -u[1]), (-u[1], u[0]), u]))
            e = (c[0] + e2[0], c[1] + e2[1])
            out.append(Segment(kind, s, e, AXES2, block=i, plane=Plane.XY, clockwise=draw(st.booleans()), centre=c))
        else:
            e = (F(draw(st.integers(-200, 3000)), 100), F(draw(st.integers(-900, 1100)), 100))
            out.append(Segment(kind, s, e, AXES2, block=i))
    return out


@settings(max_examples=examples(30, 60), deadline=None, derandomize=True)
@given(st.lists(st.tuples(st.integers(-3, 30), st.one_of(st.none(), st.integers(-8, 2)),
                          st.one_of(st.none(), st.integers(3, 10))), min_size=1, max_size=4, unique_by=lambda r: r[0]),
       chunk_segments(), st.sampled_from(["linear", "dogleg"]), st.booleans())
def test_screened_chunk_agrees_with_z3_per_segment(regions, segs, rapid_mode, with_box):
    regions = sorted(regions)
    m = machine_text(regions, (4, 9, 1, 3) if with_box else None, rapid_mode)
    a = verify_segments([chunk_of(segs, 2, AXES2)], m)
    b = verify_segments(segs, m, engine="z3")
    assert a.verdict == b.verdict
    assert [v.block for v in a.violations] == [v.block for v in b.violations]


def _box_machine(half: str):
    from nczones.machine import parse_machine

    return parse_machine(f"""
[machine]
axes = ["X", "Y"]
[machine.rapid]
X = "1000"
Y = "1000"
[machine.reference]
X = "0"
Y = "0"
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "-{half}", Y = "-{half}" }}
max = {{ X = "{half}", Y = "{half}" }}
""")


def test_rows_whose_squares_could_overflow_are_left_to_the_exact_path():
    # radius 3000 mm at scale 6 is 3e9 units: its square would pass 2**63, so the row is not screened
    big = Segment(SegmentKind.ARC, (F(3000), F(0)), (F(0), F(3000)), AXES2, block=0, plane=Plane.XY,
                  centre=(F(0), F(0)))
    small = Segment(SegmentKind.ARC, (F(3), F(0)), (F(0), F(3)), AXES2, block=1, plane=Plane.XY,
                    centre=(F(0), F(0)))
    line = Segment(SegmentKind.LINE, (F(0), F(3)), (F(1, 10**6), F(3)), AXES2, block=2)
    ch = chunk_of([big, small, line], 6, AXES2)
    m = _box_machine("5000")
    assert screen_chunk(ch, Prover(m)) == [0]
    r = verify_segments([ch], m)
    assert r.verdict is Verdict.SAFE and dict(r.stats)["screened"] == 3  # 2 by the chunk screen, 1 exactly
    tight = _box_machine("2999.999999")  # the big arc's exact extreme is 3000: unsafe
    r2 = verify_segments([chunk_of([big, small, line], 6, AXES2)], tight)
    r3 = verify_segments([big, small, line], tight, engine="z3")
    assert r2.verdict is r3.verdict is Verdict.UNSAFE
    assert [v.block for v in r2.violations] == [v.block for v in r3.violations] == [0]


def test_coordinates_beyond_the_int64_guard_are_not_screened():
    huge = 2**62
    ch = MotionChunk(AXES2, 0, kind=np.array([0, 0], dtype=np.int8),
                     start=np.array([[0, 0], [1, 1]], dtype=np.int64), end=np.array([[huge, 0], [2, 2]], dtype=np.int64),
                     line=np.array([1, 2]), block=np.array([0, 1]), tool_length=np.zeros(2, dtype=np.int64))
    assert screen_chunk(ch, Prover(_box_machine("10"))) == [0, 1]


@settings(max_examples=60, deadline=None, derandomize=True)
@given(st.lists(st.integers(-10**12, 10**12), min_size=1, max_size=40), st.data())
def test_range_table_answers_like_min_and_max(values, data):
    from nczones.prover.screen import _RangeTable

    v = np.array(values, dtype=np.int64)
    lo = np.array(data.draw(st.lists(st.integers(0, len(values) - 1), min_size=1, max_size=30)), dtype=np.int64)
    hi = np.array([data.draw(st.integers(int(a), len(values) - 1)) for a in lo], dtype=np.int64)
    assert _RangeTable(v, np.minimum).query(lo, hi).tolist() == [min(values[a:b + 1]) for a, b in zip(lo, hi)]
    assert _RangeTable(v, np.maximum).query(lo, hi).tolist() == [max(values[a:b + 1]) for a, b in zip(lo, hi)]
