"""The tests of today's Fanuc lanes (closures, the one-call lane's rows, column runs) compare those lanes with each
other through ``verify``: the numpy-free box route (:mod:`nczones.prover.fanucboxes`), which would answer both
sides of a comparison on a short program, is turned off there so they keep testing the lanes they name.
tests/prover/test_fanuc_boxes.py holds the route to today's path."""

from __future__ import annotations

import pytest

#: the modules whose subject is today's lanes
_LANE_TESTS = frozenset({"test_column_runs", "test_lane_hunt", "test_line_closures", "test_loop_lanes"})


@pytest.fixture(autouse=True)
def _today_lanes(request, monkeypatch):
    if request.module.__name__.rsplit(".", 1)[-1] in _LANE_TESTS:
        from nczones.prover import fanucboxes

        monkeypatch.setattr(fanucboxes, "ROUTE", False)
