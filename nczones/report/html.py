"""A self-contained HTML report of a verification (``nczones verify --format html``).

One file, no network resources: inline CSS, a few lines of inline script,
and the plots as inline SVG (matplotlib).  Sections:

* ``#summary``: verdict, program, machine, margin, parameter ranges, solver
  and version, engine, nczones version, counters and timings;
* ``#view3d``: the interactive view (Plotly's bundled JavaScript, embedded once when the ``plotly`` package
  of the ``html`` extra is installed; else a note that it needs it): 3-D for a machine with X, Y and Z,
  else the first relevant plane (:mod:`nczones.report.interactive`); zones as translucent solids where the
  proof puts them, toolpath with rapids dashed, violations marked; hover shows line and block text, a
  click on a point scrolls the listing to its line; the view starts around the first violation, a
  selector gives each violation's view and the whole machine;
* ``#plots``: one figure per relevant axis plane (the allowed set, the
  toolpath with rapids dashed, violating blocks red, counterexample points
  marked: SVG group ``counterexample``);
* ``#violations``: a table (rows ``tr.violation``) whose line numbers link to
  ``#L<line>`` in the listing; ``#reasons`` for ``unknown``;
* ``#listing``: the program with the flagged lines highlighted
  (``.line.hot`` violations, ``.line.unknown`` reasons).  A long program
  shows only windows around the flagged lines.

A long program's path is thinned for drawing (:func:`~nczones.report.figure.thin_path`; never a
violating block), so the page stays small and opens fast (bench/bench_html.py).

Every piece of user text (program lines, file, zone and machine names,
messages) is escaped.
"""

from __future__ import annotations

import html
import io
import re
from collections.abc import Iterable
from fractions import Fraction
from typing import Any

from .. import __version__
from ..errors import program_lines
from ..exact import format_decimal
from ..prover.result import Result
from . import numbers
from .interactive import plotly_js

__all__ = ["render_html", "PLANE_POINTS"]

#: points of the thinned feeds and rapids drawn in each plane figure (SVG)
PLANE_POINTS = 8_000

_CSS = """
body{font-family:system-ui,-apple-system,"Segoe UI",sans-serif;margin:1.5em auto;max-width:1100px;color:#222;padding:0 1em}
h1{font-size:1.4em;margin-bottom:.2em}h2{font-size:1.15em;border-bottom:1px solid #ddd;padding-bottom:.2em;margin-top:1.6em}
.verdict{display:inline-block;padding:.15em .6em;border-radius:.3em;font-weight:bold;color:#fff;letter-spacing:.05em}
.verdict-safe{background:#2e7d32}.verdict-unsafe{background:#c00000}.verdict-unknown{background:#b26a00}
table{border-collapse:collapse;font-size:.9em}td,th{border:1px solid #ddd;padding:.25em .55em;text-align:left;vertical-align:top}
th{background:#f4f4f4}table.kv th{width:14em}
code,pre{font-family:ui-monospace,"DejaVu Sans Mono",Menlo,Consolas,monospace}
figure{margin:1em 0}figure svg{max-width:100%;height:auto}figcaption{font-size:.85em;color:#555}
pre.listing{background:#fafafa;border:1px solid #ddd;padding:.4em 0;overflow-x:auto;font-size:.85em;line-height:1.35}
.line{display:block;padding:0 .6em;white-space:pre}.line .ln{display:inline-block;width:5em;color:#999;text-decoration:none;user-select:none}
.line.hot{background:#ffd7d7}.line.hot .ln{color:#c00000;font-weight:bold}.line.unknown{background:#ffefc7}
.line:target{outline:2px solid #1f4e9c}.gap{display:block;color:#999;padding:0 .6em}
tr.violation td:first-child a,tr.reason td:first-child a{font-weight:bold}
.muted{color:#666;font-size:.85em}
#view3d-plot{width:100%;height:620px;border:1px solid #ddd}.view-controls{margin:.4em 0}.view-controls select{max-width:40em}
@media print{#view3d,.view-link{display:none}}
"""

