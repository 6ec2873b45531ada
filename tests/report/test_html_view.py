"""The HTML report's interactive view (issue 37): its figure data, the thinning of long paths, and the page in
headless Chromium (one browser session for all page tests).

From the data (not pixels): every witness marker of a bundled unsafe example lies inside the solid drawn for the
zone it names (a forbid zone) or outside it (an allow zone); every violation has a view around its witness; the
thinned path keeps the violating blocks whole and stays within the grid bound of the path.  In Chromium: the
page loads without console errors or network requests, the 3-D canvas has a size and the plot holds every
trace of the data, a click on the witness (projected with the scene's own camera) scrolls the listing to its
line, and the view selector reaches the whole machine.  Screenshots of the bundled unsafe examples (mill,
grinder, lathe, Fanuc) go to build/screenshots/ (CI keeps that folder, docs/ci.md).

Chromium absent: these page tests skip, except in CI (CI=true), where they fail: .ci/run installs it.
"""

from __future__ import annotations

import functools
import json
import math
import os
import re
import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones import load_machine
from nczones.gcode.source import program_text
from nczones.prover import verify_text
from nczones.report.figure import PathFloat, collect_path, thin_path
from nczones.report.interactive import plotly_js, view_data
from tests.machines import machine_text

from .helpers import EX, MACHINES, ROOT, verify_with_hot_path

IN_CI = os.environ.get("CI", "").lower() == "true"
SCREENSHOTS = Path(os.environ.get("NCZONES_SCREENSHOTS", ROOT / "build" / "screenshots"))

#: the bundled unsafe examples, one per kind of machine (specs/examples/README.md)
EXAMPLES = {
    "mill": ("programs/helix_into_vise_corner.ngc", MACHINES / "mill.toml"),
    "mill-drill": ("programs/drill_vise.ngc", MACHINES / "mill.toml"),
    "grinder": ("programs/notch_dip.ngc", MACHINES / "grinder.toml"),
    "lathe": ("programs/g71_jaws.nc", MACHINES / "fanuc_lathe.toml"),
    "fanuc": ("programs/fanuc_slots_clamp.nc", MACHINES / "fanuc_mill.toml"),
}


@functools.lru_cache(maxsize=None)
def _view(name: str):
    """(result, machine, view data) of an example, computed once per test session (the data is not changed)."""
    program, machine_path = EXAMPLES[name]
    m, result, path = verify_with_hot_path(str(EX / program), machine_path)
    return result, m, view_data(path, result, m)


def _inside_solid(trace: dict, point: list[float], tol: float = 1e-6) -> bool:
    """Whether ``point`` lies in the solid a zone trace draws, grown by ``tol`` (shrunk when negative: its
    interior): a mesh3d prism (its first half of vertices the bottom polygon, the second half the top, extruded
    along the one axis on which they differ) or a filled 2-D polygon, read back from the trace, not the zone."""
    from matplotlib.path import Path as MplPath

    if trace["type"] == "mesh3d":
        pts = np.array([trace["x"], trace["y"], trace["z"]], float).T
        n = len(pts) // 2
        bottom, top = pts[:n], pts[n:]
        axis = int(np.argmax(np.abs(top[0] - bottom[0])))
        lo, hi = sorted((bottom[0, axis], top[0, axis]))
        if not lo - tol <= point[axis] <= hi + tol:
            return False
        plane = [k for k in range(3) if k != axis]
        poly, q = bottom[:, plane], [point[k] for k in plane]
    else:
        poly, q = np.array([trace["x"], trace["y"]], float).T[:-1], point
    # matplotlib's radius grows a polygon by |radius| with the sign matching its orientation
    area = sum(poly[i - 1][0] * poly[i][1] - poly[i][0] * poly[i - 1][1] for i in range(len(poly)))
    return bool(MplPath(poly).contains_point(q, radius=tol if area > 0 else -tol))


def _zone_solids(data: dict, zone: str) -> list[dict]:
    """The solids drawn for ``zone``: its mesh3d faces (3-D) or filled polygons (2-D)."""
    return [t for t in data["traces"] if t.get("legendgroup", "").startswith(f"zone:{zone} (")
            and (t["type"] == "mesh3d" or t.get("fill") == "toself")]


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_each_witness_lies_in_the_drawn_zone_it_names(name):
    """The ✕ (◆ in 3-D) of each witness, as the view draws it, inside the drawn solid of its forbid zone, outside
    the solid of its allow zone; the witness coordinates are the exact point of the verdict, as floats."""
    _check_witnesses(*_view(name))


