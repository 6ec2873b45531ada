"""Verification: one program's text → interpretation → lane → proof, and what the report needs of the text.

:func:`verify_source` is the pipeline of :func:`nczones.prover.verify` (see :mod:`nczones.pipeline`).
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable, Iterable, Iterator
from fractions import Fraction

from ..errors import InvalidArgument
from ..exact import format_decimal
from ..gcode.source import FileText, ProgramSource
from ..machine import Machine, declares_solids
from ..precompiled import replace  # dataclasses.replace without importing dataclasses (start-up)
from ..prover.limits import RunLimits
from ..prover.options import VerifyOptions
from ..prover.profile import RunProfile
from ..prover.result import ParamRange, Reason, Result, Verdict, Violation, reason_code

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from ..gcode import Interpretation

__all__ = ["verify_source", "interpretation", "double_pass_result", "switch_combinations",
           "switch_name", "source_lines", "FAST_PATH_MIN_LINES", "MAX_SWITCH_COMBINATIONS"]

F0 = Fraction(0)
#: Programs of fewer lines are read by the full interpreter alone: the vectorized fast path (numpy) costs
#: more to load than it saves there, and the segments are the same either way.
FAST_PATH_MIN_LINES = 512
#: Plain LinuxCNC programs (no ``#``, no o-word) the double pass is tried first for: from
#: :data:`FAST_PATH_MIN_LINES` lines (below, the full path imports no numpy either and is as quick) up to this
#: size, where a line counts 1, an R arc (an ``R`` in the text) :data:`PLAIN_PASS_R_ARC` more and an I/J arc (a
#: ``J``; G18's I/K arcs a ``K``) :data:`PLAIN_PASS_ARC` more.  It is the crossover of the pass (no numpy: about 2 us a line, 1-2 us more
#: an R arc, 3 us more an I/J arc) and the fast path (numpy's import and set-up, about 0.06 s, then about
#: 1-2.5 us a line), measured per class (specs/performance.md, "Plain programs in the double pass"): CAM G1
#: with a few arcs up to some 57,000 lines, R arcs on every line up to some 30,000, I/J arcs up to some 20,000.
PLAIN_PASS_SIZE = 60_000
PLAIN_PASS_ARC = 2
PLAIN_PASS_R_ARC = 1


def interpretation(source: ProgramSource, machine: Machine, options: VerifyOptions, *,
                   skip: frozenset[int] | None = None, ranges: tuple[ParamRange, ...] = (),
                   fast: bool = True) -> Interpretation:
    """The interpretation of ``source`` on ``machine`` with the options' dialect, library, loop bound and
    arc tolerance (:func:`nczones.gcode.interpret`); ``skip`` the block-skip switches on (None: the
    interpreter's default, none), ``ranges`` parameter ranges whose dependencies are tracked, ``fast`` the
    vectorized fast path allowed."""
    from ..gcode import interpret

    # a machine with tool solids takes the fast path too: its column chunks record the tool register that
    # picks the assembly (MotionChunk.tool_register), and the solids check screens their columns
    extra = options.interpret_keywords(machine)
    if skip is not None:
        extra["block_delete"] = skip
    if ranges:
        extra.update(track_dependencies=True, param_ranges=ranges)
    return interpret(source, machine, fast=fast, **extra)


def double_pass_result(text: str, machine: Machine, *, margin: Fraction, max_iterations: int,
                       arc_tolerance: Fraction | str | None = None) -> Result | None:
    """A ``safe`` result for ``text`` from the double pass (:mod:`nczones.gcode.linuxcnc.doubles`, proved by
    :func:`nczones.prover.doubles.prove_double_path`), or None when the pass declines or its boxes do not
    prove the program (the caller then runs the full path).  ``arc_tolerance``: the full path's (None: the
    interpreter's default)."""
    from ..gcode import DEFAULT_ARC_TOLERANCE
    from ..gcode.linuxcnc.doubles import Declined, double_pass
    from ..prover.doubles import WindowProof, prove_double_path

    started = time.perf_counter()
    # the motion in windows proved as they come: memory flat, no program too long for the pass
    windows = WindowProof(machine, margin)
    try:
        path = double_pass(text, machine, max_iterations=max_iterations, on_window=windows,
                           arc_tolerance=DEFAULT_ARC_TOLERANCE if arc_tolerance is None else arc_tolerance)
    except Declined:
        return None
    return prove_double_path(path, machine, margin, started, windows)


def verify_source(source: ProgramSource, machine: Machine, options: VerifyOptions, *,
                  progress: Callable[..., object] | None = None) -> Result:
    """Verify one program (see :func:`nczones.prover.verify` for the options' meaning); ``progress`` is
    called as ``progress(line, total_lines)`` after each chunk of motion is checked."""
    result = _verify_source(source, machine, options, progress)
    if source.notes:  # what reading the bytes assumed (a byte order mark, comment bytes read as CP1252)
        result = replace(result, notes=source.notes + tuple(result.notes))
    return result


def _verify_source(source: ProgramSource, machine: Machine, options: VerifyOptions,
                   progress: Callable[..., object] | None) -> Result:
    from ..blockskip import format_block_delete, used_switches
    from ..exact import exact
    from ..gcode import DEFAULT_ARC_TOLERANCE

    t0 = time.perf_counter()
    margin = exact(options.margin)
    ranges = options.ranges(machine)
    # a lathe tool's nose radius: the tip zones enlarged by the nose's reach (nczones.prover.nose), or a
    # reason the verdict cannot be safe
    machine, nose_note, nose_reason = _nose_zones(machine)
    nose_reasons = (Reason(nose_reason, None, None, "VF207"),) if nose_reason else ()
    modes = options.block_delete_modes(machine)
    mode = format_block_delete(modes)
    options = replace(options, params=ranges, arc_tolerance=options.machine_tolerance(machine), block_delete=mode)
    tolerance = options.arc_tolerance if options.arc_tolerance is not None else DEFAULT_ARC_TOLERANCE
    # Every option that can change the verdict, as JSON values: reports carry them and `nczones replay`
    # re-runs with them (VerifyOptions.to_settings).
    settings = options.to_settings(machine)
    dialect = options.effective_dialect(machine)
    limits = options.run_limits()
    options = replace(options, limits=limits)
    # one budget for the whole program: every case and switch position draws on it
    # one profile too: the progress bar counts the motions of every case, and --stats sums them
    profile = RunProfile()
    used = used_switches(source.text, dialect)
    deleted = bool(used)
    source = _kept_streamed(source, machine, options, dialect, ranges, deleted)
    if (options.engine == "auto" and not ranges and options.recovery is None and not deleted
            and dialect == "linuxcnc" and machine.dialect == "linuxcnc" and _double_pass_reads(source.text, machine)):
        quick = _double_pass_first(source, machine, options, tolerance, margin, t0, progress,
                                   (nose_note, nose_reasons), settings)
        if quick is not None:
            return quick
    source = _kept_streamed(source, machine, options, dialect, ranges, deleted, passed=True)

    def cases(skip: frozenset[int]) -> tuple[Result, Interpretation, set[int]]:
        return _verify_cases(source, machine, options, skip, progress, profile)

    free, combos, complete = switch_combinations(used, modes)
    combos, per_position, seen, complete, runs_done = _verify_combinations(
        combos, free, complete, cases, fanuc=dialect == "fanuc")
    unseen = sorted(n for n in seen - set(used) if modes[n] == "both")
    if unseen and not any(r.interrupted for r, _ in per_position):
        # a switch only a library program uses (the main text does not show it): verified again with it
        # among the free switches (a third switch met only then is not: VF206 below)
        used = {**used, **{n: [] for n in unseen}}
        free, combos, complete = switch_combinations(used, modes)
        combos, per_position, seen, complete, runs_done = _verify_combinations(
            combos, free, complete, cases, fanuc=dialect == "fanuc")
        if any(modes[n] == "both" for n in seen - set(used)):
            complete = False
            free = sorted(set(free) | {n for n in seen - set(used) if modes[n] == "both"})
    result, first_run = per_position[0]
    if len(combos) > 1:
        result = _merge_switch_combinations([(c, r) for c, (r, _) in zip(combos, per_position)], free, complete,
                                             options.max_violations)
    interrupted = any(r.interrupted for r, _ in per_position)
    violations, reasons, notes = list(result.violations), list(result.reasons), result.notes
    if not complete:
        reasons.append(_combinations_reason(free))
    notes += _switch_notes({**{n: [] for n in seen if n not in used}, **used}, modes, free, complete,
                           first_run.interpreter.stops)
    if len(combos) > runs_done:
        notes += (f"{runs_done} of the {len(combos)} combinations of the block-skip switches were interpreted: "
                  "the others differ from one of them only in switches its run never reached a line of, so "
                  "their path is the same",)
    notes += (nose_note,) if nose_note else ()
    reasons += nose_reasons
    if options.recovery is not None and not interrupted:
        found, reasons, interrupted, note, stats = _verify_recovery(source, machine, options, combos, free,
                                                                    reasons, limits)
        violations = sorted(violations + found,
                            key=lambda v: (sum(p == "on" for _, p in v.switches), v.block, v.kind != "motion"))
        notes += note
        result = replace(result, stats=result.stats + stats)
    verdict = Verdict.UNSAFE if violations else (Verdict.UNKNOWN if reasons else Verdict.SAFE)
    if isinstance(source.text, FileText):
        source.text.check_unchanged()  # the text verified is the text hashed
    timings = (("total_s", time.perf_counter() - t0),) + result.timings
    return replace(result, verdict=verdict, violations=tuple(violations), reasons=tuple(reasons), notes=notes,
                   interrupted=interrupted, budget_s=limits.budget_s, profile=profile.as_dict(),
                   timings=timings, extra={**result.extra, "counts": first_run.counts, "splits": result.extra.get("splits", ())},
                   program_digest=source.digest, machine_name=machine.name, machine_file=machine.source,
                   machine_sha256=machine.sha256, settings=settings)


def _nose_zones(machine: Machine) -> tuple[Machine, str | None, str | None]:
    """:func:`nczones.prover.nose.nose_zones`, whose module (with the zone kinds' table) is imported for a lathe
    only: it leaves any other machine unchanged, without a note or a reason (its first test; boot44)."""
    if not machine.is_lathe:
        return machine, None, None
    from ..prover.nose import nose_zones

    return nose_zones(machine)


#: the words every o-word line holds (``o100 sub``, ``call``, ``while``, ``if``, ``do``, ``repeat``, ``return``,
#: ``break``, ``continue``, ``end...``, ``else...``), in the cases programs write them
_OWORD_KEYWORDS = tuple(w for k in ("sub", "call", "while", "if", "do", "repeat", "return", "break", "continue")
                        for w in (k, k.upper(), k.capitalize()))
@functools.cache
def _oword_line() -> Any:
    """A line whose first code word is an o-word (after blanks, a block delete and a line number): ``o100 call``."""
    import re

    return re.compile(r"(?:^|\n)[ \t]*(?:/[ \t]*\d?[ \t]*)?(?:[nN][ \t]*\d[\d. \t]*)?[oO][ \t]*[\d<]")


def _double_pass_reads(text: str | FileText, machine: Machine | None = None) -> bool:
    r"""Whether the double pass is tried first: a program with parameters (``#``), or one with o-words (the
    fast path hands those to the language layer, which the pass runs some 4x faster: issue 36's "o-word subs,
    no #" class), a plain program of the pass's size, and any program of :data:`FAST_PATH_MIN_LINES` lines or
    more on a lathe (``machine``: ``type = "lathe"`` or diameter axes), which no fast path reads (lathe39), or
    on a machine with LinuxCNC's cutter compensation whose text may write G41/G42 (nor that: comp40).
    Soundness does not rest on this test: the pass proves or declines (then the full path decides) whatever it
    is given; a program it misses goes the full path as before.

    >>> _double_pass_reads("G1 X1 (#1 in a comment counts: the pass declines or agrees)")
    True
    >>> _double_pass_reads("o100 sub\nG1 X1\no100 endsub\no100 call\nM2")
    True
    >>> _double_pass_reads("(do the contour)\nG1 X1 Y1\nM2")
    False
    >>> _double_pass_reads("G21 G90 G17 G54 F100\n" + "G1 X1 Y1\n" * 600)  # plain, small: the pass first
    True
    >>> _double_pass_reads("G21 G90 G17 G54 F100\n" + "G2 X1 Y1 R5\n" * 600)  # R arcs, small: the pass too
    True
    >>> _double_pass_reads("G21 G90 G17 G54 F100\n" + "G2 X1 Y1 I5 J0\n" * 25_000)  # I/J arcs: the fast path
    False
    >>> _double_pass_reads("G21 G90 G18 G54 F100\n" + "G2 X1 Z1 I5 K0\n" * 25_000)  # so are G18's I/K arcs
    False
    >>> from nczones.machine import parse_machine
    >>> lathe = parse_machine('[machine]\ntype = "lathe"\naxes = ["X", "Z"]\n[machine.rapid]\nX = "1000"\n'
    ...                       'Z = "1000"\n[machine.reference]\nX = "0"\nZ = "0"\n')
    >>> _double_pass_reads("G21 G90 G18 G54 F100\n" + "G2 X1 Z1 I5 K0\n" * 25_000, lathe)  # a lathe: the pass
    True
    """
    if "#" in text:
        return True
    # an o-word line has an "o" (one quick scan; the keywords' 27 scans cost some 9 ms in 10k lines of arcs)
    if ("o" in text or "O" in text) and any(k in text for k in _OWORD_KEYWORDS):
        pieces = text.pieces(1 << 20) if isinstance(text, FileText) else (text,)
        if any(_oword_line().search(p) is not None for p in pieces):
            return True
    if machine is not None and (machine.is_lathe or machine.diameter_axes  # no fast path for a lathe
                                or (machine.cutter_compensation == "linuxcnc" and ("41" in text or "42" in text))):
        # nor for cutter compensation (comp40: the pass follows G41/G42 over straight moves)
        return _line_count(text) >= FAST_PATH_MIN_LINES  # type: ignore[arg-type]  # FileText counts too
    return _small_plain(text)


def _small_plain(text: str | FileText) -> bool:
    """Is a plain program (no ``#``, no o-word) of the size the double pass proves faster than the fast path
    (:data:`PLAIN_PASS_SIZE`)?"""
    if len(text) > PLAIN_PASS_SIZE * 64:  # characters (bytes of a streamed file): far more lines than that
        return False
    lines = _line_count(text)  # type: ignore[arg-type]  # FileText counts too
    if lines < FAST_PATH_MIN_LINES or lines > PLAIN_PASS_SIZE:
        return False
    r_arcs = _letter_count(text, "R")
    # (G18's centre words are K and I, G19's J and K: the larger count, each arc once)
    ij_arcs = max(_letter_count(text, "J"), _letter_count(text, "K"))
    return lines + PLAIN_PASS_R_ARC * r_arcs + PLAIN_PASS_ARC * ij_arcs <= PLAIN_PASS_SIZE


def _letter_count(text: str | FileText, letter: str) -> int:
    r"""How many times ``letter`` is in ``text``, in either case: the lower case counted only when the text holds
    it (``in`` finds a character with ``memchr``, some 30x quicker than ``count``'s scan, and CAM output is upper
    case: line44, some 1.4M instructions a count on 10,000 R arcs).

    >>> _letter_count("G2 X1 R2\nG3 X0 r1", "R"), _letter_count("G1 X1", "J")
    (2, 0)
    """
    small = letter.lower()
    return text.count(letter) + (text.count(small) if small in text else 0)


def _double_pass_first(source: ProgramSource, machine: Machine, options: VerifyOptions, tolerance: Fraction | str,
                       margin: Fraction, t0: float, progress: Callable[..., object] | None,
                       nose: tuple[str | None, tuple[Reason, ...]], settings: Any) -> Result | None:
    """A parametric LinuxCNC program's result by the double pass, or None when the pass declines (the full
    path then decides)."""
    from ..gcode import checked_options

    nose_note, nose_reasons = nose
    limits = options.limits
    assert limits is not None  # set by _verify_source
    # the options the full path refuses are refused before the pass too
    checked_options(machine, tolerance, options.max_iterations, options.dialect)
    if margin < 0:
        raise InvalidArgument(f"margin must not be negative, got {margin}")
    # a parametric program: the double pass first, the full path if it declines
    try:
        quick = double_pass_result(source.text, machine, margin=margin, max_iterations=options.max_iterations,
                                   arc_tolerance=tolerance)
    except KeyboardInterrupt:
        quick = Result(verdict=Verdict.UNKNOWN, reasons=(Reason(
            f"interrupted (Ctrl-C) after {time.perf_counter() - t0:.1f} s: the program was not checked",
            None, None, "VF204"),), interrupted=True, margin=margin, engine=options.engine)
    if quick is None:
        return None
    if isinstance(source.text, FileText):
        source.text.check_unchanged()  # the text proved is the text hashed
    if progress is not None and not quick.interrupted:  # done at once: the bar's last step
        total = _line_count(source.text) or None
        bar: Any = progress
        if getattr(bar, "counts", False):
            bar(total or 0, total, motions=dict(quick.stats)["segments"], blocks=quick.extra["counts"]["blocks"])
        else:
            bar(total or 0, total)
    if nose_note or nose_reasons:
        quick = replace(quick, notes=quick.notes + ((nose_note,) if nose_note else ()),
                        reasons=quick.reasons + nose_reasons,
                        verdict=(Verdict.UNKNOWN if nose_reasons and quick.verdict is Verdict.SAFE
                                 else quick.verdict))
    return replace(quick, budget_s=limits.budget_s,
                   timings=(("total_s", time.perf_counter() - t0),) + quick.timings,
                   program_digest=source.digest, machine_name=machine.name, machine_file=machine.source,
                   machine_sha256=machine.sha256, settings=settings, file=source.name)


#: Plain Fanuc programs (no ``#``, no M98/G65/G66 call in the text) of :data:`FAST_PATH_MIN_LINES` lines up to this
#: many try the numpy-free box route (:mod:`nczones.prover.fanucboxes`; its runs of plain lines read from the text
#: into a run's box, ``gcode/fanuc/boxrun.py``, about 1.5 us a straight line, 2.5-3.5 an arc) before the vectorized
#: fast path: below the crossover of the route (no numpy to load) and the fast path (numpy's import and set-up,
#: then about 1.5-2 us a line), measured on R-arc, I/J-arc and G1 programs of 4,000-60,000 lines (the I/J ones
#: cross first, at about 50,000; specs/performance.md, "Fanuc plain runs read from the text").
FANUC_BOX_LINES = 40_000


@functools.cache
def _fanuc_codes() -> Any:
    """The codes that keep a plain Fanuc program off the box route, one pattern per case of its letter: a call
    (M98, G65, G66: its loops may run far more lines than the text holds), a G68 rotation or a G51 scaling, and the
    codes under which the box route's reader leaves their lines to the general path (G20 inch input, G91
    incremental input: ``boxrun._read_transformed``) while the vectorized fast path takes them (a 10,000-line G20
    program under G68: 3.3 s on the route against 0.25 s).

    ``(G, g, M, m)``: each pattern starts with its letter, which the regex engine scans for (a class at the start
    is tested at every character: some 8x slower, issue 36); a G match's group 1 is a G65/G66 call, its group 2
    the code of the others.  Searched in the text as written, the lower-case letter's pattern only when the text
    holds that letter (line44: no ``upper()`` of the text, one scan for the G codes instead of three; 11.7M -> 2.5M
    instructions on 10,000 R arcs).  The answer is the upper-cased text's: only the letter of each pattern has a
    case, no character but ``g`` (``m``) upper-cases to a string holding a ``G`` (``M``), a digit, a point, a space
    or a tab, and a character's upper case starts with a digit or a point exactly when it is one
    (``tests/pipeline/test_fanuc_codes.py`` checks every code point, and the old scan against this one)."""
    import re

    g = r"[ \t]*0*(?:(6[56])(?!\d)|(68|51|20|91)(?![\d.]))"
    m = r"[ \t]*0*98(?![\d.])"
    return re.compile("G" + g), re.compile("g" + g), re.compile("M" + m), re.compile("m" + m)


def _fanuc_plain_piece(p: str) -> bool:
    r"""Has ``p`` no Fanuc call (M98, G65, G66), and no G68 or G51 with a G20 or G91 (:func:`_fanuc_codes`)?

    >>> _fanuc_plain_piece("G1 X1.\ng02 X2. R1."), _fanuc_plain_piece("m 098 P2"), _fanuc_plain_piece("g68\nG091")
    (True, False, False)
    """
    big_g, small_g, big_m, small_m = _fanuc_codes()
    if big_m.search(p) is not None or ("m" in p and small_m.search(p) is not None):
        return False
    codes = set()
    # (a match spans one G and no other: every G that starts a code is met)
    for pattern in (big_g, small_g) if "g" in p else (big_g,):
        for found in pattern.finditer(p):
            if found.group(1) is not None:
                return False
            codes.add(found.group(2))
    return not (codes & {"68", "51"} and codes & {"20", "91"})


def _fanuc_boxes_first(text: str | FileText) -> bool:
    r"""Whether a Fanuc program tries the box route first: fewer than :data:`FAST_PATH_MIN_LINES` lines (any
    program), or a plain one of up to :data:`FANUC_BOX_LINES` (its runs of plain lines, of hole lines and of plain
    lines under one G68 rotation or G51 scaling are read into boxes from the text: ``fanuc.boxrun``) but one with
    G68 or G51 and G20 or G91 (:func:`_fanuc_codes`: the fast path's).  Soundness does not rest on this test: the route proves or declines (then today's path decides as
    if it had not run).

    >>> _fanuc_boxes_first("G1 X1. F100.\n" * 600), _fanuc_boxes_first("M98 P10\n" + "G1 X1. F100.\n" * 600)
    (True, False)
    >>> _fanuc_boxes_first("G81 X1. Z-1. R1. F100.\n" + "X1.\n" * 600), _fanuc_boxes_first("G81 X1.\n" * 9)
    (True, True)
    >>> _fanuc_boxes_first("G68 X0 Y0 R30.\n" + "X1.\n" * 600), _fanuc_boxes_first("G51.1 X0\n" + "X1.\n" * 600)
    (True, True)
    >>> _fanuc_boxes_first("G20\nG68 X0 Y0 R30.\n" + "X1.\n" * 600), _fanuc_boxes_first("G51 P2.\nG91\n" + "X1.\n" * 600)
    (False, False)
    >>> _fanuc_boxes_first("g020\ng68 X0 Y0 R30.\n" + "X1.\n" * 600), _fanuc_boxes_first("m098 p10\n" + "X1.\n" * 600)
    (False, False)
    >>> _fanuc_boxes_first("G1 X1. F100.\n" * (FANUC_BOX_LINES + 1))
    False
    """
    global _BOXES_FIRST
    last = _BOXES_FIRST
    if last[0] is text:  # the same text asked again (the cases' loop, then the route): not even counted again
        return bool(last[1])
    lines = _line_count(text)  # type: ignore[arg-type]  # FileText counts too
    if lines < FAST_PATH_MIN_LINES:
        return True
    if lines > FANUC_BOX_LINES or len(text) > FANUC_BOX_LINES * 128 or "#" in text:
        return False
    pieces = text.pieces(1 << 20) if isinstance(text, FileText) else (text,)
    got = all(_fanuc_plain_piece(p) for p in pieces)
    _BOXES_FIRST = (text, got)  # one tuple: a thread reads a text and its own answer
    return got


#: the last text :func:`_fanuc_boxes_first` scanned for calls, and its answer
_BOXES_FIRST: tuple[Any, bool] = (None, False)


def _fanuc_boxes(source: ProgramSource, machine: Machine, options: VerifyOptions, skip: frozenset[int],
                 progress: Callable[..., object] | None, profile: RunProfile) -> tuple[Any, Result | None]:
    """One case of a short Fanuc program (:func:`_fanuc_boxes_first`) proved by the box of its motion without numpy
    (:mod:`nczones.prover.fanucboxes`): (its interpretation, its result), or (None, None) when that route does not
    apply or declines (the case is then interpreted again and proved by the full path, as if it had not run)."""
    if options.engine != "auto" or options.params or options.effective_dialect(machine) != "fanuc":
        return None, None  # before the import: a LinuxCNC program does not load the route (start-up)
    # read at each call (tests switch them): the module's flags and its proof
    from ..prover.fanucboxes import ROWS_AS_LISTS, boxes_apply, prove_boxes

    if not boxes_apply(machine) or not _fanuc_boxes_first(source.text):
        return None, None
    from ..gcode.fanuc.columns import MAX_ROWS, BoxSink, RowSink

    started = time.perf_counter()
    run = interpretation(source, machine, options, skip=skip, fast=False)  # lazy (the full path's call): nothing read
    interp: Any = run.interpreter
    if getattr(interp, "fused_lane", False) and tuple(interp.axes) == tuple(machine.axis_names):
        # the plain lane writes each run's box (BoxRows; ROWS_AS_LISTS: its rows, Rows), no segment a move
        sink = RowSink if ROWS_AS_LISTS else BoxSink
        interp.row_sink = sink(tuple(interp.axes), interp.file, 0, MAX_ROWS)
    try:
        result = prove_boxes(run, machine, options.margin, started)
    except KeyboardInterrupt:
        return run, Result(verdict=Verdict.UNKNOWN, reasons=(Reason(
            f"interrupted (Ctrl-C) after {time.perf_counter() - started:.1f} s: the program was not checked", None,
            None, "VF204"),), interrupted=True, margin=options.margin, engine=options.engine)
    except Exception:  # noqa: BLE001 - any error: the full path reads the case again and reports it as it does
        return None, None
    if result is None:
        return None, None
    if run.unsupported:  # codes not modelled (a loop past its bound): unknown, as the full path says it
        wanted = [u.span.line for u in run.unsupported if u.span is not None and not u.span.text and u.span.line >= 1]
        reasons = tuple(_unsupported_reasons(run, source_lines(run.text, wanted)))
        result = replace(result, verdict=Verdict.UNKNOWN, reasons=reasons)
    profile.motions += run.counts["segments"]
    profile.blocks = max(profile.blocks, run.counts["blocks"])
    for label, kind in (result.profile or {}).get("kinds", {}).items():  # by motion kind, as the full path counts
        profile.kinds.setdefault(label, [0, 0.0])[0] += kind["motions"]
    if progress is not None:  # done at once: the bar's last step
        total = _line_count(source.text) or None
        bar: Any = progress
        if getattr(bar, "counts", False):
            bar(total or 0, total, motions=profile.motions, blocks=profile.blocks)
        else:
            bar(total or 0, total)
    return run, result


def _spindle_check(machine: Machine, run: Interpretation) -> Any:
    """The check that the tool in the spindle is the one the solids take (:class:`~nczones.prover.solids.
    SpindleToolCheck`), on a machine with tool solids; None otherwise (nothing of the solids is imported)."""
    if not declares_solids(machine):
        return None
    from ..prover.solids import SpindleToolCheck

    return SpindleToolCheck(run.interpreter.spindle_tools) if SpindleToolCheck.wanted(machine) else None


def _kept_streamed(source: ProgramSource, machine: Machine, options: VerifyOptions, dialect: str,
                   ranges: tuple[ParamRange, ...], deleted: bool, passed: bool = False) -> ProgramSource:
    """``source``, its text read whole (:meth:`~nczones.gcode.source.ProgramSource.materialized`) when it is a
    streamed file that :func:`_streams` cannot verify streamed (``passed``: the double pass declined)."""
    if isinstance(source.text, FileText) and not _streams(source.text, machine, options, dialect, ranges, deleted,
                                                          passed):
        return source.materialized()
    return source


def _streams(text: FileText, machine: Machine, options: VerifyOptions, dialect: str,
             ranges: tuple[ParamRange, ...], deleted: bool, passed: bool = False) -> bool:
    """Whether a streamed file (:class:`~nczones.gcode.source.FileText`) can be verified without its whole
    text in memory: a LinuxCNC or Fanuc program without block delete (``deleted``: a line starts with ``/``),
    ranges, recovery or tool solids, and either a LinuxCNC program with parameters (``#``) and the double pass
    to try (it reads the file a piece at a time, UTF-8 too; ``passed``: it was tried and declined), or
    ASCII: the fast path reads it block by block, LinuxCNC's language layer a line at a time (the Fanuc
    language layer reads a program that needs it whole); the lines of violations are read back from the
    file."""
    if not (dialect in ("linuxcnc", "fanuc") and machine.dialect == dialect and not ranges
            and options.recovery is None and not declares_solids(machine) and not deleted):
        return False
    if dialect == "linuxcnc" and options.engine == "auto" and not passed and _double_pass_reads(text, machine):
        return True
    return text.ascii


def _verify_recovery(source: ProgramSource, machine: Machine, options: VerifyOptions,
                     combos: list[frozenset[int]], free: list[int], reasons: list[Reason], limits: RunLimits
                     ) -> tuple[list[Violation], list[Reason], bool, tuple[str, ...], tuple[tuple[str, Any], ...]]:
    """The tool-break recovery proved from every break point of every switch combination: (violations,
    reasons so far and its own, interrupted, notes, stats)."""
    from ..prover.recovery import verify_recovery

    ranges = options.ranges(machine)
    interrupted = False
    # The recovery is proved at one point of the parameter ranges (their nominal values where the
    # ranges hold them, else their middles): its witnesses must lie inside the ranges.
    rec_machine, at_values = _recovery_point(machine, ranges)
    found: list[Violation] = []
    rec = None
    for skip in combos if at_values is not None else ():
        rerun = interpretation(source, rec_machine, replace(options, params=()), skip=skip)
        try:
            with limits.watch():
                rec = verify_recovery(rerun, rec_machine, variant=options.recovery, margin=options.margin,
                                      max_violations=options.max_violations, limits=limits)
        except KeyboardInterrupt:
            interrupted = True
            reasons.append(Reason(f"interrupted (Ctrl-C) after {limits.elapsed():.1f} s while the tool-break "
                                  "recovery was proved: it was not checked completely", None, None, "VF204"))
            break
        source_text = source_lines(source.text, [v.span.line for v in rec.violations if v.span is not None]
                                   + [r.span.line for r in rec.reasons if r.span is not None])
        switch = tuple((switch_name(n), "on" if n in skip else "off") for n in free)
        for v in rec.violations:
            if any((v.line, v.break_line) == (w.line, w.break_line) for w in found):
                continue
            found.append(replace(v, span=_fix_span(v.span, source_text), switches=switch,
                                 params=at_values or ()))
        reasons += [replace(r, span=_fix_span(r.span, source_text)) for r in rec.reasons
                    if r.message not in {x.message for x in reasons}]
    if ranges:
        # A verdict 'safe' over the ranges would claim more than was proved.
        where = ("at " + ", ".join(f"{n} = {format_decimal(v)}" for n, v in at_values)
                 if at_values is not None else "nowhere (a homing-error range excludes 0)")
        reasons.append(Reason(
            f"RC204: the tool-break recovery was proved only {where}, one point of the parameter ranges; "
            "recovery over the whole ranges is not modelled", None, None, "RC204"))
    notes: tuple[str, ...] = ()
    stats: tuple[tuple[str, Any], ...] = ()
    if not interrupted and at_values is not None and rec is not None:
        notes = (f"tool-break recovery ({rec.variant.value} variant) checked from every break point of "
                 f"{dict(rec.stats)['recovery_motions']} cutting motions",)
        stats = rec.stats
    return found, reasons, interrupted, notes, stats


def _recovery_point(machine: Machine, ranges: tuple[ParamRange, ...]) -> tuple[Machine, tuple[tuple[str, Fraction], ...] | None]:
    """The machine at the one point of the ranges where the tool-break recovery is proved, and that point
    as witnesses name it (work offsets and the start as deviations, tool lengths absolute).

    The nominal value where a range holds it, else the middle of the range (:func:`.cases.centred`).
    ``None`` when no point can be chosen: a homing error is not interpreted, so a ``home.*`` range
    without 0 has no point the recovery proof could stand at.
    """
    from ..prover.cases import centred

    if not ranges:
        return machine, ()
    if any(r.name.startswith("home.") and not r.lo <= 0 <= r.hi for r in ranges):
        return machine, None
    at, moved = centred(machine, ranges)
    values = tuple((r.name, at.tool_length(int(r.name[1:])) if r.absolute else r.centre) for r in moved)
    return at, values


#: The most runs of block-skip switch combinations one proof interprets (all of 4 free switches).
MAX_SWITCH_COMBINATIONS = 16


def switch_name(n: int) -> str:
    """The name of block-skip switch *n* in ``Violation.switches`` and reports: ``block_delete`` for
    ``/`` and ``/1`` (the name of earlier versions), ``block_delete/2`` .. ``block_delete/9``."""
    return "block_delete" if n == 1 else f"block_delete/{n}"


def _verify_combinations(combos: list[frozenset[int]], free: list[int], complete: bool,
                         run: Callable[[frozenset[int]], tuple[Result, Interpretation, set[int]]], *, fanuc: bool
                         ) -> tuple[list[frozenset[int]], list[tuple[Result, Interpretation]], set[int], bool, int]:
    """Verify the combinations: (the combinations verified, their (result, first interpretation), the
    switches met, whether every combination was verified, how many were interpreted).

    Two combinations can differ only if a run reaches a line of a switch they differ in: the interpreter
    reads a switch at its lines only, so a run that met none of a switch's lines is the same run with the
    switch in the other position (the Fanuc runner records the switches it meets, library programs
    included; a LinuxCNC run counts as meeting all).  A combination that agrees with an interpreted one on
    every free switch that run met takes its result without a run.  Past
    :data:`MAX_SWITCH_COMBINATIONS` interpreted runs the rest is not verified (``complete`` False)."""
    done: list[tuple[frozenset[int], set[int], tuple[Result, Interpretation]]] = []
    verified: list[frozenset[int]] = []
    out: list[tuple[Result, Interpretation]] = []
    seen: set[int] = set()
    for skip in combos:
        same = next((r for d, met, r in done if all((n in skip) == (n in d) for n in met)), None)
        if same is None:
            if len(done) >= MAX_SWITCH_COMBINATIONS:
                complete = False
                break
            result, interp, met = run(skip)
            seen |= met
            same = (result, interp)
            done.append((skip, (met & set(free)) if fanuc else set(free), same))
        verified.append(skip)
        out.append(same)
        if same[0].interrupted:  # Ctrl-C: the other combinations are not verified
            break
    return verified, out, seen, complete, len(done)


def switch_combinations(used: dict[int, list[int]], modes: dict[int, str]
                        ) -> tuple[list[int], list[frozenset[int]], bool]:
    """The block-skip switches left free (used by the program, set to ``both``), the combinations of
    switches that are on to verify (the first: every free switch off; then by how many are on) and whether
    they are all of them.

    Any two switches can interact (a skipped ``G91``, ``G92`` or offset line changes what every later line
    does), so every combination of the free switches is listed (2**k, at most 512); fixed switches and
    switches the program does not use add none.  :func:`_verify_combinations` interprets only those whose
    runs can differ, at most :data:`MAX_SWITCH_COMBINATIONS`; past that the verdict cannot be ``safe``
    (VF206; the witnesses found are real).

    >>> switch_combinations({2: [3], 5: [7]}, {n: "both" for n in range(1, 10)})[1]
    [frozenset(), frozenset({2}), frozenset({5}), frozenset({2, 5})]
    >>> free, combos, _ = switch_combinations({2: [3], 5: [7]}, {**{n: "both" for n in range(1, 10)}, 5: "on",
    ...                                                            8: "on"})
    >>> free, [sorted(c) for c in combos]
    ([2], [[5, 8], [2, 5, 8]])
    """
    free = sorted(n for n in used if modes[n] == "both")
    on = frozenset(n for n in modes if modes[n] == "on")  # also those only a library program may use
    subsets = [frozenset(n for k, n in enumerate(free) if bits >> k & 1) for bits in range(2 ** len(free))]
    subsets.sort(key=lambda c: (len(c), sorted(c)))
    return free, [on | c for c in subsets], True


def _combinations_reason(free: list[int]) -> Reason:
    names = ", ".join(f"/{n}" for n in free)
    return Reason(f"VF206: the program uses {len(free)} block-skip switches left to both positions ({names}): of "
                  f"their {2 ** len(free)} combinations more than {MAX_SWITCH_COMBINATIONS} can take different "
                  "paths (their runs reach lines of the switches they differ in), more than one proof runs; "
                  f"the {MAX_SWITCH_COMBINATIONS} with the fewest switches on were verified.  Fix the positions of "
                  "the switches the operator does not use with --block-delete or the machine file's block_delete "
                  "(e.g. 3=off,4=off)", None, None, "VF206")


def _switch_notes(used: dict[int, list[int]], modes: dict[int, str], free: list[int], complete: bool,
                  stops: Iterable[tuple[int, Any]]) -> tuple[str, ...]:
    """What the report says about the operator's switches: block skip, stops."""
    notes: tuple[str, ...] = ()
    for n in sorted(used):
        lines = used[n]
        switch = "the block-delete switch" if n == 1 else f"block-delete switch /{n}"
        label = '/ (or /1)' if n == 1 else f'/{n}'
        where = (f"{len(lines)} line(s) start with {label}, the first at line {lines[0]}" if lines
                 else f"lines of a called library program start with {label}")
        others = ", ".join(f"/{k}" for k in free if k != n)
        notes += ({"both": f"{where}: verified with {switch} off (those lines run) and on (they are skipped)"
                           + (f", in every combination with {others}" if others and complete else "")
                           + (f", but not in every combination with {others} (VF206)" if not complete else "")
                           + "; a violation found in some positions only says which",
                   "off": f"{where}: verified with {switch} OFF only (those lines run), as the machine file or "
                          "--block-delete fixes it; with the switch on the path differs",
                   "on": f"{where}: verified with {switch} ON only (those lines are skipped), as the machine "
                         "file or --block-delete fixes it; with the switch off the path differs"}[modes[n]],)
    if stops:
        codes = sorted({k for k, _ in stops})
        names = {0: "M0 (program stop)", 1: "M1 (optional stop)", 60: "M60 (pallet change stop)"}
        notes += (f"{', '.join(names[k] for k in codes)} at line(s) "
                  f"{', '.join(str(n) for n in sorted({n for _, n in stops})[:10])}: no motion"
                  + ("; the path is the same with the optional-stop switch on or off" if 1 in codes else "")
                  + "; axes the operator moves while the program is stopped are not modelled",)
    return notes


def _merge_switch_combinations(runs: list[tuple[frozenset[int], Result]], free: list[int], complete: bool,
                               max_violations: int) -> Result:
    """One result from the runs of several switch combinations.

    A violation (a source line, zone, kind) is reported once, with the positions of the free switches it
    depends on (``Violation.switches``): a switch is left out when flipping it keeps the violation in every
    combination where it is found (then the witness is the one with that switch off); a violation found in
    every combination names none.  When not every combination was verified every free switch is named."""
    def key(v):
        return (v.line, v.zone, v.kind, v.break_line)

    found: dict[tuple, dict[frozenset[int], Violation]] = {}
    for combo, r in runs:
        for v in r.violations:
            found.setdefault(key(v), {}).setdefault(combo, v)
    violations: list[tuple[int, int, Violation]] = []
    order = {combo: k for k, (combo, _) in enumerate(runs)}
    for where in found.values():
        combos = set(where)
        named = [n for n in free if not complete or any(c ^ {n} not in combos for c in combos)]
        loose = set(free) - set(named)
        combo = min((c for c in combos if not c & loose), key=order.__getitem__)
        v = where[combo]
        violations.append((order[combo], len(violations), replace(
            v, switches=tuple((switch_name(n), "on" if n in combo else "off") for n in named))))
    violations.sort(key=lambda t: (t[0], t[1]))
    first = runs[0][1]
    reasons = list(first.reasons)
    for combo, r in runs[1:]:
        on = ", ".join(f"/{n}" for n in free if n in combo)
        for x in r.reasons:
            if (x.message, x.span) not in {(y.message, y.span) for y in first.reasons} and \
                    x.message not in {y.message for y in reasons}:
                reasons.append(replace(x, message=x.message + f" (with the block-skip switch(es) {on} on)"))
    stats: dict[str, Any] = dict(first.stats)
    notes = list(first.notes)
    splits = list(first.extra.get("splits", ()))
    counted = {id(first)}
    for _, r in runs[1:]:
        if id(r) in counted:  # a combination that took another's run (its path is the same): counted once
            continue
        counted.add(id(r))
        for k, count in r.stats:
            stats[k] = stats.get(k, 0) + count
        notes += [n for n in r.notes if n not in notes]
        splits += list(r.extra.get("splits", ()))
    out = [v for _, _, v in violations]
    verdict = Verdict.UNSAFE if out else (Verdict.UNKNOWN if reasons else Verdict.SAFE)
    return replace(first, verdict=verdict, violations=tuple(out[:max_violations]), reasons=tuple(reasons),
                   notes=tuple(notes), stats=tuple(stats.items()),
                   truncated=any(r.truncated for _, r in runs) or len(out) > max_violations,
                   extra={"splits": tuple(splits)})


def _verify_cases(source: ProgramSource, machine: Machine, options: VerifyOptions, skip: frozenset[int],
                  progress: Callable[..., object] | None, profile: RunProfile
                  ) -> tuple[Result, Interpretation, set[int]]:
    """Prove one combination of the block-skip switches (those on) over the parameter ranges: (result, first interpretation).

    The path is built per case: a branch that switches inside a range splits
    it (:mod:`nczones.prover.cases`), each case interpreted afresh with its
    nominal values inside it.  ``result.extra["splits"]`` lists where
    (parameter, value as ``--param`` writes it).
    """
    # nczones.prover.cases is imported for parameter ranges (a case's centre, a split) or several cases only
    ranges = options.ranges(machine)
    cases = [ranges]
    results, first_run, splits = [], None, []
    seen: set[int] = set()
    interpretations = 0
    fast = _line_count(source.text) >= FAST_PATH_MIN_LINES
    boxes = not fast or (options.effective_dialect(machine) == "fanuc" and _fanuc_boxes_first(source.text))
    while cases:
        box = cases.pop(0)
        if box:
            from ..prover.cases import centred

            case_machine, case_ranges = centred(machine, box)
        else:
            case_machine, case_ranges = machine, box
        run, result = _fanuc_boxes(source, case_machine, options, skip, progress, profile) if boxes else (None, None)
        if run is None or result is None:  # the short Fanuc route declined (or does not apply): the full path
            run = interpretation(source, case_machine, options, skip=skip, ranges=case_ranges, fast=fast)
            result = _verify_run(run, case_machine, replace(options, params=case_ranges), progress, profile)
        interpretations += 1
        for runner in run.runners:  # the Fanuc language layer: the block-skip switches its lines use
            seen |= getattr(runner, "seen_switches", set())
        if case_ranges and result.violations:
            # a violation names every ranged parameter: those its motion does not depend on at this
            # case's nominal value (another case's path may differ)
            nominal = {r.name: run.interpreter.written_deviation(r.name, F0) for r in case_ranges}
            result = replace(result, violations=tuple(
                replace(v, params=tuple(v.params) + tuple((n, x) for n, x in nominal.items()
                                                          if n not in dict(v.params)))
                for v in result.violations))
        split = run.interpreter.branch_split
        if split is not None:
            from ..prover.cases import MAX_CASES, budget_reason, split_box

            if interpretations + len(cases) + 3 <= MAX_CASES:
                at = split[1] + next(r.centre for r in case_ranges if r.name == split[0])
                splits.append((split[0], run.interpreter.written_deviation(split[0], split[1])))
                cases[0:0] = split_box(box, split[0], at)
                continue
            result = replace(result, reasons=result.reasons + (budget_reason(None),))
        first_run = first_run or run
        results.append(result)
        if result.interrupted:  # Ctrl-C: the remaining cases are not verified
            break
    if len(results) == 1:  # (what cases.merge gives one result)
        result = replace(results[0], params=ranges)
    else:
        from ..prover.cases import merge

        result = merge(results, max_violations=options.max_violations, params=ranges)
    # a witness must replay: one at values where the control stops before its line is dropped
    # (on the run's budget: an unchecked witness is not reported, VF203/VF204); only a witness at parameter
    # values has anything to replay (replayed_witnesses gives any other result back): without one, its module
    # is not imported (issue 36)
    if any(v.params for v in result.violations):
        from .witnesses import replayed_witnesses

        result = replayed_witnesses(result, machine, lambda m: interpretation(source, m, replace(options, params=()),
                                                                                skip=skip), options.run_limits())
    if splits:
        where = ", ".join(f"{n} = {format_decimal(v)}" for n, v in splits)
        result = replace(result, notes=result.notes + (f"the path branches inside the parameter ranges (a canned "
                                                       f"cycle's levels cross) at {where}: proved as separate "
                                                       "cases on each side and at the switching value",),
                         extra={"splits": tuple(splits)})
    assert first_run is not None  # the loop ran at least once (it starts with one case)
    return result, first_run, seen


def _solids_corner_check(machine: Machine, run: Interpretation, options: VerifyOptions) -> Any:
    """The proof of the tool solids over the corners the control may round
    (:class:`~nczones.prover.solids_blend.SolidsCornerCheck`); None without solids and fixtures."""
    if not declares_solids(machine):
        return None
    from ..solids import machine_solids

    solids = machine_solids(machine)
    if solids is None or not solids.fixtures:
        return None
    from ..prover.solids_blend import SolidsCornerCheck

    return SolidsCornerCheck(machine, solids, options.ranges(machine), run.interpreter.path_modes)


def _with_solid_corners(result: Result, check: Any, upto: int | None) -> Result:
    """``result`` with the reasons and notes (least clearances on the rounded path) of the solids' corner proof;
    a reason turns a ``safe`` verdict ``unknown``."""
    extra = tuple(check.finish((v.block for v in result.violations), upto))
    result = replace(result, notes=tuple(result.notes) + tuple(check.notes()))
    if not extra:
        return result
    verdict = Verdict.UNKNOWN if result.verdict is Verdict.SAFE else result.verdict
    return replace(result, verdict=verdict, reasons=result.reasons + extra)


def _verify_run(run: Interpretation, machine: Machine, options: VerifyOptions, progress: Any,
                profile: RunProfile) -> Result:
    """Prove one interpretation (one case): its result with source text, unknown codes and notes filled in."""
    from ..motion import MotionChunk

    # a progress callback with a true ``counts`` attribute (the CLI's bar) also gets the motions and
    # blocks executed so far, loops and subroutines counted as they run
    counts = bool(getattr(progress, "counts", False))
    total = _line_count(run.text) or None if progress is not None else None

    def report(line: int) -> None:
        assert progress is not None
        if counts:
            progress(line, total, motions=profile.motions, blocks=profile.blocks)
        else:
            progress(line, total)

    last_reported: list[int] = []

    def with_text(seq: Iterable[Any]) -> Iterator[Any]:
        if progress is None:  # the chunks as they come (verify_segments batches an object chunk's segments)
            yield from seq
            return
        for chunk in seq:
            if isinstance(chunk, MotionChunk) and chunk.scale is not None:
                yield chunk
                if progress is not None and len(chunk) and chunk.line is not None:
                    report(int(chunk.line[-1]))
                    last_reported[:] = [int(chunk.line[-1])]
            else:
                for s in chunk.segments():
                    yield s
                    if progress is not None and s.span is not None:
                        report(s.span.line)
                        last_reported[:] = [s.span.line]

    from ..prover.core import prove
    from ..prover.corners import Corners

    # the corners the control may round (specs/path-modes.md), proved as the motion passes (nczones.prover.blend,
    # loaded at the first corner)
    corners = Corners(machine, options.margin, options.ranges(machine), run.interpreter.path_modes,
                      options.run_limits())
    stream = corners.watch(with_text(_run_motion(run, machine, options)))
    solid_corners = _solids_corner_check(machine, run, options)
    if solid_corners is not None:  # the tool solids over the same corners
        stream = solid_corners.watch(stream)
    spindle = _spindle_check(machine, run)
    if spindle is not None:  # the tool the program put in the spindle against the assembly the solids take
        stream = spindle.watch(stream)
    result = prove(stream, machine, options, file=run.file, profile=profile)
    # the blocks executed (the proof counts those up to the last motion's), as the box route and the double pass
    # count them
    profile.blocks = max(profile.blocks, run.counts["blocks"])
    if not result.interrupted:
        upto = max(v.block for v in result.violations) if result.truncated and result.violations else None
        result = replace(result, reasons=result.reasons + tuple(corners.finish((v.block for v in result.violations),
                                                                              upto)))
        if solid_corners is not None:
            result = _with_solid_corners(result, solid_corners, upto)
        if spindle is not None:
            result = replace(result, reasons=result.reasons + spindle.reasons())
    if last_reported and counts:  # the motions decided after the last one read (segments are screened in batches)
        report(last_reported[0])
    # fill the source text of violations and reasons (column chunks carry only line numbers)
    spans = [*(v.span for v in result.violations), *(r.span for r in result.reasons),
             *(u.span for u in run.unsupported)]
    wanted = [s.line for s in spans if s is not None and not s.text and s.line >= 1]
    source_text = source_lines(run.text, wanted)
    violations = tuple(replace(v, span=_fix_span(v.span, source_text)) for v in result.violations)
    reasons = list(replace(r, span=_fix_span(r.span, source_text)) for r in result.reasons)
    reasons += _unsupported_reasons(run, source_text)
    notes = tuple(run.assumed_modal_text()) + tuple(run.notes()) + tuple(result.notes)  # + solids' clearances
    if run.counts.get("spline"):
        notes += (f"{run.counts['spline']} spline/NURBS motion(s) (G5, G5.1, G5.2, G6.2) were proved on the exact "
                  "programmed curve; a controller that approximates them (LinuxCNC turns some G5.2/G6.2 "
                  "curves into biarcs) may deviate from it, see specs/gcode-support.md",)
    verdict = Verdict.UNSAFE if violations else (Verdict.UNKNOWN if reasons else Verdict.SAFE)
    return replace(result, verdict=verdict, violations=violations, reasons=tuple(reasons), notes=notes)


def _unsupported_reasons(run: Interpretation, source_text: dict[int, str]) -> list[Reason]:
    """A reason for each code the run could not model (``run.unsupported``), with its line's text and hint;
    ``source_text``: the text of the lines wanted (:func:`source_lines`)."""
    if not run.unsupported:
        return []  # (the hints' module not imported: start-up, boot44)
    from ..gcode.dialects import unknown_hint

    reasons = []
    for u in run.unsupported:
        span = _fix_span(u.span, source_text)
        hint = unknown_hint(u.code, span.text, run.dialect) if span is not None and span.text else ""
        reasons.append(Reason(f"{u.code}: {u.reason}{hint}", span, None, reason_code(u.code)))
    return reasons


def _run_motion(run: Interpretation, machine: Machine, options: VerifyOptions) -> Iterable[Any]:
    """The interpretation's motion as the proof takes it: a Fanuc run's straight moves as column chunks, exactly.

    Not with parameter ranges: their motion goes one by one, as the corner check widens its boxes by them.
    """
    if run.dialect != "fanuc" or options.ranges(machine):
        return run
    from ..gcode.fanuc.columns import column_runs

    return column_runs(run, run.interpreter.axes, run.interpreter.file)


def _fix_span(span: Any, source_text: dict[int, str]) -> Any:
    """A span with its line's source text (column chunks and derived spans carry only the line number)."""
    if span is None or span.text or span.line not in source_text:
        return span
    return replace(span, text=source_text[span.line])


def _line_count(text: str) -> int:
    r"""Lines as spans number them (:func:`nczones.errors.program_lines`), without splitting the text.  The count of
    the last ``str`` counted is kept: the route tests and the cases' loop ask for the same text's (line44: one
    scan of a Fanuc program's text, some 1.4M instructions on 10,000 R arcs, not two).

    >>> _line_count("G1 X1\nG1 X2"), _line_count("G1 X1\n"), _line_count("")
    (2, 1, 0)
    """
    global _COUNTED
    last = _COUNTED
    if last[0] is text:
        return last[1]
    lines = text.count("\n") + (1 if text and not text.endswith("\n") else 0)
    if type(text) is str:  # (a str does not change; a streamed file's count is its own)
        _COUNTED = (text, lines)  # one tuple: a thread reads a text and its own count
    return lines


#: the last text :func:`_line_count` counted, and its count
_COUNTED: tuple[Any, int] = (None, 0)


def source_lines(text: str, wanted: Iterable[int], step: int = 1 << 16) -> dict[int, str]:
    r"""The text of the 1-based lines ``wanted`` (numbered as spans number them, see
    :func:`nczones.errors.program_lines`), without splitting the whole program: only the needed
    lines are cut out, so memory stays flat.

    >>> source_lines("G1 X1\nG1 X2\r\nG1 X3 (a\x0cb)", [3, 2, 9])
    {2: 'G1 X2', 3: 'G1 X3 (a\x0cb)'}
    """
    want = sorted(set(int(w) for w in wanted if w >= 1))
    if not want:
        return {}
    out = {}
    line, pos, n = 1, 0, len(text)
    for w in want:
        # skip whole windows by counting their newlines, then walk inside the window
        while line < w and pos < n:
            k = text.count("\n", pos, pos + step)
            if line + k < w:
                line += k
                pos += step
                continue
            while line < w:
                nl = text.find("\n", pos)
                if nl < 0:
                    pos = n
                    break
                pos = nl + 1
                line += 1
        if pos >= n:
            break
        nl = text.find("\n", pos)
        out[w] = text[pos:(n if nl < 0 else nl)].removesuffix("\r")
    if 1 in out:
        out[1] = out[1].removeprefix("\ufeff")
    return out
