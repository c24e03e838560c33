"""Online estimation on real data (docs/online.md): the plaza1 log replayed in stamp order through
sillage.OnlineEstimator, as the robot would have fed it while it drove: each period's odometry when
it ends (advance), each range once time has reached its stamp (observe, its time the stamp +- 0.2 s).
At every time the filtering estimate, the box of the position now, must hold the ground truth; a
matplotlib figure draws its size against the batch solve of the same data and model (which knows
the future). The same model and stated bounds as examples/cpp/plaza1_online.cpp (plaza1_bounds.py);
--window S: the seconds of past kept (default 60; 0: everything)."""
import math
import sys
import time
from types import SimpleNamespace

import sillage
import plaza1_bounds
from plaza1 import HEADING_WINDOW, solve
from plaza1_data import FILES, load
from example_args import out_dir_and_data, print_result, run
from sillage import (CtcFunction, CtcHeading, CtcHeadingWindow, CtcIncrement, CtcSecondDeriv, Function, Interval,
                     IntervalVector, OnlineEstimator, OnlineOptions)


def estimator(d, b, window):
    """The plaza1 model, declared (the gyro's bias free at every step)."""
    est = OnlineEstimator(d["t"][0], OnlineOptions(window=window))
    est.add_state("psi", 1, IntervalVector([Interval(b.start_heading) + Interval(-b.heading0, b.heading0)]))
    est.add_state("p", 2, IntervalVector([Interval(b.start_x - b.pos0, b.start_x + b.pos0),
                                          Interval(b.start_y - b.pos0, b.start_y + b.pos0)]))
    est.add_state("v", 2)
    est.add_input("dpsi", 1)
    est.add_input("dist", 1)
    for name, bound in (("omega", b.turn_max), ("track", b.track), ("alpha", b.turn_accel)):
        est.add_bounded(name, IntervalVector([Interval(-bound, bound)]))
    est.add_bounded("speed", IntervalVector([Interval(0, b.speed_max)]))
    est.add(CtcIncrement(), ["psi", "dpsi"])
    est.add_deriv("psi", "omega")
    est.add(CtcSecondDeriv(), ["psi", "alpha"])
    est.add(CtcHeading(b.track), ["p", "psi", "dist", "omega"])
    stride = max(1, round(HEADING_WINDOW / 4 / ((d["t"][-1] - d["t"][0]) / (len(d["t"]) - 1))))
    est.add(CtcHeadingWindow(HEADING_WINDOW, b.track, b.turn_accel, stride), ["p", "psi", "dist", "dpsi", "omega"])
    est.add(CtcFunction(Function(["a", "s", "h", "e"], "a - s*cos(h + e)")), ["v[0]", "speed", "psi", "track"])
    est.add(CtcFunction(Function(["a", "s", "h", "e"], "a - s*sin(h + e)")), ["v[1]", "speed", "psi", "track"])
    est.add_deriv("p", "v")
    return est


def replay(est, d, b):
    """Feeds the log in stamp order; per period the online box of p, and the latency of every update."""
    t, order = d["t"], sorted(range(len(d["rt"])), key=lambda j: d["rt"][j])
    rings = {i: Function(["q1", "q2"], f"sqrt((q1 - {x!r})^2 + (q2 - {y!r})^2)") for i, (x, y) in d["beacons"].items()}
    boxes, latency, nxt = [], [], 0
    for k in range(len(t) - 1):
        w = Interval(t[k + 1]) - Interval(t[k])
        dpsi = Interval(d["dpsi"][k]) + w * Interval(-b.gyro_bias, b.gyro_bias)
        dist = (Interval(d["dist"][k]) * Interval(1 - b.dist_rel, 1 + b.dist_rel)
                + Interval(-b.dist_over, b.dist_under)) & Interval(0, math.inf)
        start = time.perf_counter()
        est.advance(t[k + 1], {"dpsi": IntervalVector([dpsi]), "dist": IntervalVector([dist])})
        latency.append(time.perf_counter() - start)
        while nxt < len(order) and d["rt"][order[nxt]] <= t[k + 1]:
            j = order[nxt]
            nxt += 1
            tj = Interval(d["rt"][j] - b.time_err, d["rt"][j] + b.time_err)
            if tj.lb() < est.window_start():
                continue  # taken before the log's start
            r = Interval(d["r"][j] - b.range_long, d["r"][j] + b.range_short) & Interval(0, math.inf)
            start = time.perf_counter()
            est.observe(tj, "p", CtcFunction(rings[int(d["rid"][j])], r))
            latency.append(time.perf_counter() - start)
        boxes.append(est.now("p"))
    return boxes, latency


