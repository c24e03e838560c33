"""Causal kinematic chain (thesis 4.4.1, (4.25)-(4.27)): a Dubins car
x1' = 10 cos x3, x2' = 10 sin x3, x3' = u, u in -cos((t+33)/5) + [-0.02, 0.02],
x(0) in (4.26), t in [0, 14]. A ContractorNetwork with CtcDeriv (x' = v) and
the pointwise contractors v1 = 10 cos x3, v2 = 10 sin x3; run from x0, then
with the final box x(14) in [53.9, 55.9] x [6.9, 8.9] x [-2.36, -2.32].
Each run again by CtcIvp (validated Taylor integration, docs/ivp.md): the known
part of u written in f with the time as a state (tau' = 1), the error of u as an
input tube [-0.02, 0.02]; a matplotlib figure compares the two tubes.
The true path (u*, centre of x0) is checked inside the tubes."""
import math
import time

import numpy as np

import sillage
from example_args import bound, deriv_vs_ivp_figure, empty_exit, enclosure_ok, ivp_stats, out_dir, print_result, rk4, run
from sillage import CtcFunction, Function, Interval, IntervalVector, TDomain, Tube, TubeVector

TF, DT = 14.0, 0.01
CAPD = (Interval(38.1545777835, 71.7221807908), Interval(-11.4056594783, 27.2737690279))
FINAL = IntervalVector([bound(Interval(53.9, 55.9)), bound(Interval(6.9, 8.9)), bound(Interval(-2.36, -2.32))])


def initial_box():
    h = Interval.pi() * Interval(-6) / Interval(5)
    return IntervalVector([Interval(-1, 1), Interval(-1, 1), h + Interval(-0.02, 0.02)])


def solve(td, final_box):
    x, v = TubeVector(td, 3), TubeVector(td, 3)
    v[2] = Tube(td, "-cos((t+33)/5) + [-0.02, 0.02]")
    x.set_gate(0, initial_box())
    if final_box:
        x.set_gate(td.nb_slices(), FINAL)
    cn = sillage.ContractorNetwork()
    cn.add(CtcFunction(Function(["v1", "x3"], "v1 - 10*cos(x3)")), [v[0], x[2]])
    cn.add(CtcFunction(Function(["v2", "x3"], "v2 - 10*sin(x3)")), [v[1], x[2]])
    cn.add(sillage.CtcDeriv(), [x, v])
    cn.set_name(x, "x")  # named, so that an empty network says which tube emptied
    cn.set_name(v, "v")
    stats = cn.contract()
    return x, stats


IVP_F = Function(["x1", "x2", "x3", "tau", "n"], "(10*cos(x3), 10*sin(x3), -cos((tau+33)/5) + n, 1)")


def solve_ivp(td, final_box):
    """CtcIvp on (x1, x2, x3, tau), input n = u - u*: forward from x0, and backward from
    x(14) too when the final box is given. Returns (x1, x2, x3) and its stats (ivp_stats)."""
    ctc = sillage.CtcIvp(IVP_F, 1, 10, sillage.TimePropag.FWD_BWD if final_box else sillage.TimePropag.FORWARD)
    b = initial_box()
    x = TubeVector(td, 4)
    x.set_gate(0, IntervalVector([b[0], b[1], b[2], Interval(0.0)]))
    if final_box:
        x.set_gate(td.nb_slices(), IntervalVector([FINAL[0], FINAL[1], FINAL[2], Interval(TF)]))
    ok = ctc.contract(x, TubeVector(td, 1, bound(Interval(-0.02, 0.02))))
    return x.subvector(0, 2), ivp_stats(ok, "CtcIvp: no trajectory from x0 with the inputs reaches the final box")


def truth(n):
    """RK4 of the true car (u*, centre of x0), sampled at the n+1 time points."""
    def f(t, x):
        return np.array([10 * math.cos(x[2]), 10 * math.sin(x[2]), -math.cos((t + 33) / 5)])
    return rk4(f, [0.0, 0.0, -6 * math.pi / 5], DT, n)


def main():
    out = out_dir(__doc__)
    td = TDomain(0.0, TF, DT)
    n = td.nb_slices()
    path = truth(n)
    ok, summary, figures = True, "", []
    for final_box in (False, True):
        t0 = time.perf_counter()
        x, stats = solve(td, final_box)
        elapsed = time.perf_counter() - t0
        xf = x.gate(n)
        t0 = time.perf_counter()
        xi, ivp = solve_ivp(td, final_box)
        elapsed_ivp = time.perf_counter() - t0
        label = "with the final box" if final_box else "from x0 only"
        if stats.empty:
            return empty_exit("causal_chain", stats, label)
        if ivp.empty:
            return empty_exit("causal_chain", ivp, "CtcIvp " + label)

        def inside(tube):
            g = [tube[i].gates_array() for i in range(3)]
            return all(g[i][k, 0] - 1e-9 <= path[k, i] <= g[i][k, 1] + 1e-9 for i in range(3) for k in range(n + 1))

        ok = enclosure_ok(x) and inside(x) and enclosure_ok(xi) and inside(xi) and ok
        print(f"{label}: {stats.iterations} iterations, {stats.contractor_calls} calls, {elapsed:.3f} s; "
              f"x(14) in {xf}; truth inside: {inside(x)}")
        print(f"  CtcIvp ({elapsed_ivp:.3f} s): x(14) in {xi.gate(n)}; truth inside: {inside(xi)}")
        if not final_box:
            xif = xi.gate(n)
            summary = (f"x(14) in [{xf[0].lb():.4f}, {xf[0].ub():.4f}] x [{xf[1].lb():.4f}, {xf[1].ub():.4f}]; "
                       f"CtcIvp [{xif[0].lb():.4f}, {xif[0].ub():.4f}] x [{xif[1].lb():.4f}, {xif[1].ub():.4f}]")
            print(f"  validated-integration box {CAPD[0]} x {CAPD[1]}; ours inside: "
                  f"{xf[0].is_subset(CAPD[0]) and xf[1].is_subset(CAPD[1])}")
        tag = "final" if final_box else "x0"
        fig = sillage.tube_vector_figure(x, 0, 1, f"Causal chain, {label} (Python)")
        fig.save(str(out / f"causal_chain_{tag}_py.svg"))
        figures.append((f"causal_chain_{tag}_py.svg", f"Causal chain (4.25) {label}, Python"))
        deriv_vs_ivp_figure(x, xi, out / f"causal_chain_{tag}_deriv_vs_ivp_py.png",
                            f"Causal chain {label}: CtcDeriv (blue) vs CtcIvp (orange)", path)
        figures.append((f"causal_chain_{tag}_deriv_vs_ivp_py.png",
                        f"Causal chain (4.25) {label}: CtcDeriv network in blue, CtcIvp in orange"))
    print_result("causal_chain", summary, ok, figures)


if __name__ == "__main__":
    run(main)
