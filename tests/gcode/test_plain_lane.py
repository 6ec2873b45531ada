"""The plain-move lane gives exactly the general path's result.

The language layer hands plain lines over as ``PlainBlock`` (letters and
values, words made only when read) and the interpreter executes plain
straight moves by ``Interpreter._plain``/``_lean_move`` instead of its
general block machinery.  Both are shortcuts for speed, so they are held to
the general path here: on generated programs made to hit the lane's edges
(modal G0/G1, F, S, M3..M9, G20/G21, G90/G91, offsets, tool lengths, extra
words that must leave the lane, errors) and on the LinuxCNC-style corpus.
"""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.gcode.program as program_module
from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.gcode.interpreter import Interpreter
from nczones.gcode.lexer import PlainBlock
from nczones.gcode.program import iter_blocks
from nczones.machine import parse_machine
from tests.corpus import CORPUS
from tests.machines import machine_text

MACHINE = parse_machine(machine_text("xyza_g55_h1_h2"))


def _result(text: str, machine=MACHINE, block_delete=False):
    run = interpret_text(text, machine, fast=False, block_delete=block_delete)
    try:
        segs = [(s.kind, s.start, s.end, s.block, s.span.line, s.span.text, s.feed_mm_min, s.tool_length,
                 s.tool_register, s.centre, s.clockwise, s.dwell_s, s.derived)
                for s in run.segments()]
    except GcodeError as exc:
        return "error", [(d.code, d.message, str(d.span), d.span.column if d.span else None) for d in exc.diagnostics]
    return "ok", segs, [u.render() for u in run.unsupported], run.assumed_modal, run.counts


