"""Machine files from controller configurations, and zones back to the controls.

:func:`import_machine` reads a LinuxCNC INI configuration (with its parameter
file and tool table), a Grbl ``$$`` settings dump or a Fanuc parameter listing
and writes a commented machine file: every value names the setting it came
from, and what the machine file cannot hold is listed as a note (``IM2xx``).
Bad input is a :class:`~nczones.errors.MachineImportError` (``IM1xx``).
:func:`export_zones` is the way back: the settings a control can hold for a
machine file's zones, and what it cannot hold.  ``specs/machine-import.md``
lists every setting read or written, its meaning and its source.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..errors import Diagnostic, InvalidArgument, MachineFileError, MachineImportError
from ..machine import Machine, parse_machine
from .model import KINDS, Collector, ImportedMachine, read_source
from .render import KIND_LABELS, render_toml

__all__ = ["KINDS", "ImportResult", "ImportedMachine", "detect_kind", "import_machine", "import_text"]

_INI_SECTION = re.compile(r"^\s*\[[A-Za-z_][A-Za-z0-9_]*\]\s*(?:[#;].*)?$", re.M)
_GRBL_SETTING = re.compile(r"^\s*\$\d+\s*=", re.M)
_FANUC_BLOCK = re.compile(r"^\s*N\s*\d{1,5}\s*(?:Q\s*1\s*)?(?:[AS]\s*\d+\s*)?[PMI]\s*[-+.\d]", re.M | re.I)


@dataclass(frozen=True, slots=True)
class ImportResult:
    """An import: what was read, the machine file's text, and the machine it loads as."""

    imported: ImportedMachine
    text: str
    machine: Machine

    @property
    def notes(self) -> tuple[Diagnostic, ...]:
        return self.imported.notes


def detect_kind(text: str, path: str = "<source>") -> str:
    """The kind of configuration ``text`` is, from its content.

    Raises ``MachineImportError`` (``IM101``) when it looks like none of them,
    or like more than one.

    >>> detect_kind("[TRAJ]\\nCOORDINATES = X Y Z\\n"), detect_kind("$130=200.000\\n$131=200\\n")
    ('linuxcnc', 'grbl')
    >>> detect_kind("%\\nN01320A1P500000A2P400000\\n%\\n")
    'fanuc'
    """
    found = []
    if _INI_SECTION.search(text):
        found.append("linuxcnc")
    if _GRBL_SETTING.search(text):
        found.append("grbl")
    if _FANUC_BLOCK.search(text):
        found.append("fanuc")
    if len(found) == 1:
        return found[0]
    if not found:
        msg = ("cannot tell what kind of configuration this is: it has no [SECTION] lines (a LinuxCNC INI file), "
               "no $<number>=<value> lines (a Grbl $$ dump) and no N<number> A<axis> P<value> blocks (a Fanuc "
               "parameter listing); give --kind linuxcnc, grbl or fanuc")
    else:
        msg = (f"cannot tell what kind of configuration this is: it looks like {' and '.join(found)} at once; "
               "give --kind")
    raise MachineImportError(Diagnostic("IM101", msg, file=path))


def import_text(
    text: str,
    path: str,
    kind: str | None = None,
    *,
    output: str | None = None,
    parameter_file: str | None = None,
    tool_table: str | None = None,
) -> ImportResult:
    """Import configuration text read from ``path`` (see :func:`import_machine`)."""
    if kind is None:
        kind = detect_kind(text, path)
    elif kind not in KINDS:
        raise InvalidArgument(f"--kind {kind!r}: use one of {', '.join(KINDS)}")
    c = Collector()
    if kind != "linuxcnc" and parameter_file is not None:
        raise InvalidArgument("--parameter-file belongs to LinuxCNC configurations")
    if kind not in ("linuxcnc", "fanuc") and tool_table is not None:
        raise InvalidArgument("--tool-table belongs to LinuxCNC configurations (a .tbl) and Fanuc parameter "
                              "listings (a tool offset listing)")
    reader = _reader(kind)
    if reader is None:
        raise MachineImportError(Diagnostic(
            "IM101", f"this looks like a {KIND_LABELS.get(kind, kind)}, which this version of nczones cannot import "
            "yet (it imports LinuxCNC INI configurations)", file=path))
    if kind == "linuxcnc":
        imported = reader(path, text, c, parameter_file=parameter_file, tool_table=tool_table)
    else:
        imported = reader(path, text, c)
    if kind == "fanuc" and tool_table is not None:
        from .fanuc_tools import with_offset_solids

        imported = with_offset_solids(imported, tool_table, c)
    toml = render_toml(imported, output)
    try:
        machine = parse_machine(toml, output or f"{Path(path).stem}.toml")
    except MachineFileError as exc:
        raise MachineImportError(tuple(_not_a_machine(imported, d) for d in exc.errors)) from None
    return ImportResult(imported, toml, machine)


