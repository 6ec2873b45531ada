"""Z3 proofs about homing with a near-zero dog, grid points and a grid shift.

The model is the configuration's arithmetic (:mod:`nczones.plans.homing`), written as
linear integer/real arithmetic over exact rationals (search coordinate
``sigma = direction * x``, lengths in mm, pulse positions as integers):

* arming position ``a = sigma(edge) + t + lag`` for a trip offset ``t`` in
  ``[-jitter, +jitter]``;
* latched grid point ``g = direction*phase + k*pitch`` (``k`` an integer) with
  ``g > a`` and ``g - pitch <= a`` (the first grid point after arming);
* latched pulse ``n`` (integer) with ``n*u >= g > (n-1)*u`` (first pulse at or
  beyond it);
* installation at trip offset ``t0`` latches ``n0``; the stored shift is
  ``zero - n0``, so homing at ``t`` ends ``n - n0`` pulses (in sigma) off zero.

Each claim is proved by showing its negation unsatisfiable (universally
quantified over the detector phase and the trip offsets), or refuted with a
counterexample, which the closed form of the same arithmetic
(:func:`nczones.plans.homing.origin_error_pulses`) confirms; the pulse simulation of
the reference controller replays it independently (``nczones home --prove``,
the differential tests).  Z3 runs with a fixed random seed and a timeout; a
timeout gives ``unknown``, never ``proved``.

>>> from fractions import Fraction
>>> from nczones.plans.homing import HomingConfig
>>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5), Fraction(20),
...                    Fraction(10), Fraction(3), switch_jitter=Fraction(1, 50), start=Fraction(40))
>>> prove_exact_after_installation(cfg, Fraction(1, 1000)).status.value
'proved'
>>> cex = find_one_pitch_error(cfg, Fraction(1, 1000)).counterexample
>>> abs(cex.origin_error_pulses), cex.confirmed
(10000, True)
"""

from __future__ import annotations

import enum
import time
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import z3

from ..errors import InvalidArgument
from ..exact import format_decimal
from ..plans.homing import (
    HomingConfig,
    edge_to_grid_distance,
    exactness_margin,
    origin_error_pulses,
    window_is_clear,
)

__all__ = [
    "ProofStatus",
    "HomingCounterexample",
    "HomingProof",
    "HomingProofReport",
    "prove_exact_after_installation",
    "find_one_pitch_error",
    "prove_error_is_one_pitch",
    "prove_margin_condition",
    "prove_window_condition",
    "prove_configured_phase",
    "prove_homing",
    "SEED",
]

SEED = 0
TIMEOUT_MS = 20_000


class ProofStatus(enum.Enum):
    PROVED = "proved"
    REFUTED = "refuted"
    UNKNOWN = "unknown"


@dataclass(frozen=True, slots=True)
class HomingCounterexample:
    """A configuration where homing ends off machine zero.

    ``origin_error_pulses`` is what the Z3 model says (controller zero minus
    machine zero, machine pulses); ``confirmed`` says that the closed form of
    the grid arithmetic (:func:`nczones.plans.homing.origin_error_pulses`) gives the
    same error at the same phase and trip offset.
    """

    phase: Fraction
    trip_offset: Fraction
    install_trip_offset: Fraction
    origin_error_pulses: int
    grid_shift: Fraction
    phase_given: bool  # False: the configured phase and stored shift are used
    confirmed: bool

    def cli_args(self, axis: str) -> tuple[str, ...]:
        """The ``nczones home`` options that reproduce it."""
        args = ["--axis", axis]
        if self.phase_given:
            args += ["--phase", _text(self.phase)]
        args += ["--trip-offset", _text(self.trip_offset)]
        return tuple(args)


@dataclass(frozen=True, slots=True)
class HomingProof:
    """One claim about homing and what Z3 made of it."""

    name: str
    statement: str
    status: ProofStatus
    counterexample: HomingCounterexample | None = None
    reason: str = ""
    seconds: float = 0.0


@dataclass(frozen=True, slots=True)
class HomingProofReport:
    """All homing claims for one axis, plus the exact facts at the configured phase."""

    axis: str
    proofs: tuple[HomingProof, ...]
    edge_to_grid: Fraction
    margin: Fraction
    window_clear: bool
    solver: str

    @property
    def configured(self) -> HomingProof:
        return next(p for p in self.proofs if p.name == "configured-phase")

    @property
    def ok(self) -> bool:
        """True when the machine as configured is proved to home exactly and every general claim holds."""
        return all(p.status is ProofStatus.PROVED for p in self.proofs if p.name != "one-pitch-error")


