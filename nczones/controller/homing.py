"""Homing with a near-zero dog, detector grid points and a stored grid shift.

At power-on the controller's zero and the machine's zero are not in step.
Homing (reference return) moves one axis towards its zero until a dog closes
the near-zero switch, stops at the first grid point of the position detector
after that signal (a resolver or encoder gives one grid point per revolution),
moves on by the stored grid shift and takes that position as its origin.  The
grid shift is measured once at installation: the distance from the first grid
point after the near-zero signal to the true machine zero (JPS6046442B2).

This module reads the ``[homing.<axis>]`` section of the machine file and
simulates homing pulse by pulse with integer pulse counts and exact rationals.
``specs/homing.md`` describes every field and the model; in short:

* grid points lie at ``detector_phase + k * grid_pitch`` (machine coordinates);
* the switch trips when the axis reaches ``dog_position + direction *
  trip_offset`` where the trip offset is any value in ``[-switch_jitter,
  +switch_jitter]`` (an explicit input, so tests and proofs can choose it);
* the controller sees the signal ``servo lag`` later: the axis has moved on by
  ``lag = search_speed * servo_lag_ms / 60000`` mm when the grid latch is armed;
* the first grid point strictly beyond the arming position is latched at the
  first pulse position at or beyond it; the axis then moves by the grid shift.

The search coordinate ``sigma = direction * x`` makes every search run towards
increasing ``sigma``; positions reported to users are machine coordinates.

>>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5),
...                    Fraction(20), Fraction(10), Fraction(3), switch_jitter=Fraction(1, 50))
>>> run = simulate_homing(cfg, Fraction(1, 1000), start=Fraction(40))
>>> run.origin_error_pulses, format_decimal(run.latched_grid), format_decimal(run.grid_shift)
(0, '3', '-3')
"""

from __future__ import annotations

import difflib
import enum
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from fractions import Fraction
from math import floor, lcm
from types import MappingProxyType
from typing import Any

from ..errors import Diagnostic, InternalError, InvalidArgument, MachineFileError, SourceSpan
from ..exact import format_decimal
from ..machine import SECTION_PARSERS, Machine, _number, _written

__all__ = [
    "HomingConfig",
    "HomingEvent",
    "EventKind",
    "AlarmKind",
    "HomingAlarm",
    "HomingRun",
    "InstallationResult",
    "parse_homing_section",
    "homing_config",
    "check_pulse_multiples",
    "simulate_homing",
    "measure_grid_shift",
    "installation_start",
    "predict_latch",
    "edge_to_grid_distance",
    "exactness_margin",
    "window_is_clear",
    "HOMING_KEYS",
]

HOMING_KEYS = (
    "direction", "search_speed", "latch_speed", "dog_position", "dog_length", "grid_pitch",
    "detector_phase", "machine_zero", "grid_shift", "switch_jitter", "servo_lag_ms", "start",
)
_REQUIRED = ("direction", "search_speed", "latch_speed", "dog_position", "dog_length",
             "grid_pitch", "detector_phase")
_DIRECTIONS = {"negative": -1, "positive": 1, "-": -1, "+": 1, "-1": -1, "+1": 1, "1": 1}


@dataclass(frozen=True, slots=True)
class HomingConfig:
    """One ``[homing.<axis>]`` section (lengths in mm, speeds in mm/min).

    ``direction`` is -1 or +1: the sign of the search motion.  ``grid_shift``
    is ``None`` when the file stores none (then it is measured, see
    :func:`measure_grid_shift`).  ``start`` is ``None`` when the file does not
    say where homing starts (the machine's start position is used).
    """

    axis: str
    direction: int
    search_speed: Fraction
    latch_speed: Fraction
    dog_position: Fraction
    dog_length: Fraction
    grid_pitch: Fraction
    detector_phase: Fraction
    machine_zero: Fraction = Fraction(0)
    grid_shift: Fraction | None = None
    switch_jitter: Fraction = Fraction(0)
    servo_lag_ms: Fraction = Fraction(0)
    start: Fraction | None = None
    source: str = "<machine>"
    spans: Mapping[str, SourceSpan] = field(
        default_factory=lambda: MappingProxyType({}), compare=False, hash=False, repr=False
    )

    @property
    def lag(self) -> Fraction:
        """Servo lag as a distance: search speed times the lag time (mm).

        >>> HomingConfig("X", -1, Fraction(6000), Fraction(600), Fraction(0), Fraction(1),
        ...              Fraction(10), Fraction(0), servo_lag_ms=Fraction(5)).lag
        Fraction(1, 2)
        """
        return self.search_speed * self.servo_lag_ms / 60000


