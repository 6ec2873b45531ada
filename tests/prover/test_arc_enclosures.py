"""The exact arc tier (nczones/prover/arcs.py) agrees with the solver path and never says too much.

Soundness is what matters: the enclosure tier may leave an arc open (the
solver then decides), but it must never prove an arc that the solver shows
violating, nor report a violation the solver proves impossible.  Arcs of
every kind are drawn — I/J circles (rational centre), R-format arcs
(irrational centre), helices, spirals, multi-turn helices — against boxes,
forbid boxes and stepped tables, with and without a margin; the reference is
``Prover(engine="z3")`` (exact for circles, refinement for helices and
spirals) and, for circles, an independent sampler of exact rational points
of the arc.  ``HYPOTHESIS_PROFILE=long`` runs fifty times the examples.
"""

from __future__ import annotations

import os
from dataclasses import replace
from fractions import Fraction as F

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover import Verdict, verify_segments
from nczones.prover.arcs import ArcEnclosure, decide_arc
from nczones.prover.core import Prover, arc_bases
from nczones.prover.geometry import arc_geom, in_sweep, rational_point_on_arc
from nczones.prover.limits import RunLimits
from nczones.zones import AllowedSet, BoxZone, Region, SteppedZone
from tests.machines import machine_text

AXES = ("X", "Y", "Z")
BASE = parse_machine(machine_text("xyz_unit"))


def machine_with(zones):
    return replace(BASE, allowed=AllowedSet(tuple(zones), BASE.allowed.tool_axis))


small = st.integers(-12, 12)
coords = st.builds(lambda n, d: F(n, d), st.integers(-40, 40), st.sampled_from([1, 2, 4]))
tans = st.builds(lambda n, d: F(n, d), st.integers(-8, 8), st.sampled_from([1, 2, 3, 4, 8]))


@st.composite
def zone_sets(draw):
    """An allow box near the origin, sometimes a forbid box and a stepped table."""
    zones = []
    lo = [draw(st.integers(-30, 0)) for _ in range(3)]
    hi = [lo[k] + draw(st.integers(4, 50)) for k in range(3)]
    zones.append(BoxZone("travel", tuple((a, F(lo[k]), F(hi[k])) for k, a in enumerate(AXES))))
    if draw(st.booleans()):
        x0, y0 = draw(small), draw(small)
        zones.append(BoxZone("post", (("X", F(x0), F(x0 + draw(st.integers(1, 10)))),
                                      ("Y", F(y0), F(y0 + draw(st.integers(1, 10))))), forbid=True))
    if draw(st.booleans()):
        limited = draw(st.sampled_from(["Y", "Z"]))
        cuts = sorted(set(draw(st.lists(st.integers(-25, 25), min_size=1, max_size=3))))
        regions = tuple(Region(F(c), F(draw(st.integers(-25, 5))), None) for c in cuts) + (
            Region(F(cuts[-1] + 30), F(draw(st.integers(-25, 5))), None),)
        zones.append(SteppedZone("table", "X", limited, F(cuts[0] - 30), regions))
    return zones


@st.composite
def circle_arcs(draw, helix: bool = False, turns: bool = False):
    """An I/J arc with a rational centre and rational end points on its circle (exact)."""
    c = (draw(coords), draw(coords))
    r = F(draw(st.integers(1, 24)), draw(st.sampled_from([1, 2])))
    m_s, m_e = draw(tans), draw(tans)
    q_s, q_e = draw(st.integers(0, 3)), draw(st.integers(0, 3))
    cw = draw(st.booleans())

    def on_circle(m, quarter):
        base = [(r, F0), (F0, r), (-r, F0), (F0, -r)][quarter]
        den = 1 + m * m
        return (c[0] + ((1 - m * m) * base[0] - 2 * m * base[1]) / den,
                c[1] + ((1 - m * m) * base[1] + 2 * m * base[0]) / den)

    s, e = on_circle(m_s, q_s), on_circle(m_e, q_e)
    z0 = draw(coords)
    z1 = draw(coords) if helix else z0
    n_turns = draw(st.integers(0, 2)) if turns else 0
    return Segment(SegmentKind.ARC, (s[0], s[1], z0), (e[0], e[1], z1), AXES, plane=Plane.XY, clockwise=cw,
                   centre=c, turns=n_turns)


F0 = F(0)


@st.composite
def r_format_arcs(draw):
    s = (draw(coords), draw(coords))
    e = (draw(coords), draw(coords))
    if s == e:
        e = (e[0] + 1, e[1])
    chord2 = (e[0] - s[0]) ** 2 + (e[1] - s[1]) ** 2
    half = F(int(chord2 ** 0.5 * 500) + 1, 1000)  # > half the chord
    r = half + F(draw(st.integers(0, 40)), 4)
    if draw(st.booleans()):
        r = -r
    z = draw(coords)
    return Segment(SegmentKind.ARC, (s[0], s[1], z), (e[0], e[1], z), AXES, plane=Plane.XY,
                   clockwise=draw(st.booleans()), radius=r)


