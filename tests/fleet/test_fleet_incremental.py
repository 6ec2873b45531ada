"""The incremental rule of ``fleet check``: only jobs whose key changed run, and the result is a full run's."""

from __future__ import annotations

import os
import shutil
import signal
import time

import pytest
from fleet_helpers import check, small_library, without_status

from nczones.fleet.execute import SerialExecutor
from nczones.fleet.generate import mill_variant
from nczones.fleet.store import Store


def test_touching_one_machine_reruns_only_its_jobs_and_equals_a_fresh_run(tmp_path):
    lib = tmp_path / "lib"
    project = small_library(lib, programs=4, machines=3)
    first, cells1 = check(project, tmp_path / "a.sqlite")
    assert (first.cells, first.jobs, first.ran, first.reused) == (12, 12, 12, 0)
    assert {v[2] for v in cells1.values()} == {"safe", "unsafe"}  # part_000 cuts into the vise of mill_000
    again, cells2 = check(project, tmp_path / "a.sqlite")
    assert (again.ran, again.reused) == (0, 12)
    assert without_status(cells2) == without_status(cells1)

    # move mill_001's vise under the pocket walks: only its 4 cells get new keys and run again
    (lib / "machines" / "mill_001.toml").write_text(mill_variant(60), encoding="utf-8")
    touched, cells3 = check(project, tmp_path / "a.sqlite")
    assert (touched.ran, touched.reused) == (4, 8)
    changed = {k for k in cells3 if cells3[k][0] != cells1[k][0]}
    assert changed == {(f"programs/part_{i:03d}.ngc", "mill_001") for i in range(4)}
    assert [cells3[k][2] for k in sorted(changed)] != [cells1[k][2] for k in sorted(changed)]

    # change one program: only its cells (one per machine) run again
    prog = lib / "programs" / "part_002.ngc"
    prog.write_text(prog.read_text() + "(a comment changes the bytes)\n", encoding="utf-8")
    edited, cells4 = check(project, tmp_path / "a.sqlite")
    assert (edited.ran, edited.reused) == (3, 9)
    assert {k for k in cells4 if cells4[k][0] != cells3[k][0]} == {
        ("programs/part_002.ngc", f"mill_{k:03d}") for k in range(3)}

    # the store after these runs holds what one fresh full run gives
    fresh, cells_fresh = check(project, tmp_path / "fresh.sqlite")
    assert fresh.ran == 12
    assert without_status(cells4) == without_status(cells_fresh)
    with Store(tmp_path / "a.sqlite") as store:
        assert [r.ran for r in store.runs()] == [12, 0, 4, 3]
        assert store.prune() == 4 + 3  # the results of the old mill_001 and the old part_002 cells


def test_settings_and_the_nczones_version_are_in_the_key(tmp_path, monkeypatch):
    lib = tmp_path / "lib"
    project = small_library(lib, programs=2, machines=2)
    check(project, tmp_path / "s.sqlite")
    text = project.read_text()
    project.write_text(text + '\n[[settings]]\nprograms = ["programs/part_001.ngc"]\nmargin = "0.5"\n')
    margin, _ = check(project, tmp_path / "s.sqlite")
    assert margin.ran == 2  # part_001 on both machines
    project.write_text(text + '\n[[settings]]\nprograms = ["programs/part_001.ngc"]\nmargin = "0.50"\n')
    same, _ = check(project, tmp_path / "s.sqlite")
    assert same.ran == 0  # "0.50" and "0.5" are one margin, one key
    import nczones.fleet.check as check_module
    import nczones.fleet.work as work_module

    monkeypatch.setattr(check_module, "code_version", lambda: "nczones 99 (code x) z3 y")
    mismatch, cells = check(project, tmp_path / "s.sqlite")  # a worker on another nczones: nothing stored
    assert (mismatch.ran, mismatch.failed, mismatch.exit_code) == (0, 4, 2)
    assert "install the same nczones on every worker" in mismatch.problems[0]
    assert {v[2] for v in cells.values()} == {"error"}
    monkeypatch.setattr(work_module, "code_version", lambda: "nczones 99 (code x) z3 y")
    newer, _ = check(project, tmp_path / "s.sqlite")
    assert newer.ran == 4


def test_a_machine_file_that_does_not_load_makes_its_cells_errors_and_the_rest_runs(tmp_path):
    lib = tmp_path / "lib"
    project = small_library(lib, programs=2, machines=2)
    (lib / "machines" / "mill_001.toml").write_text("[machine]\naxes = 3\n", encoding="utf-8")
    summary, cells = check(project, tmp_path / "e.sqlite")
    assert summary.ran == 2 and summary.exit_code == 1  # part_000 is unsafe on mill_000
    assert {k: v[2] for k, v in cells.items() if k[1] == "mill_001"} == {
        ("programs/part_000.ngc", "mill_001"): "error", ("programs/part_001.ngc", "mill_001"): "error"}
    assert any("ZN1" in p for p in summary.problems)
    shutil.rmtree(lib / "programs")
    gone, cells = check(project, tmp_path / "e.sqlite")
    assert gone.cells == 0 and cells == {}


