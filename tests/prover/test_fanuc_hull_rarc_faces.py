"""Fanuc cutting mode on column chunks: runs of R arcs whose box touches a zone face (issue 36).

The column hull (``CornerCheck._hull_columns``) takes each R arc's column box from the screen's sweep-aware
box (:func:`nczones.prover.rformat.rformat_boxes`) plus one unit, and boxes exactly (``_piece_box``) only the
arcs whose column box passes the run's end points.  That is the one-motion path's box only if every column box
holds the arc's exact box.  Here the face of a forbidden block is put at the run's extreme in one of the four
plane directions (found in floats from the arcs' geometry, independent of the prover), a little outside or a
little inside, or on it (to the thousandth): both lanes must give the same verdict and reasons word for word,
and the verdict the geometry gives: outside, ``safe``; inside, not ``safe`` (the block is in the run's hull; across
the other axis it covers a band the sampled path keeps out of, when there is one, so that only the hull, not
the path, meets it).  The arcs are minor and major R arcs of a random walk, so the extreme is sometimes an
arc's bulge, sometimes an end point.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import blend, fanucboxes, screen, verify_text
from tests.machines import box_zone, machine_text
from tests.sizes import examples

#: The functions the tests wrap (Hypothesis runs many examples under one function-scoped monkeypatch).
REAL_HULL = blend.CornerCheck._hull_columns
REAL_SHARED = screen.shared_arc_boxes
LONG = 560  # more than 512 motions: column chunks
SHORT = 40  # the one-chunk lanes


def _walk(seed: int, motions: int) -> tuple[str, list[tuple[float, float, float, float, float, bool]]]:
    """A Fanuc program of ``motions`` R arcs from X0 Y0 in one cutting-mode run (thousandths), and each arc
    as ``(sx, sy, ex, ey, R, clockwise)`` in mm."""
    rnd = random.Random(seed)
    out = ["%", "O1000", "G00 G17 G21 G40 G49 G80 G90", "G54 G00 X0. Y0.", "G01 F800."]
    arcs = []
    x = y = 0
    while len(arcs) < motions:
        x1 = max(-25000, min(25000, x + rnd.randint(-5000, 5000)))
        y1 = max(-25000, min(25000, y + rnd.randint(-5000, 5000)))
        chord2 = (x1 - x) ** 2 + (y1 - y) ** 2
        if chord2 < 200**2:
            continue
        half = math.isqrt(chord2) // 2 + 2  # |R| > half the chord: no half circle (its centre is rational)
        r = rnd.randint(half, 3 * half) * (-1 if rnd.random() < 0.15 else 1)
        g = rnd.choice((2, 3))
        out.append(f"G0{g} X{x1 / 1000:.3f} Y{y1 / 1000:.3f} R{r / 1000:.3f}")
        arcs.append((x / 1000, y / 1000, x1 / 1000, y1 / 1000, r / 1000, g == 2))
        x, y = x1, y1
    return "\n".join([*out, "M30", "%"]) + "\n", arcs


def _extremes(arc: tuple[float, float, float, float, float, bool]) -> tuple[float, float, float, float]:
    """``(min X, max X, min Y, max Y)`` of an R arc in floats: Fanuc's centre (G2 with R > 0 and G3 with R < 0:
    right of the chord, the less-than-half-turn arc for R > 0), then the circle's extreme in each axis direction
    the sweep passes, else the end points'."""
    sx, sy, ex, ey, r, cw = arc
    dx, dy = ex - sx, ey - sy
    d2 = dx * dx + dy * dy
    k = math.sqrt(r * r / d2 - 0.25) * (-1 if cw != (r < 0) else 1)
    cx, cy = (sx + ex) / 2 - k * dy, (sy + ey) / 2 + k * dx
    a0, a1 = math.atan2(sy - cy, sx - cx), math.atan2(ey - cy, ex - cx)
    lo, hi = (a1, a0) if cw else (a0, a1)  # the sweep counter-clockwise from lo to hi
    span = (hi - lo) % (2 * math.pi)

    def swept(angle: float) -> bool:
        return (angle - lo) % (2 * math.pi) <= span

    rad = abs(r)
    return (cx - rad if swept(math.pi) else min(sx, ex), cx + rad if swept(0.0) else max(sx, ex),
            cy - rad if swept(-math.pi / 2) else min(sy, ey), cy + rad if swept(math.pi / 2) else max(sy, ey))


