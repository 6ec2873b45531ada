"""An independent model of LinuxCNC's corner blending between two straight motions (floats), for tests.

Written from LinuxCNC 2.9's trajectory planner (``src/emc/tp/``, tag v2.9.0-pre1), not from nczones:

* :func:`parabolic_blend`: ``tpComputeBlendVelocity`` (blend velocities within the half-segment rule and,
  with a tolerance, ``2 sqrt(a T / cos theta)``), ``tcIsBlending`` (the blend starts on the previous
  motion's final deceleration below its blend velocity), ``tpUpdateBlend`` (the next motion's target
  velocity ``blend_progress * v_b_next * v_start / v_b_this``) and ``tpDoParabolicBlending`` (the position
  is the sum of both motions' displacements), sampled every servo cycle with trapezoidal velocity.
* :func:`blend_arc`: ``blendInit3FromLineLine`` (``L1``, ``L2`` = half of each motion),
  ``tcFindBlendTolerance`` (no tolerance: a quarter of the shorter motion), ``blendComputeParameters``
  (``d_plan``, ``R_plan``) and ``blendFindPoints3`` (the arc tangent to both lines).

Positions are 2-D (the plane of the two motions); the corner is the origin's image ``c``.
"""

from __future__ import annotations

import math


def _unit(v: tuple[float, float]) -> tuple[float, float]:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def blend_velocities(l1: float, l2: float, a1: float, a2: float, v1: float, v2: float, cos_theta: float,
                     tolerance: float) -> tuple[float, float]:
    """``tpComputeBlendVelocity``: (v_blend_this, v_blend_next)."""
    reach1 = min(math.sqrt(a1 * l1), v1)  # tpCalculateTriangleVel: findVPeak(acc, target) of a finalized motion
    reach2 = min(math.sqrt(a2 * l2), v2)
    t_max = min(l1 / reach1, l2 / reach2)
    t_blend = min(t_max, max(reach1 / a1, reach2 / a2))
    vb1 = min(reach1, t_blend * a1)
    vb2 = min(reach2, t_blend * a2)
    if tolerance > 0 and cos_theta > math.cos(math.pi / 2 - 1e-3):
        tv = 2.0 * math.sqrt(a1 * tolerance / cos_theta)
        vb1, vb2 = min(vb1, tv), min(vb2, tv)
    return vb1, vb2


def parabolic_blend(start: tuple[float, float], corner: tuple[float, float], end: tuple[float, float], *,
                    a1: float, a2: float, v1: float, v2: float, tolerance: float = 0.0,
                    dt: float = 0.001) -> list[tuple[float, float]]:
    """The positions, every ``dt``, while the two motions blend (empty when they do not)."""
    d1 = (corner[0] - start[0], corner[1] - start[1])
    d2 = (end[0] - corner[0], end[1] - corner[1])
    l1, l2 = math.hypot(*d1), math.hypot(*d2)
    u1, u2 = _unit(d1), _unit(d2)
    dot = max(-1.0, min(1.0, u1[0] * u2[0] + u1[1] * u2[1]))
    theta = math.acos(-dot) / 2.0  # findIntersectionAngle
    vb1, vb2 = blend_velocities(l1, l2, a1, a2, v1, v2, math.cos(theta), tolerance)
    # the previous motion: trapezoidal, to a stop at its end (a parabolic blend's final velocity is 0)
    s, v = 0.0, 0.0
    blending, v_start = False, 0.0
    t2, w2 = 0.0, 0.0
    out: list[tuple[float, float]] = []
    for _ in range(10_000_000):
        rem = l1 - s
        if rem <= 1e-12:
            break
        v_new = min(v + a1 * dt, v1, math.sqrt(2 * a1 * rem))
        decel = v_new < v
        v = v_new
        s = min(s + v * dt, l1) if v * dt < rem else l1
        if not blending and decel and v < vb1:
            blending, v_start = True, v
        if blending:
            progress = max(0.0, min(1.0, (v_start - v) / max(v_start, 1e-12)))
            target = progress * vb2 * (v_start / vb1)
            w2 = min(w2 + a2 * dt, target)
            t2 = min(t2 + w2 * dt, l2)
            rem = l1 - s
            out.append((corner[0] - rem * u1[0] + t2 * u2[0], corner[1] - rem * u1[1] + t2 * u2[1]))
    return out


