"""The check the rs274 double-pass differentials share: LinuxCNC's ``rs274 -g`` runs a program, the full path
matches its log motion by motion (``tests.oracles.rs274.compare``), and the double pass takes the program with
rs274's motion ends (dwells included, at the log's rounding) as its rows, in order, as many."""

from __future__ import annotations

import os
import shutil
from fractions import Fraction

import pytest

from nczones.gcode.linuxcnc.doubles import DoublePath, double_pass
from tests.oracles.rs274 import compare
from tests.tools.rs274_diff import RS274, machine_of, run_rs274

#: skips a module where rs274 is not installed (in CI a missing rs274 fails instead)
NEEDS_RS274 = pytest.mark.skipif(shutil.which("rs274") is None and not os.path.exists(RS274)
                                 and not os.environ.get("CI"), reason="LinuxCNC's rs274 is not installed")


def assert_the_pass_is_rs274s_motion(text: str, setup, tmp_path) -> DoublePath:
    """The module's check for ``text`` on rs274's ``setup`` (:func:`tests.tools.rs274_diff.run_rs274`); the path."""
    moves, error, log = run_rs274(text, setup, tmp_path)
    assert error is None, log[-2000:]
    machine = machine_of(setup)
    outcome = compare(text, machine, moves, error)
    assert outcome.status == "match", outcome
    path = double_pass(text, machine, max_iterations=100)
    assert path.motions == len(moves), [m.kind for m in moves]
    assert path.dwells == sum(m.kind == "DWELL" for m in moves)
    for k, move in enumerate(moves, start=1):
        for i in range(3):
            assert abs(Fraction(path.columns[i][k]) - move.end[i]) <= move.tol + Fraction(1, 10**9), (k, move)
    _boxes_hold_rs274s_ends(path, moves)
    return path


def _boxes_hold_rs274s_ends(path: DoublePath, moves: list) -> None:
    """The boxes the proof reads hold rs274's motion: each row's box (``path.enclosure(k + 1, k)``, the rows'
    widening of ``doubles.widened``) holds rs274's end within the log's rounding, and two rows (one or two apart)
    the pass calls farther apart than a gap (``path.apart``, read by ``prover.doubles.may_be_zero`` with the
    planner's drop threshold) are that far apart in rs274's log too, up to its rounding: gaps of a micrometre, a
    tenth of a millimetre and a millimetre, so that the log's rounding does not hide a wrong answer."""
    from nczones.motion import DROPPED_BELOW

    axes = path.axes[:3]
    for k, move in enumerate(moves, start=1):
        lo, hi = path.enclosure(k + 1, k)
        for i, a in enumerate(axes):
            assert lo[a] - move.tol <= move.end[i] <= hi[a] + move.tol, (k, a, move, lo[a], hi[a])
        for j in (k - 1, k - 2):
            if j < 1:
                continue
            before = moves[j - 1]
            for gap in (DROPPED_BELOW, Fraction(1, 10**6), Fraction(1, 10), Fraction(1)):
                if path.apart(j, k, gap):
                    assert any(abs(move.end[i] - before.end[i]) + move.tol + before.tol > gap
                               for i in range(3)), (j, k, gap, move, before)
