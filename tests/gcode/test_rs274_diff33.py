"""The rs274 differential's remaining differences after the merged fixes (issue 33, seeds 2021xx-2083xx).

Each expected value is rs274's (LinuxCNC 2.9.0~pre1, ``rs274 -g``), recorded beside the program in
``tests/gcode/data/rs274_findings/NAME.rs274.txt`` (``python -m tests.tools.rs274_diff findings --record``):

* ``feed-in-g93``: ``F2000 / G93 F10 / G0 Y[#<_feed> * 0.1]`` traverses to Y200: LinuxCNC's ``execute_block``
  calls ``convert_feed_rate`` only outside G93, so ``#<_feed>`` is still 2000 (nczones read 10: Y1).  After a
  G93 feed move (``G1 X1 F10``) the feed rate is the move's length x F (``inverse_time_rate_straight``): Z1
  there; in general a double of a square root, so nczones makes that read unknown.
* ``rigid-tap-after-g84-g19``: after G84 in G19 the machine stands at X-18 Y0 Z-7 while rs274's interpreter
  believes X0 Y-7 Z-18; ``G33.1 X0 Z-20.096`` taps from the machine's point and back to it, and ``G0 X10``
  then traverses from X-18 Y0 Z-7 to X10 Y-7 Z-18 (nczones retracted the tap to X0 Y-7 Z-18 and moved along X).
* ``g30-after-units-change-under-tlo``: ``G43.1 Z10.92 / G20 / G30`` homes Z to -10.92 inch in program units
  (machine -266.4 mm, a move the program does not write), as G43/G49 after a G20/G21 (already unknown).
"""
from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest

from nczones.machine import load_machine, parse_machine
from nczones.prover import verify_text as verify
from tests import machines
from tests.oracles.rs274 import canon_motion, compare, machine_text
from tests.tools.rs274_diff import FINDING_SETUP, machine_of

MILL = load_machine("specs/machines/mill.toml")
FINDINGS = Path(__file__).parent / "data" / "rs274_findings"
MOVES = "".join(f"G1 X{i % 7} Y{i % 5}\n" for i in range(600))  # > 512 motions: the vectorized tier


def _recorded(name: str) -> str:
    return (FINDINGS / f"{name}.rs274.txt").read_text()


# -- #<_feed> in G93 ----------------------------------------------------------------------------------------

def test_the_recorded_feed_reads():
    """rs274's log: Y200 (the G94 rate 2000 x 0.1) and, after ``G1 X1 F10`` in G93, Z1 (1 mm x F10 x 0.1)."""
    log = _recorded("feed-in-g93")
    assert "STRAIGHT_TRAVERSE(0.0000, 200.0000, 0.0000," in log
    assert "STRAIGHT_TRAVERSE(1.0000, 200.0000, 1.0000," in log


@pytest.mark.parametrize("pre", ["", MOVES, "G93\nG0 X1 F10\n", "G93\n" + MOVES.replace("G1", "G0").replace(
    "\n", " F10\n")], ids=["short", "vectorized", "plain-lane", "many-g93"])
def test_feed_read_in_g93_is_the_g94_rate(pre):
    """mill.toml: G54 puts program Y0 at machine Y100; the travel ends at machine Y400.  LinuxCNC reads
    ``#<_feed>`` = 2000 in G93 (recorded above), so ``G0 Y[#<_feed> * 0.2]`` goes to program Y400 = machine Y500:
    out of travel.  nczones read the G93 F (10: Y2, machine Y102) and proved it ``safe``."""
    text = "G21 G90 G54 G94 F2000\n" + pre + "G93 F10\nG0 Y[#<_feed> * 0.2]\nM30\n"
    result = verify(text, MILL)
    assert result.verdict.label == "unsafe", (result.verdict, result.reasons)
    assert any(v.zone == "travel" and dict(v.point)["Y"] > 400 for v in result.violations), result.violations


