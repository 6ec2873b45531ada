"""Soundness hunt (hunt36b): the Fanuc line closures and the one-call plain lane's column rows against the
general path, on programs the lanes' own tests do not generate.

tests/gcode/fanuc/test_line_closures.py and test_column_runs.py hold the closures (``FanucRunner.make_op``)
and the rows (``FanucInterpreter.lane`` writing ``columns.Rows``) to the general path on loops of plain
moves, macro expressions, calls and unit switches.  Here the loop bodies, subprograms and macros also hold
what changes the frame a plain move is read in: G91, G68 rotation, G51 scaling, G51.1/G50.1 mirror, work
offsets changed inside the loop (G10 L2 / L20, G54-G59, G54.1, G52, G92, G92.1, the offset variables
#5201-#5243), tool lengths (G43/G49, G10 L10, #2001 / #11001), G20 in a subprogram, system variables read in
the loop (#5001-#5043, #4001-#4014), M99 P and GOTO out of the loop, loops made by a backward GOTO, nested G65 with locals, DPRNT, G28/G30/G53.

Relations (each side computed by nczones, no answer copied from the code under test):

1. the closures on and off (``FanucRunner.add_op`` keeping nothing: every line through the general path)
   give the same interpretation: every segment (kind, ends, feed, block, span, tool length and register, and
   its program frame, which a segment's equality leaves out and the solids proof reads),
   the status and the reasons of an ``unknown``, or the same error;
2. the one-call lane on and off (``fused_lane``) give the same segments;
3. ``verify`` with the lane's rows as columns from the first motion (``START`` 0, ``MIN_RUN`` 1), with the
   defaults, and with every motion a segment proved one by one (``DIRECT`` off, ``MIN_RUN`` above any run),
   closures on and off: the same verdict, violations, reasons and motion count (a run stopped at the
   violation cap counts the motion read before it stopped, which depends on the lane's chunking: not
   compared then);
4. a WHILE loop or a backward GOTO loop (``N10 ... IF [#1 LT n] GOTO 10``; the body without a jump out of it,
   GOTO or M99 P) and the same lines written out once per iteration: the same segments
   (kind, ends, feed, tool length, frame) and the same verdict and violations (zone, point).

The zone: the test mill's box (machine X -10..150, Y -10..90, Z -201..0) that program X50. / Y40. touch
and X50.001 / Y-60.001 cross.  CI: a few examples; ``-m long``: the counts in specs/contract.md "Where
features meet: hunt36b".
"""

from __future__ import annotations

from contextlib import contextmanager

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.gcode.fanuc import columns
from nczones.gcode.fanuc.program import FanucRunner
from nczones.machine import parse_machine
from nczones.prover import verify_text

from .helpers import MILL

_ZONE = ('\n[[zones]]\nname = "box"\nkind = "box"\nmin = { X = "-10", Y = "-10", Z = "-201" }\n'
         'max = { X = "150", Y = "90", Z = "0" }\n')
_MACHINE = parse_machine(MILL.replace("{fanuc_extra}", "").replace("{tables}", _ZONE), "mill.toml")


@contextmanager
def _general_path_only():
    """Every line through the general path: no line is kept as a closure."""
    original = FanucRunner.add_op

    def none(self, source, pos, lineno, entry):
        source.ops[pos] = None

    FanucRunner.add_op = none  # type: ignore[method-assign]
    try:
        yield
    finally:
        FanucRunner.add_op = original  # type: ignore[method-assign]


