"""The lathe tool's nose radius: the tip zones a proof checks, enlarged by the nose's reach.

A lathe tool offset (``[tool_offsets]``) measures the tool to its *imaginary tool nose*: the nose centre
for tip direction 0 or 9, else a corner (1-4) or side (5-8) point of the square of side 2R around the nose
circle ([0i-T] FANUC Series 0i-TD Operator's Manual B-64304EN, "Imaginary tool nose").  The zones with
``point = "tip"`` see that point; the cutting edge is the nose circle around the centre.  The circle must
stay clear, so the tip zones are proved against every point within reach of the imaginary tip:

* the nose centre lies within R of the imaginary tip on each axis of the turning plane (X, Z) for any tip
  direction (0 and 9: at it; 5-8: R along one axis; 1-4: R along both), whichever way the machine's tip
  numbers turn, so the circle lies in the square of half-width ``reach`` = R (tip 0, 9) or 2R (1-8)
  around the imaginary tip;
* a forbidden tip zone is replaced by its Minkowski sum with that square (a box grows by ``reach`` on X and
  Z; a polygon becomes itself and one convex hexagon per edge, the edge swept by the square: their union
  is the sum, and every point of the sum's interior reached through the square's interior lies in the
  interior of one of them);
* an allowed tip box shrinks by ``reach`` on X and Z (the whole square must stay inside).

``reach`` is the largest over the machine's tool offsets (geometry + wear radius): the program may select
any of them, so the proof holds for each.  A sound over-approximation: a square is larger than the circle,
so a violation means the square around the nose reaches into the zone (the report says so), not that the
edge does.  A tip zone of another kind (a stepped table, an allowed polygon) with a nose radius cannot be
enlarged here: the verdict is then ``unknown`` (:func:`nose_zones` returns the reason).
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction

from ..exact import format_decimal
from ..machine import Machine
from ..precompiled import replace  # dataclasses.replace without importing dataclasses (start-up)
from ..zones import AllowedSet, BoxZone, SteppedZone, Zone, ZonePoint
from ..zones.kinds import KindTable
from ..zones.model import PolygonZone

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["nose_reach", "nose_zones"]

_PLANE = ("X", "Z")


def nose_reach(machine: Machine) -> Fraction:
    """The half-width of the square (X, Z) that holds every tool's nose circle around its imaginary tip."""
    reach = Fraction(0)
    for t in machine.tool_offsets.values():
        r = t.nose_radius + t.wear_radius
        if r > 0:
            reach = max(reach, r if t.tip in (0, 9) else 2 * r)
    return reach


def _hull(points: list[tuple[Fraction, Fraction]]) -> list[tuple[Fraction, Fraction]]:
    """The convex hull, counter-clockwise, collinear points dropped (Andrew's monotone chain)."""
    pts = sorted(set(points))
    if len(pts) <= 2:
        return pts

    Pt = tuple[Fraction, Fraction]

    def cross(o: Pt, a: Pt, b: Pt) -> Fraction:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[Pt] = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper: list[Pt] = []
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _grow(lo: Fraction | None, hi: Fraction | None, d: Fraction) -> tuple[Fraction | None, Fraction | None]:
    return (None if lo is None else lo - d, None if hi is None else hi + d)


def _not_modelled(z: Zone, reach: Fraction, what: str | None = None) -> str:
    what = what or f"a {z.kind} zone"
    return (f"tool nose radius: the tip zone \"{z.name}\" is {what}; enlarging it by the "
            f"nose's reach ({format_decimal(reach)} mm) is not modelled")


#: The zones that hold the nose square of half-width ``reach`` around the imaginary tool tip wherever the
#: tip zone holds the tip (allowed: shrunk, forbidden: grown), per zone kind; or the reason for ``unknown``.
#: Fallback: not modelled (``unknown``).
NOSE_GROWN: KindTable[Callable[[Any, Fraction], tuple[Zone, ...] | str]] = KindTable(
    "prover.nose.grown", fallback=_not_modelled)
NOSE_GROWN.set(SteppedZone, _not_modelled)


@NOSE_GROWN.register(BoxZone)
def _box_grown(z: BoxZone, reach: Fraction) -> tuple[Zone, ...] | str:
    d = reach if z.forbid else -reach
    limits = tuple((a, *_grow(lo, hi, d)) if a in _PLANE else (a, lo, hi) for a, lo, hi in z.limits)
    if any(lo is not None and hi is not None and lo > hi for _a, lo, hi in limits):
        # an allowed box narrower than the nose
        return (f"tool nose radius: the allowed tip zone \"{z.name}\" is narrower than the "
                f"nose's reach ({format_decimal(reach)} mm on each side)")
    return (replace(z, limits=limits),)


@NOSE_GROWN.register(PolygonZone)
def _polygon_grown(z: PolygonZone, reach: Fraction) -> tuple[Zone, ...] | str:
    if not z.forbid:
        return _not_modelled(z, reach, "an allowed polygon")
    if set(z.plane) != set(_PLANE):
        return _not_modelled(z, reach, "a polygon outside the ZX plane")
    out: list[Zone] = [z]
    for a, b in z.edges():
        corners = [(p[0] + su * reach, p[1] + sv * reach) for p in (a, b) for su in (-1, 1)
                   for sv in (-1, 1)]
        out.append(replace(z, vertices=tuple(_hull(corners))))
    return tuple(out)


def nose_zones(machine: Machine) -> tuple[Machine, str | None, str | None]:
    """``(machine with its tip zones enlarged, note, reason for unknown)``; the machine unchanged (and no
    note) when it is no lathe or no tool offset has a nose radius."""
    reach = nose_reach(machine)
    tips = [z for z in machine.zones if z.point is ZonePoint.TIP]
    if not machine.is_lathe or reach == 0 or not tips:
        return machine, None, None
    out = []
    for z in machine.zones:
        if z.point is not ZonePoint.TIP:
            out.append(z)
            continue
        grown = NOSE_GROWN(z, reach)
        if isinstance(grown, str):
            return machine, None, grown
        out.extend(grown)
    note = (f"tool nose radius: the tip zones were proved against the square of half-width "
            f"{format_decimal(reach)} mm on X and Z around the imaginary tool tip, which holds the nose circle of "
            "every tool offset (R for tip 0/9, 2R for tips 1-8); a violation means that square reaches into the "
            "zone")
    return replace(machine, allowed=AllowedSet(tuple(out), machine.allowed.tool_axis)), note, None
