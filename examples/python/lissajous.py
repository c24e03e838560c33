"""Higher-order differential constraints (thesis 4.4.2, CN (4.29)): a robot on
the Lissajous curve x(t) = 5 (2 cos t, sin 2t), unknown to the solver, which
knows only x1'' in -10 cos(t) + [-0.001, 0.001], x2'' = -0.4 x1' x1'',
x'(0) = (0, 10), x(0) in [9.8, 10.2] x [-0.2, 0.2], on t in [0, 2 pi].
Tubes x, x', x'' (TubeVector), CtcDeriv for x' and x'', the pointwise
CtcFunction of constraint 2; x1'' is built from constraint 1. The analytic truth
and its derivatives are checked inside, rigorously. Same computations and
printed figures as examples/cpp/lissajous.cpp."""
import math
import time

import sillage
from example_args import bound, check_stats, enclosure_ok, out_dir, print_result
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
    ok, summary, results = True, "", {}
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
        print(f"delta = {dt:<6g} ({n:6d} slices): x(2pi) in {box_str(x.gate(n))}, max thickness x1 {w1:.4f}, "
              f"x2 {w2:.4f}; {stats.iterations} iterations, {stats.contractor_calls} calls, {cpu:.4f} s CPU; "
              f"truth inside x, x', x'': {'yes' if inside else 'NO'}")
        if dt == MAIN_DT:
            summary = (f"delta=0.001: max thickness x1 {w1:.3f}, x2 {w2:.3f}; x(2pi) in {box_str(x.gate(n))}; "
                       f"{1000 * cpu:.0f} ms")
            fig = sillage.tube_vector_figure(x, 0, 1, "Lissajous envelope [x1] x [x2], delta = 0.001 (Python)",
                                             sillage.TubeStyle(), x_true[0], x_true[1])
            fig.save(str(out / "lissajous_py.svg"))
    print_result("lissajous", summary, ok,
                 [("lissajous_py.svg", "Lissajous robot, CN (4.29): envelope [x1](.) x [x2](.) on [0, 2pi] and the "
                                       "unknown truth (red), Fig. 4.10, Python")])
    return ok, results


if __name__ == "__main__":
    raise SystemExit(0 if main()[0] else 1)
