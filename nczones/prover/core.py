"""The prover's driver: tiers, queries, witnesses (DESIGN §5, §9).

Per segment, in execution order:

1. **Tier 1** — exact screens: a motion whose exact bounding box (arcs: exact
   extremes from the swept quadrant crossings, radii enclosed from above;
   splines: their control points) fits every zone is proved; straight
   pieces against boxes and stepped tables are then *decided* exactly in
   rational arithmetic (:mod:`nczones.prover.exact`); arcs of every kind are
   decided by exact enclosures of pieces of their sweep
   (:mod:`nczones.prover.arcs`), splines by the local hulls of their knot
   spans.  Column chunks are screened with numpy
   (:mod:`nczones.prover.screen`).
2. **Tier 2** — Z3 (:mod:`nczones.prover.smt`) for polygons, arcs the
   enclosures left open (tangencies), parameter ranges, and every flagged
   piece (its model is the witness); a query holds only the zones the
   motion's box does not fit.  ``engine="z3"`` sends every segment here.
3. **Tier 3** — over-approximations (helices, spirals) whose witness cannot
   be certified on the exact path are refined by splitting the sweep
   (:mod:`nczones.prover.refine`, budget 64 pieces / depth 8); what the
   budget cannot decide gives ``unknown`` with the reason.

Every solver query is bounded (rlimit and a time backstop), the run has a
budget, and Ctrl-C stops it (:mod:`nczones.prover.limits`); a motion a
limit stopped is ``unknown`` with that reason, never proved.

Invariants: ``SAFE`` only when every segment was proved; every reported
violation was re-checked with ``AllowedSet.violated_zones`` on an exact
path point (or, for irrational paths, a rational box that certainly holds
the exact point and certainly violates); a failed re-check raises
``InternalError`` instead of being reported.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from fractions import Fraction
from types import MappingProxyType

from ..errors import InternalError, InvalidArgument
from ..machine import Machine, RapidMode
from ..motion import Developed, MotionChunk, Segment, SegmentKind, tip_offset
from ..zones import BoxZone, PolygonZone, SteppedZone, Zone, ZonePoint, tip_shifted
from ..zones.kinds import KindTable
from . import exact as ex
from .exact import box_fits
from .geometry import (
    ArcGeom,
    LinePiece,
    angle_bounds,
    arc_bases,
    arc_geom,
    half_tan,
    in_sweep,
    line_pieces,
    on_start_ray,
    pi_bounds,
    rational_arc_plane_box,
    rational_point_on_arc,
    simple_in,
    sqrt_bounds,
    whole_turn_box,
)
from .result import Outcome, ParamRange, Reason, Result, Verdict, Violation, reason_code
from .smt import REFERENCE_AXIS, Solver, add, mul, or_all, q, sub, zone_violation

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from .limits import RunLimits
    from .options import VerifyOptions
    from .profile import RunProfile
    from .smt import SolverAnswer

#: Parameter deviations as the solver found them: ``(name, deviation)`` pairs.
Params = tuple[tuple[str, Fraction], ...]

__all__ = ["verify_segments", "prove", "Prover"]

F0 = Fraction(0)
F1 = Fraction(1)
#: Segments that come one by one are screened by columns this many at a time (:func:`verify_segments`).
SEGMENT_BATCH = 1024
#: A run screens segments by columns (numpy) only once it has met this many motions; a smaller program is
#: decided one by one on the exact path, which costs less than loading numpy (:func:`verify_segments`).
SCREEN_MIN_SEGMENTS = 512

#: Does the arcs' enclosure route (prover/arcs.py, taken when every zone says yes) decide arcs against this
#: zone?  Not against an allowed polygon.  Fallback: no (arcs go to the SMT tier).
ARC_ENCLOSURES: KindTable[Callable[[Any], bool]] = KindTable("prover.core.arc_enclosures", fallback=lambda z: False)
ARC_ENCLOSURES.set(BoxZone, lambda z: True)
ARC_ENCLOSURES.set(SteppedZone, lambda z: True)
ARC_ENCLOSURES.set(PolygonZone, lambda z: z.forbid)

#: Does Z3 re-check the exact tier's violation of this zone (for its witness parameter)?  Not a polygon's:
#: its encoding grows with the vertices (seconds for a thousand); the exact tier's witness stands, re-checked
#: by the zone's own membership test.  Fallback: yes.
Z3_CONFIRMS: KindTable[bool] = KindTable("prover.core.z3_confirms", fallback=True)
Z3_CONFIRMS.set(BoxZone, True)
Z3_CONFIRMS.set(SteppedZone, True)
Z3_CONFIRMS.set(PolygonZone, False)


class Prover:
    """Decides segments one by one for a machine, margin and parameter ranges."""

    #: The screen's zone constants by (zone, scale), made when first needed (:mod:`nczones.prover.screen`).
    screen_constants: dict | None = None

    def __init__(self, machine: Machine, *, margin: Fraction = F0, params: tuple[ParamRange, ...] = (),
                 engine: str = "auto", rlimit: int | None = None, limits: RunLimits | None = None):
        if engine not in ("auto", "z3"):
            raise InvalidArgument(f"engine must be 'auto' or 'z3', not {engine!r}")
        if margin < 0:
            raise InvalidArgument(f"margin must not be negative, got {margin}")
        self.machine = machine
        self.allowed = machine.allowed
        self.zones: tuple[Zone, ...] = machine.allowed.zones
        self.tool_axis = machine.allowed.tool_axis
        self.axes = machine.axis_names
        self.margin = Fraction(margin)
        self.params = tuple(params)
        self.engine = engine
        self.limits = limits
        self.solver = Solver(rlimit, limits=limits)
        self.stats = {"segments": 0, "pieces": 0, "screened": 0, "exact_decided": 0, "z3_segments": 0}
        self.pvars = {p.name: f"p{i}" for i, p in enumerate(self.params)}
        self.prange = {p.name: p for p in self.params}
        self.all_decidable = all(ex.decidable(z) for z in self.zones)
        #: box_fits can prove a box inside every zone (no allow polygon)
        self.boxable = all(ARC_ENCLOSURES.of(z)(z) for z in self.zones)
        self.has_tip_zones = any(z.point is ZonePoint.TIP for z in self.zones)
        self._tip_provers: dict[tuple, Prover] = {}
        #: the depth reported so far for each block that already is a violation (set by :func:`verify_segments`):
        #: a later motion of the block only matters when it is deeper (:meth:`_no_deeper`)
        self.known_depth: dict[int, Fraction] = {}
        self._violations_memo: dict[tuple[Any, ...], list[ex.ParamRange]] = {}  # _piece_violation's (self's zones)

    def _tip_prover(self, shift: dict[str, Fraction]) -> Prover:
        """The prover of segments whose tool tip is ``shift`` away from the machine position on axes besides
        the tool axis (a lathe tool offset in X): the tip zones moved by it, the solver and counts shared."""
        key = tuple(sorted(shift.items()))
        sub = self._tip_provers.get(key)
        if sub is None:
            from dataclasses import replace as _replace

            machine = _replace(self.machine, allowed=tip_shifted(self.machine.allowed, shift))
            sub = Prover(machine, margin=self.margin, params=self.params, engine=self.engine, limits=self.limits)
            sub.solver = self.solver
            sub.stats = self.stats
            sub.has_tip_zones = False
            self._tip_provers[key] = sub
        return sub

    # ------------------------------------------------------------------ params

    def _devs(self, seg: Segment, k: int, which: str) -> list[str]:
        """Parameter variables added to coordinate k at the start/end."""
        axis = self.axes[k]
        deps = seg.deps_start if which == "start" else seg.deps_end
        out = []
        if deps and k < len(deps):
            for src in deps[k]:
                name = f"{src}.{axis}" if not src.startswith("H") else src
                if name in self.pvars:
                    out.append(self.pvars[name])
        home = f"home.{axis}"
        if home in self.pvars:
            out.append(self.pvars[home])
        return out

    def _tool_dev(self, seg: Segment) -> list[str]:
        """Parameter variables added to the tool length: the sources the interpreter tracked
        (``Segment.deps_tool``), not the H register (a length the program wrote has none)."""
        out = []
        for src in seg.deps_tool:
            name = src if src.startswith("H") else f"{src}.{self.tool_axis}"
            if name in self.pvars:
                out.append(self.pvars[name])
        return out

    def param_relevant(self, seg: Segment) -> bool:
        if not self.params:
            return False
        if any(self._devs(seg, k, w) for k in range(len(self.axes)) for w in ("start", "end")):
            return True
        return bool(self._tool_dev(seg)) and any(z.point is ZonePoint.TIP for z in self.zones)

    def _param_decls(self) -> str:
        out = []
        for p in self.params:
            v = self.pvars[p.name]
            lo_rel = "<" if getattr(p, "lo_open", False) else "<="
            hi_rel = "<" if getattr(p, "hi_open", False) else "<="
            out.append(f"(declare-const {v} Real)(assert ({lo_rel} {q(p.lo)} {v}))(assert ({hi_rel} {v} {q(p.hi)}))")
        return "".join(out)

    def _param_slack(self, seg: Segment) -> Fraction:
        """Largest total |deviation| any coordinate of ``seg`` can get (for enclosures)."""
        if not self.params:
            return F0
        return sum((max(abs(p.lo), abs(p.hi)) for p in self.params), F0)

    def instantiate(self, seg: Segment, values: dict[str, Fraction]) -> Segment:
        """The concrete segment for parameter deviations ``values`` (param name -> deviation)."""
        def coords(which):
            base = seg.start if which == "start" else seg.end
            out = []
            for k, c in enumerate(base):
                dv = F0
                for var in self._devs(seg, k, which):
                    name = next(n for n, v in self.pvars.items() if v == var)
                    dv += values.get(name, F0)
                out.append(c + dv)
            return tuple(out)

        tl = seg.tool_length
        for var in self._tool_dev(seg):
            name = next(n for n, v in self.pvars.items() if v == var)
            tl += values.get(name, F0)
        centre = seg.centre
        if seg.kind is SegmentKind.ARC and centre is not None:
            ia, ib, _ = seg.plane_indices()
            s = coords("start")
            centre = (centre[0] + s[ia] - seg.start[ia], centre[1] + s[ib] - seg.start[ib])
        from dataclasses import replace

        return replace(seg, start=coords("start"), end=coords("end"), tool_length=tl, centre=centre,
                       deps_start=(), deps_end=())

    # ------------------------------------------------------------------ encodings

    def margin_decls(self, names: list[str]) -> tuple[str, dict[str, str]]:
        if self.margin == 0:
            return "", {a: "0.0" for a in self.axes}
        d = q(self.margin)
        out, evars = [], {}
        for k, a in enumerate(self.axes):
            v = f"e{k}"
            evars[a] = v
            out.append(f"(declare-const {v} Real)(assert (<= (- {d}) {v} {d}))")
            names.append(v)
        return "".join(out), evars

    def relevant_zones(self, lo_pt: Sequence[Fraction], hi_pt: Sequence[Fraction],
                       tool_length: Fraction) -> tuple[Zone, ...]:
        """The zones that the box spanned by two points does not fit (only they can be violated in it)."""
        lo = {a: min(x, y) for a, x, y in zip(self.axes, lo_pt, hi_pt)}
        hi = {a: max(x, y) for a, x, y in zip(self.axes, lo_pt, hi_pt)}
        return tuple(z for z in self.zones if not box_fits(self.allowed, lo, hi, self.margin, tool_length, (z,)))

    def violation_formula(self, pt: dict[str, str], tool_len: str, enclosure: Mapping[str, tuple[Fraction, Fraction]],
                           zones: Iterable[Zone] | None = None) -> str:
        parts = []
        for z in self.zones if zones is None else zones:
            seen = dict(pt)
            if z.point is ZonePoint.TIP and self.tool_axis in seen:
                seen[self.tool_axis] = sub(seen[self.tool_axis], tool_len)
            ref = None
            ref_axis = REFERENCE_AXIS(z)
            if ref_axis is not None:
                lo, hi = enclosure[ref_axis]
                if z.point is ZonePoint.TIP and ref_axis == self.tool_axis:
                    ref = None
                else:
                    ref = (lo - self.margin, hi + self.margin)
            parts.append(zone_violation(z, seen, ref))
        return or_all(parts)

    def _line_query(self, seg: Segment, piece: LinePiece, with_params: bool, zone: Zone | None = None,
                    t_max: Fraction | None = None) -> tuple[str, list[str]]:
        names = ["t"]
        body = ["(declare-const t Real)", f"(assert (<= 0.0 t {q(t_max if t_max is not None else F1)}))"]
        mdecl, evars = self.margin_decls(names)
        body.append(mdecl)
        if with_params:
            body.append(self._param_decls())
            names += [self.pvars[p.name] for p in self.params]
        pt = {}
        slack = self._param_slack(seg) if with_params else F0
        enclosure = {}
        for k, a in enumerate(self.axes):
            s0, s1 = piece.p0[k], piece.p1[k]
            if with_params:
                ds = add(*self._devs(seg, k, "start"))
                de = add(*self._devs(seg, k, "end"))
            else:
                ds = de = "0.0"
            start = add(q(s0), ds)
            if ds == de:
                coord = add(q(s0), mul("t", q(s1 - s0)), ds)
            else:
                coord = add(start, mul("t", sub(add(q(s1), de), start)))
            pt[a] = add(coord, evars[a])
            enclosure[a] = (min(s0, s1) - slack, max(s0, s1) + slack)
        tl = q(seg.tool_length)
        if with_params and self._tool_dev(seg):
            tl = add(tl, *self._tool_dev(seg))
        zones: tuple[Zone, ...]
        if zone is not None:
            zones = (zone,)
        elif with_params:
            zones = self.zones
        else:  # only the zones the piece's box does not fit can be violated on it
            zones = self.relevant_zones(piece.p0, piece.p1, seg.tool_length)
        body.append(f"(assert {self.violation_formula(pt, tl, enclosure, zones)})")
        return "".join(body), names

    def arc_query(self, seg: Segment, g: ArcGeom, with_params: bool,
                   w_dir: tuple[Fraction, Fraction] | None = None) -> tuple[str, list[str]]:
        """Encoding of an arc (exact for circular arcs, over-approximation for helices/spirals).

        ``w_dir`` (a rational direction from the centre) cuts the sweep off
        there, for the first-exit bisection.
        """
        names = ["x", "y"]
        body = ["(declare-const x Real)(declare-const y Real)"]
        if g.centre is not None:
            cx, cy = q(g.centre[0]), q(g.centre[1])
            u = (q(g.s[0] - g.centre[0]), q(g.s[1] - g.centre[1]))
            w = (q(g.e[0] - g.centre[0]), q(g.e[1] - g.centre[1]))
        else:
            names += ["cx", "cy"]
            body.append("(declare-const cx Real)(declare-const cy Real)")
            assert g.r_signed is not None  # an arc without a rational centre is an R-format arc
            r2 = q(g.r_signed * g.r_signed)
            sx, sy, ex_, ey = (q(v) for v in (*g.s, *g.e))
            body.append(f"(assert (= (+ (* (- {sx} cx) (- {sx} cx)) (* (- {sy} cy) (- {sy} cy))) {r2}))")
            body.append(f"(assert (= (+ (* (- {ex_} cx) (- {ex_} cx)) (* (- {ey} cy) (- {ey} cy))) {r2}))")
            _, _, _, _, _, sign = g.r_format_parts()
            chord = (g.e[0] - g.s[0], g.e[1] - g.s[1])
            side = f"(+ (* {q(chord[0])} (- cy {sy})) (* {q(-chord[1])} (- cx {sx})))"
            body.append(f"(assert ({'>' if sign > 0 else '<'} {side} 0.0))")
            cx, cy = "cx", "cy"
            u = (f"(- {sx} cx)", f"(- {sy} cy)")
            w = (f"(- {ex_} cx)", f"(- {ey} cy)")
        v = (f"(- x {cx})", f"(- y {cy})")
        rr = f"(+ (* {v[0]} {v[0]}) (* {v[1]} {v[1]}))"
        if g.r2_lo == g.r2_hi:
            body.append(f"(assert (= {rr} {q(g.r2_lo)}))")
        else:
            body.append(f"(assert (<= {q(g.r2_lo)} {rr} {q(g.r2_hi)}))")
        full = g.full and w_dir is None
        if w_dir is not None:
            w = (q(w_dir[0]), q(w_dir[1]))
        if not full:
            sa, sb = (u, w) if g.ccw else (w, u)  # ccw sweep from sa to sb
            hw = self._half_const(g, sa, sb, w_dir)
            cross_av = f"(- (* {sa[0]} {v[1]}) (* {sa[1]} {v[0]}))"
            dot_av = f"(+ (* {sa[0]} {v[0]}) (* {sa[1]} {v[1]}))"
            half0 = f"(or (> {cross_av} 0.0) (and (= {cross_av} 0.0) (> {dot_av} 0.0)))"
            cross_vb = f"(- (* {v[0]} {sb[1]}) (* {v[1]} {sb[0]}))"
            if hw == 0:
                body.append(f"(assert (and {half0} (>= {cross_vb} 0.0)))")
            else:
                body.append(f"(assert (or {half0} (>= {cross_vb} 0.0)))")
        mdecl, evars = self.margin_decls(names)
        body.append(mdecl)
        if with_params:
            body.append(self._param_decls())
            names += [self.pvars[p.name] for p in self.params]
        pt: dict[str, str] = {}
        slack = self._param_slack(seg) if with_params else F0
        (bx, by) = g.plane_bbox()
        enclosure: dict[str, tuple[Fraction, Fraction]] = {}
        for k, a in enumerate(self.axes):
            dev = add(*self._devs(seg, k, "start")) if with_params else "0.0"
            if k == g.ia:
                coord, enc = "x", bx
            elif k == g.ib:
                coord, enc = "y", by
            elif g.start[k] == g.end[k]:
                coord, enc = q(g.start[k]), (g.start[k], g.start[k])
            else:  # helix axis: anywhere between its start and end values
                hv = f"h{k}"
                names.append(hv)
                lo, hi = sorted((g.start[k], g.end[k]))
                body.append(f"(declare-const {hv} Real)(assert (<= {q(lo)} {hv} {q(hi)}))")
                coord, enc = hv, (lo, hi)
            pt[a] = add(coord, dev, evars[a])
            enclosure[a] = (enc[0] - slack, enc[1] + slack)
        tl = q(seg.tool_length)
        if with_params and self._tool_dev(seg):
            tl = add(tl, *self._tool_dev(seg))
        zones = None
        if not with_params:  # only the zones the arc's box does not fit can be violated
            zones = self.relevant_zones(tuple(enclosure[a][0] for a in self.axes),
                                        tuple(enclosure[a][1] for a in self.axes), seg.tool_length)
        body.append(f"(assert {self.violation_formula(pt, tl, enclosure, zones)})")
        return "".join(body), names

    @staticmethod
    def _half_const(g: ArcGeom, a: tuple[str, str], b: tuple[str, str], w_dir: Any) -> int:
        """Half (0: ccw angle a->b in [0, pi), 1: [pi, 2 pi)) — constant for every arc we encode."""
        if g.centre is not None or w_dir is not None:
            c = g.centre if g.centre is not None else None
            if c is not None:
                def val(t: str) -> Fraction:
                    return Fraction(eval_lit(t))
                av = (val(a[0]), val(a[1]))
                bv = (val(b[0]), val(b[1]))
                cr = av[0] * bv[1] - av[1] * bv[0]
                dt = av[0] * bv[0] + av[1] * bv[1]
                return 0 if cr > 0 or (cr == 0 and dt > 0) else 1
        # R-format: R > 0 is the arc of at most 180 degrees
        assert g.r_signed is not None
        return 0 if g.r_signed > 0 else 1

    # ------------------------------------------------------------------ deciding

    def checkpoint(self) -> None:
        """Raise :class:`~nczones.prover.limits.BudgetSpent` when the run's budget is spent (refinement loops)."""
        if self.limits is not None:
            self.limits.checkpoint()

    def unknown_outcome(self, seg: Segment, ans: SolverAnswer, what: str = "") -> Outcome:
        """The outcome of a solver ``unknown`` (its reason says which limit stopped it)."""
        return Outcome(reason=Reason(ans.reason(what), seg.span, seg.block, ans.code),
                        engine="budget" if ans.stopped == "budget" else "unknown")

    def check(self, seg: Segment) -> Outcome:
        """Decide one segment: a violation, a reason for ``unknown``, or neither (proved).

        When the run's budget is spent (:mod:`nczones.prover.limits`) before
        the segment is decided, the outcome's engine is ``"budget"``.
        """
        from .limits import BudgetSpent

        try:
            return self._check(seg)
        except BudgetSpent:
            return Outcome(reason=Reason("budget spent before this motion was decided", seg.span, seg.block,
                                          "VF203"), engine="budget")

    def _check(self, seg: Segment) -> Outcome:
        if seg.extra and self.has_tip_zones:
            shift = tip_offset(seg.extra)
            if shift:
                return self._tip_prover(shift).check(seg)
        self.stats["segments"] += 1
        if seg.payload(Developed) is not None:  # a line in G07.1 mode is proved on the developed surface
            return _decide_developed(self, seg)
        decide = DECIDERS.get(seg.kind)
        if decide is None:  # a kind no decider is registered for: never a silent safe
            return Outcome(reason=Reason(f"segment kind {getattr(seg.kind, 'name', seg.kind)} is not handled by the "
                                          "prover", seg.span, seg.block), engine="unknown")
        return decide(self, seg)

    def decide_point_path(self, seg: Segment) -> Outcome:
        """Lines, rapids, dwells and circular arcs: the exact tiers, then Z3 (with parameter ranges)."""
        if seg.kind is SegmentKind.ARC and on_start_ray(seg):
            return self._decide_whole_turn(seg, self.param_relevant(seg))
        if self.param_relevant(seg):
            return self.check_with_params(seg)
        return self.check_concrete(seg, ())

    def _decide_whole_turn(self, seg: Segment, ranged: bool) -> Outcome:
        """An I/J arc whose end lies on the ray from the centre through its start: proved by its whole turn's box.

        LinuxCNC (posemath ``pmCircleInit``) sweeps a whole turn there, a spiral from the start radius to the end
        radius (they differ within the arc tolerance), which no tier models point by point.  Soundness: every
        point of that turn is within the larger radius of the centre and the other axes move linearly from start
        to end, so :func:`~nczones.prover.geometry.whole_turn_box` holds the path (and the path of every other
        reading of such an arc, its docstring says why); when that box fits every zone (margin and tool length
        as :func:`~nczones.prover.exact.box_fits` applies them, tip zones already shifted by :meth:`_check`) the
        motion is proved.  With parameter ranges (``ranged``: the ends move, and with them the ray's condition)
        it is decided as an arc whose shape changes with them (:meth:`_check_arc_varying`): witnesses only at
        concrete values, the proof only by an enclosure that holds the arc at every value of the ranges, a whole
        turn included (the centre's range +- the largest radius); ``ranged`` is False for an arc instantiated
        at values (a ``home.*`` range names every segment, the instantiated ones too).  With ``engine="z3"`` (no solver encoding of the
        turn) the arc stays ``unknown``.  No witness is reported for the turn itself, since the spiral's points
        are not modelled exactly.  The column screen
        (:func:`nczones.prover.screen.screen_chunk`) boxes such an arc by a larger box (the whole circle grown
        by twice the radii's difference), so it never proves one this path would not.
        """
        if self.engine != "auto":
            why = "the solver has no encoding of it (engine z3)"
        elif ranged:
            return self._check_arc_varying(seg)
        else:
            lo, hi = whole_turn_box(seg)
            if box_fits(self.allowed, dict(zip(self.axes, lo)), dict(zip(self.axes, hi)), self.margin,
                        seg.tool_length):
                self.stats["screened"] += 1
                return Outcome(engine="exact")
            why = "its box (the centre +- the larger radius) does not fit"
        return Outcome(reason=Reason("arc whose end lies on the ray from the centre through its start (a "
                                      "different radius within the arc tolerance): LinuxCNC moves a whole spiral "
                                      f"turn, which is not modelled beyond its box, and {why}", seg.span,
                                      seg.block), engine="unknown")

    def check_with_params(self, seg: Segment) -> Outcome:
        self.stats["z3_segments"] += 1
        queries = []
        if seg.kind is SegmentKind.ARC:
            if any(self._devs(seg, k, "start") != self._devs(seg, k, "end") for k in range(len(self.axes))):
                return self._check_arc_varying(seg)
            queries.append(self.arc_query(seg, arc_geom(seg), True) + (True,))
        else:
            dogleg_varies = (seg.kind is SegmentKind.RAPID and self.machine.rapid_mode is RapidMode.DOGLEG
                             and tuple(self._devs(seg, k, "start") for k in range(len(self.axes)))
                             != tuple(self._devs(seg, k, "end") for k in range(len(self.axes))))
            if dogleg_varies:  # the breakpoints move with the parameters (exact, linear)
                queries.append(self._dogleg_query(seg) + (False,))
            else:
                bilinear = any(self._devs(seg, k, "start") != self._devs(seg, k, "end")
                               for k in range(len(self.axes)))
                for piece in line_pieces(seg, self.machine):
                    queries.append(self._line_query(seg, piece, True) + (bilinear,))
        for body, names, nonlinear in queries:
            ans = self.solver.check(body, names, nonlinear=nonlinear)
            if ans.status == "unsat":
                continue
            if ans.status == "unknown":
                return self.unknown_outcome(seg, ans)
            values = {p.name: _clamp(ans.values.get(self.pvars[p.name], F0), p.lo, p.hi) for p in self.params}
            concrete = self.instantiate(seg, values)
            out = self.check_concrete(concrete, tuple(values.items()))
            if out.violation is not None:
                return out
            return Outcome(reason=Reason("a parameter combination may violate a zone but no exact "
                                          "counterexample was confirmed", seg.span, seg.block), engine="unknown")
        return Outcome(engine="z3")

    def _dogleg_query(self, seg: Segment) -> tuple[str, list[str]]:
        """Exact encoding of a dogleg rapid whose two ends move with different parameters.

        Every axis starts at the same instant and runs at its own rapid rate
        ``v`` until it arrives: at time ``tau >= 0`` axis ``k`` stands at
        ``S + clamp(v tau)`` towards ``E``, i.e. ``S + min(v tau, E - S)``
        when ``E >= S`` and ``S + max(-v tau, E - S)`` otherwise, with ``S``
        and ``E`` the ends plus their parameter deviations.  The breakpoints
        move with the parameters, but every term is linear in ``tau`` and the
        parameters (``ite`` for min/max), so this is exact (QF_LRA): the point
        set over all ``tau`` and parameter values is exactly the union of the
        machine's dogleg paths (:func:`nczones.prover.geometry.line_pieces`).
        """
        names = ["tau"]
        body = ["(declare-const tau Real)(assert (<= 0.0 tau))"]
        mdecl, evars = self.margin_decls(names)
        body.append(mdecl)
        body.append(self._param_decls())
        names += [self.pvars[p.name] for p in self.params]
        slack = self._param_slack(seg)
        pt, enclosure = {}, {}
        for k, a in enumerate(self.axes):
            s0 = add(q(seg.start[k]), *self._devs(seg, k, "start"))
            e0 = add(q(seg.end[k]), *self._devs(seg, k, "end"))
            d = sub(e0, s0)
            vt = mul(q(self.machine.axis(a).rapid_mm_min), "tau")
            forward = f"(ite (<= {vt} {d}) {vt} {d})"
            backward = f"(ite (<= {d} (- {vt})) (- {vt}) {d})"
            pt[a] = add(s0, f"(ite (<= 0.0 {d}) {forward} {backward})", evars[a])
            enclosure[a] = (min(seg.start[k], seg.end[k]) - slack, max(seg.start[k], seg.end[k]) + slack)
        tl = add(q(seg.tool_length), *self._tool_dev(seg))
        body.append(f"(assert {self.violation_formula(pt, tl, enclosure)})")
        return "".join(body), names

    def _check_arc_varying(self, seg: Segment) -> Outcome:
        """An arc whose start and end move with different parameters (e.g. the first move from a
        ``start.X`` range): its shape changes with them, so it is decided on concrete values.

        The arc at the nominal values and at the corner values of its
        parameters (every combination of low, middle and high for up to
        three parameters; all low, all high, the middle and each one alone
        at its ends for more) is decided exactly (:meth:`_check_concrete`);
        a violation there is a real counterexample with those values.  An
        I/J arc whose end is no longer on its circle at some values is not
        a motion the controller makes there (it rejects the block), so those
        values give no counterexample.  When none violates, the whole range
        is proved by an enclosure that holds the arc for every value
        (:meth:`_varying_arc_box`), or the verdict is ``unknown``.
        """
        from itertools import product

        names = sorted({n for k in range(len(self.axes)) for w in ("start", "end")
                        for n, v in self.pvars.items() if v in self._devs(seg, k, w)}
                       | {n for n, v in self.pvars.items() if v in self._tool_dev(seg)})
        ranges = [self.prange[n] for n in names]

        # a case's open end (cases.py) is not one of its values: the middle stands in for it
        def low(p: ParamRange) -> Fraction:
            return (p.lo + p.hi) / 2 if p.lo_open else p.lo

        def high(p: ParamRange) -> Fraction:
            return (p.lo + p.hi) / 2 if p.hi_open else p.hi

        levels = [tuple(dict.fromkeys((low(p), (p.lo + p.hi) / 2, high(p)))) for p in ranges]
        if len(ranges) <= 3:
            combos = list(product(*levels))
        else:
            combos = [tuple(low(p) for p in ranges), tuple(high(p) for p in ranges),
                      tuple((p.lo + p.hi) / 2 for p in ranges)]
            for i, p in enumerate(ranges):
                for v in (low(p), high(p)):
                    combos.append(tuple(v if j == i else (q.lo + q.hi) / 2 for j, q in enumerate(ranges)))
        if all((p.lo < 0 or (p.lo == 0 and not p.lo_open)) and (0 < p.hi or (p.hi == 0 and not p.hi_open))
               for p in ranges):
            combos.insert(0, tuple(F0 for _ in ranges))
        first_reason = None
        for combo in dict.fromkeys(combos):
            self.checkpoint()
            values = dict(zip(names, combo))
            concrete = self.instantiate(seg, values)
            if concrete.centre is not None:
                ia, ib, _ = concrete.plane_indices()
                c = concrete.centre
                if ((concrete.start[ia] - c[0]) ** 2 + (concrete.start[ib] - c[1]) ** 2
                        != (concrete.end[ia] - c[0]) ** 2 + (concrete.end[ib] - c[1]) ** 2) and any(combo):
                    continue
            out = self.check_concrete(concrete, tuple(values.items()))
            if out.violation is not None:
                return out
            if out.reason is not None and first_reason is None:
                first_reason = out.reason
        lo_hi = self._varying_arc_box(seg)
        if lo_hi is not None and box_fits(self.allowed, lo_hi[0], lo_hi[1], self.margin, seg.tool_length):
            self.stats["screened"] += 1
            return Outcome(engine="exact")
        why = (f"; at one of them: {first_reason.message}" if first_reason is not None else "")
        return Outcome(reason=Reason("an arc whose start and end depend on different parameters: no "
                                      "counterexample at the corner values of the ranges, and its enclosure over "
                                      f"the whole ranges meets a zone boundary{why}", seg.span, seg.block),
                        engine="unknown")

    def _varying_arc_box(self, seg: Segment) -> tuple[dict, dict] | None:
        """A box holding the arc for every value of its parameters (None when a tip zone sees a
        varying tool length)."""
        if self._tool_dev(seg) and any(z.point is ZonePoint.TIP for z in self.zones):
            return None

        def dev(k, which):
            lo = hi = F0
            for var in self._devs(seg, k, which):
                p = self.prange[next(n for n, v in self.pvars.items() if v == var)]
                lo, hi = lo + p.lo, hi + p.hi
            return lo, hi

        ia, ib, _ = seg.plane_indices()
        lo, hi = {}, {}
        for k, a in enumerate(self.axes):
            s0, s1 = dev(k, "start")
            e0, e1 = dev(k, "end")
            lo[a] = min(seg.start[k] + s0, seg.end[k] + e0)
            hi[a] = max(seg.start[k] + s1, seg.end[k] + e1)
        if seg.centre is not None:
            # the centre moves with the start (I/J are offsets from it); the path stays within the larger of
            # the start radius and the largest end radius of the centre
            c = seg.centre
            (sa0, sa1), (sb0, sb1) = dev(ia, "start"), dev(ib, "start")
            (ea0, ea1), (eb0, eb1) = dev(ia, "end"), dev(ib, "end")
            gap = (max(abs(ea0 - sa1), abs(ea1 - sa0)), max(abs(eb0 - sb1), abs(eb1 - sb0)))
            r_s = sqrt_bounds((seg.start[ia] - c[0]) ** 2 + (seg.start[ib] - c[1]) ** 2, 64)[1]
            r_e = (sqrt_bounds((seg.end[ia] - c[0]) ** 2 + (seg.end[ib] - c[1]) ** 2, 64)[1]
                   + sqrt_bounds(gap[0] ** 2 + gap[1] ** 2, 64)[1])
            r = max(r_s, r_e)
            boxes = ((c[0] + sa0 - r, c[0] + sa1 + r), (c[1] + sb0 - r, c[1] + sb1 + r))
        elif seg.radius is not None:
            # the centre is within |R| of the start, the path within |R| of the centre; a positive R is
            # a minor arc (at most a half turn): it lies within its sagitta h of its chord, and h grows
            # with the chord, so the largest chord over the ranges bounds it
            r = 2 * abs(seg.radius)
            if seg.radius > 0 and not seg.turns:
                (sa0, sa1), (sb0, sb1) = dev(ia, "start"), dev(ib, "start")
                (ea0, ea1), (eb0, eb1) = dev(ia, "end"), dev(ib, "end")
                far = [max(abs(seg.end[k] + e1 - seg.start[k] - s0), abs(seg.start[k] + s1 - seg.end[k] - e0))
                       for k, s0, s1, e0, e1 in ((ia, sa0, sa1, ea0, ea1), (ib, sb0, sb1, eb0, eb1))]
                rest = seg.radius ** 2 - (far[0] ** 2 + far[1] ** 2) / 4
                if rest >= 0:
                    r = min(r, seg.radius - sqrt_bounds(rest, 64)[0])
            boxes = ((lo[self.axes[ia]] - r, hi[self.axes[ia]] + r), (lo[self.axes[ib]] - r, hi[self.axes[ib]] + r))
        else:
            return None
        for k, (b0, b1) in zip((ia, ib), boxes):
            a = self.axes[k]
            lo[a], hi[a] = min(lo[a], b0), max(hi[a], b1)
        return lo, hi

    def check_concrete(self, seg: Segment, params: Params) -> Outcome:
        if seg.kind is SegmentKind.ARC:
            if on_start_ray(seg):  # (a segment instantiated at a parameter combination, too)
                return self._decide_whole_turn(seg, False)
            return self._check_arc(seg, params)
        pieces = line_pieces(seg, self.machine)
        self.stats["pieces"] += len(pieces)
        # once the budget is spent the exact tier decides what it can, even for engine="z3"
        use_z3 = (self.engine == "z3" or not self.all_decidable) and not (
            self.all_decidable and self.limits is not None and self.limits.budget_spent())
        if self.engine == "auto" and all(self.bbox_fits(p.p0, p.p1, seg.tool_length) for p in pieces):
            self.stats["screened"] += 1
            return Outcome(engine="exact")
        for piece in pieces:
            if self.engine == "auto" and self.bbox_fits(piece.p0, piece.p1, seg.tool_length):
                continue
            if not use_z3:
                found = self._exact_line(seg, piece)
                if found is None:
                    continue
                self.stats["exact_decided"] += 1
                known = self.known_depth.get(seg.block)
                if known is not None and self._no_deeper(seg, pieces, known):
                    return Outcome(engine="exact")  # the block's violation stands as reported: nothing to add
                # Z3 confirms and provides the witness parameter (the exact tier's own parameter
                # once the budget is spent or when a limit stops the solver)
                t_model = None
                # a polygon's witness is the exact tier's, re-checked by the zone's own membership test
                # (the solver's polygon encoding grows with the vertices: seconds for a thousand)
                if (self.limits is None or not self.limits.budget_spent()) and all(
                        Z3_CONFIRMS.of(z) for z, _ in found):
                    body, names = self._line_query(seg, piece, False)
                    ans = self.solver.check(body, names)
                    if ans.status == "unsat":
                        raise InternalError(f"tier 1 and Z3 disagree on block {seg.block} ({ans.status})")
                    t_model = ans.values.get("t")
                return Outcome(self._line_violation(seg, piece, t_model, params, "exact"), engine="exact")
            self.stats["z3_segments"] += 1
            body, names = self._line_query(seg, piece, False)
            ans = self.solver.check(body, names)
            if ans.status == "unsat":
                continue
            if ans.status == "unknown":
                return self.unknown_outcome(seg, ans)
            return Outcome(self._line_violation(seg, piece, ans.values["t"], params, "z3"), engine="z3")
        return Outcome(engine="z3" if use_z3 else "exact")

    def bbox_fits(self, lo_pt: Sequence[Fraction], hi_pt: Sequence[Fraction], tool_length: Fraction,
                   lo_given: bool = False) -> bool:
        """Tier-1 screen: does the whole axis-aligned box spanned by two points fit (with margin)?"""
        lo = {a: min(x, y) for a, x, y in zip(self.axes, lo_pt, hi_pt)}
        hi = {a: max(x, y) for a, x, y in zip(self.axes, lo_pt, hi_pt)}
        return box_fits(self.allowed, lo, hi, self.margin, tool_length)

    def _exact_line(self, seg: Segment, piece: LinePiece) -> list | None:
        found = []
        for z in self.zones:
            iv = self._piece_violation(z, piece, seg.tool_length)
            if iv:
                found.append((z, iv))
        return found or None

    def _piece_violation(self, z: Zone, piece: LinePiece, tool_length: Fraction) -> list[ex.ParamRange]:
        """``ex.line_violation`` of ``z`` on ``piece``, kept for the pieces of the last few segments: a violating
        segment asks it of each piece up to four times (its decision, its first exit, its witness, its depth),
        and against a table of thousands of regions one answer costs as much as the rest of the segment."""
        key = (id(z), piece.p0, piece.p1, tool_length)
        memo = self._violations_memo
        got = memo.get(key)
        if got is None:
            if len(memo) >= 64:
                memo.clear()
            got = memo[key] = ex.line_violation(z, piece.p0, piece.p1, self.axes, self.margin, tool_length,
                                                self.tool_axis)
        return got

    def _no_deeper(self, seg: Segment, pieces: Sequence[LinePiece], known: Fraction) -> bool:
        """Is no violating piece of ``seg`` deeper than ``known`` (its block's reported depth)?  Then the
        violation :meth:`_line_violation` would build for it (a witness, a first exit, Z3's confirmation, the
        depth: a few ms a motion) changes nothing: :func:`verify_segments` keeps the block's first violation and
        only a greater depth.  Sound: each piece and zone's :func:`~nczones.prover.exact.line_depth_bound` is at
        least the depth :meth:`_line_violation` would find there, and a zone :func:`~nczones.prover.exact.
        decidable` does not decide answers no."""
        for pc in pieces:
            for z in self.zones:
                if not ex.decidable(z):
                    return False
                if ex.line_depth_bound(z, pc.p0, pc.p1, self.axes, self.margin, seg.tool_length,
                                       self.tool_axis) > known and \
                        self._piece_violation(z, pc, seg.tool_length):
                    return False
        return True

    def _line_violation(self, seg: Segment, piece: LinePiece, t_model: Fraction | None, params: Params,
                        engine: str) -> Violation:
        """Witness, first exit and depth of a violating straight piece (all exact)."""
        pieces = line_pieces(seg, self.machine)
        # first violating piece of the segment (the flagged one may not be the first)
        first_piece, first_t, first_exact = None, None, True
        for pc in pieces:
            per_zone = []
            for z in self.zones:
                if ex.decidable(z):
                    iv = self._piece_violation(z, pc, seg.tool_length)
                    if iv:
                        per_zone.append((iv[0].lo, z))
                else:
                    inf = self._bisect_line(seg, pc, z)
                    if inf is not None:
                        per_zone.append((inf, z))
                        first_exact = False
            if per_zone:
                first_piece = pc
                first_t = min(t for t, _ in per_zone)
                break
        if first_piece is None or first_t is None:
            raise InternalError(f"block {seg.block}: a violation was found but no violating parameter")
        t = t_model if t_model is not None else F0
        path = piece.at(t)
        pmap = dict(zip(self.axes, path))
        bad = self.allowed.violated_zones(pmap, seg.tool_length, self.margin)
        if not bad:  # the model point is not a violation: use the exact first interval
            for z in self.zones:
                if ex.decidable(z):
                    iv = self._piece_violation(z, piece, seg.tool_length)
                    if iv:
                        t = iv[0].sample()
                        break
            path = piece.at(t)
            pmap = dict(zip(self.axes, path))
            bad = self.allowed.violated_zones(pmap, seg.tool_length, self.margin)
            if not bad:
                raise InternalError(f"block {seg.block}: witness failed the exact re-check")
        zone = bad[0]
        outside = ex.outside_point(self.allowed, zone, pmap, self.margin, seg.tool_length)
        if outside is None or zone not in self.allowed.violated_zones(outside, seg.tool_length):
            raise InternalError(f"block {seg.block}: no point strictly outside inside the margin box")
        depth, depth_exact = F0, True
        for pc in pieces:
            for z in self.zones:
                dv, _, dex = ex.line_depth(z, pc.p0, pc.p1, self.axes, self.margin, seg.tool_length, self.tool_axis)
                if ex.decidable(z) and not self._piece_violation(z, pc, seg.tool_length):
                    continue
                if not ex.decidable(z) and z not in bad:
                    continue
                if dv > depth:
                    depth = dv
                depth_exact = depth_exact and dex
        return Violation(
            block=seg.block, span=seg.span, zone=zone.name,
            point=tuple((a, outside[a]) for a in self.axes),
            path_point=tuple(zip(self.axes, path)),
            parameter=piece.tau(t), parameter_exact=True,
            first_exit=tuple(zip(self.axes, first_piece.at(first_t))),
            first_exit_parameter=first_piece.tau(first_t), first_exit_exact=first_exact,
            depth=depth, depth_exact=depth_exact, engine=engine, segment_kind=seg.kind.name.lower(),
            derived=seg.derived, params=self.written_params(params), zones=tuple(z.name for z in bad),
        )

    def written_params(self, values: Params) -> tuple[tuple[str, Fraction], ...]:
        out = []
        for name, dev in values:
            p = self.prange[name]
            if p.absolute:  # a tool length: the machine's value is the nominal the path was built with
                out.append((name, self.machine.tool_length(int(name[1:])) + dev))
            else:
                out.append((name, p.centre + dev))
        return tuple(out)

    def _bisect_line(self, seg: Segment, piece: LinePiece, zone: Zone, steps: int = 40) -> Fraction | None:
        body, names = self._line_query(seg, piece, False, zone)
        if self.solver.check(body, names).status != "sat":
            return None
        lo, hi = F0, F1
        for _ in range(steps):
            mid = (lo + hi) / 2
            body, names = self._line_query(seg, piece, False, zone, t_max=mid)
            if self.solver.check(body, []).status == "sat":
                hi = mid
            else:
                lo = mid
        return lo

    # ------------------------------------------------------------------ arcs

    def _check_arc(self, seg: Segment, params: Params) -> Outcome:
        self.stats["pieces"] += 1
        plane = rational_arc_plane_box(seg) if self.engine == "auto" else None
        if plane is not None and self._arc_box_fits(seg, plane):
            return Outcome(engine="exact")  # arc_geom accepts such an arc (a radius): the same answer
        try:
            g = arc_geom(seg)
        except InvalidArgument as exc:
            return Outcome(reason=Reason(f"arc cannot be modelled: {exc}", seg.span, seg.block), engine="unknown")
        if self.engine == "auto":
            if plane is None and self._arc_box_fits(seg, (*g.plane_bbox(), g.ia, g.ib)):
                return Outcome(engine="exact")
            if self.boxable:
                # exact enclosures of pieces of the sweep (prover/arcs.py): most arcs end here
                from .arcs import decide_arc

                decided: Outcome | None = decide_arc(self, seg, g, params)
                if decided is not None:
                    self.stats["arc_enclosures"] = self.stats.get("arc_enclosures", 0) + 1
                    return decided
        self.stats["z3_segments"] += 1
        body, names = self.arc_query(seg, g, False)
        ans = self.solver.check(body, names, precision=60, nonlinear=True)
        if ans.status == "unsat":
            return Outcome(engine="z3")
        if ans.status == "unknown":
            return self.unknown_outcome(seg, ans, "an arc")
        v = self._arc_witness(seg, g, ans.values, params)
        if v is None and g.centre is not None and (g.helix or not g.exact):
            # split the sweep and prove the pieces (see prover/refine.py)
            from .refine import refine_arc

            refined: Outcome | None = refine_arc(self, seg, g, params)
            if refined is not None:
                return refined
        if v is None:
            what = "helix" if g.helix else ("R-format arc with an irrational centre" if g.centre is None else "spiral arc")
            if g.exact:
                what = "arc"
            return Outcome(reason=Reason(f"{what}: the solver found a possible violation that could not be "
                                          "confirmed on the exact path (over-approximation)", seg.span, seg.block),
                            engine="unknown")
        return Outcome(v, engine="z3")

    def _arc_box_fits(self, seg: Segment, plane: tuple) -> bool:
        """Does the box of ``seg`` (``plane``: ``((lo, hi), (lo, hi), ia, ib)`` of its plane path, the other axes
        from its ends) fit the allowed set?  Counted as screened when it does.  ``plane`` is
        ``arc_geom(seg).plane_bbox()`` or :func:`~nczones.prover.geometry.rational_arc_plane_box`, the same box
        computed in integers."""
        (bx, by, ia, ib) = plane
        lo = list(map(min, seg.start, seg.end))
        hi = list(map(max, seg.start, seg.end))
        lo[ia], hi[ia] = bx
        lo[ib], hi[ib] = by
        if box_fits(self.allowed, dict(zip(self.axes, lo)), dict(zip(self.axes, hi)), self.margin, seg.tool_length):
            self.stats["screened"] += 1
            return True
        return False

    def _arc_witness(self, seg: Segment, g: ArcGeom, values: dict[str, Fraction], params: Params) -> Violation | None:
        if not g.exact or g.helix:
            return self.arc_witness_enclosed(seg, g, values, params)
        c = g.centre
        assert c is not None  # exact
        u = (g.s[0] - c[0], g.s[1] - c[1])
        target = (values["x"] - c[0], values["y"] - c[1])
        for base in arc_bases(u, g.ccw):
            m = half_tan(base, target, g.ccw)
            if m is None or m < 0 or m > 1:
                continue
            pt2 = rational_point_on_arc(g, m, base)
            vdir = (pt2[0] - c[0], pt2[1] - c[1])
            if not in_sweep(u, (g.e[0] - c[0], g.e[1] - c[1]), vdir, g.ccw, g.full):
                continue
            coords = list(seg.start)
            coords[g.ia], coords[g.ib] = pt2
            pmap = dict(zip(self.axes, coords))
            bad = self.allowed.violated_zones(pmap, seg.tool_length, self.margin)
            if bad:
                return self.arc_violation(seg, g, pmap, bad, params, True)
        return None

    def arc_witness_enclosed(self, seg: Segment, g: ArcGeom, values: dict[str, Fraction], params: Params,
                              retry: bool = True) -> Violation | None:
        """Certify a witness on an irrational path with a rational box around the exact point."""
        if g.centre is None:
            (cxl, cxh), (cyl, cyh) = g.centre_bounds(120)
            c_mid = ((cxl + cxh) / 2, (cyl + cyh) / 2)
        else:
            cxl = cxh = g.centre[0]
            cyl = cyh = g.centre[1]
            c_mid = g.centre
        d = (values["x"] - c_mid[0], values["y"] - c_mid[1])
        n2 = d[0] * d[0] + d[1] * d[1]
        if n2 == 0:
            return None
        # exact path radius at this direction
        u = (g.s[0] - c_mid[0], g.s[1] - c_mid[1])
        w = (g.e[0] - c_mid[0], g.e[1] - c_mid[1])
        frac = None
        if g.helix or g.r2_lo != g.r2_hi:
            theta = angle_bounds(u, d, g.ccw)
            total = angle_bounds(u, w, g.ccw) if not g.full else (F0, F0)
            pi_lo, pi_hi = pi_bounds()
            tot_lo = total[0] + (2 * pi_lo * seg.turns if g.full or seg.turns else 0)
            tot_hi = total[1] + (2 * pi_hi * seg.turns if g.full or seg.turns else 0)
            if g.full and seg.turns == 0:
                tot_lo, tot_hi = 2 * pi_lo, 2 * pi_hi
            if tot_lo <= 0 or seg.turns:
                return None
            frac = (max(F0, theta[0] / tot_hi), min(F1, theta[1] / tot_lo))
        rho: tuple[Fraction, Fraction]
        if g.r2_lo != g.r2_hi:
            assert g.centre is not None and frac is not None  # a spiral: I/J (rational centre), sweep fractions set
            rs = sqrt_bounds((g.s[0] - g.centre[0]) ** 2 + (g.s[1] - g.centre[1]) ** 2, 120)
            re_ = sqrt_bounds((g.e[0] - g.centre[0]) ** 2 + (g.e[1] - g.centre[1]) ** 2, 120)
            radii = sorted([rs[0] + (re_[0] - rs[0]) * f for f in frac] + [rs[1] + (re_[1] - rs[1]) * f for f in frac])
            rho = (radii[0], radii[-1])
        else:
            r = abs(g.r_signed) if g.centre is None and g.r_signed is not None else None
            rho = sqrt_bounds(g.r2_lo, 120) if r is None else (r, r)
        dn = sqrt_bounds(n2, 120)
        lo: dict[str, Fraction] = {}
        hi: dict[str, Fraction] = {}
        for k, a in enumerate(self.axes):
            lo[a] = hi[a] = seg.start[k]
        for k, (cl, ch, comp) in ((g.ia, (cxl, cxh, d[0])), (g.ib, (cyl, cyh, d[1]))):
            a = self.axes[k]
            cands = [cc + rr * comp / nn for cc in (cl, ch) for rr in rho for nn in dn]
            lo[a], hi[a] = min(cands), max(cands)
        for k, a in enumerate(self.axes):
            if k in (g.ia, g.ib) or g.start[k] == g.end[k]:
                continue
            assert frac is not None  # a helix axis: the sweep fractions were set above
            vals = [g.start[k] + (g.end[k] - g.start[k]) * f for f in frac]
            lo[a], hi[a] = min(vals), max(vals)
        # the direction must lie strictly inside the sweep for every centre in the enclosure
        for cx in (cxl, cxh):
            for cy in (cyl, cyh):
                uu = (g.s[0] - cx, g.s[1] - cy)
                ww = (g.e[0] - cx, g.e[1] - cy)
                if not in_sweep(uu, ww, d, g.ccw, g.full):
                    return None
        for z in self.zones:
            if ex.box_certainly_violates(self.allowed, z, lo, hi, self.margin, seg.tool_length):
                mid = {a: simple_in(lo[a], hi[a]) for a in self.axes}
                bad = self.allowed.violated_zones(mid, seg.tool_length, self.margin)
                if z not in bad:
                    raise InternalError("certified box centre does not violate")
                width = max(hi[a] - lo[a] for a in self.axes)
                return self.arc_violation(seg, g, mid, bad, params, False,
                                           note=f"irrational path point; reported point within "
                                                f"{float(width):.1e} mm of it, the whole enclosure violates")
        if retry:  # the over-approximation's point was spurious: try exact directions along the arc
            c = c_mid
            base0 = (g.s[0] - c[0], g.s[1] - c[1])
            for base in arc_bases(base0, g.ccw):
                for i in range(33):
                    m = Fraction(i, 32)
                    cc = g.centre if g.centre is not None else c
                    u0 = base
                    perp = (-u0[1], u0[0]) if g.ccw else (u0[1], -u0[0])
                    den = 1 + m * m
                    p2 = (cc[0] + ((1 - m * m) * u0[0] + 2 * m * perp[0]) / den,
                          cc[1] + ((1 - m * m) * u0[1] + 2 * m * perp[1]) / den)
                    v = self.arc_witness_enclosed(seg, g, {"x": p2[0], "y": p2[1]}, params, False)
                    if v is not None:
                        return v
        return None

    def arc_violation(self, seg: Segment, g: ArcGeom, pmap: dict[str, Fraction], bad: Sequence[Zone],
                       params: Params, exact_point: bool, note: str = "") -> Violation:
        zone = bad[0]
        outside = ex.outside_point(self.allowed, zone, pmap, self.margin, seg.tool_length)
        if outside is None or zone not in self.allowed.violated_zones(outside, seg.tool_length):
            raise InternalError(f"block {seg.block}: no point strictly outside inside the margin box")
        param = self._arc_param(g, pmap)
        first_param, first_pt = param, pmap
        if g.exact:
            from .limits import BudgetSpent

            try:
                fp = self._arc_first_exit(seg, g, pmap)
            except BudgetSpent:  # the witness stands; the first exit is then the witness itself
                fp = None
            if fp is not None:
                first_pt = fp
                first_param = self._arc_param(g, fp)
        # depth: a lower bound from exact rational points along the arc
        depth = F0
        samples = [pmap, first_pt]
        if g.exact:
            assert g.centre is not None
            u = (g.s[0] - g.centre[0], g.s[1] - g.centre[1])
            for base in arc_bases(u, g.ccw):
                for i in range(0, 17):
                    p2 = rational_point_on_arc(g, Fraction(i, 16), base)
                    vdir = (p2[0] - g.centre[0], p2[1] - g.centre[1])
                    if in_sweep(u, (g.e[0] - g.centre[0], g.e[1] - g.centre[1]), vdir, g.ccw, g.full):
                        coords = list(seg.start)
                        coords[g.ia], coords[g.ib] = p2
                        samples.append(dict(zip(self.axes, coords)))
        samples.append(dict(zip(self.axes, seg.start)))
        samples.append(dict(zip(self.axes, seg.end)))
        for p in samples:
            for z in self.allowed.violated_zones(p, seg.tool_length, self.margin):
                depth = max(depth, ex.point_depth(z, self.allowed.seen_by(z, p, seg.tool_length), self.margin))
        return Violation(
            block=seg.block, span=seg.span, zone=zone.name,
            point=tuple((a, outside[a]) for a in self.axes),
            path_point=tuple((a, pmap[a]) for a in self.axes),
            parameter=param, parameter_exact=False,
            first_exit=tuple((a, first_pt[a]) for a in self.axes), first_exit_parameter=first_param,
            first_exit_exact=False, depth=depth, depth_exact=False, engine="z3",
            segment_kind="arc" if not g.helix else "helix", derived=seg.derived,
            params=self.written_params(params), zones=tuple(z.name for z in bad), note=note,
            on_path=exact_point,
        )

    def _arc_param(self, g: ArcGeom, pmap: dict[str, Fraction]) -> Fraction:
        """Fraction of the swept angle at a point (approximate, for reports)."""
        c = g.centre if g.centre is not None else tuple((a + b) / 2 for a, b in g.centre_bounds(60))
        u = (g.s[0] - c[0], g.s[1] - c[1])
        v = (pmap[self.axes[g.ia]] - c[0], pmap[self.axes[g.ib]] - c[1])
        th = angle_bounds(u, v, g.ccw)[0]
        if g.full:
            tot = 2 * pi_bounds()[0]
        else:
            tot = angle_bounds(u, (g.e[0] - c[0], g.e[1] - c[1]), g.ccw)[0]
        if tot <= 0:
            return F0
        return min(F1, th / tot).limit_denominator(10**9)

    def _arc_first_exit(self, seg: Segment, g: ArcGeom, witness: dict[str, Fraction]) -> dict | None:
        """Bisection over rational points of the arc: the last point before which no violation exists.

        Returns the exact path point at the upper end of the final bracket
        (a violation exists in the closed sub-arc from the start to it; none
        exists up to the lower end, 2**-24 of a quarter turn earlier).
        """
        c = g.centre
        assert c is not None  # exact arcs only
        u = (g.s[0] - c[0], g.s[1] - c[1])
        w = (g.e[0] - c[0], g.e[1] - c[1])
        bases = arc_bases(u, g.ccw)

        def point(k: int, m: Fraction) -> tuple[Fraction, Fraction]:
            return rational_point_on_arc(g, m, bases[k])

        def violates_up_to(k: int, m: Fraction) -> bool:
            p2 = point(k, m)
            dirv = (p2[0] - c[0], p2[1] - c[1])
            if dirv == u:
                coords = list(seg.start)
                return bool(self.allowed.violated_zones(dict(zip(self.axes, coords)), seg.tool_length, self.margin))
            body, names = self.arc_query(seg, g, False, w_dir=dirv)
            return self.solver.check(body, [], nonlinear=True).status == "sat"

        # find the quarter containing the first violation
        for k in range(4):
            end_dir = (point(k, F1)[0] - c[0], point(k, F1)[1] - c[1])
            last = not in_sweep(u, w, end_dir, g.ccw, g.full) or (not g.full and end_dir == w)
            if last or violates_up_to(k, F1):
                lo, hi = F0, F1
                for _ in range(24):
                    mid = (lo + hi) / 2
                    p2 = point(k, mid)
                    if not in_sweep(u, w, (p2[0] - c[0], p2[1] - c[1]), g.ccw, g.full) and not g.full:
                        hi = mid
                        continue
                    if violates_up_to(k, mid):
                        hi = mid
                    else:
                        lo = mid
                p2 = point(k, hi)
                coords = list(seg.start)
                coords[g.ia], coords[g.ib] = p2
                return dict(zip(self.axes, coords))
        return None


