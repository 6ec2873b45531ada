"""Arc programs of more than 512 lines for the rs274 differential of the LinuxCNC double pass.

:class:`ArcWriter` draws a plain LinuxCNC program (no ``#``, no o-word: routed to the double pass,
``nczones.pipeline.verification._small_plain``) of G2/G3 arcs in R form (positive and negative R, near-half
circles, R exactly half the chord, R slightly too small for the chord, tiny and huge R) and I/J form (exact
circles, spirals inside and beyond LinuxCNC's radius rule, whole turns without axis words, an end on the
start's ray at the start's radius or off it), helices (a Z word), straight moves, work offsets G54-G59 and
``G43 H``/``G49``; with ``outside`` also constructs the pass declined (G91, G20, G18, G90.1, a P word: G20, G91 and
a second plane it takes since units39 and arc40).

Its *designed* arcs (``rational=True``) have a rational centre and radius (Pythagorean directions), so their
extremes are exact: :meth:`ArcWriter.extreme` is the largest value of ``sign * axis`` over the whole path in
machine millimetres, where the face tests put a zone face.  Coordinates are decimals of at most four places
(rs274 prints four): no rounding anywhere in the text.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction

F0 = Fraction(0)
INCH = Fraction(254, 10)
#: Unit vectors with rational components, and the denominator of each (components times it are integers).
_TRIPLES = ((3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25))
DIRECTIONS: tuple[tuple[Fraction, Fraction, int], ...] = tuple(sorted(
    {(Fraction(sx * a, c), Fraction(sy * b, c), c) for a, b, c in _TRIPLES for a, b in ((a, b), (b, a))
     for sx in (1, -1) for sy in (1, -1)}
    | {(Fraction(x), Fraction(y), 1) for x, y in ((1, 0), (0, 1), (-1, 0), (0, -1))}))
_AXES = ((1, 0), (0, 1), (-1, 0), (0, -1))
#: Arcs the pass takes (the first three rational), arcs it declines (the full path decides), arcs LinuxCNC
#: refuses or may refuse (one a program at most, near its end).
TAKEN = ("r_pyth", "ij_circle", "ij_turn", "r_pyth", "ij_circle", "r_big", "ij_spiral", "r_near_half", "r_tiny")
DECLINED = ("ij_ray_start", "ij_ray_spiral", "r_half")
RISKY = ("r_short", "ij_spiral_far", "ij_zero")
#: rs274's tool table (inches) and the work offsets of its parameter file (inches): tests.tools.rs274_diff's setup
TOOLS_INCH = {1: Fraction(1, 10), 2: Fraction(-3, 100), 3: Fraction(25, 10)}
OFFSETS_INCH = {"G55": {"X": Fraction(5, 10), "Y": Fraction(-3, 10), "Z": Fraction(1, 10)},
                "G56": {"X": Fraction(-12345, 10000), "Y": Fraction(2, 1)},
                "G59": {"X": Fraction(7, 1000), "Y": Fraction(-7, 1000), "Z": Fraction(-2, 1)}}
SETUP = (("X", "Y", "Z"), TOOLS_INCH, OFFSETS_INCH)


def dec(v: Fraction) -> str:
    """``v`` as exact decimal text (its denominator divides a power of ten)."""
    sign, v = ("-" if v < 0 else ""), abs(v)
    for places in range(0, 25):
        scaled = v * 10**places
        if scaled.denominator == 1:
            n = scaled.numerator
            if places == 0:
                return f"{sign}{n}" if n else "0"
            return f"{sign}{n // 10**places}.{n % 10**places:0{places}d}"
    raise ValueError(f"{v} is not a short decimal")


#: Per plane: the program's letters of G17 (first, second, normal axis; the two centre words) to the plane's.
_IN_PLANE = {18: str.maketrans("XYZIJ", "ZXYKI"), 19: str.maketrans("XYZIJ", "YZXJK")}


def in_plane(line: str, plane: int) -> str:
    """A line of :func:`arcs` moved to ``plane``: its axis and centre words to the plane's (G18: the first axis
    Z, the second X, the centre words K and I; G19: Y, Z, J, K), a G17 to the plane's code and a G18 (a plane
    other than the program's) to another one."""
    other = {18: "G19", 19: "G17"}[plane]
    line = line.replace("G18", "G_OTHER").replace("G17", f"G{plane}")
    head, _, rest = line.partition(" ") if line.startswith("G") else ("", "", line)
    # (lower-case names #<a> and codes are untouched; a leading G code keeps its digits)
    words = " ".join(w if w.startswith(("G", "#")) else w.translate(_IN_PLANE[plane]) for w in rest.split(" "))
    return f"{head} {words}".strip().replace("G_OTHER", other)


