"""Real data: CMU "Plaza 1" (../shared/data/plaza1, read in place; --data DIR to point elsewhere) as
a range-only temporal SLAM WITHOUT the beacon positions (thesis ch. 7, issue 13): the configuration
is the position p, the observation z the four ranges, each a tube built from its own measurements
and widened between them by |z'| <= the stated speed bound. A range is a time-invariant function of
the position whatever the beacons' places, so p(t1) = p(t2) => z(t1) = z(t2) needs no map. Dead
reckoning from the known start (the network of plaza1.py without the ranges) gives p and w = p';
then CtcPImpliesZ, fast to its fixed point and accurate to its fixed point, one iteration at a
time: the table of Table 7.2. The ground truth must lie in [p] at every gate after every iteration
(a miss, an empty or unbounded tube fails). The same bounds (plaza1_bounds.py) and results as
examples/cpp/plaza1_slam.cpp. Figures: the map (dead reckoning, SLAM, truth) and the thickness."""
import math
import sys
import time

import numpy as np

import plaza1
import plaza1_bounds
from bound_audit import print_audit
from example_args import check_stats, empty_text, enclosure_ok, out_dir_and_data, print_result, run
import sillage
from sillage import CtcPImpliesZ, RangeBounds, range_observation_tubes


def truth_inside(p, d):
    """The gates of p holding the ground truth."""
    gx, gy = p[0].gates_array(), p[1].gates_array()
    x, y = np.asarray(d["x"]), np.asarray(d["y"])
    return int(np.sum((gx[:, 0] <= x) & (x <= gx[:, 1]) & (gy[:, 0] <= y) & (y <= gy[:, 1])))


def mean_diameter(p):
    """Mean over the gates of the larger side of the position box (as plaza1.py)."""
    gx, gy = p[0].gates_array(), p[1].gates_array()
    return float(np.mean(np.maximum(gx[:, 1] - gx[:, 0], gy[:, 1] - gy[:, 0])))


def add_options(ap):
    plaza1_bounds.add_options(ap)
    ap.add_argument("--eps", type=float, default=5.0, metavar="S",
                    help="width of the t-boxes, s (default 5: a loop takes 40 s or more)")
    ap.add_argument("--heading-window", type=float, default=plaza1.HEADING_WINDOW, metavar="S",
                    help="CtcHeadingWindow over windows of S seconds in dead reckoning (0: none)")


