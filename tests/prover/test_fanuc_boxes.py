"""The numpy-free box route of short Fanuc programs (nczones/prover/fanucboxes.py, issue 36) against today's path.

Relation (both sides computed by nczones): ``verify`` with the route (``fanucboxes.ROUTE``; the lane's runs as
their boxes, ``BoxRows``, or as rows, ``ROWS_AS_LISTS``) and without it give the same verdict, violations, reasons, notes, motion count and
program name (``Result.file``: the route's reports had none, fanucarcs36); when the route answers (its ``fanuc_boxes`` count is
in the stats) the answer is ``safe``, or ``unknown`` for a code not modelled that ended the motion (a loop past
its bound: every motion read was proved), as today's path says.  The route may decline where today's path
proves ``safe`` (its boxes are coarser), never the other way round.

The test mill (tests/gcode/fanuc/helpers.py): G54 = (100, 50, -200), H1 = 100, H2 = 150.5; Fanuc G43 adds H to the
programmed Z.  Its zone here: machine X -10..150, Y -10..90, Z -201..0, so program X50. (machine 150), Y40.
(machine 90) and Z-1. (machine -201) lie on its faces; optional: a forbidden clamp (controlled point), a
forbidden tip probe (the tip is the machine point less the tool length on Z) or a forbidden triangle (a polygon).
"""

from __future__ import annotations

import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.prover import fanucboxes, verify_text
from tests.gcode.fanuc.helpers import mill

_TRAVEL = ('\n[[zones]]\nname = "box"\nkind = "box"\nmin = { X = "-10", Y = "-10", Z = "-201" }\n'
           'max = { X = "150", Y = "90", Z = "0" }\n')
# program X 20..22, Y 10..12: machine X 120..122, Y 60..62 (controlled point, every Z)
_CLAMP = ('\n[[zones]]\nname = "clamp"\nkind = "box"\nforbid = true\n'
          'min = { X = "120", Y = "60", Z = "-1000" }\nmax = { X = "122", Y = "62", Z = "1000" }\n')
# the tip in machine X 100..150, Z -300..-290: reached only with H1/H2 in force (tip = machine Z - length) near
# the Z floor: at H1 machine Z -201..-190 (program Z -1. .. 10.) puts the tip at -301..-290
_PROBE = ('\n[[zones]]\nname = "probe"\nkind = "box"\nforbid = true\npoint = "tip"\n'
          'min = { X = "130", Y = "-1000", Z = "-300" }\nmax = { X = "150", Y = "1000", Z = "-290" }\n')
# a forbidden triangle in X/Y (program X 20..30, Y 10..20), polygon zones being proved by their own box test
_TRIANGLE = ('\n[[zones]]\nname = "triangle"\nkind = "polygon"\nforbid = true\nplane = ["X", "Y"]\n'
             'vertices = [["120", "60"], ["130", "60"], ["125", "70"]]\n')
_MACHINES = {name: mill(tables=_TRAVEL + extra) for name, extra in
             (("box", ""), ("clamp", _CLAMP), ("probe", _PROBE), ("triangle", _TRIANGLE))}

#: motions inside the zone (#1 is the loop counter, 0 .. reps - 1)
_MOVES = [
    "G01 X[#1 * 0.5] Y[#1 * 0.25]",
    "G00 X5. Y5.",
    "G01 Z-1.",
    "Z-0.5",
    "G01 X50. Y40.",  # the corner of the X and Y faces
    "G01 X40. Y0.",
    "G02 X40. Y20. R10.",  # a half circle from (40, 0) or (40, 20): a rational centre, touching X50. (or not)
    "G03 X30. Y10. R7.5",  # an R arc with an irrational centre
    "G02 X0. Y10. I-5. J5.",  # an I/J arc whose radius may not match (an error, on both sides)
    "G09 G01 X10.",
    "G61",
    "G64",
    "G04 X0.1",
    "G43 H1 Z5.",
    "G43 H2 Z0.",
    "G49 Z0.",
    "G01 X35. Y15.",
    "G01 X21. Y11.",  # inside the clamp
]
#: motions that leave the zone or graze it from outside
_OUT = ["G01 X50.001", "G01 Y40.001", "G01 Z-1.001", "G02 X40. Y20. R-10.001", "G00 X[60 - #1 * 0.001]"]


