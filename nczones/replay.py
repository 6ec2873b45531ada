"""``nczones replay REPORT.json``: re-check a report's counterexamples exactly, against the files it names.

A JSON report of ``nczones verify`` names the machine file and the program
with their SHA-256, every setting that changes the verdict, and each
counterexample as exact rationals (``point_exact``, ``path_point_exact``,
``params_exact``).  Replaying one does not run the prover again: it

1. loads the machine file and the program the report names (relative paths
   from the working directory, or ``--machine``/``--program``) and refuses
   them when their SHA-256 differs from the report's (``RP102``);
2. builds the machine the counterexample speaks of: every parameter value of
   the counterexample put into the machine file's values (a work offset
   component, a tool length register, the start position; a homing error
   shifts the machine coordinates of its axis);
3. interprets the program on that machine with the report's settings
   (arc tolerance, loop bound, block delete) and takes the motions of the
   violating block;
4. checks, in exact rational arithmetic, that the path point lies on one of
   those motions (a line, a rapid the way the machine moves it — straight
   or dogleg —, a circular arc, a NURBS curve at the reported parameter, a
   tool-break recovery leg from the reported break point), that the point
   lies within the margin of it on every axis, and that the point is outside
   the allowed set, in the zone the report names.  A tool solid in a fixture
   (``kind = "solid"``, or ``kind = "recovery"`` whose ``zones`` name a part
   and not its zone: a recovery leg of the solids proof) is checked instead by
   placing the named tool part at the path point and testing that the witness
   is inside it and inside the fixture (:func:`_check_solid`).

A path point that is irrational (on a helix, an R-format arc with an
irrational centre, a developed arc; the report marks it
``path_point_on_path: false``) cannot be checked exactly: the replay checks
that it lies within :data:`IRRATIONAL_TOLERANCE_MM` of the motion and says
so.  Exit status: 0 every counterexample confirmed, 1 one was not, 2 bad
input (an unreadable report, a missing or changed file).
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any

from .errors import Diagnostic, InputError, InvalidArgument
from .exact import format_decimal, parse_rational, to_float
from .machine import Machine, RapidMode, load_machine
from .motion import Segment, SegmentKind, arc_path_float, tip_offset
from .pipeline.witnesses import concrete_machine
from .zones import tip_shifted

__all__ = ["Check", "replay_report", "replay_file", "on_line", "on_dogleg", "on_arc", "ReplayError",
           "IRRATIONAL_TOLERANCE_MM"]

#: How close an irrational path point must be to the motion (mm; degrees on a rotary axis).
IRRATIONAL_TOLERANCE_MM = 1e-6

F0, F1 = Fraction(0), Fraction(1)
Point = tuple[Fraction, ...]


class ReplayError(InputError):
    """A report that cannot be replayed (codes RP1xx)."""


@dataclass(frozen=True, slots=True)
class Check:
    """The replay of one counterexample: ``confirmed`` and what was checked (or what failed)."""

    program: str
    line: int | None
    block: int
    zone: str
    confirmed: bool
    exact: bool
    message: str

    def render(self) -> str:
        where = f"{self.program}:{self.line}" if self.line is not None else self.program
        return f"{where}: {'confirmed' if self.confirmed else 'NOT REPRODUCED'}: {self.message}"


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
    from .report.samples import polar_float_points

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


# --------------------------------------------------------------------------- reading the report


def _fail(code: str, message: str, where: str) -> ReplayError:
    return ReplayError(Diagnostic(code, message, file=where))


def _point(raw: Any, axes: tuple[str, ...], what: str, where: str) -> Point:
    if not isinstance(raw, Mapping) or set(raw) != set(axes):
        raise _fail("RP104", f"{what} must map every axis of the machine ({', '.join(axes)}) to an exact "
                             f"rational such as \"1900/3\"; found {raw!r}", where)
    try:
        return tuple(parse_rational(raw[a]) for a in axes)
    except InvalidArgument as exc:
        raise _fail("RP104", f"{what}: {exc}", where) from None


def _resolve(path: str, base: str | None) -> str:
    return path if os.path.isabs(path) or base is None else os.path.join(base, path)


def _check_hash(kind: str, path: str, actual: str, expected: Any, where: str) -> None:
    if expected and actual != expected:
        raise _fail("RP102", f"the {kind} {path} is not the one the report was made from: its SHA-256 is "
                             f"{actual[:16]}…, the report names {str(expected)[:16]}…", where)


# --------------------------------------------------------------------------- checking one counterexample


def _on_motion(p: Point, seg: Segment, machine: Machine, exact: bool, parameter: Fraction | None) -> bool:
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


def _recovery_legs(v: Mapping[str, Any], seg: Segment, segs: list[Segment], machine: Machine,
                   settings: Mapping[str, Any], break_point: Point) -> list[Segment]:
    """The recovery motion the counterexample names (a leg from the break point, or the resumed cut)."""
    from .plans.recovery import (
        RecoveryVariant,
        motion_sequences,
        recovery_legs,
        replacement_length,
        shift_segment,
        tool_axis_index,
        tool_change_config,
    )

    cfg = tool_change_config(machine, settings.get("recovery"))
    length = seg.tool_length
    new_length = replacement_length(cfg, machine, length)
    if v.get("leg") == "resume":
        return [shift_segment(seg, tool_axis_index(machine), new_length - length, new_length)]
    index = next(k for k, s in enumerate(segs) if s is seg)
    sequence_start = next(segs[a].start for a, b in motion_sequences(segs) if a <= index <= b)
    restart = break_point if cfg.variant is RecoveryVariant.BREAKPOINT else sequence_start
    legs = recovery_legs(cfg, machine, break_point, restart, length, new_length)
    # in the cut's frame: a fixture in a work offset is where the cut saw it (as the solids proof places it)
    return [replace(lg.segment(machine.axis_names, seg), frame=seg.frame) for lg in legs if lg.name == v.get("leg")]


def _check_violation(v: Mapping[str, Any], program: str, machine: Machine, segs: list[Segment],
                     shift: Point, margin: Fraction, settings: Mapping[str, Any], where: str) -> Check:
    axes = machine.axis_names
    block, zone, line = v.get("block"), v.get("zone", ""), v.get("line")
    exact = bool(v.get("path_point_on_path", True))

    def result(ok: bool, message: str) -> Check:
        return Check(program, line, block if isinstance(block, int) else -1, zone, ok, exact, message)

    # the witness is a point of X, Y, Z (inside a tool part and a fixture): a solid violation, or a recovery
    # leg's from the solids proof (its zones name the part, not its zone: a fixture)
    zones = v.get("zones") or ()
    solid = v.get("kind") == "solid" or (v.get("kind") == "recovery" and bool(zones) and zone not in zones)
    from .lathe_solids import is_lathe_axes

    space = (("X", "Z") if is_lathe_axes(axes) else ("X", "Y", "Z")) if solid else axes  # a lathe: its section
    point = _point(v.get("point_exact"), space, "point_exact", where)
    path = _point(v.get("path_point_exact"), axes, "path_point_exact", where)
    nominal = tuple(x - d for x, d in zip(path, shift))
    mine = [s for s in segs if s.block == block]
    if not mine:
        return result(False, f"the program has no motion in block {block} on this machine")
    parameter = None
    if v.get("segment_kind") == "spline" and v.get("parameter_rational") is not None:
        parameter = parse_rational(str(v["parameter_rational"]))
    what = v.get("segment_kind", "motion")
    if v.get("kind") == "recovery":
        brk = _point(v.get("break_point_exact"), axes, "break_point_exact", where)
        cutting = [s for s in mine if s.kind in (SegmentKind.LINE, SegmentKind.ARC)
                   and (s.kind is SegmentKind.LINE and on_line(brk, s.start, s.end) is not None or on_arc(brk, s))]
        if v.get("leg") != "resume" and not cutting:
            return result(False, f"the break point {_show(axes, brk)} is not on a cutting motion of block {block}")
        base = cutting or [s for s in mine if s.kind in (SegmentKind.LINE, SegmentKind.ARC)]
        mine = [leg for s in base for leg in _recovery_legs(v, s, segs, machine, settings, brk)]
        what = f"recovery leg {v.get('leg')!r} after a tool break at {_show(axes, brk)}"
    hits = [s for s in mine if _on_motion(nominal, s, machine, exact, parameter)]
    if not hits:
        return result(False, f"the path point {_show(axes, path)} is not on the {what} of block {block}"
                             + ("" if exact else f" (not within {IRRATIONAL_TOLERANCE_MM} mm)"))
    if solid:
        how = "exactly" if exact else f"within {IRRATIONAL_TOLERANCE_MM} mm (an irrational path point)"
        return result(*_check_solid(v, point, nominal, hits, machine, how, where))
    gap = max(abs(a - b) for a, b in zip(point, path))
    if gap > margin:
        return result(False, f"the point {_show(axes, point)} is {format_decimal(gap)} mm from the path point, "
                             f"more than the margin {format_decimal(margin)} mm")
    bad = [z.name for s in hits for z in tip_shifted(machine.allowed, tip_offset(s.extra)).violated_zones(
        dict(zip(axes, point)), s.tool_length)]
    if zone not in bad:
        inside = "inside the allowed set" if not bad else f"outside {', '.join(sorted(set(bad)))} only"
        return result(False, f"the point {_show(axes, point)} is {inside}, not outside zone {zone!r}")
    how = "exactly" if exact else f"within {IRRATIONAL_TOLERANCE_MM} mm (an irrational path point)"
    params = v.get("params_exact") or {}
    with_params = f" with {', '.join(f'{n}={x}' for n, x in params.items())}" if params else ""
    return result(True, f"the point {_show(axes, point)} is outside zone {zone!r} (exact) and the path point "
                        f"lies on the {what} of block {block} {how}{with_params}")


def _fixture_origin(fx: Any, seg: Segment, index: tuple[int, int, int]) -> tuple[Fraction, Fraction, Fraction] | None:
    """Where a fixture's coordinates start at a motion: machine zero, or its work offset's origin as the re-run
    motion records it (None: the motion runs in another or a rotated frame)."""
    if not fx.frame:
        return Fraction(0), Fraction(0), Fraction(0)
    frame = seg.frame
    if frame is None or frame.work != fx.frame or frame.rotation is not None or frame.work_offset is None:
        return None
    w = frame.work_offset
    return w[index[0]], w[index[1]], w[index[2]]


def _in_fixture_xy(fx: Any, x: Fraction, y: Fraction) -> bool:
    """Is ``(x, y)`` strictly inside the fixture's XY section (a circle, a box, or a polygon: an even-odd
    crossing count, a point on an edge is not inside)?  Replay's own test, exact."""
    from .solids import FixtureCylinder, FixturePrism

    if isinstance(fx, FixtureCylinder):
        return (x - fx.cx) ** 2 + (y - fx.cy) ** 2 < fx.radius ** 2
    if isinstance(fx, FixturePrism):
        vs = fx.vertices
        inside = False
        for (x0, y0), (x1, y1) in zip(vs, vs[1:] + vs[:1]):
            cross = (x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)
            if cross == 0 and min(x0, x1) <= x <= max(x0, x1) and min(y0, y1) <= y <= max(y0, y1):
                return False  # on the boundary: not in the open interior
            if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
                inside = not inside
        return inside
    return all((lo is None or lo < q) and (hi is None or q < hi) for q, lo, hi in ((x, fx.x0, fx.x1), (y, fx.y0, fx.y1)))


