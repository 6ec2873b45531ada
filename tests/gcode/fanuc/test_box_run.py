"""The box route's run reader (nczones/gcode/fanuc/boxrun.py, issue 36) against the lanes it bypasses.

Relations (every side computed by nczones; the reader is an optimisation, so the reference is the program as
today's lanes read it):

* ``verify`` with the reader (``boxrun.BOX_RUNS``) and without it (the language layer and the plain lanes,
  ``FanucInterpreter.lane`` / ``_arc_lane``, writing the same ``BoxRows``) give the same verdict, violations,
  reasons, notes, counts (blocks, motions by kind) and stats;
* the box the route tests (every ``box_fits`` call: the box and the tool length) is the same, call for call, on
  this file's programs (not in general: a straight move whose letters the lane meets first is the general
  lane's segment and ends a chunk, which the reader puts in its run instead; there only the whole motion's
  box is the same, as test_reference_boxes.py compares it);
* without the route (``fanucboxes.ROUTE`` off: the full path, or the vectorized fast path past 512 lines) the
  verdict, violations, reasons, notes and motion count are the same;
* the reader does take the plain lines (counted), so the comparisons are not vacuous.

The generated programs mix what the reader takes (G0/G1/G2/G3 with decimal numbers, R and centre arcs in the
three planes, helices, N numbers, F, CR LF ends, blank lines) with what it hands back to the language layer
(lengths without a decimal point, more decimals than IS-B's three, inch input, G91 incremental moves, M and S
words, comments, dwell, lower case) in the middle of a run.  The test mill (tests/gcode/fanuc/helpers.py):
G54 = (100, 50, -200); its zone here machine X -10..150, Y -10..90, Z -201..0 (program X -110..50, Y -60..40,
Z -1..200); the generated programs run in a wide one (machine -2000..2000 on every axis), mostly ``safe``.

The default run draws fixed examples (``derandomize``: the same programs every run, as the other differential
tests here), :data:`EXAMPLES` for the lanes (``NCZONES_BOX_RUN_EXAMPLES``; above 200 the examples are drawn
anew); the hunts under ``-m long`` draw new ones each run (``NCZONES_BOX_RUN_HUNT`` examples, default 300).
"""

from __future__ import annotations

import math
import os
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.gcode.fanuc import boxrun
from tests.gcode.fanuc.helpers import BOX_ZONE, assert_state_handed_back, mill, probe_route

_MACHINE = mill(tables=BOX_ZONE)
#: examples of the default run (fixed when at most 200: the CI size) and of the long hunts (drawn anew)
EXAMPLES = int(os.environ.get("NCZONES_BOX_RUN_EXAMPLES", "40"))
HUNT = int(os.environ.get("NCZONES_BOX_RUN_HUNT", "300"))
_FIXED = EXAMPLES <= 200
#: a zone the generated programs mostly stay in (a program that leaves it costs a witness search on each side)
_WIDE = mill(tables=BOX_ZONE.replace('"-10"', '"-2000"').replace('"-201"', '"-2000"').replace('"150"', '"2000"')
             .replace('"90"', '"2000"').replace('Z = "0"', 'Z = "2000"'))
#: vectors of length 5 (exact: an I/J arc's start and end on one circle)
_FIVE = [(3, 4), (4, 3), (5, 0), (0, 5), (-3, 4), (-4, -3), (0, -5), (-5, 0), (3, -4), (4, -3)]
_PLANES = {17: ("X", "Y", "I", "J"), 18: ("Z", "X", "K", "I"), 19: ("Y", "Z", "J", "K")}
#: lines the reader hands back (the language layer reads them; the reader takes the next line again)
_LEAVE = ["M08", "(A COMMENT)", "G04 X0.5", "S1200 M03", "G1 X10. Y5. M9", "G1 X1.0005", "g1 x5. y5.", "G1 X12",
          "G94", "G1 X+3.", "", "T1", "G1 G17 X3."]


def _num(v: Fraction) -> str:
    """``v`` as a decimal with a point (at most 3 decimals: the generator keeps its values on that grid)."""
    s = f"{float(v):.3f}".rstrip("0")
    return "0." if s in ("0.", "-0.") else s


