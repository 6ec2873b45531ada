"""Polygon zones without the solver (:mod:`nczones.prover.polygon`).

* The exact violation set of a straight piece against a polygon (allow and
  forbid, margins, prism limits, tool-tip zones) is exact: a parameter is in
  it iff the zone's own membership test (``AllowedSet.violated_zones``) says
  the margin box there violates — checked at every interval end, between
  them and at random parameters.
* The grid screen is sound: every box it proves inside (outside) the
  polygon is inside (misses the interior) by the exact box test, and its
  cells agree with exact point location.
* Verdicts and violating blocks agree with Z3 sent every segment, for
  column chunks (grid screen, then the exact tier) and single segments,
  lines and doglegs, allow and forbid polygons, with margins; with arcs
  against the polygons too (column chunks, segments screened in batches and
  segments decided one by one give the same answer; where Z3 decides, it
  agrees).
"""

from __future__ import annotations

import math
from dataclasses import replace
from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover import exact as ex
from nczones.prover import polygon as pg
from nczones.prover import verify_segments
from nczones.zones import AllowedSet, BoxZone, PolygonZone, ZonePoint
from tests.prover.test_screen_chunks import AXES2, chunk_of, chunk_segments
from tests.prover.test_segment_batches import by_columns, one_by_one
from tests.sizes import examples


@st.composite
def star_polygons(draw, forbid=None, max_vertices=9):
    """Simple polygons: vertices at increasing angles around (10, 2) with random radii (scale 2),
    so edges may be collinear, axis-parallel or form notches."""
    n = draw(st.integers(3, max_vertices))
    cuts = sorted(draw(st.lists(st.integers(0, 359), min_size=n, max_size=n, unique=True)))
    verts = []
    for deg in cuts:
        r = draw(st.integers(200, 900)) / 100
        verts.append((F(round((10 + r * math.cos(math.radians(deg))) * 100), 100),
                      F(round((2 + r * math.sin(math.radians(deg))) * 100), 100)))
    from nczones.machine import polygon_problem

    if len(set(verts)) < 3 or polygon_problem(verts) is not None:
        verts = [(F(4), F(-3)), (F(16), F(-3)), (F(16), F(7)), (F(10), F(1)), (F(4), F(7))]
    if forbid is None:
        forbid = draw(st.booleans())
    limits = ()
    if draw(st.integers(0, 3)) == 0:
        limits = (("Z", F(draw(st.integers(-3, 0))), F(draw(st.integers(0, 3)))),)
    point = draw(st.sampled_from([ZonePoint.MACHINE, ZonePoint.TIP])) if limits else ZonePoint.MACHINE
    return PolygonZone("poly", ("X", "Y"), tuple(verts), limits, forbid, point)


coord = st.integers(-200, 3000).map(lambda v: F(v, 100))
ycoord = st.integers(-900, 1100).map(lambda v: F(v, 100))
margins = st.sampled_from([F(0), F(0), F(1, 4), F(3, 2)])


@settings(max_examples=250, deadline=None, derandomize=True)
@given(star_polygons(), coord, ycoord, coord, ycoord, st.integers(-300, 300), st.integers(-300, 300), margins,
       st.sampled_from([F(0), F(2)]), st.lists(st.integers(0, 1000), max_size=6))
def test_violation_set_is_exact(zone, x0, y0, x1, y1, z0, z1, d, tool, extra):
    allowed = AllowedSet((zone,), "Z")
    p0, p1 = (x0, y0, F(z0, 100)), (x1, y1, F(z1, 100))
    axes = ("X", "Y", "Z")
    ivs = ex.line_violation(zone, p0, p1, axes, d, tool, "Z")
    ts = {F(0), F(1)} | {F(e, 1000) for e in extra}
    for iv in ivs:
        ts |= {iv.lo, iv.hi, (iv.lo + iv.hi) / 2, iv.lo + (iv.hi - iv.lo) / 1000}
    for a, b in zip(sorted(ts), sorted(ts)[1:]):
        ts.add((a + b) / 2)
    for t in ts:
        if not 0 <= t <= 1:
            continue
        p = {a: u + t * (v - u) for a, u, v in zip(axes, p0, p1)}
        truth = zone in allowed.violated_zones(p, tool, d)
        assert truth == any(iv.contains(t) for iv in ivs), (t, ivs)


