"""Cylindrical interpolation mode (G07.1 / G107) in the interpreter.

``G07.1 C<r>`` (Fanuc; ``G107`` is accepted with the same meaning — LinuxCNC
has no cylindrical interpolation) switches the mode on for the rotary axis
named, on a cylinder of radius ``r`` (mm, or inches under G20); ``G07.1 C0``
switches it off.  In the mode the rotary word is an angle in degrees, and
motion is programmed on the developed surface: the plane is (linear axis,
developed rotary axis), Z-C for C (see :mod:`nczones.geometry.cylinder`).

* ``G01`` is a straight line in the developed plane — and, because the
  developed coordinate is ``s = pi R C / 180``, linear in C, also a straight
  line in machine coordinates: an exact ``LINE`` segment (tagged with the
  cylinder in ``Segment.extra``).  Other axes may move with it.
* ``G02``/``G03`` take ``R`` (developed millimetres, negative for more than
  180 degrees) and become ``SegmentKind.DEVELOPED_ARC`` segments
  (``radius`` = R, ``clockwise``, ``extra`` = cylinder radius and axes).

Restrictions (Fanuc's, errors with line and column; codes ``GC23x`` block,
``GC33x`` interpretation):

GC230  a G code the mode does not allow: G00 and every positioning (G28,
       G30, G53, canned cycles), plane changes (G17/G18/G19), offsets and
       coordinate systems (G10, G43, G49, G52, G54-G59.3, G92), units
       (G20/G21), G07.1 with a radius while the mode is on.
GC231  a word the mode does not allow: I/J/K (arcs take R only), H, an axis
       other than the linear and rotary axes in an arc (no helix).
GC232  the G07.1 block holds other words (it must stand alone), or its axis
       word is not a rotary axis of the machine, or the machine lacks the
       parallel linear axis.
GC233  negative cylinder radius.
GC330  an arc whose chord is longer than 2|R| beyond the arc tolerance, an
       arc with equal end points, or R0.

Entering and leaving the mode never moves the machine and keeps every
position exact (the mode changes only how motion blocks are read).
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from ..motion import Developed, SegmentKind
from .blocks import Block, Word
from .interpreter import AXIS_LETTERS, INCH, ROTARY, Interpreter, fmt_number, gkey
from .mentions import PIECE_CHARS, uses_cylindrical

__all__ = ["CylindricalInterpreter", "uses_cylindrical", "CylinderMode"]

_G71, _G107 = 71, 1070
_PIECE_CHARS = PIECE_CHARS

# G codes (keys 10 x number) allowed in the mode and what the others are called in messages
_ALLOWED_G = {10, 20, 30, 40, 900, 910, 930, 940, 950, 410, 420, 400, 610, 611, 640, 800}
_FORBIDDEN_WHY = {
    0: "positioning (G00) is not allowed in cylindrical interpolation mode (Fanuc); cancel it with G07.1 C0 first",
    280: "reference return (G28) is a positioning and is not allowed in cylindrical interpolation mode",
    300: "G30 is a positioning and is not allowed in cylindrical interpolation mode",
    530: "G53 is a positioning and is not allowed in cylindrical interpolation mode",
    170: "the plane cannot be changed in cylindrical interpolation mode (it is fixed to the developed plane)",
    180: "the plane cannot be changed in cylindrical interpolation mode (it is fixed to the developed plane)",
    190: "the plane cannot be changed in cylindrical interpolation mode (it is fixed to the developed plane)",
    200: "units cannot be changed in cylindrical interpolation mode",
    210: "units cannot be changed in cylindrical interpolation mode",
}


class CylinderMode:
    """The active mode: axes and radius (exact, mm)."""

    __slots__ = ("rotary", "linear", "ir", "il", "radius")

    def __init__(self, rotary: str, linear: str, ir: int, il: int, radius: Fraction):
        self.rotary, self.linear, self.ir, self.il, self.radius = rotary, linear, ir, il, radius

    @property
    def extra(self) -> tuple[Developed]:
        return (Developed(self.linear, self.rotary, self.radius),)


class CylindricalInterpreter(Interpreter):
    """The interpreter with cylindrical interpolation (used when the program mentions G07.1/G107).

    Examples
    --------
    >>> from nczones.machine import parse_machine
    >>> from nczones.gcode import segments_text
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["Z", "C"]
    ... [machine.rapid]
    ... Z = "1000"
    ... C = "1000"
    ... [machine.reference]
    ... Z = "0"
    ... C = "0"
    ... ''')
    >>> segs = segments_text("G0 Z30 C30\\nG7.1 C57.3\\nG1 Z40 F100\\nG2 Z50 C40 R10\\nG7.1 C0\\nG0 C0\\n", m)
    >>> [s.kind.name for s in segs]
    ['RAPID', 'LINE', 'DEVELOPED_ARC', 'RAPID']
    >>> segs[2].extra[0].cylinder_radius, segs[2].radius, segs[2].clockwise
    (Fraction(573, 10), Fraction(10, 1), True)
    """

    cylinder: CylinderMode | None = None

    def execute(self, block: Block) -> None:
        g7 = [w for w in block.words if w.letter == "G" and gkey(w.value) in (_G71, _G107)]
        if g7:
            self._g071(block, g7)
        elif self.cylinder is None:
            super().execute(block)
        else:
            self._in_mode(block)

    # ------------------------------------------------------------------ G07.1
    def _g071(self, block: Block, g7: list[Word]) -> None:
        w = g7[0]
        if len(g7) > 1:
            raise self.error("GC232", "two G07.1/G107 words in one block", g7[1])
        others = [x for x in block.words if x is not w]
        axis = [x for x in others if x.letter in AXIS_LETTERS]
        rest = [x for x in others if x.letter not in AXIS_LETTERS]
        if rest:
            raise self.error("GC232", f"{rest[0].text or rest[0].letter}: G07.1 must stand alone in its block "
                              "with one rotary axis word (G07.1 C<radius> or G07.1 C0)", rest[0])
        if len(axis) != 1:
            raise self.error("GC232", "G07.1 needs exactly one rotary axis word with the cylinder radius "
                              "(G07.1 C<radius> switches the mode on, G07.1 C0 off)", axis[1] if axis else w)
        aw = axis[0]
        letter = aw.letter
        if letter not in ROTARY or letter not in self.index:
            have = ", ".join(a for a in self.axes if a in ROTARY) or "none"
            raise self.error("GC232", f"{aw.text or letter}: G07.1 names the rotary axis of the cylinder; "
                              f"{letter} is not a rotary axis of this machine (rotary axes: {have})", aw)
        if aw.value < 0:
            raise self.error("GC233", f"cylinder radius {aw.text} is negative; write the radius in mm (G07.1 C0 "
                              "switches the mode off)", aw)
        if aw.value == 0:
            self.cylinder = None
            self.invalidate_frame()
            return
        if self.cylinder is not None:
            raise self.error("GC230", f"G07.1 {aw.text}: cylindrical interpolation is already on (radius "
                              f"{fmt_number(self.cylinder.radius)} mm); cancel it with G07.1 {self.cylinder.rotary}0 first", w)
        from ..geometry.cylinder import LINEAR_AXIS_OF

        linear = LINEAR_AXIS_OF[letter]
        if linear not in self.index:
            raise self.error("GC232", f"cylindrical interpolation on {letter} needs the parallel linear axis "
                              f"{linear}; this machine has {', '.join(self.axes)}", aw)
        if self.motion not in (None, 0, 10, 20, 30):
            raise self.error("GC230", "cancel the canned cycle (G80) before G07.1", w)
        if self.track:
            self.unknown("G07.1", "parameter ranges are not supported with cylindrical interpolation", w)
        if self.prerotation_xy is not None:
            self.unknown("G07.1", "cylindrical interpolation in a rotated coordinate system (G10 L2 R) is not modelled", w)
        radius = aw.value * INCH if self.inch else aw.value
        self.cylinder = CylinderMode(letter, linear, self.index[letter], self.index[linear], radius)
        self.invalidate_frame()

    # ------------------------------------------------------------------ blocks in the mode
    def _in_mode(self, block: Block) -> None:
        cyl = self.cylinder
        assert cyl is not None  # called in cylindrical interpolation mode only
        g1 = None
        for w in block.words:
            if w.letter == "G":
                k = gkey(w.value)
                if k in _FORBIDDEN_WHY:
                    raise self.error("GC230", f"{w.text or 'G'}: {_FORBIDDEN_WHY[k]}", w)
                if k not in _ALLOWED_G:
                    raise self.error("GC230", f"{w.text or 'G'} is not allowed in cylindrical interpolation mode "
                                      "(allowed: G01 G02 G03 G04 G40-G42 G61 G64 G80 G90 G91 G93-G95); cancel "
                                      "the mode with G07.1 C0 first", w)
                if k in (10, 20, 30):
                    g1 = k
            elif w.letter in "IJK":
                raise self.error("GC231", f"{w.text or w.letter}: arcs in cylindrical interpolation take R "
                                  "(the radius on the developed surface), not I, J or K", w)
            elif w.letter == "H":
                raise self.error("GC231", f"{w.text or 'H'}: the tool length cannot change in cylindrical "
                                  "interpolation mode", w)
        motion = g1 if g1 is not None else self.motion
        axis_words = [w for w in block.words if w.letter in AXIS_LETTERS]
        if motion == 0 and axis_words and g1 is None:
            raise self.error("GC230", "positioning (modal G00) is not allowed in cylindrical interpolation mode; "
                              "write G01 or cancel the mode with G07.1 C0 first", axis_words[0])
        if motion in (20, 30) and (axis_words or g1 is not None) and not self.unsupported:
            self._arc_block(block, motion, axis_words)
            return
        n0 = len(self.emitted)
        super().execute(block)
        if len(self.emitted) > n0:
            tag = cyl.extra
            for i in range(n0, len(self.emitted)):
                s = self.emitted[i]
                if s.kind is SegmentKind.LINE:
                    self.emitted[i] = replace(s, extra=s.extra + tag)

    def _arc_block(self, block: Block, motion: int, axis_words: list[Word]) -> None:
        cyl = self.cylinder
        assert cyl is not None  # called in cylindrical interpolation mode only
        words: dict[str, Word] = {}
        for w in block.words:
            if w.letter == "G":
                k = gkey(w.value)
                if k in (900, 910):
                    self.absolute = k == 900
                    self.unset.discard("distance")
                elif k in (930, 940, 950):
                    self.feed_mode = k // 10
                    self.unset.discard("feed")
                elif k not in (20, 30):
                    raise self.error("GC230", f"{w.text}: write it in a separate block from the arc", w)
                continue
            if w.letter == "M":
                raise self.error("GC230", f"{w.text}: write M codes in a separate block from an arc in "
                                  "cylindrical interpolation mode", w)
            if w.letter in words:
                raise self.error("GC204", f"two {w.letter} words in one block", w)
            words[w.letter] = w
        for w in axis_words:
            if w.letter not in (cyl.linear, cyl.rotary):
                raise self.error("GC231", f"{w.text}: an arc in cylindrical interpolation moves only "
                                  f"{cyl.linear} and {cyl.rotary} (no helix)", w)
            if w.letter not in self.index:
                raise self.error("GC203", f"axis word {w.text} names an axis this machine does not have", w)
        for letter in words:
            if letter not in "RFNZC" + cyl.linear + cyl.rotary and letter not in "S":
                raise self.error("GC231", f"{words[letter].text}: not allowed with an arc in cylindrical "
                                  "interpolation mode", words[letter])
        if "F" in words:
            if words["F"].value < 0:
                raise self.error("GC209", f"negative feed rate {words['F'].text}", words["F"])
            self.feed = words["F"].value
        self.motion = motion
        rw = words.get("R")
        if rw is None:
            raise self.error("GC231", "an arc in cylindrical interpolation needs R (the radius on the developed "
                              "surface, mm); I, J and K are not allowed", axis_words[0] if axis_words else None)
        self.check_feed()
        self.note_assumed(("units", "distance", "offset"))
        end, _ = self.program_target([(self.index[w.letter], w) for w in axis_words], False)
        r = self.length_mm(rw.value)
        z0, c0 = self.pos[cyl.il], self.pos[cyl.ir]
        z1, c1 = end[cyl.il], end[cyl.ir]
        if r == 0:
            raise self.error("GC330", "zero-radius arc (R0)", rw)
        if z0 == z1 and c0 == c1:
            raise self.error("GC330", "arc whose end point equals its start point: the centre is undefined "
                              "in cylindrical interpolation (R format only)", rw)
        from ..geometry.cylinder import degree_length

        k_mm = degree_length(cyl.radius)
        d = k_mm * (c1 - c0)
        l2 = d.sqr() + (z1 - z0) ** 2
        limit = (abs(r) + self.arc_tolerance) ** 2 * 4
        if l2.lo > limit:
            half = l2.sqrt() / 2
            raise self.error(
                "GC330",
                f"arc radius R{fmt_number(abs(r))} mm is too small to reach the end point on the developed surface: "
                f"half the chord is {fmt_number(half.lo)} mm ({cyl.linear}{fmt_number(z1 - z0)} mm and "
                f"{cyl.rotary}{fmt_number(c1 - c0)} deg = {fmt_number(d.lo)} mm on a cylinder of radius {fmt_number(cyl.radius)} mm; "
                f"tolerance {fmt_number(self.arc_tolerance)} mm)",
                rw,
            )
        if l2.hi > limit:
            raise self.error("GC330", f"arc radius R{fmt_number(abs(r))} mm is within 1e-40 mm of the limit of "
                              "reach; it cannot be decided whether the arc is valid", rw)
        n0 = len(self.emitted)
        self.emit(SegmentKind.DEVELOPED_ARC, end, feed=True, clockwise=motion == 20, radius=r)
        if len(self.emitted) > n0:
            s = self.emitted[-1]
            self.emitted[-1] = replace(s, extra=s.extra + cyl.extra)