@pytest.mark.parametrize("move", ["G1 X1 F10\n", "G2 X2 I1 F10\n", "".join(f"G1 X{i % 7} F10\n" for i in range(600))],
                         ids=["g1", "arc", "vectorized"])
def test_feed_read_after_a_g93_feed_move_is_unknown(move):
    """After a feed move in G93 LinuxCNC's feed rate is that move's length x F (recorded: Z1 after a 1 mm G1
    F10); nczones does not follow it: the read is unknown, not the stale 2000 or 10."""
    result = verify("G21 G90 G54 G94 F2000\nG0 X0 Y0\nG93\n" + move + "G0 Z[#<_feed> * 0.001]\nM30\n", MILL)
    assert result.verdict.label == "unknown", result.verdict
    assert any("#<_feed>" in r.message and "G93" in r.message for r in result.reasons), result.reasons


def test_feed_after_g93_then_g94_is_zero_again():
    """G94 sets the feed rate to 0 (``convert_feed_mode``) whatever G93 did: the read is known again."""
    result = verify("G21 G90 G54 G94 F2000\nG93\nG1 X1 F10\nG94\nG0 Y[#<_feed> + 1]\nM30\n", MILL)
    assert result.verdict.label == "safe", (result.verdict, result.reasons)


# -- G33.1 after G84 outside G17 ----------------------------------------------------------------------------

BOX = parse_machine(machines.machine_text("rs274_box"))


def test_the_recorded_tap_starts_and_ends_where_g84_left_the_machine():
    """rs274's log, in machine mm: the G84 retract ends at X-18 Y0 Z-7, the tap reaches X0 Y-7 Z-20.096 and
    reverses to its start, and ``G0 X10`` goes to X10 Y-7 Z-18."""
    moves = [(m.kind, tuple(float(v) for v in m.end[:3])) for m in canon_motion(_recorded("rigid-tap-after-g84-g19"))]
    assert moves[-4:] == [("LINE", (-18.0, 0.0, -7.0)), ("LINE", (0.0, -7.0, -20.096)), ("LINE", (-18.0, 0.0, -7.0)),
                          ("RAPID", (10.0, -7.0, -18.0))]


@pytest.mark.parametrize("pre", ["", MOVES, "#1 = 10\n"], ids=["short", "vectorized", "parameters"])
def test_rigid_tap_after_g84_in_g19_moves_from_where_the_machine_is(pre):
    """The post (a forbid box around X-4 Y-3.5 Z-12.5) is on the straight traverse from X-18 Y0 Z-7 to X10 Y-7
    Z-18 (its midpoint) that LinuxCNC makes, and on no move nczones made before (the tap retracted to X0 Y-7
    Z-18, then G0 X10 along X): ``unsafe`` in the G0 block, where it was ``safe``."""
    x = "X[#1]" if pre.startswith("#") else "X10"
    text = ("G21 G90 F500\n" + pre + "G0 X0 Y0 Z0\nG19\nM3 S1000\nG98 G84 Y-7 Z-18 X-7.3 R-0.1018\n"
            f"G33.1 X0 Z-20.096 K1.5\nG0 {x}\nM2\n")
    result = verify(text, BOX)
    assert result.verdict.label == "unsafe", (result.verdict, result.reasons)
    (v,) = [v for v in result.violations if v.zone == "post"]
    assert v.span is not None and v.span.text.startswith("G0 X")


# -- G28/G30/G53/G10 L10 after a units change under a tool length -------------------------------------------

def test_the_recorded_g30_moves_z_by_the_unconverted_length():
    """rs274's log: after ``G43.1 Z10.92`` (mm) and G20, G30's home move is ``STRAIGHT_TRAVERSE(0, 0, -10.92)``
    in inches with the tool length 10.92 mm = 0.4299 inch applied: machine Z = -10.92 + 0.4299 inch ~ -266.4 mm,
    where the G30 position is machine Z0."""
    (last,) = canon_motion(_recorded("g30-after-units-change-under-tlo"))[-1:]
    assert last.kind == "RAPID" and abs(float(last.end[2]) - (-10.92 + 10.92 / 25.4) * 25.4) < 0.01