def _check_witnesses(result, m, data) -> None:
    marks = next(t for t in data["traces"] if t.get("meta") == "witness")
    keys = ("x", "y", "z")[:len(data["axes"])]
    checked = 0
    for k, ident in enumerate(marks["ids"]):
        v = result.violations[int(ident.split("-")[1]) - 1]
        point = [marks[c][k] for c in keys]
        exact = dict(v.point)
        assert point == pytest.approx([float(exact[a]) for a in data["axes"]], abs=1e-6)
        solids = _zone_solids(data, v.zone)
        zone = next(z for z in m.zones if z.name == v.zone)
        if not solids:  # the zone does not show in the view's axes
            assert not set(zone.axes) <= set(data["axes"])
            continue
        if zone.forbid:  # in the drawn zone (its boundary included: a forbid zone is closed)
            assert any(_inside_solid(t, point) for t in solids), (v.zone, point)
        elif set(zone.axes) <= set(data["axes"]):  # not in the interior of the drawn allowed zone
            # (on its boundary it may be: a stepped table's region owns one end of its span, not both)
            assert not any(_inside_solid(t, point, -1e-6) for t in solids), (v.zone, point)
        checked += 1
    assert checked >= 1


# the report tests' mill (tests/machines/report_mill.toml: travel 600 x 400 x 400) at G54 = 0, H1 = 100
MILL_L_CLAMP = machine_text("report_mill", set={
    "machine.name": "mill with an L-shaped clamp and a stepped floor", "machine.units": "mm",
    "machine.rapid_mode": "linear", "offsets.G54": {"X": "0", "Y": "0", "Z": "0"}, "tool_lengths.H1": "100",
}, extra="""\
[[zones]]
name = "clamp"
kind = "polygon"
forbid = true
point = "tip"
plane = ["X", "Y"]
vertices = [["100", "100"], ["200", "100"], ["200", "150"], ["140", "150"], ["140", "250"], ["100", "250"]]
min = { Z = "0" }
max = { Z = "80" }
[[zones]]
name = "floor"
kind = "stepped"
point = "tip"
reference_axis = "X"
limited_axis = "Z"
from = "0"
regions = [{ upto = "300", min = "20", max = "400" }, { upto = "600", min = "60", max = "400" }]
""")


def test_3d_solids_of_a_polygon_prism_and_a_stepped_table(tmp_path):
    """A polygon zone is a prism along the third axis, a stepped table stacked boxes, both moved by the tool
    length (H1 = 100) as the proof moves tip zones.  Line 4 plunges the tip to Z50 at X120 Y200, in the L's
    upright (X100-140, Y150-250; the clamp is Z0-80 for the tip, machine Z100-180); line 7 takes the tip to Z40
    at X400, below the floor's Z60 over X300-600 (machine Z160)."""
    machine = tmp_path / "m.toml"
    machine.write_text(MILL_L_CLAMP, encoding="utf-8")
    m = load_machine(machine)
    text = "G21 G90 G54 F100\nG43 H1\nG0 X120 Y200 Z250\nG1 Z50\nG0 Z250\nG0 X400 Y50\nG1 Z40\nG0 Z250\nM2\n"
    result = verify_text(text, m, file="t.ngc")
    assert {(v.line, v.zone) for v in result.violations} >= {(4, "clamp"), (7, "floor")}
    path = collect_path(program_text(text, "t.ngc"), m, {v.block for v in result.violations})
    data = view_data(path, result, m)
    _check_witnesses(result, m, data)
    clamp = [t for t in data["traces"] if t["type"] == "mesh3d" and t["name"].startswith("clamp (")]
    assert len(clamp) == 1 and sorted(set(clamp[0]["z"])) == [100.0, 180.0]
    # the cap is the L itself (ear clipping of a non-convex polygon): its n - 2 = 4 triangles cover
    # 100 x 50 + 40 x 100 = 9,000 mm2
    x, y = clamp[0]["x"], clamp[0]["y"]
    cap = list(zip(clamp[0]["i"], clamp[0]["j"], clamp[0]["k"]))[:4]
    area = sum(abs((x[b] - x[a]) * (y[c] - y[a]) - (x[c] - x[a]) * (y[b] - y[a])) / 2 for a, b, c in cap)
    assert area == pytest.approx(9000.0)
    floor = [t for t in data["traces"] if t["type"] == "mesh3d" and t["name"].startswith("floor (")]
    assert sorted(min(t["z"]) for t in floor) == [120.0, 160.0]  # the tip's Z20 and Z60, plus 100


