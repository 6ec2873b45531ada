"""nczones.precompiled: dataclasses whose generated methods come precompiled (issue 36, start-up).

The claim is that a class made by ``nczones.precompiled.dataclass`` is the class ``dataclasses.dataclass``
makes.  Checked three ways: every precompiled function is the bytecode Python compiles from its text (the
text ``dataclasses`` would have compiled); classes made through the table behave as the standard library's
(construction, defaults, repr, equality, order, hash, frozenness, slots); the generated module is current,
and every class of the modules that use the decorator took its functions from it.
"""

from __future__ import annotations

import copy
import dataclasses
import importlib
import json
import os
import subprocess
import sys
import types
from pathlib import Path

import pytest

from nczones import precompiled
from nczones.precompiled import functions, functions_later
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
    assert functions.FUNCTIONS and functions_later.FUNCTIONS
    assert not set(functions.FUNCTIONS) & set(functions_later.FUNCTIONS)  # each text in one of the two
    for txt, fn in {**functions.FUNCTIONS, **functions_later.FUNCTIONS}.items():
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
    # boot44: from one of the two generated modules (functions_later: what no start-up scenario makes)
    generated = (functions.__file__, functions_later.__file__)
    checked = 0
    for name in modules():
        module = importlib.import_module(name)
        for value in vars(module).values():
            if isinstance(value, type) and dataclasses.is_dataclass(value) and value.__module__ == name:
                init = value.__dict__.get("__init__")
                if isinstance(init, types.FunctionType):
                    assert init.__code__.co_filename in generated, (name, value)
                    checked += 1
    assert checked >= 40


