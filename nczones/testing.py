"""Hypothesis strategies for nczones: zone tables, machines and G-code programs.

Use them to property-test your own post-processor or machine files::

    from hypothesis import given, strategies as st
    from nczones.testing import machines, programs

    @given(data=st.data())
    def test_my_post_never_leaves_the_table(data):
        machine = data.draw(machines(axes=("X", "Y", "Z"), allow_kinds=("box", "polygon")))
        text = data.draw(programs(machine, subprograms=True))
        ...

(README.md, "Property-testing your post-processor", has a complete example.)

Every number is an exact decimal (a :class:`~fractions.Fraction` with a
power-of-ten denominator) and is rendered into the text as a decimal, so the
G-code parser is exercised as well.  Generated programs are biased towards
the zones' boundaries: they run along them, touch them, and cross them by a
few pulses, which is where provers and controllers disagree if either is
wrong.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from fractions import Fraction
from typing import Any, cast

try:
    from hypothesis import strategies as st
except ModuleNotFoundError as exc:  # a plain install: the strategies need the [testing] extra
    if exc.name != "hypothesis":
        raise
    raise ModuleNotFoundError("nczones.testing needs Hypothesis: pip install 'nczones[testing]'",
                              name="hypothesis") from None

from .exact import format_decimal
from .machine import Machine, parse_machine
from .zones import BoxZone, PolygonZone, Region, SteppedZone, Zone
from .zones.kinds import KindTable

__all__ = [
    "decimals",
    "zone_tables",
    "polygons",
    "machine_files",
    "machines",
    "programs",
    "boundary_values",
]


def decimals(
    *, min_value: Fraction | int, max_value: Fraction | int, places: int = 3
) -> st.SearchStrategy[Fraction]:
    """Exact decimals with at most ``places`` digits after the point.

    Examples
    --------
    >>> from hypothesis import find
    >>> find(decimals(min_value=1, max_value=2, places=2), lambda q: q > Fraction(3, 2))
    Fraction(151, 100)
    """
    scale = 10**places
    lo = Fraction(min_value) * scale
    hi = Fraction(max_value) * scale
    lo_i = -((-lo.numerator) // lo.denominator)  # ceil
    hi_i = hi.numerator // hi.denominator  # floor
    if lo_i > hi_i:
        raise ValueError(f"Cannot have max_value={max_value!r} < min_value={min_value!r}")
    return st.integers(lo_i, hi_i).map(lambda n: Fraction(n, scale))


def _text(q: Fraction | None) -> str:
    return "" if q is None else format_decimal(q)


@st.composite
def zone_tables(
    draw: st.DrawFn,
    *,
    reference_axis: str = "X",
    limited_axis: str = "Y",
    min_regions: int = 1,
    max_regions: int = 6,
    min_value: int = 0,
    max_value: int = 1000,
    places: int = 1,
    name: str = "table",
) -> SteppedZone:
    """Stepped limit-value tables with increasing boundaries.

    Each region bounds the limited axis below, above, both or not at all.

    Examples
    --------
    >>> from hypothesis import find
    >>> t = find(zone_tables(min_regions=3), lambda z: True)
    >>> len(t.regions), t.uptos == tuple(sorted(set(t.uptos)))
    (3, True)
    """
    n = draw(st.integers(min_regions, max_regions))
    cuts = draw(
        st.lists(
            decimals(min_value=min_value, max_value=max_value, places=places),
            min_size=n + 1,
            max_size=n + 1,
            unique=True,
        )
    )
    cuts.sort()
    regions = []
    for upto in cuts[1:]:
        bounds = draw(
            st.lists(decimals(min_value=min_value, max_value=max_value, places=places), min_size=2, max_size=2)
        )
        lo, hi = min(bounds), max(bounds)
        shape = draw(st.sampled_from(("both", "both", "min", "max")))
        regions.append(
            Region(upto, lo if shape in ("both", "min") else None, hi if shape in ("both", "max") else None)
        )
    return SteppedZone(name, reference_axis, limited_axis, cuts[0], tuple(regions))


def _stepped_toml(zone: SteppedZone, forbid: bool = False) -> str:
    rows = []
    for r in zone.regions:
        parts = [f'upto = "{_text(r.upto)}"']
        if r.min is not None:
            parts.append(f'min = "{_text(r.min)}"')
        if r.max is not None:
            parts.append(f'max = "{_text(r.max)}"')
        rows.append("  { " + ", ".join(parts) + " },")
    return "\n".join(
        [
            "[[zones]]",
            f'name = "{zone.name}"',
            'kind = "stepped"',
            f"forbid = {'true' if forbid else 'false'}",
            f'reference_axis = "{zone.reference_axis}"',
            f'limited_axis = "{zone.limited_axis}"',
            f'from = "{_text(zone.start)}"',
            "regions = [",
            *rows,
            "]",
        ]
    )


#: Directions of a star-shaped polygon's vertices, in counter-clockwise order.
_DIRECTIONS = ((1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1))


@st.composite
def polygons(
    draw: st.DrawFn,
    *,
    plane: tuple[str, str] = ("X", "Y"),
    min_vertices: int = 3,
    max_vertices: int = 8,
    min_value: int = 0,
    max_value: int = 1000,
    places: int = 1,
    forbid: bool = False,
    name: str = "polygon",
) -> PolygonZone:
    """Simple polygons, star-shaped around a centre that lies strictly inside.

    Vertices sit on up to eight rays (every 45 degrees) from the centre at
    drawn distances, in counter-clockwise order, with no gap of 180 degrees
    or more between consecutive rays, so the polygon is simple and its
    centre is an interior point (``polygon_centre`` returns it).

    Examples
    --------
    >>> from hypothesis import find
    >>> p = find(polygons(min_vertices=5), lambda z: True)
    >>> len(p.vertices) >= 5, p.contains(dict(zip(p.plane, polygon_centre(p))))
    (True, True)
    """
    span = Fraction(max_value - min_value)
    lo_c, hi_c = min_value + span * Fraction(2, 5), min_value + span * Fraction(3, 5)
    cx = draw(decimals(min_value=lo_c, max_value=hi_c, places=places))
    cy = draw(decimals(min_value=lo_c, max_value=hi_c, places=places))
    max_vertices = max(min_vertices, min(max_vertices, 8))
    # {0, 3, 5} has no gap over 135 degrees, nor has any superset of it
    extra = draw(st.lists(st.sampled_from((1, 2, 4, 6, 7)), min_size=max(0, min_vertices - 3),
                          max_size=max_vertices - 3, unique=True))
    turn = draw(st.integers(0, 7))
    rays = sorted((k + turn) % 8 for k in {0, 3, 5, *extra})
    r_max = min(cx - min_value, max_value - cx, cy - min_value, max_value - cy)
    vertices = []
    for k in rays:
        r = draw(decimals(min_value=r_max / 5, max_value=r_max, places=places))
        dx, dy = _DIRECTIONS[k]
        vertices.append((cx + dx * r, cy + dy * r))
    return PolygonZone(name, (plane[0], plane[1]), tuple(vertices), (), forbid)


def polygon_centre(zone: PolygonZone) -> tuple[Fraction, Fraction]:
    """The centre a :func:`polygons` polygon was built around (an interior point)."""
    from .machine import polygon_problem  # noqa: F401  (same package; validated by the loader)

    # The rays through opposite-or-adjacent vertices meet at the centre: solve
    # with two vertices on non-parallel rays (their directions are known).
    (ax, ay), (bx, by) = zone.vertices[0], zone.vertices[1]
    for d1 in _DIRECTIONS:
        for d2 in _DIRECTIONS:
            det = d1[0] * (-d2[1]) - d1[1] * (-d2[0])
            if det == 0:
                continue
            # centre + s*d1 = a, centre + t*d2 = b  =>  s*d1 - t*d2 = a - b
            s = ((ax - bx) * (-d2[1]) - (ay - by) * (-d2[0])) / det
            t = (d1[0] * (ay - by) - d1[1] * (ax - bx)) / det
            if s > 0 and t > 0:
                c = (ax - s * d1[0], ay - s * d1[1])
                if all(_on_ray(c, v) for v in zone.vertices) and zone.interior_contains(dict(zip(zone.plane, c))):
                    return c
    raise ValueError("not a polygon made by polygons()")


def _on_ray(c: tuple[Fraction, Fraction], v: tuple[Fraction, Fraction]) -> bool:
    dx, dy = v[0] - c[0], v[1] - c[1]
    return dx == 0 or dy == 0 or abs(dx) == abs(dy)


def _polygon_toml(zone: PolygonZone) -> str:
    verts = ", ".join(f'["{_text(a)}", "{_text(b)}"]' for a, b in zone.vertices)
    return "\n".join(
        [
            "[[zones]]",
            f'name = "{zone.name}"',
            'kind = "polygon"',
            f"forbid = {'true' if zone.forbid else 'false'}",
            f'plane = ["{zone.plane[0]}", "{zone.plane[1]}"]',
            f"vertices = [{verts}]",
        ]
    )


def _box_toml(name: str, lo: dict[str, Fraction], hi: dict[str, Fraction], forbid: bool, point: str = "") -> str:
    lines = ["[[zones]]", f'name = "{name}"', 'kind = "box"', f"forbid = {'true' if forbid else 'false'}"]
    if point:
        lines.append(f'point = "{point}"')
    if lo:
        lines.append("min = { " + ", ".join(f'{a} = "{_text(v)}"' for a, v in lo.items()) + " }")
    if hi:
        lines.append("max = { " + ", ".join(f'{a} = "{_text(v)}"' for a, v in hi.items()) + " }")
    return "\n".join(lines)


def _polygon_ok(zone: PolygonZone) -> bool:
    from .machine import polygon_problem

    return polygon_problem(list(zone.vertices)) is None


@st.composite
def machine_files(
    draw: st.DrawFn,
    *,
    axes: Sequence[str] = ("X", "Y"),
    rapid_modes: Sequence[str] = ("linear", "dogleg"),
    pulse: str = "0.001",
    forbid_boxes: bool = True,
    places: int = 1,
    allow_kinds: Sequence[str] = ("stepped",),
    size: int = 1000,
    tool_lengths: bool = True,
    tip_zones: bool = True,
) -> str:
    """Machine files (TOML text) whose main allow zone lies on the first two axes.

    The main allow zone is drawn from ``allow_kinds``: a ``"stepped"``
    limit-value table, a ``"box"`` or a star-shaped ``"polygon"``, inside
    ``[0, size]`` on both axes; optionally a forbid box sits inside it.
    With a ``Z`` axis, Z travels in ``[0, size/2]``, the file has tool length
    registers ``H1``/``H2`` (``tool_lengths``) and optionally a tool-tip
    forbid box, a vise (``tip_zones``).  The start position is drawn inside
    the allowed set (the forbid box may still cover it: :func:`machines`
    skips those), so the text loads.

    Examples
    --------
    >>> from hypothesis import find
    >>> from nczones.machine import parse_machine
    >>> text = find(machine_files(axes=("X", "Y", "Z"), allow_kinds=("polygon",)), lambda t: "vise" in t)
    >>> m = parse_machine(text)
    >>> [z.kind for z in m.zones if not z.forbid][:2], sorted(m.tool_lengths)
    (['polygon', 'box'], [1, 2])
    """
    ref_axis, lim_axis = axes[0], axes[1]
    kind = draw(st.sampled_from(tuple(allow_kinds)))
    size_q = Fraction(size)
    zones_toml: list[str] = []
    if kind == "stepped":
        table = draw(
            zone_tables(
                reference_axis=ref_axis, limited_axis=lim_axis, places=places, name="table", max_value=size
            ).filter(lambda z: any(r.min is None or r.max is None or r.min < r.max for r in z.regions))
        )
        zones_toml.append(_stepped_toml(table))
        # A start point strictly inside one region of the table (exact midpoint).
        i = draw(st.integers(0, len(table.regions) - 1))
        reg = table.regions[i]
        lower = table.start if i == 0 else table.regions[i - 1].upto
        r = (lower + reg.upto) / 2 if i else lower
        lo = reg.min if reg.min is not None else (reg.max - 10 if reg.max is not None else Fraction(0))
        hi = reg.max if reg.max is not None else lo + 10
        start = {ref_axis: r, lim_axis: (lo + hi) / 2}
    elif kind == "box":
        xs = sorted(draw(st.lists(decimals(min_value=0, max_value=size, places=places), min_size=2, max_size=2, unique=True)))
        ys = sorted(draw(st.lists(decimals(min_value=0, max_value=size, places=places), min_size=2, max_size=2, unique=True)))
        zones_toml.append(_box_toml("travel", {ref_axis: xs[0], lim_axis: ys[0]}, {ref_axis: xs[1], lim_axis: ys[1]}, False))
        start = {ref_axis: (xs[0] + xs[1]) / 2, lim_axis: (ys[0] + ys[1]) / 2}
    elif kind == "polygon":
        poly = draw(polygons(plane=(ref_axis, lim_axis), max_value=size, places=places, name="outline").filter(_polygon_ok))
        zones_toml.append(_polygon_toml(poly))
        c = polygon_centre(poly)
        start = {ref_axis: c[0], lim_axis: c[1]}
    else:
        raise ValueError(f"allow_kinds: unknown kind {kind!r}; use 'stepped', 'box' or 'polygon'")
    if forbid_boxes and draw(st.booleans()):
        a = draw(st.lists(decimals(min_value=0, max_value=size, places=places), min_size=2, max_size=2, unique=True))
        b = draw(st.lists(decimals(min_value=0, max_value=size, places=places), min_size=2, max_size=2, unique=True))
        zones_toml.append(_box_toml("clamp", {ref_axis: min(a), lim_axis: min(b)}, {ref_axis: max(a), lim_axis: max(b)}, True))
    start.update({a: Fraction(0) for a in axes[2:]})
    has_z = "Z" in axes[2:]
    tools: dict[int, Fraction] = {}
    if has_z:
        z_top = size_q / 2
        zones_toml.append(_box_toml("z travel", {"Z": Fraction(0)}, {"Z": z_top}, False))
        start["Z"] = z_top * Fraction(4, 5)
        if tool_lengths:
            for register in (1, 2):
                tools[register] = draw(decimals(min_value=size_q / 40, max_value=size_q / 8, places=places))
        if tip_zones and draw(st.booleans()):
            a = draw(st.lists(decimals(min_value=0, max_value=size, places=places), min_size=2, max_size=2, unique=True))
            b = draw(st.lists(decimals(min_value=0, max_value=size, places=places), min_size=2, max_size=2, unique=True))
            top = draw(decimals(min_value=size_q / 20, max_value=size_q / 5, places=places))
            zones_toml.append(
                _box_toml("vise", {ref_axis: min(a), lim_axis: min(b), "Z": Fraction(0)},
                          {ref_axis: max(a), lim_axis: max(b), "Z": top}, True, point="tip")
            )
    rapid_mode = draw(st.sampled_from(tuple(rapid_modes)))
    rates = {a: draw(st.sampled_from(("6000", "8000", "12000"))) for a in axes}
    g55 = {ref_axis: draw(st.sampled_from(("-5", "2.5", "10")))}
    if has_z:
        g55["Z"] = draw(st.sampled_from(("0", "-2", "3.5")))
    lines = [
        "[machine]",
        'name = "generated"',
        f"axes = [{', '.join(repr(a).replace(chr(39), chr(34)) for a in axes)}]",
        f'pulse = "{pulse}"',
        f'rapid_mode = "{rapid_mode}"',
        'monitor_period_ms = "2"',
        "[machine.rapid]",
        *(f'{a} = "{rates[a]}"' for a in axes),
        "[machine.reference]",
        *(f'{a} = "{format_decimal(start[a])}"' for a in axes),
        "[offsets]",
        "G54 = { " + ", ".join(f'{a} = "0"' for a in axes) + " }",
        "G55 = { " + ", ".join(f'{a} = "{v}"' for a, v in g55.items()) + " }",
    ]
    if tools:
        lines += ["[tool_lengths]", *(f'H{n} = "{_text(v)}"' for n, v in tools.items())]
    return "\n".join(lines + zones_toml)


def machines(**kwargs: Any) -> st.SearchStrategy[Machine]:
    """Loaded :class:`~nczones.machine.Machine` values; takes the keywords of :func:`machine_files`.

    Draws whose start point falls inside the optional forbid box are skipped.

    Examples
    --------
    >>> from hypothesis import find
    >>> m = find(machines(axes=("X", "Y", "Z"), allow_kinds=("box",)), lambda m: True)
    >>> m.axis_names, m.allowed.contains(m.point(m.start))
    (('X', 'Y', 'Z'), True)
    """
    from .errors import MachineFileError

    def load(text: str) -> Machine | None:
        try:
            return parse_machine(text, "generated.toml")
        except MachineFileError as exc:
            if all(d.code == "ZN130" for d in exc.diagnostics):
                return None
            raise

    return cast("st.SearchStrategy[Machine]", machine_files(**kwargs).map(load).filter(lambda m: m is not None))


def boundary_values(machine: Machine, axis: str) -> tuple[Fraction, ...]:
    """Every zone boundary value of ``axis`` in the machine (sorted, unique).

    Polygon vertices count on both of their plane's axes; a tool-tip zone's
    values are as the tip sees them.
    """
    values: set[Fraction] = set()
    for z in machine.zones:
        values.update(BOUNDARY_VALUES(z, axis))
    return tuple(sorted(values))


def _bounds_values(z: Zone, axis: str) -> list[Fraction]:
    return [v for a, (lo, hi) in z.bounds().items() if a == axis for v in (lo, hi) if v is not None]


#: The zone's boundary values on one axis (:func:`boundary_values`), per zone kind.  Fallback: its bounds.
BOUNDARY_VALUES: KindTable[Callable[[Any, str], list[Fraction]]] = KindTable(
    "testing.boundary_values", fallback=_bounds_values)
BOUNDARY_VALUES.set(BoxZone, _bounds_values)


@BOUNDARY_VALUES.register(SteppedZone)
def _stepped_values(z: SteppedZone, axis: str) -> list[Fraction]:
    values: list[Fraction] = []
    if axis == z.reference_axis:
        values.append(z.start)
        values += z.uptos
    if axis == z.limited_axis:
        values += [v for r in z.regions for v in (r.min, r.max) if v is not None]
    return values


@BOUNDARY_VALUES.register(PolygonZone)
def _polygon_values(z: PolygonZone, axis: str) -> list[Fraction]:
    values: list[Fraction] = []
    if axis in z.plane:
        k = z.plane.index(axis)
        values += [v[k] for v in z.vertices]
    return values + _bounds_values(z, axis)


@st.composite
def _coordinate(draw: st.DrawFn, machine: Machine, axis: str, places: int, boundary_bias: float,
                shift: Fraction = Fraction(0)) -> Fraction:
    pulse = machine.axis(axis).pulse
    bounds = boundary_values(machine, axis)
    if bounds and draw(st.floats(0, 1)) < boundary_bias:
        base = draw(st.sampled_from(bounds))
        nudge = draw(st.sampled_from((0, 0, 1, -1, 2, -2, 5, -5)))
        return base + nudge * pulse + (shift if _tip_value(machine, axis, base) else 0)
    margin = (bounds[-1] - bounds[0]) / 50 if len(bounds) > 1 else Fraction(20)
    lo = bounds[0] - margin if bounds else Fraction(-100)
    hi = bounds[-1] + margin if bounds else Fraction(100)
    return draw(decimals(min_value=lo, max_value=hi, places=places))


def _tip_value(machine: Machine, axis: str, value: Fraction) -> bool:
    """Is ``value`` a boundary of a tool-tip zone on the tool axis (seen shifted by the tool length)?"""
    from .zones import ZonePoint

    if axis != machine.tool_axis:
        return False
    for z in machine.zones:
        if z.point is ZonePoint.TIP and any(value in (lo, hi) for a, (lo, hi) in z.bounds().items() if a == axis):
            return True
    return False


@st.composite
def _inside_point(draw: st.DrawFn, machine: Machine, axes: Sequence[str], pos: dict[str, Fraction],
                  tool_length: Fraction, places: int) -> dict[str, Fraction]:
    """A point of the allowed set (rejection sampling in its bounding box, a few tries)."""
    box = machine.allowed.bounding_box()
    cand = dict(pos)
    for _ in range(4):
        for a in axes:
            lo, hi = box.get(a, (None, None))
            lo = pos[a] - 50 if lo is None else lo
            hi = pos[a] + 50 if hi is None else hi
            if lo > hi:
                lo, hi = hi, lo
            cand[a] = draw(decimals(min_value=lo, max_value=hi, places=places))
        if machine.allowed.contains(cand, tool_length):
            break
    return {a: cand[a] for a in axes}


@st.composite
def programs(
    draw: st.DrawFn,
    machine: Machine,
    *,
    min_blocks: int = 1,
    max_blocks: int = 8,
    axes: Sequence[str] | None = None,
    arcs: bool = True,
    rapids: bool = True,
    incremental: bool = True,
    offsets: bool = True,
    subprograms: bool = False,
    tool_changes: bool = True,
    boundary_bias: float = 0.6,
    inside_bias: float = 0.0,
    places: int = 3,
    mix: dict[str, int] | None = None,
) -> str:
    """Valid G-code text for ``machine``.

    Moves are drawn in machine coordinates, then written in the program's
    own frame: G54/G55 absolute or G91 incremental, with the active tool
    length (``G43 Hn``) subtracted from Z.  Each target is, by the knobs,
    a point of the allowed set (``inside_bias``), a zone boundary value or
    a few pulses either side of one (``boundary_bias``: to touch, run
    along or barely cross boundaries; one axis is sometimes kept so the
    move runs along a boundary), or a free value a little beyond the zones.

    ``axes`` are the axes that move (default: the first two, and ``Z`` if
    the machine has it).  Arcs (G2/G3 in G17, when X and Y move) are
    quarter, half, three-quarter or full circles with I J centres, so their
    end points lie exactly on the circle.  ``tool_changes`` adds
    ``G43 Hn``/``G49`` blocks with a Z move when Z moves and the machine has
    tool lengths.  ``subprograms`` moves the tail of the program into
    ``O100`` called by ``M98 P100``.  ``mix`` gives relative weights of the
    block kinds ``"line"``, ``"rapid"``, ``"arc"`` and ``"tool"`` (default
    2:1:1:1; kinds switched off by the other knobs stay off).  Every number is a decimal with at most
    ``places`` digits (plus the machine's own decimals); the first block is
    ``G21 G90 G17 G54 G94``.

    Examples
    --------
    >>> from hypothesis import Phase, find, settings
    >>> from nczones.gcode import segments_text
    >>> any_one = settings(phases=[Phase.generate])  # the first match will do: no shrinking
    >>> m = find(machines(axes=("X", "Y", "Z")), lambda m: True, settings=any_one)
    >>> text = find(programs(m, min_blocks=4), lambda t: "G43" in t and "G2" in t, settings=any_one)
    >>> len(segments_text(text, m)) >= 4
    True
    """
    names = machine.axis_names
    if axes is None:
        axes = tuple(names[:2]) + (("Z",) if "Z" in names[2:] else ())
    axes = tuple(axes)
    pos = dict(zip(names, machine.start))
    tool_axis = machine.tool_axis if machine.tool_axis in axes else None
    registers = sorted(machine.tool_lengths) if tool_changes and tool_axis else []
    offset_names = ["G54"] + (["G55"] if offsets and "G55" in machine.offsets else [])
    feed = draw(st.sampled_from(("300", "600", "1200", "3000")))
    lines = ["%", f"G21 G90 G17 G54 G94 F{feed}"]
    frame = "G54"
    distance = "G90"
    tool_length = Fraction(0)
    can_arc = arcs and "X" in axes and "Y" in axes
    body: list[str] = []
    n = draw(st.integers(min_blocks, max_blocks))
    for _ in range(n):
        weights = {"line": 2, "rapid": 1, "arc": 1, "tool": 1, **(mix or {})}
        enabled = {"line": True, "rapid": rapids, "arc": can_arc, "tool": bool(registers)}
        choices = [k for k, w in weights.items() if enabled.get(k) for _ in range(w)] or ["line"]
        what = draw(st.sampled_from(choices))
        words: list[str] = []
        if offsets and len(offset_names) > 1 and draw(st.integers(0, 4)) == 0:
            frame = draw(st.sampled_from(offset_names))
            words.append(frame)
        if incremental and what != "tool":
            new_distance = draw(st.sampled_from(("G90", "G90", "G91")))
            if new_distance != distance:
                distance = new_distance
                words.append(distance)
        off = dict(zip(names, machine.offset(frame)))
        if what == "tool":
            assert tool_axis is not None  # "tool" is enabled only with a tool axis (registers)
            if distance != "G90":
                distance = "G90"
                words.append("G90")
            if tool_length and draw(st.integers(0, 2)) == 0:
                words.append("G49")
                tool_length = Fraction(0)
            else:
                h = draw(st.sampled_from(registers))
                words.append(f"G43 H{h}")
                tool_length = machine.tool_length(h)
            target = dict(pos)
            if draw(st.floats(0, 1)) < inside_bias:
                target.update(draw(_inside_point(machine, (tool_axis,), pos, tool_length, places)))
            else:
                target[tool_axis] = draw(_coordinate(machine, tool_axis, places, boundary_bias, tool_length))
            words.append(draw(st.sampled_from(("G0", "G1"))))
            words += _words((tool_axis,), target, pos, distance, off, tool_axis, tool_length)
        elif what == "arc":
            a, b = "X", "Y"
            radius = draw(decimals(min_value=Fraction(1, 10), max_value=max(Fraction(1), _extent(machine) / 12), places=places))
            direction = draw(st.sampled_from(((1, 0), (0, 1), (-1, 0), (0, -1))))
            ca, cb = pos[a] + direction[0] * radius, pos[b] + direction[1] * radius
            quarter = draw(st.integers(1, 4))
            clockwise = draw(st.booleans())
            va, vb = pos[a] - ca, pos[b] - cb
            for _ in range(quarter % 4):
                va, vb = (vb, -va) if clockwise else (-vb, va)
            target = dict(pos)
            target.update({a: ca + va, b: cb + vb})
            words.append("G2" if clockwise else "G3")
            words += _words((a, b), target, pos, distance, off, tool_axis, tool_length)
            words += [f"I{format_decimal(ca - pos[a])}", f"J{format_decimal(cb - pos[b])}"]
        else:
            target = dict(pos)
            if draw(st.floats(0, 1)) < inside_bias:
                target.update(draw(_inside_point(machine, axes, pos, tool_length, places)))
            else:
                for ax in axes:
                    target[ax] = draw(_coordinate(machine, ax, places, boundary_bias,
                                                  tool_length if ax == tool_axis else Fraction(0)))
            if draw(st.integers(0, 3)) == 0:  # run along a boundary: keep one axis
                keep = draw(st.sampled_from(axes))
                target[keep] = pos[keep]
            if tool_axis and draw(st.integers(0, 2)):  # mostly planar moves
                target[tool_axis] = pos[tool_axis]
            words.append("G0" if what == "rapid" else "G1")
            words += _words(axes, target, pos, distance, off, tool_axis, tool_length)
        body.append(" ".join(words))
        pos = target
    if subprograms and body and draw(st.booleans()):
        split = draw(st.integers(0, len(body) - 1))
        sub = body[split:]
        lines += body[:split] + ["M98 P100", "M30", "O100", *sub, "M99", "%"]
    else:
        lines += body + ["M30", "%"]
    return "\n".join(lines) + "\n"


def _extent(machine: Machine) -> Fraction:
    box = machine.allowed.bounding_box()
    spans = [hi - lo for lo, hi in box.values() if lo is not None and hi is not None]
    return max(spans) if spans else Fraction(100)


def _words(axes: Sequence[str], target: dict[str, Fraction], pos: dict[str, Fraction], distance: str,
           off: dict[str, Fraction], tool_axis: str | None, tool_length: Fraction) -> list[str]:
    out = []
    for a in axes:
        if distance == "G91":
            out.append(f"{a}{format_decimal(target[a] - pos[a])}")
        else:
            tl = tool_length if a == tool_axis else 0
            out.append(f"{a}{format_decimal(target[a] - off[a] - tl)}")
    return out