def test_the_view_starts_around_the_first_violation_and_reaches_the_whole_machine():
    result, m, data = _view("mill")
    assert data["views"][0]["label"] == "Whole machine" and data["start"] == 1
    whole = data["views"][0]["ranges"]
    for z in m.zones:  # the travel box X0-600 Y0-400 Z0-400 is in the whole-machine view
        for a, (lo, hi) in z.bounds().items():
            k = data["axes"].index(a)
            assert all(whole[k][0] <= float(b) <= whole[k][1] for b in (lo, hi) if b is not None)
    for i, v in enumerate(result.violations, 1):
        view = next(w for w in data["views"] if w.get("violation") == i)
        for c, (lo, hi) in zip(data["axes"], view["ranges"]):
            assert lo < float(dict(v.point)[c]) < hi and hi - lo < 100  # zoomed: not the 600 mm travel


def test_hover_and_click_targets_name_the_violating_line():
    result, _, data = _view("mill-drill")
    hot = next(t for t in data["traces"] if t.get("meta") == "hot")
    lines = {data["where"][k][1] for k in hot["customdata"] if k is not None}
    assert lines == {v.line for v in result.violations}


def test_program_text_in_the_view_data_cannot_leave_its_script_element():
    """The view's data (labels hold program text) is JSON in a <script type="application/json">: a comment
    "</script><img src=x onerror=alert[1]>" on a motion line stays data (``<`` written ``\\u003c``)."""
    from nczones.report.html import render_html, without_library

    m = load_machine(MACHINES / "mill.toml")
    text = "G21 G90 G54 F100\nG0 X10 Y10 Z100 (</script><img src=x onerror=alert[1]>)\nM2\n"
    result = verify_text(text, m, file="t.ngc")
    page = without_library(render_html(result, m, program_text(text, "t.ngc")))
    assert "</script><img" not in page and "<img" not in page
    payload = re.search(r'<script type="application/json" id="view3d-data">(.*?)</script>', page, re.S).group(1)
    assert "line 2: G0 X10 Y10 Z100 (</script><img src=x onerror=alert[1]>)" in json.loads(payload)["labels"]


def _long_program(passes: int) -> str:
    """Zig-zag passes of 20 short moves at tip Z-5 (G54 Z100, H1 = 120: machine Z215), then one plunge into the
    vise: program X-30 Y20 Z-10 is tip X120 Y120 Z90, inside the vise X100-140 Y60-180 Z50-130 of mill.toml."""
    out = ["G21 G90 G17 G54", "G0 G43 H1 Z60", "G0 X50 Y0", "G1 Z-5 F1200"]
    for k in range(passes):
        xs = range(60, 260, 10) if k % 2 == 0 else range(240, 40, -10)
        out += [f"X{x} Y{k * 0.5:g}" for x in xs]
    out += ["G0 Z60", "G0 X-30 Y20", "G1 Z-10", "G0 Z60", "M2"]
    return "\n".join(out) + "\n"


def test_a_long_path_is_thinned_never_the_violating_block():
    """300 vectorized-tier passes (6,000 moves): the view draws at most its budget, the violating blocks in
    full: G1 Z-10 from machine Z 280 (60 + G54 Z100 + H1 120) down to 210 (-10 + 220), and the G0 Z60 back up,
    which starts inside the vise."""
    m = load_machine(MACHINES / "mill.toml")
    text = _long_program(300)
    result = verify_text(text, m, file="long.ngc")
    n = text.count("\n")
    assert [v.line for v in result.violations] == [n - 2, n - 1]  # G1 Z-10, G0 Z60
    path = collect_path(program_text(text, "long.ngc"), m, {v.block for v in result.violations})
    data = view_data(path, result, m, max_points=1000)
    assert data["drawn"] <= 1000 < path.segments and data["thinned"] > 0
    hot = {t["name"]: t for t in data["traces"] if t.get("meta") == "hot"}
    assert [c for c in hot["violating block"]["z"] if c is not None] == [280.0, 210.0]
    assert [c for c in hot["violating block (rapid)"]["z"] if c is not None] == [210.0, 280.0]
    assert {data["where"][k][1] for k in hot["violating block"]["customdata"] if k is not None} == {n - 2}


def _random_path(draw_points: np.ndarray, breaks: list[int]) -> PathFloat:
    path = PathFloat(("X", "Y", "Z"))
    rows = np.stack([draw_points[:-1], draw_points[1:]], axis=1)
    for b in sorted(set(breaks)):
        if 0 < b < len(rows):
            rows[b:, :, :] += 1000.0  # a jump: the next rows start a new polyline
    path.feed_lines = [rows]
    path.feed_where = [np.arange(len(rows), dtype=np.int64) + 1]
    path.files = [""]
    return path


