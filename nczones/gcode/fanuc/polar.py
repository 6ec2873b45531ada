"""Polar coordinate interpolation (G12.1 / G13.1, Haas G112 / G113) on a Fanuc turning centre: its state and
tables (the blocks are executed by :class:`~nczones.gcode.fanuc.lathe.FanucLatheInterpreter`).

``G12.1`` switches the mode on, ``G13.1`` off (each in a block of its own;
plane, feed-mode and G40 codes may share it).  In the mode the program is a
path in a Cartesian plane fixed to the workpiece (:mod:`nczones.geometry.polar`):
the linear axis X (its words read as elsewhere on this machine: diameters on
a ``diameter_axes`` axis, ``U`` incremental) and the *hypothetical axis*
written with the rotary axis' address C (millimetres; ``H`` incremental in G
code system A), with the centre of rotation at X0 C0 of the workpiece
system.  The hypothetical axis is 0 when the mode starts, and the angle 0 of
the plane is where the tool stands then (Fanuc: "polar interpolation is
started assuming the angle of 0 for the position of the tool when G12.1 is
specified").  Motion:

* ``G01`` is a straight line in the plane, ``G02``/``G03`` an arc with
  ``I`` (X, radius) ``J`` (hypothetical axis) or ``R`` — each one
  ``SegmentKind.POLAR`` segment whose end is the machine position the control
  reaches, X and C rounded to their least increments;
* other axes (Z) may move with a ``G01`` (linearly along the path); an arc
  moves X and C only (a helix is ``unknown``).

Errors (``file:line:column``): GC234 a G code the mode does not allow (G00
and positioning, coordinate system changes, cycles, planes and units inside
the mode, G12.1 twice), GC235 a word the mode does not allow (K, an arc
without I/J or R), GC236 a machine without the axes X and C, GC330 an arc
that cannot be drawn.  ``unknown`` with the reason: the tool at or below the
centre of rotation when the mode starts, a path through the centre (C would
have to turn at once), nose radius compensation, parameter ranges, a tool
offset change in the mode.
"""

from __future__ import annotations

from fractions import Fraction
from math import isqrt

from ..blocks import Block
from ..interpreter import gkey

__all__ = ["PolarState", "POLAR_ON", "POLAR_OFF", "ALLOWED_IN_MODE", "REFUSED_WHY", "WITH_SWITCH", "mentions_polar",
           "round_sqrt_to_grid", "round_to_grid"]

POLAR_ON = frozenset((121, 1120))
POLAR_OFF = frozenset((131, 1130))
SWITCH = POLAR_ON | POLAR_OFF
#: G codes that may share the block of G12.1/G13.1: plane, feed mode, G40.
WITH_SWITCH = frozenset((170, 180, 190, 980, 990, 940, 950, 400))
#: G codes allowed in the mode (Fanuc's list: G01-G03, G04, G40-G42, G65-G67, G90/G91, G94/G95 or G98/G99).
ALLOWED_IN_MODE = frozenset((10, 20, 30, 40, 400, 410, 420, 650, 660, 670, 900, 910, 940, 950, 980, 990))
REFUSED_WHY = {
    0: "positioning (G00) is not allowed in polar coordinate interpolation mode (Fanuc allows G01-G03 only); "
       "cancel the mode with G13.1 first",
    270: "reference position return check (G27) is not allowed in polar coordinate interpolation mode",
    280: "reference position return (G28) is not allowed in polar coordinate interpolation mode",
    300: "G30 is not allowed in polar coordinate interpolation mode",
    530: "G53 (machine coordinates) is not allowed in polar coordinate interpolation mode",
    500: "the coordinate system cannot be changed in polar coordinate interpolation mode",
    920: "the coordinate system cannot be changed in polar coordinate interpolation mode",
    520: "the coordinate system cannot be changed (G52) in polar coordinate interpolation mode",
    170: "the plane is fixed to X and the hypothetical axis in polar coordinate interpolation mode",
    180: "the plane is fixed to X and the hypothetical axis in polar coordinate interpolation mode",
    190: "the plane is fixed to X and the hypothetical axis in polar coordinate interpolation mode",
    200: "units cannot be changed in polar coordinate interpolation mode",
    210: "units cannot be changed in polar coordinate interpolation mode",
    121: "polar coordinate interpolation is already on",
    1120: "polar coordinate interpolation is already on",
}


def mentions_polar(block: Block) -> bool:
    """Does the block hold G12.1/G13.1/G112/G113?"""
    for w in block.words:
        if w.letter == "G" and gkey(w.value) in SWITCH:
            return True
    return False


class PolarState:
    """The active mode: where the centre of rotation is, the angle reference, the current plane point."""

    __slots__ = ("ix", "ic", "x_off", "c_entry", "point", "turns", "grid")

    def __init__(self, ix: int, ic: int, x_off: Fraction, c_entry: Fraction, point: tuple[Fraction, Fraction],
                 grid: tuple[Fraction, Fraction]):
        self.ix, self.ic = ix, ic
        self.x_off, self.c_entry = x_off, c_entry
        self.point = point
        self.turns = 0
        self.grid = grid


def round_sqrt_to_grid(q: Fraction, g: Fraction) -> Fraction:
    """``sqrt(q)`` rounded to the grid ``g`` (halves up), exactly.

    >>> round_sqrt_to_grid(Fraction(2), Fraction(1, 1000)), round_sqrt_to_grid(Fraction(25, 4), Fraction(1))
    (Fraction(707, 500), Fraction(3, 1))
    """
    s = q / (g * g)  # n = round(sqrt(s)): the largest n with (n - 1/2)**2 <= s
    n = isqrt(s.numerator // s.denominator)
    while (n + Fraction(1, 2)) ** 2 <= s:
        n += 1
    while n > 0 and (n - Fraction(1, 2)) ** 2 > s:
        n -= 1
    return n * g


def round_to_grid(v: Fraction, g: Fraction) -> Fraction:
    return (v / g + Fraction(1, 2)).__floor__() * g
