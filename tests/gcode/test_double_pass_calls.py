"""The double pass follows LinuxCNC ``o<n> sub`` / ``endsub`` / ``call`` (issue 36): agreement with the full path.

A call in LinuxCNC (``Interp::convert_control_functions``, O_call) saves the caller's #1..#30, sets #1..#n
from its arguments and leaves the rest unset (they read 0); its ``endsub`` restores the caller's #1..#30
(the full path: ``Parameters.push_scope`` / ``pop_scope``).  Generated programs define subroutines, call them
with 0 to 4 arguments, from loops and from other subroutines, and write #1..#3 and #31 in both: whenever the
pass returns, the full interpreter's run must agree with it (``check_against_full``: the same motions, each
inside its row's enclosure, no error or note).  Programs outside what the pass follows (a call of a sub not
defined yet, recursion, a caller's named parameter read in a sub, ``#<_value>``, a value returned, ``return``) must be declined.
"""

from __future__ import annotations

import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.prover import Verdict, verify_text

from .test_double_pass import (
    MACHINE,
    check_against_full,
    conditions,
    expressions,
    machine_text,
    machines,
    motions,
)

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "60"))
TARGETS = ["#1", "#2", "#3", "#30", "#31", "#<a>"]


@st.composite
def sub_body(draw, label: int, loop_label: int) -> list[str]:
    out: list[str] = []
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.integers(0, 5))
        if kind <= 1:
            out.append(f"{draw(st.sampled_from(TARGETS))} = {draw(expressions(1))}")
        elif kind <= 3:
            out.append(draw(motions()))
        elif kind == 4:
            out += [f"o{loop_label} if {draw(conditions())}", draw(motions()), f"o{loop_label} endif"]
            loop_label += 1
        else:
            out += ["#31 = 0", f"o{loop_label} while [#31 LT {draw(st.integers(0, 3))}]", draw(motions()),
                    "#31 = [#31 + 1]", f"o{loop_label} endwhile"]
            loop_label += 1
    if draw(st.integers(0, 3)):  # mostly without named parameters (a sub with one is declined)
        out = [line.replace("#<a>", "#2").replace("#<b>", "#3") for line in out]
    return [f"o{label} sub", *out, f"o{label} endsub"]


@st.composite
def call_programs(draw) -> str:
    head = draw(st.sampled_from(["G21 G90 G54 F300 G1", "G21 G90 G17 G54 G94 F800 G0", "G90 G54 F300"]))
    subs = [draw(sub_body(500 + k, 600 + 10 * k)) for k in range(draw(st.integers(1, 2)))]
    if draw(st.booleans()):  # the second sub calls the first
        subs[-1].insert(-1, f"o500 call [{draw(expressions(1))}]")
    calls: list[str] = []
    for _ in range(draw(st.integers(1, 4))):
        label = draw(st.sampled_from([500 + k for k in range(len(subs))]))
        args = " ".join(f"[{draw(expressions(1))}]" for _ in range(draw(st.integers(0, 4))))
        call = f"o{label} call {args}".rstrip()
        kind = draw(st.integers(0, 3))
        if kind == 0:
            calls += ["#11 = 0", f"o{700 + len(calls)} while [#11 LT {draw(st.integers(0, 3))}]", call,
                      "#11 = [#11 + 1]", f"o{700 + len(calls)} endwhile"]
        else:
            calls += [f"{draw(st.sampled_from(TARGETS))} = {draw(expressions(1))}", call, draw(motions())]
    order = draw(st.integers(0, 2))
    defs = [line for sub in subs for line in sub]
    lines = [*defs, head, *calls] if order else [head, *defs, *calls]
    tail = draw(st.sampled_from(["M30", "M2", ""]))
    return "\n".join([*lines, tail]) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(call_programs(), machines(), st.sampled_from([1000, 3]))
def test_calls_in_the_pass_agree_with_the_full_interpreter(text, machine, max_iterations):
    check_against_full(text, machine, max_iterations)


def test_a_call_sets_and_restores_the_callers_parameters():
    # LinuxCNC O_call: #1..#n from the arguments, #n+1..#30 unset (0); endsub restores the caller's #1..#30:
    # X goes 7 (argument), 0 (#2 unset inside), then after the call 1 and 2 (the caller's #1, #2 again)
    text = ("o100 sub\nG1 X#1 Y#2\n#1 = 99\no100 endsub\nG21 G90 G54 F100\n#1 = 1\n#2 = 2\n"
            "o100 call [7]\nG1 X#1 Y#2\nM30\n")
    path = check_against_full(text, MACHINE)
    assert path is not None, "declined"
    assert list(path.columns[0]) == [0.0, 7.0, 1.0] and list(path.columns[1]) == [0.0, 0.0, 2.0]


def test_a_call_has_its_own_named_parameters():
    # LinuxCNC: a call has its own local named parameters (enter_context), dropped at the endsub: the sub's #<a>
    # is 2 (twice its argument), the caller's #<a> is 5 again after the call
    text = ("o100 sub\n#<a> = [#1 * 2]\nG1 X#<a>\no100 endsub\nG21 G90 G54 F100\n#<a> = 5\n"
            "o100 call [1]\nG1 X#<a>\nM30\n")
    path = check_against_full(text, MACHINE)
    assert path is not None, "declined"
    assert list(path.columns[0]) == [0.0, 2.0, 5.0]


