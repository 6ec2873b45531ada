"""Soundness hunt (hunt36b): a streamed file whose special lines sit at a window edge verifies as read whole.

mem36 streams Fanuc plain programs and LinuxCNC o-word programs from disk a window at a time
(``nczones.gcode.source.FileText``; the fast path's blocks, ``fastpath.BLOCK_BYTES``; the double pass's
pieces, ``doubles.PIECE``).  tests/gcode/test_streamed_source.py and test_streamed_classes.py compare the
streamed and the whole read on CAM-like walks with windows of 64 and 97 bytes.  Here the programs hold what
a window edge could cut wrongly: ``%`` lines (first, in the middle, last, inside a comment), O-numbers and
``:`` program numbers, block-delete lines (``/``, ``/ ``), comments with characters that are not ASCII
(two- and three-byte UTF-8), a 2,000-digit number and a 3,000-character comment, blank and space-only
lines, CRLF line ends, M30/M02 with text after it, o-word sub/endsub/call; and the window is placed so that
its edge falls on (and one byte before and after) such a character.  The outcome (verdict, violations with
their spans, reasons, notes, the program's digest, the motion counted unless the run stopped at the
violation cap) or the error (code, place, message) must be the whole read's.

The fast path's blocks and the double pass's pieces stay at least 4 KiB: in nczones they are 1 MiB, above
the longest line a file may have (``MAX_LINE_CHARS``, 64 KiB); a block shorter than a line is not a state the
program reaches (with blocks of 7 bytes a witness's span loses its end column, and a read-ahead past the
violation cap meets a later error: both seen while building this hunt, both from the block size alone).

CI: two short programs with a dozen edges each; ``-m long``: the counts in specs/contract.md "Where features
meet: hunt36b".
"""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import fastpath
from nczones.gcode import source as S
from nczones.gcode.linuxcnc import doubles
from nczones.machine import load_machine
from nczones.pipeline.verification import verify_source
from nczones.prover.options import VerifyOptions

FANUC = load_machine("specs/machines/fanuc_mill.toml")
MILL = load_machine("specs/machines/mill.toml")

_FANUC_LINES = ["%", "O1000", "O2000 (SUB)", "/G01 X500.", "/ G00 Z900.", "(COMMENT \u00e9 \u00fc)",
                "(\u00c4\u00d6)G01 X1. Y1.", "G01 X2. (NOTE \u2603) Y3.", "N100 G01 X1.5 Y2.5", ":1000", "G04 X0.5",
                "M01", "M00", "(%)", "G01 X1. Y" + "0" * 2000 + "1.", "(" + "A" * 3000 + ")", "", "   ",
                "G01X1.Y2.", "M30", "M02", "G00 X1000.", "G01 Z-1000."]
_LINUXCNC_LINES = ["%", "/G1 X500", "/ G0 Z900", "(COMMENT \u00e9 \u00fc)", "(\u00c4\u00d6)G1 X1 Y1",
                   "G1 X2 (NOTE \u2603) Y3", "N100 G1 X1.5 Y2.5", "G4 P0.5", "M1", "M0", "(%)",
                   "G1 X1 Y" + "0" * 2000 + "1", "(" + "A" * 3000 + ")", "", "   ", "G1X1Y2", "M2", "G0 X1000",
                   "G1 Z-1000", ";comment \u00e9", "(MSG, hi \u00e9)", "o100 sub", "o100 endsub", "o100 call"]
_ENDS = ["M30", "M30\n%", "M30\n\n", "M02\nG01 X900.", "%\nG01 X800.", ""]


def _program(rnd: random.Random, fanuc: bool, n: int, rate: float = 0.04) -> str:
    """``n`` moves in a box of ±50 mm with a special line now and then (``rate``), a head and an end."""
    lines = ["%"] if rnd.random() < 0.5 else []
    if fanuc:
        lines += (["O1000"] if rnd.random() < 0.6 else []) + ["G90 G17 G21 G54", "G00 Z5.", "G01 F800."]
    else:
        lines += ["G21 G90 G17 G54", "G0 Z5", "G1 F800"]
    special = _FANUC_LINES if fanuc else _LINUXCNC_LINES
    for _ in range(n):
        if rnd.random() < rate:
            lines.append(rnd.choice(special))
        else:
            lines.append(f"X{rnd.uniform(-50, 50):.3f} Y{rnd.uniform(-50, 50):.3f}")
    text = "\n".join([*lines, rnd.choice(_ENDS)]) + ("\n" if rnd.random() < 0.9 else "")
    return text.replace("\n", "\r\n") if rnd.random() < 0.15 else text


