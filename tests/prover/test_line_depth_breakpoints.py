""":func:`nczones.prover.exact.line_depth` finds its breakpoints in integers over a common denominator (issue 36:
the crossings of every pair in ``Fraction`` arithmetic were nearly all of a 229-line unsafe program's 29 s).  Held
here to the former way (every signed pair crossed in ``Fraction`` arithmetic, the depth taken at each crossing),
and to what a maximum is: no sampled point of the piece is deeper, and the depth at the ``t`` returned is the one
returned."""

from __future__ import annotations

import itertools
from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.prover.exact import line_depth, point_depth, zone_constants
from nczones.zones import BoxZone

AXES = ("X", "Y", "Z")
small = st.fractions(min_value=-40, max_value=40, max_denominator=8)


@st.composite
def cases(draw):
    limits = []
    for a in AXES:
        lo, hi = sorted((draw(small), draw(small)))
        limits.append((a, lo if draw(st.booleans()) else None, hi + 1 if draw(st.booleans()) else None))
    zone = BoxZone("z", tuple(limits), forbid=draw(st.booleans()))
    p0 = tuple(draw(small) for _ in AXES)
    p1 = tuple(draw(small) for _ in AXES) if draw(st.integers(0, 4)) else p0  # a point piece now and then
    margin = draw(st.sampled_from((F(0), F(1, 2), F(3))))
    return zone, p0, p1, margin


def former_line_depth(zone, p0, p1, margin, max_candidates=20000):
    """The breakpoints as before: every pair of the signed list crossed in ``Fraction`` arithmetic."""
    ends = {a: (p0[i], p1[i]) for i, a in enumerate(AXES)}
    zaxes = [a for a in zone.axes if a in ends]
    lines = []
    for ax in zaxes:
        a, b = ends[ax]
        lo, hi = min(a, b) - margin, max(a, b) + margin
        consts = list(zone_constants(zone, ax))
        near = [c for c in consts if lo - (hi - lo) - 1 <= c <= hi + (hi - lo) + 1] or consts[:2]
        for c in near:
            for s in (-margin, margin, F(0)):
                lines.append((a - (c + s), b - (c + s)))
                lines.append((-(a - (c + s)), -(b - (c + s))))
    cands, exact = {F(0), F(1)}, True
    for f0, f1 in lines:
        if f1 != f0 and 0 < f0 / (f0 - f1) < 1:
            cands.add(f0 / (f0 - f1))
    pairs = itertools.combinations(lines, 2) if len(lines) ** 2 <= max_candidates else ()
    exact = len(lines) ** 2 <= max_candidates
    for (f0, f1), (g0, g1) in pairs:
        den = (f1 - f0) - (g1 - g0)
        if den and 0 < (g0 - f0) / den < 1:
            cands.add((g0 - f0) / den)
    best, best_t = None, F(0)
    for t in sorted(cands):
        v = point_depth(zone, {ax: ends[ax][0] + t * (ends[ax][1] - ends[ax][0]) for ax in zaxes}, margin)
        if best is None or v > best:
            best, best_t = v, t
    return best, best_t, exact


def at(p0, p1, t):
    return {a: p0[i] + t * (p1[i] - p0[i]) for i, a in enumerate(AXES)}


@settings(max_examples=300, deadline=None)
@given(cases(), st.sampled_from((20000, 200)))
def test_line_depth_is_the_former_one(case, cap):
    zone, p0, p1, margin = case
    got = line_depth(zone, p0, p1, AXES, margin, F(0), None, max_candidates=cap)
    assert got == former_line_depth(zone, p0, p1, margin, cap)


@settings(max_examples=200, deadline=None)
@given(cases(), st.lists(st.fractions(min_value=0, max_value=1, max_denominator=97), max_size=12))
def test_line_depth_is_a_maximum_attained_at_its_t(case, ts):
    zone, p0, p1, margin = case
    depth, t, exact = line_depth(zone, p0, p1, AXES, margin, F(0), None)
    assert exact
    assert point_depth(zone, at(p0, p1, t), margin) == depth
    for s in [F(0), F(1), *ts]:
        assert point_depth(zone, at(p0, p1, s), margin) <= depth


def test_the_breakpoint_between_two_limits_is_found():
    # X runs -5 -> 15 through a forbidden box 0 <= X <= 10, -10 <= Y <= 10: deepest at X = 5, 5 from a face
    zone = BoxZone("post", (("X", F(0), F(10)), ("Y", F(-10), F(10)), ("Z", None, None)), forbid=True)
    depth, t, exact = line_depth(zone, (F(-5), F(0), F(0)), (F(15), F(0), F(0)), AXES, F(0), F(0), None)
    assert (depth, t, exact) == (F(5), F(1, 2), True)
