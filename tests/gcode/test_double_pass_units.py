"""G20 (inches) in the double pass (nczones/gcode/linuxcnc/double_units.py) against the full interpreter.

The pass's invariant (``tests/gcode/test_double_pass.py``'s ``check_against_full``: the full path runs the
program to the end with as many motions, every exact end in the pass's widened box) on programs in inches,
with G20/G21 switches, G91 chains, work offsets and tool lengths, and words whose millimetres round badly
(``0.1``, ``1/3``, ``2.5443``: its double times 25.4 is 1.08 ulp below the exact 64.62522 mm); and a face at a
motion's exact extreme, and one ulp either side of it, decided alike with and without the pass.
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.prover.result import Verdict
from tests.gcode.rs274_arc_programs import in_plane
from tests.gcode.test_double_pass import MACHINE, check_against_full, expressions, machines
from tests.machines import load_machine, machine_text
from tests.prover.test_double_pass_proof import both_ways, same_outcome

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "60"))
INCH = Fraction(254, 10)

#: Words whose millimetres round badly, large coordinates, and expressions.
_WORDS = st.one_of(
    st.sampled_from(["0.1", "2.5443", "-2.544427", "[1 / 3]", "[#1 / 7]", "3937.0078", "-1234.56789", "0.0001",
                     "[#1 * 0.1]", "99999.9999", "1e"]).filter(lambda s: s != "1e"),
    st.decimals(-2000, 2000, places=4, allow_nan=False, allow_infinity=False).map(lambda d: f"{d:f}"),
    expressions(1),
)
#: Lines of the programs besides motions: units, distance modes, offsets and tool lengths (G43 or G49 after a
#: units change with a length applied: the pass declines it, as the full path answers unknown).
_LINES = ["G20", "G21", "G20 G91", "G21 G90", "G90", "G91", "G55", "G54", "G43 H1", "G49", "#1 = [#1 + 0.1]",
          "#<a> = [#1 / 3]", "G20 G90 G1 X[#<a>]", "G61", "G64", "G4 P0.1", "F[25.4 / 3]"]


@st.composite
def _motion(draw) -> str:
    code = draw(st.sampled_from(["G0 ", "G1 ", "", ""]))
    axes = draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True))
    return code + " ".join(f"{a}{draw(_WORDS)}" for a in axes)


@st.composite
def inch_programs(draw) -> str:
    """Programs that set G20 (or G21) before their first motion and may switch, with loops of G91 steps."""
    head = draw(st.sampled_from(["G20 G90 G54 F30 G1", "G20 G90 G17 G55 F30 G0", "G20 G91 G54 F10 G1",
                                 "G21 G90 G54 F300 G1", "G20 G90 G54 G43 H1 F30 G1"]))
    body: list[str] = ["#1 = 0.1", "#<a> = 1"]
    for _ in range(draw(st.integers(1, 10))):
        kind = draw(st.integers(0, 4))
        if kind <= 1:
            body.append(draw(_motion()))
        elif kind <= 3:
            body.append(draw(st.sampled_from(_LINES)))
        else:
            n = draw(st.integers(1, 30))
            steps = [draw(_motion()) for _ in range(draw(st.integers(1, 2)))]
            body += ["#9 = 0", f"o{len(body)} while [#9 LT {n}]", *steps, "#9 = [#9 + 1]", f"o{len(body)} endwhile"]
    return "\n".join([head, *body, "M30"]) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(inch_programs(), machines(tools=True))
def test_inch_programs_are_enclosed_by_the_full_interpreter(text, machine):
    check_against_full(text, machine)


# -- fixed programs -------------------------------------------------------------------------------------------

#: Offsets and a tool length in millimetres (the full path adds them in millimetres whatever the units).
MILL = load_machine("mill_g54_g55_h1_h2")

ACCEPTED = {
    "inches": "G20 G90 G17 G54 F30\n#1 = 0.1\nG1 X[#1] Y[1 / 3] Z2.5443\nG0 X3937.0078 Y-1234.56789\nM30\n",
    "a switch each way": "G20 G90 G54 F30\n#1 = 1\nG1 X[#1 / 3]\nG21 Y[#1 / 3]\nG20 Z0.1\nG21 X0.1\nM30\n",
    "G91 in inches": "G20 G91 G54 F30\n#1 = 0\no1 while [#1 LT 50]\nG1 X0.1 Y[1 / 3]\nG0 Z-2.5443\n"
                     "#1 = [#1 + 1]\no1 endwhile\nG90 X0\nG91 G21 Y0.1\nG20 Y0.1\nM30\n",
    "a tool length in inches": "G20 G90 G54 F30\n#1 = 1\nG43 H1\nG1 Z[#1 / 3]\nG55 X0.1\nG49\nG0 Z1\n"
                               "G21\nG43 H2\nG1 Z[#1 / 3]\nM30\n",
    "units on the motion's line": "G21 G90 G54 F30\n#1 = 1\nG20 G1 X[#1 / 3]\nG21 G1 X[#1 / 3]\nM30\n",
}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_inch_programs_the_pass_follows(name):
    path = check_against_full(ACCEPTED[name], MILL)
    assert path is not None, "declined"
    assert path.motions > 0


def test_the_rows_are_the_words_times_25_4_plus_the_offsets():
    """A G20 row is ``fl(fl(d * 25.4) + fl(offset))`` (the offsets in millimetres), not the word's double, nor
    the offset converted to inches first."""
    path = check_against_full("G20 G90 G54 F30\n#1 = 1\nG1 X[#1 / 3] Y0.1 Z2.5443\nG43 H1 Z0\nM30\n", MILL)
    assert path is not None
    assert [path.columns[i][1] for i in range(3)] == [(1 / 3) * 25.4 + 100.0, 0.1 * 25.4 + 0.0, 2.5443 * 25.4 + 50.0]
    assert path.columns[2][2] == 0.0 * 25.4 + 170.0


DECLINED = {
    "a half circle by R in inches": ("G20 G90 G17 G54 F30\n#1 = 1\nG1 X1\nG2 X3 R1\nM30\n", "about 2|R|"),
    "G43 after a units change": ("G21 G90 G54 F30\n#1 = 1\nG43 H1\nG1 Z1\nG20\nG43 H2\nG1 Z1\nM30\n",
                                 "after G20/G21"),
    "G49 after a units change": ("G20 G90 G54 F30\n#1 = 1\nG43 H1\nG1 Z1\nG21\nG49\nG1 Z1\nM30\n", "after G20/G21"),
    "G20 written apart": ("G2 0 G90 G54 F30\n#1 = 1\nG1 X1\nM30\n", "written apart"),
}


@pytest.mark.parametrize("name", sorted(DECLINED))
def test_inch_programs_outside_the_subset_are_declined(name):
    text, why = DECLINED[name]
    with pytest.raises(Declined, match=why):
        double_pass(text, MILL, max_iterations=5)
    if "units change" in name:  # the full path's unknown (LinuxCNC 2.9 keeps the length in the old units)
        run = interpret_text(text, MILL)
        list(run.segments())
        assert run.status != "complete" and "old units" in str(run.unsupported[0])


def test_an_arc_in_g21_after_inches_is_enclosed():
    path = check_against_full("G20 G90 G17 G54 F30\n#1 = 1\nG1 X[#1 / 3] Y0.1\nG21 G2 X20 Y2.54 R30\nM30\n", MACHINE)
    assert path is not None and path.arcs == 1


#: Pairs of G91 steps whose millimetres both drift one way (2.5443 in rounds 1.08 ulp down, 2.544427 in 0.6
#: ulp up) while the position stays small: the chain's error grows past a bound made of the rows alone.
PAIRS = ("G20 G90 G54 F30\n#1 = 0\nG91\no1 while [#1 LT 200]\nG1 X2.5443\nX-2.544427\n#1 = [#1 + 1]\n"
         "o1 endwhile\nG90 G1 X0\nM30\n")


@pytest.mark.parametrize("window", [None, 1, 7, 100])
def test_a_g20_chain_whose_steps_drift_one_way_is_enclosed(window):
    machine = load_machine("box_5000")
    exact = [Fraction(0)]
    for k in range(400):
        exact.append(exact[-1] + (Fraction("2.5443") if k % 2 == 0 else -Fraction("2.544427")) * INCH)
    exact.append(Fraction(0))
    whole = check_against_full(PAIRS, machine)
    assert whole is not None and whole.motions == 401
    drift = abs(Fraction(whole.columns[0][400]) - exact[400])
    assert drift > Fraction(1, 10**12)  # the drift the chain's bound is for
    seen = set()

    def check(p):
        for k in range(p.row0 + 1, p.motions + 1):
            lo, hi = p.enclosure(k, k)
            assert lo["X"] <= exact[k] <= hi["X"] and lo["X"] <= exact[k - 1] <= hi["X"], (window, k)
            seen.add(k)
        return True

    if window is None:
        check(whole)
    else:
        check(double_pass(PAIRS, machine, max_iterations=1000, window=window, on_window=check))
    assert seen == set(range(1, 402))


# -- faces at a motion's extreme ------------------------------------------------------------------------------

#: X2.5443 in inches: the exact end is 64.62522 mm, its double 1.08 ulp (1.53e-14 mm) below it, farther than the
#: G21 rows' bound ``2 u (|x| + |O|)`` (1.43e-14 mm).  A face ``5e-16`` mm either side of the end (a machine file's
#: decimals stop at 30 places; an ulp here is 1.42e-14) puts it between the exact end and that bound's box.
END = Fraction("2.5443") * INCH
_NEAR = Fraction(5, 10**16)
FACE_PROGRAM = "G20 G90 G17 G54 F30\n#1 = 1\nG1 X[#1 * 0 + 2.5443] Y1\nG1 X0 Y0\nM30\n"


def _face_machine(face: Fraction):
    decimal = f"{face.numerator * 10**30 // face.denominator}"
    assert Fraction(int(decimal), 10**30) == face
    decimal = f"{decimal[:-30]}.{decimal[-30:]}"
    return parse_machine(machine_text("box_5000").replace('max = { X = "5000"', f'max = {{ X = "{decimal}"'))


@pytest.mark.parametrize(("face", "verdict"), [
    (END, Verdict.SAFE),  # on the face: the pass's box crosses it, the full path proves it
    (END + _NEAR, Verdict.SAFE),
    (END - _NEAR, Verdict.UNSAFE),  # the exact end is past the face; the double (1.53e-14 below it) is not
    (END + Fraction(1, 10**9), Verdict.SAFE),  # clear of the bound: the pass proves it
])
def test_a_face_at_an_inch_motions_end_is_decided_alike(monkeypatch, face, verdict):
    assert Fraction(2.5443 * 25.4) < END - _NEAR  # the controller's double is short of the face below the end
    with_pass, without = both_ways(FACE_PROGRAM, _face_machine(face), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is verdict
    assert ("double_pass_boxes" in dict(with_pass.stats)) is (face - END > _NEAR)


# -- I/J arcs in G20 ------------------------------------------------------------------------------------------

@st.composite
def inch_arcs(draw) -> list[str]:
    """A move to a start, then an I/J arc from it in inches (radii 0.01 to 120 inch, sweeps away from 0 and a
    whole turn, the end written to 6 places: within 1e-6 inch of the circle), or an R arc of its chord (either
    sign, not a half circle: the pass declines those, ``DECLINED``), sometimes a helix."""
    import math

    sx, sy = (draw(st.integers(-4000, 4000)) / 40 for _ in range(2))
    radius = draw(st.sampled_from([0.01, 0.5, 1.0, 7.25, 120.0]))
    a0 = draw(st.sampled_from([0.0, math.pi / 2, 1.0, -2.5, math.pi / 4]))
    sweep = draw(st.sampled_from([0.3, math.pi / 2, math.pi, 2.0, -math.pi / 2, 3 * math.pi / 2, -4.0]))
    r_word = draw(st.booleans())
    if r_word and sweep == math.pi:
        sweep = 2.5  # (a half circle by R is the full path's)
    i, j = round(-radius * math.cos(a0), 6), round(-radius * math.sin(a0), 6)
    ex, ey = sx + i + radius * math.cos(a0 + sweep), sy + j + radius * math.sin(a0 + sweep)
    code = "G2" if sweep < 0 else "G3"
    helix = draw(st.sampled_from(["", "", " Z[#1 * 2]", " Z-0.1"]))
    if r_word:  # R: the short way (R > 0) when the sweep is below a half turn
        long_way = abs(sweep) > math.pi
        r = draw(st.sampled_from([f"{radius:.6f}", f"{radius * (1 + 1e-7):.9f}"]))
        return [f"G1 X{sx:.3f} Y{sy:.3f}", f"{code} X{ex:.6f} Y{ey:.6f} R{'-' if long_way else ''}{r}{helix}"]
    return [f"G1 X{sx:.3f} Y{sy:.3f}", f"{code} X{ex:.6f} Y{ey:.6f} I{i:.6f} J{j:.6f}{helix}"]


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(st.lists(inch_arcs(), min_size=1, max_size=4),
       st.sampled_from(["G20 G90 G17 G54 F30", "G20 G90 G17 G55 G43 H1 F30", "G21 G90 G17 G54 F30\nG1 X1\nG20"]),
       st.sampled_from([17, 17, 18, 19]), machines(tools=True))
def test_inch_arcs_are_enclosed_by_the_full_interpreter(arc_lines, head, plane, machine):
    """I/J and R arcs in inches (:func:`inch_arcs`), in G17, G18 or G19: every arc of the full path (its ends, its
    points at both radii and its extremes) lies in the pass's box of its motion."""
    body = [line for lines in arc_lines for line in lines]
    if plane != 17:
        head = head.replace("G17", f"G{plane}")
        body = [in_plane(line, plane) for line in body]
    path = check_against_full("\n".join([head, "#1 = 0.5", *body, "M30"]) + "\n", machine)
    if not set(machine.modal) & {"G20", "G91"}:  # every arc is in the subset: taken (a decline proves nothing)
        assert path is not None and path.arcs == len(arc_lines)


