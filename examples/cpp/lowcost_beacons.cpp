// Range-only localization with low-cost beacons (thesis 5.3.1): the robot
// (5.15) x1' = x4 cos x3, x2' = x4 sin x3, x3' = u1, x4' = u2, with
// u ∈ (-9/20 cos(t/5), 1/10 + sin(t/4)) ± 1e-3 (5.16), t ∈ [0, 64]; the initial
// position is unknown, x3(0) ∈ π/2 ± 0.01, x4(0) ∈ ±0.01 (5.17). Three beacons
// (Table 5.1) give 11 ranges [z_i] at uncertain times [t_i] (Table 5.2).
//
// The network is CN (5.18): v = f(x, u) pointwise, x' = v (CtcDeriv),
// y_k = g_k(x) and w_k = ġ_k(x, v) (5.19) pointwise, plus the reformulation
// (5.21) of w_k, which stays bounded while the position is unbounded and so
// starts the propagation; y_k' = w_k (CtcDeriv); z_i = y_k(t_i) (CtcEval).
// The wake ratio is 0: the propagation runs to the true fixed point.
//
// Truth: x(0) = (0, 0, π/2, 0) with the centre input, integrated by RK4 with a
// step of δ/10; it must stay inside the tubes at every gate and sample, and
// every time where it meets a range [z_i] must stay inside the contracted [t_i].
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "example_args.h"
#include "example_bound.h"
#include "dead_reckoning_ivp.h"
#include "example_check.h"
#include "lowcost_beacons_network.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"

using namespace sillage;
using namespace lowcost_beacons;