SUB = "o100 sub\nG1 X#1\no100 endsub\n"
DECLINED_CALLS = {
    "a call before the definition": ("G21 G90 G54 F100\n#1 = 1\no100 call [1]\n" + SUB + "M30\n", "not defined"),
    "recursion": ("o100 sub\no101 if [#1 GT 0]\no100 call [#1 - 1]\no101 endif\no100 endsub\n"
                  "G21 G90 G54 F100\no100 call [3]\nM30\n", "recursive"),
    # LinuxCNC: a sub has its own local names; the caller's #<a> is not visible (the full path's error)
    "a caller's name read in a sub": ("o100 sub\nG1 X#<a>\no100 endsub\nG21 G90 G54 F100\n#<a> = 1\no100 call\n",
                                      "KeyError"),
    "#<_value>": (SUB + "G21 G90 G54 F100\no100 call [1]\n#1 = #<_value>\nG1 X#1\n", "_value"),
    "a value returned": ("o100 sub\nG1 X#1\no100 endsub [#1]\nG21 G90 G54 F100\no100 call [1]\n", "returning"),
    "return": ("o100 sub\nG1 X#1\no100 return\no100 endsub\nG21 G90 G54 F100\no100 call [1]\n", "return"),
    "a sub inside a loop": ("G21 G90 G54 F100\n#1 = 0\no1 while [#1 LT 2]\n" + SUB + "#1 = [#1 + 1]\n"
                            "o1 endwhile\n", "sub inside"),
    "a sub defined twice": (SUB + SUB + "G21 G90 G54 F100\no100 call [1]\n", "reused"),
}


@pytest.mark.parametrize("name", sorted(DECLINED_CALLS))
def test_calls_outside_the_pass_are_declined(name):
    text, why = DECLINED_CALLS[name]
    with pytest.raises(Declined, match=why):
        double_pass(text, MACHINE, max_iterations=5)


@pytest.mark.parametrize(("reps", "x_max"), [(3, "30"), (400, "100000"), (400, "30")])
def test_verify_of_a_call_loop_matches_the_unrolled_program(reps, x_max):
    """End to end: a loop of calls (2 motions per call: 6, and 800 = the vectorized tier) has the verdict and
    violations of the same motions written out (a program without '#': no double pass).  Inside the zone the
    double pass proves it; with the zone cut at X = 30 the calls past #11 = 300 leave it (the double pass
    cannot prove it, the full path finds the violations)."""
    from nczones.machine import parse_machine

    machine = parse_machine(machine_text().replace('max = { X = "100000"', f'max = {{ X = "{x_max}"'))
    looped = ("o9010 sub\nG0 X#1 Y#2\nG1 Z-#3\no9010 endsub\nG21 G90 G17 G54 F300\n#11 = 0\n"
              f"o100 while [#11 LT {reps}]\no9010 call [#11 * 0.1] [#11 * 0.05] [2]\n#11 = [#11 + 1]\n"
              "o100 endwhile\nM30\n")
    unrolled = "G21 G90 G17 G54 F300\n" + "".join(
        f"G0 X{k * 0.1!r} Y{k * 0.05!r}\nG1 Z-2\n" for k in range(reps)) + "M30\n"
    a = verify_text(looped, machine)
    b = verify_text(unrolled, machine)
    assert a.verdict == b.verdict
    # the same points as doubles (the unrolled text has the double's shortest decimal, the loop its exact value)
    assert [(v.zone, [(n, float(x)) for n, x in v.point]) for v in a.violations] == \
        [(v.zone, [(n, float(x)) for n, x in v.point]) for v in b.violations]
    if reps * 0.1 < float(x_max):
        assert a.verdict == Verdict.SAFE and (a.profile or {}).get("double_pass", {}).get("motions") == 2 * reps
    else:
        assert a.verdict == Verdict.UNSAFE and a.violations


values = st.tuples(st.floats(-1e6, 1e6, allow_nan=False), st.none())


@settings(max_examples=60, deadline=None)
@given(st.dictionaries(st.integers(1, 40), values, max_size=12), st.lists(values, max_size=33))
def test_a_call_frame_saves_sets_and_restores_exactly(before, args):
    """The full path's frame (Parameters.push_scope/pop_scope, made cheaper for issue 36) against LinuxCNC's
    rule: inside, #k is the k-th argument for k <= 30 and unset beyond the arguments, #31.. untouched; after
    the endsub every numbered parameter reads as before (one unset before reads 0 again)."""
    from nczones.gcode.expr import SUB_PARAMS, Parameters

    p = Parameters()
    for k, v in before.items():
        p.write(k, v)
    saved = p.push_scope(tuple(args))
    for k in range(1, 41):
        inside = p.read(k)
        if k <= SUB_PARAMS:
            assert inside == (args[k - 1] if k <= len(args) else (0.0, Fraction(0)))
        else:
            assert inside == before.get(k, (0.0, Fraction(0)))
    p.pop_scope(saved)
    assert {k: p.read(k) for k in range(1, 41)} == {k: before.get(k, (0.0, Fraction(0))) for k in range(1, 41)}
    assert all(p.exists(k) for k in range(1, 41))
