"""``fleet status`` (the programs × machines matrix of the latest run) and ``fleet diff`` (what changed).

The matrix comes as text (one row per program, one column per machine,
``.`` safe, ``X`` unsafe, ``?`` unknown, ``E`` error, blank: the program
does not run on that machine, ``-`` not verified yet), as JSON
(:func:`status_json`) or as an HTML page (:func:`write_status_html`) whose
cells link to each job's HTML report (generated on demand, :func:`html_report`),
text and JSON report, written beside the page, with totals per program and
per machine.

A diff compares the cells of the latest run with those of the run before
(:func:`diff_runs`): newly unsafe first, then newly unknown or error, then
cells whose violations changed, fixed cells, and cells added or removed.
"""

from __future__ import annotations

import html
import json
import posixpath
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .store import CellRow, Run, Store

if TYPE_CHECKING:
    from .jobs import Job, JobPlan
    from .project import Project

__all__ = ["SYMBOLS", "status_text", "status_json", "write_status_html", "Change", "diff_runs", "diff_text",
           "diff_json", "html_report", "HTML_REPORTS"]

#: which cells ``fleet status --format html`` writes an HTML report for (``--html-reports``)
HTML_REPORTS = ("all", "not-safe", "none")

SYMBOLS = {"safe": ".", "unsafe": "X", "unknown": "?", "error": "E", None: "-"}
_RANK = {"unsafe": 0, "error": 1, "unknown": 2, "safe": 3, None: 4}


def _totals(cells: list[CellRow]) -> str:
    """``"1 X, 2 ."``: the cells counted by verdict symbol, worst first."""
    counts = _counts(cells)
    return ", ".join(f"{n} {SYMBOLS.get(v if v != 'pending' else None, '-')}"
                     for v, n in sorted(counts.items(), key=lambda x: _RANK.get(x[0], 5)))


def _verdict(c: CellRow) -> str | None:
    return None if c.status == "pending" else c.verdict


#: A finding in the text matrix is cut to about this many characters, at a word boundary.
FINDING_CHARS = 120


def cut_at_word(text: str, width: int = FINDING_CHARS) -> str:
    """``text`` cut to at most ``width`` characters at the last space before the limit, ``…`` marking the
    cut (a single word longer than ``width`` is cut inside it, as nothing else fits).

    >>> cut_at_word("the quick brown fox", 12), cut_at_word("short", 12), cut_at_word("abcdefghijklmnop", 8)
    ('the quick…', 'short', 'abcdefg…')
    """
    if len(text) <= width:
        return text
    head = text[:width]  # keeps width - 1 characters and the mark
    space = head.rfind(" ")
    cut = head[:space].rstrip(" ,;:") if space > 0 else head[:width - 1]
    return cut + "…"


def first_finding(c: CellRow) -> str:
    if c.violations:
        v = c.violations[0]
        return f"line {v.get('line')} ({v.get('zone')})"
    if c.reasons:
        r = c.reasons[0]
        loc = r.get("location")
        where = f"line {loc['line']}: " if isinstance(loc, dict) and loc.get("line") else ""
        return where + cut_at_word(str(r.get("message", "")).splitlines()[0])
    return cut_at_word(c.message.splitlines()[0]) if c.message else ""


def _matrix(cells: list[CellRow]) -> tuple[list[str], list[str], dict[tuple[str, str], CellRow]]:
    machines = sorted({c.machine for c in cells})
    programs = sorted({c.program for c in cells})
    return programs, machines, {(c.program, c.machine): c for c in cells}


def _counts(cells: list[CellRow]) -> dict[str, int]:
    out: dict[str, int] = {}
    for c in cells:
        v = _verdict(c) or "pending"
        out[v] = out.get(v, 0) + 1
    return out


