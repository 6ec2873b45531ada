"""Move the test files to the one layout of docs/design.md "Tests" (issue 34), and fix what refers to them.

Usage, from the repository root (a git checkout)::

    python -m tests.tools.relayout_tests            # move, rewrite references, print what it did
    python -m tests.tools.relayout_tests --dry-run  # print what it would do, change nothing

After merging a branch written against the old layout, merge with git's directory-rename detection off, so
that a file the branch added to an old folder stays there for this script to move (and fix); then run it::

    git -c merge.directoryRenames=false merge BRANCH && python -m tests.tools.relayout_tests

(with detection on, git itself moves such a file into the new folder, as a "file location" conflict, and
its ``parents[N]`` and relative imports are left unfixed).  Edits a branch made to a moved file follow the
rename either way.

The layout: a test folder is named after the nczones package or module it tests (tests/gcode/fanuc for
nczones/gcode/fanuc/, tests/polar for nczones/geometry/polar.py), except the named cross-cutting folders
(tests/packaging/test_layout.py lists them).  Today's feature folders are moved by FOLDER_RULES (every file
under the old folder, whatever its name: a branch merged later that adds a file to an old folder gets it
moved by the next run) and SPLIT_RULES (an old folder whose files go to several packages, by file name).

What a run does, in order:
1. moves every file (tracked: ``git mv``; untracked: a plain move) found under an old folder to its new
   path; an old folder's ``__init__.py`` goes to each new folder that has none (the suite imports these
   folders as packages), then the old folder is removed;
2. in each file it moved: ``Path(__file__)...parents[N]`` grows by how much deeper the file now is, and a
   relative import of a sibling that went to another folder becomes an absolute ``tests.`` import (then
   ``ruff check --fix --select I`` sorts the imports of the edited files, when ruff is installed);
3. in every text file of the repository (Python, Markdown, TOML, Makefile, CI scripts, notebooks; not the
   golden outputs, not this script): ``tests/OLD/...`` paths and ``tests.OLD.`` module names become the new
   ones (file by file for the split folders).

It is idempotent: once the old folders are gone a run moves nothing and rewrites nothing (the new names do
not contain the old ones).  It refuses to overwrite a file that already exists at a new path (it prints
the clash and leaves both files where they are).
"""

from __future__ import annotations

import argparse
import fnmatch
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

# old folder -> new folder: every file below the old folder keeps its path below the new one
FOLDER_RULES: dict[str, str] = {
    "tests/fanuc": "tests/gcode/fanuc",  # nczones/gcode/fanuc/
    "tests/turning": "tests/gcode/turning",  # nczones/gcode/turning.py, lathe.py, g7x.py
    "tests/cylindrical": "tests/gcode/cylindrical",  # nczones/gcode/cylindrical.py (+ nczones/geometry/cylinder.py)
    "tests/splines": "tests/gcode/linuxcnc/splines",  # nczones/gcode/linuxcnc/splines.py (+ geometry/nurbs.py)
    "tests/gcode/splines": "tests/gcode/linuxcnc/splines",  # (where the first layout put them)
    "tests/homing": "tests/plans/homing",  # nczones/plans/homing.py (+ the controller's and prover's homing)
    "tests/recovery": "tests/plans/recovery",  # nczones/plans/recovery.py (+ the controller's and prover's)
    "tests/polar": "tests/geometry/polar",  # nczones/geometry/polar.py (+ the G12.1 lanes)
}

# old folder -> [(file name pattern, new folder)], first match wins; SPLIT_DEFAULT if none matches
SPLIT_RULES: dict[str, list[tuple[str, str]]] = {
    "tests/foundation": [
        ("test_exact*.py", "tests/exact"),  # nczones/exact/
        ("test_machine_*.py", "tests/machine"),  # nczones/machine.py
        ("test_zone_*.py", "tests/zones"),  # nczones/zones/
        ("strategies.py", "tests/zones"),  # zone/point strategies, used by zones and exact tests
    ],
}
SPLIT_DEFAULT: dict[str, str] = {"tests/foundation": "tests/machine"}

TEXT_SUFFIXES = {".py", ".md", ".toml", ".txt", ".cfg", ".ini", ".yml", ".yaml", ".sh", ".ipynb", ".rst"}
TEXT_NAMES = {"Makefile", "run"}
SKIP_PREFIXES = ("tests/golden/", ".git/")
SELF = "tests/tools/relayout_tests.py"


def new_path(old: str) -> str | None:
    """The new repository-relative path of `old` (a path like tests/fanuc/helpers.py), None if it stays."""
    for folder, target in FOLDER_RULES.items():
        if old == folder or old.startswith(folder + "/"):
            return target + old[len(folder) :]
    for folder, rules in SPLIT_RULES.items():
        if old.startswith(folder + "/"):
            rest = old[len(folder) + 1 :]
            if "/" in rest:  # a subfolder of a split folder goes with the default
                return f"{SPLIT_DEFAULT[folder]}/{rest}"
            for pattern, target in rules:
                if fnmatch.fnmatch(rest, pattern):
                    return f"{target}/{rest}"
            return f"{SPLIT_DEFAULT[folder]}/{rest}"
    return None


