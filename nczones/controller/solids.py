"""The reference controller's check of the tool solids against the fixtures, pulse by pulse (issue 39).

The machine-file meaning is shared (:mod:`nczones.solids`: the parts of each tool, the spindle parts, the
fixtures); the distance computation is the controller's own (it never imports :mod:`nczones.prover`).

At a pulse position ``p`` (exact: pulse counts times the pulse sizes) a part of radius ``r`` over
``z0..z1`` above its reference is the closed vertical cylinder about ``(p_x, p_y)`` over heights
``p_z - L + z0 .. p_z - L + z1`` (``L`` the active tool length, as the prover reads it; a spindle part has
no ``L``).  It meets a fixture's open interior exactly when the heights overlap (strictly) and the closed
disk meets the open section: the squared distance from ``(p_x, p_y)`` to the box's closed rectangle is
below ``r²`` (to a cylinder's centre: below ``(R + r)²``).

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

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction

import numpy as np

from ..exact import format_decimal
from ..machine import Machine
from ..solids import FixtureBox, FixtureCylinder, Part, Solids, machine_solids

__all__ = ["SolidHit", "ToolSolids", "MachineSolids", "unchecked_solids"]

F0 = Fraction(0)
Fixture = FixtureBox | FixtureCylinder


class SolidHit(str):
    """The name of the fixture a part entered (a ``str``, as zone names are), with the part and fixture."""

    part: Part
    fixture: Fixture

    def __new__(cls, part: Part, fixture: Fixture) -> SolidHit:
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


#: The squared horizontal distance from a point to a fixture's section (closed rectangle / centre), and the
#: radius the part's own radius is added to (0 for a box), per fixture shape.
_GAP2: dict[type, Callable[..., Fraction]] = {FixtureBox: _box_gap2, FixtureCylinder: _cylinder_gap2}


def _reach(fx: Fixture) -> Fraction:
    return fx.radius if isinstance(fx, FixtureCylinder) else F0


def _inf(v: Fraction | None, default: float) -> float:
    return default if v is None else float(v)


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
        key = Fraction(tool_length)
        got = self._compiled.get(key)
        if got is None:
            got = self._compiled[key] = tuple((self._pair_test(part, fx, key), SolidHit(part, fx))
                                              for part in self.parts for fx in self.fixtures)
        return got

    def _pair_test(self, part: Part, fx: Fixture, tool_length: Fraction) -> Callable[[np.ndarray], np.ndarray]:
        (ix, iy, iz), (ux, uy, uz) = self.index, self.pulse
        lo, hi = self._heights(part, tool_length)
        lo_f, hi_f = float(lo), float(hi)
        z0, z1 = _inf(fx.z0, -np.inf), _inf(fx.z1, np.inf)
        reach = float(_reach(fx) + part.radius + self.grow_xy)
        if isinstance(fx, FixtureCylinder):
            sec = (float(fx.cx), float(fx.cx), float(fx.cy), float(fx.cy))
        else:
            sec = (_inf(fx.x0, -np.inf), _inf(fx.x1, np.inf), _inf(fx.y0, -np.inf), _inf(fx.y1, np.inf))
        finite = [abs(v) for v in (*sec, z0, z1, lo_f, hi_f, reach) if np.isfinite(v)]
        fu = (float(ux), float(uy), float(uz))

        def test(pos: np.ndarray) -> np.ndarray:
            x, y, z = pos[:, ix] * fu[0], pos[:, iy] * fu[1], pos[:, iz] * fu[2]
            # a margin far above the float error of these sums and squares (relative 1e-15 of the magnitudes)
            scale = 1.0 + max(finite, default=0.0) + (float(np.abs(pos).max()) * max(fu) if len(pos) else 0.0)
            tol = 1e-9 * scale
            gx = np.maximum(0.0, np.maximum(sec[0] - x, x - sec[1]))
            gy = np.maximum(0.0, np.maximum(sec[2] - y, y - sec[3]))
            g2, bottom, top = gx * gx + gy * gy, z + lo_f, z + hi_f
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


@dataclass(frozen=True)
class MachineSolids:
    """A machine's solids as the controller sees them: :meth:`for_tool` gives the parts of the active tool."""

    solids: Solids
    index: tuple[int, int, int]
    pulse: tuple[Fraction, Fraction, Fraction]
    _by_tool: dict[int | None, ToolSolids | None] = field(default_factory=dict, compare=False, repr=False)

    @classmethod
    def of(cls, machine: Machine) -> MachineSolids | None:
        """None when the machine describes no tool solids or no fixtures (nothing to check), or only solids the
        controller does not check (:func:`unchecked_solids` names them)."""
        solids = machine_solids(machine)
        if solids is None or not solids.fixtures or not isinstance(solids, Solids):
            return None
        checked = tuple(fx for fx in solids.fixtures if isinstance(fx, (FixtureBox, FixtureCylinder)) and not fx.frame)
        if not checked:
            return None
        axes = machine.axis_names
        idx = (axes.index("X"), axes.index("Y"), axes.index("Z"))
        return cls(replace(solids, fixtures=checked), idx,
                   (machine.axes[idx[0]].pulse, machine.axes[idx[1]].pulse, machine.axes[idx[2]].pulse))

    def for_tool(self, register: int | None) -> ToolSolids | None:
        """The parts while tool length register ``register`` is active.  Under G49 (None) with tools described
        the tool is not known: only the spindle parts are checked (the prover says ``unknown``, VF211)."""
        if register not in self._by_tool:
            parts = self.solids.parts_for(register)
            if parts is None:
                parts = self.solids.spindle
            fixtures = tuple(fx for fx in self.solids.fixtures if isinstance(fx, (FixtureBox, FixtureCylinder)))
            self._by_tool[register] = ToolSolids(parts, fixtures, self.index, self.pulse) if parts else None
        return self._by_tool[register]


def unchecked_solids(machine: Machine) -> str | None:
    """A note naming the tool solids the controller does not check (a lathe's turret tools, fixture prisms,
    fixtures in a work offset): the prover proves them; the reference controller is no second witness there."""
    solids = machine_solids(machine)
    if solids is None or not solids.fixtures:
        return None
    if not isinstance(solids, Solids):
        return "the reference controller does not check a lathe's tool solids (the prover does)"
    names = [fx.name for fx in solids.fixtures if type(fx) not in _GAP2 or fx.frame]
    if not names:
        return None
    return (f"the reference controller does not check the tool solids against {', '.join(f'`{n}`' for n in names)} "
            "(a fixture prism or a fixture in a work offset; the prover does)")
