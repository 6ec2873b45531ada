"""Polygon zones where they meet other features: machines, programs and the relations that hold them.

The issue-18 relations (:mod:`tests.contract.metamorphic`) draw travel boxes and stepped tables; here
the zones are polygons.  Drawn machines (:func:`polygon_machines`) have X/Y/Z, linear or dogleg
rapids, G54/G55 offsets and two tool lengths, and

* an allowed polygon prism in X/Y (the envelope): inside a travel box or as the travel itself, with
  or without Z limits; convex, star-shaped (concave), a U, or cut by a thin slit (long edges 0.02
  mm apart), its vertices on the 0.5 mm grid or 0.001 / 0.0001 mm off it;
* forbidden polygons (a fixture outline in X/Y with or without a Z range, a thin blade, a chuck
  profile in X/Z), some of them tool-tip zones, and a forbid box.

Drawn programs (:func:`polygon_programs`) aim at the polygons: targets on a vertex, on an edge, a
hair inside or outside either, near a box, or anywhere; lines and rapids in G54, G55 and G53,
incremental moves from the start position, ``G43 Hn`` / ``G49`` with Z moves that bring the tool
tip to a tip zone's Z limits, and arcs (G2/G3) on exact circles through decimal points
(Pythagorean triples) or spirals whose end is off the circle within the arc tolerance.

Relations (each a test failure when broken; any exception other than a G-code input error too):

* **ranges vs concrete values** and **margins** (:func:`~tests.contract.metamorphic.check_ranges`,
  :func:`~tests.contract.metamorphic.check_margins`, reused as they are);
* **independent oracles** (:func:`check_oracles`): the exact brute force
  (:mod:`oracles.bruteforce`, at margin 0 and ``d``) and Shapely in floats (margin 0, only where a
  point is more than :data:`GAP` from every zone boundary) against the prover's verdict and its
  first violating block, and the prover's witnesses re-judged by Shapely;
* **engines** (:func:`check_engines`): on the same segments, the default engine deciding one by one,
  the default engine with the vectorized column screen forced on (:mod:`nczones.prover.screen`,
  polygon grids), and ``engine="z3"`` reach the same verdict and the same violating blocks; every
  row the column screen proves is proved by Z3 alone and has no brute-force violation.
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from fractions import Fraction

from hypothesis import assume
from hypothesis import strategies as st

from nczones.errors import InputError, MachineFileError
from nczones.exact import format_decimal
from nczones.gcode import interpret_text
from nczones.machine import Machine, parse_machine, polygon_problem
from nczones.motion import Segment, SegmentKind
from nczones.zones import AllowedSet, BoxZone, PolygonZone, ZonePoint

from .metamorphic import MetamorphicViolation, _counted, _note
from oracles.bruteforce import dogleg_corners, first_violation

F = Fraction
F0 = Fraction(0)
#: Shapely's verdict counts only for points farther than this from every zone boundary (mm).
GAP = 1e-6


def _dec(q: Fraction) -> str:
    return format_decimal(q)


HALF = F(1, 2)


def _grid(draw, lo, hi, step=HALF) -> Fraction:
    return lo + step * draw(st.integers(0, int((hi - lo) / step)))


# ----------------------------------------------------------------------------- polygons

#: (cos, sin) of 16 directions, rounded to two places: vertices c + r * u stay decimals.
_DIRS = tuple((F(round(math.cos(k * math.pi / 8), 2)).limit_denominator(100),
               F(round(math.sin(k * math.pi / 8), 2)).limit_denominator(100)) for k in range(16))


@st.composite
def _outline(draw, centre: tuple[Fraction, Fraction], reach: Fraction, shape: str) -> list[tuple[Fraction, Fraction]]:
    """Vertices (counter-clockwise) of a simple polygon around ``centre`` within ``reach`` (L-infinity)."""
    cx, cy = centre
    if shape in ("convex", "star"):
        n = draw(st.sampled_from((3, 4, 5, 6, 8) if shape == "convex" else (8, 10, 12, 16)))
        turn = draw(st.integers(0, 15))
        step = 16 // n if 16 % n == 0 else None
        if step is None:  # 3, 5, 6, 10, 12: spread over the 16 directions, no gap of a half turn
            ks = sorted({(round(i * 16 / n) + turn) % 16 for i in range(n)})
        else:
            ks = sorted((i * step + turn) % 16 for i in range(n))
        r_out = _grid(draw, reach / 2, reach)
        r_in = _grid(draw, reach / 5, r_out * 3 / 4) if shape == "star" else r_out
        out = []
        for i, k in enumerate(ks):
            r = r_out if i % 2 == 0 else r_in
            if shape == "convex" and draw(st.integers(0, 3)) == 0:
                r = r_out - F(1, 2)
            u, v = _DIRS[k]
            out.append((cx + r * u, cy + r * v))
        return out
    if shape == "u":  # a U opening upwards (concave, axis-parallel edges)
        w, h = _grid(draw, reach / 2, reach), _grid(draw, reach / 2, reach)
        gap = _grid(draw, F(1), w / 2)
        floor = _grid(draw, -h + 1, h - 1)
        return [(cx - w, cy - h), (cx + w, cy - h), (cx + w, cy + h), (cx + gap, cy + h), (cx + gap, floor),
                (cx - gap, floor), (cx - gap, cy + h), (cx - w, cy + h)]
    if shape == "slit":  # a square cut by a slit 0.02 wide from the top edge down to `depth` (long thin edges)
        w = _grid(draw, reach / 2, reach)
        x = _grid(draw, cx - w + 1, cx + w - 1)
        depth = _grid(draw, cy - w + F(1, 2), cy + w - 1)
        lean = draw(st.sampled_from((F0, F0, F(1, 100), F(-3, 100))))
        return [(cx - w, cy - w), (cx + w, cy - w), (cx + w, cy + w), (x + F(1, 100), cy + w),
                (x + lean, depth), (x - F(1, 100), cy + w), (cx - w, cy + w)]
    if shape == "blade":  # a long thin triangle (a sliver), any direction
        k = draw(st.integers(0, 15))
        u, v = _DIRS[k]
        length = _grid(draw, reach / 2, reach)
        width = draw(st.sampled_from((F(2, 100), F(1, 10), F(1))))
        a = (cx - length * u, cy - length * v)
        b = (cx + length * u, cy + length * v)
        return [a, b, (cx - width * v, cy + width * u)]
    raise AssertionError(shape)


@st.composite
def polygon_zones(draw, name: str, plane: tuple[str, str], centre, reach, *, forbid: bool, limits=(),
                  point: ZonePoint = ZonePoint.MACHINE, shapes=("convex", "star", "u", "slit")) -> PolygonZone:
    """A simple polygon (validated exactly), its vertices on the grid or a hair off it."""
    shape = draw(st.sampled_from(shapes))
    verts = draw(_outline(centre, reach, shape))
    if draw(st.integers(0, 2)) == 0:  # near grid points: one or all vertices 0.001 or 0.0001 off
        hair = draw(st.sampled_from((F(1, 1000), F(-1, 1000), F(1, 10000), F(-1, 10000))))
        every = draw(st.booleans())
        pick = draw(st.integers(0, len(verts) - 1))
        verts = [(x + hair, y - hair) if every or i == pick else (x, y) for i, (x, y) in enumerate(verts)]
    if draw(st.booleans()):
        verts = verts[::-1]  # either orientation
    assume(polygon_problem(list(verts)) is None)
    _note(f"polygon {shape}{' forbid' if forbid else ''}")
    return PolygonZone(name, plane, tuple(verts), tuple(limits), forbid, point)


# ----------------------------------------------------------------------------- machines


def _zone_toml(z) -> str:
    lines = ["[[zones]]", f'name = "{z.name}"', f'kind = "{z.kind}"', f"forbid = {'true' if z.forbid else 'false'}"]
    if z.point is ZonePoint.TIP:
        lines.append('point = "tip"')
    if isinstance(z, PolygonZone):
        lines.append(f'plane = ["{z.plane[0]}", "{z.plane[1]}"]')
        lines.append("vertices = [" + ", ".join(f'["{_dec(a)}", "{_dec(b)}"]' for a, b in z.vertices) + "]")
    lo = {a: v for a, v, _ in z.limits if v is not None}
    hi = {a: v for a, _, v in z.limits if v is not None}
    if lo:
        lines.append("min = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in lo.items()) + " }")
    if hi:
        lines.append("max = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in hi.items()) + " }")
    return "\n".join(lines)


@st.composite
def polygon_machines(draw) -> tuple[Machine, str]:
    """(machine, its TOML text): see the module docstring."""
    zones: list = []
    travel = draw(st.sampled_from(("box+polygon", "polygon", "box+polygon", "box")))
    if travel != "polygon":
        zones.append(BoxZone("travel", (("X", F0, F(100)), ("Y", F0, F(100)), ("Z", F0, F(200)))))
    if travel != "box":
        z_limits = draw(st.sampled_from(((), (("Z", F0, F(200)),), (("Z", F(20), F(190)),), (("Z", None, F(180)),))))
        if travel == "polygon" and not z_limits:
            z_limits = (("Z", F0, F(200)),)
        centre = (_grid(draw, F(45), F(55)), _grid(draw, F(45), F(55)))
        zones.append(draw(polygon_zones("envelope", ("X", "Y"), centre, F(44), forbid=False, limits=z_limits)))
    for k in range(draw(st.sampled_from((0, 1, 1, 2)))):
        tip = draw(st.integers(0, 2)) == 0
        if draw(st.integers(0, 3)) == 0:  # a chuck or clamp profile in X/Z (Z seen at the tip or not)
            centre = (_grid(draw, F(20), F(80)), _grid(draw, F(10), F(60)))
            limits = draw(st.sampled_from(((), (("Y", F(20), F(80)),))))
            zones.append(draw(polygon_zones(f"profile{k + 1}", ("X", "Z"), centre, F(15), forbid=True, limits=limits,
                                            point=ZonePoint.TIP if tip else ZonePoint.MACHINE,
                                            shapes=("convex", "star", "u", "blade"))))
        else:
            centre = (_grid(draw, F(20), F(80)), _grid(draw, F(20), F(80)))
            limits = draw(st.sampled_from(((), (("Z", F0, _grid(draw, F(10), F(80), F(1))),))))
            zones.append(draw(polygon_zones(f"fixture{k + 1}", ("X", "Y"), centre, _grid(draw, F(4), F(20)),
                                            forbid=True, limits=limits, point=ZonePoint.TIP if tip else ZonePoint.MACHINE,
                                            shapes=("convex", "star", "u", "slit", "blade"))))
    if draw(st.integers(0, 2)) == 0:
        lo = {a: _grid(draw, F(10), F(80)) for a in "XY"}
        hi = {a: lo[a] + _grid(draw, F(1, 2), F(10)) for a in "XY"}
        lims = [(a, lo[a], hi[a]) for a in "XY"]
        if draw(st.booleans()):
            lims.append(("Z", F0, _grid(draw, F(20), F(120), F(1))))
        zones.append(BoxZone("post", tuple(lims), True))
    allowed = AllowedSet(tuple(zones))
    # the start: a grid point of the allowed set (no tool length is active at the start)
    candidates = [(F(x), F(y), F(z)) for x in range(5, 100, 5) for y in range(5, 100, 5) for z in (150, 170)]
    inside = [p for p in candidates if allowed.contains(dict(zip("XYZ", p)))]
    assume(inside)
    start = draw(st.sampled_from(inside))
    rapid_mode = draw(st.sampled_from(("dogleg", "dogleg", "linear")))
    rates = [draw(st.sampled_from(("6000", "12000"))) for _ in range(3)]
    g54 = {"X": _grid(draw, F0, F(20)), "Y": _grid(draw, F0, F(20)), "Z": _grid(draw, F(20), F(60), F(1))}
    g55 = {"X": _grid(draw, F(20), F(40)), "Y": _grid(draw, F0, F(10)), "Z": g54["Z"]}
    tools = {n: _grid(draw, F(20), F(80)) for n in (1, 2)}
    text = "\n".join([
        "[machine]", 'name = "polygon metamorphic"', 'axes = ["X", "Y", "Z"]', 'pulse = "0.001"',
        f'rapid_mode = "{rapid_mode}"',
        "[machine.rapid]", *(f'{a} = "{r}"' for a, r in zip("XYZ", rates)),
        "[machine.reference]", *(f'{a} = "{_dec(v)}"' for a, v in zip("XYZ", start)),
        "[offsets]",
        "G54 = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in g54.items()) + " }",
        "G55 = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in g55.items()) + " }",
        "[tool_lengths]", *(f'H{n} = "{_dec(v)}"' for n, v in tools.items()),
        *(_zone_toml(z) for z in zones),
    ]) + "\n"
    try:
        machine = parse_machine(text, "polygon.toml")
    except MachineFileError as exc:  # pragma: no cover - the drawn zones are valid by construction
        raise AssertionError(f"drawn machine refused: {exc}\n{text}") from exc
    return machine, text


# ----------------------------------------------------------------------------- programs

#: Pythagorean directions (x, y, r): the points c + k (x, y) lie exactly on the circle of radius k r.
_TRIPLES = ((F(3), F(4), F(5)), (F(5), F(12), F(13)), (F(8), F(15), F(17)), (F(1), F(0), F(1)))


class _Aim:
    """The generator's nominal state: the machine position, frame and tool length it aims with."""

    def __init__(self, machine: Machine):
        self.m = machine
        self.pos = dict(zip("XYZ", machine.start))
        self.frame = "G54"
        self.tool = F0
        self.register: int | None = None
        self.used: set[str] = {"start.X", "start.Y", "start.Z"}
        #: keep targets in the allowed set (a boundary point is in it): the path between two may still leave
        self.careful = False

    def fits(self, target: dict[str, Fraction]) -> bool:
        return not self.careful or self.m.allowed.contains(target, self.tool)

    @st.composite
    def inside(draw, self, target: dict[str, Fraction]) -> dict[str, Fraction]:
        """``target``, or (careful, and it is outside) a grid point of the allowed set at its Z."""
        if self.fits(target):
            return target
        grid = [{**target, "X": F(x), "Y": F(y)} for x in range(5, 100, 5) for y in range(5, 100, 5)]
        grid = [p for p in grid if self.fits(p)]
        return draw(st.sampled_from(grid)) if grid else dict(self.pos)

    def off(self, a: str) -> Fraction:
        return dict(zip("XYZ", self.m.offset(self.frame)))[a] + (self.tool if a == "Z" else 0)

    def depend(self, axes: str, frame: str | None) -> None:
        if frame is not None:
            self.used.update(f"{frame}.{a}" for a in axes if a != "Z" or frame == "G54")
            if "Z" in axes and self.register is not None:
                self.used.add(f"H{self.register}")


