"""Tool assemblies and fixtures as solids: the ``[[tools]]``, ``[spindle]`` and ``[[fixtures]]`` sections.

A mill's tool is a stack of vertical cylinders along the tool axis (Z), from the tip up: the cutter, the shank,
the holder (each ``{ name, diameter, length }``).  A ball or bull nose cutter is taken as its enclosing
cylinder, a truncated cone (a tapered holder) as the cylinder of its larger diameter: both enclose the real
solid, so a proof about them holds for it.  The spindle nose (``[spindle] parts``) is the same kind of stack
measured from the gauge line (the machine Z position with no tool length) up; it is on the spindle whatever
tool is in it.  Fixtures are solids in machine coordinates: boxes (``kind = "box"``, ``min``/``max`` per axis
X, Y, Z, an axis left out unbounded) and vertical cylinders (``kind = "cylinder"``, ``centre = { X, Y }``,
``radius``, optional ``min_z``/``max_z``); every ``forbid = true`` box zone is a fixture box too.  Touching a
fixture is allowed (as with forbid zones): only the interior is forbidden.

The sections are parsed into :attr:`nczones.machine.Machine.sections` (``"tools"``, ``"spindle"``,
``"fixtures"``); :func:`machine_solids` gathers them.  The proof is :mod:`nczones.prover.solids`.
Codes ZN160-ZN164 (``specs/machine-file.md``, "Tools and fixtures as solids").
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from fractions import Fraction
from types import MappingProxyType
from typing import Any

from .exact import format_decimal
from .lathe_solids import is_lathe_axes, lathe_solids, parse_lathe_fixtures, parse_lathe_tools
from .machine import Machine, as_written, declares_solids, read_number
from .solids_reading import empty_heights, fixture_number, read_fixture_entries, read_tool_entries
from .zones import BoxZone, PolygonZone, SteppedZone
from .zones.kinds import KindTable

__all__ = ["Part", "FixtureBox", "FixtureCylinder", "FixturePrism", "Solids", "machine_solids", "work_frame_name"]

F0 = Fraction(0)


@dataclass(frozen=True, slots=True)
class Part:
    """A vertical cylinder of ``radius`` over ``z0..z1`` above its reference (the tip, or the gauge line for
    a spindle part)."""

    name: str
    radius: Fraction
    z0: Fraction
    z1: Fraction
    spindle: bool = False

    def label(self) -> str:
        """``holder (Ø63 × 40 at 95..135 above the tip)``."""
        ref = "the gauge line" if self.spindle else "the tip"
        return (f"{self.name} (Ø{format_decimal(2 * self.radius)} × {format_decimal(self.z1 - self.z0)} at "
                f"{format_decimal(self.z0)}..{format_decimal(self.z1)} above {ref})")


@dataclass(frozen=True, slots=True)
class FixtureBox:
    """An axis-parallel box in machine coordinates; None is unbounded.  Its interior is forbidden."""

    name: str
    x0: Fraction | None
    x1: Fraction | None
    y0: Fraction | None
    y1: Fraction | None
    z0: Fraction | None
    z1: Fraction | None
    #: the work offset the fixture moves with (``"G54"``, ``"G54.1P2"``); empty: machine coordinates
    frame: str = ""


@dataclass(frozen=True, slots=True)
class FixtureCylinder:
    """A vertical cylinder (axis Z) in machine coordinates; its interior is forbidden."""

    name: str
    cx: Fraction
    cy: Fraction
    radius: Fraction
    z0: Fraction | None
    z1: Fraction | None
    #: the work offset the fixture moves with (``"G54"``, ``"G54.1P2"``); empty: machine coordinates
    frame: str = ""


@dataclass(frozen=True, slots=True)
class FixturePrism:
    """A forbidden polygon in the XY plane over the heights ``z0..z1`` (None: unbounded), in machine
    coordinates; its interior is forbidden."""

    name: str
    vertices: tuple[tuple[Fraction, Fraction], ...]
    z0: Fraction | None
    z1: Fraction | None
    frame: str = ""


Fixture = FixtureBox | FixtureCylinder | FixturePrism


@dataclass(frozen=True, slots=True)
class Solids:
    """What the solids proof needs from a machine: tool stacks by tool number, spindle parts, fixtures."""

    tools: Mapping[int, tuple[Part, ...]]
    spindle: tuple[Part, ...]
    fixtures: tuple[Fixture, ...]
    #: forbidden zones of a kind that is not a fixture solid (:data:`ZONE_FIXTURE`): not checked against the
    #: tool solids, so the verdict cannot be ``safe``
    unmodelled: tuple[str, ...] = ()

    def parts_for(self, tool: int | None) -> tuple[Part, ...] | None:
        """The parts that move with the spindle when tool ``tool`` is active (None: not known)."""
        if tool is None:
            return None if self.tools else self.spindle
        return self.tools.get(tool, ()) + self.spindle


def machine_solids(machine: Machine) -> Solids | None:
    """The machine's solids, or None when it declares no tool or spindle solids (nothing to prove).

    Forbidden zones become fixtures through :data:`ZONE_FIXTURE` (a forbid box is a fixture box); a forbidden
    zone of a kind without an entry there is named in ``unmodelled``, and the verdict cannot be ``safe``."""
    if not declares_solids(machine):
        return None
    if is_lathe_axes(machine.axis_names):  # a lathe: turret tools and solids of revolution
        return lathe_solids(machine)  # type: ignore[return-value]
    sec = machine.sections
    tools = sec.get("tools") or {}
    spindle = sec.get("spindle") or ()
    fixtures: list[Fixture] = list(sec.get("fixtures") or ())
    unmodelled: list[str] = []
    for z in machine.allowed.zones:
        if z.forbid:
            fixture = ZONE_FIXTURE(z)
            if fixture is None:
                unmodelled.append(z.name)
            elif isinstance(fixture, tuple):  # a stepped table: one box per region
                fixtures.extend(fixture)
            else:
                fixtures.append(fixture)
    return Solids(MappingProxyType(dict(tools)), tuple(spindle), tuple(fixtures), tuple(unmodelled))


def _no_fixture(zone: Any) -> Fixture | None:
    return None


#: A forbidden zone as a fixture solid (or several: a stepped table's regions), per zone kind.  Fallback:
#: none (the zone is not checked against the tool solids, and a run that has them is ``unknown``:
#: :attr:`Solids.unmodelled`).
ZONE_FIXTURE: KindTable[Callable[[Any], Fixture | tuple[Fixture, ...] | None]] = KindTable(
    "solids.zone_fixture", fallback=_no_fixture)


@ZONE_FIXTURE.register(SteppedZone)
def _stepped_fixture(z: SteppedZone) -> tuple[Fixture, ...] | None:
    """A stepped table of X, Y or Z as boxes, one per region with an interior (reference values between its
    bounds, the limited axis between its min and max, the third axis unbounded).  The part meets the open
    interior of the union iff it meets the open interior of one of them: a part has an interior, and the
    regions' interiors are dense in the union's (what they leave out are faces and flat regions)."""
    if z.reference_axis not in "XYZ" or z.limited_axis not in "XYZ":
        return None
    out: list[Fixture] = []
    lo = z.start
    for region in z.regions:
        if region.min is None or region.max is None or region.min < region.max:
            lim = {z.reference_axis: (lo, region.upto), z.limited_axis: (region.min, region.max)}
            x, y, zz = (lim.get(a, (None, None)) for a in "XYZ")
            out.append(FixtureBox(z.name, x[0], x[1], y[0], y[1], zz[0], zz[1]))
        lo = region.upto
    return tuple(out)


@ZONE_FIXTURE.register(PolygonZone)
def _prism_fixture(z: PolygonZone) -> Fixture | None:
    """A polygon in the XY plane, bounded (if at all) along Z only, is a prism; any other plane or bound is
    not a fixture solid (None: named, the verdict ``unknown``)."""
    if set(z.plane) != {"X", "Y"} or any(a != "Z" for a, _, _ in z.limits):
        return None
    verts = z.vertices if z.plane == ("X", "Y") else tuple((b, a) for a, b in z.vertices)
    lim = {a: (lo, hi) for a, lo, hi in z.limits}
    z0, z1 = lim.get("Z", (None, None))
    return FixturePrism(z.name, tuple(verts), z0, z1)


@ZONE_FIXTURE.register(BoxZone)
def _box_fixture(z: BoxZone) -> Fixture | None:
    lim = {a: (lo, hi) for a, lo, hi in z.limits}
    x, y, zz = lim.get("X", (None, None)), lim.get("Y", (None, None)), lim.get("Z", (None, None))
    return FixtureBox(z.name, x[0], x[1], y[0], y[1], zz[0], zz[1])


# --------------------------------------------------------------------------- reading

_PART_KEYS = ("name", "diameter", "length")
_FIXTURE_KEYS = {"box": ("name", "kind", "frame", "min", "max"),
                 "cylinder": ("name", "kind", "frame", "centre", "radius", "min_z", "max_z")}
_WORK_FRAMES = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")


def work_frame_name(text: str) -> str | None:
    """The interpreters' name of a work offset (``ProgramFrame.work``), or None when ``text`` names none.

    >>> work_frame_name("G54"), work_frame_name("g54.1 p7"), work_frame_name("G53")
    ('G54', 'G54.1P7', None)
    """
    t = "".join(text.split()).upper()
    if t in _WORK_FRAMES:
        return t
    m = re.fullmatch(r"G54\.1P(\d{1,3})", t)
    return f"G54.1P{int(m.group(1))}" if m and 1 <= int(m.group(1)) <= 300 else None


def _parts(rd: Any, raw: Any, where: str, header: int | None, spindle: bool) -> tuple[Part, ...] | None:
    if not isinstance(raw, list) or not raw or not all(isinstance(p, Mapping) for p in raw):
        rd.report("ZN161", f"{where} parts: expected a list of {{ name, diameter, length }} tables, from the "
                  f"{'gauge line' if spindle else 'tip'} up, got {as_written(raw)}",
                  rd.loc.key("parts", header) or rd.loc.header(header))
        return None
    out, z = [], F0
    ok = True
    for i, p in enumerate(raw):
        for key in p:
            if key not in _PART_KEYS:
                rd.report("ZN160", f"{where} part {i + 1}: unknown key {as_written(key)}; allowed keys: "
                          f"{', '.join(_PART_KEYS)}", rd.loc.element("parts", header, i, key))
                ok = False
        missing = [k for k in ("diameter", "length") if k not in p]
        if missing:
            rd.report("ZN161", f"{where} part {i + 1}: missing {', '.join(missing)}",
                      rd.loc.element("parts", header, i, "name"))
            ok = False
            continue
        name = p.get("name", f"part {i + 1}")
        if not isinstance(name, str) or not name:
            rd.report("ZN161", f"{where} part {i + 1}: name must be a non-empty string, got {as_written(name)}",
                      rd.loc.element("parts", header, i, "name"))
            ok = False
        d = read_number(rd, p["diameter"], f"{where} part {i + 1} diameter",
                        rd.loc.element("parts", header, i, "diameter"), positive=True)
        ln = read_number(rd, p["length"], f"{where} part {i + 1} length",
                         rd.loc.element("parts", header, i, "length"), positive=True)
        if d is None or ln is None or not ok:
            ok = False
            continue
        out.append(Part(str(name), d / 2, z, z + ln, spindle))
        z += ln
    return tuple(out) if ok else None


def parse_tools_section(rd: Any, raw: Any, axes: tuple[str, ...]) -> Mapping[int, tuple[Part, ...]]:
    """``[[tools]]``: ``number`` (the tool number, 0..9999) and ``parts`` from the tip up.

    >>> from nczones.machine import parse_machine
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X", "Y", "Z"]
    ... [machine.rapid]
    ... X = "1000"
    ... Y = "1000"
    ... Z = "1000"
    ... [machine.reference]
    ... X = "0"
    ... Y = "0"
    ... Z = "0"
    ... [[tools]]
    ... number = 1
    ... parts = [{ name = "cutter", diameter = "10", length = "30" }, { name = "holder", diameter = "63", length = "40" }]
    ... ''')
    >>> m.sections["tools"][1][1].label()
    'holder (Ø63 × 40 at 30..70 above the tip)'
    """
    if not isinstance(raw, list):
        rd.report("ZN161", f"[[tools]]: expected an array of tables ([[tools]]), got {as_written(raw)}",
                  rd.loc.key("tools", None))
        return MappingProxyType({})
    if is_lathe_axes(axes):  # a lathe's turret tools: rectangles relative to the tip (nczones.lathe_solids)
        return parse_lathe_tools(rd, raw)  # type: ignore[return-value]
    _solids_axes(rd, axes, "tools")
    return read_tool_entries(rd, raw, lambda parts, num, header: _parts(rd, parts, f"[[tools]] number {num}",
                                                                       header, False))


def parse_spindle_section(rd: Any, raw: Any, axes: tuple[str, ...]) -> tuple[Part, ...]:
    """``[spindle] parts``: the spindle nose as a stack of cylinders from the gauge line up."""
    header = rd.loc.section("spindle")
    if not isinstance(raw, Mapping):
        rd.report("ZN161", f"[spindle]: expected a table with parts, got {as_written(raw)}",
                  rd.loc.key("spindle", None))
        return ()
    _solids_axes(rd, axes, "spindle")
    for key in raw:
        if key != "parts":
            rd.report("ZN160", f"[spindle]: unknown key {as_written(key)}; allowed keys: parts",
                      rd.loc.key(key, header))
    return _parts(rd, raw.get("parts"), "[spindle]", header, True) or ()


def _solids_axes(rd: Any, axes: tuple[str, ...], section: str) -> None:
    if not all(a in axes for a in "XYZ"):
        lathe = ("; on a lathe (X and Z) the turret tool is [[tools]] rectangles and the fixtures [[fixtures]] "
                 "chucks (specs/turning.md): [spindle] has no lathe form") if is_lathe_axes(axes) else ""
        rd.report("ZN164", f"[{section}]: solids need the axes X, Y and Z (a vertical tool axis); this machine "
                  f"has {', '.join(axes)}{lathe}", rd.loc.header(rd.loc.section(section)))


def parse_fixtures_section(rd: Any, raw: Any, axes: tuple[str, ...]) -> tuple[Fixture, ...]:
    """``[[fixtures]]``: boxes and vertical cylinders in machine coordinates."""
    if not isinstance(raw, list):
        rd.report("ZN161", f"[[fixtures]]: expected an array of tables, got {as_written(raw)}",
                  rd.loc.key("fixtures", None))
        return ()
    if is_lathe_axes(axes):  # a lathe: solids of revolution about the spindle axis (nczones.lathe_solids)
        return parse_lathe_fixtures(rd, raw)  # type: ignore[return-value]
    _solids_axes(rd, axes, "fixtures")
    return tuple(read_fixture_entries(rd, raw, _FIXTURE_KEYS, ("ZN163", ""), "",
                                      lambda t, kind, name, header: _fixture(rd, t, kind, name, header)))


def _fixture(rd: Any, t: Mapping, kind: str, name: str, header: int | None) -> Fixture | None:
    """A box or a cylinder, in the work offset its ``frame`` names."""
    fx = _fixture_box(rd, t, name, header) if kind == "box" else _fixture_cylinder(rd, t, name, header)
    frame = _fixture_frame(rd, t, name, header)
    return replace(fx, frame=frame) if fx is not None and frame is not None else None


def _fixture_frame(rd: Any, t: Mapping, name: str, header: int | None) -> str | None:
    """``frame = "G54"``: the work offset the fixture moves with ("" when left out: machine coordinates)."""
    if "frame" not in t:
        return ""
    raw = t["frame"]
    frame = work_frame_name(raw) if isinstance(raw, str) else None
    if frame is None:
        rd.report("ZN170", f"[[fixtures]] {name!r}: frame {as_written(raw)} is not a work offset; allowed: "
                  f"{', '.join(_WORK_FRAMES)}, G54.1 P1..P300 (Fanuc), or no frame (machine coordinates)",
                  rd.loc.key("frame", header))
    return frame


def _bound(rd: Any, table: Any, axis: str, what: str, span: Any) -> Fraction | None:
    if not isinstance(table, Mapping) or axis not in table:
        return None
    return read_number(rd, table[axis], f"{what} {axis}", span)


def _fixture_box(rd: Any, t: Mapping, name: str, header: int | None) -> FixtureBox | None:
    lo, hi = t.get("min", {}), t.get("max", {})
    vals: list[Fraction | None] = []
    ok = True
    for key, table in (("min", lo), ("max", hi)):
        if not isinstance(table, Mapping) or any(a not in "XYZ" or len(a) != 1 for a in table):
            rd.report("ZN161", f"[[fixtures]] {name!r} {key}: expected a table of X, Y, Z values, got "
                      f"{as_written(table)}", rd.loc.key(key, header))
            ok = False
    if not ok:
        return None
    for a in "XYZ":
        a0 = _bound(rd, lo, a, f"[[fixtures]] {name!r} min", lambda a=a: rd.loc.key_in("min", header, a))
        a1 = _bound(rd, hi, a, f"[[fixtures]] {name!r} max", lambda a=a: rd.loc.key_in("max", header, a))
        if a0 is not None and a1 is not None and a0 >= a1:
            rd.report("ZN163", f"[[fixtures]] {name!r}: min {a} {format_decimal(a0)} is not below max {a} "
                      f"{format_decimal(a1)} (an empty box)", rd.loc.key_in("max", header, a))
            ok = False
        vals += [a0, a1]
    return FixtureBox(name, vals[0], vals[1], vals[2], vals[3], vals[4], vals[5]) if ok and not rd.failed else None


def _fixture_cylinder(rd: Any, t: Mapping, name: str, header: int | None) -> FixtureCylinder | None:
    c = t.get("centre")
    if not isinstance(c, Mapping) or set(c) != {"X", "Y"}:
        rd.report("ZN161", f"[[fixtures]] {name!r} centre: expected {{ X = \"..\", Y = \"..\" }}, got "
                  f"{as_written(c)}", rd.loc.key("centre", header) or rd.loc.header(header))
        return None
    cx = read_number(rd, c["X"], f"[[fixtures]] {name!r} centre X", rd.loc.key_in("centre", header, "X"))
    cy = read_number(rd, c["Y"], f"[[fixtures]] {name!r} centre Y", rd.loc.key_in("centre", header, "Y"))
    if "radius" not in t:
        rd.report("ZN161", f"[[fixtures]] {name!r}: missing radius", rd.loc.header(header))
        return None
    r = fixture_number(rd, t, "radius", name, header, positive=True)
    z0 = fixture_number(rd, t, "min_z", name, header)
    z1 = fixture_number(rd, t, "max_z", name, header)
    if empty_heights(rd, "ZN163", name, header, z0, z1, "cylinder"):
        return None
    if cx is None or cy is None or r is None:
        return None
    return FixtureCylinder(name, cx, cy, r, z0, z1)