def _program(body: list[str], reps: int, form: str) -> str:
    head = ["O1000", "G90 G17 G21 G54 F500.", "G00 X0. Y0. Z0.", "#1 = 0"]
    if form == "while":
        lines = head + [f"WHILE [#1 LT {reps}] DO1", *body, "#1 = #1 + 1", "END1", "M30"]
    elif form == "m98":
        lines = head + [f"WHILE [#1 LT {reps}] DO1", "M98 P9020", "#1 = #1 + 1", "END1", "M30", "O9020", *body,
                        "M99"]
    else:
        lines = head + [f"WHILE [#1 LT {reps}] DO1", "G65 P9020 A#1", "#1 = #1 + 1", "END1", "M30", "O9020",
                        "#1 = #1", *body, "M99"]
    return "\n".join(lines) + "\n"


def _verified(text: str, machine, route: bool, lists: bool = False) -> tuple:
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(fanucboxes, "ROUTE", route)
        mp.setattr(fanucboxes, "ROWS_AS_LISTS", lists)
        try:
            r = verify_text(text, machine, file="t.nc")
        except GcodeError as e:
            return ("error", tuple((d.code, d.message, str(d.span)) for d in e.diagnostics)), False
    stats = dict(r.stats)
    return ((r.verdict.label, tuple(r.violations), tuple(r.reasons), r.truncated, tuple(r.notes),
             stats["segments"], r.file), "fanuc_boxes" in stats)


def _agree(text: str, machine) -> tuple[str, bool]:
    """The route and today's path agree; (verdict, whether the route answered)."""
    today, taken_today = _verified(text, machine, False)
    routed, taken = _verified(text, machine, True)
    assert not taken_today
    assert routed == today
    assert _verified(text, machine, True, lists=True) == (routed, taken)  # the lane's runs as rows: the same
    if taken:  # the route proves every motion read: safe, or unknown for a code not modelled (a loop bound)
        assert today[0] == "safe" or (today[0] == "unknown" and today[2])
    return str(today[0]), taken


#: 12 fixed programs in the default run (25 random ones took about a minute of it); a hunt:
#: NCZONES_FANUC_ROUTE_EXAMPLES=300 (randomized above 25)
ROUTE_EXAMPLES = int(os.environ.get("NCZONES_FANUC_ROUTE_EXAMPLES", "12"))


@settings(max_examples=ROUTE_EXAMPLES, deadline=None, database=None, derandomize=ROUTE_EXAMPLES <= 25,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(_MOVES), min_size=1, max_size=7), st.lists(st.sampled_from(_OUT), max_size=1),
       st.integers(1, 6), st.sampled_from(["while", "m98", "g65"]), st.sampled_from(sorted(_MACHINES)),
       st.randoms(use_true_random=False))
def test_the_route_decides_as_today(body, out, reps, form, machine, rnd):
    body = body + out
    rnd.shuffle(body)
    _agree(_program(body, reps, form), _MACHINES[machine])


def test_the_route_answers_a_loop_of_more_than_512_motions():
    """A WHILE loop of 600 straight moves and 600 R arcs (1,200 motions: the proof's vectorized tier on today's
    path) in the zone: the route answers ``safe``, as today's path does, and says so in the stats."""
    text = _program(["G01 X[#1 * 0.05] Y5.", "G03 X[#1 * 0.05 + 2] Y7. R3."], 600, "while")
    verdict, taken = _agree(text, _MACHINES["box"])
    assert (verdict, taken) == ("safe", True)
    # and a short one, the same way
    assert _agree(_program(["G01 X10. Y10.", "G02 X20. Y10. R5."], 2, "m98"), _MACHINES["clamp"]) == ("safe", True)