@dataclass(frozen=True, slots=True)
class Circle:
    """An arc of a rational circle in machine mm: centre, radius, the unit vectors from the centre to its
    ends, its direction; ``full`` a whole turn (its end on the start's ray)."""

    cx: Fraction
    cy: Fraction
    r: Fraction
    start: tuple[Fraction, Fraction]
    end: tuple[Fraction, Fraction]
    cw: bool
    full: bool = False

    def extreme(self, axis: int, sign: int) -> Fraction:
        """The largest ``sign * coordinate`` of the arc on ``axis`` (0: X, 1: Y), exactly."""
        target = (sign, 0) if axis == 0 else (0, sign)
        c = (self.cx, self.cy)[axis]
        ends = max(sign * (c + self.r * self.start[axis]), sign * (c + self.r * self.end[axis]))
        return sign * c + self.r if self._sweeps(target) else ends

    def _sweeps(self, d: tuple[int, int]) -> bool:
        if self.full:
            return True
        a = math.atan2(float(self.start[1]), float(self.start[0]))
        b = math.atan2(float(self.end[1]), float(self.end[0]))
        t = math.atan2(d[1], d[0])
        if self.cw:
            a, b = b, a
        sweep = (b - a) % math.tau
        # the vectors are exact: a direction equal to an end is at that end (its extreme the end's)
        return (t - a) % math.tau <= sweep + 1e-12


