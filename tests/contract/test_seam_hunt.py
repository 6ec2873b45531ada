"""Soundness hunt where features meet: G64 corners at the seams of the lanes (task t7 "hunt").

The corner proof (``specs/path-modes.md``) and the lanes that feed it (the full interpreter, the vectorized
column chunks, the double pass and its windows) each cut the motion somewhere; a corner whose two motions
fall on the two sides of such a cut is where a wrong ``safe`` hides.  Findings first (each a reproducer
through :func:`nczones.prover.verify_text` that failed before its fix), then the generated hunts.

The probe of every finding is a small forbidden box around a point the control really moves through,
derived from LinuxCNC's planner (``src/emc/tp/blendmath.c``, as quoted in specs/path-modes.md §2 and §7), off
the programmed path: the same program in ``G61`` (no blending) must be ``safe`` (so the probe is off the
path), and in ``G64`` the verdict must not be ``safe``.
"""

from __future__ import annotations

from decimal import Decimal
from unittest import mock

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import nczones.gcode.linuxcnc.doubles as pass_module
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text


def probe_machine(x0: str, y0: str, x1: str, y1: str, *, path_mode: str = "G64"):
    """``xy_fast`` on a 1000 mm table with a forbidden probe box X x0..x1 Y y0..y1."""
    extra = ('[[zones]]\nname = "table"\nkind = "box"\nmin = { X = "-500", Y = "-500" }\n'
             'max = { X = "500", Y = "500" }\n'
             f'[[zones]]\nname = "probe"\nkind = "box"\nforbid = true\nmin = {{ X = "{x0}", Y = "{y0}" }}\n'
             f'max = {{ X = "{x1}", Y = "{y1}" }}\n')
    return parse_machine(machine_text("xy_fast", set={"machine.path_mode": path_mode}, extra=extra))


# ---------------------------------------------------------------------------------------------------------
# Finding 1: the double pass proved a corner next to a motion of length 0 with the wrong neighbours.
#
# LinuxCNC's canonical layer drops a move of length 0 (and tpAddLine refuses a segment shorter than
# TP_POS_EPSILON), so the corner is between the motions around it.  The double pass proves a corner that
# falls between two of its boxes from rows k-1, k, k+1 only: with motion k+1 of length 0 that region is
# the segment from C to the midpoint of motion k, and the real blend toward motion k+2 was never tested.
# Same at the end of a window (the windows overlap by one motion): a window ending on a motion of length 0
# left the corner of the motions around it in neither window.
#
# The corner: a line along +X of 20 mm into C = (0, 0), then along +Y for 20 mm (a 90 degree turn).
# blendInit3FromLineLine: L1 = min(target, 0.5 * 20) = 10, L2 = 0.5 * 20 = 10; tcFindBlendTolerance with no
# P: T = min(20/4, 20/4) = 5; theta = 45 degrees, h_tol = T / (1 - sin theta) = 17.07, d_tol = cos theta *
# h_tol = 12.07; d_geom = min(L1, L2, d_tol) = 10, R_geom = tan theta * d_geom = 10.  At a feed high enough
# that v_goal^2 / a_n >= R_geom (F10000 is 166 mm/s: above sqrt(a_n * 10) for any a_max below 3,200 mm/s^2),
# v_plan = sqrt(a_n R_geom) and R_plan = R_geom = 10: the blend arc is tangent at (-10, 0) and (0, 10),
# centre (-10, 10), and its middle is (-10 + 10/sqrt 2, 10 - 10/sqrt 2) = (-2.929, 2.929).  The probe
# X -3.2..-2.7 Y 2.7..3.2 holds it and is 2.7 mm off both lines.
PROBE = ("-3.2", "2.7", "-2.7", "3.2")


