"""The double pass (nczones/gcode/linuxcnc/doubles.py) against the full interpreter.

The module's invariant: whenever the pass returns, the full interpreter runs the same program to the end
with no error, no unknown code and no note, with as many motions and blocks, and the exact start and end of
its k-th motion lie in the pass's enclosure of motion k.  Checked on generated parametric programs in and
around the subset (``NCZONES_DOUBLE_PASS_EXAMPLES=N`` for a long run), on fixed programs that the pass must
accept, and on programs that it must decline (the reason each one is outside the subset).
"""

from __future__ import annotations

import math
import os
from bisect import bisect_right
from fractions import Fraction

import mpmath
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.gcode.expr import binary_op
from nczones.gcode.linuxcnc import doubles
from nczones.gcode.linuxcnc.doubles import Declined, DoublePath, double_pass
from nczones.gcode.runner_common import assumed_modal_notes
from nczones.machine import parse_machine
from nczones.motion import PLANE_AXES, PathMode, SegmentKind
from tests.gcode.rs274_arc_programs import in_plane

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "120"))


def machine_text(offsets: dict[str, tuple[str, str, str]] | None = None, start: tuple[str, str, str] = ("0", "0", "0"),
                 modal: str | None = None, extra: str = "", keys: str = "") -> str:
    lines = ['[machine]', 'name = "double pass"', 'axes = ["X", "Y", "Z"]', 'pulse = "0.001"']
    if modal is not None:
        lines.append(f"modal = {modal}")
    if keys:  # more [machine] keys (the start-up path mode)
        lines.append(keys)
    lines += ['[machine.rapid]', 'X = "5000"', 'Y = "5000"', 'Z = "5000"', '[machine.reference]',
              'X = "0"', 'Y = "0"', 'Z = "0"', '[machine.start]',
              f'X = "{start[0]}"', f'Y = "{start[1]}"', f'Z = "{start[2]}"']
    if offsets:
        lines.append("[offsets]")
        for name, (x, y, z) in offsets.items():
            lines.append(f'{name} = {{ X = "{x}", Y = "{y}", Z = "{z}" }}')
    lines += ['[[zones]]', 'name = "travel"', 'kind = "box"',
              'min = { X = "-100000", Y = "-100000", Z = "-100000" }',
              'max = { X = "100000", Y = "100000", Z = "100000" }']
    return "\n".join(lines) + "\n" + extra


MACHINE = parse_machine(machine_text())


def check_against_full(text: str, machine, max_iterations: int = 1000) -> DoublePath | None:
    """The module's invariant for one program; the path, or None when the pass declined."""
    try:
        path = double_pass(text, machine, max_iterations=max_iterations)
    except Declined:
        return None
    run = interpret_text(text, machine, max_loop_iterations=max_iterations)
    segments = list(run.segments())
    assert run.status == "complete", run.unsupported
    # the only notes: the modal groups the program left to the machine file, the same as the pass's
    assert run.assumed_modal_text() == assumed_modal_notes(path.assumed, machine.modal, "linuxcnc")
    assert run.notes() == []
    assert len(segments) == path.motions
    assert run.counts["blocks"] == path.blocks
    axes = machine.axis_names
    assert path.arcs == sum(seg.kind is SegmentKind.ARC for seg in segments)
    assert path.dwells == sum(seg.kind is SegmentKind.DWELL for seg in segments)
    assert path.rapids == sum(seg.kind is SegmentKind.RAPID for seg in segments)
    check_corners(path, segments, run.interpreter.path_modes)
    for k, seg in enumerate(segments, start=1):
        lo, hi = path.enclosure(k, k)
        for i, a in enumerate(axes):
            if path.first_row[i] == 0 or path.first_row[i] > k:  # an axis no motion moved yet is at the start
                assert lo[a] == hi[a] == machine.start[i]
            for v in (seg.start[i], seg.end[i]):
                assert lo[a] <= v <= hi[a], (k, a, v, lo[a], hi[a])
        if seg.kind is SegmentKind.ARC:
            check_arc_in_box(seg, lo, hi, axes)
    return path


def check_corners(path: DoublePath, segments: list, modes: list[tuple[int, PathMode]]) -> None:
    """The pass blends the corners the full path does: a corner takes the mode of the motion before it
    (``CornerCheck._segment``), G64 without P (a tolerance's corners are the margin's) and no dwell on either
    side; the full path's mode of a motion is the last entry of ``path_modes`` at or before its block."""
    blocks = [first for first, _mode in modes]
    for k in range(1, len(segments)):
        before, after = segments[k - 1], segments[k]
        mode = modes[bisect_right(blocks, before.block) - 1][1]
        bare = mode.blend and mode.tolerance is None and not mode.naive
        dwell = SegmentKind.DWELL in (before.kind, after.kind)
        assert path.blended(k) == (bare and not dwell), (k, mode, before.kind, after.kind)


