"""One solve as a self-contained task (docs/distributed.md): what goes over the wire and what comes back.

A ``ProblemTask`` holds the problem's text (with the swept keys already set) and either the bytes of
its data tables (``ship="data"``: the worker writes them to a temporary folder) or their absolute
paths (``ship="paths"``: a filesystem the workers share). ``run_task`` runs on a worker and returns a
compact record (a dict of numbers and short strings), plus the pickled map variables of the tasks
asked for a map.
"""
import dataclasses
import hashlib
import json
import os
import socket
import tempfile
import time
import warnings
from dataclasses import dataclass, field

SHIP_MODES = ("data", "paths")


@dataclass
class ProblemTask:
    """A problem file ready to solve anywhere: index in the batch, file, text, data, settings."""

    index: int
    file: str  # the path as the user gave it: the name in messages and in the table
    text: str
    settings: dict = field(default_factory=dict)  # {key: TOML value text} set in the text
    data: dict = field(default_factory=dict)  # ship="data": {table name: (file name, bytes)}
    keep_map: bool = False  # send the map variables back (the report's map of this task)

    @property
    def label(self):
        """The file, then the settings: 'plaza1.toml time_error=0.2 track=0.05'."""
        name = os.path.basename(self.file)
        return " ".join([name] + [f"{k}={v}" for k, v in self.settings.items()])


ProblemTask.__init__.__doc__ = "A task from its fields, in order: index, file, text, settings, data, keep_map."


def toml_string(text):
    """A TOML basic string for text (JSON's escapes are TOML's)."""
    return json.dumps(text)


def make_task(index, path, settings=None, ship="data", keep_map=False):
    """The task of the problem file at path with each {key: value} of settings set (sillage.set_problem_key).

    The text is parsed here, so that a bad key, value or file is an error before anything is sent.
    """
    import sillage

    if ship not in SHIP_MODES:
        raise ValueError(f"ship: found {ship!r}, expected one of {', '.join(SHIP_MODES)}")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    settings = dict(settings or {})
    for key, value in settings.items():
        text = sillage.set_problem_key(text, path, key, value)
    problem = sillage.parse_problem(text, path)
    data = {}
    for name, data_path in problem.data_files.items():
        if ship == "data":
            with open(data_path, "rb") as f:
                data[name] = (os.path.basename(data_path), f.read())
        else:
            text = sillage.set_problem_key(text, path, f"data.{name}.file", toml_string(os.path.abspath(data_path)))
    return ProblemTask(index, path, text, settings, data, keep_map)


def _problem_here(task, folder):
    """The task's problem on this machine: its tables written into folder when they travelled with it."""
    import sillage

    text = task.text
    for k, (name, (file_name, content)) in enumerate(task.data.items()):
        os.mkdir(os.path.join(folder, str(k)))  # one folder per table: two tables may share a file name
        local = os.path.join(folder, str(k), file_name)
        with open(local, "wb") as f:
            f.write(content)
        text = sillage.set_problem_key(text, task.file, f"data.{name}.file", toml_string(local))
    return sillage.parse_problem(text, task.file)


def _mean_width(value):
    """The mean finite width of a domain's slices (tubes) or components (intervals, boxes); None if unbounded."""
    import numpy as np

    import sillage

    if isinstance(value, sillage.Tube):
        a = value.slices_array()
    elif isinstance(value, sillage.TubeVector):
        a = np.concatenate([value[i].slices_array() for i in range(len(value))])
    elif isinstance(value, sillage.Interval):
        a = np.array([[value.lb(), value.ub()]])
    else:
        a = np.asarray(value.to_numpy()).reshape(-1, 2)
    w = a[:, 1] - a[:, 0]
    w = w[np.isfinite(w) & (w >= 0)]
    return float(w.mean()) if len(w) else None


def _status(result):
    if result.empty:
        return "no solution"
    return "stopped" if result.stopped else "solved"