# plotly.js is embedded as text and run after the page's load event: the summary, tables, figures and
# listing show at once, the interactive view follows (body data-view="ready" when drawn)
_VIEW_SCRIPT = """
function nczonesView() {
  if (!window.Plotly) {
    var lib = document.createElement("script");
    lib.textContent = document.getElementById("plotly-js").textContent;
    document.head.appendChild(lib);
  }
  var D = JSON.parse(document.getElementById("view3d-data").textContent);
  var gd = document.getElementById("view3d-plot"), status = document.getElementById("view3d-status");
  var select = document.getElementById("view3d-select");
  if (!window.Plotly || !gd) { return; }
  var keys = ["x", "y", "z"];
  function esc(text) {  // Plotly reads a few HTML tags in hover text: program text is shown as written
    return text.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
  }
  D.traces.forEach(function (t) {
    if (t.customdata && t.meta) {
      t.hovertext = t.customdata.map(function (k) { return k === null ? "" : esc(D.labels[k]); });
      t.hovertemplate = "%{hovertext}<extra>" + t.name + "</extra>";
    }
  });
  function update(k) {
    var v = D.views[k], u = {};
    if (D.axes.length === 3) {
      var span = v.ranges.map(function (r) { return r[1] - r[0]; }), m = Math.max.apply(null, span);
      v.ranges.forEach(function (r, i) { u["scene." + keys[i] + "axis.range"] = r; });
      u["scene.aspectratio"] = {x: Math.max(span[0] / m, 0.1), y: Math.max(span[1] / m, 0.1),
                                z: Math.max(span[2] / m, 0.1)};
    } else {
      u["xaxis.range"] = v.ranges[0]; u["yaxis.range"] = v.ranges[1];
    }
    return u;
  }
  function show(k) {
    select.value = String(k);
    gd.setAttribute("data-view-index", String(k));
    return Plotly.relayout(gd, update(k));
  }
  D.views.forEach(function (v, k) {
    var o = document.createElement("option"); o.value = String(k); o.textContent = v.label; select.appendChild(o);
  });
  select.addEventListener("change", function () { show(Number(select.value)); });
  document.getElementById("view3d-whole").addEventListener("click", function () { show(0); });
  document.querySelectorAll("[data-view-violation]").forEach(function (a) {
    a.addEventListener("click", function (ev) {
      var i = Number(a.getAttribute("data-view-violation"));
      for (var k = 0; k < D.views.length; k++) {
        if (D.views[k].violation === i) { ev.preventDefault(); show(k); gd.scrollIntoView({block: "center"}); }
      }
    });
  });
  // the first view goes into the layout: one drawing (WebGL at the page's pixel ratio: software GL is slow)
  var first = update(D.start);
  Object.keys(first).forEach(function (key) {
    var path = key.split("."), o = D.layout;
    for (var i = 0; i < path.length - 1; i++) { o = o[path[i]] = o[path[i]] || {}; }
    o[path[path.length - 1]] = first[key];
  });
  select.value = String(D.start);
  gd.setAttribute("data-view-index", String(D.start));
  // a translucent zone solid must not hide the witness inside it from a click: the zones' faces leave
  // Plotly's 3-D picking (they still show; their hover is their name, from the edges)
  function unpickZones() {
    try {
      var scene = gd._fullLayout.scene._scene, traces = scene.traces, changed = false;
      Object.keys(traces).forEach(function (k) {
        var t = traces[k];
        if (t.mesh && t.data.type === "mesh3d" && !t.mesh.nczonesUnpicked) {
          t.mesh.drawPick = function () {}; t.mesh.nczonesUnpicked = true; changed = true;
        }
      });
      if (changed) { scene.glplot.update({}); }  // redraw the pick buffer without them
    } catch (e) { /* a 2-D view, or another Plotly: zones stay pickable */ }
  }
  Plotly.newPlot(gd, D.traces, D.layout, {displaylogo: false, responsive: true, plotGlPixelRatio: 1}).then(function () {
    if (D.axes.length === 3) { unpickZones(); gd.on("plotly_afterplot", unpickZones); }
    gd.setAttribute("data-traces", String(gd.data.length));
    document.body.setAttribute("data-view", "ready");
  });
  gd.on("plotly_click", function (ev) {
    var p = ev && ev.points && ev.points[0];
    if (!p || p.customdata === undefined || p.customdata === null) { return; }
    var a = D.anchors[p.customdata], el = a && document.getElementById(a);
    if (el) {
      location.hash = a; el.scrollIntoView({block: "center"});
      status.textContent = "Went to " + D.labels[p.customdata];
    } else {
      status.textContent = D.labels[p.customdata] + " (not in the listing: a long program shows the flagged lines)";
    }
  });
}
if (document.readyState === "complete") { setTimeout(nczonesView, 0); }
else { window.addEventListener("load", function () { setTimeout(nczonesView, 0); }); }
"""

