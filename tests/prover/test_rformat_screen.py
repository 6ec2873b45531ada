"""R-format arcs in columns (issue 36): the certified centre enclosure, the column screen, the fast path.

* The box the column screen forms for an R-format row (``nczones.prover.rformat``) holds the arc: its
  end points and, for every axis direction the exact sweep contains, the exact centre plus or minus |R|
  (the centre taken to 200 bits by :func:`nczones.prover.geometry.sqrt_bounds`, independently of the
  doubles the enclosure uses); and it is at most a few units of the scale looser where the directions
  are certain.
* A chunk of R-format rows verified through the screen gives the verdict and the violating blocks of the
  same segments decided one by one on the exact path (fewer than ``SCREEN_MIN_SEGMENTS``), also where a
  zone face is exactly at an arc's extreme (the enclosure touches it: the exact path decides).
* The fast path reads R words into the same segments as the full interpreter (planes G17/G18/G19,
  inches, negative R, half circles, helices), and ``verify`` of programs of more than 512 motions gives
  the verdict and violation lines derived by hand, equal to the exact path's, in both dialects and with
  ``#`` in the text (the full interpreter's segments, screened by ``segment_columns``).
"""

from __future__ import annotations

import random
from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.motion import MotionChunk, Plane, Segment, SegmentKind
from nczones.prover import Verdict, verify_segments, verify_text
from nczones.prover.geometry import arc_geom, in_sweep
from nczones.prover.screen import arc_boxes, screen_chunk

AXES3 = ("X", "Y", "Z")
PLANE_IDX = {Plane.XY: (0, 1), Plane.XZ: (2, 0), Plane.YZ: (1, 2)}


def rchunk(segs, scale, axes=AXES3):
    """Column chunk of R-format arc segments (centre None) at ``scale``."""
    den = 10**scale

    def ints(vals):
        out = [v * den for v in vals]
        assert all(x.denominator == 1 for x in out)
        return [int(x) for x in out]

    n = len(segs)
    return MotionChunk(
        axes, scale, kind=np.full(n, int(SegmentKind.ARC), dtype=np.int8),
        start=np.array([ints(s.start) for s in segs], dtype=np.int64).reshape(n, len(axes)),
        end=np.array([ints(s.end) for s in segs], dtype=np.int64).reshape(n, len(axes)),
        line=np.arange(1, n + 1, dtype=np.int64), block=np.array([s.block for s in segs], dtype=np.int64),
        tool_length=np.zeros(n, dtype=np.int64), centre=np.zeros((n, 2), dtype=np.int64),
        plane=np.array([int(s.plane) for s in segs], dtype=np.int8),
        clockwise=np.array([s.clockwise for s in segs], dtype=bool),
        turns=np.array([s.turns for s in segs], dtype=np.int32),
        radius=np.array([ints([s.radius])[0] for s in segs], dtype=np.int64))


