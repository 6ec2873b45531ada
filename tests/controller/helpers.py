"""Shared helpers for the controller tests: small machines and segment builders."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind

F = Fraction
FAST = settings(derandomize=True, max_examples=40, deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

XYZ_FREE = """
[machine]
name = "free"
axes = ["X", "Y", "Z"]
pulse = "0.001"
rapid_mode = "{rapid}"
monitor_period_ms = "2"
[machine.rapid]
X = "6000"
Y = "4000"
Z = "3000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
{zones}
"""


def machine(zones: str = "", rapid: str = "linear", axes_pulse: str | None = None):
    text = XYZ_FREE.format(rapid=rapid, zones=zones)
    if axes_pulse:
        text = text.replace('pulse = "0.001"', axes_pulse)
    return parse_machine(text, "test.toml")


ZERO = F(0)


def line(start, end, block=0, feed="1000", kind=SegmentKind.LINE, tool_length=ZERO, axes=("X", "Y", "Z")):
    return Segment(kind, tuple(F(v) for v in start), tuple(F(v) for v in end), axes, block=block,
                   feed_mm_min=None if kind is SegmentKind.RAPID else F(feed), tool_length=tool_length)


def arc(start, end, centre, plane=Plane.XY, clockwise=False, turns=0, block=0, feed="1000",
        radius=None, axes=("X", "Y", "Z")):
    return Segment(SegmentKind.ARC, tuple(F(v) for v in start), tuple(F(v) for v in end), axes,
                   block=block, feed_mm_min=F(feed), plane=plane, clockwise=clockwise,
                   centre=None if centre is None else (F(centre[0]), F(centre[1])),
                   radius=None if radius is None else F(radius), turns=turns)


def decimals(lo: int, hi: int, places: int = 3) -> st.SearchStrategy[Fraction]:
    scale = 10**places
    return st.integers(lo * scale, hi * scale).map(lambda n: Fraction(n, scale))


def rationals(lo: int, hi: int) -> st.SearchStrategy[Fraction]:
    """Exact rationals that are not on the pulse grid (denominators 1..9 x 10**4)."""
    return st.builds(lambda n, d: Fraction(n, d * 10**4), st.integers(lo * 10**4, hi * 10**4), st.integers(1, 9)).map(
        lambda q: q if q.denominator > 1 else q)