@settings(max_examples=40, deadline=None)
@given(n=st.integers(2, 400), seed=st.integers(0, 2**31 - 1), budget=st.integers(4, 300),
       breaks=st.lists(st.integers(1, 399), max_size=5))
def test_thinning_keeps_the_path_within_its_grid_bound(n, seed, budget, breaks):
    """Property: thin_path draws only points of the path; within budget or, when only the ends of polylines
    remain, every k-th polyline; with a grid cell, every point of the path lies within cell * sqrt(3) of a
    drawn point."""
    rng = np.random.default_rng(seed)
    pts = np.cumsum(rng.normal(0, 1, (n, 3)), axis=0)
    path = _random_path(pts, breaks)
    thin = thin_path(path, budget)
    rows = path.feed_lines[0]
    every = rows.reshape(-1, 3)
    total = len(rows) + 1 + int(np.any(rows[1:, 0] != rows[:-1, 1], axis=1).sum())  # points of the polylines
    if thin is path:
        assert total <= budget
        return
    drawn = np.concatenate(thin.feed_curves)
    assert thin.thinned == total - len(drawn)
    for p in drawn:  # drawn points are points of the path
        assert np.min(np.abs(every - p).max(axis=1)) == 0
    if math.isfinite(thin.thin_cell):
        assert len(drawn) <= budget
        d = np.sqrt(((every[:, None, :] - drawn[None, :, :]) ** 2).sum(axis=2)).min(axis=1)
        assert d.max() <= thin.thin_cell * math.sqrt(3) + 1e-9


# -- the page in headless Chromium ---------------------------------------------------------------------------


def _need_browser():
    from tests.tools.browser import find_chromium

    if find_chromium() is None:
        if IN_CI:
            pytest.fail("chromium is missing in CI: .ci/install-chromium.sh installs it for the browser tests")
        pytest.skip("no chromium ($NCZONES_CHROMIUM, chromium on PATH; .ci/install-chromium.sh)")
    if plotly_js() is None:
        if IN_CI:
            pytest.fail("plotly is missing in CI: the test extra installs it")
        pytest.skip("plotly not installed (pip install 'nczones[html]')")


