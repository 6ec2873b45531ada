"""Machines built directly for the prover tests (shared by several test modules)."""

from fractions import Fraction as F

from nczones.machine import parse_machine


def machine_text(regions, forbid_box, rapid_mode):
    """A machine with the generated zones (built directly: the loader would refuse
    a reference position outside the zones, which these tests do not need)."""
    from dataclasses import replace

    from nczones.zones import AllowedSet, BoxZone, Region, SteppedZone

    base = parse_machine(f"""
[machine]
axes = ["X", "Y"]
rapid_mode = "{rapid_mode}"
[machine.rapid]
X = "3000"
Y = "1000"
[machine.reference]
X = "0"
Y = "0"
""")
    zones = [SteppedZone("table", "X", "Y", F(-5), tuple(
        Region(F(u), None if lo is None else F(lo), None if hi is None else F(hi)) for u, lo, hi in regions))]
    if forbid_box:
        x0, x1, y0, y1 = forbid_box
        zones.append(BoxZone("clamp", (("X", F(x0), F(x1)), ("Y", F(y0), F(y1))), forbid=True))
    return replace(base, allowed=AllowedSet(tuple(zones), base.allowed.tool_axis))
