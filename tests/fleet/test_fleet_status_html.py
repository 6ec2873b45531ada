"""The fleet status page (issue 37): totals per machine and per program, program paths without the folder they
all share (said once in the header), each cell linked to its job's HTML report."""

from __future__ import annotations

import re
from html.parser import HTMLParser

from fleet_helpers import check, small_library

from nczones.fleet.project import load_project
from nczones.fleet.status import write_status_html
from nczones.fleet.store import Store


def test_status_html_has_totals_and_short_program_names(tmp_path):
    project = small_library(tmp_path / "lib", programs=3, machines=2, moves=4)
    store_path = tmp_path / "s.sqlite"
    check(project, store_path)
    with Store(store_path, create=False) as store:
        run = store.latest_run()
        cells = store.cells(run.run_id)
        page = tmp_path / "site" / "index.html"
        write_status_html(run, cells, store, page, "t")
    html = page.read_text()
    # every program lives in programs/ (relative to the project file): said once, rows show the file name
    assert "program (in programs/)" in html
    names = re.findall(r'<td class="p" title="([^"]+)">([^<]+)</td>', html)
    assert names and all(full == f"programs/{short}" and "/" not in short for full, short in names)
    # totals, counted here from the store's cells (worst first: X before .)
    sym = {"safe": ".", "unsafe": "X", "unknown": "?", "error": "E"}

    def totals(cs):
        order = ["unsafe", "error", "unknown", "safe"]
        vs = [c.verdict for c in cs]
        return ", ".join(f"{vs.count(v)} {sym[v]}" for v in order if vs.count(v))

    rows = re.findall(r"<tr>(.*?)</tr>", html)
    for full, _short in names:
        row = next(r for r in rows if f'title="{full}"' in r)
        assert row.endswith(f'<td class="total">{totals([c for c in cells if c.program == full])}</td>')
    last = re.search(r'<tr class="totals">(.*?)</tr>', html).group(1)
    machines = sorted({c.machine for c in cells})
    expected = [totals([c for c in cells if c.machine == m]) for m in machines] + [totals(cells)]
    assert re.findall(r'<td class="total">([^<]*)</td>', last) == expected
    assert "X" in expected[-1]  # the generated library has an unsafe program


class _Anchors(HTMLParser):
    """Each matrix cell (a td with a verdict class) and the links in it, from the page's data."""

    def __init__(self) -> None:
        super().__init__()
        self.cells: list[dict] = []
        self._cell: dict | None = None
        self._link: str | None = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "td" and a.get("class") in ("safe", "unsafe", "unknown", "error", "pending"):
            self._cell = {"class": a["class"], "title": a.get("title", ""), "links": {}}
            self.cells.append(self._cell)
        elif tag == "a" and self._cell is not None:
            self._link = a.get("href")

    def handle_data(self, data):
        if self._link is not None and self._cell is not None:
            self._cell["links"][data.strip()] = self._link

    def handle_endtag(self, tag):
        if tag == "a":
            self._link = None
        elif tag == "td":
            self._cell = None


def test_status_html_cells_link_to_html_reports(tmp_path):
    """Each cell's verdict symbol links to its job's HTML report, made on demand beside the page; the report
    is the job's (its verdict, its violations' lines); a second status keeps the pages; ``not-safe`` makes
    pages only for the cells that are not safe; a changed program gets no page (its job is not today's)."""
    project_file = small_library(tmp_path / "lib", programs=2, machines=1, moves=3)  # part_000 is unsafe
    store_path = tmp_path / "s.sqlite"
    check(project_file, store_path)
    project = load_project(project_file)
    with Store(store_path, create=False) as store:
        run = store.latest_run()
        cells = store.cells(run.run_id)
        page = tmp_path / "site" / "index.html"
        written = write_status_html(run, cells, store, page, "t", project=project)
        again = write_status_html(run, cells, store, page, "t", project=project)
    parsed = _Anchors()
    parsed.feed(page.read_text())
    by_key = {c.job_key: c for c in cells}
    assert len(parsed.cells) == len(cells)
    symbol = {"safe": ".", "unsafe": "X", "unknown": "?"}
    for cell in parsed.cells:
        href = cell["links"][symbol[cell["class"]]]
        key = href.removeprefix("reports/").removesuffix(".html")
        assert href == f"reports/{key}.html" and cell["links"]["t"] == f"reports/{key}.txt"
        assert cell["links"]["j"] == f"reports/{key}.json"
        report = (page.parent / href).read_text()
        stored = by_key[key]
        assert f'data-verdict="{stored.verdict}"' in report  # the page of that job, not another's
        for v in stored.violations:
            assert f'href="#L{v["line"]}"' in report
    assert "X" in [symbol[c["class"]] for c in parsed.cells]  # the generated library has an unsafe program
    html_files = [p for p in written if p.suffix == ".html" and p != page]
    assert len(html_files) == len({c.job_key for c in cells})
    assert not [p for p in again if p.suffix == ".html" and p != page]  # kept, not made again

    # not-safe only, and a program edited since the run: no page for its cell, the title says why
    edited = next(c for c in cells if c.verdict == "unsafe")
    (project.root / edited.program).write_text((project.root / edited.program).read_text() + "(edited)\n")
    site = tmp_path / "site2" / "index.html"
    with Store(store_path, create=False) as store:
        written = write_status_html(run, cells, store, site, "t", project=project, html_reports="not-safe")
    parsed = _Anchors()
    parsed.feed(site.read_text())
    made = {p.stem for p in written if p.suffix == ".html" and p != site}
    expected = {c.job_key for c in cells if c.verdict != "safe" and c.program != edited.program}
    assert made == expected
    cell = next(c for c in parsed.cells if c["title"].startswith(f"{edited.program} on "))
    assert cell["links"]["X"].endswith(".txt") and "changed since this run" in cell["title"]
