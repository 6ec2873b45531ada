"""LinuxCNC's lathe cycles G70, G71 and G72 (with .1 and .2), computed as LinuxCNC computes them.

LinuxCNC 2.9 generates these cycles in ``src/emc/rs274ngc/interp_g7x.cc`` (``Interp::convert_g7x`` and
the ``g7x`` path class) in IEEE double arithmetic on ``std::complex<double>`` points (real part Z,
imaginary part X).  This module computes the same passes with the same double operations in the same
order — the complex products, Smith's complex division of libgcc's ``__divdc3``, ``hypot`` for ``abs``,
``x*x + y*y`` for ``norm``, no fused multiply-add (x86-64) — so every generated point is the double
LinuxCNC commands, taken exactly as a ``Fraction`` by the interpreter.  The algorithm, step by step, is
in ``specs/turning.md`` ("LinuxCNC G70-G72"); this is an independent implementation of it.

The shape is a list of :class:`Piece` (a straight or a circle arc, or a corner to be rounded/chamfered);
:func:`g70`, :func:`g71` and :func:`g72` return :class:`Out` moves in program coordinates (Z, X as a
radius).  A situation in which LinuxCNC raises an error (a non-monotonic profile, parallel lines to
intersect, ...) raises :class:`G7xError` with LinuxCNC's message.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..passes import PassGuard

__all__ = ["Piece", "Out", "G7xError", "g70", "g71", "g72", "TOLERANCE"]

#: interp_g7x.cc's tolerance (mm or inch: the program's units).
TOLERANCE = 1e-6
#: Where LinuxCNC would loop forever (its issue #2939, the corpus' g71-endless-loop programs), nczones stops
#: after this many steps and reports it.
_MAX_STEPS = 100_000

C = complex


class G7xError(Exception):
    """LinuxCNC would stop with this error (``G7X error: ...``)."""


# --------------------------------------------------------------------------- double complex arithmetic
# std::complex<double> as GCC computes it on x86-64: the products and sums are IEEE operations in the
# order written; division by a complex is Smith's method (libgcc __divdc3); by a double, per part.

def _mul(a: complex, b: complex) -> complex:
    return C(a.real * b.real - a.imag * b.imag, a.real * b.imag + a.imag * b.real)


def _div(a: complex, b: complex) -> complex:
    c, d = b.real, b.imag
    if abs(c) < abs(d):
        ratio = c / d
        denom = c * ratio + d
        return C((a.real * ratio + a.imag) / denom, (a.imag * ratio - a.real) / denom)
    ratio = d / c
    denom = d * ratio + c
    return C((a.imag * ratio + a.real) / denom, (a.imag - a.real * ratio) / denom)


def _divr(a: complex, d: float) -> complex:
    return C(a.real / d, a.imag / d)


def _mulr(d: float, a: complex) -> complex:
    return C(d * a.real, d * a.imag)


def _abs(a: complex) -> float:
    return math.hypot(a.real, a.imag)


def _norm(a: complex) -> float:
    return a.real * a.real + a.imag * a.imag


def _conj(a: complex) -> complex:
    return C(a.real, -a.imag)


_I = C(0.0, 1.0)


# --------------------------------------------------------------------------- output


@dataclass(frozen=True, slots=True)
class Out:
    """One generated move: ``kind`` "rapid", "feed" or "arc" to ``end`` (Z + X i), an arc around ``centre``."""

    kind: str
    end: complex
    centre: complex | None = None
    ccw: bool = False
    label: str = ""


class _Sink:
    """Collects the moves (LinuxCNC's ``motion_machine``): an arc whose end is within 1e-6 of the current point
    on both axes is dropped, as ``convert_arc`` is not called for it."""

    def __init__(self, start: complex):
        self.moves: list[Out] = []
        self.at = start
        self.label = ""

    def straight(self, end: complex) -> None:
        self.moves.append(Out("feed", end, label=self.label))
        self.at = end

    def rapid(self, end: complex) -> None:
        self.moves.append(Out("rapid", end, label=self.label))
        self.at = end

    def arc(self, ccw: bool, centre: complex, end: complex) -> None:
        if not (abs(self.at.real - end.real) < 1e-6) or not (abs(self.at.imag - end.imag) < 1e-6):
            self.moves.append(Out("arc", end, centre, ccw, label=self.label))
            self.at = end


class _Mapped:
    """The sink seen through the frame the cycle cut in (``swapped_motion<flip_state>``): one of the eight
    reflections/rotations, undone on every point (and an arc's direction reversed by a reflection)."""

    def __init__(self, sink: _Sink, state: int):
        self.sink = sink
        self.state = state

    def map(self, p: complex) -> complex:
        s = self.state
        if s == 0:
            return p
        if s == 1:
            return -_conj(p)
        if s == 2:
            return _conj(p)
        if s == 3:
            return -p
        if s == 4:
            return _mul(_I, p)
        if s == 5:
            return _conj(_mul(_I, p))
        if s == 6:
            return -_conj(_mul(_I, p))
        return _mul(-_I, p)

    def straight(self, end: complex) -> None:
        self.sink.straight(self.map(end))

    def rapid(self, end: complex) -> None:
        self.sink.rapid(self.map(end))

    def arc(self, ccw: bool, centre: complex, end: complex) -> None:
        flip = self.state in (1, 2, 5, 6)
        self.sink.arc((not ccw) if flip else ccw, self.map(centre), self.map(end))


# --------------------------------------------------------------------------- pieces of the profile


def _line_meets_circle(line_start: complex, line_end: complex, centre: complex, on_circle: complex,
                       near: complex) -> complex:
    """Where the line through ``line_start`` and ``line_end`` cuts the circle about ``centre`` through
    ``on_circle``: of the two crossings the one nearer to ``near`` (a tangent line: its foot).  The double
    operations of ``interp_g7x.cc`` in its order, the line turned onto the real axis about its end."""
    diff = line_start - line_end
    rot = _divr(_conj(diff), _abs(diff))
    pe = _mul(on_circle - line_end, rot)
    pc = _mul(centre - line_end, rot)
    b = _norm(pc - pe) - pc.imag * pc.imag
    b = 0.0 if b < 0 else math.sqrt(b)
    s1 = _div(C(pc.real + b, 0.0), rot) + line_end
    s2 = _div(C(pc.real - b, 0.0), rot) + line_end
    return s1 if _abs(near - s1) < _abs(near - s2) else s2


class Piece:
    """A straight, an arc, or a corner (fillet/chamfer) of the profile; Z + X i points."""

    finish: float = 0.0

    def __init__(self, start: complex, end: complex):
        self.start = start
        self.end = end

    def copy(self) -> Piece:
        raise NotImplementedError

    # geometry of the frame
    def flip_imag(self) -> None:
        self.start, self.end = _conj(self.start), _conj(self.end)

    def flip_real(self) -> None:
        self.start, self.end = -_conj(self.start), -_conj(self.end)

    def rotate(self) -> None:
        self.start, self.end = _mul(-self.start, _I), _mul(-self.end, _I)

    def move(self, d: complex) -> None:
        self.start, self.end = self.start + d, self.end + d

    def monotonic(self) -> bool:
        return (self.end - self.start).real <= 1e-3

    def do_finish(self, prev: Piece, nxt: Piece) -> None:
        pass

    def corner_finish(self, prev: Piece, nxt: Piece) -> complex:
        """Trim ``prev`` and ``nxt`` at the corner: both offset by the finish distance (on the side where they
        meet), intersected; the corner's centre is the intersection's midpoint."""
        p, n = prev.copy(), nxt.copy()
        p.offset(self.finish)
        n.offset(self.finish)
        if (p.end - n.start).real > 1e-2:
            self.finish = -self.finish
            p, n = prev.copy(), nxt.copy()
            p.offset(self.finish)
            n.offset(self.finish)
        if (p.end - n.start).real > 1e-2:
            raise G7xError(f"Corner finish failed at {_cxx(prev.end)}")
        p.intersect(n)
        centre = _divr(p.end + n.start, 2.0)
        p.offset(-self.finish)
        n.offset(-self.finish)
        self.start = prev.end = p.end
        self.end = nxt.start = n.start
        return centre

    # interface of the concrete pieces
    def offset(self, distance: float) -> None:
        raise NotImplementedError

    def radius(self) -> float:
        raise NotImplementedError

    def crossings(self, x: float) -> list[float]:
        raise NotImplementedError

    def climb(self, at: list[complex], out: _Mapped) -> bool:
        raise NotImplementedError

    def climb_only(self, at: list[complex], out: _Mapped) -> None:
        raise NotImplementedError

    def dive(self, at: list[complex], x: float, out: _Mapped, fast: bool) -> bool:
        raise NotImplementedError

    def draw(self, out: _Mapped) -> None:
        raise NotImplementedError

    def intersect(self, nxt: Piece) -> None:
        """Move this piece's end and ``nxt``'s start to where the two meet (``intersect``/``intersect_end``)."""
        _intersect(self, nxt)


class Straight(Piece):
    def copy(self) -> Straight:
        s = Straight(self.start, self.end)
        s.finish = self.finish
        return s

    def offset(self, distance: float) -> None:
        diff = self.start - self.end
        d = _divr(_mul(C(0.0 * distance, 1.0 * distance), diff), _abs(diff))
        self.start, self.end = self.start + d, self.end + d

    def radius(self) -> float:
        return _abs(self.start - self.end)

    def crossings(self, x: float) -> list[float]:
        s, e = self.start, self.end
        if min(s.imag, e.imag) > x + TOLERANCE or max(s.imag, e.imag) < x - TOLERANCE:
            return []
        if abs((s - e).imag) < TOLERANCE:
            return [s.real, e.real]
        return [(x - s.imag) / (e.imag - s.imag) * (e.real - s.real) + s.real]

    def climb(self, at: list[complex], out: _Mapped) -> bool:
        if self.end.imag + TOLERANCE < self.start.imag:
            return True
        if _abs(at[0] - self.start) > TOLERANCE:
            raise G7xError("How did we get here?")
        out.straight(self.end)
        at[0] = self.end
        return False

    def climb_only(self, at: list[complex], out: _Mapped) -> None:
        if self.end.imag < self.start.imag:
            return
        xs = self.crossings(at[0].imag)
        if not xs:
            return
        at[0] = C(xs[0], at[0].imag)
        out.straight(at[0])
        out.straight(self.end)
        at[0] = self.end

    def dive(self, at: list[complex], x: float, out: _Mapped, fast: bool) -> bool:
        if self.start.imag <= self.end.imag + TOLERANCE:
            return True
        if x < self.end.imag:
            (out.rapid if fast else out.straight)(self.end)
            at[0] = self.end
            return False
        xs = self.crossings(x)
        if not xs:
            raise G7xError("x too large in straight dive")
        ep = C(xs[0], x)
        (out.rapid if fast else out.straight)(ep)
        at[0] = ep
        return False

    def draw(self, out: _Mapped) -> None:
        out.straight(self.end)

    def meet_after_straight(self, p: Straight) -> None:
        """``p`` (a straight) is followed by this straight: move p's end and this start to their crossing."""
        diff = self.start - self.end
        rot = _divr(_conj(diff), _abs(diff))
        ps = _mul(p.start - self.end, rot)
        pe = _mul(p.end - self.end, rot)
        if (ps - pe).imag == 0:
            raise G7xError("Cannot intersect parallel lines")
        f = ps.imag / (ps - pe).imag
        crossing = _div(ps + _mulr(f, pe - ps), rot) + self.end
        self.start = p.end = crossing

    def meet_after(self, p: Piece) -> None:
        """An arc ``p`` followed by this straight: both meet where the line cuts p's circle, the crossing nearer
        to this start."""
        assert isinstance(p, Round)
        if _abs(self.start - p.end) < TOLERANCE:
            return
        self.start = p.end = _line_meets_circle(self.start, self.end, p.centre, p.end, self.start)


class Round(Piece):
    def __init__(self, ccw: bool, start: complex, centre: complex, end: complex):
        super().__init__(start, end)
        self.ccw = ccw
        self.centre = centre

    def copy(self) -> Round:
        r = Round(self.ccw, self.start, self.centre, self.end)
        r.finish = self.finish
        return r

    def offset(self, distance: float) -> None:
        r = _abs(self.start - self.centre)
        factor = (r + (1 if self.ccw else -1) * distance) / _abs(self.start - self.centre)
        self.start = _mulr(factor, self.start - self.centre) + self.centre
        self.end = _mulr(factor, self.end - self.centre) + self.centre

    def radius(self) -> float:
        return min(_abs(self.start - self.end), _abs(self.start - self.centre))

    def flip_imag(self) -> None:
        self.ccw = not self.ccw
        super().flip_imag()
        self.centre = _conj(self.centre)

    def flip_real(self) -> None:
        self.ccw = not self.ccw
        super().flip_real()
        self.centre = -_conj(self.centre)

    def rotate(self) -> None:
        super().rotate()
        self.centre = _mul(-self.centre, _I)

    def move(self, d: complex) -> None:
        super().move(d)
        self.centre = self.centre + d

    def monotonic(self) -> bool:
        if self.finish != 0:
            return True
        entry = (self.start - self.centre).imag
        exit_ = (self.end - self.centre).imag
        dz = (self.end - self.start).real
        if self.ccw:
            return entry >= -1e-3 and exit_ >= -1e-3 and dz <= -1e-3
        return entry <= 1e-3 and exit_ <= 1e-3 and dz <= -1e-3

    def on_arc(self, p: complex) -> bool:
        c = self.centre
        a = _mul(_conj(self.start - c), p - c).imag
        b = _mul(_conj(self.end - c), p - c).imag
        if self.ccw:
            return a >= -TOLERANCE and b <= TOLERANCE
        return a <= TOLERANCE and b >= -TOLERANCE

    def crossings(self, x: float) -> list[float]:
        r = self.start - self.centre
        ra = _abs(r)
        s = -(x - ra - self.centre.imag) * (x + ra - self.centre.imag)
        if s < -TOLERANCE:
            return []
        if s < 0:
            s = 0.0
        s = math.sqrt(s)
        out = []
        p1 = C(self.centre.real + s, x)
        if self.on_arc(p1):
            out.append(p1.real)
        p2 = C(self.centre.real - s, x)
        if self.on_arc(p2):
            out.append(p2.real)
        return out

    def climb(self, at: list[complex], out: _Mapped) -> bool:
        if not self.ccw:
            if at[0].real > self.centre.real:
                return True
            if _abs(at[0] - self.end) > 1e-3:
                out.arc(self.ccw, self.centre, self.end)
            at[0] = self.end
            return False
        if at[0].real < self.centre.real:
            return True
        ep = self.end
        if self.end.real < self.centre.real:
            ep = C(self.centre.real, self.centre.imag + _abs(self.start - self.centre))
        if _abs(at[0] - ep) > 1e-3:
            out.arc(self.ccw, self.centre, ep)
        at[0] = ep
        return True

    def climb_only(self, at: list[complex], out: _Mapped) -> None:
        xs = self.crossings(at[0].imag)
        if not xs:
            return
        if not self.ccw:
            if xs[-1] > self.centre.real:
                return
            at[0] = C(xs[-1], at[0].imag)
            out.straight(at[0])
            if _abs(at[0] - self.end) > 1e-3:
                out.arc(self.ccw, self.centre, self.end)
            at[0] = self.end
            return
        if xs[0] < self.centre.real:
            return
        at[0] = C(xs[0], at[0].imag)
        out.straight(at[0])
        ep = self.end
        if self.end.real < self.centre.real:
            ep = C(self.centre.real, self.centre.imag + _abs(self.start - self.centre))
        if _abs(at[0] - ep) > 1e-3:
            out.arc(self.ccw, self.centre, ep)
        at[0] = ep

    def dive(self, at: list[complex], x: float, out: _Mapped, fast: bool) -> bool:
        if _abs(at[0] - self.end) < TOLERANCE or (at[0] - self.end).real <= TOLERANCE:
            at[0] = self.end
            return False
        xs = self.crossings(x)
        if not xs:
            xs = self.crossings(x - TOLERANCE)
        if self.ccw:
            if at[0].real - TOLERANCE > self.centre.real:
                return True
            if not xs or xs[-1] > self.centre.real:
                out.arc(self.ccw, self.centre, self.end)
                at[0] = self.end
                return False
            ep = C(xs[-1], x)
            out.arc(self.ccw, self.centre, ep)
            at[0] = ep
            return False
        if at[0].real <= self.centre.real:
            return True
        if not xs:
            out.arc(self.ccw, self.centre, self.end)
            at[0] = self.end
            return False
        if xs[0] < self.centre.real:
            return False  # only the far side of the arc is hit: the pocket goes one level down
        ep = C(xs[0], x)
        out.arc(self.ccw, self.centre, ep)
        at[0] = ep
        return False

    def draw(self, out: _Mapped) -> None:
        out.arc(self.ccw, self.centre, self.end)

    def meet_after_straight(self, p: Straight) -> None:
        """A straight ``p`` followed by this arc: they meet where p's line cuts this circle, the crossing
        nearer to this start."""
        if _abs(self.start - p.end) < TOLERANCE:
            return
        self.start = p.end = _line_meets_circle(p.start, p.end, self.centre, self.end, self.start)

    def meet_round(self, p: Round) -> None:
        """An arc ``p`` followed by this arc: they meet where the circles cross."""
        a = _abs(self.start - self.centre)
        b = _abs(p.start - p.centre)
        c = _abs(self.centre - p.centre)
        cos_b = (c * c + a * a - b * b) / 2.0 / a / c
        cos_b2 = cos_b * cos_b
        if cos_b2 > 1:
            cos_b2 = 1.0
        rot = C(cos_b, math.sqrt(1 - cos_b2))
        t = _divr(_mul(rot, p.centre - self.centre), c)  # rot * (pc - c) / c * a + c, left to right
        crossing = C(t.real * a, t.imag * a) + self.centre
        p.end = self.start = crossing


class Fillet(Round):
    """A corner rounded with radius ``finish`` (the A word)."""

    def __init__(self, d: float, at: complex):
        super().__init__(False, at, at, at)
        self.finish = d

    def copy(self) -> Fillet:
        f = Fillet(self.finish, self.start)
        f.ccw, f.start, f.end, f.centre = self.ccw, self.start, self.end, self.centre
        return f

    def do_finish(self, prev: Piece, nxt: Piece) -> None:
        self.centre = self.corner_finish(prev, nxt)
        self.ccw = (self.start - self.centre).imag > 0 or (self.end - self.centre).imag > 0
        self.finish = 0.0


class Chamfer(Straight):
    """A corner cut by a straight (the C word), between the points a fillet of that size would touch."""

    def __init__(self, d: float, at: complex):
        super().__init__(at, at)
        self.finish = d

    def copy(self) -> Chamfer:
        c = Chamfer(self.finish, self.start)
        c.start, c.end = self.start, self.end
        return c

    def do_finish(self, prev: Piece, nxt: Piece) -> None:
        self.corner_finish(prev, nxt)


# the double dispatch of interp_g7x.cc's intersect/intersect_end: p.intersect(n) adjusts p's end and n's start
def _intersect(p: Piece, n: Piece) -> None:
    if isinstance(n, Straight):
        if isinstance(p, Straight):
            n.meet_after_straight(p)
        else:
            n.meet_after(p)
    else:
        assert isinstance(n, Round)
        if isinstance(p, Straight):
            n.meet_after_straight(p)
        else:
            assert isinstance(p, Round)
            n.meet_round(p)


def _cxx(p: complex) -> str:
    """A point as std::ostream prints a std::complex<double>: ``(z,x)`` with 6 significant digits."""
    return f"({p.real:.6g},{p.imag:.6g})"


# --------------------------------------------------------------------------- the path


class _Path:
    """The profile (a list of pieces; the first from the cycle's start point to the profile's first point)."""

    def __init__(self, pieces: list[Piece]):
        self.pieces = pieces
        self.state = 0  # which of the eight frames (swapped_motion) the path is in
        self.delta = 0.5
        self.escape = C(0.3, 0.3)
        self.pocket_starts: list[complex] = []
        self.guard: PassGuard | None = None
        #: the pocket loop of LinuxCNC after 2.9.0~pre1 (commits 48a3ee4a and 111fd213: stop at the last piece,
        #: step on from a piece whose end is reached); False: the installed 2.9.0~pre1's loop
        self.later = False

    def copy(self) -> _Path:
        q = _Path([p.copy() for p in self.pieces])
        q.state, q.delta, q.escape = self.state, self.delta, self.escape
        return q

    def rotate(self) -> None:
        for p in self.pieces:
            p.rotate()
        self.state ^= 4

    def swap(self) -> None:
        d = self.pieces[0].end - self.pieces[-1].end
        if d.imag > 0:
            for p in self.pieces:
                p.flip_imag()
            self.state ^= 2
        if d.real < 0:
            for p in self.pieces:
                p.flip_real()
            self.state ^= 1

    def monotonic(self) -> None:
        first = self.pieces[0]
        if (first.end - first.start).real > 0:
            first.start = C(first.end.real, first.start.imag)
        for p in self.pieces:
            if not p.monotonic():
                raise G7xError("Not monotonic")

    def do_finish(self) -> None:
        ps = self.pieces
        for k in range(1, len(ps) - 1):
            ps[k].do_finish(ps[k - 1], ps[k + 1])
        self.pieces = [p for p in ps if not p.radius() < 1e-3]

    def should_rotate(self) -> bool:
        q = self.copy()
        q.pieces.pop(0)
        q.swap()
        return any(not p.monotonic() for p in q.pieces)

    def add_distance(self, distance: float) -> None:
        """Offset the profile (all pieces but the first) by ``distance`` towards the start point, in steps no
        larger than half the smallest piece, joining with arcs and intersecting as it goes."""
        ps = self.pieces
        v1 = ps[0].end - ps[0].start
        v2 = ps[-1].start - ps[0].start
        if v2 == 0:
            # the cycle starts where the profile's last piece starts: LinuxCNC divides by a zero complex, which
            # GCC's __divdc3 turns into (copysign(inf, c) * a, copysign(inf, c) * b); its imaginary part is
            # negative exactly when v1's is (NaN, never negative, when v1's is 0)
            negative = math.copysign(math.inf, v2.real) * v1.imag < 0
        else:
            negative = _div(v1, v2).imag < 0
        if negative:
            distance = -distance
        first = ps.pop(0)
        current = 0.0
        steps = 0
        while current != distance:
            steps += 1
            if steps > _MAX_STEPS:
                raise G7xError("offsetting the profile does not end (LinuxCNC would loop forever)")
            max_distance = 1e9
            for p in ps:
                max_distance = min(max_distance, p.radius() / 2)
            max_distance = min(max_distance, abs(distance - current))
            if distance < 0:
                max_distance = -max_distance
            k = 0
            while k < len(ps):
                ps[k].offset(max_distance)
                if ps[k].radius() < 1e-3:
                    ps.pop(k)
                    continue
                k += 1
            k = 0
            while k < len(ps) - 1:
                p, n = ps[k], ps[k + 1]
                if (p.end - n.start).real > 1e-2:
                    s, e = p.copy(), n.copy()
                    s.offset(-max_distance)
                    e.offset(-max_distance)
                    centre = _divr(s.end + e.start, 2.0)
                    ps.insert(k + 1, Round(distance > 0, p.end, centre, n.start))
                    k += 1
                k += 1
            k = 0
            while k < len(ps) - 1:
                p = ps[k]
                if not p.monotonic():
                    if k == 0:
                        raise G7xError("an offset piece at the start of the profile is not monotonic: LinuxCNC "
                                       "compares it with the piece before the list's start (undefined behaviour)")
                    if p.radius() < ps[k - 1].radius():
                        ps.pop(k)
                    else:
                        ps.pop(k - 1)
                    k = 0
                    p = ps[k]
                n = ps[k + 1]
                if p.radius() < 1e-3:
                    ps.pop(k)
                    k = 1  # the C++ loop restarts at begin() and then steps on
                else:
                    p.intersect(n)
                    k += 1
            current += max_distance
        for k in range(len(ps) - 1):
            mid = _divr(ps[k].end + ps[k + 1].start, 2.0)
            ps[k].end = ps[k + 1].start = mid
        first.end = ps[0].start
        ps.insert(0, first)
        self.pieces = ps

    # ------------------------------------------------------------------ the cycles
    def g70(self, out: _Sink, x: float, z: float, d: float, e: float, passes: float) -> None:
        count = int(passes)
        if self.guard is not None:  # counted before any pass is made
            self.guard.count("finishing passes", count)
        self.pieces[0].start = C(z, x)
        if self.should_rotate():
            if not self.later:
                # 2.9.0~pre1's do_g70 also checks the turned copy (``path.monotonic()``, dropped with commit
                # 654f5103): "Not monotonic" where the profile is monotonic in neither frame
                q = self.copy()
                q.pieces.pop(0)
                q.swap()
                q.rotate()
                q.swap()
                q.monotonic()
            self.rotate()
        self.swap()
        self.do_finish()
        self.monotonic()
        mapped = _Mapped(out, self.state)
        # interp_g7x.cc do_g70: ``for(int pass=p; pass>0; pass--)`` counts int(P) (toward zero) passes, each at
        # ``(pass-1)*(d-e)/p+e`` with the double P: P2.6 makes 2 passes, the outer at (d - e) / 2.6 + e
        for n in range(count, 0, -1):
            out.label = f"finishing pass {count - n + 1}"
            if self.guard is not None:
                self.guard.tick(f"{count - n} finishing passes")
            distance = (n - 1) * (d - e) / passes + e
            q = self.copy()
            q.add_distance(distance)
            mapped.rapid(q.pieces[0].start)
            mapped.rapid(q.pieces[0].end)
            for p in q.pieces[1:]:
                p.draw(mapped)

    def g71(self, out: _Sink, cycle: int, x: float, z: float, u: float, w: float, d: float, i: float, r: float,
            rotate: bool = False) -> None:
        self.pieces[0].start = C(z, x)
        if rotate:
            self.rotate()
        self.swap()
        self.do_finish()
        self.monotonic()
        self.add_distance(d)
        shift = C(w, u)
        for p in self.pieces:
            p.move(shift)
        mapped = _Mapped(out, self.state)
        self.delta = max(i, 2 * TOLERANCE)
        self.escape = _mulr(r, C(1.0, 1.0))
        if self.guard is not None:
            # before any pass is made: the levels from the start's level down to the profile's lowest point
            # (its pieces are monotonic: the lowest is an end point), one every delta, each cut at least once;
            # one level of slack for the doubles (the exact number is counted as the cuts are made)
            top = self.pieces[0].start.imag
            levels = (top - min(min(p.start.imag, p.end.imag) for p in self.pieces)) / self.delta
            if levels == levels:
                self.guard.count("roughing passes", int(min(levels, 1e18)) - 1, at_least=True)
        out.label = "roughing: to the start"
        mapped.rapid(self.pieces[0].start)
        if self.pieces[-1].end.imag < self.pieces[0].start.imag:
            ep = C(self.pieces[-1].end.real, self.pieces[0].start.imag)
            self.pieces.append(Straight(self.pieces[-1].end, ep))
        self.pocket_starts.append(self.pieces[0].start)
        self.cuts = 0
        self.steps = 0
        self.out_sink = out
        self.pocket(cycle, self.pieces[0].start, 0, mapped)

    def pocket(self, cycle: int, location: complex, k: int, out: _Mapped) -> None:
        """Cut layer by layer (``g7x::pocket``): dive along the profile to the next level, cut along Z to the
        profile, escape, return, come back; where the profile climbs, follow it; a pocket is cut by
        recursion from where the climb ends."""
        ps = self.pieces
        x = self.pocket_starts[-1].imag
        at = [location]
        sink = self.out_sink

        def label(what: str) -> None:
            sink.label = what

        if cycle == 2:
            label("roughing: along the profile to the first pocket")
            while k < len(ps):
                if ps[k].dive(at, -1e9, out, k == 0):
                    break
                k += 1
            cycle = 3
        while k < len(ps):
            self.steps += 1
            if self.steps > _MAX_STEPS:
                raise G7xError("the roughing cycle does not end (LinuxCNC would loop forever)")
            if self.guard is not None:
                self.guard.tick(f"{self.cuts} roughing passes")
            while x - TOLERANCE > at[0].imag:
                x -= self.delta
            label(f"roughing pass {self.cuts + 1}: infeed")
            if ps[k].dive(at, x, out, k == 0):
                label(f"roughing pass {self.cuts + 1}: along the profile")
                if cycle == 1:
                    while k < len(ps):
                        ps[k].climb_only(at, out)
                        k += 1
                else:
                    while k < len(ps):
                        if ps[k].climb(at, out):
                            if cycle == 3:
                                if at[0].imag > self.pocket_starts[-1].imag and len(self.pocket_starts) > 1:
                                    self.pocket_starts.pop()
                                if len(self.pocket_starts) == 1:
                                    self.pocket_starts.append(at[0])
                            self.pocket(cycle, at[0], k, out)
                            return
                        k += 1
                return
            if self.later and k == len(ps) - 1:
                return
            if abs(at[0].imag - x) > TOLERANCE or (self.later and ps[k].end == at[0]):
                k += 1
                continue
            for j in range(k, len(ps)):
                xs = ps[j].crossings(at[0].imag)
                if not xs:
                    continue
                destination = xs[0] if j != k else xs[-1]
                distance = abs(destination - at[0].real)
                if destination - TOLERANCE > at[0].real:
                    continue
                if distance < TOLERANCE:
                    if j == k:
                        continue
                    if _abs(at[0] - ps[j].start) < TOLERANCE:
                        k = j
                        break
                    x -= self.delta
                    break
                self.cuts += 1
                n = self.cuts
                if self.guard is not None:
                    self.guard.count("roughing passes", n)
                dest = C(destination, at[0].imag)
                label(f"roughing pass {n}: cut")
                out.straight(dest)
                scale = _cxx_min(1.0, _fdiv(_fdiv(distance, 2.0), self.escape.real))
                dest = dest + _mulr(scale, self.escape)
                label(f"roughing pass {n}: escape")
                out.rapid(dest)
                dest = at[0] - _conj(_mulr(scale, self.escape))
                label(f"roughing pass {n}: return")
                out.rapid(dest)
                label(f"roughing pass {n}: back to the level")
                if k == 0:
                    out.rapid(at[0])
                else:
                    out.straight(at[0])
                x -= self.delta
                break


def _fdiv(a: float, b: float) -> float:
    """IEEE division (a zero divisor gives an infinity or NaN, as in C)."""
    if b != 0:
        return a / b
    if a != a or a == 0:
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


def _cxx_min(a: float, b: float) -> float:
    """``std::min(a, b)``: ``b < a ? b : a`` (a NaN b gives a)."""
    return b if b < a else a


# --------------------------------------------------------------------------- entry points


def g70(pieces: list[Piece], start: complex, *, x: float, z: float, d: float, e: float, passes: float,
        guard: PassGuard | None = None) -> list[Out]:
    """LinuxCNC's G70: ``int(passes)`` finishing passes at distances ``(n - 1) (d - e) / passes + e`` from the profile,
    each from a rapid to its start.  ``start`` is where the tool stands (after the cycle's rapid to X Z)."""
    sink = _Sink(start)
    _run(lambda p: p.g70(sink, x, z, d, e, passes), pieces, guard)
    return sink.moves


def g71(pieces: list[Piece], start: complex, *, cycle: int, x: float, z: float, u: float, w: float, d: float,
        i: float, r: float, facing: bool = False, guard: PassGuard | None = None, later: bool = False) -> list[Out]:
    """LinuxCNC's G71 (``facing``: G72) roughing cycle; ``cycle`` is 0 (G71), 1 (G71.1: no pockets) or 2 (G71.2:
    the pockets only).

    ``later=False`` computes it as the installed LinuxCNC 2.9.0~pre1 (git f1270d6e) does; ``later=True`` as the
    2.9 branch after it (interp_g7x.cc of 2.9.1 and later: the closing straight of commits 03793cc9, bb75d9cc and
    c38c192f, the pocket loop of 48a3ee4a and 111fd213).  The interpreter compares the two (specs/turning.md)."""
    sink = _Sink(start)
    path_pieces = list(pieces)
    if later:
        # convert_g7x after 2.9.0~pre1: a profile that ends moving along the cut axis, on the far side of the
        # start's level, is closed by a straight from its end to that level
        end = path_pieces[-1].end
        dfront = path_pieces[0].end - path_pieces[0].start
        dback = path_pieces[-1].end - path_pieces[-1].start
        if not facing:
            if abs(dback.real) > 0 and dfront.imag * (x - end.imag) < 0:
                path_pieces.append(Straight(end, C(end.real, x)))
        elif abs(dback.imag) > 0 and dfront.real * (z - end.real) < 0:
            path_pieces.append(Straight(end, C(z, end.imag)))
    _run(lambda p: p.g71(sink, cycle, x, z, u, w, d, i, r, rotate=facing), path_pieces, guard, later)
    return sink.moves


def g72(pieces: list[Piece], start: complex, **kw: Any) -> list[Out]:
    """LinuxCNC's G72 facing cycle: :func:`g71` with the profile turned by 90 degrees."""
    return g71(pieces, start, facing=True, **kw)


def _run(fn: Callable[[_Path], None], pieces: list[Piece], guard: PassGuard | None = None,
         later: bool = False) -> None:
    path = _Path([p.copy() for p in pieces])
    path.guard = guard
    path.later = later
    try:
        fn(path)
    except (IndexError, ZeroDivisionError, ValueError) as e:  # LinuxCNC reads past its list or divides by 0
        raise G7xError(f"the profile is degenerate for the cycle ({type(e).__name__}); LinuxCNC's behaviour here "
                       "is undefined") from None
    except RecursionError:  # 2.9.0~pre1's pocket recursion that never ends (fixed by 48a3ee4a): a crash there
        raise G7xError("the roughing cycle's pocket recursion does not end (LinuxCNC 2.9.0~pre1 recurses until "
                       "it fails)") from None
