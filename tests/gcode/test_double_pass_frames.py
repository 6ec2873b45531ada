"""Call frames in the double pass (issue 36: o-word subs at rs274's speed): agreement with the full path.

The pass runs a sub's straight lines as one compiled block and calls a sub whose body has no ``#`` without a
frame (nothing in it can read or write #1..#30 or a local name; a call it makes saves and restores its own).
The full path keeps LinuxCNC's frame on every call (``Parameters.push_scope`` / ``pop_scope``).  Generated
programs cross: subs with and without ``#``, called with and without arguments, nested (a sub calls the
subs defined before it), a sub that reads a parameter it was not given, a sub that writes #1..#30 (dropped at
its endsub) and a global #31 (read after the return), local named parameters, calls inside while loops in the
main program and in subs, and nesting past :data:`~nczones.gcode.linuxcnc.doubles.MAX_CALLS` (declined).
Whenever the pass returns, the full interpreter's run agrees with it (``check_against_full``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.gcode.linuxcnc.doubles as doubles
from nczones.gcode.linuxcnc.doubles import MAX_CALLS, Declined, double_pass
from nczones.machine import parse_machine
from nczones.pipeline import verification
from nczones.prover import Verdict, verify_text
from tests.oracles.rs274 import canon_motion

from .test_double_pass import MACHINE, check_against_full, machine_text

EXAMPLES = int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "60"))


@st.composite
def plain_motion(draw) -> str:
    return f"G1 X{draw(st.integers(-20, 60))} Y{draw(st.integers(-20, 60))}"


@st.composite
def param_motion(draw) -> str:
    # #1..#6: given or not (a sub reads 0 for one it was not given); #31 global; #<a> local (written first)
    x = draw(st.sampled_from(["#1", "#2", "#5", "#31", "[#1 + #3]", "#<a>"]))
    return f"G1 X{x} Y{draw(st.sampled_from(['#2', '#4', '#6', '7']))}"


def call_line(draw, label: int, plain_args: bool) -> str:
    n = draw(st.integers(0, 3))
    pool = ["1", "2.5", "-4"] if plain_args else ["1", "#1", "[#2 * 2]", "#31"]
    return f"o{label} call {' '.join(f'[{draw(st.sampled_from(pool))}]' for _ in range(n))}".rstrip()


@st.composite
def sub_defs(draw) -> tuple[list[str], list[int]]:
    """1..4 subs, each plain (no '#') or not; sub k may call the subs before it (nesting, never recursion)."""
    lines: list[str] = []
    labels: list[int] = []
    for k in range(draw(st.integers(1, 4))):
        label = 500 + k
        plain = draw(st.booleans())
        body: list[str] = []
        if not plain and draw(st.booleans()):
            body.append("#<a> = [#1 + 10]")  # a local name of this call
        for _ in range(draw(st.integers(1, 4))):
            kind = draw(st.integers(0, 5))
            if kind <= 1:
                body.append(draw(plain_motion() if plain else param_motion()))
            elif kind == 2 and labels:
                body.append(call_line(draw, draw(st.sampled_from(labels)), plain))
            elif kind == 3 and not plain:
                body.append(f"{draw(st.sampled_from(['#1', '#2', '#30', '#31', '#<a>']))} = [#31 + {k + 1}]")
            elif kind == 4 and not plain:
                loop = 600 + 10 * k + len(body)  # labels not reused
                body += ["#3 = 0", f"o{loop} while [#3 LT {draw(st.integers(0, 2))}]",
                         draw(param_motion()), "#3 = [#3 + 1]", f"o{loop} endwhile"]
            else:
                body.append(draw(plain_motion()))
        if not plain:
            body = [line if "#<a>" not in line or body[0].startswith("#<a> =") else line.replace("#<a>", "#6")
                    for line in body]
        lines += [f"o{label} sub", *body, f"o{label} endsub"]
        labels.append(label)
    return lines, labels


@st.composite
def frame_programs(draw) -> str:
    defs, labels = draw(sub_defs())
    main = ["G21 G90 G17 G54 F300", "#1 = 3", "#2 = 4", "#5 = 6", "#31 = 1", "#<a> = 2"]
    for k in range(draw(st.integers(1, 4))):
        call = call_line(draw, draw(st.sampled_from(labels)), draw(st.booleans()))
        if draw(st.booleans()):
            main += ["#11 = 0", f"o{700 + k} while [#11 LT {draw(st.integers(0, 3))}]", call, "#11 = [#11 + 1]",
                     f"o{700 + k} endwhile"]
        else:
            main.append(call)
        main.append("G1 X[#1 + #31] Y[#2 + #5 + #<a>]")  # the caller's after the return: restored, #31 not
    return "\n".join([*defs, *main, "M30"]) + "\n"


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(frame_programs())
def test_frames_in_the_pass_agree_with_the_full_interpreter(text):
    check_against_full(text, MACHINE)


@settings(max_examples=20, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(frame_programs(), st.integers(0, 3))
def test_bodies_kept_in_part_give_the_same_rows(monkeypatch, text, kept):
    # at most MAX_STEPS lines of bodies are kept compiled; past them a block's lines are compiled at each run
    whole = double_pass(text, MACHINE, max_iterations=1000)
    with monkeypatch.context() as m:
        m.setattr(doubles, "MAX_STEPS", kept)
        part = double_pass(text, MACHINE, max_iterations=1000)
    assert [list(c) for c in part.columns] == [list(c) for c in whole.columns]
    assert (part.motions, part.blocks, part.rapids) == (whole.motions, whole.blocks, whole.rapids)


@settings(max_examples=20, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(frame_programs())
def test_most_generated_frame_programs_are_taken_by_the_pass(text):
    # the generator stays inside the subset: a decline would make the agreement above vacuous
    try:
        double_pass(text, MACHINE, max_iterations=1000)
    except Declined as exc:  # only an evaluation error may decline ([#1 + #3] with unset names is fine)
        raise AssertionError(f"declined: {exc.reason}\n{text}") from None


def test_frames_as_rs274_runs_them():
    # rs274 -g (LinuxCNC 2.9.0~pre1) on this program prints the feeds
    #   (3, 0, 1) (4, 2, 2) (11, 12, 2) (3, 0, 2) (13, 14, 2) (4, 2, 3):
    # o100 call [3]: #1 = 3, #5 not given reads 0, #31 = 1 (global); its #5 = 7 is dropped at the endsub and
    # its #31 + 1 kept (the caller reads #1 = 4, #5 = 2, #31 = 2).  o200 (no '#': called without a frame)
    # ignores its arguments [8] [9]; the o100 call inside it sees its own [3] and, back in the main
    # program, #1 = 4 and #5 = 2 again, #31 = 3.
    text = ("o100 sub\nG1 X#1 Y#5 Z#31\n#31 = [#31 + 1]\n#5 = 7\no100 endsub\n"
            "o200 sub\nG1 X11 Y12\no100 call [3]\nG1 X13 Y14\no200 endsub\n"
            "G21 G90 G54 F100\n#5 = 2\n#1 = 4\n#31 = 1\no100 call [3]\nG1 X#1 Y#5 Z#31\n"
            "o200 call [8] [9]\nG1 X#1 Y#5 Z#31\nM2\n")
    path = check_against_full(text, MACHINE)
    assert path is not None, "declined"
    rows = list(zip(*(list(c) for c in path.columns)))[1:]
    assert rows == [(3, 0, 1), (4, 2, 2), (11, 12, 2), (3, 0, 2), (13, 14, 2), (4, 2, 3)]


def nest(depth: int) -> str:
    """Subs o501..o50<depth>, each calling the one before (plain ones and ones with '#' in turn)."""
    lines = []
    for k in range(1, depth + 1):
        inner = [f"o{500 + k - 1} call [{k}]"] if k > 1 else []
        body = ["G1 X#1 Y1", *inner] if k % 2 else ["G1 X2 Y2", *inner]
        lines += [f"o{500 + k} sub", *body, f"o{500 + k} endsub"]
    return "\n".join([*lines, "G21 G90 G54 F100", f"o{500 + depth} call [9]", "M2"]) + "\n"


def test_calls_nested_to_the_limit_are_followed_and_past_it_declined():
    assert check_against_full(nest(MAX_CALLS), MACHINE) is not None
    with pytest.raises(Declined, match="nested deeply"):
        double_pass(nest(MAX_CALLS + 1), MACHINE, max_iterations=100)
    recursive = "o500 sub\nG1 X1\no500 call\no500 endsub\nG21 G90 G54 F100\no500 call\nM2\n"  # no '#' in it
    with pytest.raises(Declined, match="recursive"):
        double_pass(recursive, MACHINE, max_iterations=100)


POST = parse_machine(machine_text(extra='[[zones]]\nname = "post"\nkind = "box"\nforbid = true\n'
                                        'min = { X = "40", Y = "40", Z = "-1000" }\n'
                                        'max = { X = "50", Y = "50", Z = "1000" }\n'))


@pytest.mark.parametrize("reps", [3, 300])  # 6 motions, and 600 (past the vectorized tier)
@pytest.mark.parametrize("into", [False, True])
def test_verify_of_plain_and_parametric_subs_in_a_loop(monkeypatch, reps, into):
    """End to end with '#' (the double pass): a plain sub (no frame) and a sub with arguments, called in a
    loop; the plain sub's contour crosses the post at X 40..50, Y 40..50 when ``into``.  The verdict and
    violations are the full path's (the pass off)."""
    contour = "G1 X45 Y45\nG1 X0 Y0" if into else "G1 X30 Y45\nG1 X0 Y0"
    text = (f"o100 sub\n{contour}\no100 endsub\no200 sub\nG0 X[#1 * 0.01] Y#2\no100 call\no200 endsub\n"
            f"G21 G90 G17 G54 F300\n#11 = 0\no1 while [#11 LT {reps}]\no200 call [#11] [-5]\n"
            "#11 = [#11 + 1]\no1 endwhile\nM30\n")
    routed = verify_text(text, POST)
    with monkeypatch.context() as m:
        m.setattr(verification, "double_pass_result", lambda *a, **k: None)
        full = verify_text(text, POST)
    assert routed.verdict == full.verdict == (Verdict.UNSAFE if into else Verdict.SAFE)
    assert [(v.block, v.zone, v.point) for v in routed.violations] == [(v.block, v.zone, v.point)
                                                                      for v in full.violations]
    assert dict(routed.stats)["segments"] == dict(full.stats)["segments"] or into
    if not into:
        assert (routed.profile or {}).get("double_pass", {}).get("motions") == 3 * reps


