"""Set inversion for the two-beacon range-only problem of thesis 2.4.3 (Table
2.2): the robot at (0, 0) cannot be told from its mirror image across the line
of the beacons. Plain SIVIA (Alg. 1) and SIVIA with separators (Fig. 2.13).
SIVIA uses every thread of the machine; on one thread (ThreadLimit) the paving
is the same."""
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from example_args import bound, out_dir, print_result, run  # noqa: E402
from sillage import Function, Interval, IntervalVector, PavingTag, SepFunction, ThreadLimit, sivia  # noqa: E402
from sillage import plot  # noqa: E402


def main():
    out = out_dir(__doc__)
    x0 = IntervalVector([[-10, 14], [-10, 10]])
    g = Function(["x1", "x2"], "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.2)^2))")
    y = IntervalVector([bound(Interval(9.03, 9.83)), bound(Interval(6.94, 7.74))])
    mirror = (11.0230, -3.9367)  # (0, 0) reflected across the beacons' line

    runs = []
    for label, solve in [("plain SIVIA", lambda: sivia(x0, g, y, 0.01)),
                         ("SIVIA + separators", lambda: sivia(x0, SepFunction(g, y), 0.01))]:
        t0 = time.perf_counter()
        p = solve()
        runs.append((label, p, time.perf_counter() - t0))

    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    ok = True
    print("Two-beacon set inversion, thesis Table 2.2 / Fig. 2.13, eps = 0.01")
    for ax, (label, p, seconds) in zip(axes, runs):
        print(f"  {label:<20} {p.nb_leaves():6d} leaves: {p.count(PavingTag.Inner)} inner, "
              f"{p.count(PavingTag.Boundary)} boundary, {p.count(PavingTag.Outside)} outside, "
              f"vol(X+) = {p.outer_volume():.4f}, {seconds * 1e3:.1f} ms")
        for q in [(0.0, 0.0), mirror]:
            ok = ok and p.tag_at(list(q)) not in (None, PavingTag.Outside)
        plot.plot_paving(ax, p)
        ax.plot([0, mirror[0]], [0, mirror[1]], "k.", markersize=6)
        ax.set_title(f"{label} (eps = 0.01)")
        ax.set_aspect("equal")
    print(f"  (0, 0) and its mirror image lie in the outer approximation: {'yes' if ok else 'NO'}")
    threads = ThreadLimit.current()
    with ThreadLimit(1):
        t0 = time.perf_counter()
        alone = sivia(x0, g, y, 0.01)
        seconds = time.perf_counter() - t0
    same = alone == runs[0][1]
    print(f"  plain SIVIA on 1 thread (ThreadLimit) against {threads}: the same paving: {'yes' if same else 'NO'} "
          f"({seconds * 1e3:.1f} ms against {runs[0][2] * 1e3:.1f} ms)")
    ok = ok and same
    name = "sivia_two_beacons_py.png"
    fig.savefig(out / name, dpi=90)
    result = "; ".join(f"{label}: {p.nb_leaves()} boxes" for label, p, _ in runs)
    print_result("sivia_two_beacons", result, ok, [(name, "Fig. 2.13 (matplotlib): plain SIVIA and separators")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