def status_text(run: Run, cells: list[CellRow], *, details: bool = True) -> str:
    """The matrix as text, a legend, the counts, and one line per cell that is not safe."""
    programs, machines, grid = _matrix(cells)
    width = max([len(p) for p in programs] + [7])
    lines = []
    for i, m in enumerate(machines):
        lines.append(" " * (width + 2) + "| " * i + m)
    lines.append(" " * (width + 2) + "| " * len(machines))
    for p in programs:
        row = " ".join(SYMBOLS[_verdict(grid[(p, m)])] if (p, m) in grid else " " for m in machines)
        lines.append(f"{p:<{width}}  {row}")
    counts = _counts(cells)
    state = " (interrupted)" if run.interrupted else ""
    lines.append("")
    lines.append(f"run {run.run_id}{state}: {len(cells)} cells: "
                 + ", ".join(f"{n} {v}" for v, n in sorted(counts.items(), key=lambda x: _RANK.get(x[0], 5)))
                 + f"; {run.ran} jobs ran, {run.reused} reused")
    lines.append("legend: . safe, X unsafe, ? unknown, E error, - not verified, blank: not on that machine")
    if details:
        bad = sorted((c for c in cells if _verdict(c) not in ("safe",)),
                     key=lambda c: (_RANK.get(_verdict(c), 5), c.machine, c.program))
        for c in bad:
            lines.append(f"{c.program} on {c.machine}: {_verdict(c) or 'not verified'}"
                         + (f": {first_finding(c)}" if first_finding(c) else ""))
    return "\n".join(lines) + "\n"


def _cell_json(c: CellRow) -> dict[str, Any]:
    return {"program": c.program, "machine": c.machine, "verdict": _verdict(c), "status": c.status,
            "job_key": c.job_key, "violations": list(c.violations), "reasons": list(c.reasons),
            "message": c.message, "wall_s": c.wall_s}


def status_json(run: Run, cells: list[CellRow]) -> str:
    """The latest run's cells as JSON: ``{"run": {...}, "counts": {...}, "machines", "programs", "cells": [...]}``."""
    programs, machines, _ = _matrix(cells)
    doc = {
        "run": {"id": run.run_id, "started_at": run.started_at, "finished_at": run.finished_at,
                "executor": run.executor, "ran": run.ran, "reused": run.reused, "interrupted": run.interrupted},
        "counts": _counts(cells),
        "machines": machines,
        "programs": programs,
        "cells": [_cell_json(c) for c in cells],
    }
    return json.dumps(doc, indent=2, ensure_ascii=False) + "\n"


_CSS = """
body{font-family:system-ui,sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px;text-align:center;font-size:13px}
th.p,td.p{text-align:left;font-family:monospace}th.m{writing-mode:vertical-rl;transform:rotate(180deg)}
td.safe{background:#d8f5d0}td.unsafe{background:#f7c5c0;font-weight:bold}td.unknown{background:#fbe9a8}
td.error{background:#e0c8f0}td.pending{background:#eee}td.total{font-family:monospace;white-space:nowrap}a{color:inherit;text-decoration:none}
"""


def html_report(project: Project, plan: JobPlan, job: Job, verdict: str | None = None) -> tuple[str | None, str]:
    """The HTML report (:func:`nczones.report.render_report`) of a stored job, made on demand: the job is
    verified again with its settings in this process (the store keeps its text and JSON reports, not the
    Result the page draws).  Returns ``(page, "")``, or ``(None, why)`` when no page is made: the program
    or machine file changed since (its SHA-256 is not the job's), it cannot be read, or the verdict comes
    out other than ``verdict`` (the stored one; a budget or time limit hit differently)."""
    import dataclasses
    import os

    from ..errors import InputError
    from ..gcode.source import load_program
    from ..machine import parse_machine
    from ..prover import verify
    from ..report import render_report
    from .project import verify_kwargs

    try:
        source = load_program(project.root / job.program, job.program)
        file = project.machine(job.machine).file
        shown = file.relative_to(project.root).as_posix() if file.is_relative_to(project.root) else str(file)
        machine = parse_machine(plan.machine_text[job.machine], shown)
    except (InputError, OSError, KeyError, ValueError) as exc:
        return None, f"cannot read the job's files again: {exc}"
    if source.sha256 != job.program_sha256:
        return None, "the program changed since the run"
    machine = dataclasses.replace(machine, sha256=job.machine_sha256)
    if machine.subroutine_path:
        machine = dataclasses.replace(machine, subroutine_path=tuple(
            os.path.join(project.root, p) for p in machine.subroutine_path))
    try:
        result = verify(source, machine, **verify_kwargs(job.settings, project.root))
    except InputError as exc:
        return None, f"the job cannot be verified again: {exc.render()}"
    if verdict is not None and result.verdict.label != verdict:
        return None, f"verified again it is {result.verdict.label}, not {verdict} (a budget or time limit)"
    try:
        return render_report(result, "html", machine=machine, program=source), ""
    except InputError as exc:
        return None, f"the report cannot be drawn: {exc.render()}"


