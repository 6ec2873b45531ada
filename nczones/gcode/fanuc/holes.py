"""A Fanuc control's hole after a drilling cycle's first block, as rows of a template (issue 36).

``FanucInterpreter._fanuc_cycle`` makes the motions of a block of X/Y words under a cycle of
:data:`~nczones.gcode.codes.FANUC_HOLE_CYCLES`; :func:`fanuc_holes` gives the same rows -- kinds, levels, the feed,
the dwell, the ``derived`` names -- for the state the interpreter is in, so that a run of hole lines need not
read every hole through it: the vectorized fast path (``fastpath._fast_cycle_run``) writes them in columns, the
numpy-free box route (:mod:`nczones.gcode.fanuc.boxrun`) boxes them.  No numpy here: the box route must not load
it.  ``tests/gcode/fanuc/test_fastpath_cycles.py`` and ``tests/gcode/fanuc/test_box_holes.py`` hold both to the
interpreter.
"""

from __future__ import annotations

from fractions import Fraction

from ...motion import Plane, SegmentKind
from ..codes import FANUC_HOLE_CYCLES

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["fanuc_holes", "holes_state_ok", "MAX_HOLE_ROWS"]

#: The most rows one hole's template may have (G73/G83 pecks beyond it: the interpreter reads the hole).
MAX_HOLE_ROWS = 256


def holes_state_ok(it: Any) -> bool:
    """A Fanuc state in which a hole line (X/Y words only) is what ``FanucInterpreter._fanuc_cycle`` makes of it
    for a cycle of :data:`FANUC_HOLE_CYCLES` after its first block: G90 G17 G94 with a feed, R and Z written in
    G90, nothing pending (no unknown code, transform, compensation, tool length change, dependency tracking, or a
    first move after a transform))."""
    data = it.cycle_data
    return (it.cycle in FANUC_HOLE_CYCLES and not it.unsupported and it.absolute and it.plane is Plane.XY
            and it.feed_mode == 94 and it.feed > 0 and it.initial_level is not None and "R" in data
            and "Z" in data and data.get("R90") is True and data.get("Z90") is True and not it.comp_on
            and not it.comp_just_off and not it.track and it.prerotation_xy is None and it.machine_at is None
            and not it.m73_saved and it.spline_state is None and it.prog is None and not it.tool_length_pending
            and not it.after_home and not it.transform_just_cancelled and all(a in it.index for a in "XYZ"))


def _pecks(it: Any, r: Fraction, bottom: Fraction) -> list[tuple[SegmentKind, Fraction, str]] | None:
    """G73's and G83's rows before the last feed, as ``FanucInterpreter._fanuc_cycle`` makes them (a feed to each
    peck depth; G83 a rapid out to R; a rapid back off by d, or down to d above the cut), or None where the full
    path decides otherwise (no Q above 0, no d, more pecks than ``max_repeats`` or :data:`MAX_HOLE_ROWS`)."""
    k, data = it.cycle, it.cycle_data
    if "Q" not in data or data["Q"] <= 0:
        return None  # GC208/GC209 on the full path
    step = it.length_mm(data["Q"])
    back = it.settings.g73_retract if k == 730 else it.settings.g83_clearance
    if back is None or -((bottom - r) // step) - 1 > min(it.max_repeats, MAX_HOLE_ROWS // 3):
        return None  # an unknown (parameter 5114/5115, too many pecks) on the full path
    name, rows, depth = "G73" if k == 730 else "G83", [], r
    R, L = SegmentKind.RAPID, SegmentKind.LINE
    while depth - step > bottom:
        depth -= step
        rows.append((L, depth, "peck"))
        if k == 830:
            rows.append((R, r, "clear"))
        rows.append((R, depth + back, "retract" if k == 730 else "approach"))
    return [(kind, z, f"{name} {what}") for kind, z, what in rows]


def fanuc_holes(it: Any) -> tuple | None:
    """A Fanuc control's hole (``FanucInterpreter._fanuc_cycle`` for a block of X/Y words: 0i/30i-M "Canned cycle
    for drilling"), as ``fastpath._linuxcnc_holes`` gives LinuxCNC's: a "position" rapid at the current level (the
    top: the initial level under G98, R under G99, where the last hole ended), a "to R" rapid when the top is not
    R, G73/G83's pecks, the feed to the bottom, a dwell (with P: G74, G82, G84, G89), then the "retract" rapid to
    the top, or (G74, G84, G85, G89) a feed back to R and a "return" rapid to the top when that is not R; None in
    another state or with the tool axis not at the top."""
    if not holes_state_ok(it):
        return None
    from .interpreter import dwell_p_seconds, gname

    k, ic, data = it.cycle, it.index["Z"], it.cycle_data
    name = gname(k)
    r = it.length_mm(data["R"]) + it.off[ic]
    bottom = it.length_mm(data["Z"]) + it.off[ic]
    top = r if it.retract_r else it.initial_level
    if it.pos[ic] != top:
        return None
    R, L, D = SegmentKind.RAPID, SegmentKind.LINE, SegmentKind.DWELL
    rows: list[tuple[SegmentKind, Fraction, str]] = [(R, top, f"{name} position")]
    if top != r:
        rows.append((R, r, f"{name} to R"))
    if k in (730, 830):
        pecks = _pecks(it, r, bottom)
        if pecks is None:
            return None
        rows += pecks
    rows.append((L, bottom, f"{name} feed"))
    dwell = dwell_p_seconds(data["P"]) if "P" in data and k in (820, 840, 890, 740) else None
    if dwell:
        rows.append((D, bottom, f"{name} dwell"))
    if k in (740, 840, 850, 890):
        rows.append((L, r, f"{name} retract"))
        if top != r:
            rows.append((R, top, f"{name} return"))
    else:
        rows.append((R, top, f"{name} retract"))
    levels = {f"z{i}": z for i, (_kind, z, _what) in enumerate(rows)}
    tmpl = [(kind, False, f"z{i}", what) for i, (kind, _z, what) in enumerate(rows)]
    return (name, levels, tmpl, it.length_mm(it.feed), dwell, ("units", "distance", "offset", "plane", "retract"))
