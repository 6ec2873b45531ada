"""Canned cycles in the double pass (:mod:`nczones.gcode.linuxcnc.doubles`), issue 36: G73, G81-G86, G89, L.

A drilling program with expressions ran the full path (about 12x ``rs274``) because the pass declined its
cycles.  This module runs a cycle block in the pass's doubles, as the full path's ``Interpreter._cycle``
does exactly (LinuxCNC's ``convert_cycle_xy`` and ``CYCLE_MACRO``, ``interp_cycles.cc``), one row per
motion the full path emits, in the same order:

* the first time (``old < R``, the initial level below R): a rapid "up to R" where the tool stands;
* per repeat (``L``, 1 without; :func:`repeats`), the hole's position: in G90 the words' (every repeat the
  same hole), in G91 the last hole plus the words' increments (:meth:`Cycles._increment`);
* the position rapid: to the hole at the current level, then to R, on the first repeat of a block when the
  tool is above R (``current > R``); else to the hole at the clear level, then to R when the clear level
  is above R;
* G73's and G83's pecks (:meth:`Cycles._pecks`): per peck a feed to ``R - k Q``, G83's rapid out to R, a rapid
  back down to 0.254 mm above the peck, as many as the full path counts in LinuxCNC's doubles;
* the feed to the bottom (the plane's normal axis: Z in G17), the dwell of G82, G84, G86 and G89 there (a row
  where the machine stands, a stop: :meth:`~nczones.gcode.linuxcnc.doubles._Pass.dwelt`; G84's is the sticky P
  of any cycle before it, 0 before any: always a row), and the way out (:data:`MODES`): a rapid to the clear
  level (G73, G81-G83, G86), a feed to it (G84, G89), or G85's feed to R then a rapid to the clear level when
  it is above R.  The clear level: R under G99, the initial level under G98.

The initial level is the normal axis's position when the cycle became modal (kept until a motion code that
is not a cycle: the full path's ``cycle_il``); R, the bottom, the dwell and the peck are sticky.  In G91 R is
above the initial level and the bottom below R (the full path's ``R + il`` and ``r + Z``).  G84 and G86 move
as the others (the spindle's stop and reverse move nothing); the full path refuses G84 unless the spindle
turns clockwise and G86 while it is stopped: the pass follows M3, M4, M5 and M6's stop (``st.spindle``,
:func:`spindle_body`) and declines those.

Why the rows hold
-----------------
In G90 every row is a machine coordinate the pass computes as it computes a G90 move's: a word's double plus
the offset's double (the hole's X and Y, R, the bottom), or a copy of the double of a row before it (where the
tool stands, the initial level); so the module's bound of :mod:`.doubles` holds for each (a copy's bound is
its own row's, no more than the widening of any box that holds it).  While a G91 chain is open a G90 cycle's
rows are G90 ones or copies of the chain's (where the tool stands, the initial level): the chain's error,
kept, bounds them (the widening adds it to the module's bound).  In G91 the rows are sums of doubles: the hole's ``fl(x + w)`` on every repeat, R's ``fl(R' + il')``,
the bottom's ``fl(r + Z')``: each is a step of a G91 chain, whose error the pass bounds as a G91 move's
(:meth:`Cycles._increment`, :meth:`Cycles._relative`; the chain's ``st.err``, added to the widening by ``xerr``,
set before the rows it bounds are added).  In G20 a word's millimetres are ``fl(w * fl(25.4))`` as a G20 move's
(:mod:`.double_units`): a G90 row within ``3.6 (|x| + offsets) 2**-53`` of its exact value (inside the widening,
and inside the levels' tolerance below), a G91 step adding :mod:`.double_units`' term (:meth:`Cycles._units`);
the pecks counted in the program's inches as LinuxCNC counts them, their rows in millimetres.  In G91 the pecks
are counted from R ``fl(R' + old)`` and the bottom ``fl(r + Z')``, ``old`` the double of the initial level in
program units, which the pass has only within its bound: :meth:`Cycles._peck_count` counts for every double it may
be (one when its exact value is a literal's) and declines unless the counts agree; a G91 R's error is added to the
peck rows' bound.  G73's and G83's peck rows: ``fl(R' - fl(k Q'))`` drifts from the
exact ``R - k Q`` by up to some ``k`` ulps of Q; :meth:`Cycles._pecks` bounds that drift and adds the bound to
the normal axis's widening (the pass's ``xerr``, as a G91 chain's, from the first peck on: :func:`_row` sets it
again after a window is handed over, which recomputes it from the chains alone).

The Q: the pass reads a Q word as M61's tool number (a literal code) in a line with an M word, else as a value
(:func:`q_value`), which only G73 and G83 take (:func:`takes_q`; a Q in any other line declines).  L: LinuxCNC's
integer of its double (:func:`repeats`), which the full path reads from the exact value's double, the same.

The branches (how many rows a block makes) are the full path's exact comparisons of levels.  The pass
decides each in doubles only where it cannot differ from the exact one (:meth:`Cycles.below`): two levels
known to have the same exact value are equal (a token each: R's is its exact value when it is a literal,
the text's :func:`~nczones.gcode.lexer.decimal_value` as the full path reads it, :func:`r_token`, or the
same sticky R word; where the tool stands, a G90 motion's literal word, :meth:`Cycles.level`, so ``G0 Z2`` then
``G98 G81 ... R2`` compares equal by value; with the same offsets, the same tuple of doubles, hence the same exact offsets; in G91
R's token and the initial level's; the tool's level is the clear level's token when no motion came after the
last cycle block, or in a text that may write a cycle no motion of that axis: :meth:`Cycles.run`); else the doubles must differ by more than both levels' bounds (``(|a| + |b| + 2 offsets)
2**-52``, taken twice over, plus a G91 level's own error); a closer pair declines (equal doubles of two
different exact values: ``R0.30000000000000001`` then ``R0.3``, where the full path's tool is above R and makes
two rapids).

Declined (besides what :mod:`.doubles` declines): a cycle before the program sets G98 or G99 or the plane
(the full path notes the assumed mode), G73 and G83 in G91 whose peck count the initial level's possible
doubles do not decide (:meth:`Cycles._peck_count`), on a lathe
(an X word may be a diameter), a units change while a cycle is modal (the full path converts the initial
level), without a positive feed, without R or the bottom the first time, an L that is not a whole number
(within 0.0001), below 1 or at the loop bound, a P with G73, G81, G83 or G85, a G82, G86 or G89 without a P
the first time, a P not above 0, a G73 or G83 without a Q above 0 or with as many pecks as the loop bound, a Q
with another cycle or a G64, G84 unless M3 turns the spindle or outside G17 (LinuxCNC then swaps its axes),
G86 with the spindle stopped, I, J or K in a cycle block, an axis word off the plane's three, a machine without
them, R below the bottom,
a plane or offset change (work offset, tool length) while a cycle is modal (the full path moves the initial
level with the offsets), G87 and G88 (the full path's unknown).
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

from ...motion import PLANE_AXES
from ..lexer import decimal_value
from ..parser import NUM

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["CYCLE_CODES", "Cycles", "cycle_call", "cycle_modal", "level_code", "literal_tokens", "may_cycle", "r_token",
           "takes_p"]

#: Per cycle the pass runs (the motion group's codes, :data:`~nczones.gcode.linuxcnc.doubles._GROUPS`): its
#: pecks (0: none; 83: a feed, a rapid out to R, a rapid back down; 73: a feed, a rapid back off), its dwell at
#: the bottom (0: none; 1: P the first time, sticky; 2: G84's, the sticky P of any cycle before, 0 before
#: any), how it leaves the bottom (:data:`RAPID_OUT`, :data:`FEED_OUT`, :data:`FEED_TO_R`) and the spindle it
#: needs (None: any; 0: turning; 1: clockwise, M3), as the full path's ``Interpreter._cycle``.
RAPID_OUT, FEED_OUT, FEED_TO_R = 0, 1, 2
MODES = {81: (0, 0, RAPID_OUT, None), 82: (0, 1, RAPID_OUT, None), 83: (83, 0, RAPID_OUT, None),
         73: (73, 0, RAPID_OUT, None), 85: (0, 0, FEED_TO_R, None), 89: (0, 1, FEED_OUT, None),
         84: (0, 2, FEED_OUT, 1), 86: (0, 1, RAPID_OUT, 0)}
CYCLE_CODES = frozenset(MODES)
#: The cycles whose block takes a P (a dwell), and a Q (a peck).
_DWELLS = frozenset(k for k, m in MODES.items() if m[1])
_PECKS = frozenset(k for k, m in MODES.items() if m[0])
#: G83's back-off above the last peck's depth (mm: the full path's ``G83_RAPID_DELTA_MM``, exactly 0.254).
_BACK_OFF = 0.254
#: The bound of two levels' distance from their exact values, per unit of ``|a| + |b| + 2 offsets``:
#: ``2**-52`` (:mod:`.doubles`'s module bound, twice half an ulp) taken twice over.
_REL = 4.5e-16
_EPS2 = 2.0**-52
#: (above the ``32 * 2**-1075`` a G20 row's bound has: :mod:`.double_units`)
_TA = 2.0**-1000
#: ``fl(25.4)``: a G20 word's double times it is its millimetres (:data:`.double_units.INCH`)
_INCH = 25.4
_INF = math.inf
#: Per plane code: the indices of its first, second and normal axis names (``PLANE_AXES``: the full path's).
_PLANES = {int(p): names for p, names in PLANE_AXES.items()}


def takes_p(groups: dict[str, int], axes: bool) -> bool:
    """May a block's P word be a cycle's dwell: G82, G84, G86 or G89 written, or axis words in a motion mode the
    block does not write (the mode may be one: :meth:`Cycles.run` declines a P in any other)."""
    motion = groups.get("motion")
    return motion in _DWELLS or (motion is None and axes)


def q_value(words: Any) -> bool:
    """Is a line's Q word a value (G83's peck), not M61's tool number: a line without an M word (a Q in one
    with an M is read as M61's, and declines but with M61)."""
    letters = [w[0] for w in words]
    return "Q" in letters and "M" not in letters


