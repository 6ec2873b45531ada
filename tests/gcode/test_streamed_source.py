"""A large program file verified without its text in memory (issue 36, flat memory).

``load_program(path, stream=True)`` leaves a plain ASCII file of at least ``STREAM_MIN_BYTES`` on disk: its
``text`` is a :class:`~nczones.gcode.source.FileText` read a window at a time.  These tests shrink the size
and the window so that small programs take the streamed path, and check that

* a FileText answers every ``str`` question the verify path asks exactly as the ``str`` of the file does
  (find, count, slices, ``in``, ``endswith``, the fast path's blocks), for any window size;
* verifying the streamed file gives the verdict, violations (blocks, spans with their text, witnesses),
  reasons and notes of verifying the same file read whole — on generated programs (short, > 512 motions: the
  vectorized tier, with ``#``: the double pass, with o-words, M98 and ``%``: the language layer, each
  streamed since issue 36's mem36 branch, tests/gcode/test_streamed_classes.py);
* a plain CAM program is verified without ever reading the whole text;
* a file changed while it is verified is an error (``GC100``), and files the stream cannot take (not UTF-8,
  too small) are read whole as before (programs with ``#``: tests/gcode/test_streamed_double_pass.py).
"""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import fastpath
from nczones.gcode import source as S
from nczones.machine import load_machine, parse_machine
from nczones.pipeline.verification import verify_source
from nczones.prover.options import VerifyOptions
from nczones.testing import machines, programs

MILL = load_machine("specs/machines/mill.toml")


@pytest.fixture
def small_stream(monkeypatch):
    """Every file streams, through windows of 64 bytes (so every search crosses window edges)."""
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    monkeypatch.setattr(S, "WINDOW_BYTES", 64)


def _file_text(tmp_path, text: str) -> S.FileText:
    path = tmp_path / "p.ngc"
    path.write_bytes(text.encode("ascii"))
    src = S.load_program(path, stream=True)
    assert isinstance(src.text, S.FileText)
    return src.text


@settings(max_examples=25, deadline=None, database=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.text(alphabet="G1X.5\n %#", min_size=1, max_size=400), st.integers(1, 40), st.data())
def test_a_file_text_answers_as_the_str_of_the_file(tmp_path_factory, text, window, data):
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(S, "STREAM_MIN_BYTES", 0)
        mp.setattr(S, "WINDOW_BYTES", window)
        ft = _file_text(tmp_path_factory.mktemp("ft"), text)
        n = len(text)
        assert len(ft) == n and ft.endswith("\n") == text.endswith("\n") and ft.read_all() == text
        for _ in range(12):
            a = data.draw(st.integers(-3, n + 3))
            b = data.draw(st.one_of(st.none(), st.integers(-3, n + 3)))
            sub = data.draw(st.sampled_from(["\n", "G", "X1", "\nG1", "%", "#", "G1X.5\n"]))
            assert ft.find(sub, a, b) == text.find(sub, a, b)
            assert ft.find(sub.encode(), a) == text.find(sub, a)
            assert ft[a:b] == text[a:b]
            assert ft.count("\n", a, b) == text.count("\n", a, b)
            assert (sub in ft) == (sub in text)
        size = data.draw(st.integers(1, 50))
        assert list(fastpath._encoded_blocks(ft, size)) == list(fastpath._encoded_blocks(text, size))


def _outcome(result) -> tuple:
    return (result.verdict, [(v.block, v.span, v.zone, v.point, v.path_point, v.first_exit, v.kind, v.note)
                             for v in result.violations],
            [(r.message, r.span, r.code) for r in result.reasons], result.notes, result.program_sha256)


def _both(tmp_path, text: str, machine, options: VerifyOptions | None = None) -> tuple[tuple, tuple]:
    """The outcome of verifying ``text`` as a streamed file and as a file read whole."""
    path = tmp_path / "prog.ngc"
    path.write_bytes(text.encode("ascii"))
    options = options or VerifyOptions()
    streamed = S.load_program(path, stream=True)
    assert isinstance(streamed.text, S.FileText)
    whole = S.load_program(path)
    assert isinstance(whole.text, str)
    return _outcome(verify_source(streamed, machine, options)), _outcome(verify_source(whole, machine, options))


