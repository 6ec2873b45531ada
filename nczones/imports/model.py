"""What an import produces: the machine's values, each with where it came from.

The readers (:mod:`.linuxcnc`, :mod:`.grbl`, :mod:`.fanuc`) turn a controller
configuration into an :class:`ImportedMachine`: exact values in the machine
file's units (mm, degrees, mm/min), each a :class:`Sourced` that remembers the
source line and how it was computed, plus the notes on what could not be taken.
:mod:`.render` writes it as a commented machine file.
"""

from __future__ import annotations

import decimal
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from types import MappingProxyType

from ..errors import Diagnostic, MachineImportError, Severity, SourceSpan
from ..exact import MAX_ABS_LENGTH, decimal_places, format_decimal

__all__ = [
    "KINDS",
    "Sourced",
    "ZoneDraft",
    "HomingDraft",
    "ImportedMachine",
    "Collector",
    "read_source",
    "line_span",
    "rounded_decimal",
    "INCH",
]

#: The kinds of configuration ``nczones import-machine`` reads.
KINDS = ("linuxcnc", "grbl", "fanuc")

#: One inch in millimetres (exact by definition).
INCH = Fraction(254, 10)

#: Values that are not finite decimals are written rounded to this many places
#: (a nanometre in mm), with a note giving the exact value.
ROUND_PLACES = 9

_REAL_RE = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\Z")


@dataclass(frozen=True, slots=True)
class Sourced:
    """An exact value in machine-file units and where it came from.

    ``how`` says in words how the value was obtained from the source, such as
    ``"[AXIS_X] MAX_VELOCITY = 30.48 (mm/s) x 60"``; it becomes the value's
    comment in the machine file.
    """

    value: Fraction
    how: str
    span: SourceSpan | None = None

    def where(self) -> str:
        """``file:line`` of the source, or empty."""
        return f"{self.span.file}:{self.span.line}" if self.span is not None else ""


@dataclass(frozen=True, slots=True)
class ZoneDraft:
    """A box zone to be written; ``min``/``max`` map an axis to its bound."""

    name: str
    forbid: bool
    min: Mapping[str, Sourced]
    max: Mapping[str, Sourced]
    comment: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class HomingDraft:
    """What the source says about one axis' homing, written commented out.

    The machine file's ``[homing.<axis>]`` needs values (dog length, grid pitch,
    detector phase) that controller configurations do not hold; ``missing``
    names them.  ``fields`` are ``(key, value, comment)`` triples in the
    section's terms.
    """

    axis: str
    fields: tuple[tuple[str, Sourced | str, str], ...]
    missing: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class ImportedMachine:
    """A machine read from a controller configuration, before it is written.

    Every per-axis mapping is keyed by the machine file's axis names; missing
    entries take the machine file's defaults (the pulse) or are errors caught
    while reading (rates, reference).  ``notes`` are the ``IM2xx`` notes: what
    was not taken, rounded or assumed.
    """

    kind: str
    source: str
    name: str
    name_how: str
    axes: tuple[str, ...]
    axes_how: str
    rapid: Mapping[str, Sourced]
    reference: Mapping[str, Sourced]
    pulse: Mapping[str, Sourced] = field(default_factory=lambda: MappingProxyType({}))
    start: Mapping[str, Sourced] = field(default_factory=lambda: MappingProxyType({}))
    rapid_mode: tuple[str, str] = ("linear", "")
    monitor_period_ms: Sourced | None = None
    modal: tuple[tuple[str, str], ...] = ()
    extra: tuple[tuple[str, str, str], ...] = ()
    offsets: Mapping[str, Mapping[str, Sourced]] = field(default_factory=lambda: MappingProxyType({}))
    tool_lengths: Mapping[int, Sourced] = field(default_factory=lambda: MappingProxyType({}))
    tool_diameters: Mapping[int, Sourced] = field(default_factory=lambda: MappingProxyType({}))
    zones: tuple[ZoneDraft, ...] = ()
    homing: tuple[HomingDraft, ...] = ()
    notes: tuple[Diagnostic, ...] = ()
    #: More per-axis tables (``"machine.reference_2"`` ...), written after ``[machine.start]``.
    axis_tables: tuple[tuple[str, Mapping[str, Sourced]], ...] = ()
    #: More tables (``"fanuc"``, ``"macros"``): rows of (key, TOML value, comment).
    tables: tuple[tuple[str, tuple[tuple[str, str, str], ...]], ...] = ()
    #: LinuxCNC ``[RS274NGC] SUBROUTINE_PATH``: (absolute folders in order, where it was written); written as
    #: ``[linuxcnc] subroutine_path`` relative to the machine file's folder.
    subroutine_path: tuple[tuple[str, ...], str] = ((), "")
    #: Commented-out ``[[tools]]`` starts from a Fanuc tool offset listing (``nczones.imports.fanuc_tools``): rows
    #: of (assignment, comment), each written as a comment line; an empty assignment is a comment alone.
    tool_solids: tuple[tuple[str, str], ...] = ()


