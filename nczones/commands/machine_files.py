"""``nczones import-machine`` and ``nczones export-zones``.

``import-machine`` exits 0 when the machine file is written (notes on what
was not taken do not change that) and 2 on bad input.  ``export-zones`` exits
0 when the control's settings hold the allowed set exactly, 1 when they hold
only a larger set (something could not be written: the notes say what), and
2 on bad input.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable
from pathlib import Path

from ..errors import Diagnostic, InputError, InvalidArgument
from ..imports import KINDS, ImportResult, import_machine
from ..imports.export import EXPORT_KINDS
from ..imports.render import KIND_LABELS
from .conventions import EXIT_FAIL, EXIT_OK, tell_beside_file

__all__ = ["configure_import", "configure_export", "summary"]


def _write(path: str, text: str) -> None:
    try:
        Path(path).write_text(text, encoding="utf-8")
    except OSError as exc:
        raise InvalidArgument(f"cannot write {path}: {exc.strerror or exc}") from None


def summary(result: ImportResult, output: str | None) -> str:
    """One line on what was imported."""
    im = result.imported
    m = result.machine
    parts = [f"axes {' '.join(im.axes)}", f"{len(m.zones)} zone{'s' if len(m.zones) != 1 else ''}"]
    if m.offsets:
        parts.append(f"{len(m.offsets)} work offset{'s' if len(m.offsets) != 1 else ''}")
    tools = set(m.tool_lengths) | set(m.tool_diameters)
    if tools:
        parts.append(f"{len(tools)} tool{'s' if len(tools) != 1 else ''}")
    notes = len(im.notes)
    target = f" -> {output}" if output else ""
    return (f"{im.source}: {KIND_LABELS[im.kind]} imported as machine \"{im.name}\" ({', '.join(parts)}){target}; "
            f"{notes} note{'s' if notes != 1 else ''} on what was not taken, rounded or assumed")


def _emit(text: str, output: str | None, summary_line: str, notes: Iterable[Diagnostic]) -> None:
    """The file to ``output`` and the report to standard output (none when it is closed: the file is the
    output), or the file to standard output and the report to standard error (so the command can be
    redirected)."""
    lines = [summary_line, *(note.render() for note in notes)]
    if output:
        _write(output, text)
        for line in lines:
            tell_beside_file(line)
        return
    sys.stdout.write(text)
    for line in lines:
        print(line, file=sys.stderr)


def _run_import(args: argparse.Namespace) -> int:
    result = import_machine(args.source, args.kind, output=args.output, parameter_file=args.parameter_file,
                            tool_table=args.tool_table)
    if args.linuxcnc_filter and (result.imported.kind != "linuxcnc" or not args.output):
        raise InputError(Diagnostic(
            "LF103", "--linuxcnc-filter writes the INI lines that name the machine file: it needs a LinuxCNC INI "
            "as SOURCE and -o M.toml" + ("" if args.output else " (the machine file's path)"),
            file="<command line>"))
    _emit(result.text, args.output, summary(result, args.output), result.notes)
    if args.linuxcnc_filter:
        from .linuxcnc_filter import ini_snippet

        _write(args.linuxcnc_filter, ini_snippet(args.output, args.source))
        tell_beside_file(f"{args.linuxcnc_filter}: the [FILTER] and [NCZONES] lines for {args.source} "
                         "(docs/linuxcnc-filter.md)")
    return EXIT_OK


def configure_import(p: argparse.ArgumentParser) -> None:
    p.description = ("Read a controller configuration and write a commented machine file: every value names "
                     "the setting it came from, and what the machine file cannot hold is printed (and written at "
                     "the end of the file) with its source line. Exit 0 when the file is written, 2 on bad input.")
    p.add_argument("source", metavar="SOURCE",
                   help="a LinuxCNC INI file, a Grbl $$ settings dump or a Fanuc parameter listing")
    p.add_argument("--kind", choices=KINDS,
                   help="what SOURCE is (default: detected from its content; an error when it cannot be told)")
    p.add_argument("-o", "--output", metavar="M.toml",
                   help="write the machine file here and the notes to standard output (default: the machine file "
                   "to standard output, the notes to standard error)")
    p.add_argument("--parameter-file", metavar="VAR",
                   help="LinuxCNC: read work offsets and the G28 position from this .var file instead of the one "
                   "[RS274NGC] PARAMETER_FILE names")
    p.add_argument("--tool-table", metavar="TBL",
                   help="LinuxCNC: read tool lengths and diameters from this .tbl file instead of the one "
                   "[EMCIO] TOOL_TABLE names; Fanuc: the control's tool offset listing (G10 blocks), whose "
                   "offsets start commented-out [[tools]] solids")
    p.add_argument("--linuxcnc-filter", metavar="SNIPPET.ini",
                   help="LinuxCNC: also write the INI lines ([FILTER] and [NCZONES] MACHINE) that make the GUI run "
                   "nczones linuxcnc-filter on every program it opens (docs/linuxcnc-filter.md); needs -o")
    p.set_defaults(handler=_run_import)



def _run_export(args: argparse.Namespace) -> int:
    from ..imports.export import export_zones
    from ..machine import load_machine

    machine = load_machine(args.machine_file)
    result = export_zones(machine, args.kind, units=args.units, increment=args.increment,
                          include_machine=args.include_machine)
    target = f" -> {args.output}" if args.output else ""
    what = {"linuxcnc": "LinuxCNC soft limits", "fanuc": "Fanuc stored stroke checks"}[result.kind]
    if result.exact:
        verdict = "the control holds the allowed set exactly"
    else:
        verdict = (f"the control cannot hold every zone and allows more than the machine file "
                   f"({len(result.notes)} note{'s' if len(result.notes) != 1 else ''}); the proof before the run "
                   "covers the difference")
    _emit(result.text, args.output, f"{machine.source}: {what}{target}: {verdict}", result.notes)
    return EXIT_OK if result.exact else EXIT_FAIL


def configure_export(p: argparse.ArgumentParser) -> None:
    p.description = ("Write the settings a control can hold for a machine file's zones: LinuxCNC's soft limits "
                     "(one box), a Fanuc control's stored stroke checks (a box and two forbidden boxes). What the "
                     "control cannot hold (stepped tables, polygons, tool-tip zones, more forbidden areas) is left "
                     "out and said; the settings then allow more than the machine file. Exit 0 when they hold the "
                     "allowed set exactly, 1 when they allow more, 2 on bad input.")
    p.add_argument("machine_file", metavar="M.toml", help="the machine file")
    p.add_argument("--kind", choices=EXPORT_KINDS, required=True, help="the control to write settings for")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="write the settings here and the notes to standard output (default: the settings to "
                   "standard output, the notes to standard error)")
    p.add_argument("--units", choices=("mm", "inch"), default="mm",
                   help="LinuxCNC: the INI's LINEAR_UNITS, the unit of the values written (default: mm)")
    p.add_argument("--increment", metavar="MM", default="0.001",
                   help="Fanuc: the control's least command increment in mm (deg), which integer parameter values "
                   "count: 0.01 (IS-A), 0.001 (IS-B, the default), 0.0001 (IS-C), 0.00001, 0.000001")
    p.add_argument("--include-machine", action="store_true",
                   help="also write the axis names, rapid rates and reference position (LinuxCNC: MAX_VELOCITY, "
                   "HOME; Fanuc: 1020, 1420, 1240), so the text describes the whole machine and imports back")
    p.set_defaults(handler=_run_export)