def cam(n: int, seed: int, spread: float = 60.0) -> str:
    """A CAM-like program of about ``n`` lines: modal X/Y/Z moves and a full I/J circle now and then, some of
    them outside the mill's travel or into its vise."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54", "G0 Z5", "G1 F800"]
    for k in range(n):
        if k % 40 == 39:
            out.append("G2 I1 J0")  # a full circle of radius 1 from where the tool stands
            out.append("G1")
        else:
            out.append(f"X{rnd.uniform(-spread, spread):.3f} Y{rnd.uniform(-spread, spread):.3f}"
                       + (f" Z{rnd.uniform(-30, 5):.2f}" if k % 7 == 0 else ""))
    out.append("M30")
    return "\n".join(out) + "\n"


@pytest.mark.parametrize("n, seed", [(20, 1), (700, 2), (3000, 3)])
def test_streamed_cam_programs_verify_as_read_whole(tmp_path, small_stream, n, seed):
    streamed, whole = _both(tmp_path, cam(n, seed), MILL)
    assert streamed == whole
    assert n < 700 or whole[1]  # the long ones have violations (and witnesses) to compare


@pytest.mark.parametrize("extra", [
    "#1 = 5\nG1 X#1 Y[#1 * 2]\n",               # parameters: the double pass, then the full path, streamed
    "o100 sub\nG1 X1 Y1\no100 endsub\no100 call\n",  # o-words: the language layer, streamed (a line at a time)
    "/G1 X500\n",                                # block delete: both switch positions, on the whole text
    "G7\nG1 X10\nG8\n",                          # lathe codes: the lathe interpreter, on the whole text
])
def test_programs_the_stream_cannot_take_are_verified_whole(tmp_path, small_stream, extra):
    text = cam(800, 5)
    text = text.replace("M30\n", extra + "M30\n")
    streamed, whole = _both(tmp_path, text, MILL)
    assert streamed == whole


def test_percent_lines_and_a_program_end_before_the_text_ends(tmp_path, small_stream):
    body = cam(900, 6).replace("M30\n", "")
    for text in ("%\n" + body + "%\n", body + "M2\nG1 X900\n", body + "M30\n\n\n"):
        streamed, whole = _both(tmp_path, text, MILL)
        assert streamed == whole


@settings(max_examples=10, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much,
                                 HealthCheck.function_scoped_fixture])
@given(st.data())
def test_generated_programs_verify_streamed_as_read_whole(tmp_path_factory, data):
    machine = data.draw(machines(axes=("X", "Y", "Z")))
    text = data.draw(programs(machine, max_blocks=12, subprograms=data.draw(st.booleans())))
    if not text.isascii():
        return
    reps = data.draw(st.sampled_from([1, 60]))  # 60 copies: past 512 lines, the vectorized tier
    text = text * reps
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(S, "STREAM_MIN_BYTES", 0)
        mp.setattr(S, "WINDOW_BYTES", 97)
        outcomes = []
        path = tmp_path_factory.mktemp("gen") / "p.ngc"
        path.write_bytes(text.encode("ascii"))
        for stream in (True, False):
            try:
                outcomes.append(_outcome(verify_source(S.load_program(path, stream=stream), machine,
                                                       VerifyOptions())))
            except GcodeError as exc:
                d = exc.diagnostics[0]
                outcomes.append(("error", d.code, d.span.line if d.span else None))
    assert outcomes[0] == outcomes[1], text


def test_a_plain_cam_program_is_never_read_whole(tmp_path, small_stream, monkeypatch):
    text = cam(2000, 7)
    path = tmp_path / "prog.ngc"
    path.write_text(text)
    whole = _outcome(verify_source(S.load_program(path), MILL, VerifyOptions()))

    def refuse(self):
        raise AssertionError("the whole text was read")

    monkeypatch.setattr(S.FileText, "read_all", refuse)
    assert _outcome(verify_source(S.load_program(path, stream=True), MILL, VerifyOptions())) == whole


def test_a_file_changed_while_it_is_verified_is_an_error(tmp_path, small_stream):
    path = tmp_path / "prog.ngc"
    path.write_text(cam(600, 8))
    src = S.load_program(path, stream=True)
    with open(path, "a") as fh:
        fh.write("G1 X900\n")
    with pytest.raises(GcodeError) as exc:
        verify_source(src, MILL, VerifyOptions())
    assert exc.value.diagnostics[0].code == "GC100" and "changed" in exc.value.diagnostics[0].message


def test_files_the_stream_cannot_take_are_read_whole(tmp_path, monkeypatch):
    path = tmp_path / "prog.ngc"
    path.write_text(cam(50, 9))
    assert isinstance(S.load_program(path, stream=True).text, str)  # below STREAM_MIN_BYTES
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    assert isinstance(S.load_program(path, stream=True).text, S.FileText)
    path.write_bytes(b"G1 X1 (caf\xe9)\n" * 10)  # not UTF-8 (CP1252 in a comment): decoded whole, as before
    assert isinstance(S.load_program(path, stream=True).text, str)
    path.write_bytes(b"G1 X1 (caf\xc3\xa9)\n" * 10)  # UTF-8: streamed, read whole by all lanes but the pass
    assert not S.load_program(path, stream=True).text.ascii
    path.write_bytes(b"G1 X1 " + b"0" * (S.MAX_LINE_CHARS + 1) + b"\n")  # an over-long line: GC110, as before
    with pytest.raises(GcodeError) as exc:
        S.load_program(path, stream=True)
    assert exc.value.diagnostics[0].code == "GC110"
    path.write_bytes(b" \n\t\n")
    with pytest.raises(GcodeError) as exc:
        S.load_program(path, stream=True).require_code()
    assert exc.value.diagnostics[0].code == "GC109"


def test_the_verify_command_streams_a_large_file(tmp_path, monkeypatch):
    from nczones.commands.verify import verify_one

    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 1 << 10)
    path = tmp_path / "prog.ngc"
    path.write_text(cam(700, 10))
    machine = parse_machine(open("specs/machines/mill.toml").read(), "mill.toml")
    source, streamed = verify_one(str(path), machine, VerifyOptions(), stream=True)
    assert isinstance(source.text, S.FileText)
    _, whole = verify_one(str(path), machine, VerifyOptions())
    assert _outcome(streamed) == _outcome(whole)
