"""The fast path reads programs in blocks: every block size gives the full interpreter's segments.

``run_with_fastpath(interp, block_bytes=k)`` cuts the program into blocks of
about ``k`` bytes at line ends and splits runs of simple lines there; the
segments (kinds, exact coordinates, centres, feeds, lines, blocks) must not
depend on ``k`` and must equal the full interpreter's.  Also: numbers that
could overflow ``int64`` go to the full path (exact), and the ``%`` cut and
the digit parser agree with their simple reference versions.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import fastpath, interpret_text
from nczones.machine import parse_machine
from tests.machines import machine_text

MACHINE = parse_machine(machine_text("mill_xyz", set={"machine.pulse": "0.0001"}, extra='[tool_lengths]\nH1 = "100"\n'))


def _key(s):
    return (s.kind, s.start, s.end, s.block, s.line, s.tool_length, s.feed_mm_min, s.plane, s.clockwise,
            s.centre, s.radius, s.turns, s.dwell_s, s.derived)


def _full(text: str):
    run = interpret_text(text, MACHINE, fast=False)
    try:
        return [_key(s) for s in run.segments()], [str(u) for u in run.unsupported]
    except GcodeError as exc:
        return ("error", str(exc.diagnostics[0].span)), []


def _fast(text: str, block_bytes: int):
    run = interpret_text(text, MACHINE)
    try:
        segs = [_key(s) for c in fastpath.run_with_fastpath(run, block_bytes=block_bytes) for s in c.segments()]
    except GcodeError as exc:
        return ("error", str(exc.diagnostics[0].span)), [], run.fast_lines
    return segs, [str(u) for u in run.unsupported], run.fast_lines


PROGRAM = """(a CAM program with everything the fast path handles, and some it does not)
G21 G90 G17 G54
G43 H1 G0 Z5 (tool length)
N10 G1 X1.5 Y-2.25 F800
X1.6 Y-2.2
x1.7 y-2.1 ; lower case and a semicolon comment
  X1.8   Y-2.0