def import_machine(
    source: str | Path,
    kind: str | None = None,
    *,
    output: str | None = None,
    parameter_file: str | None = None,
    tool_table: str | None = None,
) -> ImportResult:
    """Read a controller configuration into a machine file.

    Parameters
    ----------
    source : str or Path
        A LinuxCNC INI file, a Grbl ``$$`` dump or a Fanuc parameter listing.
    kind : {"linuxcnc", "grbl", "fanuc"}, optional
        What ``source`` is; detected from its content when not given.
    output : str, optional
        The machine file's name (used in its diagnostics).
    parameter_file, tool_table : str, optional
        LinuxCNC: read these instead of the INI's ``PARAMETER_FILE`` and
        ``TOOL_TABLE``.  Fanuc: ``tool_table`` is a tool offset listing (``G10``
        blocks), whose offsets start commented-out ``[[tools]]`` solids.

    Returns
    -------
    ImportResult
        The machine file's text (comments name every value's source), the
        loaded :class:`~nczones.machine.Machine`, and the notes on what could
        not be taken.

    Raises
    ------
    MachineImportError
        ``IM1xx``: unreadable or malformed input, units the machine file cannot
        express, a machine the machine file refuses (each with ``file:line``).

    Examples
    --------
    >>> import tempfile, os
    >>> d = tempfile.mkdtemp()
    >>> with open(os.path.join(d, "m.ini"), "w") as f:
    ...     _ = f.write("[TRAJ]\\nCOORDINATES = X Z\\nLINEAR_UNITS = mm\\n"
    ...                 "[AXIS_X]\\nMIN_LIMIT = -5\\nMAX_LIMIT = 150\\nMAX_VELOCITY = 50\\n"
    ...                 "[AXIS_Z]\\nMIN_LIMIT = -300\\nMAX_LIMIT = 0\\nMAX_VELOCITY = 80\\n")
    >>> r = import_machine(os.path.join(d, "m.ini"))
    >>> r.machine.axis_names, [str(a.rapid_mm_min) for a in r.machine.axes]
    (('X', 'Z'), ['3000', '4800'])
    >>> r.machine.allowed.bounding_box()["Z"]
    (Fraction(-300, 1), Fraction(0, 1))
    """
    path = str(source)
    text = read_source(source, "configuration")
    return import_text(text, path, kind, output=output, parameter_file=parameter_file, tool_table=tool_table)


def _reader(kind: str) -> Callable[..., ImportedMachine] | None:
    """The reader of ``kind``, or None when this version has none."""
    import importlib

    try:
        module = importlib.import_module(f"{__name__}.{kind}")
    except ModuleNotFoundError as exc:
        if exc.name == f"{__name__}.{kind}":
            return None
        raise
    reader: Callable[..., ImportedMachine] = getattr(module, f"read_{kind}")
    return reader


def _not_a_machine(imported: ImportedMachine, d: Diagnostic) -> Diagnostic:
    """A machine-file error in the imported machine, pointed back at the source."""
    span = None
    if d.code == "ZN130":
        span = next((v.span for v in list(imported.start.values()) + list(imported.reference.values())
                     if v.span is not None), None)
    return Diagnostic("IM110", f"the configuration gives a machine the machine file refuses: {d.message}", span,
                      file=imported.source)
