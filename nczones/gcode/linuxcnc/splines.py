"""Spline motion codes (LinuxCNC): G5 cubic, G5.1 quadratic, G5.2/G5.3 and G6.2 NURBS.

Every curve becomes one :data:`~nczones.motion.SegmentKind.SPLINE` segment
holding the exact NURBS (see :mod:`nczones.geometry.nurbs`) in ``Segment.extra``:
``degree``, ``knots``, ``control`` (control points in machine coordinates,
one full tuple per point: the axes outside the plane stay where they are),
``weights`` and ``source`` (the G code).  ``start`` is the first control
point, ``end`` the last (the curves are clamped).

Word semantics (LinuxCNC ``convert_nurbs``/``convert_spline``):

* **G5.2 / G5.3**: the current position is the first control point (weight
  1, or ``P`` when the G5.2 block has no axis words); each block with both
  plane axis words adds a control point with weight ``P`` (> 0, required);
  ``L`` > 3 sets the order (default 3 = quadratic); G5.3 ends the curve,
  which needs at least ``order`` points.  Knots are clamped uniform
  (``knot_vector_creator``).  Incremental coordinates are relative to the
  curve's start (the interpreter's position only moves at G5.3).
* **G6.2**: the first block gives ``P`` (order) and ``Q`` (LinuxCNC's
  interpolation method); each block with both plane axis words adds a
  control point with weight ``R`` and knot ``K``; blocks with only ``K``
  add the remaining knots.  The curve runs when it has ``points + order``
  knots.  A first control point away from the current position is reached
  by a straight feed (LinuxCNC feeds to the curve's first point).
* **G5.1** (XY only): control points current, current + (I, J), end; order 3.
* **G5** (XY only): current, current + (I, J), end + (P, Q), end; order 4;
  I/J may be omitted after a G5 (then -P, -Q of the previous G5).

Curves only in the active plane: an axis word outside the plane in a
spline block is ``unknown``; a knot vector that is not clamped is unknown.

Geometry (what the prover and controller use): the exact rational curve.
LinuxCNC's canon layer moves along an approximation of it (biarcs through
curve points for G5.2 in 2.8 and for G6.2 Q1, straight chords through
curve points for G6.2 Q0/Q2, points found by arc-length inversion for Q2/Q3);
like G64 blending, that approximation is not modelled (specs/gcode-support.md).
"""

from __future__ import annotations

from fractions import Fraction

from ...motion import PLANE_AXES, Plane, SegmentKind, SplineCurve
from ..codes import SPLINE_CODES  # G keys (10 x number) handled here

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["SPLINE_CODES", "spline_block", "spline_pending"]

_NAME = {50: "G5", 51: "G5.1", 52: "G5.2", 53: "G5.3", 62: "G6.2"}


class _Pending:
    __slots__ = ("code", "points", "weights", "knots", "order", "start", "span", "q")

    def __init__(self, code, start, span):
        self.code = code
        self.points: list[tuple[Fraction, ...]] = []
        self.weights: list[Fraction] = []
        self.knots: list[Fraction] = []
        self.order = 3
        self.start = start
        self.span = span
        self.q = None


def spline_pending(it: Any) -> str | None:
    """Why an unfinished curve is pending (for the end of the program), or None."""
    p = getattr(it, "spline_state", None)
    if p is None:
        return None
    return f"the {_NAME[p.code]} curve started at line {p.span.line if p.span else '?'} was never completed"


def _plane_words(it, words, axis_words, code):
    a, b, _ = PLANE_AXES[it.plane]
    for i, w in axis_words:
        if it.axes[i] not in (a, b):
            it.unknown(_NAME[code], f"{_NAME[code]} with an {it.axes[i]} word ({w.text}): nczones models "
                        f"spline curves in the active plane ({a}{b}) only", w)
            return None
    if a not in it.index or b not in it.index:
        raise it.error("GC308", f"a spline in plane G{int(it.plane)} needs axes {a} and {b}")
    has_a, has_b = a in words, b in words
    return a, b, has_a, has_b


