"""The reference controller's check of the tool solids against the fixtures, pulse by pulse (issue 39).

The machine-file meaning is shared (:mod:`nczones.solids`, :mod:`nczones.lathe_solids`: the parts of each
tool, the spindle parts, the fixtures); the distance computation is the controller's own (it never imports
:mod:`nczones.prover`).  Every fixture the machine file describes is checked: boxes, cylinders, prisms (a
forbidden XY polygon), fixtures in a work offset, and a lathe's turret tool against its fixtures of
revolution (:class:`LatheToolSolids`).

At a pulse position ``p`` (exact: pulse counts times the pulse sizes) a part of radius ``r`` over
``z0..z1`` above its reference is the closed vertical cylinder about ``(p_x, p_y)`` over heights
``p_z - L + z0 .. p_z - L + z1`` (``L`` the active tool length, as the prover reads it; a spindle part has
no ``L``).  It meets a fixture's open interior exactly when the heights overlap (strictly) and the closed
disk meets the open section: the squared distance from ``(p_x, p_y)`` to the box's closed rectangle is
below ``r²`` (to a cylinder's centre: below ``(R + r)²``; to a prism's closed polygon, 0 inside it, else
the least squared distance to an edge, the projection on it clamped to its ends: below ``r²``; a closed disk
meets the open polygon iff its centre is inside or an edge comes nearer than ``r``).

**Fixtures in a work offset** (``frame = "G55"``) are placed where the motion says that offset's origin is
(``ProgramFrame.work_offset``: the machine file's ``[offsets]`` as ``G10 L2``/``L20`` changed them).  A motion
run in another work offset or in a rotated frame does not say: the fixture is left out there and the result
notes it (the prover says ``unknown``, VF219, there).  A change of the placement (``G10 L2`` of the active
offset) is checked at rest like a tool change, before the next motion's first pulse.

**Between pulse positions.**  The axes move from one pulse position to the next by at most one pulse per
axis (the pulse distribution of lines, arcs, helices and dogleg rapids, :mod:`.pulses`; tested).  A point
of the straight step between ``p_k`` and ``p_k+1`` is within half the step of one of them: horizontally
within ``√(u_x² + u_y²) / 2 <= (u_x + u_y) / 2``, vertically within ``u_z / 2``.  So the monitor checks
each part **grown** by ``g_xy = (u_x + u_y) / 2`` in radius and ``g_z = u_z / 2`` at both ends: when the
grown part clears a fixture at both ends of a step, the part clears it all along the step.  The price: a
part that passes within half a pulse step of a fixture without touching it raises the alarm too (the
monitor's gray band, like a stroke check's one pulse).

Two forms of one decision, as for the zones (:mod:`.monitor`): :meth:`ToolSolids.check` on one position
(exact rationals) and :meth:`ToolSolids.compiled` on many (a float screen with a margin far above the
float error picks the candidates, each candidate is decided exactly), so both engines alarm at the same
pulse.  A hit is a :class:`SolidHit`: a ``str`` (the fixture's name, what an alarm's ``zone`` is) that
carries the part and the fixture; the controller then reports an alarm of kind ``"solid"``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import Any

import numpy as np

from ..exact import format_decimal
from ..lathe_solids import LatheFixture, LathePart, LatheSolids, turret_tool
from ..machine import Machine
from ..motion import Segment, tip_offset
from ..solids import FixtureBox, FixtureCylinder, FixturePrism, Part, Solids, machine_solids

__all__ = ["SolidHit", "ToolSolids", "MachineSolids", "LatheToolSolids", "LatheMachineSolids", "controller_solids",
           "frame_origin", "unchecked_solids"]

F0 = Fraction(0)
F1 = Fraction(1)
Fixture = FixtureBox | FixtureCylinder | FixturePrism


class SolidHit(str):
    """The name of the fixture a part entered (a ``str``, as zone names are), with the part and fixture."""

    part: Part | LathePart
    fixture: Fixture | LatheFixture

    def __new__(cls, part: Part | LathePart, fixture: Fixture | LatheFixture) -> SolidHit:
        self = super().__new__(cls, fixture.name)
        self.part = part
        self.fixture = fixture
        return self

    def note(self, position: Sequence[Fraction], axes: Sequence[str]) -> str:
        """``holder (Ø63 × 60 at 40..100 above the tip) enters `vise` at the pulse position X.. Y.. Z..``."""
        at = " ".join(f"{a}{format_decimal(v)}" for a, v in zip(axes, position))
        return f"{self.part.label()} enters `{self.fixture.name}` at the pulse position {at}"


def _box_gap2(fx: FixtureBox, x: Fraction, y: Fraction) -> Fraction:
    gx = max(F0, F0 if fx.x0 is None else fx.x0 - x, F0 if fx.x1 is None else x - fx.x1)
    gy = max(F0, F0 if fx.y0 is None else fx.y0 - y, F0 if fx.y1 is None else y - fx.y1)
    return gx * gx + gy * gy


def _cylinder_gap2(fx: FixtureCylinder, x: Fraction, y: Fraction) -> Fraction:
    return (x - fx.cx) ** 2 + (y - fx.cy) ** 2


def _edges(vertices: Sequence[tuple[Fraction, Fraction]]) -> Iterator[tuple[tuple[Fraction, Fraction],
                                                                            tuple[Fraction, Fraction]]]:
    return zip(vertices, (*vertices[1:], vertices[0]))


def _crosses(vertices: Sequence[tuple[Fraction, Fraction]], x: Fraction, y: Fraction) -> bool:
    """Even-odd: does a ray from ``(x, y)`` towards +X cross the polygon's edges an odd number of times?  (A
    point on the boundary may go either way: its distance to the boundary is 0 then, which decides.)"""
    odd = False
    for (ax, ay), (bx, by) in _edges(vertices):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            odd = not odd
    return odd


def _edge_d2(a: tuple[Fraction, Fraction], b: tuple[Fraction, Fraction], x: Fraction, y: Fraction) -> Fraction:
    """The squared distance from ``(x, y)`` to the closed segment ``a b``: the nearest point is ``a + t (b - a)``
    with ``t`` the projection clamped to ``[0, 1]`` (rational)."""
    ex, ey = b[0] - a[0], b[1] - a[1]
    e2 = ex * ex + ey * ey
    t = min(F1, max(F0, ((x - a[0]) * ex + (y - a[1]) * ey) / e2)) if e2 else F0
    dx, dy = x - a[0] - t * ex, y - a[1] - t * ey
    return dx * dx + dy * dy


def _prism_gap2(fx: FixturePrism, x: Fraction, y: Fraction) -> Fraction:
    """The squared distance from ``(x, y)`` to the closed polygon: 0 inside, else to its nearest edge."""
    if _crosses(fx.vertices, x, y):
        return F0
    return min(_edge_d2(a, b, x, y) for a, b in _edges(fx.vertices))


#: The squared horizontal distance from a point to a fixture's section (closed rectangle / centre / closed
#: polygon), per fixture shape; :func:`_reach` the radius the part's own radius is added to (a cylinder's).
_GAP2: dict[type, Callable[..., Fraction]] = {FixtureBox: _box_gap2, FixtureCylinder: _cylinder_gap2,
                                              FixturePrism: _prism_gap2}


def _reach(fx: Fixture) -> Fraction:
    return fx.radius if isinstance(fx, FixtureCylinder) else F0


def _inf(v: Fraction | None, default: float) -> float:
    return default if v is None else float(v)


def _rect_gap2_np(sec: tuple[float, float, float, float]) -> Callable[[np.ndarray, np.ndarray], np.ndarray]:
    def gap2(x: np.ndarray, y: np.ndarray) -> np.ndarray:
        gx = np.maximum(0.0, np.maximum(sec[0] - x, x - sec[1]))
        gy = np.maximum(0.0, np.maximum(sec[2] - y, y - sec[3]))
        out: np.ndarray = gx * gx + gy * gy
        return out
    return gap2


def polygon_gap2_np(vertices: Sequence[tuple[Fraction, Fraction]]) -> Callable[[np.ndarray, np.ndarray], np.ndarray]:
    """The float form of :func:`_prism_gap2` (a screen: near an edge the exact form decides; the monitor's
    polygon zones use it too)."""
    edges = [((float(a[0]), float(a[1])), (float(b[0]), float(b[1]))) for a, b in _edges(vertices)]

    def gap2(x: np.ndarray, y: np.ndarray) -> np.ndarray:
        odd = np.zeros(x.shape, dtype=bool)
        best = np.full(x.shape, np.inf)
        for (ax, ay), (bx, by) in edges:
            if ay != by:  # a horizontal edge is never crossed
                odd ^= ((ay > y) != (by > y)) & (x < ax + (y - ay) * (bx - ax) / (by - ay))
            ex, ey = bx - ax, by - ay
            e2 = ex * ex + ey * ey
            t = np.clip(((x - ax) * ex + (y - ay) * ey) / e2, 0.0, 1.0) if e2 else np.zeros(x.shape)
            dx, dy = x - ax - t * ex, y - ay - t * ey
            best = np.minimum(best, dx * dx + dy * dy)
        out: np.ndarray = np.where(odd, 0.0, best)
        return out
    return gap2


def _section_np(fx: Fixture) -> tuple[Callable[[np.ndarray, np.ndarray], np.ndarray], list[float]]:
    """The float squared distance to the fixture's section, and the magnitudes it is computed from."""
    if isinstance(fx, FixturePrism):
        return polygon_gap2_np(fx.vertices), [abs(float(c)) for v in fx.vertices for c in v]
    if isinstance(fx, FixtureCylinder):
        sec = (float(fx.cx), float(fx.cx), float(fx.cy), float(fx.cy))
    else:
        sec = (_inf(fx.x0, -np.inf), _inf(fx.x1, np.inf), _inf(fx.y0, -np.inf), _inf(fx.y1, np.inf))
    return _rect_gap2_np(sec), [abs(v) for v in sec if np.isfinite(v)]


