"""The list of what `safe` assumes: one list in code, the same in specs/contract.md, printed in HTML."""

import html
import re
from pathlib import Path

from nczones.machine import load_machine
from nczones.prover import verify
from nczones.prover.assumptions import SAFE_ASSUMPTIONS
from nczones.report.html import render_html

ROOT = Path(__file__).resolve().parents[2]


def _documented() -> list[str]:
    doc = (ROOT / "specs" / "contract.md").read_text(encoding="utf-8")
    section = doc.split("## What `safe` assumes", 1)[1].split("\n## ", 1)[0]
    items: list[str] = []
    for line in section.splitlines():
        if line.startswith("- "):
            items.append(line[2:])
        elif line.startswith("  ") and items:
            items[-1] += " " + line.strip()
    return items


def test_specs_and_code_list_the_same_assumptions():
    assert _documented() == list(SAFE_ASSUMPTIONS)


def test_the_html_report_prints_every_assumption():
    machine = load_machine(ROOT / "specs/machines/grinder.toml")
    program = str(ROOT / "specs/examples/programs/notch_over.ngc")
    page = render_html(verify(program, machine), machine, program)
    section = page.split('<section id="assumptions">', 1)[1].split("</section>", 1)[0]
    printed = [html.unescape(x) for x in re.findall(r"<li>(.*?)</li>", section)]
    assert printed == list(SAFE_ASSUMPTIONS)