def _corner_program(before: int, after: int, *, zero: str | None = "0", hashed: bool = True, mode: str = "") -> str:
    """``before`` motions along Y = 0, the last from (-20, 0) into C = (0, 0) (the ones before it run back and
    forth between X-400 and X-20), a motion to X``zero`` (None: none; "0": of length 0; a short one, which
    LinuxCNC's planner drops below 1e-12 mm), then ``after`` motions along X = ``zero``, the first 20 mm up to
    Y20 (the others back and forth between Y300 and Y20).  ``hashed``: a ``#`` line sends it through the double
    pass (which declines a G61 or G64 in the text: the machine starts in G64).  ``mode`` (G61): no blending,
    the control that the probe is off the path."""
    lines = [f"G21 G90 G54 {mode} F10000".replace("  ", " ")] + (["#1 = 0"] if hashed else [])
    lines += [f"G1 X{-20 if (before - 1 - k) % 2 == 0 else -400} Y0" for k in range(1, before)]
    lines.append("G1 X0 Y0")
    if zero is not None:
        lines.append(f"G1 X{zero} Y0")
    x = zero or "0"
    lines += [f"G1 X{x} Y{20 if (k - 1) % 2 == 0 else 300}" for k in range(1, after + 1)]
    return "\n".join(lines) + "\nM2\n"


@pytest.mark.parametrize("before", [2, 40])
def test_zero_motion_at_a_box_boundary_of_the_double_pass(before):
    """16 * ``before`` motions: the double pass's first split (boxes of ``before`` motions) puts a boundary
    right after the motion into C, and the motion after it has length 0.  The 640-motion variant is past
    the vectorized tier's 512 too (its full-path control goes through the column chunks)."""
    m = probe_machine(*PROBE)
    after = 16 * before - before - 1
    assert verify_text(_corner_program(before, after, mode="G61"), m).verdict.label == "safe"  # off the path
    full = verify_text(_corner_program(before, after, hashed=False), m)  # the full path: not safe
    assert full.verdict.label == "unknown" and {r.code for r in full.reasons} == {"VF208"}
    got = verify_text(_corner_program(before, after), m)
    assert got.verdict.label != "safe", "the double pass proved the blend into the probe safe"
    # and with a real motion in place of the zero one the corner is caught by the pass too
    assert verify_text(_corner_program(before, after - 1, zero=None), m).verdict.label != "safe"


def test_zero_motion_at_the_end_of_a_window(monkeypatch):
    """Windows of 8 motions: the first ends on the motion of length 0 after C (motion 8)."""
    monkeypatch.setattr(pass_module, "WINDOW", 8)
    m = probe_machine(*PROBE)
    assert verify_text(_corner_program(7, 4, mode="G61"), m).verdict.label == "safe"
    assert verify_text(_corner_program(7, 4, hashed=False), m).verdict.label == "unknown"
    assert verify_text(_corner_program(7, 4), m).verdict.label != "safe"


# Finding 2: LinuxCNC sends no move whose every axis change is below CART_FUZZ (1e-8 of the machine's
# units: emccanon.cc applyMinDisplacement zeroes each smaller change, and flush_segments appends the move only
# ``if ((vel && acc) || synched)``), and the planner drops a line under TP_POS_EPSILON (1e-12, tpAddLine); the
# corner then joins the motions around it, as for a motion of length 0.  The prover took 1e-14 mm as a
# motion and proved the two corners with it (each region a segment along one motion), never the blend of
# the two lines: `safe` with the probe on that blend (1e-14 mm; 1e-9 mm too on the vectorized tier).
TINY = "0.000000001"  # 1e-9 mm: under CART_FUZZ on this mm machine (and on the fast path's scale)


@pytest.mark.parametrize(("before", "hashed"), [(2, False), (600, False), (2, True), (40, True)])
def test_motion_shorter_than_the_planner_epsilon(before, hashed):
    """The full interpreter (a short program, and past the vectorized tier's 512 motions) and the double pass
    (``#``; 16 * ``before`` motions, a box boundary after the motion into C)."""
    m = probe_machine(*PROBE)
    after = 16 * before - before - 1 if hashed else 10
    assert verify_text(_corner_program(before, after, zero=TINY, hashed=hashed, mode="G61"), m).verdict.label == "safe"
    got = verify_text(_corner_program(before, after, zero=TINY, hashed=hashed), m)
    assert got.verdict.label != "safe", "a blend across a dropped motion was proved safe"


