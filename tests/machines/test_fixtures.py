"""The shared test machines (tests/machines/*.toml) stay few and honest: each parses as a machine, each is
used by a test, no two are the same machine, and ``machine_text``'s ``set`` changes exactly what it names."""

from __future__ import annotations

import itertools
import subprocess
import tomllib
from pathlib import Path

import pytest

from nczones.machine import parse_machine
from tests.machines import HERE, load_machine, machine_path, machine_text, names

TESTS = HERE.parent


@pytest.mark.parametrize("name", names())
def test_each_machine_parses(name):
    parse_machine(machine_text(name), str(machine_path(name)))


def test_each_machine_is_used_by_a_test():
    sources = "\n".join(p.read_text(encoding="utf-8") for p in TESTS.rglob("*.py") if p.parent != HERE)
    sources += "\n".join(p.read_text(encoding="utf-8") for p in TESTS.rglob("conftest.py"))
    unused = [n for n in names() if f'"{n}"' not in sources]
    assert not unused, f"machines no test names: {unused} (delete them)"


def test_no_two_files_are_the_same_machine():
    parsed = {n: tomllib.loads(machine_text(n)) for n in names()}
    same = [(a, b) for a, b in itertools.combinations(parsed, 2) if parsed[a] == parsed[b]]
    assert not same, f"the same machine twice: {same}"


def test_set_replaces_or_adds_one_value_and_extra_appends():
    base = tomllib.loads(machine_text("mill_xyz"))
    changed = tomllib.loads(machine_text(
        "mill_xyz", set={"machine.pulse": "0.0001", "machine.dialect": "fanuc", "machine.rapid.Y": "7"},
        extra='[tool_lengths]\nH1 = "10"\n'))
    expected = {**base, "machine": {**base["machine"], "pulse": "0.0001", "dialect": "fanuc",
                                    "rapid": {**base["machine"]["rapid"], "Y": "7"}},
                "tool_lengths": {"H1": "10"}}
    assert changed == expected
    with pytest.raises(KeyError):
        machine_text("mill_xyz", set={"offsets.G54": {"X": "1"}})  # no [offsets] table: extra= adds one
    with pytest.raises(FileNotFoundError):
        machine_path("no such machine")


def test_load_machine_and_the_conftest_fixture(machine_file):
    assert [axis.name for axis in load_machine("mill_xyz").axes] == ["X", "Y", "Z"]
    path = machine_file("mill_xyz", set={"machine.pulse": "0.01"})
    assert isinstance(path, Path) and tomllib.loads(path.read_text())["machine"]["pulse"] == "0.01"


def test_no_inline_machine_copies_come_back():
    """A new test names a machine of this folder (or builds a variant with ``set``/``extra``) instead of
    writing a whole machine inline; the files that still write one are templates or invalid on purpose."""
    tracked = subprocess.run(["git", "ls-files", "tests"], cwd=TESTS.parent, capture_output=True, text=True)
    files = [TESTS.parent / f for f in tracked.stdout.split() if f.endswith(".py")] or list(TESTS.rglob("*.py"))
    inline = []
    for path in files:
        text = path.read_text(encoding="utf-8")
        inline += [f"{path.relative_to(TESTS.parent)}:{i + 1}" for i, line in enumerate(text.splitlines())
                   if line.strip().strip("'\"").startswith("[machine.rapid]")]
    assert len(inline) <= INLINE_TEMPLATES, "\n".join(inline)


#: machine texts still written in test files: templates with {placeholders} (tests/controller/helpers.py,
#: tests/prover/test_blending.py, test_segment_batches.py ...), invalid machines of error tests, generated machines
#: (tests/oracles/rs274.py).  The number only goes down: 23 when the fixtures came, 32 after parallel branches
#: wrote 9 more, 20 since those 9 and 3 older copies (the polar turning centre, the spiral's XY machine, the
#: solids' machine head) became files here.
INLINE_TEMPLATES = 20
