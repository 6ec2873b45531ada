"""``safe`` from the double pass (nczones/prover/doubles.py) against the full path's verdict.

Every verdict, violation, reason and note of ``verify`` is the same with the double pass tried first and
without it, on generated parametric programs against machines with forbidden boxes, stepped tables and
polygons, with and without a margin; the boxes split where the whole program's box does not fit; a motion
that leaves the allowed set sends the program to the full path.
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.pipeline.verification as prover_doubles
from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import parametric_programs
from tests.machines import machine_text

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "60"))

HEAD = machine_text("mill_g55_zones_head")

ZONES = {
    "box": '[[zones]]\nname = "travel"\nkind = "box"\nmin = {{ X = "-{a}", Y = "-{a}", Z = "-{a}" }}\n'
           'max = {{ X = "{a}", Y = "{a}", Z = "{a}" }}\n',
    "forbid": '[[zones]]\nname = "travel"\nkind = "box"\nmin = {{ X = "-1000", Y = "-1000", Z = "-1000" }}\n'
              'max = {{ X = "1000", Y = "1000", Z = "1000" }}\n'
              '[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\nmin = {{ X = "{a}", Y = "-5" }}\n'
              'max = {{ X = "{b}", Y = "5" }}\n',
    "table": '[[zones]]\nname = "table"\nkind = "stepped"\nreference_axis = "X"\nlimited_axis = "Y"\n'
             'from = "-1000"\nregions = [ {{ upto = "{a}", min = "-1000", max = "1000" }}, '
             '{{ upto = "1000", min = "-1000", max = "{b}" }} ]\n',
    "polygon": '[[zones]]\nname = "outline"\nkind = "polygon"\nplane = ["X", "Y"]\n'
               'vertices = [["-600", "-600"], ["{a}", "-600"], ["{a}", "{b}"], ["-600", "600"]]\n',
}


def machine_of(kind: str, a: int, b: int):
    return parse_machine(HEAD + ZONES[kind].format(a=a, b=b))


def both_ways(text: str, machine, monkeypatch, **options):
    with_pass = verify_text(text, machine, **options)
    with monkeypatch.context() as m:
        m.setattr(prover_doubles, "double_pass_result", lambda *args, **kwargs: None)
        without = verify_text(text, machine, **options)
    return with_pass, without


def same_outcome(a, b) -> None:
    assert a.verdict == b.verdict
    assert [(v.line, v.zone, v.kind) for v in a.violations] == [(v.line, v.zone, v.kind) for v in b.violations]
    assert [r.message for r in a.reasons] == [r.message for r in b.reasons]
    assert a.notes == b.notes
    assert dict(a.stats).get("segments") == dict(b.stats).get("segments") or a.verdict is not Verdict.SAFE


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(parametric_programs(), st.sampled_from(sorted(ZONES)), st.integers(2, 700), st.integers(-50, 700),
       st.sampled_from(["0", "0", "0.5", "3"]))
def test_the_verdict_is_the_full_paths(monkeypatch, text, kind, a, b, margin):
    machine = machine_of(kind, a, max(a + 1, b) if kind == "forbid" else b)
    try:
        with_pass, without = both_ways(text, machine, monkeypatch, margin=margin, max_iterations=1000)
    except Exception as exc:  # noqa: BLE001  # a G-code error: the same error both ways
        with monkeypatch.context() as m:
            m.setattr(prover_doubles, "double_pass_result", lambda *args, **kwargs: None)
            with pytest.raises(type(exc)):
                verify_text(text, machine, margin=margin, max_iterations=1000)
        return
    same_outcome(with_pass, without)


LOOP = ("G21 G90 G54 F500\n#1 = 0\no1 while [#1 LT 200]\n#2 = [#1 * 1.8]\nG1 X[40 * COS[#2]] Y[40 * SIN[#2]]\n"
        "#1 = [#1 + 1]\no1 endwhile\nM30\n")


def test_a_safe_program_is_proved_by_the_pass(monkeypatch):
    machine = machine_of("box", 100, 0)
    with_pass, without = both_ways(LOOP, machine, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    assert dict(with_pass.stats)["double_pass_boxes"] == 1
    assert "double_pass_boxes" not in dict(without.stats)


def test_boxes_split_around_a_corner_of_the_allowed_set(monkeypatch):
    # a step of the table at X = 10 lowers the Y limit to 30: the circle of radius 40 does not fit in it as one box
    # but its arcs do, each in the region it crosses (no motion leaves the table)
    table = machine_of("table", 10, 1000)
    with_pass, without = both_ways(LOOP, table, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    assert dict(with_pass.stats)["double_pass_boxes"] == 1
    cut = machine_of("table", -45, 39)  # every point past X = -45 has Y <= 39: the top of the circle leaves it
    with_pass, without = both_ways(LOOP, cut, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.UNSAFE and "double_pass_boxes" not in dict(with_pass.stats)
    inside = machine_of("table", -45, 41)  # the circle fits, the program's box does not (Y up to 40 < 41 fits)
    with_pass, without = both_ways(LOOP.replace("40 * SIN", "40.5 * SIN"), inside, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE


def test_the_boxes_split_when_the_programs_box_does_not_fit(monkeypatch):
    # an L-shaped allowed set: the motion runs along both legs; no box of the whole program fits
    machine = machine_of("table", 10, 10)  # X <= 10: Y up to 1000; X > 10: Y <= 10
    text = ("G21 G90 G54 F500\n#1 = 0\no1 while [#1 LT 100]\nG1 X0 Y[#1 * 5]\n#1 = [#1 + 1]\no1 endwhile\n"
            "G1 Y0\n#1 = 0\no2 while [#1 LT 100]\nG1 X[#1 * 5] Y0\n#1 = [#1 + 1]\no2 endwhile\nM30\n")
    with_pass, without = both_ways(text, machine, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    assert dict(with_pass.stats)["double_pass_boxes"] > 1


def test_a_margin_is_proved_by_the_boxes(monkeypatch):
    machine = machine_of("box", 41, 0)
    with_pass, without = both_ways(LOOP, machine, monkeypatch, margin="0.5")
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE and "double_pass_boxes" in dict(with_pass.stats)
    with_pass, without = both_ways(LOOP, machine, monkeypatch, margin="1.5")
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.UNSAFE


def test_the_iteration_bound_is_unknown_not_safe(monkeypatch):
    machine = machine_of("box", 100, 0)
    with_pass, without = both_ways(LOOP, machine, monkeypatch, max_iterations=199)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.UNKNOWN and with_pass.reasons[0].code == "GC392"
    with_pass, without = both_ways(LOOP, machine, monkeypatch, max_iterations=200)  # 200 iterations are allowed
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE


def test_the_switches_and_ranges_take_the_full_path(monkeypatch):
    machine = machine_of("box", 100, 0)
    calls = []
    real = prover_doubles.double_pass_result
    monkeypatch.setattr(prover_doubles, "double_pass_result", lambda *a, **k: calls.append(1) or real(*a, **k))
    verify_text(LOOP, machine, params=["G54.X=-1..1"])
    verify_text("/G0 X1\n" + LOOP, machine)
    verify_text(LOOP, machine, engine="z3")
    assert calls == []
    verify_text(LOOP, machine)
    assert calls == [1]


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.floats(allow_nan=False, allow_infinity=False, min_value=-1e12, max_value=1e12),
       st.decimals(-1e6, 1e6, places=4, allow_nan=False, allow_infinity=False))
def test_the_enclosure_holds_every_exact_value_the_double_stands_for(d, offset):
    """A word whose double is ``d`` has an exact value within half an ulp of it (its shadow, or ``d``); the machine
    coordinate is that plus the exact offset, and the pass's row is ``d + float(offset)`` in doubles."""
    import math
    from array import array

    from nczones.gcode.linuxcnc.doubles import DoublePath

    off = Fraction(offset)
    m = d + float(off)
    path = DoublePath(("X",), (array("d", [m, m]),), (abs(off),), 1, 1, 0, 1, (Fraction(m),), (1,))
    lo, hi = path.enclosure(1, 1)
    half = Fraction(math.ulp(d)) / 2
    for word in (Fraction(d) - half, Fraction(d), Fraction(d) + half):
        assert lo["X"] <= word + off <= hi["X"]


