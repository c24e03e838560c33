"""Beyond one machine (docs/distributed.md): batches, sweeps and pavings as Dask tasks.

    from sillage import distributed
    records = distributed.batch(["a.toml", "b.toml"], workers=2)            # a local cluster
    records = distributed.sweep("plaza1.toml", {"constraint[8].time_error": [0.1, 0.2]},
                                scheduler="tcp://10.0.0.1:8786", out="out/sweep")
    paving = distributed.sivia([[-3, 3]] * 4, ["a", "b", "c", "d"], "a^2+b^2+c^2+d^2", [1, 2], 0.01)

The same from the command line: ``sillage batch P1.toml P2.toml ...`` and ``sillage sweep P.toml
--set KEY=V1,V2 ...`` run ``python3 -m sillage.distributed``. Each task carries its problem's text
and data (or the data's paths on a shared filesystem: ship="paths"); results are compact records,
one per task, whatever worker died on the way.
"""
import argparse
import os
import sys
import time

from .distributed_grid import TomlText, grid, parse_setting, toml_value
from .distributed_paving import InversionSpec, distributed_paving
from .distributed_report import write_report
from .distributed_run import DEFAULT_RETRIES, Progress, cluster_client, run_tasks
from .distributed_tasks import make_task, run_shared_task, share_tables

__all__ = ["batch", "sweep", "sivia", "kernel_sivia", "run_problem_tasks", "main"]


def run_problem_tasks(tasks, client=None, scheduler=None, workers=2, retries=DEFAULT_RETRIES, progress=None,
                      solve_options=None):
    """The records of the tasks (distributed_tasks.make_task), solved on client's cluster, or the scheduler's
    at `scheduler`, or a new local cluster of `workers` processes."""
    if client is not None:
        return run_tasks(client, run_shared_task, share_tables(client, tasks), retries=retries, progress=progress,
                         solve_options=solve_options)
    with cluster_client(scheduler, workers) as own:
        return run_problem_tasks(tasks, own, retries=retries, progress=progress, solve_options=solve_options)


def _finish(records, out, title, start):
    if out:
        write_report(records, out, title, time.perf_counter() - start)
    return records


def batch(paths, client=None, scheduler=None, workers=2, ship="data", out=None, maps=(0,), retries=DEFAULT_RETRIES,
          progress=None, solve_options=None):
    """Solves each problem file as a task: one record per file, in order (out: the table and report.html there)."""
    start = time.perf_counter()
    tasks = [make_task(i, p, ship=ship, keep_map=i in maps and out is not None) for i, p in enumerate(paths)]
    records = run_problem_tasks(tasks, client, scheduler, workers, retries, progress, solve_options)
    return _finish(records, out, f"sillage batch: {len(paths)} problems", start)


def sweep(path, settings, client=None, scheduler=None, workers=2, ship="data", out=None, maps=(0,),
          retries=DEFAULT_RETRIES, progress=None, solve_options=None):
    """Solves the problem file once per combination of settings {key: [values]} (Python values, or TomlText as
    the command line gives them): one record per combination, the first key varying slowest."""
    start = time.perf_counter()
    texts = {k: [toml_value(v) for v in vs] for k, vs in settings.items()}
    tasks = [make_task(i, path, s, ship=ship, keep_map=i in maps and out is not None)
             for i, s in enumerate(grid(texts))]
    records = run_problem_tasks(tasks, client, scheduler, workers, retries, progress, solve_options)
    return _finish(records, out, f"sillage sweep: {os.path.basename(path)}, {len(tasks)} settings", start)


def sivia(x0, variables, expr, y, eps, client=None, scheduler=None, workers=2, depth=None, max_boxes=None):
    """sillage.sivia(x0, Function(variables, expr), y, eps), its subtrees paved as tasks: the same Paving."""
    spec = InversionSpec("sivia", tuple(variables), expr, y=y)
    return _pave(spec, x0, eps, client, scheduler, workers, depth, max_boxes)


