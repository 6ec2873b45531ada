"""Polar coordinate interpolation (G12.1/G13.1, G112/G113; issue 23): the mode, the enclosures, the proofs,
the pulses, and the agreement of the prover and the controller."""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction as F
from pathlib import Path

import mpmath
import numpy as np
import pytest
from hypothesis import HealthCheck, assume, event, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import interpret_text, segments_text
from nczones.geometry.polar import (
    CentreCrossing,
    angle_range,
    polar_move,
    polar_move_of,
    radius_range,
    walk_angle,
)
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from nczones.prover import verify_text
from tests.machines import machine_text
from tests.sizes import examples

ROOT = Path(__file__).resolve().parents[3]
EX = ROOT / "specs" / "examples"


def machine(zones: str = "", pulse: str = "0.001", extra: str = ""):
    """A Fanuc turning centre (tests/machines/fanuc_xzc_turning_centre.toml): X diameters (machine X a radius), Z,
    C degrees; work zero on the face; exact stop mode (G61): these tests are about polar interpolation, not
    corner rounding.  ``zones`` and ``extra`` (tables such as ``[tool_offsets]``) are appended."""
    return parse_machine(machine_text("fanuc_xzc_turning_centre", set={"machine.pulse": pulse, "machine.path_mode": "G61"},
                                      extra=f"{extra}\n{zones}\n"), "turning_centre.toml")


def clamp(xlo, xhi, clo, chi, name="clamp"):
    return (f'[[zones]]\nname = "{name}"\nkind = "box"\nforbid = true\n'
            f'min = {{ X = "{xlo}", C = "{clo}" }}\nmax = {{ X = "{xhi}", C = "{chi}" }}\n')


def polar_ends(segs):
    return [(s.end[0], s.end[2]) for s in segs if s.kind is SegmentKind.POLAR]


# --------------------------------------------------------------------------- front end: golden positions

FACE = """G21 G98 G54
G00 X40. Z2. C0.
G01 Z-1. F200.
G12.1
G01 X40. C10. F100.
G03 X20. C20. R10.
G01 X-40.
C-10.
G03 X-20. C-20. I10. J0
G01 X40.
C0
G13.1
G00 Z10.
"""


def test_square_in_the_polar_plane_golden_machine_positions():
    """The profile of specs/examples/programs/polar_face.nc, derived on paper.

    G12.1 finds the tool at X40. (diameter: radius 20) C0: the plane point (20, 0) is angle 0, machine C0.
    Each block's end (x, y) in the plane goes to machine X = sqrt(x^2 + y^2) (radius, rounded to the
    radius increment 0.0005) and C = atan2(y, x) in degrees, unwound along the path (rounded to 0.001):

    ======================  =========  ==================================  =========================
    block                   (x, y)     X = sqrt(x^2+y^2)                   C
    ======================  =========  ==================================  =========================
    G01 X40. C10.           (20, 10)   sqrt(500) = 22.36068 -> 22.3605     atan(1/2) = 26.5651
    G03 X20. C20. R10.      (10, 20)   sqrt(500) -> 22.3605                atan(2) = 63.4349
    G01 X-40.               (-20, 20)  sqrt(800) = 28.28427 -> 28.2845     135
    C-10.                   (-20, -10) sqrt(500) -> 22.3605                180 + 26.5651 = 206.5651
    G03 X-20. C-20. I10 J0  (-10, -20) sqrt(500) -> 22.3605                180 + 63.4349 = 243.4349
    G01 X40.                (20, -20)  sqrt(800) -> 28.2845                315
    C0                      (20, 0)    20                                  360 (one turn, unwound)
    ======================  =========  ==================================  =========================

    The R10 arc's centre is (10, 10) (distance 10 from both ends, to the left of the chord for G03); the
    I10 J0 arc's centre is (-20 + 10, -10) = (-10, -10).
    """
    m = machine()
    segs = segments_text(FACE, m)
    assert polar_ends(segs) == [(F("22.3605"), F("26.565")), (F("22.3605"), F("63.435")), (F("28.2845"), F(135)),
                                (F("22.3605"), F("206.565")), (F("22.3605"), F("243.435")),
                                (F("28.2845"), F(315)), (F(20), F(360))]
    kinds = [s.kind for s in segs]
    assert kinds == [SegmentKind.RAPID, SegmentKind.LINE] + [SegmentKind.POLAR] * 7 + [SegmentKind.RAPID]
    # entering and leaving the mode moves nothing; after G13.1 the C word is the machine angle again
    assert segs[2].start == segs[1].end == (F(20), F(199), F(0))
    assert segs[-1].start == segs[-2].end and segs[-1].end == (F(20), F(210), F(360))
    arc = polar_move_of(segs[3]).arc
    assert arc is not None and all(c.contains(10) for c in arc.centre)


