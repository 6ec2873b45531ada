"""Runs of plain lines under a Fanuc coordinate rotation (G68) or scaling (G51), in columns (issue 36).

The vectorized fast path (:mod:`nczones.gcode.fastpath`, ``_fast_run``) computes a run's positions as scaled
``int64`` columns (``10**S``).  While one programmable transform is active it computes them in the *program*
system instead (the program point, no offsets: what ``FanucInterpreter._program_point`` reads) and this module
maps those program points to machine points exactly as ``FanucInterpreter._transform_target`` and
:mod:`nczones.gcode.fanuc.transforms` do, a column at a time:

* **scaling** (G51, P or I/J/K, a negative factor mirrors): ``centre + factor (p - centre)`` is rational; in
  scaled integers ``N = c fd + fn (p - c)`` is the point times the factor's denominator ``fd``, and the point
  is rounded to the increment ``st`` halves away from zero, ``sign(N) floor((2|N| + fd st) / (2 fd st))`` (what
  :func:`~nczones.gcode.fanuc.expr.round_to` does with an exact rational), which leaves a point on the grid as
  it is; a coordinate at its centre or of factor 1 is not moved (``transforms.scale``).  Exact integer
  arithmetic, with every magnitude checked below ``2**61`` first (else the lane declines).
* **rotation** (G68): the rotated coordinate ``u = (x cos a - y sin a) / st`` (and ``x sin a + y cos a``) is
  computed in doubles from the doubles ``c``, ``s`` nearest the midpoints of the exact core's enclosures of
  ``cos a``, ``sin a`` (``transforms.cos_sin_enclosure``) and taken where a float screen proves it is the
  general path's (below); every other coordinate is computed by ``transforms.rotate`` itself (exact
  rationals), and a point it finds uncertain (``PointNotCertain``: the general path's ``unknown``) cuts the
  run before its line.

Soundness of the rotation screen (review42)
-------------------------------------------
Notation: ``x = p_a - c_a``, ``y = p_b - c_b`` the scaled program coordinates about the centre (exact ``int64``
differences: ``|p| + |centre| < 2**60`` is checked first), ``|x|, |y| < 2**50`` and the increment ``st``
(``0.001`` mm, ``0.0001`` in ``= 0.00254`` mm, ..., times ``10**S``) ``< 2**50`` (both checked, else the lane
declines), so ``x``, ``y``, ``st`` and ``|x| + |y|`` are exact doubles; ``eps = 2**-53``; ``c``, ``s`` doubles
with ``|c|, |s| <= 1`` (their enclosures are far narrower than ``eps``).  The general path
(``transforms._coordinate``) takes the interval ``[L, H]`` of ``U = (x c' - y s') / st`` over ``c'``, ``s'`` in
the enclosures and rounds to the integer ``k`` with no tie ``j + 1/2`` in ``[L - g, H + g]`` (``g =
TIE_GUARD``), else raises.  The screen (its margins ``GUARD``, ``ROUNDING``, ``QUOTIENT`` are in
:mod:`~nczones.gcode.fanuc.transform_points`, whose ``PointMap.rotated`` is the same screen a point at a
time) computes ``q = fl(fl(fl(x c) - fl(y s)) / st)`` and accepts ``k =
floor(q) + (frac > 1/2)`` when ``|frac - 1/2| > err + |q| 2**-50 + G`` (all in doubles).  The terms:

1. *Enclosure*: ``|U - (x c - y s) / st| <= (|x| + |y|) far / st`` for every ``U`` in ``[L, H]``, ``far`` the
   greatest distance of ``c``/``s`` from an end of its enclosure; ``delta = nextafter(fl(far), inf) (1 +
   2**-40) > far`` (``fl(far)`` is within half an ulp of ``far``; ``far = 0``: ``delta = 2**-1074``).
2. *Evaluation*: two products (``eps |x c| <= eps |x|``, ``eps |y|``), the difference (``eps |d|``) and the
   quotient (``eps |d| / st``, ``|d| / st <= |q| / (1 - eps)``): ``|q - (x c - y s) / st| <= eps (|x| + |y|) /
   st + 2 eps |q| (1 + 2 eps)``; an underflow adds at most ``2**-1074`` per operation.  The screen charges
   ``2**-51 (|x| + |y|) / st`` (in ``err``) and ``2**-50 |q|``: four times these.
3. *Its own arithmetic*: ``err = fl((|x| + |y|) fl(fl(delta + 2**-51) / st))`` is at least ``(|x| + |y|) (delta +
   2**-51) / st (1 - eps)**3``, the loss below term 2's spare ``3 eps (|x| + |y|) / st`` (``delta < 1``);
   ``|q| 2**-50`` is exact (a power of two); the two additions of the right side lose at most ``eps`` of it
   each, at most ``2**-53`` in all where it matters (a right side of ``1/2`` or more accepts nothing).
4. *The distance*: ``floor(q)`` is exact, ``frac = fl(q - floor(q))`` exact (Sterbenz) but for ``-1/2 < q < 0``
   (``1 - |q|`` rounded by at most ``2**-54``, perhaps to ``1.0``: then ``floor(q) + 1 = 0``, still the nearest
   integer), ``fl(frac - 1/2)`` exact for ``frac >= 1/4``, else off by at most ``2**-55``: the computed distance
   is within ``2**-53`` of ``q``'s distance to the nearest tie.
5. *The guard*: ``G = fl(fl(g) (1 + 2**-20)) + 2**-40 > g + 2**-41``, above ``g`` by far more than terms 3 and
   4's ``2**-52`` (and any underflow's).

So an accepted ``q`` lies farther than ``(|x| + |y|) far / st + (term 2) + g`` from every tie; by 1 and 2 every
point of ``[L - g, H + g]`` lies between the same two ties as ``q``: the general path rounds to ``q``'s nearest
integer, the screen's ``k``, and the machine coordinate is ``c_a + k st`` in both.  The other coordinate is the
same argument with ``x s + y c``.  G91 (the program point a running sum of exact integers), inch (``st =
254 * 10**(S - 5)``) and an arc's centre (the program start plus I/J, mapped as a point) enter only through
``x``, ``y`` and ``st``.  Checked by ``tests/gcode/fanuc/test_transform_screen.py`` (points constructed within
ulps of the screen's and the general path's edges, the general path as the oracle on every point).

Arcs (I/J/K in the plane; an R arc declines): their centre, the program start plus the offsets, is mapped like
a point (``_transformed_arc``); a rotation in another plane than the arc's, unequal scale factors of the plane's
two axes (an ellipse) decline, and an odd number of negative factors on them reverses the direction.

Declined (the fast path then leaves the run to the general path, which decides as before): more than one
transform, a mirror image (G51.1), polar coordinates (G16), the first move after a transform's block, a lathe,
tracked parameter ranges, absolute arc centres.  ``tests/gcode/fanuc/test_transform_columns.py`` holds the lane
to the general path alone.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from ...precompiled import dataclass  # start-up: no dataclasses import

# the screen's numbers, shared with the box route (transform_points)
from .transform_points import FLOAT_EXACT as _FLOAT_EXACT
from .transform_points import GUARD as _GUARD
from .transform_points import QUOTIENT as _QUOTIENT
from .transform_points import ROUNDING as _ROUNDING
from .transform_points import rotation_doubles as _doubles
from .transforms import PointNotCertain, Rotation, Scaling, rotate

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["ColumnTransform", "column_transform"]

#: Magnitudes (scaled integers) the scaling's products stay below (the rotation's: ``transform_points``).
_INT_LIMIT = 2**61
#: The magnitude a program coordinate plus a centre, and a machine coordinate (with its offset), stay below
#: (``int64`` holds ``2**63``: no sum of two such ever wraps; the fast path's own state bound is ``2**59``).
_OUT_LIMIT = 2**60


@dataclass(frozen=True, slots=True)
class ColumnTransform:
    """The one active transform the lane mirrors: ``rotation`` or ``scaling`` (the other None), the increment a
    transformed point is rounded to (``step``, mm) and the offsets (``off``, machine = transformed + off)."""

    rotation: Rotation | None
    scaling: Scaling | None
    step: Fraction
    off: tuple[Fraction, ...]

    @property
    def numbers(self) -> tuple[Fraction, ...]:
        """The numbers the run's scale must hold exactly: the increment, the centre(s), the offsets."""
        centre = (self.rotation.ca, self.rotation.cb) if self.rotation is not None else \
            self.scaling.centre if self.scaling is not None else ()
        return (self.step, *centre, *self.off)


