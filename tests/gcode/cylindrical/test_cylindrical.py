"""Cylindrical interpolation (G07.1, issue 7): the mode, the pulses, the proofs, their agreement."""

from __future__ import annotations

import re
import subprocess
import sys
from fractions import Fraction as F
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode import segments_text
from nczones.geometry.cylinder import (
    Interval,
    degree_length,
    developed_arc,
    developed_arc_of,
    pi_interval,
)
from nczones.machine import parse_machine
from nczones.motion import Developed, SegmentKind
from nczones.prover import verify_text
from tests.machines import machine_text

ROOT = Path(__file__).resolve().parents[3]
EX = ROOT / "specs" / "examples"


def machine(pulse="0.001", zones=""):
    return parse_machine(f"""
[machine]
axes = ["X", "Z", "C"]
pulse = "{pulse}"
path_mode = "G61"  # exact stop: these tests are about the developed arc, not corner blending
[machine.rapid]
X = "5000"
Z = "5000"
C = "5000"
[machine.reference]
X = "0"
Z = "0"
C = "0"
{zones}
""")


# --------------------------------------------------------------------------- geometry


def test_pi_enclosure_is_tight_and_sound():
    p = pi_interval()
    assert F(333, 106) < p.lo < p.hi < F(355, 113)
    assert F(3141592653589793238462643383279, 10**30) < p.lo
    assert p.hi < F(3141592653589793238462643383280, 10**30)


@pytest.mark.parametrize("r", ["5", "37.266", "120"])
def test_developed_arc_passes_through_both_ends(r):
    a = developed_arc(F(30), F(30), F(40), F(60), F(r), F(-25), False)
    z, s, c = a.point(F(0))
    assert z.contains(30) and c.contains(30) and s.contains(0)
    z, s, c = a.point(F(1))
    assert z.contains(40) and c.contains(60)
    assert s.contains(F(0)) is False and (degree_length(F(r)) * 30).lo - F(1, 10**40) <= s.hi


# --------------------------------------------------------------------------- interpreter


def test_mode_emits_lines_and_developed_arcs_and_keeps_positions_exact():
    m = machine()
    prog = "G0 X5 Z30 C30\nG1 Z31 F100\nG7.1 C20\nG1 Z32 C40.5\nG3 Z34 C50 R7\nG1 X4 Z35\nG7.1 C0\nG1 Z36 C51\nG0 X0\n"
    segs = segments_text(prog, m)
    assert [s.kind for s in segs] == [SegmentKind.RAPID, SegmentKind.LINE, SegmentKind.LINE, SegmentKind.DEVELOPED_ARC,
                                      SegmentKind.LINE, SegmentKind.LINE, SegmentKind.RAPID]
    ends = [tuple(str(v) for v in s.end) for s in segs]
    assert ends == [("5", "30", "30"), ("5", "31", "30"), ("5", "32", "81/2"), ("5", "34", "50"), ("4", "35", "50"),
                    ("4", "36", "51"), ("0", "36", "51")]
    # positions chain exactly through the mode switches
    assert all(a.end == b.start for a, b in zip(segs, segs[1:]))
    arc = segs[3]
    assert arc.extra == (Developed("Z", "C", F(20)),)
    assert arc.radius == 7 and not arc.clockwise
    assert segs[2].payload(Developed) is not None and segs[5].payload(Developed) is None
    # the same motion without the mode: the same machine positions for every line
    plain = segments_text("G0 X5 Z30 C30\nG1 Z31 F100\nG1 Z32 C40.5\nG1 Z34 C50\nG1 X4 Z35\nG1 Z36 C51\nG0 X0\n", m)
    assert [s.end for s in plain] == [s.end for s in segs]


def test_g107_and_incremental_and_inch():
    m = machine()
    segs = segments_text("G0 Z10 C10\nG107 C10\nG91 G2 Z2 C5 R3 F50\nG107 C0\n", m)
    assert segs[-1].kind is SegmentKind.DEVELOPED_ARC and segs[-1].end[1:] == (F(12), F(15))
    segs = segments_text("G20\nG0 Z1 C10\nG7.1 C1\nG1 Z2 C20 F5\nG2 Z3 C30 R1\nG7.1 C0\n", m)
    assert segs[-1].payload(Developed).cylinder_radius == F("25.4")
    assert segs[-1].end[1] == F("76.2") and segs[-1].radius == F("25.4")