#: the project's own JavaScript: Plotly's scene camera projects a data point to the page (for a real click)
_PROJECT = """(function (x, y, z) {
  var gd = document.getElementById("view3d-plot");
  if (z === null) {
    var xa = gd._fullLayout.xaxis, ya = gd._fullLayout.yaxis, r = gd.getBoundingClientRect();
    return [r.left + xa._offset + xa.l2p(x), r.top + ya._offset + ya.l2p(y)];
  }
  var s = gd._fullLayout.scene._scene, c = s.glplot.cameraParams, d = s.dataScale;
  function mul(m, v) { var o = [0, 0, 0, 0]; for (var i = 0; i < 4; i++) { for (var j = 0; j < 4; j++) {
    o[i] += m[j * 4 + i] * v[j]; } } return o; }
  var q = mul(c.projection, mul(c.view, mul(c.model, [x * d[0], y * d[1], z * d[2], 1])));
  var rect = s.glplot.canvas.getBoundingClientRect();
  return [rect.left + (q[0] / q[3] + 1) / 2 * rect.width, rect.top + (1 - q[1] / q[3]) / 2 * rect.height];
})"""


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    """Every example's report opened in one Chromium: what each page did, and screenshots in SCREENSHOTS."""
    _need_browser()
    from nczones.report.html import render_html
    from tests.tools.browser import Browser

    tmp = tmp_path_factory.mktemp("view")
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    out = {}
    with Browser(width=1200, height=900) as browser:
        for name in ("mill", "grinder", "lathe", "fanuc"):
            result, m, data = _view(name)
            program, _ = EXAMPLES[name]
            report = tmp / f"{name}.html"
            report.write_text(render_html(result, m, str(EX / program)), encoding="utf-8")
            page = browser.open(report.as_uri())
            page.wait_for("document.body.getAttribute('data-view') === 'ready'")
            facts = page.eval("""(function () {
              var gd = document.getElementById("view3d-plot");
              var canvases = [...gd.querySelectorAll("canvas")].map(function (c) {
                var r = c.getBoundingClientRect(); return [r.width, r.height]; });
              return {canvases: canvases, traces: gd.data.length, svg: gd.querySelectorAll("svg.main-svg").length,
                      view: gd.getAttribute("data-view-index"), select: document.getElementById("view3d-select").value,
                      options: document.getElementById("view3d-select").options.length};
            })()""")
            facts["errors"] = page.errors()
            facts["requests"] = page.requests()
            witness = next(t for t in data["traces"] if t.get("meta") == "witness")
            xyz = [witness[c][0] for c in ("x", "y", "z") if c in witness]
            # as a person does: move onto the marker until Plotly shows its hover (its 3-D picking renders
            # in animation frames), then click; on a loaded machine the plot may still settle (a resize
            # redraw), so up to three tries, each projecting the witness afresh
            page.eval("window.nczonesHover = null; document.getElementById('view3d-plot').on('plotly_hover', "
                      "function (e) { window.nczonesHover = e.points[0].data.meta; })")
            facts["hash"] = None
            for _attempt in range(3):
                page.eval("document.getElementById('view3d-plot').scrollIntoView({block: 'center'})")
                page.eval("new Promise(function (ok) { requestAnimationFrame(function () { "
                          "requestAnimationFrame(ok); }); })", await_promise=True)
                at = page.eval(f"{_PROJECT}({xyz[0]}, {xyz[1]}, {xyz[2] if len(xyz) == 3 else 'null'})")
                page.eval("window.nczonesHover = null")
                for k in range(50):
                    page.call("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": at[0] + k % 2, "y": at[1]})
                    if page.eval("window.nczonesHover") == "witness":
                        break
                    time.sleep(0.1)
                facts["hover"], facts["at"] = page.eval("window.nczonesHover"), at
                page.click(*at)
                try:
                    facts["hash"] = page.wait_for("location.hash", timeout=5)
                    break
                except Exception:  # noqa: BLE001 - another try; the test names what failed
                    continue
            facts["line_in_view"] = page.eval(f"""(function () {{ var e = document.getElementById("{(facts['hash'] or '#x')[1:]}");
              if (!e) {{ return false; }} var r = e.getBoundingClientRect(); return r.top >= 0 && r.bottom <= innerHeight; }})()""")
            page.screenshot(str(SCREENSHOTS / f"{name}-view.png"), selector="#view3d")
            page.screenshot(str(SCREENSHOTS / f"{name}-planes.png"), selector="#plots")
            page.eval("document.getElementById('view3d-whole').click()")
            facts["whole"] = page.wait_for("document.getElementById('view3d-plot').getAttribute('data-view-index') === '0'"
                                           " && JSON.stringify(document.getElementById('view3d-plot').layout)")
            facts["data"], facts["result"] = data, result
            out[name] = facts
            page.close()
    return out


@pytest.mark.parametrize("name", ["mill", "grinder", "lathe", "fanuc"])
def test_the_page_loads_and_draws_the_view(pages, name):
    facts = pages[name]
    assert facts["errors"] == []
    assert [u for u in facts["requests"] if not u.startswith(("file:", "data:", "about:", "blob:"))] == []
    assert facts["traces"] == len(facts["data"]["traces"])  # the plot holds every trace of the data
    if len(facts["data"]["axes"]) == 3:
        assert facts["canvases"] and all(w > 100 and h > 100 for w, h in facts["canvases"][:1])
    else:
        assert facts["svg"] >= 1
    assert facts["options"] == len(facts["data"]["views"]) and facts["select"] == "1"
    assert (SCREENSHOTS / f"{name}-view.png").stat().st_size > 5000


@pytest.mark.parametrize("name", ["mill", "grinder", "lathe", "fanuc"])
def test_clicking_the_witness_scrolls_to_its_line(pages, name):
    facts = pages[name]
    line = facts["result"].violations[0].line
    assert facts["hash"] == f"#L{line}" and facts["line_in_view"], (facts["hover"], facts["at"])


def test_the_whole_machine_view(pages):
    layout = json.loads(pages["mill"]["whole"])
    whole = pages["mill"]["data"]["views"][0]["ranges"]
    for c, (lo, hi) in zip("xyz", whole):
        assert layout["scene"][f"{c}axis"]["range"] == pytest.approx([lo, hi])


def test_report_without_plotly_says_the_view_needs_it(monkeypatch):
    from nczones.report import html as html_module

    monkeypatch.setattr(html_module, "plotly_js", lambda: None)
    result, m, _ = _view("mill-drill")
    page = html_module.render_html(result, m, str(EX / EXAMPLES["mill-drill"][0]))
    assert 'id="view3d-missing"' in page and "nczones[html]" in page and "plotly-js" not in page
    assert page.count("<svg") >= 2  # the plane figures stay
    assert not re.search(r'data-view-violation', page)
