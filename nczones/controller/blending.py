"""Corner blending as LinuxCNC's trajectory planner does it: blend arcs at corners, after naive-CAM merging.

The reference controller moves the programmed path in exact path modes.  In a blending mode (LinuxCNC
``G64``, ``G64 P p``) the planner rounds the corner between two straight motions with a **blend arc**
(``src/emc/tp/tp.c`` ``tpCreateLineLineBlend``, ``src/emc/tp/blendmath.c``; LinuxCNC 2.9): a circular arc
tangent to both motions, the motions trimmed by ``d_plan`` at the corner.  This module computes that arc
from the machine file's per-axis maximum velocity (the rapid rates, ``[AXIS_x] MAX_VELOCITY``) and
acceleration (``[machine.acceleration]``, ``[AXIS_x] MAX_ACCELERATION``), written from the planner's
functions (it is the controller's own geometry; the prover's enclosure, ``nczones.prover.blend``, is not
used):

* ``blendGeom3Init``: ``theta`` is half the angle between the two motions at the corner; no blend when
  ``theta`` or ``pi/2 - theta`` is below ``TP_ANGLE_EPSILON`` (a reversal or a straight join);
* ``blendInit3FromLineLine``: ``L1 = min(prev target, prev nominal length / 2)``, ``L2 = next target / 2``
  (``BLEND_DIST_FRACTION``);
* ``tcFindBlendTolerance``: ``T = min(T1, T2, L_prev / 4, L_next / 4)`` with ``T1 = T2 = p`` (``G64 P p``) or,
  without a tolerance, a quarter of each motion's nominal length;
* ``blendParamKinematics``: ``a_max`` the inscribed diameter of the axes' acceleration bounds in the plane of
  the two motions (``calculateInscribedDiameter``), ``a_n = a_max sqrt(1 - 0.5^2)``
  (``BLEND_ACC_RATIO_NORMAL``), ``v_goal`` the larger requested velocity clipped by the planar velocity
  bound and the "altitude" velocity;
* ``blendComputeParameters`` (the trapezoidal planner, ``TRAJ_PLANNER_TYPE`` 0): ``d_geom``, ``R_geom``,
  ``v_plan``, ``R_plan``, ``d_plan``; no arc when ``R_plan`` or the arc length is too small;
* ``blendFindPoints3``: the centre on the bisector ``u2 - u1`` at ``R_plan / sin(theta)`` from the corner.

Corners with a circular arc (line-arc, arc-line, arc-arc) get the planner's blend arcs too
(``nczones.controller.blend_arcs``), and before the planner the canonical layer's naive-CAM merging (``G64 Q``,
``emccanon.cc`` ``see_segment``) joins short lines (:class:`_NaiveCam`).  Only motions of the linear axes X, Y,
Z are blended (rotary or UVW motion, a helix or a refused fit make the planner fall back to a parabolic blend,
which this controller does not reproduce: it moves that corner exactly, a path inside the same enclosure).
Floats decide the geometry; the controller rounds every arc point to whole pulses (specs/path-modes.md §7).
"""

from __future__ import annotations

import dataclasses
import math
from bisect import bisect_right
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidArgument
from ..machine import Machine, RapidMode
from ..motion import Plane, Segment, SegmentKind, arc_path_float
from .blend_arcs import (
    BLEND_DIST_FRACTION,
    TP_ANGLE_EPSILON,
    Circle,
    Corner,
    Kinematics,
    Params,
    arc_arc,
    arc_line,
    blend_tolerance,
    compute_parameters,
    inscribed_diameter,
    line_arc,
    line_limits,
    unit,
)
from .pulses import line_steps

__all__ = ["BLENDING", "BlendArc", "blend_motion", "blend_parameters", "arc_pulse_positions", "blends"]