def _truth(problem, result):
    """(inside, samples) of the file's [output] truth; (None, None) without one."""
    import sillage

    try:
        check = sillage.check_truth(problem, result)
    except sillage.Error:
        return None, None
    return check.inside, check.samples


def _map_variables(text):
    """The variables the file's [output] maps draw (their names before '['), else those of its plots."""
    import tomllib

    output = tomllib.loads(text).get("output", {})
    axes = [axis for pair in output.get("maps", []) for axis in pair] or output.get("plots", [])
    return sorted({axis.split("[")[0] for axis in axes})


def run_task(task, solve_options=None, threads=1):
    """Solves the task on this worker with at most `threads` threads (a Dask worker thread is one task,
    one core): the record of the solve ('error' and the message if it failed)."""
    import sillage

    start = time.perf_counter()
    record = {"index": task.index, "file": task.file, "label": task.label, "settings": dict(task.settings),
              "worker": f"{socket.gethostname()}:{os.getpid()}"}
    try:
        with tempfile.TemporaryDirectory(prefix="sillage-task-") as folder, sillage.ThreadLimit(threads):
            problem = _problem_here(task, folder)
            result = sillage.solve_problem(problem, **(solve_options or {}))
            step = result.schedule[-1]
            domains = result.domains
            inside, samples = _truth(problem, result)
            record.update(status=_status(result), why=result.why_empty or result.stopped, delta=step["delta"],
                          slices=step["slices"], mean_thickness=step["mean_thickness"],
                          solve_seconds=result.build_seconds() + result.contract_seconds(),
                          truth_inside=inside, truth_samples=samples,
                          truth_fraction=inside / samples if samples else None,
                          widths={name: _mean_width(v) for name, v in domains.items()})
            if task.keep_map and not result.empty:
                record["maps"] = {name: domains[name] for name in _map_variables(task.text) if name in domains}
    except Exception as e:  # noqa: BLE001 - a bad file is a row of the table, not a failed batch
        record.update(status="error", why=f"{type(e).__name__}: {e}" if not isinstance(e, sillage.Error) else str(e))
    record["seconds"] = time.perf_counter() - start
    return record


def _tables_digest(data):
    h = hashlib.sha256()
    for name, (file_name, content) in sorted(data.items()):
        h.update(f"{name}\0{file_name}\0{len(content)}\0".encode())
        h.update(content)
    return h.hexdigest()


def _tables(data):
    """A task that gives its argument: the tables of a sweep as one task of the graph."""
    return data


def share_tables(client, tasks):
    """(task, None) or (task without its tables, future of the tables) per task: a set of tables that several
    tasks read (a sweep's) goes to the cluster once, as a task that gives it (not a scattered copy, lost
    with its worker: the scheduler keeps the task and runs it again), copied to every worker before the
    tasks start; the tables of one task stay with it."""
    digests = [_tables_digest(t.data) if t.data else None for t in tasks]
    counts = {d: digests.count(d) for d in set(digests)}
    futures, items = {}, []
    for t, digest in zip(tasks, digests):
        if digest is None or counts[digest] < 2:
            items.append((t, None))
            continue
        if digest not in futures:
            with warnings.catch_warnings():  # sent once on purpose: Dask's advice is for a copy per task
                warnings.filterwarnings("ignore", message="Large object", category=UserWarning)
                futures[digest] = client.submit(_tables, t.data, key=f"sillage-tables-{digest[:16]}", pure=False)
        items.append((dataclasses.replace(t, data={}), futures[digest]))
    if futures:  # on every worker: else Dask runs the tasks where the tables are, all on one worker
        client.replicate(list(futures.values()))
    return items


def run_shared_task(item, solve_options=None, threads=1):
    """run_task on a (task, tables) pair of share_tables, the tables already fetched by Dask."""
    task, tables = item
    return run_task(dataclasses.replace(task, data=tables) if tables else task, solve_options, threads)
