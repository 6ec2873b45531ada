"""One table of G and M codes per dialect: named codes, modal groups, and what each lane does with them.

A *lane* is a way a program's blocks become motion (docs/design.md §9, §10 "How to add a lane"):

- ``full``: the full interpreter (:mod:`nczones.gcode.interpreter`, :mod:`nczones.gcode.fanuc`);
- ``plain``: its plain-move lane (``Interpreter._lean``/``_plain``): G0/G1 with axis words, F, S and one
  spindle or coolant M code;
- ``fastpath``: the vectorized fast path (:mod:`nczones.gcode.fastpath`), runs of simple lines;
- ``doubles``: the double pass (:mod:`nczones.gcode.linuxcnc.doubles`), LinuxCNC programs with ``#``;
- Fanuc only, on the numpy-free box route (:mod:`nczones.prover.fanucboxes`): ``boxes``, the plain lane when
  its sink is a ``columns.BoxSink`` (``FanucInterpreter.lane`` and ``_arc_lane``: it writes arcs into the
  run's box too, which with segments or column rows it hands on), and ``boxrun``, the box route's run reader
  (:mod:`nczones.gcode.fanuc.boxrun`, plain lines read from the text).  The Fanuc ``plain`` column is the
  plain lane with any other sink (segments, ``columns.Rows``).

Each code's row says, per lane, :data:`CLAIMS` (the lane computes it, and must agree with the full
interpreter) or a decline reason (the lane hands the block or the program to the full path, or the full
path itself answers ``unknown``/refuses with that reason).  A lane missing from a row never sees the code
(the dialect does not run that lane).  The lanes' own code sets (``GROUP_OF``, ``LEAN_M``, the double
pass's ``_GROUPS``, Fanuc's cycle sets) are derived from these tables at import time, and
``tests/gcode/test_codes.py`` runs a small program per code through every lane.

G codes are keyed as in the interpreter: ``10 * number`` (G59.1 -> 591); M codes by their number.
"""

from __future__ import annotations

from fractions import Fraction

from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

__all__ = ["CLAIMS", "LANES", "Code", "LINUXCNC_G", "LINUXCNC_M", "FANUC_G", "gname", "g_key",
           "claimed", "decline_reason", "modal_groups", "LANE_INTERPRETER", "LANE_PLAIN", "LANE_FASTPATH",
           "LANE_DOUBLES", "LANE_BOXES", "LANE_BOXRUN", "LATHE_REASON", "FANUC_CYCLE_G",
           "FANUC_CANCEL_CYCLE_G", "LaneCodes", "SPLINE_CODES"]

#: The lanes' names.
LANE_INTERPRETER, LANE_PLAIN, LANE_FASTPATH, LANE_DOUBLES = "full", "plain", "fastpath", "doubles"
#: The Fanuc box route's lanes: the plain lane into a ``columns.BoxSink``, the run reader (``boxrun``).
LANE_BOXES, LANE_BOXRUN = "boxes", "boxrun"
LANES = (LANE_INTERPRETER, LANE_PLAIN, LANE_FASTPATH, LANE_DOUBLES, LANE_BOXES, LANE_BOXRUN)
#: G keys (10 x number) of the spline and NURBS motions (G5, G5.1, G5.2, G5.3, G6.2): ``linuxcnc.splines``
#: interprets them, imported at the first one (start-up, boot44).
SPLINE_CODES = frozenset({50, 51, 52, 53, 62})
#: A lane's entry for a code it computes.
CLAIMS = ""


@dataclass(frozen=True, slots=True)
class Code:
    """One G or M code of a dialect: ``key`` (G: 10 * number), ``group`` (its modal group number, None
    for a code without one), ``lanes``: lane name -> :data:`CLAIMS` or the reason the lane declines it."""

    key: int
    group: int | None
    lanes: dict[str, str]


def g_key(number: str) -> int:
    """``"59.1"`` -> 591."""
    return int(Fraction(number) * 10)


def gname(key: int) -> str:
    """591 -> ``"G59.1"``."""
    return f"G{key // 10}" if key % 10 == 0 else f"G{key // 10}.{key % 10}"


_PLAIN_NO = "not a plain G0/G1 move: the plain lane hands the block to the full path"
_FAST_NO = "not a simple line (G0-G3, axis words, F, S, spindle/coolant M): the fast path hands it on"
_FAST_CYCLE = CLAIMS  # G81/G82 hole lines after the cycle's first block (fastpath._fast_cycle_run)
#: The fast path's decline of a lathe code: the interpretation takes the whole program by the full path.
LATHE_REASON = "a lathe program (G7/G8, G70-G72): the whole program takes the full path"
_LATHE_G = frozenset((70, 80, 700, 710, 711, 712, 720, 721, 722))
_DBL_NO = "not followed by the double pass: the program takes the full path"
_UNSUPPORTED = "the full path answers unknown: "


def _row(key: int, group: int | None, full: str = CLAIMS, plain: str = _PLAIN_NO, fast: str = _FAST_NO,
         doubles: str = _DBL_NO) -> Code:
    return Code(key, group, {LANE_INTERPRETER: full, LANE_PLAIN: plain, LANE_FASTPATH: fast, LANE_DOUBLES: doubles})