def test_clockwise_path_turns_c_negative_and_offsets_move_the_centre():
    """The tool offset and work offset on X move the centre of rotation (machine X = 80 + radius)."""
    m = machine(extra='[tool_offsets]\n1 = { X = "80", Z = "0" }\n')
    segs = segments_text("G98 T0101\nG00 X20. Z1. C5.\nG112\nG01 C-10. F50.\nU-20.\nG113\n", m)
    # at G112 the tool is at radius 10 (X20. diameter), machine X 90, C5 is the plane's angle 0
    # C-10.: (10, -10): radius sqrt(200) = 14.142136 -> 14.142; angle -45 -> machine C -40
    # U-20. (diameter): x = 10 - 10 = 0: (0, -10): radius 10, angle -90 -> machine C -85
    assert polar_ends(segs) == [(F(80) + F("14.142"), F(-40)), (F(90), F(-85))]


def test_a_motion_with_m30_moves_first():
    segs = segments_text("G98\nG00 X40. Z2. C0.\nG12.1\nG01 C10. F100. M30\nG01 C20.\n", machine())
    assert polar_ends(segs) == [(F("22.3605"), F("26.565"))]


def test_incremental_words_and_system_b():
    m = machine()
    a = polar_ends(segments_text("G98\nG00 X40. Z2. C0.\nG12.1\nG01 H10. F100.\nU-20. H10.\nG13.1\n", m))
    mb = machine(extra='[fanuc]\ngcode_system = "B"\n')
    b = polar_ends(segments_text("G94\nG00 X40. Z2. C0.\nG12.1\nG91 G01 C10. F100.\nX-20. C10.\nG13.1\n", mb))
    assert a == b == [(F("22.3605"), F("26.565")), (F("22.3605"), F("63.435"))]


def test_lines_moving_z_too_and_z_alone_and_a_dwell():
    m = machine()
    segs = segments_text("G98\nG00 X40. Z2. C0.\nG12.1\nG01 Z-1. F100.\nG04 X1.5\nX40. C10. Z-2.\nG13.1\n", m)
    assert [s.kind for s in segs[1:]] == [SegmentKind.LINE, SegmentKind.DWELL, SegmentKind.POLAR]
    assert segs[2].dwell_s == F("1.5")
    assert segs[1].end == (F(20), F(199), F(0)) and segs[3].end[1] == F(198)


@pytest.mark.parametrize("prog, code, line, col", [
    ("G12.1\nG00 X30. C5.\n", "GC234", 4, 1),
    ("G00 X30.\nG12.1\nX30. C5.\n", "GC234", 5, 1),  # modal G00 from before the mode
    ("G12.1\nG54\n", "GC234", 4, 1),
    ("G12.1\nG28 U0\n", "GC234", 4, 1),
    ("G12.1\nG50 X10.\n", "GC234", 4, 1),
    ("G12.1\nG71 U1. R1.\n", "GC234", 4, 1),
    ("G12.1 X20.\n", "GC234", 3, 7),
    ("G12.1\nG12.1\n", "GC234", 4, 1),
    ("G12.1\nG01 X30. C5. K1. F10.\n", "GC235", 4, 14),
    ("G12.1\nG02 X30. C5. F10.\n", "GC235", 4, 1),
    ("G12.1\nG02 X30. C40. R5. F10.\n", "GC330", 4, 15),
    ("G12.1\nG02 X30. C5. I1. J1. F10.\n", "GC330", 4, 14),
])
def test_mode_errors_have_codes_lines_and_columns(prog, code, line, col):
    m = machine()
    with pytest.raises(GcodeError) as e:
        segments_text("G98 F100.\nG01 X40. Z2. C0.\n" + prog, m)
    d = e.value.diagnostics[0]
    assert (d.code, d.span.line, d.span.column) == (code, line, col), d


