"""Metamorphic soundness of `safe` (issue 18; tests/contract/metamorphic.py says what each property is).

CI size: a few dozen examples per property (derandomized, tens of seconds in all);
``HYPOTHESIS_PROFILE=long`` runs 20,000 examples in all, randomized (specs/contract.md has the numbers).
The properties are plain functions so that test_metamorphic_teeth.py runs exactly these examples
against a broken interpreter.
"""

import os

from hypothesis import given, settings

from .metamorphic import (
    check_margins,
    check_ranges,
    check_state_reads,
    margin_cases,
    range_cases,
    read_cases,
)

#: Examples per property in the default (ci) profile, and in a long one (any profile of more than 100).
CI_EXAMPLES = {"ranges": 15, "margins": 12, "reads": 12}
LONG_EXAMPLES = {"ranges": 10_000, "margins": 5_000, "reads": 5_000}


def _chunk() -> dict[str, int]:
    """``NCZONES_METAMORPHIC_EXAMPLES="ranges=1000,margins=500"``: a long run in seeded chunks."""
    text = os.environ.get("NCZONES_METAMORPHIC_EXAMPLES", "")
    return {k.strip(): int(v) for k, v in (item.split("=") for item in text.split(",") if item.strip())}


def examples(name: str) -> int:
    chunk = _chunk()
    if name in chunk:
        return chunk[name]
    return LONG_EXAMPLES[name] if settings.default.max_examples > 100 else CI_EXAMPLES[name]


def ranges_property(case):
    machine, text, params = case
    check_ranges(machine, text, params)


def margins_property(case):
    machine, text, margin, shift = case
    check_margins(machine, text, margin, shift)


def reads_property(case):
    machine, text = case
    check_state_reads(machine, text)


test_a_range_verdict_holds_at_its_concrete_values = settings(max_examples=examples("ranges"))(
    given(range_cases())(ranges_property))
test_a_margin_is_clearance = settings(max_examples=examples("margins"))(given(margin_cases())(margins_property))
test_state_reads_verify_like_their_values = settings(max_examples=examples("reads"))(
    given(read_cases())(reads_property))