def _text(q: Fraction) -> str:
    """Decimal text when exact, else ``p/q`` (the CLI accepts both)."""
    s = format_decimal(q)
    return f"{q.numerator}/{q.denominator}" if s.endswith("…") else s


def _q(x: Fraction | int) -> z3.ArithRef:
    x = Fraction(x)
    return z3.Q(x.numerator, x.denominator)


class _Model:
    """Builds the constraints of one axis in one solver."""

    def __init__(self, cfg: HomingConfig, pulse: Fraction):
        if (cfg.grid_pitch / pulse).denominator != 1:
            raise InvalidArgument(f"grid pitch {format_decimal(cfg.grid_pitch)} is not a whole number of pulses")
        self.cfg = cfg
        self.pulse = pulse
        self.d = cfg.direction
        self.pitch = _q(cfg.grid_pitch)
        self.u = _q(pulse)
        self.edge = _q(cfg.direction * cfg.dog_position)
        self.lag = _q(cfg.lag)
        self.jitter = _q(cfg.switch_jitter)
        self.solver = z3.Solver()
        self.solver.set("random_seed", SEED)
        self.solver.set("timeout", TIMEOUT_MS)
        self.phase = z3.Real("phase")
        self.solver.add(self.phase >= 0, self.phase < self.pitch)

    def trip(self, name: str) -> z3.ArithRef:
        t = z3.Real(name)
        self.solver.add(t >= -self.jitter, t <= self.jitter)
        return t

    def latch(self, t: z3.ArithRef, tag: str) -> z3.ArithRef:
        """The latched pulse (sigma) for trip offset ``t``."""
        k, n = z3.Int(f"k_{tag}"), z3.Int(f"n_{tag}")
        a = self.edge + t + self.lag
        g = self.d * self.phase + k * self.pitch
        self.solver.add(g > a, g - self.pitch <= a, n * self.u >= g, n * self.u - self.u < g)
        return n

    def margin_holds(self) -> z3.BoolRef:
        """Edge-to-nearest-grid distance exceeds jitter plus lag."""
        m = z3.Int("m")
        gb = self.d * self.phase + m * self.pitch
        need = self.jitter + self.lag
        self.solver.add(gb <= self.edge, gb + self.pitch > self.edge)
        return z3.And(self.edge - gb > need, gb + self.pitch - self.edge > need)

    def window_clear(self) -> z3.BoolRef:
        """No grid point in (edge + lag - jitter, edge + lag + jitter]."""
        w = z3.Int("w")
        a1 = self.edge + self.lag - self.jitter
        gw = self.d * self.phase + w * self.pitch
        self.solver.add(gw > a1, gw - self.pitch <= a1)
        return gw > a1 + 2 * self.jitter

    def check(self) -> z3.CheckSatResult:
        return self.solver.check()


def _run(name: str, statement: str, build: Callable[[], Any], *,
         on_sat: Callable[[Any], Any] | None = None) -> HomingProof:
    """Check the negation built by ``build``; unsat proves the statement."""
    t0 = time.perf_counter()
    model = build()
    result = model.check()
    seconds = time.perf_counter() - t0
    if result == z3.unsat:
        return HomingProof(name, statement, ProofStatus.PROVED, seconds=seconds)
    if result == z3.sat:
        cex = on_sat(model) if on_sat else None
        reason = "" if cex is not None else "Z3 found a model of the negation"
        return HomingProof(name, statement, ProofStatus.REFUTED, cex, reason, seconds)
    return HomingProof(name, statement, ProofStatus.UNKNOWN,
                       reason=f"Z3: {model.solver.reason_unknown()}", seconds=seconds)


def _value(model: z3.ModelRef, x: z3.ArithRef) -> Fraction:
    v = model.eval(x, model_completion=True)
    if z3.is_int_value(v):
        return Fraction(v.as_long())
    return Fraction(v.as_fraction())


def prove_exact_after_installation(cfg: HomingConfig, pulse: Fraction) -> HomingProof:
    """(1) For every detector phase, homing that trips where the installation run tripped ends exactly at zero."""
    statement = (f"for every detector phase in [0, {format_decimal(cfg.grid_pitch)}) and every trip point "
                 "in the jitter window, after the installation measurement a homing whose switch trips where "
                 "it tripped at installation ends exactly at machine zero (0 pulses)")

    def build() -> _Model:
        m = _Model(cfg, pulse)
        t = m.trip("t")
        m.solver.add(m.latch(t, "home") != m.latch(t, "install"))
        return m

    return _run("exact-after-installation", statement, build)