#: Values of ``Settings.blending``: ``"auto"`` blends as LinuxCNC when the machine starts in G64, reads
#: LinuxCNC programs and gives every linear axis an acceleration; ``"exact"`` never; ``"linuxcnc"`` always
#: (the accelerations are then required).
BLENDING = ("auto", "exact", "linuxcnc")
LINEAR = ("X", "Y", "Z")
#: ``tpSetupTangent``'s ``SHARP_CORNER_DEG``: two motions whose directions reverse within 2 degrees stop exactly.
SHARP_CORNER_EPSILON = (math.pi * 2.0 / 180.0) ** 2
#: ``linkable`` (emccanon.cc): a naive-CAM chain holds at most 101 points (it refuses one when it has more than 100).
NAIVE_CHAIN = 101


@dataclass(frozen=True, slots=True)
class BlendArc:
    """A blend arc between two motions: it runs from ``start`` to ``end`` around ``centre`` (radius ``radius``,
    sweep ``sweep`` radians, less than half a turn), at ``speed_mm_s``; ``seg`` is the corner's first motion
    (block, line, tool length), ``corner`` the programmed corner."""

    seg: Segment
    start: tuple[float, ...]
    end: tuple[float, ...]
    centre: tuple[float, ...]
    radius: float
    sweep: float
    speed_mm_s: float
    corner: tuple[Fraction, ...]
    #: what alarms name it: a blend arc, or a programmed arc trimmed by blends (``circle`` then holds the
    #: planner's circle of what is left of it, in X, Y, Z at the indices ``xyz`` of the machine's axes)
    label: str = "G64 blend arc"
    circle: Circle | None = None
    xyz: tuple[int | None, ...] = ()

    def point(self, f: float) -> np.ndarray:
        """The arc point at fraction ``f`` of its sweep."""
        if self.circle is not None:
            first: np.ndarray = self._full(self.circle.points(np.array([f * self.circle.angle])))[0]
            return first
        c = np.array(self.centre)
        v0, v1 = np.array(self.start) - c, np.array(self.end) - c
        s = math.sin(self.sweep)
        out: np.ndarray = c + (math.sin((1 - f) * self.sweep) * v0 + math.sin(f * self.sweep) * v1) / s
        return out

    def _full(self, xyz: np.ndarray) -> np.ndarray:
        out = np.tile(np.array(self.start, dtype=float), (len(xyz), 1))
        for j, k in enumerate(self.xyz):
            if k is not None:
                out[:, k] = xyz[:, j]
        return out

    def samples(self, n: int) -> np.ndarray:
        """``n`` points from start to end, equally spaced in angle (shape (n, axes))."""
        f = np.linspace(0.0, 1.0, n)
        if self.circle is not None:
            return self._full(self.circle.points(f * self.circle.angle))
        c = np.array(self.centre)
        v0, v1 = np.array(self.start) - c, np.array(self.end) - c
        fc = f[:, None]
        out: np.ndarray = c + (np.sin((1 - fc) * self.sweep) * v0 + np.sin(fc * self.sweep) * v1) / math.sin(self.sweep)
        return out


def _mode_table(machine: Machine, motion: Any) -> list[tuple[int, Any]] | None:
    interp = getattr(motion, "interpreter", None)
    table = getattr(interp, "path_modes", None)
    return table if isinstance(table, list) else None


def _start_mode(machine: Machine) -> tuple[bool, float]:
    """(blends, tolerance p) of the machine's start-up mode."""
    tol = float(machine.path_tolerance) if machine.path_tolerance else 0.0
    return machine.path_mode == "G64", tol


def blends(machine: Machine, setting: str) -> bool:
    """Whether the controller blends corners for ``Settings.blending = setting`` on this machine."""
    if setting not in BLENDING:
        raise InvalidArgument(f"blending {setting!r}: use one of {', '.join(BLENDING)}")
    if setting == "exact":
        return False
    axes = [a for a in machine.axes if a.name in LINEAR]
    have = bool(axes) and all(a.accel_mm_s2 is not None for a in axes)
    if setting == "linuxcnc":
        if not have:
            raise InvalidArgument("blending 'linuxcnc' needs [machine.acceleration] for every linear axis "
                                  "(LinuxCNC's [AXIS_x] MAX_ACCELERATION; nczones import-machine writes it)")
        return True
    return have and machine.dialect == "linuxcnc" and machine.path_mode == "G64"


