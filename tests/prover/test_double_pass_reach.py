"""The growth of a G64 box with arcs by one motion's reach (plane41: ``nczones/gcode/linuxcnc/double_reach.py``,
``prover/doubles.py`` ``_grown_fits``) against the full path.

The bound: for every two neighbouring motions of a box, ``min(w_k, w_(k+1))`` on each axis (``w`` a motion's
exact width: a line's ends, an arc's every point at 200 bits, ``tests/gcode/test_double_pass.arc_points``) is at
most ``DoublePath.reach``, on generated programs of lines and arcs in G17, G18 and G19 mixed, G90 and G91, with
decimal words (their doubles are not the exact values).  The mutation checks: the bound without the rows' error
and the half-ulp factor (a bound one rounding tighter than proved), and without the arcs' widths (or with the
arcs' widths on the wrong plane's axes, which the bound does not read: every plane axis takes the widest arc),
fails on a fixed program each.

The verdict: with the pass and without it (the full path) the same, on the same kind of programs under G64, G64
P and G61, on a travel box tight on X (the program's long axis: a box grown by its own size does not fit, so the
reach decides) with a face at an arc's exact extreme (the program's there), one pulse inside, on it, one pulse
outside, or 1 or 10 mm outside.
"""

from __future__ import annotations

import os
from fractions import Fraction

import mpmath
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc import double_reach
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.motion import PLANE_AXES, SegmentKind
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import MACHINE, arc_points
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import both_ways, same_outcome

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "40"))
AXES = ("X", "Y", "Z")
PULSE = Fraction(1, 10**4)
#: a quarter turn counter-clockwise of (u, v) n times
_TURN = {0: lambda u, v: (u, v), 1: lambda u, v: (-v, u), 2: lambda u, v: (-u, -v), 3: lambda u, v: (v, -u)}
_CENTRE_WORD = {"X": "I", "Y": "J", "Z": "K"}


def _dec(v: Fraction) -> str:
    """A decimal of at most 4 places (the generator's values are)."""
    s = f"{float(v):.4f}"
    assert Fraction(s) == v, (v, s)
    return s


class _Writer:
    """A program's text and every motion's exact ends and arcs' extremes, as the generator writes it."""

    def __init__(self) -> None:
        self.pos = {a: Fraction(0) for a in AXES}
        self.inc = False
        self.lines: list[str] = []
        self.extremes: list[tuple[str, Fraction]] = []  # (axis, value) an arc reaches: its exact extreme
        self.ends: list[dict[str, Fraction]] = [dict(self.pos)]  # every motion's exact end

    def words(self, end: dict[str, Fraction], expr: bool) -> str:
        out = []
        for n, (a, v) in enumerate(end.items()):
            w = v - self.pos[a] if self.inc else v
            out.append(f"{a}[#1 + {_dec(w)}]" if expr and n == 0 else f"{a}{_dec(w)}")
        return " ".join(out)

    def line(self, d: dict[str, Fraction], expr: bool) -> None:
        end = {a: self.pos[a] + v for a, v in d.items()}
        self.lines.append(f"G1 {self.words(end, expr)}")
        self.pos.update(end)
        self.ends.append(dict(self.pos))

    def arc(self, plane: int, r: Fraction, start_q: int, quarters: int, cw: bool, form: str, helix: Fraction,
            expr: bool) -> None:
        a, b, n = PLANE_AXES[plane]
        ux, uy = _TURN[start_q](r, Fraction(0))  # the start's vector from the centre
        cx, cy = self.pos[a] - ux, self.pos[b] - uy
        wx, wy = _TURN[(4 - quarters) % 4 if cw else quarters](ux, uy)
        end = {a: cx + wx, b: cy + wy}
        if helix:
            end[n] = self.pos[n] + helix
        if form == "R":  # the short way (a quarter) by R > 0, three quarters by R < 0
            centre = f"R{_dec(r if quarters == 1 else -r)}"
        else:
            centre = f"{_CENTRE_WORD[a]}{_dec(-ux)} {_CENTRE_WORD[b]}{_dec(-uy)}"
        self.lines.append(f"G{plane} G{2 if cw else 3} {self.words(end, expr)} {centre}")
        # the axis directions the sweep holds: the start's angle turned by 1..quarters quarter turns (exclusive of
        # the start's own direction, which is an end)
        for q in range(1, quarters + 1):
            px, py = _TURN[(4 - q) % 4 if cw else q](ux, uy)
            self.extremes += [(a, cx + px), (b, cy + py)] if px and py else \
                [(a, cx + px)] if px else [(b, cy + py)]
        self.pos.update(end)
        self.ends.append(dict(self.pos))

    def reached(self, axis: str) -> tuple[Fraction, Fraction]:
        """The least and largest value the program's motions reach on ``axis`` (exact)."""
        values = [p[axis] for p in self.ends] + [v for a, v in self.extremes if a == axis]
        return min(values), max(values)


