"""Benchmark of the G-code front end (a script, not a test).

    python bench/bench_gcode.py [--lines 1000000] [--small 100000] [--naive-lines 100000]
                                [--full-lines 100000] [--drill-lines 100000]

Prints, each case measured in fresh processes (``--runs``, default 3; the
run with the least CPU time is shown): interpreted lines/s and
segments/s (wall clock and CPU), the share of lines the vectorized fast
path took, and the peak resident memory (the clock starts once the G-code
modules are imported; their import time is printed on its own), for

* ``stellabee1.ngc`` from the corpus, fast path and full interpreter;
* a generated CAM-style program (G0/G1/G2 with modal words) of ``--small``
  and ``--lines`` lines (the memory of the two shows whether it grows with
  the program);
* the same CAM program (``--naive-lines`` lines) through the full
  interpreter only, for the fast/naive ratio of the same run;
* a generated program with S and M3 words on every line (fast path since
  S and spindle/coolant M codes are simple words);
* a generated CAM program that also sets and reads parameters (no control
  flow: the fast path takes its runs, the full path its ``#`` lines, with
  one parameter store);
* a generated CAM program with subroutines (``o100 sub``/``call``, so the
  language layer runs the whole program and hands runs of simple lines in
  the main program and in subroutine bodies to the fast path);
* programs that need the full interpreter line by line: parameters,
  expressions and an O-word loop (``bench_interpreter.macro_program``; its
  lines are the lines the language layer executes, loop bodies once per
  iteration), and an expression in the words of every line;
* a generated drilling program (``--drill-lines`` hole lines ``X.. Y..``
  under G81/G82 cycles, each cycle opened by its full block and closed by
  G80), fast path and full interpreter.

The generators :func:`g91_program`, :func:`g20_program`, :func:`drill_expr_program`, :func:`cycle_program`,
:func:`comp_program`, :func:`comp_arc_program` and
:func:`g18_program` (not run by :func:`main`) write the parametric classes the double pass declines, which
``nczones verify`` reads by the full path (specs/performance.md, "The full path's per-line cost"); the pass
takes :func:`g18_program`'s arcs since plane38, lathes since lathe39 (:func:`lathe_program`: G7 diameters, G18
arcs by K/I and R), and :func:`g20_program`'s straight moves in inches since units39 (and its arcs, I/J and R);
:func:`g91_arc_program` (G91 arcs) and :func:`plane_mix_program` (G17 and G18 arcs in turn) it takes since arc40.
"""

from __future__ import annotations

import argparse
import math
import random
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from _bench import STELLABEE, Clock, emit, machine_description, run_case  # noqa: E402

MACHINE_TEXT = (
    '[machine]\naxes = ["X", "Y", "Z"]\npulse = "0.0001"\n[machine.rapid]\nX = "1000"\nY = "1000"\nZ = "1000"\n'
    '[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n[tool_lengths]\nH1 = "100"\n'
)


def _machine():
    from nczones.machine import parse_machine

    return parse_machine(MACHINE_TEXT)


MACHINE = _machine()


