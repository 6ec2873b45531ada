"""A lathe's turret tools and fixtures as solids (issue 39, the lathe case).

A lathe here is a machine with the axes X and Z and no Y (``specs/turning.md``, "Tool and fixture solids").
Everything is checked in the **section through the spindle axis** (the plane Y = 0 of machine X/Z, X signed:
negative X is beyond the centre line):

* a fixture is a **solid of revolution** about the spindle axis (Z): a chuck (its jaws revolved: an
  enclosure of the jaws), a tailstock quill, a centre — ``radius`` and an optional ``inner_radius`` (a
  ring: the jaws around a bore) over ``min_z..max_z``.  Its section is ``(-R, R)`` (solid) or
  ``(r, R) ∪ (-R, -r)`` (a ring) times the Z range;
* a tool part is an axis-parallel rectangle ``x = [x0, x1]``, ``z = [z0, z1]`` relative to the tool tip the
  tool offsets measure to (machine units: X a radius, as everywhere in the machine file), lying in the plane
  through the spindle axis and the tip (the tip is on centre height on a lathe without a Y axis), with an
  optional ``thickness`` (its extent across that plane, in Y, centred on it).

Why the section decides exactly: a solid of revolution ``S`` and any solid ``P`` meet iff their radial
projections ``(√(x² + y²), z)`` meet (a point of ``P`` whose projection is in ``S``'s section is in ``S``).  A
part of thickness 0 lies in the plane Y = 0, and the radial projection of a set ``I`` of signed X values is
``{|u| : u ∈ I}``, which meets ``S``'s radial section iff ``I`` meets ``S``'s signed section: exact.  The same
holds for a round bar parallel to Z whose axis is in that plane when its rectangle's X span is its
diameter (the disk's distances from the spindle axis form the interval ``[max(0, |a| - ρ), |a| + ρ]``, the
radial projection of its diameter ``[a - ρ, a + ρ]``).  A part of thickness ``w`` is a box
``[x0, x1] × [-w/2, w/2]`` across the plane: its radial extent at ``X`` lies within that of the signed
interval ``[X + x0 - w/2, X + x1 + w/2]`` (``√(u² + h²) <= |u| + h``), so the rectangle grown by ``w/2`` on
both X sides encloses it: sound, not exact (an ``unsafe`` found only through the growth may be a false
alarm; the report names the part).

Codes ZN165 (a part), ZN166 (a lathe fixture); the shared ones ZN160-ZN162 as for the mill.  The proof is
:mod:`nczones.prover.lathe_solids`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from fractions import Fraction
from types import MappingProxyType
from typing import Any

from .exact import format_decimal
from .machine import Machine, as_written, read_number
from .motion import Payload, TurretTool
from .solids_reading import empty_heights, fixture_number, read_fixture_entries, read_tool_entries
from .zones import BoxZone, PolygonZone, SteppedZone
from .zones.kinds import KindTable

__all__ = ["LathePart", "LatheFixture", "LatheSolids", "is_lathe_axes", "lathe_solids", "parse_lathe_tools",
           "parse_lathe_fixtures", "turret_tool"]

F0 = Fraction(0)


def is_lathe_axes(axes: tuple[str, ...]) -> bool:
    """Do solids on a machine with these axes take the lathe form (X and Z, no Y)?"""
    return "X" in axes and "Z" in axes and "Y" not in axes


@dataclass(frozen=True, slots=True)
class LathePart:
    """A rectangle ``x0..x1 × z0..z1`` relative to the tool tip in the section through the spindle axis,
    ``thickness`` across it (the proof grows the rectangle by half of it on both X sides)."""

    name: str
    x0: Fraction
    x1: Fraction
    z0: Fraction
    z1: Fraction
    thickness: Fraction = F0

    def rect(self) -> tuple[Fraction, Fraction, Fraction, Fraction]:
        """The rectangle the proof uses (grown by half the thickness on X): ``(x0, x1, z0, z1)``."""
        h = self.thickness / 2
        return self.x0 - h, self.x1 + h, self.z0, self.z1

    def label(self) -> str:
        """``boring bar (X -8..8, Z 6..180 from the tip)``."""
        f = format_decimal
        w = f", {f(self.thickness)} thick" if self.thickness else ""
        return f"{self.name} (X {f(self.x0)}..{f(self.x1)}, Z {f(self.z0)}..{f(self.z1)} from the tip{w})"


@dataclass(frozen=True, slots=True)
class LatheFixture:
    """A solid of revolution about the spindle axis: radii ``r_in..r_out`` (None: unbounded) over heights
    ``z0..z1`` (None: unbounded).  Its interior is forbidden."""

    name: str
    r_in: Fraction
    r_out: Fraction | None
    z0: Fraction | None
    z1: Fraction | None

    def sections(self) -> tuple[tuple[Fraction | None, Fraction | None], ...]:
        """Its open X intervals in the signed section (None: unbounded): one for a solid, two for a ring."""
        lo = None if self.r_out is None else -self.r_out
        if self.r_in == 0:
            return ((lo, self.r_out),)
        return ((self.r_in, self.r_out), (lo, -self.r_in))


@dataclass(frozen=True, slots=True)
class LatheSolids:
    """What the lathe solids proof needs: the turret tools' parts by tool number, the fixtures."""

    tools: Mapping[int, tuple[LathePart, ...]]
    fixtures: tuple[LatheFixture, ...]
    #: forbidden zones of a kind that is not a fixture solid (a polygon, a stepped table): named, not checked
    unmodelled: tuple[str, ...] = ()
    spindle: tuple = ()


