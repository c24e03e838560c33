"""The unfavourable IVP of thesis 4.3.3: x' = -sin(x), x(0) = 1, t in [0, 10].
Decomposition (4.23), every tube starting at [-oo, oo]: a = sin(x) (pointwise),
b' = a with b(0) = 0 (CtcDeriv), x = 1 - b (pointwise), in a ContractorNetwork
run to its exact fixed point (ratio 0); the equivalent network x' = v,
v = -sin(x), x(0) = 1 too. x(10) is printed beside the validated-integration
enclosure (4.24) for several delta: the approach is very pessimistic here (the
slice-wise wrapping grows like delta * e^t). The closed-form truth
x(t) = 2 atan(tan(1/2) e^-t) is checked inside on every slice and gate (its
interval enclosure may stick out by 1e-9 at most). Fig. 4.7: sweeps 1-5 and the
fixed point. Then CtcIvp (validated integration, docs/ivp.md) on the same
slices, drawn beside the CtcDeriv fixed point. Same computations and printed figures as examples/cpp/sin_ivp.cpp."""
import time

import sillage
from example_args import bound, empty_exit, enclosure_ok, out_dir, print_result, run
from sillage import CtcFunction, Function, Interval, IntervalVector, TDomain, Trajectory, Tube

TF = 10.0
REFERENCE = Interval(4.96041893247e-5, 4.96041893264e-5)  # (4.24)
TRUTH = "2*atan(tan(1/2)*exp(-t))"


def solve_decomposition(td):
    """CN of (4.23): a = sin(x), b' = a with b(0) = 0, x = 1 - b."""
    x, a, b = Tube(td), Tube(td), Tube(td)
    b.set_gate(0, bound(Interval(0)))
    cn = sillage.ContractorNetwork()
    cn.set_ratio(0)  # the exact fixed point
    cn.add(CtcFunction(Function(["a", "x"], "a - sin(x)")), [a, x])
    cn.add(sillage.CtcDeriv(), [b, a])
    cn.add(CtcFunction(Function(["x", "b"], "x - 1 + b")), [x, b])
    for tube, name in ((x, "x"), (a, "a"), (b, "b")):  # named: an empty network says which tube emptied
        cn.set_name(tube, name)
    return x, cn.contract()


def solve_direct(td):
    """The equivalent CN: x' = v, v = -sin(x), x(0) = 1."""
    x, v = Tube(td), Tube(td)
    x.set_gate(0, bound(Interval(1)))
    cn = sillage.ContractorNetwork()
    cn.set_ratio(0)
    cn.add(CtcFunction(Function(["v", "x"], "v + sin(x)")), [v, x])
    cn.add(sillage.CtcDeriv(), [x, v])
    cn.set_name(x, "x")
    cn.set_name(v, "v")
    return x, cn.contract()


def sweeps(td, max_sweeps=100000):
    """The three contractors of (4.23) applied by hand, sweep after sweep (Fig. 4.7):
    the tube x after each sweep that changed it, up to the exact fixed point."""
    x, a, b = Tube(td), Tube(td), Tube(td)
    b.set_gate(0, Interval(0))
    sin_ctc, sub_ctc = CtcFunction(Function(["a", "x"], "a - sin(x)")), CtcFunction(Function(["x", "b"], "x - 1 + b"))
    deriv = sillage.CtcDeriv()
    snaps = []
    for _ in range(max_sweeps):
        before = x.copy()
        sin_ctc.contract(a, x)
        deriv.contract(b, a)
        sub_ctc.contract(x, b)
        if x == before:
            break
        snaps.append(x.copy())
    return snaps


def truth_excess(x, truth):
    """Largest distance by which the truth's enclosure sticks out of the tube (slices and gates)."""
    td = x.tdomain()
    worst = 0.0

    def out(tube, e):
        return float("inf") if tube.is_empty() else max(0.0, tube.lb() - e.lb(), e.ub() - tube.ub())

    for k in range(td.nb_slices()):
        worst = max(worst, out(x.slice(k), truth(td.slice_domain(k))))
    for k in range(td.nb_slices() + 1):
        worst = max(worst, out(x.gate(k), truth(td.t(k))))
    return worst


def onset(x, w):
    """First time from which a slice is thicker than w (t_N if none)."""
    td = x.tdomain()
    for k in range(td.nb_slices()):
        if x.thickness(k) > w:
            return td.t(k)
    return td.t(td.nb_slices())


def fmt(x):
    return f"[{x.lb():.6g}, {x.ub():.6g}]"