#: A quarter of radius 1 (G20: 25.4 mm) whose end is ``off`` beyond the circle, under LinuxCNC's arc rule: in
#: inches it allows 0.00283 inch (0.0718 mm), in mm 0.0283 mm (with 0.1 % of the radius up to 100 times that).
OFF_CIRCLE = "{units} G90 G17 G54 F30\n#1 = 1\nG1 X{r} Y0\nG3 X0 Y{end} I-{r} J0\nM30\n"


@pytest.mark.parametrize(("units", "r", "end", "taken"), [
    ("G20", "1", "1.002", True),  # 0.0508 mm off: LinuxCNC's inch rule runs it
    ("G21", "25.4", "25.4508", False),  # the same arc in mm: LinuxCNC refuses it (GC301 on the full path)
    ("G20", "1", "1.00282", True),  # 0.00282 inch: just inside the inch rule's 0.0028284
    ("G20", "1", "1.00284", False),  # just past it
])
def test_an_inch_arc_off_its_circle_follows_linuxcncs_inch_rule(units, r, end, taken):
    from tests.gcode.test_double_pass import check_arc_in_box
    from tests.gcode.test_rs274_double_arcs import _machine

    text = OFF_CIRCLE.format(units=units, r=r, end=end)
    machine = _machine()  # LinuxCNC's arc rule
    run = interpret_text(text, machine)
    if not taken:
        with pytest.raises(Declined, match="arc tolerance"):
            double_pass(text, machine, max_iterations=10, arc_tolerance="linuxcnc")
        with pytest.raises(GcodeError, match="GC301"):
            list(run.segments())
        return
    path = double_pass(text, machine, max_iterations=10, arc_tolerance="linuxcnc")
    segments = list(run.segments())
    assert run.status == "complete" and path.arcs == 1 and len(segments) == path.motions == 2
    lo, hi = path.enclosure(2, 2)
    check_arc_in_box(segments[1], lo, hi)


