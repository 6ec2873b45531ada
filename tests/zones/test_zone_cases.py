"""Hand-picked boundary cases: boxes, polygons, forbid, tool tip, the allowed set."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from nczones.machine import load_machine
from nczones.zones import AllowedSet, BoxZone, PolygonZone, Region, SteppedZone, ZonePoint

from .strategies import FAST

F = Fraction
ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]


def P(**kw):
    return {k: F(v) for k, v in kw.items()}


# ------------------------------------------------------------------ boxes

TRAVEL = BoxZone("travel", (("X", F(0), F(100)), ("Y", F(0), F(50))))
CLAMP = BoxZone("clamp", (("X", F(40), F(60)), ("Y", F(10), F(20))), forbid=True)


@pytest.mark.parametrize(
    "point, inside",
    [
        (P(X=0, Y=0), True),  # corner of the allow box
        (P(X=100, Y=50), True),
        (P(X="100.001", Y=50), False),
        (P(X="-0.001", Y=0), False),
        (P(X=40, Y=10), True),  # corner of the forbid box: touching is allowed
        (P(X=60, Y=20), True),
        (P(X=50, Y=20), True),  # on the forbid box's top face
        (P(X=50, Y="19.999"), False),
        (P(X="40.001", Y="10.001"), False),
        (P(X=50, Y=15), False),
    ],
)
def test_box_boundaries(point, inside):
    assert AllowedSet((TRAVEL, CLAMP)).contains(point) is inside


def test_edge_sliding_along_a_forbid_face_is_allowed():
    s = AllowedSet((TRAVEL, CLAMP))
    for k in range(0, 201):
        x = F(40) + F(k, 10)  # 40 .. 60 along the top face Y = 20
        assert s.contains({"X": x, "Y": F(20)})
        assert not s.contains({"X": x, "Y": F(20) - F(1, 1000)}) or x in (F(40), F(60))


def test_margin_touching_a_forbid_face_is_allowed_and_one_micron_more_is_not():
    s = AllowedSet((TRAVEL, CLAMP))
    assert s.contains_box(P(X=50, Y=25), F(5))  # box touches Y = 20 from above
    assert not s.contains_box(P(X=50, Y=25), F("5.001"))
    assert s.contains_box(P(X=5, Y=5), F(5))  # box touches the travel corner
    assert not s.contains_box(P(X=5, Y=5), F("5.001"))
    assert s.contains_box(P(X=35, Y=5), F(5))  # box corner touches the clamp corner
    assert not s.contains_box(P(X="35.001", Y="5.001"), F(5))


def test_flat_forbid_range_has_no_interior():
    plate = BoxZone("plate", (("X", F(0), F(10)), ("Y", F(5), F(5))), forbid=True)
    s = AllowedSet((plate,))
    assert s.contains(P(X=5, Y=5))
    assert s.contains_box(P(X=5, Y=5), F(1))
    flat_row = SteppedZone("row", "X", "Y", F(0), (Region(F(10), F(5), F(5)),), forbid=True)
    assert AllowedSet((flat_row,)).contains_box(P(X=5, Y=5), F(1))


def test_unbounded_sides():
    above = BoxZone("above", (("Y", F(10), None),))
    s = AllowedSet((above,))
    assert s.contains(P(X="-999999", Y=10)) and not s.contains(P(X=0, Y="9.999"))
    assert s.bounding_box() == {"Y": (F(10), None)}


# ------------------------------------------------------------------ polygons

# An L-shaped chuck in the Z/X plane (concave corner at (40, 60)).
CHUCK = PolygonZone(
    "chuck", ("Z", "X"),
    ((F(0), F(0)), (F(40), F(0)), (F(40), F(60)), (F(55), F(60)), (F(55), F(100)), (F(0), F(100))),
    forbid=True,
)
TRI = PolygonZone("tri", ("X", "Y"), ((F(0), F(0)), (F(10), F(0)), (F(0), F(10))))


@pytest.mark.parametrize(
    "zx, on_boundary, interior",
    [
        ((0, 0), True, False),
        ((40, 30), True, False),  # on the vertical edge Z = 40
        ((40, 60), True, False),  # the concave vertex
        ((47, 60), True, False),
        ((55, 100), True, False),
        ((20, 50), False, True),
        ((50, 80), False, True),
        ((50, 30), False, False),  # in the notch of the L
        ((56, 80), False, False),
        ((20, 101), False, False),
    ],
)
def test_polygon_boundary_and_interior(zx, on_boundary, interior):
    p = {"Z": F(zx[0]), "X": F(zx[1])}
    assert CHUCK.contains(p) is (on_boundary or interior)
    assert CHUCK.interior_contains(p) is interior
    # as a forbid zone, only the interior is forbidden
    assert AllowedSet((CHUCK,), tool_axis=None).contains(p) is (not interior)


def test_polygon_point_in_polygon_is_exact_near_a_slanted_edge():
    eps = F(1, 10**30)
    assert TRI.contains(P(X=5, Y=5))  # exactly on the hypotenuse
    assert not TRI.contains({"X": F(5), "Y": F(5) + eps})
    assert TRI.interior_contains({"X": F(5), "Y": F(5) - eps})
    assert not TRI.interior_contains(P(X=5, Y=5))


def test_polygon_margin():
    s = AllowedSet((CHUCK,), tool_axis=None)
    assert s.contains_box({"Z": F(50), "X": F(30)}, F(5))  # in the notch: box Z in [45, 55], X in [25, 35]
    assert s.contains_box({"Z": F(50), "X": F(55)}, F(5))  # touches the ledge X = 60 from below
    assert not s.contains_box({"Z": F(50), "X": F(55)}, F("5.001"))
    assert not s.contains_box({"Z": F(45), "X": F(30)}, F("5.001"))  # reaches into Z < 40
    # allow triangle: the largest box at (2, 2) has half-width 2 (touches the axes)
    t = AllowedSet((TRI,), tool_axis=None)
    assert t.contains_box(P(X=2, Y=2), F(2)) and not t.contains_box(P(X=2, Y=2), F("2.001"))
    # corner (4, 4) of the box around (3, 3) with d = 1 is inside (4 + 4 <= 10) ...
    assert t.contains_box(P(X=3, Y=3), F(1))
    # ... and the corner (6, 5) of the box around (5, 4) is outside
    assert not t.contains_box(P(X=5, Y=4), F(1))


@st.composite
def rectilinear_l(draw):
    """An integer L-shaped polygon [0,w]x[0,h] with the top-right [a,w]x[b,h] cut away."""
    w, h = draw(st.integers(2, 6)), draw(st.integers(2, 6))
    a, b = draw(st.integers(1, w - 1)), draw(st.integers(1, h - 1))
    v = ((0, 0), (w, 0), (w, b), (a, b), (a, h), (0, h))
    return PolygonZone("L", ("X", "Y"), tuple((F(x), F(y)) for x, y in v), forbid=draw(st.booleans()))


@FAST
@given(rectilinear_l(), st.integers(-2, 8), st.integers(-2, 8), st.integers(0, 2))
def test_polygon_margin_agrees_with_grid(zone, x, y, d):
    p, d = P(X=x, Y=y), F(d)
    step = F(1, 2)
    n = int(2 * d / step)
    pts = [{"X": p["X"] - d + i * step, "Y": p["Y"] - d + j * step} for i in range(n + 1) for j in range(n + 1)]
    if zone.forbid:
        brute = not any(zone.interior_contains(q) for q in pts)
    else:
        brute = all(zone.contains(q) for q in pts)
    assert AllowedSet((zone,), tool_axis=None).contains_box(p, d) == brute


# ------------------------------------------------------------------ stepped tables

GRINDER = SteppedZone(
    "wheel area", "X", "Y", F(0),
    (Region(F(200), F(120), F(300)), Region(F(380), F(220), F(300)), Region(F(1000), F(40), F(300))),
)


@pytest.mark.parametrize(
    "x, y, inside",
    [
        (0, 120, True),  # from is inclusive
        ("-0.001", 200, False),
        (200, 120, True),  # upto 200 belongs to region 1 (min 120)
        ("200.001", 120, False),  # region 2 needs Y >= 220
        ("200.001", 220, True),
        (380, 220, True),
        (380, 40, False),  # X = 380 is still region 2
        ("380.001", 40, True),
        (1000, 300, True),
        ("1000.001", 300, False),
    ],
)
def test_stepped_half_open_regions(x, y, inside):
    assert GRINDER.contains(P(X=x, Y=y)) is inside


def test_stepped_margin_across_a_step():
    s = AllowedSet((GRINDER,))
    # near the step at X = 380: Y >= 220 up to X = 380 inclusive, Y >= 40 beyond
    assert not s.contains_box(P(X=390, Y=100), F(10))  # box X in [380, 400]: X = 380 reads region 2
    assert s.contains_box(P(X="390.001", Y=100), F(10))  # box X in [380.001, 400.001]
    assert not s.contains_box(P(X="389.999", Y=100), F(10))
    assert s.contains_box(P(X=390, Y=230), F(10))  # high enough for both regions


# ------------------------------------------------------------------ tool tip

MILL = ROOT / "specs" / "machines" / "mill.toml"


def test_tip_zone_sees_machine_z_minus_tool_length():
    m = load_machine(MILL)
    s = m.allowed
    over_vise = P(X=120, Y=100, Z=200)
    assert s.contains(over_vise)  # no tool: the spindle nose at Z200 is above the vise
    assert not s.contains(over_vise, tool_length=F(120))  # tip at Z80: inside the vise
    assert s.contains(over_vise, tool_length=F(70))  # tip at Z130: on the vise top face
    assert not s.contains(over_vise, tool_length=F("70.001"))
    names = [z.name for z in s.violated_zones(over_vise, tool_length=F(120))]
    assert names == ["vise"]
    # the table (tip zone Z >= 50) and travel (machine Z >= 0) are different points
    beside = P(X=300, Y=300, Z=170)
    assert s.contains(beside, tool_length=F(120))  # tip at Z50: on the table
    assert [z.name for z in s.violated_zones(beside, tool_length=F("120.001"))] == ["table"]


def test_tip_zone_margin():
    vise = BoxZone("vise", (("X", F(100), F(140)), ("Z", None, F(130))), forbid=True, point=ZonePoint.TIP)
    s = AllowedSet((vise,), tool_axis="Z")
    p = P(X=120, Z=250)
    assert s.contains_box(p, F(20), tool_length=F(100))  # tip Z150, box down to 130: touches
    assert not s.contains_box(p, F("20.001"), tool_length=F(100))


# ------------------------------------------------------------------ the allowed set


def test_intersection_of_allow_zones_minus_forbid_interiors():
    a = BoxZone("a", (("X", F(0), F(10)),))
    b = BoxZone("b", (("X", F(5), F(20)),))
    hole = BoxZone("hole", (("X", F(7), F(8)),), forbid=True)
    s = AllowedSet((a, b, hole), tool_axis=None)
    got = [x for x in range(-1, 22) if s.contains({"X": F(x)})]
    assert got == [5, 6, 7, 8, 9, 10]
    assert not s.contains({"X": F("7.5")})
    assert s.bounding_box() == {"X": (F(5), F(10))}
    assert [z.name for z in s.violated_zones({"X": F(2)})] == ["b"]


def test_no_allow_zone_means_everywhere_except_forbid_interiors():
    hole = BoxZone("hole", (("X", F(7), F(8)),), forbid=True)
    s = AllowedSet((hole,), tool_axis=None)
    assert s.contains({"X": F(-10**6)}) and s.contains({"X": F(7)})
    assert not s.contains({"X": F("7.5")})
    assert s.bounding_box() == {}
    assert AllowedSet(()).contains({"X": F(1)})


def test_axes_a_zone_does_not_name_are_free():
    s = AllowedSet((BoxZone("x only", (("X", F(0), F(1)),)),), tool_axis=None)
    assert s.contains({"X": F(1), "Y": F(10**6), "Z": F(-(10**6))})
