"""Range-only localization with low-cost beacons (thesis 5.3.1), the network of
examples/cpp/lowcost_beacons.cpp: the robot (5.15) with inputs (5.16), t in
[0, 64], unknown initial position (5.17); beacons of Table 5.1, ranges [z_i] at
uncertain times [t_i] of Table 5.2. CN (5.18): v = f(x, u), x' = v, per beacon
y = g(x), w = (5.19) and its reformulation (5.21) (one contractor for the three
equations), y' = w, z_i = y(t_i) (CtcEval); ratio 0 (true fixed point).
The true robot, x(0) = (0, 0, pi/2, 0) with the centre input (RK4, step dt/10),
must stay inside the tubes, and every time where it meets [z_i] inside [t_i]."""
import math
import time

import numpy as np

import sillage
from dead_reckoning import IVP_F, NOISE
from example_args import bound, deriv_vs_ivp_figure, empty_exit, enclosure_ok, out_dir_and_step, print_result, rk4, run
from sillage import (ContractorNetwork, CtcDeriv, CtcEval, CtcFunction, DomainRef, Figure, Function, Interval,
                     IntervalVector, Style, TDomain, ThicknessMeasure, Tube, TubeStyle, TubeVector)

TF = 64.0
BEACONS = [("alpha", 30.0, 20.0), ("beta", 80.0, -5.0), ("gamma", 125.0, 20.0)]  # Table 5.1
MEASUREMENTS = [(1, (14.75, 15.55), (11.69, 12.69)), (0, (20.80, 21.60), (15.40, 16.40)),  # Table 5.2
                (0, (23.80, 24.60), (10.62, 11.62)), (0, (26.80, 27.60), (11.05, 12.05)),
                (0, (29.80, 30.60), (11.87, 12.87)), (0, (32.80, 33.60), (15.31, 16.31)),
                (2, (44.35, 45.15), (13.65, 14.65)), (2, (47.35, 48.15), (13.32, 14.32)),
                (2, (50.35, 51.15), (12.03, 13.03)), (2, (53.35, 54.15), (15.98, 16.98)),
                (1, (56.75, 57.55), (17.45, 18.45))]


def cents(a, b):
    """The enclosure of a table entry written with two decimals (the double 15.55 is
    not the real 15.55): hundredths divided by 100, rounded outward."""
    return Interval(round(a * 100), round(b * 100)) / Interval(100)


def beacon_equations(b1, b2):
    """y = g(x), w = (5.19) and w = (5.21), each as an expression e = 0 of (y, w, x1, x2, v1, v2)."""
    d1, d2 = f"(x1 - {b1!r})", f"(x2 - {b2!r})"
    g = f"sqrt({d1}^2 + {d2}^2)"
    return (f"y - {g}", f"w - ({d1}*v1 + {d2}*v2)/{g}",
            f"w - (sign({d1})/sqrt(1 + ({d2}/{d1})^2)*v1 + sign({d2})/sqrt(1 + ({d1}/{d2})^2)*v2)")


def beacon_function(b1, b2):
    """The three equations of a beacon as one function (one HC4 pass over their shared DAG)."""
    return Function(["y", "w", "x1", "x2", "v1", "v2"], "(" + ", ".join(beacon_equations(b1, b2)) + ")")


def domain(dt):
    """[0, 64] sliced by dt, with gates at the bounds of the [t_i]: they are exact, and a
    [t_i] that pokes an ulp into a slice would take in the whole slice."""
    td = TDomain(0.0, TF, dt)
    for _, t, _ in MEASUREMENTS:
        ti = cents(*t)
        td.sample(ti.lb())
        td.sample(ti.ub())
    return td