def _polys(machine: Machine) -> list[PolygonZone]:
    return [z for z in machine.zones if isinstance(z, PolygonZone)]


@st.composite
def _plane_target(draw, machine: Machine, s: _Aim) -> dict[str, Fraction]:
    """An X/Y (or X/Z) machine target aimed at a polygon: a vertex, an edge point, a hair off either."""
    polys = _polys(machine)
    how = draw(st.integers(0, 5))
    target = dict(s.pos)
    if polys and how <= 3:
        z = draw(st.sampled_from(polys))
        vs = z.vertices
        i = draw(st.integers(0, len(vs) - 1))
        a, b = vs[i], vs[(i + 1) % len(vs)]
        t = draw(st.sampled_from((F0, F0, F(1, 2), F(1, 4), F(1, 10), F(3, 5))))
        p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
        hair = draw(st.sampled_from((F0, F0, F(1, 100), F(-1, 100), F(1, 1000), F(-1, 1000), F(1, 2), F(-1, 2))))
        p[draw(st.integers(0, 1))] += hair
        tip = z.point is ZonePoint.TIP and z.plane[1] == "Z"
        for k, axis in enumerate(z.plane):
            target[axis] = p[k] + (s.tool if tip and axis == "Z" else 0)
        return target
    if how == 4:
        for a in "XY":
            target[a] = draw(st.sampled_from((F0, F(100), F(1, 100), F(9999, 100)))) if draw(st.booleans()) \
                else _grid(draw, F(1), F(99))
        return target
    for a in "XY":
        target[a] = _grid(draw, F(1), F(99))
    return target


