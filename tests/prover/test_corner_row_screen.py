"""The corners' row screen (``CornerCheck._rows_proved`` in ``nczones/prover/blend.py``) proves only what fits.

A column chunk's corners are screened one row each by the motions' screen (``prover.screen.ZONE_ROWS``: boxes,
stepped tables, polygons' grids) before the union tests and the exact path; a corner 2.5 mm inside a 200-vertex
outline otherwise took an exact polygon test each (issue 36's polygon row: 2,102 of them at 100,000 lines).

* Soundness, directly: every row the screen passes has an exact box (its integers over ``2 * 10**scale``) that
  :func:`nczones.prover.exact.box_fits` shows fits, with the margin and the row's tool length, for boxes drawn at
  and across the faces of every zone kind, allowed and forbidden, tip zones included; a row whose box was not
  computed or whose two motions differ in tool length is never passed.
* The same corners end to end: column chunks next to a forbidden polygon or a stepped table give the same
  reasons and corner count as the same motions one at a time (the exact path), as
  ``tests/prover/test_blend_screens.py`` does for boxes.
* Teeth: a screen that forgets the margin, or rounds the boxes inwards, is caught by the first test.
"""

from __future__ import annotations

import random
from fractions import Fraction
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import blend
from nczones.prover.exact import box_fits
from tests.machines import box_zone, machine_text
from tests.prover.test_blend_screens import N_MOTIONS, _agree, _program


def _polygon(name: str, verts: list[tuple[int, int]], *, forbid: bool, tip: bool = False) -> str:
    pts = ", ".join(f'["{x}", "{y}"]' for x, y in verts)
    return (f'[[zones]]\nname = "{name}"\nkind = "polygon"\nplane = ["X", "Y"]\nvertices = [{pts}]\n'
            + ("forbid = true\n" if forbid else "") + ('point = "tip"\nmin = { Z = "-20" }\n' if tip else ""))


def _table(name: str, *, forbid: bool) -> str:
    rows = ", ".join(f'{{upto = "{u}", min = "{lo}", max = "{hi}"}}' for u, lo, hi in
                     ((-10, -30, 30), (0, -20, 25), (5, -5, 5), (20, -25, 28), (50, -40, 40)))
    return (f'[[zones]]\nname = "{name}"\nkind = "stepped"\nreference_axis = "X"\nlimited_axis = "Y"\n'
            f'from = "-50"\nregions = [{rows}]\n' + ("forbid = true\n" if forbid else ""))


STAR = [(0, 0), (12, -3), (20, 0), (14, 6), (20, 14), (8, 10), (0, 18), (3, 8)]
TABLE = box_zone("table", {"X": "-60", "Y": "-60", "Z": "-50"}, {"X": "60", "Y": "60", "Z": "50"})
#: machines with every zone kind the screen reads, allowed and forbidden, and a tip zone (tool length moves it)
MACHINES = {
    "forbidden polygon": TABLE + _polygon("star", STAR, forbid=True),
    "allowed polygon": _polygon("star", STAR, forbid=False),
    "tip polygon": TABLE + _polygon("star", STAR, forbid=True, tip=True),
    "forbidden table": TABLE + _table("steps", forbid=True),
    "allowed table": _table("steps", forbid=False),
    "forbidden box": TABLE + box_zone("clamp", {"X": "3", "Y": "-2"}, {"X": "9.5", "Y": "4.25"}, forbid=True),
}
#: a start inside each machine's allowed set
START = {"allowed polygon": ("10", "5"), "allowed table": ("-20", "0"), "forbidden table": ("-55", "0")}
_PARSED = {k: parse_machine(machine_text("xyz_corner_screens", extra=v, set={
    "machine.reference.X": START.get(k, ("-30",))[0], "machine.reference.Y": START.get(k, ("-30", "-30"))[1]}))
    for k, v in MACHINES.items()}
#: the coordinates boxes are drawn near (mm): the zones' faces and vertices, and points between them
NEAR = sorted({c for x, y in STAR for c in (x, y)} | {-50, -40, -30, -25, -20, -10, -5, 0, 3, 4.25, 5, 9.5, 20, 25,
                                                      28, 30, 40, 50, 60, -60})


