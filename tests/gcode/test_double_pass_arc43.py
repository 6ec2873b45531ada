"""The R-arc row's per-arc cuts in the double pass (arc43, issue 36) leave every box and decline as it was.

- an R arc's plan runs ``double_arcs.r_screen``'s operations inline (``r_screen_code``): the code it emits is held
  bit for bit to ``r_screen`` (the same box, the same decline) on random arcs about the decline's boundary (the
  strategy of ``test_double_pass_r_screen``: near half circles, tiny chords, any magnitude), and a dropped term
  of the box's widening or of the decline's error is caught by the same comparison;
- the pass keeps one record an arc, its plane's slot the pass's (``arc_in`` moves the records first): the boxes
  of a program with R and I/J arcs in three planes, G91 chains and G20 are the reference screens' on its rows,
  and every window is the same whatever the buffer's size;
- a line of a layout met for the first time is stepped where it stands (``_Pass._straight``): the rows and arcs
  are those of the same lines run one at a time (a piece that is not ASCII has no layouts).
"""

from __future__ import annotations

import math
import random

import pytest
from hypothesis import given, settings

from nczones.gcode.linuxcnc import doubles
from nczones.gcode.linuxcnc.double_arcs import R_WHY, r_screen, r_screen_code
from nczones.gcode.linuxcnc.doubles import double_pass
from nczones.machine import parse_machine
from tests.gcode.test_double_pass import check_against_full
from tests.gcode.test_double_pass_lathe40 import _boxes, _windows, reference_boxes
from tests.gcode.test_double_pass_r_screen import arcs
from tests.machines import machine_text

BOX = parse_machine(machine_text("box_5000"))


def inline_screen(lines: list[str] | None = None):
    """A function of ``r_screen``'s arguments that runs ``r_screen_code``'s lines (or ``lines``, a mutant)."""
    if lines is None:
        lines = r_screen_code(("sx", "sy", "ex", "ey"), "r", "offb", "rel",
                              lambda *box: [f"return ({', '.join(box)})"], "return WHY")
    src = "def screen(sx, sy, ex, ey, r, offb, rel):\n" + "".join(f"    {b}\n" for b in lines)
    scope = {"WHY": R_WHY}
    exec(src, scope)  # noqa: S102  # the module's own emitted code
    return scope["screen"]


_SCREEN = inline_screen()


def _bits(value):
    return value if value.__class__ is str else tuple(v.hex() for v in value)


@settings(max_examples=400, deadline=None)
@given(arcs())
def test_the_inline_screen_is_r_screen_bit_for_bit(args):
    assert _bits(_SCREEN(*args)) == _bits(r_screen(*args)), args


def _sample(n: int = 3000) -> list[tuple]:
    """Arcs of every kind (deterministic): R of both signs, chords from tiny to past ``2|R|``, offsets' bounds."""
    rnd = random.Random(43)
    out = []
    for _ in range(n):
        scale = 10.0 ** rnd.randint(-3, 8)
        sx, sy = rnd.uniform(-1, 1) * scale, rnd.uniform(-1, 1) * scale
        r = rnd.choice([1.0, -1.0]) * scale * 10.0 ** -rnd.randint(0, 6) * rnd.uniform(0.5, 5)
        c = rnd.choice([rnd.uniform(0, 1.0001), 1 - 10.0 ** -rnd.randint(4, 15), rnd.uniform(0, 1e-9)])
        t = rnd.uniform(0, 6.3)
        chord = 2 * abs(r) * c
        out.append((sx, sy, sx + chord * math.cos(t), sy + chord * math.sin(t), r,
                    rnd.choice([0.0, 100.00000000000001, scale]), rnd.choice([2.0**-51, 2.0**-50])))
    return out


def test_the_sample_takes_and_declines_arcs_of_both_signs():
    got = [(a[4] > 0, _SCREEN(*a).__class__ is str) for a in _sample()]
    assert all(kind in got for kind in [(True, True), (True, False), (False, True), (False, False)])
    assert [_bits(_SCREEN(*a)) for a in _sample()] == [_bits(r_screen(*a)) for a in _sample()]


@pytest.mark.parametrize(("old", "new"), [
    ("r_w = r_l1 * 0.5 + r_err", "r_w = r_l1 * 0.5"),  # R > 0: the widening dropped
    ("r_w = 2.0 * r_ar + r_err", "r_w = 2.0 * r_ar"),  # R < 0
    (") + r_l1 + offb", ") + r_l1"),  # the offsets' bound in m
    ("r_x > 1e-09 * r_rr", "r_x > 1e-10 * r_rr"),  # the half circle's margin
])
def test_a_mutant_of_the_inline_screen_is_caught(old, new):
    lines = r_screen_code(("sx", "sy", "ex", "ey"), "r", "offb", "rel",
                          lambda *box: [f"return ({', '.join(box)})"], "return WHY")
    mutant = [b.replace(old, new) for b in lines]
    assert mutant != lines
    screen = inline_screen(mutant)
    assert any(_bits(screen(*a)) != _bits(r_screen(*a)) for a in _sample())


