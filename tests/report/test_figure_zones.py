"""The drawing matches the proof: every reported witness lies inside the drawn zone it names.

Checked from the figure's data (the matplotlib patches' paths in data coordinates, not pixels): for a
forbid zone, the witness (a machine position, ``Violation.point``) is inside the patch drawn for that zone
at the placement of the tool active at the violating block; for an allow zone it is outside the drawn
allowed set in some plane.  Issue 37: the lathe's tip zones were drawn without the X tool offset (the jaws
at X25-32 where, for the turret, they are at X105-112), so the witness sat in open green space.
"""

from __future__ import annotations

from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from nczones import load_machine  # noqa: E402
from nczones.gcode.source import program_text  # noqa: E402
from nczones.prover import verify  # noqa: E402
from nczones.report.figure import (  # noqa: E402
    drawing_placements,
    plot_program,
    relevant_planes,
)
from nczones.report.placement import placed_zones  # noqa: E402
from tests.machines import machine_text

from .helpers import EX, MACHINES, verify_with_hot_path  # noqa: E402

CASES = {
    # mill, tip box moved by the G43 tool length
    "mill drill into vise (tip zone, tool length)": ("programs/drill_vise.ngc", MACHINES / "mill.toml"),
    "mill helix into vise corner": ("programs/helix_into_vise_corner.ngc", MACHINES / "mill.toml"),
    "grinder stepped table": ("programs/notch_dip.ngc", MACHINES / "grinder.toml"),
    "fanuc mill macro loop into clamp": ("programs/fanuc_slots_clamp.nc", MACHINES / "fanuc_mill.toml"),
    # Fanuc lathe, program in diameter, tip zones moved by the tool's Z *and* X offsets
    "fanuc lathe G71 into jaws (diameter, tip zones)": ("programs/g71_jaws.nc", MACHINES / "fanuc_lathe.toml"),
    "G07.1 developed arc into clamp": ("programs/cam_groove_g071.ngc", EX / "machines/cylinder_clamp_near.toml"),
    "G12.1 polar face into clamp": ("programs/polar_face.nc", EX / "machines/turning_centre_clamp_near.toml"),
}

TEXT_CASES = {
    # LinuxCNC lathe in radius, machine-point polygon chuck: G54 Z50, so program Z-20 is machine Z30, X50 radius
    # lies in the chuck polygon (Z 0..40 below X60).
    "radius lathe into polygon chuck": ("G18 G21\nG0 X50 Z20\nG1 Z-20 F100\nM2\n", MACHINES / "lathe.toml"),
    # Fanuc lathe: the tailstock is a tip polygon (plane Z,X).  T0101: tip = machine - (X80, Z50); G54 Z200.
    # X20. is a diameter: tip radius 10, program Z150 is tip Z350 -> in the polygon (Z 320..360 below X15).
    "fanuc lathe into tailstock polygon (tip)": (
        "%\nO1\nG21 G18 G99\nT0101\nG00 X100. Z150.\nG01 X20. F0.2\nG00 X200.\nM30\n%\n",
        MACHINES / "fanuc_lathe.toml"),
    # two tools, each violation drawn with the tip zones its tool saw (T2: X85 Z45, X wear 0.01)
    "fanuc lathe two tools": (
        "%\nO2\nG21 G18 G99\nT0101\nG00 X100. Z150.\nG01 X20. F0.2\nG00 X200.\nT0202\nG00 X60. Z-60.\n"
        "G01 Z-70. F0.2\nG00 X200.\nM30\n%\n",
        MACHINES / "fanuc_lathe.toml"),
}


def _patches(ax):
    return {p.get_gid(): p for p in ax.patches if p.get_gid()}


def _check(source, machine_path):
    m, result, path = verify_with_hot_path(source, machine_path)
    assert result.violations, "a known unsafe case"
    placements = drawing_placements(path)
    planes = relevant_planes(m, result)
    checked = 0
    for plane in planes:
        fig = plot_program(source, m, plane, result, path=path)
        ax = fig.axes[0]
        patches = _patches(ax)
        for v in result.violations:
            point = dict(v.point)
            if plane[0] not in point or plane[1] not in point:
                continue
            xy = (float(point[plane[0]]), float(point[plane[1]]))
            zone = next(z for z in m.zones if z.name == v.zone)
            if zone.forbid:
                k = placements.index(path.hot_placements[v.block]) if zone.point.value == "tip" else 0
                gid = f"forbid-{v.zone}" if k == 0 else f"forbid-{v.zone}@{k + 1}"
                if gid not in patches:  # the zone does not show in this plane
                    assert not set(zone.axes) <= set(plane)
                    continue
                assert patches[gid].get_path().contains_point(xy), (plane, v.zone, xy)
                checked += 1
            elif not patches["allowed-set"].get_path().contains_point(xy):
                checked += 1
            else:  # inside the drawn allowed set: only where the zone's bound is not in this plane
                assert not set(zone.axes) <= set(plane), (plane, v.zone, xy)
        plt.close(fig)
    assert checked >= 1


@pytest.mark.parametrize("name", sorted(CASES))
def test_witness_inside_the_drawn_zone_examples(name):
    program, machine = CASES[name]
    _check(str(EX / program), machine)


@pytest.mark.parametrize("name", sorted(TEXT_CASES))
def test_witness_inside_the_drawn_zone_programs(name):
    text, machine = TEXT_CASES[name]
    _check(program_text(text, "t.nc"), machine)


