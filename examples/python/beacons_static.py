"""Static range-only localization of thesis 2.3.3 (Table 2.1): three beacons,
bounded ranges, an unknown position in [-inf, inf]^2, one contractor per range
constraint (2.35), propagated to the fixed point by a ContractorNetwork."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from example_args import bound, empty_exit, enclosure_ok, out_dir, print_result, run  # noqa: E402
from sillage import ContractorNetwork, CtcFunction, Function, Interval, IntervalVector  # noqa: E402
from sillage import plot  # noqa: E402

BEACONS = [((-0.5, 4.0), bound(Interval(3.63, 4.43))),
           ((-2.5, -2.5), bound(Interval(3.13, 3.93))),
           ((2.5, -0.5), bound(Interval(2.15, 2.95)))]


def main():
    out = out_dir(__doc__)
    cn = ContractorNetwork()
    x = IntervalVector(2)  # the unknown position: [-inf, inf]^2
    rhos = []
    for (bx, by), rho in BEACONS:
        g = Function(["x1", "x2", "rho"], f"sqrt((x1 - {bx!r})^2 + (x2 - {by!r})^2) - rho")
        rhos.append(Interval(rho.lb(), rho.ub()))
        cn.add(CtcFunction(g), [x, rhos[-1]])
    cn.set_name(x, "x")  # named: an empty network says which domain emptied
    stats = cn.contract()
    if stats.empty:
        return empty_exit("beacons_static", stats)
    ok = enclosure_ok(x) and x.contains([0.0, 0.0])

    print("Static range-only localization, thesis Table 2.1 (robot at (0, 0))")
    print(f"  final box:   {x}")
    print(f"  contains (0, 0): {'yes' if ok else 'NO'}")
    print(f"  iterations:  {stats.iterations} (the thesis reports 7), contractor calls: {stats.contractor_calls},"
          f" time: {stats.time * 1e3:.3g} ms")

    fig, ax = plt.subplots(figsize=(6, 6))
    for (bx, by), rho in BEACONS:
        plot.plot_ring(ax, (bx, by), rho)
        plot.plot_box(ax, IntervalVector([[bx - 0.2, bx + 0.2], [by - 0.2, by + 0.2]]), facecolor="#d62728")
    plot.plot_box(ax, x, facecolor="#ffd24d", edgecolor="#a07800")
    ax.plot([0], [0], "k.")
    ax.set_xlim(-7.5, 7.5)
    ax.set_ylim(-7.5, 9)
    ax.set_aspect("equal")
    ax.set_title("Static range-only localization (Table 2.1)")
    name = "beacons_static_py.png"
    fig.savefig(out / name, dpi=90)
    print_result("beacons_static", f"{stats.iterations} iterations, box {x}", ok,
                 [(name, "Table 2.1 (matplotlib): rings, beacons and the contracted box")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
