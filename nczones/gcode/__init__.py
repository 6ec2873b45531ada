"""G-code front end: program text -> motion in machine coordinates.

Public API
----------
:func:`interpret` returns an :class:`Interpretation`, an iterable of
:class:`~nczones.motion.MotionChunk` that runs the program lazily (streaming,
memory independent of the program length); while and after iterating it
exposes :attr:`~Interpretation.unsupported` (why the result is ``unknown``),
:attr:`~Interpretation.assumed_modal` (modal groups the program relied on
without setting them) and :attr:`~Interpretation.counts`.
:func:`segments` is the convenience that returns every
:class:`~nczones.motion.Segment` in a list.  Both take a program *file*
(a ``str`` or ``PathLike`` path, or a :class:`~nczones.gcode.source.ProgramSource`);
:func:`interpret_text` and :func:`segments_text` take program text.  A ``str``
is never guessed to be text (see :mod:`nczones.gcode.source`).

Errors in the program raise :class:`~nczones.errors.GcodeError` (codes
``GC1xx`` lexical, ``GC2xx`` block/modal, ``GC3xx`` interpretation) with a
``file:line:column`` span, during iteration.

>>> from nczones.machine import parse_machine
>>> m = parse_machine('''
... [machine]
... axes = ["X", "Y"]
... pulse = "0.001"
... [machine.rapid]
... X = "1000"
... Y = "1000"
... [machine.reference]
... X = "0"
... Y = "299"
... ''')
>>> segs = segments_text("G91 G1 F100" + " Y0.1" * 0 + "\\n" + "Y0.1\\n" * 10, m)
>>> segs[-1].end
(Fraction(0, 1), Fraction(300, 1))
>>> run = interpret_text("G1 X1 F10\\nG41 X2\\nG1 X3\\n", m)
>>> [s.end[0] for c in run for s in c.segments()]
[Fraction(1, 1)]
>>> run.status, run.unsupported[0].code, run.unsupported[0].span.line
('unknown', 'G41', 2)
"""

from __future__ import annotations

import os
from collections.abc import Collection, Iterable, Iterator
from fractions import Fraction

from ..errors import GcodeError, InvalidArgument, program_lines
from ..machine import Machine
from ..motion import MotionChunk, Segment
from . import segments as _segments_module  # noqa: F401  # loaded first: the function segments() below keeps the name
from .runner_common import DEFAULT_MAX_LOOP_ITERATIONS
from .source import ProgramLike, ProgramSource, as_source, load_program, materialized, program_text

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from .interpreter import MODAL_GROUP_NAMES, Interpreter, Unsupported  # noqa: F401

#: An arc whose end point lies farther than this (mm) from the circle through
#: its start point around its centre is an error (GC301).
DEFAULT_ARC_TOLERANCE = Fraction(2, 1000)
#: Segments per object chunk.  Small on purpose: segments handed on young die young, so the
#: garbage collector's older generations (whose passes visit every segment still held) stay
#: small; measured on 100,000 plain lines: 4096 -> ~100k lines/s, 256 -> 111k, 128 -> 119k,
#: the same as with the collector off.
DEFAULT_CHUNK_SIZE = 128


def __getattr__(name: str) -> Any:
    """``Interpreter``, ``Unsupported`` and ``MODAL_GROUP_NAMES`` (:mod:`nczones.gcode.interpreter`), loaded
    when first used: a program the double pass proves needs none of them."""
    if name in ("Interpreter", "Unsupported", "MODAL_GROUP_NAMES"):
        from . import interpreter

        return getattr(interpreter, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "interpret",
    "interpret_text",
    "checked_options",
    "segments",
    "segments_text",
    "ProgramSource",
    "program_text",
    "load_program",
    "Interpretation",
    "Unsupported",
    "DEFAULT_ARC_TOLERANCE",
]


