"""The bathymetric temporal SLAM of thesis 7.3.2 (Table 7.2, Fig. 7.16, 7.17, 7.20) on the
synthetic mission of bathymetry_mission.py: state x = (east, north, depth), x' = w (7.31),
p = h(x) = (x1, x2) (7.25), z = the seabed depth under the vehicle (7.30). No map: only
p(t1) = p(t2) => z(t1) = z(t2). Fast (Alg. 14) then accurate (Alg. 13), each to its fixed
point; the truth is checked inside [p](.) at every gate and slice after every iteration
(on_iteration), and the run fails otherwise.

--scenario 2 is thesis 7.3.3 (Table 7.3): the start unknown, one +-1 m fix at mid-mission.
--coastal: the coastal seabed (sand waves, rocky outcrops), a narrow-beam altimeter and the
east-west transects (docs/slam.md explains why it still contracts little).
--bank: the bank mission (bank_mission_options: two channel flanks under the east-west transects,
the narrow-beam altimeter), which contracts [p](t_f) (docs/slam.md).
--duration shortens the mission (the demo: 1800 s); the full 5760 s run is in
bench/bench_slam_bathymetry.cpp."""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import sillage
from bathymetry_mission import stated_bounds
from example_args import bound, enclosure_ok, print_result, run
from sillage import CtcDeriv, Function, Interval, TemporalSlamOptions, TubeVector
from sillage.plot_bathymetry import plot_dem
from sillage.plot_tube import plot_thickness, plot_tube_vector_2d

SEED, DT = 7, 1.0


def misses(tube, times, values):
    """Samples of the truth outside the tube, at its gates and in its slices."""
    tp = np.asarray(tube.tdomain().times())
    s, g = np.asarray(tube.slices_array()), np.asarray(tube.gates_array())
    inside = (times >= tp[0]) & (times <= tp[-1])
    times, values = times[inside], values[inside]
    k = np.clip(np.searchsorted(tp, times, side="right") - 1, 0, len(s) - 1)
    on_gate = np.isin(times, tp)
    kg = np.searchsorted(tp, times[on_gate])
    return int(((values < s[k, 0]) | (values > s[k, 1])).sum()
               + ((values[on_gate] < g[kg, 0]) | (values[on_gate] > g[kg, 1])).sum())


