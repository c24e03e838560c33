// Causal kinematic chain (thesis 4.4.1, (4.25)-(4.27)): a Dubins car,
// x1' = 10 cos x3, x2' = 10 sin x3, x3' = u, u ∈ -cos((t+33)/5) + [-0.02, 0.02],
// x(0) ∈ [-1, 1] × [-1, 1] × (-6π/5 + [-0.02, 0.02]), t ∈ [0, 14].
//
// The constraint network: x' = v (CtcDeriv, forward-backward on each
// component), v1 = 10 cos x3, v2 = 10 sin x3 (pointwise, on every slice and
// gate), v3 = u. Run twice: from x0 only (Fig. 4.8), then with the final box
// x(14) ∈ [53.9, 55.9] × [6.9, 8.9] × [-2.36, -2.32] (Fig. 4.9). The final box
// is compared with a validated-integration box of the same problem; the true
// path (u*, centre of x0) and extreme paths (corners of x0 and of the input
// error, when they reach the final box) are checked inside the tubes.
// Each run is done twice: by the CtcDeriv network, and by CtcIvp (validated
// Taylor integration, docs/ivp.md) on x' = f(x, n): the known part of u
// written in f with the time as a state (tau' = 1), the error n of u as an
// input tube [-0.02, 0.02]. A figure draws both tubes.
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include "causal_chain_network.h"
#include "example_args.h"
#include "example_bound.h"
#include "example_check.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"

using namespace sillage;
using namespace causal_chain;

namespace {

const IntervalVector kCapdBox{{38.1545777835, 71.7221807908}, {-11.4056594783, 27.2737690279}};

using State = std::array<double, 3>;

// RK4 with step h of the car with input u*(t) + c; samples every step.
std::vector<State> simulate(const State& x0, double c, double h) {
  const auto f = [&](double t, const State& x) {
    return State{10 * std::cos(x[2]), 10 * std::sin(x[2]), -std::cos((t + 33) / 5) + c};
  };
  std::vector<State> path{x0};
  State x = x0;
  const auto n = static_cast<std::size_t>(std::llround(kTf / h));
  for (std::size_t j = 0; j < n; ++j) {
    const double t = j * h;
    const auto add = [](const State& a, const State& b, double s) {
      return State{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
    };
    const State k1 = f(t, x), k2 = f(t + h / 2, add(x, k1, h / 2)), k3 = f(t + h / 2, add(x, k2, h / 2)),
                k4 = f(t + h, add(x, k3, h));
    for (int i = 0; i < 3; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    path.push_back(x);
  }
  return path;
}

// Largest distance of the path (sampled at the gates) outside the tube's gates.
double excess(const TubeVector& x, const std::vector<State>& path) {
  double worst = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    for (std::size_t i = 0; i < 3; ++i) {
      const Interval g = x[i].gate(k);
      worst = std::max({worst, g.is_empty() ? INFINITY : g.lb() - path[k][i], g.is_empty() ? 0 : path[k][i] - g.ub()});
    }
  }
  return worst;
}

// Component i of a path sampled at the time points, as a trajectory.
Trajectory component(const TDomain& td, const std::vector<State>& path, std::size_t i) {
  std::vector<double> v;
  for (const State& s : path) v.push_back(s[i]);
  return Trajectory(std::vector<double>(td.times().begin(), td.times().end()), v);
}

struct Run {
  std::shared_ptr<TubeVector> x;
  ContractStats stats;
  double cpu = 0;
};

// The stated final box, tightened by SILLAGE_EXAMPLE_TIGHTEN as in causal_chain.py.
IntervalVector stated_final_box() {
  return {example::bound(kFinalBox[0]), example::bound(kFinalBox[1]), example::bound(kFinalBox[2])};
}

Run solve(const std::shared_ptr<TDomain>& td, bool with_final_box) {
  const double start = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  const Problem p = build(td, with_final_box);
  if (with_final_box) p.x->set_gate(td->nb_slices(), stated_final_box());
  Run r;
  r.x = p.x;
  r.stats = p.cn->contract();
  r.cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - start;
  return r;
}

// CtcIvp on (x1, x2, x3, tau) with the input n = u - u*: forward from x0,
// and also backward from x(14) when the final box is given.
Run solve_ivp(const std::shared_ptr<TDomain>& td, bool with_final_box) {
  const double start = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  const CtcIvp ctc(Function({"x1", "x2", "x3", "tau", "n"}, "(10*cos(x3), 10*sin(x3), -cos((tau+33)/5) + n, 1)"), 1,
                   10, with_final_box ? TimePropag::FWD_BWD : TimePropag::FORWARD);
  TubeVector x(td, 4);
  const IntervalVector b = initial_box();
  x.set_gate(0, IntervalVector{b[0], b[1], b[2], Interval(0.0)});
  if (with_final_box) {
    const IntervalVector b = stated_final_box();
    x.set_gate(td->nb_slices(), IntervalVector{b[0], b[1], b[2], Interval(kTf)});
  }
  Run r;
  r.stats.empty = !ctc.contract(x, TubeVector(td, 1, example::bound(Interval(-0.02, 0.02))));
  if (r.stats.empty) r.stats.emptiness = "CtcIvp: no trajectory from x0 with the inputs reaches the final box";
  r.x = std::make_shared<TubeVector>(x.subvector(0, 2));
  r.cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - start;
  return r;
}

std::string box_str(const IntervalVector& b) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "[%.4f, %.4f] x [%.4f, %.4f] x [%.4f, %.4f]", b[0].lb(), b[0].ub(), b[1].lb(),
                b[1].ub(), b[2].lb(), b[2].ub());
  return buf;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const double dt = 0.01;
  const auto td = TDomain::create(0.0, kTf, dt);
  const std::size_t N = td->nb_slices();
  const double pi = std::acos(-1.0);