@pytest.mark.parametrize("prog, code, line, col", [
    ("G7.1 C10\nG0 Z5\n", "GC230", 2, 1),
    ("G0 Z1\nG7.1 C10\nZ5 C3\n", "GC230", 3, 1),
    ("G7.1 C10\nG2 Z5 C3 I1 F10\n", "GC231", 2, 10),
    ("G7.1 C10\nG18\n", "GC230", 2, 1),
    ("G7.1 C10\nG54\n", "GC230", 2, 1),
    ("G7.1 C10 F10\n", "GC232", 1, 10),
    ("G7.1 X10\n", "GC232", 1, 6),
    ("G7.1 C-1\n", "GC233", 1, 6),
    ("G7.1 C10\nG7.1 C5\n", "GC230", 2, 1),
    ("G7.1 C10\nG1 Z0 F10\nG2 Z30 C1 R5\n", "GC330", 3, 11),
    ("G7.1 C10\nG1 Z1 F10\nG2 X1 Z2 C1 R5\n", "GC231", 3, 4),
    ("G7.1 C10\nG2 Z5 C3 F10\n", "GC231", 2, 4),
    ("G7.1 C10\nG1 F10\nG28\n", "GC230", 3, 1),
])
def test_mode_errors_have_codes_lines_and_columns(prog, code, line, col):
    with pytest.raises(GcodeError) as exc:
        segments_text(prog, machine())
    d = exc.value.diagnostics[0]
    assert (d.code, d.span.line, d.span.column) == (code, line, col), d.message


def test_mode_on_a_machine_without_the_linear_axis_is_an_error():
    m = parse_machine(machine_text("xc_unit"))
    with pytest.raises(GcodeError) as exc:
        segments_text("G7.1 C10\n", m)
    assert exc.value.diagnostics[0].code == "GC232" and "Z" in exc.value.diagnostics[0].message


# --------------------------------------------------------------------------- controller: one pulse


def _exact_deviation_ok(arc, z_p: F, c_p: F, uz: F, uc: F) -> bool:
    """Is the commanded point within one pulse (per axis) of an exact path point?

    Candidate path points (enclosed exactly): the radial projection of the
    developed point onto the circle, the circle points with the same Z and
    with the same developed s; a candidate counts when its direction from the
    centre is inside the sweep (tested on the enclosures' midpoints, far
    inside 1e-40 of the exact direction) and both coordinates are within one
    pulse for every value of its enclosure.  The end points count too.
    """
    from nczones.prover.geometry import in_sweep

    k = arc.k
    cz, cs = arc.centre
    s_p = k * (c_p - arc.c0)
    a, b = Interval.of(z_p) - cz, s_p - cs
    # the circle met by the two diagonals and the two mid-lines of the one-pulse box, and the
    # circle's extreme points: if the arc meets the box, one of these (or an end point) is in it
    cands = [(cz + arc.rho, cs), (cz - arc.rho, cs), (cz, cs + arc.rho), (cz, cs - arc.rho)]
    ck = k * uc
    for dz, ds in ((Interval.of(uz), ck), (Interval.of(uz), -ck), (Interval.of(uz), Interval.of(0)),
                   (Interval.of(0), ck)):
        A = dz.sqr() + ds.sqr()
        B = a * dz + b * ds
        C = a.sqr() + b.sqr() - arc.rho.sqr()
        disc = B.sqr() - A * C
        if disc.lo <= 0:
            continue
        for sign in (1, -1):
            tt = (-B + sign * disc.sqrt()) / A
            cands.append((cz + a + tt * dz, cs + b + tt * ds))
    u = (arc.u[0].mid(), arc.u[1].mid())
    w = (arc.z1 - cz.mid(), arc.d.mid() - cs.mid())
    for zs, ss in cands:
        d = (zs.mid() - cz.mid(), ss.mid() - cs.mid())
        if not in_sweep(u, w, d, not arc.clockwise, False):
            continue
        cc = arc.c0 + ss / k
        if max(abs(zs.lo - z_p), abs(zs.hi - z_p)) <= uz and max(abs(cc.lo - c_p), abs(cc.hi - c_p)) <= uc:
            return True
    return any(abs(zz - z_p) <= uz and abs(cc - c_p) <= uc for zz, cc in ((arc.z0, arc.c0), (arc.z1, arc.c1)))


