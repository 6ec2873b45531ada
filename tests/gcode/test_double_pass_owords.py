"""LinuxCNC programs with o-words and no parameters go to the double pass first (issue 36, "o-word subs, no #").

Before, the double pass was tried only for a program with ``#``; one with o-word subs, loops or branches and no
parameters went the full language layer, about 4x slower (specs/performance.md).  The pass proves or declines
whatever it is given, so routing is about speed, and these tests hold the routed result to the full path's:
the same verdict, violations (block, line, zone) and motion count, with the pass taken where it can be (it
declines ``repeat``, among others: the full path then decides, as the generated programs with one show).
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.pipeline import verification
from nczones.prover import verify_text

from .test_double_pass import check_against_full, machine_text

# a post at X 40..50, Y 40..50 (every Z): a move to X45 Y45 goes through it
POST = parse_machine(machine_text(extra='[[zones]]\nname = "post"\nkind = "box"\nforbid = true\n'
                                        'min = { X = "40", Y = "40", Z = "-1000" }\n'
                                        'max = { X = "50", Y = "50", Z = "1000" }\n'))


def _summary(r):
    return (r.verdict.label, [(v.block, v.span.line if v.span else None, v.zone) for v in r.violations],
            dict(r.stats)["segments"], sorted(x.code or "" for x in r.reasons))


def _both(text: str, monkeypatch):  # monkeypatch.context(): undone after each call
    routed = verify_text(text, POST)
    with monkeypatch.context() as m:
        m.setattr(verification, "_double_pass_reads", lambda t, machine=None: "#" in t)  # the routing before this change
        full = verify_text(text, POST)
    return routed, full


@st.composite
def oword_programs(draw) -> str:
    def move() -> str:
        return f"G1 X{draw(st.integers(-5, 60))} Y{draw(st.integers(-5, 60))}"

    sub = ["o100 sub", *[move() for _ in range(draw(st.integers(1, 4)))], "o100 endsub"]
    body = ["G21 G90 G17 G54 F500"]
    for k in range(draw(st.integers(1, 4))):
        kind = draw(st.integers(0, 3))
        if kind == 0:
            body.append("o100 call")
        elif kind == 1:
            body += [f"o{200 + k} repeat [{draw(st.integers(0, 3))}]", "o100 call", move(), f"o{200 + k} endrepeat"]
        elif kind == 2:
            body += [f"o{300 + k} if [{draw(st.integers(0, 2))} GT 1]", move(), f"o{300 + k} else", move(),
                     f"o{300 + k} endif"]
        else:
            body.append(move())
    pad = [f"G1 X{-10 - i % 7} Y{-20 - i % 5}" for i in range(600)] if draw(st.booleans()) else []
    return "\n".join([*sub, body[0], *pad, *body[1:], "M2"]) + "\n"


@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(oword_programs())
def test_routed_oword_programs_decide_as_the_full_path(monkeypatch, text):
    routed, full = _both(text, monkeypatch)
    assert _summary(routed) == _summary(full)
    check_against_full(text, POST)  # the pass's motion encloses the full interpreter's, or it declined


@pytest.mark.parametrize("pad", [0, 600])
def test_an_oword_program_without_parameters_takes_the_pass(monkeypatch, pad):
    lines = ["o100 sub", "G1 X45 Y45", "G1 X0 Y0", "o100 endsub", "G21 G90 G54 F500",
             *[f"G1 X{-10 - i % 7} Y{-20 - i % 5}" for i in range(pad)], "o100 call", "o100 call", "M2"]
    text = "\n".join(lines) + "\n"
    routed, full = _both(text, monkeypatch)
    assert routed.verdict.label == "unsafe" and _summary(routed) == _summary(full)
    safe = text.replace("X45 Y45", "X30 Y45")
    routed = verify_text(safe, POST)
    assert routed.verdict.label == "safe" and dict(routed.stats).get("double_pass_boxes", 0) >= 1, routed.stats
    with monkeypatch.context() as m:
        m.setattr(verification, "_double_pass_reads", lambda t, machine=None: "#" in t)
        assert "double_pass_boxes" not in dict(verify_text(safe, POST).stats)  # before: the full path


def test_what_is_routed():
    reads = verification._double_pass_reads
    assert reads("o100 sub\nG1 X1\no100 endsub\no100 call\nM2\n")
    assert reads("N10 O<probe> call\n") and reads("  /o1 if [1]\n")
    assert reads("G1 X1 (#1 only in a comment: the pass proves or declines)\n")
    assert not reads("(do not call the operator: the contour)\nG1 X1 Y1\nM2\n")  # keywords, no o-word
    assert not reads("G1 X1 Y1\nM2\n")