def prove_error_is_one_pitch(cfg: HomingConfig, pulse: Fraction) -> HomingProof:
    """Whatever the phase and the trip offsets, the origin error is 0 or exactly one grid pitch."""
    pp = int(cfg.grid_pitch / pulse)
    statement = (f"for every detector phase and any two trip offsets (installation and homing) in the jitter "
                 f"window, the origin error is 0 or exactly one grid pitch (+-{pp} pulses)")

    def build() -> _Model:
        m = _Model(cfg, pulse)
        diff = m.latch(m.trip("t"), "home") - m.latch(m.trip("t0"), "install")
        m.solver.add(diff != 0, diff != pp, diff != -pp)
        return m

    return _run("error-zero-or-one-pitch", statement, build)


def find_one_pitch_error(cfg: HomingConfig, pulse: Fraction) -> HomingProof:
    """(2) Search a detector phase and trip offset for which homing ends one pitch off.

    The installation is measured at trip offset 0 (the nominal switch point).
    When a grid shift is stored for the configured phase, the search excludes
    that phase (there the stored value is used, see
    :func:`prove_configured_phase`).  Phase and trip offset are first sought
    on the pulse grid, then on finer grids, so the reproduction command reads
    well.  The counterexample is confirmed by the closed form of the grid
    arithmetic.
    """
    statement = ("for every detector phase (grid shift measured at installation with the switch tripping at "
                 "the dog edge) and every trip offset in the jitter window, homing ends exactly at machine zero")
    if cfg.switch_jitter == 0:
        return _run("one-pitch-error", statement, lambda: _one_pitch_model(cfg, pulse, None))
    result = None
    for step in (pulse, pulse / 10, pulse / 1000, None):
        result = _run("one-pitch-error", statement, lambda: _one_pitch_model(cfg, pulse, step),  # noqa: B023 - called within this iteration
                      on_sat=lambda m: _one_pitch_cex(cfg, pulse, m))
        if result.status is not ProofStatus.PROVED:
            return result
    assert result is not None  # the loop ran
    return result


def _one_pitch_model(cfg: HomingConfig, pulse: Fraction, step: Fraction | None) -> _Model:
    m = _Model(cfg, pulse)
    t = m.trip("t")
    zero = z3.RealVal(0)
    m.solver.add(m.latch(t, "home") != m.latch(zero, "install"))
    if cfg.grid_shift is not None:
        m.solver.add(m.phase != _q(cfg.detector_phase))
    if step is not None:
        i, j = z3.Int("i"), z3.Int("j")
        m.solver.add(m.phase == i * _q(step), t == j * _q(step))
    m.t = t  # type: ignore[attr-defined]
    return m


def _one_pitch_cex(cfg: HomingConfig, pulse: Fraction, m: _Model) -> HomingCounterexample:
    model = m.solver.model()
    phase, t = _value(model, m.phase), _value(model, m.t)  # type: ignore[attr-defined]
    n = _value(model, z3.Int("n_home"))
    n0 = _value(model, z3.Int("n_install"))
    error = int(cfg.direction * (n - n0))
    shift = cfg.machine_zero - cfg.direction * n0 * pulse
    confirmed = origin_error_pulses(cfg, pulse, phase, t) == error
    return HomingCounterexample(phase, t, Fraction(0), error, shift, True, confirmed)


def prove_margin_condition(cfg: HomingConfig, pulse: Fraction) -> HomingProof:
    """(3) Edge-to-grid distance greater than jitter plus lag implies exact homing, for every phase."""
    statement = (f"for every detector phase whose nearest grid point is farther than jitter + lag = "
                 f"{format_decimal(exactness_margin(cfg))} mm from the dog edge, and any two trip offsets "
                 "(installation and homing) in the jitter window, homing ends exactly at machine zero")

    def build() -> _Model:
        m = _Model(cfg, pulse)
        m.solver.add(m.margin_holds())
        m.solver.add(m.latch(m.trip("t"), "home") != m.latch(m.trip("t0"), "install"))
        return m

    return _run("margin-condition", statement, build)


