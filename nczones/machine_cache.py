"""A checked cache of the parsed machine file: what ``tomllib.loads`` gave for the same bytes (issue 36).

A small verify spends about 12 ms of its ~80 ms importing :mod:`tomllib` (with :mod:`datetime`) and parsing a
machine file that rarely changes.  :func:`cached_table` keeps the parsed table of each machine file in one
:mod:`marshal` file (``marshal`` is built in: nothing to import) and gives it back only for the very same bytes.

An entry holds the **complete source bytes**, the Python version, the nczones version and :data:`FORMAT`; it is
used only when all four equal the current ones byte for byte (no hash is trusted), and when the entry and its
folder are regular, owned by the current user and writable by no one else.  Anything else -- no entry, another
file's entry, a short, corrupt, foreign or group-writable one, a value of an unexpected type -- is a miss: the
file is parsed by ``tomllib`` as without a cache, and the entry rewritten when it can be.  The cache never
causes an error: a folder that cannot be made or written is simply not used.

Soundness: a hit returns a table equal to ``tomllib.loads(text, parse_float=decimal.Decimal)`` of the bytes read
now, because the entry was written from exactly that call on exactly these bytes (the comparison is of the
whole text, not of a digest), under the same Python (its ``tomllib``) and the same nczones.  The table's values
are ``dict``, ``list``, ``str``, ``int``, ``bool`` and ``Decimal``; a Decimal is stored as its ``str`` (which
``Decimal`` reads back to the same sign, digits and exponent, NaN and infinities included) in a 1-tuple, a type
``tomllib`` never returns; a table holding anything else (TOML dates and times, a float) is not cached.  The
machine is then checked by :mod:`nczones.machine` exactly as after a parse.

Threat model (``specs/machine-file.md``, "The parse cache"): the entries are the user's own files in the
user's own folder.  Whoever can write them can also edit the machine file itself or the installed nczones, so
the cache adds no new way to change a verdict; entries others could write are not read.

Where: ``$NCZONES_CACHE_DIR``, else ``$XDG_CACHE_HOME/nczones`` (an absolute ``XDG_CACHE_HOME`` only), else
``~/.cache/nczones``; the folder is made with mode 0700, each entry written to a temporary file there and
renamed over the old one (``os.replace``, atomic), mode 0600.  ``NCZONES_CACHE=off`` turns the cache off.  An
entry is named by a digest of the machine file's absolute path; files of more than :data:`MAX_SOURCE` bytes
are not cached.
"""

from __future__ import annotations

import _thread
import decimal
import itertools
import marshal
import os
import stat
import sys

from . import __version__
from .digest import sha256

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

__all__ = ["cached_table", "cache_dir", "entry_path", "encode", "decode", "read_entry", "write_entry", "FORMAT",
           "MAX_SOURCE", "DIR_ENV", "SWITCH_ENV"]

#: The layout of an entry; a change of layout or of what is stored takes a new number.
FORMAT = 1
#: Machine files of more bytes than this are parsed every time (an entry holds the whole source).
MAX_SOURCE = 1 << 20
#: The folder of the entries, when set.
DIR_ENV = "NCZONES_CACHE_DIR"
#: ``off`` here: no entry is read or written.
SWITCH_ENV = "NCZONES_CACHE"
_MAGIC = "nczones machine-file cache"


class _NotStored(Exception):
    """A value :func:`encode` does not store (a TOML date or time, a float)."""


def cache_dir() -> str | None:
    """The folder of the entries (see the module's docstring), or None when the cache is off."""
    env = os.environ
    if env.get(SWITCH_ENV, "").strip().lower() == "off" or not hasattr(os, "getuid"):
        return None
    explicit = env.get(DIR_ENV)
    if explicit:
        return os.path.abspath(explicit)
    xdg = env.get("XDG_CACHE_HOME", "")
    if os.path.isabs(xdg):
        return os.path.join(xdg, "nczones")
    home = os.path.expanduser("~")
    return os.path.join(home, ".cache", "nczones") if os.path.isabs(home) else None