@st.composite
def _z_target(draw, machine: Machine, s: _Aim) -> Fraction:
    """A machine Z on or near a zone's Z limit (a tip zone's seen through the active tool length)."""
    levels = []
    for z in machine.zones:
        for a, lo, hi in z.limits:
            if a == "Z":
                levels += [(v + (s.tool if z.point is ZonePoint.TIP else 0)) for v in (lo, hi) if v is not None]
        if isinstance(z, PolygonZone) and "Z" in z.plane:
            k = z.plane.index("Z")
            levels += [v[k] + (s.tool if z.point is ZonePoint.TIP else 0) for v in z.vertices]
    if levels and draw(st.integers(0, 2)):
        return draw(st.sampled_from(levels)) + draw(st.sampled_from((F0, F(1, 100), F(-1, 100), F(1, 1000), F(-2))))
    return _grid(draw, F(1), F(199))


def _words(s: _Aim, target: dict[str, Fraction], axes: str) -> str:
    return " ".join(f"{a}{_dec(target[a] - s.off(a))}" for a in axes)


@st.composite
def _blocks(draw, machine: Machine, s: _Aim, kind: str) -> list[str]:
    if kind == "move":
        how = draw(st.sampled_from(("G54", "G55", "G53", "G54")))
        axes = draw(st.sampled_from(("XY", "XY", "XYZ", "Z", "X", "Y")))
        target = dict(s.pos)
        if set(axes) & set("XY"):
            plane = draw(_plane_target(machine, s))
            for a in axes:
                target[a] = plane[a]
        if "Z" in axes and target["Z"] == s.pos["Z"]:
            target["Z"] = draw(_z_target(machine, s))
        target = draw(s.inside(target))
        axes = "".join(a for a in "XYZ" if a in axes or target[a] != s.pos[a])
        g = draw(st.sampled_from(("G0", "G0", "G1")))
        if how == "G53":
            s.pos = target
            return [f"G90 G53 {g} " + " ".join(f"{a}{_dec(target[a])}" for a in axes)]
        pre = "" if how == s.frame else how + " "
        s.frame = how
        s.depend(axes, how)
        words = _words(s, target, axes)
        s.pos = target
        return [f"{pre}G90 {g} {words}"]
    if kind == "arc":
        a0 = draw(s.inside(draw(_plane_target(machine, s))))
        x, y, r = draw(st.sampled_from(_TRIPLES))
        small = s.careful and draw(st.booleans())
        k = draw(st.sampled_from(((F(1, 2), F(1)) if small else (F(1, 2), F(1), F(2), F(3))) if r > 1
                                 else ((F(2), F(5)) if small else (F(2), F(5), F(10)))))
        signs = [(sx, sy, swap) for sx in (1, -1) for sy in (1, -1) for swap in (False, True)]
        sx, sy, swap = draw(st.sampled_from(signs))
        u = (sx * k * x, sy * k * y) if not swap else (sx * k * y, sy * k * x)  # start - centre
        ex, ey, eswap = draw(st.sampled_from(signs))
        w = (ex * k * x, ey * k * y) if not eswap else (ex * k * y, ey * k * x)  # end - centre
        c = (a0["X"] - u[0], a0["Y"] - u[1])
        grow = draw(st.sampled_from((F0, F0, F0, F(1, 1000), F(-1, 1000), F(15, 10000))))  # a spiral
        end = {"X": c[0] + w[0] + grow, "Y": c[1] + w[1], "Z": s.pos["Z"]}
        cw = draw(st.booleans())
        s.depend("XY", s.frame)
        first = f"G90 G1 {_words(s, a0, 'XY')}"
        s.pos = end
        return [first, f"{'G2' if cw else 'G3'} {_words(s, end, 'XY')} I{_dec(-u[0])} J{_dec(-u[1])}"]
    if kind == "tool":
        n = draw(st.sampled_from((1, 2)))
        if draw(st.integers(0, 4)) == 0:
            s.tool, s.register = F0, None
            return ["G49"]
        s.tool, s.register = machine.tool_length(n), n
        target = dict(s.pos)
        target["Z"] = draw(_z_target(machine, s))
        if not s.fits(target):
            target["Z"] = s.pos["Z"] if s.fits(s.pos) else F(199)
        s.depend("Z", s.frame)
        s.pos = target
        return [f"G43 H{n} G90 G0 {_words(s, target, 'Z')}"]
    if kind == "incremental":
        target = draw(s.inside(draw(_plane_target(machine, s))))
        d = {a: target[a] - s.pos[a] for a in "XY"}
        s.pos = {**s.pos, "X": target["X"], "Y": target["Y"]}
        return [f"G91 {draw(st.sampled_from(('G0', 'G1')))} X{_dec(d['X'])} Y{_dec(d['Y'])}", "G90"]
    raise AssertionError(kind)


