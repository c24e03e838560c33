"""Kidnapped robot (thesis 4.4.3): the robot of 3.4, x' = (x4 cos x3, x4 sin x3,
u1, u2), u1 in -9/20 cos(t/5) + [-0.001, 0.001], u2 in 1/10 + sin(t/4) +
[-0.001, 0.001], t in [0, 64], with no prior on the position (x1, x2) but the
single measurement (4.30) x1(37) in [59.25, 61.25], x2(37) in [36.16, 38.16].
Heading and speed keep their initial box (3.17): x3(0) in pi/2 + [-0.01, 0.01],
x4(0) in [-0.01, 0.01] (without it the position is unbounded away from t = 37).
Network: x' = v (CtcDeriv, forward and backward from the measurement), v1 =
x4 cos x3, v2 = x4 sin x3 (pointwise), v3, v4 = the input tubes; the
measurement is the gate at t = 37 (sampled before the tubes are built); the
same network with CtcEval(t = 37) is run as a cross-check. The nominal RK4 path
and 64 extreme feasible paths are checked inside (gates and 3 samples per
slice). Same computations and printed figures as examples/cpp/kidnapped_robot.cpp.
Then again by CtcIvp (validated Taylor integration, docs/ivp.md) at delta = 0.05:
heading and speed (x3, x4, tau) alone, forward from x(0), give their box at
t = 37; then the whole state, its heading and speed tubes set to those, from
gate 37 = the measurement x that box, forward to 64 and backward to 0. The same
paths are checked inside; a matplotlib figure compares the two tubes."""
import math
import time

import numpy as np

import sillage
from dead_reckoning import IVP_F, NOISE
from example_args import bound, check_stats, deriv_vs_ivp_figure, enclosure_ok, out_dir, print_result, rk4, run
from sillage import CtcFunction, Function, Interval, IntervalVector, TDomain, Trajectory, Tube, TubeVector

TF, TM = 64.0, 37.0
M1, M2 = bound(Interval(5925, 6125) / Interval(100)), bound(Interval(3616, 3816) / Interval(100))  # (4.30), outward


def initial_box(heading_speed_known=True):
    """(3.17) without the position."""
    if not heading_speed_known:
        return IntervalVector(4)
    c = Interval(-1, 1) / Interval(100)
    return IntervalVector([Interval(), Interval(), Interval.half_pi() + c, c])


def make_tdomain(dt):
    td = TDomain(0.0, TF, dt)
    td.sample(TM)  # before any tube: a network's layout is fixed
    return td


def solve(td, use_eval=False, heading_speed_known=True):
    """Returns (x, stats, k37) on td (37 must be a time point of td)."""
    k37 = td.slice_index(TM)  # 37 is a time point: the slice starting there has its index
    x, v = TubeVector(td, 4), TubeVector(td, 4)
    v[2] = Tube(td, "-9/20*cos(t/5) + [-0.001, 0.001]")  # (3.16)
    v[3] = Tube(td, "1/10 + sin(t/4) + [-0.001, 0.001]")
    x.set_gate(0, initial_box(heading_speed_known))
    cn = sillage.ContractorNetwork()
    cn.add(CtcFunction(Function(["x3", "x4", "v1"], "x4*cos(x3) - v1")), [x[2], x[3], v[0]])
    cn.add(CtcFunction(Function(["x3", "x4", "v2"], "x4*sin(x3) - v2")), [x[2], x[3], v[1]])
    cn.add(sillage.CtcDeriv(), [x, v])
    if use_eval:
        t = Interval(TM)
        z1, z2 = Interval(M1), Interval(M2)
        cn.add(sillage.CtcEval(), [t, z1, x[0], v[0]])
        cn.add(sillage.CtcEval(), [t, z2, x[1], v[1]])
    else:
        x[0].set_gate(k37, M1)
        x[1].set_gate(k37, M2)
    stats = cn.contract()
    return x, stats, k37


HEADING_F = Function(["x3", "x4", "tau", "n1", "n2"], "(-9/20*cos(tau/5) + n1, 1/10 + sin(tau/4) + n2, 1)")


def solve_ivp(td):
    """CtcIvp (see the module doc): returns (x1..x4, success flag, k37)."""
    k37 = td.slice_index(TM)
    noise = TubeVector(td, 2, bound(NOISE))
    b0 = initial_box()
    h = TubeVector(td, 3)
    h.set_gate(0, IntervalVector([b0[2], b0[3], Interval(0.0)]))
    ok = sillage.CtcIvp(HEADING_F, 2, 10, sillage.TimePropag.FORWARD).contract(h, noise)
    h37 = h.gate(k37)
    x = TubeVector(td, 5)
    for i in (2, 3, 4):
        x[i] = h[i - 2]  # heading and speed as known forward from x(0)
    x.set_gate(k37, IntervalVector([M1, M2, h37[0], h37[1], Interval(TM)]))
    ok = ok and sillage.CtcIvp(IVP_F, 2, 10, sillage.TimePropag.FWD_BWD).contract(x, noise)
    if not ok:
        print("  CtcIvp: EMPTY (no trajectory of the inputs meets the measurement)")
    return x.subvector(0, 3), ok, k37