def _emit_curve(it: Any, code: Any, degree: Any, knots: Any, control: Any, weights: Any) -> None:
    # imported by the first spline, not by every verify's start
    from ...geometry.nurbs import Nurbs, NurbsError

    try:
        Nurbs(degree, tuple(knots), tuple(control), tuple(weights))
    except NurbsError as exc:
        it.unknown(_NAME[code], f"{_NAME[code]}: {exc}; nczones models clamped NURBS curves only")
        return
    if control[0] != tuple(it.pos):
        it.emit(SegmentKind.LINE, list(control[0]), feed=True, derived=f"{_NAME[code]} to the first control point")
    extra = (SplineCurve(degree, tuple(knots), tuple(map(tuple, control)), tuple(weights), _NAME[code]),)
    n0 = len(it.emitted)
    it.emit(SegmentKind.SPLINE, list(control[-1]), feed=True, plane=it.plane)
    if len(it.emitted) > n0:
        from dataclasses import replace

        it.emitted[-1] = replace(it.emitted[-1], extra=extra)


def _knots(count: int, order: int) -> Any:
    """:func:`nczones.geometry.nurbs.clamped_uniform_knots`, imported by the first spline, not by every verify."""
    from ...geometry.nurbs import clamped_uniform_knots as knots

    return knots(count, order)