def _old_folders() -> list[str]:
    return [*FOLDER_RULES, *SPLIT_RULES]


@dataclass
class Report:
    moved: list[tuple[str, str]] = field(default_factory=list)
    clashes: list[tuple[str, str]] = field(default_factory=list)
    edited: dict[str, list[str]] = field(default_factory=dict)

    def note(self, path: str, what: str) -> None:
        self.edited.setdefault(path, []).append(what)


def _git(root: Path, *args: str) -> str:
    return subprocess.run(["git", *args], cwd=root, check=True, capture_output=True, text=True).stdout


def _tracked(root: Path) -> set[str]:
    return set(_git(root, "ls-files").splitlines())


def _files_under(root: Path, folder: str) -> list[str]:
    base = root / folder
    if not base.is_dir():
        return []
    return sorted(
        p.relative_to(root).as_posix()
        for p in base.rglob("*")
        if p.is_file() and "__pycache__" not in p.parts and p.suffix != ".pyc"
    )


def _move(root: Path, old: str, new: str, tracked: set[str], dry: bool) -> None:
    if dry:
        return
    (root / new).parent.mkdir(parents=True, exist_ok=True)
    if old in tracked:
        _git(root, "mv", old, new)
    else:
        shutil.move(root / old, root / new)


def _plan(root: Path, report: Report) -> list[tuple[str, str]]:
    """(old, new) for every file to move; an old folder's __init__.py to each new folder lacking one."""
    plan: list[tuple[str, str]] = []
    for folder in _old_folders():
        files = _files_under(root, folder)
        init = f"{folder}/__init__.py"
        children = [f for f in files if f != init and Path(f).parent.as_posix() == folder]
        targets = sorted({Path(new_path(f) or f).parent.as_posix() for f in children})
        for old in files:
            if old != init:
                new = new_path(old)
                assert new is not None
                plan.append((old, new))
        if init in files:
            lacking = [t for t in targets if not (root / t / "__init__.py").exists()]
            for i, target in enumerate(lacking):
                plan.append((init if i == 0 else f"copy:{init}", f"{target}/__init__.py"))
            if not lacking:
                plan.append((init, "delete:"))
    clean: list[tuple[str, str]] = []
    for old, new in plan:
        if new != "delete:" and (root / new).exists():
            report.clashes.append((old, new))
        else:
            clean.append((old, new))
    return clean


def _depth(path: str) -> int:
    return path.count("/")


PARENTS = re.compile(r"(__file__\)(?:\.resolve\(\))?\.parents\[)(\d+)(\])")
REL_IMPORT = re.compile(r"^(\s*from )\.([A-Za-z_][A-Za-z_0-9]*)( import )", re.M)


def _fix_moved_file(root: Path, old: str, new: str, report: Report, dry: bool) -> None:
    """parents[N] by the change of depth; relative imports of siblings that went elsewhere → absolute."""
    if not new.endswith(".py"):
        return
    path = root / new if not dry else root / old
    text = path.read_text(encoding="utf-8")
    delta = _depth(new) - _depth(old)
    out = text
    if delta:
        out = PARENTS.sub(lambda m: f"{m.group(1)}{int(m.group(2)) + delta}{m.group(3)}", out)

    def absolute(m: re.Match[str]) -> str:
        sibling_old = f"{Path(old).parent.as_posix()}/{m.group(2)}.py"
        sibling_new = new_path(sibling_old) or sibling_old
        if Path(sibling_new).parent == Path(new).parent:
            return m.group(0)
        module = sibling_new[: -len(".py")].replace("/", ".")
        return f"{m.group(1)}{module}{m.group(3)}"

    out = REL_IMPORT.sub(absolute, out)
    if out != text:
        report.note(new, "parents[]/relative imports")
        if not dry:
            path.write_text(out, encoding="utf-8")


def _reference_rules(moves: list[tuple[str, str]]) -> list[tuple[re.Pattern[str], str]]:
    """Regexes from old paths/module names to new ones: whole folders, then each split folder's files."""
    end = r"(?![A-Za-z0-9_])"
    rules: list[tuple[re.Pattern[str], str]] = []
    split_files = {
        f"{folder}/{name}" for folder in SPLIT_RULES for name in _known_split_names(folder, moves)
    }
    for old in sorted(split_files, key=len, reverse=True):
        new = new_path(old)
        assert new is not None
        rules.append((re.compile(re.escape(old) + end), new))
        if old.endswith(".py"):
            rules.append((re.compile(re.escape(old[:-3].replace("/", ".")) + end), new[:-3].replace("/", ".")))
    for folder, target in FOLDER_RULES.items():
        rules.append((re.compile(re.escape(folder) + end), target))
        rules.append((re.compile(re.escape(folder.replace("/", ".")) + end), target.replace("/", ".")))
    return rules