def takes_q(groups: dict[str, int], axes: bool) -> bool:
    """May a block's Q value be G73's or G83's peck: one written, or axis words in a motion mode the block does
    not write (:meth:`Cycles.run` declines a Q in any other mode); not with a G64 (whose Q it would be too)."""
    motion = groups.get("motion")
    return "path" not in groups and (motion in _PECKS or (motion is None and axes))


def cycle_modal(groups: dict[str, int]) -> list[str]:
    """The code of a block's G98/G99 and of a motion code that ends a modal cycle (every code but a cycle's:
    the full path's ``cycle_il`` and ``last_cycle`` set to None)."""
    body = []
    if "retract" in groups:
        body.append(f"st.cyc.retract = {groups['retract'] == 99}")
    if "motion" in groups and groups["motion"] not in CYCLE_CODES:
        # (a block writing G1, G2 ... on every line: no call while no cycle ran since the last end(); ``last`` is
        # None only then, for _general sets it after every field end() resets, and a decline ends the pass)
        body.append("if st.cyc.last is not None: st.cyc.end()")
    return body


def spindle_body(ms: list[int]) -> list[str]:
    """The code of a block's M6 (which stops the spindle: LinuxCNC's ``convert_tool_change``) and M3, M4 or M5:
    the spindle's direction G84 and G86 check (``st.spindle``: 1 M3, -1 M4, 0 stopped, the full path's
    ``spindle_dir``), set before the block's motion as the full path's."""
    body = ["st.spindle = 0"] if 6 in ms else []
    for m, d in ((3, 1), (4, -1), (5, 0)):
        if m in ms:
            body.append(f"st.spindle = {d}")
    return body


def r_token(words: Any, leaf: Any) -> list[str]:
    """The source of the value a line's steps hand its plan after its words' when it has an R word: the
    R's text (a literal cut from the line, ``P[k]``; ``"n/d"`` for a literal of a line parsed afresh), whose
    exact value is the full path's (:func:`~nczones.gcode.lexer.decimal_value`), or None (an expression)."""
    for letter, tree, *_rest in words:
        if letter == "R":
            return [_literal(tree, leaf)]
    return []


