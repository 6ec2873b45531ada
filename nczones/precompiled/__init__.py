"""Dataclasses without ``dataclasses`` at start-up (issue 36).

``dataclasses.dataclass`` writes the source of each class's ``__init__``, ``__repr__``, ``__eq__``,
``__hash__``, ``__setattr__`` and ``__delattr__`` and compiles it with ``exec``: about 0.4 ms per class.
The functions are the same text at every start, so :func:`dataclass` takes them from
:mod:`nczones.precompiled.functions`, a module of those texts written by ``python -m nczones.precompiled
--write`` (whose bytecode Python caches like any module's; the texts no start-up of its scenarios makes are in
:mod:`nczones.precompiled.functions_later`, loaded at the first one a run makes): a text found there is not
compiled again, any other is compiled as ``dataclasses`` does.

Importing ``dataclasses`` itself costs more than the classes (it imports ``inspect``, hence ``ast``, ``dis``,
``tokenize``, ``copy``...: some 10 ms of a 0.07 s verify), so :func:`dataclass` also does the work of
``dataclasses._process_class`` of CPython 3.11 here, for the classes nczones declares (string annotations,
no ``InitVar`` or ``KW_ONLY``, bases that are not dataclasses or were made here): the same function texts,
set in the same order, the same class attributes, ``__match_args__``, ``__slots__``, ``__doc__`` and hash.
What needs ``dataclasses``' own objects is made when first asked for: ``__dataclass_fields__`` (the
:class:`dataclasses.Field` objects, so :func:`dataclasses.fields`, :func:`dataclasses.asdict`,
:func:`dataclasses.replace` and :func:`dataclasses.is_dataclass` work), ``__dataclass_params__``, a generated
``__doc__`` (``inspect.signature``), and the :class:`dataclasses.FrozenInstanceError` a frozen class raises.
Any other class (and every class on another Python) goes to ``dataclasses.dataclass``.  :func:`field` and
:func:`replace` stand for ``dataclasses.field`` and ``dataclasses.replace`` without importing it.

Only for CPython 3.11, whose ``dataclasses`` this module repeats; on any other version :func:`dataclass` is
``dataclasses.dataclass`` (``tests/precompiled/test_precompiled.py`` checks the generated module is current
and that the classes equal the standard library's).

>>> @dataclass(frozen=True, slots=True)
... class Point:
...     x: int
...     y: int = 0
>>> Point(1), Point(1) == Point(1, 0), hash(Point(1)) == hash((1, 0))
(Point(x=1, y=0), True, True)
"""

from __future__ import annotations

import _thread
import abc
import itertools
import os
import sys
import types

# not typing's: nczones/__init__ imports this module before the program sets the collector's threshold, and
# typing is 2 ms of objects to import (issue 36); a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field", "replace", "field_names", "make_function", "ENABLED", "RECORD_ENV", "RECORD_PATTERNS_ENV",
           "seed_patterns"]

#: Set in the environment, the texts :func:`dataclass` compiles are printed to standard error, one JSON string a
#: line (how ``--write`` collects them).
RECORD_ENV = "NCZONES_RECORD_DATACLASS_FUNCTIONS"

#: Set in the environment, the regular expressions compiled are printed to standard error, one JSON list
#: ``["pattern", [type, text, flags]]`` a line (how ``--write`` collects them for :mod:`.regexes`).
RECORD_PATTERNS_ENV = "NCZONES_RECORD_PATTERNS"

#: Whether the precompiled functions are used: CPython 3.11, the ``dataclasses`` this module repeats.
ENABLED = sys.version_info[:2] == (3, 11) and sys.implementation.name == "cpython"


def seed_patterns() -> int:
    """Put the regular expressions of :mod:`nczones.precompiled.regexes` in ``re``'s cache (how many).

    ``re.compile`` parses a pattern and generates its code in Python (``re._parser``, ``re._compiler``): some
    5 ms for the ~70 patterns a small verify compiles (tomllib's, argparse's, json's, fractions' and nczones'
    own).  The generated module holds what ``re._compiler.compile`` hands to ``_sre.compile`` for each of
    them, written by ``python -m nczones.precompiled --write`` on this very interpreter (its version and
    ``_sre.MAGIC`` are checked: on any other nothing is seeded), so ``re.compile`` of such a pattern finds it
    in its cache; ``tests/precompiled`` checks each equals a fresh compile (``Pattern.__eq__`` compares the
    code).  Patterns not there compile as always."""
    if not ENABLED:
        return 0
    import re

    if os.environ.get(RECORD_PATTERNS_ENV):
        _record_patterns(re)
        return 0
    import _sre  # type: ignore[import-not-found]

    from . import regexes

    if regexes.HEXVERSION != sys.hexversion or regexes.MAGIC != _sre.MAGIC:
        return 0
    cache = vars(re)["_cache"]  # the standard library's own (re._compile looks there first)
    room = re._MAXCACHE - len(cache)  # type: ignore[attr-defined]
    n = 0
    for pattern, flags, code_flags, code, groups, groupindex, indexgroup in regexes.PATTERNS[:max(room, 0)]:
        key = (type(pattern), pattern, flags)
        if key not in cache:
            cache[key] = _sre.compile(pattern, code_flags, list(code), groups, dict(groupindex), indexgroup)
            n += 1
    return n


