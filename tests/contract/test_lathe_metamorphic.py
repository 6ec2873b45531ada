"""Metamorphic soundness of `safe` on lathes: the issue-18 relations where turning meets ranges and margins.

The relations are those of :mod:`tests.contract.metamorphic` (a range verdict against its concrete values,
every `unsafe` witness replayed at its own values; a margin as clearance against a shifted path); here
they run on what the mill suite does not draw: diameter programming, Fanuc lathe tool offsets that move
the tip zones (``T0101``), G71/G72 roughing passes generated from a contour (both dialects) and the G70
finishing pass, work offsets and the start position as ranges, a block-delete line inside the contour.

CI size: a few dozen examples; the long profile (``HYPOTHESIS_PROFILE=long``) runs 1,000 of each.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.exact import format_decimal
from nczones.machine import parse_machine

from .metamorphic import check_margins, check_ranges
from .strategies import roughing_profiles

F = Fraction


def _examples(ci: int) -> int:
    return 1_000 if settings.default.max_examples > 100 else ci


@st.composite
def lathe_machines_and_programs(draw):
    """A lathe (X radius in the machine, Z; jaws and a tailstock as forbidden tip zones) and a program with a
    roughing cycle over a monotone contour, written in diameters or radii; Fanuc lathes use a tool offset."""
    dialect = draw(st.sampled_from(["linuxcnc", "fanuc"]))
    diameter = draw(st.booleans())
    points, top, depth, retract = draw(roughing_profiles())
    g54_z = draw(st.sampled_from([0, 5, -3]))
    tool_x, tool_z = (draw(st.sampled_from([0, 10, 25])), draw(st.sampled_from([0, 8]))) \
        if dialect == "fanuc" else (0, 0)
    # jaws and tailstock in tip coordinates (machine minus the tool offset), near the passes
    jz = points[-1][0] + g54_z + draw(st.integers(-3, 2))
    jx = draw(st.integers(points[0][1], top + 1))
    tail_z = g54_z + draw(st.integers(3, 8))
    tail_x = draw(st.integers(0, top + 2))
    zones = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "0", Z = "-40" }\n'
             'max = { X = "80", Z = "60" }\n'
             f'[[zones]]\nname = "jaws"\nkind = "box"\nforbid = true\npoint = "tip"\n'
             f'min = {{ X = "{jx}", Z = "{jz - 6}" }}\nmax = {{ X = "{jx + 2}", Z = "{jz}" }}\n'
             f'[[zones]]\nname = "tailstock"\nkind = "box"\nforbid = true\npoint = "tip"\n'
             f'min = {{ X = "0", Z = "{tail_z}" }}\nmax = {{ X = "{tail_x}", Z = "{tail_z + 10}" }}\n')
    fanuc = (f'[tool_offsets]\n1 = {{ X = "{tool_x}", Z = "{tool_z}" }}\n[fanuc]\ng71_retract = "0.5"\n'
             if dialect == "fanuc" else "")
    machine = parse_machine(
        f'[machine]\ntype = "lathe"\ndialect = "{dialect}"\naxes = ["X", "Z"]\npulse = "0.01"\n'
        + ('diameter_axes = ["X"]\n' if diameter else "")
        + f'tool_axis = "Z"\n[machine.rapid]\nX = "3000"\nZ = "{draw(st.sampled_from(["3000", "6000"]))}"\n'
        + f'[machine.reference]\nX = "{30 + tool_x}"\nZ = "{20 + g54_z + tool_z}"\n'
        + f'[offsets]\nG54 = {{ X = "0", Z = "{g54_z}" }}\n' + fanuc + zones, "lathe.toml")
    k = 2 if diameter else 1
    delete = draw(st.integers(-1, len(points) - 1))  # a contour line behind the block-delete switch
    if dialect == "linuxcnc":
        lines = [f"{'/' if i == delete else ''}G1 X{k * x} Z{z}" for i, (z, x) in enumerate(points)]
        body = "\n".join(lines) + f"\nX{k * top}"
        cycle = draw(st.sampled_from([f"G71 Q1 X{k * top} Z2 D0 I{depth} R{retract}",
                                      f"G71 Q1 X{k * top} Z2 D0.2 I{depth} R{retract}",
                                      f"G70 Q1 X{k * top} Z2 D0.5 E0 P2"]))
        text = f"G18 G21 G54 F100\no1 sub\n{body}\no1 endsub\nG0 X{k * top} Z4\n{cycle}\nG0 X{k * 30} Z20\nM2\n"
    else:
        shape = [f"N10 G00 X{k * points[0][1]}."] + [
            f"{'/' if i == delete else ''}G01 X{k * x}. Z{z}." for i, (z, x) in enumerate(points)] + [
            f"N20 X{k * top}."]
        finish = "G70 P10 Q20\n" if draw(st.booleans()) else ""
        text = (f"G21 G18 G98 G54 F100.\nT0101\nG00 X{k * top}. Z2.\nG71 U{depth} R{retract}\n"
                f"G71 P10 Q20 U0. W0.\n" + "\n".join(shape) + "\n" + finish + f"G00 X{k * 30}. Z20.\nM30\n")
    return machine, text


@st.composite
def lathe_ranges(draw):
    """A lathe case and one or two ranges of work offsets or the start position (deviations, mm)."""
    machine, text = draw(lathe_machines_and_programs())
    names = draw(st.lists(st.sampled_from(["G54.X", "G54.Z", "start.X", "start.Z"]), min_size=1, max_size=2,
                          unique=True))
    out = []
    for name in names:
        width = draw(st.sampled_from((F(2, 100), F(1, 2), F(1), F(3))))
        lo = draw(st.sampled_from((F(0), -width / 2, -width, F(1, 100), F(-3, 2))))
        out.append(f"{name}={format_decimal(lo)}..{format_decimal(lo + width)}")
    return machine, text, tuple(out)


@st.composite
def lathe_margins(draw):
    machine, text = draw(lathe_machines_and_programs())
    margin = draw(st.sampled_from((F(1, 100), F(1, 10), F(1, 2), F(2))))
    frac = [draw(st.sampled_from((F(0), F(1, 3), F(-1, 2), F(9, 10), F(-99, 100)))) for _ in range(2)]
    return machine, text, margin, {a: margin * f for a, f in zip("XZ", frac)}


@settings(max_examples=_examples(20), deadline=None)
@given(lathe_ranges())
def test_a_lathe_range_verdict_holds_at_its_concrete_values(case):
    machine, text, params = case
    check_ranges(machine, text, params)


@settings(max_examples=_examples(10), deadline=None)
@given(lathe_margins())
def test_a_lathe_margin_is_clearance(case):
    machine, text, margin, shift = case
    check_margins(machine, text, margin, shift)
