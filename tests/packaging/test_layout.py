"""The tests' layout (docs/design.md §11 "Tests"): every test folder is named after the nczones package or
module it tests, or is one of the named cross-cutting folders (issue 34)."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TESTS = ROOT / "tests"
PACKAGE = ROOT / "nczones"

#: the cross-cutting folders of docs/design.md §11, each with why it is not a package's
EXCEPTIONS = {
    "contract": "prover against the reference controller, generated and metamorphic programs",
    "oracles": "independent re-implementations the tests compare with",
    "golden": "expected outputs",
    "tools": "scripts of the test suite (rs274 differential, snapshot, complexity, relayout)",
    "packaging": "the package as a whole",
    "notebooks": "the notebooks of notebooks/",
    "machines": "the shared test machines",
    "bench": "the benchmark scripts of bench/ (outside the package)",
}


def _has_tests(folder: Path) -> bool:
    return any(folder.glob("test_*.py"))


def _maps_to_package(parts: tuple[str, ...]) -> bool:
    """tests/a/b ↔ nczones/a/b/ (a package) or nczones/a/b.py (a module)."""
    target = PACKAGE.joinpath(*parts)
    return (target.is_dir() and (target / "__init__.py").is_file()) or target.with_suffix(".py").is_file()


def test_every_test_folder_maps_to_a_package_or_is_a_named_exception():
    wrong = []
    for folder in sorted(p for p in TESTS.rglob("*") if p.is_dir() and "__pycache__" not in p.parts):
        parts = folder.relative_to(TESTS).parts
        if parts[0] in EXCEPTIONS or not _has_tests(folder):
            continue  # a named exception, or a folder of data or helpers
        if not _maps_to_package(parts):
            wrong.append("tests/" + "/".join(parts))
    assert not wrong, (
        f"test folders that name no nczones package or module: {wrong}; put the tests where the code they "
        "test is (docs/design.md §11), or name the folder in EXCEPTIONS with why; a whole folder moves with "
        "a rule in tests/tools/relayout_tests.py"
    )


def test_root_test_files_name_a_root_module():
    wrong = [p.name for p in TESTS.glob("test_*.py") if not (PACKAGE / f"{p.stem[len('test_'):]}.py").is_file()]
    assert not wrong, f"tests/{wrong}: a root test file is test_<module>.py of a module nczones/<module>.py"


def test_the_exceptions_exist():
    assert [name for name in EXCEPTIONS if not (TESTS / name).is_dir()] == []


def test_relayout_has_nothing_left_to_move():
    """The old feature folders stay gone: a file added to one is moved by the relayout script."""
    from tests.tools.relayout_tests import FOLDER_RULES, SPLIT_RULES

    left = [old for old in (*FOLDER_RULES, *SPLIT_RULES) if any((ROOT / old).rglob("*.py"))]
    assert not left, f"{left}: run python -m tests.tools.relayout_tests"
