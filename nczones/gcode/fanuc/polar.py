"""Polar coordinate interpolation (G12.1 / G13.1, Haas G112 / G113) on a Fanuc turning centre.

``G12.1`` switches the mode on, ``G13.1`` off (each in a block of its own;
plane, feed-mode and G40 codes may share it).  In the mode the program is a
path in a Cartesian plane fixed to the workpiece (:mod:`nczones.polar`):
the linear axis X (its words read as elsewhere on this machine: diameters on
a ``diameter_axes`` axis, ``U`` incremental) and the *hypothetical axis*
written with the rotary axis' address C (millimetres; ``H`` incremental in G
code system A), with the centre of rotation at X0 C0 of the workpiece
system.  The hypothetical axis is 0 when the mode starts, and the angle 0 of
the plane is where the tool stands then (Fanuc: "polar interpolation is
started assuming the angle of 0 for the position of the tool when G12.1 is
specified").  Motion:

* ``G01`` is a straight line in the plane, ``G02``/``G03`` an arc with
  ``I`` (X, radius) ``J`` (hypothetical axis) or ``R`` — each one
  ``SegmentKind.POLAR`` segment whose end is the machine position the control
  reaches, X and C rounded to their least increments;
* other axes (Z) may move with a ``G01`` (linearly along the path); an arc
  moves X and C only (a helix is ``unknown``).

Errors (``file:line:column``): GC234 a G code the mode does not allow (G00
and positioning, coordinate system changes, cycles, planes and units inside
the mode, G12.1 twice), GC235 a word the mode does not allow (K, an arc
without I/J or R), GC236 a machine without the axes X and C, GC330 an arc
that cannot be drawn.  ``unknown`` with the reason: the tool at or below the
centre of rotation when the mode starts, a path through the centre (C would
have to turn at once), nose radius compensation, parameter ranges, a tool
offset change in the mode.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from math import isqrt
from typing import TYPE_CHECKING

from ...cylinder import Interval
from ...motion import SegmentKind
from ...polar import CentreCrossing, atan2_deg, polar_move, walk_angle
from ..blocks import Block, Word
from ..interpreter import AXIS_LETTERS, StopProgram, fmt_number, gkey, gname

if TYPE_CHECKING:
    from .lathe import FanucLatheInterpreter

__all__ = ["PolarState", "POLAR_ON", "POLAR_OFF", "polar_block", "mentions_polar"]

POLAR_ON = frozenset((121, 1120))
POLAR_OFF = frozenset((131, 1130))
_SWITCH = POLAR_ON | POLAR_OFF
#: G codes that may share the block of G12.1/G13.1: plane, feed mode, G40.
_WITH_SWITCH = frozenset((170, 180, 190, 980, 990, 940, 950, 400))
#: G codes allowed in the mode (Fanuc's list: G01-G03, G04, G40-G42, G65-G67, G90/G91, G94/G95 or G98/G99).
_ALLOWED = frozenset((10, 20, 30, 40, 400, 410, 420, 650, 660, 670, 900, 910, 940, 950, 980, 990))
_WHY = {
    0: "positioning (G00) is not allowed in polar coordinate interpolation mode (Fanuc allows G01-G03 only); "
       "cancel the mode with G13.1 first",
    270: "reference position return check (G27) is not allowed in polar coordinate interpolation mode",
    280: "reference position return (G28) is not allowed in polar coordinate interpolation mode",
    300: "G30 is not allowed in polar coordinate interpolation mode",
    530: "G53 (machine coordinates) is not allowed in polar coordinate interpolation mode",
    500: "the coordinate system cannot be changed in polar coordinate interpolation mode",
    920: "the coordinate system cannot be changed in polar coordinate interpolation mode",
    520: "the coordinate system cannot be changed (G52) in polar coordinate interpolation mode",
    170: "the plane is fixed to X and the hypothetical axis in polar coordinate interpolation mode",
    180: "the plane is fixed to X and the hypothetical axis in polar coordinate interpolation mode",
    190: "the plane is fixed to X and the hypothetical axis in polar coordinate interpolation mode",
    200: "units cannot be changed in polar coordinate interpolation mode",
    210: "units cannot be changed in polar coordinate interpolation mode",
    121: "polar coordinate interpolation is already on",
    1120: "polar coordinate interpolation is already on",
}


def mentions_polar(block: Block) -> bool:
    """Does the block hold G12.1/G13.1/G112/G113?"""
    for w in block.words:
        if w.letter == "G" and gkey(w.value) in _SWITCH:
            return True
    return False


class PolarState:
    """The active mode: where the centre of rotation is, the angle reference, the current plane point."""

    __slots__ = ("ix", "ic", "x_off", "c_entry", "point", "turns", "grid")

    def __init__(self, ix: int, ic: int, x_off: Fraction, c_entry: Fraction, point: tuple[Fraction, Fraction],
                 grid: tuple[Fraction, Fraction]):
        self.ix, self.ic = ix, ic
        self.x_off, self.c_entry = x_off, c_entry
        self.point = point
        self.turns = 0
        self.grid = grid


def round_sqrt_to_grid(q: Fraction, g: Fraction) -> Fraction:
    """``sqrt(q)`` rounded to the grid ``g`` (halves up), exactly.

    >>> round_sqrt_to_grid(Fraction(2), Fraction(1, 1000)), round_sqrt_to_grid(Fraction(25, 4), Fraction(1))
    (Fraction(707, 500), Fraction(3, 1))
    """
    s = q / (g * g)  # n = round(sqrt(s)): the largest n with (n - 1/2)**2 <= s
    n = isqrt(s.numerator // s.denominator)
    while (n + Fraction(1, 2)) ** 2 <= s:
        n += 1
    while n > 0 and (n - Fraction(1, 2)) ** 2 > s:
        n -= 1
    return n * g


def _round(v: Fraction, g: Fraction) -> Fraction:
    return (v / g + Fraction(1, 2)).__floor__() * g


def polar_block(it: FanucLatheInterpreter, block: Block) -> None:
    """Execute one block when the mode is on or the block switches it."""
    if mentions_polar(block):
        _switch(it, block)
        return
    st = it.polar_ip
    assert st is not None  # called in the mode or for a switching block
    gcodes = [(gkey(w.value), w) for w in block.words if w.letter == "G"]
    g1 = None
    for k, w in gcodes:
        if k in _WHY:
            raise it.error("GC234", f"{w.text or gname(k)}: {_WHY[k]}", w)
        if k is None or k not in _ALLOWED:
            raise it.error("GC234", f"{w.text or 'G'} is not allowed in polar coordinate interpolation mode "
                            "(allowed: G01 G02 G03 G04 G40-G42 G65-G67 and the distance and feed modes); cancel the "
                            "mode with G13.1 first", w)
        if k in (10, 20, 30):
            g1 = k
    if any(k == 40 for k, _ in gcodes):  # G04 X/U/P: a dwell, its X is seconds
        it._execute_general(block)
        return
    words = {w.letter: w for w in block.words if w.letter not in "GM"}
    if "T" in words:
        it.unknown("T", "a tool or tool offset change in polar coordinate interpolation mode moves the centre of "
                   "the plane; it is not modelled", words["T"])
        return
    moving = [w for w in block.words if w.letter in AXIS_LETTERS or (it.system == "A" and w.letter in "UWVH")]
    motion = g1 if g1 is not None else it.motion
    if not moving:
        it._execute_general(block)
        return
    if motion == 0:
        raise it.error("GC234", "positioning (modal G00) is not allowed in polar coordinate interpolation mode; "
                        "write G01 or cancel the mode with G13.1 first", moving[0])
    if motion not in (10, 20, 30):
        raise it.error("GC234", f"{gname(motion or 0)} is not allowed in polar coordinate interpolation mode", moving[0])
    for letter, w in words.items():
        if letter in "IJR" and motion in (20, 30):
            continue
        if letter in "NFS" or letter in AXIS_LETTERS or (it.system == "A" and letter in "UWVH"):
            continue
        raise it.error("GC235", f"{w.text or letter}: not allowed in a motion block in polar coordinate "
                        "interpolation mode" + (" (arcs take I, J or R)" if letter in "IJKR" else ""), w)
    # the block's modes, feed and M codes as elsewhere, without its motion
    rest = tuple(w for w in block.words if not (w in moving or w.letter in "IJR"))
    stop = None
    try:
        it._execute_general(Block(rest, block.span, block.index, block.number, block.messages))
    except StopProgram as e:  # M02/M30 in the block: the motion first
        stop = e
    if not it.unsupported:
        it.motion = motion
        _move(it, st, block, words, motion)
    if stop is not None:
        raise stop


def _switch(it: FanucLatheInterpreter, block: Block) -> None:
    sw = [w for w in block.words if w.letter == "G" and gkey(w.value) in _SWITCH]
    w = sw[-1]
    k = gkey(w.value)
    assert k is not None
    others = [x for x in block.words if x not in sw]
    for x in others:
        if x.letter != "G" or gkey(x.value) not in _WITH_SWITCH:
            raise it.error("GC234", f"{x.text or x.letter}: {gname(k)} must stand in a block of its own (plane, "
                            "feed mode and G40 codes may share it)", x)
    if others:
        it._execute_general(Block(tuple(others), block.span, block.index, block.number, block.messages))
    if k in POLAR_OFF:
        it.polar_ip = None
        return
    if it.polar_ip is not None:
        raise it.error("GC234", f"{w.text or gname(k)}: polar coordinate interpolation is already on; cancel it "
                        "with G13.1 first", w)
    ix, ic = it.index.get("X"), it.index.get("C")
    if ix is None or ic is None:
        raise it.error("GC236", f"polar coordinate interpolation needs the linear axis X and the rotary axis C "
                        f"(parameters 5460/5461); this machine has {', '.join(it.axes)}", w)
    if it.turning is not None:
        raise it.error("GC234", f"cancel the turning cycle {gname(it.turning)} (G00 or G01) before {gname(k)}", w)
    if it.unsupported:
        return
    if it.comp_on:
        it.unknown(gname(k), "polar coordinate interpolation cannot start in nose radius compensation mode", w)
        return
    if it.track:
        it.unknown(gname(k), "parameter ranges are not supported with polar coordinate interpolation", w)
        return
    x0 = it.pos[ix] - it.off[ix]
    if x0 <= 0:
        where = "at" if x0 == 0 else "beyond"
        it.unknown(gname(k), f"the tool stands {where} the centre of rotation (X{fmt_number(x0)} radius in the "
                   "workpiece system) when polar coordinate interpolation starts: the angle 0 of the plane is "
                   "not defined by it", w)
        return
    it.note_assumed(("units", "offset"))
    it.polar_ip = PolarState(ix, ic, it.off[ix], it.pos[ic], (x0, Fraction(0)), (it._grid(ix), it.settings.increment_mm))


def _move(it: FanucLatheInterpreter, st: PolarState, block: Block, words: dict[str, Word], motion: int) -> None:
    targets = it._axis_targets(words)
    x0, y0 = st.point
    x1, y1 = x0, y0
    others = []
    for i, v, incremental, w in targets:
        q = it.length_mm(v)
        if i == st.ix:
            x1 = x0 + q if incremental else q
        elif i == st.ic:
            y1 = y0 + q if incremental else q
        else:
            others.append((i, v, incremental, w))
    end, _ = it.program_target(it._normalised(others), False) if others else (list(it.pos), None)
    p0, p1 = (x0, y0), (x1, y1)
    cw = motion == 20
    arc = motion in (20, 30)
    if arc and others:
        it.unknown(gname(motion), "an arc in polar coordinate interpolation that moves another axis (a helix) is "
                   "not modelled", others[0][3])
        return
    it.check_feed()
    it.note_assumed(("units", "distance"))
    if not arc and p0 == p1:
        it.emit(SegmentKind.LINE, end, feed=True)  # the other axes only: X and C stay
        return
    centre = radius = None
    if arc:
        centre, radius = _arc_geometry(it, words, p0, p1, cw)
    if x1 == 0 and y1 == 0:
        it.unknown(gname(motion), "the motion ends at the centre of rotation: the angle of the next motion's start "
                   "(and so the C axis) is not defined", block.words[0])
        return
    if not arc:
        cross = x0 * y1 - y0 * x1
        if cross == 0 and x0 * x1 + y0 * y1 <= 0:
            it.unknown(gname(motion), "the line passes through the centre of rotation: C would have to turn by 180 "
                       "degrees at once, in a direction the program does not say", block.words[0])
            return
    try:
        move = polar_move(p0, p1, st.turns, st.x_off, st.c_entry, clockwise=cw, centre=centre, radius=radius,
                          arc=arc)
        theta = walk_angle(move)
    except CentreCrossing:
        it.unknown(gname(motion), "the arc passes through the centre of rotation: C would have to turn at once",
                   block.words[0])
        return
    except ValueError as exc:
        raise it.error("GC330", f"arc in polar coordinate interpolation cannot be drawn: {exc}") from None
    gx, gc = st.grid
    end[st.ix] = st.x_off + round_sqrt_to_grid(x1 * x1 + y1 * y1, gx)
    end[st.ic] = st.c_entry + _round(theta.mid(), gc)
    turns = round((theta.mid() - atan2_deg(x1, y1).mid()) / 360)
    tag: tuple[tuple[str, object], ...] = (
        ("polar_start", p0), ("polar_end", p1), ("polar_turns", st.turns), ("polar_x_off", st.x_off),
        ("polar_c_entry", st.c_entry), ("polar_linear_axis", it.axes[st.ix]), ("polar_rotary_axis", it.axes[st.ic]),
        ("polar_grid", st.grid), ("polar_arc", arc))
    if centre is not None:
        tag += (("polar_centre", centre),)
    if radius is not None:
        tag += (("polar_radius", radius),)
    n0 = len(it.emitted)
    it.emit(SegmentKind.POLAR, end, feed=True, clockwise=cw)
    if len(it.emitted) > n0:
        s = it.emitted[-1]
        it.emitted[-1] = replace(s, extra=s.extra + tag)
    st.point = p1
    st.turns = turns


def _arc_geometry(it: FanucLatheInterpreter, words: dict[str, Word], p0: tuple[Fraction, Fraction],
                  p1: tuple[Fraction, Fraction], cw: bool) -> tuple[tuple[Fraction, Fraction] | None, Fraction | None]:
    rw = words.get("R")
    iw, jw = words.get("I"), words.get("J")
    tol = it.arc_tolerance
    if rw is not None:
        if iw is not None or jw is not None:
            raise it.error("GC235", "an arc takes R or I/J, not both", rw)
        r = it.length_mm(rw.value)
        if r == 0:
            raise it.error("GC330", "zero-radius arc (R0)", rw)
        if p0 == p1:
            raise it.error("GC330", "an R arc whose end point equals its start point: the centre is undefined", rw)
        l2 = (p1[0] - p0[0]) ** 2 + (p1[1] - p0[1]) ** 2
        if l2 > 4 * (abs(r) + tol) ** 2:
            half = Interval.of(l2).sqrt() / 2
            raise it.error("GC330", f"arc radius R{fmt_number(abs(r))} is too small to reach the end point in the "
                            f"polar plane: half the chord is {fmt_number(half.lo)} mm (tolerance "
                            f"{fmt_number(tol)} mm)", rw)
        return None, r
    if iw is None and jw is None:
        raise it.error("GC235", "an arc in polar coordinate interpolation needs I/J (the centre) or R")
    ci = it.length_mm(iw.value) if iw is not None else Fraction(0)
    cj = it.length_mm(jw.value) if jw is not None else Fraction(0)
    centre = (p0[0] + ci, p0[1] + cj)
    r0 = Interval.of((p0[0] - centre[0]) ** 2 + (p0[1] - centre[1]) ** 2).sqrt()
    r1 = Interval.of((p1[0] - centre[0]) ** 2 + (p1[1] - centre[1]) ** 2).sqrt()
    if r0.hi == 0:
        raise it.error("GC330", "arc with I0 J0: the centre is the start point", iw or jw)
    diff = r1 - r0
    if diff.lo > tol or diff.hi < -tol:
        raise it.error("GC330", f"the end point is not on the arc: its distance from the centre differs from the "
                        f"start's by {fmt_number(abs(diff.mid()))} mm, more than the tolerance "
                        f"{fmt_number(tol)} mm", iw or jw)
    return centre, None
