"""A Fanuc line that runs again is one closure (issue 36): it must do exactly what the general path does.

:meth:`nczones.gcode.fanuc.program.FanucRunner.make_op` keeps a line met a second time (a loop body, a
subprogram, a macro) as one closure per line kind: an assignment to a numbered local or common variable,
``IF [..] THEN`` one assignment, the ``WHILE`` head (its END found once), ``END``, an NC line with
expressions, a plain line, a bare ``M99``, ``M98 P<n>`` and ``G65 P<n> [L<n>]`` with its argument letters
mapped to variables once.  A closure hands the line back to the general path, having changed nothing, wherever
that path must decide (the first entry of a loop, an error to report, the loop bound or the budget, a vacant
``I``/``J``/``K`` argument that moves the later sets up, G66, a literal rounded or noted per execution).

The reference is the same run with the closures switched off (every line through the general path, as
before this change) and, for ``verify``, the same lines written out once each (a line that runs once never
becomes a closure).  Compared: every segment (kind, ends, feed, block, span), the status and the reason of
an ``unknown``, every error (code, message, span), the language layer's blocks (letters, exact values,
spans, indexes) with no plain-move lane (so each closure's declined path yields the block) and its counters
(decimal point input words, rounded literals, alarms, jumps), the variables at the end; and ``verify``'s
verdict and violations on programs of more than 512 motions (the vectorized tier) whose moves touch a zone
face and cross it by 0.001 mm.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from contextlib import contextmanager
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text
from nczones.gcode.fanuc.expr import FanucVariables, round_to
from nczones.gcode.fanuc.program import FanucRunner, iter_blocks
from nczones.gcode.program import UnsupportedGcode
from nczones.machine import parse_machine
from nczones.prover import verify_text

from .helpers import MILL, mill


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


#: custom codes of the machine file (a G code calling a macro, an M code calling a subprogram)
_CUSTOM = '\n[macros]\nG100 = 9010\nM50 = { program = 9020, call = "subprogram" }\n'


def _interpretation(text: str, max_loops: int, custom: bool = False) -> tuple:
    """Segments, status and reason of an interpretation on the test mill, or the error it raised."""
    try:
        # chunks of 7 motions: a closure whose motion fills a chunk must hand it on as the general path does
        run = interpret_text(text, mill(tables=_CUSTOM if custom else ""), file="t.nc", max_loop_iterations=max_loops,
                             chunk_size=7)
        chunks = list(run)
        segs = [(s.kind, s.start, s.end, s.feed_mm_min, s.block, str(s.span), s.span.text if s.span else None)
                for c in chunks for s in c.segments()]
        return segs, [len(c) for c in chunks], run.status, [str(u) for u in run.unsupported]
    except GcodeError as e:
        return "error", [(d.code, d.message, str(d.span)) for d in e.diagnostics]


def _language_layer(text: str, max_loops: int, custom: bool = False) -> tuple:
    """The blocks of the language layer alone (no lane: a closure's block is yielded), its counters and the
    variables at the end (or the error, with what was yielded before it)."""
    variables = FanucVariables()
    out: list = []
    got = []
    try:
        for b in iter_blocks(text, "t.nc", variables=variables, runner_out=out, max_loop_iterations=max_loops,
                             settings=mill(tables=_CUSTOM if custom else "").fanuc):
            got.append((b.letters, b.values, str(b.span), b.span.text, b.index, b.number,
                        [(w.letter, w.value, str(w.span), w.text) for w in b.words]))
        error: list | None = None
    except GcodeError as e:
        error = [(d.code, d.message, str(d.span)) for d in e.diagnostics]
    except UnsupportedGcode as e:
        d = e.diagnostic
        error = [(type(e).__name__, d.code, d.message, str(d.span))]
    r = out[0]
    counters = (r.dpi_count, r.dpi_words, r.rounded_count, r.rounded, r.alarm, r.stops, r.jumps_back, r.index,
                r.started, r.ran, len(r.frames))
    return got, error, counters, list(variables.local), list(variables.common)


def _both(fn: Callable[[str, int, bool], tuple], text: str, max_loops: int, custom: bool = False) -> tuple:
    with _general_path_only():
        before = fn(text, max_loops, custom)
    return before, fn(text, max_loops, custom)


# the main loop's body: assignments (local, common, computed target, vacant), IF-THEN, IF-GOTO forward, moves
# with expressions (vacant words dropped), literals the increment rounds (X1.2345 in G21) or the decimal point
# input notes (X100), unit switches, calls (M98, M98 L, M98 P2xxxx, G65 with arguments I J K, L), a nested
# loop, errors at some iteration (division by zero, an alarm)
_BODY = [
    "#2 = #1 * 0.5",
    "#3 = #2 * COS[#1 * 30]",
    "#100 = #100 + 0.1",
    "#[#1 + 110] = #1 / 3",
    "#4 = #0",
    "#5 = #5 + 1",
    "IF [#1 GT 2] THEN #6 = #1 * 2",
    "IF [#1 EQ 1] THEN #2 = #0",
    "IF [#2 GT 1] GOTO 50",
    "G01 X[#1 * 0.5] Y#2",
    "G00 X#24 Y#25",
    "G01 X#6 Y[#100] F[400 + #1]",
    "G01 Z-#3",
    "X1.2345",
    "X100",
    "G01 X[#1 * 0.0005] Y0.1235",
    "G20",
    "G21",
    "M98 P9020",
    "M98 P9020 L2",
    "M98 P29020",
    "G65 P9010 X[#1 * 0.1] Y#2 I#6 J1. I2. J#4",  # (a K word would take the general path: K of a cycle)
    "G65 P9010 L2 X1. Y[#1]",
    "G65 P9010 A#1 B[#2 + 1] Z-1.",
    "#9 = 0\nWHILE [#9 LT 2] DO2\nG01 X[#9] Y[#1]\n#9 = #9 + 1\nEND2",
    "#8 = 1 / [#1 - 3]",
    "IF [#1 EQ 4] THEN #3000 = 1 (STOPPED)",
    "G01 X-[#1 + 0.25] Y-#4",
    "N60 G01 X2. Y3.",
]
_SUB = ["G01 X[#1 * 0.1] Y[#1 * 0.05]", "G01 Z-2.", "#101 = #101 + 1", "G65 P9010 X#1 Y2.", "X3. Y#0"]
_MACRO = ["G00 X#24 Y#25", "G01 Z-#26", "G01 X[#4 + #5] Y#6", "#1 = #1 * 2", "#100 = #100 + #24", "M98 P9020",
          "G01 X#7 Y#8"]


def _program(body: list[str], sub: list[str], macro: list[str], reps: int) -> str:
    lines = ["O1000", "G90 G17 G21 G54 F500.", "#1 = 0", "#100 = 0", f"WHILE [#1 LT {reps}] DO1", *body,
             "N50 #7 = #7 + 1", "#1 = #1 + 1", "END1", "M30", "O9020", *sub, "M99", "O9010", *macro, "M99"]
    return "\n".join(lines) + "\n"


_programs = st.builds(_program, st.lists(st.sampled_from(_BODY), min_size=1, max_size=8),
                      st.lists(st.sampled_from(_SUB), max_size=3), st.lists(st.sampled_from(_MACRO), max_size=3),
                      st.sampled_from([2, 3, 4, 6]))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_programs, st.sampled_from([3, 12, 1000]))
def test_closures_move_and_fail_as_the_general_path(text, max_loops):
    before, after = _both(_interpretation, text, max_loops)
    assert after == before


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_programs, st.sampled_from([3, 1000]))
def test_closures_yield_the_general_paths_blocks(text, max_loops):
    before, after = _both(_language_layer, text, max_loops)
    assert after == before


def _loop(*body: str, reps: int = 5, sub: tuple = ("G01 Z-2.",), macro: tuple = ("G00 X#24 Y#25",),
          after: tuple = ()) -> str:
    lines = ["O1000", "G90 G17 G21 G54 F500.", "#1 = 0", f"WHILE [#1 LT {reps}] DO1", *body, "#1 = #1 + 1", "END1",
             *after, "M30", "O9020", *sub, "M99", "O9010", *macro, "M99"]
    return "\n".join(lines) + "\n"


#: Each way a closure hands its line back to the general path, and the general path's errors in a loop.
_CASES = {
    "division by zero in an assignment at the 4th iteration": _loop("#8 = 1 / [#1 - 3]"),
    "division by zero in a move": _loop("G01 X[1 / [#1 - 2]] Y1."),
    "an IF whose condition divides by zero": _loop("IF [[1 / [#1 - 2]] GT 0] THEN #3 = 1", "G01 X#3"),
    "an IF whose assignment divides by zero": _loop("IF [#1 GT 1] THEN #3 = 1 / [#1 - 3]", "G01 X#3"),
    "a WHILE condition that divides by zero at the head": _loop("#9 = 0", "WHILE [[1 / [3 - #9]] GT 0] DO2",
                                                                "#9 = #9 + 1", "G01 X#9", "END2"),
    "a word vacant at the 3rd iteration": _loop("#9 = #1 * 2", "IF [#1 EQ 2] THEN #9 = #0", "G01 X#9 Y[#1]"),
    "an I argument vacant at the 3rd iteration (the later sets move up)": _loop(
        "#9 = #1", "IF [#1 EQ 2] THEN #9 = #0", "G65 P9010 I#9 I2. J3. J#9",
        macro=("G01 X#4 Y#7 Z-#5", "G01 X#5 Y#8")),
    "an X argument vacant at the 3rd iteration": _loop("#9 = #1", "IF [#1 EQ 2] THEN #9 = #0", "G65 P9010 X#9 Y1.",
                                                       macro=("G01 X#24 Y#25",)),
    "M98 recursion past 15 levels": _loop("M98 P9020", sub=("G01 X1.", "M98 P9020")),
    "G65 recursion past 5 macro levels": _loop("G65 P9010 X1.", macro=("G01 X#24", "G65 P9010 X[#24 + 1]")),
    "a repeated subprogram and macro": _loop("M98 P9020 L3", "G65 P9010 L2 X[#1] Y1.", "M98 P39020"),
    "an M99 P out of the loop": _loop("G01 Y[#1]", "M98 P9020", sub=("G01 X[#1]", "M99 P60"),
                                      after=("N60 G01 X5.",)),
    "an M98 of a program that is not there": _loop("IF [#1 EQ 3] GOTO 90", "M98 P9020", "N90 M98 P9030"),
    "a jump out of the loop": _loop("G01 X[#1]", "IF [#1 EQ 2] GOTO 70", after=("N70 G01 Y7.", "#1 = 0",
                                                                                "WHILE [#1 LT 3] DO1",
                                                                                "G01 X[#1 * 2]", "#1 = #1 + 1",
                                                                                "END1")),
    "an alarm at the 3rd iteration": _loop("IF [#1 EQ 2] THEN #3000 = 7 (LIMIT)", "G01 X[#1]"),
    "a stop message": _loop("#3006 = 1 (CHECK)", "G01 X[#1]"),
    "a G66 modal call around a loop": "O1000\nG90 G21 G54 F500.\n#1 = 0\nG66 P9010 Z-1.\nWHILE [#1 LT 4] DO1\n"
                                      "G01 X[#1] Y2.\n#1 = #1 + 1\nEND1\nG67\nG01 X0 Y0\nM30\nO9010\n"
                                      "G01 Z#26\nZ0.\nM99\n",
    # X = #1 * 0.00005 is rounded to 0.0001 inch in G20 and to 0.001 mm in G21 (the same line in both)
    "G20 and G21 in the body": _loop("G20", "M98 P9020", "G21", "M98 P9020", sub=("G01 X[#1 * 0.00005] Y1.",)),
    "G20 and G21 around the loop": _loop("IF [#1 EQ 2] GOTO 40", "G01 X[#1 * 0.00005] Y1.", "N40 G20"),
    # X = #1 / 2000 (exact) is rounded to 0.001 mm, halves away from zero, as an argument and as a word
    "arguments and words rounded to the increment": _loop("G65 P9010 X[#1 * 0.0005] Y[#1 / 3]",
                                                          "G01 X[#1 * 0.0005] Y[#1 / 3]",
                                                          macro=("G01 X[#24 * 1000] Y#25",)),
    "decimal point input words and rounded literals": _loop("G01 X100 Y1.2345", "G00 X[#1] Y0"),
    "a nested loop leaving each outer iteration": _loop("#2 = 0", "WHILE [#2 LT #1] DO2", "G01 X[#2] Y[#1]",
                                                        "#2 = #2 + 1", "END2"),
    "an END without its DO": _loop("G01 X[#1]", "IF [#1 EQ 2] GOTO 80", after=("N80 END2",)),
    "computed targets and commons": _loop("#[#1 + 100] = #1 * 0.3", "#500 = #500 + #[#1 + 100]",
                                          "G01 X#500 Y#[#1 + 100]"),
    "the loop bound": _loop("G01 X[#1]", reps=50),
    "custom codes called in the loop": _loop("G100 X[#1] Y2.", "M50", "G01 X[#1] Y[#1]",
                                             macro=("G01 X#24 Y#25",), sub=("G01 Z-1.",)),
}


@pytest.mark.parametrize("name", list(_CASES))
def test_closures_hand_back_as_the_general_path(name):
    custom = "custom" in name
    text = _CASES[name]
    for fn in (_interpretation, _language_layer):
        before, after = _both(fn, text, 20, custom)
        assert after == before


def test_closures_are_taken():
    """The lines of a WHILE loop with a G65 and an M98 call become closures (and the general path alone
    makes none): the comparisons above compare two different paths."""
    text = _program(["#2 = #1 * 0.5", "G01 X[#1 * 0.5] Y#2", "M98 P9020", "G65 P9010 X1. Y[#1]",
                     "IF [#1 GT 2] THEN #6 = #1 * 2"], ["G01 Z-2."], ["G00 X#24 Y#25"], 5)

    def kept() -> int:
        out: list = []
        for _ in iter_blocks(text, "t.nc", runner_out=out):
            pass
        sources = [out[0].main, *out[0].library_sources.values()]
        return sum(op is not None for s in sources for op in s.ops.values())

    # WHILE, the assignment, the move, M98, G65, IF, N50, the increment, END1; G01 Z-2. (plain) and M99 of
    # O9020, G00 X#24 Y#25 and M99 of O9010
    assert kept() == 13
    with _general_path_only():
        assert kept() == 0


# the test mill (G54 = (100, 50, -200), no tool length) with a box whose faces are at machine X 150 (program
# X50.), Y 90 (Y40.) and Z -201 (Z-1.) (as in test_column_runs): a move to X50. touches the X face (safe: the
# zone is closed), X50.001 crosses it by 0.001 mm (unsafe)
_ZONE = ('\n[[zones]]\nname = "box"\nkind = "box"\nmin = { X = "-10", Y = "-10", Z = "-201" }\n'
         'max = { X = "150", Y = "90", Z = "0" }\n')


def _touching(over: str, kind: str, reps: int = 300) -> tuple[str, str]:
    """A loop of ``reps`` iterations (> 512 motions) whose iteration 200 moves to program X = 50 + ``over``
    (the X face, touched or crossed), as a WHILE body, a G65 macro or an M98 subprogram; and the same lines
    written out."""
    head = ["O1000", "G90 G17 G21 G54 F500.", "#1 = 0"]
    # #10: the X of the iteration, 50 + over at #1 = 200, #1 / 10 (below 30) elsewhere
    x = ["#10 = #1 * 0.1", f"IF [#1 EQ 200] THEN #10 = 50 + {over}"]
    if kind == "while":
        body = [*x, "G01 X#10 Y[#1 * 0.05]", "G00 Z-0.5", "G01 Z-1."]
        tail: list[str] = []
    elif kind == "g65":
        body = [*x, "G65 P9010 X#10 Y[#1 * 0.05]"]
        tail = ["O9010", "G01 X#24 Y#25", "G00 Z-0.5", "G01 Z-1.", "M99"]
    else:
        body = [*x, "M98 P9020"]
        tail = ["O9020", "G01 X#10 Y[#1 * 0.05]", "G00 Z-0.5", "G01 Z-1.", "M99"]
    loop = head + [f"WHILE [#1 LT {reps}] DO1", *body, "#1 = #1 + 1", "END1", "M30", *tail]
    unrolled = list(head)
    for _ in range(reps):
        unrolled += [*body, "#1 = #1 + 1"]
    unrolled += ["M30", *tail]
    return "\n".join(loop) + "\n", "\n".join(unrolled) + "\n"


def _summary(text: str) -> tuple:
    machine = parse_machine(MILL.replace("{fanuc_extra}", "").replace("{tables}", _ZONE), "mill.toml")
    r = verify_text(text, machine, file="t.nc")
    return (r.verdict.label, [(v.block, v.zone, v.point, v.first_exit, str(v.span)) for v in r.violations],
            dict(r.stats)["segments"])


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(["while", "g65", "m98"]), st.sampled_from(["0", "0.001"]))
def test_verify_of_a_long_loop_is_that_of_the_lines_written_out(kind, over):
    loop, unrolled = _touching(over, kind)
    got = _summary(loop)
    with _general_path_only():
        general = _summary(loop)
    assert got == general
    # the lines written out: the same motions and violations (their spans are other lines of the text)
    written = _summary(unrolled)
    assert (got[0], [v[:4] for v in got[1]], got[2]) == (written[0], [v[:4] for v in written[1]], written[2])
    assert got[2] > 512
    if over == "0":  # X50. is machine X 150: on the face of the closed box
        assert got[0] == "safe" and not got[1]
    else:  # X50.001 is 0.001 mm outside
        assert got[0] == "unsafe" and got[1]
        assert all(dict(v[2])["X"] > 150 for v in got[1])


def _rounded_exactly(r: Fraction, step: Fraction) -> Fraction:
    """``r`` rounded to a multiple of ``step``, halves away from zero, in rationals."""
    k = r / step
    n = (abs(k) + Fraction(1, 2)).__floor__()
    return (-n if k < 0 else n) * step


def _shown(r: Fraction) -> str:
    from decimal import Decimal

    return format((Decimal(r.numerator) / Decimal(r.denominator)).normalize(), "f")


@settings(max_examples=400, deadline=None)
@given(st.floats(allow_nan=False, allow_infinity=False, min_value=-1e7, max_value=1e7)
       | st.integers(-10**7, 10**7).map(lambda k: k / 2000) | st.integers(-10**6, 10**6).map(lambda k: k * 0.0005),
       st.sampled_from([Fraction(1, 1000), Fraction(1, 10000), Fraction(1), Fraction(1, 10), Fraction(1, 100000),
                        Fraction(3, 1000)]))
def test_round_to_a_double_is_the_rounding_of_every_reading(d, step):
    """round_to of a double without its exact shadow (the doubles' quotient decides away from a half, the
    readings at a half): where the double's 15-digit decimal (the reference's reading) and the double scaled to
    increments in doubles round alike, that multiple, halves away from zero; where they do not, unknown (GC399,
    N5 of test_reference_findings.py) naming both, never a pick.  Away from a half: the double's exact value
    rounded."""
    from nczones.gcode.fanuc.expr import RoundingNotCertain

    fifteen = _rounded_exactly(Fraction(f"{d:.15g}"), step)
    scaled = {_rounded_exactly(Fraction(d * float(1 / step)), Fraction(1)) * step,
              _rounded_exactly(Fraction(d / float(step)), Fraction(1)) * step}
    if scaled == {fifteen}:
        assert round_to((d, None), step) == fifteen
    else:
        with pytest.raises(RoundingNotCertain) as e:
            round_to((d, None), step)
        assert e.value.code == "GC399"
        assert set(re.findall(r"rounds to (-?[\d.]+);", e.value.reason)) == {_shown(r) for r in scaled | {fifteen}}
    k = Fraction(d) / step
    if abs(abs(k - k.__floor__()) - Fraction(1, 2)) > Fraction(1, 10**6) and abs(k) < 2**24:
        assert round_to((d, None), step) == _rounded_exactly(Fraction(d), step)


@settings(max_examples=300, deadline=None)
@given(st.integers(-10**10, 10**10), st.integers(0, 6),
       st.sampled_from([Fraction(1, 1000), Fraction(1, 10000), Fraction(1), Fraction(1, 10), Fraction(1, 100000),
                        Fraction(3, 1000)]))
def test_round_to_a_value_with_its_shadow_is_the_shadow_rounded(n, places, step):
    """round_to of a decimal and its double (a macro value whose exact shadow is kept): the shadow rounded in
    rationals, halves away from zero; unknown (GC399) only within a millionth of an increment of a half, where
    the double's readings can round elsewhere."""
    from nczones.gcode.fanuc.expr import RoundingNotCertain

    q = Fraction(n, 10**places)
    k = abs(q) / step
    try:
        got = round_to((float(q), q), step)
    except RoundingNotCertain:
        assert abs(k - k.__floor__() - Fraction(1, 2)) <= max(Fraction(1, 2**20), k / 2**40)
        return
    assert got == _rounded_exactly(q, step)


