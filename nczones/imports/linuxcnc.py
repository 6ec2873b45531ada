"""LinuxCNC: the INI file, its parameter file (``.var``) and its tool table (``.tbl``).

What is read and what it becomes is listed in ``specs/machine-import.md``; in
short: ``[TRAJ]`` gives the axes and units, ``[AXIS_<L>]`` and (for identity
kinematics) ``[JOINT_<n>]`` the soft limits, rapid rates and home positions,
``[EMCMOT] SERVO_PERIOD`` the monitor period, ``[RS274NGC]`` the start-up
modal state and the parameter file (work offsets, the G28 position),
``[EMCIO] TOOL_TABLE`` the tool lengths and diameters, ``[EMCIO] TOOL_CHANGE_QUILL_UP``,
``TOOL_CHANGE_AT_G30`` and ``TOOL_CHANGE_POSITION`` the moves of M6.  Every length is
converted from the machine units (``LINEAR_UNITS``) to mm exactly.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..errors import Diagnostic, InvalidArgument, SourceSpan
from ..exact import MAX_ABS_LENGTH, format_decimal
from ..machine import DEFAULT_MODAL, DEFAULT_RETRACT, MODAL_CHOICES, ROTARY_AXES, WORK_OFFSETS
from .ini import IniEntry, IniFile, parse_ini
from .model import (
    INCH,
    Collector,
    HomingDraft,
    ImportedMachine,
    Sourced,
    ZoneDraft,
    frozen,
    in_range,
    line_span,
    read_source,
    rounded_decimal,
)

__all__ = ["read_linuxcnc", "LETTERS", "MODAL_GROUPS", "startup_modal", "modal_changes"]

#: LinuxCNC's axis letters in the order of its parameters (#5221 X .. #5229 W).
LETTERS = "XYZABCUVW"

_LINEAR_UNITS = {"mm": (Fraction(1), "mm"), "metric": (Fraction(1), "mm"),
                 "in": (INCH, "in"), "inch": (INCH, "in"), "imperial": (INCH, "in")}
_ANGULAR_UNITS = {"deg": Fraction(1), "degree": Fraction(1), "grad": Fraction(9, 10), "gon": Fraction(9, 10),
                  "rad": None, "radian": None}
_IDENTITY_KINS = ("trivkins", "gantrykins")
_TRUE = ("1", "true", "yes", "on")
_FALSE = ("0", "false", "no", "off")
_SCALE_KEYS = ("SCALE", "STEP_SCALE", "INPUT_SCALE")

#: The modal groups the machine file's ``modal`` list holds.
MODAL_GROUPS = MODAL_CHOICES


@dataclass
class _Axis:
    letter: str
    section: str | None = None
    joints: list[str] = field(default_factory=list)


class _Reader:
    def __init__(self, ini: IniFile, c: Collector):
        self.ini = ini
        self.c = c
        self.path = ini.path

    # ------------------------------------------------------------------ values

    def real(self, e: IniEntry, *, limit: Fraction | None = None) -> Fraction | None:
        return self.c.real(e.value, e.describe(), e.span, limit=limit)

    def boolean(self, e: IniEntry | None) -> bool:
        if e is None:
            return False
        word = e.value.strip().lower()
        if word in _TRUE:
            return True
        if word not in _FALSE:
            self.c.error("IM105", f"{e.describe()}: {e.value!r} is not a yes/no value; LinuxCNC accepts "
                         "TRUE/YES/ON/1 and FALSE/NO/OFF/0", e.span)
        return False


def _conversion(unit: str, per_min: bool) -> str:
    """How a value in LinuxCNC's machine units becomes mm (deg), per minute for speeds."""
    factor = {"in": " x 25.4", "grad": " x 0.9"}.get(unit, "")
    if per_min:
        return f" {unit}/s,{factor} x 60"
    return f" {unit},{factor}" if factor else ""


