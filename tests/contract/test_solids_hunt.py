"""Soundness hunt where features meet (task t7 "hunt", target 3): tool solids × a tool change mid-program ×
G43 H ranges and work-offset ranges × a fixture in a work offset × tool-break recovery legs.

The prover's verdict over a range is held against the independent sampled oracle of tests/oracles/solids.py
at concrete values of the range (its ends and middle): a range ``safe`` must be ``safe`` at every value, the
oracle must find no part of the tool in a fixture along the programmed path (the fixture in G54 placed by
the value) nor along the recovery legs from sampled break points (tool-change recovery, ``breakpoint``:
the shared plan nczones.plans.recovery.recovery_legs, as the controller moves them).  The programs are
tests/prover/test_solids.py's generator (lines and helical arcs around a jaw box and a post cylinder, tool
1 or 2) with the other tool changed in after a drawn motion, on tests/prover/test_solids_ranges.py's machine
(a polygon plate, a stop box in G54) with a tool-change position.  CI size ``SOLIDS_EXAMPLES["ci"]``.
"""

from __future__ import annotations

from fractions import Fraction
from unittest import mock

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode import segments_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.solids import machine_solids
from tests.oracles.concrete import machine_at
from tests.oracles.solids import sampled_hit
from tests.prover.test_solids import programs
from tests.prover.test_solids_ranges import RANGE_MACHINE, _fmt, _oracle, ranges

SOLIDS_EXAMPLES = {"ci": 2, "long": 5_000}
OUTCOMES: dict[tuple[str, str], int] = {}
TOOL_CHANGE = ('\n[tool_change]\nposition = { X = "-70", Y = "-70", Z = "150" }\nclearance = "140"\n'
               'approach_distance = "5"\napproach_feed = "200"\nvariant = "breakpoint"\n')


def _count(key: str, value: str) -> None:
    OUTCOMES[(key, value)] = OUTCOMES.get((key, value), 0) + 1


def _recovery_hit(text: str, machine, n: int = 4):
    """The oracle over break points ``k / n`` of every cutting line: its recovery legs against the fixtures."""
    from nczones.plans.recovery import recovery_legs, replacement_length, tool_change_config

    cfg = tool_change_config(machine, "breakpoint")
    solids = machine_solids(machine)
    fixtures = solids.fixtures
    for seg in segments_text(text, machine, fast=False):
        if seg.kind.name != "LINE" or seg.tool_register is None:
            continue
        for k in range(n + 1):
            p = tuple(a + Fraction(k, n) * (b - a) for a, b in zip(seg.start, seg.end))
            legs = recovery_legs(cfg, machine, p, p, seg.tool_length,
                                 replacement_length(cfg, machine, seg.tool_length))
            for leg in legs:
                hit = sampled_hit(leg.segment(machine.axis_names, seg), solids.parts_for(seg.tool_register),
                                  [f for f in fixtures if not getattr(f, "frame", "")], 16)
                if hit is not None:
                    return seg.line, leg.name, hit
    return None


def _with_change(text: str, at: int) -> str:
    """``text`` with the other tool changed in (T M6 G43 H) after its ``at``-th motion line."""
    lines = text.split("\n")
    tool = 2 if "T1 M6" in text else 1
    motions = [i for i, line in enumerate(lines) if line.startswith(("G1 ", "G2 ", "G3 "))]
    if not motions:
        return text
    i = motions[min(at, len(motions) - 1)]
    lines[i + 1:i + 1] = [f"T{tool} M6", f"G43 H{tool}", "G0 Z120"]
    return "\n".join(lines)


def _check(text: str, rng, recovery: bool) -> None:
    name, lo, hi = rng
    machine = parse_machine(RANGE_MACHINE + (TOOL_CHANGE if recovery else ""), "hunt.toml")
    extra = {"recovery": "breakpoint"} if recovery else {}
    r = verify_text(text, machine, params=[f"{name}={_fmt(lo)}..{_fmt(hi)}"], **extra)
    _count("range", r.verdict.label)
    if r.verdict.label != "safe":
        return
    for value in sorted({lo, hi, (lo + hi) / 2}):
        at = machine_at(machine, {name: value})
        concrete = verify_text(text, at, **extra)
        _count("value", concrete.verdict.label)
        assert concrete.verdict.label != "unsafe", f"safe over {name}={lo}..{hi}, unsafe at {value}:\n{text}"
        hit = _oracle(text, at, concrete)
        assert hit is None, f"safe over {name}={lo}..{hi}; at {value} the oracle finds {hit}:\n{text}"
        if recovery:
            leg = _recovery_hit(text, at)
            assert leg is None, f"safe over {name}={lo}..{hi} with recovery; at {value} a leg hits: {leg}\n{text}"


def _examples() -> int:
    return SOLIDS_EXAMPLES["long" if settings.default.max_examples > 100 else "ci"]


def test_solids_hunt():
    @settings(max_examples=_examples(), deadline=None)
    @given(programs(), ranges(), st.integers(0, 3), st.booleans(), st.booleans())
    def run(text, rng, at, change, recovery):
        _check(_with_change(text, at) if change else text, rng, recovery)

    run()


@pytest.mark.long
def test_solids_hunt_long():
    OUTCOMES.clear()
    with mock.patch.dict(SOLIDS_EXAMPLES, {"ci": SOLIDS_EXAMPLES["long"]}):
        test_solids_hunt()
    print(f"solids hunt: {sorted(OUTCOMES.items())}")
