"""Homing pulse by pulse: the reference controller's run of a ``[homing.<axis>]`` section.

The configuration and the arithmetic that says where homing ends are
:mod:`nczones.plans.homing` (``specs/homing.md``); this module runs it the way a
controller does: one pulse at a time in the search direction, the switch
state, the arming of the grid latch and the grid crossings as integer
comparisons on positions scaled by one common denominator, then the move by
the grid shift.  The tests hold the pulse loop to :func:`nczones.plans.homing.predict_latch`.

>>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5),
...                    Fraction(20), Fraction(10), Fraction(3), switch_jitter=Fraction(1, 50))
>>> run = simulate_homing(cfg, Fraction(1, 1000), start=Fraction(40))
>>> run.origin_error_pulses, format_decimal(run.latched_grid), format_decimal(run.grid_shift)
(0, '3', '-3')
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, replace
from fractions import Fraction
from math import floor, lcm
from typing import Any

from ..errors import InternalError, InvalidArgument, MachineFileError
from ..exact import format_decimal
from ..plans.homing import HomingConfig, check_pulse_multiples, installation_start

__all__ = [
    "HomingEvent",
    "EventKind",
    "AlarmKind",
    "HomingAlarm",
    "HomingRun",
    "InstallationResult",
    "simulate_homing",
    "measure_grid_shift",
]

# --------------------------------------------------------------------------- simulation


class EventKind(enum.Enum):
    SEARCH_START = "search start"
    DOG_TRIP = "dog trip"
    SIGNAL_SEEN = "near-zero signal seen"
    GRID_LATCHED = "grid point latched"
    SHIFT_MOVE = "grid shift move"
    ORIGIN_SET = "origin set"
    SHIFT_MEASURED = "grid shift measured"
    ALARM = "alarm"


class AlarmKind(enum.Enum):
    START_ON_DOG = "start too close to the dog"
    PAST_DOG = "start past the dog"


@dataclass(frozen=True, slots=True)
class HomingEvent:
    """One step of the homing log; ``pulses`` is the axis position in machine pulses."""

    kind: EventKind
    pulses: int
    position: Fraction
    time_s: Fraction
    text: str


@dataclass(frozen=True, slots=True)
class HomingAlarm:
    kind: AlarmKind
    message: str


@dataclass(frozen=True, slots=True)
class HomingRun:
    """The outcome of one homing (or installation) run of one axis.

    ``origin_error_pulses`` is controller zero minus true machine zero, in
    pulses (``None`` after an alarm or for an installation run).
    """

    axis: str
    phase: Fraction
    trip_offset: Fraction
    pulse: Fraction
    events: tuple[HomingEvent, ...]
    alarm: HomingAlarm | None = None
    trip_pulses: int | None = None
    armed_pulses: int | None = None
    latched_grid: Fraction | None = None
    grid_index: int | None = None
    latched_pulses: int | None = None
    grid_shift: Fraction | None = None
    shift_source: str = ""
    origin_pulses: int | None = None
    origin_error_pulses: int | None = None
    pulses_moved: int = 0
    time_s: Fraction = Fraction(0)

    @property
    def exact(self) -> bool:
        return self.alarm is None and self.origin_error_pulses == 0


@dataclass(frozen=True, slots=True)
class InstallationResult:
    """The installation step: the grid shift measured from the first grid point to machine zero."""

    grid_shift: Fraction
    shift_pulses: int
    run: HomingRun


def _validate_inputs(cfg: HomingConfig, pulse: Fraction, phase: Fraction, trip_offset: Fraction) -> None:
    if not isinstance(pulse, Fraction) or pulse <= 0:
        raise InvalidArgument(f"pulse must be a positive Fraction, got {pulse!r}")
    for name, value in (("phase", phase), ("trip offset", trip_offset)):
        if not isinstance(value, Fraction):
            raise InvalidArgument(f"{name} must be an exact Fraction (not {type(value).__name__}), got {value!r}")
    if not 0 <= phase < cfg.grid_pitch:
        raise InvalidArgument(
            f"phase {format_decimal(phase)} is outside "
            f"[0, grid pitch {format_decimal(cfg.grid_pitch)})")
    if abs(trip_offset) > cfg.switch_jitter:
        raise InvalidArgument(
            f"trip offset {format_decimal(trip_offset)} is outside the switch jitter window "
            f"[-{format_decimal(cfg.switch_jitter)}, {format_decimal(cfg.switch_jitter)}]")
    bad = check_pulse_multiples(cfg, pulse)
    if bad:
        raise MachineFileError(bad)


def simulate_homing(
    cfg: HomingConfig,
    pulse: Fraction,
    *,
    start: Fraction | None = None,
    phase: Fraction | None = None,
    trip_offset: Fraction = Fraction(0),
    grid_shift: Fraction | None = None,
    install: bool = False,
) -> HomingRun:
    """Home one axis pulse by pulse.

    Parameters
    ----------
    cfg : HomingConfig
    pulse : Fraction
        The axis' pulse length (mm).
    start : Fraction, optional
        Machine coordinate where the axis stands at power-on (default ``cfg.start``).
    phase : Fraction, optional
        Detector phase (default ``cfg.detector_phase``).  A stored grid shift
        belongs to the configured phase: for any other phase the installation
        measurement is repeated (at trip offset 0) unless ``grid_shift`` is given.
    trip_offset : Fraction
        Where in ``[-jitter, +jitter]`` the switch actually trips, measured
        from the dog edge in the search direction (positive = later).
    grid_shift : Fraction, optional
        Use this grid shift instead of the stored or measured one.
    install : bool
        Stop at the grid point and do not shift (the installation run).

    Returns
    -------
    HomingRun

    Invariants: the axis moves one pulse at a time in the search direction;
    the switch state, the arming of the grid latch and grid crossings are
    integer comparisons on positions scaled by one common denominator; the
    latched position equals :func:`nczones.plans.homing.predict_latch`.

    Examples
    --------
    Starting on the dog is refused, as a Fanuc control does:

    >>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5),
    ...                    Fraction(20), Fraction(10), Fraction(3))
    >>> simulate_homing(cfg, Fraction(1, 1000), start=Fraction(2)).alarm.kind.value
    'start too close to the dog'
    """
    phase = cfg.detector_phase if phase is None else phase
    if start is None:
        start = cfg.start
    if start is None:
        raise InvalidArgument(f"[homing.{cfg.axis}]: no start position given")
    _validate_inputs(cfg, pulse, phase, trip_offset)
    if (start / pulse).denominator != 1:
        raise InvalidArgument(f"start {format_decimal(start)} is not a whole number of pulses ({format_decimal(pulse)})")

    shift_source = ""
    if not install:
        if grid_shift is not None:
            shift_source = "given"
        elif cfg.grid_shift is not None and phase == cfg.detector_phase:
            grid_shift, shift_source = cfg.grid_shift, "stored"
        else:
            grid_shift = measure_grid_shift(cfg, pulse, phase=phase).grid_shift
            shift_source = "measured at installation with trip offset 0"
        if (grid_shift / pulse).denominator != 1:
            raise InvalidArgument(f"grid shift {format_decimal(grid_shift)} is not a whole number of pulses")

    d = cfg.direction
    pitch_p = cfg.grid_pitch / pulse  # whole pulses (checked)
    edge = d * cfg.dog_position / pulse
    trip = edge + trip_offset / pulse
    arm = trip + cfg.lag / pulse
    dog_end = edge + cfg.dog_length / pulse
    residue = ((d * phase) / pulse) % pitch_p
    scale = lcm(trip.denominator, arm.denominator, residue.denominator, dog_end.denominator)
    T, A, R, E = (int(q * scale) for q in (trip, arm, residue, dog_end))
    P = int(pitch_p * scale)

    u_s = pulse * 60 / cfg.search_speed  # seconds per pulse
    u_l = pulse * 60 / cfg.latch_speed
    n = d * int(start / pulse)  # sigma, in pulses
    events: list[HomingEvent] = []

    def event(kind: EventKind, sigma: int, time: Fraction, text: str) -> None:
        events.append(HomingEvent(kind, d * sigma, d * sigma * pulse, time, text))

    base: dict[str, Any] = dict(axis=cfg.axis, phase=phase, trip_offset=trip_offset, pulse=pulse)
    event(EventKind.SEARCH_START, n, Fraction(0),
          f"search {'+' if d > 0 else '-'}{cfg.axis} at {format_decimal(cfg.search_speed)} mm/min")
    if n * scale > E:
        msg = (f"the axis starts at {format_decimal(d * n * pulse)}, past the dog "
               f"(dog from {format_decimal(cfg.dog_position)} to "
               f"{format_decimal(cfg.dog_position + d * cfg.dog_length)}); the search would never meet it")
        event(EventKind.ALARM, n, Fraction(0), msg)
        return HomingRun(**base, events=tuple(events), alarm=HomingAlarm(AlarmKind.PAST_DOG, msg))
    if n * scale >= T:
        msg = (f"start too close to the dog: the near-zero switch is already closed at "
               f"{format_decimal(d * n * pulse)} (dog edge {format_decimal(cfg.dog_position)}); "
               f"jog the axis back off the dog and home again")
        event(EventKind.ALARM, n, Fraction(0), msg)
        return HomingRun(**base, events=tuple(events), alarm=HomingAlarm(AlarmKind.START_ON_DOG, msg))

    # Upper bound on the pulses the loop may take: to the arming point, then one pitch.
    limit = (A - n * scale) // scale + int(pitch_p) + 2
    moved = 0
    search_pulses = 0
    tripped = armed = False
    trip_n = arm_n = None
    latched: tuple[int, int] | None = None
    while latched is None:
        if moved > limit:
            raise InternalError("homing loop passed its bound without latching a grid point")
        prev = n * scale
        n += 1
        moved += 1
        if not armed:
            search_pulses += 1
        cur = n * scale
        lo = prev
        if not tripped and cur >= T:
            tripped, trip_n = True, n
            event(EventKind.DOG_TRIP, n, search_pulses * u_s,
                  f"near-zero switch closed (trip point {format_decimal(d * trip * pulse)})")
        if tripped and not armed and cur >= A:
            armed, arm_n = True, n
            lo = A
            event(EventKind.SIGNAL_SEEN, n, search_pulses * u_s,
                  f"controller sees the signal after the servo lag {format_decimal(cfg.lag)} mm; "
                  f"decelerate to {format_decimal(cfg.latch_speed)} mm/min and wait for the next grid point")
        if armed:
            k_hi = (cur - R) // P
            if k_hi > (lo - R) // P:  # a grid point g with lo < g <= cur
                latched = (n, k_hi)
    n_latch, k = latched
    t = search_pulses * u_s + (moved - search_pulses) * u_l
    grid_sigma = (Fraction(R, scale) + k * pitch_p) * pulse
    grid = d * grid_sigma
    grid_index = floor((grid - phase) / cfg.grid_pitch)
    event(EventKind.GRID_LATCHED, n_latch, t,
          f"grid point {format_decimal(grid)} (phase {format_decimal(phase)} + {grid_index} x "
          f"{format_decimal(cfg.grid_pitch)}) latched; axis stopped")
    assert trip_n is not None and arm_n is not None  # a grid point latches only after the trip and the arming
    run = HomingRun(**base, events=tuple(events), trip_pulses=d * trip_n, armed_pulses=d * arm_n,
                    latched_grid=grid, grid_index=grid_index, latched_pulses=d * n_latch,
                    pulses_moved=moved, time_s=t)
    if install:
        return run
    assert grid_shift is not None  # given, stored or measured above
    shift_pulses = int(grid_shift / pulse)
    end = d * n_latch + shift_pulses
    t_shift = t + abs(shift_pulses) * u_l
    events.append(HomingEvent(EventKind.SHIFT_MOVE, end, end * pulse, t_shift,
                              f"move by the grid shift {format_decimal(grid_shift)} "
                              f"({shift_source}; {shift_pulses} pulses)"))
    error = end - int(cfg.machine_zero / pulse)
    events.append(HomingEvent(EventKind.ORIGIN_SET, end, end * pulse, t_shift,
                              f"origin set; controller zero - machine zero = {error} pulses "
                              f"({format_decimal(error * pulse)} mm)"))
    return replace(run, events=tuple(events), grid_shift=grid_shift, shift_source=shift_source,
                   origin_pulses=end, origin_error_pulses=error,
                   pulses_moved=moved + abs(shift_pulses), time_s=t_shift)



def measure_grid_shift(
    cfg: HomingConfig,
    pulse: Fraction,
    *,
    start: Fraction | None = None,
    phase: Fraction | None = None,
    trip_offset: Fraction = Fraction(0),
) -> InstallationResult:
    """The installation step: home to the first grid point, measure the distance to machine zero.

    The stored grid shift is ``machine_zero - latched grid position`` (signed,
    machine coordinates, whole pulses).  Without ``start`` the run starts at
    :func:`nczones.plans.homing.installation_start`, clear of the dog.

    >>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5),
    ...                    Fraction(20), Fraction(10), Fraction("3.2505"))
    >>> format_decimal(measure_grid_shift(cfg, Fraction(1, 1000), start=Fraction(40)).grid_shift)
    '-3.25'
    """
    if start is None:
        start = installation_start(cfg, pulse)
    run = simulate_homing(cfg, pulse, start=start, phase=phase, trip_offset=trip_offset, install=True)
    if run.alarm is not None:
        raise InvalidArgument(f"installation measurement impossible: {run.alarm.message}")
    assert run.latched_pulses is not None  # a run without alarm latched a grid point
    shift_pulses = int(cfg.machine_zero / pulse) - run.latched_pulses
    shift = shift_pulses * pulse
    log = run.events + (HomingEvent(
        EventKind.SHIFT_MEASURED, run.latched_pulses, run.latched_pulses * pulse, run.time_s,
        f"machine zero {format_decimal(cfg.machine_zero)} - latched {format_decimal(run.latched_pulses * pulse)} "
        f"= grid shift {format_decimal(shift)} ({shift_pulses} pulses)"),)
    return InstallationResult(shift, shift_pulses, replace(run, events=log, grid_shift=shift,
                                                            shift_source="measured"))
