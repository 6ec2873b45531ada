"""The double pass: a program's motion as the controller's doubles, enclosed exactly, for a quick proof.

The full interpreter (:mod:`nczones.gcode.program`, :mod:`nczones.gcode.interpreter`) carries an exact
value beside every double and builds a :class:`~nczones.motion.Segment` per motion; that is what a proof
needs when a motion comes near a zone, and most of the time of a parametric program (expressions on every
line, o-word loops).  The double pass runs a program of a small subset of LinuxCNC's language computing
only the doubles the controller computes, and returns the machine positions of its motions as columns of
doubles with a bound on how far each can be from the exact position the full interpreter would give.  A
proof over boxes widened by that bound (:mod:`nczones.prover.doubles`) is a sound over-approximation of
the full path's proof: when every box fits, every motion of the full path fits; when one does not, or the
program leaves the subset, the pass *declines* and the full path runs as if it had not been tried.

Why the bound holds
-------------------
Every double operation here is the one :func:`~nczones.gcode.expr.evaluate` makes, in the same order
(``+ - * /`` inline, every other operator and function through the same
:func:`~nczones.gcode.expr.binary_op` and :func:`~nczones.gcode.expr.unary_op`), so every condition, every
loop count and every word's double is the full path's.  A word's exact value is its shadow when there is
one, which is kept only when ``float(shadow) == double``, else the double itself: in both cases it is
within half an ulp of the double.  The machine coordinate is the word plus the exact work offset; here it
is the double sum ``d + float(offset)``.  So the exact coordinate ``m`` and the double ``m'`` here satisfy
``|m - m'| <= (|d| + |offset| + |m'|) * 2**-53 <= (2|m'| + 2|offset|) * 2**-53`` (plus the smallest
subnormal), and :meth:`DoublePath.enclosure` widens by more than that.  A straight move (G1, and G0 in
either rapid mode: each axis moves monotonically from its start to its end) stays inside the box of its
end points, so the box of a run of motions' end points, with the point before the first, holds every
position of those motions.  An arc (G2/G3 in G17, G18 or G19) is not: each arc row also has its own box
(:mod:`nczones.gcode.linuxcnc.double_arcs`, whose docstring says why it holds the full path's exact arc, an
R arc's irrational centre included; on the plane's first and second axes, :data:`_ARC_PLANES`), which
:meth:`DoublePath.enclosure` joins to the rows' box; a helix's third axis moves monotonically, so the rows
hold it.  The pass keeps a quick box of each arc (``r_screen``,
``ij_screen``: no sweep, no square root for R) and :meth:`DoublePath.refine` narrows it to the sweep's box
(``r_arc``, ``ij_arc``) when a proof needs it; each holds the arc, so their intersection does.  ``G43 H<n>`` adds the machine's ``[tool_lengths]``
entry to the tool axis's work offset, exactly, before the one rounding of ``d + float(offset)``, and the
bound's offset term covers the largest work offset plus the largest length.  A G91 move adds the word's double to
the row before (the full path adds the word's exact value to the machine position: the offsets cancel): its
error grows with each step of the chain, and :meth:`_Pass._straight_ends` bounds it (``DoublePath.inc_bound``, the
largest of a window's rows, added to the widening); a G90 move of the axis ends the chain.  In G20 a word's
millimetres are ``fl(d * fl(25.4))``, two roundings more: a G90 row is within ``3.6 (|m'| + |offset|) 2**-53`` of the
full path's exact ``25.4 w + offset``, still inside the widening, and a G91 step adds its own larger term to the chain
(:mod:`.double_units`, which derives both).

The subset
----------
The LinuxCNC dialect; numbered parameters ``#1``..``#5601`` that are not controller state, local named
parameters; ``o`` ``if``/``elseif``/``else``/``endif`` and ``while``/``endwhile`` properly nested with
labels not reused; ``o.. sub``/``endsub`` at the top level, and ``o.. call`` of a sub defined before the
call in the flow (not recursive, at most :data:`MAX_CALLS` open: the caller's #1..#30 and local named
parameters saved, #1..#n set from the arguments, the body run with its own local names, the caller's
restored at the endsub, as the full path's
``Parameters.push_scope``/``pop_scope``) in a program that does not name ``#<_value>``; G0 G1 G2 G3 G4 G17
G18 G19 G20 G21 G40 G43 G49 G54-G59 G61 G61.1 G64 G80 G90 G91 G91.1 (written out: the
full path's and LinuxCNC's start-up arc-centre mode, which the pass assumes) G94 with literal codes, F, X Y Z words of the machine's axes, N, S (not negative), one of M3 M4 M5
M7 M8 M9 a block, and M2/M30 alone to end; plain comments.  A tool: ``T<n>``, ``M6`` and ``M61 Q<n>`` with
literal numbers (:meth:`_Pass._tool_change`: nothing the pass computes reads the tool in the spindle; M6 on a
machine whose tool change moves, ``[machine] tool_change_*``, declines).  A dwell: ``G4 P<seconds>`` (P
above 0, no axis word) is a row where the machine stands, as the full path's ``DWELL`` segment.  The path
mode: G61, G61.1 and G64 without P or Q (:attr:`DoublePath.modes`, from the next motion on, its block's
included), and ``G64 P<p> [Q<q>]`` (p above 0; Q only in a block without axis words or a motion code: its
motions blend within ``p + q`` of the programmed path, ``2p`` without Q,
:attr:`DoublePath.tolerance`, which the proof adds to the margin of every motion), which with the dwells say which corners LinuxCNC blends (:meth:`DoublePath.blended`); the motions
and their rows are the same in every mode (the full path emits every motion; which ones LinuxCNC drops in a
blended corner is the proof's and the arc check's question, :meth:`_Pass.tiny`, answered for every mode the
program has been in).  G91: straight moves (the chain's bound above) and arcs, whose ends are a straight move's
and whose box is computed with the offsets' bound grown by its plane axes' chain errors at its start and end
(:func:`~.double_arcs.chain_offb` says why that holds a G91 arc's centre, ends and radii; an arc whose checks
cannot be made within them declines as a near-tolerance arc does), but where X may be a diameter.  G20:
straight moves, G90 and G91, G20/G21 anywhere, and arcs (I/J and R, :mod:`.double_units`); a G43 or G49 in other
units than the tool length applied declines (LinuxCNC 2.9 does not convert it: the full path's unknown), and so
does G20 where X may be a diameter (a lathe, or after G7).  Arcs: in
the plane the program has set, or the machine file's (G17, G18 or G19; the planes may change between arcs: each
arc's box is on its own plane's axes, ``DoublePath.arc_axes`` and ``arc_planes``), on a
machine with the plane's axes, with the plane's centre words (G17 I/J, G18 K/I, G19 J/K: G91.1, LinuxCNC's
default) or R, and X, Y, Z words; ``G43 H<n>`` with a literal register of the machine's
``[tool_lengths]`` (not on a machine with a tool tip zone), and ``G49``.  A motion while the units, distance mode or work offset (an arc: also the
plane) are still the machine file's runs in the machine file's codes, as the full path's does, which notes each
such group at the first motion that needs it: the pass records the same notes (:attr:`DoublePath.assumed`).
A lathe (``type = "lathe"`` or
``diameter_axes = ["X"]``; :mod:`.double_lathe` says what a lathe changes and why the bound holds): G7 and G8,
an X word's double halved in G7 (``st.half``; a G91 increment and an arc's X end too; I, K and R never), a
machine with X diameters starting in G7; G96 with S (D its speed limit) and G97, which move nothing; a lathe
with tool solids or other diameter axes, G70-G72, G76, G33, G95, G96 without S, D without G96 and, on a machine
that is not a lathe, a G7 after a line with an X word decline.  Everything else declines:
other codes and words, G64 with Q but not P or with P not above 0, a machine that starts in G20 or G91, block delete, magic comments,
other subroutine forms (a value returned, ``return``, a call of a sub defined after it or in a file), other
loops, a G1 without a positive feed, a loop at its iteration bound, a
parameter read of controller state, any evaluation error; an arc with P or the centre
word of the plane's normal, without axis words or a centre, of a radius about 0, with ends near or past
the arc tolerance, an R arc of a chord about
0 or about ``2|R|`` or longer (:mod:`.double_arcs`: the full path decides those), an arc after a motion
LinuxCNC may drop in a blended corner (:meth:`_Pass.tiny`) unless that motion is the program's first with the
start's doubles (:meth:`_Pass.lone`: the full path notes a dropped motion only after another) or a dwell
(which stops the machine: nothing is dropped across it, :meth:`_Pass.dwell_at`); I, J or R
without G2/G3, H without G43, G43 without H or with H0.

Canned cycles (:mod:`.double_cycles`): G73, G81-G86 and G89 (``P`` above 0; ``Q`` above 0: a Q in a line
without an M word is a value, G73's and G83's alone) with L repeats, in G90 and G91 (G73 and G83 where the
initial level's doubles decide LinuxCNC's peck count), in the
plane the program has set (G84 in G17), after the program set G98 or G99, in G21 and G20 (not on a lathe; G84
after M3, G86 with the spindle turning: the pass follows M3, M4, M5 and M6's stop), one row per motion of the full
path's ``Interpreter._cycle``; R, the bottom, P and Q sticky; the levels compared only where the doubles
decide the exact comparison or both are known exactly (a literal R, a G90 motion's literal word where the tool
stands: in a text that may write a cycle, motions hand the cycle module their literal words) (a closer pair, an offset, plane or units change while a cycle is modal, R below the
bottom decline); the peck rows widened by their drift, G91 rows by their chain's error (``xerr``).

Cutter compensation (:mod:`.double_comp`): on a machine with ``cutter_compensation = "linuxcnc"`` (not a lathe),
G40, and G41/G42 with a literal or computed ``D`` (a tool of ``[tool_diameters]``) or without (the tool in the
spindle, ``T`` and ``M6``/``M61 Q`` followed), or G41.1/G42.1 with a diameter ``D`` (no ``L``), in G17, G21 and
G90, over straight moves and arcs (I/J and R, comp41): the rows of the full
path's ``CutterComp`` (the held move, the entry line or arc, a convex corner's arc about the programmed corner with
its sweep box, a concave corner's pulled-back end, line-arc, arc-line and arc-arc corners, a compensated arc's
sweep box about its centre, G40's and M2/M30's flush) from the same float formulas
(:mod:`.comp_floats`).  Declined: G2/G3 just after its G40, with P or K or a whole turn under it, a dwell, tool change or a
plane, units, offset, tool length or path mode code while it is on, G91, G20, G7/G8 and canned cycles in a program
that may write it (a ``41`` or ``42`` in the text), and every error of the full path's compensation.

The run: the straight lines between two O-word lines run as one block (read once: each line's step found by its
layout, the line's literals cut out by the layout's slices, nothing compiled per layout: a line of letter-number
words only by :meth:`_Pass._plain`, any other by its shape; in a loop or sub body: the block's steps compiled
once and kept, :data:`MAX_STEPS` lines at most).  A
sub whose body has no ``#`` (no parameter read or written in it, nor in the arguments of the calls it makes)
cannot see its call frame: it is called without one (``tests/gcode/test_double_pass_frames.py``).

Invariant (``tests/gcode/test_double_pass.py``): whenever the pass returns, the full interpreter's run of
the same program on the same machine completes with no unknown code, no error and no notes but those of the
modal groups it assumed (the same as :attr:`DoublePath.assumed`), with the same
number of motions (as many rapids, arcs and dwells), and the end point of its k-th motion lies in the box of
the pass's k-th row widened by the bound (an arc: its every point, at both radii of a spiral, in
:meth:`DoublePath.enclosure` of its row); its corner check blends the corner between motions k and k + 1
without a tolerance exactly where :meth:`DoublePath.blended` says (``check_corners``; with
``tests/gcode/test_double_pass_tools.py`` for the tool change, dwells and path modes).
"""

from __future__ import annotations

import math
import re
from array import array
from bisect import bisect_left, bisect_right
from fractions import Fraction
from itertools import compress
from operator import itemgetter

from ...code_cache import compiled
from ...errors import GcodeError
from ...motion import DROPPED_BELOW, PLANE_AXES
from ...precompiled import dataclass  # start-up: no dataclasses import
from .. import DEFAULT_ARC_TOLERANCE
from ..codes import LANE_DOUBLES, LINUXCNC_G, LINUXCNC_M, LaneCodes, claimed
from ..expr import (
    MAX_PARAMETER,
    SUB_PARAMS,
    TOLERANCE_EQUAL,
    TRIG_DEGREES,
    EvalError,
    atan_degrees,
    binary_op,
    unary_op,
)
from ..lexer import magic_comment
from ..parser import ATAN, BIN, FN, NEG, NPAR, NUM, PAR, parse_line
from ..program import scan_oword
from ..shapes import LAYOUT, RUNS, shape_source, shaped
from .double_arcs import (
    CW,
    EXACT,
    IJ_SCREEN,
    R_INCH_REL,
    R_SCREEN,
    TURN,
    ij_check,
    inch_offb,
    inch_rule,
    r_screen_code,
    radius_rule,
    refined,
)
from .double_arcs import INCH as INCH_ARC
from .double_cycles import (
    CYCLE_CODES,
    Cycles,
    cycle_call,
    cycle_modal,
    level_code,
    literal_tokens,
    may_cycle,
    q_value,
    r_token,
    spindle_body,
    takes_p,
    takes_q,
)
from .double_lathe import (
    DIAMETER,
    SPINDLE_MODE,
    diameter_body,
    diameter_start,
    lathe_reason,
    spindle_mode,
)
from .double_units import INCH, TA, chain_start, inch_ends

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from ..source import FileText

__all__ = ["CODES", "Declined", "DoublePath", "double_pass"]


# Cutter compensation (.double_comp, with .comp_floats: some 2 million instructions to import, boot44) is imported
# when a block of the program writes G40/G41/G42 or its machine compensates: a pass without it asks only these.
def Comp(st: Any, machine: Any, declined: Any) -> Any:  # noqa: N802  # the class's name at its call
    """:class:`.double_comp.Comp` (the module imported now)."""
    from .double_comp import Comp as made

    return made(st, machine, declined)


def comp_body(st: Any, groups: dict[str, int], ms: list[int], ts: list[int], qs: list[int], others: list[str],
              declined: Any) -> tuple[list[str], list[str]]:
    """:func:`.double_comp.comp_body`: without a :class:`Comp` and without a compensation code in the block it
    adds nothing (its first test), and its module is not imported."""
    if st.cc is None and "comp" not in groups:
        return [], []
    from .double_comp import comp_body as body

    return body(st, groups, ms, ts, qs, others, declined)


def comp_others(groups: dict[str, int], others: list[str]) -> list[str]:
    """:func:`.double_comp.comp_others`: ``others`` itself in a block without a compensation code."""
    if "comp" not in groups:
        return others
    from .double_comp import comp_others as kept

    return kept(groups, others)


def arc_code(others: list[str], axes: list[tuple[int, int]], normal: list[str]) -> list[str]:
    """:func:`.double_comp.arc_code` (asked with a :class:`Comp` only)."""
    from .double_comp import arc_code as code

    return code(others, axes, normal)


def straight_code(axes: list[tuple[int, int]], normal: list[str], plane: tuple[int, int] | None = None) -> list[str]:
    """:func:`.double_comp.straight_code` (asked with a :class:`Comp` only)."""
    from .double_comp import straight_code as code

    return code(axes, normal, plane)

#: Motions the pass keeps (8 bytes per axis each) when it is run without ``on_window``: it keeps them all.
MAX_MOTIONS = 2_000_000
#: Motions of a window when the pass is run with ``on_window``: the rows are handed over and dropped each time
#: this many have been computed, so memory is flat and no program is too long for the pass.
WINDOW = 1 << 16
#: Characters of the text the pass splits into lines at a time (a list of lines costs ~10x the text).
PIECE = 1 << 20
#: Lines of loop and subroutine bodies the pass keeps compiled (a body runs again: its lines are compiled once,
#: a few hundred bytes each); the lines of a longer body are compiled again from their piece at each run, so
#: memory stays flat however long a body is.
MAX_STEPS = 1 << 16
WORK_OFFSETS = ("G54", "G55", "G56", "G57", "G58", "G59")
#: The G codes the pass follows (the code table's ``doubles`` claims), by modal group: a whole number ``n`` as
#: ``n``, ``n.1`` (G61.1, G91.1) as ``-(10 n + 1)`` (:func:`_code`).
_GROUP_NAMES = {0: "nonmodal", 1: "motion", 2: "plane", 4: "arc distance", 6: "units", 7: "comp", 8: "tool", 3: "distance",
                5: "feedmode", 10: "retract", 12: "offset", 13: "path", 14: SPINDLE_MODE, 15: DIAMETER}
