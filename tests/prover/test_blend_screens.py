"""The cheap screens of the corner proof (``nczones/prover/blend.py``) agree with the exact enclosure.

The corner proof runs on every verify, so its common cases are screened before any exact work (specs/
performance.md, "The corner proof, made cheap"): a column chunk's corners are tested all at once in one box,
the one-motion path compares coordinates by their numerators and denominators, an arc's box is computed on
integer vectors, and the proof is not even imported for a run of one motion (``nczones/prover/corners.py``).
Each screen is checked here against the path that has no screen:

* the one-box test of a column chunk against the one-motion exact path (the same chunks given to the check as
  segments: every corner queued, screened with the exact boxes and refined alone), on generated programs of
  more than 512 motions (lines, I/J arcs, G64 with and without P, a tiny P, P with Q, G61 stretches) next to
  a clamp whose faces go through points of the path; the same reasons word for word and the same corner
  count;
* the integer arc box against ``ArcGeom.plane_bbox`` (the exact sweep tests and square-root bounds): equal;
* the comparisons against Fraction's own;
* the lazy check against the check built at the start, on short runs (one motion, dwells, a motion no box
  holds in a Fanuc run).

A mutation shows the agreement test sees a wrong screen: a corner box that forgets an arc's bulge (the box of
the motions' end points) proves a clamp that the exact path does not.
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from nczones.errors import InvalidArgument
from nczones.machine import parse_machine
from nczones.motion import MotionChunk, PathMode, Plane, Segment, SegmentKind
from nczones.prover import blend, verify_text
from nczones.prover.corners import Corners
from nczones.prover.geometry import arc_geom
from tests.machines import box_zone, machine_text


class _Machine:
    """tests/machines/xyz_corner_screens.toml with a table of half-width ``half`` (Z -50..50) and a forbidden
    clamp from (x0, y0) to (x1, y1), as ``MACHINE.format(x0=.., y0=.., x1=.., y1=..)``."""

    def __init__(self, half: str) -> None:
        self.half = half

    def format(self, *, x0: str, y0: str, x1: str, y1: str) -> str:
        h = self.half
        table = box_zone("table", {"X": f"-{h}", "Y": f"-{h}", "Z": "-50"}, {"X": h, "Y": h, "Z": "50"})
        clamp = box_zone("clamp", {"X": x0, "Y": y0}, {"X": x1, "Y": y1}, forbid=True)
        return machine_text("xyz_corner_screens", extra=table + clamp)


MACHINE = _Machine("60")

N_MOTIONS = 560  # more than 512 motions: the fast path's column chunks


def _mm(v: int) -> str:
    """Thousandths of a mm as a decimal."""
    return str(Fraction(v, 1000).numerator / Fraction(v, 1000).denominator) if v % 1000 else str(v // 1000)


def _program(seed: int, mode: str, g61: float, arcs: float = 0.45) -> tuple[str, list[tuple[int, int]]]:
    """A random walk in X/Y (-40..40 mm) of lines and I/J quarter or half arcs (share ``arcs``; ends exactly on
    the circle) in ``mode``, with G61 stretches (share ``g61`` of the blocks); and the points it passes
    through."""
    rnd = random.Random(seed)
    out = ["G17 G21 G90 G54", "G0 X0 Y0", mode, "G1 F800"]
    x = y = 0
    pts = [(0, 0)]
    motions = 0
    while motions < N_MOTIONS:
        if rnd.random() < g61:
            out.append(rnd.choice(["G61", mode]))
        if rnd.random() >= arcs:
            x1 = max(-40000, min(40000, x + rnd.randint(-6000, 6000)))
            y1 = max(-40000, min(40000, y + rnd.randint(-6000, 6000)))
            if (x1, y1) == (x, y):
                continue
            out.append(f"G1 X{_mm(x1)} Y{_mm(y1)}")
        else:
            i, j = rnd.randint(-4000, 4000), rnd.randint(-4000, 4000)
            if (i, j) == (0, 0):
                continue
            g = rnd.choice((2, 3))
            ux, uy = -i, -j
            ex, ey = (-ux, -uy) if rnd.random() < 0.2 else ((-uy, ux) if g == 3 else (uy, -ux))
            x1, y1 = x + i + ex, y + j + ey
            if max(abs(x1), abs(y1), abs(x + i) + abs(i) + abs(j), abs(y + j) + abs(i) + abs(j)) > 45000:
                continue
            out.append(f"G{g} X{_mm(x1)} Y{_mm(y1)} I{_mm(i)} J{_mm(j)}")
        x, y = x1, y1
        pts.append((x, y))
        motions += 1
    return "\n".join([*out, "M2"]) + "\n", pts


def _capture(program: str, m, monkeypatch) -> tuple:
    """Verify ``program`` (end to end); the corner check's arguments and the chunks it was given."""
    got: dict = {"chunks": []}
    init, take = blend.CornerCheck.__init__, blend.CornerCheck.take

    def spy_init(self, *args):
        got["args"] = args
        init(self, *args)

    def spy_take(self, chunk):
        got["chunks"].append(chunk)
        take(self, chunk)

    import nczones.pipeline.verification as verification

    monkeypatch.setattr(blend.CornerCheck, "__init__", spy_init)
    monkeypatch.setattr(blend.CornerCheck, "take", spy_take)
    # the full path's corner check: the double pass takes G61 stretches without arcs since dpass38
    monkeypatch.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
    result = verify_text(program, m)
    monkeypatch.setattr(blend.CornerCheck, "__init__", init)
    monkeypatch.setattr(blend.CornerCheck, "take", take)
    return result, got["args"], got["chunks"]


