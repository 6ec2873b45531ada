"""Programs with ``#`` and o-words verified from a streamed file (issue 36: flat memory).

A LinuxCNC program with parameters goes through the double pass (:mod:`nczones.gcode.linuxcnc.doubles`).
From a large file, ``load_program(path, stream=True)`` gives a :class:`~nczones.gcode.source.FileText`
(ASCII, or UTF-8 with other characters) and the pass reads it a piece of ``PIECE`` characters at a time,
cut after a newline, from the file: it never holds the whole text.  Here the stream threshold, the
file's windows and the pass's pieces are made tiny, so that short programs cross many edges, and:

* the pass over the streamed file is the pass over the ``str`` of the file: the same rows, counts, bounds,
  or the same reason to decline (Hypothesis over generated parametric programs, piece sizes of 1-40
  characters, windows of 1-40 bytes, CRLF and LF, a UTF-8 comment, a last line without a newline, and
  0-6 lines of loop and sub bodies kept compiled, ``MAX_STEPS``: the rest compiled again from the file);
* ``verify`` of the streamed file has the verdict, violations (lines, spans with the source text,
  witnesses), reasons and notes of ``verify`` of the file read whole: a violation whose line straddles a
  piece edge, CRLF, a UTF-8 character across a window edge, ``%`` lines, no newline at the end;
* a program the pass proves is verified without reading the whole text;
* the pass's memory does not grow with the program (``@pytest.mark.long``: 1M and 5M lines in a child
  process, its peak RSS).
"""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.gcode.linuxcnc.doubles as doubles
from nczones.errors import GcodeError
from nczones.gcode import source as S
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import load_machine
from nczones.pipeline.verification import verify_source
from nczones.prover.options import VerifyOptions
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import ACCEPTED, parametric_programs
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import machine_of

MILL = load_machine("specs/machines/mill.toml")
SETTINGS = settings(max_examples=int(os.environ.get("NCZONES_DOUBLE_PASS_EXAMPLES", "25")), deadline=None,
                    derandomize=True, database=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                           HealthCheck.function_scoped_fixture])


def _streamed(path, window: int, mp: pytest.MonkeyPatch) -> S.ProgramSource:
    """The file streamed through windows of ``window`` bytes (``mp`` keeps them while it is read)."""
    mp.setattr(S, "STREAM_MIN_BYTES", 0)
    mp.setattr(S, "WINDOW_BYTES", window)
    src = S.load_program(path, stream=True)
    assert isinstance(src.text, S.FileText)
    return src


def _pass(text, machine) -> tuple:
    try:
        p = double_pass(text, machine, max_iterations=1000)
    except Declined as exc:
        return ("declined", exc.reason)
    return ([list(c) for c in p.columns], p.motions, p.lines, p.rapids, p.blocks, p.start, p.first_row,
            p.offset_bound)


@SETTINGS
@given(parametric_programs(), st.integers(1, 40), st.integers(1, 40),
       st.sampled_from(["", "(caf\u00e9 \u00d8 12)\n", "; \u00b0C\n"]), st.booleans(), st.integers(0, 6))
