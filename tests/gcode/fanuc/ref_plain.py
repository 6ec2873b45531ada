"""Long plain Fanuc mill programs for the box route's reference differential
(tests/gcode/fanuc/test_reference_boxes.py).

``plain_program(seed, dpi)`` writes a program of more than 512 text lines with no ``#`` and no call (the programs
``pipeline.verification._fanuc_boxes_first`` sends to the box route, ``nczones/prover/fanucboxes.py``), drawn by
a ``random.Random(seed)`` (cheap: Hypothesis draws the seed, the decimal point setting and the size): G00/G01 with
one to three axes, G02/G03 with R (both signs, near half circles included, exact half circles) or the plane's
centre offsets (ends on one circle, whole circles), helices, in G17/G18/G19, G90 and G91, F words, N numbers,
offsets (G54, G55, G54.1 P3), G43 H/G49, inch input in some programs, and lines that end a run of the box run
reader (``nczones/gcode/fanuc/boxrun.py``) in the middle so it hands back and resumes: a comment, G04, M and S
words, a length without a decimal point (read by the decimal point input setting), lines in unusual layouts
(no blanks, tabs, leading blanks, lower case, a blank inside a word, ``X+5.``, a fourth decimal zero, a
trailing comment or ``;``), blank lines, a plane change with a move, CR LF line ends.

The generator tracks the program position (in the work system, program units) so that every R is at least half
its chord and every I/J arc ends on its start's circle: the meaning of every line is fixed by the manual, and the
reference reader (tests/oracles/fanuc_ref.py) reads it.
"""

from __future__ import annotations

import random
from fractions import Fraction

F = Fraction
#: the test mill's work offsets (tests/gcode/fanuc/helpers.py), mm
_WORK = {"G54": (F(100), F(50), F(-200)), "G55": (F(300), F(50), F(-200)), "G54.1 P3": (F(500), F(20), F(-210))}
_PLANES = {17: ("X", "Y", "I", "J"), 18: ("Z", "X", "K", "I"), 19: ("Y", "Z", "J", "K")}
#: integer vectors of equal length, by squared length (an I/J arc's start and end on one circle)
_EQUAL = {25: [(3, 4), (4, 3), (5, 0), (0, 5)], 5: [(1, 2), (2, 1)], 50: [(1, 7), (5, 5), (7, 1)],
          65: [(1, 8), (4, 7), (7, 4), (8, 1)]}
#: lines that end a box run and leave the position where it is
_STILL = ["(A COMMENT)", "G04 P100", "G4 X0.5", "M08", "M09", "S1200 M03", "M05", "M01", "T2 M06", "", "F800.",
          "N77", "G94"]


def _signed(v: tuple[int, int], rnd: random.Random) -> tuple[int, int]:
    a, b = v
    if rnd.random() < 0.5:
        a, b = b, a
    return (a * rnd.choice((1, -1)), b * rnd.choice((1, -1)))


