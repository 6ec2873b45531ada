"""``python -m nczones.precompiled --write``: write :mod:`nczones.precompiled.functions`, the functions
``dataclasses`` generates for the classes made with :func:`nczones.precompiled.dataclass` that the start-ups of
:data:`SCENARIOS` make, :mod:`nczones.precompiled.functions_later`, the others (loaded at the first one a run
makes), and :mod:`nczones.precompiled.regexes`, the regular expressions those start-ups compile;
``--check``: exit 1 when a module on disk is not what would be written (the test runs this)."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

from . import RECORD_ENV, RECORD_PATTERNS_ENV
from .machines import peer_box

PACKAGE = Path(__file__).resolve().parents[1]
TARGET = Path(__file__).resolve().parent / "functions.py"
LATER = Path(__file__).resolve().parent / "functions_later.py"
REGEXES = Path(__file__).resolve().parent / "regexes.py"
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


def source(found: list[str], later: bool = False) -> str:
    """The text of :mod:`nczones.precompiled.functions` (``later``: ``functions_later``) for the function texts
    ``found``."""
    which = ("the functions no start-up of ``python -m nczones.precompiled``'s scenarios makes, " if later else
             "the functions the start-ups of ``python -m nczones.precompiled``'s scenarios make, ")
    head = ['"""The functions ``dataclasses`` generates for nczones\' classes, compiled once like any module (written',
            'by ``python -m nczones.precompiled --write``; do not edit: see :mod:`nczones.precompiled`): ' + which,
            '``functions_later`` the others)."""' if not later else 'loaded at the first one a run makes)."""',
            "# ruff: noqa", "# mypy: ignore-errors", "# fmt: off", ""]
    body, table = [], []
    for i, txt in enumerate(found):
        assert txt.startswith("def __create_fn__(")
        body += [txt.replace("def __create_fn__(", f"def f{i}(", 1), ""]
        table.append(f"    {txt!r}: f{i},")
    return "\n".join([*head, *body, "FUNCTIONS = {", *table, "}", ""])


#: The start-ups whose regular expressions are precompiled: small verifies of each dialect and format (the
#: double pass and the Fanuc box reader too), the help, a machine check (``{d}``: a scratch directory, ``{m}``: specs/machines).
SCENARIOS = (
    ["verify", "{d}/tiny.ngc", "--machine", "{m}/mill.toml", "--format", "json"],
    ["verify", "{d}/tiny.ngc", "--machine", "{m}/mill.toml"],
    ["verify", "{d}/param.ngc", "--machine", "{m}/mill.toml"],
    ["verify", "{d}/tiny.nc", "--machine", "{m}/fanuc_mill.toml", "--format", "json"],
    ["verify", "{d}/tiny.nc", "--machine", "{m}/fanuc_mill.toml"],
    ["verify", "{d}/tape.nc", "--machine", "{d}/box_fanuc.toml"],
    ["check-machine", "{m}/mill.toml"],
    ["--help"],
    ["verify", "--help"],
)

_RUN = """import contextlib, io, sys, json
from nczones.cli import main
for argv in json.loads(sys.argv[1]):
    with contextlib.redirect_stdout(io.StringIO()):
        try:
            main(argv)
        except SystemExit:
            pass
"""


def patterns() -> list[tuple[str, str, int]]:
    """(type, text, flags) of every pattern the :data:`SCENARIOS` compile, from fresh interpreters."""
    return start_ups()[0]