F0 = Fraction(0)
#: every zone's constants by axis (faces, vertices, region bounds), for :func:`_violating_point`
CONSTANTS = {"X": [Fraction(c) for c in NEAR] + [Fraction(-50)], "Y": [Fraction(c) for c in NEAR],
             "Z": [Fraction(c) for c in (-70, -50, -20, 50, 70)]}


def _rows(rnd: random.Random, n: int, scale: int) -> tuple:
    """``n`` corner boxes in integers over ``2 * 10**scale`` near :data:`NEAR`, with their tool lengths."""
    s2 = 2 * 10**scale
    lo = np.zeros((n, 3), dtype=np.int64)
    hi = np.zeros((n, 3), dtype=np.int64)
    for k in range(n):
        for a in range(3):
            c = int(Fraction(rnd.choice(NEAR) if a < 2 else rnd.choice([-15, 0, 10])) * s2)
            w = rnd.choice([0, 1, 2, s2 // 100 + 1, s2 // 2, s2, 3 * s2])
            x = c + rnd.randint(-w, w) + rnd.choice([-1, 0, 1])
            lo[k, a], hi[k, a] = x, x + rnd.choice([0, 1, rnd.randint(0, 4 * s2)])
    tl_a = np.array([rnd.choice([0, 0, 5 * 10**scale, 50 * 10**scale]) for _ in range(n)], dtype=np.int64)
    tl_b = np.where(np.array([rnd.random() < 0.15 for _ in range(n)]), tl_a + 10**scale, tl_a)
    boxed = np.array([rnd.random() > 0.1 for _ in range(n)], dtype=bool)
    return lo, hi, tl_a, tl_b, boxed


def _check(name: str, margin: Fraction) -> blend.CornerCheck:
    return blend.CornerCheck(_PARSED[name], margin, (), [])


def _unsound_rows(check: blend.CornerCheck, scale: int, rows: tuple) -> list[int]:
    """The rows the screen passes whose exact box does not fit (or that it may not pass at all)."""
    lo, hi, tl_a, tl_b, boxed = rows
    chunk = SimpleNamespace(axes=("X", "Y", "Z"), scale=scale)
    proved = check._rows_proved(chunk, lo, hi, boxed, tl_a, tl_b)
    assert proved is not None
    s2 = 2 * 10**scale
    bad = []
    for k in np.flatnonzero(proved).tolist():
        if not boxed[k] or tl_a[k] != tl_b[k]:
            bad.append(k)
            continue
        box_lo = {a: Fraction(int(lo[k, i]), s2) for i, a in enumerate("XYZ")}
        box_hi = {a: Fraction(int(hi[k, i]), s2) for i, a in enumerate("XYZ")}
        tl = Fraction(int(tl_a[k]), 10**scale)
        if not box_fits(check.allowed, box_lo, box_hi, check.margin, tl) and _violating_point(check, box_lo, box_hi, tl):
            bad.append(k)
    return bad


def _violating_point(check: blend.CornerCheck, lo: dict, hi: dict, tl: Fraction) -> dict | None:
    """A point of the box ``[lo, hi]`` whose margin box the zones' own model (``AllowedSet.violated_zones``, not
    the prover's code) finds violating: the box's corners, middle and every zone constant inside it (minus and
    plus the margin), on every axis.  (The exact box test is the first oracle; it is conservative in places --
    a stepped table's reference range before its ``from`` -- where this one decides.)"""
    import itertools

    d = check.margin
    values = {}
    for a in "XYZ":
        inner = {c + e for c in CONSTANTS[a] for e in (-d, F0, d) if lo[a] <= c + e <= hi[a]}
        values[a] = sorted({lo[a], hi[a], (lo[a] + hi[a]) / 2} | inner)
    for x, y, z in itertools.product(values["X"], values["Y"], values["Z"]):
        p = {"X": x, "Y": y, "Z": z}
        if check.allowed.violated_zones(p, tl, d):
            return p
    return None


MARGINS = [Fraction(0), Fraction(1, 1000), Fraction(1, 2), Fraction(1, 3)]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**32 - 1), name=st.sampled_from(sorted(MACHINES)), margin=st.sampled_from(MARGINS),
       scale=st.sampled_from([0, 1, 3, 6]))
