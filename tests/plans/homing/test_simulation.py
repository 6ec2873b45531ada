"""The pulse-by-pulse homing simulation: events, alarms, installation, and the proved conditions."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings
from hypothesis import strategies as st

from nczones.controller.homing import AlarmKind, EventKind, measure_grid_shift, simulate_homing
from nczones.errors import InvalidArgument, MachineFileError
from nczones.plans.homing import (
    HomingConfig,
    edge_to_grid_distance,
    exactness_margin,
    predict_latch,
    window_is_clear,
)

from .strategies import homing_setups, trip_offsets

U = Fraction(1, 1000)
FAST = settings(max_examples=40, derandomize=True, deadline=None,
                suppress_health_check=[HealthCheck.too_slow])


def mill_x(**kw) -> HomingConfig:
    base = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(8), Fraction(30), Fraction(10),
                        Fraction("3.217"), machine_zero=Fraction(0), grid_shift=Fraction("-3.217"),
                        switch_jitter=Fraction("0.02"), servo_lag_ms=Fraction(30), start=Fraction(300))
    return replace(base, **kw)


def test_event_log_of_a_normal_homing():
    run = simulate_homing(mill_x(), U)
    kinds = [e.kind for e in run.events]
    assert kinds == [EventKind.SEARCH_START, EventKind.DOG_TRIP, EventKind.SIGNAL_SEEN,
                     EventKind.GRID_LATCHED, EventKind.SHIFT_MOVE, EventKind.ORIGIN_SET]
    positions = [e.position for e in run.events]
    assert positions == [Fraction(300), Fraction(8), Fraction("6.5"), Fraction("3.217"), Fraction(0), Fraction(0)]
    assert run.trip_pulses == 8000 and run.armed_pulses == 6500 and run.latched_pulses == 3217
    assert run.origin_error_pulses == 0 and run.exact
    assert run.shift_source == "stored"
    # 292 mm at 3000 mm/min, then 1.5 mm lag at 3000, 3.283 mm at 300, 3.217 mm shift at 300
    assert run.time_s == Fraction(2935, 500) + Fraction(3283 + 3217, 5000)
    assert run.pulses_moved == 296783 + 3217


def test_positive_direction_and_machine_zero_not_at_zero():
    cfg = HomingConfig("Z", 1, Fraction(2000), Fraction(200), Fraction(392), Fraction(20), Fraction(10),
                       Fraction("5.5"), machine_zero=Fraction(400), grid_shift=Fraction("4.5"),
                       switch_jitter=Fraction("0.02"), servo_lag_ms=Fraction(30))
    run = simulate_homing(cfg, U, start=Fraction(100))
    assert run.latched_grid == Fraction("395.5") and run.grid_index == 39
    assert run.origin_pulses == 400000 and run.origin_error_pulses == 0


def test_grid_point_between_pulses_latches_the_next_pulse():
    cfg = mill_x(detector_phase=Fraction("3.2174"), grid_shift=None)
    run = simulate_homing(cfg, U, install=True)
    assert run.latched_grid == Fraction("3.2174")
    assert run.latched_pulses == 3217  # first pulse at or beyond the grid point (searching -X)
    inst = measure_grid_shift(cfg, U)
    assert inst.shift_pulses == -3217 and inst.grid_shift == Fraction("-3.217")
    assert inst.run.events[-1].kind is EventKind.SHIFT_MEASURED


def test_start_on_the_dog_is_an_alarm():
    run = simulate_homing(mill_x(), U, start=Fraction(5))
    assert run.alarm.kind is AlarmKind.START_ON_DOG
    assert "start too close to the dog" in run.alarm.message
    assert run.origin_error_pulses is None and not run.exact
    assert [e.kind for e in run.events] == [EventKind.SEARCH_START, EventKind.ALARM]


def test_start_exactly_at_the_trip_point_is_on_the_dog():
    assert simulate_homing(mill_x(), U, start=Fraction(8)).alarm.kind is AlarmKind.START_ON_DOG
    # one pulse before the trip point is fine
    assert simulate_homing(mill_x(), U, start=Fraction("8.001")).exact


def test_start_past_the_dog_is_an_alarm():
    run = simulate_homing(mill_x(), U, start=Fraction(-30))
    assert run.alarm.kind is AlarmKind.PAST_DOG


def test_other_phase_remeasures_the_shift():
    run = simulate_homing(mill_x(), U, phase=Fraction(2))
    assert run.shift_source.startswith("measured") and run.grid_shift == Fraction(-2) and run.exact


def test_inputs_outside_their_ranges_are_refused():
    with pytest.raises(InvalidArgument, match="jitter window"):
        simulate_homing(mill_x(), U, trip_offset=Fraction("0.03"))
    with pytest.raises(InvalidArgument, match="outside"):
        simulate_homing(mill_x(), U, phase=Fraction(10))
    with pytest.raises(InvalidArgument, match="Fraction"):
        simulate_homing(mill_x(), U, trip_offset=0.01)
    with pytest.raises(MachineFileError) as exc:
        simulate_homing(mill_x(machine_zero=Fraction(1, 3)), U)
    assert exc.value.code == "ZN148"


@FAST
@given(data=st.data())
def test_simulation_matches_the_closed_form(data):
    cfg, pulse, start = data.draw(homing_setups())
    t = data.draw(trip_offsets(cfg))
    run = simulate_homing(cfg, pulse, start=start, trip_offset=t, install=True)
    assert run.alarm is None
    assert run.latched_pulses == predict_latch(cfg, pulse, cfg.detector_phase, t)
    # the latched point is a grid point, after the arming position, within one pitch of it
    g = run.latched_grid
    assert ((g - cfg.detector_phase) / cfg.grid_pitch).denominator == 1
    arm = cfg.dog_position + cfg.direction * (t + cfg.lag)
    assert 0 < cfg.direction * (g - arm) <= cfg.grid_pitch
    assert 0 <= cfg.direction * (run.latched_pulses * pulse - g) < pulse


@FAST
@given(data=st.data())
def test_exact_whenever_the_proved_condition_holds(data):
    cfg, pulse, start = data.draw(homing_setups())
    assume(edge_to_grid_distance(cfg) > exactness_margin(cfg))
    t0, t = data.draw(trip_offsets(cfg)), data.draw(trip_offsets(cfg))
    shift = measure_grid_shift(cfg, pulse, trip_offset=t0).grid_shift
    run = simulate_homing(cfg, pulse, start=start, trip_offset=t, grid_shift=shift)
    assert run.origin_error_pulses == 0


@FAST
@given(data=st.data())
def test_error_is_zero_or_one_pitch_and_only_when_the_condition_fails(data):
    cfg, pulse, start = data.draw(homing_setups())
    t0, t = data.draw(trip_offsets(cfg)), data.draw(trip_offsets(cfg))
    shift = measure_grid_shift(cfg, pulse, trip_offset=t0).grid_shift
    error = simulate_homing(cfg, pulse, start=start, trip_offset=t, grid_shift=shift).origin_error_pulses
    assert error in (0, cfg.grid_pitch / pulse, -cfg.grid_pitch / pulse)
    if error:
        assert edge_to_grid_distance(cfg) <= exactness_margin(cfg)
        assert not window_is_clear(cfg)
    if window_is_clear(cfg):
        assert error == 0


@FAST
@given(data=st.data())
def test_grid_point_in_the_window_gives_one_pitch_off(data):
    """Place a grid point inside (edge+lag-jitter, edge+lag+jitter]: the extreme trips disagree by one pitch."""
    cfg, pulse, start = data.draw(homing_setups())
    assume(cfg.switch_jitter > 0)
    where = data.draw(st.fractions(min_value=0, max_value=1).filter(lambda f: f > 0))
    sigma_grid = cfg.direction * cfg.dog_position + cfg.lag - cfg.switch_jitter + where * 2 * cfg.switch_jitter
    phase = (cfg.direction * sigma_grid) % cfg.grid_pitch
    cfg = replace(cfg, detector_phase=phase)
    assert not window_is_clear(cfg)
    shift = measure_grid_shift(cfg, pulse, trip_offset=cfg.switch_jitter).grid_shift
    run = simulate_homing(cfg, pulse, start=start, trip_offset=-cfg.switch_jitter, grid_shift=shift)
    # homing latched the grid point in the window, installation the one a pitch further on
    assert run.origin_error_pulses == -cfg.direction * cfg.grid_pitch / pulse


def test_hypothesis_finds_a_one_pitch_error():
    """Search (not construct) a machine, phase and trip offsets that home one pitch off.

    The phase is drawn near the dog edge plus lag (within twice the jitter), the
    trip offsets anywhere in the window; ``find`` must come up with a case, and
    that case violates the proved condition.
    """
    from hypothesis import find

    @st.composite
    def cases(draw):
        cfg, pulse, start = draw(homing_setups())
        j = cfg.switch_jitter
        delta = draw(st.fractions(min_value=-2 * j, max_value=2 * j, max_denominator=10**5))
        phase = (cfg.dog_position + cfg.direction * (cfg.lag + delta)) % cfg.grid_pitch
        cfg = replace(cfg, detector_phase=phase)
        return cfg, pulse, start, draw(trip_offsets(cfg)), draw(trip_offsets(cfg))

    def error(case):
        cfg, pulse, start, t0, t = case
        shift = measure_grid_shift(cfg, pulse, trip_offset=t0).grid_shift
        return simulate_homing(cfg, pulse, start=start, trip_offset=t, grid_shift=shift).origin_error_pulses

    case = find(cases(), lambda c: error(c) != 0,
                settings=settings(max_examples=300, derandomize=True, database=None, deadline=None,
                                  phases=[Phase.generate]))
    cfg, pulse = case[0], case[1]
    assert abs(error(case)) == cfg.grid_pitch / pulse
    assert edge_to_grid_distance(cfg) <= exactness_margin(cfg)
    assert not window_is_clear(cfg)