def _compiled_pairs(solids: Any,
                    tool_length: Fraction) -> tuple[tuple[Callable[[np.ndarray], np.ndarray], SolidHit], ...]:
    """``solids``' vectorized test of every part against every fixture at ``tool_length``, built once per length
    (its ``_pair_test``, kept in its ``_compiled``): the mill's and the lathe's tool solids alike."""
    key = Fraction(tool_length)
    got: tuple[tuple[Callable[[np.ndarray], np.ndarray], SolidHit], ...] | None = solids._compiled.get(key)
    if got is None:
        got = solids._compiled[key] = tuple((solids._pair_test(part, fx, key), SolidHit(part, fx))
                                            for part in solids.parts for fx in solids.fixtures)
    return got


@dataclass(frozen=True)
class ToolSolids:
    """The parts in the spindle (one tool, plus the spindle's own) against a machine's fixtures."""

    parts: tuple[Part, ...]
    fixtures: tuple[Fixture, ...]
    index: tuple[int, int, int]  # the X, Y, Z columns of a pulse position
    pulse: tuple[Fraction, Fraction, Fraction]
    _compiled: dict[Fraction, tuple] = field(default_factory=dict, compare=False, repr=False)

    @property
    def grow_xy(self) -> Fraction:
        """Half a pulse step in the plane, rounded up: ``(u_x + u_y) / 2`` (module docstring)."""
        return (self.pulse[0] + self.pulse[1]) / 2

    @property
    def grow_z(self) -> Fraction:
        return self.pulse[2] / 2

    def _heights(self, part: Part, tool_length: Fraction) -> tuple[Fraction, Fraction]:
        shift = F0 if part.spindle else -tool_length
        return part.z0 + shift - self.grow_z, part.z1 + shift + self.grow_z

    def hits_at(self, x: Fraction, y: Fraction, z: Fraction, part: Part, fx: Fixture,
                tool_length: Fraction) -> bool:
        """Does the grown ``part`` at the controlled position ``(x, y, z)`` meet the fixture's interior?"""
        lo, hi = self._heights(part, tool_length)
        if (fx.z1 is not None and z + lo >= fx.z1) or (fx.z0 is not None and z + hi <= fx.z0):
            return False
        reach = _reach(fx) + part.radius + self.grow_xy
        return _GAP2[type(fx)](fx, x, y) < reach * reach

    def check(self, pos: Sequence[int], tool_length: Fraction) -> tuple[SolidHit, ...]:
        """The hits at one pulse position (exact); empty: every part clears every fixture."""
        (ix, iy, iz), (ux, uy, uz) = self.index, self.pulse
        x, y, z = pos[ix] * ux, pos[iy] * uy, pos[iz] * uz
        return tuple(SolidHit(part, fx) for part in self.parts for fx in self.fixtures
                     if self.hits_at(x, y, z, part, fx, tool_length))

    def compiled(self, tool_length: Fraction) -> tuple[tuple[Callable[[np.ndarray], np.ndarray], SolidHit], ...]:
        """One vectorized test per part and fixture: ``(n, axes)`` int64 pulse positions -> hit (exact)."""
        return _compiled_pairs(self, tool_length)

    def _pair_test(self, part: Part, fx: Fixture, tool_length: Fraction) -> Callable[[np.ndarray], np.ndarray]:
        (ix, iy, iz), (ux, uy, uz) = self.index, self.pulse
        lo, hi = self._heights(part, tool_length)
        lo_f, hi_f = float(lo), float(hi)
        z0, z1 = _inf(fx.z0, -np.inf), _inf(fx.z1, np.inf)
        reach = float(_reach(fx) + part.radius + self.grow_xy)
        gap2, mags = _section_np(fx)
        finite = [abs(v) for v in (*mags, z0, z1, lo_f, hi_f, reach) if np.isfinite(v)]
        fu = (float(ux), float(uy), float(uz))

        def test(pos: np.ndarray) -> np.ndarray:
            x, y, z = pos[:, ix] * fu[0], pos[:, iy] * fu[1], pos[:, iz] * fu[2]
            # a margin far above the float error of these sums and squares (relative 1e-15 of the magnitudes)
            scale = 1.0 + max(finite, default=0.0) + (float(np.abs(pos).max()) * max(fu) if len(pos) else 0.0)
            tol = 1e-9 * scale
            g2, bottom, top = gap2(x, y), z + lo_f, z + hi_f
            # certainly in (by more than the margin) / possibly in (within the margin of a face): only the
            # latter, the positions next to a face, are decided exactly
            out: np.ndarray = (bottom < z1 - tol) & (top > z0 + tol) & (g2 < max(reach - tol, 0.0) ** 2)
            cand = (bottom < z1 + tol) & (top > z0 - tol) & (g2 < (reach + tol) ** 2) & ~out
            for i in np.flatnonzero(cand).tolist():  # next to a face: decided exactly
                row = pos[i]
                out[i] = self.hits_at(int(row[ix]) * ux, int(row[iy]) * uy, int(row[iz]) * uz, part, fx,
                                      tool_length)
            return out
        return test