def read_linuxcnc(
    path: str,
    text: str,
    c: Collector,
    *,
    parameter_file: str | None = None,
    tool_table: str | None = None,
) -> ImportedMachine:
    """Read a LinuxCNC INI configuration (see the module docstring).

    Errors go to ``c`` (``IM1xx``) and are raised together; notes (``IM2xx``)
    are kept in the result.
    """
    ini = parse_ini(path, text, c)
    c.raise_if_failed()
    rd = _Reader(ini, c)

    # units
    lin_e = ini.get("TRAJ", "LINEAR_UNITS")
    lin: tuple[Fraction, str] | None = None
    if lin_e is None:
        c.error("IM107", "[TRAJ] LINEAR_UNITS is missing; LinuxCNC needs it (mm or inch) to know what its "
                "lengths mean, and so does the import", ini.sections.get("TRAJ"), file=path)
    else:
        lin = _LINEAR_UNITS.get(lin_e.value.strip().lower())
        if lin is None:
            c.error("IM105", f"{lin_e.describe()}: {lin_e.value!r} is not a unit LinuxCNC knows; use mm, metric, "
                    "in, inch or imperial", lin_e.span)

    # axes
    coord_e = ini.get("TRAJ", "COORDINATES")
    if coord_e is None:
        letters = "XYZ"
        axes_how = "no [TRAJ] COORDINATES: LinuxCNC's default X Y Z"
    else:
        letters = ""
        ignored = ""
        for ch in coord_e.value.upper():
            if ch in LETTERS:
                if ch not in letters:
                    letters += ch
            elif not ch.isspace():
                ignored += ch
        axes_how = f"{coord_e.describe()} ({coord_e.where()})"
        if ignored:
            c.note("IM201", f"{coord_e.describe()}: {ignored!r} is not an axis letter; LinuxCNC ignores it too",
                   coord_e.span)
        if not letters:
            c.error("IM107", f"{coord_e.describe()}: no axis letter (X Y Z A B C U V W)", coord_e.span)
    axes = tuple(letters)

    ang_e = ini.get("TRAJ", "ANGULAR_UNITS")
    ang: Fraction | None = Fraction(1)
    rotary = [a for a in axes if a in ROTARY_AXES]
    if ang_e is not None:
        word = ang_e.value.strip().lower()
        if word not in _ANGULAR_UNITS:
            c.error("IM105", f"{ang_e.describe()}: {ang_e.value!r} is not a unit LinuxCNC knows; use deg, degree, "
                    "grad, gon, rad or radian", ang_e.span)
        else:
            ang = _ANGULAR_UNITS[word]
            if ang is None and rotary:
                c.error("IM106", f"{ang_e.describe()}: the machine file measures rotary axes in degrees, and a "
                        "radian is not a finite decimal number of degrees (180/pi); set ANGULAR_UNITS = degree "
                        "and convert the rotary settings", ang_e.span)
    elif rotary:
        c.error("IM107", f"[TRAJ] ANGULAR_UNITS is missing; the rotary axes {' '.join(rotary)} need it",
                ini.sections.get("TRAJ"), file=path)
    c.raise_if_failed()
    assert lin is not None
    ang_unit = "deg" if ang == 1 else "grad"

    def unit_of(letter: str) -> tuple[Fraction, str]:
        if letter in ROTARY_AXES:
            return ang or Fraction(1), ang_unit
        return lin

    # axis and joint sections
    old_style = any(re.fullmatch(r"AXIS_\d", s) for s in ini.sections) and not any(
        s.startswith("JOINT_") for s in ini.sections)
    kins_e = ini.get("KINS", "KINEMATICS")
    kins_words = kins_e.value.split() if kins_e is not None else ["trivkins"]
    kins = kins_words[0] if kins_words else "trivkins"
    identity = kins in _IDENTITY_KINS
    joint_letters = LETTERS
    for w in kins_words[1:]:
        if w.lower().startswith("coordinates="):
            joint_letters = w.split("=", 1)[1].upper()
    info: dict[str, _Axis] = {a: _Axis(a) for a in axes}
    for a in axes:
        if f"AXIS_{a}" in ini.sections:
            info[a].section = f"AXIS_{a}"
        elif old_style and f"AXIS_{LETTERS.index(a)}" in ini.sections:
            info[a].section = f"AXIS_{LETTERS.index(a)}"
    if old_style:
        c.note("IM203", "[AXIS_<number>] sections (LinuxCNC 2.7 and older): read as axis "
               "X Y Z A B C U V W by their number, each its own joint", file=path)
    elif identity:
        for n, letter in enumerate(joint_letters):
            if letter in info and f"JOINT_{n}" in ini.sections:
                info[letter].joints.append(f"JOINT_{n}")
    else:
        joints = sorted(s for s in ini.sections if s.startswith("JOINT_"))
        if joints:
            c.note("IM201", f"[KINS] KINEMATICS = {kins}: not identity kinematics, so the [JOINT_n] limits, "
                   "speeds and home positions are in joint space, which the machine file cannot hold; only "
                   "the [AXIS_<letter>] settings are taken", kins_e.span if kins_e is not None else None,
                   file=path)

    def axis_entry(a: str, key: str) -> IniEntry | None:
        sec = info[a].section
        return ini.get(sec, key) if sec else None

    def joint_entries(a: str, key: str) -> list[IniEntry]:
        return [e for s in info[a].joints if (e := ini.get(s, key)) is not None]

    def homing_entry(a: str, key: str) -> IniEntry | None:
        if old_style:
            return axis_entry(a, key)
        found = joint_entries(a, key)
        return found[0] if found else None

    def converted(e: IniEntry, a: str, *, per_min: bool = False) -> Sourced | None:
        q = rd.real(e)
        if q is None:
            return None
        factor, unit = unit_of(a)
        q = q * factor * (60 if per_min else 1)
        return Sourced(q, e.describe() + _conversion(unit, per_min), e.span)

    # soft limits: the axis limits, narrowed by tighter joint limits (identity kinematics)
    zone_min: dict[str, Sourced] = {}
    zone_max: dict[str, Sourced] = {}
    for a in axes:
        limit_sides: tuple[tuple[str, dict[str, Sourced], Callable[[Fraction, Fraction], bool]], ...] = (
            ("MIN_LIMIT", zone_min, lambda new, old: new > old), ("MAX_LIMIT", zone_max, lambda new, old: new < old))
        for key, side, tighter in limit_sides:
            limit_entries = [e for e in [axis_entry(a, key)] if e is not None] + joint_entries(a, key)
            best: Sourced | None = None
            for le in limit_entries:
                v = converted(le, a)
                if v is None:
                    continue
                if abs(v.value) > MAX_ABS_LENGTH:
                    c.note("IM203", f"{le.describe()}: beyond the machine file's range (magnitude "
                           f"{format_decimal(MAX_ABS_LENGTH)}), taken as no limit (LinuxCNC's own default for "
                           "no limit is 1e99)", le.span)
                    continue
                if best is None or tighter(v.value, best.value):
                    if best is not None and le.section.startswith("JOINT_"):
                        c.note("IM203", f"{le.describe()} is tighter than the axis limit "
                               f"{format_decimal(best.value)}; taken, since motion stops at the joint limit "
                               "(LinuxCNC's configuration check calls this an error)", le.span)
                    best = v
            if best is not None:
                side[a] = best
        if a in zone_min and a in zone_max and zone_min[a].value > zone_max[a].value:
            c.error("IM108", f"axis {a}: {zone_min[a].how} is greater than {zone_max[a].how}; the axis could not "
                    "move at all", zone_min[a].span)
    zones: tuple[ZoneDraft, ...] = ()
    if zone_min or zone_max:
        zones = (ZoneDraft("soft limits", False, frozen(zone_min), frozen(zone_max),
                           ("LinuxCNC's soft limits: [AXIS_<letter>] MIN_LIMIT / MAX_LIMIT"
                            + (" and the joint limits" if any(info[a].joints for a in axes) else "")
                            + "; an axis without them is unlimited",)),)
    else:
        c.note("IM201", "no MIN_LIMIT or MAX_LIMIT on any axis: the machine file gets no zone, so every "
               "position is allowed", file=path)

    # rapid rates and maximum accelerations (the controller's blend arcs): the smallest of axis, joints, trajectory
    limits = (lambda a: ini.sections.get(info[a].section or "", None), axis_entry, joint_entries, converted, unit_of)
    rapid = _axis_maxima(VELOCITY, ini, c, axes, limits, path)
    accel = _axis_maxima(ACCELERATION, ini, c, axes, limits, path)

    # home positions (where homing leaves the axis)
    home: dict[str, Sourced] = {}
    traj_home = ini.get("TRAJ", "HOME")
    for a in axes:
        if identity or old_style:
            found = [e for e in ([axis_entry(a, "HOME")] if old_style else joint_entries(a, "HOME")) if e is not None]
            if found:
                v = converted(found[0], a)
                if v is not None:
                    home[a] = v
                for other in found[1:]:
                    other_home = converted(other, a)
                    if a in home and other_home is not None and other_home.value != home[a].value:
                        c.note("IM201", f"{other.describe()}: differs from {found[0].describe()}; the machine "
                               f"file has one home position per axis, {a}{format_decimal(home[a].value)} is taken",
                               other.span)
            else:
                home[a] = Sourced(Fraction(0), f"no HOME for axis {a}: LinuxCNC's default 0")
        else:
            home[a] = Sourced(Fraction(0), "nontrivial kinematics: [TRAJ] HOME or 0")
    if not identity and not old_style and traj_home is not None:
        words = traj_home.value.split()
        for a in axes:
            i = LETTERS.index(a)
            if i < len(words):
                factor, unit = unit_of(a)
                q = c.real(words[i], traj_home.describe(), traj_home.span)
                if q is not None:
                    home[a] = Sourced(q * factor, f"{traj_home.describe()}, item {i + 1}"
                                      + _conversion(unit, False), traj_home.span)
    for v in home.values():
        in_range(c, v.value, v.how, v.span)

    # pulse: steps (or encoder counts) per machine unit, a HAL setting by convention
    pulse: dict[str, Sourced] = {}
    for a in axes:
        sections = [info[a].section] if old_style else info[a].joints
        e = next((ini.get(s, k) for s in sections if s for k in _SCALE_KEYS if ini.get(s, k) is not None), None)
        if e is None:
            continue
        q = rd.real(e)
        if q is None:
            continue
        if q == 0:
            c.note("IM201", f"{e.describe()}: a scale of 0 gives no pulse length", e.span)
            continue
        factor, unit = unit_of(a)
        exact = factor / abs(q)
        p, was_rounded = rounded_decimal(exact)
        if p <= 0 or p > 1:
            c.note("IM201", f"{e.describe()}: one step would be {format_decimal(exact, 12)} mm, outside the machine "
                   "file's pulse range (0, 1]", e.span)
            continue
        how = f"1 / {e.describe()}" + (" per inch, x 25.4" if unit == "in" else "")
        if was_rounded:
            how += f"; exactly {exact.numerator}/{exact.denominator}, rounded"
            c.note("IM202", f"{e.describe()}: the pulse length {exact.numerator}/{exact.denominator} mm is not a "
                   f"finite decimal; written rounded to {format_decimal(p)} (the prover does not use the pulse; "
                   "the reference controller's pulse grid differs by less than 1e-9 mm per pulse)", e.span)
        pulse[a] = Sourced(p, how, e.span)
    if pulse and len(pulse) < len(axes):
        for a in axes:
            if a not in pulse:
                pulse[a] = Sourced(Fraction(1, 1000), "no SCALE, STEP_SCALE or INPUT_SCALE: the machine file's "
                                   "default 0.001")
                c.note("IM203", f"axis {a}: no SCALE, STEP_SCALE or INPUT_SCALE; the pulse is the machine file's "
                       "default 0.001", file=path)

    # the limit monitor runs every servo period
    period: Sourced | None = None
    sp = ini.get("EMCMOT", "SERVO_PERIOD")
    if sp is not None:
        q = rd.real(sp)
        if q is not None:
            ms = q / 1_000_000
            if 0 < ms <= 1000:
                period = Sourced(ms, f"{sp.describe()} ns, / 1000000", sp.span)
            else:
                c.note("IM201", f"{sp.describe()}: a servo period of {format_decimal(ms)} ms is outside the "
                       "machine file's monitor period range (0, 1000] ms", sp.span)

    # parameter file: work offsets, G28/G30 positions, G92 offsets, the active offset
    params, var_path = _parameters(ini, c, parameter_file)

    def param(n: int, a: str, label: str) -> Sourced:
        value, span = params.get(n, (Fraction(0), None))
        factor, unit = unit_of(a)
        how = f"#{n} = {format_decimal(value)} ({label})" + _conversion(unit, False)
        if span is None:
            how = f"#{n} ({label}) not stored: LinuxCNC's 0"
        return Sourced(value * factor, how, span)

    offsets: dict[str, dict[str, Sourced]] = {}
    for k, name in enumerate(WORK_OFFSETS):
        values = {a: param(5221 + 20 * k + LETTERS.index(a), a, f"{name} {a}") for a in axes}
        if any(v.value for v in values.values()):
            offsets[name] = {a: v for a, v in values.items() if v.value}
    # G28 moves to the stored G28 position (#5161..), machine zero when none is stored; homing ends at HOME
    reference = {a: param(5161 + LETTERS.index(a), a, f"G28 position {a}") for a in axes}
    start: dict[str, Sourced] = {}
    if any(reference[a].value != home[a].value for a in axes):
        start = home
    g30 = {a: param(5181 + LETTERS.index(a), a, f"G30 position {a}") for a in axes}
    if any(g30[a].value != reference[a].value for a in axes):
        first = next(v for a, v in g30.items() if v.value != reference[a].value)
        pos = " ".join(f"{a}{format_decimal(v.value)}" for a, v in g30.items())
        c.note("IM201", f"the G30 position {pos} differs from the G28 position; the machine file has one "
               "reference position, used by both G28 and G30, so programs with G30 are verified against "
               "the G28 position", first.span, file=var_path)
    persist = not rd.boolean(ini.get("RS274NGC", "DISABLE_G92_PERSISTENCE"))
    g92 = {a: param(5211 + LETTERS.index(a), a, f"G92 {a}") for a in axes}
    enabled = params.get(5210, (Fraction(0), None))[0] != 0
    if persist and enabled and any(v.value for v in g92.values()):
        first = next(v for v in g92.values() if v.value)
        pos = " ".join(f"{a}{format_decimal(v.value)}" for a, v in g92.items() if v.value)
        c.note("IM201", f"a G92 offset {pos} is stored and LinuxCNC restores it at start-up; the machine "
               "file has no G92 offset, so programs that rely on it are verified without it; clear it "
               "(G92.1) or set DISABLE_G92_PERSISTENCE", first.span, file=var_path)
    for v in reference.values():
        in_range(c, v.value, v.how, v.span)
    for values in offsets.values():
        for v in values.values():
            in_range(c, v.value, v.how, v.span)

    # modal state at start-up: machine units, the stored work offset, RS274NGC_STARTUP_CODE
    modal = _modal(ini, c, lin[1], params)

    # tool table
    lengths, diameters = _tools(ini, c, tool_table, axes, lin)

    # lathe and the settings the machine file has no place for
    lathe = ini.get("DISPLAY", "LATHE")
    if lathe is not None and rd.boolean(lathe):
        c.note("IM201", f"{lathe.describe()}: a lathe. LinuxCNC reads X words as radius unless a program (or "
               "RS274NGC_STARTUP_CODE) selects G7 diameter mode; diameter axes have no place in the machine file "
               "yet, so X is taken as a radius axis", lathe.span)
    for a in axes:
        wr = axis_entry(a, "WRAPPED_ROTARY")
        if wr is not None and rd.boolean(wr):
            c.note("IM201", f"{wr.describe()}: a wrapped rotary axis (0-360 degrees, moves the short way); the "
                   "machine file's rotary axes do not wrap", wr.span)

    homing = _homing(axes, old_style, identity, homing_entry, converted, c)

    # tool change: the moves M6 makes (interp_convert.cc convert_tool_change, emccanon.cc CHANGE_TOOL)
    extra: list[tuple[str, str, str]] = [
        ("dialect", '"linuxcnc"', "LinuxCNC's RS-274/NGC"),
        ("cutter_compensation", '"linuxcnc"', "G41/G42 as LinuxCNC's interpreter does them")]
    extra.extend(startup_path_mode(ini.get("RS274NGC", "RS274NGC_STARTUP_CODE"), lin[1]))
    if lin[1] == "in":
        extra.append(("control_units", '"inch"', f"{lin_e.describe() if lin_e is not None else 'LINEAR_UNITS'}: "
                      "LinuxCNC keeps its numbered parameters (#5161-#5390, #5401-#5409) in inches"))
    for key in ("TOOL_CHANGE_QUILL_UP", "TOOL_CHANGE_AT_G30"):
        e = ini.get("EMCIO", key)
        if e is not None and rd.boolean(e):
            extra.append((key.lower(), "true", f"{e.describe()} ({e.where()}): M6 moves the machine"))
    if any(k == "tool_change_at_g30" for k, _, _ in extra):
        differs = [a for a in axes if g30[a].value != reference[a].value]
        if differs:
            at = ini.get("EMCIO", "TOOL_CHANGE_AT_G30")
            c.error("IM111", f"{at.describe() if at else 'TOOL_CHANGE_AT_G30'}: M6 moves to the G30 position "
                    f"({' '.join(f'{a}{format_decimal(g30[a].value)}' for a in axes)} mm), but the machine file "
                    "has one reference position for G28 and G30 and the G28 position differs on "
                    f"{', '.join(differs)}; store the same position in #5161-#5169 and #5181-#5189 (G28.1 and "
                    "G30.1 at one point) so every tool change is proved where it goes",
                    g30[differs[0]].span or (at.span if at else None), file=var_path)
    tc_position: dict[str, Sourced] = {}
    tcp = ini.get("EMCIO", "TOOL_CHANGE_POSITION")
    if tcp is not None:
        words = tcp.value.split()
        # taskclass.cc readToolChange: sscanf of 9, else 6, else 3 numbers (X Y Z [A B C [U V W]])
        count = 9 if len(words) >= 9 else 6 if len(words) >= 6 else 3 if len(words) >= 3 else 0
        if count == 0:
            c.error("IM105", f"{tcp.describe()}: {tcp.value!r} is not a position; LinuxCNC reads 3 (X Y Z), "
                    "6 (X Y Z A B C) or 9 (X Y Z A B C U V W) numbers, and ignores the setting otherwise",
                    tcp.span)
        for k in range(count):
            letter = LETTERS[k]
            q = c.real(words[k], f"{tcp.describe()} ({letter})", tcp.span)
            if q is None or letter not in axes:
                continue
            factor, unit = unit_of(letter)
            tc_position[letter] = Sourced(q * factor, f"{tcp.describe()}: {letter} {words[k]}"
                                          + _conversion(unit, False), tcp.span)
        if tc_position:
            for v in tc_position.values():
                in_range(c, v.value, v.how, v.span)

    name_e = ini.get("EMC", "MACHINE")
    name = name_e.value if name_e is not None and name_e.value else Path(path).stem
    c.raise_if_failed()
    return ImportedMachine(
        kind="linuxcnc",
        source=path,
        name=name,
        name_how=f"{name_e.describe()} ({name_e.where()})" if name_e is not None else "the file name",
        axes=axes,
        axes_how=axes_how,
        rapid=frozen(rapid),
        reference=frozen(reference),
        start=frozen(start),
        pulse=frozen(pulse),
        rapid_mode=("linear", "LinuxCNC moves G0 on a straight line"),
        monitor_period_ms=period,
        modal=modal,
        extra=tuple(extra),
        axis_tables=((("machine.acceleration", frozen(accel)),) if accel else ())
        + ((("machine.tool_change_position", frozen(tc_position)),) if tc_position else ()),
        offsets=frozen({k: frozen(v) for k, v in offsets.items()}),
        tool_lengths=frozen(lengths),
        tool_diameters=frozen(diameters),
        zones=zones,
        homing=homing,
        notes=tuple(c.notes),
        subroutine_path=_subroutine_path(ini, path),
    )


