"""``fleet check`` chooses its executor by measurement (issue 36): the first jobs run in this process and are
timed; a local cluster takes the rest only when it is projected to win.

On a 2-core machine a 2-worker cluster ran the bundled library 4x slower than serial (1.4 vs 5.7 jobs/s):
short jobs must stay serial.  No real cluster is started here (the decision is what is tested; the cluster
runs are in test_fleet_dask.py): ``local_cluster`` is replaced by a recorder.
"""

from __future__ import annotations

import pytest
from fleet_helpers import small_library, without_status

import nczones.fleet.check as check_module
import nczones.fleet.execute as execute_module
from nczones.fleet.check import PROBE_JOBS, CheckOptions, projected_seconds, run_check
from nczones.fleet.execute import SerialExecutor
from nczones.fleet.project import load_project
from nczones.fleet.store import Store

pytest.importorskip("distributed")


def _run(project_file, store_path, **options):
    with Store(store_path) as store:
        summary = run_check(load_project(project_file), store,
                            CheckOptions(progress=False, cluster_threshold=PROBE_JOBS + 2, **options))
        from fleet_helpers import current

        return summary, current(store)


@pytest.fixture
def started(monkeypatch):
    """Replace the local cluster by an in-process executor that says it was started."""
    calls = []

    def fake(workers=None, *, attempts=3):
        calls.append(workers)
        ex = SerialExecutor()
        ex.name = "local cluster (recorded)"
        return ex

    monkeypatch.setattr(execute_module, "local_cluster", fake)
    return calls


def test_short_jobs_stay_in_this_process_and_the_run_says_why(tmp_path, started):
    project = small_library(tmp_path / "lib", programs=7, machines=2, moves=4)
    summary, cells = _run(project, tmp_path / "a.sqlite")
    _, serial = _run(project, tmp_path / "b.sqlite", executor="serial")
    assert summary.jobs == 14 and summary.ran == 14 and not started
    assert summary.executor == "serial" and summary.probe[0] == PROBE_JOBS and summary.probe[2] == 14 - PROBE_JOBS
    assert "cannot win" in summary.choice and f"over the first {PROBE_JOBS}" in summary.choice
    assert without_status(cells) == without_status(serial)


def test_long_jobs_go_to_the_cluster_after_the_probe(tmp_path, started, monkeypatch):
    """With no start-up or task cost a two-worker cluster halves any run: it must be chosen."""
    monkeypatch.setattr(check_module, "CLUSTER_START_S", 0.0)
    monkeypatch.setattr(check_module, "TASK_OVERHEAD_S", 0.0)
    monkeypatch.setattr("os.cpu_count", lambda: 2)
    project = small_library(tmp_path / "lib", programs=7, machines=2, moves=4)
    summary, cells = _run(project, tmp_path / "a.sqlite", workers=2)
    _, serial = _run(project, tmp_path / "b.sqlite", executor="serial")
    assert started == [2] and summary.executor == "local cluster (recorded)" and summary.ran == 14
    assert "projected to win" in summary.choice
    assert without_status(cells) == without_status(serial)


def test_below_the_threshold_or_with_an_explicit_executor_nothing_is_measured(tmp_path, started):
    project = small_library(tmp_path / "lib", programs=2, machines=2, moves=4)
    summary, _ = _run(project, tmp_path / "a.sqlite")
    assert summary.executor == "serial" and summary.probe == (0, 0.0, 0) and summary.choice == ""
    project = small_library(tmp_path / "lib2", programs=7, machines=2, moves=4)
    summary, _ = _run(project, tmp_path / "b.sqlite", executor="serial")
    assert summary.probe == (0, 0.0, 0) and not started


def test_the_projection_follows_the_measurement_it_was_fitted_to():
    """specs/fleet.md: 1,020 jobs of 85 ms wall took 109.4 s on two workers (4.2 s of it starting)."""
    serial, cluster = projected_seconds(0.085, 1020, 2)
    assert serial == pytest.approx(86.7) and cluster == pytest.approx(109.4, rel=0.05)
    assert projected_seconds(0.0, 10, 2) == (0.0, check_module.CLUSTER_START_S + 10 * check_module.TASK_OVERHEAD_S)
