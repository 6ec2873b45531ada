"""The ``nczones`` command line (DESIGN §8): it builds the parser from the table of subcommands and runs one.

Exit status of ``verify``: 0 safe, 1 unsafe, 2 bad input, 3 unknown.  Other
commands: 0 success, 1 an alarm or a refuted property, 2 bad input.  An
internal bug exits 4 with a traceback and a request to report it; a user error
never prints a traceback (:mod:`nczones.commands.conventions`).

The subcommands are the rows of :data:`nczones.commands.COMMANDS`, one module
each in :mod:`nczones.commands`; a command's module is imported only when that
command runs (or when :func:`build_parser` builds every command), so
``nczones --help`` and a command stay clear of what the other commands import.
This module only builds the parser and dispatches: what the commands share is in
:mod:`nczones.commands.conventions`, and no command imports this module.
"""

from __future__ import annotations

import _signal  # type: ignore[import-not-found]  # signal's functions, not the module's enums (issue 36)
import argparse
import sys
from collections.abc import Callable, Sequence

from . import __version__
from .commands import COMMANDS, configurer
from .commands.conventions import (
    EXIT_INTERRUPTED,
    EXIT_TERMINATED,
    closed_output,
    output_closed,
    report_failure,
)

# typing is not imported by `nczones --help` (issue 36); a type checker takes this name as true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, NoReturn

__all__ = ["main", "run", "build_parser", "chosen_command", "sigterm_as_interrupt"]

_terminated = [False]


def _on_sigterm(signum: int, frame: Any) -> None:
    """SIGTERM takes Ctrl-C's path: KeyboardInterrupt, which the commands turn into a partial report."""
    _terminated[0] = True
    raise KeyboardInterrupt


class sigterm_as_interrupt:  # a function's name: it was a contextlib.contextmanager
    """While a command runs (``with sigterm_as_interrupt():``), SIGTERM stops it the way Ctrl-C does (only in the
    main thread, and only when SIGTERM has its default disposition: an embedding program's own handler is left
    alone).

    ``_signal`` is :mod:`signal` without its enums (``getsignal`` gives the integer ``SIG_DFL``); its
    ``signal`` refuses (ValueError) outside the main thread, which is how that is told without :mod:`threading`.
    A class rather than a :func:`contextlib.contextmanager`: ``nczones --help`` imports neither :mod:`contextlib`
    nor :mod:`typing` (issue 36; a command that reads a machine file has both from :mod:`tomllib`)."""

    __slots__ = ("_previous", "_installed")

    def __enter__(self) -> None:
        _terminated[0] = False
        self._installed = False
        current = _signal.getsignal(_signal.SIGTERM)
        if not (isinstance(current, int) and current == _signal.SIG_DFL):
            return
        try:
            self._previous = _signal.signal(_signal.SIGTERM, _on_sigterm)
        except ValueError:  # not the main thread (of the main interpreter)
            return
        self._installed = True

    def __exit__(self, *exc: object) -> None:
        if self._installed:
            _signal.signal(_signal.SIGTERM, self._previous)


class _Formatter(argparse.HelpFormatter):
    """argparse's help formatter, as wide as ``shutil.get_terminal_size`` says (``$COLUMNS``, else the
    terminal of standard output, else 80) less 2, without importing :mod:`shutil`: argparse makes a formatter
    for every argument added, and its own default imports ``shutil`` and with it ``bz2``, ``lzma`` and ``zlib``
    (about 1.5 ms of every start-up)."""

    def __init__(self, prog: str, indent_increment: int = 2, max_help_position: int = 24,
                 width: int | None = None) -> None:
        super().__init__(prog, indent_increment, max_help_position, _columns() - 2 if width is None else width)


def _columns() -> int:
    """The terminal's width as ``shutil.get_terminal_size().columns`` gives it."""
    import os

    try:
        columns = int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        columns = 0
    if columns > 0:
        return columns
    try:
        return os.get_terminal_size(sys.__stdout__.fileno()).columns or 80  # type: ignore[union-attr]
    except (AttributeError, ValueError, OSError):
        return 80


def build_parser(command: str | None = None, *, alone: bool = False) -> argparse.ArgumentParser:
    """The command line's parser: every subcommand in full, or only ``command`` in full.

    Each row of :data:`~nczones.commands.COMMANDS` gets its parser, named and with its summary; the function
    the row names adds the arguments and the handler.  With ``command`` (the one about to run) only that
    command's module is imported; the others are listed by name and summary, which is all that
    ``nczones --help`` and an unknown command's error message show.  With ``alone`` the others get no parser
    at all (for an argument list that starts with ``command``: then nothing of the top-level parser but the
    command's own parser is shown; argparse's parsers cost about 0.3 ms each to make, issue 36).

    >>> sorted(build_parser("check-machine")._subparsers._group_actions[0].choices)[:3]
    ['check-machine', 'export-zones', 'fleet']
    """
    parser = argparse.ArgumentParser(
        prog="nczones",
        description="Prove that a CNC program keeps the machine inside its allowed area.",
        formatter_class=_Formatter,
    )
    parser.add_argument("--version", action="version", version=f"nczones {__version__}")
    # prog: what argparse would format from the parser's usage, which has no positional yet: its name alone (given,
    # argparse does not make a help formatter to find it, issue 36)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND", prog=parser.prog)
    for name, spec in COMMANDS.items():
        if alone and name != command:
            continue
        command_parser = sub.add_parser(name, help=spec.summary, formatter_class=_Formatter)
        if command is None or name == command:
            configurer(name)(command_parser)
    return parser


