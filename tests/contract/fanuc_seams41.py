"""Generated Fanuc mill programs that mix the lanes' newest features (hunt41), and their oracles.

:func:`fanuc_programs` draws programs for the test mill (``tests/gcode/fanuc/helpers.py``: G54, G55, H1, H2,
``g73_retract`` 0.5, ``g83_clearance`` 1): a header in G20 or G21, G90 or G91, G54 or G55; plain moves (numbered
now and then, G00/G01, G90/G91 switches, G43 H/G49, M03/M04/M05/M08, F); drilling cycles G73/G83 (Q), G74/G84
(P, with the spindle the cycle wants or not), G81, G82/G89 (P), G85, G86 with G98 or G99, K repeats, in G90 or
G91, then hole lines (X/Y words only: the vectorized fast path's ``_fanuc_holes``), a run of up to 90 of them
now and then (the fast path takes runs of 64 lines and more), or in a WHILE loop; macro lines that read
``#4114`` (the last N), ``#4113`` (the last M), ``#5001``-``#5003`` (the block end), ``#5021``/``#5041`` and
``SIN``/``COS`` into a position; ``M98 P1000`` and ``G65 P2000 A B`` calls of subprograms after ``M30``.

Oracles (:func:`lanes_agree`, :func:`verdicts_agree`, :func:`reference_agrees`):

1. the lanes: ``interpret_text`` as routed (the plain and expression lanes, the vectorized fast path) and the
   general path alone (``Interpreter.lane_for_blocks`` off, ``fast=False``: every block through ``run``) give the
   same segments (``Segment`` equality: kinds, exact ends, centres, feeds, lines, tool lengths...), status,
   unknown codes and the same system variables (each of :data:`READS` read into a move at the end), or the same
   error;
2. the verdict: ``verify_text`` as routed (the box route ``fanucboxes`` and its run reader ``boxrun`` under 512
   lines, the vectorized fast path above) and with every route and lane off, on the mill with a travel face at
   the extreme of a motion end along a drawn axis (or one pulse or 1e-9 mm either side): the same verdict and
   violations' lines (a wrong ``safe`` either way shows);
3. the independent reader ``tests/oracles/fanuc_ref.py`` (``ref_differential.compare``) where it models the
   program (it skips what it does not).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from fractions import Fraction

from hypothesis import strategies as st

from nczones.errors import GcodeError, NczonesError
from nczones.gcode import interpret_text
from nczones.gcode.interpreter import Interpreter

#: system variables read into moves at the end: modal groups, last F H M N T, block end, machine, current position
READS = (4001, 4003, 4005, 4006, 4009, 4010, 4014, 4107, 4109, 4111, 4113, 4114, 4120, 5001, 5002, 5003,
         5021, 5022, 5023, 5041, 5042, 5043)
#: the cycles: code -> the words it takes besides X Y Z R (a ``{q}`` a peck depth, ``{p}`` a dwell)
CYCLES = {"G73": " Q{q}", "G83": " Q{q}", "G74": " P{p}", "G84": " P{p}", "G81": "", "G82": " P{p}",
          "G85": "", "G86": "", "G89": " P{p}"}


def _num(draw, lo: int, hi: int, places: int = 3) -> str:
    """A decimal with a point between lo and hi (a Fanuc address without one is read in increments or calculator
    style)."""
    return _text(Fraction(draw(st.integers(lo * 10**places, hi * 10**places)), 10**places), places)


def _text(q: Fraction, places: int) -> str:
    """``q`` (a multiple of ``10**-places``) as a decimal with a point."""
    sign, q = ("-" if q < 0 else ""), abs(q)
    whole, frac = divmod(q.numerator * 10**places // q.denominator, 10**places)
    return f"{sign}{whole}.{frac:0{places}d}".rstrip("0")


class _Draw:
    """What the generator knows while it draws: inch, the distance mode, the cycle modal, labels, N numbers."""

    def __init__(self, draw, inch: bool, plain: bool = False):
        self.draw, self.inch = draw, inch
        #: no ``#`` anywhere (the box route's run reader takes only such a program)
        self.plain = plain
        self.incremental = False
        self.cycle = False
        self.loops = 0
        self.n = 0
        #: drawing a long run: every number with its point (a number without one ends the fast path's run)
        self.in_run = False

    def length(self, lo: int, hi: int) -> str:
        """A length in the program's units (inch: the range / 25)."""
        if not self.in_run and self.draw(st.integers(0, 7)) == 0:  # no point: millimetres or inches, or increments (the machine's)
            return str(self.draw(st.integers(lo, hi)))
        if self.inch:  # 4 places, lo/25 to hi/25 inches
            return _text(Fraction(self.draw(st.integers(lo * 400, hi * 400)), 10**4), 4)
        return _num(self.draw, lo, hi)

    def number(self) -> str:
        """``N<n> `` a third of the time (rising, as a control's sequence numbers often are)."""
        if self.draw(st.integers(0, 2)):
            return ""
        self.n += self.draw(st.integers(1, 20))
        return f"N{self.n} "


