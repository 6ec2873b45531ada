"""SMT-LIB encodings of "is some point of this motion outside the allowed set?".

Every query is SMT-LIB text evaluated in one Z3 context inside
``(push) ... (pop)`` (DESIGN §9: several times faster than building terms
through the Python API).  Exact rationals are written ``(/ n d)``; nothing
passes through a float.  The context has a fixed random seed and a
resource limit (``rlimit``) per query instead of a wall-clock timeout, so a
run is deterministic: ``unknown`` from Z3 becomes an ``unknown`` verdict.
A time backstop, the program's budget and Ctrl-C stop a query through Z3's
interrupt (:mod:`nczones.prover.limits`).

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

import functools
import re
from collections.abc import Callable, Iterable, Sequence
from fractions import Fraction

from ..errors import InternalError
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint
from ..zones.kinds import KindTable
from .exact import reachable
from .solver_version import z3_version

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["q", "Solver", "SolverAnswer", "zone_violation", "triangulate", "z3_version"]

if TYPE_CHECKING:
    import z3


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


def or_all(parts: Iterable[str]) -> str:
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


def _triangulation(zone: PolygonZone) -> tuple[list[tuple[Any, ...]], list[tuple[Any, ...]]]:
    """:func:`triangulate` of a zone, once per zone (it is quadratic in the vertices)."""
    from .polygon import cached

    return cached(zone, -1, lambda: triangulate(zone.vertices))


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
    return ZONE_VIOLATION(zone, pt, ref_range)


#: :func:`zone_violation` per zone kind (no fallback: a kind the SMT tier cannot encode is not modelled).
ZONE_VIOLATION: KindTable[Callable[[Any, dict[str, str], tuple[Fraction, Fraction] | None], str]] = KindTable(
    "prover.smt.zone_violation")


@ZONE_VIOLATION.register(BoxZone)
def _box_violation(zone: BoxZone, pt: dict[str, str], ref_range: tuple[Fraction, Fraction] | None) -> str:
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
    return _and(conds) if zone.forbid else or_all(conds)


@ZONE_VIOLATION.register(SteppedZone)
def _stepped_violation(zone: SteppedZone, pt: dict[str, str], ref_range: tuple[Fraction, Fraction] | None) -> str:
    r, lim = pt[zone.reference_axis], pt[zone.limited_axis]
    regs = zone.regions
    idx = range(len(regs)) if ref_range is None else reachable(zone, *ref_range)
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
        return or_all(parts)
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
            parts.append(_and([f"({rel} {q(zone.region_lower(i))} {r})", f"(<= {r} {q(reg.upto)})", or_all(out)]))
    return or_all(parts)


@ZONE_VIOLATION.register(PolygonZone)
def _polygon_violation(zone: PolygonZone, pt: dict[str, str], ref_range: tuple[Fraction, Fraction] | None) -> str:
    x, y = pt[zone.plane[0]], pt[zone.plane[1]]
    tris, diags = _triangulation(zone)
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
        return _and([or_all(inside)] + lims)
    closed = [_and([f"(>= {_cross_term(a, b, x, y)} 0.0)" for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))]) for t in tris]
    out = [f"(not {or_all(closed)})"]
    for a, lo, hi in zone.limits:
        if lo is not None:
            out.append(f"(< {pt[a]} {q(lo)})")
        if hi is not None:
            out.append(f"(> {pt[a]} {q(hi)})")
    return or_all(out)


#: The axis whose enclosure prunes the encoding (``ref_range`` of :func:`zone_violation`: the rows a stepped
#: table can reach), per zone kind.  Fallback: None (the whole zone is encoded).
REFERENCE_AXIS: KindTable[Callable[[Any], str | None]] = KindTable("prover.smt.reference_axis", fallback=lambda z: None)
REFERENCE_AXIS.set(BoxZone, lambda z: None)
REFERENCE_AXIS.set(SteppedZone, lambda z: z.reference_axis)
REFERENCE_AXIS.set(PolygonZone, lambda z: None)


def _maxb(a, b):
    return b if a is None else a if b is None else max(a, b)


def _minb(a, b):
    return b if a is None else a if b is None else min(a, b)


# --------------------------------------------------------------------------- solver


@dataclass(frozen=True, slots=True)
class SolverAnswer:
    """``status`` is "sat", "unsat" or "unknown"; ``values`` the model (exact where Z3 gives it).

    ``stopped`` says why an ``unknown`` came: ``"rlimit"`` (the query's resource
    limit), ``"time"`` (the per-query time backstop), ``"budget"`` (the
    program's budget), ``"interrupt"`` (Ctrl-C) or ``"incomplete"`` (Z3 gave up).
    """

    status: str
    values: dict[str, Fraction]
    approximate: frozenset[str] = frozenset()
    stopped: str = ""

    def reason(self, what: str = "") -> str:
        """A reason for an ``unknown`` verdict, e.g. "solver resource limit reached on an arc"."""
        on = f" on {what}" if what else ""
        return {
            "time": f"solver stopped by its time backstop{on} (the resource limit did not stop it; see --budget)",
            "budget": f"budget spent: the solver was stopped{on}",
            "interrupt": f"interrupted{on}",
            "incomplete": f"the solver could not decide{on} (incomplete)",
        }.get(self.stopped, f"solver resource limit reached{on}")

    @property
    def code(self) -> str:
        """Reason code: VF201 resource limit, VF202 time backstop, VF203 budget, VF204 interrupt, VF205 incomplete."""
        return {"time": "VF202", "budget": "VF203", "interrupt": "VF204", "incomplete": "VF205"}.get(self.stopped,
                                                                                                     "VF201")


_TOKEN = re.compile(r"\(|\)|[^\s()]+")


def parse_sexpr(text: str) -> list[Any]:
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


def numeral(e: Any) -> tuple[Fraction, bool] | None:
    """(value, exact) of a printed real; None for root-obj."""
    if isinstance(e, str):
        approx = e.endswith("?")
        return Fraction(e.rstrip("?")), not approx
    if e and e[0] == "-" and len(e) == 2:
        v = numeral(e[1])
        return None if v is None else (-v[0], v[1])
    if e and e[0] == "/" and len(e) == 3:
        a, b = numeral(e[1]), numeral(e[2])
        if a is None or b is None:
            return None
        return a[0] / b[0], a[1] and b[1]
    return None


class Solver:
    """One Z3 context fed with SMT-LIB text; deterministic (seed 0, rlimit per query).

    Every query has a resource limit: ``rlimit`` for linear queries and
    ``nonlinear_rlimit`` for nonlinear ones (``check(..., nonlinear=True)``).
    Z3 counts the work of its nonlinear arithmetic unevenly (seconds for a
    few hundred thousand units on some arc queries), so the time backstop of
    ``limits`` is what bounds those in the end.  With
    ``limits`` (:class:`~nczones.prover.limits.RunLimits`) a query also has
    the time backstop and the program's budget, and Ctrl-C interrupts it;
    before the query starts, a spent budget raises
    :class:`~nczones.prover.limits.BudgetSpent`.

    >>> s = Solver()
    >>> a = s.check("(declare-const t Real)(assert (and (<= 0.0 t) (< t (/ 1.0 3.0))))", ["t"])
    >>> a.status, 0 <= a.values["t"] < Fraction(1, 3)
    ('sat', True)
    """

    name = "z3"

    def __init__(self, rlimit: int | None = None, *, nonlinear_rlimit: int | None = None, limits: Any = None):
        from .limits import LINEAR_RLIMIT, NONLINEAR_RLIMIT

        #: The Z3 version every report names (Z3 itself is loaded at the first query).
        self.version = z3_version()
        self._ctx: z3.Context | None = None  # made at the first query: most runs never ask the solver
        self.rlimit = LINEAR_RLIMIT if rlimit is None else rlimit
        self.nonlinear_rlimit = NONLINEAR_RLIMIT if nonlinear_rlimit is None else nonlinear_rlimit
        self.limits = limits
        self.queries = 0
        self.seconds = 0.0
        self.stopped: dict[str, int] = {}

    @property
    def ctx(self) -> z3.Context:
        """The solver's Z3 context, made and configured when first used."""
        if self._ctx is None:
            import z3

            self._ctx = _context(z3)
            # ctrl_c false: Z3 must not install its own SIGINT handler while it solves (it would swallow
            # Ctrl-C); the run's watchdog interrupts it instead (see limits.py)
            # arith.nl.grobner false: the Groebner-basis lemmas of the nonlinear core are not bounded by the
            # rlimit and ran for minutes on R-format arc queries that are decided in a second without them
            self._eval("(set-option :ctrl_c false)(set-option :smt.random_seed 0)(set-option :sat.random_seed 0)"
                       "(set-option :nlsat.seed 0)(set-option :smt.arith.nl.grobner false)")
        return self._ctx

    def _eval(self, text: str) -> str:
        import z3

        return str(z3.Z3_eval_smtlib2_string(self.ctx.ref(), text))

    def check(self, body: str, want: list[str], precision: int = 40, *, nonlinear: bool = False) -> SolverAnswer:
        import time

        import z3

        if self.limits is not None:
            self.limits.checkpoint()
        self.queries += 1
        rlimit = self.nonlinear_rlimit if nonlinear else self.rlimit
        head = f"(push)(set-option :rlimit {rlimit})"
        check = "(check-sat)"
        t0 = time.perf_counter()
        why = ""
        try:
            if self.limits is None:
                out = self._eval(head + body + check).strip()
            else:
                with self.limits.query(self.ctx) as stopped:
                    out = self._eval(head + body + check).strip()
                    why = stopped()
        except z3.Z3Exception as exc:  # a malformed query is our bug
            self._eval("(pop)")
            raise InternalError(f"SMT query rejected: {exc}") from exc
        finally:
            self.seconds += time.perf_counter() - t0
        status = out.split()[-1] if out else "unknown"
        values: dict[str, Fraction] = {}
        approx: set[str] = set()
        if status == "sat" and want:
            got = parse_sexpr(self._eval(f"(get-value ({' '.join(want)}))"))[0]
            missing = []
            for name, val in got:
                v = numeral(val)
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
                for name, val in parse_sexpr(text)[0]:
                    v = numeral(val)
                    if v is None:
                        raise InternalError(f"cannot read Z3 value {val!r}")
                    values[name] = v[0]
                    approx.add(name)
        if status not in ("sat", "unsat"):
            status = "unknown"
            if not why:  # not stopped by the watchdog: "canceled" is nlsat's word for its rlimit
                info = self._eval("(get-info :reason-unknown)")
                why = "rlimit" if any(w in info for w in ("resource", "rlimit", "cancel")) else "incomplete"
            self.stopped[why] = self.stopped.get(why, 0) + 1
        self._eval("(pop)")
        if why == "interrupt":
            raise KeyboardInterrupt
        return SolverAnswer(status, values, frozenset(approx), why if status == "unknown" else "")


def tip_shift(zone: Zone, tool_axis: str | None) -> str | None:
    return tool_axis if zone.point is ZonePoint.TIP else None


def _context(z3: Any) -> Any:
    """A new ``z3.Context`` whose finaliser is quiet when its constructor did not finish: Ctrl-C or SIGTERM
    between Z3's ``Z3_mk_context_rc`` and ``self.owner = True`` left an object whose ``__del__`` raised
    ``AttributeError`` at exit ("Exception ignored in ... Context.__del__", a traceback on an interrupted
    run).  ``owner`` is False on the class, so such an object is not freed twice and says nothing (the
    process is ending; its context is the operating system's to free)."""
    return _quiet_context_class(z3)()


@functools.cache
def _quiet_context_class(z3: Any) -> Any:
    return type("QuietContext", (z3.Context,), {"owner": False})
