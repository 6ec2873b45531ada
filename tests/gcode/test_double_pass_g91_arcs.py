"""Arcs in G91, on G91 chains and in more than one plane in the double pass (arc40, issue 36).

A G91 arc's start carries its G91 chain's error, its end ``S' + W`` the chain's next, its centre ``S' + (I, J)``
the start's: the pass computes its box with the offsets' bound grown by the chains' errors
(``double_arcs.chain_offb``).  Arcs in G17, G18 and G19 in one program: each arc's box on its own plane's axes
(``DoublePath.arc_pair``).  Checked here:

- the pass's invariant (``check_against_full``: as many motions, every exact end and every exact arc, at both
  radii of a spiral and its extremes, inside its row's box) on generated programs mixing G90 and G91 lines, I/J
  and R arcs both ways, G91 loops of arcs (long chains), G17/G18/G19 switches and G20;
- the verdict after a long G91 chain that drifts the doubles some 240 times the arcs' own rounding away from the
  exact path, with a zone face 1e-12 mm either side of an arc's exact extreme: the routed verdict (the pass) is
  the full path's without the pass and the vectorized tier (``fast=False``), and the pass proves a face 1e-6 mm
  out.  Without the chain's bound in the arc (``chain_offb`` not applied: the mutation check of arc40) the pass
  proves the face 1e-12 mm inside the extreme ``safe``;
- the same with the arcs of a program in G17 then G18 then G19 (a box on the wrong axes, or G18 taken in the
  other sense, misses an extreme: a wrong ``safe``).

``NCZONES_G91_ARC_EXAMPLES=N`` for a longer generated run.
"""

from __future__ import annotations

import math
import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import doubles
from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.machine import parse_machine
from nczones.prover.result import Verdict
from tests.gcode.rs274_arc_programs import dec, in_plane
from tests.gcode.test_double_pass import check_against_full, machines
from tests.gcode.test_double_pass import machine_text as pass_machine_text
from tests.machines import machine_text

EXAMPLES = int(os.environ.get("NCZONES_G91_ARC_EXAMPLES", "25"))


def _dec(x: float, places: int) -> str:
    return f"{x:.{places}f}"


@st.composite
def g91_arc(draw) -> str:
    """A G91 arc in G17's letters (:func:`in_plane` moves it): I/J (an end on the circle to the words' places, a
    little off it, a whole turn by I/J alone) or R (both signs, chords up to near 2|R|), both ways, a helix."""
    code = draw(st.sampled_from(["G2", "G3"]))
    places = draw(st.sampled_from([3, 4, 6]))
    radius = draw(st.sampled_from([0.5, 1.0, 7.25, 120.0]))
    if draw(st.booleans()):
        a0 = draw(st.sampled_from([0.0, 1.0, -2.5, math.pi / 4, math.pi / 2]))
        sweep = draw(st.sampled_from([math.pi / 2, 2.0, -math.pi / 2, 3 * math.pi / 2, math.pi - 1e-6, 1e-5]))
        i, j = -radius * math.cos(a0), -radius * math.sin(a0)
        off = draw(st.sampled_from([0.0, 0.0, 1e-4, -0.0015]))
        wx = float(_dec(i, places)) + (radius + off) * math.cos(a0 + sweep)
        wy = float(_dec(j, places)) + (radius + off) * math.sin(a0 + sweep)
        words = f"X{_dec(wx, places)} Y{_dec(wy, places)} I{_dec(i, places)} J{_dec(j, places)}"
        if draw(st.integers(0, 5)) == 0:
            words = f"I{_dec(i, places)} J{_dec(j, places)} Z-0.5"  # a whole turn (a helix: the end in Z)
    else:
        half = draw(st.sampled_from([0.2, 0.5, 0.9, 0.9999999]))
        t = draw(st.sampled_from([0.0, 0.7, math.pi / 2, -2.0]))
        sign = draw(st.sampled_from(["", "-"]))
        words = (f"X{_dec(2 * radius * half * math.cos(t), places)} Y{_dec(2 * radius * half * math.sin(t), places)} "
                 f"R{sign}{radius}")
    if draw(st.integers(0, 4)) == 0:
        words += " Z[#3 + 0.25]"
    return f"{code} {words}"


