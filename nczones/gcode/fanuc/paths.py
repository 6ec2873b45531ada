"""Multi-path programs: one text holding the programs of several paths (channels) of one control.

A multi-path Fanuc control (a Swiss-type lathe such as Citizen's L series, a twin-turret lathe) runs one
program per path, each path moving its own slides, and the path programs wait for each other at wait
marks.  In a program file the path programs follow each other, each after a header line ``$n`` (n = 1, 2,
...); ``$0`` starts a data section that is no path's program (Citizen: the common variable presets).

nczones proves one path at a time: the machine file describes the slides of one path and names it
(``[fanuc] path = n``); the program is read as that path's program, every other line reads as a blank line
(so line numbers and spans stay those of the file).  The rules are in ``specs/turning.md``
("Multi-path programs").
"""

from __future__ import annotations

import re

from ...errors import Diagnostic, GcodeError
from ..lexer import make_span
from ..source import materialized

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from ..source import FileText

__all__ = ["path_headers", "select_path"]

#: A path header line: ``$`` and the path number, alone on its line (blanks and a comment may follow).
_HEADER = re.compile(r"[ \t]*\$[ \t]*(\d+)[ \t]*(?:\([^)]*\)[ \t]*)?$")
#: Lines that may come before the first header: blank lines and the tape start ``%``.
_LEAD = re.compile(r"[ \t]*%?[ \t]*$")


def path_headers(text: str | FileText) -> list[tuple[int, int]]:
    """``[(line number, path number)]`` of the path headers, empty unless ``text`` is a multi-path program.

    A text is a multi-path program when its first line other than blank lines and ``%`` is a header.

    >>> path_headers("$1\\nG0 X1.\\n$2\\nG0 Z1.\\n$0\\n#500=1\\n")
    [(1, 1), (3, 2), (5, 0)]
    >>> path_headers("G0 X1.\\n$2\\n")
    []
    """
    # the first line other than blank lines and % (read line by line: a text that is no multi-path program,
    # a streamed file among them, is not split)
    pos, n, first = 0, len(text), 0
    while True:
        nl = text.find("\n", pos)
        end = n if nl < 0 else nl
        if not _LEAD.match(text[pos:end].rstrip("\r")):
            break
        if nl < 0:
            return []
        pos, first = end + 1, first + 1
    if not _HEADER.match(text[pos:end].rstrip("\r")):
        return []
    lines = materialized(text).split("\n")
    out = []
    for i in range(first, len(lines)):
        m = _HEADER.match(lines[i].rstrip("\r"))
        if m is not None:
            out.append((i + 1, int(m.group(1))))
    return out


def select_path(text: str | FileText, path: int | None, file: str) -> str:
    """The program of path ``path`` of a multi-path text, every other line blank; other texts unchanged.

    A multi-path text needs ``path`` (``[fanuc] path``) and a ``$path`` section: else ``GcodeError`` GC101
    at the first header, naming the paths the text has.

    >>> select_path("%\\n$1\\nG0 X1.\\n$2\\nG0 Z1.\\n$0\\n#500=1\\n%\\n", 2, "p.nc").split("\\n")
    ['%', '', '', '', 'G0 Z1.', '', '', '', '']
    >>> select_path("G0 X1.\\n", None, "p.nc")
    'G0 X1.\\n'
    """
    headers = path_headers(text)
    if not headers:
        return text  # type: ignore[return-value]  # a streamed file (FileText) stays streamed, as a str would
    lines = materialized(text).split("\n")
    paths = sorted({n for _, n in headers if n != 0})
    if path is None or path not in paths:
        line0 = headers[0][0]
        shown = lines[line0 - 1].rstrip("\r")
        have = ", ".join(f"${n}" for n in paths) or "no path section"
        if path is None:
            msg = (f"a multi-path program (paths {have}): name the path this machine file describes with "
                   f"[fanuc] path = {paths[0] if paths else 1} (each path is proved as its own program, "
                   "on its own slides)")
        else:
            msg = f"the machine file names path {path} ([fanuc] path) but the program has only {have}"
        span = make_span(file, line0, 1, len(shown) + 1, shown)
        raise GcodeError(Diagnostic("GC101", msg, span))
    keep = [False] * len(lines)
    current: int | None = None
    starts = {ln: n for ln, n in headers}
    first = headers[0][0]
    for i in range(len(lines)):
        n = starts.get(i + 1)
        if n is not None:
            current = n
            continue
        keep[i] = i + 1 < first or current == path
    return "\n".join(line if k else ("\r" if line.endswith("\r") else "") for line, k in zip(lines, keep))
