"""Higher-order differential constraints (thesis 4.4.2, CN (4.29)): a robot on
the Lissajous curve x(t) = 5 (2 cos t, sin 2t), unknown to the solver, which
knows only x1'' in -10 cos(t) + [-0.001, 0.001], x2'' = -0.4 x1' x1'',
x'(0) = (0, 10), x(0) in [9.8, 10.2] x [-0.2, 0.2], on t in [0, 2 pi].
Tubes x, x', x'' (TubeVector), CtcDeriv for x' and x'', the pointwise
CtcFunction of constraint 2; x1'' is built from constraint 1. The analytic truth
and its derivatives are checked inside, rigorously. Same computations and
printed figures as examples/cpp/lissajous.cpp.
Then again by CtcIvp (validated Taylor integration, docs/ivp.md): constraints 1-2
as the state equations of (x1, x2, x1', x2', tau), the noise of x1'' as an input
tube and tau' = 1 for the known part; a matplotlib figure compares the two tubes."""
import math
import time

import sillage
import numpy as np

from example_args import bound, check_stats, deriv_vs_ivp_figure, enclosure_ok, out_dir, print_result, run
from sillage import CtcFunction, Function, Interval, IntervalVector, TDomain, Trajectory, Tube, TubeVector

TF = 2 * math.pi  # the double just below 2 pi: one period
MAIN_DT = 0.001


def solve(dt):
    """Returns (x, x', x'', stats) on [0, 2 pi] with slices of width dt."""
    td = TDomain(0.0, TF, dt)
    x, dx, ddx = TubeVector(td, 2), TubeVector(td, 2), TubeVector(td, 2)
    ddx[0] = Tube(td, "-10*cos(t) + [-0.001, 0.001]")  # constraint 1
    dx.set_gate(0, IntervalVector([Interval(0), Interval(10)]))
    # [9.8, 10.2] x [-0.2, 0.2], enclosing the decimal bounds (outward division)
    x.set_gate(0, IntervalVector([bound(Interval(98, 102) / Interval(10)), bound(Interval(-2, 2) / Interval(10))]))
    cn = sillage.ContractorNetwork()
    cn.add(CtcFunction(Function(["a2", "v1", "a1"], "a2 + 0.4*v1*a1")), [ddx[1], dx[0], ddx[0]])  # constraint 2
    cn.add(sillage.CtcDeriv(), [dx, ddx])
    cn.add(sillage.CtcDeriv(), [x, dx])
    stats = cn.contract()
    return x, dx, ddx, stats


IVP_F = Function(["x1", "x2", "v1", "v2", "tau", "n"], "(v1, v2, -10*cos(tau) + n, -0.4*v1*(-10*cos(tau) + n), 1)")


def solve_ivp(dt):
    """CtcIvp on (x1, x2, v1, v2, tau), the noise of constraint 1 as the input, forward from
    the gate at 0. Returns (x, x') and the success flag."""
    td = TDomain(0.0, TF, dt)
    x = TubeVector(td, 5)
    x.set_gate(0, IntervalVector([bound(Interval(98, 102) / Interval(10)), bound(Interval(-2, 2) / Interval(10)),
                                  Interval(0), Interval(10), Interval(0)]))
    ok = sillage.CtcIvp(IVP_F, 1, 10, sillage.TimePropag.FORWARD).contract(
        x, TubeVector(td, 1, bound(Interval(-1, 1) / Interval(1000))))
    if not ok:
        print("  CtcIvp: EMPTY (no trajectory from x(0))")
    return x.subvector(0, 1), x.subvector(2, 3), ok


def truths():
    dom = Interval(0, TF)
    return ([Trajectory("10*cos(t)", dom), Trajectory("5*sin(2*t)", dom)],
            [Trajectory("-10*sin(t)", dom), Trajectory("10*cos(2*t)", dom)],
            [Trajectory("-10*cos(t)", dom), Trajectory("-20*sin(2*t)", dom)])