def _corners(args: tuple, chunks: list, one_motion: bool) -> tuple:
    """The check's reasons and corner count over ``chunks``: as given, or every column chunk as its segments
    (the one-motion exact path)."""
    check = blend.CornerCheck(*args)
    for chunk in chunks:
        if one_motion and isinstance(chunk, MotionChunk) and chunk.scale is not None:
            for seg in chunk.segments():
                check.take(seg)
        else:
            check.take(chunk)
    reasons = check.finish()
    return sorted((r.code, r.message, r.block) for r in reasons), check.corners


def _agree(program: str, m, monkeypatch, rows: int | None = 100) -> tuple:
    """The column chunks' corners (a chunk of more than ``rows`` rows among them, unless None) and the one-motion
    path's agree; the verify's result and the reasons and corner count."""
    monkeypatch.setattr(blend, "MAX_REASONS", 10**6)  # every failing corner named, whatever order finds it
    result, args, chunks = _capture(program, m, monkeypatch)
    # a walk that crosses the clamp early stops the proof at its first violation, before any long chunk
    assert rows is None or bool(result.violations) or any(
        isinstance(c, MotionChunk) and c.scale is not None and len(c) > rows for c in chunks)
    columns = _corners(args, chunks, one_motion=False)
    assert columns == _corners(args, chunks, one_motion=True)
    return result, columns


MODES = ["G64", "G64 P0.001", "G64 P0.5", "G64 P0.01 Q0.02", "G64 P2"]
SCREENS = settings(max_examples=6, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate],
                   suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])


@SCREENS
@given(seed=st.integers(0, 2**32 - 1), mode=st.sampled_from(MODES), g61=st.sampled_from([0.0, 0.0, 0.02]),
       at=st.one_of(st.just(-1), st.integers(0, N_MOTIONS)), face=st.sampled_from([0, 0, 1, 500, 1500]), size=st.integers(1, 4000),
       side=st.integers(0, 3), arcs=st.sampled_from([0.45, 0.0]))