def may_cycle(text: Any) -> bool:
    """May ``text`` write a canned cycle the pass runs: a G word of 73 or 81-89 in it (a streamed file: a "73" or
    "8" in it).  Only then do motions hand the pass their literal words' texts (:func:`literal_tokens`); a cycle
    the test misses compares its levels without them (a close pair declines, as before cyc41).

    >>> may_cycle("G0 Z2\\nG98 G81 X1 R2"), may_cycle("G1 X81 Y73"), may_cycle("g 083 q1")
    (True, False, True)
    """
    if not isinstance(text, str):
        return "73" in text or "8" in text
    # "G" and "g" apart: a letter the regex engine scans for, not a class tested at every character (_may_compensate);
    # "g" only in a text that holds one (``in`` finds it with memchr: CAM output is upper case, line44)
    return any(re.search(g + r"[ \t]*0*(?:73|8[1-9])(?![0-9])", text) is not None for g in "Gg" if g in text)


def _literal(tree: Any, leaf: Any) -> str:
    """The source of a word's literal text (``P[k]``, or ``"n/d"`` for a literal of a line parsed afresh), whose
    exact value is the full path's (:func:`~nczones.gcode.lexer.decimal_value`); ``None`` for an expression."""
    if tree[0] != NUM:
        return "None"
    src: str = leaf(tree)
    if src.startswith("float(") and src.endswith(")"):
        return src[6:-1]
    q = tree[2]
    return repr(f"{q.numerator}/{q.denominator}")


def literal_tokens(words: Any, leaf: Any) -> list[str]:
    """The sources of a line's X, Y and Z words' literal texts (:func:`_literal`), in the order of the words: the
    values a motion's plan hands :func:`level_code` after its words' and R's (:func:`r_token`)."""
    return [_literal(tree, leaf) for letter, tree, *_rest in words if letter in "XYZ"]


def level_code(axes: list[tuple[int, int]], base: int, words: list[str]) -> list[str]:
    """The code a motion runs after its ends (in a text that :func:`may_cycle`): per axis word, what
    :meth:`Cycles.level` reads of the axis's exact position (``LV``): in G90 the word's literal text (``v[base +
    j]``, None for an expression), the offsets and the units it was moved in, whose exact value is the full
    path's ``w + offset`` (25.4 w in G20); None in G91 and where the word's double is not the word (``words``:
    the sources of the axes' doubles, ``(v[k] * st.half)`` where X may be a diameter)."""
    body = []
    for j, (k, i) in enumerate(axes):
        plain = words[j] == f"v[{k}]"
        body.append(f"LV[{i}] = None if st.inc else (v[{base + j}], off, st.inch)" if plain else f"LV[{i}] = None")
    return body


def cycle_call(others: list[str], axes: list[tuple[int, int]]) -> list[str]:
    """The code that runs a block as a cycle when the motion mode is one (and then returns), and declines
    a P, Q or L word in any other mode."""
    def val(x: str) -> str:
        return f"v[{others.index(x)}]" if x in others else "None"

    if any(x in "IJK" for x in others):
        body = ["if st.motion in CYC: raise D('I, J or K in a canned cycle block')"]
    else:
        pairs = "".join(f"({i}, v[{k}]), " for k, i in axes)
        tok = f"v[{len(others)}]" if "R" in others else "None"  # (r_token's, after the words' values)
        body = [f"if st.motion in CYC: return CY(({pairs}), {val('R')}, {val('P')}, {tok}, {val('q')}, {val('L')})"]
    if "P" in others:
        body.append("raise D('a word P outside G4, G64 and a dwell cycle')")
    if "q" in others:
        body.append("raise D('a word Q without M61, G73 or G83')")
    if "L" in others:
        body.append("raise D('a word L outside a canned cycle')")
    return body


def repeats(vl: float | None, bound: int) -> int:
    """A cycle block's repeats: 1 without L, else the integer LinuxCNC reads from L's double
    (``read_integer_value``: within 0.0001 of one; the full path's ``lcnc_integer`` of the exact value, whose
    double is L's); declined: not such an integer, below 1 (the full path's GC209), at or past ``bound`` (its
    unknown past ``max_loop_iterations``)."""
    if vl is None:
        return 1
    if not 0.5 <= vl < bound:
        raise ValueError("a canned cycle's L below 1 or at its repeat bound")
    n = math.floor(vl)
    if vl - n > 0.9999:
        n += 1
    elif vl - n > 0.0001:
        raise ValueError("a canned cycle's L that is not a whole number")
    if not 1 <= n < bound:
        raise ValueError("a canned cycle's L below 1 or at its repeat bound")
    return n


def _up(x: float) -> float:
    return math.nextafter(x, _INF)