class _Writer:
    """The program being written and the state the generator tracks (program units)."""

    def __init__(self, rnd: random.Random, dpi: str, inch: bool) -> None:
        self.rnd, self.dpi, self.inch = rnd, dpi, inch
        self.step = F(1, 10000) if inch else F(1, 1000)
        self.places = 4 if inch else 3
        self.pos = {"X": F(0), "Y": F(0), "Z": F(0)}
        self.absolute = True
        self.plane = 17
        self.modal = 0  # 0, 1: G00/G01; 2: an arc
        self.work = "G54"
        self.one_run = False  # only lines the box run reader takes (no exact half circle: it ends a run)
        self.lines: list[str] = []

    # ------------------------------------------------------------------------------------------ numbers

    def num(self, v: Fraction) -> str:
        """``v`` (a multiple of the increment) with a decimal point, in a drawn spelling."""
        assert (v / self.step).denominator == 1, v
        sign = "-" if v < 0 else ""
        v = abs(v)
        whole = v.numerator // v.denominator
        digits = str(int((v - whole) / self.step)).rjust(self.places, "0")
        style = self.rnd.random()
        if style < 0.15:
            frac = digits  # all places (trailing zeros)
        else:
            frac = digits.rstrip("0")
        if not frac and style > 0.9:
            frac = "0"
        w = "" if whole == 0 and frac and self.rnd.random() < 0.2 else str(whole)
        return f"{sign}{w}.{frac}"

    def draw(self, lo: int, hi: int) -> Fraction:
        """A multiple of the increment in ``lo``..``hi`` (a tenth of it in inches)."""
        return F(self.rnd.randint(lo * 1000, hi * 1000), 10000 if self.inch else 1000)

    # ------------------------------------------------------------------------------------------ lines

    def word(self, letter: str, target: Fraction) -> str:
        """An axis word moving ``letter`` to ``target`` (program units) in the distance mode."""
        v = target if self.absolute else target - self.pos[letter]
        self.pos[letter] = target
        return f"{letter}{self.num(v)}"

    def g(self, mode: int) -> str:
        if mode < 2 and self.modal < 2 and mode == self.modal and self.rnd.random() < 0.4:
            return ""  # modal
        text = {0: ["G00", "G0"], 1: ["G01", "G1"], 2: ["G02", "G2"], 3: ["G03", "G3"]}[mode]
        return self.rnd.choice(text) + " "

    def n(self) -> str:
        return f"N{self.rnd.randint(1, 9999)} " if self.rnd.random() < 0.15 else ""

    def straight(self) -> None:
        mode = 0 if self.rnd.random() < 0.25 else 1
        letters = self.rnd.sample("XYZ", self.rnd.randint(1, 3))
        words = [self.word(a, self.draw(-40, 40)) for a in "XYZ" if a in letters]
        f = f" F{self.rnd.choice(['300.', '800', '1200.5'])}" if mode == 1 and self.rnd.random() < 0.15 else ""
        self.lines.append(self.n() + self.g(mode) + " ".join(words) + f)
        self.modal = mode

    def r_arc(self, helix: bool) -> None:
        a, b, _la, _lb = _PLANES[self.plane]
        rnd = self.rnd
        if rnd.random() < 0.1 and not self.one_run:  # an exact half circle: a chord of 2|R| along one axis
            half = self.draw(1, 10)
            da, db = (2 * half, F(0)) if rnd.random() < 0.5 else (F(0), 2 * half)
            r = half
        else:
            da, db = self.draw(-15, 15), self.draw(-15, 15)
            if da == db == 0:
                da = self.step * 1000
            l2 = da * da + db * db
            units = int((l2 / (4 * self.step * self.step)) ** 0.5)  # about half the chord, in increments
            r = self.step * (units + rnd.choice([0, 1, 2, 10, 500, 3000, 20000]))
            while 4 * r * r < l2:
                r += self.step
        r = -r if rnd.random() < 0.35 else r
        self._arc(a, b, da, db, f"R{self.num(r)}", helix)

    def centre_arc(self, helix: bool) -> None:
        a, b, la, lb = _PLANES[self.plane]
        rnd = self.rnd
        vectors = _EQUAL[rnd.choice(sorted(_EQUAL))]
        u, w = _signed(rnd.choice(vectors), rnd), _signed(rnd.choice(vectors), rnd)
        if rnd.random() < 0.1:
            w = u  # a whole circle
        scale = self.step * rnd.choice([100, 250, 500, 1000, 1250, 3000])
        ca, cb = -u[0] * scale, -u[1] * scale  # the centre from the start
        da, db = ca + w[0] * scale, cb + w[1] * scale
        offs = [f"{la}{self.num(ca)}" if ca or rnd.random() < 0.3 else "",
                f"{lb}{self.num(cb)}" if cb or rnd.random() < 0.3 else ""]
        centre = " ".join(o for o in offs if o) or f"{la}{self.num(F(0))}"
        self._arc(a, b, da, db, centre, helix)

    def _arc(self, a: str, b: str, da: Fraction, db: Fraction, centre: str, helix: bool) -> None:
        rnd = self.rnd
        mode = 2 if rnd.random() < 0.5 else 3
        words = [self.word(a, self.pos[a] + da), self.word(b, self.pos[b] + db)]
        if helix:
            other = ({"X", "Y", "Z"} - {a, b}).pop()
            words.append(self.word(other, self.pos[other] + self.draw(-5, 5)))
        elif (da == 0) != (db == 0) and rnd.random() < 0.5:
            words.pop(0 if da == 0 else 1)  # the axis that does not move, not written
        f = " F400." if rnd.random() < 0.1 else ""
        self.lines.append(self.n() + self.g(mode) + " ".join(words) + f" {centre}{f}")
        self.modal = 2

    def distance(self) -> None:
        self.absolute = not self.absolute
        self.lines.append("G90" if self.absolute else "G91")

    def plane_change(self) -> None:
        self.plane = self.rnd.choice([17, 18, 19])
        if self.rnd.random() < 0.5:
            self.lines.append(f"G{self.plane}")
        else:  # with a straight move in the same block (the box run reader hands the line back)
            self.modal = 1
            a = _PLANES[self.plane][0]
            self.lines.append(f"G{self.plane} G01 {self.word(a, self.draw(-30, 30))}")

    def resync(self) -> None:
        """A move naming every axis in G90 (after the work system or the tool length changed)."""
        self.absolute = True
        self.modal = 0
        words = " ".join(self.word(a, self.draw(-30, 30)) for a in "XYZ")
        self.lines.append(f"G90 G00 {words}")

    def offsets(self) -> None:
        rnd = self.rnd
        kind = rnd.random()
        if kind < 0.5:
            self.work = rnd.choice(sorted(_WORK))
            self.lines.append(self.work)
        elif kind < 0.8:
            self.lines.append(f"G43 H{rnd.choice([1, 2])}")
        else:
            self.lines.append("G49")
        self.resync()

    def still(self) -> None:
        self.lines.append(self.rnd.choice(_STILL))

    def no_point(self) -> None:
        """A length without a decimal point: millimetres (or inches) in the pocket calculator setting, least
        increments in the other."""
        n = self.rnd.randint(-30, 30)
        v = F(n) if self.dpi == "calculator" else n * self.step
        self.modal = 1
        letter = self.rnd.choice("XYZ")
        target = v if self.absolute else self.pos[letter] + v
        self.pos[letter] = target
        self.lines.append(f"G01 {letter}{n}")

    def layout(self) -> None:
        """A straight move in an unusual layout (each read alike by the control)."""
        rnd = self.rnd
        self.modal = 1
        x, y = self.draw(-30, 30), self.draw(-30, 30)
        xs, ys = self.word("X", x), self.word("Y", y)
        forms = [f"G1{xs}{ys}", f"  G1 {xs} {ys}", f"G1\t{xs}\t{ys}", f"g1 {xs.lower()} {ys.lower()}",
                 f"G1 X {xs[1:]} {ys}", f"G1 {xs} {ys} (TRAILING)", f"G1 {xs} {ys} ;", f"N10G1{xs} {ys}",
                 f"G01  {xs}  {ys}  "]
        if not xs.startswith("X-"):
            forms.append(f"G1 X+{xs[1:]} {ys}")
        self.lines.append(rnd.choice(forms))


