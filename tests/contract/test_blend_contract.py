"""The controller's blended corners lie in the prover's enclosure (issue 35, specs/path-modes.md §5).

The reference controller rounds G64 corners with LinuxCNC's blend arcs (``nczones.controller.blending``,
written from ``src/emc/tp``, independent of the prover).  For generated corners next to a forbidden box:

1. every pulse position the controller moves through on a blend arc lies in the enclosure the spec states,
   checked exactly in rationals with a sound tolerance of one pulse per axis (rounding an arc point to the
   nearest pulse moves it by at most half a pulse per axis):
   * ``G64``: ``C + a (M1 - C) + b (M2 - C)``, ``a, b`` in ``[0, 1]`` (M1, M2 the motions' midpoints); a point
     within one pulse (per axis) of it has ``a`` within ``pulse * |row_a(A^-1)|_1`` of ``[0, 1]`` (A the matrix
     of the two half motions), likewise ``b``;
   * ``G64 P p`` (Q defaults to P): within ``p + q`` (per axis) of the two motions, plus one pulse;
2. verdicts agree: a controller alarm means the prover did not say ``safe``; a probe box around a pulse
   position of a blend arc (the controller certainly passes it, so it alarms) is never proved ``safe``.

Mutations that shrink the enclosure (the blend start bound ``BLEND_FRACTION`` halved, the tolerance band cut
to a quarter of P with no naive-CAM Q) make clause 2 fail on fixed deep corners.  The same clauses run on
chains with arcs and on naive-CAM runs below, each with its mutation (an arc's part shrunk to the corner, the
naive-CAM q dropped).
"""

from __future__ import annotations

import dataclasses
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller import simulate
from nczones.controller.blending import BlendArc, arc_pulse_positions, blend_motion
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from nczones.prover import blend as blend_module
from nczones.prover import verify_text
from tests.machines import box_zone, machine_text

PULSE = Fraction(1, 1000)
HALF = Fraction(1, 200)  # the probe box's half-width


def _machine(kin, box):
    vx, vy, ax, ay = kin
    (x0, y0), (x1, y1) = box
    clamp = box_zone("clamp", {"X": _dec(x0), "Y": _dec(y0), "Z": "-10"}, {"X": _dec(x1), "Y": _dec(y1), "Z": "10"},
                     forbid=True)
    return parse_machine(machine_text("xyz_table_400_accel", extra=clamp, set={
        "machine.rapid.X": vx, "machine.rapid.Y": vy, "machine.acceleration.X": ax, "machine.acceleration.Y": ay}))


def _dec(q: Fraction) -> str:
    return str(Decimal(q.numerator) / Decimal(q.denominator))


def _program(p0, c, p1, feed, mode):
    return (f"G61\nG0 X{p0[0]} Y{p0[1]}\n{mode}\nG1 F{feed} X{c[0]} Y{c[1]}\nG1 X{p1[0]} Y{p1[1]}\nG61\nG4 P0\n")


def _arcs(text, machine):
    """The blend arcs of the program with the pulse positions the controller moves through (integer pulses)."""
    run = interpret_text(text, machine, fast=False)
    segs = list(run.segments())
    prog = [round(v / PULSE) for v in segs[0].start]
    out = []
    for item in blend_motion(segs, machine, run):
        if isinstance(item, BlendArc) and item.label == "G64 blend arc":
            pos = arc_pulse_positions(item, [a.pulse for a in machine.axes], prog)
            out.append((item, pos))
            prog = [int(v) for v in pos[-1]] if len(pos) else prog
        else:  # a motion, or an arc trimmed by blends (on the programmed path): the walk ends at its end
            prog = [round(Fraction(v) / PULSE) for v in item.end]
    return out