def _plane(seg, axes: tuple[str, ...] = ("X", "Y", "Z")) -> tuple[int, int]:
    """The indices (first, second) of the plane axes of the full path's arc ``seg`` on a machine of ``axes``."""
    a, b, _n = PLANE_AXES[seg.plane]
    return axes.index(a), axes.index(b)


def arc_points(seg, axes: tuple[str, ...] = ("X", "Y", "Z")) -> list[tuple[mpmath.mpf, mpmath.mpf]]:
    """Points of the full path's arc ``seg`` at 200 bits, in its plane's axes (first, second: G18's are Z and
    X), computed from the segment alone: its ends and,
    at both radii (a spiral lies between), 64 points of its sweep and the points in every axis direction the
    sweep holds.  The centre of an R arc is ``(S + E) / 2 + s h n`` (``h = sqrt(R**2 - |E - S|**2 / 4)``, n the
    left normal of the chord, s = -1 for G2 with R > 0 and G3 with R < 0: LinuxCNC's arc_data_r)."""
    mp = mpmath.mp
    ia, ib = _plane(seg, axes)
    sx, sy, ex, ey = (mpmath.mpf(Fraction(v).numerator) / Fraction(v).denominator
                      for v in (seg.start[ia], seg.start[ib], seg.end[ia], seg.end[ib]))
    if seg.centre is not None:
        cx, cy = (mpmath.mpf(c.numerator) / c.denominator for c in seg.centre)
    else:
        r = mpmath.mpf(seg.radius.numerator) / seg.radius.denominator
        dx, dy = ex - sx, ey - sy
        d = mpmath.sqrt(dx * dx + dy * dy)
        h = mpmath.sqrt(r * r - d * d / 4)
        s = -1 if (r > 0) == seg.clockwise else 1
        cx, cy = (sx + ex) / 2 - s * h * dy / d, (sy + ey) / 2 + s * h * dx / d
    r0 = mpmath.sqrt((sx - cx) ** 2 + (sy - cy) ** 2)
    r1 = mpmath.sqrt((ex - cx) ** 2 + (ey - cy) ** 2)
    a, b = mpmath.atan2(sy - cy, sx - cx), mpmath.atan2(ey - cy, ex - cx)
    start, end = (b, a) if seg.clockwise else (a, b)
    sweep = (end - start) % (2 * mp.pi)
    if sweep < mpmath.mpf(10) ** -40:
        sweep = 2 * mp.pi  # back on the start's ray: a whole turn
    angles = [start + sweep * n / 64 for n in range(65)]
    angles += [phi for phi in (0, mp.pi / 2, mp.pi, -mp.pi / 2) if (phi - start) % (2 * mp.pi) <= sweep]
    pts = [(sx, sy), (ex, ey)]
    pts += [(cx + rad * mpmath.cos(t), cy + rad * mpmath.sin(t)) for t in angles for rad in (r0, r1)]
    return pts


def check_arc_in_box(seg, lo, hi, axes: tuple[str, ...] = ("X", "Y", "Z")) -> None:
    """Every point of :func:`arc_points` lies in the enclosure (its bounds are exact binary fractions)."""
    with mpmath.workprec(200):
        box = [(mpmath.mpf(lo[a].numerator) / lo[a].denominator, mpmath.mpf(hi[a].numerator) / hi[a].denominator)
               for a in PLANE_AXES[seg.plane][:2]]
        for p in arc_points(seg, axes):
            for v, (b_lo, b_hi) in zip(p, box):
                # 1e-45: the points' own rounding at 200 bits, far below any double's
                assert b_lo - mpmath.mpf(10) ** -45 <= v <= b_hi + mpmath.mpf(10) ** -45, (seg, p, box)


# -- generated programs -------------------------------------------------------------------------------------

numbers = st.one_of(
    st.integers(-200, 200).map(str),
    st.decimals(-500, 500, places=3, allow_nan=False, allow_infinity=False).map(lambda d: f"{d:f}"),
    st.sampled_from(["0.1", "0.2", "0.3", ".5", "-.25", "1e", "123456789.123456789", "0.000000001"]),
)
params = st.sampled_from(["#1", "#2", "#3", "#31", "#100", "#<a>", "#<b>"])


@st.composite
def expressions(draw, depth: int = 2) -> str:
    if depth == 0 or draw(st.integers(0, 2)) == 0:
        return draw(st.one_of(numbers.filter(lambda s: s != "1e"), params))
    kind = draw(st.integers(0, 3))
    a = draw(expressions(depth - 1))
    if kind == 0:
        op = draw(st.sampled_from(["+", "-", "*", "/", "MOD"]))
        return f"[{a} {op} {draw(expressions(depth - 1))}]"
    if kind == 1:
        fn = draw(st.sampled_from(["COS", "SIN", "ABS", "SQRT", "FIX", "FUP", "ROUND", "EXP", "LN"]))
        return f"{fn}[{a}]"
    if kind == 2:
        return f"-{a}"
    return f"ATAN[{a}]/[{draw(expressions(depth - 1))}]"


