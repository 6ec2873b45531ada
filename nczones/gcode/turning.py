"""Lathe cycles as the control generates them: finishing shapes and their passes, exactly.

The lathe interpreters (:mod:`nczones.gcode.fanuc.lathe` for Fanuc lathes, the LinuxCNC interpreter for
``G70``-``G72``) read a cycle block and, for the cycles with a finishing shape, the shape's blocks; this
module turns them into :class:`Move` values — rapid, feed and arc moves in **program coordinates** of the
ZX plane, radius values in millimetres — each with a label naming the pass (``"roughing pass 6: cut"``).
The interpreter adds the offsets and emits them as segments with the span of the cycle block, so a
counterexample reads "G71 at line 14, roughing pass 6: cut".  Every algorithm, with its sources, is in
``specs/turning.md``.

Coordinates are pairs ``(z, x)`` of ``Fraction`` (``x`` a radius).  Points the control computes (a
roughing level meeting a slanted or curved shape, a G73 division, a G76 infeed) are rounded to the
control's least increment on each axis, halves away from zero, as the Fanuc dialect rounds every
computed position (``specs/fanuc.md``); the rounding of an irrational value is decided exactly
(:func:`round_surd`).  What the manuals leave open is never guessed: :class:`CycleUnknown` carries the
reason, and the interpreter makes the result ``unknown``.

Invariants
----------
* Every coordinate of every move is an exact ``Fraction``; no float is used.
* A generated path is continuous: each move starts where the previous one ended, the first at the
  cycle's start point.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from fractions import Fraction

from ..motion import SegmentKind
from ..precompiled import dataclass, replace  # start-up: no dataclasses import
from .passes import PassGuard

__all__ = ["Element", "Move", "CycleUnknown", "round_to_grid", "round_surd", "rough_cycle", "pattern_cycle",
           "finish_moves", "turning_cycle", "thread_chamfer", "peck_cycle", "thread_cycle_g76", "Pt"]

Pt = tuple[Fraction, Fraction]  # (z, x)
_ZERO = Fraction(0)
_HALF = Fraction(1, 2)


class CycleUnknown(Exception):
    """The control's path for this cycle is not modelled (the message says why)."""


@dataclass(frozen=True, slots=True)
class Element:
    """One element of a finishing shape (or any programmed ZX move), program coordinates.

    ``kind``: RAPID, LINE or ARC; an arc has an exact ``centre`` and ``clockwise`` (as seen in G18,
    the LinuxCNC ARC_FEED convention of :mod:`nczones.motion`: first axis Z, second X).  ``line`` is the
    source line of its block.
    """

    kind: SegmentKind
    start: Pt
    end: Pt
    centre: Pt | None = None
    clockwise: bool = False
    line: int = 0
    feed: Fraction | None = None

    def moved(self, dz: Fraction, dx: Fraction) -> Element:
        c = None if self.centre is None else (self.centre[0] + dz, self.centre[1] + dx)
        return replace(self, start=(self.start[0] + dz, self.start[1] + dx),
                       end=(self.end[0] + dz, self.end[1] + dx), centre=c)


@dataclass(frozen=True, slots=True)
class Move:
    """One generated move: to ``end`` (program coordinates), an arc with ``centre``; ``label`` names the pass."""

    kind: SegmentKind
    end: Pt
    label: str
    centre: Pt | None = None
    clockwise: bool = False
    dwell_s: Fraction | None = None
    #: The feed of this move and the ones after it (G70 uses the shape's F words), None: the cycle's.
    feed: Fraction | None = None
    #: A thread: the feed follows the spindle (no feed rate of its own).
    synced: bool = False


# --------------------------------------------------------------------------- exact rounding


def round_to_grid(v: Fraction, step: Fraction) -> Fraction:
    """``v`` rounded to a multiple of ``step``, halves away from zero.

    >>> round_to_grid(Fraction(5, 4000), Fraction(1, 1000)), round_to_grid(Fraction(-3, 2000), Fraction(1, 1000))
    (Fraction(1, 1000), Fraction(-1, 500))
    """
    q = v / step
    n = math.floor(abs(q) + _HALF)
    return (n if q >= 0 else -n) * step


def _sign_surd(a: Fraction, b: Fraction, d: Fraction) -> int:
    """The sign of ``a + b * sqrt(d)`` (``d >= 0``), exactly."""
    if b == 0 or d == 0:
        return (a > 0) - (a < 0)
    sb = 1 if b > 0 else -1
    if a == 0:
        return sb
    sa = 1 if a > 0 else -1
    if sa == sb:
        return sa
    # opposite signs: compare a^2 with b^2 d
    lhs, rhs = a * a, b * b * d
    if lhs == rhs:
        return 0
    return sa if lhs > rhs else sb