def entry_path(folder: str, path: str) -> str:
    """The entry of the machine file ``path`` in ``folder``: named by a digest of its absolute path (two
    files whose digests meet only take each other's place; the content check keeps either correct)."""
    key = sha256(os.path.abspath(path).encode("utf-8", "surrogateescape")).hexdigest()[:24]
    return os.path.join(folder, f"machine-{key}.marshal")


def _private(st: os.stat_result, kind: Callable[[int], bool]) -> bool:
    """Whether ``st`` is of ``kind``, owned by the current user and writable by no one else."""
    return kind(st.st_mode) and st.st_uid == os.getuid() and not st.st_mode & (stat.S_IWGRP | stat.S_IWOTH)


def _header(source: bytes) -> tuple[Any, ...]:
    """What an entry for ``source`` starts with: all of it must be equal for a hit."""
    return (_MAGIC, FORMAT, sys.version, __version__, source)


def encode(value: Any, texts: dict[str, str] | None = None) -> Any:
    """The table ``value`` as :mod:`marshal` stores it: each ``Decimal`` as the 1-tuple of its ``str``, and
    equal strings (keys and values) as one object, which :mod:`marshal` writes once and refers to after
    (``texts``: the strings met so far).  A table of thousands of ``{ upto = ..., min = ..., max = ... }`` is
    then read back with its keys and repeated limits made once each (issue 36); the value is the same.

    Raises
    ------
    _NotStored
        For a value of any type but ``dict`` (of ``str`` keys), ``list``, ``str``, ``int``, ``bool`` and
        ``Decimal``.
    """
    if texts is None:
        texts = {}
    kind = type(value)
    if kind is dict:
        return {texts.setdefault(_key(k), k): encode(v, texts) for k, v in value.items()}
    if kind is list:
        return [encode(v, texts) for v in value]
    if kind is str:
        return texts.setdefault(value, value)
    if kind is int or kind is bool:
        return value
    if kind is decimal.Decimal:
        return (str(value),)
    raise _NotStored(kind.__name__)


def _key(key: Any) -> str:
    if type(key) is not str:
        raise _NotStored(type(key).__name__)
    return key


def decode(stored: Any) -> Any:
    """The table :func:`encode` stored as ``stored``, decoded in place: its dicts and lists are reused, each
    Decimal's 1-tuple replaced by the ``Decimal`` (``stored`` is what :mod:`marshal` has just made, owned by no
    one else; a machine file's table is mostly strings, and a region list of thousands of them is checked
    without building it again, issue 36).

    Raises
    ------
    _NotStored
        For anything :func:`encode` does not produce (a foreign or corrupt entry; ``stored`` is then left part
        decoded, to be dropped).
    """
    kind = type(stored)
    if kind is dict:
        for k, v in stored.items():
            if type(k) is not str:
                raise _NotStored(type(k).__name__)
            t = type(v)
            if t is not str and t is not int and t is not bool:
                stored[k] = decode(v)  # a value replaced, no key added: the iteration goes on
        return stored
    if kind is list:
        if stored and _flat_tables(stored):
            return stored  # nothing to replace (a list of regions, checked in C)
        for i, v in enumerate(stored):
            t = type(v)
            if t is not str and t is not int and t is not bool:
                stored[i] = decode(v)
        return stored
    if kind is str or kind is int or kind is bool:
        return stored
    if kind is tuple and len(stored) == 1 and type(stored[0]) is str:
        return decimal.Decimal(stored[0])
    raise _NotStored(kind.__name__)


