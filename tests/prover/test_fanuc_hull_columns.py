"""Fanuc cutting mode without ``path_tolerance`` on column chunks (issue 35/36, specs/path-modes.md §3).

A Fanuc control in cutting mode keeps the path in the hull of the run of motions between exact stops; nczones
proves the box of each run.  Column chunks (more than 512 motions) build the runs' boxes from the columns
(``CornerCheck._hull_columns``); the one-motion path (``CornerCheck._segment``, forced with
``blend.HULL_COLUMNS = False``) is the reference: on generated programs (lines, I/J and R arcs, G09, G61/G64,
dwells, a clamp near the path) both must give the same verdict and the same reasons, word for word.  The
mutation test shows the comparison is not vacuous: a column box that forgets an arc's bulge beyond its end
points (a box shrunk to the end points) disagrees.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings
from hypothesis import strategies as st

from nczones.machine import parse_machine
from nczones.prover import blend, fanucboxes, verify_text
from tests.machines import box_zone, machine_text


def _clamp_text(x0, y0, x1, y1) -> str:
    """The Fanuc mill of tests/machines/fanuc_xyz_table_60.toml with the forbidden box ``clamp`` (X and Y only)."""
    clamp = box_zone("clamp", {"X": str(x0), "Y": str(y0)}, {"X": str(x1), "Y": str(y1)}, forbid=True)
    return machine_text("fanuc_xyz_table_60", extra=clamp)


N_MOTIONS = 560  # more than 512 motions: the vectorized tier's column chunks


def _num(v: int) -> str:
    """Thousandths as a Fanuc length with a decimal point."""
    return f"{Fraction(v, 1000).numerator / Fraction(v, 1000).denominator:.3f}"


@st.composite
def programs(draw, stops: bool = False, dialect: str = "fanuc") -> str:
    """A random walk in X/Y (-40..40 mm) of lines, R arcs, I/J quarter arcs; ``stops``: with G09 blocks,
    G61/G64 switches and dwells among them (the Fanuc lane reads such programs one block at a time, no
    column chunks); ``dialect="linuxcnc"``: the same walk for LinuxCNC's reader, without stops (a dwell ends
    its column chunks too)."""
    seed = draw(st.integers(0, 2**32 - 1))
    p_g09 = draw(st.sampled_from([0.0, 0.05, 0.3])) if stops and dialect == "fanuc" else 0.0
    p_dwell = draw(st.sampled_from([0.0, 0.02, 0.1])) if stops and dialect == "fanuc" else 0.0
    p_mode = draw(st.sampled_from([0.0, 0.02, 0.1])) if stops and dialect == "fanuc" else 0.0
    import random

    rnd = random.Random(seed)
    out = ["%", "O1000", "G00 G17 G21 G40 G49 G80 G90", "G54 G00 X0. Y0.", "G01 F800."]
    if dialect != "fanuc":
        out = ["G17 G21 G90 G54", "G0 X0 Y0", "G1 F800"]
    x = y = 0  # thousandths
    motions = 0
    while motions < N_MOTIONS:
        u = rnd.random()
        if u < p_dwell:
            out.append("G04 X0.1" if dialect == "fanuc" else "G4 P0.1")
            continue
        if u < p_dwell + p_mode:
            out.append(rnd.choice(["G61", "G64"]))
            continue
        pre = "G09 " if rnd.random() < p_g09 else ""
        kind = rnd.random()
        if kind < 0.3:  # a line
            x1 = max(-40000, min(40000, x + rnd.randint(-6000, 6000)))
            y1 = max(-40000, min(40000, y + rnd.randint(-6000, 6000)))
            if (x1, y1) == (x, y):
                continue
            out.append(f"{pre}G01 X{_num(x1)} Y{_num(y1)}")
        elif kind < 0.65:  # an R arc: |R| at least half the chord (a negative R: the long way round)
            x1 = max(-35000, min(35000, x + rnd.randint(-5000, 5000)))
            y1 = max(-35000, min(35000, y + rnd.randint(-5000, 5000)))
            chord2 = (x1 - x) ** 2 + (y1 - y) ** 2
            if chord2 < 100**2:
                continue
            half = int(chord2**0.5 / 2) + 1
            r = rnd.randint(half, 3 * half)
            if rnd.random() < 0.15:
                r = -r
            out.append(f"{pre}G0{rnd.choice((2, 3))} X{_num(x1)} Y{_num(y1)} R{_num(r)}")
        else:  # an I/J quarter or half arc: the end exactly on the circle
            i, j = rnd.randint(-4000, 4000), rnd.randint(-4000, 4000)
            if (i, j) == (0, 0):
                continue
            cx, cy = x + i, y + j
            ux, uy = -i, -j  # start from the centre
            g = rnd.choice((2, 3))
            if rnd.random() < 0.2:
                ex, ey = -ux, -uy  # half a turn
            else:
                ex, ey = (-uy, ux) if g == 3 else (uy, -ux)  # a quarter turn in the arc's sense
            x1, y1 = cx + ex, cy + ey
            if max(abs(x1), abs(y1), abs(cx) + abs(i) + abs(j), abs(cy) + abs(i) + abs(j)) > 45000:
                continue
            out.append(f"{pre}G0{g} X{_num(x1)} Y{_num(y1)} I{_num(i)} J{_num(j)}")
        x, y = x1, y1
        motions += 1
    out += ["M30", "%"] if dialect == "fanuc" else ["M30"]
    return "\n".join(out) + "\n"


def _run(program: str, m, columns: bool, monkeypatch) -> tuple:
    monkeypatch.setattr(blend, "HULL_COLUMNS", columns)
    # the subject is today's column hull: a plain program of up to FANUC_BOX_LINES lines would otherwise be
    # answered by the numpy-free box route first (tests/prover/test_fanuc_box_arcs.py holds that route to this path)
    monkeypatch.setattr(fanucboxes, "ROUTE", False)
    r = verify_text(program, m)
    return r.verdict.label, [(x.code, x.message, x.span, x.block) for x in r.reasons]


def _agree(program: str, m, monkeypatch, need_columns: bool = True) -> tuple:
    calls = []
    real = blend.CornerCheck._hull_columns

    def spy(self, chunk, at):
        calls.append(len(chunk))
        return real(self, chunk, at)

    monkeypatch.setattr(blend.CornerCheck, "_hull_columns", spy)
    new = _run(program, m, True, monkeypatch)
    stopped = new[0] == "unsafe" and not calls  # the violation limit ended the stream before the column hull
    assert calls or not need_columns or stopped, "the program did not reach the column hull"
    old = _run(program, m, False, monkeypatch)
    assert new == old
    return new


# no shrinking: a failing program of 560 motions is printed whole (shrinking one takes minutes)
QUICK = settings(max_examples=4, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate],
                 suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])


@QUICK
@given(prog=programs(), clamp=st.tuples(st.integers(-40, 38), st.integers(-40, 38), st.integers(1, 6)))
def test_column_hull_agrees_with_the_one_motion_path(prog, clamp, monkeypatch):
    """End to end (``verify``): one run per program, the column chunks' runs."""
    x0, y0, size = clamp
    assume(not (x0 < 0 < x0 + size and y0 < 0 < y0 + size))  # a clamp over the start X0 Y0: ZN130, no machine
    m = parse_machine(_clamp_text(x0, y0, x0 + size, y0 + size))
    _agree(prog, m, monkeypatch)