def _decide_developed(prover: Prover, seg: Segment) -> Outcome:
    from .cylindrical import check_cylindrical  # G07.1: pi enclosed, see prover/cylindrical.py

    out: Outcome = check_cylindrical(prover, seg)
    return out


def _decide_polar(prover: Prover, seg: Segment) -> Outcome:
    from .polar import (
        check_polar,  # G12.1: square roots and arc tangents enclosed, see prover/polar.py
    )

    out: Outcome = check_polar(prover, seg)
    return out


def _decide_spline(prover: Prover, seg: Segment) -> Outcome:
    from .spline import (
        check_spline,  # exact NURBS: control hulls + refinement, see prover/spline.py
    )

    out: Outcome = check_spline(prover, seg)
    return out


#: The decider of each motion kind: the prover's tiers for it, exact first, Z3 only for what remains
#: (docs/design.md §10 "How to add a motion kind"; tests/prover/test_segment_kinds.py crosses every kind).
DECIDERS: Mapping[SegmentKind, Callable[[Prover, Segment], Outcome]] = MappingProxyType({
    SegmentKind.LINE: Prover.decide_point_path,
    SegmentKind.ARC: Prover.decide_point_path,
    SegmentKind.RAPID: Prover.decide_point_path,
    SegmentKind.DWELL: Prover.decide_point_path,
    SegmentKind.DEVELOPED_ARC: _decide_developed,
    SegmentKind.SPLINE: _decide_spline,
    SegmentKind.POLAR: _decide_polar,
})