def round_surd(a: Fraction, b: Fraction, d: Fraction, step: Fraction) -> Fraction:
    """``a + b * sqrt(d)`` rounded to a multiple of ``step``, halves away from zero, decided exactly.

    >>> round_surd(Fraction(0), Fraction(1), Fraction(2), Fraction(1, 1000))  # sqrt(2) = 1.41421...
    Fraction(707, 500)
    >>> round_surd(Fraction(1), Fraction(-1), Fraction(1, 4), Fraction(1))  # 0.5: a half, away from zero
    Fraction(1, 1)
    """
    if b == 0 or d == 0:
        return round_to_grid(a, step)
    approx = (float(a) + float(b) * math.sqrt(float(d))) / float(step)
    k = math.floor(approx)
    # the exact floor of v/step, near k: v/step - n >= 0 decides
    for _ in range(4):
        if _sign_surd(a - k * step, b, d) < 0:
            k -= 1
        elif _sign_surd(a - (k + 1) * step, b, d) >= 0:
            k += 1
        else:
            break
    else:  # pragma: no cover - float estimate off by more than a few steps
        lo, hi = k - 10**6, k + 10**6
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if _sign_surd(a - mid * step, b, d) >= 0:
                lo = mid
            else:
                hi = mid
        k = lo
    # v/step in [k, k+1): compare with k + 1/2
    s = _sign_surd(a - (k + _HALF) * step, b, d)
    if s > 0 or (s == 0 and k >= 0):
        return (k + 1) * step
    return k * step


# --------------------------------------------------------------------------- shapes in a normalised frame


@dataclass(frozen=True, slots=True)
class _Frame:
    """The frame in which a roughing cycle cuts towards decreasing ``c`` and steps towards decreasing ``h``.

    ``swap``: the cut axis is X (G72); ``sc``, ``sh``: the signs that make the directions negative.
    Normalised coordinates are ``(c, h) = (sc * cut, sh * depth)``.
    """

    swap: bool
    sc: int
    sh: int

    def to(self, p: Pt) -> Pt:
        cut, depth = (p[1], p[0]) if self.swap else p
        return (self.sc * cut, self.sh * depth)

    def back(self, p: Pt) -> Pt:
        cut, depth = self.sc * p[0], self.sh * p[1]
        return (depth, cut) if self.swap else (cut, depth)

    def clockwise(self, cw: bool) -> bool:
        """An arc's direction in the frame (each reflection and the swap reverse it)."""
        flips = (self.sc < 0) + (self.sh < 0) + self.swap
        return cw if flips % 2 == 0 else not cw


def _arc_centre_sweep(e: Element) -> tuple[Pt, bool]:
    assert e.centre is not None
    return e.centre, e.clockwise


def _cross(o: Pt, a: Pt, b: Pt) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _level_crossings(elements: Sequence[Element], level: Fraction) -> list[tuple]:
    """Where a closed boundary (frame coordinates) crosses the level ``h = level - 0`` (the region just below
    the level): a line counts when ``min h < level <= max h``; an arc at each of its points at the level where it
    passes through, or ends coming from below / starts going down.  Each crossing is ``(kind, a, b, d)``, its
    c = ``a + b * sqrt(d)``, exact."""
    out: list[tuple] = []
    for e in elements:
        (c1, h1), (c2, h2) = e.start, e.end
        if e.kind is not SegmentKind.ARC:
            if h1 != h2 and min(h1, h2) < level <= max(h1, h2):
                out.append(("line", c1 + (c2 - c1) * (level - h1) / (h2 - h1), _ZERO, _ZERO))
            continue
        assert e.centre is not None
        cc, hc = e.centre
        r2 = (c1 - cc) ** 2 + (h1 - hc) ** 2
        dh = level - hc
        disc = r2 - dh * dh
        if disc < 0 or (disc == 0 and dh < 0):
            continue  # missed, or touching at the circle's bottom (the arc is above the level around it)
        if disc == 0:
            # touching at the circle's top: inside the arc two crossings of the region just below cancel; at an
            # end point the arc comes up to it (or leaves down from it) on one side only: one crossing
            top = (cc, level)
            if top in (e.start, e.end) and e.start != e.end:
                out.append(("arc", cc, _ZERO, _ZERO))
            continue
        for sgn in (Fraction(1), Fraction(-1)):
            if not _point_on_arc(e.centre, e.start, e.end, e.clockwise, sgn, disc, dh):
                continue
            # the arc's vertical speed at the point (moving ccw in the (c, h) plane: dh/dt = c - cc)
            vh = sgn if not e.clockwise else -sgn  # sign of (c - cc) = sgn, reversed for clockwise
            at_start = h1 == level and _sign_surd(c1 - cc, -sgn, disc) == 0
            at_end = h2 == level and _sign_surd(c2 - cc, -sgn, disc) == 0
            if at_start and at_end:
                out.append(("arc", cc, sgn, disc))  # a full circle through the point
            elif at_start:
                if vh < 0:  # leaves the point downwards: below the level next to it
                    out.append(("arc", cc, sgn, disc))
            elif at_end:
                if vh > 0:  # arrives from below
                    out.append(("arc", cc, sgn, disc))
            else:
                out.append(("arc", cc, sgn, disc))
    return out