def _check_solid(v: Mapping[str, Any], point: Point, path: Point, hits: list[Segment], machine: Machine,
                 how: str, where: str) -> tuple[bool, str]:
    """A tool solid in a fixture (``kind = "solid"``): the assembly placed with its controlled point at the
    path point (the part's heights from the motion's own tool length), the witness ``point`` inside the part
    the report names (a closed vertical cylinder) and inside the open interior of the fixture (its ``zone``),
    checked here in exact rationals, independently of the prover's distance computation."""
    from .lathe_solids import LatheSolids
    from .solids import machine_solids

    solids = machine_solids(machine)
    if solids is None:
        raise _fail("RP105", "a solid violation, but the machine file describes no tool or spindle solids "
                             "([[tools]], [spindle])", where)
    names = v.get("zones")
    if not isinstance(names, list) or len(names) != 1 or not isinstance(names[0], str):
        raise _fail("RP106", f"a solid violation names its part in zones = [part], got {names!r}", where)
    if isinstance(solids, LatheSolids):  # a lathe's turret tool against fixtures of revolution
        return _check_lathe_solid(v, point, path, hits, machine, solids, how)
    part_name, zone = names[0], v.get("zone", "")
    fixtures = [f for f in solids.fixtures if f.name == zone]
    if not fixtures:
        return False, f"the machine has no fixture {zone!r}"
    axes = machine.axis_names
    ix, iy, iz = axes.index("X"), axes.index("Y"), axes.index("Z")
    qx, qy, qz = point
    px, py, pz = path[ix], path[iy], path[iz]
    placed = False
    for seg in hits:
        for part in solids.parts_for(seg.tool_register) or ():
            if part.name != part_name:
                continue
            placed = True
            base = pz if part.spindle else pz - seg.tool_length
            if not ((qx - px) ** 2 + (qy - py) ** 2 <= part.radius ** 2 and base + part.z0 <= qz <= base + part.z1):
                continue
            for fx in fixtures:
                origin = _fixture_origin(fx, seg, (ix, iy, iz))
                if origin is None:
                    return False, (f"fixture {zone!r} moves with {fx.frame}, which block {v.get('block')} does not "
                                   "run in (unrotated): replay cannot place it")
                fx_q = (qx - origin[0], qy - origin[1], qz - origin[2])
                if _in_fixture_xy(fx, fx_q[0], fx_q[1]) and (fx.z0 is None or fx.z0 < fx_q[2]) \
                        and (fx.z1 is None or fx_q[2] < fx.z1):
                    return True, (f"the point {_show(('X', 'Y', 'Z'), point)} is inside the {part.label()} placed at the path "
                                  f"point {_show(axes, path)} and inside fixture {zone!r} (exact), and the path point "
                                  f"lies on the {v.get('segment_kind', 'motion')} of block {v.get('block')} {how}")
            return False, (f"the point {_show(('X', 'Y', 'Z'), point)} is inside the {part.label()} at the path point, "
                           f"but not inside fixture {zone!r}")
    if not placed:
        return False, f"the tool assembly active at block {v.get('block')} has no part {part_name!r}"
    return False, (f"the point {_show(('X', 'Y', 'Z'), point)} is not inside the part {part_name!r} placed at the path point "
                   f"{_show(axes, path)}")


