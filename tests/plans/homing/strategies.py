"""Hypothesis strategies for homing configurations (exact rationals, whole-pulse pitches)."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

from nczones.plans.homing import HomingConfig

PULSES = (Fraction(1, 1000), Fraction(1, 200), Fraction(1, 100))


def decimals(lo: Fraction, hi: Fraction, places: int = 4) -> st.SearchStrategy[Fraction]:
    """Decimals with up to ``places`` digits in [lo, hi]."""
    scale = 10**places
    return st.integers(int(lo * scale), int(hi * scale)).map(lambda n: Fraction(n, scale))


@st.composite
def homing_setups(draw, *, phase=None, jitter=None):
    """(config, pulse, start): start clear of the dog, travel kept short for speed."""
    pulse = draw(st.sampled_from(PULSES))
    direction = draw(st.sampled_from((-1, 1)))
    pitch = Fraction(draw(st.integers(1, 24)), draw(st.sampled_from((1, 2))))
    if jitter is None:
        jitter = draw(decimals(Fraction(0), pitch / 2 - Fraction(1, 10**4)))
    if phase is None:
        phase = draw(decimals(Fraction(0), pitch - Fraction(1, 10**4)))
    cfg = HomingConfig(
        axis=draw(st.sampled_from("XYZ")),
        direction=direction,
        search_speed=Fraction(draw(st.integers(100, 6000))),
        latch_speed=Fraction(draw(st.integers(10, 600))),
        dog_position=draw(decimals(Fraction(-200), Fraction(200), 3)),
        dog_length=Fraction(draw(st.integers(5, 40))),
        grid_pitch=pitch,
        detector_phase=phase,
        machine_zero=Fraction(draw(st.integers(-50, 50))),
        switch_jitter=jitter,
        servo_lag_ms=Fraction(draw(st.integers(0, 40)), draw(st.sampled_from((1, 2, 4)))),
    )
    run_up = pitch + jitter + cfg.lag + draw(decimals(Fraction(0), Fraction(3), 2)) + pulse
    start = cfg.dog_position - direction * run_up
    start = Fraction(round(start / pulse)) * pulse
    return cfg, pulse, start


def trip_offsets(cfg: HomingConfig) -> st.SearchStrategy[Fraction]:
    j = cfg.switch_jitter
    return st.one_of(st.sampled_from((-j, Fraction(0), j)), decimals(-j, j, 5))
