"""The Fanuc/Haas corpus (``../shared/corpus/fanuc``, its README and MANIFEST.tsv) in the fanuc dialect.

Every program ends ``complete`` (a ``#3000`` alarm that stops it counts: everything it runs is known),
``unknown`` (a code named in specs/fanuc.md, a reason, a line) or ``rejected`` (a ``GcodeError`` with
``file:line:column``), never in a traceback; at least 70 % of the mill programs are complete.  Lathe
programs (issue 23 brings the lathe cycles) are read by the mill dialect too, for the no-traceback rule.
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest

from nczones.errors import GcodeError
from nczones.gcode import interpret
from nczones.machine import parse_machine
from tests.corpus import FANUC

pytestmark = [pytest.mark.corpus,
              pytest.mark.skipif(not (FANUC / "MANIFEST.tsv").is_file(), reason="fanuc corpus not available")]

ROOT = Path(__file__).resolve().parents[2]
_AXES = ["X", "Y", "Z", "A", "B", "C"]


def _machine(inch: bool):
    return parse_machine(
        '[machine]\ndialect = "fanuc"\naxes = ' + str(_AXES).replace("'", '"')
        + (f'\nmodal = ["{"G20" if inch else "G21"}"]\n')
        + "[machine.rapid]\n" + "\n".join(f'{a} = "30000"' for a in _AXES) + "\n"
        + "[machine.reference]\n" + "\n".join(f'{a} = "0"' for a in _AXES) + "\n"
        + "[tool_lengths]\n" + "\n".join(f'H{i} = "{100 + i}"' for i in range(100)) + "\n"
        + '[fanuc]\ng73_retract = "0.5"\ng83_clearance = "0.5"\nboring_shift = "+X"\n')


#: The Haas mills of ``hass-cnc-programs`` run in inches (the programs never say G20).
INCH = "hass-cnc-programs/CNC MILL/"


def rows() -> list[tuple[str, str]]:
    lines = (FANUC / "MANIFEST.tsv").read_text(encoding="utf-8").splitlines()[1:]
    return [(r.split("\t")[0], r.split("\t")[4]) for r in lines if r.strip()]


def run_all():
    outcomes = []
    for path, family in rows():
        m = _machine(path.startswith(INCH))
        try:
            run = interpret(FANUC / path, m)
            for _chunk in run:
                pass
            if run.unsupported:
                u = run.unsupported[0]
                outcomes.append((path, family, "unknown", u.code, f"{u.span.line}: {u.reason}"))
            else:
                alarm = run.alarm
                outcomes.append((path, family, "complete", "", f"alarm at line {alarm[2].line}" if alarm else ""))
        except GcodeError as e:
            d = e.diagnostics[0]
            assert d.span is not None and d.span.line >= 1, d
            outcomes.append((path, family, "rejected", d.code, d.render().splitlines()[0]))
    return outcomes


def listed_codes() -> tuple[set[str], list[tuple[int, int]], list[tuple[int, int]]]:
    """Codes specs/fanuc.md lists: single codes, and ranges of variables and of M codes."""
    text = (ROOT / "specs" / "fanuc.md").read_text(encoding="utf-8")
    singles = set(re.findall(r"`([GM]\d+(?:\.\d)?|#\d+|[A-Z][A-Za-z]+)`", text))
    singles |= set(re.findall(r"\b(G\d+(?:\.\d)?|M\d+)\b", text))
    singles |= set(re.findall(r"\*\*unknown\*\* `([^`]+)`", text))
    variables = [(int(a), int(b)) for a, b in re.findall(r"`#(\d+)`–`#(\d+)`", text)]
    mranges = [(int(a), int(b)) for a, b in re.findall(r"`M(\d+)`–`M(\d+)`", text)]
    return singles, variables, mranges


def _listed(code: str, singles, variables, mranges) -> bool:
    if code in singles:
        return True
    first = code.split()[0]
    if first in singles:
        return True
    m = re.fullmatch(r"#(\d+)", first)
    if m:
        n = int(m.group(1))
        return any(a <= n <= b for a, b in variables) or n >= 100000
    m = re.fullmatch(r"M(\d+)", first)
    if m:
        return any(a <= int(m.group(1)) <= b for a, b in mranges)
    return False


def test_fanuc_corpus_outcomes(capsys):
    t0 = time.perf_counter()
    outcomes = run_all()
    counts: dict[str, int] = {}
    for o in outcomes:
        counts[o[2]] = counts.get(o[2], 0) + 1
    mills = [o for o in outcomes if "mill" in o[1].lower()]
    complete = [o for o in mills if o[2] == "complete"]
    with capsys.disabled():
        print(f"\nfanuc corpus: {len(outcomes)} programs in {time.perf_counter() - t0:.1f}s, outcomes {counts}")
        print(f"mill programs interpreted fully: {len(complete)}/{len(mills)}")
        for o in outcomes:
            print(f"  {o[2]:9} {o[0]}: {o[3]} {o[4][:110]}")
    assert len(mills) >= 19
    assert len(complete) / len(mills) >= 0.70
    singles, variables, mranges = listed_codes()
    for o in outcomes:
        if o[2] == "unknown":
            assert _listed(o[3], singles, variables, mranges), f"{o[0]}: unknown code {o[3]!r} is not in specs/fanuc.md"
