"""The exact polygon tier's index (:class:`nczones.prover.polygon.EdgeBoxes`) against brute force.

* ``locate`` (integers over the query's denominator, the edges of one band) gives the crossing number of
  every edge in ``Fraction`` arithmetic (the rule it replaced), on points at vertices, on edges, on the
  horizontal lines through vertices and anywhere, for star-shaped and orthogonal polygons (many horizontal
  edges), scaled to huge and to tiny units and given odd denominators.
* ``near`` returns exactly the edges whose closed boxes meet the query box, in edge order, also for boxes
  whose sides fall between two multiples of the polygon's unit and for boxes of no width.
* ``box_fits`` agrees with an all-edges decision of the same rule.
"""

from __future__ import annotations

from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import polygon_problem
from nczones.prover import polygon as pg
from nczones.zones import PolygonZone
from nczones.zones.model import segment_meets_open_box
from tests.prover.test_polygon_screen import star_polygons
from tests.sizes import examples


def brute_locate(zone, q):
    """Every edge, in ``Fraction``: the crossing number of a ray to +x (half-open rule), 0 on an edge."""
    inside = False
    for a, b in zone.edges():
        if (a[1] < q[1] and b[1] < q[1]) or (a[1] > q[1] and b[1] > q[1]):
            continue
        cross = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])
        if cross == 0 and min(a[0], b[0]) <= q[0] <= max(a[0], b[0]):
            return 0
        if (a[1] > q[1]) != (b[1] > q[1]):
            x_cross = a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if q[0] < x_cross:
                inside = not inside
    return 1 if inside else -1


def brute_near(zone, x0, x1, y0, y1):
    return [(a, b) for a, b in zone.edges()
            if min(a[0], b[0]) <= x1 and max(a[0], b[0]) >= x0 and min(a[1], b[1]) <= y1 and max(a[1], b[1]) >= y0]


@st.composite
def orthogonal_polygons(draw):
    """A staircase: a simple orthogonal polygon (every other edge horizontal), with collinear runs."""
    steps = draw(st.lists(st.integers(1, 4), min_size=1, max_size=7))
    verts = [(F(0), F(0))]
    x = 0
    for h in steps:
        verts.append((F(x), F(h)))
        x += draw(st.integers(1, 3))
        verts.append((F(x), F(h)))
    verts.append((F(x), F(0)))
    # collinear vertices on the bottom edge, right to left
    verts += [(F(m, 2), F(0)) for m in range(2 * x - 1, 0, -draw(st.integers(1, 3)))]
    verts = [v for i, v in enumerate(verts) if i == 0 or v != verts[i - 1]]  # equal heights: one vertex
    assert polygon_problem(verts) is None
    return PolygonZone("stairs", ("X", "Y"), tuple(verts), forbid=draw(st.booleans()))


def scaled(zone, unit, shift):
    return PolygonZone(zone.name, zone.plane, tuple((x * unit + shift, y * unit - shift) for x, y in zone.vertices),
                       zone.limits, zone.forbid, zone.point)


polygons = st.builds(scaled, st.one_of(star_polygons(max_vertices=12), orthogonal_polygons()),
                     st.sampled_from([F(1), F(1), F(10**15), F(1, 10**22), F(3, 7), F(-2, 3)]),
                     st.sampled_from([F(0), F(1, 3), F(10**6)]))
fractions = st.builds(F, st.integers(-40, 40), st.sampled_from([1, 1, 2, 3, 7, 10**20 + 1]))


@st.composite
def points_about(draw, zone):
    """A vertex, a point of an edge, a point on a vertex's horizontal line, or any point near the polygon."""
    v = zone.vertices
    xs, ys = [p[0] for p in v], [p[1] for p in v]
    lo_x, hi_x, lo_y, hi_y = min(xs), max(xs), min(ys), max(ys)
    w, h = hi_x - lo_x, hi_y - lo_y
    kind = draw(st.integers(0, 3))
    if kind == 0:
        return draw(st.sampled_from(v))
    t = draw(st.fractions(0, 1, max_denominator=10**6))
    if kind == 1:
        a, b = draw(st.sampled_from(zone.edges()))
        return a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
    s = draw(st.fractions(-F(1, 4), F(5, 4), max_denominator=10**6))
    if kind == 2:
        return lo_x + s * w, draw(st.sampled_from(ys))
    return lo_x + s * w, lo_y + (t * 3 / 2 - F(1, 4)) * h


@settings(max_examples=examples(80, 600), deadline=None, derandomize=True)
@given(polygons, st.data())
def test_locate_agrees_with_every_edge_in_fractions(zone, data):
    for _ in range(12):
        q = data.draw(points_about(zone))
        assert pg.locate(zone, q) == brute_locate(zone, q), q


@settings(max_examples=examples(60, 400), deadline=None, derandomize=True)
@given(polygons, st.data())
def test_near_is_exactly_the_edges_whose_boxes_meet(zone, data):
    for _ in range(8):
        p, q = data.draw(points_about(zone)), data.draw(points_about(zone))
        x0, x1 = sorted((p[0], q[0]))
        y0, y1 = sorted((p[1], q[1]))
        if data.draw(st.booleans()):  # a thin box, its sides between the polygon's grid points
            y1 = y0 + data.draw(st.sampled_from([F(0), F(1, 10**30), F(1, 3)]))
        assert pg.edge_boxes(zone).near(x0, x1, y0, y1) == brute_near(zone, x0, x1, y0, y1)


@settings(max_examples=examples(60, 400), deadline=None, derandomize=True)
@given(polygons, st.data())
def test_box_fits_agrees_with_all_edges(zone, data):
    for _ in range(6):
        p, q = data.draw(points_about(zone)), data.draw(points_about(zone))
        lo, hi = (min(p[0], q[0]), min(p[1], q[1])), (max(p[0], q[0]), max(p[1], q[1]))
        if not (lo[0] < hi[0] and lo[1] < hi[1]):
            continue
        want_where = brute_locate(zone, ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2))
        meets = any(segment_meets_open_box(a, b, lo, hi) for a, b in zone.edges())
        want = not meets and (want_where < 0 if zone.forbid else want_where > 0)
        assert pg.box_fits(zone, lo, hi) == want, (lo, hi)


def test_a_tall_comb_files_each_tooth_in_few_bands():
    # 400 tall teeth: the bands widen so the lists stay a few entries an edge, and every answer stays exact
    verts = []
    for k in range(100):
        verts += [(F(4 * k), F(0)), (F(4 * k), F(1000)), (F(4 * k + 1), F(1000)), (F(4 * k + 1), F(1))]
    verts += [(F(400), F(1)), (F(400), F(-1)), (F(0), F(-1))]
    verts[0] = (F(0), F(-1))
    verts = list(dict.fromkeys(verts))
    assert polygon_problem(verts) is None
    zone = PolygonZone("comb", ("X", "Y"), tuple(verts))
    eb = pg.edge_boxes(zone)
    assert sum(len(b) for b in eb.bands) <= 6 * len(zone.vertices)
    for q in [(F(1, 2), F(500)), (F(2), F(500)), (F(4), F(1000)), (F(399, 2), F(1, 2)), (F(3), F(1))]:
        assert pg.locate(zone, q) == brute_locate(zone, q)
