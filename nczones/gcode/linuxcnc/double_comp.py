"""Cutter radius compensation (G40, G41, G42) in the double pass (:mod:`nczones.gcode.linuxcnc.doubles`).

On a machine with ``cutter_compensation = "linuxcnc"`` the full path compensates every motion while G41 or G42
is on (:mod:`.cutter_comp`, LinuxCNC's ``convert_straight_comp1/2``, ``convert_arc_comp1/2`` and its move
queue).  The pass follows the straight moves (G0, G1) and the arcs (G2, G3 with I/J or R; comp41) in G17, G21
and G90: the same motions, in the same order, each row the double of the full path's exact end.

Why the rows hold
-----------------
The full path computes the compensation in program-frame doubles: the programmed point of a plane axis is
``program_double(exact machine end, offset)``, the correctly rounded ``exact word`` (G90, G21: the end is the
word's exact value plus the offset, and a word's exact value is one whose double is the word's double, the
pass's module docstring), so it *is* the word's double the pass computes; an axis the block does not name keeps
the previous one (:attr:`Comp.words`, kept per plane axis by every G90 move of the pass, the machine's start
converted exactly, and forgotten when the axis's exact offset changes: compensation then declines).  From
those the full path and the pass call the same functions (:mod:`.comp_floats`) in the same order, so every
compensated end ``a`` is the same double; the full path's exact machine end is ``Fraction(a) + offset``, the
pass's row ``fl(a + float(offset))``: within ``(|offset| + |row|) 2**-53``, inside the pass's widening.  The
other axes of a row are the programmed ones (a convex corner's normal axis: the one before the move), the
pass's rows of the move as without compensation.

A convex corner of a feed is an arc about the programmed corner (the previous programmed point, a row of
the pass within its bound) from the previous compensated end to the next one (a spiral when the two radii
differ: the full path's segment is that spiral), clockwise for G41.  Its box (:func:`corner_box`) is
:mod:`.double_arcs`' ``sector_box`` of the annulus sector about the centre's double, with ``err`` as ``ij_check``'s:
the centre's and the ends' doubles are within the rows' bound (``rho <= (4 m + 2**-8) 2**-52``, ``m`` above
every magnitude and the offsets), so ``u = S - C``, ``w = E - C`` and the radii are within ``err / 2`` of
the exact ones, as there.  The corner arc joins the pass's arcs (``DoublePath.arc_rows``, its box already
the sweep's: ``EXACT``), and an arc after a motion LinuxCNC may drop declines as a programmed arc's does.

Arcs (comp41).  A programmed arc's centre double is LinuxCNC's own (``arc_data_ijk``, ``arc_data_r``): an I/J
arc's is the programmed start's double plus the word's (G91.1), which the pass has (the start is the kept word
:attr:`Comp.words`, the word its double) and the full path now computes the same way (``CutterComp._centre_ij``;
it used to round the exact sum, an ulp off LinuxCNC at times); an R arc's is ``comp_floats.arc_centre_r`` of
the programmed ends' doubles and R's.  From there both call the same functions (the entry arc, the corner, the
line-arc, arc-line and arc-arc pull-backs, a held arc's move: :mod:`.comp_floats`), so the compensated ends and
centres are the same doubles, and the same decisions (concave, convex, straight on; an error) are taken.  The
programmed arc is first checked as the pass checks any arc (``ij_check``, ``r_screen`` on the programmed ends:
what the full path's ``Interpreter.arc`` may refuse or decide otherwise declines).  The compensated arc is
held like a straight move and emitted, its end perhaps moved, from the previous row to its row about its
centre: the full path's exact centre is the programmed one (I/J: the exact start plus the exact words) or the
exact value of the centre's double (R, an entry arc's moved centre).  Its box is :func:`corner_box`'s with
``more`` (the centre's magnitude, the programmed and the tool radius) added to ``m``: the exact I/J centre is
within ``(|start| + |I, J| + |C|) 2**-53`` plus the offset's rounding of the double's, below ``err / 4`` with
that ``m``; the ends as a corner arc's.  A spiral (the ends' radii differ: a held arc's moved end, LinuxCNC
allows 0.01) is in the annulus sector, as a corner arc's.  A whole turn, P, K, an arc whose tool radius is not
less than its radius and every error of ``convert_arc_comp1/2`` decline.

G41.1/G42.1 take their ``D`` as the diameter (a negative one: the other side), as ``CutterComp.select``.

What declines (the full path's error or unknown, or not modelled): G41/G42 on a machine without LinuxCNC's
compensation or on a lathe, outside G17, in G20, with a tool whose diameter is not in ``[tool_diameters]``
or not above 0, D not a whole positive number, the tool in the spindle after ``T0 M6`` or ``M61``; G41 or G42
while on; G2/G3 as the move after G40's flush, a whole turn, P or K under compensation; a dwell, M6, M61, a plane, units, work offset, tool
length or path mode code while on (or, a dwell, M6 and M61, while the machine stands at G40's compensated
point); G91, G20, G7 and canned cycles in a program that writes compensation (:meth:`Comp.compile_checks`);
an entry move not longer than the radius, a gouge (a held move reversed), a zero-degree inside corner, a
concave corner right after a flush (the full path's unknown), every error of the arc formulas.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ...code_cache import compiled
from ...motion import DROPPED_BELOW
from .comp_floats import (
    CONCAVE_TOLERANCE_RAD,
    LEFT,
    RIGHT,
    arc_arc_back,
    arc_centre_r,
    arc_corner,
    arc_entry,
    arc_line_back,
    arc_moved,
    entry_line,
    find_turn,
    line_arc_back,
    line_corner,
    retreat,
    reverses,
)
from .double_arcs import EXACT, ij_check, r_screen, sector_box

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["Comp", "arc_code", "comp_body", "comp_others", "corner_box", "straight_code"]

#: The comp group's codes that turn compensation on (G41, G42; G41.1, G42.1 as the pass keys them: -411, -421).
_ON = (41, 42, -411, -421)
#: Row kinds of the queue: a rapid, a feed, a corner arc.
_RAPID, _LINE, _ARC = 0, 1, 2
#: :attr:`Comp.words`: the axis is where the machine started (converted exactly when needed).
START = "start"
_U = 2.0**-52


def corner_box(sx: float, sy: float, ex: float, ey: float, cx: float, cy: float, cw: bool,
               offb: float, more: float = 0.0) -> tuple[float, float, float, float]:
    """The box (``xlo, xhi, ylo, yhi``) of a corner arc from row ``(sx, sy)`` to row ``(ex, ey)`` about the
    programmed corner's row ``(cx, cy)`` (the module's docstring: :func:`~.double_arcs.sector_box`, the pass's
    arcs' box, with ``ij_check``'s ``err``; ``offb`` bounds the offsets), or of a compensated programmed arc
    about its centre's double (``more``: a magnitude its centre's error also depends on, added to ``m``).

    >>> [round(v, 9) + 0.0 for v in corner_box(0.0, 1.0, 1.0, 0.0, 0.0, 0.0, True, 0.0)]
    [0.0, 1.0, 0.0, 1.0]
    >>> [round(v, 9) + 0.0 for v in corner_box(1.0, 0.0, -1.0, 0.0, 0.0, 0.0, False, 0.0)]
    [-1.0, 1.0, 0.0, 1.0]
    """
    ux, uy, wx, wy = sx - cx, sy - cy, ex - cx, ey - cy
    r0, r1 = math.hypot(ux, uy), math.hypot(wx, wy)
    m = (sx if sx >= 0.0 else -sx) + (sy if sy >= 0.0 else -sy) + r0 + r1 + offb + more
    err = (64.0 * m + 0.0625) * _U
    if r1 > r0:
        return sector_box(sx, sy, ex, ey, cx, cy, ux, uy, wx, wy, r1, r1 - r0 + err, err, cw)
    return sector_box(sx, sy, ex, ey, cx, cy, ux, uy, wx, wy, r0, r0 - r1 + err, err, cw)


def comp_others(groups: dict[str, int], others: list[str]) -> list[str]:
    """The words of a block without a G41/G42's D (its tool), for the checks of the other D users."""
    if groups.get("comp") in _ON and "D" in others:
        return [x for x in others if x != "D"]
    return others