@st.composite
def polygon_programs(draw, machine: Machine, used: set | None = None) -> str:
    """A program for a :func:`polygon_machines` machine; ``used`` collects the ``--param`` names it depends on."""
    s = _Aim(machine)
    s.careful = draw(st.integers(0, 2)) > 0
    lines = ["G21 G90 G17 G40 G49 G54 G80 G94 F600"]
    if draw(st.integers(0, 3)) == 0:
        lines += draw(_blocks(machine, s, "incremental"))
    for _ in range(draw(st.integers(1, 5))):
        lines += draw(_blocks(machine, s, draw(st.sampled_from(("move", "move", "move", "arc", "arc", "tool")))))
    lines.append("M30")
    if used is not None:
        used.update(s.used)
    return "\n".join(lines) + "\n"


PARAM_NAMES = ("G54.X", "G54.Y", "G54.Z", "G55.X", "G55.Y", "H1", "H2", "start.X", "start.Y")


@st.composite
def polygon_ranges(draw, machine: Machine, used: set) -> tuple[str, ...]:
    """One or two ``--param`` ranges, mostly of parameters the program's motion depends on."""
    pool = sorted(u for u in used if u in PARAM_NAMES)
    names = draw(st.lists(st.sampled_from(pool if pool and draw(st.integers(0, 4)) else PARAM_NAMES),
                          min_size=1, max_size=2, unique=True))
    out = []
    for name in names:
        width = draw(st.sampled_from((F(2, 1000), F(2, 100), F(1, 2), F(2))))
        lo = draw(st.sampled_from((F0, -width / 2, -width, F(1, 1000), -width - F(1, 100))))
        hi = lo + width
        if name.startswith("H"):
            nominal = machine.tool_length(int(name[1:]))
            lo, hi = nominal + lo, nominal + hi
        out.append(f"{name}={_dec(lo)}..{_dec(hi)}")
    return tuple(out)


