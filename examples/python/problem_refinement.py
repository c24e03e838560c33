"""The automatic δ and the scheduling of a problem file (docs/cli.md, thesis 8.3).

Automatic δ: the robot on a line of examples/problems/line_ranges.toml (x' = v,
v = cos(t) ± 0.01, an unknown start, ranges to beacons at uncertain times; the stated
bounds through example_args.bound) solved with the file's hand-picked δ, then with
delta="auto": from 64 slices, every slice halved (refine="halving") or only the slices
thick over their gates split (refine="regions"), until the mean thickness changes by
less than 1 %. The figure: mean thickness against the number of slices of each step.
Each step is a guaranteed enclosure: the truth x(t) = sin(t) + 1 is inside every result.

Scheduling: the order within a round of the propagation, FIFO (as woken) or by expected
contraction over cost (Scheduling.Priority). With the wake ratio 0 both run to the same
fixed point, bit for bit; only the contractor runs differ. Shown with
ContractorNetwork.set_scheduling on the dead reckoning network (3.18) and with the
keyword scheduling="fifo" | "priority" of sillage.solve (`sillage solve --scheduling`)
on the line of ranges. Exits 1 when a check fails."""
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sillage  # noqa: E402
from example_args import bound, check_stats, out_dir, print_result, run  # noqa: E402
from sillage import CtcFunction, Function, Interval, IntervalVector, Scheduling, TDomain, Tube, TubeVector  # noqa: E402

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"


def line_text(extra=""):
    """line_ranges.toml, its stated bounds through bound(), data paths absolute."""
    text = (PROBLEMS / "line_ranges.toml").read_text()
    v = bound(Interval(-0.01, 0.01))
    text = text.replace('"cos(t) + [-0.01, 0.01]"', f'"cos(t) + [{v.lb()!r}, {v.ub()!r}]"')
    text = text.replace("time_error = 0.01", f"time_error = {bound(0.01)!r}")
    text = text.replace("errors = { r = 0.001 }", f"errors = {{ r = {bound(0.001)!r} }}")
    return text.replace('file = "data/', f'file = "{PROBLEMS.as_posix()}/data/') + extra


def truth_inside(r):
    """True if the result is non-empty and x(t) = sin(t) + 1 is inside x at 201 times."""
    if r.empty:
        print(f"    NO SOLUTION: {r.why_empty}")
        return False
    x = r.domains["x"]
    return all(x(0.1 * i).contains(math.sin(0.1 * i) + 1) for i in range(201))


def automatic_delta(path):
    """The file's δ against delta="auto" with both refinements: (ok, {label: schedule})."""
    runs = {"file's δ": sillage.solve(path),
            "auto, halving": sillage.solve(path, delta="auto", refine="halving"),
            "auto, regions": sillage.solve(path, delta="auto", refine="regions")}
    ok = True
    print("Automatic δ on line_ranges.toml (mean thickness of x and v, summed)")
    for label, r in runs.items():
        inside = truth_inside(r)
        ok = ok and inside
        last = r.schedule[-1]
        print(f"  {label:14s} {len(r.schedule):2d} step(s), {last['slices']:6d} slices, thickness "
              f"{last['mean_thickness']:.4g}, {r.build_seconds() + r.contract_seconds():.2f} s, truth inside: {inside}")
    if ok:  # finer slices, thinner tubes: both automatic results beat the hand-picked δ
        file_thickness = runs["file's δ"].schedule[-1]["mean_thickness"]
        ok = all(runs[k].schedule[-1]["mean_thickness"] < file_thickness for k in ("auto, halving", "auto, regions"))
    return ok, {label: r.schedule for label, r in runs.items()}


def same_tube(a, b):
    """Bit for bit the same slices and gates (on TDomains built apart: == also asks the same TDomain)."""
    return a.nb_slices() == b.nb_slices() and all(a.slice(k) == b.slice(k) for k in range(a.nb_slices())) and \
        all(a.gate(k) == b.gate(k) for k in range(a.nb_slices() + 1))