class Collector:
    """Collects the errors (``IM1xx``) and notes (``IM2xx``) of one import."""

    def __init__(self) -> None:
        self.errors: list[Diagnostic] = []
        self.notes: list[Diagnostic] = []

    def error(self, code: str, message: str, span: SourceSpan | None = None, *, file: str | None = None) -> None:
        self.errors.append(Diagnostic(code, message, span, Severity.ERROR, file=file))

    def note(self, code: str, message: str, span: SourceSpan | None = None, *, file: str | None = None) -> None:
        self.notes.append(Diagnostic(code, message, span, Severity.NOTE, file=file))

    def raise_if_failed(self) -> None:
        """Raise every error found so far, in file order (files in the order they were first named)."""
        if self.errors:
            files: dict[str, int] = {}
            for d in self.errors:
                files.setdefault(d.location().split(":")[0] if d.span is None else d.span.file, len(files))

            def key(d: Diagnostic) -> tuple[int, int, int]:
                if d.span is None:
                    return (files.get(d.file or "", 0), 0, 0)
                return (files[d.span.file], d.span.line, d.span.column)

            raise MachineImportError(sorted(self.errors, key=key))

    def real(
        self,
        text: str,
        what: str,
        span: SourceSpan | None,
        *,
        limit: Fraction | None = None,
    ) -> Fraction | None:
        """An exact number from decimal text (an exponent is allowed: ``1e99``).

        Reports ``IM103`` for text that is not a number and ``IM104`` for a
        magnitude beyond ``limit`` (when given) or an absurd exponent.
        """
        t = text.strip()
        if not _REAL_RE.match(t):
            self.error("IM103", f"{what}: {t!r} is not a number; write a decimal such as 12.5", span)
            return None
        d = decimal.Decimal(t)
        if d and d.adjusted() > 300:
            self.error("IM104", f"{what}: {t} is out of range", span)
            return None
        q = Fraction(d)
        if limit is not None and abs(q) > limit:
            self.error("IM104", f"{what}: {t} is out of range; the machine file allows a magnitude of at most "
                       f"{format_decimal(limit)}", span)
            return None
        return q


def line_span(path: str, lineno: int, text: str, start: int = 0, end: int | None = None) -> SourceSpan:
    """A span over ``text[start:end]`` of line ``lineno`` (1-based), carets under it."""
    stripped = text.rstrip("\r\n")
    if end is None or end <= start:
        end = len(stripped.rstrip()) or start + 1
    return SourceSpan(path, lineno, start + 1, end + 1, stripped)


def read_source(path: str | Path, what: str, code: str = "IM100") -> str:
    """The text of a configuration file, or ``MachineImportError`` (``code``) saying why not."""
    p = Path(path)
    try:
        data = p.read_bytes()
    except IsADirectoryError:
        raise MachineImportError(Diagnostic(code, f"cannot read the {what}: it is a directory", file=str(path))) from None
    except OSError as exc:
        raise MachineImportError(
            Diagnostic(code, f"cannot read the {what}: {exc.strerror or exc}", file=str(path))
        ) from None
    nul = data.find(b"\x00")
    if nul >= 0:
        raise MachineImportError(Diagnostic(
            code, f"the {what} is not text (it holds a NUL byte at byte {nul})", file=str(path)))
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise MachineImportError(Diagnostic(
            code, f"the {what} is not UTF-8 text ({exc.reason} at byte {exc.start}); if it was punched in ISO "
            "code with even parity, clear the eighth bit first", file=str(path))) from None


def rounded_decimal(q: Fraction) -> tuple[Fraction, bool]:
    """``q`` itself when it is a finite decimal, else rounded to ``ROUND_PLACES`` places.

    >>> rounded_decimal(Fraction(1, 8)), rounded_decimal(Fraction(1, 3))
    ((Fraction(1, 8), False), (Fraction(333333333, 1000000000), True))
    """
    places = decimal_places(q)
    if places is not None and places <= 30:
        return q, False
    scale = 10**ROUND_PLACES
    return Fraction(round(q * scale), scale), True


def in_range(c: Collector, value: Fraction, what: str, span: SourceSpan | None) -> bool:
    """Whether ``value`` fits the machine file's range (mm, deg, mm/min); ``IM104`` if not."""
    if abs(value) > MAX_ABS_LENGTH:
        c.error("IM104", f"{what}: {format_decimal(value)} is out of range; the machine file allows a magnitude "
                f"of at most {format_decimal(MAX_ABS_LENGTH)} (mm, deg, mm/min)", span)
        return False
    return True


def frozen(mapping: Mapping) -> Mapping:
    return MappingProxyType(dict(mapping))


Finder = Callable[[str], Sourced | None]
