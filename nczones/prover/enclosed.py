"""Counterexamples on irrational paths: certified boxes, their witnesses and depths.

Motions whose path points are irrational (developed arcs of G07.1, polar
moves of G12.1) are decided by enclosures: a counterexample is a tiny
rational box around an exact path point, every point of which violates a
zone.  These helpers turn such a box into the :class:`Violation` every
prover result carries, for all those motions alike.

Invariants: :func:`certify_box` returns a point only when every point of the
box violates a zone (and re-checks that point exactly); :func:`box_depth` is
a lower bound of the depth of every point of a certified box;
:func:`enclosed_violation` raises ``InternalError`` unless its witness is
strictly outside with margin 0.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..errors import InternalError
from ..motion import Segment
from . import exact as ex
from .geometry import simple_in
from .result import Violation

__all__ = ["certify_box", "box_depth", "enclosed_violation"]

F0 = Fraction(0)


def certify_box(p: Any, seg: Segment, lo: dict[str, Fraction], hi: dict[str, Fraction]) -> tuple[dict, Any] | None:
    """A short rational point of the box ``[lo, hi]`` and the zones it violates, if every box point violates one."""
    for zone in p.zones:
        if ex.box_certainly_violates(p.allowed, zone, lo, hi, p.margin, seg.tool_length):
            mid = {a: simple_in(lo[a], hi[a]) for a in seg.axes}
            bad = p.allowed.violated_zones(mid, seg.tool_length, p.margin)
            if zone not in bad:
                raise InternalError(f"block {seg.block}: a certified box's centre does not violate {zone.name}")
            return mid, bad
    return None


def box_depth(p: Any, seg: Segment, lo: dict[str, Fraction], hi: dict[str, Fraction], width: Fraction) -> Fraction:
    """How deep every point of the box goes at least: its centre's depth in each certainly violated zone, less
    the box's ``width`` (0 when no zone is certainly violated)."""
    depth = F0
    for zn in p.zones:
        if ex.box_certainly_violates(p.allowed, zn, lo, hi, p.margin, seg.tool_length):
            pt = {a: simple_in(lo[a], hi[a]) for a in seg.axes}
            if zn in p.allowed.violated_zones(pt, seg.tool_length, p.margin):
                depth = max(depth, ex.point_depth(zn, p.allowed.seen_by(zn, pt, seg.tool_length), p.margin) - width)
    return depth


def enclosed_violation(p: Any, seg: Segment, f: Fraction, mid: dict[str, Fraction], bad: Any, width: Fraction,
                       depth: Fraction, kind: str, note: str) -> Violation:
    """The :class:`Violation` of a certified box around the path point at parameter ``f`` (not exact)."""
    zone = bad[0]
    outside = ex.outside_point(p.allowed, zone, mid, p.margin, seg.tool_length)
    if outside is None or zone not in p.allowed.violated_zones(outside, seg.tool_length):
        raise InternalError(f"block {seg.block}: no point strictly outside inside the margin box")
    for zn in bad:  # the reported point's own depth, less the enclosure's width
        depth = max(depth, ex.point_depth(zn, p.allowed.seen_by(zn, mid, seg.tool_length), p.margin) - width)
    at = tuple((a, mid[a]) for a in seg.axes)
    return Violation(
        block=seg.block, span=seg.span, zone=zone.name, point=tuple((a, outside[a]) for a in seg.axes),
        path_point=at, parameter=f, parameter_exact=False, first_exit=at, first_exit_parameter=f,
        first_exit_exact=False, depth=max(depth, F0), depth_exact=False, engine="exact", segment_kind=kind,
        derived=seg.derived, params=(), zones=tuple(z.name for z in bad), note=note, on_path=False,
        exit_located=False,
    )
