"""How parameter ranges move a tool's solids against a fixture (issue 39): a mill's
(:class:`nczones.prover.solids.SolidsChecker`) and a lathe's (:class:`nczones.prover.lathe_solids.LatheSolidsChecker`).

A motion records which parameters its coordinates depend on (``Segment.deps_start``/``deps_end``, per axis:
a work offset, a tool length register, the start position) and its tool length (``Segment.deps_tool``).  A
coordinate with sources ``S`` is its nominal value plus the sum of the deviations of ``S``'s parameters on
that axis (:class:`nczones.motion.Segment`), named as the prover's core names them (``G54.X``, ``H1``).  The
tip is the controlled point less the tool length on the tool axis, so a tool part moves by the coordinate's
sources less the length's there; a fixture in a work offset moves with that offset; a homing error moves
the machine (and a fixture in a work offset maybe with it).  Per axis the displacement over the ranges is an
interval containing 0: the hull of the start's and the end's intervals along the motion.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from fractions import Fraction
from typing import Any

from ..motion import Segment

__all__ = ["UNTRACKED", "untracked", "axis_displacement"]

F0 = Fraction(0)

#: The reason (VF218) when ranges other than homing errors are given and the motion did not record its sources.
UNTRACKED = ("the motion does not say which parameters its coordinates depend on: the tool solids cannot be "
             "moved with the parameter ranges")


def untracked(ranges: Iterable[Any], seg: Segment) -> bool:
    """Do ``ranges`` hold one a motion moves by only through its recorded sources, which ``seg`` lacks?"""
    return any(not r.name.startswith("home.") for r in ranges) and not seg.deps_start


def axis_displacement(seg: Segment, dev: Mapping[str, tuple[Fraction, Fraction]], axis: str, index: int, *,
                      less_tool: bool, frame: str = "") -> tuple[Fraction, Fraction]:
    """The interval (containing 0) a part moves by on ``axis`` (the motion's coordinate ``index``) against a
    fixture over the ranges ``dev`` (name -> deviation lo, hi): the coordinate's sources, less the tool
    length's (``less_tool``: a tool part on the tool axis), less the fixture's work offset ``frame`` ("": on
    the machine), plus a homing error (module docstring)."""
    lo = hi = F0
    for deps in (seg.deps_start, seg.deps_end):
        coef: dict[str, int] = {}
        for dep in (deps[index] if deps else ()):  # named as the prover's core names them
            name = dep if dep.startswith("H") else f"{dep}.{axis}"
            coef[name] = coef.get(name, 0) + 1
        if less_tool:
            for dep in seg.deps_tool:
                name = dep if dep.startswith("H") else f"{dep}.{axis}"
                coef[name] = coef.get(name, 0) - 1
        if frame:
            coef[f"{frame}.{axis}"] = coef.get(f"{frame}.{axis}", 0) - 1
        home = dev.get(f"home.{axis}")
        e_lo, e_hi = F0, F0
        if home is not None:  # with a work offset the fixture may move with the homing too: 0 or all
            e_lo, e_hi = (min(F0, home[0]), max(F0, home[1])) if frame else home
        for name, c in coef.items():
            r = dev.get(name)
            if r is not None and c:
                e_lo, e_hi = e_lo + min(c * r[0], c * r[1]), e_hi + max(c * r[0], c * r[1])
        lo, hi = min(lo, e_lo), max(hi, e_hi)
    return lo, hi
