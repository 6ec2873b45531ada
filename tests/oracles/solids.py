"""An independent oracle for tool solids against fixtures (issue 39): dense sampling of the path, and at each
sample an exact test of "does this part, placed here, meet the fixture's interior".

It shares only the machine file's meaning with the prover (:mod:`nczones.solids`: parts by tool number,
z ranges above the tip or the gauge line, fixtures in machine coordinates, open interiors), not its code:

* the horizontal test is the rounded box written as a union, not as a distance to a clamped point: the
  centre is strictly inside the box grown by ``r`` in X only, or in Y only, or strictly within ``r`` of one
  of its four vertical edges (unbounded sides have no edges); a cylinder is met when the squared centre
  distance is below ``(R + r)²``;
* a polygon prism (a forbidden XY polygon) is met when the centre is in the closed polygon (winding number,
  not the prover's crossing parity) or strictly within ``r`` of an edge (its distance as |cross| / length);
* the heights meet when the open fixture range and the closed part range share an open interval;
* lines are sampled at ``k / n`` (exact rationals), arcs at ``n`` angles in floats (a float sample only
  suggests a hit; the exact lines are what the property tests lean on).
"""

from __future__ import annotations

import math
from fractions import Fraction

from nczones.motion import Segment, SegmentKind, arc_path_float
from nczones.solids import FixtureBox, FixtureCylinder, FixturePrism, Part


def _lt(a, b) -> bool:
    return a is None or b is None or a < b


def _on_edge(a, b, x, y) -> bool:
    cross = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
    dot = (x - a[0]) * (b[0] - a[0]) + (y - a[1]) * (b[1] - a[1])
    return cross == 0 and 0 <= dot <= (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2


def winding(vertices, x, y) -> int:
    """The winding number of the polygon about ``(x, y)`` (not on its boundary)."""
    w = 0
    n = len(vertices)
    for i in range(n):
        a, b = vertices[i], vertices[(i + 1) % n]
        side = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        if a[1] <= y < b[1] and side > 0:
            w += 1
        elif b[1] <= y < a[1] and side < 0:
            w -= 1
    return w


def in_polygon(vertices, x, y, strict: bool) -> bool:
    n = len(vertices)
    if any(_on_edge(vertices[i], vertices[(i + 1) % n], x, y) for i in range(n)):
        return not strict
    return winding(vertices, x, y) != 0


def _edge_closer(a, b, x, y, r) -> bool:
    """Is ``(x, y)`` strictly within ``r`` of the segment ``a b``?"""
    ex, ey = b[0] - a[0], b[1] - a[1]
    e2 = ex * ex + ey * ey
    dot = (x - a[0]) * ex + (y - a[1]) * ey
    if 0 <= dot <= e2:
        cross = ex * (y - a[1]) - ey * (x - a[0])
        return cross * cross < r * r * e2
    return min((x - a[0]) ** 2 + (y - a[1]) ** 2, (x - b[0]) ** 2 + (y - b[1]) ** 2) < r * r


def meets_xy(fx, x, y, r) -> bool:
    """Does the closed disk of radius ``r`` about ``(x, y)`` meet the fixture's open section?"""
    if isinstance(fx, FixturePrism):
        v = fx.vertices
        return in_polygon(v, x, y, False) or any(_edge_closer(v[i], v[(i + 1) % len(v)], x, y, r)
                                                 for i in range(len(v)))
    if isinstance(fx, FixtureCylinder):
        return (x - fx.cx) ** 2 + (y - fx.cy) ** 2 < (fx.radius + r) ** 2
    x0, x1, y0, y1 = fx.x0, fx.x1, fx.y0, fx.y1
    grown_x = _lt(x0 - r if x0 is not None else None, x) and _lt(x, x1 + r if x1 is not None else None) \
        and _lt(y0, y) and _lt(y, y1)
    grown_y = _lt(x0, x) and _lt(x, x1) and _lt(y0 - r if y0 is not None else None, y) \
        and _lt(y, y1 + r if y1 is not None else None)
    if grown_x or grown_y:
        return True
    for ex in (x0, x1):
        for ey in (y0, y1):
            if ex is not None and ey is not None and (x - ex) ** 2 + (y - ey) ** 2 < r * r:
                return True
    return False


def meets_z(fx, z_lo, z_hi) -> bool:
    """Closed part heights ``z_lo..z_hi`` against the open fixture heights."""
    return _lt(z_lo, fx.z1) and _lt(fx.z0, z_hi)


def part_hits(part: Part, fx, x, y, z, tool_length) -> bool:
    shift = 0 if part.spindle else -tool_length
    return meets_z(fx, z + shift + part.z0, z + shift + part.z1) and meets_xy(fx, x, y, part.radius)


def sampled_hit(seg: Segment, parts, fixtures, n: int = 64):
    """The first sample ``(part, fixture, point)`` of ``seg`` where a part meets a fixture, or None.
    Straight motions are sampled exactly (linear rapids only: the property tests use linear machines)."""
    ix, iy, iz = (seg.axes.index(a) for a in "XYZ")
    if seg.kind is SegmentKind.ARC:
        at, _ = arc_path_float(seg)
        points = [tuple(at(k / n)) for k in range(n + 1)]
        tl = float(seg.tool_length)
        conv = float
    else:
        points = [tuple(a + Fraction(k, n) * (b - a) for a, b in zip(seg.start, seg.end)) for k in range(n + 1)]
        tl = seg.tool_length
        conv = lambda v: v  # noqa: E731
    for p in points:
        for part in parts:
            for fx in fixtures:
                fxc = fx if conv is not float else _float_fixture(fx)
                pc = _float_part(part) if conv is float else part
                if part_hits(pc, fxc, p[ix], p[iy], p[iz], tl):
                    return part, fx, p
    return None


def _f(v):
    return None if v is None else float(v)


def _float_fixture(fx):
    if isinstance(fx, FixturePrism):
        return FixturePrism(fx.name, tuple((float(a), float(b)) for a, b in fx.vertices), _f(fx.z0), _f(fx.z1))
    if isinstance(fx, FixtureCylinder):
        return FixtureCylinder(fx.name, float(fx.cx), float(fx.cy), float(fx.radius), _f(fx.z0), _f(fx.z1))
    return FixtureBox(fx.name, *(_f(v) for v in (fx.x0, fx.x1, fx.y0, fx.y1, fx.z0, fx.z1)))


def _float_part(p: Part) -> Part:
    return Part(p.name, float(p.radius), float(p.z0), float(p.z1), p.spindle)


def inside_part_and_fixture(point, path_point, part: Part, fx, tool_length) -> bool:
    """Exactly: is ``point`` inside the closed part placed at ``path_point`` and inside the fixture's open
    interior?  (A reported contact point must be.)"""
    x, y, z = point
    px, py, pz = path_point
    shift = 0 if part.spindle else -tool_length
    in_part = (x - px) ** 2 + (y - py) ** 2 <= part.radius ** 2 and pz + shift + part.z0 <= z <= pz + shift + part.z1
    if isinstance(fx, FixturePrism):
        in_fx = in_polygon(fx.vertices, x, y, True)
    elif isinstance(fx, FixtureCylinder):
        in_fx = (x - fx.cx) ** 2 + (y - fx.cy) ** 2 < fx.radius ** 2
    else:
        in_fx = _lt(fx.x0, x) and _lt(x, fx.x1) and _lt(fx.y0, y) and _lt(y, fx.y1)
    return in_part and in_fx and _lt(fx.z0, z) and _lt(z, fx.z1) and not math.isnan(float(x))
