"""Metamorphic soundness of tool-break recovery (``--recovery``) where it meets the other features.

The issue-18 relations (:mod:`.metamorphic`) never turn recovery on.  Here the same drawn machines get a
``[tool_change]`` section (position on or inside the travel, clearance or retract distance, approach
distance, variant, replacement length register) and a fence box standing between the work area and the
tool-change position whose top lies at, just above or just below the retract height (a spindle zone, or
a tool-tip zone whose top is measured from the broken tool's tip).  The programs are the issue-18
programs (cutting moves, spiral and exact arcs, G81/G83 cycles, ``G43 Hn``, ``G10 L1/L10``, work
offsets, state reads, block-delete lines) with at least one cutting motion, so a tool can break.

Relations (each a test failure when broken; any exception other than a G-code input error fails too):

* **recovery extends the base proof** (:func:`check_recovery_extends_base`): the recovery proof adds the
  recovery legs to the program's own motions (``specs/recovery.md``: the verdict with ``--recovery`` is
  the program's violations plus the recovery's), so the motion violations with recovery on are exactly
  those without it, `safe` with recovery implies `safe` without, `unsafe` without implies `unsafe` with,
  and every reason without recovery is a reason with it.
* **ranges vs concrete values** (:func:`check_recovery_ranges`): the recovery is proved at one concrete
  point of the parameter ranges (RC204 says so and keeps the verdict from `safe`).  A motion violation
  at a sampled value must be found over the ranges unless a reason other than RC204 excuses its line;
  every witness (motion or recovery) names parameter values *inside the ranges* and replays, at those
  values and its block-delete position, as `unsafe` at its line (a recovery witness as a recovery
  violation from the same break line).
* **margins** (:func:`check_recovery_margins`): `unsafe` at margin 0 implies `unsafe` at ``d``; `safe` at
  ``d`` implies `safe` at 0 and ``d/2`` and `safe` at ``d - |v|`` for the path shifted by ``v``, where the
  shift moves the zones, the tool-change position *and the clearance height* by ``-v`` (those three are
  machine-fixed; a retract distance is relative and stays).  Every leg of the shifted recovery path is
  then within ``|v|`` (L-infinity, pointwise in time) of the original leg, dogleg rapids included.
* **state reads** (:func:`check_recovery_state_reads`): with recovery on, a program and its copy with
  every state read replaced by the value it read verify alike (verdict, violations with their break
  lines and legs).
* **the controller as the independent witness** (:func:`check_recovery_controller`): the reference
  controller runs the recovery from sampled break points (every cutting line of both block-delete
  positions, at the start, the middle and the end of its first cutting motion).  Proved `safe` with the
  margin of one pulse ``u`` ⇒ no alarm at any of them.  A recovery alarm in leg ``k`` from a break in
  line ``b`` ⇒ the margin-``u`` proof has a recovery violation from ``b`` in leg ``k`` or an earlier one
  (the prover reports the first failing leg of a motion: the legs before it are proved for every break
  point), or a reason there; counted gray when the margin-0 proof has none.  Every recovery witness (not the ``resume`` leg) replayed
  at its break point (the controller's step nearest to it) alarms when deeper than two pulses (the
  break point itself is quantized to a step: one pulse, plus the band of one pulse); shallower ones are
  counted as gray, not failed.
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from types import MappingProxyType

from hypothesis import assume
from hypothesis import strategies as st

from nczones.controller import Controller, simulate
from nczones.errors import InputError, MachineFileError
from nczones.gcode import interpret_text
from nczones.machine import Machine, parse_machine
from nczones.motion import SegmentKind, segments_of
from nczones.plans.recovery import LEG_NAMES, ToolChangeConfig, is_cutting
from nczones.prover import parse_param

from .metamorphic import (
    MetamorphicViolation,
    _box,
    _counted,
    _dec,
    _note,
    _require,
    _samples,
    _vals,
    meta_machines,
    meta_programs,
    meta_ranges,
    state_reads_substituted,
)
from oracles.concrete import machine_at, shift_zones

F = Fraction
F0 = Fraction(0)
#: The pulse of every drawn machine.
U = F(1, 100)
_CUTTING = ("G1 ", "G2 ", "G3 ", "G81", "G83")


# ----------------------------------------------------------------------------- machines


@st.composite
def recovery_machines(draw, *, clear: bool = False) -> tuple[Machine, str]:
    """(machine, TOML text): a :func:`meta_machines` machine with ``[tool_change]`` and a fence near the legs.

    ``clear``: the tool-change position and the clearance height lie 3 mm inside the travel, so that a
    recovery can be safe with a margin (of one pulse, or of up to 2 mm)."""
    _, text = draw(meta_machines())
    lines = {}
    for row in text.splitlines():
        if "=" in row and row.split("=")[0].strip() in ("H1", "H2"):
            lines[row.split("=")[0].strip()] = F(row.split('"')[1])
    edges = (F(3), F(97)) if clear else (F0, F(100))
    top = F(197) if clear else F(200)
    tc = {"X": draw(st.sampled_from((*edges, _vals(draw, F(3), F(97))))),
          "Y": draw(st.sampled_from((*edges, _vals(draw, F(3), F(97))))),
          "Z": draw(st.sampled_from((top, _vals(draw, F(150), F(197)))))}
    retract = {}
    if clear or draw(st.integers(0, 3)):
        clearance = draw(st.sampled_from((top, _vals(draw, F(100), F(197)))))
        retract["clearance"] = clearance
        height = clearance
    else:
        retract["retract_distance"] = draw(st.sampled_from((F0, F(5), _vals(draw, F(1), F(60)))))
        height = _vals(draw, F(100), F(190))
    alpha = draw(st.sampled_from((F0, F(1, 2), F(2), F(5))))
    variant = draw(st.sampled_from(("start", "breakpoint")))
    register = draw(st.sampled_from((None, None, "H1", "H2")))
    section = ["[tool_change]",
               "position = { " + ", ".join(f'{a} = "{_dec(v)}"' for a, v in tc.items()) + " }",
               *(f'{k} = "{_dec(v)}"' for k, v in retract.items()),
               f'approach_distance = "{_dec(alpha)}"', 'approach_feed = "200"', f'variant = "{variant}"']
    if register:
        section.append(f'length_register = "{register}"')
    zones = []
    if draw(st.integers(0, 4)):
        # a fence between a point of the work area and the tool-change position, its top at the retract height
        w = {a: _vals(draw, F(10), F(90)) for a in "XY"}
        f = draw(st.sampled_from((F(3, 10), F(1, 2), F(7, 10))))
        centre = {a: w[a] + f * (tc[a] - w[a]) for a in "XY"}
        half = {a: _vals(draw, F(1), F(10)) for a in "XY"}
        tip = draw(st.booleans())
        top = height + draw(st.sampled_from((F0, U, -U, F(1, 2), F(-1, 2), F(2), F(-2))))
        if tip:
            top -= lines[draw(st.sampled_from(("H1", "H2")))]
        top = max(min(top, F(200)), F(1))
        lo = {a: max(F0, centre[a] - half[a]) for a in "XY"}
        hi = {a: min(F(100), centre[a] + half[a]) for a in "XY"}
        lo["Z"], hi["Z"] = F0, top
        zones.append(_box("fence", lo, hi, True, tip=tip))
    head, sep, tail = text.partition("[[zones]]")
    full = head + "\n".join(section) + "\n\n" + sep + tail + "\n".join(zones) + ("\n" if zones else "")
    try:
        machine = parse_machine(full, "recovery.toml")
    except MachineFileError as exc:
        if all(d.code == "ZN130" for d in exc.diagnostics):  # the start inside the fence: draw again
            assume(False)
        raise
    return machine, full


def _cuts(text: str) -> bool:
    return any(c in text for c in _CUTTING)


@st.composite
def recovery_programs(draw, machine: Machine, *, used: set | None = None, reads: bool = True,
                      deletes: bool = True, inside: Fraction | None = None) -> str:
    """A :func:`meta_programs` program with at least one cutting motion (a tool can break)."""
    text = draw(meta_programs(machine, used=used, reads=reads, deletes=deletes, inside=inside))
    assume(_cuts(text))
    return text


@st.composite
def recovery_base_cases(draw):
    machine, _ = draw(recovery_machines())
    return machine, draw(recovery_programs(machine))


@st.composite
def recovery_range_cases(draw):
    machine, _ = draw(recovery_machines())
    used: set = set()
    text = draw(recovery_programs(machine, used=used))
    return machine, text, draw(meta_ranges(machine, used))


@st.composite
def recovery_margin_cases(draw):
    machine, _ = draw(recovery_machines(clear=draw(st.integers(0, 3)) > 0))
    margin = draw(st.sampled_from((F(1, 100), F(1, 10), F(1, 2), F(2))))
    text = draw(recovery_programs(machine, reads=False, inside=margin if draw(st.integers(0, 3)) else None))
    frac = [draw(st.sampled_from((F0, F(1, 3), F(-1, 2), F(9, 10), F(-99, 100)))) for _ in range(3)]
    return machine, text, margin, {a: margin * x for a, x in zip("XYZ", frac)}


@st.composite
def recovery_controller_cases(draw):
    """Programs kept off the travel limits half of the time, so that more of them are proved safe with the
    margin of one pulse (only those hold the controller to 'no alarm')."""
    machine, _ = draw(recovery_machines(clear=draw(st.integers(0, 3)) > 0))
    inside = draw(st.sampled_from((None, None, 2 * U, F(1, 2))))
    return machine, draw(recovery_programs(machine, inside=inside))


@st.composite
def recovery_read_cases(draw):
    machine, _ = draw(recovery_machines())
    text = draw(recovery_programs(machine, reads=True, deletes=False))
    assume("#" in text)
    return machine, text


# ----------------------------------------------------------------------------- helpers


def _verify(text: str, machine: Machine, **options):
    """verify_text with recovery, G-code input errors (a drawn program the interpreter refuses) rejected."""
    from nczones.prover import verify_text

    try:
        return verify_text(text, machine, max_violations=50, **options)
    except InputError as exc:
        _note(f"rejected: {exc.diagnostics[0].code if hasattr(exc, 'diagnostics') else type(exc).__name__}")
        assume(False)
        raise


def _variant(machine: Machine) -> str:
    return machine.sections["tool_change"].variant.value


def _key(v) -> tuple:
    return (v.kind, v.line, v.zone, v.switches, v.break_line, v.leg)


def shift_machine(machine: Machine, by: dict[str, Fraction]) -> Machine:
    """``machine`` with its zones, its tool-change position and its clearance height moved by ``by``.

    Everything fixed to the machine moves, so the whole recovery path moves by ``-by`` relative to it.
    """
    moved = shift_zones(machine, by)
    cfg: ToolChangeConfig = machine.sections["tool_change"]
    cfg = replace(cfg, position=tuple((a, v + by.get(a, 0)) for a, v in cfg.position),
                  clearance=None if cfg.clearance is None else cfg.clearance + by.get(cfg.retract_axis, 0))
    return replace(moved, sections=MappingProxyType({**machine.sections, "tool_change": cfg}))


def _within(machine: Machine, params: tuple[str, ...], values: dict[str, Fraction]) -> str | None:
    """None when ``values`` (a witness's parameters, missing ones at the machine file's value) lie in the
    ranges, else what is outside."""
    for p in params:
        r = parse_param(p, machine)
        nominal = machine.tool_length(int(r.name[1:])) if r.absolute else F0
        x = values.get(r.name, nominal)
        lo, hi = r.written
        if not lo <= x <= hi:
            return f"{r.name} = {x} (range {lo}..{hi}{', not given: the file value' if r.name not in values else ''})"
    return None


# ----------------------------------------------------------------------------- relations


def check_recovery_extends_base(machine: Machine, text: str) -> None:
    """The recovery proof adds the legs to the program's own proof and changes nothing of it."""
    base = _verify(text, machine)
    rec = _verify(text, machine, recovery=_variant(machine))
    _counted("recovery base")
    _note(f"recovery base: {base.verdict.label} without, {rec.verdict.label} with")
    motion = [_key(v) for v in rec.violations if v.kind != "recovery"]
    _require(motion == [_key(v) for v in base.violations],
             f"motion violations differ with recovery on: {motion} vs {[_key(v) for v in base.violations]}")
    if rec.verdict.label == "safe":
        _require(base.verdict.label == "safe", f"safe with recovery but {base.verdict.label} without")
    if base.verdict.label == "unsafe":
        _require(rec.verdict.label == "unsafe", f"unsafe without recovery but {rec.verdict.label} with")
    missing = {(r.code, r.message) for r in base.reasons} - {(r.code, r.message) for r in rec.reasons}
    _require(not missing, f"reasons lost with recovery on: {missing}")


