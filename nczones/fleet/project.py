"""The project file ``nczones.toml``: machines, which programs run on which, and their settings.

A project file sits at the root of a program library (``specs/fleet.md``)::

    [project]
    name = "shop floor"                 # optional
    store = ".nczones/results.sqlite"   # optional, relative to the project root

    [defaults]                          # settings of every job
    max_violations = 5

    [machines.grinder]
    file = "machines/grinder.toml"
    programs = ["programs/grinder/*.ngc"]
    exclude = ["programs/grinder/old_*.ngc"]   # optional
    margin = "0.01"                     # settings of this machine's jobs (optional)

    [[settings]]                        # settings of some programs, in order: later tables win
    programs = ["programs/mill/x_near_limit.ngc"]
    machines = ["mill"]                 # optional: every machine when left out
    params = ["G54.X=-2..2"]

Globs are relative to the project root (``**`` matches folders at any
depth; ``..`` reaches programs beside the library, which are then named
``../...``).  Every setting of :data:`SETTINGS` changes the verdict and is part
of the job key; the settings of a job are the defaults, then the machine's,
then every matching ``[[settings]]`` table in order.

Errors are :class:`~nczones.errors.ProjectFileError` with codes ``FL1xx``
and the line of the project file.

>>> import pathlib, tempfile
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> _ = (root / "m.toml").write_text('[machine]\\naxes = ["X"]\\n[machine.rapid]\\nX = "1000"\\n'
...                                  '[machine.reference]\\nX = "0"\\n')
>>> _ = (root / "a.ngc").write_text("G1 X1 F100\\n")
>>> _ = (root / "nczones.toml").write_text('[machines.m]\\nfile = "m.toml"\\nprograms = ["*.ngc"]\\n'
...                                        '[[settings]]\\nprograms = ["a.ngc"]\\nmargin = "0.50"\\n')
>>> project = load_project(root)
>>> [(c.program, c.machine, dict(c.settings)) for c in project.cells()]
[('a.ngc', 'm', {'margin': '0.5'})]
"""

from __future__ import annotations

import hashlib
import inspect
import json
import os
import re
import tomllib
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import Diagnostic, InvalidArgument, ProjectFileError, SourceSpan
from ..exact import format_decimal, parse_decimal

__all__ = ["PROJECT_FILE", "DEFAULT_STORE", "SETTINGS", "Setting", "MachineEntry", "Cell", "Project",
           "load_project", "find_project_file", "verify_kwargs", "settings_json", "supported_settings"]

#: The project file's name at the root of a library.
PROJECT_FILE = "nczones.toml"
#: Where the result store lives, relative to the project root, unless ``[project] store`` says otherwise.
DEFAULT_STORE = ".nczones/results.sqlite"


@dataclass(frozen=True, slots=True)
class Setting:
    """One verdict-changing setting of a job: its key in the project file and its ``verify`` keyword.

    ``normalize`` turns the TOML value into a canonical JSON value (so that
    ``"0.50"`` and ``"0.5"`` give one job key) or raises ``ValueError`` with
    what is allowed.
    """

    name: str
    keyword: str
    normalize: Callable[[Any], Any]
    help: str


def _decimal_text(value: Any) -> str:
    if isinstance(value, bool) or not isinstance(value, (str, int)):
        raise ValueError("expected a decimal number of mm as a string (e.g. \"0.01\"): a TOML float is binary, "
                         "not the decimal you wrote")
    try:
        q = parse_decimal(str(value))
    except InvalidArgument:
        raise ValueError(f"{value!r} is not a decimal number (e.g. \"0.01\")") from None
    if q < 0:
        raise ValueError(f"{value!r} must not be negative")
    return format_decimal(q)


def _choice(*allowed: str | None) -> Callable[[Any], Any]:
    def check(value: Any) -> Any:
        if value not in allowed:
            raise ValueError(f"{value!r}: allowed are " + ", ".join(repr(a) for a in allowed if a is not None))
        return value
    return check