def test_lathe_jaws_are_drawn_in_turret_coordinates():
    """specs/machines/fanuc_lathe.toml: jaws (tip) X25..32 Z100..140, tool offset 1 X80 Z50: the turret meets
    them at X105..112 Z150..190 (machine = tip + offset), and the proof checks them grown on X and Z by the
    0.8 mm reach of the tools' nose radius (nczones.prover.nose): X104.2..112.8 Z149.2..190.8."""
    m = load_machine(MACHINES / "fanuc_lathe.toml")
    jaws = next(z for z in placed_zones(m, (Fraction(50), (("X", Fraction(80)),))) if z.name == "jaws")
    reach = Fraction(4, 5)
    assert dict((a, (lo, hi)) for a, lo, hi in jaws.limits) == {"X": (105 - reach, 112 + reach),
                                                                  "Z": (150 - reach, 190 + reach)}
    source = str(EX / "programs/g71_jaws.nc")
    fig = plot_program(source, m, ("Z", "X"), verify(source, m))
    ext = _patches(fig.axes[0])["forbid-jaws"].get_path().get_extents()
    assert (ext.x0, ext.x1, ext.y0, ext.y1) == pytest.approx((149.2, 190.8, 104.2, 112.8))
    plt.close(fig)


def test_plot_machine_draws_tip_zones_for_the_tool_in_use():
    """The notebooks' plot_machine (notebook 09 draws g71_jaws with it): same placement as the proof."""
    from nczones.gcode import interpret
    from nczones.motion import MotionChunk
    from nczones.report.plot import plot_machine

    m = load_machine(MACHINES / "fanuc_lathe.toml")
    segs = [s for c in interpret(str(EX / "programs/g71_jaws.nc"), m)
            for s in (c.segments() if isinstance(c, MotionChunk) else [c])]
    ax = plot_machine(m, segs, plane=("Z", "X"))
    jaws = [p for p in ax.patches if (p.get_label() or "").startswith("jaws (")]
    b = jaws[0].get_bbox()
    # the jaws at Z150-190 X105-112 in turret coordinates, grown on Z and X by the 0.8 mm reach of the tools'
    # nose radius, as the proof checks them (nczones.prover.nose)
    assert (b.x0, b.x1, b.y0, b.y1) == pytest.approx((149.2, 190.8, 104.2, 112.8))
    plt.close(ax.figure)


def test_lathe_view_z_horizontal_x_up_and_diameter():
    """A lathe's default view puts Z horizontal and X up; diameter=True labels X ticks as diameters (twice the
    machine radius) while the drawn data stay machine coordinates (the witness X111 radius)."""
    m = load_machine(MACHINES / "fanuc_lathe.toml")
    source = str(EX / "programs/g71_jaws.nc")
    result = verify(source, m)
    assert relevant_planes(m, result)[0] == ("Z", "X")
    fig = plot_program(source, m, result=result, diameter=True)
    ax = fig.axes[0]
    assert ax.get_xlabel() == "Z (mm)" and ax.get_ylabel() == "X (diameter, mm)"
    assert ax.yaxis.get_major_formatter()(50.0, 0) == "100"
    sc = next(c for c in ax.collections if c.get_gid() == "counterexample")
    assert sc.get_offsets().tolist()[0][1] == 111.0  # X111 radius, the turret in machine coordinates
    plt.close(fig)


# the report tests' mill (tests/machines/report_mill.toml: travel 600 x 400 x 400, H1 = 120) at G54 = 0
STEPPED_TIP_MILL = machine_text("report_mill", set={
    "machine.name": "mill with a stepped floor for the tool tip", "machine.units": "mm",
    "machine.rapid_mode": "linear", "machine.monitor_period_ms": "2",
    "machine.rapid.X": "15000", "machine.rapid.Y": "15000", "offsets.G54": {"X": "0", "Y": "0", "Z": "0"},
}, extra="""\
[[zones]]
name = "floor"
kind = "stepped"
point = "tip"
reference_axis = "X"
limited_axis = "Z"
from = "0"
regions = [{ upto = "200", min = "50", max = "400" }, { upto = "600", min = "100", max = "400" }]
""")


def test_witness_outside_a_stepped_tip_table(tmp_path):
    """A stepped table (limit-value table) of the tool tip, moved by the tool length: with H1 = 120 the tip's
    floor Z100 over X200..600 is machine Z220 there; G1 Z70 at X300 (tip Z70) is below it, machine Z190."""
    machine = tmp_path / "m.toml"
    machine.write_text(STEPPED_TIP_MILL, encoding="utf-8")
    _check(program_text("G21 G90 G54\nG43 H1\nG0 X300 Y50 Z200\nG1 Z70 F100\nM2\n", "t.ngc"), machine)
    m = load_machine(machine)
    floor = next(z for z in placed_zones(m, (Fraction(120), ())) if z.name == "floor")
    assert [(r.upto, r.min) for r in floor.regions] == [(200, 170), (600, 220)]


def test_zoom_to_the_violation_keeps_the_witness_in_view():
    """helix_into_vise_corner: the helix is a few pixels of a 600 x 400 travel; zoom=True shows the violating
    block and its witness (X106 Y68, first exit at the vise corner X110 Y60), the whole machine stays drawn."""
    m = load_machine(MACHINES / "mill.toml")
    source = str(EX / "programs/helix_into_vise_corner.ngc")
    result = verify(source, m)
    fig = plot_program(source, m, ("X", "Y"), result, zoom=True)
    ax = fig.axes[0]
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    for q in (dict(result.violations[0].point), dict(result.violations[0].first_exit)):
        assert x0 < float(q["X"]) < x1 and y0 < float(q["Y"]) < y1
    assert x1 - x0 < 100 and y1 - y0 < 100  # not the 600 x 400 travel
    assert "allowed-set" in _patches(ax)
    plt.close(fig)
