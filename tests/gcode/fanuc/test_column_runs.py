"""The Fanuc full interpreter's runs of straight moves reach the proof as column chunks (issue 36).

:func:`nczones.gcode.fanuc.columns.column_runs` turns each run of plain lines and rapids into a column chunk
that keeps its segments: the columns must be the exact image of the segments (every coordinate and tool
length times ``10**SCALE``), ``segments()`` must give the interpreter's own segments in order, and
``verify`` must decide exactly as when every motion went one by one (``MIN_RUN`` above any run: the path
before this lane): the same verdict, violations (block, zone, point, first exit, span) and reasons, on
WHILE loops, G65 and M98 calls, G20/G21 switches, exact stops and dwells that cut the runs, a zone face the
motion touches and one it crosses, short programs and programs of more than 512 motions.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.gcode.fanuc import columns
from nczones.machine import parse_machine
from nczones.motion import MotionChunk
from nczones.prover import verify_text

from .helpers import MILL

# the test mill (G54 = (100, 50, -200) plus EXT Z 1, no tool length): program X50. is machine X 150, Y40. is
# machine Y 90, Y-60. is machine Y -10, Z-2. is machine Z -201.  The box's faces are at machine X -10 and 150,
# Y -10 and 90, Z -201 and 0 (the reference position 0, 0, 0 inside): a move to X50., Y40., Y-60. or Z-2.
# touches a face (safe: the zone is closed), X50.001, Y40.001, Y-60.001 or Z-2.001 crosses one (unsafe).
_ZONE = ('\n[[zones]]\nname = "box"\nkind = "box"\nmin = { X = "-10", Y = "-10", Z = "-201" }\n'
         'max = { X = "150", Y = "90", Z = "0" }\n')


def _machine(tolerance: str = ""):
    text = MILL.replace("{fanuc_extra}", "").replace("{tables}", _ZONE)
    if tolerance:
        text = text.replace('name = "fanuc test mill"', f'name = "fanuc test mill"\npath_tolerance = "{tolerance}"')
    return parse_machine(text, "mill.toml")


_MOVES = [
    "G01 X[#1 * 0.5] Y[#1 * 0.25]",
    "G00 X#24 Y#25",  # the G65 arguments (vacant in the loop and M98 bodies: the word is dropped)
    "G01 Z-1.",
    "G01 Z-2.",
    "Z-0.5",
    "G01 X50. Y40.",
    "X0. Y0.",
    "G00 Z0.",
    "G01 X[#1 * 3.7] Y[10 + #1 * 0.01]",
    "X1.2345",  # four decimals: exact in G20 input, rounded to 1.235 in G21
    "G20",
    "X0.5 Y0.25",
    "G21",
    "G61",
    "G64",
    "G09 G01 X10. Y10.",
    "G04 X0.1",
    "G01 Y-60.",
    "G01 X[#1 + 0.0005] Y[#1 / 3]",  # rounded to the increment; binary doubles
]
_OUT = ["G01 X50.001", "G01 Y40.001", "G01 Y-60.001", "G01 Z-2.001", "G00 X[60 - #1 * 0.001]"]


def _program(body: list[str], reps: int, form: str) -> str:
    head = ["O1000", "G90 G17 G21 G54 F500.", "#1 = 0"]
    if form == "while":
        lines = head + [f"WHILE [#1 LT {reps}] DO1", *body, "#1 = #1 + 1", "END1", "M30"]
    elif form == "m98":
        lines = head + [f"WHILE [#1 LT {reps}] DO1", "M98 P9020", "#1 = #1 + 1", "END1", "M30", "O9020", *body,
                        "M99"]
    else:  # a G65 call per iteration: X Y arguments are #24 #25, the body sees its own #1 (A) too
        lines = head + ["#2 = 0", f"WHILE [#2 LT {reps}] DO1", "G65 P9010 A#2 X[#2 * 0.7] Y[#2 * 0.3]",
                        "#2 = #2 + 1", "END1", "M30", "O9010", *body, "M99"]
    return "\n".join(lines) + "\n"


def _summary(result) -> tuple:
    return (result.verdict.label, tuple(result.violations), tuple(result.reasons), result.truncated)


def _both(text: str, machine) -> tuple:
    """The verify result with every run as columns (MIN_RUN 1, from the first motion on) and with none (the
    one-by-one path)."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(columns, "MIN_RUN", 1)
        mp.setattr(columns, "START", 0)
        with_columns = verify_text(text, machine)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(columns, "MIN_RUN", 10**9)
        one_by_one = verify_text(text, machine)
    return with_columns, one_by_one