@st.composite
def conditions(draw) -> str:
    op = draw(st.sampled_from(["LT", "GT", "LE", "GE", "EQ", "NE"]))
    return f"[{draw(expressions(1))} {op} {draw(expressions(1))}]"


@st.composite
def motions(draw) -> str:
    code = draw(st.sampled_from(["G0 ", "G1 ", "G01 ", "G1.0 ", "", ""]))
    axes = draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True))
    words = " ".join(f"{a}{draw(st.one_of(numbers.filter(lambda s: s != '1e'), expressions(2)))}" for a in axes)
    feed = draw(st.sampled_from(["", "", f" F{draw(st.sampled_from(['100', '250', '0', '-5', '[ABS[#1] + 50]']))}"]))
    return f"{code}{words}{feed}"


def _dec(x: float, places: int) -> str:
    return f"{x:.{places}f}"


@st.composite
def arcs(draw) -> list[str]:
    """A move to a start point, then a G2/G3 from it: I/J (quarters, near half circles, whole circles by I/J,
    ends on an axis direction from the centre, ends a little off the circle, helices) or R (small and large
    radii, both signs, near half circles), sometimes with G17 or a feed on the line, then back to G1 or not."""
    import math

    sx, sy = (draw(st.integers(-4000, 4000)) / 40 for _ in range(2))
    code = draw(st.sampled_from(["G2", "G3", "G02", "G03"]))
    places = draw(st.sampled_from([1, 3, 4, 4, 6, 6]))
    radius = draw(st.sampled_from([0.01, 0.5, 1.0, 7.25, 120.0, 3000.0]))
    kind = draw(st.integers(0, 5))
    head = [f"G1 X{_dec(sx, 3)} Y{_dec(sy, 3)}"]
    if kind <= 2:  # I/J
        a0 = draw(st.sampled_from([0.0, math.pi / 2, math.pi, 1.0, -2.5, math.pi / 4]))
        sweep = draw(st.sampled_from([0.0, math.pi / 2, math.pi, math.pi - 1e-6, 2.0, -math.pi / 2, 3 * math.pi / 2,
                                      1e-5, -1e-7]))
        i, j = -radius * math.cos(a0), -radius * math.sin(a0)
        cx, cy = sx + float(_dec(i, places)), sy + float(_dec(j, places))
        off = draw(st.sampled_from([0.0, 0.0, 0.0, 1e-4, -0.0015, 0.05]))
        ex, ey = cx + (radius + off) * math.cos(a0 + sweep), cy + (radius + off) * math.sin(a0 + sweep)
        words = f"X{_dec(ex, places)} Y{_dec(ey, places)} I{_dec(i, places)} J{_dec(j, places)}"
        if kind == 2:
            words = draw(st.sampled_from([words, f"X{_dec(sx, 3)} I{_dec(i, places)}",
                                          f"Y{_dec(sy, 3)} J{_dec(j, places)} Z-1", f"X{_dec(sx, 3)} Y{_dec(sy, 3)} "
                                          f"I{_dec(i, places)} J{_dec(j, places)} Z[#1 * 2]", words + " P2"]))
    else:  # R
        half = draw(st.sampled_from([0.2, 0.5, 0.7, 0.99, 0.9999999, 0.2, 0.5, 0.7, 0.99, 0.9999999, 1.0,
                                     1.000000000001, 1.01]))
        t = draw(st.sampled_from([0.0, 0.7, math.pi / 2, -2.0, math.pi]))
        ex, ey = sx + 2 * radius * half * math.cos(t), sy + 2 * radius * half * math.sin(t)
        sign = draw(st.sampled_from(["", "-"]))
        rr = "[#<a> * 0 + 1]" if draw(st.integers(0, 9)) == 0 else f"{sign}{radius}"
        words = f"X{_dec(ex, places)} Y{_dec(ey, places)} R{rr}"
        if kind == 5:
            words += draw(st.sampled_from([" Z2", " I1", " F50", ""]))
    lead = draw(st.sampled_from(["", "", "", "", "", "", "", "", "G17 ", "G43 H1 ", "G49 ", "G55 ", "G18 "]))
    tail = draw(st.sampled_from([[], [], [], ["G1"], ["G1"], ["G0 X0 Y0"], ["X1 Y1"]]))
    # a dwell or a path mode before the arc (a dwell stops: no blend, no motion LinuxCNC drops before the arc)
    pause = draw(st.sampled_from([[]] * 6 + [["G4 P0.1"], ["G61"], ["G64"], ["G1 X[#1 * 0.0000001]", "G4 P1"]]))
    return head + pause + [f"{lead}{code} {words}"] + tail


