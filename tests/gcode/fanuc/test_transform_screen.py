"""A second reading of the G68/G51 column lane (nczones/gcode/fanuc/transform_columns.py, review42).

* ``test_rotated_columns_are_the_general_paths`` — ``machine_points`` against ``transforms.rotate`` (the general
  path) on every point: angles with many decimals, the exact ones (0, 90, 180, 270, 360, 30, negative), near
  multiples of 90; centres, offsets, tiny and huge coordinates (up to the screen's ``2**50``), increments of
  0.001 mm, 0.0001 mm and 0.0001 in at scales 10**3..10**9; and points constructed (exact integers, searched
  with rationals) to lie a given distance from a rounding tie: on it, within 1e-12 increments either side of
  the tie guard (the general path's edge), and at the screen's own edge.  A row the general path decides must
  be its point, a row it finds uncertain must be cut (``bad``).
* ``test_the_screen_distance_is_sound_within_ulps`` — ``_nearest`` on doubles stepped by ``nextafter`` around
  ``k + 1/2 +- TIE_GUARD`` (constructed exactly): it accepts only a double truly farther than the guard.
* ``test_g91_runs_near_ties_are_the_general_paths`` — a G68 run in G91 (and G90, G20) whose points are
  constructed near ties (on one, either side of the guard): the fast path's segments, status and unknowns are
  the general path's alone (a point in doubt cuts the run; the general path says ``unknown`` there).
* ``test_scaled_columns_are_the_general_paths`` — the scaling path against ``transforms.scale`` near the
  ``int64`` limits of its products (a decline is allowed, a wrong or wrapped point is not).
* ``test_huge_numbers_decline_and_never_wrap`` — a centre or a work offset near the ``int64`` limit: the lane
  declines (the general path decides), where it raised ``OverflowError`` or wrapped a machine coordinate
  (a G54 X of 9223372036854775 mm rotated by 30 degrees came out at -9.2e15 mm).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.gcode.fanuc import transform_columns as tc
from nczones.gcode.fanuc.transforms import (
    TIE_GUARD,
    PointNotCertain,
    Rotation,
    Scaling,
    cos_sin_enclosure,
    rotate,
    scale,
)
from nczones.gcode.fastpath import MIN_RUN
from tests.sizes import examples

from .helpers import mill

_MILL = mill()
_BODY = [f"X{k % 50}.5 Y{k % 30}.25" for k in range(MIN_RUN + 8)]


def _program(pre: list[str], transform: str) -> str:
    return "\n".join(["%", "O1000", *pre, "G00 G17 G90 G21 G54 X0. Y0.", "G43 H1 Z25.", "G01 Z-1. F800.",
                      transform, "G01 X1. Y1.", *_BODY, "G69" if "G68" in transform else "G50", "G00 X0. Y0.",
                      "M30", "%"]) + "\n"


def _outcome(text: str, fast: bool) -> tuple:
    run = interpret_text(text, _MILL, fast=fast, file="xf.nc")
    return [(s.kind, s.start, s.end, s.centre) for s in run.segments()], run.status, \
        [(u.code, u.reason) for u in run.unsupported]


@pytest.mark.parametrize(("pre", "transform"), [
    ([], "G68 X9999999999999999. Y0 R30."),                      # a centre beyond int64 (scaled)
    ([], "G68 X-9223372036854775. Y0 R30."),                     # one at its edge
    (["G10 L2 P1 X9223372036854775."], "G68 X0 Y0 R30."),        # an offset the machine point wrapped past
    (["G10 L2 P1 X-9223372036854775."], "G68 X0 Y0 R30."),
    (["G10 L2 P1 X9223372036854775."], "G51 X0 Y0 Z-1. P2."),    # the machine start beyond int64
    ([], "G51 X9999999999999999. Y0 Z-1. P2."),
    ([], "G51 X9223372036854775. Y0 Z-1. P-2."),
])
def test_huge_numbers_decline_and_never_wrap(pre, transform):
    text = _program(pre, transform)
    assert _outcome(text, True) == _outcome(text, False)


# ---------------------------------------------------------------------------------------------- the rotation screen

_INCH_STEP = Fraction(254, 10**5)  # 0.0001 in, mm


@st.composite
def _angles(draw) -> Fraction:
    kind = draw(st.sampled_from(["exact", "near", "decimals"]))
    if kind == "exact":
        return Fraction(draw(st.sampled_from([0, 90, 180, 270, 360, -90, -180, 30, 150, -30, 210, 60, 45, 720])))
    if kind == "near":  # a multiple of 90 plus or minus 10**-d
        return Fraction(90 * draw(st.integers(-4, 4))) + draw(st.sampled_from([1, -1])) * Fraction(
            1, 10 ** draw(st.integers(3, 12)))
    return Fraction(draw(st.integers(-720 * 10**9, 720 * 10**9)), 10 ** draw(st.integers(0, 9)))


@st.composite
def _scale_and_step(draw) -> tuple[int, Fraction]:
    step = draw(st.sampled_from([Fraction(1, 1000), Fraction(1, 10**4), _INCH_STEP]))
    low = 5 if step == _INCH_STEP else (3 if step == Fraction(1, 1000) else 4)
    return draw(st.integers(low, 9)), step


def _tie_point(c: Fraction, s: Fraction, st_: int, d: Fraction, x0: int, span: int, other: int = 0) -> tuple[int, int]:
    """Integers ``(x, y)`` with ``(x c - y s) / st`` nearest ``j + 1/2 + d`` over ``x`` in ``x0 .. x0 + span``
    and ``y`` near ``other`` (solved and rounded; the roles swapped where ``|s| < |c|``), measured with the
    rationals ``c``, ``s`` (the enclosures' midpoints)."""
    best = None
    swap = abs(s) < abs(c)
    for x in range(x0, x0 + span):
        if swap:  # y the loop's, x solved: x = (t st + y s) / c
            y = x
            t = math.floor((other * c - y * s) / st_) + Fraction(1, 2) + d
            got = (round((t * st_ + y * s) / c), y)
        else:  # y = (x c - t st) / s
            t = math.floor((x * c - other * s) / st_) + Fraction(1, 2) + d
            got = (x, round((x * c - t * st_) / s))
        u = (got[0] * c - got[1] * s) / st_
        off = abs(abs(u - math.floor(u) - Fraction(1, 2)) - abs(d))
        if best is None or off < best[0]:
            best = (off, got)
    assert best is not None
    return best[1]


def _exact_rows(rot: Rotation, step: Fraction, off: tuple[Fraction, ...], P: np.ndarray, S: int) -> list:
    out = []
    for row in P.tolist():
        try:
            got = rotate(rot, [Fraction(v, 10**S) for v in row], step)
        except PointNotCertain:
            out.append(None)
            continue
        out.append([int((g + o) * 10**S) for g, o in zip(got, off)])
    return out


@settings(max_examples=examples(40, 600), deadline=None)
@given(_angles(), _scale_and_step(), st.integers(-10**6, 10**6), st.integers(-10**6, 10**6),
       st.integers(-10**6, 10**6), st.lists(st.tuples(st.integers(0, 49), st.integers(-2**49, 2**49),
                                                      st.integers(-2**49, 2**49)), min_size=1, max_size=12),
       st.lists(st.sampled_from(["tie", "guard-", "guard+", "screen", "near", "ulps"]), max_size=4), st.randoms())
def test_rotated_columns_are_the_general_paths(angle, scale_step, ca, cb, ox, raw, ties, rnd):
    S, step = scale_step
    st_ = int(step * 10**S)
    centre = (Fraction(ca, 1000), Fraction(cb, 1000))
    off = (Fraction(ox, 1000), Fraction(-ox, 250), Fraction(7, 2))
    rot = Rotation(0, 1, centre[0], centre[1], angle)
    C = [int(v * 10**S) for v in centre]
    rows = []
    for bits, x, y in raw:  # magnitudes from 1 to 2**49 (scaled), centred on the rotation's centre
        rows.append([C[0] + x % (2**bits) * (1 if x >= 0 else -1), C[1] + y % (2**bits) * (1 if y >= 0 else -1), 5])
    (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(angle)
    cm, sm = (c_lo + c_hi) / 2, (s_lo + s_hi) / 2
    for kind in ties:  # constructed distances from a tie (in increments) of the first coordinate
        reach = rnd.choice([10**9, 2**48])  # far out a double's ulp is a good part of an increment
        ulps = Fraction(reach, st_) * Fraction(rnd.randint(-16 * 2**10, 16 * 2**10), 2**62)  # +-16 ulps of q
        d = {"ulps": ulps, "tie": Fraction(0), "guard-": TIE_GUARD - Fraction(1, 10**12), "guard+": TIE_GUARD + Fraction(1, 10**12),
             "screen": TIE_GUARD + Fraction(2, 10**12), "near": Fraction(rnd.randint(-10**6, 10**6), 10**12)}[kind]
        d *= rnd.choice([1, -1])
        x, y = _tie_point(cm, sm, st_, d, rnd.randint(-reach, reach), 120, rnd.randint(-reach, reach) // 2)
        rows.append([C[0] + x, C[1] + y, 5])
    P = np.array(rows, dtype=np.int64)
    xf = tc.ColumnTransform(rot, None, step, off)
    got = tc.machine_points(xf, P, S)
    assert got is not None  # every magnitude is in the screen's range
    M, bad = got
    for r, want in enumerate(_exact_rows(rot, step, off, P, S)):
        if want is None:
            assert bad[r], (r, P[r])
        else:
            assert not bad[r] and M[r].tolist() == want, (r, P[r], M[r], want)


def test_the_constructed_points_reach_both_edges():
    """Not vacuous: at 27.5 degrees (0.001 mm at 10**9) the construction lands within 1e-9 increments of the
    distances asked for, the general path refuses the point inside the guard and decides the one outside, and the
    screen takes a point clear of the guard by 1e-9 but leaves one 1e-12 outside it to the exact path."""
    angle, S, step = Fraction(55, 2), 9, Fraction(1, 1000)
    st_ = int(step * 10**S)
    (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(angle)
    cm, sm = (c_lo + c_hi) / 2, (s_lo + s_hi) / 2
    rot = Rotation(0, 1, Fraction(0), Fraction(0), angle)
    c, s, delta = tc._doubles(angle)
    for d, certain, screened in ((TIE_GUARD - Fraction(1, 10**9), False, False),
                                 (TIE_GUARD + Fraction(3, 10**9), True, True),
                                 (-TIE_GUARD - Fraction(3, 10**9), True, True)):
        x, y = _tie_point(cm, sm, st_, d, 123_456_789, 2000)
        u = (x * cm - y * sm) / st_
        assert abs(abs(u - math.floor(u) - Fraction(1, 2)) - abs(d)) < Fraction(1, 10**9)
        P = np.array([[x, y, 0]], dtype=np.int64)
        _, ok = tc._nearest(np.array([(x * c - y * s) / st_]), np.array([(abs(x) + abs(y)) * ((delta + 2**-51) / st_)]))
        assert bool(ok[0]) == screened
        M, bad = tc.machine_points(tc.ColumnTransform(rot, None, step, (Fraction(0),) * 3), P, S)
        assert bool(bad[0]) == (not certain)


def test_far_out_the_doubles_cross_ties_and_the_screen_charges_it():
    """At ``|x| ~ 2**48`` increments (0.001 mm at 10**3) a double's ulp is 1/32 of an increment: constructed points
    within 1/256 increment of a tie whose computed ``q`` lies on the other side of it exist (term 2 is not
    academic), and the lane still gives the general path's point or cuts the row."""
    import random

    rnd, S, step, crossed = random.Random(42), 3, Fraction(1, 1000), 0
    for _ in range(60):
        angle = Fraction(rnd.randint(1, 3599999), 10000)
        (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(angle)
        cm, sm = (c_lo + c_hi) / 2, (s_lo + s_hi) / 2
        c, s, _delta = tc._doubles(angle)
        x, y = _tie_point(cm, sm, 1, Fraction(rnd.randint(-2**10, 2**10), 2**18), rnd.randint(-2**48, 2**48), 40,
                          rnd.randint(-2**47, 2**47))
        u, q = x * cm - y * sm, Fraction(float(x) * c - float(y) * s)
        tie = math.floor(u) + Fraction(1, 2)
        crossed += (u - tie) * (q - tie) < 0 or q == tie
        rot = Rotation(0, 1, Fraction(0), Fraction(0), angle)
        _mapped_or_declined(tc.ColumnTransform(rot, None, step, (Fraction(0),) * 3),
                            np.array([[x, y, 0]], dtype=np.int64), S, lambda p, rot=rot: rotate(rot, p, step))
    assert crossed >= 3


@pytest.mark.parametrize("k", [0, 1, -1, 7, -8, 12345, -2**40, 2**45])
@pytest.mark.parametrize("side", [1, -1])
def test_the_screen_distance_is_sound_within_ulps(k, side):
    tie = Fraction(k) + Fraction(1, 2)
    for base in (TIE_GUARD, TIE_GUARD + Fraction(1, 10**12), tc._GUARD, 0):
        u = float(tie + side * Fraction(base))
        for _ in range(40):
            _, ok = tc._nearest(np.array([u]), np.array([0.0]))
            exact = Fraction(u)
            if ok[0]:  # accepted: truly farther than the guard from the tie, and the nearest integer
                assert abs(exact - tie) > TIE_GUARD
                assert int(_[0]) == round(exact)
            u = math.nextafter(u, math.inf if side > 0 else -math.inf)


# ------------------------------------------------------------------------------------------------ int64's limits

_EDGES = [2**62, -2**62, 2**63 - 1, -2**63, 2**60, -2**60, 2**59 + 12345, 2**49, -2**49 - 1, 2**50, 0, 7]


def _mapped_or_declined(xf: tc.ColumnTransform, P: np.ndarray, S: int, exact) -> None:
    got = tc.machine_points(xf, P, S)
    if got is None:
        return  # declined: the general path decides
    M, bad = got
    for r, row in enumerate(P.tolist()):
        try:
            want = exact([Fraction(v, 10**S) for v in row])
        except PointNotCertain:
            assert bad[r]
            continue
        assert not bad[r] and M[r].tolist() == [(w + o) * 10**S for w, o in zip(want, xf.off)], (row, M[r])


@pytest.mark.parametrize("p", _EDGES)
@pytest.mark.parametrize("c", [-2**62, -2**61, 2**61 + 1, 2**62, 10**19, 0, -5])
@pytest.mark.parametrize("o", [0, 2**61, -2**62, 10**20])
def test_the_limits_decline_or_map_exactly(p, c, o):
    """A program coordinate, a centre and an offset (scaled, 10**3) anywhere near or beyond ``int64``'s range: the
    lane declines or maps exactly (a wrapped difference once passed the ``2**50`` check as ``-2**63``)."""
    S, step = 3, Fraction(1, 1000)
    P = np.array([[p, -p if p != -2**63 else p, 1]], dtype=np.int64)
    off = (Fraction(o, 1000), Fraction(0), Fraction(0))
    rot = Rotation(0, 1, Fraction(c, 1000), Fraction(-c, 1000), Fraction(30))
    _mapped_or_declined(tc.ColumnTransform(rot, None, step, off), P, S, lambda q: rotate(rot, q, step))
    for f in (Fraction(2), Fraction(-10**9, 7), Fraction(1, 3)):
        sc = Scaling((Fraction(c, 1000), Fraction(-c, 1000), Fraction(0)), (f, f, Fraction(1)))
        _mapped_or_declined(tc.ColumnTransform(None, sc, step, off), P, S, lambda q, sc=sc: scale(sc, q, step))


#: Denominators of convergents of sqrt(3): ``q sqrt 3`` within ``1 / (2 sqrt 3 q)`` of an integer, so at an angle
#: of sine +-1/2 the point ``(q, y)`` lies that close (halved) to a tie for the right ``y``; 0 an exact tie
_SQRT3_Q = [0, 1, 4, 15, 56, 209, 780, 2911, 10864, 40545, 151316, 564719, 2107560, 7865521]


@settings(max_examples=examples(4, 60), deadline=None)
@given(st.sampled_from([Fraction(30), Fraction(150), Fraction(210), Fraction(-30)]), st.booleans(), st.booleans(),
       st.randoms(use_true_random=False))
def test_g91_runs_near_ties_are_the_general_paths(angle, g91, inch, rnd):
    text = _near_tie_run(angle, g91, inch, rnd)
    assert _outcome(text, True) == _outcome(text, False)


def test_the_near_tie_runs_take_the_lane_and_meet_ties():
    """Not vacuous: such a run goes through the lane and its points on a tie are the general path's unknowns."""
    import random

    text = _near_tie_run(Fraction(30), True, False, random.Random(5))
    run = interpret_text(text, _MILL, fast=True, file="xf.nc")
    list(run.segments())  # (the counts fill as the segments stream)
    assert run.counts["fast_lines"] >= 35 and run.status == "unknown"
    assert {u.code for u in run.unsupported} == {"G68"}


def _near_tie_run(angle: Fraction, g91: bool, inch: bool, rnd) -> str:
    """A G68 run about the origin (an angle of sine +-1/2) whose points after the 40th line lie on or near a tie
    of the rotated X (``_SQRT3_Q``: from 0 to about 4e-8 increments away, inside and outside the guard), the
    others anywhere; whole increments of 0.001 mm or 0.0001 in."""
    digits = 4 if inch else 3
    (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(angle)
    cm, sm = (c_lo + c_hi) / 2, (s_lo + s_hi) / 2
    body, prev = [], (0, 0)
    for k in range(MIN_RUN + 8):
        if k >= 40 and k % 2 == 0:
            x = rnd.choice(_SQRT3_Q) * rnd.choice([1, -1])
            y = round((x * cm - math.floor(x * cm) - Fraction(1, 2)) / sm)  # x c - y s nearest the tie above x c
        else:
            x, y = rnd.randint(-10**7, 10**7), rnd.randint(-10**7, 10**7)
        wx, wy = (x - prev[0], y - prev[1]) if g91 else (x, y)
        body.append(f"G01 X{wx / 10**digits:.{digits}f} Y{wy / 10**digits:.{digits}f}")
        prev = (x, y)
    head = ["%", "O1000", f"G00 G17 G90 {'G20' if inch else 'G21'} G54 X0. Y0.", "G43 H1 Z1.", "G01 Z-0.1 F30.",
            f"G68 X0. Y0. R{int(angle)}.", "G01 X0. Y0."]
    return "\n".join([*head, *(["G91"] if g91 else []), *body, "G90", "G69", "G00 X0. Y0.", "M30", "%"]) + "\n"


# ----------------------------------------------------------------------------------------------- the scaling path

@settings(max_examples=examples(30, 400), deadline=None)
@given(st.integers(0, 9), st.sampled_from([Fraction(1, 2), Fraction(-3, 2), Fraction(2), Fraction(1, 3),
                                           Fraction(-7, 1000), Fraction(12345, 1000), Fraction(10**9, 7)]),
       st.integers(-2**62, 2**62), st.lists(st.integers(-2**62, 2**62), min_size=1, max_size=6),
       st.integers(-2**61, 2**61))
def test_scaled_columns_are_the_general_paths(bits, f, c, ps, o):
    S, step = 3, Fraction(1, 1000)
    c, o = c >> bits * 6, o >> bits * 6  # magnitudes from 2**62 down to 1
    P = np.array([[p >> bits * 6, 0] for p in ps], dtype=np.int64)
    sc = Scaling((Fraction(c, 1000), Fraction(0)), (f, Fraction(1)))
    got = tc.machine_points(tc.ColumnTransform(None, sc, step, (Fraction(o, 1000), Fraction(0))), P, S)
    if got is None:
        return  # declined: the general path decides
    M, bad = got
    assert not bad.any()
    for r, row in enumerate(P.tolist()):
        want = scale(sc, [Fraction(v, 1000) for v in row], step)
        assert M[r, 0] == (want[0] + Fraction(o, 1000)) * 1000 and M[r, 1] == row[1], (row, M[r])
