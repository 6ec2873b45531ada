"""Plain lines under one G68 rotation or G51 scaling on the box route (``boxrun._read_transformed``, issue 36).

A Fanuc program of fewer than ``FANUC_BOX_LINES`` lines with G68 or G51 takes the numpy-free box route; its plain
lines under the transform are read from the text, each point mapped by
``gcode/fanuc/transform_points.PointMap`` (the fast path's screen per point, exact integers for scaling) or by
the reader's movers (the same steps written out).  Relations (every side nczones; the reader is an optimisation):

* ``PointMap`` gives ``transforms.scale`` exactly and ``transforms.rotate`` exactly (None where ``rotate`` raises
  ``PointNotCertain``), points near a half increment included; the reader's movers give ``PointMap``'s points;
* ``verify`` with the reader (``boxrun.BOX_RUNS``) and without it (every line through
  ``FanucInterpreter._transformed_motion``, its segments boxed) give the same verdict, violations, reasons,
  notes, counts and motions; without the route (``fanucboxes.ROUTE`` off) the same verdict, violations, reasons,
  notes and motion count; the box the route tests last is the same;
* after the reader the interpreter's state (positions, the program point, counts, block index and span) is the
  one the general path leaves;
* the reader takes the lines (counted), and a transformed point one increment out of the zone is not ``safe``.

The test mill (tests/gcode/fanuc/helpers.py): G54 = (100, 50, -200); the zone machine X -10..150, Y -10..90,
Z -201..0 and EXT Z = 1, i.e. program X -110..50, Y -60..40, Z -2..199.
"""

from __future__ import annotations

import os
from fractions import Fraction

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode.fanuc import boxrun
from nczones.gcode.fanuc.transform_points import PointMap
from nczones.gcode.fanuc.transforms import PointNotCertain, Rotation, Scaling, rotate, scale
from tests.gcode.fanuc.helpers import BOX_ZONE, assert_state_handed_back, mill, probe_route

_MACHINE = mill(tables=BOX_ZONE)
EXAMPLES = int(os.environ.get("NCZONES_BOX_TRANSFORMS_EXAMPLES", "12"))
_STEP = Fraction(1, 1000)
_UNIT = 10**9
#: the transforms' blocks: rotations (30 degrees: ties at 0.001), scalings by P and by I J K (mirrors)
_TRANSFORMS = ["G68 X0. Y0. R30.", "G68 X5. Y-3. R27.5", "G68 X0. Y0. R-90.", "G68 X1.5 Y0. R0.001",
               "G51 X0. Y0. Z-1. P1.25", "G51 X2. Y-1. Z-1. P0.5", "G51 X0. Y0. Z-1. I-1.25 J1.25 K1.",
               "G51 X0. Y0. Z-1. I-1. J-1. K1.", "G51 X3. Y3. Z-1. I2. J-0.75 K1."]
#: coordinates: near the faces (program X -110..50, Y -60..40, scaled by 1.25: 40 / 32), near a half increment
_XS = ["0.", "10.", "40.", "40.001", "-88.", "-88.001", "50.", "-110.", "12.345", "0.001", "0.002", "-3.5", "7.777"]
_YS = ["0.", "5.", "32.", "32.001", "-48.", "-48.001", "40.", "-60.", "0.001", "-0.002", "7.25", "-2.", "3.333"]
#: lines the reader hands back (the general path reads them; G91, inch, R arcs, cancels, too many decimals ...)
_LEAVE = ["(A COMMENT)", "", "X1.0005", "M08", "G91 X1.", "G90", "G20", "G21", "G02 X5. Y5. R5.", "G69", "G50",
          "N7", "x3.", "G00 Z-0.5", "G01 X1. Y1. F0", "G90 X2.", "G17", "G18", "G17"]