@settings(QUICK, max_examples=3)
@given(prog=programs(stops=True), clamp=st.tuples(st.integers(-40, 38), st.integers(-40, 38), st.integers(1, 6)))
def test_programs_with_stops_agree_end_to_end(prog, clamp, monkeypatch):
    """G09, G61/G64 and dwells: the Fanuc lane declines the column chunks for them today; the verdicts agree
    whichever path they take."""
    x0, y0, size = clamp
    assume(not (x0 < 0 < x0 + size and y0 < 0 < y0 + size))  # a clamp over the start X0 Y0: ZN130, no machine
    m = parse_machine(_clamp_text(x0, y0, x0 + size, y0 + size))
    _agree(prog, m, monkeypatch, need_columns=False)


def _corner_run(chunks: list, m, modes: list, columns: bool, monkeypatch) -> tuple:
    monkeypatch.setattr(blend, "HULL_COLUMNS", columns)
    check = blend.CornerCheck(m, Fraction(0), (), modes)
    for _chunk in check.watch(chunks):
        pass
    reasons = check.finish()
    return [(r.code, r.message, r.span, r.block) for r in reasons], check.corners, len(reasons)


@settings(max_examples=8, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate],
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(prog=programs(stops=True, dialect="linuxcnc"), clamp=st.tuples(st.integers(-40, 38), st.integers(-40, 38),
                                                                      st.integers(1, 8)),
       stops=st.lists(st.tuples(st.integers(0, 700), st.integers(1, 30)), max_size=30))
