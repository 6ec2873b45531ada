"""``nczones home``: simulate homing or prove it exact (DESIGN §8).

With ``--prove`` the Z3 proofs (:mod:`nczones.prover.homing`) run, and every
counterexample they find is replayed by the controller's pulse simulation
(:mod:`nczones.controller.homing`): two independent witnesses of one
configuration (:mod:`nczones.plans.homing`).

Exit status: 0 homing ended exactly at machine zero (or, with ``--prove``,
every claim holds for the machine as configured); 1 an alarm, an origin
error, or a refuted (or unproved) claim; 2 bad input.
"""

from __future__ import annotations

import argparse
import json
import re
from dataclasses import replace
from fractions import Fraction
from typing import Any

from ..controller.homing import HomingRun, simulate_homing
from ..errors import InvalidArgument
from ..exact import format_decimal, seconds
from ..machine import Machine, load_machine
from ..plans.homing import HomingConfig, homing_config, installation_start
from .conventions import EXIT_FAIL, EXIT_OK

__all__ = ["configure", "parse_length", "replay_counterexample"]

_FRACTION_RE = re.compile(r"\s*([+-]?\d+)\s*/\s*(\d+)\s*\Z")


def parse_length(text: str, option: str) -> Fraction:
    """A decimal (``"3.25"``) or a fraction (``"13/4"``), exactly.

    >>> parse_length("-0.015", "--trip-offset"), parse_length("1/3", "--phase")
    (Fraction(-3, 200), Fraction(1, 3))
    """
    from ..exact import DECIMAL_RE

    m = _FRACTION_RE.match(text)
    if m and int(m.group(2)) != 0:
        return Fraction(int(m.group(1)), int(m.group(2)))
    if DECIMAL_RE.match(text.strip()):
        return Fraction(text.strip())
    raise InvalidArgument(f"{option} {text!r} is not a length; write a decimal such as 3.25 or a fraction such as 13/4")


def replay_counterexample(cfg: HomingConfig, pulse: Fraction, cex: Any, start: Fraction | None = None) -> int | None:
    """The origin error (pulses) the pulse simulation gives for a proof's counterexample.

    The run starts at ``start`` (default: clear of the dog); a counterexample
    at another phase than the configured one has the grid shift measured
    there at installation, as the proof assumes.
    """
    run = simulate_homing(cfg, pulse, start=start if start is not None else installation_start(cfg, pulse),
                          phase=cex.phase if cex.phase_given else None, trip_offset=cex.trip_offset)
    return run.origin_error_pulses


def _start(machine: Machine, cfg: HomingConfig) -> Fraction:
    if cfg.start is not None:
        return cfg.start
    return machine.start[machine.axis_names.index(cfg.axis)]


def _configs(args: argparse.Namespace, machine: Machine) -> dict[str, HomingConfig]:
    configs = homing_config(machine, args.axis)
    if args.phase is None:
        return configs
    phase = parse_length(args.phase, "--phase")
    out = {}
    for name, cfg in configs.items():
        if not 0 <= phase < cfg.grid_pitch:
            raise InvalidArgument(f"--phase {args.phase}: axis {name} needs a phase in [0, "
                                  f"{format_decimal(cfg.grid_pitch)}) (the grid pitch)")
        out[name] = cfg
    return out


def _run_json(run: HomingRun) -> dict[str, Any]:
    return {
        "axis": run.axis,
        "phase": format_decimal(run.phase),
        "trip_offset": format_decimal(run.trip_offset),
        "grid_shift": None if run.grid_shift is None else format_decimal(run.grid_shift),
        "shift_source": run.shift_source,
        "events": [
            {"kind": e.kind.name.lower(), "pulses": e.pulses, "position": format_decimal(e.position),
             "time_s": seconds(e.time_s), "text": e.text}
            for e in run.events
        ],
        "alarm": None if run.alarm is None else {"kind": run.alarm.kind.name.lower(), "message": run.alarm.message},
        "latched_grid": None if run.latched_grid is None else format_decimal(run.latched_grid),
        "origin_error_pulses": run.origin_error_pulses,
        "origin_error_mm": None if run.origin_error_pulses is None else format_decimal(run.origin_error_pulses * run.pulse),
        "exact": run.exact,
    }