#: Per plane code: the arc's (first, second) axes and their centre words, the full path's ``PLANE_AXES``
#: (``Interpreter.arc``; LinuxCNC's ARC_FEED order: G18's first axis is Z, its second X, its centre words K
#: and I).  The full path's arc is clockwise (G2) or not in the plane of those two axes in that order, and
#: :mod:`.double_arcs` takes the two as its x and y: the same orientation, in every plane.
_CENTRE_WORDS = {"X": "I", "Y": "J", "Z": "K"}
_ARC_PLANES = {int(p): (a, b, (_CENTRE_WORDS[a], _CENTRE_WORDS[b])) for p, (a, b, _n) in PLANE_AXES.items()}
_GROUPS = {k // 10 if k % 10 == 0 else -k: _GROUP_NAMES[LINUXCNC_G[k].group or 0]
           for k in sorted(claimed(LINUXCNC_G, LANE_DOUBLES))}

#: Calls open at once the pass follows (LinuxCNC has 10 call levels with the main program).
MAX_CALLS = 5
#: The O-word keywords the pass follows.
_FOLLOWED = frozenset(("if", "elseif", "else", "endif", "while", "endwhile", "sub", "endsub", "call"))
_SUB_KEYS = frozenset(range(1, SUB_PARAMS + 1))
_BLANKS = re.compile(r"[ \t]+")

#: The codes this lane claims and declines (the code table).
CODES = LaneCodes(LANE_DOUBLES, LINUXCNC_G, LINUXCNC_M)
#: The groups whose start-up state a straight move notes while the program has not set them.
_NOTED = frozenset(("units", "distance", "offset"))
_LETTERS = frozenset("GMFSXYZIJKRHTPQDL")  # D: G96's speed limit (.double_lathe); L: a cycle's repeats
#: Letters whose word is a literal code (H: the tool length register, T: a tool number, Q: M61's tool number,
#: read like a G or M code).
_CODE_LETTERS = "GMHTQ"
_CODE_TEXT = re.compile(r"0*(\d+)(?:\.0*)?")
_CODE_TENTH = re.compile(r"0*(61|91|41|42)\.10*")  # G61.1, G91.1, G41.1 and G42.1: the codes n.1 the pass follows
#: A line of words of a letter and a number only (:meth:`_Pass._plain`; the parser's ``_NUMBER``), and a word.
_PLAIN = re.compile(r"[ \t]*(?:[A-Za-z][+-]?(?:\d+\.?\d*|\.\d+)[ \t]*)+")
_PLAIN_WORD = re.compile(r"([A-Za-z])([+-]?(?:\d+\.?\d*|\.\d+))")
_DIGIT_RUNS = re.compile(rb"0+")  # (in a layout: every digit is 0)


#: M codes the pass follows beside M2/M30 (the code table's claims), one to a block: the spindle (M3, M4, M5)
#: and coolant (M7, M8, M9), which move nothing and set no state the path depends on (LinuxCNC checks the
#: spindle's direction for G33, G76, which the pass does not follow, and G84 and G86: ``st.spindle``)
_AUX_M = frozenset(k for k in LINUXCNC_M if CODES.claims_m(k)) - {2, 30, 6, 61}


class Declined(Exception):
    """The program leaves the double pass's subset (or may fail on the full path): ``reason`` says where."""

    def __init__(self, reason: str):
        super().__init__(reason)
        self.reason = reason


