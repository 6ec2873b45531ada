"""``export-zones``: what a control can hold, and the round trip export -> import.

The allowed sets are compared exactly: for box zones, membership only changes
at the boundary values, so testing every cell of the grid they cut (each
boundary value, a point between two neighbours, a point beyond the ends) on
every axis decides whether two sets are equal.
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.cli import main
from nczones.exact import format_decimal
from nczones.imports import import_text
from nczones.imports.export import export_zones
from nczones.machine import Machine, parse_machine
from nczones.testing import machines
from tests.machines import machine_text

F = Fraction


def _cells(values: set[Fraction]) -> list[Fraction]:
    vs = sorted(values)
    if not vs:
        return [F(0)]
    points = [vs[0] - 1, vs[-1] + 1]
    points += vs
    points += [(a + b) / 2 for a, b in zip(vs, vs[1:])]
    return points


def _grid(*ms: Machine) -> list[dict[str, Fraction]]:
    axes = ms[0].axis_names
    per_axis = []
    for a in axes:
        values: set[Fraction] = set()
        for m in ms:
            for z in m.zones:
                lo, hi = z.bounds().get(a, (None, None))
                values.update(v for v in (lo, hi) if v is not None)
        per_axis.append(_cells(values))
    return [dict(zip(axes, p)) for p in itertools.product(*per_axis)]


def _same_allowed_set(a: Machine, b: Machine) -> bool:
    return all(a.allowed.contains(p) == b.allowed.contains(p) for p in _grid(a, b))


def _contains(big: Machine, small: Machine) -> bool:
    return all(big.allowed.contains(p) for p in _grid(big, small) if small.allowed.contains(p))


def _round_trip(m: Machine, kind: str) -> tuple[Machine, object]:
    r = export_zones(m, kind, include_machine=True)
    back = import_text(r.text, "exported.ini" if kind == "linuxcnc" else "exported.prm", kind).machine
    return back, r


BOXES = dict(axes=("X", "Y", "Z"), allow_kinds=("box",), tip_zones=False, tool_lengths=False)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(m=machines(**BOXES, forbid_boxes=False))
def test_round_trip_linuxcnc_boxes(m):
    back, r = _round_trip(m, "linuxcnc")
    assert r.exact and all("MAX_VELOCITY" in n.message for n in r.notes)  # 8000 mm/min is 133.3... mm/s
    assert _same_allowed_set(m, back)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(m=machines(**BOXES, forbid_boxes=True))
def test_round_trip_fanuc_boxes_with_a_forbidden_box(m):
    back, r = _round_trip(m, "fanuc")
    assert r.exact, [n.message for n in r.notes]
    assert _same_allowed_set(m, back)
    assert back.axis_names == m.axis_names and back.reference == m.reference


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(m=machines(axes=("X", "Y", "Z"), allow_kinds=("stepped", "polygon", "box"), places=2), kind=st.sampled_from(["linuxcnc", "fanuc"]))
def test_what_the_control_holds_contains_the_allowed_set(m, kind):
    back, r = _round_trip(m, kind)
    assert _contains(back, m)
    kinds = {z.kind for z in m.zones}
    if kinds & {"stepped", "polygon"} or any(z.point.value == "tip" for z in m.zones):
        assert not r.exact and any(n.code == "EX101" for n in r.notes)
    if r.exact:
        assert _same_allowed_set(m, back)


MILL = parse_machine(machine_text("export_mill"), "mill.toml")


def test_fanuc_rounds_outwards_and_says_what_it_left_out():
    r = export_zones(MILL, "fanuc")
    assert not r.exact
    assert "N01320A1P800001A2P500000A3P0" in r.text  # 800.0005 rounded up: the control allows a little more
    assert "N01322A1P99999999A2P99999999A3P99999999" in r.text  # unbounded sides beyond stroke check 1
    assert "N01323A1P700000A2P400000A3P-99999999" in r.text
    codes = sorted(n.code for n in r.notes)
    assert codes == ["EX101", "EX101", "EX102"]
    assert "tool-tip" in " ".join(n.message for n in r.notes) and "polygon" in " ".join(n.message for n in r.notes)


def test_linuxcnc_cannot_hold_forbidden_areas_and_converts_to_inches():
    r = export_zones(MILL, "linuxcnc", units="inch")
    assert not r.exact
    assert sum(n.code == "EX101" for n in r.notes) == 3
    # mm / 25.4 is rarely a finite decimal: rounded outwards at 1e-7 in (maximum up, minimum down)
    assert "[AXIS_X]\nMIN_LIMIT = 0\nMAX_LIMIT = 31.4960827\n" in r.text  # 800.0005 mm = 31.49608267... in
    assert "[AXIS_Y]\nMIN_LIMIT = 0\nMAX_LIMIT = 19.6850394\n" in r.text  # 500 mm = 19.68503937... in
    assert "[JOINT_2]\nMIN_LIMIT = -15.7480315\nMAX_LIMIT = 0\n" in r.text  # -400 mm = -15.74803149... in
    assert export_zones(MILL, "linuxcnc").text.count("MAX_LIMIT = 800.0005") == 2  # exact in mm


@pytest.mark.parametrize("args,text", [
    (["--kind", "fanuc", "--increment", "0.002"], "--increment"),
    (["--kind", "linuxcnc", "--units", "furlong"], "--units"),
    (["--kind", "heidenhain"], "--kind"),
])
def test_cli_bad_options(tmp_path, capsys, args, text):
    m = tmp_path / "m.toml"
    m.write_text(machine_text("export_x_bare"))
    try:
        code = main(["export-zones", str(m), *args])
    except SystemExit as exc:  # argparse refuses a choice before the command runs
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err
    assert text in err and "Traceback" not in err


def test_cli_exit_status_says_whether_the_control_holds_it_exactly(tmp_path, capsys):
    exact = tmp_path / "box.toml"
    exact.write_text(machine_text("export_x_box"))
    assert main(["export-zones", str(exact), "--kind", "linuxcnc", "-o", str(tmp_path / "out.ini")]) == 0
    out = capsys.readouterr().out
    assert "holds the allowed set exactly" in out
    assert "MIN_LIMIT = -1" in (tmp_path / "out.ini").read_text()
    stepped = Path(__file__).resolve().parents[2] / "specs" / "machines" / "grinder.toml"
    assert main(["export-zones", str(stepped), "--kind", "fanuc"]) == 1
    captured = capsys.readouterr()
    assert captured.out.startswith("%\n") and "note[EX101]" in captured.err and "stepped" in captured.err


# ------------------------------------------------------------------ a Fanuc lathe's diameter axis (1006#3 DIA)
# FANUC Series 0i-D / 30i parameter manuals (B-64310EN, B-63950EN), 1320/1321: the stored stroke limits are
# machine coordinates, and on an axis with diameter specification (1006#3 DIA = 1) "a diameter value" is set;
# the 16/18-TC operator's manual B-62754EN 9.4 ("Diameter and radius programming"): "Display of axis position:
# displayed as diameter value".  The machine file counts a diameter axis' machine coordinate as a radius
# (diameter_axes, specs/turning.md), so the parameter value is twice the machine file's.

LATHE = parse_machine(machine_text("export_fanuc_lathe"), "lathe.toml")


def test_fanuc_export_writes_diameters_for_a_diameter_axis():
    r = export_zones(LATHE, "fanuc", include_machine=True)
    lines = r.text.splitlines()
    # X radius 125.25 -> diameter 250.5 = 250500 counts of 0.001; -1 -> -2000; Z as written
    assert "N01320A1P250500A2P700000" in lines and "N01321A1P-2000A2P0" in lines
    assert "N01322A1P260000A2P710000" in lines and "N01323A1P200000A2P600000" in lines
    assert "N01006A1P00001000A2P00000000" in lines  # DIA on X
    assert "N01240A1P240000A2P400000" in lines  # the reference X 120 (radius) is 240 on the control
    assert r.exact


def test_fanuc_import_halves_a_diameter_axis_and_keeps_diameter_axes():
    # 1320 X 225.0 (a diameter) allows the tool to a radius of 112.5
    text = ("%\nN01006A1P00001000A2P00000000\nN01020A1P88A2P90\nN01240A1P220000A2P300000\n"
            "N01320A1P225000A2P305000\nN01321A1P-2000A2P-5000\nN01420A1P15000A2P20000\n%\n")
    m = import_text(text, "lathe.prm", "fanuc").machine
    assert m.diameter_axes == ("X",) and m.is_lathe
    (z,) = [z for z in m.zones if not z.forbid]
    assert z.bounds()["X"] == (F(-1), F(225, 2)) and z.bounds()["Z"] == (F(-5), F(305))
    assert m.reference == (F(110), F(300))


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(xs=st.lists(st.integers(-50_000, 150_000), min_size=2, max_size=2, unique=True),
       zs=st.lists(st.integers(-50_000, 150_000), min_size=2, max_size=2, unique=True))
def test_round_trip_of_a_lathe_keeps_radii_and_diameter_axes(xs, zs):
    # radii on a 0.0005 grid (a diameter of whole 0.001 counts): exact both ways
    (x0, x1), (z0, z1) = sorted(xs), sorted(zs)
    d = format_decimal
    m = parse_machine(f"""
