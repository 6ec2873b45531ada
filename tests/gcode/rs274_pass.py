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
    return path
