"""NURBS/spline motion: exact math, prover soundness against an exact sampler, controller deviation."""

from __future__ import annotations

from fractions import Fraction as F
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller.spline import FLATNESS, spline_chord_points, spline_positions
from nczones.geometry.nurbs import Nurbs, clamped_uniform_knots
from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind, SplineCurve
from nczones.prover.core import Prover, verify_segments
from nczones.prover.result import Verdict
from tests.machines import machine_text

ROOT = Path(__file__).resolve().parents[4]

coord = st.integers(-40, 40).map(lambda v: F(v, 4))
weight = st.integers(1, 6).map(lambda v: F(v, 2))


@st.composite
def curves(draw, dim=2):
    degree = draw(st.integers(1, 3))
    n = draw(st.integers(degree + 1, degree + 4))
    pts = tuple(tuple(draw(coord) for _ in range(dim)) for _ in range(n))
    ws = tuple(draw(weight) for _ in range(n))
    inner = sorted(draw(st.lists(st.integers(1, 9), min_size=n - degree - 1, max_size=n - degree - 1)))
    knots = (F(0),) * (degree + 1) + tuple(F(k, 10) for k in inner) + (F(1),) * (degree + 1)
    try:
        return Nurbs(degree, knots, pts, ws)
    except ValueError:
        return Nurbs(degree, clamped_uniform_knots(n, degree + 1), pts, ws)


params = st.integers(0, 64).map(lambda v: F(v, 64))


@settings(max_examples=40, deadline=None, derandomize=True)
@given(curves(), params, params)
def test_knot_insertion_preserves_the_curve(c, s, t):
    lo, hi = c.domain
    s, t = lo + (hi - lo) * s, lo + (hi - lo) * t
    if lo < t < hi:
        assert c.insert(t).point(s) == c.point(s)
        a, b = c.split(t)
        assert (a if s <= t else b).point(s) == c.point(s)


@settings(max_examples=40, deadline=None, derandomize=True)
@given(curves(), params)
def test_span_hull_contains_the_curve_point(c, s):
    lo, hi = c.domain
    t = lo + (hi - lo) * s
    p = c.point(t)
    boxes = [pts for (a, b), pts in c.span_hulls() if a <= t <= b]
    assert any(all(min(q[k] for q in pts) <= p[k] <= max(q[k] for q in pts) for k in range(len(p))) for pts in boxes)


def test_clamped_ends_and_invalid_curves():
    c = Nurbs(2, (F(0),) * 3 + (F(1),) * 3, ((F(1), F(0)), (F(1), F(1)), (F(0), F(1))), (F(1), F(1), F(2)))
    assert c.point(F(0)) == (F(1), F(0)) and c.point(F(1)) == (F(0), F(1))
    with pytest.raises(ValueError):  # interior knot of multiplicity degree + 1: a jump
        Nurbs(1, (F(0), F(0), F(1, 2), F(1, 2), F(1), F(1)), ((F(0),), (F(1),), (F(2),), (F(3),)), (F(1),) * 4)
    with pytest.raises(ValueError):  # not clamped
        Nurbs(2, (F(0), F(1), F(2), F(3), F(4), F(5)), ((F(0),), (F(1),), (F(2),)), (F(1),) * 3)


MACHINE = parse_machine(machine_text("xy_table_post"))


def spline_segment(c: Nurbs) -> Segment:
    extra = (SplineCurve(c.degree, c.knots, c.points, c.weights, "G5.2"),)
    return Segment(SegmentKind.SPLINE, c.points[0], c.points[-1], ("X", "Y"), block=0, plane=Plane.XY,
                   feed_mm_min=F(100), extra=extra)


@settings(max_examples=25, deadline=None, derandomize=True)
@given(curves())
def test_prover_never_safe_when_an_exact_curve_point_is_outside(c):
    seg = spline_segment(c)
    r = verify_segments([seg], MACHINE)
    lo, hi = c.domain
    outside = [s for s in (lo + (hi - lo) * F(i, 200) for i in range(201))
               if MACHINE.allowed.violated_zones(dict(zip(("X", "Y"), c.point(s))))]
    if outside:
        assert r.verdict is not Verdict.SAFE
    if r.verdict is Verdict.UNSAFE:
        v = r.violations[0]
        assert MACHINE.allowed.violated_zones(dict(v.point))
        assert MACHINE.allowed.violated_zones(dict(v.path_point))  # the witness is a point of the curve