class Interpretation:
    """A lazily interpreted program: iterate it for :class:`MotionChunk` values.

    Iterate once; the attributes are filled while iterating and final after
    the iteration ends.

    Attributes
    ----------
    file : str
    unsupported : tuple of Unsupported
        Empty for a fully interpreted program.  Otherwise the first code that
        could not be modelled (line and reason); motion before it was emitted,
        nothing after it.
    assumed_modal : dict
        Modal group -> the machine's initial code that the program relied on
        without setting it (``{"units": "G21", "offset": "G54"}``).
    counts : dict
        ``blocks``, ``segments``, per-kind counts, ``fast_lines`` (lines that
        took the vectorized fast path).
    """

    def __init__(self, source: ProgramSource, machine: Machine, *, block_delete: bool | Collection[int],
                 track_dependencies: bool, arc_tolerance: Fraction | str, fast: bool, chunk_size: int,
                 max_loop_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS, dialect: str = "linuxcnc",
                 library: Any = None, param_ranges: tuple = ()):
        self.source = source
        text = self.text = source.text
        if not fast:
            # a streamed file (FileText) is read block by block only by the fast path (the language layer
            # takes the whole text, see run_with_fastpath)
            text = self.text = materialized(text)
        if dialect == "fanuc" and (not isinstance(text, str) or "$" in text):  # (a path header is "$n")
            from .fanuc.paths import select_path

            text = self.text = select_path(text, machine.fanuc.path, source.name)
        self.machine = machine
        self.file = source.name
        self.block_delete = block_delete
        self.max_loop_iterations = max_loop_iterations
        self.dialect = dialect
        self.library = library
        #: LinuxCNC: the folders ``o<name> call`` reads ``name.ngc`` from (``library``: one folder or several,
        #: then the machine file's [linuxcnc] subroutine_path)
        self.subroutine_path: tuple = () if dialect == "fanuc" else linuxcnc_library(library, machine)
        #: the subroutine files the run read (path -> the runner's state of it)
        self.subroutine_files: dict[str, dict] = {}
        #: The Fanuc language layer's runners (one per piece of the program it read), for their notes.
        self.runners: list = []
        self._variables: Any = None
        cls: type[Interpreter]
        lathe = False
        if dialect == "fanuc":
            cylindrical = False
            if machine.is_lathe:  # the lathe module (polar, turning) only for a lathe: a mill's start-up skips it
                from .fanuc.lathe import FanucLatheInterpreter

                cls = FanucLatheInterpreter
            else:
                from .fanuc.interpreter import FanucInterpreter

                cls = FanucInterpreter
        else:
            from .mentions import uses_cylindrical, uses_lathe

            cylindrical = uses_cylindrical(text)  # G07.1/G107: the mode's interpreter, no fast path
            lathe = bool(machine.diameter_axes) or uses_lathe(text)  # G7/G8, G70-G72: no fast path either
            from .interpreter import Interpreter

            cls = Interpreter
            if cylindrical and lathe:
                cls = _cylindrical_lathe()
            elif cylindrical:
                from .cylindrical import CylindricalInterpreter

                cls = CylindricalInterpreter
            elif lathe:
                from .linuxcnc.lathe import LatheInterpreter

                cls = LatheInterpreter
        self.interpreter = cls(machine, file=self.file, arc_tolerance=arc_tolerance,
                               track_dependencies=track_dependencies, chunk_size=chunk_size,
                               param_ranges=param_ranges)
        self.interpreter.max_repeats = max_loop_iterations  # a canned cycle's repeats and pecks count too
        # lathes read diameters, U/W words and cycles with shapes: no fast path
        self.fast = fast and not self.interpreter.track and not cylindrical and not machine.is_lathe \
            and not machine.diameter_axes and not lathe
        self.fast_lines = 0
        self._started = False
        self.finished = False

    def __iter__(self) -> Iterator[MotionChunk]:
        if self._started:
            raise InvalidArgument("an Interpretation can be iterated only once; call interpret() again")
        self._started = True
        try:
            if self.fast:
                from .fastpath import run_with_fastpath

                yield from run_with_fastpath(self)
            else:
                self.text = materialized(self.text)
                yield from self.interpreter.run(self.blocks(self.text))
        except GcodeError as exc:
            from .dialects import with_hints

            raise with_hints(exc, self.dialect) from None
        finish = getattr(self.interpreter, "finish", None)
        if finish is not None:
            finish()
        left = getattr(self.interpreter, "emitted", None)
        if left:  # moves cutter compensation held until the end of the text
            yield MotionChunk(self.interpreter.axes, None, objects=tuple(left), file=self.file)
            self.interpreter.emitted = []
        self.finished = True

    def blocks(self, text: str, first_line: int = 1, first_index: int = 0, fast_runs: Any = None) -> Iterator[Any]:
        """The language layer of this dialect over ``text`` (the whole program, or for the Fanuc dialect a
        piece of it starting at ``first_line``): its blocks, ending as ``unknown`` at an unsupported code."""
        it = self.interpreter
        if self.dialect != "fanuc":
            yield from program_blocks(text, self.file, self.block_delete, it, max_loop_iterations=self.max_loop_iterations,
                                      library=self.subroutine_path, files=self.subroutine_files)
            return
        from .fanuc.program import FanucRunner
        from .runner_common import StringSource

        runner = FanucRunner(StringSource(text), self.file, self.fanuc_variables(), settings=self.machine.fanuc,
                             block_delete=self.block_delete, library=self.library, state=it,
                             max_loop_iterations=self.max_loop_iterations, first_line=first_line,
                             first_index=first_index, fast_runs=fast_runs, lane=it.lane_for_blocks())
        self.runners.append(runner)
        yield from unknown_at_unsupported(it, runner.run())

    def fanuc_variables(self):
        """The Fanuc variables all pieces of the program share (commons from the machine file)."""
        if self._variables is None:
            from .fanuc.expr import FanucVariables

            self._variables = FanucVariables(dict(self.machine.fanuc.variables))
            self.interpreter.bind_variables(self._variables)  # type: ignore[attr-defined]
        return self._variables

    @property
    def alarm(self):
        """``(number, message, span)`` of the Fanuc ``#3000`` alarm that stopped the program, or None."""
        return next((r.alarm for r in self.runners if r.alarm is not None), None)

    def notes(self) -> list[str]:
        """What the report should say about how the program was read (dialect-specific)."""
        if self.dialect != "fanuc":
            return [f"o<{os.path.splitext(os.path.basename(f))[0]}> read from the subroutine file {f} (the proof holds for its text as read)"
                    for f in self.subroutine_files]
        from .fanuc.program import fanuc_notes

        return fanuc_notes(self)

    @property
    def unsupported(self) -> tuple[Unsupported, ...]:
        return tuple(self.interpreter.unsupported)

    @property
    def status(self) -> str:
        """``"unknown"`` if a code could not be modelled, else ``"complete"``."""
        return "unknown" if self.interpreter.unsupported else "complete"

    @property
    def assumed_modal(self) -> dict[str, str]:
        return dict(self.interpreter.assumed)

    def assumed_modal_text(self) -> list[str]:
        """Human-readable lines for the report."""
        from .runner_common import assumed_modal_notes

        return assumed_modal_notes(self.assumed_modal.items(), self.interpreter.machine.modal, self.interpreter.dialect)

    @property
    def counts(self) -> dict[str, int]:
        it = self.interpreter
        out = {"blocks": it.blocks, "segments": it.segment_count, "fast_lines": self.fast_lines}
        for k, v in it.kind_counts.items():
            out[k.name.lower()] = v
        return out

    def segments(self) -> Iterator[Segment]:
        """Iterate segment views of every chunk, each span carrying its source line."""
        lines: dict[int, str] = {}
        for chunk in self:
            if chunk.scale is not None and not lines:
                lines = dict(enumerate(program_lines(materialized(self.text)), start=1))
            yield from chunk.segments(lines)


