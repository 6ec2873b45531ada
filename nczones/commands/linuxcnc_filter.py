"""``nczones linuxcnc-filter``: the program filter LinuxCNC's GUIs run on every file they open.

LinuxCNC's INI ``[FILTER]`` section names, per file extension, a command; AXIS (``axis.py``
``filter_program``), QtVCP (``qt_action.py`` ``FilterProgram``) and GladeVCP run it as
``sh -c "<command> '<program path>'"`` with standard input closed and standard output going to a
temporary file that the GUI then loads.  Standard error is read line by line: a line that matches
``^FILTER_PROGRESS=(\\d*)$`` moves the GUI's progress bar (percent), every other line is kept; when the
command exits non-zero, the GUI loads nothing and shows the kept lines to the operator with the exit
code.  See ``docs/linuxcnc-filter.md``.

This command:

* finds the machine file: ``--machine M.toml``, else ``[NCZONES] MACHINE`` in the INI (``--ini``, else
  the ``INI_FILE_NAME`` the ``linuxcnc`` launcher exports; relative to the INI's folder), else the
  ``.toml`` beside the INI with the INI's name (``mill.ini`` -> ``mill.toml``);
* proves the program in the LinuxCNC dialect, writing ``FILTER_PROGRESS=N`` on standard error;
* on ``safe`` writes the program's bytes unchanged to standard output and exits 0;
* otherwise writes nothing to standard output, a short operator message on standard error (the
  verdict, the line, zone and depth of each violation or the reason for ``unknown``) and the full
  report next to the program (``PROGRAM.nczones.html``; ``.txt`` when the ``[html]`` extra is not
  installed), and exits 1 (unsafe), 2 (bad input: no machine file, unreadable program) or 3
  (unknown), as ``verify`` does.
"""

from __future__ import annotations

import argparse
import configparser
import os
import sys
from typing import TYPE_CHECKING, Any, TextIO

from ..errors import Diagnostic, InputError
from .conventions import (
    EXIT_INTERRUPTED,
    EXIT_OK,
    EXIT_UNKNOWN,
    budget_seconds,
    program_source,
    with_dialect,
)

if TYPE_CHECKING:
    from ..machine import Machine
    from ..prover.result import Result

__all__ = ["configure", "find_machine", "ProgressLines", "operator_message", "ini_snippet", "REPORT_SUFFIX",
           "MAX_LISTED", "EXTENSIONS"]

#: The full report is written beside the program under its name plus this suffix and ``.html`` (or ``.txt``).
REPORT_SUFFIX = ".nczones"
#: Violations (or reasons) the operator message lists; the report has all of them.
MAX_LISTED = 5