def _run_text(run: HomingRun, cfg: HomingConfig, phase_given: bool) -> str:
    phase_note = "given: detector re-mounted" if phase_given else "configured"
    lines = [
        f"homing {run.axis}: detector phase {format_decimal(run.phase)} mm ({phase_note}), trip offset "
        f"{format_decimal(run.trip_offset)} mm, servo lag {format_decimal(cfg.lag)} mm"
    ]
    if run.grid_shift is not None:
        lines.append(f"  grid shift {format_decimal(run.grid_shift)} mm ({run.shift_source})")
    for e in run.events:
        lines.append(f"  {format_decimal(e.time_s, 4):>10} s  {run.axis}{format_decimal(e.position):<12} "
                     f"{e.kind.value}: {e.text}")
    if run.alarm is not None:
        lines.append(f"  ALARM ({run.alarm.kind.value}): {run.alarm.message}")
    elif run.exact:
        lines.append(f"  result: homing ended exactly at machine zero {format_decimal(cfg.machine_zero)} "
                     "(origin error 0 pulses)")
    else:
        assert run.origin_error_pulses is not None  # a run without alarm measures its origin error
        lines.append(f"  result: origin error {run.origin_error_pulses} pulses "
                     f"({format_decimal(run.origin_error_pulses * run.pulse)} mm); controller zero is off machine zero")
    return "\n".join(lines)


def _simulate(args: argparse.Namespace, machine: Machine, configs: dict[str, HomingConfig]) -> int:
    trip = Fraction(0) if args.trip_offset is None else parse_length(args.trip_offset, "--trip-offset")
    phase = None if args.phase is None else parse_length(args.phase, "--phase")
    runs = []
    for name, cfg in configs.items():
        if phase is not None:
            # a re-mounted detector: the stored grid shift is void, installation is measured again
            cfg = replace(cfg, detector_phase=phase, grid_shift=None)
        if abs(trip) > cfg.switch_jitter:
            raise InvalidArgument(f"--trip-offset {args.trip_offset}: must lie within axis {name}'s switch jitter "
                                  f"window [-{format_decimal(cfg.switch_jitter)}, {format_decimal(cfg.switch_jitter)}]")
        pulse = machine.axis(name).pulse
        runs.append((cfg, simulate_homing(cfg, pulse, start=_start(machine, cfg), phase=phase, trip_offset=trip)))
    ok = all(r.exact for _, r in runs)
    if args.format == "json":
        print(json.dumps({"command": "home", "machine": machine.source, "prove": False,
                          "axes": [_run_json(r) for _, r in runs], "ok": ok}, indent=2))
    else:
        print("\n".join(_run_text(r, cfg, phase is not None) for cfg, r in runs))
    return EXIT_OK if ok else EXIT_FAIL


def _reproduce_command(args: argparse.Namespace, axis: str, cex: Any) -> str:
    extra = list(cex.cli_args(axis))
    if args.phase is not None and "--phase" not in extra:
        extra[2:2] = ["--phase", args.phase]  # proved for the phase given on the command line
    return " ".join(["nczones", "home", "--machine", args.machine, *extra])


