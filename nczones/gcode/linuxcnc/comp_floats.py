"""LinuxCNC's cutter radius compensation of straight moves in doubles: the formulas both the full path
(:mod:`.cutter_comp`) and the double pass (:mod:`.double_comp`) call, so both compute the same doubles.

Each is LinuxCNC's own (``interp_convert.cc`` ``convert_straight_comp1/2``, ``interp_queue.cc``
``move_endpoint_and_flush``), its operations in LinuxCNC's order, on program-frame doubles (no work offset;
inch in G20).  No ``typing`` or ``dataclasses`` import: the double pass is on the verify path's start-up.
"""

from __future__ import annotations

import math

__all__ = ["CONCAVE_TOLERANCE_RAD", "LEFT", "RIGHT", "entry_line", "line_corner", "retreat", "reverses"]

#: LinuxCNC TOLERANCE_CONCAVE_CORNER: turns smaller than this (radians) need no corner arc.
CONCAVE_TOLERANCE_RAD = 0.05
#: The sides (LinuxCNC's LEFT and RIGHT): G41 and G42.
LEFT, RIGHT = 2, 1
_PI = math.pi
_HALF_PI = math.pi / 2


def entry_line(side: int | None, radius: float, cx: float, cy: float, px: float,
               py: float) -> tuple[float, float, float, float] | None:
    """A straight entry move from ``(cx, cy)`` to the programmed ``(px, py)`` (LinuxCNC
    ``convert_straight_comp1``): ``(end_x, end_y, da, db)``, its compensated end and the direction its queued
    move keeps for the gouge test (:func:`reverses`), or None when it is not longer than ``radius`` (GC322).
    Shared by the full path and the double pass (:mod:`.double_comp`): one formula, the same doubles.

    >>> entry_line(LEFT, 1.0, 0.0, 0.0, 10.0, 0.0)[:2]
    (10.0, 1.0)
    """
    if math.hypot(px - cx, py - cy) <= radius:
        return None
    alpha = math.atan2(py - cy, px - cx) + (_PI / 2.0 if side == LEFT else -_PI / 2.0)
    return px + radius * math.cos(alpha), py + radius * math.sin(alpha), math.cos(alpha), math.sin(alpha)


def line_corner(side: int | None, radius: float, cx: float, cy: float, opx: float, opy: float, px: float,
                py: float, front: int) -> tuple[bool, float, float, float, float, float, float, float]:
    """The corner before a straight move from the programmed ``(opx, opy)`` to ``(px, py)``, the tool at
    ``(cx, cy)`` (LinuxCNC ``convert_straight_comp2``): ``(concave, beta, end_x, end_y, mid_x, mid_y, theta,
    gamma)``; ``front`` is the turn of the arc at the queue's front (0: none, or a straight move there).  Convex
    when not concave and ``beta > CONCAVE_TOLERANCE_RAD``; a concave corner's end is :func:`retreat`'s.
    Shared by the full path and the double pass (:mod:`.double_comp`)."""
    small = CONCAVE_TOLERANCE_RAD
    theta = math.atan2(cy - opy, cx - opx)
    alpha = math.atan2(py - opy, px - opx)
    if side == LEFT:
        if theta < alpha:
            theta = theta + 2 * _PI
        beta = (theta - alpha) - _HALF_PI
        gamma = _HALF_PI
    else:
        if alpha < theta:
            alpha = alpha + 2 * _PI
        beta = (alpha - theta) - _HALF_PI
        gamma = -_HALF_PI
    end_x = px + radius * math.cos(alpha + gamma)
    end_y = py + radius * math.sin(alpha + gamma)
    mid_x = opx + radius * math.cos(alpha + gamma)
    mid_y = opy + radius * math.sin(alpha + gamma)
    # the "h" shape (an arc at the front, turning away): stay above and to the side rather than loop around
    concave = beta < -small or beta > _PI + small or (
        beta > _PI - small and ((side == RIGHT and front > 0) or (side == LEFT and front < 0)))
    return concave, beta, end_x, end_y, mid_x, mid_y, theta, gamma


def retreat(radius: float, cx: float, cy: float, beta: float, theta: float,
            gamma: float) -> tuple[float, float] | None:
    """Where the held straight move ends at a concave corner between two straight moves (:func:`line_corner`'s
    values), or None for a zero-degree inside corner (GC324)."""
    halfcorner = (beta + _PI) / 2.0
    if halfcorner == 0.0:
        return None
    back = radius / math.tan(halfcorner)
    return cx + back * math.cos(theta + gamma), cy + back * math.sin(theta + gamma)


def reverses(da: float, db: float, x: float, y: float, ex: float, ey: float) -> bool:
    """Does moving a held straight move of direction ``(da, db)`` to end at ``(x, y)`` instead of ``(ex, ey)``
    reverse it (LinuxCNC ``move_endpoint_and_flush``'s dot product below 0: a gouge)?"""
    return da * (x - ex) + db * (y - ey) < 0