def _moved(fx: Fixture, o: tuple[Fraction, Fraction, Fraction]) -> Fixture:
    """A fixture of a work offset moved to machine coordinates by the offset's origin ``o``."""
    ox, oy, oz = o

    def add(v: Fraction | None, d: Fraction) -> Fraction | None:
        return None if v is None else v + d
    z0, z1 = add(fx.z0, oz), add(fx.z1, oz)
    if isinstance(fx, FixturePrism):
        return replace(fx, vertices=tuple((x + ox, y + oy) for x, y in fx.vertices), z0=z0, z1=z1, frame="")
    if isinstance(fx, FixtureCylinder):
        return replace(fx, cx=fx.cx + ox, cy=fx.cy + oy, z0=z0, z1=z1, frame="")
    return replace(fx, x0=add(fx.x0, ox), x1=add(fx.x1, ox), y0=add(fx.y0, oy), y1=add(fx.y1, oy), z0=z0, z1=z1,
                   frame="")


def frame_origin(seg: Segment, frame: str, index: tuple[int, ...]) -> tuple[Fraction, ...] | None:
    """Where the work offset ``frame``'s origin is at a motion, in machine coordinates (at the columns
    ``index``), as the motion carries it (``ProgramFrame.work_offset``: the offset as the program set it, G10
    L2/L20 included), or None when the motion does not say: it runs in another work offset, in a rotated
    frame, or its producer recorded no offset."""
    f = seg.frame
    if f is None or f.work != frame or f.rotation is not None or f.work_offset is None:
        return None
    return tuple(f.work_offset[i] for i in index)


