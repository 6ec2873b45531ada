"""M70-M73 save and restore LinuxCNC's path control mode (G61 / G61.1 / G64 P Q), and the corners see it.

LinuxCNC's ``save_settings`` keeps the path control mode with its tolerances, and ``restore_settings`` (M72, and
the return of a subroutine that ran M73) writes ``G61``, ``G61.1`` or ``G64 P Q`` back when the saved numbers
differ from the current ones, after restoring the units.  rs274 2.9.0~pre1 (``rs274 -g``) shows it: after
``M70 / G61 / M72`` it prints ``SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.000000)``; after ``G64 P1 / M70 /
G64 P0.001 / M72`` it prints ``SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 1.000000)``; and after ``G21 G64 P1 /
G20 / M70 / G61 / M72`` it prints ``CONTINUOUS, 1.000000`` under ``USE_LENGTH_UNITS(CANON_UNITS_INCHES)`` (the
canonical layer reads it in inches: 25.4 mm).  nczones forgot the path mode on restore, so a program that
switched to G61 inside an M70/M72 pair or an M73 subroutine had its later corners proved on the exact path:
a wrong ``safe``.  The expected modes here are read from rs274's own log (:func:`_rs274_modes`), never from
nczones; the verdicts from the enclosure of specs/path-modes.md.
"""

from __future__ import annotations

import re
import shutil
from fractions import Fraction

import pytest

from nczones.gcode import interpret_text
from nczones.prover import verify_text
from nczones.prover.blend import BLEND_CODE
from tests.machines import load_machine
from tests.prover.test_blending import machine

INCH = Fraction(254, 10)
L_CORNER = "G1 F100 X100 Y0\nG1 X100 Y100\n"  # the L corner around `clamp` X95..99 Y1..5

# Programs whose last motions (the L corner) run in a restored G64 (no tolerance, or a wide one): the corner
# may pass the clamp 1 mm inside it (specs/path-modes.md §2: the half-motion parallelogram; with P2, Q = P,
# up to 4 mm from the path), so the verdict is `unknown` (VF208), never `safe`.
RESTORED = {
    "m70-g61-m72": "M70\nG61\nM72\n" + L_CORNER,
    "m70-g61.1-m72": "M70\nG61.1\nM72\n" + L_CORNER,
    "m73-subroutine": "o100 sub\nM73\nG61\no100 endsub\no100 call\n" + L_CORNER,
    "m72-tolerance": "G64 P2\nM70\nG64 P0.001\nM72\n" + L_CORNER,
    "m73-tolerance": "G64 P2\no100 sub\nM73\nG64 P0.001\no100 endsub\no100 call\n" + L_CORNER,
    "m72-in-inch": "G21 G64 P1\nG20\nM70\nG61\nM72\nG21\n" + L_CORNER,
}

# No restore: the G61 of a subroutine without M73 stays (rs274: no SET_MOTION_CONTROL_MODE on return), M71
# invalidates the M73 context; the corner is on the exact path and clears the clamp by 1 mm.
KEPT = {
    "subroutine-without-m73": "o100 sub\nG61\no100 endsub\no100 call\n" + L_CORNER,
    "m73-then-m71": "o100 sub\nM73\nG61\nM71\no100 endsub\no100 call\n" + L_CORNER,
}


def _rs274_modes(program: str, tmp_path) -> list[tuple[bool, Fraction | None]]:
    """(blend, tolerance in mm) in force at each STRAIGHT_FEED of rs274's log, read from its
    ``USE_LENGTH_UNITS`` and ``SET_MOTION_CONTROL_MODE`` calls (the canonical layer converts the tolerance with
    the units in force, ``FROM_PROG_LEN``)."""
    from tests.tools.rs274_diff import FINDING_SETUP, run_rs274

    _moves, error, log = run_rs274(program + "M2\n", FINDING_SETUP, tmp_path, timeout=20)
    assert error is None, error
    unit, mode, out = Fraction(1), (True, None), []
    for line in log.splitlines():
        if "USE_LENGTH_UNITS" in line:
            unit = INCH if "INCHES" in line else Fraction(1)
        elif m := re.search(r"SET_MOTION_CONTROL_MODE\((\w+)(?:, ([0-9.]+))?\)", line):
            tol = Fraction(m.group(2)) * unit if m.group(2) else None
            mode = (m.group(1) == "CANON_CONTINUOUS", tol or None)
        elif "STRAIGHT_FEED" in line:
            out.append(mode)
    return out


