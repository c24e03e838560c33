"""Loops on real data: CMU "Plaza 1" (../shared/data/plaza1, read in place;
--data DIR to point elsewhere). A robot sweeps a plaza in a lawn-mower pattern
and crosses its own path 200 times. From the odometry alone (a distance per
0.2 s period and a heading), the t-plane (thesis ch. 6) detects the loops, and
the degree test T and the Newton test N prove some; the ground truth checks
both the bounds (integral check) and the proofs (loop check).

The same three models, bounds (plaza1_bounds.py and LOOPS_TABLE, each an option) and
checks as examples/cpp/loops_plaza1.cpp: the drifting heading (b), stated from the sensor
classes, is the check (exit status) and its bounds are audited; the (a) models use the
heading of the ground truth itself: illustrations, not guarantees, never counted
(docs/loops_real_data.md says why each bound): the detections and proofs are
the same numbers. The integral check runs on the same pairs; the integrals
between sample times are prefix sums of the slice bounds (numpy, not rounded
outward), the ones of the true crossings come from TubeAnalysis.
Figures: the t-plane and the map of each model (matplotlib)."""
import math
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection, PolyCollection

import sillage
import plaza1_bounds
import plaza1_data
from bound_audit import print_audit
from example_args import bound, out_dir_and_data, print_result, run
from sillage import Interval, TDomain, TPlane, Tube, TubeAnalysis, TubeVector
from sillage.plot_loops import LOOP_COLOURS, plot_tplane

# The bounds of the loops models beyond plaza1_bounds.py (each an option; the same as
# LoopsBounds of the C++ example): (option, attribute, value, source).
LOOPS_TABLE = [
    ("--reverse-below", "reverse_below", 0.5,
     "m/s: the odometer distance is unsigned; below this speed the robot may go either way (backing up is slow)"),
    ("--glitch-above", "glitch_above", 2.0,
     "m/s: the top speed of the robot class; a faster period is a time-stamp glitch, any direction"),
]


def models(b, args):
    """(tag, name, honest, speed (dist_rel, dist_over, dist_under), heading (ins, track, start, drift_rate)):
    the models of the C++ example, the honest one first. Honest: stated from the sensor classes,
    checked exactly, the check of the example; the (a) models use the heading of the ground truth
    itself (and, tight, bounds calibrated on this run): illustrations, compared with the tolerance
    TOL_M, never counted."""
    table = (b.dist_rel, b.dist_over, b.dist_under)
    return [
        ("gyro", f"(b) drifting heading +-({b.track + b.heading0:g} + {b.gyro_bias:g} t) rad, odometer d "
                 f"(1 +- {100 * b.dist_rel:g} %) - {b.dist_over:g} m", True, table,
         (False, b.track, b.heading0, b.gyro_bias)),
        ("ins_wide", f"(a) illustration: the truth's INS heading +-{b.track:g} rad, odometer d "
                     f"(1 +- {100 * b.dist_rel:g} %) - {b.dist_over:g} m", False, table, (True, b.track, 0.0, 0.0)),
        ("ins_tight", "(a) illustration, calibrated on this run: the truth's INS heading +-0.01 rad, odometer d "
                      "(1 +- 0.5 %) - 5 mm", False, (bound(0.005), bound(0.005), bound(0.001)),
         (True, bound(0.01), 0.0, 0.0)),
    ]


# Tolerances of the ground truth (an INS/GPS solution): positions (m), and the
# time resolution of its crossings (s): one sampling period and a bit.
TOL_M, TOL_S = 0.85, 0.25
# Map boxes wider than this (m) are dead reckoning from the start: not drawn.
MAX_MAP_BOX = 10.0


def load(folder):
    """The data (plaza1_data.load), the ground truth's t, x, y as numpy arrays."""
    d = plaza1_data.load(folder)
    d.update(t=np.asarray(d["t"]), x=np.asarray(d["x"]), y=np.asarray(d["y"]))
    return d


def slice_tube(td, slices):
    """Per-slice values; gates are hulls of their two slices (no information of their own)."""
    n = len(slices)
    gates = [slices[max(k - 1, 0)] | slices[min(k, n - 1)] for k in range(n + 1)]
    return Tube(td, slices, gates)