@st.composite
def g91_pieces(draw, depth: int = 1) -> list[str]:
    """G17-letter lines: G91 arcs, G90/G91 straight moves (far ones: a chain's error at large magnitudes), a G90 arc
    from a point the line before moves to, a loop of G91 arcs (a long chain), G20/G21."""
    kind = draw(st.integers(0, 9))
    if kind <= 4:
        return ["G91", *(draw(g91_arc()) for _ in range(draw(st.integers(1, 3))))]
    if kind == 5:
        far = draw(st.sampled_from(["1", "0.1", "4000.3", "-2500.7", "[#1 * 3]"]))
        back = far[1:] if far.startswith("-") else f"-{far}"
        return [f"G91 G1 X{far} Y0.3", f"X{back} Y-0.3"]
    if kind == 6:  # a G90 arc (its start known), perhaps still on a Z chain
        sx, sy = (draw(st.integers(-400, 400)) / 8 for _ in range(2))
        return [f"G90 G1 X{sx} Y{sy}", f"G2 X{sx + 2.0} Y{sy} I1 J0"]
    if kind == 7 and depth > 0:
        n = draw(st.integers(1, 6))
        body = [line for _ in range(draw(st.integers(1, 3))) for line in draw(g91_pieces(depth - 1))]
        return ["#11 = 0", f"o{len(body) + 100} while [#11 LT {n}]", *body, "#11 = [#11 + 1]",
                f"o{len(body) + 100} endwhile"]
    if kind == 8:
        return [draw(st.sampled_from(["G20", "G21", "G21", "G90", "G91 G0 Z0.1"]))]
    return [f"G91 G1 X[#1 + {draw(st.integers(-9, 9)) / 10}]"]


@st.composite
def g91_programs(draw) -> str:
    """A program of :func:`g91_pieces`, each in a plane drawn for it (written in that plane's letters)."""
    lines = ["G21 G90 G17 G54 F300", "#1 = 0.5", "#3 = 0"]
    labels = set()
    turn = draw(st.integers(0, 2))  # the planes in turn from this one (a piece may keep the plane before)
    for k in range(draw(st.integers(2, 8))):
        plane = (17, 18, 19)[(k + turn) % 3] if draw(st.integers(0, 3)) else 17
        piece = draw(g91_pieces())
        label = next((x.split()[0] for x in piece if " while " in x), None)
        if label in labels:
            continue  # (an o-word label once a program)
        labels.add(label)
        lines += [f"G{plane}"] + ([in_plane(x, plane) for x in piece] if plane != 17 else piece)
    return "\n".join([*lines, "M30"]) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(g91_programs(), machines())
def test_g91_arcs_and_planes_are_enclosed_by_the_full_interpreter(text, machine):
    check_against_full(text, machine)


#: Programs the pass must take (G17 letters; the checks of :func:`check_against_full`).
TAKEN = {
    "a G91 circle of quarters, 40 times": "G21 G90 G17 G54 F300\n#1 = 0\nG0 X0.3 Y0.1\nG91\no1 while [#1 LT 40]\n"
                                           "G3 X-1.1 Y1.1 I-1.1 J0\nG3 X-1.1 Y-1.1 R1.1\nG3 X1.1 Y-1.1 I0 J-1.1\n"
                                           "G3 X1.1 Y1.1 R-1.1\n#1 = [#1 + 1]\no1 endwhile\nM30\n",
    "a G90 arc on a chain of Z": "G21 G90 G17 G54 F300\n#1 = 0.1\nG0 X0 Y0\nG91 G1 Z#1\nZ#1\nG90 G2 X2 Y0 I1 J0\n"
                                 "M30\n",
    "G20 G91 arcs": "G20 G91 G17 G54 F30\n#1 = 0.1\nG1 X#1\nG2 X0.2 Y0 I0.1 J0\nG3 X0.1 Y0.1 R0.1\nG21 G2 X2 Y0 "
                    "I1 J0\nM30\n",
    "G17, G18, G19 and back": "G21 G90 G17 G54 F300\n#1 = 1\nG1 X1 Y1 Z1\nG2 X3 Y1 I1 J0\nG18 G3 Z3 X3 K1 I0\n"
                              "G19 G91 G2 Y2 Z0 R1.5\nG17 G90 G3 X5 Y1 R-2\nG18 G91 G2 Z-1 X-1 R1\nM30\n",
}