def _record_patterns(re: Any) -> None:
    """Print each pattern compiled from now on (``--write``)."""
    import json

    compile_ = re._compiler.compile

    def recording(p: Any, flags: int = 0) -> Any:
        if isinstance(p, (str, bytes)):
            text = p if isinstance(p, str) else p.decode("latin-1")
            print(json.dumps(["pattern", [type(p).__name__, text, flags]]), file=sys.stderr)
        return compile_(p, flags)

    re._compiler.compile = recording

_TABLE: list[dict[str, Any]] = []
_LATER: list[dict[str, Any]] = []


def _functions() -> dict[str, Any]:
    """The generated module's table: a function's text → the function whose code is that text's (the texts the
    start-ups of ``python -m nczones.precompiled``'s scenarios make; the others are :func:`_later_functions`')."""
    if not _TABLE:
        if os.environ.get(RECORD_ENV):
            _TABLE.append({})
        else:
            from .functions import FUNCTIONS

            _TABLE.append(FUNCTIONS)
    return _TABLE[0]


def _later_functions() -> dict[str, Any]:
    """The table of the texts no start-up makes (:mod:`nczones.precompiled.functions_later`), loaded at the first
    text :func:`_functions` lacks: a start-up unmarshals only the functions it may use (some 60 of 355 fewer,
    about 1 million instructions, boot44)."""
    if not _LATER:
        if os.environ.get(RECORD_ENV):
            _LATER.append({})
        else:
            from .functions_later import FUNCTIONS

            _LATER.append(FUNCTIONS)
    return _LATER[0]


def _create_fn(name: str, args: list[str], body: list[str], *, globals: dict[str, Any] | None = None,  # noqa: A002
               locals: dict[str, Any] | None = None,  # noqa: A002
               return_type: Any = None, returns: bool = False) -> Any:
    """``dataclasses._create_fn`` of CPython 3.11: the same text, its code taken from :func:`_functions` when
    the text is there, else compiled as there (``returns``: the function is annotated ``-> return_type``)."""
    if locals is None:
        locals = {}
    return_annotation = ""
    if returns:
        locals["_return_type"] = return_type
        return_annotation = "->_return_type"
    joined = ",".join(args)
    lines = "  " + "\n  ".join(body) if body else ""  # each line indented by two
    txt = f" def {name}({joined}){return_annotation}:\n{lines}"
    local_vars = ", ".join(locals.keys())
    txt = f"def __create_fn__({local_vars}):\n{txt}\n return {name}"
    made = _functions().get(txt)
    if made is None:
        made = _later_functions().get(txt)
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
    fn = create(**locals)
    fn.__qualname__ = f"__create_fn__.<locals>.{name}"  # the generated module's is f<n>.<locals>.<name>
    return fn


def make_function(name: str, args: list[str], body: list[str], globals: dict[str, Any]) -> Any:  # noqa: A002
    """``def name(*args): body`` (each line of ``body`` one statement, indented by the function) with the globals
    ``globals``: compiled as :func:`dataclass` compiles its methods, its code taken from
    :mod:`nczones.precompiled.functions` when the text is there (``nczones.frozen`` builds its constructors so)."""
    return _create_fn(name, args, body, globals=globals)


def _std_create_fn(name: str, args: list[str], body: list[str], *, globals: dict[str, Any] | None = None,  # noqa: A002
                   locals: dict[str, Any] | None = None, return_type: Any = None) -> Any:  # noqa: A002
    """``dataclasses._create_fn``'s signature (its ``MISSING`` meaning "no return annotation")."""
    import dataclasses

    returns = return_type is not dataclasses.MISSING
    return _create_fn(name, args, body, globals=globals, locals=locals, return_type=return_type if returns else None,
                      returns=returns)


