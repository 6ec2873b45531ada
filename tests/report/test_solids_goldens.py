"""Golden reports of the tool-solids examples (issue 39): holder_hits_vise (unsafe: the holder enters the vise)
and holder_clears_vise (safe, the holder 8.5 mm from the vise) on specs/machines/mill_solids.toml, as text,
JSON and HTML (the page without its drawings and scripts: the summary, the violations, the notes, the
listing), and the drawn tool at each contact (exact numbers).  ``NCZONES_UPDATE_GOLDENS=1`` rewrites them
(tests/golden/report/); the unsafe JSON report is also in specs/examples/reports/ (tests/report/test_replay.py)."""

from __future__ import annotations

import json
import re

import pytest

from nczones.prover.render import to_json_dict
from nczones.report.html import render_html
from nczones.report.numbers import resolution_of
from nczones.report.solids_view import contact_solids
from nczones.report.text import render_text

from .helpers import EX, ROOT, check_golden, run_example

CASES = [("unsafe_holder_hits_vise", "programs/holder_hits_vise.ngc"),
         ("safe_holder_clears_vise", "programs/holder_clears_vise.ngc")]


def _here(text: str) -> str:
    """Paths written relative to the repository (the machine file is loaded by its absolute path)."""
    return text.replace(f"{ROOT}/", "")


def _page_text(page: str) -> str:
    """The HTML page without its SVG drawings, scripts and styles (those are checked from their data)."""
    for tag in ("svg", "script", "style"):
        page = re.sub(rf"<{tag}\b.*?</{tag}>", f"<{tag}/>", page, flags=re.S)
    return page


@pytest.mark.parametrize("name, program", CASES, ids=[c[0] for c in CASES])
def test_solids_goldens(name, program):
    result, m = run_example(program, "mill_solids.toml")
    check_golden(f"{name}.txt", render_text(result, deterministic=True, resolution=resolution_of(m)))
    doc = to_json_dict(result, deterministic=True)
    check_golden(f"{name}.json", _here(json.dumps(doc, indent=2, ensure_ascii=False) + "\n"))
    page = render_html(result, m, str(EX / program), deterministic=True)
    check_golden(f"{name}.html", _here(_page_text(page)))
    # the drawings (checked from their data in tests/report/test_solids_view.py) are on the page: the clamp
    # (a [[fixtures]] cylinder no zone draws) always, the tool at the contact where the holder hits
    assert 'fixture-clamp"' in page
    assert ('contact-part-1"' in page and "tool part entering it" in page) == name.startswith("unsafe")
    drawn = [{"violation": i, "line": v.line, "fixture": fx.name,
              "parts": [{"name": s.name, "entering": hit, "centre": [str(c) for c in s.centre],
                         "radius": str(s.radius), "z": [str(s.z0), str(s.z1)]} for s, hit in parts]}
             for i, v, parts, fx in contact_solids(result)]
    check_golden(f"{name}.contacts.json", json.dumps(drawn, indent=2, ensure_ascii=False) + "\n")
    assert doc["verdict"] == ("unsafe" if name.startswith("unsafe") else "safe")


LATHE_CASES = [("unsafe_boring_bar_hits_chuck", "programs/boring_bar_hits_chuck.nc"),
               ("safe_boring_bar_clears_chuck", "programs/boring_bar_clears_chuck.nc")]


@pytest.mark.parametrize("name, program", LATHE_CASES, ids=[c[0] for c in LATHE_CASES])
def test_lathe_solids_goldens(name, program):
    """The lathe's boring bar against the chuck jaws (specs/machines/lathe_solids.toml) as text, JSON and HTML,
    and the turret parts and the fixture section drawn at each contact (X and Z spans, exact; checked against
    the witness in tests/report/test_lathe_solids_view.py)."""
    result, m = run_example(program, "lathe_solids.toml")
    check_golden(f"{name}.txt", render_text(result, deterministic=True, resolution=resolution_of(m)))
    doc = to_json_dict(result, deterministic=True)
    check_golden(f"{name}.json", _here(json.dumps(doc, indent=2, ensure_ascii=False) + "\n"))
    page = render_html(result, m, str(EX / program), deterministic=True)
    check_golden(f"{name}.html", _here(_page_text(page)))
    assert 'fixture-jaws"' in page and 'fixture-jaws-mirror"' in page
    assert ('contact-part-1"' in page and "tool part entering it" in page) == name.startswith("unsafe")

    def spans(s):
        return {a: [str(x) for x in s.span(a)] for a in "XZ"}

    drawn = [{"violation": i, "line": v.line, "fixture": {"name": fx.name, **spans(fx)},
              "parts": [{"name": s.name, "entering": hit, **spans(s)} for s, hit in parts]}
             for i, v, parts, fx in contact_solids(result)]
    check_golden(f"{name}.contacts.json", json.dumps(drawn, indent=2, ensure_ascii=False) + "\n")
    assert doc["verdict"] == ("unsafe" if name.startswith("unsafe") else "safe")
