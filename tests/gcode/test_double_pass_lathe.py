"""The double pass on LinuxCNC lathes (lathe39, issue 36): G7/G8 diameter mode, G18 arcs, G91 in diameter mode.

- the module's invariant (``tests/gcode/test_double_pass.py``, ``check_against_full``) on generated lathe
  programs (G7/G8 switched in the program, G18 arcs by K/I and R written in either mode, G91 X in G7, loops)
  on the lathes of ``tests/machines`` (``report_lathe``: G7 at the start; the same with no diameter axes: G8);
- routing: a lathe program is proved by the pass, G96/G97 taken; G70-G72, G76, G33, G95, G96 without S, a D word
  without G96, a lathe with tool solids, diameter axes other than X, a G7 after an X line on a machine that is
  not a lathe are declined;
- verdicts: faces at a motion's exact extreme in X (a diameter word: the face is at half of it) and Z, by
  straight moves, K/I and R arcs, decided as the full path decides them (and ``unsafe`` 1e-12 mm inside);
- the rows are LinuxCNC's: an X word's double halved in G7 (its increment too in G91), I/K/R never.
"""

from __future__ import annotations

import os
from collections import Counter
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from nczones.prover.result import Verdict
from tests.gcode.rs274_arc_programs import dec
from tests.gcode.test_double_pass import check_against_full, expressions, numbers
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import both_ways, same_outcome

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "60"))

#: report_lathe (X diameters: G7 at the start; G54 X10 Z200; travel X 0..150, Z 0..400) in exact stop
LATHE = parse_machine(machine_text("report_lathe", set={"machine.path_mode": "G61"}))
#: the same lathe without diameter axes: G8 at the start
RADIUS_LATHE = parse_machine(machine_text("report_lathe", set={"machine.diameter_axes": []}))
_TRAVEL_MAX = 'max = { X = "150", Z = "400" }'
_TRAVEL_MIN = 'min = { X = "0", Z = "0" }'


# -- the rows ---------------------------------------------------------------------------------------------------

def test_x_words_are_halved_in_g7_and_not_in_g8():
    text = ("G18 G21 G90 G54 F100\n#1 = 10\nG1 X[#1 * 2] Z5\nG8 X#1\nG7 G91 X2 Z-1\nG8 X2\nG7 G90 G1 X20 Z0\n"
            "G2 X15 Z-2.5 K-2.5 I0\nG3 X40 Z-5 R20\nM30\n")
    path = check_against_full(text, LATHE)
    assert path is not None
    # G54: X 10, Z 200; X diameters but after G8; G91 X2 in G7 moves 1; K/I and R radii
    assert list(path.columns[0]) == [100.0, 20.0, 20.0, 21.0, 23.0, 20.0, 17.5, 30.0]
    assert list(path.columns[1]) == [300.0, 205.0, 205.0, 204.0, 204.0, 200.0, 197.5, 195.0]
    assert path.arcs == 2


def test_a_radius_lathe_switches_to_diameters_at_g7():
    text = "G18 G21 G90 G54 F100\n#1 = 10\nG1 X#1 Z0\nG7 X#1\nG8 G0 X#1\nG7\nX[#1 * 4]\nM30\n"
    path = check_against_full(text, RADIUS_LATHE)
    assert path is not None
    assert list(path.columns[0]) == [100.0, 20.0, 15.0, 20.0, 30.0]


def test_a_mill_takes_g7_before_its_first_x_line():
    """A machine that is not a lathe compiles X words without the factor until a G7 is compiled."""
    mill = parse_machine(machine_text("xz_rapid_1000"))
    text = "G18 G7 G21 G90 G54 F100\n#1 = 10\nG1 X#1 Z0\nG8 X#1\nM30\n"
    path = check_against_full(text, mill)
    assert path is not None and list(path.columns[0])[1:] == [5.0, 10.0]
    with pytest.raises(Declined, match="G7 after a line with an X word"):
        double_pass("G18 G21 G90 G54 F100\n#1 = 10\nG1 X#1 Z0\nG7 X#1\nM30\n", mill, max_iterations=10)