class _Missing:
    """No default (``dataclasses.MISSING``, which is made when ``dataclasses`` is imported)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "MISSING"


class _Factory:
    """The default of an ``__init__`` parameter whose field has a default factory."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "<factory>"


MISSING: Any = _Missing()
_HAS_DEFAULT_FACTORY = _Factory()
_FIELD, _CLASSVAR = "field", "classvar"


class _Field:
    """What ``dataclasses.field(...)`` says about a field, before (or without) ``dataclasses`` is imported."""

    __slots__ = ("default", "default_factory", "init", "repr", "hash", "compare", "metadata", "kw_only", "name",
                 "type", "kind", "source")

    def __init__(self, default: Any, default_factory: Any, init: bool, repr: bool,  # noqa: A002
                 hash: bool | None, compare: bool, metadata: Any, kw_only: Any) -> None:  # noqa: A002
        self.default, self.default_factory, self.init, self.repr = default, default_factory, init, repr
        self.hash, self.compare, self.metadata, self.kw_only = hash, compare, metadata, kw_only
        self.name: Any = None
        self.type: Any = None
        self.source: Any = None
        self.kind = _FIELD

    def real(self) -> Any:
        """The :class:`dataclasses.Field` ``dataclasses`` would have made for this field."""
        import dataclasses

        dc: Any = dataclasses

        def std(value: Any) -> Any:
            return dc.MISSING if value is MISSING else value

        f = self.source
        if f is None:
            f = dc.Field(std(self.default), std(self.default_factory), self.init, self.repr, self.hash,
                         self.compare, self.metadata, std(self.kw_only))
        f.name, f.type = self.name, self.type
        f.kw_only = std(self.kw_only)
        f._field_type = dc._FIELD if self.kind is _FIELD else dc._FIELD_CLASSVAR
        return f


def _is_std_field(value: Any) -> bool:
    """Whether ``value`` is a :class:`dataclasses.Field` (without importing ``dataclasses``)."""
    dc = sys.modules.get("dataclasses")
    return dc is not None and isinstance(value, dc.Field)


def _as_field(value: Any) -> _Field | None:
    """A class attribute as a :class:`_Field` when it is one (ours or the standard library's), else None."""
    if isinstance(value, _Field):
        return value
    if "dataclasses" in sys.modules and _is_std_field(value):
        def own(x: Any) -> Any:
            return MISSING if x is sys.modules["dataclasses"].MISSING else x

        f = _Field(own(value.default), own(value.default_factory), value.init, value.repr, value.hash,
                   value.compare, value.metadata, own(value.kw_only))
        f.source = value
        return f
    return None


class _Spec:
    """What :func:`dataclass` made of a class: its fields (ClassVars included) and parameters."""

    __slots__ = ("fields", "params", "names", "replace")

    def __init__(self, fields: dict[str, _Field], params: tuple[bool, ...]) -> None:
        self.fields, self.params = fields, params
        real = [f for f in fields.values() if f.kind is _FIELD]
        self.names = tuple([f.name for f in real])
        self.replace = tuple([(f.name, f.init) for f in real])


#: The classes :func:`dataclass` made itself → what it made of them.
_MADE: dict[type, _Spec] = {}


class _Lazy:
    """A class attribute made from ``dataclasses`` when first read, then stored in the class in its place."""

    __slots__ = ("name", "make")

    def __init__(self, name: str, make: Any) -> None:
        self.name, self.make = name, make

    def __get__(self, obj: Any, owner: type | None = None) -> Any:
        holder = next(c for c in (owner or type(obj)).__mro__ if c.__dict__.get(self.name) is self)
        value = self.make(holder)
        setattr(holder, self.name, value)
        return value


def _fields_of(cls: type) -> dict[str, Any]:
    return {name: f.real() for name, f in _MADE[cls].fields.items()}


def _params_of(cls: type) -> Any:
    import dataclasses

    dc: Any = dataclasses
    return dc._DataclassParams(*_MADE[cls].params)


def _doc_of(cls: type) -> str:
    """The ``__doc__`` ``dataclasses`` gives a class without one: its name and ``__init__``'s signature."""
    import inspect

    try:
        text_sig = str(inspect.signature(cls)).replace(" -> None", "")
    except (TypeError, ValueError):
        text_sig = ""
    return cls.__name__ + text_sig


def _frozen_error(message: str) -> Exception:
    """``dataclasses.FrozenInstanceError(message)`` (what a frozen class's ``__setattr__`` raises)."""
    import dataclasses

    return dataclasses.FrozenInstanceError(message)


