"""LinuxCNC's cutter radius compensation of straight moves in doubles: the formulas both the full path
(:mod:`.cutter_comp`) and the double pass (:mod:`.double_comp`) call, so both compute the same doubles.

Each is LinuxCNC's own (``interp_convert.cc`` ``convert_straight_comp1/2``, ``interp_queue.cc``
``move_endpoint_and_flush``), its operations in LinuxCNC's order, on program-frame doubles (no work offset;
inch in G20).  No ``typing`` or ``dataclasses`` import: the double pass is on the verify path's start-up.
"""

from __future__ import annotations

import math

__all__ = ["CONCAVE_TOLERANCE_RAD", "LEFT", "RIGHT", "arc_arc_back", "arc_centre_r", "arc_corner", "arc_entry",
           "arc_line_back", "arc_moved", "entry_line", "find_turn", "inside", "line_arc_back", "line_corner", "retreat",
           "reverses"]

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
    dx = radius * math.cos(alpha + gamma)  # (LinuxCNC computes each twice: the same doubles)
    dy = radius * math.sin(alpha + gamma)
    end_x = px + dx
    end_y = py + dy
    mid_x = opx + dx
    mid_y = opy + dy
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


# -- arcs (``convert_arc_comp1/2``, ``interp_queue.cc``): shared by the full path and the double pass ----------

#: The errors of the arc formulas below (the full path's codes and messages, :mod:`.cutter_comp`; the double
#: pass declines on any): an entry arc not longer than the radius (GC322), a tool radius not less than the arc
#: radius (GC323), an entry arc whose cosine is about 0 (GC323), LinuxCNC's "bug" of an entry arc's radii
#: (GC329), two arcs of the same centre (GC324), a corner the tool cannot fit in (GC324).
ENTRY_SHORT, RADIUS, ENTRY_COS, SPIRAL, SAME_CENTRE, GOUGE = 1, 2, 3, 4, 5, 6
_TOLERANCE_EQUAL = 1e-6


def find_turn(x1: float, y1: float, cx: float, cy: float, turn: int, x2: float, y2: float) -> float:
    """Signed sweep (radians) of an arc from (x1, y1) to (x2, y2) around (cx, cy) (LinuxCNC ``find_turn``).

    >>> round(find_turn(1.0, 0.0, 0.0, 0.0, 1, 0.0, 1.0), 9), round(find_turn(1.0, 0.0, 0.0, 0.0, -1, 0.0, 1.0), 9)
    (1.570796327, -4.71238898)
    """
    if turn == 0:
        return 0.0
    alpha = math.atan2(y1 - cy, x1 - cx)
    beta = math.atan2(y2 - cy, x2 - cx)
    if turn > 0:
        if beta <= alpha:
            beta = beta + 2 * _PI
        return (beta - alpha) + (turn - 1) * (2 * _PI)
    if alpha <= beta:
        alpha = alpha + 2 * _PI
    return (beta - alpha) + (turn + 1) * (2 * _PI)


def inside(side: int | None, turn: int) -> bool:
    """LinuxCNC TOOL_INSIDE_ARC: the tool is on the centre's side of the arc."""
    return (side == LEFT and turn > 0) or (side == RIGHT and turn < 0)


def arc_centre_r(opx: float, opy: float, ex: float, ey: float, radius: float, cw: bool,
                 tolerance: float) -> tuple[float, float] | None:
    """Centre of an R-format arc in doubles (LinuxCNC ``arc_data_r``); None if R cannot reach.

    >>> arc_centre_r(0.0, 0.0, 2.0, 0.0, 1.0, False, 0.001)
    (1.0, 6.123233995736766e-17)
    """
    abs_radius = abs(radius)
    mx, my = (ex + opx) / 2.0, (ey + opy) / 2.0
    half = math.hypot(mx - ex, my - ey)
    if half - abs_radius > tolerance:
        return None
    if half / abs_radius > 1 - 1e-12:
        half = abs_radius
    if (cw and radius > 0) or (not cw and radius < 0):
        theta = math.atan2(ey - opy, ex - opx) - _HALF_PI
    else:
        theta = math.atan2(ey - opy, ex - opx) + _HALF_PI
    turn2 = math.asin(half / abs_radius)
    offset = abs_radius * math.cos(turn2)
    return mx + offset * math.cos(theta), my + offset * math.sin(theta)