def write_status_html(run: Run, cells: list[CellRow], store: Store, path: str | Path, title: str, *,
                      project: Project | None = None, html_reports: str = "all") -> list[Path]:
    """Write the HTML matrix to ``path`` and each cell's reports to ``reports/KEY.html|txt|json`` beside it.

    Returns the files written (a kept ``KEY.html`` is not rewritten and not listed).  The page is
    self-contained (no network resources); a cell links to its HTML report (the verdict symbol), its text
    report (``t``) and JSON report (``j``); its title shows the first finding.

    HTML reports are made on demand (:func:`html_report`) for the cells ``html_reports`` selects
    (:data:`HTML_REPORTS`: ``all``, ``not-safe``, ``none``) when ``project`` is given and the cell's job is
    the one the project's files give today (same job key: same program and machine bytes, settings and
    nczones); a job's page is named by its key, so a page already beside the matrix is kept, not made
    again.  A cell without a page links its symbol to the text report and says why in its title.
    """
    path = Path(path)
    folder = path.parent / "reports"
    folder.mkdir(parents=True, exist_ok=True)
    written = [path]
    programs, machines, grid = _matrix(cells)
    for key in sorted({c.job_key for c in cells if c.job_key}):
        res = store.result(key)
        if res is None:
            continue
        for ext, text in (("txt", res["report_text"]), ("json", res["report_json"])):
            f = folder / f"{key}.{ext}"
            f.write_text(text, encoding="utf-8")
            written.append(f)
    pages, no_page = _html_pages(cells, project, html_reports, folder, written)
    e = html.escape
    # program paths are relative to the project file's folder; a folder they all share is said once, in the header
    dirs = [posixpath.dirname(p) for p in programs]
    common = posixpath.commonpath(dirs) if dirs and all(dirs) else ""
    rows = []
    for p in programs:
        shown = posixpath.relpath(p, common) if common else p
        tds = [f'<td class="p" title="{e(p)}">{e(shown)}</td>']
        for m in machines:
            c = grid.get((p, m))
            if c is None:
                tds.append("<td></td>")
                continue
            v = _verdict(c)
            cls = v or "pending"
            label = SYMBOLS[v]
            tip = f"{p} on {m}: {v or 'not verified'}" + (f": {first_finding(c)}" if first_finding(c) else "")
            if c.job_key and v is not None and c.status != "error":
                ref = f"reports/{c.job_key}"
                if c.job_key in pages:
                    main = f'<a class="html" href="{ref}.html">{label}</a> <a href="{ref}.txt">t</a>'
                else:
                    why = no_page.get(c.job_key, "")
                    tip += f" (no HTML report: {why})" if why else ""
                    main = f'<a href="{ref}.txt">{label}</a>'
                tds.append(f'<td class="{cls}" title="{e(tip)}">{main} <a href="{ref}.json">j</a></td>')
            else:
                tds.append(f'<td class="{cls}" title="{e(tip)}">{label}</td>')
        tds.append(f'<td class="total">{e(_totals([grid[(p, m)] for m in machines if (p, m) in grid]))}</td>')
        rows.append("<tr>" + "".join(tds) + "</tr>")
    rows.append('<tr class="totals"><th class="p">totals per machine</th>'
                + "".join(f'<td class="total">{e(_totals([grid[(p, m)] for p in programs if (p, m) in grid]))}</td>'
                          for m in machines) + f'<td class="total">{e(_totals(cells))}</td></tr>')
    counts = ", ".join(f"{n} {v}" for v, n in sorted(_counts(cells).items(), key=lambda x: _RANK.get(x[0], 5)))
    head = "".join(f'<th class="m">{e(m)}</th>' for m in machines)
    links = ("Each cell links to its HTML report (the symbol), its text report (t) and JSON report (j)." if pages
             else "Each cell links to its text report (and JSON: j).")
    page = (f"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{e(title)}</title>"
            f"<style>{_CSS}</style></head><body>\n<h1>{e(title)}</h1>\n"
            f"<p>run {run.run_id}{' (interrupted)' if run.interrupted else ''}: {len(cells)} cells: {e(counts)}; "
            f"{run.ran} jobs ran, {run.reused} reused. {links}</p>\n"
            f"<table><tr><th class=\"p\">program{e(f' (in {common}/)') if common else ''}</th>{head}"
            "<th>totals per program</th></tr>\n" + "\n".join(rows) + "\n</table>\n"
            "<p>. safe, X unsafe, ? unknown, E error, - not verified</p>\n</body></html>\n")
    path.write_text(page, encoding="utf-8")
    return written