def start_ups() -> tuple[list[tuple[str, str, int]], set[str]]:
    """What the :data:`SCENARIOS` make, from fresh interpreters: (type, text, flags) of every pattern they compile,
    and the text of every function :func:`nczones.precompiled.dataclass` (or ``make_function``) makes."""
    import tempfile

    with tempfile.TemporaryDirectory() as d:
        Path(d, "tiny.ngc").write_text("G21 G90\nG0 X1 Y1\nG1 X2 Y2 F100\nM2\n", encoding="utf-8")
        Path(d, "param.ngc").write_text("G21 G90 F100\n#1 = 2.5\nG1 X[#1 * 2] Y[#1 + 1]\nM2\n", encoding="utf-8")
        Path(d, "tiny.nc").write_text("G21 G90\nG0 X1. Y1.\nG1 X2. Y2. F100.\nM30\n", encoding="utf-8")
        # a program between % lines with its O number on a machine of boxes: the Fanuc box reader's patterns (boxrun)
        Path(d, "tape.nc").write_text("%\nO0001\nG21 G90 G54\nG01 X1. Y1. F100.\nM30\n%\n", encoding="utf-8")
        # the peer benchmarks' Fanuc machine: box zones only, so the box reader runs
        Path(d, "box_fanuc.toml").write_text(peer_box("fanuc"), encoding="utf-8")
        found = set()
        made: set[str] = set()
        for argv in SCENARIOS:
            args = [a.format(d=d, m=PACKAGE.parent / "specs" / "machines") for a in argv]
            env = dict(os.environ, **{RECORD_PATTERNS_ENV: "1", RECORD_ENV: "1",
                                      "NCZONES_CACHE": "off"})  # tomllib's patterns too
            r = subprocess.run([sys.executable, "-c", _RUN, json.dumps([args])], capture_output=True, text=True,
                               env=env, cwd=d, check=True)
            for line in r.stderr.splitlines():
                if line.startswith('["pattern"'):
                    kind, text, flags = json.loads(line)[1]
                    found.add((kind, text, flags))
                elif line.startswith('"'):
                    made.add(json.loads(line))
    return sorted(found), made


def regex_source(found: list[tuple[str, str, int]]) -> str:
    """The text of :mod:`nczones.precompiled.regexes`: for each pattern, what ``re._compiler.compile`` gives
    ``_sre.compile`` (on this interpreter)."""
    import _sre  # type: ignore[import-not-found]
    from re import _compiler, _parser  # type: ignore[attr-defined]

    rows = []
    for kind, text, flags in found:
        pattern: str | bytes = text if kind == "str" else text.encode("latin-1")
        p = _parser.parse(pattern, flags)
        code = vars(_compiler)["_code"](p, flags)  # re._compiler.compile's own steps
        groupindex = p.state.groupdict
        indexgroup = [None] * p.state.groups
        for k, i in groupindex.items():
            indexgroup[i] = k
        rows.append(f"    ({pattern!r}, {flags}, {flags | p.state.flags}, {tuple(int(c) for c in code)!r}, {p.state.groups - 1}, "
                    f"{tuple(groupindex.items())!r}, {tuple(indexgroup)!r}),")
    head = ['"""The regular expressions of nczones\' start-ups, compiled (written by ``python -m nczones.precompiled',
            '--write``; do not edit: see :func:`nczones.precompiled.seed_patterns`)."""',
            "# ruff: noqa", "# mypy: ignore-errors", "# fmt: off", "",
            f"HEXVERSION = {sys.hexversion:#x}", f"MAGIC = {_sre.MAGIC}", "",
            "#: (pattern, flags, code flags, code, groups - 1, groupindex items, indexgroup): _sre.compile's arguments",
            "#: (one constant of the module's bytecode: no dict to build at import)",
            "PATTERNS = ("]
    return "\n".join([*head, *rows, ")", ""])


def main() -> int:
    found, made = start_ups()
    every = texts()
    wanted = {TARGET: source([t for t in every if t in made]), LATER: source([t for t in every if t not in made], True),
              REGEXES: regex_source(found)}
    stale = 0
    for target, text in wanted.items():
        current = target.read_text(encoding="utf-8") if target.exists() else ""
        if "--write" in sys.argv:
            if current != text:  # an unchanged file keeps its mtime (and its cached bytecode)
                target.write_text(text, encoding="utf-8")
            print(f"{'wrote' if current != text else 'unchanged:'} {target}")
            continue
        if current != text:
            print(f"{target} is not current: run python -m nczones.precompiled --write", file=sys.stderr)
            stale += 1
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
