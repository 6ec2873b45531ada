"""Flat memory for every class of the benchmark (issue 36): a long program verified from a streamed file.

``bench_peers --scaling`` measures classes of generated programs (CAM G1, R-format and I/J arcs in both
dialects, Fanuc CAM output, ...).  These tests check, per class, that

* the peak of Python's allocations (``tracemalloc``) while a streamed file is verified does not grow with the
  program: 3x the lines (3x the text) cost less than half the added text more (a text read whole costs
  1x-5x the text: the decoded text, its ``%`` cut, its lower-cased copies).  The windows are shrunk (file
  windows of 4 KiB, blocks and double-pass pieces of 16 KiB, an arc cache of 64, corner batches of 64, column runs of 512 rows) so that the fixed windows
  are (nearly) full at both sizes;
* verifying a streamed Fanuc program gives the verdict, violations (blocks, spans with their text,
  witnesses), reasons, notes and statistics of verifying the same file read whole, short and past 512
  motions (the vectorized tier), with R-format arcs, I/J arcs and straight moves, and without reading the
  whole text; so does a LinuxCNC program with o-word subroutines and no ``#`` (the language layer) and one
  with ``#`` that the double pass declines (the full path).
"""

from __future__ import annotations

import math
import random
import tracemalloc

import pytest

from nczones.gcode import fastpath
from nczones.gcode import source as S
from nczones.gcode.fanuc import columns
from nczones.gcode.fanuc.paths import path_headers
from nczones.gcode.linuxcnc import doubles
from nczones.machine import load_machine
from nczones.pipeline import verification
from nczones.pipeline.verification import verify_source
from nczones.prover import blend
from nczones.prover.options import VerifyOptions
from nczones.prover.result import Verdict
from tests.machines import load_machine as load_test_machine

FANUC = load_machine("specs/machines/fanuc_mill.toml")
MILL = load_machine("specs/machines/mill.toml")


def _box(dialect: str) -> object:
    """A box of ±900,000 mm that every generated walk stays in (bench_peers --scaling's machine)."""
    return load_test_machine("xyz_box_900000", set={"machine.dialect": dialect})


@pytest.fixture
def small_windows(monkeypatch):
    """Every file streams, through windows small enough that the sizes below fill them all."""
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    monkeypatch.setattr(S, "WINDOW_BYTES", 4096)
    monkeypatch.setattr(fastpath, "BLOCK_BYTES", 16384)
    monkeypatch.setattr(blend, "ARC_CACHE", 64)
    monkeypatch.setattr(blend, "CORNER_BATCH", 64)
    monkeypatch.setattr(doubles, "PIECE", 16384)
    monkeypatch.setattr(doubles, "WINDOW", 512)  # plain LinuxCNC files of these sizes go to the pass (issue 36)
    monkeypatch.setattr(columns, "MAX_ROWS", 512)
    # the box route reads a plain Fanuc text of up to FANUC_BOX_LINES lines whole (40,000: its window, as the
    # pass's WINDOW is the double pass's); past it the streamed lanes read it
    monkeypatch.setattr(verification, "FANUC_BOX_LINES", 1000)


def walk(n: int, seed: int, kind: str, dialect: str, spread: float = 5.0, start: str = "") -> str:
    """About ``n`` lines of moves from the origin: ``kind`` ``"r"`` (R-format arcs, some the long way round,
    a G1 every 20th line), ``"ij"`` (I/J arcs whose end is the start turned about the centre) or ``"line"``
    (straight moves); steps of up to ``spread`` mm.  Fanuc: lengths with a decimal point, ``%``/``O`` framing."""
    rnd = random.Random(seed)
    fanuc = dialect == "fanuc"
    out = (["%", "O1000 (WALK)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0."] if fanuc else
           ["G21 G90 G17 G54", "G0 X0 Y0"]) + start.splitlines() + ["G01 F800." if fanuc else "G1 F800"]
    x = y = 0.0
    while len(out) < n:
        if kind == "line" or len(out) % 20 == 0:
            x, y = round(x + rnd.uniform(-spread, spread), 3), round(y + rnd.uniform(-spread, spread), 3)
            out.append(f"G1 X{x:.3f} Y{y:.3f}")
        elif kind == "r":
            x1, y1 = round(x + rnd.uniform(-spread, spread), 3), round(y + rnd.uniform(-spread, spread), 3)
            half = math.hypot(x1 - x, y1 - y) / 2
            if half < 0.01:
                continue
            r = round(half * rnd.uniform(1.001, 4) + 0.001, 3) * (-1 if rnd.random() < 0.1 else 1)
            out.append(f"G{rnd.choice((2, 3))} X{x1:.3f} Y{y1:.3f} R{r:.3f}")
            x, y = x1, y1
        else:
            i, j = round(rnd.uniform(-spread, spread) / 2, 3), round(rnd.uniform(-spread, spread) / 2, 3)
            if math.hypot(i, j) < 0.05:
                continue
            turn, cx, cy = rnd.uniform(0.2, 2.5), x + i, y + j
            x = round(cx - i * math.cos(turn) + j * math.sin(turn), 3)
            y = round(cy - i * math.sin(turn) - j * math.cos(turn), 3)
            out.append(f"G{rnd.choice((2, 3))} X{x:.3f} Y{y:.3f} I{i:.3f} J{j:.3f}")
    out += ["M30", "%"] if fanuc else ["M30"]
    return "\n".join(out) + "\n"


