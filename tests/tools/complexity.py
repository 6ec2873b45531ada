"""Function size and complexity of the package, against a shrinking list of exemptions (issue 34).

The limits: cyclomatic complexity at most :data:`MAX_COMPLEXITY` (ruff's ``C901``), at most
:data:`MAX_STATEMENTS` statements (ruff's ``PLR0915``) and at most :data:`MAX_LINES` lines of body (the
docstring not counted).  ``tests/packaging/complexity_exemptions.txt`` lists the functions over a limit today,
one ``path::qualified.name rule value`` per line; the test fails on a function over a limit that is not listed,
and on a listed one that is now within it or gone (the list only shrinks).  After splitting a function::

    python -m tests.tools.complexity --write

rewrites the list from the code (review the diff: it must only lose lines).
"""

from __future__ import annotations

import ast
import json
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "nczones"
EXEMPTIONS = ROOT / "tests" / "packaging" / "complexity_exemptions.txt"
MAX_COMPLEXITY = 20
MAX_STATEMENTS = 80
MAX_LINES = 80


def _qualnames(tree: ast.Module) -> dict[int, tuple[str, ast.FunctionDef | ast.AsyncFunctionDef]]:
    """Line of each ``def`` → (qualified name, node), nested functions named through their parents."""
    found: dict[int, tuple[str, ast.FunctionDef | ast.AsyncFunctionDef]] = {}

    def visit(node: ast.AST, prefix: str) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                found[child.lineno] = (prefix + child.name, child)
                visit(child, prefix + child.name + ".")
            elif isinstance(child, ast.ClassDef):
                visit(child, prefix + child.name + ".")
            else:
                visit(child, prefix)

    visit(tree, "")
    return found


def _body_lines(node: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    body = node.body
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
            and isinstance(body[0].value.value, str):
        body = body[1:]
    if not body:
        return 0
    return (body[-1].end_lineno or body[-1].lineno) - body[0].lineno + 1


def _ruff() -> dict[tuple[str, int], dict[str, int]]:
    """(relative path, def line) → {rule: value} from ruff's C901 and PLR0915."""
    ruff = shutil.which("ruff") or str(Path(sys.executable).with_name("ruff"))
    out = subprocess.run(
        [ruff, "check", str(PACKAGE), "--isolated", "--select", "C901,PLR0915", "--output-format", "json",
         "--config", f"lint.mccabe.max-complexity={MAX_COMPLEXITY}",
         "--config", f"lint.pylint.max-statements={MAX_STATEMENTS}"],
        capture_output=True, text=True, check=False)
    found: dict[tuple[str, int], dict[str, int]] = {}
    for item in json.loads(out.stdout or "[]"):
        rel = Path(item["filename"]).resolve().relative_to(ROOT).as_posix()
        value = int(item["message"].split("(")[-1].split()[0])
        found.setdefault((rel, item["location"]["row"]), {})[item["code"]] = value
    return found


def measure() -> dict[str, str]:
    """``path::name rule`` → value of every function over a limit."""
    ruff = _ruff()
    over: dict[str, str] = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        for line, (name, node) in _qualnames(ast.parse(path.read_text(encoding="utf-8"))).items():
            rules = dict(ruff.get((rel, line), {}))
            lines = _body_lines(node)
            if lines > MAX_LINES:
                rules["LINES"] = lines
            for rule, value in rules.items():
                over[f"{rel}::{name} {rule}"] = str(value)
    return over


def read_exemptions() -> dict[str, str]:
    rows = [r.rsplit(" ", 1) for r in EXEMPTIONS.read_text(encoding="utf-8").splitlines()
            if r.strip() and not r.startswith("#")]
    return {key: value for key, value in rows}


def write_exemptions(over: dict[str, str]) -> None:
    head = ("# Functions over the size/complexity limits of tests/tools/complexity.py (issue 34): "
            "path::name rule value.\n# The list only shrinks: split a function, then "
            "`python -m tests.tools.complexity --write`.\n")
    EXEMPTIONS.write_text(head + "".join(f"{k} {v}\n" for k, v in sorted(over.items())), encoding="utf-8")


if __name__ == "__main__":
    measured = measure()
    if "--write" in sys.argv:
        write_exemptions(measured)
    counts: dict[str, int] = {}
    for key in measured:
        counts[key.rsplit(" ", 1)[1]] = counts.get(key.rsplit(" ", 1)[1], 0) + 1
    print(f"{len({k.rsplit(' ', 1)[0] for k in measured})} functions over a limit: {counts}")
