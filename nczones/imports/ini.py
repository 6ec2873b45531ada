"""LinuxCNC's INI file format, read as LinuxCNC reads it, with line numbers.

The rules (LinuxCNC documentation, "INI Configuration", and its reader
``src/emc/ini/inifile.cc``): a comment is a line whose first non-blank
character is ``#`` or ``;`` (inside a value, ``#`` and ``;`` are part of the
value); ``[SECTION]`` starts a section; ``KEY = value`` sets a variable, whose
value is trimmed; a line ending in ``\\`` continues on the next line;
``#INCLUDE file`` in the first column reads another file (relative to the
including file's folder) in place; section and key names are identifiers
(letters, digits, ``_``, not starting with a digit) and case sensitive; a
section named twice is merged; when a key is written twice the first one
counts.  Value escapes (``\\x20``, ``\\n``) are kept literally: none of the
values the import reads needs them.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from ..errors import SourceSpan
from .model import Collector, line_span, read_source

__all__ = ["IniEntry", "IniFile", "parse_ini"]

_ID = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
_MAX_INCLUDE_DEPTH = 16


@dataclass(frozen=True, slots=True)
class IniEntry:
    """One ``KEY = value`` line; ``span`` covers the value (or the key when the value is empty)."""

    section: str
    key: str
    value: str
    span: SourceSpan

    def where(self) -> str:
        return f"{self.span.file}:{self.span.line}"

    def describe(self) -> str:
        """``[SECTION] KEY = value`` as written."""
        return f"[{self.section}] {self.key} = {self.value}"


class IniFile:
    """The variables of an INI file (and its includes), in file order."""

    def __init__(self, path: str, entries: list[IniEntry], sections: dict[str, SourceSpan]):
        self.path = path
        self.entries = tuple(entries)
        self.sections = dict(sections)
        self._first: dict[tuple[str, str], IniEntry] = {}
        for e in self.entries:
            self._first.setdefault((e.section, e.key), e)

    def get(self, section: str, key: str) -> IniEntry | None:
        """The first ``key`` in ``section`` (LinuxCNC uses the first of several)."""
        return self._first.get((section, key))

    def all(self, section: str, key: str) -> tuple[IniEntry, ...]:
        return tuple(e for e in self.entries if e.section == section and e.key == key)

    def in_section(self, section: str) -> tuple[IniEntry, ...]:
        return tuple(e for e in self.entries if e.section == section)


def parse_ini(path: str, text: str, c: Collector) -> IniFile:
    """Read INI text; malformed lines are reported to ``c`` as ``IM102`` (and skipped).

    >>> c = Collector()
    >>> ini = parse_ini("m.ini", "[TRAJ]\\n# a comment\\nCOORDINATES = X Z\\nCOORDINATES = X Y\\n", c)
    >>> ini.get("TRAJ", "COORDINATES").value, ini.get("TRAJ", "COORDINATES").span.line, c.errors
    ('X Z', 3, [])
    """
    entries: list[IniEntry] = []
    sections: dict[str, SourceSpan] = {}
    _parse(path, text, c, entries, sections, [str(Path(path).resolve())], [None])
    return IniFile(path, entries, sections)


def _logical_lines(text: str) -> Iterator[tuple[int, str, str]]:
    """(line number, joined text, first physical line) with ``\\`` continuations joined."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    i = 0
    while i < len(lines):
        start = i
        first = lines[i].rstrip("\r")
        joined = ""
        line = first.rstrip()
        while line.endswith("\\") and i + 1 < len(lines):
            joined += line[:-1]
            i += 1
            line = lines[i].rstrip("\r").rstrip()
        joined += line
        yield start + 1, joined, first
        i += 1


def _parse(path: str, text: str, c: Collector, entries: list[IniEntry], sections: dict[str, SourceSpan],
           stack: list[str], current: list[str | None]) -> None:
    for lineno, line, first in _logical_lines(text.lstrip("\ufeff")):
        if line.startswith("#INCLUDE"):
            _include(path, lineno, line, first, c, entries, sections, stack, current)
            continue
        stripped = line.strip()
        if not stripped or stripped[0] in "#;":
            continue
        col = len(line) - len(line.lstrip())
        if stripped.startswith("["):
            end = stripped.find("]")
            name = stripped[1:end].strip() if end > 0 else ""
            if end < 0 or not _ID.match(name):
                why = "missing ']'" if end < 0 else "a section name is letters, digits and '_', not starting with a digit"
                c.error("IM102", f"invalid section header {stripped!r}: {why}", line_span(path, lineno, first, col))
                current[0] = ""  # the keys that follow belong to no section; the header's error covers them
                continue
            sections.setdefault(name, line_span(path, lineno, first, col, col + end + 1))
            current[0] = name
            continue
        eq = line.find("=")
        key = line[col:eq].strip() if eq >= 0 else stripped
        if eq < 0 or not _ID.match(key):
            why = ("expected KEY = value" if eq < 0
                   else "a key is letters, digits and '_', not starting with a digit")
            c.error("IM102", f"malformed line {stripped!r}: {why}", line_span(path, lineno, first, col))
            continue
        if not current[0]:
            if current[0] is None:
                c.error("IM102", f"{key} = ... comes before any [SECTION] header", line_span(path, lineno, first, col))
            continue
        value = line[eq + 1:].strip()
        vcol = line.find(value, eq + 1) if value else col
        if value and vcol >= len(first.rstrip()):
            vcol = col  # the value continued on a later line: point at the key
        span = line_span(path, lineno, first, vcol, vcol + len(value) if value and vcol != col else None)
        entries.append(IniEntry(current[0], key, value, span))


def _include(path: str, lineno: int, line: str, first: str, c: Collector, entries: list[IniEntry],
             sections: dict[str, SourceSpan], stack: list[str], current: list[str | None]) -> None:
    arg = line[len("#INCLUDE"):]
    if not arg[:1].isspace() or not arg.strip():
        c.error("IM102", "#INCLUDE needs a blank and a file name after it", line_span(path, lineno, first))
        return
    name = Path(arg.strip()).expanduser()
    target = name if name.is_absolute() else Path(path).parent / name
    resolved = str(target.resolve())
    span = line_span(path, lineno, first, len("#INCLUDE ") + (len(arg) - len(arg.lstrip()) - 1))
    if resolved in stack:
        c.error("IM108", f"#INCLUDE {arg.strip()}: the file includes itself (directly or through others)", span)
        return
    if len(stack) >= _MAX_INCLUDE_DEPTH:
        c.error("IM108", f"#INCLUDE {arg.strip()}: more than {_MAX_INCLUDE_DEPTH} levels of includes", span)
        return
    from ..errors import MachineImportError

    try:
        text = read_source(target, "included file", "IM109")
    except MachineImportError as exc:
        d = exc.diagnostics[0]
        c.error("IM109", f"#INCLUDE {arg.strip()}: {d.message} ({target})", span)
        return
    _parse(str(target), text, c, entries, sections, stack + [resolved], current)
