"""Write an :class:`~.model.ImportedMachine` as a commented machine file (TOML).

Every value carries a comment saying where it came from (``file:line`` and the
setting as written, with the conversion applied); homing settings the machine
file cannot take yet are written commented out; the notes (what was not
taken, rounded or assumed) close the file.  The text is checked by
:func:`nczones.machine.parse_machine` before anyone sees it.
"""

from __future__ import annotations

import os
import re
from fractions import Fraction

import tomli_w

from ..exact import format_decimal
from .model import ImportedMachine, Sourced, ZoneDraft

__all__ = ["render_toml", "KIND_LABELS"]

KIND_LABELS = {
    "linuxcnc": "LinuxCNC INI configuration",
    "grbl": "Grbl settings ($$ dump)",
    "fanuc": "Fanuc parameter listing",
}

_WIDTH = 30


def _s(text: str) -> str:
    """``text`` as a TOML basic string, quoted by tomli-w (TOML's escapes, not JSON's: DEL and other control
    characters are escaped as TOML requires)."""
    return tomli_w.dumps({"v": text}).partition(" = ")[2].rstrip("\n")


#: Characters a TOML comment may not hold (every control character but tab).
_CONTROL = re.compile(r"[\x00-\x08\x0a-\x1f\x7f]")


def _q(value: Fraction) -> str:
    return _s(format_decimal(value))


def _clean(text: str) -> str:
    """Comment text on one line, control characters shown as ``\\xNN`` (TOML comments may not hold them)."""
    return _CONTROL.sub(lambda m: f"\\x{ord(m.group()):02x}", " ".join(text.split()))


def _line(assignment: str, comment: str = "") -> str:
    if not comment:
        return assignment
    return f"{assignment:<{_WIDTH}} # {_clean(comment)}"


def _how(v: Sourced) -> str:
    where = v.where()
    return f"{v.how} ({where})" if where else v.how


def _table(out: list[str], header: str, axes: tuple[str, ...], values: dict[str, Sourced]) -> None:
    out.append("")
    out.append(f"[{header}]")
    for a in axes:
        if a in values:
            out.append(_line(f"{a} = {_q(values[a].value)}", _how(values[a])))


def _zone(out: list[str], axes: tuple[str, ...], z: ZoneDraft) -> None:
    out.append("")
    out.append("[[zones]]")
    for c in z.comment:
        out.append(f"# {_clean(c)}")
    for side, values in (("min", z.min), ("max", z.max)):
        for a in axes:
            if a in values:
                out.append(f"#   {side}.{a}: {_clean(_how(values[a]))}")
    out.append(f"name = {_s(z.name)}")
    out.append('kind = "box"')
    if z.forbid:
        out.append("forbid = true")
    for side, values in (("min", z.min), ("max", z.max)):
        items = [f"{a} = {_q(values[a].value)}" for a in axes if a in values]
        if items:
            out.append(f"{side} = {{ {', '.join(items)} }}")


def _tool_solids(out: list[str], im: ImportedMachine) -> None:
    """The tools whose table gives a diameter, as ``[[tools]]`` solids written commented out: a tool table
    gives the cutter's diameter but neither its length nor the holder, and a made-up length would make a
    proof about an invented tool (specs/machine-import.md, "Tool solids")."""
    if im.tool_solids:  # from a Fanuc offset listing (imports/fanuc_tools.py): rows already made
        out.append("")
        for assignment, comment in im.tool_solids:
            out.append("# " + (_line(assignment, comment) if assignment else _clean(comment)))
    known = [(n, d) for n, d in sorted(im.tool_diameters.items()) if d.value > 0]
    if not known or not all(a in im.axes for a in "XYZ"):
        return  # a lathe's turret tools are rectangles the tool table has nothing for
    out.append("")
    out.append("# [[tools]] is not written: a tool solid also needs the cutter's length and the holder's diameter and")
    out.append("# length, which the tool table does not give (its Z is the whole tool's length below the gauge line).")
    out.append("# What the table gives, as the section's parts (replace each \"?\", add the holder, remove the '#'s;")
    out.append("# specs/machine-file.md, \"Tools and fixtures as solids\"):")
    for n, d in known:
        length = im.tool_lengths.get(n)
        out.append("# [[tools]]")
        out.append("# " + _line(f"number = {n}", f"tool length {format_decimal(length.value)} mm below the gauge "
                                 "line: the parts from the tip up to the gauge line add up to it" if length is not None else ""))
        out.append("# " + _line(f"parts = [{{ name = \"cutter\", diameter = {_q(d.value)}, length = \"?\" }}]",
                                _how(d)))