@pytest.mark.parametrize("code, radius, expected, taken", [
    # from (40, 0) to (40, 20), chord along +Y.  G03 with R > 0 (and G02 with R < 0) has its centre left of the
    # chord (-X), G02 with R > 0 (G03 with R < 0) right of it (+X) (prover/rformat.py); the arc bulges away from
    # the centre's side when it is the minor arc (|R| > 10: the centre is 10 +- sqrt(R^2 - 100) from X 40).
    # G03 R10.: the half circle around (40, 10) (a rational centre: the chord is 2R) through (50, 10): X50. is the
    # face (machine 150): safe, its exact box touches the face, the route answers
    ("G03", "10.", "safe", True),
    # G03: the major arc around (40 + 0.4472.., 10), reaching X 40.4472 + 10.001 = 50.448: unsafe; the
    # route's box leaves the zone, it declines and today's path gives the witness
    ("G03", "-10.001", "unsafe", False),
    # G03 R10.001: the minor arc around (39.5528.., 10) (irrational), reaching X 49.554: safe; the route's box of the
    # whole circle (X <= 49.554 + its outward rounding) fits: the route answers
    ("G03", "10.001", "safe", True),
    # G02 R10.001: the minor arc around (40.4472.., 10), bulging to X 30.446: safe; its clockwise sweep about the
    # centre, from 267.4 to 92.6 degrees, passes 180 (-X) and never 0 (+X), so the box (ArcGeom.plane_bbox) stops
    # at the chord's X 40
    # (before the lead's tighter R box its whole circle reached X 50.448 past the face and the route declined)
    ("G02", "10.001", "safe", True),
])
def test_an_r_arc_whose_enclosure_touches_a_face(code, radius, expected, taken):
    """In G61 (exact stops: in cutting mode today's hull test encloses a lone R arc by its circle too, and the
    last case is ``unknown`` on both sides)."""
    text = _program(["G61", "G01 X40. Y0.", f"{code} X40. Y20. R{radius}", "G00 X0. Y0."], 1, "while")
    assert _agree(text, _MACHINES["box"]) == (expected, taken)


_TL_ZONES = ('\n[[zones]]\nname = "travel"\nkind = "box"\nmin = { X = "-1000", Y = "-1000", Z = "-1000" }\n'
             'max = { X = "1000", Y = "1000", Z = "1000" }\n'
             '[[zones]]\nname = "probe"\nkind = "box"\nforbid = true\npoint = "tip"\n'
             'min = { X = "140", Y = "-1000", Z = "-260" }\nmax = { X = "160", Y = "1000", Z = "-240" }\n')


@pytest.mark.parametrize("pad", [0, 300])
def test_a_tool_length_inside_a_run_is_tested(pad):
    """Cutting mode, ``G43 H1`` in the middle of a run: the geometry of tests/prover/test_fanuc_run_tool_lengths.py
    (hunt36's wrong ``safe``).  The run (machine X, Z) (100, -200) -> (200, -200) at length 0, -> (200, 100) at
    H1 = 100, -> (100, 0) at length 0; the tip probe X 140..160, Z -260..-240.  No motion's tip meets the probe,
    the run's hull at H1 does (tip Z -300..0 over X 100..200): not ``safe``, and the route must not answer.  With
    G61 before the run (exact stops, no hull) today's path proves it ``safe``; the route's one box still meets the
    probe at H1, so it declines and today's path answers.  ``pad``: a WHILE loop of that many motions before (past
    512 motions in all with 300)."""
    m = mill(tables=_TL_ZONES)
    loop = f"#1 = 0\nWHILE [#1 LT {pad}] DO1\nG01 X[#1 MOD 7] Y5.\n#1 = #1 + 1\nEND1\n" if pad else ""
    run = "G01 X100.\nG43 H1 Z200.\nG49 X0.\n"
    text = "O1\nG90 G17 G21 G54 G49 F500.\n" + loop + "G00 X0. Y0. Z0.\nG04 X0\n{mode}" + run + "G04 X0\nG64\nM30\n"
    verdict, taken = _agree(text.format(mode=""), m)
    assert not taken and verdict != "safe"
    assert _agree(text.format(mode="G61\n"), m) == ("safe", False)
    # the run without the G43 (every motion at length 0: the tip is the machine point, Z >= -200): the box fits
    assert _agree(text.format(mode="").replace("G43 H1 ", ""), m) == ("safe", True)


def test_exact_stops_and_dwells_are_answered():
    """G09, G61/G64 and dwells inside a loop in the zone: the route answers safe, as today's path."""
    text = _program(["G09 G01 X10. Y5.", "G61", "G01 X20.", "G04 X0.1", "G64", "G02 X30. Y5. R5."], 3, "g65")
    assert _agree(text, _MACHINES["box"]) == ("safe", True)