def dead_reckoning_network(td, scheduling):
    """CN (3.18): x' = v, v1 = x4 cos x3, v2 = x4 sin x3, v3 = u1, v4 = u2, x(0) in x0,
    run to the true fixed point (ratio 0) in the given order: (x, stats)."""
    c = bound(Interval(-1, 1)) / Interval(100)
    x, v = TubeVector(td, 4), TubeVector(td, 4)
    x.set_gate(0, IntervalVector([bound(Interval(-1, 1)), bound(Interval(-1, 1)), Interval.half_pi() + c, c]))
    v[2] = Tube(td, "-9/20*cos(t/5) + [-0.001,0.001]")
    v[3] = Tube(td, "1/10 + sin(t/4) + [-0.001,0.001]")
    cn = sillage.ContractorNetwork()
    cn.set_ratio(0.0)
    cn.set_scheduling(scheduling)
    cn.add(CtcFunction(Function(["x3", "x4", "v"], "x4*cos(x3) - v")), [x[2], x[3], v[0]])
    cn.add(CtcFunction(Function(["x3", "x4", "v"], "x4*sin(x3) - v")), [x[2], x[3], v[1]])
    cn.add(sillage.CtcDeriv(), [x, v])
    return x, cn.contract()


def scheduling(path):
    """FIFO against Priority: the same boxes, bit for bit, and their contractor runs."""
    print("Scheduling: FIFO against by expected contraction over cost (wake ratio 0)")
    td = TDomain(0.0, 32.0, 0.05)
    (xf, sf), (xp, sp) = dead_reckoning_network(td, Scheduling.Fifo), dead_reckoning_network(td, Scheduling.Priority)
    same_cn = check_stats(sf, "fifo") and check_stats(sp, "priority") and xf == xp
    print(f"  dead reckoning (ContractorNetwork.set_scheduling): FIFO {sf.contractor_calls} runs, priority "
          f"{sp.contractor_calls} runs, same tubes: {same_cn}")
    rf, rp = sillage.solve(path, scheduling="fifo"), sillage.solve(path, scheduling="priority")
    same_file = not rf.empty and not rp.empty and rp.scheduling == Scheduling.Priority and \
        all(same_tube(rf.domains[n], rp.domains[n]) for n in ("x", "v"))
    print(f"  line of ranges (sillage.solve(..., scheduling=...)): FIFO {rf.schedule[-1]['stats'].contractor_calls} "
          f"runs, priority {rp.schedule[-1]['stats'].contractor_calls} runs, same tubes: {same_file}")
    return same_cn and same_file and truth_inside(rp)


def main():
    out = out_dir(__doc__)
    path = out / "line_ranges.toml"
    path.write_text(line_text())
    ok_delta, schedules = automatic_delta(str(path))
    ratio0 = out / "line_ranges_ratio0.toml"
    ratio0.write_text(line_text("\n[network]\nratio = 0\n"))
    ok_sched = scheduling(str(ratio0))

    fig, ax = plt.subplots(figsize=(7, 4))
    for (label, steps), style in zip(schedules.items(), ["ks", "o-", "^-"]):
        ax.plot([s["slices"] for s in steps], [s["mean_thickness"] for s in steps], style, label=label)
    ax.set_xscale("log")
    ax.set_xlabel("slices")
    ax.set_ylabel("mean thickness of x and v")
    ax.set_title("Automatic δ on line_ranges.toml: one point per step")
    ax.legend()
    name = "problem_refinement_py.png"
    fig.savefig(out / name, dpi=90, bbox_inches="tight")
    ok = ok_delta and ok_sched
    print_result("problem_refinement", "automatic δ thinner than the file's, same fixed point under both schedulings"
                 if ok else "a check failed", ok,
                 [(name, "Mean thickness against slices for the file's δ and the automatic δ (halving, regions)")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