def _nczones_modes(program: str) -> list[tuple[bool, Fraction | None]]:
    run = interpret_text(program, machine())
    segs = list(run.segments())
    table = run.interpreter.path_modes
    modes = []
    for s in segs:
        mode = [m for first, m in table if first <= s.block][-1]
        modes.append((mode.blend, mode.tolerance if mode.blend else None))
    return modes


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
@pytest.mark.parametrize("name", sorted({**RESTORED, **KEPT}))
def test_the_path_mode_after_a_restore_is_rs274s(name, tmp_path):
    program = {**RESTORED, **KEPT}[name]
    assert _nczones_modes(program) == _rs274_modes(program, tmp_path)


@pytest.mark.parametrize("name", sorted(RESTORED))
def test_a_corner_in_a_restored_g64_is_not_safe(name):
    r = verify_text(RESTORED[name], machine())
    assert r.verdict.label == "unknown" and not r.violations
    assert [x for x in r.reasons if x.code == BLEND_CODE]


@pytest.mark.parametrize("name", sorted(KEPT))
def test_a_corner_in_a_kept_g61_is_safe(name):
    assert verify_text(KEPT[name], machine()).verdict.label == "safe"


# The same restore before > 512 motions (the vectorized tier proves the corners of column chunks) and with
# '#' in the text (the double pass): the L corner comes last, after 600 short moves far from the clamp.
FILLER = "".join(f"G1 X{10 + i % 7} Y{20 + i % 5}\n" for i in range(600))


@pytest.mark.parametrize("name", ["m70-g61-m72", "m73-subroutine", "m72-tolerance"])
@pytest.mark.parametrize("lane", ["vectorized", "double pass"])
def test_the_restore_holds_in_every_lane(name, lane):
    head, _, tail = RESTORED[name].partition(L_CORNER)
    assert not tail
    program = head + "F100\n" + FILLER + "G1 X0 Y0\n" + ("#1 = 100\nG1 X#1 Y0\nG1 X#1 Y100\n" if lane == "double pass"
                                          else "G1 X100 Y0\nG1 X100 Y100\n")
    r = verify_text(program, machine())
    assert r.verdict.label == "unknown" and not r.violations
    assert [x for x in r.reasons if x.code == BLEND_CODE]
    # the same program kept in G61 (no M72 / M73 restore) is safe: the restore, not the filler, decides
    assert verify_text(program.replace("M72\n", "").replace("M73\n", "").replace("G64 P2\n", ""),
                       machine()).verdict.label == "safe"


# G20/G21 and M70/M72 in the block of the G64 itself (found by hunt36).  LinuxCNC's convert_g sets the length
# units before the path control mode, and convert_m (M70-M73) runs before convert_g: rs274 2.9.0~pre1 prints
# ``USE_LENGTH_UNITS(CANON_UNITS_INCHES)`` before ``SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.040000)`` for
# ``G20 G64 P0.04``, so P is 0.04 inch = 1.016 mm (Q = P: the corner may pass 2.032 mm from the path, the clamp is
# 1 mm from it: `unknown`).  nczones read P in the units before the block (0.04 mm: bound 0.08 mm), and proved the
# L corner `safe`.  ``M70 G64 P2`` saves the mode before the block's G64 (rs274: ``M72`` then prints
# ``CANON_EXACT_PATH``).
IN_BLOCK_UNSAFE = {
    "g20-g64-one-block": "G20 G64 P0.04\nG21\n" + L_CORNER,
    "g64-g20-one-block": "G64 G20 P0.04 Q0.04\nG21\n" + L_CORNER,
}
IN_BLOCK_KEPT = {
    "m70-g64-one-block": "G61\nM70 G64 P2\nM72\n" + L_CORNER,
}


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
@pytest.mark.parametrize("name", sorted({**IN_BLOCK_UNSAFE, **IN_BLOCK_KEPT}))
def test_the_path_mode_of_a_block_with_units_or_m70_is_rs274s(name, tmp_path):
    program = {**IN_BLOCK_UNSAFE, **IN_BLOCK_KEPT}[name]
    assert _nczones_modes(program) == _rs274_modes(program, tmp_path)


