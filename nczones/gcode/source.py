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

import codecs
import os
import sys
from collections.abc import Iterator

from .. import digest as hashlib  # hashlib.sha256 without loading OpenSSL (start-up)
from ..digest import LaterDigest
from ..errors import EXCERPT_CHARS, Diagnostic, GcodeError, InvalidArgument, SourceSpan
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import BinaryIO

__all__ = [
    "MAX_LINE_CHARS",
    "ProgramSource",
    "ProgramLike",
    "load_program",
    "read_stdin",
    "program_text",
    "as_source",
    "STDIN_NAME",
    "FileText",
    "STREAM_MIN_BYTES",
    "materialized",
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
    text given directly).  ``digest`` holds the bytes until :attr:`sha256` is
    first asked for (:class:`~nczones.digest.LaterDigest`): a text report
    never hashes the program.
    """

    text: str
    name: str
    digest: LaterDigest
    path: str | None = None
    #: What reading assumed (a byte order mark, comment bytes read as CP1252); verify reports them as notes.
    notes: tuple[str, ...] = ()

    @property
    def sha256(self) -> str:
        """The SHA-256 (hex) of the program's bytes, computed at the first call."""
        return self.digest.hex

    @property
    def is_empty(self) -> bool:
        """True for no text or whitespace only."""
        if isinstance(self.text, FileText):
            return self.text.blank
        return not self.text.strip()

    def materialized(self) -> ProgramSource:
        """Itself with its whole text in memory (a streamed source, :class:`FileText`, read now)."""
        if isinstance(self.text, FileText):
            from dataclasses import replace

            return replace(self, text=self.text.read_all())
        return self

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
    return ProgramSource(text, name, LaterDigest(data), path, notes)


