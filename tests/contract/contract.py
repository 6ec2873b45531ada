"""The prover <-> controller contract of DESIGN §7, as executable checks.

:func:`check_contract` runs one program through the prover (margin 0 and
margin one pulse) and the reference controller (per-pulse and periodic
monitoring) and asserts every clause of the contract (specs/contract.md
states it exactly).  Cases inside the one-pulse gray band are counted in
:data:`STATS` (and reported with :func:`hypothesis.event`), not failed.

The prover is a parameter so that tests can inject a broken one and show
that the checks catch it.
"""

from __future__ import annotations

import time
from collections import Counter
from fractions import Fraction

from hypothesis import currently_in_test_context, event

from nczones.controller import line_steps, round_pulse, simulate
from nczones.gcode import interpret_text
from nczones.machine import Machine, RapidMode
from nczones.motion import SegmentKind
from nczones.prover import Verdict, verify_segments

from oracles.bruteforce import first_violation, zone_constants

#: Counts of every outcome class since the process started (printed by conftest).
STATS: Counter = Counter()
_T0 = time.monotonic()

F0 = Fraction(0)


class ContractViolation(AssertionError):
    """The prover and the controller disagree outside the gray band."""


def _count(label: str) -> None:
    STATS[label] += 1
    if currently_in_test_context():
        event(label)


def _flush() -> None:
    """Write STATS to $NCZONES_CONTRACT_STATS every 25 checked programs (long runs may be stopped)."""
    import json
    import os

    out = os.environ.get("NCZONES_CONTRACT_STATS")
    STATS["programs checked"] += 1
    STATS["elapsed seconds"] = int(time.monotonic() - _T0)
    if out and STATS["programs checked"] % 25 == 0:
        with open(out, "w") as fh:
            json.dump(dict(STATS), fh, indent=2, sort_keys=True)


def _require(cond: bool, message: str) -> None:
    if not cond:
        raise ContractViolation(message)


def program_segments(text: str, machine: Machine):
    """Segments of a program that the interpreter models completely."""
    # The full interpreter (not the vectorized fast path, which its own tests
    # hold to the same segments): this suite is about prover vs controller.
    run = interpret_text(text, machine, fast=False)
    segs = list(run.segments())
    if run.unsupported:
        raise ContractViolation(f"generated program uses unsupported code: {run.unsupported[0]}")
    return segs


def _line_window_hit(seg, a_pos, t_lo, t_hi, tol) -> bool:
    """Is there t in [t_lo, t_hi] with |path(t) - A| <= tol on every axis (exact)?"""
    lo, hi = max(F0, t_lo), min(Fraction(1), t_hi)
    for s, e, a in zip(seg.start, seg.end, a_pos):
        d = e - s
        if d == 0:
            if abs(s - a) > tol:
                return False
            continue
        t1, t2 = (a - tol - s) / d, (a + tol - s) / d
        lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    return lo <= hi