def test_runs_between_stops_agree_on_column_chunks(prog, clamp, stops, monkeypatch):
    """Column chunks with exact-stop blocks: the motion of a LinuxCNC program (column chunks) proved under a
    Fanuc path-mode table with exact-stop blocks and G61 ranges
    (``(first block, length)``; length 1 is a G09 block): the same stretches, reasons and corner count."""
    from nczones.gcode import interpret_text
    from nczones.motion import MotionChunk, PathMode

    x0, y0, size = clamp
    assume(not (x0 < 0 < x0 + size and y0 < 0 < y0 + size))  # a clamp over the start X0 Y0: ZN130, no machine
    zones = _clamp_text(x0, y0, x0 + size, y0 + size)
    chunks = list(interpret_text(prog, parse_machine(zones.replace('dialect = "fanuc"', ""))))
    assert any(isinstance(c, MotionChunk) and c.scale is not None and len(c) > 100 for c in chunks)
    exact_stop = set()
    for first, n in stops:
        exact_stop.update(range(first, first + n))
    g64, g61 = PathMode(True, None, Fraction(0), "fanuc", "G64"), PathMode(False, None, Fraction(0), "fanuc", "G61")
    modes = [(0, g64)]
    for b in range(1, 800):
        if (b in exact_stop) != (not modes[-1][1].blend):
            modes.append((b, g61 if b in exact_stop else g64))
    m = parse_machine(zones)
    assert _corner_run(chunks, m, modes, True, monkeypatch) == _corner_run(chunks, m, modes, False, monkeypatch)


# One run of 600 half circles (column chunks): G02 X-10 Y0 -> X10 Y0 R10 (centre X0 Y0; clockwise from the left:
# over the top, up to Y10) and G02 back with R10 (under the bottom, down to Y-10).  Each run's hull box is
# X-10..10 Y-10..10; the lowest point Y-10 is the arcs' bulge, below both end points (Y0).  A clamp
# X-5..-4 Y-10.5..-9.9 is off the path (on the circle |X| >= 4 gives Y >= -sqrt(100 - 16) = -9.17) but inside
# the hull: unknown; a clamp X-1..1 Y-12..-10.5 is below the hull: safe.
CIRCLES = "\n".join(["%", "O1", "G00 G17 G21 G90 X-10. Y0.", "G01 F500."]
                    + ["G02 X10. Y0. R10.", "G02 X-10. Y0. R10."] * 300 + ["M30", "%"]) + "\n"


def _clamp_machine(x0: str, y0: str, x1: str, y1: str):
    return parse_machine(_clamp_text(x0, y0, x1, y1))


def test_a_run_of_r_arcs_whose_bulge_meets_a_clamp(monkeypatch):
    # the clamp inside the hull of each run (Y-10..10 from the lower half circles' bulge), off the path
    verdict, reasons = _agree(CIRCLES, _clamp_machine("-5", "-10.5", "-4", "-9.9"), monkeypatch)
    assert verdict == "unknown" and reasons and all(r[0] == blend.BLEND_CODE for r in reasons)
    assert "path_tolerance" in reasons[0][1] and "Y-10" in reasons[0][1]
    # below the bulge: every run's box fits
    assert _agree(CIRCLES, _clamp_machine("-1", "-12", "1", "-10.5"), monkeypatch)[0] == "safe"


def test_a_box_shrunk_to_the_end_points_is_caught(monkeypatch):
    """Mutation: a run's box that leaves out the arcs' bulge (the end points' box) proves the clamp safe, and
    the agreement check fails."""

    def shrunk(self, chunk, rows, cols):
        lo, hi, ends_lo, ends_hi, _arc = cols
        den = 10**chunk.scale
        return (tuple(Fraction(int(v), den) for v in ends_lo[rows].min(axis=0)),
                tuple(Fraction(int(v), den) for v in ends_hi[rows].max(axis=0)))

    monkeypatch.setattr(blend.CornerCheck, "_rows_box", shrunk)
    m = _clamp_machine("-5", "-10.5", "-4", "-9.9")
    # the mutant proves what the run's hull does not allow (the end points' box is Y0..0 on every arc)
    assert _run(CIRCLES, m, True, monkeypatch)[0] == "safe"
    assert _run(CIRCLES, m, False, monkeypatch)[0] == "unknown"
    with pytest.raises(AssertionError, match="assert \\("):
        _agree(CIRCLES, m, monkeypatch)