def eval_lit(text: str) -> Fraction:
    """Value of a literal produced by :func:`nczones.prover.smt.q`."""
    from .smt import numeral, parse_sexpr

    v = numeral(parse_sexpr(text)[0])
    assert v is not None, f"not a literal: {text}"
    return v[0]


def _clamp(x: Fraction, lo: Fraction, hi: Fraction) -> Fraction:
    return max(lo, min(hi, x))


def prove(motion: Iterable[Segment | MotionChunk], machine: Machine, options: VerifyOptions, *, file: str = "",
          profile: RunProfile | None = None) -> Result:
    """Prove ``motion`` (segments or chunks in execution order) against ``machine`` with the options' margin,
    parameter ranges (:class:`~nczones.prover.result.ParamRange` values), engine, violation limit and run
    limits: :func:`verify_segments` with the settings of one :class:`~nczones.prover.options.VerifyOptions`.
    The prover never reads program text; :mod:`nczones.pipeline` turns a program into motion first.

    A machine with tool and fixture solids (:mod:`nczones.solids`) also has every motion's swept tool solids
    proved against its fixtures (:mod:`nczones.prover.solids`), and the two results are joined."""
    from ..machine import declares_solids

    if declares_solids(machine):
        from ..solids import machine_solids
        from .solids import prove_with_solids

        solids = machine_solids(machine)
        assert solids is not None  # declares_solids is machine_solids' own test
        return prove_with_solids(motion, machine, solids, options, verify_segments, file=file, profile=profile)
    return verify_segments(motion, machine, margin=options.margin, params=options.ranges(machine),
                           engine=options.engine, max_violations=options.max_violations, file=file,
                           limits=options.run_limits(), profile=profile)


