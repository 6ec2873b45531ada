"""The machines the tests use, one TOML file each (issue 34: shared fixtures instead of inline copies).

A test names a machine and, for a variant, states the delta beside it::

    from tests.machines import load_machine, machine_text

    MILL = load_machine("mill_xyz")                                   # tests/machines/mill_xyz.toml
    FINE = machine_text("mill_xyz", set={"machine.pulse": "0.0001"})  # the text, one value changed
    TOOLS = machine_text("mill_xyz", extra='[tool_lengths]\\nH1 = "10"\\n')  # a section appended

A zone of the variant is appended with ``extra=box_zone("clamp", {"X": "1", "Y": "2"}, {"X": "3", "Y": "4"},
forbid=True)``.

``set`` keys are ``section.key`` (``machine.pulse``, ``machine.rapid.X``, ``offsets.G54``): the key's line in
that table is replaced, or added at the end of the table when the table does not have it.  A value is
written as TOML: a ``str`` as a string, a ``bool`` as true/false, a ``dict`` as an inline table of strings,
a ``list`` as an array of strings.  ``[[zones]]`` entries are not addressed by ``set``: append them with
``extra`` or write the machine as its own file.

tests/machines/test_fixtures.py checks that every file parses as a machine, is used by a test, and that no
two files are the same machine.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from nczones.machine import Machine

HERE = Path(__file__).resolve().parent

_HEADER = re.compile(r"^\s*\[([^\[\]]+)\]\s*(?:#.*)?$")
_ARRAY_HEADER = re.compile(r"^\s*\[\[([^\[\]]+)\]\]\s*(?:#.*)?$")


def machine_path(name: str) -> Path:
    """The file of machine ``name`` (tests/machines/<name>.toml); a missing name is an error, not a skip."""
    path = HERE / f"{name}.toml"
    if not path.is_file():
        known = ", ".join(sorted(p.stem for p in HERE.glob("*.toml")))
        raise FileNotFoundError(f"no test machine {name!r} in {HERE} (known: {known})")
    return path


def names() -> list[str]:
    """Every machine of tests/machines, by name."""
    return sorted(p.stem for p in HERE.glob("*.toml"))


def _toml_value(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_toml_value(v)}" for k, v in value.items()) + " }"
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"no TOML form for {value!r}")


def _key(key: str) -> str:
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else _toml_value(key)


def _set(text: str, dotted: str, value: object) -> str:
    """Replace (or add) ``key = value`` in table ``section`` of ``text``, for ``dotted = section.key``."""
    section, _, key = dotted.rpartition(".")
    if not section:
        raise ValueError(f"set key {dotted!r}: write it as section.key (machine.pulse)")
    lines = text.splitlines(keepends=True)
    current, start, end = "", None, len(lines)
    key_line = re.compile(rf"^\s*{re.escape(_key(key))}\s*=")
    for i, line in enumerate(lines):
        header = _ARRAY_HEADER.match(line) or _HEADER.match(line)
        if header:
            if current == section and start is not None:
                end = i
                break
            current = header.group(1).strip()
            if current == section and not _ARRAY_HEADER.match(line):
                start = i + 1
            continue
        if current == section and start is not None and key_line.match(line):
            lines[i] = f"{_key(key)} = {_toml_value(value)}\n"
            return "".join(lines)
    if start is None:
        raise KeyError(f"set key {dotted!r}: the machine has no [{section}] table")
    while end > start and not lines[end - 1].strip():
        end -= 1
    if end > 0 and not lines[end - 1].endswith("\n"):
        lines[end - 1] += "\n"
    lines.insert(end, f"{_key(key)} = {_toml_value(value)}\n")
    return "".join(lines)


def machine_text(name: str, *, set: dict[str, object] | None = None, extra: str = "") -> str:  # noqa: A002
    """The TOML text of machine ``name``, with the ``set`` values changed and ``extra`` appended."""
    text = machine_path(name).read_text(encoding="utf-8")
    for dotted, value in (set or {}).items():
        text = _set(text, dotted, value)
    if extra:
        text = text + ("" if text.endswith("\n") else "\n") + extra
    return text


def load_machine(name: str, *, set: dict[str, object] | None = None, extra: str = "") -> Machine:  # noqa: A002
    """The parsed machine ``name`` (see :func:`machine_text` for ``set`` and ``extra``)."""
    from nczones.machine import parse_machine

    return parse_machine(machine_text(name, set=set, extra=extra), str(machine_path(name)))


def box_zone(name: str, low: dict[str, str], high: dict[str, str], *, forbid: bool = False) -> str:
    """The ``[[zones]]`` entry of a box zone (``low``/``high``: its ``min``/``max`` by axis), for ``extra``.

    >>> print(box_zone("clamp", {"X": "1"}, {"X": "2"}, forbid=True), end="")
    [[zones]]
    name = "clamp"
    kind = "box"
    forbid = true
    min = { X = "1" }
    max = { X = "2" }
    """
    lines = ["[[zones]]", f"name = {_toml_value(name)}", 'kind = "box"'] + (["forbid = true"] if forbid else [])
    return "\n".join(lines + [f"min = {_toml_value(low)}", f"max = {_toml_value(high)}"]) + "\n"