@st.composite
def polygon_range_cases(draw):
    machine, _ = draw(polygon_machines())
    used: set = set()
    text = draw(polygon_programs(machine, used))
    return machine, text, draw(polygon_ranges(machine, used))


@st.composite
def polygon_margin_cases(draw):
    machine, _ = draw(polygon_machines())
    text = draw(polygon_programs(machine))
    margin = draw(st.sampled_from((F(1, 1000), F(1, 100), F(1, 10), F(1, 2), F(2))))
    frac = [draw(st.sampled_from((F0, F(1, 3), F(-1, 2), F(9, 10), F(-99, 100)))) for _ in range(3)]
    return machine, text, margin, {a: margin * f for a, f in zip("XYZ", frac)}


@st.composite
def polygon_oracle_cases(draw):
    machine, _ = draw(polygon_machines())
    text = draw(polygon_programs(machine))
    return machine, text, draw(st.sampled_from((F(1, 1000), F(1, 100), F(1, 2))))


@st.composite
def polygon_engine_cases(draw):
    machine, _ = draw(polygon_machines())
    used: set = set()
    text = draw(polygon_programs(machine, used))
    params = draw(polygon_ranges(machine, used)) if draw(st.booleans()) else ()
    return machine, text, draw(st.sampled_from((F(1, 1000), F(1, 100), F(1, 2)))), params


