"""The one errors module of nczones.

Every exception the package raises on purpose derives from
:class:`NczonesError`.  Problems in user input (G-code text, machine files,
command-line arguments, controller configurations) are :class:`InputError`;
they carry one or more :class:`Diagnostic` values, each with a stable code
(``GC1xx`` lexical G-code, ``GC2xx`` block/modal G-code, ``GC3xx``
interpretation, ``ZN1xx`` machine file, ``IM1xx`` a controller configuration
read by ``nczones import-machine``), a source span when one is known, the
value as written and what is allowed.  Input errors are collected and raised
together.

Notes are diagnostics that stop nothing: ``IM2xx`` says what an import could
not take into the machine file (and why), ``EX1xx`` what ``nczones
export-zones`` could not write into a control's settings.

Anything else that escapes is an internal bug and is reported as such by the
command line.

Every code, with its kind and one-line meaning, is listed once in
:mod:`nczones.error_codes` (``specs/errors.md`` is generated from it); a new
code is added there.
"""

from __future__ import annotations

import enum
from collections.abc import Iterable

from .precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

__all__ = [
    "close_matches",
    "NczonesError",
    "InvalidArgument",
    "InternalError",
    "Severity",
    "SourceSpan",
    "program_lines",
    "caret_excerpt",
    "shorten",
    "EXCERPT_CHARS",
    "Diagnostic",
    "InputError",
    "GcodeError",
    "MachineFileError",
    "MachineImportError",
    "ProjectFileError",
]


class NczonesError(Exception):
    """Base class of every error nczones raises on purpose."""


class InvalidArgument(NczonesError, ValueError):
    """A public function was called with a value it cannot accept."""


class InternalError(NczonesError):
    """A broken invariant inside nczones: a bug, never the user's fault."""


class Severity(enum.Enum):
    ERROR = "error"
    WARNING = "warning"
    #: Something left out on purpose and said so (an import's "not taken").
    NOTE = "note"


@dataclass(frozen=True, slots=True)
class SourceSpan:
    """Where something stands in a source file (1-based line and column).

    ``text`` is the whole source line, so a diagnostic can echo it with a
    caret under columns ``column`` to ``end_column`` (exclusive).

    >>> str(SourceSpan("part.ngc", 12, 5, 8, "G01 X1.5 Y2"))
    'part.ngc:12:5'
    """

    file: str
    line: int
    column: int = 1
    end_column: int | None = None
    text: str = ""

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"

    def caret_lines(self) -> str:
        """The source line (cut around the caret to :data:`EXCERPT_CHARS`) and a caret line under the span.

        Empty if there is no text.
        """
        if not self.text:
            return ""
        source, caret = caret_excerpt(self.text, self.column, self.end_column or self.column + 1)
        return f"    {source}\n    {caret}"


#: The longest source excerpt a message shows (characters, the ``…`` marks included).
EXCERPT_CHARS = 200