def test_the_generated_module_is_current():
    r = subprocess.run([sys.executable, "-m", "nczones.precompiled", "--check"], capture_output=True, text=True,
                       cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr


def test_write_leaves_a_current_module_untouched_and_rewrites_a_stale_one(tmp_path, monkeypatch, capsys):
    """``--write`` rewrites only what changed: an unchanged module keeps its mtime (and its cached bytecode)."""
    import shutil

    import nczones.precompiled.__main__ as generator

    current, stale, later = tmp_path / "functions.py", tmp_path / "regexes.py", tmp_path / "functions_later.py"
    shutil.copyfile(generator.TARGET, current)
    shutil.copyfile(generator.LATER, later)
    stale.write_text("# stale\n", encoding="utf-8")
    os.utime(current, ns=(10**18, 10**18))
    monkeypatch.setattr(generator, "TARGET", current)
    monkeypatch.setattr(generator, "LATER", later)
    monkeypatch.setattr(generator, "REGEXES", stale)
    monkeypatch.setattr(sys, "argv", ["nczones.precompiled", "--write"])
    assert generator.main() == 0
    assert current.stat().st_mtime_ns == 10**18
    assert stale.read_text(encoding="utf-8") == Path(generator.__file__).with_name("regexes.py").read_text(
        encoding="utf-8")
    assert f"unchanged: {current}" in capsys.readouterr().out


#: A description of every dataclass of nczones, printed as JSON by a fresh interpreter: the class's attributes,
#: each generated function's bytecode, defaults, closure, qualified name and annotations, its fields as
#: ``dataclasses.fields`` gives them, its parameters, doc, ``__match_args__``, slots and hash.
DESCRIBE = r'''
import dataclasses, importlib, json, re, sys, types
import nczones.precompiled as p
if sys.argv[1] == "standard":
    p.ENABLED = False  # every class from dataclasses.dataclass itself
from nczones.precompiled.__main__ import modules
from tests.precompiled.test_precompiled import _codes

def r(value):  # repr without addresses (the two processes' differ)
    return re.sub(r" at 0x[0-9a-f]+", "", repr(value))

def cell(name, value):
    if name == "MISSING":  # not read by the code (dataclasses puts its own sentinel there)
        return "MISSING"
    if name == "FrozenInstanceError":  # what calling it gives
        return type(value("x")).__qualname__
    if isinstance(value, type):
        return value.__qualname__
    return r(value)

def function(fn):
    fn = getattr(fn, "__wrapped__", fn)
    code = fn.__code__
    return [r(_codes(code)), fn.__qualname__, r(fn.__defaults__), r(fn.__kwdefaults__),
            r(fn.__annotations__),
            [cell(n, c.cell_contents) for n, c in zip(code.co_freevars, fn.__closure__ or ())]]

def field(f):
    return [f.name, f.type, r(f.default), r(f.default_factory), f.init, f.repr, f.hash, f.compare,
            r(f.metadata), r(f.kw_only), r(f._field_type)]

out = {}
for name in modules():
    module = importlib.import_module(name)
    for value in vars(module).values():
        if isinstance(value, type) and dataclasses.is_dataclass(value) and value.__module__ == name:
            own = dict(vars(value))
            out[f"{name}.{value.__qualname__}"] = {
                "keys": sorted(own),
                "wrapped": sorted(k for k, v in own.items() if hasattr(v, "__wrapped__")),
                "functions": {k: function(v) for k, v in own.items() if isinstance(v, types.FunctionType)
                              and v.__module__ in (name, "dataclasses", "nczones.precompiled")
                              and k in ("__init__", "__repr__", "__eq__", "__lt__", "__le__", "__gt__", "__ge__",
                                        "__hash__", "__setattr__", "__delattr__")},
                "state": [getattr(value, k, None) is not None  # ours: nczones.precompiled._getstate, the same
                          for k in ("__getstate__", "__setstate__")],
                "fields": [field(f) for f in value.__dataclass_fields__.values()],
                "public": [f.name for f in dataclasses.fields(value)],
                "params": r(value.__dataclass_params__),
                "doc": value.__doc__, "match": r(getattr(value, "__match_args__", None)),
                "slots": r(value.__dict__.get("__slots__")), "hash": r(value.__hash__ is None),
                "mro": [c.__qualname__ for c in value.__mro__],
                "defaults": {k: r(v) for k, v in own.items() if k in value.__dataclass_fields__},
            }
print(json.dumps(out))
'''


def _described(mode: str) -> dict:
    r = subprocess.run([sys.executable, "-c", DESCRIBE, mode], capture_output=True, text=True, cwd=ROOT,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_every_class_of_nczones_is_the_class_the_standard_library_makes():
    # nczones.precompiled makes the classes itself without importing dataclasses (start-up, issue 36); the class
    # dataclasses.dataclass makes of the same body is the reference, attribute by attribute
    ours, theirs = _described("precompiled"), _described("standard")
    assert len(ours) >= 40 and ours.keys() == theirs.keys()
    for name in ours:
        assert ours[name] == theirs[name], name



@pytest.mark.parametrize("options", [{}, {"frozen": True, "slots": True}, {"order": True, "kw_only": True}])
def test_field_and_replace_without_dataclasses_are_the_standard_librarys(options):
    # nczones.precompiled.field and .replace stand for dataclasses' (which a verify no longer imports): a class
    # declared with each module's field() behaves the same, and replace() copies, changes and refuses alike
    def sample(dataclass, field):
        @dataclass(**options)
        class Sample:
            a: int
            b: list = field(default_factory=list, compare=False)
            c: int = field(default=3, repr=False, metadata={"unit": "mm"})
            d: int = field(default=0, init=False)

        return Sample

    ours = sample(precompiled.dataclass, precompiled.field)
    theirs = sample(dataclasses.dataclass, dataclasses.field)
    describe = [(f.name, f.default, f.default_factory, f.init, f.repr, f.compare, dict(f.metadata), f.kw_only)
                for f in dataclasses.fields(ours)]
    assert describe == [(f.name, f.default, f.default_factory, f.init, f.repr, f.compare, dict(f.metadata),
                         f.kw_only) for f in dataclasses.fields(theirs)]
    assert precompiled.field_names(ours) == precompiled.field_names(theirs) == ("a", "b", "c", "d")
    x, y = ours(a=1, b=[2]), theirs(a=1, b=[2])
    assert repr(x).replace("Sample", "S") == repr(y).replace("Sample", "S")
    for replace in (precompiled.replace, dataclasses.replace):
        for obj in (x, y):
            z = replace(obj, c=5)
            assert (z.a, z.b, z.c, z.d) == (1, [2], 5, 0) and z is not obj and type(z) is type(obj)
            with pytest.raises(ValueError, match="init=False"):
                replace(obj, d=1)
            with pytest.raises(TypeError):
                replace(obj, e=1)
    with pytest.raises(ValueError, match="both default and default_factory"):
        precompiled.field(default=1, default_factory=list)


def test_every_precompiled_pattern_is_what_re_compiles():
    # nczones.precompiled.regexes holds _sre.compile's arguments for the patterns of a start-up; each must make
    # the pattern re.compile makes (Pattern.__eq__ compares pattern, flags and code), with the same groups
    import _sre
    from re import _compiler

    from nczones.precompiled import regexes

    if regexes.HEXVERSION != sys.hexversion:
        pytest.skip("regexes written on another CPython 3.11 release: not used here")
    assert len(regexes.PATTERNS) >= 50
    for pattern, flags, code_flags, code, groups, groupindex, indexgroup in regexes.PATTERNS:
        ours, fresh = _sre.compile(pattern, code_flags, list(code), groups, dict(groupindex), indexgroup), \
            _compiler.compile(pattern, flags)
        assert ours == fresh and ours.flags == fresh.flags and ours.groups == fresh.groups, pattern
        assert ours.groupindex == fresh.groupindex, pattern


def test_a_small_verify_compiles_no_regular_expression(tmp_path):
    # issue 36: re.compile parses in Python (~5 ms for a start-up's patterns); after `import nczones` they are
    # in re's cache, so a small verify of either dialect (and its help) compiles none
    from nczones.precompiled import regexes

    if regexes.HEXVERSION != sys.hexversion:
        pytest.skip("regexes written on another CPython 3.11 release: nothing is seeded here")
    (tmp_path / "p.ngc").write_text("G21 G90\nG0 X1 Y1\nG1 X2 Y2 F100\nM2\n")
    (tmp_path / "p.nc").write_text("G21 G90\nG0 X1. Y1.\nG1 X2. Y2. F100.\nM30\n")
    machines = ROOT / "specs" / "machines"
    runs = [["verify", str(tmp_path / "p.ngc"), "--machine", str(machines / "mill.toml"), "--format", "json"],
            ["verify", str(tmp_path / "p.nc"), "--machine", str(machines / "fanuc_mill.toml")]]
    code = ("import contextlib, io, json, sys\nimport nczones\nfrom re import _compiler\ncompiled = []\n"
            "original = _compiler.compile\n"
            "_compiler.compile = lambda p, flags=0: compiled.append(p) or original(p, flags)\n"
            "from nczones.cli import main\n"
            f"for argv in {runs!r}:\n"
            "    with contextlib.redirect_stdout(io.StringIO()):\n"
            "        assert main(argv) == 0\n"
            "print(json.dumps(compiled))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout.splitlines()[-1]) == []


def test_the_constructors_of_nczones_frozen_take_their_code_from_the_generated_module():
    # nczones.frozen.builder makes its constructors through nczones.precompiled.make_function: no compile at
    # start-up (issue 36); they still build what the class's own constructor builds (tests/test_frozen.py)
    lexer, segments, shapes = (importlib.import_module(f"nczones.gcode.{m}") for m in ("lexer", "segments", "shapes"))
    made = [segments.make_segment, lexer.make_span, lexer.make_word, vars(shapes)["_parsed_line"]]
    assert [f.__code__.co_filename for f in made] == [functions.__file__] * 4
    assert lexer.make_span.__name__ == "make_span" and lexer.make_word.__name__ == "make_word"


def _shape(cls: type) -> dict:
    """What a dataclass is, for comparing two made from one body: attributes, generated code, fields, params."""
    own = dict(vars(cls))
    # (__getstate__/__setstate__ of a frozen slotted class: ours call dataclasses' when a pickle needs them)
    code = {k: _codes(getattr(v, "__wrapped__", v).__code__) for k, v in own.items()
            if isinstance(v, types.FunctionType) and k not in ("__getstate__", "__setstate__")}
    return {"keys": sorted(own), "code": code, "hash": own.get("__hash__", "absent") is None,
            "match": own.get("__match_args__"), "slots": own.get("__slots__"), "doc": cls.__doc__,
            "params": repr(cls.__dataclass_params__),
            "fields": [(f.name, f.type, f.default, f.default_factory, f.init, f.repr, f.hash, f.compare, f.kw_only)
                       for f in dataclasses.fields(cls)]}


@pytest.mark.parametrize("options", [
    dict(zip(("init", "repr", "eq", "order", "unsafe_hash", "frozen", "match_args", "kw_only", "slots"), flags))
    for flags in [(True, True, True, False, False, False, True, False, False),
                  (False, False, True, False, True, False, False, False, False),
                  (True, True, False, False, True, True, True, False, True),
                  (True, False, True, True, False, True, True, True, True),
                  (True, True, True, False, True, False, True, True, False),
                  (True, True, False, False, False, False, True, False, True)]])
def test_each_combination_of_options_makes_the_standard_librarys_class(options):
    # the decorator does dataclasses._process_class's work itself: per option, the class it makes has the same
    # attributes, the same generated code (bytecode), fields, hash, __match_args__, slots and doc
    def sample(decorate, field):
        @decorate(**options)
        class Sample:
            a: int
            b: str = "b"
            c: list = field(default_factory=list, hash=False)
            d: float = field(default=0.5, compare=False, repr=False, init=False)

        return Sample

    ours = sample(precompiled.dataclass, precompiled.field)
    theirs = sample(dataclasses.dataclass, dataclasses.field)
    assert ours in vars(precompiled)["_MADE"]  # made here, not handed to dataclasses
    assert _shape(ours) == _shape(theirs)
    if options["init"] and options["frozen"] and options["slots"]:  # what pickle and copy call
        x, y = ours(a=1, b="q", c=[2]), theirs(a=1, b="q", c=[2])
        assert x.__getstate__() == y.__getstate__() == [1, "q", [2], 0.5]
        z = object.__new__(ours)
        z.__setstate__([3, "r", [4], 1.5])
        assert (z.a, z.b, z.c, z.d) == (3, "r", [4], 1.5)
        assert copy.copy(x).c is x.c and copy.deepcopy(x).c == [2]


def test_the_repr_wrapper_is_functools_wraps_s():
    # boot44: _recursive_repr copies what functools.wraps copies, without it
    def make(decorate):
        class Sample:
            a: int
            b: str = "x"

        return decorate(frozen=True, slots=True)(Sample)

    ours, theirs = make(precompiled.dataclass).__repr__, make(dataclasses.dataclass).__repr__
    for attr in ("__module__", "__name__", "__qualname__", "__doc__", "__annotations__"):
        assert getattr(ours, attr) == getattr(theirs, attr), attr
    assert set(vars(ours)) == set(vars(theirs)) == {"__wrapped__"}
    assert ours.__wrapped__.__qualname__ == theirs.__wrapped__.__qualname__
    assert repr(make(precompiled.dataclass)(1)) == "test_the_repr_wrapper_is_functools_wraps_s.<locals>.make.<locals>.Sample(a=1, b='x')"


def test_a_small_verify_loads_only_the_start_up_functions(tmp_path):
    # boot44: the functions no scenario's start-up makes are in functions_later, which a small verify of either
    # dialect (and the double pass, and the Fanuc box route) does not load; a class outside them still gets its
    # functions from it, not compiled
    (tmp_path / "p.ngc").write_text("G21 G90\nG0 X1 Y1\nG1 X2 Y2 F100\nM2\n")
    (tmp_path / "q.ngc").write_text("G21 G90 F100\n#1 = 2\nG1 X[#1 * 2] Y1\nM2\n")
    (tmp_path / "p.nc").write_text("G21 G90\nG0 X1. Y1.\nG1 X2. Y2. F100.\nM30\n")
    machines = ROOT / "specs" / "machines"
    runs = [["verify", str(tmp_path / "p.ngc"), "--machine", str(machines / "mill.toml"), "--format", "json"],
            ["verify", str(tmp_path / "q.ngc"), "--machine", str(machines / "mill.toml")],
            ["verify", str(tmp_path / "p.nc"), "--machine", str(machines / "fanuc_mill.toml")]]
    code = ("import contextlib, io, sys\nfrom nczones.cli import main\n"
            f"for argv in {runs!r}:\n"
            "    with contextlib.redirect_stdout(io.StringIO()):\n"
            "        assert main(argv) == 0\n"
            "print('nczones.precompiled.functions_later' in sys.modules)\n"
            "import nczones.gcode.fanuc.transform_columns as t\n"
            "from nczones.precompiled import functions_later\n"
            "print(t.ColumnTransform.__init__.__code__.co_filename == functions_later.__file__)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["False", "True"]