@dataclass(frozen=True)
class MachineSolids:
    """A machine's solids as the controller sees them: :meth:`for_segment` gives the parts of a motion's tool
    against the fixtures where that motion sees them (a fixture in a work offset moved by it)."""

    solids: Solids
    index: tuple[int, int, int]
    pulse: tuple[Fraction, Fraction, Fraction]
    _by_key: dict[tuple, ToolSolids | None] = field(default_factory=dict, compare=False, repr=False)
    #: the fixtures in a work offset left out at some motion (its offset not known there), by name -> line
    unplaced: dict[str, int | None] = field(default_factory=dict, compare=False, repr=False)

    @classmethod
    def of(cls, machine: Machine) -> MachineSolids | None:
        """None when the machine describes no mill tool solids or no fixtures (nothing to check); a lathe's
        are :class:`~.lathe_solids.LatheMachineSolids` (:func:`controller_solids` picks)."""
        solids = machine_solids(machine)
        if solids is None or not solids.fixtures or not isinstance(solids, Solids):
            return None
        axes = machine.axis_names
        idx = (axes.index("X"), axes.index("Y"), axes.index("Z"))
        return cls(solids, idx, (machine.axes[idx[0]].pulse, machine.axes[idx[1]].pulse, machine.axes[idx[2]].pulse))

    @property
    def frames(self) -> tuple[str, ...]:
        return tuple(sorted({fx.frame for fx in self.solids.fixtures if fx.frame}))

    def key(self, seg: Segment) -> tuple:
        """What :meth:`for_segment` reads of a motion: its tool register and its work offsets' origins."""
        return seg.tool_register, tuple(frame_origin(seg, f, self.index) for f in self.frames)

    def for_segment(self, seg: Segment) -> ToolSolids | None:
        """The parts while the motion's tool length register is active, against the fixtures where the motion
        sees them.  Under G49 (None) with tools described the tool is not known: only the spindle parts are
        checked (the prover says ``unknown``, VF211).  A fixture in a work offset the motion does not carry
        (another offset active, a rotation) is left out there and named in :attr:`unplaced` (the prover says
        ``unknown``, VF219)."""
        key = self.key(seg)
        if key not in self._by_key:
            parts = self.solids.parts_for(seg.tool_register)
            if parts is None:
                parts = self.solids.spindle
            origins = dict(zip(self.frames, key[1]))
            fixtures = []
            for fx in self.solids.fixtures:
                o = origins.get(fx.frame) if fx.frame else (F0, F0, F0)
                if o is None:
                    self.unplaced.setdefault(fx.name, seg.line)
                else:
                    fixtures.append(_moved(fx, o) if fx.frame else fx)
            self._by_key[key] = ToolSolids(parts, tuple(fixtures), self.index, self.pulse) \
                if parts and fixtures else None
        return self._by_key[key]

    def notes(self) -> list[str]:
        """What the controller did not check (a fixture whose work offset a motion did not carry)."""
        return [f"the reference controller did not check the tool solids against `{name}` from line {line} on "
                f"where its work offset is not the one the motion runs in (or is rotated): where it is then is not "
                "known (the prover says unknown, VF219)" for name, line in self.unplaced.items()]