_PAD = "a step of the walk " * 12


def osub(n: int, seed: int, spread: float = 5.0) -> str:
    """About ``n`` lines of a LinuxCNC program with o-word subroutines and no ``#`` (the language layer): a
    plunge and a 20-line contour, called every 50 lines of a walk of straight moves."""
    rnd = random.Random(seed)
    contour = [f"G1 X{rnd.uniform(-spread, spread):.3f} Y{rnd.uniform(-spread, spread):.3f}" for _ in range(20)]
    out = ["o100 sub", "G0 Z5", "G1 Z-1 F200", "o100 endsub", "o200 sub", *contour, "o200 endsub",
           "G21 G90 G17 G54", "G1 F800"]
    while len(out) < n:
        out += ["o100 call", "o200 call", "G1 F800"]
        # a long comment on each line: the text outweighs the fixed windows (so the test sees a text held whole)
        out += [f"X{rnd.uniform(-spread, spread) * 10:.3f} Y{rnd.uniform(-spread, spread) * 10:.3f} ({_PAD})"
                for _ in range(50)]
    return "\n".join(out + ["M30"]) + "\n"


def declined(n: int, seed: int, spread: float = 5.0) -> str:
    """About ``n`` lines with an expression on each, the spindle started and G64 P0.01 (a path tolerance the
    double pass does not follow, so the full path reads the program), a parameter changed every tenth line."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54 F800", "S1000 M3", "G64 P0.01", "#1 = 0", "#2 = 0"]
    while len(out) < n:
        if len(out) % 10 == 0:
            out.append(f"#1 = [#1 + {rnd.uniform(-spread, spread):.3f}]")
        else:
            out.append(f"G1 X[#1 + {rnd.uniform(-spread, spread) * 10:.3f}] Y[#2 + {rnd.uniform(-spread, spread) * 10:.3f}]")
    return "\n".join(out + ["M30"]) + "\n"


#: The classes: (name, program of about n lines, dialect).  The sizes compared are 2,500 and 7,500 lines, or
#: those of SIZES (the language layer's windows of motion fill later).
CLASSES = {
    "CAM G1": (lambda n: walk(n, 1, "line", "linuxcnc"), "linuxcnc"),
    "R-format arcs": (lambda n: walk(n, 2, "r", "linuxcnc"), "linuxcnc"),
    "I/J arcs": (lambda n: walk(n, 3, "ij", "linuxcnc"), "linuxcnc"),
    "Fanuc CAM G1": (lambda n: walk(n, 4, "line", "fanuc"), "fanuc"),
    "R-format arcs, Fanuc": (lambda n: walk(n, 5, "r", "fanuc"), "fanuc"),
    "I/J arcs, Fanuc": (lambda n: walk(n, 6, "ij", "fanuc"), "fanuc"),
    "o-word subs, no #": (lambda n: osub(n, 7), "linuxcnc"),
    "# declined by the pass": (lambda n: declined(n, 8), "linuxcnc"),
}
SIZES = {"o-word subs, no #": (7500, 22500), "# declined by the pass": (5000, 15000)}


def _peak(path, machine) -> int:
    """The peak of Python's allocations (bytes) while the streamed file ``path`` is verified (``safe``)."""
    src = S.load_program(path, stream=True)
    assert isinstance(src.text, S.FileText)
    tracemalloc.start()
    try:
        result = verify_source(src, machine, VerifyOptions())
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert result.verdict is Verdict.SAFE, result.reasons
    return peak


@pytest.mark.parametrize("name", [pytest.param(c, marks=pytest.mark.long) if c == "o-word subs, no #" else c
                                  for c in CLASSES])  # the o-word class: about 20 s under tracemalloc
def test_the_memory_of_a_streamed_program_does_not_grow_with_its_length(tmp_path, small_windows, name):
    make, dialect = CLASSES[name]
    machine = _box(dialect)
    warm = tmp_path / "warm.ngc"
    warm.write_text(make(600))
    _peak(warm, machine)  # the modules each lane imports on first use, not counted below
    sizes, peaks = [], []
    for n in SIZES.get(name, (2500, 7500)):
        path = tmp_path / f"p{n}.ngc"
        path.write_text(make(n))
        sizes.append(path.stat().st_size)
        peaks.append(_peak(path, machine))
    assert peaks[1] - peaks[0] <= (sizes[1] - sizes[0]) / 2, (peaks, sizes)


