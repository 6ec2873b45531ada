"""Blend arcs next to circular arcs, as LinuxCNC's planner makes them (line–arc, arc–line, arc–arc).

Written from LinuxCNC ``v2.9.0-pre1`` (the version of the installed ``rs274``), ``src/emc/tp/tp.c``
(``tpCreateLineArcBlend``, ``tpCreateArcLineBlend``, ``tpCreateArcArcBlend``), ``src/emc/tp/blendmath.c``
(``blendInit3FromLineArc`` / ``ArcLine`` / ``ArcArc``, ``blendComputeParameters``, ``blendFindPoints3``,
``blendLineArcPostProcess`` / ``ArcLine`` / ``ArcArc``, ``checkTangentAngle``), ``src/emc/tp/tc.c``
(``pmCircleTangentVector``, ``tcFindBlendTolerance``) and ``src/libnml/posemath/_posemath.c``
(``pmCircleInit``, ``pmCirclePoint``, ``pmCircleStretch``, ``pmCartLineStretch``).  Floats, as the planner;
the controller rounds every point to whole pulses.  It is the controller's own geometry: the prover's
enclosure (``nczones.prover.blend``) is not used.

The planner approximates an arc at the corner by a line (its tangent, or for a *convex* corner the secant to
the point ``phi_max / 2`` along it) to size the blend with ``blendComputeParameters``, then fits the exact
circle tangent to the motion and the arc (the post-processing), and gives up (``TP_ERR_FAIL``: the corner
then gets a parabolic blend or a tangent join, ``tpChooseBestBlend``) when the fit is off tolerance, trims
more than ``phi_max`` of an arc, or the two motions are not in one plane.  ``phi_max`` is a third of the
next arc's sweep and two thirds of what is left of the previous arc's (``blendInit3FromArcLine``), no more
than ``theta`` (convex) or a quarter turn (concave).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

__all__ = ["BLEND_DIST_FRACTION", "TOLERANCE_RATIO", "ACC_RATIO_NORMAL", "TP_ANGLE_EPSILON", "TP_POS_EPSILON",
           "TP_MIN_ARC_LENGTH", "CYCLE_TIME_S", "Circle", "Corner", "Kinematics", "Params", "compute_parameters",
           "inscribed_diameter", "line_limits", "unit", "blend_tolerance", "line_arc", "arc_line", "arc_arc"]

#: ``BLEND_DIST_FRACTION`` (tc_types.h): how much of each straight motion a blend arc may use.
BLEND_DIST_FRACTION = 0.5
#: ``tcFindBlendTolerance``'s ``tolerance_ratio``.
TOLERANCE_RATIO = 0.25
#: ``BLEND_ACC_RATIO_NORMAL`` (blendmath.h): the share of the acceleration for the arc's normal acceleration.
ACC_RATIO_NORMAL = math.sqrt(1.0 - 0.5**2)
#: ``BLEND_KINK_FACTOR`` (blendmath.h), for ``findMaxTangentAngle``.
BLEND_KINK_FACTOR = 0.25
TP_ANGLE_EPSILON = 1e-6
TP_POS_EPSILON = 1e-12
TP_MIN_ARC_LENGTH = 1e-6
#: ``ARC_MIN_RADIUS``, ``ARC_MIN_ANGLE`` (spherical_arc.h), ``DOUBLE_FUZZ`` (posemath.h).
ARC_MIN_RADIUS = 1e-12
ARC_MIN_ANGLE = 1e-6
DOUBLE_FUZZ = 2.2204460492503131e-16
#: The planner's cycle time (``tp->cycleTime``): LinuxCNC's default servo period, 1 ms; it enters only the
#: tangent check of the arc blends (``findMaxTangentAngle``).
CYCLE_TIME_S = 0.001


def unit(v: np.ndarray) -> tuple[np.ndarray, float]:
    n = float(np.linalg.norm(v))
    return (v / n if n > 0 else v), n


def inscribed_diameter(binormal: np.ndarray, bounds: Sequence[float]) -> float:
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


def line_limits(u: np.ndarray, vel: Sequence[float], acc: Sequence[float]) -> tuple[float, float]:
    """The maximum velocity and acceleration along direction ``u`` (no axis beyond its own)."""
    v = min((vel[k] / abs(u[k]) for k in range(3) if abs(u[k]) > 1e-15), default=math.inf)
    a = min((acc[k] / abs(u[k]) for k in range(3) if abs(u[k]) > 1e-15), default=math.inf)
    return v, a


def blend_tolerance(tol: float, n_prev: float, n_next: float) -> float:
    """``tcFindBlendTolerance``: ``min(T1, T2, L_prev / 4, L_next / 4)``, ``T = p`` or a quarter of the length."""
    t1 = tol if tol > 0 else n_prev * TOLERANCE_RATIO
    t2 = tol if tol > 0 else n_next * TOLERANCE_RATIO
    return min(t1, t2, n_prev * TOLERANCE_RATIO, n_next * TOLERANCE_RATIO)


@dataclass(frozen=True, slots=True)
class Params:
    d_plan: float
    r_plan: float
    v_plan: float
    theta: float
    a_max: float = 0.0


def compute_parameters(theta: float, l1: float, l2: float, tolerance: float, a_max: float,
                       v_goal: float) -> Params | None:
    """``blendComputeParameters`` (the trapezoidal planner): None when the arc is too small."""
    phi = math.pi - 2 * theta
    a_n = a_max * ACC_RATIO_NORMAL
    h_tol = tolerance / (1.0 - math.sin(theta))
    d_tol = math.cos(theta) * h_tol
    d_geom = min(l1, l2, d_tol)
    r_geom = math.tan(theta) * d_geom
    v_plan = min(math.sqrt(max(a_n * r_geom, 0.0)), v_goal)
    a_par = a_max * 0.5
    if a_par <= 0 or a_n <= 0 or phi <= 0:
        return None
    t_blend = min(math.sqrt(max(2.0 * a_par * d_geom, 0.0)), v_plan) / a_par
    r_blend = min(t_blend * v_plan / phi, r_geom)
    r_plan = max(v_plan**2 / a_n, r_blend)
    if r_plan < TP_POS_EPSILON or r_plan * phi < TP_MIN_ARC_LENGTH:
        return None
    return Params(r_plan / math.tan(theta), r_plan, v_plan, theta, a_max)


@dataclass(frozen=True, slots=True)
class Circle:
    """posemath's ``PmCircle`` (X, Y, Z): ``point(angle)`` as ``pmCirclePoint`` (a spiral's radius grows linearly
    with the angle, a helix's axis moves linearly)."""

    center: np.ndarray
    normal: np.ndarray
    r_tan: np.ndarray
    r_perp: np.ndarray
    r_helix: np.ndarray
    radius: float
    angle: float
    spiral: float

    @staticmethod
    def init(start: np.ndarray, end: np.ndarray, center: np.ndarray, normal: np.ndarray, angle: float) -> Circle:
        """``pmCircleInit`` with the sweep given (the controller's own, turns included)."""
        v = start - center
        c = center + normal * float(np.dot(v, normal))
        r_tan = start - c
        radius = float(np.linalg.norm(r_tan))
        rel = end - c
        r_end = rel - normal * float(np.dot(rel, normal))
        return Circle(c, normal, r_tan, np.cross(normal, r_tan), rel - r_end, radius, angle,
                      float(np.linalg.norm(r_end)) - radius)

    def point(self, angle: float) -> np.ndarray:
        p = self.r_tan * math.cos(angle) + self.r_perp * math.sin(angle)
        scale = angle / self.angle
        u, _ = unit(p)
        out: np.ndarray = self.center + p + u * (scale * self.spiral) + self.r_helix * scale
        return out

    def points(self, angles: np.ndarray) -> np.ndarray:
        """``point`` at many angles (shape (n, 3))."""
        a = angles[:, None]
        p = self.r_tan * np.cos(a) + self.r_perp * np.sin(a)
        n = np.linalg.norm(p, axis=1)[:, None]
        scale = a / self.angle
        out: np.ndarray = self.center + p + p / np.where(n > 0, n, 1.0) * (scale * self.spiral) + self.r_helix * scale
        return out

    def tangent(self, angle: float) -> np.ndarray:
        """``pmCircleTangentVector``."""
        r = self.point(angle) - self.center
        u_r, _ = unit(r)
        t = np.cross(self.normal, r) + self.r_helix / self.angle + u_r * (self.spiral / self.angle)
        return unit(t)[0]

    def length(self) -> float:
        """The planar length (the spiral's, to first order) with the helix: ``pmCircle9Target``."""
        planar = self.angle * (self.radius + self.spiral / 2)
        return math.sqrt(planar**2 + float(np.dot(self.r_helix, self.r_helix)))

    def helix(self) -> bool:
        return float(np.dot(self.r_helix, self.r_helix)) > 1e-6

    def stretch(self, new_angle: float, from_end: bool) -> Circle | None:
        """``pmCircleStretch``: keep ``new_angle`` of the sweep, at the end (``from_end``) or the start."""
        if new_angle <= DOUBLE_FUZZ or self.helix():
            return None
        c = self
        if from_end:
            p = self.point(self.angle - new_angle)
            r_tan = p - self.center
            c = replace(self, r_tan=r_tan, r_perp=np.cross(self.normal, r_tan), radius=float(np.linalg.norm(r_tan)))
        return replace(c, spiral=self.spiral * new_angle / self.angle, angle=new_angle)

    def spiral_fit(self, base: np.ndarray, u_tan: np.ndarray) -> tuple[np.ndarray, float]:
        """``findSpiralApproximation``: the centre moved along the tangent by the spiral rate, and the radius."""
        c = self.center + u_tan * (self.spiral / self.angle)
        return c, float(np.linalg.norm(base - c))


