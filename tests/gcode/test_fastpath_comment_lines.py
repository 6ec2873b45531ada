"""The fast path's classifier searches only the lines with a "(" for a comment inside a word when such lines are
few (issue 36: one header comment made it scan every byte of a 100,000-line block, 0.1 s CPU).

The search line by line and the scan of the whole block must mark the same lines: a match of
``_COMMENT_IN_WORD`` holds a "(" and no newline, so it lies within one line that has a "(", and a search of that
line's text (no anchors, no look-behind) finds a match exactly when the block's scan finds one there.  Checked
on generated blocks of comment-heavy bytes, with both settings of ``COMMENT_LINES_APART`` forced, and end to end
on a long program with one header comment and a comment inside a word further down.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import fastpath
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import machine_text


class _Axes:
    axes = ("X", "Y", "Z")


def _classified(data: bytes, apart: int, monkeypatch) -> tuple:
    monkeypatch.setattr(fastpath, "COMMENT_LINES_APART", apart)
    simple, starts, ends, (code, code_line) = fastpath._classify(data, _Axes())
    return simple.tolist(), starts.tolist(), ends.tolist(), code.tobytes(), np.asarray(code_line).tolist()


_PIECES = st.sampled_from(["X1", "(c)", "0.5", "X", "(", ")", " ", "\t", ";", "G1", "Y-2", "((x))", "R1", "(MSG,a)"])
_LINE = st.one_of(
    st.lists(st.one_of(_PIECES, st.text(alphabet="GXY01239.-( )\t;R", max_size=4)), max_size=6).map("".join),
    st.sampled_from(["G1 X1(c)0.5 Y2", "G1 X(c)1", "G1 X1 (c) Y2", "(HEADER)", "G1 X1.(a) 5", "G1 X1 Y2"]))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(lines=st.lists(_LINE, min_size=1, max_size=40))
def test_line_by_line_search_marks_what_the_block_scan_marks(lines, monkeypatch):
    data = "\n".join(lines).encode()
    whole = _classified(data, 10**9, monkeypatch)  # every block: one scan of all its bytes
    each = _classified(data, 0, monkeypatch)  # every block: the lines with a "(" one by one
    assert each == whole


def test_a_long_program_with_a_header_comment_and_a_comment_inside_a_word():
    """600 straight moves after a header comment (the line-by-line search), one written ``X1(c)0.5``: LinuxCNC
    refuses a comment inside a word (GC101 on the full path, which the line goes to: a user error at its line,
    not ``X10.5``); without that line the program is ``safe``."""
    moves = [f"G1 X{k % 7}.5 Y{k % 5}" for k in range(600)]
    head = ["(HEADER COMMENT)", "G21 G90 G17", "G0 X0 Y0", "F800"]
    m = parse_machine(machine_text("fanuc_xyz_table_60").replace('dialect = "fanuc"', ""))
    assert verify_text("\n".join([*head, *moves, "M2"]) + "\n", m).verdict.label == "safe"
    bad = [*moves[:300], "G1 X1(c)0.5 Y2", *moves[300:]]
    with pytest.raises(GcodeError, match="GC101") as got:
        verify_text("\n".join([*head, *bad, "M2"]) + "\n", m)
    assert ":305:" in str(got.value)  # the line as written, not X10.5 read by the fast path