def load_program(path: str | os.PathLike, name: str | None = None, *, stream: bool = False) -> ProgramSource:
    """Read the program file at ``path`` (``GC100`` when it cannot be read, ``GC108``, ``GC110``).

    ``name`` is what diagnostics and reports call it (default: the path as given).  With ``stream``, a file of
    at least :data:`STREAM_MIN_BYTES` bytes of UTF-8 text (no byte order mark) is not read into memory: its ``text`` is a
    :class:`FileText` that reads the file a window at a time (the verify pipeline streams it; whoever needs
    the whole text calls :meth:`ProgramSource.materialized`).  Any other file is read whole, as without it.

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
    if stream:
        streamed = _streamed(path_s, shown)
        if streamed is not None:
            return streamed
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
    return ProgramSource(text, name, LaterDigest(text.encode("utf-8", errors="surrogatepass")))


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


#: The size from which :func:`load_program` with ``stream`` leaves a file on disk (smaller files are read
#: whole: their text costs less than the windows' reads).
STREAM_MIN_BYTES = 16 << 20

#: The bytes :class:`FileText` keeps in memory at a time (one window of the file).
WINDOW_BYTES = 1 << 20


def _streamed(path: str, name: str) -> ProgramSource | None:
    """A :class:`ProgramSource` whose text stays in the file, or None (read it whole): the file is smaller than
    :data:`STREAM_MIN_BYTES`, cannot be opened (the whole read reports it), or is not text with lines of at
    most :data:`MAX_LINE_CHARS` bytes, UTF-8 without a byte order mark (the whole read decodes it
    or reports it; a UTF-8 character may span two windows)."""
    try:
        fd = os.open(path, os.O_RDONLY)
    except (OSError, ValueError):
        return None
    try:
        st = os.fstat(fd)
        if st.st_size < STREAM_MIN_BYTES:
            os.close(fd)
            return None
        digest = hashlib.sha256()
        blank = True
        line = 0  # characters of the line not yet ended
        offset = 0
        present: set[str] = set()
        utf8 = None  # the UTF-8 decoder, from the first byte that is not ASCII (a character may span windows)
        while True:
            data = os.pread(fd, WINDOW_BYTES, offset)
            if not data:
                break
            digest.update(data)
            if b"\0" in data or (offset == 0 and data.startswith(b"\xef\xbb\xbf")):
                os.close(fd)  # binary, or a byte order mark: the whole read reports or drops it
                return None
            if utf8 is not None or not data.isascii():
                utf8 = utf8 or codecs.getincrementaldecoder("utf-8")()
                try:
                    utf8.decode(data)
                except UnicodeDecodeError:  # not UTF-8: the whole read decodes comments as CP1252 or reports it
                    os.close(fd)
                    return None
            if blank and data.strip():
                blank = False
            present.update(c for c in _NOTED if c.encode() in data)
            line = _line_after(data, line)
            if line < 0:
                os.close(fd)
                return None
            offset += len(data)
        if offset != st.st_size or (utf8 is not None and not _final(utf8)):
            os.close(fd)
            return None
        text = FileText(fd, offset, blank, (st.st_size, st.st_mtime_ns, st.st_ino), name,
                        frozenset(_NOTED) - present, utf8 is None)
    except OSError:
        os.close(fd)
        return None
    return ProgramSource(text, name, LaterDigest(known=digest.hexdigest()), path)  # type: ignore[arg-type]


def _final(decoder: codecs.IncrementalDecoder) -> bool:
    """Whether the UTF-8 text ends with a whole character (no sequence left open at the end of the file)."""
    try:
        decoder.decode(b"", final=True)
    except UnicodeDecodeError:
        return False
    return True


#: The characters whose absence from a streamed file the first read notes, so that asking for them (the
#: lanes' ``"#" in text``, ``text.find("O")``...) costs no further pass over the file.
_NOTED = "#/%OoMm([;\r"


def _line_after(data: bytes, line: int) -> int:
    """The length of the unfinished last line after ``data``, given ``line`` characters of a line before it;
    -1 when a line is longer than :data:`MAX_LINE_CHARS` (the scan of ``_check_lines``: a window at a time)."""
    first = data.find(b"\n")
    if first < 0:
        line += len(data)
        return -1 if line > MAX_LINE_CHARS else line
    if line + first > MAX_LINE_CHARS:
        return -1
    pos, n = first + 1, len(data)
    while n - pos > MAX_LINE_CHARS:
        nl = data.rfind(b"\n", pos, pos + MAX_LINE_CHARS + 1)
        if nl < 0:
            return -1
        pos = nl + 1
    return n - data.rfind(b"\n") - 1


class FileText:
    """The text of a program file, read from the file a window at a time instead of held whole.

    A plain ASCII file: it answers the few ``str`` questions the streamed verification asks (``len``, ``in``,
    ``find``, ``count`` of one character, ``endswith``, slices, ``isascii``) exactly as the ``str`` of the file
    would, and gives the file in blocks cut after a newline (:meth:`blocks`); anything else is not an attribute
    (a loud error, never a silent empty text).  Character offsets are byte offsets.

    A UTF-8 file with characters that are not ASCII (``ascii`` False, a comment's ``é``): the same questions
    are answered about its bytes read as Latin-1 (one character per byte, so offsets stay byte offsets, and
    an ASCII search or a newline count is exact: no byte of a UTF-8 multi-byte character is ASCII); only the
    double pass reads it so (:mod:`nczones.gcode.linuxcnc.doubles`, its lines through :meth:`decoded` of
    pieces cut after a newline), every other lane takes its whole text (:meth:`read_all`, UTF-8).

    The file stays open; a file changed while it is read is an error (:meth:`check_unchanged`).
    """

    __slots__ = ("fd", "n", "blank", "stamp", "name", "absent", "ascii", "_w0", "_window", "__weakref__")

    def __init__(self, fd: int, n: int, blank: bool, stamp: tuple[int, int, int], name: str,
                 absent: frozenset[str] = frozenset(), ascii: bool = True):
        self.fd, self.n, self.blank, self.stamp, self.name = fd, n, blank, stamp, name
        #: characters known not to occur in the file
        self.absent = absent
        #: every byte is ASCII (else UTF-8 with other characters: see the class's docstring)
        self.ascii = ascii
        self._w0 = 0
        self._window = ""

    def __del__(self) -> None:
        try:
            os.close(self.fd)
        except (OSError, AttributeError, TypeError):
            pass

    def __len__(self) -> int:
        return self.n

    def __bool__(self) -> bool:
        return self.n > 0

    def __repr__(self) -> str:
        return f"FileText({self.name!r}, {self.n} characters)"

    def _read(self, start: int, stop: int) -> str:
        data = os.pread(self.fd, max(0, stop - start), start)
        return data.decode("ascii" if self.ascii else "latin-1")

    def decoded(self, start: int, stop: int) -> str:
        """The text of bytes ``start``..``stop`` (whole UTF-8 characters: cut after a newline or at an end)."""
        return os.pread(self.fd, max(0, stop - start), start).decode("utf-8")

    def _at(self, pos: int) -> tuple[int, str]:
        """The window that holds ``pos`` (read when ``pos`` is outside the current one)."""
        if not self._w0 <= pos < self._w0 + len(self._window):
            self._w0 = pos
            self._window = self._read(pos, min(self.n, pos + WINDOW_BYTES))
        return self._w0, self._window

    def _span(self, start: int | None, end: int | None) -> tuple[int, int]:
        start = 0 if start is None else (max(0, self.n + start) if start < 0 else min(start, self.n))
        end = self.n if end is None else (max(0, self.n + end) if end < 0 else min(end, self.n))
        return start, end

    def __getitem__(self, key: slice) -> str:
        if type(key) is slice and key.step is None and type(key.start) is int and type(key.stop) is int:
            a, b = key.start - self._w0, key.stop - self._w0  # the common case: inside the current window
            if 0 <= a <= b <= len(self._window):
                return self._window[a:b]
        if not isinstance(key, slice) or key.step not in (None, 1):
            raise TypeError("FileText takes slices without a step")
        start, end = self._span(key.start, key.stop)
        if end <= start:
            return ""
        w0, window = self._at(start)
        if end <= w0 + len(window):
            return window[start - w0:end - w0]
        return self._read(start, end)

    def find(self, sub: str | bytes, start: int | None = None, end: int | None = None) -> int:
        if end is None and type(start) is int and type(sub) is str and start >= self._w0:
            k = self._window.find(sub, start - self._w0)  # the common case: a match in the current window
            if k >= 0:
                return self._w0 + k
        if isinstance(sub, bytes):
            sub = sub.decode("ascii")
        start, end = self._span(start, end)
        if not sub:
            return start if start <= end else -1
        if sub in self.absent:
            return -1
        pos = start
        while pos < end:
            w0, window = self._at(pos)
            if w0 + len(window) < min(end, pos + len(sub)):  # too short for a match at pos: read on from pos
                self._w0, self._window = pos, self._read(pos, min(self.n, pos + max(WINDOW_BYTES, 2 * len(sub))))
                w0, window = self._w0, self._window
            stop = min(end, w0 + len(window))
            k = window.find(sub, pos - w0, stop - w0)
            if k >= 0:
                return w0 + k
            if stop >= end:
                return -1
            pos = stop - len(sub) + 1  # every match starting before this was looked for (> pos: see above)
        return -1

    def rfind(self, sub: str, start: int | None = None, end: int | None = None) -> int:
        """The last match starting in ``start``..``end`` (read a window at a time from the end backwards)."""
        start, end = self._span(start, end)
        if not sub:
            return end if start <= end else -1
        if sub in self.absent:
            return -1
        hi = end  # every match starting at or after hi was looked for
        while hi > start:
            lo = max(start, hi - WINDOW_BYTES)
            k = self._read(lo, min(end, hi + len(sub) - 1)).rfind(sub)
            if k >= 0:
                return lo + k
            hi = lo
        return -1

    def head(self, n: int) -> FileText:
        """The file's first ``n`` characters as a streamed text of their own (the file opened again: each
        FileText closes its own descriptor)."""
        return FileText(os.dup(self.fd), max(0, min(n, self.n)), self.blank, self.stamp, self.name, self.absent,
                        self.ascii)

    def index(self, sub: str, start: int | None = None, end: int | None = None) -> int:
        k = self.find(sub, start, end)
        if k < 0:
            raise ValueError("substring not found")
        return k

    def count(self, sub: str, start: int | None = None, end: int | None = None) -> int:
        if len(sub) != 1:
            raise ValueError("FileText counts single characters only")
        start, end = self._span(start, end)
        total, pos = 0, start
        while pos < end:
            stop = min(end, pos + WINDOW_BYTES)
            if end - start <= WINDOW_BYTES:
                w0, window = self._at(pos)
                if stop <= w0 + len(window):
                    return total + window.count(sub, pos - w0, stop - w0)
            total += os.pread(self.fd, stop - pos, pos).count(sub.encode("ascii"))
            pos = stop
        return total

    def __contains__(self, sub: str) -> bool:
        return self.find(sub) >= 0

    def endswith(self, suffix: str) -> bool:
        return self[max(0, self.n - len(suffix)):] == suffix

    def isascii(self) -> bool:
        return self.ascii

    def blocks(self, size: int) -> Iterator[bytes]:
        """The file in blocks of about ``size`` bytes, each cut after a newline (or at the end), as
        ``_encoded_blocks`` cuts a ``str``: the cut is the first newline at or after ``size - 1``."""
        lo, n = 0, self.n
        while lo < n:
            hi = lo + size
            if hi >= n:
                yield os.pread(self.fd, n - lo, lo)
                return
            data = os.pread(self.fd, size + 4096, lo)  # most often holds the first newline from hi - 1
            cut = data.find(b"\n", size - 1)
            if cut >= 0:
                yield data[:cut + 1]
                lo += cut + 1
                continue
            cut = self.find("\n", hi - 1)
            hi = n if cut < 0 else cut + 1
            yield os.pread(self.fd, hi - lo, lo)
            lo = hi

    def pieces(self, size: int) -> Iterator[str]:
        """The text in pieces of about ``size`` characters, each cut after a newline (or at the end)."""
        for blk in self.blocks(size):
            yield blk.decode("utf-8")

    def read_all(self) -> str:
        """The whole text (for the paths that need it in memory)."""
        self.check_unchanged()
        return self.decoded(0, self.n)

    def check_unchanged(self) -> None:
        """GC100 when the file changed since it was first read (its text would not be the text hashed)."""
        st = os.fstat(self.fd)
        if (st.st_size, st.st_mtime_ns, st.st_ino) != self.stamp:
            raise GcodeError(Diagnostic("GC100", "cannot read the program: the file changed while it was being "
                                                 "verified; verify it again", file=self.name))


def materialized(text: str | FileText) -> str:
    """``text`` itself, or the whole text of a :class:`FileText`."""
    return text.read_all() if isinstance(text, FileText) else text