def test_a_long_text_goes_today_s_path(monkeypatch):
    """A program of more than FAST_PATH_MIN_LINES lines is read by the vectorized path, not the route, unless it is
    plain (no ``#``, no call) and of at most FANUC_BOX_LINES lines (pipeline.verification._fanuc_boxes_first; set
    to 700 here: the test's texts stay short)."""
    from nczones.pipeline import verification
    from nczones.pipeline.verification import _fanuc_boxes_first

    monkeypatch.setattr(verification, "FANUC_BOX_LINES", 700)
    FANUC_BOX_LINES = verification.FANUC_BOX_LINES  # noqa: N806 - the constant's value in this test

    def moves(n: int) -> str:
        return "".join(f"X{k % 40}. Y{k % 30}.\n" for k in range(n))

    text = "O1\nG90 G21 G54 G01 F500.\n" + moves(600) + "M30\n"
    assert _agree(text, _MACHINES["box"]) == ("safe", True)
    assert _agree(text.replace("O1\n", "O1\n#1 = 0\n"), _MACHINES["box"]) == ("safe", False)
    assert not _fanuc_boxes_first(text.replace("O1\n", "O1\nM98 P2\n"))  # a call may run far more lines
    assert not _fanuc_boxes_first(text.replace("O1\n", "O1\nG65 P2\n"))
    text = "O1\nG90 G21 G54 G01 F500.\n" + moves(FANUC_BOX_LINES) + "M30\n"
    assert _agree(text, _MACHINES["box"]) == ("safe", False)


def test_no_numpy_on_the_route():
    """The route imports no numpy: a verify of a WHILE loop in a fresh interpreter leaves it unloaded."""
    code = ("import sys\nfrom nczones.prover import verify_text\nfrom tests.gcode.fanuc.helpers import mill\n"
            f"m = mill(tables={_TRAVEL!r})\n"
            f"r = verify_text({_program(['G01 X[#1 * 0.01] Y5.'], 700, 'while')!r}, m)\n"
            "print(r.verdict.label, 'numpy' in sys.modules, dict(r.stats).get('fanuc_boxes'))\n")
    root = Path(__file__).resolve().parents[2]
    env = dict(os.environ, PYTHONPATH=str(root))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=root, env=env,
                         check=True).stdout.split()
    assert out == ["safe", "False", "1"]


@pytest.mark.parametrize("body, reps", [
    # a dwell after each move: every iteration's move is a run of rows of its own; X reaches 50.1 (machine 150.1,
    # past the face) at #1 = 501, in the 502nd run
    (["G01 X[#1 * 0.1] Y5.", "G04 X0"], 600),
    # one run of 10,050 rows: more than a run holds (columns.MAX_ROWS, 8,192); X reaches 50.025 at #1 = 10,005
    (["G01 X[#1 * 0.005] Y5."], 10050),
])
def test_a_late_run_that_leaves_the_zone(body, reps):
    """The exit comes in a later run of rows than the first: unsafe on both sides, the route does not answer."""
    assert _agree(_program(body, reps, "while"), _MACHINES["box"]) == ("unsafe", False)


# ---------------------------------------------------------------------------------------------------------------
# Wrong-safe hunt: hunt36b's generator of loops (tests/gcode/fanuc/test_lane_hunt.py: frames, G91, G68, G51, work
# offsets and tool lengths changed in the loop, calls, GOTO, system variables) on the three machines above (the
# travel box whose faces the programs touch and cross, a clamp, a tip probe under H1/H2).  The relation is
# _agree's.  CI: a few examples; ``-m long``: the counts in specs/contract.md "Where features meet: fanucsmall36".

#: what the hunt met: (machine, verdict, the route answered) -> programs
HUNT: dict[tuple[str, str, bool], int] = {}


def _hunt(pieces: tuple, machine: str) -> None:
    from tests.gcode.fanuc.test_lane_hunt import _program as lane_program

    verdict, taken = _agree(lane_program(*pieces), _MACHINES[machine])
    HUNT[(machine, verdict, taken)] = HUNT.get((machine, verdict, taken), 0) + 1


def _hunt_pieces():
    from tests.gcode.fanuc.test_lane_hunt import _pieces

    return st.tuples(*_pieces(jumps=True))


