"""G64 Q without P: the corners proved a block of NAIVE_CHAIN at a time (issue 36, specs/path-modes.md §2).

``nczones.prover.blend._NaiveWindows.block_region`` gives one box for the corners after the motions of a block
of NAIVE_CHAIN; a corner is proved alone (its own windows, ``region``) only when that box does not fit.  The
block box must hold every corner's own region (else a block could pass a corner that its own test refuses):
checked here against regions computed independently from the motions, and by verdicts at a zone face (one pulse
in, one out) against the corner-by-corner method (``NAIVE_BLOCKS = False``).  Two mutations of the block box
(the block after dropped, the block before dropped) must change a verdict.
"""

from __future__ import annotations

import random
from decimal import Decimal
from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.motion import Segment, SegmentKind
from nczones.prover import blend as blend_module
from nczones.prover import verify_text
from tests.machines import box_zone, machine_text

N = blend_module.NAIVE_CHAIN
AXES = ("X", "Y", "Z")


# ------------------------------------------------------------------ the reference: a corner's own region
def _own_region(points, first, i, count, boxes=None):
    """The box of ``x + y - C`` for the corner after motion ``i`` (``points[k]``, ``points[k + 1]``: motion
    ``k``'s ends; the run's motions ``first .. count - 1``), with the windows of specs/path-modes.md §2.
    ``boxes``: :func:`_motion_boxes` of ``points``, when already made."""
    lo, hi = boxes or _motion_boxes(points)
    b0, b1, a0, a1 = max(first, i - N + 1), i + 1, i + 1, min(count, i + N + 1)
    c = points[i + 1]
    return (tuple(min(lo[a][b0:b1]) + min(lo[a][a0:a1]) - c[a] for a in range(3)),
            tuple(max(hi[a][b0:b1]) + max(hi[a][a0:a1]) - c[a] for a in range(3)))


def _motion_boxes(points):
    """Per axis, the low and high ends of each straight motion ``points[k]`` to ``points[k + 1]``."""
    return ([[min(p[a], q[a]) for p, q in zip(points, points[1:])] for a in range(3)],
            [[max(p[a], q[a]) for p, q in zip(points, points[1:])] for a in range(3)])


def _inside(inner, outer):
    return all(o <= x for x, o in zip(inner[0], outer[0])) and all(x <= o for x, o in zip(inner[1], outer[1]))


def _runs(steps, stops):
    """The points of a walk (``steps``: moves on X, Y, Z) and the motions after which a run stops."""
    pts = [(F(0), F(0), F(0))]
    for dx, dy, dz in steps:
        x, y, z = pts[-1]
        pts.append((x + F(dx, 4), y + F(dy, 4), z + F(dz, 8)))
    return pts, set(stops)


def _check_blocks(windows, pts, first, done, count, boxes):
    """Every waiting block whose forward windows are complete (or all, ``count`` None: the run ended): its box
    holds each of its corners' own regions (``pts``: the points times 8, integers).  Returns the next block to
    check."""
    end = windows.count
    while True:
        k = done
        if max(first, k * N) >= end - 1 or (count is not None and (k + 2) * N > end):
            return k
        box = windows.block_region(k)
        assert box is not None
        box = tuple(tuple(8 * v for v in side) for side in box)
        for i in range(max(first, k * N), min((k + 1) * N, end - 1)):
            assert _inside(_own_region(pts, first, i, end, boxes), box), (k, i)
        done += 1


#: a walk as legs of equal moves (a run that climbs faster in one block than in the next is where a block box
#: that missed a neighbour block would show), at most 420 moves
_LEGS = st.lists(st.tuples(st.integers(-8, 8), st.integers(-8, 8), st.integers(-2, 2), st.integers(1, 120)),
                 min_size=1, max_size=12).map(lambda legs: [leg[:3] for leg in legs for _ in range(leg[3])][:420])


@settings(max_examples=30, deadline=None)
@given(_LEGS, st.lists(st.integers(0, 420), max_size=3), st.integers(0, 150))
def test_a_block_box_holds_each_corner_region(steps, stops, lead):
    # ``lead`` motions before the first run (another mode): the run's blocks need not start at a block's start
    pts, stop_at = _runs(steps, stops)
    pts = [pts[0]] * lead + pts
    ints = [tuple(int(8 * v) for v in p) for p in pts]  # the reference in integers: quicker
    boxes = _motion_boxes(ints)
    w = blend_module._NaiveWindows()
    w.count = w.first = lead
    first, done = lead, lead // N
    for k in range(lead, len(pts) - 1):
        w.add(Segment(SegmentKind.LINE, pts[k], pts[k + 1], AXES))
        done = _check_blocks(w, ints, first, done, w.count, boxes)
        if k in stop_at:  # an exact stop: the run's last corners, then a new run
            _check_blocks(w, ints, first, done, None, boxes)
            w.restart()
            first, done = w.count, w.count // N
    _check_blocks(w, ints, first, done, None, boxes)


