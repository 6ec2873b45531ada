"""Where a program's text comes from: a file, standard input, or text given directly.

A :class:`ProgramSource` is the program text with its name (for
diagnostics) and the SHA-256 of the bytes it was read from, so a report can
name exactly what it verified.  Reading is strict, because nczones is a gate
in front of a machine:

* a path is always a path: a file that does not exist or cannot be read is
  one error (``GC100``), never G-code text;
* the bytes must be UTF-8 text without NUL bytes (``GC108``);
* a line may hold at most :data:`MAX_LINE_CHARS` characters (``GC110``): a
  real block is a few hundred characters at most, and a file whose line
  ends are lost (``\\r`` only, or binary data) would otherwise be read as
  one line of many megabytes;
* :meth:`ProgramSource.require_code` refuses a program that is empty or
  only whitespace (``GC109``): a post-processor that wrote nothing must not
  pass the gate.

Text given directly (:func:`program_text`) goes through the same line check.

>>> src = program_text("G1 X1 F100\\n", "part.ngc")
>>> src.name, src.sha256[:12], src.path is None
('part.ngc', '92305d112ba1', True)
>>> program_text("  \\n").require_code()
Traceback (most recent call last):
...
nczones.errors.GcodeError: <program>: error[GC109]: empty program: the text holds only whitespace; there is nothing to verify
"""

from __future__ import annotations

import hashlib
import os
import sys
from dataclasses import dataclass
from typing import BinaryIO

from ..errors import EXCERPT_CHARS, Diagnostic, GcodeError, InvalidArgument, SourceSpan

__all__ = [
    "MAX_LINE_CHARS",
    "ProgramSource",
    "ProgramLike",
    "load_program",
    "read_stdin",
    "program_text",
    "as_source",
    "STDIN_NAME",
]

#: The longest line accepted, in characters (LinuxCNC accepts 255, Fanuc
#: controls a few hundred; CAM comments stay far below this).
MAX_LINE_CHARS = 65_536

#: How a program read from standard input is named in diagnostics and reports.
STDIN_NAME = "<stdin>"


@dataclass(frozen=True, slots=True)
class ProgramSource:
    """A program's text, its name and the SHA-256 of its bytes (UTF-8 for text given directly).

    ``path`` is the file it was read from (``None`` for standard input and
    text given directly).
    """

    text: str
    name: str
    sha256: str
    path: str | None = None

    @property
    def is_empty(self) -> bool:
        """True for no text or whitespace only."""
        return not self.text.strip()

    def require_code(self) -> ProgramSource:
        """Itself, or :class:`~nczones.errors.GcodeError` ``GC109`` when it is empty or only whitespace."""
        if self.is_empty:
            what = ("the file is empty (0 bytes)" if self.path is not None and not self.text
                    else "the input is empty (0 bytes)" if self.name == STDIN_NAME and not self.text
                    else f"the {'file' if self.path is not None else 'input' if self.name == STDIN_NAME else 'text'}"
                         " holds only whitespace")
            raise GcodeError(Diagnostic("GC109", f"empty program: {what}; there is nothing to verify",
                                        file=self.name))
        return self


#: What the Python API accepts as a program: a path (``str`` or ``PathLike``) or a :class:`ProgramSource`.
ProgramLike = str | os.PathLike | ProgramSource


def _decode(data: bytes, name: str) -> str:
    """UTF-8 text, or one GC108 error for binary or non-UTF-8 bytes."""
    nul = data.find(b"\0")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        if nul < 0 or nul > exc.start:
            raise GcodeError(Diagnostic("GC108", f"not UTF-8 text: byte 0x{data[exc.start]:02x} at offset "
                                                 f"{exc.start} (line {line}) is not valid UTF-8; save the "
                                                 "program as UTF-8 (or ASCII)", file=name)) from None
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise GcodeError(Diagnostic("GC108", f"a binary file, not G-code text: a NUL byte at offset {nul} "
                                             f"(line {line})", file=name))
    return text