def comp_body(st: Any, groups: dict[str, int], ms: list[int], ts: list[int], qs: list[int],
              others: list[str], declined: Any) -> tuple[list[str], list[str]]:
    """The code of a block's compensation: ``(checks, select)``, the checks before its modal codes (the full
    path's ``check_block``: a state compensation refuses while on), the tool change and G40/G41/G42 after
    them (before its motion)."""
    comp = groups.get("comp")
    cc = st.cc
    if cc is None:
        if comp in _ON:
            raise declined("G41/G42 on a machine without LinuxCNC's cutter compensation, or a lathe")
        return [], []
    cc.compile_checks(groups)
    checks = []
    if any(g in groups for g in ("plane", "units", "offset", "tool", "path")) or 6 in ms or 61 in ms \
            or comp in _ON:
        checks.append("if CS.side is not None: raise D('a code cutter compensation refuses while on')")
    if 6 in ms or 61 in ms or groups.get("nonmodal") == 4:
        checks.append("if CS.busy: raise D('a dwell or tool change under cutter compensation or after G40')")
    select = []
    if ts:
        select.append(f"CS.selected = {ts[0]}")
    if 6 in ms:
        select.append("CS.change()")
    if 61 in ms:
        select.append(f"CS.spindle = {qs[0]}; CS.stale = True")
    if comp == 40:
        select.append("CS.off()")
    elif comp in (41, 42):
        d = f"v[{others.index('D')}]" if "D" in others else "None"
        select.append(f"CS.on({LEFT if comp == 41 else RIGHT}, {d})")
    elif comp in _ON:  # G41.1/G42.1: D is the diameter (LinuxCNC's error without it)
        if "D" not in others:
            raise declined("G41.1/G42.1 without D")
        select.append(f"CS.on({LEFT if comp == -411 else RIGHT}, v[{others.index('D')}], True)")
    return checks, select


