"""The fleet status page (issue 37): totals per machine and per program, program paths without the folder they
all share (said once in the header)."""

from __future__ import annotations

import re

from fleet_helpers import check, small_library

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
