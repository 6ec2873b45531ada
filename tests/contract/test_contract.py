"""DESIGN §7 on generated machines and programs: prover verdicts vs the reference controller."""

from hypothesis import given, settings

from .contract import check_contract
from .strategies import contract_cases


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