@dataclass(slots=True)
class ArcWriter:
    """One drawn program (see the module's docstring)."""

    rng: random.Random
    outside: bool = False
    rational: bool = False
    #: the arc kinds drawn, when given (no declined or refused kind then); else TAKEN (its first three if rational)
    menu: tuple[str, ...] = ()
    lines: list[str] = field(default_factory=list)
    #: the program position (program units, X Y Z), the units (mm per unit), the work offset, the tool length
    pos: list[Fraction] = field(default_factory=lambda: [F0, F0, F0])
    unit: Fraction = Fraction(1)
    wcs: str = "G54"
    tool: Fraction = F0
    circles: list[Circle] = field(default_factory=list)
    points: list[tuple[Fraction, Fraction]] = field(default_factory=list)
    #: the kinds of arcs written (tests check the draw reaches them)
    kinds: set[str] = field(default_factory=set)
    #: the plane of the program (17, 18, 19): drawn in G17 and written in the plane (:func:`in_plane`: the
    #: circles' and points' (x, y) are then the plane's (first, second) axes); outside G17 a ``rational``
    #: program keeps G54 and no tool length (whose axis Z is a plane axis there: the circles would be off by it)
    plane: int = 17

    # -- positions ---------------------------------------------------------------------------------------
    def machine(self, x: Fraction, y: Fraction) -> tuple[Fraction, Fraction]:
        off = OFFSETS_INCH.get(self.wcs, {})
        return (x * self.unit + off.get("X", F0) * INCH, y * self.unit + off.get("Y", F0) * INCH)

    def coordinate(self, lo: int = -40, hi: int = 40) -> Fraction:
        return Fraction(self.rng.randint(lo * 1000, hi * 1000), 1000)

    def move(self, code: str, x: Fraction, y: Fraction, z: Fraction | None = None) -> None:
        words = f"{code} X{dec(x)} Y{dec(y)}" + (f" Z{dec(z)}" if z is not None else "")
        self.lines.append(words)
        self.pos[0], self.pos[1] = x, y
        if z is not None:
            self.pos[2] = z
        self.points.append(self.machine(x, y))

    def fresh(self) -> None:
        """A G0 to a fresh point (after the position's program coordinates changed)."""
        self.move("G0", self.coordinate(), self.coordinate(), self.coordinate(-5, 5))

    # -- blocks ------------------------------------------------------------------------------------------
    def modal(self) -> None:
        r = self.rng
        roll = r.randrange(3) if self.plane == 17 or not self.rational else -1
        if roll == 0:
            self.wcs = r.choice(["G54", "G55", "G56", "G59"])
            self.lines.append(self.wcs)
        elif roll == 1:
            n = r.choice(sorted(TOOLS_INCH))
            self.tool = TOOLS_INCH[n] * INCH
            self.lines.append(f"G43 H{n}")
        elif roll == 2:
            self.tool = F0
            self.lines.append("G49")
        self.fresh()

    def straight(self) -> None:
        self.move("G1", self.coordinate(), self.coordinate(), self.rng.choice([None, self.coordinate(-5, 5)]))

    def arc(self, kind: str | None = None) -> None:
        """An arc the double pass takes (its kinds in :data:`TAKEN`), or one of ``kind``."""
        if kind is None:
            kind = self.rng.choice(self.menu or (TAKEN[:3] if self.rational else TAKEN))
        self.kinds.add(kind)
        getattr(self, "_" + kind)()

    # -- R arcs ------------------------------------------------------------------------------------------
    def _r_word(self, code: str, ex: Fraction, ey: Fraction, radius: Fraction, helix: bool = True) -> None:
        z = self.coordinate(-5, 5) if helix and self.rng.random() < 0.2 else None
        self.move(code, ex, ey, z)
        self.lines[-1] += f" R{dec(radius)}"

    def _r_pyth(self) -> None:
        """A Pythagorean R arc: its centre and radius rational."""
        r = self.rng
        ux, uy, q = r.choice(DIRECTIONS)
        leg_a, leg_h, hyp = r.choice(_TRIPLES)
        if r.random() < 0.5:
            leg_a, leg_h = leg_h, leg_a
        t = q * Fraction(r.choice([1, 10, 100, 1000, 5000, 20000]), 10000)
        a, h, big = leg_a * t, leg_h * t, hyp * t
        code, negative = r.choice(["G2", "G3"]), r.random() < 0.5
        sx, sy = self.pos[0], self.pos[1]
        ex, ey = sx + 2 * a * ux, sy + 2 * a * uy
        # the centre left of the chord (normal (-uy, ux)) for G3 with R > 0 and G2 with R < 0
        side = 1 if (code == "G3") != negative else -1
        cx, cy = sx + a * ux - side * h * uy, sy + a * uy + side * h * ux
        mcx, mcy = self.machine(cx, cy)
        self.circles.append(Circle(mcx, mcy, big * self.unit, ((sx - cx) / big, (sy - cy) / big),
                                   ((ex - cx) / big, (ey - cy) / big), code == "G2"))
        self._r_word(code, ex, ey, -big if negative else big)

    def _chord(self, scale: list[int]) -> tuple[Fraction, Fraction, Fraction]:
        """An axis-aligned half chord ``a`` (a decimal) and the end it reaches."""
        r = self.rng
        a = Fraction(r.choice(scale), 10000)
        ux, uy = r.choice(_AXES)
        return a, self.pos[0] + 2 * a * ux, self.pos[1] + 2 * a * uy

    def _r_near_half(self) -> None:
        a, ex, ey = self._chord([1234, 50000, 5])
        delta = Fraction(self.rng.choice([1, 10, 1000]), 10**8)  # 1e-8 .. 1e-5 mm longer than half the chord
        self._r_word(self.rng.choice(["G2", "G3"]), ex, ey, self.rng.choice([1, -1]) * (a + delta))

    def _r_half(self) -> None:
        a, ex, ey = self._chord([1234, 50000, 5])
        self._r_word(self.rng.choice(["G2", "G3"]), ex, ey, self.rng.choice([1, -1]) * a)

    def _r_short(self) -> None:
        """R slightly too small for the chord: around LinuxCNC's radius tolerance (0.00005 inch)."""
        a, ex, ey = self._chord([1234, 50000])
        delta = Fraction(self.rng.choice([1, 100, 500, 1000, 1200, 1300, 2000, 5000, 10000]), 10**6)
        self._r_word(self.rng.choice(["G2", "G3"]), ex, ey, self.rng.choice([1, -1]) * (a - delta))

    def _r_big(self) -> None:
        a, ex, ey = self._chord([5000, 30000])
        big = Fraction(self.rng.choice([10005, 40000, 250000]), 10)  # 1000.5 .. 25000 mm
        self._r_word(self.rng.choice(["G2", "G3"]), ex, ey, self.rng.choice([1, -1]) * big)

    def _r_tiny(self) -> None:
        a, ex, ey = self._chord([2, 4, 15])
        big = a + Fraction(self.rng.choice([1, 3, 10]), 10000)
        self._r_word(self.rng.choice(["G2", "G3"]), ex, ey, self.rng.choice([1, -1]) * big)

    # -- I/J arcs ----------------------------------------------------------------------------------------
    def _ij(self, code: str, i: Fraction, j: Fraction, end: tuple[Fraction, Fraction] | None) -> None:
        z = self.coordinate(-5, 5) if self.rng.random() < 0.2 else None
        if end is None:  # no axis word of the plane: a whole turn (a helix with Z)
            z = self.coordinate(-5, 5) if z is None else z
            self.lines.append(f"{code} Z{dec(z)} I{dec(i)} J{dec(j)}")
            self.pos[2] = z
            self.points.append(self.machine(self.pos[0], self.pos[1]))
            return
        self.move(code, end[0], end[1], z)
        self.lines[-1] += f" I{dec(i)} J{dec(j)}"

    def _circle(self, full: bool = False, same: bool = False) -> tuple[Fraction, Fraction, Fraction, str,
                                                                        tuple[Fraction, Fraction]]:
        """A rational circle through the position: I, J, radius, the code and the end (``same``: the start)."""
        r = self.rng
        vx, vy, qv = r.choice(DIRECTIONS)
        # (an end on the start's ray is a whole turn the pass declines: only when asked for, ``same``)
        wx, wy, qw = (vx, vy, qv) if same else r.choice([d for d in DIRECTIONS if d[:2] != (vx, vy)])
        # radii from 0.002 mm (LinuxCNC refuses an I/J radius below 0.00005 inch: "Zero-radius arc")
        rad = qv * qw // math.gcd(qv, qw) * Fraction(r.choice([20, 100, 1000, 5000, 20000]), 10000)
        i, j = -rad * vx, -rad * vy
        cx, cy = self.pos[0] + i, self.pos[1] + j
        code = r.choice(["G2", "G3"])
        (mcx, mcy), mr = self.machine(cx, cy), rad * self.unit
        self.circles.append(Circle(mcx, mcy, mr, (vx, vy), (wx, wy), code == "G2", full=full or same))
        return i, j, rad, code, (cx + rad * wx, cy + rad * wy)

    def _ij_circle(self) -> None:
        i, j, _rad, code, end = self._circle()
        self._ij(code, i, j, end)

    def _ij_turn(self) -> None:
        i, j, _rad, code, _end = self._circle(full=True)
        self._ij(code, i, j, None)

    def _ij_ray_start(self) -> None:
        """The end written and equal to the start: LinuxCNC's whole turn."""
        i, j, _rad, code, end = self._circle(same=True)
        self._ij(code, i, j, end)

    def _spiral(self, deltas: list[int], same: bool = False) -> None:
        """An I/J arc whose end radius differs from its start radius by one of ``deltas`` (ten-thousandths of a
        millimetre, at most half the start radius)."""
        r = self.rng
        vx, vy = r.choice(_AXES)
        wx, wy = (vx, vy) if same else r.choice([d for d in _AXES if d != (vx, vy)])
        rad = Fraction(r.choice([50, 500, 20000, 400000]), 10000)
        delta = min(Fraction(r.choice(deltas), 10000), rad / 2) * r.choice([1, -1])
        i, j = -rad * vx, -rad * vy
        cx, cy = self.pos[0] + i, self.pos[1] + j
        self._ij(r.choice(["G2", "G3"]), i, j, (cx + (rad + delta) * wx, cy + (rad + delta) * wy))

    def _ij_spiral(self) -> None:
        self._spiral([1, 5, 100, 250])  # within 0.028 mm: LinuxCNC takes them whatever the radius

    def _ij_spiral_far(self) -> None:
        self._spiral([290, 300, 5000, 30000])  # beyond 0.028 mm: refused unless within 0.1 % of the radius

    def _ij_zero(self) -> None:
        """An I/J radius below LinuxCNC's 0.00005 inch: its "Zero-radius arc" error."""
        rad = Fraction(self.rng.choice([5, 12]), 10000)
        vx, vy = self.rng.choice(_AXES)
        wx, wy = self.rng.choice(_AXES)
        cx, cy = self.pos[0] - rad * vx, self.pos[1] - rad * vy
        self._ij(self.rng.choice(["G2", "G3"]), -rad * vx, -rad * vy, (cx + rad * wx, cy + rad * wy))

    def _ij_ray_spiral(self) -> None:
        self._spiral([1, 100, 250], same=True)

    # -- outside the pass's subset ----------------------------------------------------------------------
    def foreign(self) -> None:
        kind = self.rng.choice(["G91", "G20", "G18", "G90.1", "P"])
        self.kinds.add(kind)
        if kind == "G91":
            self.lines += ["G91", "G2 X10 Y0 R5", "G3 X-10 Y0 I-5 J0", "G90"]
            self.fresh()
        elif kind == "G20":
            self.lines.append("G20")
            self.unit = INCH
            self.fresh()
            self._r_pyth()
            self._ij_circle()
            self.lines.append("G21")
            self.unit = Fraction(1)
            self.fresh()
        elif kind == "G18":
            self.lines += ["G18", f"G2 X{dec(self.pos[0] + 10)} Z{dec(self.pos[2])} I5 K0", "G17"]
            self.fresh()
        elif kind == "G90.1":
            self.lines += ["G90.1", f"G2 X{dec(self.pos[0] + 10)} Y{dec(self.pos[1])} "
                           f"I{dec(self.pos[0] + 5)} J{dec(self.pos[1])}", "G91.1"]
            self.fresh()
        else:
            self.lines.append(f"G3 X{dec(self.pos[0])} Y{dec(self.pos[1])} I3 J4 P2")
            self.points.append(self.machine(self.pos[0], self.pos[1]))

    # -- the program -------------------------------------------------------------------------------------
    def program(self, lines: int = 530) -> str:
        """The program: at least ``lines`` lines, mostly arcs; one construct outside the pass's subset
        (``outside``), a few arcs the pass declines and one LinuxCNC may refuse, in some programs."""
        r = self.rng
        self.lines = ["G21 G90 G17 G54 G94 F300"]
        self.fresh()
        specials: dict[int, str] = {}
        if not self.rational and not self.menu:
            specials.update({r.randrange(10, lines): r.choice(DECLINED) for _ in range(r.choice([0, 0, 0, 1, 2]))})
            if r.random() < 0.3:
                specials[r.randrange(lines - 30, lines - 5)] = r.choice(RISKY)
        if self.outside:
            specials[r.randrange(20, lines - 40)] = "foreign"
        while len(self.lines) < lines:
            due = [k for k in specials if k <= len(self.lines)]
            if due:
                kind = specials.pop(min(due))
                self.foreign() if kind == "foreign" else self.arc(kind)
            self.block()
        lines = self.lines if self.plane == 17 else [in_plane(line, self.plane) for line in self.lines]
        return "\n".join(lines + ["M30"]) + "\n"

    def block(self) -> None:
        roll = self.rng.random()
        if roll < 0.06:
            self.modal()
        elif roll < 0.25:
            self.straight()
        else:
            self.arc()

    def extreme(self, axis: int, sign: int) -> Fraction:
        """The largest ``sign * coordinate`` of the path on ``axis`` (machine mm; the start included)."""
        best = F0
        for p in self.points:
            best = max(best, sign * p[axis])
        for c in self.circles:
            best = max(best, c.extreme(axis, sign))
        return best
