"""Homing as configured: the ``[homing.<axis>]`` section and the grid arithmetic.

At power-on the controller's zero and the machine's zero are not in step.
Homing (reference return) moves one axis towards its zero until a dog closes
the near-zero switch, stops at the first grid point of the position detector
after that signal (a resolver or encoder gives one grid point per revolution),
moves on by the stored grid shift and takes that position as its origin.  The
grid shift is measured once at installation: the distance from the first grid
point after the near-zero signal to the true machine zero (JPS6046442B2).

This module is the meaning both witnesses read: the configuration (parsed
from the machine file, ``specs/homing.md``) and the arithmetic that defines
where homing ends.  The pulse-by-pulse run is
:mod:`nczones.controller.homing`; the Z3 proofs are
:mod:`nczones.prover.homing`.  In short:

* grid points lie at ``detector_phase + k * grid_pitch`` (machine coordinates);
* the switch trips when the axis reaches ``dog_position + direction *
  trip_offset`` where the trip offset is any value in ``[-switch_jitter,
  +switch_jitter]`` (an explicit input, so tests and proofs can choose it);
* the controller sees the signal ``servo lag`` later: the axis has moved on by
  ``lag = search_speed * servo_lag_ms / 60000`` mm when the grid latch is armed;
* the first grid point strictly beyond the arming position is latched at the
  first pulse position at or beyond it (:func:`predict_latch`); the axis then
  moves by the grid shift, which installation measured as ``machine_zero``
  minus the latched position (:func:`origin_error_pulses`).

The search coordinate ``sigma = direction * x`` makes every search run towards
increasing ``sigma``; positions reported to users are machine coordinates.

>>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5),
...                    Fraction(20), Fraction(10), Fraction(3), switch_jitter=Fraction(1, 50))
>>> predict_latch(cfg, Fraction(1, 1000), cfg.detector_phase, Fraction(0))
3000
>>> origin_error_pulses(cfg, Fraction(1, 1000), cfg.detector_phase, Fraction(0))
0
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from math import floor
from types import MappingProxyType
from typing import Any

from ..errors import Diagnostic, InvalidArgument, MachineFileError, SourceSpan, close_matches
from ..exact import format_decimal
from ..machine import Machine, as_written, read_number

__all__ = [
    "HomingConfig",
    "parse_homing_section",
    "homing_config",
    "check_pulse_multiples",
    "first_grid_after",
    "installation_start",
    "predict_latch",
    "origin_error_pulses",
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
    rd.report("ZN143", f"{label} direction: {as_written(raw)} is not a direction; use \"negative\" or "
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
            close = close_matches(key, HOMING_KEYS, n=1)
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
        q = read_number(rd, table[key], f"{label} {key}", span(key))
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
    """The ``[homing]`` parser, listed in :data:`nczones.machine.SECTION_PARSERS`.

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
        rd.report("ZN141", f"[homing]: expected one table per axis such as [homing.X], got {as_written(raw)}",
                  rd.loc.key("homing", None))
        return MappingProxyType(out)
    for axis, table in raw.items():
        if not isinstance(table, Mapping):
            if axis in HOMING_KEYS:
                msg = (f"[homing] {axis}: {axis!r} is a per-axis key; put it under [homing.<axis>] "
                       f"(such as [homing.X]), not directly under [homing]")
            else:
                msg = f"[homing] {axis}: expected a table [homing.{axis}], got {as_written(table)}"
            rd.report("ZN141", msg, rd.loc.key(axis, header))
            continue
        if axis not in axes:
            close = close_matches(axis, axes, n=1)
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


def first_grid_after(a: Fraction, residue: Fraction, pitch: Fraction) -> tuple[int, Fraction]:
    """Index k and value of the first ``residue + k*pitch`` strictly greater than ``a``.

    >>> first_grid_after(Fraction(7), Fraction(3), Fraction(10))
    (1, Fraction(13, 1))
    >>> first_grid_after(Fraction(13), Fraction(3), Fraction(10))
    (2, Fraction(23, 1))
    """
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
    _, g = first_grid_after(sigma_a, (d * phase) % cfg.grid_pitch, cfg.grid_pitch)
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
    _, g = first_grid_after(a1, (d * phase) % cfg.grid_pitch, cfg.grid_pitch)
    return cfg.switch_jitter == 0 or g > a1 + 2 * cfg.switch_jitter


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



def origin_error_pulses(
    cfg: HomingConfig,
    pulse: Fraction,
    phase: Fraction,
    trip_offset: Fraction,
    *,
    install_trip_offset: Fraction = Fraction(0),
    grid_shift: Fraction | None = None,
) -> int:
    """Controller zero minus machine zero after homing, in pulses (closed form).

    The grid shift is ``grid_shift`` when given, else the stored one at the
    configured phase, else the one installation measures with the switch
    tripping at ``install_trip_offset``: ``machine_zero`` minus the latch
    there.  Homing then ends at its latch plus that shift.

    >>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5),
    ...                    Fraction(20), Fraction(10), Fraction(3), switch_jitter=Fraction(1, 50))
    >>> u = Fraction(1, 1000)
    >>> origin_error_pulses(cfg, u, Fraction(3), Fraction(1, 50))
    0
    >>> origin_error_pulses(cfg, u, Fraction(5), Fraction(-1, 100), install_trip_offset=Fraction(1, 100))
    10000
    """
    zero = int(cfg.machine_zero / pulse)
    if grid_shift is None and cfg.grid_shift is not None and phase == cfg.detector_phase:
        grid_shift = cfg.grid_shift
    if grid_shift is None:
        shift = zero - predict_latch(cfg, pulse, phase, install_trip_offset)
    else:
        shift = int(grid_shift / pulse)
    return predict_latch(cfg, pulse, phase, trip_offset) + shift - zero