def _in_parallelogram(p0, c, p1, pos) -> bool:
    """Every row of ``pos`` (pulses) within one pulse (per axis) of C + a (M1 - C) + b (M2 - C), a, b in [0, 1].

    Exact, in integers: with D1 = P0 - C, D2 = P1 - C in pulses (M - C = D / 2), det = D1 x D2, a point r - C
    has a = 2 (r x D2) / det, b = 2 (D1 x r) / det, and moving it by one pulse per axis changes a by at most
    2 |D2|_1 / |det| (b: 2 |D1|_1 / |det|).  Z stays within one pulse of 0."""
    k = int(1 / PULSE)
    d1 = [(p0[i] - c[i]) * k for i in range(2)]
    d2 = [(p1[i] - c[i]) * k for i in range(2)]
    det = d1[0] * d2[1] - d1[1] * d2[0]
    sgn = 1 if det > 0 else -1
    rx, ry = pos[:, 0] - c[0] * k, pos[:, 1] - c[1] * k
    a2 = 2 * sgn * (rx * d2[1] - ry * d2[0])
    b2 = 2 * sgn * (d1[0] * ry - d1[1] * rx)
    ea, eb = 2 * (abs(d2[0]) + abs(d2[1])), 2 * (abs(d1[0]) + abs(d1[1]))
    ok = (a2 >= -ea) & (a2 <= abs(det) + ea) & (b2 >= -eb) & (b2 <= abs(det) + eb) & (abs(pos[:, 2]) <= 1)
    return bool(ok.all())


def _near_path(p0, c, p1, pos, band) -> bool:
    """Every row of ``pos`` (pulses) within ``band`` plus one pulse (per axis) of one of the two motions.

    Per motion S + t D, t in [0, 1], the window of t where each axis is within the band; floats on integers
    below 10**6 with a slack of 1e-6 pulse (far below the pulse of tolerance)."""
    k = int(1 / PULSE)
    r = float(band * k) + 1 + 1e-6
    hit = np.zeros(len(pos), dtype=bool)
    for s, e in ((p0, c), (c, p1)):
        lo, hi = np.zeros(len(pos)), np.ones(len(pos))
        for i in range(2):
            si, di, q = s[i] * k, (e[i] - s[i]) * k, pos[:, i].astype(float)
            if di == 0:
                bad = np.abs(q - si) > r
                lo, hi = np.where(bad, 2.0, lo), np.where(bad, -1.0, hi)
                continue
            t1, t2 = (q - r - si) / di, (q + r - si) / di
            lo, hi = np.maximum(lo, np.minimum(t1, t2)), np.minimum(hi, np.maximum(t1, t2))
        hit |= lo <= hi
    return bool(hit.all()) and bool((np.abs(pos[:, 2]) <= 1).all())


def _corners():
    pt = st.tuples(st.integers(-150, 150), st.integers(-150, 150))
    return st.tuples(pt, pt, pt).filter(lambda t: abs((t[0][0] - t[1][0]) * (t[2][1] - t[1][1])
                                                       - (t[0][1] - t[1][1]) * (t[2][0] - t[1][0])) > 40)


KIN = st.tuples(st.sampled_from(["3000", "6000", "20000"]), st.sampled_from(["3000", "6000", "20000"]),
                st.sampled_from(["20", "100", "500", "3000"]), st.sampled_from(["20", "100", "500", "3000"]))
MODES = st.sampled_from(["G64", "G64", "G64 P0.05", "G64 P0.5 Q0", "G64 P2"])


def _probe_case(p0, c, p1, feed, mode, kin, pick):
    """(machine with a clamp around a blend pulse position, program, that position), or None (no blend)."""
    text = _program(p0, c, p1, feed, mode)
    arcs = _arcs(text, _machine(kin, ((Fraction(900), Fraction(900)), (Fraction(901), Fraction(901)))))
    pts = [row for _arc, pos in arcs for row in pos.tolist()]
    if not pts:
        return None
    q = tuple(Fraction(v) * PULSE for v in pts[int(pick * (len(pts) - 1))])
    box = ((q[0] - HALF, q[1] - HALF), (q[0] + HALF, q[1] + HALF))
    return _machine(kin, box), text, q


@settings(max_examples=25, deadline=None)
@given(_corners(), st.sampled_from([300, 1200, 6000]), MODES, KIN)
def test_every_blend_position_lies_in_the_enclosure(corner, feed, mode, kin):
    p0, c, p1 = corner
    text = _program(p0, c, p1, feed, mode)
    m = _machine(kin, ((Fraction(900), Fraction(900)), (Fraction(901), Fraction(901))))
    for _arc, pos in _arcs(text, m):
        if mode == "G64":
            assert _in_parallelogram(p0, c, p1, pos), text
        else:
            p = Fraction(mode.split()[1][1:])
            q_naive = Fraction(0) if "Q0" in mode else p
            assert _near_path(p0, c, p1, pos, p + q_naive), text


