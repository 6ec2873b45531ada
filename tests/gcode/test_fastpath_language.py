"""Programs with control flow: the language layer runs them and hands runs of simple lines to the fast path.

The language layer (``o`` subroutines, loops, conditions, ``M98``
subprograms) decides which lines run and how often; whenever its flow
reaches the first line of a long run of simple lines it asks the fast path
to take the run in columns from the state the interpreter is in.  These
tests hold that to the full interpreter's segments, errors, unknown
reasons and block numbers, on generated programs whose runs sit in the main
program, subroutine bodies, loops and branches, behind ``M73``, drilling
cycles and computed (non-decimal) positions.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode import fastpath, interpret_text
from tests.gcode.test_fastpath_blocks import MACHINE, _fast, _full
from tests.gcode.test_fastpath_cycles import (
    CLAMP_MACHINE,
    assert_same_proof_with_and_without_fast_path,
)
from tests.sizes import examples


def _moves(n: int, seed: int, z: bool = False) -> list[str]:
    out = []
    for k in range(n):
        r = seed + 31 * k
        out.append(f"X{(r % 997) / 100:.2f} Y{(r * 7 % 991) / 100:.2f}" + (f" Z{-(r % 13) / 10:.1f}" if z else ""))
    return out


SUBS = {
    "o100": lambda n, seed: ["o100 sub", "G1 F400", *_moves(n, seed), "o100 endsub"],
    # M73 in a subroutine: the caller's G90 G21 come back when it returns, before the caller's next run
    "o101": lambda n, seed: ["o101 sub", "M73", "G91 G20", *["X0.01 Y-0.02"] * n, "o101 endsub"],
    "o102": lambda n, seed: ["o102 sub", "#<r> = [#1 * 0.5]", *_moves(n, seed, z=True), "G1 X#<r>", "o102 endsub"],
}


@st.composite
def language_programs(draw):
    """Subroutines with runs in their bodies, then a main program of runs, calls, loops and branches."""
    n = st.sampled_from([70, 130, 5])
    subs = draw(st.lists(st.sampled_from(sorted(SUBS)), min_size=1, max_size=3, unique=True))
    out = []
    for name in subs:
        out += SUBS[name](draw(n), draw(st.integers(0, 999)))
    out += ["G21 G90 G17 G54", "#1 = 1", "G1 F500"]
    for _ in range(draw(st.integers(1, 5))):
        item = draw(st.sampled_from(["run", "call", "repeat", "if", "computed", "cycle", "param", "stop", "bad"]))
        seed = draw(st.integers(0, 999))
        if item == "run":
            out += _moves(draw(n), seed)
        elif item == "call":
            out.append(f"{draw(st.sampled_from(subs))} call [{seed % 5}]")
        elif item == "repeat":
            out += ["o200 repeat [2]", *_moves(draw(n), seed), "#1 = [#1 + 1]", "o200 endrepeat"]
        elif item == "if":
            out += ["o300 if [#1 GT 1]", *_moves(draw(n), seed), "o300 else", *_moves(draw(n), seed + 1), "o300 endif"]
        elif item == "computed":
            out += ["G1 X[#1 / 3] Y[1 / 7]", *_moves(draw(n), seed)]  # not decimal: declined, retried further on
        elif item == "cycle":
            out += ["G0 Z5", "G99 G81 X1 Y1 Z-1 R2 F100", *_moves(draw(n), seed), "G80"]
        elif item == "param":
            out += ["#<_x0> = #5420", f"G1 X[#<_x0> + 1] F{100 + seed}"]
        elif item == "stop" and draw(st.integers(0, 9)) == 7:
            out += [*_moves(3, seed), "M2"]
        elif item == "bad" and draw(st.integers(0, 9)) == 7:
            out += _moves(80, seed)[:40] + ["X1 Y2 Y3"] + _moves(80, seed)[40:]  # an error inside a run
    out.append("M30")
    return "\n".join(out) + "\n"


@settings(max_examples=80, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(language_programs(), st.sampled_from([400, 1 << 20]), st.sampled_from(["\n", "\r\n"]), st.booleans())
def test_language_programs_with_fast_runs_equal_the_full_interpreter(text, block_bytes, newline, accents):
    if accents:  # non-ASCII comments in and between runs: byte and character offsets differ
        text = "".join(line + (" (Ø 5 mm, café)" if k % 7 == 3 else "") + "\n"
                       for k, line in enumerate(text.splitlines()))
    text = text.replace("\n", newline)
    assert _fast(text, block_bytes)[:2] == _full(text)


def test_runs_in_subroutines_loops_and_after_m73_take_the_fast_path():
    body = _moves(100, 3)
    text = "\n".join([
        "o101 sub", "M73", "G91 G20", *["X0.01 Y-0.02"] * 80, "o101 endsub",
        "o100 sub", *body, "o100 endsub",
        "G21 G90 G1 F300", "o200 repeat [3]", "o100 call", "o200 endrepeat",
        "o101 call", *_moves(90, 7), "M30"]) + "\n"
    run = interpret_text(text, MACHINE)
    segs = list(run.segments())
    # every call and iteration, and the main program's run; o101's run is found from its "M73" line
    # (the fast path cuts before M73, then G91 stops it): retried 1, then 1 + 2 lines further on
    assert run.fast_lines == 3 * 100 + 79 + 90
    assert _fast(text, 1 << 20)[:2] == _full(text)
    # after o101 returns, M73 has restored G90 G21: the main run moves to absolute millimetres
    x, y = (Fraction(w[1:]) for w in _moves(90, 7)[0].split())
    assert segs[-90].end[:2] == (x, y)


def test_a_run_declined_for_a_computed_position_is_retried_further_on():
    text = "\n".join(["o100 sub", "o100 endsub", "G21 G90 G1 F100", "G1 X[1 / 3] Y[2 / 3]", *_moves(200, 1),
                      "M30"]) + "\n"
    run = interpret_text(text, MACHINE)
    list(run.segments())
    # X and Y are both set on the run's first line, so the retry one line further on is taken
    assert run.fast_lines == 199
    assert _fast(text, 1 << 20)[:2] == _full(text)


def test_non_ascii_text_and_undecodable_bytes():
    """Non-ASCII text takes fast runs too (offsets converted); a text holding undecodable bytes (kept as
    surrogates) does not, since its bytes and characters do not map one to one."""
    moves = [m + (" (Ø café)" if k % 5 == 0 else "") for k, m in enumerate(_moves(100, 2))]
    text = "(café)\no100 sub\no100 endsub\nG1 F100\n" + "\n".join(moves) + "\no100 call\n" + "\n".join(moves) + "\nM30\n"
    run = interpret_text(text, MACHINE)
    list(run.segments())
    assert run.fast_lines == 201  # "G1 F100" and the first 100 moves, then the 100 after the call
    assert _fast(text, 1 << 20)[:2] == _full(text) and _fast(text, 500)[:2] == _full(text)
    bad = text.replace("(café)", "(caf\udce9)")
    run = interpret_text(bad, MACHINE)
    list(run.segments())
    assert run.fast_lines == 0
    assert _fast(bad, 1 << 20)[:2] == _full(bad)


def test_a_run_declined_again_and_again_is_no_longer_offered(monkeypatch):
    """A run the fast path keeps refusing (here every state is refused) in a loop of 50 calls is offered at
    most MAX_DECLINES times per start line; the result stays the full interpreter's."""
    calls = []
    real = fastpath._take_run

    def counting(interp, runs, req):
        calls.append(req.pos)
        return real(interp, runs, req)

    monkeypatch.setattr(fastpath, "_take_run", counting)
    monkeypatch.setattr(fastpath, "_state_decimal", lambda it: None)  # every state refused
    text = "\n".join(["o100 sub", *_moves(70, 1), "o100 endsub", "G21 G90 G1 F100",
                      "o200 repeat [50]", "o100 call", "o200 endrepeat", "M30"]) + "\n"
    run = interpret_text(text, MACHINE)
    list(run.segments())
    assert run.fast_lines == 0
    assert max(calls.count(p) for p in set(calls)) == fastpath.MAX_DECLINES
    assert _fast(text, 1 << 20)[:2] == _full(text)


