"""Programs with parameters but no control flow: runs of plain lines fast, parameter lines full.

A program whose language-layer use is parameters and expressions only (no
``O`` words, ``M98``/``M99``, ``/``) is split like any other: its ``#`` and
``[`` lines are not simple, so the full path runs them, all pieces sharing
one parameter store.  These tests hold the split to the full interpreter's
segments, errors, unknown reasons and block numbers, including the state
parameters (``#5420``, ``#<_x>``) read right after a fast run.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.gcode import fastpath, interpret_text
from tests.gcode.test_fastpath_blocks import MACHINE, _fast, _full

PARAMETER_LINES = (
    "#1 = [#1 + 0.5]",
    "#2 = [#2 - 1.25] (a comment)",
    "#<depth> = -1.5",
    "#<_g> = #5420",
    "#<_h> = [#<_y> + #5421]",
    "G1 X#1 Y[#2 * 2]",
    "G0 Z#<depth>",
    "G1 X[#<_g> + 0.001] F[200 + #1]",
    "G1 Y#<_h>",
    "(DEBUG, x is #5420)",
    "#3 = [COS[30] * 10]",
    "G1 X#3",
    "G92 X[#1 + 1]",
    "G92.1",
    "#5 = 30",
)
#: Rarer: errors (a division by zero, an unset name) and computed M codes (whole program to the language layer).
RARE_LINES = ("#4 = [1 / 0]", "G1 X#<never_set>", "M#5", "M[2 + 1]")
PLAIN_LINES = ("G20", "G21", "G91", "G90", "G0 Z1", "G1 F300", "G91 G2 X1 Y0 I0.5 J0\nG90", "G1")


def _move(rnd: int) -> str:
    return f"X{(rnd % 997) / 100:.2f} Y{(rnd * 7 % 991) / 100:.2f}"


@st.composite
def parameter_programs(draw):
    """A program of long runs of moves with parameter lines and a few modal lines between them."""
    out = ["G21 G90 G17 G54", "#1 = 1", "#2 = 2", "#<depth> = -1", "#<_g> = 0", "#<_h> = 0", "G1 F500"]
    for _ in range(draw(st.integers(1, 6))):
        n = draw(st.sampled_from([70, 130, 3]))
        seed = draw(st.integers(0, 10**6))
        out += [_move(seed + k) for k in range(n)]
        between = st.sampled_from(PARAMETER_LINES + PLAIN_LINES)
        if draw(st.integers(0, 19)) == 13:  # not 0: Hypothesis favours the ends of a range
            between = st.sampled_from(RARE_LINES)
        out += draw(st.lists(between, min_size=1, max_size=3))
    out.append("M30")
    return "\n".join(out) + "\n"


@settings(max_examples=60, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(parameter_programs(), st.sampled_from([200, 1500, 1 << 20]))
def test_parameter_programs_split_equal_the_full_interpreter(text, block_bytes):
    assert _fast(text, block_bytes)[:2] == _full(text)


def test_parameter_program_takes_the_fast_path_and_reads_the_state_after_a_fast_run():
    moves = [f"X{k}.5 Y{k % 3}" for k in range(100)]
    text = "\n".join(["G21 G90 G1 F100", "#<x0> = 2", *moves, "#<_end_x> = #5420",
                      "G1 X[#<_end_x> + #<x0>] Y#<_y>", *moves, "M30"]) + "\n"
    run = interpret_text(text, MACHINE)
    segs = list(run.segments())
    assert run.fast_lines == 200
    after = segs[100]  # the move that reads the position the fast run left
    assert after.start[0] == 99.5 and after.end[0] == 101.5 and after.end[1] == 0
    assert _fast(text, 1 << 20)[:2] == _full(text)


def test_control_flow_still_takes_the_whole_program_to_the_language_layer():
    it = interpret_text("", MACHINE).interpreter
    plain = "G1 X1 F1\n"
    for text in ("#1 = 2\n", "G1 X[1 + 2]\n", "(M98 in a comment) #1 = 5\n", "T#<tool_no> M6\n",
                 "#<m98> = 1 (a name is not code)\n"):
        assert not fastpath._needs_language_layer(plain + text, it, 1 << 20)
    for text in ("o100 if [1]\no100 endif\n", "M98 P100\n", "M #1\n", "m[98]\n", "/G1 X2\n", "M99\n",
                 "o<tool_no> call\n", "#<a> = 1 (x)\nM 9 8 P1\n", "#<o\nO100 sub>\n"):
        assert fastpath._needs_language_layer(plain + text, it, 1 << 20), text
        assert fastpath._needs_language_layer((plain + text).encode(), it, 1 << 20), text


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(["M", "m", "9", "8", "3", " ", "\n", "\t", "#", "[", "G1 X1", "M98", "M 9\n9",
                                 "G1 X1 Y2 F100 S2000\n" * 20]), max_size=30))
def test_m98_m99_prefilter_is_the_regular_expression_search(pieces):
    """The pre-filter of _needs_language_layer tries the pattern at each M when M is rare, else
    searches: the same answer as one search of the text either way."""
    text = "".join(pieces)
    assert fastpath._m98_m99_raw(text) == (fastpath._M98_M99_RAW.search(text) is not None)


@settings(max_examples=150, deadline=None)
@given(st.lists(st.sampled_from(["G1 X1", "X2 Y3", "#1 = 2", "G1 X[1 + 2]", "(#1 in a comment) X4",
                                 "G1 X#1", "M3"]), min_size=1, max_size=12),
       st.lists(st.integers(1, 3 * fastpath.MIN_RUN), min_size=1, max_size=12))
def test_blocks_passed_over_unclassified_have_no_long_run(kinds, repeats):
    """_may_have_long_run is False only for blocks whose classification has no run of MIN_RUN
    simple lines: the pre-test never takes a run away from the fast path."""
    it = interpret_text("", MACHINE).interpreter
    text = "".join(f"{k}\n" * n for k, n in zip(kinds, repeats))
    blk = text.encode()
    simple = fastpath._classify(blk, it)[0]
    longest = max((b - a for a, b in fastpath._simple_runs(simple)), default=0)
    if not fastpath._may_have_long_run(blk):
        assert longest < fastpath.MIN_RUN
    prep = fastpath._prepare(blk, it)
    assert [list(r) for r in prep[4] if r[1] - r[0] >= fastpath.MIN_RUN] == \
        [r for r in fastpath._simple_runs(simple) if r[1] - r[0] >= fastpath.MIN_RUN]
    starts, ends_ = fastpath._classify(blk, it)[1:3]
    assert prep[1].tolist() == starts.tolist() and prep[2].tolist() == ends_.tolist()
