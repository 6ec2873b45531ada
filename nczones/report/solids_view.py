"""The tool at the contact, drawn: the silhouette of a solid violation (issue 39) in the plane figures and the
3-D view.

A violation of ``kind = "solid"`` says that a part of the tool assembly enters a fixture.  The prover keeps,
per violating block, the assembly active there, its tool length, the part and the fixture
(``Result.extra["solid_contacts"]``, :class:`nczones.prover.solids.SolidsChecker`).  Here every part of that
assembly is placed with its controlled point at the violation's path point (a tool part at
``z - L + z0 .. z - L + z1``, a spindle part at ``z + z0 .. z + z1``; ``specs/machine-file.md``, "Where the
parts are"), in exact rationals first, and drawn with the fixture it enters:

* in a plane figure (:func:`draw_contacts`): a part or a cylinder fixture is a circle in the XY plane and a
  rectangle in XZ / YZ; a box fixture a rectangle (an unbounded side clipped to the view).  SVG ids:
  ``tool-part-V-K`` (violation V, part K from the tip up; the whole assembly at the first contact only),
  ``contact-part-V`` (the part that enters), ``contact-fixture-V`` (the fixture it enters, where the
  solids proof puts it: a tip zone's box is drawn where the tool tip is, not shifted by the tool length),
  ``fixture-NAME``;
* in the 3-D view (:func:`contact_traces`): prisms, a cylinder as the regular 32-gon *circumscribed* about
  its circle (the drawing contains the solid, so a point inside the solid is inside the drawing).

The machine's ``[[fixtures]]`` that no forbid zone draws are drawn too (a cylinder clamp, a chuck).

A lathe (:mod:`nczones.lathe_solids`) is drawn in its section through the spindle axis (the plane figure
Z-X; it has no 3-D view): every part of the turret tool is its rectangle relative to the tip (grown by half
its thickness, as the proof uses it) placed at the path point minus the tool offsets, and a fixture of
revolution is its section rectangles, both signs of X (``fixture-NAME`` for +X, ``fixture-NAME-mirror``
for -X); the fixture entered is the section rectangle that holds the witness.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from ..lathe_solids import LatheFixture, LathePart
from ..solids import FixtureCylinder, FixturePrism, machine_solids

__all__ = ["DrawnSolid", "contact_solids", "fixture_solids", "draw_contacts", "contact_traces", "SIDES"]

#: the sides of the polygon a cylinder is drawn as in the 3-D view
SIDES = 32

_ORANGE, _GREY, _DARK = "#e69500", "#8c8c8c", "#5a3d00"


@dataclass(frozen=True, slots=True)
class DrawnSolid:
    """A vertical solid to draw, in exact machine coordinates: a cylinder (``centre``, ``radius``) or a box
    (``box``: (x0, x1, y0, y1), None unbounded), over heights ``z0..z1`` (None unbounded)."""

    name: str
    z0: Fraction | None
    z1: Fraction | None
    centre: tuple[Fraction, Fraction] | None = None
    radius: Fraction | None = None
    box: tuple[Fraction | None, Fraction | None, Fraction | None, Fraction | None] | None = None

    def span(self, axis: str) -> tuple[Fraction | None, Fraction | None]:
        """The extent along ``axis`` (X, Y or Z)."""
        if axis == "Z":
            return self.z0, self.z1
        k = "XY".index(axis)
        if self.centre is not None and self.radius is not None:
            return self.centre[k] - self.radius, self.centre[k] + self.radius
        assert self.box is not None
        return self.box[2 * k], self.box[2 * k + 1]


def _fixture(fx: Any) -> DrawnSolid:
    if isinstance(fx, FixtureCylinder):
        return DrawnSolid(fx.name, fx.z0, fx.z1, centre=(fx.cx, fx.cy), radius=fx.radius)
    return DrawnSolid(fx.name, fx.z0, fx.z1, box=(fx.x0, fx.x1, fx.y0, fx.y1))


def _lathe_sections(fx: LatheFixture) -> list[DrawnSolid]:
    """A fixture of revolution as its section rectangles (X signed), +X first."""
    return [DrawnSolid(fx.name, fx.z0, fx.z1, box=(lo, hi, None, None)) for lo, hi in fx.sections()]


def _inside(v: Fraction, lo: Fraction | None, hi: Fraction | None) -> bool:
    return (lo is None or lo < v) and (hi is None or v < hi)


def _lathe_contact(v: Any, contact: tuple) -> tuple[list[tuple[DrawnSolid, bool]], DrawnSolid]:
    """The turret tool's parts at the violation's path point and the fixture's section holding the witness."""
    parts, (sx, sz), hit, fx = contact
    p, q = dict(v.path_point), dict(v.point)
    tx, tz = p["X"] - sx, p["Z"] - sz  # the tool tip
    drawn = []
    for part in parts:
        a, b, c, d = part.rect()
        drawn.append((DrawnSolid(part.name, tz + c, tz + d, box=(tx + a, tx + b, None, None)), part == hit))
    sections = _lathe_sections(fx)
    entered = next((s for s in sections if _inside(q["X"], *s.span("X"))), sections[0])
    return drawn, entered


