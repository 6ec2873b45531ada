"""Simulation: one program's text → interpretation → the reference controller (see :mod:`nczones.pipeline`)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..gcode.source import ProgramSource
from ..machine import Machine
from ..prover.options import VerifyOptions
from .verification import interpretation

__all__ = ["simulate_source"]


def simulate_source(source: ProgramSource, machine: Machine, options: VerifyOptions, *,
                    progress: Callable[..., object] | None = None, **controller: Any) -> tuple[Any, list[str], bool]:
    """Run one program through the reference controller (:func:`nczones.controller.simulate`, its keywords
    in ``controller``) with the options' interpretation settings and budget: (the simulation result, the
    notes of the interpretation, whether the budget stopped it)."""
    from ..controller import simulate
    from ..prover.limits import interpretation_budget

    run = interpretation(source, machine, options)
    # interpretation is lazy: it runs inside simulate(), whose repetitions (loops, repeats, cycle passes)
    # ask the budget and end as VF203 once it is spent
    with interpretation_budget(options.budget_s):
        result = simulate(run, machine, progress=progress, **controller)
    notes: list[str] = []
    budget_stop = False
    for u in run.unsupported:
        if u.code == "VF203":
            budget_stop = True
            notes.append(f"{u.span}: {u.code}: {u.reason}; the simulation stopped there")
        else:
            notes.append(f"{u.span}: {u.code} is not supported ({u.reason}); the simulation stopped there")
    if run.assumed_modal:
        notes.extend(run.assumed_modal_text())
    notes.extend(run.notes())
    return result, notes, budget_stop
