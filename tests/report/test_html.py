"""The HTML report: self-contained, escaped, and rendered by headless Chromium with the violation marked."""

import glob
import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser

import pytest

from nczones.gcode.source import program_text
from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.report.html import render_html, without_library
from tests.machines import machine_text

from .helpers import EX, GOLDEN, run_example


def _find_chromium() -> str | None:
    """A headless-capable Chromium: $NCZONES_CHROMIUM or $CHROME_BIN, a browser on PATH, the usual install places."""
    for var in ("NCZONES_CHROMIUM", "CHROME_BIN"):
        if os.environ.get(var) and os.access(os.environ[var], os.X_OK):
            return os.environ[var]
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome"):
        if shutil.which(name):
            return shutil.which(name)
    places = ["/usr/lib/chromium/chromium", "/snap/bin/chromium", "/opt/google/chrome/chrome",
              "/Applications/Google Chrome.app/Contents/MacOS/Google Chrome",
              *sorted(glob.glob(os.path.expanduser("~/.cache/ms-playwright/chromium-*/chrome-linux*/chrome")))]
    return next((p for p in places if os.access(p, os.X_OK)), None)


CHROMIUM = _find_chromium()
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--disable-dev-shm-usage"]
needs_chromium = pytest.mark.skipif(
    CHROMIUM is None, reason="browser tests skipped: no chromium found ($NCZONES_CHROMIUM, $CHROME_BIN, chromium or "
                             "google-chrome on PATH, /usr/lib/chromium, Playwright's cache); .ci/run installs "
                             "Debian's chromium, or set NCZONES_CHROMIUM=/path/to/chrome")