@pytest.mark.parametrize("body", [
    "G43 H1\nG20\nG30\n", "G43 H1\nG20\nG28\n", "G43 H1\nG20\nG28 Z1\n", "G43 H1\nG20\nG53 G0 Z0\n",
    "G43 H1\nG20\nG10 L10 P2 Z1\n", "#1 = 1\nG43 H[#1]\nG20\nG30\n", MOVES + "G43 H1\nG20\nG30\n",
    "o100 sub\nG20\no100 endsub\nG43 H1\no100 call\nG30\n",
], ids=["g30", "g28", "g28-z", "g53", "g10-l10", "parameters", "vectorized", "sub"])
def test_home_and_machine_moves_after_a_units_change_under_a_tool_length_are_unknown(body):
    result = verify("G21 G90 G54 F100\nG0 X0 Y0\n" + body + "M30\n", MILL)
    assert result.verdict.label == "unknown", result.verdict
    assert any("G20/G21 while a tool length is applied" in r.message for r in result.reasons), result.reasons


@pytest.mark.parametrize("body", ["G43 H1\nG20\nG21\nG30\n", "G43 H1\nG20\nG28 X1\n", "G43 H1\nG20\nG53 G0 X0\n",
                                  "G20\nG43 H1\nG30\n"])
def test_home_moves_in_the_units_of_the_tool_length_or_off_its_axis_are_still_proved(body):
    result = verify("G21 G90 G54 F100\nG0 X0 Y0\n" + body + "M30\n", MILL)
    assert "G20/G21" not in " ".join(r.message for r in result.reasons), result.reasons


# -- the differential's comparison ---------------------------------------------------------------------------

def test_the_differential_takes_linuxcncs_arc_rule():
    """arc-linuxcnc-rule.ngc (seed 202870): rs274 runs the arc (recorded ARC_FEED); its end radius differs by
    0.034 mm = 0.084 % of 40.44 mm, inside LinuxCNC's rule (refused only above 2 x 0.01 x sqrt 2 mm *and* 0.1 %).
    nczones's default tolerance (0.002 mm) refuses it (a false error of the differential, not of LinuxCNC's
    meaning): the differential's machine takes ``arc_tolerance = "linuxcnc"``."""
    text = (FINDINGS / "arc-linuxcnc-rule.ngc").read_text()
    moves = canon_motion(_recorded("arc-linuxcnc-rule"))
    assert compare(text, machine_of(FINDING_SETUP), moves, None).status == "match"
    default = parse_machine(machine_text(*FINDING_SETUP))
    assert compare(text, default, moves, None).status == "false-error"


def test_one_peck_more_inside_the_hole_is_explained():
    """peck-count-after-g49.ngc (and seed 202145): rs274's G83 loop pecks once more than nczones (its Z read is
    a double an ulp off); the extra moves lie on the hole's line between R and the bottom: explained."""
    text = (FINDINGS / "peck-count-after-g49.ngc").read_text()
    log = _recorded("peck-count-after-g49")
    o = compare(text, machine_of(FINDING_SETUP), canon_motion(log), None)
    assert o.status == "match" and "peck" in o.detail, o


def test_a_peck_outside_the_hole_is_still_a_difference():
    """The same log with one of rs274's peck bottoms moved 1 mm below the hole's bottom: not explained."""
    text = (FINDINGS / "peck-count-after-g49.ngc").read_text()
    moves = canon_motion(_recorded("peck-count-after-g49"))
    k = max(i for i, m in enumerate(moves) if m.kind == "LINE" and i + 1 < len(moves)
            and moves[i + 1].kind == "RAPID" and moves[i + 1].end[:2] == m.end[:2])
    bottom = min(m.end[2] for m in moves[:k] if m.end[:2] == moves[k].end[:2])
    end = list(moves[k].end)
    end[2] = bottom - 1
    moves[k] = type(moves[k])(moves[k].kind, tuple(end), moves[k].tol)
    assert compare(text, machine_of(FINDING_SETUP), moves, None).status == "path"