@pytest.mark.parametrize("name", sorted(IN_BLOCK_UNSAFE))
@pytest.mark.parametrize("lane", ["short", "vectorized", "double pass"])
def test_g64_p_read_in_the_blocks_units(name, lane):
    program = IN_BLOCK_UNSAFE[name]
    if lane != "short":
        head, _, _tail = program.partition(L_CORNER)
        program = head + "F100\n" + FILLER + "G1 X0 Y0\n" + (
            "#1 = 100\nG1 X#1 Y0\nG1 X#1 Y100\n" if lane == "double pass" else "G1 X100 Y0\nG1 X100 Y100\n")
    r = verify_text(program, machine())
    assert r.verdict.label == "unknown" and not r.violations
    assert [x for x in r.reasons if x.code == BLEND_CODE]
    # in mm (P0.04 mm, bound 0.08 mm) the corner clears the clamp by 1 mm: the units decide
    assert verify_text(program.replace("G20", "G21"), machine()).verdict.label == "safe"


@pytest.mark.parametrize("name", sorted(IN_BLOCK_KEPT))
def test_m70_beside_g64_ends_in_g61(name):
    assert verify_text(IN_BLOCK_KEPT[name], machine()).verdict.label == "safe"


# M72 beside other codes (found by hunt36).  LinuxCNC 2.9's restore_settings runs the restored codes with
# ``Interp::execute(line)``, which reads each line into the interpreter's current block: when the restore runs
# anything, the rest of the M72 block (its G codes, its motion) is gone.  rs274 2.9.0~pre1 shows it
# (:func:`_rs274_feeds`): after ``G1 X0 Y0 / M70 / G61.1 / M72 G1 X100 Y0 / G1 X100 Y100`` it prints the feeds
# to (0, 0) and (100, 100) only, so the machine cuts the diagonal, through the post at X45..55 Y45..55; nczones
# moved along X first and proved the L `safe`.  Whether the restore runs depends on state nczones does not all
# follow (coolant, overrides), so M72 with anything after it in its block is `unknown`.
M72_BLOCK = "G1 X0 Y0\nM70\nG61.1\nM72 G1 X100 Y0\nG1 X100 Y100\n"


def _rs274_feeds(program: str, tmp_path) -> list[tuple[Fraction, Fraction]]:
    from tests.tools.rs274_diff import FINDING_SETUP, run_rs274

    _moves, error, log = run_rs274(program + "M2\n", FINDING_SETUP, tmp_path, timeout=20)
    assert error is None, error
    return [(Fraction(m.group(1)), Fraction(m.group(2))) for m in re.finditer(
        r"STRAIGHT_FEED\(([-0-9.]+), ([-0-9.]+),", log)]


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
def test_rs274_drops_the_rest_of_an_m72_block(tmp_path):
    assert _rs274_feeds("G61 F100\n" + M72_BLOCK, tmp_path) == [(0, 0), (100, 100)]
    # nothing to restore: the block is kept
    assert _rs274_feeds("G61 F100\nG1 X0 Y0\nM70\nM72 G1 X100 Y0\nG1 X100 Y100\n", tmp_path) == [
        (0, 0), (100, 0), (100, 100)]


@pytest.mark.parametrize("lane", ["short", "vectorized", "double pass"])
def test_m72_beside_a_motion_is_not_safe(lane):
    pad = "".join(f"G1 X{-10 - k % 7} Y{-20 - k % 5}\n" for k in range(600)) if lane != "short" else ""
    program = "G61 F100\n" + ("#1 = 100\n" if lane == "double pass" else "") + pad + M72_BLOCK + "M2\n"
    r = verify_text(program, load_machine("m72_post"))
    assert r.verdict.label == "unknown", r.verdict
    assert any(x.message.startswith("M72:") for x in r.reasons)
    # M72 alone, the motion in the next block: the L, which clears the post
    alone = program.replace("M72 G1 X100 Y0\n", "M72\nG1 X100 Y0\n")
    assert verify_text(alone, load_machine("m72_post")).verdict.label == "safe"


@pytest.mark.parametrize("block", ["M72 G64 P2", "M72 G20", "M72 M8", "M72 X5"])
def test_m72_beside_other_codes_is_unknown(block):
    r = verify_text("G61\nM70\nG64 P0.001\n" + block + "\n" + L_CORNER, machine())
    assert r.verdict.label == "unknown"
    assert any(x.message.startswith("M72:") for x in r.reasons)
