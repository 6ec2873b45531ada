"""The double pass's quick arc boxes and the motion before an arc (issue 36, helper lcnarcs36).

The pass boxes an R arc by the discs of radius ``2|R|`` about its ends, or (``R > 0``) by the disc on its chord,
and an I/J arc by its centre +- its larger radius (``double_arcs.r_screen``, ``ij_screen``); a proof narrows a
box to the sweep's (``DoublePath.refine``) only when it does not fit.  Checked here:

- every screen holds the exact arc: 200-bit points of the full path's arc (its ends, 64 points of its sweep at
  both radii, its axis extremes: ``tests.gcode.test_double_pass.arc_points``, which computes the centre from the
  segment alone, LinuxCNC's ``arc_data_r``); the R screen accepts only arcs ``r_arc`` accepts (whose test says
  the full path takes them: neither GC302 nor GC303);
- the refined boxes hold the arcs too, in programs the pass runs;
- a program's first motion of length 0 (``G0 X0 Y0`` at the start, as CAM posts and the bench files begin)
  before an arc no longer makes the pass decline: the full path skips a motion of length 0 and notes a short one
  as dropped only after another motion (``CornerCheck._segment``/``_dropped_corner``), so the arc is proved
  from its own start.  The arc's extreme is taken from rs274's ARC_FEED (its centre and radius), the verdicts
  are the full path's, and the pass proves the program (its stats), short, past 512 motions and with ``#``;
- plain arc programs of more than 512 lines, now routed to the pass (``_small_plain``), get the verdicts of the
  full path run without the pass and without the vectorized tier (``fast=False``).
"""

from __future__ import annotations

import math
import os
import shutil
from decimal import Decimal, localcontext
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc.double_arcs import ij_arc, ij_screen, r_arc, r_screen
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.motion import Plane, Segment, SegmentKind
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import arc_programs, check_arc_in_box
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import both_ways, same_outcome

AXES = ("X", "Y", "Z")
EXAMPLES = int(os.environ.get("NCZONES_ARC_SCREEN_EXAMPLES", "60"))
coord = st.integers(-40000, 40000).map(lambda n: Fraction(n, 1000))


def _box(b: tuple[float, float, float, float]) -> tuple[dict[str, Fraction], dict[str, Fraction]]:
    return {"X": Fraction(b[0]), "Y": Fraction(b[2])}, {"X": Fraction(b[1]), "Y": Fraction(b[3])}


@settings(max_examples=2 * EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200)
@given(coord, coord, coord, coord, st.sampled_from([0.5000001, 0.500001, 0.51, 0.7, 1.0, 3.0, 250.0]),
       st.booleans(), st.booleans())
def test_the_r_screen_holds_the_exact_arc(sx, sy, ex, ey, factor, clockwise, major):
    chord = math.hypot(float(ex - sx), float(ey - sy))
    assume(chord > 0)
    radius = Fraction(math.ceil(chord * factor * 1000), 1000)  # a word of 3 decimals, at least half the chord
    r = -radius if major else radius
    f = [float(v) for v in (sx, sy, ex, ey)]
    screen = r_screen(*f, float(r), 0.0)
    if isinstance(r_arc(*f, float(r), clockwise, 0.0), str):
        assert isinstance(screen, str), "the screen takes an arc r_arc declines"
    if isinstance(screen, str):
        return
    seg = Segment(SegmentKind.ARC, (sx, sy, Fraction(0)), (ex, ey, Fraction(0)), AXES, plane=Plane.XY,
                  clockwise=clockwise, radius=r)
    check_arc_in_box(seg, *_box(screen))


@settings(max_examples=2 * EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200)
@given(coord, coord, st.integers(-30000, 30000), st.integers(-30000, 30000), st.floats(-7, 7),
       st.sampled_from([0, 0, 1, -1, 5, -20]), st.booleans())