def main():
    parsed = out_dir_and_data(__doc__, "plaza1", "plaza1_slam", add_options, plaza1.FILES)
    if parsed is None:
        return 0
    out, folder, args = parsed
    if not (args.eps > 0 and math.isfinite(args.eps)) or not (args.heading_window >= 0 and
                                                              math.isfinite(args.heading_window)):
        print("plaza1_slam: --eps takes a duration > 0 and --heading-window one >= 0, in seconds", file=sys.stderr)
        sys.exit(2)
    d = plaza1.load(folder)
    b = plaza1_bounds.bounds(args, d)
    ok = print_audit("plaza1_slam", plaza1_bounds.audit(d, b))

    # 1. Dead reckoning from the known start, with its velocity w = p'.
    velocity = []
    dead, stats, cpu, inside, mean_dr, _, _ = plaza1.solve(d, False, b, -1, args.heading_window, velocity=velocity)
    w = velocity[0]
    n = dead.nb_slices()
    print(f"plaza1_slam: {n} slices; dead reckoning {cpu:.2f} s CPU")
    # No solution, or an unbounded tube: an answer without truth or box figures, and a failed check.
    if not check_stats(stats, "dead reckoning") or not enclosure_ok(dead):
        why = empty_text(stats) if stats.empty else "UNBOUNDED: the position tube is unbounded"
        if not stats.empty:
            print(f"  dead reckoning: {why}")
        print_result("plaza1_slam", f"dead reckoning: {why}", False)
    print(f"  dead reckoning: truth inside {inside} / {n + 1} gates, box diameter mean {mean_dr:.1f} m, "
          f"final {dead.gate(n).max_diam():.1f} m")
    ok = inside == n + 1 and ok

    # 2. The observation: the four ranges; the beacon positions are not used.
    ids = sorted(d["beacons"])
    rb = RangeBounds(b.range_short, b.range_long, b.time_err, b.speed_max)
    inconsistent = ""  # why the observation has no solution, if it has none
    try:
        z = range_observation_tubes(dead.tdomain(), list(d["rt"]), [int(i) for i in d["rid"]], list(d["r"]), ids, rb)
        print(f"  observation: {z.size()} range tubes ({rb!r})")
    except sillage.Error as e:  # the ranges contradict each other under these bounds: an answer, not a success
        inconsistent = f"observation inconsistent: {e}"
        print(f"  {inconsistent}")
        z, ok = None, False

    # 3. C_{p=>z}, fast then accurate, one iteration at a time: Table 7.2.
    p = sillage.TubeVector(dead)
    rows, cumulated = [], 0.0
    print("\n| it | algorithm | detections | proofs | time | cumulated | contraction of [p](t_f) | mean box | truth |")
    print("|---|---|---|---|---|---|---|---|---|")
    tf0 = dead.gate(n)
    for fast in (True, False):
        cpz = CtcPImpliesZ(args.eps, fast)
        cpz.set_max_iterations(1)  # one iteration per call: the truth is checked after each
        for _ in range(50):
            if not ok:
                break
            before = (p[0].gates_array(), p[1].gates_array(), p[0].slices_array(), p[1].slices_array())
            start = time.perf_counter()
            r = cpz.contract(p, w, z)[0]
            seconds = time.perf_counter() - start
            cumulated += seconds
            tf = p.gate(n)
            contraction = 0.0 if p.is_empty() else 1 - (tf[0].diam() + tf[1].diam()) / (tf0[0].diam() + tf0[1].diam())
            rows.append(r)
            inside = 0 if p.is_empty() else truth_inside(p, d)
            mean_p = 0.0 if p.is_empty() else mean_diameter(p)
            print(f"| {len(rows)} | {'fast' if fast else 'accurate'} | {r.nb_detections} | {r.nb_proofs} | "
                  f"{seconds:.2f} s | {cumulated:.2f} s | {100 * contraction:.1f} % | {mean_p:.1f} m | "
                  f"{inside} / {n + 1} |")
            if not enclosure_ok(p) or inside != n + 1:
                print(f"  <-- FAILED: the truth left [p] (or [p] is empty or unbounded) at iteration {len(rows)}")
                ok = False
                break
            after = (p[0].gates_array(), p[1].gates_array(), p[0].slices_array(), p[1].slices_array())
            if all(np.array_equal(x, y) for x, y in zip(before, after)):
                break  # this algorithm's fixed point
    ok = ok and p.is_subset(dead)
    mean_slam = mean_diameter(p) if not p.is_empty() else math.nan
    final = p.gate(n).max_diam() if not p.is_empty() else math.nan
    if not inconsistent and not p.is_empty():
        print(f"\nbox diameter, dead reckoning -> SLAM: mean {mean_dr:.2f} -> {mean_slam:.2f} m, "
              f"final {dead.gate(n).max_diam():.2f} -> {final:.2f} m")

    figures = []
    if not p.is_empty():
        tx, ty = sillage.Trajectory(list(d["t"]), list(d["x"])), sillage.Trajectory(list(d["t"]), list(d["y"]))
        grey, blue = sillage.TubeStyle(), sillage.TubeStyle()
        grey.slices = sillage.Style("#dddddd", "#999999", 0.4, 1.0, "dead reckoning", "dead reckoning")
        slices = blue.slices
        slices.label = "SLAM"
        blue.slices = slices
        # given the truth, the window frames it (dead reckoning alone reaches kilometres away: the note says how far)
        fig = sillage.tube_vector_figure(dead, 0, 1, "plaza1 range-only temporal SLAM (Python): dead reckoning "
                                         "(grey), SLAM (blue), truth", grey, tx, ty)
        sillage.draw_tube_vector_2d(fig, p, 0, 1, blue, tx, ty)
        fig.save(str(out / "plaza1_slam_map_py.svg"))
        figures.append(("plaza1_slam_map_py.svg", "plaza1 temporal SLAM map: DR tube, SLAM tube, truth, Python"))
    proofs = max((r.nb_proofs for r in rows), default=0)
    # An empty [p] is an answer (no trajectory fits), without box figures.
    result = (inconsistent or
              (f"EMPTY after iteration {len(rows)} of C_{{p=>z}} (no solution: the bounds or the data are inconsistent)"
               if p.is_empty() else
               f"{len(rows)} iterations, at most {proofs} loop proofs; mean box {mean_slam:.2f} m "
               f"(dead reckoning {mean_dr:.2f} m), final {final:.2f} m; {cumulated:.2f} s"))
    print_result("plaza1_slam", result, ok, figures)


if __name__ == "__main__":
    run(main)