def blend_parameters(u1: np.ndarray, u2: np.ndarray, lens: tuple[float, float, float, float], tol: float,
                     vreq: tuple[float, float], vel: Sequence[float], acc: Sequence[float]) -> Params | None:
    """``blendInit3FromLineLine`` + ``blendComputeParameters``: ``lens`` = (prev target, prev nominal length,
    next target, next nominal length), ``tol`` = G64 P (0: none), ``vreq`` the requested speeds (mm/s)."""
    dot = max(-1.0, min(1.0, float(np.dot(u1, u2))))
    theta = math.acos(-dot) / 2.0  # findIntersectionAngle
    if math.pi / 2 - theta < TP_ANGLE_EPSILON or theta < TP_ANGLE_EPSILON:
        return None
    phi = math.pi - 2 * theta
    t_prev, n_prev, t_next, n_next = lens
    l1 = min(t_prev, n_prev * BLEND_DIST_FRACTION)
    l2 = t_next * BLEND_DIST_FRACTION
    binormal, bn = unit(np.cross(u1, u2))
    if bn == 0:
        return None
    a_max = inscribed_diameter(binormal, acc)
    v_goal = _velocity_goal(u1, u2, phi, binormal, vreq, vel, acc)
    return compute_parameters(theta, l1, l2, blend_tolerance(tol, n_prev, n_next), a_max, v_goal)


def _velocity_goal(u1: np.ndarray, u2: np.ndarray, phi: float, binormal: np.ndarray, vreq: tuple[float, float],
                   vel: Sequence[float], acc: Sequence[float]) -> float:
    """``blendParamKinematics``' ``v_goal`` for two lines (feed override 1)."""
    vmax1, _ = line_limits(u1, vel, acc)
    vmax2, _ = line_limits(u2, vel, acc)
    v_goal = max(min(vreq[0], vmax1), min(vreq[1], vmax2))
    v_planar = inscribed_diameter(binormal, vel)
    phi_eff = min(phi, math.pi * 0.49)
    w1 = min(vmax1, vmax2 / math.cos(phi_eff))
    w2 = min(vmax2, vmax1 / math.cos(phi_eff))
    base = float(np.linalg.norm(u2 * w2 - u1 * w1))
    v_alt = (w1 * w2 * math.sin(phi)) / base if base > 0 else 0.0  # 2 * area / base
    return min(v_goal, max(v_alt, v_planar))


@dataclass(slots=True)
class _Pending:
    seg: Segment
    nominal: float  # the programmed length
    target: float  # what is left of it to run (less the trim at its start)
    circle: Circle | None = None  # an arc the planner may blend: its circle (what is left of it)
    trimmed: bool = False  # an arc whose start a blend trimmed (it runs as a sampled piece)