def check_recovery_ranges(machine: Machine, text: str, params: tuple[str, ...]) -> None:
    """A range verdict with recovery on against its concrete values (module docstring)."""
    variant = _variant(machine)
    result = _verify(text, machine, params=params, recovery=variant)
    _counted("recovery ranges")
    _note(f"recovery ranges: {result.verdict.label}")
    _require(any(r.code == "RC204" for r in result.reasons),
             "recovery over parameter ranges without RC204 (the recovery is proved at one point only)")
    lines = {v.line for v in result.violations if v.kind != "recovery"}
    excused = min([r.span.line if r.span is not None else 0 for r in result.reasons if r.code != "RC204"],
                  default=None)
    for values in _samples(machine, params, result.extra.get("splits", ())):
        concrete = _verify(text, machine_at(machine, values), recovery=variant)
        if result.verdict.label == "safe":
            _require(concrete.verdict.label == "safe", f"safe over {params} but {concrete.verdict.label} at {values}")
        for v in concrete.violations:
            if v.kind == "recovery" or v.line in lines or (excused is not None and excused <= (v.line or 0)):
                continue
            raise MetamorphicViolation(
                f"line {v.line} leaves zone {v.zone!r} at {values}, but the verification over {params} with "
                f"recovery is {result.verdict.label} there (motion violations at lines {sorted(lines)})")
    recovery = [v for v in result.violations if v.kind == "recovery"][:3]
    for v in [w for w in result.violations if w.kind != "recovery"][:3] + recovery:
        values = dict(v.params)
        outside = _within(machine, params, values)
        _require(outside is None, f"the {v.kind} witness of line {v.line} ({v.zone}, leg {v.leg!r}) over {params} "
                                  f"lies outside the ranges: {outside}")
        position = dict(v.switches).get("block_delete")
        replay = _verify(text, machine_at(machine, values), block_delete=position or "both", recovery=variant)
        if v.kind == "recovery":
            found = {(w.kind, w.break_line) for w in replay.violations}
            ok = ("recovery", v.break_line) in found
        else:
            found = {(w.kind, w.line) for w in replay.violations}
            ok = any(line == v.line for _, line in found)
        _require(replay.verdict.label == "unsafe" and ok,
                 f"the {v.kind} witness of line {v.line} (break line {v.break_line}, leg {v.leg!r}) over {params} "
                 f"at {values}{' block delete ' + position if position else ''} does not replay: "
                 f"{replay.verdict.label}, {sorted(found, key=str)}")
        _note(f"recovery ranges: {v.kind} witness replayed")