def test_machine_without_a_c_axis_is_an_error():
    m = parse_machine(machine_text("fanuc_xz_lathe"))
    with pytest.raises(GcodeError) as e:
        segments_text("G00 X40. Z2.\nG112\n", m)
    assert e.value.diagnostics[0].code == "GC236" and "X, Z" in e.value.diagnostics[0].message


@pytest.mark.parametrize("prog, words", [
    ("G00 X0 Z2. C0.\nG12.1\n", "at the centre of rotation"),
    ("G00 X40. Z2. C0.\nG12.1\nG01 X-40. F10.\n", "passes through the centre"),
    ("G00 X40. Z2. C0.\nG12.1\nG01 X0 C0 F10.\n", "ends at the centre"),
    ("G00 X40. Z2. C0.\nG12.1\nG03 X20. C-10. I-10. J0 F10.\n", "passes through the centre"),
    ("G00 X40. Z2. C0.\nG12.1\nG02 X40. C10. Z1. R10. F10.\n", "helix"),
    ("G00 X40. Z2. C0.\nG12.1\nG42 G01 X40. C10. F10.\n", "G42"),
    ("G00 X40. Z2. C0.\nG12.1\nT0101\n", "tool"),
])
def test_paths_through_the_centre_and_unmodelled_words_are_unknown(prog, words):
    m = machine(extra='[tool_offsets]\n1 = { X = "1", Z = "0" }\n')
    run = interpret_text("G98\n" + prog, m)
    list(run.segments())
    assert run.unsupported, prog
    u = run.unsupported[0]
    assert words in u.reason or words in u.code, u


def test_linuxcnc_has_no_polar_interpolation():
    m = parse_machine(machine_text("xzc_linuxcnc"))
    for code in ("G12.1", "G112"):
        with pytest.raises(GcodeError) as e:
            segments_text(f"{code}\nG1 X1 F10\n", m)
        assert e.value.diagnostics[0].code == "GC202"


def test_fanuc_mill_keeps_polar_interpolation_unknown():
    m = parse_machine(machine_text("fanuc_xyzc"))
    run = interpret_text("G12.1\nG1 X1 F10\n", m)
    list(run.segments())
    assert run.unsupported[0].code == "G12.1" and "lathe" in run.unsupported[0].reason


# --------------------------------------------------------------------------- enclosures vs a 60-digit reference


def _ref_point(p0, p1, f, arc):
    """The exact plane point at fraction f, in mpmath (lines; arcs from the centre and sweep of the reference)."""
    if arc is None:
        return [mpmath.mpf(a.numerator) / a.denominator + (mpmath.mpf(b.numerator) / b.denominator
                - mpmath.mpf(a.numerator) / a.denominator) * mpmath.mpf(f.numerator) / f.denominator
                for a, b in zip(p0, p1)]
    (cx, cy), cw = arc
    mp = lambda q: mpmath.mpf(q.numerator) / q.denominator  # noqa: E731
    u = (mp(p0[0]) - cx, mp(p0[1]) - cy)
    v = (mp(p1[0]) - cx, mp(p1[1]) - cy)
    a0, a1 = mpmath.atan2(u[1], u[0]), mpmath.atan2(v[1], v[0])
    d = (a0 - a1) if cw else (a1 - a0)
    d = d % (2 * mpmath.pi)
    if d < mpmath.mpf(10) ** -40:  # the end on the start's ray (exactly, up to the reference's rounding)
        d = 2 * mpmath.pi
    r0, r1 = mpmath.hypot(*u), mpmath.hypot(*v)
    a = a0 + (-d if cw else d) * mp(f)
    rho = r0 + (r1 - r0) * mp(f)
    return [cx + rho * mpmath.cos(a), cy + rho * mpmath.sin(a)]