class _Blender:
    """Turns a stream of segments into trimmed segments and blend arcs."""

    def __init__(self, machine: Machine, table: list[tuple[int, Any]] | None):
        self.machine = machine
        self.table = table
        self.blend0, self.tol0 = _start_mode(machine)
        names = machine.axis_names
        self.xyz = tuple(names.index(a) if a in names else None for a in LINEAR)
        self.others = [k for k, a in enumerate(names) if a not in LINEAR]
        self.vel = [float(machine.axis(a).rapid_mm_min) / 60 if a in names else 0.0 for a in LINEAR]
        self.acc = [float(machine.axis(a).accel_mm_s2 or 0) if a in names else 0.0 for a in LINEAR]
        self.dogleg = machine.rapid_mode is RapidMode.DOGLEG
        self._keys: list[int] | None = None

    def mode(self, block: int) -> tuple[bool, float]:
        """(blends, p) for the motion of ``block`` (the mode it was queued in)."""
        if self.table is None:
            return self.blend0, self.tol0
        m = self._entry(block)
        if m.dialect != "linuxcnc" or not m.blend:
            return False, 0.0
        return True, float(m.tolerance or 0)

    def naive(self, block: int) -> float:
        """The naive-CAM tolerance q of ``block``'s mode (0: no merging; LinuxCNC's ``G64 P p`` sets q = p)."""
        if self.table is None:
            return self.tol0 if self.blend0 else 0.0
        m = self._entry(block)
        return float(m.naive or 0) if m.dialect == "linuxcnc" and m.blend else 0.0

    def _entry(self, block: int) -> Any:
        assert self.table is not None
        if self._keys is None or len(self._keys) != len(self.table):  # the interpreter fills it as it runs
            self._keys = [b for b, _m in self.table]
        i = bisect_right(self._keys, block) - 1
        return self.table[max(i, 0)][1]

    def straight(self, seg: Segment) -> bool:
        if seg.kind is SegmentKind.LINE or (seg.kind is SegmentKind.RAPID and not self.dogleg):
            return all(seg.start[k] == seg.end[k] for k in self.others) and seg.start != seg.end
        return False

    def circle(self, seg: Segment) -> Circle | None:
        """The planner's circle of an arc of the X/Y/Z axes (``pmCircleInit``; a helix too, which no blend arc
        joins), None for other motions."""
        if seg.kind is not SegmentKind.ARC or any(seg.start[k] != seg.end[k] for k in self.others):
            return None
        i, j, _n = seg.plane_indices()
        if i not in self.xyz or j not in self.xyz:
            return None
        _at, sweep = arc_path_float(seg)
        s, e = self.vec(seg.start), self.vec(seg.end)
        xi, xj = self.xyz.index(i), self.xyz.index(j)
        centre = s.copy()
        centre[xi], centre[xj] = _float_centre(seg)
        normal = np.zeros(3)
        normal[3 - xi - xj] = 1.0  # first x second = normal for G17 (X, Y), G18 (Z, X), G19 (Y, Z)
        if seg.clockwise:
            normal = -normal
        return Circle.init(s, e, centre, normal, abs(sweep))

    def vec(self, p: Sequence[Any]) -> np.ndarray:
        return np.array([float(p[k]) if k is not None else 0.0 for k in self.xyz])

    def speed(self, seg: Segment) -> float:
        if seg.kind is SegmentKind.RAPID or seg.feed_mm_min is None:
            return math.inf
        return float(seg.feed_mm_min) / 60

    def pending(self, seg: Segment) -> _Pending:
        circ = self.circle(seg)
        n = circ.length() if circ is not None else _length(seg)
        return _Pending(seg, n, n, circ)

    def corner(self, a: _Pending, b: Segment) -> tuple[Segment | BlendArc, BlendArc, _Pending] | None:
        blend, tol = self.mode(a.seg.block)
        if not blend or a.seg.end != b.start or a.seg.tool_length != b.tool_length or a.seg.extra != b.extra:
            return None
        la, lb = self.straight(a.seg), self.straight(b)
        if la and lb:
            return self._line_line(a, b, tol)
        cb = self.circle(b) if not lb else None
        if (not la and a.circle is None) or (not lb and cb is None):
            return None
        if self._sharp(a, b, cb):
            return None
        kin = Kinematics(self.vel, self.acc, (self.speed(a.seg), self.speed(b)), (self._vmax(a.seg), self._vmax(b)))
        if la and cb is not None:
            got = line_arc(self.vec(a.seg.start), self.vec(a.seg.end), a.target, a.nominal, cb, tol, kin)
        elif a.circle is not None and lb:
            got = arc_line(a.circle, a.nominal, self.vec(b.start), self.vec(b.end), tol, kin)
        elif a.circle is not None and cb is not None:
            got = arc_arc(a.circle, a.nominal, cb, tol, kin)
        else:
            return None
        return None if got is None else self._joined(a, b, got)

    def _sharp(self, a: _Pending, b: Segment, cb: Circle | None) -> bool:
        """``tpSetupTangent``: directions that reverse within 2 degrees make an exact stop."""
        u1 = a.circle.tangent(a.circle.angle) if a.circle is not None else unit(
            self.vec(a.seg.end) - self.vec(a.seg.start))[0]
        u2 = cb.tangent(0.0) if cb is not None else unit(self.vec(b.end) - self.vec(b.start))[0]
        return float(np.dot(u1 + u2, u1 + u2)) < SHARP_CORNER_EPSILON

    def _vmax(self, seg: Segment) -> float:
        """``tc->maxvel`` when queued: a line's axis-limited speed along it; an arc's, the slower of its plane
        axes (the canonical layer's limit for the circle)."""
        if seg.kind is SegmentKind.ARC:
            i, j, _n = seg.plane_indices()
            return min(self.vel[self.xyz.index(i)], self.vel[self.xyz.index(j)])
        u, _ = unit(self.vec(seg.end) - self.vec(seg.start))
        return line_limits(u, self.vel, self.acc)[0]

    def _line_line(self, a: _Pending, b: Segment, tol: float) -> tuple[Segment, BlendArc, _Pending] | None:
        u1, _ = unit(self.vec(a.seg.end) - self.vec(a.seg.start))
        u2, lb = unit(self.vec(b.end) - self.vec(b.start))
        if float(np.dot(u1 + u2, u1 + u2)) < SHARP_CORNER_EPSILON:
            return None
        p = blend_parameters(u1, u2, (a.target, a.nominal, lb, lb), tol, (self.speed(a.seg), self.speed(b)),
                             self.vel, self.acc)
        if p is None or p.d_plan >= a.target or p.d_plan >= lb:
            return None
        c = self.vec(a.seg.end)
        normal, _ = unit(u2 - u1)
        centre = c + normal * (p.r_plan / math.sin(p.theta))
        s, e = c - u1 * p.d_plan, c + u2 * p.d_plan
        s_full, e_full = self._full(a.seg.end, s), self._full(b.start, e)
        a_cut = dataclasses.replace(a.seg, end=s_full)
        arc = BlendArc(a.seg, tuple(map(float, s_full)), tuple(map(float, e_full)),
                       tuple(map(float, self._full(a.seg.end, centre))), p.r_plan, math.pi - 2 * p.theta,
                       p.v_plan, a.seg.end)
        b_cut = dataclasses.replace(b, start=e_full)
        return a_cut, arc, _Pending(b_cut, lb, lb - p.d_plan)

    def _joined(self, a: _Pending, b: Segment, got: Corner) -> tuple[Segment | BlendArc, BlendArc, _Pending]:
        s_full, e_full = self._full(a.seg.end, got.start), self._full(b.start, got.end)
        first: Segment | BlendArc
        if got.circle1 is not None:
            first = self.piece(dataclasses.replace(a, circle=got.circle1, trimmed=True), s_full)
        else:
            first = dataclasses.replace(a.seg, end=s_full)
        arc = BlendArc(a.seg, tuple(map(float, s_full)), tuple(map(float, e_full)),
                       tuple(map(float, self._full(a.seg.end, got.centre))), got.radius, got.sweep, got.v_plan,
                       a.seg.end)
        if got.circle2 is not None:
            n = _length(b) if self.straight(b) else float(self.circle(b).length())  # type: ignore[union-attr]
            nxt = _Pending(dataclasses.replace(b, start=e_full), n, got.circle2.length(), got.circle2, True)
        else:
            lb = _length(b)
            nxt = _Pending(dataclasses.replace(b, start=e_full), lb, lb - got.trim2)
        return first, arc, nxt

    def piece(self, p: _Pending, end: tuple[Fraction, ...] | None = None) -> Segment | BlendArc:
        """What runs for a pending motion: the segment, or a sampled piece of an arc a blend trimmed."""
        if p.circle is None or not p.trimmed:
            return p.seg
        c = p.circle
        stop = end if end is not None else p.seg.end
        return BlendArc(p.seg, tuple(map(float, p.seg.start)), tuple(map(float, stop)), tuple(map(float, p.seg.start)),
                        c.radius + c.spiral / 2, c.angle, self.speed(p.seg), p.seg.end,
                        label="arc trimmed by a G64 blend", circle=c, xyz=self.xyz)

    def _full(self, base: tuple[Fraction, ...], xyz: np.ndarray) -> tuple[Fraction, ...]:
        out = list(base)
        for j, k in enumerate(self.xyz):
            if k is not None:
                out[k] = Fraction(float(xyz[j]))
        return tuple(out)


