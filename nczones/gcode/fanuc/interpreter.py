"""The Fanuc mill interpreter: evaluated blocks -> motion in machine coordinates.

:class:`FanucInterpreter` gives the blocks of :mod:`nczones.gcode.fanuc.program`
their meaning on a Fanuc 0i/30i-M (or Fanuc-compatible, Haas) mill, with the
modal groups as data (:data:`GROUPS`: group 00 one-shot codes, group 01
motion, 09 canned cycles, 08 tool length, 14 work coordinates, 16 rotation,
11 scaling, 22 mirror, 17 polar coordinates ...).  It reuses the LinuxCNC
interpreter's machinery (segments, chunks, the plain-move lane, arcs,
dependency tracking) and changes what differs (``specs/fanuc.md``):

* several G codes of different groups share a block; of one group the last
  wins (group 00 one-shot codes: at most one per block); G80 is group 09,
  so ``G00 G17 G40 G49 G80 G90`` is the standard safety line;
* ``machine = transform(program) + EXT + G54..G59/G54.1 + G52 + G92 +
  tool length``, where the transform is polar coordinates (G16), scaling
  (G51), programmable mirror image (G51.1) and rotation (G68), applied in
  that order about their centres in the workpiece system;
* a tool length change (G43/G44 H, G49, or a bare H in G43/G44 mode) moves
  the tool axis at once (parameter 5006#6 TOS = 0, ``[fanuc]
  tool_length_motion = "move"``), with the block's move or alone; an
  incremental tool axis word moves by the increment plus the change;
* G92 in G91 adds the increment to the current reading;
* canned cycles are group 09: position at the current level, rapid to R,
  the cycle, back to the initial level (G98) or R (G99); K repeats; P dwell
  in milliseconds; G73 and G83 with the retract/clearance of parameters 5114
  and 5115 from the machine file;
* G28/G30 move only the axes they name (via the intermediate point); G30
  P2..P4 go to the 2nd..4th reference positions of the machine file; G53 is a
  rapid in machine coordinates; G04 dwells X seconds or P milliseconds.

Anything else the manuals define but nczones does not model is ``unknown``
with the code and a reason; a code no Fanuc mill has is an error (GC202),
with a hint when the LinuxCNC dialect knows it.
"""

from __future__ import annotations

from fractions import Fraction

from ...machine import FANUC_OFFSETS, Machine
from ...motion import PLANE_AXES, FrameRotation, PathMode, Plane, ProgramFrame, SegmentKind
from ..blocks import Block, Word
from ..interpreter import (
    INCH,
    WORK_OFFSETS,
    Interpreter,
    StopProgram,
    dadd,
    fmt_number,
    gname,
    qadd,
    sqrt_diff_exceeds,
)
from ..segments import make_segment
from .expr import FanucVariables

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:  # (the programmable transforms are imported where a program uses one: start-up)
    from typing import Any, TypeAlias

    from .transforms import Mirror, Polar, Rotation, Scaling

_LINE, _RAPID, _ARC = SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.ARC
#: The modes an arc notes as assumed when no block set them (``Interpreter.arc``): the arc lane leaves those to it.
_ARC_ASSUMED = frozenset(("units", "distance", "offset", "plane"))
#: The centre offset letter of each plane axis (``Interpreter.arc``).
_CENTRE_LETTER = {"X": "I", "Y": "J", "Z": "K"}

#: A block's axis words (axis index, word) and its other words by letter.
AxisWords: TypeAlias = "list[tuple[int, Word]]"
Words: TypeAlias = "dict[str, Word]"

__all__ = ["FanucInterpreter", "GROUPS", "UNKNOWN_G", "HARMLESS_G", "HARMLESS_M", "CYCLE_CODES"]

_ZERO = Fraction(0)

# G codes keyed by 10 * number (G54.1 -> 541); group numbers as in the Fanuc 0i/30i-M G code list.
GROUPS: dict[int, int] = {}
for _group, _codes in {
    0: (40, 50, 51, 71, 80, 90, 100, 106, 110, 270, 280, 290, 300, 310, 370, 390, 450, 460, 470, 480, 520, 530,
        600, 650, 721, 722, 920, 921),
    1: (0, 10, 20, 30, 22, 23, 32, 33, 62, 330, 350, 360),
    2: (170, 180, 190),
    3: (900, 910),
    4: (220, 230),
    5: (930, 940, 950),
    6: (200, 210),
    7: (400, 410, 420),
    8: (430, 440, 490, 431, 434, 435, 441, 491),
    9: (730, 740, 760, 800, 810, 820, 830, 840, 842, 843, 850, 860, 870, 880, 890),
    10: (980, 990),
    11: (500, 510),
    12: (660, 670),
    13: (960, 970),
    14: (540, 541, 550, 560, 570, 580, 590),
    15: (610, 620, 630, 640),
    16: (680, 690),
    17: (150, 160),
    18: (401, 411, 421),
    19: (250, 260),
    21: (121, 131),
    22: (501, 511),
    23: (542,),
    24: (682, 683),
}.items():
    for _c in _codes:
        GROUPS[_c] = _group

#: Canned cycle codes (group 09 without G80).
CYCLE_CODES = frozenset((730, 740, 760, 810, 820, 830, 840, 842, 843, 850, 860, 870, 880, 890))
#: Codes that change nothing nczones proves (feed, spindle, look-ahead, exact stop, cutting modes).
HARMLESS_G = frozenset((50, 51, 80, 90, 110, 220, 230, 250, 260, 610, 620, 630, 640, 930, 940, 950, 960, 970))
#: Codes a Fanuc mill knows that nczones does not model: the result is unknown with the reason.
UNKNOWN_G = {
    22: "involute interpolation (G02.2) is not modelled",
    23: "involute interpolation (G03.2) is not modelled",
    32: "exponential interpolation (G02.3) is not modelled",
    33: "exponential interpolation (G03.3) is not modelled",
    62: "NURBS interpolation (G06.2) is not modelled in the fanuc dialect",
    71: "cylindrical interpolation (G07.1) is not modelled in the fanuc dialect",
    106: "tool retract and recover (G10.6) is not modelled",
    121: "polar coordinate interpolation (G12.1) is modelled on turning centres (type = \"lathe\") only",
    131: "polar coordinate interpolation (G13.1) is modelled on turning centres (type = \"lathe\") only",
    310: "skip function (G31) stops where a signal arrives, which depends on the part",
    350: "circular threading (G35) is not modelled",
    360: "circular threading (G36) is not modelled",
    370: "automatic tool length measurement (G37) stops where a signal arrives",
    390: "corner circular interpolation (G39) belongs to cutter compensation, which is not modelled",
    401: "normal direction control (G40.1) is not modelled",
    411: "normal direction control (G41.1) is not modelled",
    421: "normal direction control (G42.1) is not modelled",
    410: "cutter radius compensation (G41): the Fanuc type A/B start-up and the intersection vectors at corners "
         "are not modelled",
    420: "cutter radius compensation (G42): the Fanuc type A/B start-up and the intersection vectors at corners "
         "are not modelled",
    431: "tool length compensation in the tool axis direction (G43.1) is not modelled",
    434: "tool centre point control (G43.4) is not modelled",
    435: "tool centre point control (G43.5) is not modelled",
    441: "tool length compensation (G44.1) is not modelled",
    491: "tool length compensation cancel (G49.1) is not modelled",
    450: "tool offset increase (G45) is not modelled",
    460: "tool offset decrease (G46) is not modelled",
    470: "tool offset double increase (G47) is not modelled (on Haas G47 engraves text)",
    480: "tool offset double decrease (G48) is not modelled",
    542: "fixture offset (G54.2) is not modelled",
    600: "single direction positioning (G60) overshoots by a parameter distance that is not modelled",
    682: "tilted working plane (G68.2) is not modelled",
    683: "tilted working plane (G68.3) is not modelled",
    721: "figure copy (G72.1) is not modelled",
    722: "figure copy (G72.2) is not modelled",
    870: "back boring cycle (G87) is not modelled",
    880: "boring cycle with manual retract (G88) lets the operator move the spindle",
}
#: M codes with no effect on motion on every Fanuc mill (program stops, spindle, coolant, rigid tapping).
HARMLESS_M = frozenset((0, 1, 3, 4, 5, 7, 8, 9, 19, 29))
#: LinuxCNC G codes a Fanuc mill does not have (for the cross-dialect hint).
LINUXCNC_ONLY_G = frozenset((52, 53, 70, 171, 181, 191, 331, 382, 383, 384, 385, 432, 591, 592, 593, 611, 901,
                             911, 922, 923))