def _cylindrical_lathe() -> type:
    """The interpreter of a LinuxCNC program with both G07.1 and lathe codes (or a diameter axis)."""
    from .cylindrical import CylindricalInterpreter
    from .linuxcnc.lathe import LatheInterpreter

    return type("CylindricalLatheInterpreter", (CylindricalInterpreter, LatheInterpreter), {})


def linuxcnc_library(library: Any, machine: Any) -> tuple:
    """The folders a LinuxCNC program's ``o<name> call`` reads ``name.ngc`` from: ``library`` (a folder, a
    list of folders, or an ``os.pathsep``-separated string of them), then the machine file's
    ``[linuxcnc] subroutine_path``."""
    out: list = []
    if isinstance(library, (str, os.PathLike)):
        out += [p for p in os.fspath(library).split(os.pathsep) if p]
    elif library is not None:
        out += [os.fspath(p) for p in library]
    out += list(getattr(machine, "subroutine_path", ()) or ())
    return tuple(out)


def program_blocks(text: str, file: str, block_delete: bool | Collection[int], interpreter: Interpreter | None = None,
            first_line: int = 1, max_loop_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS,
            library: Collection = (), files: dict | None = None) -> Iterator[Any]:
    """The language layer's blocks; an UnsupportedGcode ends them as ``unknown``."""
    from .expr import Parameters
    from .program import iter_blocks

    params = Parameters()
    if interpreter is None:
        yield from iter_blocks(text, file=file, params=params, block_delete=block_delete,
                               max_loop_iterations=max_loop_iterations, library=library, files=files)
        return
    interpreter.bind_parameters(params)
    yield from unknown_at_unsupported(interpreter,
                                       iter_blocks(text, file=file, params=params, block_delete=block_delete,
                                                   max_loop_iterations=max_loop_iterations,
                                                   lane=interpreter.lane_for_blocks(), library=library,
                                                   files=files))