def _move(d: _Draw) -> list[str]:
    draw = d.draw
    axes = draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True))
    code = draw(st.sampled_from(("G00 ", "G01 ", "", "G01 ")))
    lo, hi = (-30, 30) if d.incremental else (-120, 120)
    words = " ".join(f"{a}{d.length(lo, hi if a != 'Z' else 40)}" for a in axes)
    feed = f" F{draw(st.integers(50, 900))}." if draw(st.integers(0, 4)) == 0 else ""
    m = f" M0{draw(st.sampled_from('34589'))}" if draw(st.integers(0, 9)) == 0 else ""
    return [f"{d.number()}{code}{words}{feed}{m}".strip()]


def _run_line(d: _Draw) -> list[str]:
    """A line of a long run: a move, now and then an M, F or N alone, or a comment."""
    kind = d.draw(st.integers(0, 59))
    if kind <= 2:
        return [f"{d.number()}M0{d.draw(st.sampled_from('34589'))}"]
    if kind <= 4:
        return [d.draw(st.sampled_from(("F250.", f"N{d.n + 1}", "(a comment)")))]
    if kind == 5:  # a line that ends the fast path's run
        line = d.draw(st.sampled_from(("G04 X0.1", "G90", "G91")))
        d.incremental = {"G91": True, "G90": False}.get(line, d.incremental)
        return [line]
    return _move(d)


def _cycle(d: _Draw) -> list[str]:
    """A cycle block (G98/G99, the cycle's words, K now and then), hole lines (a run of up to 90, or a WHILE loop of
    holes), maybe a line between holes, then G80."""
    draw = d.draw
    code = draw(st.sampled_from(sorted(CYCLES)))
    retract = draw(st.sampled_from(("G98 ", "G99 ", "")))
    if d.incremental:  # R from the initial level (down), Z from R (down)
        r, z = d.length(-40, -1), d.length(-30, -1)
    else:
        z = d.length(-60, -5)
        r = d.length(-4, 20)
    extra = CYCLES[code].format(q=d.length(1, 12), p=draw(st.sampled_from(("500", "1000", "0", "250"))))
    k = f" K{draw(st.integers(0, 4))}" if draw(st.integers(0, 3)) == 0 else ""
    spindle = {"G74": "M04", "G84": "M03"}.get(code, "M03")
    lines = [spindle] if draw(st.integers(0, 4)) else []
    xy = f"X{d.length(-60, 60)} Y{d.length(-60, 60)}"
    lines.append(f"{d.number()}{retract}{code} {xy} Z{z} R{r}{extra}{k} F{draw(st.integers(50, 500))}.")
    kind = draw(st.integers(0, 5))
    if kind == 1 and d.plain:
        kind = 2
    if kind in (0, 3):  # a long run of hole lines: the vectorized fast path's
        d.in_run = True
        lines += [f"{d.number() if draw(st.integers(0, 3)) == 0 else ''}X{d.length(-60, 60)} Y{d.length(-60, 60)}"
                  for _ in range(draw(st.integers(62, 100)))]
        d.in_run = False
    elif kind == 1:  # holes in a loop
        d.loops += 1
        c = f"#{20 + d.loops}"
        lines += [f"{c} = 0", f"WHILE [{c} LT {draw(st.integers(1, 4))}] DO{min(d.loops, 3)}",
                  f"X[{c} * {d.length(1, 10)} + {d.length(-30, 30)}] Y{d.length(-60, 60)}",
                  f"{c} = {c} + 1", f"END{min(d.loops, 3)}"]
    else:
        for _ in range(draw(st.integers(0, 6))):
            between = draw(st.integers(0, 6))
            if between == 0:
                macro = "M09" if d.plain else "#1 = #1 + 1."
                lines.append(draw(st.sampled_from(("G98", "G99", "M08", "F200.", "G91", "G90", macro))))
                d.incremental = {"G91": True, "G90": False}.get(lines[-1], d.incremental)
            elif between == 1:
                lines.append(f"X{d.length(-60, 60)} Z{z}")
            else:
                lines.append(f"{d.number()}X{d.length(-60, 60)} Y{d.length(-60, 60)}")
    lines.append("G80")
    return lines + (_macro(d) if draw(st.integers(0, 2)) == 0 and not d.plain else [])


