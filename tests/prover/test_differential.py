"""Differential tests: the prover against an independent brute-force checker, and tier 1 against Z3.

The brute force samples every segment densely with exact rationals and adds
every parameter at which a coordinate crosses a zone constant (shifted by
the margin), computed exactly; it uses only ``AllowedSet.violated_zones``.
"""

from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover import Verdict, verify_segments
from nczones.prover.exact import zone_constants
from nczones.prover.geometry import arc_geom, in_sweep, line_pieces, rational_point_on_arc
from tests.oracles.machines import machine_text
from tests.sizes import examples

AXES = ("X", "Y")


@st.composite
def tables(draw):
    n = draw(st.integers(1, 5))
    ups = sorted(draw(st.sets(st.integers(-3, 30), min_size=n, max_size=n)))
    regions = []
    for u in ups:
        lo = draw(st.one_of(st.none(), st.integers(-8, 2)))
        hi = draw(st.one_of(st.none(), st.integers(3, 10)))
        regions.append((u, lo, hi))
    box = None
    if draw(st.booleans()):
        x0 = draw(st.integers(-5, 25))
        y0 = draw(st.integers(-5, 8))
        box = (x0, x0 + draw(st.integers(1, 6)), y0, y0 + draw(st.integers(1, 4)))
    return regions, box


coord = st.builds(lambda n: F(n, 4), st.integers(-20, 120))
ycoord = st.builds(lambda n: F(n, 4), st.integers(-40, 44))


@st.composite
def segments(draw):
    kind = draw(st.sampled_from([SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.ARC]))
    s = (draw(coord), draw(ycoord))
    if kind is SegmentKind.ARC:
        c = (s[0] + draw(st.integers(-8, 8)), s[1] + draw(st.integers(-8, 8)))
        if c == s:
            c = (s[0] + 1, s[1])
        # end: start rotated by a rational rotation about c (exactly on the circle)
        m = F(draw(st.integers(-12, 12)), 4)
        u = (s[0] - c[0], s[1] - c[1])
        den = 1 + m * m
        e = (c[0] + ((1 - m * m) * u[0] - 2 * m * u[1]) / den, c[1] + ((1 - m * m) * u[1] + 2 * m * u[0]) / den)
        return Segment(kind, s, e, AXES, plane=Plane.XY, clockwise=draw(st.booleans()), centre=c)
    e = (draw(coord), draw(ycoord))
    return Segment(kind, s, e, AXES)


def _arc_points(seg, n):
    g = arc_geom(seg)
    c = g.centre
    u = (g.s[0] - c[0], g.s[1] - c[1])
    w = (g.e[0] - c[0], g.e[1] - c[1])
    base = u
    out = []
    for _ in range(4):
        for i in range(n + 1):
            p = rational_point_on_arc(g, F(i, n), base)
            if in_sweep(u, w, (p[0] - c[0], p[1] - c[1]), g.ccw, g.full):
                out.append(p)
        base = (-base[1], base[0]) if g.ccw else (base[1], -base[0])
    return out


def brute_force_violation(seg, machine, margin, n=64):
    """True if some sampled exact path point's margin box violates a zone."""
    allowed = machine.allowed
    pts = []
    if seg.kind is SegmentKind.ARC:
        pts = _arc_points(seg, n)
    else:
        for pc in line_pieces(seg, machine):
            ts = {F(i, n) for i in range(n + 1)}
            for k, a in enumerate(AXES):
                a0, a1 = pc.p0[k], pc.p1[k]
                if a0 == a1:
                    continue
                for z in allowed.zones:
                    for c in zone_constants(z, a):
                        for sh in (-margin, F(0), margin):
                            t = (c + sh - a0) / (a1 - a0)
                            for eps in (F(0), F(1, 10**6), F(-1, 10**6)):
                                if 0 <= t + eps <= 1:
                                    ts.add(t + eps)
            pts += [pc.at(t) for t in ts]
    return any(allowed.violated_zones(dict(zip(AXES, p)), F(0), margin) for p in pts)


@settings(max_examples=examples(60, 120), deadline=None, derandomize=True)
@given(tables(), st.lists(segments(), min_size=1, max_size=3), st.sampled_from([F(0), F(1, 2)]),
       st.sampled_from(["linear", "dogleg"]))
def test_never_safe_when_brute_force_finds_an_outside_point(table, segs, margin, rapid_mode):
    regions, box = table
    m = machine_text(regions, box, rapid_mode)
    segs = [Segment(s.kind, s.start, s.end, AXES, block=i, plane=s.plane, clockwise=s.clockwise, centre=s.centre)
            for i, s in enumerate(segs)]
    r = verify_segments(segs, m, margin=margin)
    bad = [i for i, s in enumerate(segs) if brute_force_violation(s, m, margin)]
    if bad:
        assert r.verdict is Verdict.UNSAFE
        assert r.violations[0].block <= bad[0]
    # every reported point is strictly outside
    for v in r.violations:
        assert m.allowed.violated_zones(dict(v.point), F(0))


@settings(max_examples=examples(40, 80), deadline=None, derandomize=True)
@given(tables(), st.lists(segments(), min_size=1, max_size=3), st.sampled_from([F(0), F(1, 4)]),
       st.sampled_from(["linear", "dogleg"]))
def test_tier1_and_z3_engines_agree(table, segs, margin, rapid_mode):
    regions, box = table
    m = machine_text(regions, box, rapid_mode)
    segs = [Segment(s.kind, s.start, s.end, AXES, block=i, plane=s.plane, clockwise=s.clockwise, centre=s.centre)
            for i, s in enumerate(segs)]
    a = verify_segments(segs, m, margin=margin)
    b = verify_segments(segs, m, margin=margin, engine="z3")
    assert a.verdict == b.verdict
    assert [v.block for v in a.violations] == [v.block for v in b.violations]