# -- the pass ----------------------------------------------------------------------------------------------------

def mixed_text(n: int, seed: int) -> str:
    """R arcs (G2/G3 and modal, R of both signs, radii far above the chords) and whole turns by I/J, G1 moves, in
    G17, G18 and G19, with G91 stretches and G20 ones."""
    rnd = random.Random(seed)
    out = ["G21 G90 G54 G17 F500", "G0 X0 Y0 Z0"]
    plane, arc = 17, False  # arc: the motion mode is G2 or G3 (a modal arc may follow)
    centre = {17: "IJ", 18: "KI", 19: "JK"}
    normal = {17: "Z", 18: "Y", 19: "X"}
    while len(out) < n:
        k = rnd.random()
        g = rnd.choice(["G2 ", "G3 ", ""] if arc else ["G2 ", "G3 "])
        if k < 0.04:
            plane = rnd.choice([17, 18, 19])
            out.append(f"G{plane}")
        elif k < 0.07:
            out.append(rnd.choice(["G91", "G90", "G20", "G21"]))
        elif k < 0.15:
            arc = False
            out.append(f"G1 X{rnd.uniform(-50, 50):.3f} Y{rnd.uniform(-50, 50):.3f} Z{rnd.uniform(-50, 50):.3f}")
        elif k < 0.25:  # a whole turn (a helix along the plane's normal)
            p, q = centre[plane]
            arc = True
            out.append(f"G{rnd.choice([2, 3])} {normal[plane]}{rnd.uniform(-5, 5):.3f} {p}{rnd.uniform(-5, 5):.3f} "
                       f"{q}{rnd.uniform(-5, 5):.3f}")
        else:
            r = rnd.uniform(2000, 4000) * rnd.choice([1, -1])
            arc = True
            out.append(f"{g}X{rnd.uniform(-5, 5):.3f} Y{rnd.uniform(-5, 5):.3f} Z{rnd.uniform(-5, 5):.3f} R{r:.4f}")
    out.append("M2")
    return "\n".join(out) + "\n"


def _cut_at_decline(text: str) -> str:
    """The lines of ``text`` before the first the pass declines (and an M2): a program the pass takes."""
    lines = text.splitlines()
    while True:
        try:
            double_pass("\n".join(lines) + "\n", BOX, max_iterations=100)
            return "\n".join(lines) + "\n"
        except doubles.Declined:
            lo, hi = 2, len(lines) - 1
            while lo < hi:  # the longest head the pass takes
                mid = (lo + hi + 1) // 2
                try:
                    double_pass("\n".join(lines[:mid] + ["M2"]) + "\n", BOX, max_iterations=100)
                    lo = mid
                except doubles.Declined:
                    hi = mid - 1
            lines = lines[:lo] + ["M2"]


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_pass_keeps_the_reference_screens_boxes_in_every_plane_and_mode(seed):
    text = _cut_at_decline(mixed_text(400, seed))
    path = double_pass(text, BOX, max_iterations=100)
    assert path.arcs > 40 and len(set(path.arc_planes)) > 1
    assert _boxes(path) == reference_boxes(path)


def test_the_pass_agrees_with_the_full_path_on_a_mixed_program():
    text = _cut_at_decline(mixed_text(150, 4))
    path = check_against_full(text, BOX)
    assert path is not None and path.arcs > 20


@pytest.mark.parametrize("buffer", [1, 3])
def test_every_window_is_the_same_whatever_the_buffer(monkeypatch, buffer):
    text = _cut_at_decline(mixed_text(300, 5))
    want = _windows(text, BOX, 40)
    planes = _planes(text, 40)
    monkeypatch.setattr(doubles, "_ARC_BUFFER", buffer)
    assert _windows(text, BOX, 40) == want
    assert _planes(text, 40) == planes
    assert len(want) > 5 and any(len(set(p)) > 1 for p in planes)


def _planes(text: str, window: int) -> list[list[int]]:
    """The plane slots of the arcs of every window the pass hands over (and of its last path)."""
    seen = []

    def keep(path) -> bool:
        seen.append(list(path.arc_planes))
        return True

    seen.append(list(double_pass(text, BOX, max_iterations=100, on_window=keep, window=window).arc_planes))
    return seen


def test_new_layouts_are_stepped_where_they_stand():
    text = _cut_at_decline(mixed_text(300, 6))
    path = double_pass(text, BOX, max_iterations=100)
    one_by_one = double_pass("(é)\n" + text, BOX, max_iterations=100)  # not ASCII: every line by _step
    assert [list(c) for c in path.columns] == [list(c) for c in one_by_one.columns]
    assert list(path.arc_boxes) == list(one_by_one.arc_boxes) and list(path.arc_rows) == list(one_by_one.arc_rows)
    assert list(path.arc_more[0]) == list(one_by_one.arc_more[0]) and path.arcs > 40