def test_a_row_the_screen_passes_fits_exactly(seed, name, margin, scale):
    rows = _rows(random.Random(seed), 120, scale)
    assert _unsound_rows(_check(name, margin), scale, rows) == []


def test_the_screen_proves_most_rows_far_from_the_faces():
    """Not vacuous: boxes well inside the allowed set are passed (the first test then checks real proofs)."""
    check = _check("forbidden polygon", Fraction(1, 1000))
    lo = np.array([[-80000, -80000, 0], [60000, 40000, 0], [30000, 30000, 0]], dtype=np.int64)  # over 2000
    hi = lo + 1000
    z = np.zeros(3, dtype=np.int64)
    proved = check._rows_proved(SimpleNamespace(axes=("X", "Y", "Z"), scale=3), lo, hi, np.ones(3, bool), z, z)
    assert proved.tolist() == [True, True, True]
    # the star's inside (X10 Y5) is forbidden: not passed
    lo2 = np.array([[20000, 10000, 0]], dtype=np.int64)
    proved = check._rows_proved(SimpleNamespace(axes=("X", "Y", "Z"), scale=3), lo2, lo2 + 10, np.ones(1, bool),
                                z[:1], z[:1])
    assert proved.tolist() == [False]


@pytest.mark.parametrize("mutant", ["no margin", "rounded inwards"])
def test_a_wrong_screen_is_caught(mutant, monkeypatch):
    """The first test's check finds a wrong screen: the margin forgotten, or the halves rounded inwards."""
    real = blend.CornerCheck._rows_proved

    def wrong(self, chunk, c_lo, c_hi, boxed, tl_a, tl_b):
        if mutant == "no margin":
            self.margin, margin = Fraction(0), self.margin
            try:
                return real(self, chunk, c_lo, c_hi, boxed, tl_a, tl_b)
            finally:
                self.margin = margin
        return real(self, chunk, c_lo + 1, c_hi - 1, boxed, tl_a, tl_b)  # then halved: inwards by a half unit

    monkeypatch.setattr(blend.CornerCheck, "_rows_proved", wrong)
    found = 0
    for seed in range(40):
        for name in sorted(MACHINES):
            check = _check(name, Fraction(1, 2) if mutant == "no margin" else Fraction(0))
            found += bool(_unsound_rows(check, 0, _rows(random.Random(seed), 120, 0)))
    assert found


def _star_clamp_machine(x0: int, y0: int, size: int) -> object:
    """The walk's table with a forbidden star of ``size`` thousandths a side, its box's low corner at (x0, y0)
    (thousandths)."""
    k = Fraction(size, 20_000)
    verts = [(Fraction(x0, 1000) + k * x, Fraction(y0, 1000) + k * (y + 3)) for x, y in STAR]
    pts = ", ".join(f'["{x}", "{y}"]' for x, y in ((float(x), float(y)) for x, y in verts))
    zone = f'[[zones]]\nname = "clamp"\nkind = "polygon"\nplane = ["X", "Y"]\nvertices = [{pts}]\nforbid = true\n'
    return parse_machine(machine_text("xyz_corner_screens", extra=TABLE + zone))


def _agree_if_checked(program: str, m: object, monkeypatch) -> None:
    """``_agree`` of test_blend_screens, when the corner check was built at all (a walk that meets the clamp in
    its first motions stops before any corner is checked: nothing to compare)."""
    try:
        _agree(program, m, monkeypatch, rows=None)
    except KeyError as e:
        assume(e.args != ("args",))
        raise


AGREE = settings(max_examples=6, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate],
                 suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])


@AGREE
@given(seed=st.integers(0, 2**32 - 1), mode=st.sampled_from(["G64", "G64 P0.5"]), at=st.integers(1, N_MOTIONS),
       face=st.sampled_from([0, 1, 500, 1500]), size=st.sampled_from([300, 2000, 6000]), side=st.integers(0, 3))
