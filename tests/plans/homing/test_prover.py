"""Z3 proofs about homing, and their agreement with the pulse simulation."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

import pytest
import z3
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.controller.homing import measure_grid_shift, simulate_homing
from nczones.plans.homing import HomingConfig, origin_error_pulses, predict_latch, window_is_clear
from nczones.prover.homing import (
    ProofStatus,
    _Model,
    find_one_pitch_error,
    prove_configured_phase,
    prove_error_is_one_pitch,
    prove_exact_after_installation,
    prove_homing,
    prove_margin_condition,
    prove_window_condition,
)

from .strategies import homing_setups

U = Fraction(1, 1000)


def mill_x(**kw) -> HomingConfig:
    base = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(8), Fraction(30), Fraction(10),
                        Fraction("3.217"), machine_zero=Fraction(0), grid_shift=Fraction("-3.217"),
                        switch_jitter=Fraction("0.02"), servo_lag_ms=Fraction(30), start=Fraction(300))
    return replace(base, **kw)


Z_UP = HomingConfig("Z", 1, Fraction(2000), Fraction(200), Fraction(392), Fraction(20), Fraction(10),
                    Fraction("5.5"), machine_zero=Fraction(400), grid_shift=Fraction("4.5"),
                    switch_jitter=Fraction("0.05"), servo_lag_ms=Fraction(30), start=Fraction(100))


@pytest.mark.parametrize("cfg", [mill_x(), Z_UP, mill_x(servo_lag_ms=Fraction(0)),
                                 mill_x(grid_pitch=Fraction("0.5"), detector_phase=Fraction("0.3"), grid_shift=None)],
                         ids=["mill-x", "z-up", "no-lag", "fine-pitch"])
def test_general_claims_are_proved(cfg):
    for proof in (prove_exact_after_installation(cfg, U), prove_error_is_one_pitch(cfg, U),
                  prove_margin_condition(cfg, U), *prove_window_condition(cfg, U)):
        assert proof.status is ProofStatus.PROVED, (proof.name, proof.reason)
        assert proof.counterexample is None


@pytest.mark.parametrize("cfg", [mill_x(), Z_UP], ids=["mill-x", "z-up"])
def test_one_pitch_counterexample_is_reproduced_by_the_simulation(cfg):
    proof = find_one_pitch_error(cfg, U)
    assert proof.status is ProofStatus.REFUTED
    c = proof.counterexample
    assert abs(c.origin_error_pulses) == cfg.grid_pitch / U
    assert c.confirmed
    assert c.phase != cfg.detector_phase  # a stored shift belongs to the configured phase
    assert not window_is_clear(cfg, c.phase)
    # on the pulse grid, so the reproduction command reads as plain decimals
    assert (c.phase / U).denominator == 1 and (c.trip_offset / U).denominator == 1
    run = simulate_homing(cfg, U, phase=c.phase, trip_offset=c.trip_offset)
    assert run.origin_error_pulses == c.origin_error_pulses


def test_no_jitter_no_counterexample():
    proof = find_one_pitch_error(mill_x(switch_jitter=Fraction(0)), U)
    assert proof.status is ProofStatus.PROVED


def test_configured_phase_inside_the_window_is_refuted():
    # grid point at 6.5 = edge 8 - lag 1.5: the switch jitter decides which grid point latches
    cfg = mill_x(detector_phase=Fraction("6.51"), grid_shift=Fraction("3.49"))
    proof = prove_configured_phase(cfg, U)
    assert proof.status is ProofStatus.REFUTED
    c = proof.counterexample
    assert not c.phase_given and c.confirmed and abs(c.origin_error_pulses) == 10000
    assert simulate_homing(cfg, U, trip_offset=c.trip_offset).origin_error_pulses == c.origin_error_pulses
    assert not prove_homing(cfg, U).ok


def test_stale_stored_shift_is_refuted_at_every_trip():
    cfg = mill_x(grid_shift=Fraction("-3.2"))  # detector re-mounted, shift not re-measured
    proof = prove_configured_phase(cfg, U)
    assert proof.status is ProofStatus.REFUTED
    assert proof.counterexample.origin_error_pulses == 17


def test_configured_phase_proved_for_the_example():
    assert prove_configured_phase(mill_x(), U).status is ProofStatus.PROVED
    report = prove_homing(mill_x(), U)
    assert report.ok and report.window_clear and report.edge_to_grid > report.margin
    assert report.solver.startswith("z3 ")


def test_timeout_gives_unknown(monkeypatch):
    import nczones.prover.homing as ph

    real = ph._Model.check
    monkeypatch.setattr(ph._Model, "check", lambda self: z3.unknown)
    proof = prove_exact_after_installation(mill_x(), U)
    assert proof.status is ProofStatus.UNKNOWN and proof.reason.startswith("Z3")
    monkeypatch.setattr(ph._Model, "check", real)


@settings(max_examples=25, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_z3_model_latches_where_the_simulation_latches(data):
    """Differential: the Z3 encoding, with phase and trip fixed, has exactly the simulated latch as model."""
    cfg, pulse, start = data.draw(homing_setups())
    t = data.draw(st.sampled_from((-cfg.switch_jitter, Fraction(0), cfg.switch_jitter)))
    m = _Model(cfg, pulse)
    m.solver.add(m.phase == z3.Q(cfg.detector_phase.numerator, cfg.detector_phase.denominator))
    n = m.latch(z3.Q(t.numerator, t.denominator), "x")
    assert m.check() == z3.sat
    sigma = m.solver.model().eval(n).as_long()
    expected = simulate_homing(cfg, pulse, start=start, trip_offset=t, install=True).latched_pulses
    assert cfg.direction * sigma == expected == predict_latch(cfg, pulse, cfg.detector_phase, t)
    m.solver.add(n != sigma)
    assert m.check() == z3.unsat  # the latch is unique


@settings(max_examples=40, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_closed_form_origin_error_is_the_simulations(data):
    """Differential: the shared grid arithmetic (what the proofs encode) against the controller's pulse loop."""
    cfg, pulse, start = data.draw(homing_setups())
    jitter = cfg.switch_jitter
    t = data.draw(st.sampled_from((-jitter, Fraction(0), jitter, jitter / 3)))
    t0 = data.draw(st.sampled_from((-jitter, Fraction(0), jitter)))
    shift = measure_grid_shift(cfg, pulse, start=start, trip_offset=t0).grid_shift
    run = simulate_homing(cfg, pulse, start=start, trip_offset=t, grid_shift=shift)
    assert run.origin_error_pulses == origin_error_pulses(cfg, pulse, cfg.detector_phase, t, install_trip_offset=t0)
