#!/usr/bin/python3
"""Figures of docs/benchmarks.md, "Beyond one machine" (docs/distributed.md): run with the built package,

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_distributed.py [overhead] [batch] [sweep] [paving]

on a local cluster of 2 worker processes of one thread. Each part prints its figures (no part by
default: all of them). One core = every solve or paving with sillage.ThreadLimit(1), one after the other.
"""
import os
import sys
import time
from pathlib import Path

import sillage
from sillage import distributed
from sillage.distributed_paving import InversionSpec, distributed_paving, pave_box
from sillage.distributed_run import cluster_client, run_tasks
from sillage.distributed_tasks import make_task, run_task

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = ROOT / "examples" / "problems"
WORKERS = 2


def _noop(item):
    return {"index": item, "status": "solved"}


def overhead(client):
    """Per task, what Dask adds: a task that does nothing, 400 of them on 2 workers; and one at a time."""
    n = 400
    start = time.perf_counter()
    run_tasks(client, _noop, list(range(n)))
    batch = (time.perf_counter() - start) / n
    start = time.perf_counter()
    for i in range(40):
        run_tasks(client, _noop, [i])
    alone = (time.perf_counter() - start) / 40
    print(f"overhead: {batch * 1e3:.2f} ms per task in a batch of {n} (wall / tasks), "
          f"{alone * 1e3:.1f} ms for a batch of one task (submit to result)")


def example_problems():
    """The 10 example problems, 4 times each: 40 tasks (lowcost_beacons, about a second, is most of the work)."""
    paths = sorted(str(p) for p in PROBLEMS.glob("*.toml"))
    return [p for _ in range(4) for p in paths]


def warm(client):
    """Each worker imports sillage and solves once: a batch runs on a cluster already up (the start-up is
    measured apart, in main)."""
    client.run(lambda: __import__("sillage.distributed_tasks"))
    client.run(lambda: run_task(make_task(0, str(PROBLEMS / "line_ranges.toml"))))


def batch(client):
    """40 example problems: one after the other on one core, then on the 2 workers."""
    paths = example_problems()
    tasks = [make_task(i, p) for i, p in enumerate(paths)]
    start = time.perf_counter()
    local = [run_task(t) for t in tasks]
    one = time.perf_counter() - start
    start = time.perf_counter()
    records = distributed.batch(paths, client=client)
    two = time.perf_counter() - start
    solve = sum(r["seconds"] for r in records)
    assert [r["status"] for r in records] == [r["status"] for r in local]
    longest = [p for _, p in sorted(zip((-r["seconds"] for r in local), paths))]
    start = time.perf_counter()
    distributed.batch(longest, client=client)
    lpt = time.perf_counter() - start
    print(f"batch, the longest first (their one-core times): {lpt:.2f} s: x{one / lpt:.2f}")
    print(f"batch: {len(paths)} problems, one core {one:.2f} s, {WORKERS} workers {two:.2f} s: "
          f"x{one / two:.2f}; the tasks' time on the workers {solve:.2f} s; idle {(two * WORKERS - solve) / len(paths) * 1e3:.1f} "
          f"ms per task (wall x workers - task time, per task)")


PLAZA_SWEEP = {"constraint[8].time_error": [0.1, 0.2, 0.4, 0.8], "constraint[3].track": [0.03, 0.05, 0.1, 0.2]}


def sweep(client, out):
    """plaza1 over 4 x 4 bound values with its report, against the 16 solves one after the other / 2."""
    path = str(PROBLEMS / "plaza1.toml")
    texts = {k: [distributed.toml_value(v) for v in vs] for k, vs in PLAZA_SWEEP.items()}
    from sillage.distributed_grid import grid

    start = time.perf_counter()
    seq = [run_task(make_task(i, path, s)) for i, s in enumerate(grid(texts))]
    one = time.perf_counter() - start
    start = time.perf_counter()
    records = distributed.sweep(path, PLAZA_SWEEP, client=client, out=out)
    two = time.perf_counter() - start
    assert [r["mean_thickness"] for r in records] == [r["mean_thickness"] for r in seq]
    print(f"sweep: plaza1 4 x 4, one core {one:.1f} s, {WORKERS} workers with report {two:.1f} s: "
          f"{two / (one / WORKERS):.2f} x (one core / {WORKERS}); report {out}/report.html")
    for r in records:
        print(f"  {r['label']}: {r['status']}, truth {r['truth_inside']}/{r['truth_samples']}, "
              f"thickness {r['mean_thickness']:.3f}, {r['seconds']:.2f} s")


#: A 4-D set inversion whose every box costs about 1.5 microseconds (trigonometric terms): 3.4 million nodes.
PAVING = InversionSpec(
    "sivia", ("a", "b", "c", "d"),
    "(sin(a)*cos(b) + sin(c)*cos(d) + sin(a + c)*cos(b - d) + sin(a*b)*cos(c*d) + sin(2*a - d)*cos(b + 2*c), "
    "exp(0.3*a*b) - cos(c - d) + sin(a*d) + exp(0.2*c*d)*cos(a + b) - sin(b*c), "
    "atan(a*c) + tanh(b*d) + a^2 + b^2 + c^2 + d^2 + atan(b - c)*tanh(a + d))",
    y=sillage.IntervalVector([[0.2, 1.5], [-0.5, 0.5], [0, 5]]))
PAVING_BOX = [[-2, 2]] * 4
PAVING_EPS = 0.1


def paving(client):
    """The 4-D inversion on one core, with oneTBB on the 2 cores of one process, then split over the 2 workers."""
    x0 = sillage.IntervalVector(PAVING_BOX)
    start = time.perf_counter()
    one = pave_box(PAVING, x0, PAVING_EPS)
    t_one = time.perf_counter() - start
    f = sillage.Function(list(PAVING.variables), PAVING.expr)
    start = time.perf_counter()
    threads = sillage.sivia(x0, f, PAVING.y, PAVING_EPS, sillage.SiviaOptions(parallel=True))
    t_threads = time.perf_counter() - start
    timings = {}
    start = time.perf_counter()
    two = distributed_paving(client, PAVING, PAVING_BOX, PAVING_EPS, timings=timings)
    t_two = time.perf_counter() - start
    print(f"paving: 4-D, eps {PAVING_EPS}, {one.nb_nodes()} nodes ({one.nb_leaves()} leaves), one core "
          f"{t_one:.2f} s, oneTBB on 2 threads {t_threads:.2f} s (x{t_one / t_threads:.2f}), {WORKERS} workers "
          f"{t_two:.2f} s: x{t_one / t_two:.2f} (the tasks' time on the workers {timings['task_seconds']:.2f} s); "
          f"equal to one core: {one == two}, to oneTBB: {threads == two}")


def main(parts):
    parts = parts or ["overhead", "batch", "sweep", "paving"]
    start = time.perf_counter()
    with cluster_client(workers=WORKERS) as client:
        client.wait_for_workers(WORKERS)
        up = time.perf_counter() - start
        warm(client)
        print(f"cluster: {WORKERS} worker processes up in {up:.2f} s, sillage imported and warm in "
              f"{time.perf_counter() - start - up:.2f} s more")
        if "overhead" in parts:
            overhead(client)
        if "batch" in parts:
            batch(client)
        if "sweep" in parts:
            sweep(client, os.environ.get("SWEEP_OUT", "out/bench_sweep"))
        if "paving" in parts:
            paving(client)


if __name__ == "__main__":
    main(sys.argv[1:])