def contact_solids(result: Any) -> list[tuple[int, Any, list[tuple[DrawnSolid, bool]], DrawnSolid]]:
    """Per solid violation (1-based index, violation): the parts of the assembly at its path point (each with
    True for the part that enters the fixture) and the fixture."""
    contacts = getattr(result, "extra", {}).get("solid_contacts") if result is not None else None
    if not contacts:
        return []
    out = []
    for i, v in enumerate(result.violations, 1):
        if v.kind != "solid" or v.block not in contacts:
            continue
        if isinstance(contacts[v.block][2], LathePart):  # a lathe's turret tool, in the section
            out.append((i, v, *_lathe_contact(v, contacts[v.block])))
            continue
        parts, length, hit, fx = contacts[v.block]
        if isinstance(fx, FixturePrism):  # a forbidden polygon: drawn as its zone already; no tool drawn here
            continue
        p = dict(v.path_point)
        x, y, z = p["X"], p["Y"], p["Z"]
        drawn = []
        for part in parts:
            base = z if part.spindle else z - length
            drawn.append((DrawnSolid(part.name, base + part.z0, base + part.z1, centre=(x, y), radius=part.radius),
                          part == hit))
        out.append((i, v, drawn, _fixture(fx)))
    return out


def fixture_solids(machine: Any) -> list[DrawnSolid]:
    """The machine's fixture solids that are not forbid zones (those are drawn as zones already)."""
    solids = machine_solids(machine)
    if solids is None:
        return []
    zones = {z.name for z in machine.allowed.zones if z.forbid}
    # a fixture in a work offset is where the program puts it (not one place: not drawn here)
    return [d for f in solids.fixtures if f.name not in zones and not getattr(f, "frame", "")
            for d in (_lathe_sections(f) if isinstance(f, LatheFixture) else [_fixture(f)])]


def _interval(lo: Fraction | None, hi: Fraction | None, lim: tuple[float, float]) -> tuple[float, float]:
    return (float(lo) if lo is not None else min(lim[0], lim[1]) - abs(lim[1] - lim[0]),
            float(hi) if hi is not None else max(lim[0], lim[1]) + abs(lim[1] - lim[0]))


def _patch(ax: Any, s: DrawnSolid, plane: tuple[str, str], **kw: Any) -> Any:
    from matplotlib.patches import Circle, Rectangle

    if plane == ("X", "Y") and s.centre is not None and s.radius is not None:
        return ax.add_patch(Circle((float(s.centre[0]), float(s.centre[1])), float(s.radius), **kw))
    if plane == ("Y", "X") and s.centre is not None and s.radius is not None:
        return ax.add_patch(Circle((float(s.centre[1]), float(s.centre[0])), float(s.radius), **kw))
    (h0, h1) = _interval(*s.span(plane[0]), ax.get_xlim())
    (v0, v1) = _interval(*s.span(plane[1]), ax.get_ylim())
    return ax.add_patch(Rectangle((h0, v0), h1 - h0, v1 - v0, **kw))