def _consistent(m, text) -> tuple[bool, str]:
    """(controller alarms, prover verdict)."""
    sim = simulate(interpret_text(text, m, fast=False), m)
    return bool(sim.alarms), verify_text(text, m).verdict.label


@settings(max_examples=8, deadline=None)
@given(_corners(), st.sampled_from([300, 1200, 6000]), MODES, KIN, st.floats(0, 1))
def test_a_controller_alarm_at_a_blended_corner_is_never_proved_safe(corner, feed, mode, kin, pick):
    case = _probe_case(*corner, feed, mode, kin, pick)
    if case is None:
        return
    m, text, _q = case
    alarmed, verdict = _consistent(m, text)
    assert alarmed, "the clamp contains a position the controller moves through"
    assert verdict != "safe", text


# Corners whose blends use most of what the planner allows: short motions, slow axes (the blend-start bound),
# and long motions with a tolerance (the tolerance band).
DEEP = [((0, 0), (10, 0), (10, 10), 6000, "G64", ("6000", "6000", "20", "20")),
        ((0, 0), (20, 5), (5, 20), 6000, "G64", ("6000", "6000", "20", "20")),
        ((-30, 0), (0, 0), (0, -8), 6000, "G64", ("6000", "6000", "20", "20"))]
BANDED = [((0, 0), (100, 0), (100, 100), 6000, "G64 P0.5", ("6000", "6000", "500", "500")),
          ((0, 0), (100, 30), (20, 100), 6000, "G64 P2", ("6000", "6000", "500", "500"))]


def _probes(cases):
    out = []
    for p0, c, p1, feed, mode, kin in cases:
        for pick in (0.5, 0.25, 0.75):
            case = _probe_case(p0, c, p1, feed, mode, kin, pick)
            assert case is not None, (p0, c, p1)
            out.append(case[:2])
    return out


def test_shrinking_the_blend_start_bound_breaks_the_contract(monkeypatch):
    probes = _probes(DEEP)
    assert all(_consistent(m, t) == (True, "unknown") for m, t in probes)
    monkeypatch.setattr(blend_module, "BLEND_FRACTION", blend_module.BLEND_FRACTION / 2)
    assert any(_consistent(m, t)[1] == "safe" for m, t in probes), "a quarter of each motion must not hold them"


def test_shrinking_the_tolerance_band_breaks_the_contract(monkeypatch):
    probes = _probes(BANDED)
    assert all(_consistent(m, t) == (True, "unknown") for m, t in probes)
    near = blend_module.CornerCheck._near

    def shrunk(self, seg, tls, mode, end):  # the band p + q cut to p / 4, no naive-CAM q
        return near(self, seg, tls, dataclasses.replace(mode, tolerance=(mode.tolerance or 0) / 4,
                                                        naive=Fraction(0)), end)

    monkeypatch.setattr(blend_module.CornerCheck, "_near", shrunk)
    assert any(_consistent(m, t)[1] == "safe" for m, t in probes), "p / 4 must not hold a blend within p"


# ---------------------------------------------------------------------------------------------- arc corners
# Chains of G1/G2/G3 motions in G64 modes: the controller blends line-arc, arc-line and arc-arc corners as the
# planner does (``nczones.controller.blend_arcs``, from tp.c tpCreateLineArcBlend / ArcLine / ArcArc).  Arcs
# have integer centres and end points: the radius vectors come from Pythagorean triples, so every end lies
# exactly on its circle.
#
# The enclosure the spec states for a corner with an arc (path-modes.md §2): no tolerance, the Minkowski sum of
# the boxes of the parts of the two motions a blend may use, less C; with a tolerance, within p (per axis) of
# those parts (q > 0, naive CAM: within p + q of the whole motions).  A blend may use half of a line, the last
# two thirds of an arc before the corner and the first third of one after it (the enclosure: the last three
# quarters, the first half); an arc part's box is found here from its end points and the axis extremes in it
# (floats, 1e-9 slack).  Arcs of radius 100 with short sweeps on axes of 1 mm/s^2 found the two-thirds trim
# (tests/prover/test_blend_arc_tail.py).
RADII = {5: [(5, 0), (3, 4), (4, 3)], 10: [(10, 0), (6, 8), (8, 6)], 13: [(13, 0), (5, 12), (12, 5)],
         25: [(25, 0), (7, 24), (24, 7), (15, 20), (20, 15)], 100: [(100, 0), (96, 28), (28, 96), (80, 60), (60, 80)]}