def reference_paths(dt):
    """States every h = dt/4, shape (4N+1, 65, 4): the nominal path first, then the
    16 extreme paths (corners of x3(0), x4(0), constant input errors +-0.001)
    translated to pass at each corner of the measurement box at t = 37 (with no
    prior on the position, a translation keeps a path feasible)."""
    starts, errs = [[0.0, 0.0, math.pi / 2, 0.0]], [[0.0, 0.0]]
    for e in range(16):
        starts.append([0.0, 0.0, math.pi / 2 + (0.01 if e & 1 else -0.01), 0.01 if e & 2 else -0.01])
        errs.append([1e-3 if e & 4 else -1e-3, 1e-3 if e & 8 else -1e-3])
    x0, c = np.array(starts), np.array(errs)
    h = dt / 4
    n = int(round(TF / h))

    def f(t, x):
        return np.stack([x[:, 3] * np.cos(x[:, 2]), x[:, 3] * np.sin(x[:, 2]),
                         -9 / 20 * np.cos(t / 5) + c[:, 0], 0.1 + np.sin(t / 4) + c[:, 1]], axis=1)

    base = rk4(f, x0, h, n)
    j37 = int(round(TM / h))
    paths = [base[:, 0]]
    for e in range(1, 17):
        for corner in range(4):
            p = base[:, e].copy()
            p[:, 0] += (61.25 if corner & 1 else 59.25) - p[j37, 0]
            p[:, 1] += (38.16 if corner & 2 else 36.16) - p[j37, 1]
            paths.append(p)
    return np.stack(paths, axis=1)


def max_excess(x, paths):
    """Largest distance of the sampled paths outside the tube: samples 4k are at the
    gates t_k (also in slices k-1 and k), samples 4k+1..4k+3 inside slice k."""
    worst = 0.0
    for i in range(4):
        s, g = x[i].slices_array(), x[i].gates_array()
        vals = paths[:, :, i]
        gate_vals = vals[0::4]
        ex = [np.maximum(g[:, :1] - gate_vals, gate_vals - g[:, 1:])]
        inner = vals[1:].reshape(len(s), 4, -1)[:, :3, :]
        ex.append(np.maximum(s[:, None, :1] - inner, inner - s[:, None, 1:]))
        ex.append(np.maximum(s[:, :1] - gate_vals[1:], gate_vals[1:] - s[:, 1:]))
        ex.append(np.maximum(s[:, :1] - gate_vals[:-1], gate_vals[:-1] - s[:, 1:]))
        worst = max(worst, max(float(np.nan_to_num(e, nan=np.inf).max()) for e in ex))
    return max(worst, 0.0)


def diagonal(b):
    return math.hypot(b[0].diam(), b[1].diam())