@pytest.mark.parametrize("d, step", [(71428.5, Fraction(1, 1000)), (-123456.789, Fraction(1, 1000)),
                                     (9876.54321, Fraction(1, 100000)), (2.0**30 + 0.25, Fraction(1))])
def test_a_large_value_far_from_a_half_is_rounded_without_its_readings(d, step, monkeypatch):
    """Beyond 2**24 increments (16.8 m in IS-B) the window about a half grows with the value (``x 2**-40``);
    a value far from a half is decided by its double quotient, not by comparing every reading (which made the
    G65 loop of 5M lines 3x slower per line than at 1M: a size cliff)."""
    from nczones.gcode.fanuc import expr

    assert abs(Fraction(d) / step) > 2**24
    want = _rounded_exactly(Fraction(d), step)
    monkeypatch.setattr(expr, "_agreed", lambda value, step: pytest.fail(f"readings compared for {value}"))
    assert round_to((d, None), step) == want
    assert round_to((d, Fraction(d)), step) == want


def test_past_the_bound_of_kept_lines_the_rest_run_the_general_path(monkeypatch):
    """Only MAX_KEPT_LINES lines become closures (memory: about 1 KB each); the others stay on the general path
    with the same result."""
    from nczones.gcode.fanuc import program

    text = _program(["#2 = #1 * 0.5", "G01 X[#1 * 0.5] Y#2", "M98 P9020", "G65 P9010 X1. Y[#1]"], ["G01 Z-2."],
                    ["G00 X#24 Y#25"], 5)
    with _general_path_only():
        general = _language_layer(text, 100)
    monkeypatch.setattr(program, "MAX_KEPT_LINES", 4)
    out: list = []
    for _ in iter_blocks(text, "t.nc", runner_out=out):
        pass
    assert sum(op is not None for op in out[0].main.ops.values()) == 4
    assert _language_layer(text, 100) == general


