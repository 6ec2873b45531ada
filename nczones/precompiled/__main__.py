"""``python -m nczones.precompiled --write``: write :mod:`nczones.precompiled.functions`, the functions
``dataclasses`` generates for the classes made with :func:`nczones.precompiled.dataclass`; ``--check``: exit 1
when the module on disk is not what would be written (the test runs this)."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

from . import RECORD_ENV

PACKAGE = Path(__file__).resolve().parents[1]
TARGET = Path(__file__).resolve().parent / "functions.py"
USES = re.compile(r"^from (?:\.+|nczones\.)precompiled import dataclass\b", re.M)


def modules() -> list[str]:
    """The modules of nczones that make their dataclasses with :func:`nczones.precompiled.dataclass`."""
    out = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if USES.search(path.read_text(encoding="utf-8")):
            parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
            out.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return out


def texts() -> list[str]:
    """Every function text those modules' classes compile, from a fresh interpreter that records them."""
    code = "import importlib, sys\nfor m in sys.argv[1:]:\n    importlib.import_module(m)\n"
    env = dict(os.environ, **{RECORD_ENV: "1"})
    r = subprocess.run([sys.executable, "-c", code, *modules()], capture_output=True, text=True, env=env,
                       cwd=PACKAGE.parent, check=True)
    return sorted({json.loads(line) for line in r.stderr.splitlines() if line.startswith('"')})


def source(found: list[str]) -> str:
    """The text of :mod:`nczones.precompiled.functions` for the function texts ``found``."""
    head = ['"""The functions ``dataclasses`` generates for nczones\' classes, compiled once like any module (written',
            'by ``python -m nczones.precompiled --write``; do not edit: see :mod:`nczones.precompiled`)."""',
            "# ruff: noqa", "# mypy: ignore-errors", "# fmt: off", ""]
    body, table = [], []
    for i, txt in enumerate(found):
        assert txt.startswith("def __create_fn__(")
        body += [txt.replace("def __create_fn__(", f"def f{i}(", 1), ""]
        table.append(f"    {txt!r}: f{i},")
    return "\n".join([*head, *body, "FUNCTIONS = {", *table, "}", ""])


def main() -> int:
    wanted = source(texts())
    if "--write" in sys.argv:
        TARGET.write_text(wanted, encoding="utf-8")
        print(f"wrote {TARGET}")
        return 0
    current = TARGET.read_text(encoding="utf-8") if TARGET.exists() else ""
    if current != wanted:
        print(f"{TARGET} is not current: run python -m nczones.precompiled --write", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