#: Tool changes, dwells and path modes (issue 36), most of them in the subset.
TOOLS_AND_MODES = ["T1 M6", "T2", "M6", "T03 M06 G43 H1", "M61 Q3", "M6 M3 T1", "T1 M6 G1 X[#1] F100", "G4 P0.5",
                   "G4 P[ABS[#1] + 0.1]", "G4 P[#1]", "G04 P1 M9", "G61", "G61.1", "G64", "G64 G1 X[#1 / 3]",
                   "G61 G0 Z[#2]", "G61.1 X[#1 + 0.0000001]", "G1 X[#1 + 0.0000001]", "G91", "G90", "G91 G1 X[#1]",
                   "G91 G0 Z[-#1] Y0.1", "G90 G1 X[#1] Y[#2] Z0", "G64 P0.01", "G64 P[ABS[#1] + 0.5]",
                   "G64 P0.01 G1 X[#1]", "G64 P0", "G64 P0.1 Q0.1", "G4 P1 G64 P1", "G64 P[#1]"]
#: Lines outside the subset (each must make the pass decline, or the full path agree with it).
OUTSIDE = ["G2 X1 Y1 R5", "G43 H2", "G43", "H1", "G43 H0", "G49", "G19", "G91", "G20", "M3 S1000", "#4 = #5221", "G43 H1", "T1 M6", "G10 L2 P1 X3",
           "G92 X0", "(MSG, hello)", "(DEBUG, #1)", "G59.1", "G53 G0 X1", "G64 P0.01", "#4 = #<_x>", "G4 P1",
           "/G1 X1", "%", "G1 X1 X2", "G0 G1 X1", "G80 X1", "G28", "M0", "S100", "#4 = EXISTS[#<a>]",
           "T[#1] M6", "G4 P1 X1", "G4", "M61", "Q1", "G64 Q0.1", "G4 P-1", "T1.5", "M6 M61 Q1"]


@st.composite
def statements(draw, depth: int, labels: list[int]) -> list[str]:
    kind = draw(st.integers(0, 9))
    if kind <= 2:
        target = draw(st.sampled_from(["#1", "#2", "#3", "#31", "#100", "#<a>", "#<b>"]))
        return [f"{target} = {draw(expressions(2))}"]
    if kind <= 5:
        return draw(arcs()) if draw(st.integers(0, 3)) == 0 else [draw(motions())]
    if kind == 6:
        return [draw(st.sampled_from(["G54", "G55", "G56", "G57", "G58", "G59", "G21 G90", "G17", "G94 G40 G49",
                                      "G80", "F200", "N10 G1 X1 F100", "(a plain comment)", "", "; comment",
                                      "G1 X[#1] (with a comment)", "M3 S1000", "S[ABS[#1] * 10] M4", "M5",
                                      "G1 X[#1] M8 F100", "M9", "M7 S0", "S[#1]", *TOOLS_AND_MODES]))]
    if kind == 7 and depth > 0:
        label = 100 + len(labels)
        labels.append(label)
        counter = draw(st.sampled_from(["#11", "#12", "#<i>"]))
        n = draw(st.integers(0, 4))
        body = [s for _ in range(draw(st.integers(1, 3))) for s in draw(statements(depth - 1, labels))]
        return ([f"{counter} = 0", f"o{label} while [{counter} LT {n}]"] + body
                + [f"{counter} = [{counter} + 1]", f"o{label} endwhile"])
    if kind == 8 and depth > 0:
        label = 100 + len(labels)
        labels.append(label)
        out = [f"o{label} if {draw(conditions())}"]
        out += [s for _ in range(draw(st.integers(1, 2))) for s in draw(statements(depth - 1, labels))]
        if draw(st.booleans()):
            out.append(f"o{label} elseif {draw(conditions())}")
            out += draw(statements(depth - 1, labels))
        if draw(st.booleans()):
            out.append(f"o{label} else")
            out += draw(statements(depth - 1, labels))
        return out + [f"o{label} endif"]
    return [draw(st.sampled_from(OUTSIDE))] if draw(st.integers(0, 3)) == 0 else [draw(motions())]


@st.composite
def parametric_programs(draw) -> str:
    head = draw(st.sampled_from(["G21 G90 G54 F300 G1", "G21 G90 G17 G54 G94 F800 G0", "G90 G54 F300", "G21 G90 G55 F50 G1",
                                 "G21 G90 G54 G0", "G21 G90 G54 F100 G1", "G21 G90 G17 G54 F300 G1",
                                 "G21 G90 G17 G54 G43 H1 F300 G1", "F300 G1", "G90 F300", "G21 G54 F300 G1"]))
    if draw(st.integers(0, 4)):
        head += "\n#<a> = 1.5\n#<b> = [#<a> * 2]"
    labels: list[int] = []
    body = [s for _ in range(draw(st.integers(1, 8))) for s in draw(statements(2, labels))]
    tail = draw(st.sampled_from(["M30", "M2", "", "M30\nG1 X[1/0]"]))
    eol = draw(st.sampled_from(["\n", "\n", "\r\n"]))
    return eol.join([head, *body, tail]) + eol