def caret_excerpt(text: str, column: int, end_column: int | None = None,
                  width: int = EXCERPT_CHARS) -> tuple[str, str]:
    """A source line and a caret line under columns ``column`` to ``end_column`` (exclusive, 1-based).

    Tabs count as one column (as the lexer counts them).  ``end_column=None``
    underlines to the end of the line.  A line longer than ``width`` is cut
    around the caret, with ``…`` where text is left out, so neither line is
    longer than ``width``.

    >>> caret_excerpt("G1 $5", 4)
    ('G1 $5', '   ^~')
    >>> src, caret = caret_excerpt("(" + "x" * 500 + ") G1 Q5", 507, 509, width=40)
    >>> print(src); print(caret)
    …xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx) G1 Q5
                                         ^~
    """
    source = text.rstrip("\r\n").expandtabs(1)
    column = max(1, column)
    if end_column is None:
        end_column = max(column + 1, len(source.rstrip()) + 1)
    end_column = max(end_column, column + 1)
    start, stop, cut = 0, len(source), len(source) > width
    if cut:
        room = width - 2  # the two ellipses
        start = max(0, column - 1 - room // 3)
        stop = min(len(source), start + room)
        start = max(0, stop - room)
    shown = ("…" if start > 0 else "") + source[start:stop] + ("…" if stop < len(source) else "")
    lead = column - 1 - start + (1 if start > 0 else 0)
    under = max(1, (min(end_column - 1, stop) if cut else end_column - 1) - (column - 1))
    return shown, " " * lead + "^" + "~" * (under - 1)


def shorten(text: str, width: int = EXCERPT_CHARS) -> str:
    """``text`` cut in the middle to at most ``width`` characters (``…`` marks the cut).

    >>> shorten("abcdefghij", 7)
    'abc…hij'
    """
    if len(text) <= width:
        return text
    keep = width - 1
    return text[:keep - keep // 2] + "…" + text[len(text) - keep // 2:]


def program_lines(text: str) -> list[str]:
    r"""A program's lines as spans number them: line ``n`` is item ``n - 1``.

    Lines end at ``\n`` only, as the controller reads them (so ``\x0c`` or
    ``\u2028`` in a comment does not start a line, unlike ``str.splitlines``);
    a ``\r`` before the ``\n`` and a byte-order mark at the start are not
    part of a line.

    >>> program_lines("\ufeffG1 X1\r\n(a\x0cb)\nG1 X2")
    ['G1 X1', '(a\x0cb)', 'G1 X2']
    """
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if lines and lines[0].startswith("\ufeff"):
        lines[0] = lines[0][1:]
    return [ln[:-1] if ln.endswith("\r") else ln for ln in lines]


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """One problem found in user input.

    >>> d = Diagnostic("GC101", "unexpected character '$'", SourceSpan("a.ngc", 3, 4, 5, "G1 $5"))
    >>> print(d.render())
    a.ngc:3:4: error[GC101]: unexpected character '$'
        G1 $5
           ^
    """

    code: str
    message: str
    span: SourceSpan | None = None
    severity: Severity = Severity.ERROR
    file: str | None = None  # used when there is no span

    def location(self) -> str:
        if self.span is not None:
            return str(self.span)
        return self.file or "<input>"

    def render(self) -> str:
        # a message quotes what was written; a huge word must not make a huge message
        head = f"{self.location()}: {self.severity.value}[{self.code}]: {shorten(self.message, 4 * EXCERPT_CHARS)}"
        carets = self.span.caret_lines() if self.span is not None else ""
        return f"{head}\n{carets}" if carets else head


class InputError(NczonesError):
    """Bad user input: one or more diagnostics, raised together."""

    def __init__(self, diagnostics: tuple[Diagnostic, ...] | list[Diagnostic] | Diagnostic):
        if isinstance(diagnostics, Diagnostic):
            diagnostics = (diagnostics,)
        self.diagnostics: tuple[Diagnostic, ...] = tuple(diagnostics)
        if not self.diagnostics:
            raise InternalError("InputError raised without a diagnostic")
        super().__init__(self.render())

    @property
    def errors(self) -> tuple[Diagnostic, ...]:
        return tuple(d for d in self.diagnostics if d.severity is Severity.ERROR)

    @property
    def code(self) -> str:
        """The code of the first diagnostic."""
        return self.diagnostics[0].code

    def render(self) -> str:
        return "\n".join(d.render() for d in self.diagnostics)


class GcodeError(InputError):
    """Bad G-code text (codes GC1xx, GC2xx, GC3xx)."""


class MachineFileError(InputError):
    """A bad machine file (codes ZN1xx)."""


class MachineImportError(InputError):
    """A controller configuration ``nczones import-machine`` cannot read (codes IM1xx)."""


class ProjectFileError(InputError):
    """A bad fleet project file ``nczones.toml`` (codes FL1xx)."""


def close_matches(word: str, choices: Iterable[str], n: int = 1) -> list[str]:
    """The choices closest to a misspelt ``word``, for a message's "did you mean" (:mod:`difflib`, loaded only
    when a message needs it).

    >>> close_matches("uptp", ("upto", "min", "max"))
    ['upto']
    """
    import difflib

    return difflib.get_close_matches(word, list(choices), n=n)