_MACHINES = {"": _machine(), "0.05": _machine("0.05")}


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(_MOVES), min_size=1, max_size=6), st.lists(st.sampled_from(_OUT), max_size=1),
       st.integers(1, 5), st.sampled_from(["while", "m98", "g65"]), st.sampled_from(["", "0.05"]),
       st.randoms(use_true_random=False))
def test_columns_decide_as_one_by_one(body, out, reps, form, tolerance, rnd):
    """Short loops: every lane of the corner check (cutting mode hull, path tolerance, exact stop) and the
    proof, with and without the column runs: the same result."""
    body = body + out
    rnd.shuffle(body)
    a, b = _both(_program(body, reps, form), _MACHINES[tolerance])
    assert _summary(a) == _summary(b)


@pytest.mark.parametrize("form", ["while", "m98", "g65"])
@pytest.mark.parametrize("crossing", [False, True])
def test_long_loops_decide_as_one_by_one(form, crossing):
    """More than 512 motions (the proof's vectorized tier) with the default MIN_RUN: a circle that touches
    the box's X face (machine X = 100 + 25 + 25 COS[#1 * 10] reaches 150 exactly when the angle is a multiple
    of 360 degrees: the doubles' cosine is 1.0 there), its Z face (Z-2.) and, with ``crossing``, a spiral that
    passes the X face (radius 25 + #1 * 0.001: X 150.036 at #1 = 36)."""
    radius = "[25 + #1 * 0.001]" if crossing else "25"
    body = [f"G01 X[25 + {radius} * COS[#1 * 10]] Y[20 + 20 * SIN[#1 * 10]]", "G01 Z-2.", "Z0."]
    text = _program(body, 400, form)
    m = _MACHINES[""]
    a, b = _both(text, m)
    assert dict(a.stats)["segments"] > 512
    assert _summary(a) == _summary(b)
    assert a.verdict.label == ("unsafe" if crossing else "safe")
    if form == "while":  # the default MIN_RUN and START: the runs after the first 512 motions as columns
        assert _summary(verify_text(text, m)) == _summary(b)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(_MOVES + _OUT), min_size=1, max_size=6), st.integers(1, 40),
       st.sampled_from(["while", "m98", "g65"]))
def test_column_chunks_are_the_segments(body, reps, form):
    """The chunks column_runs gives hold the interpretation's segments in order, each column chunk's rows the
    exact image of its segments."""
    machine = _machine()
    text = _program(body, reps, form)
    plain = [s for s in interpret_text(text, machine).segments()]
    run = interpret_text(text, machine)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(columns, "START", 0)
        out = list(columns.column_runs(run, run.interpreter.axes, run.interpreter.file))
    got = [s for c in out for s in c.segments()]
    assert got == plain
    den = 10**columns.SCALE
    for c in out:
        if isinstance(c, MotionChunk) and c.scale is not None and c.objects is not None:
            assert c.scale == columns.SCALE and len(c) == len(c.objects) >= columns.MIN_RUN
            for k, seg in enumerate(c.objects):
                assert [Fraction(int(v), den) for v in c.start[k]] == list(seg.start)
                assert [Fraction(int(v), den) for v in c.end[k]] == list(seg.end)
                assert Fraction(int(c.tool_length[k]), den) == seg.tool_length
                assert (int(c.kind[k]), int(c.block[k]), int(c.line[k])) == (int(seg.kind), seg.block,
                                                                           seg.span.line)
                # a row view of the chunk is the segment itself (spans, feeds, frames kept)
                assert next(c.rows(k, k + 1).segments()) is seg


def test_runs_are_taken_as_columns():
    """The lane is taken: a loop of 1,000 moves reaches the proof in column chunks after its first START
    motions (the interpreter's chunks of 128 that hold them stay objects)."""
    machine = _machine()
    text = _program(["G01 X[#1 * 0.01] Y[#1 * 0.02]", "G00 Z0."], 500, "m98")
    run = interpret_text(text, machine)
    out = list(columns.column_runs(run, run.interpreter.axes, run.interpreter.file))
    rows = sum(len(c) for c in out if isinstance(c, MotionChunk) and c.scale is not None)
    assert rows == 1000 - columns.START