@st.composite
def _programs(draw, size: int = 30) -> tuple[str, int]:
    """A plain Fanuc program and how many of its lines the reader may take (the motions in the subset)."""
    inch = draw(st.booleans()) and draw(st.booleans())
    pos = {"X": Fraction(0), "Y": Fraction(0), "Z": Fraction(0)}
    plane = 17
    arc = False  # the modal motion is G2/G3
    lines = ["O1000", f"G90 G17 {'G20' if inch else 'G21'} G54 G00 X0. Y0. Z0.", "G01 F500."]
    takes = 0
    for _ in range(draw(st.integers(1, size))):
        kind = draw(st.sampled_from(["line", "rapid", "r", "ij", "ij", "r", "helix", "plane", "leave", "inc",
                                     "int"]))
        n = f"N{draw(st.integers(1, 9999))} " if draw(st.integers(0, 5)) == 0 else ""
        a, b, la, lb = _PLANES[plane]
        if kind in ("line", "rapid"):
            words = []
            for ax in draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True)):
                pos[ax] = Fraction(draw(st.integers(-30000, 40000)), 1000)
                words.append(f"{ax}{_num(pos[ax])}")
            g = draw(st.sampled_from(["G1 ", "G01 ", "", "G0 ", "G00 "])) if kind == "line" else "G0 "
            g = "G1 " if g == "" and arc else g  # (a word without G in G2/G3 is an arc)
            arc = False
            lines.append(n + g + " ".join(words) + draw(st.sampled_from(["", "", " F800.", " F1200"])))
        elif kind in ("r", "ij", "helix"):
            cw = draw(st.booleans())
            g = "G2 " if cw else "G3 "
            if kind != "ij":
                da, db = draw(st.integers(-4000, 4000)), draw(st.integers(-4000, 4000))
                if da == db == 0:
                    da = 1000
                r = Fraction(draw(st.sampled_from([5000, 7500, 12000, 6000])), 1000)
                r = -r if draw(st.booleans()) else r
                pos[a] += Fraction(da, 1000)
                pos[b] += Fraction(db, 1000)
                centre = f"R{_num(r)}"
            else:
                (ua, ub), (wa, wb) = draw(st.sampled_from(_FIVE)), draw(st.sampled_from(_FIVE))
                ca, cb = pos[a] - ua, pos[b] - ub
                pos[a], pos[b] = ca + wa, cb + wb
                centre = " ".join(f"{c}{_num(Fraction(v))}" for c, v in ((la, -ua), (lb, -ub)) if v or
                                  draw(st.booleans()))
                centre = centre or f"{la}0."
            extra = ""
            if kind == "helix":
                other = ({"X", "Y", "Z"} - {a, b}).pop()
                pos[other] = Fraction(draw(st.integers(0, 5000)), 1000)
                extra = f" {other}{_num(pos[other])}"
            lines.append(n + g + f"{a}{_num(pos[a])} {b}{_num(pos[b])}{extra} {centre}")
            arc = True
        elif kind == "plane":
            plane = draw(st.sampled_from([17, 18, 19]))
            lines.append(f"G{plane}")
            continue
        elif kind == "inc":
            d = Fraction(draw(st.integers(-2000, 2000)), 1000)
            pos["X"] += d
            lines += [f"G91 G1 X{_num(d)}", "G90"]
            continue
        elif kind == "int":  # a length without a point (the decimal point rule), then a resync
            lines.append(f"G1 X{draw(st.integers(-20, 20))} Y{draw(st.integers(-20, 20))}")
            lines.append("G1 " + " ".join(f"{ax}{_num(v)}" for ax, v in pos.items()))
            continue
        else:
            lines.append(draw(st.sampled_from(_LEAVE)))
            if lines[-1] in ("G1 X12", "g1 x5. y5.", "G1 X1.0005", "G1 X+3.", "G1 G17 X3.", "G1 X10. Y5. M9"):
                lines.append("G1 " + " ".join(f"{ax}{_num(v)}" for ax, v in pos.items()))
            continue
        takes += 1
    lines.append("M30")
    end = "\r\n" if draw(st.integers(0, 4)) == 0 else "\n"
    return end.join(lines) + end, 0 if inch else takes


def _run(text: str, runs: bool, route: bool = True, machine=None) -> tuple[tuple, list, int]:
    """(the report, the boxes the route tested, the lines the reader took) of ``verify`` on ``text``."""
    r, tested, taken = probe_route(text, machine or _MACHINE, "t.nc", runs=runs, route=route)
    if isinstance(r, GcodeError):
        return ("error", tuple((d.code, d.message, str(d.span)) for d in r.diagnostics)), tested, taken
    stats = dict(r.stats)
    return ((r.verdict.label, tuple(r.violations), tuple(r.reasons), r.truncated, tuple(r.notes), stats["segments"],
             r.file, stats.get("fanuc_boxes"), (r.extra or {}).get("counts"), (r.profile or {}).get("blocks")),
            tested, taken)


