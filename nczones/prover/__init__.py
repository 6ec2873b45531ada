"""The prover: does every motion of a program stay inside the allowed set?

Public API
----------
:func:`verify` (a program file + machine; also named :func:`verify_file`),
:func:`verify_text` (program text + machine) and :func:`verify_segments`
(motion segments, no text) return a :class:`Result` with an ordered
:class:`Verdict` (``UNSAFE < UNKNOWN < SAFE``, so "worst wins" is ``min``),
the re-checked counterexamples (:class:`Violation`), the reasons for
``unknown`` and the solver version.  :func:`parse_param` reads
``NAME=LO..HI`` parameter ranges.

>>> from nczones.machine import parse_machine
>>> m = parse_machine('''
... [machine]
... axes = ["X", "Y"]
... [machine.rapid]
... X = "1000"
... Y = "1000"
... [machine.reference]
... X = "0"
... Y = "0"
... [[zones]]
... name = "travel"
... kind = "box"
... min = { X = "0", Y = "0" }
... max = { X = "10", Y = "10" }
... ''')
>>> verify_text("G1 X10 Y10 F100\\n", m).verdict.label
'safe'
>>> r = verify_text("G1 X10 F100\\nG3 X10 Y10 I0 J5\\n", m)
>>> r.verdict.label, r.violations[0].line, r.violations[0].zone
('unsafe', 2, 'travel')
"""

from __future__ import annotations

import os
from collections.abc import Callable
from fractions import Fraction

from ..gcode.runner_common import DEFAULT_MAX_LOOP_ITERATIONS
from ..gcode.source import ProgramLike, ProgramSource, as_source, program_text
from ..machine import Machine
from .limits import DEFAULT_BUDGET_S, RunLimits
from .options import ParamError, VerifyOptions, parse_param
from .result import ParamRange, Reason, Result, Verdict, Violation

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = [
    "verify",
    "verify_file",
    "verify_text",
    "verify_segments",
    "prove",
    "parse_param",
    "ParamError",
    "VerifyOptions",
    "Verdict",
    "Result",
    "Violation",
    "Reason",
    "ParamRange",
    "Prover",
    "source_lines",
    "RunLimits",
    "DEFAULT_BUDGET_S",
]