def test_the_spindle_speed_mode_is_taken():
    """G96 (with S, and D its speed limit) and G97 move nothing: the rows are the full path's."""
    text = HEAD + "G96 D2500 S200 M3\nG1 X#1 Z0\nG97 S1000\nG1 X[#1 * 4] Z-5\nG96 S[#1 * 10] D[#1]\nX1\nM30\n"
    path = check_against_full(text, LATHE)
    assert path is not None and list(path.columns[0]) == [100.0, 15.0, 30.0, 10.5]


# -- routing ----------------------------------------------------------------------------------------------------

HEAD = "G18 G21 G90 G54 F100\n#1 = 10\n"
DECLINED = {
    "G70": ("G70 X40 Z5\n", "G70"),
    "G71": ("G71 X40 Z5\n", "G71"),
    "G72.1": ("G72.1 X40 Z5\n", "code 72.1"),
    "G76": ("S100 M3\nG76 P1 Z-10 I-1 J0.5 K1\n", "G76"),
    "G33": ("S100 M3\nG33 Z-10 K1\n", "G33"),
    "G95": ("G95 G1 X20 F0.1\n", "G95"),
    # G96/G97 move nothing (taken: test_the_spindle_speed_mode_is_taken); LinuxCNC refuses G96 without S
    "G96 without S": ("G96 M3\nG1 X20\n", "G96 without an S word"),
    "D without G96": ("G97 D2000 S100 M3\nG1 X20\n", "D word without G96"),
    "M70": ("M70\nG1 X20\n", "M code"),
    "an arc before the plane": ("G17\nG2 X20 Z0 R30\n", "G17 on a machine without X and Y"),
}


@pytest.mark.parametrize("name", sorted(DECLINED))
def test_lathe_codes_the_pass_does_not_follow_are_declined(name):
    body, why = DECLINED[name]
    with pytest.raises(Declined, match=why):
        double_pass(HEAD + body + "M30\n", LATHE, max_iterations=10)


@pytest.mark.parametrize("name, set_, why", [
    ("linuxcnc_lathe_boring_bar", {}, "solids"),
    ("report_lathe", {"machine.diameter_axes": ["Z"]}, "not X alone"),
    ("report_lathe", {"machine.diameter_axes": ["X", "Z"]}, "not X alone"),
])
def test_lathes_the_pass_does_not_model_are_declined(name, set_, why):
    machine = parse_machine(machine_text(name, set=set_))
    with pytest.raises(Declined, match=why):
        double_pass(HEAD + "G1 X#1 Z0\nM30\n", machine, max_iterations=10)