@st.composite
def mixed_programs(draw, mode: str | None = None) -> tuple[str, _Writer]:
    """A parametric program along X: lines and arcs in G17, G18 and G19 (quarters and three quarters, by centre
    words or R, some helical), G90 and G91 in turn, decimal words; with its path mode ``mode`` (drawn: G64,
    G64 P0.01, G61) in the program's head."""
    mode = mode or draw(st.sampled_from(["G64", "G64", "G64 P0.01", "G61"]))
    w = _Writer()
    w.lines += ["G21 G90 G54 F500", mode, "#1 = 0", "G0 X0 Y0 Z0"]
    radii = st.integers(5, 400).map(lambda k: Fraction(k, 100))
    steps = st.integers(-300, 3000).map(lambda k: Fraction(k, 1000))
    for _ in range(draw(st.integers(3, 14))):
        if draw(st.integers(0, 5)) == 0:
            w.inc = not w.inc
            w.lines.append("G91" if w.inc else "G90")
        expr = draw(st.booleans())
        if draw(st.integers(0, 2)) == 0:
            d = {"X": draw(steps.filter(bool))}
            if draw(st.booleans()):
                d[draw(st.sampled_from(["Y", "Z"]))] = draw(steps)
            w.line(d, expr)
            continue
        plane = draw(st.sampled_from([17, 18, 19]))
        quarters = draw(st.sampled_from([1, 1, 2, 3]))
        form = draw(st.sampled_from(["centre", "R"])) if quarters != 2 else "centre"
        helix = draw(st.sampled_from([Fraction(0), Fraction(0), Fraction(-1, 4), Fraction(3, 8)]))
        w.arc(plane, draw(radii), draw(st.integers(0, 3)), quarters, draw(st.booleans()), form, helix, expr)
    w.lines.append("M30")
    return "\n".join(w.lines) + "\n", w


def _mp(v: Fraction) -> mpmath.mpf:
    return mpmath.mpf(v.numerator) / v.denominator


def exact_widths(seg) -> dict[str, mpmath.mpf]:
    """The width of the full path's motion ``seg`` on each axis: its ends' (a line, a helix's third axis), an arc's
    points at 200 bits on its plane's axes (its extremes among them)."""
    out = {a: abs(_mp(seg.end[i]) - _mp(seg.start[i])) for i, a in enumerate(AXES)}
    if seg.kind is SegmentKind.ARC:
        pa, pb, _n = PLANE_AXES[seg.plane]
        pts = arc_points(seg)
        out[pa] = max(p[0] for p in pts) - min(p[0] for p in pts)
        out[pb] = max(p[1] for p in pts) - min(p[1] for p in pts)
    return out


def check_reach(text: str) -> bool:
    """``reach`` of the whole program holds ``min(w_k, w_(k+1))`` of every two neighbouring motions on every
    axis; False when the pass declined the program."""
    try:
        path = double_pass(text, MACHINE, max_iterations=1000)
    except Declined:
        return False
    segments = list(interpret_text(text, MACHINE, max_loop_iterations=1000).segments())
    assert len(segments) == path.motions
    if path.motions < 2:
        return False
    with mpmath.workprec(200):
        bound = path.reach(1, path.motions)
        assert bound is not None
        widths = [exact_widths(seg) for seg in segments]
        for k in range(len(widths) - 1):
            for a in AXES:
                need = min(widths[k][a], widths[k + 1][a])
                assert need <= _mp(bound[a]), (k + 1, a, need, float(bound[a]))
    return True


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(mixed_programs())
def test_the_reach_holds_every_corners_two_motions(program):
    check_reach(program[0])


#: Two lines whose words' doubles are closer than their exact values (0.1 and 0.3: the doubles' difference is
#: below 0.2), then two three-quarter arcs in G19 (Y, Z), wider than their chords: each fails a mutation.
FIXED = ("G21 G90 G54 F500\nG64\n#1 = 0\nG1 X[#1 + 0.1]\nG1 X0.3\nG1 X0.5\n"
         "G19 G3 Y-1 Z-1 J-1 K0\nG3 Y-2 Z0 R-1\nM30\n")


def test_the_fixed_program_holds():
    assert check_reach(FIXED)


def test_mutation_a_bound_one_rounding_tighter_is_caught(monkeypatch):
    monkeypatch.setattr(double_reach, "_UP", 1)
    monkeypatch.setattr(double_reach, "row_error", lambda top, offset, inc: Fraction(0))
    try:
        check_reach(FIXED)
    except AssertionError as exc:
        assert "'X'" in str(exc)  # the lines' X: 0.3 - 0.1 in doubles is below 0.2
    else:
        raise AssertionError("the mutation survived")


def test_mutation_the_arcs_widths_left_out_is_caught(monkeypatch):
    monkeypatch.setattr(double_reach, "_widest_arc", lambda path, first, last: Fraction(0))
    try:
        check_reach(FIXED)
    except AssertionError as exc:
        assert "'Y'" in str(exc) or "'Z'" in str(exc)
    else:
        raise AssertionError("the mutation survived")