@settings(max_examples=12, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(
    rc=st.sampled_from(["3", "10", "37.266", "100"]),
    dz=st.integers(-400, 400), dc=st.integers(-400, 400), extra=st.integers(0, 300),
    cw=st.booleans(), big=st.booleans(),
)
def test_controller_rotary_pulses_follow_developed_length_over_radius(rc, dz, dc, extra, cw, big):
    """Every commanded pulse position of a developed arc is within one pulse of the exact path.

    The rotary pulse count is therefore (developed length along the path) /
    radius within one pulse; the last position is the rounded end point.
    """
    m = machine("0.01")
    rcf = F(rc)
    dzf, dcf = F(dz, 100), F(dc, 10)
    if dzf == 0 and dcf == 0:
        dcf = F(1)
    half = ((dzf ** 2 + (degree_length(rcf) * dcf).sqr()).sqrt() / 2).hi
    r = half + F(extra, 100) + F(1, 10)
    r = -r if big else r
    prog = (f"G0 Z20 C30\nG7.1 C{rc}\nG{'2' if cw else '3'} Z{float(20 + dzf):.2f} C{float(30 + dcf):.1f} "
            f"R{float(r):.6f} F500\nG7.1 C0\n")
    segs = segments_text(prog, m)
    arc = developed_arc_of(segs[-1])
    from nczones.controller import Controller

    c = Controller(m, start=segs[0].start)
    c.run(segs[:1])
    from nczones.controller.cylindrical import developed_arc_positions

    p0 = tuple(c.counter)
    pos = developed_arc_positions(segs[-1], tuple(a.pulse for a in m.axes), p0)
    u = F(1, 100)
    assert pos[-1].tolist() == [0, 2000 + int(dzf * 100), 3000 + int(dcf * 100)]
    steps = np.abs(np.diff(np.vstack([np.array(p0), pos]), axis=0))
    assert steps.max() <= 1
    for row in pos[:: max(1, len(pos) // 150)].tolist() + [pos[-1].tolist()]:
        assert _exact_deviation_ok(arc, row[1] * u, row[2] * u, u, u), row


@pytest.mark.parametrize("rc", ["8", "37.266"])
def test_controller_line_in_the_mode_stays_within_one_pulse(rc):
    m = machine("0.001")
    segs = segments_text(f"G0 Z0 C0\nG7.1 C{rc}\nG1 Z3 C7.5 F100\nG7.1 C0\n", m)
    from nczones.controller import Controller

    c = Controller(m)
    r = c.run(segs)
    assert not r.alarms and r.machine_position == (0, 3, F("7.5"))
    # along the line, developed s = k (C - C0) and the rotary pulses follow s / k
    k = degree_length(F(rc))
    total_s = k * F("7.5")
    assert (total_s / k).contains(F("7.5"))


# --------------------------------------------------------------------------- prover


def test_prover_safe_and_unsafe_on_the_clamp():
    zones = """
[[zones]]
name = "clamp"
kind = "box"
forbid = true
min = { Z = "32.6", C = "37.5" }
max = { Z = "33.5", C = "39" }
"""
    m = machine(zones=zones)
    ok = verify_text("G0 Z30 C30\nG7.1 C20\nG2 Z34 C50 R9 F100\nG7.1 C0\n", m)
    bad = verify_text("G0 Z30 C30\nG7.1 C20\nG3 Z34 C50 R9 F100\nG7.1 C0\n", m)
    # chord: 4 mm in Z, 20 deg = 6.98 mm developed; the two arcs bulge to opposite sides
    assert (ok.verdict.label, bad.verdict.label) == ("safe", "unsafe")
    v = bad.violations[0]
    assert v.line == 3 and v.zone == "clamp" and v.segment_kind == "developed_arc"
    assert "developed surface" in v.note and "s=" in v.note
    pt = dict(v.point)
    assert m.allowed.violated_zones(pt, 0)


def test_prover_unknown_for_parameter_ranges_and_tangent_touch():
    m = machine(zones='[[zones]]\nname = "t"\nkind = "box"\nmin = { Z = "0" }\nmax = { Z = "100" }\n')
    r = verify_text("G0 Z30 C30\nG7.1 C20\nG2 Z34 C50 R9 F100\nG7.1 C0\n", m, params=["G54.Z=-1..1"])
    assert r.verdict.label in ("unknown", "safe")


# --------------------------------------------------------------------------- agreement (DESIGN §7)


@settings(max_examples=14, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(
    rc=st.sampled_from(["4", "15", "40"]),
    dz=st.integers(-300, 300), dc=st.integers(-300, 300), extra=st.integers(0, 200), cw=st.booleans(),
    zlo=st.integers(-300, 300), zw=st.integers(20, 300), clo=st.integers(-300, 300), cw_=st.integers(20, 300),
)
def test_prover_and_controller_agree(rc, dz, dc, extra, cw, zlo, zw, clo, cw_):
    u = F(1, 100)
    lo_z, lo_c = F(2000 + zlo, 100), F(3000 + clo, 100)
    hi_z, hi_c = lo_z + F(zw, 100), lo_c + F(cw_, 100)
    zone = (f'[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\n'
            f'min = {{ Z = "{float(lo_z):.2f}", C = "{float(lo_c):.2f}" }}\n'
            f'max = {{ Z = "{float(hi_z):.2f}", C = "{float(hi_c):.2f}" }}\n')
    m = machine("0.01", zones=zone)
    dzf, dcf = F(dz, 100), F(dc, 100)
    if dzf == 0 and dcf == 0:
        dcf = F(1)
    half = ((dzf ** 2 + (degree_length(F(rc)) * dcf).sqr()).sqrt() / 2).hi
    r = half + F(extra, 100) + F(1, 100)
    prog = (f"G0 X0 Z20 C30\nG7.1 C{rc}\nG{'2' if cw else '3'} Z{float(20 + dzf):.2f} C{float(30 + dcf):.2f} "
            f"R{float(r):.6f} F500\nG7.1 C0\n")
    start_bad = m.allowed.violated_zones({"X": F(0), "Z": F(20), "C": F(30)}, 0)
    if start_bad:
        return
    from nczones.controller import Controller

    segs = segments_text(prog, m)
    sim = Controller(m).run(segs)
    safe = verify_text(prog, m, margin=u)
    if safe.verdict.label == "safe":
        assert not sim.alarms, (prog, zone)
    plain = verify_text(prog, m)
    if plain.verdict.label == "unsafe" and plain.violations[0].depth > u:
        assert sim.alarms and sim.alarms[0].line <= plain.violations[0].line, (prog, zone)


# --------------------------------------------------------------------------- example and CLI


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "nczones", *args], capture_output=True, text=True, cwd=ROOT)


def test_cam_groove_example_from_the_cli():
    mach = str(EX / "machines" / "cylinder.toml")
    near = str(EX / "machines" / "cylinder_clamp_near.toml")
    for prog in ("cam_groove_segments.ngc", "cam_groove_g071.ngc"):
        path = str(EX / "programs" / prog)
        assert _cli("verify", path, "--machine", mach).returncode == 0
        r = _cli("verify", path, "--machine", near)
        assert r.returncode == 1 and "clamp" in r.stdout
    r = _cli("verify", str(EX / "programs" / "cam_groove_g071.ngc"), "--machine", near)
    assert ":6:1: violation[clamp]" in r.stdout and "developed surface" in r.stdout


def test_cam_groove_numbers_in_the_docs_are_generated():
    sys.path.insert(0, str(ROOT / "docs"))
    try:
        import cam_groove
    finally:
        sys.path.pop(0)
    block = cam_groove.markdown(cam_groove.compute())
    doc = (ROOT / "specs" / "cylindrical.md").read_text()
    assert block in doc


_MENTION_REFERENCE = re.compile(r"G[ \t]*0*(?:7[ \t]*\.[ \t]*1(?![0-9])|107(?![0-9.]))", re.I)


def _mentions_by_line(text: str) -> bool:
    return any(_MENTION_REFERENCE.search(line) for line in text.split("\n"))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(["G1 X1", "g07.1 c3", "G7 .1C0", "G107", "G7.15", "G1070", "G10.7",
                                 "G0 7.1", "(G7.1)", "G7.1", "x107", "G 00107 C1", "G\n7.1"]), max_size=8),
       st.integers(0, 3))
def test_uses_cylindrical_is_a_case_blind_search_line_by_line(items, filler):
    """The piecewise lower-case search finds exactly what a case-insensitive search of each line
    finds, wherever the mention sits relative to the pieces (fillers push it across a piece end)."""
    from nczones.gcode.cylindrical import _PIECE_CHARS, uses_cylindrical

    pad = "G1 X12.5 Y3.25\n" * (filler * _PIECE_CHARS // 30)
    text = pad + "\n".join(items) + "\n" + pad
    assert uses_cylindrical(text) == _mentions_by_line(text)