class ProgressLines:
    """The prover's ``progress(line, total)`` callback as ``FILTER_PROGRESS=N`` lines (N in 0..100).

    A line is written only when the percentage grows, so a long program writes at most 101 lines.

    >>> import io
    >>> out = io.StringIO()
    >>> p = ProgressLines(out)
    >>> p(1, 4); p(1, 4); p(4, 4); p(7, None)
    >>> out.getvalue()
    'FILTER_PROGRESS=0\\nFILTER_PROGRESS=25\\nFILTER_PROGRESS=100\\n'
    """

    counts = False

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream
        self.last = -1
        self.emit(0)

    def emit(self, percent: int) -> None:
        if percent > self.last:
            self.last = percent
            self.stream.write(f"FILTER_PROGRESS={percent}\n")
            self.stream.flush()

    def __call__(self, line: int, total: int | None, **_: Any) -> None:
        if total:
            self.emit(max(0, min(100, (100 * line) // total)))


#: The program extensions the INI snippet sends through the filter (LinuxCNC itself opens .ngc; the others are
#: what CAM post-processors commonly write for it).
EXTENSIONS = ("ngc", "nc", "tap")


def ini_snippet(machine_path: str, ini_path: str | None = None, command: str = "nczones linuxcnc-filter") -> str:
    """The INI lines that put the filter in front of a LinuxCNC machine (docs/linuxcnc-filter.md).

    ``MACHINE`` is written relative to the INI's folder when ``ini_path`` is given (the filter resolves it
    from there), else as given.

    >>> print(ini_snippet("/cfg/mill.toml", "/cfg/mill.ini"), end="")
    # nczones: every program the GUI opens is proved against the machine file first
    # (add the PROGRAM_EXTENSION line and the ngc/nc/tap lines to an existing [FILTER] section)
    [FILTER]
    PROGRAM_EXTENSION = .ngc,.nc,.tap G-code proved by nczones
    ngc = nczones linuxcnc-filter
    nc = nczones linuxcnc-filter
    tap = nczones linuxcnc-filter
    <BLANKLINE>
    [NCZONES]
    MACHINE = mill.toml
    """
    path = machine_path
    if ini_path is not None:
        folder = os.path.dirname(os.path.abspath(ini_path))
        path = os.path.relpath(os.path.abspath(machine_path), folder)
    lines = ["# nczones: every program the GUI opens is proved against the machine file first",
             "# (add the PROGRAM_EXTENSION line and the "
             + "/".join(EXTENSIONS) + " lines to an existing [FILTER] section)",
             "[FILTER]",
             "PROGRAM_EXTENSION = " + ",".join("." + e for e in EXTENSIONS) + " G-code proved by nczones"]
    lines += [f"{e} = {command}" for e in EXTENSIONS]
    lines += ["", "[NCZONES]", f"MACHINE = {path}"]
    return "\n".join(lines) + "\n"


def _error(code: str, message: str, where: str = "<linuxcnc-filter>") -> InputError:
    return InputError(Diagnostic(code, message, file=where))


def find_machine(machine: str | None, ini: str | None) -> str:
    """The machine file the filter proves against (see the module docstring); ``LF1xx`` when none.

    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (d / "mill.ini").write_text("[NCZONES]\\nMACHINE = zones/mill.toml\\n")
    >>> find_machine(None, str(d / "mill.ini")) == str(d / "zones" / "mill.toml")
    True
    """
    if machine:
        return machine
    if not ini:
        raise _error("LF101", "no machine file: give --machine M.toml, or --ini FILE.ini, or run under "
                              "LinuxCNC (which sets INI_FILE_NAME)")
    parser = configparser.ConfigParser(strict=False, interpolation=None, inline_comment_prefixes=None,
                                       comment_prefixes=("#", ";"))
    parser.optionxform = str  # type: ignore[assignment,method-assign]
    try:
        with open(ini, encoding="utf-8", errors="replace") as fh:
            parser.read_file(fh)
    except OSError as exc:
        raise _error("LF102", f"cannot read the INI file {ini}: {exc.strerror or exc}") from None
    except configparser.Error as exc:
        raise _error("LF102", f"cannot read the INI file {ini}: {str(exc).splitlines()[0]}") from None
    folder = os.path.dirname(os.path.abspath(ini))
    named = parser.get("NCZONES", "MACHINE", fallback=None) if parser.has_section("NCZONES") else None
    if named is not None and named.strip():
        path = os.path.expanduser(named.strip())
        return path if os.path.isabs(path) else os.path.join(folder, path)
    beside = os.path.splitext(os.path.abspath(ini))[0] + ".toml"
    if os.path.isfile(beside):
        return beside
    raise _error("LF101", f"no machine file: {ini} has no [NCZONES] MACHINE and {beside} does not exist "
                          "(nczones import-machine INI -o M.toml --linuxcnc-filter writes both)")


def _fmt(value: Any) -> str:
    from ..exact import format_decimal

    return format_decimal(value, 3) if hasattr(value, "denominator") else str(value)


def operator_message(result: Result, program: str, report: str | None, machine: Machine | None = None) -> str:
    """The lines the GUI shows when the program is refused: verdict, then line, zone and depth."""
    from ..prover.result import Verdict

    name = os.path.basename(program)
    lines: list[str] = []
    if result.verdict is Verdict.UNSAFE:
        count = len(result.violations)
        lines.append(f"nczones: {name} is UNSAFE and was not loaded: {count} violating "
                     f"block{'s' if count != 1 else ''}{' (list cut)' if result.truncated else ''}")
        for v in result.violations[:MAX_LISTED]:
            line = f"line {v.span.line}" if v.span is not None else f"block {v.block}"
            depth = _fmt(v.depth) + " mm" + ("" if v.depth_exact else " (at least)")
            forbid = machine is not None and any(z.name == v.zone and z.forbid for z in machine.zones)
            role = f"enters the forbidden zone '{v.zone}'" if forbid else f"leaves the allowed zone '{v.zone}'"
            lines.append(f"  {line}: {role} by {depth}")
        rest = count - MAX_LISTED
    else:
        state = "could NOT be proved safe" if result.verdict is Verdict.UNKNOWN else "was refused"
        lines.append(f"nczones: {name} {state} and was not loaded (verdict {result.verdict.name.lower()})")
        for r in result.reasons[:MAX_LISTED]:
            where = f"line {r.span.line}" if r.span is not None else "program"
            code = f" [{r.code}]" if r.code else ""
            message = r.message[len(r.code) + 2:] if r.code and r.message.startswith(r.code + ": ") else r.message
            lines.append(f"  {where}{code}: {message}")
        rest = len(result.reasons) - MAX_LISTED
    if rest > 0:
        lines.append(f"  ... and {rest} more")
    if report:
        lines.append(f"full report: {report}")
    return "\n".join(lines) + "\n"


def _write_report(result: Result, machine: Machine, source: Any, program: str) -> tuple[str | None, str]:
    """The full report beside the program: (its path or None, a note for the operator or "")."""
    from ..report import render_report

    base = os.path.abspath(program) + REPORT_SUFFIX
    note = ""
    try:
        text = render_report(result, "html", machine=machine, program=source)
        path = base + ".html"
    except ModuleNotFoundError as exc:
        text = render_report(result, "text", program=source)
        path = base + ".txt"
        note = f"(text report: the HTML report needs {exc.name}; pip install 'nczones[html]')\n"
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)
    except OSError as exc:
        return None, f"nczones: cannot write the report {path}: {exc.strerror or exc}\n"
    return path, note


def _run(args: argparse.Namespace) -> int:
    from ..machine import load_machine
    from ..pipeline.verification import verify_source
    from ..prover.options import VerifyOptions
    from ..prover.result import Verdict

    progress = ProgressLines(sys.stderr)
    ini = args.ini or os.environ.get("INI_FILE_NAME") or None
    machine = with_dialect(load_machine(find_machine(args.machine, ini)), "linuxcnc")
    source = program_source(args.program)

    result = verify_source(source, machine, VerifyOptions(budget_s=budget_seconds(args.budget)), progress=progress)
    progress.emit(100)
    if result.verdict is Verdict.SAFE and not result.interrupted:
        with open(args.program, "rb") as fh:
            data = fh.read()
        sys.stdout.flush()
        sys.stdout.buffer.write(data)
        sys.stdout.buffer.flush()
        return EXIT_OK
    report, note = _write_report(result, machine, source, args.program)
    sys.stderr.write(operator_message(result, args.program, report, machine) + note)
    if result.interrupted:
        return EXIT_INTERRUPTED
    code: int = result.verdict.exit_code
    return code if code != EXIT_OK else EXIT_UNKNOWN


def configure(p: argparse.ArgumentParser) -> None:
    from ..prover.limits import DEFAULT_BUDGET_S

    p.description = ("The program filter of LinuxCNC's INI [FILTER] section (docs/linuxcnc-filter.md): prove "
                     "PROGRAM against the machine file, print it unchanged on standard output when it is safe "
                     "(exit 0); otherwise print nothing, tell the operator why on standard error, write the full "
                     "report beside the program and exit 1 (unsafe), 2 (bad input) or 3 (unknown). Progress "
                     "goes to standard error as FILTER_PROGRESS=N lines.")
    p.add_argument("program", metavar="PROGRAM", help="the program file the GUI opens (LinuxCNC passes it)")
    p.add_argument("--machine", metavar="M.toml", default=None,
                   help="the machine file (default: [NCZONES] MACHINE of the INI, else the INI's name with .toml)")
    p.add_argument("--ini", metavar="FILE.ini", default=None,
                   help="the LinuxCNC INI file (default: $INI_FILE_NAME, which the linuxcnc launcher sets)")
    p.add_argument("--budget", default=None, metavar="SECONDS",
                   help=f"time for solver work (default {DEFAULT_BUDGET_S:g}; 'none' for no limit); what is left "
                        "undecided is unknown and the program is refused")
    p.set_defaults(handler=_run)