def _float_centre(seg: Segment) -> tuple[float, float]:
    """An arc's centre in its plane, as floats (an R-format arc's from ``arc_path_float``'s rule)."""
    i, j, _ = seg.plane_indices()
    if seg.centre is not None:
        return float(seg.centre[0]), float(seg.centre[1])
    s, e = [float(x) for x in seg.start], [float(x) for x in seg.end]
    r = float(seg.radius) if seg.radius is not None else 0.0
    dx, dy = e[i] - s[i], e[j] - s[j]
    d = math.hypot(dx, dy) or 1.0
    h = math.sqrt(max(r * r - d * d / 4, 0.0))
    sign = (1 if seg.clockwise else -1) * (1 if r > 0 else -1)
    return (s[i] + e[i]) / 2 + sign * h * dy / d, (s[j] + e[j]) / 2 - sign * h * dx / d


def _length(seg: Segment) -> float:
    return math.sqrt(sum(float(e - s) ** 2 for s, e in zip(seg.start, seg.end)))


class _NaiveCam:
    """LinuxCNC's naive-CAM merging (``emccanon.cc`` ``see_segment``, ``linkable``, ``flush_segments``), before the
    planner: in ``G64`` with a naive-CAM tolerance q > 0 (``G64 P p Q q``, Q defaulting to P), consecutive straight
    feeds are chained while every chained point lies within q of the line from the chain's start (the last point
    sent, ``canon.endPoint``) to the new point, at most ``NAIVE_CHAIN`` points; the chain is sent as one line to
    its last point.  An XY arc whose chord deviation (``chord_deviation``) is below q joins the chain as its
    middle point and its end point.  A rapid, any other motion, a dwell, a change of mode, feed, tool length or
    of a rotary/UVW axis ends the chain (``flush_segments`` in ``STRAIGHT_TRAVERSE``, ``ARC_FEED``, ``DWELL``,
    ``SET_MOTION_CONTROL_MODE``, ``SET_FEED_RATE``, ``USE_TOOL_LENGTH_OFFSET``; ``see_segment``)."""

    def __init__(self, bl: _Blender):
        self.bl = bl
        self.chain: list[Segment] = []
        self.q = 0.0

    def run(self, segments: Iterable[Segment]) -> Iterator[Segment]:
        for seg in segments:
            q = self.bl.naive(seg.block) if seg.kind in (SegmentKind.LINE, SegmentKind.ARC) else 0.0
            pieces = self._pieces(seg, q) if q > 0 else None
            if pieces is None:
                yield from self.flush()
                yield seg
                continue
            if self.chain and (q != self.q or not self._same(self.chain[-1], pieces[0])):
                yield from self.flush()
            self.q = q
            for p in pieces:
                if self.chain and not self._linkable(p):
                    yield from self.flush()
                self.chain.append(p)
        yield from self.flush()

    def flush(self) -> Iterator[Segment]:
        if len(self.chain) == 1:
            yield self.chain[0]
        elif self.chain:
            yield dataclasses.replace(self.chain[-1], start=self.chain[0].start)
        self.chain = []

    def _same(self, a: Segment, b: Segment) -> bool:
        """No flush between ``a`` and ``b``: one mode entry (a G64/G61 word between them records another, and
        ``SET_MOTION_CONTROL_MODE`` flushes), the same feed, tool length and payloads, and contiguous."""
        same_mode = a.block == b.block or (self.bl._entry(a.block) is self.bl._entry(b.block) if self.bl.table
                                           is not None else True)
        return same_mode and a.end == b.start and a.feed_mm_min == b.feed_mm_min and \
            a.tool_length == b.tool_length and a.extra == b.extra

    def _pieces(self, seg: Segment, q: float) -> list[Segment] | None:
        """The chain points of a motion (as line segments), None when it ends the chain."""
        if any(seg.start[k] != seg.end[k] for k in self.bl.others):
            return None
        if seg.kind is SegmentKind.LINE:
            return [seg]
        if seg.kind is not SegmentKind.ARC or seg.plane is not Plane.XY:
            return None
        i, j, _n = seg.plane_indices()
        sx, sy, ex, ey = (float(seg.start[i]), float(seg.start[j]), float(seg.end[i]), float(seg.end[j]))
        cx, cy = _float_centre(seg)
        th1, th2, r = math.atan2(sy - cy, sx - cx), math.atan2(ey - cy, ex - cx), math.hypot(sy - cy, sx - cx)
        for _ in range(2):  # chord_deviation: the end angle past the start in the arc's sense (turns ignored)
            if seg.clockwise and th2 - th1 >= -1e-5:
                th2 -= 2 * math.pi
            elif not seg.clockwise and th2 - th1 <= 1e-5:
                th2 += 2 * math.pi
        if r * (1 - math.cos(abs(th2 - th1) / 2)) >= q:
            return None
        mid = [(a + b) / 2 for a, b in zip(seg.start, seg.end)]
        mid[i], mid[j] = Fraction(cx + r * math.cos((th1 + th2) / 2)), Fraction(cy + r * math.sin((th1 + th2) / 2))
        half = dataclasses.replace(seg, kind=SegmentKind.LINE, end=tuple(mid), plane=None, centre=None, radius=None,
                                   clockwise=False, turns=0)
        return [half, dataclasses.replace(half, start=tuple(mid), end=seg.end)]

    def _linkable(self, p: Segment) -> bool:
        """``linkable``: the chain's points within q of the line from its start to ``p``'s end."""
        if len(self.chain) > NAIVE_CHAIN - 1:
            return False
        b, x = self.bl.vec(self.chain[0].start), self.bl.vec(p.end)
        m = x - b
        mm = float(np.dot(m, m))
        if mm == 0:
            return False
        for seg in self.chain:
            pt = self.bl.vec(seg.end)
            t0 = min(max(float(np.dot(m, pt - b)) / mm, 0.0), 1.0)
            if float(np.linalg.norm(pt - (b + t0 * m))) > self.q:
                return False
        return True


