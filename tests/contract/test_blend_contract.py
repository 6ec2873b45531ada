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
to a quarter of P with no naive-CAM Q) make clause 2 fail on fixed deep corners.  Dropping only Q is not
caught: the controller does not merge collinear motions (naive CAM), so its path stays within P.
"""

from __future__ import annotations

import dataclasses
from decimal import Decimal
from fractions import Fraction

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.controller import simulate
from nczones.controller.blending import BlendArc, arc_pulse_positions, blend_motion
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
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
        if isinstance(item, BlendArc):
            pos = arc_pulse_positions(item, [a.pulse for a in machine.axes], prog)
            out.append((item, pos))
            prog = [int(v) for v in pos[-1]] if len(pos) else prog
        else:
            prog = [round(v / PULSE) for v in item.end]
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
