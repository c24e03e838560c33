// The unfavourable IVP of thesis 4.3.3: x' = -sin(x), x(0) = 1, t ∈ [0, 10].
//
// Decomposition (4.23), every tube starting at [-∞, ∞]:
//   a(·) = sin(x(·))        pointwise (CtcFunction on every slice and gate),
//   b'(·) = a(·), b(0) = 0  CtcDeriv,
//   x(·) = 1 - b(·)         pointwise,
// propagated by a ContractorNetwork to the exact fixed point (ratio 0: a
// contractor is woken by any contraction, not only by 1 % ones; the default
// ratio stops about 1 % wider at δ = 0.01, 2-4 % at smaller δ). The equivalent
// network x' = v, v = -sin(x), x(0) = 1 is run too (same wrapping, so about
// the same tube). The thesis shows that this approach is pessimistic here:
// the IVP is stable (the true solutions converge) but the slice-wise
// enclosure forgets the correlation between x and sin(x), so each slice adds
// O(δ) of width, amplified by |cos x| <= 1 over the next slices. We print
// x(10) beside the validated-integration enclosure (4.24) and say by how
// much we are wider, for several δ. The true solution (closed form
// x(t) = 2 atan(tan(1/2) e^{-t})) is checked inside on every slice and gate
// through its interval enclosure (analytic Trajectory): the check fails if
// that enclosure sticks out by more than 1e-9 (it is ~1e-15 wide, so a
// strict inclusion would fail at x(0) = 1 where the tube is exactly {1}).
//
// Figure (Fig. 4.7): the first five sweeps of the three contractors, then
// the fixed point, drawn over each other (earlier sweeps in grey). Then CtcIvp
// (validated integration, docs/ivp.md) on the same slices, drawn beside the
// CtcDeriv fixed point (sin_ivp_ctc_ivp.svg).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "example_args.h"
#include "example_bound.h"
#include "example_check.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube_ctc.h"

using namespace sillage;

namespace {

constexpr double kTf = 10.0;
const Interval kReference(4.96041893247e-5, 4.96041893264e-5);  // (4.24)
const char* kTruth = "2*atan(tan(1/2)*exp(-t))";

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Run {
  std::shared_ptr<Tube> x;
  ContractStats stats;
  double cpu = 0;
};

// CN of (4.23): a = sin(x), b' = a with b(0) = 0, x = 1 - b.
Run solve_decomposition(const std::shared_ptr<TDomain>& td) {
  const double start = cpu_seconds();
  Run r;
  r.x = std::make_shared<Tube>(td);
  auto a = std::make_shared<Tube>(td), b = std::make_shared<Tube>(td);
  b->set_gate(0, example::bound(Interval(0)));  // b(0) = ∫_0^0 a = 0
  ContractorNetwork cn;
  cn.set_ratio(0);
  // Named, so that an empty network says which tube emptied.
  cn.set_name(r.x, "x");
  cn.set_name(a, "a");
  cn.set_name(b, "b");
  cn.add(std::make_shared<CtcFunction>(Function({"a", "x"}, "a - sin(x)")), {a, r.x});
  cn.add(std::make_shared<CtcDeriv>(), {b, a});
  cn.add(std::make_shared<CtcFunction>(Function({"x", "b"}, "x - 1 + b")), {r.x, b});
  r.stats = cn.contract();
  r.cpu = cpu_seconds() - start;
  return r;
}

// The equivalent CN: x' = v, v = -sin(x), x(0) = 1.
Run solve_direct(const std::shared_ptr<TDomain>& td) {
  const double start = cpu_seconds();
  Run r;
  r.x = std::make_shared<Tube>(td);
  auto v = std::make_shared<Tube>(td);
  r.x->set_gate(0, example::bound(Interval(1)));
  ContractorNetwork cn;
  cn.set_ratio(0);
  cn.set_name(r.x, "x");
  cn.set_name(v, "v");
  cn.add(std::make_shared<CtcFunction>(Function({"v", "x"}, "v + sin(x)")), {v, r.x});
  cn.add(std::make_shared<CtcDeriv>(), {r.x, v});
  r.stats = cn.contract();
  r.cpu = cpu_seconds() - start;
  return r;
}

// The same three contractors of (4.23) applied by hand, sweep after sweep,
// to keep the intermediate tubes of Fig. 4.7. Stops at the exact fixed
// point (a sweep that changes nothing) or after max_sweeps.
std::vector<Tube> sweeps(const std::shared_ptr<TDomain>& td, std::size_t max_sweeps) {
  Tube x(td), a(td), b(td);
  b.set_gate(0, Interval(0));
  const CtcFunction sin_ctc(Function({"a", "x"}, "a - sin(x)")), sub_ctc(Function({"x", "b"}, "x - 1 + b"));
  const CtcDeriv deriv;
  std::vector<Tube> snapshots;
  for (std::size_t s = 0; s < max_sweeps; ++s) {
    const Tube before = x;
    contract(sin_ctc, {&a, &x});
    deriv.contract(b, a);
    contract(sub_ctc, {&x, &b});
    if (x == before) break;
    snapshots.push_back(x);
  }
  return snapshots;
}

// Largest distance by which the enclosure of the truth sticks out of the
// tube, over the slices and gates (+inf if the tube is empty).
double truth_excess(const Tube& x, const Trajectory& truth) {
  const TDomain& td = *x.tdomain();
  const auto out = [](const Interval& tube, const Interval& e) {
    return tube.is_empty() ? INFINITY : std::max({0.0, tube.lb() - e.lb(), e.ub() - tube.ub()});
  };
  double worst = 0;
  for (std::size_t k = 0; k < td.nb_slices(); ++k) worst = std::max(worst, out(x.slice(k), truth(td.slice_domain(k))));
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) worst = std::max(worst, out(x.gate(k), truth(td.t(k))));
  return worst;
}

