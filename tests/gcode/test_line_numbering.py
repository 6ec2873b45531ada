"""Every part of nczones numbers a program's lines as the controller reads them: at ``\\n`` only.

Form feeds, vertical tabs, ``\\x1c``-``\\x1e``, ``\\x85``, ``\\u2028`` and lone
``\\r`` are line breaks for ``str.splitlines`` but not for LinuxCNC.  The
language layer's spans are the reference; the source text that reports and
the controller look up for column chunks (which carry line numbers only)
must be the text of the same line.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import program_lines
from nczones.gcode import interpret_text
from nczones.prover import source_lines
from tests.gcode.test_fastpath_blocks import MACHINE

odd = st.sampled_from(["\x0c", "\x0b", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029", "\r", "é", ""])


@st.composite
def programs_with_odd_characters(draw):
    out = ["G21 G90 G1 F100"] if draw(st.booleans()) else ["o1 sub", "o1 endsub", "G21 G90 G1 F100"]
    for k in range(draw(st.integers(70, 150))):
        line = f"X{k}.5 Y{k % 7}"
        if draw(st.integers(0, 9)) == 3:
            line += f" (a{draw(odd)}b)"
        out.append(line)
    out.append("M30")
    head = "\ufeff" if draw(st.booleans()) else ""
    eol = draw(st.sampled_from(["\n", "\r\n"]))
    return head + eol.join(out) + eol


@settings(max_examples=40, deadline=None, derandomize=True, database=None)
@given(programs_with_odd_characters())
def test_segment_source_text_is_the_line_the_language_layer_read(text):
    full = [(s.span.line, s.span.text) for s in interpret_text(text, MACHINE, fast=False).segments()]
    run = interpret_text(text, MACHINE)
    fast = [(s.span.line, s.span.text) for s in run.segments()]
    assert run.fast_lines > 0
    assert fast == full
    lines = program_lines(text)
    assert all(lines[n - 1] == t for n, t in full)
    assert source_lines(text, [n for n, _ in full]) == dict(full)


def test_program_lines_split_at_newlines_only():
    assert program_lines("G1\x0cX1\r\nG2\u2028\rX2\n\n") == ["G1\x0cX1", "G2\u2028\rX2", ""]
    assert program_lines("") == [] and program_lines("\n") == [""]