_BODY = [
    "G91 G01 X0.5 Y0.25", "G90", "G91", "G01 X[#1 * 0.3] Y[#1 * 0.2]", "G00 X1. Y2.", "X[#1] Y[#1 * 0.5]",
    "G68 X0 Y0 R[#1 * 10]", "G69", "G51 X0 Y0 P2.", "G51 X0 Y0 P500", "G50", "G51.1 X10.", "G50.1 X0",
    "G10 L2 P2 X[100 + #1] Y55. Z-200.", "G55", "G54", "G56", "G52 X[#1] Y1.", "G52 X0 Y0",
    "G43 H1 Z10.", "G49", "G43 H2 Z5.", "G49 G00 Z0.", "#30 = #5041", "#31 = #5042 + #5043",
    "G01 X[#5041 * 0.1] Y[#5002 * 0.1]", "#32 = #5021", "G01 X[#32 * 0.01]",
    "M98 P9020", "G65 P9010 A[#1] X[#1] Y1.", "DPRNT[X#1[44]]", "IF [#1 EQ 3] GOTO 70",
    "G01 Z-1.", "G00 Z0.", "G04 X0.1", "G20", "G21", "G92 X[#1] Y0", "G92.1 X0 Y0",
    "#3 = #1 * 2", "G01 X#3", "G61", "G64", "G09 G01 X5. Y5.", "M99 P70",
    "#[#1 + 100] = #1", "G01 X#[#1 + 100]", "G53 G00 Z0.",
    "G01 X50. Y40.", "G01 X50.001", "G01 Y-60.001",
    "#5221 = 100 + #1", "#5222 = 50 + #1 * 0.1", "#5223 = -200 + #1 * 0.01", "#5241 = 300 + #1",
    "#2001 = 100 + #1", "#11001 = 100 + #1 * 0.5", "G10 L10 P1 R[100 + #1]", "G43 H1 Z[#1 * 0.1]",
    "#35 = #4003", "#36 = #4014", "IF [#4003 EQ 91] THEN #38 = 1", "G01 X[#4001 * 0.01]",
    "G54.1 P3", "G10 L20 P3 X[500 + #1] Y20. Z-210.", "M98 P9020 L2", "#3003 = 1", "#3004 = 2",
    "G01 X[#5001 + 1] Y[#5002 + 1]", "G91 G01 X[#5041 * 0.001]", "G90 G01 X#5201", "#5201 = #1",
    "G28 X0 Y0", "G30 P2 Z0",
]
_SUB = ["#5221 = 100 + #1 * 0.2", "G43 H2 Z1.", "#35 = #4003", "G91", "G20", "G01 X0.1 Y0.2", "G21",
        "G91 G01 X1.", "G90", "G01 X[#1] Y[#1 * 0.3]", "M99 P70", "G65 P9030 A[#1 + 1]", "#1 = #1",
        "G68 X0 Y0 R30.", "G69", "G52 X2.", "G43 H1 Z0.", "G49", "G01 Z-1.", "#33 = #5041", "G01 Y[#33 * 0.05]",
        "G10 L2 P1 X[100 + #1 * 0.1] Y50. Z-200."]
_MACRO = ["G00 X#24 Y#25", "G01 X[#1] Y[#1 * 0.5]", "#1 = #1 + 1", "G65 P9030 A[#1 * 2]", "G91 G01 X#1", "G90",
          "M99 P70", "G20", "G21", "G01 X#1", "#34 = #5041", "G01 Y[#34 * 0.02]", "G51 X0 Y0 P1.5", "G50"]
_INNER = ["G01 X[#1 * 0.2] Y#1", "#1 = #1 + 1", "G91 G01 X0.1", "G90"]
#: plain moves (the lanes' own blocks), drawn as often as the rest together: most frame changes above leave
#: the lane (an unknown, an active transform) or take the block to the general path, so without them the
#: closures and the rows would rarely meet a changed frame
_PLAIN = ["X[#1 * 0.5] Y[#1 * 0.25]", "G01 X[#1 * 0.3] Y2.", "G00 X1. Y2.", "X3. Y[#1]", "G01 Z-1.", "Z0.",
          "X50. Y40.", "X50.001", "Y-60.001", "X[#1 * 0.1] Y[#5042 * 0.01]", "G01 X#24 Y#25"]
