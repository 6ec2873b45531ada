"""Issue 39: the tool-solids contract on lathes (turret tools, T0101 changes), fixture prisms and fixtures in a
work offset (G55, G10 L2 P2), prover and controller held to one verdict (tests/contract/solids_more.py;
specs/contract.md, "Tool solids: lathes, prisms and work offsets")."""

import os

import pytest
from hypothesis import given, settings

from .solids_more import check_lathe, check_mill, lathe_cases, mill_cases

LONG = os.environ.get("HYPOTHESIS_PROFILE") == "long"
#: CI size: 6 + 6 programs (derandomized, a few seconds); the long profile: NCZONES_SOLIDS_MORE_EXAMPLES each
EXAMPLES = int(os.environ.get("NCZONES_SOLIDS_MORE_EXAMPLES", 10_000 if LONG else 6))


@settings(max_examples=EXAMPLES)
@given(mill_cases())
def test_prisms_and_work_offsets_keep_the_contract(case):
    check_mill(*case)


@settings(max_examples=EXAMPLES)
@given(lathe_cases())
def test_lathe_turret_solids_keep_the_contract(case):
    check_lathe(*case)


@pytest.mark.long
@settings(max_examples=EXAMPLES)
@given(mill_cases())
def test_prisms_and_work_offsets_keep_the_contract_long(case):
    check_mill(*case)


@pytest.mark.long
@settings(max_examples=EXAMPLES)
@given(lathe_cases())
def test_lathe_turret_solids_keep_the_contract_long(case):
    check_lathe(*case)