def build(td, ratio=0.0, split=False):
    """CN (5.18), in the order of the C++ example (same rounds, same result).
    split: one contractor per equation of a beacon instead of one for its three
    (the same fixed point, slower)."""
    x, v = TubeVector(td, 4), TubeVector(td, 4)
    v[2] = Tube(td, "-9/20*cos(t/5) + [-0.001, 0.001]")  # v3 = u1 (5.16)
    v[3] = Tube(td, "1/10 + sin(t/4) + [-0.001, 0.001]")  # v4 = u2
    x[2].set_gate(0, Interval.pi() / Interval(2) + Interval(-0.01, 0.01))  # (5.17)
    x[3].set_gate(0, Interval(-0.01, 0.01))
    cn = ContractorNetwork()
    cn.set_ratio(ratio)
    xc = [DomainRef.component(x, i) for i in range(4)]
    vc = [DomainRef.component(v, i) for i in range(4)]
    cn.add(CtcFunction(Function(["v1", "x4", "x3"], "v1 - x4*cos(x3)")), [vc[0], xc[3], xc[2]])
    cn.add(CtcFunction(Function(["v2", "x4", "x3"], "v2 - x4*sin(x3)")), [vc[1], xc[3], xc[2]])
    cn.add(CtcDeriv(), [x, v])
    ys, ws = [], []
    for _, b1, b2 in BEACONS:
        y, w = Tube(td), Tube(td)
        if split:
            for e in beacon_equations(b1, b2):
                cn.add(CtcFunction(Function(["y", "w", "x1", "x2", "v1", "v2"], e)), [y, w, xc[0], xc[1], vc[0], vc[1]])
        else:
            cn.add(CtcFunction(beacon_function(b1, b2)), [y, w, xc[0], xc[1], vc[0], vc[1]])
        cn.add(CtcDeriv(), [y, w])
        ys.append(y)
        ws.append(w)
    ts, zs = [], []
    for k, t, z in MEASUREMENTS:
        ts.append(bound(cents(*t)))
        zs.append(bound(cents(*z)))
        cn.add(CtcEval(), [ts[-1], zs[-1], ys[k], ws[k]])
        cn.set_name(ts[-1], f"t{len(ts)}")
        cn.set_name(zs[-1], f"z{len(zs)}")
    # Named, so that an empty network says which domain emptied.
    for d, name in ((x, "x"), (v, "v"), *((y, f"y_{b[0]}") for y, b in zip(ys, BEACONS)),
                    *((w, f"w_{b[0]}") for w, b in zip(ws, BEACONS))):
        cn.set_name(d, name)
    return dict(cn=cn, x=x, v=v, y=ys, w=ws, t=ts, z=zs)


def truth(h, n):
    """The true robot: RK4 from (0, 0, pi/2, 0) with the centre input."""
    def f(t, s):
        return np.array([s[3] * math.cos(s[2]), s[3] * math.sin(s[2]),
                         -9 / 20 * math.cos(t / 5), 0.1 + math.sin(t / 4)])
    return rk4(f, [0.0, 0.0, math.pi / 2, 0.0], h, n)


def excess(x, path, h):
    """Largest distance of the truth, sampled every h, outside the tubes: each sample
    against the slice holding its time, each gate against the sample at its time."""
    times = np.array(x.tdomain().times())
    n = len(times) - 1
    ts = np.minimum(np.arange(len(path)) * h, times[-1])
    ks = np.clip(np.searchsorted(times, ts, side="right") - 1, 0, n - 1)
    jg = np.rint(times / h).astype(int)
    worst = 0.0
    for i in range(4):
        s, g, p = x[i].slices_array(), x[i].gates_array(), path[:, i]
        worst = max(worst, np.max(np.maximum(s[ks, 0] - p, p - s[ks, 1])))
        worst = max(worst, np.max(np.maximum(g[:, 0] - p[jg], p[jg] - g[:, 1])))
    return max(worst, 0.0)


def mean_thickness(x):
    """Mean over time of d(t) = |diam([x1](t)), diam([x2](t))| (slices weighted by their width)."""
    times = np.array(x.tdomain().times())
    d = np.hypot(np.diff(x[0].slices_array(), axis=1)[:, 0], np.diff(x[1].slices_array(), axis=1)[:, 0])
    return float(np.sum(d * np.diff(times)) / (times[-1] - times[0])), float(d.max())


def truth_times(path, h, k, t, z):
    """Hull of the sampled times in [t] where the truth's range to beacon k is in [z]."""
    times = np.arange(len(path)) * h
    _, b1, b2 = BEACONS[k]
    d = np.hypot(path[:, 0] - b1, path[:, 1] - b2)
    sel = times[(times >= t[0]) & (times <= t[1]) & (d >= z[0]) & (d <= z[1])]
    return (sel.min(), sel.max()) if len(sel) else None


