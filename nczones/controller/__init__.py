"""The reference controller (DESIGN §6): pulses, interpolation, the limit monitor, modes.

It consumes motion segments (:mod:`nczones.motion`) and a machine, never text.

Public API
----------
:func:`simulate`
    ``simulate(segments_or_interpretation, machine, *, mode="normal"|"lock"|"check",
    monitor="pulse"|"periodic", settings=Settings(...), start=None)`` -> :class:`SimulationResult`.
:class:`Controller`
    The same, step by step, with :meth:`Controller.jog` for the reverse jog after an alarm.
:mod:`nczones.controller.pulses`
    Pulse distribution (linear, circular, dogleg rapids) in exact integers.
:mod:`nczones.controller.monitor`
    The limit monitor (sequential limit-value-table lookup, compiled integer checks).
:mod:`nczones.controller.blending`
    LinuxCNC's blend arcs at G64 corners (``Settings(blending="auto"|"exact"|"linuxcnc")``).
"""

from .monitor import CompiledCheck, LimitMonitor, MonitorStats
from .pulses import arc_centre, arc_walk, dogleg_steps, line_steps, round_pulse
from .simulator import (
    Alarm,
    Controller,
    Event,
    JogResult,
    Mode,
    MonitorMode,
    ServoLog,
    Settings,
    SimulationResult,
    simulate,
)

__all__ = [
    "Alarm",
    "CompiledCheck",
    "Controller",
    "Event",
    "JogResult",
    "LimitMonitor",
    "Mode",
    "MonitorMode",
    "MonitorStats",
    "ServoLog",
    "Settings",
    "SimulationResult",
    "arc_centre",
    "arc_walk",
    "dogleg_steps",
    "line_steps",
    "round_pulse",
    "simulate",
]