def _points(arc: tuple[float, float, float, float, float, bool], n: int = 64) -> list[tuple[float, float]]:
    """``n + 1`` points along an R arc (floats)."""
    sx, sy, ex, ey, r, cw = arc
    dx, dy = ex - sx, ey - sy
    k = math.sqrt(r * r / (dx * dx + dy * dy) - 0.25) * (-1 if cw != (r < 0) else 1)
    cx, cy = (sx + ex) / 2 - k * dy, (sy + ey) / 2 + k * dx
    a0, a1 = math.atan2(sy - cy, sx - cx), math.atan2(ey - cy, ex - cx)
    span = ((a0 - a1) if cw else (a1 - a0)) % (2 * math.pi)
    step = -span / n if cw else span / n
    return [(cx + abs(r) * math.cos(a0 + i * step), cy + abs(r) * math.sin(a0 + i * step)) for i in range(n + 1)]


def _free_band(arcs: list, direction: int, face: float) -> tuple[int, int]:
    """A band ``[lo, lo + 2]`` (whole mm) of the other plane axis, inside the run's extent there, where no sampled
    point of the path comes within 0.5 mm of the block beyond ``face``, or the whole table (-59..59) when there
    is none."""
    axis = direction // 2
    sign = -1 if direction % 2 == 0 else 1
    points = [p for a in arcs for p in _points(a)]
    near = [p[1 - axis] for p in points if (p[axis] - face) * sign > -0.5]
    extent = [p[1 - axis] for p in points]
    for lo in range(math.ceil(min(extent)), math.floor(max(extent)) - 1):
        if all(v < lo - 0.5 or v > lo + 2.5 for v in near):
            return lo, lo + 2
    return -59, 59


def _machine(direction: int, face: Fraction, band: tuple[int, int]):
    """The Fanuc mill of fanuc_xyz_table_60 with a forbidden block 5 mm deep beyond ``face`` in ``direction``
    (0: -X, 1: +X, 2: -Y, 3: +Y), over ``band`` the other way."""
    axis = "XY"[direction // 2]
    other = "YX"[direction // 2]
    near, far = (face - 5, face) if direction % 2 == 0 else (face, face + 5)
    low = {axis: f"{float(near):.3f}", other: str(band[0])}  # thousandths: exact as decimals
    high = {axis: f"{float(far):.3f}", other: str(band[1])}
    return parse_machine(machine_text("fanuc_xyz_table_60", extra=box_zone("block", low, high, forbid=True)))


def _run(program: str, m, columns: bool, monkeypatch) -> tuple:
    monkeypatch.setattr(blend, "HULL_COLUMNS", columns)
    # the subject is today's column hull: a plain program of up to FANUC_BOX_LINES lines would otherwise be
    # answered by the numpy-free box route first (tests/prover/test_fanuc_box_arcs.py holds that route to this path)
    monkeypatch.setattr(fanucboxes, "ROUTE", False)
    r = verify_text(program, m)
    return r.verdict.label, [(x.code, x.message, x.span, x.block) for x in r.reasons]


def _case(seed: int, motions: int, direction: int, offset: int, monkeypatch, shared: bool = True) -> tuple:
    """Verify the walk of ``seed`` with the block's face ``offset`` thousandths outside the run's extreme in
    ``direction`` (rounded to thousandths), in both lanes; assert they agree; the verdict, reasons, and whether
    the face is outside the extreme (floats; None within 1e-7 mm).  ``shared``: the hull takes the screen's
    arc boxes (``screen.shared_arc_boxes``, checked to be used), else it boxes the arcs itself."""
    program, arcs = _walk(seed, motions)
    ext = [_extremes(a) for a in arcs] + [(0.0, 0.0, 0.0, 0.0)]  # the G00 to X0 Y0 ends where the run starts
    pick = min if direction % 2 == 0 else max
    extreme = pick(e[direction] for e in ext)
    outward = -1 if direction % 2 == 0 else 1
    face = Fraction(round(extreme * 1000), 1000) + Fraction(outward * offset, 1000)
    gap = (float(face) - extreme) * outward
    inside = gap < 0
    m = _machine(direction, face, _free_band(arcs, direction, float(face)) if inside else (-59, 59))
    calls = []

    def spy(self, chunk, at):
        calls.append(len(chunk))
        return REAL_HULL(self, chunk, at)

    monkeypatch.setattr(blend.CornerCheck, "_hull_columns", spy)
    taken = []

    def boxes(chunk):
        got = REAL_SHARED(chunk) if shared else None
        taken.append(got is not None)
        return got

    monkeypatch.setattr(screen, "shared_arc_boxes", boxes)
    new = _run(program, m, True, monkeypatch)
    assert bool(calls) == (motions > 512)  # the block is off the path or just inside it: no run of violations
    assert all(taken) == shared and (bool(taken) or motions <= 512)
    assert new == _run(program, m, False, monkeypatch)
    return (*new, None if abs(gap) < 1e-7 else not inside)


QUICK = settings(max_examples=4, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate],
                 suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])


