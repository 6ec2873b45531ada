"""DESIGN §7 on generated lathe programs with roughing cycles: the prover's verdict on every generated pass
against the reference controller running the same passes pulse by pulse (LinuxCNC G71/G70 with a profile
subroutine, in radius or diameter mode; Fanuc G71 with its N-block shape; LinuxCNC G41.1/G42.1 nose
compensation with a lathe tool orientation), near chuck jaws placed where the passes may or may not reach."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine

from .contract import check_contract
from .strategies import roughing_profiles


def _lathe(dialect: str, extra: str, jaws_min: tuple[int, int], jaws_max: tuple[int, int], travel_min_x: int = 0):
    """A lathe (X radius, Z, pulse 0.01) inside a travel box, with chuck jaws ``(x, z)`` as a forbidden box."""
    zones = (f'[[zones]]\nname = "travel"\nkind = "box"\nmin = {{ X = "{travel_min_x}", Z = "-40" }}\n'
             'max = { X = "40", Z = "40" }\n[[zones]]\nname = "jaws"\nkind = "box"\nforbid = true\n'
             f'min = {{ X = "{jaws_min[0]}", Z = "{jaws_min[1]}" }}\nmax = {{ X = "{jaws_max[0]}", Z = "{jaws_max[1]}" }}\n')
    return parse_machine(
        f'[machine]\ntype = "lathe"\ndialect = "{dialect}"\naxes = ["X", "Z"]\npulse = "0.01"\n' + extra
        + '[machine.rapid]\nX = "3000"\nZ = "3000"\n[machine.reference]\nX = "30"\nZ = "20"\n' + zones, "lathe.toml")


@st.composite
def lathe_cases(draw):
    """A lathe (X radius, Z; jaws as a forbidden box) and a program with a G71 cycle over a monotone profile."""
    dialect = draw(st.sampled_from(["linuxcnc", "fanuc"]))
    diameter = draw(st.booleans())
    points, top, depth, retract = draw(roughing_profiles())
    jz = points[-1][0] + draw(st.integers(-3, 2))
    jx = draw(st.integers(points[0][1], top + 1))
    extra = ('diameter_axes = ["X"]\n' if diameter else "") + (
        '[fanuc]\ng71_retract = "0.5"\n' if dialect == "fanuc" else "")
    machine = _lathe(dialect, extra, (jx, jz - 6), (jx + 2, jz))
    k = 2 if diameter else 1
    if dialect == "linuxcnc":
        body = "\n".join(f"G1 X{k * x} Z{z}" for z, x in points) + f"\nX{k * top}"
        cycle = draw(st.sampled_from([f"G71 Q1 X{k * top} Z2 D0 I{depth} R{retract}",
                                      f"G71 Q1 X{k * top} Z2 D0.2 I{depth} R{retract}",
                                      f"G70 Q1 X{k * top} Z2 D0.5 E0 P2"]))
        text = f"G18 G21 F100\no1 sub\n{body}\no1 endsub\nG0 X{k * top} Z4\n{cycle}\nG0 X{k * 30} Z20\nM2\n"
    else:
        shape = [f"N10 G00 X{k * points[0][1]}."] + [f"G01 X{k * x}. Z{z}." for z, x in points] + [f"N20 X{k * top}."]
        text = (f"G21 G18 G98 F100.\nG00 X{k * top}. Z2.\nG71 U{depth} R{retract}\nG71 P10 Q20 U0. W0.\n"
                + "\n".join(shape) + f"\nG00 X{k * 30}. Z20.\nM30\n")
    return machine, text


@st.composite
def nose_compensation_cases(draw):
    """A LinuxCNC lathe turning a stepped profile with G41.1/G42.1 D L (a lathe tool orientation 0-9): the
    controlled point is the nose centre moved by the orientation, next to jaws the path may or may not reach."""
    orientation = draw(st.integers(0, 9))
    diameter = draw(st.sampled_from(["0.4", "0.8", "1.6"]))
    side = draw(st.sampled_from(["G42.1", "G41.1"]))
    x, z = draw(st.integers(4, 8)), 2
    zc = z - draw(st.integers(3, 6))
    moves = [f"G1 Z{zc}"]
    for _ in range(draw(st.integers(1, 3))):  # a staircase: X up, Z on towards the chuck (no concave gouge)
        x += draw(st.integers(1, 3))
        zc -= draw(st.integers(3, 8))
        moves += [f"X{x}", f"Z{zc}"]
    jx = draw(st.integers(4, x + 2))
    machine = _lathe("linuxcnc", 'cutter_compensation = "linuxcnc"\n', (jx, -24), (jx + 3, -15), -5)
    text = (f"G18 G8 G21 F100\nG0 X{x + 4} Z{z + 3}\nG0 X4 Z{z}\n"
            f"{side} D{diameter} L{orientation}\n" + "\n".join(moves) + "\nG40 G0 X30\nZ20\nM2\n")
    return machine, text


@settings(max_examples=45)
@given(st.one_of(lathe_cases(), nose_compensation_cases()))
def test_prover_and_controller_agree_on_generated_lathe_programs(case):
    """Roughing cycles (G71, G70) in both dialects and LinuxCNC nose compensation with every orientation."""
    machine, text = case
    check_contract(machine, text)