def unknown_at_unsupported(interpreter: Interpreter, blocks: Iterable[Any]) -> Iterator[Any]:
    """``blocks``; an UnsupportedGcode ends them, recorded as the interpreter's ``unknown`` reason."""
    from .runner_common import UnsupportedGcode

    try:
        yield from blocks
    except UnsupportedGcode as exc:
        d = exc.diagnostic
        from .interpreter import Unsupported

        interpreter.unsupported.append(Unsupported(d.code, d.message, d.span))


def interpret(
    source: ProgramLike,
    machine: Machine,
    *,
    file: str | None = None,
    block_delete: bool | Collection[int] = False,
    track_dependencies: bool = False,
    arc_tolerance: Fraction | str | None = None,
    fast: bool = True,
    chunk_size: int = DEFAULT_CHUNK_SIZE,
    max_loop_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS,
    dialect: str | None = None,
    library: str | os.PathLike | None = None,
    param_ranges: Iterable[Any] = (),
) -> Interpretation:
    """Interpret the G-code program file ``source`` for a machine (lazily).

    Parameters
    ----------
    source : str, path or ProgramSource
        The program file (a ``str`` is a path, never program text: use
        :func:`interpret_text` for text), or a
        :class:`~nczones.gcode.source.ProgramSource` already read.  A file
        that cannot be read is :class:`~nczones.errors.GcodeError` ``GC100``;
        binary or non-UTF-8 bytes ``GC108``; an over-long line ``GC110``.
    machine : Machine
    file : str, optional
        Name used in diagnostics (default: the path as given).
    block_delete : bool or collection of int
        True skips blocks starting with ``/`` (the block-delete switch is on);
        default False executes them, as LinuxCNC does by default.  A collection
        names the switches that are on (Fanuc ``/1`` .. ``/9``, ``/`` is 1;
        LinuxCNC's one switch is 1): ``{2}`` skips the ``/2`` lines only.
    track_dependencies : bool
        Fill ``Segment.deps_start/deps_end`` for parameter ranges (disables
        the fast path).
    arc_tolerance : Fraction, decimal str, "linuxcnc" or "grbl"
        Largest allowed mismatch (mm) of an arc's end point with its circle
        (default: the machine file's ``arc_tolerance``, else 0.002 mm).
        ``"grbl"`` is Grbl's rule as nczones takes it: I/J/K arcs off by at
        most 0.005 mm, R arcs not short at all.  ``"linuxcnc"`` accepts exactly the I/J/K arcs
        LinuxCNC accepts (0.028 mm, or up to 2.8 mm within 0.1 %) and R arcs
        short by at most 0.00127 mm; an accepted arc whose end is off its
        circle is modelled as the spiral the machine moves.
    fast : bool
        Use the vectorized fast path for CAM-style runs of lines (identical
        segments; see :mod:`nczones.gcode.fastpath`).
    chunk_size : int
        Segments per chunk of the full interpreter.
    max_loop_iterations : int
        Iterations allowed per loop (per entry into it); a loop that runs
        longer ends the interpretation as ``unknown`` (``GC302``).
    dialect : "linuxcnc" or "fanuc", optional
        How the text is read (default: the machine's ``[machine] dialect``); see ``specs/fanuc.md``.
    library : path, optional
        A folder of subprogram files (``O1234``, ``O1234.nc``, ...) that Fanuc ``M98``/``G65`` calls
        search when the program is not in the file.
    param_ranges : iterable of ParamRange
        The parameters verified over ranges (implies ``track_dependencies``):
        a state parameter read (``#5221``) whose value depends on one of
        them makes the interpretation unknown at that read.

    Returns
    -------
    Interpretation
    """
    src = as_source(source, file=file, text_function="interpret_text")
    tol = checked_options(machine, arc_tolerance, max_loop_iterations, dialect)
    dialect = machine.dialect if dialect is None else dialect
    return Interpretation(src, machine, block_delete=block_delete, track_dependencies=track_dependencies,
                          arc_tolerance=tol, fast=fast, chunk_size=chunk_size,
                          max_loop_iterations=max_loop_iterations, dialect=dialect, library=library,
                          param_ranges=tuple(param_ranges))


