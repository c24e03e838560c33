"""A small temporal SLAM (thesis 7.2, Alg. 15) on a synthetic case with a known truth:
a robot on a figure eight p*(t) = (10 sin(t - 1/2), 5 sin(2t - 1)), t in [0, 5], crosses
its own path once (t1 = 1/2, t2 = 1/2 + pi). Its state is (x1, x2, depth), its velocities
are measured to +-0.2 (u), its start is known to +-0.05, and it senses the seabed height
z = g(p) to +-0.01 where g (a synthetic field) is never given to the solver. The loop is
detected and proven in the t-plane, the observation keeps the t-boxes where z(t1) = z(t2),
and C_p=>z pulls the end of the mission back; fast (Alg. 14) then accurate (Alg. 13).
The true trajectory must stay inside [x](.) at every gate after each algorithm."""
import time

import sillage
from example_args import bound, out_dir, print_result, run
from sillage import (CtcDeriv, Function, Interval, IntervalVector, Style, TDomain, TemporalSlamOptions, Trajectory,
                     Tube, TubeStyle, TubeVector)

TRUTH = ("10*sin(t - 0.5)", "5*sin(2*t - 1)")
# The measurements: truth plus a sensor error within the stated bounds (0.2, 0.01, 0.05).
VELOCITY = ("10*cos(t - 0.5) + 0.15*sin(3*t)", "10*cos(2*t - 1) - 0.15*cos(5*t)")
FIELD = "sin(10*sin(t - 0.5)/3) + cos(5*sin(2*t - 1)/4) + sin(t - 0.5) + 0.008*sin(7*t)"  # g(p*(t)) + error
START = (-4.79425538604203 + 0.03, -4.207354924039483 - 0.03)


def mission(td):
    e_v, e_z, e_0 = bound(0.2), bound(0.01), bound(0.05)
    err = lambda e: f" + [{-e!r}, {e!r}]"
    u = TubeVector([Tube(td, VELOCITY[0] + err(e_v)), Tube(td, VELOCITY[1] + err(e_v)),
                    Tube(td, Interval(-0.01, 0.01))])
    z = TubeVector([Tube(td, FIELD + err(e_z))])
    x, v = TubeVector(td, 3), TubeVector(td, 3)
    x.set_gate(0, IntervalVector([Interval(s - e_0, s + e_0) for s in START] + [Interval(-5.05, -4.95)]))
    return x, v, u, z


def main():
    out = out_dir(__doc__)
    td = TDomain(0.0, 5.0, 0.01)
    dom = td.t0_tf()
    truth = [Trajectory(TRUTH[0], dom), Trajectory(TRUTH[1], dom), Trajectory("-5", dom)]
    x, v, u, z = mission(td)
    f = Function(["x1", "x2", "x3", "u1", "u2", "u3"], "(u1, u2, u3)")
    h = Function(["x1", "x2", "x3"], "(x1, x2)")
    dr = x.copy()
    CtcDeriv().contract(dr, u)  # dead reckoning alone, for the figures
    o = TemporalSlamOptions()
    o.eps = 0.01
    t0 = time.perf_counter()
    rows = sillage.temporal_slam(x, v, u, z, f, h, o)
    wall = time.perf_counter() - t0
    ok = not x.is_empty() and x.contains(truth) and bool(rows)
    print(f"Temporal SLAM on a figure eight, {td.nb_slices()} slices, eps = {o.eps}: {wall:.2f} s")
    print("  it  alg       detections  proofs  time (s)  cumul (s)  contraction p(tf)")
    for r in rows:
        print(f"  {r.iteration:2d}  {'fast' if r.fast else 'accurate':8s}  {r.nb_detections:10d}  {r.nb_proofs:6d}"
              f"  {r.seconds:8.3f}  {r.cumulated_seconds:9.3f}  {100 * r.contraction_tf:6.1f} %")
    print(f"  truth inside [x](.) at every gate and slice: {'yes' if ok else 'NO'}")

    # The map: dead reckoning (grey), SLAM (blue), truth; the boxes [p](t_f) before and after.
    n = td.nb_slices()
    grey = TubeStyle()
    grey.slices = Style("#e6e6e6", "#bdbdbd", 0.3, 1.0, "slice")
    fig = sillage.tube_vector_figure(dr, 0, 1, "Temporal SLAM: dead reckoning (grey), SLAM (blue), truth (red)",
                                     grey, truth[0], truth[1])
    if not x.is_empty():
        sillage.draw_tube_vector_2d(fig, x, 0, 1, TubeStyle())
        fig.draw_box(IntervalVector([dr.gate(n)[0], dr.gate(n)[1]]), Style("none", "#555555", 1.5, 1.0))
        fig.draw_box(IntervalVector([x.gate(n)[0], x.gate(n)[1]]), Style("none", "#d62728", 1.5, 1.0))
    fig.save(str(out / "temporal_slam_small_map.svg"))
    # x1(t): dead reckoning and SLAM.
    ft = sillage.tube_figure(dr[0], "x1(t): dead reckoning (grey) and temporal SLAM (blue)", grey, truth[0], 700, 300,
                             "x1")
    if not x.is_empty():
        sillage.draw_tube(ft, x[0], TubeStyle(), truth[0])
    ft.save(str(out / "temporal_slam_small_x1.svg"))
    last = rows[-1].contraction_tf if rows else 0.0
    print_result("temporal_slam_small", f"{len(rows)} iterations, p(tf) contracted by {100 * last:.0f} %", ok,
                 [("temporal_slam_small_map.svg", "Temporal SLAM: map (dead reckoning, SLAM, truth, [p](tf))"),
                  ("temporal_slam_small_x1.svg", "Temporal SLAM: x1(t) before and after")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