@dataclass(frozen=True)
class _Maximum:
    """An axis maximum the import reads: the INI key, the [TRAJ] caps, and how it is written."""

    key: str
    traj: tuple[str, str]
    per_min: bool
    what: str  # "velocity" / "acceleration"
    default: str  # the default's description, {a} the axis letter, {unit} its machine unit
    note: str


VELOCITY = _Maximum("MAX_VELOCITY", ("MAX_LINEAR_VELOCITY", "MAX_VELOCITY"), True, "velocity",
                    "no [AXIS_{a}] MAX_VELOCITY: LinuxCNC's default of 1 unit per second, x 60",
                    "axis {a}: no MAX_VELOCITY; LinuxCNC's default of 1 machine unit per second is taken")
ACCELERATION = _Maximum("MAX_ACCELERATION", ("MAX_LINEAR_ACCELERATION", "MAX_ACCELERATION"), False, "acceleration",
                        "no [AXIS_{a}] MAX_ACCELERATION: LinuxCNC's default of 1 {unit}/s^2",
                        "axis {a}: no MAX_ACCELERATION; LinuxCNC's default of 1 machine unit per second squared "
                        "is taken")


def _axis_maxima(spec: _Maximum, ini: IniFile, c: Collector, axes: tuple[str, ...], limits: tuple[Any, ...],
                 path: str) -> dict[str, Sourced]:
    """Per axis the smallest of ``[AXIS_<L>] <key>`` (LinuxCNC's default: 1 unit per second, or per second
    squared: ``DEFAULT_AXIS_MAX_ACCELERATION``), its joints' ``<key>`` and, for linear axes, the ``[TRAJ]`` cap
    (2.9 name, then 2.7's); velocities x 60 (per minute); 0 or less is ``IM108``.  ``limits``: the reader's
    (section of an axis, axis entry, joint entries, converted, unit of an axis)."""
    section_of, axis_entry, joint_entries, converted, unit_of = limits
    traj = ini.get("TRAJ", spec.traj[0]) or ini.get("TRAJ", spec.traj[1])
    out: dict[str, Sourced] = {}
    for a in axes:
        candidates: list[Sourced] = []
        e = axis_entry(a, spec.key)
        if e is not None:
            candidates.extend(v for v in [converted(e, a, per_min=spec.per_min)] if v is not None)
        else:
            factor, unit = unit_of(a)
            candidates.append(Sourced(factor * (60 if spec.per_min else 1), spec.default.format(a=a, unit=unit)))
            c.note("IM203", spec.note.format(a=a), section_of(a), file=path)
        candidates.extend(v for je in joint_entries(a, spec.key)
                          if (v := converted(je, a, per_min=spec.per_min)) is not None)
        if traj is not None and a not in ROTARY_AXES:
            candidates.extend(v for v in [converted(traj, a, per_min=spec.per_min)] if v is not None)
        good = [v for v in candidates if v.value > 0]
        for v in candidates:
            if v.value <= 0:
                c.error("IM108", f"{v.how}: a maximum {spec.what} must be greater than 0", v.span)
        if good:
            lowest = min(good, key=lambda v: v.value)
            if in_range(c, lowest.value, lowest.how, lowest.span):
                how = lowest.how if spec.per_min else lowest.how.replace(" in, x", " in/s^2, x").replace(
                    " grad, x", " grad/s^2, x")
                out[a] = Sourced(lowest.value, how, lowest.span)
    return out