coords = st.integers(-400, 400).map(lambda k: F(k, 10))


@settings(max_examples=30, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(x0=coords, y0=coords, x1=coords, y1=coords, ci=coords, cj=coords, arc=st.booleans(), cw=st.booleans(),
       t=st.integers(-40, 40), spiral=st.integers(-5, 5), fs=st.lists(st.integers(0, 64), min_size=2, max_size=2))
def test_enclosures_contain_the_60_digit_path(x0, y0, x1, y1, ci, cj, arc, cw, t, spiral, fs):
    """point(f), box(fa, fb), the machine X/C ranges of a box and the unwound end angle contain the reference.

    Arcs end on their circle turned by the rational rotation of half-angle tangent t/10 (and, for a spiral,
    moved out by spiral/100 of the radius).
    """
    with mpmath.workdps(60):
        _enclosures_contain(x0, y0, x1, y1, ci, cj, arc, cw, t, spiral, fs)


def _enclosures_contain(x0, y0, x1, y1, ci, cj, arc, cw, t, spiral, fs):
    centre = (x0 + ci, y0 + cj) if arc else None
    if arc:
        assume((ci, cj) != (0, 0))
        tt = F(t, 10)
        cs, sn = (1 - tt * tt) / (1 + tt * tt), 2 * tt / (1 + tt * tt)
        k = 1 + F(spiral, 100)
        x1 = centre[0] + k * (-ci * cs + cj * sn)
        y1 = centre[1] + k * (-ci * sn - cj * cs)
    assume((x0, y0) != (0, 0) and (x1, y1) != (0, 0))
    move = polar_move((x0, y0), (x1, y1), 0, F(0), F(0), clockwise=cw, centre=centre, arc=arc)
    ref_arc = ((mpmath.mpf(centre[0].numerator) / centre[0].denominator,
                mpmath.mpf(centre[1].numerator) / centre[1].denominator), cw) if arc else None
    # the reference's unwound angle along the path, from 720 samples: steps of at most 0.6 mm at 1 mm or more
    # from the centre turn by less than 180 degrees, so each sample's branch is the one nearest the last
    n = 720
    pts = [_ref_point((x0, y0), (x1, y1), F(k, n), ref_arc) for k in range(n + 1)]
    assume(min(mpmath.hypot(*p) for p in pts) > 1)
    ang = [mpmath.atan2(pts[0][1], pts[0][0])]
    for p in pts[1:]:
        a = mpmath.atan2(p[1], p[0])
        ang.append(a + 2 * mpmath.pi * mpmath.nint((ang[-1] - a) / (2 * mpmath.pi)))
    deg = [a * 180 / mpmath.pi for a in ang]
    fa, fb = sorted(F(k, 256) for k in fs)
    if arc:
        fb = min(fb, fa + F(1, 4))
    eps = mpmath.mpf(10) ** -50  # the reference's own rounding (60 digits)

    def within(v, iv):
        return iv.lo - eps <= v <= iv.hi + eps

    for f in (fa, fb):
        p = _ref_point((x0, y0), (x1, y1), f, ref_arc)
        x, y = move.point(f)
        assert within(p[0], x) and within(p[1], y)
    bx, by = move.box(fa, fb)
    inside = [k for k in range(n + 1) if fa <= F(k, n) <= fb]
    assert all(within(pts[k][0], bx) and within(pts[k][1], by) for k in inside)
    if inside:
        near = F(mpmath.nstr(deg[inside[0]], 30))
        ar = angle_range(bx, by, near)
        rr = radius_range(bx, by)
        for k in inside:
            assert within(mpmath.hypot(*pts[k]), rr)
            if ar is not None:
                assert within(deg[k], ar)
    end = walk_angle(move)
    assert within(deg[-1], end) and end.width() < F(1, 10**40)
    event("arc" if arc else "line")


@settings(max_examples=200, deadline=None, derandomize=True)
@given(num=st.integers(-10**30, 10**30), den=st.integers(1, 10**30))
def test_arc_tangent_enclosure_contains_the_80_digit_value(num, den):
    """The fixed-point series of nczones.geometry.cylinder (its rounding errors counted) encloses atan within 1e-55."""
    from nczones.geometry.cylinder import atan_point, pi_interval

    with mpmath.workdps(80):
        a = atan_point(F(num, den))
        r = mpmath.atan(mpmath.mpf(num) / den)
        assert a.lo <= r <= a.hi and a.width() < F(1, 10**55)
        p = pi_interval()
        assert p.lo <= mpmath.pi <= p.hi


def test_walk_refuses_the_centre():
    with pytest.raises(CentreCrossing):
        walk_angle(polar_move((F(10), F(0)), (F(-10), F(0)), 0, F(0), F(0)))


# --------------------------------------------------------------------------- prover


def test_prover_on_the_bundled_example_safe_and_unsafe():
    prog = (EX / "programs" / "polar_face.nc").read_text()
    safe = verify_text(prog, parse_machine((EX / "machines" / "turning_centre.toml").read_text()))
    assert safe.verdict.label == "safe"
    bad = verify_text(prog, parse_machine((EX / "machines" / "turning_centre_clamp_near.toml").read_text()))
    assert bad.verdict.label == "unsafe"
    v = bad.violations[0]
    assert v.span.line == 8 and v.zone == "clamp" and v.segment_kind == "polar" and not v.parameter_exact
    p = dict(v.path_point)
    assert F(27) <= p["X"] <= 40 and F(120) <= p["C"] <= 150  # the corner X-40. C20. is at radius 28.28, 135 deg


NEAR = "G98\nG00 X40. Z2. C1.\nG12.1\nG01 X40. C{y} F100.\nX-40.\nG13.1\n"


def test_passing_near_the_centre_swings_c_into_a_zone_and_the_counterexample_is_real():
    """A line at 0.5 mm from the centre: C turns from 1.43 to 178.57 deg while X dips to 0.5 mm.

    The zone X 0..1 mm, C 80..100 deg lies far from both ends (X 20.006 mm); the path point (0, 0.5) of the
    plane is machine X 0.5, C 1 + 90 = 91 deg: inside.  Moved to 2 mm from the centre, the path reaches
    X 2 mm at C 91 and misses the zone (X <= 1).
    """
    m = machine(clamp("0", "1", "80", "100", "boss"))
    bad = verify_text(NEAR.format(y="0.5"), m)
    assert bad.verdict.label == "unsafe", bad.reasons
    v = bad.violations[0]
    assert v.zone == "boss" and v.span.line == 5
    pt = dict(v.point)
    assert pt["X"] <= 1 and 80 <= pt["C"] <= 100
    from nczones.controller import Controller

    sim = Controller(m).run(segments_text(NEAR.format(y="0.5"), m))
    assert sim.alarms and sim.alarms[0].line == 5
    ok = verify_text(NEAR.format(y="2."), m)
    assert ok.verdict.label == "safe"
    assert not Controller(m).run(segments_text(NEAR.format(y="2."), m)).alarms


def test_tip_zones_see_the_tool_tip_through_a_lathe_tool_offset():
    """With tool offset X80 the centre of rotation is machine X80; a tip zone sees machine X - 80."""
    boss = clamp("0", "1", "80", "100", "boss").replace('forbid = true\n', 'forbid = true\npoint = "tip"\n')
    m = machine(boss, extra='[tool_offsets]\n1 = { X = "80", Z = "0" }\n')
    prog = "G98 T0101\n" + NEAR.format(y="0.5").split("\n", 1)[1]
    r = verify_text(prog, m)
    assert r.verdict.label == "unsafe" and r.violations[0].zone == "boss"
    assert F(80) <= dict(r.violations[0].point)["X"] <= 81
    from nczones.controller import Controller

    assert Controller(m).run(segments_text(prog, m)).alarms[0].line == 5
    assert verify_text("G98 T0101\n" + NEAR.format(y="2.").split("\n", 1)[1], m).verdict.label == "safe"


def test_margin_and_parameter_ranges_compose():
    """A margin shrinks the room exactly; ranged work offsets make the mode unknown with the reason."""
    m = machine(clamp("28.5", "40", "100", "170"))
    prog = (EX / "programs" / "polar_face.nc").read_text()
    # the path's largest radius is the corner (-20, 20) at C135: sqrt(800) = 28.2843 mm (its rounded end
    # 28.2845), 0.2157 mm below the clamp
    assert verify_text(prog, m).verdict.label == "safe"
    assert verify_text(prog, m, margin=F("0.2")).verdict.label == "safe"
    assert verify_text(prog, m, margin=F("0.25")).verdict.label == "unsafe"
    from nczones.prover import parse_param

    r = verify_text(prog, m, params=(parse_param("G54.Z=-1..1", m),))
    assert r.verdict.label == "unknown" and "parameter ranges" in r.reasons[0].message


def test_a_path_touching_a_zone_face_is_unknown_not_safe():
    """The corner at C135 exactly on the face C = 135 of a zone: never safe, never a false witness."""
    m = machine(clamp("27", "40", "135", "150"))
    r = verify_text((EX / "programs" / "polar_face.nc").read_text(), m)
    assert r.verdict.label in ("unknown", "unsafe")
    for v in r.violations:  # a witness must be certified outside
        assert m.allowed.violated_zones(dict(v.point), F(0))


# --------------------------------------------------------------------------- controller


def test_controller_pulses_follow_the_path():
    """Steps of at most one pulse per axis; C unwound to 360; extremes as the exact path's."""
    m = machine()
    segs = segments_text(FACE, m)
    from nczones.controller import Controller
    from nczones.controller.polar import polar_positions
    from nczones.controller.pulses import round_pulse

    sim = Controller(m).run(segs)
    assert not sim.alarms and sim.machine_position == (F(20), F(210), F(360))
    pulses = tuple(a.pulse for a in m.axes)
    p0 = (20000, 199000, 0)
    for s in segs[2:-1]:
        pos = polar_positions(s, pulses, p0)
        steps = np.abs(np.diff(np.vstack([np.array(p0), pos]), axis=0))
        assert steps.max() <= 1
        assert tuple(pos[-1]) == tuple(round_pulse(v, u) for v, u in zip(s.end, pulses))
        p0 = tuple(int(v) for v in pos[-1])
    # the top edge (10, 20) -> (-20, 20) comes nearest the centre at (0, 20): X = 20 exactly, C = 90
    pos = polar_positions(segs[4], pulses, (22361, 199000, 63435))
    assert int(pos[:, 0].min()) == 20000
    c_at_min = pos[pos[:, 0] == 20000][:, 2]
    # X = sqrt(400 + x^2) rounds to 20 mm for |x| < sqrt(0.02) = 0.1414 (half a pulse), i.e. C within
    # atan(0.1414 / 20) = 0.405 deg of 90
    assert c_at_min.min() <= 90000 <= c_at_min.max() and 89594 <= c_at_min.min() and c_at_min.max() <= 90406


# --------------------------------------------------------------------------- agreement (DESIGN §7)


@settings(max_examples=examples(12, 25), deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(
    moves=st.lists(st.tuples(st.sampled_from(["G01", "G02", "G03"]), st.integers(-30, 30), st.integers(-30, 30),
                             st.integers(0, 30)), min_size=1, max_size=3),
    xlo=st.integers(0, 30), xw=st.integers(1, 15), clo=st.integers(-200, 200), cw_=st.integers(5, 120),
)
def test_prover_and_controller_agree(moves, xlo, xw, clo, cw_):
    """Safe with a margin of one pulse => no alarm; unsafe deeper than one pulse => an alarm in that block or
    before (DESIGN §7), on generated polar programs next to a clamp in machine X and C."""
    u = F(1, 100)
    m = machine(clamp(xlo, xlo + xw, clo, clo + cw_), pulse="0.01")
    lines = []
    x, y = F(20), F(0)
    for g, a, b, extra in moves:
        nx, ny = F(a), F(b)
        if (nx, ny) == (x, y) or (nx, ny) == (0, 0):
            continue
        if g == "G01":
            lines.append(f"G01 X{2 * nx}. C{ny}.")
        else:
            half = mpmath.sqrt((nx - x) ** 2 + (ny - y) ** 2) / 2
            r = F(mpmath.nstr(half, 12)) + F(extra, 10) + F(1, 10)
            lines.append(f"{g} X{2 * nx}. C{ny}. R{float(r):.6f}")
        x, y = nx, ny
    assume(lines)
    prog = "G98\nG00 X40. Z2. C0.\nG12.1\nF300.\n" + "\n".join(lines) + "\nG13.1\n"
    run = interpret_text(prog, m)
    segs = list(run.segments())
    assume(not run.unsupported)  # paths through the centre are unknown by design
    if m.allowed.violated_zones(dict(zip(m.axis_names, segs[0].end)), 0):
        return
    from nczones.controller import Controller

    sim = Controller(m).run(segs)
    safe = verify_text(prog, m, margin=u)
    if safe.verdict.label == "safe":
        assert not sim.alarms, prog
    plain = verify_text(prog, m)
    if plain.verdict.label == "unsafe" and plain.violations[0].depth > u:
        assert sim.alarms and sim.alarms[0].line <= plain.violations[0].span.line, prog
    event(f"margin u: {safe.verdict.label}, margin 0: {plain.verdict.label}, alarm: {bool(sim.alarms)}")


# --------------------------------------------------------------------------- CLI


def test_cli_verify_and_simulate_the_example():
    def cli(*args):
        return subprocess.run([sys.executable, "-m", "nczones", *args], capture_output=True, text=True, cwd=ROOT)

    prog = "specs/examples/programs/polar_face.nc"
    ok = cli("verify", prog, "--machine", "specs/examples/machines/turning_centre.toml")
    assert ok.returncode == 0 and "safe" in ok.stdout, ok.stdout + ok.stderr
    bad = cli("verify", prog, "--machine", "specs/examples/machines/turning_centre_clamp_near.toml")
    assert bad.returncode == 1 and "polar_face.nc:8:1: violation[clamp]" in bad.stdout, bad.stdout + bad.stderr
    assert "polar interpolation plane" in bad.stdout
    sim = cli("simulate", prog, "--machine", "specs/examples/machines/turning_centre_clamp_near.toml")
    assert "zone \"clamp\" at line 8" in sim.stdout, sim.stdout + sim.stderr


@pytest.mark.parametrize("var,unknown", [("#5003", True), ("#5023", True), ("#5043", True), ("#5001", True),
                                         ("#5002", False), ("#5022", False)])
def test_reading_a_polar_axis_position_in_the_mode_is_unknown(var, unknown):
    """State the program reads composes with the mode: X and C positions are not modelled inside G12.1 (plane
    or machine coordinate?), so a read is unknown; Z reads as everywhere, and after G13.1 C reads again."""
    m = parse_machine((EX / "machines" / "turning_centre.toml").read_text())
    prog = (f"G21 G98 G54\nG00 X40. Z2. C0.\nG01 Z-1. F200.\nG12.1\nG01 X40. C10. F100.\n#100={var}\nG13.1\n"
            "G00 Z[10.+#100]\nM30\n")
    r = verify_text(prog, m)
    assert (r.verdict.label == "unknown") is unknown
    assert any(f"{var}: a position" in x.message for x in r.reasons) is unknown
    after = verify_text("G21 G98 G54\nG00 X40. Z2. C0.\nG12.1\nG01 X40. C10. F100.\nG13.1\n#100=#5003\nM30\n", m)
    assert after.verdict.label == "safe"
