"""Behaviour snapshots: the verdict, witnesses and JSON report of every bundled example and corpus program.

Issue 34 (one engine with named seams) redesigns the engine with behaviour unchanged; this script is how that
is checked.  ``run`` writes one JSON line per program (exit status and the JSON report with its timings and
profile removed); ``diff`` compares two snapshots taken on two checkouts and prints every difference, split
into verdict/witness differences (which must be explained) and statistics-only ones (how many motions a tier
decided, which may move when a tier is reorganised)::

    cd OLD && PYTHONPATH=$PWD python -m tests.tools.snapshot run --out /tmp/old.jsonl
    cd NEW && PYTHONPATH=$PWD python -m tests.tools.snapshot run --out /tmp/new.jsonl
    python -m tests.tools.snapshot diff /tmp/old.jsonl /tmp/new.jsonl

``--only examples`` restricts a run to the bundled examples (seconds); the corpus takes about half an hour of
CPU.  To compare with a checkout that predates this script, run this file from the new checkout with the old
one first on ``PYTHONPATH``: it imports only ``nczones.cli`` and the test helpers that both have.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import sys
import tempfile
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "specs" / "examples" / "examples.toml"

#: Report keys that measure the run, not its meaning.
VOLATILE = ("timings", "profile", "program", "file")


def _clean(value):
    """The report without run measurements and paths (the checkout's location must not matter)."""
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items() if k not in VOLATILE}
    if isinstance(value, list):
        return [_clean(v) for v in value]
    if isinstance(value, str):
        return value.replace(str(ROOT), "<checkout>")
    return value


def _verify(program: Path, machine: Path, extra: list[str]) -> dict:
    """Exit status and cleaned JSON report of ``nczones verify`` run in process."""
    from nczones.cli import main

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "report.json"
        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            code = main(["verify", str(program), "--machine", str(machine), "--budget", "10",
                         "--format", "json", "--output", str(out), *extra])
        report = json.loads(out.read_text(encoding="utf-8")) if out.exists() and out.stat().st_size else None
    errors = [line.replace(str(ROOT), "<checkout>") for line in err.getvalue().splitlines() if "error" in line][:3]
    return {"exit": code, "report": _clean(report), "errors": errors}


def _example_jobs() -> list[tuple[str, Path, Path, list[str]]]:
    jobs = []
    for ex in tomllib.loads(EXAMPLES.read_text(encoding="utf-8"))["example"]:
        extra: list[str] = []
        if "margin" in ex:
            extra += ["--margin", str(ex["margin"])]
        for p in ex.get("params", []):
            extra += ["--param", p]
        if ex.get("recovery"):
            extra += ["--recovery", str(ex["recovery"])]
        jobs.append((f"example: {ex['name']}", EXAMPLES.parent / ex["program"],
                     EXAMPLES.parent / ex["machine"], extra))
    return jobs


def _corpus_jobs(folder: Path) -> list[tuple[str, Path, Path, list[str]]]:
    from tests.corpus import CORPUS
    from tests.corpus_verify import LINUXCNC_MACHINE, fanuc_programs, linuxcnc_programs
    from tests.gcode.fanuc.test_corpus import fanuc_machine_file

    lcnc = folder / "linuxcnc.toml"
    lcnc.write_text(LINUXCNC_MACHINE, encoding="utf-8")
    jobs = [(f"corpus: {rel}", CORPUS / rel, lcnc, []) for rel in linuxcnc_programs()]
    jobs += [(f"corpus: {rel}", CORPUS / rel, fanuc_machine_file(rel, folder), []) for rel, _family in
             fanuc_programs()]
    return jobs


def run(out: Path, only: str) -> int:
    folder = Path(tempfile.mkdtemp())
    jobs = _example_jobs() if only in ("examples", "all") else []
    if only in ("corpus", "all"):
        jobs += _corpus_jobs(folder)
    with out.open("w", encoding="utf-8") as f:
        for i, (name, program, machine, extra) in enumerate(jobs, 1):
            row = {"name": name, **_verify(program, machine, extra)}
            f.write(json.dumps(row, sort_keys=True) + "\n")
            f.flush()
            print(f"{i}/{len(jobs)} {row['exit']} {name}", file=sys.stderr, flush=True)
    return 0


def _load(path: Path) -> dict[str, dict]:
    return {row["name"]: row for row in map(json.loads, path.read_text(encoding="utf-8").splitlines())}


def _split(row: dict) -> tuple[dict, dict]:
    """(meaning, statistics) of one snapshot row."""
    report = dict(row.get("report") or {})
    stats = report.pop("stats", None)
    return {"exit": row["exit"], "errors": row["errors"], "report": report}, {"stats": stats}


def _renamed(rows: dict[str, dict], renames: list[str]) -> dict[str, dict]:
    """``rows`` with every ``NEW`` of ``OLD=NEW`` written back as ``OLD`` (an intended, explained rename)."""
    if not renames:
        return rows
    text = json.dumps(rows)
    for pair in renames:
        before, after = pair.split("=", 1)
        text = text.replace(after, before)
    return json.loads(text)


def _without(value, keys: set[str]):
    """``value`` without the report fields ``keys`` (fields a change added on purpose)."""
    if isinstance(value, dict):
        return {k: _without(v, keys) for k, v in value.items() if k not in keys}
    if isinstance(value, list):
        return [_without(v, keys) for v in value]
    return value


def diff(old_path: Path, new_path: Path, renames: list[str] | None = None, ignore: list[str] | None = None) -> int:
    """Print every difference; exit 1 when a verdict, witness or report field differs, else 0.

    ``ignore`` names report fields left out on both sides; ``renames`` (``OLD=NEW``, e.g. an error code split in two) are undone in the new snapshot first."""
    old, new = _load(old_path), _renamed(_load(new_path), renames or [])
    if ignore:
        old, new = _without(old, set(ignore)), _without(new, set(ignore))
    meaning = stats_only = 0
    for name in sorted(set(old) | set(new)):
        if name not in old or name not in new:
            print(f"ONLY IN {'new' if name in new else 'old'}: {name}")
            meaning += 1
            continue
        (m_old, s_old), (m_new, s_new) = _split(old[name]), _split(new[name])
        if m_old != m_new:
            meaning += 1
            print(f"DIFFERS: {name}\n  old: {json.dumps(m_old, sort_keys=True)[:600]}\n"
                  f"  new: {json.dumps(m_new, sort_keys=True)[:600]}")
        elif s_old != s_new:
            stats_only += 1
            print(f"stats only: {name}: {s_old['stats']} -> {s_new['stats']}")
    print(f"# {len(old)} old, {len(new)} new; {meaning} differ in meaning, {stats_only} in statistics only")
    return 1 if meaning else 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.tools.snapshot", description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run")
    r.add_argument("--out", type=Path, required=True)
    r.add_argument("--only", choices=("examples", "corpus", "all"), default="all")
    d = sub.add_parser("diff")
    d.add_argument("old", type=Path)
    d.add_argument("new", type=Path)
    d.add_argument("--rename", action="append", default=[], metavar="OLD=NEW",
                   help="an intended rename (an error code) undone before comparing")
    d.add_argument("--ignore", action="append", default=[], metavar="FIELD",
                   help="a report field added on purpose, left out of both sides")
    args = parser.parse_args(argv)
    if args.command == "run":
        os.environ.setdefault("NCZONES_CORPUS", str(ROOT.parent / "shared" / "corpus"))
        return run(args.out, args.only)
    return diff(args.old, args.new, args.rename, args.ignore)


if __name__ == "__main__":
    sys.exit(main())
