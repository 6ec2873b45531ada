"""Generated program libraries: the example library's generated programs, the benchmark's and the tests'.

Everything here is deterministic (seeded), exact decimal text, and written
for the bundled 3-axis mill (``specs/machines/mill.toml``: G54 X150 Y100
Z100, travel X 0..600 Y 0..400 Z 0..400, tool tip above Z50, a vise
X100..140 Y60..180 Z50..130 for the tool tip) and the patent grinder
(``specs/machines/grinder.toml``: G54 X400, the stepped table).

* :func:`mill_program` — a CAM-style pocket walk (lines, exact I/J arcs,
  retracts); ``into_vise=True`` adds one cut through the vise;
* :func:`grinder_program` — passes over the part; ``dip=True`` dips one
  pass into the work-head notch;
* :func:`long_mill_program` — a long safe CAM program that may be split
  (:mod:`nczones.fleet.split`);
* :func:`mill_variant` — the mill's machine file with the vise and G54
  moved (a family of machines for fleet benchmarks);
* :func:`write_library` — a whole project (machines, programs, ``nczones.toml``).

>>> mill_program(1, 6).splitlines()[:3]
['(generated mill program 1)', 'G21 G90 G17 G54', 'G0 G43 H1 Z60']
"""

from __future__ import annotations

import random
from pathlib import Path

__all__ = ["mill_program", "grinder_program", "long_mill_program", "mill_variant", "write_library",
           "write_example_programs"]


def _d(value: int) -> str:
    """Tenths of a mm as decimal text (``-125`` -> ``-12.5``).

    >>> _d(-125), _d(30), _d(-5)
    ('-12.5', '3', '-0.5')
    """
    sign = "-" if value < 0 else ""
    whole, tenth = divmod(abs(value), 10)
    return f"{sign}{whole}" + (f".{tenth}" if tenth else "")