def _flat_tables(rows: list[Any]) -> bool:
    """Is every item of ``rows`` a dict of ``str`` keys and ``str``, ``int`` or ``bool`` values (a value
    :func:`decode` leaves as it is)?"""
    return (set(map(type, rows)) == _DICT and set(map(type, itertools.chain.from_iterable(rows))) <= _STR
            and set(map(type, itertools.chain.from_iterable(map(dict.values, rows)))) <= _LEAVES)


_DICT, _STR, _LEAVES = frozenset((dict,)), frozenset((str,)), frozenset((str, int, bool))


def read_entry(entry: str, header: tuple[Any, ...], limit: int) -> Any:
    """The value stored in ``entry`` after ``header`` (all of it equal, item by item), or None (a miss) --
    never an exception.  ``entry`` and its folder must be regular, owned by the current user and writable by no
    one else; at most ``limit`` bytes are read."""
    try:
        if not _private(os.stat(os.path.dirname(entry)), stat.S_ISDIR):
            return None
        fd = os.open(entry, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
        try:
            if not _private(os.fstat(fd), stat.S_ISREG):
                return None
            with os.fdopen(fd, "rb", closefd=False) as fh:
                blob = fh.read(limit)
        finally:
            os.close(fd)
        stored = marshal.loads(blob)
        if type(stored) is not tuple or len(stored) != len(header) + 1 or stored[:-1] != header:
            return None
        return stored[-1]
    except (OSError, ValueError, EOFError, TypeError, RecursionError, MemoryError):
        return None


def _read(entry: str, source: bytes) -> Any:
    """The table in ``entry`` for ``source``, or None (a miss) -- never an exception."""
    stored = read_entry(entry, _header(source), 2 * MAX_SOURCE + 65536)
    try:
        return None if stored is None else decode(stored)
    except (RecursionError, _NotStored):
        return None


def write_entry(entry: str, header: tuple[Any, ...], value: Any) -> None:
    """Store ``header`` and ``value`` (a :mod:`marshal` value) in ``entry`` if the folder can be made private;
    else nothing -- never an exception.  The entry is written to a temporary file and renamed over the old one
    (atomic: a reader sees the old entry or the new, never a torn one)."""
    try:
        blob = marshal.dumps(header + (value,))
    except (ValueError, RecursionError):
        return
    folder = os.path.dirname(entry)
    temp = f"{entry}.{os.getpid()}.{_thread.get_ident()}.tmp"  # one writer per name: no torn entry
    try:
        os.makedirs(folder, mode=0o700, exist_ok=True)
        if not _private(os.stat(folder), stat.S_ISDIR):
            return
        fd = os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0), 0o600)
        try:
            os.write(fd, blob)
        finally:
            os.close(fd)
        os.replace(temp, entry)
    except OSError:
        try:
            os.unlink(temp)
        except OSError:
            pass


def _write(entry: str, source: bytes, table: Any) -> None:
    """Store ``table`` (parsed from ``source``) in ``entry`` if the folder can be made private; else nothing."""
    try:
        value = encode(table)
    except (RecursionError, _NotStored):
        return
    write_entry(entry, _header(source), value)


def cached_table(path: str, source: bytes, parse: Callable[[], dict[str, Any]]) -> dict[str, Any]:
    """The table of the machine file ``path`` whose bytes are ``source``: from its cache entry when that was
    written for these very bytes (and this Python and nczones), else ``parse()`` -- which may raise; nothing is
    stored then -- stored for the next run.

    Parameters
    ----------
    path : str
        The machine file (names the entry).
    source : bytes
        Its complete bytes, as read now.
    parse : callable
        ``tomllib.loads`` of the text of ``source`` with ``parse_float=decimal.Decimal``.

    Returns
    -------
    dict
        Equal to what ``parse()`` returns (see the module's docstring).
    """
    folder = cache_dir() if len(source) <= MAX_SOURCE else None
    if folder is None:
        return parse()
    entry = entry_path(folder, path)
    table = _read(entry, source)
    if type(table) is dict:
        return table
    table = parse()
    _write(entry, source, table)
    return table