def _as_rs274(text: str, examples: list[int]) -> None:
    """The pass's rows against ``rs274 -g``'s log (its own HOME: the tool table file), 4 printed decimals."""
    path = double_pass(text, MACHINE, max_iterations=1000)
    with tempfile.TemporaryDirectory() as tmp:
        Path(tmp, "prog.ngc").write_text(text)
        run = subprocess.run(["rs274", "-g", "prog.ngc"], cwd=tmp, env={**os.environ, "HOME": tmp},
                             capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=30, check=False)
    moves = [m.end[:3] for m in canon_motion(run.stdout) if m.kind in ("RAPID", "LINE")]
    rows = list(zip(*(list(c) for c in path.columns)))[1:]
    assert len(moves) == len(rows), (run.stderr, text)
    for k, (move, row) in enumerate(zip(moves, rows)):
        # the machine is G54 at 0 and mm: rs274's program coordinates are the rows, to its printed 0.0001
        assert all(abs(float(a) - b) <= 0.0001 for a, b in zip(move, row)), (k, move, row, text)
    examples.append(1)


RS274 = pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")


@RS274
@settings(max_examples=15, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(frame_programs())
def test_frames_in_the_pass_as_rs274_runs_them(text):
    _as_rs274(text, [])


@RS274
@pytest.mark.long
def test_frames_in_the_pass_as_rs274_runs_them_long():
    """1,000 generated programs (specs/contract.md, "Call frames in the double pass against rs274")."""
    done: list[int] = []

    @settings(max_examples=1000, deadline=None, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(frame_programs())
    def each(text):
        _as_rs274(text, done)

    each()
    assert len(done) == 1000