def main(deltas=(0.05, 0.01, 0.005), out=None):
    out = out or out_dir(__doc__)
    ok, summary, figures, results = True, "", [], {}
    for dt in deltas:
        td = make_tdomain(dt)
        n = td.nb_slices()
        assert n == round(TF / dt), "37 must be a point of the uniform slicing for the sampled check"
        t0 = time.process_time()
        x, stats, k37 = solve(td)
        cpu = time.process_time() - t0
        paths = reference_paths(dt)
        if dt == deltas[0]:
            p37 = paths[int(round(TM / (dt / 4))), 0]
            inside37 = M1.contains(p37[0]) and M2.contains(p37[1])
            print(f"nominal RK4 truth at t = 37: ({p37[0]:.4f}, {p37[1]:.4f}), "
                  f"{'inside' if inside37 else 'NOT inside'} the measurement box [59.25, 61.25] x [36.16, 38.16]")
        worst_nominal = max_excess(x, paths[:, :1])
        worst = max_excess(x, paths)
        ok = check_stats(stats, f"delta = {dt}") and enclosure_ok(x) and worst <= 1e-9 and ok
        p0, p37, pf = x.gate(0).subvector(0, 1), x.gate(k37).subvector(0, 1), x.gate(n).subvector(0, 1)
        results[dt] = (diagonal(p0), diagonal(p37), diagonal(pf))
        print(f"delta = {dt:<5g} ({n:5d} slices): thickness d (box diagonal) at t = 0: {diagonal(p0):.3f}, "
              f"37: {diagonal(p37):.3f}, 64: {diagonal(pf):.3f}; {stats.iterations} iterations, "
              f"{stats.contractor_calls} calls, {cpu:.4f} s CPU")
        print(f"  p(0) in [{p0[0].lb():.2f}, {p0[0].ub():.2f}] x [{p0[1].lb():.2f}, {p0[1].ub():.2f}], "
              f"p(64) in [{pf[0].lb():.2f}, {pf[0].ub():.2f}] x [{pf[1].lb():.2f}, {pf[1].ub():.2f}]; "
              f"truth inside: {'yes' if worst_nominal <= 1e-9 else 'NO'} (max excess {worst_nominal:.1e}), "
              f"64 extreme paths inside: {'yes' if worst <= 1e-9 else 'NO'} (max excess {worst:.1e})")
        if dt == 0.05:
            t0 = time.process_time()
            xi, ivp_ok, _ = solve_ivp(td)
            cpu_ivp = time.process_time() - t0
            worst_ivp = max_excess(xi, paths)
            ok = ok and ivp_ok and enclosure_ok(xi) and worst_ivp <= 1e-9
            q0, qf = xi.gate(0).subvector(0, 1), xi.gate(n).subvector(0, 1)
            results["ivp"] = (diagonal(q0), diagonal(xi.gate(k37).subvector(0, 1)), diagonal(qf))
            print(f"  CtcIvp ({cpu_ivp:.3f} s CPU): d(0) = {diagonal(q0):.3f}, d(64) = {diagonal(qf):.3f}; "
                  f"p(0) in [{q0[0].lb():.2f}, {q0[0].ub():.2f}] x [{q0[1].lb():.2f}, {q0[1].ub():.2f}], "
                  f"p(64) in [{qf[0].lb():.2f}, {qf[0].ub():.2f}] x [{qf[1].lb():.2f}, {qf[1].ub():.2f}]; "
                  f"65 paths inside: {'yes' if worst_ivp <= 1e-9 else 'NO'} (max excess {worst_ivp:.1e})")
        if dt == 0.005:
            summary = (f"delta=0.005: d(0) = {diagonal(p0):.2f}, d(37) = {diagonal(p37):.2f}, "
                       f"d(64) = {diagonal(pf):.2f}; {1000 * cpu:.0f} ms")
            t0 = time.process_time()
            xe, se, _ = solve(td, use_eval=True)
            same = xe == x
            print(f"  with CtcEval(t = 37) instead of the gate: {'the same tubes' if same else 'different tubes'} "
                  f"({se.iterations} iterations, {time.process_time() - t0:.4f} s CPU)")
            ok = ok and (same or xe.is_subset(x) or x.is_subset(xe))
            xu, _, _ = solve(td, heading_speed_known=False)
            print(f"  without (3.17) on heading and speed either: x1(0) in {xu[0].gate(0)}, x1(64) in "
                  f"{xu[0].gate(n)} (unbounded, as expected)")
            times = [td.t(k) for k in range(n + 1)]
            t1 = Trajectory(times, list(paths[0::4, 0, 0]))
            t2 = Trajectory(times, list(paths[0::4, 0, 1]))
            fig = sillage.tube_vector_figure(x, 0, 1, "Kidnapped robot: [x1] x [x2], measurement at t = 37 (Python)",
                                             sillage.TubeStyle(), t1, t2)
            fig.draw_box(IntervalVector([M1, M2]), sillage.Style("#e53935", "#b71c1c", 1.0, 0.7, "measurement"))
            fig.save(str(out / "kidnapped_robot_py.svg"))
            figures.append(("kidnapped_robot_py.svg", "Kidnapped robot (4.30): [x1](.) x [x2](.), measurement box "
                                                      "in red, truth in red (Fig. 4.11), Python"))
            if 0.05 in deltas:
                deriv_vs_ivp_figure(x, xi, out / "kidnapped_robot_deriv_vs_ivp_py.png",
                                    "Kidnapped robot: CtcDeriv (blue) vs CtcIvp (orange)",
                                    paths[0::4, 0, :])
                figures.append(("kidnapped_robot_deriv_vs_ivp_py.png",
                                "Kidnapped robot: the CtcDeriv network in blue, CtcIvp in orange, truth in red"))
                summary += f"; CtcIvp d(0) = {results['ivp'][0]:.2f}, d(64) = {results['ivp'][2]:.2f}"
            th = sillage.thickness_figure(x.subvector(0, 1), sillage.ThicknessMeasure.Diagonal,
                                          "Kidnapped robot: thickness d(t) of [x1] x [x2] (Python)")
            th.save(str(out / "kidnapped_robot_thickness_py.svg"))
            figures.append(("kidnapped_robot_thickness_py.svg",
                            "Kidnapped robot: diagonal thickness of [x1](.) x [x2](.) (Fig. 4.12), Python"))
    print_result("kidnapped_robot", summary, ok, figures)
    return ok, results


if __name__ == "__main__":
    run(lambda: 0 if main()[0] else 1)