def kernel_sivia(x0, variables, expr_lo, expr_hi, eps, client=None, scheduler=None, workers=2, depth=None,
                 max_boxes=None):
    """sillage.kernel_sivia(x0, Function(variables, expr_lo), Function(variables, expr_hi), eps) as tasks."""
    spec = InversionSpec("kernel", tuple(variables), expr_lo, expr_hi=expr_hi)
    return _pave(spec, x0, eps, client, scheduler, workers, depth, max_boxes)


def _pave(spec, x0, eps, client, scheduler, workers, depth, max_boxes):
    if client is not None:
        return distributed_paving(client, spec, x0, eps, depth, max_boxes)
    with cluster_client(scheduler, workers) as own:
        return distributed_paving(own, spec, x0, eps, depth, max_boxes)


def _arguments(argv):
    parser = argparse.ArgumentParser(prog="sillage", description="problem files as Dask tasks (docs/distributed.md)")
    commands = parser.add_subparsers(dest="command", required=True)
    for name, help_text in (("batch", "solve many problem files"), ("sweep", "solve one problem over a grid of values")):
        c = commands.add_parser(name, help=help_text)
        if name == "batch":
            c.add_argument("problems", nargs="+", help="problem files (TOML)")
        else:
            c.add_argument("problem", help="the problem file (TOML)")
            c.add_argument("--set", action="append", default=[], metavar="KEY=V1,V2",
                           help="a key of the file and its values, as written in TOML (repeat for a grid)")
        c.add_argument("--out", help="output directory (default out/batch or out/<problem>_sweep)")
        c.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
        c.add_argument("--scheduler", help="an existing Dask scheduler, tcp://HOST:PORT (--workers then unused)")
        c.add_argument("--ship", choices=("data", "paths"), default="data",
                       help="send each task its data (default) or only its paths (a filesystem the workers share)")
        c.add_argument("--retries", type=int, default=DEFAULT_RETRIES, help="retries of a task that raised")
        c.add_argument("--maps", default="0", help="tasks whose map the report draws, indices (default 0)")
        c.add_argument("--quiet", action="store_true", help="no progress line, no summary")
    return parser.parse_args(argv)


def _print_summary(records, out):
    counts = {}
    for r in records:
        counts[r["status"]] = counts.get(r["status"], 0) + 1
    print(", ".join(f"{n} {s}" for s, n in sorted(counts.items())) + f"; report: {os.path.join(out, 'report.html')}")
    for r in records:
        if r["status"] == "error":
            print(f"task {r['index']} ({r.get('label', '')}): {r['why']}", file=sys.stderr)


def main(argv=None):
    """`sillage batch` / `sillage sweep`: exit status 0 if every task solved, 1 if one had no solution or
    stopped, 2 for bad input (or a task's error), 130 on Ctrl-C."""
    a = _arguments(argv)
    try:
        maps = tuple(int(m) for m in a.maps.split(",") if m.strip())
        if a.workers < 1:
            raise ValueError(f"--workers: found {a.workers}, expected a number of worker processes >= 1")
        common = dict(scheduler=a.scheduler, workers=a.workers, ship=a.ship, maps=maps, retries=a.retries,
                      progress=Progress(0, enabled=False if a.quiet else None))
        if a.command == "batch":
            out = a.out or os.path.join("out", "batch")
            common["progress"].total = len(a.problems)
            records = batch(a.problems, out=out, **common)
        else:
            out = a.out or os.path.join("out", os.path.splitext(os.path.basename(a.problem))[0] + "_sweep")
            settings = {}
            for s in a.set:
                key, values = parse_setting(s)
                settings[key] = [TomlText(v) for v in values]
            if not settings:
                raise ValueError("sweep: expected at least one --set KEY=V1,V2,...")
            common["progress"].total = len(grid(settings))
            records = sweep(a.problem, settings, out=out, **common)
    except KeyboardInterrupt:
        print("sillage: cancelled (Ctrl-C): the tasks were cancelled", file=sys.stderr)
        return 130
    except (ValueError, OSError, RuntimeError) as e:
        print(f"sillage: {e}", file=sys.stderr)
        return 2
    if not a.quiet:
        _print_summary(records, out)
    statuses = {r["status"] for r in records}
    return 2 if "error" in statuses else 1 if statuses - {"solved"} else 0


if __name__ == "__main__":
    sys.exit(main())