def blend_motion(segments: Iterable[Segment], machine: Machine, motion: Any = None) -> Iterator[Segment | BlendArc]:
    """The motions the planner runs: motions trimmed at blended corners, and the blend arcs.

    ``motion`` (an interpretation) gives the program's path modes per block (``G61``/``G64 P`` in the
    program); without it every motion runs in the machine's start-up mode.
    """
    bl = _Blender(machine, _mode_table(machine, motion))
    pending: _Pending | None = None
    for seg in _NaiveCam(bl).run(segments):
        if pending is not None:
            joined = bl.corner(pending, seg) if seg.kind is not SegmentKind.DWELL else None
            if joined is not None:
                yield joined[0]
                yield joined[1]
                pending = joined[2]
                continue
            yield bl.piece(pending)
        pending = bl.pending(seg)
    if pending is not None:
        yield bl.piece(pending)


def arc_pulse_positions(arc: BlendArc, pulse: Sequence[Fraction], p0: Sequence[int]) -> np.ndarray:
    """The pulse positions of a blend arc after leaving ``p0`` (shape (steps, axes)): arc points every at most a
    quarter of the finest pulse (floats), rounded to the nearest pulse, consecutive repeats dropped, a gap of
    more than one pulse on an axis filled with single steps (at most one pulse per axis per step)."""
    fine = min(float(u) for u in pulse)
    n = min(max(2, int(math.ceil(arc.radius * arc.sweep / (fine / 4))) + 1), 4_000_000)
    pts = arc.samples(n)
    q = np.rint(pts / np.array([float(u) for u in pulse])).astype(np.int64)
    q = np.vstack([np.array(p0, dtype=np.int64).reshape(1, -1), q])
    keep = np.any(q[1:] != q[:-1], axis=1)
    q = np.vstack([q[:1], q[1:][keep]])
    if len(q) > 1 and int(np.abs(np.diff(q, axis=0)).max()) > 1:
        rows: list[tuple[int, ...]] = []
        for a, b in zip(q[:-1].tolist(), q[1:].tolist()):
            rows.extend(line_steps(a, b))
        return np.array(rows, dtype=np.int64).reshape(-1, q.shape[1])
    out: np.ndarray = q[1:]
    return out