def velocity_tube(d, td, speed_bounds, heading_bounds, start_heading, reverse_below, glitch_above):
    """v(k) = s(k) (cos psi(k), sin psi(k)) slice by slice in interval arithmetic."""
    dist_rel, dist_over, dist_under = speed_bounds
    ins, track, start, drift_rate = heading_bounds
    dpsi = d["dpsi_ins"] if ins else d["dpsi_drift"]
    t0 = td.t(0)
    scale, offset = Interval(1 - dist_rel, 1 + dist_rel), Interval(-dist_over, dist_under)
    positive, any_direction = Interval(0, math.inf), Interval(-math.pi, math.pi)
    vx, vy = [], []
    psi = Interval(start_heading)  # psi_hat(t_k), summed with outward rounding
    for k in range(td.nb_slices()):
        dt = td.slice_width(k)
        nxt = psi + Interval(dpsi[k])
        e = track + start + drift_rate * (td.t(k + 1) - t0)
        mean_speed = d["dist"][k] / dt.mid()
        speed = ((Interval(d["dist"][k]) * scale + offset) & positive) / dt
        if mean_speed < reverse_below:
            speed = Interval(-speed.ub(), speed.ub())
        heading = (psi | nxt) + Interval(-e, e)
        if mean_speed > glitch_above:
            heading = any_direction
        vx.append(speed * sillage.cos(heading))
        vy.append(speed * sillage.sin(heading))
        psi = nxt
    return TubeVector([slice_tube(td, vx), slice_tube(td, vy)])


def thinned(t, x, y, step):
    """The points at least `step` apart (first and last kept): no crossings from a standing robot's jitter."""
    keep = [0]
    for i in range(1, len(t)):
        if i == len(t) - 1 or math.hypot(x[i] - x[keep[-1]], y[i] - y[keep[-1]]) >= step:
            keep.append(i)
    return t[keep], x[keep], y[keep]


def check_pairs(t, stride, short_span):
    """Sample pairs (i, j), i < j: every stride-th sample with every other one, then every pair
    less than short_span seconds apart not already there (check_pairs of loops_real_data.h)."""
    grid = np.arange(0, len(t), stride)
    a, b = np.triu_indices(len(grid), 1)
    i_long, j_long = grid[a], grid[b]
    # Candidates from a wider window, then the test of the C++ loop: t[j] - t[i] <= short_span.
    counts = np.searchsorted(t, t + 2 * short_span, side="right") - np.arange(len(t)) - 1
    i_short = np.repeat(np.arange(len(t)), counts)
    j_short = i_short + 1 + (np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts))
    fresh = (t[j_short] - t[i_short] <= short_span) & ((i_short % stride != 0) | (j_short % stride != 0))
    return np.concatenate([i_long, i_short[fresh]]), np.concatenate([j_long, j_short[fresh]])


def check_integrals(v, td, d, pairs, crossings):
    """The true displacements of the pairs and of the crossings (0) against the integral of [v]:
    distances (per component, the largest) from the truth to the integral, 0 when inside."""
    widths = np.diff(np.asarray(td.times()))
    gaps = np.zeros(len(pairs[0]))
    i, j = pairs
    for comp, truth in ((0, d["x"]), (1, d["y"])):
        s = v[comp].slices_array()
        lo = np.concatenate([[0.0], np.cumsum(s[:, 0] * widths)])
        hi = np.concatenate([[0.0], np.cumsum(s[:, 1] * widths)])
        disp = truth[j] - truth[i]
        g = np.maximum(0.0, np.maximum(lo[j] - lo[i] - disp, disp - (hi[j] - hi[i])))
        # an empty or unbounded integral proves nothing: never "inside"
        g[~(np.isfinite(lo[j] - lo[i]) & np.isfinite(hi[j] - hi[i]))] = np.inf
        gaps = np.maximum(gaps, g)
    analyses = [TubeAnalysis(v[0]), TubeAnalysis(v[1])]
    cross_gaps = []
    for c in crossings:
        g = 0.0
        for a in analyses:
            integral = a.integral(Interval(c.t1), Interval(c.t2))
            bounded = not integral.is_empty() and math.isfinite(integral.lb()) and math.isfinite(integral.ub())
            g = max(g, integral.lb(), -integral.ub()) if bounded else math.inf
        cross_gaps.append(g)
    times = np.asarray(td.times())
    all_gaps = np.concatenate([gaps, cross_gaps])
    t1 = np.concatenate([times[i], [c.t1 for c in crossings]])
    t2 = np.concatenate([times[j], [c.t2 for c in crossings]])
    worst = int(np.argmax(all_gaps))
    return dict(n=len(all_gaps), inside=int(np.sum(all_gaps == 0)), cm5=int(np.sum(all_gaps <= 0.05)),
                cm20=int(np.sum(all_gaps <= 0.2)), tol=int(np.sum(all_gaps <= TOL_M)),
                max_gap=float(all_gaps[worst]), worst=(t1[worst], t2[worst]))


