"""SMT-LIB encodings of "is some point of this motion outside the allowed set?".

Every query is SMT-LIB text evaluated in one Z3 context inside
``(push) ... (pop)`` (DESIGN §9: several times faster than building terms
through the Python API).  Exact rationals are written ``(/ n d)``; nothing
passes through a float.  The context has a fixed random seed and a
resource limit (``rlimit``) per query instead of a wall-clock timeout, so a
run is deterministic: ``unknown`` from Z3 becomes an ``unknown`` verdict.

Encodings (``q`` = the point a zone sees, ``e`` = margin perturbation):

* straight piece: ``q_a = s_a + dS_a + t ((e_a + dE_a) - (s_a + dS_a)) + home_a + e_a``,
  ``0 <= t <= 1``, ``-d <= e_a <= d``; ``dS``/``dE`` are sums of parameter
  deviations (linear unless start and end depend on different
  parameters, then bilinear: QF_NRA);
* dogleg rapid whose ends depend on different parameters: a time
  variable ``tau >= 0`` and per axis ``S + min(v tau, E - S)`` (``max(-v tau,
  E - S)`` backwards) with ``ite``: exact and linear (QF_LRA), see
  :meth:`nczones.prover.core.Prover._dogleg_query`;
* circular arc with rational centre ``c``: plane variables ``x, y`` with
  ``(x-cx)^2 + (y-cy)^2 = r^2`` and the swept sector as half-plane tests
  on ``v = (x,y) - c`` (exact, QF_NRA); the other axes are constant;
* R-format arc with irrational centre: centre variables constrained by
  ``|S - c|^2 = R^2``, ``|E - c|^2 = R^2`` and the side of the chord (exact);
* helix and slightly inconsistent I/J arcs (spirals): an over-approximation
  — the annulus sector between the start and end radii, the other axes
  anywhere between their start and end values.

The zone formulas are exact: half-open stepped regions
(``upto[i-1] < r <= upto[i]``, the first closed at ``from``), forbid zones
open, polygons as unions of triangles (an ear-clipping triangulation; the
open interior adds the open diagonals), tip zones subtract the tool length.
Only the stepped rows the motion's reference-axis enclosure can reach are
encoded.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import z3

from ..errors import InternalError
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint
from .exact import _reachable

__all__ = ["q", "Solver", "SolverAnswer", "zone_violation", "triangulate", "Z3_VERSION"]

Z3_VERSION = z3.get_version_string()
F0 = Fraction(0)


def q(x: Fraction | int) -> str:
    """An exact SMT-LIB real literal.

    >>> q(Fraction(-3, 4)), q(Fraction(2))
    ('(- (/ 3.0 4.0))', '2.0')
    """
    x = Fraction(x)
    n, d = abs(x.numerator), x.denominator
    body = f"{n}.0" if d == 1 else f"(/ {n}.0 {d}.0)"
    return f"(- {body})" if x < 0 else body


def add(*terms: str) -> str:
    kept = [t for t in terms if t and t != "0.0"]
    if not kept:
        return "0.0"
    return kept[0] if len(kept) == 1 else f"(+ {' '.join(kept)})"


def sub(a: str, b: str) -> str:
    return a if b == "0.0" else f"(- {a} {b})"


def mul(a: str, b: str) -> str:
    if a == "0.0" or b == "0.0":
        return "0.0"
    if a == "1.0":
        return b
    if b == "1.0":
        return a
    return f"(* {a} {b})"


def _or(parts: Iterable[str]) -> str:
    parts = [p for p in parts if p != "false"]
    if "true" in parts:
        return "true"
    if not parts:
        return "false"
    return parts[0] if len(parts) == 1 else f"(or {' '.join(parts)})"


def _and(parts: Iterable[str]) -> str:
    parts = [p for p in parts if p != "true"]
    if "false" in parts:
        return "false"
    if not parts:
        return "true"
    return parts[0] if len(parts) == 1 else f"(and {' '.join(parts)})"


# --------------------------------------------------------------------------- polygons


def _cross(o: Sequence[Fraction], a: Sequence[Fraction], b: Sequence[Fraction]) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def triangulate(vertices: Sequence[Sequence[Fraction]]) -> tuple[list[tuple[Any, ...]], list[tuple[Any, ...]]]:
    """Ear clipping of a simple polygon: (triangles in ccw order, internal diagonals).

    >>> F = Fraction
    >>> tris, diags = triangulate(((F(0), F(0)), (F(2), F(0)), (F(2), F(2)), (F(0), F(2))))
    >>> len(tris), len(diags)
    (2, 1)
    """
    pts = list(vertices)
    area2 = sum(_cross((F0, F0), pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts)))
    if area2 < 0:
        pts.reverse()
    idx = list(range(len(pts)))
    tris: list[tuple[Any, ...]] = []
    diags: list[tuple[Any, ...]] = []
    guard = 0
    while len(idx) > 3 and guard < 10 * len(pts) ** 2:
        guard += 1
        for k in range(len(idx)):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            a, b, c = pts[i0], pts[i1], pts[i2]
            if _cross(a, b, c) <= 0:
                continue
            if any(
                _cross(a, b, pts[j]) >= 0 and _cross(b, c, pts[j]) >= 0 and _cross(c, a, pts[j]) >= 0
                for j in idx if j not in (i0, i1, i2)
            ):
                continue
            tris.append((a, b, c))
            diags.append((a, c))
            idx.pop(k)
            break
    if len(idx) != 3:
        raise InternalError("polygon triangulation failed")
    tris.append(tuple(pts[i] for i in idx))
    return tris, diags


def _cross_term(o: Sequence[Fraction], a: Sequence[Fraction], x: str, y: str) -> str:
    """cross(a - o, (x, y) - o) as an SMT term (o, a rational)."""
    ax, ay = a[0] - o[0], a[1] - o[1]
    return add(mul(q(ax), sub(y, q(o[1]))), mul(q(-ay), sub(x, q(o[0]))))


# --------------------------------------------------------------------------- zones


def zone_violation(zone: Zone, pt: dict[str, str], ref_range: tuple[Fraction, Fraction] | None) -> str:
    """SMT formula: the point ``pt`` (axis -> term, as the zone sees it) violates ``zone``.

    >>> F = Fraction
    >>> zone_violation(BoxZone("b", (("X", F(0), F(1)),)), {"X": "x"}, None)
    '(or (< x 0.0) (> x 1.0))'
    """
    if isinstance(zone, BoxZone):
        conds = []
        for a, lo, hi in zone.limits:
            if zone.forbid:
                if lo is not None:
                    conds.append(f"(> {pt[a]} {q(lo)})")
                if hi is not None:
                    conds.append(f"(< {pt[a]} {q(hi)})")
            else:
                if lo is not None:
                    conds.append(f"(< {pt[a]} {q(lo)})")
                if hi is not None:
                    conds.append(f"(> {pt[a]} {q(hi)})")
        return _and(conds) if zone.forbid else _or(conds)
    if isinstance(zone, SteppedZone):
        r, lim = pt[zone.reference_axis], pt[zone.limited_axis]
        regs = zone.regions
        idx = range(len(regs)) if ref_range is None else _reachable(zone, *ref_range)
        parts = []
        if zone.forbid:
            for i in idx:
                reg = regs[i]
                c = [f"(< {q(zone.region_lower(i))} {r})", f"(< {r} {q(reg.upto)})"]
                if reg.min is not None:
                    c.append(f"(< {q(reg.min)} {lim})")
                if reg.max is not None:
                    c.append(f"(< {lim} {q(reg.max)})")
                parts.append(_and(c))
                if i + 1 < len(regs):
                    nxt = regs[i + 1]
                    lo = _maxb(reg.min, nxt.min)
                    hi = _minb(reg.max, nxt.max)
                    if lo is None or hi is None or lo < hi:
                        c = [f"(= {r} {q(reg.upto)})"]
                        if lo is not None:
                            c.append(f"(< {q(lo)} {lim})")
                        if hi is not None:
                            c.append(f"(< {lim} {q(hi)})")
                        parts.append(_and(c))
            return _or(parts)
        parts.append(f"(< {r} {q(zone.start)})")
        parts.append(f"(> {r} {q(regs[-1].upto)})")
        for i in idx:
            reg = regs[i]
            rel = "<=" if i == 0 else "<"
            out = []
            if reg.min is not None:
                out.append(f"(< {lim} {q(reg.min)})")
            if reg.max is not None:
                out.append(f"(> {lim} {q(reg.max)})")
            if out:
                parts.append(_and([f"({rel} {q(zone.region_lower(i))} {r})", f"(<= {r} {q(reg.upto)})", _or(out)]))
        return _or(parts)
    if isinstance(zone, PolygonZone):
        x, y = pt[zone.plane[0]], pt[zone.plane[1]]
        tris, diags = triangulate(zone.vertices)
        if zone.forbid:
            inside = [_and([f"(> {_cross_term(a, b, x, y)} 0.0)" for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))]) for t in tris]
            for a, b in diags:
                inside.append(_and([
                    f"(= {_cross_term(a, b, x, y)} 0.0)",
                    f"(< {q(min(a[0], b[0]))} {x})" if a[0] != b[0] else "true",
                    f"(< {x} {q(max(a[0], b[0]))})" if a[0] != b[0] else "true",
                    f"(< {q(min(a[1], b[1]))} {y})" if a[1] != b[1] else "true",
                    f"(< {y} {q(max(a[1], b[1]))})" if a[1] != b[1] else "true",
                ]))
            lims = []
            for a, lo, hi in zone.limits:
                if lo is not None:
                    lims.append(f"(> {pt[a]} {q(lo)})")
                if hi is not None:
                    lims.append(f"(< {pt[a]} {q(hi)})")
            return _and([_or(inside)] + lims)
        closed = [_and([f"(>= {_cross_term(a, b, x, y)} 0.0)" for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))]) for t in tris]
        out = [f"(not {_or(closed)})"]
        for a, lo, hi in zone.limits:
            if lo is not None:
                out.append(f"(< {pt[a]} {q(lo)})")
            if hi is not None:
                out.append(f"(> {pt[a]} {q(hi)})")
        return _or(out)
    raise InternalError(f"unknown zone kind {zone!r}")


def _maxb(a, b):
    return b if a is None else a if b is None else max(a, b)


def _minb(a, b):
    return b if a is None else a if b is None else min(a, b)


# --------------------------------------------------------------------------- solver


@dataclass(frozen=True, slots=True)
class SolverAnswer:
    """``status`` is "sat", "unsat" or "unknown"; ``values`` the model (exact where Z3 gives it)."""

    status: str
    values: dict[str, Fraction]
    approximate: frozenset[str] = frozenset()


_TOKEN = re.compile(r"\(|\)|[^\s()]+")


def _parse_sexpr(text: str) -> list[Any]:
    stack: list[list[Any]] = [[]]
    for tok in _TOKEN.findall(text):
        if tok == "(":
            stack.append([])
        elif tok == ")":
            done = stack.pop()
            stack[-1].append(done)
        else:
            stack[-1].append(tok)
    return stack[0]


def _num(e: Any) -> tuple[Fraction, bool] | None:
    """(value, exact) of a printed real; None for root-obj."""
    if isinstance(e, str):
        approx = e.endswith("?")
        return Fraction(e.rstrip("?")), not approx
    if e and e[0] == "-" and len(e) == 2:
        v = _num(e[1])
        return None if v is None else (-v[0], v[1])
    if e and e[0] == "/" and len(e) == 3:
        a, b = _num(e[1]), _num(e[2])
        if a is None or b is None:
            return None
        return a[0] / b[0], a[1] and b[1]
    return None


class Solver:
    """One Z3 context fed with SMT-LIB text; deterministic (seed 0, rlimit per query).

    >>> s = Solver()
    >>> a = s.check("(declare-const t Real)(assert (and (<= 0.0 t) (< t (/ 1.0 3.0))))", ["t"])
    >>> a.status, 0 <= a.values["t"] < Fraction(1, 3)
    ('sat', True)
    """

    name = "z3"
    version = Z3_VERSION

    def __init__(self, rlimit: int = 5_000_000):
        self.ctx = z3.Context()
        self.rlimit = rlimit
        self.queries = 0
        self._eval("(set-option :smt.random_seed 0)(set-option :sat.random_seed 0)"
                   "(set-option :nlsat.seed 0)")

    def _eval(self, text: str) -> str:
        return str(z3.Z3_eval_smtlib2_string(self.ctx.ref(), text))

    def check(self, body: str, want: list[str], precision: int = 40) -> SolverAnswer:
        self.queries += 1
        head = f"(push)(set-option :rlimit {self.rlimit})"
        try:
            out = self._eval(head + body + "(check-sat)").strip()
        except z3.Z3Exception as exc:  # a malformed query is our bug
            self._eval("(pop)")
            raise InternalError(f"SMT query rejected: {exc}") from exc
        status = out.split()[-1] if out else "unknown"
        values: dict[str, Fraction] = {}
        approx: set[str] = set()
        if status == "sat" and want:
            got = _parse_sexpr(self._eval(f"(get-value ({' '.join(want)}))"))[0]
            missing = []
            for name, val in got:
                v = _num(val)
                if v is None:
                    missing.append(name)
                else:
                    values[name] = v[0]
                    if not v[1]:
                        approx.add(name)
            if missing:
                text = self._eval(
                    f"(set-option :pp.decimal true)(set-option :pp.decimal_precision {precision})"
                    f"(get-value ({' '.join(missing)}))(set-option :pp.decimal false)"
                )
                for name, val in _parse_sexpr(text)[0]:
                    v = _num(val)
                    if v is None:
                        raise InternalError(f"cannot read Z3 value {val!r}")
                    values[name] = v[0]
                    approx.add(name)
        self._eval("(pop)")
        if status not in ("sat", "unsat"):
            status = "unknown"
        return SolverAnswer(status, values, frozenset(approx))


def tip_shift(zone: Zone, tool_axis: str | None) -> str | None:
    return tool_axis if zone.point is ZonePoint.TIP else None