def arc_entry(side: int | None, tool_radius: float, cx: float, cy: float, end_x: float, end_y: float,
              center_x: float, center_y: float, cw: bool, turn: int, arc_radius: float,
              inch: bool) -> int | tuple[float, float, float, float]:
    """An entry arc from the tool at ``(cx, cy)`` to the programmed ``(end_x, end_y)`` about the programmed
    centre (LinuxCNC ``convert_arc_comp1``; ``arc_radius``: ``|R|`` or the start's radius): ``(end_x, end_y,
    center_x, center_y)`` compensated (the centre moved so that both ends are on its circle), or an error
    (:data:`ENTRY_SHORT`, :data:`RADIUS`, :data:`ENTRY_COS`, :data:`SPIRAL`)."""
    if math.hypot(end_x - cx, end_y - cy) <= tool_radius:
        return ENTRY_SHORT
    if arc_radius <= tool_radius and ((side == LEFT and not cw) or (side == RIGHT and cw)):
        return RADIUS
    if inside(side, turn):
        gamma = math.atan2(center_y - end_y, center_x - end_x)
    else:
        gamma = math.atan2(end_y - center_y, end_x - center_x)
    end_x += tool_radius * math.cos(gamma)
    end_y += tool_radius * math.sin(gamma)
    b_len = math.hypot(cy - end_y, cx - end_x) / 2.0
    ab_ang = math.atan2(center_y - end_y, center_x - end_x)
    a_ang = math.atan2(cy - end_y, cx - end_x) - ab_ang
    if abs(math.cos(a_ang)) < _TOLERANCE_EQUAL:
        return ENTRY_COS
    c_len = b_len / math.cos(a_ang)
    center_x = end_x + c_len * math.cos(ab_ang)
    center_y = end_y + c_len * math.sin(ab_ang)
    spiral = 2 * (0.001 if inch else 0.01) * math.sqrt(2)
    if abs(math.hypot(center_x - end_x, center_y - end_y) - math.hypot(center_x - cx, center_y - cy)) > spiral:
        return SPIRAL
    return end_x, end_y, center_x, center_y


def arc_corner(side: int | None, tool_radius: float, cx: float, cy: float, opx: float, opy: float, end_x: float,
               end_y: float, centerx: float, centery: float, cw: bool,
               turn: int) -> int | tuple[int, float, float, float, float, float, float]:
    """The corner before an arc after the first move (LinuxCNC ``convert_arc_comp2``): ``(how, new_end_x,
    new_end_y, arc_radius, theta, beta, delta)`` with ``how`` 1 concave, 2 convex (a corner arc to
    ``opx + r cos(delta)``), 0 straight on; or :data:`RADIUS`'s negative (``-RADIUS``, the arc radius not above
    the tool's)."""
    small = CONCAVE_TOLERANCE_RAD
    arc_radius = math.hypot(centerx - end_x, centery - end_y)
    theta = math.atan2(cy - opy, cx - opx)
    theta = theta - _HALF_PI if side == LEFT else theta + _HALF_PI
    delta = math.atan2(centery - opy, centerx - opx)
    alpha = delta - _HALF_PI if not cw else delta + _HALF_PI
    beta = theta - alpha if side == LEFT else alpha - theta
    if beta > 1.5 * _PI:
        beta = beta - 2 * _PI
    elif beta < -_HALF_PI:
        beta = beta + 2 * _PI
    if (side == LEFT and not cw) or (side == RIGHT and cw):
        gamma = math.atan2(centery - end_y, centerx - end_x)
        if arc_radius <= tool_radius:
            return -RADIUS
    else:
        gamma = math.atan2(end_y - centery, end_x - centerx)
        delta = delta + _PI
    new_end_x = end_x + tool_radius * math.cos(gamma)
    new_end_y = end_y + tool_radius * math.sin(gamma)
    if beta < -small or beta > _PI + small or (abs(beta - _PI) < small and not inside(side, turn)):
        how = 1
    elif beta > small:
        how = 2
    else:
        how = 0
    return how, new_end_x, new_end_y, arc_radius, theta, beta, delta