@pytest.mark.long
@settings(max_examples=1500, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(language_programs(), st.sampled_from([300, 700, 1 << 20]), st.sampled_from(["\n", "\r\n"]))
def test_language_programs_with_fast_runs_long_fuzz(text, block_bytes, newline):
    """Opt-in (``-m long``): the differential test above with random (not derandomized) examples."""
    text = text.replace("\n", newline)
    assert _fast(text, block_bytes)[:2] == _full(text)


def test_language_programs_stream_in_bounded_chunks_and_memory():
    """Runs are cut at block ends, so chunks stay bounded; memory beyond the program text does not grow
    with the program's length (tracemalloc peaks of a 20,000- and an 80,000-line program)."""
    import tracemalloc

    def program(n):
        return "o100 sub\nG0 Z5\no100 endsub\nG21 G90 G1 F100\n" + "\n".join(_moves(n, 4)) + "\no100 call\nM30\n"

    text = program(3000)
    run = interpret_text(text, MACHINE)
    sizes = [len(c) for c in fastpath.run_with_fastpath(run, block_bytes=4000)]
    assert sum(sizes) == 3001 and max(sizes) <= 4000 // len("X0.00 Y0.00\n") + 1
    assert run.fast_lines == 3000  # the moves ("G21 G90 G1 F100" is declined, the run retried a line on)

    peaks = []
    for n in (20_000, 80_000):
        text = program(n)
        tracemalloc.start()
        run = interpret_text(text, MACHINE)
        segs = sum(len(c) for c in fastpath.run_with_fastpath(run, block_bytes=1 << 16))
        peaks.append(tracemalloc.get_traced_memory()[1])
        tracemalloc.stop()
        assert segs == n + 1 and run.fast_lines == n
        del run, text
    assert peaks[1] < 1.5 * peaks[0], peaks


@settings(max_examples=examples(5, 10), deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 999), st.sampled_from([10, 35, 60]), st.booleans())
def test_prover_verdicts_and_violations_agree_on_runs_handed_over_by_the_language_layer(seed, depth, in_sub):
    """End to end: a program whose moves run in subroutine bodies and the main program, around a clamp;
    the prover's verdict and violations (line, zone, point) are the same whether the language layer hands
    the runs to the fast path or the full interpreter reads every line."""
    moves = [f"X{60 + (seed + 37 * k) % 140}.{k % 10} Y{20 + (seed * 3 + 11 * k) % 200}" for k in range(80)]
    sub = ["o100 sub", "G1 Z#1", *moves, "G0 Z100", "o100 endsub"]
    main = ["G21 G90 G17 G54 G1 F300", "G0 Z100", *(["o100 call [%d]" % depth] if in_sub else []),
            "G1 Z%d" % depth, *moves[::-1], "G0 Z100", "o100 call [60]", "M30"]
    text = "\n".join(sub + main) + "\n"
    assert_same_proof_with_and_without_fast_path(text, CLAMP_MACHINE)
    run = interpret_text(text, CLAMP_MACHINE)
    sum(len(c) for c in run)
    assert run.fast_lines >= 160
