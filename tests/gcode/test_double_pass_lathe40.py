"""The lathe row's speed-ups in the double pass (lathe40, issue 36): each must leave the pass's rows, boxes and
declines exactly as they were.

- the arcs' rows, boxes and words are gathered in lists and moved to the path's arrays in bulk
  (``_Pass.arc_flush``): every window's arcs are the same whatever the buffer's size, in arrays;
"""

from __future__ import annotations

import random
from array import array

import pytest

from nczones.gcode.linuxcnc import doubles
from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.machine import parse_machine
from tests.machines import machine_text

#: report_lathe (X diameters: G7 at the start; G54 X10 Z200; travel X 0..150, Z 0..400)
LATHE = parse_machine(machine_text("report_lathe"))


def lathe_text(n: int, seed: int) -> str:
    """``bench_gcode.lathe_program``'s lines (G7, G18): a G1 whose X is an expression, a quarter G3 by K and I, a
    G2 by R, in turn, ``#1`` stepped every 30th line; diameters 20..100, Z -100..0."""
    rnd = random.Random(seed)
    out = ["G18 G7 G21 G90 G54 F300", "#1 = 0", "G0 X100 Z5"]
    while len(out) < n - 1:
        if len(out) % 30 == 0:
            out.append(f"#1 = [#1 + {rnd.uniform(0, 0.01):.4f}]")
            continue
        d, z, r = (round(rnd.uniform(lo, hi), 3) for lo, hi in ((20, 100), (-100, 0), (0.5, 3)))
        out.append(f"G1 X[#1 + {d:.3f}] Z{z:.3f}")
        out.append(f"G3 X[#1 + {d + 2 * r:.3f}] Z{z - r:.3f} K{-r:.3f} I0")
        out.append(f"G2 X[#1 + {d + 4 * r:.3f}] Z{z - 2 * r:.3f} R{1.5 * r:.3f}")
    out.append("M30")
    return "\n".join(out) + "\n"


def _windows(text: str, machine, window: int) -> list[tuple]:
    """Every window the pass hands over (and its last path): rows, arcs' rows, boxes and words, as lists."""
    seen: list[tuple] = []

    def keep(path) -> bool:
        seen.append(_contents(path))
        return True

    seen.append(_contents(double_pass(text, machine, max_iterations=100, on_window=keep, window=window)))
    return seen


def _contents(path) -> tuple:
    assert all(isinstance(a, array) for a in (path.arc_rows, path.arc_boxes, path.arc_more[0]))
    assert all(type(v) is float for col in path.columns for v in col)
    return (path.row0, path.arcs, [list(c) for c in path.columns], list(path.arc_rows), list(path.arc_boxes),
            list(path.arc_more[0]))


@pytest.mark.parametrize("buffer", [1, 2, 7])
def test_the_arcs_moved_in_bulk_are_the_arcs_of_every_window(monkeypatch, buffer):
    text = lathe_text(400, 1)
    want = _windows(text, LATHE, 50)
    monkeypatch.setattr(doubles, "_ARC_BUFFER", buffer)
    got = _windows(text, LATHE, 50)
    assert got == want
    assert len(want) > 5 and all(w[3] for w in want)  # windows with arcs
    assert sum(len(w[3]) for w in want) > want[-1][1]  # the windows overlap: arcs handed over twice

