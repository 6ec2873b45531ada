"""Fleet runs on Dask give the serial run's store: a LocalCluster, a worker killed mid-run, and a real
``dask scheduler`` with two ``dask worker`` processes started here (loopback only).

Kept small for a shared 2-core machine: a few tiny jobs, two single-threaded workers.
"""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest
from fleet_helpers import check, small_library, without_status

from nczones.fleet.execute import DaskExecutor

pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def library(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fleet")
    project = small_library(tmp / "lib", programs=5, machines=2, moves=6)
    _, serial = check(project, tmp / "serial.sqlite")
    return tmp, project, without_status(serial)


def _local_executor(workers=2):
    from distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
    return DaskExecutor(Client(cluster), cluster=cluster, name="local cluster (test)")


def test_a_local_cluster_run_equals_the_serial_run_job_by_job(library):
    tmp, project, serial = library
    summary, cells = check(project, tmp / "local.sqlite", _local_executor(), transfer="bytes")
    assert (summary.ran, summary.failed) == (10, 0)
    assert without_status(cells) == serial


class _KillOneWorker(DaskExecutor):
    """A Dask executor that kills a worker process (SIGKILL) as soon as the first result is back."""

    def results(self):
        killed = False
        for item in super().results():
            if not killed:
                killed = True
                processing = self.client.processing()
                victim = max(processing, key=lambda w: len(processing[w]))
                self.lost_tasks = set(processing[victim])
                pid = self.client.run(os.getpid, workers=[victim])[victim]
                os.kill(pid, signal.SIGKILL)
                self.victim_pid = pid
            yield item


def test_a_worker_killed_mid_run_has_its_jobs_retried_and_every_result_stored_once(library):
    from distributed import Client, LocalCluster

    tmp, project, serial = library
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    executor = _KillOneWorker(Client(cluster), cluster=cluster)
    summary, cells = check(project, tmp / "killed.sqlite", executor, transfer="bytes")
    assert executor.lost_tasks, "the killed worker was running a job"
    assert (summary.ran, summary.failed) == (10, 0)
    assert without_status(cells) == serial
    import sqlite3

    db = sqlite3.connect(tmp / "killed.sqlite")
    rows = list(db.execute("SELECT job_key, worker FROM results"))
    keys = [key for key, _ in rows]
    assert len(keys) == len(set(keys)) == 10
    # The victim may have delivered results before it died; the jobs it still
    # held must have been run again elsewhere.
    lost = {dask_key.split("-")[2] for dask_key in executor.lost_tasks}
    rerun = [worker for key, worker in rows if key[:16] in lost]
    assert rerun, "the lost jobs have stored results"
    assert not any(w.endswith(f":{executor.victim_pid}") for w in rerun)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_real_scheduler_and_two_workers_give_the_serial_store(library, tmp_path):
    tmp, project, serial = library
    dask = str(Path(sys.executable).parent / "dask")
    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[2]))
    procs = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard"],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env, cwd=tmp_path)]
    try:
        for i in range(2):
            procs.append(subprocess.Popen([dask, "worker", address, "--nthreads", "1", "--no-dashboard",
                                           "--name", f"w{i}", "--local-directory", str(tmp_path / f"w{i}")],
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env,
                                          cwd=tmp_path))
        from distributed import Client

        client = Client(address, timeout=60)
        deadline = time.monotonic() + 120
        while len(client.scheduler_info(n_workers=-1)["workers"]) < 2:
            assert time.monotonic() < deadline, "the two workers did not connect"
            time.sleep(0.2)
        client.close()
        summary, cells = check(project, tmp / "remote.sqlite", address, transfer="bytes")
        assert summary.executor == f"dask scheduler {address}"
        assert (summary.ran, summary.failed) == (10, 0)
        assert without_status(cells) == serial
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()


@pytest.mark.long
def test_a_larger_library_with_split_programs_on_a_local_cluster_equals_serial(tmp_path):
    project = small_library(tmp_path / "lib", programs=15, machines=4, moves=60)
    _, serial = check(project, tmp_path / "serial.sqlite")
    summary, cells = check(project, tmp_path / "local.sqlite", _local_executor(), split_lines=20, transfer="paths")
    assert summary.split == 60 and summary.failed == 0
    strip = {k: (v[0], v[1], tuple(x[:6] for x in v[2]), v[3]) for k, v in without_status(serial).items()}
    assert {k: (v[0], v[1], tuple(x[:6] for x in v[2]), v[3]) for k, v in without_status(cells).items()} == strip
