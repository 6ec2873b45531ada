"""Reading the ``[[tools]]`` and ``[[fixtures]]`` entries: what a mill's (:mod:`nczones.solids`) and a lathe's
(:mod:`nczones.lathe_solids`) sections share.

Both read an array of tables in the same way — each entry a table (``ZN161``), its keys among the allowed
ones (``ZN160``), a tool's ``number`` a whole number 0..9999 given once (``ZN162``), a fixture's ``kind`` one
of the form's kinds and its ``name`` a non-empty string — and differ in what a tool's ``parts`` and a
fixture's shape are, which the caller reads (``read_parts``, ``read_fixture``).  The messages and codes are
those each form had before they shared this code.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from fractions import Fraction
from types import MappingProxyType
from typing import Any, TypeVar

from .exact import format_decimal
from .machine import as_written, read_number

__all__ = ["TOOL_KEYS", "read_tool_entries", "read_fixture_entries", "fixture_number", "empty_heights"]

#: The keys of a ``[[tools]]`` entry (a mill's and a lathe's).
TOOL_KEYS = ("number", "name", "parts")

P = TypeVar("P")
X = TypeVar("X")


def read_tool_entries(rd: Any, raw: list, read_parts: Callable[[Any, int, int | None], P | None]
                      ) -> Mapping[int, P]:
    """``[[tools]]``: per entry its ``number`` and ``read_parts(parts, number, header)`` (None: not read, its
    problems reported), by tool number."""
    out: dict[int, P] = {}
    for k, t in enumerate(raw):
        header = rd.loc.section("tools", k)
        if not isinstance(t, Mapping):
            rd.report("ZN161", f"[[tools]] {k + 1}: expected a table, got {as_written(t)}", rd.loc.header(header))
            continue
        for key in t:
            if key not in TOOL_KEYS:
                rd.report("ZN160", f"[[tools]] {k + 1}: unknown key {as_written(key)}; allowed keys: "
                          f"{', '.join(TOOL_KEYS)}", rd.loc.key(key, header))
        num = t.get("number")
        if isinstance(num, bool) or not isinstance(num, int) or not 0 <= num <= 9999:
            rd.report("ZN162", f"[[tools]] {k + 1}: number must be a whole tool number 0..9999, got "
                      f"{as_written(num)}", rd.loc.key("number", header) or rd.loc.header(header))
            continue
        if num in out:
            rd.report("ZN162", f"[[tools]] {k + 1}: tool {num} is described twice", rd.loc.key("number", header))
            continue
        parts = read_parts(t.get("parts"), num, header)
        if parts is not None:
            out[num] = parts
    return MappingProxyType(out)


def read_fixture_entries(rd: Any, raw: list, kinds: Mapping[str, tuple[str, ...]], kind_error: tuple[str, str],
                         form: str, read_fixture: Callable[[Mapping, str, str, int | None], X | None]) -> list[X]:
    """``[[fixtures]]``: per entry its ``kind`` (one of ``kinds``, which give each kind's allowed keys; else
    ``kind_error``: the code and what the message adds), its ``name``, its keys, and
    ``read_fixture(entry, kind, name, header)`` (None: not read, its problems reported).  ``form`` qualifies
    the kind in the message of an unknown key (``"lathe "``: "for a lathe chuck")."""
    out: list[X] = []
    for k, t in enumerate(raw):
        header = rd.loc.section("fixtures", k)
        if not isinstance(t, Mapping):
            rd.report("ZN161", f"[[fixtures]] {k + 1}: expected a table, got {as_written(t)}", rd.loc.header(header))
            continue
        kind = t.get("kind")
        if not isinstance(kind, str) or kind not in kinds:
            code, why = kind_error
            allowed = ", ".join(f'"{n}"' for n in kinds)
            rd.report(code, f"[[fixtures]] {k + 1}: kind {as_written(kind)} is not one of {allowed}{why}",
                      rd.loc.key("kind", header) or rd.loc.header(header))
            continue
        name = t.get("name")
        if not isinstance(name, str) or not name:
            rd.report("ZN161", f"[[fixtures]] {k + 1}: name must be a non-empty string, got {as_written(name)}",
                      rd.loc.key("name", header) or rd.loc.header(header))
            continue
        for key in t:
            if key not in kinds[kind]:
                rd.report("ZN160", f"[[fixtures]] {name!r}: unknown key {as_written(key)} for a {form}{kind}; "
                          f"allowed keys: {', '.join(kinds[kind])}", rd.loc.key(key, header))
        fx = read_fixture(t, kind, name, header)
        if fx is not None:
            out.append(fx)
    return out


def fixture_number(rd: Any, t: Mapping, key: str, name: str, header: int | None, *, positive: bool = False,
                   nonnegative: bool = False) -> Fraction | None:
    """A fixture's number ``key`` (``radius``, ``min_z`` ...), None when left out or not a number (reported);
    ``positive``, ``nonnegative`` as :func:`nczones.machine.read_number` checks them."""
    if key not in t:
        return None
    return read_number(rd, t[key], f"[[fixtures]] {name!r} {key}", rd.loc.key(key, header), positive=positive,
                       nonnegative=nonnegative)


def empty_heights(rd: Any, code: str, name: str, header: int | None, z0: Fraction | None, z1: Fraction | None,
                  what: str) -> bool:
    """Is ``min_z`` not below ``max_z`` (reported with ``code``: an empty ``what``)?"""
    if z0 is not None and z1 is not None and z0 >= z1:
        rd.report(code, f"[[fixtures]] {name!r}: min_z {format_decimal(z0)} is not below max_z "
                  f"{format_decimal(z1)} (an empty {what})", rd.loc.key("max_z", header))
        return True
    return False