def _vectors(r):
    out = set()
    for a, b in RADII[r]:
        for sa in (1, -1):
            for sb in (1, -1):
                out |= {(sa * a, sb * b), (sb * b, sa * a)}
    return sorted(out)


@st.composite
def _chains(draw):
    """(start point, motions): a motion is ("L", end) or ("A", clockwise, centre, end)."""
    p = (draw(st.integers(-60, 60)), draw(st.integers(-60, 60)))
    start, out = p, []
    for _ in range(draw(st.integers(2, 3))):
        if draw(st.booleans()):
            end = (p[0] + draw(st.integers(-60, 60)), p[1] + draw(st.integers(-60, 60)))
            if end == p:
                end = (p[0] + 7, p[1])
            out.append(("L", end))
        else:
            r = draw(st.sampled_from(sorted(RADII)))
            vs = _vectors(r)
            v1, v2 = draw(st.sampled_from(vs)), draw(st.sampled_from(vs))
            centre = (p[0] - v1[0], p[1] - v1[1])
            end = (centre[0] + v2[0], centre[1] + v2[1])
            out.append(("A", draw(st.booleans()), centre, end))
        p = out[-1][-1]
    return start, out


def _chain_program(start, motions, feed, mode):
    lines = ["G61", f"G0 X{start[0]} Y{start[1]}", mode]
    p = start
    for k, mo in enumerate(motions):
        f = f" F{feed}" if k == 0 else ""
        if mo[0] == "L":
            lines.append(f"G1{f} X{mo[1][0]} Y{mo[1][1]}")
        else:
            _a, cw, c, e = mo
            lines.append(f"G{2 if cw else 3}{f} X{e[0]} Y{e[1]} I{c[0] - p[0]} J{c[1] - p[1]}")
        p = mo[-1]
    return "\n".join(lines + ["G61", "G4 P0", ""])


def _half_box(p0, mo, at_end):
    """Box (lo, hi) in mm of the part of motion ``mo`` (from ``p0``) a blend may use at its end (``at_end``) or
    start: a line's half; an arc's last three quarters, or its first half."""
    import math

    if mo[0] == "L":
        m = [(a + b) / 2 for a, b in zip(p0, mo[1])]
        q = mo[1] if at_end else p0
        return [min(a, b) for a, b in zip(m, q)], [max(a, b) for a, b in zip(m, q)]
    _a, cw, c, e = mo
    r = math.hypot(p0[0] - c[0], p0[1] - c[1])
    a0 = math.atan2(p0[1] - c[1], p0[0] - c[0])
    a1 = math.atan2(e[1] - c[1], e[0] - c[0])
    sweep = (a1 - a0) % (2 * math.pi) if not cw else -((a0 - a1) % (2 * math.pi))
    if sweep == 0:
        sweep = -2 * math.pi if cw else 2 * math.pi
    # a blend may trim up to two thirds of the arc before a corner (blendInit3FromArcLine: phi1_max = angle * 2/3),
    # a third of the arc after it: the spec's enclosure takes the arc's last three quarters, its first half
    lo_a, hi_a = (a0 + sweep / 4, a0 + sweep) if at_end else (a0, a0 + sweep / 2)
    lo_a, hi_a = min(lo_a, hi_a), max(lo_a, hi_a)
    angles = [lo_a, hi_a] + [k * math.pi / 2 for k in range(math.floor(lo_a / (math.pi / 2)) - 1,
                                                            math.ceil(hi_a / (math.pi / 2)) + 2)
                             if lo_a <= k * math.pi / 2 <= hi_a]
    xs = [c[0] + r * math.cos(t) for t in angles]
    ys = [c[1] + r * math.sin(t) for t in angles]
    return [min(xs) - 1e-9, min(ys) - 1e-9], [max(xs) + 1e-9, max(ys) + 1e-9]


