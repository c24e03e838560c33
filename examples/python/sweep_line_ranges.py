"""A sweep of error bounds as Dask tasks (docs/distributed.md): the robot on a line of
examples/problems/line_ranges.toml solved for 3 range errors x 2 time-stamp errors, each a task on a
local cluster of 2 worker processes (sillage.distributed.sweep). How thin is the answer, and does the
truth stay inside, as each bound varies? The table and report.html (a figure per swept key, the
figures of the first task) are written in --out/sweep_line_ranges. The stated bounds, the velocity's
too (one value, set in every task), go through example_args.bound; the same sweep from the command line:

    sillage sweep examples/problems/line_ranges.toml --set constraint[1].errors.r=0.001,0.002,0.004 \\
        --set constraint[1].time_error=0.01,0.04
"""
from pathlib import Path

from example_args import bound, out_dir, print_result
from sillage import Interval, distributed

PROBLEM = Path(__file__).resolve().parents[1] / "problems" / "line_ranges.toml"


def main():
    out = out_dir(__doc__)
    v = bound(Interval(-0.01, 0.01))  # the velocity's stated error: the same in every task
    settings = {"constraint[1].errors.r": [bound(0.001) * k for k in (1, 2, 4)],
                "constraint[1].time_error": [bound(0.01) * k for k in (1, 4)],
                "var.v.value": [f"cos(t) + [{v.lb()!r}, {v.ub()!r}]"]}
    records = distributed.sweep(str(PROBLEM), settings, workers=2, out=str(out / "sweep_line_ranges"))
    for r in records:
        truth = f"{r['truth_inside']}/{r['truth_samples']}" if r.get("truth_samples") else "-"
        thickness = f"{r['mean_thickness']:.4f}" if r.get("mean_thickness") is not None else "-"
        s = r["settings"]
        print(f"  r error {s['constraint[1].errors.r']}, time error {s['constraint[1].time_error']}: {r['status']}, "
              f"truth inside {truth}, mean thickness {thickness}, {r['seconds'] * 1e3:.0f} ms on {r.get('worker', '?')}")
    solved = all(r["status"] == "solved" and r["truth_inside"] == r["truth_samples"] for r in records)
    # A looser bound never gives a thinner answer: each range error (the slowest key) at each time error.
    thickness = [r["mean_thickness"] for r in records] if solved else []
    monotone = solved and all(thickness[i] <= thickness[i + 2] for i in range(len(thickness) - 2))
    print_result("sweep_line_ranges", f"{len(records)} tasks, truth inside each: {solved}, thicker with the bounds: "
                 f"{monotone}", solved and monotone)


if __name__ == "__main__":
    main()
