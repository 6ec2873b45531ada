"""Fast construction of frozen, slotted dataclass instances.

A frozen dataclass's ``__init__`` stores each field through
``object.__setattr__``; the interpreter makes one :class:`~nczones.motion.Segment`
per move and one :class:`~nczones.errors.SourceSpan` per block, where that costs
more than the move's arithmetic.  :func:`builder` compiles a constructor that
stores the fields in a *draft*, a plain class with the same slots (ordinary
attribute stores, the fastest Python has), and then turns the draft into an
instance of the frozen class by ``__class__`` assignment, which Python allows
because both classes derive from ``object`` and have the same slots.  The
result is an ordinary instance of the class, equal to the one its constructor
makes, and frozen from then on.  Where that assignment is not possible (a class
with another base, another Python), the constructor stores each field through
its slot descriptor instead.

>>> from dataclasses import dataclass
>>> @dataclass(frozen=True, slots=True)
... class Point:
...     x: int
...     y: int
...     label: str
>>> make = builder(Point, ("x", "y"), label="")
>>> make(1, 2), make(1, 2) == Point(1, 2, "")
(Point(x=1, y=2, label=''), True)
"""

from __future__ import annotations

from collections.abc import Callable

from .precompiled import field_names, make_function  # no dataclasses import, no compile (start-up)

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["builder"]


def builder(cls: type, params: tuple[str, ...] | None = None, *, name: str | None = None,
            **constants: Any) -> Callable[..., Any]:
    """A function building ``cls`` instances from ``params`` (positional) and fixed ``constants``.

    Parameters
    ----------
    cls : type
        A frozen dataclass with ``slots=True``.
    params : tuple of str, optional
        The fields the function takes, in its argument order (default: every
        field not in ``constants``, in declaration order).
    name : str, optional
        The function's name (default ``make``).
    **constants
        Fields every instance gets the same value for.

    Returns
    -------
    callable
        ``make(*values)``; ``make(*values) == cls(**fields)`` for every input.
    """
    names = field_names(cls)
    if params is None:
        params = tuple(n for n in names if n not in constants)
    if sorted((*params, *constants)) != sorted(names):
        raise ValueError(f"builder({cls.__name__}): params {params!r} and constants {sorted(constants)!r} must "
                         f"name each field of {names!r} once")
    scope = {"_new": object.__new__, "_cls": cls}
    scope.update({f"_c_{k}": v for k, v in constants.items()})
    stores = [(n, n) for n in params] + [(n, f"_c_{n}") for n in constants]
    if cls.__bases__ == (object,) and tuple(getattr(cls, "__slots__", ())) == names:
        scope["_draft"] = type(f"_{cls.__name__}Draft", (object,), {"__slots__": names})
        body = [f"o.{n} = {v}" for n, v in stores]
        make = _compiled(params, ["o = _new(_draft)", *body, "o.__class__ = _cls", "return o"], scope, cls, name)
        try:
            sample = make(*([None] * len(params)))
            if type(sample) is cls and all(getattr(sample, n) is None for n in params):
                return make
        except TypeError:  # pragma: no cover - a Python that refuses the __class__ assignment
            pass
    scope.update({f"_s_{n}": getattr(cls, n).__set__ for n in names})
    body = [f"_s_{n}(o, {v})" for n, v in stores]
    return _compiled(params, ["o = _new(_cls)", *body, "return o"], scope, cls, name)


def _compiled(params: tuple[str, ...], body: list[str], scope: dict[str, Any], cls: type,
              name: str | None) -> Callable[..., Any]:
    """``def make(*params): body`` with globals ``scope`` (field names only), its code precompiled when the text
    is one of :mod:`nczones.precompiled`'s (start-up, issue 36)."""
    make: Callable[..., Any] = make_function("make", list(params), body, scope)
    make.__name__ = make.__qualname__ = name or "make"
    make.__doc__ = f"``{cls.__name__}(...)`` from {', '.join(make.__code__.co_varnames[:make.__code__.co_argcount])}."
    return make