def test_mutation_the_arcs_widths_on_the_wrong_planes_axes_is_caught(monkeypatch):
    """The arcs are in G19 (Y, Z): their widths given to G17's axes (X, Y) leave Z short."""
    real = double_reach.reach

    def swapped(path, first, last, names=None):
        return real(_WithAxes(path, (0, 1)), first, last, names)

    monkeypatch.setattr(double_reach, "reach", swapped)
    try:
        check_reach(FIXED)
    except AssertionError as exc:
        assert "'Z'" in str(exc)
    else:
        raise AssertionError("the mutation survived")


class _WithAxes:
    """A path whose ``arc_axes`` are another plane's (the rest its own)."""

    def __init__(self, path, arc_axes):
        self._path, self.arc_axes = path, arc_axes

    def __getattr__(self, name):
        return getattr(self._path, name)


def _machine(w: _Writer, face: tuple[str, Fraction] | None, slack: int = 6):
    """box_5000 with its travel ``slack`` mm past the program's motions on X (tight: a box grown by its own size
    does not fit) and, with ``face``, one face of an axis at a value."""
    x_lo, x_hi = w.reached("X")
    lo = {a: "-5000" for a in AXES}
    hi = {a: "5000" for a in AXES}
    lo["X"], hi["X"] = _dec(x_lo - slack), _dec(x_hi + slack)
    if face is not None:
        axis, value = face
        (hi if value > 0 else lo)[axis] = _dec(value)  # (a value on the other side of 0 is never given)
    text = machine_text("box_5000")
    text = text.replace('min = { X = "-5000", Y = "-5000", Z = "-5000" }',
                        "min = { " + ", ".join(f'{a} = "{lo[a]}"' for a in AXES) + " }")
    text = text.replace('max = { X = "5000", Y = "5000", Z = "5000" }',
                        "max = { " + ", ".join(f'{a} = "{hi[a]}"' for a in AXES) + " }")
    return parse_machine(text)


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(mixed_programs(), st.data())
def test_the_verdict_is_the_full_paths_at_an_arcs_extreme(monkeypatch, program, data):
    text, w = program
    face = None
    if w.extremes:  # the face of an axis an arc reaches, at the program's extreme there (an arc's, mostly)
        axis = data.draw(st.sampled_from(sorted({a for a, _v in w.extremes})))
        side = data.draw(st.sampled_from([-1, 1]))
        value = w.reached(axis)[side > 0]
        if value * side > 0:  # (a face at 0 or across it would cut the start)
            face = (axis, value + side * data.draw(st.sampled_from([-PULSE, Fraction(0), PULSE, Fraction(1),
                                                                    Fraction(10)])))
    machine = _machine(w, face, data.draw(st.sampled_from([2, 6, 30])))
    with_pass, without = both_ways(text, machine, monkeypatch, max_iterations=1000)
    same_outcome(with_pass, without)


def test_a_long_run_of_side_arcs_is_one_box(monkeypatch):
    """bench_gcode.plane_mix_program's kind: G17 and G18 arcs along 400 mm of X on a travel 6 mm past it: grown by
    its own size the box does not fit (it split in some 100 boxes); by the reach it is one box."""
    w = _Writer()
    w.lines += ["G21 G90 G54 F500", "G64", "#1 = 0", "G0 X0 Y0 Z0"]
    for k in range(100):
        w.line({"X": Fraction(1)}, expr=True)
        w.arc(17, Fraction(1), 2, 2, k % 2 == 0, "centre", Fraction(0), expr=False)
        w.arc(18, Fraction(1, 2), 1, 1, k % 2 == 1, "R" if k % 3 else "centre", Fraction(0), expr=False)
    w.lines.append("M30")
    text = "\n".join(w.lines) + "\n"
    with_pass, without = both_ways(text, _machine(w, None), monkeypatch, max_iterations=1000)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    assert dict(with_pass.stats)["double_pass_boxes"] == 1


def test_an_arc_after_a_motion_linuxcnc_may_drop_declines_in_any_plane():
    """The pass's quick test before ``_Pass.tiny`` looks at both plane axes (plane41): a G18 arc after a motion of
    1e-8 mm on X (its plane's second axis; Z, the first, still) declines, after one of 1 mm on X it is taken."""
    head = "G21 G90 G54 F500\nG64\n#1 = 0\nG18\nG1 X[#1 + 10] Z1\n"
    arc = "G2 Z0 X{x} K-1 I0\nM30\n"
    with pytest.raises(Declined, match="may drop"):
        double_pass(head + "G1 X10.00000001\n" + arc.format(x="11.00000001"), MACHINE, max_iterations=1000)
    assert check_reach(head + "G1 X11\n" + arc.format(x="12"))