namespace {

// Records the thickness of [x1] x [x2] (thesis Fig. 3.12) each time the
// network wakes it, i.e. once per round in which the position shrank: the
// progress of the propagation, for Fig. 5.8. It contracts nothing.
class ThicknessRecorder : public NetworkCtc {
 public:
  std::string name() const override { return "ThicknessRecorder"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override {
    return std::make_shared<Node>(args, curves_);
  }
  const std::vector<std::vector<double>>& curves() const { return *curves_; }

 private:
  class Node : public CnNode {
   public:
    Node(const std::vector<BoundDomain>& args, std::shared_ptr<std::vector<std::vector<double>>> curves)
        : CnNode({args.at(0).range, args.at(1).range}),
          x1_(std::dynamic_pointer_cast<TubeDomain>(args[0].domain)),
          x2_(std::dynamic_pointer_cast<TubeDomain>(args[1].domain)),
          curves_(std::move(curves)) {}
    std::string name() const override { return "ThicknessRecorder"; }
    bool run(NodeRun&) const override {
      std::vector<double> d;
      for (std::size_t k = 0; k < x1_->tube().nb_slices(); ++k) {
        d.push_back(std::hypot(x1_->tube().slice(k).diam(), x2_->tube().slice(k).diam()));
      }
      curves_->push_back(std::move(d));
      return true;
    }

   private:
    std::shared_ptr<TubeDomain> x1_, x2_;
    std::shared_ptr<std::vector<std::vector<double>>> curves_;
  };
  std::shared_ptr<std::vector<std::vector<double>>> curves_ = std::make_shared<std::vector<std::vector<double>>>();
};


// The true robot: RK4 from (0, 0, π/2, 0) with the centre input, n steps of h.
using State = std::array<double, 4>;
std::vector<State> simulate(double h, std::size_t n) {
  const auto f = [](double t, const State& s) {
    return State{s[3] * std::cos(s[2]), s[3] * std::sin(s[2]), -9.0 / 20 * std::cos(t / 5), 0.1 + std::sin(t / 4)};
  };
  const auto add = [](const State& a, const State& b, double c) {
    return State{a[0] + c * b[0], a[1] + c * b[1], a[2] + c * b[2], a[3] + c * b[3]};
  };
  std::vector<State> path{{0, 0, std::acos(-1.0) / 2, 0}};
  for (std::size_t j = 0; j < n; ++j) {
    const double t = static_cast<double>(j) * h;
    const State& s = path.back();
    const State k1 = f(t, s), k2 = f(t + h / 2, add(s, k1, h / 2)), k3 = f(t + h / 2, add(s, k2, h / 2)),
                k4 = f(t + h, add(s, k3, h));
    State r = s;
    for (int i = 0; i < 4; ++i) r[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    path.push_back(r);
  }
  return path;
}

// Largest distance of the truth, sampled every h, outside the tubes: each
// sample against the slice(s) holding its time, each gate against the sample
// at its time (every gate is within an ulp of a sample time).
double excess(const TubeVector& x, const std::vector<State>& path, double h) {
  const TDomain& td = *x.tdomain();
  double worst = 0;
  const auto out = [](const Interval& a, double v) {
    return a.is_empty() ? INFINITY : std::max({0.0, a.lb() - v, v - a.ub()});
  };
  for (std::size_t j = 0; j < path.size(); ++j) {
    const double t = std::min(static_cast<double>(j) * h, td.tf());
    const std::size_t k = std::min(td.slice_index(t), td.nb_slices() - 1);
    for (std::size_t i = 0; i < 4; ++i) worst = std::max(worst, out(x[i].slice(k), path[j][i]));
  }
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) {
    const auto j = static_cast<std::size_t>(std::llround(td.t(k) / h));
    for (std::size_t i = 0; i < 4; ++i) worst = std::max(worst, out(x[i].gate(k), path[j][i]));
  }
  return worst;
}

// Mean of d(t) = |diam([x1](t)), diam([x2](t))| over time (slices weighted by their width).
double mean_thickness(const TDomain& td, const std::vector<double>& d) {
  double m = 0;
  for (std::size_t k = 0; k < d.size(); ++k) m += d[k] * (td.t(k + 1) - td.t(k)) / (td.tf() - td.t0());
  return m;
}

// Hull of the sampled times in [t] where the truth's range to beacon k is in [z].
Interval truth_times(const std::vector<State>& path, double h, const Measurement& m) {
  Interval r = Interval::empty();
  const Beacon& b = kBeacons[m.k];
  for (std::size_t j = 0; j < path.size(); ++j) {
    const double t = static_cast<double>(j) * h;
    if (m.t.contains(t) && m.z.contains(std::hypot(path[j][0] - b.b1, path[j][1] - b.b2))) r |= Interval(t);
  }
  return r;
}

// The map of Fig. 5.9 (view given), with beacons, range limits and [x]([t_i]).
Figure map_figure(const Problem& p, const IntervalVector& view, const std::string& title,
                  const std::vector<Vector>& truth) {
  Figure fig(view, 700);
  fig.set_title(title);
  fig.set_labels("x1", "x2");
  for (const Beacon& b : kBeacons) fig.draw_ring({b.b1, b.b2}, Interval(0, 20), {"#f7e4e4", "#c62828", 0.6, 0.35, ""});
  TubeStyle style;
  style.slices = {"#b8c4d6", "#5c6f8a", 0.3, 1.0, "slice"};
  style.initial = {"none", "#c62828", 1.5, 1.0, "initial"};  // outlines only: they are large boxes
  style.final = {"none", "#2e7d32", 1.5, 1.0, "final"};
  draw_tube_vector_2d(fig, *p.x, 0, 1, style);
  const TDomain& td = *p.x->tdomain();
  for (const auto& t : p.t) {  // the slices over [t_i], darker
    for (std::size_t k = 0; k < td.nb_slices(); ++k) {
      if (td.t(k + 1) > t->lb() && td.t(k) < t->ub()) {
        fig.draw_box(p.x->slice(k).subvector(0, 1), {"#3d3d3d", "none", 0, 0.45, ""});
      }
    }
  }
  fig.draw_polyline(truth, {"none", "#d62728", 1.5, 1, "truth"});
  for (const Beacon& b : kBeacons) {
    fig.draw_box(IntervalVector{{b.b1 - 1, b.b1 + 1}, {b.b2 - 1, b.b2 + 1}}, {"#d62728", "black", 1, 1, ""});
    fig.draw_text({b.b1 + 1.5, b.b2 + 1.5}, b.name, 12, "#a00000");
  }
  return fig;
}

// d(t) after the first recorded rounds and at the end, [t_i] in grey.
Figure thickness_plot(const TDomain& td, const std::vector<std::vector<double>>& curves,
                      const std::vector<std::shared_ptr<Interval>>& t) {
  double top = 0;  // the first round with a bounded position sets the scale
  for (const auto& c : curves) {
    for (const double d : c) top = std::isfinite(d) ? std::max(top, 1.1 * d) : top;
    if (top > 0) break;
  }
  Figure fig(IntervalVector{{td.t0(), td.tf()}, {0, top}}, 700, 280);
  fig.set_title("Thickness of [x1] x [x2] in the first rounds (light) and at the fixed point (Fig. 5.8)");
  fig.set_labels("t", "d(t)");
  for (const auto& ti : t) fig.draw_box(IntervalVector{*ti, {0, top}}, {"#cccccc", "none", 0, 0.5, ""});
  const std::size_t last = curves.size() - 1;
  for (std::size_t r = 1; r <= last; ++r) {
    if (r > 5 && r != last) continue;
    std::vector<Vector> pts;
    for (std::size_t k = 0; k < curves[r].size(); ++k) {
      const double d = std::min(curves[r][k], top);
      pts.push_back({td.t(k), d});
      pts.push_back({td.t(k + 1), d});
    }
    fig.draw_polyline(pts, r == last ? Style{"none", "#1f3f66", 2.0, 1, ""} : Style{"none", "#9ab8d8", 1.0, 1, ""});
  }
  return fig;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const double dt = example::option_number(argc, argv, "--dt", 0.05);
  const double ratio = example::option_number(argc, argv, "--ratio", 0.0);
  const auto td = make_tdomain(dt);
  const std::size_t N = td->nb_slices();

  const double c0 = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  Problem p = build(td, ratio);
  for (std::size_t i = 0; i < kMeasurements.size(); ++i) {  // tightened as in lowcost_beacons.py
    *p.t[i] = example::bound(*p.t[i]);
    *p.z[i] = example::bound(*p.z[i]);
  }
  const ContractStats s = p.cn->contract();
  const double cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - c0;

  std::printf("Range-only localization with low-cost beacons (thesis 5.3.1), t in [0, 64], dt = %g (%zu slices)\n", dt,
              N);
  std::printf("  network: %zu contractors, ratio %g%s\n", p.cn->nb_ctc(), ratio,
              ratio == 0 ? " (true fixed point)" : "");
  std::printf("  %zu iterations, %zu contractor calls, %.3f s wall, %.3f s CPU (build + contract), empty = %d\n",
              s.iterations, s.contractor_calls, s.time, cpu, s.empty);
  std::printf(
      "  thesis: fixed point after 52 iterations in 2 min; reference library: 4 iterations in 3.4 s, not "
      "at the fixed point\n");
  if (s.empty) return example::empty_exit("lowcost_beacons", s);

  // Fixed point: one more contract() runs every contractor once and must change nothing.
  const TubeVector x_fp = *p.x;
  const ContractStats again = p.cn->contract();
  const bool fixed = again.iterations == 1 && *p.x == x_fp;
  std::printf("  fixed point verified (a second contract() changes nothing): %s\n", fixed ? "yes" : "NO");

  const double h = dt / 10;  // RK4 step of the truth
  const auto path = simulate(h, static_cast<std::size_t>(std::llround(kTf / h)));
  const double e = excess(*p.x, path, h);
  bool ok = example::enclosure_ok(*p.x) && (fixed || ratio > 0) &&
            e <= 1e-7;  // a ratio > 0 stops before the fixed point

  std::printf("  measurements: [t_i] (Table 5.2) -> contracted [t_i] ; [z_i] -> contracted [z_i] ; truth times\n");
  for (std::size_t i = 0; i < kMeasurements.size(); ++i) {
    const Measurement& m = kMeasurements[i];
    const Interval tt = truth_times(path, h, m);
    const bool in = !tt.is_empty() && p.t[i]->contains(tt.lb()) && p.t[i]->contains(tt.ub());
    ok = ok && in;
    std::printf("  %2zu %-5s [%.2f, %.2f] -> [%.4f, %.4f] ; [%.2f, %.2f] -> [%.4f, %.4f] ; truth [%.3f, %.3f] %s\n",
                i + 1, kBeacons[m.k].name, m.t.lb(), m.t.ub(), p.t[i]->lb(), p.t[i]->ub(), m.z.lb(), m.z.ub(),
                p.z[i]->lb(), p.z[i]->ub(), tt.lb(), tt.ub(), in ? "inside" : "NOT INSIDE");
  }
  const IntervalVector x0 = p.x->gate(0), xf = p.x->gate(N);
  std::vector<double> d;
  for (std::size_t k = 0; k < N; ++k) d.push_back(std::hypot((*p.x)[0].slice(k).diam(), (*p.x)[1].slice(k).diam()));
  const double mean = mean_thickness(*td, d), worst = *std::max_element(d.begin(), d.end());
  std::printf("  x(0) in [%.3f, %.3f] x [%.3f, %.3f] (truth (0, 0)); x(64) in [%.3f, %.3f] x [%.3f, %.3f]\n",
              x0[0].lb(), x0[0].ub(), x0[1].lb(), x0[1].ub(), xf[0].lb(), xf[0].ub(), xf[1].lb(), xf[1].ub());
  std::printf("  position thickness d(t): mean %.3f, max %.3f\n", mean, worst);
  std::printf("  truth inside the tubes: %s (largest excess %.2g)\n", e <= 1e-7 ? "yes" : "NO", e);

  // CtcIvp after the network: the robot's f is known (that of dead reckoning,
  // dead_reckoning_ivp.h), but no gate is bounded before the network has
  // bounded the position; from the fixed point, every gate is. CtcIvp on
  // (x, τ) forward and backward from the gates, the noise of (3.16) as input.
  const double ci = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  TubeVector xi(td, 5);
  for (std::size_t i = 0; i < 4; ++i) xi[i] = (*p.x)[i];
  xi[4] = Tube(td, "t");
  const CtcIvp ivp(dead_reckoning::ivp_contractor().function(), 2, 10, TimePropag::FWD_BWD);
  const bool ivp_nonempty = ivp.contract(xi, TubeVector(td, 2, dead_reckoning::ivp_noise()));
  const double cpu_ivp = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - ci;
  const TubeVector xi4 = xi.subvector(0, 3);
  const double ei = excess(xi4, path, h);
  std::vector<double> di;
  for (std::size_t k = 0; k < N; ++k) di.push_back(std::hypot(xi4[0].slice(k).diam(), xi4[1].slice(k).diam()));
  const IntervalVector xi0 = xi4.gate(0), xif = xi4.gate(N);
  std::printf("  then CtcIvp (%.3f s CPU): x(0) in [%.3f, %.3f] x [%.3f, %.3f], x(64) in [%.3f, %.3f] x [%.3f, %.3f]; "
              "d(t) mean %.3f, max %.3f; truth inside: %s (largest excess %.2g)\n",
              cpu_ivp, xi0[0].lb(), xi0[0].ub(), xi0[1].lb(), xi0[1].ub(), xif[0].lb(), xif[0].ub(), xif[1].lb(),
              xif[1].ub(), mean_thickness(*td, di), *std::max_element(di.begin(), di.end()),
              ivp_nonempty && ei <= 1e-7 ? "yes" : "NO", ei);
  ok = ok && ivp_nonempty && example::enclosure_ok(xi4) && ei <= 1e-7;

  // Figures 5.8 and 5.9.
  std::vector<Vector> truth;
  for (std::size_t j = 0; j < path.size(); j += 10) truth.push_back({path[j][0], path[j][1]});
  const IntervalVector cod = p.x->codomain();
  const IntervalVector view{{std::max(cod[0].lb(), -40.0) - 5, std::min(cod[0].ub(), 160.0) + 5},
                            {std::max(cod[1].lb(), -60.0) - 5, std::min(cod[1].ub(), 90.0) + 5}};
  map_figure(p, view, "Low-cost beacons: [x1] x [x2] at the fixed point (Fig. 5.9a)", truth)
      .save((out / "lowcost_beacons_map.svg").string());
  map_figure(p, IntervalVector{{0, 60}, {-10, 50}}, "Zoom on beacon alpha (Fig. 5.9b)", truth)
      .save((out / "lowcost_beacons_alpha.svg").string());
  map_figure(p, IntervalVector{{50, 110}, {-35, 25}}, "Zoom on beacon beta (Fig. 5.9c)", truth)
      .save((out / "lowcost_beacons_beta.svg").string());
  {
    Figure cmp = tube_vector_figure(*p.x, 0, 1, "Low-cost beacons: CtcDeriv network (blue), then CtcIvp (orange)");
    TubeStyle orange;
    orange.slices = Style{"#f6c28b", "#c25e00", 0.4, 1.0, "slice"};
    draw_tube_vector_2d(cmp, xi4, 0, 1, orange);
    cmp.draw_polyline(truth, {"none", "#d62728", 1.5, 1, "truth"});
    cmp.save((out / "lowcost_beacons_deriv_vs_ivp.svg").string());
  }
  // Fig. 5.8: a second run, with the recorder, gives d(t) after each round.
  auto recorder = std::make_shared<ThicknessRecorder>();
  Problem q = build(td, ratio, recorder);
  q.cn->contract();
  thickness_plot(*td, recorder->curves(), p.t).save((out / "lowcost_beacons_thickness.svg").string());
  const auto& curves = recorder->curves();
  std::printf("  mean d(t) after each of the %zu rounds that shrank the position:", curves.size());
  for (std::size_t r = 0; r < curves.size(); ++r) {
    if (r >= 10 && r + 1 < curves.size()) continue;
    std::printf("%s %.3f", r + 1 == curves.size() && r >= 10 ? " ... (last)" : "", mean_thickness(*td, curves[r]));
  }
  std::printf("\n");

  char summary[200];
  std::snprintf(summary, sizeof summary, "%zu iterations, %.3f s; x(0) in [%.2f, %.2f] x [%.2f, %.2f]", s.iterations,
                s.time, x0[0].lb(), x0[0].ub(), x0[1].lb(), x0[1].ub());
  example::print_result(
      "lowcost_beacons", summary, ok,
      {{"lowcost_beacons_map.svg", "Low-cost beacons (5.3.1): position tube, truth, [t_i] (Fig. 5.9a)"},
       {"lowcost_beacons_alpha.svg", "Zoom on beacon alpha (Fig. 5.9b)"},
       {"lowcost_beacons_beta.svg", "Zoom on beacon beta (Fig. 5.9c)"},
       {"lowcost_beacons_thickness.svg", "Thickness of the position tube (Fig. 5.8)"},
       {"lowcost_beacons_deriv_vs_ivp.svg", "The network's position tube (blue), then contracted by CtcIvp (orange)"}});
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
