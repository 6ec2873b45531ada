"""The package's structure (issue 21): no private name crosses a file, the two witnesses stay apart.

``lint-imports`` (``make lint``, contracts in pyproject.toml) keeps the layers and the independence of
the prover and the controller; these tests keep what it does not see: a ``_private`` name imported from
another file (or read from an imported module, ``module._name``), a private member of another file's
class reached through an object (``prover._bbox_fits``), and an import loop among the modules, the
imports under ``TYPE_CHECKING`` included (a loop the type checker sees is a loop in the design: the lower
module declares what it needs as a Protocol instead).
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "nczones"


@functools.lru_cache(maxsize=None)
def _parse(text: str) -> ast.Module:
    """The tree of a file's text, parsed once per process for all the scans (each parse of the package takes
    about 3 s; the scans only read the trees)."""
    return ast.parse(text)


def _modules(package: Path) -> dict[str, Path]:
    out = {}
    for path in sorted(package.rglob("*.py")):
        rel = path.relative_to(package.parent).with_suffix("")
        name = ".".join(rel.parts)
        out[name.removesuffix(".__init__")] = path
    return out


def _target(module: str, path: Path, node: ast.ImportFrom) -> str:
    """The absolute module name an ``ImportFrom`` reads from."""
    if not node.level:
        return node.module or ""
    package = module if path.name == "__init__.py" else module.rsplit(".", 1)[0]
    base = package.split(".")
    if node.level > 1:
        base = base[: -(node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def private_names_across_files(package: Path = PACKAGE) -> list[str]:
    """``file:line: name`` for every private name one module takes from another."""
    modules = _modules(package)
    found = []
    for module, path in modules.items():
        tree = _parse(path.read_text(encoding="utf-8"))
        aliases: dict[str, str] = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                source = _target(module, path, node)
                for alias in node.names:
                    if f"{source}.{alias.name}" in modules:
                        aliases[alias.asname or alias.name] = f"{source}.{alias.name}"
                    elif source.startswith("nczones") and source != module and _private(alias.name):
                        found.append(f"{path.relative_to(package.parent)}:{node.lineno}: {alias.name} from {source}")
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name in modules and alias.asname:
                        aliases[alias.asname] = alias.name
        for node in ast.walk(tree):
            if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and _private(node.attr)
                    and aliases.get(node.value.id, module) != module):
                found.append(f"{path.relative_to(package.parent)}:{node.lineno}: "
                             f"{node.value.id}.{node.attr} of {aliases[node.value.id]}")
    return found


def _private_names_defined(tree: ast.Module) -> set[str]:
    """The private names a file defines: functions, classes, methods, class attributes and the attributes
    its methods set on ``self``/``cls``."""
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
            if isinstance(node, ast.ClassDef):
                for stmt in node.body:
                    targets = (stmt.targets if isinstance(stmt, ast.Assign)
                               else [stmt.target] if isinstance(stmt, ast.AnnAssign) else [])
                    names.update(n.id for target in targets for n in ast.walk(target) if isinstance(n, ast.Name))
        elif (isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store)
              and isinstance(node.value, ast.Name) and node.value.id in ("self", "cls")):
            names.add(node.attr)
    return {n for n in names if _private(n)}


def _own_object(node: ast.expr) -> bool:
    """``self``, ``cls`` or ``super()``: a class reaching its own (or an inherited) member."""
    return ((isinstance(node, ast.Name) and node.id in ("self", "cls"))
            or (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "super"))


def _member_reached(node: ast.AST) -> tuple[ast.expr, str] | None:
    """``(obj, name)`` for ``obj.name`` and for ``getattr``/``setattr``/``hasattr``/``delattr(obj, "name")``."""
    if isinstance(node, ast.Attribute):
        return node.value, node.attr
    if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
            and node.func.id in ("getattr", "setattr", "hasattr", "delattr") and len(node.args) >= 2
            and isinstance(node.args[1], ast.Constant) and isinstance(node.args[1].value, str)):
        return node.args[0], node.args[1].value
    return None


def private_members_across_files(package: Path = PACKAGE) -> list[str]:
    """``file:line: expr`` for every ``obj._name`` (or ``getattr(obj, "_name")``) that reaches into another
    file's private member.

    ``obj`` is anything but ``self``, ``cls`` or ``super()``, and ``_name`` is defined (as a function,
    method, class, class attribute or attribute set on ``self``) in another file of the package and not in
    this one (a name both define is taken as this file's own). Private attributes of foreign classes the
    package does not define (``Fraction._numerator``) are not the package's names and are not reported.
    """
    modules = _modules(package)
    trees = {m: _parse(path.read_text(encoding="utf-8")) for m, path in modules.items()}
    defined = {m: _private_names_defined(tree) for m, tree in trees.items()}
    found = []
    for module, tree in trees.items():
        hits = []
        for node in ast.walk(tree):
            reached = _member_reached(node)
            if reached is None:
                continue
            obj, name = reached
            if not _private(name) or _own_object(obj) or name in defined[module]:
                continue
            owners = sorted(m for m, names in defined.items() if m != module and name in names)
            if owners:
                hits.append((node.lineno, node.col_offset, f"{ast.unparse(node)} of {', '.join(owners)}"))
        found += [f"{modules[module].relative_to(package.parent)}:{line}: {what}" for line, _, what in sorted(hits)]
    return found


def import_loops(package: Path = PACKAGE) -> list[list[str]]:
    """Cycles among the package's modules by their imports: nested ones and those under ``TYPE_CHECKING``
    included."""
    modules = _modules(package)
    edges: dict[str, set[str]] = {m: set() for m in modules}
    for module, path in modules.items():
        tree = _parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                source = _target(module, path, node)
                targets = [source] + [f"{source}.{a.name}" for a in node.names]
            elif isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                continue
            for t in targets:
                if t in modules and t != module and not module.startswith(t + "."):
                    edges[module].add(t)
    loops, state = [], {m: 0 for m in modules}  # 0 new, 1 on the path, 2 done

    def visit(m: str, trail: list[str]) -> None:
        state[m] = 1
        trail.append(m)
        for n in sorted(edges[m]):
            if state[n] == 1:
                loops.append(trail[trail.index(n):] + [n])
            elif state[n] == 0:
                visit(n, trail)
        trail.pop()
        state[m] = 2

    for m in sorted(modules):
        if state[m] == 0:
            visit(m, [])
    return loops


def test_no_private_name_is_imported_from_another_file():
    assert private_names_across_files() == []


def test_no_private_member_is_reached_through_an_object_from_another_file():
    """``prover.bbox_fits(...)`` from a plug-in, not ``prover._bbox_fits(...)``: a member another file uses
    is public in its class."""
    assert private_members_across_files() == []


def _plant(tmp_path: Path, files: dict[str, str]) -> Path:
    fake = tmp_path / "nczones"
    for name, text in {"__init__.py": "", "prover/__init__.py": "", **files}.items():
        (fake / name).parent.mkdir(parents=True, exist_ok=True)
        (fake / name).write_text(text)
    return fake


def test_the_scans_are_not_blind(tmp_path):
    """A planted private import, a module-attribute read, a nested-import loop and a loop through a
    TYPE_CHECKING import are reported."""
    fake = _plant(tmp_path, {
        "prover/a.py": "def _helper():\n    return 1\n\n\ndef f():\n    from .c import g\n",
        "prover/b.py": "from .a import _helper\nfrom . import a\nx = a._helper()\n",
        "prover/c.py": "from .a import f\n\n\ndef g():\n    pass\n",
        "prover/d.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from .e import E\n",
        "prover/e.py": "from .d import TYPE_CHECKING\nE = 1\n",
    })
    found = private_names_across_files(fake)
    assert [f.split(": ", 1)[1] for f in found] == ["_helper from nczones.prover.a", "a._helper of nczones.prover.a"]
    assert import_loops(fake) == [["nczones.prover.a", "nczones.prover.c", "nczones.prover.a"],
                                  ["nczones.prover.d", "nczones.prover.e", "nczones.prover.d"]]


def test_the_member_scan_is_not_blind(tmp_path):
    """A private method, a private attribute set in ``__init__`` and a private class attribute reached
    through an object from another file are reported; ``self``/``super()`` calls, a file's own private
    members and a foreign class's private attribute are not."""
    fake = _plant(tmp_path, {
        "prover/core.py": (
            "class Prover:\n"
            "    _cache: dict = {}\n"
            "\n"
            "    def __init__(self):\n"
            "        self._budget = 3\n"
            "\n"
            "    def _bbox_fits(self, box):\n"
            "        return self._budget > 0\n"),
        "prover/spline.py": (
            "from fractions import Fraction\n"
            "from .core import Prover\n"
            "\n"
            "\n"
            "class Spline(Prover):\n"
            "    def _own(self):\n"
            "        return self._bbox_fits(None) and super()._bbox_fits(None)\n"
            "\n"
            "\n"
            "def check(prover, other):\n"
            "    q = Fraction(1, 3)\n"
            "    other._own()\n"
            "    q._numerator\n"
            "    return prover._bbox_fits(None) and prover._budget and Prover._cache\n"
            "\n"
            "\n"
            "def peek(prover):\n"
            "    return getattr(prover, '_budget', None), getattr(prover, 'budget', None)\n"),
    })
    found = private_members_across_files(fake)
    assert [f.split(": ", 1)[1] for f in found] == [
        "prover._bbox_fits of nczones.prover.core", "prover._budget of nczones.prover.core",
        "Prover._cache of nczones.prover.core", "getattr(prover, '_budget', None) of nczones.prover.core"]
    assert [f.split(": ", 1)[0] for f in found] == ["nczones/prover/spline.py:14"] * 3 + ["nczones/prover/spline.py:18"]


def test_no_import_loop_not_even_for_the_type_checker():
    assert import_loops() == []


def test_the_witnesses_do_not_import_each_other():
    """What the issue's grep checks: no prover file names the controller in an import, and no controller
    file the prover."""
    for side, other in (("prover", "controller"), ("controller", "prover")):
        for path in sorted((PACKAGE / side).rglob("*.py")):
            for node in ast.walk(_parse(path.read_text(encoding="utf-8"))):
                if isinstance(node, ast.ImportFrom):
                    source = _target(".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts), path, node)
                    assert not source.startswith(f"nczones.{other}"), f"{path}:{node.lineno} imports {source}"
