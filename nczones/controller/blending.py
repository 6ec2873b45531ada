"""Corner blending as LinuxCNC's trajectory planner does it: blend arcs between two straight motions.

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

Only motions of the linear axes X, Y, Z are blended (rotary or UVW motion makes the planner fall back to a
parabolic blend, which this controller does not reproduce: it moves that corner exactly, a path inside the
same enclosure).  Naive-CAM merging (``G64 Q``) is not reproduced either.  Floats decide the geometry; the
controller rounds every arc point to whole pulses.
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
from ..motion import Segment, SegmentKind
from .pulses import line_steps

__all__ = ["BLENDING", "BlendArc", "blend_motion", "blend_parameters", "arc_pulse_positions", "blends"]

#: Values of ``Settings.blending``: ``"auto"`` blends as LinuxCNC when the machine starts in G64, reads
#: LinuxCNC programs and gives every linear axis an acceleration; ``"exact"`` never; ``"linuxcnc"`` always
#: (the accelerations are then required).
BLENDING = ("auto", "exact", "linuxcnc")
#: ``BLEND_DIST_FRACTION`` (tc_types.h): how much of each motion a blend arc may use.
BLEND_DIST_FRACTION = 0.5
#: ``tcFindBlendTolerance``'s ``tolerance_ratio``.
TOLERANCE_RATIO = 0.25
#: ``BLEND_ACC_RATIO_NORMAL`` (blendmath.h): the share of the acceleration for the arc's normal acceleration.
ACC_RATIO_NORMAL = math.sqrt(1.0 - 0.5**2)
TP_ANGLE_EPSILON = 1e-6
TP_POS_EPSILON = 1e-12
TP_MIN_ARC_LENGTH = 1e-6
LINEAR = ("X", "Y", "Z")


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

    def point(self, f: float) -> np.ndarray:
        """The arc point at fraction ``f`` of its sweep."""
        c = np.array(self.centre)
        v0, v1 = np.array(self.start) - c, np.array(self.end) - c
        s = math.sin(self.sweep)
        out: np.ndarray = c + (math.sin((1 - f) * self.sweep) * v0 + math.sin(f * self.sweep) * v1) / s
        return out


@dataclass(frozen=True, slots=True)
class _Params:
    d_plan: float
    r_plan: float
    v_plan: float
    theta: float


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


def _unit(v: np.ndarray) -> tuple[np.ndarray, float]:
    n = float(np.linalg.norm(v))
    return (v / n if n > 0 else v), n


def _inscribed(binormal: np.ndarray, bounds: Sequence[float]) -> float:
    """``calculateInscribedDiameter``: the bound in the plane with normal ``binormal`` (X, Y, Z components)."""
    extents = []
    for k in range(3):
        e = np.zeros(3)
        e[k] = 1.0
        planar = np.abs(e - binormal * binormal[k])
        scale = float(np.linalg.norm(np.maximum(planar, [TP_POS_EPSILON if j == k else 0 for j in range(3)])))
        if bounds[k] != 0:
            extents.append(bounds[k] / scale)
    return min(extents) if extents else 0.0


def _line_limits(u: np.ndarray, vel: Sequence[float], acc: Sequence[float]) -> tuple[float, float]:
    """The maximum velocity and acceleration along direction ``u`` (no axis beyond its own)."""
    v = min((vel[k] / abs(u[k]) for k in range(3) if abs(u[k]) > 1e-15), default=math.inf)
    a = min((acc[k] / abs(u[k]) for k in range(3) if abs(u[k]) > 1e-15), default=math.inf)
    return v, a


def blend_parameters(u1: np.ndarray, u2: np.ndarray, lens: tuple[float, float, float, float], tol: float,
                     vreq: tuple[float, float], vel: Sequence[float], acc: Sequence[float]) -> _Params | None:
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
    t1 = tol if tol > 0 else n_prev * TOLERANCE_RATIO
    t2 = tol if tol > 0 else n_next * TOLERANCE_RATIO
    tolerance = min(t1, t2, n_prev * TOLERANCE_RATIO, n_next * TOLERANCE_RATIO)
    binormal, bn = _unit(np.cross(u1, u2))
    if bn == 0:
        return None
    a_max = _inscribed(binormal, acc)
    a_n = a_max * ACC_RATIO_NORMAL
    v_goal = _velocity_goal(u1, u2, phi, binormal, vreq, vel, acc)
    h_tol = tolerance / (1.0 - math.sin(theta))
    d_tol = math.cos(theta) * h_tol
    d_geom = min(l1, l2, d_tol)
    r_geom = math.tan(theta) * d_geom
    v_plan = min(math.sqrt(a_n * r_geom), v_goal)
    a_par = a_max * 0.5
    t_blend = min(math.sqrt(2.0 * a_par * d_geom), v_plan) / a_par
    r_blend = min(t_blend * v_plan / phi, r_geom)
    r_plan = max(v_plan**2 / a_n, r_blend)
    if r_plan < TP_POS_EPSILON or r_plan * phi < TP_MIN_ARC_LENGTH:
        return None
    return _Params(r_plan / math.tan(theta), r_plan, v_plan, theta)


def _velocity_goal(u1: np.ndarray, u2: np.ndarray, phi: float, binormal: np.ndarray, vreq: tuple[float, float],
                   vel: Sequence[float], acc: Sequence[float]) -> float:
    """``blendParamKinematics``' ``v_goal`` for two lines (feed override 1)."""
    vmax1, _ = _line_limits(u1, vel, acc)
    vmax2, _ = _line_limits(u2, vel, acc)
    v_goal = max(min(vreq[0], vmax1), min(vreq[1], vmax2))
    v_planar = _inscribed(binormal, vel)
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