#: a frame change with plain moves in it and its cancel (the lane declines inside, takes the moves after)
_FRAMES = ["G68 X0 Y0 R[#1 * 10]\nX5. Y5.\nG69", "G51 X0 Y0 P2.\nX3. Y3.\nG50", "G51.1 X10.\nX4. Y1.\nG50.1 X0",
           "G91\nX0.5 Y0.25\nG00 X-0.5\nG90", "G20\nX0.1 Y0.2\nG21", "G43 H1 Z10.\nX1. Y1.\nG49",
           "G52 X[#1] Y1.\nX2. Y2.\nG52 X0 Y0", "G55\nX1. Y1.\nG54", "#5221 = 100 + #1\nX1. Y1.",
           "G10 L2 P1 X[100 + #1 * 0.1] Y50. Z-200.\nX2. Y1.", "G92 X[#1] Y0\nX1. Y1.\nG92.1 X0 Y0"]
_JUMPS = ("GOTO", "M99 P")


def _parts(body: list[str], sub: list[str], macro: list[str], inner: list[str]) -> tuple[list[str], list[str]]:
    head = ["O1000", "G90 G17 G21 G54 F500.", "#1 = 0", "#100 = 0"]
    tail = ["N70 G01 X1. Y1.", "M30", "O9020", *sub, "M99", "O9010", *macro, "M99", "O9030", *inner, "M99"]
    return head, tail


def _program(body: list[str], sub: list[str], macro: list[str], inner: list[str], reps: int,
             form: str = "while") -> str:
    """The loop as a WHILE, or as a backward GOTO (the lines met again are the same closures)."""
    head, tail = _parts(body, sub, macro, inner)
    if form == "goto":
        loop = ["N10 #28 = #1", *body, "#1 = #1 + 1", f"IF [#1 LT {reps}] GOTO 10"]
    else:
        loop = [f"WHILE [#1 LT {reps}] DO1", *body, "#1 = #1 + 1", "END1"]
    return "\n".join([*head, *loop, *tail]) + "\n"


def _written_out(body: list[str], sub: list[str], macro: list[str], inner: list[str], reps: int,
                 form: str = "while") -> str:
    head, tail = _parts(body, sub, macro, inner)
    lines = list(head)
    for _ in range(reps):
        lines += ([] if form == "while" else ["#28 = #1"]) + [*body, "#1 = #1 + 1"]
    return "\n".join([*lines, *tail]) + "\n"


def _pieces(jumps: bool):
    def keep(xs: list[str]) -> list[str]:
        return xs if jumps else [x for x in xs if not any(j in x for j in _JUMPS)]

    line = st.one_of(st.sampled_from(keep(_BODY)), st.sampled_from(_FRAMES), st.sampled_from(_PLAIN))
    return (st.lists(line, min_size=1, max_size=8),
            st.lists(st.sampled_from(keep(_SUB) + _PLAIN + _FRAMES), max_size=4),
            st.lists(st.sampled_from(keep(_MACRO) + _PLAIN + _FRAMES), max_size=4),
            st.lists(st.sampled_from(_INNER), max_size=3), st.sampled_from([2, 3, 5, 8, 40, 200]),
            st.sampled_from(["while", "goto"]))


def _interpretation(text: str, fused: bool = True) -> tuple:
    try:
        run = interpret_text(text, _MACHINE, file="t.nc", max_loop_iterations=1000, chunk_size=7)
        run.interpreter.fused_lane = fused
        # the frame too: the solids proof places a fixture that moves with a work offset by it
        segs = [(s.kind, s.start, s.end, s.feed_mm_min, s.block, str(s.span), s.tool_length, s.tool_register,
                 s.frame) for s in run.segments()]
        return segs, run.status, [str(u) for u in run.unsupported]
    except GcodeError as e:
        return "error", [(d.code, d.message, str(d.span)) for d in e.diagnostics]