@dataclass(frozen=True, slots=True)
class Kinematics:
    """The machine's X/Y/Z velocity and acceleration bounds, and the two motions' requested speeds (mm/s) and
    own velocity limits (``tc->maxvel``)."""

    vel: Sequence[float]
    acc: Sequence[float]
    v_req: tuple[float, float]
    v_max: tuple[float, float]


@dataclass(frozen=True, slots=True)
class Corner:
    """A blend next to an arc: the previous motion's new end (``trim1``: length of a line, angle of an arc), the
    next motion's new start (``trim2``), the blend arc (``start``, ``end``, ``centre``, ``radius``, ``sweep``)
    and its speed; ``circle1``/``circle2``: the arcs trimmed (None for a line)."""

    trim1: float
    trim2: float
    start: np.ndarray
    end: np.ndarray
    centre: np.ndarray
    radius: float
    sweep: float
    v_plan: float
    circle1: Circle | None
    circle2: Circle | None


def _colinear(u1: np.ndarray, u2: np.ndarray) -> bool:
    """``pmUnitCartsColinear``: parallel or anti-parallel within ``TP_ANGLE_EPSILON``."""
    eps = TP_ANGLE_EPSILON**2
    return float(np.dot(u1 - u2, u1 - u2)) < eps or float(np.dot(u1 + u2, u1 + u2)) < eps