@st.composite
def rarcs(draw, scale=3, block=0):
    """An R-format arc in a random plane: chord and |R| from tiny to huge, R negative (the long way), helical."""
    den = 10**scale
    plane = draw(st.sampled_from(list(Plane)))
    ia, ib = PLANE_IDX[plane]
    start = [F(draw(st.integers(-50 * den, 50 * den)), den) for _ in range(3)]
    end = list(start)
    mag = draw(st.sampled_from([3, 10**scale, 100 * den, 10**5 * den]))
    da, db = draw(st.integers(-mag, mag)), draw(st.integers(-mag, mag))
    if da == db == 0:
        da = 1
    end[ia] += F(da, den)
    end[ib] += F(db, den)
    normal = 3 - ia - ib
    if draw(st.booleans()):
        end[normal] += F(draw(st.integers(-5 * den, 5 * den)), den)  # a helix
    # |R| strictly above half the chord: half the chord rounded up, plus a tiny to a huge excess
    chord2 = da * da + db * db
    h = -(-int(chord2**0.5) // 2) + 1
    r = h + draw(st.sampled_from([0, 1, 7, mag, 50 * mag, 10**6]))
    r = F(r, den) * (-1 if draw(st.integers(0, 3)) == 0 else 1)
    seg = Segment(SegmentKind.ARC, tuple(start), tuple(end), AXES3, block=block, plane=plane,
                  clockwise=draw(st.booleans()), radius=r, turns=draw(st.sampled_from([0, 0, 0, 1])))  # P2: a lap more
    return seg  # (a square q gives a rational centre: still an R-format row in the columns)


def _exact_extremes(seg):
    """Per plane axis, (must_lo, must_hi): the exact arc reaches at least this far, derived from the
    centre to 200 bits and the exact sweep tests (directions too close to call are left out)."""
    g = arc_geom(seg)
    if g.centre is not None:
        (cal, cah), (cbl, cbh) = ((g.centre[0], g.centre[0]), (g.centre[1], g.centre[1]))
    else:
        (cal, cah), (cbl, cbh) = g.centre_bounds(200)
    r = abs(seg.radius)
    c = ((cal + cah) / 2, (cbl + cbh) / 2)
    u = (g.s[0] - c[0], g.s[1] - c[1])
    w = (g.e[0] - c[0], g.e[1] - c[1])
    eps = F(1, 2**100)
    if min(abs(x) for x in (*u, *w)) < eps:
        return None
    lo = [min(g.s[0], g.e[0]), min(g.s[1], g.e[1])]
    hi = [max(g.s[0], g.e[0]), max(g.s[1], g.e[1])]
    for v, axis, sgn in (((1, 0), 0, 1), ((-1, 0), 0, -1), ((0, 1), 1, 1), ((0, -1), 1, -1)):
        if in_sweep(u, w, (F(v[0]), F(v[1])), g.ccw, g.full):
            if sgn > 0:
                hi[axis] = max(hi[axis], (cal, cbl)[axis] + r)
            else:
                lo[axis] = min(lo[axis], (cah, cbh)[axis] - r)
    return g, lo, hi


@settings(max_examples=150, deadline=None, derandomize=True)
@given(st.lists(rarcs(), min_size=1, max_size=6))
def test_rformat_boxes_hold_the_exact_arc_and_are_tight(segs):
    scale = 3
    den = 10**scale
    ch = rchunk(segs, scale)
    lo = np.minimum(ch.start, ch.end)
    hi = np.maximum(ch.start, ch.end)
    ok = arc_boxes(ch, np.arange(len(segs)), lo, hi)
    assert ok.all()  # every generated arc is within the enclosure's magnitudes
    for i, s in enumerate(segs):
        got = _exact_extremes(s)
        if got is None:
            continue
        g, must_lo, must_hi = got
        for j, k in enumerate((g.ia, g.ib)):
            box_lo, box_hi = F(int(lo[i, k]), den), F(int(hi[i, k]), den)
            assert box_lo <= must_lo[j] and must_hi[j] <= box_hi
        for k in range(3):
            if k not in (g.ia, g.ib):  # other axes (a helix): their start and end values
                assert (lo[i, k], hi[i, k]) == (min(ch.start[i, k], ch.end[i, k]), max(ch.start[i, k], ch.end[i, k]))


def test_rformat_box_is_tight_when_the_directions_are_certain():
    # G2 X2 Y0 R2 from 0 (G17): centre (1, -sqrt 3), a 60 degree arc above the chord; its box is exactly
    # [0, 2] x [0, 2 - sqrt 3 = 0.2679...]: at scale 3 the screen's box is [0, 2] x [0, 0.268]
    seg = Segment(SegmentKind.ARC, (F(0), F(0), F(0)), (F(2), F(0), F(0)), AXES3, plane=Plane.XY,
                  clockwise=True, radius=F(2))
    ch = rchunk([seg], 3)
    lo, hi = np.minimum(ch.start, ch.end), np.maximum(ch.start, ch.end)
    assert arc_boxes(ch, np.arange(1), lo, hi).all()
    assert lo[0].tolist() == [0, 0, 0] and hi[0].tolist() == [2000, 268, 0]
    # the long way (300 degrees) round the centre (1, +sqrt 3): X from 1 - 2 to 1 + 2, Y down to 0
    long_way = Segment(SegmentKind.ARC, (F(0), F(0), F(0)), (F(2), F(0), F(0)), AXES3, plane=Plane.XY,
                       clockwise=True, radius=F(-2))
    ch = rchunk([long_way], 3)
    lo, hi = np.minimum(ch.start, ch.end), np.maximum(ch.start, ch.end)
    assert arc_boxes(ch, np.arange(1), lo, hi).all()
    # 1 - 2 = -1, 1 + 2 = 3 (the enclosure of the centre's X = 1 is not a point: one unit looser at most),
    # sqrt 3 + 2 = 3.7320508...: rounded outwards at scale 3
    assert lo[0, 0] in (-1000, -1001) and lo[0, 1] == 0
    assert hi[0, 0] in (3000, 3001) and hi[0, 1] == 3733


def _machine(x_max: str, y_max: str, forbid: str | None = None, dialect: str = "linuxcnc"):
    """A travel box (and a forbidden clamp), built directly: the loader would refuse a reference position
    outside the zones, which these tests do not need."""
    from dataclasses import replace

    from nczones.zones import AllowedSet, BoxZone

    base = _parsed("1000", "1000", None, dialect)
    zones = [BoxZone("travel", (("X", F(-1000), F(x_max)), ("Y", F(-1000), F(y_max)), ("Z", F(-1000), F(1000))))]
    if forbid is not None:
        x0, y0, x1, y1 = (F(v) for v in forbid.split(","))
        zones.append(BoxZone("clamp", (("X", x0, x1), ("Y", y0, y1)), forbid=True))
    return replace(base, allowed=AllowedSet(tuple(zones), base.allowed.tool_axis))


def _parsed(x_max: str, y_max: str, forbid: str | None = None, dialect: str = "linuxcnc"):
    extra = "" if forbid is None else f"""
[[zones]]
name = "clamp"
kind = "box"
forbid = true
min = {{ X = "{forbid.split(',')[0]}", Y = "{forbid.split(',')[1]}" }}
max = {{ X = "{forbid.split(',')[2]}", Y = "{forbid.split(',')[3]}" }}
"""
    return parse_machine(f"""
[machine]
path_mode = "G61"  # exact path: this test is not about corner blending (tests/prover/test_blending.py is)
axes = ["X", "Y", "Z"]
dialect = "{dialect}"
[machine.rapid]
X = "1000"
Y = "1000"
Z = "1000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[[zones]]
name = "travel"
kind = "box"
min = {{ X = "-1000", Y = "-1000", Z = "-1000" }}
max = {{ X = "{x_max}", Y = "{y_max}", Z = "1000" }}
{extra}""")


@st.composite
def near_zone_arcs(draw):
    """R arcs in G17 at scale 2, among them 3-4-5 arcs (chord 8, |R| 5: the centre 3 off the chord's
    middle, rational) whose extreme is put exactly on a zone face."""
    out = []
    faces = []
    for i in range(draw(st.integers(1, 5))):
        s = (F(draw(st.integers(-500, 500)), 100), F(draw(st.integers(-500, 500)), 100), F(0))
        if draw(st.booleans()):
            # from s to s + (8, 0), R 5, G2: centre (s + 4, s - 3), top of the circle at s_y + 2
            e = (s[0] + 8, s[1], F(0))
            seg = Segment(SegmentKind.ARC, s, e, AXES3, block=i, plane=Plane.XY, clockwise=True, radius=F(5))
            faces.append(s[1] + 2)
        else:
            d = (F(draw(st.integers(-400, 400)), 100), F(draw(st.integers(-400, 400)), 100))
            if d == (0, 0):
                d = (F(1), F(0))
            e = (s[0] + d[0], s[1] + d[1], F(0))
            half = max(abs(d[0]), abs(d[1]))  # at least half the chord: |d| / 2 <= max(|dx|, |dy|)
            r = half + F(draw(st.integers(1, 800)), 100)
            seg = Segment(SegmentKind.ARC, s, e, AXES3, block=i, plane=Plane.XY, clockwise=draw(st.booleans()),
                          radius=r if draw(st.integers(0, 2)) else -r)
        out.append(seg)
    y_max = draw(st.sampled_from(faces)) if faces and draw(st.booleans()) else F(draw(st.integers(-300, 900)), 100)
    forbid = draw(st.one_of(st.none(), st.tuples(st.integers(-5, 5), st.integers(-5, 5))))
    return out, y_max, forbid


def _fmt(q: F) -> str:
    return str(q.numerator) if q.denominator == 1 else f"{float(q):.2f}" if (q * 100).denominator == 1 else str(float(q))


@settings(max_examples=15, deadline=None, derandomize=True)
@given(near_zone_arcs())
def test_screened_rformat_chunk_agrees_with_the_exact_path(case):
    segs, y_max, forbid = case
    box = None if forbid is None else f"{forbid[0]},{forbid[1]},{forbid[0] + 2},{forbid[1] + 2}"
    m = _machine("1000", _fmt(y_max), box)
    a = verify_segments([rchunk(segs, 2)], m)
    b = verify_segments(segs, m)  # fewer than SCREEN_MIN_SEGMENTS: one by one on the exact path
    assert a.verdict == b.verdict
    assert [v.block for v in a.violations] == [v.block for v in b.violations]


def test_an_extreme_exactly_on_the_face_is_left_to_the_exact_path():
    # G2 from (0, 0) to (8, 0) R5: centre (4, -3), the top of the arc at Y = -3 + 5 = 2 exactly; with the
    # face at Y = 2 the arc touches it (allowed), at Y = 1.99 it crosses it in block 0
    seg = Segment(SegmentKind.ARC, (F(0), F(0), F(0)), (F(8), F(0), F(0)), AXES3, plane=Plane.XY,
                  clockwise=True, radius=F(5))
    m = _machine("1000", "2")
    # a chord of exactly 2|R| given as an R-format segment (the interpreter gives it a centre): not enclosed,
    # the exact path's (it is the half circle above the chord, up to Y = 4: safe below Y 5, unsafe below Y 3)
    half = Segment(SegmentKind.ARC, (F(0), F(0), F(0)), (F(8), F(0), F(0)), AXES3, plane=Plane.XY,
                   clockwise=True, radius=F(4))
    assert screen_chunk(rchunk([half], 2), _prover(_machine("1000", "5"))) == [0]
    assert verify_segments([rchunk([half], 2)], _machine("1000", "5")).verdict is Verdict.SAFE
    assert verify_segments([rchunk([half], 2)], _machine("1000", "3")).verdict is Verdict.UNSAFE
    assert screen_chunk(rchunk([seg], 2), _prover(m)) == [0]  # the enclosure touches the face
    assert verify_segments([rchunk([seg], 2)], m).verdict is Verdict.SAFE
    r = verify_segments([rchunk([seg], 2)], _machine("1000", "1.99"))
    assert r.verdict is Verdict.UNSAFE and [v.block for v in r.violations] == [0]


def _prover(m):
    from nczones.prover import Prover

    return Prover(m)


# --------------------------------------------------------------------------- programs

def rarc_text(n: int, seed: int, plane: int = 17, inch: bool = False, fanuc: bool = False, hashes: bool = False,
              helix: bool = False) -> str:
    """``n`` R-arc lines (some G2/G3 modal, about one in ten with a negative R, some exact half circles) in
    ``plane``; in G17, the arcs stay within X, Y of [-60, 60] + |R| ... (the exact path decides)."""
    rnd = random.Random(seed)
    a, b = {17: ("X", "Y"), 18: ("Z", "X"), 19: ("Y", "Z")}[plane]
    pt = lambda v: f"{v:.3f}" if not fanuc else (f"{v:.3f}" if v != int(v) else f"{int(v)}.")  # noqa: E731
    head = ["%", "O1000"] if fanuc else []
    out = head + [f"G{plane} G{20 if inch else 21} G90 G54", f"G0 {a}0 {b}0", "G1 F500"]
    if hashes:
        out.append("#1 = 2")
    x = y = 0.0
    g = 0
    for i in range(n):
        x1 = round(min(max(x + rnd.uniform(-3, 3), -60), 60), 3)
        y1 = round(min(max(y + rnd.uniform(-3, 3), -60), 60), 3)
        if (x1, y1) == (x, y):
            continue
        word = "" if g and rnd.random() < 0.5 else f"G{rnd.choice((2, 3))} "
        if word:
            g = int(word[1])
        chord = ((x1 - x) ** 2 + (y1 - y) ** 2) ** 0.5
        if i % 17 == 5:  # an exact half circle: end = start + (2r, 0)
            x1, y1 = round(x + 2.5, 3), y
            r = 1.25
        else:
            r = round(chord / 2 * rnd.uniform(1.01, 3) + 0.002, 3)
        if rnd.random() < 0.1:
            r = -r
        zw = f" Z{pt(round(rnd.uniform(-2, 0), 3))}" if helix and plane == 17 else ""
        rtext = f"R[#1 * {r / 2:.4f}]" if hashes and i % 50 == 7 else f"R{pt(r)}"
        out.append(f"{word}{a}{pt(x1)} {b}{pt(y1)}{zw} {rtext}")
        x, y = x1, y1
    out += ["M30", "%"] if fanuc else ["M30"]
    return "\n".join(out) + "\n"


def _key(s):
    return (s.kind, s.start, s.end, s.block, s.line, s.plane, s.clockwise, s.centre, s.radius, s.turns,
            s.tool_length, s.feed_mm_min)


def _segments(text, m, fast):
    return [_key(s) for ch in interpret_text(text, m, fast=fast) for s in ch.segments()]


@pytest.mark.parametrize("plane,inch,helix", [(17, False, False), (18, False, False), (19, False, False),
                                                (17, True, False), (17, False, True)])
def test_fast_path_reads_r_arcs_as_the_full_interpreter(plane, inch, helix):
    m = _machine("1000", "1000")
    text = rarc_text(300, seed=plane + inch, plane=plane, inch=inch, helix=helix)
    run = interpret_text(text, m)
    fast = [s for ch in run for s in ch.segments()]
    assert run.fast_lines > 250  # the R lines went through the fast path (none before issue 36)
    assert [_key(s) for s in fast] == _segments(text, m, False)
    assert any(s.centre is None and s.radius is not None and s.radius < 0 for s in fast)
    assert any(s.centre is not None for s in fast)  # the half circles: the chord's midpoint


def test_fanuc_fast_path_reads_r_arcs_as_the_full_interpreter():
    m = _machine("1000", "1000", dialect="fanuc")
    text = rarc_text(300, seed=5, fanuc=True)
    run = interpret_text(text, m)
    fast = [_key(s) for ch in run for s in ch.segments()]
    assert run.fast_lines > 250
    assert fast == _segments(text, m, False)


def _bump_program(n: int, hashes: bool = False, fanuc: bool = False) -> str:
    """``n`` arcs along X between Y = 0 and the face Y = 1.35: G2 X+10 Y0 R10 bulges to
    Y = 10 - sqrt(75) = 1.3397... (0.01 below the face); every 97th arc is R-10, the long way round the
    centre (5, +8.66): up to Y = 18.66, far above it."""
    pt = (lambda v: f"{v}.") if fanuc else str
    out = (["%", "O1000"] if fanuc else []) + ["G17 G21 G90 G54", "G0 X0 Y0", "G1 F500"]
    if hashes:
        out.append("#1 = 10")
    for i in range(n):
        r = "-10" if i % 97 == 50 else "10"
        rw = "R[#1]" if hashes and i % 7 == 3 and r == "10" else f"R{pt(r)}"
        out.append(f"G2 X{pt(10 * (i + 1))} Y0 {rw}")
    out += ["M30", "%"] if fanuc else ["M30"]
    return "\n".join(out) + "\n"


@pytest.mark.parametrize("hashes,fanuc", [(False, False), (True, False), (False, True)])
def test_verify_r_arc_program_over_512_motions(hashes, fanuc, monkeypatch):
    from nczones.prover import core

    text = _bump_program(600, hashes=hashes, fanuc=fanuc)
    m = _machine("100000", "1.35", dialect="fanuc" if fanuc else "linuxcnc")
    r = verify_text(text, m, max_violations=100)
    first = 5 if fanuc else 4 if hashes else 3  # lines before the first arc (%, O1000; #1 = 10)
    expected = [first + 1 + i for i in range(600) if i % 97 == 50]  # the long-way arcs
    assert r.verdict is Verdict.UNSAFE
    assert [v.line for v in r.violations] == expected
    # every safe R arc was proved by the column screen (before issue 36: each one by one on the exact path)
    assert r.profile["motions_screened_vectorized"] == 600 - len(expected) + 1  # (and the G0)
    safe = verify_text(text.replace("R-10", "R10"), m)  # every arc the short way: 0.01 below the face
    assert safe.verdict is Verdict.SAFE  # (LinuxCNC: by the double pass, which follows R arcs since issue 36)
    with monkeypatch.context() as without_pass:  # the column screen proves them too
        without_pass.setattr("nczones.pipeline.verification.double_pass_result", lambda *args, **kwargs: None)
        without_pass.setattr("nczones.prover.fanucboxes.ROUTE", False)  # (Fanuc: the numpy-free box route first)
        safe = verify_text(text.replace("R-10", "R10"), m)
    assert safe.verdict is Verdict.SAFE and safe.profile["motions_screened_vectorized"] == 601
    if hashes or fanuc:
        return  # (the exact path's verdict is held to the same derivation once, below)
    # the exact path: the full interpreter and every motion one by one
    from nczones import prover as prover_api

    monkeypatch.setattr(core, "SCREEN_MIN_SEGMENTS", 10**9)
    monkeypatch.setattr(prover_api, "FAST_PATH_MIN_LINES", 10**9)
    exact = verify_text(text, m, max_violations=100)
    assert exact.verdict is r.verdict and [v.line for v in exact.violations] == expected


def test_ij_rows_beside_r_rows_keep_their_own_scale():
    # a whole-millimetre chunk (scale 0) holding an R row is screened at 1e-6 mm; its I/J arc of radius
    # 5000 mm (5e9 units there: its square would leave int64) is boxed at scale 0 and scaled up, so both
    # rows are proved by the screen against a 20 m box
    ij = Segment(SegmentKind.ARC, (F(5000), F(0), F(0)), (F(0), F(5000), F(0)), AXES3, block=0, plane=Plane.XY,
                 centre=(F(0), F(0)))
    r = Segment(SegmentKind.ARC, (F(0), F(0), F(0)), (F(8), F(0), F(0)), AXES3, block=1, plane=Plane.XY,
                clockwise=True, radius=F(5))
    ch = rchunk([r, r], 0)
    ch = MotionChunk(AXES3, 0, kind=ch.kind, start=np.array([[5000, 0, 0], [0, 0, 0]]),
                     end=np.array([[0, 5000, 0], [8, 0, 0]]), line=ch.line, block=np.array([0, 1]),
                     tool_length=ch.tool_length, centre=np.array([[0, 0], [0, 0]]), plane=ch.plane,
                     clockwise=np.array([False, True]), turns=ch.turns, radius=np.array([0, 5]))
    assert [s.centre for s in ch.segments()] == [ij.centre, None]
    assert screen_chunk(ch, _prover(_machine("10000", "10000"))) == []
    # the top of the R arc is Y = 2 exactly (centre (4, -3)): at 1.999999 it is flagged, and found unsafe
    assert screen_chunk(ch, _prover(_machine("10000", "1.999999"))) == [0, 1]  # (the I/J arc reaches Y 5000)
    got = verify_segments([ch], _machine("10000", "5000"))
    assert got.verdict is Verdict.SAFE and got.profile["motions_screened_vectorized"] == 2


def test_segment_columns_take_r_arcs_exactly():
    # the full interpreter's segments (programs with '#'): R arcs go into the arc chunk with their signed R,
    # and the chunk's rows read back as the same segments (centre None, the radius as written)
    from nczones.prover.screen import segment_columns

    segs = [Segment(SegmentKind.ARC, (F(0), F(0), F(0)), (F(2), F(0), F("-0.5")), AXES3, block=0, plane=Plane.XY,
                    clockwise=True, radius=F("-2.125")),
            Segment(SegmentKind.LINE, (F(2), F(0), F("-0.5")), (F(3), F(1), F(0)), AXES3, block=1),
            Segment(SegmentKind.ARC, (F(3), F(1), F(0)), (F(1), F(1), F(0)), AXES3, block=2, plane=Plane.XY,
                    centre=(F(2), F(1)))]
    cols = segment_columns(segs, _prover(_machine("1000", "1000")))
    arcs = [(c, rows) for c, rows in cols if c.radius is not None]
    assert len(arcs) == 1 and arcs[0][1] == [0, 2]
    back = list(arcs[0][0].segments())
    assert [(s.centre, s.radius, s.start, s.end, s.clockwise) for s in back] == \
        [(s.centre, s.radius, s.start, s.end, s.clockwise) for s in (segs[0], segs[2])]


@pytest.mark.skipif(__import__("shutil").which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
@pytest.mark.parametrize("plane", [17, 18, 19])
def test_fast_path_r_arcs_match_rs274(plane, tmp_path):
    # rs274 -g prints every ARC_FEED with its centre (4 decimals): the fast path's R arcs (signed R, no centre)
    # have the centre of the exact geometry within the log's rounding, their end points and directions match
    # (tests/oracles/rs274.py compares the rest of the motion)
    import math

    from nczones.prover.geometry import arc_geom
    from tests.tools.rs274_diff import machine_of, outcome, run_rs274

    setup = (("X", "Y", "Z"), {}, {})
    text = rarc_text(200, seed=40 + plane, plane=plane)
    assert outcome(text, setup, tmp_path).status == "match"
    moves, error, _log = run_rs274(text, setup, tmp_path)
    assert error is None
    run = interpret_text(text, machine_of(setup))
    segs = [s for ch in run for s in ch.segments()]
    assert run.fast_lines > 150
    arcs = [s for s in segs if s.kind is SegmentKind.ARC]
    logged = [m for m in moves if m.kind == "ARC"]
    assert len(arcs) == len(logged) > 150
    n_r = 0
    for s, mv in zip(arcs, logged):
        g = arc_geom(s)
        if g.centre is None:
            n_r += 1
            (al, ah), (bl, bh) = g.centre_bounds(64)
            centre = ((al + ah) / 2, (bl + bh) / 2)
        else:
            centre = g.centre
        for c, x in zip(centre, mv.centre):
            assert math.isclose(float(c), float(x), abs_tol=float(mv.tol) * 2 + 1e-9)
    assert n_r > 100


@st.composite
def plane_arcs(draw):
    """R arcs in G17/G18/G19 at scale 2, some helical, among them 3-4-5 arcs (chord 8 along the plane's first
    axis, |R| 5, G2: the top of the circle, 2 above the chord, on the arc) whose top is a candidate face."""
    out, faces = [], {0: [], 1: [], 2: []}
    for i in range(draw(st.integers(1, 4))):
        plane = draw(st.sampled_from(list(Plane)))
        ia, ib = PLANE_IDX[plane]
        start = [F(draw(st.integers(-300, 300)), 100) for _ in range(3)]
        end = list(start)
        if draw(st.booleans()):
            end[ia] += 8
            r, cw = F(5), True
            faces[ib].append(start[ib] + 2)
        else:
            da, db = F(draw(st.integers(-400, 400)), 100), F(draw(st.integers(-400, 400)), 100)
            if da == db == 0:
                da = F(1)
            end[ia] += da
            end[ib] += db
            r = max(abs(da), abs(db)) + F(draw(st.integers(1, 500)), 100)
            r, cw = (r if draw(st.integers(0, 2)) else -r), draw(st.booleans())
        if draw(st.booleans()):
            end[3 - ia - ib] += F(draw(st.integers(-200, 200)), 100)  # a helix
        out.append(Segment(SegmentKind.ARC, tuple(start), tuple(end), AXES3, block=i, plane=plane, clockwise=cw,
                           radius=r))
    maxes = []
    for k in range(3):
        pick = faces[k] and draw(st.booleans())
        maxes.append(draw(st.sampled_from(faces[k])) if pick else F(draw(st.integers(0, 900)), 100))
    return out, maxes


@settings(max_examples=6, deadline=None, derandomize=True)
@given(plane_arcs())
def test_screened_rformat_chunk_agrees_in_every_plane_and_on_helices(case):
    _agrees_in_every_plane(case)


@pytest.mark.long
@settings(max_examples=200, deadline=None, derandomize=True)
@given(plane_arcs())
def test_screened_rformat_chunk_agrees_in_every_plane_and_on_helices_long(case):
    _agrees_in_every_plane(case)


def _agrees_in_every_plane(case):
    from dataclasses import replace

    from nczones.zones import AllowedSet, BoxZone

    segs, maxes = case
    base = _machine("1000", "1000")
    m = replace(base, allowed=AllowedSet((BoxZone("travel", tuple((a, F(-1000), hi) for a, hi in zip(AXES3, maxes))),),
                                         base.allowed.tool_axis))
    a = verify_segments([rchunk(segs, 2)], m)
    b = verify_segments(segs, m)  # the exact path, one by one
    assert a.verdict == b.verdict
    assert [v.block for v in a.violations] == [v.block for v in b.violations]