@st.composite
def _programs(draw, size: int = 25) -> str:
    """A Fanuc program: a transform, an absolute first move, then plain lines, I/J arcs, lines the reader leaves."""
    transform = draw(st.sampled_from(_TRANSFORMS))
    lines = ["O3000", "G90 G17 G21 G54 G00 X0. Y0. Z5.", "G01 Z-1. F300.", transform,
             f"G01 X{draw(st.sampled_from(_XS))} Y{draw(st.sampled_from(_YS))}"]
    for _ in range(draw(st.integers(1, size))):
        kind = draw(st.sampled_from(["xy", "xy", "x", "y", "g0", "f", "n", "z", "arc", "leave", "again"]))
        x, y = draw(st.sampled_from(_XS)), draw(st.sampled_from(_YS))
        if kind == "leave":
            lines.append(draw(st.sampled_from(_LEAVE)))
        elif kind == "again":
            lines.append(transform)
        elif kind == "arc":  # a quarter circle from (x, y): on its circle, clockwise or not
            r = draw(st.sampled_from([Fraction(2), Fraction(1, 2), Fraction(7, 1000)]))
            lines.append(f"G01 X{x} Y{y}")
            px, py = Fraction(x), Fraction(y)
            cw = draw(st.booleans())
            ij = f"I{float(r):.3f} J0." if cw else f"I0. J{float(r):.3f}"
            lines.append(f"G0{2 if cw else 3} X{float(px + r):.3f} Y{float(py + r):.3f} {ij}")
        else:
            words = {"xy": f"X{x} Y{y}", "x": f"X{x}", "y": f"Y{y}", "g0": f"G00 X{x} Y{y}",
                     "f": f"G01 X{x} Y{y} F{draw(st.sampled_from(['200.', '50.5']))}", "n": f"N{draw(st.integers(1, 99))} X{x}",
                     "z": f"Z{draw(st.sampled_from(['-1.', '-0.5', '-2.001']))}"}
            lines.append(words[kind])
    lines += ["G69" if transform.startswith("G68") else "G50", "G00 Z5.", "X0. Y0.", "M30"]
    return "\n".join(lines) + "\n"


def _run(text: str, runs: bool, route: bool = True) -> tuple[tuple, int, tuple]:
    """(the report, the lines the reader took, the last box the route tested) of ``verify`` on ``text``."""
    r, tested, taken = probe_route(text, _MACHINE, "t.nc", runs=runs, route=route)
    if isinstance(r, GcodeError):
        return ("error", tuple((d.code, d.message, str(d.span)) for d in r.diagnostics)), taken, ()
    stats = dict(r.stats)
    extra = dict(r.extra or {})
    boxes = dict(extra.pop("fanuc_boxes", None) or {})
    boxes.pop("rows", None)  # runs of rows against segments: the reader's are rows
    return ((r.verdict.label, tuple(r.violations), tuple(r.reasons), r.truncated, tuple(r.notes), stats["segments"],
             r.file, stats.get("fanuc_boxes"), extra.get("counts"), (r.profile or {}).get("blocks"), boxes),
            taken, tuple(tested[-1:]))


def _agree(text: str) -> tuple[str, int]:
    """The reader, the general path and the path without the route agree; (verdict, lines the reader took)."""
    read, taken, box = _run(text, True)
    general, none, general_box = _run(text, False)
    assert none == 0
    assert read == general
    if read[0] == "safe":
        assert box == general_box
    today, _, _ = _run(text, True, route=False)
    assert today[:7] == read[:7]
    return str(read[0]), taken


@settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_reads_transformed_lines_as_the_general_path(text):
    _agree(text)


def test_the_reader_takes_the_lines_and_sees_a_point_out():
    """Scaled by 1.25 (and mirrored on X) inside the zone: ``safe``, the reader takes the lines; a point that
    scales an increment past a face is not ``safe``, as the general path says."""
    body = [f"X{(k % 17) * 2.5 - 20:.3f} Y{(k % 11) * 2.25 - 12:.3f}" for k in range(60)]
    arcs = ["G01 X1. Y1.", "G02 X3. Y3. I2. J0.", "G03 X3.5 Y3.5 I0. J0.5"]
    for factors in ("P1.25", "I-1.25 J1.25 K1."):
        head = ["O1", "G90 G17 G21 G54 G00 X0. Y0. Z5.", "G01 Z-1. F300.", f"G51 X0. Y0. Z-1. {factors}", "G01 X0. Y0."]
        tail = ["G50", "G00 Z5.", "M30", ""]
        verdict, taken = _agree("\n".join(head + body + arcs + tail))
        assert verdict == "safe" and taken == 63
        x_face = "X-40.001" if factors.startswith("I") else "X40.001"  # (a mirror on X: -40 -> 50)
        for k, new in ((10, f"{x_face} Y1."), (20, "X1. Y32.001"), (30, "X1. Y-48.001")):
            past = body[:k] + [new] + body[k + 1:]  # a line the reader takes, an increment out once scaled
            assert _agree("\n".join(head + past + arcs + tail))[0] != "safe"
        verdict, _ = _agree("\n".join(head + body[:10] + [x_face.replace(".001", ".") + " Y1."] + body[11:] + arcs
                                       + tail))
        assert verdict == "safe"  # on the face itself: inside