def side(box):
    return max(box[0].diam(), box[1].diam())


def main():
    parsed = out_dir_and_data(__doc__, "plaza1", "plaza1_online",
                              lambda ap: ap.add_argument("--window", type=float, default=60.0,
                                                         help="seconds of past kept (0: everything)"), FILES)
    if parsed is None:
        return 0
    out, folder, args = parsed
    if not args.window >= 0 or not math.isfinite(args.window):
        print(f"plaza1_online: --window takes seconds >= 0 (0: everything), got {args.window}", file=sys.stderr)
        sys.exit(2)
    window = args.window if args.window > 0 else math.inf
    d = load(folder)
    b = plaza1_bounds.bounds(None, d)
    est = estimator(d, b, window)
    boxes, latency = replay(est, d, b)
    t = d["t"][1:]
    inside = sum(box[0].contains(x) and box[1].contains(y) for box, x, y in zip(boxes, d["x"][1:], d["y"][1:]))
    lat = sorted(latency)
    median, p99, total = lat[len(lat) // 2], lat[min(len(lat) - 1, int(0.99 * len(lat)))], sum(latency)
    st = est.stats()
    print(f"plaza1 online, window {args.window:g} s: {len(t)} periods, {st.updates} updates in {total:.2f} s "
          f"({(d['t'][-1] - d['t'][0]) / total:.0f} x real time); per update median {1e6 * median:.0f} us, "
          f"p99 {1e6 * p99:.0f} us; {st.slices} slices in memory, {st.retired} observations retired")
    print(f"  ground truth inside the online box at {inside} / {len(t)} times")
    # The batch solve of the same data and model: the gyro's bias free at every step, as online.
    same = SimpleNamespace(**dict(vars(b), gyro_drift=b.gyro_bias))
    batch = solve(d, True, same)[0]
    online_side = [side(x) for x in boxes]
    batch_side = [side(batch.gate(k + 1)) for k in range(len(t))]
    later = [o / s for o, s, tk in zip(online_side, batch_side, t) if tk >= d["t"][0] + 60 and s > 0]
    ratio = sum(later) / len(later) if later else math.nan
    print(f"  online/batch box side after 60 s: mean {ratio:.2f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 3.6))
    ax.semilogy([x - d["t"][0] for x in t], online_side, color="#d62728", lw=0.8,
                label="online: the box of p at now (filtering)")
    ax.semilogy([x - d["t"][0] for x in t], batch_side, color="#1f77b4", lw=0.8,
                label="batch: all the data known (smoothing)")
    ax.set_xlabel("t - t0 (s)")
    ax.set_ylabel("position box side (m)")
    ax.set_title(f"plaza1 online (W = {args.window:g} s), against the batch solve")
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    name = "plaza1_online_sizes_py.png"
    fig.savefig(out / name, dpi=110)
    ok = inside == len(t) and est.last_update().summary.status != sillage.Status.NoSolution
    print_result("plaza1_online", f"W = {args.window:g} s: truth inside {inside} / {len(t)}, median update "
                 f"{1e6 * median:.0f} us, online/batch box {ratio:.2f}", ok,
                 [(name, "plaza1 online: box side over time, online vs batch")])
    return 0


if __name__ == "__main__":
    run(main)
