"""A problem file run online through a real pipe (docs/online.md, "From a problem file"): the
low-cost beacons of examples/problems/lowcost_beacons.toml (thesis 5.3: ranges whose times are only
known within [t_lb, t_ub]) fed row by row to `sillage stream` as JSON Lines on its stdin, in the
order a robot receives them (OnlineProblem.recorded_rows), while the estimates are read from its
stdout as they come. The same rows replayed in Python (sillage.replay_problem) check the truth
against the online tubes as time passes and solve the file in batch; the matplotlib figure draws the
side of the position box now (online, from the pipe) against the batch box at the same time (which
knows the future). The last estimate of the pipe must be the replay's, bit for bit."""
import json
import subprocess
import threading
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sillage  # noqa: E402
from example_args import bound, out_dir, print_result, run  # noqa: E402
from sillage import Interval  # noqa: E402

PROBLEM = Path(__file__).resolve().parents[1] / "problems" / "lowcost_beacons.toml"
SILLAGE = Path(sillage.__file__).resolve().parents[2] / "tools" / "sillage" / "sillage"


def problem_file(out):
    """lowcost_beacons.toml with its stated bounds passed through bound(), written into out."""
    text = PROBLEM.read_text()
    for e in ("0.01", "0.001"):
        b = bound(Interval(-float(e), float(e)))
        text = text.replace(f"[-{e}, {e}]", f"[{b.lb()!r}, {b.ub()!r}]")
    text = text.replace("errors = { z = 0.5 }", f"errors = {{ z = {bound(0.5)!r} }}")
    path = out / "lowcost_beacons_stream.toml"
    path.write_text(text.replace('file = "data/', f'file = "{PROBLEM.parent.as_posix()}/data/'))
    return path


def stream(path, rows):
    """The estimates `sillage stream` writes while the rows are written to it."""
    proc = subprocess.Popen([str(SILLAGE), "stream", str(path)], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)

    def feed():
        for row in rows:
            proc.stdin.write(sillage.stream_line(row) + "\n")
        proc.stdin.close()

    writer = threading.Thread(target=feed)
    writer.start()
    estimates = [json.loads(line) for line in proc.stdout]
    writer.join()
    errors = proc.stderr.read()
    return estimates, proc.wait(), errors


def side(box):
    return max(hi - lo for lo, hi in box[:2]) if box and all(b is not None and None not in b for b in box[:2]) \
        else float("inf")


def main():
    out = out_dir(__doc__.splitlines()[0])
    path = problem_file(out)
    p = sillage.load_problem(str(path))
    rows = sillage.OnlineProblem(p).recorded_rows()
    estimates, status, errors = stream(path, rows)
    if errors:
        print("  sillage stream: " + errors.strip().replace("\n", "\n  "))
    r = sillage.replay_problem(p)
    last = r.online[-1][r.outputs.index("x")]
    same = bool(estimates) and [[b.lb(), b.ub()] for b in last] == estimates[-1]["x"]
    print(f"  {len(rows)} rows piped, {len(estimates)} estimates read back (exit status {status})")
    print(f"  truth: {r.truth_inside} of {r.truth_samples} samples inside the online tubes, {r.truth_unbounded} "
          f"in a box still unbounded, {r.truth_samples - r.truth_inside - r.truth_unbounded} outside")
    print(f"  median {1e6 * r.latency_quantile(0.5):.0f} us per row; the online box holds the batch one at "
          f"{r.online_holds_batch()} of {len(r.t)} times, side ratio {r.mean_side_ratio(0):.2f}")
    fig, ax = plt.subplots(figsize=(8, 3.2))
    ax.semilogy([e["t"] for e in estimates], [side(e["x"]) for e in estimates], "r-", lw=1.2,
                label="online: the box of (x1, x2) now, read from the pipe")
    j = r.outputs.index("x")
    ax.semilogy(r.t, [max(b[0].diam(), b[1].diam()) for b in (o[j] for o in r.batch)], "b-", lw=0.8,
                label="batch: all the ranges known")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("box side (m)")
    ax.set_title("low-cost beacons through sillage stream")
    ax.legend(fontsize=8)
    fig.tight_layout()
    name = "problem_stream_py.png"
    fig.savefig(out / name, dpi=110)
    ok = status == 0 and not errors and same and not r.truth_misses and r.truth_inside > 0 and \
        r.online_holds_batch() == len(r.t)
    print_result("problem_stream", f"{len(estimates)} estimates through a pipe, truth inside {r.truth_inside} / "
                 f"{r.truth_samples} (+{r.truth_unbounded} unbounded), online holds batch {r.online_holds_batch()} / "
                 f"{len(r.t)}", ok, [(name, "low-cost beacons online through sillage stream, against the batch")])


if __name__ == "__main__":
    run(main)
