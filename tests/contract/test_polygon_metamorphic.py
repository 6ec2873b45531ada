"""Polygon zones where they meet other features (tests/contract/polygon_metamorphic.py says what each relation is).

CI size: a few dozen examples in all (derandomized); ``HYPOTHESIS_PROFILE=long`` runs 1,000 of each, and
``NCZONES_POLYGON_EXAMPLES="ranges=500,margins=250,oracles=250,engines=250"`` sets a chunk's sizes
(specs/contract.md has the runs).
"""

import os

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.zones import PolygonZone
from tests.machines import machine_text

from .metamorphic import check_margins, check_ranges
from .polygon_metamorphic import (
    check_engines,
    check_oracles,
    polygon_engine_cases,
    polygon_margin_cases,
    polygon_oracle_cases,
    polygon_range_cases,
)

CI_EXAMPLES = {"ranges": 5, "margins": 5, "oracles": 6, "engines": 4}
LONG_EXAMPLES = {"ranges": 1_000, "margins": 1_000, "oracles": 1_000, "engines": 1_000}


def examples(name: str) -> int:
    text = os.environ.get("NCZONES_POLYGON_EXAMPLES", "")
    chunk = {k.strip(): int(v) for k, v in (item.split("=") for item in text.split(",") if item.strip())}
    if name in chunk:
        return chunk[name]
    return LONG_EXAMPLES[name] if settings.default.max_examples > 100 else CI_EXAMPLES[name]


@settings(max_examples=examples("ranges"))
@given(polygon_range_cases())
def test_a_range_verdict_on_polygon_zones_holds_at_its_concrete_values(case):
    machine, text, params = case
    check_ranges(machine, text, params)


@settings(max_examples=examples("margins"))
@given(polygon_margin_cases())
def test_a_margin_from_polygon_zones_is_clearance(case):
    machine, text, margin, shift = case
    check_margins(machine, text, margin, shift)


@settings(max_examples=examples("oracles"))
@given(polygon_oracle_cases())
def test_polygon_verdicts_agree_with_the_brute_force_and_shapely(case):
    machine, text, margin = case
    check_oracles(machine, text, margin)


@settings(max_examples=examples("engines"))
@given(polygon_engine_cases())
def test_the_column_screen_and_z3_decide_polygon_zones_alike(case):
    machine, text, margin, params = case
    check_engines(machine, text, margin, params)


# ----------------------------------------------------------------------------- findings

BLADE_MACHINE = machine_text("xy_blade_polygon")


def test_a_margin_box_meeting_a_thin_polygon_has_a_witness():
    """Finding (fixed): the margin box of the line's end meets the blade's interior, but no point of the grid
    of vertex coordinates and midpoints lies in the blade (0.014 mm thin), so the witness search failed and the
    run stopped with an internal error instead of reporting the violation."""
    from fractions import Fraction

    from nczones.machine import parse_machine
    from nczones.prover import verify_text

    machine = parse_machine(BLADE_MACHINE)
    result = verify_text("G1 X51 Y48 F100\n", machine, margin=Fraction(2))
    assert result.verdict.label == "unsafe"
    (v,) = result.violations
    point = dict(v.point)
    assert v.zone == "blade" and machine.allowed.zones[1].interior_contains(point)
    assert all(abs(point[a] - q) <= 2 for a, q in v.path_point)
    assert verify_text("G1 X51 Y48 F100\n", machine, margin=Fraction(1, 2)).verdict.label == "safe"


@settings(max_examples=30 if examples("oracles") < 100 else 2_000)
@given(st.data())
def test_a_point_strictly_inside_or_outside_a_polygon_in_an_open_box(data):
    """open_box_point against Shapely: its point is in the open box and strictly on the side asked for; it
    finds none only where the box's overlap with that side has no area (in floats, beyond 1e-9 mm^2)."""
    from fractions import Fraction as F

    from shapely.geometry import Polygon, box

    from nczones.prover.polygon import locate, open_box_point

    from .polygon_metamorphic import polygon_zones

    centre = (F(data.draw(st.integers(30, 70))), F(data.draw(st.integers(30, 70))))
    zone = data.draw(polygon_zones("p", ("X", "Y"), centre, F(25), forbid=False,
                                   shapes=("convex", "star", "u", "slit", "blade")))
    lo = (F(data.draw(st.integers(0, 1000))) / 10, F(data.draw(st.integers(0, 1000))) / 10)
    size = data.draw(st.sampled_from((F(1, 100), F(1, 2), F(2), F(10), F(40))))
    hi = (lo[0] + size, lo[1] + size * data.draw(st.sampled_from((F(1), F(1, 3), F(2)))))
    inside = data.draw(st.booleans())
    q = open_box_point(zone, lo, hi, inside)
    poly = Polygon([(float(a), float(b)) for a, b in zone.vertices])
    cell = box(float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))
    area = (cell.intersection(poly) if inside else cell.difference(poly)).area
    if q is None:
        assert area < 1e-9, f"none found, but the overlap has area {area}"
    else:
        assert lo[0] < q[0] < hi[0] and lo[1] < q[1] < hi[1]
        assert locate(zone, q) == (1 if inside else -1)