def _block_delete(value: Any) -> str:
    from ..blockskip import format_block_delete, parse_block_delete

    if not isinstance(value, (str, dict)):
        raise ValueError(f"{value!r}: expected both, off, on or positions per switch (\"1=on,2=off\")")
    return format_block_delete(parse_block_delete(value))


def _positive_int(value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ValueError(f"{value!r}: expected a whole number of at least 1")
    return value


def _params(value: Any) -> list[str]:
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise ValueError("expected a list of ranges such as [\"G54.X=-2..2\", \"H1=195..205\"]")
    return [re.sub(r"\s+", "", v) for v in value]


def _arc_tolerance(value: Any) -> str:
    if value in ("linuxcnc", "grbl"):
        return str(value)
    return _decimal_text(value)


def _budget(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 < value < float("inf"):
        raise ValueError(f"{value!r}: expected a positive number of seconds (a fleet job always has a bounded "
                         "budget)")
    return float(value)


def _library(value: Any) -> str:
    if not isinstance(value, str) or not value:
        raise ValueError("expected the path of a folder of subprogram files, relative to the project root")
    return Path(value).as_posix()


#: Every setting a job can carry, by its project-file key.  Each is a keyword of
#: :func:`nczones.prover.verify`; one this nczones's ``verify`` does not take is refused.
SETTINGS: dict[str, Setting] = {s.name: s for s in (
    Setting("margin", "margin", _decimal_text, "required clearance in mm on every axis (decimal string)"),
    Setting("params", "params", _params, "parameter ranges NAME=LO..HI (list of strings)"),
    Setting("recovery", "recovery", _choice("start", "breakpoint"), "prove tool-break recovery"),
    Setting("engine", "engine", _choice("auto", "z3"), "proof engine"),
    Setting("arc_tolerance", "arc_tolerance", _arc_tolerance, "arc end-point tolerance (mm), \"linuxcnc\" or \"grbl\"; default: the machine file's"),
    Setting("max_iterations", "max_iterations", _positive_int, "loop iterations per entry before unknown"),
    Setting("max_violations", "max_violations", _positive_int, "violating blocks reported per program"),
    Setting("block_delete", "block_delete", _block_delete, "block-delete switch positions (both|off|on, or "
            "per switch: \"1=on,2=off\")"),
    Setting("dialect", "dialect", _choice("linuxcnc", "fanuc"), "G-code dialect (overrides the machine's)"),
    Setting("library", "library", _library, "folder of subprogram files (relative to the project root)"),
    Setting("budget", "budget_s", _budget, "seconds of proof work per job"),
)}


def supported_settings() -> tuple[str, ...]:
    """The settings this nczones's :func:`~nczones.prover.verify` takes (a subset of :data:`SETTINGS`).

    >>> {"margin", "params", "recovery"} <= set(supported_settings())
    True
    """
    from ..prover import verify

    keywords = set(inspect.signature(verify).parameters)
    return tuple(name for name, s in SETTINGS.items() if s.keyword in keywords)


@dataclass(frozen=True, slots=True)
class MachineEntry:
    """A machine of the project: its name, file (absolute) and the programs' globs."""

    name: str
    file: Path
    programs: tuple[str, ...]
    exclude: tuple[str, ...]
    settings: tuple[tuple[str, Any], ...]
    span: SourceSpan | None


@dataclass(frozen=True, slots=True)
class Cell:
    """One program on one machine with its settings (normalized, sorted by name)."""

    program: str  # posix path relative to the project root
    machine: str
    settings: tuple[tuple[str, Any], ...]


@dataclass(frozen=True, slots=True)
class _Rule:
    programs: tuple[str, ...]
    machines: tuple[str, ...] | None
    settings: tuple[tuple[str, Any], ...]


@dataclass(frozen=True, slots=True)
class Project:
    """A loaded project file; :meth:`cells` lists every program × machine pair with its settings."""

    file: Path
    root: Path
    name: str
    store: Path
    defaults: tuple[tuple[str, Any], ...]
    machines: tuple[MachineEntry, ...]
    rules: tuple[_Rule, ...]
    sha256: str

    def machine(self, name: str) -> MachineEntry:
        for m in self.machines:
            if m.name == name:
                return m
        raise KeyError(name)

    def cells(self, machines: Iterable[str] | None = None, programs: Iterable[str] | None = None) -> list[Cell]:
        """Every (program, machine) pair, programs sorted per machine in the machines' order.

        ``machines`` keeps only those names; ``programs`` only programs that
        match one of those globs (relative to the root).
        """
        wanted_m = None if machines is None else set(machines)
        wanted_p = None if programs is None else set().union(*(self._glob(g) for g in programs))
        rule_matches = [(r, set().union(*(self._glob(g) for g in r.programs))) for r in self.rules]
        out: list[Cell] = []
        for m in self.machines:
            if wanted_m is not None and m.name not in wanted_m:
                continue
            chosen = set().union(*(self._glob(g) for g in m.programs)) if m.programs else set()
            chosen -= set().union(*(self._glob(g) for g in m.exclude)) if m.exclude else set()
            for program in sorted(chosen):
                if wanted_p is not None and program not in wanted_p:
                    continue
                merged = dict(self.defaults)
                merged.update(m.settings)
                for rule, matched in rule_matches:
                    if program in matched and (rule.machines is None or m.name in rule.machines):
                        merged.update(rule.settings)
                out.append(Cell(program, m.name, tuple(sorted(merged.items()))))
        return out

    def _glob(self, pattern: str) -> set[str]:
        """Program files (relative posix paths) matching ``pattern`` under the root."""
        found = set()
        for p in self.root.glob(pattern):
            name = Path(os.path.relpath(p, self.root)).as_posix()
            if p.is_file() and p.name != PROJECT_FILE and ".nczones" not in Path(name).parts:
                found.add(name)
        return found


def find_project_file(where: str | os.PathLike | None) -> Path:
    """The project file for a command-line argument: a ``nczones.toml`` file, or a folder holding one.

    Without an argument, the working directory and its parents are searched.
    """
    if where is not None:
        p = Path(where)
        if p.is_dir():
            p = p / PROJECT_FILE
        if not p.is_file():
            raise ProjectFileError(Diagnostic("FL100", f"no project file: {p} does not exist (a {PROJECT_FILE} "
                                                       "at the root of the program library, see specs/fleet.md)",
                                              file=str(p)))
        return p
    here = Path.cwd()
    for folder in (here, *here.parents):
        if (folder / PROJECT_FILE).is_file():
            return folder / PROJECT_FILE
    raise ProjectFileError(Diagnostic("FL100", f"no {PROJECT_FILE} in {here} or its parents; give the project "
                                               "folder or file (see specs/fleet.md)", file=str(here)))


class _Spans:
    """Line lookup for diagnostics: the line of a table header or of ``key =`` inside a table."""

    def __init__(self, path: str, text: str):
        self.path = path
        self.lines = text.splitlines()

    def _span(self, i: int, col: int = 0, width: int | None = None) -> SourceSpan:
        line = self.lines[i]
        return SourceSpan(self.path, i + 1, col + 1, None if width is None else col + 1 + width, line)

    def header(self, pattern: str, occurrence: int = 0) -> int | None:
        rx = re.compile(pattern)
        seen = 0
        for i, line in enumerate(self.lines):
            if rx.match(line.strip()):
                if seen == occurrence:
                    return i
                seen += 1
        return None

    def key(self, header: int | None, key: str) -> SourceSpan | None:
        start = 0 if header is None else header + 1
        rx = re.compile(rf"^\s*{re.escape(key)}\s*=")
        for i in range(start, len(self.lines)):
            s = self.lines[i].strip()
            if header is not None and s.startswith("["):
                break
            if header is None and s.startswith("["):
                break
            if rx.match(self.lines[i]):
                col = len(self.lines[i]) - len(self.lines[i].lstrip())
                return self._span(i, col, len(key))
        return None

    def at(self, header: int | None) -> SourceSpan | None:
        return None if header is None else self._span(header)


def load_project(where: str | os.PathLike | None = None) -> Project:
    """Read and check a project file (a path to it, or its folder); ``FL1xx`` errors, all collected.

    Every machine file named must exist (it is loaded later, per job);
    every setting must be one this nczones's ``verify`` takes.
    """
    path = find_project_file(where)
    data_bytes = path.read_bytes()
    name = str(path)
    try:
        text = data_bytes.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ProjectFileError(Diagnostic("FL101", f"the project file is not UTF-8 text ({exc.reason} at byte "
                                                   f"{exc.start})", file=name)) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        m = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        span = None
        if m and 1 <= int(m.group(1)) <= len(text.splitlines()):
            line = int(m.group(1))
            span = SourceSpan(name, line, int(m.group(2)), None, text.splitlines()[line - 1])
        raise ProjectFileError(Diagnostic("FL101", f"not valid TOML: {str(exc).split(' (at')[0]}", span,
                                          file=name)) from None
    spans = _Spans(name, text)
    problems: list[Diagnostic] = []
    supported = set(supported_settings())
    root = path.parent.resolve()

    def fail(code: str, message: str, span: SourceSpan | None) -> None:
        problems.append(Diagnostic(code, message, span, file=name))

    def read_settings(table: Mapping[str, Any], header: int | None, skip: tuple[str, ...],
                      where_: str) -> tuple[tuple[str, Any], ...]:
        out = []
        for key, value in table.items():
            if key in skip:
                continue
            span = spans.key(header, key) or spans.at(header)
            setting = SETTINGS.get(key)
            if setting is None:
                fail("FL104", f"{where_}: unknown key {key!r}; allowed: " + ", ".join((*skip, *SETTINGS)), span)
                continue
            if key not in supported:
                fail("FL104", f"{where_}: setting {key!r} is not supported by this nczones's verify "
                              f"(it takes: {', '.join(sorted(supported))})", span)
                continue
            try:
                out.append((key, setting.normalize(value)))
            except ValueError as exc:
                fail("FL105", f"{where_}: {key} = {value!r}: {exc}", span)
        return tuple(sorted(out))

    def strings(value: Any, what: str, span: SourceSpan | None) -> tuple[str, ...]:
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
            fail("FL103", f"{what}: expected a list of strings (globs relative to the project root)", span)
            return ()
        for v in value:
            if Path(v).is_absolute():
                fail("FL103", f"{what}: {v!r} must be relative to the project root", span)
                return ()
        return tuple(value)

    for key in data:
        if key not in ("project", "defaults", "machines", "settings"):
            fail("FL102", f"unknown table [{key}]; allowed: [project], [defaults], [machines.NAME], [[settings]]",
                 spans.at(spans.header(rf"^\[+\s*{re.escape(key)}\b")))
    proj = data.get("project", {})
    proj_header = spans.header(r"^\[project\]")
    project_name = root.name
    store = root / DEFAULT_STORE
    if not isinstance(proj, dict):
        fail("FL102", "[project] must be a table", None)
        proj = {}
    for key, value in proj.items():
        span = spans.key(proj_header, key)
        if key == "name" and isinstance(value, str):
            project_name = value
        elif key == "store" and isinstance(value, str) and value:
            store = (root / value).resolve()
        else:
            fail("FL102", f"[project] {key} = {value!r}: allowed keys are name (a string) and store (a path "
                          "relative to the project root)", span)
    defaults_raw = data.get("defaults", {})
    defaults = read_settings(defaults_raw, spans.header(r"^\[defaults\]"), (), "[defaults]") \
        if isinstance(defaults_raw, dict) else ()
    machines: list[MachineEntry] = []
    raw_machines = data.get("machines", {})
    if not isinstance(raw_machines, dict) or not raw_machines:
        fail("FL102", "no machines: add a table [machines.NAME] with file = \"M.toml\" and programs = [globs]",
             None)
        raw_machines = {}
    for mname, table in raw_machines.items():
        header = spans.header(rf"^\[machines\.(\"?){re.escape(mname)}\1\]")
        where_ = f"[machines.{mname}]"
        if not isinstance(table, dict):
            fail("FL102", f"{where_} must be a table with file and programs", spans.at(header))
            continue
        file_value = table.get("file")
        if not isinstance(file_value, str) or not file_value:
            fail("FL103", f"{where_}: file = \"M.toml\" (the machine file, relative to the project root) is "
                          "missing", spans.at(header))
            continue
        mfile = (root / file_value).resolve()
        if not mfile.is_file():
            fail("FL103", f"{where_}: machine file {file_value!r} does not exist", spans.key(header, "file"))
        programs = strings(table.get("programs", []), f"{where_} programs", spans.key(header, "programs"))
        exclude = strings(table.get("exclude", []), f"{where_} exclude", spans.key(header, "exclude"))
        settings = read_settings(table, header, ("file", "programs", "exclude"), where_)
        machines.append(MachineEntry(str(mname), mfile, programs, exclude, settings, spans.at(header)))
    rules: list[_Rule] = []
    raw_rules = data.get("settings", [])
    if not isinstance(raw_rules, list):
        fail("FL102", "settings must be an array of tables: [[settings]]", None)
        raw_rules = []
    names = {m.name for m in machines}
    for k, table in enumerate(raw_rules):
        header = spans.header(r"^\[\[settings\]\]", k)
        where_ = f"[[settings]] #{k + 1}"
        programs = strings(table.get("programs", []), f"{where_} programs", spans.key(header, "programs") or
                           spans.at(header))
        if not programs:
            fail("FL103", f"{where_}: programs = [globs] is missing", spans.at(header))
        only: tuple[str, ...] | None = None
        if "machines" in table:
            only = strings(table["machines"], f"{where_} machines", spans.key(header, "machines"))
            for n in only:
                if n not in names:
                    fail("FL103", f"{where_}: no machine named {n!r} (machines: {', '.join(sorted(names))})",
                         spans.key(header, "machines"))
        rules.append(_Rule(programs, only, read_settings(table, header, ("programs", "machines"), where_)))
    if problems:
        raise ProjectFileError(problems)
    return Project(path.resolve(), root, project_name, store, defaults, tuple(machines), tuple(rules),
                   hashlib.sha256(data_bytes).hexdigest())


def settings_json(settings: Iterable[tuple[str, Any]]) -> str:
    """The canonical JSON of a job's settings (what its key hashes).

    >>> settings_json([("params", ["H1=1..2"]), ("margin", "0.5")])
    '{"margin":"0.5","params":["H1=1..2"]}'
    """
    return json.dumps(dict(settings), sort_keys=True, separators=(",", ":"))


def verify_kwargs(settings: Iterable[tuple[str, Any]], root: str | os.PathLike) -> dict[str, Any]:
    """The keyword arguments of :func:`nczones.prover.verify` for normalized settings.

    >>> verify_kwargs([("margin", "0.5"), ("budget", 30.0)], "/lib")
    {'margin': Fraction(1, 2), 'budget_s': 30.0}
    """
    out: dict[str, Any] = {}
    for key, value in settings:
        setting = SETTINGS[key]
        if key in ("margin",):
            value = parse_decimal(value)
        elif key == "arc_tolerance" and value not in ("linuxcnc", "grbl"):
            value = parse_decimal(value)
        elif key == "params":
            value = tuple(value)
        elif key == "library":
            value = str(Path(root) / value)
        out[setting.keyword] = value
    return out