def _known_split_names(folder: str, moves: list[tuple[str, str]]) -> set[str]:
    """File names of a split folder: those moved now and those the rules name (moved by an earlier run)."""
    names = {Path(old).name for old, _ in moves if old.startswith(folder + "/")}
    names |= {pattern for pattern, _ in SPLIT_RULES[folder] if not any(c in pattern for c in "*?[")}
    names |= set(SPLIT_MOVED_BEFORE.get(folder, ()))
    return names


# the files of split folders moved by the first run (so that a later run still rewrites references to them)
SPLIT_MOVED_BEFORE: dict[str, tuple[str, ...]] = {
    "tests/foundation": (
        "strategies.py",
        "test_exact.py",
        "test_exact_core.py",
        "test_machine_golden.py",
        "test_machine_robust.py",
        "test_machine_scale.py",
        "test_machine_schema.py",
        "test_zone_cases.py",
        "test_zone_properties.py",
    ),
}


def _text_files(root: Path) -> list[str]:
    files = _git(root, "ls-files", "--cached", "--others", "--exclude-standard").splitlines()
    return [
        f
        for f in files
        if not f.startswith(SKIP_PREFIXES)
        and f != SELF
        and (Path(f).suffix in TEXT_SUFFIXES or Path(f).name in TEXT_NAMES)
        and (root / f).is_file()
    ]


def _rewrite_references(root: Path, moves: list[tuple[str, str]], report: Report, dry: bool) -> None:
    rules = _reference_rules(moves)
    for rel in _text_files(root):
        path = root / rel
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        if "tests" not in text:
            continue
        out = text
        for pattern, repl in rules:
            out = pattern.sub(repl, out)
        bare = [f for f in SPLIT_RULES if re.search(re.escape(f) + r"(?![A-Za-z0-9_/.])", out)]
        for folder in bare:
            print(f"warning: {rel} names the split folder {folder} as a whole: rewrite it by hand")
        if out != text:
            report.note(rel, "references")
            if not dry:
                path.write_text(out, encoding="utf-8")


def _remove_empty(root: Path, dry: bool) -> None:
    if dry:
        return
    for folder in _old_folders():
        base = root / folder
        if not base.is_dir():
            continue
        for cache in sorted(base.rglob("__pycache__"), reverse=True):
            shutil.rmtree(cache, ignore_errors=True)
        for sub in sorted((p for p in base.rglob("*") if p.is_dir()), key=lambda p: len(p.parts), reverse=True):
            if not any(sub.iterdir()):
                sub.rmdir()
        if not any(base.iterdir()):
            base.rmdir()


def run(root: Path, dry: bool) -> Report:
    report = Report()
    tracked = _tracked(root)
    plan = _plan(root, report)
    plan.sort(key=lambda move: not move[0].startswith("copy:"))  # copy an __init__.py before moving it
    for old, new in plan:
        if new == "delete:":
            if not dry:
                _git(root, "rm", "-q", old) if old in tracked else (root / old).unlink()
        elif old.startswith("copy:"):
            if not dry:
                (root / new).parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(root / old[len("copy:") :], root / new)
                _git(root, "add", new)
        else:
            _move(root, old, new, tracked, dry)
        report.moved.append((old, new))
    moves = [(o, n) for o, n in plan if not o.startswith("copy:") and n != "delete:"]
    for old, new in moves:
        _fix_moved_file(root, old, new, report, dry)
    _rewrite_references(root, moves, report, dry)
    _remove_empty(root, dry)
    if not dry:
        _sort_imports(root, [p for p in report.edited if p.endswith(".py")])
    return report


def _sort_imports(root: Path, paths: list[str]) -> None:
    """An import made absolute may sit in the wrong isort block: let ruff sort the edited files' imports."""
    ruff = shutil.which("ruff") or str(Path(sys.executable).with_name("ruff"))
    if paths and Path(ruff).exists():
        subprocess.run([ruff, "check", "--fix", "--select", "I", "--quiet", *paths], cwd=root, check=False)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dry-run", action="store_true", help="print what would change, change nothing")
    parser.add_argument("--root", type=Path, default=None, help="repository root (default: git's top level)")
    args = parser.parse_args(argv)
    root = args.root or Path(_git(Path.cwd(), "rev-parse", "--show-toplevel").strip())
    report = run(root.resolve(), args.dry_run)
    verb = "would move" if args.dry_run else "moved"
    for old, new in report.moved:
        print(f"{verb} {old} -> {new}")
    for old, new in report.clashes:
        print(f"CLASH {old} -> {new}: {new} exists; left both in place", file=sys.stderr)
    for path, what in sorted(report.edited.items()):
        print(f"{'would edit' if args.dry_run else 'edited'} {path}: {', '.join(sorted(set(what)))}")
    print(f"{len(report.moved)} files {verb}, {len(report.edited)} files edited, {len(report.clashes)} clashes")
    return 1 if report.clashes else 0


if __name__ == "__main__":
    sys.exit(main())