def _getstate(self: Any) -> Any:
    import dataclasses

    dc: Any = dataclasses
    return dc._dataclass_getstate(self)


def _setstate(self: Any, state: Any) -> None:
    import dataclasses

    dc: Any = dataclasses
    dc._dataclass_setstate(self, state)


def _recursive_repr(user_function: Any) -> Any:
    """``dataclasses._recursive_repr``: ``...`` for a recursive call."""
    repr_running: set[tuple[int, int]] = set()

    def wrapper(self: Any) -> Any:
        key = id(self), _thread.get_ident()
        if key in repr_running:
            return "..."
        repr_running.add(key)
        try:
            result = user_function(self)
        finally:
            repr_running.discard(key)
        return result

    # functools.wraps(user_function)'s work on a function made here, whose five attributes exist and whose
    # __dict__ is empty (some 7,000 instructions a class less: start-up, boot44)
    f: Any = user_function
    wrapper.__module__, wrapper.__name__, wrapper.__qualname__ = f.__module__, f.__name__, f.__qualname__
    wrapper.__doc__, wrapper.__annotations__ = f.__doc__, f.__annotations__
    wrapper.__dict__.update(f.__dict__)
    wrapper.__wrapped__ = f  # type: ignore[attr-defined]
    return wrapper


_HEAD: list[Any] = []
#: An annotation's text → its head (``module``, ``name``) by ``dataclasses._MODULE_IDENTIFIER_RE``, None when it
#: has none: each text is matched once however many classes repeat it (start-up, issue 36).
_HEADS: dict[str, tuple[str | None, str] | None] = {}


def _head(annotation: str) -> tuple[str | None, str] | None:
    """``annotation``'s head by ``dataclasses._is_type``'s pattern: ``(module or None, name)``, or None."""
    try:
        return _HEADS[annotation]
    except KeyError:
        pass
    if not _HEAD:
        import re

        _HEAD.append(re.compile(r"^(?:\s*(\w+)\s*\.)?\s*(\w+)"))
    match = _HEAD[0].match(annotation)
    head = _HEADS[annotation] = match.groups() if match else None
    return head


def _named(annotation: str, cls: type, a_module: Any, namespace: dict[str, Any] | None = None) -> Any:
    """What the string ``annotation`` names in ``a_module`` by ``dataclasses._is_type``'s rule (its head
    ``name`` or ``module.name``, looked up in the class's module, whose namespace may be given), else None."""
    head = _head(annotation)
    if head is None:
        return None
    module_name, name = head
    if namespace is None:
        module = sys.modules.get(cls.__module__)
        namespace = module.__dict__ if module is not None else None
    if not module_name:
        return namespace.get(name) if namespace is not None else None
    if namespace is not None and namespace.get(module_name) is a_module:
        return a_module.__dict__.get(name)
    return None


def _pseudo(annotation: Any, cls: type, namespace: dict[str, Any] | None = None) -> str | None:
    """"classvar" for a ClassVar, "other" for what only ``dataclasses`` handles (not a string, InitVar,
    KW_ONLY), else None (a field): ``dataclasses._get_field``'s tests of a string annotation (``namespace``:
    the class's module's, when the caller has it).

    What :func:`_named` finds, found once for both modules: a bare head (no ``module.``) names the same object
    of the class's module whichever module is asked about (issue 36: one lookup per field at start-up)."""
    if not isinstance(annotation, str):
        return "other"
    modules = sys.modules
    typing, dc = modules.get("typing"), modules.get("dataclasses")
    if not (typing or dc):
        return None
    head = _HEADS[annotation] if annotation in _HEADS else _head(annotation)
    if head is None:
        return None
    if namespace is None:
        module = modules.get(cls.__module__)
        namespace = module.__dict__ if module is not None else None
        if namespace is None:
            return None
    module_name, name = head
    bare = None if module_name else namespace.get(name)
    if typing:
        found = bare if not module_name else (typing.__dict__.get(name) if namespace.get(module_name) is typing
                                              else None)
        if found is not None and (found is typing.ClassVar or (type(found) is typing._GenericAlias
                                                               and found.__origin__ is typing.ClassVar)):
            return "classvar"
    if dc:
        found = bare if not module_name else (dc.__dict__.get(name) if namespace.get(module_name) is dc else None)
        if found is dc.InitVar or type(found) is dc.InitVar or found is dc.KW_ONLY:
            return "other"
    return None