def straight_code(axes: list[tuple[int, int]], normal: list[str], plane: tuple[int, int] | None = None) -> list[str]:
    """A straight move's code in a program that may compensate: :meth:`Comp.straight` while compensation is on
    or G40 left the machine off the programmed point, else ``normal``; a block that names no axis but the
    plane's (``plane``: their indices) calls :meth:`Comp.line` (comp42: one call a move)."""
    moved = {i for _k, i in axes}
    if plane is not None and None not in plane and moved <= set(plane):
        x = next((f"v[{k}]" for k, i in axes if i == plane[0]), "None")
        y = next((f"v[{k}]" for k, i in axes if i == plane[1]), "None")
        call = f"CS.line(mode, {x}, {y})"
    else:
        call = f"CS.straight(mode, v, {tuple(axes)!r})"
    return ["if CS.busy:", f"    {call}", "else:", *(f"    {b}" for b in normal)]


def arc_code(others: list[str], axes: list[tuple[int, int]], normal: list[str]) -> list[str]:
    """An arc's code in a program that may compensate: :meth:`Comp.arc` while compensation is on or G40 left the
    machine off the programmed point, else ``normal``."""
    if "P" in others or "K" in others or not axes:
        comp = ["raise D('an arc with P or K, or a whole turn, under cutter compensation')"]
    else:
        spec = tuple(others.index(x) if x in others else -1 for x in "RIJ")
        comp = [f"CS.arc(mode, v, {tuple(axes)!r}, {spec!r})"]
    return ["if CS.busy:", *(f"    {b}" for b in comp), "else:", *(f"    {b}" for b in normal)]


