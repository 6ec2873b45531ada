"""The limit monitor: exact zone membership of integer pulse positions.

Two forms of one check:

* :meth:`LimitMonitor.check` — the reference, one position at a time.  A
  stepped zone is read the way the limit-value table works (patent
  JPS6133202B2): compare the reference-axis coordinate with ``from`` and then
  with each region boundary in turn until it is not greater
  (:meth:`~nczones.zones.SteppedZone.region_sequential`, at most
  ``regions + 1`` comparisons, counted in :attr:`LimitMonitor.stats`), read
  that row's limits, compare the limited axis.  Every other zone uses
  :mod:`nczones.zones` exact membership on the pulse position in mm.
* :class:`CompiledCheck` — the same decision on many positions at once: every
  bound ``b`` of a zone becomes an integer pulse threshold (``p * u >= b``
  iff ``p >= ceil(b / u)``, ``p * u > b`` iff ``p >= floor(b / u) + 1``, ...),
  so a numpy comparison on int64 pulse counts is exact.  Stepped tables use
  ``searchsorted`` over ``floor(upto / u)``, which finds the same row as the
  sequential comparison; when the smallest and the largest reference-axis
  position of the positions checked fall in the same row, every position
  between does too (``searchsorted`` is monotone), and that row's limits are
  compared at once.  Polygons and forbid stepped zones are not compiled
  (``compile`` returns None and callers use the reference).

Tool-tip zones (``point = "tip"``) see the tool axis' coordinate minus the
active tool length.

With ``solids`` (:class:`.solids.ToolSolids`, the parts of the active tool and
the machine's fixtures; a lathe's :class:`.solids.LatheToolSolids`) both forms also test every part against every fixture
at the pulse position (grown by half a pulse step, so that the step between two
positions is covered too); a hit is named by a :class:`.solids.SolidHit`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from ..machine import Machine
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint
from ..zones.kinds import KindTable
from .solids import LatheToolSolids, ToolSolids, polygon_gap2_np

__all__ = ["LimitMonitor", "CompiledCheck", "MonitorStats"]

_BIG = np.int64(2**62)


@dataclass(slots=True)
class MonitorStats:
    """What the reference monitor did: checks, stepped lookups and comparisons."""

    checks: int = 0
    lookups: int = 0
    max_lookup_comparisons: int = 0
    total_lookup_comparisons: int = 0
    max_regions: int = 0


@dataclass(frozen=True, slots=True)
class CompiledCheck:
    """Vectorized exact violation test for one tool length.

    ``bad(pos)`` takes an ``(n, axes)`` int64 array of pulse positions and
    returns a bool array: True where the position is outside the allowed set.
    """

    tests: tuple  # of callables ndarray -> bool ndarray (True = violates that zone)
    names: tuple[str, ...]

    def bad(self, pos: np.ndarray) -> np.ndarray:
        out = np.zeros(pos.shape[0], dtype=bool)
        for t in self.tests:
            out |= t(pos)
        return out

    def violated(self, pos: np.ndarray) -> tuple[str, ...]:
        """Names of the zones the single position ``pos`` (shape (axes,)) violates."""
        row = pos.reshape(1, -1)
        return tuple(n for n, t in zip(self.names, self.tests) if bool(t(row)[0]))


@dataclass
class LimitMonitor:
    """Exact limit checks of pulse positions against a machine's zones.

    Examples
    --------
    >>> from nczones.machine import load_machine
    >>> m = load_machine("specs/machines/grinder.toml")
    >>> mon = LimitMonitor(m)
    >>> mon.check((500_000, 250_000), Fraction(0))     # X500 Y250: grinding region
    ()
    >>> mon.check((300_000, 150_000), Fraction(0))     # over the work head, too low
    ('wheel area',)
    >>> mon.stats.max_lookup_comparisons <= len(m.zones[0].regions) + 1
    True
    """

    machine: Machine
    stats: MonitorStats = field(default_factory=MonitorStats)
    #: the tool solids to check as well (the parts of the active tool against the fixtures), or None
    solids: ToolSolids | LatheToolSolids | None = None
    _compiled: dict[Fraction, "CompiledCheck | None"] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.axes = self.machine.axis_names
        self.pulse = tuple(a.pulse for a in self.machine.axes)
        self.index = {a: i for i, a in enumerate(self.axes)}

    # ------------------------------------------------------------------ reference
    def point_mm(self, pos: Sequence[int]) -> dict[str, Fraction]:
        return {a: p * u for a, p, u in zip(self.axes, pos, self.pulse)}

    def _stepped_allows(self, z: SteppedZone, q: Mapping[str, Fraction]) -> bool:
        region, comparisons = z.region_sequential(q[z.reference_axis])
        st = self.stats
        st.lookups += 1
        st.total_lookup_comparisons += comparisons
        st.max_lookup_comparisons = max(st.max_lookup_comparisons, comparisons)
        st.max_regions = max(st.max_regions, len(z.regions))
        if region is None:
            return False
        row = z.regions[region]
        v = q[z.limited_axis]
        return (row.min is None or v >= row.min) and (row.max is None or v <= row.max)

    def check(self, pos: Sequence[int], tool_length: Fraction) -> tuple[str, ...]:
        """Names of the zones the pulse position violates (empty: allowed)."""
        self.stats.checks += 1
        p = self.point_mm(pos)
        allowed = self.machine.allowed
        out = []
        for z in allowed.zones:
            q = allowed.seen_by(z, p, tool_length)
            if POINT_VIOLATES(z, self, q):
                out.append(z.name)
        if self.solids is not None:
            out += self.solids.check(pos, tool_length)
        return tuple(out)

    # ------------------------------------------------------------------ compiled
    def compile(self, tool_length: Fraction) -> CompiledCheck | None:
        """The vectorized form for one tool length, or None if some zone has none."""
        key = Fraction(tool_length)
        if key in self._compiled:
            return self._compiled[key]
        tests, names = [], []
        ok = True
        for z in self.machine.allowed.zones:
            t = self._compile_zone(z, key)
            if t is None:
                ok = False
                break
            tests.append(t)
            names.append(z.name)
        if ok and self.solids is not None:
            for test, hit in self.solids.compiled(key):
                tests.append(test)
                names.append(hit)
        result = CompiledCheck(tuple(tests), tuple(names)) if ok else None
        self._compiled[key] = result
        return result

    def _shift(self, z: Zone, axis: str, tool_length: Fraction) -> Fraction:
        tip = z.point is ZonePoint.TIP and tool_length and axis == self.machine.allowed.tool_axis
        return tool_length if tip else Fraction(0)

    def _compile_zone(self, z: Zone, tl: Fraction) -> Callable[[np.ndarray], np.ndarray] | None:
        return COMPILED(z, self, tl)


def _violates(z: Zone, monitor: LimitMonitor, q: Mapping[str, Fraction]) -> bool:
    return z.interior_contains(q) if z.forbid else not z.contains(q)


#: Does the position ``q`` (in mm, as the zone sees it) violate the zone, by the controller's own test, per zone
#: kind?  Fallback: the zone's membership (forbidden: its interior; allowed: the closed set).
POINT_VIOLATES: KindTable[Callable[[Any, LimitMonitor, Mapping[str, Fraction]], bool]] = KindTable(
    "controller.monitor.point_violates", fallback=_violates)
POINT_VIOLATES.set(BoxZone, _violates)
POINT_VIOLATES.set(PolygonZone, _violates)


@POINT_VIOLATES.register(SteppedZone)
def _stepped_violates(z: SteppedZone, monitor: LimitMonitor, q: Mapping[str, Fraction]) -> bool:
    if z.forbid:
        return z.interior_contains(q)
    return not monitor._stepped_allows(z, q)  # the lookup the controller does, counted


def _not_compiled(z: Zone, monitor: LimitMonitor, tl: Fraction) -> None:
    return None


#: The vectorized test of one zone for one tool length (pulse positions -> violates), per zone kind; None:
#: the zone has none (then the monitor checks point by point).  Fallback: none.
COMPILED: KindTable[Callable[[Any, LimitMonitor, Fraction], Callable[[np.ndarray], np.ndarray] | None]] = KindTable(
    "controller.monitor.compiled", fallback=_not_compiled)


@COMPILED.register(PolygonZone)
def _polygon_compiled(z: PolygonZone, monitor: LimitMonitor, tl: Fraction) -> Callable[[np.ndarray], np.ndarray]:
    """A polygon zone on many positions: its other axes' limits as integer thresholds (exact, as for a box);
    in its plane a float screen (the squared distance to the closed polygon, 0 inside) decides the positions
    farther than a margin far above the float error from every edge, and the others, next to an edge, are
    decided exactly by the reference test (:data:`POINT_VIOLATES`)."""
    (a, b), pulse = z.plane, monitor.pulse
    ka, kb = monitor.index[a], monitor.index[b]
    sa, sb = monitor._shift(z, a, tl), monitor._shift(z, b, tl)
    gap2 = polygon_gap2_np(tuple((va + sa, vb + sb) for va, vb in z.vertices))
    mags = [abs(float(c)) for v in z.vertices for c in v] + [abs(float(sa)), abs(float(sb))]
    ua, ub = float(pulse[ka]), float(pulse[kb])
    cols, los, his = [], [], []
    for axis, lo, hi in z.limits:  # open (forbidden: the interior) or closed (allowed) bounds in pulses
        k = monitor.index[axis]
        u, s = pulse[k], monitor._shift(z, axis, tl)
        if z.forbid:
            los.append(-_BIG if lo is None else math.floor((lo + s) / u) + 1)
            his.append(_BIG if hi is None else math.ceil((hi + s) / u) - 1)
        else:
            los.append(-_BIG if lo is None else math.ceil((lo + s) / u))
            his.append(_BIG if hi is None else math.floor((hi + s) / u))
        cols.append(k)
    cols_a, lo_a, hi_a = np.array(cols, dtype=np.intp), np.array(los, dtype=np.int64), np.array(his, dtype=np.int64)

    def test(pos: np.ndarray) -> np.ndarray:
        x, y = pos[:, ka] * ua, pos[:, kb] * ub
        scale = 1.0 + max(mags, default=0.0) + (float(np.abs(pos).max()) * max(ua, ub) if len(pos) else 0.0)
        tol = 1e-9 * scale
        d2 = gap2(x, y)
        in_plane = d2 == 0.0  # inside the closed polygon (far from an edge: inside its interior too)
        within = np.all((pos[:, cols_a] >= lo_a) & (pos[:, cols_a] <= hi_a), axis=1) if len(cols) else True
        out: np.ndarray = (in_plane & within) if z.forbid else ~(in_plane & within)
        for i in np.flatnonzero(d2 <= tol * tol).tolist():  # next to an edge (or on it): decided exactly
            p = monitor.point_mm(tuple(int(v) for v in pos[i]))
            out[i] = POINT_VIOLATES(z, monitor, monitor.machine.allowed.seen_by(z, p, tl))
        return out
    return test


@COMPILED.register(BoxZone)
def _box_compiled(z: BoxZone, monitor: LimitMonitor, tl: Fraction) -> Callable[[np.ndarray], np.ndarray] | None:
    cols, los, his = [], [], []
    for axis, lo, hi in z.limits:
        k = monitor.index[axis]
        u, s = monitor.pulse[k], monitor._shift(z, axis, tl)
        if z.forbid:  # open interior: lo < p*u - s < hi
            lo_i = -_BIG if lo is None else math.floor((lo + s) / u) + 1
            hi_i = _BIG if hi is None else math.ceil((hi + s) / u) - 1
        else:
            lo_i = -_BIG if lo is None else math.ceil((lo + s) / u)
            hi_i = _BIG if hi is None else math.floor((hi + s) / u)
        cols.append(k)
        los.append(lo_i)
        his.append(hi_i)
    cols_a = np.array(cols, dtype=np.intp)
    lo_a = np.array(los, dtype=np.int64)
    hi_a = np.array(his, dtype=np.int64)
    if z.forbid:
        def test(pos, c=cols_a, lo=lo_a, hi=hi_a):
            sub = pos[:, c]
            return np.all((sub >= lo) & (sub <= hi), axis=1)
    else:
        def test(pos, c=cols_a, lo=lo_a, hi=hi_a):
            sub = pos[:, c]
            return np.any((sub < lo) | (sub > hi), axis=1)
    return test


@COMPILED.register(SteppedZone)
def _stepped_compiled(z: SteppedZone, monitor: LimitMonitor, tl: Fraction) -> Callable[[np.ndarray], np.ndarray] | None:
    if z.forbid:
        return None
    kr, kl = monitor.index[z.reference_axis], monitor.index[z.limited_axis]
    ur, ul = monitor.pulse[kr], monitor.pulse[kl]
    sr, sl = monitor._shift(z, z.reference_axis, tl), monitor._shift(z, z.limited_axis, tl)
    start = math.ceil((z.start + sr) / ur)
    bounds = np.array([math.floor((r.upto + sr) / ur) for r in z.regions], dtype=np.int64)
    lows = np.array([-_BIG if r.min is None else math.ceil((r.min + sl) / ul) for r in z.regions],
                    dtype=np.int64)
    highs = np.array([_BIG if r.max is None else math.floor((r.max + sl) / ul) for r in z.regions],
                     dtype=np.int64)
    n = len(z.regions)

    def test_stepped(pos, kr=kr, kl=kl, start=start, bounds=bounds, lo=lows, hi=highs, n=n):
        r = pos[:, kr]
        v = pos[:, kl]
        if len(r):  # one row of the table for every position (searchsorted is monotone): no lookup each
            r_lo, r_hi = int(r.min()), int(r.max())
            row, row_hi = np.searchsorted(bounds, (r_lo, r_hi), side="left").tolist()
            if row == row_hi and row < n and r_lo >= start:
                return (v < lo[row]) | (v > hi[row])
        idx = np.searchsorted(bounds, r, side="left")
        outside = (r < start) | (idx >= n)
        idx = np.minimum(idx, n - 1)
        return outside | (v < lo[idx]) | (v > hi[idx])
    return test_stepped
