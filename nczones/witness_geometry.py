"""Whether a counterexample's point lies on a re-interpreted motion and in its zone: ``nczones replay``'s geometry.

:mod:`nczones.replay` checks a report's counterexamples with it, and
:mod:`nczones.pipeline.witnesses` a ranged result's witnesses before they are
reported (:func:`motion_witness_replays`).  Nothing here runs the prover: a
point on a line, a dogleg rapid, a circular arc or a NURBS curve is decided in
exact rational arithmetic; an irrational path point (a helix, an R-format arc
with an irrational centre, a developed arc, a polar move) within
:data:`IRRATIONAL_TOLERANCE_MM` of the motion, sampled in floats.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from fractions import Fraction

from .exact import format_decimal, to_float
from .machine import Machine, RapidMode
from .motion import Segment, SegmentKind, arc_path_float, tip_offset
from .zones import tip_shifted

__all__ = ["IRRATIONAL_TOLERANCE_MM", "REPLAYED_KINDS", "in_zone", "motion_witness_replays", "off_motion", "on_arc",
           "on_dogleg", "on_line", "on_motion", "show_point"]

#: How close an irrational path point must be to the motion (mm; degrees on a rotary axis).
IRRATIONAL_TOLERANCE_MM = 1e-6

F0, F1 = Fraction(0), Fraction(1)
Point = tuple[Fraction, ...]

# --------------------------------------------------------------------------- exact geometry


def on_line(p: Point, a: Point, b: Point) -> Fraction | None:
    """The ``t`` in [0, 1] with ``p = a + t (b - a)``, or None (exact).

    >>> F = Fraction
    >>> on_line((F(1), F(2)), (F(0), F(0)), (F(3), F(6)))
    Fraction(1, 3)
    >>> on_line((F(1), F(2)), (F(0), F(0)), (F(3), F(5))) is None
    True
    """
    k = next((k for k in range(len(a)) if a[k] != b[k]), None)
    if k is None:
        return F0 if tuple(p) == tuple(a) else None
    t = (p[k] - a[k]) / (b[k] - a[k])
    if not F0 <= t <= F1:
        return None
    return t if all(p[i] == a[i] + t * (b[i] - a[i]) for i in range(len(a))) else None


def on_dogleg(p: Point, a: Point, b: Point, rates: Sequence[Fraction]) -> Fraction | None:
    """The time (min) at which a dogleg rapid from ``a`` to ``b`` passes ``p``, or None (exact).

    Every axis starts at once and moves at its own rate (``rates``, per
    minute) until it arrives, so at time ``tau`` axis ``i`` stands at
    ``a_i + sign(d_i) min(rate_i tau, |d_i|)``.

    >>> F = Fraction
    >>> on_dogleg((F(10), F(10)), (F(0), F(0)), (F(20), F(10)), (F(100), F(100)))
    Fraction(1, 10)
    >>> on_dogleg((F(10), F(5)), (F(0), F(0)), (F(20), F(10)), (F(100), F(100))) is None
    True
    """
    lo, hi = F0, None  # tau in [lo, hi]
    for pi, ai, bi, rate in zip(p, a, b, rates):
        d = bi - ai
        if d == 0:
            if pi != ai:
                return None
            continue
        s = (pi - ai) / d
        if not F0 <= s <= F1 or rate <= 0:
            return None
        need = abs(pi - ai) / rate
        if s == 1:
            lo = max(lo, need)  # arrived: any later time
        else:
            lo = max(lo, need)
            hi = need if hi is None else min(hi, need)
    if hi is not None and lo > hi:
        return None
    return lo


def _half(u: tuple[Fraction, Fraction], v: tuple[Fraction, Fraction]) -> int:
    """0 when ``v`` is in the half-turn counter-clockwise from ``u`` (``u`` itself included), else 1."""
    cross = u[0] * v[1] - u[1] * v[0]
    dot = u[0] * v[0] + u[1] * v[1]
    return 0 if cross > 0 or (cross == 0 and dot > 0) else 1


def _ccw_not_after(u: tuple[Fraction, Fraction], v: tuple[Fraction, Fraction], w: tuple[Fraction, Fraction]) -> bool:
    """Counter-clockwise from ``u``: is the direction ``v`` reached no later than ``w`` (exact)?"""
    hv, hw = _half(u, v), _half(u, w)
    if hv != hw:
        return hv < hw
    return v[0] * w[1] - v[1] * w[0] >= 0


def on_arc(p: Point, seg: Segment) -> bool:
    """Is ``p`` exactly on the circular arc ``seg`` (rational centre, start and end on one circle, no helix)?

    Returns False for motions that are not such arcs (a helix, a spiral, an
    R-format arc without a centre): their points are checked approximately.
    """
    if seg.kind is not SegmentKind.ARC or seg.centre is None:
        return False
    i, j, _ = seg.plane_indices()
    if any(seg.start[k] != seg.end[k] or p[k] != seg.start[k] for k in range(len(p)) if k not in (i, j)):
        return False
    c = seg.centre
    u = (seg.start[i] - c[0], seg.start[j] - c[1])
    w = (seg.end[i] - c[0], seg.end[j] - c[1])
    v = (p[i] - c[0], p[j] - c[1])
    r2 = u[0] ** 2 + u[1] ** 2
    if w[0] ** 2 + w[1] ** 2 != r2 or v[0] ** 2 + v[1] ** 2 != r2:
        return False
    if seg.start == seg.end or seg.turns:
        return True  # a full circle (or more)
    if seg.clockwise:  # mirror: a clockwise sweep is a counter-clockwise one of the mirrored vectors
        u, v, w = (u[0], -u[1]), (v[0], -v[1]), (w[0], -w[1])
    return _ccw_not_after(u, v, w)


# --------------------------------------------------------------------------- approximate geometry


def _float_arc_distance(p: Point, seg: Segment) -> float:
    """Distance (max over axes) from ``p`` to an arc, helix or spiral, in floats."""
    at, _ = arc_path_float(seg)
    return _min_distance([to_float(x) for x in p], at)


def _min_distance(p: list[float], at: Callable[[float], list[float]], samples: int = 4096) -> float:
    """Smallest max-norm distance from ``p`` to the curve ``at(f)``, f in [0, 1] (samples, then refined)."""
    def dist(f: float) -> float:
        return max(abs(a - b) for a, b in zip(at(f), p))

    best = min(range(samples + 1), key=lambda k: dist(k / samples))
    lo, hi = max(0.0, (best - 1) / samples), min(1.0, (best + 1) / samples)
    for _ in range(100):  # golden-section search around the best sample
        m1, m2 = lo + (hi - lo) * 0.381966, hi - (hi - lo) * 0.381966
        if dist(m1) <= dist(m2):
            hi = m2
        else:
            lo = m1
    return min(dist(lo), dist(hi), dist(best / samples))


def _float_developed_distance(p: Point, seg: Segment) -> float:
    from .geometry.cylinder import cylinder_of, developed_arc_of

    info = cylinder_of(seg)
    if info is None:
        return math.inf
    linear, rotary, _ = info
    iz, ic = seg.axes.index(linear), seg.axes.index(rotary)
    arc = developed_arc_of(seg)
    s = [to_float(x) for x in seg.start]
    e = [to_float(x) for x in seg.end]

    def at(f: float) -> list[float]:
        z, _, c = arc.point(Fraction(f).limit_denominator(10**12))
        q = [sv + (ev - sv) * f for sv, ev in zip(s, e)]
        q[iz], q[ic] = to_float(z.mid()), to_float(c.mid())
        return q

    return _min_distance([to_float(x) for x in p], at, samples=512)


def _float_polar_distance(p: Point, seg: Segment) -> float:
    """Distance (max over axes) from ``p`` to a polar move's machine path, in floats (samples, then near the best)."""
    from .geometry.polar import polar_of
    from .geometry.samples import polar_float_points

    q = [to_float(x) for x in p]
    e = polar_of(seg)
    if e is None:
        return math.inf
    ic = seg.axes.index(e.rotary_axis)
    n, lo, hi = 512, Fraction(0), Fraction(1)
    pts = polar_float_points(seg, n)
    for _ in range(4):  # the best sample, then 256 samples between its neighbours, three times
        best = min(range(len(pts)), key=lambda k: max(abs(a - b) for a, b in zip(pts[k], q)))
        k0, k1 = max(best - 1, 0), min(best + 1, len(pts) - 1)
        lo, hi = lo + (hi - lo) * Fraction(k0, n), lo + (hi - lo) * Fraction(k1, n)
        n = 256
        pts = polar_float_points(seg, n, lo, hi, pts[k0][ic] - float(e.c_entry))
    return min(max(abs(a - b) for a, b in zip(pt, q)) for pt in pts)