def holds(loop, t1, t2):
    """Mask of the crossings (t1, t2 arrays) in one of the loop's boxes widened by TOL_S."""
    h = loop.t_box()
    near = (t1 >= h[0].lb() - TOL_S) & (t1 <= h[0].ub() + TOL_S) & (t2 >= h[1].lb() - TOL_S) & (t2 <= h[1].ub() + TOL_S)
    if not near.any():
        return near
    b = np.asarray(loop.boxes_array())
    inside = ((t1[:, None] >= b[None, :, 0, 0] - TOL_S) & (t1[:, None] <= b[None, :, 0, 1] + TOL_S)
              & (t2[:, None] >= b[None, :, 1, 0] - TOL_S) & (t2[:, None] <= b[None, :, 1, 1] + TOL_S))
    return near & inside.any(axis=1)


def check_loops(tp, crossings):
    """Every true crossing must lie in a detection; every proven loop must hold a true crossing."""
    t1, t2 = np.array([c.t1 for c in crossings]), np.array([c.t2 for c in crossings])
    loops = tp.detections()
    masks = [holds(l, t1, t2) for l in loops]
    any_det, in_complete, in_proven = (np.zeros(len(crossings), bool) for _ in range(3))
    c = dict(degree_zero=0, degree_unknown=0, proven=0, proven_hit=0, newton=0, newton_hit=0, counted=0,
             count_sum=0, count_match=0, spans=[], missed=[])
    for l, m in zip(loops, masks):
        inside = int(m.sum())
        any_det |= m
        if l.complete():
            in_complete |= m
            c["degree_unknown"] += l.degree() is None
            c["degree_zero"] += l.degree() == 0
        if l.proven():
            in_proven |= m
            c["proven"] += 1
            c["proven_hit"] += inside > 0
            h = l.t_box()
            c["spans"].append(h[1].mid() - h[0].mid())
            if inside == 0:
                c["missed"].append(h)
            if l.count() is not None:
                c["counted"] += 1
                c["count_sum"] += l.count()
                c["count_match"] += l.count() == inside
        if l.proven_newton():
            c["newton"] += 1
            c["newton_hit"] += inside > 0
    c.update(nb_crossings=len(crossings), in_detection=int(any_det.sum()), in_complete=int(in_complete.sum()),
             in_proven=int(in_proven.sum()))
    c["passed"] = (c["in_detection"] == c["nb_crossings"] and c["proven_hit"] == c["proven"]
                   and c["newton_hit"] == c["newton"])
    return c