# LinuxCNC: the modal groups of interp_array.cc (_gees), keyed by 10 * number.
_LINUXCNC_GROUPS: dict[int, tuple[int, ...]] = {
    0: (40, 100, 280, 281, 300, 301, 520, 530, 920, 921, 922, 923),
    1: (0, 10, 20, 30, 330, 331, 382, 383, 384, 385, 730, 760, 800, 810, 820, 830, 840, 850,
        860, 870, 880, 890, 50, 51, 52, 53, 62, 700, 710, 711, 712, 720, 721, 722),
    2: (170, 180, 190, 171, 181, 191),
    3: (900, 910),
    4: (901, 911),
    5: (930, 940, 950),
    6: (200, 210),
    7: (400, 410, 420, 411, 421),
    8: (430, 431, 432, 490),
    10: (980, 990),
    12: (540, 550, 560, 570, 580, 590, 591, 592, 593),
    13: (610, 611, 640),
    14: (960, 970),
    15: (70, 80),
}
#: The codes the plain lane claims (G0, G1), the fast path (G0-G3; G81/G82 hole lines), the double pass (G4: a
#: dwell; G61, G61.1 and bare G64: the path mode; G91: straight moves; G91.1 written out: LinuxCNC's default
#: arc-centre mode, the one the pass assumes, issue 36; G7/G8: a lathe's diameter mode, G96/G97: the spindle speed
#: mode, which moves nothing, lathe39; G81, G82, G83 and G98/G99: drilling cycles in G90,
#: ``linuxcnc/double_cycles.py``; G20: inches, units39; G41/G42: cutter compensation of straight moves on a machine
#: with LinuxCNC's, ``linuxcnc/double_comp.py``, comp40; G73, G84, G85, G86, G89: cycles, cyc40).
_PLAIN_G = frozenset((0, 10))
_FAST_G = frozenset((0, 10, 20, 30, 810, 820))
_DOUBLES_G = frozenset((0, 10, 20, 30, 40, 430, 800, 170, 180, 190, 200, 210, 400, 490, 900, 910, 911, 940, 540, 550,
                        560, 570, 580, 590, 610, 611, 640, 70, 80, 960, 970, 810, 820, 830, 980, 990, 410, 420, 411, 421,
                        730, 840, 850, 860, 890))
#: The full path's unknown reasons live in ``interpreter.UNSUPPORTED_G`` (its messages); these are the
#: LinuxCNC codes it answers ``unknown`` for.
_LINUXCNC_UNKNOWN_G = frozenset((410, 420, 411, 421, 760, 382, 383, 384, 385, 870, 880, 432, 70, 171, 181, 191))


def _linuxcnc_g() -> dict[int, Code]:
    table: dict[int, Code] = {}
    for group, keys in _LINUXCNC_GROUPS.items():
        for k in keys:
            table[k] = _row(k, group,
                            full=_UNSUPPORTED + "see interpreter.UNSUPPORTED_G" if k in _LINUXCNC_UNKNOWN_G else CLAIMS,
                            plain=CLAIMS if k in _PLAIN_G else _PLAIN_NO,
                            fast=CLAIMS if k in _FAST_G else LATHE_REASON if k in _LATHE_G else _FAST_NO,
                            doubles=CLAIMS if k in _DOUBLES_G else _DBL_NO)
    return table


#: Every LinuxCNC G code the interpreter knows, by key.
LINUXCNC_G: dict[int, Code] = _linuxcnc_g()

# LinuxCNC M codes: modal groups of interp_array.cc (_ems).
_LINUXCNC_M_GROUPS: dict[int, tuple[int, ...]] = {
    4: (0, 1, 2, 30, 60), 5: (62, 63, 64, 65, 66, 67, 68), 6: (6, 61), 7: (3, 4, 5, 19), 8: (7, 8, 9),
    9: (48, 49, 50, 51, 52, 53), 10: (70, 71, 72, 73),
}
#: Spindle and coolant: no effect on motion; the plain lane and the fast path take a block with one.
_LEAN_M = frozenset((3, 4, 5, 7, 8, 9))
#: Program end (the double pass stops there), spindle and coolant (one to a block; issue 36: a parametric
#: program that starts its spindle is no longer the full path's), and the tool change M6 and M61 (issue 36).
_DOUBLES_M = frozenset((2, 30, 6, 61)) | _LEAN_M


def _linuxcnc_m() -> dict[int, Code]:
    table: dict[int, Code] = {}
    for group, keys in _LINUXCNC_M_GROUPS.items():
        for k in keys:
            table[k] = _row(k, group, plain=CLAIMS if k in _LEAN_M else _PLAIN_NO,
                            fast=CLAIMS if k in _LEAN_M else "an M code other than spindle/coolant ends the run",
                            doubles=CLAIMS if k in _DOUBLES_M else "an M code the double pass does not follow")
    return table


