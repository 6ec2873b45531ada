"""Cheap searches of a program's text that choose its interpreter before any block is read.

They live apart from the interpreters they choose (:mod:`nczones.gcode.cylindrical`, :mod:`nczones.gcode.linuxcnc.lathe`)
so that a program which needs neither does not import them (start-up, issue 36).
"""

from __future__ import annotations

import re

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from .source import FileText

__all__ = ["PIECE_CHARS", "uses_cylindrical", "uses_lathe"]

#: G07.1 / G107 in lower-cased text (within a line; blanks as in ``G7 .1``).  Searched in lower-cased pieces
#: rather than with ``re.I``, which is 4x slower: a literal first character lets the search skip ahead.
_CYLINDRICAL = re.compile(r"g[ \t]*0*(?:7[ \t]*\.[ \t]*1(?![0-9])|107(?![0-9.]))")
#: G7, G8 and G70-G72 (.1 .2) in lower-cased text.
_LATHE = re.compile(r"g\s*0*7\s*[0-2]?(?![\d.])|g\s*0*8(?![\d.])|g\s*0*7\s*[0-2]\s*\.\s*[0-2]")
#: The size of the pieces :func:`uses_cylindrical` lower-cases at a time (cut after a newline).
PIECE_CHARS = 1 << 16


def uses_cylindrical(text: str | FileText) -> bool:
    """Does the program text mention G07.1 / G107 (then the full interpreter with the mode runs it)?

    >>> uses_cylindrical("G7.1 C20"), uses_cylindrical("g07 .1C0"), uses_cylindrical("G107 C5"), uses_cylindrical("G7.15 G1070")
    (True, True, True, False)
    """
    n = len(text)
    lo = 0
    while lo < n:  # pieces cut after a newline: no copy of the whole program
        hi = text.find("\n", lo + PIECE_CHARS)
        hi = n if hi < 0 else hi + 1
        if _CYLINDRICAL.search(text[lo:hi].lower()) is not None:
            return True
        lo = hi
    return False


def uses_lathe(text: str | FileText) -> bool:
    """Does a LinuxCNC program mention G7, G8 or G70-G72 (then the lathe interpreter runs it, no fast path)?

    A streamed file is searched in pieces cut after a newline: a mention that the whole-text search would
    find across a line end (``G`` ending one line, ``7`` starting the next: a ``G`` without a number, an error
    in every lane) is not found there when the cut falls between them; a mention within a line always is.

    >>> uses_lathe("G7 X20"), uses_lathe("g71.1 q100"), uses_lathe("G7.1 C20"), uses_lathe("G1 X70 G80")
    (True, True, False, False)
    """
    if not isinstance(text, str):  # a streamed file (FileText): its pieces, cut after a newline
        return any(_LATHE.search(piece.lower()) is not None for piece in text.pieces(PIECE_CHARS))
    return _LATHE.search(text.lower()) is not None