def _field_types() -> tuple[type, ...]:
    """What :func:`_as_field` takes for a field: ours, and the standard library's once it is imported."""
    dc = sys.modules.get("dataclasses")
    return (_Field,) if dc is None else (_Field, dc.Field)


def _own_field(cls: type, name: str, annotation: str, kind: str | None, kw_only: bool) -> _Field | None:
    """``dataclasses._get_field``, or None where it would raise (the standard library then says why)."""
    default = getattr(cls, name, MISSING)
    f = default if isinstance(default, _Field) else _as_field(default) if "dataclasses" in sys.modules else None
    if f is None:
        if isinstance(default, types.MemberDescriptorType):
            default = MISSING
        f = _Field(default, MISSING, True, True, None, True, None, MISSING)
    f.name, f.type = name, annotation
    if kind == "classvar":
        if f.default_factory is not MISSING or f.kw_only is not MISSING:
            return None
        f.kind = _CLASSVAR
        return f
    if f.kw_only is MISSING:
        f.kw_only = kw_only
    if f.default.__class__.__hash__ is None:
        return None
    return f


def _collect(cls: type, frozen: bool, kw_only: bool) -> dict[str, _Field] | None:
    """The fields of ``cls`` (its bases' first), or None when only ``dataclasses`` can make the class."""
    fields: dict[str, _Field] = {}
    any_frozen_base = has_dataclass_bases = False
    for b in cls.__mro__[-1:0:-1]:
        owner = next((c for c in b.__mro__ if "__dataclass_fields__" in c.__dict__), None)
        if owner is None:
            continue
        if owner not in _MADE:
            return None
        has_dataclass_bases = True
        fields.update(_MADE[owner].fields)
        any_frozen_base = any_frozen_base or _MADE[owner].params[5]
    annotations = cls.__dict__.get("__annotations__", {})
    own = []
    module = sys.modules.get(cls.__module__)
    namespace = module.__dict__ if module is not None else None
    for name, annotation in annotations.items():
        kind = _pseudo(annotation, cls, namespace)
        f = None if kind == "other" else _own_field(cls, name, annotation, kind, kw_only)
        if f is None:
            return None
        own.append(f)
    kinds = _field_types()
    for k, v in cls.__dict__.items():  # a field() without an annotation: dataclasses says why
        if isinstance(v, kinds) and k not in annotations:
            return None
    if has_dataclass_bases and any_frozen_base != frozen:
        return None
    for f in own:
        fields[f.name] = f
    return fields


def _field_init(f: _Field, frozen: bool, locals: dict[str, Any], self_name: str,  # noqa: A002
                slots: bool) -> str | None:
    """``dataclasses._field_init``: the line of ``__init__`` that sets field ``f`` (None: no line)."""
    default_name = f"_dflt_{f.name}"
    if f.default_factory is not MISSING:
        locals[default_name] = f.default_factory
        value = (f"{default_name}() if {f.name} is _HAS_DEFAULT_FACTORY else {f.name}" if f.init
                 else f"{default_name}()")
    elif f.init:
        if f.default is not MISSING:
            locals[default_name] = f.default
        value = f.name
    elif slots and f.default is not MISSING:
        locals[default_name] = f.default
        value = default_name
    else:
        return None
    if frozen:
        return f"__dataclass_builtins_object__.__setattr__({self_name},{f.name!r},{value})"
    return f"{self_name}.{f.name}={value}"


def _init_param(f: _Field) -> str:
    if f.default is MISSING and f.default_factory is MISSING:
        default = ""
    elif f.default is not MISSING:
        default = f"=_dflt_{f.name}"
    else:
        default = "=_HAS_DEFAULT_FACTORY"
    return f"{f.name}:_type_{f.name}{default}"


def _init_fn(fields: list[_Field], std: list[_Field], kw: list[_Field], frozen: bool, has_post_init: bool,
             self_name: str, globals: dict[str, Any], slots: bool) -> Any:  # noqa: A002
    """``dataclasses._init_fn`` (the order of defaults checked beforehand by :func:`_checked`)."""
    locals: dict[str, Any] = {f"_type_{f.name}": f.type for f in fields}  # noqa: A001
    locals.update({"MISSING": MISSING, "_HAS_DEFAULT_FACTORY": _HAS_DEFAULT_FACTORY,
                   "__dataclass_builtins_object__": object})
    body_lines = [line for f in fields if (line := _field_init(f, frozen, locals, self_name, slots))]
    if has_post_init:
        body_lines.append(f"{self_name}.__post_init__()")
    if not body_lines:
        body_lines = ["pass"]
    params = [_init_param(f) for f in std]
    if kw:
        params += ["*", *(_init_param(f) for f in kw)]
    return _create_fn("__init__", [self_name, *params], body_lines, locals=locals, globals=globals,
                      return_type=None, returns=True)