def print_loops(name, tp, c, ic, seconds, detect_seconds, cpu):
    n, nc = tp.nb_detections(), tp.nb_complete_detections()
    pct = lambda k: 100.0 * k / ic["n"]
    print(name)
    print(f"  integral check, {ic['n']} pairs: truth inside {pct(ic['inside']):.2f} %, within 5 cm "
          f"{pct(ic['cm5']):.2f} %, 20 cm {pct(ic['cm20']):.2f} %, {TOL_M:.2f} m {pct(ic['tol']):.2f} %; "
          f"largest miss {ic['max_gap']:.3f} m at ({ic['worst'][0]:.2f}, {ic['worst'][1]:.2f})")
    print(f"  detections {n}: complete {nc} (degree 0: {c['degree_zero']}, undetermined: {c['degree_unknown']}), "
          f"touching the border or the diagonal {n - nc}")
    print(f"  proofs: T {tp.nb_proofs()}, N {tp.nb_newton_proofs()}; counted {c['counted']}, loops counted "
          f"{c['count_sum']} (equal to the crossings inside: {c['count_match']})")
    print(f"  true crossings {c['nb_crossings']}: in detections {c['in_detection']}, in complete ones "
          f"{c['in_complete']}, in proven ones {c['in_proven']}")
    print(f"  proven loops holding a true crossing: T {c['proven_hit']} / {c['proven']}, N {c['newton_hit']} / "
          f"{c['newton']}" + ("" if c["passed"] else "  <-- TRUTH CHECK FAILED"))
    if c["spans"]:
        print(f"  proven loops last {min(c['spans']):.0f} s to {max(c['spans']):.0f} s")
    for h in c["missed"]:
        print(f"    proven, no crossing: [{h[0].lb():.2f}, {h[0].ub():.2f}] x [{h[1].lb():.2f}, {h[1].ub():.2f}]")
    print(f"  time of detections and proofs: {seconds:.2f} s wall (detections {detect_seconds:.2f} s), "
          f"{cpu:.2f} s CPU (all threads)")


def save_figures(tp, d, crossings, out, tag, name, figures):
    """The t-plane with the true crossings; the map with the true path, the crossings, and each proven
    loop as the path over its [t1] and [t2] and as its map box (from the true start) when narrow."""
    fig, ax = plt.subplots(figsize=(7, 7))
    plot_tplane(ax, tp, truth=crossings)
    ax.set_title(f"plaza1 (Python), {name}:\nt-plane", fontsize=9)  # two lines: a long name fits the width
    fig.savefig(out / f"loops_plaza1_{tag}_tplane_py.png", dpi=110)
    plt.close(fig)
    figures.append((f"loops_plaza1_{tag}_tplane_py.png", f"plaza1, {name}: t-plane and true crossings (Python)"))

    fig, ax = plt.subplots(figsize=(8, 7))
    t, x, y = d["t"], d["x"], d["y"]
    ax.plot(x, y, color="#1f4e8c", linewidth=0.5)
    face, edge = LOOP_COLOURS["proven"]
    pieces, boxes = [], []
    # The detections proven whole, as nb_proofs() counts them and the C++ map draws them (tp.proofs()
    # would add every proven piece of a split detection: docs/loops.md).
    proven = [l for l in tp.detections() if l.proven()]
    for l in proven:
        h = l.t_box()
        for ti in (h[0], h[1]):
            lo, hi = np.searchsorted(t, ti.lb(), "left"), np.searchsorted(t, ti.ub(), "right")
            if hi - lo >= 2:
                pieces.append(np.column_stack([x[lo:hi], y[lo:hi]]))
        m = l.map_box()
        if not m.is_empty() and m.max_diam() <= MAX_MAP_BOX:
            bx, by = (m[0].lb() + x[0], m[0].ub() + x[0]), (m[1].lb() + y[0], m[1].ub() + y[0])
            boxes.append([(bx[0], by[0]), (bx[1], by[0]), (bx[1], by[1]), (bx[0], by[1])])
    if pieces:
        ax.add_collection(LineCollection(pieces, colors=face, linewidths=2.5))
    if boxes:
        ax.add_collection(PolyCollection(boxes, facecolors=face, edgecolors=edge, alpha=0.3))
    if crossings:
        ax.plot([c.x for c in crossings], [c.y for c in crossings], "o", color="#d62728", markersize=3,
                markeredgecolor="white", markeredgewidth=0.4, linestyle="none")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    n = len(proven)  # the title counts them: a run with none must not read as if it had some
    what = ("map, true path (no proven loop)" if n == 0 else
            f"map, true path over [t1] and [t2] of the {n} proven loop" + ("" if n == 1 else "s"))
    ax.set_title(f"plaza1 (Python), {name}:\n{what}", fontsize=9)
    fig.savefig(out / f"loops_plaza1_{tag}_map_py.png", dpi=110)
    plt.close(fig)
    figures.append((f"loops_plaza1_{tag}_map_py.png", f"plaza1, {name}: {what} (Python)"))