# ----------------------------------------------------------------------------- the independent float oracle


class ShapelyZones:
    """The machine's zones in floats (Shapely polygons), judged only with a gap of :data:`GAP` mm.

    :meth:`judge` says ``True`` (the point certainly violates some zone), ``False`` (certainly none) or
    ``None`` (some boundary within the gap).  Margin 0 only.
    """

    def __init__(self, machine: Machine):
        import shapely
        from shapely.geometry import Polygon

        self.shapely = shapely
        self.tool_axis = machine.allowed.tool_axis
        self.zones = []
        for z in machine.zones:
            poly = None
            if isinstance(z, PolygonZone):
                poly = Polygon([(float(a), float(b)) for a, b in z.vertices])
                shapely.prepare(poly)
            self.zones.append((z, poly))

    def _inside(self, z, poly, p: dict[str, float]) -> bool | None:
        """Is the (closed) zone's point set holding ``p`` (None: within the gap of its boundary)?"""
        verdict = True
        for a, lo, hi in z.limits:
            v = p[a]
            for bound, sign in ((lo, 1), (hi, -1)):
                if bound is None:
                    continue
                gap = sign * (v - float(bound))
                if gap < -GAP:
                    return False
                if gap <= GAP:
                    verdict = None  # type: ignore[assignment]
        if poly is not None:
            from shapely.geometry import Point

            q = Point(p[z.plane[0]], p[z.plane[1]])
            if poly.exterior.distance(q) <= GAP:
                return None
            if not poly.contains(q):
                return False
        return verdict

    def judge(self, p: dict[str, float], tool_length: float) -> bool | None:
        undecided = False
        for z, poly in self.zones:
            q = dict(p)
            if z.point is ZonePoint.TIP and self.tool_axis in q:
                q[self.tool_axis] -= tool_length
            inside = self._inside(z, poly, q)
            if inside is None:
                undecided = True
            elif inside == z.forbid:  # in a forbid zone (its interior: beyond the gap) or out of an allow zone
                return True
        return None if undecided else False


