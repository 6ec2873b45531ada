"""Pictures match the proof for tool solids (issue 39): the tool drawn at a solid violation's contact is where
the prover's witness puts it, and the witness is inside the drawn part and the drawn fixture.

Checked from the figures' data (matplotlib patches in data coordinates, the 3-D view's mesh vertices), not
pixels.  The machine specs/machines/mill_solids.toml: tool 1 = cutter Ø10 × 25, shank Ø10 × 15, holder
Ø63 × 60, H1 = 100, the spindle nose Ø120 × 80 above the gauge line; the vise X 100..250, Y 0..80,
Z 0..60; the clamp post a cylinder about (400, 200), radius 15, Z 0..50.  With the controlled point (the
gauge line) at machine Z ``z`` the holder spans Z ``z - 100 + 40 .. z - 100 + 100``."""

from __future__ import annotations

from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from matplotlib.path import Path as MplPath  # noqa: E402

from nczones.report.figure import collect_path, plot_program  # noqa: E402
from nczones.report.html import render_html  # noqa: E402
from nczones.report.interactive import view_data  # noqa: E402
from nczones.report.solids_view import contact_solids  # noqa: E402

from .helpers import EX, run_example  # noqa: E402

HITS = "programs/holder_hits_vise.ngc"
CLEARS = "programs/holder_clears_vise.ngc"


@pytest.fixture(scope="module")
def hits():
    return run_example(HITS, "mill_solids.toml")


def _drawn(patch):
    """The patch's outline in data coordinates."""
    return patch.get_patch_transform().transform_path(patch.get_path())


def test_the_drawn_assembly_is_the_machine_files_at_the_path_point(hits):
    result, _m = hits
    contacts = contact_solids(result)
    assert [v.line for _, v, _, _ in contacts] == [6, 7, 8]
    _i, v, parts, fx = contacts[0]
    # line 6, G1 Z10 from Z100 with H1 = 100: the witness's path point is X80 Y40 Z115 (machine Z)
    assert dict(v.path_point) == {"X": 80, "Y": 40, "Z": 115}
    z = Fraction(115)
    want = [("cutter", Fraction(5), z - 100, z - 75, False), ("shank", Fraction(5), z - 75, z - 60, False),
            ("holder", Fraction(63, 2), z - 60, z, True), ("spindle nose", Fraction(60), z, z + 80, False)]
    assert [(s.name, s.radius, s.z0, s.z1, hit) for s, hit in parts] == want
    assert all(s.centre == (80, 40) for s, _ in parts)
    assert (fx.name, fx.box, fx.z0, fx.z1) == ("vise", (100, 250, 0, 80), 0, 60)
    # the witness inside the entering part and the fixture, exactly
    for _i, v, parts, fx in contacts:
        q = dict(v.point)
        s = next(s for s, hit in parts if hit)
        assert (q["X"] - s.centre[0]) ** 2 + (q["Y"] - s.centre[1]) ** 2 <= s.radius ** 2
        assert s.z0 <= q["Z"] <= s.z1
        assert fx.box[0] < q["X"] < fx.box[1] and fx.box[2] < q["Y"] < fx.box[3] and fx.z0 < q["Z"] < fx.z1


@pytest.mark.parametrize("plane", [("X", "Y"), ("X", "Z"), ("Y", "Z")])
def test_plane_figures_draw_the_witness_inside_the_part_and_the_fixture(hits, plane):
    result, m = hits
    fig = plot_program(str(EX / HITS), m, plane, result)
    patches = {p.get_gid(): p for p in fig.axes[0].patches if p.get_gid()}
    assert "fixture-clamp" in patches  # a [[fixtures]] cylinder no zone draws
    for i, v, parts, _fx in contact_solids(result):
        q = dict(v.point)
        xy = (float(q[plane[0]]), float(q[plane[1]]))
        part, fixture = _drawn(patches[f"contact-part-{i}"]), _drawn(patches[f"contact-fixture-{i}"])
        assert part.contains_point(xy) and fixture.contains_point(xy), (plane, i, xy)
        # the part drawn where the prover placed it: its extent is the path point ± the radius, and in Z its
        # heights above the tip
        s = next(s for s, hit in parts if hit)
        ext = part.get_extents()
        want = [(float(s.span(a)[0]), float(s.span(a)[1])) for a in plane]
        assert ext.x0 == pytest.approx(want[0][0]) and ext.x1 == pytest.approx(want[0][1])
        assert ext.y0 == pytest.approx(want[1][0]) and ext.y1 == pytest.approx(want[1][1])
    plt.close(fig)


def test_the_3d_view_draws_the_witness_inside_the_part_and_the_fixture(hits):
    result, m = hits
    path = collect_path(str(EX / HITS), m, {v.block for v in result.violations})
    traces = view_data(path, result, m)["traces"]
    meshes = {t["meta"]: t for t in traces if t["type"] == "mesh3d" and t.get("meta")}
    assert "fixture" in meshes and {f"tool-part-1-{k}" for k in (1, 2, 4)} <= set(meshes)
    for i, v, _parts, _fx in contact_solids(result):
        q = [float(x) for _, x in v.point]
        assert meshes[f"contact-fixture-{i}"]["name"] == f"vise (fixture entered, violation {i})"
        for t in (meshes[f"contact-part-{i}"], meshes[f"contact-fixture-{i}"]):
            n = len(t["x"]) // 2  # the bottom ring, then the top ring
            ring = MplPath(list(zip(t["x"][:n], t["y"][:n])))
            assert ring.contains_point(q[:2]) and min(t["z"]) <= q[2] <= max(t["z"]), (i, t["name"])


def test_the_fixed_program_has_no_contact():
    result, _m = run_example(CLEARS, "mill_solids.toml")
    assert result.verdict.label == "safe" and contact_solids(result) == []
    # its HTML page (tests/report/test_solids_goldens.py) draws the clamp and no tool


@pytest.mark.long  # a browser start: about 30 s on the shared CI cores
def test_chromium_draws_the_tool_at_the_contact(hits, tmp_path):
    """The holder example in a real browser: the page loads without errors, the 3-D view holds every trace of
    the data (the tool and fixtures among them), screenshots in build/screenshots (holder-*.png)."""
    from tests.report.test_html_view import SCREENSHOTS, _need_browser

    _need_browser()
    from tests.tools.browser import Browser

    result, m = hits
    report = tmp_path / "holder.html"
    report.write_text(render_html(result, m, str(EX / HITS)), encoding="utf-8")
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    with Browser(width=1200, height=900) as browser:
        page = browser.open(report.as_uri())
        page.wait_for("document.body.getAttribute('data-view') === 'ready'")
        metas = page.eval("[...document.getElementById('view3d-plot').data].map(function (t) { return t.meta || ''; })")
        assert page.errors() == []
        page.screenshot(str(SCREENSHOTS / "holder-view.png"), selector="#view3d")
        page.screenshot(str(SCREENSHOTS / "holder-planes.png"), selector="#plots")
        page.close()
    assert {"contact-part-1", "contact-fixture-1", "fixture", "tool-part-1-4"} <= set(metas)
    assert (SCREENSHOTS / "holder-view.png").stat().st_size > 5000