def check_recovery_margins(machine: Machine, text: str, margin: Fraction, shift: dict[str, Fraction]) -> None:
    """Margin monotonicity with recovery on, and the margin as clearance against a shifted path."""
    variant = _variant(machine)
    at_d = _verify(text, machine, margin=margin, recovery=variant)
    at_0 = _verify(text, machine, recovery=variant)
    _counted("recovery margins")
    _note(f"recovery margin: {at_0.verdict.label} at 0, {at_d.verdict.label} at d")
    if at_0.verdict.label == "unsafe":
        _require(at_d.verdict.label == "unsafe",
                 f"unsafe at margin 0 ({[_key(v) for v in at_0.violations[:3]]}) but {at_d.verdict.label} at "
                 f"margin {margin}: {[(r.code, r.message) for r in at_d.reasons[:3]]}")
    if at_d.verdict.label != "safe":
        return
    _require(at_0.verdict.label == "safe", f"safe at margin {margin} but {at_0.verdict.label} at 0")
    half = _verify(text, machine, margin=margin / 2, recovery=variant)
    _require(half.verdict.label == "safe", f"safe at margin {margin} but {half.verdict.label} at {margin / 2}")
    length = max(abs(x) for x in shift.values())
    moved = shift_machine(machine, {a: -x for a, x in shift.items()})
    shifted = _verify(text, moved, margin=margin - length, recovery=variant)
    _require(shifted.verdict.label == "safe",
             f"safe at margin {margin} but the path shifted by {shift} is {shifted.verdict.label} at margin "
             f"{margin - length}: {[_key(w) for w in shifted.violations[:3]]}")