def column_transform(rotation: Rotation | None, scaling: Scaling | None, step: Fraction,
                     off: tuple[Fraction, ...]) -> ColumnTransform | None:
    """The lane's transform, None unless exactly one of ``rotation``, ``scaling`` is given."""
    if (rotation is None) == (scaling is None):
        return None
    return ColumnTransform(rotation, scaling, step, off)


def arcs_plane_ok(xf: ColumnTransform, ia: int, ib: int) -> bool:
    """Whether the lane maps arcs in the plane of axes ``ia``, ``ib`` (module docstring)."""
    if xf.rotation is not None:
        return {xf.rotation.ia, xf.rotation.ib} == {ia, ib}
    assert xf.scaling is not None
    return abs(xf.scaling.factors[ia]) == abs(xf.scaling.factors[ib])


def reverses(xf: ColumnTransform, ia: int, ib: int) -> bool:
    """Whether arcs in the plane ``ia``, ``ib`` change direction (an odd count of negative factors)."""
    if xf.scaling is None:
        return False
    return ((xf.scaling.factors[ia] < 0) + (xf.scaling.factors[ib] < 0)) % 2 == 1


def _scaled(q: Fraction, S: int) -> int:
    v = q * 10**S
    if v.denominator != 1:
        raise ValueError("not on the scale")
    return int(v)