# --------------------------------------------------------------------------- a counterexample on a motion


def on_motion(p: Point, seg: Segment, machine: Machine, exact: bool, parameter: Fraction | None) -> bool:
    """Whether ``p`` lies on the motion ``seg`` on ``machine`` (:data:`_ON_MOTION` per kind; ``exact`` False: an
    irrational path point, within :data:`IRRATIONAL_TOLERANCE_MM`; ``parameter``: a spline's, else None)."""
    if tuple(p) in (tuple(seg.start), tuple(seg.end)):
        return True
    return _ON_MOTION[seg.kind](p, seg, machine, exact, parameter)


def _on_straight(p: Point, seg: Segment, machine: Machine, exact: bool, parameter: Fraction | None) -> bool:
    if seg.kind is SegmentKind.LINE or machine.rapid_mode is RapidMode.LINEAR:
        return on_line(p, seg.start, seg.end) is not None
    rates = tuple(machine.axis(a).rapid_mm_min for a in machine.axis_names)
    return on_dogleg(p, seg.start, seg.end, rates) is not None


def _on_spline(p: Point, seg: Segment, machine: Machine, exact: bool, parameter: Fraction | None) -> bool:
    if parameter is None:
        return False
    from .geometry.nurbs import spline_curve

    curve = spline_curve(seg)
    lo, hi = curve.domain
    return tuple(curve.point(lo + parameter * (hi - lo))) == tuple(p)