def draw_contacts(ax: Any, machine: Any, plane: Sequence[str], result: Any) -> None:
    """Draw the fixtures of :func:`fixture_solids` and, per solid violation, the tool at the contact, into a
    plane figure of the axes X, Y, Z (other planes: nothing)."""
    pl = (str(plane[0]), str(plane[1]))
    if not set(pl) <= {"X", "Y", "Z"}:
        return
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    seen: set[str] = set()
    for f in fixture_solids(machine):
        p = _patch(ax, f, pl, facecolor="#b0b0b0", alpha=0.5, hatch="xx", edgecolor="#404040", zorder=2,
                   label=None if f.name in seen else f"{f.name} (fixture)")
        p.set_gid(f"fixture-{f.name}-mirror" if f.name in seen else f"fixture-{f.name}")
        seen.add(f.name)
    labels = {"fixture": "fixture entered (machine position)", "hit": "tool part entering it",
              "tool": "the rest of the tool at the contact"}
    for n, (i, _v, parts, fx) in enumerate(contact_solids(result)):
        p = _patch(ax, fx, pl, facecolor="none", edgecolor="#b22222", lw=1.5, zorder=3,
                   label=labels.pop("fixture", None))
        p.set_gid(f"contact-fixture-{i}")
        for k, (s, hit) in enumerate(parts, 1):
            if n and not hit:  # the whole assembly at the first contact; at the others the part that enters
                continue
            p = _patch(ax, s, pl, facecolor=_ORANGE if hit else _GREY, alpha=0.45 if hit else 0.25,
                       edgecolor=_DARK, lw=1.2 if hit else 0.8, zorder=6,
                       label=labels.pop("hit" if hit else "tool", None))
            p.set_gid(f"contact-part-{i}" if hit else f"tool-part-{i}-{k}")
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)


def _polygon(s: DrawnSolid, lims: list[tuple[float, float]]) -> list[tuple[float, float]]:
    if s.centre is not None and s.radius is not None:
        r = float(s.radius) / math.cos(math.pi / SIDES)  # circumscribed: contains the circle
        cx, cy = float(s.centre[0]), float(s.centre[1])
        return [(cx + r * math.cos(2 * math.pi * q / SIDES), cy + r * math.sin(2 * math.pi * q / SIDES))
                for q in range(SIDES)]
    x0, x1 = _interval(*s.span("X"), lims[0])
    y0, y1 = _interval(*s.span("Y"), lims[1])
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def contact_traces(result: Any, machine: Any, axes: Sequence[str], lims: list[tuple[float, float]],
                   make: Callable[..., list[dict[str, Any]]]) -> list[dict[str, Any]]:
    """The 3-D view's traces (``make``: the view's prism maker) of the fixtures and the tool at each contact;
    each trace's ``meta`` is ``fixture``, ``contact-fixture-V``, ``contact-part-V`` or ``tool-part-V-K``."""
    if tuple(axes) != ("X", "Y", "Z"):
        return []
    traces: list[dict[str, Any]] = []

    def add(s: DrawnSolid, name: str, group: str, first: bool, meta: str, colour: str | None,
            shown: bool = True) -> None:
        z0, z1 = _interval(s.z0, s.z1, lims[2])
        for t in make(("prism", _polygon(s, lims), (0, 1), 2, z0, z1), name, True, group, first):
            t["meta"] = meta
            if not shown:  # the tool at a later contact: one click on its legend entry shows it
                t["visible"] = "legendonly"
            if colour is None:  # the fixture entered: the view's forbid colours
                pass
            elif t["type"] == "mesh3d":
                t["color"] = colour
            else:
                t["line"] = {"color": _DARK, "width": 2}
            traces.append(t)

    for f in fixture_solids(machine):
        add(f, f"{f.name} (fixture)", f"fixture:{f.name}", True, "fixture", _GREY)
    contacts = contact_solids(result)
    for i, _v, parts, fx in contacts:
        shown = i == contacts[0][0]
        add(fx, f"{fx.name} (fixture entered, violation {i})", f"tool:{i}", False, f"contact-fixture-{i}", None,
            shown)
        for k, (s, hit) in enumerate(parts, 1):
            add(s, f"tool at the contact of violation {i}", f"tool:{i}", k == 1,
                f"contact-part-{i}" if hit else f"tool-part-{i}-{k}", _ORANGE if hit else _GREY, shown)
    return traces
