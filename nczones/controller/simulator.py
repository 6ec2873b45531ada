"""The reference controller: runs motion segments pulse by pulse.

One :class:`Controller` holds what a controller holds: the current-position
counter per axis (integer pulses; what the limit monitor reads), the movement
direction register (which (axis, sign) directions are still allowed after an
alarm), the temporary machine coordinates of program-check mode, and a clock.

Per motion it plans the pulses (:mod:`.pulses`), decides when each pulse
happens (feed, rapid rates, acc/dec before interpolation), runs the limit
monitor after every pulse or every ``monitor_period_ms``, and logs.

Modes (DESIGN §6; program check after CN patent 002):

``normal``
    The counter follows the pulses; the monitor reads it.
``lock``
    Machine lock: interpolation runs but zero pulses reach the axes; the
    machine coordinates stay frozen, so the stroke check sees only the frozen
    position — **a program that leaves the allowed set raises no alarm**.
    The result says so in ``blind_spot``.
``check``
    Program check: the axes stay still, *temporary* machine coordinates
    follow the interpolation and the stroke check runs on them; feed at the
    system maximum (the rapid rates), acc/dec skipped.  The real machine
    coordinates are unchanged afterwards.

Two engines give the same answers: ``engine="vector"`` computes long lines in
numpy chunks and checks them with the compiled integer monitor;
``engine="reference"`` runs one pulse per Python iteration with the reference
monitor.  Tests compare them.

Time is kept in float seconds: it decides *when* the periodic monitor
samples, never *where* a pulse lands.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidArgument, program_lines
from ..exact import format_decimal, seconds
from ..machine import Axis, Machine, RapidMode
from ..motion import Segment, SegmentKind, segments_of, tip_offset
from ..zones import tip_shifted
from .arcs import ArcStream, HelixColumns, path_fractions_moved, unwrap
from .blending import BlendArc, arc_pulse_positions, blend_motion, blends
from .cylindrical import developed_arc_walk
from .monitor import LimitMonitor
from .polar import polar_walk
from .pulses import (
    LINE_CHUNK,
    arc_centre,
    arc_walk,
    dogleg_steps,
    helix_steps,
    line_chunk,
    line_position,
    line_steps,
    round_pulse,
    step_deltas,
)
from .solids import SolidHit, controller_solids, unchecked_solids
from .spline import spline_walk

__all__ = [
    "Mode",
    "MonitorMode",
    "Settings",
    "Alarm",
    "Event",
    "ServoLog",
    "JogResult",
    "SimulationResult",
    "Controller",
    "simulate",
]


class Mode(enum.Enum):
    NORMAL = "normal"
    LOCK = "lock"
    CHECK = "check"


class MonitorMode(enum.Enum):
    PULSE = "pulse"  # after every pulse (every interpolation step)
    PERIODIC = "periodic"  # every machine.monitor_period_ms


@dataclass(frozen=True, slots=True)
class Settings:
    """Controller parameters the machine file does not carry.

    ``pre_time_constant_ms``: acc/dec before interpolation — the feed ramps
    linearly from 0 to the programmed feed in this time and back to 0 at the
    end of every block (exact stop).  ``post_time_constant_ms``: the filter on
    each axis' commanded position after interpolation (``post_filter``
    ``"exponential"`` first-order lag, or ``"linear"`` moving average);
    a mapping axis -> ms gives one per axis.  The filtered servo output is
    logged at ``servo_period_ms`` (normal mode only).  ``engine`` is
    ``"vector"`` or ``"reference"``.  ``blending`` (``nczones.controller.blending``): ``"auto"`` rounds corners
    with LinuxCNC's blend arcs where the machine starts in G64 (LinuxCNC dialect, ``[machine.acceleration]``
    given), ``"linuxcnc"`` always, ``"exact"`` never (the programmed path).
    """

    pre_time_constant_ms: Fraction = Fraction(0)
    post_time_constant_ms: Fraction | tuple[tuple[str, Fraction], ...] = Fraction(0)
    post_filter: str = "exponential"
    servo_period_ms: Fraction = Fraction(1)
    servo_max_samples: int = 200_000
    engine: str = "vector"
    log_motions: bool = True
    blending: str = "auto"

    def post_tau_ms(self, axis: str) -> float:
        v = self.post_time_constant_ms
        if isinstance(v, tuple):
            return float(dict(v).get(axis, 0))
        return float(v)


@dataclass(frozen=True, slots=True)
class Alarm:
    """A stroke (limit) alarm.

    ``position`` is the commanded pulse position in mm (exact) where the
    monitor saw the violation; ``blocked`` the (axis, sign) directions
    cleared from the movement register.  With periodic monitoring,
    ``first_outside`` is the first pulse position of the motion that was
    outside and ``overshoot_pulses`` how many interpolation steps later the
    monitor caught it.
    """

    block: int | None
    line: int | None
    source: str
    zone: str
    zones: tuple[str, ...]
    position: tuple[Fraction, ...]
    pulse_position: tuple[int, ...]
    time_s: float
    blocked: tuple[tuple[str, int], ...]
    derived: str = ""
    first_outside: tuple[Fraction, ...] | None = None
    overshoot_pulses: int = 0
    kind: str = "stroke"
    #: a ``"solid"`` alarm: the part that entered the fixture ``zone`` (its label, as the prover names it)
    part: str = ""


@dataclass(frozen=True, slots=True)
class Event:
    """One event-log entry; ``data`` is a tuple of (key, value) pairs."""

    time_s: float
    kind: str  # mode, motion, dwell, alarm, halt, jog, jog-refused, alarm-cleared, end, note
    block: int | None = None
    line: int | None = None
    data: tuple[tuple[str, Any], ...] = ()


@dataclass(frozen=True, slots=True)
class ServoLog:
    """Commanded position (counter) and filtered servo output, sampled (floats, mm).

    ``max_deviation_mm`` is the largest distance between the servo output and
    the commanded path (the polyline of commanded samples): the corner
    rounding that post-interpolation filtering causes.
    """

    time_s: np.ndarray
    commanded_mm: np.ndarray
    output_mm: np.ndarray
    max_deviation_mm: float
    max_deviation_time_s: float
    filter: str
    time_constants_ms: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class JogResult:
    axis: str
    requested: int
    moved: int
    refused: bool
    alarm: Alarm | None
    position: tuple[Fraction, ...]


@dataclass(frozen=True, slots=True)
class SimulationResult:
    """Everything one run produced (frozen).

    ``machine_position`` is where the real axes stand at the end (unchanged in
    ``lock`` and ``check``); ``temporary_position`` the temporary machine
    coordinates of ``check`` (None otherwise); ``program_position`` where the
    interpolation ended.  ``pulses`` counts the pulses the interpolator
    distributed per axis (absolute); ``servo_pulses`` those that reached the
    axes (zero in ``lock`` and ``check``).
    """

    mode: Mode
    monitor: MonitorMode
    axes: tuple[str, ...]
    alarms: tuple[Alarm, ...]
    completed: bool
    machine_position: tuple[Fraction, ...]
    temporary_position: tuple[Fraction, ...] | None
    program_position: tuple[Fraction, ...]
    pulses: tuple[int, ...]
    servo_pulses: tuple[int, ...]
    simulated_time_s: float
    motions: int
    steps: int
    events: tuple[Event, ...]
    monitor_checks: int
    max_lookup_comparisons: int
    max_regions: int
    overshoot_bound_mm: float
    blind_spot: str | None
    servo: ServoLog | None = None
    notes: tuple[str, ...] = ()

    @property
    def alarmed(self) -> bool:
        return bool(self.alarms)

    def to_json(self) -> dict[str, Any]:
        """The JSON form of ``nczones simulate`` (``specs/simulate.schema.json``)."""

        def pt(coords: Sequence[Fraction] | None) -> dict[str, str] | None:
            if coords is None:
                return None
            return {a: format_decimal(c) for a, c in zip(self.axes, coords)}

        return {
            "mode": self.mode.value,
            "monitor": self.monitor.value,
            "completed": self.completed,
            "alarms": [
                {
                    "kind": a.kind,
                    **({"part": a.part} if a.part else {}),
                    "line": a.line,
                    "block": a.block,
                    "source": a.source,
                    "zone": a.zone,
                    "zones": list(a.zones),
                    "position": pt(a.position),
                    "pulse_position": dict(zip(self.axes, a.pulse_position)),
                    "time_s": seconds(a.time_s),
                    "blocked": [f"{ax}{'+' if s > 0 else '-'}" for ax, s in a.blocked],
                    "first_outside": pt(a.first_outside),
                    "overshoot_pulses": a.overshoot_pulses,
                }
                for a in self.alarms
            ],
            "machine_position": pt(self.machine_position),
            "temporary_position": pt(self.temporary_position),
            "program_position": pt(self.program_position),
            "pulses": dict(zip(self.axes, self.pulses)),
            "servo_pulses": dict(zip(self.axes, self.servo_pulses)),
            "simulated_time_s": seconds(self.simulated_time_s),
            "motions": self.motions,
            "steps": self.steps,
            "monitor_checks": self.monitor_checks,
            "max_lookup_comparisons": self.max_lookup_comparisons,
            "overshoot_bound_mm": self.overshoot_bound_mm,
            "blind_spot": self.blind_spot,
            "servo_max_deviation_mm": None if self.servo is None else self.servo.max_deviation_mm,
            "notes": list(self.notes),
            "events": [
                {"time_s": seconds(e.time_s), "kind": e.kind, "block": e.block, "line": e.line, "data": _jsonable(dict(e.data))}
                for e in self.events
            ],
        }


def _jsonable(v: Any) -> Any:
    if isinstance(v, Fraction):
        return format_decimal(v)
    if isinstance(v, dict):
        return {str(k): _jsonable(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_jsonable(x) for x in v]
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (np.floating,)):
        return float(v)
    return v


# --------------------------------------------------------------------------- motion plans


@dataclass(slots=True)
class _Plan:
    """The pulses of one motion: a line (computed on demand) or explicit positions."""

    seg: Segment
    p0: tuple[int, ...]
    p1: tuple[int, ...]
    n: int
    delta: tuple[int, ...] | None = None  # lines only
    positions: np.ndarray | None = None  # explicit: (n, axes)
    sigma: np.ndarray | None = None  # explicit: path fraction after each step (float)
    exact_times: np.ndarray | None = None  # dogleg: exact step times as int64 ticks (s = ticks / tick_den)
    tick_den: int = 1
    base_time_s: float = 0.0  # duration at constant speed
    accdec: bool = False
    speed_mm_s: float = 0.0
    moved_total: tuple[int, ...] | None = None  # explicit: pulses per axis over all n steps (when known)
    stream: ArcStream | None = None  # lazy: the arc's positions, computed chunk by chunk when it runs
    make: Any = None  # lazy: builds the explicit plan (what anything but the streamed run reads)
    streamed: bool = False  # the stream ran to its end: n and moved_total are known, positions are not kept

    @property
    def lazy(self) -> bool:
        return self.make is not None and self.positions is None and self.delta is None

    def materialize(self) -> None:
        """Turn a lazy plan into an explicit one (the same positions, all at once, with path fractions)."""
        if not self.lazy:
            return
        full = self.make()
        for name in ("n", "positions", "sigma", "base_time_s", "accdec", "speed_mm_s", "moved_total"):
            setattr(self, name, getattr(full, name))
        self.stream, self.streamed = None, False

    def position(self, i: int) -> tuple[int, ...]:
        if i == 0:
            return self.p0
        if self.streamed and i == self.n:  # the stream checked that its last row is p1
            return self.p1
        self.materialize()
        if self.delta is not None:
            return line_position(self.p0, self.delta, self.n, i)
        assert self.positions is not None  # a plan without delta is explicit
        return tuple(int(v) for v in self.positions[i - 1])

    def positions_at(self, idx: np.ndarray) -> np.ndarray:
        """Positions after the given step counts (0 = the start), shape (len(idx), axes)."""
        self.materialize()
        idx = np.asarray(idx, dtype=np.int64)
        if self.delta is not None:
            out = np.empty((len(idx), len(self.p0)), dtype=np.int64)
            n = max(self.n, 1)
            for k, (p, d) in enumerate(zip(self.p0, self.delta)):
                out[:, k] = p + (2 * d * idx + n) // (2 * n) if self.n else p
            return out
        assert self.positions is not None
        rows = np.vstack([np.array(self.p0, dtype=np.int64).reshape(1, -1), self.positions])
        out_rows: np.ndarray = rows[idx]
        return out_rows

    def chunk(self, lo: int, hi: int) -> np.ndarray:
        """Positions after steps lo+1..hi."""
        self.materialize()
        if self.delta is not None:
            return line_chunk(self.p0, self.delta, self.n, lo, hi)
        assert self.positions is not None
        return self.positions[lo:hi]

    def iter_steps(self) -> Iterator[tuple[int, ...]]:
        self.materialize()
        if self.delta is not None:
            yield from line_steps(self.p0, self.p1)
        else:
            assert self.positions is not None
            for row in self.positions.tolist():
                yield tuple(row)

    def duration(self, tau_s: float) -> float:
        if self.exact_times is not None:
            return float(self.exact_times[-1]) / self.tick_den if len(self.exact_times) else 0.0
        if not self.accdec or tau_s <= 0 or self.base_time_s <= 0:
            return self.base_time_s
        T = self.base_time_s
        sa = min(tau_s / (2 * T), 0.5)
        return 2 * math.sqrt(2 * sa * T * tau_s) + (1 - 2 * sa) * T

    def steps_done_at(self, rel_times: np.ndarray, tau_s: float) -> np.ndarray:
        """How many steps are complete at each time (relative to the motion's start)."""
        if self.delta is None or self.n == 0:
            times = self.times(0, self.n, tau_s)
            return np.searchsorted(times, rel_times + 1e-12, side="right")
        # a line: invert the speed profile instead of tabulating every step's time
        T = self.base_time_s
        t = np.asarray(rel_times, dtype=float) + 1e-12
        if not self.accdec or tau_s <= 0 or T <= 0:
            sig = t / T if T > 0 else np.ones_like(t)
        else:
            sa = min(tau_s / (2 * T), 0.5)
            total = self.duration(tau_s)
            ta = math.sqrt(2 * sa * T * tau_s)
            sig = np.where(t <= ta, t * t / (2 * T * tau_s),
                           np.where(t >= total - ta, 1 - np.clip(total - t, 0, None) ** 2 / (2 * T * tau_s),
                                    sa + (t - ta) / T))
        return np.clip(np.floor(sig * self.n + 1e-9), 0, self.n).astype(np.int64)

    def times(self, lo: int, hi: int, tau_s: float) -> np.ndarray:
        """Completion times (s, relative to the motion's start) of steps lo+1..hi."""
        self.materialize()
        if self.exact_times is not None:
            return self.exact_times[lo:hi].astype(float) / self.tick_den
        if self.delta is not None:
            sig = np.arange(lo + 1, hi + 1, dtype=float) / max(self.n, 1)
        else:
            assert self.sigma is not None  # an explicit plan has its path fractions
            sig = self.sigma[lo:hi]
        T = self.base_time_s
        if not self.accdec or tau_s <= 0 or T <= 0:
            return sig * T
        # trapezoidal speed profile (linear acc/dec before interpolation), exact stop per block
        sa = min(tau_s / (2 * T), 0.5)
        total = self.duration(tau_s)
        ta = math.sqrt(2 * sa * T * tau_s)
        out = np.where(
            sig <= sa,
            np.sqrt(2 * np.clip(sig, 0, None) * T * tau_s),
            np.where(sig >= 1 - sa, total - np.sqrt(2 * np.clip(1 - sig, 0, None) * T * tau_s), ta + (sig - sa) * T),
        )
        return out


def plan_from_positions(ctrl: "Controller", seg: Segment, p0: tuple[int, ...], p1: tuple[int, ...],
                        positions: np.ndarray, length_mm: float, what: str) -> "_Plan":
    """A plan that walks precomputed pulse ``positions`` (G07.1 arcs, splines).

    ``length_mm`` is the path length the feed applies to (timing only); the
    walk must end on the rounded end point ``p1``.  Check mode moves at the
    slowest rapid rate without acceleration, like every other motion there.
    """
    n = positions.shape[0]
    if n and tuple(int(v) for v in positions[-1]) != tuple(p1):  # pragma: no cover - by construction
        raise InvalidArgument(f"{what} does not end on its rounded end point")
    sigma = np.arange(1, n + 1, dtype=float) / max(n, 1)
    plan = _Plan(seg, p0, p1, n, positions=positions, sigma=sigma)
    if ctrl.mode is Mode.CHECK:
        rate = min(float(a.rapid_mm_min) for a in ctrl.machine.axes)
        plan.base_time_s = length_mm * 60 / rate
    else:
        if seg.feed_mm_min is None or seg.feed_mm_min <= 0:
            raise InvalidArgument(f"block {seg.block} (line {seg.line}): feed move without a positive feed")
        plan.base_time_s = length_mm * 60 / float(seg.feed_mm_min)
    plan.accdec = ctrl.mode is not Mode.CHECK
    plan.speed_mm_s = length_mm / plan.base_time_s if plan.base_time_s > 0 else 0.0
    return plan


def _sign(v: int) -> int:
    return (v > 0) - (v < 0)


# --------------------------------------------------------------------------- controller


class Controller:
    """A reference NC controller for one machine (mutable; results are frozen).

    Examples
    --------
    >>> from nczones.machine import load_machine
    >>> from nczones.motion import Segment, SegmentKind
    >>> F = Fraction
    >>> m = load_machine("specs/machines/grinder.toml")
    >>> down = Segment(SegmentKind.LINE, (F(300), F(300)), (F(300), F(100)), m.axis_names,
    ...                block=0, feed_mm_min=F(1000))
    >>> c = Controller(m, start=(F(300), F(300)))
    >>> r = c.run([down])
    >>> r.alarms[0].zone, [format_decimal(v) for v in r.alarms[0].position]     # first pulse below Y220
    ('wheel area', ['300', '219.999'])
    >>> c.jog("Y", -5).refused, c.jog("Y", +5).moved                # further out: no; back: yes
    (True, 5)
    """

    def __init__(
        self,
        machine: Machine,
        *,
        mode: Mode | str = Mode.NORMAL,
        monitor: MonitorMode | str = MonitorMode.PULSE,
        settings: Settings | None = None,
        start: Sequence[Fraction] | None = None,
        break_at: tuple[int, Fraction] | None = None,
    ):
        self.machine = machine
        #: tool-break event (source line, fraction of that line's first cutting motion);
        #: :meth:`run` then hands over to :mod:`nczones.controller.recovery`
        self.break_at = break_at
        #: program text lines, to quote an alarm's block when segments carry no text
        self.source_lines: list[str] | None = None
        #: what carries the program's path modes (an interpretation's ``interpreter.path_modes``), when the
        #: motion given to :meth:`run` is not the interpretation itself
        self.mode_source: Any = None
        self.mode = Mode(mode)
        self.monitor_mode = MonitorMode(monitor)
        self.settings = settings or Settings()
        if self.settings.engine not in ("vector", "reference"):
            raise InvalidArgument(f"engine {self.settings.engine!r}: use 'vector' or 'reference'")
        self.axes = machine.axis_names
        self.pulse = tuple(a.pulse for a in machine.axes)
        self.monitor = LimitMonitor(machine)
        self._monitors: dict[tuple, LimitMonitor] = {(): self.monitor}
        #: the tool solids and fixtures (issue 39), checked with the zones by each segment's monitor
        self._solids = controller_solids(machine)
        start = tuple(Fraction(v) for v in (machine.start if start is None else start))
        if len(start) != len(self.axes):
            raise InvalidArgument(f"start has {len(start)} coordinates; the machine has axes {self.axes}")
        p = tuple(round_pulse(v, u) for v, u in zip(start, self.pulse))
        self.real = list(p)  # current-position counter of the real axes
        self.temp = list(p)  # temporary machine coordinates (check mode)
        self.prog = list(p)  # where the interpolation stands (all modes)
        self.blocked: set[tuple[int, int]] = set()
        self.tool_length = Fraction(0)
        self.clock = 0.0
        self.period_s = float(machine.monitor_period_ms) / 1000
        self.next_sample = 1  # index of the next periodic monitor sample
        self.events: list[Event] = []
        self.alarms: list[Alarm] = []
        self.pulses = [0] * len(self.axes)
        self.servo_pulses = [0] * len(self.axes)
        self.steps = 0
        self.motions = 0
        self.halted = False
        self.completed = False
        self.overshoot_bound = 0.0
        self.notes: list[str] = []
        unchecked = unchecked_solids(machine)  # forbidden zones that are no fixture solid (neither checks them)
        if unchecked:
            self.notes.append(unchecked)
        self._pending_outside: tuple[tuple[int, ...], int] | None = None  # periodic: (first outside pos, step)
        self._servo_samples: list[tuple[float, tuple[int, ...]]] = []
        self._servo_on = self.mode is Mode.NORMAL and (
            any(self.settings.post_tau_ms(a) > 0 for a in self.axes)
        )
        self.log("mode", data=(("mode", self.mode.value), ("monitor", self.monitor_mode.value)))

    # ------------------------------------------------------------------ helpers
    def log(self, kind: str, block: int | None = None, line: int | None = None, data: Any = ()) -> None:
        self.events.append(Event(self.clock, kind, block, line, tuple(data)))

    def mm(self, pos: Sequence[int]) -> tuple[Fraction, ...]:
        return tuple(p * u for p, u in zip(pos, self.pulse))

    @property
    def counter(self) -> list[int]:
        """The position counter the monitor reads in this mode."""
        return self.temp if self.mode is Mode.CHECK else self.real

    def _tau_pre(self) -> float:
        if self.mode is Mode.CHECK:
            return 0.0
        return float(self.settings.pre_time_constant_ms) / 1000

    # ------------------------------------------------------------------ planning
    def plan(self, seg: Segment, *, lazy: bool = False) -> _Plan:
        """The pulses of one motion.  ``lazy``: an arc of the vector engine is computed when it runs
        (:meth:`run_plan` streams it chunk by chunk); anything that reads its positions first gets them all."""
        if tuple(seg.axes) != self.axes:
            raise InvalidArgument(f"segment axes {seg.axes} do not match the machine's axes {self.axes}")
        p0 = tuple(self.prog)
        p1 = tuple(round_pulse(v, u) for v, u in zip(seg.end, self.pulse))
        return _PLANNERS[seg.kind](self, seg, p0, p1, lazy)

    def _plan_dwell(self, seg: Segment, p0: tuple[int, ...], p1: tuple[int, ...], lazy: bool = False) -> _Plan:
        return _Plan(seg, p0, p0, 0, delta=tuple(0 for _ in p0), base_time_s=float(seg.dwell_s or 0))

    def _plan_straight(self, seg: Segment, p0: tuple[int, ...], p1: tuple[int, ...], lazy: bool = False) -> _Plan:
        """A line, or a rapid as the machine moves it (straight, or a dogleg when ``rapid_mode = "dogleg"``)."""
        delta = tuple(b - a for a, b in zip(p0, p1))
        check = self.mode is Mode.CHECK
        axes = self.machine.axes
        disp = [float(e - s) for s, e in zip(seg.start, seg.end)]
        if seg.kind is SegmentKind.RAPID and self.machine.rapid_mode is RapidMode.DOGLEG:
            periods = tuple(a.pulse * 60 / a.rapid_mm_min for a in axes)
            pos, ticks, den = dogleg_steps(p0, p1, periods)
            plan = _Plan(seg, p0, p1, len(ticks), positions=pos, exact_times=ticks, tick_den=den)
            plan.speed_mm_s = math.sqrt(sum(float(a.rapid_mm_min) ** 2 for a, d in zip(axes, delta) if d)) / 60
            return plan
        n = max((abs(d) for d in delta), default=0)
        plan = _Plan(seg, p0, p1, n, delta=delta)
        rates = [a.rapid_mm_min for a in axes]
        if seg.kind is SegmentKind.RAPID or check:
            t = max((abs(d) * 60 / float(r) for d, r in zip(disp, rates)), default=0.0)
        else:
            t = self._feed_time(seg, disp, _path_length(axes, disp))
        plan.base_time_s = t
        plan.accdec = not check
        plan.speed_mm_s = _path_length(axes, disp) / t if t > 0 else 0.0
        return plan

    def _plan_developed(self, seg: Segment, p0: tuple[int, ...], p1: tuple[int, ...], lazy: bool = False) -> _Plan:
        pos, length = developed_arc_walk(seg, self.pulse, p0)  # G07.1: developed plane, then rotary pulses
        return plan_from_positions(self, seg, p0, p1, pos, length, "developed arc")

    def _plan_polar(self, seg: Segment, p0: tuple[int, ...], p1: tuple[int, ...], lazy: bool = False) -> _Plan:
        pos, length = polar_walk(seg, self.pulse, p0)  # G12.1: the plane path converted to X and C
        return plan_from_positions(self, seg, p0, p1, pos, length, "polar move")

    def _plan_spline(self, seg: Segment, p0: tuple[int, ...], p1: tuple[int, ...], lazy: bool = False) -> _Plan:
        pos, length = spline_walk(seg, self.pulse, p0)  # exact NURBS: flattened chords, see controller/spline.py
        return plan_from_positions(self, seg, p0, p1, pos, length, "spline")

    def _feed_time(self, seg: Segment, disp: list[float], length: float) -> float:
        if seg.feed_mm_min is None or seg.feed_mm_min <= 0:
            raise InvalidArgument(
                f"block {seg.block} (line {seg.line}): feed move without a positive feed (F = {seg.feed_mm_min})"
            )
        t = length * 60 / float(seg.feed_mm_min)
        for a, d in zip(self.machine.axes, disp):  # no axis faster than its maximum feed
            t = max(t, abs(d) * 60 / float(a.max_feed_mm_min))
        return t

    def _plan_arc(self, seg: Segment, p0: tuple[int, ...], p1: tuple[int, ...], lazy: bool = False) -> _Plan:
        i, j, _ = seg.plane_indices()
        s2 = (seg.start[i], seg.start[j])
        e2 = (seg.end[i], seg.end[j])
        if seg.centre is not None:
            centre = seg.centre
        else:
            if seg.radius is None:
                raise InvalidArgument(f"block {seg.block}: arc without centre or radius")
            centre, err = arc_centre(s2, e2, seg.radius, seg.clockwise)
            if err > min(self.pulse[i], self.pulse[j]) / 10**6:  # pragma: no cover - 64-bit enclosure
                raise InvalidArgument("R-format arc centre enclosure is not far inside one pulse")
        walk_args = ((p0[i], p0[j]), (p1[i], p1[j]), s2, e2, centre, seg.clockwise, seg.turns,
                     (self.pulse[i], self.pulse[j]))
        # helix axes follow the swept angle (float angle; rounding to the nearest pulse)
        helix = [k for k in range(len(p0)) if k not in (i, j) and p1[k] != p0[k]]
        cx, cy = float(centre[0]), float(centre[1])
        sgn = -1.0 if seg.clockwise else 1.0
        a0 = math.atan2(sgn * (float(s2[1]) - cy), float(s2[0]) - cx)
        pulse2 = (float(self.pulse[i]), float(self.pulse[j]))
        helix_cols = [(k, p0[k], p1[k]) for k in helix]
        helix_len2 = sum(float(seg.end[k] - seg.start[k]) ** 2 for k in range(len(p0))
                         if k not in (i, j) and not self.machine.axes[k].rotary)
        if self.settings.engine == "vector":  # the same positions as the reference, in chunks (controller/arcs.py)
            stream = ArcStream(len(p0), i, j, walk_args, p0, helix_cols, (pulse2, (cx, cy), sgn, a0))
            sweep_rad, radius_mm = stream.sweep_rad, stream.radius_mm
            if lazy and stream.vectorized:
                plan = _Plan(seg, p0, p1, 0, stream=stream, make=lambda: self._plan_arc(seg, p0, p1))
                self._time_arc(plan, seg, i, j, p0, p1, math.sqrt((radius_mm * sweep_rad) ** 2 + helix_len2))
                return plan
            pos = stream.positions()
        else:
            walk = arc_walk(*walk_args)
            sweep_rad, radius_mm = walk.sweep_rad, walk.radius_mm
            pos = np.empty((len(walk.points), len(p0)), dtype=np.int64)
            pos[:, [i, j]] = np.array(walk.points, dtype=np.int64).reshape(-1, 2)
            if len(pos):
                if helix:
                    _helix_columns(pos, (i, j), pulse2, (cx, cy), sgn, a0, sweep_rad, helix_cols)
                for k in range(len(p0)):
                    if k not in (i, j) and p1[k] == p0[k]:  # floor(phi * 0 + 0.5) == 0: the axis stands still
                        pos[:, k] = p0[k]
                if helix:  # a steep helix: interleave its pulses, at most one pulse per axis per step
                    pos = np.array(helix_steps(pos.tolist(), p0, helix), dtype=np.int64).reshape(-1, len(p0))
        n = pos.shape[0]
        if n == 0 and p1 != p0:  # no step in the plane (a circle below two pulses), only the helix moves
            rows = list(line_steps(p0, p1))
            plan = _Plan(seg, p0, p1, len(rows), positions=np.array(rows, dtype=np.int64),
                         sigma=np.arange(1, len(rows) + 1) / len(rows))
            plan.base_time_s = self._feed_time(seg, [float(e - s) for s, e in zip(seg.start, seg.end)],
                                               _path_length(self.machine.axes, [float(e - s) for s, e in zip(seg.start, seg.end)]))
            plan.accdec = self.mode is not Mode.CHECK
            return plan
        # path fraction after each step: cumulative chord length (floats, timing only)
        moving = [k for k in range(len(p0)) if k in (i, j) or k in helix]
        sigma, moved = path_fractions_moved(pos, p0, self.pulse, moving)
        plan = _Plan(seg, p0, p1, n, positions=pos, sigma=sigma, moved_total=moved)
        self._time_arc(plan, seg, i, j, p0, p1, math.sqrt((radius_mm * sweep_rad) ** 2 + helix_len2))
        return plan

    def _time_arc(self, plan: _Plan, seg: Segment, i: int, j: int, p0: tuple[int, ...], p1: tuple[int, ...],
                  length: float) -> None:
        if self.mode is Mode.CHECK:
            rate = min(float(a.rapid_mm_min) for k, a in enumerate(self.machine.axes) if k in (i, j) or p1[k] != p0[k])
            plan.base_time_s = length * 60 / rate
        else:
            disp = [float(e - s) for s, e in zip(seg.start, seg.end)]
            plan.base_time_s = self._feed_time(seg, [0.0 if k in (i, j) else d for k, d in enumerate(disp)], length)
        plan.accdec = self.mode is not Mode.CHECK
        plan.speed_mm_s = length / plan.base_time_s if plan.base_time_s > 0 else 0.0

    # ------------------------------------------------------------------ running
    def run(self, motion: Any) -> SimulationResult:
        """Run segments (or MotionChunks, or an interpretation) to the end or the first alarm."""
        if self.break_at is not None:
            from .recovery import run_with_break

            recovered: SimulationResult = run_with_break(self, motion)
            return recovered
        if self.mode is not Mode.LOCK and not self.alarms:
            bad = self.monitor.check(tuple(self.counter), self.tool_length)
            if bad:
                self.record_alarm(None, tuple(self.counter), bad, (), note="start position outside the allowed set")
        skipped = 0
        items: Iterable[Segment | BlendArc] = segments_of(motion)
        if blends(self.machine, self.settings.blending):
            self.log("blending", data=(("planner", "linuxcnc"),))
            items = blend_motion(segments_of(motion), self.machine,
                                 motion if self.mode_source is None else self.mode_source)
        for seg in items:
            if self.halted:
                skipped += 1
                continue
            if isinstance(seg, BlendArc):
                self.run_blend(seg)
            else:
                self.run_segment(seg)
        if self.halted and skipped:
            self.log("halt", data=(("blocks_not_run", skipped),))
        if not self.halted:
            self.final_sample()
            self.completed = not self.halted
        self.log("end", data=(("completed", self.completed),))
        return self.result()

    def run_segment(self, seg: Segment) -> None:
        before = (self.monitor, self.tool_length)
        self.tool_length = seg.tool_length
        self.monitor = self._monitor_for(seg)
        plan = self.plan(seg, lazy=True)
        if (self.monitor is not before[0] or self.tool_length != before[1]) and self._solids_at_start(plan):
            return
        self.run_plan(seg, plan)

    def _solids_at_start(self, plan: _Plan) -> bool:
        """A tool change (another assembly, another length) at rest: the new parts are checked where they are
        put, before the motion's first pulse (the steps after it are covered by the per-pulse check)."""
        solids = self.monitor.solids
        if solids is None or self.mode is Mode.LOCK or self.halted:
            return False
        hits = solids.check(tuple(self.counter), self.tool_length)
        if hits:
            self.record_alarm(plan, tuple(self.counter), hits, (), note="tool change")
        return bool(hits)

    def run_blend(self, arc: BlendArc) -> None:
        """Run a blend arc (``nczones.controller.blending``) as the motion of its corner's first block."""
        seg = replace(arc.seg, kind=SegmentKind.LINE, start=tuple(Fraction(v) for v in arc.start),
                      end=tuple(Fraction(v) for v in arc.end), feed_mm_min=Fraction(arc.speed_mm_s * 60),
                      derived=arc.label)
        self.tool_length = seg.tool_length
        self.monitor = self._monitor_for(seg)
        p0 = tuple(self.prog)
        pos = arc_pulse_positions(arc, self.pulse, p0)
        p1 = tuple(int(v) for v in pos[-1]) if len(pos) else p0
        self.run_plan(seg, plan_from_positions(self, seg, p0, p1, pos, arc.radius * arc.sweep, "blend arc"))

    def _monitor_for(self, seg: Segment) -> LimitMonitor:
        """The limit monitor for a segment: a lathe tool offset on an axis besides the tool axis moves the tool
        tip away from the machine position there, so the tip zones are checked moved by it (shared counts);
        on a machine with tool solids, the monitor also checks the parts of the segment's tool (its register; a
        lathe's T word tool) against the fixtures where the segment sees them (one in a work offset moved by
        the offset the segment carries)."""
        shift = tip_offset(seg.extra) if seg.extra else {}
        key: tuple = tuple(sorted(shift.items()))
        if self._solids is not None:  # one monitor per (shift, tool, fixture placement): never the base one
            key = (key, "tool", self._solids.key(seg))
        mon = self._monitors.get(key)
        if mon is None:
            from dataclasses import replace as _replace

            base = self._monitors[()]
            mon = LimitMonitor(_replace(self.machine, allowed=tip_shifted(self.machine.allowed, shift)),
                               stats=base.stats,
                               solids=None if self._solids is None else self._solids.for_segment(seg))
            self._monitors[key] = mon
        return mon

    def run_plan(self, seg: Segment, plan: _Plan) -> None:
        """Run one planned motion (the recovery runs parts of plans through this)."""
        streamed = None
        if plan.lazy:
            streamed = self._run_stream(plan)
            if streamed is None or streamed[1] is not None:  # not streamable, or an alarm: the rest reads the plan
                plan.materialize()
        self.motions += 1
        tau = self._tau_pre()
        t0 = self.clock
        if plan.n == 0:
            dur = plan.duration(tau)
            if self.mode is not Mode.LOCK and self.monitor_mode is MonitorMode.PERIODIC:
                self._samples_at_rest(plan, t0 + dur)
            if not self.halted:
                self.clock = t0 + dur
                if seg.kind is SegmentKind.DWELL:
                    self.log("dwell", seg.block, seg.line, (("seconds", float(seg.dwell_s or 0)),))
            return
        self.overshoot_bound = max(self.overshoot_bound, plan.speed_mm_s * self.period_s)
        if streamed is not None:
            done, alarm = streamed
        elif self.mode is Mode.LOCK:
            done, alarm = plan.n, None
        elif self.monitor_mode is MonitorMode.PULSE:
            done, alarm = self._monitor_pulse(plan)
        else:
            done, alarm = self._monitor_periodic(plan, t0, tau)
        pos = plan.position(done)
        self._account(plan, done)
        self.prog[:] = pos
        if self.mode is Mode.NORMAL:
            self.real[:] = pos
        elif self.mode is Mode.CHECK:
            self.temp[:] = pos
        if alarm is not None:
            self.clock = t0 + (float(plan.times(done - 1, done, tau)[0]) if done else 0.0)
            if self.monitor_mode is MonitorMode.PERIODIC:
                self.clock = max(self.clock, alarm[2])
            self.record_alarm(plan, pos, alarm[0], self._direction(plan, done), first=alarm[1])
        else:
            self.clock = t0 + plan.duration(tau)
        if self._servo_on:
            self._servo_collect(plan, t0, tau, done)
        if self.settings.log_motions:
            d = tuple(b - a for a, b in zip(plan.p0, pos))
            self.log("motion", seg.block, seg.line, (
                ("kind", seg.kind.name.lower()), ("steps", done), ("net_pulses", dict(zip(self.axes, d))),
                ("start_s", t0), ("end_s", self.clock),
            ))

    def _account(self, plan: _Plan, done: int) -> None:
        if done == 0:
            return
        if plan.delta is not None:
            moved = [abs(b - a) for a, b in zip(plan.p0, plan.position(done))]
        elif done == plan.n and plan.moved_total is not None:
            moved = list(plan.moved_total)
        else:
            plan.materialize()
            assert plan.positions is not None
            rows = np.vstack([np.array(plan.p0, dtype=np.int64), plan.positions[:done]])
            moved = np.abs(np.diff(rows, axis=0)).sum(axis=0).tolist()
        for k, m in enumerate(moved):
            self.pulses[k] += int(m)
            if self.mode is Mode.NORMAL:
                self.servo_pulses[k] += int(m)
        self.steps += done

    def _direction(self, plan: _Plan, done: int) -> tuple[tuple[int, int], ...]:
        """The direction of motion at the alarm: what gets cleared from the register."""
        if plan.delta is not None:
            d = plan.delta
        else:
            back = plan.position(max(done - 8, 0))
            d = tuple(b - a for a, b in zip(back, plan.position(done)))
        return tuple((k, _sign(v)) for k, v in enumerate(d) if v)

    # per-pulse monitoring ------------------------------------------------------
    def _run_stream(self, plan: _Plan) -> tuple[int, Any] | None:
        """Monitor a lazy arc chunk by chunk as its stream computes it: ``(done, alarm)`` as
        :meth:`_monitor_pulse` gives them, or None when the plan must be explicit (another monitor mode, the
        reference monitor, the servo log, an empty walk).

        Nothing of the arc's size is kept: per chunk, the compiled monitor (which stops at the first
        position outside, exactly as on the explicit plan) and the pulses each moving axis made.  A run
        to the end leaves ``n`` and the pulse totals in the plan; its last position is ``p1``.
        """
        stream = plan.stream
        lock = self.mode is Mode.LOCK
        if stream is None or self.settings.engine != "vector" or self._servo_on:
            return None
        if not lock and self.monitor_mode is not MonitorMode.PULSE:
            return None
        compiled = None if lock else self.monitor.compile(self.tool_length)
        if compiled is None and not lock:
            return None
        moving = sorted({stream.i, stream.j, *(k for k, _, _ in stream.helix)})
        totals = [0] * len(plan.p0)
        prev = [np.int64(plan.p0[k]) for k in moving]
        done = 0
        last: tuple[int, ...] = plan.p0
        for rows in stream.chunks():
            if compiled is not None:
                bad = compiled.bad(rows)
                if bad.any():
                    i = int(np.argmax(bad))
                    return done + i + 1, (compiled.violated(np.ascontiguousarray(rows[i])), None, 0.0)
            for c, k in enumerate(moving):
                col = rows[:, k]
                totals[k] += int(np.count_nonzero(step_deltas(col, prev[c])))
                prev[c] = col[-1]
            done += len(rows)
            last = tuple(int(v) for v in rows[-1])
        if not done:
            return None
        if last != plan.p1:  # pragma: no cover - by construction (the walk's approach and the helix end)
            raise InvalidArgument("arc does not end on its rounded end point")
        plan.n, plan.moved_total, plan.streamed = done, tuple(totals), True
        return done, None

    def _monitor_pulse(self, plan: _Plan) -> tuple[int, Any]:
        tl = self.tool_length
        compiled = self.monitor.compile(tl) if self.settings.engine == "vector" else None
        if compiled is not None:
            for lo in range(0, plan.n, LINE_CHUNK):
                hi = min(plan.n, lo + LINE_CHUNK)
                try:
                    pos = plan.chunk(lo, hi)
                except InvalidArgument:
                    compiled = None
                    break
                bad = compiled.bad(pos)
                if bad.any():
                    i = int(np.argmax(bad))
                    return lo + i + 1, (compiled.violated(pos[i]), None, 0.0)
            if compiled is not None:
                return plan.n, None
        for i, p in enumerate(plan.iter_steps(), start=1):
            names = self.monitor.check(p, tl)
            if names:
                return i, (names, None, 0.0)
        return plan.n, None

    # periodic monitoring ----------------------------------------------------------
    def _sample_times(self, t_end: float) -> list[float]:
        out = []
        k = self.next_sample
        while k * self.period_s <= t_end + 1e-12:
            out.append(k * self.period_s)
            k += 1
        return out

    def _monitor_periodic(self, plan: _Plan, t0: float, tau: float) -> tuple[int, Any]:
        tl = self.tool_length
        end = t0 + plan.duration(tau)
        samples = self._sample_times(end)
        if samples:
            idx = plan.steps_done_at(np.array(samples) - t0, tau)
        else:
            idx = np.zeros(0, dtype=np.int64)
        compiled = self.monitor.compile(tl) if self.settings.engine == "vector" else None
        if compiled is not None and len(idx) and plan.n < 2**30:
            # all samples of this motion at once; only the first bad one matters
            bad = compiled.bad(plan.positions_at(idx))
            if bad.any():
                first_bad = int(np.argmax(bad))
                self.next_sample += first_bad
                samples, idx = samples[first_bad:], idx[first_bad:]
            else:
                self.next_sample += len(samples)
                samples, idx = [], idx[:0]
        for s_time, i in zip(samples, idx.tolist()):
            self.next_sample += 1
            pos = plan.position(int(i))
            names = (self.monitor.check(pos, tl) if compiled is None
                     else compiled.violated(np.array(pos, dtype=np.int64)))
            if names:
                first = self._first_outside(plan, int(i), compiled)
                return int(i), (names, first, s_time)
        # remember where the path first left, for the overshoot report of a later sample
        end_pos = plan.position(plan.n)
        out = self.monitor.check(end_pos, tl) if compiled is None else compiled.violated(np.array(end_pos, dtype=np.int64))
        self._pending_outside = self._first_outside(plan, plan.n, compiled) if out else None
        return plan.n, None

    def _first_outside(self, plan: _Plan, upto: int, compiled: Any) -> tuple[tuple[int, ...], int] | None:
        """Where the excursion the monitor caught at step ``upto`` began (for the report).

        That is the step after the last inside step of this motion up to
        ``upto``; when every step so far is outside, the excursion began in an
        earlier motion (``_pending_outside``), or at this motion's first step.
        """
        last_inside = None
        if compiled is not None:
            for lo in range(0, upto, LINE_CHUNK):
                hi = min(upto, lo + LINE_CHUNK)
                inside = np.flatnonzero(~compiled.bad(plan.chunk(lo, hi)))
                if inside.size:
                    last_inside = lo + int(inside[-1]) + 1
        else:
            for i, p in enumerate(plan.iter_steps(), start=1):
                if i > upto:
                    break
                if not self.monitor.check(p, self.tool_length):
                    last_inside = i
        if last_inside is None and self._pending_outside is not None:
            return self._pending_outside
        i = 1 if last_inside is None else last_inside + 1
        if i > upto:
            return None
        return plan.position(i), self.steps + i

    def _samples_at_rest(self, plan: _Plan, t_end: float) -> None:
        pos = tuple(self.counter)
        for s_time in self._sample_times(t_end):
            self.next_sample += 1
            bad = self.monitor.check(pos, self.tool_length)
            if bad:
                self.clock = s_time
                self.record_alarm(plan, pos, bad, (), first=self._pending_outside)
                return

    def final_sample(self) -> None:
        """Periodic monitoring keeps sampling after the program ends: one more tick."""
        if self.mode is Mode.LOCK or self.monitor_mode is not MonitorMode.PERIODIC:
            return
        k = max(self.next_sample, math.floor(self.clock / self.period_s) + 1)
        pos = tuple(self.counter)
        bad = self.monitor.check(pos, self.tool_length)
        if bad:
            self.clock = k * self.period_s
            self.record_alarm(None, pos, bad, (), first=self._pending_outside)

    # alarms and jog -------------------------------------------------------------
    def record_alarm(self, plan: _Plan | None, pos: Any, zones: Any, direction: Any, first: Any = None,
               note: str = "") -> None:
        seg = plan.seg if plan is not None else None
        for d in direction:
            self.blocked.add(d)
        first_pos, overshoot = None, 0
        if first is not None:
            first_pos = self.mm(first[0])
            overshoot = max(0, self.steps - first[1])
        alarm = Alarm(
            block=None if seg is None else seg.block,
            line=None if seg is None else seg.line,
            source=self._source_of(seg),
            zone=zones[0], zones=tuple(zones), position=self.mm(pos), pulse_position=tuple(int(p) for p in pos),
            time_s=self.clock, blocked=tuple((self.axes[k], s) for k, s in direction),
            derived="" if seg is None else seg.derived, first_outside=first_pos, overshoot_pulses=overshoot,
            kind="solid" if isinstance(zones[0], SolidHit) else "stroke",
            part=zones[0].part.label() if isinstance(zones[0], SolidHit) else "",
        )
        if isinstance(zones[0], SolidHit):
            note = "; ".join(n for n in (zones[0].note(alarm.position, self.axes), note) if n)
        self.alarms.append(alarm)
        self.halted = True
        self.log("alarm", alarm.block, alarm.line, (
            ("zone", alarm.zone), ("position", dict(zip(self.axes, alarm.position))),
            ("blocked", [f"{a}{'+' if s > 0 else '-'}" for a, s in alarm.blocked]), ("note", note),
        ))

    def _source_of(self, seg: Segment | None) -> str:
        """The block's source text (column chunks carry only line numbers)."""
        if seg is None or seg.span is None:
            return ""
        if seg.span.text:
            return seg.span.text.strip()
        lines = self.source_lines
        if lines and seg.span.line is not None and 1 <= seg.span.line <= len(lines):
            return lines[seg.span.line - 1].strip()
        return ""

    def jog(self, axis: str, pulses: int) -> JogResult:
        """Jog one axis by ``pulses`` (signed), pulse by pulse, monitored after each pulse.

        A direction cleared by an alarm is refused outright (nothing moves); any
        other direction moves.  Reaching the allowed set again clears the alarm
        state and re-enables every direction; leaving it raises a new alarm and
        stops the jog.  The jog moves the counter the monitor reads (the real
        axes in normal mode, the temporary coordinates in check mode).
        """
        if axis not in self.axes:
            raise InvalidArgument(f"jog: unknown axis {axis!r}; the machine's axes are {', '.join(self.axes)}")
        k = self.axes.index(axis)
        s = _sign(pulses)
        counter = self.counter
        if s == 0:
            return JogResult(axis, pulses, 0, False, None, self.mm(counter))
        if (k, s) in self.blocked:
            self.log("jog-refused", data=(("axis", axis), ("pulses", pulses)))
            return JogResult(axis, pulses, 0, True, None, self.mm(counter))
        moved, alarm = 0, None
        outside = bool(self.monitor.check(tuple(counter), self.tool_length))
        speed = float(self.machine.axes[k].rapid_mm_min) / 60 / 10  # jog at a tenth of rapid
        for _ in range(abs(pulses)):
            counter[k] += s
            self.prog[k] = counter[k]
            moved += 1
            self.pulses[k] += 1
            if self.mode is Mode.NORMAL:
                self.servo_pulses[k] += 1
            self.clock += float(self.pulse[k]) / speed
            bad = self.monitor.check(tuple(counter), self.tool_length)
            if outside and not bad:
                outside = False
                self.blocked.clear()
                self.log("alarm-cleared", data=(("position", dict(zip(self.axes, self.mm(counter)))),))
            elif bad and not outside:
                self.blocked.add((k, s))
                seg = None
                self.record_alarm(seg, tuple(counter), bad, ((k, s),), note="jog")
                alarm = self.alarms[-1]
                break
        self.log("jog", data=(("axis", axis), ("pulses", pulses), ("moved", moved)))
        return JogResult(axis, pulses, moved, False, alarm, self.mm(counter))

    # servo (post-interpolation filter) ----------------------------------------------
    def _servo_collect(self, plan: _Plan, t0: float, tau: float, done: int) -> None:
        ts = float(self.settings.servo_period_ms) / 1000
        if len(self._servo_samples) >= self.settings.servo_max_samples:
            return
        k0 = math.floor(t0 / ts) + 1
        k1 = math.floor(self.clock / ts)
        if k1 < k0:
            return
        ticks = np.arange(k0, k1 + 1) * ts
        times = t0 + plan.times(0, done, tau) if done else np.zeros(0)
        idx = np.searchsorted(times, ticks + 1e-12, side="right")
        for t, i in zip(ticks.tolist(), idx.tolist()):
            self._servo_samples.append((t, plan.position(int(i))))
            if len(self._servo_samples) >= self.settings.servo_max_samples:
                self.notes.append("servo log truncated at servo_max_samples")
                break

    def _servo_log(self) -> ServoLog | None:
        if not self._servo_on or not self._servo_samples:
            return None
        ts = float(self.settings.servo_period_ms) / 1000
        taus = tuple(self.settings.post_tau_ms(a) for a in self.axes)
        times = np.array([t for t, _ in self._servo_samples])
        cmd = np.array([p for _, p in self._servo_samples], dtype=float) * np.array([float(u) for u in self.pulse])
        settle = int(math.ceil(12 * max(taus) / 1000 / ts)) + 1  # e**-12: settled far inside a pulse
        times = np.concatenate([times, times[-1] + ts * np.arange(1, settle + 1)])
        cmd = np.vstack([cmd, np.repeat(cmd[-1:], settle, axis=0)])
        out = np.empty_like(cmd)
        for k, tau_ms in enumerate(taus):
            x = cmd[:, k]
            if tau_ms <= 0:
                out[:, k] = x
            elif self.settings.post_filter == "linear":
                m = max(1, int(round(tau_ms / 1000 / ts)))
                padded = np.concatenate([np.full(m - 1, x[0]), x])
                c = np.cumsum(np.concatenate([[0.0], padded]))
                out[:, k] = (c[m:] - c[:-m]) / m
            else:
                alpha = 1 - math.exp(-ts / (tau_ms / 1000))
                y = np.empty_like(x)
                acc = x[0]
                for n_, v in enumerate(x):
                    acc += alpha * (v - acc)
                    y[n_] = acc
                out[:, k] = y
        dev, at = _polyline_deviation(cmd, out, int(math.ceil(6 * max(taus) / 1000 / ts)) + 2)
        return ServoLog(times, cmd, out, dev, float(times[at]) if len(times) else 0.0,
                        self.settings.post_filter, taus)

    # ------------------------------------------------------------------ result
    def result(self) -> SimulationResult:
        """A frozen snapshot of the run so far."""
        start_real = self.mm(self.real)
        blind = None
        if self.mode is Mode.LOCK:
            blind = (
                "machine lock: the axes and machine coordinates stayed frozen, so the stroke check saw only "
                f"the frozen position; {sum(self.pulses)} interpolated axis-pulses were never checked. "
                "A program that leaves the allowed set raises no alarm in this mode; use --mode check."
            )
        stats = self.monitor.stats
        return SimulationResult(
            mode=self.mode, monitor=self.monitor_mode, axes=self.axes, alarms=tuple(self.alarms),
            completed=self.completed, machine_position=start_real,
            temporary_position=self.mm(self.temp) if self.mode is Mode.CHECK else None,
            program_position=self.mm(self.prog), pulses=tuple(self.pulses), servo_pulses=tuple(self.servo_pulses),
            simulated_time_s=self.clock, motions=self.motions, steps=self.steps, events=tuple(self.events),
            monitor_checks=stats.checks, max_lookup_comparisons=stats.max_lookup_comparisons,
            max_regions=stats.max_regions,
            overshoot_bound_mm=self.overshoot_bound if self.monitor_mode is MonitorMode.PERIODIC else 0.0,
            blind_spot=blind, servo=self._servo_log(),
            notes=tuple(self.notes) + tuple(self._solids.notes() if self._solids is not None else ()),
        )


#: How the controller plans each motion kind into pulses (docs/design.md §10 "How to add a motion kind";
#: tests/prover/test_segment_kinds.py crosses every kind with this table).
_PLANNERS: dict[SegmentKind, Callable[..., _Plan]] = {
    SegmentKind.LINE: Controller._plan_straight,
    SegmentKind.RAPID: Controller._plan_straight,
    SegmentKind.DWELL: Controller._plan_dwell,
    SegmentKind.ARC: Controller._plan_arc,
    SegmentKind.DEVELOPED_ARC: Controller._plan_developed,
    SegmentKind.POLAR: Controller._plan_polar,
    SegmentKind.SPLINE: Controller._plan_spline,
}
PLANNED_KINDS = frozenset(_PLANNERS)

#: Steps per chunk when :func:`_helix_columns` fills a whole array (temporaries stay small and in cache).
ARC_CHUNK = 1 << 16


def _helix_columns(pos: np.ndarray, plane: Any, pulse2: Any, centre: Any, sgn: Any, a0: Any, sweep: Any,
                   axes: Any) -> None:
    """Fill the helix columns of the whole array ``pos`` (:class:`.arcs.HelixColumns`, in ``ARC_CHUNK`` chunks)."""
    n = len(pos)
    h = HelixColumns(plane, pulse2, centre, sgn, a0, sweep, axes)
    for lo in range(0, n, ARC_CHUNK):
        hi = min(n, lo + ARC_CHUNK)
        h.fill(pos[lo:hi], hi == n)


_unwrap = unwrap


def _path_length(axes: Sequence[Axis], disp: list[float]) -> float:
    lin = [d for a, d in zip(axes, disp) if not a.rotary]
    if any(lin):
        return math.sqrt(sum(d * d for d in lin))
    return math.sqrt(sum(d * d for d in disp))


def _polyline_deviation(cmd: np.ndarray, out: np.ndarray, window: int) -> tuple[float, int]:
    """Max over output samples of the distance to the commanded polyline (a window back in time)."""
    n = cmd.shape[0]
    if n < 2:
        return 0.0, 0
    best = np.full(n, np.inf)
    for w in range(0, min(window, n - 1) + 1):
        a_idx = np.clip(np.arange(n) - w - 1, 0, n - 1)
        b_idx = np.clip(np.arange(n) - w, 0, n - 1)
        a, b = cmd[a_idx], cmd[b_idx]
        ab = b - a
        l2 = (ab * ab).sum(axis=1)
        t = np.where(l2 > 0, ((out - a) * ab).sum(axis=1) / np.where(l2 > 0, l2, 1), 0.0)
        t = np.clip(t, 0, 1)
        d = np.sqrt((((a + t[:, None] * ab) - out) ** 2).sum(axis=1))
        best = np.minimum(best, d)
    at = int(np.argmax(best))
    return float(best[at]), at


def simulate(
    motion: Any,
    machine: Machine,
    *,
    mode: Mode | str = Mode.NORMAL,
    monitor: MonitorMode | str = MonitorMode.PULSE,
    settings: Settings | None = None,
    start: Sequence[Fraction] | None = None,
    progress: Any = None,
    break_at: tuple[int, Fraction] | None = None,
) -> SimulationResult:
    """Run motion through a fresh :class:`Controller`; returns the frozen result.

    ``progress``, if given, is called as ``progress(line, total_lines)``
    after each segment (``total_lines`` from the interpretation's text, else
    None); see :mod:`nczones.report.progress`.

    ``break_at=(line, fraction)`` injects a tool break in the first cutting
    motion of source line ``line`` after ``fraction`` of its steps and runs the
    automatic recovery of the machine's ``[tool_change]`` section
    (:mod:`nczones.controller.recovery`).

    ``motion`` is an iterable of :class:`~nczones.motion.Segment` or
    :class:`~nczones.motion.MotionChunk` (an interpretation from
    :mod:`nczones.gcode` is one).  ``start`` defaults to the first segment's
    start point (else ``machine.start``).

    Examples
    --------
    >>> from nczones.machine import load_machine
    >>> from nczones.motion import Segment, SegmentKind
    >>> F = Fraction
    >>> m = load_machine("specs/machines/grinder.toml")
    >>> prog = [Segment(SegmentKind.LINE, (F(500), F(300)), (F(500), F(100)), m.axis_names,
    ...                 block=0, feed_mm_min=F(600))]
    >>> normal = simulate(prog, m)
    >>> check = simulate(prog, m, mode="check")
    >>> lock = simulate(prog, m, mode="lock")
    >>> normal.alarms, check.alarms, lock.alarms
    ((), (), ())
    >>> normal.pulses, [str(v) for v in check.machine_position], check.simulated_time_s < normal.simulated_time_s
    ((0, 200000), ['500', '300'], True)
    """
    items = motion
    if start is None:
        items, first = _peek(motion)
        start = first.start if first is not None else None
    ctl = Controller(machine, mode=mode, monitor=monitor, settings=settings, start=start, break_at=break_at)
    text = getattr(motion, "text", None)
    if isinstance(text, str):
        ctl.source_lines = program_lines(text)
    ctl.mode_source = motion
    if progress is not None:
        items = _reporting(items, progress, getattr(motion, "text", None))
    return ctl.run(items)


def _reporting(items: Any, progress: Any, text: str | None) -> Iterator[Segment]:
    """Segments of ``items``, calling ``progress(line, total)`` after each one is run."""
    total = (text.count("\n") + (0 if text.endswith("\n") else 1)) if text else None
    for seg in segments_of(items):
        yield seg
        if seg.span is not None:
            progress(seg.span.line, total)


def _peek(motion: Any) -> tuple[Iterable[Segment], Segment | None]:
    it = segments_of(motion)
    try:
        first = next(it)
    except StopIteration:
        return (), None

    def chain() -> Iterator[Segment]:
        yield first
        yield from it

    return chain(), first
