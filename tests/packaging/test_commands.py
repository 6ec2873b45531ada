"""The seam between the command line and the subcommands (issue 34): one table, one way.

``nczones.cli`` builds the parser from ``nczones.commands.COMMANDS`` and dispatches; the subcommands share
``nczones.commands.conventions`` and never import ``nczones.cli``; nothing registers by being imported; every
row of the table has a parser and a handler, and ``nczones --help`` lists every row.
"""

from __future__ import annotations

import argparse
import ast
import subprocess
import sys
from pathlib import Path

import pytest

from nczones.cli import build_parser
from nczones.commands import COMMANDS, configurer

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "nczones"
COMMAND_FILES = sorted((PACKAGE / "commands").glob("*.py"))


def _imported_modules(text: str) -> set[str]:
    """The absolute names of the modules a file of ``nczones/commands/`` imports (TYPE_CHECKING ones included),
    each ``from X import name`` counted as both ``X`` and ``X.name``."""
    out: set[str] = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = ["nczones", "commands"][: max(0, 3 - node.level)] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            out.add(module)
            out.update(f"{module}.{a.name}" for a in node.names)
    return out


def _strings(text: str) -> list[str]:
    """The string constants of a file that are not docstrings."""
    tree = ast.parse(text)
    docstrings = {id(n.body[0].value) for n in ast.walk(tree)
                  if isinstance(n, (ast.Module, ast.FunctionDef, ast.ClassDef, ast.AsyncFunctionDef))
                  and n.body and isinstance(n.body[0], ast.Expr) and isinstance(n.body[0].value, ast.Constant)}
    return [n.value for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docstrings]


def test_the_command_files_are_found():
    names = {p.stem for p in COMMAND_FILES}
    assert {"__init__", "conventions", "verify", "check_machine"} <= names


@pytest.mark.parametrize("path", COMMAND_FILES, ids=lambda p: p.name)
def test_no_command_module_imports_the_command_line(path):
    text = path.read_text(encoding="utf-8")
    assert "nczones.cli" not in _imported_modules(text), f"{path.name} imports nczones.cli: use conventions"
    assert not [s for s in _strings(text) if s.startswith("nczones.cli")], f"{path.name} names nczones.cli"


@pytest.mark.parametrize("text", ["from .. import cli\n", "from ..cli import program_source\n",
                                  "import nczones.cli\n", "from nczones import cli\n"])
def test_the_import_check_sees_each_way_of_importing_the_command_line(text):
    """The check above catches the forms the commands used before the split (``from .. import cli``)."""
    assert "nczones.cli" in _imported_modules(text)


def _root_name(node: ast.AST) -> str | None:
    while isinstance(node, (ast.Attribute, ast.Subscript, ast.Call)):
        node = node.func if isinstance(node, ast.Call) else node.value
    return node.id if isinstance(node, ast.Name) else None


@pytest.mark.parametrize("path", COMMAND_FILES, ids=lambda p: p.name)
def test_importing_a_command_module_registers_nothing(path):
    """At module level a command module defines names; it never writes into, or calls to register with, an
    imported module (``cli.REGISTRARS["plot"] = register`` was how commands registered before the table)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    imported: set[str] = set()
    for node in tree.body:
        if isinstance(node, ast.Import):
            imported.update((a.asname or a.name).split(".")[0] for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            imported.update(a.asname or a.name for a in node.names)
    for node in tree.body:
        targets: list[ast.AST] = []
        if isinstance(node, ast.Assign):
            targets = [t for t in node.targets if not isinstance(t, ast.Name)]
        elif isinstance(node, (ast.AnnAssign, ast.AugAssign)) and not isinstance(node.target, ast.Name):
            targets = [node.target]
        elif isinstance(node, ast.Expr) and isinstance(node.value, ast.Call):
            targets = [node.value]
        for t in targets:
            assert _root_name(t) not in imported, f"{path.name}:{node.lineno}: registers with {_root_name(t)}"


def test_every_command_module_is_in_the_table():
    """Each module of ``nczones/commands/`` except the package and the conventions holds a command of the table
    (a module no row names would never be loaded), and each row names a function of a command module."""
    modules = {f"nczones.commands.{p.stem}" for p in COMMAND_FILES if p.stem not in ("__init__", "conventions")}
    assert {c.module for c in COMMANDS.values()} == modules
    for name, command in COMMANDS.items():
        function = configurer(name)
        assert callable(function) and function.__module__ == command.module, name


def test_the_table_is_the_only_place_that_names_a_command_module_by_string():
    """``nczones.cli`` reaches a command only through ``nczones.commands.configurer``; no other file of the
    package names a command's module in a string (a lookup outside the one table)."""
    for path in sorted(PACKAGE.rglob("*.py")):
        if path != PACKAGE / "commands" / "__init__.py":
            named = [s for s in _strings(path.read_text(encoding="utf-8")) if s.startswith("nczones.commands.")]
            assert not named, f"{path.relative_to(ROOT)}: {named}"
    cli_source = (PACKAGE / "cli.py").read_text(encoding="utf-8")
    assert "importlib" not in cli_source and "import_module" not in cli_source


def _subparsers(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    action = next((a for a in parser._actions if isinstance(a, argparse._SubParsersAction)), None)
    return {} if action is None else dict(action.choices)


def _handlers(parser: argparse.ArgumentParser) -> list[object]:
    """The handler of a command's parser, or of each of its own subcommands (``fleet check|status|diff``)."""
    nested = _subparsers(parser)
    if not nested:
        return [parser.get_default("handler")]
    return [h for p in nested.values() for h in _handlers(p)]


def test_every_command_in_the_table_has_a_parser_and_a_handler():
    commands = _subparsers(build_parser())
    assert list(commands) == list(COMMANDS)
    for name, parser in commands.items():
        handlers = _handlers(parser)
        assert handlers and all(callable(h) for h in handlers), name
        assert parser.prog == f"nczones {name}"
    # built alone, a command has its arguments and handler too; the others only their name
    alone = _subparsers(build_parser("replay"))
    assert callable(alone["replay"].get_default("handler"))
    assert all(alone[n].get_default("handler") is None for n in COMMANDS if n != "replay")


def test_nczones_help_lists_every_command_with_its_summary():
    r = subprocess.run([sys.executable, "-m", "nczones", "--help"], capture_output=True, text=True, cwd=ROOT,
                       timeout=60)
    assert r.returncode == 0, r.stderr
    flat = " ".join(r.stdout.split())
    for name, command in COMMANDS.items():
        assert f" {name} {' '.join(command.summary.split())}" in flat, name
