"""A Fanuc mill's cutting-mode runs: a tip probe inside a run's convex hull, at a tool length of the run, is never
proved ``safe`` (hunt36).

A Fanuc control in cutting mode (G64) without ``path_tolerance`` keeps the path inside the convex hull of the
motions since the last exact stop (specs/path-modes.md §3) and may reach any point of it; a tip zone sees the
machine point less the tool length, tested at the length of each motion of the run (as a LinuxCNC corner is at
both its motions' lengths).  The generator writes runs of G00/G01, Z moves, ``G43 H1``/``G43 H2``/``G49`` with a
Z move, G91 moves, an M98 call, a dwell, G09, G61/G64, plain or inside a WHILE loop run twice, after 600 looped
motions (the column runs of issue 36) or none.  The oracle is the interpreter's own motion and mode table (not
the prover): the runs are cut after each dwell and after each motion whose mode does not blend; a probe of
1 mm is put around a random convex combination of one run's end points, at one of its motions' tool lengths.
The point is on the machine's path model, so ``safe`` is wrong whatever the probe's size.  Before the fix of
``CornerCheck._stretch_tl`` two of 300 such programs were ``safe`` (a G43/G49 inside the run).
"""

from __future__ import annotations

import random
from fractions import Fraction
from unittest import mock

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.motion import SegmentKind
from nczones.prover import verify_text
from tests.gcode.fanuc.helpers import MILL

HULL_EXAMPLES = {"ci": 12, "long": 3_000}
OUTCOMES: dict[str, int] = {}


def _machine(probe: tuple[str, ...] | None):
    zones = ('\n[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             'max = { X = "1000", Y = "1000", Z = "1000" }\n')
    if probe is not None:
        zones += ('[[zones]]\nname = "probe"\nkind = "box"\nforbid = true\npoint = "tip"\n'
                  'min = {{ X = "{}", Y = "{}", Z = "{}" }}\nmax = {{ X = "{}", Y = "{}", Z = "{}" }}\n'.format(*probe))
    return parse_machine(MILL.replace("{fanuc_extra}", "").replace("{tables}", zones), "mill.toml")


def _statement(rnd: random.Random) -> str:
    k = rnd.randrange(10)
    x, y, z = rnd.randint(-40, 40), rnd.randint(-40, 40), rnd.randint(-30, 0)
    if k < 4:
        return f"G01 X{x}. Y{y}."
    if k == 4:
        return f"G01 Z{z}."
    if k == 5:
        return rnd.choice(["G43 H1", "G43 H2", "G49"]) + f" Z{z}."
    if k == 6:
        return rnd.choice(["G04 X0", f"G09 G01 X{x}.", "G61", "G64"])
    if k == 7:
        return f"G00 X{x}. Y{y}."
    if k == 8:
        return "M98 P100"
    return f"G91 G01 X{rnd.randint(-5, 5)}. G90"


def program(rnd: random.Random) -> str:
    body = [_statement(rnd) for _ in range(rnd.randint(2, 10))]
    pad = rnd.choice([0, 0, 600])
    lines = ["O1", "G90 G17 G21 G54 G49 G64 F500.", "G00 X0. Y0. Z0."]
    if pad:
        lines += ["#1 = 0", f"WHILE [#1 LT {pad // 2}] DO1", "G01 X[#1 MOD 3] Y1.", "G01 Y2.", "#1 = #1 + 1",
                  "END1", "G04 X0"]
    if rnd.random() < 0.5:
        lines += ["#2 = 0", "WHILE [#2 LT 2] DO2", *body, "#2 = #2 + 1", "END2"]
    else:
        lines += body
    lines += ["G04 X0", "M30", "O100", f"G01 X{rnd.randint(-40, 40)}. Y{rnd.randint(-40, 40)}.", "M99"]
    return "\n".join(lines) + "\n"


def runs(text: str) -> list[list]:
    """The interpreter's motions cut into runs: after a dwell (not in the run) and after a motion whose mode does
    not blend (in the run)."""
    interp = interpret_text(text, _machine(None))
    segs = list(interp.segments())
    assert not interp.unsupported, interp.unsupported
    table = interp.interpreter.path_modes
    out: list[list] = [[]]
    for s in segs:
        if s.kind is SegmentKind.DWELL:
            out.append([])
            continue
        out[-1].append(s)
        if not [m for first, m in table if first <= s.block][-1].blend:
            out.append([])
    return [r for r in out if r]


def _examples() -> int:
    return HULL_EXAMPLES["long" if settings.default.max_examples > 100 else "ci"]


def test_a_probe_in_a_runs_hull_is_never_safe():
    @settings(max_examples=_examples(), deadline=None)
    @given(st.randoms(use_true_random=False))
    def run(rnd):
        text = program(rnd)
        found = runs(text)
        chosen = rnd.choice([r for r in found if len(r) >= 2] or found)
        pts = [p for s in chosen for p in (s.start, s.end)]
        tl = rnd.choice(sorted({s.tool_length for s in chosen}))
        w = [Fraction(rnd.randint(0, 10)) for _ in pts]
        w[0] += 1
        c = [sum(wi * p[i] for wi, p in zip(w, pts)) / sum(w) for i in range(3)]
        c[2] -= tl  # the tip at that length
        half = Fraction(1, 2)
        probe = tuple(f"{float(v):.3f}" for v in (c[0] - half, c[1] - half, c[2] - half, c[0] + half, c[1] + half,
                                                     c[2] + half))
        assume(not all(abs(v) < 1 for v in c))  # the start (the reference, machine 0 0 0) outside the probe
        label = verify_text(text, _machine(probe)).verdict.label
        OUTCOMES[label] = OUTCOMES.get(label, 0) + 1
        assert label != "safe", f"a tip probe inside a run's hull (length {tl}) proved safe:\n{text}"

    run()


@pytest.mark.long
def test_fanuc_mill_hull_hunt_long():
    OUTCOMES.clear()
    with mock.patch.dict(HULL_EXAMPLES, {"ci": HULL_EXAMPLES["long"]}):
        test_a_probe_in_a_runs_hull_is_never_safe()
    print(f"fanuc mill hull hunt: {sorted(OUTCOMES.items())}")
