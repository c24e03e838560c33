"""One outcome for long computations (outcome.h): a SIVIA on a small budget stops
with the paving so far (Status.Stopped and its reason), still an enclosure of the
full paving's solution set; a ContractorNetwork's contract_run() reports every
round to a progress hook and ends with a Summary instead of raising."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from example_args import bound, out_dir, print_result, run  # noqa: E402
from sillage import (Budget, ContractorNetwork, CtcFunction, Function, Interval, IntervalVector,  # noqa: E402
                     PavingTag, SiviaOptions, Status, sivia_run)
from sillage import plot  # noqa: E402


def two_beacon_pavings():
    """The two-beacon set inversion (sivia_two_beacons), in full and on a budget of 400 boxes."""
    x0 = IntervalVector([[-10, 14], [-10, 10]])
    g = Function(["x1", "x2"], "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.2)^2))")
    y = IntervalVector([bound(Interval(9.03, 9.83)), bound(Interval(6.94, 7.74))])
    full = sivia_run(x0, g, y, 0.01)
    partial = sivia_run(x0, g, y, 0.01, SiviaOptions(budget=Budget(max_boxes=400)))
    return full, partial


def network_rounds():
    """x = y and y = 0.9 x from [0, 1000] (the solution {0}), 12 contractor calls at most."""
    cn = ContractorNetwork()
    x = cn.create_dom(Interval(0, 1000), "x")
    y = cn.create_dom(Interval(0, 1000), "y")
    cn.add(CtcFunction(Function(["a", "b"], "a - b")), [x, y])
    cn.add(CtcFunction(Function(["a", "b"], "b - 0.9*a")), [x, y])
    rounds = []

    def on_round(p):
        rounds.append(p.round)
        print(f"    {p.where} round {p.round}: {p.work} contractor calls, x = {x}")

    cn.set_budget(Budget(max_boxes=12, progress=on_round))
    stats = cn.contract_run()
    return stats.summary, rounds, x


def main():
    out = out_dir(__doc__)
    full, partial = two_beacon_pavings()
    print("SIVIA of the two-beacon problem (eps = 0.01), in full and on a budget of 400 boxes:")
    for label, r in [("full", full), ("budget", partial)]:
        p = r.paving
        print(f"  {label:<7} {r.summary.status.name:<9} {p.nb_leaves():5d} leaves, vol(X+) = {p.outer_volume():8.4f}, "
              f"vol(X-) = {p.volume(PavingTag.Inner):7.4f}  {r.summary.reason}")
    # The robot (0, 0) and its mirror image across the beacons' line: in X+ of both pavings.
    robot = [(0.0, 0.0), (11.0230, -3.9367)]
    inside = all(r.paving.tag_at(list(q)) not in (None, PavingTag.Outside) for r in (full, partial) for q in robot)
    encloses = partial.paving.outer_volume() >= full.paving.outer_volume()
    ok = full.summary.status == Status.Converged and partial.summary.status == Status.Stopped and inside and encloses

    print("ContractorNetwork.contract_run() with a progress hook (once per round), 12 contractor calls at most:")
    summary, rounds, x = network_rounds()
    print(f"  {summary}")
    ok = ok and summary.status == Status.Stopped and rounds == list(range(1, len(rounds) + 1)) and x.contains(0)

    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    for ax, (label, r) in zip(axes, [("Converged", full), ("Stopped: 400 boxes", partial)]):
        plot.plot_paving(ax, r.paving)
        ax.plot([q[0] for q in robot], [q[1] for q in robot], "k.", markersize=6)
        ax.set_title(f"{label}: {r.paving.nb_leaves()} leaves")
        ax.set_aspect("equal")
    name = "outcome_budget_py.png"
    fig.savefig(out / name, dpi=90)
    result = (f"SIVIA {full.summary.status.name} {full.paving.nb_leaves()} leaves, on a budget "
              f"{partial.summary.status.name} {partial.paving.nb_leaves()}; network {summary.status.name} "
              f"after {len(rounds)} rounds")
    print_result("outcome_budget", result, ok,
                 [(name, "SIVIA in full (left) and stopped by its budget (right): the boxes not yet classified "
                         "are boundary (yellow), still an enclosure")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