def float_path(seg: Segment, machine: Machine, n: int = 200) -> list[dict[str, float]]:
    """Points of the segment's path in floats: lines and both rapid modes (the dogleg's corners from the
    brute force), arcs and spirals (radius linear in the angle, as LinuxCNC moves a spiral)."""
    axes = seg.axes
    if seg.kind is SegmentKind.ARC:
        i, j, _ = seg.plane_indices()
        assert seg.centre is not None
        cx, cy = float(seg.centre[0]), float(seg.centre[1])
        s = [float(v) for v in seg.start]
        e = [float(v) for v in seg.end]
        a0 = math.atan2(s[j] - cy, s[i] - cx)
        a1 = math.atan2(e[j] - cy, e[i] - cx)
        sweep = a1 - a0
        if seg.clockwise:
            sweep = sweep - 2 * math.pi if sweep >= 0 else sweep
        else:
            sweep = sweep + 2 * math.pi if sweep <= 0 else sweep
        r0, r1 = math.hypot(s[i] - cx, s[j] - cy), math.hypot(e[i] - cx, e[j] - cy)
        out = []
        for k in range(n + 1):
            f = k / n
            q = [a + (b - a) * f for a, b in zip(s, e)]
            ang, rad = a0 + sweep * f, r0 + (r1 - r0) * f
            q[i], q[j] = cx + rad * math.cos(ang), cy + rad * math.sin(ang)
            out.append(dict(zip(axes, q)))
        return out
    corners = [seg.start, seg.end]
    if seg.kind is SegmentKind.RAPID and machine.rapid_mode.name == "DOGLEG":
        corners = dogleg_corners(seg, machine)
    out = []
    for a, b in zip(corners, corners[1:]):
        fa, fb = [float(v) for v in a], [float(v) for v in b]
        out += [dict(zip(axes, [x + (y - x) * k / n for x, y in zip(fa, fb)])) for k in range(n + 1)]
    return out or [dict(zip(axes, [float(v) for v in seg.start]))]


# ----------------------------------------------------------------------------- the relations


def _segments(machine: Machine, text: str) -> list[Segment]:
    try:
        run = interpret_text(text, machine, fast=False)
        segs = list(run.segments())
    except InputError as exc:
        _note(f"rejected: {exc.diagnostics[0].code if hasattr(exc, 'diagnostics') else type(exc).__name__}")
        assume(False)
        raise
    assume(not run.unsupported)
    return segs


def _verify_segments(segs, machine: Machine, **options):
    from nczones.prover import verify_segments

    return verify_segments(segs, machine, max_violations=1000, **options)


def _first(result) -> int | None:
    return min((v.block for v in result.violations), default=None)


def _excused(result, block: int) -> bool:
    """An `unknown` reason at or before ``block`` excuses a missing violation there."""
    return any(r.block is None or r.block <= block for r in result.reasons)


def _require(cond: bool, message: str) -> None:
    if not cond:
        raise MetamorphicViolation(message)