def check_recovery_state_reads(machine: Machine, text: str) -> None:
    """With recovery on, a program and its copy with every state read replaced by its value verify alike."""
    copy = state_reads_substituted(machine, text)
    assume(copy is not None)
    variant = _variant(machine)
    a = _verify(text, machine, recovery=variant)
    b = _verify(copy, machine, recovery=variant)
    _counted("recovery state reads")
    _note(f"recovery state reads: {a.verdict.label}")
    key_a, key_b = [_key(v) for v in a.violations], [_key(v) for v in b.violations]
    _require(a.verdict.label == b.verdict.label and key_a == key_b,
             f"reads {a.verdict.label} {key_a} but values {b.verdict.label} {key_b}\n{copy}")


def _positions(text: str) -> tuple[bool, ...]:
    from nczones.blockskip import used_switches

    return (False, True) if used_switches(text, "linuxcnc") else (False,)


def _break_steps(machine: Machine, segs, index: int) -> tuple[list[tuple[int, ...]], int] | None:
    """The pulse positions (step 0 = the start) of segment ``index`` as the controller interpolates it, after
    running the segments before it; None when the controller halts before it."""
    import numpy as np

    ctl = Controller(machine, start=segs[0].start)
    for s in segs[:index]:
        ctl.run_segment(s)
        if ctl.halted:
            return None
    seg = segs[index]
    ctl.tool_length = seg.tool_length
    plan = ctl.plan(seg)
    rows = np.asarray(plan.chunk(0, plan.n), dtype=np.int64).reshape(plan.n, len(plan.p0)) if plan.n else []
    return [tuple(plan.p0)] + [tuple(int(x) for x in r) for r in rows], plan.n