def _subroutine_path(ini: IniFile, path: str) -> tuple[tuple[str, ...], str]:
    """Where ``o<name> call`` finds ``name.ngc`` (interp_o_word.cc find_ngc_file): ``[DISPLAY] PROGRAM_PREFIX``
    first, then the ':'-separated ``[RS274NGC] SUBROUTINE_PATH`` folders (relative ones against the INI's folder,
    where LinuxCNC runs; rs274ngc_pre.cc init), as absolute paths, and where they were written."""
    base = os.path.dirname(os.path.abspath(path))
    folders: list[str] = []
    how: list[str] = []
    for section, key in (("DISPLAY", "PROGRAM_PREFIX"), ("RS274NGC", "SUBROUTINE_PATH")):
        e = ini.get(section, key)
        if e is None or not e.value.strip():
            continue
        parts = [e.value.strip()] if key == "PROGRAM_PREFIX" else e.value.split(":")
        found = [os.path.normpath(os.path.join(base, os.path.expanduser(f.strip()))) for f in parts if f.strip()]
        folders += [f for f in found if f not in folders]
        how.append(f"{e.describe()} ({e.where()})")
    return tuple(folders), "; then ".join(how) + ": o<name> call reads name.ngc from these folders, in order"



#: Parameter number -> (value, where it stands in the parameter file).
Params = dict[int, tuple[Fraction, SourceSpan]]


