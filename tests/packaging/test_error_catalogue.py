"""The one error catalogue (issue 34): every code the package uses is in ``nczones/error_codes.py`` once,
with its meaning, and ``specs/errors.md`` is generated from it.

The package source is scanned for code literals (``"GC101"``, ``'ZN148'``: two or three capital letters
and three digits in quotes); the specs and docs for code mentions.  Where a literal is the first argument of
a call whose kind is known (``self.error(...)``, ``self.unsupported(...)``, ``c.note(...)``), the kind must be
the catalogue's: an error code raised as a reason for ``unknown`` is a second meaning.  Each failure says what
to change where.
"""

from __future__ import annotations

import re
from collections import defaultdict
from pathlib import Path

import pytest

from nczones import error_codes as ec

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "nczones"
CATALOGUE_FILE = "nczones/error_codes.py"

#: A code literal in Python source: the code alone inside quotes.
_LITERAL = re.compile(r"""(["'])([A-Z]{2,3}\d{3})\1""")
#: A table row that defines a code in a spec: ``| ZN101 | meaning |`` (backticks allowed).
_ROW = re.compile(r"^\|\s*`?([A-Z]{2,3}\d{3})`?\s*\|\s*(.*?)\s*\|", re.M)

_REGEN = "then regenerate the page: python -m nczones.error_codes --write"

#: The call a code literal is the first argument of tells its kind (``self.error("GC201", ...)``,
#: ``self.unsupported("GC392", ...)``, ``c.note("IM201", ...)``); other sites are not classified.
_CALL = re.compile(r"([A-Za-z_][\w.]*)\(\s*$")
_CALL_KINDS = {
    **dict.fromkeys(("error", "Diagnostic", "fail", "_Fail", "_fail", "_usage", "_error", "_command_line_error",
                     "report"), "error"),
    **dict.fromkeys(("unsupported", "unknown", "Reason", "PassBound"), "unknown"),
    **dict.fromkeys(("note", "add"), "note"),
}


def _used() -> dict[str, list[str]]:
    """Every code literal in the package source (the catalogue itself excluded) -> its places."""
    out: dict[str, list[str]] = defaultdict(list)
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        if rel == CATALOGUE_FILE:
            continue
        for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            for m in _LITERAL.finditer(line):
                out[m.group(2)].append(f"{rel}:{lineno}")
    return out


def _raised_as() -> dict[str, dict[str, list[str]]]:
    """code -> kind -> places, for the literals that are the first argument of a call whose kind is known."""
    out: dict[str, dict[str, list[str]]] = defaultdict(lambda: defaultdict(list))
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        if rel == CATALOGUE_FILE:
            continue
        lines = path.read_text(encoding="utf-8").splitlines()
        for i, line in enumerate(lines):
            for m in _LITERAL.finditer(line):
                before = line[:m.start()] if line[:m.start()].strip() or not i else lines[i - 1]
                call = _CALL.search(before)
                name = call.group(1).rsplit(".", 1)[-1] if call else ""
                # the language layer's EvalError: GC39x is a reason for unknown (program.py), the rest errors
                kind = ("unknown" if m.group(2).startswith("GC39") else "error") if name == "EvalError" \
                    else _CALL_KINDS.get(name)
                if kind is not None:
                    out[m.group(2)][kind].append(f"{rel}:{i + 1}")
    return out


def _doc_files() -> list[Path]:
    files = sorted((ROOT / "specs").glob("*.md")) + sorted((ROOT / "docs").glob("*.md")) + [ROOT / "README.md"]
    return [p for p in files if p.relative_to(ROOT).as_posix() != ec.PAGE]


def _entry_hint(code: str, where: str) -> str:
    fam = ec.family_of(code)
    section = f"under its family {fam.prefix} {fam.first:03d}-{fam.last:03d} ({fam.title})" if fam else \
        "and add a Family for its prefix to FAMILIES"
    return (f'add  Code("{code}", "error", "<the spec that documents it, or empty>", "<its meaning, one line>"),  '
            f"to CATALOGUE in {CATALOGUE_FILE} {section} (kind: error, warning, note, unknown or rule; "
            f"see {where}); {_REGEN}")


def test_every_used_code_is_in_the_catalogue() -> None:
    known = ec.by_code()
    missing = {c: places for c, places in _used().items() if c not in known}
    assert not missing, "codes used in the package but not in the catalogue:\n" + "\n".join(
        f"  {c} (used at {', '.join(p[:3])}): {_entry_hint(c, p[0])}" for c, p in sorted(missing.items()))


def test_every_catalogued_code_is_used() -> None:
    used = _used()
    unused = [c.code for c in ec.CATALOGUE if c.status == "used" and c.code not in used]
    assert not unused, (f"codes in {CATALOGUE_FILE} that no package source uses: {', '.join(unused)}; remove "
                        f"them, or mark them status=\"reserved\" (not raised yet) or \"retired\" (never reuse); "
                        f"{_REGEN}")
    retired = [c.code for c in ec.CATALOGUE if c.status != "used" and c.code in used]
    assert not retired, (f"codes marked reserved or retired in {CATALOGUE_FILE} but used: {', '.join(retired)}; "
                         f"mark them status=\"used\" (a retired code must not come back: give a new one)")


