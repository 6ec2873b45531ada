"""Refinement by splitting for helices (nczones/prover/arcs.py, nczones/prover/refine.py, issues 4, 19).

A helix is not polynomial; the prover proves a containing set and, when that
set admits a violation the exact path may not reach, splits the sweep and
proves the pieces (exact boxes first, :mod:`nczones.prover.arcs`, then Z3
per piece, :mod:`nczones.prover.refine`), up to a budget; then ``unknown``.  An exact helix point is
rational at every quarter turn of a sweep made of whole quarter turns, which
gives the brute-force sampler below.
"""

from dataclasses import replace
from fractions import Fraction as F

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover import Prover, Verdict, arcs, refine, verify_segments
from nczones.prover.geometry import arc_geom
from nczones.zones import AllowedSet, Region, SteppedZone
from tests.machines import machine_text

AXES = ("X", "Y", "Z")


def machine(step_z: int, low_z: int = -20):
    """A stepped table along X: for X <= 0 the tool must stay at Z >= step_z, beyond at Z >= low_z."""
    rapid = {f"machine.rapid.{axis}": "3000" for axis in "XYZ"}
    base = parse_machine(machine_text("xyz_unit", set=rapid))
    z = SteppedZone("table", "X", "Z", F(-50), (Region(F(0), F(step_z), None), Region(F(50), F(low_z), None)))
    return replace(base, allowed=AllowedSet((z,), base.allowed.tool_axis))


def helix(start, end, clockwise, centre=(0, 0), block=0):
    return Segment(SegmentKind.ARC, tuple(map(F, start)), tuple(map(F, end)), AXES, block=block,
                   plane=Plane.XY, clockwise=clockwise, centre=tuple(map(F, centre)))


def test_safe_helix_near_the_step_is_proved_by_splitting():
    # half turn from (-10, 0, Z10) clockwise over (0, 10) to (10, 0, Z0): while X < 0 the
    # helix is above Z5, the step needs Z >= 4 there; the whole enclosure (X in [-10, 10]
    # times Z in [0, 10]) holds (-10, 0, 0), which violates
    m = machine(4)
    seg = helix((-10, 0, 10), (10, 0, 0), True)
    p = Prover(m)
    g = arc_geom(seg)
    body, names = p.arc_query(seg, g, False)
    ans = p.solver.check(body, names, precision=60)
    assert ans.status == "sat"  # the old single-enclosure proof fails ...
    assert p._arc_witness(seg, g, ans.values, ()) is None  # ... and finds no real violation
    r = verify_segments([seg], m)
    assert r.verdict is Verdict.SAFE
    q = Prover(m)
    assert q.check(seg).violation is None and q.stats.get("arc_pieces", 0) >= 2
    # the solver's refinement proves it too (the path when the exact pieces leave it open)
    z = Prover(m)
    assert refine.refine_arc(z, seg, g, ()).reason is None and z.stats.get("refined_pieces", 0) >= 2


def test_helix_crossing_the_step_is_unsafe_with_a_certified_witness():
    m = machine(4)
    seg = helix((-10, 0, 3), (10, 0, -7), True)  # starts allowed? no: X=-10 needs Z >= 4
    r = verify_segments([seg], m)
    assert r.verdict is Verdict.UNSAFE
    seg = helix((-10, 0, 12), (10, 0, -10), True)  # both ends allowed, crosses Z4 while X < 0
    assert not m.allowed.violated_zones(dict(zip(AXES, seg.start)), F(0))
    assert not m.allowed.violated_zones(dict(zip(AXES, seg.end)), F(0))
    r = verify_segments([seg], m)
    assert r.verdict is Verdict.UNSAFE
    v = r.violations[0]
    assert m.allowed.violated_zones(dict(v.point), F(0))
    pp = dict(v.path_point)
    assert pp["X"] < 0 and pp["Z"] < 4  # on the part of the helix over the high step


def test_budget_exhausted_is_unknown_with_the_reason():
    # the helix touches the step exactly at X = 0 (Z = 5 there, needs Z >= 5): every piece
    # holding X = 0 has an enclosure dipping below Z5, so no budget proves it
    m = machine(5)
    seg = helix((-10, 0, 10), (10, 0, 0), True)
    r = verify_segments([seg], m)
    assert r.verdict is Verdict.UNKNOWN
    assert any("budget" in x.message for x in r.reasons)


def test_a_small_budget_gives_unknown(monkeypatch):
    monkeypatch.setattr(refine, "MAX_PIECES", 2)
    monkeypatch.setattr(arcs, "MAX_PIECES", 2)
    r = verify_segments([helix((-10, 0, 10), (10, 0, 0), True)], machine(4))
    assert r.verdict is Verdict.UNKNOWN
    assert any("budget" in x.message for x in r.reasons)


_QUARTERS = [(1, 0), (0, 1), (-1, 0), (0, -1)]  # ccw order


def quarter_points(cx, cy, r, q0, n, cw, z0, z1):
    """Exact helix points at every quarter turn of a sweep of n quarter turns."""
    out = []
    for j in range(n + 1):
        d = _QUARTERS[(q0 - j) % 4] if cw else _QUARTERS[(q0 + j) % 4]
        out.append((F(cx + r * d[0]), F(cy + r * d[1]), F(z0) + F(z1 - z0) * F(j, n)))
    return out


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.integers(-6, 6), st.integers(-6, 6), st.integers(1, 12), st.integers(0, 3), st.integers(1, 4),
       st.booleans(), st.integers(-15, 15), st.integers(-15, 15), st.integers(-5, 8))
def test_never_safe_when_an_exact_helix_point_is_outside(cx, cy, r, q0, n, cw, z0, z1, step):
    if z0 == z1:
        z1 = z0 + 1
    m = machine(step, -8)
    pts = quarter_points(cx, cy, r, q0, n, cw, z0, z1)
    seg = helix(pts[0], pts[-1], cw, (cx, cy))
    res = verify_segments([seg], m)
    outside = [p for p in pts if m.allowed.violated_zones(dict(zip(AXES, p)), F(0))]
    if outside:
        assert res.verdict is Verdict.UNSAFE
    for v in res.violations:
        assert m.allowed.violated_zones(dict(v.point), F(0))
    if res.verdict is Verdict.UNKNOWN:
        assert res.reasons


def test_spiral_arc_near_the_step_is_proved_and_a_crossing_one_is_unsafe():
    # start radius 10, end radius 11 (LinuxCNC moves a spiral): per piece the radius is enclosed
    m = machine(4)
    p = Prover(m)
    assert p.check(helix((-10, 0, 10), (11, 0, 0), True)).violation is None
    assert p.stats.get("arc_pieces", 0) >= 2
    assert verify_segments([helix((-10, 0, 10), (11, 0, 0), True)], m).verdict is Verdict.SAFE
    r = verify_segments([helix((-10, 0, 12), (11, 0, -10), True)], m)
    assert r.verdict is Verdict.UNSAFE
    assert m.allowed.violated_zones(dict(r.violations[0].point), F(0))