def _parameters(ini: IniFile, c: Collector, override: str | None) -> tuple[Params, str]:
    """The parameter file's values by number; empty (with a note) when there is no file."""
    base = Path(ini.path).parent
    if override is not None:
        target = Path(override)
        origin = "--parameter-file"
    else:
        e = ini.get("RS274NGC", "PARAMETER_FILE")
        if e is None:
            target = base / "rs274ngc.var"
            origin = "LinuxCNC's default rs274ngc.var (no [RS274NGC] PARAMETER_FILE)"
        else:
            target = base / e.value
            origin = e.describe()
        if not target.exists():
            c.note("IM203", f"{origin}: {target} does not exist; LinuxCNC then starts with every parameter 0: "
                   "no work offsets, and G28 goes to machine zero", e.span if e is not None else None,
                   file=ini.path)
            return {}, str(target)
    text = read_source(target, "parameter file", "IM109")
    vpath = str(target)
    out: Params = {}
    last = 0
    for i, line in enumerate(text.split("\n"), 1):
        stripped = line.strip()
        if not stripped:
            continue
        m = re.fullmatch(r"(\d+)\s+(\S+)", stripped)
        span = line_span(vpath, i, line, len(line) - len(line.lstrip()))
        if not m:
            c.error("IM102", f"malformed parameter line {stripped!r}: expected a parameter number and a value, "
                    "such as 5221 10.5", span)
            continue
        n = int(m.group(1))
        if not 0 < n < 5602:
            c.error("IM104", f"parameter #{n} is out of range (1 to 5601)", span)
            continue
        if n <= last:
            c.error("IM108", f"parameter #{n} comes after #{last}; LinuxCNC needs the parameter file in increasing "
                    "order", span)
            continue
        last = n
        q = c.real(m.group(2), f"parameter #{n}", line_span(vpath, i, line, m.start(2) + len(line) - len(line.lstrip()),
                                                              m.end(2) + len(line) - len(line.lstrip())))
        if q is not None:
            out[n] = (q, span)
    c.raise_if_failed()
    return out, vpath