def mill_program(seed: int, moves: int = 40, *, into_vise: bool = False) -> str:
    """A pocket walk on the mill in work coordinates X 10..300, Y -50..250 at depth Z-5 (tip Z95).

    The vise (work X -50..-10, Y -40..80) is only entered by the extra cut
    of ``into_vise``.  Arcs are quarter turns with exact centres.
    """
    r = random.Random(seed)
    out = [f"(generated mill program {seed})", "G21 G90 G17 G54", "G0 G43 H1 Z60"]
    x, y = r.randint(300, 2500), r.randint(-400, 2300)
    out += [f"G0 X{_d(x)} Y{_d(y)}", "G1 Z-5 F600"]
    vise_at = r.randint(moves // 3, max(moves // 3, 2 * moves // 3)) if into_vise else -1
    for i in range(moves):
        if i == vise_at:
            out.append(f"G1 X-30 Y{_d(r.randint(-300, 700))}")
            x = -300
            out.append(f"G1 X{_d(x)}")
        c = r.random()
        if c < 0.15:
            a, b = r.randint(-80, 80), r.randint(-80, 80)
            nx, ny = x + a + b, y + b - a
            if 100 <= nx <= 2900 and -400 <= ny <= 2400 and 100 <= x + a - 1 and (a or b):
                out.append(f"G3 X{_d(nx)} Y{_d(ny)} I{_d(a)} J{_d(b)}")
                out.append(f"G1 X{_d(nx)} Y{_d(ny)}")
                x, y = nx, ny
                continue
        if c < 0.25:
            out.append("G0 Z20")
            x, y = r.randint(300, 2900), r.randint(-400, 2400)
            out += [f"X{_d(x)} Y{_d(y)}", "G1 Z-5"]
            continue
        x = min(2900, max(300, x + r.randint(-400, 400)))
        y = min(2400, max(-400, y + r.randint(-400, 400)))
        out.append(f"X{_d(x)} Y{_d(y)}" if r.random() < 0.7 else f"G1 X{_d(x)} Y{_d(y)} (cut)")
    out += ["G0 Z60", "M30"]
    return "\n".join(out) + "\n"


def grinder_program(seed: int, passes: int = 8, *, dip: bool = False) -> str:
    """Passes of the grinder wheel at machine Y 230..290 over machine X 50..1150; ``dip`` dips one into the notch.

    The dip goes to Y130 at machine X 300, where the table allows Y 220 and up.
    """
    r = random.Random(seed)
    out = [f"(generated grinder program {seed})", "G21 G90 G54", "G0 X-250 Y290"]
    dip_at = r.randint(0, passes - 1) if dip else -1
    for i in range(passes):
        y = r.randint(2300, 2900)
        x0, x1 = r.randint(-3500, 0), r.randint(0, 7500)
        out += [f"G0 X{_d(x0)} Y{_d(y)}", f"G1 X{_d(x1)} F{r.choice((300, 500, 800))}"]
        if i == dip_at:
            out += ["G0 X-100 Y240", "G1 Y130", "G1 Y240"]
    out += ["G0 Y300", "M30"]
    return "\n".join(out) + "\n"


def long_mill_program(lines: int, seed: int = 0) -> str:
    """A safe CAM program of about ``lines`` lines of modal ``X.. Y..`` moves (one that may be split).

    >>> text = long_mill_program(1000)
    >>> 990 <= text.count("\\n") <= 1010
    True
    """
    r = random.Random(seed)
    head = ["(generated long mill program)", "G21 G90 G17 G54", "G0 G43 H1 Z60", "G0 X100 Y100", "G1 Z-5 F1200"]
    moves = max(1, lines - len(head) - 2)
    xs = [r.randint(300, 2900) for _ in range(4096)]
    ys = [r.randint(-400, 2400) for _ in range(4096)]
    body = [f"X{_d(xs[i % 4096])} Y{_d(ys[(i * 7) % 4096])}" for i in range(min(moves, 65536))]
    reps, rest = divmod(moves, len(body))
    text = "\n".join(head) + "\n" + ("\n".join(body) + "\n") * reps + "".join(b + "\n" for b in body[:rest])
    return text + "G0 Z60\nM30\n"


_MILL_TOML = """# generated: the 3-axis mill with the vise moved by {shift} mm in X
[machine]
name = "mill variant {k}"
units = "mm"
axes = ["X", "Y", "Z"]
pulse = "0.001"
rapid_mode = "linear"
path_mode = "G61"          # exact path: corners are not rounded (specs/path-modes.md)

[machine.rapid]
X = "15000"
Y = "15000"
Z = "10000"

[machine.reference]
X = "0"
Y = "0"
Z = "400"

[offsets]
G54 = {{ X = "150", Y = "100", Z = "100" }}

[tool_lengths]
H1 = "120"

[[zones]]
name = "travel"
kind = "box"
min = {{ X = "0", Y = "0", Z = "0" }}
max = {{ X = "600", Y = "400", Z = "400" }}

[[zones]]
name = "table"
kind = "box"
point = "tip"
min = {{ Z = "50" }}

[[zones]]
name = "vise"
kind = "box"
forbid = true
point = "tip"
min = {{ X = "{vx0}", Y = "60", Z = "50" }}
max = {{ X = "{vx1}", Y = "180", Z = "130" }}
"""


def mill_variant(k: int) -> str:
    """Machine file text: the mill with its vise moved ``3k`` mm to the right (``k = 0``: X100..140).

    Variants with a large ``k`` put the vise under the generated pocket walks, so their verdicts differ.
    """
    shift = 3 * k
    return _MILL_TOML.format(k=k, shift=shift, vx0=100 + shift, vx1=140 + shift)


def write_library(folder: str | Path, programs: int = 30, machines: int = 34, *, moves: int = 30) -> Path:
    """A project of ``programs`` mill programs (every fifth with a cut into the original vise) on
    ``machines`` mill variants; returns the project file."""
    root = Path(folder)
    (root / "machines").mkdir(parents=True, exist_ok=True)
    (root / "programs").mkdir(parents=True, exist_ok=True)
    for k in range(machines):
        (root / "machines" / f"mill_{k:03d}.toml").write_text(mill_variant(k), encoding="utf-8")
    for i in range(programs):
        (root / "programs" / f"part_{i:03d}.ngc").write_text(mill_program(i, moves, into_vise=i % 5 == 0),
                                                             encoding="utf-8")
    lines = ["[project]", 'name = "generated mill library"', "", "[defaults]", "max_violations = 5", ""]
    for k in range(machines):
        lines += [f"[machines.mill_{k:03d}]", f'file = "machines/mill_{k:03d}.toml"',
                  'programs = ["programs/*.ngc"]', ""]
    project = root / "nczones.toml"
    project.write_text("\n".join(lines), encoding="utf-8")
    return project


def write_example_programs(folder: str | Path) -> list[Path]:
    """The generated programs of the bundled example library (``specs/examples/library/programs``)."""
    root = Path(folder)
    written = []
    for i in range(8):
        p = root / "mill" / f"pocket_{i:02d}.ngc"
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(mill_program(100 + i, 24, into_vise=i % 3 == 2), encoding="utf-8")
        written.append(p)
    for i in range(4):
        p = root / "grinder" / f"passes_{i:02d}.ngc"
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(grinder_program(200 + i, 6, dip=i % 2 == 1), encoding="utf-8")
        written.append(p)
    return written
