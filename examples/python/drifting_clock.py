"""Reliable correction of a drifting clock (thesis 5.3.2), the network of
examples/cpp/drifting_clock.cpp: an underwater beacon at (0, 0, -10) reads
tau = h(t) (truth 0.045 t^2 + 0.98 t, unknown to the solver), h(0) = 0,
h' in [0.08, 0.12] t + [0.97, 1.08] (5.24); a boat on the ephemeris (5.25)-(5.26)
gives 8 ranges stamped with the beacon's clock (Table 5.3). CN (5.27): x' = v,
y = sqrt(x1^2 + x2^2 + 10^2), w = (x1 v1 + x2 v2) / y, y' = w, h' = phi, and per
measurement tau_i = h(t_i) and z_i = y(t_i) (CtcEval) sharing t_i, unknown in
[0, 13]. The truth h(t), the true boat (90, 20) + 100 (cos t, sin t) and the
true t_i = h^-1(tau_i) must stay inside."""
import math
import time

import sillage
from example_args import bound, empty_exit, enclosure_ok, out_dir_and_step, print_result, run
from sillage import (ContractorNetwork, CtcDeriv, CtcEval, CtcFunction, DomainRef, Function, Interval,
                     IntervalVector, Style, TDomain, Trajectory, Tube, TubeStyle, TubeVector)

TF = 13.0  # holds every t_i: at t = 13 the lowest admissible clock exceeds 18.24
TAU = [1.57, 3.34, 5.32, 7.50, 9.88, 12.46, 15.25, 18.24]  # Table 5.3
Z = [(152.47, 156.47), (34.67, 38.67), (102.38, 106.38), (184.45, 188.45),
     (167.09, 171.09), (60.03, 64.03), (78.76, 82.76), (175.88, 179.88)]
H_TRUE = "0.045*t^2 + 0.98*t"  # (5.23)
PHI = "[0.08, 0.12]*t + [0.97, 1.08]"  # (5.24)
X = "([70, 90] + 100*cos(t), [10, 30] + 100*sin(t))"  # (5.25)
V = "([-0.1, 0.1] - 100*sin(t), [-0.1, 0.1] + 100*cos(t))"  # (5.26)


def cents(a, b):
    """The enclosure of a table entry written with two decimals (the double 15.55 is
    not the real 15.55): hundredths divided by 100, rounded outward."""
    return Interval(round(a * 100), round(b * 100)) / Interval(100)


def build(td, ratio=0.0):
    """CN (5.27); returns the network and its domains (contracted in place)."""
    x, v = TubeVector(td, X), TubeVector(td, V)
    y, w, h, phi = Tube(td), Tube(td), Tube(td), Tube(td, PHI)
    h.set_gate(0, bound(Interval(0.0)))  # h(0) = 0
    cn = ContractorNetwork()
    cn.set_ratio(ratio)
    x1, x2 = DomainRef.component(x, 0), DomainRef.component(x, 1)
    v1, v2 = DomainRef.component(v, 0), DomainRef.component(v, 1)
    cn.add(CtcDeriv(), [x, v])
    cn.add(CtcFunction(Function(["y", "x1", "x2"], "y - sqrt(x1^2 + x2^2 + 100)")), [y, x1, x2])
    cn.add(CtcFunction(Function(["w", "y", "x1", "x2", "v1", "v2"], "w - (x1*v1 + x2*v2)/y")),
           [w, y, x1, x2, v1, v2])
    cn.add(CtcDeriv(), [y, w])
    cn.add(CtcDeriv(), [h, phi])
    t, z, tau = [], [], []
    for i in range(len(TAU)):
        t.append(td.t0_tf())  # unknown reference time
        z.append(bound(cents(*Z[i])))
        tau.append(cents(TAU[i], TAU[i]))
        cn.add(CtcEval(), [t[i], tau[i], h, phi])  # tau_i = h(t_i)
        cn.add(CtcEval(), [t[i], z[i], y, w])  # z_i = y(t_i)
        for d, name in ((t[i], "t"), (z[i], "z"), (tau[i], "tau")):
            cn.set_name(d, f"{name}{i + 1}")
    for d, name in ((x, "x"), (v, "v"), (y, "y"), (w, "w"), (h, "h"), (phi, "phi")):
        cn.set_name(d, name)  # named, so that an empty network says which domain emptied
    return dict(cn=cn, x=x, v=v, y=y, w=w, h=h, phi=phi, t=t, z=z)


def true_time(tau):
    return (-0.98 + math.sqrt(0.98 ** 2 + 4 * 0.045 * tau)) / (2 * 0.045)


def a_priori(td):
    """[h] from h(0) = 0 and h' in [phi] only, for comparison."""
    h0, phi0 = Tube(td), Tube(td, PHI)
    h0.set_gate(0, Interval(0.0))
    CtcDeriv().contract(h0, phi0)
    return h0, phi0


def iv(a, d=4):
    return f"[{a.lb():.{d}f}, {a.ub():.{d}f}]"


