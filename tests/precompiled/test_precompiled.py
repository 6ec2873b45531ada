"""nczones.precompiled: dataclasses whose generated methods come precompiled (issue 36, start-up).

The claim is that a class made by ``nczones.precompiled.dataclass`` is the class ``dataclasses.dataclass``
makes.  Checked three ways: every precompiled function is the bytecode Python compiles from its text (the
text ``dataclasses`` would have compiled); classes made through the table behave as the standard library's
(construction, defaults, repr, equality, order, hash, frozenness, slots); the generated module is current,
and every class of the modules that use the decorator took its functions from it.
"""

from __future__ import annotations

import dataclasses
import importlib
import subprocess
import sys
import types
from pathlib import Path

import pytest

from nczones import precompiled
from nczones.precompiled import functions
from nczones.precompiled.__main__ import modules, source

ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.skipif(not precompiled.ENABLED, reason="precompiled dataclass functions: CPython 3.11 only")


def _codes(code: types.CodeType) -> list[tuple]:
    """What a code object computes, nested code included (not its file, name or line positions)."""
    own = (code.co_code, code.co_argcount, code.co_kwonlyargcount, code.co_posonlyargcount, code.co_flags,
           code.co_names, code.co_varnames, code.co_freevars, code.co_cellvars,
           tuple(c for c in code.co_consts if not isinstance(c, types.CodeType)))
    return [own] + [x for c in code.co_consts if isinstance(c, types.CodeType) for x in _codes(c)]


def _compiled(txt: str) -> types.CodeType:
    """The ``__create_fn__`` code ``exec(txt)`` runs inside ``dataclasses`` (no future flags inherited)."""
    module = compile(txt, "<string>", "exec", dont_inherit=True)
    return next(c for c in module.co_consts if isinstance(c, types.CodeType))


def test_every_precompiled_function_is_the_bytecode_of_its_text():
    assert functions.FUNCTIONS
    for txt, fn in functions.FUNCTIONS.items():
        assert _codes(fn.__code__) == _codes(_compiled(txt)), txt


def test_a_wrong_table_entry_is_caught():
    # the check above fails when an entry's function is another text's (a mutation of the generated module)
    (t1, f1), (t2, f2) = list(functions.FUNCTIONS.items())[:2]
    assert _codes(f2.__code__) != _codes(_compiled(t1))


def _sample(decorate, **options):
    @decorate(**options)
    class Sample:
        a: int
        b: str = "b"
        c: list = dataclasses.field(default_factory=list)
        d: float = dataclasses.field(default=0.5, compare=False, repr=False)

    return Sample


@pytest.mark.parametrize("options", [{}, {"frozen": True}, {"frozen": True, "slots": True},
                                     {"order": True}, {"eq": False}, {"frozen": True, "order": True, "slots": True}])
def test_a_class_made_through_the_table_behaves_as_the_standard_librarys(monkeypatch, options):
    # record the texts of the sample's functions, write them as the generator does, and make the class again
    # with that table: its functions now come from the "generated" module, as nczones' classes do
    seen: list[str] = []
    original = precompiled._create_fn

    def recording(name, args, body, **kw):
        monkeypatch.setattr(precompiled, "_functions", lambda: {})
        out = original(name, args, body, **kw)
        locals_ = dict(kw.get("locals") or {})
        rt = "->_return_type" if "_return_type" in locals_ else ""
        seen.append(f"def __create_fn__({', '.join(locals_)}):\n def {name}({','.join(args)}){rt}:\n"
                    + "\n".join(f"  {b}" for b in body) + f"\n return {name}")
        return out

    monkeypatch.setattr(precompiled, "_create_fn", recording)
    _sample(precompiled.dataclass, **options)
    monkeypatch.undo()
    namespace: dict = {}
    exec(compile(source(sorted(set(seen))), "<generated>", "exec", dont_inherit=True), namespace)  # noqa: S102
    table = namespace["FUNCTIONS"]
    assert set(table) == set(seen)
    used: list[str] = []
    monkeypatch.setattr(precompiled, "_functions", lambda: used.append("x") or table)
    ours, theirs = _sample(precompiled.dataclass, **options), _sample(dataclasses.dataclass, **options)
    assert used and ours.__init__.__code__.co_filename == "<generated>"
    x, y = ours(1, "q", [2], 9.0), theirs(1, "q", [2], 9.0)
    assert repr(x).replace("Sample", "S") == repr(y).replace("Sample", "S")
    assert ours(1) == ours(1, "b", []) if options.get("eq", True) else ours(1) != ours(1)
    assert (ours(1) == ours(1, "b", [], 7.0)) == (theirs(1) == theirs(1, "b", [], 7.0))
    assert ours(1).c is not ours(1).c
    if options.get("order"):
        assert (ours(1) < ours(2)) and not (ours(2) < ours(1))
    if options.get("frozen"):
        with pytest.raises(dataclasses.FrozenInstanceError):
            x.a = 2
        assert hash(ours(1, "b", ())) == hash(theirs(1, "b", ()))
    else:
        x.a = 3
        assert x.a == 3
    assert hasattr(ours, "__slots__") == hasattr(theirs, "__slots__")
    assert dataclasses.replace(x, a=5).a == 5 and [f.name for f in dataclasses.fields(ours)] == ["a", "b", "c", "d"]
    assert ours.__init__.__annotations__ == theirs.__init__.__annotations__
    assert ours.__init__.__qualname__ == f"{ours.__qualname__}.__init__"


@pytest.mark.parametrize("options", [{}, {"frozen": True, "slots": True}, {"order": True}])
def test_a_class_whose_text_is_not_in_the_table_is_the_standard_librarys(options):
    # the fallback (a class added since the module was written): compiled as dataclasses compiles it, with
    # the annotations evaluated although nczones.precompiled itself uses `from __future__ import annotations`
    ours, theirs = _sample(precompiled.dataclass, **options), _sample(dataclasses.dataclass, **options)
    assert ours.__init__.__code__.co_filename == "<string>"
    assert ours.__init__.__annotations__ == theirs.__init__.__annotations__
    assert _codes(ours.__init__.__code__) == _codes(theirs.__init__.__code__)
    assert repr(ours(1)).replace("Sample", "S") == repr(theirs(1)).replace("Sample", "S")


def test_the_classes_of_nczones_take_their_functions_from_the_generated_module():
    generated = functions.__file__
    checked = 0
    for name in modules():
        module = importlib.import_module(name)
        for value in vars(module).values():
            if isinstance(value, type) and dataclasses.is_dataclass(value) and value.__module__ == name:
                init = value.__dict__.get("__init__")
                if isinstance(init, types.FunctionType):
                    assert init.__code__.co_filename == generated, (name, value)
                    checked += 1
    assert checked >= 40


def test_the_generated_module_is_current():
    r = subprocess.run([sys.executable, "-m", "nczones.precompiled", "--check"], capture_output=True, text=True,
                       cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