def _geom(u_tan1: np.ndarray, u_tan2: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """``blendGeom3Init`` + ``blendCalculateNormals3``: (theta_tan, binormal, normal), None when refused."""
    dot = max(-1.0, min(1.0, float(np.dot(u_tan1, u_tan2))))
    theta = math.acos(-dot) / 2.0
    if math.pi / 2 - theta < TP_ANGLE_EPSILON or theta < TP_ANGLE_EPSILON:
        return None
    binormal, bn = unit(np.cross(u_tan1, u_tan2))
    normal, nn = unit(u_tan2 - u_tan1)
    if bn == 0 or nn == 0:
        return None
    return theta, binormal, normal


def _v_goal(binormal: np.ndarray, kin: Kinematics) -> float:
    """``blendParamKinematics``' ``v_goal`` with an arc (no "altitude" velocity; feed override 1)."""
    v_goal = max(min(kin.v_req[0], kin.v_max[0]), min(kin.v_req[1], kin.v_max[1]))
    return min(v_goal, inscribed_diameter(binormal, kin.vel))


def _convex(center: np.ndarray, p: np.ndarray, u: np.ndarray, reverse: bool) -> bool:
    """``arcConvexTest``."""
    return reverse ^ (float(np.dot(p - center, u)) < 0)


def _secant(theta: float, theta_tan: float, phi_max: float) -> float:
    """A convex arc's secant approximation reduces theta (``blendInit3From*``)."""
    return min(theta, theta_tan - phi_max / 4.0)


def _trim_angle(p: np.ndarray, arc_center: np.ndarray, center: np.ndarray) -> float:
    """``findTrimAngle``."""
    u_p, _ = unit(p - center)
    u_c, _ = unit(arc_center - center)
    return math.acos(max(-1.0, min(1.0, float(np.dot(u_p, u_c)))))


def _line_fit(p: np.ndarray, u: np.ndarray, binormal: np.ndarray, center: np.ndarray, radius: float, convex: bool,
              r_plan: float, sign: float) -> tuple[float, np.ndarray] | None:
    """``blendLineArcPostProcess`` / ``blendArcLinePostProcess``: the blend arc's centre ``r_plan`` from the line
    (direction ``u`` from P, ``sign`` -1 when the line ends at P) and ``d`` from the circle's centre."""
    d = (-r_plan if convex else r_plan) + radius
    n, _ = unit(np.cross(binormal, u))
    r_pc = center - p
    c_u, c_n = float(np.dot(r_pc, u)) * -sign, float(np.dot(r_pc, n))
    b, c = 2.0 * c_u, c_u**2 - d**2 + (r_plan - c_n) ** 2
    disc = b * b - 4.0 * c
    if disc < 0:
        return None
    t = math.sqrt(disc)
    d_l = min(abs((-b + t) / 2.0), abs((-b - t) / 2.0))
    return d_l, p + u * (sign * d_l) + n * r_plan


def _arc_fit(p: np.ndarray, normal: np.ndarray, binormal: np.ndarray, c1: np.ndarray, r1: float, convex1: bool,
             c2: np.ndarray, r2: float, convex2: bool, r_plan: float) -> np.ndarray | None:
    """``blendArcArcPostProcess``: the centre at ``d1`` from C1 and ``d2`` from C2, on the side of the corner."""
    d1 = (-r_plan if convex1 else r_plan) + r1
    d2 = (-r_plan if convex2 else r_plan) + r2
    uc, c2x = unit(c2 - c1)
    if c2x == 0:
        return None
    cx = (-(d1**2) + d2**2 - c2x**2) / (-2.0 * c2x)
    cy = math.sqrt(max(d1**2 - cx**2, 0.0))
    nc = np.cross(binormal, uc)
    if float(np.dot(normal, nc)) < 0:
        nc = -nc
    nc, nn = unit(nc)
    if nn == 0:
        return None
    r_pc1 = c1 - p
    c_y = nc * cy
    if np.linalg.norm(r_pc1 + uc * cx - c_y) < np.linalg.norm(r_pc1 + uc * cx + c_y):
        c_y = -c_y
    out: np.ndarray = c1 + uc * cx + c_y
    return out


def _blend_arc(start: np.ndarray, end: np.ndarray, centre: np.ndarray) -> tuple[float, float] | None:
    """``arcInitFromPoints``: (radius, sweep), None for a degenerate arc."""
    r0, r1 = float(np.linalg.norm(start - centre)), float(np.linalg.norm(end - centre))
    if r0 < ARC_MIN_RADIUS or r1 < ARC_MIN_RADIUS:
        return None
    dot = max(-1.0, min(1.0, float(np.dot((start - centre) / r0, (end - centre) / r1))))
    sweep = math.acos(dot)
    return (r0, sweep) if sweep >= ARC_MIN_ANGLE else None


def _tangent_ok(circ_tan: np.ndarray, arc_r: np.ndarray, binormal: np.ndarray, p: Params) -> bool:
    """``checkTangentAngle``: the blend arc's tangent (binormal x radius) meets the circle's within
    ``findMaxTangentAngle``."""
    u_arc, _ = unit(np.cross(binormal, arc_r))
    angle = math.acos(max(-1.0, min(1.0, float(np.dot(circ_tan, u_arc)))))
    dx = p.v_plan / CYCLE_TIME_S
    limit = ACC_RATIO_NORMAL * BLEND_KINK_FACTOR * p.a_max / dx if dx > 0 else TP_ANGLE_EPSILON
    return angle <= limit


def line_arc(p0: np.ndarray, pc: np.ndarray, target: float, nominal: float, circ: Circle, tol: float,
             kin: Kinematics) -> Corner | None:
    """``tpCreateLineArcBlend``: the line ``p0 -> pc`` (``target`` left of ``nominal``), then ``circ``."""
    u_tan1, _ = unit(pc - p0)
    u_tan2 = circ.tangent(0.0)
    g = _geom(u_tan1, u_tan2)
    if g is None or circ.helix():
        return None
    theta_tan, binormal, normal = g
    c2, r2 = circ.spiral_fit(pc, u_tan2)
    convex2 = _convex(c2, pc, u_tan1, True)
    phi2_max = min(circ.angle / 3.0, theta_tan if convex2 else math.pi / 2)
    theta = _secant(theta_tan, theta_tan, phi2_max) if convex2 else theta_tan
    l1 = min(target, nominal / 2.0)
    l2 = math.sin(phi2_max / 4.0) * r2 if convex2 else phi2_max * r2
    if not _colinear(binormal, circ.normal):
        return None
    a_max = inscribed_diameter(binormal, kin.acc)
    tolerance = blend_tolerance(tol, nominal, circ.length())
    prm = compute_parameters(theta, l1, l2, tolerance, a_max, _v_goal(binormal, kin))
    if prm is None:
        return None
    fit = _line_fit(pc, u_tan1, binormal, c2, r2, convex2, prm.r_plan, -1.0)
    if fit is None or float(np.linalg.norm(fit[1] - pc)) - prm.r_plan > tolerance:
        return None
    trim1, centre = fit
    trim2 = _trim_angle(pc, centre, c2)
    if trim2 > phi2_max or target - trim1 <= DOUBLE_FUZZ:
        return None
    circ2 = circ.stretch(circ.angle - trim2, True)
    if circ2 is None:
        return None
    start, end = p0 + u_tan1 * (target - trim1), circ2.point(0.0)
    arc = _blend_arc(start, end, centre)
    if arc is None or not _tangent_ok(circ2.tangent(0.0), end - centre, binormal, prm):
        return None
    return Corner(trim1, trim2, start, end, centre, arc[0], arc[1], prm.v_plan, None, circ2)


def arc_line(circ: Circle, nominal: float, pc: np.ndarray, p1: np.ndarray, tol: float,
             kin: Kinematics) -> Corner | None:
    """``tpCreateArcLineBlend``: ``circ`` (what is left of it, of ``nominal`` programmed length), then the
    line ``pc -> p1``."""
    u_tan1 = circ.tangent(circ.angle)
    u_tan2, n2 = unit(p1 - pc)
    g = _geom(u_tan1, u_tan2)
    if g is None or circ.helix():
        return None
    theta_tan, binormal, normal = g
    c1, r1 = circ.spiral_fit(pc, u_tan1)
    convex1 = _convex(c1, pc, u_tan2, False)
    phi1_max = min(circ.angle * 2.0 / 3.0, theta_tan if convex1 else math.pi / 2)
    theta = theta_tan
    if convex1:
        theta = _secant(theta, theta_tan, phi1_max)
    l1 = math.sin(phi1_max / 4.0) * r1 if convex1 else phi1_max * r1
    l2 = n2 / 2.0
    if not _colinear(binormal, circ.normal):
        return None
    a_max = inscribed_diameter(binormal, kin.acc)
    tolerance = blend_tolerance(tol, nominal, n2)
    prm = compute_parameters(theta, l1, l2, tolerance, a_max, _v_goal(binormal, kin))
    if prm is None:
        return None
    fit = _line_fit(pc, u_tan2, binormal, c1, r1, convex1, prm.r_plan, 1.0)
    if fit is None or float(np.linalg.norm(fit[1] - pc)) - prm.r_plan > tolerance:
        return None
    trim2, centre = fit
    trim1 = _trim_angle(pc, centre, c1)
    if trim1 > phi1_max or n2 - trim2 <= DOUBLE_FUZZ:
        return None
    circ1 = circ.stretch(circ.angle - trim1, False)
    if circ1 is None:
        return None
    start, end = circ1.point(circ1.angle), pc + u_tan2 * trim2
    arc = _blend_arc(start, end, centre)
    if arc is None or not _tangent_ok(circ1.tangent(circ1.angle), start - centre, binormal, prm):
        return None
    return Corner(trim1, trim2, start, end, centre, arc[0], arc[1], prm.v_plan, circ1, None)


def arc_arc(circ1: Circle, nominal: float, circ2: Circle, tol: float, kin: Kinematics) -> Corner | None:
    """``tpCreateArcArcBlend``: ``circ1`` (what is left of it, of ``nominal`` programmed length), then
    ``circ2``."""
    if not _colinear(circ1.normal, circ2.normal) or circ1.helix() or circ2.helix():
        return None
    u_tan1, u_tan2 = circ1.tangent(circ1.angle), circ2.tangent(0.0)
    g = _geom(u_tan1, u_tan2)
    if g is None:
        return None
    theta_tan, binormal, normal = g
    pc = circ2.point(0.0)
    c1, r1 = circ1.spiral_fit(pc, u_tan1)
    c2, r2 = circ2.spiral_fit(pc, u_tan2)
    convex1, convex2 = _convex(c1, pc, u_tan2, False), _convex(c2, pc, u_tan1, True)
    phi1_max = min(circ1.angle * 2.0 / 3.0, theta_tan if convex1 else math.pi / 2)
    phi2_max = min(circ2.angle / 3.0, theta_tan if convex2 else math.pi / 2)
    theta = theta_tan
    if convex1:
        theta = _secant(theta, theta_tan, phi1_max)
    if convex2:
        theta = _secant(theta, theta_tan, phi2_max)
    if theta < math.pi / 12.0:
        return None
    l1 = math.sin(phi1_max / 4.0) * r1 if convex1 else phi1_max * r1
    l2 = math.sin(phi2_max / 4.0) * r2 if convex2 else phi2_max * r2
    if not (_colinear(binormal, circ1.normal) and _colinear(binormal, circ2.normal)):
        return None
    a_max = inscribed_diameter(binormal, kin.acc)
    tolerance = blend_tolerance(tol, nominal, circ2.length())
    prm = compute_parameters(theta, l1, l2, tolerance, a_max, _v_goal(binormal, kin))
    if prm is None:
        return None
    centre = _arc_fit(pc, normal, binormal, c1, r1, convex1, c2, r2, convex2, prm.r_plan)
    if centre is None or float(np.linalg.norm(centre - pc)) - prm.r_plan > tolerance:
        return None
    trim1, trim2 = _trim_angle(pc, centre, c1), _trim_angle(pc, centre, c2)
    if trim1 > phi1_max or trim2 > phi2_max:
        return None
    a1, a2 = circ1.stretch(circ1.angle - trim1, False), circ2.stretch(circ2.angle - trim2, True)
    if a1 is None or a2 is None:
        return None
    start, end = a1.point(a1.angle), a2.point(0.0)
    arc = _blend_arc(start, end, centre)
    if (arc is None or not _tangent_ok(a1.tangent(a1.angle), start - centre, binormal, prm)
            or not _tangent_ok(a2.tangent(0.0), end - centre, binormal, prm)):
        return None
    return Corner(trim1, trim2, start, end, centre, arc[0], arc[1], prm.v_plan, a1, a2)
