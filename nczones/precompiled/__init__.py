"""Dataclasses without compiling their methods at every start-up (issue 36).

``dataclasses.dataclass`` writes the source of each class's ``__init__``, ``__repr__``, ``__eq__``,
``__hash__``, ``__setattr__`` and ``__delattr__`` and compiles it with ``exec``: about 0.4 ms per class,
some 20 ms of the 0.1 s a small ``nczones verify`` takes on the machine of specs/performance.md (the largest
single part of its imports).  The functions are the same text at every start, so :func:`dataclass` takes
them from :mod:`nczones.precompiled.functions`, a module of those texts written by
``python -m nczones.precompiled --write`` (whose bytecode Python caches like any module's): a text found
there is not compiled again, any other is compiled as ``dataclasses`` does.  The result is the class
``dataclasses.dataclass`` makes, its functions made from the same source text with the same globals and
default values; only their ``co_filename`` names the generated module instead of ``<string>``.

Only for CPython 3.11, whose ``dataclasses._create_fn`` :func:`_create_fn` repeats; on any other version
:func:`dataclass` is ``dataclasses.dataclass`` (``tests/test_precompiled.py`` checks the generated module is
current and that the classes equal the standard library's).

>>> @dataclass(frozen=True, slots=True)
... class Point:
...     x: int
...     y: int = 0
>>> Point(1), Point(1) == Point(1, 0), hash(Point(1)) == hash((1, 0))
(Point(x=1, y=0), True, True)
"""

from __future__ import annotations

import dataclasses
import os
import sys
import types
from typing import TYPE_CHECKING, Any

__all__ = ["dataclass", "ENABLED", "RECORD_ENV"]

#: Set in the environment, the texts :func:`dataclass` compiles are printed to standard error, one JSON string a
#: line (how ``--write`` collects them).
RECORD_ENV = "NCZONES_RECORD_DATACLASS_FUNCTIONS"

#: Whether the precompiled functions are used: CPython 3.11, the ``dataclasses`` whose ``_create_fn`` this
#: module repeats.
ENABLED = (sys.version_info[:2] == (3, 11) and sys.implementation.name == "cpython"
           and callable(getattr(dataclasses, "_create_fn", None)))

_TABLE: list[dict[str, Any]] = []


def _functions() -> dict[str, Any]:
    """The generated module's table: a function's text → the function whose code is that text's."""
    if not _TABLE:
        if os.environ.get(RECORD_ENV):
            _TABLE.append({})
        else:
            from .functions import FUNCTIONS

            _TABLE.append(FUNCTIONS)
    return _TABLE[0]


def _create_fn(name: str, args: list[str], body: list[str], *, globals: dict[str, Any] | None = None,  # noqa: A002
               locals: dict[str, Any] | None = None,  # noqa: A002
               return_type: Any = dataclasses.MISSING) -> Any:
    """``dataclasses._create_fn`` of CPython 3.11: the same text, its code taken from :func:`_functions` when
    the text is there, else compiled as there."""
    if locals is None:
        locals = {}
    return_annotation = ""
    if return_type is not dataclasses.MISSING:
        locals["_return_type"] = return_type
        return_annotation = "->_return_type"
    joined = ",".join(args)
    lines = "\n".join(f"  {b}" for b in body)
    txt = f" def {name}({joined}){return_annotation}:\n{lines}"
    local_vars = ", ".join(locals.keys())
    txt = f"def __create_fn__({local_vars}):\n{txt}\n return {name}"
    made = _functions().get(txt)
    if made is None:
        if os.environ.get(RECORD_ENV):
            import json

            print(json.dumps(txt), file=sys.stderr)
        ns: dict[str, Any] = {}
        # what dataclasses does (the text of the class's own fields), without this module's __future__ flags:
        # its exec compiles under those of dataclasses.py, none (annotations stay evaluated)
        exec(compile(txt, "<string>", "exec", dont_inherit=True), globals, ns)  # noqa: S102
        return ns["__create_fn__"](**locals)
    create = types.FunctionType(made.__code__, globals if globals is not None else {}, "__create_fn__")
    return create(**locals)


_ORIGINAL = getattr(dataclasses, "_create_fn", None)


if TYPE_CHECKING:
    from dataclasses import dataclass as dataclass
else:
    def dataclass(cls: type | None = None, /, **options: Any) -> Any:
        """``dataclasses.dataclass(cls, **options)``, the generated functions precompiled (see the module)."""

        def wrap(c: type) -> type:
            if not ENABLED:
                return dataclasses.dataclass(c, **options)
            dataclasses._create_fn = _create_fn
            try:
                return dataclasses.dataclass(c, **options)
            finally:
                dataclasses._create_fn = _ORIGINAL

        return wrap if cls is None else wrap(cls)