@dataclass(frozen=True, slots=True)
class DoublePath:
    """A program's motion as the pass computed it.

    ``columns[a][k]`` (a list of floats, or an ``array("d")``) is the double machine coordinate of axis ``axes[a]`` at the end of the k-th motion
    (row 0: the start position, so row k is where motion k ends and row k-1 where it starts).
    ``offset_bound[a]`` bounds the magnitude of every work offset the rows were computed with.
    """

    axes: tuple[str, ...]
    columns: tuple[list[float] | array, ...]
    offset_bound: tuple[Fraction, ...]
    motions: int
    lines: int
    rapids: int
    #: blocks executed (lines with a word), as the full interpreter counts them
    blocks: int
    #: the exact start position: an axis sits there, exactly, until a motion first moves it
    start: tuple[Fraction, ...]
    #: per axis, the first row a motion moved it to (0: no motion moves it)
    first_row: tuple[int, ...]
    #: the row ``columns[a][0]`` is (a window of a long program: rows ``row0``..``motions``; 0: every row)
    row0: int = 0
    #: arcs (G2/G3): how many in the whole program, and those of these rows: their rows (motions, ascending)
    #: and, four doubles an arc, the outer bounds ``xlo, xhi, ylo, yhi`` of its box on its plane's (first, second)
    #: axes (:mod:`.double_arcs`): ``arc_axes`` holds a pair of axis indices per plane the arcs are in (a slot),
    #: and ``arc_planes`` the slot of each arc (:meth:`arc_pair`)
    arcs: int = 0
    arc_rows: array | None = None
    arc_axes: tuple[int, ...] = ()
    arc_boxes: array | None = None
    #: what :meth:`refine` needs: four doubles an arc: its kind (``double_arcs.EXACT``: its box is the sweep's
    #: already; else a quick screen's, ``double_arcs.refined``'s flags), its words (R and 0, or I and J) and the
    #: offsets' bound it was computed with (a G91 chain's error in it, ``double_arcs.chain_offb``); the offsets'
    #: bound and the radius rule: ``(words, offb, rule)``
    arc_more: Any = None
    #: dwells (G4: a row where the machine stands) in the whole program, and the rows of those of these rows
    dwells: int = 0
    dwell_rows: array | None = None
    #: the path mode: ``(first row, bare)`` where it changes (the first: in force at ``row0``), ``bare``: the
    #: motions blend without a tolerance (G64 without P); ``()``: the machine's start mode throughout
    modes: tuple[tuple[int, bool], ...] = ()
    #: per axis, a bound (mm) of the G91 chains' error of these rows (:meth:`_Pass._straight_ends`), added to the
    #: module's bound; ``()``: none
    inc_bound: tuple[float, ...] = ()
    #: ``(group, code)`` of the modal groups the program had not set at a motion that needs them, in the order the
    #: full path notes them (``Interpreter.note_assumed``; ``units``, ``distance``, ``offset``, ``plane``): the
    #: machine file's codes, which the run assumed (:meth:`_Pass.assume`)
    assumed: tuple[tuple[str, str], ...] = ()
    #: a bound (mm, at or above ``p + q``) of how far the program's ``G64 P p [Q q]`` lets any motion
    #: blend off the programmed path (:meth:`_Pass.tolerance`); 0.0: the program wrote none
    tolerance: float = 0.0
    #: per arc of these rows (as ``arc_rows``), its plane's slot: the pair ``arc_axes[2 s]``, ``arc_axes[2 s + 1]``
    #: (``array("b")``; read only when ``arc_axes`` holds more than one pair: else every arc is in slot 0)
    arc_planes: array | None = None

    def enclosure(self, first: int, last: int) -> tuple[dict[str, Fraction], dict[str, Fraction]]:
        """Exact ``(lo, hi)`` per axis holding every position of motions ``first``..``last`` (1-based rows,
        inclusive, ``first > row0``) on the full path: the box of rows ``first - 1``..``last``, the rows a
        motion computed widened by the bound of the module's docstring, the rows at the start exact.

        >>> p = DoublePath(("X",), (array("d", [0.0, 0.1, 0.3]),), (Fraction(0),), 2, 2, 0, 2, (Fraction(0),), (1,))
        >>> lo, hi = p.enclosure(1, 2)
        >>> lo["X"] == 0 < Fraction(3, 10) < hi["X"], float(hi["X"] - Fraction(3, 10)) < 1e-15
        (True, True)
        >>> lo, hi = p.enclosure(2, 2)  # rows 1 and 2: 0.1 and 0.3 as the doubles of words, widened
        >>> lo["X"] < Fraction(1, 10) and Fraction(3, 10) < hi["X"]
        True
        """
        lo: dict[str, Fraction] = {}
        hi: dict[str, Fraction] = {}
        for a, col in enumerate(self.columns):
            f = self.first_row[a]
            bounds = [self.start[a]] if f == 0 or first - 1 < f else []  # rows at the start: exact
            if f and f <= last:  # rows a motion computed: widened
                begin = max(first - 1, f) - self.row0
                end = last + 1 - self.row0
                part = col[begin:end] if begin > 0 or end < len(col) else col
                # widened, outwards to multiples of 2**-60 mm (small denominators for the exact test)
                inc = self.inc_bound[a] if self.inc_bound else 0.0
                bounds += widened(min(part), max(part), self.offset_bound[a], inc)
            if len(bounds) == 2:  # the widened rows' alone
                lo[self.axes[a]], hi[self.axes[a]] = bounds
            else:
                lo[self.axes[a]], hi[self.axes[a]] = min(bounds), max(bounds)
        if self.arc_rows:
            self._arc_bounds(first, last, lo, hi)
        return lo, hi

    def apart(self, r0: int, r1: int, gap: Fraction) -> bool:
        """Are rows ``r0`` and ``r1`` (``row0 <= r0``, numbered as for :meth:`enclosure`) more than ``gap`` apart on
        some axis, their boxes ``enclosure(r + 1, r)`` compared, as their doubles show at once?  False: not
        shown (compare the boxes).

        Row ``r``'s box on an axis a motion computed lies within ``w_r + 2**-60`` of its double ``x_r``:
        ``w_r = (4 (|x_r| + offset_bound) + 2**-8) 2**-52 + inc_bound``, :meth:`enclosure`'s widening, then
        outwards to the ``2**-60`` grid.  So the two boxes are at least ``|x_0 - x_1| - w_0 - w_1 - 2**-59``
        apart, more than ``gap`` when ``|x_0 - x_1|`` exceeds ``gap + w_0 + w_1 + 2**-59``; the test asks for
        twice that bound evaluated in floats (each term within a relative ``2**-50`` of its value, the
        difference ``|x_0 - x_1|`` within ``2**-53`` of its own: the factor 2 covers them; an infinite or NaN
        bound shows nothing).  An axis at its exact start position in either row (no widening) is not tried.

        >>> p = DoublePath(("X",), (array("d", [0.0, 0.1, 0.1, 0.3]),), (Fraction(0),), 3, 3, 0, 3, (Fraction(0),), (1,))
        >>> p.apart(1, 3, Fraction(1, 20)), p.apart(1, 2, Fraction(0)), p.apart(0, 1, Fraction(0))
        (True, False, False)
        """
        tiny2 = 2.0**-7 * 2.0**-52 + 2.0**-59  # two rows' 2**-8 ulp and grid steps
        for a, col in enumerate(self.columns):
            f = self.first_row[a]
            if f == 0 or r0 < f:
                continue
            x0, x1 = col[r0 - self.row0], col[r1 - self.row0]
            inc = self.inc_bound[a] if self.inc_bound else 0.0
            bound = float(gap) + 4.0 * (abs(x0) + abs(x1) + 2.0 * float(self.offset_bound[a])) * 2.0**-52 \
                + tiny2 + 2.0 * inc
            if abs(x0 - x1) > 2.0 * bound:
                return True
        return False

    def reach(self, first: int, last: int, names: Any = None) -> dict[str, Fraction] | None:
        """Per axis of ``names`` (default all), a bound of how far a blended corner between two of motions
        ``first``..``last`` can leave their box (:func:`.double_reach.reach`, whose docstring says why it holds:
        ``prover/doubles.py`` grows a box with arcs by it), or None."""
        from .double_reach import reach  # (a proof of G64 boxes with arcs only)

        return reach(self, first, last, names)

    def arc_pair(self, k: int) -> tuple[int, int]:
        """The axes (first, second) of the plane of arc ``k`` (an index of ``arc_rows``)."""
        pairs = self.arc_axes
        s = 2 * self.arc_planes[k] if len(pairs) > 2 and self.arc_planes is not None else 0
        return pairs[s], pairs[s + 1]

    def _arc_bounds(self, first: int, last: int, lo: dict[str, Fraction], hi: dict[str, Fraction]) -> None:
        """Grow ``lo``/``hi`` by the boxes of the arcs among motions ``first``..``last``: per plane, the least and
        largest of its arcs' bounds on each of its axes (with several planes, the arcs of each picked by a mask of
        their slots: one scan an axis in C whatever the order of the planes)."""
        rows, boxes, pairs = self.arc_rows, self.arc_boxes, self.arc_axes
        assert rows is not None and boxes is not None
        begin, end = bisect_left(rows, first), bisect_right(rows, last)
        if begin >= end:
            return
        if len(pairs) == 2 or self.arc_planes is None:
            masks: Any = ((0, None),)
        else:
            slots = bytes(self.arc_planes[begin:end])
            masks = [(s, m) for s in range(len(pairs) // 2) if 1 in (m := slots.translate(_SLOT_MASKS[s]))]
        los: dict[int, float] = {}
        his: dict[int, float] = {}
        for s, mask in masks:
            for k, a in enumerate(pairs[2 * s:2 * s + 2]):
                low, high = boxes[4 * begin + 2 * k:4 * end:4], boxes[4 * begin + 2 * k + 1:4 * end:4]
                v, w = (min(low), max(high)) if mask is None else (min(compress(low, mask)), max(compress(high, mask)))
                los[a] = min(los.get(a, v), v)
                his[a] = max(his.get(a, w), w)
        for a, v in los.items():  # the doubles compared exactly, one Fraction an axis
            name = self.axes[a]
            lo[name] = min(lo[name], Fraction(v))
            hi[name] = max(hi[name], Fraction(his[a]))

    def refine(self, first: int, last: int) -> bool:
        """Narrow the boxes of the arcs among motions ``first``..``last`` that hold a quick screen's
        (:func:`~nczones.gcode.linuxcnc.double_arcs.r_screen`, ``ij_screen``) to the sweep's boxes
        (``r_arc``, ``ij_arc``: the box kept is the two's intersection, which holds the arc as each does);
        whether one was narrowed.  A proof calls it when a box with arcs does not fit."""
        more, rows = self.arc_more, self.arc_rows
        if more is None or not rows:
            return False
        words, _offb, rule = more
        boxes = self.arc_boxes
        assert boxes is not None
        done = False
        for k in range(bisect_left(rows, first), bisect_right(rows, last)):
            w = 4 * k
            flag = int(words[w])
            if flag == EXACT:
                continue
            words[w] = EXACT
            ia, ib = self.arc_pair(k)
            ca, cb = self.columns[ia], self.columns[ib]
            r = rows[k] - self.row0  # the arc's end row; the row before is its start (held: r >= 1)
            box = refined(flag, ca[r - 1], cb[r - 1], ca[r], cb[r], words[w + 1], words[w + 2], words[w + 3], rule)
            if box.__class__ is str:  # (r_screen and ij_screen accept only arcs these accept)
                continue
            done = True
            boxes[w:w + 4] = array("d", (max(boxes[w], box[0]), min(boxes[w + 1], box[1]),
                                         max(boxes[w + 2], box[2]), min(boxes[w + 3], box[3])))
        return done

    def blended(self, k: int) -> bool:
        """May LinuxCNC blend the corner between motions ``k`` and ``k + 1`` without a tolerance: motion ``k``
        runs in G64 without P (the full path's corner takes the mode of the motion before it:
        ``CornerCheck._segment``) and neither is a dwell (:meth:`dwell_beside`)?  Without ``modes``: every
        corner may.  (A motion LinuxCNC may drop joins the motions around it in the mode of the one before
        them, whatever its own: the proof checks the corner after such a motion too, ``prover/doubles.py``.)"""
        modes = self.modes
        if modes and not modes[max(bisect_right(modes, (k, True)) - 1, 0)][1]:
            return False
        return not self.dwell_beside(k)

    def dwell_beside(self, k: int) -> bool:
        """Is motion ``k`` or ``k + 1`` a dwell (which stops the machine: no corner joins across it, and no
        motion before it is dropped into one after it, ``CornerCheck._stop``)?"""
        rows = self.dwell_rows
        if not rows:
            return False
        at = bisect_left(rows, k)
        return at < len(rows) and rows[at] <= k + 1

    def has_arcs(self, first: int, last: int) -> bool:
        """Is one of motions ``first``..``last`` (of these rows) an arc?"""
        rows = self.arc_rows
        if not rows:
            return False
        at = bisect_left(rows, first)
        return at < len(rows) and rows[at] <= last


_ULP = Fraction(1, 2**52)
_EPS2 = 2.0**-52  # twice the unit roundoff (_Pass._straight_ends)
_DROPPED = float(DROPPED_BELOW) * 1.01 + 1e-12
#: Arcs the pass holds in lists before it moves them to its arrays (:meth:`_Pass.arc_flush`).
_ARC_BUFFER = 4096
#: Items of an arc's record in :attr:`_Pass.new_arcs`: its row (counted from ``row0 - 1``: ``row0`` changes only
#: in :meth:`_Pass.full`, after :meth:`_Pass._path` has moved the records), box (4) and words (4) (its plane's
#: slot is the pass's: :meth:`_Pass.arc_in` moves the records to the arrays before it changes).
_ARC_ITEMS = 9
_TINY = Fraction(1, 2**8)  # widens by at least 2**-60 mm: more than any subnormal's rounding
_GRID = 2**60


def widened(a_lo: float, a_hi: float, offset_bound: Fraction, inc: float) -> tuple[Fraction, Fraction]:
    """``a_lo - w`` rounded down and ``a_hi + w`` rounded up to multiples of ``2**-60`` (:data:`_GRID`), exactly:
    ``w = (4 (top + offset_bound) + 2**-8) 2**-52 + inc``, ``top = max(|a_lo|, |a_hi|)``, the rows' widening
    (:meth:`DoublePath.enclosure`, the bound of the module's docstring).

    In integers, not ``Fraction``: times ``2**60``, ``w`` is ``2**10 (top + offset_bound) + 1 + inc 2**60``; each
    float is ``n / 2**e`` (``as_integer_ratio``), so all of them over the largest of their denominators ``p``,
    times the offset bound's denominator, are integers, and the roundings are floor divisions.

    >>> widened(0.1, 0.3, Fraction(0), 0.0) == (
    ...     Fraction(math.floor((Fraction(0.1) - (4 * Fraction(0.3) + _TINY) * _ULP) * _GRID), _GRID),
    ...     Fraction(math.ceil((Fraction(0.3) + (4 * Fraction(0.3) + _TINY) * _ULP) * _GRID), _GRID))
    True
    """
    nl, dl = a_lo.as_integer_ratio()
    nh, dh = a_hi.as_integer_ratio()
    nt, dt = max(abs(a_lo), abs(a_hi)).as_integer_ratio()
    ni, di = inc.as_integer_ratio()
    p = max(dl, dh, dt, di)  # powers of two: each divides the largest
    no, do = offset_bound.numerator, offset_bound.denominator
    den = p * do
    w = ((nt * (p // dt) << 10) + p + (ni * (p // di) << 60)) * do + (no * p << 10)  # w 2**60 p do
    lo = ((nl * (p // dl) << 60) * do - w) // den
    hi = -((-((nh * (p // dh) << 60) * do + w)) // den)
    return Fraction(lo, _GRID), Fraction(hi, _GRID)


#: Per plane slot s: the bytes table that maps s to 1 and every other slot to 0 (:meth:`DoublePath._arc_bounds`).
_SLOT_MASKS = tuple(bytes(int(b == s) for b in range(256)) for s in range(3))


def double_pass(text: str | FileText, machine: Any, *, max_iterations: int, on_window: Any = None,
                window: int | None = None, arc_tolerance: Fraction | str = DEFAULT_ARC_TOLERANCE) -> DoublePath:
    """Run ``text`` on ``machine`` in doubles (see the module's docstring); raise :class:`Declined` when the
    program leaves the subset.  ``text`` may be a streamed file (:class:`~nczones.gcode.source.FileText`):
    the pass reads it a piece at a time and never holds it whole.

    Without ``on_window`` the path holds every row (and the pass declines past :data:`MAX_MOTIONS`
    motions).  With it, each time ``window`` (default :data:`WINDOW`) motions past the window's first row
    have been computed, ``on_window(path)`` is called with a :class:`DoublePath` of rows ``row0``..``motions`` (its counts so far)
    and those rows are dropped but the last two: windows overlap by one motion (the last motion of a
    window is the first of the next), so a check that needs a motion and the one before it finds both in
    one window.  ``on_window`` returns False to stop the pass (it then declines), or None to be handed the
    window again one motion later (it grows: a window that cannot end at this motion, up to twice its size,
    then the pass declines).  The path returned is the last window, with the whole program's counts.
    ``arc_tolerance`` is the full path's (its ``Interpreter``'s ``arc_tolerance``): the pass declines an I/J
    arc near or past its rule.

    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('[machine]\\naxes=["X","Y"]\\n[machine.rapid]\\nX="1000"\\nY="1000"\\n'
    ...                   '[machine.reference]\\nX="0"\\nY="0"\\n')
    >>> p = double_pass("G21 G90 G54 F100\\n#1 = 0\\no1 while [#1 LT 3]\\nG1 X[#1 * 0.1] Y1\\n"
    ...                 "#1 = [#1 + 1]\\no1 endwhile\\nM30\\n", m, max_iterations=100)
    >>> p.motions, list(p.columns[0])
    (3, [0.0, 0.0, 0.1, 0.2])
    >>> double_pass("G21 G90 G54\\nG33 X1 Y1\\n", m, max_iterations=100)
    Traceback (most recent call last):
    ...
    nczones.gcode.linuxcnc.doubles.Declined: G33 is not followed by the double pass
    """
    return _Pass(text, machine, max_iterations, on_window, WINDOW if window is None else window,
                 arc_tolerance).run()


#: The code of a step: its body, its parameter writes, its values, the source of its plan's key, its names.
_Code = tuple[list[str], list[str], list[str], str | None, dict]


def _machine_taken(machine: Any) -> None:
    """Decline a machine the pass does not run on: a lathe it does not follow (:mod:`.double_lathe`), another
    dialect, a start in G20, G91, G93 or G95."""
    lathe = lathe_reason(machine)
    if lathe is not None:
        raise Declined(lathe)
    if getattr(machine, "dialect", "linuxcnc") != "linuxcnc":
        raise Declined("a machine of another dialect than LinuxCNC")
    if set(machine.modal) & {"G20", "G91", "G93", "G95"}:
        raise Declined("the machine starts in G20, G91, G93 or G95")


class _Pass:
    def __init__(self, text: str | FileText, machine: Any, max_iterations: int, on_window: Any = None,
                 window: int = WINDOW, arc_tolerance: Fraction | str = DEFAULT_ARC_TOLERANCE):
        if window < 1:
            raise ValueError(f"a window of at least one motion, got {window}")
        self.on_window = on_window
        #: rows of a full window (the one before its first motion included); past it the window is handed over
        self.rows = window + 1 if on_window is not None else MAX_MOTIONS + 2
        self.row0 = 0  # the row columns[a][0] is
        _machine_taken(machine)
        # the lines as the full path reads them: a byte-order mark at the start and one "\r" before each
        # newline and at the end dropped (by _Lines, a piece at a time; a streamed file has no byte-order mark)
        if isinstance(text, str):
            text = text.removeprefix("\ufeff")
        #: the lines, read a piece of the text at a time (the whole text as a list of lines would be ~10x it;
        #: a streamed file, FileText, is read from the file a piece at a time, in order but for jumps)
        self.src = _Lines(text, crlf="\r" in text)
        #: the text may write G91 (a "91" in it): only then do straight moves test for G91 (_straight_ends)
        self.g91_text = "91" in text
        #: the text may write G20 (a "20" in it): only then do straight moves test for it (:mod:`.double_units`)
        self.g20_text = "20" in text
        #: the text may write a canned cycle: only then do motions hand their literal words' texts (.double_cycles)
        self.cycle_text = may_cycle(text)
        #: layout -> (its shape's step, the layout's cutter): ``step(cut(line))`` runs a line of it (nothing is
        #: compiled per layout: CAM output with arcs has hundreds of layouts of a few dozen shapes)
        self.by_layout: dict[bytes, tuple[Any, Any]] = {}
        self.max_iterations = max_iterations
        self.axes = tuple(machine.axis_names)
        self.index = {a: i for i, a in enumerate(self.axes)}
        #: G7/G8: an X word's factor now, X words compiled with it, one compiled without it (.double_lathe)
        self.half, self.diameter = diameter_start(machine)
        self.x_axis, self.x_compiled = self.index.get("X"), False
        self.g20_compiled = False  # a G20 block compiled (a later G7 on a mill declines: diameter_body)
        wcs = next((c for c in machine.modal if c.startswith(("G54", "G55", "G56", "G57", "G58", "G59"))), "G54")
        if wcs not in WORK_OFFSETS:
            raise Declined(f"the machine starts in {wcs}")
        exact_offsets = {name: tuple(machine.offset(name)) for name in WORK_OFFSETS}
        self.offsets = {int(name[1:]): tuple(float(v) for v in vec) for name, vec in exact_offsets.items()}
        self._tools(machine, exact_offsets)
        self.wcs = int(wcs[1:])
        self.off = self.offsets[self.wcs]
        self._arcs_state(machine, arc_tolerance)
        self._modes_state(machine)
        self.cyc = Cycles(self, Declined, machine)  # canned cycles (.double_cycles)
        #: cutter compensation (.double_comp), on a machine with LinuxCNC's and a text that may write G41/G42 (a
        #: G41/G42 the test misses, "G4 1" say, is declined: double_comp.comp_body without a Comp)
        self.cc = Comp(self, machine, Declined) if getattr(machine, "cutter_compensation", "none") == "linuxcnc" \
            and not self.diameter and _may_compensate(text) else None
        self.cyc.track = self.cycle_text and self.cc is None  # (motions hand the cycles their literal words)
        self.spindle = 0  # M3 1, M4 -1, stopped 0: what G84 and G86 check (.double_cycles.spindle_body)
        self.unset = set(_NOTED)
        #: the groups assumed at a motion and their codes (DoublePath.assumed); what each starts as on the full path
        self.assumed: dict[str, str] = {}
        self.start_codes = {"units": "G21", "distance": "G90", "offset": wcs}
        self.motion: int | None = None
        self.feed = 0.0
        self.start = tuple(machine.start)
        self.first_row = [0] * len(self.axes)  # the first row a motion moved each axis to (0: none yet)
        self.pos = [float(v) for v in machine.start]
        # lists, not arrays (as the arcs' rows, _arcs_state): an array's append parses its float with PyArg_Parse
        self.columns: tuple[list[float], ...] = tuple([v] for v in self.pos)
        self.rapids = self.blocks = 0
        self._language_state()

    def _language_state(self) -> None:
        """The parameters, subs, calls and compiled steps of the language the pass runs."""
        from .state import DEBUG_FLAG, DEBUG_FLAG_DEFAULT

        # numbered parameters set by the program (unset read 0); #5599 starts at 1 (nczones.gcode.linuxcnc.state)
        self.S: dict[int, float] = {DEBUG_FLAG: float(DEBUG_FLAG_DEFAULT)}
        self.N: dict[str, float] = {}  # the main program's named parameters
        self.plans: dict[tuple, Any] = {}
        #: the subs defined so far: the index of their body's first line and of their endsub
        self.subs: dict[Any, tuple[int, int]] = {}
        #: open calls: (return index, caller's #1..#30, label, caller's local named parameters; both None: a sub
        #: whose body has no ``#``, called without a frame)
        self.calls: list[tuple[int, dict | None, Any, dict | None]] = []
        self.open: set[Any] = set()  # the labels of the open calls
        self.plain: dict[Any, bool] = {}  # per sub: its body has no "#" (its frame is not seen)
        self.kept = 0  # lines of loop and sub bodies kept compiled (MAX_STEPS at most)
        self.control_lines: dict[str, Any] = {}  # an O-word line's text -> its compiled condition or arguments
        #: each shape's compiled step in this pass (the shape itself is the key: it stays alive, its id unused)
        self.shape_steps: dict[Any, Any] = {}
        self.plain_steps: dict[str, Any] = {}  # a plain line's letters -> its step (_plain)
        self.plain_kinds: dict[bytes, Any] = {}  # a plain layout, its digit runs made one -> its step (_plain)
        self.pindex: dict[str, int] = {}
        from .state import linuxcnc_state_numbers

        self.state_keys = linuxcnc_state_numbers() | {3000, 3006}
        self.env = {"S": self.S, "N": self.N, "D": Declined, "binary_op": binary_op, "unary_op": unary_op,
                    "_atan": _atan, "_code": _code, "_sin": TRIG_DEGREES["sin"],
                    "_cos": TRIG_DEGREES["cos"], "_tan": TRIG_DEGREES["tan"], "_pindex": self._pindex, "I": self.pindex}

    # -- parameters ---------------------------------------------------------------------------------------
    def _pindex(self, text: str) -> int:
        """The parameter number a literal ``#text`` reads or writes; declines state and bad numbers."""
        x = float(text)
        i = round(x) if x - x == 0 else -1
        if abs(x - i) > 0.0001 or not 1 <= i <= MAX_PARAMETER or i in self.state_keys:
            raise Declined(f"parameter #{text}")
        if len(self.pindex) < 10_000:
            self.pindex[text] = i
        return i

    def _pconst(self, node: Any) -> str:
        """The source of the parameter number of a parsed literal ``#<literal>``."""
        i = _index_const(node)
        if i in self.state_keys:
            raise Declined(f"parameter #{i}")
        return repr(i)

    # -- the run ------------------------------------------------------------------------------------------
    def run(self) -> DoublePath:
        controls = self._controls()
        marks = sorted(controls)  # the O-word lines: the straight lines between two are run as one block
        count = self.src.count
        # where each run of straight lines ends: a run starts at line 0 or just after an O-word line (every jump
        # lands on one), and ends at the next O-word line
        ends = dict(zip([0] + [m + 1 for m in marks], marks + [count]))
        blocks: dict[int, tuple] = {}  # the compiled lines of loop and sub bodies, by block (MAX_STEPS lines at most)
        counts: dict[int, int] = {}  # iterations of the current entry of each while, by its index
        looping = 0  # open while loops and calls
        back = -1  # the index of the while an endwhile just jumped to
        # iterations of all loops together: nested loops, each within its bound, may still run for hours; past
        # this the pass declines and the full path runs them under the run's budget (nczones.prover.limits)
        total, most = 0, 10 * self.max_iterations
        i = 0
        while i < count:
            ctrl = controls.get(i)
            if ctrl is None:  # the straight lines up to the next O-word line (-1: the program ended)
                end = ends.get(i)
                if end is None:  # (a run starting elsewhere: none does)
                    k = bisect_left(marks, i)
                    end = marks[k] if k < len(marks) else count
                try:
                    i = self._block(i, end, blocks) if looping else self._straight(i, end)
                except (EvalError, KeyError, ZeroDivisionError, OverflowError) as exc:
                    raise Declined(f"an evaluation error: {exc!r}") from None
                if i < 0:
                    break
                continue
            kw, target, cond = ctrl
            if kw == "while":
                if back != i:
                    counts[i] = 0
                    looping += 1
                back = -1
                if _cond(cond) != 0.0:
                    counts[i] += 1
                    total += 1
                    if counts[i] >= self.max_iterations or total > most:
                        raise Declined("a loop at its iteration bound")
                    i += 1
                else:
                    looping -= 1
                    i = target
            elif kw == "endwhile":
                i = back = target
            elif kw == "if":
                i += 1
                if _cond(cond) == 0.0:
                    for kw2, at, cond2 in target:
                        if kw2 == "endif" or kw2 == "else" or _cond(cond2) != 0.0:
                            i = at + 1
                            break
            elif kw == "call":
                i = self._call(i, target, cond)
                looping += 1  # the body runs again: its lines compiled once (as a loop body's)
            elif kw == "endsub":
                i = self._endsub()
                looping -= 1
            elif kw == "sub":
                i = self._sub(i, target)
            else:  # elseif, else: the branch before ran, on past the endif (endif: on to the next line)
                i = target
        if self.cc is not None:  # M2, M30 or the end of the text: compensation's held moves (.double_comp)
            self.cc.end()
        return self._path()

    def _straight(self, i: int, end: int) -> int:
        """Run lines ``i``..``end - 1``, read once (not in a loop or call): the next line, or -1 when the
        program ended.  A line whose layout has a step (``by_layout``) runs it on the literals its layout's
        cutter takes out of it; a line of a layout without one yet is stepped (:meth:`_line_step`) where it stands,
        in the same walk of its piece (arc43: not a new slice of the rest of the piece at each new layout, some
        2k instructions a line on CAM output with arcs).  The walk pairs the lines with their layouts (line44: no
        index a line, an ``int`` made past 256, and no ``lines[k]``; the whole piece not copied)."""
        src, by_layout = self.src, self.by_layout
        while i < end:
            lo, hi, lines, layouts = src.piece(i)
            if layouts is not None:
                first, stop = i - lo, min(end, hi) - lo
                last: bytes | None = None  # the last layout run, and its step (CAM lines often repeat a layout)
                step: Any = None
                cut: Any = None
                pairs = zip(lines, layouts) if first == 0 and stop == len(lines) \
                    else zip(lines[first:stop], layouts[first:stop])
                for line, layout in pairs:
                    if layout != last:
                        got = by_layout.get(layout)
                        if got is None:  # (its step is compiled now: the next line of its layout finds it)
                            last = None
                            fn, parts = self._line_step(line, layout)
                            if fn is not None and fn(parts):
                                return -1
                            continue
                        step, cut = got
                        last = layout
                    if step(cut(line)):
                        return -1
                i = stop + lo
                continue
            fn, parts = self._step(i)
            i += 1
            if fn is not None and fn(parts):
                return -1
        return end

    def _block(self, i: int, end: int, blocks: dict[int, tuple]) -> int:
        """Run lines ``i``..``end - 1`` of a loop or sub body (they run again): their steps compiled once and kept
        in ``blocks`` while the pass keeps at most :data:`MAX_STEPS` lines (the lines past that are compiled again
        at each run, so memory stays flat however long a body is); the next line, or -1 when the program ended."""
        got = blocks.get(i)
        if got is None:
            cut = min(end, i + max(0, MAX_STEPS - self.kept))
            try:
                steps = [self._step(j) for j in range(i, cut)]
            except Declined:  # a line the pass does not follow: declined when it is reached (an M2 may end first)
                steps, cut = [], i
            got = blocks[i] = (tuple(step for step in steps if step[0] is not None), cut)
            self.kept += cut - i
        block, cut = got
        for fn, parts in block:
            if fn(parts):
                return -1
        if cut < end:  # past what is kept
            for j in range(cut, end):
                fn, parts = self._step(j)
                if fn is not None and fn(parts):
                    return -1
        return end

    def _path(self) -> DoublePath:
        """The rows held now as a path (every row, or the current window)."""
        # a sum is finite only when every row is (an inf or nan stays one; a finite overflow declines too): one
        # scan of a window's column, not two (min and max)
        self.arc_flush()
        if not all(math.isfinite(sum(col)) for col in self.columns):
            raise Declined("a position beyond the double range")
        motions = self.row0 + len(self.columns[0]) - 1
        arcs = self.arcs + len(self.arc_rows)
        return DoublePath(self.axes, self.columns, self.offset_bound, motions,
                          motions - self.rapids - arcs - self.dwells, self.rapids, self.blocks, self.start,
                          tuple(self.first_row), self.row0, arcs, self.arc_rows, self.arc_axes, self.arc_boxes,
                          (self.arc_words, self.offb, self.rule), self.dwells, self.dwell_rows, tuple(self.modes),
                          tuple(self.xerr), tuple(self.assumed.items()), self.tol, self.arc_slots)

    def full(self) -> None:
        """The window is full: hand it over, keep its last two rows (one motion of overlap)."""
        if self.on_window is None:
            raise Declined(f"more than {MAX_MOTIONS} motions")
        proved = self.on_window(self._path())
        if proved is None and len(self.columns[0]) < 2 * self.rows:
            return  # not at this motion: handed over again after the next (the plans call full() while full)
        if not proved:
            raise Declined("a window of the double pass that its boxes do not prove")
        keep = len(self.columns[0]) - 2
        for col in self.columns:
            del col[:keep]
        self.row0 += keep
        gone = bisect_right(self.arc_rows, self.row0)  # the arcs of the rows dropped (motions up to row0)
        if gone:
            del self.arc_rows[:gone]
            self.arcs += gone
            del self.arc_boxes[:4 * gone]
            del self.arc_words[:4 * gone]
            del self.arc_slots[:gone]
        # the path mode in force at row0 and its changes after (the arcs' plane likewise); the dwells from row0 on
        k = bisect_right(self.modes, (self.row0, True)) - 1
        if k > 0:
            del self.modes[:k]
        del self.dwell_rows[:bisect_left(self.dwell_rows, self.row0)]
        if self.chained or any(self.xerr):  # the G91 errors of the two rows kept
            for i, e in enumerate(self.err):
                row, before = self.touched[i]
                self.xerr[i] = max(e or 0.0, (before or 0.0) if row > self.row0 else 0.0)

    def _step(self, i: int) -> tuple[Any, tuple]:
        """``(step, its literals)`` of line ``i`` (``step`` None: nothing to do)."""
        return self._line_step(*self.src.line(i))

    def _line_step(self, line: str, own_layout: bytes | None) -> tuple[Any, tuple]:
        """``(step, its literals)`` of the text of a line and its layout (None: its piece is not ASCII)."""
        if "(" in line or ";" in line or not line.isascii():
            return self._parsed(line), ()
        layout = line.encode().translate(LAYOUT)
        hit = RUNS.get(layout)
        if hit is None:
            if not line.strip():
                return None, ()
            plain = self._plain(line, layout)
            if plain is None:
                return self._fresh(line)
            step, cut = plain
            if own_layout is not None and layout == own_layout:
                self.by_layout[layout] = plain
            return step, cut(line)
        cut = hit[1]
        step = self._shape_step(hit[2])
        if own_layout is not None and layout == own_layout:
            self.by_layout[layout] = (step, cut)
        return step, cut(line)

    # -- control lines ------------------------------------------------------------------------------------
    def _controls(self) -> dict[int, tuple]:
        """Every O-word line as the full path's scan for jumps sees it
        (:func:`~nczones.gcode.program.scan_oword`), matched by nesting; each line's parse must agree.
        ``{line index: (keyword, target, condition)}``: a ``while``'s target is the index after its ``endwhile`` and an ``endwhile``'s its ``while``; an
        ``if``'s the ``(keyword, index, condition)`` of its ``elseif``/``else``/``endif`` lines; an
        ``elseif``'s or ``else``'s the index after the ``endif``."""
        found = []
        src = self.src
        for k in range(len(src.starts) if src.has_o else 0):  # a piece of the text at a time, in order
            part = src.part(k)
            index, counted = src.first[k], 0
            for start, line_end in _lines_with_o(part):
                index += part.count("\n", counted, start)
                counted = start
                line = part[start:line_end]
                seen = scan_oword(line)
                if seen is None:
                    continue
                kw, label = seen
                cond = self.control_lines.get(line)
                if cond is None:  # a line's condition or arguments compiled once (a call repeated: one step)
                    cond = self._control_line(line, kw, label)
                    if len(self.control_lines) < MAX_STEPS:
                        self.control_lines[line] = cond
                found.append((index, kw, label, cond, src.starts[k] + start))
        out: dict[int, tuple] = {}
        stack: list[list] = []
        opened: set = set()
        for at, kw, label, cond, start in found:
            if kw == "call":
                out[at] = ("call", label, cond)
                continue
            if kw == "sub" or kw == "endsub":
                self._sub_control(kw, label, at, start, stack, opened, out)
                continue
            if kw in ("if", "while"):
                if label in opened:  # LinuxCNC refuses a label that opens two constructs ("duplicate O-word label")
                    raise Declined("an O-word label reused")
                opened.add(label)
                stack.append([kw, label, at, cond, []])
                continue
            if not stack or stack[-1][1] != label:
                raise Declined("O-words not nested")
            top = stack[-1]
            if kw == "endwhile":
                if top[0] != "while":
                    raise Declined("O-words not nested")
                stack.pop()
                out[top[2]] = ("while", at + 1, top[3])
                out[at] = ("endwhile", top[2], None)
                continue
            if top[0] != "if" or (kw != "endif" and top[4] and top[4][-1][0] == "else"):
                raise Declined("O-words not nested")
            top[4].append((kw, at, cond))
            if kw == "endif":
                stack.pop()
                out[top[2]] = ("if", tuple(top[4]), top[3])
                for k2, at2, _c in top[4]:
                    out[at2] = (k2, at + 1, None)
        if stack:
            raise Declined("an O-word construct left open")
        if any(kw == "sub" for _a, kw, *_r in found) and self._names_value():
            # an endsub sets #<_value> and #<_value_returned> (the pass does not follow them)
            raise Declined("a program with subroutines that names #<_value>")
        return out

    def _names_value(self) -> bool:
        """Whether the text names ``#<_value>`` (blanks aside), read a piece at a time: pieces are cut after
        a newline and a blank is not one, so a name is never cut."""
        src = self.src
        parts = (src.part(k) for k in range(len(src.starts)))
        return any("_" in p and "_value" in _BLANKS.sub("", p.lower()) for p in parts)  # most have no "_"

    def _control_line(self, line: str, kw: str, label: Any) -> Any:
        """The compiled condition of an O-word line (a call's: its arguments'), after its parse agrees."""
        if kw not in _FOLLOWED:
            raise Declined(f"o-word {kw or 'label'}")
        try:
            pl = parse_line(line, 1, "<double pass>")
        except GcodeError:  # the full path reports it
            raise Declined("an O-word line that does not parse") from None
        ow = pl.oword
        if ow is None or ow.keyword != kw or ow.label != label or pl.comments or pl.words or pl.assigns \
                or pl.delete or pl.percent or pl.unsupported is not None:
            raise Declined("an O-word line read otherwise by the parser")
        if kw == "call":
            if len(ow.args) > SUB_PARAMS:
                raise Declined("a call with more than 30 arguments")
            return self._compiled_args(ow.args)
        if kw == "endsub" and ow.args:
            raise Declined("an endsub returning a value")
        return self._compiled_cond(ow.args[0]) if kw in ("if", "elseif", "while") else None

    def _sub_control(self, kw: str, label: Any, at: int, start: int, stack: list, opened: set, out: dict) -> None:
        """A ``sub`` (opened at the top level only) or its ``endsub`` matched (:meth:`_controls`)."""
        if kw == "sub":
            if stack or label in opened:
                raise Declined("a sub inside another construct, or its label reused")
            opened.add(label)
            stack.append([kw, label, at, None, [start]])
            return
        if len(stack) != 1 or stack[0][:2] != ["sub", label]:
            raise Declined("O-words not nested")
        top = stack.pop()
        out[top[2]] = ("sub", (at + 1, label), None)
        out[at] = ("endsub", None, None)

    # -- subs and calls (as the full path's ``Runner.oword``) ----------------------------------------------
    def _sub(self, i: int, target: tuple[int, Any]) -> int:
        """A sub definition reached: noted (its body's first line and its endsub's), on past its endsub."""
        after, label = target
        if label in self.subs:  # reached again (the full path reports it)
            raise Declined("a sub defined twice")
        self.subs[label] = (i + 1, after - 1)
        return after

    def _call(self, i: int, label: Any, args: Any) -> int:
        """A call: the first line of the sub's body.  It saves the caller's #1..#30, sets them from its
        arguments (the rest unset) and runs the body with no local named parameters; its endsub restores them
        (:meth:`_endsub`; as ``Parameters.push_scope`` / ``pop_scope``).  A sub whose body has no ``#`` (no
        parameter, numbered or named, read or written in it, nor in its calls' arguments) cannot see its frame:
        its calls evaluate their arguments and keep the caller's (a call it makes saves and restores them
        itself).  Declined: a call of a sub not defined before it in the flow, a recursive call, calls nested
        more than :data:`MAX_CALLS` deep."""
        sub, calls = self.subs.get(label), self.calls
        if sub is None or len(calls) >= MAX_CALLS or label in self.open:
            raise Declined("a call of a sub not defined before it, recursive or nested deeply")
        values = _args(args)
        self.open.add(label)
        body, end = sub
        plain = self.plain.get(label)
        if plain is None:
            plain = self.plain[label] = not any("#" in self.src.line(j)[0] for j in range(body, end))
        if plain:
            calls.append((i + 1, None, label, None))
            return body
        S, N = self.S, self.N
        saved = {k: S[k] for k in S.keys() & _SUB_KEYS}
        for k in saved:
            del S[k]
        S.update(zip(range(1, SUB_PARAMS + 1), values))
        calls.append((i + 1, saved, label, dict(N)))
        N.clear()  # a call's local named parameters start empty (the caller's are not visible)
        return body

    def _endsub(self) -> int:
        """An endsub: the caller's #1..#30 and local named parameters back (:meth:`_call`), its next line."""
        if not self.calls:
            raise Declined("an endsub outside a call")
        ret, saved, label, named = self.calls.pop()
        self.open.discard(label)
        if saved is not None and named is not None:
            S, N = self.S, self.N
            for k in S.keys() & _SUB_KEYS:
                del S[k]
            S.update(saved)
            N.clear()
            N.update(named)
        return ret

    # -- ordinary lines -----------------------------------------------------------------------------------
    def _parsed(self, line: str) -> Any:
        """The step of a line the parser reads afresh (comments, non-ASCII text, a new shape)."""
        if not line.strip():
            return None
        try:
            pl = parse_line(line, 1, "<double pass>")
        except GcodeError:  # the full path reports it
            raise Declined("a line that does not parse") from None
        for comment, _col in pl.comments:
            if magic_comment(comment) is not None:
                raise Declined("a magic comment")
        if pl.oword is not None or pl.delete or pl.percent or pl.unsupported is not None:
            raise Declined("a line the double pass does not follow")
        if not pl.words and not pl.assigns:
            return None
        em = _Emit(_const, self._pconst)
        body: list[str] = []
        vals, codes = _words(em, pl.words, body, _const_code, self.cycle_text)
        writes = _assigns(em, pl.assigns, body, self._pconst)
        if not pl.words:  # parameters set, no word: the plan does nothing (its ``return False``), not called
            return self._exec(body, writes, vals, None, {})
        plan = self._plan(_letters(pl.words), tuple(int(c) for c in codes))
        return self._exec(body, writes, vals, None, {"PLAN": plan})

    def _plain(self, line: str, layout: bytes) -> tuple[Any, Any] | None:
        """``(step, cutter)`` of the lines of the layout of ``line`` when it is words of a letter and a number
        only (``G2 X-1.5 Y.25 R3``, the most common CAM line), else None.  No shape is made
        (:func:`~nczones.gcode.shapes.shaped` compiles one for the full path's runner, about 1 ms; CAM output
        with arcs has dozens, and hundreds of layouts): the line is parsed (:func:`parse_line`) and its words
        must be the numbers the pattern finds, each its own ``NUM`` (``float`` of its text, sign included); the
        cutter slices those texts (the lines of a layout have their numbers at the same columns, and parse
        alike: only digits differ), and the step is compiled once per sequence of letters.  One line is parsed per
        layout with its runs of digits made one (``G2 X0.0 Y0.0`` for ``G2 X-1.25 Y3.5`` and ``G3 X12.5 Y0.75``):
        the pattern, like the parser's numbers (``_NUMBER``), reads a run of digits of any length alike."""
        found = _PLAIN.fullmatch(line)
        if found is None:
            return None
        spans = [m.span(2) for m in _PLAIN_WORD.finditer(line)]
        cuts = [slice(a, b) for a, b in spans]
        cut = itemgetter(*cuts) if len(cuts) > 1 else (lambda text, c=cuts[0]: (text[c],))
        kind = _DIGIT_RUNS.sub(b"0", layout)
        step = self.plain_kinds.get(kind)
        if step is not None:
            return step, cut
        try:
            pl = parse_line(line, 1, "<double pass>")
        except GcodeError:  # the full path reports it
            raise Declined("a line that does not parse") from None
        if pl.oword is not None or pl.delete or pl.percent or pl.unsupported is not None or pl.comments \
                or pl.assigns or len(pl.words) != len(spans):
            return None
        letters = ""
        leaf_of: dict[int, str] = {}
        for k, (word, (a, b)) in enumerate(zip(pl.words, spans)):
            letter, tree = word[0], word[1]
            if tree[0] != NUM or not tree[1] == float(line[a:b]) or line[a - 1].upper() != letter:
                return None
            leaf_of[id(tree)] = f"P[{k}]"
            letters += letter
        step = self.plain_steps.get(letters)
        if step is None:
            step = self.plain_steps[letters] = self._exec(*self._source_code(pl, leaf_of))
        if len(self.plain_kinds) < MAX_STEPS:
            self.plain_kinds[kind] = step
        return step, cut

    def _fresh(self, line: str) -> tuple:
        """The step of an ASCII line without comments whose layout has no compiled shape yet."""
        try:
            shape, literals = shaped(line, 1, "<double pass>")
        except GcodeError:  # the full path reports it
            raise Declined("a line that does not parse") from None
        if literals is not None and shape.run is not None:
            return self._shape_step(shape), literals
        return self._parsed(line), ()

    def _shape_step(self, shape: Any) -> Any:
        """The step of the lines of a shape, of their literals (``P``), made once per pass."""
        fn = self.shape_steps.get(shape)
        if fn is None:
            fn = self.shape_steps[shape] = self._exec(*self._shape_code(shape))
        return fn

    def _shape_code(self, shape: Any) -> _Code:
        return self._source_code(*shape_source(shape))

    def _source_code(self, pl: Any, leaf_of: dict[int, str]) -> _Code:
        """The code of the step of the lines parsed as ``pl`` whose literals' sources (``P[k]``) are ``leaf_of``
        (by ``id`` of their ``NUM`` nodes)."""
        if pl.oword is not None or pl.delete or pl.percent or pl.unsupported is not None or pl.comments:
            raise Declined("a line the double pass does not follow")

        def src(node: Any) -> str:
            text = leaf_of.get(id(node))
            if text is None:
                raise Declined("a literal the shape does not cut")
            return text

        def index(node: Any) -> str:
            return f"(I.get({src(node)}) or _pindex({src(node)}))"

        em = _Emit(lambda node: f"float({src(node)})", index)
        body: list[str] = []
        vals, codes = _words(em, pl.words, body, src, self.cycle_text)
        writes = _assigns(em, pl.assigns, body, index)
        letters = _letters(pl.words)
        if not codes:  # one plan for every line (made when the first is run: a plan may decline)
            if not letters:  # parameters set, no word: the plan does nothing (its ``return False``), not called
                return body, writes, vals, None, {}
            return body, writes, vals, None, {"PLAN": self._plan(letters, ())}
        made: dict[Any, Any] = {}

        def plan_of(texts: Any) -> Any:
            """The plan of a line of this shape whose G/M literals are ``texts``."""
            every = texts if len(codes) > 1 else (texts,) if codes else ()
            plan = made[texts] = self._plan(letters, tuple(_code(t) for t in every))
            return plan

        key = codes[0] if len(codes) == 1 else "(" + ", ".join(codes) + ",)"
        return body, writes, vals, key, {"PLANS": made, "PLAN_OF": plan_of}

    def _compiled_args(self, trees: Any) -> Any:
        """A call's arguments' step: ``step(())`` is the tuple of their doubles, computed in order."""
        em = _Emit(_const, self._pconst)
        body: list[str] = []
        ds = [em.value(tree, body) for tree in trees]
        lines = ["def step(P):"] + [f"    {b}" for b in body] + [f"    return ({''.join(d + ', ' for d in ds)})"]
        scope = dict(self.env)
        exec(compiled("\n".join(lines) + "\n", "<double pass>"), scope)  # noqa: S102  # built from reprs
        return scope["step"]

    def _compiled_cond(self, tree: Any) -> Any:
        """A condition's step: ``step(())`` is its double."""
        em = _Emit(_const, self._pconst)
        body: list[str] = []
        d = em.value(tree, body)
        lines = ["def step(P):"] + [f"    {b}" for b in body] + [f"    return {d}"]
        scope = dict(self.env)
        exec(compiled("\n".join(lines) + "\n", "<double pass>"), scope)  # noqa: S102  # built from reprs
        return scope["step"]

    def _exec(self, body: list[str], writes: list[str], values: list[str], key: str | None, extra: dict) -> Any:
        """``step(P)``: the body, the writes, then the line's plan on its values (True: the program ends)."""
        lines = ["def step(P):"] + [f"    {b}" for b in body] + [f"    {w}" for w in writes]
        if not extra:  # no plan: a line that only sets parameters
            lines.append("    return False")
            return self._compiled(lines, extra)
        if key is None:
            lines.append("    plan = PLAN")
        else:
            lines += [f"    plan = PLANS.get({key})", "    if plan is None:", f"        plan = PLAN_OF({key})"]
        lines.append(f"    return plan(({''.join(v + ', ' for v in values)}))")
        return self._compiled(lines, extra)

    def _compiled(self, lines: list[str], extra: dict) -> Any:
        """The function ``step`` of source ``lines``, in the pass's environment and ``extra``."""
        scope = dict(self.env)
        scope.update(extra)
        exec(compiled("\n".join(lines) + "\n", "<double pass>"), scope)  # noqa: S102  # built from reprs
        return scope["step"]

    def moved(self, axes: tuple[int, ...]) -> None:
        """The motion about to be added moves ``axes``: the first such row of each."""
        row = self.row0 + len(self.columns[0])
        for i in axes:
            if not self.first_row[i]:
                self.first_row[i] = row

    # -- tool lengths and arcs ---------------------------------------------------------------------------
    def _tools(self, machine: Any, exact_offsets: dict[str, tuple[Fraction, ...]]) -> None:
        """The tool lengths ``G43 H<n>`` may apply (the machine's ``[tool_lengths]``, on its tool axis; none on a
        machine with a tool tip zone, whose test needs the length: the full path's) and the bound of every
        offset a row may be computed with (a work offset plus a tool length)."""
        tool_axis = getattr(machine, "tool_axis", None)
        self.tool_axis = self.index.get(tool_axis) if tool_axis else None
        tips = any(getattr(getattr(z, "point", None), "value", None) == "tip" for z in machine.allowed.zones)
        lengths = dict(getattr(machine, "tool_lengths", {}) or {})
        self.lengths: dict[int, Fraction] = lengths if self.tool_axis is not None and not tips else {}
        bound = [max(abs(vec[i]) for vec in exact_offsets.values()) for i in range(len(self.axes))]
        if self.tool_axis is not None:
            bound[self.tool_axis] += max((abs(v) for v in self.lengths.values()), default=Fraction(0))
        self.offset_bound = tuple(bound)
        self.exact_offsets = {int(name[1:]): vec for name, vec in exact_offsets.items()}
        self.reg: int | None = None  # the length register applied (G43 H<reg>); None: G49
        self.reg_inch = False  # the units (G20?) the length was applied in (:meth:`tool`)
        self.tool_offsets: dict[tuple[int, int], tuple[float, ...]] = {}

    def _offset(self, wcs: int, reg: int | None) -> tuple[float, ...]:
        """The doubles of work offset ``wcs`` plus the length of register ``reg`` on the tool axis (each exact
        sum rounded once, as a work offset alone is)."""
        if reg is None:
            return self.offsets[wcs]
        off = self.tool_offsets.get((wcs, reg))
        if off is None:
            vec = list(self.exact_offsets[wcs])
            assert self.tool_axis is not None  # self.lengths is empty without one
            vec[self.tool_axis] += self.lengths[reg]
            off = self.tool_offsets[(wcs, reg)] = tuple(float(v) for v in vec)
        return off

    def tool(self, reg: int | None) -> None:
        """G43 H<reg> (None: G49): the tool length the next motions add."""
        if self.reg is not None and self.reg_inch != self.inch:
            # LinuxCNC 2.9 keeps the applied length in the units it was applied in (the full path: unknown)
            raise Declined("G43 or G49 after G20/G21 while a tool length is applied")
        self.reg, self.reg_inch = reg, self.inch
        self.off = self._offset(self.wcs, reg)
        if self.cc is not None:
            self.cc.offset_to(self.wcs, reg)

    def work(self, wcs: int) -> None:
        """G54..G59: the work offset the next motions add."""
        self.wcs = wcs
        self.off = self._offset(wcs, self.reg)
        if self.cc is not None:
            self.cc.offset_to(wcs, self.reg)

    def _arcs_state(self, machine: Any, arc_tolerance: Fraction | str) -> None:
        #: the plane the program has set (17, 18, 19; 0 before it sets one: the full path notes the plane at an
        #: arc then)
        self.plane = 0
        modal = machine.modal
        self.start_plane = 18 if "G18" in modal else 19 if "G19" in modal else 17  # the full path's start
        self.tiny_pad = float(max(self.offset_bound, default=Fraction(0))) * 1e-14  # the rows' offset term
        self.rule = radius_rule(arc_tolerance)
        #: the plane of the last arc (0: none yet) and its slot; the planes' axes (first, second: ``_ARC_PLANES``),
        #: a pair per plane in the order the arcs met them, and each plane's slot there (:attr:`DoublePath.arc_axes`);
        #: per arc held its slot (:attr:`DoublePath.arc_planes`)
        self.arc_plane = self.arc_slot = 0
        self.arc_axes: tuple[int, ...] = ()
        self.plane_slots: dict[int, int] = {}
        self.arc_slots = array("b")
        top = max((self.offset_bound[self.index[a]] for a in "XYZ" if a in self.index), default=Fraction(0))
        self.offb = math.nextafter(float(top), math.inf)  # at or above every plane axis's offsets
        self.arcs = 0  # the arcs of the rows dropped (full()); those held are arc_rows
        self.arc_rows = array("q")
        self.arc_boxes = array("d")  # per arc: xlo, xhi, ylo, yhi (DoublePath.arc_boxes)
        #: per arc: its box's kind, R and 0 or I and J, the offsets' bound it was computed with (DoublePath.arc_more)
        self.arc_words = array("d")
        #: the same of the arcs since :meth:`arc_flush`, in one list, a record of :data:`_ARC_ITEMS` an arc (its
        #: row, its box's four bounds, its four words: one ``extend`` an arc, arc43; all in :attr:`arc_slot`): an
        #: array's append and extend parse each item with ``PyArg_Parse`` (some 500 instructions, a tenth of a
        #: lathe program's pass); the arrays keep a window's arcs in a quarter of a list's memory
        self.new_arcs: list[Any] = []

    def add_arc(self, row: int, box: Any, words: tuple[float, float, float, float]) -> None:
        """An arc ending at ``row`` (counted from the program's start) with its ``box`` and ``words`` (its box's
        kind, R and 0 or I and J, the offsets' bound: :attr:`DoublePath.arc_more`), in the plane of
        :meth:`arc_in`: what a plan's ``AX`` does (a compensation corner's, .double_comp)."""
        new = self.new_arcs
        new.append(row - self.row0 + 1)  # (_ARC_ITEMS)
        new.extend(box)
        new.extend(words)
        if len(new) >= _ARC_BUFFER * _ARC_ITEMS:
            self.arc_flush()

    def arc_flush(self) -> None:
        """Move the arcs of :attr:`new_arcs` to the arrays (their items gathered by strided slices, each array's
        packed at once: no item parsed)."""
        new = self.new_arcs
        if new:
            from struct import pack as _pack  # (not at start-up: a program with arcs only)

            k, w = len(new) // _ARC_ITEMS, _ARC_ITEMS
            boxes, words = [0.0] * (4 * k), [0.0] * (4 * k)
            for j in range(4):
                boxes[j::4] = new[1 + j::w]
                words[j::4] = new[5 + j::w]
            self.arc_rows.frombytes(_pack(f"{k}q", *map((self.row0 - 1).__add__, new[0::w])))
            self.arc_boxes.frombytes(_pack(f"{4 * k}d", *boxes))
            self.arc_words.frombytes(_pack(f"{4 * k}d", *words))
            self.arc_slots.frombytes(bytes((self.arc_slot,)) * k)  # (every arc held is in it: arc_in)
            new.clear()

    def assume(self) -> None:
        """A motion while the units, distance mode or work offset are still the machine file's: the full path
        notes each such group at its first motion (``Interpreter.note_assumed``, in this order) and runs on with
        the machine file's code, as the pass does; the notes are the path's (:attr:`DoublePath.assumed`)."""
        for group in ("units", "distance", "offset"):
            if group in self.unset:
                self.assumed[group] = self.start_codes[group]
        self.unset.clear()

    def assume_plane(self) -> int:
        """An arc before the program sets the plane: the machine file's plane, noted as the full path notes it
        (after the groups of :meth:`assume`), and in force from here on."""
        self.assumed["plane"] = f"G{self.start_plane}"
        self.plane = self.start_plane
        return self.plane

    def arc_in(self, plane: int) -> None:
        """An arc in ``plane``, another than the last arc's: its plane's slot (a new pair of
        :attr:`DoublePath.arc_axes` for a plane met first) is the arcs' from it on (:attr:`DoublePath.arc_planes`)."""
        self.arc_flush()  # the arcs held are in the slot before
        slot = self.plane_slots.get(plane)
        if slot is None:
            a, b, _words = _ARC_PLANES[plane]
            slot = self.plane_slots[plane] = len(self.plane_slots)
            self.arc_axes += (self.index[a], self.index[b])
        self.arc_plane, self.arc_slot = plane, slot

    def _modes_state(self, machine: Any) -> None:
        """The path mode and the dwells (:meth:`mode`, :meth:`dwelt`), and whether M6 moves on ``machine``."""
        start = getattr(machine, "path_mode", "G64")
        #: a motion so far may blend (the machine starts in G64, with or without a tolerance, or the program set
        #: G64): an arc after a motion LinuxCNC may drop (shorter than DROPPED_BELOW on every axis) is run from
        #: the corner, which the full path answers unknown for (prover/blend.py)
        self.blend = start == "G64"
        #: the motions now blend without a tolerance (G64 without P: their corners are proved one by one)
        self.bare = start == "G64" and not getattr(machine, "path_tolerance", None)
        #: (first row, bare) where the path mode changes, rows counted from the program's start (DoublePath.modes)
        self.modes: list[tuple[int, bool]] = [(1, self.bare)]
        self.tol = 0.0  # DoublePath.tolerance
        self.dwells = 0  # dwells (G4) in the whole program; those of the rows held are dwell_rows
        self.dwell_rows = array("q")
        self._g91_state()
        self.tool_moves = bool(getattr(machine, "tool_change_quill_up", False)
                               or getattr(machine, "tool_change_at_g30", False)
                               or getattr(machine, "tool_change_position", None))

    def _g91_state(self) -> None:
        """G91: the distance mode, and per axis the bound of the error its G91 chain has built (:meth:`_straight_ends`)."""
        n = len(self.axes)
        self.inc = False  # G91 (a machine that starts in it declines)
        self.inch = False  # G20 (a machine that starts in it declines)
        self.slow = False  # G91, G20 or a G91 chain open: straight moves take the slow code (_straight_ends)
        #: per axis: None (its row is a G90 one or the start: the module's bound holds) or a bound (a float,
        #: rounded up) of the distance of its double from the full path's exact coordinate (_straight_ends)
        self.err: list[float | None] = [None] * n
        self.chained = False  # some axis has a G91 chain's error
        #: per axis: the largest error of the rows held (the window's, DoublePath.inc_bound), and the last chain
        #: ended (its G90 row, the chain's error): a window's first row keeps its error (full())
        self.xerr = [0.0] * n
        self.touched: list[tuple[int, float | None]] = [(-1, None)] * n
        self.offb2 = [math.nextafter(float(2 * b), math.inf) for b in self.offset_bound]

    def unchain(self, axes: tuple[int, ...]) -> None:
        """A G90 move sets ``axes``: their rows have the module's bound again (the chain's error is kept for
        the row before, :meth:`full`)."""
        row = self.row0 + len(self.columns[0])
        for i in axes:
            if self.err[i] is not None:
                self.touched[i] = (row, self.err[i])
                self.err[i] = None
        self.chained = any(e is not None for e in self.err)
        self.slow = self.inc or self.chained or self.inch

    def distance(self, inc: bool) -> None:
        """G90 (``inc`` false) or G91."""
        self.inc = inc
        self.slow = inc or self.chained or self.inch

    def units(self, inch: bool) -> None:
        """G20 (``inch``) or G21: the straight moves after it scale their words (:mod:`.double_units`)."""
        self.inch = inch
        self.slow = self.inc or self.chained or inch

    def mode(self, bare: bool) -> None:
        """G64 without P (``bare``), or G61 or G61.1: the path mode of the next motions (its block's included)."""
        self.blend = self.blend or bare
        if bare == self.bare:
            return
        self.bare = bare
        row = self.row0 + len(self.columns[0])  # the next motion's
        if self.modes[-1][0] == row:
            self.modes.pop()
        if not self.modes or self.modes[-1][1] != bare:
            self.modes.append((row, bare))

    def tolerance(self, p: float, q: float | None = None) -> None:
        """``G64 P<p> [Q<q>]``: the next motions blend within ``p`` of the programmed path after LinuxCNC's
        naive-CAM merging within ``q`` (``convert_control_mode``: Q absent or below 0 is P), so within ``p + q``
        of it (the full path's ``PathMode.bound``, ``CornerCheck._near``); :attr:`DoublePath.tolerance` bounds
        that for every motion.  A word's exact value is within half an ulp of its double, so at most the next
        double up; a Q whose double is below 0 or -0.0 (its exact value below 0, which is P, or 0) is bounded by
        P's, +0.0 (0, or a positive exact value below the least double) by the least double; the sum rounded up;
        in G20 (the block's units, set before its path mode) 25.4 times that, each product rounded up.  ``p`` not above 0 (no tolerance, or an exact value that may be 0)
        declines: the full path's naive-CAM windows (G64 Q without P) are not the pass's."""
        if not 0.0 < p < math.inf or not (q is None or -math.inf < q < math.inf):
            raise Declined("G64 P not above 0")
        self.mode(False)
        self.blend = True  # the motions blend (within the tolerance), so an arc after a tiny motion declines
        up = math.inf
        p = math.nextafter(p, up)
        qb = p  # Q absent, below 0 or -0.0: bounded by P's
        if q is not None and (q > 0.0 or (q == 0.0 and math.copysign(1.0, q) > 0.0)):
            qb = math.nextafter(q, up)
        t = math.nextafter(p + qb, up)
        if self.inch:  # P and Q in inches (LinuxCNC reads them after the block's units), each rounding up
            t = math.nextafter(t * math.nextafter(25.4, up), up)
        self.tol = max(self.tol, t)

    def dwelt(self, row: int) -> None:
        """G4: the row just added (of the columns held) is a dwell where the machine stands."""
        self.dwells += 1
        self.dwell_rows.append(self.row0 + row)

    def dwell_at(self, row: int) -> bool:
        """Is the motion that ends at ``row`` (of the columns held) a dwell?"""
        rows, r = self.dwell_rows, self.row0 + row
        k = bisect_left(rows, r)
        return k < len(rows) and rows[k] == r

    def tiny(self, row: int) -> bool:
        """May the motion that ends at ``row`` (of the columns held) be dropped by LinuxCNC: is it shorter than
        :data:`~nczones.motion.DROPPED_BELOW` on every axis, within far more than the rows' error?  (A G91 chain's
        rows are within its bound, at most the axis's ``xerr``, of the exact ones: twice that more.)"""
        pad = self.tiny_pad
        return all(abs(col[row] - col[row - 1]) < _DROPPED + (abs(col[row]) + abs(col[row - 1])) * 4e-15 + pad + 2 * e
                   for col, e in zip(self.columns, self.xerr))

    def lone(self, row: int) -> bool:
        """Is the motion that ends at ``row`` the program's first, with the same doubles as the start on every
        axis?  The full path (``CornerCheck._segment``, ``prover/blend.py``) skips a motion of length 0 (LinuxCNC's
        canon drops it) and notes a short one as dropped only with a motion before it (``_dropped_corner``: the
        corner is then between that motion and the next); before the first motion there is none, so an arc
        after it is proved from its own start, as the pass's box holds it.  Equal doubles: the motion's exact
        length is within the rows' bound (about ``1e-15`` of the coordinates), a motion of length 0 or one the
        full path would drop, never one it runs."""
        if self.row0 + row != 1:
            return False
        return all(col[1] == col[0] for col in self.columns)

    def _end(self, values: tuple) -> bool:
        """M2 or M30: the program ends."""
        self.blocks += 1
        return True

    # -- words ----------------------------------------------------------------------------------------------
    def _plan(self, letters: str, codes: tuple[int, ...]) -> Any:
        """What a line with ``letters`` and G/M ``codes`` does, as a function of its other words' values
        (True: the program ends); one per kind of line, shared by every step."""
        key = (letters, codes)
        plan = self.plans.get(key)
        if plan is None:
            plan = self.plans[key] = self._make_plan(letters, codes)
        return plan

    def _make_plan(self, letters: str, codes: tuple[int, ...]) -> Any:
        by: dict[str, list[int]] = {x: [] for x in _CODE_LETTERS}
        for c, letter in zip(codes, [x for x in letters if x in _CODE_LETTERS]):
            by[letter].append(c)
        gs, ms, hs, ts, qs = (by[x] for x in _CODE_LETTERS)
        others = [x for x in letters if x not in _CODE_LETTERS]
        if ms in ([2], [30]) and not gs and not others and not hs and not ts and not qs:
            return self._end
        self._tool_change(ms, ts, qs)
        aux = [m for m in ms if m != 6 and m != 61]
        if aux and (len(aux) != 1 or aux[0] not in _AUX_M):
            raise Declined("an M code the double pass does not follow")
        groups = _groups(gs)
        if len(set(others)) != len(others) or len(hs) > 1:
            raise Declined("a word twice")
        for x in others:
            if x not in "FSIJKRPDqL" and x not in self.index:
                raise Declined(f"an axis word {x} the machine does not have")
        axes = [(k, self.index[x]) for k, x in enumerate(others) if x not in "FSIJKRPDqL"]
        why = spindle_mode(groups, comp_others(groups, others))  # G96/G97 and D (.double_lathe; G41's: .double_comp)
        if why is not None:
            raise Declined(why)
        if "q" in others and not (takes_q(groups, bool(axes)) or _g64_q(groups, others, bool(axes))):
            raise Declined("a word Q without M61, G73, G83 or G64 P")  # (.double_cycles: a Q in a line without M)
        if groups.get("motion") == 80 and axes:
            raise Declined("axis words with G80")
        if "L" in others and not axes and groups.get("motion") not in CYCLE_CODES:
            raise Declined("a word L outside a canned cycle")
        body = ["st.blocks += 1", *spindle_body(ms)] if letters else []
        if "feedmode" in groups:  # LinuxCNC sets the feed rate to 0 on G94 (before it reads F)
            body.append("st.feed = 0.0")
        if "F" in others:
            body += [f"f = v[{others.index('F')}]", "if not f > 0.0: raise D('a feed that is not positive')",
                     "st.feed = f"]
        if "S" in others:  # the full path's GC209 for a negative speed; the speed itself moves nothing
            body.append(f"if not v[{others.index('S')}] >= 0.0: raise D('a negative spindle speed')")
        checks, select = comp_body(self, groups, ms, ts, qs, others, Declined)  # cutter compensation (.double_comp)
        body += checks + self._dwell_body(groups, others, bool(axes))
        body += self._modal_body(groups, hs, others) + cycle_modal(groups) + select
        if groups.get("motion") in (1, 2, 3) and not axes:  # G1 without axis words: LinuxCNC checks the feed too
            if groups["motion"] != 1 or any(x in "IJKR" for x in others):
                raise Declined("an arc without axis words")
            body.append("if not st.feed > 0.0: raise D('G1 without a positive feed')")
        # a cycle block runs without axis words too
        calls = cycle_call(others, axes) if axes or groups.get("motion") in CYCLE_CODES else []
        if axes:
            code = groups.get("motion")
            body += _cycle_in_mode(calls, self._motion_body(others, axes, code if code in (0, 1, 2, 3) else None))
        elif any(x in "IJKR" for x in others) and groups.get("motion") not in CYCLE_CODES:
            raise Declined("I, J, K or R without a motion")
        else:
            body += calls
        return self._compiled_plan(body)

    def _compiled_plan(self, body: list[str]) -> Any:
        """The function ``plan(v)`` of ``body`` (then ``return False``) in the plans' scope."""
        flags = sorted({b.strip()[3:-1] for b in body if b.strip().startswith("if NEW") and b.endswith(":")})
        lines = ["def plan(v):", *([f"    global {', '.join(flags)}"] if flags else []),
                 *(f"    {b}" for b in body), "    return False"]
        scope: dict[str, Any] = {"st": self, "D": Declined, "unset": self.unset, "pos": self.pos,
                                 "FR": self.first_row, "IJ_ARC": ij_check, "IOFFB": inch_offb,
                                 "AX": self.new_arcs.extend, "NEW": self.new_arcs,
                                 "ERR": self.err, "XERR": self.xerr,
                                 "NA": math.nextafter, "INF": math.inf, "EPS2": _EPS2, "CY": self.cyc.run,
                                 "CYC": CYCLE_CODES, "TA": TA, "CS": self.cc, "LV": self.cyc.lits,
                                 "W": None if self.cc is None else self.cc.words}
        scope.update({f"C{i}": col for i, col in enumerate(self.columns)})
        scope.update(dict.fromkeys(flags, True))  # (_first_rows: a plan's first run records its axes' first rows)
        exec(compiled("\n".join(lines) + "\n", "<double pass plan>"), scope)  # noqa: S102  # from reprs
        return scope["plan"]

    def _modal_body(self, groups: dict[str, int], hs: list[int], others: list[str]) -> list[str]:
        """The code of a block's plane, units, distance mode, work offset, tool length, path mode and motion
        mode (in LinuxCNC's order, before its motion)."""
        body = []
        if "plane" in groups:
            body.append(f"st.plane = {groups['plane']}")
        sets = sorted(g for g in ("units", "distance", "offset") if g in groups)
        if sets:
            body.append(f"unset.difference_update({tuple(sets)!r})")
        if "units" in groups:
            if groups["units"] == 20 and not self.g20_text:  # (a G20 the text's "20" misses: "G2 0")
                raise Declined("G20 written apart")
            if groups["units"] == 20:  # the inch code scales v[k], not an X diameter's half (diameter_body)
                if self.diameter:
                    raise Declined("G20 where X may be a diameter (a lathe, or after G7)")
                self.g20_compiled = True
            body.append(f"st.units({groups['units'] == 20})")
        if "offset" in groups:
            body.append(f"st.work({groups['offset']})")
        body += self._tool_body(groups.get("tool"), hs)
        diameter = diameter_body(self, groups)  # G7/G8 (.double_lathe)
        if diameter.__class__ is str:
            raise Declined(str(diameter))
        body += diameter
        if "path" in groups:
            if groups["path"] == 64 and "P" in others:  # G64 P (_dwell_body: then no G4 nor G82 takes it)
                q = f"v[{others.index('q')}]" if "q" in others else "None"  # (_g64_q: then no G83 takes it)
                body.append(f"st.tolerance(v[{others.index('P')}], {q})")
            else:
                body.append(f"st.mode({groups['path'] == 64})")
        if "distance" in groups:
            if groups["distance"] == 91 and not self.g91_text:  # (a G91 the text's "91" misses: "G9 1")
                raise Declined("G91 written apart")
            body.append(f"st.distance({groups['distance'] == 91})")
        if "motion" in groups:
            body.append(f"st.motion = {None if groups['motion'] == 80 else groups['motion']}")
        return body

    def _tool_change(self, ms: list[int], ts: list[int], qs: list[int]) -> None:
        """Decline the T, M6 and M61 Q words of a block the pass does not follow.

        ``T<n>`` selects a tool and ``M6`` (``M61 Q<n>``) puts it (tool n) in the spindle: on the full path
        (``Interpreter.put_in_spindle``) that sets ``tool_in_spindle`` and ``spindle_tools`` and stops the
        spindle; none moves anything nor changes the tool length applied (LinuxCNC keeps ``G43``'s length at
        ``M6``), and what reads them the pass declines: ``G43`` without ``H`` (the tool in the spindle's
        length), cutter compensation (its diameter), the state parameters (``#5400``, ``#<_current_tool>``)
        and the tool solids' check (``prover/doubles.py`` declines a machine with tool solids).  M6 moves
        only on a machine with ``[machine] tool_change_*`` (``Interpreter._tool_change_moves``): declined
        there.  The numbers are literals (a computed T might not be a whole number: the full path's GC209)."""
        change = [m for m in ms if m == 6 or m == 61]
        if len(ts) > 1 or len(qs) > 1 or len(change) > 1 or any(t < 0 for t in ts + qs):
            raise Declined("a T or Q word twice or not a whole number, or M6 and M61 in a block")
        if (61 in change) != bool(qs):
            raise Declined("M61 without Q, or a Q word without M61")
        if 6 in change and self.tool_moves:
            raise Declined("M6 on a machine with tool change moves ([machine] tool_change_*)")

    def _dwell_body(self, groups: dict[str, int], others: list[str], axes: bool) -> list[str]:
        """The code of a block's ``G4 P<seconds>``: a row where the machine is (the full path's ``DWELL``
        segment), noted as a stop (:meth:`dwelt`).  Declined: P without G4, G4 without P, with axis words,
        I, J, R or a motion code (LinuxCNC's G4 X is not Fanuc's), a time that is not positive (its exact
        value may be below 0: the full path's GC209; a double above 0 is an exact value above 0)."""
        if groups.get("nonmodal") is None:
            if "P" in others and (groups.get("path") == 64) == takes_p(groups, axes):
                raise Declined("a word P outside G4, G64 and G82, or a P two of them may take")
            return []
        if "P" not in others:
            raise Declined("G4 without P")
        if "path" in groups:
            raise Declined("G4 and G64 P in one block")
        if axes or "motion" in groups or any(x in "IJKR" for x in others):
            raise Declined("G4 with axis words, I, J, R or a motion code")
        return [f"if not v[{others.index('P')}] > 0.0: raise D('a dwell time that is not positive')",
                *(f"C{i}.append(pos[{i}])" for i in range(len(self.axes))),
                "n = len(C0)", "st.dwelt(n - 1)", f"if n >= {self.rows}: st.full()"]

    def _tool_body(self, code: int | None, hs: list[int]) -> list[str]:
        """A block's G43 H<n> or G49 (an H word without G43 is LinuxCNC's error; G43 without H, or with H0,
        applies the tool in the spindle, which the pass does not follow)."""
        if code is None:
            if hs:
                raise Declined("an H word without G43")
            return []
        if code == 49:
            if hs:
                raise Declined("an H word without G43")
            return ["st.tool(None)"]
        if len(hs) != 1 or hs[0] not in self.lengths:
            raise Declined("G43 without an H register of the machine's [tool_lengths] (or with a tip zone)")
        return [f"st.tool({hs[0]})"]

    def _straight_ends(self, axes: list[tuple[int, int]]) -> list[str]:
        """The code of a straight move's ends: G90 ``v + off`` (an axis set so ends a G91 chain,
        :meth:`unchain`), G91 ``x = pos + v`` with the bound ``ERR`` of its error (``_Pass.err``).

        The full path's exact G91 end is ``M + w`` (``Interpreter.program_target``: the machine position plus
        the word's exact value ``w``; the offsets cancel), the double here ``x = fl(p + d)``.  With
        ``|p - M| <= e`` (a G90 row's bound, ``(2 |p| + 2 |offset|) 2**-53``, when the chain starts),
        ``|d - w| <= |d| 2**-53`` (half an ulp) and ``|x - (p + d)| <= |x| 2**-53`` (or half the least
        subnormal): ``|x - (M + w)| <= e + (|d| + |x|) 2**-53 + 2**-1075``.  The bound is computed with
        ``2**-52`` (a float sum ``|d| + |x|`` may round down by half an ulp) and each float result moved up by
        ``nextafter``, which adds at least half the least subnormal: every float here is above the real sum it
        stands for, so ``e`` bounds the error however long the chain (it grows along it: the row before a
        chained row has no more error, which :meth:`full` relies on; a G90 move of the axis ends the chain).

        One ``nextafter`` a step (plane42): ``e' = nextafter(u, +inf)``, ``u = fl(e + t)``, ``t = fl(s 2**-52)``,
        ``s = fl(|d| + |x|) >= (|d| + |x|)(1 - 2**-53)``.  ``u`` is below ``e + t`` by at most half the gap above
        it, which ``nextafter`` adds whole: ``e' >= e + t + 2**-1075`` (a gap is at least ``2**-1074``).  So
        ``t >= (|d| + |x|) 2**-53 =: a`` is enough.  The scaling is exact unless ``s 2**-52`` is subnormal, then
        within ``2**-1075``: exact, ``t >= 2 a (1 - 2**-53) >= a``; ``t = 0``: ``s 2**-52 <= 2**-1075``, so ``a <
        2**-1075`` and ``e' >= e + 2**-1074 > e + a + 2**-1075``; else ``t >= 2**-1074``, which is ``>= a`` when
        ``a <= 2**-1074``, and otherwise ``t >= 2 a (1 - 2**-53) - 2**-1075 >= a``.  (Overflow: inf, a bound.)"""
        g90, slow = self._ends(axes)
        if slow is None:
            return g90
        # one test on the common way (G90 G21, no chain open: ``slow`` false)
        return ["if st.slow:", *(f"    {b}" for b in slow), "else:", *(f"    {b}" for b in g90)]

    def _ends(self, axes: list[tuple[int, int]]) -> tuple[list[str], list[str] | None]:
        """:meth:`_straight_ends`'s two ways: the common one's code (G90 G21, no chain open) and the slow one's
        (G91, G20 or a chain open: ``st.slow``; None when the text writes neither G91 nor G20)."""
        named = tuple(i for _k, i in axes)
        g90 = [f"pos[{i}] = x{i} = {self._word(k, i)} + off[{i}]" for k, i in axes]
        if not self.g91_text and not self.g20_text:  # no G91 nor G20 in the text (_modal_body): no chain
            return g90, None
        inc = []
        for k, i in axes:
            w = self._word(k, i)
            inc += [f"x{i} = pos[{i}] + {w}", f"e = ERR[{i}]", chain_start(i, self.offb2[i], self.g20_text),
                    f"e = ERR[{i}] = NA(e + (abs({w}) + abs(x{i})) * EPS2, INF)",
                    f"if e > XERR[{i}]: XERR[{i}] = e", f"pos[{i}] = x{i}"]
        # G20 (:mod:`.double_units`) in a text that may write it: a branch of the slow way
        inch = ["if st.inch:", *(f"    {b}" for b in inch_ends(axes, self.offb2, named)), "el"] \
            if self.g20_text else [""]
        return g90, [*inch[:-1], f"{inch[-1]}if st.inc:", *(f"    {b}" for b in inc), "    st.chained = True",
                     "else:", *(f"    {b}" for b in g90), f"    st.unchain({named!r})"]

    def _word(self, k: int, i: int) -> str:
        """The source of the double of axis word ``v[k]`` (axis ``i``): an X word times ``st.half`` (G7 halves it,
        :mod:`.double_lathe`) where X may be a diameter, else the word."""
        if i != self.x_axis:
            return f"v[{k}]"
        if not self.diameter:
            self.x_compiled = True
            return f"v[{k}]"
        return f"(v[{k}] * st.half)"

    def _arc_words(self, others: list[str], plane: int) -> tuple[list[str], list[str]]:
        """The code that sets an arc's words in mm (``p``, ``q``; an R arc: ``rel``, the bound of its radius's
        error, :func:`~.double_arcs.r_arc`; an I/J arc: ``oi``, ``ru``, the offsets' bound and rule it is checked
        with) and ``kd``, its kind (``double_arcs.refined``'s flags, G20's among them): on the common way (G21)
        and on the slow one (after the G91 chains have grown ``ob``, :meth:`_arc_plane_body`), where G20 scales
        them (a text that may write it)."""
        def val(x: str) -> str:
            return f"v[{others.index(x)}]" if x in others else "0.0"

        a, b, (wa, wb) = _ARC_PLANES[plane]
        turn = a not in others and b not in others  # the end is the start: a whole turn
        flag = R_SCREEN if "R" in others else IJ_SCREEN | (TURN if turn else 0)
        kind = f"kd = {float(flag | CW)} if mode == 2 else {float(flag)}"
        if "R" in others:  # R in G20: scaled, with double_arcs.R_INCH_REL for its error
            common = [f"p = {val('R')}; rel = {2.0**-51!r}; {kind}"]
            inch = [f"    p = p * {INCH!r}; rel = {R_INCH_REL!r}; kd = kd + {float(INCH_ARC)}"]
        else:  # I/J in G20: scaled, with the offsets' bound and rule of double_arcs.inch_offb, inch_rule
            common = [f"p = {val(wa)}; q = {val(wb)}; oi = ob; ru = {self.rule!r}; {kind}"]
            inch = [f"    p = p * {INCH!r}; q = q * {INCH!r}; oi = IOFFB(ob, p, q); ru = {inch_rule(self.rule)!r}; "
                    f"kd = kd + {float(INCH_ARC)}"]
        return common, [*common, "if st.inch:", *inch] if self.g20_text else common

    def _arc_body(self, others: list[str], plane: int, ends: tuple[str, str, str, str]) -> list[str]:
        """The code that adds the box of the arc just moved in ``plane`` (:mod:`.double_arcs`, on the plane's
        first and second axes as the full path's ``Interpreter.arc``: G18's are Z and X, with K and I) from
        ``sa, sb`` to ``ends[2:]`` with the offsets' bound ``ob`` and the words of :meth:`_arc_words`
        (:meth:`_arc_plane_body`), or declines.  An R arc's quick box is :func:`~.double_arcs.r_screen`'s, run
        inline (:func:`~.double_arcs.r_screen_code`); an I/J arc's ``ij_check``'s.  The arc's record (its row,
        box, words and plane slot, :meth:`add_arc`) is one ``extend`` of :attr:`new_arcs`."""
        a, b, _words = _ARC_PLANES[plane]
        ia, ib = self.index[a], self.index[b]
        turn = a not in others and b not in others  # the end is the start: a whole turn

        def record(xlo: str, xhi: str, ylo: str, yhi: str) -> list[str]:
            q = "0.0" if "R" in others else "q"
            return [f"AX((n, {xlo}, {xhi}, {ylo}, {yhi}, kd, p, {q}, ob))"]  # (n: _ARC_ITEMS)

        if "R" in others:
            box = r_screen_code(ends, "p", "ob", "rel", record)
        else:
            box = [f"box = IJ_ARC({', '.join(ends)}, p, q, mode == 2, oi, ru, {turn}, True)",  # (ij_screen's box)
                   "if box.__class__ is str: raise D(box)", *record("box[0]", "box[1]", "box[2]", "box[3]")]
        return [f"if st.arc_plane != {plane}: st.arc_in({plane})",
                # (first a test tiny() implies, on each of the plane's axes: _short)
                f"if st.blend and n > 2 and ({self._short(ia, 'sa')}) and ({self._short(ib, 'sb')}) "
                "and st.tiny(n - 2) and not st.lone(n - 2) and not st.dwell_at(n - 2): "
                "raise D('an arc after a motion LinuxCNC may drop in a blended corner')",
                *box, f"if len(NEW) >= {_ARC_BUFFER * _ARC_ITEMS}: st.arc_flush()"]

    def _short(self, i: int, s: str) -> str:
        """The test, on axis ``i`` whose start is ``s``, that the blended-corner test of an arc makes before
        ``tiny()``, which it implies: ``tiny()`` holds only if the motion before the arc, from row -3 to ``s`` (row
        -2), is short on every axis.  When it differs by ``LIM`` plus twice a G91 chain's error (``XERR``) or more
        and ``|s| < 1e10``, ``tiny()``'s bound there is below ``DR + PAD + 8e-5 + 4e-15 |t| + 2 XERR < |t|``: most
        arcs follow a motion that is not short on one of the plane's axes (an arc in another plane too).  The
        limit is ``LIM`` (a literal) first: with no chain's error ``LIM + 2 XERR`` is ``LIM``, and with one it is
        larger, so ``|t| < LIM`` implies ``|t| < LIM + 2 XERR`` (arc43: no sum an arc)."""
        lim = 2 * (_DROPPED + self.tiny_pad) + 1e-4
        return (f"-{lim!r} < (bt := {s} - C{i}[-3]) < {lim!r} or XERR[{i}] and -(li := {lim!r} + 2.0 * XERR[{i}]) "
                f"< bt < li or not -1e10 < {s} < 1e10")

    def _arc_plane_body(self, others: list[str], axes: list[tuple[int, int]], plane: int) -> list[str]:
        """The code of an arc in ``plane`` after its checks: its rows and its box, or a decline (the machine
        lacks a plane axis, the block has the centre word of the plane's normal: the full path's GC308,
        GC204).

        The ends are a straight move's (:meth:`_ends`: G90, G91 and G20, the G91 chains' bounds); the arc is
        computed with the offsets' bound grown by the chains' errors of its plane axes at its start and at its
        end (:func:`~.double_arcs.chain_offb`, which says why that holds the arc; ``ERR`` is None off a chain): a
        G91 arc's centre ``S' + (I, J)`` carries its start's error, its end ``S' + W`` its chain's.  The common
        way (G90 G21, no chain open: ``st.slow`` false, so no axis has a chain's error) reads none of them
        (arc43: a dozen tests less an arc)."""
        a, b, words = _ARC_PLANES[plane]
        if a not in self.index or b not in self.index:
            return [f"raise D('an arc in G{plane} on a machine without {a} and {b}')"]
        if any(x in "IJK" and x not in words for x in others):
            return [f"raise D('an arc in G{plane} with a centre word other than {words[0]} and {words[1]}')"]
        ia, ib = self.index[a], self.index[b]
        moved = tuple(sorted({i for _k, i in axes} | {ia, ib}))
        g90, slow = self._ends(axes)
        common, slow_words = self._arc_words(others, plane)
        ends = [*g90, *common]
        if slow is not None:
            slow = [*self._chain_start(ia, ib), *slow, *self._chained(ia, ib), *slow_words]
            ends = ["if st.slow:", *(f"    {b}" for b in slow), "else:", *(f"    {b}" for b in ends)]
        named = {i for _k, i in axes}
        # the ends' sources: the end rows' doubles (x<i> for an axis the block names, else pos[i] read once)
        last = [f"x{i}" if i in named else f"t{i}" for i in (ia, ib)]
        reads = [f"t{i} = pos[{i}]" for i in dict.fromkeys((ia, ib)) if i not in named]
        return [f"sa = pos[{ia}]; sb = pos[{ib}]; ob = {self.offb!r}",
                *_first_rows(moved, f"NEW{plane}"), *ends, *self._levels(others, axes), *self._kept_words(axes),
                *self._appends(axes), "n = len(C0)", *reads,
                *self._arc_body(others, plane, ("sa", "sb", last[0], last[1]))]

    def _chain_start(self, ia: int, ib: int) -> list[str]:
        """The code that reads the G91 chains' errors of the plane's axes at an arc's start (before its ends: a
        G90 end ends its chain; None: no chain), in a text that may write G91."""
        return [f"ea = ERR[{ia}]; eb = ERR[{ib}]"] if self.g91_text else []

    def _chained(self, ia: int, ib: int) -> list[str]:
        """The code that grows ``ob`` by the chains' errors at the arc's start and end, in a text that may write
        G91: :func:`~.double_arcs.chain_offb` inline (a call less an arc; at ``ein`` 0 an ulp above ``offb``, a
        larger bound), its ``ein`` the largest of the four errors (None: 0) by comparisons, not a call of max
        (plane42: 4k instructions less a G91 arc)."""
        if not self.g91_text:
            return []
        return ["if ea is not None or eb is not None or st.chained:",
                f"    ga = ERR[{ia}] or 0.0; gb = ERR[{ib}] or 0.0",
                "    if gb > ga: ga = gb",
                "    if ea is not None and ea > ga: ga = ea",
                "    if eb is not None and eb > ga: ga = eb",
                f"    ob = NA(ob + ga * {2.0**50!r}, INF)"]

    def _appends(self, axes: list[tuple[int, int]]) -> list[str]:
        """The code that appends a motion's end (``x<i>`` for the axes set, else ``pos``) to the columns."""
        set_axes = {i for _k, i in axes}
        return [f"C{i}.append(x{i})" if i in set_axes else f"C{i}.append(pos[{i}])" for i in range(len(self.axes))]

    def _motion_body(self, others: list[str], axes: list[tuple[int, int]], code: int | None = None) -> list[str]:
        """The code of a block's motion: a straight move, or (with I, J, K or R) an arc whose box
        :meth:`_arc_body` adds, in the plane the program has set (a branch per plane).  ``code``: the block's
        own G0-G3 (None: the modal one, ``st.motion``), whose tests of the mode are decided here (lathe40: a
        tenth of a straight move's code)."""
        arc = [x for x in others if x in "IJKR"]
        if arc:
            if "R" in arc and len(arc) > 1:
                raise Declined("R and I, J or K in one arc")
            if any(self.axes[i] not in "XYZ" for _k, i in axes):
                raise Declined("an arc on axes other than X, Y and Z")
        body = _mode_checks(code, bool(arc))
        if arc:
            if self.diameter:  # a G91 arc where X may be a diameter (.double_lathe): the full path's
                body.append("if st.inc or st.chained: raise D('an arc in G91, or on a G91 chain, where X may be a "
                            "diameter')")
        body += ["if unset: st.assume()", "off = st.off"]
        if arc:
            body.append("pl = st.plane or st.assume_plane()")
            planes = []
            for n, plane in enumerate(sorted(_ARC_PLANES)):
                planes.append(f"{'el' if n else ''}if pl == {plane}:")
                planes += [f"    {b}" for b in self._arc_plane_body(others, axes, plane)]
            planes += ["else:", "    raise D('an arc before the program sets the plane')",
                       f"if n >= {self.rows}: st.full()"]
            return body + (planes if self.cc is None else arc_code(others, axes, planes))  # (.double_comp)
        moved = tuple(i for _k, i in axes)
        rapids = ["if not mode: st.rapids += 1"] if code is None else ["st.rapids += 1"] if code == 0 else []
        straight = [*_first_rows(moved, "NEWS"),
                    *self._straight_ends(axes), *self._levels(others, axes), *self._kept_words(axes),
                    *self._appends(axes), "n = len(C0)",
                    f"if n >= {self.rows}: st.full()", *rapids]
        return body + (straight if self.cc is None else straight_code(axes, straight, (self.cc.ia, self.cc.ib)))

    def _levels(self, others: list[str], axes: list[tuple[int, int]]) -> list[str]:
        """In a text that may write a canned cycle (not one that may compensate, which declines cycles): the
        axes' literal words, a cycle's level where the tool stands (:func:`~.double_cycles.level_code`)."""
        if not self.cycle_text or self.cc is not None:
            return []
        base = len(others) + ("R" in others)
        return level_code(axes, base, [self._word(k, i) for k, i in axes])

    def _kept_words(self, axes: list[tuple[int, int]]) -> list[str]:
        """In a program that may compensate (:mod:`.double_comp`, which declines G91 and G20 there): the
        words of X and Y, the program-frame doubles compensation starts from."""
        cc = self.cc
        if cc is None:
            return []
        return [f"W[{i}] = {self._word(k, i)}" for k, i in axes if i in (cc.ia, cc.ib)]


def _may_compensate(text: Any) -> bool:
    """May ``text`` write G41 or G42 (G41.1, G42.1): a G word of 41 or 42 in it (a streamed file: a "41" or "42").

    >>> _may_compensate("G1 X41 Y42"), _may_compensate("g 041 D1"), _may_compensate("G42.1 D2")
    (False, True, True)
    """
    if not isinstance(text, str):
        return "41" in text or "42" in text
    # "G" and "g" searched apart: a pattern that starts with a letter is scanned for it (the regex engine's
    # literal prefix), one that starts with a class tests the class at every character (some 8x the work)
    return any(re.search(g + r"[ \t]*0*4[12](?![0-9])", text) is not None for g in "Gg" if g in text)


def _g64_q(groups: dict[str, int], others: list[str], axes: bool) -> bool:
    """Is a block's Q value G64's naive-CAM tolerance: ``G64 P`` in a block without axis words or a motion
    code (so no cycle takes the Q, nor the P: :func:`~.double_cycles.takes_q`, ``takes_p``)."""
    return groups.get("path") == 64 and "P" in others and not axes and "motion" not in groups


#: The tests of the motion mode before a motion (:func:`_mode_checks`): a straight move's, an arc's.
_STRAIGHT_MODE = ("if mode == 1:", "    if not st.feed > 0.0: raise D('G1 without a positive feed')",
                  "elif mode: raise D('an arc without I, J, K or R')")
_ARC_MODE = ("if mode < 2 or not st.feed > 0.0: raise D('I, J, K or R without G2 or G3, or without a positive feed')",)


def _mode_checks(code: int | None, arc: bool) -> list[str]:
    """The code that sets ``mode`` and tests it before a motion (an arc: ``arc``), as ``st.motion`` at run time
    (``code`` None) or the block's own code (0-3; ``st.motion`` is then that code: the block set it, and no
    cycle runs in its block), each test decided as it would be at run time: the same declines, no test left
    that cannot fail."""
    if code is None:
        return ["mode = st.motion", "if mode is None: raise D('axis words without a motion mode')",
                *(_ARC_MODE if arc else _STRAIGHT_MODE)]
    body = [f"mode = {code}"]
    if arc:
        return body + ([_ARC_MODE[0].replace("mode < 2 or ", "")] if code >= 2 else
                       ["raise D('I, J, K or R without G2 or G3, or without a positive feed')"])
    if code == 1:
        return body + [_STRAIGHT_MODE[1].strip()]
    return body + (["raise D('an arc without I, J, K or R')"] if code else [])


def _first_rows(moved: tuple[int, ...], flag: str) -> list[str]:
    """The code that records the first row of the axes a motion moves (:meth:`_Pass.moved`), run by a plan only
    until it has run once: a flag of the plan's own (``flag``, a global of its scope, :meth:`_Pass._compiled_plan`),
    true until then (line44: one global read a line, not one item of ``FR`` an axis).  ``moved`` leaves every one
    of the axes with its first row, and no first row is ever unset, so a later call would do nothing; calling it
    where the old test did not (an axis with its row already) does nothing either.

    >>> _first_rows((0, 1), "NEWS")
    ['if NEWS:', '    st.moved((0, 1)); NEWS = False']
    """
    return [f"if {flag}:", f"    st.moved({moved!r}); {flag} = False"]


def _cycle_in_mode(calls: list[str], motion: list[str]) -> list[str]:
    """``calls + motion`` (a block's cycle call, :func:`~.double_cycles.cycle_call`, and its motion), but for a modal
    move (the CAM lines ``X.. Y..`` and ``X.. Y.. R..``) the same code with the call's test of a cycle made only where
    the mode is not the move's: ``mode = st.motion``, then a straight move's ``if mode == 1`` (the feed's test),
    ``elif mode`` (the call, else the decline of an arc without its words), ``elif mode is None``; an arc's ``if mode
    == 2 or mode == 3`` (the feed's test), ``elif mode in CYC`` (the call), then the declines of None and of G0/G1,
    and any other mode's feed test.  Every mode has the outcome it had: 0-3 are no cycle's, None is in no set of
    ints, and the call was the line just before ``mode = st.motion`` (line44: a set lookup and some 7 bytecodes a
    line; ``tests/gcode/test_double_pass_line_cost.py`` runs both for every mode and feed).

    >>> calls = ["if st.motion in CYC: return CY(((0, v[0]), ), None, None, None, None, None)"]
    >>> print("\\n".join(_cycle_in_mode(calls, _mode_checks(None, False) + ["off = st.off"])))
    mode = st.motion
    if mode == 1:
        if not st.feed > 0.0: raise D('G1 without a positive feed')
    elif mode:
        if mode in CYC: return CY(((0, v[0]), ), None, None, None, None, None)
        raise D('an arc without I, J, K or R')
    elif mode is None: raise D('axis words without a motion mode')
    off = st.off
    """
    test = "if st.motion in CYC: "
    if len(calls) != 1 or not calls[0].startswith(test):
        return calls + motion
    then = calls[0][len(test):]
    none = "elif mode is None: raise D('axis words without a motion mode')"
    straight, arc = _mode_checks(None, False), _mode_checks(None, True)
    if motion[:len(straight)] == straight:
        return ["mode = st.motion", _STRAIGHT_MODE[0], _STRAIGHT_MODE[1], "elif mode:", f"    if mode in CYC: {then}",
                "    raise D('an arc without I, J, K or R')", none, *motion[len(straight):]]
    if motion[:len(arc)] == arc:
        why = "raise D('I, J, K or R without G2 or G3, or without a positive feed')"
        return ["mode = st.motion", "if mode == 2 or mode == 3:", f"    if not st.feed > 0.0: {why}",
                f"elif mode in CYC: {then}", none, f"elif mode < 2: {why}", f"elif not st.feed > 0.0: {why}",
                *motion[len(arc):]]
    return calls + motion


def _groups(gs: list[int]) -> dict[str, int]:
    """The modal groups of a block's G codes (declined: a code the pass does not follow, two of a group)."""
    groups: dict[str, int] = {}
    for g in gs:
        group = _GROUPS.get(g)
        if group is None:
            raise Declined(f"G{g} is not followed by the double pass")
        if group in groups:
            raise Declined("two G codes of one modal group")
        groups[group] = g
    return groups


class _Lines:
    """The lines of a text as ``text.split("\n")`` has them (with ``crlf``, one ``"\r"`` before each newline
    and at the end dropped first, as the full path reads them), with their layouts
    (:data:`~nczones.gcode.shapes.LAYOUT`) in pieces that are ASCII, split a piece of about ``size``
    characters at a time: the pass reads them in order but for jumps, and holds one piece.

    ``text`` is a ``str`` or a streamed file (:class:`~nczones.gcode.source.FileText`, ASCII or UTF-8): its
    pieces are read from the file, cut after a newline (so a UTF-8 character or a ``"\r\n"`` is never cut),
    and decoded one at a time; the table of where pieces start is one entry per piece.
    """

    def __init__(self, text: Any, size: int | None = None, crlf: bool = False):
        size = PIECE if size is None else max(1, size)
        self.text = text
        self.crlf = crlf
        #: the text holds an ``o`` or an ``O`` (a streamed file knows it from its first read)
        self.has_o = "o" in text or "O" in text
        # pieces end just after a newline (the last at the end of the text): their first character and line
        self.starts = [0]
        self.first = [0]
        at, line = 0, 0
        if isinstance(text, str):
            self.end = len(text)
            while True:
                cut = text.find("\n", at + size)
                if cut < 0:
                    break
                line += text.count("\n", at, cut + 1)
                at = cut + 1
                self.starts.append(at)
                self.first.append(line)
            line = text.count("\n")
        else:  # a streamed file: the blocks it is cut in (offsets are bytes), one read of the file
            self.end = len(text)
            for block in text.blocks(size):
                line += block.count(b"\n")
                at += len(block)
                if block.endswith(b"\n"):
                    self.starts.append(at)
                    self.first.append(line)
        self.count = line + 1
        self.cached: tuple = (0, 0, [], None)

    def part(self, k: int) -> str:
        """The text of piece ``k``, without the newline that ends it, ``"\r"`` dropped as the full path does."""
        begin = self.starts[k]
        end = self.end if k + 1 == len(self.starts) else self.starts[k + 1] - 1
        text = self.text
        part = text[begin:end] if isinstance(text, str) else text.decoded(begin, end)
        if self.crlf:  # the "\r" before the newline cut off (or at the end of the text) goes too
            part = part.replace("\r\n", "\n").removesuffix("\r")
        return part

    def piece(self, i: int) -> tuple[int, int, list[str], list[bytes] | None]:
        """``(first line, end line, lines, layouts)`` of the piece that holds line ``i`` (layouts None: the
        piece is not ASCII)."""
        lo, hi, _lines, _layouts = self.cached
        if lo <= i < hi:
            return self.cached
        k = bisect_right(self.first, i) - 1
        part = self.part(k)
        lines = part.split("\n")
        layouts = part.encode().translate(LAYOUT).split(b"\n") if part.isascii() else None
        self.cached = (self.first[k], self.first[k] + len(lines), lines, layouts)
        return self.cached

    def line(self, i: int) -> tuple[str, bytes | None]:
        """Line ``i`` and its layout (None: its piece is not ASCII)."""
        lo, _hi, lines, layouts = self.piece(i)
        return lines[i - lo], (layouts[i - lo] if layouts is not None else None)


def _letters(words: Any) -> str:
    letters = "".join(w[0] for w in words)
    for letter in letters:
        if letter not in _LETTERS:
            raise Declined(f"a word {letter}")
    return letters.replace("Q", "q") if q_value(words) else letters


def _lines_with_o(text: str) -> list[tuple[int, int]]:
    """``(start, end)`` of every line with an ``o`` or ``O``, in order (``str.find``: most lines have none)."""
    found = set()
    n = len(text)
    for letter in "oO":
        at = text.find(letter)
        while at >= 0:
            end = text.find("\n", at)
            end = n if end < 0 else end
            found.add((text.rfind("\n", 0, at) + 1, end))
            at = text.find(letter, end)
    return sorted(found)


def _cond(cond: Any) -> float:
    try:
        value: float = cond(())
    except (EvalError, KeyError, ZeroDivisionError, OverflowError) as exc:
        raise Declined(f"an evaluation error: {exc!r}") from None
    return value


def _args(args: Any) -> tuple[float, ...]:
    """A call's arguments' doubles (:meth:`_Pass._compiled_args`)."""
    try:
        values: tuple[float, ...] = args(())
    except (EvalError, KeyError, ZeroDivisionError, OverflowError) as exc:
        raise Declined(f"an evaluation error: {exc!r}") from None
    return values


def _atan(y: float, x: float) -> float:
    return atan_degrees(y, x)


_CODES: dict[str, int] = {}
_TENTHS = frozenset((Fraction(611, 10), Fraction(411, 10), Fraction(421, 10)))  # G61.1, G41.1, G42.1 parsed


def _code(text: str) -> int:
    """The integer a G or M literal names (``01``, ``1.``, ``1.000``; ``61.1`` as -611 and ``91.1`` as -911,
    :data:`_GROUPS`: G61.1 and G91.1 are the codes with a decimal the pass follows); declines any other."""
    c = _CODES.get(text)
    if c is None:
        m = _CODE_TEXT.fullmatch(text)
        if m is not None:
            c = int(m.group(1))
        else:
            m = _CODE_TENTH.fullmatch(text)
            if m is None:
                raise Declined(f"a code {text}")
            c = -(10 * int(m.group(1)) + 1)
        _CODES[text] = c
    return c


def _const(node: Any) -> str:
    d = node[1]
    if d - d:
        raise Declined("a literal out of the double range")
    return repr(d)


def _const_code(node: Any) -> str:
    """The source of the G or M code of a parsed literal: a whole number, else declined."""
    q = node[2]
    if q is None or q < 0 or (q.denominator != 1 and q not in _TENTHS):
        raise Declined("a G or M code that is not a whole number")
    return str(q.numerator) if q.denominator == 1 else str(-q.numerator)  # n.1: -(10 n + 1), as _code


def _words(em: _Emit, words: Any, body: list[str], code_src: Any, lits: bool) -> tuple[list[str], list[str]]:
    """Emit a line's words: the sources of their values (G, M and H excluded) and of their G, M and H codes
    (``lits``: then the X, Y and Z words' literal texts, :func:`~.double_cycles.literal_tokens`)."""
    codes = []
    vals = []
    for letter, tree, *_rest in words:
        if letter not in _LETTERS:
            raise Declined(f"a word {letter}")
        if letter in _CODE_LETTERS and not (letter == "Q" and q_value(words)):
            if tree[0] != NUM:
                raise Declined("a computed G, M or H code")
            codes.append(code_src(tree))
        else:
            vals.append(em.value(tree, body))
    vals += r_token(words, em.leaf)  # the exact value of a literal R, for a cycle's levels
    if lits:  # last: the axis words' literal texts (a cycle's level where the tool stands)
        vals += literal_tokens(words, em.leaf)
    return vals, codes


def _assigns(em: _Emit, assigns: Any, body: list[str], index_src: Any) -> list[str]:
    writes = []
    for target, tree, *_rest in assigns:
        if target[0] == NPAR:
            name = str(target[1])
            if name.startswith("_"):
                raise Declined("a global named parameter")
            dest = f"N[{name!r}]"
        elif target[0] == PAR and target[1][0] == NUM:
            dest = f"S[{index_src(target[1])}]"
        else:
            raise Declined("a computed parameter number")
        writes.append(f"{dest} = {em.value(tree, body)}")
    # every value is computed before the first is stored (LinuxCNC sets a line's parameters together)
    return writes


#: The comparisons and logic operators as :func:`~nczones.gcode.expr.binary_op` tests them (its value 1.0 when
#: the test holds, else 0.0; NaN compares as there): emitted inline, ``test_doubles_compare`` holds them equal.
_COMPARE = {
    "gt": "{a} > {b}", "ge": "{a} >= {b}", "lt": "{a} < {b}", "le": "{a} <= {b}",
    "eq": f"abs({{a}} - {{b}}) < {TOLERANCE_EQUAL!r}", "ne": f"abs({{a}} - {{b}}) >= {TOLERANCE_EQUAL!r}",
    "and": "not ({a} == 0.0 or {b} == 0.0)", "or": "({a} != 0.0 or {b} != 0.0)",
    "xor": "(({a} == 0.0) != ({b} == 0.0))",
}


class _Emit:
    """Straight-line code computing a tree's double as :func:`~nczones.gcode.expr.evaluate` does."""

    _OPS = {"+", "-", "*", "/"}

    def __init__(self, leaf: Any, index: Any):
        self.leaf = leaf  # NUM node -> source of its double
        self.index = index  # NUM node of a parameter number -> source of the number
        self.n = 0

    def value(self, node: Any, out: list[str]) -> str:
        tag = node[0]
        self.n += 1
        d = f"d{self.n}"
        if tag == NUM:
            out.append(f"{d} = {self.leaf(node)}")
        elif tag == PAR:
            if node[1][0] != NUM:
                raise Declined("a computed parameter number")
            out.append(f"{d} = S.get({self.index(node[1])}, 0.0)")
        elif tag == NPAR:
            name = str(node[1])
            if name.startswith("_"):
                raise Declined("a global named parameter")
            out.append(f"{d} = N[{name!r}]")
        elif tag == BIN:
            op = node[1]
            a = self.value(node[2], out)
            b = self.value(node[3], out)
            if op in self._OPS:
                if op == "/":
                    out.append(f"if {b} == 0.0: raise D('a division by zero')")
                out += [f"{d} = {a} {op} {b}", f"if {d} - {d}: raise D('not a finite number')"]
            elif op in _COMPARE:  # binary_op's own test, without its dispatch (its 1.0 or 0.0)
                out.append(f"{d} = 1.0 if {_COMPARE[op].format(a=a, b=b)} else 0.0")
            else:
                out.append(f"{d} = binary_op({op!r}, ({a}, None), ({b}, None))[0]")
        elif tag == NEG:
            a = self.value(node[1], out)
            out.append(f"{d} = -{a}")
        elif tag == FN:
            a = self.value(node[2], out)
            if node[1] == "abs":
                out += [f"if {a} - {a}: raise D('not a finite number')", f"{d} = abs({a})"]
            elif node[1] in TRIG_DEGREES:  # unary_op's own function, without its dispatch
                out += [f"if {a} - {a}: raise D('not a finite number')", f"{d} = _{node[1]}({a})",
                        f"if {d} - {d}: raise D('not a finite number')"]
            else:
                out.append(f"{d} = unary_op({node[1]!r}, ({a}, None))[0]")
        elif tag == ATAN:
            y = self.value(node[1], out)
            x = self.value(node[2], out)
            out.append(f"{d} = _atan({y}, {x})")
        else:
            raise Declined("EXISTS or another construct the double pass does not follow")
        return d


def _index_const(node: Any) -> int:
    d = node[1]
    if d - d:
        raise Declined("a parameter number out of range")
    i = round(d)
    if abs(d - i) > 0.0001 or not 1 <= i <= MAX_PARAMETER:
        raise Declined("a parameter number out of range")
    return int(i)
