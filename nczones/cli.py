"""The ``nczones`` command line (DESIGN §8).

Exit status of ``verify``: 0 safe, 1 unsafe, 2 bad input, 3 unknown.  Other
commands: 0 success, 1 an alarm or a refuted property, 2 bad input.  An
internal bug exits 4 with a traceback and a request to report it; a user error
never prints a traceback.

Each subcommand lives in its own ``register_*`` function (``check-machine``
below, the others in :mod:`nczones.commands`); :data:`COMMANDS` names the
module of each, which is imported only when its command runs.
"""

from __future__ import annotations

import argparse
import importlib
import os
import signal
import sys
import threading
import traceback
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from fractions import Fraction
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, NoReturn

from . import __version__
from .errors import Diagnostic, InputError, InvalidArgument, NczonesError
from .exact import format_decimal
from .machine import Machine, load_machine
from .zones import BoxZone, PolygonZone, SteppedZone, Zone
from .zones.kinds import KindTable

if TYPE_CHECKING:
    from .gcode.source import ProgramSource

__all__ = ["main", "EXIT_OK", "EXIT_FAIL", "EXIT_INPUT", "EXIT_UNKNOWN", "EXIT_INTERNAL", "EXIT_INTERRUPTED",
           "EXIT_TERMINATED"]

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

_terminated = [False]


def _on_sigterm(signum: int, frame: Any) -> None:
    """SIGTERM takes Ctrl-C's path: KeyboardInterrupt, which the commands turn into a partial report."""
    _terminated[0] = True
    raise KeyboardInterrupt


@contextmanager
def sigterm_as_interrupt() -> Iterator[None]:
    """While a command runs, SIGTERM stops it the way Ctrl-C does (only in the main thread, and only when
    SIGTERM has its default disposition: an embedding program's own handler is left alone)."""
    _terminated[0] = False
    if threading.current_thread() is not threading.main_thread() \
            or signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL:
        yield
        return
    previous = signal.signal(signal.SIGTERM, _on_sigterm)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)

Handler = Callable[[argparse.Namespace], int]

#: The optional dependencies by top-level module: the extra that installs each (pyproject.toml).  The core
#: install (``pip install nczones``) is what ``verify`` needs; a command that needs a missing one stops with
#: one line naming the extra (``PK101``, exit 2).
EXTRAS: Mapping[str, str] = MappingProxyType({
    "matplotlib": "plot", "shapely": "plot", "dask": "fleet", "distributed": "fleet",
})


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


def _bound(value: Fraction | None) -> str:
    return "unbounded" if value is None else format_decimal(value)


def _zone_lines(z: Zone, role: str, tip: str, extra: str = "") -> list[str]:
    ranges = ", ".join(f"{a} [{_bound(lo)}, {_bound(hi)}]" for a, (lo, hi) in z.bounds().items())
    return [f"    {z.name}: {role} {z.kind}{tip}{extra} {ranges}"]


#: The lines of ``check-machine`` that describe one zone (``role`` "allow"/"forbid", ``tip`` " (tool tip)" or
#: ""), per zone kind.  Fallback: its kind and bounds.
ZONE_LINES: KindTable[Callable[[Any, str, str], list[str]]] = KindTable("cli.zone_lines", fallback=_zone_lines)
ZONE_LINES.set(BoxZone, _zone_lines)


@ZONE_LINES.register(PolygonZone)
def _polygon_lines(z: PolygonZone, role: str, tip: str) -> list[str]:
    return _zone_lines(z, role, tip, f" in {z.plane[0]}{z.plane[1]} with {len(z.vertices)} vertices")