def _modal(ini: IniFile, c: Collector, unit: str, params: Params) -> tuple[tuple[str, str], ...]:
    chosen: dict[str, tuple[str, str]] = {}
    if unit == "in":
        chosen["units"] = ("G20", "[TRAJ] LINEAR_UNITS = inch: LinuxCNC starts in the machine's units")
    if 5220 in params:
        value, span = params[5220]
        index = int(value)
        if value == index and 1 <= index <= 9 and index != 1:
            chosen["offset"] = (WORK_OFFSETS[index - 1], f"#5220 = {index}: the work offset in use when LinuxCNC "
                                f"stopped ({span.file}:{span.line})")
    e = ini.get("RS274NGC", "RS274NGC_STARTUP_CODE")
    if e is not None:
        startup_modal(e.value, e.describe(), f"{e.describe()} ({e.where()})", e.span, chosen, c, path_codes=True)
    return modal_changes(chosen)


def startup_path_mode(entry: IniEntry | None, units: str) -> list[tuple[str, str, str]]:
    """``path_mode`` / ``path_tolerance`` from RS274NGC_STARTUP_CODE's G61, G61.1 or G64 P (the last one wins,
    as the interpreter executes the block; P in the machine's units at start-up, inch for LINEAR_UNITS = inch).

    >>> ini = parse_ini("x.ini", "[RS274NGC]\\nRS274NGC_STARTUP_CODE = G17 G21 G64 P0.01\\n", Collector())
    >>> [k + " = " + v for k, v, _ in startup_path_mode(ini.get("RS274NGC", "RS274NGC_STARTUP_CODE"), "mm")]
    ['path_tolerance = "0.01"']
    """
    if entry is None:
        return []
    found = list(re.finditer(r"G\s*0*(61\.1|61|64)(?![\d.])(?:\s*P\s*([+]?\d*\.?\d+))?", entry.value, re.I))
    if not found:
        return []
    code, p = found[-1].group(1), found[-1].group(2)
    how = f"{entry.describe()} ({entry.where()}): the interpreter starts in G{code}"
    if code != "64":
        return [("path_mode", f'"G{code}"', how)]
    if p is None or Fraction(p) == 0:
        return []  # G64 without tolerance is the default
    # P is in the units in force when G64 runs: a G20/G21 earlier in the block (executed first in a block: the
    # units group comes before path control), else the machine's
    before = re.findall(r"G\s*0*(20|21)(?![\d.])", entry.value, re.I)
    inch = before[-1] == "20" if before else units == "in"
    tol = Fraction(p) * (Fraction(254, 10) if inch else 1)
    return [("path_tolerance", f'"{format_decimal(tol)}"', f"{how} P{p} (its Q defaults to P)")]