def test_motion_above_the_canonical_fuzz_keeps_its_corners():
    """1e-6 mm (above 1e-8 inch) is a motion LinuxCNC keeps: its two blends use at most half of it each and
    stay near C, so the probe 2.7 mm off both lines is not reached and the program stays provable."""
    m = probe_machine(*PROBE)
    assert verify_text(_corner_program(2, 10, zero="0.000001", hashed=False), m).verdict.label == "safe"


# ---------------------------------------------------------------------------------------------------------
# Hunt 1 (generated): a G64 corner whose two motions A and B fall on the two sides of a lane's seam.
#
# Oracle: the planner's own blend arc (tests/oracles/blend.py ``blend_arc``, written from blendmath.c) at a
# feed and acceleration where it is as large as the geometry allows (F10000, a_max 200 mm/s^2: v_plan =
# sqrt(a_n R_geom) up to R_geom = 160 mm, on axes that fast: the prover's enclosure does not depend on speeds,
# so the probe machine's own rapid rates do not matter); a small forbidden probe around its middle, off the
# programmed path.  Whatever sits between A and B, if LinuxCNC blends across it the verdict must not be `safe`.  Between
# A and B (each one a command the task does not wait for motion on, emctaskmain.cc
# emcTaskCheckPreconditions: it is queued WAITING_FOR_IO or DONE, so the planner still holds A when B comes):
# nothing, an F word, G61 (A was queued in G64: the blend is A's term_cond), M70 / G61 / M72 (restored),
# T2 (EMC_TOOL_PREPARE), a comment, a parameter assignment, G17 G90, B in a subroutine, B behind a block
# delete slash (the switch off runs it), a motion of length 0 or of 1e-9 mm (LinuxCNC drops both).  Seams: motions before A so that A is the last of a fast-path chunk
# or the first past one, the 512-motion tier, the double pass's windows (shrunk) and box splits.
BETWEEN = ("", "F3000", "G61", "M70\nG61\nM72", "T2", "(between)", "#2 = [#2 + 1]", "G17 G90", "sub", "slash",
           "zero", "tiny")
PADS = (0, 1, 2, 3, 4, 5, 125, 126, 127, 128, 129, 130, 253, 254, 255, 256, 257, 509, 510, 511, 512, 513, 514)
HUNT_EXAMPLES = {"ci": 4, "long": 5_000}
#: (G61 control verdict, G64 verdict) counts of the hunts run in this session (printed by the long profile)
OUTCOMES: dict[tuple[str, str], int] = {}


def _seg_dist(p, a, b):
    import math

    ab = (b[0] - a[0], b[1] - a[1])
    t = max(0.0, min(1.0, ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / (ab[0] ** 2 + ab[1] ** 2)))
    return math.hypot(p[0] - a[0] - t * ab[0], p[1] - a[1] - t * ab[1])