def thickness_figure(curves, path):
    """Thickness of [p](t) of each (tube, colour, label), saved to path; returns the figure. Each curve
    has its own dashes, and curves that coincide (to 0.1 % of the largest thickness) share one legend
    entry that says so: the reader finds every name."""
    fig, ax = plt.subplots(figsize=(8, 3.2))
    values = [np.asarray(sillage.thickness_values(t, sillage.ThicknessMeasure.Diagonal), dtype=float)
              for t, _, _ in curves]
    finite = [v[np.isfinite(v)] for v in values]
    scale = max((float(v.max()) for v in finite if v.size), default=1.0)
    groups = []  # lists of indices of curves that coincide
    for i, v in enumerate(values):
        g = next((g for g in groups if np.allclose(values[g[0]], v, rtol=0, atol=1e-3 * scale, equal_nan=True)),
                 None)
        if g is None:
            groups.append([i])
        else:
            g.append(i)
    dashes = ["-", "--", ":", "-."]
    for i, (tube, colour, label) in enumerate(curves):
        g = next(g for g in groups if i in g)
        text = " = ".join(curves[k][2] for k in g) + (" (the curves coincide)" if len(g) > 1 else "")
        plot_thickness(ax, tube, measure=sillage.ThicknessMeasure.Diagonal, color=colour,
                       linestyle=dashes[i % len(dashes)], label=text if i == g[-1] else None)
    ax.legend()
    ax.set_ylabel("d(t) (m)")
    ax.set_title("Thickness of [p](t) (Fig. 7.17)")
    fig.tight_layout()  # room for the axis labels
    fig.savefig(path, dpi=110)
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default="out", help="folder for the figures")
    parser.add_argument("--duration", type=float, default=1800.0, help="mission duration (s)")
    parser.add_argument("--scenario", type=int, choices=(1, 2), default=1, help="1: start known; 2: mid fix")
    seabed = parser.add_mutually_exclusive_group()
    seabed.add_argument("--coastal", action="store_true",
                        help="coastal seabed, narrow-beam altimeter, east-west transects (docs/slam.md)")
    seabed.add_argument("--bank", action="store_true",
                        help="two channel flanks under the east-west transects, narrow-beam altimeter (docs/slam.md)")
    parser.add_argument("--tie-lines", type=float, default=0.0,
                        help="tie lines at this angle (deg) to the rails first, instead of the overall crossing "
                             "or the transects (docs/slam.md); 0: none")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    opts = sillage.bank_mission_options() if args.bank else sillage.BathymetryMissionOptions()
    opts.duration = args.duration
    opts.bounds = stated_bounds()
    if args.coastal:  # sand waves and outcrops at the drift scale, a 6-degree altimeter cone
        opts.seabed = sillage.coastal_seabed_options()
        opts.transects = True
    if args.coastal or args.bank:
        opts.bounds.beam_angle, opts.bounds.beam_spread = 0.0, bound(3.0)
    opts.tie_line_angle = args.tie_lines
    m = sillage.BathymetryMission(seed=SEED, options=opts)
    td = m.tdomain(DT)
    N = td.nb_slices()
    w = sillage.bathymetry_velocity_tube(m, td)
    z = TubeVector([sillage.bathymetry_observation_tube(m, td)])
    h_err = bound(1.0)  # the GNSS fix at the dive, or the mid-mission fix
    x = sillage.bathymetry_dead_reckoning(m, td, sillage.bathymetry_initial_box(m, h_err))
    if args.scenario == 2:
        i = m.sample_index(td.t(N // 2))
        x[0].set(Interval()), x[1].set(Interval())
        x[0].set_gate(N // 2, Interval(m.x1[i] - h_err, m.x1[i] + h_err))
        x[1].set_gate(N // 2, Interval(m.x2[i] - h_err, m.x2[i] + h_err))
    dr = x.copy()
    CtcDeriv().contract(dr, w)
    dr = dr.subvector(0, 1)
    times, x1, x2 = np.asarray(m.times), np.asarray(m.x1), np.asarray(m.x2)
    state = {"misses": 0, "fast": None, "accurate": None, "boxes": [dr.gate(N)]}

    def on_iteration(row, p):
        miss = misses(p[0], times, x1) + misses(p[1], times, x2)
        if miss:
            print(f"  iteration {row.iteration} lost the truth at {miss} samples")
        state["misses"] += miss
        state["boxes"].append(p.gate(N))
        state["fast" if row.fast else "accurate"] = p

    o = TemporalSlamOptions()
    o.eps = DT
    o.on_iteration = on_iteration
    f = Function(["x1", "x2", "x3", "u1", "u2", "u3"], "(u1, u2, u3)")
    h = Function(["x1", "x2", "x3"], "(x1, x2)")
    print(f"Bathymetric temporal SLAM, scenario {args.scenario}: {args.duration:.0f} s, {N} slices, eps = {o.eps} s")
    rows = sillage.temporal_slam(x, w.copy(), w, z, f, h, o)
    print("  it  algorithm  detections  proofs  time (s)  cumul (s)  contr. p(tf)  contr. p(t0)")
    for r in rows:
        print(f"  {r.iteration:2d}  {'fast' if r.fast else 'accurate':9s}  {r.nb_detections:10d}  {r.nb_proofs:6d}"
              f"  {r.seconds:8.2f}  {r.cumulated_seconds:9.2f}  {100 * r.contraction_tf:11.1f}%"
              f"  {100 * r.contraction_t0:11.1f}%")
    fast = state["fast"]
    accurate = state["accurate"] if state["accurate"] is not None else fast
    nested = fast is not None and accurate.is_subset(fast)
    final = misses(x[0], times, x1) + misses(x[1], times, x2) + misses(x[2], times, np.asarray(m.truth.depth))
    ok = bool(rows) and enclosure_ok(x) and state["misses"] == 0 and final == 0 and nested
    print(f"  truth inside [p](.) at every iteration: {'yes' if state['misses'] == 0 else 'NO'}; "
          f"in the final [x](.): {'yes' if final == 0 else 'NO'}; accurate within fast: {'yes' if nested else 'NO'}")

    tag = "" if args.scenario == 1 else "_scenario2"
    figures = []
    curves = [(t, c, lbl) for t, c, lbl in ((dr, "#777777", "dead reckoning"), (fast, "#2a6aa8", "fast"),
                                          (accurate, "#d62728", "accurate")) if t is not None]
    plt.close(thickness_figure(curves, out / f"bathymetry_slam_thickness{tag}_py.png"))
    figures.append((f"bathymetry_slam_thickness{tag}_py.png", "Thickness: dead reckoning, fast, accurate (Fig. 7.17)"))
    fig, ax = plt.subplots(figsize=(7, 7))
    truth = sillage.bathymetry_truth(m)
    plot_tube_vector_2d(ax, dr, 0, 1, color="#d9d9d9", edgecolor="#b0b0b0")
    plot_tube_vector_2d(ax, x.subvector(0, 1), 0, 1, color="#9ecae1", edgecolor="#4a90c2", truth=(truth[0], truth[1]))
    for b in state["boxes"]:
        ax.add_patch(plt.Rectangle((b[0].lb(), b[1].lb()), b[0].diam(), b[1].diam(), fill=False, color="#d62728"))
    ax.set_aspect("equal")
    ax.set_title("Mission map: DR, SLAM, truth, [p](t_f) (Fig. 7.16)")
    fig.savefig(out / f"bathymetry_slam_map{tag}_py.png", dpi=110)
    figures.append((f"bathymetry_slam_map{tag}_py.png", "Mission map (Fig. 7.16)"))
    fig, ax = plt.subplots(figsize=(7, 6))
    plot_dem(ax, m.dem, m.x1, m.x2)
    ax.set_title("Seabed DEM and path (Fig. 7.20)")
    fig.savefig(out / f"bathymetry_slam_dem{tag}_py.png", dpi=110)
    figures.append((f"bathymetry_slam_dem{tag}_py.png", "Seabed DEM with the path (Fig. 7.20)"))
    plt.close("all")
    last = rows[-1] if rows else None
    print_result("bathymetry_slam",
                 f"scenario {args.scenario}: {len(rows)} iterations, p(tf) contracted by "
                 f"{100 * (last.contraction_tf if last else 0):.0f} %, p(t0) by "
                 f"{100 * (last.contraction_t0 if last else 0):.0f} %, truth inside: {'yes' if ok else 'no'}",
                 ok, figures)
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