def main(deltas=(0.1, 0.01, 0.001, 0.0001), out=None):
    out = out or out_dir(__doc__)
    truth = Trajectory(TRUTH, Interval(0, TF))
    print(f"x' = -sin(x), x(0) = 1 on [0, 10]; true x(10) = {truth(TF).mid():.12g}; validated-integration x(10) in "
          f"[{REFERENCE.lb():.11e}, {REFERENCE.ub():.11e}] (width {REFERENCE.diam():.2g})")
    ok, summary, results = True, "", {}
    for dt in deltas:
        td = TDomain(0.0, TF, dt)
        n = td.nb_slices()
        for label, solve in (("(4.23):", solve_decomposition), ("x'=v, v=-sin x:", solve_direct)):
            t0 = time.process_time()
            x, stats = solve(td)
            cpu = time.process_time() - t0
            if stats.empty:
                return empty_exit("sin_ivp", stats, f"delta = {dt:g} {label[:-1]}")
            xf = x.gate(n)
            excess = truth_excess(x, truth)
            inside = enclosure_ok(x) and excess <= 1e-9
            ok = ok and inside
            results[(dt, label)] = xf
            print(f"delta = {dt:<6g} {label:<15s} x(10) in {fmt(xf):<26s} width {xf.diam():.3g} "
                  f"({xf.diam() / REFERENCE.diam():.2g} x the reference width), contains it: "
                  f"{'yes' if xf.is_superset(REFERENCE) else 'NO'}; thicker than 0.1 from t = {onset(x, 0.1):.2f}; "
                  f"{stats.iterations} iterations, {stats.contractor_calls} calls, {cpu:.3f} s CPU; truth inside: "
                  f"{'yes' if inside else 'NO'} (max excess {excess:.1e})")
            if dt == 0.001 and label == "(4.23):":
                summary = f"delta=0.001: x(10) in {fmt(xf)} (reference width 1.7e-15)"

    # Fig. 4.7 on delta = 0.01: sweeps 1-5 in grey, the fixed point in blue.
    td = TDomain(0.0, TF, 0.01)
    n = td.nb_slices()
    snaps = sweeps(td)
    fixed, _ = solve_decomposition(td)
    same = bool(snaps) and snaps[-1] == fixed
    print(f"Fig. 4.7 (delta = 0.01): exact fixed point after {len(snaps) + 1} sweeps of the three contractors, "
          f"x(10) in {fmt(snaps[-1].gate(n))}; the network: {'the same tube' if same else 'NOT the same tube'}, "
          f"x(10) in {fmt(fixed.gate(n))}")
    first = snaps[0].codomain()
    margin = 0.05 * first.diam()
    fig = sillage.Figure(IntervalVector([Interval(0, TF), Interval(first.lb() - margin, first.ub() + margin)]),
                         600, 300)
    fig.set_title("x' = -sin(x), x(0) = 1: sweeps 1-5 (grey) and fixed point (blue), delta = 0.01 (Python)")
    fig.set_labels("t", "x")
    for s, grey in zip(snaps[:5], ("#eeeeee", "#dddddd", "#cccccc", "#bbbbbb", "#aaaaaa")):
        st = sillage.TubeStyle()
        st.slices = sillage.Style(grey, "none", 0, 1, "sweep")
        sillage.draw_tube(fig, s, st)
    sillage.draw_tube(fig, fixed, sillage.TubeStyle(), truth)
    fig.save(str(out / "sin_ivp_py.svg"))
    ok = ok and truth_excess(fixed, truth) <= 1e-9 and all(truth_excess(s, truth) <= 1e-9 for s in snaps)
    # Beside CtcDeriv: validated integration (CtcIvp, docs/ivp.md) on the same slices.
    start = time.process_time()
    xi = Tube(td)
    xi.set_gate(0, Interval(1))
    consistent = sillage.CtcIvp(Function(["x"], "-sin(x)")).contract(xi)
    cpu = time.process_time() - start
    ivp_ok = consistent and enclosure_ok(xi) and truth_excess(xi, truth) <= 1e-9
    ok = ok and ivp_ok
    print(f"CtcIvp (delta = 0.01, order 20): x(10) in [{xi.gate(n).lb():.14e}, {xi.gate(n).ub():.14e}], "
          f"width {xi.gate(n).diam():.3g}, {cpu:.3f} s CPU; truth inside: {'yes' if ivp_ok else 'NO'}; "
          f"CtcDeriv's fixed point: width {fixed.gate(n).diam():.3g}")
    cmp = sillage.Figure(IntervalVector([Interval(0, TF), Interval(first.lb() - margin, first.ub() + margin)]),
                         600, 300)
    cmp.set_title("x' = -sin(x), x(0) = 1, delta = 0.01: CtcDeriv (grey) and CtcIvp (blue) (Python)")
    cmp.set_labels("t (s)", "x")
    # The thin CtcIvp tube over the wide CtcDeriv one, the truth thinner on top (legend below the plot).
    st, blue = sillage.TubeStyle(), sillage.TubeStyle()
    st.slices = sillage.Style("#bbbbbb", "none", 0, 1, "CtcDeriv", "CtcDeriv fixed point")
    slices = blue.slices
    slices.label = "CtcIvp"
    blue.slices = slices
    sillage.draw_tube(cmp, fixed, st)
    sillage.draw_tube(cmp, xi, blue, truth)
    cmp.save(str(out / "sin_ivp_ctc_ivp_py.svg"))
    print_result("sin_ivp", summary, ok,
                 [("sin_ivp_py.svg", "x' = -sin(x), x(0) = 1 (4.22): successive contractions and fixed point, "
                                     "Fig. 4.7, Python; true solution in red"),
                  ("sin_ivp_ctc_ivp_py.svg", "the same with validated integration (CtcIvp, blue) beside the "
                                             "CtcDeriv fixed point (grey), Python")])
    return ok, results


if __name__ == "__main__":
    run(lambda: 0 if main()[0] else 1)