@settings(max_examples=25, deadline=None, derandomize=True)
@given(curves())
def test_screened_spline_agrees_with_the_solver_path(c):
    # the screens (the box of all control points, then each knot span's local hull) against the solver
    # path (a hull query per knot span); both are sound, so where both decide they agree
    seg = spline_segment(c)
    screened = verify_segments([seg], MACHINE)
    solver = verify_segments([seg], MACHINE, engine="z3")
    if Verdict.UNKNOWN not in (screened.verdict, solver.verdict):
        assert screened.verdict == solver.verdict


def test_prover_proves_a_curve_that_stays_inside():
    c = Nurbs(2, clamped_uniform_knots(5, 3), ((F(0), F(0)), (F(0), F(1)), (F(2), F(2)), (F(2), F(0)), (F(0), F(0))),
              (F(1), F(1), F(1), F(1), F(2)))
    assert verify_segments([spline_segment(c)], MACHINE).verdict is Verdict.SAFE


def test_unknown_segment_kinds_are_unknown_never_safe():
    class Fake:
        name = "NEW_KIND"

    seg = Segment(SegmentKind.LINE, (F(0), F(0)), (F(1), F(0)), ("X", "Y"))
    object.__setattr__(seg, "kind", Fake())
    out = Prover(MACHINE).check(seg)
    assert out.violation is None and out.reason is not None and "not handled" in out.reason.message


@settings(max_examples=15, deadline=None, derandomize=True)
@given(curves())
def test_controller_stays_within_one_and_a_quarter_pulses_of_the_curve(c):
    pulse = (F(1, 100), F(1, 100))
    seg = spline_segment(c)
    p0 = tuple(round(v / u) for v, u in zip(c.points[0], pulse))
    pos = spline_positions(seg, pulse, p0)
    chords = spline_chord_points(seg, pulse)
    assert chords[0] == c.points[0] and chords[-1] == c.points[-1]
    # every chord is within FLATNESS pulses of the curve between its ends (checked at exact curve points)
    end = tuple(round(v / u) for v, u in zip(c.points[-1], pulse))
    assert (len(pos) == 0 and end == p0) or tuple(int(v) for v in pos[-1]) == end
    # each commanded position is within 1 + FLATNESS pulses of some chord point, per axis
    import numpy as np

    pts = np.array([[float(v / u) for v, u in zip(p, pulse)] for p in chords])
    for q in pos[:: max(1, len(pos) // 50)]:
        best = min(_dist_to_chord(q, a, b) for a, b in zip(pts, pts[1:]))
        assert best <= 1 + float(FLATNESS) + 1e-9


def _dist_to_chord(q, a, b) -> float:
    """An upper bound of the per-axis (L-infinity) distance from q to the segment ab (at the projection)."""
    import numpy as np

    d = b - a
    dd = float(d @ d)
    t = 0.0 if dd == 0 else min(1.0, max(0.0, float((q - a) @ d) / dd))
    return float(np.max(np.abs(q - (a + t * d))))


def test_reports_say_splines_were_proved_on_the_programmed_curve():
    from nczones import load_machine
    from nczones.prover import verify_text

    program = "G21 G90 G17 F100\nG0 X10 Y10 Z10\nG5.2 X10 Y10 P1 L3\nX20 Y30 P1\nX40 Y10 P1\nG5.3\nM2\n"
    result = verify_text(program, load_machine(ROOT / "specs" / "machines" / "mill.toml"))
    assert any("exact programmed curve" in n for n in result.notes)
    plain = verify_text("G21 G90\nG0 X10 Y10 Z10\nM2\n", load_machine(ROOT / "specs" / "machines" / "mill.toml"))
    assert not any("spline" in n for n in plain.notes)


def test_the_shared_curve_of_a_spline_segment_is_the_rational_one():
    """The curve both witnesses read (nurbs.spline_curve) against a point worked out by hand.

    Degree 2, control points (0,0), (1,1), (2,0), weights 1, 2, 1: at the middle parameter the basis is
    1/4, 1/2, 1/4, the weighted basis 1/4, 1, 1/4 (sum 3/2), so the point is (3/2, 1) / (3/2) = (1, 2/3); a
    curve that dropped its weights would give (1, 1/2).  The prover and the controller cannot catch such
    a bug by comparing each other, since both take their curve from this one function.
    """
    from nczones.geometry.nurbs import spline_curve

    c = Nurbs(2, (F(0),) * 3 + (F(1),) * 3, ((F(0), F(0)), (F(1), F(1)), (F(2), F(0))), (F(1), F(2), F(1)))
    assert spline_curve(spline_segment(c)).point(F(1, 2)) == (F(1), F(2, 3))