def map_figure(p, view, title, path):
    fig = Figure(view, 700)
    fig.set_title(title)
    fig.set_labels("x1", "x2")
    for _, b1, b2 in BEACONS:
        fig.draw_ring([b1, b2], Interval(0, 20), Style("#f7e4e4", "#c62828", 0.6, 0.35))
    style = TubeStyle()
    style.slices = Style("#b8c4d6", "#5c6f8a", 0.3, 1.0, "slice")
    style.initial = Style("none", "#c62828", 1.5, 1.0, "initial")
    style.final = Style("none", "#2e7d32", 1.5, 1.0, "final")
    sillage.draw_tube_vector_2d(fig, p["x"], 0, 1, style)
    td = p["x"].tdomain()
    times = td.times()
    for t in p["t"]:  # the slices over [t_i], darker
        for k in range(td.nb_slices()):
            if times[k + 1] > t.lb() and times[k] < t.ub():
                fig.draw_box(p["x"].slice(k).subvector(0, 1), Style("#3d3d3d", "none", 0, 0.45))
    fig.draw_polyline([[float(a), float(b)] for a, b in path[:, :2]], Style("none", "#d62728", 1.5, 1, "truth"))
    for name, b1, b2 in BEACONS:
        fig.draw_box(IntervalVector([Interval(b1 - 1, b1 + 1), Interval(b2 - 1, b2 + 1)]), Style("#d62728", "black"))
        fig.draw_text([b1 + 1.5, b2 + 1.5], name, 12, "#a00000")
    return fig


def solve_ivp(x):
    """CtcIvp after the network (the robot's f is that of dead reckoning): from the fixed
    point every gate is bounded; forward and backward on (x, tau), the noise of (3.16) as
    the input. Returns the contracted (x1..x4) and the success flag."""
    td = x.tdomain()
    xi = TubeVector(td, 5)
    for i in range(4):
        xi[i] = x[i]
    xi[4] = Tube(td, "t")
    ok = sillage.CtcIvp(IVP_F, 2, 10, sillage.TimePropag.FWD_BWD).contract(xi, TubeVector(td, 2, bound(NOISE)))
    return xi.subvector(0, 3), ok