@ZONE_LINES.register(SteppedZone)
def _stepped_lines(z: SteppedZone, role: str, tip: str) -> list[str]:
    lines = [
        f"    {z.name}: {role} stepped table{tip}, {z.limited_axis} limited by "
        f"{z.reference_axis}, {len(z.regions)} regions from {format_decimal(z.start)}"
    ]
    lower = z.start
    for i, r in enumerate(z.regions):
        bracket = "[" if i == 0 else "("
        lines.append(
            f"      region {i + 1}: {z.reference_axis} {bracket}{format_decimal(lower)}, "
            f"{format_decimal(r.upto)}] -> {z.limited_axis} [{_bound(r.min)}, {_bound(r.max)}]"
        )
        lower = r.upto
    return lines


def describe_machine(machine: Machine) -> str:
    """A readable summary of a machine (what ``check-machine`` prints).

    Examples
    --------
    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('''
    ... [machine]
    ... name = "demo"
    ... axes = ["X"]
    ... [machine.rapid]
    ... X = "1000"
    ... [machine.reference]
    ... X = "5"
    ... [[zones]]
    ... name = "travel"
    ... kind = "box"
    ... min = { X = "0" }
    ... max = { X = "10" }
    ... ''', "demo.toml")
    >>> print(describe_machine(m))
    demo.toml: machine "demo" is valid
      axes: X (linear, pulse 0.001 mm, rapid 1000 mm/min)
      rapid mode: linear; limit monitor every 5 ms
      reference: X5; start: X5
      zones (1):
        travel: allow box X [0, 10]
      allowed set lies within: X [0, 10]
    """
    lines = [f"{machine.source}: machine \"{machine.name}\" is valid"]
    axes = []
    for a in machine.axes:
        unit = "deg" if a.rotary else "mm"
        axes.append(
            f"{a.name} ({'rotary' if a.rotary else 'linear'}, pulse {format_decimal(a.pulse)} {unit}, "
            f"rapid {format_decimal(a.rapid_mm_min)} {unit}/min)"
        )
    lines.append("  axes: " + ", ".join(axes))
    lines.append(
        f"  rapid mode: {machine.rapid_mode.value}; limit monitor every "
        f"{format_decimal(machine.monitor_period_ms)} ms"
    )

    def pt(coords: tuple[Fraction, ...]) -> str:
        return " ".join(f"{n}{format_decimal(c)}" for n, c in zip(machine.axis_names, coords))

    lines.append(f"  reference: {pt(machine.reference)}; start: {pt(machine.start)}")
    if machine.offsets:
        lines.append("  work offsets: " + "; ".join(f"{k} {pt(v)}" for k, v in machine.offsets.items()))
    if machine.tool_lengths:
        lines.append(
            "  tool lengths: "
            + ", ".join(f"H{k} {format_decimal(v)}" for k, v in sorted(machine.tool_lengths.items()))
        )
    if machine.is_lathe or machine.diameter_axes:
        dia = ", ".join(machine.diameter_axes)
        lines.append(f"  type: {machine.machine_type}" + (
            f"; program words on {dia} are diameters (machine coordinates and zones are radii)" if dia else ""))
    for n, t in sorted(machine.tool_offsets.items()):
        def val(a: str, v: Fraction) -> str:
            return f"{a}{format_decimal(v)}" + (f" (diameter {format_decimal(2 * v)})"
                                                if a in machine.diameter_axes else "")
        parts = [val(a, v) for a, v in t.geometry]
        if t.wear:
            parts.append("wear " + " ".join(val(a, v) for a, v in t.wear))
        if t.nose_radius or t.wear_radius:
            parts.append(f"nose radius {format_decimal(t.nose_radius + t.wear_radius)}")
        parts.append(f"tip {t.tip}")
        lines.append(f"  tool offset {n}: " + ", ".join(parts))
    lines.append(f"  zones ({len(machine.zones)}):")
    for z in machine.zones:
        role = "forbid" if z.forbid else "allow"
        tip = " (tool tip)" if z.point.value == "tip" else ""
        lines += ZONE_LINES(z, role, tip)
    bbox = machine.allowed.bounding_box()
    if bbox:
        lines.append(
            "  allowed set lies within: "
            + ", ".join(f"{a} [{_bound(lo)}, {_bound(hi)}]" for a, (lo, hi) in bbox.items())
        )
    else:
        lines.append("  allowed set: unbounded (no machine-point allow zone)")
    for w in machine.warnings:
        lines.append(w.render())
    return "\n".join(lines)