@settings(max_examples=40, deadline=None, derandomize=True)
@given(star_polygons(), st.integers(0, 3), st.data())
def test_grid_proves_only_what_is_true(zone, scale, data):
    g = pg.grid(zone, scale)
    unit = 10**scale
    n = 40
    xs = np.array(data.draw(st.lists(st.integers(-2 * unit, 30 * unit), min_size=2 * n, max_size=2 * n)))
    ys = np.array(data.draw(st.lists(st.integers(-12 * unit, 14 * unit), min_size=2 * n, max_size=2 * n)))
    spans = np.array(data.draw(st.lists(st.integers(0, unit), min_size=2 * n, max_size=2 * n)))
    lo_a, hi_a = xs, xs + spans
    lo_b, hi_b = ys, ys + spans[::-1]
    proved = pg.screen_rows(zone, scale, lo_a, hi_a, lo_b, hi_b)
    for i in np.flatnonzero(proved).tolist():
        lo = (F(int(lo_a[i]), unit), F(int(lo_b[i]), unit))
        hi = (F(int(hi_a[i]), unit), F(int(hi_b[i]), unit))
        assert pg.box_fits(zone, lo, hi), (lo, hi)
    # cells the grid calls inside / outside: their centres are there exactly
    inside = (g.not_in[1:, 1:] - g.not_in[:-1, 1:] - g.not_in[1:, :-1] + g.not_in[:-1, :-1]) == 0
    outside = (g.not_out[1:, 1:] - g.not_out[:-1, 1:] - g.not_out[1:, :-1] + g.not_out[:-1, :-1]) == 0
    assert not (inside & outside).any()
    cells = np.argwhere(inside | outside)
    boundary = np.argwhere(~(inside | outside))
    for c, r in cells[np.random.default_rng(scale).choice(len(cells), 60)].tolist():
        centre = (F(g.x0 + int(c) * g.w, g.unit) + F(g.w, 2 * g.unit), F(g.y0 + int(r) * g.w, g.unit) + F(g.w, 2 * g.unit))
        assert pg.locate(zone, centre) == (1 if inside[c, r] else -1)
    # and every edge's cells are boundary cells: a vertex's cell is never inside or outside
    for x, y in zone.vertices:
        c = (x * g.unit - g.x0) // g.w
        r = (y * g.unit - g.y0) // g.w
        assert not inside[c, r] and not outside[c, r]
    assert len(boundary) > 0


def test_grid_screen_proves_most_of_a_band_of_short_moves():
    # a polygon with 200 vertices and 2,000 short moves within 1 of its outline, none crossing it
    n = 200
    verts = tuple((F(round(100 * math.cos(2 * math.pi * i / n) * 1000), 1000),
                   F(round(100 * math.sin(2 * math.pi * i / n) * 1000), 1000)) for i in range(n))
    zone = PolygonZone("outline", ("X", "Y"), verts)
    th = np.linspace(0, 2 * np.pi, 2000)
    r0 = 98.5
    xs = np.round(r0 * np.cos(th) * 1000).astype(np.int64)
    ys = np.round(r0 * np.sin(th) * 1000).astype(np.int64)
    proved = pg.screen_rows(zone, 3, np.minimum(xs[:-1], xs[1:]), np.maximum(xs[:-1], xs[1:]),
                            np.minimum(ys[:-1], ys[1:]), np.maximum(ys[:-1], ys[1:]))
    assert proved.mean() > 0.9


def _polygon_machine(zone: PolygonZone, rapid_mode: str):
    base = parse_machine(f"""
[machine]
axes = ["X", "Y"]
rapid_mode = "{rapid_mode}"
[machine.rapid]
X = "3000"
Y = "1000"
[machine.reference]
X = "0"
Y = "0"
""")
    zones: tuple = (zone,)
    if zone.forbid:
        zones = (BoxZone("travel", (("X", F(-3), F(31)), ("Y", F(-10), F(12)))), zone)
    return replace(base, allowed=AllowedSet(zones, None))


straight_segments = chunk_segments().map(lambda segs: [s for s in segs if s.kind is not SegmentKind.ARC]).filter(bool)