def main():
    out, args = out_dir_and_step(__doc__, 0.05)

    td = domain(args.dt)
    n = td.nb_slices()
    c0 = time.process_time()
    p = build(td, args.ratio)
    s = p["cn"].contract()
    cpu = time.process_time() - c0
    print(f"Range-only localization with low-cost beacons (thesis 5.3.1), t in [0, 64], dt = {args.dt:g} ({n} slices)")
    print(f"  {s.iterations} iterations, {s.contractor_calls} contractor calls, {s.time:.3f} s wall, "
          f"{cpu:.3f} s CPU (build + contract), empty = {s.empty}")
    print("  thesis: fixed point after 52 iterations in 2 min; reference library: 4 iterations in 3.4 s, "
          "not at the fixed point")
    if s.empty:
        return empty_exit("lowcost_beacons", s)

    # Fixed point: one more contract() runs every contractor once and must change nothing.
    x_fp = p["x"].copy()
    again = p["cn"].contract()
    fixed = again.iterations == 1 and p["x"] == x_fp
    print(f"  fixed point verified (a second contract() changes nothing): {'yes' if fixed else 'NO'}")

    h = args.dt / 10  # RK4 step of the truth
    path = truth(h, round(TF / h))
    e = excess(p["x"], path, h)
    ok = enclosure_ok(p["x"]) and (fixed or args.ratio > 0) and e <= 1e-7  # ratio > 0: stops earlier
    print("  measurements: [t_i] (Table 5.2) -> contracted [t_i] ; [z_i] -> contracted [z_i] ; truth times")
    for i, (k, t, z) in enumerate(MEASUREMENTS):
        tt = truth_times(path, h, k, t, z)
        inside = tt is not None and p["t"][i].contains(tt[0]) and p["t"][i].contains(tt[1])
        ok = ok and inside
        ti, zi = p["t"][i], p["z"][i]
        print(f"  {i + 1:2d} {BEACONS[k][0]:<5s} [{t[0]:.2f}, {t[1]:.2f}] -> [{ti.lb():.4f}, {ti.ub():.4f}] ; "
              f"[{z[0]:.2f}, {z[1]:.2f}] -> [{zi.lb():.4f}, {zi.ub():.4f}] ; "
              f"truth [{tt[0]:.3f}, {tt[1]:.3f}] {'inside' if inside else 'NOT INSIDE'}")
    x0, xf = p["x"].gate(0), p["x"].gate(n)
    mean, worst = mean_thickness(p["x"])
    print(f"  x(0) in [{x0[0].lb():.3f}, {x0[0].ub():.3f}] x [{x0[1].lb():.3f}, {x0[1].ub():.3f}] (truth (0, 0)); "
          f"x(64) in [{xf[0].lb():.3f}, {xf[0].ub():.3f}] x [{xf[1].lb():.3f}, {xf[1].ub():.3f}]")
    print(f"  position thickness d(t): mean {mean:.3f}, max {worst:.3f}")
    print(f"  truth inside the tubes: {'yes' if e <= 1e-7 else 'NO'} (largest excess {e:.2g})")

    c0 = time.process_time()
    xi, ivp_ok = solve_ivp(p["x"])
    cpu_ivp = time.process_time() - c0
    ei = excess(xi, path, h)
    xi0, xif = xi.gate(0), xi.gate(n)
    mean_i, worst_i = mean_thickness(xi)
    print(f"  then CtcIvp ({cpu_ivp:.3f} s CPU): x(0) in [{xi0[0].lb():.3f}, {xi0[0].ub():.3f}] x "
          f"[{xi0[1].lb():.3f}, {xi0[1].ub():.3f}], x(64) in [{xif[0].lb():.3f}, {xif[0].ub():.3f}] x "
          f"[{xif[1].lb():.3f}, {xif[1].ub():.3f}]; d(t) mean {mean_i:.3f}, max {worst_i:.3f}; truth inside: "
          f"{'yes' if ivp_ok and ei <= 1e-7 else 'NO'} (largest excess {ei:.2g})")
    ok = ok and ivp_ok and enclosure_ok(xi) and ei <= 1e-7
    deriv_vs_ivp_figure(p["x"], xi, out / "lowcost_beacons_deriv_vs_ivp_py.png",
                        "Low-cost beacons: network (blue), then CtcIvp (orange)", path[::10])

    cod = p["x"].codomain()
    view = IntervalVector([Interval(max(cod[0].lb(), -40.0) - 5, min(cod[0].ub(), 160.0) + 5),
                           Interval(max(cod[1].lb(), -60.0) - 5, min(cod[1].ub(), 90.0) + 5)])
    fine = path[::10]
    map_figure(p, view, "Low-cost beacons: [x1] x [x2] at the fixed point (Fig. 5.9a, Python)", fine) \
        .save(str(out / "lowcost_beacons_map_py.svg"))
    th = sillage.thickness_figure(p["x"].subvector(0, 1), ThicknessMeasure.Diagonal,
                                  "Thickness of [x1] x [x2] at the fixed point, [t_i] in grey (Fig. 5.8, Python)",
                                  700, 250)
    for t in p["t"]:
        th.draw_box(IntervalVector([t, Interval()]), Style("#999999", "none", 0, 0.3))
    th.save(str(out / "lowcost_beacons_thickness_py.svg"))

    summary = (f"{s.iterations} iterations, {s.time:.3f} s; x(0) in [{x0[0].lb():.2f}, {x0[0].ub():.2f}] x "
               f"[{x0[1].lb():.2f}, {x0[1].ub():.2f}]")
    print_result("lowcost_beacons", summary, ok,
                 [("lowcost_beacons_map_py.svg", "Low-cost beacons (5.3.1): position tube, truth, [t_i], Python"),
                  ("lowcost_beacons_thickness_py.svg", "Thickness of the position tube (Fig. 5.8), Python"),
                  ("lowcost_beacons_deriv_vs_ivp_py.png",
                   "The network's position tube (blue), then contracted by CtcIvp (orange), Python")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
