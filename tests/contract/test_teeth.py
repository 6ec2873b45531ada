"""The contract tests have teeth: a deliberately broken prover is caught.

Each test injects one plausible bug into the prover (monkeypatch), runs the
same property function as test_contract.py under Hypothesis, and requires
it to fail with a :class:`ContractViolation`.
"""

import inspect
from fractions import Fraction

import pytest
from hypothesis import Phase, given, settings

import nczones.prover.core as core
import nczones.prover.exact as ex
from nczones.motion import Segment, SegmentKind
from nczones.zones import Region, SteppedZone

from .contract import ContractViolation, check_contract
from .strategies import contract_cases


def run_property(cases, max_examples):
    @settings(max_examples=max_examples, derandomize=True, database=None, deadline=None,
              phases=[Phase.generate], report_multiple_bugs=False)
    @given(cases)
    def prop(case):
        machine, text = case
        check_contract(machine, text, periodic=False)

    prop()


def _patched_stepped_violation(old: str, new: str):
    """The exact tier's stepped-table entry (``ex.LINE_VIOLATION``) with ``old`` replaced by ``new``."""
    fn = ex.LINE_VIOLATION.of(STEP)
    src = inspect.getsource(fn)
    assert old in src, "the prover's stepped-table encoding changed; update this injected bug"
    src = "\n".join(line for line in src.splitlines() if not line.startswith("@"))  # not registered again
    ns = dict(vars(ex))
    exec(compile(src.replace(old, new), ex.__file__, "exec"), ns)
    return ns[fn.__name__]


STEP = SteppedZone("t", "X", "Y", Fraction(0), (Region(Fraction(1)),))


TOUCH = "touch = _all([ln.lt(r, b + d, False), ln.gt(r, a - d, i != 0)])"


def test_stepped_regions_open_at_their_bounds_are_caught(monkeypatch):
    # Bug: region i of an allow table covers upto[i-1] < r < upto[i] (its own upto left out),
    # so a motion exactly on a region boundary is never compared with that region's limits.
    broken = _patched_stepped_violation(TOUCH, "touch = _all([ln.lt(r, b + d, True), ln.gt(r, a - d, True)])")
    monkeypatch.setitem(ex.LINE_VIOLATION._entries, SteppedZone, broken)
    with pytest.raises(ContractViolation):
        run_property(contract_cases(axes=(("X", "Y"),), allow_kinds=("stepped",), arcs=False,
                                    pulses=("0.01",), boundary_bias=0.95, inside_biases=(0.0, 0.3)), 400)


def test_arcs_checked_only_at_their_end_points_are_caught(monkeypatch):
    def end_points_only(self, seg, params):
        for p in (seg.start, seg.end):
            point = Segment(SegmentKind.LINE, p, p, seg.axes, seg.block, seg.span, seg.tool_length)
            out = self.check_concrete(point, params)
            if out.violation is not None or out.reason is not None:
                return out
        return core.Outcome(engine="exact")

    monkeypatch.setattr(core.Prover, "_check_arc", end_points_only)
    with pytest.raises(ContractViolation):
        run_property(contract_cases(axes=(("X", "Y"),), allow_kinds=("box",), pulses=("0.01",), max_blocks=4,
                                    inside_biases=(1.0,), mix={"line": 1, "rapid": 0, "arc": 3}), 300)


def test_the_unbroken_prover_passes_the_same_runs():
    run_property(contract_cases(axes=(("X", "Y"),), allow_kinds=("stepped",), arcs=False,
                                pulses=("0.01",), boundary_bias=0.95, inside_biases=(0.0, 0.3)), 40)
