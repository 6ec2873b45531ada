"""Golden tests of ``nczones import-machine``: configurations in, machine files and notes out.

Every configuration is imported from its own folder (so paths in the output
are the file names), without ``-o``: the machine file on standard output must
equal ``<name>.toml`` and the notes on standard error ``<name>.out``; the
machine file must then pass ``nczones check-machine``.  Every file under a
``bad/`` folder must exit 2 with exactly ``<name>.err`` on standard error and
no traceback.

Sources: ``tests/golden/import/<kind>/`` holds configurations written for
these tests from the controls' documentation (each names its model in a
comment); the real configurations of the external corpus (``../shared/corpus``)
are imported in place and their goldens live in ``tests/golden/import/corpus/``.

Regenerate after a deliberate change (then review the diff by eye)::

    NCZONES_REGEN_GOLDEN=1 python -m pytest -q tests/imports/test_import_golden.py
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from nczones.cli import main
from tests.corpus import CORPUS

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden" / "import"
REGEN = os.environ.get("NCZONES_REGEN_GOLDEN") == "1"
SOURCES = {"linuxcnc": "*.ini", "grbl": "*.settings", "fanuc": "*.prm"}


def _cases(bad: bool) -> list[tuple[Path, str, tuple[str, ...], Path]]:
    out = []
    for kind, pattern in SOURCES.items():
        folder = GOLDEN / kind / ("bad" if bad else "")
        for src in sorted(folder.glob(pattern)):
            out.append((src.parent, src.name, (), src.with_suffix(".err" if bad else "")))
    return out


#: Real configurations from the corpus: (folder, file, extra arguments, golden stem).
_CORPUS_LINUXCNC = CORPUS / "linuxcnc" / "configs" / "sim" / "axis"
CORPUS_CASES = [
    (_CORPUS_LINUXCNC, "axis_mm.ini", (), "axis_mm"),
    (_CORPUS_LINUXCNC, "axis.ini", (), "axis"),
    (_CORPUS_LINUXCNC, "axis_9axis.ini", (), "axis_9axis"),
    (_CORPUS_LINUXCNC / "foam", "axis_foam.ini", (), "axis_foam"),
    (_CORPUS_LINUXCNC / "lathe-fanucy", "lathe-fanucy.ini", (), "lathe-fanucy"),
    (_CORPUS_LINUXCNC / "gantry", "gantry_mm.ini",
     ("--tool-table", str(GOLDEN / "linuxcnc" / "mill_mm.tbl")), "gantry_mm"),
    (CORPUS / "linuxcnc" / "tests" / "trajectory-planner" / "circular-arcs" / "configs", "XZ.ini", (), "tp_XZ"),
    (CORPUS / "grbl" / "test" / "settings", "kikigey89.settings", (), "kikigey89"),
    # issue 38: tool-table lines LinuxCNC skips (the pre-2.4 format; a symbolic link stored as a file) are
    # notes (IM204), not errors: LinuxCNC starts with these configurations, without those tools
    (_CORPUS_LINUXCNC / "gantry", "gantry_mm.ini", (), "gantry_mm_old_tool_table"),
    (_CORPUS_LINUXCNC, "lathe.ini", (), "lathe_stored_link"),
]


def _run(capsys, monkeypatch, folder: Path, name: str, extra: tuple[str, ...]) -> tuple[int, str, str]:
    monkeypatch.chdir(folder)
    code = main(["import-machine", name, *extra])
    out, err = capsys.readouterr()
    return code, out, err


def _compare(actual: str, expected: Path) -> None:
    # Paths into this checkout (an extra argument given absolute) are written
    # relative to it, so the goldens do not depend on where it lives.
    actual = actual.replace(str(ROOT) + os.sep, "<repo>/")
    if REGEN:
        expected.write_text(actual, encoding="utf-8")
    assert expected.exists(), f"no golden {expected}; run with NCZONES_REGEN_GOLDEN=1"
    assert actual == expected.read_text(encoding="utf-8")


def _check_machine(capsys, tmp_path: Path, text: str) -> None:
    target = tmp_path / "imported.toml"
    target.write_text(text, encoding="utf-8")
    code = main(["check-machine", str(target)])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert " is valid\n" in out


def _import_ok(capsys, monkeypatch, tmp_path, folder, name, extra, stem: Path) -> None:
    code, out, err = _run(capsys, monkeypatch, folder, name, extra)
    assert code == 0, err
    assert "Traceback" not in err
    _compare(out, stem.with_suffix(".toml"))
    _compare(err, stem.with_suffix(".out"))
    _check_machine(capsys, tmp_path, out)


OK = _cases(bad=False)
BAD = _cases(bad=True)


def test_enough_fixtures():
    kinds_ok = {p.parts[-1] for p, *_ in OK}
    assert kinds_ok >= {"linuxcnc", "grbl", "fanuc"}
    assert len(BAD) >= 20


@pytest.mark.parametrize("folder,name,extra,stem", OK, ids=[f"{p.name}/{n}" for p, n, *_ in OK])
def test_import(folder, name, extra, stem, capsys, monkeypatch, tmp_path):
    _import_ok(capsys, monkeypatch, tmp_path, folder, name, extra, stem)


@pytest.mark.parametrize("folder,name,extra,stem", BAD, ids=[f"{p.parent.name}/{n}" for p, n, *_ in BAD])
def test_import_refused(folder, name, extra, stem, capsys, monkeypatch):
    code, out, err = _run(capsys, monkeypatch, folder, name, extra)
    assert code == 2
    assert out == ""
    assert "Traceback" not in err and "internal error" not in err
    for line in err.splitlines():
        if not line.startswith(" "):
            assert "error[IM1" in line, line
    _compare(err, stem)


@pytest.mark.skipif(not CORPUS.is_dir(), reason="external corpus not present")
@pytest.mark.parametrize("folder,name,extra,stem", CORPUS_CASES, ids=[c[3] for c in CORPUS_CASES])
def test_import_corpus(folder, name, extra, stem, capsys, monkeypatch, tmp_path):
    _import_ok(capsys, monkeypatch, tmp_path, folder, name, extra, GOLDEN / "corpus" / stem)