@st.composite
def machines(draw, tools: bool = False):
    def triple():
        return tuple(draw(st.sampled_from(["0", "10", "-2.5", "0.1", "1000.0001"])) for _ in range(3))

    offsets = {name: triple() for name in ("G54", "G55", "G57") if draw(st.booleans())}
    modal = draw(st.sampled_from([None] * 12 + ['["G21", "G90", "G17", "G55"]', '["G20"]', '["G91"]',
                                                '["G21", "G90", "G18", "G56"]']))
    lengths = draw(st.sampled_from(["", '[tool_lengths]\nH1 = "100"\n', '[tool_lengths]\nH1 = "-12.3456789"\n'][tools:]))
    keys = draw(st.sampled_from([""] * 6 + ['path_mode = "G61"', 'path_mode = "G61.1"', 'path_tolerance = "0.01"']))
    return parse_machine(machine_text(offsets, triple(), modal, extra=lengths, keys=keys))


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(parametric_programs(), machines(), st.sampled_from([1000, 3, 4]))
def test_the_pass_is_enclosed_by_the_full_interpreter(text, machine, max_iterations):
    check_against_full(text, machine, max_iterations)


@st.composite
def arc_programs(draw) -> str:
    """Programs of arcs (:func:`arcs`) and G43 after a head that sets the plane, most of them in the subset."""
    head = draw(st.sampled_from(["G21 G90 G17 G54 F300", "G21 G90 G17 G54 G43 H1 F800 G1", "G17 G21 G90 G55 F50",
                                 "G21 G90 G17 G54 F300", "G21 G90 G17 G54 F300", "G21 G90 G17 G54 F300",
                                 "G21 G90 G54 F300", "F300", "G90 G54 F300"]))
    body = [line for _ in range(draw(st.integers(1, 4))) for line in draw(arcs())]
    plane = draw(st.sampled_from([17, 17, 18, 19]))
    if plane != 17:  # the same program in G18 or G19: (X, Y, Z, I, J) to the plane's (first, second, normal)
        head = head.replace("G17", f"G{plane}")
        body = [in_plane(line, plane) for line in body]
    return "\n".join([head, "#1 = 0.5", *body, "M30"]) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(arc_programs(), machines(tools=True))
def test_arcs_are_enclosed_by_the_full_interpreter(text, machine):
    """The invariant on programs of arcs: each arc of the full path (its ends, its points at both radii and
    its extremes, :func:`check_arc_in_box`) lies in the pass's box of its motion."""
    check_against_full(text, machine)


# -- fixed programs ----------------------------------------------------------------------------------------

ACCEPTED = {
    "expressions": "G21 G90 G17 G54 F800\n#1 = 0\n#2 = 0\nG1 X[#1 + 32.383] Y[#2 + 15.085]\n"
                   "#1 = [#1 + 0.124]\nG1 X[#1 + 22.324] Y[#2 + 62.743]\nX[#1 * 0.1] Y.5\nM30\n",
    "loop": "G90 G17 G21 G54 F800\n#1 = 0\n#5 = 0\no100 while [#1 LT 40]\n#2 = [#1 * 0.01]\n"
            "#3 = [#2 * COS[#1 * 3.6]]\n#4 = [#2 * SIN[#1 * 3.6]]\no101 if [#4 GT 1000]\n#5 = [#5 + 1]\n"
            "o101 endif\nG01 X#3 Y#4\n#1 = [#1 + 1]\no100 endwhile\nM30\n",
    "branches": "G21 G90 G54 F100 (set up)\n#<n> = 3\no1 if [#<n> EQ 1]\nG1 X1\no1 elseif [#<n> EQ 3]\n"
                "G0 X3 Y[#<n> / 3]\no1 else\nG1 X9\no1 endif\nG55\nG1 Z-1 ; a cut\nM2\n",
    "offsets and rows": "G21 G90 G54 F100\nG0 X0.1 Y0.2 Z0.3\nG56 X[0.1 + 0.2]\nG1 Y[1/3] F[10 * 3]\nM30\n",
    "a subroutine": "o<s> sub\nG1 X1\no<s> endsub\nG21 G90 G54 F100\n#1 = 1\no<s> call\n",
    "F after G94": "G21 G90 G54 F100\n#1 = 1\nG94 F10 G1 X#1\nG94\nF5\nG1 Y#1\nM30\n",
    "incremental": "G21 G91 G54 F100\n#1 = 1\nG1 X1\nG0 Y[#1 / 3] Z-0.1\nG55 X0.1\nG90 X1\nG91 Y1\nM30\n",
    # arc40: arcs in G91, on a G91 chain, and in two planes
    "an arc in G91": "G21 G91 G17 G54 F100\n#1 = 1\nG2 X1 Y1 R5\n",
    "an arc after G91": "G21 G91 G17 G54 F100\n#1 = 1\nG1 X1\nG90 Y2\nG2 X1 Y1 R5\n",
    "arcs in two planes": "G21 G90 G18 G54 F100\n#1 = 1\nG0 X0 Y0 Z0\nG2 X1 Z1 R5\nG17 G2 X2 Y1 R5\n",
    # issue 36: real programs carry a tool change, a dwell, an exact-stop mode
    "tools, dwells, path modes": "G21 G90 G17 G54 F800\nT1 M6\n#1 = 0\nG1 X[#1 + 1] Y2\nG4 P0.5\n"
                                 "G61\nG1 X[#1 + 3]\nG61.1 Y[#1]\nT2\nM6 M3 S1000\nG64\nG1 X0 Y0\nM61 Q3\n"
                                 "G04 P[#1 + 1]\nM30\n",
}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_programs_the_pass_follows(name):
    machine = parse_machine(machine_text({"G54": ("10", "-2.5", "0"), "G55": ("0.1", "0.1", "0.1"),
                                          "G56": ("1000.0001", "0", "0")}, ("1", "2", "3")))
    path = check_against_full(ACCEPTED[name], machine)
    assert path is not None, "declined"
    assert path.motions > 0