def test_the_pass_over_a_streamed_file_is_the_pass_over_its_text(tmp_path_factory, text, piece, window,
                                                                 comment, cut_end, kept):
    # a UTF-8 comment (2-byte characters) somewhere in the program, and maybe no newline at the end
    if comment:
        lines = text.split("\n")
        lines.insert(len(lines) // 2, comment.rstrip("\n"))
        text = "\n".join(lines)
    if cut_end:
        text = text.rstrip("\n")
    if not text.strip():
        return
    path = tmp_path_factory.mktemp("pass") / "p.ngc"
    path.write_bytes(text.encode("utf-8"))
    machine = machine_of("box", 100, 0)
    whole = _pass(S.load_program(path).text, machine)
    with pytest.MonkeyPatch.context() as mp:
        src = _streamed(path, window, mp)
        assert src.text.ascii == text.isascii()
        mp.setattr(doubles, "PIECE", piece)
        # the loop and sub bodies kept compiled: at most `kept` lines, the others compiled again from the file
        mp.setattr(doubles, "MAX_STEPS", kept)
        assert _pass(src.text, machine) == whole


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_loops_and_calls_from_a_streamed_file(tmp_path, monkeypatch, name):
    # the pass's accepted programs (loops, branches, calls): bodies jumped back to across pieces of 3-30
    # characters, kept compiled or compiled again from the file each time
    path = tmp_path / "p.ngc"
    path.write_text(ACCEPTED[name])
    machine = machine_of("box", 100, 0)
    whole = _pass(ACCEPTED[name], machine)
    assert whole[0] != "declined"
    src = _streamed(path, 5, monkeypatch)
    for piece, kept in ((3, 0), (7, 2), (30, 1 << 16)):
        monkeypatch.setattr(doubles, "PIECE", piece)
        monkeypatch.setattr(doubles, "MAX_STEPS", kept)
        assert _pass(src.text, machine) == whole, (piece, kept)


def _outcome(result) -> tuple:
    return (result.verdict, [(v.block, v.span, v.zone, v.point, v.path_point, v.first_exit, v.kind, v.note)
                             for v in result.violations],
            [(r.message, r.span, r.code) for r in result.reasons], result.notes, result.program_sha256)


def _both(path, machine, window: int = 7, piece: int = 5) -> tuple[tuple, tuple]:
    """The outcome of verifying the file streamed (tiny windows and pieces) and read whole."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(doubles, "PIECE", piece)
        mp.setattr(doubles, "WINDOW", 3)
        streamed = _outcome(verify_source(_streamed(path, window, mp), machine, VerifyOptions()))
    whole = S.load_program(path)
    assert isinstance(whole.text, str)
    return streamed, _outcome(verify_source(whole, machine, VerifyOptions()))


def expression_program(n: int, out: int | None = None, eol: str = "\n", end: str = "M30\n") -> str:
    """``n`` moves whose words are expressions (the benchmark's class), move ``out`` outside the mill's
    travel (X 2000: mill.toml's X travel ends at 600)."""
    lines = ["G21 G90 G17 G54 F800", "G0 Z150", "G0 X200 Y50", "#1 = 0", "#2 = 0"]
    for k in range(n):
        if k % 10 == 9:
            lines.append("#1 = [#1 + 0.125]")
        x = "2000" if k == out else f"[#1 + {k % 97}.25]"
        lines.append(f"G1 X{x} Y[#2 + {k % 13}.5] Z-[1 + #1 / 100]")
    return eol.join(lines) + eol + end


@pytest.mark.parametrize("piece", [1, 9, 40, 41, 64, 200])
def test_a_violation_on_a_line_across_a_piece_edge(tmp_path, piece):
    # the violating line ("G1 X2000 ...") starts in one piece of the pass and ends in the next for some of
    # these sizes: the full path decides (the pass declines), its witness and source line are those of the
    # file read whole
    path = tmp_path / "p.ngc"
    path.write_text(expression_program(30, out=17))
    streamed, whole = _both(path, MILL, piece=piece)
    assert streamed == whole
    assert whole[0] is Verdict.UNSAFE and whole[1][0][1].text.startswith("G1 X2000")


@pytest.mark.parametrize("variant", ["crlf", "utf8", "percent", "no newline", "o-words", "long"])
def test_streamed_and_whole_verify_agree(tmp_path, variant):
    text = {
        "crlf": expression_program(40, out=33, eol="\r\n"),
        # "é" is two bytes: with windows of 7 bytes some fall across an edge
        "utf8": expression_program(12).replace("#1 = [#1 + 0.125]", "#1 = [#1 + 0.125] (caf\u00e9 \u00e9t\u00e9)"),
        "percent": "%\n" + expression_program(25, out=20, end="") + "%\n",
        "no newline": expression_program(25, end="M30"),
        "o-words": ("G21 G90 G54 F500 G1\no<edge> sub\nG1 X[#1] Y[#2]\no<edge> endsub\n#1 = 0\n"
                    "o1 while [#1 LT 30]\n#2 = [#1 * 2]\no<edge> call [#1] [#2]\n#1 = [#1 + 1]\no1 endwhile\nM30\n"),
        "long": expression_program(600),  # > 512 motions: the vectorized tier if the pass declined
    }[variant]
    path = tmp_path / "p.ngc"
    path.write_bytes(text.encode("utf-8"))
    for window, piece in ((7, 5), (64, 33), (1 << 20, 1 << 20)):
        streamed, whole = _both(path, MILL, window, piece)
        assert streamed == whole, (window, piece)
    assert whole[0] is (Verdict.UNSAFE if variant in ("crlf", "percent") else Verdict.SAFE)


def test_a_program_the_pass_proves_is_never_read_whole(tmp_path, monkeypatch):
    path = tmp_path / "p.ngc"
    path.write_bytes(expression_program(300).replace("#2 = 0", "#2 = 0 (\u00e9)").encode("utf-8"))
    whole = _outcome(verify_source(S.load_program(path), MILL, VerifyOptions()))
    src = _streamed(path, 64, monkeypatch)

    def refuse(self):
        raise AssertionError("the whole text was read")

    monkeypatch.setattr(doubles, "PIECE", 50)
    monkeypatch.setattr(S.FileText, "read_all", refuse)
    assert _outcome(verify_source(src, MILL, VerifyOptions())) == whole
    assert whole[0] is Verdict.SAFE


def test_a_file_changed_while_the_pass_reads_it_is_an_error(tmp_path):
    path = tmp_path / "p.ngc"
    path.write_text(expression_program(50))
    with pytest.MonkeyPatch.context() as mp:
        src = _streamed(path, 64, mp)
    with open(path, "a") as fh:
        fh.write("G1 X900\n")
    with pytest.raises(GcodeError) as exc:
        verify_source(src, MILL, VerifyOptions())
    assert exc.value.diagnostics[0].code == "GC100"


def test_what_the_stream_takes(tmp_path, monkeypatch):
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    monkeypatch.setattr(S, "WINDOW_BYTES", 3)
    path = tmp_path / "p.ngc"
    path.write_bytes("G1 X1 (caf\u00e9)\n".encode() * 5)  # UTF-8, "é" across a 3-byte window edge
    text = S.load_program(path, stream=True).text
    assert isinstance(text, S.FileText) and not text.ascii and text.read_all() == "G1 X1 (caf\u00e9)\n" * 5
    for data in (b"G1 X1 (caf\xe9)\n", b"\xef\xbb\xbfG1 X1\n", b"G1 X1 (caf\xc3"):
        # CP1252 in a comment, a byte order mark, a character cut at the end: read whole (a note or GC108)
        path.write_bytes(data)
        try:
            assert isinstance(S.load_program(path, stream=True).text, str)
        except GcodeError as exc:
            assert exc.diagnostics[0].code == "GC108" and data.endswith(b"\xc3")


_CHILD = """
import sys
sys.path.insert(0, "bench")
import bench_gcode
open(sys.argv[1], "w").write(bench_gcode.expr_program(int(sys.argv[2])))
"""


@pytest.mark.long
def test_the_memory_of_a_streamed_expression_program_is_flat(tmp_path):
    # The benchmark's "expression every line" class (bench_peers --scaling), verified by `nczones verify` in
    # a child process whose own peak RSS (wait4) is read: 1M and 5M lines (19 and 100 MB of text) cost the
    # same memory, at most 150 MB (issue 36; specs/performance.md has the 10M-line row).
    machine = tmp_path / "box.toml"
    machine.write_text(machine_text("xyz_box_900000"))  # tests/machines/xyz_box_900000.toml
    rss = []
    for n in (1_000_000, 5_000_000):
        path = tmp_path / "p.ngc"
        subprocess.run([sys.executable, "-c", _CHILD, str(path), str(n)], check=True)
        proc = subprocess.Popen([sys.executable, "-m", "nczones", "verify", str(path), "--machine", str(machine),
                                 "--format", "json"], stdout=subprocess.DEVNULL)
        _pid, status, usage = os.wait4(proc.pid, 0)
        assert os.waitstatus_to_exitcode(status) == 0
        rss.append(usage.ru_maxrss / 1024)
        path.unlink()
    assert rss[1] <= 150 and rss[1] - rss[0] <= 15, rss