def _edges(data: bytes) -> list[int]:
    """The offsets of the bytes a window edge could cut wrongly: %, O, :, /, (, a newline, a non-ASCII byte."""
    return [i for i, b in enumerate(data) if b in b"%O:/(\n" or b >= 0x80]


def _outcome(path, stream: bool, machine) -> tuple:
    try:
        r = verify_source(S.load_program(path, stream=stream), machine, VerifyOptions())
    except GcodeError as e:
        d = e.diagnostics[0]
        return "error", d.code, str(d.span), d.message
    return (r.verdict, [(v.block, v.span, v.zone, v.point, v.first_exit, v.kind, v.note) for v in r.violations],
            [(x.message, x.span, x.code) for x in r.reasons], r.notes, r.program_sha256, r.truncated,
            None if r.truncated else dict(r.stats)["segments"])


def _streamed_as_whole(path, text: str, fanuc: bool, windows) -> str:
    data = text.encode("utf-8")
    path.write_bytes(data)
    machine = FANUC if fanuc else MILL
    whole = _outcome(path, False, machine)
    for w in sorted(windows):
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(S, "STREAM_MIN_BYTES", 0)
            mp.setattr(S, "WINDOW_BYTES", w)
            mp.setattr(fastpath, "BLOCK_BYTES", max(w, 4096))
            mp.setattr(doubles, "PIECE", max(w, 4096))
            assert _outcome(path, True, machine) == whole, f"window of {w} bytes"
    return str(whole[0])


def _windows(data: bytes, rnd: random.Random, k: int, fixed: tuple = (1, 2, 3, 64, 97)) -> set[int]:
    """Windows whose first edge falls on ``k`` drawn special bytes, one byte before them and one after, and
    the ``fixed`` ones."""
    edges = _edges(data) or [10]
    out = set(fixed)
    for e in rnd.sample(edges, min(k, len(edges))):
        out.update(x for x in (e - 1, e, e + 1) if x > 0)
    return out


_ENDERS = {"%", "M30", "M02", "M2", "M0", "M00", "o100 call"}


def _every_special_line(fanuc: bool) -> str:
    """Each special line that does not end or stop the program, between two moves, then the end."""
    rnd = random.Random(1)
    lines = ["%", "O1000", "G90 G17 G21 G54", "G00 Z5.", "G01 F800."] if fanuc else \
        ["%", "G21 G90 G17 G54", "G0 Z5", "G1 F800"]
    for special in (_FANUC_LINES if fanuc else _LINUXCNC_LINES):
        if special not in _ENDERS and not special.startswith("O2000"):
            lines += [f"X{rnd.uniform(-50, 50):.3f} Y{rnd.uniform(-50, 50):.3f}", special]
    return "\n".join([*lines, "M30", "%"]) + "\n"


@pytest.mark.parametrize("fanuc, seed, k", [(True, 3, 3), (False, 8, 1)])  # a LinuxCNC run costs ~1 s here
def test_special_lines_at_a_window_edge(tmp_path, fanuc, seed, k):
    text = _every_special_line(fanuc)
    _streamed_as_whole(tmp_path / ("p.nc" if fanuc else "p.ngc"), text, fanuc,
                       _windows(text.encode("utf-8"), random.Random(seed), k, (64,)))


OUTCOMES: dict[str, int] = {}


@pytest.mark.long
@settings(max_examples=150, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(st.integers(0, 10**9), st.booleans(), st.sampled_from([10, 40, 600]))
def test_special_lines_at_a_window_edge_long(tmp_path_factory, seed, fanuc, n):
    rnd = random.Random(seed)
    text = _program(rnd, fanuc, n)
    path = tmp_path_factory.mktemp("edge") / ("p.nc" if fanuc else "p.ngc")
    got = _streamed_as_whole(path, text, fanuc, _windows(text.encode("utf-8"), rnd, 6))
    key = f"{'fanuc' if fanuc else 'linuxcnc'} {n}: {got}"
    OUTCOMES[key] = OUTCOMES.get(key, 0) + 1


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    if OUTCOMES:
        print("\nhunt36b streamed edges:", dict(sorted(OUTCOMES.items())))
