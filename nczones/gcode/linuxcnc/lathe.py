"""LinuxCNC lathe programs: diameter mode (G7/G8) and the G70-G72 cycles with their profile subroutines.

LinuxCNC reads every X word as a diameter while G7 is active (``Interp::read_x`` halves it; G7 in a block
halves that block's X, ``convert_lathe_diameter_mode``); I and K stay radii.  A machine file with
``diameter_axes = ["X"]`` starts in G7, as a LinuxCNC lathe whose ``RS274NGC_STARTUP_CODE`` holds G7.

The cycles G70, G71 (.1 .2) and G72 (.1 .2) read their profile from the subroutine named by Q (the language
layer collects its blocks into a :class:`~nczones.gcode.blocks.ShapeBlock`); :mod:`nczones.gcode.linuxcnc.g7x`
generates the passes as LinuxCNC's ``interp_g7x.cc`` does, and every pass becomes an ordinary rapid, line
or arc segment with the cycle block's span and a note naming the pass (``G71 roughing pass 3: cut``).
What the model cannot follow is ``unknown`` with a reason (``specs/turning.md``, "LinuxCNC G70-G72").
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from typing import Any

from ...machine import Machine
from ...motion import Plane, SegmentKind
from ..blocks import Block, ShapeBlock, Word
from ..interpreter import INCH, Interpreter, dadd, gkey, qadd
from ..mentions import uses_lathe
from ..passes import PassBound
from . import g7x

__all__ = ["LatheInterpreter", "uses_lathe"]

_G7X_KEYS = {700: (70, 0), 710: (71, 0), 711: (71, 1), 712: (71, 2), 720: (72, 0), 721: (72, 1), 722: (72, 2)}
#: Words the cycle block gives the cycle (the rest run as in any block, before the cycle).
_CYCLE_LETTERS = frozenset("XZQDEIPRUWK")
#: Words a profile block may hold: the motion, the end point, the centre or radius, corners; F S T M N are read
#: and ignored (LinuxCNC only reads the profile's blocks, it does not execute them).
_PROFILE_LETTERS = frozenset("GXZUWIKRACFSTMN")


class LatheInterpreter(Interpreter):
    """The LinuxCNC interpreter with lathe diameter mode and the G70-G72 cycles.

    >>> from nczones.machine import parse_machine
    >>> from nczones.gcode import segments_text
    >>> m = parse_machine('[machine]\\naxes = ["X", "Z"]\\ndiameter_axes = ["X"]\\n[machine.rapid]\\nX = "1000"\\n'
    ...                   'Z = "1000"\\n[machine.reference]\\nX = "100"\\nZ = "100"\\n')
    >>> segs = segments_text("G18 G21 G0 X40 Z2\\nG8 G0 X40\\nG7 X10\\n", m)
    >>> [[str(v) for v in s.end] for s in segs]
    [['20', '2'], ['40', '2'], ['5', '2']]
    """

    def __init__(self, machine: Machine, **kwargs: Any):
        super().__init__(machine, **kwargs)
        #: G7 (X words are diameters) or G8
        self.diameter_mode = "X" in machine.diameter_axes

    def execute(self, block: Block) -> None:
        if self.m73_saved:
            self.m73_returns()
        block = self._diameter_words(block)
        cycle = next(((k, w) for w in block.words if w.letter == "G" and (k := gkey(w.value)) in _G7X_KEYS), None)
        if cycle is None:
            self._execute_general(block)
        else:
            self._g7x_block(block, cycle[0], cycle[1])

    # ------------------------------------------------------------------ G7 / G8
    def _diameter_words(self, block: Block) -> Block:
        """The block with G7/G8 acted on (and taken out) and its X word halved in diameter mode."""
        words = block.words
        modes = [w for w in words if w.letter == "G" and gkey(w.value) in (70, 80)]
        if modes:
            if len(modes) > 1:
                raise self.error("GC201", "G7 and G8 are in the same modal group; a block may contain only one of "
                                  "them", modes[1])
            if any(w.letter == "M" and w.value in (70, 72, 73) for w in words):
                # LinuxCNC saves/restores (convert_m) before it runs G7/G8 (convert_g), but reads the block's X
                # with the mode from before: not followed
                self.unknown("G7/G8", "G7 or G8 in a block with M70, M72 or M73 is not modelled; write them in "
                             "separate blocks", modes[0])
            self.diameter_mode = gkey(modes[0].value) == 70
            self.invalidate_frame()
            words = tuple(w for w in words if w is not modes[0])
        if self.diameter_mode and any(w.letter == "X" for w in words):
            words = tuple(replace(w, value=w.value / 2) if w.letter == "X" else w for w in words)
        if words is block.words:
            return block
        if isinstance(block, ShapeBlock):
            return ShapeBlock(words, block.span, block.index, block.number, block.messages, block.shape)
        return Block(words, block.span, block.index, block.number, block.messages)

    # ------------------------------------------------------------------ G70-G72
    def _g7x_block(self, block: Block, key: int, gw: Word) -> None:
        code, sub = _G7X_KEYS[key]
        name = f"G{code}" + (f".{sub}" if sub else "")
        words, rest = self._cycle_words(block, gw, name)
        for w in rest:
            if w.letter not in "GMFSTN" or (w.letter == "G" and gkey(w.value) in (0, 10, 20, 30, 280, 300, 920, 100,
                                                                                    520, 530, 800)):
                raise self.error("GC205", f"{w.text or w.letter} in the block of the lathe cycle {name}: write it in "
                                  "a block of its own", w)
        if rest:  # F, S, T, M and modal G codes act first (LinuxCNC's order of execution: motion comes late)
            self._execute_general(Block(tuple(rest), block.span, block.index, block.number, block.messages))
        if self.unsupported or self.ended:
            return
        if "Q" not in words:
            raise self.error("GC208", f"{name} needs a Q word: the number of the profile's subroutine", gw)
        if not isinstance(block, ShapeBlock):
            self.unknown(name, f"{name}: the profile subroutine was not collected (the cycle block is built by a "
                          "path of the language layer that does not read profiles, e.g. a line with parameters)", gw)
            return
        if any(k in words for k in "UW"):
            self.unknown(name, f"{name}: U or W in the cycle's block on a machine with that axis: LinuxCNC's rapid "
                          "to the start point moves the axis as well as taking it as the allowance (not modelled)",
                          words.get("U") or words["W"])
            return
        if self.plane is not Plane.XZ:
            raise self.error("GC308", f"{name} can only be used in the XZ plane (G18) (LinuxCNC's error)", gw)
        iz, ix = self.index.get("Z"), self.index.get("X")
        if iz is None or ix is None:
            raise self.error("GC308", f"a lathe cycle needs axes X and Z; this machine has {', '.join(self.axes)}",
                              gw)
        if self.comp_on or (self._comp is not None and self._comp.side is not None):
            self.unknown(name, f"{name} with cutter compensation on is not modelled", gw)
            return
        if self.prerotation_xy is not None:
            self.unknown(name, f"{name} in a rotated coordinate system (G10 L2 R) is not modelled", gw)
            return
        self.note_assumed(("units", "distance", "offset"))
        # the rapid to X Z (the cycle's start point; absent words: where the tool is)
        axis = [(i, words[a]) for a, i in (("X", ix), ("Z", iz)) if a in words]
        if axis:
            end, deps = self.program_target(axis, False)
            self.emit(SegmentKind.RAPID, end, derived=f"{name} to the start point", end_deps=deps)
        self.motion = 0
        if self.track:
            ranged = getattr(self, "ranged", None)
            for i in (iz, ix):
                d = dadd(self.dep_pos[i], self.dep_off[i], -1)
                names = sorted(k for k in d if ranged is None or f"{k}.{self.axes[i]}" in ranged or k in ranged)
                if names:
                    self.unknown("parameter range", f"{name}: the cycle's start point in the workpiece coordinate "
                                  f"system depends on {', '.join(f'{k}.{self.axes[i]}' for k in names)}: the "
                                  "number and places of its passes would depend on it", gw)
                    return
        unit = INCH if self.inch else Fraction(1)
        x0 = (self.pos[ix] - self.off[ix]) / unit
        z0 = (self.pos[iz] - self.off[iz]) / unit
        pieces = self._profile(name, block.shape, complex(float(z0), float(x0)), gw)
        if pieces is None:
            return
        start = complex(float(z0), float(x0))
        if len(pieces) <= 1:  # LinuxCNC: a profile of one piece or none does nothing more
            self._no_move(name, pieces, start, gw)
            return
        moves = self._cycle_moves(name, code, sub, pieces, start, words, gw)
        if moves is not None:
            self._emit_g7x(name, moves, iz, ix, unit)

    def _cycle_moves(self, name: str, code: int, sub: int, pieces: list[g7x.Piece], start: complex,
                     words: dict[str, Word], gw: Word) -> list[g7x.Out] | None:
        """The cycle's moves; None (after an unknown) where nczones does not follow LinuxCNC."""
        fl = {k: float(words[k].value) for k in "DEIRUW" if k in words}
        p = float(words["P"].value) if "P" in words else 1.0  # G70's P, a double (interp_g7x.cc)
        if fl.get("I", 1.0) <= 0:
            raise self.error("GC209", f"{name}: I must be greater than zero (LinuxCNC's error)", words["I"])
        moves: list[g7x.Out] | None
        try:
            if code == 70:  # (P below 1: no pass, as LinuxCNC 2.9's loop; no error)
                moves = g7x.g70(pieces, start, x=start.imag, z=start.real, d=fl.get("D", 0.0), e=fl.get("E", 0.0),
                                passes=p, guard=self.pass_guard(name))
            else:
                moves = self._roughing(name, pieces, start, sub, code == 72, fl, gw)
        except PassBound as e:
            self.unknown(e.code, e.reason, gw)
            return None
        except g7x.G7xError as e:
            self.unknown(name, f"{name}: LinuxCNC stops this cycle with an error or its result is not defined: {e}",
                          gw)
            return None
        if moves is not None and not moves:
            self._no_move(name, pieces, start, gw)
            return None
        return moves

    def _no_move(self, name: str, pieces: list[g7x.Piece], start: complex, gw: Word) -> None:
        """A cycle that makes no move (G70 with P below 1, a profile of one piece): LinuxCNC 2.9.0~pre1 leaves its
        position where reading the profile ended (its end), where the tool is not; the next block's absent axis
        words take that position.  Later versions (commit b1f3e7d8) restore the start.  Unknown when the two
        differ."""
        if pieces and pieces[-1].end != start:
            self.unknown(name, f"{name} makes no move here, and LinuxCNC 2.9.0~pre1 then takes the profile's end as "
                          "its position (later versions the start): the next move depends on the version", gw)

    def _cycle_words(self, block: Block, gw: Word, name: str) -> tuple[dict[str, Word], list[Word]]:
        """The cycle's own words by letter and the block's other words.  LinuxCNC reads the cycle's block as any
        block: U or W of an axis the machine lacks is refused ("Bad character 'u' used"); only the profile's
        blocks read U, W, A, C whatever the axes (interp_g7x.cc switch_settings)."""
        words: dict[str, Word] = {}
        rest: list[Word] = []
        for w in block.words:
            if w.letter in "UW" and w.letter not in self.index:
                raise self.error("GC203", f"axis word {w.text or w.letter} names axis {w.letter}, which this machine "
                                  f"does not have (axes: {', '.join(self.axes)}): LinuxCNC refuses it in the block of "
                                  f"{name} too (its error: Bad character '{w.letter.lower()}' used)", w)
            if w.letter in _CYCLE_LETTERS:
                if w.letter in words:
                    raise self.error("GC204", f"two {w.letter} words in one block ({words[w.letter].text} and "
                                      f"{w.text}); a letter may appear once", w)
                words[w.letter] = w
            elif w is not gw:
                rest.append(w)
        return words, rest

    def _roughing(self, name: str, pieces: list[g7x.Piece], start: complex, sub: int, facing: bool,
                  fl: dict[str, float], gw: Word) -> list[g7x.Out] | None:
        """G71/G72's moves as the installed LinuxCNC 2.9.0~pre1 makes them, when the 2.9 versions after it make the
        same; None (after an unknown) where they differ: the machine's version decides, the program does not say."""
        kw = dict(cycle=sub, x=start.imag, z=start.real, u=fl.get("U", 0.0), w=fl.get("W", 0.0), d=fl.get("D", 0.0),
                  i=fl.get("I", 1.0), r=fl.get("R", 0.5), facing=facing)
        moves = g7x.g71(pieces, start, guard=self.pass_guard(name), **kw)  # type: ignore[arg-type]
        try:
            later = g7x.g71(pieces, start, later=True, **kw)  # type: ignore[arg-type]
        except g7x.G7xError:
            later = None
        if later != moves:
            self.unknown(name, f"{name}: LinuxCNC 2.9.0~pre1 (the reference nczones follows) and the later 2.9 "
                          "versions cut this profile differently (the closing straight and pocket loop of "
                          "interp_g7x.cc changed after 2.9.0~pre1): the machine's version decides", gw)
            return None
        return moves

    def _profile(self, name: str, shape: tuple[Block, ...], start: complex, gw: Word) -> list[g7x.Piece] | None:
        """The profile's pieces as ``convert_g7x`` reads them: the first from the cycle's start point; X halved in
        diameter mode (U too), I and K radii, I/K relative to the block's start in G91.1; A rounds and C chamfers
        the corner at a block's end.  None (after an unknown) when a block is beyond the model."""
        pieces: list[g7x.Piece] = []
        motion = 0  # convert_g7x's rapid to the start point sets G0
        incremental = not self.absolute
        at = start
        for b in shape:
            read = self._profile_words(name, b, gw, motion)
            if read is None:
                return None
            ws, motion = read
            end = complex(0.0, 0.0) if incremental else at
            if "U" in ws:
                if incremental:
                    raise self.error("GC204", f"{name}: U cannot be used in incremental mode (G91) (LinuxCNC's "
                                      "error)", ws["U"])
                if "X" in ws:
                    raise self.error("GC204", f"{name}: U and X in the same profile block", ws["U"])
                u = float(ws["U"].value) / (2.0 if self.diameter_mode else 1.0)
                end = complex(end.real, end.imag + u)
            elif "X" in ws:
                xv = ws["X"].value / 2 if self.diameter_mode else ws["X"].value
                end = complex(end.real, float(xv))
            if "W" in ws:
                if incremental:
                    raise self.error("GC204", f"{name}: W cannot be used in incremental mode (G91) (LinuxCNC's "
                                      "error)", ws["W"])
                if "Z" in ws:
                    raise self.error("GC204", f"{name}: W and Z in the same profile block", ws["W"])
                end = complex(end.real + float(ws["W"].value), end.imag)
            elif "Z" in ws:
                end = complex(float(ws["Z"].value), end.imag)
            if incremental:
                end = end + at
            if end == at:
                continue
            if motion in (0, 10):
                pieces.append(g7x.Straight(at, end))
            else:
                centre = self._profile_centre(name, ws, at, end, motion, gw)
                if centre is None:
                    return None
                pieces.append(g7x.Round(motion == 30, at, centre, end))
            if "A" in ws and "C" in ws:
                raise self.error("GC204", f"{name}: both A and C on a corner of the profile (LinuxCNC's error)",
                                  ws["C"])
            if "A" in ws:
                pieces.append(g7x.Fillet(float(ws["A"].value), end))
            if "C" in ws:
                pieces.append(g7x.Chamfer(float(ws["C"].value), end))
            at = end
        self.motion = motion  # convert_g7x leaves the profile's motion mode active (its moves then set theirs)
        return pieces

    def _profile_words(self, name: str, b: Block, gw: Word, motion: int) -> tuple[dict[str, Word], int] | None:
        """A profile block's words by letter and the motion mode after it; None (after an unknown) for a word
        or code beyond the model."""
        ws: dict[str, Word] = {}
        for w in b.words:
            if w.letter not in _PROFILE_LETTERS:
                self.unknown(name, f"{name}: the word {w.text or w.letter} in the profile (line {w.span.line}) "
                              "is not modelled", gw)
                return None
            if w.letter == "G":
                k = gkey(w.value)
                if k in (900, 910, 901, 911):
                    # G90/G91/G90.1/G91.1: convert_g7x reads the profile's blocks without executing them and
                    # takes the distance modes in force at the cycle (switch_settings): no effect
                    continue
                if k not in (0, 10, 20, 30):
                    self.unknown(name, f"{name}: {w.text or 'G'} in the profile (line {w.span.line}): only G0 "
                                  "G1 G2 G3 are modelled there (LinuxCNC ignores other codes of a profile block)", gw)
                    return None
                motion = k
                continue
            if w.letter in ws:
                raise self.error("GC204", f"two {w.letter} words in one block of the profile", w)
            ws[w.letter] = w
        return ws, motion

    def _profile_centre(self, name: str, ws: dict[str, Word], at: complex, end: complex, motion: int,
                        gw: Word) -> complex | None:
        if "R" in ws:
            if "I" in ws or "K" in ws:
                raise self.error("GC204", f"{name}: both R and I or K on an arc of the profile", ws["R"])
            r = float(ws["R"].value)
            chord = end - at
            n = chord.real * chord.real + chord.imag * chord.imag
            q = (r * r - n / 4) / n
            if q < 0:
                # interp_g7x.cc takes the square root of the negative number without a check: a NaN centre, and
                # LinuxCNC goes on reading the profile (rs274 2.9.0~pre1 runs or stops later): not followed
                self.unknown(name, f"{name}: the arc's radius {ws['R'].text} is too small to reach its end point; "
                              "LinuxCNC computes no centre for it (NaN) and does not stop there", ws["R"])
                return None
            centre = (at + end) / 2.0
            s = q ** 0.5
            d = complex(0.0 * s, 1.0 * s) * chord
            return centre + d if motion == 30 else centre - d
        if "I" not in ws and "K" not in ws:
            raise self.error("GC208", f"{name}: either I or K must be present for an arc of the profile (LinuxCNC's "
                             "error, on this line)", next(iter(ws.values()), None))
        ci = float(ws["I"].value) if "I" in ws else 0.0
        ck = float(ws["K"].value) if "K" in ws else 0.0
        centre = complex(ck, ci) if self.arc_absolute else complex(ck, ci) + at
        r0, r1 = abs(at - centre), abs(end - centre)
        tol = 0.0002 if self.inch else 0.002  # LinuxCNC's RADIUS_TOLERANCE_INCH / _MM (arc_data_ijk)
        if abs(r0 - r1) > tol and abs(r0 - r1) > 0.001 * max(r0, r1):
            # 2.9.0~pre1 takes the arc as written (no check); LinuxCNC after it refuses it (arc_data_ijk, commit
            # b2d2c2d1): the version decides, and the moves of an arc off its circle are not modelled
            self.unknown(name, f"{name}: an arc of the profile ends off its circle (radius {r0:.6g} at its start, "
                          f"{r1:.6g} at its end): LinuxCNC 2.9.0~pre1 cuts it unchecked, later versions refuse it",
                          ws.get("I") or ws.get("K") or gw)
            return None
        return centre

    def _emit_g7x(self, name: str, moves: list[g7x.Out], iz: int, ix: int, unit: Fraction) -> None:
        """The generated moves (program units, Z + X i, doubles taken exactly) as segments of the cycle block."""
        motion = self.motion
        for m in moves:
            end = list(self.pos)
            end[iz] = qadd(Fraction(m.end.real) * unit, self.off[iz])
            end[ix] = qadd(Fraction(m.end.imag) * unit, self.off[ix])
            deps = None
            if self.track:
                deps = [dict(d) for d in self.dep_pos]
                deps[iz] = dict(self.dep_off[iz])
                deps[ix] = dict(self.dep_off[ix])
            derived = f"{name} {m.label}"
            if m.kind == "rapid":
                self.emit(SegmentKind.RAPID, end, derived=derived, end_deps=deps)
                motion = 0
            elif m.kind == "feed":
                self.check_feed()
                self.emit(SegmentKind.LINE, end, feed=True, derived=derived, end_deps=deps)
                motion = 10
            else:
                assert m.centre is not None
                self.check_feed()
                centre = (qadd(Fraction(m.centre.real) * unit, self.off[iz]),
                          qadd(Fraction(m.centre.imag) * unit, self.off[ix]))
                self.emit(SegmentKind.ARC, end, feed=True, plane=Plane.XZ, clockwise=not m.ccw, centre=centre,
                           derived=derived, end_deps=deps)
                motion = 30 if m.ccw else 20
        self.motion = motion  # LinuxCNC: the motion mode of the cycle's last move stays active