# ------------------------------------------------------------------ verdicts at a zone face
def _dec(v):
    """``v`` (a Fraction of at most three decimal places) as decimal text."""
    return f"{Decimal(F(v).numerator) / Decimal(F(v).denominator):f}"


def _machine(lo, hi):
    clamp = box_zone("clamp", {a: _dec(v) for a, v in lo.items()}, {a: _dec(v) for a, v in hi.items()}, forbid=True)
    return parse_machine(machine_text("xyz_table_200_naive_cam", extra=clamp))


def _program(pts, mode="G64 Q0.01", x0=0):
    body = "\n".join(f"G1 X{_dec(x)} Y{_dec(y)}" for x, y in pts)
    return f"G61\nG0 X{x0} Y0\n{mode}\nG1 F600 X{x0} Y0\n{body}\nG61\nG4 P0\n"


def _valley(h=5):
    """From X20 along X in steps of 0.1 with two peaks of height ``h``, for :func:`_program` with ``x0=20``
    (the rapid there is the run's motion 0, the first line motion 1): motion 99 ends at the first peak, motion
    100 comes down (block 0), block 1 (motions 101 .. 201) lies on Y0, motion 202 rises to the second peak (block
    2).  The corners of block 1 (in the valley, both peaks in their windows) reach Y ``2 h``, no other corner
    above ``h``."""
    return [(20 + F(i + 1, 10), F(h) if i in (98, 201) else F(0)) for i in range(343)]


def _verdicts(text, machine, blocks, monkeypatch):
    monkeypatch.setattr(blend_module, "NAIVE_BLOCKS", blocks)
    return verify_text(text, machine).verdict.label


@pytest.mark.parametrize("face", ["9.999", "10"])
def test_the_valley_at_a_zone_face(face, monkeypatch):
    text = _program(_valley(), x0=20)
    m = _machine({"X": -5, "Y": F(face)}, {"X": 150, "Y": 150})
    want = "unknown" if face == "9.999" else "safe"  # one pulse into Y 2h; touching it
    assert _verdicts(text, m, False, monkeypatch) == want
    assert _verdicts(text, m, True, monkeypatch) == want


def _mutated(shift):
    """block_region with the neighbour block ``k + shift`` read as block ``k`` itself (dropped)."""
    real = blend_module._NaiveWindows.block_region

    def block_region(self, k):
        saved = dict(self.blocks)
        if k + shift in self.blocks:
            self.blocks[k + shift] = self.blocks.get(k)
        try:
            return real(self, k)
        finally:
            self.blocks.clear()
            self.blocks.update(saved)

    return block_region


@pytest.mark.parametrize("shift", [1, -1])  # the block after dropped; the block before (a window a block short)
def test_a_dropped_neighbour_block_is_caught(shift, monkeypatch):
    text = _program(_valley(), x0=20)
    m = _machine({"X": -5, "Y": F("9.999")}, {"X": 150, "Y": 150})
    assert _verdicts(text, m, True, monkeypatch) == "unknown"
    monkeypatch.setattr(blend_module._NaiveWindows, "block_region", _mutated(shift))
    assert _verdicts(text, m, True, monkeypatch) == "safe", "the mutated block box must let the valley through"


def _walk(seed, n=330):
    rnd = random.Random(seed)
    pts, x, y = [], F(0), F(0)
    for _ in range(n):
        x, y = x + F(rnd.randint(-30, 40), 100), y + F(rnd.randint(-30, 40), 100)
        pts.append((x, y))
    return pts


@pytest.mark.parametrize("seed", [1, 2])
def test_random_walks_at_each_zone_face(seed, monkeypatch):
    # the zone's face one pulse beyond or inside the largest (smallest) corner region on an axis, computed from
    # the motions: the block method and the corner-by-corner one agree, and the verdict turns at the face
    pts = _walk(seed)
    text = _program(pts)
    xyz = [(F(0), F(0), F(0))] + [(x, y, F(0)) for x, y in pts]
    boxes = _motion_boxes(xyz)
    regions = [_own_region(xyz, 0, i, len(pts), boxes) for i in range(len(pts) - 1)]
    axis = seed % 2
    top = max(r[1][axis] for r in regions)
    name = AXES[axis]
    other = AXES[1 - axis]
    got = []
    for d in (F(-1, 1000), F(1, 1000)):
        m = _machine({name: top + d, other: -10}, {name: top + 20, other: 200})
        by_block, alone = _verdicts(text, m, True, monkeypatch), _verdicts(text, m, False, monkeypatch)
        assert by_block == alone, (d, by_block, alone)
        got.append(by_block)
    assert got == ["unknown", "safe"]
