"""How the interpreter and cutter compensation build segments and track what they depend on.

A segment's dependencies are linear forms over the named parameters (work
offsets, tool lengths, the start position): ``{name: coefficient}``
dictionaries, added with :func:`dadd`.
"""

from __future__ import annotations

from ..frozen import builder
from ..motion import Segment
from ..precompiled import field_names, replace  # dataclasses' without importing it (start-up)

__all__ = ["make_segment", "dadd", "with_tool_deps"]

#: ``Segment(...)`` with all fields but ``deps_tool`` positional, in order (``frame`` last), built 3x faster
#: (see nczones.frozen).
make_segment = builder(Segment, tuple(f for f in field_names(Segment) if f != "deps_tool"), deps_tool=())


def dadd(a: dict, b: dict, sign: int = 1) -> dict:
    """``a + sign * b`` for dependency forms; zero coefficients are dropped.

    >>> dadd({"G54.X": 1}, {"G54.X": 1, "H1": 1}, -1)
    {'H1': -1}
    """
    out = dict(a)
    for k, v in b.items():
        n = out.get(k, 0) + sign * v
        if n:
            out[k] = n
        else:
            out.pop(k, None)
    return out


def with_tool_deps(seg: Segment, names: tuple[str, ...]) -> Segment:
    """``seg`` depending on the tool lengths ``names`` as well."""
    return replace(seg, deps_tool=names)