ASSUMED = {  # a program that leaves modal groups to the machine file: the groups the full path notes, in order
    "no header": ("F100\n#1 = 1\nG1 X#1 Y2\nG2 X3 Y2 R2\nM30\n", None,
                  (("units", "G21"), ("distance", "G90"), ("offset", "G54"), ("plane", "G17"))),
    "an arc before G17": ("G21 G90 G54 F100\n#1 = 1\nG2 X1 Y1 R5\n", None, (("plane", "G17"),)),
    "a G55 machine": ("G21 F100\n#1 = 1\nG0 X#1\nG54 G90 G1 Y1\n", '["G55"]',
                      (("distance", "G90"), ("offset", "G55"))),
    "a G18 machine": ("G90 G21 G54 F100\n#1 = 1\nG1 X#1\nG2 X3 Z0 R2\nG3 X4 Z1 R2\n", '["G18"]',
                      (("plane", "G18"),)),
    "a plane set before the first arc": ("F100\n#1 = 1\nG1 X#1\nG18\nG2 X3 Z0 R2\n", None,
                                         (("units", "G21"), ("distance", "G90"), ("offset", "G54"))),
    "a dwell first": ("F100\n#1 = 1\nG4 P1\nG21 G90\nG1 X#1\n", None, (("offset", "G54"),)),
    "no units": ("G90 G54 F100\n#1 = 1\nG1 X#1\n", None, (("units", "G21"),)),
}


@pytest.mark.parametrize("name", sorted(ASSUMED))
def test_the_pass_notes_the_groups_it_assumed(name):
    """Each group the program left to the machine file, at the first motion that needs it (an arc: the plane
    too), with the machine file's code; the full path's notes are the same (:func:`check_against_full`)."""
    text, modal, assumed = ASSUMED[name]
    path = check_against_full(text, parse_machine(machine_text(modal=modal)))
    assert path is not None, "declined"
    assert path.assumed == assumed


def test_the_rows_are_the_controllers_doubles():
    path = check_against_full("G21 G90 G54 F100\nG1 X[0.1 + 0.2] Y[1 / 3]\n#1 = 0.1\nG1 X[#1 * 3]\n", MACHINE)
    assert path is not None
    assert list(path.columns[0]) == [0.0, 0.1 + 0.2, 0.1 * 3]
    assert list(path.columns[1]) == [0.0, 1 / 3, 1 / 3]
    lo, hi = path.enclosure(2, 2)  # rows 1 and 2: X = 0.1 + 0.2 and 0.1 * 3, both 0.30000000000000004
    assert lo["X"] < Fraction(3, 10) < hi["X"] and hi["X"] - lo["X"] < Fraction(1, 10**12)
    assert lo["Y"] < Fraction(1, 3) < hi["Y"] and hi["Y"] - lo["Y"] < Fraction(1, 10**12)