def _run_check_machine(args: argparse.Namespace) -> int:
    machine = load_machine(args.machine_file)
    print(describe_machine(machine))
    return EXIT_OK


def register_check_machine(sub: argparse._SubParsersAction) -> None:
    p = add_command(sub, "check-machine")
    p.add_argument("machine_file", metavar="M.toml", help="the machine file to check (specs/machine-file.md)")
    p.set_defaults(handler=_run_check_machine)


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
    from .prover.options import library_folders

    return library_folders(path)


def program_source(name: str, *, stream: bool = False) -> ProgramSource:
    """The program ``name`` names: ``-`` is standard input, anything else a file (``GC1xx`` errors); ``stream``:
    a large plain file is left on disk and read as it is verified (:func:`nczones.gcode.source.load_program`)."""
    from .gcode.source import load_program, read_stdin

    return (read_stdin() if name == "-" else load_program(name, stream=stream)).require_code()


def arc_tolerance(text: str | None) -> Fraction | str | None:
    """``--arc-tolerance``: "linuxcnc", "grbl" or a non-negative decimal (mm); None (not given) stays None.

    >>> arc_tolerance("0.002"), arc_tolerance("linuxcnc")
    (Fraction(1, 500), 'linuxcnc')
    """
    from .prover.options import arc_tolerance_option

    return arc_tolerance_option(text)


@dataclass(frozen=True, slots=True)
class Command:
    """A subcommand: the module that registers it and its one line in ``nczones --help``."""

    module: str
    summary: str


#: The subcommands in the order ``nczones --help`` lists them.  A command's module is imported only when the
#: command runs (or when :func:`build_parser` builds every command), so ``nczones --help`` and a command stay
#: clear of what the other commands import (the prover, the controller, numpy, Z3, matplotlib).
COMMANDS: Mapping[str, Command] = MappingProxyType({
    "check-machine": Command("nczones.cli", "validate a machine file and summarise it"),
    "verify": Command("nczones.commands.verify",
                      "prove that programs stay inside the allowed set (or show where not)"),
    "simulate": Command("nczones.commands.simulate",
                        "run a program through the reference controller (pulses, limit monitor)"),
    "home": Command("nczones.commands.home",
                    "simulate homing (near-zero dog, grid point, grid shift) or prove it exact"),
    "plot": Command("nczones.commands.plot",
                    "draw a program's toolpath over the machine's allowed set (PNG/SVG/PDF)"),
    "import-machine": Command("nczones.commands.machine_files",
                              "write a machine file from a LinuxCNC, Grbl or Fanuc configuration"),
    "export-zones": Command("nczones.commands.machine_files",
                            "write the soft limits (LinuxCNC) or stored stroke checks (Fanuc) that hold a machine "
                            "file's zones"),
    "replay": Command("nczones.commands.replay",
                      "re-check the counterexamples of a JSON report exactly against the files it names"),
    "fleet": Command("nczones.commands.fleet",
                     "verify a library of programs against its machines, incrementally (serial or on Dask)"),
    "linuxcnc-filter": Command("nczones.commands.linuxcnc_filter",
                               "LinuxCNC's [FILTER] program: pass a program through only when it is proved safe"),
})

#: Subcommand registrars by command name; each command's module adds its own when imported.
REGISTRARS: dict[str, Callable[[argparse._SubParsersAction], None]] = {"check-machine": register_check_machine}


def add_command(sub: argparse._SubParsersAction, name: str, **kwargs: Any) -> argparse.ArgumentParser:
    """The parser of subcommand ``name`` with its summary from :data:`COMMANDS` (for the registrars)."""
    parser: argparse.ArgumentParser = sub.add_parser(name, help=COMMANDS[name].summary, **kwargs)
    return parser