def _deepen(violations: list[Violation], block: int, found: Violation, known: dict[int, Fraction]) -> None:
    """A later violation ``found`` of ``block``, already reported: the report's depth raised when ``found`` is
    deeper (its exactness then both's), and the prover told (:attr:`Prover.known_depth`)."""
    old = next(i for i, v in enumerate(violations) if v.block == block)
    if found.depth > violations[old].depth:
        from dataclasses import replace

        violations[old] = replace(violations[old], depth=found.depth,
                                  depth_exact=violations[old].depth_exact and found.depth_exact)
        known[block] = found.depth


def verify_segments(
    segments: Iterable[Segment | MotionChunk],
    machine: Machine,
    *,
    margin: Fraction | int = 0,
    params: tuple[ParamRange, ...] = (),
    engine: str = "auto",
    max_violations: int = 20,
    notes: tuple[str, ...] = (),
    unsupported: Iterable[Any] = (),
    file: str = "",
    budget_s: float | None = None,
    limits: RunLimits | None = None,
    profile: RunProfile | None = None,
) -> Result:
    """Verify motion segments (no G-code text needed) against a machine's zones.

    Parameters
    ----------
    segments : iterable of Segment or MotionChunk
        In execution order (machine coordinates, exact).
    machine : Machine
        Its zones, rapid mode and axes.
    margin : Fraction
        Required clearance ``d`` (the box of half-width ``d`` around every
        path point must fit).
    params : tuple of ParamRange
        Parameter ranges (see :func:`nczones.prover.parse_param`); segments
        need ``deps_start``/``deps_end`` for offset and start parameters.
    engine : "auto" or "z3"
    max_violations : int
        Stop after this many violating blocks (the verdict is then already
        ``unsafe``; ``Result.truncated`` says so).
    budget_s : float or None
        Seconds for the run's solver work and refinement (default
        :data:`~nczones.prover.limits.DEFAULT_BUDGET_S`; see
        :mod:`nczones.prover.limits`); motions that would need more are
        ``unknown`` ("budget spent"), the exact tiers still check the rest.
    limits : RunLimits, optional
        Use these limits (budget, time backstop, Ctrl-C) instead of new ones.
    profile : RunProfile, optional
        Filled while the run goes (:mod:`nczones.prover.profile`; the
        progress bar reads it); a new one otherwise.  ``Result.profile`` is
        its summary.

    A ``KeyboardInterrupt`` (Ctrl-C) ends the run with a partial result:
    ``Result.interrupted`` is True and the verdict is ``unsafe`` when a
    violation was already found, otherwise ``unknown``.

    Returns
    -------
    Result

    Examples
    --------
    >>> from nczones.machine import parse_machine
    >>> from nczones.motion import Segment, SegmentKind
    >>> m = parse_machine('''
    ... [machine]
    ... axes = ["X", "Y"]
    ... [machine.rapid]
    ... X = "1000"
    ... Y = "1000"
    ... [machine.reference]
    ... X = "0"
    ... Y = "5"
    ... [[zones]]
    ... name = "table"
    ... kind = "stepped"
    ... reference_axis = "X"
    ... limited_axis = "Y"
    ... from = "0"
    ... regions = [{upto = "10", min = "5"}, {upto = "20", min = "0"}, {upto = "30", min = "5"}]
    ... ''')
    >>> F = Fraction
    >>> line = Segment(SegmentKind.LINE, (F(5), F(6)), (F(25), F(2)), ("X", "Y"), block=0)
    >>> r = verify_segments([line], m)
    >>> r.verdict.label, r.violations[0].zone, str(r.violations[0].first_exit_parameter)
    ('unsafe', 'table', '3/4')
    """
    from .limits import DEFAULT_BUDGET_S, RunLimits
    from .profile import RunProfile

    t0 = time.perf_counter()
    if limits is None:
        limits = RunLimits(DEFAULT_BUDGET_S if budget_s is None else budget_s)
    if profile is None:
        profile = RunProfile()
    clock = time.perf_counter
    prover = Prover(machine, margin=Fraction(margin), params=params, engine=engine, limits=limits)
    violations: list[Violation] = []
    reasons: list[Reason] = []
    engines: dict[int, str] = {}
    seen_blocks: set[int] = set()
    truncated = False
    interrupted = False
    undecided: list[Segment] = []  # motions the spent budget left undecided (first one kept)
    n_undecided = 0
    last_line: list[int | None] = [None]
    met = 0  # motions met so far: columns from SCREEN_MIN_SEGMENTS on

    def handle(seg: Segment, from_chunk: bool = False) -> bool:
        nonlocal n_undecided
        if seg.span is not None:
            last_line[0] = seg.span.line
        if seg.block in seen_blocks and limits.budget_spent():
            # the block is already a violation: its other motions would only deepen its reported depth (an
            # exact depth costs tens of ms a motion, and one canned-cycle block may hold 100,000 holes); past
            # the budget the depth stays a lower bound, marked inexact
            old = next(i for i, v in enumerate(violations) if v.block == seg.block)
            if violations[old].depth_exact:
                from dataclasses import replace

                violations[old] = replace(violations[old], depth_exact=False)
            return True
        started = clock()
        out = prover.check(seg)
        profile.decided(seg, clock() - started, counted=not from_chunk)
        if out.engine == "budget":
            n_undecided += 1
            if not undecided:
                undecided.append(seg)
                engines.setdefault(seg.block, "unknown")
                assert out.reason is not None  # a budget outcome carries its VF203 reason
                reasons.append(out.reason)  # placeholder, replaced by the summary below
            return True
        if out.violation is not None or out.reason is not None:
            engines.setdefault(seg.block, out.engine)
        if out.violation is not None:
            if seg.block in seen_blocks:
                _deepen(violations, seg.block, out.violation, prover.known_depth)
                return True
            if len(violations) >= max_violations:
                return False
            seen_blocks.add(seg.block)
            v = out.violation
            prover.known_depth[seg.block] = v.depth
            if seg.frame is not None and v.frame is None:  # for the program point, reports only
                from dataclasses import replace

                v = replace(v, frame=seg.frame)
            violations.append(v)
        elif out.reason is not None:
            reasons.append(out.reason)
        return True

    # segments that come one by one (the full interpreter's, a caller's) are screened in batches
    batch: list[Segment] = []
    batch_size = SEGMENT_BATCH if engine == "auto" else 0

    def flush() -> bool:
        """Decide the batched segments in order: the column screen first (in a run that has met
        :data:`SCREEN_MIN_SEGMENTS` motions), the rest one by one."""
        segs = batch[:]
        batch.clear()
        proved: set[int] = set()
        in_chunk: set[int] = set()
        started = clock()
        if met >= SCREEN_MIN_SEGMENTS:
            from .screen import screen_chunk, segment_columns

            columns = segment_columns(segs, prover)
        else:
            columns = []
        for chunk, rows in columns:
            flagged = screen_chunk(chunk, prover)
            profile.screened(chunk, len(flagged), clock() - started)
            n_proved = len(rows) - len(flagged)
            prover.stats["screened"] += n_proved
            prover.stats["segments"] += n_proved
            in_chunk.update(rows)
            proved.update(rows)
            proved.difference_update(rows[k] for k in flagged)
            started = clock()
        for i, seg in enumerate(segs):
            if i in proved:
                if seg.span is not None:
                    last_line[0] = seg.span.line
                continue
            if not handle(seg, i in in_chunk):
                return False
        return True

    try:
        with limits.watch():
            for item in segments:
                met += 1 if isinstance(item, Segment) else len(item)
                if isinstance(item, Segment) and batch_size:
                    batch.append(item)
                    if len(batch) >= batch_size and not flush():
                        truncated = True
                        break
                    continue
                if isinstance(item, MotionChunk) and item.scale is None and batch_size:
                    batch.extend(item.segments())
                    if len(batch) >= batch_size and not flush():
                        truncated = True
                        break
                    continue
                if batch and not flush():
                    truncated = True
                    break
                if isinstance(item, MotionChunk):
                    if len(item) and item.scale is not None and item.line is not None:
                        last_line[0] = int(item.line[0])
                    from_chunk = item.scale is not None and engine == "auto" and not prover.params
                    if from_chunk:
                        from .screen import screen_chunk

                        n = len(item)
                        started = clock()
                        flagged = screen_chunk(item, prover)
                        profile.screened(item, len(flagged), clock() - started)
                        prover.stats["screened"] += n - len(flagged)
                        prover.stats["segments"] += n - len(flagged)
                        it: Iterable[Segment] = _chunk_rows(item, flagged)
                    else:
                        it = item.segments()
                    for seg in it:
                        if not handle(seg, from_chunk):
                            truncated = True
                            break
                    if not truncated and len(item) and item.scale is not None and item.line is not None:
                        last_line[0] = int(item.line[-1])
                else:
                    if not handle(item):
                        truncated = True
                if truncated:
                    break
            if batch and not truncated and not flush():
                truncated = True
    except KeyboardInterrupt:
        interrupted = True
    if undecided:
        first = undecided[0]
        where = reasons.index(next(r for r in reasons if r.code == "VF203" and r.block == first.block))
        reasons[where] = Reason(
            f"budget of {limits.budget_s:g} s spent after {limits.spent_at or limits.elapsed():.1f} s: "
            f"{n_undecided} motion{'s' if n_undecided != 1 else ''} needing solver work or refinement "
            f"{'were' if n_undecided != 1 else 'was'} not decided, the first here (the exact tiers checked the "
            "rest; raise --budget to decide them)", first.span, first.block, "VF203")
    if interrupted:
        line = last_line[0]
        reasons.append(Reason(
            f"interrupted (Ctrl-C) after {limits.elapsed():.1f} s"
            + (f" near line {line}" if line is not None else "")
            + ": the rest of the program was not checked", None, None, "VF204"))
    for u in unsupported:
        named, message = getattr(u, "code", ""), getattr(u, "message", str(u))
        if reason_code(named) != named and not message.startswith(named + ": "):
            message = f"{named}: {message}"  # the construct stays named when the code is the scheme's
        reasons.append(Reason(message, getattr(u, "span", None), None, reason_code(named)))
    if violations:
        verdict = Verdict.UNSAFE
    elif reasons:
        verdict = Verdict.UNKNOWN
    else:
        verdict = Verdict.SAFE
    summary = profile.as_dict(prover.solver)
    profile.solver_done(prover.solver)
    stats = dict(prover.stats)
    stats["z3_queries"] = prover.solver.queries
    stats.update({f"solver_stopped_{k}": v for k, v in sorted(prover.solver.stopped.items())})
    if n_undecided:
        stats["budget_undecided"] = n_undecided
    return Result(
        verdict=verdict, violations=tuple(violations), reasons=tuple(reasons),
        engines=tuple(sorted(engines.items())), solver="z3", solver_version=prover.solver.version,
        timings=(("prove_s", time.perf_counter() - t0),), notes=tuple(notes),
        stats=tuple(stats.items()), margin=Fraction(margin), params=tuple(params), engine=engine,
        truncated=truncated, file=file, interrupted=interrupted, budget_s=limits.budget_s,
        profile=summary,
    )


