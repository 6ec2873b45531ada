"""A G71/G72 cycle (or G70 with D) whose start point is the start of the profile's last piece.

LinuxCNC's ``g7x::add_distance`` (interp_g7x.cc) decides the side of the offset from
``imag(v1 / v2)``, ``v2 = back()->sp() - front()->sp()``: here 0, a complex division by zero.  GCC's
``__divdc3`` returns ``(copysign(inf, c) * a, copysign(inf, c) * b)`` for a zero divisor, so the test
``imag(angle) < 0`` is ``v1.imag < 0`` (NaN, false, when it is 0) and the cycle runs on; nczones raised
ZeroDivisionError and made the cycle ``unknown`` ("the profile is degenerate").  About 5 % of generated
G70-G72 cycles with their start on the profile were such (all 15 of one generated run now match rs274).

Expected motion: ``rs274 -g`` (LinuxCNC 2.9.0~pre1) on PROGRAM, recorded in LOG below (X Z in mm, the cycle
block's passes: G72 with D0.5 then G70 with D0.5).
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.oracles.rs274 import canon_motion, compare, machine_text

PROGRAM = """G18 G21 G90 F400
O100 SUB
G0 X2 Z1
G1 X3 Z0
O100 ENDSUB
G72 Q100 X2 Z0 D0.5 I0.5 R0.3
G70 Q100 X2 Z0 D0.5 P1
M2
"""
LOG = """    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    9 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
   10 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   11 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, -0.0000, 0.0000, 0.0000, 0.0000)
   12 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, -0.0000, 0.0000, 0.0000, 0.0000)
   13 N..... STRAIGHT_FEED(2.2929, 0.0000, -0.0000, 0.0000, 0.0000, 0.0000)
   14 N..... STRAIGHT_TRAVERSE(2.1464, 0.0000, -0.1464, 0.0000, 0.0000, 0.0000)
   15 N..... STRAIGHT_TRAVERSE(2.1464, 0.0000, -0.1464, 0.0000, 0.0000, 0.0000)
   16 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, -0.0000, 0.0000, 0.0000, 0.0000)
   17 N..... STRAIGHT_TRAVERSE(1.7265, 0.0000, 0.5000, 0.0000, 0.0000, 0.0000)
   18 N..... STRAIGHT_FEED(1.7929, 0.0000, 0.5000, 0.0000, 0.0000, 0.0000)
   19 N..... STRAIGHT_TRAVERSE(1.7597, 0.0000, 0.4668, 0.0000, 0.0000, 0.0000)
   20 N..... STRAIGHT_TRAVERSE(1.7597, 0.0000, 0.4668, 0.0000, 0.0000, 0.0000)
   21 N..... STRAIGHT_TRAVERSE(1.7265, 0.0000, 0.5000, 0.0000, 0.0000, 0.0000)
   22 N..... STRAIGHT_TRAVERSE(1.6464, 0.0000, 0.6464, 0.0000, 0.0000, 0.0000)
   23 N..... STRAIGHT_FEED(2.6464, 0.0000, -0.3536, 0.0000, 0.0000, 0.0000)
   24 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   25 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, 1.0000, 0.0000, 0.0000, 0.0000)
   26 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, 1.0000, 0.0000, 0.0000, 0.0000)
   27 N..... STRAIGHT_FEED(3.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
"""

MACHINE_TEXT = machine_text(("X", "Z"), {1: Fraction(0)})


def test_the_cycles_move_as_rs274_printed():
    outcome = compare(PROGRAM, parse_machine(MACHINE_TEXT), canon_motion(LOG), None)
    assert outcome.status == "match", outcome.detail


ZONES = '''
[[zones]]
name = "chuck"
kind = "box"
forbid = true
min = { X = "3.2", Z = "-5" }
max = { X = "10", Z = "-0.2" }
'''


@pytest.mark.parametrize("lane", ["short", "many", "hash"])
def test_verify_proves_the_cycles(lane):
    """No move of the log enters the chuck box (X above 3.2 below Z -0.2: the deepest feed ends at X2.6464
    Z-0.3536); nczones proved nothing of it before (unknown).  The last G70 feed ends at X3 Z0, the profile's
    end, and the box 0.2 below it stays clear."""
    text = PROGRAM
    if lane == "many":
        text = PROGRAM.replace("G72", "".join(f"G1 X{2 + (k % 2)} Z1\n" for k in range(600)) + "G0 X2 Z0\nG72", 1)
    elif lane == "hash":
        text = "#1 = 0.5\n" + PROGRAM.replace("D0.5 I0.5", "D#1 I#1")
    r = verify_text(text, parse_machine(MACHINE_TEXT + ZONES))
    assert r.verdict.label == "safe", r


def test_verify_finds_the_deepest_g72_feed():
    """A box around the deepest G72 feed's end (X2.6464 Z-0.3536 in the log) is entered: unsafe, first at the G72
    (the G70 after it starts there, inside the box, so it violates too)."""
    box = '''
[[zones]]
name = "pin"
kind = "box"
forbid = true
min = { X = "2.6", Z = "-0.4" }
max = { X = "2.7", Z = "-0.3" }
'''
    r = verify_text(PROGRAM, parse_machine(MACHINE_TEXT + box))
    assert r.verdict.label == "unsafe" and min(v.line for v in r.violations) == 6
