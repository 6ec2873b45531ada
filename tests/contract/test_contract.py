"""DESIGN §7 on generated machines and programs: prover verdicts vs the reference controller."""

import os

from hypothesis import given, settings

from .contract import check_contract, check_solids_contract
from .strategies import contract_cases, solids_contract_cases

#: 30 programs in the default run (the ci profile's 60 took about two minutes of it); the long profile
#: (HYPOTHESIS_PROFILE=long) keeps its 20,000; NCZONES_CONTRACT_EXAMPLES sets another count
CONTRACT_EXAMPLES = int(os.environ.get("NCZONES_CONTRACT_EXAMPLES",
                                       settings.default.max_examples
                                       if os.environ.get("HYPOTHESIS_PROFILE") == "long" else 30))


@settings(max_examples=CONTRACT_EXAMPLES)
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


def test_the_solids_contract_has_teeth():
    """A prover blind to the tool solids (it keeps only the controlled point's verdict) is caught: the holder
    passes 2 mm into a box the tip stays out of, the controller alarms, and clause S1 fails."""
    from dataclasses import replace

    import pytest

    from nczones.prover import Verdict
    from nczones.prover import prove as real_prove

    from .contract import ContractViolation

    tools = {1: ([("cutter", "10", "25"), ("holder", "40", "40")], "65"), 2: ([("cutter", "6", "20")], "20")}
    fixtures = [{"kind": "box", "name": "box0", "x0": "0", "x1": "20", "y0": "0", "y1": "20", "z0": "0",
                 "z1": "35", "zone": False}]
    # the holder (radius 20, 25..65 above the tip) at X-18 reaches X2, 2 into the box's X range. With the tip
    # at Z20 it is at heights 45..85, above the box top 35; the tip goes down to Z5 and the holder (30..70)
    # enters the box once its bottom is below 35, i.e. the tip below Z10. The cutter (radius 5) stays 13 away
    text = "G21 G90 G17 G54\nT1 M6\nG43 H1\nG0 X-18 Y10 Z20\nG1 Z5 F2000\nM30\n"
    assert check_solids_contract("0.01", tools, fixtures, text) == "unsafe"

    def blind(segs, machine, options):
        r = real_prove(segs, machine, options)
        kept = tuple(v for v in r.violations if v.kind != "solid")
        return replace(r, violations=kept, verdict=Verdict.SAFE if not kept else r.verdict)

    with pytest.raises(ContractViolation, match="grown by 4 pulses"):
        check_solids_contract("0.01", tools, fixtures, text, prove=blind)