def _tuple_str(obj_name: str, fields: list[_Field]) -> str:
    if not fields:
        return "()"
    return f'({",".join([f"{obj_name}.{f.name}" for f in fields])},)'


def _cmp_fn(name: str, op: str, fields: list[_Field], globals: dict[str, Any]) -> Any:  # noqa: A002
    return _create_fn(name, ["self", "other"], ["if other.__class__ is self.__class__:",
                                                 f" return {_tuple_str('self', fields)}{op}{_tuple_str('other', fields)}",
                                                 "return NotImplemented"], globals=globals)


def _set_new_attribute(cls: type, name: str, value: Any, into: dict[str, Any] | None = None) -> None:
    """``dataclasses._set_new_attribute``; ``into``: the namespace of the class :func:`_add_slots` makes of
    ``cls`` (then set there: ``cls`` itself is left as it was)."""
    own = cls.__dict__ if into is None else into
    if name in own:
        return
    if isinstance(value, types.FunctionType):
        value.__qualname__ = f"{cls.__qualname__}.{value.__name__}"
    if into is None:
        setattr(cls, name, value)
    else:
        into[name] = value


#: ``dataclasses._hash_action`` by (unsafe_hash, eq, frozen, explicit __hash__): "add", "none" or None (nothing);
#: the combinations where it raises are left to ``dataclasses`` (:func:`_checked`).
_HASH_ACTION = {(False, True, False, False): "none", (False, True, True, False): "add",
                (True, False, False, False): "add", (True, False, True, False): "add",
                (True, True, False, False): "add", (True, True, True, False): "add"}


def _checked(cls: type, options: dict[str, Any], fields: dict[str, _Field]) -> bool:
    """Whether the class makes none of the errors ``dataclasses`` reports (those classes go there, unchanged)."""
    o = options
    if (o["order"] and not o["eq"]) or (o["weakref_slot"] and not o["slots"]):
        return False
    if o["slots"] and "__slots__" in cls.__dict__:
        return False
    own = cls.__dict__
    if o["order"] and ("__lt__" in own or "__le__" in own or "__gt__" in own or "__ge__" in own):
        return False
    if o["frozen"] and ("__setattr__" in own or "__delattr__" in own):
        return False
    class_hash = own.get("__hash__", MISSING)
    explicit = not (class_hash is MISSING or (class_hash is None and "__eq__" in own))
    if o["unsafe_hash"] and explicit:
        return False
    seen_default = False
    for f in fields.values():
        if f.kind is _FIELD and f.init and not f.kw_only:
            if not (f.default is MISSING and f.default_factory is MISSING):
                seen_default = True
            elif seen_default:
                return False
    return True


def _methods(cls: type, options: dict[str, Any], fields: dict[str, _Field], globals: dict[str, Any],  # noqa: A002
             into: dict[str, Any] | None = None) -> None:
    """Set the methods ``dataclasses._process_class`` sets, in its order (``into``: see
    :func:`_set_new_attribute`)."""
    o = options
    field_list = [f for f in fields.values() if f.kind is _FIELD]
    if o["init"]:
        std = [f for f in field_list if f.init and not f.kw_only]
        kw = [f for f in field_list if f.init and f.kw_only]
        _set_new_attribute(cls, "__init__", _init_fn(
            field_list, std, kw, o["frozen"], hasattr(cls, "__post_init__"),
            "__dataclass_self__" if "self" in fields else "self", globals, o["slots"]), into)
    if o["repr"]:
        shown = ", ".join([f"{f.name}={{self.{f.name}!r}}" for f in field_list if f.repr])
        fn = _create_fn("__repr__", ["self"], ['return self.__class__.__qualname__ + f"(' + shown + ')"'],
                        globals=globals)
        _set_new_attribute(cls, "__repr__", _recursive_repr(fn), into)
    compared = [f for f in field_list if f.compare]
    if o["eq"]:
        _set_new_attribute(cls, "__eq__", _cmp_fn("__eq__", "==", compared, globals), into)
    if o["order"]:
        for name, op in (("__lt__", "<"), ("__le__", "<="), ("__gt__", ">"), ("__ge__", ">=")):
            _set_new_attribute(cls, name, _cmp_fn(name, op, compared, globals), into)
    if o["frozen"]:
        names = "(" + ",".join([repr(f.name) for f in field_list]) + ",)" if field_list else "()"
        locals = {"cls": cls, "FrozenInstanceError": _frozen_error}  # noqa: A001
        for name, args, verb, tail in (("__setattr__", ["self", "name", "value"], "assign to", "name, value"),
                                       ("__delattr__", ["self", "name"], "delete", "name")):
            _set_new_attribute(cls, name, _create_fn(name, args, [
                f"if type(self) is cls or name in {names}:",
                f' raise FrozenInstanceError(f"cannot {verb} field {{name!r}}")',
                f"super(cls, self).{name}({tail})"], locals=dict(locals), globals=globals), into)


