"""Where a program's text comes from: a file, standard input, or text given directly.

A :class:`ProgramSource` is the program text with its name (for
diagnostics) and the SHA-256 of the bytes it was read from, so a report can
name exactly what it verified.  Reading is strict, because nczones is a gate
in front of a machine:

* a path is always a path: a file that does not exist or cannot be read is
  one error (``GC100``), never G-code text;
* the bytes must be UTF-8 text without NUL bytes (``GC108``); a byte order
  mark decides the encoding instead (UTF-8, UTF-16 LE or BE), and bytes that
  are not UTF-8 inside a comment (``(...)`` or after ``;``) are read as
  CP1252 (Latin-1 for the five bytes CP1252 leaves undefined), the usual
  shop encodings, with a note in :attr:`ProgramSource.notes`; outside a
  comment they stay an error;
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
    #: What reading assumed (a byte order mark, comment bytes read as CP1252); verify reports them as notes.
    notes: tuple[str, ...] = ()

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


#: Byte order marks and the encoding each names (UTF-32 is not a shop encoding: its NULs stay GC108).
_BOMS = ((b"\xef\xbb\xbf", "utf-8", "UTF-8"), (b"\xff\xfe", "utf-16-le", "UTF-16 LE"),
         (b"\xfe\xff", "utf-16-be", "UTF-16 BE"))


def _comment_spans(line: str) -> list[tuple[int, int]]:
    """The ``(...)`` comments of one line and a ``;`` comment to its end, as [start, end) offsets.

    An unclosed ``(`` runs to the end of the line (the parser refuses it later).
    """
    spans, i, n = [], 0, len(line)
    while i < n:
        c = line[i]
        if c == "(":
            j = line.find(")", i + 1)
            j = n if j < 0 else j + 1
            spans.append((i, j))
            i = j
        elif c == ";":
            spans.append((i, n))
            break
        else:
            i += 1
    return spans


def _cp1252(byte: int) -> str:
    try:
        return bytes([byte]).decode("cp1252")
    except UnicodeDecodeError:  # 0x81, 0x8d, 0x8f, 0x90, 0x9d: undefined in CP1252
        return chr(byte)


def _decode_comments(data: bytes, name: str) -> tuple[str, tuple[str, ...]]:
    """UTF-8 text whose non-UTF-8 bytes all lie in comments, those read as CP1252; else GC108 on the first."""
    text = data.decode("utf-8", errors="surrogateescape")
    out: list[str] = []
    lines_noted: list[int] = []
    offset = 0  # byte offset of the current line
    for number, line in enumerate(text.split("\n"), 1):
        raw_len = len(line.encode("utf-8", errors="surrogateescape"))
        if any("\udc80" <= c <= "\udcff" for c in line):
            spans = _comment_spans(line)
            chars = list(line)
            for k, c in enumerate(chars):
                if "\udc80" <= c <= "\udcff":
                    if not any(a <= k < b for a, b in spans):
                        byte_at = offset + len(line[:k].encode("utf-8", errors="surrogateescape"))
                        raise GcodeError(Diagnostic(
                            "GC108", f"not UTF-8 text: byte 0x{data[byte_at]:02x} at offset {byte_at} (line "
                                     f"{number}) is not valid UTF-8 and is not inside a comment; save the "
                                     "program as UTF-8 (or ASCII)", file=name))
                    chars[k] = _cp1252(ord(c) - 0xDC00)
            line = "".join(chars)
            lines_noted.append(number)
        out.append(line)
        offset += raw_len + 1
    shown = ", ".join(map(str, lines_noted[:5])) + (", ..." if len(lines_noted) > 5 else "")
    note = (f"the program is not UTF-8: bytes inside comments on line(s) {shown} were read as CP1252/Latin-1 "
            "(comments only; they do not change what the machine does)")
    return "\n".join(out), (note,)


def _decode(data: bytes, name: str) -> tuple[str, tuple[str, ...]]:
    """The text and what reading it assumed; one GC108 error for binary bytes or non-UTF-8 bytes outside comments.

    A byte order mark decides the encoding (UTF-8, UTF-16 LE/BE).  Without one,
    the text is UTF-8, except that bytes that are not UTF-8 inside comments
    are read as CP1252 (Latin-1), with a note.
    """
    notes: tuple[str, ...] = ()
    for bom, codec, label in _BOMS:
        if data.startswith(bom):
            try:
                text = data[len(bom):].decode(codec)
            except UnicodeDecodeError as exc:
                at = exc.start + len(bom)
                raise GcodeError(Diagnostic("GC108", f"not {label} text although it starts with a {label} byte "
                                                     f"order mark: the bytes at offset {at} are not valid "
                                                     f"{label}", file=name)) from None
            if "\0" in text:
                at = text.index("\0")
                raise GcodeError(Diagnostic("GC108", f"a binary file, not G-code text: a NUL character (character "
                                                     f"{at} of the {label} text)", file=name))
            if codec != "utf-8":
                notes = (f"the program is {label} text (read by its byte order mark)",)
            return text, notes
    nul = data.find(b"\0")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        if nul < 0 or nul > exc.start:
            bad = data[:nul] if nul >= 0 else data
            text, notes = _decode_comments(bad, name)
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise GcodeError(Diagnostic("GC108", f"a binary file, not G-code text: a NUL byte at offset {nul} "
                                             f"(line {line})", file=name))
    return text, notes


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
    text, notes = _decode(data, name)
    _check_lines(text, name)
    return ProgramSource(text, name, hashlib.sha256(data).hexdigest(), path, notes)


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