def chosen_command(argv: Sequence[str]) -> str:
    """The subcommand an argument list runs: its first word that is not an option ("" when there is none).

    The top-level options (``--help``, ``--version``) take no value, so the first other word names the command.

    >>> chosen_command(["--version"]), chosen_command(["verify", "p.ngc", "--machine", "m.toml"])
    ('', 'verify')
    """
    return next((a for a in argv if not a.startswith("-")), "")


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    arguments = sys.argv[1:] if argv is None else list(argv)
    _one_blas_thread()
    command = chosen_command(arguments)
    # `nczones COMMAND ...`: only that command's parser is made (what an error or --help shows is its own)
    restore = _untranslated_argparse()
    try:
        parser = build_parser(command, alone=bool(arguments) and arguments[0] == command and command in COMMANDS)
        args = parser.parse_args(arguments)
    finally:
        restore()
    with sigterm_as_interrupt():
        code = _run_handler(args)
    if _terminated[0] and code == EXIT_INTERRUPTED:
        print("nczones: stopped by SIGTERM (as by Ctrl-C: the report above is partial)", file=sys.stderr)
        return EXIT_TERMINATED
    return code


def _untranslated_argparse() -> Callable[[], None]:
    """While the command line is parsed, argparse's messages are given as gettext would give them where it can
    find no catalogue, without asking gettext: the function that gives gettext's functions back to argparse.

    argparse passes each of its messages (a parser's group titles, its help, its errors) through
    :func:`gettext.gettext` (or :func:`gettext.ngettext`), which looks for a catalogue of the current domain,
    ``<localedir>/<language>/LC_MESSAGES/<domain>.mo``, at every call, and imports :mod:`locale` to list the
    languages (together some 2 ms of a small verify, issue 36).  Where ``localedir`` (the domain's bound folder,
    else gettext's default, ``sys.base_prefix/share/locale``) is no folder, no catalogue exists and gettext
    gives the message itself (``ngettext``: the singular when ``n == 1``, else the plural): so do the stand-ins.
    Anywhere else (a folder of catalogues, a bound domain, argparse's functions not gettext's) nothing changes.
    """
    import gettext
    import os

    ns, g = vars(argparse), vars(gettext)
    try:  # gettext's own names (CPython's gettext.py); another gettext: nothing changes
        folder = g["_localedirs"].get(g["_current_domain"]) or g["_default_localedir"]
    except (KeyError, AttributeError, TypeError):
        return _nothing
    replaced = ns.get("_") is not gettext.gettext or ns.get("ngettext") is not gettext.ngettext
    if replaced or not isinstance(folder, str) or os.path.isdir(folder):
        return _nothing
    ns["_"], ns["ngettext"] = _same_message, _same_plural

    def restore() -> None:
        ns["_"], ns["ngettext"] = gettext.gettext, gettext.ngettext

    return restore


def _nothing() -> None:
    return None


def _same_message(message: str) -> str:
    """:func:`gettext.gettext` where no catalogue exists."""
    return message


def _same_plural(singular: str, plural: str, n: int) -> str:
    """:func:`gettext.ngettext` where no catalogue exists."""
    return singular if n == 1 else plural


def _run_handler(args: argparse.Namespace) -> int:
    """Run the chosen command: its exit status; whatever stops it is told by
    :func:`~nczones.commands.conventions.report_failure` (a user error one line, exit 2; a bug exit 4).

    With standard output closed, the command runs with :func:`~nczones.commands.conventions.closed_output` as
    ``sys.stdout``: whatever it writes there stops it, exit 2, as ``verify`` (``sys.stdout`` is given back
    after, so Python's own exit still finds it None)."""
    previous = sys.stdout
    closed = output_closed()
    if closed:
        sys.stdout = closed_output()
    try:
        code: int = args.handler(args)
        return code
    except (Exception, KeyboardInterrupt) as exc:  # noqa: BLE001 - each kind is told and given its status there
        return report_failure(exc, getattr(args, "command", "") or "")
    finally:
        if closed:
            sys.stdout = previous