def test_the_progress_bar_gets_its_last_step(monkeypatch):
    calls = []

    def bar(line, total, **counts):
        calls.append((line, total, counts))

    bar.counts = True  # type: ignore[attr-defined]
    r = verify_text(LOOP, machine_of("box", 100, 0), progress=bar)
    assert "double_pass_boxes" in dict(r.stats)
    assert calls == [(LOOP.count("\n"), LOOP.count("\n"), {"motions": 200, "blocks": 202})]


def test_ctrl_c_in_the_double_pass_is_an_interrupted_result(monkeypatch):
    import nczones.gcode.linuxcnc.doubles as doubles

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(doubles, "double_pass", interrupted)
    r = verify_text(LOOP, machine_of("box", 100, 0))
    assert r.interrupted and r.verdict is Verdict.UNKNOWN
    assert [x.code for x in r.reasons] == ["VF204"]


def test_the_text_report_names_the_double_pass(tmp_path):
    from nczones.cli import main

    machine = tmp_path / "m.toml"
    machine.write_text(HEAD + ZONES["box"].format(a=100, b=0))
    program = tmp_path / "loop.ngc"
    program.write_text(LOOP)
    out = tmp_path / "report.txt"
    assert main(["verify", "--machine", str(machine), str(program), "--output", str(out)]) == 0
    assert "200 segments checked (by the double pass in 1 box, 0 solver queries)" in out.read_text()


@pytest.mark.parametrize("option", [{"margin": "-0.5"}, {"max_iterations": 0}, {"max_iterations": 1.5},
                                    {"arc_tolerance": "-1"}, {"arc_tolerance": "abc"}])
def test_options_the_full_path_refuses_are_refused_with_the_pass(option):
    # found by the dp-hunt relations: the pass ran before these were checked, a negative margin proved "safe"
    from nczones.errors import NczonesError

    text = "G21 G90 G54 F100\n#1 = 1\nG1 X100.3\nM30\n"
    with pytest.raises(NczonesError):
        verify_text(text, machine_of("box", 100, 0), **option)


def test_the_stats_name_the_double_pass():
    from nczones.report.text import render_stats

    r = verify_text(LOOP, machine_of("box", 100, 0), file="loop.ngc")
    first = render_stats(r, "loop.ngc").splitlines()[0]
    assert first.startswith("loop.ngc: stats: 200 motions in 202 blocks, ")
    assert first.endswith("0 motions proved by the vectorized screen, 200 by the double pass in 1 box "
                          "(its time is the interpretation's)")


def test_an_axis_the_program_never_moves_stays_exactly_at_its_start(monkeypatch):
    # the start is on the travel's top face (Z = 50): a widened Z would leave it, the exact start does not
    machine = parse_machine(HEAD.replace('[offsets]', '[machine.start]\nX = "0"\nY = "0"\nZ = "50"\n[offsets]')
                            + ZONES["box"].format(a=50, b=0))
    with_pass, without = both_ways(LOOP, machine, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE and "double_pass_boxes" in dict(with_pass.stats)