def _check_lathe_solid(v: Mapping[str, Any], point: Point, path: Point, hits: list[Segment], machine: Machine,
                       solids: Any, how: str) -> tuple[bool, str]:
    """A lathe's turret tool part in a fixture of revolution, in the section through the spindle axis
    (``specs/turning.md``, "Tool and fixture solids"): the part's rectangle relative to the tip (grown by half
    its thickness, as the proof uses it) placed at the path point minus the motion's tool offsets, the
    witness ``(X, Z)`` in that closed rectangle and in the open section of the fixture (``|X|`` between its
    radii, Z inside its range), in exact rationals, independently of the prover's Minkowski rectangles."""
    from .prover.lathe_solids import segment_tool, tip_shift

    part_name, zone = v["zones"][0], v.get("zone", "")
    fixtures = [f for f in solids.fixtures if f.name == zone]
    if not fixtures:
        return False, f"the machine has no fixture {zone!r}"
    axes = machine.axis_names
    qx, qz = point
    px, pz = path[axes.index("X")], path[axes.index("Z")]
    shown = _show(("X", "Z"), point)
    placed = False
    for seg in hits:
        tool = segment_tool(seg)
        for part in solids.tools.get(tool, ()) if tool is not None else ():
            if part.name != part_name:
                continue
            placed = True
            sx, sz = tip_shift(seg, machine.tool_axis)
            a, b, c, d = part.rect()
            if not (px - sx + a <= qx <= px - sx + b and pz - sz + c <= qz <= pz - sz + d):
                continue
            for fx in fixtures:
                in_r = fx.r_in < abs(qx) and (fx.r_out is None or abs(qx) < fx.r_out)
                if in_r and (fx.z0 is None or fx.z0 < qz) and (fx.z1 is None or qz < fx.z1):
                    return True, (f"the point {shown} is inside the {part.label()} of tool {tool} placed at the "
                                  f"path point {_show(axes, path)} and inside fixture {zone!r} (exact, in the "
                                  f"section through the spindle axis), and the path point lies on the "
                                  f"{v.get('segment_kind', 'motion')} of block {v.get('block')} {how}")
            return False, (f"the point {shown} is inside the {part.label()} at the path point, but not inside "
                           f"fixture {zone!r}")
    if not placed:
        return False, f"the turret tool active at block {v.get('block')} has no part {part_name!r}"
    return False, (f"the point {shown} is not inside the part {part_name!r} placed at the path point "
                   f"{_show(axes, path)}")