def turret_tool(extra: tuple[Payload, ...]) -> int | None:
    """The turret tool a segment carries (its :class:`~nczones.motion.TurretTool`, the Fanuc lathe
    interpreter's ``T`` tool number), or None."""
    for p in extra:
        if type(p) is TurretTool:
            return p.number
    return None


def _radial(lo: Fraction | None, hi: Fraction | None) -> tuple[Fraction, Fraction | None]:
    """The radii ``|u|`` of the signed X interval ``lo..hi`` (None: unbounded): ``(least, greatest)``."""
    if lo is not None and lo >= 0:
        return lo, hi
    if hi is not None and hi <= 0:
        return -hi, None if lo is None else -lo
    return F0, None if lo is None or hi is None else max(-lo, hi)


def _no_fixture(zone: Any) -> LatheFixture | None:
    return None


#: A forbidden zone on a lathe as a fixture solid of revolution, per zone kind.  Fallback: none (the zone is
#: named in :attr:`LatheSolids.unmodelled` and the verdict cannot be ``safe``).
LATHE_ZONE_FIXTURE: KindTable[Callable[[Any], LatheFixture | None]] = KindTable(
    "lathe_solids.zone_fixture", fallback=_no_fixture)
# a forbidden polygon or stepped table in the ZX plane is not revolved yet: named, never skipped
LATHE_ZONE_FIXTURE.set(SteppedZone, _no_fixture)
LATHE_ZONE_FIXTURE.set(PolygonZone, _no_fixture)


@LATHE_ZONE_FIXTURE.register(BoxZone)
def zone_fixture(z: BoxZone) -> LatheFixture | None:
    """A forbidden box zone on a lathe as the solid it sweeps about the spindle axis (an enclosure)."""
    lim = {a: (lo, hi) for a, lo, hi in z.limits}
    x, zz = lim.get("X", (None, None)), lim.get("Z", (None, None))
    r_in, r_out = _radial(*x)
    return LatheFixture(z.name, r_in, r_out, zz[0], zz[1])


def lathe_solids(machine: Machine) -> LatheSolids | None:
    """The lathe's solids, or None when it describes no tool parts.  Forbidden box zones are fixtures too
    (revolved about the spindle axis); a forbidden zone of another kind is named in ``unmodelled``."""
    tools = machine.sections.get("tools") or {}
    if not tools:
        return None
    fixtures: list[LatheFixture] = list(machine.sections.get("fixtures") or ())
    unmodelled: list[str] = []
    for z in machine.allowed.zones:
        if z.forbid:
            fixture = LATHE_ZONE_FIXTURE(z)
            if fixture is None:
                unmodelled.append(z.name)
            else:
                fixtures.append(fixture)
    return LatheSolids(MappingProxyType(dict(tools)), tuple(fixtures), tuple(unmodelled))


# --------------------------------------------------------------------------- reading

_PART_KEYS = ("name", "x", "z", "thickness")
_FIXTURE_KEYS = ("name", "kind", "radius", "inner_radius", "min_z", "max_z")


def _pair(rd: Any, p: Mapping, key: str, what: str, span: Any) -> tuple[Fraction, Fraction] | None:
    raw = p.get(key)
    if not isinstance(raw, list) or len(raw) != 2:
        rd.report("ZN165", f"{what} {key}: expected [\"low\", \"high\"] relative to the tip, got {as_written(raw)}",
                  span)
        return None
    lo = read_number(rd, raw[0], f"{what} {key} low", span)
    hi = read_number(rd, raw[1], f"{what} {key} high", span)
    if lo is None or hi is None:
        return None
    if lo >= hi:
        rd.report("ZN165", f"{what} {key}: {format_decimal(lo)} is not below {format_decimal(hi)} (an empty "
                  "rectangle)", span)
        return None
    return lo, hi


