"""Metamorphic soundness of tool-break recovery (tests/contract/recovery_metamorphic.py says what each relation is).

CI size: a handful of examples per relation (derandomized, well under a minute in all);
``NCZONES_RECOVERY_EXAMPLES="base=500,ranges=500,..."`` with ``HYPOTHESIS_PROFILE=long`` runs seeded chunks
(specs/contract.md has the runs).
"""

import os

from hypothesis import given, settings

from .recovery_metamorphic import (
    check_recovery_controller,
    check_recovery_extends_base,
    check_recovery_margins,
    check_recovery_ranges,
    check_recovery_state_reads,
    recovery_base_cases,
    recovery_controller_cases,
    recovery_margin_cases,
    recovery_range_cases,
    recovery_read_cases,
)

#: Examples per relation in the default (ci) profile, and in a long one (any profile of more than 100).
CI_EXAMPLES = {"base": 6, "ranges": 4, "margins": 6, "reads": 4, "controller": 8}
LONG_EXAMPLES = {"base": 1_000, "ranges": 2_000, "margins": 1_000, "reads": 500, "controller": 1_000}


def _chunk() -> dict[str, int]:
    text = os.environ.get("NCZONES_RECOVERY_EXAMPLES", "")
    return {k.strip(): int(v) for k, v in (item.split("=") for item in text.split(",") if item.strip())}


def examples(name: str) -> int:
    chunk = _chunk()
    if name in chunk:
        return chunk[name]
    return LONG_EXAMPLES[name] if settings.default.max_examples > 100 else CI_EXAMPLES[name]


def base_property(case):
    check_recovery_extends_base(*case)


def ranges_property(case):
    check_recovery_ranges(*case)


def margins_property(case):
    check_recovery_margins(*case)


def reads_property(case):
    check_recovery_state_reads(*case)


def controller_property(case):
    check_recovery_controller(*case)


test_recovery_extends_the_base_proof = settings(max_examples=examples("base"))(
    given(recovery_base_cases())(base_property))
test_recovery_over_ranges_holds_at_its_concrete_values = settings(max_examples=examples("ranges"))(
    given(recovery_range_cases())(ranges_property))
test_recovery_margin_is_clearance = settings(max_examples=examples("margins"))(
    given(recovery_margin_cases())(margins_property))
test_recovery_state_reads_verify_like_their_values = settings(max_examples=examples("reads"))(
    given(recovery_read_cases())(reads_property))
test_recovery_controller_is_the_independent_witness = settings(max_examples=examples("controller"))(
    given(recovery_controller_cases())(controller_property))