def box_str(b):
    return f"[{b[0].lb():.4f}, {b[0].ub():.4f}] x [{b[1].lb():.4f}, {b[1].ub():.4f}]"


def main(deltas=(0.01, 0.001, 0.0001), out=None):
    out = out or out_dir(__doc__)
    x_true, dx_true, ddx_true = truths()
    ok, summary, results, results_tubes = True, "", {}, {}
    for dt in deltas:
        t0 = time.process_time()
        x, dx, ddx, stats = solve(dt)
        cpu = time.process_time() - t0
        n = x.nb_slices()
        inside = (check_stats(stats, f"delta = {dt}") and enclosure_ok(x, dx, ddx) and x.contains(x_true)
                  and dx.contains(dx_true) and ddx.contains(ddx_true))
        ok = ok and inside
        w1, w2 = x[0].max_thickness(), x[1].max_thickness()
        results[dt] = (x.gate(n), w1, w2)
        results_tubes[dt] = x
        print(f"delta = {dt:<6g} ({n:6d} slices): x(2pi) in {box_str(x.gate(n))}, max thickness x1 {w1:.4f}, "
              f"x2 {w2:.4f}; {stats.iterations} iterations, {stats.contractor_calls} calls, {cpu:.4f} s CPU; "
              f"truth inside x, x', x'': {'yes' if inside else 'NO'}")
        if dt == MAIN_DT:
            summary = (f"delta=0.001: max thickness x1 {w1:.3f}, x2 {w2:.3f}; x(2pi) in {box_str(x.gate(n))}; "
                       f"{1000 * cpu:.0f} ms")
            fig = sillage.tube_vector_figure(x, 0, 1, "Lissajous envelope [x1] x [x2], delta = 0.001 (Python)",
                                             sillage.TubeStyle(), x_true[0], x_true[1])
            fig.save(str(out / "lissajous_py.svg"))
    # CtcIvp beside the network, on the same slices (the main delta).
    t0 = time.process_time()
    xi, dxi, ivp_ok = solve_ivp(MAIN_DT)
    cpu = time.process_time() - t0
    n = xi.nb_slices()
    inside = ivp_ok and enclosure_ok(xi, dxi) and xi.contains(x_true) and dxi.contains(dx_true)
    ok = ok and inside
    wi1, wi2 = xi[0].max_thickness(), xi[1].max_thickness()
    results["ivp"] = (xi.gate(n), wi1, wi2)
    print(f"CtcIvp, delta = {MAIN_DT:g}: x(2pi) in {box_str(xi.gate(n))}, max thickness x1 {wi1:.4f}, x2 {wi2:.4f}; "
          f"{cpu:.3f} s CPU; truth inside x, x': {'yes' if inside else 'NO'}")
    summary += f"; CtcIvp: max thickness x1 {wi1:.3f}, x2 {wi2:.3f}, x(2pi) in {box_str(xi.gate(n))}"
    figures = [("lissajous_py.svg", "Lissajous robot, CN (4.29): envelope [x1](.) x [x2](.) on [0, 2pi] and the "
                                    "unknown truth (red), Fig. 4.10, Python")]
    if MAIN_DT in deltas:
        ts = np.linspace(0.0, TF, 400)
        deriv_vs_ivp_figure(results_tubes[MAIN_DT], xi, out / "lissajous_deriv_vs_ivp_py.png",
                            "Lissajous, delta = 0.001: CtcDeriv (blue) vs CtcIvp (orange)",
                            np.column_stack([10 * np.cos(ts), 5 * np.sin(2 * ts)]))
        figures.append(("lissajous_deriv_vs_ivp_py.png",
                        "Lissajous robot: the CtcDeriv network in blue, CtcIvp in orange, the truth in red"))
    print_result("lissajous", summary, ok, figures)
    return ok, results


if __name__ == "__main__":
    run(lambda: 0 if main()[0] else 1)