DECLINED = {
    "an arc without a centre": ("G21 G90 G17 G54 F100\n#1 = 1\nG2 X1 Y1\n", "without I, J, K or R"),
    # (G20: tests/gcode/test_double_pass_units.py)
    "a half circle by R in inches": ("G20 G90 G17 G54 F100\n#1 = 1\nG2 X2 R1\n", "about 2|R|"),
    # spindle and coolant M codes, one to a block, and S are followed (issue 36); two in a block are not
    "two spindle and coolant codes": ("G21 G90 G54 F100\n#1 = 1\nM3 M8\nG1 X1\n", "M code"),
    # the full path's GC209
    "a negative spindle speed": ("G21 G90 G54 F100\n#1 = 1\nS[#1 - 2] M3\nG1 X1\n", "negative spindle speed"),
    "a computed tool number": ("G21 G90 G54 F100\n#1 = 1\nT[#1] M6\nG1 X1\n", "computed"),
    "a tool number not whole": ("G21 G90 G54 F100\n#1 = 1\nT1.5 M6\nG1 X1\n", "code 1.5"),
    "M61 without Q": ("G21 G90 G54 F100\n#1 = 1\nM61\nG1 X1\n", "M61 without Q"),
    "Q without M61": ("G21 G90 G54 F100\n#1 = 1\nQ1\nG1 X1\n", "without M61"),
    "G4 without P": ("G21 G90 G54 F100\n#1 = 1\nG4\nG1 X1\n", "G4 without P"),
    "G4 with an axis word": ("G21 G90 G54 F100\n#1 = 1\nG4 P1 X1\n", "G4 with axis words"),
    "a dwell of no time": ("G21 G90 G54 F100\n#1 = 0\nG4 P#1\nG1 X1\n", "not positive"),
    "G64 Q without P": ("G21 G90 G54 F100\n#1 = 1\nG64 Q0.01\nG1 X1\n", "Q"),
    "G61.2": ("G21 G90 G54 F100\n#1 = 1\nG61.2\nG1 X1\n", "code"),
    "state read": ("G21 G90 G54 F100\n#1 = #5221\nG1 X#1\n", "parameter"),
    "a global name": ("G21 G90 G54 F100\n#<_a> = 1\nG1 X#<_a>\n", "global"),
    "no feed": ("G21 G90 G54\n#1 = 1\nG1 X#1\n", "feed"),
    "feed zero": ("G21 G90 G54 F0\n#1 = 1\nG0 X#1\n", "feed"),
    "a message": ("G21 G90 G54 F100\n#1 = 1\n(MSG, hello)\nG1 X#1\n", "magic"),
    "division by zero": ("G21 G90 G54 F100\n#1 = [1 / 0]\nG1 X#1\n", "division"),
    # the pass follows a sub defined before its call (issue 36: tests/gcode/test_double_pass_calls.py), not
    # LinuxCNC's search forward for one defined after it
    "a subroutine defined after its call": ("G21 G90 G54 F100\n#1 = 1\no<s> call\no<s> sub\nG1 X1\no<s> endsub\n",
                                            "not defined before"),
    "a repeat": ("G21 G90 G54 F100\n#1 = 1\no1 repeat [2]\nG1 X#1\no1 endrepeat\n", "repeat"),
    "break": ("G21 G90 G54 F100\n#1 = 0\no1 while [1]\no1 break\no1 endwhile\n", "break"),
    "the iteration bound": ("G21 G90 G54 F100\n#1 = 0\no1 while [#1 LT 5]\n#1 = [#1 + 1]\nG1 X#1\no1 endwhile\n",
                            "iteration bound"),
    "labels crossed": ("G21 G90 G54 F100\n#1 = 0\no1 if [1]\no2 if [1]\no1 endif\no2 endif\n", "nested"),
    "a label reused inside": ("G21 G90 G54 F100\n#1 = 0\no1 if [1]\no1 if [1]\no1 endif\no1 endif\n", "reused"),
    # rs274: "duplicate O-word label - already defined in line 3" (found by the dp-hunt relations)
    "a label reused after": ("G21 G90 G54 F100\n#1 = 0\no1 if [1]\no1 endif\no1 if [1]\no1 endif\n", "reused"),
    "block delete": ("G21 G90 G54 F100\n#1 = 1\n/G1 X#1\n", "does not follow"),
    "a computed code": ("G21 G90 G54 F100\n#1 = 1\nG[#1] X2\n", "computed"),
    "G1.5": ("G21 G90 G54 F100\n#1 = 1\nG1.5 X2\n", "code"),
    "two motions": ("G21 G90 G54 F100\n#1 = 1\nG0 G1 X2\n", "modal group"),
    "a tool length not in the machine": ("G21 G90 G54 F100\n#1 = 1\nG43 H1\nG1 X#1\n", "H register"),
    "an H word alone": ("G21 G90 G54 F100\n#1 = 1\nH1\nG1 X#1\n", "H word without G43"),
    "a J word in G18": ("G21 G90 G18 G54 F100\n#1 = 1\nG2 X1 Z1 I1 J1\n", "centre word other than K and I"),
    "an I word in G19": ("G21 G90 G19 G54 F100\n#1 = 1\nG2 Y1 Z1 I1\n", "centre word other than J and K"),
    "turns": ("G21 G90 G17 G54 F100\n#1 = 1\nG2 X1 Y1 R5 P2\n", "word P"),
    "R and I": ("G21 G90 G17 G54 F100\n#1 = 1\nG2 X1 Y1 R5 I1\n", "R and I"),
    "a half circle by R": ("G21 G90 G17 G54 F100\n#1 = 1\nG2 X2 R1\n", "about 2|R|"),
    "R too short": ("G21 G90 G17 G54 F100\n#1 = 1\nG2 X2 R0.9\n", "about 2|R|"),
    "an arc off its circle": ("G21 G90 G17 G54 F100\n#1 = 1\nG2 X2 I1.1\n", "arc tolerance"),
    "I with G1": ("G21 G90 G17 G54 F100\n#1 = 1\nG1 X2 I1\n", "without G2"),
    "G59.1": ("G21 G90 G59.1 F100\n#1 = 1\nG1 X#1\n", "code"),
    "EXISTS": ("G21 G90 G54 F100\n#1 = EXISTS[#<a>]\nG1 X#1\n", "EXISTS"),
    "a line that does not parse": ("G21 G90 G54 F100\n#1 = [1 +\nG1 X#1\n", "parse"),
    # LinuxCNC checks the feed of a G1 block without axis words too (found by the dp-hunt relations)
    "G1 alone without a feed": ("#1 = 1\nG21 G90 G54\nG1\nM30\n", "feed"),
    # G94 sets the feed rate to 0 before F is read (convert_feed_mode; rs274 prints SET_FEED_RATE(0))
    "G94 resets the feed": ("G21 G90 G54 F100\n#1 = 1\nG94\nG1 X1\nM30\n", "feed"),
    "G94 on the line of the motion": ("G21 G90 G54 F100\n#1 = 1\nG94 G1 X1\nM30\n", "feed"),
}