def spline_block(it: Any, motion: int, axis_words: Any, words: Any, g1: Any) -> None:
    """Execute one block whose active motion is a spline code (called by the interpreter)."""
    code = motion
    name = _NAME[code]
    if it.comp_on:
        raise it.error("GC204", f"{name} cannot be used with cutter radius compensation on")
    it.check_feed()
    if code in (50, 51) and it.feed_mode == 93 and "F" not in words:
        # rs274: "F word missing with inverse time arc move" (rs274_findings/g93-spline-without-f.ngc)
        raise it.error("GC305", f"inverse time feed (G93): every {name} block needs its own F word",
                       g1[1] if g1 else None)
    it.note_assumed(("units", "distance", "offset", "plane"))
    pend = getattr(it, "spline_state", None)
    if code in (50, 51):
        if it.plane is not Plane.XY:
            raise it.error("GC204", f"{name}: splines must be in the XY plane (G17)")
        pw = _plane_words(it, words, axis_words, code)
        if pw is None:
            return
        cur = tuple(it.pos)
        ix, iy = it.index["X"], it.index["Y"]
        end, _ = it.program_target(axis_words, False)
        end = tuple(end)

        def off(p, dx, dy):
            q = list(p)
            q[ix] += dx
            q[iy] += dy
            return tuple(q)

        iw, jw = words.get("I"), words.get("J")
        if code == 51:
            if iw is None and jw is None and not g1:
                # a modal G5.1 block (no G5.1 word) without I J: rs274 2.9.0~pre1 feeds straight to its end
                # (rs274_findings/g5-without-ij.ngc: STRAIGHT_FEED(10, 4)); with the word it refuses, as here
                end_pt, deps = it.program_target(axis_words, False)
                it.emit(SegmentKind.LINE, end_pt, feed=True, end_deps=deps)
                return
            if iw is None or jw is None:
                raise it.error("GC208", "G5.1 needs both I and J", g1[1] if g1 else None)
            ctrl = [cur, off(cur, it.length_mm(iw.value), it.length_mm(jw.value)), end]
            _emit_curve(it, code, 2, _knots(3, 3), ctrl, [Fraction(1)] * 3)
            return
        pw_, qw = words.get("P"), words.get("Q")
        if pw_ is None or qw is None:
            raise it.error("GC208", "G5 needs both P and Q", g1[1] if g1 else None)
        if (iw is None) != (jw is None):
            raise it.error("GC208", "G5 needs both I and J, or neither", iw or jw)
        if iw is None:
            prev = getattr(it, "_g5_next_ij", None)
            if prev is None:
                # LinuxCNC 2.9 runs it (rs274_findings/g5-without-ij.ngc: a NURBS_FEED whose control points rs274 -g
                # does not print): its start direction is not known here
                it.unknown("G5", "G5 without I and J that does not follow a G5: LinuxCNC 2.9 runs it with a start "
                           "direction nczones does not model", g1[1] if g1 else None)
                return
            di, dj = prev
        else:
            di, dj = it.length_mm(iw.value), it.length_mm(jw.value)
        dp, dq = it.length_mm(pw_.value), it.length_mm(qw.value)
        ctrl = [cur, off(cur, di, dj), off(end, dp, dq), end]
        it._g5_next_ij = (-dp, -dq)
        _emit_curve(it, code, 3, _knots(4, 4), ctrl, [Fraction(1)] * 4)
        return
    if code == 53:
        if pend is None or pend.code != 52:
            raise it.error("GC208", "G5.3 without a G5.2 curve before it", g1[1] if g1 else None)
        it.spline_state = None
        it.motion = None
        if len(pend.points) < pend.order:
            raise it.error("GC209", f"a G5.2 curve of order L={pend.order} needs at least {pend.order} control "
                            f"points; it has {len(pend.points)}")
        knots = _knots(len(pend.points), pend.order)
        _emit_curve(it, 52, pend.order - 1, knots, pend.points, pend.weights)
        return
    pw = _plane_words(it, words, axis_words, code)
    if pw is None:
        return
    a, b, has_a, has_b = pw
    if has_a != has_b:
        raise it.error("GC208", f"{name}: a control point needs both {a} and {b}", axis_words[0][1])
    target = None
    if has_a:
        # incremental coordinates are relative to the curve's start (LinuxCNC keeps current_x/y until the end)
        end, _ = it.program_target(axis_words, False)
        target = tuple(end)
    if code == 52:
        if pend is not None and pend.code != 52:
            pend = None
        p = words.get("P")
        if pend is None:
            pend = _Pending(52, tuple(it.pos), it.span)
            w0 = p.value if (p is not None and target is None and p.value > 0) else Fraction(1)
            pend.points.append(tuple(it.pos))
            pend.weights.append(w0)
            it.spline_state = pend
        lw = words.get("L")
        if lw is not None and lw.value > 3:
            if lw.value.denominator != 1:
                raise it.error("GC209", f"G5.2 order {lw.text} must be an integer", lw)
            pend.order = int(lw.value)
        if target is not None:
            if p is None or p.value <= 0:
                raise it.error("GC208", "G5.2: every control point needs a positive weight P", p or axis_words[0][1])
            pend.points.append(target)
            pend.weights.append(p.value)
        elif p is not None and len(pend.points) > 1:
            raise it.error("GC208", "G5.2: P without axis words is allowed only for the first control point", p)
        return
    # G6.2
    kw, rw, pw_ = words.get("K"), words.get("R"), words.get("P")
    if pw_ is not None:
        if pend is not None:
            it.unknown(name, "a new G6.2 curve (P word) started before the previous one had all its knots", pw_)
            it.spline_state = None
            return
        if pw_.value.denominator != 1 or pw_.value < 2:
            raise it.error("GC209", f"G6.2 order {pw_.text} must be an integer of at least 2", pw_)
        pend = _Pending(62, tuple(it.pos), it.span)
        pend.order = int(pw_.value)
        qv = words.get("Q")
        pend.q = qv.value if qv is not None else None
        it.spline_state = pend
    if pend is None or pend.code != 62:
        it.unknown(name, "G6.2 data before the block that gives the order P", (kw or rw or (g1[1] if g1 else None)))
        return
    if kw is None:
        raise it.error("GC208", "G6.2: every block needs a knot K", g1[1] if g1 else (axis_words[0][1] if axis_words else None))
    if target is not None:
        if len(pend.knots) != len(pend.points):
            it.unknown(name, "a G6.2 control point after the trailing knots", axis_words[0][1])
            it.spline_state = None
            return
        weight = rw.value if rw is not None else Fraction(1)
        if weight <= 0:
            raise it.error("GC209", f"G6.2 weight {rw.text} must be positive", rw)
        pend.points.append(target)
        pend.weights.append(weight)
    pend.knots.append(kw.value)
    if pend.knots and len(pend.knots) == len(pend.points) + pend.order:
        it.spline_state = None
        _emit_curve(it, 62, pend.order - 1, pend.knots, pend.points, pend.weights)
        it._spline_last = True