def _replay_fraction(machine: Machine, segs, v) -> Fraction | str:
    """The break fraction whose step is nearest the witness's break point, on the first cutting motion of its
    line (where the controller breaks); else why there is none."""
    index = next((i for i, s in enumerate(segs) if is_cutting(s) and s.line == v.break_line), None)
    if index is None:
        return "no cutting motion in its line"
    seg = segs[index]
    bp = tuple(x for _, x in v.break_point)
    if seg.kind is SegmentKind.LINE:
        d = [b - a for a, b in zip(seg.start, seg.end)]
        k = max(range(len(d)), key=lambda j: abs(d[j]))
        t = (bp[k] - seg.start[k]) / d[k] if d[k] else F0  # a motion of length 0: its start
        if not 0 <= t <= 1 or any(seg.start[j] + t * d[j] != bp[j] for j in range(len(d))):
            return "not on the first cutting motion of its line"
    else:
        i, j, _ = seg.plane_indices()
        c = seg.centre
        r2 = (seg.start[i] - c[0]) ** 2 + (seg.start[j] - c[1]) ** 2
        if (bp[i] - c[0]) ** 2 + (bp[j] - c[1]) ** 2 != r2:
            return "not on the first cutting motion of its line"
    steps = _break_steps(machine, segs, index)
    if steps is None:
        return "the controller halts before the break (the program's own alarm)"
    rows, n = steps
    if n == 0:
        return F0
    want = [x / U for x in bp]
    k = min(range(n + 1), key=lambda s: max(abs(p - w) for p, w in zip(rows[s], want)))
    return F(k, n)


