"""The HTML report of a long program: its size and how fast headless Chromium opens it (issue 37).

    python bench/bench_html.py [--lines 100000] [--repeat 3] [--keep report.html]

Generates a program of ``--lines`` lines for specs/machines/mill.toml (zig-zag passes of short moves with a
half-circle arc at each end, rapids between layers, one plunge into the vise: unsafe, two violations),
verifies it, builds its HTML report (the interactive view and the plane figures, paths thinned) and opens it
in headless Chromium ``--repeat`` times, each in a fresh browser.  Prints the report's size, the time to the
page's load event (summary, tables, plane figures and listing shown), the time until the interactive view is
drawn (``data-view="ready"``), and the CPU seconds of all Chromium processes for that (from /proc; the
browser start not counted).  Targets (issue 37): < 10 MB, open in < 5 s.  Results: specs/performance.md.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from _bench import ROOT, machine_description  # noqa: E402

from nczones import load_machine  # noqa: E402
from nczones.gcode.source import program_text  # noqa: E402
from nczones.prover import verify_text  # noqa: E402
from nczones.report.html import render_html  # noqa: E402
from tests.tools.browser import Browser, find_chromium  # noqa: E402


def long_program(lines: int) -> str:
    """About ``lines`` lines: passes of 35 moves of 10 mm along X at Z-5 (tip), 0.5 mm apart in Y, joined by
    G2/G3 half circles of radius 0.25; every 50 passes a rapid back to the start; after pass 1000 one
    plunge into the vise (program X-30 Y20 Z-10 with G54 X150 Y100 Z100 and H1 = 120: tip X120 Y120 Z90,
    inside the vise X100-140 Y60-180 Z50-130)."""
    out = ["(bench_html: a long zig-zag pocket with arcs, one plunge into the vise)", "G21 G90 G17 G54",
           "G0 G43 H1 Z60", "G0 X50 Y0", "G1 Z-5 F1200"]
    k = 0
    while len(out) < lines - 2:
        y = (k % 500) * 0.5
        x0, x1, step = (50, 400, 10) if k % 2 == 0 else (400, 50, -10)
        out += [f"X{x} Y{y:g}" for x in range(x0 + step, x1 + step, step)]
        out.append(f"{'G3' if k % 2 == 0 else 'G2'} X{x1} Y{y + 0.5:g} R0.25")
        out.append("G1")
        if k == 1000:
            out += ["G0 Z60", "G0 X-30 Y20", "G1 Z-10", "G0 Z60", "G0 X50 Y0", "G1 Z-5"]
        if k % 50 == 49:
            out += ["G0 Z10", "G0 X50 Y0", "G1 Z-5"]
        k += 1
    return "\n".join(out[:lines - 2]) + "\nG0 Z60\nM30\n"


def open_once(report: Path) -> tuple[float, float, float, list[str]]:
    """(seconds to the load event, seconds until the view is drawn, Chromium CPU seconds, console errors)."""
    with Browser() as browser:
        browser.open("about:blank")
        cpu0 = browser.cpu_seconds()
        page = browser.open(report.as_uri(), timeout=120)
        deadline = time.monotonic() + 120
        while page.eval("document.body.getAttribute('data-view')") != "ready":
            if time.monotonic() > deadline:
                raise RuntimeError("the interactive view was not drawn within 120 s")
            time.sleep(0.02)
        ready = time.monotonic() - page.started
        return page.loaded - page.started, ready, browser.cpu_seconds() - cpu0, page.errors()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--lines", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--keep", type=Path, help="write the report here")
    args = ap.parse_args()
    print(machine_description())
    machine = load_machine(ROOT / "specs/machines/mill.toml")
    text = long_program(args.lines)
    t0 = time.perf_counter()
    result = verify_text(text, machine, file="bench_html.ngc")
    t1 = time.perf_counter()
    page = render_html(result, machine, program_text(text, "bench_html.ngc"))
    t2 = time.perf_counter()
    print(f"program: {text.count(chr(10))} lines; verdict {result.verdict.label}, {len(result.violations)} violations; "
          f"verify {t1 - t0:.1f} s, report built in {t2 - t1:.1f} s")
    with tempfile.TemporaryDirectory() as tmp:
        report = args.keep or Path(tmp) / "report.html"
        report.write_text(page, encoding="utf-8")
        size = report.stat().st_size
        print(f"report: {size / 1e6:.2f} MB ({size} bytes)")
        if find_chromium() is None:
            print("no chromium: load times not measured")
            return
        runs = [open_once(report) for _ in range(args.repeat)]
    for k, (load, ready, cpu, errors) in enumerate(runs, 1):
        print(f"run {k}: load event {load:.2f} s, view drawn {ready:.2f} s, Chromium CPU {cpu:.2f} s"
              + (f", errors {errors}" if errors else ""))
    print(f"median: load event {statistics.median(r[0] for r in runs):.2f} s, view drawn "
          f"{statistics.median(r[1] for r in runs):.2f} s, Chromium CPU {statistics.median(r[2] for r in runs):.2f} s")


if __name__ == "__main__":
    main()