  // Paths: the truth (centre of x0, u*) and the corners x input extremes.
  std::vector<std::pair<std::string, std::vector<State>>> paths{{"truth", simulate({0, 0, -6 * pi / 5}, 0, dt)}};
  for (int e = 0; e < 16; ++e) {
    const State x0{e & 1 ? 1.0 : -1.0, e & 2 ? 1.0 : -1.0, -6 * pi / 5 + (e & 4 ? 0.02 : -0.02)};
    paths.push_back({"extreme " + std::to_string(e), simulate(x0, e & 8 ? 0.02 : -0.02, dt)});
  }

  bool ok = true;
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  for (const bool final_box : {false, true}) {
    const char* label = final_box ? "with the final box" : "from x0 only";
    const Run r = solve(td, final_box), ri = solve_ivp(td, final_box);
    if (r.stats.empty) return example::empty_exit("causal_chain", r.stats, label);
    if (ri.stats.empty) return example::empty_exit("causal_chain", ri.stats, std::string("CtcIvp ") + label);
    const IntervalVector xf = r.x->gate(N), xi = ri.x->gate(N);
    std::printf("%s: %zu iterations, %zu contractor calls, %.3f s CPU, empty = %d\n", label, r.stats.iterations,
                r.stats.contractor_calls, r.cpu, r.stats.empty);
    std::printf("  CtcDeriv network: x(14) in %s\n", box_str(xf).c_str());
    std::printf("  CtcIvp (%.3f s CPU): x(14) in %s, x(0) in %s\n", ri.cpu, box_str(xi).c_str(),
                box_str(ri.x->gate(0)).c_str());
    if (!final_box) {
      const bool inside_capd = xf[0].is_subset(kCapdBox[0]) && xf[1].is_subset(kCapdBox[1]);
      std::printf("  validated-integration box [%.4f, %.4f] x [%.4f, %.4f]: ours %s it (widths %.3f x %.3f vs %.3f x %.3f)\n",
                  kCapdBox[0].lb(), kCapdBox[0].ub(), kCapdBox[1].lb(), kCapdBox[1].ub(),
                  inside_capd ? "inside" : "not inside", xf[0].diam(), xf[1].diam(), kCapdBox[0].diam(),
                  kCapdBox[1].diam());
      summary = "x(14) in " + box_str(xf) + (inside_capd ? " (inside the validated-integration box)" : "") +
                "; CtcIvp " + box_str(xi);
    }
    // Every path that satisfies the constraints of this run must stay inside
    // both tubes; the hull of their final points is an inner bound.
    IntervalVector hull(3, Interval::empty());
    for (const auto& [name, path] : paths) {
      const State& end = path.back();
      const bool feasible = !final_box || stated_final_box().contains({end[0], end[1], end[2]});
      if (!feasible) continue;
      for (std::size_t i = 0; i < 3; ++i) hull[i] |= Interval(end[i]);
      for (const Run* run : {&r, &ri}) {
        const double e = excess(*run->x, path);
        if (e > 1e-9) {
          ok = false;
          std::printf("  %s leaves the %s tube by %.3g\n", name.c_str(), run == &r ? "CtcDeriv" : "CtcIvp", e);
        }
      }
    }
    std::printf("  hull of the feasible sampled x(14): %s\n", hull[0].is_empty() ? "none" : box_str(hull).c_str());
    std::printf("  truth inside: %s\n",
                excess(*r.x, paths[0].second) <= 1e-9 && excess(*ri.x, paths[0].second) <= 1e-9 ? "yes" : "NO");
    ok = example::enclosure_ok(*r.x) && example::enclosure_ok(*ri.x) && ok;
    const std::string tag = final_box ? "final" : "x0";
    const Trajectory t1 = component(*td, paths[0].second, 0), t2 = component(*td, paths[0].second, 1);
    tube_vector_figure(*r.x, 0, 1,
                       final_box ? "Causal chain with x(14) in [xf] (Fig. 4.9)" : "Causal chain from [x0] (Fig. 4.8)",
                       {}, &t1, &t2)
        .save((out / ("causal_chain_" + tag + ".svg")).string());
    figures.push_back({"causal_chain_" + tag + ".svg", final_box ? "Causal chain (4.25) with the final box, Fig. 4.9"
                                                                  : "Causal chain (4.25) from x0, Fig. 4.8"});
    // CtcDeriv (blue) and CtcIvp (orange, drawn over it).
    Figure cmp = tube_vector_figure(*r.x, 0, 1, std::string("Causal chain ") + label + ": CtcDeriv (blue) vs CtcIvp (orange)",
                                    {}, &t1, &t2);
    TubeStyle orange;
    orange.slices = Style{"#f6c28b", "#c25e00", 0.4, 1.0, "slice"};
    draw_tube_vector_2d(cmp, *ri.x, 0, 1, orange, &t1, &t2);
    cmp.save((out / ("causal_chain_" + tag + "_deriv_vs_ivp.svg")).string());
    figures.push_back({"causal_chain_" + tag + "_deriv_vs_ivp.svg",
                       std::string("Causal chain (4.25) ") + label + ": CtcDeriv network in blue, CtcIvp in orange"});
  }
  example::print_result("causal_chain", summary, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