class Cycles:
    """The modal state of canned cycles in the pass, and :meth:`run`, a cycle block's rows.

    A level (of the plane's normal axis) is a triple ``(double, token, error)``: two equal tokens are the same
    exact value; ``error`` 0.0: the double is within the module's bound of its exact value (a G90 row), else
    ``error`` bounds its distance (a G91 one, :meth:`_relative`)."""

    __slots__ = ("st", "declined", "retract", "last", "il", "il_off", "il_axis", "il_inch", "r", "r_tok", "z", "p", "mark",
                 "pos_tok", "tokens", "steady",
                 "lathe", "q", "peck_err", "pecks", "lits", "blank", "track")

    def __init__(self, st: Any, declined: type[Exception], machine: Any):
        self.st = st
        self.declined = declined  # the pass's Declined (this module is imported by its module)
        #: a lathe (its X words may be diameters, G7): its cycles decline, whatever the pass takes of it
        self.lathe = getattr(machine, "machine_type", "mill") != "mill" or bool(getattr(machine, "diameter_axes", ()))
        #: G99 (True: retract to R), G98 (False), None: the program has not set one (the full path notes it)
        self.retract: bool | None = None
        self.tokens = 0  # the last token handed out (:meth:`_fresh`)
        #: the motions but dwells (:func:`_moves`) when the last cycle block ended: the tool at its clear level
        #: while they are as many (a dwell, a tool change move nothing in the pass)
        self.mark = -1
        self.pos_tok: Any = 0  # the token of that clear level
        self.r: float | None = None  # R and the bottom as the program wrote them (doubles), sticky
        self.r_tok: Any = 0
        self.z: float | None = None
        #: the dwell of G82, G84, G86 and G89, sticky (None: none yet, the full path's exact 0)
        self.p: float | None = None
        self.q: float | None = None  # G73's and G83's peck, sticky
        #: the largest bound of a peck row's error (mm; 0.0: none yet), the pass's ``xerr`` of the normal
        #: axis from the first peck on (:meth:`_pecks`)
        self.peck_err = 0.0
        self.pecks = 0  # the pecks of the last peck block's holes (:meth:`_pecks`: its rows, :meth:`_sequence`)
        #: per axis, where the last motion that moved it left it, when that is a G90 literal word: ``(text, offsets,
        #: inch)`` (:func:`level_code`; ``text`` None: an expression), else None (a cycle block moved it since)
        self.blank = (None,) * len(st.axes)
        self.lits: list[Any] = list(self.blank)
        #: motions set ``lits`` (a text that may write a cycle, :func:`may_cycle`, without compensation): then a
        #: cycle block leaves its clear level's token there, valid until a motion moves that axis
        self.track = False
        self.end()

    def end(self) -> None:
        """A motion code other than a cycle's: the next cycle is a first one, with a new initial level."""
        self.last: int | None = None
        self.steady: tuple | None = None  # the template of the next hole line (_template)
        self.il: tuple | None = None  # the initial level (a level: the class's docstring)
        self.il_off: Any = None
        self.il_axis = -1
        self.il_inch = False  # the units the initial level was taken in (the full path converts it at G20/G21)

    def _fresh(self) -> int:
        """A token no level has: its exact value is not known to equal another's."""
        self.tokens += 1
        return self.tokens

    def level(self, i: int) -> Any:
        """The token of where the tool stands on axis ``i``: a G90 literal word's (:func:`level_code`), as R's
        (:meth:`_words`: its exact value, the offsets' ``id``, the units; the full path's exact ``w + offset``, the
        same for both), so a level equal to R by value is seen equal (``G0 Z2`` then ``G98 G81 ... R2``); the
        clear level's token when the last motion of the axis was a cycle block's (the tool left there: ``G80``,
        ``G0 X0 Y0``, then a cycle whose R is that level); else a fresh one (an expression, G91)."""
        lit = self.lits[i]
        if lit is None or lit[0] is None:
            return self._fresh()
        text, off, inch = lit
        if text == "=":  # (the clear level a cycle block left the tool at, :meth:`run`)
            return off
        return ("q", Fraction(text) if "/" in text else decimal_value(text)), id(off), inch

    def below(self, a: tuple, b: tuple) -> bool:
        """Is level ``a`` below level ``b`` exactly, as the full path compares them (``_level_lt``)?  Equal
        tokens: the same exact value.  Else the doubles' difference must exceed both levels' bounds (the
        module's docstring, and a G91 level's own error); a closer pair declines."""
        if a[1] == b[1]:
            return False
        tol = (abs(a[0]) + abs(b[0]) + self.st.offb2[self.il_axis]) * _REL + a[2] + b[2] + 1e-300
        d = b[0] - a[0]
        if d > tol:
            return True
        if d < -tol:
            return False
        raise self.declined("canned cycle levels too close to compare exactly")

    def _axes(self, mode: int) -> tuple[int, int, int]:
        """The machine axes of the plane's first, second and normal axis; declines the states the full path
        notes or refuses."""
        st = self.st
        names = _PLANES.get(st.plane)
        if names is None or self.retract is None or st.unset:
            raise self.declined("a canned cycle before the program sets the plane, its retract mode, units, distance "
                           "mode and work offset")
        if self.lathe:  # (an X word may be a diameter: G7)
            raise self.declined("a canned cycle on a lathe")
        if not st.feed > 0.0:
            raise self.declined("a canned cycle without a positive feed")
        spin = MODES[mode][3]
        if spin is not None and (st.spindle == 0 or (spin == 1 and st.spindle != 1)):
            raise self.declined("G84 without M3, or G86 with the spindle stopped")
        if mode == 84 and st.plane != 17:  # (LinuxCNC's G84 outside G17 swaps its axes: the full path's own rows)
            raise self.declined("G84 outside G17")
        index = st.index
        if any(n not in index for n in names):
            raise self.declined("a canned cycle on a machine without the plane's axes")
        return index[names[0]], index[names[1]], index[names[2]]

    def _words(self, mode: int, first: bool, z: float | None, vr: float | None, vp: float | None,
               text: str | None) -> tuple:
        """The block's R (and its token: its exact value for a literal, ``text``, else a fresh one) and
        bottom, sticky when not written; the dwell checked."""
        if vr is None:
            if first or self.r is None:
                raise self.declined("a canned cycle without R the first time")
            vr, rtok = self.r, self.r_tok
        elif text is None:
            rtok = self._fresh()
        else:
            rtok = ("q", Fraction(text) if "/" in text else decimal_value(text))
        if z is None:
            if first or self.z is None:
                raise self.declined("a canned cycle without its bottom the first time")
            z = self.z
        kind = MODES[mode][1]
        if kind:
            if vp is None:
                if kind == 1 and (first or self.p is None):
                    raise self.declined("a dwell cycle without P the first time")
            elif not vp > 0.0:  # a double above 0 is an exact value above 0 (the full path's GC209 below 0)
                raise self.declined("a cycle's dwell time that is not positive")
            else:
                self.p = vp
        elif vp is not None:
            raise self.declined("a word P outside G4, G64 and a dwell cycle")
        return vr, rtok, z

    def run(self, pairs: tuple[tuple[int, float], ...], vr: float | None, vp: float | None,
            text: str | None, vq: float | None = None, vl: float | None = None) -> bool:
        """A cycle block (the plan's ``CY``): its rows (the module's docstring); False (the program goes on)."""
        if not (vr is None and vp is None and vq is None and self.steady is not None and self._steady(pairs, vl)):
            self._general(pairs, vr, vp, text, vq, vl)
        lits = self.lits
        lits[:] = self.blank  # (the block moved the plane's axes: no literal word is where they stand)
        if self.track:  # (the tool at the clear level: its token, until a motion moves the normal axis)
            lits[self.il_axis] = ("=", self.pos_tok, None)
        return False

    def _general(self, pairs: tuple[tuple[int, float], ...], vr: float | None, vp: float | None,
                 text: str | None, vq: float | None, vl: float | None) -> None:
        """Any cycle block: its words read, its levels compared, its rows; the template of the next hole."""
        self.steady = None
        st = self.st
        mode = st.motion
        axes = ia, ib, ic = self._axes(mode)
        words = dict(pairs)
        if any(i not in axes for i in words):
            raise self.declined("an axis word off the plane's axes in a canned cycle")
        first = self.last != mode
        vr, rtok, z = self._words(mode, first, words.get(ic), vr, vp, text)
        self._peck_word(mode, first, vq)
        inch = st.inch
        if inch:  # (millimetres: ``fl(w * fl(25.4))``, as LinuxCNC's canon, :mod:`.double_units`)
            words = {i: w * _INCH for i, w in words.items()}
        try:
            reps = repeats(vl, st.max_iterations)
        except ValueError as exc:
            raise self.declined(str(exc)) from None
        off, pos = st.off, st.pos
        err = st.err[ic]
        cur = (pos[ic], self.pos_tok if self.mark == _moves(st) else self.level(ic), err or 0.0)
        if self.il is None:
            self.il, self.il_off, self.il_axis, self.il_inch = cur, off, ic, inch
        elif self.il_axis != ic or self.il_off is not off or self.il_inch != inch:
            raise self.declined("a plane, offset or units change while a canned cycle is modal")
        mr, mz = (vr * _INCH, z * _INCH) if inch else (vr, z)
        if st.inc:
            r, cc = self._relative((mr, (rtok, inch)), mz, cur, ic)
        else:
            r, cc = (mr + off[ic], (rtok, id(off), inch), 0.0), (mz + off[ic], self._fresh(), 0.0)
            if st.chained and (cur[2] or self.il[2]):  # (the levels of a G91 chain: their rows keep its error)
                self._chain(ic, max(cur[2], self.il[2]))
        if self.below(r, cc):
            raise self.declined("a canned cycle's R below its bottom")
        clear, cur = self._up_to_r(r, cur, axes)
        if mode in _PECKS:
            self.pecks = self._peck_count(vr, z, ic)
        aa, bb = pos[ia], pos[ib]
        for rep in range(reps):
            if rep == 1 and len(st.columns) == 3:  # (a mill's three axes, not at a window's end)
                seq = self._sequence(r, cc[0], clear)
                if len(st.columns[0]) + len(seq[0]) * reps < st.rows:
                    steps = (words.get(ia), words.get(ib)) if st.inc else (None, None)
                    self._repeat_rows(reps - 1, (aa, bb), steps, seq, axes)
                    break
            if st.inc:
                aa, bb = self._increment(ia, words.get(ia), aa), self._increment(ib, words.get(ib), bb)
            else:
                aa = words[ia] + off[ia] if ia in words else aa
                bb = words[ib] + off[ib] if ib in words else bb
            self._position(aa, bb, r, None if rep else cur, clear, axes)
            if mode in _PECKS:
                self._pecks(aa, bb, r, axes, mode == 83)
            self._hole(aa, bb, cc[0], (r, clear), mode, axes)
        self.mark, self.pos_tok = _moves(st), clear[1]
        self.r, self.r_tok, self.z, self.last = vr, rtok, z, mode
        self.steady = self._template(r, cc[0], clear, axes)

    def _sequence(self, r: tuple, cc: float, clear: tuple) -> tuple[list[float], int, int]:
        """The levels of a repeat's rows after its first (and of every repeat of a hole line, :meth:`_steady`),
        where the tool starts at the clear level: the position at the clear level and, where it is above R, the
        rapid to R (:meth:`_position`), then the hole's (:meth:`_hole`); the index of the dwell's row (-1: none)
        and the repeat's rapids."""
        _peck, dwell, out, _spin = MODES[self.st.motion]
        zs = [clear[0], r[0]] if self.below(r, clear) else [clear[0]]
        rapids = len(zs)
        if _peck:  # (the pecks' rows, the same doubles as _pecks's: its count, kept in ``pecks``)
            rr, q, out83 = r[0], self.q, _peck == 83
            assert q is not None
            if self.st.inch:
                q = q * _INCH  # (as _pecks: the same doubles)
            for k in range(1, self.pecks + 1):
                depth = rr - k * q
                zs += (depth, rr, depth + _BACK_OFF) if out83 else (depth, depth + _BACK_OFF)
            rapids += (1 + out83) * self.pecks
        at = len(zs) + 1 if dwell else -1  # (the second after the position's)
        zs += [cc, cc] if dwell else [cc]
        if out == FEED_TO_R:
            zs.append(r[0])
            if self.below(r, clear):
                zs.append(clear[0])
                rapids += 1
        else:
            zs.append(clear[0])
            rapids += out == RAPID_OUT
        return zs, at, rapids

    def _repeat_rows(self, n: int, at: tuple[float, float], steps: tuple, seq: tuple, axes: tuple[int, int, int]) -> None:
        """``n`` repeats' rows at once, from the hole ``at`` plus the G91 increments ``steps`` (None: the same
        hole) before each, the levels ``seq`` (:meth:`_sequence`), on a machine of the plane's three axes, the
        window not full before the last (the same rows :meth:`_increment`, :meth:`_position` and :meth:`_hole`
        make).  The holes ``fl(x + w)`` of a G91 axis are a chain of ``n`` steps from ``x``: each step adds at
        most ``(|w| + |y|) 2**-52`` rounded up (:meth:`_increment`) and ``|y|`` is at most the larger of the first
        and last hole's (the doubles move one way: ``fl`` is monotone), so ``e + n (|w| + max |y|) 2**-52``, each
        float rounded up (a rounding up adds at least the least subnormal, above each step's half of it), bounds
        every hole's error (``e``: the chain's, or a G90 row's bound); it is set before a window can be handed
        over."""
        st = self.st
        ia, ib, ic = axes
        zs, dwell, rapids = seq
        if self.peck_err > st.xerr[ic] and st.motion in _PECKS:  # (a window handed over since: full())
            st.xerr[ic] = self.peck_err
        aa, bb = at
        wa, wb = steps
        cols = st.columns
        ca, cb, cz = cols[ia], cols[ib], cols[ic]
        m = len(zs)
        f, t = self._units()
        for i, w, x0 in ((ia, wa, aa), (ib, wb, bb)):
            if w is not None:
                e = st.err[i]
                x1 = x0 + n * w  # (a bound of the last hole's magnitude: doubled, and rounded up below)
                self._chain(i, _up((e if e is not None else self._g90(x0, i))
                                   + _up(n * _up((f * abs(w) + 2.0 * max(abs(x0), abs(x1)) + 1.0) * _EPS2 + t))))
        for _ in range(n):
            if wa is not None:
                aa += wa
            if wb is not None:
                bb += wb
            ca.extend((aa,) * m)
            cb.extend((bb,) * m)
            cz.extend(zs)
            if dwell >= 0:
                st.dwelt(len(cz) - m + dwell)
        st.rapids += n * rapids
        pos = st.pos
        pos[ia], pos[ib], pos[ic] = aa, bb, zs[-1]

    def _relative(self, rw: tuple, z: float, cur: tuple, ic: int) -> tuple[tuple, tuple]:
        """G91's levels: R ``fl(R' + il')`` above the initial level, the bottom ``fl(r + Z')`` below R (the full
        path's exact ``R + il`` and ``r + Z``).  As a G91 chain's step (:meth:`~.doubles._Pass._straight_ends`):
        with ``|il' - il| <= e`` (the initial level's error, or a G90 row's bound, ``(2 |il'| + 2 offsets)
        2**-53`` plus the G20 rows' ``2**-1000``), ``|R' - R| <= |R'| 2**-53`` and one rounding,
        ``|r - (R + il)| <= e + (|R'| + |r|) 2**-53``, each float of the bound rounded up; the bottom likewise
        from R's.  The normal axis's chain error (``st.err``, ``xerr``) is set to the largest of these and of
        where the tool stands before any row is added: it bounds every row of the block on that axis."""
        vr, rtok = rw
        il = self.il
        assert il is not None
        ei = il[2] or self._g90(il[0], ic)
        f, t = self._units()
        rv = vr + il[0]
        er = _up(ei + _up((f * abs(vr) + abs(rv)) * _EPS2 + t))
        cv = rv + z
        ec = _up(er + _up((f * abs(z) + abs(cv)) * _EPS2 + t))
        e = max(cur[2] or self._g90(cur[0], ic), ei, er, ec)
        self._chain(ic, e)
        return (rv, ("inc", rtok, il[1]), er), (cv, self._fresh(), ec)

    def _units(self) -> tuple[float, float]:
        """The factor of a G91 step's word and the absolute term its error bound takes: ``(1, 0)`` in G21; in G20
        ``(3, 2**-1000)`` (the step ``fl(fl(w * 25.4) + x)``: :func:`~.double_units.inch_ends`, which says why)."""
        return (3.0, _TA) if self.st.inch else (1.0, 0.0)

    def _g90(self, x: float, i: int) -> float:
        """The bound of a G90 row ``x`` of axis ``i`` (:func:`~.double_units.chain_start`'s, with its G20 term)."""
        return _up((2.0 * abs(x) + self.st.offb2[i]) * _EPS2 + _TA)

    def _chain(self, i: int, e: float) -> None:
        """Axis ``i``'s rows from here on are G91 ones within ``e`` of their exact values (the pass's chain)."""
        st = self.st
        old = st.err[i]
        if old is None or e > old:
            st.err[i] = e
        if e > st.xerr[i]:
            st.xerr[i] = e
        st.chained = True

    def _increment(self, i: int, w: float | None, x: float) -> float:
        """One repeat's hole on axis ``i`` in G91: ``fl(x + w)`` (the full path's exact ``aa + inc``), its error
        grown as a G91 chain's step (:meth:`~.doubles._Pass._straight_ends`); ``x`` without a word."""
        if w is None:
            return x
        st = self.st
        y = x + w
        e = st.err[i]
        if e is None:
            e = self._g90(x, i)
        f, t = self._units()
        self._chain(i, _up(e + _up((f * abs(w) + abs(y)) * _EPS2 + t)))
        return y

    def _peck_word(self, mode: int, first: bool, vq: float | None) -> None:
        """G73's and G83's Q (sticky; above 0: the full path's GC209 else); a Q in another cycle declines."""
        if mode not in _PECKS:
            if vq is not None:
                raise self.declined("a word Q without M61, G73 or G83")
            return
        if vq is None:
            if first or self.q is None:
                raise self.declined("a peck cycle without Q the first time")
            vq = self.q
        if not vq > 0.0:  # a double above 0 is an exact value above 0
            raise self.declined("a peck that is not positive")
        self.q = vq

    def _peck_count(self, vr: float, z: float, ic: int) -> int:
        """How many pecks a hole of this block makes: LinuxCNC's loop (``_linuxcnc_pecks``, the full path's) on the
        doubles of the program's R, bottom and Q.  In G90 those are the words'.  In G91 R is ``fl(R' + old)`` and
        the bottom ``fl(r + Z')``, ``old`` the double of the exact initial level in program units (the full path's
        ``to_float(il - offset)``, divided by 25.4 in G20): :meth:`_olds` gives every double it may be, and the
        count must be the same for each (else the block declines)."""
        q = self.q
        assert q is not None  # (_peck_word)
        if not self.st.inc:
            return self._count(vr, z, q)
        counts = {self._count(r, r + z, q) for r in {vr + old for old in self._olds(ic)}}
        if len(counts) != 1:
            raise self.declined("a G91 peck count the initial level's doubles do not decide")
        return counts.pop()

    def _count(self, r: float, bottom: float, q: float) -> int:
        """LinuxCNC's peck loop ``for (d = r - q; d > bottom; d -= q)`` in doubles; declined at the loop bound
        (the full path's too_many: unknown past it)."""
        n, d = 0, r - q
        while d > bottom:
            n += 1
            if n >= self.st.max_iterations:
                raise self.declined("a peck cycle at its iteration bound")
            d -= q
        return n

    def _olds(self, ic: int) -> list[float]:
        """The doubles the initial level's exact value in program units may round to (G91 pecks,
        :meth:`_peck_count`).  Its exact value is known when its token is a literal's (:meth:`level`, or a G90
        R's) in the offsets now: ``w`` (25.4 w when moved in G20), one double.  Else it lies within the level's
        bound ``e`` of its double ``il'`` (a G90 row's, :meth:`_g90`, or a G91 chain's): the program value within
        ``e + (|off'| + |c|) 2**-52`` of ``c = fl(il' - off')`` (the offset's double within half an ulp of the
        exact one, the subtraction one rounding), in G20 within that over 25 plus ``|c_in| 2**-50`` of
        ``c_in = fl(c / fl(25.4))`` (fl(25.4) and the division: under 2 ulps); ``fl`` is monotone, so the double
        of any value in that interval lies between the doubles at its ends, every one of which is listed
        (declined past 4096)."""
        st = self.st
        il = self.il
        assert il is not None
        tok, off, inch = il[1], st.off[ic], st.inch
        if tok.__class__ is tuple and tok[0].__class__ is tuple and tok[0][0] == "q" and tok[1] == id(st.off):
            mm = tok[0][1] * (Fraction(254, 10) if tok[2] else 1)
            return [float(mm / Fraction(254, 10) if inch else mm)]
        c = il[0] - off
        e = _up(_up(il[2] or self._g90(il[0], ic)) + _up((abs(off) + abs(c)) * _EPS2))
        if inch:
            c = c / _INCH
            e = _up(e / 25.0 + abs(c) * 2.0**-50)
        lo, hi = math.nextafter(c - e, -_INF), _up(c + e)
        olds = [lo]
        while olds[-1] < hi:
            if len(olds) > 4096:
                raise self.declined("a G91 peck cycle whose initial level is known too loosely")
            olds.append(_up(olds[-1]))
        return olds

    def _pecks(self, aa: float, bb: float, level: tuple, axes: tuple[int, int, int], out: bool) -> None:
        """The pecks before the last feed: per peck a feed to ``R - k Q``, G83's rapid out to R (``out``), a
        rapid to 0.254 mm above the peck (the full path's ``_cycle``; G73 and G83 alike but for the rapid out).  As
        many as the full path makes (:meth:`_peck_count`, ``pecks``).  A peck's row is
        ``fl(R' - fl(k Q'))``: its distance from the exact ``R - k Q`` is at most ``|R' - R| + 2 k |Q'| 2**-53 +
        |row| 2**-53`` (R''s bound is the module's, ``(2 |R'| + 2 offsets) 2**-53``, plus a G91 R's own error
        ``level[2]``; ``Q'`` within half an ulp of ``Q``), the back-off's one rounding and 0.254's more: the bound
        ``peck_err`` (that sum over every row of the block, taken twice over and rounded up, plus R's G91 error)
        is added to the normal axis's widening (the pass's ``xerr``: every row of the windows from the first peck
        on)."""
        st = self.st
        q = self.q
        assert q is not None  # (_peck_word)
        n, r = self.pecks, level[0]
        if st.inch:  # (the rows' peck in millimetres: within 2.52 ulps of 25.4 Q, inside the bound's 8 ulps)
            q = q * _INCH
        ic = axes[2]
        top = abs(r) + abs(r - n * q) + _BACK_OFF
        err = _up(_up((2.0 * abs(r) + st.offb2[ic] + 2.0 * n * q + 2.0 * top + 1.0) * 2.0**-51) + level[2])
        if err > self.peck_err:
            self.peck_err = err
        if err > st.xerr[ic]:
            st.xerr[ic] = err
        cols = st.columns
        if len(cols) == 3 and len(cols[0]) + 3 * n < st.rows:  # a mill's three axes, away from a window's end
            _peck_rows(st, axes, aa, bb, r, q, n, out)
            return
        for k in range(1, n + 1):
            depth = r - k * q
            _row(st, axes, aa, bb, depth, False)  # the peck
            if out:
                _row(st, axes, aa, bb, r, True)  # out to R
            _row(st, axes, aa, bb, depth + _BACK_OFF, True)  # back down, backed off

    def _template(self, r: tuple, cc: float, clear: tuple, axes: tuple[int, int, int]) -> tuple | None:
        """What the next block makes when it is a hole line (X and Y words, L) in the state this one leaves
        (:meth:`_steady`): the tool at the clear level, the same initial level, R, bottom, dwell, peck, retract
        mode, distance mode, offsets and plane.  Its branches are then these: "up to R" where ``il < R``; the tool
        (at the clear level, the same token) above R exactly where the clear level is, so every repeat's rows are
        the same levels (:meth:`_sequence`; the pecks as many: LinuxCNC counts them from the same R, bottom and
        Q).  In G91 R and the bottom are the same doubles (the same initial level, R and bottom words): the normal
        axis's chain error bounds them already.  In G20 the levels are the block's millimetres and a hole line's
        words are scaled as :meth:`_general` scales them (``fl(w * fl(25.4))``: the same doubles, the same bounds).
        None: a comparison too close to call (the next block then runs :meth:`_general`, which declines), or a
        block in G90 with a G91 chain open."""
        st = self.st
        mode = st.motion
        if st.chained and not st.inc:
            return None
        try:
            up = self.below(self.il, r)  # type: ignore[arg-type]
            seq = self._sequence(r, cc, clear)
        except self.declined:
            return None
        return (mode, st.plane, self.retract, st.off, axes, st.inc, r[0], up, seq, st.inch)

    def _steady(self, pairs: tuple[tuple[int, float], ...], vl: float | None) -> bool:
        """A hole line (no R, bottom, P or Q) in the state the last cycle block left (:meth:`_template`), on a
        machine of the plane's three axes, not at a window's end: its rows from the template; False (nothing
        done): not such a line."""
        st = self.st
        mode, plane, retract, off, axes, inc, r, up, seq, inch = self.steady  # type: ignore[misc]
        cols = st.columns
        n = len(cols[0])
        if st.motion != mode or st.plane != plane or self.retract != retract or st.off is not off \
                or self.mark != st.row0 + n - 1 - st.dwells or not st.feed > 0.0 or st.inc != inc \
                or st.inch != inch or (st.chained and not inc) or len(cols) != 3 \
                or (mode in (84, 86) and st.spindle != 1):
            return False  # (G84 and G86 after M3: else _general checks the spindle, and declines G84's)
        try:
            reps = 1 if vl is None else repeats(vl, st.max_iterations)
        except ValueError as exc:
            raise self.declined(str(exc)) from None
        if n + 1 + len(seq[0]) * reps >= st.rows:
            return False
        ia, ib, ic = axes
        pos = st.pos
        aa, bb = pos[ia], pos[ib]
        wa = wb = None
        for i, v in pairs:
            if i == ia:
                wa = v * _INCH if inch else v  # (millimetres, as _general's words)
            elif i == ib:
                wb = v * _INCH if inch else v
            else:
                return False
        ca, cb, cz = cols[ia], cols[ib], cols[ic]
        if up:  # up to R where the tool stands
            ca.append(aa), cb.append(bb), cz.append(r)
            st.rapids += 1
        if reps == 1 and not inc:  # (the most common line: _repeat_rows's rows, inline)
            zs, dwell, rapids = seq
            m = len(zs)
            aa = aa if wa is None else wa + off[ia]
            bb = bb if wb is None else wb + off[ib]
            for z in zs:
                ca.append(aa), cb.append(bb), cz.append(z)
            if dwell >= 0:
                st.dwelt(len(cz) - m + dwell)
            if self.peck_err > st.xerr[ic] and mode in _PECKS:  # (as _repeat_rows)
                st.xerr[ic] = self.peck_err
            st.rapids += rapids
            pos[ia], pos[ib], pos[ic] = aa, bb, zs[-1]
            self.mark = st.row0 + len(cz) - 1 - st.dwells
            return True
        if inc:
            self._repeat_rows(reps, (aa, bb), (wa, wb), seq, axes)
        else:
            hole = (aa if wa is None else wa + off[ia], bb if wb is None else wb + off[ib])
            self._repeat_rows(reps, hole, (None, None), seq, axes)
        self.mark = st.row0 + len(cols[0]) - 1 - st.dwells
        return True

    def _up_to_r(self, r: tuple, cur: tuple, axes: tuple[int, int, int]) -> tuple[tuple, tuple]:
        """The rapid up to R where the tool stands when the initial level is below R; the clear level (R under
        G99, else the initial level, or R when it was below) and the level the tool is at."""
        ia, ib, ic = axes
        st = self.st
        old = self.il
        assert old is not None  # (set by _general before)
        if not (st.first_row[ia] and st.first_row[ib] and st.first_row[ic]):
            st.moved(axes)
        if self.below(old, r):
            _row(st, axes, st.pos[ia], st.pos[ib], r[0], True)  # up to R, where the tool stands
            old = cur = r
        return (r if self.retract else old), cur

    def _position(self, aa: float, bb: float, r: tuple, cur: tuple | None, clear: tuple,
                  axes: tuple[int, int, int]) -> None:
        """A repeat's rapids to the hole and R: at the current level then to R when the tool is above R (the
        first repeat: ``cur`` is where the tool stands; None after), else at the clear level, then to R when the
        clear level is above R."""
        st = self.st
        if cur is not None and self.below(r, cur):
            _row(st, axes, aa, bb, cur[0], True)  # to the hole at the current level
            _row(st, axes, aa, bb, r[0], True)
        else:
            _row(st, axes, aa, bb, clear[0], True)  # to the hole at the clear level
            if self.below(r, clear):
                _row(st, axes, aa, bb, r[0], True)

    def _hole(self, aa: float, bb: float, cc: float, levels: tuple[tuple, tuple], mode: int,
              axes: tuple[int, int, int]) -> None:
        """The feed to the bottom, the dwell, the way out (:data:`MODES`): a rapid or a feed to the clear level,
        or G85's feed to R and a rapid to the clear level when it is another (exactly: above R)."""
        st = self.st
        r, clear = levels
        _peck, dwell, out, _spin = MODES[mode]
        _row(st, axes, aa, bb, cc, False)
        if dwell:
            _row(st, axes, aa, bb, cc, False, dwell=True)
        if out == FEED_TO_R:
            _row(st, axes, aa, bb, r[0], False)
            if self.below(r, clear):
                _row(st, axes, aa, bb, clear[0], True)
        else:
            _row(st, axes, aa, bb, clear[0], out == RAPID_OUT)