def _outcome(result) -> tuple:
    return (result.verdict, [(v.block, v.span, v.zone, v.point, v.path_point, v.first_exit, v.kind, v.note)
                             for v in result.violations],
            [(r.message, r.span, r.code) for r in result.reasons], result.notes, result.program_sha256,
            result.stats)


@pytest.mark.parametrize("kind, n", [("r", 40), ("r", 600), ("ij", 600), ("line", 600)])
def test_a_streamed_fanuc_program_verifies_as_read_whole(tmp_path, monkeypatch, kind, n):
    # fanuc_mill.toml: the travel is program X -360..400, Y -180..250 (G54 X-400 Y-250); the clamp is at
    # program X 85..115, Y -20..60 for a tip below Z 15: steps of up to 60 mm from the origin at Z-1 leave the
    # travel and cross the clamp now and then (the long programs have violations, with their witnesses)
    text = walk(n, 7 + n, kind, "fanuc", spread=60.0, start="G43 H1 Z25.\nG01 Z-1. F800.")
    path = tmp_path / "p.nc"
    path.write_text(text)
    whole = _outcome(verify_source(S.load_program(path), FANUC, VerifyOptions()))
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    monkeypatch.setattr(S, "WINDOW_BYTES", 64)

    def refuse(self):
        raise AssertionError("the whole text was read")

    if n >= 512:  # a shorter program is read by the full interpreter alone, on its whole text
        monkeypatch.setattr(S.FileText, "read_all", refuse)
    src = S.load_program(path, stream=True)
    assert isinstance(src.text, S.FileText)
    assert _outcome(verify_source(src, FANUC, VerifyOptions())) == whole
    assert n < 600 or whole[1]


@pytest.mark.parametrize("make, n", [(osub, 40), (osub, 600), (declined, 600)])
def test_a_streamed_linuxcnc_program_the_pass_does_not_take_verifies_as_read_whole(tmp_path, monkeypatch, make,
                                                                                    n):
    # mill.toml: steps of up to 600 mm leave the travel now and then (the long programs have violations)
    text = make(n, 9 + n, spread=60.0)
    path = tmp_path / "p.ngc"
    path.write_text(text)
    whole = _outcome(verify_source(S.load_program(path), MILL, VerifyOptions()))
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    monkeypatch.setattr(S, "WINDOW_BYTES", 64)

    def refuse(self):
        raise AssertionError("the whole text was read")

    if n >= 512:  # a shorter program is read by the full interpreter alone, on its whole text
        monkeypatch.setattr(S.FileText, "read_all", refuse)
    src = S.load_program(path, stream=True)
    assert isinstance(src.text, S.FileText)
    assert _outcome(verify_source(src, MILL, VerifyOptions())) == whole
    assert n < 600 or whole[1]


def test_a_file_text_cut_and_searched_backwards(tmp_path, monkeypatch):
    # FileText.rfind and FileText.head (the % cut of a streamed file) answer as the str of the file does
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    rnd = random.Random(3)
    text = "".join(rnd.choice("G1X.5\n %") for _ in range(300))
    path = tmp_path / "p.nc"
    path.write_text(text)
    for window in (1, 7, 64):
        monkeypatch.setattr(S, "WINDOW_BYTES", window)
        ft = S.load_program(path, stream=True).text
        for _ in range(200):
            a, b = rnd.randint(-5, 305), rnd.choice([None, rnd.randint(-5, 305)])
            sub = rnd.choice(["\n", "%", "G1", "\nG", "X.5\n"])
            assert ft.rfind(sub, a, b) == text.rfind(sub, a, b), (window, sub, a, b)
            k = b if b is not None and b >= 0 else 400
            head, cut = ft.head(k), text[:k]
            assert len(head) == len(cut) and head.read_all() == cut and head.find(sub, a) == cut.find(sub, a)


@pytest.mark.parametrize("text", ["%\n\n$1\nG0 X1.\n$2\nG0 Z1.\n$0\n#500=1\n%\n", "%\nO1\n$1\nG0 X1.\n",
                                  "\n \n%\n", "G0 X1.\n$2\n", "", "$1"])
def test_path_headers_of_a_streamed_file(tmp_path, monkeypatch, text):
    monkeypatch.setattr(S, "STREAM_MIN_BYTES", 0)
    monkeypatch.setattr(S, "WINDOW_BYTES", 3)
    path = tmp_path / "p.nc"
    path.write_text(text)
    src = S.load_program(path, stream=True)
    assert path_headers(src.text) == path_headers(text)