class Comp:
    """The compensation state of one pass (``_Pass.cc``) and LinuxCNC's move queue, as
    :class:`~nczones.gcode.linuxcnc.cutter_comp.CutterComp` keeps them, on the pass's doubles."""

    def __init__(self, st: Any, machine: Any, declined: Any):
        self.st = st
        self.declined = declined
        self.diameters = dict(getattr(machine, "tool_diameters", {}) or {})
        self.side: int | None = None
        #: compensation on, or G40 flushed it and the next motion has not run (the machine stands at the
        #: compensated point, LinuxCNC's ``comp_just_off``): the straight moves go through :meth:`straight`
        self.busy = False
        self.radius = 0.0
        self.first = True
        #: held moves: ``[kind, a, b, da, db, row]`` (``row``: the move's own list of the other axes' doubles,
        #: its plane axes set when emitted); an arc's adds ``ca, cb, turn, sweep, radius`` (its programmed radius)
        self.queue: list[list[Any]] = []
        self.endpoint = (0.0, 0.0)
        self.valid = False
        self.cur = (0.0, 0.0)
        self.prog = (0.0, 0.0)
        index = st.index
        self.ia, self.ib, self.inn = index.get("X"), index.get("Y"), index.get("Z")
        #: per axis: the program-frame double of the programmed point (the last G90 word), :data:`START`, or
        #: None (its exact offset changed since: compensation from there declines)
        self.words: list[Any] = [START] * len(st.axes)
        self.key = (st.wcs, st.reg)
        self.selected = self.spindle = 0
        self.stale = False
        self.adds: tuple[Any, ...] | None = None  # the columns' appends, once a row was added (_row)
        self.emit: Any = None  # a row's appends in one call, once a row was added (_emitter)
        #: a compensated arc's words (``DoublePath.arc_more``: its box is the sweep's, the offsets' bound)
        self.arc_words = (float(EXACT), 0.0, 0.0, st.offb)
        #: a plane axis's step at or above this is not one LinuxCNC may drop (``_Pass.tiny``; the plans' LIM)
        self.lim = 2 * (float(DROPPED_BELOW) * 1.01 + 1e-12 + st.tiny_pad) + 1e-4

    # -- what a program that compensates may not do ------------------------------------------------------
    def compile_checks(self, groups: dict[str, int]) -> None:
        """Decline G91, G20, G7/G8 and canned cycles in a program that writes compensation (the words it keeps are
        G90 millimetres), and G41/G42 outside what the module follows."""
        from .double_cycles import CYCLE_CODES

        if groups.get("distance") == 91 or groups.get("units") == 20 or "diameter" in groups \
                or groups.get("motion") in CYCLE_CODES:
            raise self.declined("G91, G20, G7 or a canned cycle in a program with cutter compensation")

    # -- state ------------------------------------------------------------------------------------------
    def _exact_offset(self, i: int, key: tuple[int, int | None]) -> Fraction:
        st = self.st
        wcs, reg = key
        off: Fraction = st.exact_offsets[wcs][i]
        if reg is not None and i == st.tool_axis:
            off += st.lengths[reg]
        return off

    def offset_to(self, wcs: int, reg: int | None) -> None:
        """G54..G59, G43 or G49 (not while on): the plane axes whose exact offset changes forget their word."""
        key = (wcs, reg)
        if key == self.key:
            return
        for i in (self.ia, self.ib):
            if i is not None and self.words[i] not in (None, START) \
                    and self._exact_offset(i, self.key) != self._exact_offset(i, key):
                self.words[i] = None
        self.key = key

    def _program(self, i: int) -> float:
        """The program-frame double of axis ``i``'s programmed point (the full path's ``_fprog``)."""
        w = self.words[i]
        if w is None:
            raise self.declined("cutter compensation after a work offset or tool length change")
        if w is START:
            from .cutter_comp import program_double

            return program_double(Fraction(self.st.start[i]), self._exact_offset(i, self.key), (1, 1))
        value: float = w
        return value

    def change(self) -> None:
        """M6: the selected tool in the spindle (``Interpreter``: T0 M6 leaves the slot's entry behind)."""
        if self.selected == 0 and self.spindle != 0:
            self.stale = True
        elif self.selected != 0:
            self.stale = False
        self.spindle = self.selected

    def on(self, side: int, d: float | None, dynamic: bool = False) -> None:
        """G41 (``side`` LEFT) or G42 with D ``d`` (None: the tool in the spindle), or (``dynamic``) G41.1/G42.1
        with the diameter ``d``, as ``CutterComp.select``."""
        st = self.st
        if (st.plane or st.start_plane) != 17 or st.inch or st.diameter or self.ia is None or self.ib is None \
                or st.tool_axis in (self.ia, self.ib):
            raise self.declined("cutter compensation outside G17 and G21 on X and Y")
        if dynamic:
            self._dynamic(side, d)
            return
        if d is None or d == 0.0:
            if self.stale:
                raise self.declined("cutter compensation of the tool in the spindle after T0 M6 or M61")
            tool = self.spindle
        else:
            tool = int(d + 0.5)
            if not (d > 0.0 and abs(tool - d) < 0.0001):
                raise self.declined("a D word that is not a whole positive number")
        dia = self.diameters.get(tool)
        if dia is None or not dia > 0:
            raise self.declined("cutter compensation with a tool without a positive diameter")
        self.side, self.radius = side, float(dia) / 2.0
        self.busy, self.first, self.queue = True, True, []

    def _dynamic(self, side: int, d: Any) -> None:
        """G41.1/G42.1 D ``d`` (a diameter: LinuxCNC's radius is ``d / 2``, a negative one the other side)."""
        if self.side is not None:
            raise self.declined("G41.1/G42.1 while compensation is on")
        radius = d / 2.0
        if radius < 0.0:
            radius, side = -radius, RIGHT if side == LEFT else LEFT
        if not radius > 0.0:
            raise self.declined("G41.1/G42.1 with a diameter of 0")
        self.side, self.radius = side, radius
        self.busy, self.first, self.queue = True, True, []

    def off(self) -> None:
        """G40: the held moves flushed where the tool is; the next motion starts from there."""
        if self.side is not None and not self.first:
            self._flush(*self.cur)
            self.valid = False
            self.busy = True  # LinuxCNC's comp_just_off: the next motion must be straight
        else:
            self.busy = False
        self.side = None
        self.first = True

    def end(self) -> None:
        """M2, M30 or the end of the text: the held moves flushed."""
        if self.side is not None and self.queue:
            self._flush(*self.cur)
        self.side = None
        self.first = True
        self.busy = False

    # -- moves ------------------------------------------------------------------------------------------
    def straight(self, mode: int, v: Any, axes: tuple[tuple[int, int], ...]) -> None:
        """A G0 (``mode`` 0) or G1 move of words ``v`` (``axes``: word index, axis index) while :attr:`busy`."""
        st = self.st
        pos, off, words = st.pos, st.off, self.words
        ia, ib = self.ia, self.ib
        if self.first and self.side is not None:  # (before this move's words are kept)
            self.prog = self.cur = (self._program(ia), self._program(ib))
        before = (pos[ia], pos[ib], pos[self.inn] if self.inn is not None else 0.0)
        px, py = self.prog
        for k, i in axes:
            x = words[i] = v[k]
            pos[i] = x + off[i]
            if i == ia:
                px = x
            elif i == ib:
                py = x
        if self.side is None:  # the move after G40's flush: from the compensated point, uncompensated
            self.busy = False
            self._row(mode, list(pos))
            return
        words[ia], words[ib] = px, py
        if self.first:
            self._first(mode, px, py, pos[:])
        else:
            self._next(mode, px, py, pos[:], before)

    def line(self, mode: int, x: float | None, y: float | None) -> None:
        """A G0 (``mode`` 0) or G1 move that names no axis but the plane's (``x``, ``y``: its words, None for one
        it lacks) while :attr:`busy`: :meth:`straight` and :meth:`_next` in one function (comp42: the same
        formulas in the same order, so the same rows, without four calls a move).  The entry move, the move
        after G40's flush and every other block take :meth:`straight`."""
        if self.first or self.side is None:
            ia, ib = self.ia, self.ib
            axes = ((0, ia),) if x is not None else ()
            self.straight(mode, (x, y), axes + ((1, ib),) if y is not None else axes)
            return
        st = self.st
        pos, off, words = st.pos, st.off, self.words
        ia, ib = self.ia, self.ib
        bx, by = pos[ia], pos[ib]  # the programmed corner's row (a convex corner's centre)
        opx, opy = self.prog
        if x is None:
            px = opx
        else:
            px = x
            pos[ia] = x + off[ia]
        if y is None:
            py = opy
        else:
            py = y
            pos[ib] = y + off[ib]
        words[ia], words[ib] = px, py
        row = pos[:]
        cx, cy = self.cur
        queue = self.queue
        if py == opy and px == opx:  # no motion in the plane
            queue.append([mode, cx, cy, 0.0, 0.0, row])
            return
        front = queue[0][8] if queue and queue[0][0] == _ARC else 0
        concave, beta, end_x, end_y, mid_x, mid_y, theta, gamma = line_corner(self.side, self.radius, cx, cy,
                                                                               opx, opy, px, py, front)
        if not concave and beta > CONCAVE_TOLERANCE_RAD:  # convex: around the corner (_flush, then _corner)
            self._flush(cx, cy)
            corner = row[:]
            corner[ia], corner[ib] = mid_x + off[ia], mid_y + off[ib]
            if mode:  # the corner arc: its box, then its row
                self._arc(corner, bx, by, self.side == LEFT, 0.0)
                (self.emit or self._emitter())(corner)
                if len(st.columns[0]) >= st.rows:
                    st.full()
            else:
                self._row(_RAPID, corner)
            self.endpoint, self.valid = (mid_x, mid_y), True
        elif concave:
            self._concave(front, cx, cy, beta, theta, gamma, opx, opy, px, py)
        else:  # straight on
            self._dequeue()
            self.endpoint, self.valid = (cx, cy), True
        self.queue.append([mode, end_x, end_y, px - opx, py - opy, row])
        self.cur, self.prog = (end_x, end_y), (px, py)

    def _first(self, kind: int, px: float, py: float, row: list[float]) -> None:
        """The entry move (``CutterComp._straight_first``)."""
        cx, cy = self.cur
        got = entry_line(self.side, self.radius, cx, cy, px, py)
        if got is None:
            raise self.declined("a cutter compensation entry move not longer than the radius")
        ex, ey, da, db = got
        self.endpoint, self.valid = (cx, cy), True
        self.queue.append([kind, ex, ey, da, db, row])
        self.first = False
        self.cur, self.prog = (ex, ey), (px, py)

    def _next(self, kind: int, px: float, py: float, row: list[float], before: tuple[float, float, float]) -> None:
        """A move after the first (``CutterComp._straight_next``; a corner arc is emitted at once, a programmed
        arc may be held at the queue's front)."""
        cx, cy = self.cur
        opx, opy = self.prog
        if py == opy and px == opx:  # no motion in the plane
            self.queue.append([kind, cx, cy, 0.0, 0.0, row])
            return
        queue = self.queue
        front = queue[0][8] if queue and queue[0][0] == _ARC else 0
        concave, beta, end_x, end_y, mid_x, mid_y, theta, gamma = line_corner(self.side, self.radius, cx, cy,
                                                                               opx, opy, px, py, front)
        if not concave and beta > CONCAVE_TOLERANCE_RAD:  # convex: around the corner
            self._flush(cx, cy)
            # the corner move, held and emitted at once (CutterComp: _enqueue, then _dequeue)
            self._corner(kind, mid_x, mid_y, row, before)
        elif concave:
            self._concave(front, cx, cy, beta, theta, gamma, opx, opy, px, py)
        else:  # straight on
            self._dequeue()
            self.endpoint, self.valid = (cx, cy), True
        queue = self.queue
        queue.append([kind, end_x, end_y, px - opx, py - opy, row])
        self.cur, self.prog = (end_x, end_y), (px, py)

    def _concave(self, front: int, cx: float, cy: float, beta: float, theta: float, gamma: float, opx: float,
                 opy: float, px: float, py: float) -> None:
        """A concave corner before the straight move from ``(opx, opy)`` to ``(px, py)`` (:meth:`line`,
        :meth:`_next`; ``line_corner``'s ``beta``, ``theta``, ``gamma``): the held moves flushed to where the
        queue's end is pulled back (``arc_line_back`` when an arc of turn ``front`` is held, else ``retreat`` from
        ``(cx, cy)``); declined as LinuxCNC errs (no held move, a zero-degree corner or a gouge)."""
        queue = self.queue
        if not queue:
            raise self.declined("a concave corner after the compensation queue was flushed")
        if front:  # an arc held: its end pulled back (arc_line_back)
            q = queue[0]
            back = arc_line_back(self.side, self.radius, q[1], q[2], q[6], q[7], front, opx, opy, px, py)
        else:
            back = retreat(self.radius, cx, cy, beta, theta, gamma)
        if back is None:
            raise self.declined("a zero-degree inside corner or a gouge (LinuxCNC's error)")
        self._flush(*back)

    def _corner(self, kind: int, mid_x: float, mid_y: float, row: Any, before: tuple[float, float, float]) -> None:
        """A convex corner's move to ``(mid_x, mid_y)`` (an arc about the programmed corner ``before``, a
        rapid's straight), emitted at once; the queue's endpoint there."""
        corner = list(row)
        if self.inn is not None:
            corner[self.inn] = before[2]
        off = self.st.off
        corner[self.ia], corner[self.ib] = mid_x + off[self.ia], mid_y + off[self.ib]
        if kind:  # an arc: its box, then its row (_row's)
            emit = self.emit or self._emitter()
            self._arc(corner, before[0], before[1], self.side == LEFT, 0.0)
            st = self.st
            emit(corner)
            if len(st.columns[0]) >= st.rows:
                st.full()
        else:
            self._row(_RAPID, corner)
        self.endpoint, self.valid = (mid_x, mid_y), True

    # -- arcs -------------------------------------------------------------------------------------------
    def arc(self, mode: int, v: Any, axes: tuple[tuple[int, int], ...], spec: tuple[int, int, int]) -> None:
        """A G2 (``mode`` 2) or G3 of words ``v`` (``axes``: word index, axis index; ``spec``: the indices of
        R, I and J, -1 for a word the block lacks) while :attr:`busy` (``CutterComp.arc``): the programmed
        arc's checks (the pass's own, on the programmed ends: what the full path's ``Interpreter.arc`` may
        refuse declines), its centre's doubles as LinuxCNC's (``arc_centre_r``; I/J: the programmed start's
        double plus the words', as ``CutterComp._centre_ij``), then the entry or the corner."""
        if self.side is None:
            raise self.declined("an arc just after G40's flush")
        st = self.st
        pos, off, words = st.pos, st.off, self.words
        ia, ib = self.ia, self.ib
        if self.first:
            self.prog = self.cur = (self._program(ia), self._program(ib))
        before = (pos[ia], pos[ib], pos[self.inn] if self.inn is not None else 0.0)
        opx, opy = self.prog
        px, py = opx, opy
        for k, i in axes:
            x = words[i] = v[k]
            pos[i] = x + off[i]
            if i == ia:
                px = x
            elif i == ib:
                py = x
        words[ia], words[ib] = px, py
        if px == opx and py == opy:
            raise self.declined("a whole turn under cutter compensation")
        cw = mode == 2
        ri, ii, ji = spec
        if ri >= 0:
            r = v[ri]
            why = r_screen(before[0], before[1], pos[ia], pos[ib], r, st.offb)
            centre = arc_centre_r(opx, opy, px, py, r, cw, 0.00005 * 25.4)
            radius = abs(r)
        else:
            wi, wj = v[ii] if ii >= 0 else 0.0, v[ji] if ji >= 0 else 0.0
            why = ij_check(before[0], before[1], pos[ia], pos[ib], wi, wj, cw, st.offb, st.rule, False, True)
            centre = (opx + wi, opy + wj)
            radius = math.hypot(centre[0] - self.cur[0], centre[1] - self.cur[1])
        if why.__class__ is str or centre is None:
            raise self.declined(f"a compensated arc's programmed arc: {why}")
        row = pos[:]
        turn = -1 if cw else 1
        if self.first:
            self._arc_first(cw, turn, px, py, centre, radius, row)
        else:
            self._arc_next(cw, turn, px, py, centre, row, before)
        self.prog = (px, py)

    def _arc_first(self, cw: bool, turn: int, px: float, py: float, centre: tuple[float, float], radius: float,
                   row: list[float]) -> None:
        """The entry arc (``CutterComp._arc_first``: :func:`.comp_floats.arc_entry`)."""
        cx, cy = self.cur
        got = arc_entry(self.side, self.radius, cx, cy, px, py, centre[0], centre[1], cw, turn, radius, False)
        if got.__class__ is int:
            raise self.declined("a cutter compensation entry arc LinuxCNC refuses")
        ex, ey, ccx, ccy = got  # type: ignore[misc]
        self.first = False
        self.queue.append([_ARC, ex, ey, 0.0, 0.0, row, ccx, ccy, turn, find_turn(cx, cy, ccx, ccy, turn, ex, ey),
                           radius])
        self.cur = (ex, ey)

    def _arc_next(self, cw: bool, turn: int, px: float, py: float, centre: tuple[float, float],
                  row: list[float], before: tuple[float, float, float]) -> None:
        """An arc after the first move (``CutterComp._arc_next``: :func:`.comp_floats.arc_corner` and the
        pull-backs of a concave corner)."""
        cx, cy = self.cur
        opx, opy = self.prog
        side, radius = self.side, self.radius
        c0, c1 = centre
        got = arc_corner(side, radius, cx, cy, opx, opy, px, py, c0, c1, cw, turn)
        if got.__class__ is int:
            raise self.declined("a tool radius not less than a compensated arc's (LinuxCNC's error)")
        how, nx, ny, arc_radius, theta, beta, delta = got  # type: ignore[misc]
        main = [_ARC, nx, ny, 0.0, 0.0, row, c0, c1, turn, find_turn(opx, opy, c0, c1, turn, px, py),
                arc_radius]
        if how == 1:  # concave
            queue = self.queue
            if not queue:
                raise self.declined("a concave corner after the compensation queue was flushed")
            q = queue[0]
            if q[0] == _ARC:
                back: Any = arc_arc_back(side, radius, arc_radius, q[1], q[2], q[6], q[7], q[8], c0, c1, turn)
            else:
                back = line_arc_back(side, radius, arc_radius, theta, beta, turn, c0, c1)
            if back is None or back.__class__ is int:
                raise self.declined("a concave corner before an arc the tool cannot reach (LinuxCNC's error)")
            self._flush(*back)
        elif how == 2:  # convex: a corner arc to opx + r cos(delta) first
            self._dequeue()
            self._corner(1, opx + radius * math.cos(delta), opy + radius * math.sin(delta), row, before)
        else:
            self._dequeue()
            self.endpoint, self.valid = (cx, cy), True
        self.queue.append(main)
        self.cur = (nx, ny)

    def _flush(self, x: float, y: float) -> None:
        """Move every held move's end to ``(x, y)`` and emit them (``_move_endpoint_and_flush``); a reversed
        straight one or an arc LinuxCNC refuses (:func:`.comp_floats.arc_moved`) is its gouge error: declined.
        One held straight move (a contour of lines: most flushes) is emitted here, as :meth:`_dequeue` would."""
        queue = self.queue
        if not queue:
            return
        ex, ey = self.endpoint
        valid = self.valid
        if len(queue) == 1 and queue[0][0] != _ARC:
            q = queue[0]
            if valid and reverses(q[3], q[4], x, y, ex, ey):
                raise self.declined("a compensated move reversed in a concave corner (LinuxCNC's gouge error)")
            st = self.st
            r = q[5]
            r[self.ia] = x + st.off[self.ia]
            r[self.ib] = y + st.off[self.ib]
            (self.emit or self._emitter())(r)
            if q[0] == _RAPID:
                st.rapids += 1
            self.queue = []
            if len(st.columns[0]) >= st.rows:
                st.full()
            self.endpoint = (x, y)  # (valid: already, or set below)
            self.valid = True
            return
        for q in queue:
            if q[0] == _ARC:
                if arc_moved(q[1], q[2], q[6], q[7], q[8], q[9], x, y, ex, ey, valid, False):
                    raise self.declined("a held compensated arc LinuxCNC refuses to move")
            elif valid and reverses(q[3], q[4], x, y, ex, ey):
                raise self.declined("a compensated move reversed in a concave corner (LinuxCNC's gouge error)")
            q[1], q[2] = x, y
        self._dequeue()
        self.endpoint, self.valid = (x, y), True

    def _dequeue(self) -> None:
        """Emit the held moves as rows (an arc: its box, :meth:`_arc`; a held move's row is its own list)."""
        self.valid = False
        st = self.st
        off, ia, ib = st.off, self.ia, self.ib
        oa, ob = off[ia], off[ib]
        emit = self.emit or self._emitter()
        col0, rows = st.columns[0], st.rows
        for q in self.queue:
            kind = q[0]
            r = q[5]
            r[ia] = q[1] + oa
            r[ib] = q[2] + ob
            if kind == _ARC:  # a programmed arc about its centre (more: |ca| + |cb| + its radius + the tool's)
                ca, cb = q[6], q[7]
                self._arc(r, ca + oa, cb + ob, q[8] < 0,
                          (ca if ca >= 0.0 else -ca) + (cb if cb >= 0.0 else -cb) + q[10] + self.radius)
            emit(r)
            if kind == _RAPID:
                st.rapids += 1
            if len(col0) >= rows:
                st.full()
        self.queue = []

    def _adds(self) -> tuple[Any, ...]:
        """The columns' appends, at the first row: every axis may move from here (sound: ``_Pass.moved``)."""
        st = self.st
        if not all(st.first_row):
            st.moved(tuple(range(len(st.columns))))
        adds = self.adds = tuple(col.append for col in st.columns)  # (full() drops rows in place)
        return adds

    def _emitter(self) -> Any:
        """:attr:`emit`, at the first row: one function that appends a row to every column (comp42: no ``zip``
        loop a row), after :meth:`_adds`."""
        adds = self.adds or self._adds()
        scope = {f"a{i}": add for i, add in enumerate(adds)}
        source = "def emit(r):\n" + "".join(f"    a{i}(r[{i}])\n" for i in range(len(adds)))
        exec(compiled(source, "<compensated rows>"), scope)  # noqa: S102  # from indices only
        self.emit = scope["emit"]
        return self.emit

    def _row(self, kind: int, row: Any) -> None:
        """Append a motion's row (a rapid or a feed)."""
        st = self.st
        (self.emit or self._emitter())(row)
        if kind == _RAPID:
            st.rapids += 1
        if len(st.columns[0]) >= st.rows:
            st.full()

    def _arc(self, row: Any, cx: float, cy: float, cw: bool, more: float) -> None:
        """A corner arc or a compensated programmed arc about ``(cx, cy)`` (its centre's row doubles; ``cw``:
        clockwise; ``more``: :func:`corner_box`'s) ending at ``row``: its box, before its row is appended (an arc after a motion LinuxCNC may drop declines, as ``_Pass._arc_body``)."""
        st = self.st
        ia, ib = self.ia, self.ib
        ca, cb = st.columns[ia], st.columns[ib]
        last = len(ca) - 1  # the motion before the arc ends at this row
        step = ca[last] - ca[last - 1] if last > 0 else 0.0  # (a quick test tiny() implies, as _Pass._arc_body's)
        if st.blend and last > 0 and (-self.lim < step < self.lim or not -1e10 < ca[last] < 1e10) \
                and st.tiny(last) and not st.lone(last) and not st.dwell_at(last):
            raise self.declined("a corner arc after a motion LinuxCNC may drop in a blended corner")
        if st.arc_plane != 17:
            st.arc_in(17)
        box = corner_box(ca[-1], cb[-1], row[ia], row[ib], cx, cy, cw, st.offb, more)
        st.add_arc(st.row0 + last + 1, box, self.arc_words)