// First time from which a slice is thicker than w (t_N if none).
double onset(const Tube& x, double w) {
  const TDomain& td = *x.tdomain();
  for (std::size_t k = 0; k < td.nb_slices(); ++k) {
    if (x.thickness(k) > w) return td.t(k);
  }
  return td.tf();
}

std::string interval_str(const Interval& x) {
  char buf[120];
  std::snprintf(buf, sizeof buf, "[%.6g, %.6g]", x.lb(), x.ub());
  return buf;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const Trajectory truth(kTruth, Interval(0, kTf));
  std::printf("x' = -sin(x), x(0) = 1 on [0, 10]; true x(10) = %.12g; validated-integration x(10) in [%.11e, %.11e] "
              "(width %.2g)\n",
              truth(kTf).mid(), kReference.lb(), kReference.ub(), kReference.diam());

  bool ok = true;
  std::string summary;
  for (const double dt : {0.1, 0.01, 0.001, 0.0001}) {
    const auto td = TDomain::create(0.0, kTf, dt);
    const std::size_t N = td->nb_slices();
    const Run dec = solve_decomposition(td), dir = solve_direct(td);
    for (const Run* r : {&dec, &dir}) {
      const char* model = r == &dec ? "(4.23)" : "x'=v, v=-sin x";
      if (r->stats.empty) {
        char label[64];
        std::snprintf(label, sizeof label, "delta = %g %s", dt, model);
        return example::empty_exit("sin_ivp", r->stats, label);
      }
      const Interval xf = r->x->gate(N);
      const double excess = truth_excess(*r->x, truth);
      const bool inside = example::enclosure_ok(*r->x) && excess <= 1e-9;
      ok = ok && inside;
      std::printf("delta = %-6g %-15s x(10) in %-26s width %.3g (%.2g x the reference width), contains it: %s; "
                  "thicker than 0.1 from t = %.2f; %zu iterations, %zu calls, %.3f s CPU; "
                  "truth inside: %s (max excess %.1e)\n",
                  dt, (std::string(model) + ":").c_str(), interval_str(xf).c_str(), xf.diam(),
                  xf.diam() / kReference.diam(), xf.is_superset(kReference) ? "yes" : "NO",
                  onset(*r->x, 0.1), r->stats.iterations, r->stats.contractor_calls, r->cpu,
                  inside ? "yes" : "NO", excess);
    }
    if (dt == 0.001) summary = "delta=0.001: x(10) in " + interval_str(dec.x->gate(N)) + " (reference width 1.7e-15)";
  }

  // Fig. 4.7 on δ = 0.01: sweeps 1-5 in grey, the fixed point in blue.
  const auto td = TDomain::create(0.0, kTf, 0.01);
  const std::vector<Tube> snaps = sweeps(td, 100000);
  const Run fixed = solve_decomposition(td);
  const bool same = !snaps.empty() && snaps.back() == *fixed.x;
  const std::size_t N = td->nb_slices();
  std::printf("Fig. 4.7 (delta = 0.01): exact fixed point after %zu sweeps of the three contractors, x(10) in %s; "
              "the network: %s, x(10) in %s\n",
              snaps.size() + 1, interval_str(snaps.back().gate(N)).c_str(),
              same ? "the same tube" : "NOT the same tube", interval_str(fixed.x->gate(N)).c_str());
  bool clipped = false;
  std::vector<Interval> all(snaps.front().slices().begin(), snaps.front().slices().end());
  Figure fig(IntervalVector{td->t0_tf(), finite_window(all, clipped)}, 600, 300);
  fig.set_title("x' = -sin(x), x(0) = 1: sweeps 1-5 (grey) and fixed point (blue), delta = 0.01");
  fig.set_labels("t", "x");
  const char* greys[] = {"#eeeeee", "#dddddd", "#cccccc", "#bbbbbb", "#aaaaaa"};
  for (std::size_t s = 0; s < 5 && s < snaps.size(); ++s) {
    TubeStyle st;
    st.slices = Style{greys[s], "none", 0, 1, "sweep"};
    draw_tube(fig, snaps[s], st);
  }
  draw_tube(fig, *fixed.x, {}, &truth);
  fig.save((out / "sin_ivp.svg").string());
  ok = ok && truth_excess(*fixed.x, truth) <= 1e-9;
  for (const Tube& s : snaps) ok = ok && truth_excess(s, truth) <= 1e-9;

  // Beside CtcDeriv: validated integration, CtcIvp (docs/ivp.md), on the
  // same slices; it keeps the correlation between x and sin(x) along time.
  const double ivp_start = cpu_seconds();
  Tube xi(td);
  xi.set_gate(0, Interval(1));
  const bool ivp_consistent = CtcIvp(Function({"x"}, "-sin(x)")).contract(xi);
  const double ivp_cpu = cpu_seconds() - ivp_start;
  const double ivp_excess = truth_excess(xi, truth);
  const bool ivp_ok = ivp_consistent && example::enclosure_ok(xi) && ivp_excess <= 1e-9 && xi.is_subset(Tube(td));
  ok = ok && ivp_ok;
  std::printf("CtcIvp (delta = 0.01, order 20): x(10) in [%.14e, %.14e], width %.3g (%.2g x the reference width), "
              "%.3f s CPU; truth inside: %s; CtcDeriv's fixed point: width %.3g\n",
              xi.gate(N).lb(), xi.gate(N).ub(), xi.gate(N).diam(), xi.gate(N).diam() / kReference.diam(), ivp_cpu,
              ivp_ok ? "yes" : "NO", fixed.x->gate(N).diam());
  Figure cmp(IntervalVector{td->t0_tf(), finite_window(all, clipped)}, 600, 300);
  cmp.set_title("x' = -sin(x), x(0) = 1, delta = 0.01: CtcDeriv fixed point (grey) and CtcIvp (blue)");
  cmp.set_labels("t (s)", "x");
  // The thin CtcIvp tube over the wide CtcDeriv one, the truth thinner on top (legend below the plot).
  TubeStyle grey, blue;
  grey.slices = Style{"#bbbbbb", "none", 0, 1, "CtcDeriv", "CtcDeriv fixed point"};
  blue.slices.label = "CtcIvp";
  draw_tube(cmp, *fixed.x, grey);
  draw_tube(cmp, xi, blue, &truth);
  cmp.save((out / "sin_ivp_ctc_ivp.svg").string());

  example::print_result("sin_ivp", summary, ok,
                        {{"sin_ivp.svg", "x' = -sin(x), x(0) = 1 (4.22): successive contractions and fixed point, "
                                         "Fig. 4.7; true solution in red"},
                         {"sin_ivp_ctc_ivp.svg", "the same with validated integration (CtcIvp, blue) beside the "
                                                 "CtcDeriv fixed point (grey)"}});
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