def _peck_rows(st: Any, axes: tuple[int, int, int], aa: float, bb: float, r: float, q: float, n: int,
               out: bool) -> None:
    """:meth:`Cycles._pecks`'s ``n`` pecks appended at once, the same doubles as its :func:`_row` calls (on a
    machine of the three axes, the window not full before the last)."""
    ia, ib, ic = axes
    ca, cb, cz = st.columns[ia], st.columns[ib], st.columns[ic]
    for k in range(1, n + 1):
        depth = r - k * q
        if out:
            ca.extend((aa, aa, aa))
            cb.extend((bb, bb, bb))
            cz.extend((depth, r, depth + _BACK_OFF))
        else:
            ca.extend((aa, aa))
            cb.extend((bb, bb))
            cz.extend((depth, depth + _BACK_OFF))
    st.rapids += (1 + out) * n
    if n:
        pos = st.pos
        pos[ia], pos[ib], pos[ic] = aa, bb, cz[-1]


def _moves(st: Any) -> int:
    """The pass's motions so far but its dwells (a dwell is a row where the machine stands)."""
    moves: int = st.row0 + len(st.columns[0]) - 1 - st.dwells
    return moves


def _row(st: Any, axes: tuple[int, int, int], a: float, b: float, c: float, rapid: bool, dwell: bool = False) -> None:
    """Append the row of a motion (or a dwell) ending at ``a, b, c`` on ``axes`` (the rest where they are)."""
    pos, cols = st.pos, st.columns
    ia, ib, ic = axes
    pos[ia], pos[ib], pos[ic] = a, b, c
    for i, col in enumerate(cols):
        col.append(pos[i])
    n = len(cols[0])
    if dwell:
        st.dwelt(n - 1)
    if rapid:
        st.rapids += 1
    if n >= st.rows:
        st.full()
        err = st.cyc.peck_err  # (full() set the xerr of the rows it kept from the G91 chains' alone)
        if err > st.xerr[ic]:
            st.xerr[ic] = err