def unchecked_solids(machine: Machine) -> str | None:
    """A note naming the forbidden zones that are no fixture solid (a polygon outside the XY plane, a lathe's
    polygon or stepped table): neither the prover (``unknown``, VF210) nor the controller checks the tool
    solids against them."""
    solids = machine_solids(machine)
    names = getattr(solids, "unmodelled", ()) if solids is not None else ()
    if not names:
        return None
    return (f"the tool solids are not checked against {', '.join(f'`{n}`' for n in names)} (a forbidden zone that "
            "is no fixture solid; the prover says unknown, VF210)")


# --------------------------------------------------------------------------- a lathe's turret tool

#: A controlled position's open bounds on one axis (None: unbounded), where a part meets a fixture.
_Open = tuple[Fraction | None, Fraction | None]
_BIG = 2**62


def _below(v: Fraction | None, u: Fraction) -> int:
    """The least pulse count ``p`` with ``p * u > v`` (v None: none bounds it)."""
    return -_BIG if v is None else math.floor(v / u) + 1


def _above(v: Fraction | None, u: Fraction) -> int:
    """The greatest pulse count ``p`` with ``p * u < v``."""
    return _BIG if v is None else math.ceil(v / u) - 1


def _meets(lo: Fraction, hi: Fraction, f0: Fraction | None, f1: Fraction | None) -> bool:
    """Does the closed interval ``lo..hi`` meet the open ``f0..f1`` (None: unbounded)?"""
    return (f0 is None or hi > f0) and (f1 is None or lo < f1)