def test_calls_between_texts_hand_over_as_the_general_path(tmp_path):
    """M98/G65 and M99 within one text go on with that text's closures; a call into a library file, a library
    program calling one of its own file and one of the main file, and the returns across them, switch texts
    (issue 36, fanucloops36).  Blocks, counters and variables equal the general path's, and the interpretation's
    segments too."""
    (tmp_path / "O7000.nc").write_text("%\nO7000 (LIB)\nG01 X[#1 * 0.1] Y#24\nM98 P7001\nM98 P9020\nM99\n"
                                       "O7001\nG01 Z-[#1 * 0.01]\nG65 P7002 X[#1]\nM99\nO7002\nG00 X#24 Y2.\nM99\n%\n")
    text = _loop("M98 P7000", "G65 P7000 X[#1 + 1]", "M98 P9020", "G65 P9010 X[#1] Y1.", reps=6,
                 sub=("G01 Z-2.", "G65 P9010 X[#1 * 2]"))
    for fn in (_language_layer_in(tmp_path), _interpretation_in(tmp_path)):
        with _general_path_only():
            before = fn(text)
        assert fn(text) == before
    out: list = []
    for _ in iter_blocks(text, "t.nc", runner_out=out, library=tmp_path):
        pass
    assert sum(op is not None for op in out[0].library_sources[7000].ops.values()) >= 6  # the library's closures


def _language_layer_in(folder) -> Callable[[str], tuple]:
    def run(text: str) -> tuple:
        variables = FanucVariables()
        out: list = []
        got = [(b.letters, b.values, str(b.span), b.index) for b in iter_blocks(
            text, "t.nc", variables=variables, runner_out=out, library=folder)]
        r = out[0]
        return got, (r.index, r.started, r.ran, len(r.frames)), list(variables.local), list(variables.common)
    return run


def _interpretation_in(folder) -> Callable[[str], tuple]:
    def run(text: str) -> tuple:
        chunks = list(interpret_text(text, mill(), file="t.nc", library=folder, chunk_size=7))
        return [(s.kind, s.start, s.end, s.block, str(s.span)) for c in chunks for s in c.segments()]
    return run
