"""The code objects of the source nczones writes at run time, compiled once (issue 36).

The LinuxCNC double pass and the line shapes write small Python functions for the kinds of line a program has
(``doubles.py``'s steps and plans, ``shapes.py``'s shapes) and compile them.  A plan of an arc is some 9,000
characters; compiling the plans of a 10,000-line program of R-format arcs took about 20 ms of its ~150 ms,
every run.  :func:`compiled` gives the code object of a source:

- from this process's memo when the same source was compiled before (two plans of one program often have the
  same text);
- else, for a source of at least :data:`MIN_STORED` characters, from its entry in the cache folder of
  :mod:`nczones.machine_cache` (``$NCZONES_CACHE_DIR``, ``~/.cache/nczones``; ``NCZONES_CACHE=off`` turns it
  off) when that entry was written for the **very same source text**, file name, Python and nczones: the
  whole text is compared, no digest is trusted;
- else from ``compile``, then stored.

Soundness: a hit is a code object ``marshal`` wrote from ``compile(source, filename, "exec")`` of exactly this
text under this Python (``sys.version`` is in the entry's header; :mod:`marshal`'s format and the bytecode
belong to it), as Python's own ``__pycache__`` does for modules.  The entries are read under the same rules as
the machine files' (the user's own folder and files, writable by no one else; see :mod:`nczones.machine_cache`
and ``specs/machine-file.md``, "The parse cache").  A miss of any kind compiles; the cache never raises.

Bounds: an entry is named by the first :data:`SLOTS_HEX` hex digits of a digest of the source, so the folder
holds at most ``16 ** SLOTS_HEX`` code entries (two sources whose digests share them take each other's place:
the text check keeps either correct); sources of more than :data:`MAX_STORED` characters are not stored; the
memo holds at most :data:`MAX_MEMO` code objects.
"""

from __future__ import annotations

import os
import sys
from types import CodeType

from . import __version__
from .digest import sha256
from .machine_cache import cache_dir, read_entry, write_entry

__all__ = ["compiled", "forget", "MIN_STORED", "MAX_STORED", "MAX_MEMO", "SLOTS_HEX"]

#: Sources shorter than this are compiled (about 0.1 ms) rather than read from a file (about 0.05 ms).
MIN_STORED = 1000
#: Sources longer than this are not stored.
MAX_STORED = 1 << 17
#: Code objects this process keeps by source (when full it is emptied and fills again).
MAX_MEMO = 4096
#: Hex digits of a source's digest that name its entry (16 ** 3 = 4096 entries at most).
SLOTS_HEX = 3
_MAGIC = "nczones code cache"
_FORMAT = 1
_memo: dict[tuple[str, str], CodeType] = {}


def compiled(source: str, filename: str) -> CodeType:
    """The code object of ``compile(source, filename, "exec")``: from the memo, the cache folder or ``compile``.

    >>> code = compiled("x = 6 * 7\\n", "<doctest>")
    >>> scope = {}
    >>> exec(code, scope)
    >>> scope["x"]
    42
    >>> compiled("x = 6 * 7\\n", "<doctest>") is code
    True
    """
    key = (source, filename)
    code = _memo.get(key)
    if code is not None:
        return code
    folder = cache_dir() if MIN_STORED <= len(source) <= MAX_STORED else None
    if folder is None:
        code = compile(source, filename, "exec")
    else:
        entry = _entry(folder, source)
        header = (_MAGIC, _FORMAT, sys.version, __version__, filename, source)
        code = read_entry(entry, header, 8 * MAX_STORED + 65536)
        if type(code) is not CodeType:
            code = compile(source, filename, "exec")
            write_entry(entry, header, code)
    if len(_memo) >= MAX_MEMO:  # a long process (a fleet, a test run) starts the memo again, never stops using it
        _memo.clear()
    _memo[key] = code
    return code


def forget() -> None:
    """Empty this process's memo (the folder's entries stay)."""
    _memo.clear()


def _entry(folder: str, source: str) -> str:
    """The entry of ``source`` in ``folder`` (one of ``16 ** SLOTS_HEX`` names)."""
    slot = sha256(source.encode("utf-8", "surrogatepass")).hexdigest()[:SLOTS_HEX]
    return os.path.join(folder, f"code-{slot}.marshal")