def test_a_program_that_changes_during_the_run_is_an_error_for_that_run_and_not_stored(tmp_path):
    from nczones.fleet.check import CheckOptions, run_check
    from nczones.fleet.execute import SerialExecutor
    from nczones.fleet.project import load_project

    lib = tmp_path / "lib"
    project = load_project(small_library(lib, programs=2, machines=1))

    def executor_after_an_edit(options, jobs):  # called after the keys were computed, before any job is sent
        (lib / "programs" / "part_001.ngc").write_text("G0 X1\n", encoding="utf-8")
        return SerialExecutor()

    for transfer in ("bytes", "paths"):
        with Store(tmp_path / f"{transfer}.sqlite") as store:
            summary = run_check(project, store, CheckOptions(transfer=transfer, progress=False),
                                make_executor=executor_after_an_edit)
            assert (summary.ran, summary.failed) == (1, 1)
            assert "FL201" in summary.problems[0] or "changed while the fleet ran" in summary.problems[0]
            assert len(list(store.results())) == 1
        (lib / "programs" / "part_001.ngc").write_text(
            __import__("nczones.fleet.generate", fromlist=["x"]).mill_program(1, 6), encoding="utf-8")


def test_the_progress_bar_counts_jobs_and_names_the_verdicts_that_are_not_safe(tmp_path):
    import io

    from nczones.fleet.check import CheckOptions, run_check
    from nczones.fleet.project import load_project

    project = load_project(small_library(tmp_path / "lib", programs=2, machines=1))
    err = io.StringIO()
    with Store(tmp_path / "p.sqlite") as store:
        run_check(project, store, CheckOptions(executor="serial", progress=True), err=err)
    frames = [f for f in err.getvalue().split("\r") if f.strip()]
    assert frames[-1].startswith("fleet [##############################] 2/2 jobs; 1 unsafe; ")
    assert err.getvalue().endswith("\r")  # the bar is erased at the end


class _SwallowsCtrlC(SerialExecutor):
    """Runs tasks in this process; during the second one a SIGINT arrives whose KeyboardInterrupt is lost, as
    Python loses one raised inside a finalizer (``__del__``)."""

    def results(self):
        for n, item in enumerate(super().results()):
            if n == 1:
                try:
                    os.kill(os.getpid(), signal.SIGINT)
                    time.sleep(0.5)  # the handler runs here
                except KeyboardInterrupt:
                    pass
            yield item


def test_a_ctrl_c_whose_exception_is_lost_still_stops_the_run(tmp_path):
    project = small_library(tmp_path / "lib", programs=3, machines=2)
    with pytest.raises(KeyboardInterrupt):
        check(project, tmp_path / "s.sqlite", _SwallowsCtrlC())
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # put back
    with Store(tmp_path / "s.sqlite") as store:
        (run,) = store.runs()
        assert run.interrupted and run.ran == 1  # the first job; the second's answer came after Ctrl-C
        assert sum(c.status == "pending" for c in store.cells(run.run_id)) == 5


@pytest.mark.parametrize("where", ["after_commit", "before_commit"])
def test_a_ctrl_c_between_a_result_and_its_count_keeps_the_store_consistent(tmp_path, monkeypatch, where):
    """A Ctrl-C right after a result's commit (before the run counted it) or between the result and its cells'
    mark (before the commit): the run's ``ran`` is the number of results kept, and every cell without one is
    pending (found by the whole-suite runs: ``ran`` 3 with 4 results stored)."""
    from nczones.fleet import store as store_module

    calls = {"puts": 0, "raised": False}
    real_put, real_commit, real_finish = (store_module.Store.put, store_module.Store.commit,
                                          store_module.Store.finish_cells)

    def put(self, *args, **kw):
        real_put(self, *args, **kw)
        calls["puts"] += 1

    def ctrl_c_at_the_second_result():
        if calls["puts"] == 2 and not calls["raised"]:
            calls["raised"] = True
            raise KeyboardInterrupt

    def commit(self):
        real_commit(self)
        if where == "after_commit":
            ctrl_c_at_the_second_result()

    def finish_cells(self, run_id, key, verdict):
        if where == "before_commit":
            ctrl_c_at_the_second_result()
        real_finish(self, run_id, key, verdict)

    monkeypatch.setattr(store_module.Store, "put", put)
    monkeypatch.setattr(store_module.Store, "commit", commit)
    monkeypatch.setattr(store_module.Store, "finish_cells", finish_cells)
    project = small_library(tmp_path / "lib", programs=3, machines=2)
    with pytest.raises(KeyboardInterrupt):
        check(project, tmp_path / "s.sqlite")
    monkeypatch.undo()
    with Store(tmp_path / "s.sqlite") as store:
        (run,) = store.runs()
        stored = len(list(store.results()))
        assert run.interrupted and run.ran == stored == (2 if where == "after_commit" else 1)
        assert sum(c.status == "pending" for c in store.cells(run.run_id)) == 6 - stored