@dataclass(frozen=True)
class LatheToolSolids:
    """A lathe's turret tool (its parts: rectangles relative to the tool tip, :class:`~nczones.lathe_solids.
    LathePart`) against the fixtures of revolution, in the section through the spindle axis.

    At the controlled position ``(X, Z)`` the tip is ``(X - s_x, Z - s_z)`` (``s`` the tool offsets: the
    motion's X offset and the tool length on the tool axis Z, as the machine file means them), and a part
    with the rectangle ``a..b × c..d`` (grown by half its thickness on X, the machine file's enclosure) covers
    ``X - s_x + a .. X - s_x + b`` by ``Z - s_z + c .. Z - s_z + d``.  It meets a fixture when that closed
    rectangle meets one of the fixture's open section rectangles (``|x|`` strictly between its radii: one
    interval for a solid, two for a ring), grown by half a pulse per axis: a step moves each axis by at most
    one pulse, so every point of it is within half a pulse on X and on Z of one of its ends."""

    parts: tuple[LathePart, ...]
    fixtures: tuple[LatheFixture, ...]
    index: tuple[int, int]  # the X, Z columns of a pulse position
    pulse: tuple[Fraction, Fraction]
    #: the motion's tip offsets off the tool axis (X, Z); the tool length replaces the tool axis' one
    offset: tuple[Fraction, Fraction]
    tool_axis: str | None
    _compiled: dict[Fraction, tuple] = field(default_factory=dict, compare=False, repr=False)

    def shift(self, tool_length: Fraction) -> tuple[Fraction, Fraction]:
        """The controlled point minus the tool tip (X, Z)."""
        return (tool_length if self.tool_axis == "X" else self.offset[0],
                tool_length if self.tool_axis == "Z" else self.offset[1])

    def hits_at(self, x: Fraction, z: Fraction, part: LathePart, fx: LatheFixture, tool_length: Fraction) -> bool:
        """Does the grown part, the tool at the controlled position ``(x, z)``, meet the fixture's interior?"""
        sx, sz = self.shift(tool_length)
        gx, gz = self.pulse[0] / 2, self.pulse[1] / 2
        a, b, c, d = part.rect()
        tx, tz = x - sx, z - sz  # the tip
        if not _meets(tz + c - gz, tz + d + gz, fx.z0, fx.z1):
            return False
        return any(_meets(tx + a - gx, tx + b + gx, f0, f1) for f0, f1 in fx.sections())

    def check(self, pos: Sequence[int], tool_length: Fraction) -> tuple[SolidHit, ...]:
        """The hits at one pulse position (exact); empty: every part clears every fixture."""
        (ix, iz), (ux, uz) = self.index, self.pulse
        x, z = pos[ix] * ux, pos[iz] * uz
        return tuple(SolidHit(part, fx) for part in self.parts for fx in self.fixtures
                     if self.hits_at(x, z, part, fx, tool_length))

    def compiled(self, tool_length: Fraction) -> tuple[tuple[Callable[[np.ndarray], np.ndarray], SolidHit], ...]:
        """One vectorized test per part and fixture, exact: the open bounds on the controlled X and Z become
        integer pulse thresholds (``p u > v`` iff ``p >= floor(v / u) + 1``, ``p u < v`` iff
        ``p <= ceil(v / u) - 1``), compared on the int64 pulse counts."""
        return _compiled_pairs(self, tool_length)

    def _bounds(self, part: LathePart, fx: LatheFixture, tool_length: Fraction) -> list[tuple[_Open, _Open]]:
        """Per section rectangle of the fixture, the open bounds of the controlled X and Z where the grown part
        meets it (the tip's interval conditions of :meth:`hits_at` solved for the controlled point)."""
        sx, sz = self.shift(tool_length)
        gx, gz = self.pulse[0] / 2, self.pulse[1] / 2
        a, b, c, d = part.rect()

        def add(v: Fraction | None, w: Fraction) -> Fraction | None:
            return None if v is None else v + w
        zb = (add(fx.z0, sz - d - gz), add(fx.z1, sz - c + gz))
        return [((add(f0, sx - b - gx), add(f1, sx - a + gx)), zb) for f0, f1 in fx.sections()]

    def _pair_test(self, part: LathePart, fx: LatheFixture, tool_length: Fraction
                   ) -> Callable[[np.ndarray], np.ndarray]:
        (ix, iz), (ux, uz) = self.index, self.pulse
        rows = [(_below(xb[0], ux), _above(xb[1], ux), _below(zb[0], uz), _above(zb[1], uz))
                for xb, zb in self._bounds(part, fx, tool_length)]

        def test(pos: np.ndarray) -> np.ndarray:
            px, pz = pos[:, ix], pos[:, iz]
            out = np.zeros(pos.shape[0], dtype=bool)
            for x0, x1, z0, z1 in rows:
                out |= (px >= x0) & (px <= x1) & (pz >= z0) & (pz <= z1)
            return out
        return test