def _general(text: str, machine=MACHINE, block_delete=False):
    """The result with the shortcuts off: no PlainBlocks (so no plain-line loop either), no lean moves."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(program_module, "scan_plain", lambda line: None)
        mp.setattr(Interpreter, "_lean", lambda self, *args: False)
        return _result(text, machine, block_delete)


words = st.sampled_from([
    "G0", "G1", "g01", "G00", "F100", "F0", "F-5", "S1200", "S0", "M3", "M5", "M8", "M9", "M6", "M0",
    "T2", "G2", "G17", "G4", "P1", "R2", "I1", "Z", "G53",
    "M2", "M02", "M30", "M30.0", "M2.5", "M98", "M99", "G65", "G65.1", "G64", "G67",  # words the language layer acts on
])
numbers = st.sampled_from(["0", "1", "-1.5", ".25", "2.", "-0.001", "12.3456", "100"])


@st.composite
def plain_lines(draw):
    kind = draw(st.integers(0, 9))
    if kind == 0:
        return draw(st.sampled_from(["G90", "G91", "G20", "G21", "G55", "G54", "G43 H1", "G43 H2", "G49",
                                     "G94", "G93", "G1 F200", "M3 S100", "/G1 X3", "N10 G0 X0 Y0",
                                     "G92 X1", "G92.1", "G80", "(comment) G1 X1", "/X2 Y1", "/ G1 X-1", "%", ""]))
    parts = []
    for _ in range(draw(st.integers(0, 3))):
        w = draw(words)
        parts.append(w + (draw(numbers) if w in ("Z", "P", "R", "I") else ""))
    for axis in draw(st.lists(st.sampled_from("XYZA"), max_size=3)):
        parts.append(axis + draw(numbers))
    parts = draw(st.permutations(parts))
    sep = draw(st.sampled_from([" ", "", "  "]))
    return sep.join(parts)


expression_lines = st.sampled_from([
    "#1 = 2.5", "#2 = [1 / 3]", "X[1 + 2] Y#1", "G[1] X#2", "X[#1 / 3] F[100 * 2]", "G0 X[COS[30]] Y-#1", "M[3] S[100]",
    "G1 X#2 Z[#1 - 0.5]", "F#1 X[2 ** 0.5]", "X[#1] X[2]", "G[0.5] X1", "M[98] P1", "#3 = -1\nF#3 X1", "A[#1 * 10]",
    "X[1/0]", "N7 G1 X[#1 + 1] (cut)", "G91 X[#2]", "G20 X[#1]", "Y[#<_x> + 1]",
])


@settings(max_examples=200, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.one_of(plain_lines(), expression_lines), min_size=1, max_size=14), st.booleans())
def test_evaluated_blocks_in_the_lane_equal_the_general_path(lines, feed_first):
    """Blocks whose words the language layer evaluated ([...], #) are handed over in the lane's form too."""
    text = ("G1 F500\n" if feed_first else "") + "\n".join(lines) + "\n"
    assert _result(text) == _general(text), text


@settings(max_examples=300, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(plain_lines(), min_size=1, max_size=14), st.booleans(), st.booleans(), st.sampled_from(["\n", "\r\n"]))
def test_plain_lane_equals_general_path_on_generated_programs(lines, feed_first, block_delete, eol):
    text = ("G1 F500" + eol if feed_first else "") + eol.join(lines) + eol
    assert _result(text, block_delete=block_delete) == _general(text, block_delete=block_delete), text


def test_plain_lines_become_plain_blocks_and_others_do_not():
    blocks = list(iter_blocks("G1 X1 Y2 F100\nG1 X2 (cut)\n#1=2\nG1 X#1\nN5 X3 S100 M3\nM98 P10\nM2\nO10\nM99\n"))
    # line 4's words are evaluated by the general path and handed on in the lane's form too, words kept;
    # M2 ends the program and is read by the general path (which hands it on the same way)
    assert [(type(b) is PlainBlock, b.span.line) for b in blocks] == [
        (True, 1), (False, 2), (True, 4), (True, 5), (True, 7)]
    assert [w.text for w in blocks[2].words] == ["G1", "X#1"]
    # words of a plain block are made on reading and equal the general lexer's
    assert [(w.letter, w.value, w.text, str(w.span)) for w in blocks[0].words] == [
        ("G", 1, "G1", "<program>:1:1"), ("X", 1, "X1", "<program>:1:4"), ("Y", 2, "Y2", "<program>:1:7"),
        ("F", 100, "F100", "<program>:1:10")]


def test_errors_from_plain_lines_keep_column_and_text():
    """A plain line that must fail fails in the general path, with the word's own span."""
    for text, code, col in (("G1 X1 F-5\n", "GC209", 7), ("G1 X1 X2 F1\n", "GC204", 7), ("G1 Q1 X1 F1\n", None, None),
                            ("G0 B1\n", "GC203", 4), ("G1 X1\n", "GC305", None)):
        res = _result(text)
        assert res == _general(text)
        if code is not None:
            assert res[0] == "error" and res[1][0][0] == code, (text, res)
            if col is not None:
                assert res[1][0][3] == col, (text, res)


def _corpus_programs():
    if not CORPUS.is_dir():
        return []
    files = sorted(CORPUS.rglob("*.ngc")) + sorted(CORPUS.rglob("*.nc"))
    return files[::5] if os.environ.get("NCZONES_FULL_CORPUS") != "1" else files  # a fifth by default


@pytest.mark.skipif(not CORPUS.is_dir(), reason="corpus not available")
@pytest.mark.parametrize("path", _corpus_programs(), ids=lambda p: str(p.relative_to(CORPUS)))
def test_plain_lane_equals_general_path_on_the_corpus(path):
    text = path.read_text(errors="replace")
    if len(text) > 400_000:
        pytest.skip("large program: covered by the fast-path corpus differential")
    assert _result(text) == _general(text)


def test_the_lane_takes_plain_moves_and_only_them(monkeypatch):
    taken = []
    original = Interpreter._lean_move
    monkeypatch.setattr(Interpreter, "_lean_move", lambda self, axis_at, values: (
        taken.append(self.span.line), original(self, axis_at, values))[1])
    text = ("G21 G90 G1 X1 F100\nX2 S3 M3\nG0 Y1\nG91 X1\nX1 (note)\nG2 X1 Y1 I1\nG1 X1 M6\n"
            "N8 G1 X3 F50 S1 M8\nM2\n")
    assert _result(text) == _general(text)
    # 2, 3, 8 are PlainBlocks; 5 (a comment) is a plain move lexed by the general lexer
    assert taken == [2, 3, 5, 8]


@pytest.mark.parametrize("eol", ["\n", "\r\n"])
@pytest.mark.parametrize("block_delete", [False, True])
def test_runs_of_plain_lines_honour_block_delete_line_ends_and_program_end(block_delete, eol):
    """The language layer reads runs of plain main-program lines in a loop of their own: it skips
    block-deleted lines only with the switch on, strips CR, and hands M2/M30/M98 lines to the
    general path (nothing after M30 is read)."""
    lines = ["G21 G90 G1 F100", "X1 Y1", "/X2 Y2", "/ X3", "", "X4 Y4", "N7 X5", "M30", "X9 Y9"]
    text = eol.join(lines) + eol
    res = _result(text, block_delete=block_delete)
    assert res == _general(text, block_delete=block_delete)
    ends = [seg[2][:2] for seg in res[1]]
    if block_delete:
        assert ends == [(1, 1), (4, 4), (5, 4)]
    else:
        assert ends == [(1, 1), (2, 2), (3, 2), (4, 4), (5, 4)]
    assert [seg[5] for seg in res[1]][-1] == "N7 X5"  # the span's text, without the CR


control_lines = st.sampled_from([
    "o100 sub\nG1 X[#1 + 1] Y2\nX3\no100 endsub", "o100 call [1.5]", "o7 repeat [3]\nX[#1 + 0.5] Y1\nG0 Z2\no7 endrepeat",
    "#1 = [#1 + 0.25]", "M73", "G1 X#<_x> F300",
])


def _chunked(text: str, chunk_size: int, lane: bool):
    """Chunk lengths, segments, counts and errors with the language layer handing plain blocks to the
    interpreter's lane (``lane``) or yielding every block."""
    with pytest.MonkeyPatch.context() as mp:
        if not lane:
            mp.setattr(Interpreter, "lane_for_blocks", lambda self: None)
        run = interpret_text(text, MACHINE, fast=False, chunk_size=chunk_size)
        chunks = []
        try:
            for chunk in run:
                chunks.append([(s.kind, s.start, s.end, s.block, str(s.span), s.span.text, s.feed_mm_min)
                               for s in chunk.segments()])
        except GcodeError as exc:
            return chunks, [(d.code, str(d.span)) for d in exc.diagnostics]
        return chunks, run.counts, [u.render() for u in run.unsupported]


@settings(max_examples=150, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.one_of(plain_lines(), expression_lines, control_lines), min_size=1, max_size=12),
       st.sampled_from([1, 2, 3, 4096]))