def _load_optional_registrars() -> None:
    """Import every subcommand's module (each adds its registrar to REGISTRARS)."""
    for command in COMMANDS.values():
        importlib.import_module(command.module)


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The command line's parser: every subcommand in full, or only ``command`` in full.

    With ``command`` (the one about to run) only that command's module is
    imported; the others are listed by name and summary, which is all that
    ``nczones --help`` and an unknown command's error message show.

    >>> sorted(build_parser("check-machine")._subparsers._group_actions[0].choices)[:3]
    ['check-machine', 'export-zones', 'fleet']
    """
    if command is None:
        _load_optional_registrars()
    elif command in COMMANDS:
        importlib.import_module(COMMANDS[command].module)
    parser = argparse.ArgumentParser(
        prog="nczones",
        description="Prove that a CNC program keeps the machine inside its allowed area.",
    )
    parser.add_argument("--version", action="version", version=f"nczones {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, spec in COMMANDS.items():
        if command is None or name == command:
            REGISTRARS[name](sub)
        else:
            sub.add_parser(name, help=spec.summary)
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
    parser = build_parser(chosen_command(arguments))
    args = parser.parse_args(arguments)
    with sigterm_as_interrupt():
        code = _run_handler(args)
    if _terminated[0] and code == EXIT_INTERRUPTED:
        print("nczones: stopped by SIGTERM (as by Ctrl-C: the report above is partial)", file=sys.stderr)
        return EXIT_TERMINATED
    return code


def _run_handler(args: argparse.Namespace) -> int:
    """Run the chosen command: its exit status, every user error one line (exit 2), a bug exit 4."""
    try:
        code: int = args.handler(args)
        return code
    except InputError as exc:
        print(exc.render(), file=sys.stderr)
        return EXIT_INPUT
    except InvalidArgument as exc:
        print(f"nczones: error: {exc}", file=sys.stderr)
        return EXIT_INPUT
    except NczonesError as exc:
        print(f"nczones: internal error: {exc}\nThis is a bug in nczones; please report it.", file=sys.stderr)
        return EXIT_INTERNAL
    except KeyboardInterrupt:
        print("nczones: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except ModuleNotFoundError as exc:
        missing = missing_extra(exc, getattr(args, "command", "") or "")
        if missing is None:
            traceback.print_exc()
            print("nczones: internal error (the traceback above is a bug in nczones; please report it)",
                  file=sys.stderr)
            return EXIT_INTERNAL
        print(missing.render(), file=sys.stderr)
        return EXIT_INPUT
    except OSError as exc:  # reading or writing the user's files and streams (one line, never a traceback)
        _quiet_stdout(exc)
        where = f" {exc.filename}" if exc.filename is not None else (
            " standard output" if isinstance(exc, BrokenPipeError) else "")
        print(f"nczones: error: cannot read or write{where}: {exc.strerror or exc}", file=sys.stderr)
        return EXIT_INPUT
    except Exception:  # noqa: BLE001 - an internal bug, never the user's fault
        traceback.print_exc()
        print("nczones: internal error (the traceback above is a bug in nczones; please report it)", file=sys.stderr)
        return EXIT_INTERNAL


def run() -> NoReturn:
    """The ``nczones`` program (its console script, and ``python -m nczones``): :func:`main`, then exit.

    Before Python shuts down, every object is moved to the collector's permanent generation
    (:func:`gc.freeze`): the process is ending, so nothing needs collecting, while the collections of
    Python's finalization would traverse every object of numpy and of the run (about 15 ms of CPU after a
    100,000-line verify).  Exit handlers and the flushing of the streams run as usual.
    """
    _keep_freed_memory()
    code = main()
    import gc

    gc.freeze()
    sys.exit(code)


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


def _quiet_stdout(exc: OSError) -> None:
    """After a broken pipe, point standard output at /dev/null so the interpreter's final flush stays quiet."""
    if isinstance(exc, BrokenPipeError):
        import os

        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
        except (OSError, ValueError):
            pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