def _point_on_arc(centre: Pt, s: Pt, e: Pt, cw: bool, sgn: Fraction, d: Fraction, dh: Fraction) -> bool:
    """The circle point ``centre + (sgn * sqrt(d), dh)`` lies on the arc (with its end points)."""
    # write the point's offset as (z, a + b sqrt d): here z-part is the surd, so swap roles:
    # p = (sgn sqrt d, dh); use the cross/dot tests with p0 = sgn sqrt d.
    vs = (s[0] - centre[0], s[1] - centre[1])
    ve = (e[0] - centre[0], e[1] - centre[1])
    if cw:
        vs, ve = ve, vs

    def cross(u: Pt) -> int:  # u x p = u0 * dh - u1 * sgn sqrt d
        return _sign_surd(u[0] * dh, -u[1] * sgn, d)

    def dot(u: Pt) -> int:  # u . p = u0 sgn sqrt d + u1 dh
        return _sign_surd(u[1] * dh, u[0] * sgn, d)

    def half_p(u: Pt) -> int:
        c = cross(u)
        if c != 0:
            return 0 if c > 0 else 1
        return 0 if dot(u) > 0 else 1

    def half_v(u: Pt, v: Pt) -> int:
        c = u[0] * v[1] - u[1] * v[0]
        if c != 0:
            return 0 if c > 0 else 1
        return 0 if u[0] * v[0] + u[1] * v[1] > 0 else 1

    if s == e:
        return True  # a full circle
    hp, he = half_p(vs), half_v(vs, ve)
    if hp != he:
        return hp < he
    # same half: p before or at ve iff p x ve >= 0
    # p x ve = sgn sqrt d * ve1 - dh * ve0
    return _sign_surd(-dh * ve[0], sgn * ve[1], d) >= 0


def _surd_value(k: tuple[str, Fraction, Fraction, Fraction]) -> float:
    _kind, a, b, d = k
    return float(a) + float(b) * math.sqrt(float(d))


def _surd_compare(x: tuple, y: tuple) -> int:
    """Exact comparison of two crossing values ``a + b sqrt(d)`` (different d: by squaring)."""
    _k1, a1, b1, d1 = x
    _k2, a2, b2, d2 = y
    if b1 == 0 or d1 == 0:
        return -_sign_surd(a2 - a1, b2, d2) if not (b2 == 0 or d2 == 0) else ((a1 > a2) - (a1 < a2))
    if b2 == 0 or d2 == 0:
        return _sign_surd(a1 - a2, b1, d1)
    if d1 == d2:
        return _sign_surd(a1 - a2, b1 - b2, d1)
    # a + b1 r1 - b2 r2 with two surds: sign by isolating (exact squaring)
    a = a1 - a2
    # sign(a + b1 r1 - b2 r2): let u = a + b1 r1 (sign su), compare u with b2 r2
    su = _sign_surd(a, b1, d1)
    sv = (b2 > 0) - (b2 < 0)
    if su != sv:
        return su if su != 0 else -sv
    # same sign: compare u^2 = a^2 + b1^2 d1 + 2 a b1 r1 with b2^2 d2
    lhs = _sign_surd(a * a + b1 * b1 * d1 - b2 * b2 * d2, 2 * a * b1, d1)
    return su * lhs


def _max_crossing(xs: list[tuple]) -> tuple:
    best = xs[0]
    for x in xs[1:]:
        if _surd_compare(x, best) > 0:
            best = x
    return best


def _sorted_desc(xs: list[tuple]) -> list[tuple]:
    import functools

    def desc(p: tuple, q: tuple) -> int:
        return -_surd_compare(p, q)

    return sorted(xs, key=functools.cmp_to_key(desc))


# --------------------------------------------------------------------------- G71 / G72


def _shape_check(elements: Sequence[Element], frame: _Frame, type_one: bool, code: str) -> None:
    """Fanuc's conditions on the finishing shape (frame coordinates): c never increases along it; for
    type I, h never decreases either (0i-TD alarms PS0064/PS0065 otherwise)."""
    for e in elements:
        s, t = frame.to(e.start), frame.to(e.end)
        if e.kind is SegmentKind.ARC:
            assert e.centre is not None
            c = frame.to(e.centre)
            cw = frame.clockwise(e.clockwise)
            fe = Element(e.kind, s, t, c, cw, e.line)
            # the arc's extreme points in c and h must not lie strictly inside it where they reverse monotonicity
            r2 = (s[0] - c[0]) ** 2 + (s[1] - c[1]) ** 2
            for dz, dh, what in ((1, 0, "c"), (-1, 0, "c"), (0, 1, "h"), (0, -1, "h")):
                # point centre + r * (dz, dh); r may be irrational: use d = r2
                if dz:
                    inside = _point_on_arc(c, s, t, cw, Fraction(dz), r2, _ZERO)
                    p_is_end = (s[0] - c[0]) * dz > 0 and s[1] == c[1] or (t[0] - c[0]) * dz > 0 and t[1] == c[1]
                else:
                    inside = _point_on_arc_h(c, s, t, cw, Fraction(dh), r2)
                    p_is_end = (s[1] - c[1]) * dh > 0 and s[0] == c[0] or (t[1] - c[1]) * dh > 0 and t[0] == c[0]
                if inside and not p_is_end and (what == "c" or type_one):
                    raise CycleUnknown(
                        f"{code}: the finishing shape is not monotonic along {'Z' if (what == 'c') != frame.swap else 'X'} "
                        f"(the arc of line {e.line} turns back); the control alarms (PS0064/PS0065){_type2_hint(type_one, what)}")
            del fe
            chk_s, chk_t = s, t
        else:
            chk_s, chk_t = s, t
        if chk_t[0] > chk_s[0]:
            raise CycleUnknown(f"{code}: the finishing shape turns back along {'X' if frame.swap else 'Z'} at line "
                               f"{e.line}; the control alarms (PS0065)")
        if type_one and chk_t[1] < chk_s[1]:
            raise CycleUnknown(f"{code}: type I needs a monotonic finishing shape, but it turns back along "
                               f"{'Z' if frame.swap else 'X'} at line {e.line}; the control alarms (PS0064); "
                               "a first shape block that moves both axes selects type II")


