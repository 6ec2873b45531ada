"""Golden positions from the Fanuc manuals for the codes of specs/fanuc.md that only a turning centre
models (the rules: tests/gcode/fanuc/test_manual_examples.py; marked with ``@covers``).

The machine: a Fanuc turning centre, X a diameter axis (machine X a radius, its increment 0.0005), Z, C
in degrees (increment 0.001); G54 = (0, 200, 0) puts the work zero on the face.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction as Q

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from tests.machines import machine_text

COVERED: dict[str, list[str]] = {}


def covers(*codes: str) -> Callable:
    def mark(fn):
        for c in codes:
            COVERED.setdefault(c, []).append(fn.__name__)
        return fn
    return mark


TURNING_CENTRE = machine_text("fanuc_manual_turning_centre")


@covers("G12.1", "G13.1")
def test_polar_coordinate_interpolation():
    # [15i-M] "Polar coordinate interpolation (G12.1, G13.1)" (specs/turning.md): the program is a
    # contour in the plane of the linear axis X and the hypothetical axis (written with C's address, in
    # mm); "the virtual axis is at coordinate 0 immediately after G12.1 is specified.  Polar interpolation
    # is started assuming the angle of 0 for the position of the tool when G12.1 is specified"; the control
    # turns each plane point (x, y) into the linear axis at the distance sqrt(x^2 + y^2) from the centre and
    # the rotary axis at the angle atan2(y, x); G13.1 ends the mode.
    #   G00 X60. Z1. C0     the tool at the radius 30 (X is a diameter), angle 0: machine (30, 201, 0)
    #   G12.1               no motion; the plane point (30, 0) is angle 0
    #   G01 X60. C40. F100  the plane point (30, 40): radius sqrt(900 + 1600) = 50 exactly, angle
    #                       atan2(40, 30) = 53.1301...deg -> C 53.130 (to the 0.001 increment)
    #   C0                  back to (30, 0): radius 30, angle 0
    #   G13.1               no motion
    text = "G90 G54 G00 X60. Z1. C0\nG12.1\nG01 X60. C40. F100.\nC0\nG13.1\nM30\n"
    run = interpret_text(text, parse_machine(TURNING_CENTRE, "tc.toml"))
    segs = [s for s in run.segments() if tuple(s.start) != tuple(s.end)]
    assert run.status == "complete", run.unsupported
    assert [s.kind for s in segs] == [SegmentKind.RAPID, SegmentKind.POLAR, SegmentKind.POLAR]
    assert tuple(segs[0].end) == (Q(30), Q(201), Q(0))
    assert tuple(segs[1].end) == (Q(50), Q(201), Q("53.130"))
    assert tuple(segs[2].end) == (Q(30), Q(201), Q(0))