_SCRIPT = """
document.addEventListener("DOMContentLoaded", function () {
  var rows = document.querySelectorAll("#violation-table tr.violation").length;
  var el = document.getElementById("violation-count");
  if (el) { el.textContent = String(rows); }
  document.body.setAttribute("data-rendered", "yes");
});
"""


def _e(text: object) -> str:
    return html.escape(str(text), quote=True)


def _d(x: Fraction) -> str:
    return format_decimal(x, 12)



def _svg(fig: Any, salt: str) -> str:
    """The figure as an inline <svg> element (no XML prolog, deterministic ids)."""
    import matplotlib

    buf = io.StringIO()
    with matplotlib.rc_context({"svg.hashsalt": salt, "svg.fonttype": "path"}):
        fig.savefig(buf, format="svg", metadata={"Date": None, "Creator": None})
    text = buf.getvalue()
    start = text.find("<svg")
    text = text[start:] if start >= 0 else text
    return re.sub(r"<metadata>.*?</metadata>\s*", "", text, flags=re.S)


def _listing(lines: list[str], hot: dict[int, str], unknown: set[int], context: int, full_limit: int) -> str:
    flagged = set(hot) | unknown
    if len(lines) <= full_limit:
        shown: Iterable[int] = range(1, len(lines) + 1)
    else:
        keep: set[int] = set()
        for n in flagged:
            keep.update(range(max(1, n - context), min(len(lines), n + context) + 1))
        keep.update(range(1, min(len(lines), context) + 1))
        shown = sorted(keep)
    out = []
    prev = 0
    for n in shown:
        if n != prev + 1:
            out.append(f'<span class="gap">… lines {prev + 1}–{n - 1} not shown …</span>')
        cls = "line" + (" hot" if n in hot else "") + (" unknown" if n in unknown and n not in hot else "")
        title = f' title="{_e(hot[n])}"' if n in hot else ""
        out.append(f'<span class="{cls}" id="L{n}"{title}><a class="ln" href="#L{n}">{n}</a>'
                   f'{_e(lines[n - 1].rstrip(chr(13)))}</span>')
        prev = n
    if shown and prev < len(lines):
        out.append(f'<span class="gap">… lines {prev + 1}–{len(lines)} not shown …</span>')
    return "".join(out)


def without_library(page: str) -> str:
    """``page`` without its embedded plotly.js (to look at what nczones itself wrote)."""
    return re.sub(r'<script type="text/plain" id="plotly-js">.*?</script>', "", page, flags=re.S)


def _view_section(path: Any, result: Result, machine: Any, library: str | None, name: str, program: Any,
                  lines: list[str], others: dict[str, Any]) -> str:
    """The ``#view3d`` section: the interactive view's element, its data and its controls, or the note
    that it needs the plotly package."""
    import json

    from .interactive import view_data

    head = '<section id="view3d"><h2>Interactive view</h2>'
    if library is None:
        return (head + '<p class="muted" id="view3d-missing">The interactive 3-D view needs the plotly package: '
                "<code>pip install 'nczones[html]'</code>. The plane views below show the same toolpath, "
                "zones and violations.</p></section>")
    data = view_data(path, result, machine)
    main = {name, getattr(program, "name", None), ""}
    labels: list[str] = []
    anchors: list[str | None] = []
    for file, ln in data.pop("where"):
        if ln is None:
            labels.append(file or "—")
            anchors.append(None)
        elif file in main or file not in others:
            text = lines[ln - 1].strip() if file in main and 0 < ln <= len(lines) else ""
            labels.append(f"line {ln}: {text[:120]}" if file in main else f"{file}:{ln}")
            anchors.append(f"L{ln}" if file in main else None)
        else:
            k = list(others).index(file) + 1
            labels.append(f"{file}:{ln}")
            anchors.append(f"F{k}L{ln}")
    data["labels"], data["anchors"] = labels, anchors
    payload = json.dumps(data, separators=(",", ":"), allow_nan=False).replace("<", "\\u003c")
    axes = "".join(data["axes"])
    kind = "3-D" if len(data["axes"]) == 3 else f"{axes} plane"
    thinned = (f" The toolpath is thinned for drawing: {data['drawn']} points drawn, {data['thinned']} left out "
               "(the violating blocks in full)." if data["thinned"] else "")
    return (head + f'<div class="view-controls">View: <select id="view3d-select"></select> '
            '<button type="button" id="view3d-whole">Whole machine</button></div>'
            f'<div id="view3d-plot" data-axes="{_e(axes)}"></div>'
            f'<p class="muted" id="view3d-status">{_e(kind)} view, machine coordinates: zones where the proof '
            "puts them (forbidden red, allowed green), feeds solid, rapids dashed, violating blocks red, "
            f"counterexample {'◆' if len(data['axes']) == 3 else '✕'}, first exit ○. Drag to rotate or pan, scroll to zoom; hover for the line, click "
            f"a point to go to its line in the listing.{_e(thinned)}</p>"
            f'<script type="application/json" id="view3d-data">{payload}</script></section>')