def main():
    out, args = out_dir_and_step(__doc__, 0.01)

    td = TDomain(0.0, TF, args.dt)
    h0, phi0 = a_priori(td)
    c0 = time.process_time()
    p = build(td, args.ratio)
    s = p["cn"].contract()
    cpu = time.process_time() - c0
    print(f"Drifting clock (thesis 5.3.2), t in [0, {TF:g}], dt = {args.dt:g} ({td.nb_slices()} slices)")
    print(f"  {s.iterations} iterations, {s.contractor_calls} contractor calls, {s.time:.4f} s wall, "
          f"{cpu:.4f} s CPU (build + contract), empty = {s.empty}")
    print("  thesis: 5 steps in less than 2 s; reference library: 0.8 s")
    if s.empty:
        return empty_exit("drifting_clock", s)

    # Fixed point: one more contract() runs every contractor once and must change nothing.
    h_fp = p["h"].copy()
    again = p["cn"].contract()
    fixed = again.iterations == 1 and p["h"] == h_fp
    print(f"  fixed point verified (a second contract() changes nothing): {'yes' if fixed else 'NO'}")

    dom = td.t0_tf()
    h_true = Trajectory(H_TRUE, dom)
    b1, b2 = Trajectory("90 + 100*cos(t)", dom), Trajectory("20 + 100*sin(t)", dom)
    y_true = Trajectory("sqrt((90 + 100*cos(t))^2 + (20 + 100*sin(t))^2 + 100)", dom)
    h_in = p["h"].contains(h_true)
    boat_in = p["x"].contains([b1, b2]) and p["y"].contains(y_true)
    ok = enclosure_ok(p["h"]) and (fixed or args.ratio > 0) and h_in and boat_in  # a ratio > 0 stops earlier
    print("  i  tau_i  a priori [h]^-1(tau_i)  contracted [t_i]       true t_i  contracted [z_i]")
    w0 = w1 = 0.0
    for i, tau in enumerate(TAU):
        a = h0.inverse(cents(tau, tau), phi0)
        tt = true_time(tau)
        inside = p["t"][i].contains(tt)
        ok = ok and inside
        w0 += a.diam() / len(TAU)
        w1 += p["t"][i].diam() / len(TAU)
        print(f"  {i + 1}  {tau:5.2f}  {iv(a)}      {iv(p['t'][i])}  {tt:.4f} {'in ' if inside else 'OUT'}  "
              f"{iv(p['z'][i], 2)}")
    n = td.nb_slices()
    print(f"  mean width of [t_i]: {w0:.4f} a priori -> {w1:.4f} contracted")
    print(f"  [h](13): a priori {iv(h0.gate(n))} -> {iv(p['h'].gate(n))}; "
          f"max thickness of [h]: {h0.max_thickness():.4f} -> {p['h'].max_thickness():.4f}")
    print(f"  truth h(t) inside [h]: {'yes' if h_in else 'NO'}; "
          f"true boat inside [x] and [y]: {'yes' if boat_in else 'NO'}")

    # Fig. 5.13: [h] over the a priori tube, the truth, the (tau_i, [t_i]) boxes.
    grey = TubeStyle()
    grey.slices = Style("#e6e6e6", "#bdbdbd", 0.3, 1.0, "slice")
    fh = sillage.tube_figure(h0, "Clock drift [h](t), truth in red (Fig. 5.13, Python)", grey, None, 700, 350)
    fh.set_labels("t", "tau = h(t)")
    sillage.draw_tube(fh, p["h"], TubeStyle(), h_true)
    for i, tau in enumerate(TAU):
        band = Interval(tau - 0.15, tau + 0.15)
        fh.draw_box(IntervalVector([h0.inverse(cents(tau, tau), phi0), band]), Style("#4a90d9", "#2a5f9e", 0.6, 0.5))
        fh.draw_box(IntervalVector([p["t"][i], band]), Style("#d62728", "#8b0000", 0.6, 0.9))
    fh.save(str(out / "drifting_clock_h_py.svg"))
    # Fig. 5.12: [y] with the measurement boxes, a priori (blue) and contracted (red).
    fy = sillage.tube_figure(p["y"], "Distances [y](t) and the measurements (Fig. 5.12, Python)", TubeStyle(),
                             y_true, 700, 350)
    fy.set_labels("t", "y(t)")
    for i, tau in enumerate(TAU):
        fy.draw_box(IntervalVector([h0.inverse(cents(tau, tau), phi0), cents(*Z[i])]),
                    Style("#4a90d9", "#2a5f9e", 0.6, 0.35))
        fy.draw_box(IntervalVector([p["t"][i], p["z"][i]]), Style("#d62728", "#8b0000", 0.6, 0.9))
    fy.save(str(out / "drifting_clock_y_py.svg"))

    summary = f"{s.iterations} iterations; [t_i] = " + " ".join(iv(t, 3) for t in p["t"])
    print_result("drifting_clock", summary, ok,
                 [("drifting_clock_h_py.svg", "Drifting clock (5.3.2): [h] with the truth (Fig. 5.13), Python"),
                  ("drifting_clock_y_py.svg", "Distances [y] and measurements (Fig. 5.12), Python")])
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