def reference(m, seg, margin):
    """The solver path's outcome: "safe", "unsafe" or "open"."""
    limits = RunLimits(budget_s=None, query_time_s=2.0)
    p = Prover(m, margin=margin, engine="z3", limits=limits)
    with limits.watch():
        out = p.check(seg)
    if out.violation is not None:
        return "unsafe", out.violation
    return ("open" if out.reason is not None else "safe"), None


def enclosure(m, seg, margin):
    p = Prover(m, margin=margin)
    out = decide_arc(p, seg, arc_geom(seg), ())
    if out is None:
        return "open", None
    return ("unsafe", out.violation) if out.violation is not None else ("safe", None)


def exact_samples(seg):
    """Exact rational points of a circle arc (rational centre, no helix), 64 per quarter."""
    g = arc_geom(seg)
    c = g.centre
    u = (g.s[0] - c[0], g.s[1] - c[1])
    w = (g.e[0] - c[0], g.e[1] - c[1])
    out = []
    for base in arc_bases(u, g.ccw):
        for i in range(65):
            p = rational_point_on_arc(g, F(i, 64), base)
            if in_sweep(u, w, (p[0] - c[0], p[1] - c[1]), g.ccw, g.full):
                out.append(dict(zip(AXES, (p[0], p[1], seg.start[2]))))
    return out


def agree(m, seg, margin):
    mine, v = enclosure(m, seg, margin)
    ref, rv = reference(m, seg, margin)
    assert not (mine == "safe" and ref == "unsafe"), (seg, rv)
    assert not (mine == "unsafe" and ref == "safe"), (seg, v)
    if v is not None:  # a certified point: strictly outside, and it violates
        assert m.allowed.violated_zones(dict(v.point), seg.tool_length)
        assert m.allowed.violated_zones(dict(v.path_point), seg.tool_length, margin)
    return mine, ref, v


#: HYPOTHESIS_PROFILE=long multiplies the examples by 50 (randomized); the default run stays small.
LONG = os.environ.get("HYPOTHESIS_PROFILE") == "long"