def _first_exit_check(machine, seg, v0, vu, alarm, u) -> None:
    """Clause (2b): a transversal crossing of an axis-aligned face by a line."""
    linear = seg.kind is SegmentKind.LINE or (
        seg.kind is SegmentKind.RAPID and machine.rapid_mode is RapidMode.LINEAR)
    if not linear:
        _count("first exit: not a straight motion (arc or dogleg), window check only")
        return
    if not (v0.first_exit_exact and vu.first_exit_exact):
        _count("first exit: parameter not exact, skipped")
        return
    pulses = [machine.axis(a).pulse for a in seg.axes]
    delta = [abs((e - s) / p) for s, e, p in zip(seg.start, seg.end, pulses)]
    n_steps = max(delta)
    e = dict(v0.first_exit)
    faces, near = [], []
    for k, a in enumerate(seg.axes):
        consts = zone_constants(machine, a, seg.tool_length)
        gap = min((abs(e[a] - c) for c in consts), default=None)
        if gap == 0:
            faces.append(k)
        elif gap is not None and gap < 3 * u:
            near.append(k)
    if len(faces) != 1 or near or delta[faces[0]] != n_steps or n_steps.denominator != 1:
        _count("first exit: oblique, corner or minor-axis crossing (gray)")
        return
    j = faces[0]
    a_pos = alarm.position
    dist = max(abs(a_pos[k] - e[a]) / pulses[k] for k, a in enumerate(seg.axes))
    STATS["first exit: max distance (pulses) x1000"] = max(
        STATS["first exit: max distance (pulses) x1000"], int(dist * 1000))
    _require(abs(a_pos[j] - e[seg.axes[j]]) <= u,
             f"alarm at {a_pos} is more than one pulse from the first exit {e} on the crossing axis {seg.axes[j]}")
    _require(_line_window_hit(seg, a_pos, vu.first_exit_parameter, v0.first_exit_parameter + 1 / n_steps, u),
             f"alarm at {a_pos} is not within one pulse of the path between the margin-u entry "
             f"(t={vu.first_exit_parameter}) and one step past the first exit (t={v0.first_exit_parameter})")
    _count("first exit: transversal, checked")


def _replay_witnesses(machine, result, by_block, margin) -> None:
    """Clause (3): every reported witness is outside the allowed set (exactly)."""
    for v in result.violations:
        seg = by_block[v.block][0]
        names = {z.name for z in machine.allowed.violated_zones(dict(v.point), seg.tool_length)}
        _require(bool(names), f"witness {dict(v.point)} of block {v.block} is inside the allowed set")
        _require(v.zone in names, f"witness of block {v.block} names zone {v.zone!r}, but violates {sorted(names)}")
        pp, p = dict(v.path_point), dict(v.point)
        _require(all(abs(p[a] - pp[a]) <= margin for a in p),
                 f"witness {p} is not within the margin box of its path point {pp}")
        segs = by_block[v.block]
        if len(segs) == 1 and v.parameter_exact and segs[0].kind is SegmentKind.LINE:
            s = segs[0]
            at = tuple(a + v.parameter * (b - a) for a, b in zip(s.start, s.end))
            _require(dict(zip(s.axes, at)) == pp, f"path point {pp} is not the line's point at t={v.parameter}")
        if len(segs) == 1 and segs[0].kind is SegmentKind.ARC and segs[0].centre is not None and not segs[0].is_helix():
            s = segs[0]
            i, j, _ = s.plane_indices()
            r2 = (s.start[i] - s.centre[0]) ** 2 + (s.start[j] - s.centre[1]) ** 2
            q = (pp[s.axes[i]] - s.centre[0]) ** 2 + (pp[s.axes[j]] - s.centre[1]) ** 2
            if q != r2:
                _count("witness: arc path point not exactly on the circle (enclosure)")


def _max_speed_mm_s(machine, segs) -> Fraction:
    feeds = [s.feed_mm_min for s in segs if s.feed_mm_min is not None]
    rates = [a.rapid_mm_min for a in machine.axes]
    return max(feeds + rates) / 60