def test_a_program_rs274_runs_forever_is_compared_up_to_where_it_got(monkeypatch, tmp_path):
    """seed 202426: after a ``continue`` in a ``do`` inside a ``repeat``, rs274 (LinuxCNC 2.9's loop-state
    defect) never ends, printing feeds; nczones is unknown there (GC390).  The differential stopped rs274 and
    compared nothing ("53 motions before unknown, rs274 has 0"); now it compares the log up to the stop."""
    from tests.tools import rs274_diff

    if not Path(rs274_diff.RS274).exists():
        pytest.skip("rs274 not installed")
    monkeypatch.setattr(rs274_diff, "LOG_LIMIT", 100_000)
    text = ("G21 G90 F100\no100 repeat [3]\n#101 = 0\no101 do\n#101 = [#101 + 1]\no102 if [#101 GT 1]\n"
            "o101 continue\no102 endif\nG1 X[#101]\no101 while [#101 LT 2]\nG1 Y1\nG1 Y0\no100 endrepeat\nM2\n")
    moves, error, _ = rs274_diff.run_rs274(text, FINDING_SETUP, tmp_path, timeout=20)
    assert error == ("rs274 timed out", "") and len(moves) > 100
    assert rs274_diff.outcome(text, FINDING_SETUP, tmp_path).status == "unknown"


@pytest.mark.parametrize("depth", ["-3.3", "-3"])
def test_a_peck_count_off_by_a_broken_rule_is_still_a_difference(depth):
    """R1 to Z-3.3 with Q1 is 4.3 pecks: LinuxCNC's loop (``d > bottom``) feeds to 0, -1, -2, -3 before the last
    plunge to -3.3.  nczones's own motion stands for rs274's here (it follows that loop; the CI differential holds
    it to rs274); the ``pecks-round`` mutant (tests/tools/rs274_mutants.py: round 4.3 to 4, one peck less) ends
    its missing peck 0.3 above the bottom, not at a whole number of pecks from it: a difference, not the ulp
    peck.  R1 to Z-3 is 4 pecks exactly: the mutant agrees with the loop, no difference."""
    from tests.oracles.rs274 import AXES6, HALF_DIGIT, CanonMove, nczones_motion
    from tests.tools.rs274_mutants import mutant

    text = f"G21 G90 F100\nG0 X0 Y0 Z10\nG99 G83 X1 Y1 Z{depth} R1 Q1\nG80\nM2\n"
    machine = machine_of(FINDING_SETUP)
    segs, _err, _uns = nczones_motion(text, machine)
    moves = [CanonMove(s.kind.name, tuple(s.end) + (Fraction(0),) * (len(AXES6) - len(s.end)), HALF_DIGIT)
             for s in segs]
    assert compare(text, machine, moves, None).status == "match"
    with mutant("pecks-round"):
        o = compare(text, machine, moves, None)
    assert o.status == ("path" if depth == "-3.3" else "match"), o


# -- a repeat around a do whose continue ran (seed 215995) ---------------------------------------------------

REPEAT_DO = ("o100 repeat [1]\n#101 = 0\no101 do\n#101 = [#101 + 1]\no102 if [#101 GT 1]\no101 continue\no102 endif\n"
             "o101 while [#101 LT 2]\nG91 G1 Z-1\nG90\no100 endrepeat\n")