def _agree(text: str, machine=None) -> tuple[str, int]:
    """The reader, the lanes and the path without the route agree; (verdict, lines the reader took)."""
    read, boxes, taken = _run(text, True, machine=machine)
    lanes, lane_boxes, none = _run(text, False, machine=machine)
    assert none == 0
    assert read == lanes
    assert boxes == lane_boxes
    today, _, _ = _run(text, True, route=False, machine=machine)
    assert today[:7] == read[:7]
    return str(read[0]), taken


@settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=_FIXED,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_reads_as_the_lanes(program):
    text, _takes = program
    _agree(text, _WIDE)


@settings(max_examples=max(3, EXAMPLES // 4), deadline=None, database=None, derandomize=_FIXED,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_reads_as_the_fast_path(program):
    """A generated program after 520 straight moves (more than 512 lines: without the route the vectorized fast
    path reads it) agrees on every side as above."""
    text, _takes = program
    head, _, rest = text.partition("G01 F500.")
    _agree(head + "G01 F500." + "".join(f"\nG1 X{k % 7}. Y{k % 5}." for k in range(520)) + rest, _WIDE)


def test_the_reader_takes_the_plain_lines():
    """A program of plain lines is read by the reader but for the lines it hands back: 6 of its 8 motions (the
    first straight move notes the assumed modes on the general lane; a length without a point is the decimal
    point rule's), and the report is the lanes' (safe: every position inside the zone)."""
    text = ("O1\nG90 G17 G21 G54 G00 X0. Y0. Z0.\nG01 F500.\nG1 X10. Y5.\nG2 X14. Y5. R2.5\nG3 X10. Y5. I-2.\n"
            "N10 G1X5.Y5.\nG1 X12\nG1 X12. Y5.\nG18\nG2 Z2. X14. R3.\nG19 G2 Y7. Z2. J1.\nM30\n")
    # lines 4-7 (the straight move of line 4 is the general lane's first, noting the modes: not line 4), 9, 11
    verdict, taken = _agree(text)
    assert verdict in ("safe", "unsafe")
    assert taken == 5


def test_a_long_program_agrees_with_the_fast_path():
    """600 R arcs and straight moves (more than 512 motions: without the route the vectorized fast path reads the
    program): the reader takes them all, and the route answers ``safe`` as the fast path does."""
    moves = []
    for k in range(300):
        x = Fraction(k % 40)
        moves += [f"G1 X{_num(x)} Y5.", f"G3 X{_num(x + 2)} Y7. R3."]
    text = "O1\nG90 G17 G21 G54 G00 X0. Y0. Z0.\nG01 F500.\nG1 X0. Y5.\n" + "\n".join(moves) + "\nM30\n"
    verdict, taken = _agree(text)
    assert verdict == "safe"
    assert taken == 600


@pytest.mark.parametrize("k", [0, 2200, 4400])
def test_a_long_program_with_one_bulging_arc_is_not_safe(k):
    """More than 4,000 lines in the zone and one R arc whose ends lie inside but whose middle leaves it: from
    program (40, 0) to (40, 20) with G03 R-10.001 (the major arc: its centre (40 +- ~0.14, 10) from the chord,
    it reaches X 40 + 0.14 + 10.001 > 50, the X face at program 50).  Not ``safe``: ``unsafe`` with the arc's
    line as the witness, on the reader's route as without the route."""
    moves = [f"G1 X{_num(Fraction(j % 40))} Y{_num(Fraction(j % 30))}" for j in range(4500)]
    moves[k:k] = ["G1 X40. Y0.", "G03 X40. Y20. R-10.001"]
    text = "O1\nG90 G17 G21 G54 G00 X0. Y0. Z0.\nG01 F500.\nG1 X0. Y5.\n" + "\n".join(moves) + "\nM30\n"
    read, _, taken = _run(text, True)
    assert read[0] == "unsafe"
    assert {v.span.line for v in read[1] if v.span is not None} == {k + 6}
    today, _, _ = _run(text, True, route=False)
    assert today[:7] == read[:7]


@pytest.mark.long
@settings(max_examples=HUNT, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
@given(_programs(120))
def test_the_reader_reads_as_the_lanes_long(program):
    _agree(program[0], _WIDE)


@pytest.mark.parametrize("arc, past", [
    ("G3 X5. Y8.5 R3.", False),  # the minor arc between (5, 8) and (5, 8.5): within 0.5 of the ends
    ("G3 X5. Y8.5 R-3.", True),  # the major one: its circle (centre ~(5 -+ 2.99, 8.25)) reaches Y 11.25 > 11
    ("G2 X5. Y8.5 R-3.", True),
    ("G2 X4. Y5. R-2.", False),  # the major arc of radius 2 about (4.5, 5 -+ 1.94): Y 1.06 .. 8.94, inside
    ("G2 X5. Y8. J1.", False),  # a whole circle about (5, 9): Y 8 .. 10
    ("G2 X5. Y8. J1.5", False),  # about (5, 9.5): up to Y 11, the box's face
    ("G3 X5. Y8. J1.6", True),  # about (5, 9.6): Y 11.2
    ("G3 X6.6 Y9.6 J1.6", True),  # a quarter about (5, 9.6) from its bottom to its right: Y 8 .. 9.6, but the
    # circle's box reaches 11.2: the route's box is centre_arc_box's (the sweep's extremes only), not the circle's
])
def test_an_arc_inside_the_run_s_box(arc, past):
    """The reader leaves the box as it is for an R arc that lies within 2|R| of both ends inside the run's box
    (every point of an arc is within a diameter of its ends), and makes its box otherwise: the boxes tested are
    the lanes' (which make every arc's box) in both cases.  The run's box: program X -1..11, Y -1..11 (straight
    moves to its corners).  An arc whose ends are inside and whose bulge leaves the box by less than 2|R| (Y
    11.25: the major arc of radius 3 through (5, 8) and (5, 8.5), its centre 2.99 from the chord's midpoint Y
    8.25) must widen it."""
    text = ("O1\nG90 G17 G21 G54 G00 X0. Y0. Z0.\nG01 F500.\nG1 X-1. Y-1.\nX11. Y11.\nX-1. Y11.\nX11. Y-1.\n"
            f"X5. Y8.\n{arc}\nM30\n")
    read, boxes, taken = _run(text, True, machine=_WIDE)
    lanes, lane_boxes, _ = _run(text, False, machine=_WIDE)
    assert (read, boxes) == (lanes, lane_boxes)
    assert taken == 5
    hi_y = dict(boxes[-1][1])["Y"] - 50  # program Y (G54 Y = 50)
    assert (hi_y > 11) == (past and "X6.6" not in arc)


@pytest.mark.parametrize("start, arc, axis, past", [
    ("X10.5 Y3.", "G3 X10.5 Y6. R1.74", "X", True),  # the minor arc of chord 3 bulges 0.858 to X 11.358
    ("X10.2 Y3.", "G3 X10.2 Y6. R1.74", "X", True),  # to X 11.058: past the face by less than a quarter chord
    ("X3. Y10.2", "G2 X6. Y10.2 R1.74", "Y", True),  # the same along the Y face (G2 going +X bulges +Y)
    ("X10.5 Y3.", "G3 X10.5 Y6. R3.", "X", False),  # bulges 0.402: X 10.902, inside
    ("X10.5 Y3.", "G2 X10.5 Y6. R1.74", "X", False),  # bulges away from the face
    ("X10.5 Y3.", "G3 X10.5 Y6. R-1.74", "X", True),  # the major arc round its centre (11.382, 4.5): X 13.12
])
def test_a_minor_arc_along_the_run_s_box(start, arc, axis, past):
    """The reader's inside test for a minor arc (within half its chord of the chord's midpoint: ``_lines``) next
    to a face of the run's box (program X, Y up to 11): an arc whose bulge passes the face by less than a quarter
    of its chord widens the box as the lanes do (a test tighter than half the chord would leave it), one that
    stays inside leaves it; the boxes tested are the lanes' in every case."""
    text = ("O1\nG90 G17 G21 G54 G00 X0. Y0. Z0.\nG01 F500.\nG1 X-1. Y-1.\nX11. Y11.\nX-1. Y11.\nX11. Y-1.\n"
            f"{start}\n{arc}\nM30\n")
    read, boxes, taken = _run(text, True, machine=_WIDE)
    lanes, lane_boxes, _ = _run(text, False, machine=_WIDE)
    assert (read, boxes) == (lanes, lane_boxes)
    assert taken == 5
    hi = dict(boxes[-1][1])[axis] - (100 if axis == "X" else 50)  # program X, Y (G54 = (100, 50))
    assert (hi > 11) == past


@settings(max_examples=60, deadline=None, database=None, derandomize=True)
@given(st.lists(st.sampled_from(["G1 X1.", "", "G2 X3. Y1. R2.5", "(C)", "\r"]), min_size=1, max_size=30),
       st.lists(st.integers(0, 10**6), min_size=1, max_size=12))
def test_the_line_index_is_the_line_of_the_offset(lines, picks):
    """The text cut into lines (boxrun._Lines) gives the index of the line starting at any offset, asked in any
    order (runs read forward; a jump back, a GOTO or a return, asks an earlier line): the count of line ends
    before it, and its layout and its text without points are that line's."""
    text = "\n".join(lines) + "\n"
    starts = [0] + [k + 1 for k, c in enumerate(text) if c == "\n"][:-1]
    cut = boxrun._Lines(text)
    for pick in picks:
        pos = starts[pick % len(starts)]
        i = cut.index(pos)
        cut.pos, cut.at = pos, i  # as read_box_run keeps it
        assert i == text.count("\n", 0, pos)
        line = text[pos:text.index("\n", pos)]
        assert cut.keys[i] == line.translate(boxrun._ZERO_DIGITS) and cut.dotless[i] == line.replace(".", "")


def test_a_program_the_reader_declines_line_by_line_is_tried_seldom(monkeypatch):
    """Incremental input (G91) on every line: the reader takes none of its 600 lines (the lanes do not take G91) and
    after 8k attempts in a row that took none passes the next k lines (FanucRunner.box_run): about
    sqrt(16 * 600) = 98 attempts, not 600; the report is the lanes'."""
    calls = [0]
    real = boxrun.read_box_run

    def counted(*a):
        calls[0] += 1
        return real(*a)

    text = "O1\nG91 G17 G21 G54 G01 F500.\n" + "X0.01 Y0.01\nX-0.01 Y0.005\n" * 300 + "M30\n"
    monkeypatch.setattr(boxrun, "read_box_run", counted)
    read, boxes, taken = _run(text, True)
    assert taken == 0
    assert 60 < calls[0] < 140
    assert (read, boxes) == _run(text, False)[:2]


@settings(max_examples=max(3, EXAMPLES * 3 // 8), deadline=None, database=None, derandomize=_FIXED,
          suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_the_reader_hands_the_state_back_as_the_lanes_leave_it(program):
    """A program that ends on the reader's lines (no M30: the text ends): the position, motion, feed, counts,
    block index and span, the cycle's initial level and the runner's block index are the lanes' after it."""
    _state_handed_back(program[0])


@pytest.mark.long
@settings(max_examples=HUNT // 2, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
@given(_programs(60))
def test_the_reader_hands_the_state_back_long(program):
    """The hunt of the relation above: programs drawn anew, up to 60 motions."""
    _state_handed_back(program[0])


def _state_handed_back(text: str) -> None:
    # (a drawn program the interpreter refuses, K in G17 after a plane change: so does the reader)
    assert_state_handed_back(text[:text.rindex("M30")], _WIDE)


@pytest.mark.long
@pytest.mark.corpus
def test_the_reader_reads_the_fanuc_corpus_as_the_lanes():
    """Every Fanuc program of the corpus (``fanuc/`` and the Fanuc rows of MANIFEST.tsv, 71 files) on the wide
    mill and the test zone: the reader on and off give the same report and the same boxes tested (2026-12-06:
    1,224 lines taken by the reader, no difference)."""
    import csv

    from tests.corpus import CORPUS, FANUC, MANIFEST

    if not MANIFEST.is_file():
        pytest.skip("corpus not available")
    files = {p for p in FANUC.rglob("*") if p.is_file()}
    with MANIFEST.open() as fh:
        files |= {CORPUS / r["path"] for r in csv.DictReader(fh, delimiter="\t")
                  if "Fanuc" in r["dialect"] and r["role"] == "program"}
    taken = 0
    for path in sorted(files):
        text = path.read_text(errors="replace")
        for machine in (_WIDE, _MACHINE):
            read, boxes, got = _run(text, True, machine=machine)
            assert (read, boxes) == _run(text, False, machine=machine)[:2], path
            taken += got
    assert taken > 0


@st.composite
def _r_arcs(draw) -> str:
    """A run's box (program X, Y up to 11: straight moves to its corners), then R arcs in G17 from a point in it to
    ends drawn near it (in thousandths): minor and major ones (R < 0), radii from just over half the chord to 20
    times it, exact half circles (the interpreter's: the reader hands them back) and ones just past half (within
    the tolerance or not), arcs along a face of the box (X or Y 11) a little inside it (bulging past it or not),
    modal G2/G3, blank lines between, LF or CR LF ends.
    Their bulges cross the box's faces and stay inside it: the reader's inside tests (a minor arc within half its
    chord of the chord's midpoint, any arc within 2|R| of its ends) on both sides of the faces."""
    lines = ["O1000", "G90 G17 G21 G54 G00 X0. Y0. Z0.", "G01 F500.", "G1 X-1. Y-1.", "X11. Y11.", "X-1. Y11.",
             "X11. Y-1.", "X5. Y5."]
    x = y = 5000
    modal = False
    for _ in range(draw(st.integers(1, 25))):
        kind = draw(st.sampled_from(["arc", "arc", "arc", "half", "near", "face", "face", "blank"]))
        if kind == "blank":
            lines.append(draw(st.sampled_from(["", " ", "\r"])))
            continue
        if kind == "face":  # a straight move to within 1.5 of a face, then an arc along it, bulging to it or away
            a, f = draw(st.sampled_from([(0, 11000), (1, 11000)]))  # (the box holds the machine's zero too)
            d = -draw(st.integers(0, 1500))
            x, y = (f + d, draw(st.integers(0, 10000))) if a == 0 else (draw(st.integers(0, 10000)), f + d)
            lines.append(f"G1 X{_num(Fraction(x, 1000))} Y{_num(Fraction(y, 1000))}")
            along = draw(st.integers(500, 4000)) * draw(st.sampled_from([1, -1]))
            ex, ey = (x, y + along) if a == 0 else (x + along, y)
        else:
            ex = min(max(x + draw(st.integers(-3000, 3000)), -1500), 11500)
            ey = y if kind == "half" else min(max(y + draw(st.integers(-3000, 3000)), -1500), 11500)
        if kind == "half" and (ex - x) % 2:
            ex += 1
        if (ex, ey) == (x, y):
            ex += 1000
        half = Fraction(math.isqrt(4 * ((ex - x) ** 2 + (ey - y) ** 2)) + 1, 4)  # just over half the chord
        if kind == "face":  # a chord of at most sqrt(3) R (the reader's inside test) from 2 / sqrt(3) h on
            r = math.ceil(half * draw(st.sampled_from([Fraction(1155, 1000), Fraction(116, 100), Fraction(6, 5), 2])))
        elif kind == "half":
            r = abs(ex - x) // 2  # a diameter
        elif kind == "near":
            r = math.ceil(half) + draw(st.sampled_from([0, 1, 2, 50, 300]))
        else:
            r = math.ceil(half * draw(st.sampled_from([Fraction(101, 100), Fraction(6, 5), 2, 5, 20])))
        r = -r if draw(st.integers(0, 3)) == 0 else r
        word = draw(st.sampled_from(["G2 ", "G3 ", "G02 ", "", ""] if modal else ["G2 ", "G3 ", "G03 "]))
        word = word or ("G2 " if lines[-1].startswith("G1") else "")  # (after a straight move: G2 again)
        lines.append(f"{word}X{_num(Fraction(ex, 1000))} Y{_num(Fraction(ey, 1000))} R{_num(Fraction(r, 1000))}")
        x, y, modal = ex, ey, True
    return draw(st.sampled_from(["\n", "\r\n"])).join(lines) + "\n"


@settings(max_examples=max(3, EXAMPLES * 5 // 8), deadline=None, database=None, derandomize=_FIXED,
          suppress_health_check=[HealthCheck.too_slow])
@given(_r_arcs())
def test_r_arcs_read_as_the_lanes(text):
    """R arcs the reader reads itself (``_lines``' written-out R-arc steps, issue 36) and those it hands back: the
    report and every box tested are the lanes' (which make every arc's box with ``r_arc_box``), and the state
    after them (position, counts, block index, span) is the lanes' too."""
    read, boxes, taken = _run(text + "M30\n", True, machine=_WIDE)
    lanes, lane_boxes, _ = _run(text + "M30\n", False, machine=_WIDE)
    assert (read, boxes) == (lanes, lane_boxes)
    assert taken >= 1
    _state_handed_back(text + "M30")