def line_arc_back(side: int | None, tool_radius: float, arc_radius: float, theta: float, beta: float,
                  turn: int, centerx: float, centery: float) -> tuple[float, float] | None:
    """Where a held straight move ends at a concave corner before an arc (:func:`arc_corner`'s values), or
    None: the tool cannot reach it (GC324)."""
    cyy = arc_radius * math.sin(beta - _HALF_PI)
    if inside(side, turn):
        dist_from_center = arc_radius - tool_radius
        lr = (cyy + tool_radius) / dist_from_center
        if lr > 1.0 or lr < -1.0:
            return None
        ang = theta + math.asin(lr) if turn > 0 else theta - math.asin(lr)
    else:
        dist_from_center = arc_radius + tool_radius
        lr = (cyy - tool_radius) / dist_from_center
        if lr > 1.0 or lr < -1.0:
            return None
        ang = theta + _PI - math.asin(lr) if turn > 0 else theta + _PI + math.asin(lr)
    return centerx + dist_from_center * math.cos(ang), centery + dist_from_center * math.sin(ang)


def arc_arc_back(side: int | None, tool_radius: float, arc_radius: float, pa: float, pb: float, pca: float,
                 pcb: float, pturn: int, centerx: float, centery: float, turn: int) -> int | tuple[float, float]:
    """Where a held arc (its compensated end ``(pa, pb)``, centre ``(pca, pcb)``, turn ``pturn``) ends at a
    concave corner before an arc about ``(centerx, centery)``, or :data:`SAME_CENTRE` or :data:`GOUGE`."""
    oldrad = math.hypot(pcb - pb, pca - pa)
    newrad = arc_radius - tool_radius if inside(side, turn) else arc_radius + tool_radius
    arc_cc = math.hypot(pcb - centery, pca - centerx)
    if oldrad == 0 or arc_cc == 0:
        return SAME_CENTRE
    a = (oldrad * oldrad + arc_cc * arc_cc - newrad * newrad) / (2 * oldrad * arc_cc)
    if a > 1.0 or a < -1.0:
        return GOUGE
    pullback = math.acos(a)
    cc_dir = math.atan2(centery - pcb, centerx - pca)
    if inside(side, pturn):
        d = cc_dir + pullback if turn > 0 else cc_dir - pullback
    else:
        d = cc_dir - pullback if turn > 0 else cc_dir + pullback
    return pca + oldrad * math.cos(d), pcb + oldrad * math.sin(d)


def arc_line_back(side: int | None, tool_radius: float, pa: float, pb: float, pca: float, pcb: float, pturn: int,
                  opx: float, opy: float, px: float, py: float) -> tuple[float, float] | None:
    """Where a held arc (as :func:`arc_arc_back`'s) ends at a concave corner before a straight move from the
    programmed ``(opx, opy)`` to ``(px, py)``, or None: the tool cannot fit (GC324)."""
    oldrad = math.hypot(pcb - pb, pca - pa)
    base_dir = math.atan2(py - opy, px - opx)
    th = base_dir + _HALF_PI if pturn > 0 else base_dir - _HALF_PI
    phi = math.atan2(pcb - opy, pca - opx)
    oldrad_uncomp = oldrad + tool_radius if inside(side, pturn) else oldrad - tool_radius
    d = oldrad_uncomp * math.cos(th - phi)
    if inside(side, pturn):
        lr = (d - tool_radius) / oldrad
        if lr > 1.0 or lr < -1.0:
            return None
        ang = (-math.acos(lr) + th + _PI) if pturn > 0 else (math.acos(lr) + th + _PI)
    else:
        lr = (d + tool_radius) / oldrad
        if lr > 1.0 or lr < -1.0:
            return None
        ang = (math.acos(lr) + th + _PI) if pturn > 0 else (-math.acos(lr) + th + _PI)
    return pca + oldrad * math.cos(ang), pcb + oldrad * math.sin(ang)


def arc_moved(a: float, b: float, ca: float, cb: float, turn: int, sweep: float, x: float, y: float, ex: float,
              ey: float, valid: bool, inch: bool) -> int:
    """Moving a held arc's end from ``(a, b)`` to ``(x, y)`` (``interp_queue.cc``, the queue's endpoint
    ``(ex, ey)``): 0, or :data:`SPIRAL` (radii differing by more than 0.01: LinuxCNC's "BUG") or :data:`GOUGE`
    (its sweep grown by more than .0254 in G21, .001 in G20)."""
    r1 = math.hypot(a - ca, b - cb)
    r2 = math.hypot(x - ca, y - cb)
    l2 = find_turn(ex, ey, ca, cb, turn, x, y)
    if abs(r1 - r2) > 0.01:
        return SPIRAL
    if sweep and valid and abs(l2) > abs(sweep) + (0.001 if inch else 0.0254):
        return GOUGE
    return 0