def test_parameter_ranges_keep_the_one_by_one_path(monkeypatch):
    """With a parameter range the corner check widens every box by it (its one-motion path); the column
    runs are not taken (540 motions, past START): G54.X within ±0.002 of 100 moves the circle of the long test by
    as much, so its touch of the X face becomes a crossing (unsafe), and the result is the one-by-one path's."""
    m = _MACHINES[""]
    text = _program(["G01 X[25 + 25 * COS[#1 * 10]] Y[20 + 20 * SIN[#1 * 10]]", "G01 Z-1.", "Z0."], 180, "while")
    taken: list[int] = []
    real = columns.column_runs

    def spy(chunks, axes, file):
        taken.append(1)
        return real(chunks, axes, file)

    monkeypatch.setattr(columns, "column_runs", spy)
    ranged = verify_text(text, m, params=["G54.X=-0.002..0.002"])
    assert not taken
    assert ranged.verdict.label == "unsafe"
    assert verify_text(text, m).verdict.label == "safe" and taken  # without the range: the column runs


# ---------------------------------------------------------------------------------------------------------------
# The lane writes rows (issue 36, fourth step): with ``column_runs`` the Fanuc interpreter's plain lane writes its
# straight moves as column rows (``columns.Rows``), building a segment only when one is read.  Held to the path
# where every motion is a segment (``columns.DIRECT`` off), one by one (MIN_RUN above any run).


def _rows_and_segments(text: str, machine, start: int | None = None, min_run: int | None = None) -> tuple:
    """verify with the lane's rows (``START``/``MIN_RUN`` as given, else the defaults) and with every motion a
    segment proved one by one (``DIRECT`` off, ``MIN_RUN`` above any run)."""
    with pytest.MonkeyPatch.context() as mp:
        if start is not None:
            mp.setattr(columns, "START", start)
        if min_run is not None:
            mp.setattr(columns, "MIN_RUN", min_run)
        rows = verify_text(text, machine)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(columns, "DIRECT", False)
        mp.setattr(columns, "MIN_RUN", 10**9)
        segments = verify_text(text, machine)
    return rows, segments


def _full(result) -> tuple:
    """Verdict, violations (block, zone, point, first exit, span), reasons, truncation and the motion counted
    (unless the violations were truncated: a chunk of rows the screen proves at once may run past the motion
    where the proof stopped, and its rows are counted as checked, which they were)."""
    return _summary(result) + (None if result.truncated else dict(result.stats)["segments"],)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(_MOVES), min_size=1, max_size=6), st.lists(st.sampled_from(_OUT), max_size=1),
       st.integers(1, 6), st.sampled_from(["while", "m98", "g65"]), st.sampled_from(["", "0.05"]),
       st.sampled_from([(0, 1), (0, 4), (None, None)]), st.randoms(use_true_random=False))
def test_rows_decide_as_segments_one_by_one(body, out, reps, form, tolerance, lane, rnd):
    """Short loops (WHILE, M98 and G65 bodies with G20/G21, G61/G64/G09, dwells, a face touched or crossed by
    0.001 on X, Y or Z): the rows written by the lane (as columns from the first motion, in runs of 1 or 4 rows
    or more, or with the defaults, where they stay objects) decide as the segments one by one."""
    body = body + out
    rnd.shuffle(body)
    a, b = _rows_and_segments(_program(body, reps, form), _MACHINES[tolerance], *lane)
    assert _full(a) == _full(b)


def test_rows_past_the_twentieth_violation_decide_as_segments():
    """A loop whose every pass leaves the box five times: the proof stops at ``max_violations`` inside a chunk
    of rows the screen proved at once (it counts one motion more than the one-by-one path: ``_full``), with
    the same violations, reasons and truncation (a Hypothesis find of ``test_rows_decide_as_segments_one_by_one``)."""
    body = ["G01 X[#1 * 0.5] Y[#1 * 0.25]", "G01 Y-60.001", "G01 Z-1.", "X1.2345", "G01 Z-1.",
            "G01 X[#1 * 0.5] Y[#1 * 0.25]"]
    a, b = _rows_and_segments(_program(body, 6, "while"), _MACHINES[""], 0, 1)
    assert a.truncated and len(a.violations) == 20
    assert _full(a) == _full(b)