def _on_arc(p: Point, seg: Segment, machine: Machine, exact: bool, parameter: Fraction | None) -> bool:
    return on_arc(p, seg) if exact else _float_arc_distance(p, seg) <= IRRATIONAL_TOLERANCE_MM


def _on_float_curve(distance: Callable[[Point, Segment], float]) -> Callable[..., bool]:
    """A curve whose points are irrational in general: on it within the tolerance, never exactly."""
    return lambda p, seg, machine, exact, parameter: not exact and distance(p, seg) <= IRRATIONAL_TOLERANCE_MM


#: Whether a counterexample's point lies on a motion, per motion kind (docs/design.md §10 "How to add a
#: motion kind"); the segment's start and end are on every kind.
_ON_MOTION: dict[SegmentKind, Callable[[Point, Segment, Machine, bool, Fraction | None], bool]] = {
    SegmentKind.LINE: _on_straight,
    SegmentKind.RAPID: _on_straight,
    SegmentKind.DWELL: lambda p, seg, machine, exact, parameter: False,
    SegmentKind.ARC: _on_arc,
    SegmentKind.SPLINE: _on_spline,
    SegmentKind.DEVELOPED_ARC: _on_float_curve(_float_developed_distance),
    SegmentKind.POLAR: _on_float_curve(_float_polar_distance),
}
REPLAYED_KINDS = frozenset(_ON_MOTION)

def off_motion(axes: tuple[str, ...], path: Point, what: str, block: object, exact: bool) -> str:
    """What a path point that is on no motion of its block is reported as."""
    return (f"the path point {show_point(axes, path)} is not on the {what} of block {block}"
            + ("" if exact else f" (not within {IRRATIONAL_TOLERANCE_MM} mm)"))


def in_zone(point: Point, path: Point, zone: str, hits: Sequence[Segment], machine: Machine,
             margin: Fraction) -> tuple[bool, str]:
    """Whether ``point`` is within ``margin`` of ``path`` on every axis and outside the allowed set in ``zone``
    with the tool length (and tip offsets) of one of the motions ``hits`` (exact): (ok, what was found)."""
    axes = machine.axis_names
    gap = max(abs(a - b) for a, b in zip(point, path))
    if gap > margin:
        return False, (f"the point {show_point(axes, point)} is {format_decimal(gap)} mm from the path point, "
                       f"more than the margin {format_decimal(margin)} mm")
    bad = [z.name for s in hits for z in tip_shifted(machine.allowed, tip_offset(s.extra)).violated_zones(
        dict(zip(axes, point)), s.tool_length)]
    if zone not in bad:
        inside = "inside the allowed set" if not bad else f"outside {', '.join(sorted(set(bad)))} only"
        return False, f"the point {show_point(axes, point)} is {inside}, not outside zone {zone!r}"
    return True, f"the point {show_point(axes, point)} is outside zone {zone!r} (exact)"


def motion_witness_replays(mine: Sequence[Segment], machine: Machine, shift: Sequence[Fraction], margin: Fraction,
                           *, block: int, zone: str, point: Point, path: Point, exact: bool,
                           parameter: Fraction | None, what: str) -> tuple[bool, str]:
    """Whether a motion's witness (not a solid's, not a recovery leg's) replays on ``mine``, the motions of its
    block re-interpreted at its values on ``machine`` (homing errors apart, as ``shift``): the check ``nczones
    replay`` makes of a report's counterexample, on the values a :class:`~nczones.prover.result.Violation`
    carries.  The path point (less the shift) lies on one of the motions (exactly; within
    :data:`IRRATIONAL_TOLERANCE_MM` when ``exact`` is False, an irrational path point), the point within
    ``margin`` of it and outside the allowed set in ``zone`` (exact).  Returns (replays, what was found)."""
    nominal = tuple(x - d for x, d in zip(path, shift))
    hits = [s for s in mine if on_motion(nominal, s, machine, exact, parameter)]
    if not hits:
        return False, off_motion(machine.axis_names, path, what, block, exact)
    return in_zone(point, path, zone, hits, machine, margin)


def show_point(axes: tuple[str, ...], p: Point) -> str:
    """``p`` as ``X1.5 Y2 Z0.333333…`` (six decimals at most)."""
    return " ".join(f"{a}{format_decimal(x, 6)}" for a, x in zip(axes, p))