def test_corners_by_a_polygon_agree_with_the_one_motion_path(seed, mode, at, face, size, side, monkeypatch):
    """A forbidden star ``face`` thousandths beside a point of the walk (``side``: right, left, above, below): the
    column chunks (the row screen, the union tests, the exact path) and the same motions one at a time give the
    same reasons and corner count."""
    program, pts = _program(seed, mode, 0.0, arcs=0.0)
    px, py = pts[at]
    x0, y0 = [(px + face, py - size // 2), (px - face - size, py - size // 2), (px - size // 2, py + face),
              (px - size // 2, py - face - size)][side]
    assume(not (x0 - 1000 <= 0 <= x0 + size + 1000 and y0 - 1000 <= 0 <= y0 + size + 1000))  # X0 Y0: the start
    _agree_if_checked(program, _star_clamp_machine(x0, y0, size), monkeypatch)


@pytest.mark.parametrize("forbid", [True, False])
def test_corners_by_a_stepped_table_agree_with_the_one_motion_path(forbid, monkeypatch):
    """A table whose faces are within a few mm of the walk's edge (Y 40): forbidden teeth above it, or an allowed
    table just around it."""
    program, _pts = _program(11, "G64", 0.0, arcs=0.0)
    rows = ", ".join(f'{{upto = "{-50 + 5 * (i + 1)}", min = "{-41 - i % 3 if not forbid else 40.001 + i % 4}", '
                     f'max = "{41 + i % 4 if not forbid else 50}"}}' for i in range(20))
    steps = (f'[[zones]]\nname = "steps"\nkind = "stepped"\nreference_axis = "X"\nlimited_axis = "Y"\n'
             f'from = "-50"\nregions = [{rows}]\n' + ("forbid = true\n" if forbid else ""))
    extra = (TABLE if forbid else "") + steps
    m = parse_machine(machine_text("xyz_corner_screens", extra=extra))
    result, (reasons, corners) = _agree(program, m, monkeypatch, rows=None)
    assert reasons or result.verdict.label == "safe"


def test_the_row_screen_takes_the_corners_far_from_a_polygon(monkeypatch):
    """The walk 5 mm inside an allowed 40-gon whose box it leaves: the row screen proves every corner the chunk's one box does not;
    no union test and no exact corner is left."""
    import nczones.pipeline.verification as verification
    from nczones.prover import verify_text

    calls = {"fits": 0, "corner": 0}
    fits, corner = blend.CornerCheck._fits, blend.CornerCheck._corner

    def count_fits(self, *a, **k):
        calls["fits"] += 1
        return fits(self, *a, **k)

    def count_corner(self, *a, **k):
        calls["corner"] += 1
        return corner(self, *a, **k)

    monkeypatch.setattr(blend.CornerCheck, "_fits", count_fits)
    monkeypatch.setattr(blend.CornerCheck, "_corner", count_corner)
    monkeypatch.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
    circle = [(round(55.6 * np.cos(2 * np.pi * k / 40), 3), round(55.6 * np.sin(2 * np.pi * k / 40), 3))
              for k in range(40)]
    zone = ('[[zones]]\nname = "outline"\nkind = "polygon"\nplane = ["X", "Y"]\nvertices = ['
            + ", ".join(f'["{x}", "{y}"]' for x, y in circle) + ']\nmin = { Z = "-50" }\nmax = { Z = "50" }\n')
    m = parse_machine(machine_text("xyz_corner_screens", extra=zone))
    program, _pts = _program(5, "G64", 0.0, arcs=0.0)  # within 50.6 mm of X0 Y0; its box is not (40, 40)
    assert verify_text(program, m).verdict.label == "safe"
    # the walk's box (-40..40) passes the 40-gon (radius 55.6) at its corners: the chunk's one box does not fit (one test a
    # chunk); each corner is then the row screen's, none a union test or an exact corner
    assert calls["corner"] <= 2 and calls["fits"] <= 4, calls


@given(x=st.fractions(), scale=st.integers(0, 12), up=st.booleans())
def test_scaled_is_the_rounded_product(x, scale, up):
    """``screen._scaled`` (the zones' limits at a chunk's scale, in integers) is the ceiling or floor of
    ``x * 10**scale`` within the screen's bounds."""
    import math

    from nczones.prover import screen

    v = x * 10**scale
    want = max(min(math.ceil(v) if up else math.floor(v), screen._POS), screen._NEG)
    assert screen._scaled(x, scale, up, 0) == want