def test_the_ij_screen_holds_the_exact_arc(sx, sy, i, j, turn, off, clockwise):
    # the end on the circle turned by `turn` radians, moved off it by `off` thousandths along its radius: a
    # spiral the full path accepts when within the arc tolerance (ij_arc declines the others, as the screen)
    i, j = Fraction(i, 1000), Fraction(j, 1000)
    cx, cy = sx + i, sy + j
    r0 = math.hypot(float(i), float(j))
    assume(r0 > 0.01)
    a = math.atan2(float(-j), float(-i)) + turn
    rad = r0 + off / 1000
    ex = Fraction(round((float(cx) + rad * math.cos(a)) * 1000), 1000)
    ey = Fraction(round((float(cy) + rad * math.sin(a)) * 1000), 1000)
    f = [float(v) for v in (sx, sy, ex, ey, i, j)]
    screen = ij_screen(*f, clockwise, 0.0, 0.002)
    assert isinstance(screen, str) == isinstance(ij_arc(*f, clockwise, 0.0, 0.002), str)
    if isinstance(screen, str):
        return
    seg = Segment(SegmentKind.ARC, (sx, sy, Fraction(0)), (ex, ey, Fraction(0)), AXES, plane=Plane.XY,
                  clockwise=clockwise, centre=(cx, cy))
    check_arc_in_box(seg, *_box(screen))


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(arc_programs())
def test_the_refined_boxes_hold_the_full_paths_arcs(text):
    machine = _machine("1000")
    try:
        path = double_pass(text, machine, max_iterations=1000)
    except Declined:
        return
    screens = [path.enclosure(k, k) for k in range(1, path.motions + 1)]
    path.refine(1, path.motions)
    segments = list(interpret_text(text, machine, max_loop_iterations=1000).segments())
    for k, seg in enumerate(segments, start=1):
        if seg.kind is SegmentKind.ARC:
            lo, hi = path.enclosure(k, k)
            check_arc_in_box(seg, lo, hi)
            assert all(screens[k - 1][0][a] <= lo[a] and hi[a] <= screens[k - 1][1][a] for a in lo)


# -- a first motion of length 0 before an arc ----------------------------------------------------------------

#: A mill starting at (0, 0, 0) in G64, with no work offsets (box_5000, pulse 0.0001); its zone's Y face at
#: ``ymax`` (:func:`_machine`).
_TRAVEL_MAX = 'max = { X = "5000", Y = "5000", Z = "5000" }'
#: From the start (0, 0, 0): G0 to it (length 0), then G2 from (0, 0) to (8, 0) with R5.
ZERO_THEN_ARC = ["G0 X0 Y0", "G2 X8 Y0 R5", "G1 X0 Y0"]


def _decimal(v: Fraction) -> str:
    """``v`` (a decimal fraction) as decimal text."""
    with localcontext() as ctx:
        ctx.prec = 60
        return str(Decimal(v.numerator) / Decimal(v.denominator))


def _machine(ymax: str):
    text = machine_text("box_5000", set={"machine.pulse": "0.0001", "machine.dialect": "linuxcnc"})
    assert _TRAVEL_MAX in text
    return parse_machine(text.replace(_TRAVEL_MAX, f'max = {{ X = "5000", Y = "{ymax}", Z = "5000" }}'))


def _variant(lines: list[str], variant: str) -> str:
    head, body = "G21 G90 G17 G54 F300\n", "\n".join(lines) + "\n"
    if variant == "long":  # past 512 motions: the first is still the G0 of length 0
        body += ("\n".join(lines[1:]) + "\n") * 300
    if variant == "hash":
        head += "#1 = 0\n"
    return head + body + "M30\n"