def machine_points(xf: ColumnTransform, P: np.ndarray, S: int) -> tuple[np.ndarray, np.ndarray] | None:
    """The machine points of the program points ``P`` (rows of scaled ``int64``, ``10**S``): ``(M, bad)`` with
    ``bad`` the rows whose point the general path finds uncertain (their ``M`` rows meaningless), or None when
    a magnitude is out of the lane's range (module docstring)."""
    st = _scaled(xf.step, S)
    centre = (xf.rotation.ca, xf.rotation.cb) if xf.rotation is not None else \
        xf.scaling.centre if xf.scaling is not None else ()
    if st >= _FLOAT_EXACT or _magnitude(P) + max((abs(_scaled(c, S)) for c in centre), default=0) >= _OUT_LIMIT:
        return None  # a difference p - centre could wrap (or a centre not even fit int64): the general path
    M = P.copy()
    bad = np.zeros(len(P), dtype=bool)
    if xf.scaling is not None:
        for i, (c, f) in enumerate(zip(xf.scaling.centre, xf.scaling.factors)):
            if f != 1 and not _scale_column(P[:, i], M[:, i], _scaled(c, S), f, st):
                return None
    else:
        assert xf.rotation is not None
        if not _rotate_columns(xf, P, M, bad, st, S):
            return None
    if _magnitude(M) + max((abs(_scaled(o, S)) for o in xf.off), default=0) >= _OUT_LIMIT:
        return None  # a machine coordinate could wrap: the general path
    for i, o in enumerate(xf.off):
        if o:
            M[:, i] += _scaled(o, S)
    return M, bad


def _magnitude(a: np.ndarray) -> int:
    """The largest ``|v|`` of ``a`` as a Python int (no ``int64`` negation that could wrap), 0 when empty."""
    return max(int(a.max()), -int(a.min())) if a.size else 0


def _scale_column(p: np.ndarray, out: np.ndarray, c: int, f: Fraction, st: int) -> bool:
    """``out`` = ``p`` scaled about ``c`` by ``f`` and rounded to ``st`` (module docstring), False when a
    product could leave ``int64``."""
    if not p.size:
        return True
    fn, fd = f.numerator, f.denominator
    d = p - c
    big = max(abs(int(d.max())), abs(int(d.min())))
    if big * abs(fn) + abs(c) * fd >= _INT_LIMIT // 2 or fd * st >= _INT_LIMIT or abs(fn) >= _INT_LIMIT:
        return False
    n = c * fd + fn * d
    den = fd * st
    k = (2 * np.abs(n) + den) // (2 * den)
    out[:] = np.where(d == 0, p, np.where(n < 0, -k, k) * st)
    return True


