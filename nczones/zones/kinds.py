"""Per-kind tables: where each consumer of the zones keeps its code for each zone kind (issue 34).

A consumer (the prover's exact tier, the vectorized screen, the SMT encoding, the nose growth, the
reference controller, the drawings, the export, ...) does not ask ``isinstance(zone, BoxZone)``: it makes
one :class:`KindTable` next to its code and registers one entry per zone kind in it, keyed by the class::

    LINE_VIOLATION: KindTable[Callable[..., list[Interval]]] = KindTable("prover.exact.line_violation")

    @LINE_VIOLATION.register(BoxZone)
    def _box_line_violation(zone: BoxZone, ...) -> list[Interval]: ...

    LINE_VIOLATION(zone, ...)          # calls the entry of type(zone)

The lookup is by the exact class (no subclass silently takes its parent's entry).  A table either has
no fallback (every kind must register: the kind is not modelled there without it) or declares one sound
fallback that a kind without its own entry gets (e.g. "the screen proves nothing for this kind, the
exact tier decides").  :func:`coverage` crosses :data:`ZONE_KINDS` with every table made so far:
tests/zones/test_kind_registries.py fails while a kind lacks an entry of a table without fallback, and
lists the tables where a kind rides the fallback (the test keeps that list explicit).
"""

from __future__ import annotations

from collections.abc import Callable

from ..errors import InternalError
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)
from .model import ZONE_KINDS

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, Generic, TypeVar

    V = TypeVar("V")
    R = TypeVar("R")
else:
    V = R = None

    class Generic:
        """``typing.Generic`` for the runtime: ``KindTable[X]`` is ``KindTable`` (generic to type checkers only)."""

        __slots__ = ()

        def __class_getitem__(cls, item):
            return cls


__all__ = ["ZONE_KINDS", "KindTable", "TABLES", "Coverage", "coverage"]

_NO_FALLBACK: Any = object()

#: Every table made so far, in the order made (the consumers' modules make theirs on import).
TABLES: list[KindTable[Any]] = []


class KindTable(Generic[V]):
    """One consumer's entries per zone kind, keyed by the zone class.

    >>> from fractions import Fraction as F
    >>> from nczones.zones import BoxZone, SteppedZone
    >>> t: KindTable[str] = KindTable("doc.example", register_globally=False)
    >>> t.set(BoxZone, "a box")
    >>> t.of(BoxZone("b", (("X", F(0), F(1)),)))
    'a box'
    >>> t.missing((BoxZone, SteppedZone))
    (<class 'nczones.zones.model.SteppedZone'>,)
    """

    def __init__(self, name: str, *, fallback: Any = _NO_FALLBACK, register_globally: bool = True):
        self.name = name
        self._entries: dict[type, V] = {}
        self._fallback = fallback
        if register_globally:
            TABLES.append(self)

    @property
    def has_fallback(self) -> bool:
        return self._fallback is not _NO_FALLBACK

    @property
    def kinds(self) -> tuple[type, ...]:
        """The kinds with their own entry."""
        return tuple(self._entries)

    def set(self, kind: type, value: V) -> None:
        """Register ``value`` for ``kind`` (twice is a bug)."""
        if kind in self._entries:
            raise InternalError(f"{self.name}: zone kind {kind.__name__} registered twice")
        self._entries[kind] = value

    def register(self, *kinds: type) -> Callable[[V], V]:
        """Decorator: register the function for each of ``kinds``."""
        def add(value: V) -> V:
            for kind in kinds:
                self.set(kind, value)
            return value
        return add

    def of(self, zone: object) -> V:
        """The entry for ``type(zone)`` (or the fallback)."""
        got = self._entries.get(type(zone), _NO_FALLBACK)
        if got is _NO_FALLBACK:
            if self._fallback is _NO_FALLBACK:
                raise InternalError(f"{self.name}: no entry for zone kind {type(zone).__name__}")
            return self._fallback  # type: ignore[no-any-return]
        return got  # type: ignore[no-any-return]

    def __call__(self: KindTable[Callable[..., R]], zone: Any, *args: Any, **kwargs: Any) -> R:
        """Call the entry of ``type(zone)`` with the zone and the rest of the arguments."""
        return self.of(zone)(zone, *args, **kwargs)

    def missing(self, kinds: tuple[type, ...] = ZONE_KINDS) -> tuple[type, ...]:
        """The kinds of ``kinds`` without their own entry."""
        return tuple(k for k in kinds if k not in self._entries)

    def __repr__(self) -> str:
        return f"KindTable({self.name!r}, {len(self._entries)} kinds{', fallback' if self.has_fallback else ''})"


@dataclass(frozen=True)
class Coverage:
    """Which (table, kind) pairs have no entry: ``missing`` where the table has no fallback (the kind is
    not modelled there), ``on_fallback`` where the kind gets the table's declared fallback."""

    missing: tuple[tuple[str, str], ...]
    on_fallback: tuple[tuple[str, str], ...]


def coverage(kinds: tuple[type, ...] = ZONE_KINDS, tables: list[KindTable[Any]] | None = None) -> Coverage:
    """Cross ``kinds`` with ``tables`` (default: every table made so far)."""
    missing: list[tuple[str, str]] = []
    fallback: list[tuple[str, str]] = []
    for table in TABLES if tables is None else tables:
        for kind in table.missing(kinds):
            (fallback if table.has_fallback else missing).append((table.name, kind.__name__))
    return Coverage(tuple(missing), tuple(fallback))
