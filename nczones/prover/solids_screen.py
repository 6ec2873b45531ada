"""A vectorized screen of straight motions before the exact solids proof (issue 39, speed).

:class:`nczones.prover.solids.SolidsChecker` proves each motion exactly (rationals, about a millisecond per
motion with a few parts and fixtures).  Most motions of a CAM program pass far from every fixture; this
screen decides them in bulk with numpy, soundly, and sends only the undecided ones to the exact proof.

For a batch of straight motions (lines, rapids — each axis of a dogleg rapid moves monotonically, so every
rapid stays in the box of its end points — and dwells) with a known tool, per part and fixture:

* the part's heights over the motion lie in ``[min z + lo, max z + hi]`` (``lo``/``hi``: the part's
  heights relative to the controlled point, :meth:`SolidsChecker._offsets`); when that interval is at least
  :data:`EPS` below the fixture's bottom or above its top, the part never meets the fixture on the motion
  (and the exact proof would not count the motion in the least clearance either: their heights never
  overlap);
* otherwise the horizontal distance from the box of the part's axis over the motion to the fixture's section
  (a box: the rectangle; a cylinder: its centre, less its radius) is a lower bound of the distance during
  the motion; when it is at least :data:`EPS` above ``c + r`` (``c``: the least clearance of the pair so far,
  ``r`` the part's radius; a cylinder adds its own radius), the part neither enters the fixture nor comes
  closer than ``c``, so the motion changes neither the verdict nor the least clearance (which only
  decreases: a motion screened against an earlier ``c`` is at least as far from the later one).

A pair without a least clearance yet is not screened by distance (the exact proof sets it).  Every other
motion goes to the exact proof, in program order.  The floats: each coordinate is the correctly rounded
value of its rational, every operation adds at most one rounding; with coordinates below :data:`LIMIT` mm
the accumulated error is below 1e-8 mm, far inside :data:`EPS` = 1e-6 mm; a motion with a coordinate
beyond :data:`LIMIT` is not screened.  ``tests/prover/test_solids_screen.py`` holds the screen to the exact
proof (same violations, reasons and least clearances) on generated programs.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from ..motion import MotionChunk, Segment, SegmentKind
from ..solids import FixtureCylinder, Part

__all__ = ["Pair", "Screened", "needs_exact", "needs_exact_columns", "group_by_tool", "EPS", "LIMIT"]

#: the margin (mm) the screen keeps from every decision
EPS = 1e-6
#: coordinates (mm) beyond which a motion is not screened
LIMIT = 1e7


def _fixture_arrays(fixtures: Sequence[Any]) -> dict[str, np.ndarray]:
    inf = np.inf

    def val(v: Fraction | None, default: float) -> float:
        return default if v is None else float(v)

    cyl = np.array([isinstance(f, FixtureCylinder) for f in fixtures])
    out = {"cyl": cyl,
           "z0": np.array([val(f.z0, -inf) for f in fixtures]), "z1": np.array([val(f.z1, inf) for f in fixtures])}
    # a cylinder's section is its centre (a degenerate rectangle) grown by its radius
    out["x0"] = np.array([float(f.cx) if c else val(f.x0, -inf) for f, c in zip(fixtures, cyl)])
    out["x1"] = np.array([float(f.cx) if c else val(f.x1, inf) for f, c in zip(fixtures, cyl)])
    out["y0"] = np.array([float(f.cy) if c else val(f.y0, -inf) for f, c in zip(fixtures, cyl)])
    out["y1"] = np.array([float(f.cy) if c else val(f.y1, inf) for f, c in zip(fixtures, cyl)])
    out["grow"] = np.array([float(f.radius) if c else 0.0 for f, c in zip(fixtures, cyl)])
    return out


@dataclass
class Pair:
    """One part and fixture's candidates (:class:`Screened`): ``cand`` per motion, ``key`` per motion a lower
    bound of their distance (the float ``g``: horizontal distance less ``thr``; or, ``grid`` set, the exact
    integer squared horizontal distance at the scale ``grid`` of the columns, less nothing), ``thr`` the radius
    sum (the part's, plus a cylinder fixture's)."""

    part: Part
    fixture: Any
    cand: np.ndarray
    key: np.ndarray
    thr: Fraction
    grid: int = 0
    _c: Fraction | None = None
    _limit: float | int = 0

    def far(self, k: int, c: Fraction | None) -> bool:
        """Whether motion ``k`` cannot come closer than the least clearance ``c``: on the grid exactly the exact
        proof's box test (``SolidsChecker._far``), else with the margin :data:`EPS`."""
        if c is None or c < 0:
            return False
        if c != self._c:  # the threshold once per change of the least clearance
            self._c = c
            self._limit = _ceil((c + self.thr) ** 2 * self.grid * self.grid) if self.grid else float(c) + EPS
        return bool(self.key[k] >= self._limit)