def check_contract(machine: Machine, text: str, *, verify=verify_segments, periodic: bool = True) -> str:
    """Check DESIGN §7 on one program; returns the outcome class (also counted in STATS)."""
    segs = program_segments(text, machine)
    u = max(a.pulse for a in machine.axes)
    r0 = verify(segs, machine, max_violations=3)
    ru = verify(segs, machine, margin=u, max_violations=1)
    by_block: dict[int, list] = {}
    for s in segs:
        by_block.setdefault(s.block, []).append(s)
    _replay_witnesses(machine, r0, by_block, F0)
    _replay_witnesses(machine, ru, by_block, u)
    if Verdict.UNKNOWN in (r0.verdict, ru.verdict):
        _count("prover unknown (not compared)")
        _flush()
        return "unknown"
    _require(not (ru.verdict is Verdict.SAFE and r0.verdict is not Verdict.SAFE),
             "safe with a one-pulse margin but not safe with none")
    sim = simulate(segs, machine, start=machine.start, monitor="pulse")
    alarm = sim.alarms[0] if sim.alarms else None
    if ru.verdict is Verdict.SAFE:
        # clause (1)
        _require(alarm is None, f"prover: safe with margin {u}; controller: alarm {alarm}")
        _count("safe with margin u: no alarm")
        outcome = "safe"
    else:
        b_u = ru.violations[0].block
        if alarm is not None:
            tl = by_block[alarm.block][0].tool_length if alarm.block is not None else F0
            _require(not machine.allowed.contains(machine.point(alarm.position), tl),
                     f"alarm at {alarm.position}, a point inside the allowed set")
            _require(alarm.block is not None and alarm.block >= b_u,
                     f"alarm in block {alarm.block}, before any point comes within one pulse of a boundary "
                     f"(first such block: {b_u})")
        deep = next((v for v in r0.violations if v.depth > u), None)
        if r0.verdict is Verdict.SAFE and alarm is not None:
            # gray only if the path really stays inside: the independent brute force must agree
            hit = first_violation(segs, machine)
            _require(hit is None, f"prover: safe; controller alarms in block {alarm.block} and the brute force "
                                  f"finds the path point {hit and hit.point} of block {hit and hit.block} outside")
        if deep is None:
            kind = "safe" if r0.verdict is Verdict.SAFE else "unsafe <= 1 pulse deep"
            _count(f"gray band ({kind}): {'alarm' if alarm else 'no alarm'}")
            outcome = "gray"
        else:
            # clause (2)
            _require(alarm is not None,
                     f"prover: block {deep.block} goes {deep.depth} deep (> {u}); controller: no alarm")
            _require(alarm.block <= deep.block,
                     f"prover: block {deep.block} goes {deep.depth} deep; controller alarms only in block {alarm.block}")
            v0, vu = r0.violations[0], ru.violations[0]
            if alarm.block < deep.block:
                _count("unsafe: alarm in an earlier block that comes within one pulse")
            else:
                _count("unsafe: alarm in the deep block")
            if v0 is deep and v0.block == alarm.block == vu.block and len(by_block[v0.block]) == 1:
                _first_exit_check(machine, by_block[v0.block][0], v0, vu, alarm, u)
            outcome = "unsafe"
    if periodic:
        _check_periodic(machine, segs, alarm)
    _flush()
    return outcome


def _check_periodic(machine, segs, alarm) -> None:
    """Periodic monitoring: no alarm without a pulse alarm; at most one period (+1 pulse) later."""
    sim = simulate(segs, machine, start=machine.start, monitor="periodic")
    p = sim.alarms[0] if sim.alarms else None
    if alarm is None:
        _require(p is None, f"periodic monitor alarms at {p and p.position} although no pulse position is outside")
        return
    if p is None:
        _count("periodic: excursion shorter than a period, not sampled")
        return
    period_s = machine.monitor_period_ms / 1000
    _require(p.time_s >= alarm.time_s - 1e-9, "periodic alarm before the first outside pulse")
    tl = next((s.tool_length for s in segs if s.block == p.block), segs[-1].tool_length)
    _require(not machine.allowed.contains(machine.point(p.position), tl),
             f"periodic alarm at {p.position}, a point inside the allowed set")
    if p.block is None:
        _count("periodic: caught by the sample after the program ended")
        return
    if p.block != alarm.block:
        _count("periodic: caught in a later block (the first excursion was shorter than a period)")
        return
    seg = [s for s in segs if s.block == p.block]
    if len(seg) != 1 or not (seg[0].kind is SegmentKind.LINE or (
            seg[0].kind is SegmentKind.RAPID and machine.rapid_mode is RapidMode.LINEAR)):
        _count("periodic: same block, not a straight motion (time bound not checked)")
        return
    # Same excursion?  The controller's own pulses of this line, between the two alarms, all outside.
    pulses = [a.pulse for a in machine.axes]
    p0 = tuple(round_pulse(v, q) for v, q in zip(seg[0].start, pulses))
    p1 = tuple(round_pulse(v, q) for v, q in zip(seg[0].end, pulses))
    steps = list(line_steps(p0, p1))
    i, j = steps.index(tuple(alarm.pulse_position)), steps.index(tuple(p.pulse_position))
    if any(machine.allowed.contains(machine.point(tuple(k * q for k, q in zip(st, pulses))), tl)
           for st in steps[i:j + 1]):
        _count("periodic: the first excursion re-entered before a sample")
        return
    _require(p.time_s - alarm.time_s <= float(period_s) + 1e-9,
             f"periodic alarm {p.time_s - alarm.time_s:.6f} s after the first outside pulse (> one period)")
    u = max(a.pulse for a in machine.axes)
    travel = _max_speed_mm_s(machine, segs) * period_s + u
    dist = max(abs(a - b) for a, b in zip(p.position, alarm.position))
    _require(dist <= travel, f"periodic alarm {dist} mm past the first outside pulse (> one period of travel + 1 pulse = {travel})")
    _count("periodic: alarm within one period of travel")