def _rotate_columns(xf: ColumnTransform, P: np.ndarray, M: np.ndarray, bad: np.ndarray, st: int, S: int) -> bool:
    """The rotated plane columns of ``P`` into ``M``: the float screen, then the exact rotation on the rows it
    leaves (module docstring); False when a coordinate is too large for the screen."""
    rot = xf.rotation
    assert rot is not None
    ia, ib = rot.ia, rot.ib
    ca, cb = _scaled(rot.ca, S), _scaled(rot.cb, S)
    if not len(P):
        return True
    x = P[:, ia] - ca
    y = P[:, ib] - cb
    if max(int(np.abs(x).max()), int(np.abs(y).max())) >= _FLOAT_EXACT:
        return False
    c, s, delta = _doubles(rot.angle)
    xd, yd = x.astype(np.float64), y.astype(np.float64)
    err = (np.abs(xd) + np.abs(yd)) * ((delta + _ROUNDING) / st)
    ka, oka = _nearest((xd * c - yd * s) / st, err)
    kb, okb = _nearest((xd * s + yd * c) / st, err)
    M[:, ia] = ca + ka * st
    M[:, ib] = cb + kb * st
    for r in np.flatnonzero(~(oka & okb)).tolist():
        point = [Fraction(int(v), 10**S) for v in P[r]]
        try:
            got = rotate(rot, point, xf.step)
        except PointNotCertain:
            bad[r] = True
            continue
        M[r, ia], M[r, ib] = _scaled(got[ia], S), _scaled(got[ib], S)
    return True


def _nearest(u: np.ndarray, err: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The nearest integer to each ``u`` and whether it is certain: ``u`` farther from a tie than its error
    ``err`` (in increments, for the quotient's own rounding ``|u| 2**-50`` more) and the tie guard."""
    m = np.floor(u)
    frac = u - m  # exact: |u| < 2**50
    ok = np.abs(frac - 0.5) > err + np.abs(u) * _QUOTIENT + _GUARD
    return (m + (frac > 0.5)).astype(np.int64), ok


def arc_centres(xf: ColumnTransform, pstart: np.ndarray, ca: np.ndarray, cb: np.ndarray, ia: int, ib: int,
                S: int) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """The machine centres of arcs whose program centres are ``(ca, cb)`` (their program starts ``pstart``: the
    other axes of the point ``_transformed_arc`` maps): ``(centre a, centre b, bad)`` or None (out of range)."""
    points = pstart.copy()
    points[:, ia] = ca
    points[:, ib] = cb
    got = machine_points(xf, points, S)
    if got is None:
        return None
    M, bad = got
    return M[:, ia], M[:, ib], bad


def machine_columns(xf: ColumnTransform, pos0: list[int], pend: np.ndarray, rows: np.ndarray, S: int,
                    arcs: Any = None) -> tuple | int | None:
    """The machine start and end columns of a run's motions (``rows``, the lines that move; ``pend`` every
    line's program point; ``pos0`` the scaled machine position before the run) and, given
    ``arcs = (arc mask over rows, program starts of the arcs, centre a, centre b, ia, ib)``, the arcs' machine
    centres: ``(start, end, centre a, centre b)``, the index of the first line the general path must take (a
    point it finds uncertain), or None (out of range)."""
    if max(map(abs, pos0), default=0) >= _OUT_LIMIT:
        return None  # the machine start (its offsets) beyond the lane's range: the general path
    got = machine_points(xf, pend[rows], S)
    if got is None:
        return None
    men, bad = got
    line = int(rows[np.argmax(bad)]) if bad.any() else len(pend)
    cen_a = cen_b = None
    if arcs is not None:
        mask, pst, pa, pb, ia, ib = arcs
        cen = arc_centres(xf, pst, pa, pb, ia, ib, S)
        if cen is None:
            return None
        cen_a, cen_b, cbad = cen
        if cbad.any():
            line = min(line, int(rows[np.flatnonzero(mask)[np.argmax(cbad)]]))
    if line < len(pend):
        return line
    mst = np.vstack((np.array(pos0, dtype=np.int64)[None, :], men[:-1])) if len(men) else men
    return mst, men, cen_a, cen_b