def sized(n: int):
    return settings(max_examples=n * 50 if LONG else n, deadline=None, derandomize=not LONG,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


@sized(40)
@given(circle_arcs(), zone_sets(), st.sampled_from([F0, F0, F(1, 2)]))
def test_circles_agree_with_the_solver_and_with_exact_points(seg, zones, margin):
    m = machine_with(zones)
    mine, ref, v = agree(m, seg, margin)
    outside = [p for p in exact_samples(seg) if m.allowed.violated_zones(p, F0, margin)]
    if outside:
        assert mine != "safe"
    if v is not None:  # the path point of a circle is exact: on the circle and in the sweep
        g = arc_geom(seg)
        pp = dict(v.path_point)
        d = (pp["X"] - g.centre[0], pp["Y"] - g.centre[1])
        assert d[0] ** 2 + d[1] ** 2 == g.r2_lo
        assert in_sweep((g.s[0] - g.centre[0], g.s[1] - g.centre[1]), (g.e[0] - g.centre[0], g.e[1] - g.centre[1]),
                        d, g.ccw, g.full)


@sized(25)
@given(circle_arcs(helix=True, turns=True), zone_sets(), st.sampled_from([F0, F(1, 4)]))
def test_helices_and_multi_turn_helices_agree_with_the_solver(seg, zones, margin):
    agree(machine_with(zones), seg, margin)


@sized(15)
@given(r_format_arcs(), zone_sets())
def test_r_format_arcs_agree_with_the_solver(seg, zones):
    m = machine_with(zones)
    mine, ref, v = agree(m, seg, F0)
    if v is not None:  # the reported point lies within the note's distance of the exact arc
        assert "irrational path point" in v.note or v.parameter in (0, 1) or v.path_point in (
            tuple(zip(AXES, seg.start)), tuple(zip(AXES, seg.end)))


@sized(25)
@given(circle_arcs(helix=True), zone_sets(), st.integers(1, 30))
def test_spirals_agree_with_the_solver(seg, zones, grow):
    # move the end point outwards along its radius by grow/1000: the start and end radii differ
    g = arc_geom(seg)
    c = g.centre
    e = (c[0] + (seg.end[0] - c[0]) * (1 + F(grow, 1000)), c[1] + (seg.end[1] - c[1]) * (1 + F(grow, 1000)))
    if (e[0], e[1]) == seg.start[:2]:
        return
    spiral = replace(seg, end=(e[0], e[1], seg.end[2]))
    assert ArcEnclosure(Prover(machine_with(zones)), spiral, arc_geom(spiral)).spiral
    agree(machine_with(zones), spiral, F0)


def _spiral_xy(seg, samples: int = 4000):
    """Float points of a spiral (radius linear in the swept angle), an independent evaluation."""
    import math

    c = [float(x) for x in seg.centre]
    s = [float(x) - k for x, k in zip(seg.start[:2], c)]
    e = [float(x) - k for x, k in zip(seg.end[:2], c)]
    r0, r1 = math.hypot(*s), math.hypot(*e)
    a0, a1 = math.atan2(s[1], s[0]), math.atan2(e[1], e[0])
    sign = -1 if seg.clockwise else 1
    sweep = (sign * (a1 - a0)) % (2 * math.pi) or 2 * math.pi
    for i in range(samples + 1):
        t = i / samples
        a, r = a0 + sign * sweep * t, r0 + (r1 - r0) * t
        yield c[0] + r * math.cos(a), c[1] + r * math.sin(a)


@sized(30)
@given(circle_arcs(), st.integers(1, 30), st.integers(0, 3))
def test_spirals_ending_on_a_zone_face_agree_with_the_solver_and_with_sampled_points(seg, grow, face):
    # a spiral whose end lies exactly on one face of the travel box: the pieces next to the end never fit
    # as annulus boxes; where a coordinate is monotone the piece's range comes from its end points
    g = arc_geom(seg)
    c = g.centre
    e = (c[0] + (seg.end[0] - c[0]) * (1 + F(grow, 1000)), c[1] + (seg.end[1] - c[1]) * (1 + F(grow, 1000)))
    if (e[0], e[1]) == seg.start[:2]:
        return
    spiral = replace(seg, end=(e[0], e[1], seg.end[2]))
    axis, side = ("X", "Y")[face % 2], face // 2  # side 0: the face is the box's max, 1: its min
    k = AXES.index(axis)
    limits = [(a, F(-100), F(100)) for a in AXES]
    limits[k] = (axis, F(-100), e[k]) if side == 0 else (axis, e[k], F(100))
    m = machine_with([BoxZone("travel", tuple(limits))])
    mine, ref, v = agree(m, spiral, F0)
    if mine == "safe":
        for x, y in _spiral_xy(spiral):
            coord = (x, y)[k]
            assert (coord <= float(e[k]) + 1e-9) if side == 0 else (coord >= float(e[k]) - 1e-9), (x, y)


def test_multi_turn_helix_leaving_the_allowed_set_is_unsafe_with_a_witness():
    # from (10, 0, Z0) two and a half turns (LinuxCNC P3: turns=2) of radius 10 around (0, 0) down to
    # (-10, 0, Z-40); the table allows Z >= -40 for X <= 5 but only Z >= -25 beyond X5, and both
    # end points are allowed: the third pass over X > 5 (Z about -32) dips below the table
    table = SteppedZone("table", "X", "Z", F(-50), (Region(F(5), F(-40), None), Region(F(50), F(-25), None)))
    m = machine_with([table])
    seg = Segment(SegmentKind.ARC, (F(10), F0, F0), (F(-10), F0, F(-40)), AXES, block=7, plane=Plane.XY,
                  clockwise=False, centre=(F0, F0), turns=2)
    for end in (seg.start, seg.end):
        assert not m.allowed.violated_zones(dict(zip(AXES, end)), F0)
    r = verify_segments([seg], m)
    assert r.verdict is Verdict.UNSAFE, r.reasons
    v = r.violations[0]
    assert v.segment_kind == "helix" and m.allowed.violated_zones(dict(v.point), F0)
    pp = dict(v.path_point)
    assert pp["X"] > 5 and pp["Z"] < -25
    assert F(7, 10) < v.first_exit_parameter < F(9, 10)  # the third pass, not the first two
    # the same helix a turn shorter (1.5 turns down to Z-40) passes X > 5 the last time at Z-26.7: also
    # unsafe; with its end at Z-30 it stays above Z-25 beyond X5 (at Z-20 there): safe
    assert verify_segments([replace(seg, turns=1)], m).verdict is Verdict.UNSAFE
    assert verify_segments([replace(seg, turns=1, end=(F(-10), F0, F(-30)))], m).verdict is Verdict.SAFE


@sized(50)
@given(st.fractions(min_value=0, max_value=1, max_denominator=2**40))
def test_fixed_point_arctangent_encloses_the_series(m):
    from nczones.prover.arcs import _atan_iv, _out
    from nczones.prover.geometry import atan_bounds

    lo, hi = _atan_iv(m)
    a, b = atan_bounds(m, 200)  # a finer enclosure of the same core lies inside (nczones.exact.elementary)
    assert lo <= a <= b <= hi and hi - lo < F(1, 2**85)
    o_lo, o_hi = _out((lo, hi))
    assert o_lo <= lo and hi <= o_hi and o_hi - o_lo <= hi - lo + F(2, 2**72)