@pytest.mark.parametrize("name", sorted(DECLINED))
def test_programs_outside_the_subset_are_declined(name):
    text, why = DECLINED[name]
    with pytest.raises(Declined, match=why):
        double_pass(text, MACHINE, max_iterations=5)


@pytest.mark.parametrize("modal", ['["G20"]', '["G91"]', '["G93"]', '["G59.1"]'])
def test_a_machine_that_starts_outside_the_subset_is_declined(modal):
    machine = parse_machine(machine_text(modal=modal))
    with pytest.raises(Declined):
        double_pass("G21 G90 G54 F100\n#1 = 1\nG1 X#1\n", machine, max_iterations=5)


def test_a_machine_of_another_dialect_is_declined():
    from pathlib import Path

    fanuc = Path(__file__).resolve().parents[2] / "specs" / "machines" / "fanuc_mill.toml"
    from nczones.machine import load_machine

    with pytest.raises(Declined, match="dialect"):
        double_pass("G21 G90 G54 F100\n#1 = 1\nG1 X1\nM30\n", load_machine(fanuc), max_iterations=5)


def test_a_position_beyond_the_double_range_is_declined():
    huge = "9" * 400  # its double is infinite; the line has the shape of the one before, whose step reads it
    with pytest.raises(Declined, match="a position beyond the double range"):
        double_pass(f"G21 G90 G54 F100\n#1 = 1\nG1 X1 Y1\nG1 X{huge} Y2\n", MACHINE, max_iterations=5)


_OPERANDS = st.one_of(st.floats(), st.sampled_from([0.0, -0.0, 1e-4, -1e-4, 5e-5, 1.0, 2.0, math.inf, -math.inf]))


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.sampled_from(sorted(doubles._COMPARE)), _OPERANDS, _OPERANDS)
def test_doubles_compare(op, a, b):
    # the comparisons the double pass emits inline give binary_op's value (NaN and infinities included)
    got = eval("1.0 if " + doubles._COMPARE[op].format(a="a", b="b") + " else 0.0", {}, {"a": a, "b": b})  # noqa: S307
    assert got == binary_op(op, (a, None), (b, None))[0]
    assert set(doubles._COMPARE) == {"gt", "ge", "lt", "le", "eq", "ne", "and", "or", "xor"}


def test_an_assignment_line_calls_no_plan():
    # a line that only sets parameters runs no plan; the program's motions are the full path's
    text = ("G21 G90 G54 F100\n#1 = 0\n#2 = 0\no1 while [#1 LT 5]\n#2 = [#2 + [#1 GT 2] + [#1 EQ 1]]\n"
            "#1 = [#1 + 1]\nG1 X#2 Y[#1 XOR 0]\no1 endwhile\nM30\n")
    p = double_pass(text, MACHINE, max_iterations=100)
    assert list(p.columns[0]) == [0.0, 0.0, 1.0, 1.0, 2.0, 3.0]
    assert list(p.columns[1]) == [0.0, 1.0, 1.0, 1.0, 1.0, 1.0]