def _check_lines(text: str, name: str) -> None:
    """GC110 for the first line longer than :data:`MAX_LINE_CHARS` (a scan that jumps a window at a time)."""
    pos, n, limit = 0, len(text), MAX_LINE_CHARS
    while n - pos > limit:
        nl = text.rfind("\n", pos, pos + limit + 1)
        if nl >= 0:
            pos = nl + 1
            continue
        end = text.find("\n", pos)
        end = n if end < 0 else end
        line = text.count("\n", 0, pos) + 1
        hint = ""
        if "\r" in text[pos:pos + limit]:
            hint = "; its lines seem to end with a carriage return only (\\r): convert them to \\n"
        raise GcodeError(Diagnostic(
            "GC110", f"line {line} is {end - pos:,} characters long; nczones reads lines of at most "
                     f"{limit:,} characters{hint}",
            SourceSpan(name, line, 1, None, text[pos:pos + 2 * EXCERPT_CHARS])))


def _source(data: bytes, name: str, path: str | None) -> ProgramSource:
    text = _decode(data, name)
    _check_lines(text, name)
    return ProgramSource(text, name, hashlib.sha256(data).hexdigest(), path)


def load_program(path: str | os.PathLike, name: str | None = None) -> ProgramSource:
    """Read the program file at ``path`` (``GC100`` when it cannot be read, ``GC108``, ``GC110``).

    ``name`` is what diagnostics and reports call it (default: the path as given).

    >>> load_program("specs/examples/programs/notch_dip.ngc").text.splitlines()[4]
    'G1 X50'
    >>> load_program("no/such/part.nc")
    Traceback (most recent call last):
    ...
    nczones.errors.GcodeError: no/such/part.nc: error[GC100]: cannot read the program: No such file or directory
    """
    path_s = os.fspath(path)
    if not isinstance(path_s, str):
        raise InvalidArgument(f"a program path must be text, not {type(path_s).__name__}")
    shown = name or path_s
    try:
        with open(path_s, "rb") as fh:
            data = fh.read()
    except OSError as exc:
        raise GcodeError(Diagnostic("GC100", f"cannot read the program: {exc.strerror or exc}", file=shown)) from None
    except ValueError as exc:  # a NUL character in the path
        raise GcodeError(Diagnostic("GC100", f"cannot read the program: {exc}", file=repr(shown))) from None
    return _source(data, shown, path_s)


def read_stdin(stream: BinaryIO | None = None) -> ProgramSource:
    """Read a program from standard input (or ``stream``), named :data:`STDIN_NAME`."""
    if stream is None:
        stream = sys.stdin.buffer
    try:
        data = stream.read()
    except OSError as exc:
        raise GcodeError(Diagnostic("GC100", f"cannot read the program: {exc.strerror or exc}",
                                    file=STDIN_NAME)) from None
    return _source(data, STDIN_NAME, None)


def program_text(text: str, name: str = "<program>") -> ProgramSource:
    """Program text given directly (``GC110`` for an over-long line); its SHA-256 is that of its UTF-8 bytes."""
    if not isinstance(text, str):
        raise InvalidArgument(f"program text must be a str, not {type(text).__name__}")
    _check_lines(text, name)
    return ProgramSource(text, name, hashlib.sha256(text.encode("utf-8", errors="surrogatepass")).hexdigest())


def as_source(program: ProgramLike, *, file: str | None = None, text_function: str = "interpret_text") -> ProgramSource:
    """A :class:`ProgramSource` from a path or a source; a ``str`` is a path, never program text.

    ``file`` renames it for diagnostics.  A ``str`` with a line break cannot
    be a path and is refused with a pointer to ``text_function``, the
    function that takes text.
    """
    if isinstance(program, ProgramSource):
        if file is not None and file != program.name:
            from dataclasses import replace

            return replace(program, name=file)
        return program
    if isinstance(program, str) and ("\n" in program or "\r" in program):
        raise InvalidArgument(f"a program given as str is a path to a file; this one holds a line break, so it "
                              f"looks like program text: pass text to {text_function}() instead")
    if not isinstance(program, (str, os.PathLike)):
        raise InvalidArgument(f"a program is a path (str or os.PathLike) or a ProgramSource, not "
                              f"{type(program).__name__}; pass text to {text_function}()")
    return load_program(program, file)
