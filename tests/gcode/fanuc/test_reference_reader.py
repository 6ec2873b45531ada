"""The reference reader (tests/oracles/fanuc_ref.py) on the manuals' worked examples: it must reproduce them
before it may judge nczones."""

from __future__ import annotations

from fractions import Fraction as Q

from tests.oracles.fanuc_ref import RefMachine, reference_motion

from .ref_differential import normalise

ZERO = {"G54": [Q(0), Q(0), Q(0)]}

# FANUC 0i-MD B-64304EN, "Tool length compensation", example (H01 = -4.0), block for block:
B64304_TLC = """G21
N1 G91 G00 X120.0 Y80.0
N2 G43 Z-32.0 H01
N3 G01 Z-21.0 F1000
N4 G04 P2000
N5 G00 Z21.0
N6 X30.0 Y-50.0
N7 G01 Z-41.0
N8 G00 Z41.0
N9 X50.0 Y30.0
N10 G01 Z-25.0
N11 G04 P2000
N12 G00 Z57.0 H00
N13 X-200.0 Y-60.0
N14 M2
"""


def test_manual_tool_length_example():
    # Z moves: N2 -32 + (-4 - 0) = -36; N3 -21; N5 +21; N7 -41; N8 +41; N10 -25;
    # N12 (H00 alone in G43 mode: the offset becomes 0) +57 + (0 - (-4)) = +61.  The Z moves sum to 0 and
    # X/Y return to the start (120 + 30 + 50 - 200 = 0, 80 - 50 + 30 - 60 = 0).
    m = RefMachine(work=dict(ZERO), lengths={1: Q(-4)})
    out = normalise(reference_motion(B64304_TLC, m))
    z = [Q(0)] + [e[2] for _, e in out]
    dz = [b - a for a, b in zip(z, z[1:]) if b != a]
    assert dz == [-36, -21, 21, -41, 41, -25, 61]
    assert out[-1][1] == (0, 0, 0)


def test_g92_sets_the_programmed_position():
    # B-64304EN "Workpiece coordinate system setting (G92)": G92 IP_ makes the current position read IP_.
    # From machine (10, 0, 0) in a zero G54: G92 X0 -> X0 is machine 10; G90 X5 -> machine 15.
    m = RefMachine(work=dict(ZERO), lengths={})
    out = reference_motion("G21\nG90 G00 X10.\nG92 X0\nX5.\nM30\n", m)
    assert [e for _, e in out] == [(10, 0, 0), (15, 0, 0)]


def test_incremental_cycle_repeats():
    # B-64304EN "Canned cycle for drilling": in G91 R is the distance from the initial level and Z from R;
    # K3 drills three holes 10 apart.  Initial Z 5: R = 5 - 3 = 2, bottom 2 - 4 = -2 (G99: back to R).
    m = RefMachine(work=dict(ZERO), lengths={})
    out = normalise(reference_motion("G21\nG90 G00 X0 Y0 Z5.\nG91 G99 G81 X10. R-3. Z-4. K3 F100.\nG80\nM30\n",
                                     m))
    assert out[1:] == [("rapid", (10, 0, 5)), ("rapid", (10, 0, 2)), ("line", (10, 0, -2)), ("rapid", (10, 0, 2)),
                       ("rapid", (20, 0, 2)), ("line", (20, 0, -2)), ("rapid", (20, 0, 2)),
                       ("rapid", (30, 0, 2)), ("line", (30, 0, -2)), ("rapid", (30, 0, 2))]


def test_g92_in_g91_adds_the_increment_to_the_reading():
    # B-64304EN "Setting a workpiece coordinate system", method using G92: "If IP_ is an incremental command
    # value, the workpiece coordinate system is defined so that the current tool position coincides with the
    # result of adding the specified incremental value to the coordinates of the previous tool position".
    # From machine X 10 (reading 10): G91 G92 X3. -> the position reads 13; G90 X15. -> machine 12.
    m = RefMachine(work=dict(ZERO), lengths={})
    out = reference_motion("G21\nG90 G00 X10.\nG91 G92 X3.\nG90 X15.\nM30\n", m)
    assert [e for _, e in out] == [(10, 0, 0), (12, 0, 0)]


def test_optional_block_skip_switches_are_nine():
    # B-64304EN "Optional block skip": a block with /n is skipped while switch n is on; '/' is '/1'.
    m = RefMachine(work=dict(ZERO), lengths={})
    text = "G21\nG90 G00 X1.\n/2 X2.\n/ X3.\n/9 X4.\nM30\n"
    ends = {sw: [e[0] for _, e in reference_motion(text, m, block_delete=sw)] for sw in ((), frozenset({2}), frozenset({1, 9}), True)}
    assert ends == {(): [1, 2, 3, 4], frozenset({2}): [1, 3, 4], frozenset({1, 9}): [1, 2], True: [1, 2, 4]}


def test_m00_m01_stop_without_motion():
    # B-64304EN "Program stop (M00)" / "Optional stop (M01)": the block is executed, then automatic
    # operation stops (modal information unchanged) until cycle start: the motion is that of the program
    # without M00/M01.
    m = RefMachine(work=dict(ZERO), lengths={})
    with_stops = reference_motion("G21\nG91 G00 X1. M00\nM01\nX2.\nM30\n", m)
    assert [e for _, e in with_stops] == [(1, 0, 0), (3, 0, 0)]


def test_lathe_g50_during_offset_sets_the_position_before_offset():
    # 0i-TD B-64304EN "Coordinate system setting": "If a coordinate system is set using G50 during offset, a
    # coordinate system in which the position before offset matches the position specified in G50 is set."
    # Machine (X radius 240, Z 650), G54 = 0, offset 1 = (X 10, Z 5) radius, LGT = 0 (a shift, no motion).
    # T0101 then G50 X200. Z300.: the position before offset (machine - work - shift) reads X 100 (radius)
    # and Z 300, on both axes alike: shift = (240 - 100, 650 - 300) = (140, 350).  G00 X100. Z300. then goes
    # to the programmed point + shift + offset = (100 + 140 + 10, 300 + 350 + 5) = (250, 655).
    from tests.oracles.fanuc_ref import RefLathe, reference_lathe_motion

    lathe = RefLathe(work={"G54": [Q(0), Q(0)]}, tool_offsets={1: (Q(10), Q(5))})
    out = reference_lathe_motion("G21\nG54\nT0101\nG50 X200. Z300.\nG00 X200. Z300.\nM30\n", lathe)
    assert out[-1][1] == (250, 655)
