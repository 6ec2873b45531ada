"""Arcs and G43 in the double pass (issue 36) against the full path's verdict, end to end through ``verify``.

Every verdict, violation, reason and note is the same with the pass tried first and without it
(:func:`tests.prover.test_double_pass_proof.both_ways`), on generated arc programs (I/J and R, both directions,
small and large radii, near half circles, whole circles, G43) against forbidden boxes, stepped tables and
polygons; on a zone face an arc's extreme touches exactly and one it crosses by less than the pass's rounding
bound; and on G43 lengths that decide a Z face.  Each fixed case runs short, with more than 512 motions (the
vectorized tier when the pass is off) and with ``#`` in the text.
"""

from __future__ import annotations

import math
import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from nczones.errors import MachineFileError
from nczones.machine import parse_machine
from nczones.prover.result import Verdict
from tests.gcode.test_double_pass import arc_programs
from tests.machines import machine_text
from tests.prover.test_double_pass_proof import EXAMPLES, ZONES, both_ways, same_outcome

HEAD = machine_text("mill_g55_zones_head")
TOOLS = '[tool_lengths]\nH1 = "100"\n'


def machine_of(kind: str, a: int, b: int, extra: str = TOOLS, head: str = HEAD):
    """The machine of a zone kind; a machine whose start is outside its zones is not drawn (ZN130)."""
    try:
        return parse_machine(head + extra + ZONES[kind].format(a=a, b=b))
    except MachineFileError:
        assume(False)


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES <= 200,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(arc_programs(), st.sampled_from(sorted(ZONES)), st.integers(2, 150), st.integers(-50, 150),
       st.sampled_from(["0", "0", "0.5"]))
def test_arc_programs_get_the_full_paths_verdict(monkeypatch, text, kind, a, b, margin):
    machine = machine_of(kind, a, max(a + 1, b) if kind == "forbid" else b)
    try:
        with_pass, without = both_ways(text, machine, monkeypatch, margin=margin)
    except Exception as exc:  # noqa: BLE001  # a G-code error: the same error both ways
        with monkeypatch.context() as m:
            import nczones.pipeline.verification as verification

            m.setattr(verification, "double_pass_result", lambda *args, **kwargs: None)
            from nczones.prover import verify_text

            with pytest.raises(type(exc)):
                verify_text(text, machine, margin=margin)
        return
    same_outcome(with_pass, without)


