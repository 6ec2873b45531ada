"""The cam-groove numbers of specs/cylindrical.md, computed (not typed).

Run ``python docs/cam_groove.py`` to print the Markdown block, or
``python docs/cam_groove.py --write`` to replace the block between the
markers in specs/cylindrical.md.  Exact quantities come from nczones (the
enclosures of nczones.geometry.cylinder); the deviation between the two paths is a
report number, measured in floats on the developed surface (dense sampling,
1e-6 mm resolution is far below the printed precision).
"""

from __future__ import annotations

import math
import sys
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from nczones.gcode import segments  # noqa: E402
from nczones.geometry.cylinder import degree_length, developed_arc_of  # noqa: E402
from nczones.machine import load_machine  # noqa: E402
from nczones.prover import verify  # noqa: E402

EX = ROOT / "specs" / "examples"
BEGIN, END = "<!-- cam-groove numbers: begin (docs/cam_groove.py) -->", "<!-- cam-groove numbers: end -->"


def _code(path: Path) -> list[str]:
    """The blocks of a program without comments and blanks."""
    out = []
    for line in path.read_text().splitlines():
        code = line.split("(")[0].strip()
        if code and not code.startswith("%"):
            out.append(" ".join(code.split()))
    return out


def _blocks(path: Path) -> int:
    return len(_code(path))


def _dist_point_polyline_float(p, poly):
    best = math.inf
    for a, b in zip(poly, poly[1:]):
        ax, ay, bx, by = *a, *b
        dx, dy = bx - ax, by - ay
        L = dx * dx + dy * dy
        t = 0.0 if L == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L))
        best = min(best, math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy))
    return best


def compute() -> dict:
    m = load_machine(EX / "machines" / "cylinder.toml")
    near = load_machine(EX / "machines" / "cylinder_clamp_near.toml")
    seg_prog, arc_prog = EX / "programs" / "cam_groove_segments.ngc", EX / "programs" / "cam_groove_g071.ngc"
    arc = next(s for s in segments(str(arc_prog), m) if s.kind.name == "DEVELOPED_ARC")
    g = developed_arc_of(arc)
    rc = g.cylinder_radius
    k = degree_length(rc)
    lines = [s for s in segments(str(seg_prog), m) if s.kind.name == "LINE"]
    poly_deg = [(lines[0].start[0], lines[0].start[1])] + [(s.end[0], s.end[1]) for s in lines]
    kf = float(k.mid())
    poly = [(float(z), float(c - poly_deg[0][1]) * kf) for z, c in poly_deg]  # developed (Z, s from C30)
    cz, cs, rho = float(g.centre[0].mid()), float(g.centre[1].mid()), float(g.rho.mid())
    sweep = float(g.sweep.mid())
    ux, uy = float(g.u[0].mid()), float(g.u[1].mid())
    n = 20000
    arc_pts = []
    for i in range(n + 1):
        phi = -sweep * i / n  # clockwise
        arc_pts.append((cz + ux * math.cos(phi) - uy * math.sin(phi), cs + ux * math.sin(phi) + uy * math.cos(phi)))
    d1 = max(_dist_point_polyline_float(p, poly) for p in arc_pts)
    d2 = max(min(abs(math.hypot(p[0] - cz, p[1] - cs) - rho), math.inf) for p in poly)
    vertex_dev = [abs(math.hypot(p[0] - cz, p[1] - cs) - rho) for p in poly]
    out = {
        "radius": rc,
        "k_lo": k.lo, "d": g.d, "centre": g.centre, "rho": g.rho, "sweep_deg": g.sweep * 180 / 1,
        "length": g.length(),
        "poly_length": sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(poly, poly[1:])),
        "hausdorff": max(d1, d2), "worst_vertex": max(vertex_dev),
        "worst_vertex_at": poly_deg[max(range(len(poly)), key=lambda i: vertex_dev[i])],
        "blocks_segments": _blocks(seg_prog), "blocks_arc": _blocks(arc_prog),
        "bytes_segments": sum(len(b) + 1 for b in _code(seg_prog)),
        "bytes_arc": sum(len(b) + 1 for b in _code(arc_prog)),
        "verdicts": {},
    }
    from nczones.geometry.cylinder import pi_interval

    out["sweep_deg"] = (g.sweep.mid() * 180 / pi_interval().mid())
    for name, mach in (("clamp C160..200", m), ("clamp C150..200", near)):
        for label, prog in (("7 x G01", seg_prog), ("G07.1 arc", arc_prog)):
            r = verify(str(prog), mach)
            first = r.violations[0] if r.violations else None
            out["verdicts"][(name, label)] = (r.verdict.label, None if first is None else (first.line, first.depth))
    return out


def _d(x, places=4) -> str:
    x = Fraction(x) if not isinstance(x, float) else x
    return f"{float(x):.{places}f}"


def markdown(n: dict) -> str:
    rows = [
        BEGIN,
        "",
        "| quantity | value |",
        "|---|---|",
        f"| cylinder radius R (G07.1 C...) | {_d(n['radius'], 3)} mm |",
        f"| developed length of 123 deg (k x 123, k = pi R / 180) | {_d(n['d'].mid(), 6)} mm |",
        f"| arc: start (Z30, s0), end (Z110, s0 + {_d(n['d'].mid(), 3)}), G02 R80 | |",
        f"| centre on the developed surface (Z, s - s0) | ({_d(n['centre'][0].mid(), 6)}, {_d(n['centre'][1].mid(), 6)}) mm |",
        f"| swept angle on the developed surface | {_d(n['sweep_deg'], 4)} deg |",
        f"| developed arc length | {_d(n['length'].mid(), 4)} mm |",
        f"| length of the 7-segment polyline (developed) | {n['poly_length']:.4f} mm |",
        f"| max deviation between the two paths (Hausdorff, developed mm) | {n['hausdorff']:.4f} mm |",
        f"| worst polyline vertex off the arc | {n['worst_vertex']:.4f} mm at Z{_d(n['worst_vertex_at'][0], 1)} C{_d(n['worst_vertex_at'][1], 1)} |",
        f"| program blocks: 7 x G01 / G07.1 arc | {n['blocks_segments']} / {n['blocks_arc']} |",
        f"| program characters without comments: 7 x G01 / G07.1 arc | {n['bytes_segments']} / {n['bytes_arc']} |",
    ]
    for (mach, prog), (verdict, first) in n["verdicts"].items():
        extra = "" if first is None else f" (line {first[0]}, depth >= {_d(first[1], 3)} mm)"
        rows.append(f"| verify {prog} with {mach} | {verdict}{extra} |")
    rows += ["", END]
    return "\n".join(rows)


def main(argv: list[str]) -> int:
    block = markdown(compute())
    if "--write" in argv:
        doc = ROOT / "specs" / "cylindrical.md"
        text = doc.read_text()
        a, b = text.index(BEGIN), text.index(END) + len(END)
        doc.write_text(text[:a] + block + text[b:])
    else:
        print(block)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
