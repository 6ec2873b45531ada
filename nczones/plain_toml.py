"""The machine file's TOML, read without :mod:`tomllib` when it keeps to a plain subset (issue 36, start-up).

Importing ``tomllib`` costs about 7 ms of every start (its regular expressions are compiled and
:mod:`datetime` loaded), more than reading a machine file.  :func:`loads` reads the subset machine files are
written in and returns exactly what ``tomllib.loads(text, parse_float=decimal.Decimal)`` returns; for any
text outside the subset, valid or not, it returns None and the caller asks ``tomllib`` (which also words
every error).  The subset, one item a line:

* blank lines and ``#`` comments (also after a value);
* headers ``[a]``, ``[a.b]`` and ``[[a]]`` of bare keys (``A-Za-z0-9_-``), each table defined once; an
  array of tables only as ``[[a]]`` with a top-level bare key, and no header below one;
* ``key = value`` with a bare key, once per table; values: basic strings without ``\\`` (escapes), integers
  and decimals without ``_``, exponent or leading zero, ``true``/``false``, one-line arrays of them (nested,
  a trailing comma allowed) and one-line inline tables of ``key = value`` pairs.

Anything else (dotted or quoted keys, literal or multi-line strings, dates, arrays over several lines, ...)
is left to ``tomllib``.  ``tests/test_plain_toml.py`` compares the two on the shipped machine files and on
generated texts, in and out of the subset.

>>> loads('[machine]\\naxes = ["X", "Y"]  # two\\npulse = 0.001\\n[[zones]]\\nmin = { X = "0", Y = -1 }\\n')
{'machine': {'axes': ['X', 'Y'], 'pulse': Decimal('0.001')}, 'zones': [{'min': {'X': '0', 'Y': -1}}]}
>>> loads("a = 1979-05-27") is None  # a date: tomllib's
True
"""

from __future__ import annotations

import re
from decimal import Decimal
from typing import Any

__all__ = ["loads"]

_KEY = r"[A-Za-z0-9_-]+"
_HEADER = re.compile(rf"\[(\[?)({_KEY}(?:\.{_KEY})*)\](\]?)[ \t]*(?:#[^\n]*)?\Z")
_KEY_EQ = re.compile(rf"({_KEY})[ \t]*=[ \t]*")
_SCALAR = re.compile(r'"([^"\\\x00-\x08\x0a-\x1f\x7f]*)"|([+-]?(?:0|[1-9][0-9]*))(\.[0-9]+)?(?![0-9A-Za-z_.:+-])'
                     r"|(true|false)(?![0-9A-Za-z_-])")
_SPACE = re.compile(r"[ \t]*")
_END = re.compile(r"[ \t]*(?:#[^\x00-\x08\x0a-\x1f\x7f]*)?\Z")


class _Outside(Exception):
    """The text leaves the subset: tomllib reads it."""


def loads(text: str) -> dict[str, Any] | None:
    """``tomllib.loads(text, parse_float=decimal.Decimal)`` for a text in the subset (see the module), else
    None."""
    root: dict[str, Any] = {}
    table = root
    defined: set[tuple[str, ...]] = set()  # tables a header (or a key's value) made; a second header is an error
    arrays: set[str] = set()
    try:
        for line in text.split("\n"):
            if line.endswith("\r"):
                raise _Outside
            stripped = line.strip(" \t")
            if not stripped or stripped.startswith("#"):
                if "\x7f" in line or any(c < " " and c != "\t" for c in line):
                    raise _Outside
                continue
            if stripped.startswith("["):
                table = _header(stripped, root, defined, arrays)
            else:
                _pair(stripped, table)
    except _Outside:
        return None
    plain: dict[str, Any] = _plain(root)
    return plain


def _plain(value: Any) -> Any:
    """``value`` with every inline table a plain ``dict``, as tomllib gives it."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value


def _header(line: str, root: dict[str, Any], defined: set[tuple[str, ...]], arrays: set[str]) -> dict[str, Any]:
    m = _HEADER.match(line)
    if m is None or bool(m.group(1)) != bool(m.group(3)):
        raise _Outside
    path = tuple(m.group(2).split("."))
    if any(p in arrays for p in path[:1]) and not (m.group(1) and len(path) == 1):
        raise _Outside  # a table below an array of tables: tomllib's
    if m.group(1):  # [[name]]
        if len(path) != 1 or (path[0] in root and path[0] not in arrays):
            raise _Outside
        arrays.add(path[0])
        entry: dict[str, Any] = {}
        root.setdefault(path[0], []).append(entry)
        return entry
    if path in defined:
        raise _Outside
    table = root
    for key in path:
        value = table.setdefault(key, {})
        if type(value) is not dict:  # a value (an inline table is an _Inline until the end): tomllib's
            raise _Outside
        table = value
    defined.add(path)
    return table


def _pair(line: str, table: dict[str, Any]) -> None:
    m = _KEY_EQ.match(line)
    if m is None:
        raise _Outside
    key = m.group(1)
    if key in table:
        raise _Outside
    value, end = _value(line, m.end(), 0)
    if not _END.match(line, end):
        raise _Outside
    table[key] = value


class _Inline(dict):
    """An inline table while it is read (a header may not reach into one)."""


def _value(line: str, pos: int, depth: int) -> tuple[Any, int]:
    if depth > 8:
        raise _Outside
    c = line[pos:pos + 1]
    if c == "[":
        return _array(line, pos + 1, depth)
    if c == "{":
        return _inline(line, pos + 1, depth)
    m = _SCALAR.match(line, pos)
    if m is None:
        raise _Outside
    if m.group(1) is not None:
        return m.group(1), m.end()
    if m.group(2) is not None:
        if m.group(3) is not None:
            return Decimal(m.group(2) + m.group(3)), m.end()
        return int(m.group(2)), m.end()
    return m.group(4) == "true", m.end()


def _array(line: str, pos: int, depth: int) -> tuple[list[Any], int]:
    out: list[Any] = []
    pos = _SPACE.match(line, pos).end()  # type: ignore[union-attr]
    while True:
        if line[pos:pos + 1] == "]":
            return out, pos + 1
        value, pos = _value(line, pos, depth + 1)
        out.append(value)
        pos = _SPACE.match(line, pos).end()  # type: ignore[union-attr]
        c = line[pos:pos + 1]
        if c == "]":
            return out, pos + 1
        if c != ",":
            raise _Outside
        pos = _SPACE.match(line, pos + 1).end()  # type: ignore[union-attr]


def _inline(line: str, pos: int, depth: int) -> tuple[dict[str, Any], int]:
    out: dict[str, Any] = _Inline()
    pos = _SPACE.match(line, pos).end()  # type: ignore[union-attr]
    if line[pos:pos + 1] == "}":
        return out, pos + 1
    while True:
        m = _KEY_EQ.match(line, pos)
        if m is None or m.group(1) in out:
            raise _Outside
        value, pos = _value(line, m.end(), depth + 1)
        out[m.group(1)] = value
        pos = _SPACE.match(line, pos).end()  # type: ignore[union-attr]
        c = line[pos:pos + 1]
        if c == "}":
            return out, pos + 1
        if c != ",":
            raise _Outside
        pos = _SPACE.match(line, pos + 1).end()  # type: ignore[union-attr]