# --------------------------------------------------------------------------- parsing


def _direction(rd: Any, raw: Any, label: str, span: SourceSpan | None) -> int | None:
    key = raw.strip().lower() if isinstance(raw, str) else raw
    if isinstance(key, bool):
        key = None
    if isinstance(key, int) and key in (-1, 1):
        return key
    if isinstance(key, str) and key in _DIRECTIONS:
        return _DIRECTIONS[key]
    rd.report("ZN143", f"{label} direction: {_written(raw)} is not a direction; use \"negative\" or "
              "\"positive\" (or -1 / +1), the sign of the search motion towards the dog", span)
    return None


def _axis_section(rd: Any, axis: str, table: Mapping[str, Any]) -> HomingConfig | None:
    label = f"[homing.{axis}]"
    header = rd.loc.section(f"homing.{axis}")

    def span(key: str) -> SourceSpan | None:
        found: SourceSpan | None = rd.loc.key(key, header)
        return found

    ok = True
    for key in table:
        if key not in HOMING_KEYS:
            close = difflib.get_close_matches(key, HOMING_KEYS, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else f"; allowed keys: {', '.join(HOMING_KEYS)}"
            rd.report("ZN140", f"{label}: unknown key {key!r}{hint}", span(key))
            ok = False
    missing = [k for k in _REQUIRED if k not in table]
    if missing:
        header_span = None
        if header is not None:
            line = rd.loc.lines[header]
            header_span = SourceSpan(rd.path, header + 1, 1, len(line.rstrip()) + 1, line)
        rd.report("ZN142", f"{label}: missing {', '.join(missing)} (required: {', '.join(_REQUIRED)})",
                  header_span)
        ok = False
    values: dict[str, Any] = {}
    if "direction" in table:
        values["direction"] = _direction(rd, table["direction"], label, span("direction"))
        ok = ok and values["direction"] is not None
    for key in HOMING_KEYS[1:]:
        if key not in table:
            continue
        q = _number(rd, table[key], f"{label} {key}", span(key))
        if q is None:
            ok = False
            continue
        values[key] = q
    for key in ("search_speed", "latch_speed"):
        if key in values and values[key] <= 0:
            rd.report("ZN144", f"{label} {key}: {format_decimal(values[key])} mm/min must be greater than 0 "
                      "(the direction is given by 'direction', not by the sign of the speed)", span(key))
            ok = False
    for key, strict in (("grid_pitch", True), ("dog_length", True), ("switch_jitter", False), ("servo_lag_ms", False)):
        if key in values and (values[key] <= 0 if strict else values[key] < 0):
            rule = "must be greater than 0" if strict else "must not be negative"
            rd.report("ZN146", f"{label} {key}: {format_decimal(values[key])} {rule}", span(key))
            ok = False
    pitch = values.get("grid_pitch")
    if pitch is not None and pitch > 0 and "detector_phase" in values:
        phase = values["detector_phase"]
        if not 0 <= phase < pitch:
            rd.report("ZN145", f"{label} detector_phase: {format_decimal(phase)} is outside [0, grid_pitch) = "
                      f"[0, {format_decimal(pitch)}); write the phase modulo the pitch "
                      f"({format_decimal(phase % pitch)})", span("detector_phase"))
            ok = False
    jitter = values.get("switch_jitter")
    if pitch is not None and pitch > 0 and jitter is not None and 2 * jitter >= pitch:
        rd.report("ZN147", f"{label} switch_jitter: {format_decimal(jitter)} is too large; the trip window "
                  f"(2 x jitter = {format_decimal(2 * jitter)}) must be shorter than the grid pitch "
                  f"{format_decimal(pitch)}", span("switch_jitter"))
        ok = False
    if not ok:
        return None
    spans = {k: s for k in table if (s := span(k)) is not None}
    return HomingConfig(
        axis=axis, direction=values["direction"], search_speed=values["search_speed"],
        latch_speed=values["latch_speed"], dog_position=values["dog_position"],
        dog_length=values["dog_length"], grid_pitch=values["grid_pitch"],
        detector_phase=values["detector_phase"], machine_zero=values.get("machine_zero", Fraction(0)),
        grid_shift=values.get("grid_shift"), switch_jitter=values.get("switch_jitter", Fraction(0)),
        servo_lag_ms=values.get("servo_lag_ms", Fraction(0)), start=values.get("start"),
        source=rd.path, spans=MappingProxyType(spans),
    )


def parse_homing_section(rd: Any, raw: Any, axes: tuple[str, ...]) -> Mapping[str, HomingConfig]:
    """The ``[homing]`` parser registered in :data:`nczones.machine.SECTION_PARSERS`.

    Returns axis name -> :class:`HomingConfig` for the valid axis sections;
    problems are reported to ``rd`` with codes ZN140-ZN147.

    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X"]
    ... [machine.rapid]
    ... X = "10000"
    ... [machine.reference]
    ... X = "0"
    ... [homing.X]
    ... direction = "negative"
    ... search_speed = "3000"
    ... latch_speed = "300"
    ... dog_position = "5"
    ... dog_length = "20"
    ... grid_pitch = "10"
    ... detector_phase = "3.25"
    ... ''')
    >>> m.sections["homing"]["X"].detector_phase
    Fraction(13, 4)
    """
    out: dict[str, HomingConfig] = {}
    header = rd.loc.section("homing")
    if not isinstance(raw, Mapping):
        rd.report("ZN141", f"[homing]: expected one table per axis such as [homing.X], got {_written(raw)}",
                  rd.loc.key("homing", None))
        return MappingProxyType(out)
    for axis, table in raw.items():
        if not isinstance(table, Mapping):
            if axis in HOMING_KEYS:
                msg = (f"[homing] {axis}: {axis!r} is a per-axis key; put it under [homing.<axis>] "
                       f"(such as [homing.X]), not directly under [homing]")
            else:
                msg = f"[homing] {axis}: expected a table [homing.{axis}], got {_written(table)}"
            rd.report("ZN141", msg, rd.loc.key(axis, header))
            continue
        if axis not in axes:
            close = difflib.get_close_matches(axis, axes, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            line = rd.loc.section(f"homing.{axis}")
            span = None
            if line is not None:
                text = rd.loc.lines[line]
                span = SourceSpan(rd.path, line + 1, 1, len(text.rstrip()) + 1, text)
            rd.report("ZN141", f"[homing.{axis}]: unknown axis {axis!r}; the machine's axes are "
                      f"{', '.join(axes)}{hint}", span)
            continue
        cfg = _axis_section(rd, axis, table)
        if cfg is not None:
            out[axis] = cfg
    return MappingProxyType(out)


SECTION_PARSERS["homing"] = parse_homing_section


def homing_config(machine: Machine, axis: str | None = None) -> dict[str, HomingConfig]:
    """The homing sections of a machine (one axis, or all), checked against its pulses.

    Raises
    ------
    InvalidArgument
        If the machine has no homing section for ``axis``.
    MachineFileError
        If a length is not a whole number of the axis' pulses (ZN148).
    """
    sections = machine.sections.get("homing", {})
    if axis is not None:
        if axis not in sections:
            have = ", ".join(sections) or "none"
            raise InvalidArgument(f"--axis {axis}: the machine has no [homing.{axis}] section "
                                  f"(homing sections: {have})")
        chosen = {axis: sections[axis]}
    else:
        if not sections:
            raise InvalidArgument(f"{machine.source}: the machine has no [homing.<axis>] section; "
                                  "see specs/homing.md")
        chosen = dict(sections)
    problems: list[Diagnostic] = []
    for name, cfg in chosen.items():
        problems += check_pulse_multiples(cfg, machine.axis(name).pulse)
    if problems:
        raise MachineFileError(problems)
    return chosen


def check_pulse_multiples(cfg: HomingConfig, pulse: Fraction) -> list[Diagnostic]:
    """ZN148 diagnostics for lengths that must be whole pulses (pitch, zero, shift, start).

    >>> cfg = HomingConfig("X", -1, Fraction(1), Fraction(1), Fraction(0), Fraction(1),
    ...                    Fraction(10), Fraction(0), machine_zero=Fraction(1, 3000))
    >>> [d.code for d in check_pulse_multiples(cfg, Fraction(1, 1000))]
    ['ZN148']
    """
    out = []
    for key in ("grid_pitch", "machine_zero", "grid_shift", "start"):
        value = getattr(cfg, key)
        if value is not None and (value / pulse).denominator != 1:
            out.append(Diagnostic(
                "ZN148",
                f"[homing.{cfg.axis}] {key}: {format_decimal(value)} is not a whole number of "
                f"pulses ({format_decimal(pulse)}); the controller can only count whole pulses",
                cfg.spans.get(key), file=cfg.source))
    return out


# --------------------------------------------------------------------------- closed form


def _first_grid_after(a: Fraction, residue: Fraction, pitch: Fraction) -> tuple[int, Fraction]:
    """Index k and value of the first ``residue + k*pitch`` strictly greater than ``a``."""
    k = floor((a - residue) / pitch) + 1
    return k, residue + k * pitch


def _ceil(q: Fraction) -> int:
    return -floor(-q)


def predict_latch(cfg: HomingConfig, pulse: Fraction, phase: Fraction, trip_offset: Fraction) -> int:
    """Closed form of the latched position (machine pulses) — what the pulse loop must reproduce.

    Invariant: the latched grid point ``g`` is the first grid point with
    ``direction*(g - a) > 0`` for the arming position ``a = dog_position +
    direction*(trip_offset + lag)``, and the latch is the first pulse position
    at or beyond ``g``.

    >>> cfg = HomingConfig("X", 1, Fraction(600), Fraction(60), Fraction(5), Fraction(20),
    ...                    Fraction(10), Fraction(7))
    >>> predict_latch(cfg, Fraction(1, 1000), Fraction(7), Fraction(0))
    7000
    """
    d = cfg.direction
    sigma_a = d * cfg.dog_position + trip_offset + cfg.lag
    _, g = _first_grid_after(sigma_a, (d * phase) % cfg.grid_pitch, cfg.grid_pitch)
    return d * _ceil(g / pulse)


def edge_to_grid_distance(cfg: HomingConfig, phase: Fraction | None = None) -> Fraction:
    """Distance from the dog's switching edge to the nearest grid point (mm).

    >>> cfg = HomingConfig("X", -1, Fraction(1), Fraction(1), Fraction(5), Fraction(1),
    ...                    Fraction(10), Fraction(3))
    >>> edge_to_grid_distance(cfg)
    Fraction(2, 1)
    """
    phase = cfg.detector_phase if phase is None else phase
    r = (cfg.dog_position - phase) % cfg.grid_pitch
    return min(r, cfg.grid_pitch - r)


def exactness_margin(cfg: HomingConfig) -> Fraction:
    """Jitter plus lag: homing is always exact when the edge-to-grid distance exceeds it."""
    return cfg.switch_jitter + cfg.lag


def window_is_clear(cfg: HomingConfig, phase: Fraction | None = None) -> bool:
    """The exact condition: no grid point in the arming window (A1, A2].

    With ``sigma`` the search coordinate, ``A1 = edge + lag - jitter`` and
    ``A2 = edge + lag + jitter``; homing latches the same grid point for every
    trip offset exactly when no grid point lies in ``(A1, A2]``.
    """
    phase = cfg.detector_phase if phase is None else phase
    d = cfg.direction
    a1 = d * cfg.dog_position + cfg.lag - cfg.switch_jitter
    _, g = _first_grid_after(a1, (d * phase) % cfg.grid_pitch, cfg.grid_pitch)
    return cfg.switch_jitter == 0 or g > a1 + 2 * cfg.switch_jitter


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
    latched position equals :func:`predict_latch`.

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


def installation_start(cfg: HomingConfig, pulse: Fraction) -> Fraction:
    """A start position clear of the dog: one pitch plus the jitter before its edge, on a pulse.

    >>> cfg = HomingConfig("X", -1, Fraction(1), Fraction(1), Fraction(5), Fraction(1),
    ...                    Fraction(10), Fraction(0), switch_jitter=Fraction(1, 10))
    >>> installation_start(cfg, Fraction(1, 1000))
    Fraction(151, 10)
    """
    d = cfg.direction
    sigma = floor((d * cfg.dog_position - cfg.switch_jitter - cfg.grid_pitch) / pulse)
    return d * sigma * pulse


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
    :func:`installation_start`, clear of the dog.

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