# The face a move touches (program coordinates on the test mill, from the machine faces above: X50. is machine
# X 150, Y40. is machine Y 90; on Z the work offset is G54's -200 plus EXT's 1, so Z-2. is machine Z -201) and
# the sign that takes it outside.
_FACES = {"X": ("50.", 1), "Y": ("40.", 1), "Z": ("-2.", -1)}


@pytest.mark.parametrize("form", ["while", "m98", "g65"])
@pytest.mark.parametrize("axis", ["X", "Y", "Z"])
@pytest.mark.parametrize("delta", ["0", "0.001"])
def test_long_rows_touch_and_cross_a_face(form, axis, delta):
    """300 iterations of two moves (600 motions: past the proof's 512 and the lane's START, so rows with the
    default settings): iteration 290 moves to the face (``delta`` 0: it touches it, the zone is closed: safe)
    or 0.001 past it (unsafe: that move ends outside and the next one starts there, the violations on those two
    lines); the rows decide as the segments one by one."""
    face, sign = _FACES[axis]
    body = ["#7 = 0", f"IF [#1 EQ 290] THEN #7 = {delta}", f"G01 {axis}[{face} + {sign} * #7]",
            "G01 X[#1 * 0.1] Y[#1 * 0.05] Z0."]
    text = _program(body, 300, form)  # #1: the counter (a G65 body's A argument)
    m = _MACHINES[""]
    a, b = _rows_and_segments(text, m)
    assert dict(a.stats)["segments"] > 512
    assert _full(a) == _full(b)
    if delta == "0":
        assert a.verdict.label == "safe"
    else:
        assert a.verdict.label == "unsafe"
        line = next(i for i, t in enumerate(text.splitlines(), 1) if t.startswith(f"G01 {axis}["))
        assert {v.span.line for v in a.violations} == {line, line + 1}


def test_rows_are_written_by_the_lane():
    """The lane is taken: after START motions a loop's moves reach column_runs as ``Rows`` (no segment built
    for them unless read), and the column chunks made of them are their exact image."""
    machine = _machine()
    text = _program(["G01 X[#1 * 0.01] Y[#1 * 0.02]", "G00 Z0."], 500, "m98")
    plain = list(interpret_text(text, machine).segments())
    run = interpret_text(text, machine)
    out = list(columns.column_runs(run, run.interpreter.axes, run.interpreter.file))
    built = [c for c in out if isinstance(c, MotionChunk) and c.scale is not None]
    assert built and all(type(c.objects).__name__ == "_Built" for c in built)
    assert sum(len(c) for c in built) == 1000 - columns.START
    assert all(s is None for c in built for s in c.objects.segs)  # nothing read yet: nothing built
    last = built[0].objects[-1]  # one row read: that segment alone is built, the same object from then on
    assert sum(s is not None for s in built[0].objects.segs) == 1 and built[0].objects[len(built[0]) - 1] is last
    den = 10**columns.SCALE
    k = 0
    for c in out:
        for i, seg in enumerate(c.segments()):
            assert seg == plain[k]
            if c.scale is not None:
                assert [Fraction(int(v), den) for v in c.start[i]] == list(seg.start)
                assert [Fraction(int(v), den) for v in c.end[i]] == list(seg.end)
                assert next(c.rows(i, i + 1).segments()) is seg
            k += 1
    assert k == len(plain)


_FEEDS = ["G01 X[#1 * 0.2] F[300 + #1]", "Y2. F250.", "G00 X1. F0."]  # F in the lane's blocks


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(_MOVES + _OUT + _FEEDS), min_size=1, max_size=6), st.integers(1, 30),
       st.sampled_from(["while", "m98", "g65"]))
def test_one_call_lane_gives_the_general_lanes_segments(body, reps, form):
    """``FanucInterpreter.lane`` in one call (``fused_lane``) and ``Interpreter.lane``'s steps give the same
    segments, frames, spans and feeds included (a frame is not part of a segment's equality)."""
    machine = _machine()
    text = _program(body, reps, form)

    def motion(fused: bool) -> list:
        run = interpret_text(text, machine)
        run.interpreter.fused_lane = fused
        out: list = []
        try:
            for s in run.segments():
                out.append((s, s.frame, s.span, s.feed_mm_min, s.tool_register))
        except GcodeError as e:  # G1 after F0.: the same error, after the same motion
            out.append(str(e))
        return out

    assert motion(True) == motion(False)