def blend_arc(start: tuple[float, float], corner: tuple[float, float], end: tuple[float, float], *,
              a_max: float, v_goal: float, tolerance: float = 0.0, samples: int = 64) -> list[tuple[float, float]]:
    """Points of the blend arc the planner would insert (empty when it would not)."""
    d1 = (corner[0] - start[0], corner[1] - start[1])
    d2 = (end[0] - corner[0], end[1] - corner[1])
    l1, l2 = math.hypot(*d1), math.hypot(*d2)
    u1, u2 = _unit(d1), _unit(d2)
    dot = max(-1.0, min(1.0, u1[0] * u2[0] + u1[1] * u2[1]))
    theta = math.acos(-dot) / 2.0
    if math.pi / 2 - theta < 1e-6 or theta < 1e-6:  # blendGeom3Init: TP_ERR_TOLERANCE
        return []
    t1 = tolerance if tolerance > 0 else l1 * 0.25
    t2 = tolerance if tolerance > 0 else l2 * 0.25
    tol = min(t1, t2, l1 * 0.25, l2 * 0.25)  # tcFindBlendTolerance
    big_l1, big_l2 = l1 * 0.5, l2 * 0.5  # BLEND_DIST_FRACTION
    h_tol = tol / (1.0 - math.sin(theta))
    d_tol = math.cos(theta) * h_tol
    d_geom = min(big_l1, big_l2, d_tol)
    r_geom = math.tan(theta) * d_geom
    a_n = a_max * math.sqrt(1 - 0.25)  # BLEND_ACC_RATIO_NORMAL
    v_plan = min(math.sqrt(a_n * r_geom), v_goal)
    a_par = a_max * 0.5
    v_tri = math.sqrt(2.0 * a_par * d_geom)
    t_blend = min(v_tri, v_plan) / a_par
    s_blend = t_blend * v_plan
    phi = math.pi - 2 * theta
    r_blend = min(s_blend / phi, r_geom)
    r_plan = max(v_plan ** 2 / a_n, r_blend)
    d_plan = r_plan / math.tan(theta)
    # blendFindPoints3: centre along the normal u2 - u1, at R / sin(theta) from the corner
    n = _unit((u2[0] - u1[0], u2[1] - u1[1]))
    cd = r_plan / math.sin(theta)
    centre = (corner[0] + n[0] * cd, corner[1] + n[1] * cd)
    p0 = (corner[0] - u1[0] * d_plan, corner[1] - u1[1] * d_plan)
    p1 = (corner[0] + u2[0] * d_plan, corner[1] + u2[1] * d_plan)
    a0 = math.atan2(p0[1] - centre[1], p0[0] - centre[0])
    a1 = math.atan2(p1[1] - centre[1], p1[0] - centre[0])
    sweep = (a1 - a0 + math.pi) % (2 * math.pi) - math.pi  # the short way round (less than half a turn)
    return [(centre[0] + r_plan * math.cos(a0 + sweep * k / samples),
             centre[1] + r_plan * math.sin(a0 + sweep * k / samples)) for k in range(samples + 1)]


def naive_cam(start: tuple[float, float], points: list[tuple[float, float]], q: float) -> list[tuple[float, float]]:
    """The vertices of the lines LinuxCNC's naive CAM sends the planner for the straight feeds from ``start``
    through ``points`` (``emccanon.cc`` ``see_segment`` / ``linkable`` / ``flush_segments``, v2.9.0-pre1): a point
    joins the chain while the chain has at most 100 points, it is not the chain's start, and every chained point
    lies within ``q`` of the line from the chain's start to it; otherwise the chain is sent as one line."""
    out = [start]
    chain: list[tuple[float, float]] = []
    end = start

    def linkable(p: tuple[float, float]) -> bool:
        if q == 0 or len(chain) > 100 or p == end:
            return False
        mx, my = p[0] - end[0], p[1] - end[1]
        mm = mx * mx + my * my
        for c in chain:
            t = max(0.0, min(1.0, ((c[0] - end[0]) * mx + (c[1] - end[1]) * my) / mm))
            if math.hypot(c[0] - end[0] - t * mx, c[1] - end[1] - t * my) > q:
                return False
        return True

    for p in points:
        if chain and not linkable(p):
            end = chain[-1]
            out.append(end)
            chain = []
        chain.append(p)
    if chain:
        out.append(chain[-1])
    return out
