"""No input makes the loader crash: every mutation of an example machine either
loads or raises MachineFileError with located, coded diagnostics."""

from __future__ import annotations

import decimal
import json
import tomllib
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import MachineFileError
from nczones.machine import parse_machine

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "specs" / "machines").glob("*.toml"))

ODD_VALUES = ["[]", "{}", '"x"', "true", "-1", "0", '"nan"', "[[]]", '[""]', "1e400", '["X", "X"]', '{ Q = "1" }']


def toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, (int, decimal.Decimal)):
        return str(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return "{ " + ", ".join(f"{json.dumps(k)} = {toml_value(x)}" for k, x in v.items()) + " }"


def leaves(v, path=()):
    yield path
    if isinstance(v, dict):
        for k, x in v.items():
            yield from leaves(x, path + (k,))
    elif isinstance(v, list):
        for i, x in enumerate(v):
            yield from leaves(x, path + (i,))


def replaced(v, path, new):
    if not path:
        return new
    v = dict(v) if isinstance(v, dict) else list(v)
    v[path[0]] = replaced(v[path[0]], path[1:], new)
    return v


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_mutations_never_crash(path):
    data = tomllib.loads(path.read_text(encoding="utf-8"), parse_float=decimal.Decimal)
    # the inline rewrite of the example is itself valid
    parse_machine("\n".join(f"{k} = {toml_value(x)}" for k, x in data.items()))
    tried = 0
    for where in list(leaves(data))[1:]:
        for odd in ODD_VALUES:
            new = tomllib.loads(f"v = {odd}", parse_float=decimal.Decimal)["v"]
            doc = replaced(data, where, new)
            text = "\n".join(f"{json.dumps(k)} = {toml_value(x)}" for k, x in doc.items())
            tried += 1
            try:
                parse_machine(text, "m.toml")
            except MachineFileError as exc:
                for d in exc.diagnostics:
                    assert d.code.startswith("ZN") and d.message
                    assert d.location().startswith("m.toml")
    assert tried > 100


@given(st.text())
@settings(max_examples=200, deadline=None)
def test_a_string_as_written_is_its_json_text(text):
    # issue 36 (startup36d): machine.py quotes strings (zone labels, values in messages) without importing json;
    # the quoting must stay json.dumps(text, ensure_ascii=False), which it was before
    from nczones.machine import as_written

    assert as_written(text) == json.dumps(text, ensure_ascii=False)