def _type2_hint(type_one: bool, what: str) -> str:
    return "; a first shape block that moves both axes selects type II" if type_one and what == "h" else ""


def _point_on_arc_h(centre: Pt, s: Pt, e: Pt, cw: bool, dh: Fraction, r2: Fraction) -> bool:
    """The circle point ``centre + (0, dh * r)`` (r = sqrt(r2)) lies on the arc."""
    vs = (s[0] - centre[0], s[1] - centre[1])
    ve = (e[0] - centre[0], e[1] - centre[1])
    if cw:
        vs, ve = ve, vs
    if s == e:
        return True

    # p = (0, dh r): u x p = u0 dh r ; u . p = u1 dh r
    def half_p(u: Pt) -> int:
        c = _sign_surd(_ZERO, u[0] * dh, r2)
        if c != 0:
            return 0 if c > 0 else 1
        return 0 if _sign_surd(_ZERO, u[1] * dh, r2) > 0 else 1

    def half_v(u: Pt, v: Pt) -> int:
        c = u[0] * v[1] - u[1] * v[0]
        if c != 0:
            return 0 if c > 0 else 1
        return 0 if u[0] * v[0] + u[1] * v[1] > 0 else 1

    hp, he = half_p(vs), half_v(vs, ve)
    if hp != he:
        return hp < he
    # p x ve = 0 * ve1 - dh r ve0
    return _sign_surd(_ZERO, -dh * ve[0], r2) >= 0