# --------------------------------------------------------------------------- tool solids (issue 39)

#: How far (mm, in pulses of the machine) the grown and shrunk provers move every fixture face: a pulse
#: position is within 2 pulses per axis of a path point (the rounding of the pulse distribution), so within
#: 2·√2 < 3 pulses horizontally and 2 vertically, and the controller grows each part by half a step (at most
#: one pulse horizontally, half a pulse vertically): 4 pulses covers both.
SOLIDS_GROW = 4


def _solid_violations(result):
    return [v for v in result.violations if v.kind == "solid"]


def _first_block(items) -> int | None:
    blocks = [x.block for x in items if x.block is not None]
    return min(blocks) if blocks else None


def _replay_solid_witnesses(solids, result, by_block) -> None:
    """Every solid witness is a point inside the named part (placed at the reported path point) and inside the
    named fixture's open interior, decided exactly by the oracle (tests/oracles/solids.py)."""
    from oracles.solids import inside_part_and_fixture

    for v in _solid_violations(result):
        seg = by_block[v.block][0]
        parts = solids.parts_for(seg.tool_register) or ()
        part = next((p for p in parts if p.name in v.zones), None)
        fx = next((f for f in solids.fixtures if f.name == v.zone), None)
        _require(part is not None and fx is not None, f"witness names part {v.zones} / fixture {v.zone!r}, "
                 f"not parts of tool H{seg.tool_register} and a fixture")
        point, path = tuple(x for _, x in v.point), tuple(x for _, x in v.path_point)
        _require(inside_part_and_fixture(point, path, part, fx, seg.tool_length),
                 f"solid witness {point} is not inside {part.label()} at {path} and inside `{fx.name}`: {v.note}")
        segs = by_block[v.block]
        if len(segs) == 1 and v.parameter_exact and segs[0].kind is SegmentKind.LINE:
            s = segs[0]
            at = tuple(a + v.parameter * (b - a) for a, b in zip(s.start, s.end))
            _require(at == path, f"solid witness path point {path} is not the line's point at t={v.parameter}")
        _count("solids: unsafe witness replayed")