def _macro(d: _Draw) -> list[str]:
    """A system variable (any of :data:`READS`) or SIN/COS read into a variable, then a move by it (a read just
    after a lane's block or run)."""
    draw = d.draw
    var = draw(st.sampled_from((*READS, 0, 1)))
    if var == 0:
        value = f"SIN[{_num(draw, -360, 360, 1)}] * {d.length(1, 50)}"
    elif var == 1:
        value = f"COS[#1 * 10.] * {d.length(1, 50)}"
    else:
        value = f"#{var}"
    axis = draw(st.sampled_from("XY"))
    scale = "0.01" if 4000 < var < 5000 else "0.5"
    return [f"#3 = {value}", f"{d.number()}G01 {axis}[#3 * {scale} + {d.length(-20, 20)}]"]


def _setting(d: _Draw) -> list[str]:
    draw = d.draw
    line = draw(st.sampled_from(("G90", "G91", "G54", "G55", "G43 H1", "G43 H2", "G49", "M03 S1000", "M04",
                                 "M05", "M08", "M09", "F300.", "M08" if d.plain else "#1 = #1 + 0.5")))
    if line in ("G90", "G91"):
        d.incremental = line == "G91"
    if line.startswith("G43") and d.incremental:
        return ["G49"]
    return [f"{d.number()}{line}" if line[0] in "GM" else line]


def _statement(d: _Draw) -> list[str]:
    kind = d.draw(st.integers(0, 9))
    if kind <= 2:
        return _move(d)
    if kind <= 4:
        return _cycle(d)
    if kind == 5:
        return _move(d) if d.plain else _macro(d)
    if kind == 6:
        calls = ("M98 P1000", "M98 P21000", "G65 P2000 A1.5 B-2.", "G65 P2000 A#1 B3.")
        return [d.draw(st.sampled_from(calls[:2] if d.plain else calls))]
    if kind == 7 or (kind == 8 and d.draw(st.booleans())):  # a long run of plain moves, maybe a read after it
        d.in_run = True
        run = [line for _ in range(d.draw(st.integers(62, 100))) for line in _run_line(d)]
        d.in_run = False
        return run + (_macro(d) if d.draw(st.booleans()) and not d.plain else [])
    return _setting(d)


@st.composite
def fanuc_programs(draw) -> tuple[str, str]:
    """A program (module docstring) in two parts: header and statements; the end (M30, O1000, O2000).
    :func:`program` joins them, with or without the :data:`READS` read into moves before the M30.  A quarter of
    them are plain: no ``#`` (no macro line, G65 call nor read; sub O2000 without one)."""
    inch = draw(st.integers(0, 3)) == 0
    return parts(_Draw(draw, inch, plain=draw(st.integers(0, 3)) == 0), _statement, 7)


def parts(d: _Draw, statement: Callable[[_Draw], list[str]], most: int, tail: Sequence[str] = ()) -> tuple[str, str]:
    """A program's two parts (:func:`fanuc_programs`) drawn with ``d``: the header, 1 to ``most`` of
    ``statement``'s statements and ``tail``; the end (M30, O1000, O2000; O2000 without ``#`` when ``d.plain``).
    hunt42's and hunt43's generators (:mod:`tests.contract.fanuc_seams42`, ``fanuc_seams43``) draw theirs here."""
    draw, inch = d.draw, d.inch
    head = ["O0001", f"G17 G40 G80 {'G20' if inch else 'G21'} G90 {draw(st.sampled_from(('G54', 'G55')))} F300.",
            "G00 Z20." if not inch else "G00 Z0.8", "M08" if d.plain else f"#1 = {_num(draw, -5, 5, 1)}"]
    body: list[str] = []
    for _ in range(draw(st.integers(1, most))):
        body += statement(d)
    sub1 = ["O1000", "G91 G01 X1. Y-1.", "G90", "N900 G81 X5. Y5. Z-10. R2. F100.", "X6.", "G80", "M99"]
    sub2 = ["O2000", "G01 X[#1 * 2.] Y[#2 + #4114 * 0.001]", "#5 = #5001", "G01 X[#5 + 1.]", "M99"]
    if d.plain:
        sub2 = ["O2000", "G01 X2. Y3.", "M99"]
    return "\n".join([*head, *body, *tail]) + "\n", "\n".join(["M30"] + sub1 + sub2) + "\n"