@QUICK
@given(seed=st.integers(0, 2**32 - 1), direction=st.integers(0, 3), offset=st.sampled_from([-10, -1, 0, 1, 10]),
       shared=st.booleans())
def test_a_face_at_the_runs_extreme_agrees_with_the_one_motion_path(seed, direction, offset, shared, monkeypatch):
    verdict, _reasons, outside = _case(seed, LONG, direction, offset, monkeypatch, shared)
    assert outside is None or (verdict == "safe") == outside


@settings(QUICK, max_examples=6)
@given(seed=st.integers(0, 2**32 - 1), direction=st.integers(0, 3), offset=st.sampled_from([-10, -1, 0, 1, 10]))
def test_a_short_run_with_a_face_at_its_extreme(seed, direction, offset, monkeypatch):
    verdict, _reasons, outside = _case(seed, SHORT, direction, offset, monkeypatch)
    assert outside is None or (verdict == "safe") == outside


def test_column_boxes_shrunk_to_the_end_points_are_caught(monkeypatch):
    """Mutation: R arcs' column boxes that leave out the bulge make ``_rows_box`` stop before the arc that
    reaches the face; the column lane then proves the block ``safe`` while the arc enters it."""
    import numpy as np

    def shrunk(chunk, rows, lo, hi):
        lo[rows] = np.minimum(chunk.start[rows], chunk.end[rows])
        hi[rows] = np.maximum(chunk.start[rows], chunk.end[rows])

    monkeypatch.setattr(blend, "_one_unit_out", shrunk)
    found = 0
    for seed in range(6):
        try:
            _case(seed, LONG, seed % 4, -10, monkeypatch)
        except AssertionError:
            found += 1
    assert found >= 2


def _linuxcnc(program: str, tolerance: str) -> str:
    """The walk in LinuxCNC's words (the same R arcs: LinuxCNC puts the centre on the same side), blended with
    ``G64 P``."""
    body = [ln for ln in program.splitlines() if ln.startswith(("G02", "G03"))]
    return "\n".join(["G17 G21 G90 G54", "G0 X0 Y0", f"G64 P{tolerance}", "G1 F800", *body, "M2"]) + "\n"


@settings(QUICK, max_examples=examples(3, 6))
@given(seed=st.integers(0, 2**32 - 1), tolerance=st.sampled_from(["0.01", "0.5"]),
       clamp=st.tuples(st.integers(-50, 45), st.integers(-50, 45), st.integers(1, 6)))
def test_linuxcnc_corners_take_the_screens_boxes_with_the_same_result(seed, tolerance, clamp, monkeypatch):
    """LinuxCNC's blended corners on column chunks (``CornerCheck._corner_columns``) box the arcs next to a
    corner with the screen's boxes of the chunk (rounded outwards to its scale) or their own: the same verdict
    and reasons either way, end to end, and the shared boxes are taken."""
    program = _linuxcnc(_walk(seed, LONG)[0], tolerance)
    x0, y0, size = clamp
    block = box_zone("clamp", {"X": str(x0), "Y": str(y0)}, {"X": str(x0 + size), "Y": str(y0 + size)},
                     forbid=True)
    m = parse_machine(machine_text("fanuc_xyz_table_60", extra=block).replace('dialect = "fanuc"', ""))
    results = []
    for shared in (True, False):
        taken = []

        def boxes(chunk, shared=shared, taken=taken):
            got = REAL_SHARED(chunk) if shared else None
            taken.append(got is not None)
            return got

        monkeypatch.setattr(screen, "shared_arc_boxes", boxes)
        r = verify_text(program, m)
        results.append((r.verdict.label, [(x.code, x.message, x.span, x.block) for x in r.reasons]))
        # the corners of a chunk are proved after the screen's zone test, unless its violations end the run
        assert (taken or r.truncated) and all(taken) == (shared or not taken)
    assert results[0] == results[1]