def _blend_middle(p0, c, p2):
    from oracles.blend import blend_arc

    arc = blend_arc(p0, c, p2, a_max=200.0, v_goal=10000 / 60)
    return arc[len(arc) // 2] if arc else None


def _seam_program(p0, c, p2, pad: int, between: str, hashed: bool) -> str:
    """``pad`` motions along Y-450, then to P0 (down X = P0.x), A to C, ``between``, B to P2, and out."""
    lines = ["G21 G90 G54 F10000"]
    sub = between == "sub"
    if sub:
        lines += ["o100 sub", f"G1 X{p2[0]} Y{p2[1]}", "o100 endsub"]
    if hashed or between.startswith("#"):
        lines.append("#2 = 0")
    lines += [f"G1 X{400 if k % 2 else -400} Y-450" for k in range(pad)]
    lines += [f"G1 X{p0[0]} Y-450", f"G1 X{p0[0]} Y{p0[1]}", f"G1 X{c[0]} Y{c[1]}"]
    if between == "zero":
        lines.append(f"G1 X{c[0]} Y{c[1]}")
    elif between == "tiny":
        lines.append(f"G1 X{Decimal(c[0]) + Decimal('1E-9'):f} Y{c[1]}")
    elif between not in ("", "sub", "slash"):
        lines += between.split("\n")
    if sub:
        lines.append("o100 call")
    else:
        lines.append(("/" if between == "slash" else "") + f"G1 X{p2[0]} Y{p2[1]}")
    lines += [f"G1 X{p2[0]} Y450", "G1 X-400 Y450", "M2"]
    return "\n".join(lines) + "\n"


def _probe_of(p0, c, p2):
    """The probe box (X lo, Y lo, X hi, Y hi as decimal text) around the blend arc's middle, or None when the
    corner has no arc or the probe would touch the programmed path (or the lead-in and lead-out lines)."""
    q = _blend_middle(p0, c, p2)
    if q is None:
        return None
    h = 0.05
    path = [((p0[0], -450.0), p0), (p0, c), (c, p2), (p2, (p2[0], 450.0))]
    if min(_seg_dist(q, a, b) for a, b in path) < 4 * h or not all(abs(v) < 440 for v in q):
        return None
    return (f"{q[0] - h:.3f}", f"{q[1] - h:.3f}", f"{q[0] + h:.3f}", f"{q[1] + h:.3f}")


def _hunt_examples() -> int:
    return HUNT_EXAMPLES["long" if settings.default.max_examples > 100 else "ci"]


_POINT = st.tuples(st.integers(-150, 150), st.integers(-150, 150))


def _corner_probe(draw_corner):
    p0, c, p2 = draw_corner
    if min(abs(p0[0] - c[0]) + abs(p0[1] - c[1]), abs(p2[0] - c[0]) + abs(p2[1] - c[1])) < 4:
        return None
    return _probe_of(tuple(map(float, p0)), tuple(map(float, c)), tuple(map(float, p2)))


def _check_seam(p0, c, p2, probe, pad, between, hashed, window):
    m = probe_machine(*probe)
    text = _seam_program(p0, c, p2, pad, between, hashed)
    with mock.patch.object(pass_module, "WINDOW", window or pass_module.WINDOW):
        got = verify_text(text, m)
        exact = verify_text(_seam_program(p0, c, p2, pad, "", hashed).replace("F10000", "G61 F10000"), m)
    OUTCOMES[(exact.verdict.label, got.verdict.label)] = OUTCOMES.get((exact.verdict.label, got.verdict.label), 0) + 1
    assert got.verdict.label != "safe", f"a blend across {between!r} into the probe proved safe:\n{text}"


@pytest.mark.parametrize("hashed", [False, True])
def test_hunt_corner_at_a_lane_seam(hashed):
    """The full interpreter and its tiers (``hashed`` False) and the double pass with windows of 3..9 motions
    (True); CI size in :data:`HUNT_EXAMPLES`."""

    @settings(max_examples=_hunt_examples(), deadline=None)
    @given(st.tuples(_POINT, _POINT, _POINT), st.sampled_from(PADS), st.sampled_from(BETWEEN),
           st.integers(3, 9))
    def run(corner, pad, between, window):
        probe = _corner_probe(corner)
        assume(probe is not None)
        if hashed:
            pad = pad % 12
        p0, c, p2 = corner
        _check_seam(p0, c, p2, probe, pad, between, hashed, window if hashed else None)

    run()


@pytest.mark.long
@pytest.mark.parametrize("hashed", [False, True])
def test_hunt_corner_at_a_lane_seam_long(hashed):
    """The long profile of the hunt (``HUNT_EXAMPLES["long"]`` each; numbers in specs/contract.md)."""
    OUTCOMES.clear()
    with mock.patch.dict(HUNT_EXAMPLES, {"ci": HUNT_EXAMPLES["long"]}):
        test_hunt_corner_at_a_lane_seam(hashed)
        if not hashed:
            test_hunt_g91_rewrite()
    print(f"seam hunt (hashed={hashed}): (G61, G64) verdicts {sorted(OUTCOMES.items())}")


@pytest.mark.parametrize("before", [2, 600])
def test_dropped_motion_in_g61_after_a_g64_motion(before):
    """A (into C) queued in G64, then G61 and a 1e-9 mm move, then B: LinuxCNC drops the short move, and the
    blend of A and B is A's (tp.c reads ``prev_tc->term_cond``, set when A was queued), so it is rounded.  The
    short move's own mode (G61) does not stop it: the fix of finding 2 first required the corner after the
    short move to be joined, and proved this program `safe`.  A dwell instead stops it: `safe`."""
    m = probe_machine(*PROBE)
    text = _corner_program(before, 10, zero=None, hashed=False)
    tiny = text.replace("G1 X0 Y0\nG1 X0 Y20", f"G1 X0 Y0\nG61\nG1 X{TINY} Y0\nG1 X0 Y20", 1)
    assert tiny != text
    assert verify_text(tiny, m).verdict.label != "safe"
    dwell = text.replace("G1 X0 Y0\nG1 X0 Y20", f"G1 X0 Y0\nG4 P0\nG61\nG1 X{TINY} Y0\nG1 X0 Y20", 1)
    assert verify_text(dwell, m).verdict.label == "safe"


# Hunt 2 (generated): the G91 rewrite of a seam program (every G1 X Y as its increment from the position before;
# xy_fast starts at its reference X0 Y0) moves the machine alike, so the verdict must be the same, and never
# `safe` with the probe on the blend.  Not with a sub or a block-delete slash (the rewrite would change them).
def _to_g91(text: str) -> str:
    import re

    out, pos = [], (Decimal(0), Decimal(0))
    for line in text.split("\n"):
        mo = re.fullmatch(r"G1 X(-?[0-9.]+) Y(-?[0-9.]+)", line)
        if mo:
            x, y = Decimal(mo.group(1)), Decimal(mo.group(2))
            out.append(f"G91 G1 X{x - pos[0]:f} Y{y - pos[1]:f}")
            pos = (x, y)
        else:
            out.append(line)
    return "\n".join(out)


def test_hunt_g91_rewrite():
    @settings(max_examples=max(2, _hunt_examples() // 3), deadline=None)
    @given(st.tuples(_POINT, _POINT, _POINT), st.sampled_from(PADS),
           st.sampled_from([b for b in BETWEEN if b not in ("sub", "slash")]))
    def run(corner, pad, between):
        probe = _corner_probe(corner)
        assume(probe is not None)
        p0, c, p2 = corner
        m = probe_machine(*probe)
        text = _seam_program(p0, c, p2, pad, between, False)
        g90, g91 = verify_text(text, m).verdict.label, verify_text(_to_g91(text), m).verdict.label
        OUTCOMES[("g90/g91", f"{g90}/{g91}")] = OUTCOMES.get(("g90/g91", f"{g90}/{g91}"), 0) + 1
        assert g90 == g91 and g91 != "safe", f"G90 {g90}, G91 {g91}:\n{_to_g91(text)}"

    run()


def test_dropped_motion_before_an_arc_is_not_proved_safe():
    """A 1e-9 mm move between a line into C = (0, 0) and a whole circle G2 I10 (centre X10, from C + 1e-9 back to
    it): LinuxCNC drops the move and runs the arc from C (tpAddCircle starts at the planner's goal), a curve
    whose start and end differ by 1e-9 mm (a whole turn or almost none), and the blend of the line and that
    curve (a 90 degree corner: the line along +X, the circle leaving C along +Y) rounds into X < 0 Y > 0, where
    the probe is.  The arc from another start is another curve: the prover gives a reason (VF208).
    Before, the corner of the line and the rewritten arc (of no sweep) was proved: `safe`."""
    m = probe_machine(*PROBE)
    text = ("G21 G90 G54 F10000\nG1 X-20 Y0\nG1 X0 Y0\nG1 X0.000000001 Y0\nG2 X0.000000001 Y0 I10 J0\n"
            "G1 X50 Y50\nM2\n")
    got = verify_text(text, m)
    assert got.verdict.label == "unknown" and {r.code for r in got.reasons} == {"VF208"}