def test_the_reader_takes_rotated_lines_and_leaves_a_tie():
    """Rotated by 30 degrees: the reader takes the lines; ``X0.001`` rotates to ``X0.000866 Y0.0005``, a tie the
    general path calls uncertain (``unknown``): the reader leaves that line to it."""
    body = [f"X{(k % 13) * 3.5 - 20:.3f} Y{(k % 7) * 1.75 - 5:.3f}" for k in range(40)]
    head = ["O1", "G90 G17 G21 G54 G00 X0. Y0. Z5.", "G01 Z-1. F300.", "G68 X0. Y0. R30.", "G01 X0. Y0."]
    tail = ["G01 X0. Y0.", "G02 X2. Y2. I2. J0.", "G69", "G00 Z5.", "M30", ""]
    verdict, taken = _agree("\n".join(head + body + tail))
    assert verdict == "safe" and taken == 42
    verdict, taken = _agree("\n".join(head + body[:20] + ["X0.001 Y0."] + body[21:] + tail))
    assert verdict == "unknown" and taken < 42


@settings(max_examples=max(3, EXAMPLES // 3), deadline=None, database=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_hands_the_state_back_as_the_general_path_leaves_it(text):
    """A program that ends under the transform (the text ends there): the state is the interpreter's."""
    assert_state_handed_back(text[:text.rindex("\nG69\n" if "\nG69\n" in text else "\nG50\n") + 1], _MACHINE)


def test_the_first_move_after_a_cancel_is_the_general_paths():
    """G69 / G50 set ``transform_just_cancelled``: the next move (here incremental: unknown) is not read; the
    same program with an absolute move after the cancel is ``safe`` and read."""
    body = "".join(f"X{k % 9}. Y{k % 5}.\n" for k in range(20))
    for on, off in (("G68 X0. Y0. R27.5", "G69"), ("G51 X0. Y0. Z-1. P1.25", "G50")):
        head = f"O1\nG90 G17 G21 G54 G00 X0. Y0. Z5.\nG01 Z-1. F300.\n{on}\nG01 X0. Y0.\n" + body + off + "\n"
        verdict, taken = _agree(head + "G91 X1.\nG90\nG00 Z5.\nM30\n")
        assert verdict == "unknown" and taken == 20
        verdict, taken = _agree(head + "X1.\nG00 Z5.\nM30\n")
        assert verdict == "safe"


_FACTORS = st.sampled_from([Fraction(5, 4), Fraction(-5, 4), Fraction(1, 2), Fraction(-1), Fraction(3),
                            Fraction(7, 3), Fraction(-2, 7), Fraction(1)])
_COORDS = st.integers(-10**8, 10**8).map(lambda k: Fraction(k, 1000))
_CENTRES = st.sampled_from([Fraction(0), Fraction(-1), Fraction(5, 2), Fraction(1, 3000)]) | _COORDS


@settings(max_examples=300, deadline=None, database=None)
@given(_FACTORS, _CENTRES, _COORDS | _CENTRES)
def test_point_map_scales_as_transforms_scale(f, c, v):
    """``PointMap.scaled`` is ``transforms.scale`` (a centre off the grid or off the scale included)."""
    xf = (None, Scaling((c, Fraction(0)), (f, Fraction(1))), _STEP)
    pm = PointMap.of(xf, 9)
    if (c * _UNIT).denominator != 1:
        assert pm is None
        return
    v = Fraction(round(v * _UNIT), _UNIT)  # the reader's numbers are on the scale
    want = scale(xf[1], [v, Fraction(0)], _STEP)[0]
    assert Fraction(pm.scaled(0, int(v * _UNIT)), _UNIT) == want
    if (v * 1000).denominator == 1:  # a word the reader reads: its scaling mover gives the same
        st_ = _Box()
        move = boxrun._scaling_mover(st_, pm, [0, 0])
        line = f"X{int(v * 1000)}"
        assert move(line, ((slice(1, len(line)), 10**6, 0),)) and Fraction(st_.p[0], _UNIT) == want


_ANGLES = st.sampled_from([Fraction(30), Fraction(55, 2), Fraction(-90), Fraction(45), Fraction(1, 1000),
                           Fraction(120), Fraction(0)])


@settings(max_examples=400, deadline=None, database=None)
@given(_ANGLES, _COORDS, _COORDS, st.sampled_from([(Fraction(0), Fraction(0)), (Fraction(5), Fraction(-3))]))
def test_point_map_rotates_as_transforms_rotate(angle, x, y, centre):
    """``PointMap.rotated`` is ``transforms.rotate``, None where it raises ``PointNotCertain``; the rotation mover
    of the reader gives the same point (or refuses the line)."""
    rot = Rotation(0, 1, centre[0], centre[1], angle)
    pm = PointMap.of((rot, None, _STEP), 9)
    try:
        want = rotate(rot, [x, y], _STEP)
    except PointNotCertain:
        want = None
    got = pm.rotated(int(x * _UNIT), int(y * _UNIT))
    assert (None if got is None else [Fraction(v, _UNIT) for v in got]) == want
    assert _moved(pm, x, y) == want


def test_points_near_a_half_increment_are_left_or_rounded_as_rotate():
    """Small points under 30 degrees: sin 30 = 1/2 puts ``x' = -y/2`` on a tie for every odd thousandth."""
    rot = Rotation(0, 1, Fraction(0), Fraction(0), Fraction(30))
    pm = PointMap.of((rot, None, _STEP), 9)
    left = 0
    for k in range(-40, 41):
        for x in (Fraction(0), Fraction(k, 1000), Fraction(3)):
            y = Fraction(k, 1000)
            try:
                want = rotate(rot, [x, y], _STEP)
            except PointNotCertain:
                want = None
                left += 1
            got = pm.rotated(int(x * _UNIT), int(y * _UNIT))
            assert (None if got is None else [Fraction(v, _UNIT) for v in got]) == want
            assert _moved(pm, x, y) == want
    assert left >= 40


class _Box:
    """The reader's state a mover writes (``boxrun._Run``'s position, box and offsets)."""

    def __init__(self) -> None:
        self.p, self.lo, self.hi, self.off = [0, 0], [0, 0], [0, 0], [0, 0]


def _moved(pm: PointMap, x: Fraction, y: Fraction) -> list[Fraction] | None:
    """The point ``boxrun``'s rotation mover writes for a line ``X.. Y..`` (None: it refuses the line)."""
    st_ = _Box()
    prog = [0, 0]
    line = f"X{int(x * 1000)}Y{int(y * 1000)}"
    at = line.index("Y")
    move = boxrun._rotation_mover(st_, pm, prog)
    if not move(line, (slice(1, at), 10**6, slice(at + 1, len(line)), 10**6, ())):
        return None
    return [Fraction(v, _UNIT) for v in st_.p]


def test_a_mirrored_arc_turns_the_other_way():
    """The program's G03 from (-5, -56) about (0, -56) to (0, -51) is three quarters of a circle through
    (0, -61), below the zone's floor (program Y -60): not ``safe``; its G02 is the quarter above: ``safe``.
    Mirrored on X (``I-1.``) the machine arc is the mirror image, turning the other way: the same verdicts (read
    in the program's direction, the mirrored G03 would be the quarter, ``safe``)."""
    head = ["O1", "G90 G17 G21 G54 G00 X0. Y0. Z5.", "G01 Z-1. F300."]
    tail = ["G01 X0. Y0.", "G50", "G00 Z5.", "M30", ""]
    for factors in ("I-1. J1. K1.", "I1. J1. K1.5"):
        for g, want in (("G03", "not safe"), ("G02", "safe")):
            arc = ["G01 X-5. Y-56.", f"{g} X0. Y-51. I5. J0."]
            verdict, taken = _agree("\n".join(head + [f"G51 X0. Y0. Z-1. {factors}"] + arc + tail))
            assert (verdict == "safe") == (want == "safe") and taken == 2, (factors, g)
