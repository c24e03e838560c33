"""sillage.distributed against a cluster started as a user starts one: a `dask scheduler` and a
`dask worker` process on the loopback address (free ports), the batch sent to its address; and the
command `sillage batch` / `sillage sweep` (which runs python3 -m sillage.distributed)."""
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

import sillage

pytest.importorskip("distributed")
import distributed  # noqa: E402

from sillage import distributed as sillage_distributed  # noqa: E402

PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"
LINE = str(PROBLEMS / "line_ranges.toml")
BUILD = Path(sillage.__file__).resolve().parents[2]
SILLAGE = BUILD / "tools" / "sillage" / "sillage"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def dask_command(name):
    """`dask scheduler` / `dask worker`, the user's commands, run by this test's Python."""
    return [sys.executable, "-m", "dask", name]


@pytest.fixture(scope="module")
def user_cluster(tmp_path_factory):
    """tcp://127.0.0.1:PORT of a scheduler and one worker (processes of their own), shut down after."""
    tmp_path = tmp_path_factory.mktemp("dask")
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(sillage.__file__)))
    scheduler = subprocess.Popen(dask_command("scheduler") + ["--host", "127.0.0.1", "--port", str(port),
                                                                "--no-dashboard"],
                                 env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=tmp_path)
    worker = subprocess.Popen(dask_command("worker") + [address, "--nthreads", "1", "--nworkers", "1",
                                                          "--host", "127.0.0.1", "--no-dashboard"],
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=tmp_path)
    try:
        yield address
    finally:
        with distributed.Client(address, timeout="10s") as client:
            client.shutdown()  # the scheduler closes its workers, then itself
        for p in (worker, scheduler):
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        for p in (worker, scheduler):
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                p.kill()


def test_batch_on_a_scheduler_and_worker_of_their_own(user_cluster, tmp_path):
    records = sillage_distributed.batch([LINE, LINE], scheduler=user_cluster, out=str(tmp_path))
    assert [r["status"] for r in records] == ["solved", "solved"]
    assert (tmp_path / "report.html").is_file()


def test_the_command_sweeps_on_that_scheduler(user_cluster, tmp_path):
    r = subprocess.run([str(SILLAGE), "sweep", LINE, "--set", "constraint[1].errors.r=0.001,0.01",
                        "--scheduler", user_cluster, "--out", str(tmp_path)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "2 solved" in r.stdout and (tmp_path / "results.csv").read_text().count("\n") == 3


def test_the_command_says_what_is_wrong_with_a_setting(tmp_path):
    r = subprocess.run([str(SILLAGE), "sweep", LINE, "--set", "constraint[1].errors.r=[0.1,", "--out",
                        str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "--set constraint[1].errors.r: found the values" in r.stderr
    r = subprocess.run([str(SILLAGE), "sweep", LINE, "--set", "constraint[1].error.r=1", "--out", str(tmp_path)],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "no 'error' in constraint[1]" in r.stderr


def test_ctrl_c_cancels_the_batch(tmp_path):
    """SIGINT while `sillage batch` runs on its local cluster: the tasks are cancelled, the cluster
    closed, exit status 130 (SIGINT's default restored for the child, whatever this run ignores)."""
    slow = str(PROBLEMS / "lowcost_beacons.toml")
    proc = subprocess.Popen([str(SILLAGE), "batch", *[slow] * 8, "--workers", "1", "--out", str(tmp_path)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    time.sleep(4)  # the cluster up and tasks running (or still starting: a Ctrl-C then is handled the same)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err[-2000:]
    assert "cancelled (Ctrl-C)" in err
    assert not (tmp_path / "report.html").exists()
