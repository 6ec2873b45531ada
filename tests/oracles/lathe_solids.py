"""An independent oracle for a lathe's turret tool solids against chucks (issue 39, the lathe case): dense
sampling of the path and, at each sample, an exact test in space.

It shares only the machine file's meaning with the prover (:mod:`nczones.lathe_solids`: parts as rectangles
``x0..x1 × z0..z1`` relative to the tool tip with a ``thickness`` across the plane of the spindle axis and
the tip, fixtures as solids of revolution ``r_in..r_out × z0..z1`` with open interiors, the tip at the
controlled point minus the ``tip_offset`` and the tool length, the tool by ``turret_tool`` or the H
register), not its code nor its signed-section reduction:

* the part placed at the tip ``(X, Z)`` is the box ``[X + x0, X + x1] × [-w/2, w/2] × [Z + z0, Z + z1]`` in
  space (``w`` its thickness); its distances from the spindle axis form the interval from the distance of
  ``[X + x0, X + x1]`` to 0 up to ``√(max((X + x0)², (X + x1)²) + (w/2)²)`` — exact, where the prover grows
  the rectangle by ``w/2`` instead (an enclosure): an oracle hit must never be a prover ``safe``;
* the solid of revolution is met when that interval meets the open ``(r_in, r_out)`` (with ``r_in = 0`` the
  axis itself is inside) and the heights share an open interval;
* lines are sampled at ``k / n`` (exact rationals), arcs at ``n`` angles in floats with a small margin (a
  float sample only suggests a hit; only clear ones count).
"""

from __future__ import annotations

from fractions import Fraction

from nczones.motion import Segment, SegmentKind, TipOffset, TurretTool, arc_path_float

EPS = 1e-6


def tool_of(seg: Segment) -> int | None:
    """The turret tool of a segment: its TurretTool payload, else its H register."""
    turret = seg.payload(TurretTool)
    return seg.tool_register if turret is None else turret.number


def tip_of(seg: Segment, point) -> tuple:
    """The tool tip ``(X, Z)`` at a controlled point: minus the X tool offset and the tool length (on Z)."""
    tip = seg.payload(TipOffset)
    off = dict(tip.offsets) if tip is not None else {}
    ix, iz = seg.axes.index("X"), seg.axes.index("Z")
    return point[ix] - off.get("X", 0), point[iz] - seg.tool_length


def part_meets(part, fx, x, z, eps=0) -> bool:
    """Does the part (its box in space) placed with its tip at ``(x, z)`` meet the open solid of revolution?
    ``eps`` > 0: by more than that margin (float samples)."""
    u0, u1 = x + part.x0, x + part.x1
    h = part.thickness / 2
    r_min = 0 if u0 <= 0 <= u1 else min(abs(u0), abs(u1))
    r_max2 = max(u0 * u0, u1 * u1) + h * h
    if fx.r_out is not None and not r_min < fx.r_out - eps:
        return False
    if fx.r_in > 0 and not r_max2 > fx.r_in * fx.r_in + eps:
        return False
    if fx.z1 is not None and not z + part.z0 < fx.z1 - eps:
        return False
    return fx.z0 is None or z + part.z1 > fx.z0 + eps


def sampled_hit(seg: Segment, parts, fixtures, n: int = 64):
    """The first sample ``(part, fixture, tip)`` of ``seg`` where a part meets a fixture, or None (linear
    rapids only: the property tests use a linear machine)."""
    if seg.kind is SegmentKind.ARC:
        at, _ = arc_path_float(seg)
        points = [tuple(at(k / n)) for k in range(n + 1)]
        conv, eps = float, EPS
    else:
        points = [tuple(a + Fraction(k, n) * (b - a) for a, b in zip(seg.start, seg.end)) for k in range(n + 1)]
        conv, eps = (lambda v: v), 0  # noqa: E731
    for p in points:
        x, z = tip_of(seg, [conv(v) for v in p]) if conv is float else tip_of(seg, p)
        if conv is float:
            x, z = float(x), float(z)
        for part in parts:
            for fx in fixtures:
                if part_meets(_conv_part(part, conv), _conv_fx(fx, conv), x, z, eps):
                    return part, fx, (x, z)
    return None


def _conv_part(part, conv):
    if conv is not float:
        return part
    return type(part)(part.name, *(float(v) for v in (part.x0, part.x1, part.z0, part.z1, part.thickness)))


def _conv_fx(fx, conv):
    if conv is not float:
        return fx
    f = (lambda v: None if v is None else float(v))  # noqa: E731
    return type(fx)(fx.name, float(fx.r_in), f(fx.r_out), f(fx.z0), f(fx.z1))


def contact_inside(point, tip, part, fx) -> bool:
    """Exactly: is the contact point ``(X, Z)`` (in the plane Y = 0) inside the part of thickness 0 placed with
    its tip at ``tip`` and inside the fixture's open interior?"""
    x, z = point
    in_part = tip[0] + part.x0 <= x <= tip[0] + part.x1 and tip[1] + part.z0 <= z <= tip[1] + part.z1
    r = abs(x)
    in_fx = (fx.r_in < r or (fx.r_in == 0)) and (fx.r_out is None or r < fx.r_out)
    in_fx = in_fx and (fx.z0 is None or fx.z0 < z) and (fx.z1 is None or z < fx.z1)
    return in_part and in_fx
