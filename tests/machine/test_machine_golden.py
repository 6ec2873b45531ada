"""Golden tests of ``nczones check-machine``: malformed files and summaries.

Every ``tests/golden/machine/*.toml`` is a malformed machine file; running
``nczones check-machine tests/golden/machine/NAME.toml`` from the repository
root must exit 2 and print exactly ``NAME.expected`` on stderr, without a
traceback.  ``tests/golden/machine/ok/*.toml`` and the example machines must
exit 0 and print exactly their ``.expected`` summary on stdout.

Regenerate the golden files (then review the diff by eye!) with::

    NCZONES_REGEN_GOLDEN=1 python -m pytest -q tests/machine/test_machine_golden.py
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from nczones.cli import main
from nczones.machine import load_machine

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden" / "machine"
REGEN = os.environ.get("NCZONES_REGEN_GOLDEN") == "1"

BAD = sorted(GOLDEN.glob("*.toml"))
OK = sorted((GOLDEN / "ok").glob("*.toml"))
EXAMPLES = sorted((ROOT / "specs" / "machines").glob("*.toml"))


def _run(capsys, monkeypatch, path: Path) -> tuple[int, str, str]:
    monkeypatch.chdir(ROOT)
    code = main(["check-machine", path.relative_to(ROOT).as_posix()])
    out, err = capsys.readouterr()
    return code, out, err


def _compare(actual: str, expected_file: Path) -> None:
    if REGEN:
        expected_file.write_text(actual, encoding="utf-8")
    assert expected_file.exists(), f"no golden {expected_file}; run with NCZONES_REGEN_GOLDEN=1"
    assert actual == expected_file.read_text(encoding="utf-8")


def test_enough_malformed_files():
    assert len(BAD) >= 25


@pytest.mark.parametrize("path", BAD, ids=[p.stem for p in BAD])
def test_malformed_machine_file(path, capsys, monkeypatch):
    code, out, err = _run(capsys, monkeypatch, path)
    assert code == 2
    assert out == ""
    assert "Traceback" not in err and "internal error" not in err
    # every message names the file, and carries a ZN code
    for line in err.splitlines():
        if not line.startswith(" "):
            assert line.startswith(f"tests/golden/machine/{path.name}"), line
            assert "error[ZN" in line, line
    _compare(err, path.with_suffix(".expected"))


@pytest.mark.parametrize("path", OK + EXAMPLES, ids=[p.stem for p in OK + EXAMPLES])
def test_valid_machine_summary(path, capsys, monkeypatch):
    code, out, err = _run(capsys, monkeypatch, path)
    assert code == 0, err
    assert err == ""
    assert out.startswith(f"{path.relative_to(ROOT).as_posix()}: machine ")
    assert " is valid\n" in out
    if path.parent == GOLDEN / "ok" or path.stem == "grinder":
        _compare(out, GOLDEN / "ok" / f"{path.stem}.expected")


def test_reference_outside_is_a_warning_not_an_error():
    m = load_machine(GOLDEN / "ok" / "reference_outside_warning.toml")
    assert [w.code for w in m.warnings] == ["ZN131"]


def test_missing_file_exits_2_with_a_clear_message(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    code = main(["check-machine", "tests/golden/machine/no_such_machine.toml"])
    out, err = capsys.readouterr()
    assert code == 2
    assert out == ""
    assert "Traceback" not in err
    assert err == (
        "tests/golden/machine/no_such_machine.toml: error[ZN099]: "
        "cannot read the machine file: No such file or directory\n"
    )


def test_directory_instead_of_file_exits_2(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    code = main(["check-machine", "tests/golden/machine"])
    _, err = capsys.readouterr()
    assert code == 2
    assert err.startswith("tests/golden/machine: error[ZN099]: cannot read the machine file: ")
    assert "Traceback" not in err


def test_not_utf8_exits_2(tmp_path, capsys, monkeypatch):
    bad = tmp_path / "latin1.toml"
    bad.write_bytes('[machine]\nname = "Fräse"\n'.encode("latin-1"))
    code = main(["check-machine", str(bad)])
    _, err = capsys.readouterr()
    assert code == 2
    assert "error[ZN099]: the machine file is not UTF-8 text" in err
    assert "Traceback" not in err


def test_every_code_is_documented_and_has_a_golden():
    import re

    source = (ROOT / "nczones" / "machine.py").read_text(encoding="utf-8")
    doc = (ROOT / "specs" / "machine-file.md").read_text(encoding="utf-8")
    codes = set(re.findall(r'"(ZN\d{3})"', source))
    documented = set(re.findall(r"^\| (ZN\d{3}) \|", doc, re.M))
    assert codes == documented
    goldens = "".join(p.read_text(encoding="utf-8") for p in GOLDEN.rglob("*.expected"))
    assert {c for c in codes if c != "ZN099"} <= set(re.findall(r"\[(ZN\d{3})\]", goldens))