def test_a_lathe_program_is_proved_by_the_pass(monkeypatch):
    text = HEAD + "o1 while [#1 LT 30]\nG1 X[#1 * 2] Z[-#1]\nG2 X[#1 * 2 + 4] Z[-#1 - 2] R2\n#1 = [#1 + 1]\n" \
                  "o1 endwhile\nG0 X100 Z50\nM30\n"
    with_pass, without = both_ways(text, LATHE, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    assert "double_pass_boxes" in dict(with_pass.stats)
    assert "double_pass_boxes" not in dict(without.stats)


def test_a_plain_lathe_program_past_the_mills_crossover_is_proved_by_the_pass():
    """No fast path reads a lathe program: a plain one goes to the pass at any size from 512 lines (on a mill,
    40,000 lines of lines and K/I arcs go to the fast path: ``verification._small_plain``)."""
    from nczones.pipeline import verification
    from nczones.prover import verify_text

    arcs = "G1 X20 Z0\nG3 X30 Z-5 K-5 I0\n"  # a quarter from radius 10 to radius 15
    text = "G18 G21 G90 G54 F100\n" + arcs * 20_000 + "M30\n"
    mill = parse_machine(machine_text("xz_rapid_1000"))
    assert not verification._double_pass_reads(text, mill) and verification._double_pass_reads(text, LATHE)
    assert not verification._double_pass_reads(arcs * 200, LATHE)  # below 512 lines: the full path is as quick
    result = verify_text(text, LATHE)
    assert result.verdict is Verdict.SAFE and "double_pass_boxes" in dict(result.stats)


# -- verdicts at a face -------------------------------------------------------------------------------------------

#: (program after HEAD, axis, side, the exact extreme in machine coordinates): a straight move to X diameter
#: 40 (radius 20 + G54's 10), K/I and R arcs over radius 15 (X 25) and a K/I arc through Z -10 (Z 190).
FACES = {
    "a diameter": ("G0 X[#1 * 4] Z5\nG1 X10 Z-10\n", "X", 1, Fraction(30)),
    "a diameter in G91": ("G0 X20 Z5\nG91 G1 X[#1 * 2] Z-1\nG90 X10 Z0\n", "X", 1, Fraction(30)),
    "an arc by K and I": ("G0 X20 Z0\nG3 X20 Z-10 K-5 I0\n", "X", 1, Fraction(25)),
    "an arc by R": ("G0 X20 Z0\nG3 X28 Z-8 R5\n", "X", 1, Fraction(25)),
    "an arc through Z": ("G0 X30 Z-5\nG3 X10 Z-5 K0 I-5\n", "Z", -1, Fraction(190)),
    "a radius in G8": ("G8 G0 X#1 Z5\nG1 X20 Z0\n", "X", 1, Fraction(30)),
}


def _faced(axis: str, side: int, value: Fraction):
    """``LATHE`` started at X 20 with its travel's face on ``axis`` (``side`` 1: max, -1: min) at ``value``."""
    text = machine_text("report_lathe", set={"machine.path_mode": "G61"},
                        extra='[machine.start]\nX = "20"\nZ = "300"\n')
    line = _TRAVEL_MAX if side > 0 else _TRAVEL_MIN
    old = f'{axis} = "{150 if axis == "X" else 400}"' if side > 0 else f'{axis} = "0"'
    places = dec(value)
    assert old in line
    return parse_machine(text.replace(line, line.replace(old, f'{axis} = "{places}"')))


@pytest.mark.parametrize("name", sorted(FACES))
def test_a_face_at_the_extreme_is_decided_as_the_full_path_does(name, monkeypatch):
    body, axis, side, extreme = FACES[name]
    text = HEAD + body + "M30\n"
    assert check_against_full(text, LATHE) is not None  # the pass takes it
    for eps in (Fraction(-1, 10**12), Fraction(0), Fraction(1, 10**12), Fraction(1, 10**9)):
        with_pass, without = both_ways(text, _faced(axis, side, extreme + side * eps), monkeypatch)
        same_outcome(with_pass, without)
        assert with_pass.verdict is (Verdict.UNSAFE if eps < 0 else Verdict.SAFE), (eps, with_pass.reasons)
        if eps > Fraction(1, 10**10):  # past the pass's rounding: its proof
            assert "double_pass_boxes" in dict(with_pass.stats)


@pytest.mark.parametrize("jaw, verdict", [(("30", "40"), Verdict.UNSAFE), (("55", "65"), Verdict.SAFE)])
def test_a_diameter_in_a_forbidden_box_is_decided_as_the_full_path_does(jaw, verdict, monkeypatch):
    """``X50`` in G7 is radius 25 (machine 35, G54's X 10): in jaws at machine X 30..40, clear of jaws at 55..65,
    where a pass that took the diameter for a radius (machine 60) would see it (the mutation check)."""
    jaws = ('[[zones]]\nname = "jaws"\nkind = "box"\nforbid = true\n'
            f'min = {{ X = "{jaw[0]}", Z = "150" }}\nmax = {{ X = "{jaw[1]}", Z = "210" }}\n')
    machine = parse_machine(machine_text("report_lathe", set={"machine.path_mode": "G61"},
                                         extra='[machine.start]\nX = "20"\nZ = "300"\n' + jaws))
    text = HEAD + "G0 Z50\nG0 X[#1 * 5]\nG1 Z0\nG0 Z50\nM30\n"  # X moves at Z 250, clear of the jaws
    with_pass, without = both_ways(text, machine, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is verdict


# -- the invariant on generated lathe programs ---------------------------------------------------------------------

def _word(draw) -> str:
    return draw(st.one_of(numbers.filter(lambda s: s != "1e"), expressions(2)))


@st.composite
def lathe_moves(draw) -> str:
    code = draw(st.sampled_from(["G0 ", "G1 ", "", "", "G7 ", "G8 ", "G7 G1 ", "G8 G0 ", "G91 G1 ", "G90 G1 "]))
    axes = draw(st.lists(st.sampled_from("XZ"), min_size=1, max_size=2, unique=True))
    return code + " ".join(f"{a}{_word(draw)}" for a in axes)


@st.composite
def lathe_arcs(draw) -> list[str]:
    """A move to a start in one mode, then a G2/G3 in G18 by K/I or R in the mode of the move or the other (a
    mode the arc was not drawn for: off its circle, declined or not taken as drawn)."""
    import math

    sz, sx = draw(st.integers(-400, 400)) / 8, draw(st.integers(0, 400)) / 8  # Z, X radius
    r = draw(st.sampled_from([0.5, 2.0, 7.25, 30.0]))
    a0 = draw(st.sampled_from([0.0, math.pi / 2, 1.0, -2.5, math.pi]))
    sweep = draw(st.sampled_from([math.pi / 2, 2.0, -math.pi / 2, 1.0, -0.5]))
    cz, cx = sz - r * math.cos(a0), sx - r * math.sin(a0)
    ez, ex = cz + r * math.cos(a0 + sweep), cx + r * math.sin(a0 + sweep)
    code = "G3" if sweep > 0 else "G2"
    mode = draw(st.sampled_from(["G7", "G8"]))
    arc_mode = draw(st.sampled_from([mode, mode, mode, "G7" if mode == "G8" else "G8", ""]))
    scale = 2 if mode == "G7" else 1
    start = f"{mode} G90 G1 X{sx * scale:.4f} Z{sz:.4f}"
    end = f"X{ex * (2 if (arc_mode or mode) == 'G7' else 1):.4f} Z{ez:.4f}"
    if draw(st.booleans()):
        words = f"{end} K{cz - sz:.4f} I{cx - sx:.4f}"
    else:
        words = f"{end} R{r if abs(sweep) < math.pi else -r}"
    return [start, f"{arc_mode} {code} {words}".strip(), *draw(st.sampled_from([[], ["G1 X[#1] Z0"], ["G8"]]))]


#: Lines a lathe program may hold that the pass declines (each must make it decline, or agree).
OUTSIDE = ["G96", "G96 S100 D-1", "G97 D5", "D1", "G95", "G33 Z-1 K0.1", "G70 Q1", "M70", "G7 X1 M72", "G17", "G2 X1 Z1 J1", "G20",
           "G7.1", "G18 G2 X1 Z1"]


@st.composite
def lathe_statements(draw, depth: int, labels: list[int]) -> list[str]:
    kind = draw(st.integers(0, 9))
    if kind <= 1:
        target = draw(st.sampled_from(["#1", "#2", "#<a>"]))
        return [f"{target} = {draw(expressions(2))}"]
    if kind <= 4:
        return [draw(lathe_moves())]
    if kind <= 6:
        return draw(lathe_arcs())
    if kind == 7 and depth > 0:
        label = 100 + len(labels)
        labels.append(label)
        n = draw(st.integers(0, 3))
        body = [s for _ in range(draw(st.integers(1, 3))) for s in draw(lathe_statements(depth - 1, labels))]
        return [f"#<i{label}> = 0", f"o{label} while [#<i{label}> LT {n}]", *body,
                f"#<i{label}> = [#<i{label}> + 1]", f"o{label} endwhile"]
    if kind == 8:
        return [draw(st.sampled_from(["G7", "G8", "G91", "G90", "G55", "G54", "G18", "G4 P0.1", "M3 S500", "T1 M6",
                                      "G96 D2500 S200 M3", "G97 S[#<a> * 100]"]))]
    return [draw(st.sampled_from(OUTSIDE))]


@st.composite
def lathe_programs(draw) -> str:
    head = draw(st.sampled_from(["G18 G21 G90 G54 F300", "G18 G7 G21 G90 G54 F300", "G18 G8 G21 G90 G54 F300",
                                 "G7 G18 G21 G90 G55 F100 G1", "G18 G7 G21 G91 G54 F300 G1 X[#1] Z-1"]))
    labels: list[int] = []
    body = [s for _ in range(draw(st.integers(1, 8))) for s in draw(lathe_statements(2, labels))]
    return "\n".join(["#1 = 1.5", head, "#2 = -0.25", "#<a> = 3", "#<b> = 0.5", *body, "G90 G0 X100 Z100", "M30"]) + "\n"


@st.composite
def lathes(draw):
    def pair():
        return {"X": draw(st.sampled_from(["0", "10", "-2.5", "0.1"])), "Z": draw(st.sampled_from(["0", "200", "-0.3"]))}

    set_ = {"offsets.G54": pair(), "offsets.G55": pair(),
            "machine.path_mode": draw(st.sampled_from(["G64", "G61"]))}
    if draw(st.booleans()):
        set_["machine.diameter_axes"] = []
    return parse_machine(machine_text("report_lathe", set=set_))


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(lathe_programs(), lathes())
def test_the_pass_is_enclosed_by_the_full_interpreter_on_lathes(text, machine):
    check_against_full(text, machine)


def test_the_generated_lathe_programs_are_often_taken():
    """The generator is worth its time: of 60 of its programs, the pass takes a fair share, with arcs, with G7 and
    G8 both, and with G91 (so the invariant above is not checked on declines alone)."""
    seen: Counter = Counter()

    @settings(max_examples=60, deadline=None, derandomize=True, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(lathe_programs(), lathes())
    def count(text, machine):
        try:
            path = double_pass(text, machine, max_iterations=1000)
        except Declined:
            return
        seen["taken"] += 1
        seen["arcs"] += path.arcs > 0
        seen["G7 and G8"] += "G7" in text and "G8" in text
        seen["G91"] += "G91" in text

    count()
    assert seen["taken"] >= 15 and min(seen[k] for k in ("arcs", "G7 and G8", "G91")) >= 3, seen


@st.composite
def zoned_lathes(draw):
    """report_lathe (G7 at the start, or G8) with its travel's X and Z faces drawn near the generated programs'
    moves, and a forbidden box (a chuck's jaws) or not."""
    hi_x, lo_z = draw(st.integers(5, 600)), draw(st.integers(-400, 215))
    extra = ""
    if draw(st.booleans()):
        a = draw(st.integers(0, 60))
        extra = ('[[zones]]\nname = "jaws"\nkind = "box"\nforbid = true\n'
                 f'min = {{ X = "{a}", Z = "150" }}\nmax = {{ X = "{a + 5}", Z = "{draw(st.integers(160, 205))}" }}\n')
    set_: dict = {"machine.path_mode": draw(st.sampled_from(["G64", "G61"]))}
    if draw(st.booleans()):
        set_["machine.diameter_axes"] = []
    text = machine_text("report_lathe", set=set_, extra='[machine.start]\nX = "1"\nZ = "300"\n' + extra)
    text = text.replace(_TRAVEL_MAX, f'max = {{ X = "{hi_x}", Z = "400" }}')
    return parse_machine(text.replace(_TRAVEL_MIN, f'min = {{ X = "-{hi_x}", Z = "{lo_z}" }}'))


@settings(max_examples=int(os.environ.get("NCZONES_DOUBLE_PASS_LATHE_VERDICTS", "16")), deadline=None,
          derandomize=True, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                                   HealthCheck.function_scoped_fixture])
@given(lathe_programs(), zoned_lathes())
def test_the_verdict_on_a_lathe_is_the_full_paths(monkeypatch, text, machine):
    """Every verdict, violation, reason and note with the pass tried first is the full path's, on generated lathe
    programs against travel faces and a forbidden box near their moves (a long run:
    ``NCZONES_DOUBLE_PASS_LATHE_VERDICTS``)."""
    try:
        with_pass, without = both_ways(text, machine, monkeypatch, max_iterations=1000)
    except Exception as exc:  # noqa: BLE001  # a G-code error: the same error both ways
        from nczones.prover import verify_text
        from tests.prover.test_double_pass_proof import prover_doubles

        with monkeypatch.context() as m:
            m.setattr(prover_doubles, "double_pass_result", lambda *args, **kwargs: None)
            with pytest.raises(type(exc)):
                verify_text(text, machine, max_iterations=1000)
        return
    same_outcome(with_pass, without)