def verify(
    program: ProgramLike,
    machine: Machine,
    *,
    margin: Fraction | str | int = 0,
    params: tuple[ParamRange, ...] | list[str] | tuple[str, ...] = (),
    engine: str = "auto",
    max_violations: int = 20,
    file: str | None = None,
    arc_tolerance: Fraction | str | None = None,
    progress: Callable[[int, int | None], object] | None = None,
    recovery: str | None = None,
    max_iterations: int = DEFAULT_MAX_LOOP_ITERATIONS,
    dialect: str | None = None,
    library: str | os.PathLike | None = None,
    block_delete: str | None = None,
    budget_s: float | None = DEFAULT_BUDGET_S,
    limits: RunLimits | None = None,
) -> Result:
    """Verify the G-code program *file* ``program`` on a machine (DESIGN §5).

    ``program`` is a path (``str`` or ``PathLike``: a ``str`` is never read
    as G-code text, use :func:`verify_text` for text) or a
    :class:`~nczones.gcode.source.ProgramSource`.  A file that cannot be
    read, is not UTF-8 text, or is empty raises
    :class:`~nczones.errors.GcodeError` (``GC100``, ``GC108``, ``GC109``).

    ``params`` may be :class:`ParamRange` values or ``"NAME=LO..HI"`` strings.
    ``arc_tolerance`` is passed to the interpreter (largest end-point mismatch
    of an I/J arc; such arcs are proved as spirals, over-approximated).
    ``max_iterations`` bounds every loop of the program (per entry into it);
    a loop that runs longer makes the verdict ``unknown`` (``GC302``).
    A code the interpreter cannot model makes the verdict ``unknown`` unless
    a violation before it already makes it ``unsafe``.  G-code errors raise
    :class:`~nczones.errors.GcodeError`.  ``progress``, if given, is called as
    ``progress(line, total_lines)`` after each chunk of motion is checked
    (see :mod:`nczones.report.progress`).

    ``recovery="start"|"breakpoint"`` also proves the machine's automatic
    tool-break recovery (``[tool_change]``) from every break point of every
    cutting motion (:mod:`nczones.prover.recovery`); its violations have
    ``kind == "recovery"``.

    ``block_delete`` (default: the machine file's ``block_delete``, itself
    ``"both"`` by default) says which positions of the block-delete switches
    the proof covers (:mod:`nczones.blockskip`; Fanuc ``/1`` .. ``/9``,
    LinuxCNC one switch): ``"both"`` verifies a program that has lines
    starting with ``/`` with each switch it uses off (the lines run) and on
    (they are skipped), in every combination (:func:`switch_combinations`,
    past :data:`MAX_SWITCH_COMBINATIONS` unknown, VF206); a violation names
    the positions of the switches it depends on (``Violation.switches``).
    ``"off"``/``"on"`` fix every switch, ``"1=on,2=off"`` single ones.  The
    notes of a program with ``/`` lines say what was verified; stops (M0,
    M1, M60) are noted too.

    ``dialect`` overrides the machine's ``[machine] dialect`` (``"linuxcnc"``
    or ``"fanuc"``, ``specs/fanuc.md``); ``library`` is a folder (or a list
    of folders, or folders joined by ``os.pathsep``, searched in order) of
    subprogram files: Fanuc ``M98``/``G65`` calls search it for ``O1234``
    files, a LinuxCNC ``o<name> call`` of a sub the program does not define
    reads ``name.ngc`` from it (LinuxCNC's ``SUBROUTINE_PATH``).

    ``budget_s`` (seconds, None for none) bounds the solver work and
    refinement of the whole run (:mod:`nczones.prover.limits`): what it
    leaves undecided is ``unknown`` ("budget spent").  Ctrl-C during the run
    returns the partial result with :attr:`Result.interrupted` set.

    The result names what was verified (:attr:`Result.program_sha256`, the
    machine file and its SHA-256) and every setting that changes the verdict
    (:attr:`Result.settings`), so ``nczones replay`` can re-check it.

    >>> from nczones.machine import load_machine
    >>> r = verify("specs/examples/programs/notch_dip.ngc", load_machine("specs/machines/grinder.toml"))
    >>> r.verdict.label, r.violations[0].line, r.program_sha256[:12]
    ('unsafe', 5, '421c2299bb06')
    >>> verify("specs/examples/programs/O1000", load_machine("specs/machines/grinder.toml"))
    Traceback (most recent call last):
    ...
    nczones.errors.GcodeError: specs/examples/programs/O1000: error[GC100]: cannot read the program: No such file or directory
    """
    source = as_source(program, file=file, text_function="verify_text").require_code()
    options = VerifyOptions.from_keywords(
        margin=margin, params=params, engine=engine, max_violations=max_violations, arc_tolerance=arc_tolerance,
        recovery=recovery, max_iterations=max_iterations, dialect=dialect, library=library,
        block_delete=block_delete, budget_s=budget_s, limits=limits)
    return _run(source, machine, options, progress)


#: :func:`verify` under the name that says what it takes.
verify_file = verify


def verify_text(text: str, machine: Machine, *, file: str = "<program>", **options: Any) -> Result:
    """Verify program *text* (``file`` names it in reports); options as :func:`verify`.

    Empty text (or whitespace only) raises :class:`~nczones.errors.GcodeError` ``GC109``.
    """
    source = program_text(text, file).require_code()
    progress = options.pop("progress", None)
    return _run(source, machine, VerifyOptions.from_keywords(**options), progress)


def _run(source: ProgramSource, machine: Machine, options: VerifyOptions,
         progress: Callable[..., object] | None) -> Result:
    """The pipeline (:mod:`nczones.pipeline`, above the prover: the public entry points of the package hand
    the program over to it; the prover itself proves motion, :func:`prove`)."""
    from ..pipeline.verification import verify_source

    return verify_source(source, machine, options, progress=progress)


#: Loaded when first used: the prover's driver (a program the double pass proves needs none of it) and the
#: names of the pipeline that earlier versions exported from here.
_LAZY = {"Prover": "core", "verify_segments": "core", "prove": "core"}
_PIPELINE = ("source_lines", "switch_combinations", "switch_name", "MAX_SWITCH_COMBINATIONS",
             "FAST_PATH_MIN_LINES")


def __getattr__(name: str) -> Any:
    """``Prover``, ``verify_segments`` and ``prove`` (:mod:`nczones.prover.core`), and the pipeline's
    ``source_lines``, ``switch_combinations``, ... (:mod:`nczones.pipeline.verification`), loaded when first used."""
    if name in _LAZY:
        from . import core

        return getattr(core, name)
    if name in _PIPELINE:
        from ..pipeline import verification as pipeline

        return getattr(pipeline, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
