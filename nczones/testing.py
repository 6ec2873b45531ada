"""Hypothesis strategies for nczones: zone tables, machines and G-code programs.

Use them to property-test your own post-processor or machine files::

    from hypothesis import given
    from nczones.testing import machines, programs

    @given(data=st.data())
    def test_my_post_never_leaves_the_table(data):
        machine = data.draw(machines())
        text = data.draw(programs(machine))
        ...

Every number is an exact decimal (a :class:`~fractions.Fraction` with a
power-of-ten denominator) and is rendered into the text as a decimal, so the
G-code parser is exercised as well.  Generated programs are biased towards
the zones' boundaries: they run along them, touch them, and cross them by a
few pulses, which is where provers and controllers disagree if either is
wrong.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

from hypothesis import strategies as st

from .exact import format_decimal
from .machine import Machine, parse_machine
from .zones import Region, SteppedZone

__all__ = ["decimals", "zone_tables", "machine_files", "machines", "programs", "boundary_values"]


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


@st.composite
def machine_files(
    draw: st.DrawFn,
    *,
    axes: Sequence[str] = ("X", "Y"),
    rapid_modes: Sequence[str] = ("linear", "dogleg"),
    pulse: str = "0.001",
    forbid_boxes: bool = True,
    places: int = 1,
) -> str:
    """Machine files (TOML text) with a stepped table on the first two axes.

    The table lies in ``[0, 1000]`` on both axes; optionally a forbid box
    sits inside it.  The start position is drawn inside the allowed set, so
    the text always loads.
    """
    ref_axis, lim_axis = axes[0], axes[1]
    table = draw(
        zone_tables(reference_axis=ref_axis, limited_axis=lim_axis, places=places, name="table").filter(
            lambda z: any(r.min is None or r.max is None or r.min < r.max for r in z.regions)
        )
    )
    zones_toml = [_stepped_toml(table)]
    if forbid_boxes and draw(st.booleans()):
        a = draw(st.lists(decimals(min_value=0, max_value=1000, places=places), min_size=2, max_size=2, unique=True))
        b = draw(st.lists(decimals(min_value=0, max_value=1000, places=places), min_size=2, max_size=2, unique=True))
        zones_toml.append(
            "\n".join(
                [
                    "[[zones]]",
                    'name = "clamp"',
                    'kind = "box"',
                    "forbid = true",
                    f'min = {{ {ref_axis} = "{_text(min(a))}", {lim_axis} = "{_text(min(b))}" }}',
                    f'max = {{ {ref_axis} = "{_text(max(a))}", {lim_axis} = "{_text(max(b))}" }}',
                ]
            )
        )
    # A start point strictly inside one region of the table (exact midpoint).
    i = draw(st.integers(0, len(table.regions) - 1))
    reg = table.regions[i]
    lower = table.start if i == 0 else table.regions[i - 1].upto
    r = (lower + reg.upto) / 2 if i else lower
    lo = reg.min if reg.min is not None else (reg.max - 10 if reg.max is not None else Fraction(0))
    hi = reg.max if reg.max is not None else lo + 10
    lim = (lo + hi) / 2
    rapid_mode = draw(st.sampled_from(tuple(rapid_modes)))
    rates = {a: draw(st.sampled_from(("6000", "8000", "12000"))) for a in axes}
    start = {ref_axis: r, lim_axis: lim}
    start.update({a: Fraction(0) for a in axes[2:]})
    text = "\n".join(
        [
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
            "G55 = { " + f'{ref_axis} = "{draw(st.sampled_from(("-5", "2.5", "10")))}"' + " }",
            *zones_toml,
        ]
    )
    return text


def machines(**kwargs) -> st.SearchStrategy[Machine]:
    """Loaded :class:`~nczones.machine.Machine` values; see :func:`machine_files`.

    Draws whose start point falls inside the optional forbid box are skipped.
    """
    from .errors import MachineFileError

    def load(text: str) -> Machine | None:
        try:
            return parse_machine(text, "generated.toml")
        except MachineFileError as exc:
            if all(d.code == "ZN130" for d in exc.diagnostics):
                return None
            raise

    return machine_files(**kwargs).map(load).filter(lambda m: m is not None)


def boundary_values(machine: Machine, axis: str) -> tuple[Fraction, ...]:
    """Every zone boundary value of ``axis`` in the machine (sorted, unique)."""
    values: set[Fraction] = set()
    for z in machine.zones:
        if z.kind == "stepped":
            if axis == z.reference_axis:
                values.add(z.start)
                values.update(z.uptos)
            if axis == z.limited_axis:
                values.update(v for r in z.regions for v in (r.min, r.max) if v is not None)
        else:
            for a, (lo, hi) in z.bounds().items():
                if a == axis:
                    values.update(v for v in (lo, hi) if v is not None)
    return tuple(sorted(values))


@st.composite
def _coordinate(draw: st.DrawFn, machine: Machine, axis: str, places: int, boundary_bias: float) -> Fraction:
    pulse = machine.axis(axis).pulse
    bounds = boundary_values(machine, axis)
    if bounds and draw(st.floats(0, 1)) < boundary_bias:
        base = draw(st.sampled_from(bounds))
        nudge = draw(st.sampled_from((0, 0, 1, -1, 2, -2, 5, -5)))
        return base + nudge * pulse
    lo = bounds[0] - 20 if bounds else Fraction(-100)
    hi = bounds[-1] + 20 if bounds else Fraction(100)
    return draw(decimals(min_value=lo, max_value=hi, places=places))


@st.composite
def programs(
    draw: st.DrawFn,
    machine: Machine,
    *,
    min_blocks: int = 1,
    max_blocks: int = 8,
    arcs: bool = True,
    rapids: bool = True,
    incremental: bool = True,
    offsets: bool = True,
    subprograms: bool = False,
    boundary_bias: float = 0.6,
    places: int = 3,
) -> str:
    """Valid G-code text for ``machine`` (first two axes move; others stay).

    Moves are drawn in machine coordinates (targets biased to the zones'
    boundaries, and a few pulses either side), then written in the program's
    own frame: G54/G55 absolute or G91 incremental.  Arcs are quarter, half,
    three-quarter or full circles with I J centres, so their end points lie
    exactly on the circle.  Every number is a decimal with at most ``places``
    digits; the first block is ``G21 G90 G17 G54 G94``.
    """
    a, b = machine.axis_names[0], machine.axis_names[1]
    pos = {a: machine.start[0], b: machine.start[1]}
    offset_names = ["G54"] + (["G55"] if offsets and "G55" in machine.offsets else [])
    lines = ["%", "G21 G90 G17 G54 G94 F600"]
    frame = "G54"
    distance = "G90"
    body: list[str] = []
    n = draw(st.integers(min_blocks, max_blocks))
    for _ in range(n):
        choices = ["line"] + (["rapid"] if rapids else []) + (["arc"] if arcs else [])
        what = draw(st.sampled_from(choices))
        words: list[str] = []
        if offsets and len(offset_names) > 1 and draw(st.integers(0, 4)) == 0:
            frame = draw(st.sampled_from(offset_names))
            words.append(frame)
        if incremental:
            new_distance = draw(st.sampled_from(("G90", "G90", "G91")))
            if new_distance != distance:
                distance = new_distance
                words.append(distance)
        off = machine.offset(frame)
        off_a, off_b = off[0], off[1]
        if what == "arc":
            radius = draw(decimals(min_value=Fraction(1, 10), max_value=80, places=places))
            direction = draw(st.sampled_from(((1, 0), (0, 1), (-1, 0), (0, -1))))
            ca, cb = pos[a] + direction[0] * radius, pos[b] + direction[1] * radius
            quarter = draw(st.integers(1, 4))
            clockwise = draw(st.booleans())
            va, vb = pos[a] - ca, pos[b] - cb
            for _ in range(quarter % 4):
                va, vb = (vb, -va) if clockwise else (-vb, va)
            end = {a: ca + va, b: cb + vb}
            words.append("G2" if clockwise else "G3")
            target = end
            words += _axis_words(a, b, target, pos, distance, off_a, off_b)
            words += [f"I{format_decimal(ca - pos[a])}", f"J{format_decimal(cb - pos[b])}"]
        else:
            target = {
                a: draw(_coordinate(machine, a, places, boundary_bias)),
                b: draw(_coordinate(machine, b, places, boundary_bias)),
            }
            if draw(st.integers(0, 3)) == 0:  # run along a boundary: keep one axis
                keep = draw(st.sampled_from((a, b)))
                target[keep] = pos[keep]
            words.append("G0" if what == "rapid" else "G1")
            words += _axis_words(a, b, target, pos, distance, off_a, off_b)
        body.append(" ".join(words))
        pos = target
    if subprograms and body and draw(st.booleans()):
        split = draw(st.integers(0, len(body) - 1))
        sub = body[split:]
        lines += body[:split] + ["M98 P100", "M30", "O100", *sub, "M99", "%"]
    else:
        lines += body + ["M30", "%"]
    return "\n".join(lines) + "\n"


def _axis_words(a, b, target, pos, distance, off_a, off_b) -> list[str]:
    if distance == "G91":
        return [f"{a}{format_decimal(target[a] - pos[a])}", f"{b}{format_decimal(target[b] - pos[b])}"]
    return [f"{a}{format_decimal(target[a] - off_a)}", f"{b}{format_decimal(target[b] - off_b)}"]