def test_a_box_certified_against_a_tip_polygon_sees_the_tool_length():
    """Finding (fixed): box_certainly_violates tested a tip polygon's edges against the machine box, not the box
    the tip sees (Z less the tool length) when the polygon's plane holds Z: a box with tip Z from 12 to 22 across
    a chuck's top face (Z 20) was certified although its points above the face do not violate."""
    import itertools
    from fractions import Fraction as F

    from nczones.prover.exact import box_certainly_violates
    from nczones.zones import AllowedSet, ZonePoint

    chuck = PolygonZone("chuck", ("X", "Z"), ((F(40), F(0)), (F(60), F(0)), (F(60), F(20)), (F(40), F(20))),
                        forbid=True, point=ZonePoint.TIP)
    allowed = AllowedSet((chuck,), "Z")
    lo, hi = {"X": F(50), "Z": F(62)}, {"X": F(51), "Z": F(72)}
    assert not box_certainly_violates(allowed, chuck, lo, hi, F(0), F(50))
    assert box_certainly_violates(allowed, chuck, {"X": F(50), "Z": F(55)}, {"X": F(51), "Z": F(65)}, F(0), F(50))
    assert box_certainly_violates(allowed, chuck, {"X": F(50), "Z": F(55)}, {"X": F(51), "Z": F(65)}, F(1), F(50))
    for p in itertools.product((F(50), F(51)), (F(55), F(65))):
        assert allowed.violated_zones(dict(zip("XZ", p)), F(50), F(1))


@settings(max_examples=20 if examples("oracles") < 100 else 1_000)
@given(st.data())
def test_a_box_certified_against_polygon_zones_violates_at_every_point(data):
    """box_certainly_violates (the certificate of witnesses on arcs, splines, developed arcs) on the polygon
    machines: boxes around vertices and edge points, with the tool lengths, flat or not."""
    import itertools
    from fractions import Fraction as F

    from nczones.prover.exact import box_certainly_violates

    from .polygon_metamorphic import polygon_machines

    machine, _ = data.draw(polygon_machines())
    tool = data.draw(st.sampled_from((F(0), *machine.tool_lengths.values())))
    margin = data.draw(st.sampled_from((F(0), F(1, 1000), F(1, 2))))
    zone = data.draw(st.sampled_from(machine.zones))
    polys = [z for z in machine.zones if isinstance(z, PolygonZone)]
    lo, hi = {}, {}
    base = {"X": F(50), "Y": F(50), "Z": F(100)}
    if polys:
        z = data.draw(st.sampled_from(polys))
        v = data.draw(st.sampled_from(z.vertices))
        for k, a in enumerate(z.plane):
            base[a] = v[k] + (tool if a == "Z" and z.point.name == "TIP" else 0)
    for a in "XYZ":
        off = data.draw(st.sampled_from((F(0), margin, -margin, F(1, 100), F(-1, 3), F(-2))))
        width = data.draw(st.sampled_from((F(0), F(1, 1000), F(1, 10), F(3))))
        lo[a], hi[a] = base[a] + off, base[a] + off + width
    if not box_certainly_violates(machine.allowed, zone, lo, hi, margin, tool):
        return
    corners = [dict(zip("XYZ", c)) for c in itertools.product(*((lo[a], hi[a]) for a in "XYZ"))]
    inner = [{a: lo[a] + (hi[a] - lo[a]) * data.draw(st.fractions(0, 1, max_denominator=64)) for a in "XYZ"}
             for _ in range(8)]
    for p in corners + inner:
        assert zone in machine.allowed.violated_zones(p, tool, margin), (zone.name, p, margin, tool)


SPIRAL_MACHINE = machine_text("xyz_spiral_wall")


def test_an_arc_ending_on_its_start_ray_is_not_proved_safe():
    """Finding (open, made unknown): Shapely in the long run (seed 1) found a spiral whose end lies on the ray
    from the centre through its start, 0.0015 mm further out or in.  LinuxCNC (posemath pmCircleInit) sweeps a
    whole turn there; the prover swept nothing and proved it safe although the turn reaches the wall at X 66.
    The exact circle (end = start) is a whole turn and unsafe; the spirals are now unknown, in both the
    one-by-one path and the column screen, never safe."""
    from nczones.machine import parse_machine
    from nczones.prover import verify_text

    from .polygon_metamorphic import column_screen_forced

    machine = parse_machine(SPIRAL_MACHINE)
    assert verify_text("G90 G1 X63 Y20 F600\nG2 X63 Y20 I2 J0\nM30\n", machine).verdict.label == "unsafe"
    for end in ("63.0015", "62.9985"):
        for g in ("G2", "G3"):
            text = f"G90 G1 X63 Y20 F600\n{g} X{end} Y20 I2 J0\nM30\n"
            assert verify_text(text, machine).verdict.label == "unknown", text
            with column_screen_forced():
                assert verify_text(text, machine).verdict.label == "unknown", text