def cam_program(n: int, seed: int = 1) -> str:
    """About ``n`` lines: modal X/Y moves, an arc every 50 lines."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54", "G43 H1 G0 Z5", "G1 F800"]
    x = y = 0.0
    while len(out) < n - 1:
        if len(out) % 50 == 49:
            x = round(x + 2, 3)
            out.append(f"G2 X{x:.3f} Y{y:.3f} I1.000 J0")
            out.append("G1")
        else:
            x = round(x + rnd.uniform(-1, 1), 3)
            y = round(y + rnd.uniform(-1, 1), 3)
            out.append(f"X{x:.3f} Y{y:.3f}")
    out.append("M30")
    return "\n".join(out) + "\n"


def full_program(n: int, seed: int = 2) -> str:
    rnd = random.Random(seed)
    out = ["G21 G91 G17 G54 F500"]
    for i in range(n - 2):
        out.append(f"G1 X{rnd.uniform(-1, 1):.3f} Y{rnd.uniform(-1, 1):.3f} S{1000 + i % 7} M3")
    out.append("M30")
    return "\n".join(out) + "\n"


def param_program(n: int, seed: int = 4) -> str:
    rnd = random.Random(seed)
    out = ["#<feed> = 800", "G21 G90 G17 G54 G1 F#<feed>"]
    for _ in range(n - 3):
        out.append(f"X{rnd.uniform(0, 200):.3f} Y{rnd.uniform(0, 100):.3f}")
    out.append("M30")
    return "\n".join(out) + "\n"


def sub_program(n: int, seed: int = 5) -> str:
    """About ``n`` lines: a CAM main program calling two subroutines (a plunge and a 200-line contour)."""
    rnd = random.Random(seed)
    contour = [f"G1 X[#1 + {rnd.uniform(0, 50):.3f}] Y{rnd.uniform(0, 50):.3f}" if k == 0 else
               f"X{rnd.uniform(0, 50):.3f} Y{rnd.uniform(0, 50):.3f}" for k in range(200)]
    out = ["o100 sub", "G0 Z5", "G1 Z#1 F200", "o100 endsub", "o200 sub", *contour, "o200 endsub",
           "G21 G90 G17 G54", "G1 F800"]
    while len(out) < n - 1:
        out += ["o100 call [-1]", "o200 call [10]"]
        out += [f"X{rnd.uniform(0, 200):.3f} Y{rnd.uniform(0, 100):.3f}" for _ in range(500)]
    out.append("M30")
    return "\n".join(out) + "\n"


def expr_program(n: int, seed: int = 7) -> str:
    """About ``n`` lines: moves whose words are expressions (``G1 X[#1 + 12.5] Y[#2 + 3.25]``), a
    parameter changed every tenth line, no control flow (every line is different, nothing repeats)."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54 F800", "#1 = 0", "#2 = 0"]
    while len(out) < n - 1:
        if len(out) % 10 == 0:
            out.append(f"#1 = [#1 + {rnd.uniform(0, 1):.3f}]")
        else:
            out.append(f"G1 X[#1 + {rnd.uniform(0, 100):.3f}] Y[#2 + {rnd.uniform(0, 100):.3f}]")
    out.append("M30")
    return "\n".join(out) + "\n"


def rarc_program(n: int, seed: int = 11, dialect: str = "linuxcnc") -> str:
    """About ``n`` lines of R-format arcs as posts and hand programming write them: ``G2``/``G3`` with
    ``X Y R`` (some modal, some with a negative R: the long way round), a ``G1`` line every 20th line.
    Fanuc: every length with a decimal point, ``O``/``%`` framing."""
    rnd = random.Random(seed)
    if dialect == "fanuc":
        out = ["%", "O1000 (R ARCS)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0.", "G01 F800."]
    else:
        out = ["G21 G90 G17 G54", "G0 X0 Y0", "G1 F800"]
    x = y = 0.0
    g = 2
    while len(out) < n - (3 if dialect == "fanuc" else 1):
        x1 = round(min(max(x + rnd.uniform(-5, 5), -200), 200), 3)
        y1 = round(min(max(y + rnd.uniform(-5, 5), -200), 200), 3)
        if len(out) % 20 == 0:
            out.append(f"G1 X{x1:.3f} Y{y1:.3f}")
            g = 0
        else:
            half = math.hypot(x1 - x, y1 - y) / 2
            if half < 0.01:
                continue
            r = round(half * rnd.uniform(1.001, 4) + 0.001, 3)
            if rnd.random() < 0.1:
                r = -r
            word = "" if g in (2, 3) and rnd.random() < 0.5 else f"G{rnd.choice((2, 3))} "
            if word:
                g = int(word[1])
            out.append(f"{word}X{x1:.3f} Y{y1:.3f} R{r:.3f}")
        x, y = x1, y1
    out += ["M30", "%"] if dialect == "fanuc" else ["M30"]
    return "\n".join(out) + "\n"


def ijarc_program(n: int, seed: int = 13, dialect: str = "linuxcnc") -> str:
    """About ``n`` lines of I/J arcs (``G2``/``G3 X Y I J``, the centre given exactly, mostly modal) with a
    ``G1`` line every 20th line.  Fanuc: every length with a decimal point, ``O``/``%`` framing."""
    rnd = random.Random(seed)
    if dialect == "fanuc":
        out = ["%", "O1000 (IJ ARCS)", "G00 G17 G40 G49 G80 G90 G21", "G54 G00 X0. Y0.", "G01 F800."]
    else:
        out = ["G21 G90 G17 G54", "G0 X0 Y0", "G1 F800"]
    x = y = 0.0
    g = 0
    while len(out) < n - (3 if dialect == "fanuc" else 1):
        if len(out) % 20 == 0:
            x = round(min(max(x + rnd.uniform(-5, 5), -200), 200), 3)
            y = round(min(max(y + rnd.uniform(-5, 5), -200), 200), 3)
            out.append(f"G1 X{x:.3f} Y{y:.3f}")
            g = 0
            continue
        # a centre (x + i, y + j) and an end on the same circle: the end is the start turned about the centre
        i, j = round(rnd.uniform(-3, 3), 3), round(rnd.uniform(-3, 3), 3)
        turn = rnd.uniform(0.2, 2.5)
        cx, cy = x + i, y + j
        c, s_ = math.cos(turn), math.sin(turn)
        x1 = round(cx + (x - cx) * c - (y - cy) * s_, 3)
        y1 = round(cy + (x - cx) * s_ + (y - cy) * c, 3)
        if abs(x1) > 250 or abs(y1) > 250 or math.hypot(i, j) < 0.05:
            continue
        word = "" if g in (2, 3) and rnd.random() < 0.7 else f"G{rnd.choice((2, 3))} "
        if word:
            g = int(word[1])
        out.append(f"{word}X{x1:.3f} Y{y1:.3f} I{i:.3f} J{j:.3f}")
        x, y = x1, y1
    out += ["M30", "%"] if dialect == "fanuc" else ["M30"]
    return "\n".join(out) + "\n"


def osub_program(n: int, seed: int = 17) -> str:
    """About ``n`` lines of a LinuxCNC program with o-word subroutines and no parameters (``#``): two subs
    (a plunge and a 50-line contour) called from a CAM main program every 200 lines, as hand-edited
    programs with o-word subroutines are written."""
    rnd = random.Random(seed)
    contour = [f"G1 X{rnd.uniform(0, 50):.3f} Y{rnd.uniform(0, 50):.3f}" for _ in range(50)]
    out = ["o100 sub", "G0 Z5", "G1 Z-1 F200", "o100 endsub", "o200 sub", *contour, "o200 endsub",
           "G21 G90 G17 G54", "G1 F800"]
    while len(out) < n - 1:
        out += ["o100 call", "o200 call", "G1 F800"]
        out += [f"X{rnd.uniform(0, 200):.3f} Y{rnd.uniform(0, 100):.3f}" for _ in range(200)]
    out.append("M30")
    return "\n".join(out) + "\n"


def declined_program(n: int, seed: int = 19) -> str:
    """The expression-every-line program (:func:`expr_program`) with the spindle started and ``G64 Q0.01``
    (naive-CAM merging without a path tolerance), which the double pass does not follow: it declines, and the
    full path reads the program.  (``S1000 M3`` alone was this class until the pass learnt spindle and coolant
    codes, ``G61`` until it learnt path modes, ``G91.1`` until it took the default arc-centre mode written out,
    ``G64 P0.01`` until it took a path tolerance, ``G64 P0.01 Q0.01`` until it took Q, issue 36.)"""
    text = expr_program(n, seed)
    head, rest = text.split("\n", 1)
    return f"{head}\nS1000 M3\nG64 Q0.01\n{rest}"


def g91_program(n: int, seed: int = 23) -> str:
    """About ``n`` lines of relative moves (G91) whose words are expressions (``G1 X[#1 + 0.05] Y[#2 * -0.3]``),
    ``#1`` negated every tenth line: a parametric program the double pass declines (G91), read by the full path."""
    rnd = random.Random(seed)
    out = ["G21 G91 G17 G54 F800", "#1 = 0.5", "#2 = 0.25"]
    while len(out) < n - 1:
        if len(out) % 10 == 0:
            out.append("#1 = [0 - #1]")
        else:
            out.append(f"G1 X[#1 + {rnd.uniform(-0.1, 0.1):.3f}] Y[#2 * {rnd.uniform(-1, 1):.3f}]")
    out.append("M30")
    return "\n".join(out) + "\n"


def g20_program(n: int, seed: int = 41) -> str:
    """:func:`expr_program` in inches (G20: the double pass takes its straight moves), its moves within 4 inches."""
    rnd = random.Random(seed)
    out = ["G20 G90 G17 G54 F30", "#1 = 0", "#2 = 0"]
    while len(out) < n - 1:
        if len(out) % 10 == 0:
            out.append(f"#1 = [#1 + {rnd.uniform(0, 0.01):.4f}]")
        else:
            out.append(f"G1 X[#1 + {rnd.uniform(0, 4):.4f}] Y[#2 + {rnd.uniform(0, 4):.4f}]")
    out.append("M30")
    return "\n".join(out) + "\n"


def drill_expr_program(n: int, seed: int = 31) -> str:
    """About ``n`` lines of G81 holes whose X is an expression (``X[#1 + 123.456] Y78.9``), 1000 a cycle (a
    canned cycle: the double pass declines; three motions a hole)."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54", "G43 H1 G0 Z20", "G0 X0 Y0", "F300", "#1 = 10"]
    while len(out) < n - 1:
        out.append("G99 G81 X1.000 Y1.000 Z-3 R2")
        for _ in range(min(1000, n - 2 - len(out))):
            out.append(f"X[#1 + {rnd.uniform(0, 400):.3f}] Y{rnd.uniform(0, 300):.3f}")
        out.append("G80")
    out.append("M30")
    return "\n".join(out) + "\n"


#: :func:`cycle_program`'s forms: the block that opens a cycle (after ``#1 = 10`` and the tool at Z 20) and the
#: hole line (``{x}``, ``{y}``: numbers; ``{l}``: an L word or nothing).
CYCLE_FORMS = {
    "g91l": ("G91 G99 G81 X1 Y1 Z-5 R-18 L2", "X[#1 * 0.1 + {x}] Y{y}{l}"),
    "g73": ("G99 G73 X1 Y1 Z-3 R2 Q1", "X[#1 + {x}] Y{y}"),
    "g85": ("G98 G85 X1 Y1 Z-3 R2", "X[#1 + {x}] Y{y}"),
    "g89": ("G99 G89 X1 Y1 Z-3 R2 P0.5", "X[#1 + {x}] Y{y}"),
    "g84": ("M3 S500\nG99 G84 X1 Y1 Z-3 R2", "X[#1 + {x}] Y{y}"),
    "g86": ("M3 S500\nG98 G86 X1 Y1 Z-3 R2 P0.5", "X[#1 + {x}] Y{y}"),
    # cyc41: G20 hole lines (the template), a G98 R equal to the initial level by value, G83 in G91
    "g20": ("G99 G81 X1 Y1 Z-0.1 R0.1", "X[#1 + {x}] Y{y}"),
    "g98v": ("G98 G81 X1 Y1 Z-3 R20", "X[#1 + {x}] Y{y}"),
    "g83i": ("G91 G99 G83 X1 Y1 Z-5 R-18 Q2", "X[#1 * 0.1 + {x}] Y{y}"),
}
#: the forms whose hole lines are G91 increments (closed by ``G90 G80`` and a move back), and those in inches
_G91_FORMS = frozenset({"g91l", "g83i"})
_G20_FORMS = frozenset({"g20"})


def cycle_program(n: int, form: str = "g91l", seed: int = 41) -> str:
    """About ``n`` lines of canned cycle holes whose X is an expression, 1000 a cycle (:data:`CYCLE_FORMS`):
    ``g91l`` a G91 G81 hole pattern (X and Y increments, ``L1``-``L4`` on most lines), ``g73`` chip-break pecks,
    ``g84``-``g89`` tapping and boring (the cycles the double pass took from cyc40 on; :func:`drill_expr_program`
    is G81's); from cyc41: ``g20`` G81 in inches, ``g98v`` a G98 cycle whose R equals the initial level by value
    (``Z20`` then ``R20``), ``g83i`` G83 pecks in G91."""
    rnd = random.Random(seed)
    first, hole = CYCLE_FORMS[form]
    units = "G20" if form in _G20_FORMS else "G21"
    out = [f"{units} G90 G17 G54", "G43 H1 G0 Z20", "G0 X0 Y0", "F300", "#1 = 10"]
    inc = form in _G91_FORMS
    while len(out) < n - 2:
        out.append(first)
        for _ in range(min(1000, n - 3 - len(out))):
            if inc:
                x, y = f"{rnd.uniform(-5, 5):.3f}", f"{rnd.uniform(-3, 3):.3f}"
                reps = rnd.choice(["", " L2", " L3", " L4"])
            else:
                x, y, reps = f"{rnd.uniform(0, 400):.3f}", f"{rnd.uniform(0, 300):.3f}", ""
            out.append(hole.format(x=x, y=y, l=reps))
        out += ["G90 G80", "G0 X0 Y0 Z20"] if inc else ["G80"]
    out.append("M30")
    return "\n".join(out) + "\n"


def comp_program(n: int, seed: int = 29) -> str:
    """About ``n`` lines of a G41 contour (cutter compensation, tool T1: a machine with ``cutter_compensation =
    "linuxcnc"`` and ``[tool_diameters]``), X up by 10 a line, Y an expression: LinuxCNC's corner arcs at every
    convex corner (spirals about a rational centre: their ends rounded)."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54 F800", "T1 M6", "#1 = 0", "G0 X0 Y0", "G41 G1 X5 Y0"]
    x = 5.0
    while len(out) < n - 2:
        x += 10
        out.append(f"X{x:.3f} Y[#1 + {rnd.uniform(0, 3):.3f}]")
    out += ["G40 G0 X0 Y0", "M30"]
    return "\n".join(out) + "\n"


def comp_arc_program(n: int, seed: int = 31) -> str:
    """About ``n`` lines of a G41 finishing contour as CAM writes it (cutter compensation, tool T1 as
    :func:`comp_program`): waves of lines and quarter arcs, I/J and R, G2 (the tool outside) and G3 (inside,
    radius 2 to 5 mm), tangent but for a line whose Y is an expression a little off (a small convex or concave
    corner): every compensated arc, its corners and pull-backs LinuxCNC's ``convert_arc_comp2`` (comp41)."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54 F800", "T1 M6", "#1 = 0", "G0 X-10 Y-5", "G41 G1 X0 Y0"]
    x = y = 0.0
    while len(out) < n - 2:
        r = round(rnd.uniform(2, 5), 3)
        a = round(rnd.uniform(1, 6), 3)
        b = round(rnd.uniform(1, 6), 3)
        x += a
        y += round(rnd.uniform(-0.05, 0.05), 3)
        out += [f"G1 X{x:.3f} Y[#1 + {y:.3f}]",
                f"G3 X{x + r:.3f} Y{y + r:.3f} I0 J{r:.3f}",
                f"G2 X{x + 2 * r:.3f} Y{y + 2 * r:.3f} R{r:.3f}",
                f"G1 X{x + 2 * r + b:.3f}",
                f"G2 X{x + 3 * r + b:.3f} Y{y + r:.3f} I0 J{-r:.3f}",
                f"G3 X{x + 4 * r + b:.3f} Y{y:.3f} R{r:.3f}"]
        x += 4 * r + b
    out += ["G40 G0 X0 Y-10", "M30"]
    return "\n".join(out) + "\n"


def g18_program(n: int, seed: int = 37) -> str:
    """About ``n`` lines in G18: a G1 with an expression, then an R-format G2 (an irrational centre), in turn."""
    rnd = random.Random(seed)
    out = ["G21 G90 G18 G54 F800", "#1 = 0", "G0 X0 Z0"]
    x = 0.0
    while len(out) < n - 1:
        if len(out) % 2:
            x += 1
            out.append(f"G1 X{x:.3f} Z[#1 + {rnd.uniform(0, 1):.3f}]")
        else:
            out.append(f"G2 X{x + 1:.3f} Z0 R2")
            x += 1
    out.append("M30")
    return "\n".join(out) + "\n"


def g91_arc_program(n: int, seed: int = 47) -> str:
    """About ``n`` lines of G91 arcs as hand programming writes them: closed circles of four quarters (I/J or R, either
    way, the radius an expression of ``#1`` in some), a short G91 ``G1`` between circles: one G91 chain the whole
    program (the double pass takes it since arc40)."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54 F800", "#1 = 0.5", "G0 X0 Y0", "G91"]
    while len(out) < n - 1:
        if rnd.random() < 0.2:
            out.append(f"G1 X[#1 * {rnd.uniform(-4, 4):.3f}] Y{rnd.uniform(-2, 2):.3f}")
            continue
        r = round(rnd.uniform(0.5, 20), 3)
        g = rnd.choice(("G2", "G3"))
        s = 1 if g == "G3" else -1  # a quarter turn ccw (G3) or cw (G2) from the start's angle pi
        form = rnd.random()
        for q in range(4):
            # the start's vector from the centre turns by +-pi/2 a quarter: u -> w, end = start - u + w
            ux, uy = [(-r, 0.0), (0.0, -s * r), (r, 0.0), (0.0, s * r)][q]
            wx, wy = [(0.0, -s * r), (r, 0.0), (0.0, s * r), (-r, 0.0)][q]
            dx, dy = wx - ux, wy - uy
            if form < 0.5:
                out.append(f"{g} X{dx:.3f} Y{dy:.3f} I{-ux:.3f} J{-uy:.3f}")
            elif form < 0.8:
                out.append(f"{g} X{dx:.3f} Y{dy:.3f} R{r:.3f}")
            else:
                out.append(f"{g} X[{dx:.3f} * #1 * 2] Y[{dy:.3f} * #1 * 2] R[{r:.3f} * #1 * 2]")
    out.append("M30")
    return "\n".join(out) + "\n"


def plane_mix_program(n: int, seed: int = 53) -> str:
    """About ``n`` lines as 3-axis CAM writes side arcs: a ``G1`` with an expression, then a G17 arc (I/J) and a
    G18 arc (K/I or R, the plane's first axis Z), in turn, G90 (the double pass takes a second plane since arc40)."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54 F800", "#1 = 0", "G0 X0 Y0 Z0"]
    x = 0.0
    while len(out) < n - 1:
        if x > 4000:  # back (inside a 5,000 mm box)
            out.append("G0 Z5\nG0 X0 Y0")
            x = 0.0
        x += 1
        z = round(rnd.uniform(-1, 0), 3)
        out.append(f"G17 G1 X{x:.3f} Y[#1 + 0] Z{z:.3f}")
        out.append(f"G3 X{x + 2:.3f} Y0 I1 J0" if rnd.random() < 0.5 else f"G2 X{x + 2:.3f} Y0 R2")
        out.append(f"G18 G2 Z{z - 1:.3f} X{x + 3:.3f} K-1 I0" if rnd.random() < 0.5
                   else f"G18 G3 Z{z - 1:.3f} X{x + 3:.3f} R1")
        x += 3
    out.append("M30")
    return "\n".join(out) + "\n"


def lathe_program(n: int, seed: int = 43) -> str:
    """About ``n`` lines of a LinuxCNC lathe program in G7 (X words are diameters) and G18: a ``G1`` whose X is an
    expression (``X[#1 + 41.250] Z-12.5``), a quarter ``G3`` by K and I (radii) and a ``G2`` by R from its end,
    in turn, with ``#1`` stepped every 30th line (the arcs' X words follow it, so every arc ends on its circle).
    The pass takes it on a lathe since lathe39; before, every lathe program ran the full path."""
    rnd = random.Random(seed)
    out = ["G18 G7 G21 G90 G54 F300", "#1 = 0", "G0 X100 Z5"]
    while len(out) < n - 1:
        if len(out) % 30 == 0:
            out.append(f"#1 = [#1 + {rnd.uniform(0, 0.01):.4f}]")
            continue
        d, z, r = (round(rnd.uniform(lo, hi), 3) for lo, hi in ((20, 100), (-100, 0), (0.5, 3)))
        out.append(f"G1 X[#1 + {d:.3f}] Z{z:.3f}")
        # a quarter counter-clockwise in (Z, X) about (z - r, x): to (z - r, x + r), diameter + 2 r
        out.append(f"G3 X[#1 + {d + 2 * r:.3f}] Z{z - r:.3f} K{-r:.3f} I0")
        out.append(f"G2 X[#1 + {d + 4 * r:.3f}] Z{z - 2 * r:.3f} R{1.5 * r:.3f}")
    out.append("M30")
    return "\n".join(out) + "\n"


def drill_program(n: int, seed: int = 3) -> str:
    """About ``n`` lines: G81 and G82 cycles (G98/G99) of 1000 holes each, as CAM posts them."""
    rnd = random.Random(seed)
    out = ["G21 G90 G17 G54", "G43 H1 G0 Z20", "G0 X0 Y0", "F300"]
    k = 0
    while len(out) < n - 1:
        head = ["G99 G81 X1.000 Y1.000 Z-3 R2", "G98 G82 X1.000 Y1.000 Z-4.5 R1.5 P0.5"][k % 2]
        out.append(f"N{len(out)} {head}" if k % 3 == 0 else head)
        for _ in range(min(1000, n - 2 - len(out))):
            out.append(f"X{rnd.uniform(0, 500):.3f} Y{rnd.uniform(0, 300):.3f}")
        out.append("G80")
        k += 1
    out.append("M30")
    return "\n".join(out) + "\n"


def case(path: str, fast: bool, limit: int | None, executed: int = 0) -> None:
    """One measurement (in this fresh process): interpret the program, print a JSON line.

    ``executed``: the lines the language layer executes (counted by the parent process, so that
    nothing here is warmed up before the clock starts); default the program's lines.
    """
    import importlib
    import time

    t0 = time.process_time()
    # nczones.gcode and the modules interpret() imports on first use: compiling and running them is a
    # one-time cost per process (26-50 ms more where bytecode is not cached), reported on its own
    for module in ("nczones.gcode", "nczones.gcode.program", "nczones.gcode.fastpath", "nczones.gcode.cylindrical"):
        importlib.import_module(module)
    import_s = time.process_time() - t0
    from nczones.gcode import interpret, interpret_text

    p = Path(path)
    if limit:
        text = "".join(p.read_text().splitlines(keepends=True)[:limit])
        src = text
        lines = text.count("\n")
    else:
        src = p
        lines = executed or p.read_bytes().count(b"\n")
    with Clock() as c:
        run = (interpret_text if isinstance(src, str) else interpret)(src, MACHINE, fast=fast, arc_tolerance="0.1")
        segs = sum(len(ch) for ch in run)
    emit({"lines": lines, "segments": segs, "wall": c.wall, "cpu": c.cpu, "fast_lines": run.fast_lines,
          "import_cpu": import_s})


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, default=1_000_000)
    ap.add_argument("--small", type=int, default=100_000)
    ap.add_argument("--naive-lines", type=int, default=100_000)
    ap.add_argument("--full-lines", type=int, default=100_000)
    ap.add_argument("--drill-lines", type=int, default=100_000)
    ap.add_argument("--runs", type=int, default=3, help="fresh processes per case; the least CPU time is shown")
    ap.add_argument("--case", nargs="+", metavar="PATH FAST LIMIT [EXECUTED]", help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.case:
        case(a.case[0], a.case[1] == "1", int(a.case[2]) or None, int(a.case[3]) if len(a.case) > 3 else 0)
        return
    # imported here, not at the top: a case's process must not import (and warm up) the language layer
    from bench_interpreter import executed_lines, macro_program

    me = str(Path(__file__).resolve())

    def run(*args):
        return run_case(*args, runs=a.runs)

    print(f"machine: {machine_description()}")
    rows = []
    with tempfile.TemporaryDirectory() as d:
        if STELLABEE.is_file():
            rows.append(("stellabee1.ngc, fast path", run(me, "--case", str(STELLABEE), "1", "0")))
            rows.append(("stellabee1.ngc, full interpreter (naive)", run(me, "--case", str(STELLABEE), "0", "0")))
        small = Path(d) / "cam_small.ngc"
        small.write_text(cam_program(a.small))
        big = Path(d) / "cam_big.ngc"
        big.write_text(cam_program(a.lines))
        rows.append((f"generated CAM {a.small:,} lines, fast path", run(me, "--case", str(small), "1", "0")))
        rows.append((f"generated CAM {a.lines:,} lines, fast path", run(me, "--case", str(big), "1", "0")))
        rows.append((f"generated CAM first {a.naive_lines:,} lines, full interpreter (naive)",
                     run(me, "--case", str(big), "0", str(a.naive_lines))))
        full = Path(d) / "full.ngc"
        full.write_text(full_program(a.full_lines))
        rows.append((f"generated M/S-word program {a.full_lines:,} lines", run(me, "--case", str(full), "1", "0")))
        param = Path(d) / "param.ngc"
        param.write_text(param_program(a.full_lines))
        rows.append((f"generated CAM + parameters {a.full_lines:,} lines (fast runs, shared parameters)",
                     run(me, "--case", str(param), "1", "0")))
        subs = Path(d) / "subs.ngc"
        subs.write_text(sub_program(a.full_lines))
        rows.append((f"generated CAM + subroutines {a.full_lines:,} lines (O words; fast runs)",
                     run(me, "--case", str(subs), "1", "0", str(executed_lines(subs.read_text())))))
        macro = Path(d) / "macro.ngc"
        macro.write_text(macro_program(a.full_lines))
        rows.append((f"NEEDS FULL INTERPRETER: params, COS/SIN, o-word repeat ({a.full_lines:,} executed)",
                     run(me, "--case", str(macro), "1", "0", str(executed_lines(macro.read_text())))))
        exprs = Path(d) / "exprs.ngc"
        exprs.write_text(expr_program(a.full_lines))
        rows.append((f"NEEDS FULL INTERPRETER: an expression on every line, {a.full_lines:,} lines",
                     run(me, "--case", str(exprs), "1", "0")))
        drill = Path(d) / "drill.ngc"
        drill.write_text(drill_program(a.drill_lines))
        rows.append((f"generated drilling (G81/G82) {a.drill_lines:,} lines, fast path",
                     run(me, "--case", str(drill), "1", "0")))
        rows.append((f"generated drilling (G81/G82) {a.drill_lines:,} lines, full interpreter (naive)",
                     run(me, "--case", str(drill), "0", "0")))
    print(f"{'case':72s} {'lines':>9s} {'segments':>9s} {'wall s':>7s} {'cpu s':>7s} {'lines/s wall':>13s} "
          f"{'lines/s cpu':>12s} {'segments/s':>11s} {'fast share':>10s} {'peak RSS':>9s}")
    for name, r in rows:
        print(f"{name:72s} {r['lines']:9d} {r['segments']:9d} {r['wall']:7.2f} {r['cpu']:7.2f} "
              f"{r['lines'] / r['wall']:13,.0f} {r['lines'] / r['cpu']:12,.0f} {r['segments'] / r['wall']:11,.0f} "
              f"{r['fast_lines'] / max(r['lines'], 1):10.1%} {r['peak_rss_mib']:7.0f} MiB")
    by = dict(rows)
    fast = by[f"generated CAM {a.lines:,} lines, fast path"]
    naive = by[f"generated CAM first {a.naive_lines:,} lines, full interpreter (naive)"]
    print(f"fast path vs full interpreter on the CAM program (lines/s, CPU): "
          f"{(fast['lines'] / fast['cpu']) / (naive['lines'] / naive['cpu']):.0f}x")
    full = [r for name, r in rows if name.startswith("NEEDS FULL")]
    print("programs that need the full interpreter (target 100,000 lines/s): "
          + ", ".join(f"{r['lines'] / r['cpu']:,.0f}" for r in full) + " lines/s (CPU)")
    if STELLABEE.is_file():
        f, n = by["stellabee1.ngc, fast path"], by["stellabee1.ngc, full interpreter (naive)"]
        print(f"fast path vs full interpreter on stellabee1.ngc (CPU): {n['cpu'] / f['cpu']:.0f}x")
    imports = [r["import_cpu"] for _name, r in rows]
    print(f"not in the figures above: importing the G-code modules, once per process, "
          f"{min(imports) * 1000:.0f}-{max(imports) * 1000:.0f} ms CPU (nczones.gcode and what interpret() imports "
          f"on first use; more where Python does not cache bytecode)")
    sm = by[f"generated CAM {a.small:,} lines, fast path"]
    print(f"peak RSS {sm['peak_rss_mib']:.0f} MiB at {a.small:,} lines, {fast['peak_rss_mib']:.0f} MiB at "
          f"{a.lines:,} lines (the program text itself is held: about 1 byte per character)")


if __name__ == "__main__":
    main()