def _hash(cls: type, options: dict[str, Any], fields: dict[str, _Field], globals: dict[str, Any],  # noqa: A002
          into: dict[str, Any] | None = None) -> None:
    """``dataclasses``' hash action (``into``: see :func:`_set_new_attribute`)."""
    own = cls.__dict__ if into is None else into
    class_hash = own.get("__hash__", MISSING)
    explicit = not (class_hash is MISSING or (class_hash is None and "__eq__" in own))
    action = _HASH_ACTION.get((bool(options["unsafe_hash"]), bool(options["eq"]), bool(options["frozen"]), explicit))
    if action == "none":
        _set(cls, "__hash__", None, into)
    elif action == "add":
        hashed = [f for f in fields.values() if f.kind is _FIELD and (f.compare if f.hash is None else f.hash)]
        fn = _create_fn("__hash__", ["self"], [f"return hash({_tuple_str('self', hashed)})"], globals=globals)
        fn.__qualname__ = f"{cls.__qualname__}.{fn.__name__}"
        _set(cls, "__hash__", fn, into)


def _set(cls: type, name: str, value: Any, into: dict[str, Any] | None) -> None:
    """``setattr(cls, name, value)``, or into the namespace ``into`` (see :func:`_set_new_attribute`)."""
    if into is None:
        setattr(cls, name, value)
    else:
        into[name] = value


def _get_slots(cls: type) -> Any:
    slots = cls.__dict__.get("__slots__")
    if slots is None:
        return ()
    if isinstance(slots, str):
        return (slots,)
    if not hasattr(slots, "__next__"):
        return slots
    raise TypeError(f"Slots of '{cls.__name__}' cannot be determined")


def _add_slots(cls: type, is_frozen: bool, weakref_slot: bool, field_names: tuple[str, ...],
               cls_dict: dict[str, Any]) -> type:
    """``dataclasses._add_slots``: the class made again with ``__slots__``, from ``cls_dict``: ``cls``'s
    namespace as ``dataclasses`` leaves it (the methods set in it rather than on ``cls``: setting a dunder on a
    class updates its type slots, some 3,000 instructions each, for a class about to be discarded)."""
    inherited_slots = set(itertools.chain.from_iterable(map(_get_slots, cls.__mro__[1:-1])))
    cls_dict["__slots__"] = tuple(itertools.filterfalse(
        inherited_slots.__contains__, itertools.chain(field_names, ("__weakref__",) if weakref_slot else ())))
    for field_name in field_names:
        cls_dict.pop(field_name, None)
    cls_dict.pop("__dict__", None)
    cls_dict.pop("__weakref__", None)
    qualname = getattr(cls, "__qualname__", None)
    cls = type(cls)(cls.__name__, cls.__bases__, cls_dict)
    if qualname is not None:
        cls.__qualname__ = qualname
    if is_frozen:
        made: Any = cls
        if "__getstate__" not in cls_dict:
            made.__getstate__ = _getstate
        if "__setstate__" not in cls_dict:
            made.__setstate__ = _setstate
    return cls