def _whole_box(p0, mo):
    a, b = _half_box(p0, mo, False), _half_box(p0, mo, True)
    return [min(x, y) for x, y in zip(a[0], b[0])], [max(x, y) for x, y in zip(a[1], b[1])]


def _in_region(row, lo, hi, slack):
    """``row`` (pulses) within ``slack`` mm per axis of the box (lo, hi) in mm; Z within one pulse of 0."""
    x, y = row[0] * float(PULSE), row[1] * float(PULSE)
    return (lo[0] - slack <= x <= hi[0] + slack and lo[1] - slack <= y <= hi[1] + slack
            and abs(row[2]) <= 1)


def _chain_arcs(text, machine):
    """(block line of the corner's first motion, pulse positions) of every blend arc of the program."""
    return [(arc.seg.line, pos) for arc, pos in _arcs(text, machine)]


def _chain_in_enclosure(start, motions, mode, arcs) -> str | None:
    """None when every blend pulse position lies in the enclosure of its corner, else a description."""
    pts = [start] + [mo[-1] for mo in motions]
    band = None
    naive = Fraction(0)
    if mode != "G64":
        band = Fraction(mode.split()[1][1:])
        naive = Fraction(0) if "Q0" in mode else band
    every = [_whole_box(pts[k], mo) for k, mo in enumerate(motions)]
    for line, pos in arcs:
        k = line - 4  # the corner between motions k and k + 1 (motion i is on line 4 + i)
        if band is not None and naive > 0:
            # naive CAM merges motions (the merged chord carries its last line): within p + q of the motions,
            # as the prover proves every corner's two whole motions grown by p + q
            slack = float(band + naive + PULSE) + 1e-9
            ok = all(any(_in_region(r, lo, hi, slack) for lo, hi in every) for r in pos.tolist())
            if not ok:
                return f"corner after line {line}"
            continue
        a, b, c = motions[k], motions[k + 1], pts[k + 1]
        if band is None:
            if a[0] == "L" and b[0] == "L":
                ok = _in_parallelogram(pts[k], c, b[1], pos)
            else:
                ba, bb = _half_box(pts[k], a, True), _half_box(c, b, False)
                lo = [x + y - z for x, y, z in zip(ba[0], bb[0], c)]
                hi = [x + y - z for x, y, z in zip(ba[1], bb[1], c)]
                ok = all(_in_region(r, lo, hi, float(PULSE)) for r in pos.tolist())
        else:
            slack = float(band + PULSE) + 1e-9
            boxes = [_half_box(pts[k], a, True), _half_box(c, b, False)]
            ok = all(any(_in_region(r, lo, hi, slack) for lo, hi in boxes) for r in pos.tolist())
        if not ok:
            return f"corner after line {line}"
    return None


ARC_MODES = st.sampled_from(["G64", "G64", "G64", "G64 P0.05", "G64 P0.5 Q0", "G64 P2"])
SLOW = st.tuples(st.sampled_from(["3000", "6000"]), st.sampled_from(["3000", "6000"]),
                 st.sampled_from(["1", "20", "100", "500"]), st.sampled_from(["1", "20", "100", "500"]))


@settings(max_examples=60, deadline=None)
@given(_chains(), st.sampled_from([300, 1200, 6000]), ARC_MODES, SLOW)
def test_every_blend_position_next_to_an_arc_lies_in_the_enclosure(chain, feed, mode, kin):
    start, motions = chain
    text = _chain_program(start, motions, feed, mode)
    m = _machine(kin, ((Fraction(900), Fraction(900)), (Fraction(901), Fraction(901))))
    bad = _chain_in_enclosure(start, motions, mode, _chain_arcs(text, m))
    assert bad is None, f"{bad}:\n{text}"