def _ceil(q: Fraction) -> int:
    return -((-q.numerator) // q.denominator)


@dataclass
class Screened:
    """What the screen left for the exact proof: ``hit`` (per motion: a part may meet a fixture, or the motion
    is not screened: the full exact proof, in program order) and per pair (:class:`Pair`) the other motions
    that may come closer than the pair's least clearance so far (the exact proof of the pair alone, nearest
    first, decides them: none of them can meet the fixture)."""

    hit: np.ndarray
    pairs: list[Pair] = field(default_factory=list)


def needs_exact(segs: Sequence[Segment], axes: tuple[int, int, int], parts: tuple[Part, ...],
                fixtures: Sequence[Any], best: Callable[[Part, Any], Fraction | None]) -> Screened:
    """The screen of ``segs`` (straight motions, all with the assembly ``parts``).  ``best(part, fixture)``:
    the least clearance of the pair so far (None: none yet)."""
    n = len(segs)
    ix, iy, iz = axes
    start = np.array([[float(s.start[ix]), float(s.start[iy]), float(s.start[iz])] for s in segs]).reshape(n, 3)
    end = np.array([[float(s.end[ix]), float(s.end[iy]), float(s.end[iz])] for s in segs]).reshape(n, 3)
    length = np.array([float(s.tool_length) for s in segs])
    return _needs(start, end, length, parts, fixtures, best, np.zeros(n, dtype=bool))


def needs_exact_columns(chunk: MotionChunk, a: int, b: int, axes: tuple[int, int, int], parts: tuple[Part, ...],
                        fixtures: Sequence[Any], best: Callable[[Part, Any], Fraction | None]) -> Screened:
    """:func:`needs_exact` of rows ``a..b`` of a column chunk (integers at ``10**-scale``; converted to the
    nearest float, exact for integers below 2**53); rows that are not straight motions are always ``hit``."""
    assert chunk.scale is not None and chunk.kind is not None and chunk.start is not None
    assert chunk.end is not None and chunk.tool_length is not None
    den = float(10**chunk.scale)
    cols = list(axes)
    start_i, end_i = np.asarray(chunk.start[a:b]), np.asarray(chunk.end[a:b])
    start = start_i[:, cols].astype(np.float64) / den
    end = end_i[:, cols].astype(np.float64) / den
    length = np.asarray(chunk.tool_length[a:b], dtype=np.float64) / den
    kinds = np.asarray(chunk.kind[a:b])
    straight = np.isin(kinds, [k.value for k in (SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.DWELL)])
    others = [k for k in range(start_i.shape[1]) if k not in cols]
    if others:  # a motion of another axis is not modelled: the exact proof says so
        straight &= (start_i[:, others] == end_i[:, others]).all(axis=1)
    grid = _needs_grid(start_i[:, cols].astype(np.int64), end_i[:, cols].astype(np.int64),
                       np.asarray(chunk.tool_length[a:b], dtype=np.int64), 10**chunk.scale, parts, fixtures, best,
                       ~straight)
    if grid is not None:
        return grid
    big = (np.abs(start_i[:, cols]) >= 2**53).any(axis=1) | (np.abs(end_i[:, cols]) >= 2**53).any(axis=1)
    return _needs(start, end, length, parts, fixtures, best, ~straight | big)


def _needs(start: np.ndarray, end: np.ndarray, length: np.ndarray, parts: tuple[Part, ...],
           fixtures: Sequence[Any], best: Callable[[Part, Any], Fraction | None], hit: np.ndarray) -> Screened:
    lo, hi = np.minimum(start, end), np.maximum(start, end)
    hit = hit | ~(np.isfinite(start).all(axis=1) & np.isfinite(end).all(axis=1)
                  & (np.abs(start).max(axis=1) < LIMIT) & (np.abs(end).max(axis=1) < LIMIT)
                  & (np.abs(length) < LIMIT))
    fx = _fixture_arrays(fixtures)
    # horizontal gap from the box of the controlled point to each fixture's section: (n, fixtures)
    gx = np.maximum(0.0, np.maximum(lo[:, :1] - fx["x1"][None, :], fx["x0"][None, :] - hi[:, :1]))
    gy = np.maximum(0.0, np.maximum(lo[:, 1:2] - fx["y1"][None, :], fx["y0"][None, :] - hi[:, 1:2]))
    gap = np.hypot(gx, gy) - fx["grow"][None, :]
    near: list[tuple[Part, Any, np.ndarray, np.ndarray]] = []
    for part in parts:
        shift = 0.0 if part.spindle else -length
        zlo = lo[:, 2] + float(part.z0) + shift
        zhi = hi[:, 2] + float(part.z1) + shift
        apart = (zlo[:, None] >= fx["z1"][None, :] + EPS) | (zhi[:, None] <= fx["z0"][None, :] - EPS)
        r = float(part.radius)
        for k, f in enumerate(fixtures):
            g = gap[:, k] - r  # a lower bound (up to rounding) of the part's distance to the fixture
            hit |= ~apart[:, k] & (g < EPS)
            c = best(part, f)
            limit = np.inf if c is None or c < 0 else float(c) + EPS
            near.append((part, f, ~apart[:, k] & (g < limit), g))
    out = Screened(hit)
    out.pairs = [Pair(part, f, cand & ~hit, g, _radius_sum(part, f)) for part, f, cand, g in near
                 if (cand & ~hit).any()]
    return out


def _radius_sum(part: Part, f: Any) -> Fraction:
    return part.radius + f.radius if isinstance(f, FixtureCylinder) else part.radius


#: grid integers the exact screen accepts (their differences squared and summed stay below 2**63)
_GRID_LIMIT = 2**30
#: a threshold beyond int64 is capped here: every squared distance (below 2**63 - 2**33) is below it, so the
#: motion stays undecided (sound)
_CAP = 2**63 - 1


def _on_grid(v: Fraction | None, den: int, unbounded: int) -> int | None:
    """``v * den`` as an integer (``unbounded`` for None), None when not an integer or too large."""
    if v is None:
        return unbounded
    q = v * den
    if q.denominator != 1 or abs(q.numerator) >= _GRID_LIMIT:
        return None
    return q.numerator


def _needs_grid(start: np.ndarray, end: np.ndarray, length: np.ndarray, den: int, parts: tuple[Part, ...],
                fixtures: Sequence[Any], best: Callable[[Part, Any], Fraction | None],
                hit: np.ndarray) -> Screened | None:
    """The screen in exact integers at the columns' scale (``den = 10**scale``): every decision the same as
    the exact proof's own box tests (no margin needed).  None when a value is off the grid or too large."""
    big = 2**62
    if len(length) == 0 or max(int(np.abs(start).max()), int(np.abs(end).max()), int(np.abs(length).max())) \
            >= _GRID_LIMIT:
        return None
    grid: list[list[int]] = []
    for f in fixtures:
        if isinstance(f, FixtureCylinder):
            vals = [_on_grid(f.cx, den, 0), _on_grid(f.cx, den, 0), _on_grid(f.cy, den, 0), _on_grid(f.cy, den, 0)]
        else:
            vals = [_on_grid(f.x0, den, -big), _on_grid(f.x1, den, big), _on_grid(f.y0, den, -big),
                    _on_grid(f.y1, den, big)]
        vals += [_on_grid(f.z0, den, -big), _on_grid(f.z1, den, big)]
        if any(v is None for v in vals):
            return None
        grid.append(vals)  # type: ignore[arg-type]
    g = np.array(grid, dtype=np.int64).reshape(len(fixtures), 6)
    lo, hi = np.minimum(start, end), np.maximum(start, end)
    gx = np.maximum(0, np.maximum(lo[:, :1] - g[None, :, 1], g[None, :, 0] - hi[:, :1]))
    gy = np.maximum(0, np.maximum(lo[:, 1:2] - g[None, :, 3], g[None, :, 2] - hi[:, 1:2]))
    gap2 = gx * gx + gy * gy  # exact: each term below 2**62
    pairs: list[Pair] = []
    for part in parts:
        pz = [_on_grid(part.z0, den, 0), _on_grid(part.z1, den, 0)]
        if pz[0] is None or pz[1] is None:
            return None
        shift = np.zeros_like(length) if part.spindle else -length
        zlo, zhi = lo[:, 2] + pz[0] + shift, hi[:, 2] + pz[1] + shift
        # the exact proof's height test: no t with z + lo < f.z1 and z + hi > f.z0
        apart = (zlo[:, None] >= g[None, :, 5]) | (zhi[:, None] <= g[None, :, 4])
        for k, f in enumerate(fixtures):
            thr = _radius_sum(part, f)
            t2 = _ceil(thr * thr * den * den)  # an integer x is below q exactly when it is below ceil(q)
            hit |= ~apart[:, k] & (gap2[:, k] < min(t2, _CAP))  # the box of the path meets the grown fixture
            c = best(part, f)
            if c is None or c < 0:
                cand = ~apart[:, k]
            else:
                cand = ~apart[:, k] & (gap2[:, k] < min(_ceil((c + thr) ** 2 * den * den), _CAP))
            pairs.append(Pair(part, f, cand, gap2[:, k], thr, den))
    out = Screened(hit)
    for p in pairs:
        p.cand = p.cand & ~hit
    out.pairs = [p for p in pairs if p.cand.any()]
    return out


def group_by_tool(segs: Sequence[Segment]) -> Mapping[int | None, list[int]]:
    """Indexes of ``segs`` per tool register (the assembly)."""
    out: dict[int | None, list[int]] = {}
    for k, s in enumerate(segs):
        out.setdefault(s.tool_register, []).append(k)
    return out
