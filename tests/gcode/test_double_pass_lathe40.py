"""The lathe row's speed-ups in the double pass (lathe40, issue 36): each must leave the pass's rows, boxes and
declines exactly as they were.

- the arcs' rows, boxes and words are gathered in lists and moved to the path's arrays in bulk
  (``_Pass.arc_flush``): every window's arcs are the same whatever the buffer's size, in arrays;
- the arcs' quick boxes: the pass's box of every arc is the reference screens' (``double_arcs.r_screen``, and
  ``_ij_screen_before``: ``ij_screen`` as it was, from ``ij_check``'s fourteen values) on the pass's rows, and
  ``ij_check(..., screen=True)`` is that reference on arcs of every kind (declined ones too);
- a block's own G0-G3 decides the tests of the motion mode when the plan is made (``doubles._mode_checks``): the
  same declines as the modal code's at run time, the same rapids.
"""

from __future__ import annotations

import random
from array import array

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import double_arcs, doubles
from nczones.gcode.linuxcnc.double_arcs import (
    CW,
    INCH,
    R_INCH_REL,
    R_SCREEN,
    TURN,
    inch_offb,
    inch_rule,
)
from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.machine import parse_machine
from tests.gcode.test_double_pass import check_against_full
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


# -- the arcs' quick boxes ---------------------------------------------------------------------------------------

def _ij_screen_before(sx, sy, ex, ey, i, j, cw, offb, tol, turn=False):
    """``double_arcs.ij_screen`` before lathe40: the box from :func:`ij_check`'s fourteen values."""
    got = double_arcs.ij_check(sx, sy, ex, ey, i, j, cw, offb, tol, turn)
    if got.__class__ is str:
        return got
    cx, cy, big, err = got[4], got[5], got[10], got[12]
    w = big + 2 * err
    return (cx - w, cx + w, cy - w, cy + w)


def reference_boxes(path) -> list[tuple]:
    """The quick box of every arc of ``path`` by the reference screens, from the pass's rows and words."""
    words, _offb, rule = path.arc_more
    out = []
    for k, row in enumerate(path.arc_rows):
        # (arc40: four words an arc, the last the offsets' bound it was computed with; its plane's axes)
        flag, p, q, offb = int(words[4 * k]), words[4 * k + 1], words[4 * k + 2], words[4 * k + 3]
        ia, ib = path.arc_pair(k)
        ca, cb = path.columns[ia], path.columns[ib]
        r = row - path.row0
        ends = (ca[r - 1], cb[r - 1], ca[r], cb[r])
        if flag & 3 == R_SCREEN:
            out.append(double_arcs.r_screen(*ends, p, offb, R_INCH_REL if flag & INCH else 2.0**-51))
        else:
            ob, ru = (inch_offb(offb, p, q), inch_rule(rule)) if flag & INCH else (offb, rule)
            out.append(_ij_screen_before(*ends, p, q, bool(flag & CW), ob, ru, bool(flag & TURN)))
    return out


def _boxes(path) -> list[tuple]:
    b = path.arc_boxes
    return [tuple(b[k:k + 4]) for k in range(0, len(b), 4)]


@pytest.mark.parametrize("seed", [1, 2])
def test_the_pass_keeps_the_reference_screens_boxes(seed):
    path = double_pass(lathe_text(600, seed), LATHE, max_iterations=100)
    assert path.arcs > 300
    assert _boxes(path) == reference_boxes(path)


def test_the_pass_keeps_the_reference_screens_boxes_on_the_full_paths_programs():
    text = ("G18 G21 G90 G54 F100\n#1 = 10\nG1 X[#1 * 2] Z5\nG8 X#1\nG7 G90 G1 X20 Z0\n"
            "G2 X15 Z-2.5 K-2.5 I0\nG3 X40 Z-5 R20\nG2 X40.5 Z-5.25 R-0.3\nG3 X41.5 Z-5.75 K-0.5 I0\nM30\n")
    path = check_against_full(text, LATHE)
    assert path is not None and path.arcs == 4
    assert _boxes(path) == reference_boxes(path)


_coord = st.one_of(st.floats(-500, 500, allow_nan=False), st.sampled_from([0.0, 1.0, -1.0, 2.5, 1e-3]))


@settings(max_examples=300, deadline=None, derandomize=True)
@given(_coord, _coord, _coord, _coord, _coord, _coord, st.booleans(), st.sampled_from([0.0, 5e-324, 200.0]),
       st.sampled_from([-1.0, -2.0, 0.0019999999999999996, 0.005]), st.booleans(), st.booleans())
def test_the_check_gives_the_reference_screen(sx, sy, i, j, ex, ey, cw, offb, tol, turn, on_circle):
    if on_circle:  # an end on the start's circle (the usual arc): turned about the centre
        cx, cy = sx + i, sy + j
        ex, ey = cx + (sy - cy) * (1 if cw else -1), cy - (sx - cx) * (1 if cw else -1)
    if turn:
        ex, ey = sx, sy
    got = double_arcs.ij_check(sx, sy, ex, ey, i, j, cw, offb, tol, turn, True)
    assert got == _ij_screen_before(sx, sy, ex, ey, i, j, cw, offb, tol, turn)
    assert double_arcs.ij_screen(sx, sy, ex, ey, i, j, cw, offb, tol, turn) == got


# -- the motion mode decided when the plan is made -----------------------------------------------------------------

_HEAD = "G18 G21 G90 G54\n#1 = 10\n"


@pytest.mark.parametrize("texts, why", [
    (["G1 X#1 Z0"], "G1 without a positive feed"),  # (no G1 block sets the mode without a feed)
    (["G2 X#1 Z0 R2"], "without a positive feed"),
    (["F100\nG2 X#1 Z0", "F100\nG1 X1 Z1\nG2 X2 Z0 R5\nX#1 Z0"], "an arc without I, J, K or R"),
    (["F100\nG3 X#1 Z0", "F100\nG1 X1 Z1\nG3 X2 Z0 R5\nX#1 Z0"], "an arc without I, J, K or R"),
    (["G0 X#1 Z0 R2", "G0 X1 Z1\nX#1 Z0 R2"], "I, J, K or R without G2 or G3"),
    (["F100\nG1 X#1 Z0 K1 I0", "F100\nG1 X1 Z1\nX#1 Z0 K1 I0"], "I, J, K or R without G2 or G3"),
])
def test_a_blocks_own_motion_code_declines_as_the_modal_one(texts, why):
    for text in texts:
        with pytest.raises(doubles.Declined, match=why):
            double_pass(f"{_HEAD}{text}\nM30\n", LATHE, max_iterations=10)


def test_a_blocks_own_motion_code_counts_as_the_modal_one():
    text = (_HEAD + "G0 X#1 Z5\nX[#1 * 2] Z4\nG1 X#1 Z3 F100\nG0 X[#1 + 1]\nG1 Z2\nG2 X[#1 + 2] Z1 R1\n"
            "G0 X[#1 + 3] Z0\nG3 X[#1 + 4] Z-0.5 K-0.5 I0\nG0 Z0\nM30\n")
    path = check_against_full(text, LATHE)  # the rows, arcs and rapids are the full path's
    assert path is not None and (path.rapids, path.arcs, path.lines) == (5, 2, 2)