def _chain_probe(text, kin, pick):
    """(machine with a clamp around a blend pulse position next to an arc, the position), or None."""
    arcs = _chain_arcs(text, _machine(kin, ((Fraction(900), Fraction(900)), (Fraction(901), Fraction(901)))))
    pts = [row for _line, pos in arcs for row in pos.tolist()]
    if not pts:
        return None
    q = tuple(Fraction(v) * PULSE for v in pts[int(pick * (len(pts) - 1))])
    return _machine(kin, ((q[0] - HALF, q[1] - HALF), (q[0] + HALF, q[1] + HALF))), q


@settings(max_examples=10, deadline=None)
@given(_chains(), st.sampled_from([300, 1200, 6000]), ARC_MODES, SLOW, st.floats(0, 1))
def test_a_controller_alarm_next_to_an_arc_is_never_proved_safe(chain, feed, mode, kin, pick):
    text = _chain_program(*chain, feed, mode)
    case = _chain_probe(text, kin, pick)
    if case is None:
        return
    m, _q = case
    alarmed, verdict = _consistent(m, text)
    assert alarmed, "the clamp contains a position the controller moves through"
    assert verdict != "safe", text


# Deep corners next to arcs (line-arc, arc-line, arc-arc; fast feed, slow axes: the blends use what the planner
# allows).  The probe boxes sit in the middle of the blend arcs, off the programmed path.
DEEP_ARCS = [((0, 0), [("L", (20, 0)), ("A", False, (32, 5), (44, 10))]),
             ((-25, 0), [("A", True, (0, 0), (0, 25)), ("L", (20, 5))]),
             ((0, 0), [("A", False, (0, 10), (10, 10)), ("A", True, (15, 22), (2, 22))])]


def test_shrinking_the_arc_corner_enclosure_breaks_the_contract(monkeypatch):
    kin = ("6000", "6000", "20", "20")
    probes = []
    for start, motions in DEEP_ARCS:
        text = _chain_program(start, motions, 6000, "G64")
        for pick in (0.5, 0.25):
            case = _chain_probe(text, kin, pick)
            assert case is not None, motions
            probes.append((case[0], text))
    assert all(_consistent(m, t) == (True, "unknown") for m, t in probes)
    half = blend_module._half_box

    def at_the_corner(seg, dogleg, end):  # an arc's part of the enclosure shrunk to the corner point
        if seg.kind.name == "ARC":
            p = seg.end if end else seg.start
            return p, p
        return half(seg, dogleg, end)

    monkeypatch.setattr(blend_module, "_half_box", at_the_corner)
    assert any(_consistent(m, t)[1] == "safe" for m, t in probes), "the corner point must not hold an arc blend"


# ---------------------------------------------------------------------------------------------- naive CAM (G64 Q)
# Runs of short lines that zig-zag within a few tenths of a straight line, then a corner, in ``G64 P p Q q`` (or
# ``G64 Q q`` without P).  The controller merges them as emccanon's naive-CAM detector does and blends the merged
# lines.  The enclosure the spec states (path-modes.md §2): with P, every point within p + q of the programmed
# path (the prover: of the motions of each corner, per axis); without P, the merged lines within q of the path
# and every blend at a programmed corner C in ``C + (x - C) + (y - C)``, x in the box of the motions (up to 101)
# before C, y in the box of those after it.
NAIVE_MODES = st.sampled_from(["G64 P0.01 Q0.2", "G64 P0.1 Q0.5", "G64 P0.05", "G64 Q0.3"])


@st.composite
def _runs(draw):
    """(start, end points of the lines): a zig-zag run along a direction, then a corner."""
    start = (draw(st.integers(-50, 50)), draw(st.integers(-50, 50)))
    d = draw(st.sampled_from([(1, 0), (0, 1), (3, 4), (-4, 3), (1, 1)]))
    norm = (d[0] ** 2 + d[1] ** 2) ** 0.5
    pts, s = [], 0
    for _ in range(draw(st.integers(3, 7))):
        s += draw(st.integers(2, 12))
        off = Fraction(draw(st.integers(-4, 4)), 10)  # up to 0.4 mm off the run's line
        pts.append((start[0] + Fraction(round(s * d[0] / norm * 1000), 1000) - off * Fraction(round(d[1] / norm * 1000), 1000),
                    start[1] + Fraction(round(s * d[1] / norm * 1000), 1000) + off * Fraction(round(d[0] / norm * 1000), 1000)))
    last = pts[-1]
    turn = draw(st.sampled_from([(20, 30), (-25, 10), (5, -30)]))
    pts.append((last[0] + turn[0], last[1] + turn[1]))
    return start, pts