#: Every LinuxCNC M code with a modal group, by number (M98/M99 and user M100-M199 are the language
#: layer's, outside this table).
LINUXCNC_M: dict[int, Code] = _linuxcnc_m()

# Fanuc (milling, system A-C share these): the canned cycles and the codes that cancel one.
FANUC_CYCLE_G: frozenset[int | Fraction] = frozenset((73, 74, 76, 81, 82, 83, 84, 85, 86, 87, 88, 89, Fraction("84.2"), Fraction("84.3")))
FANUC_CANCEL_CYCLE_G: frozenset[int | Fraction] = frozenset((0, 1, 2, 3, 80))
#: The Fanuc codes the plain lane claims (``FanucInterpreter.lane``, ``Interpreter._lean``: G0, G1), the plain lane
#: into a box (``FanucInterpreter._arc_lane`` too) and the box run reader (``boxrun._G``): G0-G3; the fast path.
_FANUC_PLAIN_G = frozenset((0, 10))
_FANUC_BOX_G = frozenset((0, 10, 20, 30))
_FANUC_FAST_G = frozenset((0, 10, 20, 30))
#: The Fanuc cycles whose hole lines (X/Y after the cycle's first block) the fast path takes
#: (fastpath._fast_cycle_run with fanuc.holes.fanuc_holes; G76's shift and G87's back boring are the full path's)
FANUC_HOLE_CYCLES = frozenset((730, 740, 810, 820, 830, 840, 850, 860, 890))
_FANUC_ARC_PLAIN = ("an arc: the plain lane writes it only into the box route's run box (the boxes column); with "
                    "segments or column rows it hands the block to the full path")
_BOXES_NO = "not a plain G0-G3 move: the plain lane hands the block to the full path"
_BOXRUN_NO = "not G0-G3: the box run reader ends its run there, the language layer reads the line"
_FANUC_DBL = "the double pass runs LinuxCNC only"
#: The Fanuc codes of this table the full path answers ``unknown`` for (its messages: ``fanuc.interpreter.UNKNOWN_G``).
_FANUC_UNKNOWN_G = frozenset((870, 880))


def _fanuc_row(key: int, group: int) -> Code:
    """The row of a Fanuc G code: what each lane does with it (every lane of :data:`LANES`)."""
    return Code(key, group, {
        LANE_INTERPRETER: _UNSUPPORTED + "see fanuc.interpreter.UNKNOWN_G" if key in _FANUC_UNKNOWN_G else CLAIMS,
        LANE_PLAIN: CLAIMS if key in _FANUC_PLAIN_G else _FANUC_ARC_PLAIN if key in _FANUC_BOX_G else _PLAIN_NO,
        LANE_FASTPATH: CLAIMS if key in _FANUC_FAST_G or key in FANUC_HOLE_CYCLES else _FAST_NO,
        LANE_DOUBLES: _FANUC_DBL,
        LANE_BOXES: CLAIMS if key in _FANUC_BOX_G else _BOXES_NO,
        LANE_BOXRUN: CLAIMS if key in _FANUC_BOX_G else _BOXRUN_NO,
    })


#: Fanuc G codes (by 10 * number) this table names: the cycles (group 9) and motion group 1 (G80: group 9).
FANUC_G: dict[int, Code] = {
    **{int(g * 10): _fanuc_row(int(g * 10), 9) for g in FANUC_CYCLE_G},
    **{int(g * 10): _fanuc_row(int(g * 10), 1 if g != 80 else 9) for g in FANUC_CANCEL_CYCLE_G},
}


def claimed(table: dict[int, Code], lane: str) -> frozenset[int]:
    """The keys of ``table`` that ``lane`` claims."""
    return frozenset(k for k, c in table.items() if c.lanes.get(lane) == CLAIMS)


def decline_reason(table: dict[int, Code], lane: str, key: int) -> str | None:
    """Why ``lane`` declines code ``key`` (None: it claims it); a code missing from the table is declined."""
    c = table.get(key)
    if c is None:
        return "not in the dialect's code table"
    r = c.lanes.get(lane, "the lane never sees this code")
    return r or None


def modal_groups(table: dict[int, Code]) -> dict[int, int]:
    """key -> modal group number, for the codes with one."""
    return {k: c.group for k, c in table.items() if c.group is not None}


@dataclass(frozen=True, slots=True)
class LaneCodes:
    """What one lane declares about a dialect's codes: each lane module holds one (``CODES``).

    ``claims_g(key)``/``claims_m(number)``: the lane computes blocks with that code (and must agree with
    the full interpreter); ``decline_g``/``decline_m``: why it does not (None when it claims the code).
    """

    lane: str
    g: dict[int, Code]
    m: dict[int, Code]

    def claims_g(self, key: int) -> bool:
        return decline_reason(self.g, self.lane, key) is None

    def claims_m(self, number: int) -> bool:
        return decline_reason(self.m, self.lane, number) is None

    def decline_g(self, key: int) -> str | None:
        return decline_reason(self.g, self.lane, key)

    def decline_m(self, number: int) -> str | None:
        return decline_reason(self.m, self.lane, number)