#: A half circle in inches about (1, 0.3) inch (G55: X +200, Y +10 mm on mill_g54_g55_h1_h2's offsets, here on
#: box_5000's with the same G55) of radius 1.1 inch: its top, exactly 10 + 25.4 * 1.4 = 45.56 mm, is inside the
#: sweep, not at an end; the rows and words are rounded (1.1 * 25.4, 0.3 * 25.4 are not doubles).
ARC_TOP = Fraction(10) + INCH * Fraction(14, 10)
ARC_PROGRAM = "G20 G90 G17 G55 F30\n#1 = 1\nG1 X[#1 * 2.1] Y0.3\nG3 X-0.1 Y0.3 I-1.1 J0\nG1 X0 Y0\nM30\n"


def _arc_face_machine(face: Fraction):
    decimal = f"{face.numerator * 10**30 // face.denominator}"
    assert Fraction(int(decimal), 10**30) == face
    decimal = f"{decimal[:-30]}.{decimal[-30:]}"
    text = machine_text("box_5000", extra='[offsets]\nG55 = { X = "200", Y = "10", Z = "0" }\n')
    return parse_machine(text.replace('Y = "5000", Z = "5000" }', f'Y = "{decimal}", Z = "5000" }}'))


@pytest.mark.parametrize(("face", "verdict", "by_pass"), [
    (ARC_TOP, Verdict.SAFE, False),  # the arc touches the face: the full path proves it
    (ARC_TOP - Fraction(1, 10**13), Verdict.UNSAFE, False),  # the arc crosses it
    (ARC_TOP + Fraction(1, 10**13), Verdict.SAFE, False),  # within the arc box's error: the full path's
    (ARC_TOP + Fraction(1, 10**9), Verdict.SAFE, True),  # clear of it: the pass proves it
])
def test_a_face_at_an_inch_arcs_top_is_decided_alike(monkeypatch, face, verdict, by_pass):
    with_pass, without = both_ways(ARC_PROGRAM, _arc_face_machine(face), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is verdict
    assert ("double_pass_boxes" in dict(with_pass.stats)) is by_pass
