"""The numbers the README quotes are checked against what they count (issue 38: "57 vs 59 fleet cells",
"about 1,300 tests" when the suite had 2,392)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _quoted(pattern: str) -> int:
    found = re.findall(pattern, README)
    assert len(found) == 1, f"README: expected one match of {pattern!r}, found {found}"
    return int(found[0].replace(",", ""))


def test_fleet_cells_of_the_bundled_library():
    from nczones.fleet.project import load_project

    cells = load_project(ROOT / "specs/examples/library").cells()
    assert _quoted(r"example library \((\d+) cells") == len(cells)
    fleet = (ROOT / "specs/fleet.md").read_text(encoding="utf-8")
    pairs = re.findall(r"generated ones \((\d+) cells|bundled example library: (\d+) cells", fleet)
    quoted = {int(n) for pair in pairs for n in pair if n}
    assert quoted == {len(cells)}, f"specs/fleet.md quotes {sorted(quoted)} cells; the library has {len(cells)}"


def test_the_test_count(request):
    """The README's "about N tests" is within 10 % of what a full default run (``make test``) collects.

    Only a run of the whole default suite counts them (``pytest`` with no paths, ``-k`` or ``-m`` other than
    the default); any narrower run skips with that reason.
    """
    config = request.config
    full = not config.args or [Path(a).resolve() for a in config.args] == [
        (Path(config.rootpath) / p).resolve() for p in config.getini("testpaths")]
    narrowed = config.getoption("keyword") or config.getoption("markexpr") not in ("", "not long")
    if not full or narrowed:
        pytest.skip("the README's test count is checked only by a run of the whole default suite")
    collected = len(request.session.items)
    quoted = _quoted(r"about ([\d,]+)\s+tests")
    assert abs(quoted - collected) <= collected // 10, (
        f"README says about {quoted} tests; this run has {collected}: write about {round(collected, -2):,}")