@settings(max_examples=6, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
@given(_hunt_pieces(), st.sampled_from(sorted(_MACHINES)))
def test_hunt_few(pieces, machine):
    _hunt(pieces, machine)


@pytest.mark.long
@settings(max_examples=400, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
@given(_hunt_pieces(), st.sampled_from(sorted(_MACHINES)))
def test_hunt_long(pieces, machine):
    _hunt(pieces, machine)


@pytest.mark.long
def test_hunt_long_counts():
    """Prints what test_hunt_long met (run after it: ``-m long -s``)."""
    print({f"{m} {v} {'route' if t else 'today'}": n for (m, v, t), n in sorted(HUNT.items())})


def test_a_loop_past_its_bound_is_unknown_once():
    """A WHILE loop of 1,500 iterations with max_loop_iterations 1,000: the full path proves the 1,000 moves read and
    says ``unknown`` (GC390) at the WHILE line; the route answers the same, reading the program once."""
    text = _program(["G01 X[#1 * 0.01] Y5."], 1500, "while")
    calls: list[int] = []
    real = fanucboxes.prove_boxes

    def spy(*a, **k):
        calls.append(1)
        return real(*a, **k)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(fanucboxes, "prove_boxes", spy)
        routed = verify_text(text, _MACHINES["box"], file="t.nc", max_iterations=1000)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(fanucboxes, "ROUTE", False)
        today = verify_text(text, _MACHINES["box"], file="t.nc", max_iterations=1000)
    assert calls == [1] and "fanuc_boxes" in dict(routed.stats)
    assert (routed.verdict.label, routed.reasons, routed.notes) == (today.verdict.label, today.reasons, today.notes)
    assert routed.verdict.label == "unknown" and [r.code for r in routed.reasons] == ["GC390"]
    assert dict(routed.stats)["segments"] == dict(today.stats)["segments"] == 1001  # the G00 and 1,000 moves


def test_a_tool_length_only_rows_carry():
    """``G43 H1`` alone (no motion: only the lane's rows after it carry H1 = 100).  Program Z-95. is machine
    Z -95 - 200 + 100 = -195 (inside the travel box's -201), its tip -195 - 100 = -295, in the probe's -300..-290,
    at machine X 100 + 40 = 140 in the probe's 130..150: unsafe on both sides, and the route, whose box must be
    tested at H1, does not answer.  (The lane sends the first move after a G43 through the general path, so a
    segment carries H1 too: a BoxRows that forgot its rows' lengths is not caught here; it records them.)"""
    text = ("O1\nG90 G17 G21 G54 F500.\nG00 X0. Y0. Z0.\nG43 H1\n#1 = 0\nWHILE [#1 LT 3] DO1\nG01 X[#1 * 10 + 20] Y5.\n"
            "G01 Z-95.\nG01 Z0.\n#1 = #1 + 1\nEND1\nM30\n")
    assert _agree(text, _MACHINES["probe"]) == ("unsafe", False)
    # the same machine positions without the G43 (Z5. is machine -195): the tip is the machine point, Z >= -195,
    # above the probe: safe, and the route answers
    assert _agree(text.replace("G43 H1\n", "").replace("Z-95.", "Z5."), _MACHINES["probe"]) == ("safe", True)


_COORD = st.one_of(st.integers(-10**6, 10**6).map(lambda n: Fraction(n, 1000)),  # increments: the integer box
                   st.fractions(min_value=-1000, max_value=1000, max_denominator=7),  # thirds...: the Fraction box
                   st.integers(-1000, 1000))  # ints (a Fraction's slots missing)


@given(st.lists(st.tuples(st.sampled_from(["line", "rapid", "dwell"]), st.tuples(_COORD, _COORD, _COORD),
                          st.booleans(), st.sampled_from([Fraction(0), Fraction(100), Fraction(1, 3)])),
                min_size=1, max_size=30))
@settings(max_examples=100, deadline=None)
def test_the_walks_box_is_the_box_of_every_position(moves):
    """``BoxWalk``'s box (integer box for coordinates on the 10**-12 grid, Fraction box for the others, a chained
    start taken once) equals the box of every start and end by Fraction min/max, and its tool lengths every
    motion's; a chained start (``joined``: the previous end's object) is the previous end."""
    from nczones.gcode.segments import make_segment
    from nczones.motion import MotionChunk, SegmentKind

    kinds = {"line": SegmentKind.LINE, "rapid": SegmentKind.RAPID, "dwell": SegmentKind.DWELL}
    axes = ("X", "Y", "Z")
    segs, prev = [], (Fraction(5), Fraction(-7, 3), 0)
    for kind, end, joined, tl in moves:
        start = prev if joined else tuple(reversed(end))
        end = start if kind == "dwell" else end
        segs.append(make_segment(kinds[kind], start, end, axes, 0, None, tl, None, None, False, None, None, 0,
                                 None, "", None, (), (), (), None))
        prev = end
    walk = fanucboxes.BoxWalk(axes)
    walk.take(MotionChunk(axes, None, objects=tuple(segs)))
    lo, hi = walk.box()
    points = [p for s in segs for p in (s.start, s.end)]
    assert lo == {a: min(Fraction(p[i]) for p in points) for i, a in enumerate(axes)}
    assert hi == {a: max(Fraction(p[i]) for p in points) for i, a in enumerate(axes)}
    assert walk.tool_lengths() == {s.tool_length for s in segs}