def test_blocks_handed_to_the_lane_equal_blocks_yielded(lines, chunk_size):
    """``iter_blocks(..., lane=Interpreter.lane)`` executes plain blocks without building them: the same
    segments in the same chunks (a full chunk is handed on after the same block), the same block
    counts, errors and unknown reasons, in the main program, loops and subroutines."""
    text = "G1 F500\n" + "\n".join(lines) + "\nM2\n"
    assert _chunked(text, chunk_size, True) == _chunked(text, chunk_size, False), text


def test_the_language_layer_offers_plain_blocks_to_a_lane_and_yields_the_rest():
    from nczones.gcode import shapes
    from nczones.gcode.blocks import LANE_FULL

    # the line shapes are the process's: another test that ran a line like "X#1" first would have compiled it
    # (CI's worker order met that once), and this test is about the first line of each shape
    shapes.clear()
    offered = []

    def lane(letters, values, span, index):
        offered.append((letters, values, span.line, span.text, index))
        return {2: 1, 4: 2}.get(span.line, 0)  # take line 2; take line 4 and ask for control back

    # line 3 is the first of its shape (parsed, executed by the general path), line 4 has compiled code
    text = "G1 X1 F100\nX2\nX[1 + 2]\nX[1 + 3]\n#1 = 4\nX#1\nM2\n"
    out = list(iter_blocks(text, lane=lane))
    assert [b if b is LANE_FULL else (b.span.line, b.index) for b in out] == [(1, 0), (3, 2), LANE_FULL, (6, 4), (7, 5)]
    assert offered == [("GXF", (1, 1, 100), 1, "G1 X1 F100", 0), ("X", (2,), 2, "X2", 1), ("X", (4,), 4, "X[1 + 3]", 3)]