def startup_modal(block: str, label: str, how: str, span: SourceSpan | None, chosen: dict[str, tuple[str, str]],
                  c: Collector, path_codes: bool = False) -> None:
    """Take the modal G codes of a start-up block into ``chosen`` (group -> (code, how)); note the rest.

    >>> c = Collector(); chosen = {}
    >>> startup_modal("G18 G020 G64 P0.01", "start-up", "start-up", None, chosen, c)
    >>> chosen["plane"][0], chosen["units"][0], c.notes[0].message.split(";")[0]
    ('G18', 'G20', 'start-up: G64 P0.01 not taken')
    """
    left: list[str] = []
    path_words = False  # path_codes: G61, G61.1, G64 and G64's P and Q are taken by startup_path_mode
    for letter, number in re.findall(r"([A-Za-z])\s*([-+]?\d*\.?\d*)", block):
        word = f"{letter.upper()}{number}"
        if path_codes and letter.upper() == "G" and re.fullmatch(r"0*(61(\.1)?|64)", number):
            path_words = number.lstrip("0") == "64"
            continue
        if path_words and letter.upper() in "PQ":
            continue
        path_words = False
        if letter.upper() == "G" and re.fullmatch(r"\d+(?:\.\d+)?", number):
            code = "G" + format_decimal(Fraction(number))
            group = next((g for g, codes in MODAL_GROUPS.items() if code in codes), None)
            if group is not None:
                chosen[group] = (code, how)
                continue
        left.append(word)
    if left:
        c.note("IM201", f"{label}: {' '.join(left)} not taken; the machine file's modal list holds distance, units, "
               "plane, work offset, feed and retract modes (and G40, G49, G80)", span)


def modal_changes(chosen: dict[str, tuple[str, str]]) -> tuple[tuple[str, str], ...]:
    """The chosen codes that differ from the machine file's default modal state, with how each was found."""
    defaults = dict(zip(MODAL_GROUPS, DEFAULT_MODAL)) | {"retract": DEFAULT_RETRACT["linuxcnc"]}
    return tuple((code, how) for group, (code, how) in chosen.items() if defaults[group] != code)


def _stored_link(table: Path, line: str) -> str:
    """A hint when a tool table line is a path to an existing file: a symbolic link stored as a plain file.

    Git writes a symlink as a file holding its target where links are not made (an archive, a checkout
    with ``core.symlinks=false``).  LinuxCNC reads such a file as a table whose one line it skips; the
    import does the same and says how to get the real table read.
    """
    text = line.strip()
    if not text or any(ch.isspace() for ch in text) or len(text) > 4096:
        return ""
    try:
        linked = (table.parent / text)
        exists = linked.is_file() and linked.resolve() != table.resolve()
    except (OSError, ValueError):
        return ""
    if exists:
        return (f"; the file holds only the path {text!r}, which exists: it looks like a symbolic link stored as "
                f"a file (make it a link, or give --tool-table {linked})")
    if "/" in text or text.lower().endswith(".tbl"):
        return (f"; the file holds only the path {text!r}: it looks like a symbolic link stored as a file, whose "
                f"target {linked} is not there (put the real table there, or give --tool-table)")
    return ""


def _tools(ini: IniFile, c: Collector, override: str | None, axes: tuple[str, ...],
           lin: tuple[Fraction, str]) -> tuple[dict[int, Sourced], dict[int, Sourced]]:
    lengths: dict[int, Sourced] = {}
    diameters: dict[int, Sourced] = {}
    base = Path(ini.path).parent
    db = ini.get("EMCIO", "DB_PROGRAM")
    if override is not None:
        target = Path(override)
    else:
        e = ini.get("EMCIO", "TOOL_TABLE")
        if db is not None:
            c.note("IM201", f"{db.describe()}: tool data from a database program are not read; no tools taken",
                   db.span)
            return lengths, diameters
        if e is None:
            return lengths, diameters
        target = base / e.value
        if not target.exists():
            c.note("IM203", f"{e.describe()}: {target} does not exist; no tool lengths or diameters taken", e.span)
            return lengths, diameters
    return _read_tool_table(target, c, axes, lin)


def read_tool_table(path: str | Path, units: str, axes: tuple[str, ...] = ("X", "Y", "Z")
                    ) -> tuple[dict[int, Fraction], dict[int, Fraction], tuple[Diagnostic, ...]]:
    """A LinuxCNC tool table (``.tbl``) on its own: tool lengths (Z) and diameters in mm, and the notes.

    ``units`` is the table's length unit, LinuxCNC's ``[TRAJ] LINEAR_UNITS`` (``"mm"`` or ``"inch"``):
    a table does not say it.  Raises :class:`~nczones.errors.MachineImportError` (``IM1xx``) on a bad
    table, as ``import-machine`` would.  ``nczones verify --tool-table`` reads tools with it.
    """
    lin = _LINEAR_UNITS.get(units.strip().lower())
    if lin is None:
        raise InvalidArgument(f"tool table units {units!r}: use mm or inch")
    c = Collector()
    lengths, diameters = _read_tool_table(Path(path), c, axes, lin)
    c.raise_if_failed()
    return ({k: v.value for k, v in lengths.items()}, {k: v.value for k, v in diameters.items()},
            tuple(c.notes))