def _process_class(cls: type, options: dict[str, Any]) -> type | None:
    """``dataclasses._process_class`` of CPython 3.11 for the classes it can make (None: the others)."""
    fields = _collect(cls, options["frozen"], options["kw_only"])
    if fields is None or not _checked(cls, options, fields):
        return None
    module = sys.modules.get(cls.__module__)
    globals = module.__dict__ if module is not None else {}  # noqa: A001
    params = (options["init"], options["repr"], options["eq"], options["order"], options["unsafe_hash"],
              options["frozen"])
    cls.__dataclass_params__ = _Lazy("__dataclass_params__", _params_of)  # type: ignore[attr-defined]
    annotations, kinds = cls.__dict__.get("__annotations__", {}), _field_types()
    for name, f in fields.items():
        if name in annotations and isinstance(getattr(cls, name, None), kinds):  # own fields only, as dataclasses
            if f.default is MISSING:
                delattr(cls, name)
            else:
                setattr(cls, name, f.default)
    # a slotted class is made again from its namespace (_add_slots): what follows is set there, not on cls
    into = dict(cls.__dict__) if options["slots"] else None
    _set(cls, "__dataclass_fields__", _Lazy("__dataclass_fields__", _fields_of), into)
    spec = _Spec(fields, params)
    _methods(cls, options, fields, globals, into)
    _hash(cls, options, fields, globals, into)
    if not cls.__doc__:
        _set(cls, "__doc__", _Lazy("__doc__", _doc_of), into)
    if options["match_args"]:
        _set_new_attribute(cls, "__match_args__",
                           tuple([f.name for f in fields.values() if f.kind is _FIELD and f.init and not f.kw_only]),
                           into)
    if into is not None:
        cls = _add_slots(cls, options["frozen"], options["weakref_slot"], spec.names, into)
    abc.update_abstractmethods(cls)
    _MADE[cls] = spec
    return cls


_DEFAULTS = {"init": True, "repr": True, "eq": True, "order": False, "unsafe_hash": False, "frozen": False,
             "match_args": True, "kw_only": False, "slots": False, "weakref_slot": False}


def _standard(cls: type, options: dict[str, Any]) -> type:
    """``dataclasses.dataclass(cls, **options)``, our :func:`field` stand-ins made real first."""
    import dataclasses

    dc: Any = dataclasses
    for name, value in list(cls.__dict__.items()):
        if isinstance(value, _Field):
            given: dict[str, Any] = {k: (dc.MISSING if getattr(value, k) is MISSING else getattr(value, k))
                                     for k in ("default", "default_factory", "init", "repr", "hash", "compare",
                                               "metadata", "kw_only")}
            setattr(cls, name, value.source or dc.field(**given))
    if not ENABLED:
        return dc.dataclass(cls, **options)  # type: ignore[no-any-return]
    original = dc._create_fn
    dc._create_fn = _std_create_fn
    try:
        return dc.dataclass(cls, **options)  # type: ignore[no-any-return]
    finally:
        dc._create_fn = original


if TYPE_CHECKING:
    from dataclasses import dataclass as dataclass
    from dataclasses import field as field
    from dataclasses import replace as replace
else:
    def dataclass(cls: type | None = None, /, **options: Any) -> Any:
        """``dataclasses.dataclass(cls, **options)``, made here when it can be (see the module)."""
        unknown = set(options) - set(_DEFAULTS)
        if unknown:
            raise TypeError(f"dataclass() got an unexpected keyword argument {sorted(unknown)[0]!r}")

        def wrap(c: type) -> type:
            given = {**_DEFAULTS, **options}
            made = _process_class(c, given) if ENABLED else None
            return made if made is not None else _standard(c, options)

        return wrap if cls is None else wrap(cls)

    def field(*, default: Any = MISSING, default_factory: Any = MISSING, init: bool = True, repr: bool = True,  # noqa: A002
              hash: bool | None = None, compare: bool = True, metadata: Any = None,  # noqa: A002
              kw_only: Any = MISSING) -> Any:
        """``dataclasses.field(...)`` (made a :class:`dataclasses.Field` when ``dataclasses`` needs it)."""
        if default is not MISSING and default_factory is not MISSING:
            raise ValueError("cannot specify both default and default_factory")
        return _Field(default, default_factory, init, repr, hash, compare, metadata, kw_only)

    def replace(obj: Any, /, **changes: Any) -> Any:
        """``dataclasses.replace(obj, **changes)``."""
        spec = _MADE.get(type(obj))
        if spec is None:
            import dataclasses

            return dataclasses.replace(obj, **changes)
        for name, init in spec.replace:
            if not init:
                if name in changes:
                    raise ValueError(f"field {name} is declared with init=False, it cannot be specified with "
                                     "replace()")
                continue
            if name not in changes:
                changes[name] = getattr(obj, name)
        return obj.__class__(**changes)


def field_names(cls: type) -> tuple[str, ...]:
    """The names of the fields of dataclass ``cls`` (``dataclasses.fields(cls)``'s), in order."""
    spec = _MADE.get(cls)
    if spec is not None:
        return spec.names
    import dataclasses

    return tuple(f.name for f in dataclasses.fields(cls))