@settings(max_examples=examples(15, 30), deadline=None, derandomize=True)
@given(star_polygons(max_vertices=7).map(lambda z: replace(z, limits=(), point=ZonePoint.MACHINE)),
       straight_segments, st.sampled_from(["linear", "dogleg"]), st.sampled_from([F(0), F(0), F(1, 2)]))
def test_polygon_verdicts_agree_with_z3_per_segment(zone, segs, rapid_mode, margin):
    m = _polygon_machine(zone, rapid_mode)
    b = verify_segments(segs, m, engine="z3", margin=margin)
    if b.verdict.label == "unknown":
        return  # the solver could not decide: nothing to compare
    a = verify_segments([chunk_of(segs, 2, AXES2)], m, margin=margin)
    with by_columns():
        c = verify_segments(segs, m, margin=margin)
    with one_by_one():
        d = verify_segments(segs, m, margin=margin)
    assert a.verdict == b.verdict == c.verdict == d.verdict
    assert [v.block for v in a.violations] == [v.block for v in b.violations] == [v.block for v in c.violations] \
        == [v.block for v in d.violations]


@st.composite
def arcs_near_the_polygons(draw):
    """Arcs (quarter, half, three-quarter and full turns, scale 2) around points near the stars' centre."""
    out = []
    for i in range(draw(st.integers(1, 4))):
        c = (F(draw(st.integers(700, 1300)), 100), F(draw(st.integers(-100, 500)), 100))
        u = (F(draw(st.integers(-350, 350)), 100), F(draw(st.integers(-350, 350)), 100))
        if u == (0, 0):
            u = (F(1), F(0))
        e2 = draw(st.sampled_from([(u[1], -u[0]), (-u[0], -u[1]), (-u[1], u[0]), u]))
        s, e = (c[0] + u[0], c[1] + u[1]), (c[0] + e2[0], c[1] + e2[1])
        out.append(Segment(SegmentKind.ARC, s, e, AXES2, block=i, plane=Plane.XY, clockwise=draw(st.booleans()),
                           centre=c))
    return out


@settings(max_examples=examples(6, 12), deadline=None, derandomize=True)
@given(star_polygons(max_vertices=6).map(lambda z: replace(z, limits=(), point=ZonePoint.MACHINE)),
       arcs_near_the_polygons(), st.sampled_from([F(0), F(0), F(1, 2)]))
def test_arcs_against_polygons_agree_with_z3_per_segment(zone, segs, margin):
    m = _polygon_machine(zone, "linear")
    a = verify_segments([chunk_of(segs, 2, AXES2)], m, margin=margin)  # the column screen, then one by one
    with by_columns():
        c = verify_segments(segs, m, margin=margin)  # screened in batches
    with one_by_one():
        d = verify_segments(segs, m, margin=margin)  # every arc on its own: exact box, enclosures, Z3
    assert a.verdict == c.verdict == d.verdict
    assert [v.block for v in a.violations] == [v.block for v in c.violations] == [v.block for v in d.violations]
    b = verify_segments(segs, m, engine="z3", margin=margin)
    if b.verdict.label != "unknown" and a.verdict.label != "unknown":
        assert a.verdict == b.verdict
        assert [v.block for v in a.violations] == [v.block for v in b.violations]


def test_a_line_through_a_notch_is_found_without_the_solver():
    zone = PolygonZone("p", ("X", "Y"), ((F(0), F(0)), (F(10), F(0)), (F(10), F(10)), (F(5), F(3)), (F(0), F(10))))
    m = _polygon_machine(zone, "linear")
    seg = Segment(SegmentKind.LINE, (F(1), F(5)), (F(9), F(5)), AXES2, block=0)
    r = verify_segments([chunk_of([seg], 0, AXES2)], m)
    assert r.verdict.label == "unsafe" and dict(r.stats)["z3_queries"] == 0
    v = r.violations[0]
    assert v.first_exit_parameter == F(9, 28)  # where y = 5 meets the notch's left edge, x = 25/7
    ok = Segment(SegmentKind.LINE, (F(1), F(2)), (F(9), F(2)), AXES2, block=0)
    r2 = verify_segments([chunk_of([ok], 0, AXES2)], m)
    assert r2.verdict.label == "safe" and dict(r2.stats)["z3_queries"] == 0