def _show(axes: tuple[str, ...], p: Point) -> str:
    return " ".join(f"{a}{format_decimal(x, 6)}" for a, x in zip(axes, p))


def _segments(source: Any, machine: Machine, settings: Mapping[str, Any], skip: frozenset[int]) -> list[Segment]:
    """The motion of the program as the report's settings interpret it (:class:`VerifyOptions`), with the
    block-skip switches ``skip`` on."""
    from .pipeline.verification import interpretation
    from .prover.options import VerifyOptions

    options = VerifyOptions.from_settings(settings)
    return list(interpretation(source, machine, options, skip=skip).segments())


def _skips_deleted_blocks(v: Mapping[str, Any], settings: Mapping[str, Any]) -> frozenset[int]:
    """The block-skip switches on along the violation's path (their lines skipped): those the violation
    names on, and those the settings fix on; a switch left to both that it does not name is off."""
    from .blockskip import parse_block_delete

    mode = settings.get("block_delete")
    try:
        modes = parse_block_delete("on" if mode is True else mode if isinstance(mode, str) else "both")
    except ValueError:
        modes = parse_block_delete("both")
    on = {n for n, p in modes.items() if p == "on"}
    switches = v.get("switches")
    if isinstance(switches, Mapping):
        for name, position in switches.items():
            if name == "block_delete" or (isinstance(name, str) and name.startswith("block_delete/")
                                          and name[13:].isdigit()):
                n = 1 if name == "block_delete" else int(name[13:])
                if position == "on":
                    on.add(n)
                else:
                    on.discard(n)
    return frozenset(on)