@pytest.mark.parametrize("name", sorted(TAKEN))
def test_programs_the_pass_takes(name):
    machine = parse_machine(pass_machine_text({"G54": ("10", "-2.5", "0.1")}, ("1", "2", "3")))
    path = check_against_full(TAKEN[name], machine)
    assert path is not None, "declined"
    assert path.arcs > 0


def test_a_g91_arc_where_x_may_be_a_diameter_declines():
    """A lathe (X diameters, G7): a G91 arc declines as before (the full path decides it)."""
    lathe = parse_machine(machine_text("report_lathe", set={"machine.path_mode": "G61"}))
    text = "G21 G90 G18 G54 F100\n#1 = 1\nG1 X#1 Z0\nG91 G2 X2 Z2 R2\nM30\n"
    with pytest.raises(doubles.Declined, match="diameter"):
        double_pass(text, lathe, max_iterations=10)


# -- a zone face at an arc's exact extreme after a long G91 chain -------------------------------------------

#: 300 times out 4000.3 mm, back 4000.6, on 0.3 (exactly back at X0.3): the doubles drift +1.36e-10 mm (some 240
#: times the arc's own rounding at its magnitude), then an arc clockwise through its -X extreme at X-3.7 (centre
#: S + (6, 8), radius 10; by I/J or R, in G91 or in G90) and a G90 move away.
_DRIFT = ("G21 G90 G17 G54 F300\n#1 = 0\nG0 X0.3 Y0 Z0\nG91\no1 while [#1 LT 300]\nG1 X4000.3\nX-4000.6\nX0.3\n"
          "#1 = [#1 + 1]\no1 endwhile\n{arc}\nG90 G0 X1 Y30\nM30\n")
DRIFT_ARCS = {"I/J": "G2 X0 Y16 I6 J8", "R": "G2 X0 Y16 R10",
              # the same arc in G90 from the chain's last row: its start's error alone
              "I/J in G90": "G90 G2 X0.3 Y16 I6 J8", "R in G90": "G90 G2 X0.3 Y16 R10"}


def _face_machine(axis: str, sign: int, face: Fraction):
    """box_5000 in exact stop (G61: no rounded corner reaches past the motions) with its travel's face on ``axis``
    (``sign``) at ``sign * face``."""
    text = machine_text("box_5000", set={"machine.path_mode": "G61"})
    line = 'max = { X = "5000", Y = "5000", Z = "5000" }' if sign > 0 else 'min = { X = "-5000", Y = "-5000", Z = "-5000" }'
    assert line in text
    return parse_machine(text.replace(line, line.replace(f'{axis} = "{sign * 5000}"', f'{axis} = "{dec(sign * face)}"')))


def _verdicts(text: str, machine, monkeypatch):
    from tests.gcode.test_rs274_double_arcs import _verdicts as both

    return both(text, machine, monkeypatch)


def test_the_chain_drifts_the_doubles_far_past_the_arcs_rounding():
    """The premise of the face test: the arc's start row is 1e-10 mm off the exact X0.3."""
    path = double_pass(_DRIFT.format(arc=DRIFT_ARCS["I/J"]), parse_machine(machine_text("box_5000")),
                       max_iterations=1000)
    start = path.columns[0][path.arc_rows[0] - 1]
    assert Fraction(start) - Fraction(3, 10) > Fraction(1, 10**10)
    assert path.inc_bound[0] > 1e-10


@pytest.mark.parametrize("form", sorted(DRIFT_ARCS))
def test_a_face_at_the_arcs_extreme_after_a_long_g91_chain(form, monkeypatch):
    text = _DRIFT.format(arc=DRIFT_ARCS[form])
    for eps in (Fraction(-1, 10**12), Fraction(0), Fraction(1, 10**12), Fraction(1, 10**6)):
        routed, _full = _verdicts(text, _face_machine("X", -1, Fraction(37, 10) + eps), monkeypatch)
        assert routed.verdict is (Verdict.UNSAFE if eps < 0 else Verdict.SAFE), (eps, routed.reasons)
        if eps > Fraction(1, 10**7):  # past the chain's bound: the pass proves it
            assert "double_pass_boxes" in dict(routed.stats), routed.reasons