def render_html(result: Result, machine: Any, program: Any = None, *, planes: Any = None,
                source_text: str | None = None,
                deterministic: bool = False, listing_limit: int = 5000, context: int = 15,
                interactive: bool = True) -> str:
    r"""The self-contained HTML report.

    Parameters
    ----------
    result : Result
    machine : Machine
    program : str, path or ProgramSource, optional
        The program file to draw (a ``str`` is a path; pass
        :func:`~nczones.gcode.source.program_text` for text); default ``result.file``.
    planes : list of (str, str), optional
        Axis planes to plot (default :func:`~nczones.report.figure.relevant_planes`).
    source_text : str, optional
        The program text for the listing (default: read ``program``).
    deterministic : bool
        Leave out timings and the solver version.
    interactive : bool
        Add the interactive view (``#view3d``; needs the ``plotly`` package, else the page says so).

    Examples
    --------
    >>> from nczones import load_machine
    >>> from nczones.prover import verify
    >>> m = load_machine("specs/machines/grinder.toml")
    >>> r = verify("specs/examples/programs/notch_dip.ngc", m)
    >>> page = render_html(r, m)
    >>> page.startswith("<!DOCTYPE html>"), 'id="counterexample"' in page, '<tr class="violation"' in page
    (True, True, True)
    >>> import re  # nothing fetched (plotly.js, embedded, holds inline data: URLs only)
    >>> re.findall(r'(?:src|href)="(?!#)[^"]*"|url\((?!#)|@import', without_library(page))
    []
    """
    import matplotlib.pyplot as plt

    from ..errors import InputError
    from ..gcode.source import as_source
    from .figure import (
        collect_path,
        hot_passes,
        path_within,
        plot_program,
        relevant_planes,
        thin_path,
        violation_view,
    )

    program = program if program is not None else result.file
    if program:
        try:
            program = as_source(program)
        except InputError:  # the report still renders, without a listing and plots
            program = None
    text = source_text
    if text is None and program is not None:
        text = program.text
    lines = program_lines(text or "")
    verdict = result.verdict.label
    name = result.file or (program.name if program is not None else "<program>")

    # plots
    figures = []
    path = None
    if program:
        hot_blocks = {v.block for v in result.violations}
        path = collect_path(program, machine, hot_blocks, passes=hot_passes(result.violations),
                            library=dict(result.settings).get("library"))
        plane_path = thin_path(path, PLANE_POINTS)
        for k, plane in enumerate(planes or relevant_planes(machine, result)):
            fig = plot_program(program, machine, plane, result, path=plane_path)
            fig.set_size_inches(9, 5.2)
            svg = _svg(fig, f"nczones-{k}")
            # matplotlib ids are unique within one SVG; prefix them per figure
            svg = re.sub(r'(id="|url\(#|href="#)([A-Za-z_][\w.-]*)', lambda m: f"{m.group(1)}f{k}-{m.group(2)}"  # noqa: B023 - called within this iteration
                         if not m.group(2).startswith(("counterexample", "first-exit", "violating-block",
                                                       "toolpath", "allowed-set", "forbid-")) else m.group(0), svg)
            plt.close(fig)
            figures.append((plane, svg, False))
            # the same plane around the violations (a violation is often a few pixels of the whole machine);
            # only what that view shows is drawn, its ids prefixed so the page's ids stay unique
            view = violation_view(path, result, plane, machine) if result.violations else None
            if view is not None:
                near = path_within(plane_path, plane, machine, view)
                fig = plot_program(program, machine, plane, result, path=near, zoom=True,
                                   title=f"{machine.name}: {plane[0]}{plane[1]} plane, around the violations")
                fig.set_size_inches(9, 5.2)
                svg = _svg(fig, f"nczones-{k}z")
                svg = re.sub(r'(id="|url\(#|href="#)([A-Za-z_][\w.-]*)',
                             lambda m: f"{m.group(1)}f{k}z-{m.group(2)}", svg)  # noqa: B023 - called within this iteration
                plt.close(fig)
                figures.append((plane, svg, True))

    # summary
    stats = dict(result.stats)
    rows = [
        ("Verdict", f'<span class="verdict verdict-{_e(verdict)}" id="verdict">{_e(verdict.upper())}</span>'),
        ("Program", f"<code>{_e(name)}</code> ({len(lines)} lines)"),
        ("Machine", f"{_e(machine.name)} — <code>{_e(machine.source)}</code>; axes "
                    f"{_e(', '.join(machine.axis_names))}; rapid mode {_e(machine.rapid_mode.value)}"),
        ("Zones", _e("; ".join(f"{z.name} ({'forbid' if z.forbid else 'allow'} {z.kind}"
                               f"{', tool tip' if z.point.value == 'tip' else ''})" for z in machine.zones))),
        ("Margin", f"{_e(format_decimal(result.margin))} mm"),
        ("Parameter ranges", _e(", ".join(f"{p.name} = {format_decimal(p.written[0])} .. "
                                          f"{format_decimal(p.written[1])}" for p in result.params) or "none")),
        ("Violating blocks", f'<span id="violation-count">{len(result.violations)}</span>'
                             + (" (list truncated)" if result.truncated else "")),
        ("Dialect", _e(result.dialect)),
        ("Solver", _e(result.solver + ("" if deterministic else f" {result.solver_version}"))
                   + f"; engine {_e(result.engine)}"),
        ("nczones", _e(__version__)),
        ("Checked", _e(numbers.checked_in_words(stats))),
    ]
    if not deterministic and result.timings:
        rows.append(("Timings", _e(", ".join(f"{k.removesuffix('_s')} {t:.3f} s" for k, t in result.timings))))
    if result.notes:
        rows.append(("Notes", "<br>".join(_e(n) for n in result.notes)))
    summary = "".join(f"<tr><th>{k}</th><td>{v}</td></tr>" for k, v in rows)

    # violations table; a line of another file (a subroutine file of a call) links to that file's listing
    res = numbers.resolution_of(machine)
    hot: dict[int, str] = {}
    others: dict[str, tuple[dict[int, str], set[int]]] = {}  # file -> (its hot lines, its unknown lines)

    def other(span: Any) -> tuple[dict[int, str], set[int]] | None:
        file = getattr(span, "file", None)
        if span is None or not file or file == name or (program is not None and file == program.name):
            return None
        return others.setdefault(file, ({}, set()))

    def anchor(span: Any, ln: int) -> str:
        if other(span) is None:
            return f'<a href="#L{ln}">{ln}:{span.column}</a>'
        k = list(others).index(span.file) + 1
        return f'<a href="#F{k}L{ln}">{_e(span.file)}:{ln}:{span.column}</a>'

    library = plotly_js() if interactive and path is not None else None
    vrows = []
    for i, v in enumerate(result.violations, 1):
        ln = v.line
        if ln is not None:
            elsewhere = other(v.span)
            (hot if elsewhere is None else elsewhere[0]).setdefault(ln, f"violation[{v.zone}]")
        link = anchor(v.span, ln) if ln is not None and v.span else "—"
        if library is not None:
            link += (f' <a class="view-link" href="#view3d" data-view-violation="{i}" '
                     'title="show it in the interactive view">view</a>')
        depth = ("≥ " if not v.depth_exact else "") + numbers.depth(v.depth, v.depth_exact, numbers.depth_step(res))
        params = ", ".join([f"{n}={_d(x)}" for n, x in v.params] + [f"{s.replace('_', '-')} {p}" for s, p in v.switches])
        in_program = numbers.program_point(v, res)
        program_cell = "" if in_program is None else \
            f'<br><span class="point-program" data-point-program="1">{_e(in_program)}</span>'
        vrows.append(
            f'<tr class="violation" id="v{i}"><td>{link}</td><td><code>{_e(v.source)}</code></td>'
            f"<td>{_e(v.zone)}</td><td>{_e(v.kind)}: {_e(v.segment_kind)}"
            f"{(' (' + _e(v.derived) + ')') if v.derived else ''}</td>"
            f"<td><code>{_e(numbers.point(v.point, res))}</code> (machine){program_cell}</td><td>{_e(depth)} mm</td>"
            f"<td><code>{_e(numbers.point(v.first_exit, res))}</code></td><td>{_e(params) or '—'}</td>"
            f"<td>{_e(v.engine)}</td></tr>")
    unknown_lines: set[int] = set()
    rrows = []
    for i, r in enumerate(result.reasons, 1):
        ln = r.span.line if r.span is not None else None
        if ln is not None:
            elsewhere = other(r.span)
            (unknown_lines if elsewhere is None else elsewhere[1]).add(ln)
        link = anchor(r.span, ln) if r.span is not None and ln is not None else "—"
        rrows.append(f'<tr class="reason" id="r{i}"><td>{link}</td><td>{_e(r.code) or "—"}</td>'
                     f"<td>{_e(r.message)}</td></tr>")

    view_section = ""
    if interactive and path is not None:
        view_section = _view_section(path, result, machine, library, name, program, lines, others)

    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>nczones: {_e(name)} — {_e(verdict)}</title>",
        f"<style>{_CSS}</style></head>",
        f'<body data-verdict="{_e(verdict)}">',
        f"<h1>nczones verification report: <code>{_e(name)}</code></h1>",
        '<section id="summary"><h2>Summary</h2>',
        f'<table class="kv">{summary}</table></section>',
    ]
    if view_section:
        parts.append(view_section)
    if figures:
        parts.append('<section id="plots"><h2>Toolpath and allowed set</h2>')
        for plane, svg, zoomed in figures:
            if zoomed:
                parts.append(f'<figure class="plot zoom" data-plane="{_e(plane[0])}{_e(plane[1])}">{svg}'
                             f"<figcaption>{_e(plane[0])}{_e(plane[1])} plane around the violations (the figure "
                             "above shows the whole machine).</figcaption></figure>")
                continue
            parts.append(f'<figure class="plot" data-plane="{_e(plane[0])}{_e(plane[1])}">{svg}'
                         f"<figcaption>{_e(plane[0])}{_e(plane[1])} plane: allowed set green, forbidden "
                         "zones hatched red, feeds solid, rapids dashed, violating blocks red, "
                         "counterexample points ✕ and first exits ○ (machine coordinates)."
                         "</figcaption></figure>")
        parts.append("</section>")
    parts.append('<section id="violations"><h2>Violations</h2>')
    if vrows:
        parts.append('<table id="violation-table"><thead><tr><th>Line</th><th>Block</th><th>Zone</th>'
                     "<th>Kind</th><th>Point outside</th><th>Depth</th><th>First exit</th><th>Parameters</th>"
                     f"<th>Engine</th></tr></thead><tbody>{''.join(vrows)}</tbody></table>")
    else:
        parts.append('<p id="no-violations">No violating block.</p>')
    parts.append("</section>")
    if rrows:
        parts.append('<section id="reasons"><h2>Not proved (unknown)</h2><table id="reason-table"><thead><tr>'
                     f"<th>Line</th><th>Code</th><th>Reason</th></tr></thead><tbody>{''.join(rrows)}"
                     "</tbody></table></section>")
    if lines:
        parts.append('<section id="listing"><h2>Program</h2><pre class="listing">'
                     f"{_listing(lines, hot, unknown_lines, context, listing_limit)}</pre></section>")
    for k, (file, (file_hot, file_unknown)) in enumerate(others.items(), 1):
        try:  # a subroutine file the run read (LinuxCNC SUBROUTINE_PATH, Fanuc library): its own listing
            with open(file, "rb") as fh:
                other_lines = program_lines(fh.read().decode("utf-8", errors="replace"))
        except OSError:
            continue
        listing = _listing(other_lines, file_hot, file_unknown, context, listing_limit)
        parts.append(f'<section class="listing-file" id="file-{k}"><h2>Called file <code>{_e(file)}</code></h2>'
                     '<pre class="listing">' + listing.replace(' id="L', f' id="F{k}L').replace('href="#L', f'href="#F{k}L')
                     + "</pre></section>")
    from ..prover.assumptions import SAFE_ASSUMPTIONS

    parts.append('<section id="assumptions"><h2>What <code>safe</code> assumes</h2><ul>'
                 + "".join(f"<li>{_e(a)}</li>" for a in SAFE_ASSUMPTIONS)
                 + "</ul><p class=\"muted\">This run's own settings (margin, parameter ranges, block-delete "
                   "positions) are in the summary and its notes above.</p></section>")
    parts.append(f'<p class="muted">Generated by nczones {_e(__version__)}.</p>')
    parts.append(f"<script>{_SCRIPT}</script>")
    if library is not None and view_section:
        parts.append(f'<script type="text/plain" id="plotly-js">{library}</script>')
        parts.append(f"<script>{_VIEW_SCRIPT}</script>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