def render_toml(im: ImportedMachine, output: str | None = None) -> str:
    """The machine file text (ends with a newline); ``output`` is where it is written (the folders of
    ``[linuxcnc] subroutine_path`` are relative to it; to the source's folder without one)."""
    label = KIND_LABELS.get(im.kind, im.kind)
    out = [
        f"# Machine file imported from {_clean(im.source)} ({label}) by `nczones import-machine`.",
        "# Each value's comment names the setting it came from. The notes at the end say",
        "# what could not be taken; read them, then check this file with `nczones check-machine`.",
        "",
        "[machine]",
        _line(f"name = {_s(im.name)}", im.name_how),
        _line(f"axes = [{', '.join(_s(a) for a in im.axes)}]", im.axes_how),
        'units = "mm"',
        _line(f"rapid_mode = {_s(im.rapid_mode[0])}", im.rapid_mode[1]),
    ]
    if im.monitor_period_ms is not None:
        out.append(_line(f"monitor_period_ms = {_q(im.monitor_period_ms.value)}", _how(im.monitor_period_ms)))
    if im.modal:
        for code, how in im.modal:
            out.append(f"#   {code}: {_clean(how)}")
        out.append(f"modal = [{', '.join(_s(code) for code, _ in im.modal)}]")
    for key, value, how in im.extra:
        out.append(_line(f"{key} = {value}", how))
    if im.pulse:
        _table(out, "machine.pulse", im.axes, dict(im.pulse))
    _table(out, "machine.rapid", im.axes, dict(im.rapid))
    _table(out, "machine.reference", im.axes, dict(im.reference))
    if im.start:
        _table(out, "machine.start", im.axes, dict(im.start))
    for header, values in im.axis_tables:
        _table(out, header, im.axes, dict(values))
    if im.offsets:
        out.append("")
        out.append("[offsets]")
        for name, values in im.offsets.items():
            for a in im.axes:
                if a in values:
                    out.append(f"#   {name}.{a}: {_clean(_how(values[a]))}")
            items = ", ".join(f"{a} = {_q(values[a].value)}" for a in im.axes if a in values)
            out.append(f"{_s(name) if '.' in name else name} = {{ {items} }}")
    for header, prefix, registers in (("tool_lengths", "H", im.tool_lengths),
                                      ("tool_diameters", "T", im.tool_diameters)):
        if registers:
            out.append("")
            out.append(f"[{header}]")
            for n in sorted(registers):
                out.append(_line(f"{prefix}{n} = {_q(registers[n].value)}", _how(registers[n])))
    _tool_solids(out, im)
    folders, how = im.subroutine_path
    if folders:
        # relative to where the machine file goes; without -o, as if beside the INI (where LinuxCNC reads them)
        base = os.path.dirname(os.path.abspath(output if output else im.source))
        relative = [os.path.relpath(f, base) for f in folders]
        out.append("")
        out.append("[linuxcnc]")
        out.append(_line("subroutine_path = [" + ", ".join(_s(f) for f in relative) + "]", how))
    for header, rows in im.tables:
        out.append("")
        out.append(f"[{header}]")
        for key, value, how in rows:
            out.append(_line(f"{key} = {value}", how))
    for z in im.zones:
        _zone(out, im.axes, z)
    for h in im.homing:
        out.append("")
        out.append(f"# [homing.{h.axis}] is not written: the machine file's homing section also needs "
                   f"{', '.join(h.missing)}, which the source does not give.")
        out.append("# What the source says, in the section's terms (complete it and remove the '#'s to use it):")
        out.append(f"# [homing.{h.axis}]")
        for key, field_value, how in h.fields:
            shown = _q(field_value.value) if isinstance(field_value, Sourced) else field_value
            comment = _how(field_value) if isinstance(field_value, Sourced) else how
            out.append("# " + _line(f"{key} = {shown}", comment))
    if im.notes:
        out.append("")
        out.append("# Notes: what was not taken, rounded or assumed")
        for note in im.notes:
            out.append(f"#   {_clean(note.location())}: {note.code}: {_clean(note.message)}")
    return "\n".join(out) + "\n"