def _rs274_extreme(text: str, tmp_path) -> Fraction:
    """The largest Y of the program's first arc, from rs274's canonical log: its centre's Y plus its radius
    (the distance of the arc's end from its centre; the sweep of a G2 from (0, 0) to (8, 0) about a centre
    below the chord passes the top of the circle)."""
    from tests.oracles.rs274 import canon_motion
    from tests.tools.rs274_diff import FINDING_SETUP, run_rs274

    _moves, error, log = run_rs274(text, FINDING_SETUP, tmp_path, timeout=20)
    assert error is None, error
    moves = canon_motion(log)
    assert moves[0].kind == "RAPID" and moves[0].end[:3] == (0, 0, 0)  # the motion of length 0 is in the log
    arc = next(m for m in moves if m.kind == "ARC")
    assert arc.centre is not None and arc.direction < 0  # clockwise
    cx, cy = arc.centre
    radius = math.hypot(float(arc.end[0] - cx), float(arc.end[1] - cy))
    assert abs(radius - 5) < 1e-3 and cy < 0
    return cy + Fraction(radius).limit_denominator(1000)


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
@pytest.mark.parametrize("variant", ["short", "long", "hash"])
def test_a_first_motion_of_length_0_then_an_arc(monkeypatch, tmp_path, variant):
    text = _variant(ZERO_THEN_ARC, variant)
    top = _rs274_extreme(_variant(ZERO_THEN_ARC, "short"), tmp_path)  # LinuxCNC: centre (4, -3), R 5: top Y = 2
    assert top == 2
    for ymax, verdict, by_pass in ((top + Fraction(1, 1000), Verdict.SAFE, True),
                                   (top - Fraction(1, 10**14), Verdict.UNSAFE, False),
                                   (Fraction(1000), Verdict.SAFE, True)):
        machine = _machine(_decimal(ymax))
        with_pass, without = both_ways(text, machine, monkeypatch)
        same_outcome(with_pass, without)
        assert with_pass.verdict is verdict, (ymax, with_pass.reasons)
        # (a short plain program is not given to the pass; past 512 motions, 300 arcs each 0.001 from the face
        # need a box each, beyond the pass's box budget: the full path decides those)
        if by_pass and (variant == "hash" or (variant == "long" and ymax == 1000)):
            assert "double_pass_boxes" in dict(with_pass.stats), "the pass proves the arc after the G0 of length 0"


@pytest.mark.parametrize("first", ["G0 X0.0000001 Y0", "G1 X5 Y0\nG0 X5 Y0"])
def test_a_short_motion_after_another_before_an_arc_still_declines(first):
    # a motion that may be dropped after another motion: the full path notes the dropped corner (the arc run
    # from it is not modelled); the pass leaves it to the full path.  A first motion of 1e-7 mm: its doubles
    # differ from the start's, which the pass does not take either.
    text = "G21 G90 G17 G54 F300\n#1 = 0\n" + first + "\nG2 X8 Y0 R5\nM30\n"
    with pytest.raises(Declined, match="blended corner"):
        double_pass(text, _machine("1000"), max_iterations=100)


def test_the_zero_motion_then_arc_is_taken_by_the_pass():
    path = double_pass(_variant(ZERO_THEN_ARC, "hash"), _machine("1000"), max_iterations=100)
    assert path.arcs == 1 and path.motions == 3


# -- plain arc programs past 512 lines: the pass against fast=False ------------------------------------------

@settings(max_examples=max(3, EXAMPLES // 15), deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(arc_programs(), st.sampled_from(["1000", "30", "8", "2.5"]))
def test_plain_arc_programs_past_512_lines_get_the_full_paths_verdict(monkeypatch, text, ymax):
    _past_512(monkeypatch, text, ymax)


@pytest.mark.long
@settings(max_examples=int(os.environ.get("NCZONES_ARC_SCREEN_HUNT", "300")), deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(arc_programs(), st.sampled_from(["1000", "30", "8", "2.5", "0.5"]))
def test_plain_arc_programs_past_512_lines_hunt(monkeypatch, text, ymax):
    _past_512(monkeypatch, text, ymax)


def _past_512(monkeypatch, text: str, ymax: str) -> None:
    import nczones.pipeline.verification as verification
    from nczones.prover import verify_text

    lines = [line for line in text.splitlines() if "#" not in line and line != "M30"]
    plain = "\n".join(lines * (600 // max(1, len(lines)) + 1)) + "\nM30\n"
    assume("#" not in plain and 512 < plain.count("\n") <= verification.PLAIN_PASS_SIZE)
    machine = _machine(ymax)
    try:
        routed = verify_text(plain, machine)
    except Exception as exc:  # noqa: BLE001  # a G-code error: the same error on the full path
        with monkeypatch.context() as m:
            m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
            m.setattr(verification, "interpretation", _slow(verification.interpretation))
            with pytest.raises(type(exc)):
                verify_text(plain, machine)
        return
    with monkeypatch.context() as m:
        m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
        m.setattr(verification, "interpretation", _slow(verification.interpretation))
        full = verify_text(plain, machine)
    same_outcome(routed, full)


def _slow(interpretation):
    """``interpretation`` with the vectorized tier off (``fast=False``)."""
    def run(*args, **kwargs):
        kwargs["fast"] = False
        return interpretation(*args, **kwargs)
    return run
