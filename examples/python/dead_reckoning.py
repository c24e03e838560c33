"""Dead reckoning of a mobile robot (thesis 3.4, (3.14)-(3.20)): inputs (3.16)
as tubes, x0 in the box (3.17), t in [0, 64]. Four guaranteed resolutions, as
in the C++ example:
  plain:  primitives of [u], v = x4 cos x3 by tube arithmetic, primitives of [v];
  cn:     the contractor network (3.18): x' = v by CtcDeriv, v1 = x4 cos x3,
          v2 = x4 sin x3 as pointwise tube contractors, in a ContractorNetwork;
  taylor: slice integrals by first-order Taylor forms from the gates
          (sillage.primitive_taylor / taylor_increments);
  linear: linearisation around the nominal path with a bounded second-order
          remainder, at 64 checkpoints, intersected with taylor;
  ivp:    CtcIvp (validated Taylor integration, docs/ivp.md) on x' = f(x, u):
          the nominal inputs written in f with the time as a state (tau' = 1),
          the noise as an input tube (any n(t) within 1/1000).
The nominal and extreme trajectories (RK4, step delta/4) are checked inside."""
import time

import numpy as np

import sillage  # noqa: F401
from example_args import bound, check_stats, deriv_vs_ivp_figure, enclosure_ok, out_dir, print_result, rk4, run
from sillage import CtcFunction, Function, Interval, IntervalVector, TDomain, Tube, TubeVector

TF = 64.0


def initial_box():
    c = bound(Interval(-1, 1)) / Interval(100)
    return IntervalVector([bound(Interval(-1, 1)), bound(Interval(-1, 1)), Interval.half_pi() + c, c])


def inputs(td):
    return (Tube(td, "-9/20*cos(t/5) + [-0.001,0.001]"), Tube(td, "1/10 + sin(t/4) + [-0.001,0.001]"))


def solve_plain(td):
    x0 = initial_box()
    u1, u2 = inputs(td)
    x3, x4 = u1.primitive(x0[2]), u2.primitive(x0[3])
    x1 = (x4 * sillage.cos(x3)).primitive(x0[0])
    x2 = (x4 * sillage.sin(x3)).primitive(x0[1])
    return TubeVector([x1, x2, x3, x4])


def solve_cn(td):
    """CN (3.18) in a ContractorNetwork: x' = v by CtcDeriv (the optimal slice rule of
    chapter 4), v1 = x4 cos x3, v2 = x4 sin x3 pointwise, v3 = u1, v4 = u2, x(0) in x0."""
    u1, u2 = inputs(td)
    x, v = TubeVector(td, 4), TubeVector(td, 4)
    x.set_gate(0, initial_box())
    v[2], v[3] = u1, u2
    cn = sillage.ContractorNetwork()
    cn.add(CtcFunction(Function(["x3", "x4", "v"], "x4*cos(x3) - v")), [x[2], x[3], v[0]])
    cn.add(CtcFunction(Function(["x3", "x4", "v"], "x4*sin(x3) - v")), [x[2], x[3], v[1]])
    cn.add(sillage.CtcDeriv(), [x, v])
    check_stats(cn.contract(), "cn")  # empty: x is empty and fails enclosure_ok
    return x


NOISE = Interval(-1, 1) / Interval(1000)


def solve_taylor(td):
    """Slice integrals from the gates: int v in d v(t_k) + d^2/2 [v'](k), from either gate."""
    x0 = initial_box()
    u1, u2 = inputs(td)
    x3 = sillage.primitive_taylor(Tube(td, "-9/20*cos(t/5)"), Tube(td, "9/100*sin(t/5)"), x0[2], NOISE)
    x4 = sillage.primitive_taylor(Tube(td, "1/10 + sin(t/4)"), Tube(td, "cos(t/4)/4"), x0[3], NOISE)
    c, s = sillage.cos(x3), sillage.sin(x3)
    v1, v2 = x4 * c, x4 * s
    dv1, dv2 = u2 * c - x4 * s * u1, u2 * s + x4 * c * u1
    inc1, inc2 = sillage.taylor_increments(v1, dv1), sillage.taylor_increments(v2, dv2)
    x1 = sillage.primitive_from_increments(v1, inc1, x0[0])
    x2 = sillage.primitive_from_increments(v2, inc2, x0[1])
    return TubeVector([x1, x2, x3, x4]), (v1, v2, inc1, inc2)