def prove_window_condition(cfg: HomingConfig, pulse: Fraction) -> tuple[HomingProof, HomingProof]:
    """The exact condition: homing is always exact iff no grid point lies in (edge+lag-jitter, edge+lag+jitter].

    Returns the two directions: sufficiency (clear window => equal latches for
    any two trip offsets) and necessity (a grid point in the window => the
    extreme trip offsets -jitter and +jitter latch different grid points).
    """
    window = (f"(edge + lag - jitter, edge + lag + jitter] (lag {format_decimal(cfg.lag)} mm, "
              f"jitter {format_decimal(cfg.switch_jitter)} mm, in the search direction)")

    def sufficient() -> _Model:
        m = _Model(cfg, pulse)
        m.solver.add(m.window_clear())
        m.solver.add(m.latch(m.trip("t"), "home") != m.latch(m.trip("t0"), "install"))
        return m

    def necessary() -> _Model:
        m = _Model(cfg, pulse)
        m.solver.add(z3.Not(m.window_clear()))
        n = m.latch(-m.jitter, "home")
        n0 = m.latch(m.jitter, "install")
        m.solver.add(n == n0)
        return m

    return (
        _run("window-sufficient", f"for every detector phase with no grid point in {window}, homing is exact "
             "for any two trip offsets in the jitter window", sufficient),
        _run("window-necessary", f"for every detector phase with a grid point in {window}, the trip offsets "
             "-jitter and +jitter latch different grid points (homing can end one pitch off)", necessary),
    )


def prove_configured_phase(cfg: HomingConfig, pulse: Fraction) -> HomingProof:
    """At the configured phase with the stored (or installation-measured) grid shift: exact for every trip offset?"""
    stored = cfg.grid_shift is not None
    what = "the stored grid shift" if stored else "the grid shift measured at installation (trip offset 0)"
    statement = (f"at the configured detector phase {format_decimal(cfg.detector_phase)} with {what}, homing ends "
                 "exactly at machine zero for every trip offset in the jitter window")
    d = cfg.direction
    zero_pulses = int(cfg.machine_zero / pulse)

    def build() -> _Model:
        m = _Model(cfg, pulse)
        m.solver.add(m.phase == _q(cfg.detector_phase))
        t = m.trip("t")
        n = m.latch(t, "home")
        if stored:
            assert cfg.grid_shift is not None  # stored means the machine file gives it
            shift = int(cfg.grid_shift / pulse)
        else:
            shift_var = z3.Int("shift")
            m.solver.add(shift_var == zero_pulses - d * m.latch(z3.RealVal(0), "install"))
            shift = shift_var
        err = z3.Int("err")
        m.solver.add(err == d * n + shift - zero_pulses, err != 0)
        m.t = t  # type: ignore[attr-defined]
        return m

    def cex(m: _Model) -> HomingCounterexample:
        model = m.solver.model()
        t = _value(model, m.t)  # type: ignore[attr-defined]
        # prefer a trip offset on the pulse grid when one exists
        for step in (pulse, pulse / 10):
            probe = build()
            j = z3.Int("j")
            probe.solver.add(probe.t == j * _q(step))  # type: ignore[attr-defined]
            if probe.check() == z3.sat:
                m, model = probe, probe.solver.model()
                t = _value(model, m.t)  # type: ignore[attr-defined]
                break
        error = int(_value(model, z3.Int("err")))
        shift = cfg.grid_shift if stored and cfg.grid_shift is not None else _value(model, z3.Int("shift")) * pulse
        confirmed = origin_error_pulses(cfg, pulse, cfg.detector_phase, t) == error
        return HomingCounterexample(cfg.detector_phase, t, Fraction(0), error, shift, False, confirmed)

    return _run("configured-phase", statement, build, on_sat=cex)


def prove_homing(cfg: HomingConfig, pulse: Fraction) -> HomingProofReport:
    """Every homing claim for one axis.

    Examples
    --------
    >>> from nczones.plans.homing import HomingConfig
    >>> cfg = HomingConfig("X", -1, Fraction(3000), Fraction(300), Fraction(5), Fraction(20),
    ...                    Fraction(10), Fraction(3), switch_jitter=Fraction(1, 50), start=Fraction(40))
    >>> report = prove_homing(cfg, Fraction(1, 1000))
    >>> [(p.name, p.status.value) for p in report.proofs]  # doctest: +NORMALIZE_WHITESPACE
    [('exact-after-installation', 'proved'), ('error-zero-or-one-pitch', 'proved'),
     ('margin-condition', 'proved'), ('window-sufficient', 'proved'), ('window-necessary', 'proved'),
     ('one-pitch-error', 'refuted'), ('configured-phase', 'proved')]
    >>> report.ok
    True
    """
    sufficient, necessary = prove_window_condition(cfg, pulse)
    proofs = (
        prove_exact_after_installation(cfg, pulse),
        prove_error_is_one_pitch(cfg, pulse),
        prove_margin_condition(cfg, pulse),
        sufficient,
        necessary,
        find_one_pitch_error(cfg, pulse),
        prove_configured_phase(cfg, pulse),
    )
    return HomingProofReport(cfg.axis, proofs, edge_to_grid_distance(cfg), exactness_margin(cfg),
                             window_is_clear(cfg), f"z3 {z3.get_version_string()} (seed {SEED})")
