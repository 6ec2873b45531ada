"""``#4114`` after lines of an N alone, against a model of the reading (mend44: ``last["N*"]`` keeps only the N).

A line with an N and no NC word (``N25`` alone, a macro statement's label) is no block for nczones' reader; the
control's ``#4114`` after it holds its N or the last block's N, which no manual sentence settles
(test_last_sequence_number.py).  The model: walking the lines, the last block's N (a block with an NC word: a
move, ``M08``) and the N of a line alone after it (a block's N clears it); a read is unknown where the N alone
differs from the block's N, else the block's N.  The interpreter keeps the N alone in ``last["N*"]`` and
compares it with ``last["N"]``, which every setter of ``last["N"]`` makes safe (each drops ``last["N*"]``).

The generated programs mix numbered and unnumbered moves, general blocks, N alone and labels, and optionally a
run of 600 plain lines (the vectorized fast path's, ``fastpath._keep_last``) with an N alone inside it or at its
end; the read is the model's on the full path, the lanes and the vectorized path.
"""

from __future__ import annotations

import os
from fractions import Fraction

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.gcode.fanuc.test_last_sequence_number import alone_read

HEAD = "O6000\nG90 G17 G21 G54 F300.\n#1 = 0\nN1 G01 X1. Y1.\n"
TAIL = "G01 X[#4114 + 0.5] Y2.\nM30\n"
EXAMPLES = int(os.environ.get("NCZONES_LAST_N_MODEL_EXAMPLES", "20"))
_N = st.integers(1, 60)  # few numbers: an N alone often equals the block's N


@st.composite
def _programs(draw) -> tuple[str, Fraction | None]:
    """A program that moves by ``#4114`` at its end, and the move's X the model gives (None: unknown)."""
    block, alone = Fraction(1), None
    lines: list[str] = []

    def step(kind: str, k: int) -> None:
        nonlocal block, alone
        if kind == "move":
            lines.append(f"N{k} G01 X{k % 7}. Y{k % 5}.")
            block, alone = Fraction(k), None
        elif kind == "general":
            lines.append(f"N{k} M08")
            block, alone = Fraction(k), None
        elif kind == "plain":
            lines.append(f"G01 X{k % 7}. Y{k % 3}.")
        elif kind == "alone":
            lines.append(f"N{k}")
            alone = Fraction(k)
        else:
            lines.append(f"N{k} #1 = #1 + 1")
            alone = Fraction(k)

    kinds = st.sampled_from(["move", "general", "plain", "alone", "label"])
    count = draw(st.integers(1, 8))
    long_at = draw(st.sampled_from([None, None, 0, count - 1]))  # before which short line a long run comes
    for i in range(count):
        if i == long_at:  # 600 plain lines (no macro line: the vectorized path takes them), an N alone in them
            inside = draw(st.sampled_from([None, 0, 300, 599]))
            for j in range(600):
                step("alone" if j == inside else ("move" if j % 2 else "plain"), 1000 + j)
        kind = draw(kinds)
        # an N alone or a label often repeats the block's N (the read is then known)
        same = kind in ("alone", "label") and draw(st.booleans())
        step(kind, int(block) if same else draw(_N))
    if draw(st.booleans()):  # a long run last, ending on an N alone or a block
        for j in range(600):
            step("move" if j % 2 else "plain", 2000 + j)
        step(draw(st.sampled_from(["alone", "label", "move"])), draw(st.sampled_from([2599, 2598, 7])))
    read = None if alone is not None and alone != block else block
    return HEAD + "\n".join(lines) + "\n" + TAIL, read


_read = alone_read  # the N the move by #4114 reads (None: unknown), with or without block lanes


@settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(_programs())
def test_the_read_after_lines_of_an_n_alone_is_the_model_s(program):
    text, read = program
    for fast, lanes in ((True, True), (False, True), (False, False)):
        assert _read(text, fast, lanes) == read, (fast, lanes)