def _lathe_part(rd: Any, p: Mapping, i: int, where: str, header: int | None) -> LathePart | None:
    what = f"{where} part {i + 1}"
    ok = True
    for key in p:
        if key not in _PART_KEYS:
            rd.report("ZN160", f"{what}: unknown key {as_written(key)}; allowed keys on a lathe: "
                      f"{', '.join(_PART_KEYS)} (a rectangle relative to the tip, X a radius)",
                      rd.loc.element("parts", header, i, key))
            ok = False
    name = p.get("name", f"part {i + 1}")
    if not isinstance(name, str) or not name:
        rd.report("ZN161", f"{what}: name must be a non-empty string, got {as_written(name)}",
                  rd.loc.element("parts", header, i, "name"))
        ok = False
    x = _pair(rd, p, "x", what, rd.loc.element("parts", header, i, "x") or rd.loc.header(header))
    z = _pair(rd, p, "z", what, rd.loc.element("parts", header, i, "z") or rd.loc.header(header))
    w = F0
    if "thickness" in p:
        w = read_number(rd, p["thickness"], f"{what} thickness", rd.loc.element("parts", header, i, "thickness"),
                        nonnegative=True) or F0
    if x is None or z is None or not ok:
        return None
    return LathePart(str(name), x[0], x[1], z[0], z[1], w)


def parse_lathe_tools(rd: Any, raw: list) -> Mapping[int, tuple[LathePart, ...]]:
    """``[[tools]]`` on a lathe: ``number`` (the turret tool, ``T0101``: 1) and ``parts``, each
    ``{ name, x = [lo, hi], z = [lo, hi], thickness }`` relative to the tool tip."""

    def parts_of(parts: Any, num: int, header: int | None) -> tuple[LathePart, ...] | None:
        if not isinstance(parts, list) or not parts or not all(isinstance(p, Mapping) for p in parts):
            rd.report("ZN161", f"[[tools]] number {num} parts: expected a list of {{ name, x, z }} tables, got "
                      f"{as_written(parts)}", rd.loc.key("parts", header) or rd.loc.header(header))
            return None
        read = [_lathe_part(rd, p, i, f"[[tools]] number {num}", header) for i, p in enumerate(parts)]
        return tuple(p for p in read if p is not None) if all(p is not None for p in read) else None

    return read_tool_entries(rd, raw, parts_of)


_FIXTURE_KINDS = {"chuck": _FIXTURE_KEYS, "cylinder": _FIXTURE_KEYS}


def parse_lathe_fixtures(rd: Any, raw: list) -> tuple[LatheFixture, ...]:
    """``[[fixtures]]`` on a lathe: ``kind = "chuck"`` or ``"cylinder"``, solids of revolution about the
    spindle axis: ``radius``, optional ``inner_radius`` (a ring), ``min_z``, ``max_z``."""
    return tuple(read_fixture_entries(
        rd, raw, _FIXTURE_KINDS, ("ZN166", " (on a lathe a fixture is a solid of revolution about the spindle axis)"),
        "lathe ", lambda t, _kind, name, header: _lathe_fixture(rd, t, name, header)))


def _lathe_fixture(rd: Any, t: Mapping, name: str, header: int | None) -> LatheFixture | None:
    if "radius" not in t:
        rd.report("ZN161", f"[[fixtures]] {name!r}: missing radius", rd.loc.header(header))
        return None
    r = fixture_number(rd, t, "radius", name, header, positive=True)
    r_in = fixture_number(rd, t, "inner_radius", name, header, nonnegative=True) if "inner_radius" in t else F0
    z0 = fixture_number(rd, t, "min_z", name, header)
    z1 = fixture_number(rd, t, "max_z", name, header)
    if r is None or r_in is None:
        return None
    if r_in >= r:
        rd.report("ZN166", f"[[fixtures]] {name!r}: inner_radius {format_decimal(r_in)} is not below radius "
                  f"{format_decimal(r)} (an empty ring)", rd.loc.key("inner_radius", header))
        return None
    if empty_heights(rd, "ZN166", name, header, z0, z1, "solid"):
        return None
    return LatheFixture(name, r_in, r, z0, z1)