#: line kinds and their weights
_KINDS = (("straight", 34), ("r_arc", 16), ("centre_arc", 14), ("helix_r", 3), ("helix_centre", 2),
          ("distance", 3), ("plane_change", 3), ("offsets", 2), ("still", 6), ("no_point", 3), ("layout", 4))


#: the kinds a box run reader takes in the first plane, metric, G90 (one run past ``columns.MAX_ROWS`` lines)
_RUN_KINDS = (("straight", 50), ("r_arc", 25), ("centre_arc", 20), ("helix_r", 3), ("helix_centre", 2))


def plain_program(seed: int, dpi: str, lines: int = 540, *, one_run: bool = False) -> str:
    """A plain Fanuc mill program of more than ``lines`` text lines (module docstring); ``one_run``: only lines
    the box run reader takes (metric, G17, G90: straight moves, arcs, helices), one run as long as the program."""
    rnd = random.Random(seed)
    inch = rnd.random() < 0.15 and not one_run
    w = _Writer(rnd, dpi, inch)
    w.one_run = one_run
    w.lines += ["%", "O0001", "G20" if inch else "G21", "G90 G17 G40 G49 G80 G94 G54 F500."]
    w.resync()
    kinds = _RUN_KINDS if one_run else _KINDS
    names = [k for k, _ in kinds]
    weights = [n for _, n in kinds]
    while len(w.lines) < lines:
        kind = rnd.choices(names, weights)[0]
        if kind == "helix_r":
            w.r_arc(True)
        elif kind == "helix_centre":
            w.centre_arc(True)
        elif kind in ("r_arc", "centre_arc"):
            getattr(w, kind)(False)
        else:
            getattr(w, kind)()
    w.lines += ["M30", "%"]
    end = "\r\n" if rnd.random() < 0.1 and not one_run else "\n"
    return end.join(w.lines) + end
