"""Outliers: a robot localised from ranges to 20 beacons, three of which are
wrong. The strict intersection of the rings is empty (inconsistent data);
GOMNE finds the smallest number q of wrong ranges that makes the data
consistent, names the wrong ranges and locates the robot. Exits non-zero if
q, the outliers or the truth check disagree."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from example_args import bound, out_dir, print_result, run  # noqa: E402
from sillage import CtcFunction, CtcInter, Function, Interval, IntervalVector, gomne, sivia  # noqa: E402
from sillage import plot  # noqa: E402

# (x, y, measured range +-0.1); truth (3.25, -1.5); ranges 4, 11, 16 are off by +9, -6.5, +12.
BEACONS = [(-15, 16, 25.27), (1, 25, 26.57), (-32, 25, 44.1), (-26, -10, 30.5), (10, 27, 38.31),
           (-40, -30, 51.83), (-9, -22, 23.92), (-23, -5, 26.53), (26, 24, 34.16), (35, -27, 40.76),
           (-2, -12, 11.77), (22, 24, 25.18), (27, 5, 24.64), (-32, -23, 41.25), (-21, -34, 40.57),
           (-10, 17, 22.8), (30, -26, 48.31), (-32, 13, 38.09), (-16, 6, 20.65), (5, -5, 3.87)]
TRUTH = [3.25, -1.5]
WRONG = [4, 11, 16]
EPS = 0.1


def ring(b):
    e = bound(0.1)  # the stated range error of the simulated sensor
    return Interval(b[2] - e, b[2] + e)


def draw(ax, r):
    for i, b in enumerate(BEACONS):
        bad = i in r.outliers
        plot.plot_ring(ax, b[:2], ring(b), facecolor="#fc9272" if bad else "#9ecae1", alpha=0.6 if bad else 0.35)
        ax.plot(*b[:2], "o", color="red" if bad else "navy", markersize=3)
    plot.plot_boxes(ax, r.leaves, facecolor="#ffd92f", edgecolor="black")
    plot.plot_box(ax, r.box, edgecolor="black", linewidth=1.2)
    ax.plot(*TRUTH, "k.", markersize=6)
    ax.set_aspect("equal")


def main():
    out = out_dir(__doc__)
    x0 = IntervalVector([[-50, 50], [-50, 50]])
    ctcs = [CtcFunction(Function(["x1", "x2"], f"sqrt((x1 - ({b[0]}))^2 + (x2 - ({b[1]}))^2)"), ring(b))
            for b in BEACONS]

    inconsistent = len(sivia(x0, CtcInter(ctcs), EPS).outer()) == 0
    r = gomne(ctcs, x0, eps=EPS)
    truth_in = r.box.contains(TRUTH)
    print(f"Range-only localisation, {len(ctcs)} beacons, ranges +-0.1, eps = {EPS}")
    print(f"  strict intersection: {'empty -> inconsistent data' if inconsistent else 'not proven empty'}")
    print(f"  GOMNE: q = {r.q}; proven outliers (if at most q are wrong): {r.outliers}, injected: {WRONG}")
    print(f"  robot in {r.box} ({len(r.leaves)} leaves), truth inside: {'yes' if truth_in else 'NO'}")
    ok = inconsistent and r.q == len(WRONG) and r.outliers == WRONG and truth_in

    fig, axes = plt.subplots(1, 2, figsize=(12, 6))
    draw(axes[0], r)
    axes[0].set_xlim(-50, 50)
    axes[0].set_ylim(-50, 50)
    axes[0].set_title(f"20 ranges, proven outliers in red (q = {r.q})")
    draw(axes[1], r)
    axes[1].set_xlim(r.box[0].lb() - 1, r.box[0].ub() + 1)
    axes[1].set_ylim(r.box[1].lb() - 1, r.box[1].ub() + 1)
    axes[1].set_title("q-relaxed set (yellow), its hull, the truth")
    name = "outliers_ranges_py.png"
    fig.savefig(out / name, dpi=90)
    result = f"strict: {'inconsistent' if inconsistent else '?'}; q = {r.q}, outliers {r.outliers}"
    print_result("outliers_ranges", result, ok, [(name, "GOMNE on 20 ranges with 3 outliers (matplotlib)")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