def run() -> NoReturn:
    """The ``nczones`` program (its console script, and ``python -m nczones``): :func:`main`, then exit.

    Before Python shuts down, every object is moved to the collector's permanent generation
    (:func:`gc.freeze`): the process is ending, so nothing needs collecting, while the collections of
    Python's finalization would traverse every object of numpy and of the run (about 15 ms of CPU after a
    100,000-line verify).  Exit handlers and the flushing of the streams run as usual; when there are none
    to run, the process ends without the finalization (:func:`_leave_now`).  While it runs, the collector's
    first threshold is :data:`YOUNG_OBJECTS`.
    """
    import gc

    sys.meta_path.insert(0, _BeforeNumpy())  # glibc keeps freed memory once numpy loads (_keep_freed_memory)
    first, second, third = gc.get_threshold()
    if 0 < first < YOUNG_OBJECTS:  # raised, never lowered; 0 (collection off) stays 0
        gc.set_threshold(YOUNG_OBJECTS, second, third)
    code = main()
    gc.freeze()
    _leave_now(code)
    sys.exit(code)


def _leave_now(code: int) -> None:
    """End the process with status ``code`` at once when nothing waits for Python's finalization; else return.

    After the command, Python would still tear down every module and free every object one by one (some 7
    million instructions after a 10,000-line verify, 2-3 % of its CPU, issue 36) before the process ends,
    which frees them all at once.  Nothing of the user's is lost by skipping it when: no exit handler is
    registered (:mod:`atexit`: a temporary folder to remove, a log to close, a Dask cluster, a coverage
    measurement, and anything else that registers one, then end as usual), no other thread runs, the
    standard streams are the process's own and flush without error (a closed pipe: the usual exit reports
    it).  Files the commands write are closed where they are written (``with``), so no buffer waits for a
    finalizer.
    """
    import atexit
    import os

    threading = sys.modules.get("threading")
    if getattr(atexit, "_ncallbacks", lambda: 1)() or (threading is not None and threading.active_count() > 1):
        return
    streams = (sys.stdout, sys.stderr)
    if streams != (sys.__stdout__, sys.__stderr__) or None in streams:
        return
    try:
        for stream in streams:
            stream.flush()  # type: ignore[union-attr]
    except (OSError, ValueError):
        return
    os._exit(code)


#: The collector's first threshold for the ``nczones`` program (Python's default: 700).  A start imports
#: modules that make some 20,000 objects, all of which live; at 700 each of the ~20 collections they set off
#: traverses the young ones for nothing (2-3 ms of a small verify's CPU, issue 36).  At this threshold a small
#: verify sets off none, and a long one collects every so many allocations of containers: the garbage a
#: collection waits for stays bounded (a few MB).  Above ``verify``'s own (``commands.verify.GC_THRESHOLD``, which
#: only raises it); :mod:`nczones.__main__` sets the same number before the command line's modules load.
YOUNG_OBJECTS = 50_000


class _BeforeNumpy:
    """An import hook that calls :func:`_keep_freed_memory` when numpy is about to be imported, then leaves.

    Only the vectorized lanes (numpy) allocate and free the arrays of megabytes it is for; a run without numpy
    does not import :mod:`ctypes` to ask (about 2 ms of its start-up, issue 36).  It finds no module itself.
    """

    def find_spec(self, name: str, path: Any = None, target: Any = None) -> None:
        if name == "numpy":
            if self in sys.meta_path:
                sys.meta_path.remove(self)
            _keep_freed_memory()


def _keep_freed_memory() -> None:
    """Ask glibc's allocator to keep the memory the program frees for its next allocations.

    The vectorized path works through a long program in blocks of about a megabyte, each allocating and
    freeing arrays of several megabytes.  By default glibc gives arrays above 128 KiB back to the system
    when they are freed, and the next block's arrays fault their pages in afresh (about 10 ms of CPU per
    100,000 lines).  Raising the thresholds makes those arrays come from the heap and be reused; the peak
    memory stays that of one block.  Nothing happens where the C library is not glibc.
    """
    try:
        import ctypes

        libc = ctypes.CDLL(None)
        mallopt = libc.mallopt
    except (OSError, AttributeError, ImportError, TypeError):  # no C library to load, or not glibc
        return
    m_trim_threshold, m_mmap_threshold = -1, -3
    mallopt(m_mmap_threshold, 64 << 20)
    mallopt(m_trim_threshold, 128 << 20)


def _one_blas_thread() -> None:
    """Ask numpy's OpenBLAS for one thread, unless the user chose (``OPENBLAS_NUM_THREADS``, ``OMP_NUM_THREADS``).

    nczones does no linear algebra that threads would speed up (its arrays are integer columns), while
    OpenBLAS starting one busy thread per core when numpy loads costs about 0.06 s of CPU on two cores,
    more than the vectorized path then spends on 100,000 lines.  Read when numpy is first imported, so it
    is set before any command runs.
    """
    import os

    if "numpy" not in sys.modules and "OPENBLAS_NUM_THREADS" not in os.environ \
            and "OMP_NUM_THREADS" not in os.environ:
        os.environ["OPENBLAS_NUM_THREADS"] = "1"


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
