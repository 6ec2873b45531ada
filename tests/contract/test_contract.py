"""DESIGN §7 on generated machines and programs: prover verdicts vs the reference controller."""

import os

from hypothesis import given, settings

from .contract import check_contract, check_solids_contract
from .strategies import contract_cases, solids_contract_cases


@settings()
@given(contract_cases())
def test_prover_and_controller_keep_the_contract(case):
    machine, text = case
    check_contract(machine, text)


@settings()
@given(contract_cases(allow_kinds=("stepped", "box"), pulses=("0.01",), max_blocks=4))
def test_contract_on_tables_and_boxes(case):
    """The cheaper half (vectorized monitor, exact line decisions): the long profile's main run."""
    machine, text = case
    check_contract(machine, text)


#: 12 programs at CI size (about 4 s); the long profile (HYPOTHESIS_PROFILE=long) runs 20,000
SOLIDS_EXAMPLES = int(os.environ.get("NCZONES_SOLIDS_CONTRACT_EXAMPLES",
                                     20_000 if os.environ.get("HYPOTHESIS_PROFILE") == "long" else 12))


@settings(max_examples=SOLIDS_EXAMPLES)
@given(solids_contract_cases())
def test_solids_prover_and_controller_keep_the_contract(case):
    """Issue 39: tool solids against fixtures, the prover and the controller held to one verdict
    (contract.check_solids_contract; the long profile runs it with HYPOTHESIS_PROFILE=long)."""
    check_solids_contract(*case)