#: Arcs in G17, G18, G19 in turn (each on a circle of radius 10 through its plane's + and - extremes, as
#: test_double_pass_planes draws them), G91 and G90, the extremes exact: (plane, words, the extremes it reaches
#: as (first / second axis, sign)).
_MIXED = ("G21 G90 G54 F300\n#1 = 10\nG17 G0 X#1 Y0 Z0\nG3 X-6 Y8 I-10 J0\nG18 G0 Z10 X0\nG91 G2 Z-16 X8 R-10\n"
          "G90 G19 G0 Y5 Z5\nG91 G3 Y-16 Z8 J-10 K0\nG90 G0 X0 Y0 Z0\nM30\n")
MIXED_FACES = [("Y", 1, 10), ("Z", -1, 10), ("X", -1, 10), ("Z", 1, 15)]


@pytest.mark.parametrize("axis, sign, top", MIXED_FACES)
def test_a_face_at_an_extreme_of_arcs_in_three_planes(axis, sign, top, monkeypatch):
    """G17's ccw arc about the origin reaches Y+10; G18's clockwise R-10 (the long way, first axis Z, second X,
    about the origin) reaches Z-10 and X-10; G19's ccw arc (Y, Z) about (-5, 5) reaches Z+15; no row reaches
    them: a face 1e-12 mm inside is ``unsafe``, on it and beyond ``safe``, as the full path decides; 1e-6 mm
    beyond, the pass's proof."""
    path = check_against_full(_MIXED, parse_machine(machine_text("box_5000")))
    assert path is not None and path.arcs == 3 and sorted(path.arc_planes) == [0, 1, 2]
    for eps in (Fraction(-1, 10**12), Fraction(0), Fraction(1, 10**12), Fraction(1, 10**6)):
        routed, _full = _verdicts(_MIXED, _face_machine(axis, sign, top + eps), monkeypatch)
        assert routed.verdict is (Verdict.UNSAFE if eps < 0 else Verdict.SAFE), (eps, routed.reasons)
        if eps > Fraction(1, 10**7):
            assert "double_pass_boxes" in dict(routed.stats), routed.reasons


def test_windows_keep_each_arcs_plane_box_and_offsets_bound():
    """Run in windows of 5 motions (``on_window``, as ``verify`` runs a long program), every arc has the row, the
    plane (``arc_pair``), the quick box and the offsets' bound (``arc_more``: a chain's error in it) of the whole
    run, across windows' edges and plane changes (and a window within a run of G18 arcs); refined in a window,
    the box of the whole run refined.  (Dropping a window's arcs' planes out of step with their rows fails it.)"""
    text = ("G21 G90 G17 G54 F300\n#1 = 0\nG0 X1 Y1 Z1\no1 while [#1 LT 6]\nG17 G91 G2 X2 Y0 I1 J0\nG18 G3 Z1 X1 R1\n"
            "G2 Z1 X-1 R1\nG3 Z1 X1 R1\nG2 Z1 X-1 R1\nG3 Z1 X1 R1\nG2 Z1 X-1 R1\nG90 G19 G1 Y1 Z1\nG2 Y3 Z1 J1 K0\nG91 G1 X4000.3\nX-4000.3\n#1 = [#1 + 1]\no1 endwhile\nM30\n")
    machine = parse_machine(machine_text("box_5000"))
    whole = double_pass(text, machine, max_iterations=100)

    def arcs(path) -> dict[int, tuple]:
        words = path.arc_more[0]
        return {row: (path.arc_pair(k), tuple(path.arc_boxes[4 * k:4 * k + 4]), words[4 * k + 3])
                for k, row in enumerate(path.arc_rows)}

    want = arcs(whole)
    assert len({pair for pair, _box, _ob in want.values()}) == 3 and len(want) == whole.arcs == 48
    assert max(ob for _pair, _box, ob in want.values()) > whole.arc_more[1]  # a chain's error in some
    whole.refine(1, whole.motions)
    refined = arcs(whole)
    seen: dict[int, tuple] = {}

    def take(window) -> bool:
        for row, got in arcs(window).items():
            assert seen.setdefault(row, got) == got == want[row], row
        return True

    take(double_pass(text, machine, max_iterations=100, on_window=take, window=5))
    assert seen == want

    def take_refined(window) -> bool:  # (the last arc of a window may be the next's first: refined already)
        assert all(got in (want[row], refined[row]) for row, got in arcs(window).items())
        window.refine(window.row0 + 1, window.motions)
        assert all(got == refined[row] for row, got in arcs(window).items())
        return True

    take_refined(double_pass(text, machine, max_iterations=100, on_window=take_refined, window=5))