def _run_program(start, pts, feed, mode):
    lines = ["G61", f"G0 X{start[0]} Y{start[1]}", mode]
    for k, p in enumerate(pts):
        lines.append(f"G1{' F%d' % feed if k == 0 else ''} X{_dec(Fraction(p[0]))} Y{_dec(Fraction(p[1]))}")
    return "\n".join(lines + ["G61", "G4 P0", ""])


def _dist_to_path(xy, path):
    """Euclidean distances from the points ``xy`` (shape (n, 2)) to the polyline ``path`` (floats)."""
    best = np.full(len(xy), np.inf)
    for a, b in zip(path, path[1:]):
        a, d = np.array(a), np.array(b) - np.array(a)
        t = np.clip((xy - a) @ d / float(d @ d), 0.0, 1.0)
        best = np.minimum(best, np.linalg.norm(xy - (a + t[:, None] * d), axis=1))
    return best


def _moved(text, machine):
    """Floats (x, y, kind) along every motion the controller moves in the G64 part: merged lines every 0.05 mm,
    blend arcs at their pulse positions."""
    run = interpret_text(text, machine, fast=False)
    segs = list(run.segments())
    out = []
    for item in blend_motion(segs, machine, run):
        if isinstance(item, BlendArc):
            for x, y, *_ in item.samples(max(2, int(item.radius * item.sweep / 0.01))).tolist():
                out.append((x, y, "blend", item.corner))
        elif item.kind is SegmentKind.LINE:
            s, e = [float(v) for v in item.start], [float(v) for v in item.end]
            n = max(2, int(max(abs(e[0] - s[0]), abs(e[1] - s[1])) / 0.05))
            for t in np.linspace(0, 1, n):
                out.append((s[0] + t * (e[0] - s[0]), s[1] + t * (e[1] - s[1]), "line", None))
    return out


def _naive_in_enclosure(start, pts, mode, moved) -> str | None:
    path = [tuple(map(float, start))] + [tuple(map(float, p)) for p in pts]
    words = dict((w[0], Fraction(w[1:])) for w in mode.split()[1:])
    p, q = words.get("P", Fraction(0)), words.get("Q", words.get("P", Fraction(0)))
    slack = float(PULSE) + 1e-9
    xy = np.array([(x, y) for x, y, _k, _c in moved])
    near = _dist_to_path(xy, path) <= float(p + q) + slack
    for (x, y, kind, corner), ok in zip(moved, near.tolist()):
        if p > 0 or kind == "line":
            if not ok:
                return f"{kind} point ({x:.4f}, {y:.4f}) beyond p + q"
        else:
            c = (float(corner[0]), float(corner[1]))
            k = path.index(c)
            before, after = path[max(0, k - 101):k + 1], path[k:k + 102]
            for i in (0, 1):
                lo = min(v[i] for v in before) + min(v[i] for v in after) - c[i]
                hi = max(v[i] for v in before) + max(v[i] for v in after) - c[i]
                if not lo - slack <= (x, y)[i] <= hi + slack:
                    return f"blend point ({x:.4f}, {y:.4f}) outside the windows' box sum at {c}"
    return None


@settings(max_examples=20, deadline=None)
@given(_runs(), st.sampled_from([600, 3000]), NAIVE_MODES, SLOW)
def test_every_naive_cam_position_lies_in_the_enclosure(run, feed, mode, kin):
    start, pts = run
    text = _run_program(start, pts, feed, mode)
    m = _machine(kin, ((Fraction(900), Fraction(900)), (Fraction(901), Fraction(901))))
    bad = _naive_in_enclosure(start, pts, mode, _moved(text, m))
    assert bad is None, f"{bad}:\n{text}"