def checked_options(machine: Machine, arc_tolerance: Fraction | str | None, max_loop_iterations: int,
                    dialect: str | None) -> Fraction | str:
    """The arc tolerance as :func:`interpret` takes it, after the checks of its options
    (:class:`~nczones.errors.InvalidArgument` for a negative tolerance, an iteration bound that is not a
    positive integer, an unknown dialect).

    >>> checked_options(None, "0.002", 10, "linuxcnc")
    Fraction(1, 500)
    """
    from ..exact import exact

    if arc_tolerance is None:  # the machine file's, else the default
        arc_tolerance = getattr(machine, "arc_tolerance", None)
        if arc_tolerance is None:
            arc_tolerance = DEFAULT_ARC_TOLERANCE
    tol: Fraction | str = arc_tolerance if arc_tolerance in ("linuxcnc", "grbl") else exact(arc_tolerance)
    if isinstance(tol, Fraction) and tol < 0:
        raise InvalidArgument(f"arc_tolerance must not be negative, got {arc_tolerance!r}")
    if not isinstance(max_loop_iterations, int) or isinstance(max_loop_iterations, bool) or max_loop_iterations < 1:
        raise InvalidArgument(f"max_loop_iterations must be a positive integer, got {max_loop_iterations!r}")
    dialect = machine.dialect if dialect is None else dialect
    if dialect not in ("linuxcnc", "fanuc"):
        raise InvalidArgument(f"dialect must be \"linuxcnc\" or \"fanuc\", got {dialect!r}")
    return tol


def interpret_text(text: str, machine: Machine, *, file: str = "<program>", **options: Any) -> Interpretation:
    """Interpret program *text* (``file`` names it in diagnostics); options as :func:`interpret`.

    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('[machine]\\naxes=["X"]\\n[machine.rapid]\\nX="1000"\\n[machine.reference]\\nX="0"\\n')
    >>> [s.end for s in interpret_text("G1 X2 F10\\n", m).segments()]
    [(Fraction(2, 1),)]
    """
    return interpret(program_text(text, file), machine, **options)


def segments(source: ProgramLike, machine: Machine, **options: Any) -> list[Segment]:
    """Every segment of the program file ``source`` as a list (holds them all in memory).

    Takes the options of :func:`interpret`.  Check
    ``interpret(...).unsupported`` when the result must be complete; this
    convenience returns the segments emitted before an unsupported code.
    """
    return list(interpret(source, machine, **options).segments())


def segments_text(text: str, machine: Machine, *, file: str = "<program>", **options: Any) -> list[Segment]:
    """:func:`segments` of program *text*."""
    return list(interpret_text(text, machine, file=file, **options).segments())
