"""LinuxCNC's ``rs274`` against the double pass on G91 arcs and arcs in several planes (arc40, issue 36).

Drawn programs (:func:`program`) of G91 arcs (I/J and R, both ways, quarters of circles that close, helices),
G91 loops of them (a chain some hundreds of arcs long), far G91 moves out and back (a chain's error at large
magnitudes), G90 arcs from a G90 point on an open chain, G20 pieces, in G17, G18 and G19 in turn: ``rs274 -g``
runs each, the full path matches its log motion by motion (``tests.oracles.rs274.compare``), the pass takes the
program with rs274's motion ends as its rows (``tests.gcode.rs274_pass``), rs274's whole arcs lie in the pass's
quick and refined boxes on their own plane's axes (``check_pass_arcs``), and the routed verdict is the full
path's without the pass and the vectorized tier.  ``NCZONES_RS274_G91_ARCS_LONG`` programs (default 100) with
``pytest -m long``.
"""

from __future__ import annotations

import os
import random

import pytest

from tests.gcode.rs274_arc_programs import SETUP, in_plane
from tests.gcode.rs274_pass import NEEDS_RS274, assert_the_pass_is_rs274s_motion
from tests.gcode.test_rs274_double_arcs import _verdicts, check_pass_arcs
from tests.oracles.rs274 import compare
from tests.tools.rs274_diff import machine_of, run_rs274

pytestmark = NEEDS_RS274

LONG = int(os.environ.get("NCZONES_RS274_G91_ARCS_LONG", "100"))


def _quarters(rng: random.Random, r: str, scale: str = "") -> list[str]:
    """A circle of radius ``r`` in four G91 quarters (G17 letters), each by I/J or R, one direction; ``scale``: a
    factor written in the words (an expression of ``#1``, which is 1)."""
    g = rng.choice(("G2", "G3"))
    s = 1 if g == "G3" else -1  # G3 turns the start's vector from the centre u to w counter-clockwise
    rf = float(r)
    out = []
    for q in range(4):
        ux, uy = [(-1, 0), (0, -s), (1, 0), (0, s)][q]
        wx, wy = [(0, -s), (1, 0), (0, s), (-1, 0)][q]
        words = f"X{(wx - ux) * rf:.4f} Y{(wy - uy) * rf:.4f}"
        words += f" I{-ux * rf:.4f} J{-uy * rf:.4f}" if rng.random() < 0.5 else f" R{r}"
        if scale:
            words = " ".join(f"{w[0]}[{w[1:]}{scale}]" for w in words.split())
        if rng.random() < 0.15:
            words += f" Z{rng.choice(['0.1', '-0.1'])}"
        out.append(f"{g} {words}")
    return out


def program(seed: int) -> str:
    """A drawn program (module docstring)."""
    rng = random.Random(seed)
    lines = ["G21 G90 G17 G54 F300", "#1 = 1", "G0 X1 Y2 Z3"]
    label = 100
    for _ in range(rng.randint(8, 16)):
        plane = rng.choice([17, 17, 18, 19])
        kind = rng.random()
        r = f"{rng.uniform(0.2, 30):.3f}"
        if kind < 0.4:
            piece = ["G91", *_quarters(rng, r, " * #1" if rng.random() < 0.3 else "")]
        elif kind < 0.55:
            label += 1
            n = rng.randint(20, 80)
            piece = ["G91", "#2 = 0", f"o{label} while [#2 LT {n}]", *_quarters(rng, r), "#2 = [#2 + 1]",
                     f"o{label} endwhile"]
        elif kind < 0.7:
            far = rng.choice(["4000.3", "2500.7", "1234.567"])
            piece = ["G91 G1 X" + far, f"X-{far} Y0.3", "Y-0.3", *_quarters(rng, r)]
        elif kind < 0.85:  # a G90 arc from a G90 point (a chain of the normal axis may be open)
            x, y = (round(rng.uniform(-50, 50), 3) for _ in range(2))
            piece = ["G91 G1 Z0.1", f"G90 G1 X{x} Y{y}", f"G3 X{x + 4} Y{y} I2 J0", f"G2 X{x} Y{y} R2.5"]
        else:  # inches
            piece = ["G20 G91", *_quarters(rng, f"{rng.uniform(0.05, 1):.3f}"), "G21"]
        lines += [f"G{plane}"] + ([in_plane(x, plane) for x in piece] if plane != 17 else piece)
    return "\n".join([*lines, "G90 G0 X0 Y0 Z0", "M30"]) + "\n"


def differential(seed: int, tmp_path, monkeypatch, verdicts: bool = True) -> None:
    text = program(seed)
    path = assert_the_pass_is_rs274s_motion(text, SETUP, tmp_path)
    moves, error, _log = run_rs274(text, SETUP, tmp_path)
    machine = machine_of(SETUP)
    assert compare(text, machine, moves, error).status == "match"
    assert check_pass_arcs(path, moves) == path.arcs > 0
    if verdicts:
        _verdicts(text, machine, monkeypatch)


@pytest.mark.parametrize("seed", range(4))
def test_g91_arcs_in_three_planes_against_rs274(seed, tmp_path, monkeypatch):
    differential(seed, tmp_path, monkeypatch, verdicts=seed < 2)


def test_the_draw_has_chains_planes_and_inches():
    """The CI programs hold every piece: a loop of G91 arcs, far moves, G90 arcs, G20, G18 and G19."""
    texts = "".join(program(seed) for seed in range(4))
    for piece in ("while", "2500.7", "1234.567", "G20 G91", "G18", "G19", "R", "I", "G90 G1", "* #1"):
        assert piece in texts, piece


@pytest.mark.long
def test_g91_arcs_in_three_planes_against_rs274_long(tmp_path, monkeypatch):
    for seed in range(1000, 1000 + LONG):
        differential(seed, tmp_path, monkeypatch, verdicts=seed % 10 == 0)
