"""A problem as a file (docs/cli.md): the robot on a line of
examples/problems/line_ranges.toml (x' = v, v = cos(t) ± 0.01, an unknown start,
ranges to beacons at uncertain times), loaded and solved (sillage.load_problem,
sillage.solve_problem) without writing a network, its [output] truth checked
by sillage.check_truth, its warnings (none) and its memory estimate printed; the stated bounds go
through example_args.bound. The same file runs
with `sillage solve examples/problems/line_ranges.toml`. Then the loops of
examples/problems/figure_eight.toml (a path known from its velocity within
± 0.01), found by sillage.find_loops from the file's [output] loops."""
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sillage  # noqa: E402
from example_args import bound, out_dir, print_result, run  # noqa: E402
from sillage import Interval, plot  # noqa: E402

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"


def problem_text():
    """line_ranges.toml with its stated bounds passed through bound()."""
    text = (PROBLEMS / "line_ranges.toml").read_text()
    v = bound(Interval(-0.01, 0.01))
    text = text.replace('"cos(t) + [-0.01, 0.01]"', f'"cos(t) + [{v.lb()!r}, {v.ub()!r}]"')
    text = text.replace("time_error = 0.01", f"time_error = {bound(0.01)!r}")
    text = text.replace("errors = { r = 0.001 }", f"errors = {{ r = {bound(0.001)!r} }}")
    return text.replace('file = "data/', f'file = "{PROBLEMS.as_posix()}/data/')


def figure_eight_loops(out):
    """The proven loops of figure_eight.toml: its one crossing (t = pi/2, 3 pi/2)."""
    e = bound(0.01)
    text = (PROBLEMS / "figure_eight.toml").read_text().replace("[-0.01, 0.01]", f"[{-e!r}, {e!r}]")
    path = out / "figure_eight.toml"
    path.write_text(text)
    p = sillage.load_problem(str(path))
    r = sillage.solve_problem(p)
    if r.empty:
        print(f"  figure eight: NO SOLUTION: {r.why_empty}")
        return False
    tp = sillage.find_loops(p, r)
    proven = [l for l in tp.detections() if l.complete() and l.proven()]
    print(f"  figure eight: {tp.nb_detections()} detection(s), {len(proven)} proven loop(s)",
          *[f"t1 in {l.t_box()[0]}, t2 in {l.t_box()[1]}" for l in proven])
    return len(proven) == 1 and proven[0].t_box()[0].contains(math.pi / 2) and \
        proven[0].t_box()[1].contains(3 * math.pi / 2)


def tube_figure(x, path):
    """[x](t) (None: no solution) and the truth sin(t) + 1, saved to path; returns the figure."""
    fig, ax = plt.subplots(figsize=(8, 3))
    if x is not None:
        plot.plot_tube(ax, x)
    ts = [0.1 * i for i in range(201)]
    ax.plot(ts, [math.sin(t) + 1 for t in ts], "r-", lw=1)
    ax.set_title("[x](t) from examples/problems/line_ranges.toml, truth in red")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("x")
    fig.tight_layout()  # room for the title and the axis labels: a wide, short figure clips them otherwise
    fig.savefig(path, dpi=90)
    return fig


def main():
    out = out_dir(__doc__)
    path = out / "line_ranges.toml"
    path.write_text(problem_text())
    p = sillage.load_problem(str(path))
    r = sillage.solve_problem(p)
    x, v = r.domains["x"], r.domains["v"]
    truth = sillage.check_truth(p, r)  # the file's [output] truth: x, a miss where x is unbounded
    inside = 0
    if not r.empty:  # the truth: x(t) = sin(t) + 1, v(t) = cos(t)
        inside = sum(1 for i in range(201)
                     if x(0.1 * i).contains(math.sin(0.1 * i) + 1) and v(0.1 * i).contains(math.cos(0.1 * i)))
    print("A robot on a line localised by ranges, from a problem file")
    if r.empty:
        print(f"  NO SOLUTION: {r.why_empty}")
    else:
        print(f"  x(0) in {x(0.0)} (truth 1), max thickness {x.max_thickness():.3g}, 201 truth samples: {inside} inside")
        print(f"  the file's truth check: {truth.inside} of {truth.samples} time points inside",
              *truth.first_misses[:3])
    # What the file may state without meaning to (an eval with no row, ...): none here.
    for w in r.warnings:
        print(f"  warning: {w}")
    peak = sillage.peak_memory_estimate(p, r.schedule[-1]["slices"]) / 2**20
    print(f"  about {peak:.1f} MiB at the peak of the solve (sillage.peak_memory_estimate)")
    ok = not r.empty and not r.warnings and inside == 201 and truth.samples == 201 and truth.inside == 201 \
        and figure_eight_loops(out)
    name = "problem_file_py.png"
    plt.close(tube_figure(None if r.empty else x, out / name))
    print_result("problem_file", f"{inside}/201 truth samples inside" if not r.empty else "no solution", ok,
                 [(name, "The tube of the problem file (sillage.solve) and the truth")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
