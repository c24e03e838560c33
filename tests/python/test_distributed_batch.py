"""sillage.distributed on a real local Dask cluster (2 worker processes, the session's dask_client):
batches and sweeps give one record per task, in order, with what a local solve gives; the report
is written; a worker killed mid-batch loses nothing."""
import json
import os
import shutil
import signal
import threading
import time
from pathlib import Path

import pytest

import sillage

pytest.importorskip("distributed")
from sillage import distributed  # noqa: E402
from sillage.distributed_tasks import make_task, run_task  # noqa: E402

PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"
LINE = str(PROBLEMS / "line_ranges.toml")
CLOCK = str(PROBLEMS / "drifting_clock.toml")
SLOW = str(PROBLEMS / "lowcost_beacons.toml")  # about a second: long enough to die in


def test_a_task_solves_as_a_local_solve():
    """The task, run here, gives the truth check and thickness of sillage.solve on the file."""
    record = run_task(make_task(0, LINE))
    result = sillage.solve(LINE)
    check = sillage.check_truth(sillage.load_problem(LINE), result)
    assert record["status"] == "solved"
    assert (record["truth_inside"], record["truth_samples"]) == (check.inside, check.samples)
    assert record["mean_thickness"] == result.schedule[-1]["mean_thickness"]
    assert record["widths"]["x"] > 0


def test_batch_gives_one_record_per_file_in_order(dask_client, tmp_path):
    records = distributed.batch([LINE, CLOCK, LINE], client=dask_client, out=str(tmp_path))
    assert [r["index"] for r in records] == [0, 1, 2]
    assert [os.path.basename(r["file"]) for r in records] == ["line_ranges.toml", "drifting_clock.toml",
                                                               "line_ranges.toml"]
    assert all(r["status"] == "solved" for r in records)
    assert records[0]["mean_thickness"] == records[2]["mean_thickness"]
    page = (tmp_path / "report.html").read_text()
    assert "task 0: line_ranges.toml" in page and "data:image/png;base64" in page
    assert len(json.loads((tmp_path / "results.json").read_text())) == 3
    assert (tmp_path / "results.csv").read_text().count("\n") == 4


def test_sweep_sets_each_combination(dask_client, tmp_path):
    settings = {"constraint[1].errors.r": [0.001, 0.1], "constraint[1].time_error": [0.01, 0.5]}
    records = distributed.sweep(LINE, settings, client=dask_client, ship="paths", out=str(tmp_path))
    assert [r["settings"] for r in records] == [
        {"constraint[1].errors.r": "0.001", "constraint[1].time_error": "0.01"},
        {"constraint[1].errors.r": "0.001", "constraint[1].time_error": "0.5"},
        {"constraint[1].errors.r": "0.1", "constraint[1].time_error": "0.01"},
        {"constraint[1].errors.r": "0.1", "constraint[1].time_error": "0.5"}]
    thickness = [r["mean_thickness"] for r in records]
    # Looser bounds, thicker tubes; the first is the file's own statement.
    assert thickness[0] < thickness[1] < thickness[3] and thickness[0] < thickness[2] < thickness[3]
    assert thickness[0] == run_task(make_task(0, LINE))["mean_thickness"]
    page = (tmp_path / "report.html").read_text()
    assert "<h2>constraint[1].errors.r</h2>" in page and "<h2>constraint[1].time_error</h2>" in page


def test_a_bad_setting_is_an_error_before_anything_runs():
    """Every task's text is parsed where it is made: no cluster is reached (the address is dead)."""
    with pytest.raises(sillage.Error, match=r"no 'time_eror' in constraint\[1\]"):
        distributed.sweep(LINE, {"constraint[1].time_eror": [1]}, scheduler="tcp://127.0.0.1:1")
    with pytest.raises(sillage.Error, match=r"line_ranges.toml:19:16: found the bound \"\[-10, nope\]\""):
        distributed.sweep(LINE, {"var.x.value": ["[-10, 10]", "[-10, nope]"]}, scheduler="tcp://127.0.0.1:1")


def test_a_task_that_fails_on_the_worker_is_a_row(dask_client, tmp_path):
    """A table missing on the worker's shared path is that task's error, named; the others solve."""
    (tmp_path / "data").mkdir()
    for name in ("beacon_ranges.csv", "line_truth.csv"):
        shutil.copy(PROBLEMS / "data" / name, tmp_path / "data" / name)
    shutil.copy(LINE, tmp_path / "line.toml")
    tasks = [make_task(0, LINE, ship="paths"), make_task(1, str(tmp_path / "line.toml"), ship="paths")]
    (tmp_path / "data" / "beacon_ranges.csv").unlink()
    records = distributed.run_problem_tasks(tasks, client=dask_client)
    assert [r["status"] for r in records] == ["solved", "error"]
    assert "beacon_ranges.csv" in records[1]["why"]


def _kill_one_worker_when_busy(client, victims):
    """Kills a worker process (SIGKILL) once tasks are running on it."""
    for _ in range(200):
        busy = [w for w, tasks in client.processing().items() if tasks]
        if busy:
            pid = client.run(os.getpid, workers=[busy[0]])[busy[0]]
            os.kill(pid, signal.SIGKILL)
            victims.append(pid)
            return
        time.sleep(0.05)


def test_a_worker_killed_mid_batch_loses_nothing(dask_client):
    """Every task's record comes back once, although a worker process died running tasks (its nanny
    starts another; the scheduler runs its tasks again)."""
    paths = [SLOW, LINE] * 3
    victims = []
    killer = threading.Thread(target=_kill_one_worker_when_busy, args=(dask_client, victims))
    killer.start()
    records = distributed.batch(paths, client=dask_client)
    killer.join()
    assert victims, "no worker was busy"
    assert [r["index"] for r in records] == list(range(len(paths)))
    assert all(r["status"] == "solved" for r in records)
    assert records[0]["mean_thickness"] == records[2]["mean_thickness"] == records[4]["mean_thickness"]
    dask_client.wait_for_workers(2, timeout=30)  # the nanny's new worker, for the tests after this one


def test_tasks_go_in_a_window_and_come_back_in_order(dask_client):
    """At most max_in_flight tasks on the cluster at a time (a fleet's data never all at once), the
    results in the order of the items."""
    from sillage.distributed_run import run_tasks
    from sillage.distributed_tasks import _tables as identity

    items = [{"index": i, "status": "solved"} for i in range(25)]
    assert run_tasks(dask_client, identity, items, max_in_flight=3) == items