def rough_cycle(code: str, start: Pt, approach: Element, shape: Sequence[Element], *, facing: bool,
                depth: Fraction, retract: Fraction, allowance: Pt, type_one: bool, infeed_rapid: bool,
                final_pass: bool, grid: Pt, guard: PassGuard | None = None) -> list[Move]:
    """The moves of Fanuc's G71 (``facing=False``) or G72 (``facing=True``) roughing cycle.

    Parameters
    ----------
    start : (z, x)
        The start point A (where the tool stands at the cycle block).
    approach : Element
        The shape's first block: the move from A to A'.
    shape : sequence of Element
        The finishing shape from A' to B (program coordinates).
    depth, retract : Fraction
        The depth of cut Δd and the escape e (radius values).
    allowance : (z, x)
        The finishing allowance (Δw, Δu/2): the shape is moved by it.
    type_one : bool
        Type I (the first block moves only the depth axis) or type II.
    infeed_rapid : bool
        The first block is G00 (the infeeds are rapid), else G01 (feed).
    final_pass : bool
        End with a cut along the moved shape (parameter 5102#2 RF1 = 0).
    grid : (z, x)
        The least increment per axis (radius on a diameter axis).

    Invariant: the levels are ``h(A) - k * depth`` (k = 1, 2, ...) above the lowest point of the moved
    shape; each roughing pass infeeds at A's cut coordinate, cuts to where the level meets the moved shape
    (or the end of the shape, when the level is above it), escapes by ``retract`` on both axes (45°) at
    rapid and returns at rapid to A's cut coordinate.  See ``specs/turning.md``.

    >>> F = Fraction
    >>> A = (F(2), F(25))
    >>> approach = Element(SegmentKind.RAPID, A, (F(2), F(10)))
    >>> shape = [Element(SegmentKind.LINE, (F(2), F(10)), (F(-20), F(10))),
    ...          Element(SegmentKind.LINE, (F(-20), F(10)), (F(-20), F(25)))]
    >>> moves = rough_cycle("G71", A, approach, shape, facing=False, depth=F(5), retract=F(1),
    ...                     allowance=(F(0), F(0)), type_one=True, infeed_rapid=True, final_pass=False,
    ...                     grid=(F(1, 1000), F(1, 2000)))
    >>> [(m.label, str(m.end[0]), str(m.end[1])) for m in moves[:4]]
    [('roughing pass 1: infeed', '2', '20'), ('roughing pass 1: cut', '-20', '20'), ('roughing pass 1: escape', '-19', '21'), ('roughing pass 1: return', '2', '21')]
    """
    if depth <= 0:
        raise CycleUnknown(f"{code}: the depth of cut must be greater than 0")
    if retract < 0:
        raise CycleUnknown(f"{code}: the escape amount must not be negative")
    a_prime = approach.end
    if not shape:
        raise CycleUnknown(f"{code}: the finishing shape has no move after its first block")
    b = shape[-1].end
    depth_axis = 0 if facing else 1
    cut_axis = 1 - depth_axis
    if a_prime[depth_axis] == start[depth_axis]:
        raise CycleUnknown(f"{code}: the shape's first block does not move {'Z' if facing else 'X'} (the depth "
                           "direction is not defined)")
    if b[cut_axis] == a_prime[cut_axis]:
        raise CycleUnknown(f"{code}: the finishing shape does not move along {'X' if facing else 'Z'} (the cutting "
                           "direction is not defined)")
    frame = _Frame(facing, -1 if b[cut_axis] > a_prime[cut_axis] else 1,
                   -1 if a_prime[depth_axis] > start[depth_axis] else 1)
    _shape_check(shape, frame, type_one, code)
    moved = [e.moved(*allowance) for e in shape]
    fs = [Element(e.kind, frame.to(e.start), frame.to(e.end),
                  None if e.centre is None else frame.to(e.centre), frame.clockwise(e.clockwise), e.line)
          for e in moved]
    a_n = frame.to(start)
    ca, ha = a_n
    # the lowest point of the moved shape: a + b sqrt(d) (an arc's bottom may be irrational)
    lowest: tuple = ("line", min(min(e.start[1], e.end[1]) for e in fs), _ZERO, _ZERO)
    for e in fs:
        if e.kind is SegmentKind.ARC:
            assert e.centre is not None
            r2 = (e.start[0] - e.centre[0]) ** 2 + (e.start[1] - e.centre[1]) ** 2
            if _point_on_arc_h(e.centre, e.start, e.end, e.clockwise, Fraction(-1), r2):
                bottom = ("arc", e.centre[1], Fraction(-1), r2)
                if _surd_compare(bottom, lowest) < 0:
                    lowest = bottom
    a2, b2 = fs[0].start, fs[-1].end
    # the closed boundary of the material: A, A'' (moved shape), B'', up to A's level, back to A
    closing = [Element(SegmentKind.LINE, a_n, a2)] + fs + [
        Element(SegmentKind.LINE, b2, (b2[0], ha)), Element(SegmentKind.LINE, (b2[0], ha), a_n)]
    gc = grid[cut_axis]
    moves: list[Move] = []
    infeed = SegmentKind.RAPID if infeed_rapid else SegmentKind.LINE

    def out(kind: SegmentKind, p: Pt, label: str, centre: Pt | None = None, cw: bool = False) -> None:
        moves.append(Move(kind, frame.back(p), label, None if centre is None else frame.back(centre),
                          frame.clockwise(cw)))

    if guard is not None:
        # the levels are the k >= 1 with ha - k * depth above the lowest point: counted before any is made
        # (ceil((ha - lowest) / depth) - 1, the lowest point taken as a float when it is irrational; the loop
        # below checks the exact count too)
        if lowest[0] == "line":
            guard.count("roughing passes", max(0, -((ha - lowest[1]) // -depth) - 1))
        else:  # one less, for the float's error
            guard.count("roughing passes", max(0, -((ha - Fraction(_surd_value(lowest))) // -depth) - 2))
    k = 0
    level = ha
    while True:
        nxt = ha - (k + 1) * depth
        if _surd_compare(("line", nxt, _ZERO, _ZERO), lowest) <= 0:
            break
        k += 1
        if guard is not None:
            guard.count("roughing passes", k)
            guard.tick(f"{k - 1} roughing passes")
        level = nxt
        xs = _level_crossings(closing, level)
        if len(xs) % 2:
            raise CycleUnknown(f"{code}: roughing level {k} meets the shape's boundary an odd number of times "
                               "(a degenerate shape)")
        xs = _sorted_desc(xs)
        intervals = [(xs[i], xs[i + 1]) for i in range(0, len(xs), 2)]
        intervals = [iv for iv in intervals if _surd_compare(iv[0], iv[1]) != 0]
        if len(intervals) != 1:
            what = "no material" if not intervals else f"{len(intervals)} separate stretches of material (a pocket)"
            raise CycleUnknown(f"{code}: roughing level {k} meets {what}; the order in which the control cuts "
                               "pockets (type II) is not modelled")
        _right, left = intervals[0]
        end_c = _round_crossing(left, frame, cut_axis, gc)
        if end_c >= ca:
            raise CycleUnknown(f"{code}: at roughing level {k} the material lies behind the start point (the "
                               "finishing shape lies beyond the cycle's start point on the cutting axis)")
        label = f"roughing pass {k}"
        out(infeed, (ca, level), f"{label}: infeed")
        out(SegmentKind.LINE, (end_c, level), f"{label}: cut")
        out(SegmentKind.RAPID, (end_c + retract, level + retract), f"{label}: escape")
        out(SegmentKind.RAPID, (ca, level + retract), f"{label}: return")
    if final_pass:
        label = "finishing allowance pass"
        out(infeed, a2, label)
        for e in fs:
            kind = e.kind
            out(kind, e.end, label, e.centre, e.clockwise)
        out(SegmentKind.RAPID, a_n, f"{label}: return to the start point")
    else:
        out(SegmentKind.RAPID, a_n, "return to the start point")
    return moves


def _round_crossing(x: tuple, frame: _Frame, cut_axis: int, step: Fraction) -> Fraction:
    """A crossing's frame coordinate ``a + b sqrt(d)``, rounded to the increment in program coordinates."""
    _k, a, b, d = x
    s = frame.sc
    return s * round_surd(s * a, s * b, d, step)


# --------------------------------------------------------------------------- G73 and G70


def pattern_cycle(code: str, start: Pt, approach: Element, shape: Sequence[Element], *, relief: Pt,
                  divisions: int, allowance: Pt, grid: Pt, guard: PassGuard | None = None) -> list[Move]:
    """Fanuc's G73 pattern repeating cycle: the shape (with its first block) cut ``divisions`` times, moved by
    ``allowance + relief * (divisions - j) / (divisions - 1)`` in pass j, each pass from the start point and
    back to it at rapid (0i-TD "Pattern repeating").

    >>> F = Fraction
    >>> A = (F(5), F(30))
    >>> ap = Element(SegmentKind.RAPID, A, (F(0), F(10)))
    >>> sh = [Element(SegmentKind.LINE, (F(0), F(10)), (F(-10), F(20)))]
    >>> ms = pattern_cycle("G73", A, ap, sh, relief=(F(0), F(4)), divisions=3, allowance=(F(0), F(0)),
    ...                    grid=(F(1, 1000), F(1, 1000)))
    >>> [(m.label, str(m.end[1])) for m in ms]  # doctest: +NORMALIZE_WHITESPACE
    [('pattern pass 1: approach', '14'), ('pattern pass 1', '24'), ('pattern pass 1: return', '30'),
     ('pattern pass 2: approach', '12'), ('pattern pass 2', '22'), ('pattern pass 2: return', '30'),
     ('pattern pass 3: approach', '10'), ('pattern pass 3', '20'), ('pattern pass 3: return', '30')]
    """
    if divisions < 1:
        raise CycleUnknown(f"{code}: the number of divisions must be at least 1")
    if guard is not None:
        guard.count("pattern passes (divisions)", divisions)
    moves: list[Move] = []
    for j in range(1, divisions + 1):
        if guard is not None:
            guard.tick(f"{j - 1} pattern passes")
        f = Fraction(divisions - j, divisions - 1) if divisions > 1 else _ZERO
        dz = allowance[0] + round_to_grid(relief[0] * f, grid[0])
        dx = allowance[1] + round_to_grid(relief[1] * f, grid[1])
        label = f"pattern pass {j}"
        moves.append(Move(approach.kind if approach.kind is not SegmentKind.ARC else SegmentKind.LINE,
                          (approach.end[0] + dz, approach.end[1] + dx), f"{label}: approach"))
        for e in shape:
            m = e.moved(dz, dx)
            moves.append(Move(m.kind, m.end, label, m.centre, m.clockwise))
        moves.append(Move(SegmentKind.RAPID, start, f"{label}: return"))
    return moves


def finish_moves(start: Pt, approach: Element, shape: Sequence[Element], label: str = "finishing pass") -> list[Move]:
    """Fanuc's G70: the shape as programmed (its first block included), then back to the start point at rapid."""
    moves = [Move(approach.kind, approach.end, label, approach.centre, approach.clockwise, feed=approach.feed)]
    for e in shape:
        moves.append(Move(e.kind, e.end, label, e.centre, e.clockwise, feed=e.feed))
    moves.append(Move(SegmentKind.RAPID, start, f"{label}: return to the start point"))
    return moves


# --------------------------------------------------------------------------- G90 / G94 / G92


def turning_cycle(code: str, start: Pt, end: Pt, taper: Fraction, *, facing: bool, thread: bool,
                  chamfer: Pt | None = None) -> list[Move]:
    """Fanuc's single cycles (G code system A): G90 (outer/inner turning), G94 (end face turning), G92
    (threading).  ``end`` is the programmed point (z, x); ``taper`` is R (the radius difference of the
    cut's start from its end for G90/G92, the Z difference for G94).

    G90/G92: (1) rapid along X to the cut's start, (2) feed (G92: thread) along Z to the end point,
    (3) X back to the start's X (G90: feed, G92: rapid), (4) rapid along Z back to the start point.  A G92
    with a thread chamfer ``(length along Z, rise in X)`` leaves the thread ``length`` before its end and pulls
    out to the end's Z, ``rise`` outwards.  G94: the same with X and Z exchanged, (3) at feed.

    >>> F = Fraction
    >>> [(m.label, str(m.end[0]), str(m.end[1])) for m in turning_cycle("G90", (F(5), F(30)), (F(-20), F(20)),
    ...  F(0), facing=False, thread=False)]  # doctest: +NORMALIZE_WHITESPACE
    [('(1) infeed', '5', '20'), ('(2) cut', '-20', '20'), ('(3) out', '-20', '30'), ('(4) return', '5', '30')]
    """
    zs, xs = start
    ze, xe = end
    if not facing:
        p1: Pt = (zs, xe + taper)
        p3: Pt = (ze, xs)
    else:
        p1 = (ze + taper, xs)
        p3 = (zs, xe)
    moves = [Move(SegmentKind.RAPID, p1, "(1) infeed")]
    if thread and chamfer is not None and chamfer[0] != 0:
        length, rise = chamfer
        if zs == ze or abs(ze - zs) < length:
            raise CycleUnknown(f"{code}: the thread chamfer ({length} mm) is longer than the thread")
        zdir = 1 if ze > zs else -1
        zc = ze - zdir * length
        xc = xe + taper * (zc - ze) / (zs - ze)
        out = 1 if xs >= xe else -1
        moves.append(Move(SegmentKind.LINE, (zc, xc), "(2) thread", synced=True))
        moves.append(Move(SegmentKind.LINE, (ze, xe + out * rise), "(2) thread chamfer", synced=True))
    else:
        moves.append(Move(SegmentKind.LINE, (ze, xe), f"(2) {'thread' if thread else 'cut'}", synced=thread))
    moves.append(Move(SegmentKind.RAPID if thread else SegmentKind.LINE, p3, "(3) out"))
    moves.append(Move(SegmentKind.RAPID, start, "(4) return"))
    return moves


def thread_chamfer(lead: Fraction, leads: Fraction, angle: Fraction, grid: Pt) -> Pt | None:
    """The thread chamfer (pull-out) of G92/G76: ``(length along Z, rise in X)`` for a chamfer of ``leads``
    leads at ``angle`` degrees (parameters 5130, 5131), rounded to the increment; None when it is 0.

    >>> thread_chamfer(Fraction(2), Fraction(1, 2), Fraction(45), (Fraction(1, 1000), Fraction(1, 2000)))
    (Fraction(1, 1), Fraction(1, 1))
    """
    length = round_to_grid(lead * leads, grid[0])
    if length == 0:
        return None
    if angle == 45:
        return length, round_to_grid(length, grid[1])
    if angle == 60:  # rise = length tan 60
        return length, round_surd(_ZERO, length, Fraction(3), grid[1])
    if angle == 30:
        return length, round_surd(_ZERO, length / 3, Fraction(3), grid[1])
    raise CycleUnknown(f"the thread chamfer angle {angle} degrees (parameter 5131) has an irrational rise nczones "
                       "does not round exactly (modelled: 30, 45, 60)")


# --------------------------------------------------------------------------- G74 / G75


def peck_cycle(code: str, start: Pt, end: Pt, *, along_z: bool, step_peck: Fraction, step_shift: Fraction,
               back: Fraction, relief: Fraction, grid: Pt, guard: PassGuard | None = None) -> list[Move]:
    """Fanuc's G74 (end face peck drilling/grooving: pecks along Z, shifts along X) and G75 (outer/inner
    grooving: pecks along X, shifts along Z).

    From the start point, for each shift position (the start, then every ``step_shift`` towards the end
    point's shift coordinate, the last at it): peck towards the end point's peck coordinate by ``step_peck``,
    backing off ``back`` at rapid after each peck but the last; at the bottom, relieve by ``relief``
    (away from the shift direction) at rapid, return at rapid to the start's peck coordinate, take the
    relief back and shift at rapid to the next position.  After the last position the tool returns to the
    start point at rapid.  See ``specs/turning.md``.

    >>> F = Fraction
    >>> ms = peck_cycle("G74", (F(1), F(0)), (F(-4), F(0)), along_z=True, step_peck=F(2), step_shift=F(1),
    ...                 back=F(1, 2), relief=F(0), grid=(F(1, 1000), F(1, 1000)))
    >>> [(m.label, str(m.end[0])) for m in ms]  # doctest: +NORMALIZE_WHITESPACE
    [('position 1: peck 1', '-1'), ('position 1: back off', '-1/2'), ('position 1: peck 2', '-3'),
     ('position 1: back off', '-5/2'), ('position 1: peck 3', '-4'), ('position 1: return', '1')]
    """
    p_axis = 0 if along_z else 1
    s_axis = 1 - p_axis
    if step_peck <= 0:
        raise CycleUnknown(f"{code}: the peck depth must be greater than 0")
    p0, p1 = start[p_axis], end[p_axis]
    s0, s1 = start[s_axis], end[s_axis]
    pdir = 1 if p1 > p0 else -1
    sdir = 1 if s1 > s0 else -1

    def pt(p: Fraction, s: Fraction) -> Pt:
        return (p, s) if along_z else (s, p)

    positions = [s0]
    if s1 != s0:
        if step_shift <= 0:
            raise CycleUnknown(f"{code}: the shift amount must be greater than 0 to reach the end point")
    if guard is not None:
        # counted before any is made: 1 + ceil(|s1 - s0| / shift) positions, ceil(|p1 - p0| / peck) pecks
        # (at least 1) at each
        n_pos = 1 + (-(-abs(s1 - s0) // step_shift) if s1 != s0 else 0)
        n_peck = max(1, -(-abs(p1 - p0) // step_peck))
        guard.count("shift positions", n_pos)
        guard.count("pecks in all", n_pos * n_peck)
    if s1 != s0:
        n = 1
        while True:
            s = s0 + sdir * n * step_shift
            if (s - s1) * sdir >= 0:
                positions.append(s1)
                break
            positions.append(s)
            n += 1
    moves: list[Move] = []
    for j, s in enumerate(positions, start=1):
        label = f"position {j}"
        if guard is not None:
            guard.tick(f"{j - 1} shift positions")
        if j > 1:
            moves.append(Move(SegmentKind.RAPID, pt(p0, s), f"{label}: shift"))
        depth = p0
        peck = 0
        while True:
            peck += 1
            target = depth + pdir * step_peck
            last = (target - p1) * pdir >= 0
            if last:
                target = p1
            moves.append(Move(SegmentKind.LINE, pt(target, s), f"{label}: peck {peck}"))
            depth = target
            if last:
                break
            moves.append(Move(SegmentKind.RAPID, pt(depth - pdir * back, s), f"{label}: back off"))
        sr = s
        if relief and j > 0:
            sr = s - sdir * relief
            moves.append(Move(SegmentKind.RAPID, pt(depth, sr), f"{label}: relief"))
        moves.append(Move(SegmentKind.RAPID, pt(p0, sr), f"{label}: return"))
        if sr != s:
            moves.append(Move(SegmentKind.RAPID, pt(p0, s), f"{label}: relief back"))
    if positions[-1] != s0:
        moves.append(Move(SegmentKind.RAPID, start, "back to the start point"))
    return moves


# --------------------------------------------------------------------------- G76


def thread_cycle_g76(code: str, start: Pt, end: Pt, *, taper: Fraction, height: Fraction, first_depth: Fraction,
                     min_depth: Fraction, finish_allowance: Fraction, finish_passes: int, tool_angle: Fraction,
                     chamfer: Pt | None, grid: Pt, guard: PassGuard | None = None) -> list[Move]:
    """Fanuc's G76 multiple threading cycle, single-edge infeed along the flank.

    ``end`` is the programmed point: X at the thread's root, Z at its end.  Roughing pass n (n = 1, 2, ...)
    cuts at depth ``d_n = first_depth * sqrt(n)`` below the crest (at least ``min_depth`` more than the
    previous pass) while ``d_n < height - finish_allowance``; then one pass at ``height - finish_allowance``
    (when the allowance is not 0) and ``finish_passes`` passes at ``height``.  Each pass: rapid to the infeed
    point (X at the depth, Z moved back along the flank by ``depth * tan(tool_angle / 2)``), thread to the end
    (with the chamfer pull-out), rapid out to the start's X, rapid back to the start point.  Depths and shifts
    are rounded to the increment.  See ``specs/turning.md``.

    >>> F = Fraction
    >>> ms = thread_cycle_g76("G76", (F(5), F(12)), (F(-20), F(9)), taper=F(0), height=F(1), first_depth=F(1, 2),
    ...                       min_depth=F(1, 10), finish_allowance=F(0), finish_passes=1, tool_angle=F(0),
    ...                       chamfer=None, grid=(F(1, 1000), F(1, 1000)))
    >>> [(m.label, str(m.end[1])) for m in ms if m.label.endswith("thread")]
    [('thread pass 1: thread', '19/2'), ('thread pass 2: thread', '9293/1000'), ('thread pass 3: thread', '4567/500'), ('thread pass 4 (finishing): thread', '9')]
    """
    zs, xs = start
    ze, xe = end
    if height <= 0 or first_depth <= 0:
        raise CycleUnknown(f"{code}: the thread height and the first depth of cut must be greater than 0")
    shift_of = _tan_half_exact(code, tool_angle)
    out = 1 if xs > xe else -1  # external thread: the start is above the root
    crest = xe + out * height
    zdir = 1 if ze > zs else -1
    depths: list[tuple[Fraction, str]] = []
    last = _ZERO
    limit = height - finish_allowance
    n = 0
    while True:
        dn = round_surd(_ZERO, first_depth, Fraction(n + 1), grid[1])
        if dn - last < min_depth:
            dn = last + min_depth
        if dn >= limit:
            break
        n += 1
        if guard is not None:  # the depths are counted before any pass is made
            guard.count("thread passes", n + finish_passes)
            if n % 1000 == 0:
                guard.tick(f"{n} thread depths")
        depths.append((dn, f"thread pass {n}"))
        last = dn
    if guard is not None:
        guard.count("thread passes", n + (1 if finish_allowance else 0) + finish_passes)
    if finish_allowance:
        n += 1
        depths.append((limit, f"thread pass {n}"))
    for _m in range(finish_passes):
        n += 1
        depths.append((height, f"thread pass {n} (finishing)"))
    moves: list[Move] = []
    for dn, label in depths:
        x_at = crest - out * dn
        z_at = zs - zdir * shift_of(dn, grid[0])
        moves.append(Move(SegmentKind.RAPID, (z_at, x_at + taper), f"{label}: infeed"))
        if chamfer is not None:
            zc = ze - zdir * chamfer[0]
            xc = x_at + taper * (zc - ze) / (z_at - ze) if z_at != ze else x_at
            moves.append(Move(SegmentKind.LINE, (zc, xc), f"{label}: thread", synced=True))
            moves.append(Move(SegmentKind.LINE, (ze, x_at + out * chamfer[1]), f"{label}: thread chamfer",
                              synced=True))
        else:
            moves.append(Move(SegmentKind.LINE, (ze, x_at), f"{label}: thread", synced=True))
        moves.append(Move(SegmentKind.RAPID, (ze, xs), f"{label}: out"))
        moves.append(Move(SegmentKind.RAPID, start, f"{label}: return"))
    return moves


def _tan_half_exact(code: str, angle: Fraction) -> Callable[[Fraction, Fraction], Fraction]:
    """``depth * tan(angle / 2)`` rounded to a grid, exactly, for the tool angles whose half-angle tangent is a
    surd (0, 60, 90, 120 degrees), else :class:`CycleUnknown`."""
    if angle == 0:
        return lambda d, g: _ZERO
    if angle == 60:  # tan 30 = sqrt(3)/3
        return lambda d, g: round_surd(_ZERO, d / 3, Fraction(3), g)
    if angle == 90:  # tan 45 = 1
        return lambda d, g: round_to_grid(d, g)
    if angle == 120:  # tan 60 = sqrt(3)
        return lambda d, g: round_surd(_ZERO, d, Fraction(3), g)
    raise CycleUnknown(f"{code}: the tool angle {angle} degrees has an irrational infeed shift nczones does not "
                       "round exactly (modelled: 0, 60, 90, 120 degrees; 55 and 80 are not)")