def test_each_code_once_in_its_family_with_a_kind_and_a_meaning() -> None:
    seen: set[str] = set()
    for c in ec.CATALOGUE:
        assert c.code not in seen, f"{c.code} is listed twice in {CATALOGUE_FILE}: keep one entry, one meaning"
        seen.add(c.code)
        assert ec.family_of(c.code) is not None, f"{c.code}: no Family in FAMILIES holds it; add one"
        kinds = c.kind.split(" / ")
        assert all(k in ec.KINDS for k in kinds), f"{c.code}: kind {c.kind!r}; use one of {ec.KINDS}"
        assert c.status in ("used", "reserved", "retired"), f"{c.code}: status {c.status!r}"
        assert c.meaning and "\n" not in c.meaning, f"{c.code}: the meaning is one line"
        if len(kinds) > 1:
            assert c.code in ec.TWO_MEANINGS, (f"{c.code} is raised as {c.kind}: one code, two meanings; give "
                                               f"one of them a new code (or list it in TWO_MEANINGS, as a debt)")


def test_each_code_is_raised_as_its_kind_only() -> None:
    """An error code raised as a reason for unknown (or the reverse) is a second meaning: give it a new code."""
    known = ec.by_code()
    wrong = []
    for code, kinds in sorted(_raised_as().items()):
        allowed = set(known[code].kind.split(" / ")) if code in known else set()
        if "warning" in allowed:
            allowed.add("error")  # a machine-file warning is reported as its errors are, with a severity
        for kind, places in sorted(kinds.items()):
            if kind not in allowed:
                wrong.append(f"{code} ({known[code].kind if code in known else 'not catalogued'}) raised as "
                             f"{kind} at {', '.join(places[:3])}")
    assert not wrong, ("codes raised as another kind than the catalogue gives (one code, two meanings: give the "
                       "new use a new code in " + CATALOGUE_FILE + "):\n  " + "\n  ".join(wrong))


def test_codes_with_two_meanings_are_the_listed_debts_only() -> None:
    known = ec.by_code()
    for code in sorted(ec.TWO_MEANINGS):
        assert code in known, f"TWO_MEANINGS names {code}, which is not in the catalogue; remove it there"
        assert " also " in known[code].meaning, (
            f"{code} is in TWO_MEANINGS: its meaning must say both (\"...; also ...\"), or, when it was split, "
            f"remove it from TWO_MEANINGS")
    doubled = [c.code for c in ec.CATALOGUE if " also " in c.meaning and c.code not in ec.TWO_MEANINGS]
    assert not doubled, f"{doubled}: a meaning with \"also\" is a second meaning; list it in TWO_MEANINGS or split it"
    # VF105 meant both --library and --max-iterations (issue 34); --library is VF112 now
    assert "VF105" not in ec.TWO_MEANINGS and "library" not in known["VF105"].meaning
    assert "library" in known["VF112"].meaning


def test_the_page_is_current() -> None:
    page = ROOT / ec.PAGE
    assert page.exists() and page.read_text(encoding="utf-8") == ec.render_page(), (
        f"{ec.PAGE} is not what {CATALOGUE_FILE} generates: {_REGEN}")


def test_the_page_lists_every_code_once() -> None:
    rows = _ROW.findall(ec.render_page())
    codes = [code for code, _ in rows]
    assert sorted(codes) == sorted(c.code for c in ec.CATALOGUE)


def test_each_documented_in_file_names_its_code() -> None:
    wrong = []
    for c in ec.CATALOGUE:
        if not c.doc:
            continue
        path = ROOT / c.doc
        if not path.exists() or not re.search(rf"\b{c.code}\b", path.read_text(encoding="utf-8")):
            wrong.append(f"{c.code}: {c.doc}")
    assert not wrong, (f"the \"documented in\" file of these codes does not name them: {'; '.join(wrong)}; "
                       f"fix the doc field in {CATALOGUE_FILE} (or document the code there); {_REGEN}")


def test_the_docs_name_only_catalogued_codes() -> None:
    known = ec.by_code()
    prefixes = {f.prefix for f in ec.FAMILIES}
    stray = []
    for path in _doc_files():
        for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            for m in ec.CODE_PATTERN.finditer(line):
                if m.group(1) in prefixes and m.group(0) not in known:
                    stray.append(f"{path.relative_to(ROOT)}:{lineno}: {m.group(0)}")
    assert not stray, ("the docs name codes the catalogue does not have (a typo, or a code that is gone): "
                       + "; ".join(stray))


def test_no_code_is_defined_by_two_tables() -> None:
    """A spec's table row ``| CODE | meaning |`` defines a code; two such rows would be two meanings."""
    rows: dict[str, list[str]] = defaultdict(list)
    for path in _doc_files():
        for m in _ROW.finditer(path.read_text(encoding="utf-8")):
            rows[m.group(1)].append(f"{path.relative_to(ROOT)}: {m.group(2)[:60]!r}")
    twice = {c: where for c, where in rows.items() if len(where) > 1}
    assert not twice, ("codes defined by more than one table row (keep one, let the others refer to it):\n"
                       + "\n".join(f"  {c}: {' / '.join(w)}" for c, w in sorted(twice.items())))


def test_the_generator_writes_and_checks(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "specs").mkdir()
    assert ec.main(["--check"]) == 1
    assert ec.main(["--write"]) == 0
    assert (tmp_path / ec.PAGE).read_text(encoding="utf-8") == ec.render_page()
    assert ec.main(["--check"]) == 0
    assert ec.main(["--bogus"]) == 2
