"""What every subcommand shares: its exit statuses, how it reads the common arguments, how it fails.

The subcommands (one module each in :mod:`nczones.commands`) import these; :mod:`nczones.cli` imports them
too (the exit statuses and :func:`report_failure`), and no subcommand imports :mod:`nczones.cli`.  This module
is loaded by every start of the program (``nczones --help`` included), so it imports nothing heavy: each helper
imports the stage it needs when it is called.

* **Exit statuses** (DESIGN §8): :data:`EXIT_OK` … :data:`EXIT_TERMINATED`.
* **Arguments**: ``--dialect``/``--library`` (:func:`add_dialect_arguments`, :func:`with_dialect`,
  :func:`library_folder`), the program (:func:`program_source`), ``--arc-tolerance`` (:func:`arc_tolerance`),
  ``--budget`` (:func:`budget_seconds`).
* **Failures**: a bad option is :func:`usage_error` (an ``InputError`` at ``<command line>``); whatever a
  command raises is told by :func:`report_failure`: a user error one line and exit 2, a missing optional
  dependency ``PK101`` (:func:`missing_extra`), a bug a traceback and exit 4.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Mapping
from fractions import Fraction
from types import MappingProxyType

from ..errors import Diagnostic, InputError, InvalidArgument, NczonesError

# typing is not imported by `nczones --help` (issue 36); a type checker takes this name as true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, TextIO

    from ..gcode.source import ProgramSource
    from ..machine import Machine

__all__ = ["EXIT_OK", "EXIT_FAIL", "EXIT_INPUT", "EXIT_UNKNOWN", "EXIT_INTERNAL", "EXIT_INTERRUPTED",
           "EXIT_TERMINATED", "EXTRAS", "usage_error", "add_dialect_arguments", "with_dialect", "library_folder",
           "program_source", "arc_tolerance", "budget_seconds", "missing_extra", "report_failure",
           "standard_output", "closed_output", "output_closed", "tell_beside_file"]

EXIT_OK = 0
EXIT_FAIL = 1
EXIT_INPUT = 2
EXIT_UNKNOWN = 3
EXIT_INTERNAL = 4
#: Ctrl-C (SIGINT) stopped the run: 128 + 2, as shells report it.
EXIT_INTERRUPTED = 130
#: SIGTERM (a CI job cancelled, ``timeout``) stopped the run: 128 + 15.  The run stops as for Ctrl-C (the
#: partial report, VF204) and exits with this status.
EXIT_TERMINATED = 143

#: The optional dependencies by top-level module: the extra that installs each (pyproject.toml).  The core
#: install (``pip install nczones``) is what ``verify`` needs; a command that needs a missing one stops with
#: one line naming the extra (``PK101``, exit 2).
EXTRAS: Mapping[str, str] = MappingProxyType({
    "matplotlib": "plot", "shapely": "plot", "dask": "fleet", "distributed": "fleet",
})


def usage_error(code: str, message: str) -> InputError:
    """The error of a bad command-line option or argument (exit 2), located at ``<command line>``.

    >>> print(usage_error("VF106", "standard input (-) can be read only once").render())
    <command line>: error[VF106]: standard input (-) can be read only once
    """
    return InputError(Diagnostic(code, message, file="<command line>"))


def add_dialect_arguments(p: argparse.ArgumentParser) -> None:
    """``--dialect`` and ``--library``, for the commands that read a program."""
    p.add_argument("--dialect", choices=("linuxcnc", "fanuc"), default=None,
                   help="how the program text is read (default: the machine file's [machine] dialect, else "
                        "linuxcnc); see specs/fanuc.md")
    p.add_argument("--library", metavar="DIR", default=None, action="append",
                   help="a folder of subprogram files: Fanuc M98/G65 calls read O1234, O1234.nc, ... from it, "
                        "LinuxCNC 'o<name> call' reads name.ngc (as SUBROUTINE_PATH) when the program does not "
                        "define the subroutine; LinuxCNC: repeatable, or folders separated by "
                        f"{os.pathsep!r}, searched in order")


def with_dialect(machine: Machine, dialect: str | None) -> Machine:
    """The machine with ``--dialect`` applied (its ``[machine] dialect`` otherwise)."""
    if dialect is None or dialect == machine.dialect:
        return machine
    from dataclasses import replace

    return replace(machine, dialect=dialect)


def library_folder(path: str | list[str] | None) -> str | None:
    """``--library DIR`` (repeated, or folders joined by ``os.pathsep``): existing folders, joined by
    ``os.pathsep`` in the order given, or an input error (exit 2)."""
    from ..prover.options import library_folders

    return library_folders(path)


def program_source(name: str, *, stream: bool = False) -> ProgramSource:
    """The program ``name`` names: ``-`` is standard input, anything else a file (``GC1xx`` errors); ``stream``:
    a large plain file is left on disk and read as it is verified (:func:`nczones.gcode.source.load_program`)."""
    from ..gcode.source import load_program, read_stdin

    return (read_stdin() if name == "-" else load_program(name, stream=stream)).require_code()


def arc_tolerance(text: str | None) -> Fraction | str | None:
    """``--arc-tolerance``: "linuxcnc", "grbl" or a non-negative decimal (mm); None (not given) stays None.

    >>> arc_tolerance("0.002"), arc_tolerance("linuxcnc")
    (Fraction(1, 500), 'linuxcnc')
    """
    from ..prover.options import arc_tolerance_option

    return arc_tolerance_option(text)


def budget_seconds(text: str | None) -> float | None:
    """``--budget``: positive seconds, or "none" (``VF109``; :func:`nczones.prover.options.budget_seconds`)."""
    from ..prover.options import budget_seconds as read

    return read(text)


def missing_extra(exc: BaseException, command: str = "") -> Diagnostic | None:
    """The ``PK101`` diagnostic for an import of an optional dependency that is not installed (else None).

    >>> print(missing_extra(ModuleNotFoundError("No module named 'matplotlib'", name="matplotlib"), "plot").render())
    <environment>: error[PK101]: nczones plot needs matplotlib, which is not installed: pip install 'nczones[plot]' (or 'nczones[all]')
    >>> missing_extra(ModuleNotFoundError("No module named 'foo'", name="foo")) is None
    True
    """
    if not isinstance(exc, ModuleNotFoundError) or not exc.name:
        return None
    top = exc.name.split(".")[0]
    extra = EXTRAS.get(top)
    if extra is None:
        return None
    if extra == "plot" and command in ("verify", "replay"):
        extra = "html"  # the same packages, named for what they serve there (--format html)
    who = f"nczones {command}" if command else "this command"
    return Diagnostic("PK101", f"{who} needs {top}, which is not installed: pip install 'nczones[{extra}]' "
                               "(or 'nczones[all]')", file="<environment>")


def report_failure(exc: BaseException, command: str = "") -> int:
    """Tell what stopped ``command`` on standard error and return its exit status: a user error (bad input, a
    missing extra, a file that cannot be read or written) one line and 2, Ctrl-C 130, a bug its traceback and
    a request to report it, 4."""
    if isinstance(exc, InputError):
        print(exc.render(), file=sys.stderr)
        return EXIT_INPUT
    if isinstance(exc, InvalidArgument):
        print(f"nczones: error: {exc}", file=sys.stderr)
        return EXIT_INPUT
    if isinstance(exc, NczonesError):
        print(f"nczones: internal error: {exc}\nThis is a bug in nczones; please report it.", file=sys.stderr)
        return EXIT_INTERNAL
    if isinstance(exc, KeyboardInterrupt):
        print("nczones: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    missing = missing_extra(exc, command)
    if missing is not None:
        print(missing.render(), file=sys.stderr)
        return EXIT_INPUT
    if isinstance(exc, OSError):
        # reading or writing the user's files and streams (one line, never a traceback)
        _quiet_stdout(exc)
        where = f" {exc.filename}" if exc.filename is not None else (
            " standard output" if isinstance(exc, BrokenPipeError) else "")
        print(f"nczones: error: cannot read or write{where}: {exc.strerror or exc}", file=sys.stderr)
        return EXIT_INPUT
    import traceback  # a bug's report only: not imported at every start

    traceback.print_exception(exc)
    print("nczones: internal error (the traceback above is a bug in nczones; please report it)", file=sys.stderr)
    return EXIT_INTERNAL


def standard_output() -> TextIO:
    """``sys.stdout``, or an :class:`OSError` when standard output is closed (Python sets ``sys.stdout`` to None
    when the process starts without file descriptor 1): :func:`report_failure` tells it as a user's error, as a
    full disk or a broken pipe, not as a bug (hunt43's F1)."""
    stream = sys.stdout
    if stream is None:
        raise _closed_error()
    return stream


def output_closed() -> bool:
    """Whether standard output is closed: ``sys.stdout`` None (the process started without file descriptor 1,
    ``cmd >&-``) or a closed stream (:func:`closed_output`'s says so too)."""
    stream = sys.stdout
    return stream is None or bool(getattr(stream, "closed", False))


def closed_output() -> Any:
    """What ``sys.stdout`` is while a command runs with standard output closed (``nczones.cli`` puts it there): a
    stream whose writing, flushing or bytes raise the :class:`OSError` that :func:`report_failure` tells as
    "cannot read or write: standard output is closed", exit 2.  Without it, ``print()`` with ``sys.stdout`` None
    writes nothing and the command would exit 0 with its output lost (mend44).  A line that only tells about a
    file the command wrote goes through :func:`tell_beside_file`, which leaves it out instead.  (The class is
    made here, when standard output is closed: not at every start, issue 36.)

    >>> closed_output().write("report")
    Traceback (most recent call last):
    OSError: [Errno 9] standard output is closed
    """

    class ClosedOutput:
        __slots__ = ()
        closed = True

        def write(self, text: str) -> int:
            raise _closed_error()

        def writelines(self, lines: object) -> None:
            raise _closed_error()

        def flush(self) -> None:
            raise _closed_error()

        def fileno(self) -> int:
            raise _closed_error()

        def isatty(self) -> bool:
            return False

        @property
        def buffer(self) -> object:  # (linuxcnc-filter writes the program's bytes there)
            raise _closed_error()

    return ClosedOutput()


def tell_beside_file(text: str) -> None:
    """Print ``text``, a line about a file the command wrote (``--output``: where it went, each program's
    summary), unless standard output is closed: then the file is the whole of the command's output, and the
    command succeeds without the line (as ``verify --output``, hunt43's F1)."""
    if not output_closed():
        print(text)


def _closed_error() -> OSError:
    import errno

    return OSError(errno.EBADF, "standard output is closed")


def _quiet_stdout(exc: OSError) -> None:
    """After a broken pipe, point standard output at /dev/null so the interpreter's final flush stays quiet."""
    if isinstance(exc, BrokenPipeError):
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
        except (OSError, ValueError):
            pass