def test_the_column_screen_agrees_with_the_one_motion_path(seed, mode, g61, at, face, size, side, arcs,
                                                           monkeypatch):
    """Column chunks against the same motion one segment at a time; the clamp has a face ``face`` thousandths
    (0: exactly on it) beyond a point of the path (``at``) on the side ``side``, or (``at`` -1) beyond the
    path's extreme there, where only the blends' bound may reach it (``arcs`` 0: lines only, no bulge past the
    end points)."""
    program, pts = _program(seed, mode, g61, arcs)
    if at < 0:  # beyond the walk's box, the clamp as long as the table
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        x0, y0, w, h = [(max(xs) + face, -50000, size, 100000), (min(xs) - face - size, -50000, size, 100000),
                        (-50000, max(ys) + face, 100000, size), (-50000, min(ys) - face - size, 100000, size)][side]
        m = parse_machine(MACHINE.format(x0=_mm(x0), y0=_mm(y0), x1=_mm(x0 + w), y1=_mm(y0 + h)))
        _agree(program, m, monkeypatch, rows=100 if not g61 else None)
        return
    px, py = pts[at]
    x0, y0 = [(px + face, py - size // 2), (px - face - size, py - size // 2), (px - size // 2, py + face),
              (px - size // 2, py - face - size)][side]
    m = parse_machine(MACHINE.format(x0=_mm(x0), y0=_mm(y0), x1=_mm(x0 + size), y1=_mm(y0 + size)))
    # a mode word ends the fast path's run there (the rest of the program may be read one block at a time)
    _agree(program, m, monkeypatch, rows=100 if not g61 else None)


def test_a_far_clamp_is_proved_by_the_one_box(monkeypatch):
    """Plain CAM output far from every zone: the chunk's one box fits; the screen's boxes are not built."""
    built = []
    real = blend.CornerCheck._screen
    monkeypatch.setattr(blend.CornerCheck, "_screen", lambda self, *a: built.append(1) or real(self, *a))
    program, _pts = _program(7, "G64", 0.0)
    m = parse_machine(MACHINE.format(x0="55", y0="55", x1="58", y1="58"))
    result, (reasons, corners) = _agree(program, m, monkeypatch)
    assert result.verdict.label == "safe" and not reasons and corners >= N_MOTIONS - 1
    assert not built


# An arc corner inside 600 motions far away: X100 Y0 -> the lower half circle about X110 Y0 (G3 from X100 Y0: it
# starts downwards, a 90 degree corner).  The blend may use half of each motion, so its region is the Minkowski
# sum of the line's half box (X75..100 Y0) and the arc's half box (X100..110 Y-10..0) less the corner: X75..110
# Y-10..0 (specs/path-modes.md §1).  A clamp X90..98 Y-5..-1 is in it, off the path (the line is at Y0; the arc is
# at X100 and beyond), below the motions' end points (Y0).
ARC_CORNER = ("G17 G21 G90 G54\nG0 X-30 Y-30\nG1 F800\n"
              + "".join(f"G1 X{-30 + k % 7} Y{-30 + k % 5}\n" for k in range(600))
              + "G0 X50 Y0\nG1 X100\nG3 X120 Y0 I10 J0\nM2\n")
ARC_MACHINE = _Machine("130")


def test_an_arc_corner_in_a_column_chunk(monkeypatch):
    m = parse_machine(ARC_MACHINE.format(x0="90", y0="-5", x1="98", y1="-1"))
    result, (reasons, _corners_seen) = _agree(ARC_CORNER, m, monkeypatch)
    assert result.verdict.label == "unknown" and len(reasons) == 1
    assert "`clamp`" in reasons[0][1]


# A corner whose enclosure passes the box of every motion: X100 Y-10 up to X100 Y0, then back down along the lower
# half circle about X110 Y0 (G3).  The line's half at the corner is X100 Y-5..0, the arc's half at its start
# X100..110 Y-10..0, so the enclosure (their Minkowski sum less the corner X100 Y0) is X100..110 Y-15..0, below
# every motion (down to Y-10; the 600 motions before are at Y30..34).  A clamp X104..106 Y-14..-12 is in it:
# unknown, from the column chunk's one box too (it holds the arc corners' boxes).
BELOW = ("G17 G21 G90 G54\nG0 X-30 Y30\nG1 F800\n"
         + "".join(f"G1 X{-30 + k % 7} Y{30 + k % 5}\n" for k in range(600))
         + "G0 X100 Y-10\nG1 X100 Y0\nG3 X120 Y0 I10 J0\nM2\n")


def test_an_arc_corners_enclosure_below_every_motion(monkeypatch):
    m = parse_machine(ARC_MACHINE.format(x0="104", y0="-14", x1="106", y1="-12"))
    result, (reasons, _corners_seen) = _agree(BELOW, m, monkeypatch)
    assert result.verdict.label == "unknown" and len(reasons) == 1 and "lines 605 and 606" in reasons[0][1] and "X100..110 Y-15..0" in reasons[0][1]
    # a mm lower, outside the enclosure: safe
    m = parse_machine(ARC_MACHINE.format(x0="104", y0="-17", x1="106", y1="-15.5"))
    assert _agree(BELOW, m, monkeypatch)[0].verdict.label == "safe"


def test_a_screen_that_forgets_an_arcs_bulge_is_caught(monkeypatch):
    """Mutation: corner boxes of the two motions' end points (an arc's bulge forgotten) prove the clamp of
    :data:`ARC_CORNER` on the column chunks; the one-motion path does not, and the agreement check fails."""
    import numpy as np

    def end_points_only(self, chunk, lo, hi, i, j, at, scale2):
        s, e = chunk.start, chunk.end
        return (2 * np.minimum(np.minimum(s[i], e[i]), np.minimum(s[j], e[j])),
                2 * np.maximum(np.maximum(s[i], e[i]), np.maximum(s[j], e[j])))

    monkeypatch.setattr(blend.CornerCheck, "_corner_ints", end_points_only)
    m = parse_machine(ARC_MACHINE.format(x0="90", y0="-5", x1="98", y1="-1"))
    assert verify_text(ARC_CORNER, m).verdict.label == "safe"
    with pytest.raises(AssertionError):
        _agree(ARC_CORNER, m, monkeypatch)


# ---------------------------------------------------------------------------------------------- arc boxes

_DENS = st.sampled_from([1, 10, 1000, 2**20, 2**52])


def _q(n: int, d: int) -> Fraction:
    return Fraction(n, d)


@st.composite
def arcs(draw) -> Segment:
    """An arc in XY, XZ or YZ (a helix now and then): a rational centre, the start at a rational vector from it,
    the end at the same distance (a symmetry of the vector, or a rational rotation by the 3-4-5 triangle), or a
    little farther (a spiral; on the start's ray: a whole spiral turn), or at the start (a whole turn)."""
    d = draw(_DENS)
    c = (_q(draw(st.integers(-10**6, 10**6)), d), _q(draw(st.integers(-10**6, 10**6)), d))
    u = (_q(draw(st.integers(-10**5, 10**5)), d), _q(draw(st.integers(-10**5, 10**5)), d))
    how = draw(st.sampled_from(["flip", "swap", "rotate", "spiral", "full", "ray"]))
    sx, sy = draw(st.sampled_from([1, -1])), draw(st.sampled_from([1, -1]))
    if how == "flip":
        w = (sx * u[0], sy * u[1])
    elif how == "swap":
        w = (sx * u[1], sy * u[0])
    elif how == "rotate":
        w = ((3 * u[0] - sx * 4 * u[1]) / 5, (sx * 4 * u[0] + 3 * u[1]) / 5)
    elif how == "spiral":
        w = (u[0] * Fraction(1001, 1000), u[1])
    elif how == "ray":  # LinuxCNC's whole spiral turn (on_start_ray)
        w = (u[0] * Fraction(1001, 1000), u[1] * Fraction(1001, 1000))
    else:
        w = u
    plane = draw(st.sampled_from([Plane.XY, Plane.XZ, Plane.YZ]))
    ia, ib = {Plane.XY: (0, 1), Plane.XZ: (2, 0), Plane.YZ: (1, 2)}[plane]
    other = 3 - ia - ib
    start, end = [Fraction(0)] * 3, [Fraction(0)] * 3
    start[ia], start[ib] = c[0] + u[0], c[1] + u[1]
    end[ia], end[ib] = c[0] + w[0], c[1] + w[1]
    end[other] = _q(draw(st.integers(-1000, 1000)), 10)
    return Segment(SegmentKind.ARC, tuple(start), tuple(end), ("X", "Y", "Z"), plane=plane,
                   clockwise=draw(st.booleans()), centre=c, turns=draw(st.sampled_from([0, 0, 0, 1])))


@settings(max_examples=300, deadline=None)
@given(seg=arcs())
def test_the_integer_arc_box_is_plane_bbox(seg):
    try:
        g = arc_geom(seg)
    except InvalidArgument:  # a zero radius: no box either way
        assert blend._arc_plane_box(seg) is None
        return
    got = blend._arc_plane_box(seg)
    # circles, spirals (plane_bbox's annulus) and whole turns alike: the same bounds, exactly
    assert got == (*g.plane_bbox(), g.ia, g.ib)
    assert got == (*g.plane_bbox(sweep=True), g.ia, g.ib)
    lo, hi = blend._piece_box(seg)
    assert (lo[g.ia], hi[g.ia]) == g.plane_bbox()[0] and (lo[g.ib], hi[g.ib]) == g.plane_bbox()[1]


# ---------------------------------------------------------------------------------------------- comparisons

_NUMBERS = st.one_of(st.fractions(max_denominator=10**30), st.integers(-10**40, 10**40),
                     st.builds(Fraction, st.floats(allow_nan=False, allow_infinity=False)))


@settings(max_examples=300, deadline=None)
@given(a=_NUMBERS, b=_NUMBERS)
def test_the_fast_comparisons_are_fractions_own(a, b):
    assert blend._lt(a, b) == (a < b)
    assert blend._lo(a, b) == min(a, b) and blend._hi(a, b) == max(a, b)
    assert blend._same((a, b), (a, b)) and blend._same((a, b), (Fraction(a), Fraction(b)))
    assert blend._same((a, b), (b, a)) == (a == b)


@settings(max_examples=300, deadline=None)
@given(a=_NUMBERS, b=_NUMBERS, c=_NUMBERS)
def test_the_one_fraction_sums_are_fractions_own(a, b, c):
    """The half boxes' midpoints and the screen's Minkowski sums, each one Fraction from the parts (arcs38)."""
    assert blend._mid(a, b) == (a + b) / 2 and type(blend._mid(a, b)) is type((a + b) / 2)
    assert blend._plus_less(a, b, c) == a + b - c


# ---------------------------------------------------------------------------------------------- the lazy check

_LINUXCNC = [(-1, PathMode(True, None, Fraction(0), "linuxcnc", "G64"))]
_FANUC = [(-1, PathMode(True, None, Fraction(0), "fanuc", "G64"))]


def _seg(kind: SegmentKind, a: tuple, b: tuple, block: int, **kw) -> Segment:
    return Segment(kind, tuple(map(Fraction, a)), tuple(map(Fraction, b)), ("X", "Y", "Z"), block, **kw)


def _both(m, modes: list, segs: list) -> tuple:
    lazy = Corners(m, Fraction(0), (), modes)
    for _s in lazy.watch(iter(segs)):
        pass
    eager = blend.CornerCheck(m, Fraction(0), (), modes)
    for _s in eager.watch(iter(segs)):
        pass
    return ([r.message for r in lazy.finish()], lazy.check is not None), [r.message for r in eager.finish()]


def test_one_line_builds_no_check_and_two_do():
    m = parse_machine(MACHINE.format(x0="8", y0="0.5", x1="9.5", y1="2"))
    one = [_seg(SegmentKind.DWELL, (0, 0, 0), (0, 0, 0), 0), _seg(SegmentKind.LINE, (0, 0, 0), (10, 0, 0), 1)]
    assert _both(m, _LINUXCNC, one) == (([], False), [])
    # the L corner at X10 Y0 next to the clamp X8..9.5 Y0.5..2: G64 may round it into the clamp (the region
    # X5..10 Y0..5, test_blending)
    two = [*one, _seg(SegmentKind.LINE, (10, 0, 0), (10, 10, 0), 2)]
    (lazy, built), eager = _both(m, _LINUXCNC, two)
    assert built and lazy == eager and len(eager) == 1 and "VF208" in eager[0]


def test_one_motion_no_box_holds_is_named_in_a_fanuc_run():
    """An arc of zero radius (the per-motion proof refuses it) alone in cutting mode: the check names it
    (a motion without a box in a run), built at the end."""
    m = parse_machine(MACHINE.format(x0="8", y0="0.5", x1="9.5", y1="2"))
    arc = _seg(SegmentKind.ARC, (1, 1, 0), (1, 1, 0), 0, plane=Plane.XY, centre=(Fraction(1), Fraction(1)))
    (lazy, built), eager = _both(m, _FANUC, [arc])
    assert built and lazy == eager and len(eager) == 1 and "not modelled" in eager[0]


def test_a_three_line_verify_does_not_import_the_corner_check():
    import subprocess
    import sys

    code = ("import sys\nfrom nczones.machine import parse_machine\nfrom nczones.prover import verify_text\n"
            f"m = parse_machine({MACHINE.format(x0='8', y0='0.5', x1='9.5', y1='2')!r})\n"
            "r = verify_text('G90 G21\\nG1 X10 Y10 F100\\nM2\\n', m)\n"
            "print(r.verdict.label, 'nczones.prover.blend' in sys.modules, 'nczones.prover.hull2d' in sys.modules)\n"
            "r = verify_text('G90 G21\\nG1 X10 Y0 F100\\nG1 X10 Y10\\nM2\\n', m)\n"
            "print(r.verdict.label, 'nczones.prover.blend' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split("\n")
    assert out[0] == "safe False False" and out[1] == "unknown True"


@pytest.mark.parametrize("mode, tol", [("G64", "0.5"), ("G64", "")])
def test_a_lathe_with_tip_offsets_agrees(mode, tol, monkeypatch):
    """The tip zone moved by a T-word offset (``test_blend_lathe_tip``): 600 motions then the corner by the zone;
    the chunks as given and one motion at a time give the same reasons (the offsets the tests are moved by)."""
    from tests.prover import test_blend_lathe_tip as lathe

    program = "T0101\nG00 X60. Z-100.\nG01 F100\n" + lathe.FILLER + lathe.CORNER + "M30\n"
    m = lathe._machine(mode, tol, "50")
    result, (reasons, _n) = _agree(program, m, monkeypatch, rows=None)
    assert result.verdict.label == "unknown" and reasons and all("`post`" in r[1] for r in reasons)
