"""Every reason code is in the ``XX123`` scheme (issue 38: ``unknown[@ ^]``, ``unknown[#5405]``).

The interpreters name what they do not model by the construct (``@ ^``, ``#5405``, ``G68``); the reason
then carries GC390 ("a construct nczones does not model") and its message starts with the construct, so
the text report reads ``unknown[GC390]: @ ^: ...`` and JSON/SARIF consumers can key on a stable code.
"""

from __future__ import annotations

import json
import re

import pytest

from nczones import load_machine
from nczones.prover import verify_text
from nczones.report import render_report

SCHEME = re.compile(r"[A-Z]{2}\d{3}")

CASES = [
    # LinuxCNC polar words in a G91 canned cycle with L2: the angle turns on every repeat (not modelled).
    ("linuxcnc", "G17 G21 G90\nG0 X0 Y0 Z10\nG91 G81 @5 ^30 R-1 Z-2 L2 F100\nG80\nM2\n", "@ ^"),
    # A Haas tool-life timer read in Fanuc Macro B (specs/fanuc.md lists #5405 as not modelled).
    ("fanuc", "G17 G21 G90\nG0 X0 Y0 Z10\n#1=#5405\nM30\n", "#5405"),
]


@pytest.mark.parametrize("dialect,program,construct", CASES)
def test_unknown_constructs_carry_a_scheme_code_and_stay_named(dialect, program, construct):
    machine = load_machine("specs/machines/fanuc_mill.toml")
    result = verify_text(program, machine, dialect=dialect)
    assert result.verdict.label == "unknown"
    assert all(SCHEME.fullmatch(r.code) for r in result.reasons), [r.code for r in result.reasons]
    assert result.reasons[0].code == "GC390" and result.reasons[0].message.startswith(construct + ": ")
    text = render_report(result, "text", deterministic=True)
    assert f"unknown[GC390]: {construct}: " in text and f"unknown[{construct}]" not in text
    doc = json.loads(render_report(result, "json", deterministic=True))
    assert [r["code"] for r in doc["reasons"]] == ["GC390"]