def _verified(text: str, start: int | None = None, min_run: int | None = None, direct: bool = True) -> tuple:
    with pytest.MonkeyPatch.context() as mp:
        if start is not None:
            mp.setattr(columns, "START", start)
        if min_run is not None:
            mp.setattr(columns, "MIN_RUN", min_run)
        mp.setattr(columns, "DIRECT", direct)
        try:
            r = verify_text(text, _MACHINE, file="t.nc")
        except GcodeError as e:
            return "error", [(d.code, d.message, str(d.span)) for d in e.diagnostics]
    return (r.verdict.label, tuple(r.violations), tuple(r.reasons), r.truncated,
            None if r.truncated else dict(r.stats)["segments"])


def _lanes_agree(text: str) -> str:
    closures = _interpretation(text)
    with _general_path_only():
        assert _interpretation(text) == closures, "closures on / off"
    assert _interpretation(text, fused=False) == closures, "one-call lane on / off"
    one_by_one = _verified(text, None, 10**9, direct=False)
    assert _verified(text, 0, 1) == one_by_one, "rows as columns from the first motion"
    assert _verified(text) == one_by_one, "the defaults"
    with _general_path_only():
        assert _verified(text, None, 10**9, direct=False) == one_by_one, "closures off, one by one"
    return str(one_by_one[0])


def _as_written_out(parts: tuple) -> str:
    def motion(text: str) -> tuple:
        try:
            run = interpret_text(text, _MACHINE, file="t.nc", max_loop_iterations=100000)
            return [(s.kind, s.start, s.end, s.feed_mm_min, s.tool_length, s.frame)
                    for s in run.segments()], run.status
        except GcodeError as e:
            return "error", [d.code for d in e.diagnostics]

    def verdict(text: str) -> tuple:
        try:
            r = verify_text(text, _MACHINE, file="t.nc")
        except GcodeError as e:
            return "error", [d.code for d in e.diagnostics]
        return r.verdict.label, [(v.zone, v.point) for v in r.violations], [x.code for x in r.reasons]

    loop, written = _program(*parts), _written_out(*parts)
    assert motion(loop) == motion(written)
    got = verdict(loop)
    assert got == verdict(written)
    return str(got[0])


_SETTINGS = dict(deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])


@settings(max_examples=12, **_SETTINGS)  # type: ignore[arg-type]
@given(*_pieces(jumps=True))
def test_closures_and_rows_agree_with_the_general_path(body, sub, macro, inner, reps, form):
    _lanes_agree(_program(body, sub, macro, inner, reps, form))


@settings(max_examples=6, **_SETTINGS)  # type: ignore[arg-type]
@given(*_pieces(jumps=False))
def test_a_loop_decides_as_its_lines_written_out(body, sub, macro, inner, reps, form):
    _as_written_out((body, sub, macro, inner, reps, form))


#: what the long runs met (printed by -s): verdicts per relation
OUTCOMES: dict[tuple[str, str], int] = {}


@pytest.mark.long
@settings(max_examples=1500, **_SETTINGS)  # type: ignore[arg-type]
@given(*_pieces(jumps=True))
def test_closures_and_rows_agree_with_the_general_path_long(body, sub, macro, inner, reps, form):
    key = ("lanes", _lanes_agree(_program(body, sub, macro, inner, reps, form)))
    OUTCOMES[key] = OUTCOMES.get(key, 0) + 1


@pytest.mark.long
@settings(max_examples=800, **_SETTINGS)  # type: ignore[arg-type]
@given(*_pieces(jumps=False))
def test_a_loop_decides_as_its_lines_written_out_long(body, sub, macro, inner, reps, form):
    key = ("written out", _as_written_out((body, sub, macro, inner, reps, form)))
    OUTCOMES[key] = OUTCOMES.get(key, 0) + 1


@pytest.fixture(scope="module", autouse=True)
def _report():
    """Print what the long runs met (pytest -s)."""
    yield
    if OUTCOMES:
        print("\nhunt36b lanes:", dict(sorted(OUTCOMES.items())))