[machine]
type = "lathe"
dialect = "fanuc"
axes = ["X", "Z"]
diameter_axes = ["X"]
rapid = {{ X = "12000", Z = "15000" }}
reference = {{ X = "{d(F((x0 + x1) // 2, 2000))}", Z = "{d(F(z0, 1000))}" }}
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "{d(F(x0, 2000))}", Z = "{d(F(z0, 1000))}" }}
max = {{ X = "{d(F(x1, 2000))}", Z = "{d(F(z1, 1000))}" }}
""", "lathe.toml")
    back, r = _round_trip(m, "fanuc")
    assert r.exact, [n.message for n in r.notes]
    assert back.diameter_axes == ("X",) and back.is_lathe
    assert _same_allowed_set(m, back)
    assert back.reference == m.reference


def test_fanuc_import_reads_the_lathe_tool_offset_bits():
    # 5002 #4 LGT = 0 (coordinate shift), #5 LGC = 1 (offset number 0 cancels the geometry too); a lathe only
    text = ("%\nN01006A1P00001000A2P00000000\nN01020A1P88A2P90\nN01420A1P15000A2P20000\n"
            "N05002P00100000\n%\n")
    # LGT's reading is the 0i-TC operator's manual's (B-64114EN, 14.1: "LGT = 0 (Tool geometry compensation is
    # based on shift of the coordinate system.)", "LGT = 1 (... based on tool movement.)"); for LGC no manual text
    # was found: it is written commented out, and the machine file leaves tool_offset_cancel unset
    im = import_text(text, "lathe.prm", "fanuc")
    assert (im.machine.fanuc.tool_offset_motion, im.machine.fanuc.tool_offset_cancel) == ("shift", None)
    assert '# tool_offset_cancel = "all"' in im.text
    m = import_text(text.replace("N05002P00100000", "N05002P00010000"), "lathe.prm", "fanuc").machine
    assert (m.fanuc.tool_offset_motion, m.fanuc.tool_offset_cancel) == ("move", None)