def _chromium(tmp_path, *args, timeout=60):
    profile = tmp_path / "profile"
    profile.mkdir(exist_ok=True)
    return subprocess.run([CHROMIUM, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", *args],
                          capture_output=True, text=True, timeout=timeout)


def _external_resources(page: str) -> list[str]:
    """What nczones's own text would fetch (the embedded plotly.js holds inline data: URLs only; the browser test
    tests/report/test_html_view.py sees that the page requests nothing)."""
    return re.findall(r'(?:src|href)\s*=\s*"(?!#)[^"]*"|url\((?!#)|@import|<link\b', without_library(page))


def test_report_is_self_contained_and_complete():
    result, m = run_example("programs/several.ngc", "grinder.toml", base=GOLDEN)
    page = without_library(render_html(result, m, str(GOLDEN / "programs/several.ngc")))
    assert page.startswith("<!DOCTYPE html>") and _external_resources(page) == []
    assert page.count('<tr class="violation"') == 4
    for line in (5, 6, 8, 9):
        assert f'<a href="#L{line}">' in page and re.search(rf'class="line hot" id="L{line}"', page)
    assert 'class="line" id="L4"' in page
    # the whole plane and the same plane around the violations (ids of the second prefixed: unique in the page)
    assert page.count("<svg") == 2 and page.count('id="counterexample"') == 1 and 'id="violating-block-1"' in page
    assert "z3 " + result.solver_version in page and "Timings" in page
    # user text is escaped: the program's comment holds "& back <out>"
    assert "&amp; back &lt;out&gt;" in page and "<out>" not in page


def test_user_text_is_escaped_everywhere():
    m = parse_machine(machine_text("html_escape"), "evil<1>.toml")
    prog = "(<img src=x onerror=alert[2]>)\nG1 X20 F100\n"
    result = verify_text(prog, m, file="<b>evil</b>.ngc")
    page = without_library(render_html(result, m, program_text(prog, "<b>evil</b>.ngc")))
    assert "<script>alert" not in page and "<img" not in page and "<b>evil" not in page
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in page and "&lt;img src=x onerror=alert[2]&gt;" in page
    assert "a&lt;b&gt;&amp;&quot;zone&quot;" in page
    assert _external_resources(page) == []


def test_mill_report_plots_the_planes_the_zones_use():
    result, m = run_example("programs/drill_vise.ngc", "mill.toml")
    page = without_library(render_html(result, m, str(EX / "programs/drill_vise.ngc")))
    assert re.findall(r'<figure class="plot" data-plane="(\w+)"', page) == ["XY", "XZ"]
    assert page.count('id="counterexample"') == 2  # marked in both planes (the zoomed figures' ids are prefixed)


def test_unknown_report_lists_the_reason():
    result, m = run_example("programs/cutter_comp.ngc", "mill.toml")
    page = without_library(render_html(result, m, str(EX / "programs/cutter_comp.ngc")))
    assert 'id="reason-table"' in page and 'class="line unknown" id="L4"' in page and "verdict-unknown" in page


def test_long_program_listing_is_windowed():
    m_result, m = run_example("programs/notch_dip.ngc", "grinder.toml")
    text = "G21 G90 G54\nG0 X-250 Y300\nG1 Y130 F500\n" + "G1 X-240\n" * 3000 + "G1 X50\n"
    result = verify_text(text, m, file="long.ngc")
    page = without_library(render_html(result, m, program_text(text, "long.ngc"), listing_limit=500, context=3))
    assert 'id="L3004"' in page and 'class="line hot" id="L3004"' in page and 'id="L1500"' not in page
    assert "not shown" in page


class _DomProbe(HTMLParser):
    """Collects what the browser rendered: elements with ids, classes and the text of #violation-count."""

    def __init__(self):
        super().__init__()
        self.ids, self.rows, self.hot, self.svg_in_figure, self.body_attrs = {}, 0, [], 0, {}
        self._stack, self._count_text, self._in_count = [], "", False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self._stack.append(tag)
        if "id" in a:
            self.ids[a["id"]] = (tag, a)
        if tag == "body":
            self.body_attrs = a
        if tag == "tr" and a.get("class") == "violation":
            self.rows += 1
        if tag == "span" and "hot" in (a.get("class") or "").split():
            self.hot.append(a.get("id"))
        if tag == "svg" and "figure" in self._stack:
            self.svg_in_figure += 1
        self._in_count = a.get("id") == "violation-count"

    def handle_endtag(self, tag):
        while self._stack and self._stack.pop() != tag:
            pass
        self._in_count = False

    def handle_data(self, data):
        if self._in_count:
            self._count_text += data


@needs_chromium
def test_chromium_renders_the_report_with_the_violation_marked(tmp_path):
    result, m = run_example("programs/notch_dip.ngc", "grinder.toml")
    page = render_html(result, m, str(EX / "programs/notch_dip.ngc"))
    # the script fills #violation-count from the table; the browser, not Python, writes this text
    page = page.replace('<span id="violation-count">1</span>', '<span id="violation-count">?</span>')
    html_file = tmp_path / "report.html"
    html_file.write_text(page, encoding="utf-8")
    r = _chromium(tmp_path, "--dump-dom", html_file.as_uri())
    assert r.returncode == 0, r.stderr[-2000:]
    probe = _DomProbe()
    probe.feed(r.stdout)
    assert probe.body_attrs.get("data-rendered") == "yes"  # the inline script ran
    assert probe._count_text == "1"
    assert probe.svg_in_figure == 2  # the whole plane and the zoom around the violation
    tag, attrs = probe.ids["counterexample"]
    assert tag == "g"  # matplotlib's group holding the marker paths
    assert "violating-block-1" in probe.ids and "allowed-set" in probe.ids
    assert probe.rows == 1 and probe.hot == ["L5"]
    assert probe.ids["verdict"][1].get("class") == "verdict verdict-unsafe"
    # the counterexample group really contains drawn marker geometry
    seg = r.stdout[r.stdout.index('id="counterexample"'):]
    assert re.search(r"<(path|use)\b", seg[:3000])


@needs_chromium
def test_chromium_screenshot_shows_red_marks(tmp_path):
    import matplotlib.image as mpimg

    result, m = run_example("programs/notch_dip.ngc", "grinder.toml")
    html_file = tmp_path / "report.html"
    html_file.write_text(render_html(result, m, str(EX / "programs/notch_dip.ngc")), encoding="utf-8")
    shot = tmp_path / "shot.png"
    r = _chromium(tmp_path, f"--screenshot={shot}", "--window-size=1200,1600", html_file.as_uri())
    assert r.returncode == 0 and shot.exists(), r.stderr[-2000:]
    img = mpimg.imread(shot)[..., :3]
    red = (img[..., 0] > 0.6) & (img[..., 1] < 0.2) & (img[..., 2] < 0.2)  # the violation red #c00000
    assert red.sum() > 200, "no violation marking visible in the rendered report"


def test_cli_html(tmp_path):
    out = tmp_path / "r.html"
    r = subprocess.run([sys.executable, "-m", "nczones", "verify", "programs/notch_dip.ngc", "--machine",
                        "../machines/grinder.toml", "--format", "html", "--output", str(out)],
                       capture_output=True, text=True, cwd=EX)
    assert r.returncode == 1, r.stderr
    page = out.read_text(encoding="utf-8")
    assert 'id="counterexample"' in page and '<tr class="violation"' in page


def test_zoomed_figure_around_the_violation_ids_unique():
    """Issue 37: the helix of helix_into_vise_corner is a few pixels of the 600 x 400 travel; the report adds each
    plane around the violations, drawing only what that view shows, and every id in the page stays unique."""
    result, m = run_example("programs/helix_into_vise_corner.ngc", "mill.toml")
    page = without_library(render_html(result, m, str(EX / "programs/helix_into_vise_corner.ngc"), deterministic=True))
    # the zoomed figures add no id of the whole-plane figures (their own are prefixed f<k>z-)
    assert page.count('id="counterexample"') == 2 and page.count('id="allowed-set"') == 2
    zoom_ids = [i for i in re.findall(r'\bid="([^"]+)"', page) if re.match(r"f\dz-", i)]
    assert zoom_ids and len(zoom_ids) == len(set(zoom_ids))
    zooms = re.findall(r'<figure class="plot zoom" data-plane="(\w+)">', page)
    assert zooms == ["XY", "XZ"]
    assert "f0z-counterexample" in page and "around the violations" in page