def _read_tool_table(target: Path, c: Collector, axes: tuple[str, ...], lin: tuple[Fraction, str]
                     ) -> tuple[dict[int, Sourced], dict[int, Sourced]]:
    lengths: dict[int, Sourced] = {}
    diameters: dict[int, Sourced] = {}
    text = read_source(target, "tool table", "IM109")
    tpath = str(target)
    factor, unit = lin
    seen: dict[int, SourceSpan] = {}
    for i, line in enumerate(text.split("\n"), 1):
        body = line.rstrip("\r")
        if body.lstrip().startswith(";") or not body.split(";")[0].strip():
            continue
        data = body.split(";")[0]
        fields: dict[str, tuple[str, SourceSpan]] = {}
        bad = None
        for m in re.finditer(r"\S+", data):
            token = m.group(0)
            letter, number = token[0].upper(), token[1:]
            pattern = r"[+-]?\d+" if letter in "TPQ" else r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
            if letter not in "TPXYZABCUVWDIJQ" or not re.fullmatch(pattern, number):
                bad = (token, line_span(tpath, i, body, m.start(), m.end()), letter)
                break
            fields[letter] = (number, line_span(tpath, i, body, m.start(), m.end()))
        if bad is not None:
            token, span, letter = bad
            # LinuxCNC (tooldata_common.cc tooldata_read_entry) reads each word with sscanf: a word whose
            # letter it knows and whose text starts with a number is read up to where the number ends
            # ("Z1,5" is Z1); the import refuses such a word rather than guess (IM102).  Any other word
            # makes LinuxCNC skip the whole line ("Unrecognized line skipped"): a note, the line is skipped.
            c_prefix = (r"\s*[+-]?\d" if letter in "TPQ"
                        else r"\s*[+-]?(?:\d|\.\d)")
            if letter in "TPXYZABCUVWDIJQ" and re.match(c_prefix, token[1:]):
                c.error("IM102", f"malformed tool table entry {token!r}: LinuxCNC reads only the number at its "
                        "start (C's sscanf stops at the first character that is not part of it); write the "
                        "number plainly, such as Z1.5", span)
                continue
            hint = (" (this looks like the tool table format of LinuxCNC before 2.4, which it no longer reads: "
                    "write T<n> P<pocket> Z<length> D<diameter>)" if token[0].isdigit() or token.isalpha() else "")
            what = f"{letter} takes a whole number" if letter in "TPQ" else (
                "expected a letter T P X Y Z A B C U V W D I J or Q followed by a number")
            link = _stored_link(target, data)
            if link:
                hint += link
            # LinuxCNC reads the rest of the table (a warning on its console): a note, and no tool from the line
            c.note("IM204", f"malformed tool table entry {token!r}: {what}; LinuxCNC skips this line, and so "
                   f"does the import (no tool taken from it){hint}", span)
            continue
        if "T" not in fields:
            c.note("IM204", "a tool table line without a T word (the tool number): LinuxCNC skips it, and so does "
                   "the import", line_span(tpath, i, body))
            continue
        tool = int(fields["T"][0])
        tspan = fields["T"][1]
        if tool in seen:
            c.error("IM108", f"tool T{tool} is listed twice (first at line {seen[tool].line}); tool numbers must be "
                    "unique", tspan)
            continue
        seen[tool] = tspan
        if not 0 <= tool <= 9999:
            c.note("IM201", f"T{tool}: the machine file numbers tools 0 to 9999; this tool is not taken", tspan)
            continue
        unit_how = _conversion(unit, False)
        if "Z" in fields and "Z" in axes:
            number, span = fields["Z"]
            q = c.real(number, f"T{tool} Z", span)
            if q is not None and in_range(c, q * factor, f"T{tool} Z", span):
                lengths[tool] = Sourced(q * factor, f"T{tool} Z{number}{unit_how}", span)
        elif "Z" in fields:
            c.note("IM201", f"T{tool}: a Z offset, but the machine has no Z axis to apply it to", fields["Z"][1])
        number, span = fields.get("D", ("0", tspan))
        q = c.real(number, f"T{tool} D", span)
        if q is not None and in_range(c, q * factor, f"T{tool} D", span):
            how = f"T{tool} D{number}{unit_how}" if "D" in fields else f"T{tool} has no D word: LinuxCNC's diameter 0"
            diameters[tool] = Sourced(q * factor, how, span)
        others = [f"{k}{fields[k][0]}" for k in "XYABCUVWIJQ" if k in fields and Fraction(fields[k][0]) != 0]
        if others:
            c.note("IM201", f"T{tool}: {' '.join(others)} not taken; the machine file holds a tool length on the tool "
                   "axis and a diameter (lathe tool offsets and orientations have no place yet)", tspan)
    c.raise_if_failed()
    return lengths, diameters


def _homing(axes: tuple[str, ...], old_style: bool, identity: bool,
            homing_entry: Callable[[str, str], IniEntry | None], converted: Callable[..., Sourced | None],
            c: Collector) -> tuple[HomingDraft, ...]:
    drafts = []
    if not (identity or old_style):
        return ()
    for a in axes:
        search = homing_entry(a, "HOME_SEARCH_VEL")
        if search is None:
            continue
        sv = converted(search, a, per_min=True)
        if sv is None or sv.value == 0:
            continue
        fields: list[tuple[str, Sourced | str, str]] = [
            ("direction", '"positive"' if sv.value > 0 else '"negative"', f"the sign of {search.describe()} "
             f"({search.where()})"),
            ("search_speed", Sourced(abs(sv.value), sv.how, sv.span), ""),
        ]
        latch = homing_entry(a, "HOME_LATCH_VEL")
        if latch is not None:
            lv = converted(latch, a, per_min=True)
            if lv is not None and lv.value:
                fields.append(("latch_speed", Sourced(abs(lv.value), lv.how, lv.span), ""))
        offset = homing_entry(a, "HOME_OFFSET")
        index = homing_entry(a, "HOME_USE_INDEX")
        uses_index = index is not None and index.value.strip().lower() in _TRUE
        missing = ["dog_length", "grid_pitch", "detector_phase"]
        if offset is not None:
            ov = converted(offset, a)
            if ov is not None:
                if uses_index:
                    fields.append(("grid_shift", Sourced(-ov.value, f"minus {ov.how}: the index pulse is at "
                                                         "HOME_OFFSET and becomes the origin", ov.span), ""))
                    missing.insert(0, "dog_position")
                else:
                    fields.append(("dog_position", Sourced(ov.value, f"{ov.how}: the home switch position", ov.span),
                                   ""))
        drafts.append(HomingDraft(a, tuple(fields), tuple(missing)))
        c.note("IM201", f"axis {a} homing ({search.describe()}): not taken; the machine file's [homing.{a}] also "
               f"needs {', '.join(missing)}, which the INI does not give (LinuxCNC homes to the switch"
               f"{' and the index pulse' if uses_index else ''}); written commented out", search.span)
    return tuple(drafts)