def check_recovery_controller(machine: Machine, text: str) -> None:
    """The prover's recovery verdict against the reference controller running the recovery (module docstring)."""
    variant = _variant(machine)
    r0 = _verify(text, machine, recovery=variant)
    ru = _verify(text, machine, recovery=variant, margin=U)
    _counted("recovery controller")
    _note(f"recovery controller: {r0.verdict.label} at 0, {ru.verdict.label} at one pulse")
    for skip in _positions(text):
        switch = "on" if skip else "off"
        run = interpret_text(text, machine, block_delete=skip, fast=False)
        segs = list(segments_of(run))
        if run.unsupported:
            continue
        lines = []
        for s in segs:
            if is_cutting(s) and s.line not in lines:
                lines.append(s.line)

        rec0 = [v for v in r0.violations if v.kind == "recovery"]
        recu = [v for v in ru.violations if v.kind == "recovery"]
        for line in lines[:4]:
            for frac in (F0, F(1, 2), F(1)):
                sim = simulate(segs, machine, break_at=(line, frac))
                if ru.verdict.label == "safe" and sim.alarms:
                    raise MetamorphicViolation(f"recovery proved safe with margin {U}, but the controller alarms "
                                               f"with a break at line {line}:{frac} (block delete {switch}): "
                                               f"{sim.alarms[0]}")
                alarms = [a for a in sim.alarms if a.kind == "recovery"]
                if not alarms:
                    continue
                reasons = [r for r in (*r0.reasons, *ru.reasons) if r.span is None or r.span.line == line
                           or (not r.code.startswith("RC") and r.span.line <= line)]
                if reasons:
                    _note("recovery controller: alarm where the prover is unknown")
                    continue
                leg = alarms[0].derived.split(": ", 1)[1]
                found = [LEG_NAMES.index(v.leg) for v in recu if v.break_line == line and v.leg != "resume"]
                _require(bool(found),
                         f"the controller alarms in the recovery from a break at line {line}:{frac} (block delete "
                         f"{switch}, leg {leg!r}, zone {alarms[0].zone}), but the prover found no recovery "
                         f"violation from line {line} even with margin {U}")
                # the prover tries the legs in order and reports the first that fails: the legs before it are
                # proved for every break point of the motion, with the margin of one pulse
                _require(LEG_NAMES.index(leg) >= min(found),
                         f"the controller alarms in leg {leg!r} from a break at line {line}:{frac} (block delete "
                         f"{switch}, zone {alarms[0].zone}), a leg the prover proved with margin {U} (its first "
                         f"failing leg there is {LEG_NAMES[min(found)]!r})")
                if any(v.break_line == line for v in rec0):
                    _note("recovery controller: alarm where the prover found the break line unsafe")
                else:
                    _note("gray band (recovery): alarm, unsafe only with margin u")
        mine = [w for w in rec0 if w.leg != "resume" and dict(w.switches).get("block_delete", "off") == switch]
        for v in mine[:3]:
            frac = _replay_fraction(machine, segs, v)
            if isinstance(frac, str):
                _note(f"recovery controller: witness not replayed, {frac}")
                continue
            sim = simulate(segs, machine, break_at=(v.break_line, frac))
            if sim.alarms:
                _note("recovery controller: witness replayed, alarm")
                continue
            _require(v.depth <= 2 * U,
                     f"the recovery witness from line {v.break_line} (leg {v.leg!r}, zone {v.zone}, depth "
                     f"{v.depth}) does not alarm in the controller at break fraction {frac} (block delete {switch})")
            _note("gray band (recovery witness <= 2 pulses deep): no alarm")