def solve_linear(td, taylor, checkpoints=64):
    """x = nominal + e. The first-order part of e(T) is linear in the initial error
    (|e0| <= 1/100) and the input noise (|eps| <= 1/1000): its exact range is
    (|A(0)| + |B(0)|)/100 + int_0^T (|A| + |B|)/1000, A(s) = int_s^T alpha, B likewise
    (alpha, beta: the sensitivities below); the second-order remainder is bounded with
    |e3|, |e4| <= E(t) = 1/100 + t/1000. Added at checkpoints, then propagated by the
    Taylor increments."""
    (x_t, (v1, v2, inc1, inc2)) = taylor
    x0 = initial_box()
    a, s = Tube(td, "sin(9/4*sin(t/5))"), Tube(td, "cos(9/4*sin(t/5))")  # cos x3n, sin x3n
    x4n, E = Tube(td, "t/10 + 4 - 4*cos(t/4)"), Tube(td, "1/100 + t/1000")
    da = Tube(td, "cos(9/4*sin(t/5))*9/20*cos(t/5)")
    ds = Tube(td, "-sin(9/4*sin(t/5))*9/20*cos(t/5)")
    u2n = Tube(td, "1/10 + sin(t/4)")
    pa, ps = a.primitive(), s.primitive()
    pb1, pb2 = (-(x4n * s)).primitive(), (x4n * a).primitive()
    rem = (sillage.abs(x4n) * sillage.sqr(E) / Interval(2) + E * (E + sillage.sqr(E) / Interval(2))).primitive()
    n1 = sillage.primitive_taylor(x4n * a, u2n * a + x4n * da)
    n2 = sillage.primitive_taylor(x4n * s, u2n * s + x4n * ds)

    def radius(p_a, p_b, k):
        at, bt = p_a.gate(k), p_b.gate(k)
        absum = sillage.abs(at - p_a) + sillage.abs(bt - p_b)  # |A|, |B| over each slice
        first = (Interval((at - p_a.gate(0)).mag()) + Interval((bt - p_b.gate(0)).mag())) / Interval(100)
        return (first + absum.integral(td.t(k)) / Interval(1000)).ub()

    n = td.nb_slices()
    g1, g2 = [x_t[0].gate(k) for k in range(n + 1)], [x_t[1].gate(k) for k in range(n + 1)]
    step = max(1, n // checkpoints)
    for k in list(range(step, n, step)) + [n]:
        r = rem.gate(k).ub()
        g1[k] &= x0[0] + n1.gate(k) + Interval(-1, 1) * Interval(radius(pa, pb1, k) + r)
        g2[k] &= x0[1] + n2.gate(k) + Interval(-1, 1) * Interval(radius(ps, pb2, k) + r)
    x = TubeVector(x_t)
    x[0] = sillage.primitive_from_increments(v1, inc1, x0[0], g1)
    x[1] = sillage.primitive_from_increments(v2, inc2, x0[1], g2)
    return x


IVP_F = Function(["x1", "x2", "x3", "x4", "tau", "n1", "n2"],
                 "(x4*cos(x3), x4*sin(x3), -9/20*cos(tau/5) + n1, 1/10 + sin(tau/4) + n2, 1)")


def solve_ivp(td):
    """Validated integration by CtcIvp, forward from x0 (the only bounded gate):
    state (x1, x2, x3, x4, tau), inputs (n1, n2) = the noise of (3.16) as tubes."""
    ctc = sillage.CtcIvp(IVP_F, 2, 10, sillage.TimePropag.FORWARD)
    b = initial_box()
    x = TubeVector(td, 5)
    x.set_gate(0, IntervalVector([b[0], b[1], b[2], b[3], Interval(0.0)]))
    if not ctc.contract(x, TubeVector(td, 2, bound(NOISE))):
        print("  ivp: EMPTY (no trajectory fits x0 and the inputs)")
    return x.subvector(0, 3)


def rk4_paths(dt):
    """Nominal path first, then the corners of x0 (x3, x4) x constant input errors
    +-0.001 (x1, x2 at corners too); states sampled every h = dt/4: shape (steps+1, paths, 4)."""
    starts, errs = [[0.0, 0.0, np.pi / 2, 0.0]], [[0.0, 0.0]]
    for e in range(16):
        s3, s4 = (1 if e & 1 else -1), (1 if e & 2 else -1)
        starts.append([1.0 if e & 1 else -1.0, -1.0 if e & 2 else 1.0, np.pi / 2 + 0.01 * s3, 0.01 * s4])
        errs.append([1e-3 if e & 4 else -1e-3, 1e-3 if e & 8 else -1e-3])
    x, c = np.array(starts), np.array(errs)
    h = dt / 4
    n = int(round(TF / h))

    def f(t, x):
        return np.stack([x[:, 3] * np.cos(x[:, 2]), x[:, 3] * np.sin(x[:, 2]),
                         -9 / 20 * np.cos(t / 5) + c[:, 0], 0.1 + np.sin(t / 4) + c[:, 1]], axis=1)

    return rk4(f, x, h, n)


def check(x, paths):
    """(misses beyond 1e-9, borderline misses in (0, 1e-9], max excess) over every sample."""
    misses = borderline = 0
    worst = 0.0
    for i in range(4):
        s, g = x[i].slices_array(), x[i].gates_array()
        vals = paths[:, :, i]                      # (4N+1, paths)
        gate_vals = vals[0::4]                     # at t_k
        ex = np.maximum(g[:, :1] - gate_vals, gate_vals - g[:, 1:])
        inner = vals[1:].reshape(len(s), 4, -1)[:, :3, :]  # samples strictly inside slice k
        ex_s = np.maximum(s[:, None, :1] - inner, inner - s[:, None, 1:])
        # a gate time also lies in both neighbouring slices
        ex_l = np.maximum(s[:, :1] - gate_vals[1:], gate_vals[1:] - s[:, 1:])
        ex_r = np.maximum(s[:, :1] - gate_vals[:-1], gate_vals[:-1] - s[:, 1:])
        all_ex = np.concatenate([ex.ravel(), ex_s.ravel(), ex_l.ravel(), ex_r.ravel()])
        misses += int(np.sum(all_ex > 1e-9))
        borderline += int(np.sum((all_ex > 0) & (all_ex <= 1e-9)))
        worst = max(worst, float(all_ex.max()))
    return misses, borderline, worst


def compare_figure(deriv, ivp, paths, out):
    """[x1] x [x2] of the CtcDeriv network (blue) and of CtcIvp (orange, over it), matplotlib."""
    deriv_vs_ivp_figure(deriv, ivp, out / "dead_reckoning_deriv_vs_ivp_py.png",
                        "Dead reckoning, delta = 0.005: CtcDeriv (blue) vs CtcIvp (orange)", paths[:, 0, :])
    return ("dead_reckoning_deriv_vs_ivp_py.png", "CtcDeriv network (3.18) in blue, CtcIvp in orange, nominal in red")


def map_figure(x, nominal, out):
    """[x1] x [x2] (SVG) with the nominal RK4 path over it: the path the tube must hold."""
    fig = sillage.tube_vector_figure(x, 0, 1, "[x1] x [x2], delta = 0.005, and the nominal path")
    # One point in 16 (4 delta apart): the line stays light and still follows the path.
    fig.draw_polyline([[float(a), float(b)] for a, b in nominal[::16, :2]],
                      sillage.Style("none", "#d62728", 1.0, 1.0, "nominal", "nominal path (RK4)"))
    fig.save(str(out / "dead_reckoning_py.svg"))
    return ("dead_reckoning_py.svg", "Dead reckoning (3.18): [x1](.) x [x2](.) and the nominal path (red), Python")


def box_str(a, b):
    return f"[{a.lb():.2f}, {a.ub():.2f}] x [{b.lb():.2f}, {b.ub():.2f}]"


def main():
    out = out_dir(__doc__)
    ok, summary, figures = True, "", []
    for dt in (0.05, 0.01, 0.005):
        td = TDomain(0.0, TF, dt)
        n = td.nb_slices()
        paths = rk4_paths(dt)
        print(f"delta = {dt} ({n} slices)")
        results = {}
        taylor = None

        def run_taylor(td):
            nonlocal taylor
            taylor = solve_taylor(td)
            return taylor[0]

        for name, solve in (("plain", solve_plain), ("cn", solve_cn), ("taylor", run_taylor),
                            ("linear", lambda td: solve_linear(td, taylor)), ("ivp", solve_ivp)):
            t0 = time.perf_counter()
            x = solve(td)
            elapsed = time.perf_counter() - t0
            misses, border, worst = check(x, paths)
            ok = ok and enclosure_ok(x) and misses == 0
            results[name] = x
            print(f"  {name:6s} p(tf) in {box_str(x[0].gate(n), x[1].gate(n))}  ({elapsed:.3f} s); "
                  f"{paths.shape[1]} RK4 paths: {misses} misses, {border} borderline, max excess {worst:.1e}")
        print(f"  nominal RK4 p(tf) = ({paths[-1, 0, 0]:.4f}, {paths[-1, 0, 1]:.4f})")
        end = paths[-1, :, :2]  # the sampled final positions: their hull is an inner bound of the true set
        print(f"  hull of the {paths.shape[1]} RK4 p(tf): [{end[:, 0].min():.2f}, {end[:, 0].max():.2f}] x "
              f"[{end[:, 1].min():.2f}, {end[:, 1].max():.2f}]; CtcDeriv (cn) "
              f"{box_str(results['cn'][0].gate(n), results['cn'][1].gate(n))}, CtcIvp "
              f"{box_str(results['ivp'][0].gate(n), results['ivp'][1].gate(n))}")
        if dt == 0.005:
            summary = "delta=0.005: p(64) in " + ", ".join(
                f"{box_str(results[k][0].gate(n), results[k][1].gate(n))} ({k})"
                for k in ("plain", "cn", "taylor", "linear", "ivp"))
            figures.append(compare_figure(results["cn"], results["ivp"], paths, out))
            try:
                figures.append(map_figure(results["plain"], paths[:, 0, :], out))
                th = sillage.thickness_figure(results["plain"].subvector(0, 1), sillage.ThicknessMeasure.Diagonal,
                                              "Thickness of [x1] x [x2]")
                th.save(str(out / "dead_reckoning_thickness_py.svg"))
                figures.append(("dead_reckoning_thickness_py.svg", "Thickness d(t) of [x1](.) x [x2](.)"))
            except AttributeError:  # the tube figures are not bound
                pass
    print_result("dead_reckoning", summary, ok, figures)


if __name__ == "__main__":
    run(main)