def program(parts: tuple[str, str], reads: bool = True) -> str:
    """The program of :func:`fanuc_programs`' ``parts``; ``reads``: each of :data:`READS` read into a move before
    the M30 (the reference reader models few of them)."""
    tail = ["G90 G49 G80"] + [f"#7 = #{v}\nG01 X[#7 + 0.5] Y{k}. F100." for k, v in enumerate(READS)]
    plain = "#" not in parts[0] + parts[1]
    return parts[0] + ("\n".join(tail) + "\n" if reads and not plain else "") + parts[1]


def _key(segment) -> tuple:
    """A segment as the oracles compare it: every field, the source span by its line and column (the lanes do not
    all record where a block's text ends)."""
    span = segment.span
    return (replace(segment, span=None), None if span is None else (span.file, span.line, span.column))


# ---------------------------------------------------------------------------------------------- oracles
def _motion(text: str, machine, lanes: bool):
    """(segments, status, unknown codes) of ``interpret_text``, or the error's text; ``lanes`` False: the general
    path alone (no lane, no vectorized fast path)."""
    saved = Interpreter.lane_for_blocks
    if not lanes:
        Interpreter.lane_for_blocks = lambda self: None  # type: ignore[method-assign]
    try:
        run = interpret_text(text, machine, file="t.nc", fast=lanes, max_loop_iterations=2000)
        return [_key(s) for s in run.segments()], run.status, [u.code for u in run.unsupported]
    except GcodeError as exc:
        return str(exc)
    finally:
        Interpreter.lane_for_blocks = saved  # type: ignore[method-assign]


def lanes_agree(text: str, machine) -> str:
    """Oracle 1; what happened (an event)."""
    routed, general = _motion(text, machine, True), _motion(text, machine, False)
    if isinstance(routed, str) or isinstance(general, str):
        assert routed == general, f"oracle 1: routed {routed!r:.300}\ngeneral {general!r:.300}\n{text}"
        return "error"
    for k, (a, b) in enumerate(zip(routed[0], general[0])):
        assert a == b, f"oracle 1: motion {k}:\nrouted  {a}\ngeneral {b}\n{text}"
    assert len(routed[0]) == len(general[0]), f"oracle 1: {len(routed[0])} motions, {len(general[0])}\n{text}"
    assert routed[1:] == general[1:], f"oracle 1: {routed[1:]} {general[1:]}\n{text}"
    return f"{routed[1]} ({len(routed[0])} motions)"


def verify_off(text: str, machine):
    """``verify_text`` with every route and lane off: the box route and its run reader, the lanes, the fast
    path."""
    from nczones.gcode.fanuc import boxrun
    from nczones.pipeline import verification
    from nczones.prover import fanucboxes, verify_text

    saved = (boxrun.BOX_RUNS, fanucboxes.ROUTE, verification.interpretation, Interpreter.lane_for_blocks)
    inner = verification.interpretation
    boxrun.BOX_RUNS = fanucboxes.ROUTE = False
    verification.interpretation = lambda *a, **k: inner(*a, **{**k, "fast": False})
    Interpreter.lane_for_blocks = lambda self: None  # type: ignore[method-assign]
    try:
        return verify_text(text, machine, file="t.nc")
    except NczonesError as exc:
        return exc
    finally:
        boxrun.BOX_RUNS, fanucboxes.ROUTE, verification.interpretation, Interpreter.lane_for_blocks = saved


def verify_routed(text: str, machine):
    from nczones.prover import verify_text

    try:
        return verify_text(text, machine, file="t.nc")
    except NczonesError as exc:
        return exc