@dataclass(frozen=True)
class LatheMachineSolids:
    """A lathe's solids as the controller sees them: :meth:`for_segment` gives the turret tool of a motion (its
    T word's tool, Fanuc; else its tool length register) placed with the motion's tool offsets."""

    solids: LatheSolids
    index: tuple[int, int]
    pulse: tuple[Fraction, Fraction]
    tool_axis: str | None
    _by_key: dict[tuple, LatheToolSolids | None] = field(default_factory=dict, compare=False, repr=False)

    @classmethod
    def of(cls, machine: Machine, solids: LatheSolids) -> LatheMachineSolids | None:
        if not solids.fixtures:
            return None
        axes = machine.axis_names
        idx = (axes.index("X"), axes.index("Z"))
        return cls(solids, idx, (machine.axes[idx[0]].pulse, machine.axes[idx[1]].pulse), machine.tool_axis)

    def key(self, seg: Segment) -> tuple:
        """What :meth:`for_segment` reads of a motion: the turret tool and the tip offsets besides the length."""
        tool = turret_tool(seg.extra) if seg.extra else None
        off = tip_offset(seg.extra) if seg.extra else {}
        return (seg.tool_register if tool is None else tool), off.get("X", F0), off.get("Z", F0)

    def for_segment(self, seg: Segment) -> LatheToolSolids | None:
        """None when the tool is not known (no T word, G49: the prover says ``unknown``, VF211) or has no parts
        (nothing described to check)."""
        key = self.key(seg)
        if key not in self._by_key:
            parts = self.solids.tools.get(key[0], ()) if key[0] is not None else ()
            self._by_key[key] = LatheToolSolids(tuple(parts), self.solids.fixtures, self.index, self.pulse,
                                                (key[1], key[2]), self.tool_axis) if parts else None
        return self._by_key[key]

    def notes(self) -> list[str]:
        return []


def controller_solids(machine: Machine) -> MachineSolids | LatheMachineSolids | None:
    """The machine's tool solids as the controller checks them (a mill's or a lathe's), or None: nothing to
    check (no tool solids, no fixtures)."""
    solids = machine_solids(machine)
    if isinstance(solids, LatheSolids):
        return LatheMachineSolids.of(machine, solids)
    return MachineSolids.of(machine)