class FanucInterpreter(Interpreter):
    """Modal state machine of a Fanuc mill, from blocks to machine-coordinate motion.

    Takes the :class:`~nczones.gcode.interpreter.Interpreter` arguments; the
    Fanuc settings come from ``machine.fanuc``.

    >>> from nczones.machine import parse_machine
    >>> from nczones.gcode import segments_text
    >>> m = parse_machine('''
    ... [machine]
    ... dialect = "fanuc"
    ... axes = ["X", "Y", "Z"]
    ... [machine.rapid]
    ... X = "1000"
    ... Y = "1000"
    ... Z = "1000"
    ... [machine.reference]
    ... X = "0"
    ... Y = "0"
    ... Z = "0"
    ... [tool_lengths]
    ... H1 = "100"
    ... ''')
    >>> segs = segments_text("G00 G17 G40 G49 G80 G90\\nX10 Y5\\nG43 H1\\n", m)
    >>> [[str(v) for v in s.end] for s in segs]
    [['10', '5', '0'], ['10', '5', '100']]
    """

    dialect = "fanuc"

    def __init__(self, machine: Machine, **kwargs: Any):
        super().__init__(machine, **kwargs)
        self.settings = machine.fanuc
        #: :meth:`lane`'s one-call form is this class's meaning: the mill's (a subclass, such as the lathe's, may
        #: change a step of it and takes the general lane)
        self.fused_lane = type(self) is FanucInterpreter
        self._arc_plans: dict = {}  # letters of a block -> (plane, how the arc lane reads it there: _arc_plan)
        n = self.naxes
        offsets, zeros = machine.offsets, [_ZERO] * len(machine.axes)  # (machine.offset's zeros, built once)
        for name in FANUC_OFFSETS:
            given = offsets.get(name)
            self.g5x[name] = list(given) if given is not None else zeros[:]
            self.dep_g5x[name] = [{name: 1} for _ in range(n)]
            self.rot[name] = _ZERO
        self.g52 = [_ZERO] * n
        self.dep_g52: list[dict] = [{} for _ in range(n)]
        self.motion = 0  # group 01 at power-on: G00 (parameter 3402#0 G01 = 0)
        self.cycle: int | None = None  # group 09 (None: G80)
        self.cycle_data: dict = {}  # R, Z (program values), Q, P of the active cycle
        self.initial_level: Fraction | None = None
        self.initial_level_deps: dict = {}
        self.retract_r = self.initial_retract_r(set(machine.modal))
        self.spindle_dir = self.spindle_speed = None  # LinuxCNC's spindle checks do not apply
        self.tlo_register: int | None = None
        self.tlo_sign = 1
        self.h_geometry = {k: v for k, v in machine.tool_lengths.items()}
        self.h_wear: dict[int, Fraction] = dict(machine.tool_length_wear)  # a listing's L11 (memory C)
        #: geometry registers the program set (G10 L10 in G90, #11001 =): no longer the machine file's value, so
        #: a --param range of that H does not reach them
        self.h_set: set[int] = set()
        self.d_geometry = {k: v / 2 for k, v in machine.tool_diameters.items()}
        self.d_wear: dict[int, Fraction] = dict(machine.tool_radius_wear)  # a listing's L13
        self._tlo_shift: Fraction | None = None  # a tool length change the block's move must carry out
        self._tlo_shift_deps: dict | None = None
        #: with tool_length_motion = "shift": a length change no absolute tool axis move has taken yet
        self._tlo_untaken = False
        self.references = {1: tuple(machine.reference)}
        self.references.update(machine.fanuc.references)
        self.after_home: set[int] = set()  # axes returned by G28/G30 while a tool length offset was active
        self.intermediate: list | None = None  # G28/G30's intermediate point (machine), for G29
        self.intermediate_deps: list[dict] | None = None  # its range dependencies
        self.stops: list[tuple[int, int]] = []  # (0 or 1, line) of M00/M01, as the LinuxCNC interpreter's
        # programmable transforms: each acts on the program point (mm, workpiece system) about its centre
        self.rotation: Rotation | None = None
        self.scaling: Scaling | None = None
        self.mirroring: Mirror | None = None
        self.polar: Polar | None = None
        self.prog: list[Fraction] | None = None  # the program point while a transform is active
        self.prog_deps: list[dict] | None = None
        #: per axis, the range dependencies of a transform centre taken from the current program point (G68 or
        #: G51 without the centre's words); kept until every transform is off
        self.centre_deps: dict[int, dict] = {}
        self._first_after_transform = False  # the first move after G68/G69, G51/G50, ... must be absolute
        self.vars: FanucVariables | None = None
        self.clock = {3001: (0.0, _ZERO), 3002: (0.0, _ZERO)}
        self.last: dict[str, Any] = {}  # the last D, M, N words, for #4107 ... (and "N*": number_alone)
        self._harmless_m = HARMLESS_M | machine.fanuc.harmless_m
        self.recompute_offsets()

    # ------------------------------------------------------------------ offsets
    def recompute_offsets(self) -> None:
        g5 = self.g5x[self.wcs]
        ext = self.g5x.get("EXT")
        g52 = getattr(self, "g52", None)
        if ext is None or g52 is None:  # during Interpreter.__init__
            return super().recompute_offsets()
        off = [ext[i] + g5[i] + g52[i] + self.g92[i] for i in range(self.naxes)]
        if self.tool_axis is not None:
            off[self.tool_axis] += self.tlo
        self.off = off
        if self.track:
            deps = []
            for i in range(self.naxes):
                d = dadd(dadd(dadd(self.dep_g5x["EXT"][i], self.dep_g5x[self.wcs][i]), self.dep_g52[i]),
                          self.dep_g92[i])
                if i == self.tool_axis:
                    d = dadd(d, self.dep_tlo)
                deps.append(d)
            self.dep_off = deps

    def make_frame(self) -> ProgramFrame:
        """The program frame (:class:`~nczones.motion.ProgramFrame`): ``machine = program + self.off`` (EXT,
        work offset, G52, G92, tool offsets), G68 rotating about its centre; a diameter axis of a lathe; no
        program point under G51 scaling, G51.1 mirror image, G16 polar coordinates, G12.1 or G07.1."""
        rot = None
        r = self.rotation
        if r is not None:
            from .transforms import cos_sin_enclosure

            (c_lo, c_hi), (s_lo, s_hi) = cos_sin_enclosure(r.angle)
            off = self.off
            rot = FrameRotation((self.axes[r.ia], self.axes[r.ib]), r.angle, (c_lo + c_hi) / 2, (s_lo + s_hi) / 2,
                                (-r.ca, -r.cb), (r.ca + off[r.ia], r.cb + off[r.ib]))
        opaque = ""
        for on, what in ((self.scaling, "scaling (G51)"), (self.mirroring, "mirror image (G51.1)"),
                         (self.polar, "polar coordinates (G16)"), (getattr(self, "polar_ip", None),
                                                                  "polar coordinate interpolation (G12.1)"),
                         (getattr(self, "cylinder", None), "cylindrical interpolation (G07.1)")):
            if on is not None:
                opaque = f"{what} is active: the program point is not given"
                break
        diameter = tuple(self.axes[i] for i in sorted(getattr(self, "diameter", ())))
        ext, g5 = self.g5x.get("EXT"), self.g5x[self.wcs]
        work = tuple(g5[i] + (ext[i] if ext is not None else 0) for i in range(self.naxes))
        return ProgramFrame(self.wcs, tuple(self.off), rot, diameter, self.inch, opaque, work)

    def in_cycle(self) -> bool:
        """A canned cycle is active (the language layer reads K as its repeat count)."""
        return self.cycle is not None

    @property
    def tool_length_pending(self) -> bool:
        """A tool length change the tool axis has not moved by yet (TOS = 0: with the block's move; TOS = 1: with
        the next tool axis move), which a canned cycle's hole reads (``fanuc.holes.fanuc_holes`` declines then)."""
        return self._tlo_shift is not None or self._tlo_untaken

    def fast_state_ok(self) -> bool:
        """Nothing the vectorized fast path does not model is active (a transform only where
        :meth:`column_transform` gives the one it maps)."""
        return self.cycle is None and self._tlo_shift is None and not self.after_home and not self._tlo_untaken \
            and (self.prog is None or self.column_transform() is not None)

    def column_transform(self) -> Any:
        """The programmable transform the fast path maps a run's program points by
        (:class:`~nczones.gcode.fanuc.transform_columns.ColumnTransform`: one G68 rotation or G51 scaling, its
        increment and the offsets), None when none is active or the lane does not mirror it: a mirror image,
        polar coordinates, two transforms, the first move after a transform's block (which must be absolute),
        tracked parameter ranges."""
        if not self._one_transform():
            return None
        from .transform_columns import column_transform

        return column_transform(self.rotation, self.scaling, self._grid_step(), tuple(self.off))

    def _one_transform(self) -> bool:
        """:meth:`column_transform`'s tests of the state (one G68 or G51 is then active: the lanes look)."""
        return not (self.prog is None or self.mirroring is not None or self.polar is not None
                    or self._first_after_transform or self.track or self.centre_deps)

    @property
    def modal_flags(self) -> dict[int, bool]:
        """Which of the transform groups (11 scaling, 16 rotation, 17 polar, 22 mirror) are on (#4011 ...)."""
        return {11: self.scaling is not None, 16: self.rotation is not None, 17: self.polar is not None,
                22: self.mirroring is not None}

    keeps_number = True  # #4114 (Interpreter.run: a PlainBlock the plain-move lane takes)

    # ------------------------------------------------------------------ the plain-move lane
    #: Set by ``nczones.gcode.fanuc.columns.column_runs``: the lane then writes its straight moves from motion
    #: ``row_sink.start`` on as column rows (``columns.Rows`` in ``emitted``), not as segments
    row_sink: Any = None

    def lane(self, letters: str, values: tuple, span: Any, index: int) -> int:
        """:meth:`Interpreter.lane` in one call for the common Fanuc straight move: a block of axis words and at
        most G0/G1 and F (no M, S), absolute metric input, G94, a plan already made for its letters and nothing
        pending; anything else goes to :meth:`Interpreter.lane` untouched, which decides as before.

        What it does is what ``lane`` -> ``_plain`` -> ``_lean`` (this class's, then the base's) ->
        ``_lean_move`` do for such a block, step for step (``tests/gcode/fanuc/test_column_runs.py``,
        ``test_one_call_lane_gives_the_general_lanes_segments``, holds it to them)."""
        plan = self._plans.get(letters)
        if plan is None and self.row_sink is not None and self.row_sink.arcs and \
                (taken := self._arc_lane(letters, values, span, index)):
            return taken
        if plan is None or plan[2] >= 0 or plan[4] >= 0 or self.ended or self.m73_saved or self.track \
                or self.machine_at is not None or self.unsupported or self.prerotation_xy is not None \
                or self.spline_state is not None or self.comp_on or self.comp_just_off or self.cycle is not None \
                or self._tlo_shift is not None or self.after_home or self.prog is not None or self._tlo_untaken \
                or self.inch or not self.absolute or self.feed_mode != 94 or not self.fused_lane \
                or (self.unset and not self._noted_straight):
            return Interpreter.lane(self, letters, values, span, index)
        axis_at, gk, _mk, fk, _sk = plan
        motion = self.motion
        if gk >= 0:
            v: Any = values[gk]  # a Fraction, read through its slots
            if v._denominator != 1:
                return Interpreter.lane(self, letters, values, span, index)
            motion = v._numerator * 10
        if motion != 10 and motion != 0:
            return Interpreter.lane(self, letters, values, span, index)
        if fk >= 0:
            fv: Any = values[fk]
            if fv._numerator < 0:
                return Interpreter.lane(self, letters, values, span, index)
            self.feed = fv
        self.block_index = index
        self.span = span
        self.blocks += 1
        if gk >= 0:
            self.cycle_il = None
            self.last_cycle = None
            self.motion = motion
        pos = self.pos
        end: Any = list(pos)
        off = self.off
        for k, i in axis_at:
            o: Any = off[i]
            end[i] = qadd(values[k], o) if o._numerator else values[k]
        fmm = None
        if motion == 10:
            kind = _LINE
            feed: Any = self.feed
            if feed._numerator == 0:
                self.check_feed()
            fmm = self.feed
        else:
            kind = _RAPID
        end = tuple(end)
        fr = self._frame
        if fr is None or self._frame_off is not off:
            fr = self.program_frame()
        emitted = self.emitted
        sink = self.row_sink
        if sink is not None and self.segment_count >= sink.start:
            # a column row instead of a segment (nczones.gcode.fanuc.columns.Rows: the segment is built if read;
            # BoxRows for the numpy-free route: the run's box only)
            rows: Any = emitted[-1] if emitted else None
            if type(rows) is not sink.rows or rows.prev_end is not pos or rows.full:
                rows = sink.open(pos)
                if rows is not None and rows.add(kind, end, axis_at, index, span, self.tlo, fmm, self.tool_register,
                                                 fr):
                    emitted.append(rows)
                else:
                    rows = None
            elif not rows.add(kind, end, axis_at, index, span, self.tlo, fmm, self.tool_register, fr):
                rows = None
            if rows is not None:
                self.segment_count += 1
                self.kind_counts[kind] += 1
                self.pos = end
                self.prerotation_xy_next = None
                return 2 if rows.full or len(emitted) >= self.chunk_size else 1
        emitted.append(make_segment(kind, pos if type(pos) is tuple else tuple(pos), end, self.axes, index, span,
                                    self.tlo, fmm, None, False, None, None, 0, None, "", self.tool_register, (), (),
                                    (), fr))
        self.segment_count += 1
        self.kind_counts[kind] += 1
        self.pos = end
        self.prerotation_xy_next = None
        return 2 if len(emitted) >= self.chunk_size else 1

    def _arc_plan(self, letters: str, plane: Plane) -> tuple | None:
        """How :meth:`_arc_lane` reads a block with these letters in this plane: ``((value index, axis index),
        ...)``, the value indices of G, F, R and the plane's two centre offsets (-1: absent) and the plane's axis
        indices; None unless every letter is an axis or one of G, F, R and those offsets, once, with R or an offset
        (not both) and a word of a plane axis (else the general path: errors, a 0 degree arc, a whole circle)."""
        plan = None
        a_name, b_name, _n = PLANE_AXES[plane]
        ia, ib = self.index.get(a_name), self.index.get(b_name)
        la, lb = _CENTRE_LETTER[a_name], _CENTRE_LETTER[b_name]
        if ia is not None and ib is not None and len(set(letters)) == len(letters) \
                and all(c in self.index or c in "GFR" or c == la or c == lb for c in letters) \
                and ("R" in letters) != (la in letters or lb in letters):
            axis_at = tuple((k, self.index[c]) for k, c in enumerate(letters) if c in self.index)
            if any(i == ia or i == ib for _k, i in axis_at):
                plan = (axis_at, letters.find("G"), letters.find("F"), letters.find("R"), letters.find(la),
                        letters.find(lb), ia, ib)
        if len(self._arc_plans) < 4096:
            self._arc_plans[letters] = (plane, plan)
        return plan

    def _arc_lane(self, letters: str, values: tuple, span: Any, index: int) -> int:
        """A G2/G3 block (axis words, R or the plane's I/J/K, at most G2/G3 and F) in the state :meth:`lane` takes,
        written into the run's box (``row_sink`` a ``columns.BoxSink``: the numpy-free route of
        ``nczones.prover.fanucboxes``): 1 or 2 as :meth:`lane` returns, or 0 with nothing changed (the block then
        takes the general path, which decides every case left out here: errors, a 0 degree arc, a half circle
        within the R tolerance, an I/J arc off its circle by more than the tolerance or ending on its start's ray,
        a first arc that notes an assumed mode).  What it does for the block is what ``_execute_general`` -> ``_fanuc_motion`` ->
        ``Interpreter.arc`` -> ``emit`` do, but that the arc's box replaces its segment
        (``tests/prover/test_fanuc_boxes.py`` holds the route's verdicts and reports to the full path's)."""
        plane = self.plane
        got = self._arc_plans.get(letters)  # (the plane it was made for, the plan)
        plan = got[1] if got is not None and got[0] is plane else self._arc_plan(letters, plane)
        if plan is None or self.ended or self.m73_saved or self.track or self.machine_at is not None \
                or self.unsupported or self.prerotation_xy is not None or self.spline_state is not None \
                or self.comp_on or self.comp_just_off or self.cycle is not None or self._tlo_shift is not None \
                or self.after_home or self.prog is not None or self._tlo_untaken or self.inch or not self.absolute \
                or self.feed_mode != 94 or not self.fused_lane or self._first_after_transform or self.arc_absolute \
                or (self.unset and not self.unset.isdisjoint(_ARC_ASSUMED)):
            return 0
        axis_at, gk, fk, rk, ka, kb, ia, ib = plan
        motion = self.motion
        if gk >= 0:
            v: Any = values[gk]  # a Fraction, read through its slots
            if v._denominator != 1:
                return 0
            motion = v._numerator * 10
        if motion != 20 and motion != 30:
            return 0
        feed: Any = self.feed
        if fk >= 0:
            feed = values[fk]
            if feed._numerator < 0:
                return 0
        if feed._numerator == 0:
            return 0  # GC305 (check_feed)
        pos = self.pos
        end: Any = list(pos)
        off = self.off
        for k, i in axis_at:
            o: Any = off[i]
            end[i] = qadd(values[k], o) if o._numerator else values[k]
        end = tuple(end)
        emitted = self.emitted
        sink = self.row_sink
        rows: Any = emitted[-1] if emitted else None
        fresh = type(rows) is not sink.rows or rows.prev_end is not pos or rows.full
        if fresh:
            rows = sink.open(pos)
            if rows is None:
                return 0
        ij = (values[ka] if ka >= 0 else _ZERO, values[kb] if kb >= 0 else _ZERO) if rk < 0 else None
        if not rows.add_arc(motion == 20, end, axis_at, ia, ib, values[rk] if rk >= 0 else None, ij, span, self.tlo,
                            self.arc_tolerance if self.arc_rule == "fixed" else None):
            return 0
        if fresh:
            emitted.append(rows)
        self.block_index = index
        self.span = span
        self.blocks += 1
        if gk >= 0:
            self.cycle_il = None
            self.last_cycle = None
            self.motion = motion
        self.feed = feed
        self.segment_count += 1
        self.kind_counts[_ARC] += 1
        self.pos = end
        self.prerotation_xy_next = None
        return 2 if rows.full or len(emitted) >= self.chunk_size else 1

    @property
    def transform_just_cancelled(self) -> bool:
        """Whether the next move is the first after a coordinate transform was set or cancelled (it must be
        absolute; ``fanuc.holes.holes_state_ok`` leaves such a hole to :meth:`_fanuc_cycle`)."""
        return self._first_after_transform

    def box_lane_modes(self) -> tuple[bool, bool] | None:
        """Whether the state is one :meth:`lane` and :meth:`_arc_lane` both take a plain block in (their tests but
        for the block's own words; ``nczones.gcode.fanuc.boxrun`` reads runs of lines in it): (a straight move
        would take the one-call lane: no mode left to note as assumed; an arc would take the arc lane), or None."""
        if self.prog is not None or not self._box_state_ok():
            return None
        unset = self.unset
        return not unset or self._noted_straight, not unset or unset.isdisjoint(_ARC_ASSUMED)

    def _box_state_ok(self) -> bool:
        """:meth:`box_lane_modes`' tests of the state but the transform's."""
        return not (self.ended or self.m73_saved or self.track or self.machine_at is not None or self.unsupported
                    or self.prerotation_xy is not None or self.spline_state is not None or self.comp_on
                    or self.comp_just_off or self.cycle is not None or self._tlo_shift is not None or self.after_home
                    or self._tlo_untaken or self.inch or not self.absolute or self.feed_mode != 94
                    or not self.fused_lane or self._first_after_transform or self.arc_absolute)

    def box_transform(self) -> Any:
        """``(rotation, scaling, increment)``: the one transform (a G68 rotation or a G51 scaling, the other None;
        :meth:`column_transform`'s, without importing numpy) under which ``nczones.gcode.fanuc.boxrun`` reads plain
        lines as :meth:`_transformed_motion` moves them, when the state is one it mirrors: :meth:`box_lane_modes`'
        tests but the transform's, and no mode of a transformed move left to note as assumed (the first move after
        the transform's block noted them); else None."""
        if self.prog is None or not self._box_state_ok():
            return None
        unset = self.unset
        if unset and any(g in unset and g not in self.assumed for g in ("units", "distance", "offset")):
            return None
        if not self._one_transform() or (self.rotation is None) == (self.scaling is None):
            return None
        return self.rotation, self.scaling, self._grid_step()

    def _lean(self, g: int | None, m: int | None, f: Any, extra: int, s: Any = None) -> bool:
        if self.cycle is not None or self._tlo_shift is not None or self.after_home or self.prog is not None \
                or self._tlo_untaken:
            return False
        if m is not None and m not in (3, 4, 5, 7, 8, 9):
            return False
        if not Interpreter._lean(self, g, m, f, extra):  # S: no LinuxCNC spindle checks (no class between)
            return False
        if m is not None:
            self.last["M"] = Fraction(m)
        return True

    # ------------------------------------------------------------------ one block
    def _feed_word(self, fw: Word) -> None:
        """F: the feed rate (not negative)."""
        if fw.value < 0:
            raise self.error("GC209", f"negative feed rate {fw.text}; F must be 0 or more", fw)
        self.feed = fw.value

    def _record_block(self, block: Block, mcodes: Any, mset: set) -> None:
        """What a block leaves for the system variables (the last M and N) and the M0/M1 stops."""
        if mcodes:
            self.last["M"] = Fraction(mcodes[-1][0])
        if block.number is not None:
            if block.words:
                self.keep_number(block.number)
            else:  # a line of its N alone, handed on as a block (FanucRunner.number_alone)
                self.last["N*"] = block.number
        for k in (0, 1):
            if k in mset and len(self.stops) < 100:
                self.stops.append((k, block.span.line if block.span else 0))

    def _plain_modes(self, groups: dict) -> None:
        """The modal groups mill and lathe read alike: plane (02), units (06), distance (03), G40 (07)."""
        if 2 in groups:
            self.plane = {170: Plane.XY, 180: Plane.XZ, 190: Plane.YZ}[groups[2][0]]
            self.unset.discard("plane")
        if 6 in groups:
            self.inch = groups[6][0] == 200
            self.invalidate_frame()
            self.unset.discard("units")
        if 3 in groups:
            self.absolute = groups[3][0] == 900
            self.unset.discard("distance")
        if 7 in groups and groups[7][0] == 400:
            self.comp_on = False

    def _execute_general(self, block: Block) -> None:
        gcodes, mcodes, words, axis_words = self._split_words(block)
        # ---- modal groups: of one group the last code wins; one-shot codes one per block
        groups: dict[int, tuple[int, Word]] = {}
        for k, w in gcodes:
            g = GROUPS.get(k)
            if g is None:
                hint = "; valid in the linuxcnc dialect: set dialect = \"linuxcnc\" in [machine]" \
                    if k in LINUXCNC_ONLY_G else ""
                raise self.error("GC202", f"unknown G code {gname(k)} (written {w.text or gname(k)}): not a "
                                  f"Fanuc mill G code; see specs/fanuc.md{hint}", w)
            if g == 0 and 0 in groups:
                raise self.error("GC201", f"{gname(groups[0][0])} and {gname(k)} are both one-shot (group 00) "
                                  "codes; write them in separate blocks", w)
            groups[g] = (k, w)
        if len(mcodes) > 3:
            raise self.error("GC206", f"{len(mcodes)} M words in one block; at most 3 are allowed", mcodes[3][1])
        g0 = groups.get(0)
        g1 = groups.get(1)
        g9 = groups.get(9)
        if g1 and g9 and g9[0] != 800:
            self.unknown(f"{gname(g1[0])} {gname(g9[0])}", f"{gname(g1[0])} and the canned cycle "
                          f"{gname(g9[0])} in one block: which one the control runs depends on the model", g9[1])
        for k, w in gcodes:
            if k in UNKNOWN_G:
                self.unknown(gname(k), UNKNOWN_G[k], w)
        for k, w in mcodes:
            if k not in self._harmless_m and k not in (2, 30, 6):
                self.unknown(f"M{k}", f"M{k} is not a code nczones models (machine M codes may move anything; "
                              "list the harmless ones in [fanuc] harmless_m)", w)
        mset = {k for k, _ in mcodes}
        # ---- feed, spindle, tool
        if 5 in groups:
            self.feed_mode = groups[5][0] // 10
            self.unset.discard("feed")
        if "F" in words:
            self._feed_word(words["F"])
        if "T" in words:
            t = words["T"].value
            if t.denominator != 1 or t < 0:
                raise self.error("GC209", f"tool number {words['T'].text} must be a non-negative integer", words["T"])
            self.tool_selected = int(t)
        if 6 in mset:
            self.put_in_spindle(self.tool_selected)
        if "D" in words:
            self.last["D"] = words["D"].value
        self._record_block(block, mcodes, mset)
        # ---- modes
        self._plain_modes(groups)
        if 15 in groups:  # G61 exact stop mode; G62 (corner override), G63 (tapping), G64: cutting mode, blending
            mode_key = groups[15][0]
            self.set_path_mode(self._fanuc_path_mode(mode_key != 610, gname(mode_key)))
        if g0 and g0[0] == 90:  # G09: exact stop at the end of this block's motion only
            self.path_modes.append((self.block_index, self._fanuc_path_mode(False, "G09")))
            self.path_modes.append((self.block_index + 1, self.path_mode))
        if 10 in groups:
            self.retract_r = groups[10][0] == 990
            self.unset.discard("retract")
        # ---- programmable transforms (groups 17, 11, 22, 16); their blocks' axis words are centres
        transform_axes = False
        if any(g in groups for g in (17, 11, 22, 16)):
            transform_axes = any(groups.get(g, (0,))[0] in (680, 510, 511, 501) for g in (16, 11, 22))
            self._transform_codes(groups, words, axis_words)
        # ---- tool length (group 08): the tool axis moves with this block's move, or alone
        if 8 in groups and groups[8][0] in (430, 440, 490):
            self._fanuc_tool_length(groups[8], words)
        elif 8 not in groups and "H" in words and self.tool_register is not None:
            # a bare H in G43/G44 mode switches the offset: [0i] "Tool length compensation", whose example
            # cancels with ``G00 Z57.0 H00`` (H00's value 0) in G43 mode
            self._fanuc_tool_length((430 if self.tlo_sign > 0 else 440, words["H"]), words)
        # ---- work coordinate system (group 14)
        if 14 in groups:
            if self.prog is not None:
                self.unknown(gname(groups[14][0]), "changing the workpiece coordinate system while a coordinate "
                              "transform (G68, G51, G51.1, G16) is active is not modelled", groups[14][1])
            self._select_wcs(groups[14], words)
        # ---- one-shot codes that use the axis words
        uses_axes = transform_axes
        if g0 is not None and self.prog is not None and g0[0] in (100, 270, 280, 290, 300, 520, 530, 920, 921):
            self.unknown(gname(g0[0]), f"{gname(g0[0])} while a coordinate transform (G68, G51, G51.1, G16) is "
                          "active is not modelled", g0[1])
        if g0 is not None and g0[0] in (270, 280, 290, 300) and self._tlo_shift is not None and not self.absolute \
                and any(i == self.tool_axis for i, _ in axis_words):
            # the G00 rule (increment + change) is the manual's; for the intermediate point of a reference
            # return the manuals do not say it, and a cancel in the return block may act at the reference
            self.unknown(gname(g0[0]), f"{gname(g0[0])} with an incremental tool axis word in the block of a tool "
                          "length change: whether the intermediate point carries the change is not stated in the "
                          "manuals; change the tool length in another block", g0[1])
        if g0 is not None:
            k = g0[0]
            uses_axes = uses_axes or k in (40, 100, 270, 280, 290, 300, 520, 530, 920, 921)
            if k == 40:
                self._dwell(words, g0[1])
            elif k == 100:
                self._fanuc_g10(words, axis_words, g0[1])
            elif k in (280, 300):
                self._fanuc_home(k, axis_words, words, g0[1])
            elif k == 290:
                self._g29(axis_words, g0[1])
            elif k == 270:
                self._fanuc_rapid(axis_words, derived="G27 reference check")
            elif k == 520:
                self._fanuc_g52(axis_words, g0[1])
            elif k == 530:
                self._fanuc_g53(axis_words, g0[1])
            elif k == 920:
                if self.g52 != [_ZERO] * self.naxes:
                    self.unknown("G92", "G92 while a local coordinate system (G52) is set: how the two combine "
                                  "depends on the control", g0[1])
                self._g92(axis_words, g0[1])
            elif k == 921:
                self._fanuc_g92_1(axis_words, g0[1])
        # ---- group 09 and 01
        if g9 is not None:
            k = g9[0]
            if k == 800:
                self._cancel_cycle()
            elif k in UNKNOWN_G:
                self.cycle = None
            else:
                if self.cycle is None or self.initial_level is None:
                    self.initial_level = None
                self.cycle = k
        if g1 is not None:
            self.motion = g1[0]
            if g9 is None:
                self._cancel_cycle()
        if self.after_home and self.tool_axis is not None and any(i == self.tool_axis for i, _ in axis_words) \
                and not (g0 and g0[0] in (280, 300, 530)) and 8 not in groups:
            self.unknown("G28", "the tool axis moves after G28/G30 returned it with a tool length offset active: "
                          "whether the offset is still applied depends on the control's parameters", axis_words[0][1])
        if self._tlo_untaken and not transform_axes and not (g0 and g0[0] in (100, 520, 920)) and (
                self.cycle is not None or any(i == self.tool_axis for i, _ in axis_words)):
            if not self.absolute:
                # TOS = 1: the next tool axis move takes the change ([0i] "Tool length compensation"); for an
                # incremental one the manuals do not say whether the increment carries it
                code = "G49" if self.tool_register is None else "G43" if self.tlo_sign > 0 else "G44"
                self.unknown(code, "an incremental tool axis move after a tool length change "
                              "with tool_length_motion = \"shift\" (parameter 5006#6 TOS = 1): whether the move "
                              "carries the change is not stated in the manuals; move the tool axis in G90 first",
                              axis_words[0][1] if axis_words else None)
            elif not (g0 and g0[0] == 530) and any(i == self.tool_axis for i, _ in axis_words):
                self._tlo_untaken = False  # an absolute tool axis word (not G53) takes the change
        if not uses_axes:
            moving = bool(axis_words) or (g1 is not None and g1[0] in (20, 30))
            if self.cycle is not None and (axis_words or "R" in words) and g1 is None:
                self._fanuc_cycle(axis_words, words, block)
            elif moving and not self.unsupported:
                self._fanuc_motion(block, axis_words, words, g1)
        if self._tlo_shift is not None:
            if not self.unsupported and self.tool_axis is not None:  # the tool length change, no tool axis move
                end = list(self.pos)
                end[self.tool_axis] = qadd(end[self.tool_axis], self._tlo_shift)
                deps = None
                if self.track:
                    deps = [dict(d) for d in self.dep_pos]
                    deps[self.tool_axis] = dadd(deps[self.tool_axis], self._tlo_shift_deps or {})
                kind = SegmentKind.RAPID if self.motion == 0 or self.cycle is not None else SegmentKind.LINE
                if kind is SegmentKind.LINE:
                    self.check_feed()
                self.emit(kind, end, feed=kind is SegmentKind.LINE, derived="tool length offset", end_deps=deps)
            self._tlo_shift = None
        if 2 in mset or 30 in mset:
            raise StopProgram

    # ------------------------------------------------------------------ pieces
    def initial_path_mode(self, machine: Machine) -> PathMode:
        """A Fanuc control starts in cutting mode G64 unless ``[machine] path_mode`` says G61."""
        return self._fanuc_path_mode(machine.path_mode == "G64", machine.path_mode, machine)

    def _fanuc_path_mode(self, blend: bool, code: str, machine: Machine | None = None) -> PathMode:
        """Cutting mode rounds corners by acc/dec after interpolation: bounded only by the machine file's
        ``path_tolerance`` (specs/path-modes.md)."""
        tol = (machine or self.machine).path_tolerance if blend else None
        return PathMode(blend, tol if tol else None, Fraction(0), "fanuc", code)

    def _cancel_cycle(self) -> None:
        self.cycle = None
        self.cycle_data = {}
        self.initial_level = None

    def _fanuc_tool_length(self, g: tuple[int, Word], words: dict[str, Word]) -> None:
        """G43/G44 H, G49: the new length; the tool axis moves by the change (TOS = 0)."""
        k, w = g
        self.unset.discard("tool")
        old, old_deps = self.tlo, self.dep_tlo
        if k == 490:
            self.tlo, self.tool_register, self.dep_tlo = _ZERO, None, {}
        else:
            h = words.get("H")
            if h is None:
                reg = self.tlo_register
                if reg is None:
                    raise self.error("GC208", f"{gname(k)} needs an H word with the offset number the first time", w)
            else:
                if h.value.denominator != 1 or h.value < 0:
                    raise self.error("GC209", f"H word {h.text} must be a non-negative integer offset number", h)
                reg = int(h.value)
            sign = 1 if k == 430 else -1
            if reg != 0 and reg not in self.h_geometry:
                where = h if h is not None else w
                known = ", ".join(f"H{r}" for r in sorted(self.h_geometry)) or "none"
                raise self.error("GC310", f"tool length offset H{reg} is not in the machine file's [tool_lengths] "
                                  f"(known: {known})", where)
            length = self.h_geometry.get(reg, _ZERO) + self.h_wear.get(reg, _ZERO)
            self.tlo = sign * length
            self.tlo_register = reg
            self.tlo_sign = sign
            self.tool_register = reg
            ranged = reg != 0 and reg not in self.h_set
            self.dep_tlo = {f"H{reg}": sign} if ranged else {}
            if sign < 0 and self.track and ranged:
                self.unknown("G44", "parameter ranges on a tool length used with G44 (subtracted) are not "
                              "modelled", w)
        self.recompute_offsets()
        if self.tool_axis is not None and self.tlo != old:
            if self.settings.tool_length_motion == "move":
                self._tlo_shift = self.tlo - old
                self._tlo_shift_deps = dadd(self.dep_tlo, old_deps, -1) if self.track else None
            else:
                self._tlo_untaken = True
            self.after_home.discard(self.tool_axis)
        elif self.tool_axis is not None:
            self.after_home.discard(self.tool_axis)

    def _select_wcs(self, g: tuple[int, Word], words: dict[str, Word]) -> None:
        k, w = g
        if k == 541:
            p = words.get("P")
            if p is None or p.value.denominator != 1 or not 1 <= p.value <= 48:
                raise self.error("GC209", "G54.1 needs P1 to P48 (the additional workpiece coordinate system)",
                                  p or w)
            self.wcs = f"G54.1P{int(p.value)}"
        else:
            self.wcs = {540: "G54", 550: "G55", 560: "G56", 570: "G57", 580: "G58", 590: "G59"}[k]
        self.unset.discard("offset")
        self.recompute_offsets()

    def _dwell(self, words: dict[str, Word], w: Word) -> None:
        """G04 X (seconds), U (seconds), P (milliseconds); none: an exact stop (no dwell)."""
        given = [x for x in (words.get("X"), words.get("U"), words.get("P")) if x is not None]
        if len(given) > 1:
            raise self.error("GC204", "G04 takes one of X, U (seconds) and P (milliseconds)", given[1])
        seconds = _ZERO
        if given:
            x = given[0]
            if x.value < 0:
                raise self.error("GC209", f"dwell time {x.text} is negative", x)
            if x.letter == "P":
                seconds = dwell_p_seconds(x.value)
            else:
                seconds = x.value
        self.emit(SegmentKind.DWELL, list(self.pos), dwell=seconds)

    def _target(self, axis_words: AxisWords, absolute: bool | None = None) -> tuple[list[Fraction], list[dict] | None]:
        """The machine target of the block's axis words, with a pending tool length change on the tool axis."""
        end, deps = self.program_target(axis_words, False, absolute)
        shift = self._tlo_shift
        incremental = not (self.absolute if absolute is None else absolute)
        # an absolute tool axis word already reads the new length through the offsets; an incremental one
        # moves from where the old length put the tool, so the change is added to the increment:
        # [0i] "Tool length compensation", N2 ``G91 G00 G43 Z-32.0 H01`` (H01 = -4.0) moves Z by -36
        if shift is not None and self.tool_axis is not None and (
                incremental or not any(i == self.tool_axis for i, _ in axis_words)):
            end[self.tool_axis] = qadd(end[self.tool_axis], shift)
            if deps is not None:
                deps[self.tool_axis] = dadd(deps[self.tool_axis], self._tlo_shift_deps or {})
        self._tlo_shift = None
        return end, deps

    def _fanuc_motion(self, block: Block, axis_words: AxisWords, words: Words, g1: tuple | None) -> None:
        if self.prog is not None:
            self._transformed_motion(block, axis_words, words)
            return
        if self._first_after_transform:
            self._first_after_transform = False
            if not self.absolute:
                self.unknown(gname(self.motion or 0), "the first move after a coordinate transform is cancelled must be "
                              "absolute (G90): the manuals give an incremental one no meaning")
                return
        motion = self.motion
        if motion in (0, 10):
            if not axis_words and self._tlo_shift is None:
                return
            self.note_assumed(("units", "distance", "offset"))
            end, deps = self._target(axis_words)
            if motion == 0:
                self.emit(SegmentKind.RAPID, end, end_deps=deps)
            else:
                self.check_feed()
                self.emit(SegmentKind.LINE, end, feed=True, end_deps=deps)
        elif motion in (20, 30):
            if self._tlo_shift is not None:
                self.unknown(gname(motion), "a tool length change in an arc block: the tool axis moves along "
                              "the arc in a way the manuals do not state")
                return
            rw = words.get("R")
            if rw is not None and not any(i in self._plane_indices() for i, _ in axis_words):
                return  # R arc to the point it starts from: a 0 degree arc, no motion (0i/30i)
            self.arc(block, axis_words, words, motion == 20, False)
        elif motion == 330:
            kw = words.get("F")
            if kw is None and self.feed == 0:
                raise self.error("GC208", "G33 needs F (the lead)")
            end, deps = self._target(axis_words)
            self.emit(SegmentKind.LINE, end, derived="G33 thread", end_deps=deps)
        else:
            self.unknown(gname(motion or 0), f"{gname(motion or 0)} is not modelled")

    def _plane_indices(self) -> tuple:
        a, b, _n = PLANE_AXES[self.plane]
        return (self.index.get(a), self.index.get(b))

    def _fanuc_rapid(self, axis_words: AxisWords, derived: str = "") -> None:
        if not axis_words:
            return
        end, deps = self._target(axis_words)
        self.emit(SegmentKind.RAPID, end, derived=derived, end_deps=deps)

    def _fanuc_g53(self, axis_words: AxisWords, w: Word) -> None:
        """G53: a rapid to machine coordinates (the tool axis' offsets do not apply to it)."""
        if not self.absolute:
            self.unknown("G53", "G53 in incremental mode (G91): the manuals give it no meaning", w)
            return
        if not axis_words:
            return
        self.note_assumed(("units",))
        end, deps = self.program_target(axis_words, True)
        if self._tlo_shift is not None and self.tool_axis is not None and not any(
                i == self.tool_axis for i, _ in axis_words):
            end[self.tool_axis] = qadd(end[self.tool_axis], self._tlo_shift)
            if deps is not None:
                deps[self.tool_axis] = dadd(deps[self.tool_axis], self._tlo_shift_deps or {})
        self._tlo_shift = None
        for i, _w in axis_words:
            self.after_home.discard(i)
        self.emit(SegmentKind.RAPID, end, derived="G53", end_deps=deps)

    def _fanuc_home(self, k: int, axis_words: AxisWords, words: Words, w: Word) -> None:
        """G28 / G30 Pn: rapid to the intermediate point, then the named axes to the reference position."""
        if not axis_words:
            self.unknown(gname(k), f"{gname(k)} without axis words: Fanuc moves no axis, Haas returns every "
                          "axis; nczones does not know which this machine does", w)
            return
        n = 1
        if k == 300:
            pw = words.get("P")
            if pw is not None and pw.value not in (2, 3, 4):
                raise self.error("GC209", f"G30 {pw.text}: P is 2, 3 or 4 (the reference position number)", pw)
            n = 2 if pw is None else int(pw.value)
        home = self.references.get(n)
        if home is None:
            self.unknown(f"G30 P{n}", f"the {n}{'nd' if n == 2 else 'rd' if n == 3 else 'th'} reference position "
                          f"is not in the machine file ([machine.reference_{n}])", w)
            return
        self.note_assumed(("units", "distance", "offset"))
        inter, deps = self._target(axis_words)
        self.emit(SegmentKind.RAPID, inter, derived=f"{gname(k)} intermediate", end_deps=deps)
        self.intermediate = list(inter)
        self.intermediate_deps = [dict(d) for d in deps] if deps is not None else None
        end = list(self.pos)
        hdeps = [dict(d) for d in self.dep_pos] if self.track else None
        for i, _aw in axis_words:
            end[i] = home[i]
            if hdeps is not None:
                hdeps[i] = {}
            if i == self.tool_axis and self.tlo:
                self.after_home.add(i)
        self.emit(SegmentKind.RAPID, end, derived=f"{gname(k)} reference {n}", end_deps=hdeps)

    def _g29(self, axis_words: AxisWords, w: Word) -> None:
        """G29: from the reference position via G28's intermediate point to the target."""
        if self.intermediate is None:
            self.unknown("G29", "G29 without an earlier G28/G30 intermediate point", w)
            return
        if not axis_words:
            return
        mid = list(self.pos)
        mid_deps = [dict(d) for d in self.dep_pos] if self.track else None
        for i, _aw in axis_words:
            mid[i] = self.intermediate[i]
            if mid_deps is not None:
                mid_deps[i] = dict(self.intermediate_deps[i]) if self.intermediate_deps is not None else {}
        self.emit(SegmentKind.RAPID, mid, derived="G29 intermediate", end_deps=mid_deps)
        end, deps = self._target(axis_words)
        self.emit(SegmentKind.RAPID, end, derived="G29", end_deps=deps)

    def _fanuc_g52(self, axis_words: AxisWords, w: Word) -> None:
        """G52: the local coordinate system's origin in the workpiece system (G52 IP0 cancels it)."""
        if not self.absolute:
            self.unknown("G52", "G52 in incremental mode (G91) is not modelled", w)
            return
        for i, aw in axis_words:
            self.g52[i] = self._mm(aw.value, i)
            self.dep_g52[i] = {}
        self.recompute_offsets()

    def _fanuc_g92_1(self, axis_words: AxisWords, w: Word) -> None:
        """G92.1 IP 0 (workpiece coordinate system preset): the G92 shift of the named axes is cancelled.

        No manual text for the preset was found (specs/fanuc.md): what it does beyond cancelling the G92 shift
        of the axes it names (a local coordinate system G52, the axes it does not name, a value other than 0)
        is unknown rather than guessed."""
        named = {i for i, _aw in axis_words}
        if not named:
            self.unknown("G92.1", "G92.1 without axis words: which axes the preset acts on is not modelled", w)
            return
        if any(aw.value != 0 for _i, aw in axis_words):
            self.unknown("G92.1", "G92.1 with an axis value other than 0 (the format is G92.1 IP 0) is not modelled",
                         w)
            return
        if any(v != 0 for v in self.g52):
            self.unknown("G92.1", "G92.1 while a local coordinate system (G52) is set: whether the preset cancels it "
                         "is not modelled", w)
            return
        if any(v != 0 or self.dep_g92[i] for i, v in enumerate(self.g92) if i not in named):
            self.unknown("G92.1", "G92.1 that does not name an axis with a G92 shift: whether that axis is preset too "
                         "is not modelled", w)
            return
        for i in named:
            self.g92[i] = _ZERO
            self.dep_g92[i] = {}
        self.recompute_offsets()

    def _fanuc_g10(self, words: Words, axis_words: AxisWords, w: Word) -> None:
        """G10 L2 P0..P6 (EXT, G54..G59), L20 P1..P48 (G54.1), L10..L13 P R (tool offsets, memory C)."""
        lw, pw = words.get("L"), words.get("P")
        if lw is None:
            raise self.error("GC208", "G10 needs an L word (L2, L20, L10 to L13)", w)
        L = lw.value
        if pw is None:
            raise self.error("GC208", f"G10 L{L} needs a P word", w)
        P = pw.value
        if L in (2, 20):
            top = 6 if L == 2 else 48
            low = 0 if L == 2 else 1
            if P.denominator != 1 or not low <= P <= top:
                raise self.error("GC209", f"G10 L{L} {pw.text}: P must be an integer {low} to {top}", pw)
            name = (("EXT",) + WORK_OFFSETS[:6])[int(P)] if L == 2 else f"G54.1P{int(P)}"
            reg, dreg = self.g5x[name], self.dep_g5x[name]
            for i, aw in axis_words:
                v = self._mm(aw.value, i)
                reg[i] = v if self.absolute else reg[i] + v
                if self.absolute:
                    dreg[i] = {}
            self.recompute_offsets()
        elif L in (10, 11, 12, 13):
            rw = words.get("R")
            if P.denominator != 1 or P < 0:
                raise self.error("GC209", f"G10 L{L} {pw.text}: P must be a non-negative offset number", pw)
            if rw is None:
                raise self.error("GC208", f"G10 L{L} needs an R word with the offset value", w)
            table = {10: self.h_geometry, 11: self.h_wear, 12: self.d_geometry, 13: self.d_wear}[int(L)]
            v = self.length_mm(rw.value)
            number = int(P)
            table[number] = v if self.absolute else table.get(number, _ZERO) + v
            if L == 10 and self.absolute:
                self.h_set.add(number)
        elif L in (1, 3, 50, 52):
            self.unknown(f"G10 L{L}", f"G10 L{L} ({'tool offset memory A' if L == 1 else 'tool life data' if L == 3 else 'parameter input'}) is not modelled", lw)
        else:
            raise self.error("GC209", f"G10 {lw.text}: L must be 2, 20 or 10 to 13 on a Fanuc mill", lw)

    # ------------------------------------------------------------------ programmable transforms
    def _transform_codes(self, groups: dict, words: Words, axis_words: AxisWords) -> None:
        """G16/G15, G51/G50, G51.1/G50.1, G68/G69 (in that order within a block)."""
        from .transforms import Mirror, Polar

        for g in (17, 11, 22, 16):
            if g not in groups:
                continue
            k, w = groups[g]
            self.invalidate_frame()  # the program frame names the transform
            on = k in (160, 510, 511, 680)
            if on:
                self._enter_transform()
            if k == 150:
                self.polar = None
            elif k == 160:
                a, b, _n = PLANE_AXES[self.plane]
                ia, ib = self.index.get(a), self.index.get(b)
                if ia is None or ib is None:
                    raise self.error("GC308", f"G16 in plane G{int(self.plane)} needs axes {a} and {b}", w)
                self.polar = Polar(ia, ib)
            elif k == 500:
                self.scaling = None
            elif k == 510:
                self.scaling = self._g51(words, axis_words, w)
            elif k == 501:
                if self.mirroring is not None:
                    named = {i for i, _aw in axis_words}
                    kept = tuple((i, c) for i, c in self.mirroring.axes if named and i not in named)
                    self.mirroring = Mirror(kept) if kept else None
            elif k == 511:
                if not self.absolute:
                    self.unknown("G51.1", "G51.1 in incremental mode (G91) is not modelled", w)
                    return
                axes = dict(self.mirroring.axes) if self.mirroring is not None else {}
                for i, aw in axis_words:
                    axes[i] = self._mm(aw.value, i)
                self.mirroring = Mirror(tuple(sorted(axes.items()))) if axes else self.mirroring
            elif k == 690:
                self.rotation = None
            elif k == 680:
                self.rotation = self._g68(words, axis_words, w)
            self._first_after_transform = True
        active = [x for x in (self.polar, self.scaling, self.mirroring, self.rotation) if x is not None]
        if len(active) > 1:
            self.unknown("G68" if self.rotation is not None else "G51", "polar coordinates, scaling, mirror image "
                          "and rotation are modelled one at a time: the order a control combines them in is not "
                          "modelled")
        if not active:
            self.prog = None
            self.prog_deps = None
            self.centre_deps = {}

    def _program(self) -> list[Fraction]:
        """The program point (only while a transform is active)."""
        assert self.prog is not None
        return self.prog

    def _enter_transform(self) -> None:
        if self.prog is None:
            self.prog = [self.pos[i] - self.off[i] for i in range(self.naxes)]
            self.prog_deps = [dadd(self.dep_pos[i], self.dep_off[i], -1) for i in range(self.naxes)] \
                if self.track else [{} for _ in range(self.naxes)]

    def _centre(self, axis_words: AxisWords, i: int, w: Word) -> Fraction:
        """A transform's centre on axis ``i``: the block's word (absolute), else the current program point."""
        for j, aw in axis_words:
            if j == i:
                return self._mm(aw.value, i)
        if self.track and self.prog_deps is not None and self._on_a_range(self.prog_deps[i], i):
            self.centre_deps[i] = dadd(self.centre_deps.get(i, {}), self.prog_deps[i])
        return self._program()[i]

    def _on_a_range(self, deps: dict, i: int) -> bool:
        """Whether a coordinate on axis ``i`` with dependencies ``deps`` depends on a ranged parameter."""
        if not self.ranged:
            return bool(deps)
        return any(c and (k if k.startswith("H") else f"{k}.{self.axes[i]}") in self.ranged for k, c in deps.items())

    def _g68(self, words: Words, axis_words: AxisWords, w: Word) -> Rotation | None:
        from .transforms import Rotation

        a, b, _n = PLANE_AXES[self.plane]
        ia, ib = self.index.get(a), self.index.get(b)
        if ia is None or ib is None:
            raise self.error("GC308", f"G68 in plane G{int(self.plane)} needs axes {a} and {b}", w)
        if not self.absolute and axis_words:
            self.unknown("G68", "a G68 centre in incremental mode (G91) is not modelled", w)
            return self.rotation
        rw = words.get("R")
        if rw is None:
            self.unknown("G68", "G68 without R takes the angle from parameter 5410, which the machine file does "
                          "not hold", w)
            return self.rotation
        angle = rw.value
        if self.settings.rotation_incremental and not self.absolute and self.rotation is not None:
            angle += self.rotation.angle
        return Rotation(ia, ib, self._centre(axis_words, ia, w), self._centre(axis_words, ib, w), angle)

    def _g51(self, words: Words, axis_words: AxisWords, w: Word) -> Scaling | None:
        from .transforms import Scaling

        if not self.absolute and axis_words:
            self.unknown("G51", "a G51 centre in incremental mode (G91) is not modelled", w)
            return self.scaling
        pw = words.get("P")
        per_axis = [words.get(letter) for letter in "IJK"]
        factors = [Fraction(1)] * self.naxes
        if pw is not None and not any(per_axis):
            for letter in "XYZ":
                i = self.index.get(letter)
                if i is not None:
                    factors[i] = pw.value
        elif pw is None and all(per_axis):
            for letter, fw in zip("XYZ", per_axis):
                i = self.index.get(letter)
                if i is not None and fw is not None:
                    factors[i] = fw.value
        else:
            self.unknown("G51", "G51 needs either P or all of I, J, K; the defaults come from parameters 5411 and "
                          "5421, which the machine file does not hold", w)
            return self.scaling
        if any(f == 0 for f in factors):
            raise self.error("GC209", "a scale factor of 0 (G51) collapses the axis", w)
        centre = tuple(self._centre(axis_words, i, w) for i in range(self.naxes))
        return Scaling(centre, tuple(factors))

    def _program_point(self, axis_words: AxisWords) -> tuple[list[Fraction], list[dict]] | None:
        """The program point a block's axis words name while a transform is active (polar coordinates read
        here), with its dependencies; None after recording why it is unknown."""
        p = list(self._program())
        pd = [dict(d) for d in (self.prog_deps or [{} for _ in p])]
        polar = self.polar
        radius = angle = None
        for i, w in axis_words:
            if polar is not None and i in (polar.ia, polar.ib):
                if not self.absolute:
                    self.unknown("G16", "polar coordinates in incremental mode (G91) are not modelled", w)
                    return None
                if i == polar.ia:
                    radius = self._mm(w.value, i)
                else:
                    angle = w.value
                continue
            v = self._mm(w.value, i)
            if self.absolute:
                p[i] = v
                pd[i] = {}
            else:
                p[i] = p[i] + v
        if polar is not None and (radius is not None or angle is not None):
            from .transforms import PointNotCertain, Polar, polar_point

            radius = radius if radius is not None else polar.radius
            angle = angle if angle is not None else polar.angle
            if radius is None or angle is None:
                self.unknown("G16", "the first polar coordinate command needs both the radius and the angle")
                return None
            try:
                p[polar.ia], p[polar.ib] = polar_point(radius, angle, self._grid_step())
            except PointNotCertain as e:
                self.unknown("G16", e.reason)
                return None
            pd[polar.ia] = {}
            pd[polar.ib] = {}
            self.polar = Polar(polar.ia, polar.ib, radius, angle)
        return p, pd

    def _grid_step(self) -> Fraction:
        """The least input increment of a linear axis, in mm: a transformed point is rounded to it.  In G20 it
        is the inch increment (IS-B: 0.0001 in = 0.00254 mm; B-64304EN "Increment system"), not 0.001 mm."""
        inc = self.settings.increment_mm
        return inc / 10 * INCH if self.inch else inc

    def _transform_target(self, p: list[Fraction], pd: list[dict]) -> tuple[list[Fraction], list[dict] | None]:
        """The machine point of a program point: polar (already in ``p``), scaling, mirror, rotation, offsets."""
        from .transforms import PointNotCertain, mirror, rotate, scale

        step = self._grid_step()
        q = p
        mixed: set[int] = set()
        if self.scaling is not None:
            q = scale(self.scaling, q, step)
            mixed |= {i for i, f in enumerate(self.scaling.factors) if f != 1}
        if self.mirroring is not None:
            q = mirror(self.mirroring, q)
            mixed |= {i for i, _c in self.mirroring.axes}
        if self.rotation is not None:
            try:
                q = rotate(self.rotation, q, step)
            except PointNotCertain as e:  # the block is unknown; the candidate keeps the state going
                self.unknown("G68", e.reason)
                q = e.point
            mixed |= {self.rotation.ia, self.rotation.ib}
        end = [qadd(q[i], self.off[i]) for i in range(self.naxes)]
        self._tlo_shift = None  # the offsets hold the new tool length: this move carries it out
        deps = None
        if self.track:
            deps = []
            for i in range(self.naxes):
                if i in mixed:
                    if any(pd[j] for j in mixed):
                        self.unknown("G68" if self.rotation is not None else "G51",
                                      "parameter ranges on a point a coordinate transform moves are not modelled")
                    elif any(self.centre_deps.get(j) for j in mixed):
                        self.unknown("G68" if self.rotation is not None else "G51",
                                      "parameter ranges on the centre of a coordinate transform (taken from the "
                                      "current point: no centre words) are not modelled")
                    deps.append(dict(self.dep_off[i]))
                else:
                    deps.append(dadd(pd[i], self.dep_off[i]))
        return end, deps

    def _transformed_motion(self, block: Block, axis_words: AxisWords, words: Words) -> None:
        motion = self.motion
        if self._first_after_transform and not self.absolute:
            self.unknown(gname(motion or 0), "the first move after G68, G51, G51.1 or G16 must be absolute (G90): "
                          "the manuals give an incremental one no meaning")
            return
        self._first_after_transform = False
        if motion not in (0, 10, 20, 30):
            self.unknown(gname(motion or 0), f"{gname(motion or 0)} under a coordinate transform is not modelled")
            return
        point = self._program_point(axis_words)
        if point is None:
            return
        p, pd = point
        self.note_assumed(("units", "distance", "offset"))
        if motion in (20, 30):
            self._transformed_arc(p, pd, words, motion == 20, axis_words)
            return
        end, deps = self._transform_target(p, pd)
        if self._unnamed_axis_moves(axis_words, end):
            return
        if motion == 0:
            self.emit(SegmentKind.RAPID, end, end_deps=deps)
        else:
            self.check_feed()
            self.emit(SegmentKind.LINE, end, feed=True, end_deps=deps)
        self.prog, self.prog_deps = p, pd

    def _unnamed_axis_moves(self, axis_words: AxisWords, end: list[Fraction]) -> bool:
        """Whether a scaled or mirrored axis the block does not name would move (recorded as unknown, True).

        The model takes an axis a block does not name at its program value, scaled or mirrored: on the first
        move after G51 or G51.1 whose centre on that axis is not where the tool stands, that moves the axis.
        Whether a control does so, or leaves an axis the block does not name where it is (as a block without
        that word does without a transform), the manuals do not say; either reading may be the one that reaches
        a zone, so the block is not modelled.  The rotation's plane is the rotation's model (both of its axes
        are rotated from the program point)."""
        named = {i for i, _w in axis_words}
        changed = set()
        if self.scaling is not None:
            changed |= {i for i, f in enumerate(self.scaling.factors) if f != 1}
        if self.mirroring is not None:
            changed |= {i for i, _c in self.mirroring.axes}
        if self.rotation is not None:
            changed -= {self.rotation.ia, self.rotation.ib}
        moved = sorted(i for i in changed - named if end[i] != self.pos[i])
        if not moved:
            return False
        code = "G51" if self.scaling is not None and any(self.scaling.factors[i] > 0 for i in moved) else "G51.1"
        self.unknown(code, f"axis {', '.join(self.axes[i] for i in moved)} not named in a block would move to its "
                     "scaled or mirrored position (the program point there is not the transform's centre): whether "
                     "a control moves an axis a block does not name under a transform is not modelled")
        return True

    def _transformed_arc(self, p: list[Fraction], pd: list[dict], words: Words, cw: bool,
                         axis_words: AxisWords) -> None:
        """An arc under a transform: its centre and end points transformed; a mirror or a negative scale
        factor on one of the plane's axes reverses the direction."""
        plane = self.plane
        a_name, b_name, n_name = PLANE_AXES[plane]
        ia, ib = self.index.get(a_name), self.index.get(b_name)
        if ia is None or ib is None:
            raise self.error("GC308", f"an arc in plane G{int(plane)} needs axes {a_name} and {b_name}")
        if self.polar is not None:
            self.unknown("G16", "arcs in polar coordinate mode are not modelled")
            return
        if self.rotation is not None and {self.rotation.ia, self.rotation.ib} != {ia, ib}:
            self.unknown("G68", "an arc in another plane than the rotation's is not modelled")
            return
        fa = fb = Fraction(1)
        if self.scaling is not None:
            fa, fb = self.scaling.factors[ia], self.scaling.factors[ib]
            if abs(fa) != abs(fb):
                self.unknown("G51", "an arc scaled differently on its two axes becomes an ellipse; not modelled")
                return
        mirrored = {i for i, _c in self.mirroring.axes} if self.mirroring is not None else set()
        flips = (ia in mirrored) + (ib in mirrored) + (fa < 0) + (fb < 0)
        clockwise = cw if flips % 2 == 0 else not cw
        offs = {"X": "I", "Y": "J", "Z": "K"}
        la, lb, ln = offs[a_name], offs[b_name], offs[n_name]
        if ln in words:
            raise self.error("GC204", f"{ln} word {words[ln].text} given for an arc in plane G{int(plane)}",
                              words[ln])
        rw = words.get("R")
        self.check_feed()
        sa, sb = self._program()[ia], self._program()[ib]
        ea, eb = p[ia], p[ib]
        tol = self.arc_tolerance
        turns = 0
        pw = words.get("P")
        if pw is not None:
            if pw.value.denominator != 1 or pw.value < 1:
                raise self.error("GC209", f"arc turn count {pw.text} must be a positive integer", pw)
            turns = int(pw.value) - 1
        end, deps = self._transform_target(p, pd)
        if self._unnamed_axis_moves(axis_words, end):
            return
        if rw is not None:
            r = self.length_mm(rw.value)
            if sa == ea and sb == eb:
                return  # a 0 degree arc: no motion
            h2 = ((ea - sa) ** 2 + (eb - sb) ** 2) / 4
            if h2 > (abs(r) + tol) ** 2:
                raise self.error("GC302", f"arc radius R{fmt_number(abs(r))} mm is too small to reach the end point", rw)
            r_machine = r * abs(fa)
            mh2 = ((end[ia] - self.pos[ia]) ** 2 + (end[ib] - self.pos[ib]) ** 2) / 4
            if mh2 >= r_machine ** 2:
                centre = ((self.pos[ia] + end[ia]) / 2, (self.pos[ib] + end[ib]) / 2)
                self.emit(SegmentKind.ARC, end, feed=True, plane=plane, clockwise=clockwise, centre=centre,
                           turns=turns, end_deps=deps)
            else:
                self.emit(SegmentKind.ARC, end, feed=True, plane=plane, clockwise=clockwise, radius=r_machine,
                           turns=turns, end_deps=deps)
            self.prog, self.prog_deps = p, pd
            return
        iw, jw = words.get(la), words.get(lb)
        if iw is None and jw is None:
            raise self.error("GC208", f"arc without {la}, {lb} or R word: the centre or radius is missing")
        ca = sa + (self.length_mm(iw.value) if iw is not None else _ZERO)
        cb = sb + (self.length_mm(jw.value) if jw is not None else _ZERO)
        r0 = (sa - ca) ** 2 + (sb - cb) ** 2
        r1 = (ea - ca) ** 2 + (eb - cb) ** 2
        if r0 == 0 or r1 == 0:
            raise self.error("GC304", "zero-radius arc: the centre coincides with the start or end point", iw or jw)
        if r0 != r1 and sqrt_diff_exceeds(r0, r1, tol):
            raise self.error("GC301", f"arc end point is off its circle by more than {fmt_number(tol)} mm", iw or jw)
        centre_point = list(self._program())
        centre_point[ia], centre_point[ib] = ca, cb
        shift = self._tlo_shift
        machine_centre, _d = self._transform_target(centre_point, [{} for _ in range(self.naxes)])
        self._tlo_shift = shift
        self.emit(SegmentKind.ARC, end, feed=True, plane=plane, clockwise=clockwise,
                   centre=(machine_centre[ia], machine_centre[ib]), turns=turns, end_deps=deps)
        self.prog, self.prog_deps = p, pd

    #: G92 (G50 on a lathe) during a tool length offset sets the position *before* the offset to the value
    #: (the lathe: [0i-T] "If a coordinate system is set using G50 during offset, a coordinate system in which
    #: the position before offset matches the position specified in G50 is set"); the mill keeps the
    #: tool tip reading the value
    g92_before_offset = False

    def _g92(self, axis_words: AxisWords, w: Word, incremental: set[int] | None = None) -> None:
        """G92: the workpiece systems are shifted so the current position reads the given values.

        In G91 (or, on a lathe, by U/W: the axes of ``incremental``) a value is an increment: the current
        position then reads its previous reading plus the increment ([0i] "Setting a workpiece coordinate
        system", method using G92: "If IP_ is an incremental command value, the workpiece coordinate system
        is defined so that the current tool position coincides with the result of adding the specified
        incremental value to the coordinates of the previous tool position"), so the G92 shift falls by the
        increment and nothing else changes."""
        if not axis_words:
            raise self.error("GC208", "G92 needs at least one axis word", w)
        ext = self.g5x["EXT"]
        for i, aw in axis_words:
            if (not self.absolute) if incremental is None else i in incremental:
                self.g92[i] = self.g92[i] - self._mm(aw.value, i)  # the dependencies stay those of the old shift
                continue
            if i == self.tool_axis and not self.g92_before_offset and (self.tlo or self.dep_tlo):
                # the lathe manual sets the position *before* the offset to a G50 value; the mill reading
                # (the tool tip, as nczones' G92 sets it) is not confirmed by a manual sentence, and the two
                # differ by the tool length
                self.unknown("G92", "G92 on the tool axis while a tool length offset is active: whether the "
                              "value is the position with or without the tool length is not confirmed for "
                              "Fanuc mills (the lathe manual sets the position before offset); cancel the "
                              "offset (G49) first or leave the tool axis out of G92", w)
            tl = self.tlo if i == self.tool_axis and not self.g92_before_offset else _ZERO
            self.g92[i] = self.pos[i] - ext[i] - self.g5x[self.wcs][i] - self.g52[i] - tl - self._mm(aw.value, i)
            if self.track:
                d = dadd(dadd(self.dep_pos[i], self.dep_g5x[self.wcs][i], -1), self.dep_g5x["EXT"][i], -1)
                d = dadd(d, self.dep_g52[i], -1)
                if i == self.tool_axis and not self.g92_before_offset:
                    d = dadd(d, self.dep_tlo, -1)
                self.dep_g92[i] = d
        self.recompute_offsets()

    # ------------------------------------------------------------------ canned cycles
    def _holes_may_start(self, name: str, iz: int) -> bool:
        """Whether :meth:`_fanuc_cycle` may drill (False: unknown said): the drilling axis ``iz`` not scaled,
        mirrored or rotated, and a hole that is the first move after a transform's block (set or cancelled)
        positioned in G90, as the manuals ask of that move; it then clears the flag (hunt42's H2)."""
        if self.prog is not None and ((self.scaling is not None and self.scaling.factors[iz] != 1) or (
                self.mirroring is not None and any(i == iz for i, _c in self.mirroring.axes)) or (
                self.rotation is not None and iz in (self.rotation.ia, self.rotation.ib))):
            self.unknown(name, f"{name} with the drilling axis scaled, mirrored or rotated is not modelled")
            return False
        if self._first_after_transform:
            if not self.absolute:
                self.unknown(name, f"the first {name} hole after a coordinate transform must be absolute (G90)")
                return False
            self._first_after_transform = False
        return True

    def _fanuc_cycle(self, axis_words: AxisWords, words: Words, block: Block) -> None:
        """A block in canned cycle mode (G73 G74 G76 G81-G86 G89): position, R point, the cycle, return.

        0i/30i-M, "Canned cycle for drilling": operation 1 positions X/Y at rapid at the current level,
        2 rapids to the R point, 3 the hole machining, 4 at the bottom (dwell, spindle), 5 back to R, 6 a
        rapid to the initial level (G98) or stay at R (G99).  The initial level is the tool axis position
        when the cycle mode began.  In G91, R is the distance from the initial level and Z from R.
        """
        k = self.cycle
        assert k is not None  # called in canned cycle mode
        name = gname(k)
        if self.plane is not Plane.XY:
            self.unknown(name, f"{name} outside G17: the drilling axis depends on parameter 5101#0 FXY")
            return
        if self.unsupported:
            return
        ix, iy, iz = self.index.get("X"), self.index.get("Y"), self.index.get("Z")
        if ix is None or iy is None or iz is None:
            raise self.error("GC308", f"a canned cycle needs axes X, Y and Z; this machine has {', '.join(self.axes)}")
        data = self.cycle_data
        for letter in ("R", "Z", "Q", "P"):
            if letter in words:
                data[letter] = words[letter].value
                if letter in "RZ":
                    data[letter + "90"] = self.absolute  # the distance mode the value was written in
        kw = words.get("K") or words.get("L")
        reps = 1
        if kw is not None:
            if kw.value.denominator != 1 or kw.value < 0:
                raise self.error("GC209", f"canned cycle repeat count {kw.text} must be a non-negative integer", kw)
            reps = int(kw.value)
        missing = [letter for letter in ("R", "Z") if letter not in data]
        if missing:
            self.unknown(name, f"{name} without {' and '.join(missing)} (R point, hole bottom) given since the cycle "
                          "began: what the control then uses is not stated in the manuals")
            return
        switched = [letter for letter in ("R", "Z") if data.get(letter + "90", self.absolute) != self.absolute]
        if switched:
            # the manual reads R and Z by the distance mode of the block ("Canned cycle for drilling": in G91,
            # R from the initial level, Z from R) but does not say what a value kept from a block in the other
            # mode means after G90/G91 changes: the number again in the new mode, or the level it named
            written = "G90" if data[switched[0] + "90"] else "G91"
            self.unknown(name, f"{' and '.join(switched)} kept from a block in {written}, used in "
                          f"{'G90' if self.absolute else 'G91'}: whether the control reads the stored value in the "
                          "new distance mode or keeps the level it named is not stated in the manuals; give "
                          f"{' and '.join(switched)} again after the change")
            return
        if k in (730, 830) and any(x in words for x in "IJ"):
            self.unknown(name, f"{name} with I or J: Haas's variable-peck mode is not modelled (on Fanuc K is "
                          "the repeat count)")
            return
        if k in (730, 830) and "Q" not in data:
            raise self.error("GC208", f"{name} needs Q (the depth of cut per peck)")
        if k in (730, 830) and data["Q"] <= 0:
            raise self.error("GC209", f"peck depth Q{fmt_number(data['Q'])} must be greater than 0")
        if k == 760 and "Q" not in data:
            data["Q"] = _ZERO
        self.check_feed()
        self.note_assumed(("units", "distance", "offset", "plane", "retract"))
        if self._tlo_shift is not None:
            self.unknown(name, "a tool length change in a canned cycle block is not modelled")
            return
        if self.initial_level is None:
            self.initial_level = self.pos[iz]
            self.initial_level_deps = dict(self.dep_pos[iz]) if self.track else {}
        initial = self.initial_level
        offz = self.off[iz]
        if self.absolute:
            r = qadd(self.length_mm(data["R"]), offz)
            bottom = qadd(self.length_mm(data["Z"]), offz)
        else:
            r = qadd(initial, self.length_mm(data["R"]))
            bottom = qadd(r, self.length_mm(data["Z"]))
        wd = {self.axes[i]: aw for i, aw in axis_words}
        for i, aw in axis_words:
            if self.axes[i] not in ("X", "Y", "Z"):
                raise self.error("GC210", f"cannot put an {self.axes[i].lower()} word ({aw.text}) in a canned cycle", aw)
        if reps == 0:
            return  # K0: the drilling data is stored, no hole is drilled
        if self.too_many(name, f"{name} {kw.text if kw is not None else ''}", reps, kw):
            return
        if k in (730, 830):
            step = self.length_mm(data["Q"])
            back = self.settings.g73_retract if k == 730 else self.settings.g83_clearance
            if back is None:
                param, key = ("5114", "g73_retract") if k == 730 else ("5115", "g83_clearance")
                self.unknown(name, f"{name}'s {'retract' if k == 730 else 'clearance'} d is parameter {param}; "
                              f"set [fanuc] {key} in the machine file")
                return
        if k in (760,):
            shift = self.settings.boring_shift
            if shift is None:
                self.unknown(name, "G76's shift direction is parameter 5101 bits RD1/RD2; set [fanuc] "
                              "boring_shift in the machine file")
                return
        dwell = dwell_p_seconds(data["P"]) if "P" in data and k in (760, 820, 840, 890, 740, 842, 843) else None
        top = initial if not self.retract_r else r
        top_deps = self.initial_level_deps if not self.retract_r and self.track else None
        transformed = self.prog is not None
        if not self._holes_may_start(name, iz):
            return
        xy_words = [(i, aw) for i, aw in axis_words if i in (ix, iy)]
        for rep in range(reps):
            if rep and self.budget_gone(name, f"{kw.text if kw is not None else ''} had drilled {rep} holes", kw):
                return
            target = list(self.pos)
            if transformed:
                point = self._program_point(xy_words)
                if point is None:
                    return
                p, pd = point
                machine_target, _deps = self._transform_target(p, pd)
                target[ix], target[iy] = machine_target[ix], machine_target[iy]
                self._program()[ix], self._program()[iy] = p[ix], p[iy]
            elif self.absolute:
                if "X" in wd:
                    target[ix] = qadd(self._mm(wd["X"].value, ix), self.off[ix])
                if "Y" in wd:
                    target[iy] = qadd(self._mm(wd["Y"].value, iy), self.off[iy])
            else:
                if "X" in wd:
                    target[ix] = qadd(target[ix], self._mm(wd["X"].value, ix))
                if "Y" in wd:
                    target[iy] = qadd(target[iy], self._mm(wd["Y"].value, iy))
            a, b = target[ix], target[iy]

            def go(kind, z, derived, x=None, y=None, a=a, b=b, z_deps=None):
                end = list(self.pos)
                end[ix] = a if x is None else x
                end[iy] = b if y is None else y
                end[iz] = z
                deps = None
                if self.track:
                    deps = [dict(d) for d in self.dep_pos]
                    if self.absolute:
                        for i, letter in ((ix, "X"), (iy, "Y")):
                            if letter in wd:
                                deps[i] = dict(self.dep_off[i])
                        # R, the bottom and the pecks move with the offsets; the initial level is where
                        # the tool stood (a machine position with its own dependencies)
                        deps[iz] = dict(self.dep_off[iz] if z_deps is None else z_deps)
                    else:
                        self.unknown(name, "parameter ranges with incremental canned cycles are not modelled")
                self.emit(kind, end, feed=kind is SegmentKind.LINE, derived=derived, end_deps=deps)

            go(SegmentKind.RAPID, self.pos[iz], f"{name} position", z_deps=self.dep_pos[iz] if self.track else None)
            if self.pos[iz] != r or self.track:  # with ranges the levels differ for other values
                go(SegmentKind.RAPID, r, f"{name} to R")
            if k in (730, 830):
                depth = r
                if self.too_many(name, f"{name} Q{fmt_number(data['Q'])} (one peck per Q)", -((bottom - r) // step) - 1):
                    return
                while depth - step > bottom:  # G73: back off d; G83: out to R, down to d above the cut
                    depth -= step
                    go(SegmentKind.LINE, depth, f"{name} peck")
                    if k == 830:
                        go(SegmentKind.RAPID, r, f"{name} clear")
                    go(SegmentKind.RAPID, depth + (back or _ZERO), f"{name} {'retract' if k == 730 else 'approach'}")
            go(SegmentKind.LINE, bottom, f"{name} feed")
            if dwell:
                self.emit(SegmentKind.DWELL, list(self.pos), dwell=dwell, derived=f"{name} dwell")
            if k == 760:
                sa, sb = self._boring_shift(data["Q"])
                go(SegmentKind.RAPID, bottom, f"{name} shift", x=a + sa, y=b + sb)
                go(SegmentKind.RAPID, top, f"{name} retract", x=a + sa, y=b + sb, z_deps=top_deps)
                go(SegmentKind.RAPID, top, f"{name} shift back", z_deps=top_deps)
            elif k in (740, 840, 842, 843, 850, 890):
                go(SegmentKind.LINE, r, f"{name} retract")
                if top != r or (self.track and top_deps is not None):
                    go(SegmentKind.RAPID, top, f"{name} return", z_deps=top_deps)
            else:
                go(SegmentKind.RAPID, top, f"{name} retract", z_deps=top_deps)
        if transformed:
            self._program()[iz] = self.pos[iz] - self.off[iz]

    def _boring_shift(self, q: Fraction) -> tuple[Fraction, Fraction]:
        d = self.length_mm(abs(q))
        shift = self.settings.boring_shift or "+X"  # _fanuc_cycle leaves G76 unknown without the setting
        return {"+X": (d, _ZERO), "-X": (-d, _ZERO), "+Y": (_ZERO, d), "-Y": (_ZERO, -d)}[shift]

    # ------------------------------------------------------------------ system variables
    def bind_variables(self, variables: FanucVariables) -> None:
        """Serve the system variables (``#1000`` and up) the program reads and writes (``specs/fanuc.md``)."""
        self.vars = variables
        variables.system_read = self.system_read
        variables.system_write = self.system_write

    def bind_parameters(self, params: Any) -> None:  # the LinuxCNC store is not used in this dialect
        self._scopes = None

    def system_read(self, n: int) -> tuple:
        from .system import read

        return read(self, n)

    def system_write(self, n: int, value: tuple) -> None:
        from .system import write

        write(self, n, value)


def dwell_p_seconds(p: Fraction) -> Fraction:
    """A dwell P as seconds: milliseconds when written as an integer (Fanuc), seconds with a decimal
    fraction (Haas writes ``P0.5``)."""
    return p / 1000 if p.denominator == 1 else p