def _prove(args: argparse.Namespace, machine: Machine, configs: dict[str, HomingConfig]) -> int:
    from ..prover.homing import ProofStatus, prove_homing

    if args.trip_offset is not None:
        raise InvalidArgument("--trip-offset is for simulation; --prove already covers every trip offset "
                              "in the jitter window")
    reports = []
    for name, cfg in configs.items():
        if args.phase is not None:
            # a re-mounted detector: the stored grid shift is void, installation is measured again
            cfg = replace(cfg, detector_phase=parse_length(args.phase, "--phase"), grid_shift=None)
        reports.append((cfg, prove_homing(cfg, machine.axis(name).pulse)))
    ok = all(r.ok for _, r in reports)
    simulated: dict[tuple[str, str], int | None] = {}
    for cfg, r in reports:
        for p in r.proofs:
            if p.counterexample is not None:
                simulated[r.axis, p.name] = replay_counterexample(cfg, machine.axis(r.axis).pulse, p.counterexample,
                                                                  _start(machine, cfg))

    def cex_json(p, axis):
        c = p.counterexample
        if c is None:
            return None
        sim = simulated[axis, p.name]
        return {"phase": format_decimal(c.phase), "trip_offset": format_decimal(c.trip_offset),
                "install_trip_offset": format_decimal(c.install_trip_offset),
                "origin_error_pulses": c.origin_error_pulses, "simulated_error_pulses": sim,
                "reproduced": sim == c.origin_error_pulses, "grid_shift": format_decimal(c.grid_shift),
                "reproduce": _reproduce_command(args, axis, c)}

    if args.format == "json":
        axes_out: list[dict[str, Any]] = []
        out = {"command": "home", "machine": machine.source, "prove": True, "ok": ok, "axes": axes_out}
        for cfg, r in reports:
            axes_out.append({
                "axis": r.axis, "solver": r.solver, "phase": format_decimal(cfg.detector_phase),
                "edge_to_grid": format_decimal(r.edge_to_grid), "jitter_plus_lag": format_decimal(r.margin),
                "window_clear": r.window_clear, "ok": r.ok,
                "proofs": [{"name": p.name, "status": p.status.value, "statement": p.statement,
                            "reason": p.reason, "time_s": seconds(p.seconds),
                            "counterexample": cex_json(p, r.axis)} for p in r.proofs],
            })
        print(json.dumps(out, indent=2))
        return EXIT_OK if ok else EXIT_FAIL

    lines = []
    for cfg, r in reports:
        lines.append(f"homing {r.axis}: proofs with {r.solver}")
        lines.append(f"  detector phase {format_decimal(cfg.detector_phase)} mm: dog edge to nearest grid point "
                     f"{format_decimal(r.edge_to_grid)} mm, jitter + lag {format_decimal(r.margin)} mm")
        for p in r.proofs:
            tag = {ProofStatus.PROVED: "proved", ProofStatus.REFUTED: "COUNTEREXAMPLE",
                   ProofStatus.UNKNOWN: "unknown"}[p.status]
            if p.name == "one-pitch-error" and p.status is ProofStatus.REFUTED:
                tag = "counterexample (expected: another mounting can fail)"
            lines.append(f"  [{tag}] {p.name}: {p.statement}")
            if p.reason:
                lines.append(f"      reason: {p.reason}")
            c = p.counterexample
            if c is not None:
                sim = simulated[r.axis, p.name]
                lines.append(f"      phase {format_decimal(c.phase)} mm, trip offset {format_decimal(c.trip_offset)} mm "
                             f"(installation at {format_decimal(c.install_trip_offset)}): origin error "
                             f"{c.origin_error_pulses} pulses; the simulation gives {sim} "
                             f"({'reproduced' if sim == c.origin_error_pulses else 'NOT reproduced'})")
                lines.append(f"      reproduce: {_reproduce_command(args, r.axis, c)}")
        verdict = ("homing is proved exact at the configured phase" if r.ok
                   else "homing is NOT proved exact at the configured phase")
        lines.append(f"  => {verdict}")
    print("\n".join(lines))
    return EXIT_OK if ok else EXIT_FAIL


def _run_home(args: argparse.Namespace) -> int:
    machine = load_machine(args.machine)
    configs = _configs(args, machine)
    if args.prove:
        return _prove(args, machine, configs)
    return _simulate(args, machine, configs)


def configure(p: argparse.ArgumentParser) -> None:
    p.description = ("Simulate homing of one axis or all axes pulse by pulse, or prove with Z3 "
                     "when it ends exactly at machine zero (see specs/homing.md).")
    p.add_argument("--machine", required=True, metavar="M.toml",
                   help="the machine file with [homing.<axis>] sections (specs/homing.md)")
    p.add_argument("--axis", help="home only this axis (default: every axis with a [homing.<axis>] section)")
    p.add_argument("--phase", metavar="P", help="detector phase in mm (decimal or p/q); a phase other than the "
                   "configured one voids the stored grid shift, which is measured again at installation")
    p.add_argument("--trip-offset", metavar="T", help="where the near-zero switch trips relative to the dog edge, "
                   "mm in the search direction, within +-switch_jitter (default 0)")
    p.add_argument("--prove", action="store_true", help="prove the homing claims with Z3 instead of simulating")
    p.add_argument("--format", choices=("text", "json"), default="text",
                   help="text (readable) or json (times in seconds as numbers, positions as exact decimals)")
    p.set_defaults(handler=_run_home)