def check_oracles(machine: Machine, text: str, margin: Fraction) -> None:
    """The prover against the exact brute force (margins 0 and ``d``) and Shapely (margin 0)."""
    segs = _segments(machine, text)
    _counted("polygon oracles")
    for d in (F0, margin):
        result = _verify_segments(segs, machine, margin=d)
        _note(f"oracle: {result.verdict.label} at margin {'0' if d == 0 else 'd'}")
        hit = first_violation(segs, machine, d)
        if hit is not None:
            first = _first(result)
            _require((first is not None and first <= hit.block) or _excused(result, hit.block),
                     f"margin {d}: the brute force finds block {hit.block} outside at {hit.point} (zones {hit.zones}) "
                     f"but the prover is {result.verdict.label} with violations at {sorted({v.block for v in result.violations})}")
        if result.verdict.label == "unsafe":
            _note(f"oracle: unsafe at margin {'0' if d == 0 else 'd'}, brute force {'agrees' if hit else 'finds none'}")
        if d != 0:
            continue
        shapes = ShapelyZones(machine)
        found = None
        for seg in segs:
            for p in float_path(seg, machine):
                if shapes.judge(p, float(seg.tool_length)):
                    found = (seg.block, p)
                    break
            if found:
                break
        if found is not None:
            first = _first(result)
            _require((first is not None and first <= found[0]) or _excused(result, found[0]),
                     f"Shapely finds block {found[0]} outside at {found[1]} (more than {GAP} mm from every boundary) "
                     f"but the prover is {result.verdict.label} with violations at "
                     f"{sorted({v.block for v in result.violations})}")
        elif result.verdict.label == "unsafe":
            _note("oracle: unsafe, Shapely's samples all within the gap or inside")
        for v in result.violations:  # every witness, judged in floats where it is clear of the boundaries
            seg = next(s for s in segs if s.block == v.block)
            for point in (v.point, v.path_point):
                verdict = shapes.judge({a: float(x) for a, x in point}, float(seg.tool_length))
                _require(verdict is not False, f"the witness {point} of block {v.block} ({v.zone}) is inside every "
                                                f"zone by more than {GAP} mm (Shapely)")


@contextmanager
def column_screen_forced():
    """Every batch of segments goes through the vectorized column screen (not only runs of 512 motions)."""
    from nczones.prover import core

    saved = core.SCREEN_MIN_SEGMENTS
    core.SCREEN_MIN_SEGMENTS = 0
    try:
        yield
    finally:
        core.SCREEN_MIN_SEGMENTS = saved


def check_engines(machine: Machine, text: str, margin: Fraction, params: tuple[str, ...] = ()) -> None:
    """One by one, through the column screen, the fast interpreter's columns, and Z3 alone: one verdict, one set
    of violating blocks (at margins 0 and ``d``); over ``params``, the default engine and Z3 alone alike."""
    from nczones.prover import Prover
    from nczones.prover.screen import screen_chunk, segment_columns

    segs = _segments(machine, text)
    _counted("polygon engines")
    for d in (F0, margin):
        auto = _verify_segments(segs, machine, margin=d)
        with column_screen_forced():
            screened = _verify_segments(segs, machine, margin=d)
        z3 = _verify_segments(segs, machine, margin=d, engine="z3")
        fast = _verify_segments(list(interpret_text(text, machine, fast=True)), machine, margin=d)
        runs = {"one by one": auto, "column screen": screened, "z3": z3, "fast interpreter": fast}
        labels = {k: r.verdict.label for k, r in runs.items()}
        _note(f"engines: {'/'.join(sorted(set(labels.values())))}")
        _require(not ("safe" in labels.values() and "unsafe" in labels.values()),
                 f"margin {d}: the engines disagree: {labels}")
        decided = {k: r for k, r in runs.items() if not r.reasons}
        blocks = {k: sorted({v.block for v in r.violations}) for k, r in decided.items()}
        _require(len({tuple(b) for b in blocks.values()}) <= 1,
                 f"margin {d}: the engines report different violating blocks: {blocks}")
        prover = Prover(machine, margin=d)
        for chunk, rows in segment_columns(segs, prover):
            flagged = set(screen_chunk(chunk, prover))
            for k, i in enumerate(rows):
                if k in flagged:
                    continue
                _note("engines: a row proved by the column screen")
                alone = _verify_segments([segs[i]], machine, margin=d, engine="z3")
                hit = first_violation([segs[i]], machine, d)
                _require(alone.verdict.label != "unsafe" and hit is None,
                         f"margin {d}: the column screen proves segment {i} (block {segs[i].block}) but Z3 alone says "
                         f"{alone.verdict.label} and the brute force {hit}")
    if params:  # over parameter ranges: the default engine against Z3 alone
        from nczones.prover import verify_text

        try:
            by = {e: verify_text(text, machine, params=params, engine=e, max_violations=1000) for e in ("auto", "z3")}
        except InputError:
            assume(False)
            raise
        labels = {e: r.verdict.label for e, r in by.items()}
        _note(f"engines over ranges: {'/'.join(sorted(set(labels.values())))}")
        _require(not ("safe" in labels.values() and "unsafe" in labels.values()),
                 f"over {params} the engines disagree: {labels}")
        if not any(r.reasons for r in by.values()):
            lines = {e: sorted({v.line for v in r.violations}) for e, r in by.items()}
            _require(lines["auto"] == lines["z3"], f"over {params} the engines report different lines: {lines}")