G2 X2.8 Y-2.0 I0.5 J0
G3 X1.8 Y-2.0 R0.5
G1 X1.9
M3 S1000
X2.0 Y-1.9 Z-1.0
G0 Z5
G91
G1 X0.1 Y0.1
X0.1
X-0.05 Y0.025 Z-0.125
G2 X0.2 Y0 I0.1 J0
G90
G20
G1 X0.1 Y0.2
X0.15 Y0.25 F10.5
G4 P0.5
G21
G1 X3 Y3 F100
(MSG, a magic comment)
X3.5
G1 X4 Z0
G18
G2 X4 Z-2 K-1 I0
G17
G1 X4.5 Y4.5
M30
"""


def test_every_block_size_gives_the_full_interpreters_segments():
    want = _full(PROGRAM)
    assert want[0] and want[0][0] != "error"
    n = len(PROGRAM.encode())
    sizes = list(range(1, 80)) + list(range(80, n + 20, 7))
    used = 0
    for k in sizes:
        segs, unsupported, fast_lines = _fast(PROGRAM, k)
        assert (segs, unsupported) == want, k
        used = max(used, fast_lines)
    assert used > 10  # the fast path really took part


@st.composite
def cam_programs(draw):
    lines = [draw(st.sampled_from(["G21 G90 G17", "G20 G91 G17", "G21 G91 G17", "G90"]))]
    mode = None
    for _ in range(draw(st.integers(1, 40))):
        kind = draw(st.sampled_from(["move", "move", "move", "g", "comment", "blank", "other", "arc"]))
        if kind == "g":
            mode = draw(st.sampled_from(["G0", "G1"]))
            lines.append(f"{mode} F{draw(st.integers(1, 2000))}")
        elif kind == "move" and mode is not None:
            x = Fraction(draw(st.integers(-99999, 99999)), 10 ** draw(st.integers(0, 4)))
            y = Fraction(draw(st.integers(-99999, 99999)), 10 ** draw(st.integers(0, 4)))
            lines.append(f"X{float(x):.4f} Y{float(y):.3f}")
        elif kind == "arc":
            r = draw(st.integers(1, 50))
            lines.append(f"G2 X{2 * r} Y0 I{r} J0 F100")
            lines.append(f"G3 X0 Y0 I-{r} J0")
            mode = "G3"
        elif kind == "comment":
            lines.append("(comment G1 X99)")
        elif kind == "blank":
            lines.append("")
        else:
            lines.append(draw(st.sampled_from(["M8", "S500 M3", "G4 P1", "T1 M6"])))
    return "\n".join(lines) + "\n"


@settings(max_examples=25, deadline=None, derandomize=True)
@given(cam_programs(), st.integers(1, 200))
def test_random_programs_any_block_size(text, k):
    want = _full(text)
    segs, unsupported, _ = _fast(text, k)
    assert (segs, unsupported) == want


def test_numbers_that_could_overflow_go_to_the_full_path():
    big = "G21 G90 G17\nG1 F100\n" + "".join(f"X{123456789012 + i}.123456 Y-98765432109.87654\n" for i in range(80))
    want = _full(big)
    segs, unsupported, fast_lines = _fast(big, 1 << 20)
    assert (segs, unsupported) == want
    assert fast_lines == 0  # 10**6 scale times 1.2e11 is beyond the int64 guard: not taken fast
    assert want[0][-1][2][0] == Fraction(123456789012 + 79) + Fraction(123456, 10**6)


def test_incremental_sum_overflow_goes_to_the_full_path():
    text = "G21 G91 G17\nG1 F100\n" + "X99999999999.999999\n" * 100
    want = _full(text)
    segs, _, fast_lines = _fast(text, 1 << 20)
    assert segs == want[0]
    assert fast_lines == 0
    assert want[0][-1][2][0] == 100 * Fraction(99999999999999999, 10**6)


def test_language_layer_programs_are_not_split():
    text = "G1 F100\n" + "X1 Y1\n" * 100 + "o100 sub\nG1 X2\no100 endsub\no100 call\nM30\n"
    assert fastpath._needs_language_layer(text.encode(), interpret_text(text, MACHINE).interpreter, 64)
    assert not fastpath._needs_language_layer(b"(Operation / M98 in a comment)\nG1 X1 F1\n",
                                              interpret_text("", MACHINE).interpreter, 64)
    assert fastpath._needs_language_layer(b"G1 X1 F1\nm 9 8 P100\n", interpret_text("", MACHINE).interpreter, 4)
    assert _fast(text, 50)[:2] == _full(text)


RUN = "\n".join(f"X{k}.5 Y{k % 3}" for k in range(70))  # long enough for the fast path


@settings(max_examples=150, deadline=None, derandomize=True, database=None)
@given(st.lists(st.sampled_from(["G1 X1 F100", RUN, "%", " % (x)", "\t%", "(c) %", "; %", "(only)", "",
                                 "%a", "\r", "X2\r", "\x0c%", "(MSG, hi)", "G1 X3 (50% feed)", "#1 = 2", "N10"]),
                max_size=8))
def test_percent_lines_end_the_program_as_the_language_layer_says(parts):
    """The fast path cuts a program at its % lines only where the language layer would stop reading
    (a % line before the first line of code is skipped, the next one ends the program); everywhere
    else the language layer reads the whole program."""
    text = "\n".join(parts) + ("\n" if parts else "")
    assert _fast(text, 1 << 20)[:2] == _full(text)
    assert _fast(text, 300)[:2] == _full(text)


def test_a_percent_line_between_lines_of_code_ends_the_program_on_both_paths():
    text = "G1 X1 F100\n" + RUN + "\n%\n" + RUN.replace("X", "X1") + "\n"
    want = _full(text)
    assert _fast(text, 1 << 20)[:2] == want
    assert want[0][-1][2][0] == Fraction(695, 10)  # the last move before the % line


@settings(max_examples=80, deadline=None, derandomize=True)
@given(st.lists(st.tuples(st.sampled_from("XYZIJKF"), st.one_of(st.integers(-10**12, 10**12),
                                                                 st.integers(-(10**18 - 1), 10**18 - 1)),
                          st.integers(0, 6), st.booleans(), st.booleans()), min_size=1, max_size=12))
def test_digit_parser_is_exact(words):
    # up to 18 digits (the most a word may have), words of different lengths, over several lines
    text = []
    want = []
    line_of = []
    line = 0
    for letter, v, dec, plus, new_line in words:
        digits = str(abs(v)).rjust(dec + 1, "0")
        lit = digits[: len(digits) - dec] + ("." + digits[len(digits) - dec:] if dec else "")
        sign = "-" if v < 0 else ("+" if plus else "")
        text.append(f"{letter}{sign}{lit}")
        want.append(Fraction(v, 10**dec))
        line += bool(new_line and text[:-1])
        line_of += [line] * len(text[-1])
    code = np.frombuffer("".join(text).encode(), dtype=np.uint8)
    parsed = fastpath._parse_words(code, np.array(line_of, dtype=np.int32), 0, line + 1)
    assert parsed is not None
    lines, letters, value, dec, points = parsed
    got = [Fraction(int(v), 10 ** int(d)) for v, d in zip(value, dec)]
    assert got == want
    assert bytes(letters.tolist()).decode() == "".join(w[0] for w in words)
    assert lines.tolist() == [line_of[sum(len(t) for t in text[:i])] for i in range(len(text))]
    assert points.tolist() == ["." in t for t in text]  # the Fanuc dialect's decimal point input rule reads it


@pytest.mark.parametrize("bad", ["X1.2.3", "X+-1", "X", "X1-2", "1X2", "X.", "X1234567890123456789", "X1#2", "X1*2", "X.-1"])
def test_digit_parser_refuses_malformed_words(bad):
    code = np.frombuffer(bad.encode(), dtype=np.uint8)
    assert fastpath._parse_words(code, np.zeros(code.size, dtype=np.int32), 0, 1) is None


@pytest.mark.parametrize("stop", ["M2", "M30", "M0", "M1", "G1 X1 M6", "M110"])
def test_a_run_cut_by_another_m_code_is_read_once(stop, monkeypatch):
    # the lines before the M code go fast from the words already parsed for the whole run
    body = "\n".join(f"X{k % 97}.{k % 10}5 Y-{k % 31}.25" for k in range(3 * fastpath.MIN_RUN))
    text = f"G21 G90 G17 G54\nG1 F800\n{body}\n{stop}\nX1 Y1\n" + body + "\nM2\n"
    calls = []
    parse = fastpath._parse_words
    monkeypatch.setattr(fastpath, "_parse_words", lambda *a: calls.append(a[2:]) or parse(*a))
    got = _fast(text, 1 << 20)
    assert got[:2] == _full(text) and got[2] >= 3 * fastpath.MIN_RUN - 1
    assert not any(a[0] == b[0] and a[1] < b[1] for a in calls for b in calls)  # no run's first lines again


@settings(max_examples=60, deadline=None, derandomize=True)
@given(st.lists(st.lists(st.tuples(st.sampled_from("XYZF"), st.integers(-10**6, 10**6), st.integers(0, 4)),
                         min_size=0, max_size=4), min_size=1, max_size=12), st.data())
def test_the_words_of_a_run_cut_at_a_line_are_the_words_of_its_lines(lines, data):
    """``_words_from``: the run's parsed words cut at line ``i`` are what parsing lines ``i..`` alone gives
    (a retry of a run from a later line reuses them)."""
    text, line_of = [], []
    for n, words in enumerate(lines):
        for letter, v, dec in words:
            w = f"{letter}{'-' if v < 0 else ''}{str(abs(v)).rjust(dec + 1, '0')}"
            w = w if not dec else w[:len(w) - dec] + "." + w[len(w) - dec:]
            text.append(w)
            line_of += [n] * len(w)
    code = np.frombuffer("".join(text).encode() or b"", dtype=np.uint8)
    cl = np.array(line_of, dtype=np.int32)
    whole = fastpath._parse_words(code, cl, 0, len(lines))
    i = data.draw(st.integers(0, len(lines)))
    cut = fastpath._words_from({(0, len(lines)): whole}, 0, len(lines), i)
    alone = fastpath._parse_words(code, cl, i, len(lines))
    assert whole is not None and alone is not None
    assert [a.tolist() for a in cut] == [a.tolist() for a in alone]


def test_a_run_declined_at_its_header_is_parsed_once(monkeypatch):
    # a run whose first lines set modes the fast path does not take (G20, G17 G40, G64, G18: an R arc makes
    # them one run with the body) is tried again from later lines with the words parsed once
    body = "\n".join(f"X{k % 97}.{k % 10}5 Y-{k % 31}.25" for k in range(3 * fastpath.MIN_RUN))
    text = f"G21\nG17 G40\nG80 G90 G94\nG64\nF999.0\nG1 X1 Y1\n{body}\nM2\n"
    calls = []
    parse = fastpath._parse_words
    monkeypatch.setattr(fastpath, "_parse_words", lambda *a: calls.append(a[2:]) or parse(*a))
    got = _fast(text, 1 << 20)
    assert got[:2] == _full(text)
    assert len([c for c in calls if c[1] - c[0] > fastpath.MIN_RUN]) == 1, calls


@pytest.mark.parametrize("line", ["X1 X2", "X1 Y2 X3", "X1 Y2 Z3 X4", "G1 X1 G1 Y2", "F10 X1 Y1 Z1 F20", "N5 X1 Y2 Y3"])
def test_a_letter_twice_in_a_line_of_a_run_is_left_to_the_full_interpreter(line):
    body = [f"X{k % 97}.{k % 10}5 Y-{k % 31}.25 Z{k % 3}" for k in range(2 * fastpath.MIN_RUN)]
    body[fastpath.MIN_RUN + 3] = line
    text = "G21 G90 G17 G54\nG1 F800\n" + "\n".join(body) + "\nM2\n"
    assert _fast(text, 1 << 20)[:2] == _full(text)


def test_axis_words_the_machine_lacks_are_never_dropped():
    xy = parse_machine(machine_text("xy_unit"))
    text = "G1 F100\n" + "X1 Y1\n" * 100 + "X2 Z5\n" + "X1 Y1\n" * 100
    with pytest.raises(GcodeError) as e:
        list(interpret_text(text, xy).segments())
    d = e.value.diagnostics[0]
    assert d.code == "GC203" and (d.span.line, d.span.column, d.span.text.strip()) == (102, 4, "X2 Z5")


@settings(max_examples=400, deadline=None, derandomize=True, database=None)
@given(st.lists(st.one_of(
    st.sampled_from(["M", "m", "9", "8", "3", "0", " ", "\t", "\n", "\r", "G1", "X1", "(", ")", ";", "P", "#", "O",
                     "/", "["]),
    st.builds(lambda m, gap, d, tail: m + gap + d + tail, st.sampled_from("Mm"),
              st.sampled_from(["", " ", "\t", "\n", "0", " 0 "]), st.sampled_from("0983"),
              st.sampled_from(["", " ", "8", "9", " 8", "\t9", "\n9"]))), max_size=12).map("".join))
def test_quick_m98_screen_agrees_with_the_exact_check(text):
    """The text-level shortcut of ``_needs_language_layer`` (str input) decides as the exact
    byte-level check does (bytes input, which does not take the shortcut)."""
    from nczones.gcode.interpreter import Interpreter

    it = Interpreter(MACHINE)
    assert fastpath._needs_language_layer(text, it, 1 << 20) == fastpath._needs_language_layer(
        text.encode(), it, 1 << 20), repr(text)


sm_lines = st.one_of(
    st.builds(lambda x, y: f"X{x} Y{y}", st.integers(-999, 999), st.integers(-999, 999)),
    st.sampled_from(["M3", "M5 S0", "S12000 M3", "S1000", "M8", "M9", "G1 X1 S200 M4", "X2 M7", "G0 Z5 M5",
                     "M3 M8", "M3.0", "M6", "M0", "M2", "M30", "M98 P1", "S-5", "S1 S2", "m3 s100", "N5 M3 X1",
                     "M62 P1", "G1 F0 M3", "T1 M6", "M19 R1"]),
)


@settings(max_examples=150, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(sm_lines, min_size=0, max_size=12), st.integers(0, 3), st.integers(40, 200))
def test_spindle_and_coolant_words_in_fast_runs(sprinkled, every, n):
    """Long runs with S and M words: the fast path takes S and M3/M4/M5/M7/M8/M9 in its columns and
    cuts a run before any other M code (M2, M30, M6, M0, M98, ...); segments, errors, unknown
    reasons and block numbers stay those of the full interpreter."""
    lines = ["G21 G90 G17 G54 G1 F500"]
    for i in range(n):
        lines.append(f"X{i % 97}.{i % 7} Y{(i * 3) % 89}")
        if sprinkled and every and i % (every * 7) == 3:
            lines.append(sprinkled[i % len(sprinkled)])
    lines += sprinkled + ["X1 Y1", "M30", "X9"]
    text = "\n".join(lines) + "\n"
    for size in (1 << 20, 333):
        segs, unsupported, fast_lines = _fast(text, size)
        assert (segs, unsupported) == _full(text), (text, size)


def test_runs_with_spindle_words_take_the_fast_path():
    text = "G21 G90 G1 F500 S1000 M3\n" + "".join(f"X{i}.5 Y1 S{1000 + i % 5} M{3 + (i % 2) * 5}\n" for i in range(300)) + "M30\n"
    segs, unsupported, fast_lines = _fast(text, 1 << 20)
    assert (segs, unsupported) == _full(text)
    assert fast_lines >= 300