def replay_report(doc: Mapping[str, Any], *, base: str | None = None, machine_file: str | None = None,
                  program_file: str | None = None, where: str = "<report>") -> list[Check]:
    """Replay every counterexample of one JSON report (a dict, as ``nczones verify --format json`` writes).

    Relative paths in the report are taken from ``base`` (default: the
    working directory); ``machine_file`` and ``program_file`` replace the
    files the report names (their SHA-256 must still match).

    >>> import json, subprocess, sys
    >>> out = subprocess.run([sys.executable, "-m", "nczones", "verify", "specs/examples/programs/notch_dip.ngc",
    ...                       "--machine", "specs/machines/grinder.toml", "--format", "json"],
    ...                      capture_output=True, text=True).stdout
    >>> [(c.line, c.zone, c.confirmed, c.exact) for c in replay_report(json.loads(out))]
    [(5, 'wheel area', True, True)]
    """
    from .gcode.source import load_program

    if not isinstance(doc, Mapping) or "verdict" not in doc or not isinstance(doc.get("violations"), list):
        raise _fail("RP101", "not a report of nczones verify (a JSON object with verdict and violations)", where)
    violations = doc["violations"]
    if not violations:
        return []
    machine_info: Mapping[str, Any] = doc["machine"] if isinstance(doc.get("machine"), Mapping) else {}
    mpath = machine_file or machine_info.get("file")
    if not mpath:
        raise _fail("RP103", "the report names no machine file; pass --machine", where)
    machine = load_machine(_resolve(mpath, base if machine_file is None else None))
    _check_hash("machine file", mpath, machine.sha256, machine_info.get("sha256"), where)
    ppath = program_file or doc.get("program")
    if not ppath or (program_file is None and str(ppath).startswith("<")):
        raise _fail("RP103", f"the report's program is {ppath or 'unnamed'} (not a file); pass --program", where)
    source = load_program(_resolve(ppath, base if program_file is None else None), name=doc.get("program") or ppath)
    _check_hash("program", ppath, source.sha256, doc.get("program_sha256"), where)
    settings: Mapping[str, Any] = doc["settings"] if isinstance(doc.get("settings"), Mapping) else {}
    try:
        margin = parse_rational(str(settings.get("margin", doc.get("margin", "0"))))
    except InvalidArgument as exc:
        raise _fail("RP104", f"margin: {exc}", where) from None
    cache: dict[tuple, tuple[list[Segment], Point, Machine]] = {}
    checks = []
    for v in violations:
        raw = v.get("params_exact") or {}
        try:
            params = {str(n): parse_rational(x) for n, x in raw.items()}
        except InvalidArgument as exc:
            raise _fail("RP104", f"params_exact: {exc}", where) from None
        skip = _skips_deleted_blocks(v, settings)
        key = (tuple(sorted(params.items())), skip)
        if key not in cache:
            concrete, shift = concrete_machine(machine, params)
            cache[key] = (_segments(source, concrete, settings, skip), shift, concrete)
        segs, shift, concrete = cache[key]
        checks.append(_check_violation(v, source.name, concrete, segs, shift, margin, settings, where))
    return checks


def _documents(data: Any) -> Iterator[Mapping[str, Any]]:
    if isinstance(data, list):
        for d in data:
            if isinstance(d, Mapping) and d.get("verdict") == "error":
                continue  # a program the verification could not read: nothing to replay
            yield d
    else:
        yield data


def replay_file(path: str, *, base: str | None = None, machine_file: str | None = None,
                program_file: str | None = None) -> list[Check]:
    """:func:`replay_report` of every report in a JSON file (one report, or a list of them)."""
    try:
        with open(path, encoding="utf-8") as fh:
            data = json.load(fh)
    except OSError as exc:
        raise _fail("RP100", f"cannot read the report: {exc.strerror or exc}", path) from None
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise _fail("RP101", f"not a JSON report: {exc}", path) from None
    docs = list(_documents(data))
    if len(docs) > 1 and (machine_file or program_file):
        raise _fail("RP103", "--machine and --program apply to a report of one program", path)
    out: list[Check] = []
    for doc in docs:
        out.extend(replay_report(doc, base=base, machine_file=machine_file, program_file=program_file, where=path))
    return out