def _html_pages(cells: list[CellRow], project: Project | None, which: str, folder: Path,
                written: list[Path]) -> tuple[set[str], dict[str, str]]:
    """Make (or keep) the HTML report of each selected cell's job: the keys that have a page beside the
    matrix, and why the others have none."""
    if which not in HTML_REPORTS:
        raise ValueError(f"html_reports must be one of {HTML_REPORTS}, not {which!r}")
    if project is None or which == "none":
        return set(), {}
    from .jobs import plan_jobs

    wanted = [c for c in cells if c.job_key and c.status != "error" and _verdict(c) not in (None, "error")
              and (which == "all" or _verdict(c) != "safe")]
    if not wanted:
        return set(), {}
    where = {(c.program, c.machine) for c in wanted}
    plan = plan_jobs(project, [c for c in project.cells() if (c.program, c.machine) in where])
    pages: set[str] = set()
    no_page: dict[str, str] = {}
    for c in wanted:
        key = c.job_key
        assert key is not None
        if key in pages or key in no_page:
            continue
        f = folder / f"{key}.html"
        if plan.cell_keys.get((c.program, c.machine)) != key:
            no_page[key] = ("the program, the machine file, the settings or nczones changed since this run "
                            "(run nczones fleet check)")
            continue
        if f.is_file():  # a job's page depends only on its key
            pages.add(key)
            continue
        page, why = html_report(project, plan, plan.jobs[key], _verdict(c))
        if page is None:
            no_page[key] = why
            continue
        f.write_text(page, encoding="utf-8")
        written.append(f)
        pages.add(key)
    return pages, no_page


@dataclass(frozen=True, slots=True)
class Change:
    """One cell that differs between two runs."""

    kind: str  # newly unsafe, newly unknown, newly error, violations changed, fixed, added, removed
    program: str
    machine: str
    before: str | None
    after: str | None
    detail: str


_ORDER = ("newly unsafe", "newly error", "newly unknown", "violations changed", "fixed", "added", "removed")


def _violation_key(c: CellRow) -> list[tuple[Any, ...]]:
    return [(v.get("line"), v.get("zone"), v.get("kind")) for v in c.violations]


def diff_runs(old: list[CellRow], new: list[CellRow]) -> list[Change]:
    """The cells that changed from run ``old`` to run ``new``, newly unsafe first (see the module docstring)."""
    before = {(c.program, c.machine): c for c in old}
    after = {(c.program, c.machine): c for c in new}
    changes = []
    for where in sorted(set(before) | set(after)):
        b, a = before.get(where), after.get(where)
        p, m = where
        if b is None and a is not None:
            changes.append(Change("added", p, m, None, _verdict(a), first_finding(a)))
            continue
        if a is None and b is not None:
            changes.append(Change("removed", p, m, _verdict(b), None, ""))
            continue
        assert a is not None and b is not None
        vb, va = _verdict(b), _verdict(a)
        if va is None or vb is None:
            if va != vb and va is not None:
                changes.append(Change("added", p, m, vb, va, first_finding(a)))
            continue
        if va != vb:
            kind = {"unsafe": "newly unsafe", "unknown": "newly unknown", "error": "newly error"}.get(va, "fixed")
            changes.append(Change(kind, p, m, vb, va, first_finding(a)))
        elif va == "unsafe" and _violation_key(a) != _violation_key(b):
            changes.append(Change("violations changed", p, m, vb, va, f"was {first_finding(b)}, now {first_finding(a)}"))
    changes.sort(key=lambda c: (_ORDER.index(c.kind), c.machine, c.program))
    return changes


def diff_text(old_run: Run, new_run: Run, changes: list[Change]) -> str:
    lines = [f"changes from run {old_run.run_id} to run {new_run.run_id}: "
             + (f"{len(changes)} cells" if changes else "none")]
    for c in changes:
        lines.append(f"{c.kind}: {c.program} on {c.machine}: {c.before or '-'} -> {c.after or '-'}"
                     + (f": {c.detail}" if c.detail else ""))
    return "\n".join(lines) + "\n"


def diff_json(old_run: Run, new_run: Run, changes: list[Change]) -> str:
    doc = {"from_run": old_run.run_id, "to_run": new_run.run_id,
           "changes": [{"kind": c.kind, "program": c.program, "machine": c.machine, "before": c.before,
                        "after": c.after, "detail": c.detail} for c in changes]}
    return json.dumps(doc, indent=2, ensure_ascii=False) + "\n"