def main():
    def eps_option(ap):
        ap.add_argument("--eps-div", type=float, default=2000, help="eps = (tf - t0) / EPS_DIV")
        plaza1_bounds.add_options(ap)
        for option, attr, value, source in LOOPS_TABLE:
            ap.add_argument(option, dest=attr, type=float, default=value, metavar="X",
                            help=f"(default {value:g}) {source}".replace("%", "%%"))
    parsed = out_dir_and_data(__doc__, "plaza1", "loops_plaza1", eps_option, plaza1_data.FILES)
    if parsed is None:
        return 0
    out, folder, args = parsed
    if not 1 <= args.eps_div <= 1e6:
        print(f"--eps-div must be a number in [1, 1e6], got {args.eps_div}")
        return 2
    d = load(folder)
    td = TDomain(list(d["t"]))
    dom = td.t0_tf()
    eps = (dom.ub() - dom.lb()) / args.eps_div
    # Crossings counted as in the data README: points at least 0.2 m apart.
    crossings = sillage.self_crossings(*(list(a) for a in thinned(d["t"], d["x"], d["y"], 0.2)))
    pairs = check_pairs(d["t"], 20, 10.0)
    print(f"plaza1: {td.nb_slices()} slices, eps = {eps:.3f} s, {len(crossings)} true crossings "
          "(path thinned to 0.2 m)")

    b = plaza1_bounds.bounds(args, d)
    # The audit reports; it changes no bound. It is the audit of the honest model (b), the table's
    # bounds: one that the truth violates voids the guarantee, a failure.
    ok, summary, figures = print_audit("loops_plaza1, model (b)", plaza1_bounds.audit(d, b)), "", []
    illustrations = False  # their heading line printed
    for tag, name, honest, speed_bounds, heading_bounds in models(b, args):
        if not honest and not illustrations:
            illustrations = True
            # The truth against its own heading, which the (a) models use: why they need a tolerance.
            t = plaza1_bounds.track_audit(d, b.track, args.reverse_below, args.glitch_above)
            print(f"\nillustrations, not guarantees: the (a) models use the heading of the ground truth itself, not a "
                  f"sensor of the robot;\ntheir integral check allows the truth's own error ({TOL_M:.2f} m) and they do "
                  f"not count in the check.\n  the truth's direction of travel vs its own heading: max {t.used:.4g} rad "
                  f"against the (a) bound of {t.allowed:g} rad ({t.how})")
            summary += "illustrations with the truth's heading, not guarantees: "
        v = velocity_tube(d, td, speed_bounds, heading_bounds, b.start_heading, args.reverse_below,
                          args.glitch_above)
        ic = check_integrals(v, td, d, pairs, crossings)
        wall0, cpu0 = time.perf_counter(), time.process_time()
        tp = TPlane(td)
        tp.compute_detections(eps, v)
        detect_seconds = time.perf_counter() - wall0
        tp.compute_proofs(v)
        seconds, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
        c = check_loops(tp, crossings)
        print_loops(name, tp, c, ic, seconds, detect_seconds, cpu)
        if honest:  # honest bounds must hold the truth exactly, no tolerance
            ok = ok and c["passed"] and ic["inside"] == ic["n"]
            if ic["inside"] != ic["n"]:
                print("  <-- INTEGRAL CHECK FAILED (honest bounds: no tolerance)")
        else:
            print(f"  illustration: truth within {TOL_M:.2f} m of the integrals: "
                  f"{'yes' if ic['tol'] == ic['n'] else 'no'}; proofs holding a true crossing: "
                  f"{'yes' if c['passed'] else 'no'} (not counted)")
        summary += (f"{name}: {tp.nb_detections()} detections ({tp.nb_complete_detections()} complete), "
                    f"{tp.nb_proofs()} proofs T, {tp.nb_newton_proofs()} N, {c['in_proven']}/{c['nb_crossings']} "
                    f"crossings in proofs, {seconds:.2f} s; ")
        save_figures(tp, d, crossings, out, tag, name, figures)
    print_result("loops_plaza1", summary, ok, figures)
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