class _Blender:
    """Turns a stream of segments into trimmed segments and blend arcs."""

    def __init__(self, machine: Machine, table: list[tuple[int, Any]] | None):
        self.machine = machine
        self.table = table
        self.blend0, self.tol0 = _start_mode(machine)
        names = machine.axis_names
        self.xyz = [names.index(a) if a in names else None for a in LINEAR]
        self.others = [k for k, a in enumerate(names) if a not in LINEAR]
        self.vel = [float(machine.axis(a).rapid_mm_min) / 60 if a in names else 0.0 for a in LINEAR]
        self.acc = [float(machine.axis(a).accel_mm_s2 or 0) if a in names else 0.0 for a in LINEAR]
        self.dogleg = machine.rapid_mode is RapidMode.DOGLEG

    def mode(self, block: int) -> tuple[bool, float]:
        """(blends, p) for the motion of ``block`` (the mode it was queued in)."""
        if self.table is None:
            return self.blend0, self.tol0
        i = bisect_right([b for b, _m in self.table], block) - 1
        m = self.table[max(i, 0)][1]
        if m.dialect != "linuxcnc" or not m.blend:
            return False, 0.0
        if m.naive and not m.tolerance:
            return False, 0.0  # G64 Q without P: not reproduced (moved exactly)
        return True, float(m.tolerance or 0)

    def straight(self, seg: Segment) -> bool:
        if seg.kind is SegmentKind.LINE or (seg.kind is SegmentKind.RAPID and not self.dogleg):
            return all(seg.start[k] == seg.end[k] for k in self.others) and seg.start != seg.end
        return False

    def vec(self, p: Sequence[Any]) -> np.ndarray:
        return np.array([float(p[k]) if k is not None else 0.0 for k in self.xyz])

    def speed(self, seg: Segment) -> float:
        if seg.kind is SegmentKind.RAPID or seg.feed_mm_min is None:
            return math.inf
        return float(seg.feed_mm_min) / 60

    def corner(self, a: _Pending, b: Segment) -> tuple[Segment, BlendArc, _Pending] | None:
        blend, tol = self.mode(a.seg.block)
        if not blend or not (self.straight(a.seg) and self.straight(b)) or a.seg.end != b.start:
            return None
        if a.seg.tool_length != b.tool_length or a.seg.extra != b.extra:
            return None
        u1, _ = _unit(self.vec(a.seg.end) - self.vec(a.seg.start))
        u2, lb = _unit(self.vec(b.end) - self.vec(b.start))
        p = blend_parameters(u1, u2, (a.target, a.nominal, lb, lb), tol, (self.speed(a.seg), self.speed(b)),
                             self.vel, self.acc)
        if p is None or p.d_plan >= a.target or p.d_plan >= lb:
            return None
        c = self.vec(a.seg.end)
        normal, _ = _unit(u2 - u1)
        centre = c + normal * (p.r_plan / math.sin(p.theta))
        s, e = c - u1 * p.d_plan, c + u2 * p.d_plan
        s_full, e_full = self._full(a.seg.end, s), self._full(b.start, e)
        a_cut = dataclasses.replace(a.seg, end=s_full)
        arc = BlendArc(a.seg, tuple(map(float, self._full(a.seg.end, s))), tuple(map(float, e_full)),
                       tuple(map(float, self._full(a.seg.end, centre))), p.r_plan, math.pi - 2 * p.theta,
                       p.v_plan, a.seg.end)
        b_cut = dataclasses.replace(b, start=e_full)
        return a_cut, arc, _Pending(b_cut, lb, lb - p.d_plan)

    def _full(self, base: tuple[Fraction, ...], xyz: np.ndarray) -> tuple[Fraction, ...]:
        out = list(base)
        for j, k in enumerate(self.xyz):
            if k is not None:
                out[k] = Fraction(float(xyz[j]))
        return tuple(out)


def _length(seg: Segment) -> float:
    return math.sqrt(sum(float(e - s) ** 2 for s, e in zip(seg.start, seg.end)))


def blend_motion(segments: Iterable[Segment], machine: Machine, motion: Any = None) -> Iterator[Segment | BlendArc]:
    """The motions the planner runs: straight motions trimmed at blended corners, and the blend arcs.

    ``motion`` (an interpretation) gives the program's path modes per block (``G61``/``G64 P`` in the
    program); without it every motion runs in the machine's start-up mode.
    """
    bl = _Blender(machine, _mode_table(machine, motion))
    pending: _Pending | None = None
    for seg in segments:
        if pending is not None:
            joined = bl.corner(pending, seg) if seg.kind is not SegmentKind.DWELL else None
            if joined is not None:
                yield joined[0]
                yield joined[1]
                pending = joined[2]
                continue
            yield pending.seg
        n = _length(seg)
        pending = _Pending(seg, n, n)
    if pending is not None:
        yield pending.seg


def arc_pulse_positions(arc: BlendArc, pulse: Sequence[Fraction], p0: Sequence[int]) -> np.ndarray:
    """The pulse positions of a blend arc after leaving ``p0`` (shape (steps, axes)): arc points every at most a
    quarter of the finest pulse (floats), rounded to the nearest pulse, consecutive repeats dropped, a gap of
    more than one pulse on an axis filled with single steps (at most one pulse per axis per step)."""
    fine = min(float(u) for u in pulse)
    n = min(max(2, int(math.ceil(arc.radius * arc.sweep / (fine / 4))) + 1), 4_000_000)
    f = np.linspace(0.0, 1.0, n)[:, None]
    c = np.array(arc.centre)
    v0, v1 = np.array(arc.start) - c, np.array(arc.end) - c
    pts = c + (np.sin((1 - f) * arc.sweep) * v0 + np.sin(f * arc.sweep) * v1) / math.sin(arc.sweep)
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