@settings(max_examples=8, deadline=None)
@given(_runs(), st.sampled_from([600, 3000]), NAIVE_MODES, SLOW, st.floats(0, 1))
def test_a_controller_alarm_on_a_merged_run_is_never_proved_safe(run, feed, mode, kin, pick):
    text = _run_program(*run, feed, mode)
    moved = _moved(text, _machine(kin, ((Fraction(900), Fraction(900)), (Fraction(901), Fraction(901)))))
    x, y, _kind, _c = moved[int(pick * (len(moved) - 1))]
    q = (Fraction(round(x * 1000), 1000), Fraction(round(y * 1000), 1000))
    if abs(q[0]) <= 2 * HALF and abs(q[1]) <= 2 * HALF:
        return  # a clamp around the machine's reference position is not a valid machine
    m = _machine(kin, ((q[0] - HALF, q[1] - HALF), (q[0] + HALF, q[1] + HALF)))
    alarmed, verdict = _consistent(m, text)
    assert alarmed, "the clamp contains a position the controller moves through"
    assert verdict != "safe", text


# A merged zig-zag: (0,0) (10,0.4) (20,0) (30,0.4) (40,0) lie within q = 0.5 of the chord (0,0)-(40,0), so the
# controller moves the chord (emccanon linkable), 0.4 mm from the programmed vertex (10, 0.4) and the
# polyline near it, far beyond p = 0.01.  A clamp around (10, 0) on the chord: the controller alarms.
ZIGZAG = "G61\nG0 X0 Y0\nG64 P0.01 Q0.5\nG1 F3000 X10 Y0.4\nG1 X20 Y0\nG1 X30 Y0.4\nG1 X40 Y0\nG1 X40 Y30\nG61\nG4 P0\n"


def test_dropping_the_naive_cam_q_breaks_the_contract(monkeypatch):
    kin = ("6000", "6000", "500", "500")
    m = _machine(kin, ((Fraction(10) - HALF, -HALF), (Fraction(10) + HALF, HALF)))
    assert _consistent(m, ZIGZAG) == (True, "unknown")
    near = blend_module.CornerCheck._near

    def no_q(self, seg, tls, mode, end):  # the band p + q cut to p: naive CAM dropped
        return near(self, seg, tls, dataclasses.replace(mode, naive=Fraction(0)), end)

    monkeypatch.setattr(blend_module.CornerCheck, "_near", no_q)
    assert _consistent(m, ZIGZAG)[1] == "safe", "p alone must not hold a merged chord"


# ---------------------------------------------------------------------------------------------- long profile
# Opt-in (``pytest -m long``), numbers in specs/path-modes.md §7.
LONG = 2000


@pytest.mark.long
@settings(max_examples=LONG, deadline=None, derandomize=False)
@given(_chains(), st.sampled_from([300, 1200, 6000]), ARC_MODES, SLOW)
def test_long_arc_corners_in_the_enclosure(chain, feed, mode, kin):
    test_every_blend_position_next_to_an_arc_lies_in_the_enclosure.hypothesis.inner_test(chain, feed, mode, kin)


@pytest.mark.long
@settings(max_examples=LONG, deadline=None, derandomize=False)
@given(_runs(), st.sampled_from([600, 3000]), NAIVE_MODES, SLOW)
def test_long_naive_cam_in_the_enclosure(run, feed, mode, kin):
    test_every_naive_cam_position_lies_in_the_enclosure.hypothesis.inner_test(run, feed, mode, kin)


@pytest.mark.long
@settings(max_examples=LONG // 4, deadline=None, derandomize=False)
@given(_chains(), st.sampled_from([300, 1200, 6000]), ARC_MODES, SLOW, st.floats(0, 1))
def test_long_arc_probes_never_safe(chain, feed, mode, kin, pick):
    test_a_controller_alarm_next_to_an_arc_is_never_proved_safe.hypothesis.inner_test(chain, feed, mode, kin, pick)


@pytest.mark.long
@settings(max_examples=LONG // 4, deadline=None, derandomize=False)
@given(_runs(), st.sampled_from([600, 3000]), NAIVE_MODES, SLOW, st.floats(0, 1))
def test_long_naive_probes_never_safe(run, feed, mode, kin, pick):
    test_a_controller_alarm_on_a_merged_run_is_never_proved_safe.hypothesis.inner_test(run, feed, mode, kin, pick)