def check_solids_contract(pulse: str, tools: dict, fixtures: list, text: str, *, prove=None) -> str:
    """The contract with tool solids on one generated machine and program (specs/contract.md, "Tool solids").

    Three provers: on the machine (``r0``), with every fixture grown by :data:`SOLIDS_GROW` pulses (``rg``) and
    shrunk by as much (``rs``); the controller (pulse monitor, vector engine) on the machine.

    * (S1) ``rg`` safe => no solid alarm; a solid alarm in block b => ``rg`` has a solid violation or an
      ``unknown`` reason in a block <= b.
    * (S2) ``rs`` has a solid violation in block b => the controller alarms (solid or stroke) in a block <= b.
    * (S3) every solid witness of ``r0`` is replayed exactly (inside the part and the fixture).
    * gray band: ``r0`` safe and a solid alarm: counted; the alarm position must be clear of the shrunk
      fixtures for every part (else a path point near it would put a part into a fixture: ``r0`` was wrong).
    """
    from nczones.machine import parse_machine
    from nczones.prover import VerifyOptions
    from nczones.prover import prove as _prove
    from nczones.solids import machine_solids

    from .strategies import solids_machine_text
    from oracles.solids import part_hits

    prove = prove or _prove
    u = Fraction(pulse)
    machine = parse_machine(solids_machine_text(pulse, tools, fixtures), "solids.toml")
    grown = parse_machine(solids_machine_text(pulse, tools, fixtures, grow=str(SOLIDS_GROW * u)), "grown.toml")
    shrunk = parse_machine(solids_machine_text(pulse, tools, fixtures, grow=str(-SOLIDS_GROW * u)), "shrunk.toml")
    segs = program_segments(text, machine)
    by_block: dict[int, list] = {}
    for s in segs:
        by_block.setdefault(s.block, []).append(s)
    opts = VerifyOptions(max_violations=1000)
    r0, rg, rs = (prove(segs, m, opts) for m in (machine, grown, shrunk))
    solids = machine_solids(machine)
    _replay_solid_witnesses(solids, r0, by_block)
    sim = simulate(segs, machine, start=machine.start, monitor="pulse")
    alarm = sim.alarms[0] if sim.alarms else None
    solid_alarm = alarm if alarm is not None and alarm.kind == "solid" else None
    # (S1)
    if rg.verdict is Verdict.SAFE:
        _require(solid_alarm is None, f"prover: safe with the fixtures grown by {SOLIDS_GROW} pulses; controller: "
                                      f"{solid_alarm}")
        _count("solids: grown safe, no solid alarm")
    if solid_alarm is not None:
        first = _first_block(_solid_violations(rg) + list(rg.reasons))
        _require(first is not None and first <= solid_alarm.block,
                 f"controller: {solid_alarm.part} enters `{solid_alarm.zone}` in block {solid_alarm.block}; the "
                 f"prover with the fixtures grown finds nothing there or before (first: {first})")
    # (S2)
    deep = _first_block(_solid_violations(rs))
    if deep is not None:
        _require(alarm is not None and alarm.block is not None and alarm.block <= deep,
                 f"prover: a part enters a fixture shrunk by {SOLIDS_GROW} pulses in block {deep}; controller: "
                 f"{'no alarm' if alarm is None else f'alarm only in block {alarm.block}'}")
        _count("solids: deep (shrunk unsafe), alarm at or before" + (" (stroke)" if solid_alarm is None else ""))
    # the gray band
    if r0.verdict is Verdict.SAFE and solid_alarm is not None:
        seg = by_block[solid_alarm.block][0]
        small = machine_solids(shrunk)
        x, y, z = solid_alarm.position
        for part in solids.parts_for(seg.tool_register) or solids.spindle:
            for fx in small.fixtures if small is not None else ():
                _require(not part_hits(part, fx, x, y, z, seg.tool_length),
                         f"prover: safe; controller alarm at {solid_alarm.position}, where {part.label()} is in "
                         f"`{fx.name}` shrunk by {SOLIDS_GROW} pulses")
        _count("solids: gray band (safe, solid alarm)")
    outcome = {Verdict.SAFE: "safe", Verdict.UNSAFE: "unsafe"}.get(r0.verdict, "unknown")
    _count(f"solids: prover {outcome}, controller {alarm.kind if alarm else 'clean'}")
    _flush()
    return outcome