def _variants(lines: list[str]) -> dict[str, str]:
    """The program short, repeated past 512 motions, and with ``#`` in the text."""
    head = "G21 G90 G17 G54 F300\n"
    body = "\n".join(lines) + "\n"
    return {"short": head + body + "M30\n", "long": head + body * (520 // len(lines) + 1) + "M30\n",
            "hash": head + "#1 = 0\n" + body + "M30\n"}


def _face(xmax: str) -> object:
    """X <= ``xmax`` (else wide): the face the arcs' extreme X = 5 meets; exact stop (G61) at every corner,
    so that only the arcs meet the face (a rounded corner next to an arc is enclosed by the two motions'
    boxes, which reach the face: the full path answers unknown there, VF208)."""
    return parse_machine(machine_text("mill_g55_zones_head", set={"machine.path_mode": "G61"}) + '[[zones]]\nname = "travel"\nkind = "box"\n'
                         f'min = {{ X = "-1000", Y = "-1000", Z = "-1000" }}\nmax = {{ X = "{xmax}", Y = "1000", Z = "1000" }}\n')


# arcs about the origin of radius 5 that reach X = 5 at (5, 0)
FACE_ARCS = {
    "I/J": ["G1 X0 Y-5", "G3 X0 Y5 I0 J5", "G2 X0 Y-5 I0 J-5"],  # the +X half both ways (G2 back: cw from the top)
    "R": ["G1 X-3 Y-4", "G3 X-3 Y4 R-5", "G1 X-3 Y-4"],  # from (-3, -4) ccw to (-3, 4) the long way: through (5, 0)
    # from (3, -4) ccw to (3, 4) the short way (R > 0: the centre left of the chord, (3, 0) - 3 (1, 0) = (0, 0)):
    # through (5, 0); the pass's quick box of it (the disc on the chord, X up to 3 + 4) crosses the face
    "R short": ["G1 X3 Y-4", "G3 X3 Y4 R5", "G1 X3 Y-4"],
}


@pytest.mark.parametrize("arcs", sorted(FACE_ARCS))
@pytest.mark.parametrize("variant", ["short", "long", "hash"])
def test_an_arc_that_touches_a_face_is_safe_and_one_over_it_by_less_than_the_rounding_is_not(monkeypatch, arcs,
                                                                                              variant):
    # The arc's exact extreme is X = 5 (centre (0, 0), radius 5: 3**2 + 4**2 = 5**2 for the R arc, whose
    # centre is to the right of its chord for G3 with R < 0, LinuxCNC arc_data_r): a face at X = 5 holds it
    # (safe); a face 1e-14 below it, far within the pass's rounding bound (64 * 5 * 2**-52 ~ 7e-14), does not:
    # the full path finds the crossing and the pass must not prove it.
    text = _variants(FACE_ARCS[arcs])[variant]
    with_pass, without = both_ways(text, _face("5"), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    with_pass, without = both_ways(text, _face("4.99999999999999"), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.UNSAFE
    with_pass, without = both_ways(text, _face("5.001"), monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    if variant != "short":  # (a plain program of fewer than 512 lines is not given to the pass)
        assert "double_pass_boxes" in dict(with_pass.stats), "the pass proves it 0.001 away from the face"


@pytest.mark.parametrize("variant", ["short", "long", "hash"])
def test_g43_adds_the_machines_tool_length_on_z(monkeypatch, variant):
    # LinuxCNC G43 H1: the tool axis's machine coordinate is the program's plus the length of register 1 (100 in
    # [tool_lengths]); a face at Z = 150 holds Z40 + 100, not Z60 + 100; after G49 Z60 is 60
    zface = ('[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             'max = { X = "1000", Y = "1000", Z = "150" }\n')
    machine = parse_machine(HEAD + TOOLS + zface)
    for lines, verdict in ((["G43 H1 G0 Z40", "G1 X1 Y1", "G1 X0 Y0"], Verdict.SAFE),
                           (["G43 H1 G0 Z60", "G1 X1 Y1", "G1 X0 Y0"], Verdict.UNSAFE),
                           (["G43 H1", "G49", "G0 Z60", "G1 X1 Y1", "G1 X0 Y0"], Verdict.SAFE)):
        with_pass, without = both_ways(_variants(lines)[variant], machine, monkeypatch)
        same_outcome(with_pass, without)
        assert with_pass.verdict is verdict, lines
    tip = machine_text("mill_g55_zones_head") + TOOLS + zface.replace('kind = "box"', 'kind = "box"\npoint = "tip"')
    with_pass, without = both_ways(_variants(["G43 H1 G0 Z60", "G1 X1"])[variant], parse_machine(tip), monkeypatch)
    same_outcome(with_pass, without)  # a tip zone: the pass declines G43, the full path decides
    assert "double_pass_boxes" not in dict(with_pass.stats)


HUNT = int(os.environ.get("NCZONES_ARC_HUNT", "300"))


@pytest.mark.long
@settings(max_examples=HUNT, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                 HealthCheck.function_scoped_fixture])
@given(arc_programs(), st.sampled_from(sorted(ZONES)), st.integers(2, 120), st.integers(-50, 120),
       st.sampled_from(["0", "0", "0.5"]), st.sampled_from([None, 2, 5]), st.sampled_from(["G64", "G61"]),
       st.integers(1, 3))
def test_arc_hunt_no_wrong_safe(monkeypatch, text, kind, a, b, margin, window, mode, repeat):
    """The wrong-safe hunt (specs/contract.md, "Arcs and G43 in the double pass"): random seeds, arc programs
    repeated up to 3 times, the pass's windows tiny or not, corners rounded (G64) or not; the verdict,
    violations, reasons and notes must be the full path's."""
    import nczones.gcode.linuxcnc.doubles as doubles

    head, _, rest = text.partition("\n")
    body, _, _ = rest.rpartition("M30\n")
    text = head + "\n" + body * repeat + "M30\n"
    machine = machine_of(kind, a, max(a + 1, b) if kind == "forbid" else b,
                         head=machine_text("mill_g55_zones_head", set={"machine.path_mode": mode}))
    if window is not None:
        monkeypatch.setattr(doubles, "WINDOW", window)
    try:
        with_pass, without = both_ways(text, machine, monkeypatch, margin=margin)
    except Exception:  # noqa: BLE001  # a G-code error: test_arc_programs_get_the_full_paths_verdict checks those
        return
    same_outcome(with_pass, without)


RS274_ARCS = [
    "G1 X1 Y0\nG3 X0 Y1 I-1 J0\nG2 X-2.5 Y1 I-1.25 J-0.75\nG3 Z0.5 I1 J0.5",  # a whole turn by I/J (a helix)
    "G1 X-3 Y-4\nG3 X-3 Y4 R-5\nG2 X1.234 Y5.678 R7.25\nG2 X1.2 Y5.6 R-0.1\nG3 X0 Y0 R30",
    "G43 H1 G0 Z2\nG1 X10 Y10\nG2 X12 Y10 R1.0000001\nG3 X11 Y11 I-1 J0 Z-1",  # near a half circle; a helix
]


@pytest.mark.parametrize("body", RS274_ARCS)
def test_the_arcs_of_the_pass_against_rs274(tmp_path, body):
    """LinuxCNC's own interpreter (``rs274 -g``, its centres and ends printed to 4 decimals, machine mm by
    tests/oracles/rs274.py) runs the program the pass follows: each arc's centre is the full path's exact
    centre (I/J: the start plus I, J; R: ``(S + E) / 2 + s h n``, derived here at 200 bits), its end is the
    pass's row, and the circle rs274 moves on, in every axis direction its sweep holds, stays in the pass's
    box of the motion, all within the log's rounding."""
    import mpmath

    from nczones.gcode.linuxcnc.doubles import double_pass
    from tests.tools import rs274_diff

    if not os.path.exists(rs274_diff.RS274):
        pytest.skip("rs274 not installed")
    text = "G21 G90 G17 G54 F300\n#1 = 0\n" + body + "\nM2\n"
    moves, error, _log = rs274_diff.run_rs274(text, rs274_diff.FINDING_SETUP, tmp_path)
    assert error is None
    machine = rs274_diff.machine_of(rs274_diff.FINDING_SETUP)
    path = double_pass(text, machine, max_iterations=10, arc_tolerance="linuxcnc")
    assert len(moves) == path.motions and path.arcs == sum(mv.kind == "ARC" for mv in moves)
    slack = 3 * Fraction(5, 100000)  # three printed numbers (value, offset, length) to 4 decimals
    x, y = 0.0, 0.0
    for k, mv in enumerate(moves, start=1):
        lo, hi = path.enclosure(k, k)
        for i, a in enumerate("XYZ"):
            assert abs(Fraction(path.columns[i][k]) - mv.end[i]) <= slack, (k, a)
        if mv.kind == "ARC":
            assert mv.centre is not None
            line = body.split("\n")[k - 1]
            words = dict((w[0], float(w[1:])) for w in line.split() if w[0] in "XYIJR")
            ex, ey = float(mv.end[0]), float(mv.end[1])
            if "R" in words:
                r = words["R"]
                d = math.hypot(ex - x, ey - y)
                h = math.sqrt(r * r - d * d / 4)
                s = -1 if (r > 0) == line.lstrip().startswith("G2") else 1
                centre = ((x + ex) / 2 - s * h * (ey - y) / d, (y + ey) / 2 + s * h * (ex - x) / d)
            else:
                centre = (x + words.get("I", 0.0), y + words.get("J", 0.0))
            assert abs(centre[0] - float(mv.centre[0])) < 2e-4 and abs(centre[1] - float(mv.centre[1])) < 2e-4
            cx, cy = (mpmath.mpf(float(c)) for c in mv.centre)
            radius = math.hypot(ex - float(cx), ey - float(cy))
            for axis, sign, point in ((0, 1, (cx + radius, cy)), (0, -1, (cx - radius, cy)),
                                      (1, 1, (cx, cy + radius)), (1, -1, (cx, cy - radius))):
                a = "XY"[axis]
                # the direction is in the sweep of rs274's arc when the box must reach it; check by the box:
                # a point the pass's box leaves out must not be on rs274's arc (its sweep, ccw for direction > 0)
                inside = lo[a] - slack <= Fraction(float(point[axis])) <= hi[a] + slack
                if not inside:
                    start = math.atan2(y - float(cy), x - float(cx))
                    end = math.atan2(ey - float(cy), ex - float(cx))
                    phi = math.atan2(float(point[1] - cy), float(point[0] - cx))
                    a0, a1 = (start, end) if mv.direction > 0 else (end, start)
                    sweep = (a1 - a0) % (2 * math.pi) or 2 * math.pi
                    assert (phi - a0) % (2 * math.pi) > sweep + 1e-6, (k, a, sign)
        x, y = float(mv.end[0]), float(mv.end[1])


@pytest.mark.parametrize("variant", ["short", "long", "hash"])
def test_an_end_on_the_starts_ray_is_the_full_paths(monkeypatch, variant):
    """Found by the hunt (G2 X0.0001 Y0 I-0.01 J0 from the origin: the end on the ray from the centre through the
    start, 0.0001 farther out, within the arc tolerance): LinuxCNC moves a whole spiral turn there, which the
    full path answered ``unknown`` for; the pass proved its whole-turn box ``safe``.  It declines such an arc now,
    and still proves a whole turn whose block names no axis of the plane (a helix: the end is the start).
    The full path proves the spiral's whole-turn box too now (codes36: ``Prover._decide_whole_turn``, as the fast
    path's column screen did past 512 motions): ``safe`` both ways, in every variant."""
    machine = machine_of("box", 2, 0)
    spiral = _variants(["G1 X0 Y0", "G2 X0.0001 Y0 I-0.01 J0"])[variant]
    with_pass, without = both_ways(spiral, machine, monkeypatch)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    assert "double_pass_boxes" not in dict(with_pass.stats)
    turn = _variants(["G1 X0 Y0 Z1", "G2 Z-0.5 I-0.01 J0"])[variant]
    with_pass, without = both_ways(turn, machine_of("box", 20, 0), monkeypatch)  # (room for corners next to arcs)
    same_outcome(with_pass, without)
    assert with_pass.verdict is Verdict.SAFE
    if variant == "hash":
        assert "double_pass_boxes" in dict(with_pass.stats)


@pytest.mark.parametrize("variant", ["short", "long", "hash"])
def test_an_arc_after_a_motion_linuxcnc_may_drop_is_the_full_paths(monkeypatch, variant):
    """A straight motion shorter than 3e-7 mm on every axis before an arc, in a blended corner: LinuxCNC may drop
    it and run the arc from the corner, which the full path answers ``unknown`` for (prover/blend.py); the pass
    declines it (its boxes would hold the arc as programmed only)."""
    machine = machine_of("box", 20, 0)
    text = _variants(["G1 X1 Y0", "G1 X1.0000001 Y0", "G3 X-1 Y0 R1.0000001"])[variant]
    with_pass, without = both_ways(text, machine, monkeypatch)
    same_outcome(with_pass, without)
    assert "double_pass_boxes" not in dict(with_pass.stats)
    if variant != "long":  # (past 512 motions: the fast path's verdict, whatever it is, both ways)
        assert with_pass.verdict is Verdict.UNKNOWN