#: where :func:`travel` puts its face: (axis index, side, which move of the face), drawn before the program (a
#: draw after a long program may overrun Hypothesis's buffer, which drops the example)
FACES = st.tuples(st.integers(0, 2), st.sampled_from((1, -1)), st.integers(0, 5), st.booleans())


def travel(segments, axes, face: tuple[int, int, int, bool], pulse: Fraction, at: Fraction | None = None) -> str:
    """A travel box of +-5000 mm with one face at the extreme of the motion ends (and starts) along axis
    ``face[0]`` on side ``face[1]``, moved by 0, one pulse or 1e-9 mm either way (``face[2]``); or (``face[3]``) a
    forbidden slab beyond that face (``[[zones]]`` text for ``helpers.mill(tables=...)``); ``at``: the face there
    instead of at the extreme (hunt42: one motion's end)."""
    k, side = face[0] % len(axes), face[1]
    if at is None:
        at = max(v * side for s in segments for v in (s.start[k], s.end[k])) * side
    start = segments[0].start[k]
    moved = (0, 0, pulse, -pulse, Fraction(1, 10**9), -Fraction(1, 10**9))[face[2]]
    if (at + moved - start) * side >= 0:  # not past the start (a machine whose start is outside: ZN130)
        at += moved
    lo = {a: Fraction(-5000) for a in axes}
    hi = {a: Fraction(5000) for a in axes}
    (hi if side > 0 else lo)[axes[k]] = at

    def text(q: Fraction) -> str:
        n = round(q * 10**12)
        sign, n = ("-" if n < 0 else ""), abs(n)
        return f'"{sign}{n // 10**12}.{n % 10**12:012d}"'

    row = ", ".join
    forbid = ""
    if face[3]:  # the slab from the face outwards, in a wide travel box
        forbid = "forbid = true\n"
        (lo if side > 0 else hi)[axes[k]] = at
        (hi if side > 0 else lo)[axes[k]] = at + side * 5000
    return ('\n[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-20000", Y = "-20000", Z = "-20000" }\n'
            'max = { X = "20000", Y = "20000", Z = "20000" }\n' * bool(forbid) +
            f'\n[[zones]]\nname = "{"slab" if forbid else "travel"}"\nkind = "box"\n{forbid}'
            f"min = {{ {row(f'{a} = {text(lo[a])}' for a in axes)} }}\n"
            f"max = {{ {row(f'{a} = {text(hi[a])}' for a in axes)} }}\n")


def verdicts_agree(text: str, face: tuple[int, int, int, bool], dpi: str = "calculator") -> str:
    """Oracle 2 on the test mill (``dpi``: its ``decimal_point_input``) with a face at a motion's extreme; what
    happened (an event)."""
    from tests.gcode.fanuc.helpers import mill

    extra = f'decimal_point_input = "{dpi}"'
    plain = mill(extra)
    got = _motion(text, plain, False)
    if isinstance(got, str) or not got[0]:
        return "no motion"
    machine = mill(extra, tables=travel([g[0] for g in got[0]], plain.axis_names, face, Fraction(1, 1000)))
    routed, off = verify_routed(text, machine), verify_off(text, machine)
    if isinstance(routed, Exception) or isinstance(off, Exception):
        assert type(routed) is type(off) and str(routed) == str(off), f"oracle 2: {routed!r}\n{off!r}\n{text}"
        return "error"
    case = (f"oracle 2: routed {routed.verdict} {routed.reasons[:2]} {routed.violations[:1]}\n"
            f"off {off.verdict} {off.reasons[:2]} {off.violations[:1]}\nprogram:\n{text}\nzones:{machine}")
    assert routed.verdict == off.verdict, case
    assert [v.line for v in routed.violations] == [v.line for v in off.violations], case
    return routed.verdict.name


def reference_agrees(text: str, dpi: str = "calculator") -> str:
    """Oracle 3 (``tests/gcode/fanuc/ref_differential.compare`` on the same mill); what happened."""
    from tests.gcode.fanuc.ref_differential import compare, first_difference

    outcome = compare(text, dpi)
    assert outcome.status in ("same", "skip", "reject"), f"oracle 3: {first_difference(outcome)}\n{text}"
    return outcome.status if outcome.status != "skip" else f"skip: {outcome.reason[:50]}"