def _chunk_rows(chunk: MotionChunk, rows: Iterable[int]) -> Iterator[Segment]:
    """Segment views of selected rows of a column chunk."""
    from ..errors import SourceSpan
    from ..motion import Plane

    assert chunk.scale is not None and chunk.kind is not None and chunk.line is not None \
        and chunk.start is not None and chunk.end is not None and chunk.block is not None \
        and chunk.tool_length is not None, "the columns form"
    den = 10**chunk.scale
    if chunk.objects is not None:  # columns with their segments (MotionChunk): the segments themselves
        objects = chunk.objects
        for i in rows:
            yield objects[i]
        return
    for i in rows:
        kind = SegmentKind(int(chunk.kind[i]))
        line_no = int(chunk.line[i])
        span = SourceSpan(chunk.file, line_no, 1, None, "")
        start = tuple(Fraction(int(v), den) for v in chunk.start[i])
        end = tuple(Fraction(int(v), den) for v in chunk.end[i])
        arc: dict[str, Any] = {}
        if kind is SegmentKind.ARC:
            assert chunk.plane is not None and chunk.clockwise is not None and chunk.centre is not None \
                and chunk.turns is not None
            arc = dict(plane=Plane(int(chunk.plane[i])), clockwise=bool(chunk.clockwise[i]),
                       centre=(Fraction(int(chunk.centre[i, 0]), den), Fraction(int(chunk.centre[i, 1]), den)),
                       turns=int(chunk.turns[i]))
            if chunk.radius is not None and chunk.radius[i]:  # an R-format arc: its centre is not in the columns
                arc["centre"], arc["radius"] = None, Fraction(int(chunk.radius[i]), den)
        if chunk.derived is not None:  # canned-cycle rows name what produced them (reports)
            arc["derived"] = str(chunk.derived[i])
        yield Segment(kind, start, end, chunk.axes, int(chunk.block[i]), span,
                      Fraction(int(chunk.tool_length[i]), den), None, **arc, frame=chunk.frame)
