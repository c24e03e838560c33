"""Tasks on a Dask cluster: a local one by default, or the scheduler at an address; results once each.

Every task is submitted with ``retries``: a task whose worker dies is run again elsewhere (the
scheduler's own rule, for a lost worker) and a task that raised is retried ``retries`` times. Results
are gathered by task index, so each comes back exactly once whatever ran twice. Ctrl-C cancels the
tasks still queued or running, then the cluster is closed.
"""
import contextlib
import sys
import time
import uuid

#: How often a task is run again after it raised (a lost worker is the scheduler's business).
DEFAULT_RETRIES = 2


def need_distributed():
    """The `distributed` module, or an error saying how to install it."""
    try:
        import distributed
    except ImportError as e:
        raise RuntimeError("sillage.distributed needs Dask distributed: apt-get install python3-distributed "
                           "python3-dask (scripts/setup.sh installs them)") from e
    return distributed


@contextlib.contextmanager
def cluster_client(scheduler=None, workers=2):
    """A Client: of the scheduler at `scheduler` ('tcp://host:port'), else of a new local cluster of
    `workers` processes with one thread each (closed on exit)."""
    distributed = need_distributed()
    if scheduler:
        client = distributed.Client(scheduler, timeout="20s")
        try:
            yield client
        finally:
            client.close()
        return
    if workers < 1:
        raise ValueError(f"workers: found {workers}, expected a number of worker processes >= 1")
    import dask

    # On the loopback, compressing the results (pavings: hundreds of MB) costs more CPU than it saves.
    with dask.config.set({"distributed.comm.compression": None}), \
            distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                     dashboard_address=":0") as cluster, distributed.Client(cluster) as client:
        yield client


class Progress:
    """A line on stderr, redrawn as tasks end (only on a terminal): done/total, statuses, elapsed."""

    def __init__(self, total, enabled=None, stream=None):
        """For `total` tasks, on `stream` (stderr); enabled: None for "when it is a terminal"."""
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.total, self.counts, self.start = total, {}, time.perf_counter()

    def update(self, record):
        """Counts the record's status and redraws the line."""
        self.counts[record["status"]] = self.counts.get(record["status"], 0) + 1
        if self.enabled:
            done = sum(self.counts.values())
            parts = ", ".join(f"{n} {s}" for s, n in sorted(self.counts.items()))
            self.stream.write(f"\r[{done}/{self.total}] {parts}, {time.perf_counter() - self.start:.1f} s\x1b[K")
            self.stream.flush()

    def close(self):
        """Ends the line (the next output starts on its own)."""
        if self.enabled:
            self.stream.write("\n")


def _lost_record(task_index, future):
    """The record of a task Dask gave up on (its workers died more often than the scheduler allows)."""
    try:
        why = repr(future.exception())
    except Exception as e:  # noqa: BLE001 - a cancelled future has no exception to fetch
        why = repr(e)
    return {"index": task_index, "status": "error", "why": f"the task failed on the cluster: {why}"}


def in_flight_limit(client):
    """How many tasks are submitted ahead of their results: enough to keep every worker thread busy (4 per
    thread, 256 at least), few enough that the scheduler never holds a whole fleet's data at once."""
    threads = sum(w.get("nthreads", 1) for w in client.scheduler_info().get("workers", {}).values())
    return max(256, 4 * threads)


def run_tasks(client, function, items, retries=DEFAULT_RETRIES, progress=None, max_in_flight=None, **kwargs):
    """function(item, **kwargs) for each item on the cluster: the results in item order.

    A result must be a dict; a task that failed on the cluster (not in function, which records its own
    errors) gives {'index', 'status': 'error', 'why'}. progress: a Progress, updated per result. At most
    max_in_flight tasks (default in_flight_limit) are on the cluster at a time; the next go as results come.
    """
    distributed = need_distributed()
    batch = uuid.uuid4().hex[:8]
    items = list(items)
    limit = max_in_flight or in_flight_limit(client)
    futures = {}

    def submit(i):
        f = client.submit(function, items[i], key=f"sillage-{batch}-{i}", retries=retries, pure=False, **kwargs)
        futures[f] = i
        return f

    queue = distributed.as_completed([submit(i) for i in range(min(limit, len(items)))])
    following = iter(range(min(limit, len(items)), len(items)))
    results = {}
    try:
        for future in queue:
            i = futures.pop(future)
            results[i] = future.result() if future.status == "finished" else _lost_record(i, future)
            if progress:
                progress.update(results[i])
            nxt = next(following, None)
            if nxt is not None:
                queue.add(submit(nxt))
    except BaseException:  # Ctrl-C (KeyboardInterrupt) and any other stop: nothing left running
        client.cancel(list(futures))
        raise
    finally:
        if progress:
            progress.close()
    return [results[i] for i in range(len(items))]