@pytest.mark.parametrize("pre", ["", MOVES], ids=["short", "vectorized"])
def test_a_repeat_around_a_do_whose_continue_ran_is_unknown(pre):
    """rs274 on ``G21 G90 F100`` + REPEAT_DO + ``G0 X5 / M2`` never ends: ``STRAIGHT_FEED(0, 0, -3332)`` after 10,000
    log lines, one Z-1 feed per pass.  The ``continue`` leaves LinuxCNC 2.9's ``doing_continue`` set (the do's
    closing ``while`` does not clear it), so the repeat's exit at ``endrepeat`` loops back and recounts: the
    repeat runs again, forever here.  nczones ran it once (one Z-1 feed: ``safe``); now unknown (GC390)."""
    result = verify("G21 G90 G54 F100\nG0 X0 Y0\n" + pre + REPEAT_DO + "G0 X5\nM30\n", MILL)
    assert result.verdict.label == "unknown", result.verdict
    assert any(r.code == "GC390" and "endrepeat after a continue in a do" in r.message for r in result.reasons), \
        result.reasons


@pytest.mark.parametrize("loop", ["while", "no-continue"])
def test_a_repeat_around_a_while_continue_or_a_plain_do_is_proved(loop):
    """A ``continue`` in a ``while`` is cleared at its ``endwhile`` (LinuxCNC's skipping endwhile resets
    ``doing_continue``), and a ``do`` without ``continue`` sets nothing: the repeat ends as written."""
    body = (REPEAT_DO.replace("o101 do\n", "o101 while [#101 LT 2]\n").replace("o101 while [#101 LT 2]\nG91",
                                                                              "o101 endwhile\nG91")
            if loop == "while" else REPEAT_DO.replace("o101 continue\n", ""))
    result = verify("G21 G90 G54 F100\nG0 X0 Y0\n" + body + "G0 X5\nM30\n", MILL)
    assert result.verdict.label == "safe", (result.verdict, result.reasons)


# -- a spline's end held as LinuxCNC's double (the oracle's, seed 331616) ----------------------------------

def test_the_move_to_a_spline_end_is_matched_within_the_doubles_slack():
    """rs274 prints a bare ``G0`` after G5 curves as a traverse to the curve's end (its canon does not hold the
    end; nczones leaves it out). Here the end's Y is 28.77215 (``Y28.86`` + ``#<_value>`` = -0.08785, a double a
    few ulps below the decimal) - 26.4406 = 2.33155, which the log prints as 2.3316: 5e-5 + 1.1e-15 mm from
    nczones's exact value of the double, past the half digit by the double's error. Every other comparison
    allows 1e-9 mm beyond the rounding; the skip of that traverse did not (a false path mismatch)."""
    log = _recorded("spline-end-double")
    assert "STRAIGHT_TRAVERSE(-21.6020, 2.3316, 6.2490," in log and log.count("NURBS_FEED") == 3
    text = (FINDINGS / "spline-end-double.ngc").read_text()
    outcome = compare(text, machine_of(FINDING_SETUP), canon_motion(log), None)
    assert outcome.status == "match", outcome


def test_the_same_point_printed_in_inches_then_in_mm_is_no_move():
    """rs274 prints ``G0 Z[#<_z> + 0]`` after G21 as a traverse to where the G20 polar move ended: 0.52585 in
    printed 0.5258, then 13.3566 mm. Each print is within its own rounding of the same point, so they may
    differ by the sum of both (0.00127 + 0.00005 mm), not the larger; nczones drops the zero-length move, and
    the oracle kept rs274's as a motion (a false path mismatch, seed 343058)."""
    log = _recorded("inch-then-mm-same-point")
    assert "STRAIGHT_FEED(0.5258, 0.1224, 0.0000," in log and "STRAIGHT_TRAVERSE(13.3566, 3.1082, 0.0000," in log
    text = (FINDINGS / "inch-then-mm-same-point.ngc").read_text()
    outcome = compare(text, machine_of(FINDING_SETUP), canon_motion(log), None)
    assert outcome.status == "match", outcome
